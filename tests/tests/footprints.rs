//! Footprints (`dof_shaders::footprint`): fragments splatted from the sub-samples of their pixel
//! that saw them. Energy kept and light moved where the footprint lies, on hand-built frames;
//! area-integrated scenes on Vulkan against the CPU, stage by stage; the frame API's checks.

use dof::backend::{Backend, CpuBackend};
use dof::frame::{ContextDesc, CountBuffer, Extent, Frame, MethodOptions, RgbBuffer, SlotBuffer, registry};
use dof::layers::{Fragment, LayeredImage, RgbImage};
use dof::methods::buffers::slot_words;
use dof::methods::splat::{Merge, SplatOptions, splat};
use dof::scene::{Camera, GuardBand, LayerOptions, builtin, raycast_layers};
use dof::stress::test_lens;
use dof_shaders::footprint;
use dof_shaders::lens::ThinLens;
use dof_tests::oracle::splat_stages::splat_with_stages;
use dof_tests::{assert_clean, vulkan};

const W: u32 = 24;

/// A `W`x`W` frame of a black wall at the test lens' focus (every pixel's sharp front, which takes
/// all the coverage left, so nothing is renormalised) with one emitter of energy `energy` at pixel
/// (11, 12), covering the sub-samples `mask` of a `side`² grid (alpha their share), at depth `z`.
fn one_emitter(side: u32, mask: u32, z: f32, energy: f32) -> LayeredImage {
    let mut img = LayeredImage::new(W, W, 2).unwrap();
    img.footprints = vec![footprint::WHOLE; img.fragments.len()];
    img.footprint_side = side;
    for y in 0..W {
        for x in 0..W {
            let p = img.pixel_index(x, y);
            if (x, y) == (11, 12) {
                let alpha = mask.count_ones() as f32 / (side * side) as f32;
                img.push(x, y, Fragment { color: [energy; 3], alpha, depth: z }).unwrap();
                img.footprints[2 * p] = mask;
            }
            img.push(x, y, Fragment { color: [0.0; 3], alpha: 1.0, depth: 2.0 }).unwrap();
        }
    }
    img
}

fn lens() -> ThinLens {
    test_lens(0.02)
}

fn energy(image: &RgbImage) -> f64 {
    image.data.iter().map(|p| p[0] as f64).sum()
}

/// The light-weighted mean position of an image (pixel centres at `x + ½`).
fn centroid(image: &RgbImage) -> [f64; 2] {
    let (mut sx, mut sy, mut s) = (0.0, 0.0, 0.0);
    for y in 0..image.height {
        for x in 0..image.width {
            let v = image.data[(y * image.width + x) as usize][0] as f64;
            sx += v * (x as f64 + 0.5);
            sy += v * (y as f64 + 0.5);
            s += v;
        }
    }
    [sx / s, sy / s]
}

#[test]
fn a_footprint_spreads_exactly_its_energy_from_where_it_lies() {
    let l = lens();
    for z in [0.6f32, 1.0, 1.4, 1.8] {
        let r = l.coc_radius_px(z);
        for (side, mask) in [(2u32, 0b0001u32), (2, 0b0101), (4, 0xffff), (4, 0x0033), (4, 0x8000)] {
            let img = one_emitter(side, mask, z, 1000.0);
            let out = splat(&mut CpuBackend::new(), &img, &l, &SplatOptions::default()).unwrap();
            let e = energy(&out.image);
            // A footprint of every sub-sample is the whole pixel, splatted from its centre by
            // splatting's own weight (normalised by its lattice sum, or beyond 4 px its integral).
            let tolerance = if mask == footprint::full(side) { 1e-3 } else { 1e-4 };
            assert!((e / 1000.0 - 1.0).abs() < tolerance, "CoC {r} px, {side}x{side} mask {mask:b}: energy {e}");
            // Out of focus, the light's centre is the mean of the footprint's sub-samples.
            let mut want = [0.0f64; 2];
            for k in 0..side * side {
                if mask & (1 << k) != 0 {
                    let o = dof_shaders::resolve::subsample_offset(k, side);
                    want[0] += (11.0 + o[0]) as f64 / mask.count_ones() as f64;
                    want[1] += (12.0 + o[1]) as f64 / mask.count_ones() as f64;
                }
            }
            let got = centroid(&out.image);
            if r > 1.0 {
                assert!((got[0] - want[0]).abs() < 0.03 && (got[1] - want[1]).abs() < 0.03, "CoC {r}: {got:?} against {want:?}");
            }
            // Without the footprint, the light is centred on the pixel.
            let whole = splat(&mut CpuBackend::new(), &img.clone().without_footprints(), &l, &SplatOptions::default()).unwrap();
            let c = centroid(&whole.image);
            assert!((c[0] - 11.5).abs() < 1e-3 && (c[1] - 12.5).abs() < 1e-3, "{c:?}");
        }
    }
}

/// Bits beyond the grid mean nothing: a footprint with none of its grid's bits, or all of them, is
/// the whole pixel.
#[test]
fn footprints_beyond_the_grid_are_the_whole_pixel() {
    let whole = splat(&mut CpuBackend::new(), &one_emitter(2, 0b1111, 1.2, 50.0).without_footprints(), &lens(), &SplatOptions::default());
    for mask in [0xfff0u32, 0xffff, 0b1111, 0] {
        let out = splat(&mut CpuBackend::new(), &one_emitter(2, mask, 1.2, 50.0), &lens(), &SplatOptions::default()).unwrap();
        // The emitter's alpha is its mask's share of the grid: compare light, not coverage.
        let img = one_emitter(2, 0b1111, 1.2, 50.0);
        let mut img = img.clone();
        img.footprints = one_emitter(2, mask, 1.2, 50.0).footprints;
        let same_alpha = splat(&mut CpuBackend::new(), &img, &lens(), &SplatOptions::default()).unwrap();
        assert_eq!(same_alpha.image.data, whole.as_ref().unwrap().image.data, "mask {mask:x}");
        assert!(energy(&out.image) > 0.0);
    }
}

#[test]
fn in_focus_footprints_change_nothing() {
    // Just in front of the test lens' focus (depth 2) the emitter is in focus too: a sharp front,
    // kept in its pixel, as without its footprint.
    let img = one_emitter(4, 0x0f0f, 1.999, 50.0);
    let a = splat(&mut CpuBackend::new(), &img, &lens(), &SplatOptions::default()).unwrap();
    let b = splat(&mut CpuBackend::new(), &img.clone().without_footprints(), &lens(), &SplatOptions::default()).unwrap();
    assert_eq!(a.image.data, b.image.data);
}

/// `highlights` ray cast at 4 and 16 sub-samples: every stage on Vulkan equals the CPU's, footprint
/// words included; the image within float rounding; and the footprints changed the image.
#[test]
fn area_integrated_scenes_on_vulkan_match_the_cpu() {
    let Some(mut vk) = vulkan() else { return };
    let scene = builtin("highlights").unwrap();
    let camera = Camera { width: 64, height: 36, ..scene.camera };
    let l = scene.lens.thin_lens(&camera).unwrap();
    for (subsamples, merge) in [(4, Merge::None), (16, Merge::X4)] {
        let options = LayerOptions { subsamples, guard_band: GuardBand::Pixels(2), ..LayerOptions::default() };
        let layers = raycast_layers(&scene.scene, &camera, &l, &options).unwrap().layers;
        assert!(layers.has_footprints());
        assert!(layers.footprints.iter().any(|&m| m != 0 && m != footprint::full(layers.footprint_side)), "partial footprints");
        let o = SplatOptions { merge, ..Default::default() };
        let on_vk = splat_with_stages(&mut vk, &layers, &l, &o).unwrap();
        assert_clean(&mut vk);
        let on_cpu = splat_with_stages(&mut CpuBackend::new(), &layers, &l, &o).unwrap();
        let (a, b) = (&on_vk.intermediates, &on_cpu.intermediates);
        assert!(a.dense == b.dense, "dense fragments and footprints ({subsamples} sub-samples)");
        assert!(a.sorted == b.sorted, "sorted lists ({subsamples} sub-samples)");
        for (p, q) in on_vk.image.data.iter().zip(&on_cpu.image.data) {
            for c in 0..3 {
                assert!((p[c] - q[c]).abs() <= 1e-5 * q[c].abs().max(1e-2), "{p:?} vs {q:?}");
            }
        }
        let without = splat(&mut CpuBackend::new(), &layers.clone().without_footprints(), &l, &o).unwrap();
        assert!(without.image.data != on_cpu.image.data, "the footprints moved light");
    }
}

#[test]
fn the_frame_api_checks_footprints() {
    let mut b = CpuBackend::new();
    let img = one_emitter(2, 0b0011, 1.2, 10.0);
    let words = slot_words(&img);
    let pixels = (W * W) as u64;
    let input = b.create_buffer(words.len() as u64, "test/input").unwrap();
    let counts = b.create_buffer(pixels, "test/counts").unwrap();
    let out = b.create_buffer(3 * pixels, "test/out").unwrap();
    b.write_buffer(input, 0, &words).unwrap();
    b.write_buffer(counts, 0, &img.counts).unwrap();
    let frame = Frame::layers(W, W, 2, lens(), SlotBuffer::current(input), CountBuffer(counts), RgbBuffer(out));
    let method = registry::method("multilayer").unwrap();
    let extent = Extent::new(W, W, 2);
    // A context made without room for footprints refuses a frame that has them.
    let mut plain = (method.create)(&mut b, &ContextDesc::new(extent, MethodOptions::default())).unwrap();
    let e = plain.record(&mut b, &frame.with_footprints(2)).unwrap_err().to_string();
    assert!(e.contains("footprints"), "{e}");
    plain.destroy(&mut b);
    let mut options = MethodOptions::default();
    options.splat.footprint_side = 2;
    let mut ctx = (method.create)(&mut b, &ContextDesc::new(extent, options)).unwrap();
    let e = ctx.record(&mut b, &frame.with_footprints(5)).unwrap_err().to_string();
    assert!(e.contains("grid"), "{e}");
    // The same frame through the frame API and through the one-shot path: the same image.
    ctx.record(&mut b, &frame.with_footprints(2)).unwrap();
    b.submit().unwrap();
    let got = b.read_buffer(out, 0, 3 * pixels).unwrap();
    let want = splat(&mut CpuBackend::new(), &img, &lens(), &SplatOptions::default()).unwrap();
    let want: Vec<u32> = want.image.data.iter().flat_map(|p| p.map(f32::to_bits)).collect();
    assert_eq!(got, want);
    ctx.destroy(&mut b);
    // A buffer without the footprint words is too small for a frame that says it has them.
    let short = b.create_buffer(words.len() as u64 - pixels * 2, "test/short").unwrap();
    let frame = Frame::layers(W, W, 2, lens(), SlotBuffer::current(short), CountBuffer(counts), RgbBuffer(out)).with_footprints(2);
    let mut options = MethodOptions::default();
    options.splat.footprint_side = 2;
    let mut ctx = (method.create)(&mut b, &ContextDesc::new(extent, options)).unwrap();
    assert!(ctx.record(&mut b, &frame).is_err());
    ctx.destroy(&mut b);
}

/// A floor receding from the eye, seen at a 2x2 grid of sub-samples: each pixel's upper sub-samples
/// see a part of it 6% farther than its lower ones, so the pixel resolves into two clusters side
/// by side (`dof_shaders::resolve`): the near half (blue) at alpha 1/2, and the far half (red) at
/// alpha 1, the composite's sense (all the light its own sub-samples let through). A black sky lies
/// behind, hidden. The frame's pixels all show half red and half blue; their depths interleave
/// from row to row, 12% apart.
fn receding_floor(w: u32, h: u32) -> LayeredImage {
    let mut img = LayeredImage::new(w, h, 3).unwrap();
    img.footprints = vec![footprint::WHOLE; img.fragments.len()];
    img.footprint_side = 2;
    let depth = |y: f32| 3.0 * 1.12f32.powf(2.0 * (h as f32 - y));
    for y in 0..h {
        for x in 0..w {
            let p = img.pixel_index(x, y);
            img.push(x, y, Fragment { color: [0.0, 0.0, 0.5], alpha: 0.5, depth: depth(y as f32 + 0.75) }).unwrap();
            img.footprints[3 * p] = 0b1100;
            img.push(x, y, Fragment { color: [1.0, 0.0, 0.0], alpha: 1.0, depth: depth(y as f32 + 0.25) }).unwrap();
            img.footprints[3 * p + 1] = 0b0011;
            img.push(x, y, Fragment { color: [0.0; 3], alpha: 1.0, depth: f32::INFINITY }).unwrap();
        }
    }
    img
}

/// The floor blurs to what its pixels show, half red and half blue, away from the frame's edge
/// (where the light from beyond it is missing and the sky fills in), within the 2% a destination's
/// summed disc shares stray from 1 on the lattice. Spending each cluster's composite alpha of the
/// coverage budget instead lets the far half count twice (red 2/3, blue 1/3); and a partial
/// footprint's alpha taken for a pane's, seen through the nearer rows, lets the sky darken it.
fn side_by_side_halves(b: &mut dyn Backend) {
    let (w, h) = (24, 48);
    let img = receding_floor(w, h);
    let l = test_lens(0.03);
    let edge = l.coc_radius_px(f32::INFINITY).ceil() as u32 + 1;
    assert!(l.coc_radius_px(3.0) > 1.5 && 2 * edge < w);
    for merge in [Merge::None, Merge::X4] {
        let out = splat(b, &img, &l, &SplatOptions { merge, ..Default::default() }).unwrap();
        for y in edge..h - edge {
            for x in edge..w - edge {
                let p = out.image.data[(y * w + x) as usize];
                assert!((p[0] - 0.5).abs() < 2e-2 && p[1] == 0.0 && (p[2] - 0.5).abs() < 2e-2, "{merge:?}, pixel ({x}, {y}): {p:?}");
            }
        }
    }
}

#[test]
fn side_by_side_halves_of_a_pixel_blur_to_their_share_cpu() {
    side_by_side_halves(&mut CpuBackend::new());
}

#[test]
fn side_by_side_halves_of_a_pixel_blur_to_their_share_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    side_by_side_halves(&mut vk);
    assert_clean(&mut vk);
}
