//! Layered depth of field with matting (Schedl and Wimmer 2012; kernels and the matting rules in
//! `dof_shaders::layered`) with its layers planned per frame on the host: the suites' oracle for
//! the frame API's `dof::frame::LayeredContext`, which plans on the device over candidate layers
//! fixed at creation. Both run one schedule (`dof::frame::layered::Schedule`); what differs is the
//! plan. It allocates, uploads and reads back per call:
//!
//! - **Layers from the depth range.** A min/max reduction over every fragment's signed CoC (the sky
//!   at the far limit) gives the blur present on each side of the focus plane. Layer CoCs grow
//!   geometrically from `first_coc` by `2^(1/layers_per_doubling)` until they reach it (the last
//!   one clamped to it, at most `max_coc`), so the count follows the scene, not a constant.
//! - **Anchors by the CoC inverse** (eq. 9): between layers `k` and `k+1` at their mean CoC, `D1`
//!   in front of the focus layer, `D2` behind it, `+inf` where eq. 8's bound is exceeded.
//! - **Used layers**: those some fragment has a non-zero matte for. The schedule's steps of the
//!   others do not run: their gates, from these flags, are closed.

use dof::backend::{Backend, CommandTime, RunKernel, with_buffers};
use dof::frame::layered::{Schedule, ScheduleBuffers, Step};
use dof::layers::{LayeredImage, RgbImage};
use dof::methods::buffers::{read_rgb, slot_words};
use dof_core::error::{Error, Result};
use dof_shaders::layered::{
    ALWAYS, LayeredParams, LayeredPlanParams, PLAN_ANCHORS, PLAN_COCS, PLAN_LAYERS, PLAN_USED, PLAN_WORDS, SLOT_WORDS, layered_plan_end,
    matte_front, matte_hidden,
};
use dof_shaders::lens::ThinLens;

pub use dof::frame::layered::LayeredOptions;

/// The per-frame decomposition.
#[derive(Clone, Debug)]
pub struct LayerPlan {
    /// Signed CoC diameter (px) of each layer, front to back; the focus layer's is 0.
    pub cocs: Vec<f32>,
    /// `anchors[k]` separates layer `k` from `k + 1` (depth; `+inf` past eq. 8's bound).
    pub anchors: Vec<f32>,
    pub focus_layer: usize,
    /// Whether a layer holds no fragment with a non-zero matte.
    pub empty: Vec<bool>,
    /// Smallest and largest signed CoC present (px).
    pub coc_range: (f32, f32),
    /// Fragments whose CoC exceeded `max_coc`.
    pub capped: u64,
}

impl LayerPlan {
    /// `[a[k-2], a[k-1], a[k], a[k+1]]` of layer `k`.
    pub fn anchors_of(&self, k: usize) -> [f32; 4] {
        let a = |i: isize| -> f32 { if i < 0 { 0.0 } else { self.anchors.get(i as usize).copied().unwrap_or(f32::INFINITY) } };
        let k = k as isize;
        [a(k - 2), a(k - 1), a(k), a(k + 1)]
    }

    pub fn used_layers(&self) -> usize {
        self.empty.iter().filter(|e| !**e).count()
    }
}

/// Plans the layers of `image` under `lens`.
pub fn plan(image: &LayeredImage, lens: &ThinLens, options: &LayeredOptions) -> Result<LayerPlan> {
    dof::lens::check(lens)?;
    options.check()?;
    if image.width == 0 || image.height == 0 || image.max_layers == 0 {
        return Err(Error::InvalidArgument(format!("layered DoF needs a non-empty image, got {}x{}", image.width, image.height)));
    }
    // The min/max reduction over the signed CoC (the sky, a pixel without fragments, at the far limit).
    let (mut lo, mut hi, mut capped) = (0.0f32, 0.0f32, 0u64);
    let mut note = |c: f32| {
        if c.abs() > options.max_coc {
            capped += 1;
        }
        let c = c.clamp(-options.max_coc, options.max_coc);
        lo = lo.min(c);
        hi = hi.max(c);
    };
    for p in 0..image.counts.len() {
        let n = image.counts[p].min(image.max_layers) as usize;
        if n == 0 || image.ends_translucent(p) {
            note(lens.far_limit_px());
        }
        for f in &image.fragments[p * image.max_layers as usize..][..n] {
            let c = lens.signed_coc_px(f.depth);
            if c.is_finite() && f.color.iter().all(|v| v.is_finite()) {
                note(c);
            }
        }
    }
    let side = |extent: f32| options.side(extent);
    let near = side(-lo);
    let far = side(hi);
    let cocs: Vec<f32> = near.iter().rev().map(|c| -c).chain(std::iter::once(0.0)).chain(far.iter().copied()).collect();
    let anchors: Vec<f32> = cocs
        .windows(2)
        .map(|w| {
            let mean = 0.5 * (w[0] + w[1]);
            let (d1, d2) = lens.inverse_px(mean.abs());
            if mean < 0.0 { d1 } else { d2 }
        })
        .collect();
    let mut plan = LayerPlan { empty: vec![true; cocs.len()], focus_layer: near.len(), cocs, anchors, coc_range: (lo, hi), capped };
    // Which layers some fragment reaches: its own and the neighbours its mattes ramp into (the
    // front fragment by `ω`, hidden ones and the sky by `ω̇`, as the matting kernel does).
    let last = plan.cocs.len() - 1;
    let mut empty = vec![true; plan.cocs.len()];
    let mut reach = |z: f32, front: bool| {
        let k = plan.anchors.partition_point(|&a| a < z).min(last);
        for j in k.saturating_sub(1)..=(k + 1).min(last) {
            let a = plan.anchors_of(j);
            if (if front { matte_front(&a, z) } else { matte_hidden(&a, z) }) > 0.0 {
                empty[j] = false;
            }
        }
    };
    for p in 0..image.counts.len() {
        let n = image.counts[p].min(image.max_layers) as usize;
        if n == 0 || image.ends_translucent(p) {
            reach(f32::INFINITY, false);
        }
        let usable =
            image.fragments[p * image.max_layers as usize..][..n].iter().filter(|f| f.depth > 0.0 && f.color.iter().all(|v| v.is_finite()));
        for (i, f) in usable.enumerate() {
            reach(f.depth, i == 0);
        }
    }
    plan.empty = empty;
    Ok(plan)
}

/// The blurred image, the plan and what the frame did.
pub struct LayeredOutput {
    pub image: RgbImage,
    pub times: Vec<CommandTime>,
    pub plan: LayerPlan,
    /// Layers matted, and blur passes run (each separable pair counts once) with their widest
    /// radius (px): the schedule's steps whose gates the plan opened.
    pub mattes: u32,
    pub blurs: u32,
    pub widest_radius: u32,
    pub buffer_bytes: u64,
}

/// Renders `image` through `lens` by layered DoF on `backend`: the layers planned here, on the
/// host, then the schedule the context runs (`dof::frame::layered::Schedule`) over them, its
/// cascade's gates derived from the used flags by the device plan's own last pass.
pub fn layered(backend: &mut dyn Backend, image: &LayeredImage, lens: &ThinLens, options: &LayeredOptions) -> Result<LayeredOutput> {
    let plan = plan(image, lens, options)?;
    let layers = plan.cocs.len() as u32;
    if layers > PLAN_LAYERS {
        return Err(Error::InvalidArgument(format!("{layers} layers, a plan holds {PLAN_LAYERS}")));
    }
    let (width, height) = (image.width, image.height);
    let pixels = width as u64 * height as u64;
    let schedule = Schedule::new(&plan.cocs, plan.focus_layer, options.cascaded);
    // The host plan in the device plan's layout: the layers' CoCs, anchors and used flags.
    let mut plan_words = vec![0u32; PLAN_WORDS as usize];
    let at = |base: u32, k: usize| (base as usize) + k;
    plan.cocs.iter().enumerate().for_each(|(k, c)| plan_words[at(PLAN_COCS, k)] = c.to_bits());
    plan.anchors.iter().enumerate().for_each(|(k, a)| plan_words[at(PLAN_ANCHORS, k)] = a.to_bits());
    plan.empty.iter().enumerate().for_each(|(k, &e)| plan_words[at(PLAN_USED, k)] = !e as u32);
    let slots = pixels * image.max_layers as u64;
    let sizes = [
        (SLOT_WORDS as u64 * slots, "layered/input"),
        (pixels, "layered/counts"),
        (PLAN_WORDS as u64, "layered/plan"),
        (schedule.weights.len().max(1) as u64, "layered/weights"),
        (4 * pixels, "layered/layer"),
        (4 * pixels, "layered/tmp"),
        (4 * pixels, "layered/far"),
        (4 * pixels, "layered/near"),
        (3 * pixels, "layered/out"),
    ];
    let max_words = backend.limits().max_buffer_bytes / 4;
    if let Some(&(words, what)) = sizes.iter().find(|s| s.0 > max_words) {
        return Err(Error::TooLarge { what: format!("{what} (words)"), size: words, limit: max_words });
    }
    let buffer_bytes = 4 * sizes.iter().map(|s| s.0).sum::<u64>();
    let input = slot_words(image);
    with_buffers(backend, &sizes, |backend, b| {
        let [input_buf, counts, plan_buf, weights, layer, tmp, far, near, out] = [b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7], b[8]];
        backend.write_buffer(input_buf, 0, &input)?;
        backend.write_buffer(counts, 0, &image.counts)?;
        backend.write_buffer(plan_buf, 0, &plan_words)?;
        if !schedule.weights.is_empty() {
            backend.write_buffer(weights, 0, &schedule.weights)?;
        }
        backend.fill(far, 0, 4 * pixels, 0, "layered/clear")?;
        backend.fill(near, 0, 4 * pixels, 0, "layered/clear")?;
        let gates =
            LayeredPlanParams { width, height, max_layers: image.max_layers, layers, focus: plan.focus_layer as u32, ..Default::default() };
        backend.run(layered_plan_end::Bindings { plan: plan_buf }, [1, 1, 1], &gates, "layered/plan")?;
        let base = LayeredParams { width, height, max_layers: image.max_layers, layers, ..Default::default() };
        let buffers = ScheduleBuffers { input: input_buf, counts, plan: plan_buf, weights, layer, tmp, far, near, out };
        schedule.record(backend, &base, &buffers)?;
        let times = backend.submit()?;
        // What ran: the steps whose gates the plan opened.
        let words = backend.read_buffer(plan_buf, 0, PLAN_WORDS as u64)?;
        let open = |gate: u32| gate == ALWAYS || words[gate as usize] != 0;
        let (mut mattes, mut blurs, mut widest_radius) = (0, 0, 0);
        for step in &schedule.steps {
            match *step {
                Step::Matte(k) if open(PLAN_USED + k) => mattes += 1,
                Step::Blur { radius, gate, .. } if open(gate) => {
                    blurs += 1;
                    widest_radius = widest_radius.max(radius);
                }
                _ => {}
            }
        }
        Ok(LayeredOutput {
            image: read_rgb(backend, out, width, height)?,
            times,
            plan: plan.clone(),
            mattes,
            blurs,
            widest_radius,
            buffer_bytes,
        })
    })
}
