//! One splatting frame of a host image, through the frame API: upload the image, create a
//! [`SplatContext`] sized to it, record, submit once, read back the image and the report.
//!
//! This is the convenience path for the CLI, the evaluation and the tests: it allocates per call.
//! A renderer keeps one context and records frame after frame ([`crate::frame`]). Where a frame's
//! lists overflow the default pool, this path runs it again with a pool as large as the frame
//! wanted, so its result is always whole.

use crate::backend::{Backend, CommandTime, with_buffers};
use crate::frame::splat::{SplatContext, SplatContextDesc};
use crate::frame::splat::{SplatOptions, SplatReport};
use crate::frame::{CountBuffer, Frame, RgbBuffer, SlotBuffer};
use crate::frame::{DofContext, Extent};
use crate::layers::{LayeredImage, RgbImage};
use crate::methods::buffers::{read_rgb, slot_words};
use crate::methods::one_shot::grow_to_fit;
use dof_core::error::{Error, Result};
use dof_shaders::lens::ThinLens;

pub struct SplatOutput {
    pub image: RgbImage,
    pub report: SplatReport,
    pub stages: Vec<CommandTime>,
}

/// Renders `image` through `lens` by tiled splatting on `backend`.
pub fn splat(backend: &mut dyn Backend, image: &LayeredImage, lens: &ThinLens, options: &SplatOptions) -> Result<SplatOutput> {
    splat_then(backend, image, lens, options, |_, _, _| Ok(())).map(|(out, ())| out)
}

/// [`splat`], then `then` with the backend, the context and the frame once the frame has run,
/// before the image and the report are read: for a caller that reads the context's buffers or
/// records the frame again (the suites' stage-by-stage comparison).
pub fn splat_then<T>(
    backend: &mut dyn Backend,
    image: &LayeredImage,
    lens: &ThinLens,
    options: &SplatOptions,
    then: impl FnOnce(&mut dyn Backend, &mut SplatContext, &Frame) -> Result<T>,
) -> Result<(SplatOutput, T)> {
    crate::lens::check(lens)?;
    crate::frame::splat::check_options(options)?;
    let (w, h, layers) = (image.width, image.height, image.max_layers);
    if w == 0 || h == 0 || layers == 0 {
        return Err(Error::InvalidArgument(format!("an empty {w}x{h} image with {layers} layers")));
    }
    let mut options = options.clone();
    options.footprint_side = options.footprint_side.max(image.footprint_grid());
    let desc = SplatContextDesc::new(Extent::new(w, h, layers), options);
    // The context checks the bounds (and refuses) before the input is uploaded.
    let mut ctx = SplatContext::new(backend, &desc)?;
    let pixels = w as u64 * h as u64;
    let input = slot_words(image);
    let sizes = [(input.len() as u64, "splat/input"), (pixels, "splat/input-counts"), (3 * pixels, "splat/out")];
    let result = with_buffers(backend, &sizes, |backend, io| {
        backend.write_buffer(io[0], 0, &input)?;
        backend.write_buffer(io[1], 0, &image.counts)?;
        let frame = Frame::layers(w, h, layers, *lens, SlotBuffer::current(io[0]), CountBuffer(io[1]), RgbBuffer(io[2]))
            .with_footprints(image.footprint_grid());
        // The frame, then, while its lists overflowed the pool, the context grown and the frame
        // run again: the one rule every one-shot run follows (`one_shot::grow_to_fit`).
        let mut stages = Vec::new();
        let mut run_frame = |ctx: &mut dyn DofContext, backend: &mut dyn Backend| -> Result<()> {
            ctx.record(backend, &frame)?;
            stages = backend.submit()?;
            Ok(())
        };
        run_frame(&mut ctx, backend)?;
        grow_to_fit(&mut ctx, backend, &mut run_frame)?;
        let then = then(backend, &mut ctx, &frame)?;
        let mut report = ctx.report(backend)?;
        report.input_fragments = Some(image.counts.iter().map(|&n| n.min(layers) as u64).sum());
        Ok((SplatOutput { image: read_rgb(backend, io[2], w, h)?, report, stages }, then))
    });
    ctx.destroy(backend);
    result
}
