//! The gathering baseline (Riguer et al. 2003) as a frame context: the window radius reduced on the
//! device from the frame's depths, so nothing is planned on the host.

use super::context::{ContextReport, Described, DofContext, Extent, remake};
use super::in_flight::{InFlight, per_frame};
use super::io::{
    Frame, ImageIo, Owned, check_frame, clamped_summary, context_pixels, output_buffer, ready, record_clamp_count, record_front,
    record_input, record_output,
};
use super::recording::{Recording, capture};
use crate::backend::{Backend, BufferId, RunKernel, groups_for};
use crate::error::{Error, Result};
use dof_shaders::gather::{GATHER, GATHER_PLAN, GatherParams, TILE, gather, gather_plan};

/// The scanned window is `2 r + 1` pixels wide: beyond this radius the gather's cost (quadratic in
/// it) belongs to a reduced-resolution path, which this baseline does not have.
pub const MAX_RADIUS: u32 = 48;

/// What a gathering context is created for.
#[derive(Clone, Debug)]
pub struct GatherContextDesc {
    pub max_width: u32,
    pub max_height: u32,
    /// Most slots per pixel of a multi-layer input (the gather reads the front one).
    pub max_layers: u32,
    /// Cap on the CoC radius, whole pixels (default and upper bound [`MAX_RADIUS`]).
    pub max_radius: Option<u32>,
    /// Hold the buffers that image inputs and outputs go through.
    pub image_io: bool,
    /// Frames in flight (default 1): copies kept of what the report reads.
    pub frames_in_flight: u32,
}

super::context::described!(GatherContextDesc);

impl GatherContextDesc {
    /// A description for frames up to `max`, with the defaults of the rest.
    pub fn new(max: Extent) -> Self {
        let Extent { width: max_width, height: max_height, layers: max_layers } = max;
        GatherContextDesc { max_width, max_height, max_layers, max_radius: None, image_io: false, frames_in_flight: 1 }
    }
}

/// Records the window radius's reduction over `b.depth` into `b.plan` (zeroed first), then the
/// gather with radii capped at `cap`.
pub(crate) fn record_gather(backend: &mut dyn Backend, f: &Frame, cap: u32, b: gather::Bindings<BufferId>) -> Result<()> {
    let params = GatherParams { width: f.width, height: f.height, max_radius: cap, _pad: 0, lens: f.lens };
    backend.fill(b.plan, 0, 1, 0, "gather/plan")?;
    let pixel_groups = groups_for(&GATHER_PLAN, f.width as u64 * f.height as u64);
    backend.run(gather_plan::Bindings { depth: b.depth, plan: b.plan }, pixel_groups, &params, "gather/plan")?;
    let groups = [f.width.div_ceil(TILE), f.height.div_ceil(TILE), 1];
    backend.run(b, groups, &params, "gather")
}

/// A gathering context (see the [module docs](crate::frame)).
pub struct GatherContext {
    desc: GatherContextDesc,
    cap: u32,
    color: BufferId,
    depth: BufferId,
    /// Per frame in flight: the window radius its report reads.
    plans: Vec<BufferId>,
    in_flight: InFlight<()>,
    io: Option<ImageIo>,
    owned: Owned,
}

impl GatherContext {
    pub fn new(backend: &mut dyn Backend, desc: &GatherContextDesc) -> Result<Self> {
        let cap = desc.max_radius.unwrap_or(MAX_RADIUS);
        if cap > MAX_RADIUS {
            return Err(Error::TooLarge { what: "gather radius (px)".into(), size: cap as u64, limit: MAX_RADIUS as u64 });
        }
        let pixels = context_pixels(backend, "gathering", desc.max_width, desc.max_height, desc.max_layers)?;
        let in_flight = InFlight::new(desc.frames_in_flight)?;
        let mut owned = Owned::default();
        let made = (|| {
            let color = owned.make(backend, 3 * pixels, "gather/color")?;
            let depth = owned.make(backend, pixels, "gather/depth")?;
            // Per frame: the window radius, then the count of clamped input colours.
            let plans = per_frame(&mut owned, backend, desc.frames_in_flight, 2, "gather/plan")?;
            let io = if desc.image_io { Some(ImageIo::new(backend, pixels, &mut owned)?) } else { None };
            Ok((color, depth, plans, io))
        })();
        let ((color, depth, plans, io), owned) = owned.or_free(backend, made)?;
        let ctx = GatherContext { desc: desc.clone(), cap, color, depth, plans, in_flight, io, owned };
        let mut kernels = vec![&GATHER, &GATHER_PLAN];
        kernels.extend(dof_shaders::frame_io::KERNELS);
        kernels.extend(dof_shaders::radiance::KERNELS);
        ready(backend, ctx, &kernels, &[], Self::destroy)
    }

    pub fn destroy(self, backend: &mut dyn Backend) {
        self.owned.free(backend);
    }

    pub fn device_bytes(&self) -> u64 {
        self.owned.bytes()
    }

    /// Records one frame: the front layer of the input, the radius reduction, the gather.
    pub fn recording(&mut self, backend: &dyn Backend, f: &Frame) -> Result<Recording> {
        check_frame(backend, f, &self.owned, self.desc.extent(), self.io.as_ref())?;
        let recording = capture(self, backend, f, Self::commands)?;
        self.in_flight.recorded(());
        Ok(recording)
    }

    /// The frame's commands (captured, and checked, by [`capture`]).
    fn commands(&mut self, backend: &mut dyn Backend, f: &Frame) -> Result<()> {
        let slots = record_input(backend, f, self.io.as_ref())?;
        let output = output_buffer(f, self.io.as_ref())?;
        record_front(backend, f, slots, self.color, self.depth)?;
        let plan = self.plans[self.in_flight.next()];
        record_clamp_count(backend, f, slots, 1, plan, 1)?;
        let bindings = gather::Bindings { color: self.color, depth: self.depth, out: output, plan };
        record_gather(backend, f, self.cap, bindings)?;
        record_output(backend, f, self.io.as_ref())
    }

    /// The window radius the last frame scanned (reads it back: call once the frame completed).
    pub fn radius(&self, backend: &mut dyn Backend) -> Result<u32> {
        self.radius_of(backend, 0)
    }

    /// The window radius the frame recorded `frames_ago` recordings before the last scanned (see
    /// [`DofContext::report_frame`]).
    pub fn radius_of(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<u32> {
        self.owned.check(backend)?;
        Ok(self.plan_of(backend, frames_ago)?.0)
    }

    /// The window radius and the clamped input colours of the frame `frames_ago` recordings
    /// before the last.
    fn plan_of(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<(u32, u32)> {
        self.owned.check(backend)?;
        let (slot, ()) = self.in_flight.slot(frames_ago)?;
        let words = backend.read_buffer(self.plans[slot], 0, 2)?;
        Ok((words[0].min(self.cap), words[1]))
    }
}

impl DofContext for GatherContext {
    fn method(&self) -> &'static str {
        "gather"
    }
    fn extent(&self) -> Extent {
        self.desc.extent()
    }
    fn recording(&mut self, backend: &dyn Backend, frame: &Frame) -> Result<Recording> {
        GatherContext::recording(self, backend, frame)
    }
    fn frames_in_flight(&self) -> u32 {
        self.in_flight.frames()
    }
    fn report_frame(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<ContextReport> {
        let (radius, clamped) = self.plan_of(backend, frames_ago)?;
        Ok(ContextReport {
            summary: format!("gathered over a window of radius {radius} px (cap {} px){}", self.cap, clamped_summary(clamped)),
            details: Some(std::sync::Arc::new(GatherReport { radius_px: radius, clamped })),
            ..Default::default()
        })
    }
    fn device_bytes(&self) -> u64 {
        GatherContext::device_bytes(self)
    }
    fn resize(&mut self, backend: &mut dyn Backend, extent: Extent) -> Result<()> {
        self.owned.check(backend)?;
        let desc = self.desc.clone();
        remake(self, backend, &desc, extent, GatherContext::new, GatherContext::destroy)
    }
    fn destroy(self: Box<Self>, backend: &mut dyn Backend) {
        GatherContext::destroy(*self, backend)
    }
}

/// What a gather frame did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GatherReport {
    /// The CoC radius scanned (px): the frame's largest, up to the cap.
    pub radius_px: u32,
    /// Input values clamped where read (the numerical contract).
    pub clamped: u32,
}

super::context::report_details!(GatherReport, |r| vec![("radius_px", r.radius_px as f64), ("clamped", r.clamped as f64)]);
