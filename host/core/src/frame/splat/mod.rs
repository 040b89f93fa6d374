//! Tiled splatting as a frame context: every buffer and bound fixed at creation, then per frame a
//! recording of the stages in `dof_shaders::splat` with no allocation, readback or host planning.

use super::context::{ContextReport, Described, DofContext, Extent};
use super::in_flight::{InFlight, per_frame};
use super::io::{Frame, ImageIo, Owned, check_frame, output_buffer, record_input, record_output};
use super::recording::Recording;
use super::transient::{self, Transients};
use crate::backend::{Backend, BufferId, RunKernel, groups_for};
use crate::error::{Error, Result};
mod options;
mod report;

use crate::ops::sort::SegmentedSort;
use dof_shaders::KernelDesc;
use dof_shaders::sort::{CLASS_CAPS, top_class_for};
use dof_shaders::splat::accumulate::splat_accumulate;
use dof_shaders::splat::bin::{
    ALLOC, LEVELS, splat_alloc, splat_bin, splat_bin_count, splat_bin_plan, splat_tile_count, tiles_per_count_group,
};
use dof_shaders::splat::fragment::{MAX_EDGE, footprint_base, footprint_words};
use dof_shaders::splat::merge::{MERGE, splat_merge};
use dof_shaders::splat::pack::{PACK, splat_pack};
use dof_shaders::splat::plan::{splat_plan_finish, splat_plan_reduce};
use dof_shaders::splat::{
    FLAG_SERIAL, FLAG_UMBRA_MERGE, FOOTPRINT_SIDE_SHIFT, MAX_GROUPS, MAX_RINGS, SplatParams, THREADS, TILE_SIZES, block_for, stats,
};
pub use options::{Merge, SplatOptions, SplatPlanReport};
pub use report::{LLVMPIPE_SAFE_LIST, SplatReport};

/// Most tile-list entries a context may hold: 2^29, so that each list buffer stays within 2 GiB.
/// A GPU with list buffers past 2 GiB (though under its 4 GiB buffer limit) has returned almost
/// every list empty without an error (docs/limits.md).
pub const MAX_LIST_ENTRIES: u64 = 1 << 29;
/// List entries a context holds per pixel of its maximum extent unless told otherwise, and the
/// least it holds (so that small frames with strong blur, whose lists are long, still fit).
/// Merged 4x4 with 4 layers, every built-in scene fits at 1920x1080 and 3840x2160; lists grow with
/// the blur in pixels, and a smaller pool overflows at 4K (docs/measurements.md, "Lists, memory
/// and frames in flight"). Unmerged frames want more (the one-shot path grows the pool).
pub const DEFAULT_LIST_ENTRIES_PER_PIXEL: u64 = 2;
pub const MIN_LIST_ENTRIES: u64 = 1 << 20;
/// The longest list a context sorts unless told otherwise: the largest the device sorts in
/// workgroup memory (`dof_shaders::sort::CLASS_CAPS`, from its workgroup-memory limit: 4096 with
/// 32 KiB, 6144 with 48 KiB). A longer list is thinned to fit
/// (`dof_shaders::splat::bin::thin_keeps`), so a frame records none of the global-memory sort's
/// commands (22 more, most of them empty in most frames, for lists of up to 65 536). Give a longer
/// bound (`SplatContextDesc::max_list`) to sort such lists whole; the one-shot path does so after a
/// frame that thinned ([`DofContext::grow_to_fit`]).
pub fn default_max_list(backend: &dyn Backend) -> u32 {
    CLASS_CAPS[top_class_for(backend.limits().max_shared_bytes) as usize]
}

/// What a context is created for.
#[derive(Clone, Debug)]
pub struct SplatContextDesc {
    /// Largest frame, in pixels, and most layers (fragment slots) per pixel.
    pub max_width: u32,
    pub max_height: u32,
    pub max_layers: u32,
    /// Tile size, merging, radius cap, aperture: fixed for the context's life.
    pub options: SplatOptions,
    /// Tile-list entries the pool holds (default: [`DEFAULT_LIST_ENTRIES_PER_PIXEL`] per pixel of
    /// the maximum extent, at least [`MIN_LIST_ENTRIES`]; at most [`MAX_LIST_ENTRIES`]).
    pub list_entries: Option<u64>,
    /// Longest list one tile may have (default [`default_max_list`]).
    pub max_list: Option<u32>,
    /// Hold the buffers that image inputs and outputs go through (10 words a pixel).
    pub image_io: bool,
    /// Frames in flight (default 1): copies kept of the statistics and lists' lengths reports read.
    pub frames_in_flight: u32,
}

impl SplatContextDesc {
    /// A description for frames up to `max`, with the defaults of the rest.
    pub fn new(max: Extent, options: SplatOptions) -> Self {
        let Extent { width: max_width, height: max_height, layers: max_layers } = max;
        SplatContextDesc {
            max_width,
            max_height,
            max_layers,
            options,
            list_entries: None,
            max_list: None,
            image_io: false,
            frames_in_flight: 1,
        }
    }
}

/// The context's own buffers: the statistics, segments and aperture mask are the backend's; every
/// other is a stand-in for a transient (`Transients`), given its buffer as each frame is recorded.
struct Buffers {
    stats: BufferId,
    sharp: BufferId,
    /// Per cell of the frame (a pixel, or a merged 2x2 or 4x4 block): its fragment count, then its
    /// widest radius.
    cells: BufferId,
    /// Per cell, its offset in its tile, then its widest radius again, for binning.
    offsets: BufferId,
    tile_count: BufferId,
    tile_radius: BufferId,
    copy: BufferId,
    /// Per tile, its list's length at every thinning level (binning's count, for its plan).
    thin_counts: BufferId,
    /// Per tile and invocation, binning's count's test results of its first candidates.
    bin_cache: BufferId,
    segments: BufferId,
    dense: BufferId,
    mask: BufferId,
    keys: BufferId,
    values: BufferId,
    keys_sorted: BufferId,
    values_sorted: BufferId,
    io: Option<ImageIo>,
}

/// A tiled-splatting context (see the [module docs](crate::frame)).
pub struct SplatContext {
    desc: SplatContextDesc,
    /// The configured radius cap (px): the user's, or what `MAX_RINGS` rings reach.
    radius_cap: f32,
    merge_steps: u32,
    list_entries: u64,
    max_list: u32,
    owned: Owned,
    /// The buffers of `b` a frame uses only within itself, placed by their lifetimes.
    transients: Transients,
    bytes: u64,
    b: Buffers,
    sort: SegmentedSort,
    /// Per frame in flight, the statistics and segments its report reads (the recording writes
    /// them through `b.stats` and `b.segments`), and its frame.
    reports: Vec<(BufferId, BufferId)>,
    in_flight: InFlight<Frame>,
    /// The registry name it records as (`multilayer`, or `tiled` when handed front layers).
    name: &'static str,
    /// Whether the backend runs on llvmpipe (lavapipe), whose loop limit long lists reach
    /// ([`LLVMPIPE_SAFE_LIST`]); the driver is known at creation.
    llvmpipe: bool,
    /// Whether the backend runs a workgroup's invocations one after another
    /// (`Limits::serial_invocations`): the kernels' `FLAG_SERIAL`.
    serial: bool,
}

/// Checks the options against what the kernels support; returns the configured radius cap.
pub fn check_options(o: &SplatOptions) -> Result<f32> {
    let bad = |m: String| Err(Error::InvalidArgument(m));
    o.aperture.check()?;
    if !TILE_SIZES.contains(&o.tile) {
        return bad(format!("tile size {} is not one of {TILE_SIZES:?}", o.tile));
    }
    if !(o.merge_depth_ratio.is_finite() && o.merge_depth_ratio >= 1.0) {
        return bad(format!("merge depth ratio must be a finite number >= 1, got {}", o.merge_depth_ratio));
    }
    if !(o.merge_color_tol.is_finite() && o.merge_color_tol >= 0.0 && o.merge_min_radius.is_finite() && o.merge_min_radius >= 0.0) {
        return bad(format!("merge tolerances must be finite and >= 0 ({} and {})", o.merge_color_tol, o.merge_min_radius));
    }
    let ring_limit = (MAX_RINGS * o.tile) as f32;
    match o.max_radius {
        Some(r) if !(r.is_finite() && r >= 0.5) => bad(format!("max CoC radius must be at least 0.5 px, got {r}")),
        Some(r) if r > ring_limit => bad(format!(
            "a CoC radius cap of {r} px exceeds the {ring_limit} px that {MAX_RINGS} rings of {} px tiles reach: use larger tiles or a smaller cap",
            o.tile
        )),
        Some(r) => Ok(r),
        None => Ok(ring_limit),
    }
}

/// Cells after `steps` merging steps: edge, slots per cell, and the grid.
fn cells(width: u32, height: u32, layers: u32, steps: u32) -> (u32, u32, u32, u32) {
    let edge = 1 << steps;
    (edge, layers << (2 * steps), width.div_ceil(edge), height.div_ceil(edge))
}

impl SplatContext {
    /// Creates the context: checks the options and bounds, and allocates every buffer.
    pub fn new(backend: &mut dyn Backend, desc: &SplatContextDesc) -> Result<Self> {
        let radius_cap = check_options(&desc.options)?;
        let (w, h, layers) = (desc.max_width, desc.max_height, desc.max_layers);
        if w == 0 || h == 0 || layers == 0 {
            return Err(Error::InvalidArgument(format!("a splatting context for an empty {w}x{h} extent with {layers} layers")));
        }
        if w > MAX_EDGE || h > MAX_EDGE {
            return Err(Error::TooLarge { what: "image edge for splatting (px)".into(), size: w.max(h) as u64, limit: MAX_EDGE as u64 });
        }
        let tile = desc.options.tile;
        let pixels = w as u64 * h as u64;
        let tiles = w.div_ceil(tile) as u64 * h.div_ceil(tile) as u64;
        // Every cell keeps a region of the dense array as large as its slots, over the whole tile
        // grid (`SplatParams::cell_region`): the input's slots, padded to whole tiles.
        let slots = tiles * (tile * tile) as u64 * layers as u64;
        let max_words = backend.limits().max_buffer_bytes / 4;
        if 4 * slots > max_words {
            return Err(Error::TooLarge {
                what: "fragment slots of the input, padded to whole tiles (words)".into(),
                size: 4 * slots,
                limit: max_words,
            });
        }
        let list_entries = desc.list_entries.unwrap_or((DEFAULT_LIST_ENTRIES_PER_PIXEL * pixels).max(MIN_LIST_ENTRIES));
        if list_entries == 0 || list_entries > MAX_LIST_ENTRIES.min(max_words) {
            return Err(Error::TooLarge {
                what: "tile list entries (merge fragments with --merge 2x2 or 4x4, or render smaller)".into(),
                size: list_entries,
                limit: MAX_LIST_ENTRIES.min(max_words),
            });
        }
        // The pool's bump pointer must not wrap: every tile adds at most `max_list` to it.
        let max_list =
            desc.max_list.unwrap_or_else(|| default_max_list(backend)).clamp(1, (u32::MAX as u64 / tiles).min(list_entries) as u32);
        let merge_steps = desc.options.merge.steps();
        let in_flight = InFlight::new(desc.frames_in_flight)?;

        let sort = SegmentedSort::in_flight(backend, tiles as u32, list_entries as u32, max_list, desc.frames_in_flight)?;
        // The sorted keys are written and never read by a later stage: where the sort has a key
        // scratch for its long lists, they share it (see `SegmentedSort::scratch_keys`).
        let sorted_keys_in_scratch = sort.scratch_keys();
        // What a frame uses only within itself is placed by lifetime once the context exists
        // (`transient::placed`); the rest is kept from frame to frame, or read back.
        let mut t = Transients::default();
        let mut owned = Owned::default();
        let built = (|| {
            let (_, _, fx, fy) = cells(w, h, layers, merge_steps);
            let cell_words = 2 * fx as u64 * fy as u64;
            // Fragments are stored once, in the dense array (worst case: every slot blurred and
            // nothing merged); no level of merging is stored (`dof_shaders::splat::merge`).
            let footprint_words = match desc.options.footprint_side {
                0 => 0,
                side => footprint_words(slots as u32, side) as u64,
            };
            let io = if desc.image_io { Some(ImageIo::new(backend, pixels, &mut owned)?) } else { None };
            let mask_words = desc.options.aperture.mask_words();
            let stats = per_frame(&mut owned, backend, desc.frames_in_flight, stats::WORDS as u64, "splat/stats")?;
            let segments = per_frame(&mut owned, backend, desc.frames_in_flight, 2 * tiles, "splat/segments")?;
            let b = Buffers {
                stats: stats[0],
                sharp: t.declare(4 * pixels, "splat/sharp"),
                cells: t.declare(cell_words, "splat/cells"),
                offsets: t.declare(cell_words, "splat/offsets"),
                tile_count: t.declare(tiles, "splat/tile-count"),
                tile_radius: t.declare(tiles, "splat/tile-radius"),
                copy: t.declare(tiles, "splat/copy"),
                thin_counts: t.declare(tiles * LEVELS as u64, "splat/thin-counts"),
                bin_cache: t.declare(tiles * THREADS as u64, "splat/bin-cache"),
                segments: segments[0],
                dense: t.declare(4 * slots + footprint_words, "splat/dense"),
                mask: owned.make(backend, mask_words.len() as u64, "splat/aperture-mask")?,
                keys: t.declare(list_entries, "splat/keys"),
                values: t.declare(list_entries, "splat/values"),
                keys_sorted: match sorted_keys_in_scratch {
                    Some(scratch) => t.kept_in(scratch, list_entries, "splat/keys-sorted"),
                    None => t.declare(list_entries, "splat/keys-sorted"),
                },
                values_sorted: t.declare(list_entries, "splat/values-sorted"),
                io,
            };
            backend.write_buffer(b.mask, 0, &mask_words)?;
            Ok((b, stats.into_iter().zip(segments).collect()))
        })();
        let ((b, reports), mut owned) = match owned.or_free(backend, built) {
            Ok(made) => made,
            Err(e) => {
                sort.destroy(backend);
                return Err(e);
            }
        };
        owned.adopt(&sort.buffers());
        let mut kernels: Vec<&'static KernelDesc> = dof_shaders::splat::KERNELS.to_vec();
        kernels.extend(sort.kernels());
        if desc.image_io {
            kernels.extend(dof_shaders::frame_io::KERNELS);
        }
        let ctx = SplatContext {
            desc: desc.clone(),
            radius_cap,
            merge_steps,
            list_entries,
            max_list,
            owned,
            transients: t,
            bytes: 0,
            b,
            sort,
            reports,
            in_flight,
            name: "multilayer",
            llvmpipe: backend.driver().contains("llvmpipe"),
            serial: backend.limits().serial_invocations,
        };
        // Placed from a frame of the largest extent, with every optional stage.
        let parts: fn(&mut Self) -> (&mut Transients, &mut Owned) = |c| (&mut c.transients, &mut c.owned);
        let (max, side) = (desc.extent(), desc.options.footprint_side);
        let mut ctx = transient::placed(ctx, backend, max, side, parts, Self::commands, Self::destroy)?;
        ctx.bytes = ctx.owned.bytes() + ctx.sort.bytes();
        super::io::ready(backend, ctx, &kernels, &[], Self::destroy)
    }

    /// Frees every buffer. The backend must not be running the context's work.
    pub fn destroy(self, backend: &mut dyn Backend) {
        // The sort's buffers are among the owned ones.
        self.owned.free(backend);
    }

    /// The same context under another registry name (`tiled` for single-layer splatting).
    pub fn named(mut self, name: &'static str) -> Self {
        self.name = name;
        self
    }

    pub fn desc(&self) -> &SplatContextDesc {
        &self.desc
    }

    /// Device memory the context holds, in bytes.
    pub fn device_bytes(&self) -> u64 {
        self.bytes
    }

    /// Device memory per buffer, in bytes, summing to [`Self::device_bytes`]: one row per label
    /// (a buffer that holds several stages' data in turn names them all; the report buffers of
    /// every frame in flight are one row).
    pub fn memory_table(&self) -> Vec<(String, u64)> {
        let mut rows = self.owned.table();
        let sorted_in_scratch = self.sort.scratch_keys() == Some(self.transients.buffer(self.b.keys_sorted));
        rows.extend(self.sort.table().into_iter().map(|(label, bytes)| match label.starts_with("sort/scratch") && sorted_in_scratch {
            true => (format!("{label} (the first also splat/keys-sorted)"), bytes),
            false => (label, bytes),
        }));
        rows
    }

    /// The list pool's size (entries) and the longest list the sort handles.
    pub fn list_bounds(&self) -> (u64, u32) {
        (self.list_entries, self.max_list)
    }

    /// The kernels' parameters for frame `f` (every splatting kernel's push constants: the frame's
    /// grids, and where each cell's fragments lie in the dense array), for a caller that reads
    /// the frame's transients (`Recording::transients`) or runs the kernels itself.
    pub fn kernel_params(&self, f: &Frame) -> SplatParams {
        self.params(f, self.merge_steps)
    }

    fn params(&self, f: &Frame, step: u32) -> SplatParams {
        let o = &self.desc.options;
        let layers = f.layer_count();
        let (cell, _, cells_x, cells_y) = cells(f.width, f.height, layers, step);
        SplatParams {
            width: f.width,
            height: f.height,
            layers,
            cell,
            cells_x,
            cells_y,
            tile: o.tile,
            tiles_x: f.width.div_ceil(o.tile),
            tiles_y: f.height.div_ceil(o.tile),
            // The device plan replaces these two (`dof_shaders::splat::planned`).
            rings: MAX_RINGS,
            flags: if o.umbra_merge { FLAG_UMBRA_MERGE } else { 0 }
                | if self.serial { FLAG_SERIAL } else { 0 }
                | (self.footprint_side(f) << FOOTPRINT_SIDE_SHIFT),
            max_radius: self.radius_cap,
            merge_min_radius: o.merge_min_radius,
            merge_depth_ratio: o.merge_depth_ratio,
            merge_color_tol: o.merge_color_tol,
            lens: f.lens,
            aperture: o.aperture.kernel,
            list_capacity: self.list_entries as u32,
            max_list: self.max_list,
        }
    }

    /// The side of the footprints the frame's fragments are splatted from: its input's, with the
    /// circular aperture (a shaped one splats every fragment from its centre).
    fn footprint_side(&self, f: &Frame) -> u32 {
        if self.desc.options.aperture.kernel.is_circle() { f.footprint_side() } else { 0 }
    }

    /// Grows (or shrinks) the context to a new maximum extent: frees and reallocates its buffers.
    /// Frames within the current maximum need no resize.
    pub fn resize(&mut self, backend: &mut dyn Backend, max_width: u32, max_height: u32, max_layers: u32) -> Result<()> {
        self.owned.check(backend)?;
        let desc = self.desc.at(Extent::new(max_width, max_height, max_layers));
        let fresh = SplatContext::new(backend, &desc)?.named(self.name);
        let old = std::mem::replace(self, fresh);
        old.destroy(backend);
        Ok(())
    }

    /// Records one frame. Nothing is allocated, read back or submitted; on Vulkan the commands go
    /// into the backend's current command buffer (its own, or the caller's between
    /// `begin_external` and `end_external`).
    pub fn recording(&mut self, backend: &dyn Backend, f: &Frame) -> Result<Recording> {
        check_frame(backend, f, &self.owned, self.desc.extent(), self.b.io.as_ref())?;
        if f.footprint_side() > self.desc.options.footprint_side {
            return Err(Error::InvalidArgument(format!(
                "a frame with footprints on a {0}x{0} grid needs a splatting context created with `SplatOptions::footprint_side` \
                 {0} or more (it has {1})",
                f.footprint_side(),
                self.desc.options.footprint_side
            )));
        }
        // This frame's slot of what reports read; every other buffer is shared between frames.
        let slot = self.in_flight.next();
        (self.b.stats, self.b.segments) = self.reports[slot];
        self.sort.use_slot(slot);
        let recording = transient::capture_with_transients(self, backend, f, |c| &mut c.transients, Self::commands)?;
        self.in_flight.recorded(*f);
        Ok(recording)
    }

    /// The frame's commands (captured, and checked, by [`capture`]).
    fn commands(&mut self, backend: &mut dyn Backend, f: &Frame) -> Result<()> {
        let b = &self.b;
        let pixels = f.width as u64 * f.height as u64;
        let tiles_x = f.width.div_ceil(self.desc.options.tile);
        let tiles_y = f.height.div_ceil(self.desc.options.tile);
        let tiles = tiles_x as u64 * tiles_y as u64;
        let last = self.merge_steps;
        let (fin, first) = (self.params(f, last), self.params(f, 0));
        let tile_grid = [tiles_x, tiles_y, 1];
        let pixel_groups = groups_for(&PACK, pixels);
        let (fragments, counts) = record_input(backend, f, b.io.as_ref())?;
        let output = output_buffer(f, b.io.as_ref())?;

        backend.fill(b.stats, 0, stats::WORDS as u64, 0, "splat/clear")?;
        let side = self.footprint_side(f);
        if side > 0 {
            // Packing or merging adds each footprint into its cleared field.
            backend.fill(b.dense, footprint_base(&fin) as u64, footprint_words(fin.dense_slots(), side) as u64, 0, "splat/clear")?;
        }
        backend.run(splat_plan_reduce::Bindings { layers: fragments, counts, st: b.stats }, pixel_groups, &first, "splat/plan")?;
        backend.run(splat_plan_finish::Bindings { st: b.stats }, [1, 1, 1], &fin, "splat/plan")?;
        let (_, _, fx, fy) = cells(f.width, f.height, f.layer_count(), last);
        let (cells, cell_groups) = (b.cells, fx as u64 * fy as u64);
        let dense = b.dense;
        backend.run(
            splat_pack::Bindings { layers: fragments, counts, cells, sharp: b.sharp, dense, st: b.stats },
            pixel_groups,
            &fin,
            "splat/pack",
        )?;
        if last > 0 {
            let label = if last == 1 { "splat/merge-2x2" } else { "splat/merge-4x4" };
            let merge = splat_merge::Bindings { layers: fragments, counts, cells, dense, st: b.stats };
            backend.run(merge, groups_for(&MERGE, cell_groups), &fin, label)?;
        }
        let (tile_count, offsets, tile_radius, st) = (b.tile_count, b.offsets, b.tile_radius, b.stats);
        let count = splat_tile_count::Bindings { cells, tile_count, offsets, tile_radius, st };
        let count_groups = (tiles as u32).div_ceil(tiles_per_count_group(&fin)).min(MAX_GROUPS);
        backend.run(count, [count_groups, 1, 1], &fin, "splat/tile-count")?;
        let alloc = splat_alloc::Bindings { tile_count, tile_radius, copy: b.copy, st };
        backend.run(alloc, groups_for(&ALLOC, tiles), &fin, "splat/alloc")?;
        let (copy, keys, values, segments) = (b.copy, b.keys, b.values, b.segments);
        let (thin_counts, cache) = (b.thin_counts, b.bin_cache);
        let count = splat_bin_count::Bindings { dense, tile_count, offsets, tile_radius, copy, thin_counts, cache, st };
        backend.run(count, tile_grid, &fin, "splat/bin-count")?;
        backend.run(splat_bin_plan::Bindings { thin_counts, copy, segments, st }, [1, 1, 1], &fin, "splat/bin-plan")?;
        let bin = splat_bin::Bindings { dense, tile_count, offsets, tile_radius, copy, segments, cache, keys, values, st };
        backend.run(bin, tile_grid, &fin, "splat/bin")?;
        self.sort.record(backend, b.segments, tiles as u32, b.keys, b.values, b.keys_sorted, b.values_sorted)?;
        let acc =
            splat_accumulate::Bindings { sharp: b.sharp, dense, values: b.values_sorted, segments, copy, out: output, st, mask: b.mask };
        let sub = self.desc.options.tile / block_for(self.desc.options.tile);
        backend.run(acc, [tiles_x * sub, tiles_y * sub, 1], &fin, "splat/accumulate")?;
        record_output(backend, f, b.io.as_ref())
    }

    /// What the last recorded frame did and left out. Reads the context's statistics back, so call
    /// it only once that frame's work has completed (standalone: after `submit`). The input's
    /// fragment count, which the device does not count, is left `None` (`input_fragments`).
    pub fn report(&self, backend: &mut dyn Backend) -> Result<SplatReport> {
        self.report_of(backend, 0)
    }

    /// What the frame recorded `frames_ago` recordings before the last did (see
    /// [`DofContext::report_frame`]).
    pub fn report_of(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<SplatReport> {
        self.owned.check(backend)?;
        let (slot, f) = self.in_flight.slot(frames_ago)?;
        let (stats_buf, segments) = self.reports[slot];
        let tiles_x = f.width.div_ceil(self.desc.options.tile);
        let tiles_y = f.height.div_ceil(self.desc.options.tile);
        let tiles = tiles_x as u64 * tiles_y as u64;
        let st = backend.read_buffer(stats_buf, 0, stats::WORDS as u64)?;
        let seg = backend.read_buffer(segments, 0, 2 * tiles)?;
        let list_lengths: Vec<u32> = seg.as_chunks::<2>().0.iter().map(|s| s[1]).collect();
        let c = |i: u32| st[i as usize];
        let pixels = f.width as u64 * f.height as u64;
        let plan = SplatPlanReport {
            width: f.width,
            height: f.height,
            layers: f.layer_count(),
            tile: self.desc.options.tile,
            tiles_x,
            tiles_y,
            block: block_for(self.desc.options.tile),
            max_coc_radius: f32::from_bits(c(stats::WIDEST)),
            radius_cap: f32::from_bits(c(stats::RADIUS_CAP)),
            rings: c(stats::RINGS),
            merge_steps: self.merge_steps,
        };
        Ok(SplatReport {
            pixels,
            input_fragments: None,
            full_layer_slots: pixels * f.layer_count() as u64,
            dropped: c(stats::DROPPED),
            clamped: c(stats::CLAMPED),
            alpha_clamped: c(stats::ALPHA_CLAMPED),
            backed: c(stats::BACKED),
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
            list_offsets: seg.as_chunks::<2>().0.iter().map(|s| s[0]).collect(),
            list_capacity: self.list_entries,
            overflow_tiles: c(stats::OVERFLOW_TILES),
            overflow_entries: c(stats::OVERFLOW_ENTRIES) as u64,
            thinned_tiles: c(stats::THINNED_TILES),
            thinned_entries: c(stats::THINNED_ENTRIES) as u64,
            longest_list_wanted: c(stats::MAX_CAPACITY),
            list_top: c(stats::LIST_TOP) as u64,
            driver_loop_limit: self.llvmpipe && c(stats::MAX_CAPACITY) > LLVMPIPE_SAFE_LIST,
            sort: self.sort.stats_of(backend, slot)?,
            early_out_pixels: c(stats::EARLY_OUT),
            skipped_entries: c(stats::SKIPPED_ENTRIES),
            buffer_bytes: self.bytes,
            plan: Some(plan),
        })
    }
}

impl DofContext for SplatContext {
    fn method(&self) -> &'static str {
        self.name
    }
    fn extent(&self) -> Extent {
        self.desc.extent()
    }
    fn recording(&mut self, backend: &dyn Backend, frame: &Frame) -> Result<Recording> {
        SplatContext::recording(self, backend, frame)
    }
    fn frames_in_flight(&self) -> u32 {
        self.in_flight.frames()
    }
    fn report_frame(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<ContextReport> {
        let r = SplatContext::report_of(self, backend, frames_ago)?;
        Ok(ContextReport {
            summary: r.summary(),
            list_histogram: r.list_histogram(),
            overflow: r.tiles_cut_short() as u64,
            details: Some(std::sync::Arc::new(r)),
        })
    }
    fn device_bytes(&self) -> u64 {
        SplatContext::device_bytes(self)
    }
    fn resize(&mut self, backend: &mut dyn Backend, extent: Extent) -> Result<()> {
        SplatContext::resize(self, backend, extent.width, extent.height, extent.layers)
    }
    fn grow_to_fit(&mut self, backend: &mut dyn Backend) -> Result<bool> {
        let report = SplatContext::report(self, backend)?;
        if report.tiles_cut_short() == 0 {
            return Ok(false);
        }
        // The pool the frame wanted: every list that was placed or tried, at least double.
        let (entries, max_list) = self.list_bounds();
        if entries >= MAX_LIST_ENTRIES {
            return Err(Error::TooLarge {
                what: "tile list entries (merge fragments with --merge 2x2 or 4x4, or render smaller)".into(),
                size: report.entries_wanted(),
                limit: MAX_LIST_ENTRIES,
            });
        }
        let wanted = report.entries_wanted().max(2 * entries).min(MAX_LIST_ENTRIES);
        let desc =
            SplatContextDesc { list_entries: Some(wanted), max_list: Some(max_list.max(report.longest_list_wanted)), ..self.desc.clone() };
        let grown = SplatContext::new(backend, &desc)?.named(self.name);
        std::mem::replace(self, grown).destroy(backend);
        Ok(true)
    }
    fn destroy(self: Box<Self>, backend: &mut dyn Backend) {
        SplatContext::destroy(*self, backend)
    }
}

super::context::described!(SplatContextDesc);
