//! What only tests use (feature `testing`, off by default; the workspace's tests crate turns it
//! on): a splatting context's last frame parameters and the buffers its recording does not list, and the ray tracer's
//! recording for the one-shot oracle that the suites compare its context with. A renderer's build
//! does not see any of it.

use crate::backend::{Backend, BufferId};
use crate::error::Result;
use crate::frame::splat::SplatContext;
use dof_shaders::raytrace::{TraceParams, raytrace_trace};

pub use crate::frame::splat::StageBuffers;

/// What comparing backends stage by stage needs besides the recording's transients (which a later
/// stage's transient may share a buffer with: read each as its last command leaves it, by encoding
/// the frame's recording in parts).
pub fn stage_buffers(ctx: &SplatContext) -> StageBuffers {
    ctx.stage_buffers()
}

/// Records the ray tracer's hierarchy and trace over the caller's bindings, as its context does.
pub fn record_trace(backend: &mut dyn Backend, params: &TraceParams, b: raytrace_trace::Bindings<BufferId>) -> Result<()> {
    crate::frame::raytrace::record_trace(backend, params, b)
}
