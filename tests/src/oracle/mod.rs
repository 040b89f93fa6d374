//! Host-driven oracles the suites compare the frame API's contexts with: one-shot paths that
//! allocate, upload and read back per call, and a splatting frame read back stage by stage.

pub mod layered;
pub mod raytrace;
pub mod splat_stages;
