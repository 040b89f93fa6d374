//! What every method does with its buffers the same way: the layered input's slot words, the size
//! of a one-dimensional grid-stride dispatch, and reading an RGB result back.

use crate::backend::{Backend, BufferId, with_buffers};
use crate::frame::{CountBuffer, Frame, RgbBuffer, SlotBuffer};
use crate::layers::{LayeredImage, RgbImage};
use dof_core::error::{Error, Result};
use dof_shaders::lens::ThinLens;

pub use crate::backend::{MAX_GROUPS, groups_for};

pub use dof_shaders::slot::SLOT_WORDS;

/// Every fragment slot of `image` as [`SLOT_WORDS`] words: premultiplied r, g, b, depth, alpha
/// (`dof_shaders::slot`, the layer input of every method and of the frame API), then its
/// footprints, one word a slot, where it has them (`FrameInput::Layers::footprint_side`).
pub fn slot_words(image: &LayeredImage) -> Vec<u32> {
    let mut words: Vec<u32> = image.fragments.iter().flat_map(|f| f.slot().words()).collect();
    if image.has_footprints() {
        words.extend_from_slice(&image.footprints);
    }
    words
}

/// Words of `image`'s layer input ([`slot_words`]).
pub fn input_words(image: &LayeredImage) -> u64 {
    let per_slot = SLOT_WORDS as u64 + image.has_footprints() as u64;
    per_slot * image.fragments.len() as u64
}

/// A `width` x `height` RGB image from 3 words a pixel of `buffer`.
pub fn read_rgb(backend: &mut dyn Backend, buffer: BufferId, width: u32, height: u32) -> Result<RgbImage> {
    let words = backend.read_buffer(buffer, 0, 3 * width as u64 * height as u64)?;
    let data = words.as_chunks::<3>().0.iter().map(|c| [f32::from_bits(c[0]), f32::from_bits(c[1]), f32::from_bits(c[2])]).collect();
    Ok(RgbImage { width, height, data })
}

/// One frame of a single-layer method (`what`, for errors) over `image` and its `depth`: checks
/// them and the lens, uploads them as a one-slot layered input, and hands `run` the frame to record
/// and submit through its context. Returns the output image with what `run` returned.
pub fn one_layer_frame<T>(
    backend: &mut dyn Backend,
    what: &str,
    image: &RgbImage,
    depth: &[f32],
    lens: &ThinLens,
    run: impl FnOnce(&mut dyn Backend, &Frame) -> Result<T>,
) -> Result<(RgbImage, T)> {
    let pixels = image.width as u64 * image.height as u64;
    if pixels == 0 || image.data.len() as u64 != pixels || depth.len() as u64 != pixels {
        return Err(Error::InvalidArgument(format!(
            "{what} needs a non-empty {}x{} image with one depth per pixel ({} colours, {} depths)",
            image.width,
            image.height,
            image.data.len(),
            depth.len()
        )));
    }
    crate::lens::check(lens)?;
    let slots: Vec<u32> = image.data.iter().zip(depth).flat_map(|(c, z)| dof_shaders::slot::Slot::opaque(*c, *z).words()).collect();
    let sizes = [(SLOT_WORDS as u64 * pixels, "one-layer/input"), (pixels, "one-layer/input-counts"), (3 * pixels, "one-layer/out")];
    with_buffers(backend, &sizes, |backend, b| {
        backend.write_buffer(b[0], 0, &slots)?;
        backend.write_buffer(b[1], 0, &vec![1u32; pixels as usize])?;
        let ran = run(
            backend,
            &Frame::layers(image.width, image.height, 1, *lens, SlotBuffer::current(b[0]), CountBuffer(b[1]), RgbBuffer(b[2])),
        )?;
        Ok((read_rgb(backend, b[2], image.width, image.height)?, ran))
    })
}
