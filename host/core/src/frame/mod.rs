//! The frame API: a context created once per device, maximum extent, method and quality, which
//! records one depth-of-field frame at a time against buffers the caller owns.
//!
//! The shape follows an effect API such as AMD FidelityFX's (create, record, destroy): the context
//! allocates every transient buffer and builds every plan bound when it is created, so a frame
//! only records commands. Per frame there is
//! - no allocation: lists come from a pool whose size is fixed at creation, and a list that does
//!   not fit is counted on the device and its tile copied through (never written out of bounds);
//! - no host readback and no pass over the image on the host: the largest CoC, the rings and the
//!   colour scale are reduced on the device, and the sort's dispatch sizes are written there for
//!   indirect dispatch;
//! - no submission: the caller submits (on Vulkan, `VulkanBackend::begin_external` records into
//!   the caller's own command buffer; standalone, one `submit` runs the frame).
//!
//! Every context implements [`DofContext`] (record, report, device bytes, resize, destroy), and
//! [`registry::METHODS`] lists them with their names, papers, knobs and constructors: callers that
//! drive several methods hold `Box<dyn DofContext>` and never match on a method. What a frame did
//! and left out stays on the device until the caller asks for it ([`DofContext::report`]), after
//! the frame's work has completed. A context made for N frames in flight keeps N copies of that
//! and nothing else ([`DofContext::report_frame`]; the transient buffers are shared, ordered on
//! one queue by barriers).
//!
//! Methods: multi-layer tiled splatting (Franke, Hofmann, Stamminger, Selgrad 2018) and its
//! single-layer predecessor (Selgrad, Franke, Stamminger 2016, the same pipeline on the front
//! layer) run through [`SplatContext`], the gathering baseline (Riguer et al. 2003) through
//! [`GatherContext`], the engine-grade gather (after AMD FidelityFX DoF, Unreal Engine's Diaphragm
//! DoF and Jimenez 2014) through [`RingGatherContext`], bokeh sprites (de Rousiers, Pettineo)
//! through [`BokehContext`], ray tracing through layers (Lee et al. 2010) through
//! [`RaytraceContext`] (hierarchy sized for the largest frame, lens samples written at creation),
//! layered DoF with matting (Schedl, Wimmer 2012) through [`LayeredContext`], whose layer plan
//! (the signed-CoC range and which candidate layers are used) is a device reduction over layers
//! fixed at creation, and scatter-as-you-gather with tile depth separation (Jimenez 2014) through
//! [`ScatterGatherContext`]. Every context records the same [`Frame`] description. The one-shot functions
//! in `methods` of the crate `dof` above the core (what the CLI, the evaluation and the tests call) run one frame through
//! these contexts, except ray tracing's and layered DoF's, which keep their own per-call paths
//! (ray tracing's records the context's kernels; layered DoF's plans on the host and is the
//! oracle the context is tested against).

pub mod bokeh;
pub mod context;
pub mod gather;
mod in_flight;
pub mod io;
pub mod layer_options;
pub mod layered;
pub mod options;
pub mod peel;
pub mod raytrace;
pub mod recording;
pub mod registry;
pub mod renderer_peel;
pub mod ring_gather;
pub mod scatter_gather;
pub mod splat;
mod transient;

pub use bokeh::{BokehContext, BokehContextDesc, BokehOptions, BokehReport};
pub use context::{ContextReport, DofContext, Extent, ReportDetails};
pub use gather::{GatherContext, GatherContextDesc, GatherReport};
pub use in_flight::MAX_FRAMES_IN_FLIGHT;
pub use io::{CountBuffer, DepthEncoding, Frame, FrameInput, FrameOutput, RgbBuffer, SLOT_WORDS, SlotBuffer, SlotLayout};
pub use layer_options::{GuardBand, LayerOptions};
pub use layered::{LayeredContext, LayeredContextDesc, LayeredOptions, LayeredPlanReport, LayeredReport};
pub use options::{Kind, MethodOption, MethodOptions, OptionSpec, Setting, Value};
pub use raytrace::{RaytraceContext, RaytraceContextDesc, RaytraceOptions, RaytraceReport};
pub use recording::{Command, Groups, Recording, TransientUse};
pub use registry::{Column, ContextDesc, METHODS, MethodInfo, Reach, Reads, Scale, Stage, Sweep, Tolerances, VulkanTolerance};
pub use renderer_peel::{RendererPeel, RendererPeelDesc};
pub use ring_gather::{RingGatherContext, RingGatherContextDesc, RingGatherOptions, RingGatherReport};
pub use scatter_gather::{ScatterGatherContext, ScatterGatherContextDesc, ScatterGatherOptions, ScatterGatherReport};
pub use splat::{Merge, SplatContext, SplatContextDesc, SplatOptions, SplatReport};
