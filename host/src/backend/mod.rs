//! The two backends that run the kernels: the CPU (the kernel bodies as plain Rust, workgroups in
//! parallel with rayon) and Vulkan (the same bodies compiled to SPIR-V). A method is written once as
//! a sequence of [`Backend`] calls and runs on either.
//!
//! Semantics shared by both: `fill`, `dispatch` and `dispatch_indirect` are recorded and run in order,
//! each one seeing every write of the ones before it (the Vulkan backend puts a full memory barrier
//! between commands); `submit` runs what was recorded, waits, and returns one timing per dispatch.
//! `write_buffer` and `read_buffer` act on the host: they first submit anything still recorded.

use crate::error::{Error, Result};
use dof_shaders::{DrawDesc, KernelDesc};

pub mod cpu;
pub mod vulkan;

pub use cpu::CpuBackend;
pub use vulkan::{VulkanBackend, VulkanOptions};

/// A buffer of `u32` words owned by a backend.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BufferId(pub u32);

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
    /// Largest single buffer in bytes (`maxStorageBufferRange`, bounded by the heap).
    pub max_buffer_bytes: u64,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BackendKind {
    Cpu,
    Vulkan,
}

impl std::fmt::Display for BackendKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            BackendKind::Cpu => "cpu",
            BackendKind::Vulkan => "vulkan",
        })
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

pub trait Backend {
    fn kind(&self) -> BackendKind;
    /// The device, as the driver names it (`llvmpipe (LLVM 15.0.6, 256 bits)` for lavapipe).
    fn device_name(&self) -> String;
    /// The driver and its version, where there is one (`llvmpipe Mesa 22.3.6 (LLVM 15.0.6)`).
    fn driver(&self) -> String {
        String::new()
    }
    fn limits(&self) -> &Limits;

    /// A zeroed buffer of `words` u32 words (at least one).
    fn create_buffer(&mut self, words: u64, label: &str) -> Result<BufferId>;
    fn destroy_buffer(&mut self, buffer: BufferId);
    /// Size in words.
    fn buffer_words(&self, buffer: BufferId) -> Result<u64>;
    fn write_buffer(&mut self, buffer: BufferId, offset_words: u64, data: &[u32]) -> Result<()>;
    fn read_buffer(&mut self, buffer: BufferId, offset_words: u64, words: u64) -> Result<Vec<u32>>;

    fn fill(&mut self, buffer: BufferId, offset_words: u64, words: u64, value: u32, label: &str) -> Result<()>;
    fn dispatch(
        &mut self,
        kernel: &'static KernelDesc,
        groups: [u32; 3],
        buffers: &[BufferId],
        push: &[u32],
        label: &str,
    ) -> Result<()>;
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
        check_draw(self, draw, args, buffers, target, size, push)?;
        self.fill(target, 0, 4 * size[0] as u64 * size[1] as u64, 0, label)?;
        let mut bound = buffers.to_vec();
        bound.extend([args, target]);
        if let Some(prepass) = draw.fallback_prepass {
            self.dispatch(prepass, [dof_shaders::kernel::PREPASS_GROUPS, 1, 1], &bound, push, label)?;
        }
        let groups = [size[0].div_ceil(draw.fallback_tile), size[1].div_ceil(draw.fallback_tile), 1];
        self.dispatch(draw.fallback, groups, &bound, push, label)
    }
    fn submit(&mut self) -> Result<Vec<CommandTime>>;
    /// Messages from driver-side checking (the validation layer on Vulkan) since the last call.
    fn take_diagnostics(&mut self) -> Vec<String> {
        Vec::new()
    }
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
            draw.vertex, draw.bindings, draw.push_bytes, buffers.len(), 4 * push.len()
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

/// Checks a dispatch against the kernel's declaration and the device limits (both backends call it,
/// so the CPU backend rejects exactly what Vulkan would).
pub(crate) fn check_dispatch(
    limits: &Limits,
    kernel: &KernelDesc,
    groups: Option<[u32; 3]>,
    buffers: usize,
    push_words: usize,
) -> Result<()> {
    if buffers != kernel.bindings as usize {
        return Err(Error::InvalidArgument(format!(
            "kernel {} takes {} buffers, {} given",
            kernel.entry, kernel.bindings, buffers
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
pub fn push_words<P: bytemuck::Pod>(params: &P) -> Vec<u32> {
    let bytes = bytemuck::bytes_of(params);
    let mut words = vec![0u32; bytes.len().div_ceil(4)];
    bytemuck::cast_slice_mut::<u32, u8>(&mut words)[..bytes.len()].copy_from_slice(bytes);
    words
}
