//! Alpha through every method, on the CPU backend and on Vulkan (lavapipe in CI):
//!
//! - **The in-focus oracle**: with a pinhole-sized aperture (radius 1e-7), every registered method
//!   and the pinhole return the input's front-to-back composite over black, on three cases: an
//!   RGB+Z EXR of premultiplied 0.4 at alpha 0.5 gives 0.4 (not 0.8), a two-layer pixel of
//!   premultiplied (0.8, 0.4, 0.2) at alpha 0.5 over an opaque (0.1, 0.9, 0.1) gives
//!   (0.85, 0.85, 0.25) (not brighter than its input), and an anti-aliased edge pixel of alpha 0.5
//!   stays half covered.
//! - **A blurred translucent pane over a wall**: inside the pane, far from its edges, every method
//!   gives the composite (the wall shows through), however blurred; so does multi-layer splatting
//!   through a blurred stack of 100 panes of alpha 0.01 (0.99^100 of the wall gets through).
//! - **Alpha 0 everywhere** in an EXR is light that hides nothing: the colour, never black, and
//!   noted in the report.
//! - **CPU equals Vulkan** on a translucent input, every method.

use std::path::PathBuf;

use dof::backend::{Backend, CpuBackend};
use dof::frame::splat::LLVMPIPE_SAFE_LIST;
use dof::frame::splat::{Merge, SplatOptions};
use dof::frame::{Extent, METHODS, MethodInfo, MethodOptions};
use dof::io::codecs::exr::prelude as exr;
use dof::io::read_layered_exr;
use dof::layers::{Fragment, LayeredImage, RgbImage};
use dof::methods::one_shot::one_shot;
use dof::methods::splat::splat;
use dof::stress::{test_lens, varied};
use dof_shaders::lens::ThinLens;
use dof_tests::{ContextFrame, assert_clean, context_frames, vulkan};

/// The pinhole-sized aperture: every CoC of the test lens is under 1e-4 px.
const PINHOLE: f32 = 1e-7;

/// Every registered method's image of `image` through `lens`, and the pinhole's (the input
/// flattened), by name.
fn every_method(b: &mut dyn Backend, image: &LayeredImage, lens: &ThinLens) -> Vec<(&'static str, RgbImage)> {
    let mut out = vec![("pinhole", image.front().0)];
    for m in METHODS {
        let shot = one_shot(b, m, &MethodOptions::default(), image, lens).unwrap_or_else(|e| panic!("{}: {e}", m.name));
        out.push((m.name, shot.image));
    }
    out
}

fn temp(name: &str) -> PathBuf {
    std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("dof-alpha-{}-{name}", std::process::id()))
}

/// An RGB+Z EXR (channels R, G, B, A, Z) of `w`x`h` pixels, each `(premultiplied colour, alpha,
/// depth)`, read back through the library's reader.
fn rgbz_exr(name: &str, w: usize, h: usize, pixel: impl Fn(usize, usize) -> ([f32; 3], f32, f32)) -> LayeredImage {
    use exr::WritableImage;
    let values: Vec<_> = (0..w * h).map(|p| pixel(p % w, p / w)).collect();
    let plane = |f: &dyn Fn(&([f32; 3], f32, f32)) -> f32| exr::FlatSamples::F32(values.iter().map(f).collect());
    let channels = vec![
        exr::AnyChannel::new("R", plane(&|v| v.0[0])),
        exr::AnyChannel::new("G", plane(&|v| v.0[1])),
        exr::AnyChannel::new("B", plane(&|v| v.0[2])),
        exr::AnyChannel::new("A", plane(&|v| v.1)),
        exr::AnyChannel::new("Z", plane(&|v| v.2)),
    ];
    let path = temp(name);
    exr::Image::from_channels((w, h), exr::AnyChannels::sort(channels.into_iter().collect())).write().to_file(&path).unwrap();
    let (image, _) = read_layered_exr(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    image
}

/// Asserts every method's image equals `want(x, y)` within `tol` relative (to at least 1e-3), at
/// least `margin` pixels from the frame's edges.
fn assert_all(
    b: &mut dyn Backend,
    case: &str,
    (image, margin): (&LayeredImage, u32),
    lens: &ThinLens,
    tol: f32,
    want: impl Fn(u32, u32) -> [f32; 3],
) {
    for (name, got) in every_method(b, image, lens) {
        for y in margin..image.height - margin {
            for x in margin..image.width - margin {
                let (g, w) = (got.get(x, y), want(x, y));
                for c in 0..3 {
                    assert!(
                        (g[c] - w[c]).abs() <= tol * w[c].abs().max(1e-3),
                        "{case}, {name} on {}: pixel ({x}, {y}) is {g:?}, the composite {w:?}",
                        b.kind()
                    );
                }
            }
        }
    }
}

/// The in-focus oracle on the three cases of the module's documentation.
fn in_focus_oracle(b: &mut dyn Backend) {
    let lens = test_lens(PINHOLE);
    // Premultiplied 0.4 at alpha 0.5 in an RGB+Z EXR, beside opaque pixels.
    let image = rgbz_exr("half.exr", 12, 9, |x, _| if x < 6 { ([0.4; 3], 0.5, 3.0) } else { ([0.2, 0.3, 0.5], 1.0, 4.0) });
    assert_all(b, "premultiplied 0.4 at alpha 0.5", (&image, 0), &lens, 1e-5, |x, _| if x < 6 { [0.4; 3] } else { [0.2, 0.3, 0.5] });

    // Two layers: (0.8, 0.4, 0.2) at alpha 0.5 over an opaque (0.1, 0.9, 0.1).
    let mut image = LayeredImage::new(10, 7, 2).unwrap();
    for y in 0..7 {
        for x in 0..10 {
            image.push(x, y, Fragment { color: [0.8, 0.4, 0.2], alpha: 0.5, depth: 2.0 }).unwrap();
            image.push(x, y, Fragment::opaque([0.1, 0.9, 0.1], 5.0)).unwrap();
        }
    }
    assert_all(b, "two layers", (&image, 0), &lens, 1e-5, |_, _| [0.85, 0.85, 0.25]);

    // An anti-aliased edge: an opaque white surface, its edge column half covered, nothing beyond
    // (alpha 0 and black: no data, black).
    let image = rgbz_exr("edge.exr", 11, 6, |x, _| match x {
        0..5 => ([1.0; 3], 1.0, 3.0),
        5 => ([0.5; 3], 0.5, 3.0),
        _ => ([0.0; 3], 0.0, 3.0),
    });
    assert_eq!(image.pixel(5, 0), [Fragment { color: [0.5; 3], alpha: 0.5, depth: 3.0 }]);
    assert_all(b, "anti-aliased edge", (&image, 0), &lens, 1e-5, |x, _| match x {
        0..5 => [1.0; 3],
        5 => [0.5; 3],
        _ => [0.0; 3],
    });
}

#[test]
fn in_focus_every_method_returns_the_composite_cpu() {
    in_focus_oracle(&mut CpuBackend::new());
}

#[test]
fn in_focus_every_method_returns_the_composite_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    in_focus_oracle(&mut vk);
    assert_clean(&mut vk);
}

/// A uniform pane of premultiplied `pane` at alpha `alpha` (depth 1.2, blurred) in front of a flat
/// wall (depth 3, blurred) over the whole frame.
fn pane_over_wall(w: u32, h: u32, pane: [f32; 3], alpha: f32, wall: [f32; 3]) -> LayeredImage {
    let mut image = LayeredImage::new(w, h, 2).unwrap();
    for y in 0..h {
        for x in 0..w {
            image.push(x, y, Fragment { color: pane, alpha, depth: 1.2 }).unwrap();
            image.push(x, y, Fragment::opaque(wall, 3.0)).unwrap();
        }
    }
    image
}

/// Out of focus, a uniform translucent pane over a wall gives the composite away from the frame's
/// edges (the wall shows through it): within 1e-3 (splatting's 10-bit alpha: 0.35 is stored as
/// 358/1023). At the edges, where half the blur's fragments lie beyond the frame, the methods
/// normalise by the coverage they found, which for a translucent layer is not the composite.
fn blurred_pane(b: &mut dyn Backend) {
    let (pane, alpha, wall) = ([0.7, 0.0, 0.07], 0.35, [0.1, 0.8, 0.3]);
    let image = pane_over_wall(48, 40, pane, alpha, wall);
    let want = [0, 1, 2].map(|c| pane[c] + (1.0 - alpha) * wall[c]);
    assert_all(b, "blurred pane over a wall", (&image, 12), &test_lens(0.01), 1e-3, |_, _| want);
}

#[test]
fn a_blurred_translucent_pane_shows_the_wall_cpu() {
    blurred_pane(&mut CpuBackend::new());
}

#[test]
fn a_blurred_translucent_pane_shows_the_wall_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    blurred_pane(&mut vk);
    assert_clean(&mut vk);
}

/// 100 panes of alpha 0.01, premultiplied red, 1 mm apart from 1.2 m, over an opaque green wall at
/// 1.5 m, out of focus (CoC radius 4.1 px, the wall 2 px): multi-layer splatting lets about
/// `0.99^100` = 0.366 of the wall through, as compositing does, where adding the panes' coverage
/// would hide it (`1 − 100·0.01`, 0.02 with 10-bit alpha, measured). Splatting stores alpha in 10
/// bits (0.01 as 10/1023, which alone gives 0.9902^100 = 0.375) and tells the panes apart by their
/// summed disc shares (`dof_shaders::splat::surfaces`): unmerged within `UNMERGED_TOL` (0.374
/// measured), merged 4x4 (16 times fewer, wider fragments, so coarser boundaries between the panes)
/// within `MERGED_TOL` (0.366 to 0.384 measured).
fn blurred_stack(b: &mut dyn Backend, merges: &[Merge]) {
    let (w, h, panes) = (40, 36, 100);
    let mut image = LayeredImage::new(w, h, panes + 1).unwrap();
    for y in 0..h {
        for x in 0..w {
            for k in 0..panes {
                image.push(x, y, Fragment { color: [0.01, 0.0, 0.0], alpha: 0.01, depth: 1.2 + 0.001 * k as f32 }).unwrap();
            }
            image.push(x, y, Fragment::opaque([0.0, 1.0, 0.0], 1.5)).unwrap();
        }
    }
    let lens = test_lens(0.03);
    let want = 0.99f32.powi(panes as i32);
    let multilayer = METHODS.iter().find(|m| m.name == "multilayer").unwrap();
    for &merge in merges {
        let tol = if merge == Merge::None { UNMERGED_TOL } else { MERGED_TOL };
        let options = MethodOptions { splat: SplatOptions { merge, ..Default::default() }, ..Default::default() };
        let got = one_shot(b, multilayer, &options, &image, &lens).unwrap().image;
        let (mut lo, mut hi) = (f32::INFINITY, f32::NEG_INFINITY);
        for y in 12..h - 12 {
            for x in 12..w - 12 {
                let through = got.get(x, y)[1];
                lo = lo.min(through);
                hi = hi.max(through);
                assert!(
                    (through - want).abs() <= tol,
                    "{merge:?} on {}: pixel ({x}, {y}) lets {through} of the wall through, the composite {want}",
                    b.kind()
                );
            }
        }
        eprintln!("{merge:?} on {}: {lo} to {hi} of the wall through (the composite {want})", b.kind());
    }
}

const UNMERGED_TOL: f32 = 0.01;
const MERGED_TOL: f32 = 0.02;

#[test]
fn a_blurred_stack_of_100_panes_lets_the_composite_through_cpu() {
    blurred_stack(&mut CpuBackend::new(), &[Merge::None, Merge::X4]);
}

/// Merged only on Vulkan: unmerged, the stack makes tile lists of 16 384 to 53 972 entries, and
/// lavapipe (llvmpipe) ends every loop of a shader invocation after 65 535 iterations in all
/// (Mesa's `LP_MAX_TGSI_LOOP_ITERATIONS`, shared between the loops): the accumulation's pixels stop
/// after about 11 500 entries and come out without the wall behind the panes (red 1.023, green 0).
/// Merged 4x4 (lists up to 4096) both backends agree.
#[test]
fn a_blurred_stack_of_100_panes_lets_the_composite_through_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    blurred_stack(&mut vk, &[Merge::X4]);
    assert_clean(&mut vk);
}

/// The report says when llvmpipe's loop limit may have cut a frame short: set for the unmerged
/// stack's lists on llvmpipe (and never on another driver or the CPU backend), clear when merged.
#[test]
fn the_report_flags_lists_beyond_llvmpipes_loop_limit() {
    let mut image = LayeredImage::new(40, 36, 21).unwrap();
    for y in 0..36 {
        for x in 0..40 {
            for k in 0..20 {
                image.push(x, y, Fragment { color: [0.001, 0.0, 0.0], alpha: 0.001, depth: 1.2 + 0.001 * k as f32 }).unwrap();
            }
            image.push(x, y, Fragment::opaque([0.0, 1.0, 0.0], 1.5)).unwrap();
        }
    }
    let lens = test_lens(0.03);
    let mut backends: Vec<Box<dyn Backend>> = vec![Box::new(CpuBackend::new())];
    if let Some(vk) = vulkan() {
        backends.push(Box::new(vk));
    }
    for b in &mut backends {
        let llvmpipe = b.driver().contains("llvmpipe");
        for merge in [Merge::None, Merge::X4] {
            let out = splat(b.as_mut(), &image, &lens, &SplatOptions { merge, ..Default::default() }).unwrap();
            let long = out.report.longest_list_wanted > LLVMPIPE_SAFE_LIST;
            assert_eq!(long, merge == Merge::None, "{merge:?}: longest list {}", out.report.longest_list_wanted);
            assert_eq!(out.report.driver_loop_limit, llvmpipe && long, "{merge:?} on {}", b.driver());
            assert_eq!(out.report.summary().contains("llvmpipe ends"), out.report.driver_loop_limit);
        }
    }
}

/// An EXR whose alpha is 0 everywhere (colour not black, depth finite): read as light that hides
/// nothing and noted, so every method shows the colour, never black.
#[test]
fn an_exr_with_alpha_0_everywhere_shows_its_colour() {
    use exr::WritableImage;
    let (w, h) = (8usize, 6usize);
    let colour = |p: usize| [0.3 + 0.01 * p as f32, 0.2, 0.1];
    let plane = |f: &dyn Fn(usize) -> f32| exr::FlatSamples::F32((0..w * h).map(f).collect());
    let channels = vec![
        exr::AnyChannel::new("R", plane(&|p| colour(p)[0])),
        exr::AnyChannel::new("G", plane(&|p| colour(p)[1])),
        exr::AnyChannel::new("B", plane(&|p| colour(p)[2])),
        exr::AnyChannel::new("A", plane(&|_| 0.0)),
        exr::AnyChannel::new("Z", plane(&|_| 3.0)),
    ];
    let path = temp("alpha0.exr");
    exr::Image::from_channels((w, h), exr::AnyChannels::sort(channels.into_iter().collect())).write().to_file(&path).unwrap();
    let (image, report) = read_layered_exr(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    assert_eq!(report.counts.emission_only, (w * h) as u64);
    assert!(report.total() > 0, "the CLI prints a note");
    assert!(report.to_string().contains("alpha 0 and a colour, read as light that hides nothing"), "{report}");
    assert_all(&mut CpuBackend::new(), "alpha 0 everywhere", (&image, 0), &test_lens(PINHOLE), 1e-5, |x, y| {
        colour(y as usize * w + x as usize)
    });
}

/// Alphas NaN or outside [0, 1] are clamped and counted in the reports, never silently: splatting
/// counts them on the device (`alpha_clamped`), the other frame-API methods in their clamp count.
#[test]
fn bad_alphas_are_clamped_and_counted() {
    let mut image = LayeredImage::new(16, 12, 2).unwrap();
    let bad = [f32::NAN, -0.5, 1.5, f32::INFINITY];
    for y in 0..12 {
        for x in 0..16 {
            let p = (y * 16 + x) as usize;
            let alpha = if p.is_multiple_of(8) { bad[(p / 8) % 4] } else { 0.5 };
            image.push(x, y, Fragment { color: [0.2, 0.3, 0.4], alpha, depth: 1.5 }).unwrap();
            image.push(x, y, Fragment::opaque([0.5; 3], 3.0)).unwrap();
        }
    }
    let bad_count = (16 * 12 / 8) as f64;
    let mut cpu = CpuBackend::new();
    for m in METHODS {
        let shot = one_shot(&mut cpu, m, &MethodOptions::default(), &image, &test_lens(0.01)).unwrap();
        let out = &shot.image;
        assert!(out.data.iter().flatten().all(|c| c.is_finite() && *c >= 0.0), "{}", m.name);
        if m.name == "multilayer" {
            assert_eq!(shot.report.figures()["alpha_clamped"], bad_count, "{}", shot.report.summary);
            assert!(shot.report.summary.contains(&format!("alpha: {bad_count} clamped")), "{}", shot.report.summary);
        }
        if ["layered", "raytrace"].contains(&m.name) {
            assert!(shot.report.summary.contains(&format!("{bad_count} input values clamped")), "{}: {}", m.name, shot.report.summary);
        }
    }
    // The one-shot path hands single-layer methods the flattened image (opaque; `dof render` counts
    // the input's alphas itself); through the frame API they read the caller's slots and count the
    // front slot's.
    let frame = ContextFrame { image: &image, lens: test_lens(0.01), resize: None };
    for name in ["gather", "ring-gather", "bokeh"] {
        let extent = Extent::new(image.width, image.height, image.max_layers);
        let (_, report) = context_frames(&mut cpu, name, &MethodOptions::default(), extent, std::slice::from_ref(&frame)).remove(0);
        assert!(report.summary.contains(&format!("{bad_count} input values clamped")), "{name}: {}", report.summary);
    }
}

/// A translucent scene: a noise wall, translucent panes of varied alpha in front of it (some
/// pixels with two, some of alpha 0), a sky at infinity in a corner; blurred.
fn translucent_scene(w: u32, h: u32) -> LayeredImage {
    let mut image = LayeredImage::new(w, h, 3).unwrap();
    for y in 0..h {
        for x in 0..w {
            let p = y * w + x;
            if (x / 6 + y / 5) % 2 == 0 {
                let alpha: f32 = [0.0, 0.2, 0.5, 0.9][(p % 4) as usize];
                image
                    .push(x, y, Fragment { color: varied(p).map(|c| 0.01 * c * alpha.max(0.1)), alpha, depth: 0.8 + 0.01 * (x % 7) as f32 })
                    .unwrap();
            }
            if x % 9 == 0 {
                image.push(x, y, Fragment { color: [0.2, 0.1, 0.4], alpha: 0.3, depth: 1.5 }).unwrap();
            }
            if x + y < 8 {
                image.push(x, y, Fragment::opaque([0.5, 0.6, 0.9], f32::INFINITY)).unwrap();
            } else {
                image.push(x, y, Fragment::opaque(varied(p * 3).map(|c| 0.01 * c), 4.0)).unwrap();
            }
        }
    }
    image
}

/// Every method on the CPU backend and on Vulkan, the same translucent frame: splatting bit for bit
/// (one rule in the shaders crate, exact on lavapipe), the others within 1e-4 of the image's peak
/// (the bounds `tests/tests/oracles.rs` states for them; bokeh sprites are rasterised on Vulkan).
#[test]
fn cpu_equals_vulkan_on_translucent_input() {
    let Some(mut vk) = vulkan() else { return };
    let image = translucent_scene(45, 38);
    let lens = test_lens(0.012);
    let mut cpu = CpuBackend::new();
    for m in METHODS {
        let run = |b: &mut dyn Backend, m: &MethodInfo| one_shot(b, m, &MethodOptions::default(), &image, &lens).unwrap().image;
        let (a, v) = (run(&mut cpu, m), run(&mut vk, m));
        if m.name == "multilayer" || m.name == "tiled" {
            assert!(a == v, "{}: CPU and Vulkan differ", m.name);
            continue;
        }
        let peak = a.data.iter().flatten().fold(0.0f32, |m, &c| m.max(c));
        let worst = a.data.iter().flatten().zip(v.data.iter().flatten()).map(|(x, y)| (x - y).abs()).fold(0.0f32, f32::max);
        assert!(worst <= 1e-4 * peak, "{}: CPU and Vulkan differ by {worst} (peak {peak})", m.name);
    }
    assert_clean(&mut vk);
}
