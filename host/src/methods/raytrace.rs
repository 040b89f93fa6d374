//! Thin-lens ray tracing through the multi-layer image (kernels and their rules in
//! `dof_shaders::raytrace`): a min/max hierarchy of the signed CoC, then `spp` rays per pixel.
//!
//! Lens samples are made here, once per frame: `patterns` independent sets of `spp` points
//! stratified over the lens disc (the reference renderer's sampler and concentric mapping), each
//! pixel picking a set by a hash, so neighbouring pixels do not share one noise pattern. The same
//! buffer goes to both backends, so both trace the same rays.

use super::buffers::{groups_for, read_rgb, slot_words};
use crate::backend::{Backend, CommandTime, push_words, with_buffers};
use crate::error::{Error, Result};
use crate::layers::{LayeredImage, RgbImage};
use crate::scene::sampling::{concentric_disc, pixel_rng, stratified};
use dof_shaders::lens::ThinLens;
use dof_shaders::raytrace::{RT_BASE, RT_REDUCE, RT_TRACE, SLOT_WORDS, STATS_WORDS, TILE, TraceParams, level_offsets, levels_for};

/// Rays per pixel at most.
pub const MAX_SPP: u32 = 4096;

#[derive(Clone, Debug)]
pub struct RaytraceOptions {
    /// Rays per pixel, `1..=MAX_SPP`.
    pub spp: u32,
    /// Independent sample sets pixels choose from (default 16).
    pub patterns: u32,
    pub seed: u64,
}

impl Default for RaytraceOptions {
    fn default() -> Self {
        RaytraceOptions { spp: 16, patterns: 16, seed: 0x5eed }
    }
}

pub struct RaytraceOutput {
    pub image: RgbImage,
    pub times: Vec<CommandTime>,
    /// Rays that hit no stored fragment (left the image, or passed behind every fragment where
    /// they ended) and took the deepest fragment there instead.
    pub missed_rays: u64,
    pub rays: u64,
    /// Levels of the min/max hierarchy.
    pub levels: u32,
    pub buffer_bytes: u64,
}

/// `patterns` sets of `spp` lens points in the unit disc, stratified, as `[x, y]` word pairs.
pub fn lens_samples(spp: u32, patterns: u32, seed: u64) -> Vec<u32> {
    let mut words = Vec::with_capacity(2 * (spp * patterns) as usize);
    let (mut samples, mut perm) = (Vec::new(), Vec::new());
    for pattern in 0..patterns {
        let mut rng = pixel_rng(seed, 0, pattern as u64);
        stratified(spp, true, &mut rng, &mut samples, &mut perm);
        for s in &samples {
            let (x, y) = concentric_disc(s.lens.0, s.lens.1);
            words.extend_from_slice(&[x.to_bits(), y.to_bits()]);
        }
    }
    words
}

/// Renders `image` through `lens` by ray tracing the layers on `backend`.
pub fn raytrace(backend: &mut dyn Backend, image: &LayeredImage, lens: &ThinLens, options: &RaytraceOptions) -> Result<RaytraceOutput> {
    if !lens.is_valid() {
        return Err(Error::InvalidArgument(format!("invalid lens: {lens:?}")));
    }
    if !(1..=MAX_SPP).contains(&options.spp) {
        return Err(Error::InvalidArgument(format!("rays per pixel must be 1 to {MAX_SPP}, got {}", options.spp)));
    }
    if !(1..=256).contains(&options.patterns) {
        return Err(Error::InvalidArgument(format!("sample patterns must be 1 to 256, got {}", options.patterns)));
    }
    let (width, height) = (image.width, image.height);
    let pixels = width as u64 * height as u64;
    if pixels == 0 || image.max_layers == 0 {
        return Err(Error::InvalidArgument(format!(
            "ray tracing needs a non-empty image, got {width}x{height} with {} layers",
            image.max_layers
        )));
    }
    let levels = levels_for(width, height);
    let mut params = TraceParams {
        width,
        height,
        max_layers: image.max_layers,
        levels,
        spp: options.spp,
        patterns: options.patterns,
        lens: *lens,
        ..Default::default()
    };
    let (offsets, hier_cells) = level_offsets(&params);
    params.offsets = offsets;
    let slots = pixels * image.max_layers as u64;
    let sizes = [
        (SLOT_WORDS as u64 * slots, "raytrace/input"),
        (pixels, "raytrace/counts"),
        (2 * hier_cells, "raytrace/hierarchy"),
        (2 * (options.spp * options.patterns) as u64, "raytrace/samples"),
        (3 * pixels, "raytrace/out"),
        (STATS_WORDS as u64, "raytrace/stats"),
    ];
    let max_words = backend.limits().max_buffer_bytes / 4;
    if let Some(&(words, what)) = sizes.iter().find(|s| s.0 > max_words) {
        return Err(Error::TooLarge { what: format!("{what} (words)"), size: words, limit: max_words });
    }
    let buffer_bytes = 4 * sizes.iter().map(|s| s.0).sum::<u64>();
    let input = slot_words(image);
    let samples = lens_samples(options.spp, options.patterns, options.seed);
    with_buffers(backend, &sizes, |backend, b| {
        let [input_buf, counts, hier, samples_buf, out, stats] = [b[0], b[1], b[2], b[3], b[4], b[5]];
        backend.write_buffer(input_buf, 0, &input)?;
        backend.write_buffer(counts, 0, &image.counts)?;
        backend.write_buffer(samples_buf, 0, &samples)?;
        backend.write_buffer(stats, 0, &[0])?;
        backend.dispatch(&RT_BASE, groups_for(&RT_BASE, pixels), &[input_buf, counts, hier], &push_words(&params), "raytrace/hierarchy")?;
        for level in 1..levels {
            let p = TraceParams { level, ..params };
            let (w, h) = dof_shaders::raytrace::level_size(&p, level);
            backend.dispatch(&RT_REDUCE, groups_for(&RT_REDUCE, w as u64 * h as u64), &[hier], &push_words(&p), "raytrace/hierarchy")?;
        }
        let tiles = [width.div_ceil(TILE), height.div_ceil(TILE), 1];
        backend.dispatch(&RT_TRACE, tiles, &[input_buf, counts, hier, samples_buf, out, stats], &push_words(&params), "raytrace/trace")?;
        let times = backend.submit()?;
        let missed = backend.read_buffer(stats, 0, 1)?[0] as u64;
        Ok(RaytraceOutput {
            image: read_rgb(backend, out, width, height)?,
            times,
            missed_rays: missed,
            rays: pixels * options.spp as u64,
            levels,
            buffer_bytes,
        })
    })
}
