//! Draws through the graphics pipeline (`DrawDesc`): one pipeline per draw from its vertex and
//! fragment modules, and one target per image size: an RGBA32F colour attachment and a D32 depth
//! attachment, both cleared by the render pass. A draw either adds its fragments (blending, no
//! depth test: sprites) or keeps the nearest (reversed depth, `GREATER`, no blending: the
//! rasteriser). After the draw the colour attachment is copied into the caller's storage buffer (4
//! words a pixel), so later kernels read it like any other buffer.

use super::spirv;
use crate::error::{Error, Result, VkContext};
use ash::vk;
use dof_shaders::DrawDesc;
use gpu_allocator::MemoryLocation;
use gpu_allocator::vulkan::{Allocation, AllocationCreateDesc, AllocationScheme, Allocator};
use std::collections::HashMap;
use std::ffi::CString;

pub(super) const FORMAT: vk::Format = vk::Format::R32G32B32A32_SFLOAT;
pub(super) const DEPTH_FORMAT: vk::Format = vk::Format::D32_SFLOAT;

#[derive(Clone, Copy, Default)]
pub(super) struct GraphicsPipeline {
    pub set_layout: vk::DescriptorSetLayout,
    pub layout: vk::PipelineLayout,
    pub render_pass: vk::RenderPass,
    pub pipeline: vk::Pipeline,
}

/// The colour and depth attachments of one size and their framebuffer.
pub(super) struct Target {
    pub size: [u32; 2],
    pub image: vk::Image,
    pub view: vk::ImageView,
    depth: vk::Image,
    depth_view: vk::ImageView,
    pub framebuffer: vk::Framebuffer,
    allocations: Vec<Allocation>,
}

#[derive(Default)]
pub(super) struct Draws {
    pipelines: HashMap<&'static str, GraphicsPipeline>,
    pub target: Option<Target>,
    /// The largest framebuffer, once the device has been checked for draws (format and limits).
    pub max_size: Option<[u32; 2]>,
}

impl Draws {
    pub fn pipeline(&mut self, device: &ash::Device, draw: &'static DrawDesc) -> Result<GraphicsPipeline> {
        if let Some(p) = self.pipelines.get(draw.vertex) {
            return Ok(*p);
        }
        let p = create_pipeline(device, draw)?;
        self.pipelines.insert(draw.vertex, p);
        Ok(p)
    }

    /// Destroys every pipeline and the target. The GPU must be idle.
    pub fn destroy(&mut self, device: &ash::Device, allocator: &mut Allocator) {
        for (_, p) in self.pipelines.drain() {
            destroy_pipeline(device, &p);
        }
        if let Some(t) = self.target.take() {
            t.destroy(device, allocator);
        }
    }
}

impl Target {
    /// A target of `size` for `render_pass`. Whatever is made before a failure is destroyed.
    pub fn new(device: &ash::Device, allocator: &mut Allocator, render_pass: vk::RenderPass, size: [u32; 2]) -> Result<Self> {
        let mut t = Target {
            size,
            image: vk::Image::null(),
            view: vk::ImageView::null(),
            depth: vk::Image::null(),
            depth_view: vk::ImageView::null(),
            framebuffer: vk::Framebuffer::null(),
            allocations: Vec::new(),
        };
        let colour_usage = vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC;
        // SAFETY: create infos on a live device; each handle is stored at once so `destroy` frees it.
        let made = unsafe {
            (|| -> Result<()> {
                (t.image, t.view) = t.attachment(device, allocator, FORMAT, colour_usage, vk::ImageAspectFlags::COLOR)?;
                (t.depth, t.depth_view) = t.attachment(
                    device,
                    allocator,
                    DEPTH_FORMAT,
                    vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
                    vk::ImageAspectFlags::DEPTH,
                )?;
                let views = [t.view, t.depth_view];
                let fb = vk::FramebufferCreateInfo::default()
                    .render_pass(render_pass)
                    .attachments(&views)
                    .width(size[0])
                    .height(size[1])
                    .layers(1);
                t.framebuffer = device.create_framebuffer(&fb, None).vk("vkCreateFramebuffer")?;
                Ok(())
            })()
        };
        match made {
            Ok(()) => Ok(t),
            Err(e) => {
                t.destroy(device, allocator);
                Err(e)
            }
        }
    }

    /// One attachment image with its memory and view. Its allocation joins `self.allocations` (which
    /// `destroy` frees); on a later failure the image itself is destroyed here.
    unsafe fn attachment(
        &mut self,
        device: &ash::Device,
        allocator: &mut Allocator,
        format: vk::Format,
        usage: vk::ImageUsageFlags,
        aspect: vk::ImageAspectFlags,
    ) -> Result<(vk::Image, vk::ImageView)> {
        let info = vk::ImageCreateInfo::default()
            .image_type(vk::ImageType::TYPE_2D)
            .format(format)
            .extent(vk::Extent3D { width: self.size[0], height: self.size[1], depth: 1 })
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .tiling(vk::ImageTiling::OPTIMAL)
            .usage(usage)
            .initial_layout(vk::ImageLayout::UNDEFINED);
        // SAFETY: the caller's device is live; the image is destroyed here if binding fails.
        unsafe {
            let image = device.create_image(&info, None).vk("vkCreateImage")?;
            let requirements = device.get_image_memory_requirements(image);
            let bound = allocator
                .allocate(&AllocationCreateDesc {
                    name: "dof draw target",
                    requirements,
                    location: MemoryLocation::GpuOnly,
                    linear: false,
                    allocation_scheme: AllocationScheme::GpuAllocatorManaged,
                })
                .map_err(|e| Error::Allocation(e.to_string()))
                .and_then(|a| {
                    let r = device.bind_image_memory(image, a.memory(), a.offset()).vk("vkBindImageMemory");
                    self.allocations.push(a);
                    r
                });
            if let Err(e) = bound {
                device.destroy_image(image, None);
                return Err(e);
            }
            let range = vk::ImageSubresourceRange::default().aspect_mask(aspect).level_count(1).layer_count(1);
            let view_info = vk::ImageViewCreateInfo::default()
                .image(image)
                .view_type(vk::ImageViewType::TYPE_2D)
                .format(format)
                .subresource_range(range);
            match device.create_image_view(&view_info, None).vk("vkCreateImageView") {
                Ok(view) => Ok((image, view)),
                Err(e) => {
                    device.destroy_image(image, None);
                    Err(e)
                }
            }
        }
    }

    pub fn destroy(mut self, device: &ash::Device, allocator: &mut Allocator) {
        // SAFETY: the GPU is done with the target; null handles are ignored.
        unsafe {
            device.destroy_framebuffer(self.framebuffer, None);
            device.destroy_image_view(self.view, None);
            device.destroy_image(self.image, None);
            device.destroy_image_view(self.depth_view, None);
            device.destroy_image(self.depth, None);
        }
        for a in self.allocations.drain(..) {
            let _ = allocator.free(a);
        }
    }
}

/// Whether the device can blend into the attachment format (not mandatory for 32-bit floats).
pub(super) fn check_format(instance: &ash::Instance, physical: vk::PhysicalDevice) -> Result<()> {
    // SAFETY: a query on a live instance and one of its physical devices.
    let props = unsafe { instance.get_physical_device_format_properties(physical, FORMAT) };
    let need = vk::FormatFeatureFlags::COLOR_ATTACHMENT | vk::FormatFeatureFlags::COLOR_ATTACHMENT_BLEND;
    if !props.optimal_tiling_features.contains(need) {
        return Err(Error::InvalidArgument(
            "the device cannot blend into RGBA32F attachments, which the draws need; use the CPU backend".into(),
        ));
    }
    // SAFETY: as above.
    let depth = unsafe { instance.get_physical_device_format_properties(physical, DEPTH_FORMAT) };
    if !depth.optimal_tiling_features.contains(vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT) {
        return Err(Error::InvalidArgument(
            "the device has no D32 depth attachments, which the rasteriser needs; use the CPU backend".into(),
        ));
    }
    Ok(())
}

fn create_pipeline(device: &ash::Device, draw: &DrawDesc) -> Result<GraphicsPipeline> {
    let module_of = |entry: &str| {
        spirv::kernel_module(entry).ok_or_else(|| Error::InvalidArgument(format!("no SPIR-V module holds the entry point `{entry}`")))
    };
    let (vs_words, vs_name) = module_of(draw.vertex)?;
    let (fs_words, fs_name) = module_of(draw.fragment)?;
    let nul = |_| Error::InvalidArgument("an entry point name contains a NUL byte".into());
    let (vs_name, fs_name) = (CString::new(vs_name).map_err(nul)?, CString::new(fs_name).map_err(nul)?);
    let stages = vk::ShaderStageFlags::VERTEX | vk::ShaderStageFlags::FRAGMENT;
    let bindings: Vec<_> = (0..draw.bindings)
        .map(|b| {
            vk::DescriptorSetLayoutBinding::default()
                .binding(b)
                .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                .descriptor_count(1)
                .stage_flags(stages)
        })
        .collect();
    let set_info =
        vk::DescriptorSetLayoutCreateInfo::default().flags(vk::DescriptorSetLayoutCreateFlags::PUSH_DESCRIPTOR_KHR).bindings(&bindings);
    let ranges = [vk::PushConstantRange::default().stage_flags(stages).size(draw.push_bytes.div_ceil(4) * 4)];

    let attachment = [
        vk::AttachmentDescription::default()
            .format(FORMAT)
            .samples(vk::SampleCountFlags::TYPE_1)
            .load_op(vk::AttachmentLoadOp::CLEAR)
            .store_op(vk::AttachmentStoreOp::STORE)
            .stencil_load_op(vk::AttachmentLoadOp::DONT_CARE)
            .stencil_store_op(vk::AttachmentStoreOp::DONT_CARE)
            .initial_layout(vk::ImageLayout::UNDEFINED)
            .final_layout(vk::ImageLayout::TRANSFER_SRC_OPTIMAL),
        vk::AttachmentDescription::default()
            .format(DEPTH_FORMAT)
            .samples(vk::SampleCountFlags::TYPE_1)
            .load_op(vk::AttachmentLoadOp::CLEAR)
            .store_op(vk::AttachmentStoreOp::DONT_CARE)
            .stencil_load_op(vk::AttachmentLoadOp::DONT_CARE)
            .stencil_store_op(vk::AttachmentStoreOp::DONT_CARE)
            .initial_layout(vk::ImageLayout::UNDEFINED)
            .final_layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
    ];
    let colour_ref = [vk::AttachmentReference::default().attachment(0).layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)];
    let depth_ref = vk::AttachmentReference::default().attachment(1).layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    let subpass = [vk::SubpassDescription::default()
        .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
        .color_attachments(&colour_ref)
        .depth_stencil_attachment(&depth_ref)];
    let depth_stages = vk::PipelineStageFlags::EARLY_FRAGMENT_TESTS | vk::PipelineStageFlags::LATE_FRAGMENT_TESTS;
    // Before: the previous draw's copy out of the colour attachment and its depth writes are done.
    // After: the copy sees the draw.
    let dependencies = [
        vk::SubpassDependency::default()
            .src_subpass(vk::SUBPASS_EXTERNAL)
            .dst_subpass(0)
            .src_stage_mask(vk::PipelineStageFlags::TRANSFER | depth_stages)
            .src_access_mask(vk::AccessFlags::TRANSFER_READ | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE)
            .dst_stage_mask(vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT | depth_stages)
            .dst_access_mask(
                vk::AccessFlags::COLOR_ATTACHMENT_WRITE
                    | vk::AccessFlags::COLOR_ATTACHMENT_READ
                    | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_READ
                    | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE,
            ),
        vk::SubpassDependency::default()
            .src_subpass(0)
            .dst_subpass(vk::SUBPASS_EXTERNAL)
            .src_stage_mask(vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT)
            .src_access_mask(vk::AccessFlags::COLOR_ATTACHMENT_WRITE)
            .dst_stage_mask(vk::PipelineStageFlags::TRANSFER)
            .dst_access_mask(vk::AccessFlags::TRANSFER_READ),
    ];
    let pass_info = vk::RenderPassCreateInfo::default().attachments(&attachment).subpasses(&subpass).dependencies(&dependencies);

    let mut p = GraphicsPipeline::default();
    let (mut vs, mut fs) = (vk::ShaderModule::null(), vk::ShaderModule::null());
    // SAFETY: create infos point at live locals; on failure whatever was made is destroyed, and the
    // modules are not needed once the pipeline exists.
    let result = unsafe {
        (|| -> Result<()> {
            vs = device.create_shader_module(&vk::ShaderModuleCreateInfo::default().code(&vs_words), None).vk("vkCreateShaderModule")?;
            fs = device.create_shader_module(&vk::ShaderModuleCreateInfo::default().code(&fs_words), None).vk("vkCreateShaderModule")?;
            p.set_layout = device.create_descriptor_set_layout(&set_info, None).vk("vkCreateDescriptorSetLayout")?;
            let set_layouts = [p.set_layout];
            let layout_info = vk::PipelineLayoutCreateInfo::default().set_layouts(&set_layouts).push_constant_ranges(&ranges);
            p.layout = device.create_pipeline_layout(&layout_info, None).vk("vkCreatePipelineLayout")?;
            p.render_pass = device.create_render_pass(&pass_info, None).vk("vkCreateRenderPass")?;
            let shader_stages = [
                vk::PipelineShaderStageCreateInfo::default().stage(vk::ShaderStageFlags::VERTEX).module(vs).name(&vs_name),
                vk::PipelineShaderStageCreateInfo::default().stage(vk::ShaderStageFlags::FRAGMENT).module(fs).name(&fs_name),
            ];
            let vertex_input = vk::PipelineVertexInputStateCreateInfo::default();
            let assembly = vk::PipelineInputAssemblyStateCreateInfo::default().topology(vk::PrimitiveTopology::TRIANGLE_LIST);
            let viewport = vk::PipelineViewportStateCreateInfo::default().viewport_count(1).scissor_count(1);
            let raster = vk::PipelineRasterizationStateCreateInfo::default()
                .polygon_mode(vk::PolygonMode::FILL)
                .cull_mode(vk::CullModeFlags::NONE)
                .front_face(vk::FrontFace::COUNTER_CLOCKWISE)
                .line_width(1.0);
            let multisample = vk::PipelineMultisampleStateCreateInfo::default().rasterization_samples(vk::SampleCountFlags::TYPE_1);
            // Reversed depth: nearer is greater; the attachment clears to 0 (infinitely far).
            let depth = vk::PipelineDepthStencilStateCreateInfo::default()
                .depth_test_enable(draw.depth_test)
                .depth_write_enable(draw.depth_test)
                .depth_compare_op(vk::CompareOp::GREATER);
            let blend = [vk::PipelineColorBlendAttachmentState::default()
                .blend_enable(!draw.depth_test)
                .src_color_blend_factor(vk::BlendFactor::ONE)
                .dst_color_blend_factor(vk::BlendFactor::ONE)
                .color_blend_op(vk::BlendOp::ADD)
                .src_alpha_blend_factor(vk::BlendFactor::ONE)
                .dst_alpha_blend_factor(vk::BlendFactor::ONE)
                .alpha_blend_op(vk::BlendOp::ADD)
                .color_write_mask(vk::ColorComponentFlags::RGBA)];
            let blending = vk::PipelineColorBlendStateCreateInfo::default().attachments(&blend);
            let dynamic_states = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
            let dynamic = vk::PipelineDynamicStateCreateInfo::default().dynamic_states(&dynamic_states);
            let info = [vk::GraphicsPipelineCreateInfo::default()
                .stages(&shader_stages)
                .vertex_input_state(&vertex_input)
                .input_assembly_state(&assembly)
                .viewport_state(&viewport)
                .rasterization_state(&raster)
                .multisample_state(&multisample)
                .color_blend_state(&blending)
                .depth_stencil_state(&depth)
                .dynamic_state(&dynamic)
                .layout(p.layout)
                .render_pass(p.render_pass)
                .subpass(0)];
            let pipelines = device
                .create_graphics_pipelines(vk::PipelineCache::null(), &info, None)
                .map_err(|(_, result)| Error::Vulkan { call: "vkCreateGraphicsPipelines", result })?;
            p.pipeline = pipelines.first().copied().unwrap_or_default();
            Ok(())
        })()
    };
    // SAFETY: the pipeline (if any) no longer needs the modules; null modules are ignored.
    unsafe {
        device.destroy_shader_module(vs, None);
        device.destroy_shader_module(fs, None);
    }
    match result {
        Ok(()) => Ok(p),
        Err(e) => {
            destroy_pipeline(device, &p);
            Err(e)
        }
    }
}

fn destroy_pipeline(device: &ash::Device, p: &GraphicsPipeline) {
    // SAFETY: the GPU is done with the pipeline; null handles are ignored by vkDestroy*.
    unsafe {
        device.destroy_pipeline(p.pipeline, None);
        device.destroy_render_pass(p.render_pass, None);
        device.destroy_pipeline_layout(p.layout, None);
        device.destroy_descriptor_set_layout(p.set_layout, None);
    }
}
