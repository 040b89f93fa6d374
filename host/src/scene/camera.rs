//! The pinhole camera: placement, field of view, image size, pixel rays and planar depth.
//!
//! glTF conventions: the camera looks down its local −Z with +Y up; image +x is to the right and the
//! top row comes first. Rays are returned with a direction whose component along the view axis is 1,
//! so the ray parameter `t` of a hit *is* its planar depth.

use glam::Vec3;

use crate::error::{CoreError, Error, Result};

/// A perspective camera. Validate it with [`Camera::frame`] before use; every function taking a
/// camera does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Centre of projection (and of the lens).
    pub eye: Vec3,
    /// A point the camera looks at (sets the view axis only; focus is set by the lens).
    pub target: Vec3,
    /// Roughly up; must not be parallel to the view axis.
    pub up: Vec3,
    /// Vertical field of view in radians, in (0, π).
    pub yfov_radians: f32,
    /// Image size in pixels, both `> 0`.
    pub width: u32,
    pub height: u32,
}

/// A validated camera: an orthonormal basis and what pixel rays need.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraFrame {
    pub eye: Vec3,
    /// Unit view axis (the camera's local −Z).
    pub forward: Vec3,
    /// Unit image +x.
    pub right: Vec3,
    /// Unit image +y (up on screen).
    pub up: Vec3,
    /// `tan(yfov/2)`: half the image height at depth 1.
    pub tan_half_fov: f32,
    /// `width / height`.
    pub aspect: f32,
    pub width: u32,
    pub height: u32,
}

/// A ray `origin + t·direction`; `direction` has a unit component along the camera's view axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    pub origin: Vec3,
    pub direction: Vec3,
}

impl Ray {
    #[inline]
    pub fn at(&self, t: f32) -> Vec3 {
        self.origin + t * self.direction
    }
}

/// `v` at unit length, also when its components are so small that their squares underflow (it is
/// scaled by its largest component first); `None` for zero or non-finite vectors.
fn unit(v: Vec3) -> Option<Vec3> {
    let largest = v.abs().max_element();
    if !(largest > 0.0 && largest.is_finite()) {
        return None;
    }
    let u = (v / largest).normalize();
    (u.is_finite() && (u.length() - 1.0).abs() < 1e-4).then_some(u)
}

impl Camera {
    /// A camera at `eye` looking at `target` with +Y up.
    pub fn look_at(eye: Vec3, target: Vec3, yfov_radians: f32, width: u32, height: u32) -> Self {
        Camera { eye, target, up: Vec3::Y, yfov_radians, width, height }
    }

    /// Checks the camera and builds its frame. Errors (`InvalidArgument`) on a zero image size, a
    /// field of view outside (0°, 180°) or NaN, non-finite vectors, `eye == target`, or `up`
    /// parallel to the view axis.
    pub fn frame(&self) -> Result<CameraFrame> {
        if self.width == 0 || self.height == 0 {
            return Err(Error::invalid(format!("the image size must be positive, got {}x{}", self.width, self.height)));
        }
        let fov = self.yfov_radians;
        if !(fov > 0.0 && fov < std::f32::consts::PI) {
            return Err(Error::invalid(format!(
                "the vertical field of view must lie strictly between 0 and 180 degrees, got {} degrees",
                fov.to_degrees()
            )));
        }
        if !(self.eye.is_finite() && self.target.is_finite() && self.up.is_finite()) {
            return Err(Error::invalid("camera eye, target and up must be finite".into()));
        }
        let forward = unit(self.target - self.eye).ok_or_else(|| Error::invalid("the camera's target must differ from its eye".into()))?;
        let right = unit(self.up)
            .map(|up| forward.cross(up))
            .filter(|r| r.length() > 1e-6)
            .and_then(unit)
            .ok_or_else(|| Error::invalid("the camera's up vector must not be zero or parallel to its view axis".into()))?;
        let up = right.cross(forward);
        let tan_half_fov = (0.5 * fov).tan();
        if !(tan_half_fov.is_finite() && tan_half_fov > 0.0) {
            return Err(Error::invalid(format!("the vertical field of view {} degrees is too close to 0 or 180", fov.to_degrees())));
        }
        Ok(CameraFrame {
            eye: self.eye,
            forward,
            right,
            up,
            tan_half_fov,
            aspect: self.width as f32 / self.height as f32,
            width: self.width,
            height: self.height,
        })
    }
}

impl CameraFrame {
    /// The camera's orientation as a unit quaternion `[x, y, z, w]` taking its axes (+x right, +y
    /// up, −z forward) to the world, as the rasteriser's shading reads it.
    pub fn orientation(&self) -> [f32; 4] {
        glam::Quat::from_mat3(&glam::Mat3::from_cols(self.right, self.up, -self.forward)).normalize().to_array()
    }

    /// Direction of the pinhole ray through image position `(px, py)` in pixels (`(0, 0)` the top
    /// left corner of the image, `(x + 0.5, y + 0.5)` the centre of pixel `(x, y)`), with a unit
    /// component along the view axis.
    #[inline]
    pub fn direction(&self, px: f32, py: f32) -> Vec3 {
        let sx = (2.0 * px / self.width as f32 - 1.0) * self.aspect * self.tan_half_fov;
        let sy = (1.0 - 2.0 * py / self.height as f32) * self.tan_half_fov;
        self.forward + sx * self.right + sy * self.up
    }

    /// The pinhole ray through the centre of pixel `(x, y)`.
    #[inline]
    pub fn pixel_ray(&self, x: u32, y: u32) -> Ray {
        Ray { origin: self.eye, direction: self.direction(x as f32 + 0.5, y as f32 + 0.5) }
    }

    /// The ray through image position `(px, py)` from the lens point `(lx, ly)` (scene units, in the
    /// lens plane along image +x and +y) of a thin lens focused at planar depth `focus_distance`:
    /// it passes through the point the pinhole ray meets at the focus plane, and its parameter is
    /// still planar depth. `(0, 0)` gives exactly the pinhole ray.
    #[inline]
    pub fn lens_ray(&self, px: f32, py: f32, lx: f32, ly: f32, focus_distance: f32) -> Ray {
        let d = self.direction(px, py);
        if lx == 0.0 && ly == 0.0 {
            return Ray { origin: self.eye, direction: d };
        }
        let offset = lx * self.right + ly * self.up;
        Ray { origin: self.eye + offset, direction: d - offset / focus_distance }
    }

    /// Planar depth of a point: its distance along the view axis (negative behind the camera).
    #[inline]
    pub fn depth_of(&self, p: Vec3) -> f32 {
        (p - self.eye).dot(self.forward)
    }

    /// Projects a point to image position in pixels (`None` at or behind the camera plane).
    pub fn project(&self, p: Vec3) -> Option<(f32, f32)> {
        let rel = p - self.eye;
        let z = rel.dot(self.forward);
        if !(z > 0.0) {
            return None;
        }
        let sx = rel.dot(self.right) / (z * self.tan_half_fov * self.aspect);
        let sy = rel.dot(self.up) / (z * self.tan_half_fov);
        Some(((sx + 1.0) * 0.5 * self.width as f32, (1.0 - sy) * 0.5 * self.height as f32))
    }

    /// Half the height of one pixel at planar depth `z`, scene units: the radius of a pixel's
    /// footprint on a surface facing the camera (what [`dof_shaders::lens::ThinLens::umbra_length`]
    /// takes).
    #[inline]
    pub fn pixel_footprint_radius(&self, z: f32) -> f32 {
        z * self.tan_half_fov / self.height as f32
    }

    pub fn pixels(&self) -> usize {
        self.width as usize * self.height as usize
    }

    /// Errors (`TooLarge`) when an image of this size with `per_pixel` slots exceeds
    /// [`MAX_SLOTS`], before anything is allocated.
    pub fn check_size(&self, what: &str, per_pixel: u64) -> Result<()> {
        let slots = (self.width as u64 * self.height as u64).saturating_mul(per_pixel.max(1));
        if slots > MAX_SLOTS {
            return Err(Error::Core(CoreError::TooLarge {
                what: format!("{what} ({}x{} pixels x {per_pixel})", self.width, self.height),
                size: slots,
                limit: MAX_SLOTS,
            }));
        }
        Ok(())
    }
}

/// Largest number of per-pixel slots (pixels × layers, or pixels) the scene renderers allocate:
/// 2^28, e.g. 16384x16384 pixels with one slot, a few GiB at most.
pub const MAX_SLOTS: u64 = 1 << 28;
