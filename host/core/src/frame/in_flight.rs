//! Frames in flight: a context made for `N` of them keeps `N` copies of what its report reads
//! (statistics, plans, counters) and nothing else. Each recording writes the next copy, round
//! robin; a report reads the copy of a given frame. Transient buffers stay single: on one queue a
//! frame's writes are ordered after the previous frame's accesses (the backend's barriers, and
//! `begin_external`'s opening barrier between recordings), so only what the host reads after a
//! frame's fence, while later frames run, must differ between frames.

use super::io::Owned;
use crate::backend::{Backend, BufferId};
use crate::error::{Error, Result};

/// Most frames in flight a context holds: engines keep two or three; the bound turns a mistaken
/// count into an error instead of a silently larger context.
pub const MAX_FRAMES_IN_FLIGHT: u32 = 8;

/// Which slot a context's next recording writes, and which slot holds the report of a frame
/// recorded `frames_ago` recordings before the last, with what the host kept of that frame (`T`:
/// its size, the options it ran with).
#[derive(Clone, Debug)]
pub(crate) struct InFlight<T> {
    /// Per slot, what the host kept of the frame last recorded into it.
    slots: Vec<Option<T>>,
    /// Frames recorded so far.
    recorded: u64,
}

impl<T: Clone> InFlight<T> {
    /// Refuses a count outside `1..=MAX_FRAMES_IN_FLIGHT` (before anything is allocated).
    pub fn new(frames: u32) -> Result<Self> {
        if !(1..=MAX_FRAMES_IN_FLIGHT).contains(&frames) {
            return Err(Error::InvalidArgument(format!("frames in flight must be 1 to {MAX_FRAMES_IN_FLIGHT}, got {frames}")));
        }
        Ok(InFlight { slots: vec![None; frames as usize], recorded: 0 })
    }

    pub fn frames(&self) -> u32 {
        self.slots.len() as u32
    }

    /// The slot the next recording writes.
    pub fn next(&self) -> usize {
        (self.recorded % self.slots.len() as u64) as usize
    }

    /// Marks the next slot as holding `kept`'s frame (after its recording succeeded; a refused
    /// recording leaves the slots as they were).
    pub fn recorded(&mut self, kept: T) {
        let slot = self.next();
        self.slots[slot] = Some(kept);
        self.recorded += 1;
    }

    /// The slot of the frame recorded `frames_ago` recordings before the last (0: the last), and
    /// what was kept of it. Refused where that many frames were not recorded, and where a later
    /// frame's recording has taken its slot (`frames_ago` at least the frames in flight).
    pub fn slot(&self, frames_ago: u32) -> Result<(usize, T)> {
        let n = self.slots.len() as u64;
        if frames_ago as u64 >= n {
            return Err(Error::InvalidArgument(format!(
                "the frame {frames_ago} recordings before the last is gone: a context made for {n} frames in flight keeps the \
                 reports of its last {n} (read a frame's report after its fence, before recording {n} more)"
            )));
        }
        if self.recorded == 0 {
            return Err(Error::InvalidArgument("no frame has been recorded yet".into()));
        }
        if frames_ago as u64 >= self.recorded {
            return Err(Error::InvalidArgument(format!(
                "no frame recorded {frames_ago} recordings before the last: {} recorded so far",
                self.recorded
            )));
        }
        let slot = ((self.recorded - 1 - frames_ago as u64) % n) as usize;
        let kept = self.slots[slot].clone().expect("a recorded slot keeps its frame");
        Ok((slot, kept))
    }
}

/// One buffer of `words` per frame in flight, owned (and counted) by `owned`, labelled `label`
/// (with the slot after it where there are several).
pub(crate) fn per_frame(owned: &mut Owned, backend: &mut dyn Backend, frames: u32, words: u64, label: &str) -> Result<Vec<BufferId>> {
    let name = |i: u32| if frames == 1 { label.to_string() } else { format!("{label}/frame-{i}") };
    (0..frames).map(|i| owned.make(backend, words, &name(i))).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slots_go_round_robin_and_reports_stay_until_their_slot_is_reused() {
        let mut f = InFlight::<u32>::new(3).unwrap();
        assert!(f.slot(0).unwrap_err().to_string().contains("no frame has been recorded"));
        for frame in 0..7 {
            assert_eq!(f.next(), frame as usize % 3);
            f.recorded(frame);
        }
        // Frames 4, 5 and 6 are in slots 1, 2 and 0.
        assert_eq!(f.slot(0).unwrap(), (0, 6));
        assert_eq!(f.slot(1).unwrap(), (2, 5));
        assert_eq!(f.slot(2).unwrap(), (1, 4));
        assert!(f.slot(3).unwrap_err().to_string().contains("gone"));
        let mut one = InFlight::<u32>::new(2).unwrap();
        one.recorded(9);
        assert!(one.slot(1).unwrap_err().to_string().contains("1 recorded"));
        assert!(InFlight::<u32>::new(0).is_err() && InFlight::<u32>::new(MAX_FRAMES_IN_FLIGHT + 1).is_err());
    }
}
