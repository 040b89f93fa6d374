//! The engine-grade gather (kernels and their rules in `dof_shaders::ring_gather`) as a frame
//! context: half-resolution fields over a fixed budget of sample rings, every buffer bound at
//! creation and nothing planned on the host, so its cost is fixed by the frame's size and the ring
//! count, not by the blur.

use super::context::{ContextReport, Described, DofContext, Extent, remake};
use super::in_flight::{InFlight, per_frame};
use super::io::{
    Frame, ImageIo, Owned, check_frame, clamped_summary, context_pixels, output_buffer, ready, record_clamp_count, record_front,
    record_input, record_output,
};
use super::recording::Recording;
use super::transient::{self, Transients};
use crate::backend::{Backend, BufferId, RunKernel, groups_for};
use crate::error::{Error, Result};
use dof_shaders::ring_gather::{
    BRIGHT_TILE_WORDS, DILATED_WORDS, FIELD_WORDS, HALF_WORDS, HIGHLIGHTS_PER_TILE, RING_GATHER_DILATE, RingGatherParams, STATS_CAPPED,
    ring_gather, ring_gather_composite, ring_gather_dilate, ring_gather_downsample,
};

/// What engines ship by default: about five rings (Unreal Engine's Diaphragm DoF), 91 samples a
/// half-resolution pixel. Fixed before anything was compared with it.
pub const DEFAULT_RINGS: u32 = 5;
/// The quality knob's range: 1 ring (7 samples) to 8 rings (217 samples).
pub const MAX_SAMPLE_RINGS: u32 = 8;
/// Default cap on the CoC radius, pixels of the frame (32 half-resolution pixels).
pub const DEFAULT_MAX_RADIUS: u32 = 64;
/// Largest cap accepted: the tile dilation's neighbourhood grows with it (17x17 tiles at 128 px).
pub const MAX_RADIUS: u32 = 128;

/// The engine-grade gather's settings.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RingGatherOptions {
    /// Sample rings at half resolution, 1 to [`MAX_SAMPLE_RINGS`].
    pub rings: u32,
    /// Cap on the CoC radius, pixels, 1 to [`MAX_RADIUS`].
    pub max_radius: u32,
}

impl Default for RingGatherOptions {
    fn default() -> Self {
        RingGatherOptions { rings: DEFAULT_RINGS, max_radius: DEFAULT_MAX_RADIUS }
    }
}

impl RingGatherOptions {
    /// Refuses a ring count or radius cap out of range.
    pub fn check(&self) -> Result<()> {
        if !(1..=MAX_SAMPLE_RINGS).contains(&self.rings) {
            return Err(Error::InvalidArgument(format!("the ring gather takes 1 to {MAX_SAMPLE_RINGS} rings, got {}", self.rings)));
        }
        if !(1..=MAX_RADIUS).contains(&self.max_radius) {
            return Err(Error::InvalidArgument(format!(
                "the ring gather's CoC radius cap is 1 to {MAX_RADIUS} px, got {}",
                self.max_radius
            )));
        }
        Ok(())
    }
}

/// What a ring-gather context is created for.
#[derive(Clone, Debug)]
pub struct RingGatherContextDesc {
    pub max_width: u32,
    pub max_height: u32,
    /// Most slots per pixel of a multi-layer input (the gather reads the front one).
    pub max_layers: u32,
    pub options: RingGatherOptions,
    /// Hold the buffers that image inputs and outputs go through.
    pub image_io: bool,
    /// Frames in flight (default 1): copies kept of what the report reads.
    pub frames_in_flight: u32,
}

super::context::described!(RingGatherContextDesc);

impl RingGatherContextDesc {
    /// A description for frames up to `max`, with the defaults of the rest.
    pub fn new(max: Extent) -> Self {
        let Extent { width: max_width, height: max_height, layers: max_layers } = max;
        RingGatherContextDesc {
            max_width,
            max_height,
            max_layers,
            options: RingGatherOptions::default(),
            image_io: false,
            frames_in_flight: 1,
        }
    }
}

/// The buffers one frame's passes read and write: transients, placed by their lifetimes
/// ([`super::transient`]).
struct Passes {
    /// The front layer: 3 words a pixel, and its depth.
    color: BufferId,
    depth: BufferId,
    /// The front layer's colours less what the highlight path scatters (3 words a pixel): what the
    /// full-resolution path reads.
    fine: BufferId,
    /// Half-resolution colour and signed CoC ([`HALF_WORDS`] a half-resolution pixel).
    half: BufferId,
    /// Each tile's largest near-field radius, then dilated (with its highlight reach,
    /// [`DILATED_WORDS`] a tile).
    tiles: BufferId,
    dilated: BufferId,
    /// Each tile's highlights, drawn as discs instead of gathered ([`BRIGHT_TILE_WORDS`] a tile).
    bright: BufferId,
    /// The background and near fields ([`FIELD_WORDS`] a half-resolution pixel).
    fields: BufferId,
}

/// A ring-gather context (see the [module docs](crate::frame)).
pub struct RingGatherContext {
    desc: RingGatherContextDesc,
    passes: Passes,
    /// Per frame in flight, the options its frame ran with (its report) and, on the device, the
    /// count of clamped input colours and of the highlights left in the gather by a tile's cap.
    in_flight: InFlight<RingGatherOptions>,
    stats: Vec<BufferId>,
    io: Option<ImageIo>,
    owned: Owned,
    transients: Transients,
}

impl RingGatherContext {
    pub fn new(backend: &mut dyn Backend, desc: &RingGatherContextDesc) -> Result<Self> {
        desc.options.check()?;
        let pixels = context_pixels(backend, "ring-gather", desc.max_width, desc.max_height, desc.max_layers)?;
        let shape = RingGatherParams { width: desc.max_width, height: desc.max_height, ..Default::default() };
        let half = shape.half_width() as u64 * shape.half_height() as u64;
        let tiles = shape.tiles_x() as u64 * shape.tiles_y() as u64;
        let in_flight = InFlight::new(desc.frames_in_flight)?;
        let mut owned = Owned::default();
        let mut t = Transients::default();
        let passes = Passes {
            color: t.declare(3 * pixels, "ring-gather/color"),
            depth: t.declare(pixels, "ring-gather/depth"),
            fine: t.declare(3 * pixels, "ring-gather/fine"),
            half: t.declare(HALF_WORDS as u64 * half, "ring-gather/half"),
            tiles: t.declare(tiles, "ring-gather/tiles"),
            dilated: t.declare(DILATED_WORDS as u64 * tiles, "ring-gather/dilated"),
            bright: t.declare(BRIGHT_TILE_WORDS as u64 * tiles, "ring-gather/bright"),
            fields: t.declare(FIELD_WORDS as u64 * half, "ring-gather/fields"),
        };
        let made = (|| {
            let stats = per_frame(&mut owned, backend, desc.frames_in_flight, 2, "ring-gather/stats")?;
            let io = if desc.image_io { Some(ImageIo::new(backend, pixels, &mut owned)?) } else { None };
            Ok((stats, io))
        })();
        let ((stats, io), owned) = owned.or_free(backend, made)?;
        let ctx = RingGatherContext { desc: desc.clone(), passes, in_flight, stats, io, owned, transients: t };
        let parts: fn(&mut Self) -> (&mut Transients, &mut Owned) = |c| (&mut c.transients, &mut c.owned);
        let ctx = transient::placed(ctx, backend, desc.extent(), 0, parts, Self::commands, Self::destroy)?;
        let mut kernels = dof_shaders::ring_gather::KERNELS.to_vec();
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

    pub fn options(&self) -> RingGatherOptions {
        self.desc.options
    }

    /// Changes the ring count or the radius cap for the frames recorded next (no allocation: the
    /// buffers do not depend on them).
    pub fn set_options(&mut self, options: RingGatherOptions) -> Result<()> {
        options.check()?;
        self.desc.options = options;
        Ok(())
    }

    /// Records one frame: the front layer of the input, then downsampling, tile dilation, the
    /// gather over rings and the composite with the highlights' discs.
    pub fn recording(&mut self, backend: &dyn Backend, f: &Frame) -> Result<Recording> {
        check_frame(backend, f, &self.owned, self.desc.extent(), self.io.as_ref())?;
        let recording = transient::capture_with_transients(self, backend, f, |c| &mut c.transients, Self::commands)?;
        self.in_flight.recorded(self.desc.options);
        Ok(recording)
    }

    /// The frame's commands (captured, and checked, by [`transient::capture_with_transients`]).
    fn commands(&mut self, backend: &mut dyn Backend, f: &Frame) -> Result<()> {
        let d = &self.desc;
        let slots = record_input(backend, f, self.io.as_ref())?;
        let output = output_buffer(f, self.io.as_ref())?;
        let b = &self.passes;
        record_front(backend, f, slots, b.color, b.depth)?;
        let stats = self.stats[self.in_flight.next()];
        record_clamp_count(backend, f, slots, 1, stats, 0)?;
        backend.fill(stats, STATS_CAPPED as u64, 1, 0, "ring-gather/capped")?;
        let p =
            RingGatherParams { width: f.width, height: f.height, rings: d.options.rings, max_radius: d.options.max_radius, lens: f.lens };
        let tile_groups = [p.tiles_x(), p.tiles_y(), 1];
        let (color, depth, fine, half, tiles, bright, dilated, fields) =
            (b.color, b.depth, b.fine, b.half, b.tiles, b.bright, b.dilated, b.fields);
        let downsample = ring_gather_downsample::Bindings { color, depth, half, tiles, bright, fine, stats };
        backend.run(downsample, tile_groups, &p, "ring-gather/downsample")?;
        let tile_count = p.tiles_x() as u64 * p.tiles_y() as u64;
        let dilate = ring_gather_dilate::Bindings { tiles, bright, dilated };
        backend.run(dilate, groups_for(&RING_GATHER_DILATE, tile_count), &p, "ring-gather/dilate")?;
        backend.run(ring_gather::Bindings { half, dilated, fields }, tile_groups, &p, "ring-gather")?;
        let pixel_groups = [f.width.div_ceil(8), f.height.div_ceil(8), 1];
        let composite = ring_gather_composite::Bindings { fine, depth, fields, bright, dilated, out: output };
        backend.run(composite, pixel_groups, &p, "ring-gather/composite")?;
        record_output(backend, f, self.io.as_ref())
    }
}

impl DofContext for RingGatherContext {
    fn method(&self) -> &'static str {
        "ring-gather"
    }
    fn extent(&self) -> Extent {
        self.desc.extent()
    }
    fn recording(&mut self, backend: &dyn Backend, frame: &Frame) -> Result<Recording> {
        RingGatherContext::recording(self, backend, frame)
    }
    fn frames_in_flight(&self) -> u32 {
        self.in_flight.frames()
    }
    fn report_frame(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<ContextReport> {
        self.owned.check(backend)?;
        let (slot, o) = self.in_flight.slot(frames_ago)?;
        let words = backend.read_buffer(self.stats[slot], 0, 2)?;
        let (clamped, capped) = (words[0], words[STATS_CAPPED as usize]);
        let samples = dof_shaders::ring_gather::samples(o.rings);
        // Highlights beyond a tile's cap are gathered, not lost: the report says how many.
        let capped_summary = if capped == 0 {
            String::new()
        } else {
            format!("; {capped} highlights gathered instead of drawn as discs (more than {HIGHLIGHTS_PER_TILE} in their tile)")
        };
        Ok(ContextReport {
            summary: format!(
                "{} rings, {samples} samples a half-resolution pixel, CoC radius cap {} px{}{capped_summary}",
                o.rings,
                o.max_radius,
                clamped_summary(clamped)
            ),
            details: Some(std::sync::Arc::new(RingGatherReport {
                rings: o.rings,
                samples_per_half_pixel: samples,
                clamped,
                highlights_capped: capped,
            })),
            ..Default::default()
        })
    }
    fn device_bytes(&self) -> u64 {
        RingGatherContext::device_bytes(self)
    }
    fn resize(&mut self, backend: &mut dyn Backend, extent: Extent) -> Result<()> {
        self.owned.check(backend)?;
        let desc = self.desc.clone();
        remake(self, backend, &desc, extent, RingGatherContext::new, RingGatherContext::destroy)
    }
    fn knob(&self) -> Option<u32> {
        Some(self.desc.options.rings)
    }
    fn set_knob(&mut self, rings: u32) -> Result<()> {
        self.set_options(RingGatherOptions { rings, ..self.desc.options })
    }
    fn destroy(self: Box<Self>, backend: &mut dyn Backend) {
        RingGatherContext::destroy(*self, backend)
    }
}

/// What a ring gather frame did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RingGatherReport {
    pub rings: u32,
    pub samples_per_half_pixel: u32,
    /// Input values clamped where read (the numerical contract).
    pub clamped: u32,
    /// Highlights beyond their tile's cap, gathered instead of drawn as discs.
    pub highlights_capped: u32,
}

super::context::report_details!(RingGatherReport, |r| vec![
    ("rings", r.rings as f64),
    ("samples_per_half_pixel", r.samples_per_half_pixel as f64),
    ("clamped", r.clamped as f64),
    ("highlights_capped", r.highlights_capped as f64),
]);
