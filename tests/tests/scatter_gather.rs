//! Scatter-as-you-gather with tile depth separation (Jimenez 2014): the input bit for bit in focus,
//! finite and non-negative with NaN and Inf in the input, a blurred near object's edge spread over
//! a sharp background as a blend of the two, never a blurred background over a sharp object, the
//! radius cap held, the same bits on Vulkan as on the CPU, frames through its context without
//! allocation, bad options refused, and measured against the exact reference.

use dof::CoreError;
use dof::backend::{Backend, CpuBackend};
use dof::frame::Extent;
use dof::frame::scatter_gather::{DEFAULT_RINGS, MAX_RADIUS, MAX_RINGS};
use dof::frame::{
    CountBuffer, DofContext, Frame, MethodOptions, RgbBuffer, ScatterGatherContext, ScatterGatherContextDesc, ScatterGatherOptions,
    SlotBuffer, registry,
};
use dof::layers::{Fragment, LayeredImage, RgbImage};
use dof::methods::buffers::{SLOT_WORDS, read_rgb, slot_words};
use dof::methods::one_shot::{OneShot, one_shot};
use dof::metrics::compare;
use dof::scene::{LayerOptions, ReferenceOptions, builtin, raycast_layers, reference};
use dof::stress::{noise_with_sky, test_lens};
use dof_shaders::lens::ThinLens;
use dof_tests::{assert_clean, vulkan};

fn options(rings: u32, max_radius: u32) -> ScatterGatherOptions {
    ScatterGatherOptions { rings, max_radius }
}

/// One frame of `image` through the registry's entry with `o`.
fn run(b: &mut dyn Backend, image: &LayeredImage, lens: &ThinLens, o: ScatterGatherOptions) -> OneShot {
    let m = registry::method("scatter-gather").unwrap();
    one_shot(b, m, &MethodOptions { scatter_gather: o, ..Default::default() }, image, lens).unwrap()
}

/// A one-layer image of `colour` and `depth`, taken as given (NaN and Inf included).
fn one_layer(w: u32, h: u32, pixel: impl Fn(u32, u32) -> ([f32; 3], f32)) -> LayeredImage {
    let mut img = LayeredImage::new(w, h, 1).unwrap();
    for y in 0..h {
        for x in 0..w {
            let (color, depth) = pixel(x, y);
            let p = (y * w + x) as usize;
            img.counts[p] = 1;
            img.fragments[p] = Fragment { color, alpha: 1.0, depth };
        }
    }
    img
}

/// Through the pinhole, a pinhole-sized aperture (every CoC under 1e-4 px) and an aperture whose
/// largest CoC radius is under half a pixel, every ring count gives the flattened input bit for bit.
#[test]
fn in_focus_the_output_is_the_input() {
    let image = noise_with_sky(37, 21, 3);
    let (front, _) = image.front();
    // Depths from 0.5 to 15.5 and the sky: the largest CoC radius is 205 · 3 · a px.
    for aperture in [0.0, 1e-7, 0.49 / (205.0 * 3.0)] {
        for rings in [1, DEFAULT_RINGS, MAX_RINGS] {
            let out = run(&mut CpuBackend::new(), &image, &test_lens(aperture), options(rings, 32));
            assert!(out.image == front, "aperture {aperture}, {rings} rings");
            assert!(out.report.figures()["largest_radius_px"] < 0.5, "{}", out.report.summary);
        }
    }
}

/// NaN and Inf colours and NaN, zero, negative and infinite depths: the output is finite and
/// non-negative at every aperture; in focus an unusable pixel comes out black and the rest are the
/// input.
#[test]
fn nan_and_inf_input_gives_finite_non_negative_output() {
    let base = noise_with_sky(33, 29, 1);
    let (front, depth) = base.front();
    let bad: [([f32; 3], f32); 6] = [
        ([f32::NAN, 1.0, 1.0], 3.0),
        ([f32::INFINITY, 1.0, 1.0], 0.7),
        ([1.0, f32::NEG_INFINITY, 1.0], 9.0),
        ([1.0; 3], f32::NAN),
        ([1.0; 3], -2.0),
        ([1.0; 3], 0.0),
    ];
    // Every 97th pixel from the 100th.
    let at = |p: usize| (p >= 100 && (p - 100).is_multiple_of(97)).then(|| bad.get((p - 100) / 97)).flatten();
    let image = one_layer(33, 29, |x, y| {
        let p = (y * 33 + x) as usize;
        at(p).copied().unwrap_or((front.data[p], depth[p]))
    });
    for aperture in [0.0, 0.005, 0.02, 1.0] {
        let out = run(&mut CpuBackend::new(), &image, &test_lens(aperture), ScatterGatherOptions::default());
        assert!(out.image.data.iter().flatten().all(|c| c.is_finite() && *c >= 0.0), "aperture {aperture}");
        if aperture == 0.0 {
            for (p, got) in out.image.data.iter().enumerate() {
                let want = if at(p).is_some() { [0.0; 3] } else { front.data[p] };
                assert_eq!(*got, want, "pixel {p}");
            }
        }
    }
}

/// A flat colour stays flat under blur at mixed depths, with the sky among them.
#[test]
fn a_flat_colour_stays_flat() {
    let (_, depth) = noise_with_sky(50, 41, 2).front();
    let flat = one_layer(50, 41, |x, y| ([0.25, 3.0, 1200.0], depth[(y * 50 + x) as usize]));
    let out = run(&mut CpuBackend::new(), &flat, &test_lens(0.03), ScatterGatherOptions::default());
    for p in &out.image.data {
        assert_eq!(*p, [0.25, 3.0, 1200.0]);
    }
}

/// 64x48, the background in focus (2 m, blue), a 12x12 red square at 0.5 m in the top-left corner
/// (CoC radius 18.5 px with `test_lens(0.03)`).
fn square_in_front() -> LayeredImage {
    one_layer(64, 48, |x, y| if x < 12 && y < 12 { ([4.0, 0.0, 0.0], 0.5) } else { ([0.0, 0.0, 1.0], 2.0) })
}

/// Partial occlusion, as a single layer can give it: past the blurred square's edge the sharp
/// background shows through a coverage of the square between 0 and 1 that falls with the distance
/// (each pixel a blend of the two colours), inside the edge the square's coverage is under 1 too,
/// and beyond the blur's reach the background is exact.
#[test]
fn a_blurred_near_edge_spreads_over_a_sharp_background() {
    let out = run(&mut CpuBackend::new(), &square_in_front(), &test_lens(0.03), ScatterGatherOptions::default()).image;
    let coverage = |x: u32, y: u32| {
        let p = out.get(x, y);
        // A blend of red (4, 0, 0) and blue (0, 0, 1): its red share is its coverage.
        assert!((p[0] / 4.0 + p[2] - 1.0).abs() < 1e-5 && p[1] == 0.0, "({x}, {y}): {p:?} is no blend of the two colours");
        p[0] / 4.0
    };
    let outside: Vec<f32> = [12, 14, 18, 24].iter().map(|&x| coverage(x, 5)).collect();
    eprintln!("coverage of the square at x = 12, 14, 18, 24 (y = 5): {outside:?}; at x = 10: {}", coverage(10, 5));
    assert!(outside[0] > 0.2 && outside[0] < 0.9, "just past the edge: {}", outside[0]);
    assert!(outside.windows(2).all(|w| w[0] >= w[1]), "falling with the distance: {outside:?}");
    assert!(outside[3] > 0.0 && outside[3] < outside[0] - 0.1, "{outside:?}");
    let inside = coverage(10, 5);
    assert!(inside > outside[0] && inside < 1.0, "inside the edge: {inside}");
    // 19 px and more from the square, beyond its reach (18.5 px and the pixel's half).
    for (x, y) in [(40, 5), (40, 40), (5, 40), (63, 47)] {
        assert_eq!(out.get(x, y), [0.0, 0.0, 1.0], "({x}, {y})");
    }
}

/// A blurred background never smears over a sharp object in front of it: the object's pixels keep
/// their colour bit for bit, while the background around is blurred.
#[test]
fn a_blurred_background_does_not_bleed_over_a_sharp_object() {
    // A bright checkerboard at 20 m (CoC radius 5.5 px), a sharp green square at the focus.
    let image = one_layer(48, 48, |x, y| {
        if (16..32).contains(&x) && (16..32).contains(&y) {
            ([0.0, 1.0, 0.0], 2.0)
        } else {
            (if (x + y) % 2 == 0 { [50.0, 50.0, 0.0] } else { [0.0; 3] }, 20.0)
        }
    });
    for rings in [1, DEFAULT_RINGS, MAX_RINGS] {
        let out = run(&mut CpuBackend::new(), &image, &test_lens(0.03), options(rings, 32)).image;
        for y in 16..32 {
            for x in 16..32 {
                assert_eq!(out.get(x, y), [0.0, 1.0, 0.0], "{rings} rings, ({x}, {y})");
            }
        }
        // The background is blurred: every pixel of a block between the checkerboard's two
        // colours, the block's mean theirs (the rings' samples catch the squares of a one-pixel
        // checkerboard unevenly, so each pixel alone aliases: 9.2 and 40.8 with 3 rings).
        let block: Vec<f32> = (2..10).flat_map(|y| (2..10).map(move |x| (x, y))).map(|(x, y)| out.get(x, y)[0]).collect();
        assert!(block.iter().all(|&v| v > 1.0 && v < 49.0), "{rings} rings: {block:?}");
        let mean = block.iter().sum::<f32>() / block.len() as f32;
        assert!((mean - 25.0).abs() < 1.0, "{rings} rings: mean {mean}");
    }
}

/// The radius cap holds: with a 3 px cap the square's blur reaches 3.5 px past its edge, no further.
#[test]
fn the_radius_cap_bounds_the_blur() {
    let out = run(&mut CpuBackend::new(), &square_in_front(), &test_lens(0.03), options(DEFAULT_RINGS, 3));
    assert_eq!(out.report.figures()["largest_radius_px"], 3.0, "{}", out.report.summary);
    assert!(out.image.get(13, 5)[0] > 0.0, "spread past the edge");
    for x in 16..64 {
        assert_eq!(out.image.get(x, 5), [0.0, 0.0, 1.0], "x = {x}");
    }
}

/// The same frame on Vulkan (validation on) as on the CPU, bit for bit, at every ring count, with
/// the report's figures equal and every stage timed.
#[test]
fn vulkan_equals_the_cpu_bit_for_bit() {
    let Some(mut vk) = vulkan() else { return };
    let image = noise_with_sky(45, 27, 3);
    let square = square_in_front();
    for (image, aperture) in [(&image, 0.02), (&image, 0.3), (&square, 0.03)] {
        for rings in [1, DEFAULT_RINGS, MAX_RINGS] {
            let o = options(rings, 32);
            let on_vk = run(&mut vk, image, &test_lens(aperture), o);
            assert_clean(&mut vk);
            let on_cpu = run(&mut CpuBackend::new(), image, &test_lens(aperture), o);
            let bits = |i: &RgbImage| i.data.iter().flatten().map(|c| c.to_bits()).collect::<Vec<_>>();
            assert!(bits(&on_vk.image) == bits(&on_cpu.image), "aperture {aperture}, {rings} rings: Vulkan differs");
            assert_eq!(on_vk.report, on_cpu.report);
            for stage in ["scatter-gather/tiles", "scatter-gather/dilate", "scatter-gather"] {
                assert!(on_vk.stages.iter().any(|t| t.label == stage), "no {stage} in {:?}", on_vk.stages);
            }
        }
    }
}

/// Through its context: frames of different sizes, apertures and options record with no
/// allocation, readback or upload and one submission each, and give the one-shot path's image; the
/// report gives the frame's largest CoC radius as the host computes it.
#[test]
fn a_context_records_frames_without_allocating() {
    let mut cpu = CpuBackend::new();
    let (w, h, layers) = (40u32, 24u32, 2u32);
    let mut ctx = ScatterGatherContext::new(&mut cpu, &ScatterGatherContextDesc::new(Extent::new(w, h, layers))).unwrap();
    let pixels = (w * h) as u64;
    let input = cpu.create_buffer(SLOT_WORDS as u64 * pixels * layers as u64, "input").unwrap();
    let counts = cpu.create_buffer(pixels, "counts").unwrap();
    let output = cpu.create_buffer(3 * pixels, "output").unwrap();
    for (fw, fh, aperture, o) in [(40u32, 24u32, 0.02f32, options(3, 32)), (17, 9, 0.05, options(1, 5)), (40, 24, 0.01, options(8, 128))] {
        let image = noise_with_sky(fw, fh, layers);
        cpu.write_buffer(input, 0, &slot_words(&image)).unwrap();
        cpu.write_buffer(counts, 0, &image.counts).unwrap();
        ctx.set_options(o).unwrap();
        let lens = test_lens(aperture);
        let before = cpu.counters();
        ctx.record(&mut cpu, &Frame::layers(fw, fh, layers, lens, SlotBuffer::current(input), CountBuffer(counts), RgbBuffer(output)))
            .unwrap();
        cpu.submit().unwrap();
        let spent = cpu.counters().since(&before);
        assert_eq!((spent.allocations, spent.readbacks, spent.uploads, spent.submissions), (0, 0, 0, 1), "{fw}x{fh}");
        let framed = read_rgb(&mut cpu, output, fw, fh).unwrap();
        let once = run(&mut CpuBackend::new(), &image, &lens, o);
        assert!(framed == once.image, "{fw}x{fh}, {o:?}: the one-shot path differs");
        let report = ctx.report(&mut cpu).unwrap();
        let (_, depth) = image.front();
        let cap = o.max_radius as f32;
        let largest = depth.iter().map(|&z| dof_shaders::ring_gather::signed_radius(&lens, z, cap).abs()).fold(0.0f32, f32::max);
        assert_eq!(report.figures()["largest_radius_px"], largest as f64, "{}", report.summary);
        assert_eq!(report.figures()["samples_per_pixel"], (1 + 4 * o.rings * (o.rings + 1)) as f64);
    }
    ctx.destroy(&mut cpu);
    for b in [input, counts, output] {
        cpu.destroy_buffer(b);
    }
    assert_eq!(cpu.counters().device_bytes, 0);
}

/// Ring counts and caps out of range are refused with a clear message, when a context is made (also
/// through the registry) and when its options change; nothing panics.
#[test]
fn bad_options_are_refused() {
    let mut cpu = CpuBackend::new();
    let m = registry::method("scatter-gather").unwrap();
    for (bad, says) in [
        (options(0, 32), "1 to 8 rings, got 0"),
        (options(MAX_RINGS + 1, 32), "rings, got 9"),
        (options(3, 0), "cap is 1 to 128 px, got 0"),
        (options(3, MAX_RADIUS + 1), "got 129"),
    ] {
        let desc = ScatterGatherContextDesc { options: bad, ..ScatterGatherContextDesc::new(Extent::new(16, 16, 1)) };
        let Err(e) = ScatterGatherContext::new(&mut cpu, &desc) else { panic!("{bad:?} accepted") };
        assert!(matches!(e, CoreError::InvalidArgument(_)) && e.to_string().contains(says), "{bad:?}: {e}");
        let d = registry::ContextDesc::new(dof::frame::Extent::new(16, 16, 1), MethodOptions { scatter_gather: bad, ..Default::default() });
        assert!((m.create)(&mut cpu, &d).is_err(), "{bad:?} through the registry");
        let mut ctx = ScatterGatherContext::new(&mut cpu, &ScatterGatherContextDesc::new(Extent::new(16, 16, 1))).unwrap();
        assert!(ctx.set_options(bad).is_err(), "{bad:?} by set_options");
        assert_eq!(ctx.options(), ScatterGatherOptions::default());
        ctx.destroy(&mut cpu);
    }
    assert_eq!(cpu.counters().device_bytes, 0);
}

/// On `simple` at 160x90 scatter-as-you-gather is closer to the exact reference than the unblurred
/// image, and more rings are closer than fewer (figures printed; bounds under the measured ones).
#[test]
fn against_the_exact_reference() {
    let scene = builtin("simple").unwrap().with_size(160, 90);
    let lens = scene.thin_lens().unwrap();
    let layers = raycast_layers(&scene.scene, &scene.camera, &lens, &LayerOptions::default()).unwrap();
    let exact = reference(&scene.scene, &scene.camera, &lens, &ReferenceOptions { spp: 256, ..Default::default() }).unwrap();
    let sharp = compare(&layers.front().0, &exact.image, Some(&layers.mask)).unwrap();
    let mut m = Vec::new();
    for rings in [1, DEFAULT_RINGS, MAX_RINGS] {
        let blurred = layers.crop(&run(&mut CpuBackend::new(), &layers.layers, &lens, options(rings, 32)).image);
        let r = compare(&blurred, &exact.image, Some(&layers.mask)).unwrap();
        eprintln!("{rings} rings: {r:?}");
        m.push(r);
    }
    eprintln!("pinhole: {sharp:?}");
    for r in &m {
        assert!(r.psnr_db > sharp.psnr_db + 0.5 && r.ssim > sharp.ssim, "{r:?} vs pinhole {sharp:?}");
    }
    assert!(m[1].psnr_db > m[0].psnr_db, "3 rings {:?}, 1 ring {:?}", m[1], m[0]);
}
