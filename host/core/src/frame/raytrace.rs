//! Thin-lens ray tracing through the layers (Lee et al. 2010; kernels and their rules in
//! `dof_shaders::raytrace`) as a frame context: a min/max hierarchy of the signed CoC, then `spp`
//! rays a pixel. Every buffer is made at creation for the largest frame (the hierarchy for its
//! levels), and the lens samples are written then too: they depend only on the options. A frame
//! clears the missed-ray count, builds the hierarchy level by level (the level count and offsets
//! follow from the frame's size, a parameter, not from its data) and traces.
//!
//! Lens samples: `patterns` independent sets of `spp` points stratified over the lens disc (the
//! reference renderer's sampler and concentric mapping), each pixel picking a set by a hash, so
//! neighbouring pixels do not share one noise pattern. Both backends get the same buffer, so both
//! trace the same rays.

use super::context::{ContextReport, Described, DofContext, Extent, remake};
use super::in_flight::{InFlight, per_frame};
use super::io::{
    Frame, ImageIo, Owned, check_frame, clamped_summary, context_pixels, output_buffer, ready, record_clamp_count, record_input,
    record_output,
};
use super::recording::{Recording, capture};
use crate::backend::{Backend, BufferId, RunKernel, groups_for};
use crate::error::{Error, Result};
// The sampler is a leaf module of pure functions (the reference renderer's), shared so that the
// traced rays are stratified the same way.
use crate::sampling::{concentric_disc, pixel_rng, stratified};
use dof_shaders::raytrace::{
    MAX_LEVELS, RT_BASE, RT_REDUCE, STATS_WORDS, TILE, TraceParams, level_offsets, levels_for, raytrace_base, raytrace_reduce,
    raytrace_trace,
};

/// Rays per pixel at most.
pub const MAX_SPP: u32 = 4096;
/// Sample patterns at most.
pub const MAX_PATTERNS: u32 = 256;
/// The largest side the hierarchy covers with one top cell ([`MAX_LEVELS`] levels).
pub const MAX_SIDE: u32 = 1 << (MAX_LEVELS - 1);

/// Ray tracing's settings; all fixed at creation (the lens samples depend on them).
#[derive(Clone, Debug, PartialEq)]
pub struct RaytraceOptions {
    /// Rays per pixel, `1..=MAX_SPP`.
    pub spp: u32,
    /// Independent sample sets pixels choose from, `1..=MAX_PATTERNS` (default 16).
    pub patterns: u32,
    pub seed: u64,
}

impl Default for RaytraceOptions {
    fn default() -> Self {
        RaytraceOptions { spp: 16, patterns: 16, seed: 0x5eed }
    }
}

impl RaytraceOptions {
    /// Refuses a ray or pattern count out of range.
    pub fn check(&self) -> Result<()> {
        if !(1..=MAX_SPP).contains(&self.spp) {
            return Err(Error::InvalidArgument(format!("rays per pixel must be 1 to {MAX_SPP}, got {}", self.spp)));
        }
        if !(1..=MAX_PATTERNS).contains(&self.patterns) {
            return Err(Error::InvalidArgument(format!("sample patterns must be 1 to {MAX_PATTERNS}, got {}", self.patterns)));
        }
        Ok(())
    }
}

/// `patterns` sets of `spp` lens points in the unit disc, stratified, as `[x, y]` word pairs.
pub fn lens_samples(spp: u32, patterns: u32, seed: u64) -> Vec<u32> {
    let mut words = Vec::with_capacity(2 * (spp * patterns) as usize);
    let (mut samples, mut perm) = (Vec::new(), Vec::new());
    for pattern in 0..patterns {
        let mut rng = pixel_rng(seed, 0, pattern as u64);
        stratified(spp, true, &mut rng, &mut samples, &mut perm);
        for s in &samples {
            let (x, y) = concentric_disc(s.lens.0, s.lens.1);
            words.extend_from_slice(&[x.to_bits(), y.to_bits()]);
        }
    }
    words
}

/// The kernel parameters of a `width` x `height` frame with `layers` slots a pixel: the hierarchy's
/// level count and offsets follow from the size. Returns them with the hierarchy's cell count.
pub fn trace_params(
    width: u32,
    height: u32,
    layers: u32,
    options: &RaytraceOptions,
    lens: dof_shaders::lens::ThinLens,
) -> (TraceParams, u64) {
    let mut params = TraceParams {
        width,
        height,
        max_layers: layers,
        levels: levels_for(width, height),
        spp: options.spp,
        patterns: options.patterns,
        lens,
        ..Default::default()
    };
    let (offsets, cells) = level_offsets(&params);
    params.offsets = offsets;
    (params, cells)
}

/// Records the hierarchy and the trace of one frame over `b.input` and `b.counts` into `b.out`,
/// counting missed rays into `b.stats` (cleared first): what the context runs, over any buffers
/// (the one-shot oracle of the suites runs it over its own).
pub fn record_trace(backend: &mut dyn Backend, params: &TraceParams, b: raytrace_trace::Bindings<BufferId>) -> Result<()> {
    let pixels = params.width as u64 * params.height as u64;
    backend.fill(b.stats, 0, STATS_WORDS as u64, 0, "raytrace/stats")?;
    let base = raytrace_base::Bindings { input: b.input, counts: b.counts, hier: b.hier };
    backend.run(base, groups_for(&RT_BASE, pixels), params, "raytrace/hierarchy")?;
    for level in 1..params.levels {
        let p = TraceParams { level, ..*params };
        let (w, h) = dof_shaders::raytrace::level_size(&p, level);
        backend.run(raytrace_reduce::Bindings { hier: b.hier }, groups_for(&RT_REDUCE, w as u64 * h as u64), &p, "raytrace/hierarchy")?;
    }
    let tiles = [params.width.div_ceil(TILE), params.height.div_ceil(TILE), 1];
    backend.run(b, tiles, params, "raytrace/trace")
}

/// What a ray-tracing context is created for.
#[derive(Clone, Debug)]
pub struct RaytraceContextDesc {
    pub max_width: u32,
    pub max_height: u32,
    /// Most fragment slots per pixel of the input.
    pub max_layers: u32,
    pub options: RaytraceOptions,
    /// Hold the buffers that image inputs and outputs go through.
    pub image_io: bool,
    /// Frames in flight (default 1): copies kept of what the report reads.
    pub frames_in_flight: u32,
}

impl RaytraceContextDesc {
    /// A description for frames up to `max`, with the defaults of the rest.
    pub fn new(max: Extent, options: RaytraceOptions) -> Self {
        let Extent { width: max_width, height: max_height, layers: max_layers } = max;
        RaytraceContextDesc { max_width, max_height, max_layers, options, image_io: false, frames_in_flight: 1 }
    }
}

/// A ray-tracing context (see the [module docs](crate::frame)).
pub struct RaytraceContext {
    desc: RaytraceContextDesc,
    /// The min/max hierarchy, sized for the largest frame's levels.
    hier: BufferId,
    /// The lens samples, written at creation.
    samples: BufferId,
    /// Per frame in flight, [`STATS_WORDS`] (the missed rays of its frame), then the count of
    /// clamped input colours.
    stats: Vec<BufferId>,
    io: Option<ImageIo>,
    owned: Owned,
    /// Per frame in flight, the pixels and hierarchy levels of its frame (for its report).
    in_flight: InFlight<(u64, u32)>,
}

impl RaytraceContext {
    pub fn new(backend: &mut dyn Backend, desc: &RaytraceContextDesc) -> Result<Self> {
        desc.options.check()?;
        let pixels = context_pixels(backend, "raytrace", desc.max_width, desc.max_height, desc.max_layers)?;
        if desc.max_width > MAX_SIDE || desc.max_height > MAX_SIDE {
            return Err(Error::InvalidArgument(format!(
                "ray tracing's hierarchy covers sides up to {MAX_SIDE} px, got {}x{}",
                desc.max_width, desc.max_height
            )));
        }
        // Every smaller frame's levels fit in the largest one's: each level is at most as large.
        let (_, cells) = trace_params(desc.max_width, desc.max_height, desc.max_layers, &desc.options, Default::default());
        let sample_words = lens_samples(desc.options.spp, desc.options.patterns, desc.options.seed);
        let max_words = backend.limits().max_buffer_bytes / 4;
        for (words, what) in
            [(2 * cells, "raytrace/hierarchy"), (sample_words.len() as u64, "raytrace/samples"), (3 * pixels, "raytrace/out")]
        {
            if words > max_words {
                return Err(Error::TooLarge { what: format!("{what} (words)"), size: words, limit: max_words });
            }
        }
        let in_flight = InFlight::new(desc.frames_in_flight)?;
        let mut owned = Owned::default();
        let made = (|| {
            let hier = owned.make(backend, 2 * cells, "raytrace/hierarchy")?;
            let samples = owned.make(backend, sample_words.len() as u64, "raytrace/samples")?;
            let stats = per_frame(&mut owned, backend, desc.frames_in_flight, STATS_WORDS as u64 + 1, "raytrace/stats")?;
            backend.write_buffer(samples, 0, &sample_words)?;
            let io = if desc.image_io { Some(ImageIo::new(backend, pixels, &mut owned)?) } else { None };
            Ok((hier, samples, stats, io))
        })();
        let ((hier, samples, stats, io), owned) = owned.or_free(backend, made)?;
        let ctx = RaytraceContext { desc: desc.clone(), hier, samples, stats, io, owned, in_flight };
        let mut kernels = dof_shaders::raytrace::KERNELS.to_vec();
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

    pub fn options(&self) -> &RaytraceOptions {
        &self.desc.options
    }

    /// Records one frame: the missed-ray count cleared, the hierarchy, the trace.
    pub fn recording(&mut self, backend: &dyn Backend, f: &Frame) -> Result<Recording> {
        check_frame(backend, f, &self.owned, self.desc.extent(), self.io.as_ref())?;
        let recording = capture(self, backend, f, Self::commands)?;
        let levels = trace_params(f.width, f.height, f.layer_count(), &self.desc.options, f.lens).0.levels;
        self.in_flight.recorded((f.width as u64 * f.height as u64, levels));
        Ok(recording)
    }

    /// The frame's commands (captured, and checked, by [`capture`]).
    fn commands(&mut self, backend: &mut dyn Backend, f: &Frame) -> Result<()> {
        let d = &self.desc;
        let (input, counts) = record_input(backend, f, self.io.as_ref())?;
        let output = output_buffer(f, self.io.as_ref())?;
        let (params, _) = trace_params(f.width, f.height, f.layer_count(), &d.options, f.lens);
        let stats = self.stats[self.in_flight.next()];
        record_clamp_count(backend, f, (input, counts), f.layer_count(), stats, STATS_WORDS)?;
        let trace = raytrace_trace::Bindings { input, counts, hier: self.hier, samples: self.samples, out: output, stats };
        record_trace(backend, &params, trace)?;
        record_output(backend, f, self.io.as_ref())
    }

    /// Rays of the last frame that hit no stored fragment (reads the device: call once the frame
    /// completed).
    pub fn missed_rays(&self, backend: &mut dyn Backend) -> Result<u64> {
        Ok(self.missed_rays_of(backend, 0)?.0)
    }

    /// The missed rays of the frame recorded `frames_ago` recordings before the last (see
    /// [`DofContext::report_frame`]), with that frame's pixels and hierarchy levels.
    fn missed_rays_of(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<(u64, (u64, u32))> {
        let (missed, _, kept) = self.stats_of(backend, frames_ago)?;
        Ok((missed, kept))
    }

    /// The missed rays and clamped input colours of the frame `frames_ago` recordings before the
    /// last, with that frame's pixels and hierarchy levels.
    fn stats_of(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<(u64, u32, (u64, u32))> {
        self.owned.check(backend)?;
        let (slot, kept) = self.in_flight.slot(frames_ago)?;
        let words = backend.read_buffer(self.stats[slot], 0, STATS_WORDS as u64 + 1)?;
        Ok((words[0] as u64, words[STATS_WORDS as usize], kept))
    }
}

impl DofContext for RaytraceContext {
    fn method(&self) -> &'static str {
        "raytrace"
    }
    fn extent(&self) -> Extent {
        self.desc.extent()
    }
    fn recording(&mut self, backend: &dyn Backend, frame: &Frame) -> Result<Recording> {
        RaytraceContext::recording(self, backend, frame)
    }
    fn frames_in_flight(&self) -> u32 {
        self.in_flight.frames()
    }
    fn report_frame(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<ContextReport> {
        let (missed, clamped, (pixels, levels)) = self.stats_of(backend, frames_ago)?;
        let spp = self.desc.options.spp;
        let rays = pixels * spp as u64;
        Ok(ContextReport {
            summary: format!(
                "{spp} rays per pixel, {levels}-level hierarchy; {missed} of {rays} rays ({:.2}%) hit no stored fragment{}",
                100.0 * missed as f64 / rays.max(1) as f64,
                clamped_summary(clamped)
            ),
            details: Some(std::sync::Arc::new(RaytraceReport { spp, levels, rays, missed_rays: missed, clamped })),
            ..Default::default()
        })
    }
    fn device_bytes(&self) -> u64 {
        RaytraceContext::device_bytes(self)
    }
    fn resize(&mut self, backend: &mut dyn Backend, extent: Extent) -> Result<()> {
        self.owned.check(backend)?;
        let desc = self.desc.clone();
        remake(self, backend, &desc, extent, RaytraceContext::new, RaytraceContext::destroy)
    }
    fn destroy(self: Box<Self>, backend: &mut dyn Backend) {
        RaytraceContext::destroy(*self, backend)
    }
}

super::context::described!(RaytraceContextDesc);

/// What a frame of ray tracing through the layers did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RaytraceReport {
    pub spp: u32,
    /// Levels of the min/max hierarchy.
    pub levels: u32,
    pub rays: u64,
    /// Rays that hit no stored fragment.
    pub missed_rays: u64,
    /// Input values clamped where read (the numerical contract).
    pub clamped: u32,
}

super::context::report_details!(RaytraceReport, |r| vec![
    ("spp", r.spp as f64),
    ("levels", r.levels as f64),
    ("rays", r.rays as f64),
    ("missed_rays", r.missed_rays as f64),
    ("clamped", r.clamped as f64),
]);
