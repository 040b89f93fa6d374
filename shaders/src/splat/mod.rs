//! Tiled splatting of a multi-layer image (Franke et al. 2018, §5-6; Selgrad et al. 2016 is the same pipeline on the front
//! layer only). Stages, each a kernel here, recorded by `host/src/frame/splat.rs`:
//!
//! 0. [`plan`]: the largest CoC radius, reduced on the device, gives the rings and the radius cap
//!    (nothing is decided on the host from the image).
//! 1. [`pack`]: per-pixel layer slots → 16-byte [`fragment::Fragment`]s (Franke et al. 2018, Fig. 7,
//!    with a per-fragment colour exponent and alpha); non-finite colours and invalid depths are
//!    dropped, colours clamped to the numerical contract ([`crate::radiance`]), and an empty
//!    pixel gets the sky (black at infinite depth) so that coverage is complete. In-focus fragments
//!    stay out of the lists: a pixel's first one is kept per pixel (its "sharp front"). Unmerged,
//!    it writes each pixel's list fragments into the dense array, in the pixel's region
//!    ([`SplatParams::cell_region`]), and counts them.
//! 2. [`merge`] (optional, 2x2 or 4x4, both levels in one pass): neighbouring out-of-focus
//!    fragments of similar depth and colour become one larger fragment; umbra-aware merging drops
//!    what the merged fragment shadows from every lens point (§6.1-6.2). It writes each cell's
//!    merged list into the cell's region of the dense array and counts it; no level is stored.
//! 3. [`bin`]: per-tile fragment counts and an index over the partially filled cells (the
//!    load-balancing structure of §5.1), which tiles no blur reaches, then the tile lists, each
//!    placed exactly in a bounded pool by a plan for the whole frame (lists that do not fit are
//!    thinned to a coarser lattice of their sources until they do, and counted).
//! 4. The foundation's segmented sort orders every list by depth.
//! 5. [`accumulate`]: per pixel, front to back over its tile's list with early termination, ending
//!    at the pixel's sharp front; tiles that no blur reaches write their sharp fronts through.
//!
//! All kernels share [`SplatParams`]; each documents the fields it reads.

pub mod accumulate;
pub mod bin;
pub mod fragment;
pub mod merge;
pub mod pack;
pub mod plan;
pub mod surfaces;

use crate::aperture::Aperture;
use crate::exec::Load;
use crate::lens::ThinLens;

/// Invocations per workgroup of every splatting kernel.
pub const THREADS: u32 = 256;
/// Tile edges the pipeline supports.
pub const TILE_SIZES: [u32; 3] = [16, 24, 32];
/// Most tile rings a fragment may reach (the "more rings" path for large blur; see the README).
pub const MAX_RINGS: u32 = 6;
// `splat_bin` gives every neighbour tile within the rings one invocation.
const _: () = assert!((2 * MAX_RINGS + 1) * (2 * MAX_RINGS + 1) <= THREADS);
/// Largest workgroup count in one dimension the host dispatches; kernels loop over the rest.
pub const MAX_GROUPS: u32 = 65535;

/// `flags`: drop fragments inside a merged fragment's umbra (§6.2).
pub const FLAG_UMBRA_MERGE: u32 = 1;
/// `flags`: the device runs a workgroup's invocations one after another (the CPU backend), so a
/// kernel may give an invocation a run of consecutive items where a GPU gives it one. The results
/// do not depend on it.
pub const FLAG_SERIAL: u32 = 2;
/// `flags` bits 8-10: the side of the sub-sample grid of the input's footprints (1 to 4; 0: the
/// input has none). The input slot buffer then carries one footprint word a slot after its slots
/// ([`crate::footprint::slot_word`]), and the dense array one a fragment after its fragments
/// ([`fragment::footprint_word`]).
pub const FOOTPRINT_SIDE_SHIFT: u32 = 8;

/// Push constants of every splatting kernel (128 bytes, all that Vulkan guarantees). `rings` and
/// `max_radius` are the configured bounds here; the kernels use the frame's own,
/// which `plan::splat_plan_finish` writes on the device (see [`planned`]).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct SplatParams {
    pub width: u32,
    pub height: u32,
    /// Input slots per pixel (`pack`, and the copy-through of `accumulate`).
    pub layers: u32,
    /// Edge in pixels of the frame's cells (1, or 2 or 4 merged); see [`SplatParams::cell_cap`].
    pub cell: u32,
    pub cells_x: u32,
    pub cells_y: u32,
    /// Tile edge in pixels, tile grid, and the rings of neighbours a fragment may reach.
    pub tile: u32,
    pub tiles_x: u32,
    pub tiles_y: u32,
    pub rings: u32,
    pub flags: u32,
    /// Cap on a fragment's radius in pixels (`rings · tile` at most).
    pub max_radius: f32,
    /// Merging: smallest CoC radius (px) that counts as out of focus, largest ratio of depths, and
    /// largest per-channel colour spread relative to the channel's value.
    pub merge_min_radius: f32,
    pub merge_depth_ratio: f32,
    pub merge_color_tol: f32,
    pub lens: ThinLens,
    /// The aperture shape `accumulate` tests pixels against (binning uses the enclosing circle).
    pub aperture: Aperture,
    /// Entries the list buffers hold, and the longest list the sort was sized for: a tile whose
    /// list does not fit either is thinned ([`stats::THINNED_TILES`]), or where no thinning fits,
    /// counted in [`stats::OVERFLOW_TILES`] and copied through.
    pub list_capacity: u32,
    pub max_list: u32,
}

const _: () = assert!(core::mem::size_of::<SplatParams>() <= 128);

impl SplatParams {
    /// Fragment slots per cell: every slot of the pixels a cell covers, the most its list holds.
    #[inline]
    pub fn cell_cap(&self) -> u32 {
        self.layers * self.cell * self.cell
    }
    /// The first dense index of cell `c`'s fragments. Each cell keeps a region of
    /// [`Self::cell_cap`] fragments, tile by tile and row-major inside its tile: the pass that
    /// makes a cell's list writes it as it goes, with no count of the cells before it (binning
    /// finds a tile's fragments through its cells' offsets in the tile, `bin::tile_count_pass`).
    /// Walked in that order, the fragments come tile by tile, cell by cell, front to back.
    #[inline]
    pub fn cell_region(&self, c: u32) -> u32 {
        let ct = self.cells_per_tile_edge();
        let (gx, gy) = (c % self.cells_x, c / self.cells_x);
        self.region_in_tile((gy / ct) * self.tiles_x + gx / ct, gx % ct, gy % ct)
    }
    /// [`Self::cell_region`] of the cell at column `x`, row `y` of tile `t`.
    #[inline]
    pub fn region_in_tile(&self, t: u32, x: u32, y: u32) -> u32 {
        let ct = self.cells_per_tile_edge();
        ((t * ct + y) * ct + x) * self.cell_cap()
    }
    /// Cells along a tile's edge.
    #[inline]
    pub fn cells_per_tile_edge(&self) -> u32 {
        self.tile / self.cell
    }
    /// Fragments the dense array has room for: the regions of every cell of the tile grid.
    #[inline]
    pub fn dense_slots(&self) -> u32 {
        self.tiles_x * self.tiles_y * self.tile * self.tile * self.layers
    }
    /// The side of the input footprints' sub-sample grid, 0 for none ([`FOOTPRINT_SIDE_SHIFT`]).
    #[inline]
    pub fn footprint_side(&self) -> u32 {
        (self.flags >> FOOTPRINT_SIDE_SHIFT) & 7
    }
    /// Edge of the pixel block one accumulation workgroup covers (divides `tile`).
    #[inline]
    pub fn block(&self) -> u32 {
        block_for(self.tile)
    }
}

/// Edge of the pixel block one accumulation workgroup covers for tiles of `tile` pixels.
#[inline]
pub const fn block_for(tile: u32) -> u32 {
    if tile == 24 { 12 } else { 16 }
}

/// The push constants with the device plan's fields (`rings`, `max_radius`) read
/// from the frame words that `splat_plan_finish` wrote.
#[inline]
pub fn planned(p: &SplatParams, st: &impl Load) -> SplatParams {
    let mut q = *p;
    q.rings = st.load(stats::RINGS);
    q.max_radius = f32::from_bits(st.load(stats::RADIUS_CAP));
    q
}

/// Words of the statistics buffer every run fills (atomic counters, so order-independent).
pub mod stats {
    /// Input fragments dropped for a non-finite colour or a depth that is not positive.
    pub const DROPPED: u32 = 0;
    /// Input colours changed by the numerical contract's clamp (`radiance::clamp_color`).
    pub const CLAMPED: u32 = 1;
    /// Black background fragments added for pixels without data (no slot at all).
    pub const SKY: u32 = 2;
    /// Fragments produced by merging, and the fragments they replaced.
    pub const MERGED: u32 = 3;
    pub const MERGED_INPUTS: u32 = 4;
    /// Fragments dropped inside a merged fragment's umbra.
    pub const UMBRA_SKIPPED: u32 = 5;
    /// Fragments whose radius was capped at `max_radius`.
    pub const CAPPED: u32 = 6;
    /// Tiles copied through (no blur reaches them).
    pub const COPY_TILES: u32 = 7;
    /// Longest tile list (entries) the frame wanted, before any thinning.
    pub const MAX_CAPACITY: u32 = 8;
    /// Pixels that stopped before the end of their list (saturated).
    pub const EARLY_OUT: u32 = 9;
    /// List entries those pixels did not visit.
    pub const SKIPPED_ENTRIES: u32 = 10;
    /// Pixels with a sharp front (kept out of the lists), and in-focus fragments hidden behind one.
    pub const SHARP: u32 = 11;
    pub const HIDDEN_SHARP: u32 = 12;
    /// Fragments entering tiling (after merging).
    pub const TILED: u32 = 13;
    /// Tiles whose list did not fit the list pool (or exceeded the longest list the sort handles),
    /// and the entries those lists would have held: such tiles are copied through.
    pub const OVERFLOW_TILES: u32 = 14;
    pub const OVERFLOW_ENTRIES: u32 = 15;
    /// List entries the plan placed in the pool (`bin::bin_plan_pass`).
    pub const LIST_TOP: u32 = 16;
    /// The device plan: largest CoC radius present (f32 bits, reduced), then the rings and the
    /// radius cap (f32 bits) derived from it.
    pub const WIDEST: u32 = 17;
    pub const RINGS: u32 = 18;
    pub const RADIUS_CAP: u32 = 19;
    /// Input alphas NaN or outside [0, 1], clamped (`slot::clamp_alpha`).
    pub const ALPHA_CLAMPED: u32 = 20;
    /// Pixels whose slots end translucent, given black behind them (a pixel composites over black).
    pub const BACKED: u32 = 21;
    /// Tiles whose list was thinned to fit (`bin::thin_keeps`), and the entries thinning left out.
    pub const THINNED_TILES: u32 = 22;
    pub const THINNED_ENTRIES: u32 = 23;
    pub const WORDS: u32 = 24;
}

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 10] = [
    &plan::PLAN_REDUCE,
    &plan::PLAN_FINISH,
    &pack::PACK,
    &merge::MERGE,
    &bin::TILE_COUNT,
    &bin::ALLOC,
    &bin::BIN_COUNT,
    &bin::BIN_PLAN,
    &bin::BIN,
    &accumulate::ACCUMULATE,
];
