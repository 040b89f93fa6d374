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

/// Depth at and beyond which a surface is the **background** (read as a fragment at depth `+inf`):
/// 10^10 scene units.
///
/// - Blender writes exactly 10^10 as the depth of pixels where no surface was hit (Cycles and
///   Eevee), so the threshold is that value: `>=` takes it in.
/// - Tools writing `f32::MAX` or `+inf` (and any depth stored as half float above 65 504, which
///   becomes `+inf`) are beyond it.
/// - 65 504, the largest finite half float, is *not* a threshold: scenes in millimetres or
///   centimetres hold real surfaces farther than that. 10^10 is beyond any real surface in any unit
///   a renderer uses (10^10 mm is 10 000 km).
/// - Moving a surface from `z >= 10^10` to infinity changes its circle of confusion
///   `K·|1 − z_f/z|` by at most `K·z_f/10^10`: for any focus distance `z_f` below 10^6 scene units
///   that is under 10^-4 of the far-field limit `K`, far below a pixel. At 10^10 an `f32` depth
///   also has no precision left to speak of (its spacing there is 1024 units).
pub const BACKGROUND_DEPTH: f32 = 1e10;

/// Whether a stored depth is the background: `+inf` or at least [`BACKGROUND_DEPTH`] (NaN is not).
#[inline]
pub fn is_background_depth(depth: f32) -> bool {
    depth >= BACKGROUND_DEPTH
}

/// Counts of the values the policy changed or dropped. Colour and alpha counts are per sample
/// (one channel of one fragment); depth and background counts are per fragment (one layer of one
/// pixel).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SanitizeCounts {
    /// Colour samples that were NaN, set to 0.
    pub color_nan: u64,
    /// Colour samples that were infinite: `+inf` set to [`COLOR_INF_REPLACEMENT`], `-inf` to 0.
    pub color_inf: u64,
    /// Alpha samples that were NaN (set to 0: the fragment is dropped) or outside [0, 1] (clamped).
    pub alpha_invalid: u64,
    /// Fragments with a NaN, zero or negative depth (`-inf` included): dropped, so that layer of the
    /// pixel is empty.
    pub depth_invalid: u64,
    /// Layer slots dropped because their pixel already had a background: a pixel keeps one
    /// background fragment (the first in layer order) and it ends the pixel, so further slots at
    /// background depth are behind it.
    pub behind_background: u64,
    /// Not a repair, for information: background fragments read (depth `+inf` or at least
    /// [`BACKGROUND_DEPTH`]), each kept with its colour at depth `+inf`.
    pub background: u64,
    /// Not a repair, for information: layer slots with alpha 0 and a black colour (empty by
    /// definition, no fragment).
    pub empty_alpha: u64,
    /// Not a repair, but always noted: fragments with alpha 0 and a colour that is not black. The
    /// colour is premultiplied, so such a fragment is light that hides nothing (emission, a glow),
    /// and it is read so: an image whose alpha is 0 everywhere shows its colour, never black.
    pub emission_only: u64,
}

impl SanitizeCounts {
    /// Values the policy had to repair or drop (NaN/Inf colour, invalid alpha, invalid depth, slots
    /// behind the background). The informational counts (`background`, `empty_alpha`) are not
    /// included.
    pub fn repaired(&self) -> u64 {
        self.color_nan + self.color_inf + self.alpha_invalid + self.depth_invalid + self.behind_background
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
            behind_background: self.behind_background + o.behind_background,
            background: self.background + o.background,
            empty_alpha: self.empty_alpha + o.empty_alpha,
            emission_only: self.emission_only + o.emission_only,
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

    /// One alpha sample under the policy (the methods' own, `dof_shaders::slot::clamp_alpha`): NaN → 0,
    /// below 0 → 0, above 1 → 1 (infinities included).
    #[inline]
    pub fn alpha(&mut self, a: f32) -> f32 {
        self.alpha_invalid += dof_shaders::slot::is_alpha_clamped(a) as u64;
        dof_shaders::slot::clamp_alpha(a)
    }

    /// One layer slot of a multi-layer pixel as stored in a file: colour **premultiplied** by alpha
    /// (the OpenEXR convention, and [`Fragment`]'s), alpha (1 where the file has none) and depth.
    /// Returns the fragment, or `None` where the slot is empty:
    ///
    /// 1. alpha is sanitised ([`Self::alpha`]); alpha 0 with a black colour → empty (counted in
    ///    `empty_alpha`; depth is not looked at, so zero-filled empty slots, which
    ///    [`write_layered_exr`] writes with depth `+inf`, are neither a background nor reported as
    ///    bad depth); alpha 0 with a colour is light that hides nothing (counted in `emission_only`);
    /// 2. depth `+inf` or at least [`BACKGROUND_DEPTH`] → the background ([`Self::background`]);
    ///    depth NaN, `<= 0` or `-inf` → dropped, counted in `depth_invalid`;
    /// 3. colour samples are sanitised ([`Self::color`]), and kept premultiplied.
    ///
    /// [`write_layered_exr`]: super::write_layered_exr
    #[inline]
    pub fn fragment(&mut self, premultiplied: [f32; 3], alpha: f32, depth: f32) -> Option<Fragment> {
        let alpha = self.alpha(alpha);
        if alpha == 0.0 && premultiplied.iter().all(|&c| c == 0.0) {
            self.empty_alpha += 1;
            return None;
        }
        if is_background_depth(depth) {
            return Some(self.background(premultiplied));
        }
        if !(depth > 0.0) {
            self.depth_invalid += 1;
            return None;
        }
        self.emission_only += (alpha == 0.0) as u64;
        let color = premultiplied.map(|c| self.color(c));
        Some(Fragment { color, alpha, depth })
    }

    /// The only layer of an RGB+Z pixel: as [`Self::fragment`], except that a pixel at background
    /// depth is the background whatever its alpha (not looked at): the single layer is the whole
    /// pixel, so its stored colour is what lies behind everything, even where a renderer with a
    /// transparent film wrote alpha 0 there (then it is usually black, and stays a black background).
    #[inline]
    pub fn sole_fragment(&mut self, premultiplied: [f32; 3], alpha: f32, depth: f32) -> Option<Fragment> {
        if is_background_depth(depth) {
            return Some(self.background(premultiplied));
        }
        self.fragment(premultiplied, alpha, depth)
    }

    /// The background fragment of a slot stored at background depth: depth `+inf`, alpha 1, and the
    /// stored colour under the colour policy ([`Self::color`]), taken as it is: the colour as
    /// stored is premultiplied, so a partly transparent background becomes the background composited
    /// over black. Counted in `background`.
    #[inline]
    pub fn background(&mut self, premultiplied: [f32; 3]) -> Fragment {
        self.background += 1;
        Fragment { color: premultiplied.map(|c| self.color(c)), alpha: 1.0, depth: f32::INFINITY }
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
        let sky = Fragment { color: [1.0; 3], alpha: 1.0, depth: f32::INFINITY };
        assert_eq!(c.fragment([1.0; 3], 1.0, f32::INFINITY), Some(sky));
        assert_eq!(c.fragment([0.0; 3], 0.0, f32::INFINITY), None, "an empty slot, not a background");
        // Alpha 0 with a colour is not empty: its depth is checked.
        assert_eq!(c.fragment([1.0; 3], 0.0, f32::NAN), None);
        // Premultiplied colour is kept as it is.
        let f = c.fragment([0.5, 0.25, 0.0], 0.5, 2.0).unwrap();
        assert_eq!((f.color, f.alpha), ([0.5, 0.25, 0.0], 0.5));
        assert_eq!(
            c,
            SanitizeCounts {
                color_nan: 1,
                color_inf: 2,
                alpha_invalid: 3,
                depth_invalid: 3,
                behind_background: 0,
                background: 1,
                empty_alpha: 1,
                emission_only: 0
            }
        );
        assert_eq!(c.repaired(), 9);
        // Light that hides nothing: alpha 0 and a colour.
        let glow = c.fragment([0.4, 0.2, 0.0], 0.0, 3.0).unwrap();
        assert_eq!(glow, Fragment { color: [0.4, 0.2, 0.0], alpha: 0.0, depth: 3.0 });
        assert_eq!(c.emission_only, 1);
    }

    #[test]
    fn background_threshold() {
        let mut c = SanitizeCounts::default();
        assert!(!is_background_depth(f32::NAN) && !is_background_depth(9.99e9) && !is_background_depth(65504.0));
        assert!(is_background_depth(1e10) && is_background_depth(f32::MAX) && is_background_depth(f32::INFINITY));
        // Partial alpha at background depth: the stored (premultiplied) colour, alpha 1.
        let b = c.fragment([0.25, f32::NAN, 2.0], 0.5, 1e10).unwrap();
        assert_eq!(b, Fragment { color: [0.25, 0.0, 2.0], alpha: 1.0, depth: f32::INFINITY });
        // A sole layer at background depth is the background even with alpha 0.
        let b = c.sole_fragment([0.0; 3], 0.0, f32::MAX).unwrap();
        assert_eq!(b, Fragment { color: [0.0; 3], alpha: 1.0, depth: f32::INFINITY });
        assert_eq!(c.sole_fragment([1.0; 3], 0.0, 3.0), Some(Fragment { color: [1.0; 3], alpha: 0.0, depth: 3.0 }));
        assert_eq!(c.sole_fragment([0.0; 3], 0.0, 3.0), None);
        assert_eq!((c.background, c.color_nan, c.empty_alpha, c.emission_only), (2, 1, 1, 1));
    }
}
