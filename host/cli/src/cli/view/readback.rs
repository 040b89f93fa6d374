//! What the viewer reads back from a completed frame: the screenshot (the presented 8-bit sRGB
//! swapchain pixels, written as they are) and the linear result compared with the reference.

use anyhow::Result;
use dof::backend::{Backend, BufferId};
use dof::layers::RgbImage;
use std::path::Path;

/// Writes 8-bit sRGB swapchain pixels (BGRA when `bgra`, else RGBA) as an RGB PNG, unchanged.
pub fn write_screenshot(path: &Path, width: u32, height: u32, bytes: &[u8], bgra: bool) -> Result<()> {
    let pixels: Vec<[f32; 3]> = bytes
        .as_chunks::<4>()
        .0
        .iter()
        .map(|p| if bgra { [p[2], p[1], p[0]] } else { [p[0], p[1], p[2]] })
        // write_png_display stores round(255 v): each code value comes back exactly.
        .map(|p| p.map(|c| c as f32 / 255.0))
        .collect();
    dof::io::write_png_display(path, width, height, &pixels)?;
    Ok(())
}

/// The window's part of a frame's linear RGB result (3 words a pixel, `frame_width` wide, the
/// window at `margin` pixels from its top left corner), read back from the library's buffer.
pub fn window_of_rgb(backend: &mut dyn Backend, rgb: BufferId, frame_width: u32, margin: u32, size: [u32; 2]) -> Result<RgbImage> {
    let [w, h] = size;
    if margin as u64 + w as u64 > frame_width as u64 {
        anyhow::bail!("the window ({w} px wide at {margin} px) is not inside the frame ({frame_width} px wide)");
    }
    let row = 3 * frame_width as u64;
    let words = backend.read_buffer(rgb, row * margin as u64, row * h as u64)?;
    let data = words
        .chunks_exact(row as usize)
        .flat_map(|r| r[3 * margin as usize..3 * (margin + w) as usize].as_chunks::<3>().0)
        .map(|c| [f32::from_bits(c[0]), f32::from_bits(c[1]), f32::from_bits(c[2])])
        .collect();
    Ok(RgbImage { width: w, height: h, data })
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
