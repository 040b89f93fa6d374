//! The viewer's own Vulkan instance, device, queue, command buffer and fence, made the way an
//! integrator makes them (as `host/examples/ash_host.rs` does): with the extensions and features
//! `VulkanBackend` asks for, plus what a window needs (surface and swapchain extensions).

use anyhow::{Context, Result, bail};
use dof::backend::VulkanBackend;
use dof::backend::vulkan::ash::{self, vk};
use raw_window_handle::RawDisplayHandle;
use std::ffi::{CStr, c_char, c_void};
use std::sync::{Arc, Mutex};

/// Warnings and errors of the validation layer, collected by the debug messenger.
pub type Log = Mutex<Vec<String>>;

unsafe extern "system" fn collect(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    log: *mut c_void,
) -> vk::Bool32 {
    // SAFETY: the layer passes valid data for the call's duration; `log` is the `Log` the `Device`
    // keeps alive until after the instance is destroyed.
    let (data, log) = unsafe { (&*data, &*(log as *const Log)) };
    let text = |p: *const c_char| if p.is_null() { String::new() } else { unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned() };
    let message = format!("[{severity:?}] {}: {}", text(data.p_message_id_name), text(data.p_message));
    eprintln!("validation: {message}");
    log.lock().unwrap_or_else(|e| e.into_inner()).push(message);
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

pub struct Device {
    pub entry: ash::Entry,
    pub instance: ash::Instance,
    messenger: Option<(ash::ext::debug_utils::Instance, vk::DebugUtilsMessengerEXT)>,
    pub log: Arc<Log>,
    pub physical: vk::PhysicalDevice,
    pub device: ash::Device,
    pub queue_family: u32,
    pub queue: vk::Queue,
    pub pool: vk::CommandPool,
    pub cb: vk::CommandBuffer,
    /// Signalled when the frame's submission completes: the one host wait per frame.
    pub fence: vk::Fence,
}

impl Device {
    /// The instance (with the surface extensions `display` needs) and the instance-level loaders.
    pub fn instance(
        display: RawDisplayHandle,
        validation: bool,
    ) -> Result<(ash::Entry, ash::Instance, Option<(ash::ext::debug_utils::Instance, vk::DebugUtilsMessengerEXT)>, Arc<Log>)> {
        let log: Arc<Log> = Arc::default();
        // SAFETY: loading the system's Vulkan loader; the create infos point at live locals.
        unsafe {
            let entry = ash::Entry::load().context("no Vulkan loader (install a Vulkan driver, e.g. mesa-vulkan-drivers)")?;
            let app = vk::ApplicationInfo::default().application_name(c"dof view").api_version(VulkanBackend::REQUIRED_API_VERSION);
            let mut extensions: Vec<*const c_char> =
                ash_window::enumerate_required_extensions(display).context("this display has no Vulkan surface support")?.to_vec();
            let layers = [c"VK_LAYER_KHRONOS_validation".as_ptr()];
            let sync = [vk::ValidationFeatureEnableEXT::SYNCHRONIZATION_VALIDATION];
            let mut features = vk::ValidationFeaturesEXT::default().enabled_validation_features(&sync);
            let mut chained = messenger_info(&log);
            if validation {
                extensions.extend([vk::EXT_DEBUG_UTILS_NAME.as_ptr(), vk::EXT_VALIDATION_FEATURES_NAME.as_ptr()]);
            }
            let mut info = vk::InstanceCreateInfo::default().application_info(&app).enabled_extension_names(&extensions);
            if validation {
                // Chained, the messenger also sees what instance creation and destruction report
                // (objects left alive at vkDestroyInstance: leaks).
                info = info.enabled_layer_names(&layers).push_next(&mut features).push_next(&mut chained);
            }
            let instance = entry
                .create_instance(&info, None)
                .context("vkCreateInstance (with --validation: is vulkan-validationlayers installed?)")?;
            let messenger = if validation {
                let debug = ash::ext::debug_utils::Instance::new(&entry, &instance);
                let messenger = debug.create_debug_utils_messenger(&messenger_info(&log), None)?;
                Some((debug, messenger))
            } else {
                None
            };
            Ok((entry, instance, messenger, log))
        }
    }

    /// Picks a device that can present to `surface` with a graphics and compute queue and the
    /// library's extensions (`name` filters by device name), and makes it.
    pub fn new(
        (entry, instance, messenger, log): (
            ash::Entry,
            ash::Instance,
            Option<(ash::ext::debug_utils::Instance, vk::DebugUtilsMessengerEXT)>,
            Arc<Log>,
        ),
        surface_fn: &ash::khr::surface::Instance,
        surface: vk::SurfaceKHR,
        name: Option<&str>,
    ) -> Result<Device> {
        // SAFETY: queries and creation on the live instance; everything is destroyed in `destroy`.
        unsafe {
            let mut wanted: Vec<&CStr> = VulkanBackend::required_device_extensions().to_vec();
            wanted.push(ash::khr::swapchain::NAME);
            let mut chosen = None;
            for pd in instance.enumerate_physical_devices()? {
                let props = instance.get_physical_device_properties(pd);
                let device_name = props.device_name_as_c_str().unwrap_or_default().to_string_lossy().into_owned();
                let have = instance.enumerate_device_extension_properties(pd)?;
                let supported = wanted.iter().all(|w| have.iter().any(|h| h.extension_name_as_c_str() == Ok(*w)));
                let families = instance.get_physical_device_queue_family_properties(pd);
                let family = (0..families.len() as u32).find(|&i| {
                    families[i as usize].queue_flags.contains(vk::QueueFlags::GRAPHICS | vk::QueueFlags::COMPUTE)
                        && surface_fn.get_physical_device_surface_support(pd, i, surface).unwrap_or(false)
                });
                let named = name.is_none_or(|n| device_name.to_lowercase().contains(&n.to_lowercase()));
                if let (true, true, true, Some(family)) =
                    (named, supported, props.api_version >= VulkanBackend::REQUIRED_API_VERSION, family)
                {
                    chosen = Some((pd, family, device_name));
                    break;
                }
            }
            let (physical, queue_family, _name) = chosen.context(
                "no Vulkan 1.2 device that presents to this window with the extensions the library needs (--device filters by name)",
            )?;
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
            // Created signalled: the first frame's wait returns at once.
            let fence = device.create_fence(&vk::FenceCreateInfo::default().flags(vk::FenceCreateFlags::SIGNALED), None)?;
            Ok(Device { entry, instance, messenger, log, physical, device, queue_family, queue, pool, cb, fence })
        }
    }

    /// Device memory of a type with `flags` for `req`.
    pub fn memory(&self, req: vk::MemoryRequirements, flags: vk::MemoryPropertyFlags) -> Result<vk::DeviceMemory> {
        // SAFETY: a query on the live instance and an allocation of a type it reported.
        unsafe {
            let props = self.instance.get_physical_device_memory_properties(self.physical);
            let index = (0..props.memory_type_count)
                .find(|&i| req.memory_type_bits & (1 << i) != 0 && props.memory_types[i as usize].property_flags.contains(flags))
                .context("no suitable memory type")?;
            let info = vk::MemoryAllocateInfo::default().allocation_size(req.size).memory_type_index(index);
            Ok(self.device.allocate_memory(&info, None)?)
        }
    }

    /// A layout transition of `image` after `src` (stages, accesses) and before `dst`.
    pub fn image_barrier(&self, image: vk::Image, old: vk::ImageLayout, new: vk::ImageLayout, src: Scope, dst: Scope) {
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

    pub fn memory_barrier(&self, src: Scope, dst: Scope) {
        let barrier = [vk::MemoryBarrier::default().src_access_mask(src.1).dst_access_mask(dst.1)];
        // SAFETY: the command buffer is recording, outside a render pass.
        unsafe { self.device.cmd_pipeline_barrier(self.cb, src.0, dst.0, vk::DependencyFlags::empty(), &barrier, &[], &[]) };
    }

    /// The validation messages so far (taken).
    pub fn take_messages(&self) -> Vec<String> {
        std::mem::take(&mut *self.log.lock().unwrap_or_else(|e| e.into_inner()))
    }

    /// Destroys the device's objects, the device, then (after the caller's surface) the instance.
    /// Every other object of the device must be gone and the device idle.
    pub fn destroy(self, surface: Option<(&ash::khr::surface::Instance, vk::SurfaceKHR)>) {
        // SAFETY: nothing is in use any more; each object is destroyed once, children first.
        unsafe {
            let d = &self.device;
            d.device_wait_idle().ok();
            d.destroy_fence(self.fence, None);
            d.destroy_command_pool(self.pool, None);
            d.destroy_device(None);
            if let Some((surface_fn, surface)) = surface {
                surface_fn.destroy_surface(surface, None);
            }
            if let Some((debug, messenger)) = &self.messenger {
                debug.destroy_debug_utils_messenger(*messenger, None);
            }
            self.instance.destroy_instance(None);
        }
    }
}

/// A synchronisation scope: pipeline stages and memory accesses.
pub type Scope = (vk::PipelineStageFlags, vk::AccessFlags);
pub const TRANSFER: vk::PipelineStageFlags = vk::PipelineStageFlags::TRANSFER;

/// An image or buffer with its own memory; `mapped` is set for host-visible buffers.
pub struct Owned<T> {
    pub handle: T,
    pub memory: vk::DeviceMemory,
    pub mapped: *mut u8,
    pub bytes: u64,
}

impl Device {
    /// A buffer in host-visible coherent memory, mapped (read-backs).
    pub fn host_buffer(&self, bytes: u64, usage: vk::BufferUsageFlags) -> Result<Owned<vk::Buffer>> {
        use vk::MemoryPropertyFlags as M;
        // SAFETY: creation on the live device; destroyed with `destroy_buffer`.
        unsafe {
            let buffer = self.device.create_buffer(&vk::BufferCreateInfo::default().size(bytes).usage(usage), None)?;
            let memory = self.memory(self.device.get_buffer_memory_requirements(buffer), M::HOST_VISIBLE | M::HOST_COHERENT)?;
            self.device.bind_buffer_memory(buffer, memory, 0)?;
            let mapped = self.device.map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())? as *mut u8;
            Ok(Owned { handle: buffer, memory, mapped, bytes })
        }
    }

    pub fn destroy_buffer(&self, b: Owned<vk::Buffer>) {
        // SAFETY: the buffer is no longer in use (the caller waited for its fence).
        unsafe {
            self.device.destroy_buffer(b.handle, None);
            self.device.free_memory(b.memory, None);
        }
    }

    /// A 2D device-local image, optimal tiling, initially UNDEFINED.
    pub fn image(&self, format: vk::Format, extent: [u32; 2], usage: vk::ImageUsageFlags) -> Result<Owned<vk::Image>> {
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
        // SAFETY: creation on the live device; destroyed with `destroy_image`.
        unsafe {
            let image = self.device.create_image(&info, None)?;
            let req = self.device.get_image_memory_requirements(image);
            let memory = self.memory(req, vk::MemoryPropertyFlags::DEVICE_LOCAL)?;
            self.device.bind_image_memory(image, memory, 0)?;
            Ok(Owned { handle: image, memory, mapped: std::ptr::null_mut(), bytes: req.size })
        }
    }

    pub fn destroy_image(&self, i: Owned<vk::Image>) {
        // SAFETY: the image is no longer in use (the caller waited for its fence).
        unsafe {
            self.device.destroy_image(i.handle, None);
            self.device.free_memory(i.memory, None);
        }
    }
}

/// What a window of `window` pixels needs of the device: the swapchain image, the frames the
/// contexts are made for (`frame` pixels: the window and the guard band beyond it, `layers`
/// fragment slots a pixel) as the largest single buffer and a lower bound of the memory the viewer
/// and a context hold, and the output image. `flags` names what set the size, for the error.
pub struct Fit<'a> {
    pub flags: &'a str,
    pub window: [u32; 2],
    pub frame: [u32; 2],
    pub layers: u32,
}

impl Device {
    /// Refuses sizes the device cannot hold, before anything is made for them.
    pub fn check_fits(
        &self,
        surface_fn: &ash::khr::surface::Instance,
        surface: vk::SurfaceKHR,
        limits: &dof::backend::Limits,
        fit: &Fit,
    ) -> Result<()> {
        // SAFETY: queries on the live instance, physical device and surface.
        let (caps, props, memory) = unsafe {
            (
                surface_fn.get_physical_device_surface_capabilities(self.physical, surface)?,
                self.instance.get_physical_device_properties(self.physical),
                self.instance.get_physical_device_memory_properties(self.physical),
            )
        };
        let name = props.device_name_as_c_str().unwrap_or_default().to_string_lossy().into_owned();
        let Fit { flags, window: [ww, wh], frame: [fw, fh], layers } = *fit;
        let edge = props.limits.max_image_dimension2_d;
        let (mw, mh) = (caps.max_image_extent.width.min(edge), caps.max_image_extent.height.min(edge));
        if ww > mw || wh > mh {
            bail!("{flags}: a window of {ww}x{wh} pixels is larger than the largest swapchain image {name} makes for it, {mw}x{mh}");
        }
        if fw > edge || fh > edge {
            bail!(
                "{flags}: frames of {fw}x{fh} pixels (the window and the guard band beyond it) exceed the largest image edge of {name}, {edge} pixels"
            );
        }
        let gb = |b: u64| b as f64 / 1e9;
        let pixels = fw as u64 * fh as u64;
        // Fragment slots (`dof_shaders::slot`): the viewer's input and each context's largest buffer.
        let slots = 4 * dof::methods::buffers::SLOT_WORDS as u64 * pixels * layers as u64;
        if slots > limits.max_buffer_bytes {
            bail!(
                "{flags}: frames of {fw}x{fh} pixels (the window and the guard band beyond it) with {layers} layers need buffers of {:.2} GB; \
                 the largest buffer {name} holds is {:.2} GB",
                gb(slots),
                gb(limits.max_buffer_bytes)
            );
        }
        // At least: the input and a context's copy of it, the output image, the result and its
        // display form.
        let least = 2 * slots + (16 + 12 + 16) * pixels;
        let heap = memory.memory_heaps[..memory.memory_heap_count as usize]
            .iter()
            .filter(|h| h.flags.contains(vk::MemoryHeapFlags::DEVICE_LOCAL))
            .map(|h| h.size)
            .max()
            .unwrap_or(u64::MAX);
        if least > heap {
            bail!(
                "{flags}: frames of {fw}x{fh} pixels with {layers} layers need more than {:.2} GB of device memory; {name} has {:.2} GB",
                gb(least),
                gb(heap)
            );
        }
        Ok(())
    }
}
