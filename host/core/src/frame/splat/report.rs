//! What a splatting frame did and what it left out, for the CLI and the evaluation.

use super::options::SplatPlanReport;
use crate::ops::sort::SortStats;

/// What a frame did and left out.
#[derive(Clone, Debug, Default)]
pub struct SplatReport {
    pub plan: Option<SplatPlanReport>,
    pub pixels: u64,
    /// Fragments in the input (slots used, up to the frame's layers), where the host knows them:
    /// the one-shot function counts its image's; a context reads only the device, which does not
    /// count them, and leaves `None`. Then the slots a full multi-layer image of this many layers
    /// would hold.
    pub input_fragments: Option<u64>,
    pub full_layer_slots: u64,
    pub dropped: u32,
    pub clamped: u32,
    /// Input alphas NaN or outside [0, 1], clamped (NaN to 0; `dof_shaders::slot::clamp_alpha`).
    pub alpha_clamped: u32,
    /// Pixels whose fragments end translucent, given black behind them (a pixel composites over
    /// black).
    pub backed: u32,
    /// Pixels without data, given a black background fragment.
    pub sky: u32,
    /// Pixels whose front is in focus (kept out of the lists), and in-focus fragments behind one.
    pub sharp_pixels: u32,
    pub hidden_sharp: u32,
    /// Fragments entering tiling (after merging) and those merging produced and replaced.
    pub fragments: u64,
    pub merged: u32,
    pub merged_inputs: u32,
    pub umbra_skipped: u32,
    pub capped: u32,
    pub tiles: u32,
    pub copy_tiles: u32,
    /// Per tile, the sorted list's length (0 for copied tiles).
    pub list_lengths: Vec<u32>,
    /// Per tile, where its list starts in the pool (the order tiles placed their lists in is the
    /// device's).
    pub list_offsets: Vec<u32>,
    /// Entries the list pool holds, and entries binned.
    pub list_capacity: u64,
    pub list_entries: u64,
    /// Tiles whose list did not fit the pool (or the longest list the sort handles), copied through
    /// instead, and the entries they would have held. Zero in a whole frame.
    pub overflow_tiles: u32,
    pub overflow_entries: u64,
    /// Tiles whose list was thinned to fit the pool or the sort (a coarser lattice of its wide
    /// sources, each standing for its block: `dof_shaders::splat::bin::thin_keeps`), and the
    /// entries thinning left out. Blurred, but approximately; zero in a whole frame.
    pub thinned_tiles: u32,
    pub thinned_entries: u64,
    /// The longest list any tile wanted, and the pool's bump pointer at the end of the frame.
    pub longest_list_wanted: u32,
    pub list_top: u64,
    /// Whether the frame ran on llvmpipe (lavapipe) with a list long enough that the driver's loop
    /// limit may have cut pixels' walks short ([`LLVMPIPE_SAFE_LIST`]): the image may then lack what
    /// lies behind in those tiles. Merging shortens the lists.
    pub driver_loop_limit: bool,
    pub sort: SortStats,
    pub early_out_pixels: u32,
    pub skipped_entries: u32,
    /// Bytes of every buffer the splatting context holds.
    pub buffer_bytes: u64,
}

/// The longest tile list the accumulation walks whole on llvmpipe (lavapipe), whose loops end after
/// 65 535 iterations in all per shader invocation (Mesa's `LP_MAX_TGSI_LOOP_ITERATIONS`, shared
/// between every loop): about 5.7 iterations a list entry. Measured: 11 088 entries walked whole,
/// 11 644 not (`tests/tests/alpha.rs`); set with a margin.
pub const LLVMPIPE_SAFE_LIST: u32 = 10_000;

impl SplatReport {
    /// Mean list length over the tiles that were splatted.
    pub fn mean_list_length(&self) -> f64 {
        let splatted = (self.tiles - self.copy_tiles).max(1);
        self.list_entries as f64 / splatted as f64
    }
    /// Tiles the frame could not splat whole: thinned or left sharp.
    pub fn tiles_cut_short(&self) -> u32 {
        self.overflow_tiles + self.thinned_tiles
    }
    /// The list entries the frame wanted: those placed, those thinning left out and those of the
    /// tiles left sharp (what a pool that holds the whole frame needs).
    pub fn entries_wanted(&self) -> u64 {
        self.list_top + self.thinned_entries + self.overflow_entries
    }
    pub fn max_list_length(&self) -> u32 {
        self.list_lengths.iter().copied().max().unwrap_or(0)
    }
    /// List-length histogram (Franke et al. 2018, Fig. 12): `(upper bound, tiles)` for the power-of-two buckets
    /// `0`, `1`, `2..=2`, `3..=4`, ..., up to the longest list; copied tiles count as length 0.
    pub fn list_histogram(&self) -> Vec<(u32, u32)> {
        let mut buckets: Vec<(u32, u32)> = Vec::new();
        for &n in &self.list_lengths {
            let bound = if n == 0 { 0 } else { n.next_power_of_two() };
            match buckets.iter_mut().find(|b| b.0 == bound) {
                Some(b) => b.1 += 1,
                None => buckets.push((bound, 1)),
            }
        }
        buckets.sort_unstable();
        buckets
    }
    /// One paragraph for the CLI: what the frame did and what it skipped.
    pub fn summary(&self) -> String {
        let mut s = String::new();
        if let Some(p) = &self.plan {
            s += &format!(
                "tiles {}x{} of {} px, {} ring(s) (largest CoC radius present {:.1} px, cap {:.0} px), merge steps {}\n",
                p.tiles_x, p.tiles_y, p.tile, p.rings, p.max_coc_radius, p.radius_cap, p.merge_steps
            );
        }
        let layers = self.plan.as_ref().map_or(0, |p| p.layers);
        let input = match self.input_fragments {
            Some(n) => format!(
                "{n} in ({:.2}/px; a full {layers}-layer image holds {})",
                n as f64 / self.pixels.max(1) as f64,
                self.full_layer_slots
            ),
            None => format!("input count not read back (a full {layers}-layer image holds {})", self.full_layer_slots),
        };
        s += &format!(
            "fragments: {input}, {} dropped (non-finite or bad depth), {} clamped (negative, subnormal or above 2^100), {} empty pixels given a black background\n",
            self.dropped, self.clamped, self.sky
        );
        if self.alpha_clamped > 0 || self.backed > 0 {
            s += &format!(
                "alpha: {} clamped (NaN or outside [0, 1]), {} pixels ending translucent given black behind\n",
                self.alpha_clamped, self.backed
            );
        }
        s += &format!(
            "in focus: {} pixels keep their sharp front out of the lists, {} in-focus fragments behind one left out\n",
            self.sharp_pixels, self.hidden_sharp
        );
        s += &format!(
            "merging: {} merged fragments replaced {}, {} dropped in umbrae; {} fragments tiled, {} radii capped\n",
            self.merged, self.merged_inputs, self.umbra_skipped, self.fragments, self.capped
        );
        s += &format!(
            "tiles copied through (no blur reaches them): {} of {}; lists: {} entries (mean {:.0}, max {}) in a pool of {}\n",
            self.copy_tiles,
            self.tiles,
            self.list_entries,
            self.mean_list_length(),
            self.max_list_length(),
            self.list_capacity
        );
        if self.thinned_tiles > 0 {
            s += &format!(
                "THINNED: {} tiles did not fit the list pool whole and were splatted from a coarser lattice of their \
                 wide fragments ({} list entries left out)\n",
                self.thinned_tiles, self.thinned_entries
            );
        }
        if self.overflow_tiles > 0 {
            s += &format!(
                "OVERFLOW: {} tiles ({} list entries) did not fit the list pool even thinned and show only their in-focus fronts\n",
                self.overflow_tiles, self.overflow_entries
            );
        }
        let classes: Vec<String> = dof_shaders::sort::CLASS_CAPS
            .iter()
            .zip(&self.sort.class_counts)
            .filter(|(_, n)| **n > 0)
            .map(|(cap, n)| format!("{n}x<={cap}"))
            .collect();
        let histogram: Vec<String> = self.list_histogram().iter().map(|(b, n)| format!("<={b}: {n}")).collect();
        s += &format!("list lengths (tiles per bucket): {}\n", histogram.join(", "));
        s += &format!(
            "sort classes used: {} (global path: {}); early termination: {} pixels skipped {} list entries",
            if classes.is_empty() { "none".into() } else { classes.join(", ") },
            self.sort.global_lists,
            self.early_out_pixels,
            self.skipped_entries
        );
        if self.driver_loop_limit {
            s += &format!(
                "\nwarning: llvmpipe ends a shader invocation's loops after 65535 iterations in all; a list of {} \
                 entries (over {LLVMPIPE_SAFE_LIST}) may have been walked only in part: use --merge 2x2 or 4x4",
                self.longest_list_wanted
            );
        }
        s
    }
}

crate::frame::context::report_details!(SplatReport, |r| vec![
    ("list_entries", r.list_entries as f64),
    ("mean_list_length", r.mean_list_length()),
    ("max_list_length", r.max_list_length() as f64),
    ("copy_tiles", r.copy_tiles as f64),
    ("merged", r.merged as f64),
    ("overflow_tiles", r.overflow_tiles as f64),
    ("thinned_tiles", r.thinned_tiles as f64),
    ("list_pool", r.list_capacity as f64),
    ("clamped", r.clamped as f64),
    ("alpha_clamped", r.alpha_clamped as f64),
]);
