//! A renderer's textures as a frame's input and output: imported once, then sampled and written in
//! place by kernels where their usage allows, or copied to and from buffers as the frame API's
//! images are on Vulkan. Depth is read by a kernel (`texture_read`), as f32 depths: wgpu copies no
//! depth out of `Depth24Plus` or `Depth24PlusStencil8`, and copies one out of the others only for
//! the whole texture.

use super::timing::Command;
use super::{Groups, Pipeline, WgpuBackend, storage_binding, texture_binding};
use crate::backend::{BufferId, ImageFormat, ImageRef};
use crate::error::{Error, Result};
use dof_shaders::texture_read::{DEPTH_TEXTURE_WORDS, THREADS, TextureReadParams};

pub(super) struct WgpuTexture {
    texture: wgpu::Texture,
    /// A depth texture's depth aspect, as the `texture_read` kernel binds it (made at import);
    /// `None` for a colour texture, which is copied.
    depth_view: Option<wgpu::TextureView>,
    /// The view kernels sample it through in place (made at import): the depth aspect of a depth
    /// texture, mip 0 and layer 0 of a colour texture with TEXTURE_BINDING usage; `None` for a
    /// colour texture without that usage, which a frame copies.
    sampled_view: Option<wgpu::TextureView>,
    /// The view kernels write it through in place (made at import): mip 0 and layer 0 of an
    /// RGBA32F or RGBA16F texture with STORAGE_BINDING usage; `None` otherwise (a frame's result
    /// is then copied in).
    storage_view: Option<wgpu::TextureView>,
}

/// The texture formats a frame takes, as the [`ImageFormat`] their texels have in a buffer.
fn buffer_format(format: wgpu::TextureFormat) -> Option<ImageFormat> {
    use wgpu::TextureFormat as T;
    Some(match format {
        T::Rgba32Float => ImageFormat::Rgba32Float,
        T::Rgba16Float => ImageFormat::Rgba16Float,
        // The same bits as Vulkan's B10G11R11_UFLOAT_PACK32: red in the low 11.
        T::Rg11b10Ufloat => ImageFormat::B10G11R11Ufloat,
        T::R32Float => ImageFormat::R32Float,
        // Read by the kernel as f32 depths.
        T::Depth32Float | T::Depth32FloatStencil8 | T::Depth24Plus | T::Depth24PlusStencil8 => ImageFormat::D32Float,
        _ => return None,
    })
}

const FORMATS: &str = "Rgba32Float, Rgba16Float, Rg11b10Ufloat, R32Float, Depth32Float, Depth32FloatStencil8, Depth24Plus, \
                       Depth24PlusStencil8";

impl WgpuBackend {
    /// Makes the caller's 2D `texture` an image a frame reads or writes ([`crate::FrameInput::Images`],
    /// [`crate::FrameOutput::Image`]). Its [`ImageRef`]'s format is the layout its texels take in a
    /// buffer: its own, except that every depth format reads as `D32Float` (f32 depths, read by a
    /// kernel). Mip level 0 and array layer 0 are used. An input is read in place where it has
    /// TEXTURE_BINDING usage (a depth texture always needs it); a colour texture without it is
    /// copied, and needs COPY_SRC. An output is written in place where it has STORAGE_BINDING
    /// usage, and copied into otherwise, which needs COPY_DST; wgpu orders the frame's access
    /// after the caller's earlier commands. The backend keeps a reference until
    /// [`WgpuBackend::forget_texture`].
    pub fn import_texture(&mut self, texture: &wgpu::Texture) -> Result<ImageRef> {
        let format = texture.format();
        let Some(image_format) = buffer_format(format) else {
            return Err(Error::InvalidArgument(format!("a frame takes no {format:?} texture; the formats are {FORMATS}")));
        };
        if texture.dimension() != wgpu::TextureDimension::D2 || texture.sample_count() != 1 {
            return Err(Error::InvalidArgument(format!(
                "a frame takes single-sampled 2D textures, not a {:?} one with {} samples (resolve it first)",
                texture.dimension(),
                texture.sample_count()
            )));
        }
        let view = |aspect| {
            texture.create_view(&wgpu::TextureViewDescriptor {
                label: Some("dof input"),
                dimension: Some(wgpu::TextureViewDimension::D2),
                aspect,
                base_mip_level: 0,
                mip_level_count: Some(1),
                base_array_layer: 0,
                array_layer_count: Some(1),
                ..Default::default()
            })
        };
        let depth_view = format.is_depth_stencil_format().then(|| view(wgpu::TextureAspect::DepthOnly));
        let sampled_view = match &depth_view {
            Some(depth) => Some(depth.clone()),
            None => texture.usage().contains(wgpu::TextureUsages::TEXTURE_BINDING).then(|| view(wgpu::TextureAspect::All)),
        };
        let writable = matches!(format, wgpu::TextureFormat::Rgba32Float | wgpu::TextureFormat::Rgba16Float)
            && texture.usage().contains(wgpu::TextureUsages::STORAGE_BINDING);
        let storage_view = writable.then(|| view(wgpu::TextureAspect::All));
        if depth_view.is_some() {
            // Made now, so that no frame makes it.
            self.depth_read_pipeline()?;
        }
        self.check_errors()?;
        let slot = self.textures.iter().position(Option::is_none).unwrap_or(self.textures.len());
        if slot == self.textures.len() {
            self.textures.push(None);
        }
        let view = if sampled_view.is_some() || storage_view.is_some() { slot as u64 + 1 } else { 0 };
        self.textures[slot] = Some(WgpuTexture { texture: texture.clone(), depth_view, sampled_view, storage_view });
        let size = texture.size();
        Ok(ImageRef::in_table(slot as u64 + 1, view, image_format, [size.width, size.height]))
    }

    /// Drops the backend's reference to an imported texture; its `ImageRef` is then refused.
    pub fn forget_texture(&mut self, image: &ImageRef) {
        if let Some(slot) = (image.handle as usize).checked_sub(1).and_then(|i| self.textures.get_mut(i)) {
            *slot = None;
        }
    }

    fn texture(&self, image: &ImageRef) -> Result<&WgpuTexture> {
        let found = (image.handle as usize).checked_sub(1).and_then(|i| self.textures.get(i)).and_then(Option::as_ref);
        let texture = found.ok_or_else(|| {
            Error::InvalidArgument(format!("unknown image {} (the wgpu backend's images come from import_texture)", image.handle))
        })?;
        match buffer_format(texture.texture.format()) {
            Some(format) if format == image.format => Ok(texture),
            _ => Err(Error::InvalidArgument(format!(
                "image {} is a {:?} texture, described as {}",
                image.handle,
                texture.texture.format(),
                image.format
            ))),
        }
    }

    /// The checks of sampling a texture in place, made before anything is recorded.
    pub(super) fn check_texture_sample(&self, image: &ImageRef) -> Result<()> {
        image.check_sample("dispatch_images")?;
        self.texture_in_place(image, false).map(drop)
    }

    /// The checks of writing a texture in place, made before anything is recorded.
    pub(super) fn check_texture_store(&self, image: &ImageRef) -> Result<()> {
        self.texture_in_place(image, true)?;
        image.check_store("dispatch_images")
    }

    /// `image`'s texture, where its extent fits and it has the view a kernel samples it through
    /// (or writes it through, `store`).
    fn texture_in_place(&self, image: &ImageRef, store: bool) -> Result<&WgpuTexture> {
        let texture = self.texture(image)?;
        let size = texture.texture.size();
        if image.extent[0] > size.width || image.extent[1] > size.height {
            return Err(Error::InvalidArgument(format!(
                "dispatch_images: {}x{} texels of a {}x{} texture",
                image.extent[0], image.extent[1], size.width, size.height
            )));
        }
        let (view, usage) = if store { (&texture.storage_view, "STORAGE_BINDING") } else { (&texture.sampled_view, "TEXTURE_BINDING") };
        if view.is_none() {
            return Err(Error::InvalidArgument(format!(
                "dispatch_images: the {:?} texture has no {usage} usage (it has {:?})",
                texture.texture.format(),
                texture.texture.usage()
            )));
        }
        Ok(texture)
    }

    /// The view a kernel writes `image` through.
    pub(super) fn storage_view(&self, image: &ImageRef) -> Result<wgpu::TextureView> {
        self.check_texture_store(image)?;
        self.texture(image)?.storage_view.clone().ok_or_else(|| Error::InvalidArgument("a texture without a storage view".into()))
    }

    /// The view a kernel samples `image` through.
    pub(super) fn sampled_view(&self, image: &ImageRef) -> Result<wgpu::TextureView> {
        self.check_texture_sample(image)?;
        self.texture(image)?.sampled_view.clone().ok_or_else(|| Error::InvalidArgument("a texture without a sampled view".into()))
    }

    /// The checks of a copy (`into_image`: into the texture) made before anything is recorded.
    pub(super) fn check_texture_copy(&self, image: &ImageRef, into_image: bool) -> Result<()> {
        let what = if into_image { "copy_buffer_to_image" } else { "copy_image_to_buffer" };
        image.check_copy(into_image, what)?;
        let texture = self.texture(image)?;
        let size = texture.texture.size();
        if image.extent[0] > size.width || image.extent[1] > size.height {
            return Err(Error::InvalidArgument(format!(
                "{what}: {}x{} texels of a {}x{} texture",
                image.extent[0], image.extent[1], size.width, size.height
            )));
        }
        let (needed, usage) = match (into_image, texture.depth_view.is_some()) {
            (true, true) => return Err(Error::InvalidArgument(format!("{what}: a frame writes no depth texture"))),
            (true, false) => (wgpu::TextureUsages::COPY_DST, "COPY_DST"),
            (false, true) => (wgpu::TextureUsages::TEXTURE_BINDING, "TEXTURE_BINDING"),
            (false, false) => (wgpu::TextureUsages::COPY_SRC, "COPY_SRC"),
        };
        if !texture.texture.usage().contains(needed) {
            return Err(Error::InvalidArgument(format!(
                "{what}: the {:?} texture needs {usage} usage (it has {:?})",
                texture.texture.format(),
                texture.texture.usage()
            )));
        }
        Ok(())
    }

    /// Records a copy between the top-left `image.extent` of a texture and `buffer[offset_words..]`,
    /// rows unpadded: one copy where a row is a multiple of 256 bytes (wgpu's row pitch), else one
    /// a row.
    pub(super) fn copy_texture(
        &mut self,
        image: ImageRef,
        buffer: BufferId,
        offset_words: u64,
        into_image: bool,
        label: &str,
    ) -> Result<()> {
        self.check_texture_copy(&image, into_image)?;
        self.check_range(buffer, offset_words, image.words())?;
        let texture = self.texture(&image)?;
        let (texture, depth_view) = (texture.texture.clone(), texture.depth_view.clone());
        if let Some(view) = depth_view {
            return self.read_depth(&view, buffer, offset_words, image.extent, label);
        }
        let target = self.buffer(buffer)?.buffer.clone();
        let [width, height] = image.extent;
        let aspect = wgpu::TextureAspect::All;
        let row_bytes = image.format.words_per_pixel() * 4 * width as u64;
        let rows: Vec<(u32, u32)> =
            if height == 1 || row_bytes.is_multiple_of(256) { vec![(0, height)] } else { (0..height).map(|y| (y, 1)).collect() };
        let encoder = self.encoder();
        for &(y, count) in &rows {
            let texel = wgpu::TexelCopyTextureInfo { texture: &texture, mip_level: 0, origin: wgpu::Origin3d { x: 0, y, z: 0 }, aspect };
            let layout = wgpu::TexelCopyBufferLayout {
                offset: offset_words * 4 + y as u64 * row_bytes,
                bytes_per_row: (count > 1).then_some(row_bytes as u32),
                rows_per_image: None,
            };
            let texels = wgpu::TexelCopyBufferInfo { buffer: &target, layout };
            let size = wgpu::Extent3d { width, height: count, depth_or_array_layers: 1 };
            if into_image {
                encoder.copy_buffer_to_texture(texels, texel, size)
            } else {
                encoder.copy_texture_to_buffer(texel, texels, size)
            }
        }
        let what = if into_image { "copy_buffer_to_image" } else { "copy_image_to_buffer" };
        self.counters.commands += rows.len() as u64;
        self.commands.extend(rows.iter().map(|_| Command::new(label, what)));
        Ok(())
    }

    /// Records the `texture_read` kernel: the depths of the top-left `extent` as f32 words.
    fn read_depth(&mut self, view: &wgpu::TextureView, buffer: BufferId, offset_words: u64, extent: [u32; 2], label: &str) -> Result<()> {
        let offset_words = u32::try_from(offset_words)
            .map_err(|_| Error::InvalidArgument(format!("`{label}`: a depth read at word {offset_words}, past 2^32")))?;
        let params = TextureReadParams { width: extent[0], height: extent[1], offset_words };
        let texels = extent[0] as u64 * extent[1] as u64;
        let groups = texels.div_ceil(THREADS as u64).clamp(1, self.limits.max_workgroup_count[0] as u64) as u32;
        let target = self.buffer(buffer)?.buffer.clone();
        let Pipeline { pipeline, layout } = self.depth_read_pipeline()?;
        let bind_group = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(label),
            layout: &layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(view) },
                wgpu::BindGroupEntry { binding: 1, resource: target.as_entire_binding() },
            ],
        });
        self.record_pass(DEPTH_TEXTURE_WORDS, &pipeline, &bind_group, bytemuck::bytes_of(&params), Groups::Direct([groups, 1, 1]), label);
        Ok(())
    }

    /// The `texture_read` kernel's pipeline, made on first use: a depth texture and a storage
    /// buffer, its parameters as immediates.
    fn depth_read_pipeline(&mut self) -> Result<Pipeline> {
        if let Some(pipeline) = &self.depth_read {
            return Ok(pipeline.clone());
        }
        let depth = texture_binding(0, true);
        let push_bytes = std::mem::size_of::<TextureReadParams>() as u32;
        let pipeline = self.compute_pipeline(DEPTH_TEXTURE_WORDS, &[depth, storage_binding(1, false)], push_bytes)?;
        self.depth_read = Some(pipeline.clone());
        Ok(pipeline)
    }
}
