//! Bokeh sprites over a gathering blur (seed 001; kernels, shaders and the sprite layout in
//! `dof_shaders::bokeh`). One submission: detection, a scan of its flags into sprite slots, the
//! sprites and the blur's input, the gather of what detection left, the
//! indirect draw command written on the device, the sprite draw (the graphics pipeline on Vulkan,
//! its compute fallback on the CPU backend), and the sum. The host reads the detection count only
//! afterwards, for the report.

use super::gather::{MAX_RADIUS, needed_radius};
use super::buffers::{groups_for, read_rgb};
use crate::backend::{Backend, CommandTime, push_words, with_buffers};
use crate::error::{Error, Result};
use crate::layers::RgbImage;
use crate::aperture::ApertureShape;
use crate::ops::scan::ScanScratch;
use dof_shaders::bokeh::{ARGS_WORDS, BOKEH_ARGS, BOKEH_COMBINE, BOKEH_DETECT, BOKEH_DRAW, BOKEH_EMIT, BokehParams, COUNTER, SPRITE_WORDS};
use dof_shaders::gather::{GATHER, GatherParams, TILE};
use dof_shaders::lens::ThinLens;


#[derive(Clone, Debug)]
pub struct BokehOptions {
    /// Luminance above the 5x5 neighbourhood's mean that makes a sprite (`LumThreshold`, linear
    /// units; default 1, a diffuse white).
    pub lum_threshold: f32,
    /// Smallest CoC radius (px) that makes a sprite (`CoCThreshold`; default 2).
    pub coc_threshold: f32,
    /// Sprites the buffer holds (default 4096); more are counted and left in the blur.
    pub capacity: u32,
    /// Largest sprite CoC radius (px; default 256).
    pub max_radius: f32,
    pub aperture: ApertureShape,
}

impl Default for BokehOptions {
    fn default() -> Self {
        BokehOptions { lum_threshold: 1.0, coc_threshold: 2.0, capacity: 4096, max_radius: 256.0, aperture: ApertureShape::circle() }
    }
}

pub struct BokehOutput {
    pub image: RgbImage,
    pub times: Vec<CommandTime>,
    /// Bright pixels detected, and those beyond the capacity (left in the blur).
    pub detected: u64,
    pub overflow: u64,
    /// Radius the gather scanned.
    pub blur_radius: u32,
    pub buffer_bytes: u64,
}

pub fn bokeh(backend: &mut dyn Backend, image: &RgbImage, depth: &[f32], lens: &ThinLens, options: &BokehOptions) -> Result<BokehOutput> {
    let (width, height) = (image.width, image.height);
    let pixels = width as u64 * height as u64;
    if pixels == 0 || image.data.len() as u64 != pixels || depth.len() as u64 != pixels {
        return Err(Error::InvalidArgument(format!("bokeh sprites need a non-empty {width}x{height} image with one depth per pixel")));
    }
    if !lens.is_valid() {
        return Err(Error::InvalidArgument(format!("invalid lens: {lens:?}")));
    }
    let finite = |v: f32| v.is_finite() && v >= 0.0;
    if !(finite(options.lum_threshold) && finite(options.coc_threshold) && options.max_radius > 0.0 && options.max_radius <= 4096.0) {
        return Err(Error::InvalidArgument(format!(
            "bokeh thresholds must be finite and non-negative and the sprite radius cap in (0, 4096] px, got {}, {} and {}",
            options.lum_threshold, options.coc_threshold, options.max_radius
        )));
    }
    if !(1..=1 << 20).contains(&options.capacity) {
        return Err(Error::InvalidArgument(format!("the sprite capacity must be 1 to 1048576, got {}", options.capacity)));
    }
    let blur_radius = needed_radius(lens, depth, MAX_RADIUS);
    let mask = options.aperture.mask_words();
    let sizes = [
        (mask.len() as u64, "bokeh/aperture-mask"),
        (pixels, "bokeh/slots"),
        (3 * pixels, "bokeh/color"),
        (pixels, "bokeh/depth"),
        (3 * pixels, "bokeh/rest"),
        (SPRITE_WORDS as u64 * options.capacity as u64, "bokeh/sprites"),
        (ARGS_WORDS as u64 + 1, "bokeh/counters"),
        (3 * pixels, "bokeh/blur"),
        (4 * pixels, "bokeh/sprite-image"),
        (3 * pixels, "bokeh/out"),
        (1, "bokeh/gather-radius"),
    ];
    let max_words = backend.limits().max_buffer_bytes / 4;
    if let Some(&(words, what)) = sizes.iter().find(|s| s.0 > max_words) {
        return Err(Error::TooLarge { what: format!("{what} (words)"), size: words, limit: max_words });
    }
    let buffer_bytes = 4 * sizes.iter().map(|s| s.0).sum::<u64>();
    let colour_words: Vec<u32> = image.data.iter().flat_map(|c| c.map(f32::to_bits)).collect();
    let depth_words: Vec<u32> = depth.iter().map(|z| z.to_bits()).collect();
    let params = BokehParams {
        width,
        height,
        capacity: options.capacity,
        lum_threshold: options.lum_threshold,
        coc_threshold: options.coc_threshold,
        max_radius: options.max_radius,
        lens: *lens,
        aperture: options.aperture.kernel,
        ..Default::default()
    };
    with_buffers(backend, &sizes, |backend, b| {
        let [mask_buf, slots, color, depth_buf, rest, sprites, counters, blur, sprite_image, out, gather_radius] =
            [b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7], b[8], b[9], b[10]];
        // The blur's window is planned on the host here (bokeh sprites do not run through the
        // frame API yet): the gather reads it from its plan word.
        backend.write_buffer(gather_radius, 0, &[blur_radius])?;
        backend.write_buffer(mask_buf, 0, &mask)?;
        backend.write_buffer(color, 0, &colour_words)?;
        backend.write_buffer(depth_buf, 0, &depth_words)?;
        let push = push_words(&params);
        let groups = groups_for(&BOKEH_DETECT, pixels);
        backend.dispatch(&BOKEH_DETECT, groups, &[color, depth_buf, slots, counters], &push, "bokeh/detect")?;
        let scratch = ScanScratch::new(backend, pixels)?;
        if let Err(e) = scratch.record(backend, slots, 0, pixels) {
            scratch.destroy(backend);
            return Err(e);
        }
        backend.dispatch(&BOKEH_EMIT, groups, &[color, depth_buf, slots, sprites, rest, mask_buf], &push, "bokeh/detect")?;
        let gather_params = GatherParams { width, height, max_radius: blur_radius, _pad: 0, lens: *lens };
        let tiles = [width.div_ceil(TILE), height.div_ceil(TILE), 1];
        backend.dispatch(&GATHER, tiles, &[rest, depth_buf, blur, gather_radius], &push_words(&gather_params), "gather")?;
        backend.dispatch(&BOKEH_ARGS, [1, 1, 1], &[counters], &push, "bokeh/draw")?;
        backend.draw_indirect(&BOKEH_DRAW, counters, &[sprites, mask_buf], sprite_image, [width, height], &push, "bokeh/draw")?;
        backend.dispatch(&BOKEH_COMBINE, groups, &[blur, sprite_image, out], &push, "bokeh/draw")?;
        let times = backend.submit();
        scratch.destroy(backend);
        let times = times?;
        let detected = backend.read_buffer(counters, COUNTER as u64, 1)?[0] as u64;
        Ok(BokehOutput {
            image: read_rgb(backend, out, width, height)?,
            times,
            detected,
            overflow: detected.saturating_sub(options.capacity as u64),
            blur_radius,
            buffer_bytes,
        })
    })
}
