//! Thin-lens ray tracing through the multi-layer image: exact where the geometry says it must be,
//! Vulkan against the CPU backend, convergence with rays per pixel against the exact reference, and
//! bad options refused.

use dof::CoreError;
use dof::backend::{Backend, CpuBackend};
use dof::frame::RaytraceReport;
use dof::layers::LayeredImage;
use dof::methods::gather::gather;
use dof::metrics::compare;
use dof::scene::{LayerOptions, ReferenceOptions, builtin, raycast_layers, reference};
use dof::stress::{noise_image, noise_with_sky, test_lens};
use dof_shaders::lens::ThinLens;
use dof_tests::oracle::raytrace::{RaytraceOptions, RaytraceOutput, raytrace};
use dof_tests::{assert_clean, vulkan};

fn trace(backend: &mut dyn Backend, img: &LayeredImage, lens: &ThinLens, spp: u32) -> RaytraceOutput {
    raytrace(backend, img, lens, &RaytraceOptions { spp, ..Default::default() }).unwrap()
}

/// The front layer as the pinhole sees it (sky black).
fn front(img: &LayeredImage) -> Vec<[f32; 3]> {
    img.front().0.data
}

#[test]
fn pinhole_and_sub_half_pixel_blur_return_the_front_layer_bit_for_bit() {
    let img = noise_with_sky(37, 29, 3);
    // Every ray of a pixel stays inside it while the CoC radius is under half a pixel, and the mean
    // of equal colours is that colour exactly.
    let largest = dof::eval::sweep::max_coc_radius(&img, &test_lens(1.0));
    let small = test_lens(0.49 / largest as f32);
    for lens in [test_lens(0.0), small] {
        let mut cpu = CpuBackend::new();
        let out = trace(&mut cpu, &img, &lens, 16);
        assert_eq!(out.image.data, front(&img), "aperture {}", lens.aperture_radius);
        assert_eq!(out.missed_rays, 0);
        if let Some(mut vk) = vulkan() {
            assert_eq!(trace(&mut vk, &img, &lens, 16).image.data, front(&img), "Vulkan, aperture {}", lens.aperture_radius);
            assert_clean(&mut vk);
        }
    }
}

#[test]
fn one_colour_stays_one_colour() {
    // Whatever fragment a ray hits or falls back to, it has the same colour; the sky is left out.
    let colour = [0.25, 3.0, 1200.0];
    let img = noise_image(41, 23, 3, |_| colour);
    let out = trace(&mut CpuBackend::new(), &img, &test_lens(0.01), 16);
    for p in &out.image.data {
        for c in 0..3 {
            assert!((p[c] - colour[c]).abs() <= 1e-6 * colour[c], "{p:?}");
        }
    }
}

#[test]
fn non_finite_input_is_never_hit() {
    let mut img = noise_with_sky(29, 17, 3);
    for (i, f) in img.fragments.iter_mut().enumerate() {
        match i % 11 {
            0 => f.color[1] = f32::NAN,
            3 => f.color[0] = f32::INFINITY,
            5 => f.depth = f32::NAN,
            7 => f.depth = -1.0,
            _ => {}
        }
    }
    let mut cpu = CpuBackend::new();
    let out = trace(&mut cpu, &img, &test_lens(0.01), 8);
    assert!(out.image.data.iter().flatten().all(|c| c.is_finite()));
    if let Some(mut vk) = vulkan() {
        assert!(trace(&mut vk, &img, &test_lens(0.01), 8).image.data.iter().flatten().all(|c| c.is_finite()), "Vulkan");
        assert_clean(&mut vk);
    }
}

#[test]
fn vulkan_traces_the_same_rays_as_the_cpu() {
    let Some(mut vk) = vulkan() else { return };
    let scene = builtin("railing").unwrap().with_size(160, 90);
    let lens = scene.thin_lens().unwrap();
    let layers = raycast_layers(&scene.scene, &scene.camera, &lens, &LayerOptions::default()).unwrap().layers;
    let cpu = trace(&mut CpuBackend::new(), &layers, &lens, 16);
    let gpu = trace(&mut vk, &layers, &lens, 16);
    assert_clean(&mut vk);
    // The same rays and the same arithmetic; a ray grazing a pixel corner may still go either way
    // where the two backends round a division differently.
    let differing =
        cpu.image.data.iter().zip(&gpu.image.data).filter(|(a, b)| (0..3).any(|c| (a[c] - b[c]).abs() > 1e-5 * (1.0 + a[c].abs()))).count();
    eprintln!("pixels differing: {differing} of {}; missed rays {} / {}", cpu.image.data.len(), cpu.missed_rays, gpu.missed_rays);
    assert!(differing * 200 <= cpu.image.data.len(), "{differing} pixels differ");
    assert!(cpu.missed_rays.abs_diff(gpu.missed_rays) * 1000 <= cpu.rays);
    // Bit-identical run to run on each backend.
    assert_eq!(trace(&mut vk, &layers, &lens, 16).image.data, gpu.image.data);
    assert_eq!(trace(&mut CpuBackend::new(), &layers, &lens, 16).image.data, cpu.image.data);
}

#[test]
fn converges_towards_the_exact_reference_with_rays_per_pixel() {
    let scene = builtin("simple").unwrap().with_size(320, 180);
    let lens = scene.thin_lens().unwrap();
    let ml = raycast_layers(&scene.scene, &scene.camera, &lens, &LayerOptions::default()).unwrap();
    let exact = reference(&scene.scene, &scene.camera, &lens, &ReferenceOptions { spp: 256, ..Default::default() }).unwrap();
    let mut cpu = CpuBackend::new();
    let err = |img: &dof::layers::RgbImage| compare(&ml.crop(img), &exact.image, Some(&ml.mask)).unwrap();
    let e4 = err(&trace(&mut cpu, &ml.layers, &lens, 4).image);
    let e64 = err(&trace(&mut cpu, &ml.layers, &lens, 64).image);
    let (front, depth) = ml.layers.front();
    let g = err(&gather(&mut cpu, &front, &depth, &lens, None).unwrap().image);
    let region = |e: &dof::metrics::ImageError| e.psnr_masked_db.unwrap();
    eprintln!(
        "simple 320x180: raytrace 4 spp {:.2} dB ({:.2} region), 64 spp {:.2} dB ({:.2} region); gather {:.2} dB ({:.2} region)",
        e4.psnr_db,
        region(&e4),
        e64.psnr_db,
        region(&e64),
        g.psnr_db,
        region(&g)
    );
    // Measured: +3.2 dB full frame, and +4.2 dB over the gather in the region.
    assert!(e64.psnr_db >= e4.psnr_db + 2.5, "16x the rays gains at least 2.5 dB");
    assert!(region(&e64) >= region(&g) + 3.5, "through the layers, ray tracing sees what the gather cannot");
}

#[test]
fn bad_options_are_errors() {
    let img = noise_with_sky(8, 8, 2);
    let mut cpu = CpuBackend::new();
    let bad = [
        (RaytraceOptions { spp: 0, ..Default::default() }, test_lens(0.01)),
        (RaytraceOptions { spp: 100_000, ..Default::default() }, test_lens(0.01)),
        (RaytraceOptions { patterns: 0, ..Default::default() }, test_lens(0.01)),
        (RaytraceOptions::default(), ThinLens { focus_distance: 0.01, ..test_lens(0.01) }),
        (RaytraceOptions::default(), ThinLens { aperture_radius: f32::NAN, ..test_lens(0.01) }),
    ];
    for (options, lens) in bad {
        let err = raytrace(&mut cpu, &img, &lens, &options).err().expect("an error");
        assert!(matches!(err, CoreError::InvalidArgument(_) | CoreError::InvalidLens(_)), "{err}");
    }
    assert!(
        LayeredImage::new(0, 4, 1).is_err()
            || raytrace(&mut cpu, &LayeredImage::new(0, 4, 1).unwrap(), &test_lens(0.01), &RaytraceOptions::default()).is_err()
    );
}

/// Frames of changing size, layer count and lens through one ray-tracing context of the registry
/// (resized once between frames), each equal bit for bit to the one-shot function (the same
/// kernels in the same order) with the same missed-ray count; returns the images.
fn context_frames_equal_the_one_shot_function(b: &mut dyn Backend) -> Vec<dof::layers::RgbImage> {
    use dof::frame::{Extent, MethodOptions};
    use dof_tests::{ContextFrame, context_frames};
    let options = RaytraceOptions { spp: 8, ..Default::default() };
    let images = [noise_with_sky(60, 40, 3), noise_with_sky(33, 21, 2), noise_with_sky(60, 40, 1), noise_with_sky(80, 50, 4)];
    let apertures = [0.02f32, 0.01, 0.0, 0.03];
    let resizes = [None, None, None, Some(Extent::new(80, 50, 4))];
    let frames: Vec<ContextFrame> =
        (0..4).map(|i| ContextFrame { image: &images[i], lens: test_lens(apertures[i]), resize: resizes[i] }).collect();
    let method_options = MethodOptions { raytrace: options.clone(), ..Default::default() };
    let got = context_frames(b, "raytrace", &method_options, Extent::new(60, 40, 3), &frames);
    for (i, (image, report)) in got.iter().enumerate() {
        let expected = raytrace(b, &images[i], &frames[i].lens, &options).unwrap();
        assert!(image.data == expected.image.data, "frame {i} differs from the one-shot function");
        let typed = report.details::<RaytraceReport>().expect("ray tracing's own report");
        assert_eq!((typed.missed_rays, typed.levels), (expected.missed_rays, expected.levels), "frame {i}");
        assert_eq!(report.figures()["missed_rays"], expected.missed_rays as f64, "frame {i}");
    }
    got.into_iter().map(|g| g.0).collect()
}

#[test]
fn a_context_records_frames_without_allocating_or_reading_back() {
    context_frames_equal_the_one_shot_function(&mut CpuBackend::new());
}

/// The same frames on Vulkan (validation on), and against the CPU's within the tolerance of
/// `vulkan_traces_the_same_rays_as_the_cpu`.
#[test]
fn a_context_records_frames_without_allocating_or_reading_back_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    let gpu = context_frames_equal_the_one_shot_function(&mut vk);
    assert_clean(&mut vk);
    let cpu = context_frames_equal_the_one_shot_function(&mut CpuBackend::new());
    for (i, (a, b)) in cpu.iter().zip(&gpu).enumerate() {
        let differing = a.data.iter().zip(&b.data).filter(|(a, b)| (0..3).any(|c| (a[c] - b[c]).abs() > 1e-5 * (1.0 + a[c].abs()))).count();
        assert!(differing * 200 <= a.data.len(), "frame {i}: {differing} pixels differ");
    }
}

/// The registry's one-shot path (a context sized to the image) equals the one-shot function bit
/// for bit on a built-in scene, and a context too small for a frame refuses it.
#[test]
fn the_registry_one_shot_path_equals_the_one_shot_function() {
    use dof::frame::{ContextDesc, CountBuffer, Extent, Frame, MethodOptions, RgbBuffer, SlotBuffer, registry};
    use dof::methods::one_shot::one_shot;
    let scene = builtin("railing").unwrap().with_size(96, 54);
    let lens = scene.thin_lens().unwrap();
    let layers = raycast_layers(&scene.scene, &scene.camera, &lens, &LayerOptions::default()).unwrap().layers;
    let method = registry::method("raytrace").unwrap();
    let mut backends: Vec<Box<dyn Backend>> = vec![Box::new(CpuBackend::new())];
    if let Some(vk) = vulkan() {
        backends.push(Box::new(vk));
    }
    for b in &mut backends {
        let options = MethodOptions { raytrace: RaytraceOptions { spp: 12, ..Default::default() }, ..Default::default() };
        let shot = one_shot(b.as_mut(), method, &options, &layers, &lens).unwrap();
        let expected = raytrace(b.as_mut(), &layers, &lens, &options.raytrace).unwrap();
        assert!(shot.image.data == expected.image.data, "{}", b.kind());
        assert_eq!(shot.report.figures()["missed_rays"], expected.missed_rays as f64);
        let mut ctx = (method.create)(b.as_mut(), &ContextDesc::new(Extent::new(16, 16, 1), options)).unwrap();
        let out = b.create_buffer(3 * 96 * 54, "out").unwrap();
        let f = Frame::layers(96, 54, 1, lens, SlotBuffer::current(out), CountBuffer(out), RgbBuffer(out));
        assert!(matches!(ctx.record(b.as_mut(), &f), Err(CoreError::ResizeNeeded { .. })));
        ctx.destroy(b.as_mut());
        b.destroy_buffer(out);
        assert_eq!(b.take_diagnostics(), Vec::<String>::new(), "{}", b.kind());
    }
}

/// The context refuses the options the one-shot function refuses, before allocating anything.
#[test]
fn a_context_with_bad_options_is_refused() {
    use dof::frame::{ContextDesc, Extent, MethodOptions, registry};
    let mut b = CpuBackend::new();
    let method = registry::method("raytrace").unwrap();
    for raytrace in [RaytraceOptions { spp: 0, ..Default::default() }, RaytraceOptions { patterns: 0, ..Default::default() }] {
        let desc = ContextDesc::new(Extent::new(8, 8, 2), MethodOptions { raytrace, ..Default::default() });
        assert!(matches!((method.create)(&mut b, &desc), Err(CoreError::InvalidArgument(_))));
    }
    let huge = ContextDesc::new(Extent::new(10_000, 1, 1), MethodOptions::default());
    assert!(matches!((method.create)(&mut b, &huge), Err(CoreError::InvalidArgument(_))));
    assert_eq!(b.counters().device_bytes, 0);
}
