//! The thin lens from the values a renderer's camera has: focal length, f-number (or aperture
//! radius), focus distance, and the field of view (given directly, from a sensor height, or read
//! from a perspective projection matrix), for an image of a given height.
//!
//! The sensor sits where the focus plane is imaged, `s = f·z_f/(z_f − f)` behind the lens, and
//! spans the camera's field of view there: `pixels_per_unit = height_px / (2·s·tan(yfov/2))`. The
//! CoC in pixels is then `R·|1 − z_f/z|·height_px / (z_f·tan(yfov/2))`, the blur a thin-lens ray
//! tracer with the same camera produces, whatever the focal length.
//!
//! ```
//! use dof_core::lens::{Aperture, CameraLens, yfov_from_projection};
//! # fn main() -> dof_core::Result<()> {
//! // A 50 mm lens at f/2 focused at 3 m, a 24 mm sensor, a 1080-row image (scene units: metres).
//! let lens = CameraLens::from_sensor(0.050, Aperture::FNumber(2.0), 3.0, 0.024, 1080).thin_lens()?;
//! assert!((lens.aperture_radius - 0.0125).abs() < 1e-7);
//! // The field of view of a renderer's projection (column-major, as glam's `to_cols_array_2d`).
//! let cot = 1.0 / (0.4f32).tan();
//! let proj = [[cot / 1.78, 0.0, 0.0, 0.0], [0.0, cot, 0.0, 0.0], [0.0, 0.0, 0.0, -1.0], [0.0, 0.0, 0.1, 0.0]];
//! assert!((yfov_from_projection(&proj)? - 0.8).abs() < 1e-6);
//! # Ok(())
//! # }
//! ```

use crate::error::{Error, Result};
use dof_shaders::lens::ThinLens;

/// How large the aperture is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Aperture {
    /// The f-number N: an aperture diameter of f/N. `+inf` is a pinhole.
    FNumber(f32),
    /// The aperture radius in scene units; 0 is a pinhole.
    Radius(f32),
}

impl Aperture {
    /// The aperture radius in scene units for a focal length `f` (scene units), or why there is none.
    pub fn radius(self, f: f32) -> Result<f32> {
        match self {
            Aperture::FNumber(n) if n > 0.0 => Ok(f / (2.0 * n)),
            Aperture::FNumber(n) => Err(Error::InvalidLens(format!("the f-number must be positive, got {n}"))),
            Aperture::Radius(r) if r >= 0.0 && r.is_finite() => Ok(r),
            Aperture::Radius(r) => Err(Error::InvalidLens(format!("the aperture radius must be finite and not negative, got {r}"))),
        }
    }
}

/// A camera's lens in scene units, and the image it makes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraLens {
    /// Focal length, scene units.
    pub focal_length: f32,
    pub aperture: Aperture,
    /// Planar distance of the focus plane, scene units.
    pub focus_distance: f32,
    /// The camera's vertical field of view, radians.
    pub yfov: f32,
    /// Rows of the image.
    pub height_px: u32,
}

impl CameraLens {
    /// A lens whose field of view is that of a sensor `sensor_height` tall (scene units) at the
    /// focal length (the lens focused at infinity, as cameras and Bevy's `PhysicalCameraParameters`
    /// quote it): `yfov = 2·atan(sensor_height / (2·focal_length))`.
    pub fn from_sensor(focal_length: f32, aperture: Aperture, focus_distance: f32, sensor_height: f32, height_px: u32) -> Self {
        let yfov = 2.0 * (sensor_height / (2.0 * focal_length)).atan();
        CameraLens { focal_length, aperture, focus_distance, yfov, height_px }
    }

    /// The kernels' thin lens, or an [`Error::InvalidLens`] naming the value at fault.
    pub fn thin_lens(&self) -> Result<ThinLens> {
        let yfov = self.yfov;
        if !(yfov > 0.0 && yfov < std::f32::consts::PI) {
            return Err(Error::InvalidLens(format!("the vertical field of view must lie in (0, pi) radians, got {yfov}")));
        }
        let radius = self.aperture.radius(self.focal_length)?;
        thin_lens_for_view(self.focal_length, radius, self.focus_distance, (0.5 * yfov).tan(), self.height_px)
    }
}

/// The vertical field of view (radians) of a perspective projection matrix, column-major
/// (`m[column][row]`, as glam's `Mat4::to_cols_array_2d`): `m[1][1]` is `1/tan(yfov/2)` (negated
/// for a projection that flips y, as Vulkan's often do). Standard, reversed and infinite-far
/// projections alike.
pub fn yfov_from_projection(m: &[[f32; 4]; 4]) -> Result<f32> {
    let cot = m[1][1].abs();
    if !(cot > 0.0 && cot.is_finite()) || m[2][3] == 0.0 || m[3][3] != 0.0 {
        return Err(Error::InvalidLens(format!("not a perspective projection matrix (column-major): {m:?}")));
    }
    Ok(2.0 * (1.0 / cot).atan())
}

/// The thin lens of focal length `f`, aperture radius `radius` and focus distance `zf` (scene
/// units) on a camera whose vertical field of view has `tan(yfov/2) = tan_half_yfov`, for an image
/// `height_px` rows tall (see the [module](self)).
pub fn thin_lens_for_view(f: f32, radius: f32, zf: f32, tan_half_yfov: f32, height_px: u32) -> Result<ThinLens> {
    if !(f > 0.0 && f.is_finite()) {
        return Err(Error::InvalidLens(format!("the focal length must be positive and finite, got {f}")));
    }
    if !(zf > 0.0 && zf.is_finite()) {
        return Err(Error::InvalidLens(format!("the focus distance must be positive and finite, got {zf}")));
    }
    if f >= zf {
        return Err(Error::InvalidLens(format!(
            "the focal length ({f}) must be shorter than the focus distance ({zf}): a thin lens cannot focus closer than its focal length"
        )));
    }
    if height_px == 0 {
        return Err(Error::InvalidLens("an image of 0 rows".into()));
    }
    let sensor_distance = f * zf / (zf - f);
    let pixels_per_unit = height_px as f32 / (2.0 * sensor_distance * tan_half_yfov);
    let lens = ThinLens { focal_length: f, aperture_radius: radius, focus_distance: zf, pixels_per_unit };
    check(&lens)?;
    Ok(lens)
}

/// Whether the kernels can evaluate `lens`: `0 < f < z_f`, all finite, aperture `>= 0`,
/// `pixels_per_unit > 0`, and a far-field CoC that is finite.
pub fn check(lens: &ThinLens) -> Result<()> {
    if lens.is_valid() && lens.far_limit_px().is_finite() {
        Ok(())
    } else {
        Err(Error::InvalidLens(format!(
            "the lens {lens:?} cannot be evaluated (it needs 0 < focal_length < focus_distance, aperture_radius >= 0 and \
             pixels_per_unit > 0, all finite, with a finite far-field blur)"
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_field_of_view_gives_the_pixels_per_unit() {
        let lens = CameraLens { focal_length: 0.05, aperture: Aperture::FNumber(2.0), focus_distance: 3.0, yfov: 0.8, height_px: 1080 };
        let t = lens.thin_lens().unwrap();
        // The CoC of a point at infinity: R·height / (z_f·tan(yfov/2)).
        let expected = 0.0125 * 1080.0 / (3.0 * 0.4f32.tan());
        assert!((t.far_limit_px() - expected).abs() < 1e-3 * expected, "{} {expected}", t.far_limit_px());
        for bad in [
            CameraLens { yfov: 0.0, ..lens },
            CameraLens { yfov: f32::NAN, ..lens },
            CameraLens { focus_distance: 0.04, ..lens },
            CameraLens { aperture: Aperture::FNumber(-1.0), ..lens },
            CameraLens { aperture: Aperture::Radius(f32::INFINITY), ..lens },
            CameraLens { height_px: 0, ..lens },
            CameraLens { focal_length: f32::NAN, ..lens },
        ] {
            assert!(matches!(bad.thin_lens(), Err(Error::InvalidLens(_))), "{bad:?}");
        }
        // A pinhole.
        assert_eq!(CameraLens { aperture: Aperture::FNumber(f32::INFINITY), ..lens }.thin_lens().unwrap().aperture_radius, 0.0);
    }

    #[test]
    fn projections_give_their_field_of_view() {
        let yfov = 1.1f32;
        let cot = 1.0 / (0.5 * yfov).tan();
        let (n, f) = (0.1f32, 100.0f32);
        let standard = [[cot, 0.0, 0.0, 0.0], [0.0, cot, 0.0, 0.0], [0.0, 0.0, f / (n - f), -1.0], [0.0, 0.0, n * f / (n - f), 0.0]];
        let flipped = [[cot, 0.0, 0.0, 0.0], [0.0, -cot, 0.0, 0.0], [0.0, 0.0, 0.0, -1.0], [0.0, 0.0, n, 0.0]];
        for m in [standard, flipped] {
            assert!((yfov_from_projection(&m).unwrap() - yfov).abs() < 1e-6);
        }
        let orthographic = [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, -0.01, 0.0], [0.0, 0.0, 0.0, 1.0]];
        assert!(matches!(yfov_from_projection(&orthographic), Err(Error::InvalidLens(_))));
    }
}
