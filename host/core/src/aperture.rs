//! Aperture shapes as the user names them, for the splatting methods and bokeh sprites: the circle,
//! n-blade polygons (analytic, `dof_shaders::aperture`), and masks: a star drawn here, or an image.
//!
//! `--aperture` accepts `circle`, `blades:N[:ROTATION_DEGREES[:CURVATURE]]`,
//! `star:N[:ROTATION_DEGREES[:INNER]]` (N points, the notches at `INNER` times the tips' radius,
//! default 0.5) or a PNG file. An image is centred in a square (letterboxed), box-filtered to at most
//! 128 texels a side, its luminance taken as coverage (8-bit values over 255, scaled so the brightest
//! texel is 1), and cleared outside its inscribed circle: the shape must fit the circle of the CoC
//! radius, which binning relies on. Shapes are as seen in the background (y down); the foreground
//! shows them point-reflected.

use crate::error::{Error, Result};
use dof_shaders::aperture::{Aperture, blades, masked};
#[cfg(feature = "png")]
use std::path::Path;

/// An aperture: the kernels' description and, for a mask, its texels.
#[derive(Clone, Debug, PartialEq)]
pub struct ApertureShape {
    pub kernel: Aperture,
    /// `kernel.mask²` coverage values, row-major; empty for the analytic shapes.
    pub mask: Vec<f32>,
}

/// Side of the star's mask, and its supersampling per texel side.
const STAR_SIDE: u32 = 96;
const STAR_SAMPLES: u32 = 4;
/// Largest side of an image mask.
#[cfg(feature = "png")]
const MAX_IMAGE_SIDE: u32 = 128;
/// Shortest longer side of an aperture image: the mask needs at least 2x2 texels.
#[cfg(feature = "png")]
const MIN_IMAGE_SIDE: u32 = 2;

impl ApertureShape {
    pub fn circle() -> Self {
        ApertureShape { kernel: Aperture::circle(), mask: Vec::new() }
    }

    /// Checks that the description is one the kernels can run (its fields are public, so a shape
    /// built by hand may not be): the circle, 3 to 64 blades with a curvature in [0, 1], or a mask
    /// of 2 to 512 texels a side holding `side²` coverages in [0, 1]; every number finite.
    pub fn check(&self) -> Result<()> {
        let k = &self.kernel;
        let finite = [k.curvature, k.normal[0], k.normal[1], k.step[0], k.step[1], k.inv_inradius, k.area].iter().all(|v| v.is_finite());
        let analytic = k.mask == 0
            && self.mask.is_empty()
            && (k.blades == 0 || (3..=64).contains(&k.blades))
            && (0.0..=1.0).contains(&k.curvature)
            && k.inv_inradius >= 1.0;
        let side = k.mask as u64;
        let masked = k.blades == 0
            && (2..=512).contains(&k.mask)
            && self.mask.len() as u64 == side * side
            && self.mask.iter().all(|v| (0.0..=1.0).contains(v));
        if finite && k.area > 0.0 && (analytic || masked) {
            Ok(())
        } else {
            Err(Error::InvalidArgument(format!(
                "an aperture the kernels cannot run: {} blades, a mask of side {} with {} texels, curvature {}, area {}                  (use ApertureShape::circle, parse_aperture or image_aperture)",
                k.blades,
                k.mask,
                self.mask.len(),
                k.curvature,
                k.area
            )))
        }
    }

    /// The mask as buffer words (one zero word for the analytic shapes, so there is always a buffer
    /// to bind).
    pub fn mask_words(&self) -> Vec<u32> {
        if self.mask.is_empty() { vec![0] } else { self.mask.iter().map(|v| v.to_bits()).collect() }
    }
}

impl Default for ApertureShape {
    fn default() -> Self {
        Self::circle()
    }
}

fn syntax(text: &str) -> Error {
    Error::InvalidArgument(format!(
        "unknown aperture `{text}`: use `circle`, `blades:N[:ROTATION_DEGREES[:CURVATURE]]` (3 to 64 blades, curvature 0 to 1), \
         `star:N[:ROTATION_DEGREES[:INNER]]` (3 to 32 points, inner radius 0.05 to 0.95) or a PNG file"
    ))
}

/// Parses `--aperture` (see the module notes).
pub fn parse_aperture(text: &str) -> Result<ApertureShape> {
    if text == "circle" {
        return Ok(ApertureShape::circle());
    }
    let numbers = |rest: &str| -> Result<(u32, f32, Option<f32>)> {
        let parts: Vec<&str> = rest.split(':').collect();
        if parts.len() > 3 {
            return Err(syntax(text));
        }
        let n = parts[0].parse().map_err(|_| syntax(text))?;
        let rotation = parts.get(1).map_or(Ok(0.0), |v| v.parse()).map_err(|_| syntax(text))?;
        let third = parts.get(2).map(|v| v.parse()).transpose().map_err(|_| syntax(text))?;
        Ok((n, rotation, third))
    };
    if let Some(rest) = text.strip_prefix("blades:") {
        let (n, rotation, curvature) = numbers(rest)?;
        let kernel = blades(n, rotation.to_radians(), curvature.unwrap_or(0.0)).ok_or_else(|| syntax(text))?;
        return Ok(ApertureShape { kernel, mask: Vec::new() });
    }
    if let Some(rest) = text.strip_prefix("star:") {
        let (n, rotation, inner) = numbers(rest)?;
        return star(n, rotation.to_radians(), inner.unwrap_or(0.5)).ok_or_else(|| syntax(text));
    }
    if text.to_ascii_lowercase().ends_with(".png") {
        #[cfg(feature = "png")]
        return image_aperture(Path::new(text));
        #[cfg(not(feature = "png"))]
        return Err(Error::InvalidArgument(format!(
            "aperture image {text}: reading PNG files needs the `png` feature of dof-core (the `exr` feature of dof)"
        )));
    }
    Err(syntax(text))
}

/// Whether `(x, y)` lies inside the polygon (even-odd rule; any simple polygon, convex or not).
fn inside(x: f64, y: f64, poly: &[(f64, f64)]) -> bool {
    let mut odd = false;
    let mut j = poly.len() - 1;
    for i in 0..poly.len() {
        let ((xi, yi), (xj, yj)) = (poly[i], poly[j]);
        if (yi > y) != (yj > y) && x < xi + (y - yi) / (yj - yi) * (xj - xi) {
            odd = !odd;
        }
        j = i;
    }
    odd
}

/// An `n`-point star with its tips on the unit circle (the first at `rotation`) and its notches at
/// `inner` times that radius, as a supersampled mask.
pub fn star(n: u32, rotation: f32, inner: f32) -> Option<ApertureShape> {
    if !(3..=32).contains(&n) || !(0.05..=0.95).contains(&inner) || !rotation.is_finite() {
        return None;
    }
    let poly: Vec<(f64, f64)> = (0..2 * n)
        .map(|k| {
            let a = rotation as f64 + k as f64 * std::f64::consts::PI / n as f64;
            let r = if k % 2 == 0 { 1.0 } else { inner as f64 };
            (r * a.cos(), r * a.sin())
        })
        .collect();
    let side = STAR_SIDE;
    let mut mask = vec![0.0f32; (side * side) as usize];
    for ty in 0..side {
        for tx in 0..side {
            let mut hits = 0;
            for sy in 0..STAR_SAMPLES {
                for sx in 0..STAR_SAMPLES {
                    let x = -1.0 + 2.0 * (tx as f64 + (sx as f64 + 0.5) / STAR_SAMPLES as f64) / side as f64;
                    let y = -1.0 + 2.0 * (ty as f64 + (sy as f64 + 0.5) / STAR_SAMPLES as f64) / side as f64;
                    hits += inside(x, y, &poly) as u32;
                }
            }
            mask[(ty * side + tx) as usize] = hits as f32 / (STAR_SAMPLES * STAR_SAMPLES) as f32;
        }
    }
    let kernel = masked(side, &mask)?;
    Some(ApertureShape { kernel, mask })
}

/// An aperture from a PNG (see the module notes; feature `png`).
#[cfg(feature = "png")]
pub fn image_aperture(path: &Path) -> Result<ApertureShape> {
    let bad = |why: String| Error::InvalidArgument(format!("aperture image {}: {why}", path.display()));
    let bytes = std::fs::read(path).map_err(|e| bad(format!("cannot read it ({e})")))?;
    let mut decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = decoder.read_info().map_err(|e| bad(format!("not a readable PNG ({e})")))?;
    // A palette the png crate (0.18) expands without checking: its length must be whole RGB
    // entries, at most 256 of them, with at most one alpha per entry (a 14-byte palette panicked
    // inside its expansion; found by the aperture_png fuzz target).
    if let Some(palette) = &reader.info().palette {
        let entries = palette.len() / 3;
        if palette.is_empty() || palette.len() % 3 != 0 || entries > 256 {
            return Err(bad(format!("its palette of {} bytes is not 1 to 256 RGB entries", palette.len())));
        }
        if let Some(trns) = reader.info().trns.as_ref().filter(|t| t.len() > entries) {
            return Err(bad(format!("its transparency chunk has {} entries for a palette of {entries}", trns.len())));
        }
    }
    // The size from the header, before the pixels are allocated.
    let usable = |w: u32, h: u32| (1..=8192).contains(&w) && (1..=8192).contains(&h);
    let (w, h) = reader.info().size();
    if !usable(w, h) {
        return Err(bad(format!("{w}x{h} is not a usable size (1 to 8192 a side)")));
    }
    let mut buf = vec![0u8; reader.output_buffer_size().ok_or_else(|| bad("too large".into()))?];
    let info = reader.next_frame(&mut buf).map_err(|e| bad(format!("not a readable PNG ({e})")))?;
    let (w, h) = (info.width, info.height);
    let channels = info.color_type.samples();
    if !usable(w, h) {
        return Err(bad(format!("{w}x{h} is not a usable size (1 to 8192 a side)")));
    }
    let luminance = |x: u32, y: u32| -> f32 {
        let p = &buf[((y * w + x) as usize) * channels..][..channels];
        let v = match channels {
            1 | 2 => p[0] as f32,
            _ => 0.2126 * p[0] as f32 + 0.7152 * p[1] as f32 + 0.0722 * p[2] as f32,
        };
        let alpha = if channels == 2 || channels == 4 { p[channels - 1] as f32 / 255.0 } else { 1.0 };
        v / 255.0 * alpha
    };
    // Letterbox into a square, then box-filter down to at most MAX_IMAGE_SIDE.
    let square = w.max(h);
    if square < MIN_IMAGE_SIDE {
        return Err(bad(format!(
            "{w}x{h} is below the minimum size: its longer side must be at least {MIN_IMAGE_SIDE} pixels \
             (the mask is sampled as a square of {MIN_IMAGE_SIDE} to {MAX_IMAGE_SIDE} texels a side)"
        )));
    }
    let side = square.min(MAX_IMAGE_SIDE);
    let (ox, oy) = ((square - w) / 2, (square - h) / 2);
    let mut mask = vec![0.0f32; (side * side) as usize];
    for sy in 0..square {
        for sx in 0..square {
            let (x, y) = (sx as i64 - ox as i64, sy as i64 - oy as i64);
            if x >= 0 && y >= 0 && (x as u32) < w && (y as u32) < h {
                let t = ((sy as u64 * side as u64 / square as u64) * side as u64 + sx as u64 * side as u64 / square as u64) as usize;
                mask[t] += luminance(x as u32, y as u32);
            }
        }
    }
    let per_texel = (square as f32 / side as f32).powi(2);
    for (t, v) in mask.iter_mut().enumerate() {
        let (tx, ty) = ((t as u32 % side) as f32 + 0.5, (t as u32 / side) as f32 + 0.5);
        let (u, v2) = (2.0 * tx / side as f32 - 1.0, 2.0 * ty / side as f32 - 1.0);
        *v = if u * u + v2 * v2 <= 1.0 { *v / per_texel } else { 0.0 };
    }
    let peak = mask.iter().fold(0.0f32, |m, &v| m.max(v));
    if !(peak > 0.0) {
        return Err(bad("it is black inside its inscribed circle: nothing would pass the aperture".into()));
    }
    mask.iter_mut().for_each(|v| *v = (*v / peak).clamp(0.0, 1.0));
    let kernel = masked(side, &mask)
        .ok_or_else(|| bad(format!("not a usable mask: its {side}x{side} coverage has no area or values outside [0, 1]")))?;
    Ok(ApertureShape { kernel, mask })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn star_area_and_containment() {
        let s = star(5, 0.0, 0.5).unwrap();
        // The area of a star polygon: n triangles (centre, tip, notch) twice.
        let expected = 2.0 * 5.0 * 0.5 * 1.0 * 0.5 * (std::f32::consts::PI / 5.0).sin();
        assert!((s.kernel.area - expected).abs() < 0.02 * expected, "{} vs {expected}", s.kernel.area);
        let side = s.kernel.mask;
        for (t, &v) in s.mask.iter().enumerate() {
            let (x, y) = ((t as u32 % side) as f32 + 0.5, (t as u32 / side) as f32 + 0.5);
            let (u, w) = (2.0 * x / side as f32 - 1.0, 2.0 * y / side as f32 - 1.0);
            assert!(v == 0.0 || u * u + w * w <= 1.05, "texel {t} outside the unit circle");
        }
        assert!(star(2, 0.0, 0.5).is_none() && star(5, 0.0, 1.0).is_none());
    }
}
