//! The accumulation-buffer reference for mesh scenes: `N` pinhole renders from stratified points of
//! the lens, each through the sheared frustum that keeps the focus plane fixed ([`View`]) and with a
//! stratified sub-pixel jitter, shaded and averaged in f32 on the device.
//!
//! Every render sees the front surface only; a `BLEND` surface counts with its coverage over black
//! (nothing behind it is added), so the reference is exact for opaque and masked materials.

use super::mesh::{DeviceMesh, RasterScene};
use super::peel::{Pass, check_view, shade_params};
use super::view::View;
use crate::backend::{Backend, CommandTime, with_buffers};
use crate::error::{Error, Result};
use crate::layers::RgbImage;
use crate::methods::buffers::read_rgb;
use crate::progress::Progress;
use crate::scene::Camera;
use crate::scene::sampling::{concentric_disc, pixel_rng, stratified};
use dof_shaders::lens::ThinLens;
use dof_shaders::raster::shade::ACCUMULATE;

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
    let frame = check_view(camera, lens, near)?;
    if options.samples == 0 || options.samples > crate::scene::MAX_SPP {
        return Err(Error::InvalidArgument(format!(
            "the accumulation buffer takes 1 to {} renders, got {}",
            crate::scene::MAX_SPP,
            options.samples
        )));
    }
    frame.check_size("accumulation buffer", 3)?;
    let pixels = frame.width as u64 * frame.height as u64;
    let views = views(options.samples, lens.aperture_radius, options.seed);
    let mesh = DeviceMesh::upload(backend, scene)?;
    let template = "accumulation buffer [{elapsed_precise}] {wide_bar} {pos}/{len} renders (eta {eta})";
    let bar = Progress::new(options.progress, views.len() as u64, template, "");
    let mut sizes = Pass::sizes(&mesh, pixels, 1).to_vec();
    sizes.push((3 * pixels, "accum/sum"));
    let result = with_buffers(backend, &sizes, |backend, b| {
        let pass = Pass::new(backend, &mesh, b, 1)?;
        let sum = b[4];
        backend.fill(sum, 0, 3 * pixels, 0, "accum/sum")?;
        let mut times = Vec::new();
        for (i, view) in views.iter().enumerate() {
            pass.draw(backend, &mesh, view, &frame, lens, near, false, "accum/draw")?;
            pass.shade(backend, &mesh, &shade_params(scene, &mesh, &frame, lens, view, ACCUMULATE), sum, "accum/shade")?;
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
    mesh.destroy(backend);
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    let (image, times) = result?;
    Ok(Accumulated { image, samples: options.samples, times })
}
