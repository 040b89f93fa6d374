//! The gathering baseline (kernel and its rules in `dof_shaders::gather`) on a single-layer image,
//! one frame through [`crate::frame::GatherContext`].

use super::buffers::one_layer_frame;
use crate::backend::{Backend, CommandTime};
use crate::frame::Extent;
use crate::frame::{DofContext, GatherContext, GatherContextDesc};
use crate::layers::RgbImage;
use dof_core::error::{Error, Result};
use dof_shaders::gather::radius_px;
use dof_shaders::lens::ThinLens;

pub use crate::frame::gather::MAX_RADIUS;

/// The largest CoC radius actually present in `depth` (whole pixels, rounded up), so the kernel
/// scans no wider than the scene needs; at most `cap`.
pub fn needed_radius(lens: &ThinLens, depth: &[f32], cap: u32) -> u32 {
    let largest = depth.iter().map(|&z| radius_px(lens, z, cap as f32)).fold(0.0f32, f32::max);
    (largest.ceil() as u32).min(cap)
}

/// The blurred image and the time of each dispatch.
pub struct GatherOutput {
    pub image: RgbImage,
    /// Radius the kernel scanned.
    pub radius: u32,
    pub times: Vec<CommandTime>,
    /// Device buffer bytes the frame held (the context's, the input's and the output's).
    pub buffer_bytes: u64,
}

/// Runs the gathering baseline on `backend`. `max_radius` caps the CoC radius (default: what the
/// depth needs, up to [`MAX_RADIUS`]).
pub fn gather(
    backend: &mut dyn Backend,
    image: &RgbImage,
    depth: &[f32],
    lens: &ThinLens,
    max_radius: Option<u32>,
) -> Result<GatherOutput> {
    let cap = max_radius.unwrap_or(MAX_RADIUS);
    if cap > MAX_RADIUS {
        return Err(Error::TooLarge { what: "gather radius (px)".into(), size: cap as u64, limit: MAX_RADIUS as u64 });
    }
    let desc = GatherContextDesc { max_radius: Some(cap), ..GatherContextDesc::new(Extent::new(image.width, image.height, 1)) };
    let (out, (radius, times, context_bytes)) = one_layer_frame(backend, "gather", image, depth, lens, |backend, frame| {
        let mut ctx = GatherContext::new(backend, &desc)?;
        let ran = (|| {
            ctx.record(backend, frame)?;
            let times = backend.submit()?;
            Ok((ctx.radius(backend)?, times, ctx.device_bytes()))
        })();
        ctx.destroy(backend);
        ran
    })?;
    let pixels = image.width as u64 * image.height as u64;
    Ok(GatherOutput { image: out, radius, times, buffer_bytes: context_bytes + 4 * 8 * pixels })
}
