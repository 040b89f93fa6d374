//! One splatting frame with every stage's buffers read back, for comparing backends stage by stage.
//! The frame runs as `dof::methods::splat::splat` runs it (its pool grown to the frame's lists),
//! then once more with its recording encoded in parts, each submitted (`splat_then`): each transient
//! (`Recording::transients`) is read as the last command that uses it leaves it, since a later
//! stage's transient may share its buffer.

use dof::backend::{Backend, CommandTime};
use dof::frame::Frame;
use dof::frame::splat::{SplatContext, SplatOptions, SplatReport};
use dof::layers::{LayeredImage, RgbImage};
use dof::methods::splat::splat_then;
use dof_core::error::{Error, Result};
use dof_shaders::lens::ThinLens;
use dof_shaders::splat::SplatParams;
use dof_shaders::splat::fragment::WORDS as FRAGMENT_WORDS;
use std::collections::HashMap;

/// Every stage's buffers.
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

pub struct Staged {
    pub image: RgbImage,
    pub report: SplatReport,
    /// The times of the parts' commands.
    pub stages: Vec<CommandTime>,
    pub intermediates: Intermediates,
}

/// Renders `image` through `lens` by tiled splatting on `backend`, reading every stage's buffers.
pub fn splat_with_stages(backend: &mut dyn Backend, image: &LayeredImage, lens: &ThinLens, options: &SplatOptions) -> Result<Staged> {
    let (out, (reads, stages, params)) = splat_then(backend, image, lens, options, |backend, ctx, frame| {
        let (reads, stages) = record_in_parts(backend, ctx, frame)?;
        Ok((reads, stages, ctx.kernel_params(frame)))
    })?;
    let intermediates = intermediates(&params, &out.report, reads)?;
    Ok(Staged { image: out.image, report: out.report, stages, intermediates })
}

/// Each transient of the frame, by label, as the last command that uses it left it.
type StageReads = HashMap<String, Vec<u32>>;

/// Encodes the frame's recording in parts, each ending at a transient's last command, submits
/// each and reads that transient; returns the reads and the parts' times.
fn record_in_parts(backend: &mut dyn Backend, ctx: &mut SplatContext, frame: &Frame) -> Result<(StageReads, Vec<CommandTime>)> {
    let recording = ctx.recording(backend, frame)?;
    let commands = recording.commands();
    let mut uses: Vec<_> = recording.transients().iter().collect();
    uses.sort_by_key(|u| u.last);
    let (mut reads, mut times, mut at) = (StageReads::new(), Vec::new(), 0);
    for u in uses {
        commands[at..=u.last].iter().try_for_each(|c| c.encode(backend))?;
        times.extend(backend.submit()?);
        reads.insert(u.label.clone(), backend.read_buffer(u.buffer, 0, u.words)?);
        at = u.last + 1;
    }
    commands[at..].iter().try_for_each(|c| c.encode(backend))?;
    times.extend(backend.submit()?);
    Ok((reads, times))
}

fn intermediates(p: &SplatParams, report: &SplatReport, mut reads: StageReads) -> Result<Intermediates> {
    let mut take = |label: &str| reads.remove(label).ok_or_else(|| Error::InvalidArgument(format!("the frame has no transient `{label}`")));
    // The cells' counts, then their widest radii; their offsets, then the radii again.
    let n = (p.cells_x * p.cells_y) as usize;
    let (mut counts, mut offsets) = (take("splat/cells")?, take("splat/offsets")?);
    counts.truncate(n);
    offsets.truncate(n);
    let mut tile_count = take("splat/tile-count")?;
    tile_count.truncate(report.tiles as usize);
    // The dense array with each cell region's unused tail left out (what lies there is whatever
    // the buffer held), then the footprint fields, which the frame clears.
    let all = take("splat/dense")?;
    let mut regions: Vec<(u32, u32)> = (0..n as u32).map(|c| (p.cell_region(c), counts[c as usize])).collect();
    regions.sort_unstable();
    let words = FRAGMENT_WORDS as usize;
    let mut dense: Vec<u32> = regions.iter().flat_map(|&(at, n)| &all[words * at as usize..words * (at + n) as usize]).copied().collect();
    dense.extend_from_slice(&all[words * p.dense_slots() as usize..]);
    // Each tile's list, in tile order.
    let lists: Vec<(u32, u32)> = report.list_offsets.iter().copied().zip(report.list_lengths.iter().copied()).collect();
    let pick =
        |all: &[u32]| -> Vec<u32> { lists.iter().flat_map(|&(at, n)| all[at as usize..(at + n) as usize].iter().copied()).collect() };
    let binned = (pick(&take("splat/keys")?), pick(&take("splat/values")?));
    let sorted = (pick(&take("splat/keys-sorted")?), pick(&take("splat/values-sorted")?));
    Ok(Intermediates { cells: vec![(counts, offsets)], tile_count, dense, list_lengths: report.list_lengths.clone(), binned, sorted })
}
