//! The gathering baseline: exact in the stiff cases, the same on both backends, and measured against
//! the exact reference of a built-in scene.

use dof::backend::CpuBackend;
use dof::layers::RgbImage;
use dof::methods::gather::{MAX_RADIUS, gather};
use dof::metrics::compare;
use dof::scene::{LayerOptions, ReferenceOptions, builtin, raycast_layers, reference};
use dof_shaders::lens::ThinLens;
use dof_tests::{assert_clean, noise_image, vulkan};

fn lens(aperture_radius: f32) -> ThinLens {
    ThinLens { focal_length: 0.05, aperture_radius, focus_distance: 2.0, pixels_per_unit: 8000.0 }
}

#[test]
fn pinhole_returns_the_input_exactly() {
    let (img, depth) = noise_image(37, 21);
    let out = gather(&mut CpuBackend::new(), &img, &depth, &lens(0.0), None).unwrap();
    assert_eq!(out.radius, 0);
    assert_eq!(out.image, img);
}

#[test]
fn a_flat_field_stays_flat() {
    let (mut img, depth) = noise_image(40, 30);
    img.data.iter_mut().for_each(|p| *p = [0.25, 3.0, 1200.0]);
    let out = gather(&mut CpuBackend::new(), &img, &depth, &lens(0.02), Some(12)).unwrap();
    assert!(out.radius > 0);
    for p in &out.image.data {
        for c in 0..3 {
            assert!((p[c] - img.data[0][c]).abs() <= 1e-5 * img.data[0][c], "{p:?}");
        }
    }
}

#[test]
fn nan_and_inf_pixels_do_not_spread() {
    let (mut img, mut depth) = noise_image(33, 33);
    img.data[16 * 33 + 16] = [f32::NAN, 1.0, 1.0];
    img.data[5 * 33 + 5] = [f32::INFINITY, 1.0, 1.0];
    depth[20 * 33 + 3] = f32::NAN;
    let out = gather(&mut CpuBackend::new(), &img, &depth, &lens(0.02), Some(8)).unwrap();
    assert!(out.image.data.iter().all(|p| p.iter().all(|c| c.is_finite())));
}

#[test]
fn bad_input_is_an_error() {
    let (img, depth) = noise_image(8, 8);
    let mut cpu = CpuBackend::new();
    assert!(gather(&mut cpu, &img, &depth[1..], &lens(0.01), None).is_err());
    assert!(gather(&mut cpu, &img, &depth, &lens(-1.0), None).is_err());
    assert!(gather(&mut cpu, &img, &depth, &lens(0.01), Some(MAX_RADIUS + 1)).is_err());
}

#[test]
fn vulkan_matches_cpu() {
    let Some(mut vk) = vulkan() else { return };
    let (img, depth) = noise_image(45, 27);
    let on_vk = gather(&mut vk, &img, &depth, &lens(0.02), Some(10)).unwrap();
    assert_clean(&mut vk);
    let on_cpu = gather(&mut CpuBackend::new(), &img, &depth, &lens(0.02), Some(10)).unwrap();
    assert_eq!(on_vk.radius, on_cpu.radius);
    // Same operations in the same order; a driver may still contract a*b+c into an FMA.
    for (a, b) in on_vk.image.data.iter().zip(&on_cpu.image.data) {
        for c in 0..3 {
            assert!((a[c] - b[c]).abs() <= 1e-5 * b[c].abs().max(1e-3), "{a:?} vs {b:?}");
        }
    }
    assert!(on_vk.times.iter().any(|t| t.label == "gather"));
}

/// On `simple` at 160x90 the gather is closer to the exact reference than the unblurred image, full
/// frame and inside the partial-occlusion region. Measured: pinhole 29.8 dB (18.7 dB in the region),
/// gather 32.5 dB (21.3 dB); the bounds sit just under those margins.
#[test]
fn gather_against_the_exact_reference() {
    let scene = builtin("simple").unwrap().with_size(160, 90);
    let lens = scene.thin_lens().unwrap();
    let layers = raycast_layers(&scene.scene, &scene.camera, &lens, &LayerOptions::default()).unwrap();
    let (front, depth) = layers.layers.front();
    let exact = reference(&scene.scene, &scene.camera, &lens, &ReferenceOptions { spp: 256, ..Default::default() }).unwrap();
    let blurred = layers.crop(&gather(&mut CpuBackend::new(), &front, &depth, &lens, None).unwrap().image);
    let sharp = compare(&layers.front().0, &exact.image, Some(&layers.mask)).unwrap();
    let gathered = compare(&blurred, &exact.image, Some(&layers.mask)).unwrap();
    eprintln!("pinhole {sharp:?}\ngather  {gathered:?}");
    assert!(gathered.psnr_db > sharp.psnr_db + 2.0, "gather {gathered:?} vs pinhole {sharp:?}");
    assert!(gathered.psnr_masked_db.unwrap() > sharp.psnr_masked_db.unwrap() + 2.0);
    assert!(gathered.ssim > sharp.ssim && gathered.ssim_masked.unwrap() > sharp.ssim_masked.unwrap());
}

/// Extreme sizes and blur: a 1x1 image is returned as is; sizes that are not multiples of the 8x8
/// tile are covered to the last pixel; a CoC far beyond the window is capped, not an error.
#[test]
fn extreme_sizes_and_blur() {
    let mut cpu = CpuBackend::new();
    let one = RgbImage { width: 1, height: 1, data: vec![[0.5, 2.0, 7.0]] };
    let out = gather(&mut cpu, &one, &[3.0], &lens(0.05), None).unwrap();
    assert_eq!(out.image, one);

    let (img, depth) = noise_image(17, 5);
    let out = gather(&mut cpu, &img, &depth, &lens(0.0), None).unwrap();
    assert_eq!(out.image, img, "every pixel of a 17x5 image, including the last column and row");

    // Focus at 2 m, everything at 0.1 m: a CoC of thousands of pixels, capped at the window.
    let (img, _) = noise_image(24, 24);
    let near = vec![0.1f32; 24 * 24];
    let out = gather(&mut cpu, &img, &near, &lens(0.05), Some(6)).unwrap();
    assert_eq!(out.radius, 6);
    assert!(out.image.data.iter().all(|p| p.iter().all(|c| c.is_finite())));
}
