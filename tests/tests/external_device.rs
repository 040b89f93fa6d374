//! The Vulkan backend inside someone else's renderer: the test plays the renderer. It makes its own
//! instance (validation layer with synchronization validation, its own debug messenger collecting
//! every warning and error), its own device with the backend's required extensions and features,
//! its own buffers and an RGBA32F image, and its own command buffer and fence. The backend is built on
//! those handles (`VulkanBackend::from_raw`), imports the buffers, and records a copy out of the
//! image, a prefix scan, a segmented sort of the imported buffers and a copy back into the image into
//! the renderer's command buffer, between the renderer's own passes. Results must equal the CPU
//! backend's bit for bit, and the validation layer must report nothing, leaks included.
//!
//! Like every Vulkan suite it fails where Vulkan or the layer is missing, unless `DOF_SKIP_VULKAN=1`
//! asks to skip it.

use dof::backend::vulkan::ash::{self, vk};
use dof::backend::vulkan::gpu_allocator;
use dof::backend::{Backend, BackendCounters, BufferId, CpuBackend, ImageFormat, ImageRef, RawDevice, RawOptions, VulkanBackend};
use dof::frame::{Frame, GatherContext, GatherContextDesc};
use dof::ops::scan::{ScanScratch, exclusive_scan};
use dof::ops::sort::{SegmentedSort, SortInput, sort_on};
use dof::workload::{lists_with, random_key};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use std::ffi::{CStr, c_char, c_void};
use std::sync::{Arc, Mutex};

const VALIDATION_LAYER: &CStr = c"VK_LAYER_KHRONOS_validation";
/// The image: odd sizes, 4 words a pixel, 9 scan blocks (two scan levels).
const WIDTH: u32 = 61;
const HEIGHT: u32 = 37;

fn skip_requested() -> bool {
    if std::env::var_os("DOF_SKIP_VULKAN").is_some_and(|v| v == "1") {
        eprintln!("DOF_SKIP_VULKAN=1: skipping a Vulkan test on purpose");
        return true;
    }
    false
}

type Log = Arc<Mutex<Vec<String>>>;

unsafe extern "system" fn collect(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user: *mut c_void,
) -> vk::Bool32 {
    use vk::DebugUtilsMessageSeverityFlagsEXT as S;
    if data.is_null() || user.is_null() || !severity.intersects(S::WARNING | S::ERROR) {
        return vk::FALSE;
    }
    // SAFETY: the layer passes valid data for the call; `user` is the test's log, which outlives the
    // instance.
    let (data, log) = unsafe { (&*data, &*(user as *const Mutex<Vec<String>>)) };
    let text = |p: *const c_char| if p.is_null() { String::new() } else { unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned() };
    let line = format!("[{severity:?}] {}: {}", text(data.p_message_id_name), text(data.p_message));
    log.lock().unwrap_or_else(|e| e.into_inner()).push(line);
    vk::FALSE
}

fn messenger_info(log: &Log) -> vk::DebugUtilsMessengerCreateInfoEXT<'static> {
    vk::DebugUtilsMessengerCreateInfoEXT::default()
        .message_severity(vk::DebugUtilsMessageSeverityFlagsEXT::WARNING | vk::DebugUtilsMessageSeverityFlagsEXT::ERROR)
        .message_type(
            vk::DebugUtilsMessageTypeFlagsEXT::GENERAL
                | vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION
                | vk::DebugUtilsMessageTypeFlagsEXT::PERFORMANCE,
        )
        .pfn_user_callback(Some(collect))
        .user_data(Arc::as_ptr(log) as *mut c_void)
}

/// A buffer of the renderer's with its memory, mapped when host-visible.
#[derive(Clone, Copy)]
struct OwnBuffer {
    buffer: vk::Buffer,
    memory: vk::DeviceMemory,
    bytes: u64,
    mapped: *mut u8,
}

/// The renderer: everything here is made and destroyed by the test, never by the backend.
struct Renderer {
    log: Log,
    entry: ash::Entry,
    instance: ash::Instance,
    debug: ash::ext::debug_utils::Instance,
    messenger: vk::DebugUtilsMessengerEXT,
    physical: vk::PhysicalDevice,
    device: ash::Device,
    queue_family: u32,
    queue: vk::Queue,
    pool: vk::CommandPool,
    cb: vk::CommandBuffer,
    fence: vk::Fence,
    buffers: Vec<OwnBuffer>,
    images: Vec<(vk::Image, vk::DeviceMemory)>,
}

impl Renderer {
    fn new() -> Renderer {
        let log: Log = Arc::default();
        // SAFETY: loading the system's Vulkan loader.
        let entry = unsafe { ash::Entry::load() }.expect("Vulkan is required (set DOF_SKIP_VULKAN=1 to skip on purpose)");
        // SAFETY: plain enumeration.
        let layers = unsafe { entry.enumerate_instance_layer_properties() }.expect("vkEnumerateInstanceLayerProperties");
        assert!(
            layers.iter().any(|l| l.layer_name_as_c_str() == Ok(VALIDATION_LAYER)),
            "the Khronos validation layer is required: apt-get install vulkan-validationlayers (or DOF_SKIP_VULKAN=1)"
        );
        let app = vk::ApplicationInfo::default().application_name(c"renderer").api_version(VulkanBackend::REQUIRED_API_VERSION);
        let layer_names = [VALIDATION_LAYER.as_ptr()];
        let extensions = [vk::EXT_DEBUG_UTILS_NAME.as_ptr(), vk::EXT_VALIDATION_FEATURES_NAME.as_ptr()];
        let sync = [vk::ValidationFeatureEnableEXT::SYNCHRONIZATION_VALIDATION];
        let mut features = vk::ValidationFeaturesEXT::default().enabled_validation_features(&sync);
        let mut chained = messenger_info(&log);
        let info = vk::InstanceCreateInfo::default()
            .application_info(&app)
            .enabled_layer_names(&layer_names)
            .enabled_extension_names(&extensions)
            .push_next(&mut features)
            .push_next(&mut chained);
        // SAFETY: the create info points at live locals.
        let instance = unsafe { entry.create_instance(&info, None) }.expect("vkCreateInstance");
        let debug = ash::ext::debug_utils::Instance::new(&entry, &instance);
        // SAFETY: the log outlives the messenger (the renderer holds it).
        let messenger = unsafe { debug.create_debug_utils_messenger(&messenger_info(&log), None) }.expect("messenger");

        // lavapipe where there is one (the CI device), else the first device.
        // SAFETY: queries on the live instance.
        let physical = unsafe {
            let all = instance.enumerate_physical_devices().expect("vkEnumeratePhysicalDevices");
            let name = |&pd: &vk::PhysicalDevice| {
                instance
                    .get_physical_device_properties(pd)
                    .device_name_as_c_str()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default()
            };
            all.iter().copied().find(|pd| name(pd).contains("llvmpipe")).or(all.first().copied()).expect("a Vulkan device")
        };
        // SAFETY: as above.
        let families = unsafe { instance.get_physical_device_queue_family_properties(physical) };
        let wanted = vk::QueueFlags::GRAPHICS | vk::QueueFlags::COMPUTE;
        let queue_family = families
            .iter()
            .position(|f| f.queue_flags.contains(wanted) && f.timestamp_valid_bits > 0)
            .expect("a graphics and compute queue with timestamps") as u32;

        // The device the backend needs, made by the renderer.
        let priorities = [1.0];
        let queues = [vk::DeviceQueueCreateInfo::default().queue_family_index(queue_family).queue_priorities(&priorities)];
        let extensions: Vec<*const c_char> = VulkanBackend::required_device_extensions().iter().map(|e| e.as_ptr()).collect();
        let mut required = VulkanBackend::required_features();
        let info = vk::DeviceCreateInfo::default()
            .queue_create_infos(&queues)
            .enabled_extension_names(&extensions)
            .enabled_features(&required.core)
            .push_next(&mut required.vulkan12);
        // SAFETY: the physical device is the instance's; the info points at live locals.
        let device = unsafe { instance.create_device(physical, &info, None) }.expect("vkCreateDevice");
        // SAFETY: the family was created with one queue; plain creation calls on the live device.
        let (queue, pool, cb, fence) = unsafe {
            let queue = device.get_device_queue(queue_family, 0);
            let pool_info = vk::CommandPoolCreateInfo::default()
                .queue_family_index(queue_family)
                .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER);
            let pool = device.create_command_pool(&pool_info, None).expect("vkCreateCommandPool");
            let alloc =
                vk::CommandBufferAllocateInfo::default().command_pool(pool).level(vk::CommandBufferLevel::PRIMARY).command_buffer_count(1);
            let cb = device.allocate_command_buffers(&alloc).expect("vkAllocateCommandBuffers")[0];
            let fence = device.create_fence(&vk::FenceCreateInfo::default(), None).expect("vkCreateFence");
            (queue, pool, cb, fence)
        };
        Renderer {
            log,
            entry,
            instance,
            debug,
            messenger,
            physical,
            device,
            queue_family,
            queue,
            pool,
            cb,
            fence,
            buffers: Vec::new(),
            images: Vec::new(),
        }
    }

    fn raw(&self) -> RawDevice {
        RawDevice {
            entry: self.entry.clone(),
            instance: self.instance.clone(),
            physical_device: self.physical,
            device: self.device.clone(),
            queue_family: self.queue_family,
            queue: self.queue,
        }
    }

    fn memory_type(&self, bits: u32, flags: vk::MemoryPropertyFlags) -> u32 {
        // SAFETY: a query on the live instance.
        let props = unsafe { self.instance.get_physical_device_memory_properties(self.physical) };
        (0..props.memory_type_count)
            .find(|&i| bits & (1 << i) != 0 && props.memory_types[i as usize].property_flags.contains(flags))
            .expect("a memory type")
    }

    /// A buffer with plain vkAllocateMemory: device-local, or host-visible and mapped.
    fn buffer(&mut self, bytes: u64, usage: vk::BufferUsageFlags, host: bool) -> OwnBuffer {
        let d = &self.device;
        // SAFETY: creation calls on the live device; everything is destroyed in `finish`.
        unsafe {
            let buffer = d.create_buffer(&vk::BufferCreateInfo::default().size(bytes).usage(usage), None).expect("vkCreateBuffer");
            let req = d.get_buffer_memory_requirements(buffer);
            let flags = if host {
                vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT
            } else {
                vk::MemoryPropertyFlags::DEVICE_LOCAL
            };
            let info = vk::MemoryAllocateInfo::default()
                .allocation_size(req.size)
                .memory_type_index(self.memory_type(req.memory_type_bits, flags));
            let memory = d.allocate_memory(&info, None).expect("vkAllocateMemory");
            d.bind_buffer_memory(buffer, memory, 0).expect("vkBindBufferMemory");
            let mapped = if host {
                d.map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty()).expect("vkMapMemory") as *mut u8
            } else {
                std::ptr::null_mut()
            };
            let b = OwnBuffer { buffer, memory, bytes, mapped };
            self.buffers.push(b);
            b
        }
    }

    fn image(&mut self, format: vk::Format, usage: vk::ImageUsageFlags) -> vk::Image {
        let d = &self.device;
        let info = vk::ImageCreateInfo::default()
            .image_type(vk::ImageType::TYPE_2D)
            .format(format)
            .extent(vk::Extent3D { width: WIDTH, height: HEIGHT, depth: 1 })
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .tiling(vk::ImageTiling::OPTIMAL)
            .usage(usage)
            .initial_layout(vk::ImageLayout::UNDEFINED);
        // SAFETY: creation calls on the live device; destroyed in `finish`.
        unsafe {
            let image = d.create_image(&info, None).expect("vkCreateImage");
            let req = d.get_image_memory_requirements(image);
            let alloc = vk::MemoryAllocateInfo::default()
                .allocation_size(req.size)
                .memory_type_index(self.memory_type(req.memory_type_bits, vk::MemoryPropertyFlags::DEVICE_LOCAL));
            let memory = d.allocate_memory(&alloc, None).expect("vkAllocateMemory");
            d.bind_image_memory(image, memory, 0).expect("vkBindImageMemory");
            self.images.push((image, memory));
            image
        }
    }

    fn write(b: &OwnBuffer, words: &[u32]) {
        assert!(words.len() as u64 * 4 <= b.bytes && !b.mapped.is_null());
        // SAFETY: the mapping covers the buffer; the GPU is not using it (every submission is waited for).
        unsafe { std::ptr::copy_nonoverlapping(words.as_ptr() as *const u8, b.mapped, words.len() * 4) };
    }

    fn read(b: &OwnBuffer, offset_words: usize, words: usize) -> Vec<u32> {
        assert!(((offset_words + words) * 4) as u64 <= b.bytes && !b.mapped.is_null());
        let mut out = vec![0u32; words];
        // SAFETY: as in `write`; the copy's writes were made available to the host and the fence waited.
        unsafe { std::ptr::copy_nonoverlapping(b.mapped.add(offset_words * 4), out.as_mut_ptr() as *mut u8, words * 4) };
        out
    }

    /// Begins the renderer's command buffer (after its last submission completed).
    fn begin(&self) {
        // SAFETY: the command buffer is not pending (every submission is waited for).
        unsafe {
            self.device.reset_command_buffer(self.cb, vk::CommandBufferResetFlags::empty()).expect("reset");
            let begin = vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
            self.device.begin_command_buffer(self.cb, &begin).expect("vkBeginCommandBuffer");
        }
    }

    /// Ends, submits with the renderer's own fence, and waits.
    fn submit_and_wait(&self) {
        let cbs = [self.cb];
        let submit = [vk::SubmitInfo::default().command_buffers(&cbs)];
        // SAFETY: the command buffer is recorded; the fence is unsignalled.
        unsafe {
            self.device.end_command_buffer(self.cb).expect("vkEndCommandBuffer");
            self.device.queue_submit(self.queue, &submit, self.fence).expect("vkQueueSubmit");
            self.device.wait_for_fences(&[self.fence], true, u64::MAX).expect("vkWaitForFences");
            self.device.reset_fences(&[self.fence]).expect("vkResetFences");
        }
    }

    fn barrier(&self, src: vk::PipelineStageFlags, src_access: vk::AccessFlags, dst: vk::PipelineStageFlags, dst_access: vk::AccessFlags) {
        let memory = [vk::MemoryBarrier::default().src_access_mask(src_access).dst_access_mask(dst_access)];
        // SAFETY: the command buffer is recording.
        unsafe { self.device.cmd_pipeline_barrier(self.cb, src, dst, vk::DependencyFlags::empty(), &memory, &[], &[]) };
    }

    #[allow(clippy::too_many_arguments)]
    fn image_barrier(
        &self,
        image: vk::Image,
        old: vk::ImageLayout,
        new: vk::ImageLayout,
        src: vk::PipelineStageFlags,
        src_access: vk::AccessFlags,
        dst: vk::PipelineStageFlags,
        dst_access: vk::AccessFlags,
    ) {
        let b = [vk::ImageMemoryBarrier::default()
            .image(image)
            .old_layout(old)
            .new_layout(new)
            .src_access_mask(src_access)
            .dst_access_mask(dst_access)
            .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .subresource_range(
                vk::ImageSubresourceRange::default().aspect_mask(vk::ImageAspectFlags::COLOR).level_count(1).layer_count(1),
            )];
        // SAFETY: the command buffer is recording; the image is live.
        unsafe { self.device.cmd_pipeline_barrier(self.cb, src, dst, vk::DependencyFlags::empty(), &[], &[], &b) };
    }

    fn copy(&self, src: &OwnBuffer, dst: &OwnBuffer, bytes: u64) {
        // SAFETY: the command buffer is recording; both buffers hold `bytes`.
        unsafe { self.device.cmd_copy_buffer(self.cb, src.buffer, dst.buffer, &[vk::BufferCopy::default().size(bytes)]) };
    }

    fn image_region() -> [vk::BufferImageCopy; 1] {
        [vk::BufferImageCopy::default()
            .image_subresource(vk::ImageSubresourceLayers::default().aspect_mask(vk::ImageAspectFlags::COLOR).layer_count(1))
            .image_extent(vk::Extent3D { width: WIDTH, height: HEIGHT, depth: 1 })]
    }

    fn messages(&self) -> Vec<String> {
        std::mem::take(&mut *self.log.lock().unwrap_or_else(|e| e.into_inner()))
    }

    /// Destroys everything the renderer made (the backend must be gone already) and returns the
    /// messages the layer reported meanwhile: objects of the device never destroyed are reported at
    /// vkDestroyDevice.
    fn finish(self) -> Vec<String> {
        // SAFETY: the device is idle (every submission was waited for) and nothing is used any more.
        unsafe {
            let d = &self.device;
            d.device_wait_idle().expect("vkDeviceWaitIdle");
            for b in &self.buffers {
                d.destroy_buffer(b.buffer, None);
                d.free_memory(b.memory, None);
            }
            for &(image, memory) in &self.images {
                d.destroy_image(image, None);
                d.free_memory(memory, None);
            }
            d.destroy_fence(self.fence, None);
            d.destroy_command_pool(self.pool, None);
            d.destroy_device(None);
            self.debug.destroy_debug_utils_messenger(self.messenger, None);
            self.instance.destroy_instance(None);
        }
        std::mem::take(&mut *self.log.lock().unwrap_or_else(|e| e.into_inner()))
    }
}

fn assert_no_messages(messages: Vec<String>, when: &str) {
    assert!(messages.is_empty(), "validation layer reported {} message(s) {when}:\n{}", messages.len(), messages.join("\n"));
}

/// A sort input with lists of every class and one long enough for the global path.
fn sort_input() -> SortInput {
    let mut rng = Pcg64::seed_from_u64(31);
    lists_with(&[0, 1, 7, 64, 300, 1000, 2048, 4097, 9000, 33], |_, _| random_key(&mut rng))
}

#[test]
fn records_into_the_callers_command_buffer_on_the_callers_device() {
    if skip_requested() {
        return;
    }
    let mut r = Renderer::new();
    let storage = vk::BufferUsageFlags::STORAGE_BUFFER | vk::BufferUsageFlags::TRANSFER_SRC | vk::BufferUsageFlags::TRANSFER_DST;

    // The renderer's data: an RGBA32F image's pixels and a sort problem, in its own buffers.
    let mut rng = Pcg64::seed_from_u64(30);
    // Small words, so the prefix sums stay far from overflowing.
    let pixel_words: Vec<u32> = (0..4 * WIDTH * HEIGHT).map(|_| rng.random_range(0..4096u32)).collect();
    let input = sort_input();
    let n = input.keys.len();
    let key_bits: Vec<u32> = input.keys.iter().map(|k| k.to_bits()).collect();
    let seg_words: Vec<u32> = input.segments.iter().flat_map(|&(o, l)| [o, l]).collect();
    let bytes = |words: usize| words as u64 * 4;

    let pixels_staging = r.buffer(bytes(pixel_words.len()), vk::BufferUsageFlags::TRANSFER_SRC, true);
    let upload = r.buffer(bytes(2 * n + seg_words.len()), vk::BufferUsageFlags::TRANSFER_SRC, true);
    let readback = r.buffer(bytes(pixel_words.len() + 2 * n + 64), vk::BufferUsageFlags::TRANSFER_DST, true);
    let flags = r.buffer(bytes(64), storage, false);
    let segments = r.buffer(bytes(seg_words.len()), storage, false);
    let keys_in = r.buffer(bytes(n), storage, false);
    let values_in = r.buffer(bytes(n), storage, false);
    let keys_out = r.buffer(bytes(n), storage, false);
    let values_out = r.buffer(bytes(n), storage, false);
    let image = r.image(
        vk::Format::R32G32B32A32_SFLOAT,
        vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST | vk::ImageUsageFlags::SAMPLED,
    );

    // Uploads through the renderer's own staging, its own submission.
    Renderer::write(&pixels_staging, &pixel_words);
    Renderer::write(&upload, &[key_bits.as_slice(), &input.values, &seg_words].concat());
    r.begin();
    // SAFETY: the command buffer is recording; regions lie inside the buffers.
    unsafe {
        let d = &r.device;
        d.cmd_copy_buffer(r.cb, upload.buffer, keys_in.buffer, &[vk::BufferCopy::default().size(bytes(n))]);
        d.cmd_copy_buffer(r.cb, upload.buffer, values_in.buffer, &[vk::BufferCopy::default().src_offset(bytes(n)).size(bytes(n))]);
        let segs = vk::BufferCopy::default().src_offset(bytes(2 * n)).size(bytes(seg_words.len()));
        d.cmd_copy_buffer(r.cb, upload.buffer, segments.buffer, &[segs]);
    }
    r.submit_and_wait();

    // The backend on the renderer's device.
    // SAFETY: the handles are live and outlive the backend; the device enables what the backend
    // requires; the backend is dropped before the renderer destroys anything, after its work completed.
    let mut vk = unsafe { VulkanBackend::from_raw(r.raw(), &RawOptions::default()) }.expect("from_raw");
    assert!(vk.take_diagnostics().is_empty(), "the caller owns the messenger");
    let import = |vk: &mut VulkanBackend, b: &OwnBuffer, label: &str| -> BufferId {
        // SAFETY: a live storage buffer of the device with transfer usage, alive until the backend is dropped.
        unsafe { vk.import_buffer(b.buffer, b.bytes, label) }.expect("import_buffer")
    };
    let (segments_id, keys_in_id, values_in_id) =
        (import(&mut vk, &segments, "segments"), import(&mut vk, &keys_in, "keys"), import(&mut vk, &values_in, "values"));
    let (keys_out_id, values_out_id) = (import(&mut vk, &keys_out, "keys-out"), import(&mut vk, &values_out, "values-out"));
    let flags_id = import(&mut vk, &flags, "flags");
    assert_eq!(vk.buffer_words(keys_in_id).unwrap(), n as u64);
    let after_imports = vk.counters();
    assert_eq!(after_imports, BackendCounters::default(), "imports allocate nothing");

    // What the backend needs of its own, created once before the frames.
    let words = pixel_words.len() as u64;
    let pixels = vk.create_buffer(words, "pixels").expect("create_buffer");
    let scan = ScanScratch::new(&mut vk, words).expect("scan scratch");
    let sort = SegmentedSort::new(&mut vk, input.segments.len() as u32, n as u32, input.max_list_len()).expect("sort");
    let created = vk.counters();
    assert!(created.allocations >= 4 && created.submissions == 0 && created.device_bytes >= bytes(words as usize));

    let mut cpu = CpuBackend::with_shared_bytes(vk.limits().max_shared_bytes);
    let (want_pixels, want_total) = exclusive_scan(&mut cpu, &pixel_words).expect("CPU scan");
    let want_sort = sort_on(&mut cpu, &input).expect("CPU sort");
    let (ref_keys, ref_values) = input.reference();
    let bits = |k: &[f32]| k.iter().map(|k| k.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&want_sort.keys), bits(&ref_keys));
    assert_eq!(want_sort.values, ref_values);

    for frame in 0..2 {
        r.begin();
        // The renderer's pass before: every earlier frame's work is done with what it rewrites; the
        // image gets fresh pixels and the sort outputs start as copies of the inputs.
        r.barrier(
            vk::PipelineStageFlags::ALL_COMMANDS,
            vk::AccessFlags::MEMORY_WRITE,
            vk::PipelineStageFlags::TRANSFER,
            vk::AccessFlags::TRANSFER_READ | vk::AccessFlags::TRANSFER_WRITE,
        );
        r.image_barrier(
            image,
            vk::ImageLayout::UNDEFINED,
            vk::ImageLayout::TRANSFER_DST_OPTIMAL,
            vk::PipelineStageFlags::TRANSFER,
            vk::AccessFlags::empty(),
            vk::PipelineStageFlags::TRANSFER,
            vk::AccessFlags::TRANSFER_WRITE,
        );
        // SAFETY: the command buffer is recording; the image is in TRANSFER_DST_OPTIMAL.
        unsafe {
            r.device.cmd_copy_buffer_to_image(
                r.cb,
                pixels_staging.buffer,
                image,
                vk::ImageLayout::TRANSFER_DST_OPTIMAL,
                &Renderer::image_region(),
            )
        };
        r.copy(&keys_in, &keys_out, bytes(n));
        r.copy(&values_in, &values_out, bytes(n));
        // SAFETY: the command buffer is recording; the buffer holds 64 words.
        unsafe { r.device.cmd_fill_buffer(r.cb, flags.buffer, 0, bytes(64), 1) };

        // The backend's part, recorded into the renderer's command buffer.
        let before = vk.counters();
        // SAFETY: the renderer's command buffer is recording, outside a render pass, from a pool of the
        // backend's queue family; the renderer records nothing until end_external.
        unsafe { vk.begin_external(r.cb) }.expect("begin_external");
        let began = vk.counters();
        // The first frame submits the zeroing of the buffers created above (documented); later ones nothing.
        assert_eq!(began.since(&before).submissions, if frame == 0 { 1 } else { 0 }, "frame {frame}");
        // SAFETY: the renderer's live RGBA32F image, TRANSFER_SRC|DST usage, WIDTHxHEIGHT, in the declared layout.
        let written = unsafe {
            ImageRef::vulkan(
                image,
                ImageFormat::Rgba32Float,
                [WIDTH, HEIGHT],
                vk::ImageLayout::TRANSFER_DST_OPTIMAL,
                vk::PipelineStageFlags::TRANSFER,
                vk::AccessFlags::TRANSFER_WRITE,
                vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
            )
        };
        // First: a fill over the renderer's fill (ordered by the barrier opening the recording).
        vk.fill(flags_id, 0, 32, 5, "flags").expect("fill");
        vk.copy_image_to_buffer(written, pixels, 0, "image-in").expect("copy_image_to_buffer");
        scan.record(&mut vk, pixels, 0, words).expect("scan");
        sort.record(&mut vk, segments_id, input.segments.len() as u32, keys_in_id, values_in_id, keys_out_id, values_out_id).expect("sort");
        // The backend left the image in SHADER_READ_ONLY_OPTIMAL; nothing of the renderer's touched it since.
        // SAFETY: as above.
        let left = unsafe {
            ImageRef::vulkan(
                image,
                ImageFormat::Rgba32Float,
                [WIDTH, HEIGHT],
                vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
                vk::PipelineStageFlags::empty(),
                vk::AccessFlags::empty(),
                vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
            )
        };
        vk.copy_buffer_to_image(pixels, 0, left, "image-out").expect("copy_buffer_to_image");
        vk.end_external().expect("end_external");
        let during = vk.counters().since(&began);
        assert_eq!(
            (during.submissions, during.readbacks, during.uploads, during.allocations),
            (0, 0, 0, 0),
            "frame {frame}: the external recording submitted, transferred or allocated: {during:?}"
        );
        assert_eq!(during.device_bytes, created.device_bytes);

        // The renderer's pass after: the image and the sort outputs into its host-visible buffer.
        // SAFETY: the command buffer is recording; the image is in TRANSFER_SRC_OPTIMAL, and the
        // backend's closing barrier made its writes visible to transfers.
        unsafe {
            let d = &r.device;
            d.cmd_copy_image_to_buffer(r.cb, image, vk::ImageLayout::TRANSFER_SRC_OPTIMAL, readback.buffer, &Renderer::image_region());
            let at = bytes(pixel_words.len());
            d.cmd_copy_buffer(r.cb, keys_out.buffer, readback.buffer, &[vk::BufferCopy::default().dst_offset(at).size(bytes(n))]);
            d.cmd_copy_buffer(
                r.cb,
                values_out.buffer,
                readback.buffer,
                &[vk::BufferCopy::default().dst_offset(at + bytes(n)).size(bytes(n))],
            );
            let flags_at = vk::BufferCopy::default().dst_offset(at + bytes(2 * n)).size(bytes(64));
            d.cmd_copy_buffer(r.cb, flags.buffer, readback.buffer, &[flags_at]);
        }
        r.barrier(
            vk::PipelineStageFlags::TRANSFER,
            vk::AccessFlags::TRANSFER_WRITE,
            vk::PipelineStageFlags::HOST,
            vk::AccessFlags::HOST_READ,
        );
        r.submit_and_wait();

        let times = vk.take_external_times().expect("take_external_times").expect("the work completed, so its times are there");
        let labels: Vec<&str> = times.iter().map(|t| t.label.as_str()).collect();
        assert_eq!(labels[..2], ["flags", "image-in"]);
        assert_eq!(labels.last(), Some(&"image-out"));
        assert!(labels.contains(&"scan/block") && labels.contains(&"sort/classify") && labels.contains(&"sort/global-store"), "{labels:?}");
        assert!(times.iter().all(|t| t.ms.is_finite() && t.ms >= 0.0), "{times:?}");
        assert_eq!(vk.take_external_times().unwrap().map(|t| t.len()), Some(0), "times are taken once");

        let got_pixels = Renderer::read(&readback, 0, pixel_words.len());
        assert_eq!(got_pixels, want_pixels, "frame {frame}: the scanned image differs from the CPU backend's");
        let got_keys = Renderer::read(&readback, pixel_words.len(), n);
        let got_values = Renderer::read(&readback, pixel_words.len() + n, n);
        assert_eq!(got_keys, bits(&want_sort.keys), "frame {frame}: sorted keys differ from the CPU backend's");
        assert_eq!(got_values, want_sort.values, "frame {frame}: sorted payloads differ from the CPU backend's");
        let got_flags = Renderer::read(&readback, pixel_words.len() + 2 * n, 64);
        assert_eq!(got_flags, [[5; 32], [1; 32]].concat(), "frame {frame}: the backend's fill and the renderer's");
        assert_no_messages(r.messages(), &format!("in frame {frame}"));
    }

    // Outside a recording the backend reads its own buffers (through the renderer's queue).
    let (total_buffer, total_offset) = scan.total(words);
    assert_eq!(vk.read_buffer(total_buffer, total_offset, 1).unwrap(), vec![want_total]);

    // Imports are only forgotten; the backend's own buffers are freed with it.
    for id in [segments_id, keys_in_id, values_in_id, keys_out_id, values_out_id, flags_id] {
        vk.destroy_buffer(id);
    }
    assert!(vk.buffer_words(keys_in_id).is_err());
    scan.destroy(&mut vk);
    drop(vk);
    assert_no_messages(r.messages(), "while the backend was dropped");
    assert_no_messages(r.finish(), "when the renderer destroyed its device and instance (a leak of the backend's would show here)");
}

#[test]
fn refuses_what_would_submit_or_allocate_inside_the_callers_recording() {
    if skip_requested() {
        return;
    }
    let mut r = Renderer::new();
    let storage = vk::BufferUsageFlags::STORAGE_BUFFER | vk::BufferUsageFlags::TRANSFER_SRC | vk::BufferUsageFlags::TRANSFER_DST;
    let own = r.buffer(64, storage, false);
    let image = r.image(vk::Format::R32_SFLOAT, vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST);

    // The renderer's own gpu-allocator serves the backend too.
    let allocator = gpu_allocator::vulkan::Allocator::new(&gpu_allocator::vulkan::AllocatorCreateDesc {
        instance: r.instance.clone(),
        device: r.device.clone(),
        physical_device: r.physical,
        debug_settings: Default::default(),
        buffer_device_address: false,
        allocation_sizes: Default::default(),
    })
    .expect("allocator");
    let shared = Arc::new(Mutex::new(allocator));
    let opts = RawOptions { debug_names: true, allocator: Some(shared.clone()) };
    // SAFETY: as in the test above; the allocator was made for this device.
    let mut vk = unsafe { VulkanBackend::from_raw(r.raw(), &opts) }.expect("from_raw");
    drop(opts);
    // SAFETY: a live storage buffer of 64 bytes.
    assert!(unsafe { vk.import_buffer(own.buffer, 62, "odd") }.is_err(), "bytes must be whole words");
    // SAFETY: as above.
    let imported = unsafe { vk.import_buffer(own.buffer, own.bytes, "own") }.expect("import");
    let mine = vk.create_buffer(16, "mine").expect("create_buffer");
    let spare = vk.create_buffer(16, "spare").expect("create_buffer");
    // Outside a recording, imported buffers read and write like any other.
    vk.write_buffer(imported, 0, &[5, 6, 7, 8]).expect("write into an imported buffer");
    assert_eq!(vk.read_buffer(imported, 1, 3).unwrap(), vec![6, 7, 8]);

    // A frame recorded outside begin_external would go into the backend's own command buffer and
    // run at its next submission, after the renderer may have changed what it reads: refused, with
    // nothing recorded. Making the context (its one-time zeroing) may submit.
    let mut ctx = GatherContext::new(&mut vk, &GatherContextDesc::new(4, 4, 1)).expect("a context on the renderer's device");
    let bufs = [16u64, 4, 12].map(|w| vk.create_buffer(w, "frame").expect("create_buffer"));
    let before = vk.counters();
    let outside = ctx.record(&mut vk, &Frame::layers(4, 4, 1, dof::stress::test_lens(0.01), bufs[0], bufs[1], bufs[2]));
    assert!(matches!(&outside, Err(dof::Error::InvalidArgument(m)) if m.contains("begin_external")), "{outside:?}");
    assert_eq!(vk.counters(), before, "the refused frame recorded nothing");
    assert!(vk.submit().unwrap().is_empty(), "nothing was left recorded");
    ctx.destroy(&mut vk);
    bufs.into_iter().for_each(|id| vk.destroy_buffer(id));

    assert!(vk.end_external().is_err(), "end without begin");
    r.begin();
    // SAFETY: the renderer's command buffer is recording, outside a render pass.
    unsafe { vk.begin_external(r.cb) }.expect("begin_external");
    assert!(vk.is_external());
    // SAFETY: as above.
    assert!(unsafe { vk.begin_external(r.cb) }.is_err(), "nested begin");
    vk.fill(imported, 0, 16, 3, "fill").expect("fill");
    vk.fill(mine, 0, 16, 4, "fill").expect("fill");
    // SAFETY: the renderer's R32F image, TRANSFER_DST usage, WIDTHxHEIGHT (discarded: UNDEFINED).
    let target = unsafe {
        ImageRef::vulkan(
            image,
            ImageFormat::R32Float,
            [WIDTH, HEIGHT],
            vk::ImageLayout::UNDEFINED,
            vk::PipelineStageFlags::empty(),
            vk::AccessFlags::empty(),
            vk::ImageLayout::GENERAL,
        )
    };
    // The buffer is too small for the image: refused before recording.
    assert!(vk.copy_buffer_to_image(mine, 0, target, "too small").is_err());
    // SAFETY: as above.
    let undefined_source = unsafe {
        ImageRef::vulkan(
            image,
            ImageFormat::R32Float,
            [WIDTH, HEIGHT],
            vk::ImageLayout::UNDEFINED,
            vk::PipelineStageFlags::empty(),
            vk::AccessFlags::empty(),
            vk::ImageLayout::GENERAL,
        )
    };
    assert!(vk.copy_image_to_buffer(undefined_source, mine, 0, "undefined").is_err(), "nothing defined to copy");
    let before = vk.counters();
    assert!(vk.submit().is_err());
    assert!(vk.read_buffer(mine, 0, 1).is_err());
    assert!(vk.write_buffer(mine, 0, &[1]).is_err());
    assert!(vk.create_buffer(4, "late").is_err());
    assert_eq!(vk.counters(), before, "refused calls count nothing");
    let held = vk.counters().device_bytes;
    vk.destroy_buffer(mine); // used by the recording: its id goes now, its memory once the recording completed
    vk.destroy_buffer(spare); // not used: freed
    assert!(vk.buffer_words(mine).is_err() && vk.buffer_words(spare).is_err());
    assert_eq!(vk.counters().device_bytes, held - 64, "only the unused buffer's bytes are back");
    vk.end_external().expect("end_external");
    assert!(!vk.is_external());
    assert_eq!(vk.release_finished().unwrap(), 0, "not submitted yet: nothing freed");
    r.submit_and_wait();
    assert_eq!(vk.release_finished().unwrap(), 64, "freed once the command buffer completed");
    assert_eq!(vk.counters().device_bytes, held - 128);
    assert_eq!(vk.read_buffer(imported, 0, 16).unwrap(), vec![3; 16]);
    assert_eq!(vk.take_external_times().unwrap().map(|t| t.len()), Some(2));
    assert_eq!(vk.take_external_times().unwrap().map(|t| t.len()), Some(0), "taken once");

    // Two recordings in one submission keep their own times, taken oldest first.
    r.begin();
    for fills in [1u64, 3] {
        // SAFETY: the renderer's command buffer is recording, outside a render pass.
        unsafe { vk.begin_external(r.cb) }.expect("begin_external");
        for i in 0..fills {
            vk.fill(imported, i, 1, 9, "per-recording").expect("fill");
        }
        vk.end_external().expect("end_external");
    }
    r.submit_and_wait();
    assert_eq!(vk.take_external_times().unwrap().map(|t| t.len()), Some(1), "the first recording's times");
    assert_eq!(vk.take_external_times().unwrap().map(|t| t.len()), Some(3), "the second recording's times");
    assert_eq!(vk.take_external_times().unwrap().map(|t| t.len()), Some(0));

    // The CPU backend copies only its own stand-in images.
    let mut cpu = CpuBackend::new();
    let b = cpu.create_buffer(4 * WIDTH as u64 * HEIGHT as u64, "b").unwrap();
    assert!(matches!(cpu.copy_image_to_buffer(target, b, 0, "x"), Err(dof::Error::InvalidArgument(_))));
    assert!(matches!(cpu.copy_buffer_to_image(b, 0, target, "x"), Err(dof::Error::InvalidArgument(_))));

    drop(vk);
    // The renderer's allocator, which the backend no longer holds, goes before its device.
    assert_eq!(Arc::strong_count(&shared), 1);
    drop(shared);
    assert_no_messages(r.messages(), "");
    assert_no_messages(r.finish(), "when the renderer destroyed its device and instance");
}

/// The renderer's messenger is live and sync validation on: two fills of one buffer in its command
/// buffer with no barrier between them are reported (so the empty logs above mean something).
#[test]
fn the_renderers_messenger_reports_hazards() {
    if skip_requested() {
        return;
    }
    let mut r = Renderer::new();
    let b = r.buffer(64, vk::BufferUsageFlags::TRANSFER_DST, false);
    r.begin();
    // SAFETY: the command buffer is recording; the missing barrier is the point.
    unsafe {
        r.device.cmd_fill_buffer(r.cb, b.buffer, 0, 64, 1);
        r.device.cmd_fill_buffer(r.cb, b.buffer, 0, 64, 2);
    }
    r.submit_and_wait();
    let messages = r.messages();
    assert!(messages.iter().any(|m| m.contains("SYNC-HAZARD-WRITE-AFTER-WRITE")), "{messages:?}");
    assert_no_messages(r.finish(), "after the hazard");
}
