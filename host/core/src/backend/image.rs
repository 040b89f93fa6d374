//! The caller's images a frame copies in and out of buffers: their formats, and the
//! synchronisation state a Vulkan image is in ([`ImageRef`], described by name with [`ImageDesc`]).
//! Without the `vulkan` feature an image is the CPU backend's stand-in, with no state to describe.

use crate::error::{Error, Result};

/// Formats an image can be copied in and out of a buffer as. Buffers hold 4-byte words; pixels are
/// packed row after row, top row first, with no padding:
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ImageFormat {
    /// `R32G32B32A32_SFLOAT`: 4 words a pixel, the bits of R, G, B, A.
    Rgba32Float,
    /// `R32_SFLOAT`: 1 word a pixel.
    R32Float,
    /// `R16G16B16A16_SFLOAT`: 2 words a pixel, the IEEE half bits of R in the low and G in the high
    /// half of the first word, B and A likewise in the second (a kernel converts them).
    Rgba16Float,
    /// `B10G11R11_UFLOAT_PACK32`: 1 word a pixel, R an 11-bit float in bits 0–10, G one in bits
    /// 11–21, B a 10-bit float in bits 22–31 (a kernel converts them).
    B10G11R11Ufloat,
    /// `D32_SFLOAT`, a depth attachment, copied through its depth aspect: 1 word a pixel, f32 bits.
    D32Float,
    /// `D24_UNORM_S8_UINT`, copied through its depth aspect: 1 word a pixel, the 24-bit unorm depth
    /// in the low bits, the high 8 bits undefined (Vulkan leaves them so; the kernel ignores them).
    D24UnormS8Uint,
    /// `X8_D24_UNORM_PACK32`, copied through its depth aspect: as [`ImageFormat::D24UnormS8Uint`].
    X8D24UnormPack32,
}

impl ImageFormat {
    /// Every format, for look-ups and error messages.
    pub const ALL: [ImageFormat; 7] = [
        ImageFormat::Rgba32Float,
        ImageFormat::R32Float,
        ImageFormat::Rgba16Float,
        ImageFormat::B10G11R11Ufloat,
        ImageFormat::D32Float,
        ImageFormat::D24UnormS8Uint,
        ImageFormat::X8D24UnormPack32,
    ];

    pub fn words_per_pixel(self) -> u64 {
        match self {
            ImageFormat::Rgba32Float => 4,
            ImageFormat::Rgba16Float => 2,
            ImageFormat::R32Float
            | ImageFormat::B10G11R11Ufloat
            | ImageFormat::D32Float
            | ImageFormat::D24UnormS8Uint
            | ImageFormat::X8D24UnormPack32 => 1,
        }
    }

    /// How a kernel decodes the format's packed texels (`dof_shaders::texels`).
    pub fn texels(self) -> u32 {
        use dof_shaders::texels;
        match self {
            ImageFormat::Rgba32Float => texels::RGBA32F,
            ImageFormat::Rgba16Float => texels::RGBA16F,
            ImageFormat::B10G11R11Ufloat => texels::B10G11R11,
            ImageFormat::R32Float | ImageFormat::D32Float => texels::R32F,
            ImageFormat::D24UnormS8Uint | ImageFormat::X8D24UnormPack32 => texels::D24,
        }
    }

    /// The Vulkan name of the format (`D32_SFLOAT`).
    pub fn name(self) -> &'static str {
        match self {
            ImageFormat::Rgba32Float => "R32G32B32A32_SFLOAT",
            ImageFormat::R32Float => "R32_SFLOAT",
            ImageFormat::Rgba16Float => "R16G16B16A16_SFLOAT",
            ImageFormat::B10G11R11Ufloat => "B10G11R11_UFLOAT_PACK32",
            ImageFormat::D32Float => "D32_SFLOAT",
            ImageFormat::D24UnormS8Uint => "D24_UNORM_S8_UINT",
            ImageFormat::X8D24UnormPack32 => "X8_D24_UNORM_PACK32",
        }
    }

    /// The Vulkan format.
    #[cfg(feature = "vulkan")]
    pub fn vk_format(self) -> ash::vk::Format {
        use ash::vk::Format;
        match self {
            ImageFormat::Rgba32Float => Format::R32G32B32A32_SFLOAT,
            ImageFormat::R32Float => Format::R32_SFLOAT,
            ImageFormat::Rgba16Float => Format::R16G16B16A16_SFLOAT,
            ImageFormat::B10G11R11Ufloat => Format::B10G11R11_UFLOAT_PACK32,
            ImageFormat::D32Float => Format::D32_SFLOAT,
            ImageFormat::D24UnormS8Uint => Format::D24_UNORM_S8_UINT,
            ImageFormat::X8D24UnormPack32 => Format::X8_D24_UNORM_PACK32,
        }
    }

    /// Whether it is a depth attachment's format (copied through the depth aspect).
    pub fn is_depth(self) -> bool {
        matches!(self, ImageFormat::D32Float | ImageFormat::D24UnormS8Uint | ImageFormat::X8D24UnormPack32)
    }

    /// Whether a depth word holds a 24-bit unorm in its low bits (else an f32).
    pub fn is_unorm24(self) -> bool {
        matches!(self, ImageFormat::D24UnormS8Uint | ImageFormat::X8D24UnormPack32)
    }

    /// The aspect a copy reads or writes.
    #[cfg(feature = "vulkan")]
    pub fn copy_aspect(self) -> ash::vk::ImageAspectFlags {
        if self.is_depth() { ash::vk::ImageAspectFlags::DEPTH } else { ash::vk::ImageAspectFlags::COLOR }
    }

    /// The aspects a layout transition names: depth and stencil together for a format with both
    /// (required without `separateDepthStencilLayouts`).
    #[cfg(feature = "vulkan")]
    pub fn layout_aspects(self) -> ash::vk::ImageAspectFlags {
        match self {
            ImageFormat::D24UnormS8Uint => ash::vk::ImageAspectFlags::DEPTH | ash::vk::ImageAspectFlags::STENCIL,
            other => other.copy_aspect(),
        }
    }
}

impl std::fmt::Display for ImageFormat {
    /// The Vulkan name (`D32_SFLOAT`).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// `formats` as Vulkan names, for error messages.
pub(crate) fn format_names(formats: &[ImageFormat]) -> String {
    formats.iter().map(|f| f.to_string()).collect::<Vec<_>>().join(", ")
}

#[cfg(feature = "vulkan")]
impl TryFrom<ash::vk::Format> for ImageFormat {
    type Error = Error;
    /// The image format of a Vulkan format, or an error naming the formats there are.
    fn try_from(format: ash::vk::Format) -> Result<Self> {
        ImageFormat::ALL.into_iter().find(|f| f.vk_format() == format).ok_or_else(|| {
            Error::InvalidArgument(format!("images of {format:?} cannot be copied; the formats are {}", format_names(&ImageFormat::ALL)))
        })
    }
}

/// A 2D image the caller owns, and the synchronisation state it is in, for `copy_image_to_buffer`
/// and `copy_buffer_to_image`. The state is in Vulkan terms (the CPU backend's stand-ins ignore it); the copy
/// covers mip level 0, array layer 0, the colour aspect (the depth aspect of a depth format), and
/// the top-left `extent` of the image, which may be larger.
///
/// The backend records a barrier from (`layout`, `stage`, `access`) to the transfer layout, the copy,
/// and a barrier from the transfer to `final_layout` that makes the copy visible to every later
/// access (all commands, memory read and write). The backend's own earlier copies are covered too, so
/// an image the backend left in `final_layout` can be declared as `layout = final_layout` with no
/// stage or access.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ImageRef {
    /// The raw handle (`vk::Image::as_raw()`, set by [`ImageRef::vulkan`]), or the CPU backend's
    /// stand-in's number.
    pub(crate) handle: u64,
    /// A view kernels sample the image through (`vk::ImageView::as_raw()`, set by
    /// [`ImageDesc::sampled_through`]; the stand-in's number on the CPU backend), or 0: then a frame
    /// copies the image instead of reading it in place.
    pub(crate) view: u64,
    pub format: ImageFormat,
    /// Width and height in pixels.
    pub extent: [u32; 2],
    /// The layout the image is in when the copy runs. UNDEFINED discards its contents: allowed only
    /// when copying into it.
    #[cfg(feature = "vulkan")]
    pub layout: ash::vk::ImageLayout,
    /// The stages of the caller's last access, which the copy waits for (may be empty).
    #[cfg(feature = "vulkan")]
    pub stage: ash::vk::PipelineStageFlags,
    /// The caller's last accesses (its writes must be named here to be made visible to the copy).
    #[cfg(feature = "vulkan")]
    pub access: ash::vk::AccessFlags,
    /// The layout to leave the image in (not UNDEFINED or PREINITIALIZED).
    #[cfg(feature = "vulkan")]
    pub final_layout: ash::vk::ImageLayout,
}

impl ImageRef {
    /// A Vulkan image last accessed at `stage` with `access` in `layout`, to be left in `final_layout`.
    ///
    /// # Safety
    ///
    /// `image` is a live 2D image of the device the backend runs on, with `format`, at least
    /// `extent`, one sample, TRANSFER_SRC usage if it is copied from and TRANSFER_DST usage if it is
    /// copied into, and queue family ownership (if exclusive) on the backend's queue family; it is in
    /// `layout` when the recorded copy runs, and stays alive until the copy completed.
    #[cfg(feature = "vulkan")]
    pub unsafe fn vulkan(
        image: ash::vk::Image,
        format: ImageFormat,
        extent: [u32; 2],
        layout: ash::vk::ImageLayout,
        stage: ash::vk::PipelineStageFlags,
        access: ash::vk::AccessFlags,
        final_layout: ash::vk::ImageLayout,
    ) -> Self {
        use ash::vk::Handle;
        ImageRef { handle: image.as_raw(), view: 0, format, extent, layout, stage, access, final_layout }
    }

    /// Starts describing a caller's Vulkan image of `format` and `extent` (see [`ImageDesc`]):
    /// the format is checked now, the state is named with the builder's methods. Until
    /// [`ImageDesc::after`] narrows it, the frame waits for every earlier write of any stage
    /// (depth-attachment writes included).
    #[cfg(feature = "vulkan")]
    pub fn describe(image: ash::vk::Image, format: ash::vk::Format, extent: [u32; 2]) -> Result<ImageDesc> {
        let format = ImageFormat::try_from(format)?;
        let layout = ash::vk::ImageLayout::GENERAL;
        Ok(ImageDesc {
            image,
            format,
            extent,
            layout,
            stage: ash::vk::PipelineStageFlags::ALL_COMMANDS,
            access: ash::vk::AccessFlags::MEMORY_WRITE,
            final_layout: None,
            view: ash::vk::ImageView::null(),
        })
    }

    /// An image a backend keeps itself, by `handle`: the CPU backend's stand-ins and the wgpu
    /// backend's textures by their number in its table (those backends have no layouts), the Vulkan
    /// backend's own images by their raw handle. Its Vulkan state says GENERAL and nothing to wait
    /// for, the state the backend's own copies leave an image in. Kernels sample it through `view`
    /// (0: it is only copied).
    pub(crate) fn in_table(handle: u64, view: u64, format: ImageFormat, extent: [u32; 2]) -> Self {
        ImageRef {
            handle,
            view,
            format,
            extent,
            #[cfg(feature = "vulkan")]
            layout: ash::vk::ImageLayout::GENERAL,
            #[cfg(feature = "vulkan")]
            stage: ash::vk::PipelineStageFlags::empty(),
            #[cfg(feature = "vulkan")]
            access: ash::vk::AccessFlags::empty(),
            #[cfg(feature = "vulkan")]
            final_layout: ash::vk::ImageLayout::GENERAL,
        }
    }

    /// The raw Vulkan handle.
    pub fn handle(&self) -> u64 {
        self.handle
    }

    /// The same image without its view: a frame copies it into the context's buffers instead of
    /// sampling it in place (to measure the copy, or where a view must not be used).
    pub fn copied(self) -> ImageRef {
        ImageRef { view: 0, ..self }
    }

    /// Whether kernels can read the image in place (it has a view to sample it through); a frame
    /// copies an image without one.
    pub fn sampled(&self) -> bool {
        self.view != 0
    }

    /// What every backend checks before a kernel writes the image in place (a storage image): a
    /// non-empty extent, a handle and a view, a colour format kernels write (RGBA32F or RGBA16F),
    /// and (on Vulkan) a final layout.
    pub(crate) fn check_store(&self, what: &str) -> Result<()> {
        if self.view == 0 {
            return Err(Error::InvalidArgument(format!("{what}: the {} image has no view to write it through", self.format)));
        }
        if !matches!(self.format, ImageFormat::Rgba32Float | ImageFormat::Rgba16Float) {
            return Err(Error::InvalidArgument(format!("{what}: kernels write RGBA32F and RGBA16F images, not {}", self.format)));
        }
        self.check_copy(true, what)
    }

    /// What every backend checks before a kernel samples the image: a non-empty extent, a handle
    /// and a view, and (on Vulkan) a layout with defined contents and a final layout.
    pub(crate) fn check_sample(&self, what: &str) -> Result<()> {
        if self.view == 0 {
            return Err(Error::InvalidArgument(format!("{what}: the {} image has no view to sample it through", self.format)));
        }
        self.check_copy(false, what)
    }

    /// Words the image takes in a buffer.
    pub fn words(&self) -> u64 {
        self.format.words_per_pixel() * self.extent[0] as u64 * self.extent[1] as u64
    }

    /// The same image, its copies covering only its top-left `width` x `height`.
    pub fn top_left(self, width: u32, height: u32) -> ImageRef {
        ImageRef { extent: [width, height], ..self }
    }

    /// What every backend checks before recording a copy of the image: a non-empty extent and a
    /// handle, layouts a copy can start from (`into_image`: one may discard the contents) and end
    /// in. `what` names the copy in the error.
    pub(crate) fn check_copy(&self, into_image: bool, what: &str) -> Result<()> {
        let [width, height] = self.extent;
        if width == 0 || height == 0 || self.handle == 0 {
            return Err(Error::InvalidArgument(format!("{what}: an empty ({width}x{height}) or null {} image", self.format)));
        }
        #[cfg(feature = "vulkan")]
        {
            let bad_final = [ash::vk::ImageLayout::UNDEFINED, ash::vk::ImageLayout::PREINITIALIZED];
            if bad_final.contains(&self.final_layout) {
                return Err(Error::InvalidArgument(format!("{what}: the final layout cannot be {:?}", self.final_layout)));
            }
            if !into_image && bad_final.contains(&self.layout) {
                return Err(Error::InvalidArgument(format!(
                    "{what}: an image in layout {:?} has no defined contents to copy",
                    self.layout
                )));
            }
        }
        #[cfg(not(feature = "vulkan"))]
        let _ = into_image;
        Ok(())
    }
}

/// An [`ImageRef`] being described, by name rather than by position: the image is in GENERAL, its
/// copy waits for every earlier write (all commands, memory writes), and it is left in the layout it
/// was in, unless told otherwise. Naming the last access with [`ImageDesc::after`] narrows the wait
/// to it.
///
/// ```no_run
/// # use dof_core::backend::ImageRef;
/// # use dof_core::backend::vulkan::ash::vk;
/// # fn f(image: vk::Image) -> dof_core::Result<ImageRef> {
/// let colour = ImageRef::describe(image, vk::Format::R16G16B16A16_SFLOAT, [1920, 1080])?
///     .in_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
///     .after(vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT, vk::AccessFlags::COLOR_ATTACHMENT_WRITE)
///     .leave_in(vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL);
/// // SAFETY: the caller's image, as `ImageRef::vulkan` requires.
/// Ok(unsafe { colour.build() })
/// # }
/// ```
#[cfg(feature = "vulkan")]
#[derive(Clone, Copy, Debug)]
pub struct ImageDesc {
    image: ash::vk::Image,
    format: ImageFormat,
    extent: [u32; 2],
    layout: ash::vk::ImageLayout,
    stage: ash::vk::PipelineStageFlags,
    access: ash::vk::AccessFlags,
    final_layout: Option<ash::vk::ImageLayout>,
    view: ash::vk::ImageView,
}

#[cfg(feature = "vulkan")]
impl ImageDesc {
    /// A view of the image the frame's kernels read or write it through in place instead of
    /// copying it: a 2D view of mip level 0 and array layer 0, of the image's format, and for a
    /// depth format of its depth aspect alone. An input then needs SAMPLED usage (and no
    /// TRANSFER_SRC), an output STORAGE usage (and no TRANSFER_DST). An image without a view is
    /// copied through the context's buffers.
    pub fn sampled_through(self, view: ash::vk::ImageView) -> Self {
        ImageDesc { view, ..self }
    }

    /// The layout the image is in when the frame's copy runs (UNDEFINED discards its contents:
    /// allowed only for an image the frame writes).
    pub fn in_layout(self, layout: ash::vk::ImageLayout) -> Self {
        ImageDesc { layout, ..self }
    }

    /// The caller's last access of the image, which the frame waits for and makes visible (instead
    /// of every earlier write, the default).
    pub fn after(self, stage: ash::vk::PipelineStageFlags, access: ash::vk::AccessFlags) -> Self {
        ImageDesc { stage, access, ..self }
    }

    /// The layout to leave the image in (default: the layout it was in; GENERAL after UNDEFINED).
    pub fn leave_in(self, final_layout: ash::vk::ImageLayout) -> Self {
        ImageDesc { final_layout: Some(final_layout), ..self }
    }

    /// The description.
    ///
    /// # Safety
    ///
    /// As for [`ImageRef::vulkan`]: a live 2D image of the backend's device with this format and
    /// at least this extent, the usages the copies need (SAMPLED where it is sampled through a
    /// view, which must be a live view of it as [`ImageDesc::sampled_through`] says), in the named
    /// layout when the frame runs.
    pub unsafe fn build(self) -> ImageRef {
        use ash::vk::ImageLayout;
        let final_layout = self.final_layout.unwrap_or(match self.layout {
            ImageLayout::UNDEFINED | ImageLayout::PREINITIALIZED => ImageLayout::GENERAL,
            other => other,
        });
        use ash::vk::Handle;
        // SAFETY: the caller's contract, passed on.
        let image = unsafe { ImageRef::vulkan(self.image, self.format, self.extent, self.layout, self.stage, self.access, final_layout) };
        ImageRef { view: self.view.as_raw(), ..image }
    }
}

#[cfg(all(test, feature = "vulkan"))]
mod tests {
    use super::*;

    #[test]
    fn names_are_the_vulkan_names() {
        for f in ImageFormat::ALL {
            assert_eq!(f.name(), format!("{:?}", f.vk_format()));
        }
    }
}
