//! Lists too long for the sort or the pool are thinned, never left sharp
//! (`dof_shaders::splat::bin::thin_keeps`): a real-time context cannot grow mid-frame, so a tile
//! whose list does not fit takes its wide fragments from a coarser lattice of source cells, each
//! standing for its block. The oracles:
//! - every tile is either the whole frame's, bit for bit, or counted as thinned;
//! - a thinned tile is blurred: much nearer the whole frame's blur than the sharp fronts are;
//! - the frame is finite and non-negative, and the same on the CPU and Vulkan: the same tiles
//!   thinned to the same lists (thinning is chosen per tile from its own list, so with a pool that
//!   holds every thinned list, it does not depend on the order tiles run in).

use dof::backend::{Backend, BufferId, CpuBackend};
use dof::frame::Extent;
use dof::frame::{CountBuffer, DofContext, Frame, RgbBuffer, SlotBuffer, SplatContext, SplatContextDesc};
use dof::layers::LayeredImage;
use dof::methods::buffers::{SLOT_WORDS, read_rgb, slot_words};
use dof::methods::splat::{Merge, SplatOptions, SplatReport, splat};
use dof::scene::{Camera, GuardBand, LayerOptions, builtin, raycast_layers};
use dof_shaders::lens::ThinLens;
use dof_tests::{assert_clean, vulkan};

const TILE: usize = 16;

/// `railing` small, its multi-layer input ray cast, and its lens with a wide aperture (CoC radii
/// up to about 17 px: wide enough to thin).
fn scene() -> (LayeredImage, ThinLens) {
    let s = builtin("railing").unwrap();
    let camera = Camera { width: 160, height: 96, ..s.camera };
    let lens = s.lens.thin_lens(&camera).unwrap();
    let lens = ThinLens { aperture_radius: 6.0 * lens.aperture_radius, ..lens };
    let options = LayerOptions { subsamples: 1, guard_band: GuardBand::Pixels(0), ..LayerOptions::default() };
    (raycast_layers(&s.scene, &camera, &lens, &options).unwrap().layers, lens)
}

/// One frame through a context whose sort takes lists of at most `max_list` entries.
fn frame(b: &mut dyn Backend, image: &LayeredImage, lens: &ThinLens, max_list: u32) -> (Vec<[f32; 3]>, SplatReport) {
    let (w, h, l) = (image.width, image.height, image.max_layers);
    let pixels = w as u64 * h as u64;
    let bufs: [BufferId; 3] = [
        b.create_buffer(SLOT_WORDS as u64 * pixels * l as u64, "caller/fragments").unwrap(),
        b.create_buffer(pixels, "caller/counts").unwrap(),
        b.create_buffer(3 * pixels, "caller/output").unwrap(),
    ];
    b.write_buffer(bufs[0], 0, &slot_words(image)).unwrap();
    b.write_buffer(bufs[1], 0, &image.counts).unwrap();
    let mut desc = SplatContextDesc::new(Extent::new(w, h, l), SplatOptions { merge: Merge::None, ..Default::default() });
    desc.max_list = Some(max_list);
    let mut ctx = SplatContext::new(b, &desc).unwrap();
    ctx.record(b, &Frame::layers(w, h, l, *lens, SlotBuffer::current(bufs[0]), CountBuffer(bufs[1]), RgbBuffer(bufs[2]))).unwrap();
    b.submit().unwrap();
    let report = ctx.report(b).unwrap();
    let out = read_rgb(b, bufs[2], w, h).unwrap().data;
    ctx.destroy(b);
    bufs.iter().for_each(|&id| b.destroy_buffer(id));
    (out, report)
}

/// The pixels of each 16x16 tile.
fn tiles(w: usize, h: usize) -> Vec<Vec<usize>> {
    let mut all = Vec::new();
    for ty in 0..h.div_ceil(TILE) {
        for tx in 0..w.div_ceil(TILE) {
            all.push(
                (ty * TILE..(ty * TILE + TILE).min(h))
                    .flat_map(|y| (tx * TILE..(tx * TILE + TILE).min(w)).map(move |x| y * w + x))
                    .collect(),
            );
        }
    }
    all
}

fn mean_abs(a: &[[f32; 3]], b: &[[f32; 3]], pixels: &[usize]) -> f64 {
    let sum: f64 = pixels.iter().map(|&p| (0..3).map(|c| (a[p][c] - b[p][c]).abs() as f64).sum::<f64>()).sum();
    sum / (3 * pixels.len().max(1)) as f64
}

#[test]
fn lists_beyond_the_sort_are_thinned_and_stay_blurred() {
    let (image, lens) = scene();
    let (w, h) = (image.width as usize, image.height as usize);
    let mut b = CpuBackend::new();
    let whole = splat(&mut b, &image, &lens, &SplatOptions { merge: Merge::None, ..Default::default() }).unwrap();
    assert_eq!(whole.report.tiles_cut_short(), 0, "the one-shot path grows until the frame is whole");
    let longest = whole.report.max_list_length();
    // Two thirds: every list then fits thinned (a list's narrow fragments, which are never
    // thinned, are about half of the longest here).
    let max_list = 2 * longest / 3;
    let (thinned, report) = frame(&mut b, &image, &lens, max_list);
    assert!(report.thinned_tiles > 0 && report.thinned_entries > 0, "lists of up to {longest} entries, sort for {max_list}: {report:?}");
    assert_eq!(report.overflow_tiles, 0, "no tile left sharp");
    assert!(report.max_list_length() <= max_list, "{} > {max_list}", report.max_list_length());
    assert!(report.summary().contains("THINNED"));
    assert!(thinned.iter().flatten().all(|c| c.is_finite() && *c >= 0.0), "finite and non-negative");

    let sharp = image.front().0.data;
    let (mut differing, mut err_thinned, mut err_sharp) = (0, 0.0, 0.0);
    for pixels in tiles(w, h) {
        if pixels.iter().all(|&p| thinned[p].map(f32::to_bits) == whole.image.data[p].map(f32::to_bits)) {
            continue;
        }
        differing += 1;
        err_thinned += mean_abs(&thinned, &whole.image.data, &pixels);
        err_sharp += mean_abs(&sharp, &whole.image.data, &pixels);
    }
    assert!(
        differing > 0 && differing <= report.thinned_tiles,
        "{differing} tiles differ from the whole frame, {} thinned",
        report.thinned_tiles
    );
    assert!(
        err_thinned < 0.25 * err_sharp,
        "thinned tiles must stay blurred: mean error {err_thinned:.4} against the whole frame, sharp fronts {err_sharp:.4}"
    );
}

#[test]
fn thinned_frames_are_the_same_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    let (image, lens) = scene();
    let mut cpu = CpuBackend::new();
    let whole = splat(&mut cpu, &image, &lens, &SplatOptions { merge: Merge::None, ..Default::default() }).unwrap();
    let max_list = 2 * whole.report.max_list_length() / 3;
    let (on_cpu, cpu_report) = frame(&mut cpu, &image, &lens, max_list);
    let (on_vk, vk_report) = frame(&mut vk, &image, &lens, max_list);
    assert!(cpu_report.thinned_tiles > 0);
    // The same tiles thinned to the same lists.
    assert_eq!((cpu_report.thinned_tiles, cpu_report.thinned_entries), (vk_report.thinned_tiles, vk_report.thinned_entries));
    assert_eq!(cpu_report.list_lengths, vk_report.list_lengths);
    // The same image, to a float's rounding: with blur this wide, lavapipe rounds some sums of this
    // frame a unit in the last place apart from the CPU thinned or not (its compiler may fuse
    // multiply-adds, which SPIR-V allows), so bits are compared where they are known to agree
    // (`vulkan_equivalence`) and values here.
    for (i, (a, b)) in on_cpu.iter().zip(&on_vk).enumerate() {
        for c in 0..3 {
            assert!((a[c] - b[c]).abs() <= 1e-5 * a[c].abs().max(1e-3), "pixel {i}: {a:?} on the CPU, {b:?} on Vulkan");
        }
    }
    assert_clean(&mut vk);
}
