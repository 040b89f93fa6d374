//! Thin-lens ray tracing through the multi-layer image (in the spirit of Lee et al. 2010, the
//! high-quality comparison of Franke et al. 2018): every pixel shoots `spp` rays from stratified points on
//! the lens through its point on the focus plane and returns the mean colour of the first fragments
//! they hit.
//!
//! Geometry. A ray from the lens point at `s` (unit disc, in aperture radii) through pixel centre
//! `c` meets depth `z` where a pinhole sees image position `c + s·r(z)`, with `r(z)` the signed CoC
//! radius in pixels ([`ThinLens::signed_coc_px`] / 2: negative before the focus plane, positive
//! behind, `K/2` at infinity). `r` grows with depth, so the ray is a straight screen-space segment
//! along which `r` is the depth coordinate, marched front to back from the image's smallest `r` to
//! the sky's. While the ray is inside pixel `q` its `r` spans an interval; a fragment of `q` whose
//! `r` falls in it is hit (each fragment is a pixel-sized slab, so the test needs no thickness
//! parameter, and the central ray (`s = 0`) hits the front fragment: the pinhole image).
//!
//! Acceleration: a min/max hierarchy of `r` (level 0 per pixel, each level halving both sides).
//! A block whose `[min, max]` misses the ray's `r` interval inside it is skipped whole and the march
//! climbs a level; a block that may hold a hit is descended into.
//!
//! Fragments carry alpha ([`crate::slot`]): the ray composites the fragments it hits front to back
//! ("over", premultiplied colour) and ends at the first that makes it opaque; an opaque first hit
//! is returned as it is. Pixels without fragments are the sky: black, at `r = K/2`. A ray that
//! leaves the image, or passes behind every stored fragment (information the multi-layer image does
//! not hold), takes the deepest fragment at the pixel where it ended (clamped to the image), if that
//! lies behind what it passed through, and is counted; where nothing lies behind, a ray that passed
//! through translucent fragments sees black behind them (a pixel's slots composite over black).
//! Non-finite colours and depths are never hit.

use crate::exec::{Group, Load, Mem};
use crate::lens::{ThinLens, is_finite};
use crate::math::floor;
use crate::slot::{self, Composite};
use crate::wg::for_each_item;

/// Pixels per side of a trace workgroup.
pub const TILE: u32 = 8;
/// Hierarchy levels at most (level `k` has cells of `2^k` pixels): enough for 8192-pixel sides.
pub const MAX_LEVELS: u32 = 14;
/// Words per fragment slot of the input ([`crate::slot`]).
pub use crate::slot::SLOT_WORDS;
/// Stats words: [0] rays that ended without a hit.
pub const STATS_WORDS: u32 = 1;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct TraceParams {
    pub width: u32,
    pub height: u32,
    /// Fragment slots per pixel of the input (L).
    pub max_layers: u32,
    /// Hierarchy levels built, `1..=MAX_LEVELS`.
    pub levels: u32,
    /// Rays per pixel.
    pub spp: u32,
    /// Sample patterns in the sample buffer (each `spp` points); pixels pick one by a hash.
    pub patterns: u32,
    /// The level a reduction pass writes (`1..levels`); unused by the other kernels.
    pub level: u32,
    pub _pad: u32,
    pub lens: ThinLens,
    /// First cell of each level in the hierarchy buffer ([`level_offsets`]), so the march does not
    /// recompute them per step.
    pub offsets: [u32; MAX_LEVELS as usize],
    pub _pad2: [u32; 2],
}

// Push constants are guaranteed only up to 128 bytes.
const _: () = assert!(core::mem::size_of::<TraceParams>() <= 128);

/// Cells per row and column of hierarchy level `k`.
#[inline]
pub fn level_size(p: &TraceParams, k: u32) -> (u32, u32) {
    let b = 1u32 << k;
    (p.width.div_ceil(b), p.height.div_ceil(b))
}

/// First cell of level `k` in the hierarchy buffer (two words a cell: min and max `r`).
#[inline]
pub fn level_offset(p: &TraceParams, k: u32) -> u32 {
    p.offsets[k as usize]
}

/// The level offsets for `p.width`, `p.height` and `p.levels`: entry `k < levels` is the first cell
/// of level `k`, entry `levels` (when it fits) the total cell count. Host side.
#[cfg(not(target_arch = "spirv"))]
pub fn level_offsets(p: &TraceParams) -> ([u32; MAX_LEVELS as usize], u64) {
    let mut offsets = [0u32; MAX_LEVELS as usize];
    let mut total = 0u64;
    for k in 0..p.levels.min(MAX_LEVELS) {
        offsets[k as usize] = total as u32;
        let (w, h) = level_size(p, k);
        total += w as u64 * h as u64;
    }
    (offsets, total)
}

/// Levels needed until one cell covers the image, at most [`MAX_LEVELS`].
pub fn levels_for(width: u32, height: u32) -> u32 {
    let mut levels = 1;
    while levels < MAX_LEVELS && (width.max(height) > (1u32 << (levels - 1))) {
        levels += 1;
    }
    levels
}

/// Signed CoC radius in pixels: the ray's depth coordinate.
#[inline]
fn ray_r(lens: &ThinLens, z: f32) -> f32 {
    0.5 * lens.signed_coc_px(z)
}

/// The `r` of the sky.
#[inline]
fn sky_r(lens: &ThinLens) -> f32 {
    0.5 * lens.far_limit_px()
}

/// Fragment `j` of pixel `pi`: premultiplied colour, `r` and alpha, or `None` when it is not
/// finite.
#[inline]
fn fragment(p: &TraceParams, input: &impl Load, pi: u32, j: u32) -> Option<([f32; 3], f32, f32)> {
    let s = slot::load(input, pi * p.max_layers + j);
    if slot::is_valid(&s) {
        let r = ray_r(&p.lens, s.depth);
        if is_finite(r) {
            return Some((crate::radiance::clamp_color(s.color), r, slot::clamp_alpha(s.alpha)));
        }
    }
    None
}

/// Level 0: per pixel, the smallest and largest `r` of its fragments (the sky's for a pixel
/// without fragments; an empty interval when none is usable).
pub fn base_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &TraceParams, input: R, counts: R, mut hier: M) {
    for_each_item(g, p.width * p.height, |pi| {
        let n = counts.load(pi).min(p.max_layers);
        let (mut lo, mut hi) = if n == 0 { (sky_r(&p.lens), sky_r(&p.lens)) } else { (f32::INFINITY, f32::NEG_INFINITY) };
        let mut j = 0;
        while j < n {
            if let Some((_, r, _)) = fragment(p, &input, pi, j) {
                lo = lo.min(r);
                hi = hi.max(r);
            }
            j += 1;
        }
        hier.store(2 * pi, lo.to_bits());
        hier.store(2 * pi + 1, hi.to_bits());
    });
}

/// Level `p.level` from the level below: min of the mins and max of the maxes of the 2x2 children.
pub fn reduce_pass<G: Group, M: Mem>(g: &mut G, p: &TraceParams, mut hier: M) {
    let (w, h) = level_size(p, p.level);
    let (cw, ch) = level_size(p, p.level - 1);
    let (dst, src) = (level_offset(p, p.level), level_offset(p, p.level - 1));
    for_each_item(g, w * h, |cell| {
        let (x, y) = (cell % w, cell / w);
        let (mut lo, mut hi) = (f32::INFINITY, f32::NEG_INFINITY);
        let mut k = 0;
        while k < 4 {
            let (cx, cy) = (2 * x + k % 2, 2 * y + k / 2);
            if cx < cw && cy < ch {
                let at = src + cy * cw + cx;
                lo = lo.min(f32::from_bits(hier.load(2 * at)));
                hi = hi.max(f32::from_bits(hier.load(2 * at + 1)));
            }
            k += 1;
        }
        hier.store(2 * (dst + cell), lo.to_bits());
        hier.store(2 * (dst + cell) + 1, hi.to_bits());
    });
}

/// The `r` at which a ray from `c` along `s` leaves the `size`-pixel block `b` along one axis.
#[inline]
fn exit_r(c: f32, s: f32, b: u32, size: u32) -> f32 {
    if s > 0.0 {
        ((b + 1) as f32 * size as f32 - c) / s
    } else if s < 0.0 {
        (b as f32 * size as f32 - c) / s
    } else {
        f32::INFINITY
    }
}

/// The `r` interval in which a ray from `c` along `s` stays inside `[0, extent)` on one axis.
#[inline]
fn span(c: f32, s: f32, extent: f32) -> (f32, f32) {
    if s == 0.0 {
        return (f32::NEG_INFINITY, f32::INFINITY);
    }
    let (a, b) = (-c / s, (extent - c) / s);
    (a.min(b), a.max(b))
}

/// What one ray returns: its colour and whether it hit a stored fragment.
struct Ray {
    colour: [f32; 3],
    hit: bool,
}

fn trace_ray(p: &TraceParams, input: &impl Load, counts: &impl Load, hier: &impl Load, c: [f32; 2], s: [f32; 2]) -> Ray {
    let top = level_offset(p, p.levels - 1);
    let (w, h) = (p.width as f32, p.height as f32);
    // From the image's nearest `r` to the sky's, clipped to where the ray is inside the image.
    let (in_x, out_x) = span(c[0], s[0], w);
    let (in_y, out_y) = span(c[1], s[1], h);
    let r_start = f32::from_bits(hier.load(2 * top)).max(in_x).max(in_y);
    let r_end = sky_r(&p.lens).min(out_x).min(out_y);
    // Past a block boundary by a hundredth of a pixel, so the next block is entered.
    let speed = s[0].abs().max(s[1].abs());
    let nudge = if speed > 0.0 { 0.01 / speed } else { f32::INFINITY };
    let mut r = r_start;
    let mut level = 0u32;
    let mut steps = 0u32;
    let max_steps = 4 * (p.width + p.height) + 8 * p.levels;
    let mut last_pixel = (c[1] as u32) * p.width + c[0] as u32;
    // What the ray passed through (translucent fragments), and the last of them.
    let mut over = Composite::EMPTY;
    let (mut hit_pixel, mut hit_slot, mut hit_r) = (u32::MAX, 0u32, f32::NEG_INFINITY);
    while r <= r_end && steps < max_steps {
        steps += 1;
        let (x, y) = (c[0] + s[0] * r, c[1] + s[1] * r);
        if !(x >= 0.0 && y >= 0.0 && x < w && y < h) {
            break;
        }
        let (px, py) = (floor(x) as u32, floor(y) as u32);
        last_pixel = py * p.width + px;
        let (bx, by) = (px >> level, py >> level);
        let size = 1u32 << level;
        let leave = exit_r(c[0], s[0], bx, size).min(exit_r(c[1], s[1], by, size)).min(r_end);
        let (lw, _) = level_size(p, level);
        let cell = level_offset(p, level) + by * lw + bx;
        let (lo, hi) = (f32::from_bits(hier.load(2 * cell)), f32::from_bits(hier.load(2 * cell + 1)));
        let slack = 1e-5 * (r.abs() + leave.abs() + 1.0);
        if hi < r - slack || lo > leave + slack {
            r = leave + nudge;
            if level + 1 < p.levels {
                level += 1;
            }
        } else if level > 0 {
            level -= 1;
        } else {
            let n = counts.load(last_pixel).min(p.max_layers);
            if n == 0 {
                // No data: black, behind whatever the ray passed through.
                return Ray { colour: over.color, hit: true };
            }
            let mut j = 0;
            while j < n {
                if let Some((colour, rf, a)) = fragment(p, input, last_pixel, j) {
                    // Each fragment once: the slack lets neighbouring blocks' intervals overlap.
                    let new = last_pixel != hit_pixel || j > hit_slot;
                    if new && rf >= r - slack && rf <= leave + slack {
                        if a >= 1.0 && over.is_empty() {
                            return Ray { colour, hit: true };
                        }
                        // Translucent: composited front to back ("over"); the ray goes on.
                        over.add(colour, a);
                        hit_pixel = last_pixel;
                        hit_slot = j;
                        hit_r = rf;
                        if over.transmit <= 0.0 {
                            return Ray { colour: over.color, hit: true };
                        }
                    }
                }
                j += 1;
            }
            r = leave + nudge;
        }
    }
    // No opaque hit: the deepest usable fragment where the ray ended (black for the sky), if it lies
    // behind what the ray passed through; none there is black behind them (a pixel's slots
    // composite over black), a hit.
    let mut behind = None;
    let n = counts.load(last_pixel).min(p.max_layers);
    let mut j = 0;
    while j < n {
        if let Some((c, rf, _)) = fragment(p, input, last_pixel, j) {
            if rf > hit_r && (last_pixel != hit_pixel || j > hit_slot) {
                behind = Some(c);
            }
        }
        j += 1;
    }
    match behind {
        Some(c) if over.is_empty() => Ray { colour: c, hit: false },
        Some(c) => {
            over.add(c, 1.0);
            Ray { colour: over.color, hit: false }
        }
        None => Ray { colour: over.color, hit: over.transmit < 1.0 },
    }
}

/// A small integer hash (pixels pick their sample pattern by it).
#[inline]
fn hash(mut v: u32) -> u32 {
    v ^= v >> 16;
    v = v.wrapping_mul(0x7feb_352d);
    v ^= v >> 15;
    v = v.wrapping_mul(0x846c_a68b);
    v ^ (v >> 16)
}

/// One invocation per pixel of an 8x8 tile: `spp` rays, their mean into `out`.
pub fn trace_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &TraceParams,
    input: R,
    counts: R,
    hier: R,
    samples: R,
    mut out: M,
    mut stats: M,
) {
    let [wx, wy, _] = g.workgroup_id();
    g.each(|lid| {
        let x = wx * TILE + lid % TILE;
        let y = wy * TILE + lid / TILE;
        if x >= p.width || y >= p.height {
            return;
        }
        let pattern = hash(y * p.width + x) % p.patterns.max(1);
        let c = [x as f32 + 0.5, y as f32 + 0.5];
        // The mean as the first ray's colour plus the mean difference from it: exact when every ray
        // returns the same colour (a pinhole, a sub-pixel blur, a flat field).
        let mut first = [0.0f32; 3];
        let mut acc = [0.0f32; 3];
        let mut misses = 0u32;
        let mut i = 0;
        while i < p.spp {
            let at = 2 * (pattern * p.spp + i);
            let s = [f32::from_bits(samples.load(at)), f32::from_bits(samples.load(at + 1))];
            let ray = trace_ray(p, &input, &counts, &hier, c, s);
            if i == 0 {
                first = ray.colour;
            }
            acc[0] += ray.colour[0] - first[0];
            acc[1] += ray.colour[1] - first[1];
            acc[2] += ray.colour[2] - first[2];
            if !ray.hit {
                misses += 1;
            }
            i += 1;
        }
        let inv = 1.0 / p.spp.max(1) as f32;
        let pi = y * p.width + x;
        out.store(3 * pi, (first[0] + acc[0] * inv).to_bits());
        out.store(3 * pi + 1, (first[1] + acc[1] * inv).to_bits());
        out.store(3 * pi + 2, (first[2] + acc[2] * inv).to_bits());
        if misses > 0 {
            stats.atomic_add(0, misses);
        }
    });
}

kernel!(
    /// Level 0 of the min/max hierarchy of the signed CoC radius, one pixel an invocation.
    RT_BASE = raytrace_base [256] (TraceParams) { read input, read counts, hier } => base_pass
);
kernel!(
    /// One level of the min/max hierarchy from the level below.
    RT_REDUCE = raytrace_reduce [256] (TraceParams) { hier } => reduce_pass
);
kernel!(
    /// `spp` thin-lens rays per pixel through the multi-layer image.
    RT_TRACE = raytrace_trace [64] (TraceParams) { read input, read counts, read hier, read samples, out, stats } => trace_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 3] = [&RT_BASE, &RT_REDUCE, &RT_TRACE];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn levels_reach_one_cell() {
        assert_eq!(levels_for(1, 1), 1);
        assert_eq!(levels_for(2, 1), 2);
        assert_eq!(levels_for(640, 360), 11);
        let mut p = TraceParams { width: 640, height: 360, levels: levels_for(640, 360), ..Default::default() };
        assert_eq!(level_size(&p, p.levels - 1), (1, 1));
        let (offsets, total) = level_offsets(&p);
        p.offsets = offsets;
        assert_eq!(level_offset(&p, 1), 640 * 360);
        assert_eq!(level_offset(&p, 2), 640 * 360 + 320 * 180);
        assert_eq!(total, (level_offset(&p, p.levels - 1) + 1) as u64);
    }

    #[test]
    fn exits_follow_the_direction() {
        assert_eq!(exit_r(2.5, 1.0, 2, 1), 0.5);
        assert_eq!(exit_r(2.5, -1.0, 2, 1), 0.5);
        assert_eq!(exit_r(2.5, -0.5, 0, 4), 5.0);
        assert_eq!(exit_r(2.5, 0.0, 2, 1), f32::INFINITY);
    }
}
