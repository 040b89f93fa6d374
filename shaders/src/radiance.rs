//! The numerical contract on input colour, shared by every method (see `docs/methods.md`,
//! "Numerical contract").
//!
//! A method reads an input colour through [`clamp_color`] where it loads it, after its own test for
//! non-finite values (which it drops). A finite channel comes out in `{0} ∪ [MIN_POSITIVE,
//! COLOR_MAX]`: negative values and subnormals become 0, values above [`COLOR_MAX`] become
//! [`COLOR_MAX`]; the rest pass unchanged, bit for bit. Non-finite channels pass unchanged (the
//! caller drops them). With every colour at most `COLOR_MAX = 2^100`, a weighted sum of up to
//! `2^27` colours with weights of at most 1 stays finite in f32, and so does its division by a
//! total weight of at least `2^-20`: room that every method's accumulation stays within.

use crate::exec::{Group, Load, Mem};
use crate::lens::{is_finite, is_positive};
use crate::wg::for_each_item;

/// Largest colour a method reads (2^100 ≈ 1.27e30); larger finite values are clamped to it.
pub const COLOR_MAX: f32 = 1.267_650_6e30;

/// One channel under the contract: finite values into `{0} ∪ [f32::MIN_POSITIVE, COLOR_MAX]`;
/// NaN and ±inf unchanged.
#[inline]
pub fn clamp_channel(v: f32) -> f32 {
    if v > COLOR_MAX && v <= f32::MAX {
        COLOR_MAX
    } else if v < f32::MIN_POSITIVE && v >= -f32::MAX {
        // Negative, zero (either sign) or subnormal: 0. A device may flush subnormals anyway; this
        // makes the CPU backend do the same.
        0.0
    } else {
        v
    }
}

/// A colour under the contract (see [`clamp_channel`]).
#[inline]
pub fn clamp_color(c: [f32; 3]) -> [f32; 3] {
    [clamp_channel(c[0]), clamp_channel(c[1]), clamp_channel(c[2])]
}

/// Whether [`clamp_color`] changes the value of `c` (−0.0 and subnormal-free zero are unchanged):
/// what a method's report counts as clamped.
#[inline]
pub fn is_clamped(c: [f32; 3]) -> bool {
    let d = clamp_color(c);
    // NaN never compares equal: such a colour is dropped, not clamped.
    let same = |a: f32, b: f32| a == b || crate::lens::is_nan(a);
    !(same(c[0], d[0]) && same(c[1], d[1]) && same(c[2], d[2]))
}

/// What [`COUNT_CLAMPED`] reads: the multi-layer input's size and where the count goes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct ClampCountParams {
    pub pixels: u32,
    /// Slots per pixel of the input.
    pub layers: u32,
    /// The word of `stats` the count is added to.
    pub stats_at: u32,
    /// Slots a pixel the method reads, front first (1 for the single-layer methods).
    pub reads: u32,
}

/// Adds to `stats[stats_at]` the values among the slots of the input ([`crate::slot`]; `counts`
/// used per pixel; the first `reads` of each pixel) a method keeps (finite colour, positive depth)
/// that its reads clamp: colours [`clamp_color`] changes and alphas `slot::clamp_alpha` changes (NaN
/// or outside [0, 1]), one each. The count the reports of the methods that clamp where they load give.
pub fn count_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &ClampCountParams, slots: R, counts: R, mut stats: M) {
    for_each_item(g, p.pixels, |i| {
        let n = counts.load(i).min(p.layers).min(p.reads);
        let mut clamped = 0u32;
        let mut k = 0;
        while k < n {
            let s = crate::slot::load(&slots, i * p.layers + k);
            let c = s.color;
            let kept = is_finite(c[0]) && is_finite(c[1]) && is_finite(c[2]) && is_positive(s.depth);
            if kept {
                clamped += is_clamped(c) as u32 + crate::slot::is_alpha_clamped(s.alpha) as u32;
            }
            k += 1;
        }
        if clamped > 0 {
            stats.atomic_add(p.stats_at, clamped);
        }
    });
}

kernel!(
    /// Counts the input colours the numerical contract clamps.
    COUNT_CLAMPED = radiance_count_clamped [256] (ClampCountParams) { read slots, read counts, stats } => count_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 1] = [&COUNT_CLAMPED];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_maximum_is_two_to_the_hundred() {
        assert_eq!(COLOR_MAX.to_bits(), (127 + 100) << 23);
    }

    #[test]
    fn channels_land_in_the_contract_range() {
        assert_eq!(clamp_channel(f32::MAX), COLOR_MAX);
        assert_eq!(clamp_channel(3e38), COLOR_MAX);
        assert_eq!(clamp_channel(1e30), 1e30);
        assert_eq!(clamp_channel(COLOR_MAX), COLOR_MAX);
        assert_eq!(clamp_channel(0.5), 0.5);
        assert_eq!(clamp_channel(f32::MIN_POSITIVE), f32::MIN_POSITIVE);
        assert_eq!(clamp_channel(1e-40), 0.0);
        assert_eq!(clamp_channel(-1.0).to_bits(), 0);
        assert_eq!(clamp_channel(-0.0).to_bits(), 0);
        assert_eq!(clamp_channel(-f32::MAX), 0.0);
        assert!(clamp_channel(f32::NAN).is_nan());
        assert_eq!(clamp_channel(f32::INFINITY), f32::INFINITY);
        assert_eq!(clamp_channel(f32::NEG_INFINITY), f32::NEG_INFINITY);
    }

    #[test]
    fn clamping_is_counted_only_when_it_changes_a_value() {
        assert!(!is_clamped([0.0, 1.0, 1e30]));
        assert!(!is_clamped([-0.0, 0.0, 0.0]));
        assert!(!is_clamped([f32::NAN, 1.0, 1.0]));
        assert!(is_clamped([1e38, 1.0, 1.0]));
        assert!(is_clamped([1.0, -1.0, 1.0]));
        assert!(is_clamped([1.0, 1.0, 1e-40]));
    }
}
