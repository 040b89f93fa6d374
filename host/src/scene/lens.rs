//! Lens settings as a user gives them (photographically or as an aperture radius in scene units),
//! validated into the [`ThinLens`] the kernels evaluate.
//!
//! The field of view is the camera's. The sensor sits where the focus plane is imaged, at
//! `s = f·z_f/(z_f − f)` behind the lens, so its height is `2·s·tan(yfov/2)` and
//! `pixels_per_unit = height_px / (2·s·tan(yfov/2))`. With that choice the CoC in pixels,
//! `R·|1 − z_f/z|·height_px / (z_f·tan(yfov/2))`, is exactly the blur a thin-lens ray tracer with
//! the same camera produces (see `reference`), whatever the focal length.

use dof_shaders::lens::{ArtistLens, ThinLens};
use glam::Vec3;

use super::camera::Camera;
use crate::error::{Error, Result};
pub use dof_core::lens::Aperture;

/// Where the camera focuses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Focus {
    /// Planar distance of the focus plane, scene units.
    Distance(f32),
    /// Focus on the plane through this point (parallel to the image plane).
    Point(Vec3),
}

/// A thin lens as a user describes it. Scene units are metres unless `metres_per_unit` says
/// otherwise (it only matters for millimetre inputs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LensSettings {
    pub focus: Focus,
    pub aperture: Aperture,
    /// Focal length in millimetres; `None`: from the camera's field of view and
    /// `sensor_height_mm` (`f = sensor/(2·tan(yfov/2))`, the lens focused at infinity).
    pub focal_length_mm: Option<f32>,
    /// Sensor height in millimetres, used only to derive the focal length (default 24, full frame).
    pub sensor_height_mm: f32,
    /// Length of one scene unit in metres (default 1).
    pub metres_per_unit: f32,
}

impl LensSettings {
    /// Photographic: focus distance (scene units) and f-number; focal length from the field of view.
    pub fn photographic(focus_distance: f32, f_number: f32) -> Self {
        LensSettings {
            focus: Focus::Distance(focus_distance),
            aperture: Aperture::FNumber(f_number),
            focal_length_mm: None,
            sensor_height_mm: 24.0,
            metres_per_unit: 1.0,
        }
    }

    /// Aperture radius in scene units and focus distance.
    pub fn with_aperture_radius(focus_distance: f32, aperture_radius: f32) -> Self {
        LensSettings { aperture: Aperture::Radius(aperture_radius), ..Self::photographic(focus_distance, 1.0) }
    }

    /// The same settings with an explicit focal length in millimetres.
    pub fn focal_length_mm(self, mm: f32) -> Self {
        LensSettings { focal_length_mm: Some(mm), ..self }
    }

    /// The same settings focused on the plane through `p`.
    pub fn focused_on(self, p: Vec3) -> Self {
        LensSettings { focus: Focus::Point(p), ..self }
    }

    /// The thin lens these settings describe for `camera`. Errors (`InvalidArgument`, naming the
    /// value) on an invalid camera (see [`Camera::frame`]); a focus distance that is not positive
    /// and finite, or a focus point behind the camera; a focal length or sensor height that is not
    /// positive and finite; a focal length not shorter than the focus distance; a negative or NaN
    /// aperture (radius or f-number); a non-positive scale.
    pub fn thin_lens(&self, camera: &Camera) -> Result<ThinLens> {
        let frame = camera.frame()?;
        let zf = match self.focus {
            Focus::Distance(d) => {
                if !(d > 0.0 && d.is_finite()) {
                    return Err(Error::invalid(format!("the focus distance must be positive and finite, got {d}")));
                }
                d
            }
            Focus::Point(p) => {
                let d = frame.depth_of(p);
                if !p.is_finite() || !(d > 0.0) {
                    return Err(Error::invalid(format!("the focus point {p} is behind or in the plane of the camera (planar depth {d})")));
                }
                d
            }
        };
        let mpu = self.metres_per_unit;
        if !(mpu > 0.0 && mpu.is_finite()) {
            return Err(Error::invalid(format!("metres per scene unit must be positive and finite, got {mpu}")));
        }
        let f_mm = match self.focal_length_mm {
            Some(f) => {
                if !(f > 0.0 && f.is_finite()) {
                    return Err(Error::invalid(format!("the focal length must be positive and finite, got {f} mm")));
                }
                f
            }
            None => {
                let s = self.sensor_height_mm;
                if !(s > 0.0 && s.is_finite()) {
                    return Err(Error::invalid(format!("the sensor height must be positive and finite, got {s} mm")));
                }
                s / (2.0 * frame.tan_half_fov)
            }
        };
        // In scene units; the core checks it against the focus distance.
        let f = f_mm * 1e-3 / mpu;
        let radius = self.aperture.radius(f)?;
        let lens = dof_core::lens::thin_lens_for_view(f, radius, zf, frame.tan_half_fov, frame.height)?;
        Ok(lens)
    }
}

/// Checks an [`ArtistLens`] (de Rousiers and Pettineo's linear model): `near_end <= near_start <= far_start <=
/// far_end`, values finite (`far_end` may be `+inf`), `max_radius_px >= 0` with a finite diameter
/// (`2 · max_radius_px`: beyond it the CoC is `inf · 0`, NaN, in the sharp zone).
pub fn validate_artist_lens(lens: &ArtistLens) -> Result<()> {
    if lens.is_valid() && (2.0 * lens.max_radius_px).is_finite() {
        Ok(())
    } else {
        Err(Error::invalid(format!(
            "an artist lens needs near_end <= near_start <= far_start <= far_end and max_radius_px >= 0, \
             all finite (far_end may be infinite) and max_radius_px below {:e}; got {lens:?}",
            f32::MAX / 2.0
        )))
    }
}
