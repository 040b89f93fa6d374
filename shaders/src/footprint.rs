//! A fragment's footprint: which sub-samples of its pixel it covers, and the splat weight that
//! spreads it from there.
//!
//! An area-integrated layer image ([`crate::resolve`]) knows, for each fragment, the sub-samples of
//! the pixel's `side × side` grid that saw it (bit `k` for sub-sample `k`, at
//! [`subsample_offset`]). A renderer with multisampling has the same thing: a
//! fragment's sample mask. Splatting a fragment from its pixel's centre puts a sphere 1 px across
//! anywhere in the pixel on the same pixels; splatting it from its sub-samples spreads it over the
//! footprint it really has. With the disc's exact coverage of each destination pixel's box in place
//! of a linear rim, this is what lights the rim pixels of a small, saturated emitter's bokeh as an
//! integral over the pixel's area does (the measurement is in `docs/measurements.md`, "Where
//! `highlights`' region error comes from").
//!
//! A footprint word is the mask in its low [`MAX_BITS`] bits; 0 means "none given": the fragment
//! stands for its whole pixel and is splatted from the centre as before.

use crate::lane::{LaneMask, Lanes};
use crate::slot::SLOT_WORDS;

/// Bits a footprint holds (a 4x4 grid).
pub const MAX_BITS: u32 = 16;
/// The footprint of no sub-sample given.
pub const WHOLE: u32 = 0;
/// How far beyond its CoC radius a footprint's splat reaches from the pixel centre: the farthest
/// sub-sample lies `(side − 1)/(2·side)·√2 < √2/2` from it, and a destination box reaches `√2/2`
/// beyond the point it is tested at.
pub const REACH: f32 = core::f32::consts::SQRT_2;

/// Where sub-sample `k` of a `side` x `side` grid lies in its pixel: the stratum centres
/// `((i + 0.5) / side, (j + 0.5) / side)`, `k = j · side + i` (the pixel centre for `side = 1`).
#[inline]
pub fn subsample_offset(k: u32, side: u32) -> [f32; 2] {
    let s = side as f32;
    [((k % side) as f32 + 0.5) / s, ((k / side) as f32 + 0.5) / s]
}
/// Where a slot buffer of `slots` slots that carries footprints holds slot `index`'s: one word a
/// slot, after the slots.
#[inline]
pub fn slot_word(slots: u32, index: u32) -> u32 {
    SLOT_WORDS * slots + index
}

/// Every sub-sample of a `side × side` grid.
#[inline]
pub fn full(side: u32) -> u32 {
    let n = side * side;
    if n >= 32 { u32::MAX } else { (1u32 << n) - 1 }
}

/// Arc sine on `[-1, 1]` (clamped), from arithmetic and a square root only, so that both targets
/// compute the same bits: GLSL.std.450 `Asin` has no stated precision, and the footprint weights
/// multiply it by `r²`. `x + x³·P(x²)` up to 1/2, a least-squares fit of degree 4 (relative error
/// under 3e-7 in f32), and `π/2 − 2·asin(√((1 − x)/2))` above.
#[inline(always)]
fn asin<V: Lanes>(x: V) -> V {
    let c = V::splat;
    let negative = x.lt(c(0.0));
    let a = V::select(negative, -x, x);
    let a = V::select(c(1.0).lt(a), c(1.0), a);
    let small = a.le(c(0.5));
    let t = V::select(small, a, (c(0.5) * (c(1.0) - a)).sqrt());
    let u = t * t;
    let p = c(0.166_667_3) + u * (c(0.074_963_33) + u * (c(0.045_331_25) + u * (c(0.024_905_317) + u * c(0.040_875_46))));
    let s = t + t * u * p;
    let r = V::select(small, s, c(core::f32::consts::FRAC_PI_2) - c(2.0) * s);
    V::select(negative, -r, r)
}

// The integrals below run per destination pixel, or for several at once ([`crate::lane`]): their
// branches are selects, and the closed form is computed only where some pixel needs it. The disc's
// radius is the fragment's, the same for every pixel. Always inlined, so that the splat walk's copy
// for AVX2 and AVX-512 (`crate::pass_with_simd`) has them in those instructions too.

/// `∫ s(x) dx` with `s(x) = √(r² − x²)`, for `x` in `[−r, r]`.
#[inline(always)]
fn chord_integral<V: Lanes>(x: V, r: f32) -> V {
    let rr = V::splat(r * r);
    let q = rr - x * x;
    let s = V::select(V::splat(0.0).lt(q), q.sqrt(), V::splat(0.0));
    let t = clamp_to(x / V::splat(r), V::splat(1.0));
    V::splat(0.5) * (x * s + rr * asin(t))
}

/// `x` clamped to `[−a, a]`.
#[inline(always)]
fn clamp_to<V: Lanes>(x: V, a: V) -> V {
    V::select(a.lt(x), a, V::select(x.lt(-a), -a, x))
}

/// `∫ min(c, s(x)) dx` over `[x0, x1]`, for `c >= 0` and `s(x) = √(r² − x²)` (0 outside `[−r, r]`):
/// `c` where the chord is longer than `c` (`|x| < a`, `a = √(r² − c²)`), the chord elsewhere.
#[inline(always)]
fn capped_chords<V: Lanes>(c: V, x0: V, x1: V, r: f32) -> V {
    let q = V::splat(r * r) - c * c;
    let a = V::select(V::splat(0.0).lt(q), q.sqrt(), V::splat(0.0));
    let (u0, u1) = (clamp_to(x0, a), clamp_to(x1, a));
    let (v0, v1) = (clamp_to(x0, V::splat(r)), clamp_to(x1, V::splat(r)));
    c * (u1 - u0) + (chord_integral(v1, r) - chord_integral(v0, r)) - (chord_integral(u1, r) - chord_integral(u0, r))
}

/// Area of the disc of radius `r` about the origin inside the box `[x0, x1] × [y0, y1]`, exact (the
/// integral of each vertical chord's length inside `[y0, y1]`, in closed form), in `[0, box area]`.
#[inline(always)]
pub fn disc_box_area<V: Lanes>(r: f32, x0: V, x1: V, y0: V, y1: V) -> V {
    let zero = V::splat(0.0);
    if !(r > 0.0) {
        return zero;
    }
    // The chord at x spans [−s, s]; inside [y0, y1] it is min(y1, s) − max(y0, −s) where positive:
    // for a box above the axis the chords capped at y1 less those capped at y0, below it the
    // mirror image, across it the two halves.
    let above = zero.le(y0);
    let below = !above & y1.le(zero);
    let first = V::select(below, -y0, y1);
    let second = V::select(above, y0, V::select(below, -y1, -y0));
    let sign = V::select(above | below, V::splat(-1.0), V::splat(1.0));
    let area = capped_chords(first, x0, x1, r) + sign * capped_chords(second, x0, x1, r);
    let most = (x1 - x0) * (y1 - y0);
    V::select(most.lt(area), most, V::select(zero.lt(area), area, zero))
}

/// The share of a point's disc of radius `r` that falls in the unit box at `[ox, ox + 1] × [oy, oy +
/// 1]` relative to the point: 1 or 0 without the integral where the box lies wholly inside or
/// outside; a point source (`r` under 1e-4) gives its whole share to the box that holds it. The
/// shares of every box of the pixel lattice sum to 1. Only the pixels `active` need a value.
#[inline(always)]
pub fn box_share<V: Lanes>(r: f32, ox: V, oy: V, active: V::Mask) -> V {
    let c = V::splat;
    let (x1, y1) = (ox + c(1.0), oy + c(1.0));
    if !(r >= 1e-4) {
        let holds = ox.le(c(0.0)) & c(0.0).lt(x1) & oy.le(c(0.0)) & c(0.0).lt(y1);
        return V::select(holds, c(1.0), c(0.0));
    }
    // Nearest and farthest points of the box from the origin.
    let nx = V::select(c(0.0).lt(ox), ox, V::select(x1.lt(c(0.0)), -x1, c(0.0)));
    let ny = V::select(c(0.0).lt(oy), oy, V::select(y1.lt(c(0.0)), -y1, c(0.0)));
    let rr = c(r * r);
    let outside = rr.le(nx * nx + ny * ny);
    let fx = V::select(x1.lt(-ox), -ox, x1);
    let fy = V::select(y1.lt(-oy), -oy, y1);
    let inside = (fx * fx + fy * fy).le(rr);
    let area = if (active & !outside & !inside).any() { V::select(inside, c(1.0), disc_box_area(r, ox, x1, oy, y1)) } else { c(1.0) };
    V::select(outside, c(0.0), area / c(core::f32::consts::PI * r * r))
}

/// The weight a pixel whose centre lies at `d` (pixel centre minus the fragment's pixel centre)
/// receives from a fragment of footprint `mask` on a `side × side` grid with CoC radius `r`: the
/// mean over its sub-samples of [`box_share`]. Normalised: a fragment's weights over the pixel
/// lattice sum to 1, so it spreads exactly its energy. Per pixel, or for several at once of which
/// only those `active` need a value.
#[inline(always)]
pub fn weight_at<V: Lanes>(mask: u32, side: u32, d: [V; 2], r: f32, active: V::Mask) -> V {
    // Every sub-sample's box inside the disc (no sub-sample lies farther than REACH − √2/2 from
    // the pixel centre, no box corner farther than √2/2 from its centre).
    let d2 = d[0] * d[0] + d[1] * d[1];
    let inner = r - REACH;
    let interior = V::Mask::splat(inner > 0.0) & d2.le(V::splat(inner * inner));
    let whole = V::splat(1.0 / (core::f32::consts::PI * r * r));
    if !(active & !interior).any() {
        return whole;
    }
    let n = side * side;
    let (mut sum, mut count) = (V::splat(0.0), 0u32);
    let mut k = 0;
    while k < n && k < MAX_BITS {
        if mask & (1 << k) != 0 {
            // The destination box relative to sub-sample k: the pixel centre is at d + ½ from the
            // fragment pixel's corner, the sub-sample at its offset.
            let o = subsample_offset(k, side);
            sum = sum + box_share(r, d[0] - V::splat(o[0]), d[1] - V::splat(o[1]), active & !interior);
            count += 1;
        }
        k += 1;
    }
    V::select(interior, whole, if count == 0 { V::splat(0.0) } else { sum / V::splat(count as f32) })
}

/// [`weight_at`] for one pixel.
#[inline]
pub fn weight(mask: u32, side: u32, d: [f32; 2], r: f32) -> f32 {
    weight_at(mask, side, d, r, true)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The disc's area inside a box by a fine midpoint rule.
    fn brute(r: f32, x0: f32, x1: f32, y0: f32, y1: f32) -> f64 {
        let g = 400;
        let (mut inside, cell) = (0u64, ((x1 - x0) as f64 / g as f64) * ((y1 - y0) as f64 / g as f64));
        for j in 0..g {
            for i in 0..g {
                let x = x0 as f64 + (x1 - x0) as f64 * (i as f64 + 0.5) / g as f64;
                let y = y0 as f64 + (y1 - y0) as f64 * (j as f64 + 0.5) / g as f64;
                inside += (x * x + y * y < (r * r) as f64) as u64;
            }
        }
        inside as f64 * cell
    }

    #[test]
    fn asin_is_within_3e_7_of_the_library() {
        let mut worst = 0.0f64;
        for i in 0..=200_000 {
            let x = -1.0 + 2.0 * i as f32 / 200_000.0;
            let want = (x as f64).asin();
            let err = (asin(x) as f64 - want).abs() / want.abs().max(1e-30);
            worst = worst.max(if want == 0.0 { asin(x).abs() as f64 } else { err });
        }
        assert!(worst < 3e-7, "worst relative error {worst}");
        assert_eq!(asin(2.0f32), core::f32::consts::FRAC_PI_2);
        assert_eq!(asin(-7.0f32), -core::f32::consts::FRAC_PI_2);
    }

    /// The CPU walks several pixels at once: each lane's weight is the one-pixel weight, bit for
    /// bit, whichever of its neighbours need the integral, and lanes left inactive do not matter.
    #[test]
    fn weights_for_several_pixels_are_each_pixels_weight() {
        use crate::lane::{LaneMask, Wide, WideMask};
        for side in 1..=4u32 {
            for mask in [full(side), 1, 0b1001, 0b0110_1001_0000_0011] {
                for r in [1e-5f32, 0.3, 1.2, 2.5, 6.0, 40.0] {
                    for y in -8..=8 {
                        for x0 in (-9..=9).step_by(Wide::N) {
                            let xs = Wide::from_fn(|l| (x0 + l as i32) as f32);
                            let ys = Wide::splat(y as f32);
                            let active = WideMask::from_fn(|l| (x0 + l as i32 + y) % 3 != 0);
                            let w = weight_at(mask, side, [xs, ys], r, active);
                            for l in 0..Wide::N {
                                if active.test(l) {
                                    let one = weight(mask, side, [xs.lane(l), y as f32], r);
                                    assert_eq!(
                                        w.lane(l).to_bits(),
                                        one.to_bits(),
                                        "side {side} mask {mask:#x} r {r} at ({}, {y})",
                                        xs.lane(l)
                                    );
                                }
                            }
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn the_disc_in_a_box_matches_a_midpoint_rule() {
        for &r in &[0.05f32, 0.3, 0.7, 1.0, 1.6, 3.3, 7.5] {
            for &(x0, y0) in &[(-0.5f32, -0.5f32), (0.0, 0.0), (-1.2, 0.3), (0.4, -2.1), (r - 0.5, -0.5), (-r - 0.4, r - 0.7), (2.0, 2.0)] {
                let a = disc_box_area(r, x0, x0 + 1.0, y0, y0 + 1.0) as f64;
                let b = brute(r, x0, x0 + 1.0, y0, y0 + 1.0);
                assert!((a - b).abs() < 2e-3 * (1.0 + b), "r {r} box at ({x0}, {y0}): {a} against {b}");
            }
        }
    }

    #[test]
    fn a_box_over_the_whole_disc_holds_all_of_it() {
        for &r in &[0.01f32, 0.5, 2.0, 9.0] {
            let a = disc_box_area(r, -r - 1.0, r + 0.5, -r - 0.25, r + 2.0);
            let want = core::f32::consts::PI * r * r;
            assert!((a - want).abs() <= 1e-5 * want.max(1e-3), "{r}: {a} against {want}");
        }
    }

    /// Shares over the lattice sum to 1 from any sub-sample, for point sources and wide discs.
    #[test]
    fn shares_over_the_lattice_sum_to_one() {
        for &r in &[0.0f32, 5e-5, 0.2, 0.6, 1.0, 2.4, 6.0, 13.7] {
            for side in 1..=4u32 {
                for mask in [full(side), 1, 1 << (side * side - 1), 0b0110 & full(side)] {
                    if mask == 0 {
                        continue;
                    }
                    let reach = (r + 2.0).ceil() as i32;
                    let mut sum = 0.0f64;
                    for y in -reach..=reach {
                        for x in -reach..=reach {
                            sum += weight(mask, side, [x as f32, y as f32], r) as f64;
                        }
                    }
                    assert!((sum - 1.0).abs() < 2e-4, "r {r} side {side} mask {mask:b}: {sum}");
                }
            }
        }
    }

    #[test]
    fn a_footprint_reaches_no_farther_than_its_bound() {
        for &r in &[0.3f32, 1.0, 3.7] {
            for side in [2u32, 4] {
                for y in -8..=8 {
                    for x in -8..=8 {
                        let d = ((x * x + y * y) as f32).sqrt();
                        if weight(full(side), side, [x as f32, y as f32], r) > 0.0 {
                            assert!(d < r + REACH, "r {r}: ({x}, {y}) lit");
                        }
                    }
                }
            }
        }
    }

    /// A sub-sample in the pixel's top-left corner lights its left and upper neighbours more than
    /// its right and lower ones.
    #[test]
    fn the_footprint_moves_the_disc() {
        let r = 1.2;
        let corner = 1; // sub-sample 0 of a 2x2 grid
        assert!(weight(corner, 2, [-1.0, 0.0], r) > weight(corner, 2, [1.0, 0.0], r));
        assert!(weight(corner, 2, [0.0, -1.0], r) > weight(corner, 2, [0.0, 1.0], r));
        let whole = full(2);
        assert!((weight(whole, 2, [-1.0, 0.0], r) - weight(whole, 2, [1.0, 0.0], r)).abs() < 1e-6);
    }
}
