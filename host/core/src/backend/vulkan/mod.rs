//! The Vulkan backend: the kernels compiled to SPIR-V by rust-gpu, run as compute pipelines.
//!
//! - `instance`: loading, the instance and validation layer, device choice, the logical device;
//! - `memory`: storage and staging buffers (gpu-allocator);
//! - `pipelines`: one pipeline per kernel, from its own SPIR-V module (push descriptors): the project's
//!   embedded ones, and a caller's own added with [`VulkanBackend::add_modules`];
//! - `spirv`: what the backend reads from the modules (capabilities, entry point names);
//! - `recorder`: the command buffer, barriers, timestamps and submission;
//! - `draw`: draws through the graphics pipeline into an RGBA32F target copied into a buffer.
//!
//! Two ways to run. Standalone ([`VulkanBackend::new`], the CLI and tests): the backend makes its own
//! instance and device, records into its own command buffer, and every submission is waited for, so
//! between calls the GPU is idle and buffers can be read, written or freed without further
//! synchronisation. Inside a renderer ([`VulkanBackend::from_raw`]): the backend runs on the caller's
//! device and queue, works on the caller's buffers ([`VulkanBackend::import_buffer`]) and images
//! ([`super::ImageRef`]), and records into the caller's command buffer between
//! [`VulkanBackend::begin_external`] and [`VulkanBackend::end_external`]; the caller submits and
//! synchronises that work itself.

mod draw;
mod external;
mod images;
mod instance;
mod memory;
mod pipelines;
mod recorder;
mod spirv;

use super::access::{Access, Resource, copy_accesses, dispatch_accesses, draw_accesses};
use super::{
    Backend, BackendCounters, BackendId, BackendKind, BufferId, CommandTime, ImageFormat, ImageRef, Limits, RetireQueue, Subgroups,
    check_dispatch, check_draw, check_images, draw_fallback,
};
use crate::error::{Error, Result, VkContext};
use ash::vk;
use ash::vk::Handle;
use dof_shaders::{DrawDesc, KernelDesc};
use gpu_allocator::MemoryLocation;
use gpu_allocator::vulkan::{Allocator, AllocatorCreateDesc};
use instance::{DeviceCtx, Features, InstanceCtx};
use memory::{GpuBuffer, STAGING_CHUNK_BYTES, STORAGE_USAGE, Staging, StorageBuffer};
use pipelines::Pipelines;
use recorder::Recorder;
use std::collections::{HashMap, HashSet};
use std::ffi::CStr;
use std::sync::{Arc, Mutex, MutexGuard};

pub use external::External;
pub use instance::DEVICE_ENV;
pub use memory::SharedAllocator;
/// The `ash` and `gpu-allocator` the backend is built with, for callers handing it their handles.
pub use {ash, gpu_allocator};

#[derive(Clone, Debug, Default)]
pub struct VulkanOptions {
    /// Enable the Khronos validation layer (with synchronization validation) and record its messages.
    pub validation: bool,
    /// The device: a decimal index or a case-insensitive substring of its name. `None` consults
    /// `DOF_VULKAN_DEVICE`, then picks the best device (discrete > integrated > virtual > CPU).
    pub device: Option<String>,
    /// Have the driver keep each pipeline's statistics (VK_KHR_pipeline_executable_properties):
    /// registers, spills and the like, for [`VulkanBackend::pipeline_statistics`]. Refused where
    /// the device does not report them (lavapipe does not).
    pub pipeline_statistics: bool,
    /// How draws (the device peel's rasterisation) run. `Auto` consults `DOF_VULKAN_DRAWS`
    /// (`graphics` or `compute`), then takes the graphics pipeline where the queue has it.
    pub draws: DrawPath,
    /// Whether kernels run their subgroup variants (see [`Subgroups`]).
    pub subgroups: Subgroups,
}

/// How a backend runs draws ([`Backend::draw_indirect`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DrawPath {
    /// `DOF_VULKAN_DRAWS` if set, else the graphics pipeline where the queue has graphics.
    #[default]
    Auto,
    /// Through the graphics pipeline (refused on a compute-only queue).
    Graphics,
    /// Through each draw's compute fallback, the rasteriser the CPU backend runs (the same
    /// slots, bit for bit). Each of its workgroups walks every triangle for its tile, so it suits
    /// small meshes (docs/measurements.md has its cost against the graphics pipeline).
    Compute,
}

/// Environment variable choosing the draw path when `VulkanOptions::draws` is `Auto`.
pub const DRAWS_ENV: &str = "DOF_VULKAN_DRAWS";

impl DrawPath {
    /// The path `Auto` stands for: `DOF_VULKAN_DRAWS`, else graphics.
    fn resolve(self) -> Result<DrawPath> {
        if self != DrawPath::Auto {
            return Ok(self);
        }
        match std::env::var(DRAWS_ENV).ok().as_deref().map(str::trim) {
            None | Some("") => Ok(DrawPath::Graphics),
            Some(v) if v.eq_ignore_ascii_case("graphics") => Ok(DrawPath::Graphics),
            Some(v) if v.eq_ignore_ascii_case("compute") => Ok(DrawPath::Compute),
            Some(v) => Err(Error::InvalidArgument(format!("{DRAWS_ENV}={v}: give `graphics` or `compute` (or unset it)"))),
        }
    }
}

/// One statistic a driver reports of a pipeline's executable ([`VulkanBackend::pipeline_statistics`]).
#[derive(Clone, Debug)]
pub struct PipelineStatistic {
    /// The executable (a compute pipeline has one; its name is the driver's).
    pub executable: String,
    /// The statistic's name and description, as the driver gives them (for example NVIDIA's
    /// register count and local-memory bytes).
    pub name: String,
    pub description: String,
    /// Its value (booleans as 0 or 1).
    pub value: f64,
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

/// The Vulkan objects of a caller's device, for [`VulkanBackend::from_raw`]. The backend clones the
/// loader tables; it never destroys the instance or the device.
#[derive(Clone)]
pub struct RawDevice {
    pub entry: ash::Entry,
    pub instance: ash::Instance,
    pub physical_device: vk::PhysicalDevice,
    pub device: ash::Device,
    /// The family of `queue`; it must support compute (and graphics for draws through the graphics
    /// pipeline: without graphics the backend draws with the draws' compute fallbacks).
    pub queue_family: u32,
    /// The queue the backend's own submissions go to (`submit`, `read_buffer`, `write_buffer`).
    pub queue: vk::Queue,
}

/// Options of [`VulkanBackend::from_raw`].
#[derive(Clone, Default)]
pub struct RawOptions {
    /// Name the backend's objects (`dof commands`, each buffer's label) through VK_EXT_debug_utils;
    /// only where the caller's instance enabled that extension.
    pub debug_names: bool,
    /// The caller's gpu-allocator to allocate the backend's buffers from (made for the same device);
    /// `None` makes the backend its own, dropped with the backend.
    pub allocator: Option<SharedAllocator>,
    /// Whether kernels run their subgroup variants (see [`Subgroups`]).
    pub subgroups: Subgroups,
}

/// The device features the kernels need, as the structs to chain into `VkDeviceCreateInfo`
/// (`enabled_features(&core)` and `push_next(&mut vulkan12)`): the same ones the standalone backend
/// enables on its own device.
#[derive(Clone, Copy, Debug)]
pub struct RequiredFeatures {
    pub core: vk::PhysicalDeviceFeatures,
    pub vulkan12: vk::PhysicalDeviceVulkan12Features<'static>,
}

pub struct VulkanBackend {
    id: BackendId,
    /// See [`Backend::set_memory_budget`].
    budget: Option<u64>,
    // Fields drop in declaration order after `Drop::drop` has destroyed what they made: the device
    // before the instance (and the message log, inside the instance, last). A caller's device and
    // instance are not destroyed.
    device: DeviceCtx,
    instance: InstanceCtx,
    /// `None` only during drop, where it must go before the device.
    allocator: Option<SharedAllocator>,
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
    /// Everything but `submissions`, which the recorder counts.
    counters: BackendCounters,
    /// Buffers the open external recording uses.
    external_used: HashSet<u32>,
    /// Buffers destroyed during the open external recording that it uses, with their bytes: they
    /// wait for the recording at `end_external`.
    retiring: Vec<(GpuBuffer, u64)>,
    /// Ended external recordings not known to have completed: the number of each and the event
    /// it sets at its end.
    pending: Vec<(u64, vk::Event)>,
    /// The number the next ended external recording gets.
    recordings: u64,
    /// Buffers waiting for recordings (by number) to complete, with their bytes: freed by
    /// `release_finished` once none of those recordings is pending.
    waiting: Vec<(Vec<u64>, GpuBuffer, u64)>,
    /// Events of completed recordings, reset, to be used again.
    spare_events: Vec<vk::Event>,
    /// Buffers given back by contexts dropped without `destroy`.
    retire: RetireQueue,
    /// Draws go through the graphics pipeline (else through their compute fallbacks).
    graphics_draws: bool,
    /// Images of `create_image`, by raw handle.
    images: HashMap<u64, images::OwnImage>,
}

fn lock(allocator: &SharedAllocator) -> MutexGuard<'_, Allocator> {
    allocator.lock().unwrap_or_else(|e| e.into_inner())
}

impl VulkanBackend {
    /// The standalone backend: its own instance (with the validation layer if asked), device, queue
    /// and allocator.
    pub fn new(opts: &VulkanOptions) -> Result<Self> {
        let choice = opts.device.clone().or_else(|| std::env::var(DEVICE_ENV).ok().filter(|s| !s.trim().is_empty()));
        let draws = opts.draws.resolve()?;
        let instance = InstanceCtx::new(opts.validation)?;
        // Device features follow from the capabilities the kernel modules declare.
        let needed = spirv::all_capabilities();
        let candidate = instance::select(instance::candidates(&instance.instance, &needed)?, choice.as_deref())?;
        let device = DeviceCtx::new(&instance, &candidate, opts.pipeline_statistics)?;
        let allocator = Allocator::new(&AllocatorCreateDesc {
            instance: instance.instance.clone(),
            device: device.device.clone(),
            physical_device: candidate.physical,
            debug_settings: Default::default(),
            buffer_device_address: false,
            allocation_sizes: Default::default(),
        })
        .map_err(|e| Error::Allocation(e.to_string()))?;
        let graphics = device.graphics;
        if opts.draws == DrawPath::Graphics && !graphics {
            return Err(Error::InvalidArgument("draws through the graphics pipeline: the queue has no graphics".into()));
        }
        let mut backend = Self::assemble(
            device,
            instance,
            Arc::new(Mutex::new(allocator)),
            candidate.info,
            candidate.physical,
            candidate.timestamp_bits,
            opts.subgroups,
        )?;
        backend.graphics_draws = graphics && draws != DrawPath::Compute;
        Ok(backend)
    }

    /// Whether draws go through the graphics pipeline (else through their compute fallbacks,
    /// [`DrawPath`]).
    pub fn draws_through_graphics(&self) -> bool {
        self.graphics_draws
    }

    /// The backend on the caller's device: it creates only its own pipelines, buffers, command pool,
    /// fence, query pools and (unless `opts` hands it one) allocator, and destroys only those.
    ///
    /// What the backend does with the caller's objects: it submits to `queue` in `submit`,
    /// `read_buffer`, `write_buffer` and `begin_external` (only while it has unsubmitted work of its
    /// own, e.g. the zeroing of buffers created since the last submission), waiting on its own fence
    /// each time; it records into the caller's command buffers only between `begin_external` and
    /// `end_external`. Validation messages go to the caller's debug messenger, if any: this backend's
    /// `take_diagnostics` and `validation_messages` return nothing.
    ///
    /// # Safety
    ///
    /// - every handle in `handles` is valid: `instance` was made from `entry`, `physical_device` is
    ///   one of its physical devices, `device` was made from it, `queue` is a queue of `device` in
    ///   `queue_family`; all outlive the backend;
    /// - `device` was created with the API version [`Self::REQUIRED_API_VERSION`] or later, every
    ///   extension of [`Self::required_device_extensions`] and every feature of
    ///   [`Self::required_features`] enabled (the backend checks that the physical device supports
    ///   them, but cannot see what the device enabled);
    /// - the caller does not use `queue` from another thread during the calls above that submit;
    /// - an `opts.allocator` was made for this same instance, physical device and device;
    /// - before dropping the backend, the caller has waited for every command buffer it recorded
    ///   through the backend (the backend does not wait for the caller's device when dropped).
    pub unsafe fn from_raw(handles: RawDevice, opts: &RawOptions) -> Result<Self> {
        let RawDevice { entry, instance, physical_device, device, queue_family, queue } = handles;
        let instance = InstanceCtx::borrowed(entry, instance);
        // SAFETY: the instance is live (the caller's contract).
        let physical = unsafe { instance.instance.enumerate_physical_devices() }.vk("vkEnumeratePhysicalDevices")?;
        let index = physical
            .iter()
            .position(|&p| p == physical_device)
            .ok_or_else(|| Error::InvalidArgument("from_raw: the physical device is not one of the instance's".into()))?;
        let features = Features::needed_by(&spirv::all_capabilities());
        let candidate = instance::describe(&instance.instance, physical_device, index, features)?;
        if let Some(problem) = &candidate.problem {
            return Err(Error::InvalidArgument(format!("from_raw: the caller's device {} {problem}", candidate.info.name)));
        }
        let family = instance::queue_family(&instance.instance, physical_device, queue_family)
            .ok_or_else(|| Error::InvalidArgument(format!("from_raw: the device has no queue family {queue_family}")))?;
        if !family.queue_flags.contains(vk::QueueFlags::COMPUTE) {
            return Err(Error::InvalidArgument(format!(
                "from_raw: queue family {queue_family} has no compute ({:?}); the kernels need a compute queue",
                family.queue_flags
            )));
        }
        if queue == vk::Queue::null() {
            return Err(Error::InvalidArgument("from_raw: the queue is null".into()));
        }
        let device = DeviceCtx::borrowed(&instance, physical_device, device, queue_family, queue, opts.debug_names);
        let allocator = match &opts.allocator {
            Some(allocator) => allocator.clone(),
            None => Arc::new(Mutex::new(
                Allocator::new(&AllocatorCreateDesc {
                    instance: instance.instance.clone(),
                    device: device.device.clone(),
                    physical_device,
                    debug_settings: Default::default(),
                    buffer_device_address: false,
                    allocation_sizes: Default::default(),
                })
                .map_err(|e| Error::Allocation(e.to_string()))?,
            )),
        };
        Self::assemble(device, instance, allocator, candidate.info, physical_device, family.timestamp_valid_bits, opts.subgroups)
    }

    fn assemble(
        device: DeviceCtx,
        instance: InstanceCtx,
        allocator: SharedAllocator,
        mut info: DeviceInfo,
        physical: vk::PhysicalDevice,
        timestamp_bits: u32,
        subgroups: Subgroups,
    ) -> Result<Self> {
        let capture_statistics = device.executable_properties.is_some();
        info.limits.subgroup_kernels = subgroups.resolve(info.limits.subgroup_kernels)?;
        let pipelines = Pipelines::new(capture_statistics, info.limits.subgroup_kernels);
        // From here on `Drop` cleans up whatever a failing step leaves behind.
        let mut backend = VulkanBackend {
            device,
            instance,
            allocator: Some(allocator),
            info,
            pipelines,
            draws: draw::Draws::default(),
            physical,
            recorder: Recorder::empty(),
            buffers: HashMap::new(),
            next_id: 0,
            doomed: Vec::new(),
            upload: Staging::new(MemoryLocation::CpuToGpu),
            readback: Staging::new(MemoryLocation::GpuToCpu),
            counters: BackendCounters::default(),
            id: BackendId::fresh(),
            budget: None,
            external_used: HashSet::new(),
            retiring: Vec::new(),
            pending: Vec::new(),
            recordings: 0,
            waiting: Vec::new(),
            spare_events: Vec::new(),
            retire: RetireQueue::default(),
            graphics_draws: false,
            images: HashMap::new(),
        };
        backend.graphics_draws = backend.device.graphics;
        backend.recorder.init(&backend.device, timestamp_bits, backend.info.timestamp_period_ns)?;
        Ok(backend)
    }

    /// The Vulkan version the backend's device must support and be created for.
    pub const REQUIRED_API_VERSION: u32 = vk::API_VERSION_1_2;

    /// What the driver reports of `kernel`'s pipeline (created now if need be), executable by
    /// executable: for each, its statistics by the driver's names (registers, spills, ...). Needs a
    /// backend made with [`VulkanOptions::pipeline_statistics`].
    pub fn pipeline_statistics(&mut self, kernel: &'static KernelDesc) -> Result<Vec<PipelineStatistic>> {
        let Some(ext) = self.device.executable_properties.clone() else {
            return Err(Error::InvalidArgument("pipeline statistics need a backend made with `VulkanOptions::pipeline_statistics`".into()));
        };
        let pipeline = self.pipelines.get(&self.device.device, kernel)?.pipeline;
        let mut all = Vec::new();
        // SAFETY: the pipeline was created on this device with CAPTURE_STATISTICS_KHR (the
        // backend's pipelines are, once statistics are enabled), and stays alive during the calls.
        unsafe {
            let executables = ext
                .get_pipeline_executable_properties(&vk::PipelineInfoKHR::default().pipeline(pipeline))
                .vk("vkGetPipelineExecutablePropertiesKHR")?;
            for (index, executable) in executables.iter().enumerate() {
                let name = executable.name_as_c_str().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
                let info = vk::PipelineExecutableInfoKHR::default().pipeline(pipeline).executable_index(index as u32);
                for stat in ext.get_pipeline_executable_statistics(&info).vk("vkGetPipelineExecutableStatisticsKHR")? {
                    let value = match stat.format {
                        vk::PipelineExecutableStatisticFormatKHR::BOOL32 => (stat.value.b32 == vk::TRUE) as u64 as f64,
                        vk::PipelineExecutableStatisticFormatKHR::INT64 => stat.value.i64 as f64,
                        vk::PipelineExecutableStatisticFormatKHR::UINT64 => stat.value.u64 as f64,
                        vk::PipelineExecutableStatisticFormatKHR::FLOAT64 => stat.value.f64,
                        _ => f64::NAN,
                    };
                    all.push(PipelineStatistic {
                        executable: name.clone(),
                        name: stat.name_as_c_str().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default(),
                        description: stat.description_as_c_str().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default(),
                        value,
                    });
                }
            }
        }
        Ok(all)
    }

    /// The device extensions a caller's device must enable for [`Self::from_raw`].
    pub fn required_device_extensions() -> &'static [&'static CStr] {
        &instance::REQUIRED_EXTENSIONS
    }

    /// The device features a caller's device must enable for [`Self::from_raw`], from the
    /// capabilities the kernel modules declare (the standalone backend enables the same).
    pub fn required_features() -> RequiredFeatures {
        let (core, vulkan12) = Features::needed_by(&spirv::all_capabilities()).structs();
        RequiredFeatures { core, vulkan12 }
    }

    /// Adds SPIR-V modules of the caller's own kernels, `(entry point, module bytes)`: kernels
    /// declared with `dof_shaders::kernel!` in the caller's rust-gpu crate and compiled by its own
    /// build (spirv-builder, one module per entry point or one module holding them all; the entry is
    /// the `KernelDesc::entry` of the kernel). From then on [`Backend::dispatch`] runs those kernels
    /// like the project's, whose embedded modules stay the default and are never replaced.
    ///
    /// All or nothing, refused with [`Error::InvalidArgument`] naming the entry when an entry point
    /// is one of the project's or was added before (or is twice in `modules`), when a module is not
    /// SPIR-V or lacks its entry point, or when it declares a capability whose device feature the
    /// backend's device does not enable (those the project's kernels need: see
    /// [`Self::required_features`]). See `examples/own-kernel`.
    pub fn add_modules(&mut self, modules: &[(&str, &[u8])]) -> Result<()> {
        self.pipelines.add(modules, &spirv::all_capabilities())
    }

    /// The chosen device.
    pub fn info(&self) -> DeviceInfo {
        self.info.clone()
    }

    /// Every warning and error the validation layer reported so far (empty without validation, and
    /// on a caller's device, whose messages go to the caller's messenger).
    pub fn validation_messages(&self) -> Vec<String> {
        self.instance.messages.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }

    /// Like `validation_messages`, emptying the log.
    pub fn take_validation_messages(&mut self) -> Vec<String> {
        std::mem::take(&mut *self.instance.messages.lock().unwrap_or_else(|e| e.into_inner()))
    }

    fn allocator(&self) -> Result<SharedAllocator> {
        self.allocator.clone().ok_or_else(|| Error::Allocation("the allocator is gone".into()))
    }

    fn buffer(&self, id: BufferId) -> Result<&StorageBuffer> {
        self.buffers.get(&id.0).ok_or_else(|| Error::InvalidArgument(format!("unknown buffer {}", id.0)))
    }

    /// `accesses` by raw handle, as the recorder's barriers track them.
    fn raw_accesses(&self, accesses: &[Access]) -> Result<Vec<(u64, bool)>> {
        accesses
            .iter()
            .map(|a| match a.resource {
                Resource::Buffer(id) => Ok((self.buffer(id)?.handle.as_raw(), a.writes)),
                Resource::Image(handle) => Ok((handle, a.writes)),
            })
            .collect()
    }

    /// The buffer, after checking that `offset..offset + words` lies inside it.
    fn range(&self, id: BufferId, offset: u64, words: u64) -> Result<vk::Buffer> {
        let b = self.buffer(id)?;
        match offset.checked_add(words) {
            Some(end) if end <= b.words => Ok(b.handle),
            _ => Err(Error::InvalidArgument(format!("range {offset}..{offset}+{words} outside buffer {} of {} words", id.0, b.words))),
        }
    }

    /// Makes the draw target cover `size`: grown, never shrunk (a draw renders into its top-left
    /// corner), within the framebuffer limits. Growing replaces the target, which needs the GPU done
    /// with the old one: refused inside an external recording, so contexts reserve their largest
    /// frame when they are made ([`Backend::reserve_draw_target`]).
    fn ensure_draw_target(&mut self, draw: &'static DrawDesc, size: [u32; 2], label: &str) -> Result<()> {
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
                what: format!("draw target {}x{} (framebuffer side on this device)", size[0], size[1]),
                size: size[0].max(size[1]) as u64,
                limit: max[0].min(max[1]) as u64,
            });
        }
        let pipeline = self.draws.pipeline(&self.device.device, draw)?;
        let have = self.draws.target.as_ref().map(|t| t.size);
        if have.is_some_and(|t| t[0] >= size[0] && t[1] >= size[1]) {
            return Ok(());
        }
        let grown = have.map_or(size, |t| [t[0].max(size[0]), t[1].max(size[1])]);
        if self.recorder.is_external() && have.is_some() {
            // Earlier external recordings, which may still run, draw into the old target.
            return Err(Error::InvalidArgument(format!(
                "draw `{label}` at {}x{} inside an external recording: the draw target is smaller, and growing it needs the \
                 GPU idle; make the context for the largest frame before begin_external",
                size[0], size[1]
            )));
        }
        // Recorded work may still use the old target.
        self.flush()?;
        let allocator = self.allocator()?;
        let mut allocator = lock(&allocator);
        if let Some(old) = self.draws.target.take() {
            old.destroy(&self.device.device, &mut allocator);
        }
        self.draws.target = Some(draw::Target::new(&self.device.device, &mut allocator, pipeline.render_pass, grown)?);
        Ok(())
    }

    /// Notes that the open external recording (if any) uses `ids`.
    fn note_used(&mut self, ids: impl IntoIterator<Item = BufferId>) {
        if self.recorder.is_external() {
            self.external_used.extend(ids.into_iter().map(|b| b.0));
        }
    }

    /// Submits recorded work (keeping its timings for `submit`) and frees buffers it was holding.
    fn flush(&mut self) -> Result<()> {
        let result = self.recorder.flush(&self.device);
        // After a failed submission the device is most likely lost; freeing is still the best move.
        if !self.recorder.is_recording() && !self.doomed.is_empty() {
            let doomed = std::mem::take(&mut self.doomed);
            if let Some(allocator) = &self.allocator {
                let mut allocator = lock(allocator);
                for b in doomed {
                    b.destroy(&self.device.device, &mut allocator);
                }
            }
        }
        result
    }

    #[allow(clippy::too_many_arguments)]
    fn record_dispatch(
        &mut self,
        kernel: &'static KernelDesc,
        groups: Option<[u32; 3]>,
        indirect: Option<(BufferId, u64)>,
        buffers: &[BufferId],
        images: &[ImageRef],
        push: &[u32],
        label: &str,
    ) -> Result<()> {
        check_dispatch(&self.info.limits, kernel, groups, buffers.len(), images.len(), push.len())?;
        check_images(self, kernel, images)?;
        let bound: Vec<vk::Buffer> = buffers.iter().map(|&b| self.buffer(b).map(|b| b.handle)).collect::<Result<_>>()?;
        let args = match indirect {
            Some((id, offset)) => Some((self.range(id, offset, 3)?, offset * 4)),
            None => None,
        };
        let pipeline = self.pipelines.get(&self.device.device, kernel)?;
        self.note_used(buffers.iter().copied().chain(indirect.map(|(id, _)| id)));
        let accessed = self.raw_accesses(&dispatch_accesses(kernel, buffers, images, indirect.map(|(id, _)| id)))?;

        let buffer_infos = buffer_infos(&bound);
        // Each image with whether the kernel writes it (a storage image), in binding order.
        let image_bindings = (0..kernel.bindings).filter(|b| kernel.images & (1 << b) != 0);
        let bound_images: Vec<(ImageRef, bool)> =
            images.iter().zip(image_bindings).map(|(image, b)| (*image, kernel.storage_images & (1 << b) != 0)).collect();
        let image_infos: Vec<vk::DescriptorImageInfo> = bound_images
            .iter()
            .map(|&(image, written)| {
                vk::DescriptorImageInfo::default()
                    .image_view(vk::ImageView::from_raw(image.view))
                    .image_layout(bound_layout(image.format, written))
            })
            .collect();
        let writes = descriptor_writes(kernel.images, kernel.storage_images, &buffer_infos, &image_infos);
        let (acquire, release) = image_barriers(&bound_images);
        // Exactly the kernel's push constant bytes (rounded to whole words, as Vulkan requires).
        let push_bytes = kernel.push_bytes.div_ceil(4) as usize * 4;
        let push_data: &[u8] = &bytemuck::cast_slice::<u32, u8>(push)[..push_bytes];
        let push_descriptor = &self.device.push_descriptor;
        // Images wait for their last accesses: the caller's, and the backend's own copies.
        let wait_stages = images.iter().fold(vk::PipelineStageFlags::TRANSFER, |stages, image| stages | image.stage);
        self.counters.commands += 1;
        self.counters.dispatches += 1;
        self.counters.barriers += 2 * (!images.is_empty()) as u64;

        self.recorder.record(&self.device, Some((label, kernel.entry)), &accessed, |d, cb| {
            // SAFETY: `cb` is recording; the pipeline, its layout and every bound buffer are alive
            // until the submission finishes (destroyed buffers are kept until then); sampled images
            // and their views are the caller's, live and in their declared layouts
            // (`ImageDesc::build`'s contract).
            unsafe {
                if !acquire.is_empty() {
                    let compute = vk::PipelineStageFlags::COMPUTE_SHADER;
                    d.cmd_pipeline_barrier(cb, wait_stages, compute, vk::DependencyFlags::empty(), &[], &[], &acquire);
                }
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
                if !release.is_empty() {
                    let (compute, all) = (vk::PipelineStageFlags::COMPUTE_SHADER, vk::PipelineStageFlags::ALL_COMMANDS);
                    d.cmd_pipeline_barrier(cb, compute, all, vk::DependencyFlags::empty(), &[], &[], &release);
                }
            }
        })
    }

    /// Refuses `format` where the device's optimally tiled images of it lack `feature` (`what` the
    /// feature allows, for the error).
    fn check_format_feature(&self, format: ImageFormat, feature: vk::FormatFeatureFlags, what: &str) -> Result<()> {
        // SAFETY: a query on the live instance and the device's physical device.
        let features = unsafe { self.instance.instance.get_physical_device_format_properties(self.physical, format.vk_format()) }
            .optimal_tiling_features;
        if !features.contains(feature) {
            return Err(Error::InvalidArgument(format!(
                "dispatch_images: {format} images cannot be {what} on {} (optimal tiling features {features:?})",
                self.info.name
            )));
        }
        Ok(())
    }

    /// Records a copy between the whole of `image` and `buffer[offset_words ..]`, with the image's
    /// barriers into and out of the transfer layout.
    fn record_image_copy(&mut self, image: ImageRef, buffer: BufferId, offset_words: u64, into_image: bool, label: &str) -> Result<()> {
        let what = if into_image { "copy_buffer_to_image" } else { "copy_image_to_buffer" };
        self.check_image_copy(&image, into_image)?;
        let [width, height] = image.extent;
        let per_pixel = image.format.words_per_pixel();
        if !offset_words.is_multiple_of(per_pixel) {
            return Err(Error::InvalidArgument(format!(
                "{what} `{label}`: the buffer offset {offset_words} is not a multiple of the {per_pixel} words of a {} pixel",
                image.format
            )));
        }
        let target = self.range(buffer, offset_words, image.words())?;
        self.note_used([buffer]);
        let handle = vk::Image::from_raw(image.handle);
        let (transfer_layout, transfer_access) = if into_image {
            (vk::ImageLayout::TRANSFER_DST_OPTIMAL, vk::AccessFlags::TRANSFER_WRITE)
        } else {
            (vk::ImageLayout::TRANSFER_SRC_OPTIMAL, vk::AccessFlags::TRANSFER_READ)
        };
        let range = vk::ImageSubresourceRange::default().aspect_mask(image.format.layout_aspects()).level_count(1).layer_count(1);
        // From the caller's last use, and from the backend's own earlier copies (transfer writes).
        let acquire = [vk::ImageMemoryBarrier::default()
            .src_access_mask(image.access | vk::AccessFlags::TRANSFER_WRITE)
            .dst_access_mask(transfer_access)
            .old_layout(image.layout)
            .new_layout(transfer_layout)
            .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .image(handle)
            .subresource_range(range)];
        let src_stage = image.stage | vk::PipelineStageFlags::TRANSFER;
        let written = if into_image { vk::AccessFlags::TRANSFER_WRITE } else { vk::AccessFlags::empty() };
        let release = [vk::ImageMemoryBarrier::default()
            .src_access_mask(written)
            .dst_access_mask(vk::AccessFlags::MEMORY_READ | vk::AccessFlags::MEMORY_WRITE)
            .old_layout(transfer_layout)
            .new_layout(image.final_layout)
            .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .image(handle)
            .subresource_range(range)];
        // A depth format goes through its depth aspect (D24 as 32-bit words, depth in the low 24 bits).
        let region = [vk::BufferImageCopy::default()
            .buffer_offset(offset_words * 4)
            .image_subresource(vk::ImageSubresourceLayers::default().aspect_mask(image.format.copy_aspect()).layer_count(1))
            .image_extent(vk::Extent3D { width, height, depth: 1 })];
        let accessed = self.raw_accesses(&copy_accesses(image.handle, buffer, into_image))?;
        self.counters.commands += 1;
        // The acquire and release transitions around the copy.
        self.counters.barriers += 2;
        self.recorder.record(&self.device, Some((label, what)), &accessed, |d, cb| {
            // SAFETY: `cb` is recording outside a render pass; the image is live with the declared
            // format, extent and layout (`ImageRef::vulkan`'s contract) and the region lies inside
            // the buffer.
            unsafe {
                d.cmd_pipeline_barrier(cb, src_stage, vk::PipelineStageFlags::TRANSFER, vk::DependencyFlags::empty(), &[], &[], &acquire);
                if into_image {
                    d.cmd_copy_buffer_to_image(cb, target, handle, transfer_layout, &region);
                } else {
                    d.cmd_copy_image_to_buffer(cb, handle, transfer_layout, target, &region);
                }
                d.cmd_pipeline_barrier(
                    cb,
                    vk::PipelineStageFlags::TRANSFER,
                    vk::PipelineStageFlags::ALL_COMMANDS,
                    vk::DependencyFlags::empty(),
                    &[],
                    &[],
                    &release,
                );
            }
        })
    }
}

/// Descriptor infos binding each buffer whole.
fn buffer_infos(bound: &[vk::Buffer]) -> Vec<vk::DescriptorBufferInfo> {
    bound.iter().map(|&buffer| vk::DescriptorBufferInfo::default().buffer(buffer).offset(0).range(vk::WHOLE_SIZE)).collect()
}

/// Push-descriptor writes of bindings `0..` in order: the images (the bindings of the mask
/// `images_at`, as `KernelDesc::images`; storage images those of `storage_at`, the others sampled)
/// from `images`, the storage buffers from `buffers`.
fn descriptor_writes<'a>(
    images_at: u32,
    storage_at: u32,
    buffers: &'a [vk::DescriptorBufferInfo],
    images: &'a [vk::DescriptorImageInfo],
) -> Vec<vk::WriteDescriptorSet<'a>> {
    let bindings = (buffers.len() + images.len()) as u32;
    let (mut buffers, mut images) = (buffers.iter(), images.iter());
    (0..bindings)
        .filter_map(|binding| {
            let write = vk::WriteDescriptorSet::default().dst_binding(binding);
            if images_at & (1 << binding) != 0 {
                let info = images.next()?;
                let kind =
                    if storage_at & (1 << binding) != 0 { vk::DescriptorType::STORAGE_IMAGE } else { vk::DescriptorType::SAMPLED_IMAGE };
                Some(write.descriptor_type(kind).image_info(std::slice::from_ref(info)))
            } else {
                let info = buffers.next()?;
                Some(write.descriptor_type(vk::DescriptorType::STORAGE_BUFFER).buffer_info(std::slice::from_ref(info)))
            }
        })
        .collect()
}

/// The layout a kernel binds an image of `format` in: GENERAL where it writes it, else a read-only
/// layout.
fn bound_layout(format: ImageFormat, written: bool) -> vk::ImageLayout {
    if written {
        vk::ImageLayout::GENERAL
    } else if format.is_depth() {
        vk::ImageLayout::DEPTH_STENCIL_READ_ONLY_OPTIMAL
    } else {
        vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL
    }
}

/// The barriers around a dispatch binding `images` (each with whether it writes it): from each
/// image's last access (the caller's, or the backend's own copies) into its bound layout, and from
/// there into its final layout, the kernel's writes visible to every later access.
fn image_barriers(images: &[(ImageRef, bool)]) -> (Vec<vk::ImageMemoryBarrier<'static>>, Vec<vk::ImageMemoryBarrier<'static>>) {
    let barrier = |image: &ImageRef, old, new| {
        vk::ImageMemoryBarrier::default()
            .old_layout(old)
            .new_layout(new)
            .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .image(vk::Image::from_raw(image.handle))
            .subresource_range(
                vk::ImageSubresourceRange::default().aspect_mask(image.format.layout_aspects()).level_count(1).layer_count(1),
            )
    };
    let acquire = images.iter().map(|(image, written)| {
        let access = if *written { vk::AccessFlags::SHADER_READ | vk::AccessFlags::SHADER_WRITE } else { vk::AccessFlags::SHADER_READ };
        barrier(image, image.layout, bound_layout(image.format, *written))
            .src_access_mask(image.access | vk::AccessFlags::TRANSFER_WRITE)
            .dst_access_mask(access)
    });
    let release = images.iter().map(|(image, written)| {
        let wrote = if *written { vk::AccessFlags::SHADER_WRITE } else { vk::AccessFlags::empty() };
        barrier(image, bound_layout(image.format, *written), image.final_layout)
            .src_access_mask(wrote)
            .dst_access_mask(vk::AccessFlags::MEMORY_READ | vk::AccessFlags::MEMORY_WRITE)
    });
    (acquire.collect(), release.collect())
}

impl Backend for VulkanBackend {
    fn check_image_copy(&self, image: &ImageRef, into_image: bool) -> Result<()> {
        let what = if into_image { "copy_buffer_to_image" } else { "copy_image_to_buffer" };
        image.check_copy(into_image, what)?;
        // Images are assumed optimally tiled (what renderers' attachments are).
        // SAFETY: a query on the live instance and the device's physical device.
        let features = unsafe { self.instance.instance.get_physical_device_format_properties(self.physical, image.format.vk_format()) }
            .optimal_tiling_features;
        let needed = if into_image { vk::FormatFeatureFlags::TRANSFER_DST } else { vk::FormatFeatureFlags::TRANSFER_SRC };
        if !features.contains(needed) {
            return Err(Error::InvalidArgument(format!(
                "{what}: {} images cannot be a transfer {} on {} (optimal tiling features {features:?})",
                image.format,
                if into_image { "destination" } else { "source" },
                self.info.name
            )));
        }
        Ok(())
    }
    fn check_draw_target(&self, _draw: &'static DrawDesc, size: [u32; 2]) -> Result<()> {
        let covered = self.draws.target.as_ref().is_some_and(|t| t.size[0] >= size[0] && t.size[1] >= size[1]);
        if self.graphics_draws && self.recorder.is_external() && !covered {
            return Err(Error::InvalidArgument(format!(
                "a draw at {}x{} inside an external recording: the draw target is smaller, and growing it needs the GPU idle; \
                 make the context for the largest frame before begin_external",
                size[0], size[1]
            )));
        }
        Ok(())
    }
    fn reserve_draw_target(&mut self, draw: &'static DrawDesc, size: [u32; 2]) -> Result<()> {
        if !self.graphics_draws {
            return Ok(());
        }
        self.ensure_draw_target(draw, size, "reserve")
    }
    fn check_frame_recording(&self) -> Result<()> {
        if self.device.is_borrowed() && !self.recorder.is_external() {
            return Err(Error::RecordingState(
                "a frame on a backend wrapping the caller's device must be recorded into the caller's command buffer: \
                 call record_into (or begin_external) first"
                    .into(),
            ));
        }
        Ok(())
    }
    fn id(&self) -> BackendId {
        self.id
    }
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

    fn set_memory_budget(&mut self, budget: Option<u64>) {
        self.budget = budget;
    }

    fn reset_peak_device_bytes(&mut self) {
        self.counters.reset_peak();
    }

    fn retire_queue(&self) -> RetireQueue {
        self.retire.clone()
    }

    fn release_finished(&mut self) -> Result<u64> {
        VulkanBackend::release_finished(self)
    }

    fn create_buffer(&mut self, words: u64, label: &str) -> Result<BufferId> {
        self.refuse_external("create_buffer")?;
        self.release_finished()?;
        let limit = self.info.limits.max_buffer_bytes;
        let bytes = words.max(1).checked_mul(4).filter(|&b| b <= limit).ok_or_else(|| Error::TooLarge {
            what: format!("buffer `{label}` on this device"),
            size: words.saturating_mul(4),
            limit,
        })?;
        self.counters.check_budget(self.budget, bytes, label)?;
        let id = self.next_id;
        let next = id.checked_add(1).ok_or_else(|| Error::InvalidArgument("too many buffers created".into()))?;
        let allocator = self.allocator()?;
        let gpu = GpuBuffer::new(&self.device.device, &mut lock(&allocator), bytes, STORAGE_USAGE, MemoryLocation::GpuOnly, label)?;
        self.device.name(gpu.buffer, label);
        let handle = gpu.buffer;
        self.buffers.insert(id, StorageBuffer { handle, words: bytes / 4, owned: Some(gpu), label: label.to_string() });
        self.next_id = next;
        self.counters.add_buffer(bytes);
        // Zeroed on the GPU, ahead of (and ordered by the barrier before) whatever uses it next.
        let zeroed = self.recorder.record(&self.device, None, &[(handle.as_raw(), true)], |d, cb| {
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
        if self.recorder.is_external() && self.external_used.contains(&buffer.0) {
            // The caller's command buffer uses it: freed once that completed (`release_finished`).
            if let Some(StorageBuffer { owned: Some(gpu), words, label, .. }) = self.buffers.remove(&buffer.0) {
                log::debug!("destroy_buffer `{label}` inside an external recording that uses it: freed once it completed");
                self.retiring.push((gpu, words * 4));
            }
            return;
        }
        let Some(b) = self.buffers.remove(&buffer.0) else { return };
        // An imported buffer is only forgotten.
        let Some(gpu) = b.owned else { return };
        self.counters.remove_buffer(b.words * 4);
        if self.recorder.is_recording() {
            self.doomed.push(gpu);
        } else if let Some(allocator) = &self.allocator {
            gpu.destroy(&self.device.device, &mut lock(allocator));
        }
    }

    fn buffer_words(&self, buffer: BufferId) -> Result<u64> {
        Ok(self.buffer(buffer)?.words)
    }

    fn write_buffer(&mut self, buffer: BufferId, offset_words: u64, data: &[u32]) -> Result<()> {
        self.refuse_external("write_buffer")?;
        let target = self.range(buffer, offset_words, data.len() as u64)?;
        self.counters.uploads += 1;
        self.flush()?;
        let allocator = self.allocator()?;
        let graphics = self.recorder.graphics();
        let bytes: &[u8] = bytemuck::cast_slice(data);
        for (i, chunk) in bytes.chunks(STAGING_CHUNK_BYTES as usize).enumerate() {
            let staging = self.upload.get(&self.device.device, &mut lock(&allocator), chunk.len() as u64)?;
            staging.mapped()?[..chunk.len()].copy_from_slice(chunk);
            // Host writes before vkQueueSubmit are visible to the device (the memory is host-coherent).
            let src = staging.buffer;
            let region =
                [vk::BufferCopy::default().dst_offset(offset_words * 4 + (i as u64) * STAGING_CHUNK_BYTES).size(chunk.len() as u64)];
            self.recorder.run_once(&self.device, |d, cb| {
                // Earlier submissions' accesses to the target come first.
                recorder::full_barrier(d, cb, graphics);
                // SAFETY: `cb` is recording; both buffers are alive and the region lies inside them.
                unsafe { d.cmd_copy_buffer(cb, src, target, &region) };
            })?;
        }
        Ok(())
    }

    fn read_buffer(&mut self, buffer: BufferId, offset_words: u64, words: u64) -> Result<Vec<u32>> {
        self.refuse_external("read_buffer")?;
        let source = self.range(buffer, offset_words, words)?;
        self.counters.readbacks += 1;
        self.flush()?;
        let len = usize::try_from(words).map_err(|_| Error::InvalidArgument(format!("cannot read {words} words")))?;
        let mut out = vec![0u32; len];
        let allocator = self.allocator()?;
        let graphics = self.recorder.graphics();
        let out_bytes: &mut [u8] = bytemuck::cast_slice_mut(&mut out);
        for (i, chunk) in out_bytes.chunks_mut(STAGING_CHUNK_BYTES as usize).enumerate() {
            let dst = self.readback.get(&self.device.device, &mut lock(&allocator), chunk.len() as u64)?.buffer;
            let region =
                [vk::BufferCopy::default().src_offset(offset_words * 4 + (i as u64) * STAGING_CHUNK_BYTES).size(chunk.len() as u64)];
            self.recorder.run_once(&self.device, |d, cb| {
                recorder::full_barrier(d, cb, graphics);
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
        self.note_used([buffer]);
        self.counters.commands += 1;
        self.recorder.record(&self.device, Some((label, "fill")), &[(target.as_raw(), true)], |d, cb| {
            if words > 0 {
                // SAFETY: `cb` is recording; the range lies inside the buffer.
                unsafe { d.cmd_fill_buffer(cb, target, offset_words * 4, words * 4, value) }
            }
        })
    }

    fn dispatch(&mut self, kernel: &'static KernelDesc, groups: [u32; 3], buffers: &[BufferId], push: &[u32], label: &str) -> Result<()> {
        self.record_dispatch(kernel, Some(groups), None, buffers, &[], push, label)
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
        self.record_dispatch(kernel, Some(groups), None, buffers, images, push, label)
    }

    fn check_image_sample(&self, image: &ImageRef) -> Result<()> {
        image.check_sample("dispatch_images")?;
        self.check_format_feature(image.format, vk::FormatFeatureFlags::SAMPLED_IMAGE, "sampled")
    }

    fn check_image_store(&self, image: &ImageRef) -> Result<()> {
        image.check_store("dispatch_images")?;
        self.check_format_feature(image.format, vk::FormatFeatureFlags::STORAGE_IMAGE, "written as storage images")
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
        self.record_dispatch(kernel, None, Some((args, args_offset_words)), buffers, &[], push, label)
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
        if !self.graphics_draws {
            // A compute-only queue (a caller's), or compute draws asked for: the draw's compute
            // fallback, as on the CPU.
            return draw_fallback(self, draw, args, buffers, target, size, push, label);
        }
        check_draw(self, draw, args, buffers, target, size, push)?;
        self.ensure_draw_target(draw, size, label)?;
        let pipeline = self.draws.pipeline(&self.device.device, draw)?;
        let (image, framebuffer) = match &self.draws.target {
            Some(t) => (t.image, t.framebuffer),
            None => return Err(Error::InvalidArgument("no draw target".into())),
        };
        let pixels = size[0] as u64 * size[1] as u64;
        let args_buffer = self.range(args, 0, 4)?;
        let target_buffer = self.range(target, 0, 4 * pixels)?;
        let bound: Vec<vk::Buffer> = buffers.iter().map(|&b| self.buffer(b).map(|b| b.handle)).collect::<Result<_>>()?;
        self.note_used(buffers.iter().copied().chain([args, target]));
        // And the draw writes its image, copied into the target.
        let mut accessed = self.raw_accesses(&draw_accesses(buffers, args, target))?;
        accessed.push((image.as_raw(), true));
        let infos = buffer_infos(&bound);
        let writes = descriptor_writes(0, 0, &infos, &[]);
        let push_bytes = draw.push_bytes.div_ceil(4) as usize * 4;
        let push_data: Vec<u8> = bytemuck::cast_slice::<u32, u8>(push)[..push_bytes].to_vec();
        let push_descriptor = &self.device.push_descriptor;
        let extent = vk::Extent2D { width: size[0], height: size[1] };
        let stages = vk::ShaderStageFlags::VERTEX | vk::ShaderStageFlags::FRAGMENT;
        self.counters.commands += 1;
        self.counters.dispatches += 1;
        self.recorder.record(&self.device, Some((label, draw.vertex)), &accessed, |d, cb| {
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

    fn copy_image_to_buffer(&mut self, image: ImageRef, buffer: BufferId, offset_words: u64, label: &str) -> Result<()> {
        self.record_image_copy(image, buffer, offset_words, false, label)
    }

    fn copy_buffer_to_image(&mut self, buffer: BufferId, offset_words: u64, image: ImageRef, label: &str) -> Result<()> {
        self.record_image_copy(image, buffer, offset_words, true, label)
    }

    fn create_image(&mut self, format: ImageFormat, extent: [u32; 2]) -> Result<ImageRef> {
        self.make_image(format, extent)
    }

    fn write_image(&mut self, image: &ImageRef, texels: &[u32]) -> Result<()> {
        self.fill_image(image, texels)
    }

    fn destroy_image(&mut self, image: &ImageRef) {
        self.free_image(image)
    }

    fn submit(&mut self) -> Result<Vec<CommandTime>> {
        self.refuse_external("submit")?;
        self.flush()?;
        self.release_finished()?;
        Ok(self.recorder.take_times())
    }

    fn begin_span(&mut self, label: &str) -> Result<()> {
        self.recorder.begin_span(&self.device, label)
    }

    fn set_command_timestamps(&mut self, on: bool) {
        self.recorder.set_command_timestamps(on);
    }
    fn end_span(&mut self) -> Result<()> {
        self.recorder.end_span(&self.device)
    }

    fn take_span_times(&mut self) -> Vec<CommandTime> {
        self.recorder.take_span_times()
    }

    fn counters(&self) -> BackendCounters {
        let barriers = self.counters.barriers + self.recorder.barriers();
        BackendCounters { submissions: self.recorder.submissions(), barriers, ..self.counters }
    }

    fn prepare(&mut self, kernels: &[&'static KernelDesc], draws: &[&'static DrawDesc]) -> Result<()> {
        for &kernel in kernels {
            self.pipelines.get(&self.device.device, kernel)?;
        }
        for &draw in draws {
            self.draws.pipeline(&self.device.device, draw)?;
        }
        Ok(())
    }

    fn take_diagnostics(&mut self) -> Vec<String> {
        self.take_validation_messages()
    }
}

impl Drop for VulkanBackend {
    fn drop(&mut self) {
        let d = self.device.device.clone();
        if self.device.owned() {
            // SAFETY: waiting makes every object below unused. On a caller's device the caller has
            // waited for what it recorded through the backend (`from_raw`'s contract), and every
            // submission of the backend's own was waited for.
            unsafe {
                let _ = d.device_wait_idle();
            }
        }
        // SAFETY (of the destruction below): nothing is pending and nothing is destroyed twice.
        self.pipelines.destroy(&d);
        self.recorder.destroy(&d);
        for event in self.spare_events.drain(..).chain(self.pending.iter().map(|&(_, e)| e)) {
            // SAFETY: nothing pending uses it.
            unsafe { d.destroy_event(event, None) };
        }
        if let Some(shared) = self.allocator.take() {
            let mut allocator = lock(&shared);
            self.draws.destroy(&d, &mut allocator);
            for (_, image) in self.images.drain() {
                image.destroy(&d, &mut allocator);
            }
            for (_, b) in self.buffers.drain() {
                // Imported buffers are the caller's.
                if let Some(gpu) = b.owned {
                    gpu.destroy(&d, &mut allocator);
                }
            }
            for b in self.doomed.drain(..) {
                b.destroy(&d, &mut allocator);
            }
            // The caller waited for its command buffers (`from_raw`'s contract).
            let waiting = self.waiting.drain(..).map(|(_, gpu, bytes)| (gpu, bytes));
            for (b, _) in self.retiring.drain(..).chain(waiting) {
                b.destroy(&d, &mut allocator);
            }
            self.upload.destroy(&d, &mut allocator);
            self.readback.destroy(&d, &mut allocator);
            drop(allocator);
            // The backend's own allocator frees its memory blocks here, while the device still
            // exists; a caller's lives on with the caller.
            drop(shared);
        }
        // `device`, then `instance`, are destroyed as the fields drop (when the backend made them).
    }
}

#[cfg(test)]
mod tests;
