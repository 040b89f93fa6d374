//! Oracles over every method of the frame API's registry: what a method returns compared with what
//! it should return, on small random multi-layer images (sizes that are and are not multiples of
//! 16, 1 to 4 layers, depths from 0.5 to 40 units and the sky at +inf, colours from 0 to 10^4).
//! The methods are iterated from `METHODS` and run through the one-shot path; nothing here names
//! a method except the tables of tolerances, which must hold an entry for every registered method
//! (a new method fails here until its tolerances are stated).
//!
//! - **In focus**: through the test lens with a pinhole-sized aperture (radius 1e-7: every CoC is
//!   under 1e-4 px), every method returns the input's front composite: the front fragment's colour
//!   (fragments are opaque), the sky where that is the front fragment, black where a pixel has none.
//! - **Finite and non-negative**: finite, non-negative input gives finite, non-negative output at
//!   any aperture.
//! - **Energy**: an image at one depth (a random patch over a flat colour) keeps its mean over a
//!   window that holds the patch's blur and stays clear of the frame's edges.
//! - **CPU equals Vulkan**: the same frame on both backends (validation on), within the tolerances
//!   the method suites state.

use dof::backend::{Backend, CpuBackend};
use dof::frame::{METHODS, MethodInfo, MethodOptions, RaytraceOptions, Scale, Tolerances, VulkanTolerance};
use dof::layers::{Fragment, LayeredImage, RgbImage};
use dof::methods::one_shot::one_shot;
use dof::stress::test_lens;
use dof_shaders::lens::ThinLens;
use dof_tests::{assert_clean, vulkan};
use proptest::prelude::*;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

/// Image edges: multiples of 16 and not, down to one pixel.
const EDGES: &[u32] = &[1, 5, 16, 17, 24, 33];

/// A random multi-layer image: per pixel 0 to `layers` opaque fragments front to back (a pixel
/// without any is rare), depths in [0.5, 40] growing by at least 0.01, the last one the sky at +inf
/// a quarter of the time; every channel 0 (one time in eight) or log-uniform in [1e-3, 1e4].
fn random_image(w: u32, h: u32, layers: u32, seed: u64) -> LayeredImage {
    let mut rng = Pcg64::seed_from_u64(seed);
    let mut img = LayeredImage::new(w, h, layers).expect("a small image");
    for y in 0..h {
        for x in 0..w {
            let n = if rng.random_range(0..32) == 0 { 0 } else { rng.random_range(1..=layers) };
            let mut depth = rng.random_range(0.5f32..20.0);
            for k in 0..n {
                let sky = k + 1 == n && rng.random_range(0..4) == 0;
                let color = [0; 3].map(|_| if rng.random_range(0..8) == 0 { 0.0 } else { 10f32.powf(rng.random_range(-3.0f32..4.0)) });
                let d = if sky { f32::INFINITY } else { depth };
                assert!(img.push(x, y, Fragment { color, alpha: 1.0, depth: d }).expect("front to back"));
                depth += rng.random_range(0.01f32..5.0);
            }
        }
    }
    img
}

fn run(b: &mut dyn Backend, m: &MethodInfo, image: &LayeredImage, lens: &ThinLens) -> RgbImage {
    let out = one_shot(b, m, &MethodOptions::default(), image, lens).unwrap_or_else(|e| panic!("{}: {e}", m.name));
    assert_eq!((out.image.width, out.image.height), (image.width, image.height), "{}: output size", m.name);
    out.image
}

/// The largest difference relative to `max(|want|, floor)` over every channel, and where.
fn worst_relative(got: &RgbImage, want: &RgbImage, floor: f32) -> (f32, usize) {
    let mut worst = (0.0f32, 0);
    for (i, (g, w)) in got.data.iter().zip(&want.data).enumerate() {
        for c in 0..3 {
            let e = if g[c].to_bits() == w[c].to_bits() { 0.0 } else { (g[c] - w[c]).abs() / w[c].abs().max(floor) };
            if !(e <= worst.0) {
                worst = (e, i);
            }
        }
    }
    worst
}

/// A `side`x`side` image at one depth (or the sky): a random `patch`-wide square at the centre
/// over a flat colour, one opaque fragment a pixel.
fn flat_depth_image(side: u32, patch: u32, depth: f32, seed: u64) -> LayeredImage {
    let mut rng = Pcg64::seed_from_u64(seed);
    let flat = [0; 3].map(|_| 10f32.powf(rng.random_range(-2.0f32..3.0)));
    let lo = (side - patch) / 2;
    let inside = |v: u32| (lo..lo + patch).contains(&v);
    let mut img = LayeredImage::new(side, side, 1).expect("a small image");
    for y in 0..side {
        for x in 0..side {
            let color = if inside(x) && inside(y) { [0; 3].map(|_| 10f32.powf(rng.random_range(-3.0f32..4.0))) } else { flat };
            img.push(x, y, Fragment { color, alpha: 1.0, depth }).expect("one fragment");
        }
    }
    img
}

/// The mean of each channel over the pixels at least `margin` from every edge.
fn window_mean(img: &RgbImage, margin: u32) -> [f64; 3] {
    let mut sum = [0.0f64; 3];
    let mut n = 0.0;
    for y in margin..img.height - margin {
        for x in margin..img.width - margin {
            let p = img.get(x, y);
            (0..3).for_each(|c| sum[c] += p[c] as f64);
            n += 1.0;
        }
    }
    sum.map(|s| s / n)
}

fn size() -> impl Strategy<Value = (u32, u32)> {
    (prop::sample::select(EDGES), prop::sample::select(EDGES))
}

/// The tolerances each registry entry states ([`MethodInfo::tolerances`]), with the reasons:
/// - in focus, the gathering baseline (and bokeh sprites, whose blur it is): a sub-pixel CoC gives
///   the pixel's own sample the weight `w = 1 / (r + 1/2)²`, not a power of two, and the result is
///   `(w·c)·(1/w)`: two roundings, so within 2 ulp (2.4e-7 relative; measured 1.2e-7). The others
///   copy the front layer through bit for bit (splatting copies tiles without a list, ray tracing
///   hits the pixel's own front fragment, layered DoF and the ring gather composite the pixel
///   alone, scatter-as-you-gather copies a tile whose kernel is under half a pixel).
/// - energy: splatting stores a fragment's colour as half floats (a relative rounding of up to
///   2^-11 a value, 4.9e-4; measured 1.4e-4 on the mean), so 1e-3; the others sum in f32 over at
///   most a few hundred pixels, measured at most 2.5e-6, so 1e-5. Ray tracing is run with one lens
///   sample pattern for every pixel, which makes it a convolution (measured 3e-8); with its default
///   16 patterns it keeps the mean only in expectation (1% to 9% off on these patches).
/// - Vulkan: the bounds the method suites state (`splat.rs`, `gather.rs`, `ring_gather.rs`,
///   `bokeh.rs`, `raytrace.rs`, `layered.rs`): a driver may contract `a·b + c` into an FMA or round
///   a division differently, the sprite rasteriser interpolates what the CPU fallback computes, a
///   ray grazing a pixel corner may go either way. On lavapipe the gathers, ray tracing and
///   layered DoF measured bit for bit on these images, splatting within 2.3e-6 and bokeh sprites
///   within 3.2e-5 (relative to `max(|cpu|, 1e-3)`); scatter-as-you-gather is held to bit for bit,
///   as its suite holds it.
fn tolerances_of(m: &MethodInfo) -> Tolerances {
    m.tolerances
}

/// The pinhole-sized aperture: every CoC of the test lens between 0.5 units and +inf is under
/// 1e-4 px.
const PINHOLE: f32 = 1e-7;

/// Apertures from a pinhole to 1 unit (a far-field CoC of about 400 px, beyond every method's cap).
fn aperture() -> impl Strategy<Value = f32> {
    prop_oneof![Just(0.0f32), Just(PINHOLE), 0.0f32..0.002, 0.002f32..0.03, 0.03f32..1.0]
}

/// A case of the non-negativity oracle: a pixel bright enough for a bokeh sprite, red, with
/// a blue neighbour in its 5x5 window. A sprite carrying the pixel's excess over the neighbourhood mean channel by
/// channel would have a negative blue channel, and so would the image; every method gives a
/// non-negative image (the case kept as a plain test, since random seeds change run to run).
#[test]
fn a_red_highlight_beside_a_blue_one_stays_non_negative() {
    let mut image = LayeredImage::new(24, 24, 1).unwrap();
    for y in 0..24 {
        for x in 0..24 {
            let color = match (x, y) {
                (12, 12) => [5000.0, 0.0, 0.0],
                (14, 12) => [0.0, 0.0, 2400.0],
                _ => [0.0; 3],
            };
            image.push(x, y, Fragment { color, alpha: 1.0, depth: 10.0 }).unwrap();
        }
    }
    let mut cpu = CpuBackend::new();
    for m in METHODS {
        let out = run(&mut cpu, m, &image, &test_lens(0.02));
        let bad = out.data.iter().position(|p| !p.iter().all(|c| c.is_finite() && *c >= 0.0));
        assert!(bad.is_none(), "{}: pixel {bad:?} is {:?}", m.name, bad.map(|i| out.data[i]));
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 16, ..ProptestConfig::default() })]

    /// In focus, every method returns the input's front composite (within its stated tolerance).
    #[test]
    fn in_focus_every_method_returns_the_front_composite((w, h) in size(), layers in 1u32..=4, seed: u64) {
        let image = random_image(w, h, layers, seed);
        let (front, _) = image.front();
        let mut cpu = CpuBackend::new();
        for m in METHODS {
            let out = run(&mut cpu, m, &image, &test_lens(PINHOLE));
            let (err, i) = worst_relative(&out, &front, f32::MIN_POSITIVE);
            let tol = tolerances_of(m).in_focus;
            prop_assert!(
                err <= tol,
                "{} {w}x{h}, {layers} layers: pixel {i} is {:?}, the front composite {:?} ({err:.3e} > {tol:.1e} relative)",
                m.name, out.data[i], front.data[i]
            );
        }
    }

    /// Finite, non-negative input gives finite, non-negative output at any aperture.
    #[test]
    fn output_is_finite_and_non_negative((w, h) in size(), layers in 1u32..=4, seed: u64, aperture in aperture()) {
        let image = random_image(w, h, layers, seed);
        let mut cpu = CpuBackend::new();
        for m in METHODS {
            let out = run(&mut cpu, m, &image, &test_lens(aperture));
            if let Some(i) = out.data.iter().position(|p| !p.iter().all(|c| c.is_finite() && *c >= 0.0)) {
                prop_assert!(false, "{} {w}x{h}, {layers} layers, aperture {aperture}: pixel {i} is {:?}", m.name, out.data[i]);
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, ..ProptestConfig::default() })]

    /// A 64x64 image at one depth (a random 16x16 patch over a flat colour, CoC radius 0.5 to 4
    /// px): the mean over the pixels at least 12 from the frame's edges (12 from the patch too:
    /// they hold the patch's blur, Gaussian tails included, and take as much of the flat colour as
    /// they give) is kept.
    #[test]
    fn a_flat_depth_image_keeps_its_mean(depth in prop_oneof![0.5f32..40.0, Just(f32::INFINITY)], radius in 0.5f32..4.0, seed: u64) {
        let image = flat_depth_image(64, 16, depth, seed);
        let lens = test_lens(radius / test_lens(1.0).coc_radius_px(depth));
        // One lens-sample pattern for every pixel: ray tracing becomes a convolution.
        let options = MethodOptions { raytrace: RaytraceOptions { patterns: 1, ..Default::default() }, ..Default::default() };
        let want = window_mean(&image.front().0, 12);
        let mut cpu = CpuBackend::new();
        for m in METHODS {
            let out = one_shot(&mut cpu, m, &options, &image, &lens).unwrap_or_else(|e| panic!("{}: {e}", m.name)).image;
            let got = window_mean(&out, 12);
            let err = (0..3).map(|c| (got[c] / want[c] - 1.0).abs()).fold(0.0, f64::max);
            let tol = tolerances_of(m).energy;
            prop_assert!(err <= tol, "{} at depth {depth}, CoC radius {radius} px: mean {got:?}, input {want:?} ({err:.3e} > {tol:.0e})", m.name);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 4, ..ProptestConfig::default() })]

    /// The same frame on Vulkan (validation on) and on the CPU, within the stated tolerances.
    #[test]
    fn vulkan_equals_the_cpu((w, h) in size(), layers in 1u32..=4, seed: u64, aperture in prop_oneof![Just(PINHOLE), 0.0f32..0.03]) {
        let Some(mut vk) = vulkan() else { return Ok(()) };
        let image = random_image(w, h, layers, seed);
        let mut cpu = CpuBackend::new();
        for m in METHODS {
            let a = run(&mut cpu, m, &image, &test_lens(aperture));
            let b = run(&mut vk, m, &image, &test_lens(aperture));
            assert_clean(&mut vk);
            let VulkanTolerance { rel, scale, share } = tolerances_of(m).vulkan;
            let peak = a.data.iter().flatten().fold(0.0f32, |m, &v| m.max(v));
            let bound = |c: f32| rel * match scale { Scale::Value(floor) => c.abs().max(floor), Scale::Peak => peak };
            let differing: Vec<usize> =
                (0..a.data.len()).filter(|&i| (0..3).any(|c| !((a.data[i][c] - b.data[i][c]).abs() <= bound(a.data[i][c])))).collect();
            let allowed = a.data.len().checked_div(share).unwrap_or(0);
            prop_assert!(
                differing.len() <= allowed,
                "{} {w}x{h}, {layers} layers, aperture {aperture}: {} pixels beyond the tolerance (allowed {allowed}), first {:?}",
                m.name, differing.len(), differing.first().map(|&i| (i, a.data[i], b.data[i]))
            );
        }
    }
}
