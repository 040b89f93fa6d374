//! What the viewer reads back from a completed frame: the screenshot (the presented 8-bit sRGB
//! swapchain pixels, written as they are) and the linear result compared with the reference.

use anyhow::Result;
use dof::layers::RgbImage;
use std::path::Path;

/// Writes 8-bit sRGB swapchain pixels (BGRA when `bgra`, else RGBA) as an RGB PNG, unchanged.
pub fn write_screenshot(path: &Path, width: u32, height: u32, bytes: &[u8], bgra: bool) -> Result<()> {
    let pixels: Vec<[f32; 3]> = bytes
        .chunks_exact(4)
        .map(|p| if bgra { [p[2], p[1], p[0]] } else { [p[0], p[1], p[2]] })
        // write_png_display stores round(255 v): each code value comes back exactly.
        .map(|p| p.map(|c| c as f32 / 255.0))
        .collect();
    dof::io::write_png_display(path, width, height, &pixels)?;
    Ok(())
}

/// The RGB image in RGBA32F pixels (the frame API's output format).
pub fn rgb_of_rgba32f(width: u32, height: u32, words: &[f32]) -> RgbImage {
    RgbImage { width, height, data: words.chunks_exact(4).map(|p| [p[0], p[1], p[2]]).collect() }
}

/// The PSNR of `image` against `reference` (the project's PSNR, on the tone map) and the absolute
/// error, 8 times amplified, as a picture for the UI.
pub fn error_view(image: &RgbImage, reference: &RgbImage) -> Result<(f64, egui::ColorImage)> {
    let psnr = dof::metrics::psnr(image, reference)?;
    let rgba: Vec<u8> = image
        .data
        .iter()
        .zip(&reference.data)
        .flat_map(|(a, b)| {
            let e = |c: usize| dof::io::tonemap::to_u8(8.0 * (a[c] - b[c]).abs().min(1.0));
            [e(0), e(1), e(2), 255]
        })
        .collect();
    Ok((psnr, egui::ColorImage::from_rgba_unmultiplied([image.width as usize, image.height as usize], &rgba)))
}
