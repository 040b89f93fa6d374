//! The window's swapchain, the render pass the UI is drawn in over the blurred image, and the
//! per-image framebuffers and semaphores. Recreated whenever the window's size changes.

use super::device::Device;
use anyhow::{Context, Result, bail};
use dof::backend::vulkan::ash::{self, vk};

pub struct Swapchain {
    pub loader: ash::khr::swapchain::Device,
    pub handle: vk::SwapchainKHR,
    pub format: vk::Format,
    pub extent: vk::Extent2D,
    pub present_mode: vk::PresentModeKHR,
    pub images: Vec<vk::Image>,
    views: Vec<vk::ImageView>,
    pub framebuffers: Vec<vk::Framebuffer>,
    /// Signalled by a frame's submission, waited for by its present: one per image, so that a
    /// semaphore is never signalled again while a present may still wait on it.
    pub rendered: Vec<vk::Semaphore>,
    /// Signalled when the acquired image is ready; one suffices with one frame in flight.
    pub acquired: vk::Semaphore,
    /// Load the blurred image, draw the UI over it, leave it ready for a copy (screenshot) and the
    /// transition to PRESENT_SRC.
    pub render_pass: vk::RenderPass,
}

/// The 8-bit UNORM formats (with the sRGB colour space) the viewer presents in. The display pass
/// (`dof_shaders::tonemap::display_tonemap`) writes values that are already sRGB-encoded (the tone
/// map's OETF, or the OETF of the clamped linear values), so the blit into the swapchain image must
/// store them as they are: a UNORM image does, where an `*_SRGB` one would encode them a second
/// time. The UI renderer is told the framebuffer is not sRGB for the same reason.
const FORMATS: [vk::Format; 2] = [vk::Format::B8G8R8A8_UNORM, vk::Format::R8G8B8A8_UNORM];

impl Swapchain {
    /// `vsync`: FIFO; otherwise MAILBOX or IMMEDIATE where the surface offers one (frame times are
    /// then the renderer's, not the display's), FIFO where it does not.
    pub fn new(
        d: &Device,
        surface_fn: &ash::khr::surface::Instance,
        surface: vk::SurfaceKHR,
        size: [u32; 2],
        vsync: bool,
        old: Option<Swapchain>,
    ) -> Result<Swapchain> {
        // SAFETY: queries and creation on live objects; the old swapchain is retired here and
        // destroyed once the device is idle (the caller waited).
        unsafe {
            let caps = surface_fn.get_physical_device_surface_capabilities(d.physical, surface)?;
            let formats = surface_fn.get_physical_device_surface_formats(d.physical, surface)?;
            let format = FORMATS
                .iter()
                .find_map(|f| formats.iter().find(|s| s.format == *f && s.color_space == vk::ColorSpaceKHR::SRGB_NONLINEAR))
                .copied()
                .context("the surface offers no 8-bit UNORM format in the sRGB colour space (B8G8R8A8_UNORM or R8G8B8A8_UNORM)")?;
            let modes = surface_fn.get_physical_device_surface_present_modes(d.physical, surface)?;
            let present_mode = if vsync {
                vk::PresentModeKHR::FIFO
            } else {
                [vk::PresentModeKHR::MAILBOX, vk::PresentModeKHR::IMMEDIATE]
                    .into_iter()
                    .find(|m| modes.contains(m))
                    .unwrap_or(vk::PresentModeKHR::FIFO)
            };
            let extent = if caps.current_extent.width != u32::MAX {
                caps.current_extent
            } else {
                vk::Extent2D {
                    width: size[0].clamp(caps.min_image_extent.width, caps.max_image_extent.width),
                    height: size[1].clamp(caps.min_image_extent.height, caps.max_image_extent.height),
                }
            };
            if extent.width == 0 || extent.height == 0 {
                bail!("the window has no area");
            }
            let usage = vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_DST | vk::ImageUsageFlags::TRANSFER_SRC;
            if !caps.supported_usage_flags.contains(usage) {
                bail!("the surface's images cannot be blitted into and copied from (usage {:?})", caps.supported_usage_flags);
            }
            let mut count = caps.min_image_count + 1;
            if caps.max_image_count > 0 {
                count = count.min(caps.max_image_count);
            }
            let loader = match &old {
                Some(o) => o.loader.clone(),
                None => ash::khr::swapchain::Device::new(&d.instance, &d.device),
            };
            let info = vk::SwapchainCreateInfoKHR::default()
                .surface(surface)
                .min_image_count(count)
                .image_format(format.format)
                .image_color_space(format.color_space)
                .image_extent(extent)
                .image_array_layers(1)
                .image_usage(usage)
                .image_sharing_mode(vk::SharingMode::EXCLUSIVE)
                .pre_transform(caps.current_transform)
                .composite_alpha(vk::CompositeAlphaFlagsKHR::OPAQUE)
                .present_mode(present_mode)
                .clipped(true)
                .old_swapchain(old.as_ref().map_or(vk::SwapchainKHR::null(), |o| o.handle));
            let handle = loader.create_swapchain(&info, None)?;
            let render_pass = match &old {
                Some(o) if o.format == format.format => o.render_pass,
                _ => render_pass(d, format.format)?,
            };
            if let Some(o) = old {
                let own_pass = o.render_pass != render_pass;
                o.destroy(d, own_pass);
            }
            let images = loader.get_swapchain_images(handle)?;
            let mut views = Vec::new();
            let mut framebuffers = Vec::new();
            let mut rendered = Vec::new();
            for &image in &images {
                let view_info = vk::ImageViewCreateInfo::default()
                    .image(image)
                    .view_type(vk::ImageViewType::TYPE_2D)
                    .format(format.format)
                    .subresource_range(
                        vk::ImageSubresourceRange::default().aspect_mask(vk::ImageAspectFlags::COLOR).level_count(1).layer_count(1),
                    );
                let view = d.device.create_image_view(&view_info, None)?;
                views.push(view);
                let attachments = [view];
                let fb_info = vk::FramebufferCreateInfo::default()
                    .render_pass(render_pass)
                    .attachments(&attachments)
                    .width(extent.width)
                    .height(extent.height)
                    .layers(1);
                framebuffers.push(d.device.create_framebuffer(&fb_info, None)?);
                rendered.push(d.device.create_semaphore(&vk::SemaphoreCreateInfo::default(), None)?);
            }
            let acquired = d.device.create_semaphore(&vk::SemaphoreCreateInfo::default(), None)?;
            Ok(Swapchain {
                loader,
                handle,
                format: format.format,
                extent,
                present_mode,
                images,
                views,
                framebuffers,
                rendered,
                acquired,
                render_pass,
            })
        }
    }

    /// Destroys the swapchain's objects (the device must be idle for them); the render pass too
    /// when `render_pass`.
    pub fn destroy(self, d: &Device, render_pass: bool) {
        // SAFETY: the device is idle; each object is destroyed once.
        unsafe {
            for fb in &self.framebuffers {
                d.device.destroy_framebuffer(*fb, None);
            }
            for v in &self.views {
                d.device.destroy_image_view(*v, None);
            }
            for s in &self.rendered {
                d.device.destroy_semaphore(*s, None);
            }
            d.device.destroy_semaphore(self.acquired, None);
            self.loader.destroy_swapchain(self.handle, None);
            if render_pass {
                d.device.destroy_render_pass(self.render_pass, None);
            }
        }
    }
}

/// One colour attachment, loaded (the blit wrote it), left in TRANSFER_SRC_OPTIMAL.
fn render_pass(d: &Device, format: vk::Format) -> Result<vk::RenderPass> {
    use vk::{AccessFlags as A, PipelineStageFlags as S};
    let attachments = [vk::AttachmentDescription::default()
        .format(format)
        .samples(vk::SampleCountFlags::TYPE_1)
        .load_op(vk::AttachmentLoadOp::LOAD)
        .store_op(vk::AttachmentStoreOp::STORE)
        .stencil_load_op(vk::AttachmentLoadOp::DONT_CARE)
        .stencil_store_op(vk::AttachmentStoreOp::DONT_CARE)
        .initial_layout(vk::ImageLayout::TRANSFER_DST_OPTIMAL)
        .final_layout(vk::ImageLayout::TRANSFER_SRC_OPTIMAL)];
    let color = [vk::AttachmentReference::default().attachment(0).layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)];
    let subpasses = [vk::SubpassDescription::default().pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS).color_attachments(&color)];
    // In: after the blit's write. Out: before the screenshot copy and the transition to present.
    let dependencies = [
        vk::SubpassDependency::default()
            .src_subpass(vk::SUBPASS_EXTERNAL)
            .dst_subpass(0)
            .src_stage_mask(S::TRANSFER)
            .src_access_mask(A::TRANSFER_WRITE)
            .dst_stage_mask(S::COLOR_ATTACHMENT_OUTPUT)
            .dst_access_mask(A::COLOR_ATTACHMENT_READ | A::COLOR_ATTACHMENT_WRITE),
        vk::SubpassDependency::default()
            .src_subpass(0)
            .dst_subpass(vk::SUBPASS_EXTERNAL)
            .src_stage_mask(S::COLOR_ATTACHMENT_OUTPUT)
            .src_access_mask(A::COLOR_ATTACHMENT_WRITE)
            .dst_stage_mask(S::TRANSFER)
            .dst_access_mask(A::TRANSFER_READ),
    ];
    let info = vk::RenderPassCreateInfo::default().attachments(&attachments).subpasses(&subpasses).dependencies(&dependencies);
    // SAFETY: creation on the live device; destroyed with the swapchain.
    Ok(unsafe { d.device.create_render_pass(&info, None)? })
}
