//! The gathering baseline (kernel and its rules in `dof_shaders::gather`) on a single-layer image.

use super::buffers::read_rgb;
use crate::backend::{Backend, CommandTime, push_words, with_buffers};
use crate::error::{Error, Result};
use crate::layers::RgbImage;
use dof_shaders::gather::{GATHER, GatherParams, TILE, radius_px};
use dof_shaders::lens::ThinLens;

/// The scanned window is `2 r + 1` pixels wide: beyond this radius the gather's cost (quadratic in
/// it) belongs to a reduced-resolution path, which this baseline does not have.
pub const MAX_RADIUS: u32 = 48;

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
    /// Device buffer bytes the pass held (colour, depth and output).
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
    let radius = needed_radius(lens, depth, cap);
    let colour_words: Vec<u32> = image.data.iter().flat_map(|c| c.map(f32::to_bits)).collect();
    let depth_words: Vec<u32> = depth.iter().map(|z| z.to_bits()).collect();
    let sizes = [(3 * pixels, "gather/color"), (pixels, "gather/depth"), (3 * pixels, "gather/out")];
    let buffer_bytes = 4 * sizes.iter().map(|s| s.0).sum::<u64>();
    with_buffers(backend, &sizes, |backend, b| {
        let (color, depth, out) = (b[0], b[1], b[2]);
        backend.write_buffer(color, 0, &colour_words)?;
        backend.write_buffer(depth, 0, &depth_words)?;
        let params = GatherParams { width: image.width, height: image.height, max_radius: radius, _pad: 0, lens: *lens };
        let groups = [image.width.div_ceil(TILE), image.height.div_ceil(TILE), 1];
        backend.dispatch(&GATHER, groups, &[color, depth, out], &push_words(&params), "gather")?;
        let times = backend.submit()?;
        let image = read_rgb(backend, out, image.width, image.height)?;
        Ok(GatherOutput { image, radius, times, buffer_bytes })
    })
}
