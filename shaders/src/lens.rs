//! The lens models every method shares, evaluated per fragment on both backends.
//!
//! - [`ThinLens`]: the physical thin lens. The circle of confusion (CoC) of a point at planar depth
//!   `z` is `c(z) = A·f·|z − z_f| / (z·(z_f − f))` on the sensor (A = 2·aperture radius, f the focal
//!   length, z_f the focus distance), times `pixels_per_unit` in pixels. Written as
//!   `c(z) = K·|1 − z_f/z|` with `K = A·f/(z_f − f)·pixels_per_unit` ([`ThinLens::far_limit_px`],
//!   the z → ∞ asymptote; `f²/(N·(z_f − f))` for A = f/N) it needs one division per fragment.
//! - [`ArtistLens`]: the linear near/far model of de Rousiers and Pettineo (de Rousiers and Pettineo).
//!
//! Sign convention everywhere: a *signed* CoC is negative in front of the focus plane (near field)
//! and positive behind it (far field); unsigned CoCs are diameters in pixels.
//!
//! Only `f32` arithmetic and comparisons are used (no `sqrt`, no `tan`): this file compiles for the
//! SPIR-V target as well. The host validates lenses (`dof::scene::LensSettings`); on a lens that
//! breaks `0 < f < z_f`, `aperture_radius >= 0`, `pixels_per_unit > 0` the results are unspecified
//! numbers, never a panic.
//!
//! Depth conventions (what each function returns outside the valid range is part of its contract):
//! - `z <= 0`, `z` NaN: NaN (no CoC exists in or behind the lens plane);
//! - `z = +inf` (the sky): the far-field limit;
//! - `0 < z` tiny: the CoC grows like `K·z_f/z` and reaches `+inf` when that overflows.

/// A thin lens in scene units. `#[repr(C)]`: four `f32`, 16 bytes, uploadable as push constants.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct ThinLens {
    /// Focal length f, scene units.
    pub focal_length: f32,
    /// Aperture radius (half the aperture diameter A), scene units. 0: a pinhole.
    pub aperture_radius: f32,
    /// Planar distance of the focus plane z_f, scene units, `> focal_length`.
    pub focus_distance: f32,
    /// Pixels per scene unit on the sensor: image height in pixels / sensor height.
    pub pixels_per_unit: f32,
}

impl ThinLens {
    /// Whether the lens satisfies the contract above (`0 < f < z_f`, all finite, aperture `>= 0`,
    /// `pixels_per_unit > 0`).
    pub fn is_valid(&self) -> bool {
        let finite = is_finite(self.focal_length)
            && is_finite(self.aperture_radius)
            && is_finite(self.focus_distance)
            && is_finite(self.pixels_per_unit);
        finite
            && self.focal_length > 0.0
            && self.focus_distance > self.focal_length
            && self.aperture_radius >= 0.0
            && self.pixels_per_unit > 0.0
    }

    /// The far-field CoC diameter in pixels, the limit of [`Self::coc_px`] as z → ∞:
    /// `A·f/(z_f − f)` on the sensor (`f²/(N·(z_f − f))` for A = f/N), eq. 8's bound.
    #[inline]
    pub fn far_limit_px(&self) -> f32 {
        2.0 * self.aperture_radius * self.focal_length / (self.focus_distance - self.focal_length) * self.pixels_per_unit
    }

    /// Signed CoC diameter in pixels: negative in front of the focus plane, positive behind it,
    /// 0 on it. `z <= 0` or NaN: NaN; `z = inf`: [`Self::far_limit_px`]. A pinhole (aperture 0)
    /// gives 0 for every `z > 0`.
    #[inline]
    pub fn signed_coc_px(&self, z: f32) -> f32 {
        if !is_positive(z) {
            return f32::NAN;
        }
        let k = self.far_limit_px();
        if k == 0.0 {
            // A pinhole; also avoids 0 · inf when z_f/z overflows.
            return 0.0;
        }
        k * (1.0 - self.focus_distance / z)
    }

    /// CoC diameter in pixels, `>= 0` (NaN for `z <= 0` or NaN, see [`Self::signed_coc_px`]).
    #[inline]
    pub fn coc_px(&self, z: f32) -> f32 {
        abs(self.signed_coc_px(z))
    }

    /// CoC radius in pixels for the kernels: half of [`Self::coc_px`], the far-field limit for the
    /// sky (`+inf`, tested on the bits), and 0 for an invalid depth (NaN, `<= 0`), so a bad sample
    /// never widens a window.
    #[inline]
    pub fn coc_radius_px(&self, z: f32) -> f32 {
        let r = if is_pos_inf(z) { 0.5 * self.far_limit_px() } else { 0.5 * self.coc_px(z) };
        if is_nan(r) { 0.0 } else { r }
    }

    /// The two depths whose CoC diameter is `c` pixels (Schedl and Wimmer 2012, eq. 5-7): the near depth
    /// `D1 = z_f·K/(K + c)` in front of the focus plane and the far depth `D2 = z_f·K/(K − c)` behind
    /// it, with `K` = [`Self::far_limit_px`]. Equivalently `[D1, D2]` is the depth interval whose CoC
    /// is at most `c`, so:
    /// - `c >= K` (outside eq. 8's bound): `D2 = +inf` (every depth behind the focus plane qualifies);
    /// - `c = 0`: `(z_f, z_f)`; `c = +inf`: `(0, +inf)`;
    /// - a pinhole (`K = 0`): `(0, +inf)` for every `c >= 0`;
    /// - `c < 0` or NaN: `(NaN, NaN)`.
    #[inline]
    pub fn inverse_px(&self, c: f32) -> (f32, f32) {
        if !(c >= 0.0) {
            return (f32::NAN, f32::NAN);
        }
        let k = self.far_limit_px();
        let zf = self.focus_distance;
        if !(k > 0.0) {
            return (0.0, f32::INFINITY);
        }
        let near = if c == f32::INFINITY { 0.0 } else { zf * k / (k + c) };
        let far = if c >= k { f32::INFINITY } else { zf * k / (k - c) };
        (near, far)
    }

    /// Length (scene units, along the view axis) of the umbra behind a fragment at depth `z` whose
    /// world-space footprint is a disc of radius `footprint_radius` facing the lens: the region no
    /// lens ray reaches (Franke et al. 2018, §4.1 and §6.2 after Lee et al. 2010, with the lens as a disc light
    /// source and the fragment as the occluder). The umbra cone's apex lies where the lines through
    /// the rims of lens and footprint meet: length `r·z/(R − r)` for footprint radius `r` and aperture
    /// radius `R`.
    /// - `r = 0`: 0 (a point hides nothing), also for a pinhole;
    /// - `r >= R` (footprint as large as the aperture): `+inf`, the shadow never closes;
    /// - grows linearly with `z`; `z = inf` with `0 < r < R`: `+inf`;
    /// - `z <= 0`, NaN, or a negative/NaN footprint: NaN.
    #[inline]
    pub fn umbra_length(&self, z: f32, footprint_radius: f32) -> f32 {
        let r = footprint_radius;
        if !is_positive(z) || !(r >= 0.0) || is_nan(r) {
            return f32::NAN;
        }
        if r == 0.0 {
            return 0.0;
        }
        let big_r = self.aperture_radius;
        if r >= big_r {
            return f32::INFINITY;
        }
        r * z / (big_r - r)
    }
}

/// The linear near/far CoC model of de Rousiers and Pettineo: blur grows linearly from 0 at a region's *start*
/// depth to `max_radius_px` at its *end* depth, clamped beyond (`CoC = (z − z_start)/(z_end −
/// z_start)` normalised to [0, 1], then scaled by MaxRadius).
///
/// - near field: blur starts at `near_start` (the near edge of the sharp zone) and is full at
///   `near_end`, closer to the camera: `near_end <= near_start`;
/// - far field: blur starts at `far_start` and is full at `far_end`: `far_start <= far_end`;
/// - the sharp zone `[near_start, far_start]` may be empty but not negative: `near_start <=
///   far_start`.
///
/// An end equal to its start is a step. `#[repr(C)]`: five `f32`, 20 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct ArtistLens {
    pub near_start: f32,
    pub near_end: f32,
    pub far_start: f32,
    pub far_end: f32,
    /// Largest CoC *radius* in pixels, `>= 0`.
    pub max_radius_px: f32,
}

impl ArtistLens {
    /// Whether the ordering above holds, the values are finite and `max_radius_px >= 0` (`far_end`
    /// alone may be `+inf`: no far blur at any finite depth).
    pub fn is_valid(&self) -> bool {
        is_finite(self.near_start)
            && is_finite(self.near_end)
            && is_finite(self.far_start)
            && !is_nan(self.far_end)
            && is_finite(self.max_radius_px)
            && self.near_end <= self.near_start
            && self.near_start <= self.far_start
            && self.far_start <= self.far_end
            && self.max_radius_px >= 0.0
    }

    /// Signed CoC diameter in pixels (`2·radius`): negative in the near field, positive in the far
    /// field, 0 in the sharp zone. `z <= 0` or NaN: NaN; `z = inf`: `2·max_radius_px` (unless
    /// `far_start` is infinite).
    #[inline]
    pub fn signed_coc_px(&self, z: f32) -> f32 {
        if !is_positive(z) {
            return f32::NAN;
        }
        let far = if z <= self.far_start {
            0.0
        } else if z >= self.far_end {
            1.0
        } else {
            (z - self.far_start) / (self.far_end - self.far_start)
        };
        let near = if z >= self.near_start {
            0.0
        } else if z <= self.near_end {
            1.0
        } else {
            (self.near_start - z) / (self.near_start - self.near_end)
        };
        2.0 * self.max_radius_px * (far - near)
    }

    /// CoC diameter in pixels, `>= 0` (NaN for `z <= 0` or NaN).
    #[inline]
    pub fn coc_px(&self, z: f32) -> f32 {
        abs(self.signed_coc_px(z))
    }
}

/// `|x|` by comparison (NaN stays NaN).
#[inline]
fn abs(x: f32) -> f32 {
    if x < 0.0 { -x } else { x }
}

// NaN and infinity are tested on the bits: GPU compilers may assume IEEE specials away in float
// arithmetic and comparisons (Mesa folds `x - x` to 0 and `x == x` to true), never in integer code.

/// Neither NaN nor infinite.
#[inline]
pub fn is_finite(x: f32) -> bool {
    x.to_bits() & 0x7f80_0000 != 0x7f80_0000
}

/// NaN.
#[inline]
pub fn is_nan(x: f32) -> bool {
    x.to_bits() & 0x7fff_ffff > 0x7f80_0000
}

/// `+inf`.
#[inline]
pub fn is_pos_inf(x: f32) -> bool {
    x.to_bits() == 0x7f80_0000
}

/// A valid depth: greater than zero (`+inf` included), not NaN.
#[inline]
pub fn is_positive(z: f32) -> bool {
    let b = z.to_bits();
    b != 0 && b <= 0x7f80_0000
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lens() -> ThinLens {
        // 50 mm f/2 focused at 2 m on a 24 mm sensor imaged onto 1080 rows.
        ThinLens { focal_length: 0.05, aperture_radius: 0.0125, focus_distance: 2.0, pixels_per_unit: 1080.0 / 0.024 }
    }

    #[test]
    fn coc_matches_the_textbook_formula() {
        let l = lens();
        assert!(l.is_valid());
        let a = 2.0 * l.aperture_radius;
        for z in [0.3f32, 1.0, 1.9, 2.0, 2.5, 10.0, 1000.0] {
            let want = a * l.focal_length * (z - l.focus_distance).abs() / (z * (l.focus_distance - l.focal_length)) * l.pixels_per_unit;
            let got = l.coc_px(z);
            assert!((got - want).abs() <= 1e-4 * want.max(1.0), "z={z}: {got} vs {want}");
            assert_eq!(l.signed_coc_px(z) < 0.0, z < l.focus_distance && got > 0.0);
        }
        assert_eq!(l.coc_px(2.0), 0.0);
    }

    #[test]
    fn out_of_range_depths_have_documented_results() {
        let l = lens();
        assert!(l.coc_px(0.0).is_nan());
        assert!(l.coc_px(-1.0).is_nan());
        assert!(l.coc_px(f32::NAN).is_nan());
        assert_eq!(l.coc_px(f32::INFINITY), l.far_limit_px());
        assert_eq!(l.coc_px(f32::MIN_POSITIVE / 4.0), f32::INFINITY);
        let pinhole = ThinLens { aperture_radius: 0.0, ..l };
        assert_eq!(pinhole.coc_px(f32::MIN_POSITIVE / 4.0), 0.0);
        assert_eq!(pinhole.coc_px(f32::INFINITY), 0.0);
    }

    #[test]
    fn inverse_edges() {
        let l = lens();
        assert_eq!(l.inverse_px(0.0), (2.0, 2.0));
        assert_eq!(l.inverse_px(f32::INFINITY), (0.0, f32::INFINITY));
        assert_eq!(l.inverse_px(l.far_limit_px()).1, f32::INFINITY);
        let (n, f) = l.inverse_px(-1.0);
        assert!(n.is_nan() && f.is_nan());
        let pinhole = ThinLens { aperture_radius: 0.0, ..l };
        assert_eq!(pinhole.inverse_px(3.0), (0.0, f32::INFINITY));
    }

    #[test]
    fn umbra_edges() {
        let l = lens();
        assert_eq!(l.umbra_length(1.0, 0.0), 0.0);
        assert_eq!(l.umbra_length(1.0, l.aperture_radius), f32::INFINITY);
        let r = l.aperture_radius / 2.0;
        assert!((l.umbra_length(3.0, r) - 3.0).abs() < 1e-6);
        assert!(l.umbra_length(0.0, r).is_nan());
        assert!(l.umbra_length(1.0, -r).is_nan());
        assert_eq!(l.umbra_length(f32::INFINITY, r), f32::INFINITY);
    }

    #[test]
    fn artist_ramps() {
        let a = ArtistLens { near_start: 2.0, near_end: 1.0, far_start: 5.0, far_end: 9.0, max_radius_px: 8.0 };
        assert!(a.is_valid());
        assert_eq!(a.signed_coc_px(0.5), -16.0);
        assert_eq!(a.signed_coc_px(1.5), -8.0);
        assert_eq!(a.signed_coc_px(3.0), 0.0);
        assert_eq!(a.signed_coc_px(7.0), 8.0);
        assert_eq!(a.signed_coc_px(f32::INFINITY), 16.0);
        assert!(a.coc_px(0.0).is_nan());
        let step = ArtistLens { near_start: 2.0, near_end: 2.0, far_start: 2.0, far_end: 2.0, max_radius_px: 1.0 };
        assert!(step.is_valid());
        assert_eq!(step.coc_px(1.999), 2.0);
        assert_eq!(step.coc_px(2.0), 0.0);
        assert_eq!(step.coc_px(2.001), 2.0);
    }
}
