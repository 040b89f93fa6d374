//! Thin-lens ray tracing through the multi-layer image (kernels and their rules in
//! `dof_shaders::raytrace`): a min/max hierarchy of the signed CoC, then `spp` rays per pixel. The
//! context, [`crate::frame::RaytraceContext`], makes the lens samples and holds the options; a
//! frame of it is [`super::one_shot`].

pub use crate::frame::raytrace::{MAX_PATTERNS, MAX_SPP, RaytraceOptions, lens_samples};
