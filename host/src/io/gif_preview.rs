//! Animated previews: a sequence of linear HDR frames as a looping GIF through the same tone map
//! as the PNG previews ([`tonemap_to_srgb8`]), each frame quantised to its own 256-colour palette
//! by the `gif` crate (NeuQuant).

use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use rayon::prelude::*;

use super::tonemap::tonemap_to_srgb8;
use super::{check_rgb_image, fs_error, persist, temp_beside};
use crate::error::{Error, Result};
use crate::layers::RgbImage;

/// The largest edge a GIF holds (its header stores 16 bits).
pub const MAX_GIF_EDGE: u32 = u16::MAX as u32;

/// Writes `frames` (all of one size) as a looping animated GIF, `delay_ms` per frame (rounded to
/// the format's hundredths of a second, at least one), each tone-mapped with `exposure`
/// ([`GifPreview`] with every frame at once).
///
/// Errors: no frames, frames of different sizes or larger than [`MAX_GIF_EDGE`], an exposure that
/// is not a positive finite number, a file that cannot be written.
pub fn write_gif_preview(path: impl AsRef<Path>, frames: &[RgbImage], exposure: f32, delay_ms: u32) -> Result<()> {
    let Some(first) = frames.first() else { return Err(Error::invalid("an animated GIF needs at least one frame".into())) };
    let mut gif = GifPreview::create(path, first.width, first.height, exposure, delay_ms)?;
    for image in frames {
        gif.push(image)?;
    }
    gif.finish()
}

/// An animated GIF written frame by frame, as a sequence renders: each frame is tone-mapped,
/// quantised and encoded into a temporary file beside the output when it comes, so memory holds one
/// frame, not the sequence; [`Self::finish`] renames the file into place (complete or absent).
/// Dropped unfinished, the temporary file is removed.
pub struct GifPreview {
    path: PathBuf,
    temp: PathBuf,
    encoder: Option<::gif::Encoder<BufWriter<File>>>,
    size: (u32, u32),
    exposure: f32,
    delay: u16,
    frames: u32,
}

impl GifPreview {
    /// A preview of `width` x `height` frames at `path` (see [`write_gif_preview`] for the rest).
    pub fn create(path: impl AsRef<Path>, width: u32, height: u32, exposure: f32, delay_ms: u32) -> Result<GifPreview> {
        let path = path.as_ref().to_path_buf();
        if !(exposure > 0.0 && exposure.is_finite()) {
            return Err(Error::invalid(format!("GIF preview exposure must be a positive finite number, got {exposure}")));
        }
        if width == 0 || height == 0 || width > MAX_GIF_EDGE || height > MAX_GIF_EDGE {
            return Err(Error::invalid(format!("a GIF is 1 to {MAX_GIF_EDGE} px on an edge, got {width}x{height}")));
        }
        let temp = temp_beside(&path);
        let file = File::create(&temp).map_err(|e| fs_error("create", &path, &e))?;
        let mut gif = GifPreview {
            path,
            temp,
            encoder: None,
            size: (width, height),
            exposure,
            delay: (delay_ms.div_ceil(10)).clamp(1, u16::MAX as u32) as u16,
            frames: 0,
        };
        let mut encoder = ::gif::Encoder::new(BufWriter::new(file), width as u16, height as u16, &[]).map_err(|e| gif.error(e))?;
        encoder.set_repeat(::gif::Repeat::Infinite).map_err(|e| gif.error(e))?;
        gif.encoder = Some(encoder);
        Ok(gif)
    }

    fn error(&self, e: ::gif::EncodingError) -> Error {
        Error::invalid(format!("encoding the GIF {}: {e}", self.path.display()))
    }

    /// Appends a frame of the preview's size.
    pub fn push(&mut self, image: &RgbImage) -> Result<()> {
        check_rgb_image(image, "a GIF frame")?;
        let (w, h) = self.size;
        if (image.width, image.height) != (w, h) {
            return Err(Error::invalid(format!("the frames of a GIF share one size: {w}x{h} and {}x{}", image.width, image.height)));
        }
        let bytes: Vec<u8> = image.data.par_iter().flat_map_iter(|&c| tonemap_to_srgb8(c, self.exposure)).collect();
        let mut frame = ::gif::Frame::from_rgb_speed(w as u16, h as u16, &bytes, 10);
        frame.delay = self.delay;
        let Some(encoder) = self.encoder.as_mut() else { return Err(Error::invalid("the GIF preview is already finished".into())) };
        let written = encoder.write_frame(&frame);
        written.map_err(|e| self.error(e))?;
        self.frames += 1;
        Ok(())
    }

    /// Ends the GIF and renames it into place. Errors when it has no frame or cannot be written.
    pub fn finish(mut self) -> Result<()> {
        if self.frames == 0 {
            return Err(Error::invalid("an animated GIF needs at least one frame".into()));
        }
        let Some(encoder) = self.encoder.take() else { return Err(Error::invalid("the GIF preview is already finished".into())) };
        let writer = encoder.into_inner().map_err(|e| fs_error("create", &self.path, &e))?;
        let file = writer.into_inner().map_err(|e| fs_error("create", &self.path, e.error()))?;
        persist(file, &self.temp, &self.path).map_err(|e| fs_error("create", &self.path, &e))?;
        self.temp.clear();
        Ok(())
    }
}

impl Drop for GifPreview {
    fn drop(&mut self) {
        if !self.temp.as_os_str().is_empty() {
            self.encoder = None;
            let _ = std::fs::remove_file(&self.temp);
        }
    }
}
