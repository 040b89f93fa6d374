//! EXR output: a colour image with optional extra single-channel planes, and multi-layer images.

use std::path::Path;

use ::exr::prelude::*;

use super::{check_rgb_image, write_file};
use crate::error::{Error, Result};
use crate::layers::{LayeredImage, RgbImage};

/// The sample type of the colour channels in a written EXR. Extra planes are always `f32`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ExrPrecision {
    /// 16-bit half floats: half the size, about 3 significant digits, values above 65 504 become
    /// `inf`. For previews and deliverables, not for references.
    Half,
    /// 32-bit floats: written and read back bit for bit.
    #[default]
    Float,
}

/// How the pixel data of a written EXR is compressed. Both are lossless.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ExrCompression {
    /// ZIP over blocks of 16 scan lines: small files, readable everywhere; writing costs about
    /// 20 ns per sample on one core.
    #[default]
    Zip,
    /// Uncompressed scan lines: the fastest to write and read, the largest files.
    None,
}

/// Where an image lies in an EXR's pixel space: the corner of its data window and the display
/// window (`[x_min, y_min, x_max, y_max]`, inclusive, as OpenEXR stores it). An input's windows,
/// written back with the result, keep a render's place in its frame (an offset crop, a data
/// window beyond or inside the display window).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ExrWindow {
    pub origin: (i32, i32),
    pub display: [i32; 4],
}

impl ExrWindow {
    /// A data window at `(0, 0)` that is the display window too.
    pub fn plain(width: u32, height: u32) -> ExrWindow {
        ExrWindow { origin: (0, 0), display: [0, 0, width as i32 - 1, height as i32 - 1] }
    }

    /// Whether the data window is at `(0, 0)` and is the display window.
    pub fn is_plain(&self, width: u32, height: u32) -> bool {
        *self == ExrWindow::plain(width, height)
    }
}

/// Options of [`write_exr_with`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ExrWriteOptions {
    /// Sample type of the colour channels (extra planes are always `f32`).
    pub precision: ExrPrecision,
    pub compression: ExrCompression,
    /// The data window's corner and the display window (default: the image at `(0, 0)`, its own
    /// display window).
    pub window: Option<ExrWindow>,
}

impl ExrCompression {
    fn encoding(self) -> Encoding {
        match self {
            ExrCompression::Zip => Encoding::SMALL_LOSSLESS,
            ExrCompression::None => Encoding::UNCOMPRESSED,
        }
    }
}

/// Writes `image` as a linear `f32` RGB EXR (ZIP-compressed scan lines, lossless; see
/// [`write_exr_with`] for half floats or no compression) with the extra
/// single-channel `f32` planes `extra` (name, one value per pixel in the image's order), e.g.
/// `("Z", depth)`, `("coc", coc_px)`, `("mask", mask)`. A `"Z"` plane makes the file an RGB+Z image
/// that [`read_layered_exr`](super::read_layered_exr) reads back. Values are written as they are
/// (NaN and `inf` included).
pub fn write_exr(path: impl AsRef<Path>, image: &RgbImage, extra: &[(&str, &[f32])]) -> Result<()> {
    write_exr_with(path, image, extra, &ExrWriteOptions::default())
}

/// [`write_exr`] with the colour channels in the given precision and the given compression.
///
/// Errors: a zero-sized image; `image.data` or an extra plane not holding `width · height` values;
/// an extra plane name that is empty, longer than 255 bytes, not printable ASCII, repeated, or one
/// of the colour channels `R`, `G`, `B`; a file that cannot be written.
pub fn write_exr_with(path: impl AsRef<Path>, image: &RgbImage, extra: &[(&str, &[f32])], options: &ExrWriteOptions) -> Result<()> {
    let path = path.as_ref();
    check_rgb_image(image, "an EXR image")?;
    let pixels = image.data.len();
    let mut names: Vec<&str> = vec!["R", "G", "B"];
    for &(name, plane) in extra {
        check_channel_name(name)?;
        if names.contains(&name) {
            return Err(Error::invalid(format!(
                "EXR channel name `{name}` is used twice (R, G and B hold the colour): give every extra plane its own name"
            )));
        }
        names.push(name);
        if plane.len() != pixels {
            return Err(Error::invalid(format!(
                "extra EXR plane `{name}` has {} values but the image is {}x{} = {pixels} pixels",
                plane.len(),
                image.width,
                image.height
            )));
        }
    }

    // The channels are copied into the encoder's planes, and the file is encoded in memory: about
    // twice the samples, refused up front rather than aborted part way.
    let samples = pixels as u128 * (3 + extra.len() as u128) * 4;
    crate::memory::check_fits(&format!("writing {}", path.display()), 2 * samples, crate::memory::available())?;
    let colour = |k: usize| -> FlatSamples {
        match options.precision {
            ExrPrecision::Float => FlatSamples::F32(image.data.iter().map(|c| c[k]).collect()),
            ExrPrecision::Half => FlatSamples::F16(image.data.iter().map(|c| f16::from_f32(c[k])).collect()),
        }
    };
    let mut channels: SmallVec<[AnyChannel<FlatSamples>; 4]> = SmallVec::new();
    for (k, name) in ["R", "G", "B"].into_iter().enumerate() {
        channels.push(AnyChannel::new(text(name)?, colour(k)));
    }
    for &(name, plane) in extra {
        channels.push(AnyChannel::new(text(name)?, FlatSamples::F32(plane.to_vec())));
    }
    let size = (image.width as usize, image.height as usize);
    let mut exr_image = Image::from_encoded_channels(size, options.compression.encoding(), AnyChannels::sort(channels));
    if let Some(w) = options.window {
        let [x0, y0, x1, y1] = w.display;
        if x1 < x0 || y1 < y0 {
            return Err(Error::invalid(format!("an EXR display window needs its maximum at or after its minimum, got {:?}", w.display)));
        }
        exr_image.layer_data.attributes.layer_position = Vec2(w.origin.0, w.origin.1);
        exr_image.attributes.display_window =
            IntegerBounds::new(Vec2(x0, y0), Vec2((x1 as i64 - x0 as i64 + 1) as usize, (y1 as i64 - y0 as i64 + 1) as usize));
    }
    encode_and_write(path, &exr_image)
}

/// Writes a multi-layer image as one EXR part with, for every layer `i` in `0..max_layers`, the
/// `f32` channels `layer{i}.R`, `.G`, `.B`, `.A`, `.Z`: the `i`-th fragment of each pixel, colour
/// premultiplied by alpha (the OpenEXR convention), and for pixels with fewer fragments an empty
/// slot (colour 0, A 0, Z `+inf`). [`read_layered_exr`](super::read_layered_exr) reads it back.
///
/// ZIP-compressed (lossless). Errors on a zero size or inconsistent storage (`counts` and
/// `fragments` not sized for `width · height · max_layers`).
pub fn write_layered_exr(path: impl AsRef<Path>, image: &LayeredImage) -> Result<()> {
    let path = path.as_ref();
    let pixels = image.width as usize * image.height as usize;
    let layers = image.max_layers as usize;
    if pixels == 0 || layers == 0 {
        return Err(Error::invalid(format!(
            "cannot write a layered EXR of size {}x{} with {} layers: the size and layer count must be positive",
            image.width, image.height, image.max_layers
        )));
    }
    if image.counts.len() != pixels || image.fragments.len() != pixels * layers {
        return Err(Error::invalid(format!(
            "layered image {}x{} with {} layers holds {} counts and {} fragment slots; expected {pixels} and {}",
            image.width,
            image.height,
            image.max_layers,
            image.counts.len(),
            image.fragments.len(),
            pixels * layers
        )));
    }
    let mut channels: SmallVec<[AnyChannel<FlatSamples>; 4]> = SmallVec::new();
    for layer in 0..layers {
        let slot = |p: usize| (layer < image.counts[p] as usize).then(|| image.fragments[p * layers + layer]);
        for (k, c) in ["R", "G", "B"].into_iter().enumerate() {
            let values = (0..pixels).map(|p| slot(p).map_or(0.0, |f| f.color[k])).collect();
            channels.push(AnyChannel::new(text(&format!("layer{layer}.{c}"))?, FlatSamples::F32(values)));
        }
        let alpha = (0..pixels).map(|p| slot(p).map_or(0.0, |f| f.alpha)).collect();
        channels.push(AnyChannel::new(text(&format!("layer{layer}.A"))?, FlatSamples::F32(alpha)));
        let depth = (0..pixels).map(|p| slot(p).map_or(f32::INFINITY, |f| f.depth)).collect();
        channels.push(AnyChannel::new(text(&format!("layer{layer}.Z"))?, FlatSamples::F32(depth)));
    }
    let size = (image.width as usize, image.height as usize);
    let exr_image = Image::from_encoded_channels(size, ExrCompression::Zip.encoding(), AnyChannels::sort(channels));
    encode_and_write(path, &exr_image)
}

fn check_channel_name(name: &str) -> Result<()> {
    if name.is_empty() || name.len() > 255 || !name.bytes().all(|b| b.is_ascii_graphic()) {
        return Err(Error::invalid(format!(
            "`{name}` cannot be an EXR channel name: use 1 to 255 printable ASCII characters without spaces"
        )));
    }
    Ok(())
}

fn text(name: &str) -> Result<Text> {
    Text::new_or_none(name).ok_or_else(|| Error::invalid(format!("`{name}` cannot be an EXR channel name: use printable ASCII")))
}

fn encode_and_write(path: &Path, image: &Image<Layer<AnyChannels<FlatSamples>>>) -> Result<()> {
    // Encoded in memory, then written in one call, so that every I/O error is reported with the path.
    let mut encoded = std::io::Cursor::new(Vec::new());
    image.write().to_buffered(&mut encoded).map_err(|e| Error::invalid(format!("encoding the EXR {}: {e}", path.display())))?;
    write_file(path, encoded.get_ref())
}
