//! The guard band: a margin rendered beyond the frame so that blur from outside reaches into it.
//!
//! A blurred near object that crosses the edge of the frame spreads light into the frame from the
//! part beyond the edge (Franke et al. 2018, §7, name this a limitation of screen-space methods).
//! The scenes this system renders itself (analytic ray casting, glTF depth peeling) are therefore
//! rendered with a margin of `m` pixels on every side: the same pixel pitch and centre
//! ([`Camera::overscan`]), so the frame is the inner `width x height` pixels. Every method runs on
//! the larger image and its result is cropped ([`crate::layers::RgbImage::crop`]). The references
//! need no band: they trace the whole lens.
//!
//! The margin is the largest CoC radius that can reach into the frame ([`GuardBand::Auto`]): the
//! CoC radius at the nearest depth of any geometry within [`MAX_GUARD_BAND`] pixels of the frame
//! (each surface clipped to that widened view and to the nearest rendered depth), and the
//! background's (the far-field limit), rounded up and capped at [`MAX_GUARD_BAND`], the splatting
//! methods' largest honoured radius with 16-pixel tiles. It is conservative: a surface counts with
//! its nearest depth anywhere in that widened view.

use glam::Vec3;

use super::analytic::{Scene, Shape};
use super::camera::{Camera, CameraFrame};
use dof_shaders::lens::ThinLens;
use dof_shaders::peel::nearest_in_reach;

pub use dof_shaders::peel::MAX_GUARD_BAND;

/// How wide a margin: in the core, a field of [`LayerOptions`](crate::scene::LayerOptions).
pub use crate::frame::GuardBand;

impl Camera {
    /// The camera that sees `margin` more pixels on every side with the same pixel pitch and centre:
    /// its pixel `(x + margin, y + margin)` is this camera's pixel `(x, y)`. A lens computed for
    /// this camera stays valid for it (same pixels per scene unit).
    pub fn overscan(&self, margin: u32) -> Camera {
        if margin == 0 {
            return *self;
        }
        let height = self.height.saturating_add(2 * margin);
        let scale = height as f64 / self.height.max(1) as f64;
        let tan = (0.5 * self.yfov_radians as f64).tan() * scale;
        Camera { width: self.width.saturating_add(2 * margin), height, yfov_radians: (2.0 * tan.atan()) as f32, ..*self }
    }
}

/// The view within [`MAX_GUARD_BAND`] pixels of the frame, from `z_min` on: four side planes
/// through the eye and the near plane, as inward normals with offsets (`n·p >= d` inside).
struct Reach {
    planes: [(Vec3, f32); 5],
}

impl Reach {
    fn new(camera: &Camera, z_min: f32) -> crate::Result<Self> {
        let wide = camera.overscan(MAX_GUARD_BAND).frame()?;
        let (w, h) = (wide.width as f32, wide.height as f32);
        let [tl, tr, bl, br] = [(0.0, 0.0), (w, 0.0), (0.0, h), (w, h)].map(|(x, y)| wide.direction(x, y));
        // Inward normals of the sides: left, right, top, bottom.
        let side = |a: Vec3, b: Vec3| {
            let n = a.cross(b).normalize_or_zero();
            let n = if n.dot(wide.forward) < 0.0 { -n } else { n };
            (n, n.dot(wide.eye))
        };
        Ok(Reach { planes: [side(bl, tl), side(tr, br), side(tl, tr), side(br, bl), (wide.forward, wide.forward.dot(wide.eye) + z_min)] })
    }

    /// The planes as the device takes them: `[n.x, n.y, n.z, d]`.
    fn words(&self) -> [[f32; 4]; 5] {
        self.planes.map(|(n, d)| [n.x, n.y, n.z, d])
    }

    /// Nearest planar depth of the convex polygon `poly` (3 or 4 corners in order) inside the
    /// reach ([`nearest_in_reach`], the device peel's rule); `None` if nothing is left.
    fn nearest(&self, poly: &[Vec3], eye: Vec3, forward: Vec3) -> Option<f32> {
        let mut corners = [[0.0; 3]; 4];
        for (c, p) in corners.iter_mut().zip(poly) {
            *c = p.to_array();
        }
        let z = nearest_in_reach(&self.words(), corners, poly.len().min(4), eye.to_array(), forward.to_array());
        z.is_finite().then_some(z)
    }
}

/// The widest guard band's view of `camera` from the near plane `near` on, as the device's band
/// kernels take it (`dof_shaders::peel::BandParams::planes`).
pub fn reach_planes(camera: &Camera, near: f32) -> crate::Result<[[f32; 4]; 5]> {
    Ok(Reach::new(camera, near)?.words())
}

/// The largest CoC radius (pixels, rounded up, at most [`MAX_GUARD_BAND`]) that can reach into the
/// frame of `camera` from `scene`'s geometry or its background; `z_min` is the nearest depth
/// rendered (analytic ray casting has no near plane: give a small positive depth).
pub fn auto_margin(scene: &Scene, camera: &Camera, lens: &ThinLens, z_min: f32) -> crate::Result<u32> {
    let frame = camera.frame()?;
    let reach = Reach::new(camera, z_min)?;
    let wide = camera.overscan(MAX_GUARD_BAND).frame()?;
    let (eye, fwd) = (frame.eye, frame.forward);
    let mut radius = lens.coc_radius_px(f32::INFINITY);
    for prim in scene.primitives() {
        let depth = match prim.shape {
            Shape::Sphere { center, radius } => {
                // Conservative: the sphere's nearest depth if it meets the reach at all.
                let inside = reach.planes.iter().all(|(n, d)| n.dot(center) - d >= -radius);
                inside.then(|| ((center - eye).dot(fwd) - radius).max(z_min))
            }
            Shape::Cuboid { min, max } => {
                let c = |i: u32| {
                    Vec3::new(
                        if i & 1 == 0 { min.x } else { max.x },
                        if i & 2 == 0 { min.y } else { max.y },
                        if i & 4 == 0 { min.z } else { max.z },
                    )
                };
                const FACES: [[u32; 4]; 6] = [[0, 1, 3, 2], [4, 5, 7, 6], [0, 1, 5, 4], [2, 3, 7, 6], [0, 2, 6, 4], [1, 3, 7, 5]];
                FACES.iter().filter_map(|f| reach.nearest(&f.map(c), eye, fwd)).reduce(f32::min)
            }
            Shape::Quad { corner, edge_u, edge_v } => {
                reach.nearest(&[corner, corner + edge_u, corner + edge_u + edge_v, corner + edge_v], eye, fwd)
            }
            Shape::Plane { point, normal } => plane_depth(&wide, point, normal, z_min),
        };
        if let Some(z) = depth {
            radius = radius.max(lens.coc_radius_px(z));
        }
    }
    Ok(margin_of(radius))
}

/// The nearest depth of a plane inside the widened view: the nearest of the view's corner rays'
/// hits, since depth is linear over the plane and its visible part is convex with corners on
/// those rays; `z_min` when the plane passes through the eye.
fn plane_depth(wide: &CameraFrame, point: Vec3, normal: Vec3, z_min: f32) -> Option<f32> {
    let offset = (point - wide.eye).dot(normal);
    if offset.abs() <= 1e-6 * normal.length() * (point - wide.eye).length().max(1.0) {
        return Some(z_min);
    }
    let (w, h) = (wide.width as f32, wide.height as f32);
    [(0.0, 0.0), (w, 0.0), (0.0, h), (w, h)]
        .iter()
        .filter_map(|&(px, py)| {
            let d = wide.direction(px, py);
            let t = offset / d.dot(normal);
            (t > 0.0 && t.is_finite()).then_some(t.max(z_min))
        })
        .reduce(f32::min)
}

/// The guard band of a triangle mesh: like [`auto_margin`], triangle by triangle, with the near
/// plane as the nearest depth.
pub fn auto_margin_mesh(triangles: impl Iterator<Item = [Vec3; 3]>, camera: &Camera, lens: &ThinLens, near: f32) -> crate::Result<u32> {
    let frame = camera.frame()?;
    let reach = Reach::new(camera, near)?;
    let mut radius = lens.coc_radius_px(f32::INFINITY);
    for tri in triangles {
        if let Some(z) = reach.nearest(&tri, frame.eye, frame.forward) {
            radius = radius.max(lens.coc_radius_px(z));
            if radius >= MAX_GUARD_BAND as f32 {
                break;
            }
        }
    }
    Ok(margin_of(radius))
}

pub use dof_shaders::peel::margin_of;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::analytic::{Lighting, Material, Primitive};

    fn camera() -> Camera {
        Camera::look_at(Vec3::ZERO, -Vec3::Z, 40f32.to_radians(), 160, 90)
    }

    fn lens() -> ThinLens {
        // Far-field CoC 2 px; a point at depth 1 gets 2·(10/1 − 1) = 18 px.
        ThinLens { focal_length: 0.05, aperture_radius: 0.0, focus_distance: 10.0, pixels_per_unit: 1.0 }.with_far_limit(2.0)
    }

    trait FarLimit {
        fn with_far_limit(self, px: f32) -> Self;
    }
    impl FarLimit for ThinLens {
        fn with_far_limit(self, px: f32) -> Self {
            let unit = ThinLens { aperture_radius: 1.0, ..self }.far_limit_px();
            ThinLens { aperture_radius: px / unit, ..self }
        }
    }

    fn square(centre: Vec3, half: f32) -> Primitive {
        let shape = Shape::Quad { corner: centre - Vec3::new(half, half, 0.0), edge_u: Vec3::X * 2.0 * half, edge_v: Vec3::Y * 2.0 * half };
        Primitive { shape, material: Material::Emissive([1.0; 3]) }
    }

    fn margin(prims: Vec<Primitive>) -> u32 {
        let scene = Scene::new(prims, Lighting::default()).unwrap();
        auto_margin(&scene, &camera(), &lens(), 1e-3).unwrap()
    }

    #[test]
    fn overscan_keeps_the_pixel_pitch_and_centre() {
        let (frame, wide) = (camera().frame().unwrap(), camera().overscan(7).frame().unwrap());
        assert_eq!((wide.width, wide.height), (174, 104));
        for (x, y) in [(0.0, 0.0), (80.5, 45.5), (160.0, 90.0), (3.25, 77.0)] {
            let (a, b) = (frame.direction(x, y), wide.direction(x + 7.0, y + 7.0));
            assert!((a - b).length() < 1e-5, "({x}, {y}): {a} vs {b}");
        }
        assert_eq!(camera().overscan(0), camera());
    }

    #[test]
    fn the_band_is_the_nearest_blur_that_reaches_the_frame() {
        // Only the background: its radius, 1 px.
        assert_eq!(margin(vec![]), 1);
        // A near square in view at depth 1: CoC 18 px, radius 9.
        assert_eq!(margin(vec![square(Vec3::new(0.0, 0.0, -1.0), 0.1)]), 9);
        // The same square far beyond the left edge (and beyond the widened view) adds nothing.
        assert_eq!(margin(vec![square(Vec3::new(-50.0, 0.0, -1.0), 0.1)]), 1);
        // Behind the camera: nothing.
        assert_eq!(margin(vec![square(Vec3::new(0.0, 0.0, 1.0), 0.1)]), 1);
        // A plane through the eye (a floor under the camera's feet would be one) takes the cap.
        let floor = Primitive { shape: Shape::Plane { point: Vec3::ZERO, normal: Vec3::Y }, material: Material::Emissive([1.0; 3]) };
        assert_eq!(margin(vec![floor]), MAX_GUARD_BAND);
        // A floor tile under the eye, reaching behind it: clipped to the widened view it starts
        // at depth 0.1 / 1.14 (CoC radius 113 px), so the band takes the cap.
        let tile = Shape::Quad { corner: Vec3::new(-0.5, -0.1, 0.5), edge_u: Vec3::X, edge_v: -Vec3::Z };
        assert_eq!(margin(vec![Primitive { shape: tile, material: Material::Emissive([1.0; 3]) }]), MAX_GUARD_BAND);
        // The same tile 1.5 below the eye: nearest in view at depth 1.32, CoC radius 6.6 px.
        let low = Shape::Quad { corner: Vec3::new(-0.5, -1.5, 0.5), edge_u: Vec3::X, edge_v: -Vec3::Z * 3.0 };
        assert_eq!(margin(vec![Primitive { shape: low, material: Material::Emissive([1.0; 3]) }]), 7);
    }

    #[test]
    fn fixed_bands_are_bounded() {
        assert_eq!(GuardBand::Off.resolve(|| Ok(5)).unwrap(), 0);
        assert_eq!(GuardBand::Auto.resolve(|| Ok(5)).unwrap(), 5);
        assert_eq!(GuardBand::Pixels(12).resolve(|| Ok(5)).unwrap(), 12);
        assert!(matches!(GuardBand::Pixels(MAX_GUARD_BAND + 1).resolve(|| Ok(5)), Err(crate::CoreError::TooLarge { .. })));
    }
}
