//! The gathering baseline (kernel and its rules in `dof_shaders::gather`) on a single-layer image,
//! one frame through [`crate::frame::GatherContext`].

use super::buffers::read_rgb;
use crate::backend::{Backend, CommandTime, with_buffers};
use crate::error::{Error, Result};
use crate::frame::{Frame, GatherContext, GatherContextDesc};
use crate::layers::RgbImage;
use dof_shaders::gather::radius_px;
use dof_shaders::lens::ThinLens;

pub use crate::frame::gather::MAX_RADIUS;

/// The largest CoC radius actually present in `depth` (whole pixels, rounded up), so the kernel
/// scans no wider than the scene needs; at most `cap`.
pub fn needed_radius(lens: &ThinLens, depth: &[f32], cap: u32) -> u32 {
    let largest = depth
        .iter()
        .map(|&z| radius_px(lens, z, cap as f32))
        .fold(0.0f32, f32::max);
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
    let pixels = image.width as u64 * image.height as u64;
    if pixels == 0 || image.data.len() as u64 != pixels || depth.len() as u64 != pixels {
        return Err(Error::InvalidArgument(format!(
            "gather needs a non-empty {}x{} image with one depth per pixel ({} colours, {} depths)",
            image.width,
            image.height,
            image.data.len(),
            depth.len()
        )));
    }
    if !lens.is_valid() {
        return Err(Error::InvalidArgument(format!("invalid lens: {lens:?}")));
    }
    let cap = max_radius.unwrap_or(MAX_RADIUS);
    if cap > MAX_RADIUS {
        return Err(Error::TooLarge { what: "gather radius (px)".into(), size: cap as u64, limit: MAX_RADIUS as u64 });
    }
    let slots: Vec<u32> = image.data.iter().zip(depth).flat_map(|(c, z)| [c[0].to_bits(), c[1].to_bits(), c[2].to_bits(), z.to_bits()]).collect();
    let desc = GatherContextDesc { max_radius: Some(cap), ..GatherContextDesc::new(image.width, image.height, 1) };
    let sizes = [(4 * pixels, "gather/input"), (pixels, "gather/input-counts"), (3 * pixels, "gather/out")];
    with_buffers(backend, &sizes, |backend, b| {
        backend.write_buffer(b[0], 0, &slots)?;
        backend.write_buffer(b[1], 0, &vec![1u32; pixels as usize])?;
        let mut ctx = GatherContext::new(backend, &desc)?;
        let ran = (|| {
            ctx.record(backend, &Frame::layers(image.width, image.height, 1, *lens, b[0], b[1], b[2]))?;
            let times = backend.submit()?;
            let radius = ctx.radius(backend)?;
            let image = read_rgb(backend, b[2], image.width, image.height)?;
            Ok(GatherOutput { image, radius, times, buffer_bytes: ctx.device_bytes() + 4 * 8 * pixels })
        })();
        ctx.destroy(backend);
        ran
    })
}
