//! What only tests use (feature `testing`, off by default; the workspace's tests crate turns it
//! on): a splatting context that keeps each stage's buffers apart and hands them out, and the
//! ray tracer's recording for the one-shot oracle that the suites compare its context with. A
//! renderer's build does not see any of it.

use crate::backend::{Backend, BufferId};
use crate::error::Result;
use crate::frame::splat::{SplatContext, SplatContextDesc};
use dof_shaders::raytrace::{TraceParams, raytrace_trace};

pub use crate::frame::splat::StageBuffers;

/// A splatting context that keeps each stage's buffers apart instead of reusing one stage's for a
/// later one (two more list-sized buffers), so that [`stage_buffers`] can read every stage. Resizing
/// and growing keep it so.
pub fn splat_context_with_distinct_stages(backend: &mut dyn Backend, desc: &SplatContextDesc) -> Result<SplatContext> {
    SplatContext::build(backend, desc, true)
}

/// The context's buffers of each stage, for comparing backends stage by stage. Only a context made
/// by [`splat_context_with_distinct_stages`] holds every stage's data after a frame.
pub fn stage_buffers(ctx: &SplatContext) -> StageBuffers {
    ctx.stage_buffers()
}

/// Records the ray tracer's hierarchy and trace over the caller's bindings, as its context does.
pub fn record_trace(backend: &mut dyn Backend, params: &TraceParams, b: raytrace_trace::Bindings<BufferId>) -> Result<()> {
    crate::frame::raytrace::record_trace(backend, params, b)
}
