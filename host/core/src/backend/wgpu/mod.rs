//! The wgpu backend: the kernels as WGSL (`host/wgsl/`, naga's translation of the SPIR-V the Vulkan
//! backend runs) on any device wgpu drives: Vulkan, Metal, DX12 and GL.
//!
//! What it does as the other backends do: every kernel, with its push constants as wgpu's
//! immediates; indirect dispatches; draws through their compute fallbacks. Each dispatch is a
//! compute pass of its own, and wgpu places the barriers between them. What it does differently:
//! - `fill` with zero is the encoder's clear; another value runs the `fill_words` kernel;
//! - a dispatch is timed by timestamps around its pass where wgpu has them (`timing.rs`); a clear,
//!   and anything recorded into a caller's encoder, is not (NaN);
//! - wgpu's barriers are its own, so `barriers` in the counters stays 0;
//! - images are the caller's textures ([`WgpuBackend::import_texture`], in `textures.rs`), sampled
//!   and written in place by kernels where their usage allows, otherwise copied row by row where a
//!   row is not a multiple of wgpu's 256-byte pitch; depth is read by a kernel, since wgpu copies
//!   none out of `Depth24Plus` and only whole textures out of the others.
//!
//! A renderer on its own device ([`WgpuBackend::from_device`]) records frames into its own command
//! encoder ([`WgpuBackend::record_into`], in `external.rs`): nothing is made, submitted or read back.
//!
//! wgpu reports a misuse it catches through its error handler, not the call: the backend gathers
//! those messages and fails the next `submit`, `read_buffer` or `write_buffer` with them.

use super::{
    Backend, BackendCounters, BackendId, BackendKind, BufferId, CommandTime, ImageRef, Limits, RetireQueue, Subgroups, check_dispatch,
    check_images,
};
use crate::error::{Error, Result};
use dof_shaders::KernelDesc;
use dof_shaders::fill::{FILL, FillParams, THREADS as FILL_THREADS};
use std::collections::HashMap;
use std::sync::{Arc, Mutex};

mod external;
mod textures;
mod timing;
pub use external::WgpuRecording;
use timing::{Command, Timestamps};

/// What device a [`WgpuBackend`] asks wgpu for.
#[derive(Clone, Debug)]
pub struct WgpuOptions {
    /// The APIs wgpu may use; by default those `WGPU_BACKEND` names, or the primary ones (Vulkan,
    /// Metal, DX12; GL only when named).
    pub backends: wgpu::Backends,
    pub power_preference: wgpu::PowerPreference,
    /// Whether kernels run their subgroup variants ([`Subgroups`]); `new` asks for
    /// [`wgpu::Features::SUBGROUP`] when they do.
    pub subgroups: Subgroups,
}

impl Default for WgpuOptions {
    fn default() -> Self {
        WgpuOptions {
            backends: wgpu::Backends::from_env().unwrap_or(wgpu::Backends::PRIMARY),
            power_preference: wgpu::PowerPreference::HighPerformance,
            subgroups: Subgroups::Auto,
        }
    }
}

struct WgpuBuffer {
    buffer: wgpu::Buffer,
    words: u64,
    /// The caller's ([`WgpuBackend::import_buffer`]): forgotten, not counted.
    imported: bool,
}

/// How many workgroups a dispatch runs.
enum Groups {
    Direct([u32; 3]),
    /// Read on the device from this buffer, at this byte offset.
    Indirect(wgpu::Buffer, u64),
}

#[derive(Clone)]
struct Pipeline {
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
}

pub struct WgpuBackend {
    id: BackendId,
    limits: Limits,
    info: wgpu::AdapterInfo,
    device: wgpu::Device,
    queue: wgpu::Queue,
    buffers: Vec<Option<WgpuBuffer>>,
    pipelines: HashMap<&'static str, Pipeline>,
    /// The caller's textures ([`WgpuBackend::import_texture`]), by image handle − 1.
    textures: Vec<Option<textures::WgpuTexture>>,
    /// The `texture_read` kernel's pipeline, made when a depth texture is imported.
    depth_read: Option<Pipeline>,
    /// Commands recorded since the last submission; during [`WgpuBackend::record_into`], the
    /// caller's encoder.
    encoder: Option<wgpu::CommandEncoder>,
    /// Recording into the caller's encoder.
    external: bool,
    /// The device is the caller's ([`WgpuBackend::from_device`]): frames go into its encoder.
    callers_device: bool,
    /// The commands of the backend's own encoder since the last `submit`, and their timestamps.
    commands: Vec<Command>,
    timestamps: Option<Timestamps>,
    /// Spans since the last `submit` (label, first command, end; end `usize::MAX` while open),
    /// in opening order; the open ones' indices there, innermost last; and the times of the spans
    /// of past submissions.
    spans: Vec<(String, usize, usize)>,
    open_spans: Vec<usize>,
    span_times: Vec<CommandTime>,
    /// What wgpu's error handler reported since the last check.
    errors: Arc<Mutex<Vec<String>>>,
    counters: BackendCounters,
    budget: Option<u64>,
    retire: RetireQueue,
}

/// Whether the kernels' subgroup variants can run on a device of these `features`: it has
/// [`wgpu::Features::SUBGROUP`], and it is not a browser's WebGPU, whose subgroups lack the
/// `subgroup_id` and `num_subgroups` built-ins the variants read (naga's, which native backends have).
fn subgroups_usable(features: wgpu::Features, info: &wgpu::AdapterInfo) -> bool {
    features.contains(wgpu::Features::SUBGROUP) && info.backend != wgpu::Backend::BrowserWebGpu
}

impl WgpuBackend {
    /// A device of the first adapter wgpu offers for `options`.
    pub fn new(options: &WgpuOptions) -> Result<Self> {
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
            backends: options.backends,
            ..wgpu::InstanceDescriptor::new_without_display_handle()
        });
        let adapter_options = wgpu::RequestAdapterOptions { power_preference: options.power_preference, ..Default::default() };
        let adapter = pollster::block_on(instance.request_adapter(&adapter_options))
            .map_err(|e| Error::NoDevice(format!("wgpu offers no adapter for {:?}: {e}", options.backends)))?;
        let info = adapter.get_info();
        if !adapter.features().contains(wgpu::Features::IMMEDIATES) {
            return Err(Error::NoDevice(format!(
                "{} ({:?}) has no immediates (push constants), which every kernel reads",
                info.name, info.backend
            )));
        }
        let subgroups = options.subgroups.resolve(subgroups_usable(adapter.features(), &info))?;
        let descriptor = wgpu::DeviceDescriptor {
            label: Some("dof"),
            required_features: wgpu::Features::IMMEDIATES
                | (adapter.features() & wgpu::Features::TIMESTAMP_QUERY)
                | if subgroups { wgpu::Features::SUBGROUP } else { wgpu::Features::empty() },
            required_limits: adapter.limits(),
            ..Default::default()
        };
        let (device, queue) = pollster::block_on(adapter.request_device(&descriptor))
            .map_err(|e| Error::NoDevice(format!("{} ({:?}) refuses a device: {e}", info.name, info.backend)))?;
        let mut backend = Self::from_device(device, queue, info);
        backend.callers_device = false;
        Ok(backend)
    }

    /// A backend on a device the caller made (with [`wgpu::Features::IMMEDIATES`]); `info` is its
    /// adapter's. Frames on it are recorded into the caller's encoder ([`WgpuBackend::record_into`]).
    /// The backend's own submissions are timed where the device has [`wgpu::Features::TIMESTAMP_QUERY`].
    /// Kernels run their subgroup variants where the device has [`wgpu::Features::SUBGROUP`]
    /// outside a browser ([`WgpuBackend::set_subgroups`] turns them off).
    pub fn from_device(device: wgpu::Device, queue: wgpu::Queue, info: wgpu::AdapterInfo) -> Self {
        let errors = Arc::new(Mutex::new(Vec::new()));
        let sink = errors.clone();
        device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
            if let Ok(mut errors) = sink.lock() {
                errors.push(e.to_string());
            }
        }));
        let l = device.limits();
        let limits = Limits {
            max_shared_bytes: l.max_compute_workgroup_storage_size,
            max_workgroup_invocations: l.max_compute_invocations_per_workgroup,
            max_workgroup_count: [l.max_compute_workgroups_per_dimension; 3],
            subgroup_size: (info.subgroup_min_size == info.subgroup_max_size).then_some(info.subgroup_min_size),
            subgroup_kernels: subgroups_usable(device.features(), &info),
            max_buffer_bytes: l.max_buffer_size.min(l.max_storage_buffer_binding_size),
            serial_invocations: false,
        };
        let timestamps = Timestamps::new(&device, &queue);
        WgpuBackend {
            id: BackendId::fresh(),
            limits,
            info,
            device,
            queue,
            buffers: Vec::new(),
            pipelines: HashMap::new(),
            textures: Vec::new(),
            depth_read: None,
            encoder: None,
            external: false,
            callers_device: true,
            commands: Vec::new(),
            timestamps,
            spans: Vec::new(),
            open_spans: Vec::new(),
            span_times: Vec::new(),
            errors,
            counters: BackendCounters::default(),
            budget: None,
            retire: RetireQueue::default(),
        }
    }

    pub fn device(&self) -> &wgpu::Device {
        &self.device
    }

    /// Whether kernels run their subgroup variants, on this device (`Required` is refused where
    /// [`subgroups_usable`] says no). Pipelines made before are made again.
    pub fn set_subgroups(&mut self, subgroups: Subgroups) -> Result<()> {
        let on = subgroups.resolve(subgroups_usable(self.device.features(), &self.info))?;
        if on != self.limits.subgroup_kernels {
            self.limits.subgroup_kernels = on;
            self.pipelines.clear();
        }
        Ok(())
    }

    pub fn queue(&self) -> &wgpu::Queue {
        &self.queue
    }

    fn insert(&mut self, buffer: WgpuBuffer) -> BufferId {
        let slot = self.buffers.iter().position(Option::is_none).unwrap_or(self.buffers.len());
        if slot == self.buffers.len() {
            self.buffers.push(None);
        }
        self.buffers[slot] = Some(buffer);
        BufferId(slot as u32)
    }

    fn buffer(&self, id: BufferId) -> Result<&WgpuBuffer> {
        self.buffers.get(id.0 as usize).and_then(Option::as_ref).ok_or_else(|| Error::InvalidArgument(format!("unknown buffer {}", id.0)))
    }

    fn check_range(&self, id: BufferId, offset: u64, words: u64) -> Result<()> {
        let buffer = self.buffer(id)?;
        match offset.checked_add(words) {
            Some(end) if end <= buffer.words => Ok(()),
            _ => Err(Error::InvalidArgument(format!("range {offset}..{offset}+{words} outside buffer {} of {} words", id.0, buffer.words))),
        }
    }

    /// Fails with what wgpu reported since the last check.
    fn check_errors(&self) -> Result<()> {
        let mut errors = self.errors.lock().map_err(|_| Error::Device("wgpu's error list is poisoned".into()))?;
        if errors.is_empty() {
            return Ok(());
        }
        let all = std::mem::take(&mut *errors);
        Err(Error::Device(format!("wgpu reported {} error(s):\n{}", all.len(), all.join("\n"))))
    }

    fn encoder(&mut self) -> &mut wgpu::CommandEncoder {
        let device = &self.device;
        self.encoder.get_or_insert_with(|| device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("dof") }))
    }

    /// An error for `what`, which submits or allocates, while recording into the caller's encoder.
    fn refuse_external(&self, what: &str) -> Result<()> {
        if self.external {
            return Err(Error::RecordingState(format!(
                "{what} is not allowed while recording into the caller's command encoder (record_into): it would submit or allocate"
            )));
        }
        Ok(())
    }

    /// Submits what is recorded and waits for it (and for its timestamps).
    fn flush(&mut self) -> Result<()> {
        self.refuse_external("a submission")?;
        if let Some(mut encoder) = self.encoder.take() {
            if let Some(timestamps) = &self.timestamps {
                timestamps.resolve(&mut encoder);
            }
            self.queue.submit([encoder.finish()]);
            self.counters.submissions += 1;
            wait(&self.device)?;
            if let Some(timestamps) = self.timestamps.as_mut() {
                let device = &self.device;
                timestamps.read(&mut self.commands, || wait(device))?;
            }
        }
        self.check_errors()
    }

    fn pipeline(&mut self, kernel: &'static KernelDesc) -> Result<&Pipeline> {
        if !self.pipelines.contains_key(kernel.entry) {
            let pipeline = self.create_pipeline(kernel)?;
            self.pipelines.insert(kernel.entry, pipeline);
        }
        self.pipelines.get(kernel.entry).ok_or_else(|| Error::Device(format!("no pipeline for {}", kernel.entry)))
    }

    fn create_pipeline(&self, kernel: &'static KernelDesc) -> Result<Pipeline> {
        let entries: Vec<wgpu::BindGroupLayoutEntry> = (0..kernel.bindings)
            .map(|binding| {
                if kernel.storage_images & (1 << binding) != 0 {
                    storage_texture_binding(binding, kernel.half_images & (1 << binding) != 0)
                } else if kernel.images & (1 << binding) != 0 {
                    texture_binding(binding, kernel.depth_images & (1 << binding) != 0)
                } else {
                    storage_binding(binding, kernel.read_only & (1 << binding) != 0)
                }
            })
            .collect();
        let entry = super::pipeline_entry(kernel, self.limits.subgroup_kernels);
        self.compute_pipeline(entry, &entries, kernel.push_bytes)
    }

    /// The compute pipeline of the WGSL module of `entry`, one bind group of `entries`, and
    /// `push_bytes` of immediates.
    fn compute_pipeline(&self, entry: &'static str, entries: &[wgpu::BindGroupLayoutEntry], push_bytes: u32) -> Result<Pipeline> {
        let source = crate::shaders::wgsl_module(entry)
            .ok_or_else(|| Error::InvalidArgument(format!("kernel {entry} has no WGSL module (host/wgsl/)")))?;
        let layout = self.device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor { label: Some(entry), entries });
        let pipeline_layout = self.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(entry),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: push_bytes.next_multiple_of(4),
        });
        let module = self
            .device
            .create_shader_module(wgpu::ShaderModuleDescriptor { label: Some(entry), source: wgpu::ShaderSource::Wgsl(source.into()) });
        let pipeline = self.device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(entry),
            layout: Some(&pipeline_layout),
            module: &module,
            entry_point: None,
            compilation_options: Default::default(),
            cache: None,
        });
        self.check_errors().map_err(|e| Error::Device(format!("the pipeline of {entry}: {e}")))?;
        Ok(Pipeline { pipeline, layout })
    }

    /// Records one dispatch of `kernel`, direct (`groups`) or indirect (`args` at a word offset),
    /// bound to `buffers` and the textures it samples or writes, `images` (each in binding order).
    fn record_dispatch(
        &mut self,
        kernel: &'static KernelDesc,
        groups: Groups,
        buffers: &[BufferId],
        images: &[ImageRef],
        push: &[u32],
        label: &str,
    ) -> Result<()> {
        let bound: Vec<wgpu::Buffer> = buffers.iter().map(|&b| self.buffer(b).map(|b| b.buffer.clone())).collect::<Result<_>>()?;
        let image_bindings = (0..kernel.bindings).filter(|b| kernel.images & (1 << b) != 0);
        let views: Vec<wgpu::TextureView> = images
            .iter()
            .zip(image_bindings)
            .map(
                |(image, binding)| {
                    if kernel.storage_images & (1 << binding) != 0 { self.storage_view(image) } else { self.sampled_view(image) }
                },
            )
            .collect::<Result<_>>()?;
        let (layout, pipeline) = {
            let p = self.pipeline(kernel)?;
            (p.layout.clone(), p.pipeline.clone())
        };
        let (mut bound_iter, mut views_iter) = (bound.iter(), views.iter());
        let entries: Vec<wgpu::BindGroupEntry> = (0..kernel.bindings)
            .filter_map(|binding| {
                let resource = if kernel.images & (1 << binding) != 0 {
                    wgpu::BindingResource::TextureView(views_iter.next()?)
                } else {
                    bound_iter.next()?.as_entire_binding()
                };
                Some(wgpu::BindGroupEntry { binding, resource })
            })
            .collect();
        let bind_group =
            self.device.create_bind_group(&wgpu::BindGroupDescriptor { label: Some(label), layout: &layout, entries: &entries });
        let immediates: Vec<u8> = bytemuck::cast_slice(push).iter().copied().take(kernel.push_bytes.next_multiple_of(4) as usize).collect();
        self.record_pass(kernel.entry, &pipeline, &bind_group, &immediates, groups, label);
        Ok(())
    }

    /// Records a compute pass of its own running `pipeline` (the kernel `entry`) on `bind_group`,
    /// timed where the backend's own encoder has timestamps, and counts it.
    fn record_pass(
        &mut self,
        entry: &'static str,
        pipeline: &wgpu::ComputePipeline,
        bind_group: &wgpu::BindGroup,
        immediates: &[u8],
        groups: Groups,
        label: &str,
    ) {
        let mut command = Command::new(label, entry);
        let device = &self.device;
        let encoder =
            self.encoder.get_or_insert_with(|| device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("dof") }));
        let timestamp_writes = if self.external { None } else { self.timestamps.as_mut().and_then(|t| t.pass_writes(&mut command)) };
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor { label: Some(label), timestamp_writes });
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, bind_group, &[]);
        if !immediates.is_empty() {
            pass.set_immediates(0, immediates);
        }
        match groups {
            Groups::Direct([x, y, z]) => pass.dispatch_workgroups(x, y, z),
            Groups::Indirect(args, offset) => pass.dispatch_workgroups_indirect(&args, offset),
        }
        drop(pass);
        self.counters.commands += 1;
        self.counters.dispatches += 1;
        self.commands.push(command);
    }
}

/// A compute stage's storage buffer at `binding`.
/// A sampled 2D texture's layout entry: a depth texture, or a colour one read without filtering.
fn texture_binding(binding: u32, depth: bool) -> wgpu::BindGroupLayoutEntry {
    let sample_type = if depth { wgpu::TextureSampleType::Depth } else { wgpu::TextureSampleType::Float { filterable: false } };
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Texture { sample_type, view_dimension: wgpu::TextureViewDimension::D2, multisampled: false },
        count: None,
    }
}

/// A storage texture a kernel only writes (`write_only_images` made its WGSL `write`).
fn storage_texture_binding(binding: u32, half: bool) -> wgpu::BindGroupLayoutEntry {
    let format = if half { wgpu::TextureFormat::Rgba16Float } else { wgpu::TextureFormat::Rgba32Float };
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::StorageTexture {
            access: wgpu::StorageTextureAccess::WriteOnly,
            format,
            view_dimension: wgpu::TextureViewDimension::D2,
        },
        count: None,
    }
}

fn storage_binding(binding: u32, read_only: bool) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

impl Backend for WgpuBackend {
    fn kind(&self) -> BackendKind {
        BackendKind::Wgpu
    }

    fn id(&self) -> BackendId {
        self.id
    }

    fn device_name(&self) -> String {
        format!("{} (wgpu, {:?})", self.info.name, self.info.backend)
    }

    fn driver(&self) -> String {
        format!("{} {}", self.info.driver, self.info.driver_info).trim().to_string()
    }

    fn limits(&self) -> &Limits {
        &self.limits
    }

    fn retire_queue(&self) -> RetireQueue {
        self.retire.clone()
    }

    fn release_finished(&mut self) -> Result<u64> {
        // wgpu keeps a dropped buffer alive until the device is done with it.
        let before = self.counters.device_bytes;
        self.retire.take().into_iter().for_each(|id| self.destroy_buffer(id));
        Ok(before - self.counters.device_bytes)
    }

    fn create_buffer(&mut self, words: u64, label: &str) -> Result<BufferId> {
        self.refuse_external(&format!("creating buffer `{label}`"))?;
        self.release_finished()?;
        let bytes = words.max(1) * 4;
        if bytes > self.limits.max_buffer_bytes {
            return Err(Error::TooLarge {
                what: format!("buffer `{label}` on {}", self.info.name),
                size: bytes,
                limit: self.limits.max_buffer_bytes,
            });
        }
        self.counters.check_budget(self.budget, bytes, label)?;
        // wgpu zeroes new buffers.
        let buffer = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size: bytes,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::INDIRECT | wgpu::BufferUsages::COPY_SRC | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        self.check_errors()?;
        self.counters.add_buffer(bytes);
        Ok(self.insert(WgpuBuffer { buffer, words: bytes / 4, imported: false }))
    }

    fn destroy_buffer(&mut self, buffer: BufferId) {
        if let Some(slot) = self.buffers.get_mut(buffer.0 as usize)
            && let Some(b) = slot.take()
            && !b.imported
        {
            self.counters.remove_buffer(b.words * 4);
        }
    }

    fn buffer_words(&self, buffer: BufferId) -> Result<u64> {
        Ok(self.buffer(buffer)?.words)
    }

    fn write_buffer(&mut self, buffer: BufferId, offset_words: u64, data: &[u32]) -> Result<()> {
        self.check_range(buffer, offset_words, data.len() as u64)?;
        self.flush()?;
        // Lands before the commands of the next submission, after those of the last.
        self.queue.write_buffer(&self.buffer(buffer)?.buffer, offset_words * 4, bytemuck::cast_slice(data));
        self.counters.uploads += 1;
        Ok(())
    }

    fn read_buffer(&mut self, buffer: BufferId, offset_words: u64, words: u64) -> Result<Vec<u32>> {
        self.check_range(buffer, offset_words, words)?;
        self.refuse_external("read_buffer")?;
        if words == 0 {
            self.counters.readbacks += 1;
            return Ok(Vec::new());
        }
        let staging = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("dof readback"),
            size: words * 4,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let source = self.buffer(buffer)?.buffer.clone();
        self.encoder().copy_buffer_to_buffer(&source, offset_words * 4, &staging, 0, words * 4);
        self.flush()?;
        let mapped = Arc::new(Mutex::new(None));
        let done = mapped.clone();
        staging.map_async(wgpu::MapMode::Read, .., move |result| {
            if let Ok(mut slot) = done.lock() {
                *slot = Some(result);
            }
        });
        wait(&self.device)?;
        let outcome = mapped.lock().map_err(|_| Error::Device("the readback's state is poisoned".into()))?.take();
        match outcome {
            Some(Ok(())) => {}
            Some(Err(e)) => return Err(Error::Device(format!("mapping the readback: {e}"))),
            None => return Err(Error::Device("the readback was not mapped after the device went idle".into())),
        }
        let view = staging.get_mapped_range(..).map_err(|e| Error::Device(format!("reading the readback: {e}")))?;
        let out: Vec<u32> = view.as_chunks::<4>().0.iter().map(|w| u32::from_le_bytes(*w)).collect();
        drop(view);
        staging.unmap();
        self.counters.readbacks += 1;
        Ok(out)
    }

    fn fill(&mut self, buffer: BufferId, offset_words: u64, words: u64, value: u32, label: &str) -> Result<()> {
        self.check_range(buffer, offset_words, words)?;
        if value != 0 {
            let (Ok(offset), Ok(count)) = (u32::try_from(offset_words), u32::try_from(words)) else {
                return Err(Error::InvalidArgument(format!("fill `{label}` of a non-zero value beyond 2^32 words")));
            };
            let groups = count.div_ceil(FILL_THREADS).clamp(1, self.limits.max_workgroup_count[0]);
            let params = FillParams { offset, words: count, value };
            return self.dispatch(&FILL, [groups, 1, 1], &[buffer], bytemuck::cast_slice(&[params]), label);
        }
        let target = self.buffer(buffer)?.buffer.clone();
        self.encoder().clear_buffer(&target, offset_words * 4, Some(words * 4));
        self.counters.commands += 1;
        self.commands.push(Command::new(label, "fill"));
        Ok(())
    }

    fn dispatch(&mut self, kernel: &'static KernelDesc, groups: [u32; 3], buffers: &[BufferId], push: &[u32], label: &str) -> Result<()> {
        check_dispatch(&self.limits, kernel, Some(groups), buffers.len(), 0, push.len())?;
        self.record_dispatch(kernel, Groups::Direct(groups), buffers, &[], push, label)?;
        if groups.contains(&0) {
            self.counters.empty_dispatches += 1;
        }
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
        check_dispatch(&self.limits, kernel, Some(groups), buffers.len(), images.len(), push.len())?;
        check_images(self, kernel, images)?;
        self.record_dispatch(kernel, Groups::Direct(groups), buffers, images, push, label)?;
        if groups.contains(&0) {
            self.counters.empty_dispatches += 1;
        }
        Ok(())
    }

    fn check_image_sample(&self, image: &ImageRef) -> Result<()> {
        self.check_texture_sample(image)
    }

    fn check_image_store(&self, image: &ImageRef) -> Result<()> {
        self.check_texture_store(image)
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
        check_dispatch(&self.limits, kernel, None, buffers.len(), 0, push.len())?;
        self.check_range(args, args_offset_words, 3)?;
        let args = self.buffer(args)?.buffer.clone();
        self.record_dispatch(kernel, Groups::Indirect(args, args_offset_words * 4), buffers, &[], push, label)
    }

    fn copy_image_to_buffer(&mut self, image: ImageRef, buffer: BufferId, offset_words: u64, label: &str) -> Result<()> {
        self.copy_texture(image, buffer, offset_words, false, label)
    }

    fn copy_buffer_to_image(&mut self, buffer: BufferId, offset_words: u64, image: ImageRef, label: &str) -> Result<()> {
        self.copy_texture(image, buffer, offset_words, true, label)
    }

    fn check_image_copy(&self, image: &ImageRef, into_image: bool) -> Result<()> {
        self.check_texture_copy(image, into_image)
    }

    fn submit(&mut self) -> Result<Vec<CommandTime>> {
        self.refuse_external("submit")?;
        if !self.open_spans.is_empty() {
            return Err(Error::RecordingState(format!("submit with {} span(s) still open", self.open_spans.len())));
        }
        self.release_finished()?;
        self.flush()?;
        let (times, spans) = timing::times(&self.commands, &self.spans);
        self.commands.clear();
        self.spans.clear();
        self.span_times.extend(spans);
        Ok(times)
    }

    fn begin_span(&mut self, label: &str) -> Result<()> {
        self.refuse_external("a span")?;
        self.open_spans.push(self.spans.len());
        self.spans.push((label.to_string(), self.commands.len(), usize::MAX));
        Ok(())
    }

    fn end_span(&mut self) -> Result<()> {
        let open = self.open_spans.pop().ok_or_else(|| Error::RecordingState("end_span without an open span".into()))?;
        let end = self.commands.len();
        if let Some(span) = self.spans.get_mut(open) {
            span.2 = end;
        }
        Ok(())
    }

    fn take_span_times(&mut self) -> Vec<CommandTime> {
        std::mem::take(&mut self.span_times)
    }

    fn check_frame_recording(&self) -> Result<()> {
        if self.callers_device && !self.external {
            return Err(Error::RecordingState(
                "a frame on a backend wrapping the caller's wgpu device must be recorded into the caller's encoder: call record_into first"
                    .into(),
            ));
        }
        Ok(())
    }

    fn counters(&self) -> BackendCounters {
        self.counters
    }

    fn reset_peak_device_bytes(&mut self) {
        self.counters.reset_peak();
    }

    fn set_memory_budget(&mut self, budget: Option<u64>) {
        self.budget = budget;
    }

    fn prepare(&mut self, kernels: &[&'static KernelDesc], draws: &[&'static dof_shaders::DrawDesc]) -> Result<()> {
        for kernel in kernels.iter().copied().chain(draws.iter().flat_map(|d| [Some(d.fallback), d.fallback_prepass]).flatten()) {
            self.pipeline(kernel)?;
        }
        Ok(())
    }

    fn take_diagnostics(&mut self) -> Vec<String> {
        self.errors.lock().map(|mut e| std::mem::take(&mut *e)).unwrap_or_default()
    }
}

/// Waits until the device has run everything submitted.
fn wait(device: &wgpu::Device) -> Result<()> {
    device
        .poll(wgpu::PollType::Wait { submission_index: None, timeout: None })
        .map(|_| ())
        .map_err(|e| Error::Device(format!("waiting for the device: {e}")))
}
