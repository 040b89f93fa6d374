//! Per scene, an image grid: the reference beside every method's best image (on the first backend),
//! each with its error heat map, written as `<scene>-grid.png` next to the report.
//!
//! Layout: one row per image, two columns: the image through the documented tone map, then the
//! absolute difference to the reference's tone-mapped pixel (mean of the channels, times 4), coloured
//! black → red → yellow → white. Row order: reference, then methods in registry order.

use crate::error::Result;
use crate::io::tonemap::tonemap_image;
use crate::io::write_png_display;
use crate::layers::RgbImage;
use std::path::Path;

/// Heat-map colour of an error `e` in [0, 1] (clamped).
fn heat(e: f32) -> [f32; 3] {
    let t = (3.0 * e).clamp(0.0, 3.0);
    [t.min(1.0), (t - 1.0).clamp(0.0, 1.0), (t - 2.0).clamp(0.0, 1.0)]
}

/// Writes the grid of `rows` (label, image), the reference first, to `path`.
pub fn write_grid(path: &Path, reference: &RgbImage, rows: &[(String, RgbImage)]) -> Result<()> {
    let (w, h) = (reference.width as usize, reference.height as usize);
    let gap = 4;
    let (gw, gh) = (2 * w + gap, (rows.len() + 1) * (h + gap) - gap);
    let mut pixels = vec![[0.15f32; 3]; gw * gh];
    let want = tonemap_image(reference, 1.0);
    let mut blit = |row: usize, col: usize, cells: &[[f32; 3]]| {
        for y in 0..h {
            let at = (row * (h + gap) + y) * gw + col * (w + gap);
            pixels[at..at + w].copy_from_slice(&cells[y * w..(y + 1) * w]);
        }
    };
    blit(0, 0, &want);
    blit(0, 1, &vec![[0.0; 3]; w * h]);
    for (i, (_, image)) in rows.iter().enumerate() {
        let got = tonemap_image(image, 1.0);
        let errors: Vec<[f32; 3]> = got
            .iter()
            .zip(&want)
            .map(|(g, r)| heat(4.0 * (0..3).map(|c| (g[c] - r[c]).abs()).sum::<f32>() / 3.0))
            .collect();
        blit(i + 1, 0, &got);
        blit(i + 1, 1, &errors);
    }
    write_png_display(path, gw as u32, gh as u32, &pixels)
}
