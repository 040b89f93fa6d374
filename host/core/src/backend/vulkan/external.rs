//! Recording into a caller's command buffer: the buffers a caller imports, the begin and end of
//! an external recording (and the [`External`] guard that ends it), and the retirement of buffers
//! freed while the caller's command buffers may still run.

use super::memory::StorageBuffer;
use super::{VulkanBackend, lock};
use crate::backend::{BufferId, CommandTime};
use crate::error::{Error, Result, VkContext};
use ash::vk;

impl VulkanBackend {
    /// Makes the caller's buffer `buffer` of `bytes` (a multiple of 4) a backend buffer. The backend
    /// never frees it: `destroy_buffer` only forgets it. Every command works on it as on the
    /// backend's own buffers; `read_buffer` and `write_buffer` go through the backend's staging
    /// buffers (device-local memory is fine) and submit to the queue like on the backend's own
    /// buffers. `device_bytes` and `allocations` do not count it.
    ///
    /// # Safety
    ///
    /// `buffer` is a live buffer of the backend's device, at least `bytes` long, bound to memory,
    /// with STORAGE_BUFFER usage, TRANSFER_DST usage where it is filled, written or copied into,
    /// TRANSFER_SRC usage where it is read or copied from, and INDIRECT_BUFFER usage where it holds
    /// indirect arguments; it stays alive until the backend forgot it and the GPU finished every
    /// command using it. Its exclusive queue family ownership (if any) is the backend's queue family.
    pub unsafe fn import_buffer(&mut self, buffer: vk::Buffer, bytes: u64, label: &str) -> Result<BufferId> {
        if buffer == vk::Buffer::null() {
            return Err(Error::InvalidArgument(format!("import_buffer `{label}`: the buffer is null")));
        }
        if bytes == 0 || !bytes.is_multiple_of(4) {
            return Err(Error::InvalidArgument(format!("import_buffer `{label}`: {bytes} bytes is not a positive multiple of 4")));
        }
        let limit = self.info.limits.max_buffer_bytes;
        if bytes > limit {
            return Err(Error::TooLarge { what: format!("imported buffer `{label}` on this device"), size: bytes, limit });
        }
        let id = self.next_id;
        self.next_id = id.checked_add(1).ok_or_else(|| Error::InvalidArgument("too many buffers created".into()))?;
        self.buffers.insert(id, StorageBuffer { handle: buffer, words: bytes / 4, owned: None, label: label.to_string() });
        Ok(BufferId(id))
    }

    /// Starts recording into the caller's command buffer `cb`: from here to [`Self::end_external`],
    /// `fill`, `dispatch`, `dispatch_indirect`, `draw_indirect` and the image copies are recorded
    /// into `cb`, which the caller submits and synchronises itself; `submit`, `read_buffer`,
    /// `write_buffer` and `create_buffer` are refused. `destroy_buffer` of a buffer the recording
    /// uses (a context destroyed mid-recording) forgets its id at once and frees its memory once the
    /// caller's command buffer has completed: see [`Self::release_finished`].
    ///
    /// Work the backend recorded in its own command buffer and has not submitted (such as the zeroing
    /// of buffers created since) is submitted first and waited for: one submission, counted.
    ///
    /// Synchronisation: the recording starts with a barrier from the caller's earlier compute,
    /// transfer, vertex/fragment shader and colour-attachment writes (and accesses at those stages) to
    /// every access of the backend's commands; inside, the backend orders its commands itself; it ends
    /// (in `end_external`) with a barrier making the backend's writes visible to later compute,
    /// indirect, vertex/fragment, colour-attachment and transfer accesses. The caller orders anything
    /// else (other queues, other submissions: semaphores) itself. Timed commands write timestamps into
    /// the backend's own query pools, reset inside `cb`; see [`Self::take_external_times`].
    ///
    /// # Safety
    ///
    /// `cb` is a primary command buffer of the backend's device, allocated from a pool of the
    /// backend's queue family, in the recording state and outside a render pass; the caller records
    /// nothing into it until `end_external` (or adds its own barriers against the backend's commands);
    /// it is submitted only after `end_external`, to a queue of that family; every buffer and image the
    /// recording uses stays alive until it completed.
    pub unsafe fn begin_external(&mut self, cb: vk::CommandBuffer) -> Result<()> {
        if self.recorder.is_external() {
            return Err(Error::RecordingState(
                "begin_external: already recording into a caller's command buffer; call end_external first".into(),
            ));
        }
        if cb == vk::CommandBuffer::null() {
            return Err(Error::InvalidArgument("begin_external: the command buffer is null".into()));
        }
        self.flush()?;
        self.release_finished()?;
        self.recorder.begin_external(&self.device, cb);
        self.external_used.clear();
        Ok(())
    }

    /// [`Self::begin_external`] as a guard: the returned [`External`] is the backend for the
    /// recording (it dereferences to it), and the recording ends, with the closing barrier, when
    /// the guard is dropped or [`External::end`] is called (which returns the error, where ending
    /// failed, that a drop can only log).
    ///
    /// ```no_run
    /// # use dof_core::backend::VulkanBackend;
    /// # use dof_core::frame::{DofContext, Frame};
    /// # fn frame(backend: &mut VulkanBackend, cb: dof_core::backend::vulkan::ash::vk::CommandBuffer,
    /// #          ctx: &mut dyn DofContext, frame: &Frame) -> dof_core::Result<()> {
    /// // SAFETY: `cb` is the renderer's primary command buffer, recording, outside a render pass.
    /// let mut recording = unsafe { backend.record_into(cb)? };
    /// ctx.record(&mut *recording, frame)?;
    /// recording.end() // or let it drop
    /// # }
    /// ```
    ///
    /// # Safety
    ///
    /// As for [`Self::begin_external`], with the guard's end in place of `end_external`.
    pub unsafe fn record_into(&mut self, cb: vk::CommandBuffer) -> Result<External<'_>> {
        // SAFETY: the caller's contract, passed on.
        unsafe { self.begin_external(cb)? };
        Ok(External { backend: self })
    }

    /// Ends the recording into the caller's command buffer (with the closing barrier described at
    /// [`Self::begin_external`]), and records the setting of an event of the backend's, by which
    /// [`Self::release_finished`] knows that the command buffer has completed (and may free the
    /// buffers destroyed or given back while it could still run).
    pub fn end_external(&mut self) -> Result<()> {
        let Some(cb) = self.recorder.external_command_buffer() else {
            return Err(Error::RecordingState("end_external without begin_external".into()));
        };
        let event = match self.spare_events.pop() {
            Some(event) => Ok(event),
            // SAFETY: a plain creation on the live device; destroyed in `drop`.
            None => unsafe { self.device.device.create_event(&vk::EventCreateInfo::default(), None) }.vk("vkCreateEvent"),
        };
        let ended = event.map(|event| {
            // SAFETY: `cb` is recording, outside a render pass; the event is the backend's and
            // unset (new, or reset once its recording completed).
            unsafe { self.device.device.cmd_set_event(cb, event, vk::PipelineStageFlags::ALL_COMMANDS) };
            let number = self.recordings;
            self.recordings += 1;
            self.pending.push((number, event));
            self.waiting.extend(self.retiring.drain(..).map(|(gpu, bytes)| (vec![number], gpu, bytes)));
        });
        self.recorder.end_external(&self.device);
        self.external_used.clear();
        // Without an event the destroyed buffers wait for the next recording's end (or the drop).
        ended
    }

    /// Frees what is due (never blocks): buffers destroyed during external recordings, and buffers
    /// of contexts dropped without `destroy`, once every recording that may use them has completed.
    /// A recording still running keeps them until a later call; one whose command buffer was never
    /// submitted keeps them until the backend is dropped. Returns the bytes freed.
    /// `begin_external`, `submit` and `create_buffer` call it too.
    pub fn release_finished(&mut self) -> Result<u64> {
        // The recordings that completed.
        let mut i = 0;
        while i < self.pending.len() {
            // SAFETY: the event is the backend's and alive.
            if unsafe { self.device.device.get_event_status(self.pending[i].1) }.vk("vkGetEventStatus")? {
                let (_, event) = self.pending.swap_remove(i);
                // SAFETY: the command that set it has executed; nothing else uses it.
                unsafe { self.device.device.reset_event(event) }.vk("vkResetEvent")?;
                self.spare_events.push(event);
            } else {
                i += 1;
            }
        }
        // Buffers given back: they wait for every recording that may still run.
        if !self.recorder.is_external() {
            let running: Vec<u64> = self.pending.iter().map(|&(n, _)| n).collect();
            for id in self.retire.take() {
                let Some(b) = self.buffers.remove(&id.0) else { continue };
                // An imported buffer is only forgotten.
                if let Some(gpu) = b.owned {
                    self.waiting.push((running.clone(), gpu, b.words * 4));
                }
            }
        }
        let (due, wait): (Vec<_>, Vec<_>) =
            std::mem::take(&mut self.waiting).into_iter().partition(|(on, ..)| on.iter().all(|n| self.pending.iter().all(|p| p.0 != *n)));
        self.waiting = wait;
        let mut freed = 0;
        for (_, gpu, bytes) in due {
            self.counters.remove_buffer(bytes);
            freed += bytes;
            if self.recorder.is_recording() {
                // The backend's own unsubmitted commands may use it: freed after their submission.
                self.doomed.push(gpu);
            } else {
                let allocator = self.allocator()?;
                gpu.destroy(&self.device.device, &mut lock(&allocator));
            }
        }
        Ok(freed)
    }

    /// Whether commands go into a caller's command buffer (between `begin_external` and `end_external`).
    pub fn is_external(&self) -> bool {
        self.recorder.is_external()
    }

    /// The timings of the oldest ended external recording whose times were not taken, one per
    /// timed command as `submit` returns them: `Ok(None)` while the device has not run it all (never
    /// blocks: call it after the caller's fence signalled); `Ok(Some(times))` once, after which they
    /// are gone (an empty list when there is nothing to take). Every recording keeps its own times,
    /// also several in one submission or frames in flight; past eight recordings not taken, the
    /// oldest one's are dropped. On a queue without timestamps the times are NaN.
    pub fn take_external_times(&mut self) -> Result<Option<Vec<CommandTime>>> {
        self.recorder.take_external_times(&self.device)
    }

    /// An error for `what`, which needs the backend's own command buffer, during an external recording.
    pub(super) fn refuse_external(&self, what: &str) -> Result<()> {
        if self.recorder.is_external() {
            return Err(Error::RecordingState(format!(
                "{what} is not allowed while recording into the caller's command buffer (between begin_external and \
                 end_external): it would submit or allocate; do it before begin_external or after end_external"
            )));
        }
        Ok(())
    }
}

/// A recording into a caller's command buffer ([`VulkanBackend::record_into`]): the backend while
/// it lasts, ended when dropped.
pub struct External<'a> {
    backend: &'a mut VulkanBackend,
}

impl External<'_> {
    /// Ends the recording (the closing barrier, and the event that frees buffers destroyed during
    /// it once the command buffer completes), returning what went wrong where something did.
    pub fn end(self) -> Result<()> {
        self.backend.end_external()
    }
}

impl std::ops::Deref for External<'_> {
    type Target = VulkanBackend;
    fn deref(&self) -> &VulkanBackend {
        self.backend
    }
}

impl std::ops::DerefMut for External<'_> {
    fn deref_mut(&mut self) -> &mut VulkanBackend {
        self.backend
    }
}

impl Drop for External<'_> {
    /// Ends the recording if [`External::end`] has not (an error can only be logged here).
    fn drop(&mut self) {
        if self.backend.is_external()
            && let Err(e) = self.backend.end_external()
        {
            log::error!("ending the recording into the caller's command buffer: {e}");
        }
    }
}
