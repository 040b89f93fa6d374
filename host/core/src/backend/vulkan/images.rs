//! Images the standalone backend makes itself: stand-ins for a renderer's colour and depth images,
//! so that benchmarks and tests run the frame API's image inputs and outputs (their copies and
//! barriers) on a device without a renderer around it. They are set-up work, not a frame's: making
//! and writing one submits and waits.

use super::{VulkanBackend, lock};
use crate::backend::{Backend, ImageFormat, ImageRef};
use crate::error::{Error, Result, VkContext};
use ash::vk;
use ash::vk::Handle;
use gpu_allocator::MemoryLocation;
use gpu_allocator::vulkan::{Allocation, AllocationCreateDesc, AllocationScheme, Allocator};

/// One image of [`VulkanBackend::create_image`] and its memory.
pub(super) struct OwnImage {
    image: vk::Image,
    /// The view kernels sample or write it through (its depth aspect for a depth format).
    view: vk::ImageView,
    allocation: Allocation,
    format: ImageFormat,
    extent: [u32; 2],
}

impl OwnImage {
    pub fn destroy(self, device: &ash::Device, allocator: &mut Allocator) {
        // SAFETY: the caller guarantees no pending work uses the image or its view.
        unsafe {
            device.destroy_image_view(self.view, None);
            device.destroy_image(self.image, None);
        }
        // Freeing only fails for an allocation the allocator does not know.
        let _ = allocator.free(self.allocation);
    }
}

impl VulkanBackend {
    /// A device-local image of `format` and `extent` the backend owns, zeroed, with transfer
    /// usage (copied from and into, as a renderer's images are), and sampled and storage usage and
    /// a view where the device samples or writes the format in place: its [`ImageRef`] is in GENERAL with nothing to wait for, the
    /// state the backend's own copies leave it in. Freed by
    /// [`Backend::destroy_image`] or with the backend. Refused inside an external recording (it
    /// submits).
    pub(super) fn make_image(&mut self, format: ImageFormat, extent: [u32; 2]) -> Result<ImageRef> {
        self.refuse_external("create_image")?;
        let [width, height] = extent;
        // SAFETY: a query on the live instance and the device's physical device.
        let limit = unsafe { self.instance.instance.get_physical_device_properties(self.physical) }.limits.max_image_dimension2_d;
        if width == 0 || height == 0 || width > limit || height > limit {
            return Err(Error::InvalidArgument(format!(
                "a {width}x{height} image: each side must lie in 1..={limit} on {}",
                self.info.name
            )));
        }
        let probe = ImageRef::in_table(u64::MAX, u64::MAX, format, extent);
        self.check_image_copy(&probe, true)?;
        self.check_image_copy(&probe, false)?;
        let sampled = self.check_image_sample(&probe).is_ok();
        let stored = self.check_image_store(&probe).is_ok();
        let mut usage = vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST;
        if sampled {
            usage |= vk::ImageUsageFlags::SAMPLED;
        }
        if stored {
            usage |= vk::ImageUsageFlags::STORAGE;
        }
        let info = vk::ImageCreateInfo::default()
            .image_type(vk::ImageType::TYPE_2D)
            .format(format.vk_format())
            .extent(vk::Extent3D { width, height, depth: 1 })
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .tiling(vk::ImageTiling::OPTIMAL)
            .usage(usage)
            .initial_layout(vk::ImageLayout::UNDEFINED);
        let allocator = self.allocator()?;
        let device = self.device.device.clone();
        // SAFETY: a valid create info on the live device; on every later failure the image is
        // destroyed here.
        let own = unsafe {
            let image = device.create_image(&info, None).vk("vkCreateImage")?;
            let requirements = device.get_image_memory_requirements(image);
            let desc = AllocationCreateDesc {
                name: "dof stand-in image",
                requirements,
                location: MemoryLocation::GpuOnly,
                linear: false,
                allocation_scheme: AllocationScheme::GpuAllocatorManaged,
            };
            let allocation = match lock(&allocator).allocate(&desc) {
                Ok(a) => a,
                Err(e) => {
                    device.destroy_image(image, None);
                    return Err(Error::Allocation(e.to_string()));
                }
            };
            let view = device.bind_image_memory(image, allocation.memory(), allocation.offset()).vk("vkBindImageMemory").and_then(|()| {
                if !sampled && !stored {
                    return Ok(vk::ImageView::null());
                }
                let range = vk::ImageSubresourceRange::default().aspect_mask(format.copy_aspect()).level_count(1).layer_count(1);
                let info = vk::ImageViewCreateInfo::default()
                    .image(image)
                    .view_type(vk::ImageViewType::TYPE_2D)
                    .format(format.vk_format())
                    .subresource_range(range);
                device.create_image_view(&info, None).vk("vkCreateImageView")
            });
            match view {
                Ok(view) => OwnImage { image, view, allocation, format, extent },
                Err(e) => {
                    let _ = lock(&allocator).free(allocation);
                    device.destroy_image(image, None);
                    return Err(e);
                }
            }
        };
        let made = ImageRef::in_table(own.image.as_raw(), own.view.as_raw(), format, extent);
        self.images.insert(made.handle, own);
        // Its first copy starts from UNDEFINED; every later one from GENERAL.
        let zeros = vec![0; made.words() as usize];
        let first = ImageRef { layout: vk::ImageLayout::UNDEFINED, ..made };
        if let Err(e) = self.upload_image(first, &zeros) {
            self.free_image(&made);
            return Err(e);
        }
        Ok(made)
    }

    /// Writes every texel of an image of [`VulkanBackend::make_image`] (packed as the copies pack
    /// them, row after row), through a buffer made for it; submits and waits.
    pub(super) fn fill_image(&mut self, image: &ImageRef, texels: &[u32]) -> Result<()> {
        self.refuse_external("write_image")?;
        let own = self
            .images
            .get(&image.handle)
            .ok_or_else(|| Error::InvalidArgument(format!("image {:#x} is not one of the backend's own (`create_image`)", image.handle)))?;
        if (own.format, own.extent) != (image.format, image.extent) {
            return Err(Error::InvalidArgument(format!(
                "image {:#x} is {} of {}x{}, described as {} of {}x{}",
                image.handle, own.format, own.extent[0], own.extent[1], image.format, image.extent[0], image.extent[1]
            )));
        }
        if texels.len() as u64 != image.words() {
            return Err(Error::InvalidArgument(format!("the image holds {} words, {} given", image.words(), texels.len())));
        }
        self.upload_image(*image, texels)
    }

    fn upload_image(&mut self, image: ImageRef, texels: &[u32]) -> Result<()> {
        let staging = self.create_buffer(image.words(), "stand-in image upload")?;
        let done = self
            .write_buffer(staging, 0, texels)
            .and_then(|()| self.copy_buffer_to_image(staging, 0, image, "stand-in image upload"))
            .and_then(|()| self.submit().map(drop));
        self.destroy_buffer(staging);
        done
    }

    /// Frees an image of [`VulkanBackend::make_image`] once the work recorded so far completed
    /// (the standalone backend waits for each submission). Inside an external recording it is kept
    /// until the backend is dropped, with an error in the log.
    pub(super) fn free_image(&mut self, image: &ImageRef) {
        if self.refuse_external("destroy_image").is_err() {
            log::error!("destroy_image inside an external recording: image {:#x} is kept until the backend is dropped", image.handle);
            return;
        }
        let Some(own) = self.images.remove(&image.handle) else { return };
        if let Err(e) = self.flush() {
            log::error!("{e}: image {:#x} is kept until the backend is dropped", image.handle);
            self.images.insert(image.handle, own);
            return;
        }
        if let Some(allocator) = &self.allocator {
            own.destroy(&self.device.device, &mut lock(allocator));
        }
    }
}
