//! A small renderer of the tests' own, for suites that hand the library a caller's device,
//! images and command buffer: its own instance with the validation layer (synchronization
//! validation on) and a debug messenger collecting every warning and error, its own device with the
//! backend's required extensions and features, images of any format filled through its own
//! staging, and one command buffer and fence. Everything it makes it destroys in [`Renderer::finish`].

use dof::backend::vulkan::ash::{self, vk};
use dof::backend::{ImageFormat, RawDevice, VulkanBackend};
use std::ffi::{CStr, c_char, c_void};
use std::sync::{Arc, Mutex};

const VALIDATION_LAYER: &CStr = c"VK_LAYER_KHRONOS_validation";

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
    // SAFETY: the layer passes valid data for the call; `user` is the renderer's log, which
    // outlives the instance.
    let (data, log) = unsafe { (&*data, &*(user as *const Mutex<Vec<String>>)) };
    let text = |p: *const c_char| if p.is_null() { String::new() } else { unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned() };
    log.lock().unwrap_or_else(|e| e.into_inner()).push(format!(
        "[{severity:?}] {}: {}",
        text(data.p_message_id_name),
        text(data.p_message)
    ));
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

/// A buffer of the renderer's with its memory: device-local, or host-visible and mapped.
#[derive(Clone, Copy)]
pub struct OwnBuffer {
    pub buffer: vk::Buffer,
    memory: vk::DeviceMemory,
    pub bytes: u64,
    /// Null for a device-local buffer.
    mapped: *mut u8,
}

pub struct Renderer {
    log: Log,
    entry: ash::Entry,
    pub instance: ash::Instance,
    debug: ash::ext::debug_utils::Instance,
    messenger: vk::DebugUtilsMessengerEXT,
    pub physical: vk::PhysicalDevice,
    pub device: ash::Device,
    queue_family: u32,
    queue: vk::Queue,
    pool: vk::CommandPool,
    pub cb: vk::CommandBuffer,
    fence: vk::Fence,
    buffers: Vec<OwnBuffer>,
    images: Vec<(vk::Image, vk::DeviceMemory)>,
    /// Render passes, framebuffers and views of the depth passes, destroyed in `finish`.
    passes: Vec<(vk::RenderPass, vk::Framebuffer, vk::ImageView)>,
    /// Views a frame samples images through, destroyed in `finish`.
    views: Vec<vk::ImageView>,
}

impl Renderer {
    /// The renderer on lavapipe where there is one (the CI device), else the first device; `None`
    /// where `DOF_SKIP_VULKAN=1` asks to skip Vulkan suites.
    pub fn new() -> Option<Renderer> {
        if std::env::var_os("DOF_SKIP_VULKAN").is_some_and(|v| v == "1") {
            eprintln!("DOF_SKIP_VULKAN=1: skipping a Vulkan test on purpose");
            return None;
        }
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
        let instance = unsafe { entry.create_instance(&info, None) }.expect("vkCreateInstance (with the Khronos validation layer)");
        let debug = ash::ext::debug_utils::Instance::new(&entry, &instance);
        // SAFETY: the log outlives the messenger (the renderer holds it).
        let messenger = unsafe { debug.create_debug_utils_messenger(&messenger_info(&log), None) }.expect("messenger");
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
        let queue_family =
            families.iter().position(|f| f.queue_flags.contains(wanted) && f.timestamp_valid_bits > 0).expect("a graphics queue") as u32;
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
        // SAFETY: plain creation calls on the live device.
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
        Some(Renderer {
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
            views: Vec::new(),
            passes: Vec::new(),
        })
    }

    pub fn raw(&self) -> RawDevice {
        RawDevice {
            entry: self.entry.clone(),
            instance: self.instance.clone(),
            physical_device: self.physical,
            device: self.device.clone(),
            queue_family: self.queue_family,
            queue: self.queue,
        }
    }

    /// What the device can do with optimally tiled images of `format`.
    pub fn format_features(&self, format: vk::Format) -> vk::FormatFeatureFlags {
        // SAFETY: a query on the live instance.
        unsafe { self.instance.get_physical_device_format_properties(self.physical, format) }.optimal_tiling_features
    }

    fn memory_type(&self, bits: u32, flags: vk::MemoryPropertyFlags) -> u32 {
        // SAFETY: a query on the live instance.
        let props = unsafe { self.instance.get_physical_device_memory_properties(self.physical) };
        (0..props.memory_type_count)
            .find(|&i| bits & (1 << i) != 0 && props.memory_types[i as usize].property_flags.contains(flags))
            .expect("a memory type")
    }

    /// A host-visible, mapped buffer for transfers.
    pub fn host_buffer(&mut self, bytes: u64) -> OwnBuffer {
        self.buffer(bytes, vk::BufferUsageFlags::TRANSFER_SRC | vk::BufferUsageFlags::TRANSFER_DST, true)
    }

    /// A buffer with plain vkAllocateMemory: device-local, or host-visible and mapped.
    pub fn buffer(&mut self, bytes: u64, usage: vk::BufferUsageFlags, host: bool) -> OwnBuffer {
        let d = &self.device;
        // SAFETY: creation calls on the live device; destroyed in `finish`.
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

    /// Writes words into a host buffer (no submission of the renderer's may be running on it).
    pub fn write(b: &OwnBuffer, words: &[u32]) {
        assert!(words.len() as u64 * 4 <= b.bytes && !b.mapped.is_null());
        // SAFETY: the mapping covers the buffer; the GPU is not using it (every submission is waited for).
        unsafe { std::ptr::copy_nonoverlapping(words.as_ptr() as *const u8, b.mapped, words.len() * 4) };
    }

    /// Reads words from a host buffer (after the submission that wrote it was waited for).
    pub fn read(b: &OwnBuffer, offset_words: usize, words: usize) -> Vec<u32> {
        assert!(((offset_words + words) * 4) as u64 <= b.bytes && !b.mapped.is_null());
        let mut out = vec![0u32; words];
        // SAFETY: as in `write`; the copy's writes were made available to the host and the fence waited.
        unsafe { std::ptr::copy_nonoverlapping(b.mapped.add(offset_words * 4), out.as_mut_ptr() as *mut u8, words * 4) };
        out
    }

    /// An optimally tiled 2D image of `format` with transfer and sampled usage (an attachment's
    /// usage too where the format has it, as a renderer's would).
    pub fn image(&mut self, format: ImageFormat, extent: [u32; 2]) -> vk::Image {
        // An attachment's usage where the format has it.
        let features = self.format_features(format.vk_format());
        let attachment = if format.is_depth() && features.contains(vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT) {
            vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT
        } else if !format.is_depth() && features.contains(vk::FormatFeatureFlags::COLOR_ATTACHMENT) {
            vk::ImageUsageFlags::COLOR_ATTACHMENT
        } else {
            vk::ImageUsageFlags::empty()
        };
        let usage = vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST | vk::ImageUsageFlags::SAMPLED | attachment;
        self.raw_image(format.vk_format(), extent, usage)
    }

    /// A view a frame samples `image` through (`ImageDesc::sampled_through`): 2D, mip 0, layer 0,
    /// the depth aspect alone for a depth format.
    pub fn sampled_view(&mut self, image: vk::Image, format: ImageFormat) -> vk::ImageView {
        let aspect = if format.is_depth() { vk::ImageAspectFlags::DEPTH } else { vk::ImageAspectFlags::COLOR };
        let info = vk::ImageViewCreateInfo::default()
            .image(image)
            .view_type(vk::ImageViewType::TYPE_2D)
            .format(format.vk_format())
            .subresource_range(vk::ImageSubresourceRange::default().aspect_mask(aspect).level_count(1).layer_count(1));
        // SAFETY: a live image of this format with SAMPLED usage; destroyed in `finish`.
        let view = unsafe { self.device.create_image_view(&info, None) }.expect("vkCreateImageView");
        self.views.push(view);
        view
    }

    /// An optimally tiled, device-local 2D image of any Vulkan format and usage.
    pub fn raw_image(&mut self, format: vk::Format, extent: [u32; 2], usage: vk::ImageUsageFlags) -> vk::Image {
        let info = vk::ImageCreateInfo::default()
            .image_type(vk::ImageType::TYPE_2D)
            .format(format)
            .extent(vk::Extent3D { width: extent[0], height: extent[1], depth: 1 })
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .tiling(vk::ImageTiling::OPTIMAL)
            .usage(usage)
            .initial_layout(vk::ImageLayout::UNDEFINED);
        let d = &self.device;
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

    /// Records into the renderer's command buffer the upload of `staging` (texels packed as the
    /// library's copies pack them) into the whole of `image`, through its depth aspect for a depth
    /// format, leaving it in `layout` after `stage`/`access` (as a renderer's pass would).
    #[allow(clippy::too_many_arguments)]
    pub fn upload_image(
        &self,
        staging: &OwnBuffer,
        image: vk::Image,
        format: ImageFormat,
        extent: [u32; 2],
        layout: vk::ImageLayout,
        stage: vk::PipelineStageFlags,
        access: vk::AccessFlags,
    ) {
        let range = vk::ImageSubresourceRange::default().aspect_mask(format.layout_aspects()).level_count(1).layer_count(1);
        let barrier = |old, new, src_access, dst_access| {
            [vk::ImageMemoryBarrier::default()
                .image(image)
                .old_layout(old)
                .new_layout(new)
                .src_access_mask(src_access)
                .dst_access_mask(dst_access)
                .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
                .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
                .subresource_range(range)]
        };
        let region = [vk::BufferImageCopy::default()
            .image_subresource(vk::ImageSubresourceLayers::default().aspect_mask(format.copy_aspect()).layer_count(1))
            .image_extent(vk::Extent3D { width: extent[0], height: extent[1], depth: 1 })];
        let to_dst = barrier(
            vk::ImageLayout::UNDEFINED,
            vk::ImageLayout::TRANSFER_DST_OPTIMAL,
            vk::AccessFlags::empty(),
            vk::AccessFlags::TRANSFER_WRITE,
        );
        let to_final = barrier(vk::ImageLayout::TRANSFER_DST_OPTIMAL, layout, vk::AccessFlags::TRANSFER_WRITE, access);
        let d = &self.device;
        // SAFETY: the command buffer is recording, outside a render pass; image and buffer are live.
        unsafe {
            let none = vk::DependencyFlags::empty();
            d.cmd_pipeline_barrier(self.cb, vk::PipelineStageFlags::TOP_OF_PIPE, vk::PipelineStageFlags::TRANSFER, none, &[], &[], &to_dst);
            d.cmd_copy_buffer_to_image(self.cb, staging.buffer, image, vk::ImageLayout::TRANSFER_DST_OPTIMAL, &region);
            d.cmd_pipeline_barrier(self.cb, vk::PipelineStageFlags::TRANSFER, stage, none, &[], &[], &to_final);
        }
    }

    /// Records a render pass whose only attachment is the depth image `image` (a depth format),
    /// cleared to `depth` and stored: a depth-attachment write at the fragment-test stages, as a
    /// renderer's depth prepass makes. It leaves the image in DEPTH_STENCIL_ATTACHMENT_OPTIMAL and
    /// records no barrier after it.
    pub fn depth_pass(&mut self, image: vk::Image, format: ImageFormat, extent: [u32; 2], depth: f32) {
        let d = &self.device;
        let attachment = [vk::AttachmentDescription::default()
            .format(format.vk_format())
            .samples(vk::SampleCountFlags::TYPE_1)
            .load_op(vk::AttachmentLoadOp::CLEAR)
            .store_op(vk::AttachmentStoreOp::STORE)
            .stencil_load_op(vk::AttachmentLoadOp::CLEAR)
            .stencil_store_op(vk::AttachmentStoreOp::STORE)
            .initial_layout(vk::ImageLayout::UNDEFINED)
            .final_layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL)];
        let depth_ref = vk::AttachmentReference::default().attachment(0).layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
        let subpass =
            [vk::SubpassDescription::default().pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS).depth_stencil_attachment(&depth_ref)];
        let range = vk::ImageSubresourceRange::default().aspect_mask(vk::ImageAspectFlags::DEPTH).level_count(1).layer_count(1);
        let view_info = vk::ImageViewCreateInfo::default()
            .image(image)
            .view_type(vk::ImageViewType::TYPE_2D)
            .format(format.vk_format())
            .subresource_range(range);
        // SAFETY: creation and recording calls on the live device; the command buffer is recording
        // outside a render pass; everything made is destroyed in `finish`, after the device idles.
        unsafe {
            let pass = d
                .create_render_pass(&vk::RenderPassCreateInfo::default().attachments(&attachment).subpasses(&subpass), None)
                .expect("vkCreateRenderPass");
            let view = d.create_image_view(&view_info, None).expect("vkCreateImageView");
            let views = [view];
            let fb_info =
                vk::FramebufferCreateInfo::default().render_pass(pass).attachments(&views).width(extent[0]).height(extent[1]).layers(1);
            let framebuffer = d.create_framebuffer(&fb_info, None).expect("vkCreateFramebuffer");
            let clear = [vk::ClearValue { depth_stencil: vk::ClearDepthStencilValue { depth, stencil: 0 } }];
            let begin = vk::RenderPassBeginInfo::default()
                .render_pass(pass)
                .framebuffer(framebuffer)
                .render_area(vk::Rect2D { offset: vk::Offset2D::default(), extent: vk::Extent2D { width: extent[0], height: extent[1] } })
                .clear_values(&clear);
            d.cmd_begin_render_pass(self.cb, &begin, vk::SubpassContents::INLINE);
            d.cmd_end_render_pass(self.cb);
            self.passes.push((pass, framebuffer, view));
        }
    }

    /// A global memory barrier in the renderer's command buffer.
    pub fn barrier(
        &self,
        src: vk::PipelineStageFlags,
        src_access: vk::AccessFlags,
        dst: vk::PipelineStageFlags,
        dst_access: vk::AccessFlags,
    ) {
        let memory = [vk::MemoryBarrier::default().src_access_mask(src_access).dst_access_mask(dst_access)];
        // SAFETY: the command buffer is recording.
        unsafe { self.device.cmd_pipeline_barrier(self.cb, src, dst, vk::DependencyFlags::empty(), &memory, &[], &[]) };
    }

    /// A layout transition of a colour image's whole subresource, with its memory dependency.
    #[allow(clippy::too_many_arguments)]
    pub fn image_barrier(
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

    /// Copies the first `bytes` of `src` into `dst` in the renderer's command buffer.
    pub fn copy(&self, src: &OwnBuffer, dst: &OwnBuffer, bytes: u64) {
        // SAFETY: the command buffer is recording; both buffers hold `bytes`.
        unsafe { self.device.cmd_copy_buffer(self.cb, src.buffer, dst.buffer, &[vk::BufferCopy::default().size(bytes)]) };
    }

    /// Begins the renderer's command buffer (after its last submission completed).
    pub fn begin(&self) {
        // SAFETY: the command buffer is not pending (every submission is waited for).
        unsafe {
            self.device.reset_command_buffer(self.cb, vk::CommandBufferResetFlags::empty()).expect("reset");
            let begin = vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
            self.device.begin_command_buffer(self.cb, &begin).expect("vkBeginCommandBuffer");
        }
    }

    /// Ends, submits with the renderer's own fence, and waits.
    pub fn submit_and_wait(&self) {
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

    /// The layer's messages so far, emptying the log.
    pub fn messages(&self) -> Vec<String> {
        std::mem::take(&mut *self.log.lock().unwrap_or_else(|e| e.into_inner()))
    }

    /// Destroys everything the renderer made (the backend must be gone) and returns the messages
    /// the layer reported meanwhile (objects never destroyed show up at vkDestroyDevice).
    pub fn finish(self) -> Vec<String> {
        // SAFETY: the device is idle after the wait and nothing is used any more.
        unsafe {
            let d = &self.device;
            d.device_wait_idle().expect("vkDeviceWaitIdle");
            for b in &self.buffers {
                d.destroy_buffer(b.buffer, None);
                d.free_memory(b.memory, None);
            }
            for &(pass, framebuffer, view) in &self.passes {
                d.destroy_framebuffer(framebuffer, None);
                d.destroy_image_view(view, None);
                d.destroy_render_pass(pass, None);
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
            self.debug.destroy_debug_utils_messenger(self.messenger, None);
            self.instance.destroy_instance(None);
        }
        std::mem::take(&mut *self.log.lock().unwrap_or_else(|e| e.into_inner()))
    }
}

/// Fails if the layer reported anything.
pub fn assert_no_messages(messages: Vec<String>, when: &str) {
    assert!(messages.is_empty(), "validation layer reported {} message(s) {when}:\n{}", messages.len(), messages.join("\n"));
}
