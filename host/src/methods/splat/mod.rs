//! Tiled splatting on any backend (kernels and the algorithm in `dof_shaders::splat`): multi-layer
//! (seed 000) on a partial multi-layer image, single-layer (seed 003) on its front layer.
//!
//! [`plan`] decides per frame what the scene needs (rings from the largest CoC present, merging only
//! where something is blurred enough to merge); [`run`] records the stages and reads back what was
//! left out, so every result carries a [`SplatReport`] ([`report`]).

mod plan;
mod report;
mod run;

pub use plan::{Merge, Plan, SplatOptions};
pub use report::SplatReport;
pub use run::{Intermediates, SplatOutput, splat};
