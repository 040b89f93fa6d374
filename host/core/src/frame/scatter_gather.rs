//! Scatter-as-you-gather with tile depth separation (Jimenez 2014; kernels and their rules in
//! `dof_shaders::scatter_gather`) as a frame context: every buffer bound at creation and nothing
//! planned on the host, so a frame's cost is fixed by its size and the ring count.

use super::context::{ContextReport, Described, DofContext, Extent, remake};
use super::in_flight::{InFlight, per_frame};
use super::io::{
    Frame, ImageIo, Owned, check_frame, clamped_summary, context_pixels, output_buffer, ready, record_clamp_count, record_front,
    record_input, record_output,
};
use super::recording::{Recording, capture};
use crate::backend::{Backend, BufferId, RunKernel};
use crate::error::{Error, Result};
use dof_shaders::scatter_gather::{
    STATS_LARGEST, ScatterGatherParams, TILE_WORDS, samples, scatter_gather, scatter_gather_dilate, scatter_gather_tiles,
};

/// The paper's budget: 1 + 8 + 16 + 24 = 49 samples a pixel.
pub const DEFAULT_RINGS: u32 = 3;
/// The most rings: 289 samples a pixel.
pub const MAX_RINGS: u32 = 8;
/// Default cap on the CoC radius, pixels: with the default rings, samples 11 px apart at the cap.
pub const DEFAULT_MAX_RADIUS: u32 = 32;
/// Largest cap accepted: the tile dilation's neighbourhood grows with it (19x19 tiles at 128 px).
pub const MAX_RADIUS: u32 = 128;

/// Scatter-as-you-gather's settings.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ScatterGatherOptions {
    /// Sample rings around each pixel, 1 to [`MAX_RINGS`].
    pub rings: u32,
    /// Cap on the CoC radius, pixels, 1 to [`MAX_RADIUS`].
    pub max_radius: u32,
}

impl Default for ScatterGatherOptions {
    fn default() -> Self {
        ScatterGatherOptions { rings: DEFAULT_RINGS, max_radius: DEFAULT_MAX_RADIUS }
    }
}

impl ScatterGatherOptions {
    /// Refuses a ring count or radius cap out of range.
    pub fn check(&self) -> Result<()> {
        if !(1..=MAX_RINGS).contains(&self.rings) {
            return Err(Error::InvalidArgument(format!("scatter-as-you-gather takes 1 to {MAX_RINGS} rings, got {}", self.rings)));
        }
        if !(1..=MAX_RADIUS).contains(&self.max_radius) {
            return Err(Error::InvalidArgument(format!(
                "scatter-as-you-gather's CoC radius cap is 1 to {MAX_RADIUS} px, got {}",
                self.max_radius
            )));
        }
        Ok(())
    }
}

/// What a scatter-as-you-gather context is created for.
#[derive(Clone, Debug)]
pub struct ScatterGatherContextDesc {
    pub max_width: u32,
    pub max_height: u32,
    /// Most slots per pixel of a multi-layer input (the gather reads the front one).
    pub max_layers: u32,
    pub options: ScatterGatherOptions,
    /// Hold the buffers that image inputs and outputs go through.
    pub image_io: bool,
    /// Frames in flight (default 1): copies kept of what the report reads.
    pub frames_in_flight: u32,
}

super::context::described!(ScatterGatherContextDesc);

impl ScatterGatherContextDesc {
    /// A description for frames up to `max`, with the defaults of the rest.
    pub fn new(max: Extent) -> Self {
        let Extent { width: max_width, height: max_height, layers: max_layers } = max;
        ScatterGatherContextDesc {
            max_width,
            max_height,
            max_layers,
            options: ScatterGatherOptions::default(),
            image_io: false,
            frames_in_flight: 1,
        }
    }
}

/// The buffers one frame's passes read and write.
struct Passes {
    /// The front layer: 3 words a pixel, and its depth.
    color: BufferId,
    depth: BufferId,
    /// Each pixel's signed CoC radius (NaN where unusable).
    coc: BufferId,
    /// Each tile's largest radius and closest depth ([`TILE_WORDS`] a tile), then dilated.
    tiles: BufferId,
    dilated: BufferId,
}

/// A scatter-as-you-gather context (see the [module docs](crate::frame)).
pub struct ScatterGatherContext {
    desc: ScatterGatherContextDesc,
    passes: Passes,
    /// Per frame in flight, the options its frame ran with (its report) and, on the device, the
    /// count of clamped input colours and the frame's largest CoC radius.
    in_flight: InFlight<ScatterGatherOptions>,
    stats: Vec<BufferId>,
    io: Option<ImageIo>,
    owned: Owned,
}

impl ScatterGatherContext {
    pub fn new(backend: &mut dyn Backend, desc: &ScatterGatherContextDesc) -> Result<Self> {
        desc.options.check()?;
        let pixels = context_pixels(backend, "scatter-gather", desc.max_width, desc.max_height, desc.max_layers)?;
        let shape = ScatterGatherParams { width: desc.max_width, height: desc.max_height, ..Default::default() };
        let tiles = shape.tiles_x() as u64 * shape.tiles_y() as u64;
        let in_flight = InFlight::new(desc.frames_in_flight)?;
        let mut owned = Owned::default();
        let made = (|| {
            let passes = Passes {
                color: owned.make(backend, 3 * pixels, "scatter-gather/color")?,
                depth: owned.make(backend, pixels, "scatter-gather/depth")?,
                coc: owned.make(backend, pixels, "scatter-gather/coc")?,
                tiles: owned.make(backend, TILE_WORDS as u64 * tiles, "scatter-gather/tiles")?,
                dilated: owned.make(backend, TILE_WORDS as u64 * tiles, "scatter-gather/dilated")?,
            };
            let stats = per_frame(&mut owned, backend, desc.frames_in_flight, 2, "scatter-gather/stats")?;
            let io = if desc.image_io { Some(ImageIo::new(backend, pixels, &mut owned)?) } else { None };
            Ok((passes, stats, io))
        })();
        let ((passes, stats, io), owned) = owned.or_free(backend, made)?;
        let ctx = ScatterGatherContext { desc: desc.clone(), passes, in_flight, stats, io, owned };
        let mut kernels = dof_shaders::scatter_gather::KERNELS.to_vec();
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

    pub fn options(&self) -> ScatterGatherOptions {
        self.desc.options
    }

    /// Changes the ring count or the radius cap for the frames recorded next (no allocation: the
    /// buffers do not depend on them).
    pub fn set_options(&mut self, options: ScatterGatherOptions) -> Result<()> {
        options.check()?;
        self.desc.options = options;
        Ok(())
    }

    /// Records one frame: the front layer of the input, then the tiles, their dilation and the
    /// gather.
    pub fn recording(&mut self, backend: &dyn Backend, f: &Frame) -> Result<Recording> {
        check_frame(backend, f, &self.owned, self.desc.extent(), self.io.as_ref())?;
        let recording = capture(self, backend, f, Self::commands)?;
        self.in_flight.recorded(self.desc.options);
        Ok(recording)
    }

    /// The frame's commands (captured, and checked, by [`capture`]).
    fn commands(&mut self, backend: &mut dyn Backend, f: &Frame) -> Result<()> {
        let o = self.desc.options;
        let slots = record_input(backend, f, self.io.as_ref())?;
        let out = output_buffer(f, self.io.as_ref())?;
        let Passes { color, depth, coc, tiles, dilated } = self.passes;
        record_front(backend, f, slots, color, depth)?;
        let stats = self.stats[self.in_flight.next()];
        record_clamp_count(backend, f, slots, 1, stats, 0)?;
        backend.fill(stats, STATS_LARGEST as u64, 1, 0, "scatter-gather/largest")?;
        let p = ScatterGatherParams { width: f.width, height: f.height, rings: o.rings, max_radius: o.max_radius, lens: f.lens };
        let bindings = scatter_gather_tiles::Bindings { color, depth, coc, tiles, stats };
        backend.run(bindings, [p.tiles_x(), p.tiles_y(), 1], &p, "scatter-gather/tiles")?;
        let groups = [p.tiles_x().div_ceil(8), p.tiles_y().div_ceil(8), 1];
        backend.run(scatter_gather_dilate::Bindings { tiles, dilated }, groups, &p, "scatter-gather/dilate")?;
        let groups = [f.width.div_ceil(8), f.height.div_ceil(8), 1];
        backend.run(scatter_gather::Bindings { color, depth, coc, dilated, out }, groups, &p, "scatter-gather")?;
        record_output(backend, f, self.io.as_ref())
    }
}

impl DofContext for ScatterGatherContext {
    fn method(&self) -> &'static str {
        "scatter-gather"
    }
    fn extent(&self) -> Extent {
        self.desc.extent()
    }
    fn recording(&mut self, backend: &dyn Backend, frame: &Frame) -> Result<Recording> {
        ScatterGatherContext::recording(self, backend, frame)
    }
    fn frames_in_flight(&self) -> u32 {
        self.in_flight.frames()
    }
    fn report_frame(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<ContextReport> {
        self.owned.check(backend)?;
        let (slot, o) = self.in_flight.slot(frames_ago)?;
        let words = backend.read_buffer(self.stats[slot], 0, 2)?;
        let (clamped, largest) = (words[0], f32::from_bits(words[STATS_LARGEST as usize]));
        let samples = samples(o.rings);
        Ok(ContextReport {
            summary: format!(
                "{} rings, {samples} samples a pixel, largest CoC radius {largest:.2} px (cap {} px){}",
                o.rings,
                o.max_radius,
                clamped_summary(clamped)
            ),
            details: Some(std::sync::Arc::new(ScatterGatherReport {
                rings: o.rings,
                samples_per_pixel: samples,
                largest_radius_px: largest,
                clamped,
            })),
            ..Default::default()
        })
    }
    fn device_bytes(&self) -> u64 {
        ScatterGatherContext::device_bytes(self)
    }
    fn resize(&mut self, backend: &mut dyn Backend, extent: Extent) -> Result<()> {
        self.owned.check(backend)?;
        let desc = self.desc.clone();
        remake(self, backend, &desc, extent, ScatterGatherContext::new, ScatterGatherContext::destroy)
    }
    fn destroy(self: Box<Self>, backend: &mut dyn Backend) {
        ScatterGatherContext::destroy(*self, backend)
    }
}

/// What a scatter-as-you-gather frame did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScatterGatherReport {
    pub rings: u32,
    pub samples_per_pixel: u32,
    /// The frame's largest CoC radius (px), after the cap.
    pub largest_radius_px: f32,
    /// Input values clamped where read (the numerical contract).
    pub clamped: u32,
}

super::context::report_details!(ScatterGatherReport, |r| vec![
    ("rings", r.rings as f64),
    ("samples_per_pixel", r.samples_per_pixel as f64),
    ("largest_radius_px", r.largest_radius_px as f64),
    ("clamped", r.clamped as f64),
]);
