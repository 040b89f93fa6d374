//! One splatting frame of a host image, through the frame API: upload the image, create a
//! [`SplatContext`] sized to it, record, submit once, read back the image and the report.
//!
//! This is the convenience path for the CLI, the evaluation and the tests: it allocates per call.
//! A renderer keeps one context and records frame after frame ([`crate::frame`]). Where a frame's
//! lists overflow the default pool, this path runs it again with a pool as large as the frame
//! wanted, so its result is always whole.

use crate::backend::{Backend, CommandTime, with_buffers};
use crate::frame::splat::{SplatContext, SplatContextDesc};
use crate::frame::splat::{SplatOptions, SplatReport};
use crate::frame::{CountBuffer, Frame, RgbBuffer, SlotBuffer};
use crate::frame::{DofContext, Extent};
use crate::layers::{LayeredImage, RgbImage};
use crate::methods::buffers::{read_rgb, slot_words};
use crate::methods::one_shot::grow_to_fit;
use dof_core::error::{Error, Result};
use dof_shaders::lens::ThinLens;
#[cfg(feature = "testing")]
use dof_shaders::splat::fragment::WORDS as FRAGMENT_WORDS;

/// Every stage's buffers, read back by [`splat_with_stages`] (feature `testing`).
#[cfg(feature = "testing")]
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Intermediates {
    /// Per cell of the frame (a pixel, or a merged block): its fragment count, and its offset in
    /// its tile (one entry: no merging level's fragments are stored).
    pub cells: Vec<(Vec<u32>, Vec<u32>)>,
    pub tile_count: Vec<u32>,
    /// The dense fragments, cell region by cell region without their unused tails, then the
    /// footprint fields.
    pub dense: Vec<u32>,
    /// Each tile's list length (where a list lies in the pool depends on the order tiles ran in).
    pub list_lengths: Vec<u32>,
    /// The binned lists (keys, values) before and after sorting, list after list in tile order.
    pub binned: (Vec<u32>, Vec<u32>),
    pub sorted: (Vec<u32>, Vec<u32>),
}

pub struct SplatOutput {
    pub image: RgbImage,
    pub report: SplatReport,
    pub stages: Vec<CommandTime>,
    /// Every stage's buffers, where [`splat_with_stages`] ran it.
    #[cfg(feature = "testing")]
    pub intermediates: Option<Intermediates>,
}

/// Renders `image` through `lens` by tiled splatting on `backend`.
pub fn splat(backend: &mut dyn Backend, image: &LayeredImage, lens: &ThinLens, options: &SplatOptions) -> Result<SplatOutput> {
    run(backend, image, lens, options, false)
}

/// [`splat`], reading every stage's buffers back as the output's `intermediates`: for comparing
/// backends stage by stage (feature `testing`). The frame's recording is encoded in parts, each
/// submitted, so that a buffer a later stage reuses is read as its own stage left it.
#[cfg(feature = "testing")]
pub fn splat_with_stages(backend: &mut dyn Backend, image: &LayeredImage, lens: &ThinLens, options: &SplatOptions) -> Result<SplatOutput> {
    run(backend, image, lens, options, true)
}

fn run(backend: &mut dyn Backend, image: &LayeredImage, lens: &ThinLens, options: &SplatOptions, keep_stages: bool) -> Result<SplatOutput> {
    crate::lens::check(lens)?;
    crate::frame::splat::check_options(options)?;
    let (w, h, layers) = (image.width, image.height, image.max_layers);
    if w == 0 || h == 0 || layers == 0 {
        return Err(Error::InvalidArgument(format!("an empty {w}x{h} image with {layers} layers")));
    }
    let mut options = options.clone();
    options.footprint_side = options.footprint_side.max(image.footprint_grid());
    let desc = SplatContextDesc::new(Extent::new(w, h, layers), options);
    // The context checks the bounds (and refuses) before the input is uploaded.
    let mut ctx = SplatContext::new(backend, &desc)?;
    let pixels = w as u64 * h as u64;
    let input = slot_words(image);
    let sizes = [(input.len() as u64, "splat/input"), (pixels, "splat/input-counts"), (3 * pixels, "splat/out")];
    let result = with_buffers(backend, &sizes, |backend, io| {
        backend.write_buffer(io[0], 0, &input)?;
        backend.write_buffer(io[1], 0, &image.counts)?;
        let frame = Frame::layers(w, h, layers, *lens, SlotBuffer::current(io[0]), CountBuffer(io[1]), RgbBuffer(io[2]))
            .with_footprints(image.footprint_grid());
        // The frame, then, while its lists overflowed the pool, the context grown and the frame
        // run again: the one rule every one-shot run follows (`one_shot::grow_to_fit`).
        let mut stages = Vec::new();
        let mut run_frame = |ctx: &mut dyn DofContext, backend: &mut dyn Backend| -> Result<()> {
            ctx.record(backend, &frame)?;
            stages = backend.submit()?;
            Ok(())
        };
        run_frame(&mut ctx, backend)?;
        grow_to_fit(&mut ctx, backend, &mut run_frame)?;
        // Every stage's buffers as it left them: the whole frame once more, in parts.
        let _parts = if keep_stages {
            let (parts, times) = record_frame(backend, &mut ctx, &frame, keep_stages)?;
            stages = times;
            stages.extend(backend.submit()?);
            parts
        } else {
            None
        };
        let mut report = ctx.report(backend)?;
        report.input_fragments = Some(image.counts.iter().map(|&n| n.min(layers) as u64).sum());
        let out = read_rgb(backend, io[2], w, h)?;
        #[cfg(feature = "testing")]
        let inter = match _parts {
            Some(parts) => Some(intermediates(backend, &ctx, &report, parts)?),
            None => None,
        };
        Ok(SplatOutput {
            image: out,
            report,
            stages,
            #[cfg(feature = "testing")]
            intermediates: inter,
        })
    });
    ctx.destroy(backend);
    result
}

/// Records the frame. Where `keep_stages` (feature `testing`), encodes its recording in parts
/// instead, each but the last submitted, and returns what each stage's buffers held as the stage
/// left them, and the times of the parts submitted.
#[cfg(feature = "testing")]
fn record_frame(
    backend: &mut dyn Backend,
    ctx: &mut SplatContext,
    frame: &Frame,
    keep_stages: bool,
) -> Result<(Option<StageReads>, Vec<CommandTime>)> {
    if !keep_stages {
        return ctx.record(backend, frame).map(|_| (None, Vec::new()));
    }
    let recording = ctx.recording(backend, frame)?;
    let commands = recording.commands();
    let mut times = Vec::new();
    // Each transient is read as the last command that uses it leaves it: a later stage's
    // transient may share its buffer.
    let mut uses: Vec<_> = recording.transients().iter().collect();
    uses.sort_by_key(|u| u.last);
    let mut reads = StageReads::new();
    let mut at = 0;
    for u in uses {
        commands[at..=u.last].iter().try_for_each(|c| c.encode(backend))?;
        times.extend(backend.submit()?);
        reads.insert(u.label.clone(), backend.read_buffer(u.buffer, 0, u.words)?);
        at = u.last + 1;
    }
    commands[at..].iter().try_for_each(|c| c.encode(backend))?;
    Ok((Some(reads), times))
}

#[cfg(not(feature = "testing"))]
fn record_frame(
    backend: &mut dyn Backend,
    ctx: &mut SplatContext,
    frame: &Frame,
    _keep_stages: bool,
) -> Result<(Option<()>, Vec<CommandTime>)> {
    ctx.record(backend, frame).map(|_| (None, Vec::new()))
}

/// Each transient of the frame, by label, as the last command that uses it left it.
#[cfg(feature = "testing")]
type StageReads = std::collections::HashMap<String, Vec<u32>>;

#[cfg(feature = "testing")]
fn intermediates(backend: &mut dyn Backend, ctx: &SplatContext, report: &SplatReport, stages: StageReads) -> Result<Intermediates> {
    let s = dof_core::testing::stage_buffers(ctx);
    let p = s.params.ok_or_else(|| Error::InvalidArgument("the splatting context has recorded no frame".into()))?;
    let mut stages = stages;
    let mut take =
        |label: &str| stages.remove(label).ok_or_else(|| Error::InvalidArgument(format!("the frame has no transient `{label}`")));
    // The cells' counts, then their widest radii; their offsets, then the radii again.
    let n = (p.cells_x * p.cells_y) as usize;
    let (mut counts, mut offsets) = (take("splat/cells")?, take("splat/offsets")?);
    counts.truncate(n);
    offsets.truncate(n);
    let tiles = report.tiles as usize;
    let mut tile_count = take("splat/tile-count")?;
    tile_count.truncate(tiles);
    let (keys, values) = (take("splat/keys")?, take("splat/values")?);
    // The dense array with each cell region's unused tail left out (what lies there is whatever
    // the buffer held), then the footprint fields, which the frame clears.
    let all = take("splat/dense")?;
    let mut regions: Vec<(u32, u32)> = (0..counts.len() as u32).map(|c| (p.cell_region(c), counts[c as usize])).collect();
    regions.sort_unstable();
    let words = FRAGMENT_WORDS as usize;
    let mut dense: Vec<u32> = regions.iter().flat_map(|&(at, n)| &all[words * at as usize..words * (at + n) as usize]).copied().collect();
    dense.extend_from_slice(&all[words * p.dense_slots() as usize..]);
    let cells = vec![(counts, offsets)];
    let segments = backend.read_buffer(s.segments, 0, 2 * tiles as u64)?;
    let pick = |all: &[u32]| -> Vec<u32> {
        segments.as_chunks::<2>().0.iter().flat_map(|s| all[s[0] as usize..(s[0] + s[1]) as usize].iter().copied()).collect()
    };
    let binned = (pick(&keys), pick(&values));
    // The sorted keys are a transient unless they go to the sort's scratch.
    let keys_sorted = match take("splat/keys-sorted") {
        Ok(keys) => keys,
        Err(_) => backend.read_buffer(s.keys_sorted, 0, backend.buffer_words(s.keys_sorted)?)?,
    };
    let sorted = (pick(&keys_sorted), pick(&take("splat/values-sorted")?));
    Ok(Intermediates { cells, tile_count, dense, list_lengths: segments.as_chunks::<2>().0.iter().map(|s| s[1]).collect(), binned, sorted })
}
