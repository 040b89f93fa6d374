//! Exports an analytic scene as a Mitsuba 3 scene (Jakob et al. 2022, XML format 3.0.0), for an
//! independent check of the exact reference (`tools/independent_check.py`).
//!
//! Only scenes Mitsuba can render *exactly* are exported, so that the lens integration is the one
//! thing that differs; anything else is [`MitsubaExport::Skipped`] with the reason, never
//! approximated.
//! - Every surface is black (`diffuse`, reflectance 0) and carries an `area` emitter with the
//!   radiance the analytic lighting model gives it, so no shading model can differ: an emissive
//!   primitive its emission; a diffuse quad, plane or box face the model's radiance baked through
//!   [`Scene::shade`], which is exact because it is constant over a face (solid albedo) or takes
//!   two values laid out on a grid (a checker, as Mitsuba's `checkerboard` texture on the face's
//!   own coordinates). A diffuse sphere's radiance varies continuously: its scene is skipped.
//! - Mitsuba's area emitters emit only on the side of the shape's normal (the third column of a
//!   `rectangle`'s `to_world`), while analytic quads and planes are two-sided: each is turned
//!   towards the side the lens sees. A surface whose plane cuts the lens, or a closed shape the
//!   lens touches, is seen from both sides: skipped.
//! - Spheres are `sphere`s, quads and box faces `rectangle`s (an oblique quad as a sheared one,
//!   which Mitsuba 3.9 intersects exactly; early 3.x releases refuse shear), an infinite plane a square
//!   `rectangle` centred under the eye and twice as wide as the farthest point of it that any lens
//!   ray reaches first (sampled at every pixel corner from the lens centre and 8 rim points). A plane
//!   whose horizon is in view becomes a square [`HORIZON_FACTOR`] times its distance from the eye
//!   (solid colour: the gap below the horizon is far below a pixel), and is skipped when it carries
//!   a checker (whose cells float precision would shift on such a square).
//! - The camera is a `thinlens` sensor with the thin lens of the reference ([`mod@super::reference`]):
//!   the same aperture radius, [`ThinLens::aperture_radius`] in scene units, and the same planar
//!   focus distance, which [`CameraFrame::lens_ray`] takes; with them a point at depth `z` blurs to
//!   `K·|1 − z_f/z|` pixels ([`ThinLens::coc_px`]). `fov` is the vertical field of view with
//!   `fov_axis` y; a `lookat` transform (Mitsuba's camera looks down its local +Z, and `lookat`
//!   puts image +x on the camera's right: the image is not mirrored).
//! - A translucent quad or plane (opacity `α` below 1) gets a `mask` BSDF of opacity `α` over the
//!   black one and an emitter of `α` times its radiance: a ray sees `α·L` and passes on with
//!   probability `1 − α`, which is glTF's "over" ([`Scene::trace`]); `max_depth` grows by one per
//!   translucent surface so that the pass-throughs are not cut.
//! - `hdrfilm` (RGB, float32) with a `box` reconstruction filter: each sample stays in its pixel,
//!   as in the reference; integrator `path` with `max_depth` 2 (the first hit's emission; the black
//!   surfaces reflect nothing); the background a `constant` emitter. The sample count is the XML
//!   parameter `$spp` (default [`MitsubaOptions::spp`]).

use dof_shaders::lens::ThinLens;
use glam::Vec3;
use rayon::prelude::*;
use serde_json::{Value, json};

use super::analytic::{Albedo, Hit, Material, Primitive, Scene, Shape, surface_coords, tangents};
use super::camera::{Camera, CameraFrame, Ray};
use crate::error::{Error, Result};

/// A plane whose horizon is in view becomes a square this many times its distance from the eye in
/// half-side: the strip it leaves below the horizon is `1/HORIZON_FACTOR` radians high.
pub const HORIZON_FACTOR: f32 = 1e6;

/// Options of [`export_mitsuba`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MitsubaOptions {
    /// Default of the `$spp` parameter (samples per pixel).
    pub spp: u32,
}

impl Default for MitsubaOptions {
    fn default() -> Self {
        MitsubaOptions { spp: 1024 }
    }
}

/// An exported scene.
#[derive(Clone, Debug, PartialEq)]
pub struct MitsubaScene {
    pub xml: String,
    /// What the export decided (plane sizes), one line each.
    pub notes: Vec<String>,
}

/// What [`export_mitsuba`] made of a scene.
#[derive(Clone, Debug, PartialEq)]
pub enum MitsubaExport {
    Exact(MitsubaScene),
    /// The scene has something Mitsuba cannot reproduce exactly; the reason names it.
    Skipped(String),
}

/// Exports `scene` seen through `camera` and `lens` (module docs). Errors on an invalid camera or
/// lens; a scene without an exact counterpart is `Ok(Skipped(reason))`.
pub fn export_mitsuba(scene: &Scene, camera: &Camera, lens: &ThinLens, options: &MitsubaOptions) -> Result<MitsubaExport> {
    let frame = camera.frame()?;
    crate::lens::check(lens)?;
    let view = View { frame, radius: lens.aperture_radius, focus: lens.focus_distance };
    let reach = plane_reach(scene, &view);
    let mut shapes = Vec::new();
    let mut notes = Vec::new();
    for (i, prim) in scene.primitives().iter().enumerate() {
        match export_primitive(scene, &view, i, prim, reach[i], &mut notes)? {
            Ok(mut s) => shapes.append(&mut s),
            Err(why) => return Ok(MitsubaExport::Skipped(format!("primitive {i} ({}): {why}", kind(prim)))),
        }
    }
    // Far clip beyond everything exported, so nothing is cut off (Mitsuba's default is 10^4).
    let far = shapes.iter().map(|s| s.extent_from(view.frame.eye)).fold(1.0f32, f32::max) * 2.0;
    let xml = write_xml(scene, camera, lens, options, &shapes, far);
    Ok(MitsubaExport::Exact(MitsubaScene { xml, notes }))
}

/// The sidecar the tools read next to the XML: camera, lens (with its CoC model) and the outcome.
pub fn export_metadata(name: &str, camera: &Camera, lens: &ThinLens, export: &MitsubaExport) -> Value {
    let (exported, reason, notes) = match export {
        MitsubaExport::Exact(s) => (true, Value::Null, s.notes.clone()),
        MitsubaExport::Skipped(why) => (false, Value::String(why.clone()), Vec::new()),
    };
    json!({
        "scene": name,
        "exported": exported,
        "reason": reason,
        "notes": notes,
        "width": camera.width,
        "height": camera.height,
        "yfov_degrees": (camera.yfov_radians as f64).to_degrees(),
        "eye": camera.eye.to_array().map(short),
        "target": camera.target.to_array().map(short),
        "up": camera.up.to_array().map(short),
        "lens": {
            "focal_length": short(lens.focal_length),
            "aperture_radius": short(lens.aperture_radius),
            "focus_distance": short(lens.focus_distance),
            "pixels_per_unit": short(lens.pixels_per_unit),
            "coc_model": "coc_px(z) = far_limit_px * |1 - focus_distance / z|",
            "far_limit_px": short(lens.far_limit_px()),
        },
    })
}

/// An `f32` as the `f64` with the same shortest decimal text (0.045, not 0.04500000178813934).
fn short(v: f32) -> f64 {
    num(v).parse().unwrap_or(v as f64)
}

/// The camera and lens as the export needs them.
struct View {
    frame: CameraFrame,
    radius: f32,
    focus: f32,
}

/// Emitted radiance over a rectangle: one colour, or a checker of two over its `uv` (Mitsuba's
/// `checkerboard`: `color0` where the fractional parts of `uv·scale + offset` lie on the same side
/// of 1/2).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Radiance {
    Rgb([f32; 3]),
    Checker { color0: [f32; 3], color1: [f32; 3], scale: [f32; 2], offset: [f32; 2] },
}

impl Radiance {
    /// Every colour scaled by `k` (a translucent surface's opacity: premultiplied radiance).
    fn times(self, k: f32) -> Radiance {
        if k == 1.0 {
            return self;
        }
        let m = |c: [f32; 3]| c.map(|v| v * k);
        match self {
            Radiance::Rgb(c) => Radiance::Rgb(m(c)),
            Radiance::Checker { color0, color1, scale, offset } => {
                Radiance::Checker { color0: m(color0), color1: m(color1), scale, offset }
            }
        }
    }
}

/// A Mitsuba shape: the sphere, or the rectangle `centre + s·half_u + t·half_v`, `s, t` in
/// [−1, 1], emitting on the side of `normal` (unit).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Out {
    Sphere {
        center: Vec3,
        radius: f32,
        radiance: [f32; 3],
    },
    /// `alpha` below 1: translucent, a `mask` BSDF of that opacity over an emitter already scaled
    /// by it.
    Rect {
        center: Vec3,
        half_u: Vec3,
        half_v: Vec3,
        normal: Vec3,
        radiance: Radiance,
        alpha: f32,
    },
}

impl Out {
    /// Distance from `eye` to the farthest point of the shape (bounded above).
    fn extent_from(&self, eye: Vec3) -> f32 {
        match *self {
            Out::Sphere { center, radius, .. } => (center - eye).length() + radius,
            Out::Rect { center, half_u, half_v, .. } => (center - eye).length() + half_u.length() + half_v.length(),
        }
    }
}

/// "emissive sphere", "checker plane", ...: how a skip reason names a primitive.
fn kind(p: &Primitive) -> String {
    let material = match p.material {
        Material::Emissive(_) => "emissive",
        Material::Diffuse(Albedo::Solid(_)) => "diffuse",
        Material::Diffuse(Albedo::Checker { .. }) => "checker",
    };
    let shape = match p.shape {
        Shape::Sphere { .. } => "sphere",
        Shape::Cuboid { .. } => "box",
        Shape::Quad { .. } => "quad",
        Shape::Plane { .. } => "plane",
    };
    format!("{material} {shape}")
}

/// One primitive as Mitsuba shapes; `Ok(Err(reason))` when it has no exact counterpart.
fn export_primitive(
    scene: &Scene,
    view: &View,
    index: usize,
    prim: &Primitive,
    reach: Reach,
    notes: &mut Vec<String>,
) -> Result<std::result::Result<Vec<Out>, String>> {
    let eye = view.frame.eye;
    Ok(Ok(match prim.shape {
        Shape::Sphere { center, radius } => {
            let Material::Emissive(radiance) = prim.material else {
                return Ok(Err(
                    "the lighting model shades a diffuse sphere differently at every point; only emissive spheres export exactly".into(),
                ));
            };
            if (center - eye).length() <= radius + view.radius {
                return Ok(Err("the lens touches or lies inside the sphere".into()));
            }
            vec![Out::Sphere { center, radius, radiance }]
        }
        Shape::Quad { corner, edge_u, edge_v } => {
            let n = edge_u.cross(edge_v);
            let n = n / n.length();
            let Some(normal) = seen_side(view, n, corner) else {
                return Ok(Err("the plane of the quad cuts the lens, which sees both of its sides".into()));
            };
            let center = corner + 0.5 * edge_u + 0.5 * edge_v;
            let radiance = face_radiance(scene, prim, normal, corner, [corner + edge_u, corner + edge_v])?;
            let alpha = scene.alpha(index as u32);
            vec![Out::Rect { center, half_u: 0.5 * edge_u, half_v: 0.5 * edge_v, normal, radiance: radiance.times(alpha), alpha }]
        }
        Shape::Plane { point, normal } => {
            let n = normal.normalize();
            let Some(side) = seen_side(view, n, point) else {
                return Ok(Err("the plane cuts the lens, which sees both of its sides".into()));
            };
            let height = (eye - point).dot(n).abs();
            let center = eye - (eye - point).dot(n) * n;
            let half = match reach {
                Reach::Horizon if matches!(prim.material, Material::Diffuse(Albedo::Checker { .. })) => {
                    return Ok(Err("its horizon is in view, where a finite checkered square cannot stand in for it".into()));
                }
                Reach::Horizon => {
                    let half = HORIZON_FACTOR * height;
                    let gap_px = view.frame.height as f32 / (2.0 * view.frame.tan_half_fov) / HORIZON_FACTOR;
                    notes.push(format!(
                        "plane {index}: horizon in view, a square of half-side {half} (gap below the horizon {gap_px:.1e} px)"
                    ));
                    half
                }
                Reach::Within(d) => {
                    let half = (2.0 * d).max(height).max(f32::MIN_POSITIVE);
                    notes.push(format!("plane {index}: a square of half-side {half} (seen up to {d} from the eye's foot)"));
                    half
                }
            };
            let (t, b) = tangents(n);
            let corner = center - half * t - half * b;
            let far = [corner + 2.0 * half * t, corner + 2.0 * half * b];
            let radiance = face_radiance(scene, prim, side, corner, far)?;
            let alpha = scene.alpha(index as u32);
            vec![Out::Rect { center, half_u: half * t, half_v: half * b, normal: side, radiance: radiance.times(alpha), alpha }]
        }
        Shape::Cuboid { min, max } => {
            let size = max - min;
            if !(size.min_element() > 0.0) {
                return Ok(Err("a flat box (zero extent on an axis) has two coincident faces".into()));
            }
            if (eye - eye.clamp(min, max)).length() <= view.radius {
                return Ok(Err("the lens touches or lies inside the box".into()));
            }
            let center = 0.5 * (min + max);
            let mut faces = Vec::with_capacity(6);
            for axis in 0..3 {
                // The face's coordinate axes as the checker uses them (`surface_coords`).
                let (ua, va) = match axis {
                    0 => (2, 1),
                    1 => (0, 2),
                    _ => (0, 1),
                };
                for sign in [-1.0f32, 1.0] {
                    let normal = Vec3::AXES[axis] * sign;
                    let half_u = Vec3::AXES[ua] * 0.5 * size[ua];
                    let half_v = Vec3::AXES[va] * 0.5 * size[va];
                    let c = center + normal * 0.5 * size[axis];
                    let corner = c - half_u - half_v;
                    let radiance = face_radiance(scene, prim, normal, corner, [corner + 2.0 * half_u, corner + 2.0 * half_v])?;
                    faces.push(Out::Rect { center: c, half_u, half_v, normal, radiance, alpha: 1.0 });
                }
            }
            faces
        }
    }))
}

/// The unit normal of the side of the plane through `point` (normal `n`, unit) that every lens
/// point sees; `None` when the plane cuts the lens disc.
fn seen_side(view: &View, n: Vec3, point: Vec3) -> Option<Vec3> {
    let f = &view.frame;
    let s = (f.eye - point).dot(n);
    let spread = view.radius * (n.dot(f.right).powi(2) + n.dot(f.up).powi(2)).sqrt();
    (s.abs() > spread).then(|| if s > 0.0 { n } else { -n })
}

/// Radiance of a flat face seen from the side of `normal`: emission, or the lighting model baked
/// through [`Scene::shade`] (a checker as Mitsuba's checkerboard over the rectangle whose `uv`
/// origin is `corner` and whose `uv` axes end at `ends`).
fn face_radiance(scene: &Scene, prim: &Primitive, normal: Vec3, corner: Vec3, ends: [Vec3; 2]) -> Result<Radiance> {
    let albedo = match prim.material {
        Material::Emissive(c) => return Ok(Radiance::Rgb(c)),
        Material::Diffuse(a) => a,
    };
    // The model's radiance for albedo 1, from `shade` itself: albedo times it is bit for bit what
    // `shade` returns for that albedo (one product per channel either way).
    let unit = Scene::new(vec![Primitive { shape: prim.shape, material: Material::Diffuse(Albedo::Solid([1.0; 3])) }], *scene.lighting())?;
    let ray = Ray { origin: corner + normal, direction: -normal };
    let factor = unit.shade(&ray, &Hit { t: 1.0, primitive: 0, normal, self_occluded: false });
    let times = |a: [f32; 3]| [0, 1, 2].map(|k| a[k] * factor[k]);
    Ok(match albedo {
        Albedo::Solid(a) => Radiance::Rgb(times(a)),
        Albedo::Checker { a, b, cell } => {
            // The checker coordinates at the rectangle's uv origin and at the ends of its two uv
            // axes, over two cells (one period of Mitsuba's texture). The rectangle's axes are the
            // face's coordinate axes, so uv maps to them by a scale and an offset.
            let at = |p: Vec3| {
                let (u, v) = surface_coords(&prim.shape, p, normal);
                [u as f64 / (2.0 * cell as f64), v as f64 / (2.0 * cell as f64)]
            };
            let (o, eu, ev) = (at(corner), at(ends[0]), at(ends[1]));
            let (su, sv) = (eu[0] - o[0], ev[1] - o[1]);
            let skew = (eu[1] - o[1]).abs().max((ev[0] - o[0]).abs());
            if !(skew <= 1e-6 * su.abs().max(sv.abs())) {
                return Err(Error::invalid(format!("checker axes not along the face's edges (skew {skew})")));
            }
            Radiance::Checker { color0: times(a), color1: times(b), scale: [su as f32, sv as f32], offset: [o[0] as f32, o[1] as f32] }
        }
    })
}

/// How far a plane is seen from the foot of the eye on it.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Reach {
    /// Largest in-plane distance (either tangent) of a point of it that a lens ray sees first.
    Within(f32),
    /// Rays see it up to its horizon.
    Horizon,
}

/// Lens points the reach is sampled from: the centre and 8 on the rim.
fn lens_points(radius: f32) -> Vec<(f32, f32)> {
    let mut points = vec![(0.0, 0.0)];
    if radius > 0.0 {
        points.extend((0..8).map(|k| {
            let a = k as f32 * std::f32::consts::FRAC_PI_4;
            (radius * a.cos(), radius * a.sin())
        }));
    }
    points
}

/// Per primitive, how far each plane is seen (`Within(0)` for other primitives). Rays go through
/// every pixel corner from each lens point; a plane is seen as far as its farthest first hit, and
/// where a ray that sees it neighbours one that never meets it (the horizon lies between), as far
/// as what that neighbour hits, or up to its horizon when the neighbour escapes.
fn plane_reach(scene: &Scene, view: &View) -> Vec<Reach> {
    let planes: Vec<(usize, Vec3, Vec3)> = scene
        .primitives()
        .iter()
        .enumerate()
        .filter_map(|(i, p)| match p.shape {
            Shape::Plane { point, normal } => Some((i, point, normal.normalize())),
            _ => None,
        })
        .collect();
    let mut reach = vec![Reach::Within(0.0); scene.primitives().len()];
    if planes.is_empty() {
        return reach;
    }
    let f = &view.frame;
    let (w, h) = (f.width as usize + 1, f.height as usize + 1);
    for (lx, ly) in lens_points(view.radius) {
        let ray_at = |x: usize, y: usize| f.lens_ray(x as f32, y as f32, lx, ly, view.focus);
        // What every corner ray sees: its hits up to the first opaque one (primitive index and
        // point), and whether it escapes past them.
        let hits: Vec<(Vec<(u32, Vec3)>, bool)> = (0..w * h)
            .into_par_iter()
            .map_init(Vec::new, |all, k| {
                let ray = ray_at(k % w, k / w);
                visible_hits(scene, &ray, all)
            })
            .collect();
        for &(i, point, n) in &planes {
            let eye_foot = f.eye - (f.eye - point).dot(n) * n;
            let (t, b) = tangents(n);
            let dist = |p: Vec3| (p - eye_foot).dot(t).abs().max((p - eye_foot).dot(b).abs());
            let meets = |ray: &Ray| {
                let denom = ray.direction.dot(n);
                denom != 0.0 && ((point - ray.origin).dot(n) / denom) > 0.0
            };
            let mut far = 0.0f32;
            let mut horizon = false;
            for k in 0..w * h {
                let Some(&(_, p)) = hits[k].0.iter().find(|(prim, _)| *prim as usize == i) else { continue };
                far = far.max(dist(p));
                let (x, y) = (k % w, k / w);
                let neighbours = [(x.wrapping_sub(1), y), (x + 1, y), (x, y.wrapping_sub(1)), (x, y + 1)];
                for (nx, ny) in neighbours.into_iter().filter(|&(nx, ny)| nx < w && ny < h) {
                    if meets(&ray_at(nx, ny)) {
                        continue;
                    }
                    let (seen, escapes) = &hits[ny * w + nx];
                    if *escapes {
                        horizon = true;
                    }
                    if let Some(&(_, q)) = seen.last() {
                        far = far.max(dist(q));
                    }
                }
            }
            reach[i] = if horizon || !far.is_finite() { Reach::Horizon } else { Reach::Within(far) };
        }
    }
    reach
}

/// The hits of `ray` up to and including the first opaque one (every surface it shows), and
/// whether it escapes past them (no opaque hit); `all` is a reused buffer.
fn visible_hits(scene: &Scene, ray: &Ray, all: &mut Vec<Hit>) -> (Vec<(u32, Vec3)>, bool) {
    if !scene.has_translucency() {
        return match scene.first_hit(ray, 0.0) {
            Some(hit) => (vec![(hit.primitive, ray.at(hit.t))], false),
            None => (Vec::new(), true),
        };
    }
    scene.all_hits(ray, 0.0, all);
    let mut seen = Vec::new();
    for hit in all.iter().filter(|h| !h.self_occluded) {
        seen.push((hit.primitive, ray.at(hit.t)));
        if scene.alpha(hit.primitive) >= 1.0 {
            return (seen, false);
        }
    }
    (seen, true)
}

/// Writes the scene file.
fn write_xml(scene: &Scene, camera: &Camera, lens: &ThinLens, options: &MitsubaOptions, shapes: &[Out], far_clip: f32) -> String {
    let mut x = Xml::default();
    x.out.push_str("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n");
    x.comment("Exported by dof (host/src/scene/mitsuba_export.rs): emissive-only surfaces (black BSDF, area emitter");
    x.comment("with the analytic model's radiance), the exact reference's thin lens, a box pixel filter.");
    x.open("scene", &[("version", "3.0.0".into())]);
    x.leaf("default", &[("name", "spp".into()), ("value", options.spp.to_string())]);
    // Depth 2 is the first hit's emission; each translucent (flat) surface a ray can cross adds one
    // interaction, its mask's pass-through.
    let translucent = (0..scene.primitives().len() as u32).filter(|&i| scene.alpha(i) < 1.0).count();
    x.open("integrator", &[("type", "path".into())]);
    x.leaf("integer", &[("name", "max_depth".into()), ("value", (2 + translucent).to_string())]);
    x.close("integrator");
    x.open("sensor", &[("type", "thinlens".into())]);
    x.float("fov", (camera.yfov_radians as f64).to_degrees() as f32);
    x.leaf("string", &[("name", "fov_axis".into()), ("value", "y".into())]);
    x.comment(&format!("The reference's lens: far-field CoC {} px, coc_px(z) = K |1 - z_f/z|.", lens.far_limit_px()));
    x.float("aperture_radius", lens.aperture_radius);
    x.float("focus_distance", lens.focus_distance);
    x.float("near_clip", NEAR_CLIP);
    x.float("far_clip", far_clip);
    x.open("transform", &[("name", "to_world".into())]);
    x.leaf("lookat", &[("origin", vec3(camera.eye)), ("target", vec3(camera.target)), ("up", vec3(camera.up))]);
    x.close("transform");
    x.open("sampler", &[("type", "independent".into())]);
    x.leaf("integer", &[("name", "sample_count".into()), ("value", "$spp".into())]);
    x.close("sampler");
    x.open("film", &[("type", "hdrfilm".into())]);
    x.leaf("integer", &[("name", "width".into()), ("value", camera.width.to_string())]);
    x.leaf("integer", &[("name", "height".into()), ("value", camera.height.to_string())]);
    x.leaf("string", &[("name", "pixel_format".into()), ("value", "rgb".into())]);
    x.leaf("string", &[("name", "component_format".into()), ("value", "float32".into())]);
    x.leaf("rfilter", &[("type", "box".into())]);
    x.close("film");
    x.close("sensor");
    x.open("bsdf", &[("type", "diffuse".into()), ("id", "black".into())]);
    x.leaf("rgb", &[("name", "reflectance".into()), ("value", "0, 0, 0".into())]);
    x.close("bsdf");
    let bg = scene.background();
    if bg.iter().any(|&v| v > 0.0) {
        x.open("emitter", &[("type", "constant".into())]);
        x.rgb("radiance", bg);
        x.close("emitter");
    }
    for s in shapes {
        write_shape(&mut x, s);
    }
    x.close("scene");
    x.out
}

/// Mitsuba's near clip moves ray origins along the view axis; every built-in surface is farther.
const NEAR_CLIP: f32 = 1e-3;

fn write_shape(x: &mut Xml, shape: &Out) {
    match *shape {
        Out::Sphere { center, radius, radiance } => {
            x.open("shape", &[("type", "sphere".into())]);
            x.leaf("point", &[("name", "center".into()), ("value", vec3(center))]);
            x.float("radius", radius);
            x.leaf("ref", &[("id", "black".into())]);
            emitter(x, &Radiance::Rgb(radiance));
        }
        Out::Rect { center, half_u, half_v, normal, radiance, alpha } => {
            x.open("shape", &[("type", "rectangle".into())]);
            x.open("transform", &[("name", "to_world".into())]);
            // Columns: local x, y, z (the emitting side) and the centre.
            let cols = [half_u, half_v, normal, center];
            let m: Vec<String> =
                (0..3).flat_map(|r| cols.iter().map(move |c| num(c[r]))).chain(["0", "0", "0", "1"].map(String::from)).collect();
            x.leaf("matrix", &[("value", m.join(" "))]);
            x.close("transform");
            if alpha < 1.0 {
                // glTF's "over": the emitter shows alpha times the radiance (already scaled), and
                // the mask lets 1 − alpha of the rays through to what lies behind.
                x.open("bsdf", &[("type", "mask".into())]);
                x.float("opacity", alpha);
                x.leaf("ref", &[("id", "black".into())]);
                x.close("bsdf");
            } else {
                x.leaf("ref", &[("id", "black".into())]);
            }
            emitter(x, &radiance);
        }
    }
    x.close("shape");
}

fn emitter(x: &mut Xml, radiance: &Radiance) {
    x.open("emitter", &[("type", "area".into())]);
    match *radiance {
        Radiance::Rgb(c) => x.rgb("radiance", c),
        Radiance::Checker { color0, color1, scale, offset } => {
            x.open("texture", &[("type", "checkerboard".into()), ("name", "radiance".into())]);
            x.rgb("color0", color0);
            x.rgb("color1", color1);
            // Scale, then translate: Mitsuba 3.9 drops the translation of a 3x3 `matrix` here.
            x.open("transform", &[("name", "to_uv".into())]);
            x.leaf("scale", &[("x", num(scale[0])), ("y", num(scale[1]))]);
            x.leaf("translate", &[("x", num(offset[0])), ("y", num(offset[1]))]);
            x.close("transform");
            x.close("texture");
        }
    }
    x.close("emitter");
}

/// Shortest text that reads back as the same `f32`.
fn num(v: f32) -> String {
    format!("{v}")
}

fn vec3(v: Vec3) -> String {
    format!("{}, {}, {}", num(v.x), num(v.y), num(v.z))
}

/// A minimal indented XML writer (attribute values here are numbers and identifiers).
#[derive(Default)]
struct Xml {
    out: String,
    depth: usize,
}

impl Xml {
    fn tag(&mut self, name: &str, attrs: &[(&str, String)], end: &str) {
        self.out.push_str(&"    ".repeat(self.depth));
        self.out.push('<');
        self.out.push_str(name);
        for (k, v) in attrs {
            self.out.push_str(&format!(" {k}=\"{}\"", v.replace('&', "&amp;").replace('"', "&quot;").replace('<', "&lt;")));
        }
        self.out.push_str(end);
        self.out.push('\n');
    }

    fn open(&mut self, name: &str, attrs: &[(&str, String)]) {
        self.tag(name, attrs, ">");
        self.depth += 1;
    }

    fn leaf(&mut self, name: &str, attrs: &[(&str, String)]) {
        self.tag(name, attrs, "/>");
    }

    fn close(&mut self, name: &str) {
        self.depth = self.depth.saturating_sub(1);
        self.out.push_str(&format!("{}</{name}>\n", "    ".repeat(self.depth)));
    }

    /// A comment; `--` may not appear inside one.
    fn comment(&mut self, text: &str) {
        self.out.push_str(&format!("{}<!-- {} -->\n", "    ".repeat(self.depth), text.replace("--", "- -")));
    }

    fn float(&mut self, name: &str, v: f32) {
        self.leaf("float", &[("name", name.into()), ("value", num(v))]);
    }

    fn rgb(&mut self, name: &str, c: [f32; 3]) {
        self.leaf("rgb", &[("name", name.into()), ("value", format!("{}, {}, {}", num(c[0]), num(c[1]), num(c[2])))]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::builtin::builtin;

    fn export(name: &str, width: u32, height: u32) -> (MitsubaExport, ThinLens) {
        let b = builtin(name).unwrap().with_size(width, height);
        let lens = b.thin_lens().unwrap();
        (export_mitsuba(&b.scene, &b.camera, &lens, &MitsubaOptions::default()).unwrap(), lens)
    }

    /// Every opened tag is closed in order, and the document is one `scene` element.
    fn check_well_formed(xml: &str) {
        let mut stack: Vec<String> = Vec::new();
        let mut rest = xml;
        let mut roots = 0;
        while let Some(start) = rest.find('<') {
            let end = rest[start..].find('>').expect("unterminated tag") + start;
            let tag = &rest[start + 1..end];
            rest = &rest[end + 1..];
            if tag.starts_with('?') || tag.starts_with("!--") {
                assert!(tag.ends_with('?') || tag.ends_with("--"), "bad declaration or comment <{tag}>");
                continue;
            }
            assert_eq!(tag.matches('"').count() % 2, 0, "unbalanced quotes in <{tag}>");
            if let Some(name) = tag.strip_prefix('/') {
                assert_eq!(stack.pop().as_deref(), Some(name), "mismatched </{name}>");
            } else {
                let name = tag.split_whitespace().next().unwrap().trim_end_matches('/').to_string();
                if stack.is_empty() {
                    roots += 1;
                }
                if !tag.ends_with('/') {
                    stack.push(name);
                }
            }
        }
        assert!(stack.is_empty(), "unclosed: {stack:?}");
        assert_eq!(roots, 1);
    }

    fn attr(xml: &str, name: &str) -> f32 {
        let key = format!("name=\"{name}\" value=\"");
        let at = xml.find(&key).unwrap_or_else(|| panic!("no {name}")) + key.len();
        xml[at..at + xml[at..].find('"').unwrap()].parse().unwrap()
    }

    #[test]
    fn emissive_scenes_export_with_their_lens_and_sky() {
        for name in ["fence", "edges"] {
            let (MitsubaExport::Exact(s), lens) = export(name, 320, 240) else { panic!("{name} must export") };
            check_well_formed(&s.xml);
            assert!(s.xml.contains("<scene version=\"3.0.0\">"));
            assert!(s.xml.contains("<sensor type=\"thinlens\">") && s.xml.contains("<rfilter type=\"box\"/>"));
            assert!(s.xml.contains("<emitter type=\"constant\">"), "{name}: the sky");
            // The reference's own lens: the radius lens_ray gets and the planar focus distance.
            assert_eq!(attr(&s.xml, "aperture_radius"), lens.aperture_radius);
            assert_eq!(attr(&s.xml, "focus_distance"), lens.focus_distance);
            assert_eq!(attr(&s.xml, "fov"), 40.0);
            let b = builtin(name).unwrap();
            let shapes = s.xml.matches("<shape ").count();
            assert_eq!(shapes, b.scene.primitives().len(), "{name}: one shape per quad or sphere");
            assert_eq!(s.xml.matches("<emitter type=\"area\">").count(), shapes);
        }
    }

    #[test]
    fn inexact_scenes_are_skipped_with_a_reason() {
        for name in ["simple", "railing"] {
            match export(name, 64, 48).0 {
                MitsubaExport::Skipped(why) => assert!(why.contains("diffuse sphere"), "{name}: {why}"),
                MitsubaExport::Exact(_) => panic!("{name} has diffuse spheres and must be skipped"),
            }
        }
        // A diffuse plane seen up to its horizon with a checker cannot be a finite square.
        let camera = Camera::look_at(Vec3::new(0.0, 1.0, 0.0), Vec3::new(0.0, 1.0, -1.0), 0.7, 64, 48);
        let floor = Primitive {
            shape: Shape::Plane { point: Vec3::ZERO, normal: Vec3::Y },
            material: Material::Diffuse(Albedo::Checker { a: [1.0; 3], b: [0.0; 3], cell: 1.0 }),
        };
        let scene = Scene::new(vec![floor], Default::default()).unwrap();
        let lens = crate::scene::lens::LensSettings::with_aperture_radius(5.0, 0.02).thin_lens(&camera).unwrap();
        let MitsubaExport::Skipped(why) = export_mitsuba(&scene, &camera, &lens, &MitsubaOptions::default()).unwrap() else { panic!() };
        assert!(why.contains("horizon"), "{why}");
        // The same floor in a solid colour is a very large square.
        let solid = Primitive { material: Material::Diffuse(Albedo::Solid([0.5; 3])), ..floor };
        let scene = Scene::new(vec![solid], Default::default()).unwrap();
        let MitsubaExport::Exact(s) = export_mitsuba(&scene, &camera, &lens, &MitsubaOptions::default()).unwrap() else { panic!() };
        assert!(s.notes[0].contains("horizon"), "{:?}", s.notes);
        assert!(attr(&s.xml, "far_clip") > 2.0 * HORIZON_FACTOR);
    }

    #[test]
    fn lens_radius_gives_the_coc_model() {
        // A rim ray of the reference's thin lens (radius R, as `reference` passes it to lens_ray)
        // lands coc_px(z)/2 pixels from the pinhole ray's point at depth z, on both sides of focus.
        let b = builtin("fence").unwrap().with_size(320, 240);
        let lens = b.thin_lens().unwrap();
        let f = b.camera.frame().unwrap();
        let (px, py) = (100.5, 70.5);
        for z in [1.2f32, 3.0, 19.0, 40.0, 1000.0] {
            let pinhole = f.lens_ray(px, py, 0.0, 0.0, lens.focus_distance).at(z);
            let rim = f.lens_ray(px, py, lens.aperture_radius, 0.0, lens.focus_distance).at(z);
            let offset_px = (rim - pinhole).length() / (2.0 * f.pixel_footprint_radius(z));
            let expected = 0.5 * lens.coc_px(z);
            assert!((offset_px - expected).abs() <= 1e-3 * expected.max(1.0), "z = {z}: {offset_px} px, model {expected} px");
        }
    }

    #[test]
    fn diffuse_faces_bake_the_lighting_model() {
        // `highlights`: checker floor, diffuse wall and boxes, emissive spheres: exact.
        let (MitsubaExport::Exact(s), _) = export("highlights", 64, 48) else { panic!("highlights must export") };
        check_well_formed(&s.xml);
        assert_eq!(s.xml.matches("type=\"checkerboard\"").count(), 1);
        // A box face's radiance is what shade gives a ray hitting it from outside.
        let b = builtin("highlights").unwrap();
        let (i, prim) = b.scene.primitives().iter().enumerate().find(|(_, p)| matches!(p.shape, Shape::Cuboid { .. })).unwrap();
        let Shape::Cuboid { min, max } = prim.shape else { unreachable!() };
        let c = 0.5 * (min + max);
        let ray = Ray { origin: Vec3::new(c.x, c.y, 10.0), direction: Vec3::new(0.0, 0.0, -1.0) };
        let hit = b.scene.first_hit(&ray, 0.0).unwrap();
        assert_eq!(hit.primitive as usize, i);
        let rgb = b.scene.shade(&ray, &hit);
        assert!(s.xml.contains(&format!("value=\"{}, {}, {}\"", rgb[0], rgb[1], rgb[2])), "front face radiance {rgb:?}");
    }

    #[test]
    fn checkers_land_on_the_analytic_cells() {
        // `columns`' floor: Mitsuba's rule (color0 where the fractional parts of uv·scale + offset
        // lie on the same side of 1/2) on the exported square against `shade` at the same point.
        let b = builtin("columns").unwrap().with_size(64, 48);
        let lens = b.thin_lens().unwrap();
        let view = View { frame: b.camera.frame().unwrap(), radius: lens.aperture_radius, focus: lens.focus_distance };
        let reach = plane_reach(&b.scene, &view);
        let prim = b.scene.primitives()[0];
        let shapes = export_primitive(&b.scene, &view, 0, &prim, reach[0], &mut Vec::new()).unwrap().unwrap();
        let Out::Rect { center, half_u, half_v, radiance: Radiance::Checker { color0, color1, scale, offset }, .. } = shapes[0] else {
            panic!("the floor is a checkered rectangle")
        };
        let mut checked = 0;
        for i in 0..400 {
            let p = Vec3::new(-6.0 + 0.5848 * (i % 20) as f32, 0.0, -0.3 - 1.4672 * (i / 20) as f32);
            let near_edge = |v: f32| (v - v.round()).abs() < 1e-3;
            if near_edge(p.x) || near_edge(p.z) {
                continue; // on a cell boundary, where rounding may pick either side
            }
            let ray = Ray { origin: b.camera.eye, direction: (p - b.camera.eye) / (p - b.camera.eye).dot(view.frame.forward) };
            let Some(hit) = b.scene.first_hit(&ray, 0.0).filter(|h| h.primitive == 0) else { continue };
            let local = [(p - center).dot(half_u) / half_u.length_squared(), (p - center).dot(half_v) / half_v.length_squared()];
            let side = |k: usize| {
                let t = (0.5 * local[k] + 0.5) * scale[k] + offset[k];
                t - t.floor() > 0.5
            };
            let expected = if side(0) == side(1) { color0 } else { color1 };
            assert_eq!(b.scene.shade(&ray, &hit), expected, "at {p}");
            checked += 1;
        }
        assert!(checked > 100, "{checked} points on the visible floor");
    }

    #[test]
    fn planes_cover_the_view() {
        // `simple`'s far wall (were its sphere emissive): the square reaches beyond every corner ray.
        let b = builtin("simple").unwrap().with_size(64, 36);
        let lens = b.thin_lens().unwrap();
        let f = b.camera.frame().unwrap();
        let view = View { frame: f, radius: lens.aperture_radius, focus: lens.focus_distance };
        let Reach::Within(d) = plane_reach(&b.scene, &view)[0] else { panic!("the wall faces the camera") };
        let corner = f.lens_ray(0.0, 0.0, -lens.aperture_radius, 0.0, lens.focus_distance).at(12.0);
        assert!(d >= corner.x.abs() && d >= corner.y.abs() && d < 2.0 * corner.x.abs(), "reach {d}, corner {corner}");
    }
}
