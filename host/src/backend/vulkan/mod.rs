//! The Vulkan backend: the kernels compiled to SPIR-V by rust-gpu, run as compute pipelines.
//!
//! - `instance`: loading, the instance and validation layer, device choice, the logical device;
//! - `memory`: storage and staging buffers (gpu-allocator);
//! - `pipelines`: one pipeline per kernel, from its own SPIR-V module (push descriptors);
//! - `spirv`: what the backend reads from the modules (capabilities, entry point names);
//! - `recorder`: the command buffer, barriers, timestamps and submission;
//! - `draw`: draws through the graphics pipeline into an RGBA32F target copied into a buffer.
//!
//! Everything is synchronous: every submission is waited for, so between calls the GPU is idle and
//! buffers can be read, written or freed without further synchronisation.

mod draw;
mod instance;
mod memory;
mod pipelines;
mod recorder;
mod spirv;

use super::{Backend, BackendKind, BufferId, CommandTime, Limits, check_dispatch, check_draw};
use crate::error::{Error, Result};
use ash::vk;
use dof_shaders::{DrawDesc, KernelDesc};
use gpu_allocator::MemoryLocation;
use gpu_allocator::vulkan::{Allocator, AllocatorCreateDesc};
use instance::{DeviceCtx, InstanceCtx};
use memory::{GpuBuffer, STAGING_CHUNK_BYTES, STORAGE_USAGE, Staging, StorageBuffer};
use pipelines::Pipelines;
use recorder::Recorder;
use std::collections::HashMap;

pub use instance::DEVICE_ENV;

#[derive(Clone, Debug, Default)]
pub struct VulkanOptions {
    /// Enable the Khronos validation layer (with synchronization validation) and record its messages.
    pub validation: bool,
    /// The device: a decimal index or a case-insensitive substring of its name. `None` consults
    /// `DOF_VULKAN_DEVICE`, then picks the best device (discrete > integrated > virtual > CPU).
    pub device: Option<String>,
}

/// A physical device as `list_devices` and `info` describe it.
#[derive(Clone, Debug)]
pub struct DeviceInfo {
    /// Position in the driver's enumeration (what `VulkanOptions::device` accepts as an index).
    pub index: usize,
    pub name: String,
    /// `discrete GPU`, `integrated GPU`, `virtual GPU`, `CPU` or `other`.
    pub device_type: String,
    pub api_version: String,
    /// Driver name and info (`llvmpipe Mesa 22.3.6 (LLVM 15.0.6)`).
    pub driver: String,
    pub limits: Limits,
    pub timestamp_period_ns: f32,
}

/// Every Vulkan physical device, usable or not.
pub fn list_devices() -> Result<Vec<DeviceInfo>> {
    let instance = InstanceCtx::new(false)?;
    let needed = spirv::all_capabilities();
    Ok(instance::candidates(&instance.instance, &needed)?.into_iter().map(|c| c.info).collect())
}

pub struct VulkanBackend {
    // Fields drop in declaration order after `Drop::drop` has destroyed what they made: the device
    // before the instance (and the message log, inside the instance, last).
    device: DeviceCtx,
    instance: InstanceCtx,
    /// `None` only during drop, where it must go before the device.
    allocator: Option<Allocator>,
    info: DeviceInfo,
    pipelines: Pipelines,
    draws: draw::Draws,
    physical: vk::PhysicalDevice,
    recorder: Recorder,
    buffers: HashMap<u32, StorageBuffer>,
    next_id: u32,
    /// Buffers destroyed while recorded work may still use them; freed after the next submission.
    doomed: Vec<GpuBuffer>,
    upload: Staging,
    readback: Staging,
}

impl VulkanBackend {
    pub fn new(opts: &VulkanOptions) -> Result<Self> {
        let choice = opts.device.clone().or_else(|| std::env::var(DEVICE_ENV).ok().filter(|s| !s.trim().is_empty()));
        let instance = InstanceCtx::new(opts.validation)?;
        // Device features follow from the capabilities the kernel modules declare.
        let needed = spirv::all_capabilities();
        let candidate = instance::select(instance::candidates(&instance.instance, &needed)?, choice.as_deref())?;
        let queue_family = candidate.queue_family.ok_or_else(|| Error::NoVulkan("the device has no compute queue".into()))?;
        let device = DeviceCtx::new(&instance, &candidate)?;
        let allocator = Allocator::new(&AllocatorCreateDesc {
            instance: instance.instance.clone(),
            device: device.device.clone(),
            physical_device: candidate.physical,
            debug_settings: Default::default(),
            buffer_device_address: false,
            allocation_sizes: Default::default(),
        })
        .map_err(|e| Error::Allocation(e.to_string()))?;

        // From here on `Drop` cleans up whatever a failing step leaves behind.
        let mut backend = VulkanBackend {
            device,
            instance,
            allocator: Some(allocator),
            info: candidate.info,
            pipelines: Pipelines::default(),
            draws: draw::Draws::default(),
            physical: candidate.physical,
            recorder: Recorder::empty(),
            buffers: HashMap::new(),
            next_id: 0,
            doomed: Vec::new(),
            upload: Staging::new(MemoryLocation::CpuToGpu),
            readback: Staging::new(MemoryLocation::GpuToCpu),
        };
        backend.recorder.init(&backend.device, queue_family, candidate.timestamp_bits, backend.info.timestamp_period_ns)?;
        Ok(backend)
    }

    /// The chosen device.
    pub fn info(&self) -> DeviceInfo {
        self.info.clone()
    }

    /// Every warning and error the validation layer reported so far (empty without validation).
    pub fn validation_messages(&self) -> Vec<String> {
        self.instance.messages.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }

    /// Like `validation_messages`, emptying the log.
    pub fn take_validation_messages(&mut self) -> Vec<String> {
        std::mem::take(&mut *self.instance.messages.lock().unwrap_or_else(|e| e.into_inner()))
    }

    fn allocator(&mut self) -> Result<&mut Allocator> {
        self.allocator.as_mut().ok_or_else(|| Error::Allocation("the allocator is gone".into()))
    }

    fn buffer(&self, id: BufferId) -> Result<&StorageBuffer> {
        self.buffers.get(&id.0).ok_or_else(|| Error::InvalidArgument(format!("unknown buffer {}", id.0)))
    }

    /// The buffer, after checking that `offset..offset + words` lies inside it.
    fn range(&self, id: BufferId, offset: u64, words: u64) -> Result<vk::Buffer> {
        let b = self.buffer(id)?;
        match offset.checked_add(words) {
            Some(end) if end <= b.words => Ok(b.gpu.buffer),
            _ => Err(Error::InvalidArgument(format!(
                "range {offset}..{offset}+{words} outside buffer {} of {} words",
                id.0, b.words
            ))),
        }
    }

    /// Submits recorded work (keeping its timings for `submit`) and frees buffers it was holding.
    fn flush(&mut self) -> Result<()> {
        let result = self.recorder.flush(&self.device);
        // After a failed submission the device is most likely lost; freeing is still the best move.
        if !self.recorder.is_recording() {
            let doomed = std::mem::take(&mut self.doomed);
            if let Some(allocator) = self.allocator.as_mut() {
                for b in doomed {
                    b.destroy(&self.device.device, allocator);
                }
            }
        }
        result
    }

    fn record_dispatch(
        &mut self,
        kernel: &'static KernelDesc,
        groups: Option<[u32; 3]>,
        indirect: Option<(BufferId, u64)>,
        buffers: &[BufferId],
        push: &[u32],
        label: &str,
    ) -> Result<()> {
        check_dispatch(&self.info.limits, kernel, groups, buffers.len(), push.len())?;
        let bound: Vec<vk::Buffer> = buffers.iter().map(|&b| self.buffer(b).map(|b| b.gpu.buffer)).collect::<Result<_>>()?;
        let args = match indirect {
            Some((id, offset)) => Some((self.range(id, offset, 3)?, offset * 4)),
            None => None,
        };
        let pipeline = self.pipelines.get(&self.device.device, kernel)?;

        let infos = buffer_infos(&bound);
        let writes = storage_writes(&infos);
        // Exactly the kernel's push constant bytes (rounded to whole words, as Vulkan requires).
        let push_bytes = kernel.push_bytes.div_ceil(4) as usize * 4;
        let push_data: &[u8] = &bytemuck::cast_slice::<u32, u8>(push)[..push_bytes];
        let push_descriptor = &self.device.push_descriptor;

        self.recorder.record(&self.device, Some((label, kernel.entry)), |d, cb| {
            // SAFETY: `cb` is recording; the pipeline, its layout and every bound buffer are alive
            // until the submission finishes (destroyed buffers are kept until then).
            unsafe {
                d.cmd_bind_pipeline(cb, vk::PipelineBindPoint::COMPUTE, pipeline.pipeline);
                if !writes.is_empty() {
                    push_descriptor.cmd_push_descriptor_set(cb, vk::PipelineBindPoint::COMPUTE, pipeline.layout, 0, &writes);
                }
                if !push_data.is_empty() {
                    d.cmd_push_constants(cb, pipeline.layout, vk::ShaderStageFlags::COMPUTE, 0, push_data);
                }
                match (groups, args) {
                    (_, Some((buffer, offset))) => d.cmd_dispatch_indirect(cb, buffer, offset),
                    (Some([x, y, z]), None) => d.cmd_dispatch(cb, x, y, z),
                    (None, None) => {}
                }
            }
        })
    }
}

/// Descriptor infos binding each buffer whole.
fn buffer_infos(bound: &[vk::Buffer]) -> Vec<vk::DescriptorBufferInfo> {
    bound.iter().map(|&buffer| vk::DescriptorBufferInfo::default().buffer(buffer).offset(0).range(vk::WHOLE_SIZE)).collect()
}

/// Push-descriptor writes of storage buffers at bindings `0..` in order.
fn storage_writes(infos: &[vk::DescriptorBufferInfo]) -> Vec<vk::WriteDescriptorSet<'_>> {
    infos
        .iter()
        .enumerate()
        .map(|(i, info)| {
            vk::WriteDescriptorSet::default().dst_binding(i as u32).descriptor_type(vk::DescriptorType::STORAGE_BUFFER).buffer_info(std::slice::from_ref(info))
        })
        .collect()
}

impl Backend for VulkanBackend {
    fn kind(&self) -> BackendKind {
        BackendKind::Vulkan
    }

    fn device_name(&self) -> String {
        self.info.name.clone()
    }

    fn driver(&self) -> String {
        format!("{}, Vulkan {}", self.info.driver, self.info.api_version)
    }

    fn limits(&self) -> &Limits {
        &self.info.limits
    }

    fn create_buffer(&mut self, words: u64, label: &str) -> Result<BufferId> {
        let limit = self.info.limits.max_buffer_bytes;
        let bytes = words.max(1).checked_mul(4).filter(|&b| b <= limit).ok_or_else(|| Error::TooLarge {
            what: format!("buffer `{label}`"),
            size: words.saturating_mul(4),
            limit,
        })?;
        let id = self.next_id;
        let next = id.checked_add(1).ok_or_else(|| Error::InvalidArgument("too many buffers created".into()))?;
        let device = self.device.device.clone();
        let gpu = GpuBuffer::new(&device, self.allocator()?, bytes, STORAGE_USAGE, MemoryLocation::GpuOnly, label)?;
        self.device.name(gpu.buffer, label);
        let handle = gpu.buffer;
        self.buffers.insert(id, StorageBuffer { gpu, words: bytes / 4 });
        self.next_id = next;
        // Zeroed on the GPU, ahead of (and ordered by the barrier before) whatever uses it next.
        let zeroed = self.recorder.record(&self.device, None, |d, cb| {
            // SAFETY: `cb` is recording; the buffer lives until the submission finishes.
            unsafe { d.cmd_fill_buffer(cb, handle, 0, vk::WHOLE_SIZE, 0) }
        });
        if let Err(e) = zeroed {
            self.destroy_buffer(BufferId(id));
            return Err(e);
        }
        Ok(BufferId(id))
    }

    fn destroy_buffer(&mut self, buffer: BufferId) {
        let Some(b) = self.buffers.remove(&buffer.0) else { return };
        if self.recorder.is_recording() {
            self.doomed.push(b.gpu);
        } else if let Some(allocator) = self.allocator.as_mut() {
            b.gpu.destroy(&self.device.device, allocator);
        }
    }

    fn buffer_words(&self, buffer: BufferId) -> Result<u64> {
        Ok(self.buffer(buffer)?.words)
    }

    fn write_buffer(&mut self, buffer: BufferId, offset_words: u64, data: &[u32]) -> Result<()> {
        let target = self.range(buffer, offset_words, data.len() as u64)?;
        self.flush()?;
        let device = self.device.device.clone();
        let bytes: &[u8] = bytemuck::cast_slice(data);
        for (i, chunk) in bytes.chunks(STAGING_CHUNK_BYTES as usize).enumerate() {
            let allocator = self.allocator.as_mut().ok_or_else(|| Error::Allocation("the allocator is gone".into()))?;
            let staging = self.upload.get(&device, allocator, chunk.len() as u64)?;
            staging.mapped()?[..chunk.len()].copy_from_slice(chunk);
            // Host writes before vkQueueSubmit are visible to the device (the memory is host-coherent).
            let src = staging.buffer;
            let region = [vk::BufferCopy::default()
                .dst_offset(offset_words * 4 + (i as u64) * STAGING_CHUNK_BYTES)
                .size(chunk.len() as u64)];
            self.recorder.run_once(&self.device, |d, cb| {
                // Earlier submissions' accesses to the target come first.
                recorder::full_barrier(d, cb);
                // SAFETY: `cb` is recording; both buffers are alive and the region lies inside them.
                unsafe { d.cmd_copy_buffer(cb, src, target, &region) };
            })?;
        }
        Ok(())
    }

    fn read_buffer(&mut self, buffer: BufferId, offset_words: u64, words: u64) -> Result<Vec<u32>> {
        let source = self.range(buffer, offset_words, words)?;
        self.flush()?;
        let len = usize::try_from(words).map_err(|_| Error::InvalidArgument(format!("cannot read {words} words")))?;
        let mut out = vec![0u32; len];
        let device = self.device.device.clone();
        let out_bytes: &mut [u8] = bytemuck::cast_slice_mut(&mut out);
        for (i, chunk) in out_bytes.chunks_mut(STAGING_CHUNK_BYTES as usize).enumerate() {
            let allocator = self.allocator.as_mut().ok_or_else(|| Error::Allocation("the allocator is gone".into()))?;
            let dst = self.readback.get(&device, allocator, chunk.len() as u64)?.buffer;
            let region = [vk::BufferCopy::default()
                .src_offset(offset_words * 4 + (i as u64) * STAGING_CHUNK_BYTES)
                .size(chunk.len() as u64)];
            self.recorder.run_once(&self.device, |d, cb| {
                recorder::full_barrier(d, cb);
                // SAFETY: `cb` is recording; both buffers are alive and the region lies inside them.
                unsafe { d.cmd_copy_buffer(cb, source, dst, &region) };
                // The copy's writes must be made available to the host before it maps them.
                recorder::barrier(
                    d,
                    cb,
                    vk::PipelineStageFlags::TRANSFER,
                    vk::AccessFlags::TRANSFER_WRITE,
                    vk::PipelineStageFlags::HOST,
                    vk::AccessFlags::HOST_READ,
                );
            })?;
            let staging = self.readback.buffer.as_mut().ok_or_else(|| Error::Allocation("staging buffer missing".into()))?;
            chunk.copy_from_slice(&staging.mapped()?[..chunk.len()]);
        }
        Ok(out)
    }

    fn fill(&mut self, buffer: BufferId, offset_words: u64, words: u64, value: u32, label: &str) -> Result<()> {
        let target = self.range(buffer, offset_words, words)?;
        self.recorder.record(&self.device, Some((label, "fill")), |d, cb| {
            if words > 0 {
                // SAFETY: `cb` is recording; the range lies inside the buffer.
                unsafe { d.cmd_fill_buffer(cb, target, offset_words * 4, words * 4, value) }
            }
        })
    }

    fn dispatch(&mut self, kernel: &'static KernelDesc, groups: [u32; 3], buffers: &[BufferId], push: &[u32], label: &str) -> Result<()> {
        self.record_dispatch(kernel, Some(groups), None, buffers, push, label)
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
        self.record_dispatch(kernel, None, Some((args, args_offset_words)), buffers, push, label)
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
        let max = match self.draws.max_size {
            Some(max) => max,
            None => {
                // Once per backend: the attachment format must blend, and the framebuffer limits.
                draw::check_format(&self.instance.instance, self.physical)?;
                // SAFETY: a query on the live instance and the device's physical device.
                let limits = unsafe { self.instance.instance.get_physical_device_properties(self.physical) }.limits;
                let max = [limits.max_framebuffer_width, limits.max_framebuffer_height];
                self.draws.max_size = Some(max);
                max
            }
        };
        if size[0] > max[0] || size[1] > max[1] {
            return Err(Error::TooLarge {
                what: format!("draw target {}x{} (framebuffer side)", size[0], size[1]),
                size: size[0].max(size[1]) as u64,
                limit: max[0].min(max[1]) as u64,
            });
        }
        let pipeline = self.draws.pipeline(&self.device.device, draw)?;
        if self.draws.target.as_ref().map(|t| t.size) != Some(size) {
            // Recorded work may still use the old target.
            self.flush()?;
            let device = self.device.device.clone();
            let allocator = self.allocator.as_mut().ok_or_else(|| Error::Allocation("the allocator is gone".into()))?;
            if let Some(old) = self.draws.target.take() {
                old.destroy(&device, allocator);
            }
            self.draws.target = Some(draw::Target::new(&device, allocator, pipeline.render_pass, size)?);
        }
        let (image, framebuffer) = match &self.draws.target {
            Some(t) => (t.image, t.framebuffer),
            None => return Err(Error::InvalidArgument("no draw target".into())),
        };
        let pixels = size[0] as u64 * size[1] as u64;
        let args_buffer = self.range(args, 0, 4)?;
        let target_buffer = self.range(target, 0, 4 * pixels)?;
        let bound: Vec<vk::Buffer> = buffers.iter().map(|&b| self.buffer(b).map(|b| b.gpu.buffer)).collect::<Result<_>>()?;
        let infos = buffer_infos(&bound);
        let writes = storage_writes(&infos);
        let push_bytes = draw.push_bytes.div_ceil(4) as usize * 4;
        let push_data: Vec<u8> = bytemuck::cast_slice::<u32, u8>(push)[..push_bytes].to_vec();
        let push_descriptor = &self.device.push_descriptor;
        let extent = vk::Extent2D { width: size[0], height: size[1] };
        let stages = vk::ShaderStageFlags::VERTEX | vk::ShaderStageFlags::FRAGMENT;
        self.recorder.record(&self.device, Some((label, draw.vertex)), |d, cb| {
            let clear = [
                vk::ClearValue { color: vk::ClearColorValue { float32: [0.0; 4] } },
                vk::ClearValue { depth_stencil: vk::ClearDepthStencilValue { depth: 0.0, stencil: 0 } },
            ];
            let begin = vk::RenderPassBeginInfo::default()
                .render_pass(pipeline.render_pass)
                .framebuffer(framebuffer)
                .render_area(vk::Rect2D { offset: vk::Offset2D::default(), extent })
                .clear_values(&clear);
            let viewport = [vk::Viewport { x: 0.0, y: 0.0, width: size[0] as f32, height: size[1] as f32, min_depth: 0.0, max_depth: 1.0 }];
            let scissor = [vk::Rect2D { offset: vk::Offset2D::default(), extent }];
            let region = [vk::BufferImageCopy::default()
                .image_subresource(vk::ImageSubresourceLayers::default().aspect_mask(vk::ImageAspectFlags::COLOR).layer_count(1))
                .image_extent(vk::Extent3D { width: size[0], height: size[1], depth: 1 })];
            // SAFETY: `cb` is recording; pipeline, target and buffers live until the submission ends
            // (a target is only replaced after a flush); the render pass leaves the image in
            // TRANSFER_SRC_OPTIMAL, and its external dependency orders the copy after the draw.
            unsafe {
                d.cmd_begin_render_pass(cb, &begin, vk::SubpassContents::INLINE);
                d.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, pipeline.pipeline);
                if !writes.is_empty() {
                    push_descriptor.cmd_push_descriptor_set(cb, vk::PipelineBindPoint::GRAPHICS, pipeline.layout, 0, &writes);
                }
                if !push_data.is_empty() {
                    d.cmd_push_constants(cb, pipeline.layout, stages, 0, &push_data);
                }
                d.cmd_set_viewport(cb, 0, &viewport);
                d.cmd_set_scissor(cb, 0, &scissor);
                d.cmd_draw_indirect(cb, args_buffer, 0, 1, 16);
                d.cmd_end_render_pass(cb);
                d.cmd_copy_image_to_buffer(cb, image, vk::ImageLayout::TRANSFER_SRC_OPTIMAL, target_buffer, &region);
            }
        })
    }

    fn submit(&mut self) -> Result<Vec<CommandTime>> {
        self.flush()?;
        Ok(self.recorder.take_times())
    }

    fn take_diagnostics(&mut self) -> Vec<String> {
        self.take_validation_messages()
    }
}

impl Drop for VulkanBackend {
    fn drop(&mut self) {
        let d = self.device.device.clone();
        // SAFETY: waiting makes every object below unused; nothing is destroyed twice.
        unsafe {
            let _ = d.device_wait_idle();
        }
        self.pipelines.destroy(&d);
        self.recorder.destroy(&d);
        if let Some(mut allocator) = self.allocator.take() {
            self.draws.destroy(&d, &mut allocator);
            for (_, b) in self.buffers.drain() {
                b.gpu.destroy(&d, &mut allocator);
            }
            for b in self.doomed.drain(..) {
                b.destroy(&d, &mut allocator);
            }
            self.upload.destroy(&d, &mut allocator);
            self.readback.destroy(&d, &mut allocator);
            // The allocator frees its memory blocks here, while the device still exists.
            drop(allocator);
        }
        // `device`, then `instance`, are destroyed as the fields drop.
    }
}

#[cfg(test)]
mod tests;
