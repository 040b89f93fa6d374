//! What every method does with its buffers the same way: the layered input's slot words, the size
//! of a one-dimensional grid-stride dispatch, and reading an RGB result back.

use crate::backend::{Backend, BufferId};
use crate::error::Result;
use crate::layers::{LayeredImage, RgbImage};
use dof_shaders::KernelDesc;

/// Workgroups the host dispatches at most in one dimension; grid-stride kernels loop over the rest.
pub use dof_shaders::splat::MAX_GROUPS;

/// Every fragment slot of `image` as 4 words: r, g, b, depth (the input layout of the splatting,
/// ray-tracing and layered kernels).
pub fn slot_words(image: &LayeredImage) -> Vec<u32> {
    image.fragments.iter().flat_map(|f| [f.color[0].to_bits(), f.color[1].to_bits(), f.color[2].to_bits(), f.depth.to_bits()]).collect()
}

/// Workgroups of `kernel` for `items` one-dimensional items (at least one, at most [`MAX_GROUPS`]).
pub fn groups_for(kernel: &KernelDesc, items: u64) -> [u32; 3] {
    [(items.div_ceil(kernel.workgroup_size as u64)).clamp(1, MAX_GROUPS as u64) as u32, 1, 1]
}

/// A `width` x `height` RGB image from 3 words a pixel of `buffer`.
pub fn read_rgb(backend: &mut dyn Backend, buffer: BufferId, width: u32, height: u32) -> Result<RgbImage> {
    let words = backend.read_buffer(buffer, 0, 3 * width as u64 * height as u64)?;
    let data = words.chunks_exact(3).map(|c| [f32::from_bits(c[0]), f32::from_bits(c[1]), f32::from_bits(c[2])]).collect();
    Ok(RgbImage { width, height, data })
}
