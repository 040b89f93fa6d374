//! A frame as a value: the commands a context records for one frame, each with what it reads and
//! writes, made once and then encoded into a backend (or scheduled by a caller's render graph).
//!
//! A context makes its [`Recording`] by running its frame's commands against [`Capture`], a backend
//! that checks each command as the real backend would (buffer ranges, the kernel's bindings and
//! push constants, device limits, image copies, draw targets) and keeps it instead of running it.
//! So every check runs before anything reaches a command buffer: a refused frame leaves the
//! caller's command buffer as it was, in every context alike, and a frame is recorded once.
//!
//! From the one value:
//! - [`Recording::encode`] records it into a backend: the CPU backend runs it, the Vulkan backend
//!   appends it to its command buffer (or the caller's), barriers following from each command's
//!   reads and writes;
//! - [`Recording::commands`] and [`Command::accesses`] give a render graph the passes, their
//!   resources and the dependencies between them; [`Recording::barriers`] says where the backend's
//!   barriers go, by the same rule ([`Hazards`]);
//! - [`Recording::stages`] names the frame's stages in order.

use super::io::Frame;
use crate::backend::access::{copy_accesses, dispatch_accesses, draw_accesses};
use crate::backend::{
    Access, Backend, BackendCounters, BackendId, BackendKind, BufferId, CommandTime, Hazards, ImageRef, Limits, Resource, RetireQueue,
    check_dispatch, check_draw, check_images,
};
use crate::error::{Error, Result};
use dof_shaders::{DrawDesc, KernelDesc};

/// How many workgroups a dispatch runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Groups {
    /// Known when it is recorded.
    Direct([u32; 3]),
    /// Read on the device from `args[offset_words .. offset_words + 3]` when it runs (planned by an
    /// earlier command of the frame).
    Indirect { args: BufferId, offset_words: u64 },
}

/// One command of a frame. Buffers are the backend's ([`BufferId`]): the context's own and the
/// caller's; images are the caller's ([`ImageRef`]).
#[derive(Clone)]
#[non_exhaustive]
pub enum Command {
    /// `words` words of `buffer` from `offset_words` set to `value`.
    Fill { buffer: BufferId, offset_words: u64, words: u64, value: u32, label: String },
    /// A compute kernel over `groups`, bound to `buffers` (its storage buffers in binding order) and
    /// `images` (the caller's images it samples in place, in binding order; mostly none), with push
    /// constants `push`.
    Dispatch { kernel: &'static KernelDesc, groups: Groups, buffers: Vec<BufferId>, images: Vec<ImageRef>, push: Vec<u32>, label: String },
    /// A draw through the graphics pipeline (see [`Backend::draw_indirect`]).
    Draw {
        draw: &'static DrawDesc,
        args: BufferId,
        buffers: Vec<BufferId>,
        target: BufferId,
        size: [u32; 2],
        push: Vec<u32>,
        label: String,
    },
    /// The caller's image copied into `buffer[offset_words ..]`.
    CopyImageToBuffer { image: ImageRef, buffer: BufferId, offset_words: u64, label: String },
    /// `buffer[offset_words ..]` copied into the caller's image.
    CopyBufferToImage { buffer: BufferId, offset_words: u64, image: ImageRef, label: String },
}

impl std::fmt::Debug for Command {
    /// The kind of command, its label, its kernel or draw, and its accesses.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (kind, entry) = match self {
            Command::Fill { .. } => ("fill", ""),
            Command::Dispatch { kernel, .. } => ("dispatch", kernel.entry),
            Command::Draw { draw, .. } => ("draw", draw.vertex),
            Command::CopyImageToBuffer { .. } => ("copy_image_to_buffer", ""),
            Command::CopyBufferToImage { .. } => ("copy_buffer_to_image", ""),
        };
        f.debug_struct(kind).field("label", &self.label()).field("entry", &entry).field("accesses", &self.accesses()).finish()
    }
}

impl Command {
    /// The stage the command belongs to (`sort/classify`, `gather/plan`, ...).
    pub fn label(&self) -> &str {
        match self {
            Command::Fill { label, .. }
            | Command::Dispatch { label, .. }
            | Command::Draw { label, .. }
            | Command::CopyImageToBuffer { label, .. }
            | Command::CopyBufferToImage { label, .. } => label,
        }
    }

    /// What the command reads and writes (a kernel's `read` bindings are reads, its others writes;
    /// see [`crate::backend::access`]).
    pub fn accesses(&self) -> Vec<Access> {
        match self {
            Command::Fill { buffer, .. } => vec![Access::write(*buffer)],
            Command::Dispatch { kernel, groups, buffers, images, .. } => {
                let args = match groups {
                    Groups::Direct(_) => None,
                    Groups::Indirect { args, .. } => Some(*args),
                };
                dispatch_accesses(kernel, buffers, images, args)
            }
            Command::Draw { args, buffers, target, .. } => draw_accesses(buffers, *args, *target),
            Command::CopyImageToBuffer { image, buffer, .. } => copy_accesses(image.handle, *buffer, false).to_vec(),
            Command::CopyBufferToImage { image, buffer, .. } => copy_accesses(image.handle, *buffer, true).to_vec(),
        }
    }

    /// Calls `f` on every buffer the command names (its bindings, indirect arguments, target).
    pub(crate) fn for_each_buffer(&mut self, mut f: impl FnMut(&mut BufferId)) {
        match self {
            Command::Fill { buffer, .. } | Command::CopyImageToBuffer { buffer, .. } | Command::CopyBufferToImage { buffer, .. } => {
                f(buffer)
            }
            Command::Dispatch { groups, buffers, .. } => {
                if let Groups::Indirect { args, .. } = groups {
                    f(args);
                }
                buffers.iter_mut().for_each(f);
            }
            Command::Draw { args, buffers, target, .. } => {
                f(args);
                f(target);
                buffers.iter_mut().for_each(f);
            }
        }
    }

    /// Records the command alone into `backend` (a render graph that schedules the frame's commands
    /// itself encodes each where it goes, in an order that keeps every dependency, and puts its own
    /// barriers between them).
    pub fn encode(&self, backend: &mut dyn Backend) -> Result<()> {
        match self {
            Command::Fill { buffer, offset_words, words, value, label } => backend.fill(*buffer, *offset_words, *words, *value, label),
            Command::Dispatch { kernel, groups: Groups::Direct(groups), buffers, images, push, label } if images.is_empty() => {
                backend.dispatch(kernel, *groups, buffers, push, label)
            }
            Command::Dispatch { kernel, groups: Groups::Direct(groups), buffers, images, push, label } => {
                backend.dispatch_images(kernel, *groups, images, buffers, push, label)
            }
            Command::Dispatch { kernel, groups: Groups::Indirect { args, offset_words }, buffers, push, label, .. } => {
                backend.dispatch_indirect(kernel, *args, *offset_words, buffers, push, label)
            }
            Command::Draw { draw, args, buffers, target, size, push, label } => {
                backend.draw_indirect(draw, *args, buffers, *target, *size, push, label)
            }
            Command::CopyImageToBuffer { image, buffer, offset_words, label } => {
                backend.copy_image_to_buffer(*image, *buffer, *offset_words, label)
            }
            Command::CopyBufferToImage { buffer, offset_words, image, label } => {
                backend.copy_buffer_to_image(*buffer, *offset_words, *image, label)
            }
        }
    }
}

/// One transient buffer's use in a recorded frame ([`Recording::transients`]): the buffer it lives
/// in (shared with the transients whose uses it does not overlap) and the first and last commands
/// that use it. What its buffer holds outside those commands belongs to the buffer's other
/// transients, so a render graph may also alias the buffer with its own resources there.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TransientUse {
    /// The context's name for it (`splat/keys`, ...).
    pub label: String,
    pub buffer: BufferId,
    /// Its size; its buffer may be larger.
    pub words: u64,
    /// Indices into [`Recording::commands`], inclusive.
    pub first: usize,
    pub last: usize,
}

/// One frame's commands, checked, in the order they run. Made by a context's
/// [`recording`](super::DofContext::recording), for the backend that made the context.
#[derive(Clone, Debug)]
pub struct Recording {
    backend: BackendId,
    commands: Vec<Command>,
    transients: Vec<TransientUse>,
}

impl Recording {
    pub(crate) fn new(backend: BackendId, commands: Vec<Command>, transients: Vec<TransientUse>) -> Self {
        Recording { backend, commands, transients }
    }

    /// The commands, in order: each sees every write of the ones before it.
    pub fn commands(&self) -> &[Command] {
        &self.commands
    }

    /// The context's buffers that hold nothing between frames, with the commands that first and
    /// last use each in this frame ([`super::transient`]): several share one buffer where their
    /// uses do not overlap. Empty for a context that places none by lifetime.
    pub fn transients(&self) -> &[TransientUse] {
        &self.transients
    }

    /// The backend the recording is for (the one that made its context).
    pub fn backend(&self) -> BackendId {
        self.backend
    }

    /// The distinct stage labels, in the order they first appear.
    pub fn stages(&self) -> Vec<&str> {
        let mut stages: Vec<&str> = Vec::new();
        for c in &self.commands {
            if !stages.contains(&c.label()) {
                stages.push(c.label());
            }
        }
        stages
    }

    /// The commands a barrier goes before (indices into [`Recording::commands`]), by the rule the
    /// Vulkan backend follows ([`Hazards`]): before the first command, and before each command that
    /// reads what a command since the last barrier wrote, or writes what one accessed.
    pub fn barriers(&self) -> Vec<usize> {
        let mut hazards = Hazards::<Resource>::default();
        let accessed = |c: &Command| c.accesses().iter().map(|a| (a.resource, a.writes)).collect::<Vec<_>>();
        (0..self.commands.len()).filter(|&i| hazards.next(&accessed(&self.commands[i]))).collect()
    }

    /// Records the frame into `backend`, which must be the one the recording was made for, in a
    /// state where a frame may be recorded ([`Backend::check_frame_recording`]: on a caller's
    /// device, inside the caller's command buffer).
    pub fn encode(&self, backend: &mut dyn Backend) -> Result<()> {
        if backend.id() != self.backend {
            return Err(Error::WrongBackend(format!(
                "a recording made for another backend was handed the {} backend (recordings are tied to their context's backend)",
                backend.kind()
            )));
        }
        backend.check_frame_recording()?;
        self.commands.iter().try_for_each(|c| c.encode(backend))
    }
}

/// Runs `commands` (a context's frame) against [`Capture`] on `backend`: the checked recording.
pub(crate) fn capture<C>(
    ctx: &mut C,
    backend: &dyn Backend,
    f: &Frame,
    commands: fn(&mut C, &mut dyn Backend, &Frame) -> Result<()>,
) -> Result<Recording> {
    let commands = capture_over(ctx, backend, None, f, commands)?;
    Ok(Recording::new(backend.id(), commands, Vec::new()))
}

/// Stand-ins for buffers no backend holds yet, by their sizes (a context's transients before
/// placement, [`super::transient`]).
pub(crate) trait StandIns {
    /// The words of stand-in `id`, or `None` for a backend's buffer.
    fn words(&self, id: BufferId) -> Option<u64>;
}

/// The commands of a frame, checked, over the backend's buffers and `stand_ins` (left in place).
pub(crate) fn capture_over<C>(
    ctx: &mut C,
    backend: &dyn Backend,
    stand_ins: Option<&dyn StandIns>,
    f: &Frame,
    commands: fn(&mut C, &mut dyn Backend, &Frame) -> Result<()>,
) -> Result<Vec<Command>> {
    let mut capture = Capture { inner: backend, stand_ins, commands: Vec::new() };
    commands(ctx, &mut capture, f)?;
    Ok(capture.commands)
}

/// A backend that checks the commands recorded into it against a real backend's buffers, limits
/// and state, with the checks that backend makes before recording, and keeps them. Anything but
/// recording commands is refused: a frame does not allocate, transfer, time or submit.
struct Capture<'a> {
    inner: &'a dyn Backend,
    /// Buffers checked at their declared sizes.
    stand_ins: Option<&'a dyn StandIns>,
    commands: Vec<Command>,
}

impl Capture<'_> {
    fn range(&self, buffer: BufferId, offset: u64, words: u64) -> Result<()> {
        let have = self.buffer_words(buffer)?;
        match offset.checked_add(words) {
            Some(end) if end <= have => Ok(()),
            _ => Err(Error::InvalidArgument(format!("range {offset}..{offset}+{words} outside buffer {} of {have} words", buffer.0))),
        }
    }

    fn buffers(&self, buffers: &[BufferId]) -> Result<()> {
        buffers.iter().try_for_each(|&b| self.buffer_words(b).map(drop))
    }

    fn refused(&self, what: &str) -> Error {
        Error::RecordingState(format!("{what} while recording a frame (a frame only records commands)"))
    }
}

impl Backend for Capture<'_> {
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
    fn retire_queue(&self) -> RetireQueue {
        self.inner.retire_queue()
    }
    fn release_finished(&mut self) -> Result<u64> {
        Err(self.refused("release_finished"))
    }
    fn create_buffer(&mut self, _words: u64, _label: &str) -> Result<BufferId> {
        Err(self.refused("create_buffer"))
    }
    fn destroy_buffer(&mut self, _buffer: BufferId) {}
    fn buffer_words(&self, buffer: BufferId) -> Result<u64> {
        match self.stand_ins.and_then(|t| t.words(buffer)) {
            Some(words) => Ok(words),
            None => self.inner.buffer_words(buffer),
        }
    }
    fn write_buffer(&mut self, _buffer: BufferId, _offset_words: u64, _data: &[u32]) -> Result<()> {
        Err(self.refused("write_buffer"))
    }
    fn read_buffer(&mut self, _buffer: BufferId, _offset_words: u64, _words: u64) -> Result<Vec<u32>> {
        Err(self.refused("read_buffer"))
    }
    fn fill(&mut self, buffer: BufferId, offset_words: u64, words: u64, value: u32, label: &str) -> Result<()> {
        self.range(buffer, offset_words, words)?;
        self.commands.push(Command::Fill { buffer, offset_words, words, value, label: label.to_string() });
        Ok(())
    }
    fn dispatch(&mut self, kernel: &'static KernelDesc, groups: [u32; 3], buffers: &[BufferId], push: &[u32], label: &str) -> Result<()> {
        check_dispatch(self.inner.limits(), kernel, Some(groups), buffers.len(), 0, push.len())?;
        self.buffers(buffers)?;
        let (buffers, push, label) = (buffers.to_vec(), push.to_vec(), label.to_string());
        self.commands.push(Command::Dispatch { kernel, groups: Groups::Direct(groups), buffers, images: Vec::new(), push, label });
        Ok(())
    }
    fn dispatch_images(
        &mut self,
        kernel: &'static KernelDesc,
        groups: [u32; 3],
        images: &[ImageRef],
        buffers: &[BufferId],
        push: &[u32],
        label: &str,
    ) -> Result<()> {
        check_dispatch(self.inner.limits(), kernel, Some(groups), buffers.len(), images.len(), push.len())?;
        check_images(self.inner, kernel, images)?;
        self.buffers(buffers)?;
        let (buffers, images, push, label) = (buffers.to_vec(), images.to_vec(), push.to_vec(), label.to_string());
        self.commands.push(Command::Dispatch { kernel, groups: Groups::Direct(groups), buffers, images, push, label });
        Ok(())
    }
    fn check_image_sample(&self, image: &ImageRef) -> Result<()> {
        self.inner.check_image_sample(image)
    }
    fn check_image_store(&self, image: &ImageRef) -> Result<()> {
        self.inner.check_image_store(image)
    }
    fn dispatch_indirect(
        &mut self,
        kernel: &'static KernelDesc,
        args: BufferId,
        args_offset_words: u64,
        buffers: &[BufferId],
        push: &[u32],
        label: &str,
    ) -> Result<()> {
        // The group counts are the device's, known only when it runs.
        check_dispatch(self.inner.limits(), kernel, None, buffers.len(), 0, push.len())?;
        self.range(args, args_offset_words, 3)?;
        self.buffers(buffers)?;
        let groups = Groups::Indirect { args, offset_words: args_offset_words };
        let (buffers, push, label) = (buffers.to_vec(), push.to_vec(), label.to_string());
        self.commands.push(Command::Dispatch { kernel, groups, buffers, images: Vec::new(), push, label });
        Ok(())
    }
    fn draw_indirect(
        &mut self,
        draw: &'static DrawDesc,
        args: BufferId,
        buffers: &[BufferId],
        target: BufferId,
        size: [u32; 2],
        push: &[u32],
        label: &str,
    ) -> Result<()> {
        check_draw(self, draw, args, buffers, target, size, push)?;
        self.buffers(buffers)?;
        self.inner.check_draw_target(draw, size)?;
        let (buffers, push, label) = (buffers.to_vec(), push.to_vec(), label.to_string());
        self.commands.push(Command::Draw { draw, args, buffers, target, size, push, label });
        Ok(())
    }
    fn copy_image_to_buffer(&mut self, image: ImageRef, buffer: BufferId, offset_words: u64, label: &str) -> Result<()> {
        self.inner.check_image_copy(&image, false)?;
        self.range(buffer, offset_words, image.words())?;
        self.commands.push(Command::CopyImageToBuffer { image, buffer, offset_words, label: label.to_string() });
        Ok(())
    }
    fn copy_buffer_to_image(&mut self, buffer: BufferId, offset_words: u64, image: ImageRef, label: &str) -> Result<()> {
        self.inner.check_image_copy(&image, true)?;
        self.range(buffer, offset_words, image.words())?;
        self.commands.push(Command::CopyBufferToImage { buffer, offset_words, image, label: label.to_string() });
        Ok(())
    }
    fn check_image_copy(&self, image: &ImageRef, into_image: bool) -> Result<()> {
        self.inner.check_image_copy(image, into_image)
    }
    fn check_draw_target(&self, draw: &'static DrawDesc, size: [u32; 2]) -> Result<()> {
        self.inner.check_draw_target(draw, size)
    }
    fn begin_span(&mut self, label: &str) -> Result<()> {
        Err(self.refused(&format!("the span `{label}`")))
    }
    fn end_span(&mut self) -> Result<()> {
        Err(self.refused("end_span"))
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
