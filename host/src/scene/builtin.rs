//! Built-in analytic scenes, each with a default camera (640x360, 40° vertical field of view) and a
//! lens that gives visible blur at that size. Scene units are metres. Every scene has tens of
//! primitives, so exact ray casting stays cheap.
//!
//! | name | what it tests |
//! |---|---|
//! | `simple` | Franke et al. 2018, Fig. 11: far white plane, red sphere in focus, small blue quad near the camera |
//! | `railing` | out-of-focus railing bars near the camera over a detailed far field (Franke et al. 2018, Fig. 1) |
//! | `columns` | a colonnade seen at an angle: many overlapping depth layers |
//! | `highlights` | small, very bright emissive dots at many depths (bokeh), some above 65504 |
//! | `fence` | out-of-focus fence bars near the camera over a far wall, open sky above and below it |
//! | `edges` | out-of-focus near objects crossing all four edges of the frame, open sky above |
//! | `panes` | two tinted translucent panes (opacity 0.35 and 0.6) out of focus in front of an in-focus wall |
//! | `foliage` | alpha-blended cards, as foliage is drawn, near the camera and around the focus |
//! | `glass` | a translucent near pane over open sky and the top of a far wall |
//!
//! `fence`, `edges` and the three translucent scenes are emissive only (every surface unlit, radiance = emission) and have a
//! coloured sky, so an independent renderer (`tools/independent_check.py`) sees exactly the same
//! radiance and only the lens integration differs.

use dof_shaders::lens::ThinLens;
use glam::Vec3;

use super::analytic::{Albedo, Lighting, Material, Primitive, Scene, Shape};
use super::camera::Camera;
use super::lens::LensSettings;
use crate::error::{Error, Result};

/// A named scene with its default view.
#[derive(Clone, Debug, PartialEq)]
pub struct BuiltinScene {
    pub name: &'static str,
    pub description: &'static str,
    pub scene: Scene,
    pub camera: Camera,
    pub lens: LensSettings,
}

impl BuiltinScene {
    /// The same scene rendered at another size (the field of view stays; the CoC in pixels scales
    /// with the height).
    pub fn with_size(mut self, width: u32, height: u32) -> Self {
        self.camera.width = width;
        self.camera.height = height;
        self
    }

    /// The default lens for the default (or resized) camera.
    pub fn thin_lens(&self) -> Result<ThinLens> {
        self.lens.thin_lens(&self.camera)
    }
}

const NAMES: [&str; 9] = ["simple", "railing", "columns", "highlights", "fence", "edges", "panes", "foliage", "glass"];

/// Names of the built-in scenes.
pub fn builtin_names() -> &'static [&'static str] {
    &NAMES
}

/// The built-in scene called `name`; an unknown name is an error listing the names.
pub fn builtin(name: &str) -> Result<BuiltinScene> {
    match name {
        "simple" => simple(),
        "railing" => railing(),
        "columns" => columns(),
        "highlights" => highlights(),
        "fence" => fence(),
        "edges" => edges(),
        "panes" => panes(),
        "foliage" => foliage(),
        "glass" => glass(),
        _ => Err(Error::invalid(format!("unknown built-in scene `{name}`; the built-in scenes are: {}", NAMES.join(", ")))),
    }
}

const WIDTH: u32 = 640;
const HEIGHT: u32 = 360;
const FOV_DEGREES: f32 = 40.0;

fn camera(eye: Vec3, target: Vec3) -> Camera {
    Camera::look_at(eye, target, FOV_DEGREES.to_radians(), WIDTH, HEIGHT)
}

fn diffuse(shape: Shape, rgb: [f32; 3]) -> Primitive {
    Primitive { shape, material: Material::Diffuse(Albedo::Solid(rgb)) }
}

fn checker(shape: Shape, a: [f32; 3], b: [f32; 3], cell: f32) -> Primitive {
    Primitive { shape, material: Material::Diffuse(Albedo::Checker { a, b, cell }) }
}

fn cuboid(min: [f32; 3], max: [f32; 3]) -> Shape {
    Shape::Cuboid { min: Vec3::from(min), max: Vec3::from(max) }
}

fn sphere(center: [f32; 3], radius: f32) -> Shape {
    Shape::Sphere { center: Vec3::from(center), radius }
}

fn plane(point: [f32; 3], normal: [f32; 3]) -> Shape {
    Shape::Plane { point: Vec3::from(point), normal: Vec3::from(normal) }
}

/// Seed 000 Fig. 11: a white plane far away, a red sphere in focus and a small blue quad close to
/// the camera, overlapping the sphere's silhouette.
fn simple() -> Result<BuiltinScene> {
    let prims = vec![
        diffuse(plane([0.0, 0.0, -12.0], [0.0, 0.0, 1.0]), [0.9, 0.9, 0.9]),
        diffuse(sphere([0.35, 0.0, -5.0], 0.8), [0.85, 0.1, 0.08]),
        diffuse(
            Shape::Quad { corner: Vec3::new(-0.32, -0.2, -1.3), edge_u: Vec3::new(0.26, 0.0, 0.0), edge_v: Vec3::new(0.0, 0.26, 0.0) },
            [0.1, 0.2, 0.9],
        ),
    ];
    Ok(BuiltinScene {
        name: "simple",
        description: "Franke et al. 2018, Fig. 11: far white plane, red sphere in focus, small blue quad in the near field",
        scene: Scene::new(prims, Lighting::default())?,
        camera: camera(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0)),
        // Focused on the sphere's front; near quad CoC ~21 px, far plane ~6 px at 640x360.
        lens: LensSettings::with_aperture_radius(4.2, 0.04),
    })
}

/// Railing bars and a top rail 1.2 m in front of the camera, out of focus, over a courtyard: a
/// checker floor and wall, boxes and spheres between 7 and 16 m, in focus at 10 m.
fn railing() -> Result<BuiltinScene> {
    let mut prims = vec![
        checker(plane([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]), [0.75, 0.72, 0.65], [0.25, 0.25, 0.28], 1.0),
        checker(plane([0.0, 0.0, -22.0], [0.0, 0.0, 1.0]), [0.8, 0.5, 0.3], [0.9, 0.85, 0.75], 0.5),
        diffuse(cuboid([-3.5, 0.0, -12.0], [-2.5, 2.4, -11.0]), [0.3, 0.55, 0.8]),
        diffuse(cuboid([1.6, 0.0, -9.5], [2.4, 1.2, -8.7]), [0.85, 0.8, 0.2]),
        diffuse(cuboid([-0.8, 0.0, -16.0], [0.6, 3.0, -15.0]), [0.6, 0.6, 0.65]),
        diffuse(sphere([-1.2, 0.5, -7.5], 0.5), [0.2, 0.75, 0.3]),
        diffuse(sphere([0.9, 0.35, -10.0], 0.35), [0.9, 0.3, 0.6]),
        diffuse(sphere([3.5, 1.0, -14.0], 1.0), [0.95, 0.95, 0.95]),
        // Top rail.
        diffuse(cuboid([-2.0, 1.18, -1.32], [2.0, 1.24, -1.2]), [0.35, 0.22, 0.12]),
    ];
    // Vertical bars every 0.2 m.
    for i in -5..=5 {
        let x = i as f32 * 0.2;
        prims.push(diffuse(cuboid([x - 0.02, 0.0, -1.28], [x + 0.02, 1.18, -1.24]), [0.4, 0.26, 0.14]));
    }
    Ok(BuiltinScene {
        name: "railing",
        description: "near out-of-focus railing bars over a detailed far field",
        scene: Scene::new(prims, Lighting::default())?,
        camera: camera(Vec3::new(0.0, 1.15, 0.0), Vec3::new(0.0, 1.0, -10.0)),
        // Bars ~21 px CoC (wider than the bars), the far field within ~2 px.
        lens: LensSettings::with_aperture_radius(10.0, 0.03),
    })
}

/// Two rows of square columns on a checker floor, seen at an angle so that columns at many depths
/// overlap, in focus at 8 m.
fn columns() -> Result<BuiltinScene> {
    let mut prims = vec![
        checker(plane([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]), [0.8, 0.78, 0.7], [0.3, 0.3, 0.32], 1.0),
        diffuse(plane([0.0, 0.0, -34.0], [0.0, 0.0, 1.0]), [0.55, 0.6, 0.7]),
        diffuse(cuboid([-2.2, 4.0, -32.0], [2.2, 4.4, -1.0]), [0.7, 0.65, 0.55]),
    ];
    for i in 0..12 {
        let z = -2.0 - 2.5 * i as f32;
        let colour = if i % 2 == 0 { [0.85, 0.82, 0.75] } else { [0.65, 0.45, 0.35] };
        prims.push(diffuse(cuboid([-1.9, 0.0, z - 0.2], [-1.5, 4.0, z + 0.2]), colour));
        prims.push(diffuse(cuboid([1.5, 0.0, z - 0.2], [1.9, 4.0, z + 0.2]), colour));
    }
    Ok(BuiltinScene {
        name: "columns",
        description: "a colonnade seen at an angle: a row of columns with high depth complexity",
        scene: Scene::new(prims, Lighting { direction: Vec3::new(0.6, 0.7, 0.3), ..Lighting::default() })?,
        camera: camera(Vec3::new(0.9, 1.6, 1.0), Vec3::new(-1.6, 1.5, -14.0)),
        lens: LensSettings::with_aperture_radius(8.0, 0.05),
    })
}

/// SplitMix64: a small fixed generator so the scenes (and the examples' estimators) do not depend
/// on a crate's algorithm. The state is the seed.
pub struct SplitMix(pub u64);

impl SplitMix {
    /// The next uniform float in [0, 1) (24 bits).
    pub fn next_f32(&mut self) -> f32 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        (z >> 40) as f32 / (1u64 << 24) as f32
    }
}

/// A dark room with 48 small emissive spheres between 1.5 and 25 m (each about 1-3 px across in
/// the pinhole image), emission from 200 to 200000 (some above the half-float range, 65504); a dim
/// floor and two diffuse boxes; in focus at 4 m.
fn highlights() -> Result<BuiltinScene> {
    let eye = Vec3::new(0.0, 1.2, 0.0);
    let cam = camera(eye, Vec3::new(0.0, 1.2, -10.0));
    let frame = cam.frame()?;
    let mut prims = vec![
        checker(plane([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]), [0.06, 0.06, 0.07], [0.12, 0.11, 0.1], 0.5),
        diffuse(plane([0.0, 0.0, -30.0], [0.0, 0.0, 1.0]), [0.04, 0.04, 0.05]),
        diffuse(cuboid([-1.6, 0.0, -4.5], [-0.8, 0.9, -3.7]), [0.5, 0.45, 0.4]),
        diffuse(cuboid([0.9, 0.0, -9.0], [1.9, 1.5, -8.0]), [0.35, 0.4, 0.5]),
    ];
    let palette = [[1.0, 0.85, 0.6], [1.0, 0.55, 0.3], [0.6, 0.8, 1.0], [1.0, 1.0, 1.0], [1.0, 0.4, 0.5], [0.5, 1.0, 0.6]];
    let mut rng = SplitMix(0x005e_ed0f_b0ce);
    let mut placed = 0;
    while placed < 48 {
        // Depth log-uniform in [1.5, 25], position uniform over the view.
        let z = 1.5 * (25.0f32 / 1.5).powf(rng.next_f32());
        let sx = (2.0 * rng.next_f32() - 1.0) * 0.95;
        let sy = (2.0 * rng.next_f32() - 1.0) * 0.95;
        let p = eye + z * (frame.forward + sx * frame.aspect * frame.tan_half_fov * frame.right + sy * frame.tan_half_fov * frame.up);
        let px_size = frame.pixel_footprint_radius(z) * 2.0;
        let radius = px_size * (0.6 + 0.9 * rng.next_f32());
        if p.y - radius <= 0.05 {
            continue;
        }
        let colour = palette[placed % palette.len()];
        let power = 2000.0 * 100.0f32.powf(rng.next_f32());
        prims.push(Primitive { shape: sphere(p.to_array(), radius), material: Material::Emissive(colour.map(|c| c * power)) });
        placed += 1;
    }
    Ok(BuiltinScene {
        name: "highlights",
        description: "a field of small, very bright emissive dots at various depths, for bokeh",
        scene: Scene::new(prims, Lighting { color: [0.15, 0.15, 0.18], ambient: [0.05, 0.05, 0.05], ..Lighting::default() })?,
        camera: cam,
        lens: LensSettings::with_aperture_radius(4.0, 0.04),
    })
}

fn emissive(shape: Shape, rgb: [f32; 3]) -> Primitive {
    Primitive { shape, material: Material::Emissive(rgb) }
}

/// An axis-aligned rectangle facing the camera (+Z) at depth `z`, from `(x0, y0)` to `(x1, y1)`.
fn facing_quad(x0: f32, y0: f32, x1: f32, y1: f32, z: f32) -> Shape {
    Shape::Quad { corner: Vec3::new(x0, y0, z), edge_u: Vec3::new(x1 - x0, 0.0, 0.0), edge_v: Vec3::new(0.0, y1 - y0, 0.0) }
}

/// A far wall of emissive tiles in `rows` x `cols` cells, colours cycling through a palette, from
/// `(x0, y0)` to `(x1, y1)` at depth `z`.
fn tiled_wall(x0: f32, y0: f32, x1: f32, y1: f32, z: f32, rows: u32, cols: u32) -> Vec<Primitive> {
    let palette =
        [[0.9, 0.75, 0.5], [0.35, 0.45, 0.3], [0.8, 0.35, 0.25], [0.25, 0.3, 0.55], [0.95, 0.9, 0.85], [0.5, 0.2, 0.4], [0.15, 0.15, 0.15]];
    let (w, h) = ((x1 - x0) / cols as f32, (y1 - y0) / rows as f32);
    let mut prims = Vec::new();
    for r in 0..rows {
        for c in 0..cols {
            let (x, y) = (x0 + c as f32 * w, y0 + r as f32 * h);
            prims.push(emissive(facing_quad(x, y, x + w, y + h, z), palette[((r * 3 + c * 5) % 7) as usize]));
        }
    }
    prims
}

/// The sky of the emissive scenes: a pale blue, bright enough that losing it shows.
const SKY: [f32; 3] = [0.45, 0.6, 0.9];

/// Vertical fence bars 1.5 m in front of the camera, out of focus (CoC about 25 px at 640x360), over
/// a far wall of emissive tiles at 20 m that fills the middle of the frame, with open sky in strips
/// above and below it; three small HDR lamps in front of the wall. The bars end inside the sky
/// strips, so their blurred ends are seen over the sky. In focus at 20 m.
fn fence() -> Result<BuiltinScene> {
    let mut prims = tiled_wall(-16.0, -4.0, 16.0, 4.0, -20.0, 4, 16);
    for (i, x) in [-4.0f32, 1.5, 5.0].iter().enumerate() {
        let power = [40.0, 300.0, 2000.0][i];
        prims.push(emissive(sphere([*x, 1.0 - i as f32, -18.0], 0.08), [power, 0.8 * power, 0.6 * power]));
    }
    for i in -8..=8 {
        let x = i as f32 * 0.12;
        prims.push(emissive(facing_quad(x - 0.016, -0.4, x + 0.016, 0.4, -1.5), [0.55, 0.32, 0.16]));
    }
    Ok(BuiltinScene {
        name: "fence",
        description: "out-of-focus fence bars over a far wall, open sky above and below it (emissive only)",
        scene: Scene::new(prims, Lighting::default())?.with_background(SKY)?,
        camera: camera(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0)),
        // Far-field CoC 2 px: the bars (z = 1.5) get 2·(20/1.5 − 1) ≈ 25 px.
        lens: LensSettings::with_aperture_radius(20.0, 0.045),
    })
}

/// Out-of-focus objects 1.2 m in front of the camera crossing each edge of the frame: a post on the
/// left and one on the right, a beam along the bottom and a branch across the top, over a far wall
/// of emissive tiles at 15 m with open sky above it. In focus at 15 m; the near objects' CoC is
/// about 30 px at 640x360, so their blur reaches into the frame from beyond its edges.
fn edges() -> Result<BuiltinScene> {
    let mut prims = tiled_wall(-12.0, -6.0, 12.0, 1.5, -15.0, 5, 12);
    let near = -1.2;
    let post = [0.7, 0.5, 0.3];
    prims.extend([
        emissive(facing_quad(-0.9, -1.0, -0.66, 1.0, near), post),
        emissive(facing_quad(0.68, -1.0, 0.95, 1.0, near), [0.3, 0.55, 0.35]),
        emissive(facing_quad(-1.0, -0.62, 1.0, -0.4, near), [0.85, 0.8, 0.7]),
        emissive(facing_quad(-0.3, 0.4, 1.0, 0.6, near - 0.1), [0.2, 0.25, 0.15]),
        emissive(sphere([-0.15, 0.5, near - 0.3], 0.04), [6.0, 5.0, 3.0]),
    ]);
    Ok(BuiltinScene {
        name: "edges",
        description: "out-of-focus near objects crossing each edge of the frame, open sky above (emissive only)",
        scene: Scene::new(prims, Lighting::default())?.with_background(SKY)?,
        camera: camera(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0)),
        // Far-field CoC 2.5 px: the near objects (z = 1.2) get 2.5·(15/1.2 − 1) ≈ 29 px.
        lens: LensSettings::with_aperture_radius(15.0, 0.045),
    })
}

/// Builds a scene from `(primitive, opacity)` pairs: an opacity below 1 makes that primitive
/// translucent ([`Scene::with_alpha`]).
fn translucent_scene(prims: Vec<(Primitive, f32)>, background: [f32; 3]) -> Result<Scene> {
    let alphas: Vec<f32> = prims.iter().map(|p| p.1).collect();
    let mut scene = Scene::new(prims.into_iter().map(|p| p.0).collect(), Lighting::default())?.with_background(background)?;
    for (i, a) in alphas.into_iter().enumerate() {
        if a < 1.0 {
            scene = scene.with_alpha(i, a)?;
        }
    }
    Ok(scene)
}

/// Two tinted translucent panes out of focus in front of a far wall: a blue one of opacity 0.35 at
/// 1.5 m and an amber one of opacity 0.6 at 2.5 m, overlapping in the middle of the frame, over a
/// wall of emissive tiles at 10 m (in focus) with open sky above it. Every edge of both panes lies
/// inside the frame, over the wall or the sky.
fn panes() -> Result<BuiltinScene> {
    let mut prims: Vec<(Primitive, f32)> = tiled_wall(-8.0, -3.0, 8.0, 1.5, -10.0, 4, 10).into_iter().map(|p| (p, 1.0)).collect();
    prims.push((emissive(facing_quad(-0.7, -0.35, 0.15, 0.3, -1.5), [0.2, 0.35, 0.7]), 0.35));
    prims.push((emissive(facing_quad(-0.2, -0.6, 1.1, 0.5, -2.5), [0.85, 0.5, 0.15]), 0.6));
    Ok(BuiltinScene {
        name: "panes",
        description: "two tinted translucent panes (opacity 0.35 and 0.6) out of focus in front of an in-focus wall (emissive only)",
        scene: translucent_scene(prims, SKY)?,
        camera: camera(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0)),
        // Far-field CoC 4 px: the panes get about 22 px (1.5 m) and 12 px (2.5 m).
        lens: LensSettings::with_aperture_radius(10.0, 0.04),
    })
}

/// Alpha-blended cards in the manner of foliage: 40 leaf-green cards of opacity 0.45 to 0.9, turned
/// in the image plane, 20 between 1.2 and 3 m (out of focus) and 20 around the focus at 8 m, over
/// a wall of emissive tiles at 12 m with open sky above it.
fn foliage() -> Result<BuiltinScene> {
    let mut prims: Vec<(Primitive, f32)> = tiled_wall(-10.0, -4.0, 10.0, 1.0, -12.0, 4, 12).into_iter().map(|p| (p, 1.0)).collect();
    let greens = [[0.2, 0.45, 0.12], [0.35, 0.6, 0.18], [0.55, 0.65, 0.2], [0.15, 0.3, 0.1]];
    let mut rng = SplitMix(0x00f0_11a9e);
    let half_view = (FOV_DEGREES.to_radians() * 0.5).tan();
    for i in 0..40 {
        let near = i < 20;
        let z = if near { 1.2 + 1.8 * rng.next_f32() } else { 7.0 + 2.0 * rng.next_f32() };
        // Centre within the view at that depth (16:9), size a fixed share of the view's height.
        let (hh, hw) = (z * half_view, z * half_view * 16.0 / 9.0);
        let (cx, cy) = ((2.0 * rng.next_f32() - 1.0) * hw * 0.9, (2.0 * rng.next_f32() - 1.0) * hh * 0.9);
        let size = hh * (if near { 0.12 } else { 0.06 }) * (0.6 + 0.8 * rng.next_f32());
        let angle = std::f32::consts::PI * rng.next_f32();
        let (u, v) = (Vec3::new(angle.cos(), angle.sin(), 0.0) * size, Vec3::new(-angle.sin(), angle.cos(), 0.0) * (0.5 * size));
        let corner = Vec3::new(cx, cy, -z) - 0.5 * (u + v);
        let alpha = 0.45 + 0.45 * rng.next_f32();
        prims.push((emissive(Shape::Quad { corner, edge_u: u, edge_v: v }, greens[i % greens.len()]), alpha));
    }
    Ok(BuiltinScene {
        name: "foliage",
        description: "alpha-blended leaf cards near the camera and around the focus, over a far wall and sky (emissive only)",
        scene: translucent_scene(prims, SKY)?,
        camera: camera(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0)),
        // Far-field CoC 3.1 px: the near cards get 5 to 18 px.
        lens: LensSettings::with_aperture_radius(8.0, 0.025),
    })
}

/// A translucent near object over open sky: a pale pane of opacity 0.45 at 1.2 m, out of focus
/// (CoC about 33 px at 640x360), mostly over the sky and crossing the top edge of a far wall of
/// emissive tiles at 12 m (in focus) that fills the lower part of the frame.
fn glass() -> Result<BuiltinScene> {
    let mut prims: Vec<(Primitive, f32)> = tiled_wall(-10.0, -5.0, 10.0, -0.8, -12.0, 3, 10).into_iter().map(|p| (p, 1.0)).collect();
    prims.push((emissive(facing_quad(-0.35, -0.12, 0.25, 0.32, -1.2), [0.55, 0.55, 0.6]), 0.45));
    Ok(BuiltinScene {
        name: "glass",
        description: "a translucent near pane over open sky and the top of an in-focus wall (emissive only)",
        scene: translucent_scene(prims, SKY)?,
        camera: camera(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0)),
        // Far-field CoC 3.7 px: the pane (z = 1.2) gets 3.7·(12/1.2 − 1) ≈ 33 px.
        lens: LensSettings::with_aperture_radius(12.0, 0.045),
    })
}
