//! Rasterising triangle meshes (glTF scenes) into the multi-layer image and the
//! accumulation-buffer reference (Franke et al. 2018, §4).
//!
//! - [`mesh`]: the scene's buffers and the lighting model;
//! - [`project`]: the clip transform, culling and homogeneous rasterisation;
//! - [`texture`]: texture lookups;
//! - [`draw`]: the depth-tested draw into a visibility buffer (graphics stages and CPU fallback);
//! - [`shade`]: the visibility buffer shaded into a layer or the accumulation buffer.

pub mod draw;
pub mod mesh;
pub mod project;
pub mod shade;
pub mod texture;

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 3] = [&draw::RASTER_SETUP, &draw::RASTER_FALLBACK, &shade::RASTER_SHADE];
