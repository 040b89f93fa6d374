//! Loading Vulkan, the instance (with the validation layer and its message log when asked for),
//! describing and choosing a physical device, and the logical device.

use super::DeviceInfo;
use super::spirv::{ModuleInfo, cap};
use crate::backend::Limits;
use crate::error::{Error, Result, VkContext};
use ash::vk;
use std::ffi::{CStr, c_char, c_void};
use std::sync::{Arc, Mutex};

const VALIDATION_LAYER: &CStr = c"VK_LAYER_KHRONOS_validation";
/// Environment variable naming the device when `VulkanOptions::device` is `None`.
pub const DEVICE_ENV: &str = "DOF_VULKAN_DEVICE";

/// Messages the validation layer reported, shared with the debug callback.
pub(super) type MessageLog = Arc<Mutex<Vec<String>>>;

/// The device extensions the backend uses (the caller's device must enable them, see
/// `VulkanBackend::from_raw`).
pub(super) const REQUIRED_EXTENSIONS: [&CStr; 1] = [vk::KHR_PUSH_DESCRIPTOR_NAME];

/// The loader, the instance and (with validation) the debug messenger. Dropping an instance the
/// backend made destroys the messenger and the instance; the log outlives both because it is a field
/// dropped after `drop`. A caller's instance (`borrowed`) is left alone.
pub(super) struct InstanceCtx {
    pub entry: ash::Entry,
    pub instance: ash::Instance,
    debug: Option<(ash::ext::debug_utils::Instance, vk::DebugUtilsMessengerEXT)>,
    pub messages: MessageLog,
    /// Whether the backend created the instance (and destroys it).
    owned: bool,
}

impl InstanceCtx {
    pub fn new(validation: bool) -> Result<Self> {
        // SAFETY: loading the system's Vulkan loader; the library stays loaded as long as `entry`.
        let entry = unsafe { ash::Entry::load() }.map_err(|e| Error::NoVulkan(format!("cannot load the Vulkan loader: {e}")))?;
        let messages: MessageLog = Arc::default();

        let app = vk::ApplicationInfo::default().application_name(c"dof").engine_name(c"dof").api_version(vk::API_VERSION_1_2);
        let mut layers: Vec<*const c_char> = Vec::new();
        let mut extensions: Vec<*const c_char> = Vec::new();
        let sync_validation = [vk::ValidationFeatureEnableEXT::SYNCHRONIZATION_VALIDATION];
        let mut features = vk::ValidationFeaturesEXT::default().enabled_validation_features(&sync_validation);
        let mut messenger_info = messenger_create_info(&messages);

        if validation {
            // SAFETY: plain enumeration calls on a loaded entry.
            let available = unsafe { entry.enumerate_instance_layer_properties() }.vk("vkEnumerateInstanceLayerProperties")?;
            if !available.iter().any(|l| l.layer_name_as_c_str() == Ok(VALIDATION_LAYER)) {
                return Err(Error::NoValidationLayer);
            }
            let mut ext_names = instance_extensions(&entry, None)?;
            ext_names.extend(instance_extensions(&entry, Some(VALIDATION_LAYER))?);
            if !ext_names.iter().any(|e| e.as_c_str() == vk::EXT_DEBUG_UTILS_NAME) {
                return Err(Error::NoVulkan("the validation layer is present but VK_EXT_debug_utils is not".into()));
            }
            layers.push(VALIDATION_LAYER.as_ptr());
            extensions.push(vk::EXT_DEBUG_UTILS_NAME.as_ptr());
            // Chaining VkValidationFeaturesEXT formally needs its extension, which the layer provides.
            if ext_names.iter().any(|e| e.as_c_str() == vk::EXT_VALIDATION_FEATURES_NAME) {
                extensions.push(vk::EXT_VALIDATION_FEATURES_NAME.as_ptr());
            }
        }

        let mut create_info =
            vk::InstanceCreateInfo::default().application_info(&app).enabled_layer_names(&layers).enabled_extension_names(&extensions);
        if validation {
            // The messenger in the chain also catches messages from vkCreateInstance/vkDestroyInstance.
            create_info = create_info.push_next(&mut features).push_next(&mut messenger_info);
        }
        // SAFETY: every pointer in `create_info` refers to locals alive for the call.
        let instance = unsafe { entry.create_instance(&create_info, None) }.map_err(|result| match result {
            vk::Result::ERROR_INCOMPATIBLE_DRIVER => Error::NoVulkan("vkCreateInstance found no driver (ICD) supporting Vulkan 1.2".into()),
            result => Error::Vulkan { call: "vkCreateInstance", result },
        })?;
        let mut ctx = InstanceCtx { entry, instance, debug: None, messages, owned: true };

        if validation {
            let loader = ash::ext::debug_utils::Instance::new(&ctx.entry, &ctx.instance);
            let info = messenger_create_info(&ctx.messages);
            // SAFETY: the user data points into `ctx.messages`, which outlives the messenger.
            let messenger = unsafe { loader.create_debug_utils_messenger(&info, None) }.vk("vkCreateDebugUtilsMessengerEXT")?;
            ctx.debug = Some((loader, messenger));
        }
        Ok(ctx)
    }

    /// The caller's instance: no messenger (the caller owns its own), never destroyed here.
    pub fn borrowed(entry: ash::Entry, instance: ash::Instance) -> Self {
        InstanceCtx { entry, instance, debug: None, messages: Arc::default(), owned: false }
    }

    pub fn validation(&self) -> bool {
        self.debug.is_some()
    }
}

impl Drop for InstanceCtx {
    fn drop(&mut self) {
        if !self.owned {
            return;
        }
        // SAFETY: every child object was destroyed by the owners dropped before this one.
        unsafe {
            if let Some((loader, messenger)) = self.debug.take() {
                loader.destroy_debug_utils_messenger(messenger, None);
            }
            self.instance.destroy_instance(None);
        }
    }
}

fn instance_extensions(entry: &ash::Entry, layer: Option<&CStr>) -> Result<Vec<std::ffi::CString>> {
    // SAFETY: plain enumeration call on a loaded entry.
    let props = unsafe { entry.enumerate_instance_extension_properties(layer) }.vk("vkEnumerateInstanceExtensionProperties")?;
    Ok(props.iter().filter_map(|p| p.extension_name_as_c_str().ok().map(CStr::to_owned)).collect())
}

fn messenger_create_info(log: &MessageLog) -> vk::DebugUtilsMessengerCreateInfoEXT<'static> {
    vk::DebugUtilsMessengerCreateInfoEXT::default()
        .message_severity(vk::DebugUtilsMessageSeverityFlagsEXT::WARNING | vk::DebugUtilsMessageSeverityFlagsEXT::ERROR)
        .message_type(
            vk::DebugUtilsMessageTypeFlagsEXT::GENERAL
                | vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION
                | vk::DebugUtilsMessageTypeFlagsEXT::PERFORMANCE,
        )
        .pfn_user_callback(Some(on_message))
        .user_data(Arc::as_ptr(log) as *mut c_void)
}

/// Records warnings and errors in the backend's log. Must not unwind: it is called from C.
unsafe extern "system" fn on_message(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user: *mut c_void,
) -> vk::Bool32 {
    use vk::DebugUtilsMessageSeverityFlagsEXT as S;
    if user.is_null() || data.is_null() || !severity.intersects(S::WARNING | S::ERROR) {
        return vk::FALSE;
    }
    // SAFETY: the layer passes valid callback data for the duration of the call; `user` is the
    // `Mutex` inside the backend's `Arc`, alive as long as the messenger and the instance.
    let (data, log) = unsafe { (&*data, &*(user as *const Mutex<Vec<String>>)) };
    let text = |p: *const c_char| {
        // SAFETY: non-null strings from the layer are NUL-terminated.
        if p.is_null() { String::new() } else { unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned() }
    };
    let level = if severity.contains(S::ERROR) { "error" } else { "warning" };
    let line = format!("[{level} {types:?}] {}: {}", text(data.p_message_id_name), text(data.p_message));
    log::warn!("vulkan validation: {line}");
    log.lock().unwrap_or_else(|e| e.into_inner()).push(line);
    vk::FALSE
}

/// A physical device with what choosing and opening it needs.
pub(super) struct Candidate {
    pub physical: vk::PhysicalDevice,
    pub info: DeviceInfo,
    pub queue_family: Option<u32>,
    pub timestamp_bits: u32,
    /// The features the module's capabilities need.
    pub features: Features,
    /// Why the device cannot run the kernels, if it cannot.
    pub problem: Option<String>,
    /// Whether it can report its pipelines' statistics (VK_KHR_pipeline_executable_properties
    /// with `pipelineExecutableInfo`): the driver's register and spill counts.
    pub pipeline_statistics: bool,
}

/// Device features to enable, from the capabilities the SPIR-V module declares.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Features {
    pub float64: bool,
    pub int64: bool,
    pub int16: bool,
    pub int8: bool,
    pub memory_model: bool,
    pub memory_model_device_scope: bool,
}

impl Features {
    pub fn needed_by(module: &ModuleInfo) -> Self {
        Features {
            float64: module.has(cap::FLOAT64),
            int64: module.has(cap::INT64),
            int16: module.has(cap::INT16),
            int8: module.has(cap::INT8),
            memory_model: module.has(cap::VULKAN_MEMORY_MODEL),
            memory_model_device_scope: module.has(cap::VULKAN_MEMORY_MODEL_DEVICE_SCOPE),
        }
    }

    /// The core and Vulkan 1.2 feature structs enabling exactly these features (to chain into
    /// `VkDeviceCreateInfo`).
    pub fn structs(&self) -> (vk::PhysicalDeviceFeatures, vk::PhysicalDeviceVulkan12Features<'static>) {
        let core = vk::PhysicalDeviceFeatures::default().shader_float64(self.float64).shader_int64(self.int64).shader_int16(self.int16);
        let v12 = vk::PhysicalDeviceVulkan12Features::default()
            .shader_int8(self.int8)
            .vulkan_memory_model(self.memory_model)
            .vulkan_memory_model_device_scope(self.memory_model_device_scope);
        (core, v12)
    }

    /// The needed features the device lacks, by name.
    fn missing(&self, core: &vk::PhysicalDeviceFeatures, v12: &vk::PhysicalDeviceVulkan12Features) -> Vec<&'static str> {
        [
            (self.float64 && core.shader_float64 == vk::FALSE, "shaderFloat64"),
            (self.int64 && core.shader_int64 == vk::FALSE, "shaderInt64"),
            (self.int16 && core.shader_int16 == vk::FALSE, "shaderInt16"),
            (self.int8 && v12.shader_int8 == vk::FALSE, "shaderInt8"),
            (self.memory_model && v12.vulkan_memory_model == vk::FALSE, "vulkanMemoryModel"),
            (self.memory_model_device_scope && v12.vulkan_memory_model_device_scope == vk::FALSE, "vulkanMemoryModelDeviceScope"),
        ]
        .into_iter()
        .filter_map(|(missing, name)| missing.then_some(name))
        .collect()
    }
}

pub(super) fn candidates(instance: &ash::Instance, module: &ModuleInfo) -> Result<Vec<Candidate>> {
    // SAFETY: plain enumeration call on a live instance.
    let devices = unsafe { instance.enumerate_physical_devices() }.map_err(|result| match result {
        vk::Result::ERROR_INITIALIZATION_FAILED => Error::NoVulkan("the Vulkan loader found no usable driver".into()),
        result => Error::Vulkan { call: "vkEnumeratePhysicalDevices", result },
    })?;
    let features = Features::needed_by(module);
    devices.into_iter().enumerate().map(|(index, pd)| describe(instance, pd, index, features)).collect()
}

pub(super) fn describe(instance: &ash::Instance, pd: vk::PhysicalDevice, index: usize, features: Features) -> Result<Candidate> {
    // SAFETY: queries on a physical device enumerated from this instance; the chained structs are
    // only those the device's API version (or its extensions) defines.
    unsafe {
        let props = instance.get_physical_device_properties(pd);
        let extensions = instance.enumerate_device_extension_properties(pd).vk("vkEnumerateDeviceExtensionProperties")?;
        let has_ext = |name: &CStr| extensions.iter().any(|e| e.extension_name_as_c_str() == Ok(name));
        let api = props.api_version;
        let at_least = |minor| vk::api_version_major(api) > 1 || vk::api_version_minor(api) >= minor;

        let mut subgroup = vk::PhysicalDeviceSubgroupProperties::default();
        let mut maintenance3 = vk::PhysicalDeviceMaintenance3Properties::default();
        let mut driver = vk::PhysicalDeviceDriverProperties::default();
        let has_driver_props = at_least(2) || has_ext(vk::KHR_DRIVER_PROPERTIES_NAME);
        if at_least(1) {
            let mut props2 = vk::PhysicalDeviceProperties2::default().push_next(&mut subgroup).push_next(&mut maintenance3);
            if has_driver_props {
                props2 = props2.push_next(&mut driver);
            }
            instance.get_physical_device_properties2(pd, &mut props2);
        }

        let memory = instance.get_physical_device_memory_properties(pd);
        let largest_local_heap = memory.memory_heaps[..memory.memory_heap_count.min(vk::MAX_MEMORY_HEAPS as u32) as usize]
            .iter()
            .filter(|h| h.flags.contains(vk::MemoryHeapFlags::DEVICE_LOCAL))
            .map(|h| h.size)
            .max()
            .unwrap_or(0);
        let mut max_buffer_bytes = (props.limits.max_storage_buffer_range as u64).min(largest_local_heap);
        if at_least(1) && maintenance3.max_memory_allocation_size > 0 {
            // A buffer larger than one allocation can hold cannot be bound either.
            max_buffer_bytes = max_buffer_bytes.min(maintenance3.max_memory_allocation_size);
        }
        let limits = Limits {
            max_shared_bytes: props.limits.max_compute_shared_memory_size,
            max_workgroup_invocations: props.limits.max_compute_work_group_invocations,
            max_workgroup_count: props.limits.max_compute_work_group_count,
            subgroup_size: (subgroup.subgroup_size > 0).then_some(subgroup.subgroup_size),
            subgroup_kernels: at_least(1)
                && subgroup.supported_stages.contains(vk::ShaderStageFlags::COMPUTE)
                && subgroup.supported_operations.contains(
                    vk::SubgroupFeatureFlags::BASIC | vk::SubgroupFeatureFlags::ARITHMETIC | vk::SubgroupFeatureFlags::SHUFFLE_RELATIVE,
                ),
            max_buffer_bytes,
            serial_invocations: false,
        };

        // A compute queue, preferring one that can write timestamps.
        let families = instance.get_physical_device_queue_family_properties(pd);
        let compute = |f: &vk::QueueFamilyProperties| f.queue_flags.contains(vk::QueueFlags::COMPUTE) && f.queue_count > 0;
        let queue_family = families
            .iter()
            .position(|f| compute(f) && f.timestamp_valid_bits > 0)
            .or_else(|| families.iter().position(compute))
            .map(|i| i as u32);
        let timestamp_bits = queue_family.map_or(0, |i| families[i as usize].timestamp_valid_bits);

        let mut missing = Vec::new();
        let mut pipeline_statistics = false;
        if at_least(2) {
            let mut v12 = vk::PhysicalDeviceVulkan12Features::default();
            let mut executable = vk::PhysicalDevicePipelineExecutablePropertiesFeaturesKHR::default();
            let has_executable = has_ext(vk::KHR_PIPELINE_EXECUTABLE_PROPERTIES_NAME);
            let mut features2 = vk::PhysicalDeviceFeatures2::default().push_next(&mut v12);
            if has_executable {
                features2 = features2.push_next(&mut executable);
            }
            instance.get_physical_device_features2(pd, &mut features2);
            let core = features2.features;
            missing = features.missing(&core, &v12);
            pipeline_statistics = has_executable && executable.pipeline_executable_info == vk::TRUE;
        }

        let problem = if !at_least(2) {
            Some(format!("supports only Vulkan {} (the kernels need 1.2)", version_string(api)))
        } else if queue_family.is_none() {
            Some("has no compute queue".to_string())
        } else if let Some(ext) = REQUIRED_EXTENSIONS.iter().find(|e| !has_ext(e)) {
            Some(format!("lacks the device extension {}", ext.to_string_lossy()))
        } else if !missing.is_empty() {
            Some(format!("lacks features the kernels use: {}", missing.join(", ")))
        } else {
            None
        };

        let name = props.device_name_as_c_str().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        let driver = if has_driver_props {
            let name = driver.driver_name_as_c_str().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
            let info = driver.driver_info_as_c_str().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
            format!("{name} {info}").trim().to_string()
        } else {
            format!("driver version {:#x}", props.driver_version)
        };
        let info = DeviceInfo {
            index,
            name,
            device_type: type_name(props.device_type).to_string(),
            api_version: version_string(api),
            driver,
            limits,
            timestamp_period_ns: props.limits.timestamp_period,
        };
        Ok(Candidate { physical: pd, info, queue_family, timestamp_bits, features, problem, pipeline_statistics })
    }
}

fn version_string(v: u32) -> String {
    format!("{}.{}.{}", vk::api_version_major(v), vk::api_version_minor(v), vk::api_version_patch(v))
}

fn type_name(t: vk::PhysicalDeviceType) -> &'static str {
    match t {
        vk::PhysicalDeviceType::DISCRETE_GPU => "discrete GPU",
        vk::PhysicalDeviceType::INTEGRATED_GPU => "integrated GPU",
        vk::PhysicalDeviceType::VIRTUAL_GPU => "virtual GPU",
        vk::PhysicalDeviceType::CPU => "CPU",
        _ => "other",
    }
}

fn type_rank(t: &str) -> u32 {
    match t {
        "discrete GPU" => 0,
        "integrated GPU" => 1,
        "virtual GPU" => 2,
        "CPU" => 3,
        _ => 4,
    }
}

/// Picks the device `choice` names (a decimal index or a case-insensitive substring of the name),
/// or else the best usable one: discrete > integrated > virtual > CPU.
pub(super) fn select(mut all: Vec<Candidate>, choice: Option<&str>) -> Result<Candidate> {
    if all.is_empty() {
        return Err(Error::NoVulkan("the Vulkan loader reports no physical device".into()));
    }
    let picked = match choice {
        Some(choice) => {
            let lower = choice.to_lowercase();
            let position = match choice.trim().parse::<usize>() {
                Ok(index) => all.iter().position(|c| c.info.index == index),
                Err(_) => all.iter().position(|c| c.info.name.to_lowercase().contains(&lower)),
            };
            let Some(position) = position else {
                // A wrong choice, not a missing driver: name where choices come from.
                return Err(Error::InvalidArgument(format!(
                    "no Vulkan device matches `{choice}` (the device asked for, e.g. by {DEVICE_ENV}); devices: {}; \
                     give an index or part of a name, or unset {DEVICE_ENV} to take the best",
                    all_names(&all)
                )));
            };
            position
        }
        None => {
            let best = all
                .iter()
                .enumerate()
                .filter(|(_, c)| c.problem.is_none())
                .min_by_key(|(_, c)| (type_rank(&c.info.device_type), c.info.index))
                .map(|(i, _)| i);
            let Some(best) = best else {
                let reasons: Vec<String> =
                    all.iter().map(|c| format!("{} ({}) {}", c.info.index, c.info.name, c.problem.as_deref().unwrap_or(""))).collect();
                return Err(Error::NoVulkan(format!("no usable Vulkan device: {}", reasons.join("; "))));
            };
            best
        }
    };
    let candidate = all.swap_remove(picked);
    if let Some(problem) = &candidate.problem {
        return Err(Error::NoVulkan(format!("device {} ({}) {problem}", candidate.info.index, candidate.info.name)));
    }
    Ok(candidate)
}

fn all_names(all: &[Candidate]) -> String {
    all.iter().map(|c| format!("{}: {}", c.info.index, c.info.name)).collect::<Vec<_>>().join(", ")
}

/// The logical device and its queue. Dropping a device the backend made waits for it and destroys
/// it, so every object made from it must be gone first; a caller's device (`borrowed`) is left alone.
pub(super) struct DeviceCtx {
    pub device: ash::Device,
    pub queue: vk::Queue,
    pub queue_family: u32,
    /// Whether the queue family supports graphics (draws, and graphics stages in barriers).
    pub graphics: bool,
    pub push_descriptor: ash::khr::push_descriptor::Device,
    /// Names objects for validation messages, with validation only.
    pub debug_utils: Option<ash::ext::debug_utils::Device>,
    /// Reads pipelines' statistics, where the backend was asked to and the device can
    /// (`VulkanOptions::pipeline_statistics`).
    pub executable_properties: Option<ash::khr::pipeline_executable_properties::Device>,
    /// Whether the backend created the device (and destroys it).
    owned: bool,
}

impl DeviceCtx {
    /// The device of `candidate`; with `pipeline_statistics`, also the extension and feature that
    /// report pipelines' statistics (refused where the device lacks them).
    pub fn new(instance: &InstanceCtx, candidate: &Candidate, pipeline_statistics: bool) -> Result<Self> {
        let family = candidate.queue_family.ok_or_else(|| Error::NoVulkan("the device has no compute queue".into()))?;
        if pipeline_statistics && !candidate.pipeline_statistics {
            return Err(Error::InvalidArgument(format!(
                "pipeline statistics were asked for, but {} does not report them (it lacks VK_KHR_pipeline_executable_properties \
                 with pipelineExecutableInfo)",
                candidate.info.name
            )));
        }
        let priorities = [1.0f32];
        let queues = [vk::DeviceQueueCreateInfo::default().queue_family_index(family).queue_priorities(&priorities)];
        let mut extensions: Vec<*const std::ffi::c_char> = REQUIRED_EXTENSIONS.map(CStr::as_ptr).to_vec();
        if pipeline_statistics {
            extensions.push(vk::KHR_PIPELINE_EXECUTABLE_PROPERTIES_NAME.as_ptr());
        }
        let (core, mut v12) = candidate.features.structs();
        let mut executable = vk::PhysicalDevicePipelineExecutablePropertiesFeaturesKHR::default().pipeline_executable_info(true);
        let mut info = vk::DeviceCreateInfo::default()
            .queue_create_infos(&queues)
            .enabled_extension_names(&extensions)
            .enabled_features(&core)
            .push_next(&mut v12);
        if pipeline_statistics {
            info = info.push_next(&mut executable);
        }
        // SAFETY: the physical device comes from this instance; `info` points at live locals.
        let device = unsafe { instance.instance.create_device(candidate.physical, &info, None) }.vk("vkCreateDevice")?;
        // SAFETY: family `family` was created with one queue.
        let queue = unsafe { device.get_device_queue(family, 0) };
        let push_descriptor = ash::khr::push_descriptor::Device::new(&instance.instance, &device);
        let debug_utils = instance.validation().then(|| ash::ext::debug_utils::Device::new(&instance.instance, &device));
        let graphics = queue_flags(&instance.instance, candidate.physical, family).contains(vk::QueueFlags::GRAPHICS);
        let executable_properties =
            pipeline_statistics.then(|| ash::khr::pipeline_executable_properties::Device::new(&instance.instance, &device));
        Ok(DeviceCtx { device, queue, queue_family: family, graphics, push_descriptor, debug_utils, executable_properties, owned: true })
    }

    /// The caller's device and queue, never destroyed here. `debug_names` names the backend's objects
    /// through VK_EXT_debug_utils (which the caller's instance must have enabled).
    pub fn borrowed(
        instance: &InstanceCtx,
        physical: vk::PhysicalDevice,
        device: ash::Device,
        queue_family: u32,
        queue: vk::Queue,
        debug_names: bool,
    ) -> Self {
        let push_descriptor = ash::khr::push_descriptor::Device::new(&instance.instance, &device);
        let debug_utils = debug_names.then(|| ash::ext::debug_utils::Device::new(&instance.instance, &device));
        let graphics = queue_flags(&instance.instance, physical, queue_family).contains(vk::QueueFlags::GRAPHICS);
        DeviceCtx { device, queue, queue_family, graphics, push_descriptor, debug_utils, executable_properties: None, owned: false }
    }

    /// Whether the device is the caller's (made by [`Self::borrowed`]).
    pub fn is_borrowed(&self) -> bool {
        !self.owned
    }

    /// Whether the backend created the device (and destroys it).
    pub fn owned(&self) -> bool {
        self.owned
    }

    /// Gives `object` a name in validation messages (a no-op without validation).
    pub fn name<H: vk::Handle>(&self, object: H, name: &str) {
        let (Some(utils), Ok(name)) = (&self.debug_utils, std::ffi::CString::new(name)) else { return };
        let info = vk::DebugUtilsObjectNameInfoEXT::default().object_handle(object).object_name(&name);
        // SAFETY: `object` is a live handle of this device; failure only loses a debug name.
        let _ = unsafe { utils.set_debug_utils_object_name(&info) };
    }
}

impl Drop for DeviceCtx {
    fn drop(&mut self) {
        if !self.owned {
            return;
        }
        // SAFETY: the owners of every object made from the device are dropped before this one.
        unsafe {
            let _ = self.device.device_wait_idle();
            self.device.destroy_device(None);
        }
    }
}

/// The capabilities of queue family `family` (empty if there is no such family).
pub(super) fn queue_flags(instance: &ash::Instance, physical: vk::PhysicalDevice, family: u32) -> vk::QueueFlags {
    queue_family(instance, physical, family).map_or(vk::QueueFlags::empty(), |f| f.queue_flags)
}

/// The properties of queue family `family`, if the device has it.
pub(super) fn queue_family(instance: &ash::Instance, physical: vk::PhysicalDevice, family: u32) -> Option<vk::QueueFamilyProperties> {
    // SAFETY: a query on a physical device of this instance.
    let families = unsafe { instance.get_physical_device_queue_family_properties(physical) };
    families.get(family as usize).copied()
}
