//! The NaN/Inf policy applied to every value read from an input file (see the [module
//! documentation](super) for the table), and the counts of what it changed.
//!
//! The policy lives here, apart from the EXR decoding, so that every loader applies the same rules
//! and reports them the same way.

use crate::layers::Fragment;

/// What a colour sample of `+inf` becomes: 65 504, the largest finite half float — the brightest
/// value a half-float EXR (what most renderers write) can hold. Clamping to this rather than to
/// `f32::MAX` keeps sums of many such pixels (a splat, a blur) finite in `f32`. Finite colour values
/// above it are kept as they are.
pub const COLOR_INF_REPLACEMENT: f32 = 65504.0;

/// Counts of the values the policy changed or dropped. Colour and alpha counts are per sample
/// (one channel of one fragment); depth and sky counts are per fragment (one layer of one pixel).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SanitizeCounts {
    /// Colour samples that were NaN, set to 0.
    pub color_nan: u64,
    /// Colour samples that were infinite: `+inf` set to [`COLOR_INF_REPLACEMENT`], `-inf` to 0. Also
    /// counts colours that overflowed when divided by a tiny alpha (set to the same maximum).
    pub color_inf: u64,
    /// Alpha samples that were NaN (set to 0: the fragment is dropped) or outside [0, 1] (clamped).
    pub alpha_invalid: u64,
    /// Fragments with a NaN, zero or negative depth (`-inf` included): dropped, so that layer of the
    /// pixel is empty.
    pub depth_invalid: u64,
    /// Not a repair, for information: fragments at depth `+inf` (the sky, stored as no fragment) that
    /// carried a non-zero colour, which is discarded.
    pub sky_with_color: u64,
    /// Not a repair, for information: layer slots with alpha 0 (empty by definition, no fragment).
    pub empty_alpha: u64,
}

impl SanitizeCounts {
    /// Values the policy had to repair or drop (NaN/Inf colour, invalid alpha, invalid depth). The
    /// informational counts (`sky_with_color`, `empty_alpha`) are not included.
    pub fn repaired(&self) -> u64 {
        self.color_nan + self.color_inf + self.alpha_invalid + self.depth_invalid
    }
}

impl std::ops::Add for SanitizeCounts {
    type Output = SanitizeCounts;
    fn add(self, o: SanitizeCounts) -> SanitizeCounts {
        SanitizeCounts {
            color_nan: self.color_nan + o.color_nan,
            color_inf: self.color_inf + o.color_inf,
            alpha_invalid: self.alpha_invalid + o.alpha_invalid,
            depth_invalid: self.depth_invalid + o.depth_invalid,
            sky_with_color: self.sky_with_color + o.sky_with_color,
            empty_alpha: self.empty_alpha + o.empty_alpha,
        }
    }
}

impl std::ops::AddAssign for SanitizeCounts {
    fn add_assign(&mut self, o: SanitizeCounts) {
        *self = *self + o;
    }
}

impl SanitizeCounts {
    /// One colour sample under the policy: NaN → 0, `+inf` → [`COLOR_INF_REPLACEMENT`], `-inf` → 0,
    /// finite values (negative ones included) unchanged.
    #[inline]
    pub fn color(&mut self, c: f32) -> f32 {
        if c.is_nan() {
            self.color_nan += 1;
            0.0
        } else if c == f32::INFINITY {
            self.color_inf += 1;
            COLOR_INF_REPLACEMENT
        } else if c == f32::NEG_INFINITY {
            self.color_inf += 1;
            0.0
        } else {
            c
        }
    }

    /// One alpha sample under the policy: NaN → 0, below 0 → 0, above 1 → 1 (infinities included).
    #[inline]
    pub fn alpha(&mut self, a: f32) -> f32 {
        if a.is_nan() {
            self.alpha_invalid += 1;
            0.0
        } else if a < 0.0 {
            self.alpha_invalid += 1;
            0.0
        } else if a > 1.0 {
            self.alpha_invalid += 1;
            1.0
        } else {
            a
        }
    }

    /// One layer slot of one pixel as stored in a file: colour **premultiplied** by alpha (the
    /// OpenEXR convention), alpha (1 where the file has none) and depth. Returns the fragment (with
    /// straight colour, as [`Fragment`] holds it), or `None` where the slot is empty:
    ///
    /// 1. alpha is sanitised ([`Self::alpha`]); alpha 0 → empty (counted in `empty_alpha`; nothing
    ///    else is looked at, so zero-filled empty slots are not reported as bad depth);
    /// 2. depth `+inf` → the sky, empty (counted in `sky_with_color` if any colour sample is not 0);
    ///    depth NaN, `<= 0` or `-inf` → dropped, counted in `depth_invalid`;
    /// 3. colour samples are sanitised ([`Self::color`]) and divided by alpha; a quotient that
    ///    overflows becomes [`COLOR_INF_REPLACEMENT`] (counted in `color_inf`).
    #[inline]
    pub fn fragment(&mut self, premultiplied: [f32; 3], alpha: f32, depth: f32) -> Option<Fragment> {
        let alpha = self.alpha(alpha);
        if alpha == 0.0 {
            self.empty_alpha += 1;
            return None;
        }
        if depth == f32::INFINITY {
            if premultiplied.iter().any(|&c| c != 0.0) {
                self.sky_with_color += 1;
            }
            return None;
        }
        if !(depth > 0.0) {
            self.depth_invalid += 1;
            return None;
        }
        let mut color = premultiplied.map(|c| self.color(c));
        if alpha != 1.0 {
            for c in &mut color {
                let straight = *c / alpha;
                *c = if straight.is_finite() {
                    straight
                } else {
                    self.color_inf += 1;
                    COLOR_INF_REPLACEMENT
                };
            }
        }
        Some(Fragment { color, alpha, depth })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn policy_table() {
        let mut c = SanitizeCounts::default();
        assert_eq!(c.color(f32::NAN), 0.0);
        assert_eq!(c.color(f32::INFINITY), COLOR_INF_REPLACEMENT);
        assert_eq!(c.color(f32::NEG_INFINITY), 0.0);
        assert_eq!(c.color(-2.5), -2.5);
        assert_eq!(c.alpha(f32::NAN), 0.0);
        assert_eq!(c.alpha(1.5), 1.0);
        assert_eq!(c.alpha(-0.5), 0.0);
        assert_eq!(c.alpha(0.25), 0.25);
        assert_eq!(c.fragment([1.0; 3], 1.0, f32::NAN), None);
        assert_eq!(c.fragment([1.0; 3], 1.0, 0.0), None);
        assert_eq!(c.fragment([1.0; 3], 1.0, f32::INFINITY), None);
        assert_eq!(c.fragment([1.0; 3], 0.0, f32::NAN), None);
        let f = c.fragment([0.5, 0.25, 0.0], 0.5, 2.0).unwrap();
        assert_eq!(f.color, [1.0, 0.5, 0.0]);
        assert_eq!(
            c,
            SanitizeCounts {
                color_nan: 1,
                color_inf: 2,
                alpha_invalid: 3,
                depth_invalid: 2,
                sky_with_color: 1,
                empty_alpha: 1
            }
        );
        assert_eq!(c.repaired(), 8);
    }
}
