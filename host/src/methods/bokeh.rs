//! Bokeh sprites over a gathering blur (de Rousiers, Pettineo; kernels, shaders and the sprite
//! layout in `dof_shaders::bokeh`): one frame of a host image through
//! [`crate::frame::BokehContext`], one submission, and the detection count read back afterwards
//! for the report.

use super::buffers::read_rgb;
use crate::backend::{Backend, CommandTime, with_buffers};
use crate::error::{Error, Result};
use crate::frame::{BokehContext, BokehContextDesc, Frame};
use crate::layers::RgbImage;
use crate::aperture::ApertureShape;
use dof_shaders::lens::ThinLens;


#[derive(Clone, Debug)]
pub struct BokehOptions {
    /// Luminance above the 5x5 neighbourhood's mean that makes a sprite (`LumThreshold`, linear
    /// units; default 1, a diffuse white).
    pub lum_threshold: f32,
    /// Smallest CoC radius (px) that makes a sprite (`CoCThreshold`; default 2).
    pub coc_threshold: f32,
    /// Sprites the buffer holds (default 4096); more are counted and left in the blur.
    pub capacity: u32,
    /// Largest sprite CoC radius (px; default 256).
    pub max_radius: f32,
    pub aperture: ApertureShape,
}

impl Default for BokehOptions {
    fn default() -> Self {
        BokehOptions { lum_threshold: 1.0, coc_threshold: 2.0, capacity: 4096, max_radius: 256.0, aperture: ApertureShape::circle() }
    }
}

pub struct BokehOutput {
    pub image: RgbImage,
    pub times: Vec<CommandTime>,
    /// Bright pixels detected, and those beyond the capacity (left in the blur).
    pub detected: u64,
    pub overflow: u64,
    /// Radius the gather scanned.
    pub blur_radius: u32,
    pub buffer_bytes: u64,
}

pub fn bokeh(backend: &mut dyn Backend, image: &RgbImage, depth: &[f32], lens: &ThinLens, options: &BokehOptions) -> Result<BokehOutput> {
    let (width, height) = (image.width, image.height);
    let pixels = width as u64 * height as u64;
    if pixels == 0 || image.data.len() as u64 != pixels || depth.len() as u64 != pixels {
        return Err(Error::InvalidArgument(format!("bokeh sprites need a non-empty {width}x{height} image with one depth per pixel")));
    }
    if !lens.is_valid() {
        return Err(Error::InvalidArgument(format!("invalid lens: {lens:?}")));
    }
    crate::frame::bokeh::check_options(options)?;
    let slots: Vec<u32> = image.data.iter().zip(depth).flat_map(|(c, z)| [c[0].to_bits(), c[1].to_bits(), c[2].to_bits(), z.to_bits()]).collect();
    let desc = BokehContextDesc::new(width, height, 1, options.clone());
    let sizes = [(4 * pixels, "bokeh/input"), (pixels, "bokeh/input-counts"), (3 * pixels, "bokeh/out")];
    with_buffers(backend, &sizes, |backend, b| {
        backend.write_buffer(b[0], 0, &slots)?;
        backend.write_buffer(b[1], 0, &vec![1u32; pixels as usize])?;
        let mut ctx = BokehContext::new(backend, &desc)?;
        let ran = (|| {
            ctx.record(backend, &Frame::layers(width, height, 1, *lens, b[0], b[1], b[2]))?;
            let times = backend.submit()?;
            let (detected, blur_radius) = ctx.detected_and_radius(backend)?;
            Ok(BokehOutput {
                image: read_rgb(backend, b[2], width, height)?,
                times,
                detected,
                overflow: detected.saturating_sub(options.capacity as u64),
                blur_radius,
                buffer_bytes: ctx.device_bytes() + 4 * 8 * pixels,
            })
        })();
        ctx.destroy(backend);
        ran
    })
}
