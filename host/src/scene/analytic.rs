//! Analytic scenes: spheres, axis-aligned boxes, parallelograms (quads) and infinite planes, each
//! diffuse or emissive, intersected exactly.
//!
//! Lighting model (deliberately simple and view-independent, so every renderer can match it):
//! - a diffuse surface with albedo `a` at a point with unit normal `n` (turned to face the incoming
//!   ray) has radiance `a · (ambient + light_color · max(0, n·l))`, `l` the unit direction *towards*
//!   the one directional light; no shadows, no interreflection;
//! - an emissive surface has radiance equal to its emission, unlit; emission may exceed the
//!   half-float range (65504), as highlights do;
//! - where a ray hits nothing it sees the background ([`Scene::background`], black unless set): a
//!   surface at infinite depth, the deepest fragment of every pixel whose ray escapes;
//! - a flat primitive (quad or plane) may be translucent, with an opacity `alpha` in [0, 1]
//!   ([`Scene::with_alpha`]; 1 unless set): it shows `alpha` times its radiance and lets `1 − alpha`
//!   of what lies behind it through, glTF's `BLEND` ("over" with premultiplied colour, Porter and
//!   Duff 1984). A ray composites every surface it crosses front to back until an opaque one or the
//!   background ([`Scene::trace`]). Closed shapes stay opaque: their inner faces would need a
//!   radiance of their own.

use dof_shaders::radiance::COLOR_MAX;
use dof_shaders::slot::{Composite, premultiply};
use glam::Vec3;

use super::bvh::{Aabb, Bvh};
use super::camera::Ray;
use crate::error::{CoreError, Error, Result};

/// The geometry of one primitive.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    Sphere {
        center: Vec3,
        radius: f32,
    },
    /// Axis-aligned box, `min <= max` on every axis.
    Cuboid {
        min: Vec3,
        max: Vec3,
    },
    /// Parallelogram `corner + a·edge_u + b·edge_v`, `a, b` in [0, 1]; two-sided.
    Quad {
        corner: Vec3,
        edge_u: Vec3,
        edge_v: Vec3,
    },
    /// Infinite plane through `point` with normal `normal` (any length); two-sided.
    Plane {
        point: Vec3,
        normal: Vec3,
    },
}

/// Diffuse reflectance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Albedo {
    Solid([f32; 3]),
    /// Alternating squares of side `cell` (scene units) in the surface's own coordinates (quads:
    /// along the edges from the corner; planes: two fixed tangents; boxes: the face's two axes;
    /// spheres: longitude and latitude arc lengths).
    Checker {
        a: [f32; 3],
        b: [f32; 3],
        cell: f32,
    },
}

/// How a surface looks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Material {
    Diffuse(Albedo),
    /// Emitted linear radiance, unlit.
    Emissive([f32; 3]),
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Primitive {
    pub shape: Shape,
    pub material: Material,
}

/// One directional light plus ambient, and the background.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lighting {
    /// Direction *towards* the light (any length, not zero).
    pub direction: Vec3,
    pub color: [f32; 3],
    pub ambient: [f32; 3],
    /// Radiance of the background, what a ray that hits nothing sees (black by default): a surface
    /// at infinite depth, the deepest fragment of every pixel whose ray escapes.
    pub background: [f32; 3],
}

impl Default for Lighting {
    fn default() -> Self {
        Lighting { direction: Vec3::new(-0.4, 0.8, 0.45), color: [0.8, 0.8, 0.8], ambient: [0.2, 0.2, 0.2], background: [0.0; 3] }
    }
}

/// A scene: primitives and lighting. Build it with [`Scene::new`], which validates.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    primitives: Vec<Primitive>,
    lighting: Lighting,
    light_dir: Vec3,
    /// Hierarchy over the bounded primitives.
    bvh: Bvh,
    /// Planes, tested by every ray.
    unbounded: Vec<u32>,
    /// Opacity per primitive, in [0, 1] (1: opaque; below 1 only for quads and planes).
    alpha: Vec<f32>,
    /// Whether any primitive is translucent (rays then composite past their first hit).
    translucent: bool,
}

/// One intersection of a ray with a primitive.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Ray parameter; for camera rays (unit component along the view axis) the planar depth.
    pub t: f32,
    /// Index of the primitive in the scene.
    pub primitive: u32,
    /// Geometric normal, unit length up to rounding: outward for spheres and boxes, the shape's own
    /// normal for quads and planes (not yet turned towards the ray).
    pub normal: Vec3,
    /// The exit point of a closed shape (sphere, box) whose entry point lies on the same ray, in
    /// front of it: hidden behind the shape's own front face from every viewpoint outside the shape.
    pub self_occluded: bool,
}

impl Scene {
    /// Validates and builds a scene. Errors on non-finite values, a non-positive sphere radius, a box
    /// with `min > max`, a degenerate quad or plane normal, a zero light direction, a NaN, negative
    /// or infinite colour, or a non-positive checker cell, naming the primitive.
    pub fn new(primitives: Vec<Primitive>, lighting: Lighting) -> Result<Self> {
        if primitives.len() > u32::MAX as usize {
            return Err(Error::Core(CoreError::TooLarge {
                what: "primitives".into(),
                size: primitives.len() as u64,
                limit: u32::MAX as u64,
            }));
        }
        for (i, p) in primitives.iter().enumerate() {
            let bad = |why: &str| Error::invalid(format!("primitive {i} ({:?}): {why}", p.shape));
            match p.shape {
                Shape::Sphere { center, radius } => {
                    if !center.is_finite() || !(radius > 0.0 && radius.is_finite()) {
                        return Err(bad("a sphere needs a finite centre and a positive finite radius"));
                    }
                }
                Shape::Cuboid { min, max } => {
                    if !min.is_finite() || !max.is_finite() || !min.cmple(max).all() {
                        return Err(bad("a box needs finite corners with min <= max"));
                    }
                }
                Shape::Quad { corner, edge_u, edge_v } => {
                    if !corner.is_finite() || !edge_u.is_finite() || !edge_v.is_finite() || !(edge_u.cross(edge_v).length_squared() > 0.0) {
                        return Err(bad("a quad needs finite, non-parallel, non-zero edges"));
                    }
                }
                Shape::Plane { point, normal } => {
                    if !point.is_finite() || !normal.is_finite() || !(normal.length_squared() > 0.0) {
                        return Err(bad("a plane needs a finite point and a non-zero normal"));
                    }
                }
            }
            let colour_ok = |c: [f32; 3]| c.iter().all(|v| *v >= 0.0 && v.is_finite());
            let ok = match p.material {
                Material::Emissive(c) | Material::Diffuse(Albedo::Solid(c)) => colour_ok(c),
                Material::Diffuse(Albedo::Checker { a, b, cell }) => colour_ok(a) && colour_ok(b) && cell > 0.0 && cell.is_finite(),
            };
            if !ok {
                return Err(bad("colours must be finite and not negative, checker cells positive"));
            }
        }
        let l = lighting;
        if !l.direction.is_finite() || !(l.direction.length_squared() > 0.0) {
            return Err(Error::invalid("the light direction must be finite and not zero".into()));
        }
        if !l.color.iter().chain(l.ambient.iter()).all(|v| *v >= 0.0 && v.is_finite()) {
            return Err(Error::invalid("light and ambient colours must be finite and not negative".into()));
        }
        check_background(l.background)?;
        let lighting = Lighting { background: in_contract(l.background), ..lighting };
        let mut boxes = Vec::new();
        let mut unbounded = Vec::new();
        for (i, p) in primitives.iter().enumerate() {
            match bounds(&p.shape) {
                Some(b) => boxes.push((i as u32, b)),
                None => unbounded.push(i as u32),
            }
        }
        let alpha = vec![1.0; primitives.len()];
        Ok(Scene {
            bvh: Bvh::build(&boxes),
            unbounded,
            primitives,
            lighting,
            light_dir: l.direction.normalize(),
            alpha,
            translucent: false,
        })
    }

    /// The same scene with primitive `index` translucent, of opacity `alpha` (module docs). Errors on
    /// an index out of range, an opacity that is NaN or outside [0, 1], or a translucent closed
    /// shape (sphere, box).
    pub fn with_alpha(mut self, index: usize, alpha: f32) -> Result<Self> {
        let Some(p) = self.primitives.get(index) else {
            return Err(Error::invalid(format!("no primitive {index} to make translucent ({} in the scene)", self.primitives.len())));
        };
        if !(0.0..=1.0).contains(&alpha) {
            return Err(Error::invalid(format!("primitive {index}: an opacity lies in [0, 1], got {alpha}")));
        }
        if alpha < 1.0 && !matches!(p.shape, Shape::Quad { .. } | Shape::Plane { .. }) {
            return Err(Error::invalid(format!(
                "primitive {index} ({:?}): only quads and planes may be translucent (a closed shape's inner faces have no radiance of their own)",
                p.shape
            )));
        }
        self.alpha[index] = alpha;
        self.translucent = self.alpha.iter().any(|a| *a < 1.0);
        Ok(self)
    }

    /// Opacity of primitive `index` (1 for an index naming no primitive).
    pub fn alpha(&self, index: u32) -> f32 {
        self.alpha.get(index as usize).copied().unwrap_or(1.0)
    }

    /// Whether any primitive is translucent.
    pub fn has_translucency(&self) -> bool {
        self.translucent
    }

    /// The same scene with another background radiance. Errors on a NaN, negative or infinite value.
    pub fn with_background(mut self, rgb: [f32; 3]) -> Result<Self> {
        check_background(rgb)?;
        self.lighting.background = in_contract(rgb);
        Ok(self)
    }

    /// Radiance of the background: what a ray that hits nothing sees, at infinite depth.
    pub fn background(&self) -> [f32; 3] {
        self.lighting.background
    }

    pub fn primitives(&self) -> &[Primitive] {
        &self.primitives
    }

    pub fn lighting(&self) -> &Lighting {
        &self.lighting
    }

    /// Every intersection with `t > t_min`, front to back (ties by primitive index, entry before
    /// exit), appended to `out` after clearing it. A ray with a zero or non-finite direction or
    /// origin hits nothing.
    pub fn all_hits(&self, ray: &Ray, t_min: f32, out: &mut Vec<Hit>) {
        out.clear();
        let Some(ray) = Prepared::new(ray) else { return };
        let mut emit = |h| out.push(h);
        for &i in &self.unbounded {
            intersect(&self.primitives[i as usize].shape, i, &ray, t_min, &mut emit);
        }
        let mut t_max = f32::INFINITY;
        self.bvh.traverse(ray.origin, ray.direction, t_min, &mut t_max, |i, _| {
            intersect(&self.primitives[i as usize].shape, i, &ray, t_min, &mut emit);
        });
        out.sort_by(|a, b| a.t.total_cmp(&b.t).then(a.primitive.cmp(&b.primitive)).then(a.self_occluded.cmp(&b.self_occluded)));
    }

    /// The nearest intersection with `t > t_min` (ties: the lowest primitive index).
    pub fn first_hit(&self, ray: &Ray, t_min: f32) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let ray = Prepared::new(ray)?;
        let consider = |h: Hit, best: &mut Option<Hit>| {
            if best.is_none_or(|b| h.t < b.t || (h.t == b.t && h.primitive < b.primitive)) {
                *best = Some(h);
            }
        };
        for &i in &self.unbounded {
            intersect(&self.primitives[i as usize].shape, i, &ray, t_min, &mut |h| consider(h, &mut best));
        }
        let mut t_max = best.map_or(f32::INFINITY, |b| b.t);
        self.bvh.traverse(ray.origin, ray.direction, t_min, &mut t_max, |i, t_max| {
            intersect(&self.primitives[i as usize].shape, i, &ray, t_min, &mut |h| consider(h, &mut best));
            if let Some(b) = best {
                *t_max = b.t;
            }
        });
        best
    }

    /// Radiance leaving `hit` towards the origin of `ray` (the lighting model of this module);
    /// black for a hit naming no primitive of this scene.
    pub fn shade(&self, ray: &Ray, hit: &Hit) -> [f32; 3] {
        let Some(prim) = self.primitives.get(hit.primitive as usize) else { return [0.0; 3] };
        match prim.material {
            Material::Emissive(c) => in_contract(c),
            Material::Diffuse(albedo) => {
                let n = if hit.normal.dot(ray.direction) > 0.0 { -hit.normal } else { hit.normal };
                let lambert = n.dot(self.light_dir).max(0.0);
                let a = match albedo {
                    Albedo::Solid(c) => c,
                    Albedo::Checker { a, b, cell } => {
                        let (u, v) = surface_coords(&prim.shape, ray.at(hit.t), hit.normal);
                        let parity = ((u / cell).floor() as i64 + (v / cell).floor() as i64) & 1;
                        if parity == 0 { a } else { b }
                    }
                };
                let l = &self.lighting;
                in_contract([0, 1, 2].map(|k| a[k] * (l.ambient[k] + l.color[k] * lambert)))
            }
        }
    }

    /// The radiance a ray sees: the first hit shaded, the background if it hits nothing; past a
    /// translucent hit, every surface along the ray composited front to back ("over", module docs).
    pub fn trace(&self, ray: &Ray) -> [f32; 3] {
        self.trace_with(ray, &mut Vec::new())
    }

    /// [`Self::trace`] with a buffer for the hits behind a translucent one (reused across calls).
    pub fn trace_with(&self, ray: &Ray, hits: &mut Vec<Hit>) -> [f32; 3] {
        let first = self.first_hit(ray, 0.0);
        match first {
            None => return self.lighting.background,
            Some(h) if self.alpha(h.primitive) >= 1.0 => return self.shade(ray, &h),
            Some(_) => {}
        }
        self.all_hits(ray, 0.0, hits);
        // The methods' own "over" (`dof_shaders::slot`), so that the pinhole image is the ray-cast
        // layers flattened, bit for bit.
        let mut over = Composite::EMPTY;
        for h in hits.iter().filter(|h| !h.self_occluded) {
            let alpha = self.alpha(h.primitive);
            over.add(premultiply(self.shade(ray, h), alpha), alpha);
            if over.transmit <= 0.0 {
                return over.color;
            }
        }
        over.add(self.lighting.background, 1.0);
        over.color
    }
}

/// A radiance under the numerical contract's ceiling: each channel at most
/// [`COLOR_MAX`] = 2^100, so that summing a pixel's sub-samples, or a lens's samples, stays finite
/// (a product that overflowed to +inf becomes the ceiling too).
pub fn in_contract(rgb: [f32; 3]) -> [f32; 3] {
    rgb.map(|v| if v > COLOR_MAX { COLOR_MAX } else { v })
}

/// A background radiance must be finite and not negative (HDR values above the half-float range
/// are fine: the splatting methods scale them like any colour; above 2^100 they are taken as 2^100,
/// [`in_contract`]).
pub fn check_background(rgb: [f32; 3]) -> Result<()> {
    if rgb.iter().all(|v| *v >= 0.0 && v.is_finite()) {
        Ok(())
    } else {
        Err(Error::invalid(format!("the background colour must be finite and not negative, got {rgb:?}")))
    }
}

/// Bounds of a primitive; `None` for an unbounded plane.
fn bounds(shape: &Shape) -> Option<Aabb> {
    match *shape {
        Shape::Sphere { center, radius } => Some(Aabb { min: center - Vec3::splat(radius), max: center + Vec3::splat(radius) }),
        Shape::Cuboid { min, max } => Some(Aabb { min, max }),
        Shape::Quad { corner, edge_u, edge_v } => {
            let pts = [corner, corner + edge_u, corner + edge_v, corner + edge_u + edge_v];
            Some(pts.iter().fold(Aabb::EMPTY, |b, p| b.union(Aabb { min: *p, max: *p })))
        }
        Shape::Plane { .. } => None,
    }
}

/// Two tangent directions of a plane with normal `n`.
pub(crate) fn tangents(n: Vec3) -> (Vec3, Vec3) {
    let n = n.normalize();
    let helper = if n.y.abs() < 0.9 { Vec3::Y } else { Vec3::X };
    let t = helper.cross(n).normalize();
    (t, n.cross(t))
}

/// Surface coordinates in scene units for checker textures.
pub(crate) fn surface_coords(shape: &Shape, p: Vec3, normal: Vec3) -> (f32, f32) {
    match *shape {
        Shape::Sphere { center, radius } => {
            let d = (p - center) / radius;
            (d.z.atan2(d.x) * radius, d.y.clamp(-1.0, 1.0).asin() * radius)
        }
        Shape::Cuboid { min, .. } => {
            let r = p - min;
            let a = normal.abs();
            if a.x >= a.y && a.x >= a.z {
                (r.z, r.y)
            } else if a.y >= a.z {
                (r.x, r.z)
            } else {
                (r.x, r.y)
            }
        }
        Shape::Quad { corner, edge_u, edge_v } => {
            let w = p - corner;
            let n = edge_u.cross(edge_v);
            let nn = n.length_squared();
            let a = w.cross(edge_v).dot(n) / nn;
            let b = edge_u.cross(w).dot(n) / nn;
            (a * edge_u.length(), b * edge_v.length())
        }
        Shape::Plane { point, normal } => {
            let (t, b) = tangents(normal);
            let w = p - point;
            (w.dot(t), w.dot(b))
        }
    }
}

/// Calls `emit` for every intersection of `ray` with `shape` at `t > t_min`, front to back.
/// A ray with what every sphere test needs computed once.
struct Prepared {
    origin: Vec3,
    direction: Vec3,
    /// `direction / |direction|`.
    unit: Vec3,
    /// `1 / |direction|`.
    inv_len: f32,
}

impl Prepared {
    fn new(ray: &Ray) -> Option<Self> {
        let len = ray.direction.length();
        if !(len > 0.0 && len.is_finite() && ray.origin.is_finite()) {
            return None;
        }
        Some(Prepared { origin: ray.origin, direction: ray.direction, unit: ray.direction / len, inv_len: 1.0 / len })
    }
}

fn intersect(shape: &Shape, index: u32, ray: &Prepared, t_min: f32, emit: &mut impl FnMut(Hit)) {
    let o = ray.origin;
    let d = ray.direction;
    match *shape {
        Shape::Sphere { center, radius } => {
            // Geometric form (Haines et al., Ray Tracing Gems ch. 7): the discriminant from the
            // ray's perpendicular distance to the centre, stable for small far spheres.
            let oc = o - center;
            let c = oc.length_squared() - radius * radius;
            let b = oc.dot(ray.unit);
            if c > 0.0 && b > 0.0 {
                return; // outside and moving away
            }
            let perp = oc - b * ray.unit;
            let disc = radius * radius - perp.length_squared();
            if disc < 0.0 {
                return;
            }
            let q = -b - b.signum() * disc.sqrt();
            let (mut n0, mut n1) = if q == 0.0 { (0.0, 0.0) } else { (c / q, q) };
            if n0 > n1 {
                std::mem::swap(&mut n0, &mut n1);
            }
            let (t0, t1) = (n0 * ray.inv_len, n1 * ray.inv_len);
            let inv_r = 1.0 / radius;
            let normal_at = |t: f32| ((o + t * d) - center) * inv_r;
            if t0 > t_min {
                emit(Hit { t: t0, primitive: index, normal: normal_at(t0), self_occluded: false });
                if t1 > t0 {
                    emit(Hit { t: t1, primitive: index, normal: normal_at(t1), self_occluded: true });
                }
            } else if t1 > t_min {
                emit(Hit { t: t1, primitive: index, normal: normal_at(t1), self_occluded: false });
            }
        }
        Shape::Cuboid { min, max } => {
            let mut t_near = f32::NEG_INFINITY;
            let mut t_far = f32::INFINITY;
            let mut near_axis = 0usize;
            let mut far_axis = 0usize;
            for k in 0..3 {
                if d[k] == 0.0 {
                    if o[k] < min[k] || o[k] > max[k] {
                        return;
                    }
                    continue;
                }
                let inv = 1.0 / d[k];
                let (mut a, mut b) = ((min[k] - o[k]) * inv, (max[k] - o[k]) * inv);
                if a > b {
                    std::mem::swap(&mut a, &mut b);
                }
                if a > t_near {
                    t_near = a;
                    near_axis = k;
                }
                if b < t_far {
                    t_far = b;
                    far_axis = k;
                }
            }
            if !(t_near <= t_far) {
                return;
            }
            let axis_normal = |k: usize, sign: f32| {
                let mut n = Vec3::ZERO;
                n[k] = sign;
                n
            };
            let near_normal = axis_normal(near_axis, -d[near_axis].signum());
            let far_normal = axis_normal(far_axis, d[far_axis].signum());
            if t_near > t_min {
                emit(Hit { t: t_near, primitive: index, normal: near_normal, self_occluded: false });
                if t_far > t_near {
                    emit(Hit { t: t_far, primitive: index, normal: far_normal, self_occluded: true });
                }
            } else if t_far > t_min {
                emit(Hit { t: t_far, primitive: index, normal: far_normal, self_occluded: false });
            }
        }
        Shape::Quad { corner, edge_u, edge_v } => {
            let n = edge_u.cross(edge_v);
            let denom = d.dot(n);
            if denom == 0.0 {
                return;
            }
            let t = (corner - o).dot(n) / denom;
            if !(t > t_min) || !t.is_finite() {
                return;
            }
            let w = o + t * d - corner;
            let nn = n.length_squared();
            let a = w.cross(edge_v).dot(n) / nn;
            let b = edge_u.cross(w).dot(n) / nn;
            if (0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b) {
                emit(Hit { t, primitive: index, normal: n / nn.sqrt(), self_occluded: false });
            }
        }
        Shape::Plane { point, normal } => {
            let denom = d.dot(normal);
            if denom == 0.0 {
                return;
            }
            let t = (point - o).dot(normal) / denom;
            if t > t_min && t.is_finite() {
                emit(Hit { t, primitive: index, normal: normal.normalize(), self_occluded: false });
            }
        }
    }
}
