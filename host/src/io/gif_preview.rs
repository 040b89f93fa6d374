//! Animated previews: a sequence of linear HDR frames as a looping GIF through the same tone map
//! as the PNG previews ([`tonemap_to_srgb8`]), each frame quantised to its own 256-colour palette
//! by the `gif` crate (NeuQuant).

use std::path::Path;

use rayon::prelude::*;

use super::tonemap::tonemap_to_srgb8;
use super::{check_rgb_image, write_file};
use crate::error::{Error, Result};
use crate::layers::RgbImage;

/// The largest edge a GIF holds (its header stores 16 bits).
pub const MAX_GIF_EDGE: u32 = u16::MAX as u32;

/// Writes `frames` (all of one size) as a looping animated GIF, `delay_ms` per frame (rounded to
/// the format's hundredths of a second, at least one), each tone-mapped with `exposure`.
///
/// Errors: no frames, frames of different sizes or larger than [`MAX_GIF_EDGE`], an exposure that
/// is not a positive finite number, a file that cannot be written.
pub fn write_gif_preview(path: impl AsRef<Path>, frames: &[RgbImage], exposure: f32, delay_ms: u32) -> Result<()> {
    let path = path.as_ref();
    let Some(first) = frames.first() else { return Err(Error::invalid("an animated GIF needs at least one frame".into())) };
    if !(exposure > 0.0 && exposure.is_finite()) {
        return Err(Error::invalid(format!("GIF preview exposure must be a positive finite number, got {exposure}")));
    }
    let (w, h) = (first.width, first.height);
    if w > MAX_GIF_EDGE || h > MAX_GIF_EDGE {
        return Err(Error::invalid(format!("a GIF is at most {MAX_GIF_EDGE} px on an edge, got {w}x{h}")));
    }
    let mut encoded = Vec::new();
    let gif_error = |e: ::gif::EncodingError| Error::invalid(format!("encoding the GIF {}: {e}", path.display()));
    {
        let mut encoder = ::gif::Encoder::new(&mut encoded, w as u16, h as u16, &[]).map_err(gif_error)?;
        encoder.set_repeat(::gif::Repeat::Infinite).map_err(gif_error)?;
        let delay = (delay_ms.div_ceil(10)).clamp(1, u16::MAX as u32) as u16;
        for image in frames {
            check_rgb_image(image, "a GIF frame")?;
            if (image.width, image.height) != (w, h) {
                return Err(Error::invalid(format!("the frames of a GIF share one size: {w}x{h} and {}x{}", image.width, image.height)));
            }
            let bytes: Vec<u8> = image.data.par_iter().flat_map_iter(|&c| tonemap_to_srgb8(c, exposure)).collect();
            let mut frame = ::gif::Frame::from_rgb_speed(w as u16, h as u16, &bytes, 10);
            frame.delay = delay;
            encoder.write_frame(&frame).map_err(gif_error)?;
        }
    }
    write_file(path, &encoded)
}
