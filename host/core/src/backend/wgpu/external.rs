//! A renderer's side of the wgpu backend: its buffers imported, and frames recorded into its own
//! command encoder.

use super::{WgpuBackend, WgpuBuffer};
use crate::backend::BufferId;
use crate::error::{Error, Result};

impl WgpuBackend {
    /// Makes the caller's `buffer` a backend buffer. The backend never frees it: `destroy_buffer`
    /// only forgets it, and wgpu keeps it alive while recorded commands use it. `device_bytes` and
    /// `allocations` do not count it. It needs STORAGE usage, COPY_DST where it is filled or
    /// written, COPY_SRC where it is read, and INDIRECT where it holds dispatch arguments (wgpu
    /// refuses a command that lacks one, at the next submission or the end of the recording).
    pub fn import_buffer(&mut self, buffer: &wgpu::Buffer, label: &str) -> Result<BufferId> {
        let bytes = buffer.size();
        if bytes == 0 || !bytes.is_multiple_of(4) {
            return Err(Error::InvalidArgument(format!("import_buffer `{label}`: {bytes} bytes is not a positive multiple of 4")));
        }
        if !buffer.usage().contains(wgpu::BufferUsages::STORAGE) {
            return Err(Error::InvalidArgument(format!("import_buffer `{label}`: the buffer has no STORAGE usage ({:?})", buffer.usage())));
        }
        Ok(self.insert(WgpuBuffer { buffer: buffer.clone(), words: bytes / 4, imported: true }))
    }

    /// Records what follows into `encoder` (the caller's), until the returned recording is dropped:
    /// frames, and any other command. Anything the backend recorded into its own encoder before is
    /// submitted first. While it lasts, whatever would submit or make a buffer is refused
    /// ([`Error::RecordingState`]): `submit`, `read_buffer`, `write_buffer`, `create_buffer`.
    /// The caller submits its encoder as it likes; frames recorded there make nothing, submit
    /// nothing and read nothing back.
    pub fn record_into<'a>(&'a mut self, encoder: &'a mut wgpu::CommandEncoder) -> Result<WgpuRecording<'a>> {
        if self.external {
            return Err(Error::RecordingState("record_into while already recording into the caller's encoder".into()));
        }
        self.flush()?;
        // The caller's encoder is the backend's until the recording ends; an empty one stands in.
        let stand_in = self.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("dof stand-in") });
        self.encoder = Some(std::mem::replace(encoder, stand_in));
        self.external = true;
        let commands_before = self.commands.len();
        Ok(WgpuRecording { backend: self, callers: encoder, commands_before })
    }
}

/// A recording into a caller's encoder ([`WgpuBackend::record_into`]): the backend while it lasts;
/// dropped, the caller's encoder holds what was recorded.
pub struct WgpuRecording<'a> {
    backend: &'a mut WgpuBackend,
    callers: &'a mut wgpu::CommandEncoder,
    /// The backend's own commands before this recording (the caller's are not its to time).
    commands_before: usize,
}

impl std::ops::Deref for WgpuRecording<'_> {
    type Target = WgpuBackend;
    fn deref(&self) -> &WgpuBackend {
        self.backend
    }
}

impl std::ops::DerefMut for WgpuRecording<'_> {
    fn deref_mut(&mut self) -> &mut WgpuBackend {
        self.backend
    }
}

impl Drop for WgpuRecording<'_> {
    fn drop(&mut self) {
        if let Some(encoder) = self.backend.encoder.take() {
            *self.callers = encoder;
        }
        self.backend.external = false;
        self.backend.commands.truncate(self.commands_before);
    }
}
