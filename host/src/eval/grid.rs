//! Per scene, an image grid: the reference beside every method's best image (on the first backend),
//! each with its error heat map, written as `<scene>-grid.png` next to the report.
//!
//! Layout: a header band naming the two columns, then one row per image. Left of each row a label
//! column names it (the caller's label, one line per `\n`: the evaluation writes the method, its
//! setting and its PSNR). The two image columns: the image through the documented tone map, then the
//! absolute difference to the reference's tone-mapped pixel (mean of the channels, times 4), coloured
//! black → red → yellow → white. Row order: reference, then the rows as given (the evaluation gives
//! methods in registry order).
//!
//! The labels are drawn with the plots' font ([`super::plot::ensure_font`]); without a font the grid
//! is written without its label column and header.

use super::plot::{FONT, ensure_font};
use crate::error::{Error, Result};
use crate::io::tonemap::{to_u8, tonemap_image};
use crate::layers::RgbImage;
use plotters::prelude::*;
use std::path::Path;

/// Gap between cells, px.
const GAP: usize = 4;
/// Width of the label column, px.
pub const LABEL_WIDTH: usize = 250;
/// Height of the header band naming the columns, px.
pub const HEADER_HEIGHT: usize = 26;
/// Height of one label line, px (the first line is larger).
const LINE: usize = 17;
/// The grid's background, display-encoded.
pub const BACKGROUND: f32 = 0.15;

/// Heat-map colour of an error `e` in [0, 1] (clamped).
fn heat(e: f32) -> [f32; 3] {
    let t = (3.0 * e).clamp(0.0, 3.0);
    [t.min(1.0), (t - 1.0).clamp(0.0, 1.0), (t - 2.0).clamp(0.0, 1.0)]
}

/// A composed grid: 8-bit sRGB pixels, row-major, 3 bytes a pixel.
pub struct Grid {
    pub width: usize,
    pub height: usize,
    pub rgb: Vec<u8>,
    /// Whether the label column and header were drawn (a font was found).
    pub labelled: bool,
    /// Top edge of each row (the reference first), px.
    pub row_tops: Vec<usize>,
    /// Left edge of the image column and of the error column, px.
    pub column_lefts: [usize; 2],
}

/// Composes the grid of `rows` (label, image) below the reference. Every image must have the
/// reference's size.
pub fn compose(reference: &RgbImage, rows: &[(String, RgbImage)]) -> Result<Grid> {
    let (w, h) = (reference.width as usize, reference.height as usize);
    if let Some((label, image)) = rows.iter().find(|(_, i)| (i.width, i.height) != (reference.width, reference.height)) {
        return Err(Error::invalid(format!(
            "grid row `{}` is {}x{}, the reference {}x{}",
            label.replace('\n', " "),
            image.width,
            image.height,
            w,
            h
        )));
    }
    let labelled = ensure_font().is_ok();
    let lines = rows.iter().map(|(l, _)| l.lines().count()).max().unwrap_or(1).max(2);
    // A row is as tall as its image, or its label where the image is smaller.
    let row_h = if labelled { h.max(lines * LINE + 8) } else { h };
    let (left, top) = if labelled { (LABEL_WIDTH + GAP, HEADER_HEIGHT) } else { (0, 0) };
    let (gw, gh) = (left + 2 * w + GAP, top + (rows.len() + 1) * (row_h + GAP) - GAP);
    let mut pixels = vec![[BACKGROUND; 3]; gw * gh];
    let row_tops: Vec<usize> = (0..=rows.len()).map(|r| top + r * (row_h + GAP)).collect();
    let column_lefts = [left, left + w + GAP];
    let want = tonemap_image(reference, 1.0);
    let mut blit = |row: usize, col: usize, cells: &[[f32; 3]]| {
        for y in 0..h {
            let at = (row_tops[row] + y) * gw + column_lefts[col];
            pixels[at..at + w].copy_from_slice(&cells[y * w..(y + 1) * w]);
        }
    };
    blit(0, 0, &want);
    blit(0, 1, &vec![[0.0; 3]; w * h]);
    for (i, (_, image)) in rows.iter().enumerate() {
        let got = tonemap_image(image, 1.0);
        let errors: Vec<[f32; 3]> =
            got.iter().zip(&want).map(|(g, r)| heat(4.0 * (0..3).map(|c| (g[c] - r[c]).abs()).sum::<f32>() / 3.0)).collect();
        blit(i + 1, 0, &got);
        blit(i + 1, 1, &errors);
    }
    let mut rgb: Vec<u8> = pixels.iter().flat_map(|p| p.map(to_u8)).collect();
    if labelled {
        let mut labels = vec!["reference".to_string()];
        labels.extend(rows.iter().map(|(l, _)| l.clone()));
        draw_labels(&mut rgb, (gw, gh), &labels, &row_tops, column_lefts, w).map_err(Error::Plot)?;
    }
    Ok(Grid { width: gw, height: gh, rgb, labelled, row_tops, column_lefts })
}

/// The largest size up to `size` at which `text` fits `width` px (at least 8).
fn fitting<DB: DrawingBackend>(area: &DrawingArea<DB, plotters::coord::Shift>, text: &str, size: u32, width: usize) -> u32 {
    (8..=size)
        .rev()
        .find(|&s| area.estimate_text_size(text, &TextStyle::from((FONT, s).into_font())).is_ok_and(|(tw, _)| tw as usize <= width))
        .unwrap_or(8)
}

fn draw_labels(
    rgb: &mut [u8],
    size: (usize, usize),
    labels: &[String],
    row_tops: &[usize],
    column_lefts: [usize; 2],
    w: usize,
) -> std::result::Result<(), String> {
    let root = BitMapBackend::with_buffer(rgb, (size.0 as u32, size.1 as u32)).into_drawing_area();
    let fail = |e: DrawingAreaErrorKind<_>| e.to_string();
    let ink = RGBColor(235, 235, 235);
    let dim = RGBColor(190, 190, 190);
    for (title, x) in [("image (tone-mapped)", column_lefts[0]), ("error ×4 (heat map)", column_lefts[1])] {
        let s = fitting(&root, title, 15, w);
        root.draw(&Text::new(title.to_string(), (x as i32 + 2, 5), (FONT, s).into_font().color(&ink))).map_err(fail)?;
    }
    for (label, &top) in labels.iter().zip(row_tops) {
        for (i, line) in label.lines().enumerate() {
            let (want, colour) = if i == 0 { (16, ink) } else { (14, dim) };
            let s = fitting(&root, line, want, LABEL_WIDTH - 8);
            let y = (top + 4 + i * LINE) as i32;
            root.draw(&Text::new(line.to_string(), (6, y), (FONT, s).into_font().color(&colour))).map_err(fail)?;
        }
    }
    root.present().map_err(fail)
}

/// Writes the grid of `rows` (label, image), the reference first, to `path`; a label's lines are
/// separated by `\n`.
pub fn write_grid(path: &Path, reference: &RgbImage, rows: &[(String, RgbImage)]) -> Result<()> {
    let grid = compose(reference, rows)?;
    crate::io::write_srgb8(path, grid.width as u32, grid.height as u32, &grid.rgb)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flat(w: u32, h: u32, rgb: [f32; 3]) -> RgbImage {
        RgbImage { width: w, height: h, data: vec![rgb; (w * h) as usize] }
    }

    fn pixel(g: &Grid, x: usize, y: usize) -> [u8; 3] {
        let at = 3 * (y * g.width + x);
        [g.rgb[at], g.rgb[at + 1], g.rgb[at + 2]]
    }

    /// Pixels of the label column in `y0..y1` that differ from the background.
    fn ink(g: &Grid, y0: usize, y1: usize) -> Vec<(usize, usize)> {
        let bg = to_u8(BACKGROUND);
        (y0..y1).flat_map(|y| (0..LABEL_WIDTH).map(move |x| (x, y))).filter(|&(x, y)| pixel(g, x, y) != [bg; 3]).collect()
    }

    #[test]
    fn rows_are_labelled_in_the_order_given() -> Result<()> {
        if ensure_font().is_err() {
            eprintln!("no font: the label test needs one (fonts-dejavu-core)");
            return Ok(());
        }
        let (w, h) = (40, 30);
        let reference = flat(w, h, [0.5, 0.5, 0.5]);
        // Distinct colours, so each row's image says which row it is.
        let rows = vec![
            ("gather\nmax_coc=96\nPSNR 20.00 dB".to_string(), flat(w, h, [4.0, 0.0, 0.0])),
            ("multilayer\nmerge=4x4 tile=16\nPSNR 30.00 dB".to_string(), flat(w, h, [0.0, 4.0, 0.0])),
        ];
        let g = compose(&reference, &rows)?;
        assert!(g.labelled);
        // The label column and header make the grid larger than the bare images.
        assert!(g.width >= LABEL_WIDTH + 2 * w as usize, "{}", g.width);
        assert!(g.height >= HEADER_HEIGHT + 3 * h as usize, "{}", g.height);
        assert_eq!(g.row_tops.len(), 3);
        // Row order: the image column of row i + 1 shows row i's colour.
        for (i, want) in [[255u8, 0, 0], [0, 255, 0]].iter().enumerate() {
            let p = pixel(&g, g.column_lefts[0] + 5, g.row_tops[i + 1] + 5);
            let dominant = (0..3).max_by_key(|&c| p[c]).unwrap();
            assert!(p[dominant] > 200, "row {i}: {p:?}");
            assert_eq!(want[dominant], 255, "row {i} shows another row's image: {p:?}");
        }
        // Every row's label is drawn, inside its own row, and the labels differ.
        let inks: Vec<_> = g.row_tops.iter().map(|&t| ink(&g, t, t + h as usize)).collect();
        for (i, pixels) in inks.iter().enumerate() {
            assert!(pixels.len() > 50, "row {i} has {} label pixels", pixels.len());
        }
        assert_ne!(inks[1], inks[2]);
        // The header names the columns.
        let header = (0..HEADER_HEIGHT - 2).flat_map(|y| (g.column_lefts[0]..g.width).map(move |x| (x, y)));
        assert!(header.filter(|&(x, y)| pixel(&g, x, y) != [to_u8(BACKGROUND); 3]).count() > 50);
        Ok(())
    }

    #[test]
    fn mismatched_rows_are_refused() {
        let rows = vec![("a".to_string(), flat(4, 4, [0.0; 3]))];
        let e = compose(&flat(8, 8, [0.0; 3]), &rows).err().expect("a size mismatch is an error");
        assert!(e.to_string().contains("4x4"), "{e}");
    }
}
