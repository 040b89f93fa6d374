//! Layered depth of field with matting (Schedl and Wimmer 2012; kernels and the matting rules in
//! `dof_shaders::layered`) as a frame context, planned on the device:
//!
//! - **Candidate layers fixed at creation.** Layer CoCs grow geometrically from `first_coc` by
//!   `2^(1/layers_per_doubling)` on each side of the focus layer up to `max_coc` (the last one
//!   clamped to it): what the suites' host-planned oracle (`dof_tests::oracle::layered`) plans
//!   for a frame whose blur reaches the cap. Every blur's Gaussian weights are computed then and written once.
//! - **The plan on the device, per frame.** One workgroup places the anchors from the frame's lens
//!   (eq. 9); a reduction over every fragment finds the signed-CoC range (capped at `max_coc`,
//!   the fragments beyond counted) and marks the layers some fragment's matte reaches; one
//!   invocation derives which of the cascade's blurs have anything to blur. Layers no fragment
//!   reaches, and layers behind an infinite anchor (past eq. 8's bound), are left out: their
//!   matte, blur and composite dispatches are recorded but return at once (a gate word of the
//!   plan).
//! - **Blur.** Non-cascaded: each used layer by its own `σ = |d|/4`, composited back to front.
//!   Cascaded: behind the focus the running composite is blurred by the step
//!   `sqrt(σ_{k+1}² − σ_k²)` before layer `k` joins it, in front mirrored, the two joined at the
//!   end. Every step runs once a used layer lies beyond it, so the Gaussians are composed: their
//!   weights have variance `σ²` exactly ([`gaussian`]), so the composed variances add up.
//!
//! So a frame records a fixed sequence of dispatches ([`Schedule`]): no allocation, upload,
//! readback or host pass over the image. The suites' oracle runs the same schedule over layers it
//! plans on the host from the frame's CoC range; the two differ where the frame's blur stops short
//! of a candidate layer (the oracle clamps its outermost layer's CoC to the range), and the layered
//! suite measures how much.

use super::context::{ContextReport, Described, DofContext, Extent, remake};
use super::in_flight::{InFlight, per_frame};
use super::io::{
    Frame, ImageIo, Owned, check_frame, clamped_summary, context_pixels, output_buffer, ready, record_clamp_count, record_input,
    record_output,
};
use super::recording::{Recording, capture};
use crate::backend::{Backend, BufferId, RunKernel, groups_for};
use crate::error::{Error, Result};
use dof_shaders::layered::{
    ALWAYS, LAYERED_MATTE_AT, LAYERED_PLAN_REACH, LayeredParams, LayeredPlanParams, OVER, PLAN_COCS, PLAN_FAR_GATE, PLAN_LAYERS,
    PLAN_NEAR_GATE, PLAN_STATS, PLAN_USED, PLAN_WORDS, UNDER, layered_blur_gated, layered_composite_gated, layered_matte_at,
    layered_plan_begin, layered_plan_end, layered_plan_reach, layered_resolve,
};

/// Layered DoF's settings; all fixed at creation (the candidate layers and blur weights follow
/// from them).
#[derive(Clone, Debug, PartialEq)]
pub struct LayeredOptions {
    /// Recursive (cascaded) blurring instead of one blur per layer.
    pub cascaded: bool,
    /// Layers per doubling of the CoC, `1..=4` (default 2).
    pub layers_per_doubling: u32,
    /// CoC diameter (px) of the first layer beside the focus layer (default 2).
    pub first_coc: f32,
    /// Largest layer CoC diameter (px); larger blur is capped to it and counted (default 256).
    pub max_coc: f32,
}

impl Default for LayeredOptions {
    fn default() -> Self {
        LayeredOptions { cascaded: true, layers_per_doubling: 2, first_coc: 2.0, max_coc: 256.0 }
    }
}

impl LayeredOptions {
    /// Refuses layers per doubling out of `1..=4` and CoCs outside `1 <= first <= max <= 1024`.
    pub fn check(&self) -> Result<()> {
        if !(1..=4).contains(&self.layers_per_doubling) {
            return Err(Error::InvalidArgument(format!("layers per doubling must be 1 to 4, got {}", self.layers_per_doubling)));
        }
        if !(self.first_coc >= 1.0 && self.first_coc.is_finite() && self.max_coc >= self.first_coc && self.max_coc <= 1024.0) {
            return Err(Error::InvalidArgument(format!(
                "need 1 <= first CoC <= max CoC <= 1024 px, got {} and {}",
                self.first_coc, self.max_coc
            )));
        }
        Ok(())
    }

    /// The layer CoC diameters (px) on one side of the focus layer reaching `extent`: from
    /// `first_coc`, growing by `2^(1/layers_per_doubling)`, the last clamped to `extent`; none
    /// where `extent` is under half the first.
    pub fn side(&self, extent: f32) -> Vec<f32> {
        let mut cocs = Vec::new();
        let mut j = 0;
        while extent > self.first_coc * 0.5 && cocs.last().is_none_or(|&c: &f32| c < extent) {
            cocs.push((self.first_coc * 2f32.powf(j as f32 / self.layers_per_doubling as f32)).min(extent));
            j += 1;
        }
        cocs
    }

    /// Every candidate layer's signed CoC (px), front to back, reaching `max_coc` on both sides,
    /// and the focus layer's index.
    pub fn candidates(&self) -> (Vec<f32>, usize) {
        let side = self.side(self.max_coc);
        let cocs = side.iter().rev().map(|c| -c).chain(std::iter::once(0.0)).chain(side.iter().copied()).collect();
        (cocs, side.len())
    }
}

/// The Gaussian `σ` of a layer of CoC diameter `coc` (eq. 10: `d = 4σ`).
pub fn sigma(coc: f32) -> f32 {
    coc.abs() / 4.0
}

/// Normalised Gaussian weights for `σ`: the centre, then each distance up to `ceil(3σ)`, whose
/// variance is `σ²`. Samples of a Gaussian of width `σ` have less (a small `σ` much less: at
/// `σ = 0.5`, 17% less; cut at 3σ, 3% less at any `σ`), so the cascade's steps, each small, would
/// add up to less blur than their sum: the samples are of the width, solved by bisection, whose
/// cut and normalised samples have variance `σ²`.
pub fn gaussian(sigma: f32) -> Vec<f32> {
    let radius = (3.0 * sigma).ceil() as usize;
    let samples = |width: f64| -> Vec<f64> { (0..=radius).map(|i| (-((i * i) as f64) / (2.0 * width * width)).exp()).collect() };
    let normalised = |w: Vec<f64>| {
        let total = w[0] + 2.0 * w[1..].iter().sum::<f64>();
        w.into_iter().map(move |v| v / total)
    };
    let variance = |width: f64| normalised(samples(width)).enumerate().map(|(i, v)| 2.0 * (i * i) as f64 * v).sum::<f64>();
    let target = (sigma as f64).powi(2);
    // The variance grows with the width, towards the box's `r(r + 1)/3 > σ²` (r >= 3σ).
    let (mut lo, mut hi) = (0.0f64, 1.0 + 4.0 * sigma as f64);
    for _ in 0..64 {
        let mid = 0.5 * (lo + hi);
        if variance(mid) < target { lo = mid } else { hi = mid }
    }
    normalised(samples(0.5 * (lo + hi))).map(|v| v as f32).collect()
}

/// What a layered context is created for.
#[derive(Clone, Debug)]
pub struct LayeredContextDesc {
    pub max_width: u32,
    pub max_height: u32,
    /// Most fragment slots per pixel of the input.
    pub max_layers: u32,
    pub options: LayeredOptions,
    /// Hold the buffers that image inputs and outputs go through.
    pub image_io: bool,
    /// Frames in flight (default 1): copies kept of what the report reads.
    pub frames_in_flight: u32,
}

super::context::described!(LayeredContextDesc);

impl LayeredContextDesc {
    /// A description for frames up to `max`, with the defaults of the rest.
    pub fn new(max: Extent, options: LayeredOptions) -> Self {
        let Extent { width: max_width, height: max_height, layers: max_layers } = max;
        LayeredContextDesc { max_width, max_height, max_layers, options, image_io: false, frames_in_flight: 1 }
    }
}

/// The premultiplied RGBA buffers a schedule's steps write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Buf {
    /// The layer being matted and blurred.
    Layer,
    /// The composite behind the focus (and, at the end, the whole image).
    Far,
    /// The composite in front of the focus.
    Near,
}

/// One step of a [`Schedule`]: it runs where its gate (a word of the plan buffer, see
/// `dof_shaders::layered::PLAN_USED` and the gates after it) is not 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Step {
    /// Layer `k` matted into [`Buf::Layer`] with the plan's anchors, gated by its used flag.
    Matte(u32),
    /// The separable Gaussian of `buf` with the weights at `weights_at`.
    Blur { buf: Buf, weights_at: u32, radius: u32, gate: u32 },
    /// `layer` over `acc` ([`OVER`]) or `acc` over `layer` ([`UNDER`]), into `acc`.
    Composite { layer: Buf, acc: Buf, mode: u32, gate: u32 },
}

/// The buffers a [`Schedule`] runs over: the input, the plan (its layers' anchors, used flags and
/// the cascade's gates), every blur's weights, the four RGBA images and the output.
#[derive(Clone, Copy, Debug)]
pub struct ScheduleBuffers {
    pub input: BufferId,
    pub counts: BufferId,
    pub plan: BufferId,
    pub weights: BufferId,
    pub layer: BufferId,
    pub tmp: BufferId,
    pub far: BufferId,
    pub near: BufferId,
    pub out: BufferId,
}

/// Layered DoF's dispatch sequence over a plan's layers (module docs), every step gated by the
/// plan: the context runs it over its candidate layers and its device plan; a host check plans
/// layers of its own into a plan buffer and runs the same schedule over them.
#[derive(Clone, Debug, PartialEq)]
pub struct Schedule {
    pub steps: Vec<Step>,
    /// Every blur's normalised Gaussian weights (f32 bits), where its step's `weights_at` says.
    pub weights: Vec<u32>,
}

impl Schedule {
    /// The schedule over layers of signed CoC diameters `cocs` (px, front to back) whose focus layer
    /// is `focus`: cascaded, or one blur a layer.
    pub fn new(cocs: &[f32], focus: usize, cascaded: bool) -> Schedule {
        let mut steps = Vec::new();
        let mut weights = Vec::new();
        let mut blur = |steps: &mut Vec<Step>, buf: Buf, s: f32, gate: u32| {
            if s > 0.0 {
                let w = gaussian(s);
                steps.push(Step::Blur { buf, weights_at: weights.len() as u32, radius: (w.len() - 1) as u32, gate });
                weights.extend(w.iter().map(|v| v.to_bits()));
            }
        };
        let s = |k: usize| sigma(cocs[k]);
        let used = |k: usize| PLAN_USED + k as u32;
        let n = cocs.len();
        if !cascaded {
            for k in (0..n).rev() {
                steps.push(Step::Matte(k as u32));
                blur(&mut steps, Buf::Layer, s(k), used(k));
                steps.push(Step::Composite { layer: Buf::Layer, acc: Buf::Far, mode: OVER, gate: used(k) });
            }
            return Schedule { steps, weights };
        }
        // Behind the focus, from the back: blur by the step to layer k, then join layer k.
        for k in (focus..n).rev() {
            if k + 1 < n {
                blur(&mut steps, Buf::Far, (s(k + 1).powi(2) - s(k).powi(2)).max(0.0).sqrt(), PLAN_FAR_GATE + k as u32);
            }
            steps.push(Step::Matte(k as u32));
            steps.push(Step::Composite { layer: Buf::Layer, acc: Buf::Far, mode: OVER, gate: used(k) });
        }
        // In front, from the nearest: blur by the step to layer k, then join layer k behind.
        for k in 0..focus {
            if k > 0 {
                blur(&mut steps, Buf::Near, (s(k - 1).powi(2) - s(k).powi(2)).max(0.0).sqrt(), PLAN_NEAR_GATE + k as u32);
            }
            steps.push(Step::Matte(k as u32));
            steps.push(Step::Composite { layer: Buf::Layer, acc: Buf::Near, mode: UNDER, gate: used(k) });
        }
        if focus > 0 {
            let gate = PLAN_NEAR_GATE + focus as u32;
            blur(&mut steps, Buf::Near, s(focus - 1), gate);
            steps.push(Step::Composite { layer: Buf::Near, acc: Buf::Far, mode: OVER, gate });
        }
        Schedule { steps, weights }
    }

    /// Records the steps over `b` for `base`'s frame (its size, slots a pixel and plan layers; the
    /// composites cleared before), then the far composite normalised into `b.out`.
    pub fn record(&self, backend: &mut dyn Backend, base: &LayeredParams, b: &ScheduleBuffers) -> Result<()> {
        let base = LayeredParams { gate: ALWAYS, ..*base };
        // Every layered kernel runs one item a pixel with the same workgroup size.
        let groups = groups_for(&LAYERED_MATTE_AT, base.width as u64 * base.height as u64);
        let id = |buf: Buf| match buf {
            Buf::Layer => b.layer,
            Buf::Far => b.far,
            Buf::Near => b.near,
        };
        for step in &self.steps {
            match *step {
                Step::Matte(k) => {
                    let p = LayeredParams { layer: k, gate: PLAN_USED + k, ..base };
                    let matte = layered_matte_at::Bindings { input: b.input, counts: b.counts, plan: b.plan, layer: b.layer };
                    backend.run(matte, groups, &p, "layered/matte")?;
                }
                Step::Blur { buf, weights_at, radius, gate } => {
                    let h = LayeredParams { radius, weights_at, mode: 0, gate, ..base };
                    let v = LayeredParams { mode: 1, ..h };
                    let across = layered_blur_gated::Bindings { src: id(buf), weights: b.weights, dst: b.tmp, plan: b.plan };
                    backend.run(across, groups, &h, "layered/blur")?;
                    backend.run(layered_blur_gated::Bindings { src: b.tmp, dst: id(buf), ..across }, groups, &v, "layered/blur")?;
                }
                Step::Composite { layer, acc, mode, gate } => {
                    let p = LayeredParams { mode, gate, ..base };
                    let composite = layered_composite_gated::Bindings { layer: id(layer), acc: id(acc), plan: b.plan };
                    backend.run(composite, groups, &p, "layered/composite")?;
                }
            }
        }
        backend.run(layered_resolve::Bindings { acc: b.far, out: b.out }, groups, &base, "layered/composite")
    }
}

/// An `f32` from its [`dof_shaders::keys::sort_key`].
fn from_key(key: u32) -> f32 {
    if key >= 0x8000_0000 { f32::from_bits(key & 0x7fff_ffff) } else { f32::from_bits(!key) }
}

/// The buffers one frame's passes read and write.
struct Passes {
    /// The device plan ([`PLAN_WORDS`]): candidate CoCs, anchors, used flags, gates, range; one
    /// per frame in flight (the report reads it).
    plans: Vec<BufferId>,
    /// Every blur's weights.
    weights: BufferId,
    /// Premultiplied RGBA, 4 words a pixel: the layer matted, the blur's intermediate, the far
    /// and near composites.
    layer: BufferId,
    tmp: BufferId,
    far: BufferId,
    near: BufferId,
}

/// A layered-DoF context (see the [module docs](crate::frame)).
pub struct LayeredContext {
    desc: LayeredContextDesc,
    cocs: Vec<f32>,
    focus: usize,
    schedule: Schedule,
    passes: Passes,
    in_flight: InFlight<()>,
    io: Option<ImageIo>,
    owned: Owned,
}

impl LayeredContext {
    pub fn new(backend: &mut dyn Backend, desc: &LayeredContextDesc) -> Result<Self> {
        desc.options.check()?;
        let pixels = context_pixels(backend, "layered", desc.max_width, desc.max_height, desc.max_layers)?;
        let (cocs, focus) = desc.options.candidates();
        if cocs.len() > PLAN_LAYERS as usize {
            return Err(Error::InvalidArgument(format!("{} candidate layers, the device plan holds {PLAN_LAYERS}", cocs.len())));
        }
        let schedule = Schedule::new(&cocs, focus, desc.options.cascaded);
        let weights = &schedule.weights;
        let max_words = backend.limits().max_buffer_bytes / 4;
        if 4 * pixels > max_words {
            return Err(Error::TooLarge { what: "layered/layer (words)".into(), size: 4 * pixels, limit: max_words });
        }
        let in_flight = InFlight::new(desc.frames_in_flight)?;
        let mut owned = Owned::default();
        let made = (|| {
            let passes = Passes {
                // The plan, then the count of clamped input colours.
                plans: per_frame(&mut owned, backend, desc.frames_in_flight, PLAN_WORDS as u64 + 1, "layered/plan")?,
                weights: owned.make(backend, weights.len() as u64, "layered/weights")?,
                layer: owned.make(backend, 4 * pixels, "layered/layer")?,
                tmp: owned.make(backend, 4 * pixels, "layered/tmp")?,
                far: owned.make(backend, 4 * pixels, "layered/far")?,
                near: owned.make(backend, 4 * pixels, "layered/near")?,
            };
            let coc_words: Vec<u32> = cocs.iter().map(|c| c.to_bits()).collect();
            for &plan in &passes.plans {
                backend.write_buffer(plan, PLAN_COCS as u64, &coc_words)?;
            }
            if !weights.is_empty() {
                backend.write_buffer(passes.weights, 0, weights)?;
            }
            let io = if desc.image_io { Some(ImageIo::new(backend, pixels, &mut owned)?) } else { None };
            Ok((passes, io))
        })();
        let ((passes, io), owned) = owned.or_free(backend, made)?;
        let ctx = LayeredContext { desc: desc.clone(), cocs, focus, schedule, passes, in_flight, io, owned };
        let mut kernels = dof_shaders::layered::KERNELS.to_vec();
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

    pub fn options(&self) -> &LayeredOptions {
        &self.desc.options
    }

    /// The candidate layers' signed CoC diameters (px), front to back, and the focus layer.
    pub fn candidates(&self) -> (&[f32], usize) {
        (&self.cocs, self.focus)
    }

    /// Records one frame: the composites cleared, the device plan, the fixed schedule of gated
    /// mattes, blurs and composites, the normalisation.
    pub fn recording(&mut self, backend: &dyn Backend, f: &Frame) -> Result<Recording> {
        check_frame(backend, f, &self.owned, self.desc.extent(), self.io.as_ref())?;
        let recording = capture(self, backend, f, Self::commands)?;
        self.in_flight.recorded(());
        Ok(recording)
    }

    /// The frame's commands (captured, and checked, by [`capture`]).
    fn commands(&mut self, backend: &mut dyn Backend, f: &Frame) -> Result<()> {
        let d = &self.desc;
        let (input, counts) = record_input(backend, f, self.io.as_ref())?;
        let output = output_buffer(f, self.io.as_ref())?;
        let b = &self.passes;
        let plan_buf = b.plans[self.in_flight.next()];
        record_clamp_count(backend, f, (input, counts), f.layer_count(), plan_buf, PLAN_WORDS)?;
        let pixels = f.width as u64 * f.height as u64;
        backend.fill(b.far, 0, 4 * pixels, 0, "layered/clear")?;
        backend.fill(b.near, 0, 4 * pixels, 0, "layered/clear")?;
        let layers = self.cocs.len() as u32;
        let plan = LayeredPlanParams {
            width: f.width,
            height: f.height,
            max_layers: f.layer_count(),
            layers,
            focus: self.focus as u32,
            max_coc: d.options.max_coc,
            lens: f.lens,
            ..Default::default()
        };
        backend.run(layered_plan_begin::Bindings { plan: plan_buf }, [1, 1, 1], &plan, "layered/plan")?;
        let reach = layered_plan_reach::Bindings { input, counts, plan: plan_buf };
        backend.run(reach, groups_for(&LAYERED_PLAN_REACH, pixels), &plan, "layered/plan")?;
        backend.run(layered_plan_end::Bindings { plan: plan_buf }, [1, 1, 1], &plan, "layered/plan")?;
        let base = LayeredParams { width: f.width, height: f.height, max_layers: f.layer_count(), layers, ..Default::default() };
        let (layer, tmp, far, near, weights) = (b.layer, b.tmp, b.far, b.near, b.weights);
        let buffers = ScheduleBuffers { input, counts, plan: plan_buf, weights, layer, tmp, far, near, out: output };
        self.schedule.record(backend, &base, &buffers)?;
        record_output(backend, f, self.io.as_ref())
    }

    /// The last frame's device plan: the signed-CoC range (px), the fragments beyond the cap, and
    /// which candidate layers were used (reads the device: call once the frame completed).
    pub fn plan(&self, backend: &mut dyn Backend) -> Result<LayeredPlanReport> {
        self.plan_of(backend, 0)
    }

    /// The device plan of the frame recorded `frames_ago` recordings before the last (see
    /// [`DofContext::report_frame`]).
    pub fn plan_of(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<LayeredPlanReport> {
        self.owned.check(backend)?;
        let (slot, ()) = self.in_flight.slot(frames_ago)?;
        let words = backend.read_buffer(self.passes.plans[slot], 0, PLAN_WORDS as u64 + 1)?;
        let s = PLAN_STATS as usize;
        let used = (0..self.cocs.len()).map(|k| words[PLAN_USED as usize + k] != 0).collect();
        let (coc_range, capped, clamped) = ((-from_key(words[s]), from_key(words[s + 1])), words[s + 2] as u64, words[PLAN_WORDS as usize]);
        Ok(LayeredPlanReport { coc_range, capped, used, clamped: clamped as u64 })
    }
}

/// What the device planned for a frame.
#[derive(Clone, Debug, PartialEq)]
pub struct LayeredPlanReport {
    /// Smallest and largest signed CoC present (px, capped at `max_coc`; 0 included).
    pub coc_range: (f32, f32),
    /// Fragments whose CoC exceeded `max_coc`.
    pub capped: u64,
    /// Per candidate layer, front to back: whether some fragment reached it.
    pub used: Vec<bool>,
    /// Input colours the numerical contract clamped (`dof_shaders::radiance`).
    pub clamped: u64,
}

impl LayeredPlanReport {
    pub fn used_layers(&self) -> usize {
        self.used.iter().filter(|u| **u).count()
    }
}

impl DofContext for LayeredContext {
    fn method(&self) -> &'static str {
        "layered"
    }
    fn extent(&self) -> Extent {
        self.desc.extent()
    }
    fn recording(&mut self, backend: &dyn Backend, frame: &Frame) -> Result<Recording> {
        LayeredContext::recording(self, backend, frame)
    }
    fn frames_in_flight(&self) -> u32 {
        self.in_flight.frames()
    }
    fn report_frame(&self, backend: &mut dyn Backend, frames_ago: u32) -> Result<ContextReport> {
        let p = self.plan_of(backend, frames_ago)?;
        let o = &self.desc.options;
        let mut summary = format!(
            "{} of {} candidate layers used for CoC {:.1} to {:.1} px, {}",
            p.used_layers(),
            self.cocs.len(),
            p.coc_range.0,
            p.coc_range.1,
            if o.cascaded { "cascaded blurs" } else { "one blur per layer" }
        );
        if p.capped > 0 {
            summary += &format!("; {} fragments beyond the {} px cap", p.capped, o.max_coc);
        }
        summary += &clamped_summary(p.clamped as u32);
        Ok(ContextReport {
            summary,
            details: Some(std::sync::Arc::new(LayeredReport { layers: self.cocs.len() as u32, plan: p })),
            ..Default::default()
        })
    }
    fn device_bytes(&self) -> u64 {
        LayeredContext::device_bytes(self)
    }
    fn resize(&mut self, backend: &mut dyn Backend, extent: Extent) -> Result<()> {
        self.owned.check(backend)?;
        let desc = self.desc.clone();
        remake(self, backend, &desc, extent, LayeredContext::new, LayeredContext::destroy)
    }
    fn destroy(self: Box<Self>, backend: &mut dyn Backend) {
        LayeredContext::destroy(*self, backend)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gaussian_weights_sum_to_one_with_variance_sigma_squared() {
        for s in [0.25f32, 0.5, 1.0, 7.3, 64.0] {
            let w = gaussian(s);
            let total = w[0] + 2.0 * w[1..].iter().sum::<f32>();
            assert!((total - 1.0).abs() < 1e-5, "{s}: {total}");
            assert_eq!(w.len(), (3.0 * s).ceil() as usize + 1);
            let variance: f64 = w.iter().enumerate().map(|(i, &v)| 2.0 * (i * i) as f64 * v as f64).sum();
            assert!((variance / (s as f64).powi(2) - 1.0).abs() < 1e-4, "{s}: variance {variance}");
            assert!(w.windows(2).all(|p| p[0] >= p[1]), "{s}: not decreasing");
        }
    }

    #[test]
    fn candidates_reach_the_cap_on_both_sides() {
        let (cocs, focus) = LayeredOptions::default().candidates();
        assert_eq!(cocs[focus], 0.0);
        assert_eq!((cocs[0], cocs[cocs.len() - 1]), (-256.0, 256.0));
        assert!(cocs.windows(2).all(|w| w[0] < w[1]));
        let most = LayeredOptions { layers_per_doubling: 4, first_coc: 1.0, max_coc: 1024.0, ..Default::default() };
        assert!(most.candidates().0.len() <= PLAN_LAYERS as usize);
    }

    #[test]
    fn keys_decode_to_their_floats() {
        use dof_shaders::keys::sort_key;
        for v in [0.0f32, 1.5, -2.25, 256.0, -1e-3] {
            assert_eq!(from_key(sort_key(v.to_bits())), v);
        }
    }
}

/// What a layered DoF frame did: the candidate layers and the frame's plan.
#[derive(Clone, Debug, PartialEq)]
pub struct LayeredReport {
    /// Candidate layers fixed at creation.
    pub layers: u32,
    pub plan: LayeredPlanReport,
}

super::context::report_details!(LayeredReport, |r| vec![
    ("layers", r.layers as f64),
    ("used_layers", r.plan.used_layers() as f64),
    ("coc_min", r.plan.coc_range.0 as f64),
    ("coc_max", r.plan.coc_range.1 as f64),
    ("capped", r.plan.capped as f64),
    ("clamped", r.plan.clamped as f64),
]);
