//! Buffers given back without a backend at hand: a context dropped without `destroy` hands its
//! buffer ids to its backend's [`RetireQueue`], and the backend frees them at its next chance once
//! the device is done with them (the CPU backend at once; the Vulkan backend once every recording
//! into a caller's command buffer that ended before has completed).

use super::BufferId;
use std::sync::{Arc, Mutex};

/// A backend's queue of buffers to free (a handle: clones share the queue).
#[derive(Clone, Debug, Default)]
pub struct RetireQueue(Arc<Mutex<Vec<BufferId>>>);

impl RetireQueue {
    /// Hands `ids` to the backend, which frees them at its next chance.
    pub fn retire(&self, ids: impl IntoIterator<Item = BufferId>) {
        self.0.lock().unwrap_or_else(|e| e.into_inner()).extend(ids);
    }

    /// Everything handed over since the last call (for the backend).
    pub(crate) fn take(&self) -> Vec<BufferId> {
        std::mem::take(&mut *self.0.lock().unwrap_or_else(|e| e.into_inner()))
    }
}
