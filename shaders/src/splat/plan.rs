//! Stage 0: the frame's plan, decided on the device from the input, so that no pass over the image
//! runs on the host and nothing is read back between stages.
//!
//! - `splat_plan_reduce` (grid-stride over pixels): the largest CoC radius present (an empty pixel
//!   counts as the background at infinite depth, and so does the black behind slots that end
//!   translucent), reduced in workgroup memory and then with one
//!   atomic maximum per workgroup into the frame words.
//! - `splat_plan_finish` (one invocation): from it, the tile rings fragments may reach and the
//!   radius cap the rings allow. Every later kernel reads them through [`planned`](super::planned).
//!
//! No colour scale: every fragment carries its own exponent (see [`super::fragment`]).

use super::pack::{input_slot, is_valid};
use super::{MAX_RINGS, SplatParams, THREADS, stats};
use crate::exec::{Group, Load, Mem};
use crate::slot::clamp_alpha;
use crate::wg::{Max, reduce};

/// Rings and radius cap for the widest radius present: fragments merged into cells of `cell` pixels
/// reach half a cell beyond their CoC, and `cap` (the configured cap, at most `MAX_RINGS` tiles)
/// bounds both.
#[inline]
pub fn rings_for(widest: f32, cell: u32, cap: f32, tile: u32) -> (u32, f32) {
    let reach = widest + 0.5 * cell as f32;
    let needed = if reach < cap { reach } else { cap };
    let mut rings = 1;
    while rings < MAX_RINGS && ((rings * tile) as f32) < needed {
        rings += 1;
    }
    let ring_reach = (rings * tile) as f32;
    (rings, if cap < ring_reach { cap } else { ring_reach })
}

pub fn reduce_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &SplatParams,
    sh: &mut [u32; 2 * THREADS as usize],
    layers: R,
    counts: R,
    mut st: M,
) {
    let pixels = p.width * p.height;
    // [0, 2T): scan of the widest radius, a non-negative float (or +inf) whose bits order like
    // its value.
    let stride = g.num_workgroups()[0] * THREADS;
    let base = g.workgroup_id()[0] * THREADS;
    g.each(|lid| {
        let mut widest = 0.0f32;
        let mut i = base + lid;
        while i < pixels {
            let n = counts.load(i);
            let n = if n < p.layers { n } else { p.layers };
            let mut through = 1.0f32;
            let mut valid = false;
            let mut k = 0;
            while k < n {
                let s = input_slot(&layers, p, i, k);
                let (c, z) = (s.color, s.depth);
                k += 1;
                if !is_valid(c, z) {
                    continue;
                }
                valid = true;
                through *= 1.0 - clamp_alpha(s.alpha);
                let r = p.lens.coc_radius_px(z);
                widest = if r > widest { r } else { widest };
            }
            // The black background of an empty pixel, or behind slots that end translucent.
            if n == 0 || (valid && through > 0.0) {
                let r = p.lens.coc_radius_px(f32::INFINITY);
                widest = if r > widest { r } else { widest };
            }
            i += stride;
        }
        sh[lid as usize] = widest.to_bits();
    });
    let w = reduce(g, sh, 0, Max);
    g.each(|lid| {
        if lid == 0 {
            st.atomic_max(stats::WIDEST, w);
        }
    });
}

pub fn finish_pass<G: Group, M: Mem>(g: &mut G, p: &SplatParams, mut st: M) {
    g.each(|lid| {
        if lid != 0 {
            return;
        }
        let widest = f32::from_bits(st.load(stats::WIDEST));
        // Run with the last merging step's parameters: `cell` is the merged cells' edge.
        // A fragment with a footprint reaches `footprint::REACH` beyond its CoC, not half a pixel.
        let widest = if p.footprint_side() > 0 { widest + crate::footprint::REACH - 0.5 } else { widest };
        let (rings, cap) = rings_for(widest, p.cell, p.max_radius, p.tile);
        st.store(stats::RINGS, rings);
        st.store(stats::RADIUS_CAP, cap.to_bits());
    });
}

kernel!(
    /// The largest CoC radius of the input, into the frame words.
    PLAN_REDUCE = splat_plan_reduce [256 subgroups] (SplatParams) shared [u32; 2 * 256] { read layers, read counts, st } => reduce_pass
);
kernel!(
    /// Rings and radius cap from the reduction.
    PLAN_FINISH = splat_plan_finish [64] (SplatParams) { st } => finish_pass
);
