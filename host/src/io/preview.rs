//! PNG previews: 8-bit sRGB through the documented [tone map](super::tonemap).

use std::path::Path;

use rayon::prelude::*;

use super::tonemap::tonemap_to_srgb8;
use super::{check_rgb_image, write_file};
use crate::error::{Error, Result};
use crate::layers::RgbImage;

/// Writes `image` as an 8-bit RGB PNG (tagged sRGB): each pixel is [`tonemap`](super::tonemap::tonemap)
/// `(rgb, exposure)` quantised with `round(255 · v)`. NaN pixels become 0 (black); `+inf` white.
///
/// Errors: a zero-sized image, `data` not holding `width · height` pixels, an exposure that is not
/// a positive finite number, a file that cannot be created or written.
pub fn write_png_preview(path: impl AsRef<Path>, image: &RgbImage, exposure: f32) -> Result<()> {
    let path = path.as_ref();
    check_rgb_image(image, "a PNG preview")?;
    if !(exposure > 0.0 && exposure.is_finite()) {
        return Err(Error::invalid(format!(
            "PNG preview exposure must be a positive finite number, got {exposure} (1 leaves the image as is)"
        )));
    }
    let bytes: Vec<u8> = image.data.par_iter().flat_map_iter(|&c| tonemap_to_srgb8(c, exposure)).collect();
    write_srgb8(path, image.width, image.height, &bytes)
}

/// Writes display-referred colours (already in [0, 1], sRGB-encoded: a tone-mapped image, a heat map)
/// as an 8-bit RGB PNG.
pub fn write_png_display(path: impl AsRef<Path>, width: u32, height: u32, pixels: &[[f32; 3]]) -> Result<()> {
    let image = RgbImage { width, height, data: pixels.to_vec() };
    check_rgb_image(&image, "a PNG")?;
    let bytes: Vec<u8> = pixels.iter().flat_map(|p| p.map(super::tonemap::to_u8)).collect();
    write_srgb8(path.as_ref(), width, height, &bytes)
}

/// Writes 8-bit sRGB pixels (`width * height * 3` bytes) as a PNG.
pub(crate) fn write_srgb8(path: &Path, width: u32, height: u32, bytes: &[u8]) -> Result<()> {
    // Encoded in memory, then written in one call, so that every I/O error is reported with the path.
    let mut encoded = Vec::new();
    let png_error = |e: ::png::EncodingError| Error::invalid(format!("encoding the PNG {}: {e}", path.display()));
    let mut encoder = ::png::Encoder::new(&mut encoded, width, height);
    encoder.set_color(::png::ColorType::Rgb);
    encoder.set_depth(::png::BitDepth::Eight);
    encoder.set_source_srgb(::png::SrgbRenderingIntent::Perceptual);
    let mut writer = encoder.write_header().map_err(png_error)?;
    writer.write_image_data(bytes).map_err(png_error)?;
    writer.finish().map_err(png_error)?;
    write_file(path, &encoded)
}
