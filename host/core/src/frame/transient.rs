//! Buffers a context uses within a frame only, placed in device memory by their lifetimes in the
//! frame's recording: two whose first and last commands do not overlap share one buffer, so a
//! context holds what its frame needs at once, not the sum of its stages.
//!
//! A context declares each such buffer with its size and gets a stand-in id that no backend holds.
//! It records one frame at its largest extent over the stand-ins ([`Transients::place`]), and the
//! buffers are made from that recording: largest first, each into the smallest buffer made so far
//! whose other occupants it does not overlap in time, else into one of its own. Each frame's
//! recording is then checked against the placement and its stand-ins replaced by the buffers
//! ([`Transients::resolve`]). A later frame records a subsequence of the planning frame's commands
//! (what it leaves out, such as the footprints' clear, only shortens lifetimes); one that did not
//! would be refused, not corrupted.
//!
//! A transient holds nothing from one frame to the next: the command that first uses it in a frame
//! writes it. Placement refuses one whose first use reads it.

use super::io::{CountBuffer, Frame, RgbBuffer, SlotBuffer};
use super::recording::{Command, Recording, StandIns, TransientUse, capture_over};
use crate::backend::{Backend, BufferId, Resource};
use crate::error::{Error, Result};
use crate::extent::Extent;
use crate::frame::io::Owned;
use dof_shaders::lens::ThinLens;

/// Stand-in ids count up from here; the backends' own ids are slot indices, far below.
const FIRST_STAND_IN: u32 = 0xC000_0000;

struct Declared {
    words: u64,
    label: String,
    kind: Kind,
}

#[derive(Clone, Copy, PartialEq)]
enum Kind {
    /// Placed by its lifetime.
    Placed,
    /// Kept in a buffer of the context's own choosing, beside what else it holds (the sorted keys
    /// in the sort's key scratch): listed with the transients, never placed or checked against
    /// them.
    In(BufferId),
    /// A caller's buffer stood in for by the planning frame: checked as any size, never placed.
    Caller,
}

/// A context's transient buffers: declared, then placed, then resolved frame by frame.
#[derive(Default)]
pub(crate) struct Transients {
    declared: Vec<Declared>,
    /// Each declared transient's buffer, once placed (the caller's stand-ins have none).
    placed: Vec<Option<BufferId>>,
}

/// A transient's commands in one recording, and whether the first writes it.
#[derive(Clone, Copy)]
struct Span {
    first: usize,
    last: usize,
    first_writes: bool,
}

impl Transients {
    /// A transient of `words` words: its stand-in id, for the context's buffers until placement.
    pub(crate) fn declare(&mut self, words: u64, label: &str) -> BufferId {
        self.push(Declared { words: words.max(1), label: label.to_string(), kind: Kind::Placed })
    }

    /// A transient kept in `buffer`, a buffer of the context's (listed in each frame's recording
    /// with the others, so a reader finds it by its label, but not placed).
    pub(crate) fn kept_in(&mut self, buffer: BufferId, words: u64, label: &str) -> BufferId {
        self.push(Declared { words: words.max(1), label: label.to_string(), kind: Kind::In(buffer) })
    }

    /// A stand-in for a caller's buffer in the planning frame, of any size.
    pub(crate) fn caller(&mut self, label: &str) -> BufferId {
        self.push(Declared { words: u64::MAX / 2, label: label.to_string(), kind: Kind::Caller })
    }

    fn push(&mut self, d: Declared) -> BufferId {
        self.declared.push(d);
        BufferId(FIRST_STAND_IN + self.declared.len() as u32 - 1)
    }

    fn index(&self, id: BufferId) -> Option<usize> {
        let i = id.0.checked_sub(FIRST_STAND_IN)? as usize;
        (i < self.declared.len()).then_some(i)
    }

    /// The buffer a stand-in was placed in, or `id` itself (a backend's buffer).
    pub(crate) fn buffer(&self, id: BufferId) -> BufferId {
        self.index(id).and_then(|i| self.placed.get(i).copied().flatten()).unwrap_or(id)
    }

    /// Each transient's commands in `commands` (`None` where unused).
    fn spans(&self, commands: &[Command]) -> Vec<Option<Span>> {
        let mut spans: Vec<Option<Span>> = vec![None; self.declared.len()];
        for (at, c) in commands.iter().enumerate() {
            for a in c.accesses() {
                let Resource::Buffer(id) = a.resource else { continue };
                let Some(i) = self.index(id) else { continue };
                let span = spans[i].get_or_insert(Span { first: at, last: at, first_writes: a.writes });
                if span.first == at {
                    // A command that both reads and writes it (two bindings) reads what it holds.
                    span.first_writes &= a.writes;
                }
                span.last = at;
            }
        }
        spans
    }

    /// Makes the transients' buffers in `owned` from their uses in `commands`, one frame recorded
    /// over the stand-ins at the context's largest extent. A transient unused there gets a buffer
    /// of its own.
    pub(crate) fn place(&mut self, backend: &mut dyn Backend, owned: &mut Owned, commands: &[Command]) -> Result<()> {
        let spans = self.spans(commands);
        let mut order: Vec<usize> = (0..self.declared.len()).filter(|&i| self.declared[i].kind != Kind::Caller).collect();
        for &i in &order {
            if let Some(s) = spans[i]
                && !s.first_writes
            {
                return Err(Error::RecordingState(format!(
                    "the transient buffer `{}` is read by the first command that uses it in a frame: a transient holds nothing \
                     between frames",
                    self.declared[i].label
                )));
            }
        }
        self.placed = self.declared.iter().map(|d| if let Kind::In(buffer) = d.kind { Some(buffer) } else { None }).collect();
        order.retain(|&i| self.declared[i].kind == Kind::Placed);
        // Largest first, so a buffer's first occupant sets its size and every later one fits.
        order.sort_by_key(|&i| std::cmp::Reverse(self.declared[i].words));
        let mut groups: Vec<Vec<usize>> = Vec::new();
        for i in order {
            let fits = |g: &Vec<usize>| match spans[i] {
                Some(s) => g.iter().all(|&j| spans[j].is_some_and(|t| s.last < t.first || t.last < s.first)),
                None => false,
            };
            // The smallest buffer it can share: the last made of those it fits.
            match groups.iter_mut().rev().find(|g| fits(g)) {
                Some(g) => g.push(i),
                None => groups.push(vec![i]),
            }
        }
        for g in groups {
            let words = self.declared[g[0]].words;
            let label = g.iter().map(|&i| self.declared[i].label.as_str()).collect::<Vec<_>>().join(", ");
            let id = owned.make(backend, words, &label)?;
            g.iter().for_each(|&i| self.placed[i] = Some(id));
        }
        Ok(())
    }

    /// Checks a frame's `commands`, recorded over the stand-ins, against the placement, and puts
    /// each transient's buffer in place of its stand-in. Returns the transients' uses.
    pub(crate) fn resolve(&self, commands: &mut [Command]) -> Result<Vec<TransientUse>> {
        let spans = self.spans(commands);
        let used: Vec<(usize, Span, BufferId)> =
            spans.iter().enumerate().filter_map(|(i, s)| Some((i, (*s)?, self.placed.get(i).copied().flatten()?))).collect();
        for (n, &(i, s, buffer)) in used.iter().enumerate() {
            if let Some(&(j, _, _)) =
                used[n + 1..].iter().find(|&&(_, t, other)| other == buffer && !(s.last < t.first || t.last < s.first))
            {
                return Err(Error::RecordingState(format!(
                    "the frame uses the transient buffers `{}` and `{}` at once, which share memory",
                    self.declared[i].label, self.declared[j].label
                )));
            }
        }
        for c in commands.iter_mut() {
            c.for_each_buffer(|id| *id = self.buffer(*id));
        }
        Ok(used
            .into_iter()
            .map(|(i, s, buffer)| TransientUse {
                label: self.declared[i].label.clone(),
                buffer,
                words: self.declared[i].words,
                first: s.first,
                last: s.last,
            })
            .collect())
    }
}

impl StandIns for Transients {
    fn words(&self, id: BufferId) -> Option<u64> {
        self.index(id).map(|i| self.declared[i].words)
    }
}

/// The frame's commands of a context (`ctx`'s `commands`, run against a capturing backend).
pub(crate) type Commands<C> = fn(&mut C, &mut dyn Backend, &Frame) -> Result<()>;

/// A new context with its transients placed (reached through `parts`, beside the owner of its
/// buffers): records a frame of extent `max` with input footprints on a `footprint_side` grid
/// (every optional stage the context records) over their stand-ins, and makes their buffers from
/// it. Where that fails, the context is destroyed and the error passed on.
pub(crate) fn placed<C>(
    mut ctx: C,
    backend: &mut dyn Backend,
    max: Extent,
    footprint_side: u32,
    parts: fn(&mut C) -> (&mut Transients, &mut Owned),
    commands: Commands<C>,
    destroy: impl FnOnce(C, &mut dyn Backend),
) -> Result<C> {
    let mut t = std::mem::take(parts(&mut ctx).0);
    let (slots, counts, out) = (t.caller("slots"), t.caller("counts"), t.caller("output"));
    let lens = ThinLens { focal_length: 0.05, aperture_radius: 0.01, focus_distance: 1.0, pixels_per_unit: 1000.0 };
    let frame = Frame::layers(max.width, max.height, max.layers, lens, SlotBuffer::current(slots), CountBuffer(counts), RgbBuffer(out))
        .with_footprints(footprint_side);
    let planned = capture_over(&mut ctx, backend, Some(&t), &frame, commands);
    let made = planned.and_then(|c| t.place(backend, parts(&mut ctx).1, &c));
    *parts(&mut ctx).0 = t;
    match made {
        Ok(()) => Ok(ctx),
        Err(e) => {
            destroy(ctx, backend);
            Err(e)
        }
    }
}

/// A context's recording of frame `f` with its transients placed: recorded over their stand-ins,
/// checked against the placement, and given their buffers.
pub(crate) fn capture_with_transients<C>(
    ctx: &mut C,
    backend: &dyn Backend,
    f: &Frame,
    transients: fn(&mut C) -> &mut Transients,
    commands: Commands<C>,
) -> Result<Recording> {
    let t = std::mem::take(transients(ctx));
    let captured = capture_over(ctx, backend, Some(&t), f, commands);
    let recording = captured.and_then(|mut commands| {
        let uses = t.resolve(&mut commands)?;
        Ok(Recording::new(backend.id(), commands, uses))
    });
    *transients(ctx) = t;
    recording
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::backend::CpuBackend;
    use crate::frame::Groups;

    fn fill(buffer: BufferId) -> Command {
        Command::Fill { buffer, offset_words: 0, words: 1, value: 0, label: "test".into() }
    }

    /// A dispatch that reads `read` and writes `write` (the sort's classify kernel: it reads its
    /// first binding, the lists' segments).
    fn read_into(read: BufferId, write: BufferId) -> Command {
        let kernel = &dof_shaders::sort::CLASSIFY;
        assert_eq!(kernel.read_only & 0b111, 0b001, "the kernel reads its first binding only");
        let buffers = vec![read, write, write];
        Command::Dispatch { kernel, groups: Groups::Direct([1, 1, 1]), buffers, images: vec![], push: vec![], label: "test".into() }
    }

    fn stand_ins(t: &Transients, commands: &[Command]) -> usize {
        let mut n = 0;
        commands.iter().cloned().for_each(|mut c| c.for_each_buffer(|id| n += t.index(*id).is_some() as usize));
        n
    }

    #[test]
    fn transients_whose_uses_do_not_overlap_share_a_buffer_the_size_of_the_largest() {
        let mut b = CpuBackend::new();
        let mut owned = Owned::default();
        let mut t = Transients::default();
        let (big, small, late, lone) = (t.declare(100, "big"), t.declare(10, "small"), t.declare(50, "late"), t.declare(60, "lone"));
        // lone 0-4 (overlaps all), big 1-2, small 2-3 (overlaps big), late 4.
        let commands = vec![fill(lone), fill(big), read_into(big, small), read_into(small, lone), read_into(lone, late)];
        t.place(&mut b, &mut owned, &commands).unwrap();
        // big and late share; small overlaps big and lone, so it has a buffer of its own.
        assert_eq!(owned.bytes(), 4 * (100 + 60 + 10));
        let mut frame = commands.clone();
        let uses = t.resolve(&mut frame).unwrap();
        let buffer = |label: &str| uses.iter().find(|u| u.label == label).map(|u| (u.buffer, u.first, u.last)).unwrap();
        assert_eq!(buffer("big").0, buffer("late").0);
        assert_ne!(buffer("big").0, buffer("small").0);
        assert_eq!((buffer("small").1, buffer("small").2), (2, 3));
        assert_eq!(stand_ins(&t, &frame), 0, "stand-ins replaced");
        // A frame that uses two sharing transients at once is refused.
        let mut clash = vec![fill(big), read_into(big, late)];
        let e = t.resolve(&mut clash).unwrap_err().to_string();
        assert!(e.contains("`big` and `late`"), "{e}");
        owned.free(&mut b);
    }

    #[test]
    fn a_transient_first_read_in_its_frame_is_refused() {
        let mut b = CpuBackend::new();
        let mut owned = Owned::default();
        let mut t = Transients::default();
        let (kept, out) = (t.declare(4, "kept"), t.declare(4, "out"));
        let e = t.place(&mut b, &mut owned, &[read_into(kept, out)]).unwrap_err().to_string();
        assert!(e.contains("`kept` is read by the first command"), "{e}");
        assert_eq!(owned.bytes(), 0, "nothing made");
    }
}
