//! Triangle-mesh scenes (glTF) on the device: rasterised into the partial multi-layer image by
//! depth peeling, and into the accumulation-buffer reference (Franke et al. 2018, §4; kernels and shaders in
//! `dof_shaders::raster`).
//!
//! - [`mesh`]: the mesh as the rasteriser takes it, and its upload;
//! - [`mipmap`]: its textures as the shading samples them (mip chains of half floats);
//! - [`view`]: the clip transform for a pinhole or for one lens point (sheared frustum);
//! - [`peel`]: depth peeling with the umbra threshold, then the disocclusion buffer (the host
//!   oracle, reading each pass back);
//! - [`peel_context`]: the same peel recorded on the device, frame after frame, without readback;
//! - [`mod@accumulate`]: the accumulation-buffer reference.
//!
//! Both run on either backend: on Vulkan through the graphics pipeline (rust-gpu vertex and
//! fragment shaders, a depth attachment), on the CPU through the draw's compute fallback.

pub mod accumulate;
pub mod mesh;
pub mod mipmap;
pub mod peel;
pub mod peel_context;
pub mod view;

pub use accumulate::{AccumulateOptions, Accumulated, accumulate, accumulate_with};
pub use mesh::{DeviceMesh, RasterScene};
pub use peel::{MAX_PASSES, Peeled, check_texture_probes, peel_layers, peel_layers_with, peel_passes};
pub use peel_context::{MeshPeelContext, MeshPeelDesc};
pub use view::{View, default_near};
