//! Renders depth of field with `dof` on the CPU backend, from a crate outside its workspace on
//! stable Rust: a hand-built two-layer image and a built-in analytic scene, each splatted with
//! multi-layer tiled splatting, checked against what they must give.

use dof::methods::splat::{SplatOptions, splat};
use dof::scene::{LayerOptions, ReferenceOptions, builtin, raycast_layers, reference};
use dof::{CpuBackend, Fragment, LayeredImage, RgbImage, ThinLens};

fn mean(image: &RgbImage) -> [f64; 3] {
    let mut sum = [0.0f64; 3];
    for p in &image.data {
        for c in 0..3 {
            sum[c] += p[c] as f64;
        }
    }
    sum.map(|s| s / image.data.len() as f64)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut cpu = CpuBackend::new();

    // By hand: a 64x64 image, grey background at depth 10 behind an orange square (alpha 1) at
    // depth 2, the lens focused on the background. The square blurs, but splatting conserves
    // energy away from the borders: the mean colour of the frame stays that of the input.
    let (w, h) = (64u32, 64u32);
    // 50 mm at 10 m with a 20 mm aperture, 20 000 px per metre on the sensor: the square's CoC is
    // 8 px across.
    let lens = ThinLens { focal_length: 0.05, aperture_radius: 0.01, focus_distance: 10.0, pixels_per_unit: 20_000.0 };
    println!("CoC of the square: {:.1} px", lens.coc_px(2.0));
    let mut image = LayeredImage::new(w, h, 2)?;
    let (square, background) = ([1.0, 0.5, 0.1], [0.2, 0.2, 0.2]);
    for y in 0..h {
        for x in 0..w {
            if (24..40).contains(&x) && (24..40).contains(&y) {
                image.push(x, y, Fragment { color: square, alpha: 1.0, depth: 2.0 })?;
            }
            image.push(x, y, Fragment { color: background, alpha: 1.0, depth: 10.0 })?;
        }
    }
    let out = splat(&mut cpu, &image, &lens, &SplatOptions::default())?;
    let input_mean = [0.2 + 0.0625 * 0.8, 0.2 + 0.0625 * 0.3, 0.2 - 0.0625 * 0.1];
    let m = mean(&out.image);
    println!(
        "hand-built 64x64, 2 layers: mean colour {:.4} {:.4} {:.4} (input {:.4} {:.4} {:.4})",
        m[0], m[1], m[2], input_mean[0], input_mean[1], input_mean[2]
    );
    for c in 0..3 {
        if (m[c] - input_mean[c]).abs() > 0.01 {
            return Err(format!("channel {c}: mean {} is not the input's {}", m[c], input_mean[c]).into());
        }
    }

    // A built-in analytic scene: its partial multi-layer image by ray casting, splatted, against
    // the exact thin-lens reference (distributed ray tracing).
    let scene = builtin("simple")?.with_size(160, 90);
    let lens = scene.lens.thin_lens(&scene.camera)?;
    let layers = raycast_layers(&scene.scene, &scene.camera, &lens, &LayerOptions::default())?;
    let out = splat(&mut cpu, &layers.layers, &lens, &SplatOptions::default())?;
    let image = layers.crop(&out.image);
    let exact = reference(&scene.scene, &scene.camera, &lens, &ReferenceOptions { spp: 64, ..Default::default() })?;
    let psnr = dof::metrics::psnr(&image, &exact.image)?;
    let m = mean(&image);
    println!("`simple` at 160x90: mean colour {:.4} {:.4} {:.4}, {:.1} dB PSNR against the exact reference", m[0], m[1], m[2], psnr);
    if !(psnr > 30.0) {
        return Err(format!("multi-layer splatting is only {psnr:.1} dB from the reference").into());
    }
    println!(
        "ok: {} SPIR-V modules embedded ({} bytes), kernel sources {}",
        dof::shaders::MODULES.len(),
        dof::shaders::total_bytes(),
        &dof::shaders::SOURCE_HASH[..12]
    );
    Ok(())
}
