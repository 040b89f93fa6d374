//! Tiled splatting on any backend (kernels and the algorithm in `dof_shaders::splat`): multi-layer
//! (Franke, Hofmann, Stamminger, Selgrad 2018) on a partial multi-layer image, single-layer
//! (Selgrad, Franke, Stamminger 2016) on its front layer.
//!
//! The frame is recorded by [`crate::frame::SplatContext`], which plans it on the device (rings
//! from the largest CoC present, the colour scale from the brightest colour); [`splat`] runs one
//! frame of a host image through it and reads back the image and what was left out, so every
//! result carries a [`SplatReport`].

mod run;

pub use crate::frame::splat::{Merge, SplatOptions, SplatPlanReport, SplatReport};
pub use run::{SplatOutput, splat, splat_then};
