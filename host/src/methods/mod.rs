//! Depth-of-field methods, each a sequence of kernel dispatches recorded on any
//! [`crate::backend::Backend`], so it runs on the CPU and on Vulkan from the same kernels.

pub mod bokeh;
pub mod buffers;
pub mod gather;
pub mod one_shot;
pub mod raytrace;
pub mod ring_gather;
pub mod splat;
