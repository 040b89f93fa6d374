//! An engine-grade gathering depth of field, the kind shipping renderers use by default, built from
//! the published descriptions of AMD FidelityFX DoF, Unreal Engine's Diaphragm DoF and Jimenez 2014
//! ("Next-Generation Post-Processing in Call of Duty: Advanced Warfare"): half-resolution colour and
//! CoC, per-tile near-field CoC dilated over the neighbouring tiles, a fixed budget of sample rings,
//! a background field and a near field gathered separately and composited at full resolution with
//! the near field's coverage as alpha, and a full-resolution path for what is in focus or slightly
//! blurred.
//!
//! Four passes (all sizes in the frame's pixels unless said "half"):
//! 1. [`downsample_pass`]: every half-resolution pixel splits its 2x2 pixels into a near part and
//!    the rest by a continuous weight (0 at a 1 px near CoC radius, 1 at 3 px) and keeps both as
//!    samples: colour, signed radius, and the near part's coverage of the block. The rest weighs
//!    its pixels by how much the composite shows the background field over them, so a sharp pixel
//!    does not tint the field of its blurred neighbours. Each 8x8 tile reduces its largest
//!    near-field radius, and takes out its highlights (at most [`HIGHLIGHTS_PER_TILE`]): blocks
//!    much brighter than their 12 neighbours (less those the emitter lights itself) with a CoC
//!    radius of at least 1/2 px everywhere (a ramp from 1/4 px), whose excess over the neighbours
//!    becomes a disc drawn at full resolution; the gather and the full-resolution path see the
//!    input without it.
//! 2. [`dilate_pass`]: every tile takes the largest near radius of the tiles that radius reaches,
//!    fading in over the last tile of the reach, so a blurred foreground spreads over the sharp
//!    tiles beside it (Unreal's "foreground hole filling", FidelityFX's tile dilation); and how far
//!    to look for highlights whose discs reach it.
//! 3. [`gather_pass`]: every half-resolution pixel reads `1 + 3 R (R + 1)` samples on `R` hexagonal
//!    rings (ring `i` holds `6 i` points of a hexagonal lattice, so the samples cover the disc with
//!    uniform density and no trigonometry) for each of two fields, each with its own kernel (one
//!    set of rings where the two agree). A sample's near share rises continuously from 0 at a 0.5
//!    half-pixel near radius to 1 at 1.5:
//!    - background, as wide as the pixel's own CoC (either side of the focus plane, so a slightly
//!      near pixel's rings never switch off while its neighbours in front still reach it):
//!      scatter-as-gather as in
//!      [`crate::gather`], each sample weighted by its coverage over the inverse of its CoC area, a
//!      sample behind the pixel reaching at most the pixel's own CoC (so a blurred background does
//!      not smear over a sharper object); where the pixel itself is in the near field, the kernel
//!      is the near one and the background seen within it fills in what the pixel hides;
//!    - near, as wide as the tile's dilated near radius: each sample adds the share of its CoC disc
//!      that one lattice cell covers, times its near share; their sum is the near field's coverage
//!      (alpha, 1 for a uniform near field), their weighted mean its colour.
//! 4. [`composite_pass`]: every pixel blends a full-resolution scatter-as-gather of its 3x3
//!    neighbourhood (below a 1 px CoC radius) with the background field, upsampled bilinearly
//!    (from 2 px), adds the discs of the highlights behind it, puts the near field over that by its
//!    coverage and the discs of the near highlights on top.
//!
//! Every decision that a focus pull moves through is a continuous weight, not a threshold (the
//! near split, the dilation, the half- and full-resolution blend, the highlight share), so the
//! image changes smoothly with the lens; only a tile's highlight cap is a count. Samples beyond the
//! frame's edge take the edge pixel (clamp-to-edge addressing), so a blurred object cut by the
//! frame keeps its full coverage there. Non-finite colours and depths are skipped as in the
//! exhaustive gather. What it cannot do, by construction: show what a blurred foreground hides (a
//! single layer), honour CoCs beyond its radius cap, or resolve blur larger than its ring spacing
//! allows (with few rings a large blur is sampled sparsely; the highlight discs cover the worst of
//! it, isolated bright pixels).

use crate::exec::{Group, Load, Mem};
use crate::lens::{ThinLens, is_finite as finite, is_nan, is_pos_inf, is_positive};
use crate::math::{absf, maxf, minf, saturate};

/// Half-resolution pixels on a side of a tile (tiles are 16x16 pixels of the frame).
pub const TILE: u32 = 8;
/// A half-resolution pixel's 9 words: its 2x2 pixels split into a near part and the rest by a
/// continuous weight, as two samples: the near part's colour and its share of the block
/// (coverage), the rest's colour, then the two signed CoC radii in half-resolution pixels (the
/// rest's NaN where none of the pixels was valid). Colours are less what the highlight path took.
pub const HALF_WORDS: u32 = 9;
/// A half-resolution pixel's 8 words in the fields buffer: the background field's colour and 1 (0
/// where nothing was gathered), then the near field's premultiplied colour and coverage.
pub const FIELD_WORDS: u32 = 8;
/// A tile's 2 words after dilation: its dilated near-field radius (half-resolution pixels), then 1
/// plus the tiles on each side whose highlights may reach it (0: none does).
pub const DILATED_WORDS: u32 = 2;
/// A sample's near share rises from 0 at this near CoC radius (half-resolution pixels) to 1 at
/// `NEAR_MIN_RADIUS + NEAR_RAMP`: nearly sharp samples belong to the background field, and no
/// sample jumps from one field to the other as the focus moves.
pub const NEAR_MIN_RADIUS: f32 = 0.5;
pub const NEAR_RAMP: f32 = 1.0;
/// Highlights drawn as discs instead of gathered: the scattered share rises from 0 at this CoC
/// radius (pixels of the frame) to 1 at `HIGHLIGHT_MIN_RADIUS + HIGHLIGHT_RAMP`, where a disc is
/// wider than its pixel. Unreal Engine's Diaphragm DoF scatters from 3 px. Left to the gather, an
/// emitter is averaged into the half-resolution field its more blurred neighbours read and
/// upsampled from it: a dim halo 1 to 5 px around it, which the saturating display transform shows
/// (on `highlights` at 320x180 against the converged reference, 561 pixels lit that the reference
/// leaves dark with the earlier ramp from 1/2 px to 1 px, 345 with this one, the gather 79). In
/// focus the share is 0: a block's taken light is one disc, which would spread two sharp emitters
/// of a block over each other's pixels.
pub const HIGHLIGHT_MIN_RADIUS: f32 = 0.25;
pub const HIGHLIGHT_RAMP: f32 = 0.25;
/// ... and from 0 where the block's luminance is this many times its ring of 12 neighbours' to 1 at
/// twice that ...
pub const HIGHLIGHT_CONTRAST: f32 = 4.0;
/// ... and from 0 where the excess over the neighbours has this luminance to 1 at twice that.
pub const HIGHLIGHT_MIN_EXCESS: f32 = 0.25;
/// Highlights a tile holds (1 in 8 of its half-resolution pixels; Unreal caps at 10% of quads).
/// Beyond it a highlight stays in the gather whole, and is counted ([`STATS_CAPPED`]).
pub const HIGHLIGHTS_PER_TILE: u32 = 8;
/// A highlight's 8 words: centre x, y (pixels of the frame), signed CoC radius (pixels), then its
/// colour per unit of disc weight (r, g, b), the spread of its light (pixels, [`disc_weight`]),
/// then 1 unused.
pub const HIGHLIGHT_WORDS: u32 = 8;
/// A tile's highlight record: the count, the farthest reach of its discs (radius plus spread, pixels,
/// bits of an f32), the highlights.
pub const BRIGHT_TILE_WORDS: u32 = 2 + HIGHLIGHTS_PER_TILE * HIGHLIGHT_WORDS;
/// The word of the frame's statistics buffer that counts the highlights left in the gather because
/// their tile held [`HIGHLIGHTS_PER_TILE`] already (word 0 counts the clamped input colours).
pub const STATS_CAPPED: u32 = 1;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct RingGatherParams {
    pub width: u32,
    pub height: u32,
    /// Sample rings (the quality knob): `1 + 3 R (R + 1)` samples a half-resolution pixel for each
    /// field that needs its own kernel.
    pub rings: u32,
    /// Cap on the CoC radius in pixels of the frame.
    pub max_radius: u32,
    pub lens: ThinLens,
}

impl RingGatherParams {
    #[inline]
    pub fn half_width(&self) -> u32 {
        self.width.div_ceil(2)
    }
    #[inline]
    pub fn half_height(&self) -> u32 {
        self.height.div_ceil(2)
    }
    #[inline]
    pub fn tiles_x(&self) -> u32 {
        self.half_width().div_ceil(TILE)
    }
    #[inline]
    pub fn tiles_y(&self) -> u32 {
        self.half_height().div_ceil(TILE)
    }
    /// Tiles on each side a tile's dilation looks at: as far as the capped radius reaches.
    #[inline]
    pub fn dilation_tiles(&self) -> u32 {
        (self.max_radius + 1).div_ceil(2 * TILE)
    }
}

/// Samples per half-resolution pixel with `rings` rings.
#[inline]
pub const fn samples(rings: u32) -> u32 {
    1 + 3 * rings * (rings + 1)
}

#[inline]
fn luminance(c: [f32; 3]) -> f32 {
    0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
}

/// Signed CoC radius in pixels of a sample at depth `z` (negative in front of the focus plane),
/// within `±cap`; the sky (`+inf`) takes the far-field limit. Only for valid depths.
#[inline]
pub fn signed_radius(lens: &ThinLens, z: f32, cap: f32) -> f32 {
    let r = if is_pos_inf(z) { 0.5 * lens.far_limit_px() } else { 0.5 * lens.signed_coc_px(z) };
    maxf(minf(r, cap), -cap)
}

/// The share of a sample of signed radius `s` (half-resolution pixels) that belongs to the near field.
#[inline]
pub fn near_share(s: f32) -> f32 {
    saturate((-s - NEAR_MIN_RADIUS) / NEAR_RAMP)
}

/// The colour of pixel `i` with its depth, or `None` when either is unusable.
#[inline]
fn sample(color: &impl Load, depth: &impl Load, i: u32) -> Option<([f32; 3], f32)> {
    let c = [f32::from_bits(color.load(3 * i)), f32::from_bits(color.load(3 * i + 1)), f32::from_bits(color.load(3 * i + 2))];
    let c = crate::radiance::clamp_color(c);
    let z = f32::from_bits(depth.load(i));
    if finite(c[0]) && finite(c[1]) && finite(c[2]) && is_positive(z) { Some((c, z)) } else { None }
}

/// Unit vector `k` (0..6) of the hexagonal lattice: 60° apart, starting on +x.
#[inline]
fn hex_dir(k: u32) -> [f32; 2] {
    const S: f32 = 0.866_025_4;
    if k == 0 {
        [1.0, 0.0]
    } else if k == 1 {
        [0.5, S]
    } else if k == 2 {
        [-0.5, S]
    } else if k == 3 {
        [-1.0, 0.0]
    } else if k == 4 {
        [-0.5, -S]
    } else {
        [0.5, -S]
    }
}

/// Point `j` (0..6 ring) of hexagonal ring `ring` (>= 1) of the unit lattice: the ring's six sides
/// walked corner to corner, `ring` points a side.
#[inline]
pub fn hex_point(ring: u32, j: u32) -> [f32; 2] {
    let side = j / ring;
    let step = (j % ring) as f32;
    let a = hex_dir(side);
    let b = hex_dir((side + 1) % 6);
    let r = ring as f32;
    [a[0] * r + (b[0] - a[0]) * step, a[1] * r + (b[1] - a[1]) * step]
}

/// A highlight's disc weight at a pixel whose centre is `d` pixels from the disc's centre: the CoC
/// disc of `radius` seen through a pixel and spread over the light's footprint, `spread` its mean
/// distance from the centre (0 for the light of one pixel): 1 inside `radius − 1/2 − spread`, a
/// soft edge `1 + 2·spread` wide out to `radius + 1/2 + spread`: splatting's rim of a fragment
/// standing for a block of pixels ([`crate::splat::fragment::linear_rim`]), with the footprint's
/// width in place of the block's. One pixel's light has the one-pixel soft edge of a single
/// pixel's disc.
#[inline]
pub fn disc_weight(radius: f32, spread: f32, d: f32) -> f32 {
    crate::splat::fragment::linear_rim(d, radius + 0.5 + spread, 1.0 + 2.0 * spread)
}

/// The sum of [`disc_weight`] over every pixel centre of the plane for a disc of `radius` (>= 1/2)
/// and `spread` centred at (`cx`, `cy`): the pixels whose weight is 1 counted row by row, the soft
/// edge summed, so a highlight's disc keeps its energy exactly (in O(radius), not O(radius²)).
pub fn disc_weight_sum(cx: f32, cy: f32, radius: f32, spread: f32) -> f32 {
    let outer = radius + 0.5 + spread;
    let inner = radius - 0.5 - spread;
    let mut sum = 0.0f32;
    let mut y = crate::math::floor(cy - outer);
    let last = crate::math::floor(cy + outer);
    while y <= last {
        let oy = y + 0.5 - cy;
        let b2 = outer * outer - oy * oy;
        if b2 > 0.0 {
            let b = crate::math::sqrt(b2);
            // Whole pixels: centres within the inner radius (none when the soft edge reaches the
            // centre, a footprint wider than the CoC disc).
            let a2 = if inner > 0.0 { inner * inner - oy * oy } else { -1.0 };
            let (lo, hi) = if a2 > 0.0 {
                let a = crate::math::sqrt(a2);
                (crate::math::ceil(cx - a - 0.5), crate::math::floor(cx + a - 0.5))
            } else {
                (1.0, 0.0)
            };
            if hi >= lo {
                sum += hi - lo + 1.0;
            }
            let mut x = crate::math::floor(cx - b - 0.5);
            let end = crate::math::ceil(cx + b - 0.5);
            while x <= end {
                if x < lo || x > hi {
                    let ox = x + 0.5 - cx;
                    sum += disc_weight(radius, spread, crate::math::sqrt(ox * ox + oy * oy));
                }
                x += 1.0;
            }
        }
        y += 1.0;
    }
    sum
}

/// A pixel's weight in its block's near part: 0 at a 1 px near CoC radius, 1 at 3 px.
#[inline]
fn near_weight(r: f32) -> f32 {
    saturate((-r - 1.0) * 0.5)
}

mod composite;
mod dilate;
mod downsample;
mod gather;

pub use composite::{FINE_REACH, composite_pass};
pub use dilate::dilate_pass;
pub use downsample::downsample_pass;
pub use gather::{gather_pass, lattice};

kernel!(
    /// Half-resolution colour and signed CoC, each tile's largest near-field radius and its highlights, taken out of the full-resolution colours.
    RING_GATHER_DOWNSAMPLE = ring_gather_downsample [64 subgroups] (RingGatherParams) shared [u32; 6 * 64]
        { read color, read depth, half, tiles, bright, fine, stats } => downsample_pass
);
kernel!(
    /// Each tile's near-field radius dilated over the tiles it reaches, and its highlight reach.
    RING_GATHER_DILATE = ring_gather_dilate [64] (RingGatherParams) { read tiles, read bright, dilated } => dilate_pass
);
kernel!(
    /// The background and near fields at half resolution, over hexagonal sample rings.
    RING_GATHER = ring_gather [64] (RingGatherParams) { read half, read dilated, fields } => gather_pass
);
kernel!(
    /// The full-resolution composite of the pixel, the background field, the near field and the highlights' discs.
    RING_GATHER_COMPOSITE = ring_gather_composite [64] (RingGatherParams)
        { read fine, read depth, read fields, read bright, read dilated, out } => composite_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 4] = [&RING_GATHER_DOWNSAMPLE, &RING_GATHER_DILATE, &RING_GATHER, &RING_GATHER_COMPOSITE];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hexagonal_rings_are_distinct_lattice_points_at_the_ring_distance() {
        for ring in 1..=8u32 {
            let mut seen: Vec<[i64; 2]> = Vec::new();
            for j in 0..6 * ring {
                let q = hex_point(ring, j);
                // On the hexagon of "radius" `ring`: between its inradius and its circumradius.
                let d = (q[0] * q[0] + q[1] * q[1]).sqrt();
                assert!(d >= ring as f32 * 0.866 - 1e-4 && d <= ring as f32 + 1e-4, "ring {ring} point {j}: {d}");
                let key = [(q[0] * 1000.0).round() as i64, (q[1] * 1000.0).round() as i64];
                assert!(!seen.contains(&key), "ring {ring} repeats {q:?}");
                seen.push(key);
            }
        }
        assert_eq!(samples(5), 91);
    }
}
