//! Triangle scenes: the host-side form of what the rasteriser draws, as the loader of glTF files
//! (`load_gltf`, feature `gltf`) builds it.
//!
//! The buffers are the kernel crate's types ([`dof_shaders::raster::mesh`]), in world space, ready
//! to upload. Cameras and the light come along from the file; [`LoadReport`] counts what the
//! loader dropped or changed rather than failing on it:
//! - zero-area triangles (repeated indices, or a cross product of two edges no longer than `1e-12`
//!   times the longest squared edge) are dropped, since they cover no pixel;
//! - point and line primitives, orthographic cameras, lights other than the first directional one
//!   and textures whose coordinates a primitive cannot give (a set it lacks, or different sets or
//!   transforms for its base colour and emissive textures) are skipped or changed.

use dof_shaders::raster::mesh::{MeshMaterial, MeshVertex, TextureInfo};

use super::lens::LensSettings;
use glam::Vec3;

use super::analytic::Lighting;
use super::camera::Camera;
use crate::error::{CoreError, Error, Result};

/// Most triangles a mesh may have: the rasteriser's visibility buffer stores `triangle + 1` as an
/// exact f32.
pub const MAX_TRIANGLES: u64 = 1 << 24;
/// Most texels all textures together may hold: 2^27 (134 M; Crytek Sponza has about 71 M). Each
/// costs 16 bytes as loaded (linear RGBA f32) and about 10.7 on the device (half floats, 8 bytes,
/// with a third more for the mip chain): 2 GiB and 1.3 GiB at the limit.
pub const MAX_TEXELS: u64 = 1 << 27;

/// Packs linear RGBA as two words of half floats (`r | g << 16`, `b | a << 16`), as texels and
/// vertex colours are stored; values past the half range become its largest finite value.
pub fn pack_halves(t: [f32; 4]) -> [u32; 2] {
    let h = |x: f32| half::f16::from_f32(x.clamp(-65504.0, 65504.0)).to_bits() as u32;
    [h(t[0]) | (h(t[1]) << 16), h(t[2]) | (h(t[3]) << 16)]
}

/// A triangle scene in world space (the default is empty, with the default light).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshScene {
    /// World-space vertices (node transforms applied); normals unit length, or zero where the file
    /// gives none (the rasteriser then uses the face normal).
    pub vertices: Vec<MeshVertex>,
    /// `[i0, i1, i2, material]`, counter-clockwise seen from the front.
    pub triangles: Vec<[u32; 4]>,
    pub materials: Vec<MeshMaterial>,
    /// Offset into `texels`, width, height and sampler bits of every texture.
    pub textures: Vec<TextureInfo>,
    /// Linear RGBA, row-major, top row first.
    pub texels: Vec<[f32; 4]>,
    pub lighting: Lighting,
    pub cameras: Vec<MeshCamera>,
    /// What the loader dropped or changed.
    pub report: LoadReport,
}

/// A perspective camera placed in the scene.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshCamera {
    pub name: Option<String>,
    pub eye: Vec3,
    /// Unit view axis: the camera's local −Z in world space.
    pub forward: Vec3,
    /// The camera's local +Y in world space.
    pub up: Vec3,
    pub yfov_radians: f32,
    /// Width over height the file asks for, if any (the image size given to [`MeshCamera::camera`]
    /// decides the aspect ratio actually rendered).
    pub aspect_ratio: Option<f32>,
    pub znear: f32,
}

impl MeshCamera {
    /// The library camera looking from `eye` along `forward` for an image of `width`x`height`
    /// pixels; errors (`InvalidArgument`) when [`Camera::frame`] rejects it (zero size, a field of
    /// view outside (0°, 180°), non-finite or degenerate axes).
    pub fn camera(&self, width: u32, height: u32) -> Result<Camera> {
        let camera = Camera { eye: self.eye, target: self.eye + self.forward, up: self.up, yfov_radians: self.yfov_radians, width, height };
        camera.frame().map_err(|e| match e {
            Error::Core(CoreError::InvalidArgument(m)) => {
                Error::invalid(format!("camera {}: {m}", self.name.as_deref().unwrap_or("(unnamed)")))
            }
            other => other,
        })?;
        Ok(camera)
    }
}

/// What loading dropped or changed, counted; all zero for a file used in full.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LoadReport {
    /// Zero-area triangles dropped.
    pub degenerate_triangles: u64,
    /// Point and line primitives skipped.
    pub skipped_primitives: u64,
    /// Orthographic cameras skipped.
    pub orthographic_cameras: u64,
    /// Primitives whose material's base colour and emissive textures read different coordinate
    /// sets or transforms (the base colour texture's are used for both).
    pub mixed_texture_coordinates: u64,
    /// Primitives whose textures name a coordinate set they lack (their coordinates read as 0).
    pub missing_texture_coordinates: u64,
    /// Punctual lights not used: point and spot lights, and directional lights after the first.
    pub ignored_lights: u64,
}

impl LoadReport {
    /// True when nothing was dropped or changed.
    pub fn is_clean(&self) -> bool {
        *self == LoadReport::default()
    }
}

/// The non-zero counts, comma-separated (empty when clean).
impl std::fmt::Display for LoadReport {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let items = [
            (self.degenerate_triangles, "zero-area triangles dropped"),
            (self.skipped_primitives, "point or line primitives skipped"),
            (self.orthographic_cameras, "orthographic cameras skipped"),
            (
                self.mixed_texture_coordinates,
                "primitives whose base colour and emissive textures use different coordinates (the base colour's used for both)",
            ),
            (self.missing_texture_coordinates, "primitives lacking the texture coordinate set their textures name (read as 0)"),
            (self.ignored_lights, "lights not used (only the first directional light is)"),
        ];
        let parts: Vec<String> = items.iter().filter(|(n, _)| *n > 0).map(|(n, what)| format!("{n} {what}")).collect();
        f.write_str(&parts.join(", "))
    }
}

/// Whether the triangle `p0 p1 p2` has (numerically) zero area: the cross product of two edges no
/// longer than `1e-12` times the longest squared edge, computed in f64.
#[cfg_attr(not(feature = "gltf"), allow(dead_code))]
pub(crate) fn zero_area(p0: Vec3, p1: Vec3, p2: Vec3) -> bool {
    let (a, b, c) = (p0.as_dvec3(), p1.as_dvec3(), p2.as_dvec3());
    let (e1, e2, e3) = (b - a, c - a, c - b);
    let longest = e1.length_squared().max(e2.length_squared()).max(e3.length_squared());
    e1.cross(e2).length() <= 1e-12 * longest
}

impl MeshScene {
    /// The view a file scene is rendered with by default: its first camera, `width` pixels wide
    /// and `height` high (default: the camera's aspect ratio, 16:9 when it has none), the near plane
    /// its `znear`, and [`MeshScene::default_lens`]. Errors when the file has no camera.
    pub fn default_view(&self, width: u32, height: Option<u32>) -> Result<(Camera, LensSettings, f32)> {
        let (camera, near) = self.default_camera(width, height)?;
        Ok((camera, self.default_lens(&camera)?, near))
    }

    /// The camera and near plane of [`MeshScene::default_view`], without its lens.
    pub fn default_camera(&self, width: u32, height: Option<u32>) -> Result<(Camera, f32)> {
        let Some(c) = self.cameras.first() else {
            return Err(Error::Scene("the scene has no camera; give one (eye, target and vertical field of view)".into()));
        };
        let aspect = c.aspect_ratio.filter(|a| a.is_finite() && *a > 0.0).unwrap_or(16.0 / 9.0);
        let height = height.unwrap_or(((width as f32 / aspect).round() as u32).max(1));
        Ok((c.camera(width, height)?, c.znear))
    }

    /// A lens for scenes that carry none: focused on what the image centre sees (the nearest
    /// triangle on the view axis, else the bounds' centre), with the aperture radius
    /// `0.02 · z_f · tan(yfov/2)`, which makes the far-field CoC 2% of the image height whatever
    /// the scene's scale (a physical f/2.8 blurs a room-sized scene by a fraction of a pixel at
    /// these image sizes, which would leave nothing to compare).
    pub fn default_lens(&self, camera: &Camera) -> Result<LensSettings> {
        self.lens_focused_at(camera, None)
    }

    /// [`MeshScene::default_lens`] focused at `focus` when given (the image centre need then see
    /// nothing), else as that function finds it.
    pub fn lens_focused_at(&self, camera: &Camera, focus: Option<f32>) -> Result<LensSettings> {
        let frame = camera.frame()?;
        let centre = self.bounds().map(|(lo, hi)| 0.5 * (lo + hi)).unwrap_or(camera.target);
        let focus = focus.unwrap_or_else(|| self.first_hit(frame.eye, frame.forward).unwrap_or_else(|| frame.depth_of(centre)));
        if !(focus > 0.0 && focus.is_finite()) {
            return Err(Error::Scene("the camera sees nothing to focus on; give the focus distance (--focus)".into()));
        }
        Ok(LensSettings::with_aperture_radius(focus, 0.02 * focus * frame.tan_half_fov))
    }

    /// Distance along the unit `direction` from `origin` to the nearest triangle (either side).
    pub fn first_hit(&self, origin: Vec3, direction: Vec3) -> Option<f32> {
        (0..self.triangles.len()).filter_map(|t| self.ray_hits(t, origin, direction)).min_by(f32::total_cmp)
    }

    /// Where the ray from `origin` along `direction` crosses triangle `t` (either side, in front of
    /// the origin): its distance in units of `direction` (Möller-Trumbore), `None` when it misses.
    pub(crate) fn ray_hits(&self, t: usize, origin: Vec3, direction: Vec3) -> Option<f32> {
        let at = |i: u32| self.vertices.get(i as usize).map(|v| Vec3::from(v.position));
        let tri = self.triangles.get(t)?;
        let (a, b, c) = (at(tri[0])?, at(tri[1])?, at(tri[2])?);
        let (e1, e2) = (b - a, c - a);
        let p = direction.cross(e2);
        let det = e1.dot(p);
        if det.abs() < 1e-12 {
            return None;
        }
        let s = origin - a;
        let u = s.dot(p) / det;
        let q = s.cross(e1);
        let v = direction.dot(q) / det;
        let t = e2.dot(q) / det;
        (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0).then_some(t)
    }

    /// Axis-aligned bounds of all vertex positions; `None` without vertices.
    pub fn bounds(&self) -> Option<(Vec3, Vec3)> {
        let mut it = self.vertices.iter().map(|v| Vec3::from(v.position));
        let first = it.next()?;
        Some(it.fold((first, first), |(lo, hi), p| (lo.min(p), hi.max(p))))
    }
}
