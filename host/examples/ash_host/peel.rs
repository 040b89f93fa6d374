//! The example host's own depth-peeling pass: a render pass, a graphics pipeline and GLSL shaders
//! of its own (`peel.vert`, `peel.frag`, compiled with glslangValidator and checked in beside them;
//! `.ci/glsl` recompiles and compares), drawing coloured triangles into an RGBA16F colour and a
//! D32_SFLOAT depth attachment. Its fragment shader calls the library's peel test
//! (`dof_peel_keep`, the GLSL of docs/integration.md) against the bound buffer the library writes;
//! its draw is indirect, from the command the library writes (a count of zero past the last useful
//! pass). Everything else about peeling is `dof_core::frame::RendererPeel`'s.

use super::{Buffer, Renderer};
use anyhow::Result;
use dof_core::backend::vulkan::ash::{self, vk};
use dof_core::backend::{ImageRef, VulkanBackend};
use std::ffi::CStr;

const VERT: &[u8] = include_bytes!("peel.vert.spv");
const FRAG: &[u8] = include_bytes!("peel.frag.spv");
pub const COLOR: vk::Format = vk::Format::R16G16B16A16_SFLOAT;
pub const DEPTH: vk::Format = vk::Format::D32_SFLOAT;

/// A vertex: position, then colour and coverage.
pub type Vertex = [f32; 7];

/// The push constants of both stages: the view-projection matrix (column-major) and the width.
#[repr(C)]
#[derive(Clone, Copy)]
struct Push {
    view_proj: [f32; 16],
    width: u32,
}

pub struct PeelPass {
    pub colour: vk::Image,
    pub depth: vk::Image,
    /// The library's bound (one f32 a pixel) and indirect draw command, in buffers of ours.
    pub bound: Buffer,
    pub draw: Buffer,
    pub vertex_count: u32,
    extent: [u32; 2],
    vertices: Buffer,
    views: [vk::ImageView; 2],
    render_pass: vk::RenderPass,
    framebuffer: vk::Framebuffer,
    set_layout: vk::DescriptorSetLayout,
    pool: vk::DescriptorPool,
    set: vk::DescriptorSet,
    layout: vk::PipelineLayout,
    pipeline: vk::Pipeline,
}

fn module(d: &ash::Device, spv: &[u8]) -> Result<vk::ShaderModule> {
    let words: Vec<u32> = spv.as_chunks::<4>().0.iter().map(|c| u32::from_le_bytes(*c)).collect();
    // SAFETY: valid SPIR-V from glslangValidator.
    Ok(unsafe { d.create_shader_module(&vk::ShaderModuleCreateInfo::default().code(&words), None)? })
}

impl PeelPass {
    pub fn new(r: &mut Renderer, extent: [u32; 2], triangles: &[Vertex]) -> Result<PeelPass> {
        use vk::BufferUsageFlags as B;
        let pixels = extent[0] as u64 * extent[1] as u64;
        let attachment = vk::ImageUsageFlags::TRANSFER_SRC;
        let colour = r.image(COLOR, extent, attachment | vk::ImageUsageFlags::COLOR_ATTACHMENT)?;
        let depth = r.image(DEPTH, extent, attachment | vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT)?;
        // The library fills and writes them (storage, transfer), we read them (fragment, indirect).
        let bound = r.buffer(4 * pixels, B::STORAGE_BUFFER | B::TRANSFER_DST, false)?;
        let draw = r.buffer(20, B::STORAGE_BUFFER | B::TRANSFER_DST | B::INDIRECT_BUFFER, false)?;
        let vertices = r.buffer(28 * triangles.len() as u64, B::VERTEX_BUFFER, true)?;
        // SAFETY: the mapping covers the vertices.
        unsafe { std::ptr::copy_nonoverlapping(triangles.as_ptr() as *const u8, vertices.mapped, 28 * triangles.len()) };
        let d = &r.device;
        // SAFETY: creation calls with infos pointing at live locals; all destroyed in `destroy`.
        unsafe {
            let view = |image, format, aspect| {
                let range = vk::ImageSubresourceRange::default().aspect_mask(aspect).level_count(1).layer_count(1);
                let info = vk::ImageViewCreateInfo::default()
                    .image(image)
                    .view_type(vk::ImageViewType::TYPE_2D)
                    .format(format)
                    .subresource_range(range);
                d.create_image_view(&info, None)
            };
            let views = [view(colour, COLOR, vk::ImageAspectFlags::COLOR)?, view(depth, DEPTH, vk::ImageAspectFlags::DEPTH)?];
            // Cleared every pass; left as attachments, for the library's copies.
            let attachment = |format, final_layout| {
                vk::AttachmentDescription::default()
                    .format(format)
                    .samples(vk::SampleCountFlags::TYPE_1)
                    .load_op(vk::AttachmentLoadOp::CLEAR)
                    .store_op(vk::AttachmentStoreOp::STORE)
                    .initial_layout(vk::ImageLayout::UNDEFINED)
                    .final_layout(final_layout)
            };
            let attachments = [
                attachment(COLOR, vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL),
                attachment(DEPTH, vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
            ];
            let colour_ref = [vk::AttachmentReference::default().attachment(0).layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)];
            let depth_ref = vk::AttachmentReference::default().attachment(1).layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
            let subpass = [vk::SubpassDescription::default().color_attachments(&colour_ref).depth_stencil_attachment(&depth_ref)];
            // After the library's copies of the last pass and its writes of the bound and draw
            // command; the library's own copies wait for our attachment writes (their ImageRefs).
            use vk::{AccessFlags as A, PipelineStageFlags as S};
            let tests = S::EARLY_FRAGMENT_TESTS | S::LATE_FRAGMENT_TESTS;
            let dependency = [vk::SubpassDependency::default()
                .src_subpass(vk::SUBPASS_EXTERNAL)
                .dst_subpass(0)
                .src_stage_mask(S::TRANSFER | S::COMPUTE_SHADER)
                .src_access_mask(A::SHADER_WRITE)
                .dst_stage_mask(S::DRAW_INDIRECT | S::FRAGMENT_SHADER | S::COLOR_ATTACHMENT_OUTPUT | tests)
                .dst_access_mask(
                    A::INDIRECT_COMMAND_READ
                        | A::SHADER_READ
                        | A::COLOR_ATTACHMENT_WRITE
                        | A::DEPTH_STENCIL_ATTACHMENT_READ
                        | A::DEPTH_STENCIL_ATTACHMENT_WRITE,
                )];
            let info = vk::RenderPassCreateInfo::default().attachments(&attachments).subpasses(&subpass).dependencies(&dependency);
            let render_pass = d.create_render_pass(&info, None)?;
            let fb = vk::FramebufferCreateInfo::default()
                .render_pass(render_pass)
                .attachments(&views)
                .width(extent[0])
                .height(extent[1])
                .layers(1);
            let framebuffer = d.create_framebuffer(&fb, None)?;

            let binding = [vk::DescriptorSetLayoutBinding::default()
                .binding(0)
                .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                .descriptor_count(1)
                .stage_flags(vk::ShaderStageFlags::FRAGMENT)];
            let set_layout = d.create_descriptor_set_layout(&vk::DescriptorSetLayoutCreateInfo::default().bindings(&binding), None)?;
            let sizes = [vk::DescriptorPoolSize { ty: vk::DescriptorType::STORAGE_BUFFER, descriptor_count: 1 }];
            let pool = d.create_descriptor_pool(&vk::DescriptorPoolCreateInfo::default().max_sets(1).pool_sizes(&sizes), None)?;
            let layouts = [set_layout];
            let set = d.allocate_descriptor_sets(&vk::DescriptorSetAllocateInfo::default().descriptor_pool(pool).set_layouts(&layouts))?[0];
            let info = [vk::DescriptorBufferInfo { buffer: bound.buffer, offset: 0, range: vk::WHOLE_SIZE }];
            let write = vk::WriteDescriptorSet::default()
                .dst_set(set)
                .dst_binding(0)
                .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                .buffer_info(&info);
            d.update_descriptor_sets(&[write], &[]);
            let push = [vk::PushConstantRange::default()
                .stage_flags(vk::ShaderStageFlags::VERTEX | vk::ShaderStageFlags::FRAGMENT)
                .size(size_of::<Push>() as u32)];
            let layout =
                d.create_pipeline_layout(&vk::PipelineLayoutCreateInfo::default().set_layouts(&layouts).push_constant_ranges(&push), None)?;

            let (vert, frag) = (module(d, VERT)?, module(d, FRAG)?);
            let main: &CStr = c"main";
            let stages = [
                vk::PipelineShaderStageCreateInfo::default().stage(vk::ShaderStageFlags::VERTEX).module(vert).name(main),
                vk::PipelineShaderStageCreateInfo::default().stage(vk::ShaderStageFlags::FRAGMENT).module(frag).name(main),
            ];
            let bindings = [vk::VertexInputBindingDescription::default().binding(0).stride(28)];
            let attributes = [
                vk::VertexInputAttributeDescription::default().location(0).format(vk::Format::R32G32B32_SFLOAT),
                vk::VertexInputAttributeDescription::default().location(1).format(vk::Format::R32G32B32A32_SFLOAT).offset(12),
            ];
            let vertex_input = vk::PipelineVertexInputStateCreateInfo::default()
                .vertex_binding_descriptions(&bindings)
                .vertex_attribute_descriptions(&attributes);
            let assembly = vk::PipelineInputAssemblyStateCreateInfo::default().topology(vk::PrimitiveTopology::TRIANGLE_LIST);
            let viewports = [vk::Viewport { width: extent[0] as f32, height: extent[1] as f32, max_depth: 1.0, ..Default::default() }];
            let scissors = [vk::Rect2D { extent: vk::Extent2D { width: extent[0], height: extent[1] }, ..Default::default() }];
            let viewport = vk::PipelineViewportStateCreateInfo::default().viewports(&viewports).scissors(&scissors);
            let raster = vk::PipelineRasterizationStateCreateInfo::default().polygon_mode(vk::PolygonMode::FILL).line_width(1.0);
            let multisample = vk::PipelineMultisampleStateCreateInfo::default().rasterization_samples(vk::SampleCountFlags::TYPE_1);
            // The nearest fragment the bound lets through wins (standard planes: less is nearer).
            let depth_state = vk::PipelineDepthStencilStateCreateInfo::default()
                .depth_test_enable(true)
                .depth_write_enable(true)
                .depth_compare_op(vk::CompareOp::LESS);
            let blend = [vk::PipelineColorBlendAttachmentState::default().color_write_mask(vk::ColorComponentFlags::RGBA)];
            let blend = vk::PipelineColorBlendStateCreateInfo::default().attachments(&blend);
            let info = vk::GraphicsPipelineCreateInfo::default()
                .stages(&stages)
                .vertex_input_state(&vertex_input)
                .input_assembly_state(&assembly)
                .viewport_state(&viewport)
                .rasterization_state(&raster)
                .multisample_state(&multisample)
                .depth_stencil_state(&depth_state)
                .color_blend_state(&blend)
                .layout(layout)
                .render_pass(render_pass);
            let pipeline = d.create_graphics_pipelines(vk::PipelineCache::null(), &[info], None).map_err(|(_, e)| e)?[0];
            d.destroy_shader_module(vert, None);
            d.destroy_shader_module(frag, None);
            Ok(PeelPass {
                colour,
                depth,
                bound,
                draw,
                vertex_count: triangles.len() as u32,
                extent,
                vertices,
                views,
                render_pass,
                framebuffer,
                set_layout,
                pool,
                set,
                layout,
                pipeline,
            })
        }
    }

    /// Records one peel pass into the renderer's command buffer: cleared attachments (the
    /// background colour, the far depth), then the triangles beyond the bound.
    pub fn record(&self, r: &Renderer, view_proj: [f32; 16], background: [f32; 3]) {
        let d = &r.device;
        let clear = [
            vk::ClearValue { color: vk::ClearColorValue { float32: [background[0], background[1], background[2], 1.0] } },
            vk::ClearValue { depth_stencil: vk::ClearDepthStencilValue { depth: 1.0, stencil: 0 } },
        ];
        let area = vk::Rect2D { extent: vk::Extent2D { width: self.extent[0], height: self.extent[1] }, ..Default::default() };
        let begin = vk::RenderPassBeginInfo::default()
            .render_pass(self.render_pass)
            .framebuffer(self.framebuffer)
            .render_area(area)
            .clear_values(&clear);
        let push = Push { view_proj, width: self.extent[0] };
        // SAFETY: the command buffer is recording; every object is live; the push constants match
        // the layout's range.
        unsafe {
            d.cmd_begin_render_pass(r.cb, &begin, vk::SubpassContents::INLINE);
            d.cmd_bind_pipeline(r.cb, vk::PipelineBindPoint::GRAPHICS, self.pipeline);
            d.cmd_bind_descriptor_sets(r.cb, vk::PipelineBindPoint::GRAPHICS, self.layout, 0, &[self.set], &[]);
            d.cmd_bind_vertex_buffers(r.cb, 0, &[self.vertices.buffer], &[0]);
            let bytes = std::slice::from_raw_parts(&push as *const Push as *const u8, size_of::<Push>());
            d.cmd_push_constants(r.cb, self.layout, vk::ShaderStageFlags::VERTEX | vk::ShaderStageFlags::FRAGMENT, 0, bytes);
            d.cmd_draw_indirect(r.cb, self.draw.buffer, 0, 1, 0);
            d.cmd_end_render_pass(r.cb);
        }
    }

    /// The attachments as the library reads them: as our render pass left them.
    pub fn attachments(&self) -> Result<(ImageRef, ImageRef)> {
        use vk::{AccessFlags as A, ImageLayout as L, PipelineStageFlags as S};
        let colour = ImageRef::describe(self.colour, COLOR, self.extent)?
            .in_layout(L::COLOR_ATTACHMENT_OPTIMAL)
            .after(S::COLOR_ATTACHMENT_OUTPUT, A::COLOR_ATTACHMENT_WRITE);
        let depth = ImageRef::describe(self.depth, DEPTH, self.extent)?
            .in_layout(L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL)
            .after(S::LATE_FRAGMENT_TESTS, A::DEPTH_STENCIL_ATTACHMENT_WRITE);
        // SAFETY: our live images of these formats and extent, with TRANSFER_SRC usage, in these
        // layouts after our render pass; alive until the frame's fence.
        Ok(unsafe { (colour.build(), depth.build()) })
    }

    /// Our bound and draw buffers, imported for the library to write.
    pub fn import(&self, backend: &mut VulkanBackend) -> Result<(dof_core::backend::BufferId, dof_core::backend::BufferId)> {
        // SAFETY: our live storage buffers of these sizes, alive until the backend has forgotten them.
        unsafe {
            Ok((
                backend.import_buffer(self.bound.buffer, self.bound.bytes, "peel/bound")?,
                backend.import_buffer(self.draw.buffer, self.draw.bytes, "peel/draw")?,
            ))
        }
    }

    /// Destroys the pass's own objects (its images and buffers go with the renderer's).
    pub fn destroy(self, r: &Renderer) {
        let d = &r.device;
        // SAFETY: the device is idle; each object is destroyed once.
        unsafe {
            d.device_wait_idle().ok();
            d.destroy_pipeline(self.pipeline, None);
            d.destroy_pipeline_layout(self.layout, None);
            d.destroy_descriptor_pool(self.pool, None);
            d.destroy_descriptor_set_layout(self.set_layout, None);
            d.destroy_framebuffer(self.framebuffer, None);
            d.destroy_render_pass(self.render_pass, None);
            for v in self.views {
                d.destroy_image_view(v, None);
            }
        }
    }
}
