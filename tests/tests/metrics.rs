//! Error metrics against a reference.

use dof::io::tonemap::tonemap;
use dof::layers::RgbImage;
use dof::metrics::{compare, psnr};

fn gradient(w: u32, h: u32) -> RgbImage {
    let mut img = RgbImage::new(w, h);
    for y in 0..h {
        for x in 0..w {
            let i = img.index(x, y);
            img.data[i] = [x as f32 / w as f32, y as f32 / h as f32, 0.25];
        }
    }
    img
}

#[test]
fn identical_images_are_perfect() {
    let a = gradient(40, 24);
    let e = compare(&a, &a, Some(&vec![true; 40 * 24])).unwrap();
    assert_eq!(e.psnr_db, f64::INFINITY);
    assert!((e.ssim - 1.0).abs() < 1e-9, "{}", e.ssim);
    assert_eq!(e.psnr_masked_db, Some(f64::INFINITY));
    assert!((e.ssim_masked.unwrap() - 1.0).abs() < 1e-9);
    assert_eq!((e.flip, e.flip_masked), (0.0, Some(0.0)));
}

#[test]
fn psnr_is_measured_on_the_display_transform() {
    let a = gradient(32, 16);
    let mut b = a.clone();
    b.data[0] = [4.0, 4.0, 4.0];
    let (p, q) = (tonemap(a.data[0], 1.0), tonemap(b.data[0], 1.0));
    let sum: f64 = (0..3).map(|c| (p[c] as f64 - q[c] as f64).powi(2)).sum();
    let expected = -10.0 * (sum / (3.0 * 32.0 * 16.0)).log10();
    assert!((psnr(&b, &a).unwrap() - expected).abs() < 1e-9);
}

#[test]
fn the_mask_selects_the_region() {
    let a = gradient(32, 32);
    let mut b = a.clone();
    // Damage only the left half; a mask on the right half sees a perfect image.
    for y in 0..32 {
        for x in 0..16 {
            let i = b.index(x, y);
            b.data[i] = [0.9, 0.1, 0.7];
        }
    }
    let right: Vec<bool> = (0..32 * 32).map(|i| i % 32 >= 16).collect();
    let left: Vec<bool> = right.iter().map(|m| !m).collect();
    let on_right = compare(&b, &a, Some(&right)).unwrap();
    let on_left = compare(&b, &a, Some(&left)).unwrap();
    assert_eq!(on_right.psnr_masked_db, Some(f64::INFINITY));
    assert!(on_left.psnr_masked_db.unwrap() < on_left.psnr_db, "the damage is concentrated in the left half");
    assert!(on_left.ssim_masked.unwrap() < on_right.ssim_masked.unwrap());
    // FLIP: clearly visible damage on the left; the right half is only touched near the seam.
    assert!(on_left.flip_masked.unwrap() > 0.2 && on_left.flip_masked.unwrap() > 5.0 * on_right.flip_masked.unwrap());
    assert!((on_left.flip - (on_left.flip_masked.unwrap() + on_right.flip_masked.unwrap()) / 2.0).abs() < 1e-6);
    let none = compare(&b, &a, Some(&vec![false; 32 * 32])).unwrap();
    assert_eq!((none.psnr_masked_db, none.ssim_masked, none.masked_pixels), (None, None, 0));
}

#[test]
fn mismatched_inputs_are_errors() {
    let a = gradient(8, 8);
    assert!(compare(&a, &gradient(8, 9), None).is_err());
    assert!(compare(&a, &a, Some(&[true; 3])).is_err());
}

/// An image as far as can be from its reference (a sky at 3e38 against black) scores 0 dB, printed
/// as 0.00 and written to JSON as 0, never −0.
#[test]
fn the_largest_error_is_zero_db_not_minus_zero() {
    let sky = RgbImage { width: 4, height: 2, data: vec![[3e38; 3]; 8] };
    let black = RgbImage { width: 4, height: 2, data: vec![[0.0; 3]; 8] };
    let p = psnr(&black, &sky).unwrap();
    assert!(p == 0.0 && p.is_sign_positive(), "{p}");
    assert_eq!(format!("{p:.2}"), "0.00");
    assert!(dof::metrics::psnr_of_mse(1.0).is_sign_positive());
}
