//! Area-integrated multi-layer images (`dof_shaders::resolve`): the resolve rule on hand-built
//! sub-sample sets, the ray caster's energy on a scene, and the device resolve (the `resolve`
//! kernel, and the mesh peel at sub-sample resolution) against the host, bit for bit, on the CPU
//! backend and on Vulkan.

use dof::backend::{Backend, CpuBackend, RunKernel, groups_for};
use dof::layers::LayeredImage;
use dof::methods::buffers::slot_words;
use dof::raster::{MeshPeelContext, MeshPeelDesc, default_near, peel_layers};
use dof::scene::{Camera, ExportOptions, GuardBand, LayerOptions, MeshScene, builtin, export_glb, load_gltf_slice, raycast_layers};
use dof::scene::{check_subsamples, resolve_subsamples};
use dof_shaders::resolve::{RESOLVE, ResolveParams, Resolved, Sample, resolve, resolve_pixel};
use dof_shaders::slot::SLOT_WORDS;
use dof_tests::{assert_clean, vulkan};

fn frag(color: [f32; 3], depth: f32) -> Sample {
    Sample { color, alpha: 1.0, depth }
}

/// Resolves hand-built sub-sample lists into at most `layers` fragments (premultiplied colour).
fn run(lists: &[Vec<Sample>], layers: u32, tolerance: f32) -> (Vec<Sample>, Resolved) {
    let (out, _, r) = run_with_footprints(lists, layers, tolerance);
    (out, r)
}

/// [`run`], with each fragment's footprint.
fn run_with_footprints(lists: &[Vec<Sample>], layers: u32, tolerance: f32) -> (Vec<Sample>, Vec<u32>, Resolved) {
    let mut out = vec![frag([0.0; 3], 0.0); layers as usize];
    let mut footprints = vec![0; layers as usize];
    let r = resolve_pixel(
        lists.len() as u32,
        |s| lists[s as usize].len() as u32,
        |s, k| lists[s as usize][k as usize],
        layers,
        tolerance,
        |k, f, footprint| {
            out[k as usize] = f;
            footprints[k as usize] = footprint;
        },
    );
    out.truncate(r.count as usize);
    footprints.truncate(r.count as usize);
    (out, footprints, r)
}

#[test]
fn each_fragment_knows_the_sub_samples_that_saw_it() {
    let (e, w, sky) = ([50.0, 40.0, 30.0], [0.2; 3], [0.0; 3]);
    // Sub-samples 1 and 3 see an emitter in front of a wall, 0 and 2 the wall, and sub-sample 2
    // the sky behind it (the wall casts no umbra there).
    let lists = vec![
        vec![frag(w, 8.0)],
        vec![frag(e, 2.0), frag(w, 8.0)],
        vec![frag(w, 8.0), frag(sky, f32::INFINITY)],
        vec![frag(e, 2.0), frag(w, 8.0)],
    ];
    let (out, footprints, r) = run_with_footprints(&lists, 4, 0.05);
    assert_eq!((r.count, r.merged), (3, 0));
    assert_eq!(out[0].alpha, 0.5);
    assert_eq!(footprints, vec![0b1010, 0b1111, 0b0100]);
    // Clusters composited into the last slot join their footprints.
    let (_, footprints, r) = run_with_footprints(&lists, 2, 0.05);
    assert_eq!((r.count, r.merged), (2, 1));
    assert_eq!(footprints, vec![0b1010, 0b1111]);
    let (_, footprints, _) = run_with_footprints(&lists, 1, 0.05);
    assert_eq!(footprints, vec![0b1111]);
    // Black, fully transparent fragments give no sub-sample to a footprint.
    let lists = vec![vec![Sample { color: [0.0; 3], alpha: 0.0, depth: 3.0 }], vec![frag(e, 3.0)], vec![], vec![]];
    let (_, footprints, _) = run_with_footprints(&lists, 4, 0.05);
    assert_eq!(footprints, vec![0b0010]);
}

/// Front-to-back "over" of premultiplied fragments.
fn composite(fragments: &[Sample]) -> [f32; 3] {
    let (mut c, mut t) = ([0.0f32; 3], 1.0f32);
    for f in fragments {
        for j in 0..3 {
            c[j] += t * f.color[j];
        }
        t *= 1.0 - f.alpha;
    }
    c
}

fn close(a: f32, b: f32) -> bool {
    (a - b).abs() <= 1e-6 * a.abs().max(b.abs()).max(1.0)
}

#[test]
fn a_half_covered_edge_pixel_keeps_its_front_at_half_coverage_and_what_lies_behind() {
    let (f, b) = ([1.0, 0.5, 0.25], [0.0, 0.2, 0.8]);
    // Two sub-samples see the front surface (the back one hidden behind it), two the back one.
    let lists = vec![vec![frag(f, 2.0), frag(b, 9.0)], vec![frag(f, 2.0), frag(b, 9.0)], vec![frag(b, 9.0)], vec![frag(b, 9.0)]];
    let (out, r) = run(&lists, 4, 0.05);
    assert_eq!((r.count, r.merged), (2, 0));
    assert_eq!(out[0].alpha, 0.5);
    assert_eq!(out[0].depth, 2.0);
    assert_eq!(out[1].alpha, 1.0, "the back surface lies behind the whole pixel");
    assert_eq!(out[1].depth, 9.0);
    // The composite is the pixel's area mean.
    let c = composite(&out);
    for j in 0..3 {
        assert!(close(c[j], 0.5 * f[j] + 0.5 * b[j]), "{c:?}");
    }
    // Where the back surface was only seen beside the front one (the front's umbra hid it in the
    // other lists), it covers what the front leaves: the composite is the same area mean.
    let lists = vec![vec![frag(f, 2.0)], vec![frag(f, 2.0)], vec![frag(b, 9.0)], vec![frag(b, 9.0)]];
    let (out, _) = run(&lists, 4, 0.05);
    assert_eq!((out[0].alpha, out[1].alpha), (0.5, 1.0));
    let c = composite(&out);
    for j in 0..3 {
        assert!(close(c[j], 0.5 * f[j] + 0.5 * b[j]), "{c:?}");
    }
}

/// Where the front surface's sub-samples see past the surface beside it to something farther (a
/// floor receding from the eye, split in two clusters by depth, with the sky beyond its umbra; two
/// objects side by side over the sky), the surface beside still covers all the front leaves
/// open: the composite is the area mean, not darkened by the sky the front hides.
#[test]
fn a_surface_beside_the_front_covers_what_the_front_leaves_open() {
    let (near, far, sky) = ([0.2, 0.4, 0.6], [0.6, 0.3, 0.1], [0.0, 0.0, 0.0]);
    let at_inf = frag(sky, f32::INFINITY);
    for lists in [
        vec![vec![frag(near, 18.8), at_inf], vec![frag(near, 18.9), at_inf], vec![frag(far, 20.0), at_inf], vec![frag(far, 20.1), at_inf]],
        vec![vec![frag(near, 2.0), at_inf], vec![frag(near, 2.0), at_inf], vec![frag(near, 2.0), at_inf], vec![frag(far, 9.0), at_inf]],
    ] {
        let (out, r) = run(&lists, 4, 0.05);
        let near_share = lists.iter().filter(|l| l[0].color == near).count() as f32 / 4.0;
        assert_eq!(r.count, 3, "{out:?}");
        assert_eq!((out[0].alpha, out[1].alpha), (near_share, 1.0), "{out:?}");
        assert_eq!(out[2].depth, f32::INFINITY, "the sky stays, for the lens points that see past the surfaces: {out:?}");
        let c = composite(&out);
        for j in 0..3 {
            assert!(close(c[j], near_share * near[j] + (1.0 - near_share) * far[j]), "{c:?} from {out:?}");
        }
    }
}

#[test]
fn a_sub_pixel_emitter_keeps_its_energy_at_partial_coverage() {
    let (e, w) = ([5000.0, 4000.0, 3000.0], [0.1, 0.1, 0.1]);
    let mut lists: Vec<Vec<Sample>> = (0..15).map(|_| vec![frag(w, 10.0), frag([0.0; 3], f32::INFINITY)]).collect();
    lists.insert(5, vec![frag(e, 3.0), frag(w, 10.0), frag([0.0; 3], f32::INFINITY)]);
    let (out, r) = run(&lists, 4, 0.05);
    assert_eq!(r.count, 3);
    assert_eq!(out[0].alpha, 1.0 / 16.0);
    assert_eq!(out[0].depth, 3.0);
    for j in 0..3 {
        assert_eq!(out[0].color[j], e[j] / 16.0, "premultiplied: the emitter's energy over the pixel");
        assert_eq!(out[0].color[j] / out[0].alpha, e[j], "its radiance");
    }
    assert_eq!((out[1].alpha, out[1].depth), (1.0, 10.0));
    assert_eq!(out[2].depth, f32::INFINITY, "the background last");
    let c = composite(&out);
    for j in 0..3 {
        assert!(close(c[j], (e[j] + 15.0 * w[j]) / 16.0), "{c:?}");
    }
}

#[test]
fn clusters_beyond_the_layers_are_composited_into_the_last() {
    // Four sub-samples, each a surface of its own at 1, 2, 3 and 4: four clusters, two layers.
    let colors = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 1.0, 1.0]];
    let lists: Vec<Vec<Sample>> = (0..4).map(|i| vec![frag(colors[i], 1.0 + i as f32)]).collect();
    let (out, r) = run(&lists, 2, 0.05);
    assert_eq!((r.count, r.merged), (2, 2));
    assert_eq!((out[0].alpha, out[0].depth), (0.25, 1.0));
    // The second holds the 2nd cluster (seen by 3 lists, covering 1 of them) and the rest "over".
    assert_eq!(out[1].depth, 2.0, "the merged tail keeps its first cluster's depth");
    let c = composite(&out);
    for j in 0..3 {
        let mean = colors.iter().map(|c| c[j]).sum::<f32>() / 4.0;
        assert!(close(c[j], mean), "no energy lost: {c:?}");
    }
    // Clusters within the tolerance are one surface; beyond it, two.
    let lists = vec![vec![frag([1.0; 3], 10.0)], vec![frag([1.0; 3], 10.3)]];
    assert_eq!(run(&lists, 4, 0.05).1.count, 1);
    assert_eq!(run(&lists, 4, 0.01).1.count, 2);
}

#[test]
fn one_sub_sample_resolves_to_its_own_list() {
    let list = vec![frag([0.3, 0.2, 0.1], 1.5), frag([2.0, 1.0, 0.5], 4.0), frag([0.5; 3], f32::INFINITY)];
    let (out, r) = run(std::slice::from_ref(&list), 4, 0.05);
    assert_eq!(r.count, 3);
    assert_eq!(out, list);
    // Translucent members (premultiplied) composite within their list.
    let list = vec![Sample { color: [1.0, 0.0, 0.0], alpha: 0.5, depth: 2.0 }, Sample { color: [0.0, 1.0, 0.0], alpha: 0.5, depth: 2.01 }];
    let (out, _) = run(&[list], 4, 0.05);
    assert_eq!(out.len(), 1);
    assert_eq!(out[0].alpha, 0.75);
    assert_eq!(out[0].color, [1.0, 0.5, 0.0]);
}

#[test]
fn sub_sample_counts_are_checked() {
    for n in [1, 4, 9, 16] {
        check_subsamples(n).unwrap();
    }
    for n in [0, 2, 3, 8, 25] {
        assert!(check_subsamples(n).unwrap_err().to_string().contains("1, 4, 9 or 16"));
    }
    let s = builtin("highlights").unwrap().with_size(32, 18);
    let lens = s.thin_lens().unwrap();
    assert!(raycast_layers(&s.scene, &s.camera, &lens, &LayerOptions { subsamples: 3, ..LayerOptions::default() }).is_err());
}

fn frame_only(subsamples: u32) -> LayerOptions {
    LayerOptions { guard_band: GuardBand::Off, disocclusion: false, subsamples, ..LayerOptions::default() }
}

/// Front-to-back composite of every pixel of an image (premultiplied colour).
fn pinhole(layers: &LayeredImage) -> Vec<[f64; 3]> {
    (0..layers.counts.len())
        .map(|p| {
            let (x, y) = (p as u32 % layers.width, p as u32 / layers.width);
            let (mut c, mut t) = ([0.0f64; 3], 1.0f64);
            for f in layers.pixel(x, y) {
                for j in 0..3 {
                    c[j] += t * f.color[j] as f64;
                }
                t *= 1.0 - f.alpha as f64;
            }
            c
        })
        .collect()
}

#[test]
fn area_integrated_layers_keep_the_energy_of_their_sub_samples() {
    let s = builtin("highlights").unwrap().with_size(96, 54);
    let lens = s.thin_lens().unwrap();
    // The 4x4 sub-samples as pixels of a 4x finer image (the same stratum centres), point-sampled.
    let fine = raycast_layers(&s.scene, &Camera { width: 4 * 96, height: 4 * 54, ..s.camera }, &lens, &frame_only(1)).unwrap();
    let area = raycast_layers(&s.scene, &s.camera, &lens, &frame_only(16)).unwrap();
    let point = raycast_layers(&s.scene, &s.camera, &lens, &frame_only(1)).unwrap();
    let total = |img: &[[f64; 3]]| img.iter().map(|c| c[0] + c[1] + c[2]).sum::<f64>();
    let want = total(&pinhole(&fine.layers)) / 16.0;
    let got = total(&pinhole(&area.layers));
    let was = total(&pinhole(&point.layers));
    assert!(((got - want) / want).abs() < 1e-4, "area-integrated {got} against its sub-samples' {want}");
    assert!(((was - want) / want).abs() > 0.05, "the point-sampled layers' energy {was} should be off the area mean {want}");
    // Pixel by pixel: the composite is the sub-samples' mean except where three or more surfaces
    // overlap with correlated coverage ("over" cannot express it; docs/scenes-and-references.md).
    let fine_px = pinhole(&fine.layers);
    let mut worst = 0.0f64;
    let mut off = 0usize;
    for (p, c) in pinhole(&area.layers).iter().enumerate() {
        let (x, y) = (p % 96, p / 96);
        let mut mean = [0.0f64; 3];
        for k in 0..16 {
            let q = (4 * y + k / 4) * 4 * 96 + 4 * x + k % 4;
            for j in 0..3 {
                mean[j] += fine_px[q][j] / 16.0;
            }
        }
        let d = (0..3).map(|j| (c[j] - mean[j]).abs() / mean[j].abs().max(1.0)).fold(0.0, f64::max);
        worst = worst.max(d);
        off += (d > 1e-4) as usize;
    }
    eprintln!("pixels off the area mean by more than 1e-4: {off} of {}; largest departure {worst}", 96 * 54);
    assert!(off * 100 <= 96 * 54, "{off} pixels off the area mean");
    assert!(worst < 0.05, "largest per-pixel departure from the area mean {worst}");
    // The area-integrated image has pixels of partial coverage; the point-sampled one none.
    assert!(area.layers.fragments.iter().any(|f| f.alpha > 0.0 && f.alpha < 1.0));
    assert!(point.layers.fragments.iter().all(|f| f.alpha == 0.0 || f.alpha == 1.0));
}

/// A layered image's slots and counts uploaded as the device holds them.
fn upload(b: &mut dyn Backend, image: &LayeredImage) -> (dof::backend::BufferId, dof::backend::BufferId) {
    let words = slot_words(image);
    let f = b.create_buffer(words.len() as u64, "test/fine").unwrap();
    b.write_buffer(f, 0, &words).unwrap();
    let c = b.create_buffer(image.counts.len() as u64, "test/fine-counts").unwrap();
    b.write_buffer(c, 0, &image.counts).unwrap();
    (f, c)
}

/// The `resolve` kernel on a ray-cast sub-sample image equals the host's resolve, bit for bit.
fn kernel_equals_host_on(b: &mut dyn Backend) {
    let s = builtin("columns").unwrap();
    let (w, h, side) = (48u32, 27u32, 4u32);
    let lens = s.lens.thin_lens(&Camera { width: w, height: h, ..s.camera }).unwrap();
    let fine = raycast_layers(&s.scene, &Camera { width: w * side, height: h * side, ..s.camera }, &lens, &frame_only(1)).unwrap().layers;
    let layers = 3;
    let want = resolve_subsamples(&fine, side, layers, 0.05).unwrap();
    assert!(want.fragments.iter().any(|f| f.alpha > 0.0 && f.alpha < 1.0), "the image has partly covered fragments");
    assert!(want.counts.contains(&layers), "some pixel is full");
    let (ff, fc) = upload(b, &fine);
    let pixels = (w * h) as u64;
    let words = SLOT_WORDS as u64 * pixels * layers as u64;
    let out = b.create_buffer(words, "test/slots").unwrap();
    let counts = b.create_buffer(pixels, "test/counts").unwrap();
    b.fill(out, 0, words, 0, "test").unwrap();
    let params = ResolveParams { width: w, height: h, side, fine_layers: fine.max_layers, layers, tolerance: 0.05, footprints: 0, _pad: 0 };
    b.run(resolve::Bindings { fine: ff, fine_counts: fc, fragments: out, counts }, groups_for(&RESOLVE, pixels), &params, "test/resolve")
        .unwrap();
    b.submit().unwrap();
    let got_counts = b.read_buffer(counts, 0, pixels).unwrap();
    let got = b.read_buffer(out, 0, words).unwrap();
    assert_eq!(got_counts, want.counts);
    let want_words = slot_words(&want);
    for p in 0..pixels as usize {
        let n = SLOT_WORDS as usize * want.counts[p] as usize;
        let at = SLOT_WORDS as usize * p * layers as usize;
        assert_eq!(got[at..at + n], want_words[at..at + n], "pixel {p}");
    }
    for id in [ff, fc, out, counts] {
        b.destroy_buffer(id);
    }
}

#[test]
fn the_resolve_kernel_equals_the_host_on_the_cpu() {
    kernel_equals_host_on(&mut CpuBackend::new());
}

#[test]
fn the_resolve_kernel_equals_the_host_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    kernel_equals_host_on(&mut vk);
    assert_clean(&mut vk);
}

/// The device peel at sub-sample resolution, resolved on the device, equals the host peel with
/// the same sub-samples, slot for slot; a frame records no allocation, upload or readback.
fn device_peel_equals_host_on(b: &mut dyn Backend) {
    let scene = builtin("fence").unwrap();
    let camera = Camera { width: 64, height: 36, ..scene.camera };
    let lens = scene.lens.thin_lens(&camera).unwrap();
    let glb = export_glb(&scene.scene, &scene.camera, &ExportOptions::default()).unwrap();
    let mesh: MeshScene = load_gltf_slice(&glb).unwrap();
    let near = default_near(lens.focus_distance);
    let options =
        LayerOptions { max_layers: 4, guard_band: GuardBand::Pixels(3), disocclusion: true, subsamples: 4, ..LayerOptions::default() };
    let host = peel_layers(b, &mesh.raster(), &camera, &lens, near, &options).unwrap();
    assert!(host.image.layers.fragments.iter().any(|f| f.alpha > 0.0 && f.alpha < 1.0), "partly covered fragments");
    let mut ctx = MeshPeelContext::new(b, &mesh.raster(), &camera, &lens, &MeshPeelDesc::new(&options, near)).unwrap();
    assert_eq!(ctx.size(), [64 + 6, 36 + 6], "the frame's slots, not the sub-sample grid's");
    let before = b.counters();
    ctx.record(b, &camera, &lens).unwrap();
    let times = b.submit().unwrap();
    let c = b.counters().since(&before);
    assert_eq!((c.allocations, c.uploads, c.readbacks), (0, 0, 0), "per frame: {c:?}");
    assert_eq!(times.iter().filter(|t| t.label == "peel/resolve").count(), 1, "the resolve ran on the device");
    let s = ctx.slots().clone();
    let pixels = s.width as u64 * s.height as u64;
    assert_eq!(s.footprint_side, host.image.layers.footprint_side);
    let fragments = b.read_buffer(s.fragments, 0, (SLOT_WORDS as u64 + 1) * pixels * s.layers as u64).unwrap();
    let counts = b.read_buffer(s.counts, 0, pixels).unwrap();
    assert_eq!(counts, host.image.layers.counts);
    assert_eq!(fragments, slot_words(&host.image.layers), "slots and footprints");
    let mask = b.read_buffer(s.mask, 0, pixels).unwrap();
    let m = ctx.margin() as usize;
    let w = s.width as usize;
    let cropped: Vec<bool> =
        (m..s.height as usize - m).flat_map(|y| (m..w - m).map(move |x| (x, y))).map(|(x, y)| mask[y * w + x] != 0).collect();
    assert_eq!(cropped, host.image.mask, "the disocclusion buffer");
    ctx.destroy(b);
}

#[test]
fn the_device_peel_resolves_like_the_host_on_the_cpu() {
    device_peel_equals_host_on(&mut CpuBackend::new());
}

#[test]
fn the_device_peel_resolves_like_the_host_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    device_peel_equals_host_on(&mut vk);
    assert_clean(&mut vk);
}

mod composite_property {
    use super::*;
    use proptest::prelude::*;

    /// Surfaces far enough apart that each is one cluster (gaps well past the 5% tolerance).
    const SURFACES: [f32; 4] = [1.0, 2.0, 4.0, 8.0];

    /// One sub-sample's list, front to back: some of the surfaces (each a little off its depth,
    /// within 1%), translucent or not, ending on an opaque surface or the sky, as a peel's lists
    /// end.
    fn list() -> impl Strategy<Value = Vec<Sample>> {
        let fragment = (0.0f32..1.0, 0.0f32..1.0, 0.0f32..1.0, 0.05f32..1.0, -0.01f32..0.01);
        (proptest::collection::vec(any::<bool>(), 4), proptest::collection::vec(fragment, 4), 0usize..5).prop_map(|(used, f, end)| {
            let mut out = Vec::new();
            for k in 0..end.min(4) {
                if used[k] {
                    let (r, g, b, a, jitter) = f[k];
                    out.push(Sample { color: [r * a, g * a, b * a], alpha: a, depth: SURFACES[k] * (1.0 + jitter) });
                }
            }
            // The end: an opaque surface behind the rest, or the sky.
            let (r, g, b, _, _) = f[end.min(3)];
            let depth = if end < 4 { SURFACES[end] } else { f32::INFINITY };
            out.retain(|s| s.depth < depth * 0.99);
            out.push(Sample { color: [r, g, b], alpha: 1.0, depth });
            out
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

        /// The oracle the resolve is held to: the front-to-back composite of the resolved
        /// fragments is the mean of the sub-samples' own composites (the pixel's area mean), when
        /// every list ends opaque and no cluster is merged for want of layers.
        #[test]
        fn the_composite_of_the_resolved_pixel_is_the_mean_of_its_sub_samples(
            lists in prop_oneof![proptest::collection::vec(list(), 4), proptest::collection::vec(list(), 16)]
        ) {
            let (out, r) = run(&lists, 16, 0.05);
            prop_assert_eq!(r.merged, 0);
            let got = composite(&out);
            let mut want = [0.0f32; 3];
            for l in &lists {
                let c = composite(l);
                for j in 0..3 {
                    want[j] += c[j] / lists.len() as f32;
                }
            }
            for j in 0..3 {
                prop_assert!((got[j] - want[j]).abs() <= 1e-5 * want[j].max(1.0), "{:?} against {:?} from {:?}", got, want, out);
            }
        }
    }
}
