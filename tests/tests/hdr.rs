//! The numerical contract (docs/methods.md, "Numerical contract") on the splatting fragment, and
//! deterministic ties: a fronto-parallel wall whose fragments share one depth renders the same on
//! the CPU backend and on Vulkan, and the same when recorded twice.

use dof::backend::{Backend, CpuBackend};
use dof::layers::{Fragment, LayeredImage};
use dof::methods::splat::{Merge, SplatOptions, splat};
use dof::stress::{hash, test_lens};
use dof_shaders::keys::sort_key;
use dof_shaders::radiance::COLOR_MAX;
use dof_tests::oracle::splat_stages::{Staged, splat_with_stages};
use dof_tests::{assert_clean, vulkan};

/// A fronto-parallel textured wall at 4 m behind a near wall at 0.8 m that covers the middle third,
/// and a far wall at 9 m behind both: three depths, every fragment of a wall at exactly its wall's
/// depth (many exact ties).
fn walls(w: u32, h: u32) -> LayeredImage {
    let mut img = LayeredImage::new(w, h, 3).unwrap();
    for y in 0..h {
        for x in 0..w {
            let v = hash(y * w + x);
            let tex = |k: u32| 0.1 + ((v >> (8 * k)) & 0xff) as f32 / 255.0;
            if (w / 3..2 * w / 3).contains(&x) {
                img.push(x, y, Fragment { color: [tex(0), 0.2, 0.1], alpha: 1.0, depth: 0.8 }).unwrap();
            }
            img.push(x, y, Fragment { color: [0.3, tex(1), tex(2)], alpha: 1.0, depth: 4.0 }).unwrap();
            img.push(x, y, Fragment { color: [0.9, 0.9, tex(3)], alpha: 1.0, depth: 9.0 }).unwrap();
        }
    }
    img
}

/// Every sorted list is in strictly increasing `(depth key, dense index)`: the tie key of
/// `dof_shaders::splat::fragment` (ties in dense order, which follows position and slot).
fn assert_tie_order(out: &Staged) {
    let st = &out.intermediates;
    let (keys, values) = &st.sorted;
    let mut at = 0usize;
    let mut ties = 0;
    for &len in &st.list_lengths {
        let list = at..at + len as usize;
        for i in list.clone().skip(1) {
            let (a, b) = ((sort_key(keys[i - 1]), values[i - 1]), (sort_key(keys[i]), values[i]));
            assert!(a < b, "list entries {} and {i}: {a:?} then {b:?}", i - 1);
            ties += (a.0 == b.0) as u32;
        }
        at = list.end;
    }
    assert!(ties > 1000, "the scene has many exact ties ({ties})");
}

fn options() -> [SplatOptions; 2] {
    [SplatOptions::default(), SplatOptions { merge: Merge::X4, tile: 24, ..Default::default() }]
}

/// Recorded twice, on each backend, a frame equals itself bit for bit, and ties follow the key.
#[test]
fn ties_are_deterministic_on_each_backend() {
    let img = walls(96, 64);
    let lens = test_lens(0.03);
    let mut vk = vulkan();
    let mut backends: Vec<Box<dyn Backend>> = vec![Box::new(CpuBackend::new())];
    if let Some(vk) = vk.take() {
        backends.push(Box::new(vk));
    }
    for backend in &mut backends {
        for o in options() {
            let a = splat_with_stages(backend.as_mut(), &img, &lens, &o).unwrap();
            let b = splat_with_stages(backend.as_mut(), &img, &lens, &o).unwrap();
            assert_tie_order(&a);
            assert!(a.image == b.image, "two frames differ on {} ({:?})", backend.kind(), o.merge);
            assert!(a.intermediates.sorted == b.intermediates.sorted);
        }
    }
}

/// The wall of exact ties on the CPU backend and on Vulkan: every stage up to the sorted lists is
/// equal bit for bit (so ties meet accumulation in the same order), and the images agree within
/// float rounding (Vulkan's division and square root are not correctly rounded, and a device may
/// fuse a multiply and an add): relative 1e-5, or 1e-5 of the pixel's brightest channel.
#[test]
fn ties_match_between_cpu_and_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    let img = walls(96, 64);
    let lens = test_lens(0.03);
    for o in options() {
        let on_vk = splat_with_stages(&mut vk, &img, &lens, &o).unwrap();
        assert_clean(&mut vk);
        let on_cpu = splat_with_stages(&mut CpuBackend::new(), &img, &lens, &o).unwrap();
        let (a, b) = (&on_vk.intermediates, &on_cpu.intermediates);
        assert!(a.dense == b.dense && a.sorted == b.sorted, "lists differ ({:?})", o.merge);
        assert_eq!(on_vk.report.early_out_pixels, on_cpu.report.early_out_pixels, "early termination ({:?})", o.merge);
        let mut worst = 0.0f32;
        for (p, q) in on_vk.image.data.iter().zip(&on_cpu.image.data) {
            let top = q.iter().copied().fold(1e-2f32, f32::max);
            for c in 0..3 {
                worst = worst.max((p[c] - q[c]).abs() / top);
            }
        }
        eprintln!("{:?}: CPU and Vulkan differ by at most {worst:.2e} (relative)", o.merge);
        assert!(worst <= 1e-5, "CPU and Vulkan differ by {worst:.2e} ({:?})", o.merge);
    }
}

/// Clamped colours are counted in the report and named in its summary (what `dof render` prints).
/// A 24x24 frame of 0.5 at 3 m whose front holds four colours the contract clamps (f32::MAX,
/// 1e38, a negative and a subnormal channel), with `behind(x, y)` pushed behind a pixel's front.
fn four_clamped_fronts(layers: u32, behind: impl Fn(u32, u32) -> Option<Fragment>) -> LayeredImage {
    let mut img = LayeredImage::new(24, 24, layers).unwrap();
    for y in 0..24 {
        for x in 0..24 {
            let color = match (x, y) {
                (8, 8) => [f32::MAX, 0.5, 0.5],
                (14, 9) => [1e38, 1e38, 0.5],
                (20, 20) => [-1.0, 0.5, 0.5],
                (5, 17) => [0.5, 1e-40, 0.5],
                _ => [0.5; 3],
            };
            img.push(x, y, Fragment { color, alpha: 1.0, depth: 3.0 }).unwrap();
            if let Some(f) = behind(x, y) {
                img.push(x, y, f).unwrap();
            }
        }
    }
    img
}

#[test]
fn clamps_are_counted_and_printed() {
    let img = four_clamped_fronts(1, |_, _| None);
    let out = splat(&mut CpuBackend::new(), &img, &test_lens(0.02), &SplatOptions::default()).unwrap();
    assert_eq!(out.report.clamped, 4);
    assert!(out.report.summary().contains("4 clamped"), "{}", out.report.summary());
    assert!(out.image.data.iter().all(|p| p.iter().all(|&c| c.is_finite() && c >= 0.0)));
    // The clamped highlight keeps the contract's maximum, spread over its disc.
    let total: f64 = out.image.data.iter().map(|p| p[0] as f64).sum();
    assert!(total > 0.9 * 2.0 * COLOR_MAX as f64 && total < 1.1 * 2.0 * COLOR_MAX as f64, "{total:e}");
}

/// Every method of the frame API counts the input colours it clamps in its report (figure
/// `clamped`, and the summary), the same on the CPU backend and on Vulkan: a one-layer input and a
/// two-layer one, whose hidden slot only the multi-layer methods read.
#[test]
fn every_method_reports_what_it_clamped() {
    use dof::frame::{METHODS, MethodOptions, Reads};
    use dof::methods::one_shot::one_shot;
    // Behind one front, a fifth clamped colour: read by the multi-layer methods only.
    let behind = |x, y| ((x, y) == (3, 3)).then_some(Fragment { color: [2e38, 0.5, 0.5], alpha: 1.0, depth: 6.0 });
    let img = four_clamped_fronts(2, behind);
    let check = |b: &mut dyn Backend| {
        for method in METHODS {
            let out = one_shot(b, method, &MethodOptions::default(), &img, &test_lens(0.02)).unwrap();
            let want = if method.reads == Reads::AllLayers { 5.0 } else { 4.0 };
            assert_eq!(out.report.figures().get("clamped"), Some(&want), "{} on {}: {}", method.name, b.kind(), out.report.summary);
            assert!(out.report.summary.contains("clamped"), "{}: {}", method.name, out.report.summary);
            assert!(out.image.data.iter().all(|p| p.iter().all(|&c| c.is_finite() && c >= 0.0)), "{}", method.name);
        }
    };
    check(&mut CpuBackend::new());
    if let Some(mut vk) = vulkan() {
        check(&mut vk);
        assert_clean(&mut vk);
    }
}

/// One 1e11 pixel in a 0.3 frame (a frame-wide half-float scale pulls the rest down by 17%), and
/// a 1e12 pixel every 97 pixels over 0.5 (a frame-wide scale blacks out tiles): beyond the highlights' discs the frame is
/// unchanged, and no pixel anywhere is darker than the frame.
#[test]
fn a_highlight_costs_the_frame_nothing() {
    let lens = test_lens(0.02);
    let flat = |c: f32, spot: &dyn Fn(u32, u32) -> Option<f32>| {
        let mut img = LayeredImage::new(64, 64, 1).unwrap();
        for y in 0..64 {
            for x in 0..64 {
                let v = spot(x, y).unwrap_or(c);
                img.push(x, y, Fragment { color: [v; 3], alpha: 1.0, depth: 5.0 }).unwrap();
            }
        }
        img
    };
    for merge in [Merge::None, Merge::X4] {
        let o = SplatOptions { merge, ..Default::default() };
        let one = splat(&mut CpuBackend::new(), &flat(0.3, &|x, y| ((x, y) == (10, 10)).then_some(1e11)), &lens, &o).unwrap();
        for (i, p) in one.image.data.iter().enumerate() {
            let (x, y) = ((i % 64) as i32, (i / 64) as i32);
            if (x - 10).pow(2) + (y - 10).pow(2) > 400 {
                assert!((p[1] / 0.3 - 1.0).abs() < 1e-4, "pixel ({x}, {y}): {p:?} ({merge:?})");
            }
        }
        let many = splat(&mut CpuBackend::new(), &flat(0.5, &|x, y| ((y * 64 + x) % 97 == 0).then_some(1e12)), &lens, &o).unwrap();
        assert!(many.image.data.iter().all(|p| p.iter().all(|&c| c >= 0.5 * (1.0 - 1e-4) && c.is_finite())), "{merge:?}");
    }
}

/// `--background 3e38` (where sums can reach +inf in the gather, −inf in ray tracing) and the float's
/// maximum, each taken as 2^100 when read, through the path `dof render` takes: a built-in scene ray cast into layers with that
/// background, then every method of the frame API on both backends: finite, non-negative output.
#[test]
fn a_background_at_the_float_limit_in_every_method() {
    use dof::frame::{METHODS, MethodOptions};
    use dof::methods::one_shot::one_shot;
    use dof::scene::{LayerOptions, builtin, raycast_layers};
    let mut vk = vulkan();
    // Pixels that come out black with an ordinary background, per method and backend.
    let mut black_with_dim: Vec<usize> = Vec::new();
    for bg in [0.5f32, 1e30, 3e38, f32::MAX] {
        let mut b = builtin("fence").unwrap().with_size(64, 36);
        b.scene = b.scene.with_background([bg; 3]).unwrap();
        let lens = b.thin_lens().unwrap();
        let layers = raycast_layers(&b.scene, &b.camera, &lens, &LayerOptions::default()).unwrap().layers;
        // Above 2^100 the background is taken as 2^100 when read (the numerical contract).
        let want = bg.min(COLOR_MAX);
        let sky = layers.fragments.iter().filter(|f| f.depth.is_infinite() && f.color == [want; 3]).count();
        assert!(sky > 100, "the background reaches the layers ({sky} fragments)");
        let mut backends: Vec<&mut dyn Backend> = Vec::new();
        let mut cpu = CpuBackend::new();
        backends.push(&mut cpu);
        if let Some(vk) = vk.as_mut() {
            backends.push(vk);
        }
        let mut run = 0;
        for backend in backends {
            let kind = backend.kind();
            for method in METHODS {
                let out = one_shot(backend, method, &MethodOptions::default(), &layers, &lens).unwrap();
                let bad = out.image.data.iter().filter(|p| !p.iter().all(|&c| c.is_finite() && c >= 0.0)).count();
                assert_eq!(bad, 0, "{} on {kind} with background {bg:e}: {bad} pixels not finite and non-negative", method.name);
                // A background of 1e30 can black out foreground pixels in tiled splatting: no more black than with 0.5.
                let black = out.image.data.iter().filter(|p| p.iter().all(|&c| c == 0.0)).count();
                if bg == 0.5 {
                    black_with_dim.push(black);
                } else {
                    assert!(black <= black_with_dim[run], "{} on {kind} with background {bg:e}: {black} black pixels", method.name);
                }
                run += 1;
            }
        }
    }
    if let Some(vk) = vk.as_mut() {
        assert_clean(vk);
    }
}
