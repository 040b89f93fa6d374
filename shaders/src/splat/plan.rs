//! Stage 0: the frame's plan, decided on the device from the input, so that no pass over the image
//! runs on the host and nothing is read back between stages.
//!
//! - `splat_plan_reduce` (grid-stride over pixels): the largest CoC radius present (an empty pixel
//!   counts as the background at infinite depth) and the brightest colour channel, reduced in
//!   workgroup memory and then with one atomic maximum per workgroup into the frame words.
//! - `splat_plan_finish` (one invocation): from those two, the tile rings fragments may reach, the
//!   radius cap the rings allow, and the power of two that brings the brightest colour into the
//!   half-float range. Every later kernel reads them through [`planned`].

use super::pack::{input_slot, is_valid};
use super::{MAX_RINGS, SplatParams, THREADS, stats};
use crate::exec::{Group, Mem};
use crate::half::HALF_MAX;
use crate::wg::{inclusive_scan, max};

/// The push constants with the device plan's fields (`rings`, `max_radius`, `color_scale`) read
/// from the frame words that `splat_plan_finish` wrote.
#[inline]
pub fn planned<M: Mem>(p: &SplatParams, st: &M) -> SplatParams {
    let mut q = *p;
    q.rings = st.load(stats::RINGS);
    q.max_radius = f32::from_bits(st.load(stats::RADIUS_CAP));
    q.color_scale = f32::from_bits(st.load(stats::COLOR_SCALE));
    q
}

/// The largest power of two `s <= 1` with `brightest · s` within the half-float range.
#[inline]
pub fn color_scale(brightest: f32) -> f32 {
    let mut s = 1.0f32;
    while brightest * s > HALF_MAX && s > f32::MIN_POSITIVE {
        s *= 0.5;
    }
    s
}

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

pub fn reduce_pass<G: Group, M: Mem>(g: &mut G, p: &SplatParams, sh: &mut [u32; 4 * THREADS as usize], layers: M, counts: M, mut st: M) {
    let pixels = p.width * p.height;
    let t = THREADS as usize;
    // [0, 2T): scan of the widest radius; [2T, 4T): scan of the brightest channel. Both are
    // non-negative floats (or +inf), whose bits order like their values.
    let stride = g.num_workgroups()[0] * THREADS;
    let base = g.workgroup_id()[0] * THREADS;
    g.each(|lid| {
        let (mut widest, mut brightest) = (0.0f32, 0.0f32);
        let mut i = base + lid;
        while i < pixels {
            let n = counts.load(i);
            let n = if n < p.layers { n } else { p.layers };
            if n == 0 {
                let r = p.lens.coc_radius_px(f32::INFINITY);
                widest = if r > widest { r } else { widest };
            }
            let mut k = 0;
            while k < n {
                let (c, z) = input_slot(&layers, p, i, k);
                k += 1;
                if !is_valid(c, z) {
                    continue;
                }
                let r = p.lens.coc_radius_px(z);
                widest = if r > widest { r } else { widest };
                let mut j = 0;
                while j < 3 {
                    let a = if c[j] < 0.0 { -c[j] } else { c[j] };
                    brightest = if a > brightest { a } else { brightest };
                    j += 1;
                }
            }
            i += stride;
        }
        sh[lid as usize] = widest.to_bits();
        sh[2 * t + lid as usize] = brightest.to_bits();
    });
    let w = inclusive_scan(g, sh, 0, max);
    let b = inclusive_scan(g, sh, 2 * t, max);
    g.each(|lid| {
        if lid == THREADS - 1 {
            st.atomic_max(stats::WIDEST, sh[w + lid as usize]);
            st.atomic_max(stats::BRIGHTEST, sh[b + lid as usize]);
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
        let (rings, cap) = rings_for(widest, p.cell, p.max_radius, p.tile);
        st.store(stats::RINGS, rings);
        st.store(stats::RADIUS_CAP, cap.to_bits());
        st.store(stats::COLOR_SCALE, color_scale(f32::from_bits(st.load(stats::BRIGHTEST))).to_bits());
    });
}

kernel!(
    /// The largest CoC radius and the brightest channel of the input, into the frame words.
    PLAN_REDUCE = splat_plan_reduce [256] (SplatParams) shared [u32; 4 * 256] { layers, counts, st } reads { layers, counts } => reduce_pass
);
kernel!(
    /// Rings, radius cap and colour scale from the reduction.
    PLAN_FINISH = splat_plan_finish [64] (SplatParams) { st } => finish_pass
);
