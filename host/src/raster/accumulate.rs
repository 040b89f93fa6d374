//! The accumulation-buffer reference for mesh scenes: `N` pinhole renders from stratified points of
//! the lens, each through the sheared frustum that keeps the focus plane fixed ([`View`]) and with a
//! stratified sub-pixel jitter, shaded and averaged in f32 on the device.
//!
//! Opaque and masked materials: every render keeps the front surface only and adds it into a sum
//! on the device, one draw a view.
//!
//! `BLEND` materials: every render is depth-peeled in its own view (Everitt 2001): pass `k` keeps
//! the nearest fragment beyond the last pass's (the rasteriser's peel, with the reach the shading
//! pass writes) and it is composited front to back with the transmittance left in front of it
//! ("over", Porter and Duff 1984: `sum += T·alpha·rgb`, `T *= 1 − alpha`, the methods' own
//! `dof_shaders::slot::Composite`), until an opaque surface
//! or the background ends every pixel. So blended surfaces are blended in depth order, per pixel
//! and per lens sample, with what lies behind them. The layers are read back and composited on the
//! host after each pass (this is the reference, not a real-time path).

use super::mesh::{DeviceMesh, RasterScene};
use super::peel::{Pass, check_view, shade_params};
use super::view::View;
use crate::backend::{Backend, CommandTime, with_buffers};
use crate::error::{Error, Result};
use crate::layers::RgbImage;
use crate::methods::buffers::read_rgb;
use crate::progress::Progress;
use crate::scene::sampling::{concentric_disc, pixel_rng, stratified};
use crate::scene::{Camera, CameraFrame};
use dof_shaders::lens::ThinLens;
use dof_shaders::peel::{is_surface, slot_kept};
use dof_shaders::raster::mesh::ALPHA_BLEND;
use dof_shaders::raster::shade::{ACCUMULATE, LAYER, LAYER_WORDS};
use dof_shaders::slot::{Composite, premultiply};

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AccumulateOptions {
    /// Pinhole renders `N`, `>= 1`.
    pub samples: u32,
    pub seed: u64,
    /// Show a progress bar on the terminal (feature `progress`; ignored without it).
    pub progress: bool,
    /// Renders recorded per submission (bounds how much work a progress step waits for).
    pub batch: u32,
}

impl Default for AccumulateOptions {
    fn default() -> Self {
        AccumulateOptions { samples: 256, seed: 1, progress: false, batch: 8 }
    }
}

pub struct Accumulated {
    pub image: RgbImage,
    pub samples: u32,
    pub times: Vec<CommandTime>,
}

/// The `N` views: lens points stratified over the aperture disc (concentric mapping) and jitters
/// stratified over the pixel, jointly permuted as the exact reference's samples are.
pub fn views(samples: u32, aperture_radius: f32, seed: u64) -> Vec<View> {
    let (mut out, mut perm) = (Vec::new(), Vec::new());
    let mut rng = pixel_rng(seed, u64::MAX, 0);
    stratified(samples, true, &mut rng, &mut out, &mut perm);
    out.iter()
        .map(|s| {
            let (dx, dy) = concentric_disc(s.lens.0, s.lens.1);
            View { lens: (aperture_radius * dx, aperture_radius * dy), jitter: (s.pixel.0 - 0.5, s.pixel.1 - 0.5) }
        })
        .collect()
}

/// Renders the accumulation-buffer reference of `scene` (module docs).
pub fn accumulate(
    backend: &mut dyn Backend,
    scene: &RasterScene,
    camera: &Camera,
    lens: &ThinLens,
    near: f32,
    options: &AccumulateOptions,
) -> Result<Accumulated> {
    DeviceMesh::scoped(backend, scene, |backend, mesh| accumulate_with(backend, scene, mesh, camera, lens, near, options))
}

/// [`accumulate`] with `scene` already on the device as `mesh`, which it leaves there
/// ([`DeviceMesh::scoped`]).
pub fn accumulate_with(
    backend: &mut dyn Backend,
    scene: &RasterScene,
    mesh: &DeviceMesh,
    camera: &Camera,
    lens: &ThinLens,
    near: f32,
    options: &AccumulateOptions,
) -> Result<Accumulated> {
    let frame = check_view(camera, lens, near)?;
    if options.samples == 0 || options.samples > crate::scene::MAX_SPP {
        return Err(Error::invalid(format!(
            "the accumulation buffer takes 1 to {} renders, got {}",
            crate::scene::MAX_SPP,
            options.samples
        )));
    }
    frame.check_size("accumulation buffer", 3)?;
    let pixels = frame.width as u64 * frame.height as u64;
    let views = views(options.samples, lens.aperture_radius, options.seed);
    let template = "accumulation buffer [{elapsed_precise}] {wide_bar} {pos}/{len} renders (eta {eta})";
    let bar = Progress::new(options.progress, views.len() as u64, template, "");
    let blended = scene.materials.iter().any(|m| m.flags & ALPHA_BLEND != 0);
    if blended {
        let result = accumulate_blended(backend, scene, mesh, &frame, lens, near, &views, bar.as_ref());
        if let Some(bar) = bar {
            bar.finish_and_clear();
        }
        let (image, times) = result?;
        return Ok(Accumulated { image, samples: options.samples, times });
    }
    let mut sizes = Pass::sizes(mesh, pixels, 1).to_vec();
    sizes.push((3 * pixels, "accum/sum"));
    let result = with_buffers(backend, &sizes, |backend, b| {
        let pass = Pass::new(backend, mesh, b, 1)?;
        let sum = b[4];
        backend.fill(sum, 0, 3 * pixels, 0, "accum/sum")?;
        let mut times = Vec::new();
        for (i, view) in views.iter().enumerate() {
            pass.draw(backend, mesh, view, &frame, lens, near, false, "accum/draw")?;
            pass.shade(backend, mesh, &shade_params(scene, mesh, &frame, lens, view, ACCUMULATE), sum, "accum/shade")?;
            if (i + 1) % options.batch.max(1) as usize == 0 || i + 1 == views.len() {
                times.extend(backend.submit()?);
                if let Some(bar) = &bar {
                    bar.set_position(i as u64 + 1);
                }
            }
        }
        let mut image = read_rgb(backend, sum, frame.width, frame.height)?;
        let n = views.len() as f32;
        image.data.iter_mut().flatten().for_each(|c| *c /= n);
        Ok((image, times))
    });
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    let (image, times) = result?;
    Ok(Accumulated { image, samples: options.samples, times })
}

/// The accumulation buffer of a scene with `BLEND` materials: every view depth-peeled and
/// composited front to back (module docs).
#[allow(clippy::too_many_arguments)]
fn accumulate_blended(
    backend: &mut dyn Backend,
    scene: &RasterScene,
    mesh: &DeviceMesh,
    frame: &CameraFrame,
    lens: &ThinLens,
    near: f32,
    views: &[View],
    bar: Option<&Progress>,
) -> Result<(RgbImage, Vec<CommandTime>)> {
    let pixels = frame.width as u64 * frame.height as u64;
    let mut sizes = Pass::sizes(mesh, pixels, pixels).to_vec();
    sizes.push((LAYER_WORDS as u64 * pixels, "accum/layer"));
    Ok(with_buffers(backend, &sizes, |backend, b| {
        let pass = Pass::new(backend, mesh, b, pixels)?;
        let layer = b[4];
        let mut sum = vec![[0.0f64; 3]; pixels as usize];
        let mut over = vec![Composite::EMPTY; pixels as usize];
        let mut times = Vec::new();
        for (i, view) in views.iter().enumerate() {
            over.fill(Composite::EMPTY);
            // A finite reach: the first pass that finds a pixel's ray escaping writes the background.
            backend.fill(pass.reach, 0, pixels, 0, "accum/reach")?;
            let shade = shade_params(scene, mesh, frame, lens, view, LAYER);
            let mut k = 0;
            loop {
                pass.draw(backend, mesh, view, frame, lens, near, k > 0, "accum/peel draw")?;
                pass.shade(backend, mesh, &shade, layer, "accum/peel shade")?;
                times.extend(backend.submit()?);
                let words = backend.read_buffer(layer, 0, LAYER_WORDS as u64 * pixels)?;
                let mut open = false;
                for (p, w) in words.as_chunks::<{ LAYER_WORDS as usize }>().0.iter().enumerate() {
                    let (alpha, depth) = (f32::from_bits(w[3]), f32::from_bits(w[4]));
                    if over[p].transmit <= 0.0 || !slot_kept(alpha, depth) {
                        continue;
                    }
                    // The methods' own "over" (`dof_shaders::slot`), behind what this view found.
                    over[p].add(premultiply([0, 1, 2].map(|j| f32::from_bits(w[j])), alpha), alpha);
                    // Still open: something lies beyond this translucent surface, or may.
                    open |= over[p].transmit > 0.0 && is_surface(depth);
                }
                k += 1;
                if !open {
                    break;
                }
            }
            for (s, o) in sum.iter_mut().zip(&over) {
                for j in 0..3 {
                    s[j] += o.color[j] as f64;
                }
            }
            if let Some(bar) = bar {
                bar.set_position(i as u64 + 1);
            }
        }
        let n = views.len() as f64;
        let mut image = RgbImage::new(frame.width, frame.height);
        for (out, s) in image.data.iter_mut().zip(&sum) {
            *out = s.map(|v| (v / n) as f32);
        }
        Ok((image, times))
    })?)
}
