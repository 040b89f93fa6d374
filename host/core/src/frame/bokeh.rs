//! Bokeh sprites over a gathering blur (de Rousiers, Pettineo) as a frame context: detection, the
//! sprite slots (a scan on the device), the sprites and what the blur gathers, the gather's window
//! reduced on the device, the draw command written on the device, the sprite draw (the graphics
//! pipeline on Vulkan, its compute fallback on the CPU) and the sum. Nothing is planned or read
//! back on the host.

use super::context::{ContextReport, Described, DofContext, Extent, remake};
use super::gather::{MAX_RADIUS, record_gather};
use super::in_flight::{InFlight, per_frame};
use super::io::{
    Frame, ImageIo, Owned, check_frame, clamped_summary, output_buffer, ready, record_clamp_count, record_front, record_input,
    record_output,
};
use super::recording::Recording;
use super::transient::{self, Transients};
use crate::aperture::ApertureShape;
use crate::backend::{Backend, BufferId, RunKernel, groups_for, push_words};
use crate::error::{Error, Result};
use crate::ops::scan::ScanScratch;
use dof_shaders::bokeh::{
    ARGS_WORDS, BOKEH_DETECT, BOKEH_DRAW, BokehParams, COUNTER, SPRITE_WORDS, bokeh_args, bokeh_combine, bokeh_detect, bokeh_emit,
};
use dof_shaders::gather::{GATHER, GATHER_PLAN, gather};

#[derive(Clone, Debug)]
pub struct BokehOptions {
    /// Luminance above the 5x5 neighbourhood's mean that makes a sprite (`LumThreshold`, linear
    /// units; default 1, a diffuse white).
    pub lum_threshold: f32,
    /// Smallest CoC radius (px) that makes a sprite (`CoCThreshold`; default 2).
    pub coc_threshold: f32,
    /// Sprites the buffer holds (default 4096); more are counted and left in the blur.
    pub capacity: u32,
    /// Largest sprite CoC radius (px; default 256).
    pub max_radius: f32,
    pub aperture: ApertureShape,
}

impl Default for BokehOptions {
    fn default() -> Self {
        BokehOptions { lum_threshold: 1.0, coc_threshold: 2.0, capacity: 4096, max_radius: 256.0, aperture: ApertureShape::circle() }
    }
}

/// What a bokeh context is created for.
#[derive(Clone, Debug)]
pub struct BokehContextDesc {
    pub max_width: u32,
    pub max_height: u32,
    /// Most slots per pixel of a multi-layer input (the method reads the front one).
    pub max_layers: u32,
    pub options: BokehOptions,
    /// Hold the buffers that image inputs and outputs go through.
    pub image_io: bool,
    /// Frames in flight (default 1): copies kept of what the report reads.
    pub frames_in_flight: u32,
}

super::context::described!(BokehContextDesc);

impl BokehContextDesc {
    /// A description for frames up to `max`, with the defaults of the rest.
    pub fn new(max: Extent, options: BokehOptions) -> Self {
        let Extent { width: max_width, height: max_height, layers: max_layers } = max;
        BokehContextDesc { max_width, max_height, max_layers, options, image_io: false, frames_in_flight: 1 }
    }
}

/// The context's buffers: the aperture mask and the per-frame counters are the backend's, the rest
/// stand-ins for transients (given their buffers as each frame is recorded).
struct Buffers {
    mask: BufferId,
    slots: BufferId,
    color: BufferId,
    depth: BufferId,
    rest: BufferId,
    sprites: BufferId,
    blur: BufferId,
    sprite_image: BufferId,
    /// Per frame in flight, what its report reads: the detection counter (beside the draw's
    /// arguments) and the gather's window radius.
    counters: Vec<BufferId>,
    radius: Vec<BufferId>,
}

/// A bokeh-sprite context (see the [module docs](crate::frame)).
pub struct BokehContext {
    desc: BokehContextDesc,
    b: Buffers,
    in_flight: InFlight<()>,
    io: Option<ImageIo>,
    scan: ScanScratch,
    /// The buffers of `b` a frame uses only within itself, placed by their lifetimes.
    transients: Transients,
    owned: Owned,
}

/// Checks the options: finite thresholds, a sprite radius cap in (0, 4096] px, a capacity of 1 to
/// 2^20 sprites.
pub fn check_options(o: &BokehOptions) -> Result<()> {
    o.aperture.check()?;
    let finite = |v: f32| v.is_finite() && v >= 0.0;
    if !(finite(o.lum_threshold) && finite(o.coc_threshold) && o.max_radius > 0.0 && o.max_radius <= 4096.0) {
        return Err(Error::InvalidArgument(format!(
            "bokeh thresholds must be finite and non-negative and the sprite radius cap in (0, 4096] px, got {}, {} and {}",
            o.lum_threshold, o.coc_threshold, o.max_radius
        )));
    }
    if !(1..=1 << 20).contains(&o.capacity) {
        return Err(Error::InvalidArgument(format!("the sprite capacity must be 1 to 1048576, got {}", o.capacity)));
    }
    Ok(())
}

impl BokehContext {
    pub fn new(backend: &mut dyn Backend, desc: &BokehContextDesc) -> Result<Self> {
        check_options(&desc.options)?;
        let (w, h) = (desc.max_width, desc.max_height);
        if w == 0 || h == 0 || desc.max_layers == 0 {
            return Err(Error::InvalidArgument(format!("a bokeh context for an empty {w}x{h} extent with {} layers", desc.max_layers)));
        }
        let pixels = w as u64 * h as u64;
        let mask_words = desc.options.aperture.mask_words();
        // What a frame uses only within itself, placed by lifetime once the context exists.
        let transient = [
            (pixels, "bokeh/slots"),
            (3 * pixels, "bokeh/color"),
            (pixels, "bokeh/depth"),
            (3 * pixels, "bokeh/rest"),
            (SPRITE_WORDS as u64 * desc.options.capacity as u64, "bokeh/sprites"),
            (3 * pixels, "bokeh/blur"),
            (4 * pixels, "bokeh/sprite-image"),
        ];
        let max_words = backend.limits().max_buffer_bytes / 4;
        let widest = transient
            .iter()
            .copied()
            .chain([(mask_words.len() as u64, "bokeh/aperture-mask")])
            .chain([(dof_shaders::slot::SLOT_WORDS as u64 * pixels * desc.max_layers as u64, "input slots")])
            .max_by_key(|s| s.0);
        if let Some((words, what)) = widest.filter(|s| s.0 > max_words) {
            return Err(Error::TooLarge { what: format!("{what} (words)"), size: words, limit: max_words });
        }
        let in_flight = InFlight::new(desc.frames_in_flight)?;
        let mut t = Transients::default();
        let [slots, color, depth, rest, sprites, blur, sprite_image] = transient.map(|(words, label)| t.declare(words, label));
        let mut owned = Owned::default();
        let made = (|| {
            let mask = owned.make(backend, mask_words.len() as u64, "bokeh/aperture-mask")?;
            backend.write_buffer(mask, 0, &mask_words)?;
            let frames = desc.frames_in_flight;
            let counters = per_frame(&mut owned, backend, frames, ARGS_WORDS as u64 + 1, "bokeh/counters")?;
            // Per frame: the gather's window radius, then the count of clamped input colours.
            let radius = per_frame(&mut owned, backend, frames, 2, "bokeh/gather-radius")?;
            let io = if desc.image_io { Some(ImageIo::new(backend, pixels, &mut owned)?) } else { None };
            // The sprite draw's target for the largest frame, so that no frame makes one.
            backend.reserve_draw_target(&BOKEH_DRAW, [w, h])?;
            let scan = ScanScratch::new(backend, pixels)?;
            Ok((Buffers { mask, slots, color, depth, rest, sprites, blur, sprite_image, counters, radius }, io, scan))
        })();
        let ((b, io, scan), mut owned) = owned.or_free(backend, made)?;
        owned.adopt(scan.buffers());
        let ctx = BokehContext { desc: desc.clone(), b, in_flight, io, scan, owned, transients: t };
        let parts: fn(&mut Self) -> (&mut Transients, &mut Owned) = |c| (&mut c.transients, &mut c.owned);
        let ctx = transient::placed(ctx, backend, desc.extent(), 0, parts, Self::commands, Self::destroy)?;
        // Pipelines now and the buffers' zeroing submitted now: the first frame records only its own
        // work (Vulkan still makes its draw target at the first draw of a size).
        let mut kernels: Vec<&'static dof_shaders::KernelDesc> = dof_shaders::bokeh::KERNELS.to_vec();
        kernels.extend([&GATHER, &GATHER_PLAN]);
        kernels.extend(dof_shaders::scan::KERNELS);
        kernels.extend(dof_shaders::frame_io::KERNELS);
        kernels.extend(dof_shaders::radiance::KERNELS);
        ready(backend, ctx, &kernels, &[&BOKEH_DRAW], Self::destroy)
    }

    pub fn destroy(self, backend: &mut dyn Backend) {
        // The scan's buffers are among the owned ones.
        self.owned.free(backend);
    }

    pub fn device_bytes(&self) -> u64 {
        self.owned.bytes() + self.scan.bytes()
    }

    pub fn recording(&mut self, backend: &dyn Backend, f: &Frame) -> Result<Recording> {
        check_frame(backend, f, &self.owned, self.desc.extent(), self.io.as_ref())?;
        let recording = transient::capture_with_transients(self, backend, f, |c| &mut c.transients, Self::commands)?;
        self.in_flight.recorded(());
        Ok(recording)
    }

    /// The frame's commands (captured, and checked, by [`transient::capture_with_transients`]).
    fn commands(&mut self, backend: &mut dyn Backend, f: &Frame) -> Result<()> {
        let d = &self.desc;
        let b = &self.b;
        let slot = self.in_flight.next();
        let (counters, radius) = (b.counters[slot], b.radius[slot]);
        let (width, height) = (f.width, f.height);
        let pixels = width as u64 * height as u64;
        let slots = record_input(backend, f, self.io.as_ref())?;
        let out = output_buffer(f, self.io.as_ref())?;
        record_front(backend, f, slots, b.color, b.depth)?;
        record_clamp_count(backend, f, slots, 1, radius, 1)?;
        let o = &d.options;
        let params = BokehParams {
            width,
            height,
            capacity: o.capacity,
            lum_threshold: o.lum_threshold,
            coc_threshold: o.coc_threshold,
            max_radius: o.max_radius,
            lens: f.lens,
            aperture: o.aperture.kernel,
            ..Default::default()
        };
        let push = push_words(&params);
        let groups = groups_for(&BOKEH_DETECT, pixels);
        backend.fill(counters, 0, ARGS_WORDS as u64 + 1, 0, "bokeh/detect")?;
        let detect = bokeh_detect::Bindings { color: b.color, depth: b.depth, flags: b.slots, counters };
        backend.run(detect, groups, &params, "bokeh/detect")?;
        self.scan.record(backend, b.slots, 0, pixels)?;
        let emit = bokeh_emit::Bindings { color: b.color, depth: b.depth, slots: b.slots, sprites: b.sprites, rest: b.rest, mask: b.mask };
        backend.run(emit, groups, &params, "bokeh/detect")?;
        record_gather(backend, f, MAX_RADIUS, gather::Bindings { color: b.rest, depth: b.depth, out: b.blur, plan: radius })?;
        backend.run(bokeh_args::Bindings { counters }, [1, 1, 1], &params, "bokeh/draw")?;
        backend.draw_indirect(&BOKEH_DRAW, counters, &[b.sprites, b.mask], b.sprite_image, [width, height], &push, "bokeh/draw")?;
        backend.run(bokeh_combine::Bindings { blur: b.blur, sprites: b.sprite_image, out }, groups, &params, "bokeh/draw")?;
        record_output(backend, f, self.io.as_ref())
    }

    /// Bright pixels the last frame detected and the gather's window radius (reads them back:
    /// call once the frame completed).
    pub fn detected_and_radius(&self, backend: &mut dyn Backend) -> Result<(u64, u32)> {
        self.detected_and_radius_of(backend, 0)
    }

    /// The same for the frame recorded `frames_ago` recordings before the last (see
    /// [`DofContext::report_frame`]).
    pub fn detected_and_radius_of(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<(u64, u32)> {
        let (detected, radius, _) = self.figures_of(backend, frames_ago)?;
        Ok((detected, radius))
    }

    /// Bright pixels detected, the gather's radius and the clamped input colours of the frame
    /// `frames_ago` recordings before the last.
    fn figures_of(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<(u64, u32, u32)> {
        self.owned.check(backend)?;
        let (slot, ()) = self.in_flight.slot(frames_ago)?;
        let detected = backend.read_buffer(self.b.counters[slot], COUNTER as u64, 1)?[0] as u64;
        let words = backend.read_buffer(self.b.radius[slot], 0, 2)?;
        Ok((detected, words[0].min(MAX_RADIUS), words[1]))
    }
}

impl DofContext for BokehContext {
    fn method(&self) -> &'static str {
        "bokeh"
    }
    fn extent(&self) -> Extent {
        self.desc.extent()
    }
    fn recording(&mut self, backend: &dyn Backend, frame: &Frame) -> Result<Recording> {
        BokehContext::recording(self, backend, frame)
    }
    fn frames_in_flight(&self) -> u32 {
        self.in_flight.frames()
    }
    fn report_frame(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<ContextReport> {
        let (detected, radius, clamped) = self.figures_of(backend, frames_ago)?;
        let overflow = detected.saturating_sub(self.desc.options.capacity as u64);
        let mut summary = format!("{detected} bright pixels detected, {} drawn as sprites", detected - overflow);
        if overflow > 0 {
            summary += &format!(" ({overflow} beyond the capacity of {} left in the blur)", self.desc.options.capacity);
        }
        summary += &format!(", over a gather of radius {radius} px{}", clamped_summary(clamped));
        Ok(ContextReport {
            summary,
            details: Some(std::sync::Arc::new(BokehReport { sprites: detected, radius_px: radius, clamped })),
            overflow,
            ..Default::default()
        })
    }
    fn device_bytes(&self) -> u64 {
        BokehContext::device_bytes(self)
    }
    fn resize(&mut self, backend: &mut dyn Backend, extent: Extent) -> Result<()> {
        self.owned.check(backend)?;
        let desc = self.desc.clone();
        remake(self, backend, &desc, extent, BokehContext::new, BokehContext::destroy)
    }
    fn destroy(self: Box<Self>, backend: &mut dyn Backend) {
        BokehContext::destroy(*self, backend)
    }
}

/// What a bokeh sprite frame did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BokehReport {
    /// Bright pixels detected (those beyond the capacity stay in the blur).
    pub sprites: u64,
    /// The gather's radius (px).
    pub radius_px: u32,
    /// Input values clamped where read (the numerical contract).
    pub clamped: u32,
}

super::context::report_details!(BokehReport, |r| vec![
    ("sprites", r.sprites as f64),
    ("radius_px", r.radius_px as f64),
    ("clamped", r.clamped as f64),
]);
