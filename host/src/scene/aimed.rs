//! The light of small emissive spheres, integrated with samples aimed at each sphere: the part of
//! the thin-lens reference that uniform sampling leaves unconverged.
//!
//! The uniform reference samples pixel × lens evenly, so a pixel that a saturating bokeh disc
//! overlaps by less than about one sample in `spp` comes out black, and which ones do is chance:
//! on `highlights` two 1024-spp references agree to only 19 dB in the partial-occlusion region
//! (docs/measurements.md). Here each emissive sphere's light is integrated on its own: per pixel
//! that can see it, stratified pixel points over the part of the pixel within reach, and per pixel
//! point lens points drawn only in the bounding box of the sphere's projection, from the point's
//! focus-plane point, onto the lens plane (the whole lens where that projection is unbounded). The
//! estimate is the box's share of the lens disc times the share of its points whose ray's first hit
//! is the sphere; every ray is traced through the whole scene, so occlusion stays exact. Added to
//! the uniform reference of the scene with those spheres black, it is the converged image up to its
//! own noise (two seeds of it agree to 44 / 36 dB there).
//!
//! It holds for spheres whose light reaches the camera directly: the analytic scenes' emitters
//! light nothing else. A translucent surface in front of a sphere would pass part of its light,
//! which a first-hit test does not count, so scenes with translucency are refused.

use rayon::prelude::*;

use super::analytic::{Lighting, Material, Primitive, Scene, Shape};
use super::builtin::SplitMix;
use super::camera::CameraFrame;
use crate::error::{Error, Result};
use crate::layers::RgbImage;
use dof_shaders::lens::ThinLens;
use glam::Vec3;

/// An emissive sphere: its primitive's index, centre, radius and radiance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emitter {
    pub primitive: u32,
    pub center: Vec3,
    pub radius: f32,
    pub radiance: [f32; 3],
}

/// The scene's emissive spheres of non-black radiance.
pub fn emitters(scene: &Scene) -> Vec<Emitter> {
    scene
        .primitives()
        .iter()
        .enumerate()
        .filter_map(|(i, p)| match (p.shape, p.material) {
            (Shape::Sphere { center, radius }, Material::Emissive(c)) if c != [0.0; 3] => {
                Some(Emitter { primitive: i as u32, center, radius, radiance: c })
            }
            _ => None,
        })
        .collect()
}

/// The scene with every emissive sphere black: they still hide what lies behind them.
pub fn without_emitters(scene: &Scene) -> Result<Scene> {
    refuse_translucency(scene)?;
    let prims: Vec<Primitive> = scene
        .primitives()
        .iter()
        .map(|p| match (p.shape, p.material) {
            (Shape::Sphere { .. }, Material::Emissive(_)) => Primitive { shape: p.shape, material: Material::Emissive([0.0; 3]) },
            _ => *p,
        })
        .collect();
    Scene::new(prims, *scene.lighting())
}

/// The scene with only its emitters' light: no lighting, a black background (every surface still
/// hides what lies behind it).
pub fn emitters_only(scene: &Scene) -> Result<Scene> {
    refuse_translucency(scene)?;
    let l = *scene.lighting();
    Scene::new(scene.primitives().to_vec(), Lighting { color: [0.0; 3], ambient: [0.0; 3], background: [0.0; 3], ..l })
}

fn refuse_translucency(scene: &Scene) -> Result<()> {
    if scene.has_translucency() {
        return Err(Error::invalid(
            "aimed emitter sampling needs a scene without translucent surfaces (a first-hit test does not count light passed through them)"
                .to_string(),
        ));
    }
    Ok(())
}

/// Pixel points and lens points (per side) for `spp` samples a pixel: `(64·spp)^(1/4)` each, at
/// least 2, so that each pixel that can see a sphere gets 64 times the uniform reference's samples
/// for that sphere alone (16 and 16 at 1024 spp).
pub fn sides_for(spp: u32) -> (u32, u32) {
    let side = ((64.0 * spp as f64).powf(0.25).round() as u32).max(2);
    (side, side)
}

/// The light of every emitter of `scene`, aimed (module docs), with `pixel_side`² pixel points and
/// `lens_side`² lens points for each pixel in an emitter's reach. `seed` picks the jitter.
pub fn aimed_emitters(scene: &Scene, frame: &CameraFrame, lens: &ThinLens, pixel_side: u32, lens_side: u32, seed: u64) -> RgbImage {
    let parts: Vec<Vec<(usize, [f64; 3])>> =
        emitters(scene).par_iter().map(|e| aimed_emitter(scene, frame, lens, e, pixel_side, lens_side, seed)).collect();
    let mut image = RgbImage::new(frame.width, frame.height);
    for (i, v) in parts.into_iter().flatten() {
        for k in 0..3 {
            image.data[i][k] += v[k] as f32;
        }
    }
    image
}

fn aimed_emitter(
    scene: &Scene,
    frame: &CameraFrame,
    lens: &ThinLens,
    e: &Emitter,
    pixel_side: u32,
    lens_side: u32,
    seed: u64,
) -> Vec<(usize, [f64; 3])> {
    let (w, h) = (frame.width as i64, frame.height as i64);
    let (a, focus) = (lens.aperture_radius, lens.focus_distance);
    let (c, rho) = (e.center, e.radius);
    let mut out = Vec::new();
    let z = frame.depth_of(c);
    let Some((cx, cy)) = frame.project(c) else { return out };
    // Pixels that can see the sphere lie within its CoC plus its projected radius (with margin:
    // a check per emitter found every hit well inside).
    let support = lens.coc_radius_px(z) + 1.5 * rho / (2.0 * frame.pixel_footprint_radius(z)) + 1.0;
    let mut rng = SplitMix(seed ^ ((e.primitive as u64) << 32));
    let (x0, x1) = (((cx - support).floor() as i64).max(0), ((cx + support).ceil() as i64).min(w - 1));
    let (y0, y1) = (((cy - support).floor() as i64).max(0), ((cy + support).ceil() as i64).min(h - 1));
    let (ps, ls) = (pixel_side as f32, lens_side as f32);
    for py in y0..=y1 {
        for px in x0..=x1 {
            let (bx0, bx1) = ((px as f32).max(cx - support), (px as f32 + 1.0).min(cx + support));
            let (by0, by1) = ((py as f32).max(cy - support), (py as f32 + 1.0).min(cy + support));
            if !(bx1 > bx0 && by1 > by0) {
                continue;
            }
            let mut cover = 0.0f64;
            for k in 0..pixel_side * pixel_side {
                let sx = bx0 + (bx1 - bx0) * ((k % pixel_side) as f32 + rng.next_f32()) / ps;
                let sy = by0 + (by1 - by0) * ((k / pixel_side) as f32 + rng.next_f32()) / ps;
                let f = frame.eye + focus * frame.direction(sx, sy);
                let Some((lo, hi)) = lens_box(frame, f, c, rho, a, focus) else { continue };
                let mut hits = 0u32;
                for j in 0..lens_side * lens_side {
                    let lx = lo[0] + (hi[0] - lo[0]) * ((j % lens_side) as f32 + rng.next_f32()) / ls;
                    let ly = lo[1] + (hi[1] - lo[1]) * ((j / lens_side) as f32 + rng.next_f32()) / ls;
                    if lx * lx + ly * ly <= a * a {
                        let ray = frame.lens_ray(sx, sy, lx, ly, focus);
                        hits += scene.first_hit(&ray, 0.0).is_some_and(|hit| hit.primitive == e.primitive) as u32;
                    }
                }
                let box_area = ((hi[0] - lo[0]) * (hi[1] - lo[1])) as f64;
                cover += box_area * hits as f64 / (lens_side * lens_side) as f64 / (std::f64::consts::PI * (a as f64).powi(2));
            }
            let v = cover / (pixel_side * pixel_side) as f64 * ((bx1 - bx0) * (by1 - by0)) as f64;
            if v > 0.0 {
                out.push(((py * w + px) as usize, e.radiance.map(|c| c as f64 * v)));
            }
        }
    }
    out
}

/// The lens-plane box (along the camera's right and up, clipped to the lens's square) of the lens
/// points whose ray through the focus-plane point `f` meets the sphere: the bounding box of the
/// sphere's silhouette seen from `f`, projected from `f` onto the lens plane, padded by 3%; the
/// whole lens where that projection is unbounded (`f` inside the sphere, or the silhouette
/// crossing the focus depth).
fn lens_box(frame: &CameraFrame, f: Vec3, c: Vec3, rho: f32, a: f32, focus: f32) -> Option<([f32; 2], [f32; 2])> {
    let v = c - f;
    let d2 = v.length_squared();
    let whole = ([-a, -a], [a, a]);
    if d2 <= 1.0001 * rho * rho {
        return Some(whole);
    }
    let centre = c - (rho * rho / d2) * v;
    let radius = rho * (1.0 - rho * rho / d2).sqrt();
    let axis = v.normalize();
    let (t1, t2) = (axis.any_orthonormal_vector(), axis.cross(axis.any_orthonormal_vector()));
    let (mut lo, mut hi) = ([f32::INFINITY; 2], [f32::NEG_INFINITY; 2]);
    let (mut behind, mut before) = (false, false);
    for s in 0..64 {
        let angle = s as f32 * std::f32::consts::TAU / 64.0;
        let p = centre + radius * (angle.cos() * t1 + angle.sin() * t2);
        let dz = frame.depth_of(p) - focus;
        if dz > 0.0 {
            behind = true;
        } else {
            before = true;
        }
        if dz.abs() < 1e-6 * focus {
            return Some(whole);
        }
        let q = f + (p - f) * (-focus / dz) - frame.eye;
        let l = [q.dot(frame.right), q.dot(frame.up)];
        for k in 0..2 {
            lo[k] = lo[k].min(l[k]);
            hi[k] = hi[k].max(l[k]);
        }
    }
    if behind && before {
        return Some(whole);
    }
    for k in 0..2 {
        let pad = 0.03 * (hi[k] - lo[k]) + 1e-6 * a;
        lo[k] = (lo[k] - pad).max(-a);
        hi[k] = (hi[k] + pad).min(a);
    }
    (hi[0] > lo[0] && hi[1] > lo[1]).then_some((lo, hi))
}
