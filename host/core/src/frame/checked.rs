//! Every check of a frame before its first command: a context records its frame once into
//! [`DryRun`], which checks each command as the backend would and records nothing, and only then
//! into the backend. So a refused frame leaves the caller's command buffer as it was, whichever
//! command would have been refused, in every context alike.

use super::io::Frame;
use crate::backend::{
    Backend, BackendCounters, BackendId, BackendKind, BufferId, CommandTime, ImageRef, Limits, check_dispatch, check_draw,
};
use crate::error::{Error, Result};
use dof_shaders::{DrawDesc, KernelDesc};

/// Records `f` through `commands` twice: checked against [`DryRun`] first, then for real.
pub(crate) fn record_checked<C>(
    ctx: &mut C,
    backend: &mut dyn Backend,
    f: &Frame,
    commands: fn(&mut C, &mut dyn Backend, &Frame) -> Result<()>,
) -> Result<()> {
    commands(ctx, &mut DryRun { inner: &*backend }, f)?;
    commands(ctx, backend, f)
}

/// A backend that checks the commands recorded into it against a real backend's buffers, limits
/// and state, with the checks that backend makes before recording, and records nothing. Anything
/// but recording commands is refused: a frame does not allocate, transfer or submit.
pub(crate) struct DryRun<'a> {
    inner: &'a dyn Backend,
}

impl DryRun<'_> {
    fn range(&self, buffer: BufferId, offset: u64, words: u64) -> Result<()> {
        let have = self.inner.buffer_words(buffer)?;
        match offset.checked_add(words) {
            Some(end) if end <= have => Ok(()),
            _ => Err(Error::InvalidArgument(format!("range {offset}..{offset}+{words} outside buffer {} of {have} words", buffer.0))),
        }
    }

    fn buffers(&self, buffers: &[BufferId]) -> Result<()> {
        buffers.iter().try_for_each(|&b| self.inner.buffer_words(b).map(drop))
    }

    fn refused(&self, what: &str) -> Error {
        Error::InvalidArgument(format!("{what} while recording a frame (a frame only records commands)"))
    }
}

impl Backend for DryRun<'_> {
    fn kind(&self) -> BackendKind {
        self.inner.kind()
    }
    fn id(&self) -> BackendId {
        self.inner.id()
    }
    fn device_name(&self) -> String {
        self.inner.device_name()
    }
    fn limits(&self) -> &Limits {
        self.inner.limits()
    }
    fn create_buffer(&mut self, _words: u64, _label: &str) -> Result<BufferId> {
        Err(self.refused("create_buffer"))
    }
    fn destroy_buffer(&mut self, _buffer: BufferId) {}
    fn buffer_words(&self, buffer: BufferId) -> Result<u64> {
        self.inner.buffer_words(buffer)
    }
    fn write_buffer(&mut self, _buffer: BufferId, _offset_words: u64, _data: &[u32]) -> Result<()> {
        Err(self.refused("write_buffer"))
    }
    fn read_buffer(&mut self, _buffer: BufferId, _offset_words: u64, _words: u64) -> Result<Vec<u32>> {
        Err(self.refused("read_buffer"))
    }
    fn fill(&mut self, buffer: BufferId, offset_words: u64, words: u64, _value: u32, _label: &str) -> Result<()> {
        self.range(buffer, offset_words, words)
    }
    fn dispatch(&mut self, kernel: &'static KernelDesc, groups: [u32; 3], buffers: &[BufferId], push: &[u32], _label: &str) -> Result<()> {
        check_dispatch(self.inner.limits(), kernel, Some(groups), buffers.len(), push.len())?;
        self.buffers(buffers)
    }
    fn dispatch_indirect(
        &mut self,
        kernel: &'static KernelDesc,
        args: BufferId,
        args_offset_words: u64,
        buffers: &[BufferId],
        push: &[u32],
        _label: &str,
    ) -> Result<()> {
        // The group counts are the device's, known only when it runs.
        check_dispatch(self.inner.limits(), kernel, None, buffers.len(), push.len())?;
        self.range(args, args_offset_words, 3)?;
        self.buffers(buffers)
    }
    fn draw_indirect(
        &mut self,
        draw: &'static DrawDesc,
        args: BufferId,
        buffers: &[BufferId],
        target: BufferId,
        size: [u32; 2],
        push: &[u32],
        _label: &str,
    ) -> Result<()> {
        check_draw(self, draw, args, buffers, target, size, push)?;
        self.buffers(buffers)?;
        self.inner.check_draw_target(draw, size)
    }
    fn copy_image_to_buffer(&mut self, image: ImageRef, buffer: BufferId, offset_words: u64, _label: &str) -> Result<()> {
        self.inner.check_image_copy(&image, false)?;
        self.range(buffer, offset_words, image.words())
    }
    fn copy_buffer_to_image(&mut self, buffer: BufferId, offset_words: u64, image: ImageRef, _label: &str) -> Result<()> {
        self.inner.check_image_copy(&image, true)?;
        self.range(buffer, offset_words, image.words())
    }
    fn check_image_copy(&self, image: &ImageRef, into_image: bool) -> Result<()> {
        self.inner.check_image_copy(image, into_image)
    }
    fn check_draw_target(&self, draw: &'static DrawDesc, size: [u32; 2]) -> Result<()> {
        self.inner.check_draw_target(draw, size)
    }
    fn check_frame_recording(&self) -> Result<()> {
        self.inner.check_frame_recording()
    }
    fn submit(&mut self) -> Result<Vec<CommandTime>> {
        Err(self.refused("submit"))
    }
    fn counters(&self) -> BackendCounters {
        self.inner.counters()
    }
    fn reset_peak_device_bytes(&mut self) {}
    fn set_memory_budget(&mut self, _budget: Option<u64>) {}
}
