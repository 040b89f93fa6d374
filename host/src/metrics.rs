//! Error of an image against its reference, measured on the documented display transform
//! ([`crate::io::tonemap::tonemap`] at exposure 1: ACES fit, then sRGB), as the evaluation reports it:
//! - PSNR in dB over the three display-encoded channels in [0, 1], in floating point; identical
//!   images give `+inf`;
//! - SSIM from the `image-compare` crate (its MSSIM: SSIM over 8x8 windows, per channel, averaged) on
//!   the 8-bit display encoding.
//!
//! - FLIP (LDR-FLIP through the `nv-flip` bindings to NVIDIA's reference implementation) on the
//!   same 8-bit display encoding, at the crate's default of 67 pixels per degree of visual angle:
//!   the mean of its per-pixel perceptual error in [0, 1], lower is better.
//!
//! All come full-frame and, given a mask, inside it (the partial-occlusion region): masked PSNR
//! averages the squared error over the masked pixels, masked SSIM averages the crate's SSIM map there
//! (which it exposes clamped to [0, 1] in 8 bits), masked FLIP averages FLIP's error map there.
//!
//! SSIM and FLIP ([`compare`], [`ImageError`]) need the `eval` feature; PSNR is always here.
#![cfg_attr(not(feature = "eval"), allow(rustdoc::broken_intra_doc_links))]

use crate::error::{Error, Result};
use crate::io::tonemap::tonemap;
#[cfg(feature = "eval")]
use crate::io::tonemap::tonemap_to_srgb8;
use crate::layers::RgbImage;
#[cfg(feature = "eval")]
use image_compare::prelude::RgbImage as Rgb8Image;

/// The error of one image against a reference.
#[cfg(feature = "eval")]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImageError {
    pub psnr_db: f64,
    pub ssim: f64,
    /// Inside the mask; `None` without a mask or when it selects no pixel.
    pub psnr_masked_db: Option<f64>,
    pub ssim_masked: Option<f64>,
    /// Mean FLIP error, full frame and inside the mask.
    pub flip: f64,
    pub flip_masked: Option<f64>,
    pub masked_pixels: u64,
}

fn check_sizes(a: &RgbImage, b: &RgbImage, mask: Option<&[bool]>) -> Result<()> {
    if (a.width, a.height) != (b.width, b.height) || a.data.len() != b.data.len() {
        return Err(Error::invalid(format!("cannot compare a {}x{} image with a {}x{} reference", a.width, a.height, b.width, b.height)));
    }
    if a.data.is_empty() {
        return Err(Error::invalid("cannot compare empty images".into()));
    }
    if let Some(m) = mask.filter(|m| m.len() != a.data.len()) {
        return Err(Error::invalid(format!("the mask has {} entries for {} pixels", m.len(), a.data.len())));
    }
    Ok(())
}

/// Squared display-space error of one pixel, summed over its channels.
#[inline]
pub fn squared_error(p: [f32; 3], q: [f32; 3]) -> f64 {
    let (p, q) = (tonemap(p, 1.0), tonemap(q, 1.0));
    (0..3).map(|c| (p[c] as f64 - q[c] as f64).powi(2)).sum()
}

/// PSNR (signal peak 1) of a mean squared error per channel; `+inf` for 0. An error of the whole
/// peak is 0 dB, never −0 (`+ 0.0` turns −0 into +0).
pub fn psnr_of_mse(mse: f64) -> f64 {
    if mse > 0.0 { -10.0 * mse.log10() + 0.0 } else { f64::INFINITY }
}

fn squared_errors(a: &RgbImage, b: &RgbImage) -> Vec<f64> {
    a.data.iter().zip(&b.data).map(|(&p, &q)| squared_error(p, q)).collect()
}

fn psnr_from(sum: f64, pixels: u64) -> f64 {
    psnr_of_mse(sum / (3 * pixels.max(1)) as f64)
}

/// PSNR of `image` against `reference` on the display transform.
pub fn psnr(image: &RgbImage, reference: &RgbImage) -> Result<f64> {
    check_sizes(image, reference, None)?;
    Ok(psnr_from(squared_errors(image, reference).iter().sum(), image.data.len() as u64))
}

#[cfg(feature = "eval")]
fn to_rgb8(image: &RgbImage) -> Rgb8Image {
    let bytes: Vec<u8> = image.data.iter().flat_map(|&p| tonemap_to_srgb8(p, 1.0)).collect();
    // The buffer has exactly width * height * 3 bytes, so construction cannot fail.
    Rgb8Image::from_raw(image.width, image.height, bytes).unwrap_or_else(|| Rgb8Image::new(image.width, image.height))
}

/// FLIP's per-pixel error map of `image` against `reference` (same size, checked by the caller).
#[cfg(feature = "eval")]
fn flip_map(image: &RgbImage, reference: &RgbImage) -> Vec<f32> {
    let bytes = |img: &RgbImage| -> Vec<u8> { img.data.iter().flat_map(|&p| tonemap_to_srgb8(p, 1.0)).collect() };
    let reference = nv_flip::FlipImageRgb8::with_data(reference.width, reference.height, &bytes(reference));
    let test = nv_flip::FlipImageRgb8::with_data(image.width, image.height, &bytes(image));
    nv_flip::flip(reference, test, nv_flip::DEFAULT_PIXELS_PER_DEGREE).to_vec()
}

/// PSNR, SSIM and FLIP of `image` against `reference`, full-frame and inside `mask` (row-major, one entry
/// per pixel). Feature `eval`.
#[cfg(feature = "eval")]
pub fn compare(image: &RgbImage, reference: &RgbImage, mask: Option<&[bool]>) -> Result<ImageError> {
    check_sizes(image, reference, mask)?;
    let squared = squared_errors(image, reference);
    let pixels = squared.len() as u64;
    let similarity = image_compare::rgb_similarity_structure(&image_compare::Algorithm::MSSIMSimple, &to_rgb8(image), &to_rgb8(reference))
        .map_err(|e| Error::invalid(format!("SSIM failed: {e}")))?;
    let flip_map = flip_map(image, reference);
    let mut result = ImageError {
        psnr_db: psnr_from(squared.iter().sum(), pixels),
        ssim: similarity.score,
        psnr_masked_db: None,
        ssim_masked: None,
        flip: flip_map.iter().map(|&e| e as f64).sum::<f64>() / pixels as f64,
        flip_masked: None,
        masked_pixels: 0,
    };
    if let Some(mask) = mask {
        let inside: Vec<usize> = (0..mask.len()).filter(|&i| mask[i]).collect();
        result.masked_pixels = inside.len() as u64;
        if !inside.is_empty() {
            result.psnr_masked_db = Some(psnr_from(inside.iter().map(|&i| squared[i]).sum(), inside.len() as u64));
            // The crate exposes its per-pixel SSIM map only as an 8-bit picture (values clamped to
            // [0, 1]), so the masked SSIM carries that quantisation (1/255).
            let map = similarity.image.to_color_map().to_rgb8();
            let w = image.width as usize;
            let sum: f64 = inside
                .iter()
                .map(|&i| {
                    let px = map.get_pixel((i % w) as u32, (i / w) as u32).0;
                    (px[0] as f64 + px[1] as f64 + px[2] as f64) / (3.0 * 255.0)
                })
                .sum();
            result.ssim_masked = Some(sum / inside.len() as f64);
            result.flip_masked = Some(inside.iter().map(|&i| flip_map[i] as f64).sum::<f64>() / inside.len() as f64);
        }
    }
    Ok(result)
}
