//! Bokeh sprites over a gathering blur (de Rousiers, Pettineo; kernels, shaders and the sprite
//! layout in `dof_shaders::bokeh`): one frame of a host image through
//! [`crate::frame::BokehContext`], one submission, and the detection count read back afterwards
//! for the report.

use super::buffers::one_layer_frame;
use crate::backend::{Backend, CommandTime};
use crate::frame::Extent;
pub use crate::frame::bokeh::BokehOptions;
use crate::frame::{BokehContext, BokehContextDesc, DofContext};
use crate::layers::RgbImage;
use dof_core::error::Result;
use dof_shaders::lens::ThinLens;

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
    crate::frame::bokeh::check_options(options)?;
    let desc = BokehContextDesc::new(Extent::new(image.width, image.height, 1), options.clone());
    let (out, (times, (detected, blur_radius), context_bytes)) =
        one_layer_frame(backend, "bokeh sprites", image, depth, lens, |backend, frame| {
            let mut ctx = BokehContext::new(backend, &desc)?;
            let ran = (|| {
                ctx.record(backend, frame)?;
                let times = backend.submit()?;
                Ok((times, ctx.detected_and_radius(backend)?, ctx.device_bytes()))
            })();
            ctx.destroy(backend);
            ran
        })?;
    let pixels = image.width as u64 * image.height as u64;
    Ok(BokehOutput {
        image: out,
        times,
        detected,
        overflow: detected.saturating_sub(options.capacity as u64),
        blur_radius,
        buffer_bytes: context_bytes + 4 * 8 * pixels,
    })
}
