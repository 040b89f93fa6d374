//! The clip transform of one raster pass: the camera seen from a point of the lens through the
//! sheared frustum that keeps the focus plane fixed (the accumulation buffer's pinhole renders),
//! shifted by a sub-pixel jitter. Lens point `(0, 0)` without jitter is the pinhole camera.
//!
//! With the camera basis (right `r`, up `u`, forward `f`), `x = r·(P − eye)`, `y = u·(P − eye)`,
//! `z = f·(P − eye)` and the lens point `(lx, ly)`: the image position is
//! `((x − lx) + lx·z/z_f) / z`, so a point on the focus plane `z = z_f` lands where the pinhole puts
//! it whatever the lens point. `w = z` stays the planar depth.

use crate::scene::CameraFrame;
use dof_shaders::raster::project::RasterParams;
use glam::Vec3;

/// Where one pass looks from.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct View {
    /// Lens point along image +x and +y, scene units.
    pub lens: (f32, f32),
    /// Sub-pixel offset of the sample position from the pixel centre, pixels.
    pub jitter: (f32, f32),
}

/// A near plane for scenes without one: a thousandth of the focus distance (geometry nearer than
/// that is clipped).
pub fn default_near(focus_distance: f32) -> f32 {
    1e-3 * focus_distance
}

fn row(v: Vec3, c: f32) -> [f32; 4] {
    [v.x, v.y, v.z, c]
}

impl View {
    /// The eye of this view in world space.
    pub fn eye(&self, frame: &CameraFrame) -> Vec3 {
        frame.eye + self.lens.0 * frame.right + self.lens.1 * frame.up
    }

    /// The push constants of a raster pass (everything but the table sizes and the peel flag).
    pub fn params(&self, frame: &CameraFrame, focus_distance: f32, near: f32) -> RasterParams {
        let (r, u, f, e) = (frame.right, frame.up, frame.forward, frame.eye);
        let tx = frame.tan_half_fov * frame.aspect;
        let ty = frame.tan_half_fov;
        let (lx, ly) = self.lens;
        // Sample at centre + jitter: shift the image the other way.
        let sx = -2.0 * self.jitter.0 / frame.width as f32;
        let sy = -2.0 * self.jitter.1 / frame.height as f32;
        let kx = lx / (focus_distance * tx) + sx;
        let ky = -ly / (focus_distance * ty) + sy;
        let row_x = r / tx + kx * f;
        let row_y = -u / ty + ky * f;
        RasterParams {
            row_x: row(row_x, -row_x.dot(e) - lx / tx),
            row_y: row(row_y, -row_y.dot(e) + ly / ty),
            row_w: row(f, -f.dot(e)),
            eye: self.eye(frame).to_array(),
            near,
            width: frame.width,
            height: frame.height,
            ..RasterParams::default()
        }
    }
}
