//! Depth peeling with a renderer's own passes (Franke et al. 2018, §4.1-4.3): the renderer keeps
//! its materials, pipelines and render passes; the library owns the peeling logic
//! ([`super::peel::PeelSlots`], the rules in `dof_shaders::renderer_peel` and `dof_shaders::peel`).
//!
//! Per frame, all in the caller's command buffer (each library call between `begin_external` and
//! `end_external`), nothing read back, uploaded or allocated:
//!
//! ```text
//! begin ──► draw 0 ──► append(0) ──► draw 1 ──► append(1) ──► … ──► draw L−1 ──► append(L−1) ──► finish
//!   │        ▲            │            ▲           │
//!   │  bound: keep all    │  bound(1), draw args   │  bound(2), …
//!   └─ draw args (pass 0) └────────────────────────┘
//! ```
//!
//! - `bound()` holds one f32 a pixel: the renderer's fragment shader discards a fragment unless
//!   `dof_shaders::renderer_peel::keep(gl_FragCoord.z, bound[pixel])` (GLSL in `docs/integration.md`). It is
//!   the previous layer's reach (its depth plus the umbra behind it) in the attachment's own depth
//!   encoding, or "discard all" outside the disocclusion buffer behind an opaque layer (a translucent
//!   one never ends the peel) and where nothing lies beyond.
//! - `append(k)` copies the renderer's colour and depth attachments into the context's buffers,
//!   turns them into pass `k`'s layer and appends it to the slots, then writes pass `k + 1`'s bound
//!   and indirect draw command. After pass 0 it builds the disocclusion buffer (§4.3) from the front
//!   layer, which later passes do not change.
//! - Passes past the last useful one: the draw command the library writes into the caller's
//!   `draw` buffer has a count of zero (decided on the device), and the library's own kernels of
//!   that pass dispatch zero workgroups; only the two attachment copies remain. A renderer that
//!   draws directly instead gets every fragment discarded by the bound.

use super::LayerOptions;
use super::context::ContextReport;
use super::in_flight::InFlight;
use super::io::{CountBuffer, DepthEncoding, Frame, FrameInput, FrameOutput, Owned, SlotBuffer, context_pixels, ready};
use super::peel::{KERNELS, PeelReport, PeelSlots};
use crate::backend::{Backend, BufferId, ImageFormat, ImageRef, RunKernel, format_names};
use crate::error::{Error, Result};
use dof_shaders::frame_io::{DEPTH_F32, DEPTH_REVERSED, DEPTH_STANDARD, DEPTH_UNORM24, FrameIoParams};
use dof_shaders::lens::ThinLens;
use dof_shaders::peel::{APPEND_ARGS, SHADE_ARGS};
use dof_shaders::renderer_peel::{
    KEEP_ALL, PEEL_RENDERER_BOUND, PEEL_RENDERER_DRAW, PEEL_RENDERER_LAYER, RendererPeelParams, peel_renderer_bound, peel_renderer_draw,
    peel_renderer_layer,
};

/// Depth attachments a renderer's passes may have.
const DEPTH_FORMATS: [ImageFormat; 3] = [ImageFormat::D32Float, ImageFormat::D24UnormS8Uint, ImageFormat::X8D24UnormPack32];
/// Colour attachments a renderer's passes may have.
const COLOR_FORMATS: [ImageFormat; 3] = [ImageFormat::Rgba16Float, ImageFormat::Rgba32Float, ImageFormat::B10G11R11Ufloat];

/// What a renderer's peel is made for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RendererPeelDesc {
    /// The attachments' size (the frame and any guard band the renderer draws).
    pub width: u32,
    pub height: u32,
    /// Slots a pixel, and passes a frame (>= 1).
    pub max_layers: u32,
    /// The colour attachment: RGBA16F, RGBA32F (alpha: coverage) or B10G11R11 (coverage 1).
    pub color_format: ImageFormat,
    /// The depth attachment: D32_SFLOAT, D24_UNORM_S8_UINT or X8_D24_UNORM_PACK32.
    pub depth_format: ImageFormat,
    /// The projection's depth planes (`Standard` or `Reversed`; the far plane may be infinite).
    pub encoding: DepthEncoding,
    /// `tan(vertical field of view / 2)`: the pixel footprint the umbra is measured with.
    pub tan_half_fov: f32,
    /// The count of the renderer's useful draw (vertices, or indices of an indexed draw), written
    /// into the indirect draw command of every pass that may find something.
    pub draw_count: u32,
    /// Relative depth difference between 4-neighbours that counts as a discontinuity.
    pub edge_depth_ratio: f32,
    /// Passes after the first keep nothing outside the disocclusion buffer.
    pub disocclusion: bool,
    /// Frames in flight (default 1, at most [`super::MAX_FRAMES_IN_FLIGHT`]): copies kept of what
    /// a frame's report reads, so that each of the last N frames' reports stays readable.
    pub frames_in_flight: u32,
}

impl RendererPeelDesc {
    /// The description for `options` (layers, edge ratio, disocclusion), attachments of
    /// `width` x `height` in RGBA16F and D32_SFLOAT.
    pub fn new(options: &LayerOptions, width: u32, height: u32, encoding: DepthEncoding, tan_half_fov: f32, draw_count: u32) -> Self {
        RendererPeelDesc {
            width,
            height,
            max_layers: options.max_layers,
            color_format: ImageFormat::Rgba16Float,
            depth_format: ImageFormat::D32Float,
            encoding,
            tan_half_fov,
            draw_count,
            edge_depth_ratio: options.edge_depth_ratio,
            disocclusion: options.disocclusion,
            frames_in_flight: 1,
        }
    }
}

/// A depth peel whose passes a renderer draws (module docs).
pub struct RendererPeel {
    desc: RendererPeelDesc,
    slots: PeelSlots,
    /// The attachments, copied (colour words, then one depth word a pixel).
    color: BufferId,
    depth: BufferId,
    /// The caller's: one bound a pixel, and an indirect draw command (5 words).
    bound: BufferId,
    draw: Option<BufferId>,
    /// The frame's lens and the next pass to append (`None`: no frame begun).
    lens: ThinLens,
    next: Option<u32>,
    /// The report slot each finished frame wrote.
    in_flight: InFlight<()>,
    owned: Owned,
}

impl RendererPeel {
    /// Makes the slots and the attachment copies. `bound` (the caller's, `width · height` words)
    /// receives each pass's bound; `draw` (the caller's, 5 words), when given, each pass's
    /// indirect draw command.
    pub fn new(backend: &mut dyn Backend, desc: &RendererPeelDesc, bound: BufferId, draw: Option<BufferId>) -> Result<Self> {
        let d = desc;
        let pixels = context_pixels(backend, "renderer peel", d.width, d.height, d.max_layers)?;
        if !DEPTH_FORMATS.contains(&d.depth_format) || !COLOR_FORMATS.contains(&d.color_format) {
            return Err(Error::InvalidArgument(format!(
                "a renderer's peel takes depth attachments of {} and colour of {}, got {} and {}",
                format_names(&DEPTH_FORMATS),
                format_names(&COLOR_FORMATS),
                d.depth_format,
                d.color_format
            )));
        }
        match d.encoding {
            DepthEncoding::Standard { near, far } | DepthEncoding::Reversed { near, far }
                if near.is_finite() && near > 0.0 && far > near => {}
            e => {
                return Err(Error::InvalidArgument(format!(
                    "a renderer's peel needs its depth planes (Standard or Reversed, 0 < near < far), got {e:?}"
                )));
            }
        }
        if !(d.tan_half_fov > 0.0 && d.tan_half_fov.is_finite()) || !(d.edge_depth_ratio >= 0.0) {
            return Err(Error::InvalidArgument(format!(
                "need tan(fov/2) > 0 and a non-negative edge ratio, got {} and {}",
                d.tan_half_fov, d.edge_depth_ratio
            )));
        }
        for (what, id, words) in [("bound", Some(bound), pixels), ("draw", draw, 5)] {
            if let Some(id) = id {
                let have = backend.buffer_words(id)?;
                if have < words {
                    return Err(Error::InvalidArgument(format!("the {what} buffer holds {have} words, the peel needs {words}")));
                }
            }
        }
        let in_flight = InFlight::new(d.frames_in_flight)?;
        let mut owned = Owned::default();
        let made = (|| {
            let slots = PeelSlots::new(backend, &mut owned, d.width, d.height, d.max_layers, d.max_layers, 0)?;
            let slots = slots.with_frames_in_flight(backend, &mut owned, d.frames_in_flight)?;
            let color = owned.make(backend, d.color_format.words_per_pixel() * pixels, "renderer-peel/color")?;
            let depth = owned.make(backend, pixels, "renderer-peel/depth")?;
            Ok((slots, color, depth))
        })();
        let ((slots, color, depth), owned) = owned.or_free(backend, made)?;
        let lens = ThinLens::default();
        let ctx = RendererPeel { desc: *d, slots, color, depth, bound, draw, lens, next: None, in_flight, owned };
        let mut kernels = vec![&PEEL_RENDERER_LAYER, &PEEL_RENDERER_BOUND, &PEEL_RENDERER_DRAW];
        kernels.extend(KERNELS);
        ready(backend, ctx, &kernels, &[], Self::destroy)
    }

    pub fn destroy(self, backend: &mut dyn Backend) {
        self.owned.free(backend);
    }

    /// Device bytes of the context's own buffers (not the caller's bound and draw buffers).
    pub fn device_bytes(&self) -> u64 {
        self.owned.bytes()
    }

    /// The attachments' size.
    pub fn size(&self) -> [u32; 2] {
        [self.desc.width, self.desc.height]
    }

    /// Slots a pixel (passes a frame).
    pub fn layers(&self) -> u32 {
        self.desc.max_layers
    }

    /// The slots, counts and disocclusion buffer on the device.
    pub fn slots(&self) -> &PeelSlots {
        &self.slots
    }

    /// The slots the last finished frame wrote, as a frame of the frame API.
    pub fn frame(&self, lens: ThinLens, output: FrameOutput) -> Frame {
        let s = &self.slots;
        let input = FrameInput::Layers {
            fragments: SlotBuffer::current(s.fragments),
            counts: CountBuffer(s.counts),
            layers: s.layers,
            footprint_side: s.footprint_side,
        };
        Frame { width: s.width, height: s.height, lens, input, output }
    }

    fn params(&self, pass: u32) -> RendererPeelParams {
        let d = &self.desc;
        let (depth_encoding, near, far) = match d.encoding {
            DepthEncoding::Reversed { near, far } => (DEPTH_REVERSED, near, far),
            DepthEncoding::Standard { near, far } => (DEPTH_STANDARD, near, far),
            DepthEncoding::Linear => (DEPTH_STANDARD, 0.0, 0.0), // refused at creation
        };
        RendererPeelParams {
            io: FrameIoParams {
                width: d.width,
                height: d.height,
                color_words: d.color_format.words_per_pixel() as u32,
                depth_encoding,
                near,
                far,
                layers: d.max_layers,
                depth_format: if d.depth_format.is_unorm24() { DEPTH_UNORM24 } else { DEPTH_F32 },
            },
            lens: self.lens,
            footprint_per_depth: d.tan_half_fov / d.height as f32,
            pass,
            disocclusion: d.disocclusion as u32,
            _pad: 0,
        }
    }

    fn check(&self, backend: &dyn Backend) -> Result<()> {
        self.owned.check(backend)?;
        backend.check_frame_recording()
    }

    /// Starts a frame seen through `lens`: no slots, pass 0's bound keeps everything, pass 0's draw
    /// command written.
    pub fn begin(&mut self, backend: &mut dyn Backend, lens: &ThinLens) -> Result<()> {
        self.check(backend)?;
        crate::lens::check(lens)?;
        self.lens = *lens;
        let pixels = self.desc.width as u64 * self.desc.height as u64;
        self.slots.use_slot(self.in_flight.next());
        self.slots.begin(backend)?;
        backend.fill(self.bound, 0, pixels, KEEP_ALL.to_bits(), "renderer-peel/bound")?;
        self.slots.plan(backend, 0, self.desc.draw_count)?;
        self.write_draw(backend)?;
        self.next = Some(0);
        Ok(())
    }

    fn write_draw(&self, backend: &mut dyn Backend) -> Result<()> {
        match self.draw {
            Some(draw) => {
                backend.run(peel_renderer_draw::Bindings { args: self.slots.args, draw }, [1, 1, 1], &self.params(0), "renderer-peel/draw")
            }
            None => Ok(()),
        }
    }

    /// Appends pass `pass` (the renderer's `color` and `depth` attachments, of the context's
    /// formats and at least its size; their top-left part is read) and writes the next pass's bound
    /// and draw command. Passes go in order, `0 .. max_layers`, after [`Self::begin`].
    pub fn append(&mut self, backend: &mut dyn Backend, pass: u32, color: ImageRef, depth: ImageRef) -> Result<()> {
        self.check(backend)?;
        if self.next != Some(pass) {
            return Err(Error::InvalidArgument(match self.next {
                None => format!("pass {pass} appended outside a frame (call begin first)"),
                Some(k) if k >= self.desc.max_layers => format!("pass {pass} appended after the last pass (call finish)"),
                Some(k) => format!("pass {pass} appended where pass {k} comes next"),
            }));
        }
        let (w, h) = (self.desc.width, self.desc.height);
        for (what, image, format) in [("colour", &color, self.desc.color_format), ("depth", &depth, self.desc.depth_format)] {
            if image.format != format {
                return Err(Error::InvalidArgument(format!("the {what} attachment is {}; the peel was made for {format}", image.format)));
            }
            if image.extent[0] < w || image.extent[1] < h {
                return Err(Error::InvalidArgument(format!(
                    "the {what} attachment is {}x{}, smaller than the peel's {w}x{h}",
                    image.extent[0], image.extent[1]
                )));
            }
            backend.check_image_copy(&image.top_left(w, h), false)?;
        }
        let s = &self.slots;
        backend.copy_image_to_buffer(color.top_left(w, h), self.color, 0, "renderer-peel/color")?;
        backend.copy_image_to_buffer(depth.top_left(w, h), self.depth, 0, "renderer-peel/depth")?;
        let layer = peel_renderer_layer::Bindings { color: self.color, depth: self.depth, reach: s.reach, layer: s.layer };
        backend.run_indirect(layer, s.args, SHADE_ARGS as u64, &self.params(pass), "renderer-peel/layer")?;
        s.append(backend, pass)?;
        if pass == 0 {
            // The disocclusion buffer from the front layer, final from here on: the later passes'
            // bounds discard everything outside it.
            s.finish(backend, self.lens, self.desc.edge_depth_ratio, self.desc.disocclusion)?;
        }
        s.plan(backend, pass + 1, self.desc.draw_count)?;
        if pass + 1 < self.desc.max_layers {
            self.write_draw(backend)?;
            // Zero workgroups after a pass that found nothing: the bound it left finds nothing again.
            let bound = peel_renderer_bound::Bindings { depth: self.depth, mask: s.mask, reach: s.reach, bound: self.bound };
            backend.run_indirect(bound, s.args, APPEND_ARGS as u64, &self.params(pass + 1), "renderer-peel/bound")?;
        }
        self.next = Some(pass + 1);
        Ok(())
    }

    /// Ends the frame after its last pass: unused slots reset, and outside the disocclusion buffer
    /// (when on) only the slots up to the first opaque one kept. The slots are then [`Self::frame`]'s input.
    pub fn finish(&mut self, backend: &mut dyn Backend) -> Result<()> {
        self.check(backend)?;
        if self.next != Some(self.desc.max_layers) {
            return Err(Error::InvalidArgument(format!(
                "finish after {} of {} passes (append every pass first)",
                self.next.unwrap_or(0),
                self.desc.max_layers
            )));
        }
        self.slots.finish(backend, self.lens, self.desc.edge_depth_ratio, self.desc.disocclusion)?;
        self.next = None;
        self.in_flight.recorded(());
        Ok(())
    }

    /// Frames in flight whose reports the peel keeps.
    pub fn frames_in_flight(&self) -> u32 {
        self.in_flight.frames()
    }

    /// What the last finished frame's passes did (reads the device: once the frame completed). The
    /// guard band figures are not measured here (the renderer draws its own band): they read 0.
    pub fn report(&self, backend: &mut dyn Backend) -> Result<PeelReport> {
        self.report_of(backend, 0)
    }

    /// What the frame finished `frames_ago` frames before the last did (0: the last), once it
    /// completed; refused where no such frame was finished or a later one took its slot
    /// (`frames_ago` at least the frames in flight).
    pub fn report_of(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<PeelReport> {
        self.owned.check(backend)?;
        let (slot, ()) = self.in_flight.slot(frames_ago)?;
        self.slots.report_of(backend, slot)
    }

    /// [`Self::report_of`] in the shape every context's report has ([`ContextReport`], its
    /// details a [`super::peel::PeelFrameReport`]).
    pub fn report_frame(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<ContextReport> {
        Ok(self.report_of(backend, frames_ago)?.context_report(0))
    }
}
