//! The exact partial multi-layer image of an analytic scene (Franke et al. 2018, §4): every surface along each
//! pixel's centre ray, front to back, thinned by the umbra threshold and kept beyond the front layer
//! only inside the disocclusion buffer.
//!
//! 1. **Hits.** All intersections of the pinhole ray through the pixel centre, front to back. The
//!    exit points of closed shapes behind their own entry point (`Hit::self_occluded`) are dropped:
//!    no viewpoint outside the shape sees them.
//! 2. **Umbra threshold** (§4.1, Lee et al. 2010). The first hit is kept. A later hit is dropped
//!    while it lies within `ThinLens::umbra_length(z_k, r(z_k))` behind the last kept fragment at
//!    depth `z_k`, where `r(z)` is the radius of a pixel's footprint facing the camera at depth `z`
//!    ([`CameraFrame::pixel_footprint_radius`]). A footprint as large as the aperture shadows
//!    everything behind it, so a pinhole keeps one layer. At most `max_layers` are kept. Where the
//!    ray escapes, the background ([`Scene::background`], at infinite depth) is its last fragment.
//!    A translucent hit ([`Scene::alpha`] below 1) is kept with its opacity as the fragment's
//!    coverage (colour premultiplied by it), but sets no umbra: what lies behind it stays visible through it, so only an opaque
//!    fragment ends a pixel's layers early. A hit of opacity 0 shows and hides nothing: skipped.
//!    A pixel whose `max_layers` slots are full with the last one translucent takes what lies
//!    behind it (the next hits up to an opaque one, else the background) composited "over" into
//!    that last slot, which keeps its depth, as the area resolve does with clusters beyond
//!    `max_layers` ([`dof_shaders::resolve`]): a deep stack of panes keeps its light and what it
//!    lets through.
//! 3. **Disocclusion buffer** (§4.2). On the front layer, two 4-neighbours are a depth
//!    discontinuity when exactly one is sky or `|z_a − z_b| > edge_depth_ratio · min(z_a, z_b)`.
//!    Both pixels of such a pair tag every pixel whose centre lies within `ceil(c/2)` pixels of
//!    theirs, `c` the larger CoC of the two depths (the sky counts as the far limit). The larger
//!    one, because hidden fragments matter on both sides: a blurred occluder uncovers what lies
//!    behind its rim, and a blurred background is seen around a sharp occluder's rim. Untagged
//!    pixels keep their fragments up to the first opaque one (the front one when it is opaque):
//!    what a translucent fragment does not hide is seen in focus too
//!    ([`dof_shaders::peel::slots_outside_buffer`], the device peel's rule).

use dof_shaders::lens::ThinLens;
use dof_shaders::peel::{covers, disk_budget, pair_radius, slots_outside_buffer};
use dof_shaders::resolve::{Sample, grid_side, resolve_pixel, subsample_offset};
use dof_shaders::slot::premultiply;
use rayon::prelude::*;

use super::analytic::{Hit, Scene};
use super::camera::{Camera, CameraFrame, Ray};
use super::guard_band::auto_margin;
use crate::error::{Error, Result};
use crate::layers::{Fragment, LayerStats, LayeredImage, RgbImage, crop_plane};

/// How the multi-layer image is built: in the core, beside the renderer peel that reads it too.
pub use crate::frame::LayerOptions;

/// Sub-samples a pixel that `dof render`, `dof eval` and `dof bench frame` take by default (see
/// [`LayerOptions::subsamples`]): 4, where the error against memory turns (docs/measurements.md,
/// "Area-integrated layers"). The library's `LayerOptions::default()` keeps 1 (point-sampled).
pub const DEFAULT_SUBSAMPLES: u32 = 4;

/// Errors unless `n` is a sub-sample count the layers take (1, 4, 9 or 16).
pub fn check_subsamples(n: u32) -> Result<()> {
    if grid_side(n) == 0 {
        return Err(Error::invalid(format!("sub-samples a pixel must be 1, 4, 9 or 16 (a square grid), got {n}")));
    }
    Ok(())
}

/// A scene rendered into layers (by [`raycast_layers`], or by the rasteriser's depth peel):
/// the [`LayeredImage`] of the frame and its guard band, the disocclusion buffer and the layer
/// statistics. Methods run on [`Self::layers`]; [`Self::crop`] cuts their result to the frame.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneLayers {
    /// The layers, `margin` pixels larger than the frame on every side (the guard band): limited by
    /// the disocclusion buffer when `LayerOptions::disocclusion` was on, all kept otherwise. Run a
    /// method on these and crop its result with [`SceneLayers::crop`].
    pub layers: LayeredImage,
    /// The guard band's width in pixels.
    pub margin: u32,
    /// The disocclusion buffer over the frame, row-major: `true` where a pixel may keep more than
    /// one fragment (the partial-occlusion region the metrics use).
    pub mask: Vec<bool>,
    /// Statistics over the frame with the disocclusion buffer applied.
    pub with_mask: LayerStats,
    /// Statistics over the frame with every pixel keeping up to `max_layers` fragments.
    pub without_mask: LayerStats,
}

impl SceneLayers {
    /// Share of the frame's pixels inside the disocclusion buffer.
    pub fn mask_share(&self) -> f64 {
        self.mask.iter().filter(|m| **m).count() as f64 / self.mask.len().max(1) as f64
    }

    /// A method's result over [`Self::layers`] cut to the frame.
    pub fn crop(&self, image: &RgbImage) -> RgbImage {
        image.crop(self.margin)
    }

    /// The frame's own layers (the guard band cut away): what an RGB+Z or multi-layer EXR of the
    /// frame would hold.
    pub fn frame_layers(&self) -> LayeredImage {
        self.layers.crop(self.margin)
    }

    /// The front layer of the frame: the pinhole image and its depth.
    pub fn front(&self) -> (RgbImage, Vec<f32>) {
        let (image, depth) = self.layers.front();
        (image.crop(self.margin), crop_plane(&depth, self.layers.width, self.margin))
    }
}

/// Ray casts the exact multi-layer image of `scene` seen by `camera` through `lens` (module docs).
/// Errors on an invalid camera or lens, `max_layers == 0`, a NaN or negative edge ratio, or an
/// image too large to address.
pub fn raycast_layers(scene: &Scene, camera: &Camera, lens: &ThinLens, options: &LayerOptions) -> Result<SceneLayers> {
    camera.frame()?;
    crate::lens::check(lens)?;
    // Ray casting has no near plane; a thousandth of the focus distance bounds the band's search.
    let margin = options.guard_band.resolve(|| Ok(auto_margin(scene, camera, lens, 1e-3 * lens.focus_distance)?))?;
    let frame = camera.overscan(margin).frame()?;
    if !(options.edge_depth_ratio >= 0.0) {
        return Err(Error::invalid(format!("the edge depth ratio must not be negative, got {}", options.edge_depth_ratio)));
    }
    frame.check_size("multi-layer image", options.max_layers as u64)?;
    check_subsamples(options.subsamples)?;
    let mut full = LayeredImage::new(frame.width, frame.height, options.max_layers)?;
    cast_all(scene, &frame, lens, options, &mut full);
    let full = if options.footprints { full } else { full.without_footprints() };
    Ok(apply_disocclusion(full, &frame, lens, options, margin))
}

/// Step 3 on a multi-layer image holding every kept fragment (the ray caster's or the
/// rasteriser's, seen by `frame`, `margin` pixels of guard band around the frame): the
/// disocclusion buffer from its front layer, and the frame's statistics with and without it. The
/// layers returned are masked when `options.disocclusion` is on.
pub fn apply_disocclusion(full: LayeredImage, frame: &CameraFrame, lens: &ThinLens, options: &LayerOptions, margin: u32) -> SceneLayers {
    let l = full.max_layers as usize;
    let front: Vec<f32> =
        (0..full.counts.len()).map(|p| if full.counts[p] > 0 { full.fragments[p * l].depth } else { f32::INFINITY }).collect();
    let mask = disocclusion_mask(frame, lens, &front, options.edge_depth_ratio);

    let without_mask = full.crop(margin).stats();
    let mut masked = full.clone();
    for (p, (count, &keep)) in masked.counts.iter_mut().zip(&mask).enumerate() {
        if !keep {
            *count = slots_outside_buffer(*count, |i| full.fragments[p * l + i as usize].alpha);
        }
    }
    // Unused slots are reset so that equal images compare equal whatever was dropped.
    for (p, &count) in masked.counts.iter().enumerate() {
        for slot in &mut masked.fragments[p * l + count as usize..(p + 1) * l] {
            *slot = Fragment { color: [0.0; 3], alpha: 0.0, depth: f32::INFINITY };
        }
    }
    let with_mask = masked.crop(margin).stats();
    let layers = if options.disocclusion { masked } else { full };
    let mask = crop_plane(&mask, frame.width, margin);
    SceneLayers { layers, margin, mask, with_mask, without_mask }
}

/// Fills `image` with every pixel's kept hits (steps 1 and 2), rows in parallel: from the pixel
/// centre's ray, or with `options.subsamples > 1` from each sub-sample's ray, resolved into area-
/// integrated fragments by `dof_shaders::resolve::resolve_pixel` (see [`LayerOptions::subsamples`]).
fn cast_all(scene: &Scene, frame: &CameraFrame, lens: &ThinLens, options: &LayerOptions, image: &mut LayeredImage) {
    let width = frame.width as usize;
    let l = options.max_layers as usize;
    let n = options.subsamples.max(1);
    let side = grid_side(n);
    if n > 1 {
        image.footprints = vec![dof_shaders::footprint::WHOLE; image.fragments.len()];
        image.footprint_side = side;
    }
    // Point-sampled images hold no footprints: one empty chunk a row.
    let footprint_rows: Vec<&mut [u32]> = match n > 1 {
        true => image.footprints.chunks_mut(width * l).collect(),
        false => (0..frame.height).map(|_| <&mut [u32]>::default()).collect(),
    };
    image.fragments.par_chunks_mut(width * l).zip(image.counts.par_chunks_mut(width)).zip(footprint_rows).enumerate().for_each_init(
        || (Vec::<Hit>::new(), vec![EMPTY_FRAGMENT; n as usize * l], vec![0u32; n as usize]),
        |(hits, sub, sub_counts), (y, ((fragments, counts), footprints))| {
            for x in 0..width {
                if n == 1 {
                    let ray = frame.pixel_ray(x as u32, y as u32);
                    counts[x] = cast_ray(scene, frame, lens, options, &ray, hits, &mut fragments[x * l..(x + 1) * l]);
                    continue;
                }
                for k in 0..n {
                    let [dx, dy] = subsample_offset(k, side);
                    let ray = Ray { origin: frame.eye, direction: frame.direction(x as f32 + dx, y as f32 + dy) };
                    let kk = k as usize;
                    sub_counts[kk] = cast_ray(scene, frame, lens, options, &ray, hits, &mut sub[kk * l..(kk + 1) * l]);
                }
                let fragment = |k: u32, j: u32| {
                    let f = sub[k as usize * l + j as usize];
                    Sample { color: f.color, alpha: f.alpha, depth: f.depth }
                };
                let out = &mut fragments[x * l..(x + 1) * l];
                let marks = &mut footprints[x * l..(x + 1) * l];
                let r = resolve_pixel(
                    n,
                    |k| sub_counts[k as usize],
                    fragment,
                    l as u32,
                    options.edge_depth_ratio,
                    |j, s, footprint| {
                        out[j as usize] = Fragment { color: s.color, alpha: s.alpha, depth: s.depth };
                        marks[j as usize] = footprint;
                    },
                );
                counts[x] = r.count;
            }
        },
    );
}

/// Steps 1 and 2 along one ray: its kept hits into `fragments` (at most its length), front to
/// back; returns how many.
fn cast_ray(
    scene: &Scene,
    frame: &CameraFrame,
    lens: &ThinLens,
    options: &LayerOptions,
    ray: &Ray,
    hits: &mut Vec<Hit>,
    fragments: &mut [Fragment],
) -> u32 {
    let l = fragments.len();
    scene.all_hits(ray, 0.0, hits);
    let mut n = 0usize;
    let mut reach = 0.0f32;
    for hit in hits.iter().filter(|h| !h.self_occluded) {
        if n == l && !(fragments[l - 1].alpha < 1.0) {
            break;
        }
        let alpha = scene.alpha(hit.primitive);
        if (n > 0 && options.umbra_threshold && hit.t < reach) || alpha <= 0.0 {
            continue;
        }
        let fragment = Fragment { color: premultiply(scene.shade(ray, hit), alpha), alpha, depth: hit.t };
        if n == l {
            // Full behind a translucent last slot: into it (module docs, step 2).
            fragments[l - 1] = over(fragments[l - 1], fragment);
            continue;
        }
        fragments[n] = fragment;
        n += 1;
        if alpha < 1.0 {
            continue; // translucent: sets no umbra
        }
        let umbra = lens.umbra_length(hit.t, frame.pixel_footprint_radius(hit.t));
        reach = if umbra.is_nan() { f32::INFINITY } else { hit.t + umbra };
    }
    // The ray escapes: the background is its deepest fragment, unless the last surface's umbra
    // reaches infinity; into a full pixel's translucent last slot.
    if n == 0 || !options.umbra_threshold || reach < f32::INFINITY {
        let background = Fragment { color: scene.background(), alpha: 1.0, depth: f32::INFINITY };
        if n < l {
            fragments[n] = background;
            n += 1;
        } else if fragments[l - 1].alpha < 1.0 {
            fragments[l - 1] = over(fragments[l - 1], background);
        }
    }
    n as u32
}

/// `back` behind a full pixel's translucent last slot `front` ([`dof_shaders::peel::behind`], the
/// device peel's rule), at `front`'s depth.
fn over(front: Fragment, back: Fragment) -> Fragment {
    let s = dof_shaders::peel::behind(front.slot(), back.slot());
    Fragment { color: s.color, alpha: s.alpha, depth: s.depth }
}

/// Resolves a sub-sample image (`side` times wider and higher than the result: sub-sample `(i, j)`
/// of pixel `(x, y)` is its pixel `(side·x + i, side·y + j)`) into area-integrated fragments with
/// `dof_shaders::resolve::resolve_pixel`, at most `max_layers` a pixel; the peel's host path and
/// the device kernel's oracle. Errors when the sizes do not divide or `max_layers` is 0.
pub fn resolve_subsamples(fine: &LayeredImage, side: u32, max_layers: u32, tolerance: f32) -> Result<LayeredImage> {
    if side == 0 || !fine.width.is_multiple_of(side) || !fine.height.is_multiple_of(side) || side > 4 {
        return Err(Error::invalid(format!(
            "a {}x{} sub-sample image does not divide into {side}x{side} grids (side 1 to 4)",
            fine.width, fine.height
        )));
    }
    let (w, h) = (fine.width / side, fine.height / side);
    let mut out = LayeredImage::new(w, h, max_layers)?;
    let (fl, l) = (fine.max_layers as usize, max_layers as usize);
    let fw = fine.width as usize;
    let s = side as usize;
    out.footprints = vec![dof_shaders::footprint::WHOLE; out.fragments.len()];
    out.footprint_side = side;
    let footprint_rows = out.footprints.par_chunks_mut(w as usize * l);
    out.fragments.par_chunks_mut(w as usize * l).zip(out.counts.par_chunks_mut(w as usize)).zip(footprint_rows).enumerate().for_each(
        |(y, ((fragments, counts), footprints))| {
            for x in 0..w as usize {
                let pixel = |k: u32| (y * s + k as usize / s) * fw + x * s + k as usize % s;
                let fragment = |k: u32, j: u32| {
                    let f = fine.fragments[pixel(k) * fl + j as usize];
                    Sample { color: f.color, alpha: f.alpha, depth: f.depth }
                };
                let out = &mut fragments[x * l..(x + 1) * l];
                let marks = &mut footprints[x * l..(x + 1) * l];
                let r = resolve_pixel(
                    side * side,
                    |k| fine.counts[pixel(k)].min(fl as u32),
                    fragment,
                    max_layers,
                    tolerance,
                    |j, s, footprint| {
                        out[j as usize] = Fragment { color: s.color, alpha: s.alpha, depth: s.depth };
                        marks[j as usize] = footprint;
                    },
                );
                counts[x] = r.count;
            }
        },
    );
    Ok(out)
}

const EMPTY_FRAGMENT: Fragment = Fragment { color: [0.0; 3], alpha: 0.0, depth: f32::INFINITY };

/// The disocclusion buffer from the front-layer depths (step 3), with the device peel's rules
/// (`dof_shaders::peel`: [`pair_radius`], [`disk_budget`], [`covers`]).
pub(crate) fn disocclusion_mask(frame: &CameraFrame, lens: &ThinLens, front: &[f32], ratio: f32) -> Vec<bool> {
    let (w, h) = (frame.width as usize, frame.height as usize);
    let limit = w.max(h).min(i32::MAX as usize) as i32;
    // Largest tag radius per edge pixel (-1: not an edge).
    let mut edge = vec![-1i32; w * h];
    for y in 0..h {
        for x in 0..w {
            let p = y * w + x;
            for (q, ok) in [(p + 1, x + 1 < w), (p + w, y + 1 < h)] {
                if ok {
                    let r = pair_radius(lens, front[p], front[q], ratio, limit);
                    edge[p] = edge[p].max(r);
                    edge[q] = edge[q].max(r);
                }
            }
        }
    }
    // Edges bucketed by row, then each output row scans the rows within the largest radius.
    let mut by_row: Vec<Vec<(i32, i32)>> = vec![Vec::new(); h];
    let mut max_r = 0i32;
    for (p, &r) in edge.iter().enumerate() {
        if r >= 0 {
            by_row[p / w].push(((p % w) as i32, r));
            max_r = max_r.max(r);
        }
    }
    let mut mask = vec![false; w * h];
    mask.par_chunks_mut(w).enumerate().for_each(|(y, row)| {
        let y = y as i32;
        let lo = (y - max_r).max(0);
        let hi = (y + max_r).min(h as i32 - 1);
        for ey in lo..=hi {
            let dy = ey - y;
            for &(ex, r) in &by_row[ey as usize] {
                if dy.abs() > r {
                    continue;
                }
                let x0 = (ex - r).max(0);
                let x1 = (ex + r).min(w as i32 - 1);
                for x in x0..=x1 {
                    if covers(disk_budget(x - ex, r), dy) {
                        row[x as usize] = true;
                    }
                }
            }
        }
    });
    mask
}
