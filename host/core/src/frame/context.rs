//! The one shape every method's frame context has: [`DofContext`]. A context is made once for a
//! backend and a largest frame ([`Extent`]), records any frame within it, reports what its last
//! frame did, resizes, and is destroyed on the backend that made it. Callers that drive several
//! methods (the CLI, the viewer, the benchmarks, the fuzz target) hold `Box<dyn DofContext>` made
//! through the [registry](super::registry) and never name a concrete context.

use super::io::Frame;
use super::recording::Recording;
use crate::backend::Backend;
use crate::error::Result;
pub use crate::extent::Extent;
use std::any::Any;
use std::collections::BTreeMap;
use std::sync::Arc;

/// What every context's description holds: its largest frame, as `max_width`, `max_height` and
/// `max_layers`.
pub(crate) trait Described: Clone {
    fn extent(&self) -> Extent;
    /// The same description for another largest frame.
    fn at(&self, extent: Extent) -> Self;
}

/// `described!(Desc)` in a context's module: [`Described`] for a description with `max_width`,
/// `max_height` and `max_layers` fields.
macro_rules! described {
    ($desc:ty) => {
        impl $crate::frame::context::Described for $desc {
            fn extent(&self) -> $crate::frame::context::Extent {
                $crate::frame::context::Extent::new(self.max_width, self.max_height, self.max_layers)
            }
            fn at(&self, e: $crate::frame::context::Extent) -> Self {
                Self { max_width: e.width, max_height: e.height, max_layers: e.layers, ..self.clone() }
            }
        }
    };
}
pub(crate) use described;

/// How every context resizes: one made by `make` from its description at `extent` replaces it,
/// and the old one is freed after, so a failure keeps the old one. Callers check first that
/// `backend` is the context's own.
pub(crate) fn remake<C, D: Described>(
    ctx: &mut C,
    backend: &mut dyn Backend,
    desc: &D,
    extent: Extent,
    make: fn(&mut dyn Backend, &D) -> Result<C>,
    destroy: fn(C, &mut dyn Backend),
) -> Result<()> {
    let fresh = make(backend, &desc.at(extent))?;
    destroy(std::mem::replace(ctx, fresh), backend);
    Ok(())
}

/// What a method's frame did, as its own type (`SplatReport`, `GatherReport`, ...): read back
/// by type with [`ContextReport::details`], flattened by name for tables with
/// [`ContextReport::figures`].
pub trait ReportDetails: std::fmt::Debug + Send + Sync + 'static {
    /// Its figures by name (`mean_list_length`, `radius_px`, ...).
    fn figures(&self) -> Vec<(&'static str, f64)>;
    /// Itself, for [`ContextReport::details`].
    fn as_any(&self) -> &dyn Any;
}

/// What a context's last frame did and left out, in a form every method shares, with the
/// method's own report inside. Read from the device, so only once that frame's work has
/// completed.
#[derive(Clone, Debug, Default)]
pub struct ContextReport {
    /// One line for people: what the frame did and what it left out.
    pub summary: String,
    /// The method's own report ([`ContextReport::details`] reads it by type).
    pub details: Option<Arc<dyn ReportDetails>>,
    /// Tiles per list-length bucket `(upper bound, tiles)` (Franke et al. 2018, Fig. 12); empty for
    /// methods without tile lists.
    pub list_histogram: Vec<(u32, u32)>,
    /// Work the frame could not hold and cut short (tiles whose lists overflowed, highlights beyond
    /// the sprite capacity): 0 when the frame is whole.
    pub overflow: u64,
}

impl ContextReport {
    /// A report of `details`, with its summary.
    pub fn of(summary: String, details: impl ReportDetails) -> Self {
        ContextReport { summary, details: Some(Arc::new(details)), ..Default::default() }
    }

    /// The method's own report, if it is a `T`:
    /// `report.details::<SplatReport>().map(|r| r.overflow_tiles)`.
    pub fn details<T: ReportDetails>(&self) -> Option<&T> {
        self.details.as_deref().and_then(|d| d.as_any().downcast_ref())
    }

    /// The method's figures by name, for tables that list every method's.
    pub fn figures(&self) -> BTreeMap<String, f64> {
        self.details.iter().flat_map(|d| d.figures()).map(|(k, v)| (k.to_string(), v)).collect()
    }

    /// One figure by name.
    pub fn figure(&self, name: &str) -> Option<f64> {
        self.details.as_ref()?.figures().into_iter().find(|(k, _)| *k == name).map(|(_, v)| v)
    }
}

/// Two reports are equal when they say the same: summary, figures, histogram and overflow.
impl PartialEq for ContextReport {
    fn eq(&self, other: &Self) -> bool {
        self.summary == other.summary
            && self.figures() == other.figures()
            && self.list_histogram == other.list_histogram
            && self.overflow == other.overflow
    }
}

/// Implements [`ReportDetails`] for a report struct from a list of its figures.
macro_rules! report_details {
    ($t:ty, |$r:ident| $figures:expr) => {
        impl $crate::frame::context::ReportDetails for $t {
            fn figures(&self) -> Vec<(&'static str, f64)> {
                let $r = self;
                $figures
            }
            fn as_any(&self) -> &dyn std::any::Any {
                self
            }
        }
    };
}
pub(crate) use report_details;

/// A method's frame context (see the [module docs](crate::frame) for what a frame may and may not
/// do). Every method implements it; nothing outside a method's own module names its concrete type.
pub trait DofContext {
    /// The registry name of the method (`multilayer`, `ring-gather`, ...).
    fn method(&self) -> &'static str;
    /// The largest frame it records.
    fn extent(&self) -> Extent;
    /// One frame of any size within [`DofContext::extent`] as a value: its commands, checked
    /// against `backend` (the one that made the context; another is refused), with what each
    /// reads and writes. Nothing is recorded until it is [encoded](Recording::encode), into the
    /// backend, or by a caller's render graph that schedules the commands itself. Making it takes
    /// the frame's report slot (see [`DofContext::report_frame`]).
    fn recording(&mut self, backend: &dyn Backend, frame: &Frame) -> Result<Recording>;
    /// Records one frame into the backend's current command buffer (the caller's, on a caller's
    /// device): its [`DofContext::recording`], encoded. No allocation, readback or submission.
    /// Every check runs before the first command is recorded: a refused frame leaves the command
    /// buffer, and the context, as they were.
    fn record(&mut self, backend: &mut dyn Backend, frame: &Frame) -> Result<()> {
        backend.check_frame_recording()?;
        self.recording(backend, frame)?.encode(backend)
    }
    /// What the last recorded frame did and left out (reads the device: call once it completed).
    fn report(&self, backend: &mut dyn Backend) -> Result<ContextReport> {
        self.report_frame(backend, 0)
    }
    /// Frames in flight the context serves (chosen at creation, `frames_in_flight` of its
    /// description): each recording writes the next of that many report slots, round robin.
    fn frames_in_flight(&self) -> u32 {
        1
    }
    /// What the frame recorded `frames_ago` recordings before the last did (0: the last, as
    /// [`DofContext::report`]). Read a frame's report after its fence and before recording
    /// [`DofContext::frames_in_flight`] more frames, which reuse its slot: with `N` frames in
    /// flight, after waiting on the fence of the frame about to be reused and before recording
    /// into it, that frame's report is `report_frame(backend, N - 1)`. Refused for a frame whose
    /// slot was reused or that was never recorded.
    ///
    /// A renderer's loop with `N` fences, on the CPU backend (where `submit` stands for the
    /// renderer's submission with fence `frame % N`, and the wait on it is implied):
    ///
    /// ```
    /// use dof_core::ThinLens;
    /// use dof_core::backend::{Backend, CpuBackend};
    /// use dof_core::frame::{ContextDesc, CountBuffer, Extent, Frame, MethodOptions, RgbBuffer, SlotBuffer, registry};
    /// # fn main() -> dof_core::Result<()> {
    /// const N: u32 = 2;
    /// let mut b = CpuBackend::new();
    /// let desc = ContextDesc { frames_in_flight: N, ..ContextDesc::new(Extent::new(32, 32, 1), MethodOptions::default()) };
    /// let mut ctx = registry::create(&mut b, registry::method("gather")?, &desc)?;
    /// let [fragments, counts, out] = [5 * 1024, 1024, 3 * 1024].map(|w| b.create_buffer(w, "caller").unwrap());
    /// // One opaque fragment a pixel (the layered input's slot words: premultiplied r, g, b, depth,
    /// // alpha), depths 0.5 to 8.2.
    /// let slots: Vec<u32> = (0..1024u32)
    ///     .flat_map(|i| [0.5, 0.25, (i % 7) as f32 / 7.0, 0.5 + (i * 37 % 101) as f32 / 13.0, 1.0].map(f32::to_bits))
    ///     .collect();
    /// b.write_buffer(fragments, 0, &slots)?;
    /// b.write_buffer(counts, 0, &[1u32; 1024])?;
    /// let mut radii = Vec::new();
    /// for frame in 0..6u32 {
    ///     // After waiting on fence `frame % N`: frame - N has completed, its slot is about to be reused.
    ///     if frame >= N {
    ///         radii.push(ctx.report_frame(&mut b, N - 1)?.figure("radius_px").unwrap_or(0.0));
    ///     }
    ///     let lens = ThinLens { focal_length: 0.05, aperture_radius: 0.002 * (frame + 1) as f32, focus_distance: 2.0, pixels_per_unit: 8000.0 };
    ///     let (slots, counts, rgb) = (SlotBuffer::current(fragments), CountBuffer(counts), RgbBuffer(out));
    ///     ctx.record(&mut b, &Frame::layers(32, 32, 1, lens, slots, counts, rgb))?;
    ///     b.submit()?;
    /// }
    /// // Frames 0 to 3, each with its own (growing) aperture, hence window radius.
    /// assert_eq!(radii.len(), 4);
    /// assert!(radii.windows(2).all(|r| r[0] < r[1]), "{radii:?}");
    /// # ctx.destroy(&mut b);
    /// # Ok(())
    /// # }
    /// ```
    fn report_frame(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<ContextReport>;
    /// Device bytes the context holds.
    fn device_bytes(&self) -> u64;
    /// Makes the context hold frames up to `extent` (frees and reallocates; between frames only,
    /// once every frame in flight has completed: their reports go with the old buffers).
    fn resize(&mut self, backend: &mut dyn Backend, extent: Extent) -> Result<()>;
    /// The method's quality knob (see [`super::registry::Knob`]), where it has one that changes
    /// between frames without reallocating.
    fn knob(&self) -> Option<u32> {
        None
    }
    /// Changes the quality knob for the frames recorded next; refused where the method has none
    /// or the value is out of its range.
    fn set_knob(&mut self, value: u32) -> Result<()> {
        Err(crate::error::Error::InvalidArgument(format!("the {} method has no knob to set to {value}", self.method())))
    }
    /// After a frame that overflowed (its report's `overflow` is not 0), grows what overflowed to
    /// what that frame wanted, so that the same frame recorded again is whole. Returns whether it
    /// grew; `false` where the method has nothing to grow or is at its limit. Allocates: between
    /// frames only, never in a renderer's frame loop.
    fn grow_to_fit(&mut self, _backend: &mut dyn Backend) -> Result<bool> {
        Ok(false)
    }
    /// Frees every buffer on the backend that made the context now (handed another, it frees
    /// nothing there; see [`crate::backend::BackendId`]). Optional: a context dropped without it
    /// gives its buffers back through the backend's [`RetireQueue`](crate::backend::RetireQueue),
    /// and the backend frees them once the device is done with them.
    fn destroy(self: Box<Self>, backend: &mut dyn Backend);
}
