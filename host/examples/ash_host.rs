//! An example host: a small Vulkan renderer written directly against `ash` that runs depth of field
//! through the public frame API inside its own frames. It is the proof that an integrator needs
//! nothing beyond that API, and a template to copy from.
//!
//! What the renderer does, and what it hands the library:
//! 1. It makes its own instance (with `--validation`: the Khronos validation layer with
//!    synchronization validation, and a debug messenger collecting warnings and errors), picks a
//!    device, and makes its own device (with `VulkanBackend::required_device_extensions` and
//!    `required_features`), queue, command pool, command buffer and fence.
//! 2. It renders the built-in `simple` scene on the CPU (the library's ray caster stands in for the
//!    renderer's G-buffer passes) and uploads it through its own staging buffer: a pinhole colour
//!    image (RGBA32F), a linear view-depth image (R32F), and the multi-layer image in two storage
//!    buffers of its own. It also makes the RGBA32F image the result goes to.
//! 3. It wraps its device with `VulkanBackend::from_raw`, imports its two storage buffers, and
//!    creates one `SplatContext` (every allocation happens here, once).
//! 4. Per frame, in its own command buffer: its own pass before (clearing the output image), then
//!    the library's recording (`VulkanBackend::record_into`, a guard that ends it), `record`, then
//!    its own pass after (copying the
//!    result into a host-visible buffer), one submission with its own fence. Several multi-layer
//!    frames with a changing focus distance, then one frame from the colour and depth images, which
//!    the library samples in place through the renderer's views (`ImageDesc::sampled_through`);
//!    every result is written in place into the renderer's output image, through its view.
//!    Inside a frame the library allocates, submits and reads back nothing: checked on its counters.
//! 5. Each result is compared with the same `SplatContext` run on the library's CPU backend from
//!    the same slots (`dof-core` only), and the last multi-layer and the single-layer results are
//!    written as EXR and PNG (with the `exr` and `png` crates).
//! 6. Peeled frames, the camera orbiting 2 degrees a frame: the renderer draws each peel pass with
//!    its own render pass, pipeline and GLSL shaders (`ash_host/peel.rs`, `peel.vert`, `peel.frag`,
//!    their SPIR-V checked in beside them) into an RGBA16F colour and a D32 depth attachment; its
//!    fragment shader discards by the library's test (`dof_peel_keep`, docs/integration.md) against
//!    the bound `RendererPeel` writes, and its draw is indirect from the command the library
//!    writes. `RendererPeel` appends each pass into the multi-layer image on the device, and the
//!    same `SplatContext` blurs it: one submission of ours a frame, and none, no allocation, upload
//!    or readback of the library's (its counters). (That these passes give the slots the library's own
//!    mesh peel gives is `tests/tests/renderer_peel.rs`.)
//! 7. Teardown: the contexts, the backend, then the renderer's own objects, the messenger last.
//!
//! Beyond `dof-core`, the example takes only its input from `dof`: the built-in scene and its
//! ray-cast layers.
//!
//! `cargo run --example ash_host -- [--validation] [--width W --height H] [--frames N] [--out DIR]
//! [--device NAME]`; it exits non-zero when a check fails or the validation layer said anything.

use anyhow::{Context, Result, bail, ensure};
use dof::frame::Extent;
use dof::layers::LayeredImage;
use dof::scene::{Focus, GuardBand, LayerOptions, LensSettings, ThinLens, Vec3, builtin, raycast_layers};
use dof_core::backend::vulkan::ash::vk::{AccessFlags as Access, ImageLayout as Layout};
use dof_core::backend::vulkan::ash::{self, vk};
use dof_core::backend::{Backend, BackendCounters, CommandTime, ImageRef, RawDevice, RawOptions, VulkanBackend};
use dof_core::frame::{
    CountBuffer, DepthEncoding, DofContext, Frame, FrameInput, FrameOutput, Merge, RendererPeel, RendererPeelDesc, RgbBuffer, SlotBuffer,
    SplatContext, SplatContextDesc, SplatOptions,
};
use dof_shaders::slot::SLOT_WORDS;
use std::ffi::{CStr, c_char, c_void};
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::{Arc, Mutex};
use std::time::Instant;

#[path = "ash_host/peel.rs"]
mod peel;
#[path = "common/shared.rs"]
mod shared;
use shared::{CpuCheck, Rgb, compare, look_at, peel_scene, projection, write_image};

const USAGE: &str = "usage: ash_host [--validation] [--width W] [--height H] [--frames N] [--out DIR] [--device NAME]";

struct Args {
    validation: bool,
    width: u32,
    height: u32,
    frames: u32,
    out: PathBuf,
    device: Option<String>,
}

fn parse_args() -> Result<Args> {
    let mut args = Args { validation: false, width: 320, height: 180, frames: 3, out: "out/ash_host".into(), device: None };
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        let mut value = || it.next().with_context(|| format!("{arg} needs a value\n{USAGE}"));
        match arg.as_str() {
            "--validation" => args.validation = true,
            "--width" => args.width = value()?.parse()?,
            "--height" => args.height = value()?.parse()?,
            "--frames" => args.frames = value()?.parse()?,
            "--out" => args.out = value()?.into(),
            "--device" => args.device = Some(value()?),
            "-h" | "--help" => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            _ => bail!("unknown argument `{arg}`\n{USAGE}"),
        }
    }
    ensure!(args.width > 0 && args.height > 0 && args.frames > 0, "width, height and frames must be positive");
    Ok(args)
}

// ---------------------------------------------------------------------------------------------
// The renderer's own Vulkan objects. Nothing here is specific to the library, except the device
// extensions and features it asks for.
// ---------------------------------------------------------------------------------------------

/// Warnings and errors of the validation layer, collected by the debug messenger.
type Log = Mutex<Vec<String>>;

unsafe extern "system" fn collect(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    log: *mut c_void,
) -> vk::Bool32 {
    // SAFETY: the layer passes valid data for the duration of the call; `log` is the `Log` that
    // `main` keeps alive until after the instance is destroyed.
    let (data, log) = unsafe { (&*data, &*(log as *const Log)) };
    let text = |p: *const c_char| if p.is_null() { String::new() } else { unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned() };
    log.lock().unwrap_or_else(|e| e.into_inner()).push(format!(
        "[{severity:?}] {}: {}",
        text(data.p_message_id_name),
        text(data.p_message)
    ));
    vk::FALSE
}

fn messenger_info(log: &Arc<Log>) -> vk::DebugUtilsMessengerCreateInfoEXT<'static> {
    use vk::DebugUtilsMessageTypeFlagsEXT as T;
    vk::DebugUtilsMessengerCreateInfoEXT::default()
        .message_severity(vk::DebugUtilsMessageSeverityFlagsEXT::WARNING | vk::DebugUtilsMessageSeverityFlagsEXT::ERROR)
        .message_type(T::GENERAL | T::VALIDATION | T::PERFORMANCE)
        .pfn_user_callback(Some(collect))
        .user_data(Arc::as_ptr(log) as *mut c_void)
}

/// A buffer with its own memory; `mapped` is set for host-visible ones.
#[derive(Clone, Copy)]
struct Buffer {
    buffer: vk::Buffer,
    memory: vk::DeviceMemory,
    bytes: u64,
    mapped: *mut u8,
}

struct Renderer {
    entry: ash::Entry,
    instance: ash::Instance,
    messenger: Option<(ash::ext::debug_utils::Instance, vk::DebugUtilsMessengerEXT)>,
    physical: vk::PhysicalDevice,
    graphics: bool,
    device: ash::Device,
    queue_family: u32,
    queue: vk::Queue,
    pool: vk::CommandPool,
    cb: vk::CommandBuffer,
    fence: vk::Fence,
    buffers: Vec<Buffer>,
    images: Vec<(vk::Image, vk::DeviceMemory)>,
    /// Views the frame samples our colour and depth images through.
    views: Vec<vk::ImageView>,
}

impl Renderer {
    fn new(validation: bool, log: &Arc<Log>, device_name: Option<&str>) -> Result<Renderer> {
        // SAFETY: loading the system's Vulkan loader; every call below gets valid create infos that
        // point at live locals, and every object is destroyed in `destroy`.
        unsafe {
            let entry = ash::Entry::load().context("no Vulkan loader")?;
            let app = vk::ApplicationInfo::default().application_name(c"ash_host").api_version(VulkanBackend::REQUIRED_API_VERSION);
            let layers = [c"VK_LAYER_KHRONOS_validation".as_ptr()];
            let extensions = [vk::EXT_DEBUG_UTILS_NAME.as_ptr(), vk::EXT_VALIDATION_FEATURES_NAME.as_ptr()];
            let sync = [vk::ValidationFeatureEnableEXT::SYNCHRONIZATION_VALIDATION];
            let mut features = vk::ValidationFeaturesEXT::default().enabled_validation_features(&sync);
            // Chained, this messenger also sees what vkCreateInstance and vkDestroyInstance report.
            let mut chained = messenger_info(log);
            let mut info = vk::InstanceCreateInfo::default().application_info(&app);
            if validation {
                info =
                    info.enabled_layer_names(&layers).enabled_extension_names(&extensions).push_next(&mut features).push_next(&mut chained);
            }
            let instance = entry
                .create_instance(&info, None)
                .context("vkCreateInstance (with --validation: is vulkan-validationlayers installed?)")?;
            let messenger = if validation {
                let debug = ash::ext::debug_utils::Instance::new(&entry, &instance);
                let messenger = debug.create_debug_utils_messenger(&messenger_info(log), None)?;
                Some((debug, messenger))
            } else {
                None
            };

            // A Vulkan 1.2 device with the extensions the library needs and a compute queue (graphics
            // too where there is one): `--device` picks by name, else the first such device.
            let wanted = VulkanBackend::required_device_extensions();
            let mut chosen = None;
            for pd in instance.enumerate_physical_devices()? {
                let props = instance.get_physical_device_properties(pd);
                let name = props.device_name_as_c_str().unwrap_or_default().to_string_lossy().into_owned();
                let have = instance.enumerate_device_extension_properties(pd)?;
                let supported = wanted.iter().all(|w| have.iter().any(|h| h.extension_name_as_c_str() == Ok(*w)));
                let families = instance.get_physical_device_queue_family_properties(pd);
                let family = families
                    .iter()
                    .position(|f| f.queue_flags.contains(vk::QueueFlags::GRAPHICS | vk::QueueFlags::COMPUTE))
                    .or_else(|| families.iter().position(|f| f.queue_flags.contains(vk::QueueFlags::COMPUTE)));
                let named = device_name.is_none_or(|n| name.to_lowercase().contains(&n.to_lowercase()));
                if let (true, true, true, Some(family)) =
                    (named, supported, props.api_version >= VulkanBackend::REQUIRED_API_VERSION, family)
                {
                    let graphics = families[family].queue_flags.contains(vk::QueueFlags::GRAPHICS);
                    chosen = Some((pd, family as u32, graphics, name));
                    break;
                }
            }
            let (physical, queue_family, graphics, name) = chosen.context("no Vulkan 1.2 device with the extensions the library needs")?;
            println!("device: {name}");

            // The device the library needs, made by the renderer: its extensions and features (a
            // real renderer adds its own to these lists).
            let priorities = [1.0];
            let queues = [vk::DeviceQueueCreateInfo::default().queue_family_index(queue_family).queue_priorities(&priorities)];
            let extensions: Vec<*const c_char> = wanted.iter().map(|e| e.as_ptr()).collect();
            let mut required = VulkanBackend::required_features();
            let info = vk::DeviceCreateInfo::default()
                .queue_create_infos(&queues)
                .enabled_extension_names(&extensions)
                .enabled_features(&required.core)
                .push_next(&mut required.vulkan12);
            let device = instance.create_device(physical, &info, None)?;
            let queue = device.get_device_queue(queue_family, 0);
            let pool_info = vk::CommandPoolCreateInfo::default()
                .queue_family_index(queue_family)
                .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER);
            let pool = device.create_command_pool(&pool_info, None)?;
            let alloc =
                vk::CommandBufferAllocateInfo::default().command_pool(pool).level(vk::CommandBufferLevel::PRIMARY).command_buffer_count(1);
            let cb = device.allocate_command_buffers(&alloc)?[0];
            let fence = device.create_fence(&vk::FenceCreateInfo::default(), None)?;
            let (buffers, images, views) = (Vec::new(), Vec::new(), Vec::new());
            Ok(Renderer {
                entry,
                instance,
                messenger,
                physical,
                graphics,
                device,
                queue_family,
                queue,
                pool,
                cb,
                fence,
                buffers,
                images,
                views,
            })
        }
    }

    fn memory(&self, req: vk::MemoryRequirements, flags: vk::MemoryPropertyFlags) -> Result<vk::DeviceMemory> {
        // SAFETY: a query on the live instance, and an allocation of a type it reported.
        unsafe {
            let props = self.instance.get_physical_device_memory_properties(self.physical);
            let index = (0..props.memory_type_count)
                .find(|&i| req.memory_type_bits & (1 << i) != 0 && props.memory_types[i as usize].property_flags.contains(flags))
                .context("no suitable memory type")?;
            let info = vk::MemoryAllocateInfo::default().allocation_size(req.size).memory_type_index(index);
            Ok(self.device.allocate_memory(&info, None)?)
        }
    }

    /// A buffer in device-local memory, or in host-visible coherent memory, mapped, when `host`.
    fn buffer(&mut self, bytes: u64, usage: vk::BufferUsageFlags, host: bool) -> Result<Buffer> {
        use vk::MemoryPropertyFlags as M;
        let flags = if host { M::HOST_VISIBLE | M::HOST_COHERENT } else { M::DEVICE_LOCAL };
        // SAFETY: creation on the live device; destroyed in `destroy`.
        unsafe {
            let buffer = self.device.create_buffer(&vk::BufferCreateInfo::default().size(bytes).usage(usage), None)?;
            let memory = self.memory(self.device.get_buffer_memory_requirements(buffer), flags)?;
            self.device.bind_buffer_memory(buffer, memory, 0)?;
            let mapped = match host {
                true => self.device.map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())? as *mut u8,
                false => std::ptr::null_mut(),
            };
            self.buffers.push(Buffer { buffer, memory, bytes, mapped });
            Ok(Buffer { buffer, memory, bytes, mapped })
        }
    }

    /// A 2D image, optimal tiling, in device-local memory (initially UNDEFINED).
    fn image(&mut self, format: vk::Format, extent: [u32; 2], usage: vk::ImageUsageFlags) -> Result<vk::Image> {
        let info = vk::ImageCreateInfo::default()
            .image_type(vk::ImageType::TYPE_2D)
            .format(format)
            .extent(vk::Extent3D { width: extent[0], height: extent[1], depth: 1 })
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .tiling(vk::ImageTiling::OPTIMAL)
            .usage(usage)
            .initial_layout(Layout::UNDEFINED);
        // SAFETY: creation on the live device; destroyed in `destroy`.
        unsafe {
            let image = self.device.create_image(&info, None)?;
            let memory = self.memory(self.device.get_image_memory_requirements(image), vk::MemoryPropertyFlags::DEVICE_LOCAL)?;
            self.device.bind_image_memory(image, memory, 0)?;
            self.images.push((image, memory));
            Ok(image)
        }
    }

    /// A 2D colour view of mip 0 and layer 0 of `image`, as a renderer keeps for sampling.
    fn view(&mut self, image: vk::Image, format: vk::Format) -> Result<vk::ImageView> {
        let range = vk::ImageSubresourceRange::default().aspect_mask(vk::ImageAspectFlags::COLOR).level_count(1).layer_count(1);
        let info =
            vk::ImageViewCreateInfo::default().image(image).view_type(vk::ImageViewType::TYPE_2D).format(format).subresource_range(range);
        // SAFETY: creation on the live device for a live image; destroyed in `destroy`.
        let view = unsafe { self.device.create_image_view(&info, None)? };
        self.views.push(view);
        Ok(view)
    }

    /// Begins the command buffer (its last submission has completed: every one is waited for).
    fn begin(&self) -> Result<()> {
        // SAFETY: the command buffer is not pending.
        unsafe {
            self.device.reset_command_buffer(self.cb, vk::CommandBufferResetFlags::empty())?;
            self.device.begin_command_buffer(
                self.cb,
                &vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT),
            )?;
        }
        Ok(())
    }

    /// Ends the command buffer, submits it with the renderer's fence and waits.
    fn submit_and_wait(&self) -> Result<()> {
        let cbs = [self.cb];
        // SAFETY: the command buffer is recorded; the fence is unsignalled.
        unsafe {
            self.device.end_command_buffer(self.cb)?;
            self.device.queue_submit(self.queue, &[vk::SubmitInfo::default().command_buffers(&cbs)], self.fence)?;
            self.device.wait_for_fences(&[self.fence], true, u64::MAX)?;
            self.device.reset_fences(&[self.fence])?;
        }
        Ok(())
    }

    /// A layout transition of `image` after `src` (stages, accesses) and before `dst`.
    fn image_barrier(&self, image: vk::Image, old: Layout, new: Layout, src: Scope, dst: Scope) {
        let barrier = [vk::ImageMemoryBarrier::default()
            .image(image)
            .old_layout(old)
            .new_layout(new)
            .src_access_mask(src.1)
            .dst_access_mask(dst.1)
            .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .subresource_range(
                vk::ImageSubresourceRange::default().aspect_mask(vk::ImageAspectFlags::COLOR).level_count(1).layer_count(1),
            )];
        // SAFETY: the command buffer is recording, outside a render pass; the image is live.
        unsafe { self.device.cmd_pipeline_barrier(self.cb, src.0, dst.0, vk::DependencyFlags::empty(), &[], &[], &barrier) };
    }

    fn memory_barrier(&self, src: Scope, dst: Scope) {
        let barrier = [vk::MemoryBarrier::default().src_access_mask(src.1).dst_access_mask(dst.1)];
        // SAFETY: the command buffer is recording, outside a render pass.
        unsafe { self.device.cmd_pipeline_barrier(self.cb, src.0, dst.0, vk::DependencyFlags::empty(), &barrier, &[], &[]) };
    }

    /// Destroys everything (the backend must be gone and the device idle), the messenger last.
    fn destroy(self) {
        // SAFETY: nothing is in use any more; each object is destroyed once, children first.
        unsafe {
            let d = &self.device;
            d.device_wait_idle().ok();
            for b in &self.buffers {
                d.destroy_buffer(b.buffer, None);
                d.free_memory(b.memory, None);
            }
            for &view in &self.views {
                d.destroy_image_view(view, None);
            }
            for &(image, memory) in &self.images {
                d.destroy_image(image, None);
                d.free_memory(memory, None);
            }
            d.destroy_fence(self.fence, None);
            d.destroy_command_pool(self.pool, None);
            d.destroy_device(None);
            if let Some((debug, messenger)) = &self.messenger {
                debug.destroy_debug_utils_messenger(*messenger, None);
            }
            self.instance.destroy_instance(None);
        }
    }
}

fn region(extent: [u32; 2], buffer_offset: u64) -> [vk::BufferImageCopy; 1] {
    [vk::BufferImageCopy::default()
        .buffer_offset(buffer_offset)
        .image_subresource(vk::ImageSubresourceLayers::default().aspect_mask(vk::ImageAspectFlags::COLOR).layer_count(1))
        .image_extent(vk::Extent3D { width: extent[0], height: extent[1], depth: 1 })]
}

/// A synchronisation scope: pipeline stages and memory accesses.
type Scope = (vk::PipelineStageFlags, vk::AccessFlags);
const TRANSFER: vk::PipelineStageFlags = vk::PipelineStageFlags::TRANSFER;
const COMPUTE: vk::PipelineStageFlags = vk::PipelineStageFlags::COMPUTE_SHADER;

// ---------------------------------------------------------------------------------------------
// The frame.
// ---------------------------------------------------------------------------------------------

/// What one frame produced.
struct FrameResult {
    image: Rgb,
    counters: BackendCounters,
    times: Vec<CommandTime>,
    record_ms: f64,
}

/// The renderer's output image and the host-visible buffer it reads the image back through.
struct Output {
    image: vk::Image,
    /// The view the library writes the image through, in place.
    view: vk::ImageView,
    readback: Buffer,
    extent: [u32; 2],
}

/// A frame's layers peeled by our own pipeline: the library's peel, our pass, the view.
struct Peeling<'a> {
    peel: &'a mut RendererPeel,
    pass: &'a peel::PeelPass,
    view_proj: [f32; 16],
    background: [f32; 3],
}

/// One frame in the renderer's command buffer: its pass before (and, when `peeling`, its own peel
/// passes, each appended by the library), the depth of field, its pass after.
fn run_frame(
    r: &Renderer,
    backend: &mut VulkanBackend,
    ctx: &mut SplatContext,
    out: &Output,
    lens: ThinLens,
    input: FrameInput,
    mut peeling: Option<Peeling>,
) -> Result<FrameResult> {
    let (output, extent) = (out.image, out.extent);
    let shader_read = Layout::SHADER_READ_ONLY_OPTIMAL;
    let before = backend.counters();
    let start = Instant::now();
    r.begin()?;
    // Our peel passes, in our command buffer: each library call inside a recording of the
    // library's (`record_into`, ended when it drops), our render passes between them
    // (docs/integration.md has the order).
    if let Some(p) = peeling.as_mut() {
        // SAFETY: as for the frame below.
        p.peel.begin(&mut *unsafe { backend.record_into(r.cb)? }, &lens)?;
        for k in 0..p.peel.layers() {
            p.pass.record(r, p.view_proj, p.background);
            let (colour, depth) = p.pass.attachments()?;
            // SAFETY: as for the frame below.
            p.peel.append(&mut *unsafe { backend.record_into(r.cb)? }, k, colour, depth)?;
        }
    }

    // The pass before: here a clear of the output image (magenta, so a pixel the frame did not write
    // would show, and fail the comparison). The previous frame's readback copy read the image, so
    // the transition waits for transfers; its contents are discarded (UNDEFINED).
    r.image_barrier(
        output,
        Layout::UNDEFINED,
        Layout::TRANSFER_DST_OPTIMAL,
        (TRANSFER, Access::empty()),
        (TRANSFER, Access::TRANSFER_WRITE),
    );
    let range = [vk::ImageSubresourceRange::default().aspect_mask(vk::ImageAspectFlags::COLOR).level_count(1).layer_count(1)];
    let magenta = vk::ClearColorValue { float32: [1.0, 0.0, 1.0, 1.0] };
    // SAFETY: recording, outside a render pass; the image has TRANSFER_DST usage and is in that layout.
    unsafe { r.device.cmd_clear_color_image(r.cb, output, Layout::TRANSFER_DST_OPTIMAL, &magenta, &range) };

    // The output as the library sees it: in TRANSFER_DST_OPTIMAL after our clear (a transfer write,
    // which the library's kernel must wait for; a pixel it did not write would keep the magenta),
    // written in place through our view, to be left in SHADER_READ_ONLY_OPTIMAL, where a
    // renderer's next pass (tone mapping, UI) would sample it.
    // SAFETY: our live RGBA32F image of this extent, TRANSFER_DST|TRANSFER_SRC|SAMPLED|STORAGE
    // usage, and a live view of it, on the backend's queue family, in the declared layout when the
    // frame runs; alive until the fence.
    let out_ref = ImageRef::describe(output, vk::Format::R32G32B32A32_SFLOAT, extent)?
        .in_layout(Layout::TRANSFER_DST_OPTIMAL)
        .after(TRANSFER, Access::TRANSFER_WRITE)
        .leave_in(shader_read)
        .sampled_through(out.view);
    let out_ref = unsafe { out_ref.build() };
    let frame = Frame { width: extent[0], height: extent[1], lens, input, output: FrameOutput::Image(out_ref) };

    // The library's part, recorded into our command buffer. While its recording lasts we record
    // nothing ourselves; it opens with a barrier after our transfer, compute and attachment writes,
    // and its end closes it with one before our later transfer and shader accesses. (The first
    // frame of each input kind takes longer to record: the library creates a kernel's pipeline on
    // its first use.)
    // SAFETY: our command buffer is recording, outside a render pass, from a pool of the backend's
    // queue family; it is submitted after the recording ends, and every resource outlives the fence
    // wait.
    let mut recording = unsafe { backend.record_into(r.cb)? };
    if let Some(p) = peeling.as_mut() {
        p.peel.finish(&mut *recording)?;
    }
    ctx.record(&mut *recording, &frame)?;
    recording.end()?;
    let record_ms = start.elapsed().as_secs_f64() * 1e3;

    // The pass after: the result into our host-visible buffer. The library documents the state it
    // leaves the output in: `final_layout`, last written by a transfer (its copy) whose writes it made
    // visible to every later command. Our barrier names that transfer write as its source and moves
    // the image to the layout our copy needs.
    r.image_barrier(
        output,
        shader_read,
        Layout::TRANSFER_SRC_OPTIMAL,
        (TRANSFER, Access::TRANSFER_WRITE),
        (TRANSFER, Access::TRANSFER_READ),
    );
    // SAFETY: recording; the image is in TRANSFER_SRC_OPTIMAL and the buffer holds 16 bytes a pixel.
    unsafe { r.device.cmd_copy_image_to_buffer(r.cb, output, Layout::TRANSFER_SRC_OPTIMAL, out.readback.buffer, &region(extent, 0)) };
    r.memory_barrier((TRANSFER, Access::TRANSFER_WRITE), (vk::PipelineStageFlags::HOST, Access::HOST_READ));
    r.submit_and_wait()?;

    // After our fence: the library's counters over the frame, and its GPU timestamps.
    let counters = backend.counters().since(&before);
    let mut times = backend.take_external_times()?.context("the frame completed, so its times are ready")?;
    // One list per recording (the peel's passes are recordings of their own); empty: none left.
    while let Some(more) = backend.take_external_times()?.filter(|t| !t.is_empty()) {
        times.extend(more);
    }
    let pixels = extent[0] as usize * extent[1] as usize;
    let mut rgba = vec![0f32; 4 * pixels];
    // SAFETY: the mapping covers the buffer; the copy completed and was made visible to the host.
    unsafe { std::ptr::copy_nonoverlapping(out.readback.mapped as *const f32, rgba.as_mut_ptr(), 4 * pixels) };
    let data = rgba.as_chunks::<4>().0.iter().map(|p| [p[0], p[1], p[2]]).collect();
    Ok(FrameResult { image: Rgb { width: extent[0], height: extent[1], data }, counters, times, record_ms })
}

fn times_summary(times: &[CommandTime]) -> String {
    let total: f64 = times.iter().map(|t| t.ms).sum();
    let mut by_label: Vec<(String, f64)> = Vec::new();
    for t in times {
        match by_label.iter_mut().find(|(l, _)| *l == t.label) {
            Some((_, ms)) => *ms += t.ms,
            None => by_label.push((t.label.clone(), t.ms)),
        }
    }
    by_label.sort_by(|a, b| b.1.total_cmp(&a.1));
    let top: Vec<String> = by_label.iter().take(3).map(|(l, ms)| format!("{l} {ms:.2}")).collect();
    format!("GPU {total:.2} ms over {} commands (slowest: {})", times.len(), top.join(", "))
}

fn main() -> Result<ExitCode> {
    let args = parse_args()?;
    let (w, h) = (args.width, args.height);
    let extent = [w, h];
    let pixels = w as u64 * h as u64;
    let mut failures: Vec<String> = Vec::new();

    // The scene, rendered on the CPU: every layer everywhere (no disocclusion buffer, which depends
    // on the focus, since the focus changes per frame) and no guard band (the renderer's frame is
    // all there is).
    let scene = builtin("simple")?.with_size(w, h);
    let default_lens = scene.thin_lens()?;
    let options = LayerOptions { guard_band: GuardBand::Off, disocclusion: false, ..LayerOptions::default() };
    let layers: LayeredImage = raycast_layers(&scene.scene, &scene.camera, &default_lens, &options)?.layers;
    let (colour, depth) = layers.front();
    let front = layers.front_layer();
    let l = layers.max_layers as u64;

    // The renderer, its resources, and the upload through its own staging buffer.
    let log: Arc<Log> = Arc::default();
    let mut r = Renderer::new(args.validation, &log, args.device.as_deref())?;
    let storage = vk::BufferUsageFlags::STORAGE_BUFFER | vk::BufferUsageFlags::TRANSFER_DST;
    let fragments = r.buffer(4 * SLOT_WORDS as u64 * pixels * l, storage, false)?;
    let counts = r.buffer(4 * pixels, storage, false)?;
    let image_usage = vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST | vk::ImageUsageFlags::SAMPLED;
    let colour_image = r.image(vk::Format::R32G32B32A32_SFLOAT, extent, image_usage)?;
    let depth_image = r.image(vk::Format::R32_SFLOAT, extent, image_usage)?;
    let (colour_view, depth_view) = (r.view(colour_image, vk::Format::R32G32B32A32_SFLOAT)?, r.view(depth_image, vk::Format::R32_SFLOAT)?);
    let output_image = r.image(vk::Format::R32G32B32A32_SFLOAT, extent, image_usage | vk::ImageUsageFlags::STORAGE)?;
    let output = Output {
        image: output_image,
        view: r.view(output_image, vk::Format::R32G32B32A32_SFLOAT)?,
        readback: r.buffer(16 * pixels, vk::BufferUsageFlags::TRANSFER_DST, true)?,
        extent,
    };

    // Staging holds, in order: colour (RGBA32F), depth (R32F), fragments (5 words a slot:
    // premultiplied red, green, blue, depth, alpha; `dof_shaders::slot`), counts. Colour goes first: an image copy's buffer offset must be a
    // multiple of the texel size (16 bytes for RGBA32F).
    let mut words: Vec<u32> = colour.data.iter().flat_map(|c| [c[0], c[1], c[2], 1.0]).map(f32::to_bits).collect();
    words.extend(depth.iter().map(|d| d.to_bits()));
    words.extend(layers.fragments.iter().flat_map(|f| f.slot().words()));
    words.extend(&layers.counts);
    let staging = r.buffer(4 * words.len() as u64, vk::BufferUsageFlags::TRANSFER_SRC, true)?;
    // SAFETY: the mapping covers `words`; the GPU does not use the buffer yet.
    unsafe { std::ptr::copy_nonoverlapping(words.as_ptr() as *const u8, staging.mapped, 4 * words.len()) };
    let (at_depth, at_fragments) = (16 * pixels, 20 * pixels);
    let at_counts = at_fragments + fragments.bytes;
    r.begin()?;
    let to_dst = (TRANSFER, Access::TRANSFER_WRITE);
    for image in [colour_image, depth_image] {
        r.image_barrier(
            image,
            Layout::UNDEFINED,
            Layout::TRANSFER_DST_OPTIMAL,
            (vk::PipelineStageFlags::TOP_OF_PIPE, Access::empty()),
            to_dst,
        );
    }
    // SAFETY: recording; the regions lie inside the buffers, the images are in TRANSFER_DST_OPTIMAL.
    unsafe {
        let d = &r.device;
        d.cmd_copy_buffer(
            r.cb,
            staging.buffer,
            fragments.buffer,
            &[vk::BufferCopy::default().src_offset(at_fragments).size(fragments.bytes)],
        );
        d.cmd_copy_buffer(r.cb, staging.buffer, counts.buffer, &[vk::BufferCopy::default().src_offset(at_counts).size(counts.bytes)]);
        d.cmd_copy_buffer_to_image(r.cb, staging.buffer, colour_image, Layout::TRANSFER_DST_OPTIMAL, &region(extent, 0));
        d.cmd_copy_buffer_to_image(r.cb, staging.buffer, depth_image, Layout::TRANSFER_DST_OPTIMAL, &region(extent, at_depth));
    }
    // The images end where a renderer's G-buffer pass would leave them for sampling in a compute
    // pass; the buffers' writes are made visible to compute reads.
    for image in [colour_image, depth_image] {
        r.image_barrier(image, Layout::TRANSFER_DST_OPTIMAL, Layout::SHADER_READ_ONLY_OPTIMAL, to_dst, (COMPUTE, Access::SHADER_READ));
    }
    r.memory_barrier(to_dst, (COMPUTE, Access::SHADER_READ));
    r.submit_and_wait()?;

    // The library on our device. It makes its own pipelines, command pool, query pools, allocator
    // and the context's buffers; it never destroys our objects.
    let raw = RawDevice {
        entry: r.entry.clone(),
        instance: r.instance.clone(),
        physical_device: r.physical,
        device: r.device.clone(),
        queue_family: r.queue_family,
        queue: r.queue,
    };
    // SAFETY: the handles are live and outlive the backend; the device was made with the required
    // API version, extensions and features; we do not use the queue from another thread; we drop
    // the backend only after every command buffer it recorded into has completed.
    let mut backend = unsafe { VulkanBackend::from_raw(raw, &RawOptions { debug_names: args.validation, ..Default::default() })? };
    println!("backend: {} ({}), queue with graphics: {}", backend.device_name(), backend.driver(), r.graphics);
    // SAFETY: our live storage buffers of this device with the sizes given; the library only reads
    // them; they outlive the backend's use (forgotten before the backend is dropped).
    let fragments_id = unsafe { backend.import_buffer(fragments.buffer, fragments.bytes, "fragments")? };
    // SAFETY: as above.
    let counts_id = unsafe { backend.import_buffer(counts.buffer, counts.bytes, "counts")? };

    let splat_options = SplatOptions { merge: Merge::X4, ..SplatOptions::default() };
    let mut desc = SplatContextDesc::new(Extent::new(w, h, layers.max_layers), splat_options.clone());
    desc.image_io = true;
    let mut ctx = SplatContext::new(&mut backend, &desc)?;
    // Creating the context recorded the zeroing of its buffers in the backend's own command buffer;
    // running it now (one submission to our queue, waited for) leaves nothing for the first frame's
    // recording to flush, so that every frame submits nothing.
    backend.submit()?;
    println!(
        "context: {:.1} MiB of device memory, {} allocations",
        ctx.device_bytes() as f64 / (1 << 20) as f64,
        backend.counters().allocations
    );

    // The check: the same context on the CPU backend.
    let mut check = CpuCheck::new(
        backend.limits().max_shared_bytes,
        &SplatContextDesc::new(Extent::new(w, h, layers.max_layers), splat_options.clone()),
    )?;

    // The frames: multi-layer from our buffers with the focus sweeping from near to far, then one
    // frame from our colour and depth images.
    let near_far = (1.5f32, 9.0f32);
    let mut results: Vec<(&str, Rgb)> = Vec::new();
    for i in 0..=args.frames {
        let multi = i < args.frames;
        let (lens, input, kind) = if multi {
            let t = if args.frames > 1 { i as f32 / (args.frames - 1) as f32 } else { 0.5 };
            let focus = near_far.0 * (near_far.1 / near_far.0).powf(t);
            let lens = LensSettings { focus: Focus::Distance(focus), ..scene.lens }.thin_lens(&scene.camera)?;
            (
                lens,
                FrameInput::Layers {
                    fragments: SlotBuffer::current(fragments_id),
                    counts: CountBuffer(counts_id),
                    layers: layers.max_layers,
                    footprint_side: 0,
                },
                "multi-layer",
            )
        } else {
            // Our upload left both images in SHADER_READ_ONLY_OPTIMAL, visible to compute; nothing
            // has written them since, so there is no write to name. They stay in that layout. The
            // frame samples them in place through our views: no copy.
            // SAFETY: our live RGBA32F and R32F images of this extent with SAMPLED usage, and live
            // views of them, on the backend's queue family, in the declared layout; alive until the
            // fence.
            let image = |image: vk::Image, view: vk::ImageView, format: vk::Format| -> dof_core::Result<ImageRef> {
                let desc =
                    ImageRef::describe(image, format, extent)?.in_layout(Layout::SHADER_READ_ONLY_OPTIMAL).after(COMPUTE, Access::empty());
                Ok(unsafe { desc.sampled_through(view).build() })
            };
            let color = image(colour_image, colour_view, vk::Format::R32G32B32A32_SFLOAT)?;
            let depth = image(depth_image, depth_view, vk::Format::R32_SFLOAT)?;
            let input = FrameInput::Images { color, depth, encoding: DepthEncoding::Linear };
            (default_lens, input, "single-layer")
        };
        let frame = run_frame(&r, &mut backend, &mut ctx, &output, lens, input, None)?;
        let c = frame.counters;
        println!(
            "frame {i} ({kind}, focus {:.2}): recorded in {:.2} ms; {} allocations, {} submissions, {} readbacks, {} uploads; {}",
            lens.focus_distance,
            frame.record_ms,
            c.allocations,
            c.submissions,
            c.readbacks,
            c.uploads,
            times_summary(&frame.times)
        );
        if (c.allocations, c.submissions, c.readbacks, c.uploads) != (0, 0, 0, 0) {
            failures.push(format!("frame {i}: the library allocated, submitted or transferred: {c:?}"));
        }
        let image = if multi { &layers } else { &front };
        let slots: Vec<u32> = image.fragments.iter().flat_map(|f| f.slot().words()).collect();
        let want = check.run(&slots, &image.counts, image.max_layers, lens)?;
        let (diff, ok) = compare(&frame.image, &want);
        println!(
            "  vs the same context on the CPU backend: largest difference per channel {diff:?}{}",
            if ok { "" } else { ": TOO LARGE" }
        );
        if !ok {
            failures.push(format!("frame {i} ({kind}) differs from the CPU backend by {diff:?}"));
        }
        if i + 1 >= args.frames {
            results.push((kind, frame.image));
        }
    }
    // Peeled frames: our own pipeline draws each peel pass (peel.rs), the library turns the passes
    // into the multi-layer image on the device and blurs it, the camera orbiting the focus point
    // 2 degrees a frame. All in one command buffer and one submission of ours per frame.
    let background = [0.5, 0.7, 1.0];
    let pass = peel::PeelPass::new(&mut r, extent, &peel_scene())?;
    let (bound_id, draw_id) = pass.import(&mut backend)?;
    let (yfov, near, far) = (50f32.to_radians(), 0.1, 100.0);
    let peel_options = LayerOptions { max_layers: layers.max_layers, ..LayerOptions::default() };
    let encoding = DepthEncoding::Standard { near, far };
    let peel_desc = RendererPeelDesc::new(&peel_options, w, h, encoding, (yfov / 2.0).tan(), pass.vertex_count);
    let mut renderer_peel = RendererPeel::new(&mut backend, &peel_desc, bound_id, Some(draw_id))?;
    backend.submit()?; // the peel's one-time zeroing, before the frames
    let lens = ThinLens { focal_length: 0.05, aperture_radius: 0.02, focus_distance: 3.0, pixels_per_unit: h as f32 / 0.024 };
    let target = Vec3::new(0.0, 0.0, -3.0);
    for i in 0..args.frames {
        let angle = (2.0 * i as f32).to_radians();
        let eye = target + 3.0 * Vec3::new(angle.sin(), 0.0, angle.cos());
        let view_proj = (projection(yfov, w as f32 / h as f32, near, far, true) * look_at(eye, target)).to_cols_array();
        let input = renderer_peel.frame(lens, FrameOutput::Buffer(RgbBuffer(bound_id))).input;
        let peeling = Peeling { peel: &mut renderer_peel, pass: &pass, view_proj, background };
        let frame = run_frame(&r, &mut backend, &mut ctx, &output, lens, input, Some(peeling))?;
        let c = frame.counters;
        println!(
            "peeled frame {i} (orbit {:.0} deg): recorded in {:.2} ms; {} allocations, {} submissions, {} readbacks, {} uploads; {}",
            angle.to_degrees(),
            frame.record_ms,
            c.allocations,
            c.submissions,
            c.readbacks,
            c.uploads,
            times_summary(&frame.times)
        );
        if (c.allocations, c.submissions, c.readbacks, c.uploads) != (0, 0, 0, 0) {
            failures.push(format!("peeled frame {i}: the library allocated, submitted or transferred: {c:?}"));
        }
        let unwritten = frame.image.data.iter().filter(|p| !p.iter().all(|v| v.is_finite()) || *p == &[1.0, 0.0, 1.0]).count();
        if unwritten > 0 {
            failures.push(format!("peeled frame {i}: {unwritten} pixels not written or not finite"));
        }
        if i + 1 == args.frames {
            results.push(("peeled", frame.image));
        }
    }
    let report = renderer_peel.report(&mut backend)?;
    println!("peel: {} passes recorded, {} drawn, {} found a surface", report.recorded, report.drawn, report.with_surface);
    if report.with_surface < 3 {
        failures.push(format!("the peel found surfaces in {} passes, want 3 (bar, pane, wall)", report.with_surface));
    }

    // What the last frame did, read from the context once its work is done (a readback, outside
    // the frames).
    let report = ctx.report(&mut backend)?;
    println!(
        "last frame's report: {} fragments tiled into {} list entries (pool {}), {} tiles overflowed",
        report.fragments, report.list_entries, report.list_capacity, report.overflow_tiles
    );

    std::fs::create_dir_all(&args.out)?;
    for (kind, image) in &results {
        let path = args.out.join(kind);
        write_image(&path, image)?;
        println!("wrote {} and .png", path.with_extension("exr").display());
    }

    // Teardown: the library's objects first (imports are only forgotten), then ours. The contexts
    // free themselves when dropped (through the backend, once the device is done with them).
    drop((renderer_peel, ctx));
    backend.destroy_buffer(bound_id);
    backend.destroy_buffer(draw_id);
    pass.destroy(&r);
    check.destroy();
    backend.destroy_buffer(fragments_id);
    backend.destroy_buffer(counts_id);
    drop(backend);
    r.destroy();
    if args.validation {
        let messages = std::mem::take(&mut *log.lock().unwrap());
        println!("validation: {} message(s)", messages.len());
        for m in &messages {
            println!("  {m}");
        }
        if !messages.is_empty() {
            failures.push(format!("{} validation message(s)", messages.len()));
        }
    }
    if failures.is_empty() {
        println!("ok");
        Ok(ExitCode::SUCCESS)
    } else {
        eprintln!("FAILED:\n  {}", failures.join("\n  "));
        Ok(ExitCode::FAILURE)
    }
}
