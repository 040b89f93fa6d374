//! The engine-grade gather (kernels and their rules in `dof_shaders::ring_gather`) on a
//! single-layer image, one frame through [`crate::frame::RingGatherContext`].

use super::buffers::one_layer_frame;
use crate::backend::{Backend, CommandTime};
use crate::frame::Extent;
use crate::frame::{DofContext, RingGatherContext, RingGatherContextDesc};
use crate::layers::RgbImage;
use dof_core::error::Result;
use dof_shaders::lens::ThinLens;

pub use crate::frame::ring_gather::{DEFAULT_MAX_RADIUS, DEFAULT_RINGS, MAX_RADIUS, MAX_SAMPLE_RINGS, RingGatherOptions};

/// The blurred image and the time of each dispatch.
pub struct RingGatherOutput {
    pub image: RgbImage,
    pub times: Vec<CommandTime>,
    /// Samples each half-resolution pixel read.
    pub samples: u32,
    /// Device buffer bytes the frame held (the context's, the input's and the output's).
    pub buffer_bytes: u64,
}

/// Runs the engine-grade gather on `backend`.
pub fn ring_gather(
    backend: &mut dyn Backend,
    image: &RgbImage,
    depth: &[f32],
    lens: &ThinLens,
    options: &RingGatherOptions,
) -> Result<RingGatherOutput> {
    options.check()?;
    let desc = RingGatherContextDesc { options: *options, ..RingGatherContextDesc::new(Extent::new(image.width, image.height, 1)) };
    let (out, (times, context_bytes)) = one_layer_frame(backend, "the ring gather", image, depth, lens, |backend, frame| {
        let mut ctx = RingGatherContext::new(backend, &desc)?;
        let ran = ctx.record(backend, frame).and_then(|_| backend.submit()).map(|times| (times, ctx.device_bytes()));
        ctx.destroy(backend);
        ran
    })?;
    let pixels = image.width as u64 * image.height as u64;
    let samples = dof_shaders::ring_gather::samples(options.rings);
    Ok(RingGatherOutput { image: out, times, samples, buffer_bytes: context_bytes + 4 * 8 * pixels })
}
