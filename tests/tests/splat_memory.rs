//! Device memory of the multi-layer splatting context, buffer by buffer, and of every method of
//! the registry, at 1280x720, 1920x1080 and 3840x2160 with 4 layers (printed for
//! `docs/measurements.md`; run with `--nocapture`). Buffers hold the same bytes on every backend,
//! so the CPU backend is enough.
//! - The per-buffer table sums to `device_bytes`, which equals what the backend holds for it.
//! - Transients whose lifetimes do not overlap share a buffer, buffers that hold several stages in
//!   turn are not counted twice, and the context at 1920x1080
//!   with 4 layers stays within [`BOUND_1080P`] unmerged (the registry's options) and merged.

use dof::backend::{Backend, CpuBackend};
use dof::frame::{ContextDesc, Extent, METHODS, Merge, MethodOptions, SplatContext, SplatContextDesc, SplatOptions};
use dof::methods::splat::splat;
use dof::stress::{noise_with_sky, test_lens};
use dof_tests::oracle::splat_stages::splat_with_stages;
use dof_tests::vulkan;

const SIZES: [(u32, u32); 3] = [(1280, 720), (1920, 1080), (3840, 2160)];
const LAYERS: u32 = 4;
/// What the multi-layer context may hold at 1920x1080 with 4 layers, unmerged (the registry's
/// options) and merged: 256 MB (10^6 bytes), the real-time memory bound.
const BOUND_1080P: u64 = 256_000_000;

#[test]
fn splat_memory_table_sums_to_device_bytes() {
    let mut b = CpuBackend::new();
    for merge in [Merge::None, Merge::X2, Merge::X4] {
        for (w, h) in SIZES {
            let before = b.counters().device_bytes;
            let desc = SplatContextDesc::new(Extent::new(w, h, LAYERS), SplatOptions { merge, ..SplatOptions::default() });
            let ctx = SplatContext::new(&mut b, &desc).unwrap_or_else(|e| panic!("{w}x{h} merge {}: {e}", merge.name()));
            let held = b.counters().device_bytes - before;
            let table = ctx.memory_table();
            let sum: u64 = table.iter().map(|(_, bytes)| bytes).sum();
            assert_eq!(sum, ctx.device_bytes(), "{w}x{h} merge {}: the table's rows", merge.name());
            assert_eq!(held, ctx.device_bytes(), "{w}x{h} merge {}: what the backend holds", merge.name());
            let (entries, _) = ctx.list_bounds();
            eprintln!("splat context {w}x{h}x{LAYERS}, merge {}, list pool {entries} entries: {sum} bytes", merge.name());
            for (label, bytes) in &table {
                eprintln!("  {label:<48} {bytes:>12} ({:.1} MB)", *bytes as f64 / 1e6);
            }
            // Transients placed by lifetime: the cells, their offsets, binning's thinning counts and
            // cache share the buffers of the lists, which are never more than the four the sort
            // reads and writes at once.
            for part in ["splat/cells", "splat/offsets", "splat/thin-counts", "splat/bin-cache"] {
                let row = table.iter().find(|(l, _)| l.split(", ").any(|p| p == part));
                assert!(row.is_some_and(|(l, _)| l.contains(", ")), "{w}x{h} merge {}: {part} has a buffer of its own", merge.name());
            }
            let list_sized = table.iter().filter(|(l, _)| l.contains("splat/keys") || l.contains("splat/values")).count();
            assert_eq!(list_sized, 4, "{w}x{h} merge {}: buffers of the lists", merge.name());
            // One fragment-sized buffer: no merging level is stored.
            let fragment_sized = table.iter().filter(|(_, bytes)| *bytes >= 16 * (w * h) as u64 * LAYERS as u64).count();
            assert_eq!(fragment_sized, 1, "{w}x{h} merge {}: buffers of every slot's fragment", merge.name());
            if (w, h) == (1920, 1080) {
                assert!(sum <= BOUND_1080P, "merge {}: the context at 1080p holds {sum} bytes", merge.name());
            }
            ctx.destroy(&mut b);
        }
    }
    assert_eq!(b.counters().device_bytes, 0, "every context freed");
}

/// Footprints add a field a slot to the dense array (its slots: the input's, padded to whole
/// tiles): 4 bits with 2x2 sub-samples (the command line's default), 16 with 3x3 or 4x4; at 1080p
/// with 2x2 the context stays within the bound.
#[test]
fn footprints_add_a_field_a_slot() {
    let mut b = CpuBackend::new();
    let (w, h): (u32, u32) = (1920, 1080);
    let tile = SplatOptions::default().tile;
    let slots = (w.next_multiple_of(tile) * h.next_multiple_of(tile) * LAYERS) as u64;
    let bytes = |b: &mut CpuBackend, side: u32| {
        let desc = SplatContextDesc::new(
            Extent::new(w, h, LAYERS),
            SplatOptions { merge: Merge::X4, footprint_side: side, ..SplatOptions::default() },
        );
        let ctx = SplatContext::new(b, &desc).unwrap();
        let n = ctx.device_bytes();
        ctx.destroy(b);
        n
    };
    let none = bytes(&mut b, 0);
    for (side, bits) in [(1, 1), (2, 4), (3, 16), (4, 16)] {
        let with = bytes(&mut b, side);
        eprintln!("1920x1080x{LAYERS}, footprints on a {side}x{side} grid: {with} bytes ({:.1} MB)", with as f64 / 1e6);
        assert_eq!(with - none, 4 * (slots * bits).div_ceil(32), "side {side}");
        if side <= 2 {
            assert!(with <= BOUND_1080P, "side {side}: {with} bytes");
        }
    }
}

#[test]
fn device_bytes_of_every_method() {
    let mut b = CpuBackend::new();
    for (w, h) in SIZES {
        for m in METHODS {
            let desc = ContextDesc::new(Extent::new(w, h, LAYERS), MethodOptions::default());
            match (m.create)(&mut b, &desc) {
                Ok(ctx) => {
                    eprintln!("device bytes {w}x{h}x{LAYERS} {}: {}", m.name, ctx.device_bytes());
                    if (m.name == "multilayer" || m.name == "tiled") && (w, h) == (1920, 1080) {
                        assert!(ctx.device_bytes() <= BOUND_1080P, "multilayer at 1080p holds {} bytes", ctx.device_bytes());
                    }
                    ctx.destroy(&mut b);
                }
                // A method may refuse a size beyond its limits; the multi-layer context never does here.
                Err(e) => {
                    assert_ne!(m.name, "multilayer", "{w}x{h}: {e}");
                    eprintln!("device bytes {w}x{h}x{LAYERS} {}: refused: {e}", m.name);
                }
            }
        }
    }
    assert_eq!(b.counters().device_bytes, 0, "every context freed");
}

/// A frame whose long lists take the sort's global path (whose key scratch then also holds the
/// sorted keys) writes the same image, bit for bit, recorded at once and encoded stage by stage
/// with a submission and a readback of the stages' buffers between (as `splat_with_stages` does),
/// on the CPU backend and on Vulkan: each transient is read after its last use, before a later one
/// in its buffer, and reading them changes nothing.
#[test]
fn a_frame_encoded_stage_by_stage_gives_the_same_image() {
    let mut backends: Vec<Box<dyn Backend>> = vec![Box::new(CpuBackend::new())];
    if let Some(vk) = vulkan() {
        backends.push(Box::new(vk));
    }
    let img = noise_with_sky(64, 48, LAYERS);
    for b in &mut backends {
        for merge in [Merge::None, Merge::X4] {
            let o = SplatOptions { merge, tile: 32, ..SplatOptions::default() };
            let shared = splat(b.as_mut(), &img, &test_lens(0.2), &o).unwrap();
            let staged = splat_with_stages(b.as_mut(), &img, &test_lens(0.2), &o).unwrap();
            let what = format!("{} merge {}", b.kind(), merge.name());
            assert!(shared.report.sort.global_lists > 0, "{what}: no list took the global path: {:?}", shared.report.sort);
            assert_eq!(shared.report.overflow_tiles, 0, "{what}");
            let bits = |o: &dof::layers::RgbImage| o.data.iter().flatten().map(|v| v.to_bits()).collect::<Vec<_>>();
            assert!(bits(&shared.image) == bits(&staged.image), "{what}: the image differs when encoded stage by stage");
            let stages = &staged.intermediates;
            assert!(stages.binned.0.len() as u64 == shared.report.list_entries && stages.sorted.0.len() == stages.binned.0.len());
            // Each list's sorted keys are its binned keys in order: the binned lists were read
            // before the sort, the sorted ones after it.
            let mut at = 0;
            for &n in &stages.list_lengths {
                let mut binned = stages.binned.0[at..at + n as usize].to_vec();
                binned.sort_unstable();
                assert!(binned == stages.sorted.0[at..at + n as usize], "{what}: a list's sorted keys are not its binned keys, sorted");
                at += n as usize;
            }
        }
    }
}
