//! Bokeh sprites (de Rousiers and Pettineo): the graphics pipeline on Vulkan against its compute fallback on the
//! CPU, no highlights, more highlights than the buffer holds, energy kept, bad options refused.

use dof::CoreError;
use dof::aperture::parse_aperture;
use dof::backend::{Backend, CpuBackend};
use dof::layers::RgbImage;
use dof::methods::bokeh::{BokehOptions, BokehOutput, bokeh};
use dof::methods::gather::gather;
use dof::scene::{LayerOptions, builtin, raycast_layers};
use dof::stress::test_lens;
use dof_shaders::lens::ThinLens;
use dof_tests::{assert_clean, vulkan};

/// `highlights` at 160x90 with a wide aperture: dozens of emitters, CoC radii to ~9 px.
fn highlights() -> (RgbImage, Vec<f32>, ThinLens) {
    let mut scene = builtin("highlights").unwrap().with_size(160, 90);
    scene.lens.aperture = dof::scene::Aperture::Radius(0.15);
    let lens = scene.thin_lens().unwrap();
    let (front, depth) = raycast_layers(&scene.scene, &scene.camera, &lens, &LayerOptions::default()).unwrap().layers.front();
    (front, depth, lens)
}

fn run(backend: &mut dyn Backend, img: &RgbImage, depth: &[f32], lens: &ThinLens, options: &BokehOptions) -> BokehOutput {
    bokeh(backend, img, depth, lens, options).unwrap()
}

fn total(img: &RgbImage) -> f64 {
    img.data.iter().flatten().map(|&v| v as f64).sum()
}

#[test]
fn the_sprite_draw_on_vulkan_matches_its_cpu_fallback() {
    let Some(mut vk) = vulkan() else { return };
    let (img, depth, lens) = highlights();
    for shape in ["circle", "blades:6:10", "blades:5:0:0.3", "star:6:0:0.4"] {
        let options = BokehOptions { aperture: parse_aperture(shape).unwrap(), ..Default::default() };
        let cpu = run(&mut CpuBackend::new(), &img, &depth, &lens, &options);
        let gpu = run(&mut vk, &img, &depth, &lens, &options);
        assert_clean(&mut vk);
        assert!(cpu.detected > 10 && cpu.detected == gpu.detected, "{shape}: {} and {} sprites", cpu.detected, gpu.detected);
        let peak = cpu.image.data.iter().flatten().fold(0.0f32, |m, &v| m.max(v));
        let worst = cpu.image.data.iter().flatten().zip(gpu.image.data.iter().flatten()).map(|(a, b)| (a - b).abs()).fold(0.0f32, f32::max);
        eprintln!("{shape}: {} sprites, largest difference {worst:.3e} of a peak {peak:.3e}", cpu.detected);
        // The rasteriser interpolates the offset the fallback computes; they agree to rounding.
        assert!(worst <= 1e-4 * peak, "{shape}: {worst} against a peak of {peak}");
        // Sprite slots come from a scan, not from the order the atomics happen to give.
        assert_eq!(run(&mut vk, &img, &depth, &lens, &options).image.data, gpu.image.data, "{shape}: two Vulkan runs differ");
        assert_eq!(run(&mut CpuBackend::new(), &img, &depth, &lens, &options).image.data, cpu.image.data, "{shape}: two CPU runs differ");
    }
}

#[test]
fn without_highlights_it_is_the_gather() {
    let (img, depth, lens) = highlights();
    let options = BokehOptions { lum_threshold: 1e9, ..Default::default() };
    let mut cpu = CpuBackend::new();
    let out = run(&mut cpu, &img, &depth, &lens, &options);
    assert_eq!(out.detected, 0);
    assert_eq!(out.image.data, gather(&mut cpu, &img, &depth, &lens, None).unwrap().image.data);
}

#[test]
fn more_highlights_than_the_buffer_holds_are_counted_and_kept_in_the_blur() {
    let (img, depth, lens) = highlights();
    let mut backends: Vec<Box<dyn Backend>> = vec![Box::new(CpuBackend::new())];
    if let Some(vk) = vulkan() {
        backends.push(Box::new(vk));
    }
    for b in backends.iter_mut() {
        let all = run(b.as_mut(), &img, &depth, &lens, &BokehOptions::default());
        let few = run(b.as_mut(), &img, &depth, &lens, &BokehOptions { capacity: 4, ..Default::default() });
        assert_eq!(few.detected, all.detected);
        assert_eq!(few.overflow, all.detected - 4);
        assert!(few.image.data.iter().flatten().all(|v| v.is_finite()));
        // Left in the blur, an overflowing highlight is not lost: the totals differ only by what the
        // gather's per-pixel normalisation does to a highlight's energy (4.0% measured here, where
        // the sprites keep it exactly).
        let (a, f) = (total(&all.image), total(&few.image));
        assert!((a - f).abs() <= 0.05 * a, "{}: {a} vs {f}", b.device_name());
        assert!(b.take_diagnostics().is_empty());
    }
}

#[test]
fn a_highlight_keeps_its_energy() {
    // One bright pixel on a dark plane at one depth: the plane's blur stays flat, so what the output
    // holds above the plane is the sprite, which must spread exactly the pixel's excess.
    let (w, h) = (48u32, 40u32);
    let lens = test_lens(0.1);
    let z = lens.inverse_px(16.0).1;
    let mut img = RgbImage { width: w, height: h, data: vec![[0.1; 3]; (w * h) as usize] };
    img.data[(20 * w + 24) as usize] = [500.0; 3];
    let depth = vec![z; (w * h) as usize];
    let out = run(&mut CpuBackend::new(), &img, &depth, &lens, &BokehOptions::default());
    assert_eq!(out.detected, 1);
    let above: f64 = out.image.data.iter().map(|p| p[0] as f64 - 0.1).sum();
    assert!((above - 499.9).abs() < 0.01 * 499.9, "{above}");
}

#[test]
fn against_the_exact_reference_it_keeps_the_gathers_error() {
    // With the gather underneath and a circular aperture, sprites move energy from the blur to
    // discs of the same size: the error against the exact reference stays the gather's.
    for name in ["highlights", "simple"] {
        let scene = builtin(name).unwrap().with_size(320, 180);
        let lens = scene.thin_lens().unwrap();
        let ml = raycast_layers(&scene.scene, &scene.camera, &lens, &LayerOptions::default()).unwrap();
        let exact =
            dof::scene::reference(&scene.scene, &scene.camera, &lens, &dof::scene::ReferenceOptions { spp: 256, ..Default::default() })
                .unwrap();
        let (front, depth) = ml.layers.front();
        let mut cpu = CpuBackend::new();
        let err = |img: &RgbImage| dof::metrics::compare(&ml.crop(img), &exact.image, Some(&ml.mask)).unwrap();
        let b = err(&run(&mut cpu, &front, &depth, &lens, &BokehOptions::default()).image);
        let g = err(&gather(&mut cpu, &front, &depth, &lens, None).unwrap().image);
        eprintln!(
            "{name} 320x180: bokeh {:.2} dB ({:?} region), gather {:.2} dB ({:?} region)",
            b.psnr_db, b.psnr_masked_db, g.psnr_db, g.psnr_masked_db
        );
        assert!(b.psnr_db >= g.psnr_db - 0.05, "{name}: {} vs {}", b.psnr_db, g.psnr_db);
    }
}

#[test]
fn bad_options_are_errors() {
    let (img, depth, lens) = highlights();
    let bad = [
        BokehOptions { lum_threshold: f32::NAN, ..Default::default() },
        BokehOptions { coc_threshold: -1.0, ..Default::default() },
        BokehOptions { capacity: 0, ..Default::default() },
        BokehOptions { max_radius: 0.0, ..Default::default() },
    ];
    for options in bad {
        let err = bokeh(&mut CpuBackend::new(), &img, &depth, &lens, &options).err().expect("an error");
        assert!(matches!(err, CoreError::InvalidArgument(_)), "{err}");
    }
    assert!(bokeh(&mut CpuBackend::new(), &img, &depth[1..], &lens, &BokehOptions::default()).is_err());
}

#[test]
fn stage_timestamps_survive_a_draw() {
    // Once a framebuffer is bound, lavapipe takes timestamps when it next flushes its binned scene;
    // the recorder forces that flush, or every later stage would time as zero. A check of the
    // instrumentation, not of speed: the bound is a factor of 5 where the fault gave 300.
    let Some(mut vk) = vulkan() else { return };
    let (img, depth, lens) = highlights();
    let ms =
        |vk: &mut dof::backend::VulkanBackend| -> f64 { gather(vk, &img, &depth, &lens, None).unwrap().times.iter().map(|t| t.ms).sum() };
    let before = (0..3).map(|_| ms(&mut vk)).fold(f64::INFINITY, f64::min);
    run(&mut vk, &img, &depth, &lens, &BokehOptions::default());
    let after = (0..3).map(|_| ms(&mut vk)).fold(f64::INFINITY, f64::min);
    assert!(after > 0.2 * before, "the gather timed {before:.3} ms before a draw and {after:.3} ms after");
    assert_clean(&mut vk);
}
