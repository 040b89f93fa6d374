//! The ring gather as an honest baseline: close to the
//! exhaustive gather inside the partial-occlusion region, sub-pixel highlights drawn as discs that
//! keep their energy (the highlight path) on both backends, and a focus pull without flicker.
//! Bounds sit under the margins measured (see `docs/measurements.md`).

use dof::backend::{Backend, CpuBackend};
use dof::eval::temporal::temporal_psnr;
use dof::frame::Extent;
use dof::frame::{CountBuffer, DofContext, Frame, RgbBuffer, RingGatherContext, RingGatherContextDesc, SlotBuffer};
use dof::io::tonemap::tonemap_image;
use dof::layers::RgbImage;
use dof::methods::gather::gather;
use dof::methods::ring_gather::{DEFAULT_RINGS, RingGatherOptions, ring_gather};
use dof::metrics::compare;
use dof::scene::guard_band::auto_margin;
use dof::scene::{Focus, GuardBand, LayerOptions, ReferenceOptions, builtin, raycast_layers, reference};
use dof_shaders::lens::ThinLens;
use dof_tests::{assert_clean, vulkan};

fn defaults() -> RingGatherOptions {
    RingGatherOptions { rings: DEFAULT_RINGS, ..Default::default() }
}

/// A dark background at 20 m (CoC radius about 9 px with focus at 2 m) with one emitter a pixel
/// wide at (`x`, `y`).
fn emitter(w: u32, h: u32, x: u32, y: u32) -> (RgbImage, Vec<f32>, ThinLens) {
    let mut img = RgbImage::new(w, h);
    img.data.iter_mut().for_each(|p| *p = [0.05, 0.05, 0.05]);
    img.data[(y * w + x) as usize] = [400.0, 300.0, 200.0];
    let lens = ThinLens { focal_length: 0.05, aperture_radius: 0.05, focus_distance: 2.0, pixels_per_unit: 8000.0 };
    (img, vec![20.0f32; (w * h) as usize], lens)
}

/// A sub-pixel emitter far behind the focus becomes a disc of its CoC, evenly lit and keeping its
/// energy, wherever it sits on the half-resolution grid (the plain gather draws it as the pattern
/// of its ring lattice: half-resolution squares with gaps). The same on Vulkan.
#[test]
fn a_sub_pixel_highlight_becomes_an_even_disc_that_keeps_its_energy() {
    let (w, h) = (64u32, 64u32);
    for (x, y) in [(32u32, 32u32), (33, 32), (33, 33), (20, 41)] {
        let (img, depth, lens) = emitter(w, h, x, y);
        let out = ring_gather(&mut CpuBackend::new(), &img, &depth, &lens, &defaults()).unwrap();
        let radius = lens.coc_radius_px(20.0);
        let excess: Vec<f32> = out.image.data.iter().map(|p| p[0] - 0.05).collect();
        let energy: f32 = excess.iter().sum();
        assert!((energy - (400.0 - 0.05)).abs() < 0.01 * 400.0, "({x}, {y}): energy {energy} of 400");
        // Inside 70% of the radius, every pixel within 15% of the mean there.
        let (cx, cy) = (x as f32 + 0.5, y as f32 + 0.5);
        let inside: Vec<f32> = (0..w * h)
            .filter(|i| {
                let (px, py) = ((i % w) as f32 + 0.5 - cx, (i / w) as f32 + 0.5 - cy);
                (px * px + py * py).sqrt() < 0.7 * radius
            })
            .map(|i| excess[i as usize])
            .collect();
        let mean = inside.iter().sum::<f32>() / inside.len() as f32;
        let (lo, hi) = inside.iter().fold((f32::MAX, f32::MIN), |(a, b), &v| (a.min(v), b.max(v)));
        eprintln!("({x}, {y}): radius {radius:.2} px, energy {energy:.2}, inside {lo:.3} to {hi:.3} (mean {mean:.3})");
        assert!(lo > 0.85 * mean && hi < 1.15 * mean, "({x}, {y}): uneven disc {lo} to {hi}, mean {mean}");
        // Nothing beyond the disc's soft edge (but the background's own blur).
        for i in 0..w * h {
            let (px, py) = ((i % w) as f32 + 0.5 - cx, (i / w) as f32 + 0.5 - cy);
            if (px * px + py * py).sqrt() > radius + 2.5 {
                assert!(excess[i as usize].abs() < 0.02 * mean, "({x}, {y}): {} at pixel {i}", excess[i as usize]);
            }
        }
        if let Some(mut vk) = vulkan() {
            let on_vk = ring_gather(&mut vk, &img, &depth, &lens, &defaults()).unwrap();
            assert_clean(&mut vk);
            for (a, b) in on_vk.image.data.iter().zip(&out.image.data) {
                for c in 0..3 {
                    assert!((a[c] - b[c]).abs() <= 1e-4 * b[c].abs().max(1e-2), "{a:?} vs {b:?}");
                }
            }
        }
    }
}

/// An emitter of 1 to 3 pixels a side with a CoC radius of 1.5 or 2.5 px in front of a background
/// blurred by 9 px (the case of `highlights`): below Unreal's 3 px threshold, but drawn as a disc
/// at full resolution that keeps its energy wherever it sits on the half-resolution grid. The same
/// on Vulkan, bit for bit.
#[test]
fn a_small_emitter_before_a_blurred_background_keeps_its_energy() {
    let (w, h) = (48u32, 48u32);
    let (_, _, lens) = emitter(w, h, 0, 0);
    let mut vk = vulkan();
    for z in [2.342f32, 2.644] {
        for side in 1..=3u32 {
            for offset in [(0u32, 0u32), (1, 0), (1, 1)] {
                let (mut img, mut depth, _) = emitter(w, h, 0, 0);
                img.data[0] = [0.05, 0.05, 0.05];
                for y in 0..side {
                    for x in 0..side {
                        let i = ((20 + offset.1 + y) * w + 20 + offset.0 + x) as usize;
                        img.data[i] = [4000.0, 3000.0, 2000.0];
                        depth[i] = z;
                    }
                }
                let out = ring_gather(&mut CpuBackend::new(), &img, &depth, &lens, &defaults()).unwrap();
                let given: f64 = img.data.iter().map(|p| p[0] as f64).sum();
                let kept: f64 = out.image.data.iter().map(|p| p[0] as f64).sum();
                eprintln!(
                    "CoC radius {:.2} px, {side}x{side} at {offset:?}: energy {kept:.1} of {given:.1} ({:+.3}%)",
                    lens.coc_radius_px(z),
                    100.0 * (kept / given - 1.0)
                );
                assert!((kept / given - 1.0).abs() < 0.01, "CoC {z} m, {side}x{side} at {offset:?}: {kept} of {given}");
                // Nothing beyond the disc's soft edge but the background's own blur.
                let (cx, cy) = ((20 + offset.0) as f32 + 0.5 * side as f32, (20 + offset.1) as f32 + 0.5 * side as f32);
                for i in 0..w * h {
                    let (px, py) = ((i % w) as f32 + 0.5 - cx, (i / w) as f32 + 0.5 - cy);
                    let far = (px * px + py * py).sqrt() > lens.coc_radius_px(z) + 0.5 * side as f32 + 1.5;
                    assert!(!far || out.image.data[i as usize][0] < 1.0, "pixel {i}: {:?}", out.image.data[i as usize]);
                }
                if let Some(vk) = vk.as_mut() {
                    let on_vk = ring_gather(vk, &img, &depth, &lens, &defaults()).unwrap();
                    assert_clean(vk);
                    assert_eq!(on_vk.image.data, out.image.data, "CoC {z} m, {side}x{side} at {offset:?}");
                }
            }
        }
    }
}

/// More highlights than a tile holds: the rest stay in the gather whole, so the energy is kept.
#[test]
fn highlights_beyond_a_tiles_capacity_stay_in_the_gather() {
    let (w, h) = (48u32, 48u32);
    let (mut img, depth, lens) = emitter(w, h, 0, 0);
    img.data.iter_mut().for_each(|p| *p = [0.05, 0.05, 0.05]);
    // Every other half-resolution pixel of a 16x16 tile: 16 highlights in one tile.
    for y in (16..32).step_by(4) {
        for x in (16..32).step_by(4) {
            img.data[(y * w + x) as usize] = [50.0, 50.0, 50.0];
        }
    }
    let out = ring_gather(&mut CpuBackend::new(), &img, &depth, &lens, &defaults()).unwrap();
    let sum = |i: &RgbImage| i.data.iter().map(|p| p[1] as f64).sum::<f64>();
    // The discs reach past the frame's edge a little: most of the energy stays.
    let (kept, given) = (sum(&out.image), sum(&img));
    assert!(kept > 0.97 * given && kept < 1.001 * given, "{kept} of {given}");
    assert!(out.image.data.iter().all(|p| p.iter().all(|c| c.is_finite() && *c >= 0.0)));
    // The context's report counts the 8 beyond the tile's 8, with no readback in the frame.
    let mut cpu = CpuBackend::new();
    let mut ctx = RingGatherContext::new(&mut cpu, &RingGatherContextDesc::new(Extent::new(w, h, 1))).unwrap();
    // Opaque slots (`dof_shaders::slot`: premultiplied colour, depth, alpha).
    let slots: Vec<u32> = img.data.iter().zip(&depth).flat_map(|(c, z)| [c[0], c[1], c[2], *z, 1.0].map(f32::to_bits)).collect();
    let input = cpu.create_buffer(slots.len() as u64, "input").unwrap();
    let counts = cpu.create_buffer((w * h) as u64, "counts").unwrap();
    let output = cpu.create_buffer(3 * (w * h) as u64, "output").unwrap();
    cpu.write_buffer(input, 0, &slots).unwrap();
    cpu.write_buffer(counts, 0, &vec![1u32; (w * h) as usize]).unwrap();
    for _ in 0..2 {
        let before = cpu.counters();
        ctx.record(&mut cpu, &Frame::layers(w, h, 1, lens, SlotBuffer::current(input), CountBuffer(counts), RgbBuffer(output))).unwrap();
        cpu.submit().unwrap();
        let spent = cpu.counters().since(&before);
        assert_eq!((spent.allocations, spent.readbacks, spent.uploads), (0, 0, 0));
        let report = ctx.report(&mut cpu).unwrap();
        assert_eq!(report.figures()["highlights_capped"], 8.0, "{}", report.summary);
        assert!(report.summary.contains("8 highlights gathered"), "{}", report.summary);
    }
    ctx.destroy(&mut cpu);
}

/// Inside the partial-occlusion region the ring gather stays within 2 dB of the exhaustive gather
/// (Riguer et al. 2003) on `railing` and `fence` at 320x180, the scenes whose foreground crosses the
/// frame, and on `highlights`, whose emitters of a few pixels' blur the highlight path must keep.
/// `RING_REGION=WxH` measures every built-in scene at that size instead (64-spp references), as
/// `docs/measurements.md` reports; `RING_SCENES=a,b` picks scenes.
#[test]
fn close_to_the_exhaustive_gather_in_the_partial_occlusion_region() {
    let (size, mut names): ((u32, u32), Vec<&str>) = match std::env::var("RING_REGION").ok().and_then(|v| {
        let (w, h) = v.split_once('x')?;
        Some((w.parse().ok()?, h.parse().ok()?))
    }) {
        Some(size) => (size, dof::scene::builtin_names().to_vec()),
        None => ((320, 180), vec!["railing", "fence", "highlights"]),
    };
    let picked = std::env::var("RING_SCENES").unwrap_or_default();
    if !picked.is_empty() {
        names.retain(|n| picked.split(',').any(|p| p == *n));
    }
    let mut missed = Vec::new();
    for name in names {
        let scene = builtin(name).unwrap().with_size(size.0, size.1);
        let lens = scene.thin_lens().unwrap();
        let layers = raycast_layers(&scene.scene, &scene.camera, &lens, &LayerOptions::default()).unwrap();
        let (front, depth) = layers.layers.front();
        let exact = reference(&scene.scene, &scene.camera, &lens, &ReferenceOptions { spp: 64, ..Default::default() }).unwrap();
        let ring = layers.crop(&ring_gather(&mut CpuBackend::new(), &front, &depth, &lens, &defaults()).unwrap().image);
        let full = layers.crop(&gather(&mut CpuBackend::new(), &front, &depth, &lens, None).unwrap().image);
        let ring = compare(&ring, &exact.image, Some(&layers.mask)).unwrap();
        let full = compare(&full, &exact.image, Some(&layers.mask)).unwrap();
        let (r, g) = (ring.psnr_masked_db.unwrap(), full.psnr_masked_db.unwrap());
        eprintln!(
            "{name} {}x{}: region PSNR ring gather {r:.2} dB, gather {g:.2} dB; full frame {:.2} and {:.2} dB",
            size.0, size.1, ring.psnr_db, full.psnr_db
        );
        if r <= g - 2.0 {
            missed.push(format!("{name}: ring gather {r:.2} dB against the gather's {g:.2} dB in the region"));
        }
    }
    assert!(missed.is_empty(), "{missed:?}");
}

/// A focus pull on `railing` (focus from the scene's to 0.4 of it, one guard band for every frame
/// as in `dof eval --temporal`): no frame-to-frame change of the ring gather is more than 1.3 times
/// the reference's (measured up to 1.17), measured as RMS on the tone-mapped images; at the size of
/// `dof eval --temporal` no more than 1.75 times (measured up to 1.65, the last step, where the
/// far wall's checker, aliased in the one-sample input, starts to blur).
#[test]
fn a_focus_pull_does_not_flicker() {
    // `RING_TEMPORAL=WxHxFRAMESxSPP` measures at another size (`dof eval --temporal`: 160x90x12x256).
    let size = std::env::var("RING_TEMPORAL").ok().and_then(|v| {
        let n: Vec<u32> = v.split('x').filter_map(|s| s.parse().ok()).collect();
        (n.len() == 4).then(|| (n[0], n[1], n[2] as usize, n[3]))
    });
    let bound = if size.is_some() { 1.75 } else { 1.3 };
    let (w, h, frames, spp) = size.unwrap_or((96, 54, 8, 128));
    let built = builtin("railing").unwrap().with_size(w, h);
    let f0 = built.thin_lens().unwrap().focus_distance;
    let lenses: Vec<ThinLens> = (0..frames)
        .map(|i| {
            let mut settings = built.lens;
            settings.focus = Focus::Distance(f0 + (0.4 * f0 - f0) * i as f32 / (frames - 1) as f32);
            settings.thin_lens(&built.camera).unwrap()
        })
        .collect();
    let margin = lenses.iter().map(|l| auto_margin(&built.scene, &built.camera, l, 1e-3 * l.focus_distance).unwrap()).max().unwrap();
    let options = LayerOptions { guard_band: GuardBand::Pixels(margin), ..Default::default() };
    let mut images = Vec::new();
    let mut references = Vec::new();
    for lens in &lenses {
        let layers = raycast_layers(&built.scene, &built.camera, lens, &options).unwrap();
        let (front, depth) = layers.layers.front();
        images.push(layers.crop(&ring_gather(&mut CpuBackend::new(), &front, &depth, lens, &defaults()).unwrap().image));
        references.push(reference(&built.scene, &built.camera, lens, &ReferenceOptions { spp, ..Default::default() }).unwrap().image);
    }
    let rms = |a: &RgbImage, b: &RgbImage| {
        let (a, b) = (tonemap_image(a, 1.0), tonemap_image(b, 1.0));
        let sum: f64 = a.iter().zip(&b).map(|(p, q)| (0..3).map(|c| ((p[c] - q[c]) as f64).powi(2)).sum::<f64>()).sum();
        (sum / (3 * a.len()) as f64).sqrt()
    };
    let mut worst: f64 = 0.0;
    for i in 1..frames {
        let ratio = rms(&images[i], &images[i - 1]) / rms(&references[i], &references[i - 1]);
        let t = temporal_psnr(&images[i - 1], &images[i], &references[i - 1], &references[i]).unwrap();
        let p = compare(&images[i], &references[i], None).unwrap().psnr_db;
        eprintln!("step {i}: PSNR {p:.2} dB, temporal PSNR {t:.2} dB, change {ratio:.2}x the reference's");
        worst = worst.max(ratio);
    }
    assert!(worst < bound, "a step changes {worst:.2}x as much as the reference's (at most {bound}x)");
}
