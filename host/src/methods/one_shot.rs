//! One frame of a host image through any method of the frame API: a context sized to the image,
//! the input uploaded, one recording, one submission, the result and the report read back, the
//! context destroyed. The convenience path for the CLI, the evaluation and the tests; it allocates
//! per call, where a renderer keeps one context ([`crate::frame`]). A frame whose context
//! overflowed is run again with the context grown ([`DofContext::grow_to_fit`]), so the result is
//! whole.

use crate::backend::{Backend, CommandTime, with_buffers};
use crate::error::{Error, Result};
use crate::frame::{ContextDesc, ContextReport, DofContext, Extent, Frame, MethodInfo, MethodOptions, Reads};
use crate::layers::{LayeredImage, RgbImage};
use crate::methods::buffers::{read_rgb, slot_words};
use dof_shaders::lens::ThinLens;

/// What one frame gave.
pub struct OneShot {
    pub image: RgbImage,
    pub report: ContextReport,
    /// One entry per recorded command, labelled by stage.
    pub stages: Vec<CommandTime>,
    /// Device bytes of the context, the input and the output.
    pub buffer_bytes: u64,
}

/// Renders `image` through `lens` with `method` on `backend`. A method that reads the front layer
/// is handed only that ([`Reads::FrontLayer`]).
pub fn one_shot(
    backend: &mut dyn Backend,
    method: &MethodInfo,
    options: &MethodOptions,
    image: &LayeredImage,
    lens: &ThinLens,
) -> Result<OneShot> {
    if !lens.is_valid() {
        return Err(Error::InvalidArgument(format!("invalid lens: {lens:?}")));
    }
    let front;
    let image = match method.reads {
        Reads::FrontLayer if image.max_layers > 1 => {
            front = image.front_layer();
            &front
        }
        _ => image,
    };
    let (w, h, layers) = (image.width, image.height, image.max_layers);
    if w == 0 || h == 0 || layers == 0 {
        return Err(Error::InvalidArgument(format!("{} needs a non-empty image, got {w}x{h} with {layers} layers", method.name)));
    }
    // The context checks the extent (and refuses) before the input is uploaded.
    let mut ctx = (method.create)(backend, &ContextDesc::new(Extent::new(w, h, layers), options.clone()))?;
    let ran = run(backend, ctx.as_mut(), image, lens);
    ctx.destroy(backend);
    ran
}

/// Runs a frame again with a grown context at most this many times after an overflow.
const RETRIES: u32 = 3;

fn run(backend: &mut dyn Backend, ctx: &mut dyn DofContext, image: &LayeredImage, lens: &ThinLens) -> Result<OneShot> {
    let (w, h, layers) = (image.width, image.height, image.max_layers);
    let pixels = w as u64 * h as u64;
    let input = slot_words(image);
    let sizes = [(input.len() as u64, "one-shot/input"), (pixels, "one-shot/input-counts"), (3 * pixels, "one-shot/out")];
    let io_bytes = 4 * sizes.iter().map(|s| s.0).sum::<u64>();
    with_buffers(backend, &sizes, |backend, io| {
        backend.write_buffer(io[0], 0, &input)?;
        backend.write_buffer(io[1], 0, &image.counts)?;
        let frame = Frame::layers(w, h, layers, *lens, io[0], io[1], io[2]);
        let mut attempt = 0;
        let (stages, report) = loop {
            ctx.record(backend, &frame)?;
            let stages = backend.submit()?;
            let report = ctx.report(backend)?;
            // A one-shot result is whole: what overflowed is grown and the frame run again.
            if report.overflow == 0 || attempt == RETRIES || !ctx.grow_to_fit(backend)? {
                break (stages, report);
            }
            attempt += 1;
        };
        let image = read_rgb(backend, io[2], w, h)?;
        Ok(OneShot { image, report, stages, buffer_bytes: ctx.device_bytes() + io_bytes })
    })
}
