//! Records one splatting frame on a backend and reads back the image and what the frame left out.
//!
//! Two submissions: the first packs, merges, counts, compacts and allocates the tile lists; the host
//! then reads one word (the lists' total capacity) and the largest list capacity to size the list
//! and sort buffers; the second bins, sorts and accumulates.

use super::plan::{SplatOptions, plan};
use super::report::SplatReport;
use crate::backend::{Backend, BufferId, CommandTime, push_words, with_buffers};
use crate::methods::buffers::{groups_for, read_rgb, slot_words};
use crate::error::{Error, Result};
use crate::layers::{LayeredImage, RgbImage};
use crate::ops::scan::ScanScratch;
use crate::ops::sort::SegmentedSort;
use dof_shaders::lens::ThinLens;
use dof_shaders::splat::accumulate::ACCUMULATE;
use dof_shaders::splat::bin::{ALLOC, BIN, COMPACT, TILE_COUNT};
use dof_shaders::splat::merge::MERGE;
use dof_shaders::splat::pack::PACK;
use dof_shaders::splat::{FLAG_UMBRA_MERGE, SplatParams, stats};

/// Every stage's buffers, read back when `keep_intermediates` is set.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Intermediates {
    /// Packed fragments and counts per cell after packing and after each merging step.
    pub cells: Vec<(Vec<u32>, Vec<u32>)>,
    pub tile_count: Vec<u32>,
    pub dense: Vec<u32>,
    pub capacity_offsets: Vec<u32>,
    pub segments: Vec<u32>,
    /// The binned lists (keys, values) before and after sorting, restricted to the list ranges.
    pub binned: (Vec<u32>, Vec<u32>),
    pub sorted: (Vec<u32>, Vec<u32>),
}

pub struct SplatOutput {
    pub image: RgbImage,
    pub report: SplatReport,
    pub stages: Vec<CommandTime>,
    pub intermediates: Option<Intermediates>,
}

/// Most tile-list entries a frame may allocate: 2^29, so that each list buffer stays within 2 GiB.
/// Measured on an NVIDIA H100 (driver 580.159.04): a 3840x2160 unmerged frame whose list buffers
/// held 584 million entries (2.3 GB each, under the device's 4 GiB limit) came back with almost
/// every list empty and no error, while at 1920x1080 (63 million entries) its lists were whole.
/// Refusing is better than a wrong image.
pub const MAX_LIST_ENTRIES: u64 = 1 << 29;

fn groups_1d(n: u32) -> [u32; 3] {
    groups_for(&PACK, n as u64)
}

/// Only the words inside the lists, so buffers' unused tails do not enter comparisons.
fn list_words(words: &[u32], segments: &[u32]) -> Vec<u32> {
    segments.chunks_exact(2).flat_map(|s| words[s[0] as usize..(s[0] + s[1]) as usize].iter().copied()).collect()
}

/// Renders `image` through `lens` by tiled splatting on `backend`.
pub fn splat(backend: &mut dyn Backend, image: &LayeredImage, lens: &ThinLens, options: &SplatOptions) -> Result<SplatOutput> {
    let plan = plan(image, lens, options)?;
    let pixels = plan.width as u64 * plan.height as u64;
    let slots = pixels * plan.layers as u64;
    let max_words = backend.limits().max_buffer_bytes / 4;
    if 4 * slots > max_words {
        return Err(Error::TooLarge { what: "fragment slots of the input (words)".into(), size: 4 * slots, limit: max_words });
    }
    let input = slot_words(image);
    let mask = options.aperture.mask_words();
    let tiles = plan.tiles() as u64;
    let mut sizes: Vec<(u64, String)> = vec![
        (4 * slots, "splat/input".into()),
        (pixels, "splat/input-counts".into()),
        (stats::WORDS as u64, "splat/stats".into()),
        (3 * pixels, "splat/out".into()),
        (tiles, "splat/tile-count".into()),
        (tiles, "splat/tile-base".into()),
        (tiles, "splat/tile-radius".into()),
        (tiles + 1, "splat/capacity".into()),
        (tiles, "splat/copy".into()),
        (4 * slots, "splat/dense".into()),
        (4 * pixels, "splat/sharp".into()),
        (2 * tiles, "splat/segments".into()),
        (mask.len() as u64, "splat/aperture-mask".into()),
    ];
    for step in 0..=plan.merge_steps {
        let (_, cap, cx, cy) = plan.cells(step);
        let cells = cx as u64 * cy as u64;
        sizes.push((4 * cells * cap as u64, format!("splat/cells-{step}")));
        sizes.push((cells, format!("splat/cell-counts-{step}")));
    }
    let (_, _, fx, fy) = plan.cells(plan.merge_steps);
    sizes.push((fx as u64 * fy as u64, "splat/cell-offsets".into()));
    let size_refs: Vec<(u64, &str)> = sizes.iter().map(|(w, l)| (*w, l.as_str())).collect();
    let first_bytes: u64 = sizes.iter().map(|s| 4 * s.0).sum();

    with_buffers(backend, &size_refs, |backend, b| {
        let [input_buf, counts_buf, st, out, tile_count, tile_base, tile_radius, capacity, copy, dense, sharp, segments, mask_buf] =
            [b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7], b[8], b[9], b[10], b[11], b[12]];
        let cells: Vec<(BufferId, BufferId)> = (0..=plan.merge_steps as usize).map(|s| (b[13 + 2 * s], b[14 + 2 * s])).collect();
        let cell_off = b[b.len() - 1];
        backend.write_buffer(input_buf, 0, &input)?;
        backend.write_buffer(counts_buf, 0, &image.counts)?;
        backend.write_buffer(mask_buf, 0, &mask)?;

        let params = |step: u32| {
            let (cell, cell_cap, cells_x, cells_y) = plan.cells(step);
            SplatParams {
                width: plan.width,
                height: plan.height,
                layers: plan.layers,
                cell,
                cell_cap,
                cells_x,
                cells_y,
                tile: plan.tile,
                tiles_x: plan.tiles_x,
                tiles_y: plan.tiles_y,
                rings: plan.rings,
                block: plan.block,
                flags: if options.umbra_merge { FLAG_UMBRA_MERGE } else { 0 },
                max_radius: plan.radius_cap,
                merge_min_radius: options.merge_min_radius,
                merge_depth_ratio: options.merge_depth_ratio,
                merge_color_tol: options.merge_color_tol,
                color_scale: plan.color_scale,
                lens: *lens,
                aperture: options.aperture.kernel,
            }
        };
        let last = plan.merge_steps;
        let fin = push_words(&params(last));
        let tile_grid = [plan.tiles_x, plan.tiles_y, 1];
        let (cells0, counts0) = cells[0];
        backend.dispatch(&PACK, groups_1d(pixels as u32), &[input_buf, counts_buf, cells0, counts0, sharp, st], &push_words(&params(0)), "splat/pack")?;
        for step in 0..last {
            let (ci, ni) = cells[step as usize];
            let (co, no) = cells[step as usize + 1];
            let (_, _, ox, oy) = plan.cells(step + 1);
            let label = if step == 0 { "splat/merge-2x2" } else { "splat/merge-4x4" };
            backend.dispatch(&MERGE, groups_1d(ox * oy), &[ci, ni, co, no, st], &push_words(&params(step)), label)?;
        }
        let (cells_f, counts_f) = cells[last as usize];
        let count_bufs = [cells_f, counts_f, cell_off, tile_count, tile_base, tile_radius, st];
        backend.dispatch(&TILE_COUNT, tile_grid, &count_bufs, &fin, "splat/tile-count")?;
        let scan = ScanScratch::new(backend, tiles + 1)?;
        let first = (|| {
            scan.record(backend, tile_base, 0, tiles)?;
            backend.dispatch(&COMPACT, tile_grid, &[cells_f, counts_f, cell_off, tile_base, dense], &fin, "splat/compact")?;
            backend.dispatch(&ALLOC, groups_1d(tiles as u32), &[tile_count, tile_radius, capacity, copy, st], &fin, "splat/alloc")?;
            scan.record(backend, capacity, 0, tiles + 1)?;
            backend.submit()
        })();
        scan.destroy(backend);
        let mut stages = first?;
        let total = backend.read_buffer(capacity, tiles, 1)?[0] as u64;
        if total > MAX_LIST_ENTRIES {
            return Err(Error::TooLarge {
                what: "tile list entries (merge fragments with --merge 2x2 or 4x4, or render smaller)".into(),
                size: total,
                limit: MAX_LIST_ENTRIES,
            });
        }
        let counters = backend.read_buffer(st, 0, stats::WORDS as u64)?;
        let max_list = counters[stats::MAX_CAPACITY as usize];

        let mut inter = if options.keep_intermediates {
            let mut cell_dumps = Vec::new();
            for &(c, n) in &cells {
                let words = backend.buffer_words(c)?;
                cell_dumps.push((backend.read_buffer(c, 0, words)?, backend.read_buffer(n, 0, backend.buffer_words(n)?)?));
            }
            Some(Intermediates {
                cells: cell_dumps,
                tile_count: backend.read_buffer(tile_count, 0, tiles)?,
                dense: backend.read_buffer(dense, 0, 4 * slots)?,
                capacity_offsets: backend.read_buffer(capacity, 0, tiles + 1)?,
                ..Default::default()
            })
        } else {
            None
        };

        let list_sizes = [
            (total.max(1), "splat/keys"),
            (total.max(1), "splat/values"),
            (total.max(1), "splat/keys-sorted"),
            (total.max(1), "splat/values-sorted"),
        ];
        let (second, sort_stats) = with_buffers(backend, &list_sizes, |backend, l| {
            let (keys, values, keys_out, values_out) = (l[0], l[1], l[2], l[3]);
            let bin_bufs = [dense, tile_count, tile_base, tile_radius, capacity, copy, keys, values, segments];
            backend.dispatch(&BIN, tile_grid, &bin_bufs, &fin, "splat/bin")?;
            if let Some(inter) = inter.as_mut() {
                backend.submit()?.into_iter().for_each(|t| stages.push(t));
                inter.segments = backend.read_buffer(segments, 0, 2 * tiles)?;
                let k = backend.read_buffer(keys, 0, total.max(1))?;
                let v = backend.read_buffer(values, 0, total.max(1))?;
                inter.binned = (list_words(&k, &inter.segments), list_words(&v, &inter.segments));
            }
            let sort = SegmentedSort::new(backend, tiles as u32, total.max(1) as u32, max_list)?;
            let recorded = sort.record(backend, segments, tiles as u32, keys, values, keys_out, values_out).and_then(|_| {
                let acc_bufs = [sharp, dense, values_out, segments, copy, out, st, mask_buf];
                let sub = plan.tile / plan.block;
                let grid = [plan.tiles_x * sub, plan.tiles_y * sub, 1];
                backend.dispatch(&ACCUMULATE, grid, &acc_bufs, &fin, "splat/accumulate")?;
                let times = backend.submit()?;
                let sort_stats = sort.stats(backend)?;
                if let Some(inter) = inter.as_mut() {
                    let k = backend.read_buffer(keys_out, 0, total.max(1))?;
                    let v = backend.read_buffer(values_out, 0, total.max(1))?;
                    inter.sorted = (list_words(&k, &inter.segments), list_words(&v, &inter.segments));
                }
                Ok((times, sort_stats))
            });
            sort.destroy(backend);
            recorded
        })?;
        stages.extend(second);

        let image_out = read_rgb(backend, out, plan.width, plan.height)?;
        let counters = backend.read_buffer(st, 0, stats::WORDS as u64)?;
        let seg = backend.read_buffer(segments, 0, 2 * tiles)?;
        let list_lengths: Vec<u32> = seg.chunks_exact(2).map(|s| s[1]).collect();
        let c = |i: u32| counters[i as usize];
        let report = SplatReport {
            pixels,
            input_fragments: image.counts.iter().map(|&n| n.min(plan.layers) as u64).sum(),
            full_layer_slots: slots,
            dropped: c(stats::DROPPED),
            clamped: c(stats::CLAMPED),
            sky: c(stats::SKY),
            sharp_pixels: c(stats::SHARP),
            hidden_sharp: c(stats::HIDDEN_SHARP),
            fragments: c(stats::TILED) as u64,
            merged: c(stats::MERGED),
            merged_inputs: c(stats::MERGED_INPUTS),
            umbra_skipped: c(stats::UMBRA_SKIPPED),
            capped: c(stats::CAPPED),
            tiles: tiles as u32,
            copy_tiles: c(stats::COPY_TILES),
            list_entries: list_lengths.iter().map(|&n| n as u64).sum(),
            list_lengths,
            list_capacity: total,
            sort: sort_stats,
            early_out_pixels: c(stats::EARLY_OUT),
            skipped_entries: c(stats::SKIPPED_ENTRIES),
            buffer_bytes: first_bytes + 16 * total.max(1),
            plan: Some(plan.clone()),
        };
        Ok(SplatOutput { image: image_out, report, stages, intermediates: inter })
    })
}
