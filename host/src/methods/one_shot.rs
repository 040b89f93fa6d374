//! Frames of host images through any method of the frame API: a [`Runner`] holds one context of a
//! registry method and the buffers its frames go through, made once, and runs frame after frame
//! (upload, record, submit, read back); [`one_shot`] is one frame through a runner made for it.
//! The convenience path for the CLI, the evaluation, sequences and the tests; a renderer records
//! into its own command buffer instead ([`crate::frame`]). A frame whose context overflowed is run
//! again with the context grown ([`DofContext::grow_to_fit`]), so every result is whole.
//! [`Runner::time_frames`] times frames as a renderer runs them: the input uploaded once, frames
//! back to back after a warm-up, nothing read back until the last.

use crate::backend::{Backend, BackendCounters, BufferId, CommandTime, ImageFormat, ImageRef};
use crate::frame::{
    ContextDesc, ContextReport, CountBuffer, DepthEncoding, DofContext, Extent, Frame, FrameInput, FrameOutput, MethodInfo, MethodOptions,
    Reads, RgbBuffer, SlotBuffer,
};
use crate::layers::{LayeredImage, RgbImage};
use crate::methods::buffers::{input_words, read_rgb, slot_words};
use crate::timing::{RunTimes, Warmup};
use dof_core::error::{Error, Result};
use dof_shaders::frame_io::{DEPTH_REVERSED, FrameIoParams, buffer_depth};
use dof_shaders::half::{HALF_MAX, f32_to_f16};
use dof_shaders::lens::ThinLens;
use std::borrow::Cow;

/// What one frame gave.
pub struct OneShot {
    pub image: RgbImage,
    pub report: ContextReport,
    /// One entry per recorded command, labelled by stage.
    pub stages: Vec<CommandTime>,
    /// Device bytes of the context, the input and the output.
    pub buffer_bytes: u64,
}

/// Runs a frame again with a grown context at most this many times after an overflow.
const RETRIES: u32 = 3;

/// The span [`Runner::time_frames`] opens around each timed frame's recording.
pub const FRAME_SPAN: &str = "frame/dof";

/// After a frame: while its context overflowed, grows the context ([`DofContext::grow_to_fit`]) and
/// runs `again` (record and submit the same frame), at most [`RETRIES`] times, as a renderer grows
/// it between frames. Returns how many times it grew and the last frame's report.
pub fn grow_to_fit(
    ctx: &mut dyn DofContext,
    backend: &mut dyn Backend,
    mut again: impl FnMut(&mut dyn DofContext, &mut dyn Backend) -> Result<()>,
) -> Result<(u32, ContextReport)> {
    let mut grown = 0;
    loop {
        let report = ctx.report(backend)?;
        if report.overflow == 0 || grown == RETRIES || !ctx.grow_to_fit(backend)? {
            return Ok((grown, report));
        }
        grown += 1;
        again(ctx, backend)?;
    }
}

/// The warm-up's frames of `ctx` (`frame` records and submits one), then, if the last one
/// overflowed, the context grown and the frame run again ([`grow_to_fit`]). Returns the warm-up's
/// frames and the times the context grew.
pub fn warm_up(
    ctx: &mut dyn DofContext,
    backend: &mut dyn Backend,
    warmup: Warmup,
    mut frame: impl FnMut(&mut dyn DofContext, &mut dyn Backend) -> Result<()>,
) -> Result<(u32, u32)> {
    let warmed = warmup.run(|| frame(&mut *ctx, &mut *backend))?;
    let grown = if warmed > 0 { grow_to_fit(ctx, backend, &mut frame)?.0 } else { 0 };
    Ok((warmed, grown))
}

/// What [`Runner::time_frames`] measured.
pub struct TimedFrames {
    /// The last timed frame: its image, report and commands.
    pub last: OneShot,
    /// Each timed frame's commands, by stage.
    pub runs: RunTimes,
    /// Each timed frame's span around its recording (ms; NaN where the queue has no timestamps).
    pub spans_ms: Vec<f64>,
    /// CPU time to record a frame, the mean (the CPU backend runs the kernels as it records).
    pub record_ms: f64,
    /// The backend's counters over the timed frames.
    pub counters: BackendCounters,
    /// Warm-up frames run.
    pub warmed: u32,
    /// Times the context grew after an overflowing warm-up frame.
    pub grown: u32,
}

/// The input `method` reads of `image`: the front layer for [`Reads::FrontLayer`], else all of it.
pub fn method_input<'a>(method: &MethodInfo, image: &'a LayeredImage) -> Cow<'a, LayeredImage> {
    match method.reads {
        Reads::FrontLayer if image.max_layers > 1 => Cow::Owned(image.front_layer()),
        _ => Cow::Borrowed(image),
    }
}

/// Where a runner's frames come from.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RunnerInput {
    /// Slot and count buffers of the multi-layer image (`FrameInput::Layers`).
    #[default]
    Layers,
    /// A colour and a depth image, as a renderer hands in its own (`FrameInput::Images`): the
    /// image flattened ([`LayeredImage::flattened`]) into an RGBA16F colour image and a D32 depth
    /// image of reversed depth with an infinite far plane, images the backend makes
    /// ([`Backend::create_image`]). The frame reads them in place where the backend samples them
    /// (stage `frame/input`).
    Images,
    /// The same images, described without their views ([`ImageRef::copied`]): the frame copies
    /// them into its buffers, then converts them (stages `frame/input-color`, `frame/input-depth`
    /// and `frame/input`).
    CopiedImages,
}

/// The stand-in images of a runner fed images ([`RunnerInput::Images`], [`RunnerInput::CopiedImages`]).
#[derive(Clone, Copy, Debug)]
struct ImageInput {
    color: ImageRef,
    depth: ImageRef,
    /// Frames describe them without their views.
    copied: bool,
}

/// One context of a registry method and the buffers its frames go through, made once for frames
/// of one size and layer count (a sequence).
pub struct Runner {
    ctx: Box<dyn DofContext>,
    io: [BufferId; 3],
    extent: Extent,
    /// Words of the input buffer, and the side of its footprints' grid (0: none).
    input_words: u64,
    footprint_side: u32,
    /// Allocations (backend counters) during the frames after the first: 0 unless a frame
    /// overflowed and its context grew.
    pub later_allocations: u64,
    pub frames: u32,
    images: Option<ImageInput>,
}

impl Runner {
    /// A context of `method` for frames the size and layer count of `image` (already the input
    /// the method reads: see [`method_input`]), and the buffers they go through.
    pub fn new(backend: &mut dyn Backend, method: &MethodInfo, options: &MethodOptions, image: &LayeredImage) -> Result<Self> {
        Self::fed(backend, method, options, image, RunnerInput::Layers)
    }

    /// As [`Runner::new`], its frames fed as `input` says; fed images, the context takes one layer
    /// and image I/O, and the images are made here.
    pub fn fed(
        backend: &mut dyn Backend,
        method: &MethodInfo,
        options: &MethodOptions,
        image: &LayeredImage,
        input: RunnerInput,
    ) -> Result<Self> {
        let (w, h) = (image.width, image.height);
        let fed_layers = input == RunnerInput::Layers;
        let layers = if fed_layers { image.max_layers } else { 1 };
        if w == 0 || h == 0 || layers == 0 {
            return Err(Error::InvalidArgument(format!("{} needs a non-empty image, got {w}x{h} with {layers} layers", method.name)));
        }
        let extent = Extent::new(w, h, layers);
        // Splatting holds a word a fragment for the footprints of an area-integrated input.
        let mut options = options.clone();
        if fed_layers {
            options.splat.footprint_side = options.splat.footprint_side.max(image.footprint_grid());
        }
        // The context checks the extent (and refuses) before any buffer of the input is made.
        let mut desc = ContextDesc::new(extent, options);
        desc.image_io = !fed_layers;
        let ctx = (method.create)(backend, &desc)?;
        let images = match input {
            RunnerInput::Layers => None,
            RunnerInput::Images | RunnerInput::CopiedImages => match ImageInput::new(backend, image, input == RunnerInput::CopiedImages) {
                Ok(images) => Some(images),
                Err(e) => {
                    ctx.destroy(backend);
                    return Err(e);
                }
            },
        };
        let pixels = w as u64 * h as u64;
        // Fed images, the frame reads no slot or count buffer: one word stands in for each.
        let (slots, counts) = if fed_layers { (input_words(image), pixels) } else { (1, 1) };
        let sizes = [(slots, "frames/input"), (counts, "frames/input-counts"), (3 * pixels, "frames/out")];
        let mut io = Vec::new();
        for (words, label) in sizes {
            match backend.create_buffer(words, label) {
                Ok(id) => io.push(id),
                Err(e) => {
                    io.into_iter().for_each(|id| backend.destroy_buffer(id));
                    images.iter().for_each(|i| i.destroy(backend));
                    ctx.destroy(backend);
                    return Err(e);
                }
            }
        }
        let (input_words, footprint_side) = (sizes[0].0, if fed_layers { image.footprint_grid() } else { 0 });
        Ok(Runner { ctx, io: [io[0], io[1], io[2]], extent, input_words, footprint_side, later_allocations: 0, frames: 0, images })
    }

    /// Device bytes of the context, the input and the output.
    pub fn buffer_bytes(&self) -> u64 {
        let pixels = self.extent.width as u64 * self.extent.height as u64;
        let counts = if self.images.is_some() { 1 } else { pixels };
        self.ctx.device_bytes() + 4 * (self.input_words + counts + 3 * pixels)
    }

    /// Uploads `image` (of the runner's size and layer count) and returns the frame that reads it
    /// through `lens`.
    fn upload(&self, backend: &mut dyn Backend, image: &LayeredImage, lens: &ThinLens) -> Result<Frame> {
        let e = self.extent;
        let side = image.footprint_grid();
        crate::lens::check(lens)?;
        if let Some(images) = &self.images {
            if (image.width, image.height) != (e.width, e.height) {
                return Err(Error::InvalidArgument(format!(
                    "a frame of {}x{} differs from the {}x{} its runner was made for",
                    image.width, image.height, e.width, e.height
                )));
            }
            return images.frame(backend, image, *lens, RgbBuffer(self.io[2]));
        }
        if (image.width, image.height, image.max_layers, side) != (e.width, e.height, e.layers, self.footprint_side) {
            return Err(Error::InvalidArgument(format!(
                "a frame of {}x{} with {} layers differs from the {}x{} with {} its runner was made for",
                image.width, image.height, image.max_layers, e.width, e.height, e.layers
            )));
        }
        backend.write_buffer(self.io[0], 0, &slot_words(image))?;
        backend.write_buffer(self.io[1], 0, &image.counts)?;
        let frame = Frame::layers(
            e.width,
            e.height,
            e.layers,
            *lens,
            SlotBuffer::current(self.io[0]),
            CountBuffer(self.io[1]),
            RgbBuffer(self.io[2]),
        );
        Ok(frame.with_footprints(side))
    }

    /// One frame of `image` (of the runner's size and layer count) through `lens`: upload, record,
    /// submit, read back.
    pub fn frame(&mut self, backend: &mut dyn Backend, image: &LayeredImage, lens: &ThinLens) -> Result<OneShot> {
        let e = self.extent;
        let before = backend.counters();
        let frame = self.upload(backend, image, lens)?;
        self.ctx.record(backend, &frame)?;
        let mut stages = backend.submit()?;
        let (_, report) = grow_to_fit(self.ctx.as_mut(), backend, |ctx, backend| {
            ctx.record(backend, &frame)?;
            stages = backend.submit()?;
            Ok(())
        })?;
        let image = read_rgb(backend, self.io[2], e.width, e.height)?;
        if self.frames > 0 {
            self.later_allocations += backend.counters().since(&before).allocations;
        }
        self.frames += 1;
        Ok(OneShot { image, report, stages, buffer_bytes: self.buffer_bytes() })
    }

    /// Times `frames` frames of `image` through `lens` as a renderer runs them: the input uploaded
    /// once, the warm-up's frames, the context grown if a warm-up frame overflowed (as a renderer
    /// grows it between frames, so the timed frames are whole), then the timed frames back to back,
    /// each with a span ([`FRAME_SPAN`]) around its recording; the last one is read back after.
    pub fn time_frames(
        &mut self,
        backend: &mut dyn Backend,
        image: &LayeredImage,
        lens: &ThinLens,
        warmup: Warmup,
        frames: u32,
    ) -> Result<TimedFrames> {
        if frames == 0 {
            return Err(Error::InvalidArgument("timing needs at least one frame".into()));
        }
        let frame = self.upload(backend, image, lens)?;
        let ctx = &mut self.ctx;
        let (warmed, grown) = warm_up(ctx.as_mut(), backend, warmup, |ctx, backend| {
            ctx.record(backend, &frame)?;
            backend.submit()?;
            Ok(())
        })?;
        backend.take_span_times();
        let before = backend.counters();
        let (mut runs, mut spans_ms, mut record_ms, mut stages) = (RunTimes::default(), Vec::new(), 0.0, Vec::new());
        for _ in 0..frames {
            let start = std::time::Instant::now();
            backend.begin_span(FRAME_SPAN)?;
            ctx.record(backend, &frame)?;
            backend.end_span()?;
            record_ms += start.elapsed().as_secs_f64() * 1e3 / frames as f64;
            stages = backend.submit()?;
            runs.add(&stages);
            spans_ms.extend(backend.take_span_times().into_iter().filter(|s| s.label == FRAME_SPAN).map(|s| s.ms));
        }
        let counters = backend.counters().since(&before);
        let report = ctx.report(backend)?;
        let e = self.extent;
        let image = read_rgb(backend, self.io[2], e.width, e.height)?;
        self.frames += warmed + grown + frames;
        let last = OneShot { image, report, stages, buffer_bytes: self.buffer_bytes() };
        Ok(TimedFrames { last, runs, spans_ms, record_ms, counters, warmed, grown })
    }

    /// Refuses, before the first frame, a frame whose host memory is more than the machine has free:
    /// the input's words on their way up, the output's on their way back and its image; on the CPU
    /// backend the buffers themselves are host memory, reserved but not yet touched
    /// ([`dof_core::host_memory::available_beside`]).
    pub fn check_host_memory(&self, backend: &dyn Backend) -> Result<()> {
        let pixels = self.extent.width as u64 * self.extent.height as u64;
        let bytes = 4 * self.input_words as u128 + 2 * 12 * pixels as u128;
        let reserved = if backend.kind() == crate::backend::BackendKind::Cpu { self.buffer_bytes() } else { 0 };
        match dof_core::host_memory::available_beside(reserved) {
            Some(free) if bytes > free as u128 => Err(Error::HostMemory {
                what: format!(
                    "a {}x{} frame of {} layer(s) (its input and output on their way; {} MiB free)",
                    self.extent.width,
                    self.extent.height,
                    self.extent.layers,
                    free >> 20
                ),
                bytes: bytes.min(u64::MAX as u128) as u64,
            }),
            _ => Ok(()),
        }
    }

    /// Device bytes of the context alone.
    pub fn device_bytes(&self) -> u64 {
        self.ctx.device_bytes()
    }

    pub fn destroy(self, backend: &mut dyn Backend) {
        self.ctx.destroy(backend);
        self.io.into_iter().for_each(|id| backend.destroy_buffer(id));
        self.images.iter().for_each(|i| i.destroy(backend));
    }
}

impl ImageInput {
    /// The images for frames of `image`'s size, described to frames without their views where
    /// `copied`.
    fn new(backend: &mut dyn Backend, image: &LayeredImage, copied: bool) -> Result<Self> {
        let size = [image.width, image.height];
        let color = backend.create_image(ImageFormat::Rgba16Float, size)?;
        match backend.create_image(ImageFormat::D32Float, size) {
            Ok(depth) => Ok(ImageInput { color, depth, copied }),
            Err(e) => {
                backend.destroy_image(&color);
                Err(e)
            }
        }
    }

    /// Writes `image` flattened into the images and returns the frame that reads them. The depths
    /// are encoded for a near plane at half this image's nearest depth, so none lies before it.
    fn frame(&self, backend: &mut dyn Backend, image: &LayeredImage, lens: ThinLens, out: RgbBuffer) -> Result<Frame> {
        let pixels = image.width as usize * image.height as usize;
        let flat: Vec<([f32; 3], f32)> = (0..pixels).map(|p| image.flattened(p)).collect();
        let nearest = flat.iter().map(|f| f.1).filter(|z| z.is_finite() && *z > 0.0).fold(f32::INFINITY, f32::min);
        let near = if nearest.is_finite() { 0.5 * nearest } else { 0.1 };
        let encoding = DepthEncoding::Reversed { near, far: f32::INFINITY };
        let params = FrameIoParams { depth_encoding: DEPTH_REVERSED, near, far: f32::INFINITY, ..Default::default() };
        let (mut color, mut depth) = (Vec::with_capacity(2 * pixels), Vec::with_capacity(pixels));
        for &(c, z) in &flat {
            // Emitters brighter than a half float holds saturate, as in a renderer's HDR target.
            let half = |v: f32| f32_to_f16(v.min(HALF_MAX));
            color.extend([half(c[0]) | (half(c[1]) << 16), half(c[2]) | (half(1.0) << 16)]);
            // Nothing at a pixel (infinitely far) is 0 in a reversed depth buffer.
            depth.push(if z.is_finite() { buffer_depth(&params, z) } else { 0.0 }.to_bits());
        }
        backend.write_image(&self.color, &color)?;
        backend.write_image(&self.depth, &depth)?;
        Ok(Frame {
            width: image.width,
            height: image.height,
            lens,
            input: if self.copied {
                FrameInput::Images { color: self.color.copied(), depth: self.depth.copied(), encoding }
            } else {
                FrameInput::Images { color: self.color, depth: self.depth, encoding }
            },
            output: FrameOutput::Buffer(out),
        })
    }

    fn destroy(&self, backend: &mut dyn Backend) {
        backend.destroy_image(&self.color);
        backend.destroy_image(&self.depth);
    }
}

/// Renders `image` through `lens` with `method` on `backend`: one frame through a [`Runner`] made
/// for it. A method that reads the front layer is handed only that ([`Reads::FrontLayer`]).
pub fn one_shot(
    backend: &mut dyn Backend,
    method: &MethodInfo,
    options: &MethodOptions,
    image: &LayeredImage,
    lens: &ThinLens,
) -> Result<OneShot> {
    crate::lens::check(lens)?;
    let input = method_input(method, image);
    let mut runner = Runner::new(backend, method, options, &input)?;
    if let Err(e) = runner.check_host_memory(backend) {
        runner.destroy(backend);
        return Err(e);
    }
    let ran = runner.frame(backend, &input, lens);
    runner.destroy(backend);
    ran
}
