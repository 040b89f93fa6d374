//! One compute pipeline per kernel, created on first use from the kernel's own SPIR-V module: the
//! project's (embedded, `crate::shaders::MODULES`) or one a caller added with
//! [`super::VulkanBackend::add_modules`] (its own rust-gpu kernels). Storage buffers, sampled
//! and storage images are bound with push descriptors, so there are no descriptor pools or sets.

use super::spirv;
use crate::error::{Error, Result, VkContext};
use ash::vk;
use dof_shaders::KernelDesc;
use std::collections::HashMap;
use std::ffi::CString;

#[derive(Clone, Copy, Default)]
pub(super) struct Pipeline {
    pub set_layout: vk::DescriptorSetLayout,
    pub layout: vk::PipelineLayout,
    pub pipeline: vk::Pipeline,
}

pub(super) struct Pipelines {
    by_entry: HashMap<&'static str, Pipeline>,
    /// Create pipelines with CAPTURE_STATISTICS_KHR (the device enabled pipeline statistics).
    capture_statistics: bool,
    /// Create a kernel's pipeline from its subgroup variant where it has one.
    subgroups: bool,
    /// The caller's modules (`VulkanBackend::add_modules`): entry -> (words, the entry point's name
    /// inside the module). No entry here is one of the project's.
    added: HashMap<String, (Vec<u32>, String)>,
}

impl Pipelines {
    pub fn new(capture_statistics: bool, subgroups: bool) -> Self {
        Pipelines { by_entry: HashMap::new(), capture_statistics, subgroups, added: HashMap::new() }
    }

    /// Adds a caller's modules, all or none: every entry must be new (neither the project's nor
    /// added before, nor twice in `modules`), every module SPIR-V holding that entry point, and its
    /// capabilities within `enabled` (what the device was created with).
    pub fn add(&mut self, modules: &[(&str, &[u8])], enabled: &spirv::ModuleInfo) -> Result<()> {
        let mut new: HashMap<String, (Vec<u32>, String)> = HashMap::new();
        for &(entry, bytes) in modules {
            let refuse = |why: String| Err(Error::InvalidArgument(format!("add_modules: entry point `{entry}`: {why}")));
            if entry.is_empty() || entry.contains('\0') {
                return refuse("not a valid entry point name".into());
            }
            if spirv::kernel_module(entry).is_some() {
                return refuse("the project's kernels already have an entry point of that name (rename the kernel or its module)".into());
            }
            if self.added.contains_key(entry) || new.contains_key(entry) {
                return refuse("a module of that entry point was already added (entry point names must be unique)".into());
            }
            if bytes.len() % 4 != 0 || bytes.len() < 20 || bytes[..4] != 0x0723_0203u32.to_le_bytes() {
                return refuse(format!("its module ({} bytes) is not little-endian SPIR-V", bytes.len()));
            }
            let words: Vec<u32> = bytes.as_chunks::<4>().0.iter().map(|c| u32::from_le_bytes(*c)).collect();
            let info = spirv::ModuleInfo::parse(&words);
            let Some(name) = info.resolve(entry).map(str::to_string) else {
                return refuse(format!("its module has no such entry point (it has {:?})", info.entry_points));
            };
            let missing: Vec<u32> =
                info.capabilities.iter().copied().filter(|c| spirv::cap::NEEDS_FEATURE.contains(c) && !enabled.has(*c)).collect();
            if !missing.is_empty() {
                return refuse(format!(
                    "its module declares SPIR-V capabilities {missing:?} whose device features the project's kernels do not need, \
                     so the backend's device does not enable them"
                ));
            }
            new.insert(entry.to_string(), (words, name));
        }
        self.added.extend(new);
        Ok(())
    }

    /// The module holding `entry` (a caller's, else the project's) and the entry point's name in it.
    fn module(&self, entry: &str) -> Option<(Vec<u32>, String)> {
        self.added.get(entry).cloned().or_else(|| spirv::kernel_module(entry))
    }

    /// The pipeline of `kernel`, created and cached on first use.
    pub fn get(&mut self, device: &ash::Device, kernel: &'static KernelDesc) -> Result<Pipeline> {
        if let Some(p) = self.by_entry.get(kernel.entry) {
            return Ok(*p);
        }
        let entry = crate::backend::pipeline_entry(kernel, self.subgroups);
        let (words, name) = self.module(entry).ok_or_else(|| {
            Error::InvalidArgument(format!(
                "no SPIR-V module holds the entry point `{entry}` (a kernel of your own needs `VulkanBackend::add_modules`)"
            ))
        })?;
        let p = create(device, kernel, &words, &name, self.capture_statistics)?;
        self.by_entry.insert(kernel.entry, p);
        Ok(p)
    }

    /// Destroys every pipeline. The GPU must be idle.
    pub fn destroy(&mut self, device: &ash::Device) {
        for (_, p) in self.by_entry.drain() {
            destroy(device, &p);
        }
    }
}

fn create(device: &ash::Device, kernel: &KernelDesc, words: &[u32], name: &str, capture_statistics: bool) -> Result<Pipeline> {
    let entry = CString::new(name).map_err(|_| Error::InvalidArgument(format!("kernel entry `{}` contains a NUL byte", kernel.entry)))?;
    let bindings: Vec<_> = (0..kernel.bindings)
        .map(|b| {
            vk::DescriptorSetLayoutBinding::default()
                .binding(b)
                .descriptor_type(if kernel.storage_images & (1 << b) != 0 {
                    vk::DescriptorType::STORAGE_IMAGE
                } else if kernel.images & (1 << b) != 0 {
                    vk::DescriptorType::SAMPLED_IMAGE
                } else {
                    vk::DescriptorType::STORAGE_BUFFER
                })
                .descriptor_count(1)
                .stage_flags(vk::ShaderStageFlags::COMPUTE)
        })
        .collect();
    let set_info =
        vk::DescriptorSetLayoutCreateInfo::default().flags(vk::DescriptorSetLayoutCreateFlags::PUSH_DESCRIPTOR_KHR).bindings(&bindings);
    // Push constant sizes must be multiples of 4; the parameter structs are made of words.
    let push_size = kernel.push_bytes.div_ceil(4) * 4;
    let ranges = [vk::PushConstantRange::default().stage_flags(vk::ShaderStageFlags::COMPUTE).size(push_size)];

    let mut p = Pipeline::default();
    let mut module = vk::ShaderModule::null();
    // SAFETY: create infos point at live locals; on failure whatever was made is destroyed, and the
    // module is not needed once the pipeline exists.
    let result = unsafe {
        (|| -> Result<()> {
            module = device.create_shader_module(&vk::ShaderModuleCreateInfo::default().code(words), None).vk("vkCreateShaderModule")?;
            p.set_layout = device.create_descriptor_set_layout(&set_info, None).vk("vkCreateDescriptorSetLayout")?;
            let set_layouts = [p.set_layout];
            let mut layout_info = vk::PipelineLayoutCreateInfo::default().set_layouts(&set_layouts);
            if push_size > 0 {
                layout_info = layout_info.push_constant_ranges(&ranges);
            }
            p.layout = device.create_pipeline_layout(&layout_info, None).vk("vkCreatePipelineLayout")?;
            let stage = vk::PipelineShaderStageCreateInfo::default().stage(vk::ShaderStageFlags::COMPUTE).module(module).name(&entry);
            let flags = if capture_statistics { vk::PipelineCreateFlags::CAPTURE_STATISTICS_KHR } else { vk::PipelineCreateFlags::empty() };
            let info = [vk::ComputePipelineCreateInfo::default().flags(flags).stage(stage).layout(p.layout)];
            let pipelines = device
                .create_compute_pipelines(vk::PipelineCache::null(), &info, None)
                .map_err(|(_, result)| Error::Vulkan { call: "vkCreateComputePipelines", result })?;
            p.pipeline = pipelines.first().copied().unwrap_or_default();
            Ok(())
        })()
    };
    // SAFETY: the pipeline (if any) no longer needs the module; a null module is ignored.
    unsafe { device.destroy_shader_module(module, None) };
    match result {
        Ok(()) => Ok(p),
        Err(e) => {
            destroy(device, &p);
            Err(e)
        }
    }
}

fn destroy(device: &ash::Device, p: &Pipeline) {
    // SAFETY: the GPU is done with the pipeline; null handles are ignored by vkDestroy*.
    unsafe {
        device.destroy_pipeline(p.pipeline, None);
        device.destroy_pipeline_layout(p.layout, None);
        device.destroy_descriptor_set_layout(p.set_layout, None);
    }
}
