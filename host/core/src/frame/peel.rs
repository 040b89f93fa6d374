//! The device half of depth peeling (Franke et al. 2018, §4.1-4.3), whatever draws the passes: the
//! slots in the layout [`super::FrameInput::Layers`] reads, the reach the next pass tests against,
//! the indirect arguments of each pass, and the disocclusion buffer. Kernels and rules in
//! `dof_shaders::peel`; a drawer (the mesh rasteriser's `MeshPeelContext`, in the crate `dof` above the core) records,
//! per frame:
//!
//! ```text
//! begin ─┬─ plan(k) ── draw k (indirect, reach) ── shade k (indirect) ── append(k) ─┬─ plan(L) ── finish
//!        └────────────────────────── k = 0 .. L − 1 ────────────────────────────────┘
//! ```
//!
//! Every pass is recorded; `plan(k)` zeroes pass `k`'s draw and dispatches on the device when pass
//! `k − 1` found no surface anywhere, so the passes past the last useful one cost a cleared target
//! and nothing else. Nothing is read back, uploaded or allocated per frame.

use super::context::ContextReport;
use super::io::Owned;
use crate::backend::{Backend, BufferId, RunKernel, groups_for};
use crate::error::{Error, Result};
use dof_shaders::lens::ThinLens;
use dof_shaders::peel::{
    APPEND_ARGS, ARGS_WORDS, BandParams, PEEL_APPEND, PEEL_BAND, PEEL_BAND_END, PEEL_EDGES, PEEL_MASK, PEEL_PLAN, PEEL_SPAN, PeelParams,
    SHADE_ARGS, SLOT_WORDS, peel_append, peel_band, peel_band_end, peel_edges, peel_mask, peel_plan, peel_span,
};
use dof_shaders::raster::shade::{LAYER_WORDS, RASTER_SHADE};
use dof_shaders::resolve::{RESOLVE, ResolveParams, resolve};

/// The kernels a peel records (a drawer prepares them with its own; the resolve only with
/// sub-samples).
pub const KERNELS: [&dof_shaders::KernelDesc; 8] =
    [&PEEL_PLAN, &PEEL_APPEND, &PEEL_EDGES, &PEEL_SPAN, &PEEL_MASK, &PEEL_BAND, &PEEL_BAND_END, &RESOLVE];

/// The peel's buffers on the device for a `width` x `height` image with `layers` slots a pixel
/// (owned by the context that made them).
#[derive(Clone, Debug)]
pub struct PeelSlots {
    pub width: u32,
    pub height: u32,
    pub layers: u32,
    /// Passes a frame: `layers`, then those that composite a translucent stack deeper than the
    /// slots into its last slot (`dof_shaders::peel::target_slot`).
    pub passes: u32,
    /// `layers` slots a pixel ([`SLOT_WORDS`] words: premultiplied r, g, b, depth, alpha; the frame
    /// API's layer input), front to back; then, with `footprint_side` above 0, a footprint a slot
    /// (`dof_shaders::footprint`; the frame API's `FrameInput::Layers::footprint_side`).
    pub fragments: BufferId,
    pub footprint_side: u32,
    /// Slots used per pixel.
    pub counts: BufferId,
    /// Per pixel, the depth the next pass's fragments must lie beyond (f32 bits).
    pub reach: BufferId,
    /// [`ARGS_WORDS`] words: the next pass's draw command, then its shading and append dispatches.
    pub args: BufferId,
    /// The shaded layer of the pass being appended (5 words a pixel: r, g, b, alpha, depth).
    pub layer: BufferId,
    /// The disocclusion buffer, one word a pixel (1: inside).
    pub mask: BufferId,
    found: BufferId,
    /// `2 · passes` words: whether pass `k` was drawn, then whether it kept a surface where the
    /// pixel can take more (`dof_shaders::peel::takes_more`). One a frame in flight
    /// ([`Self::with_frames_in_flight`]); frames write `passes_run[slot]`.
    passes_run: Vec<BufferId>,
    slot: usize,
    edge: BufferId,
    widest: BufferId,
    span: BufferId,
    /// The guard band a view needs: the widest CoC radius found (f32 bits, per frame), the last
    /// frame's band, and the frames whose band exceeded the image's.
    band: BufferId,
}

/// What a frame's peel did, from the device.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PeelReport {
    /// Passes recorded (the slots a pixel, then the passes for translucent stacks deeper than them).
    pub recorded: u32,
    /// Passes that drew (the earlier pass kept a surface where a pixel can take more).
    pub drawn: u32,
    /// Passes that kept a surface somewhere where the pixel can take more (the last slot's pass,
    /// where it fills every pixel with an opaque surface, counts as finding none).
    pub with_surface: u32,
    /// The guard band (pixels) the last frame's view needed (`scene::guard_band`'s rule, computed
    /// on the device), where the image has the band fixed at creation.
    pub band_needed: u32,
    /// Frames since the context was made whose view needed a wider band than the image has (their
    /// edges miss some blur from beyond the band).
    pub band_exceeded_frames: u32,
}

impl PeelReport {
    /// The report in the shape every context's has, with the guard band the image was made with.
    pub fn context_report(&self, margin: u32) -> ContextReport {
        ContextReport::of(
            format!(
                "peeled {} passes: {} drawn, {} found a surface (guard band {margin} px; this view needs {} px; {} frames needed more)",
                self.recorded, self.drawn, self.with_surface, self.band_needed, self.band_exceeded_frames
            ),
            PeelFrameReport { peel: self.clone(), guard_band_px: margin },
        )
    }
}

/// A peel's report with the guard band its image was made with.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PeelFrameReport {
    pub peel: PeelReport,
    pub guard_band_px: u32,
}

super::context::report_details!(PeelFrameReport, |r| vec![
    ("peel_passes_recorded", r.peel.recorded as f64),
    ("peel_passes_drawn", r.peel.drawn as f64),
    ("peel_passes_with_surface", r.peel.with_surface as f64),
    ("guard_band_px", r.guard_band_px as f64),
    ("guard_band_needed_px", r.peel.band_needed as f64),
    ("guard_band_exceeded_frames", r.peel.band_exceeded_frames as f64),
]);

impl PeelSlots {
    /// Makes the buffers (into `owned`) for `layers` slots a pixel filled by `passes` passes a frame
    /// (at least `layers`), refusing an empty image or slots beyond one buffer; with a
    /// `footprint_side` above 0 the slots carry footprints (written by [`Self::resolve_from`]).
    pub fn new(
        backend: &mut dyn Backend,
        owned: &mut Owned,
        width: u32,
        height: u32,
        layers: u32,
        passes: u32,
        footprint_side: u32,
    ) -> Result<Self> {
        if passes < layers {
            return Err(Error::InvalidArgument(format!("a peel of {layers} slots a pixel needs at least {layers} passes, got {passes}")));
        }
        let pixels = super::io::context_pixels(backend, "peel", width, height, layers)?;
        if width > i32::MAX as u32 / 2 || height > i32::MAX as u32 / 2 {
            return Err(Error::TooLarge {
                what: "peel image side (px)".into(),
                size: width.max(height) as u64,
                limit: i32::MAX as u64 / 2,
            });
        }
        Ok(PeelSlots {
            width,
            height,
            layers,
            passes,
            footprint_side,
            fragments: owned.make(backend, (SLOT_WORDS as u64 + (footprint_side > 0) as u64) * pixels * layers as u64, "peel/fragments")?,
            counts: owned.make(backend, pixels, "peel/counts")?,
            reach: owned.make(backend, pixels, "peel/reach")?,
            args: owned.make(backend, ARGS_WORDS as u64, "peel/args")?,
            layer: owned.make(backend, LAYER_WORDS as u64 * pixels, "peel/layer")?,
            mask: owned.make(backend, pixels, "peel/mask")?,
            found: owned.make(backend, 1, "peel/found")?,
            passes_run: vec![owned.make(backend, 2 * passes as u64, "peel/passes")?],
            slot: 0,
            edge: owned.make(backend, pixels, "peel/edge")?,
            widest: owned.make(backend, 1, "peel/widest")?,
            span: owned.make(backend, pixels, "peel/span")?,
            band: owned.make(backend, 3, "peel/band")?,
        })
    }

    /// The slots with `frames` copies of what a frame's report reads of its passes (the slots
    /// themselves, and the guard band, stay single: frames in flight run one after another on one
    /// queue, and the guard band is the mesh peel's, which keeps one frame).
    pub fn with_frames_in_flight(mut self, backend: &mut dyn Backend, owned: &mut Owned, frames: u32) -> Result<Self> {
        let label = |i: u32| format!("peel/passes/frame-{i}");
        for i in 1..frames {
            self.passes_run.push(owned.make(backend, 2 * self.passes as u64, &label(i))?);
        }
        Ok(self)
    }

    /// Makes the frames recorded next write report slot `slot` (below the frames in flight).
    pub fn use_slot(&mut self, slot: usize) {
        self.slot = slot.min(self.passes_run.len() - 1);
    }

    fn pixels(&self) -> u64 {
        self.width as u64 * self.height as u64
    }

    fn params(&self, pass: u32, draw_vertices: u32, lens: ThinLens, edge_depth_ratio: f32, disocclusion: bool) -> PeelParams {
        PeelParams {
            lens,
            width: self.width,
            height: self.height,
            layers: self.layers,
            pass,
            edge_depth_ratio,
            disocclusion: disocclusion as u32,
            draw_vertices,
            shade_groups: groups_for(&RASTER_SHADE, self.pixels())[0],
            append_groups: groups_for(&PEEL_APPEND, self.pixels())[0],
            passes: self.passes,
            _pad: [0; 2],
        }
    }

    /// Where the shading pass's indirect dispatch arguments lie in [`Self::args`].
    pub fn shade_args(&self) -> (BufferId, u64) {
        (self.args, SHADE_ARGS as u64)
    }

    /// Starts a frame: no slots, a reach of 0 (pass 0 keeps the nearest fragment), pass 0 planned.
    pub fn begin(&self, backend: &mut dyn Backend) -> Result<()> {
        let pixels = self.pixels();
        backend.fill(self.counts, 0, pixels, 0, "peel/begin")?;
        backend.fill(self.reach, 0, pixels, 0, "peel/begin")?;
        backend.fill(self.found, 0, 1, 1, "peel/begin")?;
        backend.fill(self.widest, 0, 1, 0, "peel/begin")
    }

    /// Plans pass `pass` (`passes`: after the last) for a drawer whose useful pass draws
    /// `draw_vertices` vertices.
    pub fn plan(&self, backend: &mut dyn Backend, pass: u32, draw_vertices: u32) -> Result<()> {
        let params = self.params(pass, draw_vertices, ThinLens::default(), 0.0, false);
        let passes = self.passes_run[self.slot];
        backend.run(peel_plan::Bindings { found: self.found, args: self.args, passes }, [1, 1, 1], &params, "peel/plan")
    }

    /// Appends pass `pass`'s shaded layer ([`Self::layer`]) into the slots, or behind a full
    /// pixel's translucent last slot (indirect: nothing when the pass was not drawn).
    pub fn append(&self, backend: &mut dyn Backend, pass: u32) -> Result<()> {
        let params = self.params(pass, 0, ThinLens::default(), 0.0, false);
        let bound = peel_append::Bindings { layer: self.layer, fragments: self.fragments, counts: self.counts, found: self.found };
        backend.run_indirect(bound, self.args, APPEND_ARGS as u64, &params, "peel/append")
    }

    /// Ends a frame: the disocclusion buffer from the front slots and `lens`, applied when
    /// `disocclusion` is on (unused slots reset either way).
    pub fn finish(&self, backend: &mut dyn Backend, lens: ThinLens, edge_depth_ratio: f32, disocclusion: bool) -> Result<()> {
        let params = self.params(self.passes, 0, lens, edge_depth_ratio, disocclusion);
        let groups = groups_for(&PEEL_EDGES, self.pixels());
        let edges = peel_edges::Bindings { fragments: self.fragments, counts: self.counts, edge: self.edge, widest: self.widest };
        backend.run(edges, groups, &params, "peel/mask")?;
        backend.run(peel_span::Bindings { edge: self.edge, widest: self.widest, span: self.span }, groups, &params, "peel/mask")?;
        let mask =
            peel_mask::Bindings { span: self.span, widest: self.widest, mask: self.mask, fragments: self.fragments, counts: self.counts };
        backend.run(mask, groups, &params, "peel/mask")
    }

    /// Resolves the slots of `fine`, a peel at sub-sample resolution (`side` times wider and higher
    /// than these slots; see `dof_shaders::resolve`), into these slots: area-integrated fragments,
    /// clusters `tolerance` apart in relative depth. Run [`Self::finish`] on these slots after it.
    pub fn resolve_from(&self, backend: &mut dyn Backend, fine: &PeelSlots, side: u32, tolerance: f32) -> Result<()> {
        if side == 0
            || fine.width != self.width * side
            || fine.height != self.height * side
            || (self.footprint_side != 0 && self.footprint_side != side)
        {
            return Err(Error::InvalidArgument(format!(
                "a {}x{} sub-sample peel does not resolve into {}x{} slots with {side}x{side} sub-samples",
                fine.width, fine.height, self.width, self.height
            )));
        }
        let params = ResolveParams {
            width: self.width,
            height: self.height,
            side,
            fine_layers: fine.layers,
            layers: self.layers,
            tolerance,
            footprints: (self.footprint_side > 0) as u32,
            _pad: 0,
        };
        let bound = resolve::Bindings { fine: fine.fragments, fine_counts: fine.counts, fragments: self.fragments, counts: self.counts };
        backend.run(bound, groups_for(&RESOLVE, self.pixels()), &params, "peel/resolve")
    }

    /// Records the guard band the view of `params` needs, from `triangles` triangles of a mesh
    /// (its vertex and triangle buffers), and counts the frame when it exceeds `params.margin`.
    pub fn band(&self, backend: &mut dyn Backend, vertices: BufferId, triangles: BufferId, params: &BandParams) -> Result<()> {
        let groups = groups_for(&PEEL_BAND, params.triangles as u64);
        backend.run(peel_band::Bindings { vertices, triangles, band: self.band }, groups, params, "peel/band")?;
        backend.run(peel_band_end::Bindings { band: self.band }, [1, 1, 1], params, "peel/band")
    }

    /// What the last frame's passes did (reads the device: once the frame completed).
    pub fn report(&self, backend: &mut dyn Backend) -> Result<PeelReport> {
        self.report_of(backend, self.slot)
    }

    /// What the frame that wrote report slot `slot` did (once it completed).
    pub fn report_of(&self, backend: &mut dyn Backend, slot: usize) -> Result<PeelReport> {
        let passes = *self.passes_run.get(slot).ok_or_else(|| Error::InvalidArgument(format!("no peel report slot {slot}")))?;
        let words = backend.read_buffer(passes, 0, 2 * self.passes as u64)?;
        let band = backend.read_buffer(self.band, 0, 3)?;
        let (drawn, found) = words.split_at(self.passes as usize);
        let count = |w: &[u32]| w.iter().filter(|&&v| v != 0).count() as u32;
        Ok(PeelReport {
            recorded: self.passes,
            drawn: count(drawn),
            with_surface: count(found),
            band_needed: band[1],
            band_exceeded_frames: band[2],
        })
    }
}
