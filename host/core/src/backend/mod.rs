//! The two backends that run the kernels: the CPU (the kernel bodies as plain Rust, workgroups in
//! parallel with rayon) and Vulkan (the same bodies compiled to SPIR-V). A method is written once as
//! a sequence of [`Backend`] calls and runs on either.
//!
//! Semantics shared by both: `fill`, `dispatch` and `dispatch_indirect` are recorded and run in order,
//! each one seeing every write of the ones before it (the Vulkan backend puts a memory barrier before
//! a command that accesses a buffer an earlier command accessed since the last barrier; commands on
//! disjoint buffers may overlap); `submit` runs what was recorded, waits, and returns one timing per
//! dispatch.
//! `write_buffer` and `read_buffer` act on the host: they first submit anything still recorded.
//!
//! Images (the caller's own on Vulkan; stand-ins made by the CPU backend, [`CpuBackend::create_image`])
//! are copied into and out of buffers by `copy_image_to_buffer` and `copy_buffer_to_image`, recorded
//! like any other command; a backend that has no images refuses
//! them with an error.

use crate::error::{Error, Result};
use dof_shaders::{DrawDesc, KernelDesc};

pub mod access;
pub mod cpu;
mod image;
mod retire;
mod run;
#[cfg(feature = "vulkan")]
pub mod vulkan;
#[cfg(feature = "wgpu")]
pub mod wgpu;

#[cfg(feature = "wgpu")]
pub use self::wgpu::{WgpuBackend, WgpuOptions};
pub use access::{Access, Hazards, Resource};
pub use cpu::CpuBackend;
#[cfg(feature = "vulkan")]
pub use image::ImageDesc;
pub(crate) use image::format_names;
pub use image::{ImageFormat, ImageRef};
pub use retire::RetireQueue;

pub use run::RunKernel;
#[cfg(feature = "vulkan")]
pub use vulkan::{DRAWS_ENV, DrawPath, External, PipelineStatistic, RawDevice, RawOptions, RequiredFeatures, VulkanBackend, VulkanOptions};

/// A buffer of `u32` words owned by a backend.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BufferId(pub u32);

/// Which backend object made a resource: every backend gets its own when it is made, so a context
/// recorded or destroyed on another backend than its own is refused instead of touching that
/// backend's buffers (whose ids may well exist there too).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BackendId(u64);

impl BackendId {
    /// A new identity, never handed out before in this process.
    pub(crate) fn fresh() -> BackendId {
        static NEXT: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(1);
        BackendId(NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed))
    }
}

/// What a backend can do; the kernels' plans are sized from these (for instance the largest sort class
/// from `max_shared_bytes`).
#[derive(Clone, Debug)]
pub struct Limits {
    /// `maxComputeSharedMemorySize`.
    pub max_shared_bytes: u32,
    /// `maxComputeWorkGroupInvocations`.
    pub max_workgroup_invocations: u32,
    /// `maxComputeWorkGroupCount`.
    pub max_workgroup_count: [u32; 3],
    /// Subgroup size, where the device reports one.
    pub subgroup_size: Option<u32>,
    /// The backend runs a kernel's subgroup variant (`KernelDesc::subgroup_entry`) where it has one:
    /// the device has subgroup arithmetic in compute (the CPU backend emulates subgroups of
    /// `subgroup_size`).
    pub subgroup_kernels: bool,
    /// Largest single buffer in bytes (`maxStorageBufferRange`, bounded by the heap).
    pub max_buffer_bytes: u64,
    /// A workgroup's invocations run one after another (the CPU backend), so a kernel may choose
    /// work-efficient serial code over a parallel network (the segmented sort does).
    pub serial_invocations: bool,
}

/// Whether a GPU backend runs the kernels' subgroup variants (`KernelDesc::subgroup_entry`): the
/// same results with fewer barriers, on devices with subgroup arithmetic in compute.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Subgroups {
    /// `DOF_SUBGROUPS` if set (`on` or `off`), else wherever the device has subgroup arithmetic.
    #[default]
    Auto,
    /// Always; refused on a device without subgroup arithmetic.
    Required,
    /// Never: every kernel runs without subgroup operations.
    Off,
}

/// Environment variable choosing [`Subgroups`] when the options say `Auto`.
pub const SUBGROUPS_ENV: &str = "DOF_SUBGROUPS";

impl Subgroups {
    /// Whether to run the subgroup variants on a device that has (`device_has`) or lacks
    /// subgroup arithmetic.
    pub fn resolve(self, device_has: bool) -> Result<bool> {
        let choice = match self {
            Subgroups::Auto => match std::env::var(SUBGROUPS_ENV).ok().as_deref().map(str::trim) {
                None | Some("") => return Ok(device_has),
                Some(v) if v.eq_ignore_ascii_case("on") => Subgroups::Required,
                Some(v) if v.eq_ignore_ascii_case("off") => Subgroups::Off,
                Some(v) => return Err(Error::InvalidArgument(format!("{SUBGROUPS_ENV}={v}: give `on` or `off` (or unset it)"))),
            },
            other => other,
        };
        match choice {
            Subgroups::Required if !device_has => {
                Err(Error::InvalidArgument("subgroups required, but the device has no subgroup arithmetic in compute shaders".into()))
            }
            choice => Ok(choice == Subgroups::Required),
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BackendKind {
    Cpu,
    Vulkan,
    Wgpu,
}

impl std::fmt::Display for BackendKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            BackendKind::Cpu => "cpu",
            BackendKind::Vulkan => "vulkan",
            BackendKind::Wgpu => "wgpu",
        })
    }
}

/// What a backend has done since it was made: the numbers a frame benchmark reports per frame (the
/// difference of two snapshots, [`BackendCounters::since`]). Exact on both backends.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BackendCounters {
    /// Successful `create_buffer` calls (imported buffers do not count, nor the Vulkan backend's
    /// internal staging buffers and draw targets).
    pub allocations: u64,
    /// Queue submissions, hidden ones included: on Vulkan every `vkQueueSubmit` (by `submit`, by
    /// `read_buffer`/`write_buffer` transfers, by the flush of pending work before an external
    /// recording); on the CPU every `submit` call.
    pub submissions: u64,
    /// `read_buffer` calls that read something back (past the argument checks).
    pub readbacks: u64,
    /// `write_buffer` calls that wrote something (past the argument checks).
    pub uploads: u64,
    /// Commands recorded: `fill`, `dispatch`, `dispatch_indirect`, `draw_indirect` and image
    /// copies (on Vulkan into the backend's command buffer or the caller's; on the CPU, run).
    pub commands: u64,
    /// Kernel dispatches and draws among `commands` (`dispatch`, `dispatch_indirect`,
    /// `draw_indirect`; a draw's CPU fallback counts its prepass and its kernel).
    pub dispatches: u64,
    /// Dispatches among `dispatches` of no workgroup (an indirect dispatch whose size the device
    /// planned as zero). Counted on the CPU backend, which reads the size in place; a Vulkan
    /// backend cannot know it without a readback and counts none.
    pub empty_dispatches: u64,
    /// Pipeline barriers recorded between commands (on Vulkan: the recorder's hazard barriers and
    /// an image copy's layout transitions; on the CPU none, each command completes before the next).
    pub barriers: u64,
    /// Workgroup barriers executed inside kernels, summed over every workgroup: a GPU-shape figure
    /// the CPU backend counts (one a step of a kernel body, `dof_shaders::exec::Group::each` or a
    /// subgroup step); GPU backends count none.
    pub workgroup_barriers: u64,
    /// Bytes of the buffers the backend owns now (`4 · words` of each live `create_buffer` buffer;
    /// imports, staging and draw targets excluded).
    pub device_bytes: u64,
    /// The most `device_bytes` has been.
    pub peak_device_bytes: u64,
}

impl BackendCounters {
    /// Whether a buffer of `bytes` fits `budget` next to what is held now.
    pub(crate) fn check_budget(&self, budget: Option<u64>, bytes: u64, label: &str) -> Result<()> {
        match budget {
            Some(budget) if self.device_bytes.saturating_add(bytes) > budget => {
                Err(Error::OutOfMemory { what: label.to_string(), requested: bytes, held: self.device_bytes, budget })
            }
            _ => Ok(()),
        }
    }

    /// The counts since `earlier` (an older snapshot of the same backend); `device_bytes` and
    /// `peak_device_bytes` stay as they are now.
    pub fn since(&self, earlier: &BackendCounters) -> BackendCounters {
        BackendCounters {
            allocations: self.allocations - earlier.allocations,
            submissions: self.submissions - earlier.submissions,
            readbacks: self.readbacks - earlier.readbacks,
            uploads: self.uploads - earlier.uploads,
            commands: self.commands - earlier.commands,
            dispatches: self.dispatches - earlier.dispatches,
            empty_dispatches: self.empty_dispatches - earlier.empty_dispatches,
            barriers: self.barriers - earlier.barriers,
            workgroup_barriers: self.workgroup_barriers - earlier.workgroup_barriers,
            device_bytes: self.device_bytes,
            peak_device_bytes: self.peak_device_bytes,
        }
    }

    /// Books a buffer of `bytes` the backend now owns.
    pub(crate) fn add_buffer(&mut self, bytes: u64) {
        self.allocations += 1;
        self.device_bytes += bytes;
        self.peak_device_bytes = self.peak_device_bytes.max(self.device_bytes);
    }

    /// Forgets the peak: it becomes what is held now.
    pub(crate) fn reset_peak(&mut self) {
        self.peak_device_bytes = self.device_bytes;
    }

    /// Books a buffer of `bytes` the backend no longer owns.
    pub(crate) fn remove_buffer(&mut self, bytes: u64) {
        self.device_bytes = self.device_bytes.saturating_sub(bytes);
    }
}

/// Time one recorded command took: GPU timestamps on Vulkan, wall time on the CPU.
#[derive(Clone, Debug)]
pub struct CommandTime {
    /// The label given when recording (a stage name such as `sort/classify`).
    pub label: String,
    /// The kernel's entry point, or `fill`.
    pub kernel: &'static str,
    pub ms: f64,
}

/// The `kernel` of a span's [`CommandTime`] (see [`Backend::begin_span`]).
pub const SPAN: &str = "span";

pub trait Backend {
    fn kind(&self) -> BackendKind;
    /// This backend object's identity (see [`BackendId`]).
    fn id(&self) -> BackendId;
    /// The device, as the driver names it (`llvmpipe (LLVM 15.0.6, 256 bits)` for lavapipe).
    fn device_name(&self) -> String;
    /// The driver and its version, where there is one (`llvmpipe Mesa 22.3.6 (LLVM 15.0.6)`).
    fn driver(&self) -> String {
        String::new()
    }
    fn limits(&self) -> &Limits;

    /// The queue through which buffers are given back without the backend at hand (a context
    /// dropped without `destroy`): the backend frees what it holds at its next `create_buffer`,
    /// `submit` or [`Backend::release_finished`], once the device is done with it.
    fn retire_queue(&self) -> RetireQueue;
    /// Frees what is due: buffers given back through [`Backend::retire_queue`], and (Vulkan)
    /// buffers destroyed during recordings into a caller's command buffer, once the recordings
    /// that may use them have completed. Never blocks. Returns the bytes freed.
    fn release_finished(&mut self) -> Result<u64> {
        Ok(0)
    }
    /// A zeroed buffer of `words` u32 words (at least one).
    fn create_buffer(&mut self, words: u64, label: &str) -> Result<BufferId>;
    fn destroy_buffer(&mut self, buffer: BufferId);
    /// Size in words.
    fn buffer_words(&self, buffer: BufferId) -> Result<u64>;
    fn write_buffer(&mut self, buffer: BufferId, offset_words: u64, data: &[u32]) -> Result<()>;
    fn read_buffer(&mut self, buffer: BufferId, offset_words: u64, words: u64) -> Result<Vec<u32>>;

    fn fill(&mut self, buffer: BufferId, offset_words: u64, words: u64, value: u32, label: &str) -> Result<()>;
    fn dispatch(&mut self, kernel: &'static KernelDesc, groups: [u32; 3], buffers: &[BufferId], push: &[u32], label: &str) -> Result<()>;
    /// Like `dispatch`, with the workgroup counts read at run time from `args[offset .. offset + 3]`.
    fn dispatch_indirect(
        &mut self,
        kernel: &'static KernelDesc,
        args: BufferId,
        args_offset_words: u64,
        buffers: &[BufferId],
        push: &[u32],
        label: &str,
    ) -> Result<()>;
    /// Draws `draw` through the graphics pipeline: `args[0..4]` is the indirect draw command (vertex
    /// count, instance count, first vertex, first instance), read on the device; `buffers` are the
    /// draw's storage buffers. The sum of every instance's fragments over zero lands in `target`
    /// (`size[0] · size[1]` pixels of 4 f32 words). The default runs the draw's compute fallback
    /// from the same sources, for backends without a graphics pipeline.
    #[allow(clippy::too_many_arguments)]
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
        draw_fallback(self, draw, args, buffers, target, size, push, label)
    }
    /// Records `kernel` reading or writing images in place: `images` bind its image bindings
    /// ([`KernelDesc::images`]) in order, `buffers` its storage buffers in order; otherwise as
    /// [`Backend::dispatch`]. An image it samples must pass [`Backend::check_image_sample`], one it
    /// writes ([`KernelDesc::storage_images`]) [`Backend::check_image_store`]. On Vulkan the images
    /// go into a read layout (GENERAL for a written one) for the dispatch and into their final
    /// layouts after it, as a copy's do. Backends that bind no images refuse it.
    fn dispatch_images(
        &mut self,
        kernel: &'static KernelDesc,
        groups: [u32; 3],
        images: &[ImageRef],
        buffers: &[BufferId],
        push: &[u32],
        label: &str,
    ) -> Result<()> {
        let _ = (groups, buffers, push, label);
        check_images(self, kernel, images)?;
        Err(Error::InvalidArgument(format!("the {} backend binds no images: kernel {} needs it", self.kind(), kernel.entry)))
    }
    /// Whether a kernel can sample `image` in place ([`Backend::dispatch_images`]): the checks made
    /// before a frame records anything. A frame copies an image that fails them (one without a
    /// view, say). Backends that sample no images refuse.
    fn check_image_sample(&self, image: &ImageRef) -> Result<()> {
        let _ = image;
        Err(Error::InvalidArgument(format!("the {} backend samples no images in place", self.kind())))
    }
    /// Whether a kernel can write `image` in place (a storage image, [`Backend::dispatch_images`]):
    /// the checks made before a frame records anything. A frame copies its result into an image
    /// that fails them. Backends that write no images in place refuse.
    fn check_image_store(&self, image: &ImageRef) -> Result<()> {
        let _ = image;
        Err(Error::InvalidArgument(format!("the {} backend writes no images in place", self.kind())))
    }
    /// Copies the whole of `image` into `buffer[offset_words ..]` (packed as [`ImageFormat`] says);
    /// recorded like `fill`. `offset_words` must be a multiple of the format's words per pixel.
    /// Backends without images refuse it.
    fn copy_image_to_buffer(&mut self, image: ImageRef, buffer: BufferId, offset_words: u64, label: &str) -> Result<()> {
        let _ = (image, buffer, offset_words, label);
        Err(Error::InvalidArgument(format!("the {} backend has no images: copy_image_to_buffer needs images of the backend", self.kind())))
    }
    /// Copies `buffer[offset_words ..]` into the whole of `image`; the reverse of
    /// `copy_image_to_buffer`. Backends without images refuse it.
    fn copy_buffer_to_image(&mut self, buffer: BufferId, offset_words: u64, image: ImageRef, label: &str) -> Result<()> {
        let _ = (image, buffer, offset_words, label);
        Err(Error::InvalidArgument(format!("the {} backend has no images: copy_buffer_to_image needs images of the backend", self.kind())))
    }
    /// An image the backend makes and owns, zeroed, in the state the backend's own copies leave it
    /// in (GENERAL on Vulkan): a stand-in for a renderer's image, so that tests and benchmarks run
    /// image inputs and outputs without a renderer. Set-up work, not a frame's: on Vulkan it
    /// submits and waits. Backends without images of their own refuse.
    fn create_image(&mut self, format: ImageFormat, extent: [u32; 2]) -> Result<ImageRef> {
        let _ = (format, extent);
        Err(Error::InvalidArgument(format!("the {} backend makes no images of its own", self.kind())))
    }
    /// Writes every texel of an image of [`Backend::create_image`], packed as the copies pack them
    /// (row after row). Set-up work, as `create_image`.
    fn write_image(&mut self, image: &ImageRef, texels: &[u32]) -> Result<()> {
        let _ = (image, texels);
        Err(Error::InvalidArgument(format!("the {} backend makes no images of its own", self.kind())))
    }
    /// Frees an image of [`Backend::create_image`] once the work recorded so far is done; other
    /// images are left alone.
    fn destroy_image(&mut self, image: &ImageRef) {
        let _ = image;
    }
    /// Whether a copy of `image` (into it where `into_image`) would be recorded: the checks of
    /// [`Backend::copy_image_to_buffer`] and [`Backend::copy_buffer_to_image`] that do not depend on
    /// the buffer, made before a frame records anything. Backends without images refuse.
    fn check_image_copy(&self, image: &ImageRef, into_image: bool) -> Result<()> {
        let _ = (image, into_image);
        Err(Error::InvalidArgument(format!("the {} backend has no images", self.kind())))
    }
    /// Whether a draw of `draw` at `size` would be recorded without making anything: the check of
    /// [`Backend::draw_indirect`] that does not depend on its buffers (Vulkan: inside a caller's
    /// recording, the draw target must already cover `size`).
    fn check_draw_target(&self, _draw: &'static DrawDesc, _size: [u32; 2]) -> Result<()> {
        Ok(())
    }
    fn submit(&mut self) -> Result<Vec<CommandTime>>;
    /// Opens a span named `label`: one pair of GPU timestamps (Vulkan) or the wall clock (CPU
    /// backend) around every command recorded until the matching [`Backend::end_span`], in the
    /// backend's own submission. Spans nest; every one must be closed before `submit`. Their times
    /// come from [`Backend::take_span_times`] after the submission: a frame's time as one figure
    /// rather than a sum of per-command pairs. Backends that time nothing ignore spans.
    fn begin_span(&mut self, label: &str) -> Result<()> {
        let _ = label;
        Ok(())
    }
    /// Closes the innermost open span.
    fn end_span(&mut self) -> Result<()> {
        Ok(())
    }
    /// Whether each command gets a timestamp pair of its own (on by default): off, only spans are
    /// timed, so that a frame's span measures the frame without the per-command queries (each
    /// pair drains the pipeline between commands on some GPUs). Backends that time nothing, or
    /// time by the wall clock, ignore it.
    fn set_command_timestamps(&mut self, on: bool) {
        let _ = on;
    }
    /// The spans of everything submitted since the last call, in the order they were opened
    /// (`kernel` is [`SPAN`]; NaN on a queue without timestamps).
    fn take_span_times(&mut self) -> Vec<CommandTime> {
        Vec::new()
    }
    /// Whether a frame may be recorded now. A backend on a caller's device records frames only into
    /// the caller's command buffer (Vulkan: between `begin_external` and `end_external`); recorded
    /// into its own, the frame would run at its next submission, after the caller may have changed
    /// or freed what the frame reads. Contexts check this before recording anything.
    fn check_frame_recording(&self) -> Result<()> {
        Ok(())
    }
    /// Makes sure draws of `draw` up to `size` need nothing made at draw time (Vulkan: the draw
    /// target, grown to cover `size` and kept). Contexts that draw call it when they are made, so
    /// that a frame of any size within their extent records no allocation or submission.
    fn reserve_draw_target(&mut self, _draw: &'static DrawDesc, _size: [u32; 2]) -> Result<()> {
        Ok(())
    }
    /// Allocations, submissions, transfers and memory so far (see [`BackendCounters`]).
    fn counters(&self) -> BackendCounters;
    /// Starts [`BackendCounters::peak_device_bytes`] over from the bytes held now, so that the peak
    /// read after a piece of work is that work's own (the scaling sweep measures each run this way).
    fn reset_peak_device_bytes(&mut self);
    /// Caps the bytes of buffers the backend may hold at once (`None`: only the device's own
    /// limits). A `create_buffer` beyond it fails with [`Error::OutOfMemory`] and allocates
    /// nothing: how device memory running out is tested, and how a renderer keeps the library
    /// within its share.
    fn set_memory_budget(&mut self, budget: Option<u64>);
    /// Builds what running `kernels` and `draws` needs (pipelines on Vulkan) now, so that the
    /// first frame that records them does not pay for it. Nothing on the CPU backend.
    fn prepare(&mut self, kernels: &[&'static KernelDesc], draws: &[&'static DrawDesc]) -> Result<()> {
        let _ = (kernels, draws);
        Ok(())
    }
    /// Messages from driver-side checking (the validation layer on Vulkan) since the last call.
    fn take_diagnostics(&mut self) -> Vec<String> {
        Vec::new()
    }
}

/// A draw through its compute fallback (what `draw_indirect` does on backends without a graphics
/// pipeline).
#[allow(clippy::too_many_arguments)]
pub(crate) fn draw_fallback<B: Backend + ?Sized>(
    backend: &mut B,
    draw: &'static DrawDesc,
    args: BufferId,
    buffers: &[BufferId],
    target: BufferId,
    size: [u32; 2],
    push: &[u32],
    label: &str,
) -> Result<()> {
    check_draw(backend, draw, args, buffers, target, size, push)?;
    backend.fill(target, 0, 4 * size[0] as u64 * size[1] as u64, 0, label)?;
    let mut bound = buffers.to_vec();
    bound.extend([args, target]);
    if let Some(prepass) = draw.fallback_prepass {
        backend.dispatch(prepass, [dof_shaders::kernel::PREPASS_GROUPS, 1, 1], &bound, push, label)?;
    }
    let groups = [size[0].div_ceil(draw.fallback_tile), size[1].div_ceil(draw.fallback_tile), 1];
    backend.dispatch(draw.fallback, groups, &bound, push, label)
}

/// Checks a draw against its declaration and its buffers' sizes (both backends call it).
pub(crate) fn check_draw<B: Backend + ?Sized>(
    backend: &B,
    draw: &DrawDesc,
    args: BufferId,
    buffers: &[BufferId],
    target: BufferId,
    size: [u32; 2],
    push: &[u32],
) -> Result<()> {
    if buffers.len() != draw.bindings as usize || (push.len() as u64) * 4 < draw.push_bytes as u64 {
        return Err(Error::InvalidArgument(format!(
            "draw `{}` takes {} buffers and {} push bytes, got {} and {}",
            draw.vertex,
            draw.bindings,
            draw.push_bytes,
            buffers.len(),
            4 * push.len()
        )));
    }
    let pixels = size[0] as u64 * size[1] as u64;
    if pixels == 0 {
        return Err(Error::InvalidArgument(format!("draw `{}` into an empty {}x{} target", draw.vertex, size[0], size[1])));
    }
    if backend.buffer_words(target)? < 4 * pixels || backend.buffer_words(args)? < 4 {
        return Err(Error::InvalidArgument(format!("draw `{}`: the target needs {} words and the command 4", draw.vertex, 4 * pixels)));
    }
    Ok(())
}

/// The entry point a GPU backend makes `kernel`'s pipeline from: its subgroup variant where it
/// has one and the backend runs them (`Limits::subgroup_kernels`), else the kernel itself.
#[cfg(any(feature = "vulkan", feature = "wgpu"))]
pub(crate) fn pipeline_entry(kernel: &KernelDesc, subgroups: bool) -> &'static str {
    kernel.subgroup_entry.filter(|_| subgroups).unwrap_or(kernel.entry)
}

/// Checks a dispatch against the kernel's declaration (its buffers and sampled images) and the
/// device limits (both backends call it, so the CPU backend rejects exactly what Vulkan would).
pub(crate) fn check_dispatch(
    limits: &Limits,
    kernel: &KernelDesc,
    groups: Option<[u32; 3]>,
    buffers: usize,
    images: usize,
    push_words: usize,
) -> Result<()> {
    let takes_images = kernel.images.count_ones() as usize;
    let takes_buffers = kernel.bindings as usize - takes_images;
    if (buffers, images) != (takes_buffers, takes_images) {
        return Err(Error::InvalidArgument(format!(
            "kernel {} takes {takes_buffers} buffers and {takes_images} sampled images, {buffers} and {images} given",
            kernel.entry
        )));
    }
    if push_words * 4 < kernel.push_bytes as usize {
        return Err(Error::InvalidArgument(format!(
            "kernel {} takes {} bytes of push constants, {} given",
            kernel.entry,
            kernel.push_bytes,
            push_words * 4
        )));
    }
    if kernel.shared_bytes > limits.max_shared_bytes {
        return Err(Error::TooLarge {
            what: format!("workgroup memory of kernel {}", kernel.entry),
            size: kernel.shared_bytes as u64,
            limit: limits.max_shared_bytes as u64,
        });
    }
    if kernel.workgroup_size > limits.max_workgroup_invocations {
        return Err(Error::TooLarge {
            what: format!("workgroup size of kernel {}", kernel.entry),
            size: kernel.workgroup_size as u64,
            limit: limits.max_workgroup_invocations as u64,
        });
    }
    if let Some(groups) = groups {
        for (axis, (&n, &max)) in groups.iter().zip(&limits.max_workgroup_count).enumerate() {
            if n > max {
                return Err(Error::TooLarge {
                    what: format!("workgroup count of kernel {} along axis {axis}", kernel.entry),
                    size: n as u64,
                    limit: max as u64,
                });
            }
        }
    }
    Ok(())
}

/// Checks `images` against `kernel`'s image bindings in order: those it writes with
/// [`Backend::check_image_store`], those it samples with [`Backend::check_image_sample`].
pub(crate) fn check_images<B: Backend + ?Sized>(backend: &B, kernel: &KernelDesc, images: &[ImageRef]) -> Result<()> {
    let bindings = (0..kernel.bindings).filter(|b| kernel.images & (1 << b) != 0);
    images.iter().zip(bindings).try_for_each(|(image, binding)| {
        if kernel.storage_images & (1 << binding) != 0 { backend.check_image_store(image) } else { backend.check_image_sample(image) }
    })
}

/// Creates buffers of the given sizes, runs `f` with them, and destroys them whether `f` succeeded
/// or not (a buffer created before a failing one is destroyed too).
pub fn with_buffers<T>(
    backend: &mut dyn Backend,
    sizes: &[(u64, &str)],
    f: impl FnOnce(&mut dyn Backend, &[BufferId]) -> Result<T>,
) -> Result<T> {
    let mut buffers = Vec::with_capacity(sizes.len());
    let mut result = Ok(());
    for &(words, label) in sizes {
        match backend.create_buffer(words, label) {
            Ok(b) => buffers.push(b),
            Err(e) => {
                result = Err(e);
                break;
            }
        }
    }
    let result = result.and_then(|_| f(backend, &buffers));
    for b in buffers {
        backend.destroy_buffer(b);
    }
    result
}

/// Push constants as words, from a kernel's `#[repr(C)]` parameter struct.
/// Workgroups the host dispatches at most in one dimension; grid-stride kernels loop over the rest.
pub use dof_shaders::splat::MAX_GROUPS;

/// Workgroups of `kernel` for `items` one-dimensional items (at least one, at most [`MAX_GROUPS`]).
pub fn groups_for(kernel: &KernelDesc, items: u64) -> [u32; 3] {
    [(items.div_ceil(kernel.workgroup_size as u64)).clamp(1, MAX_GROUPS as u64) as u32, 1, 1]
}

pub fn push_words<P: bytemuck::Pod>(params: &P) -> Vec<u32> {
    let bytes = bytemuck::bytes_of(params);
    let mut words = vec![0u32; bytes.len().div_ceil(4)];
    bytemuck::cast_slice_mut::<u32, u8>(&mut words)[..bytes.len()].copy_from_slice(bytes);
    words
}
