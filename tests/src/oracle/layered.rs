//! Layered depth of field with matting (Schedl and Wimmer 2012; kernels and the matting rules in
//! `dof_shaders::layered`), planned per frame on the host: the suites' oracle for the frame API's
//! `dof::frame::LayeredContext`, which plans on the device over candidate layers fixed at
//! creation. It allocates, uploads and reads back per call:
//!
//! - **Layers from the depth range.** A min/max reduction over every fragment's signed CoC (the sky
//!   at the far limit) gives the blur present on each side of the focus plane. Layer CoCs grow
//!   geometrically from `first_coc` by `2^(1/layers_per_doubling)` until they reach it (the last
//!   one clamped to it, at most `max_coc`), so the count follows the scene, not a constant.
//! - **Anchors by the CoC inverse** (eq. 9): between layers `k` and `k+1` at their mean CoC, `D1`
//!   in front of the focus layer, `D2` behind it, `+inf` where eq. 8's bound is exceeded.
//! - **Empty layers are skipped**: a layer no fragment has a non-zero matte for is neither matted,
//!   blurred nor composited (and its blur is folded into the next one in the cascade).
//! - **Blur** `σ = |d| / 4` (eq. 10), separable, radius `ceil(3σ)`. Non-cascaded: every layer is
//!   blurred by its own `σ` and composited back to front. Cascaded (recursive): behind the focus
//!   the running composite is blurred by `sqrt(σ_k² − σ_{k−1}²)` after layer `k` joins it, from the
//!   back layer forwards; in front of it, mirrored from the nearest layer backwards; the two are
//!   joined at the end. Each layer so receives its own `σ` in total, at the price of blurring the
//!   occlusion edges of the layers it is composited with (the "slight alteration" the paper notes).
//! - **Normalisation**: the composite is divided by its alpha.

use dof::backend::{Backend, BufferId, CommandTime, RunKernel, with_buffers};
use dof::frame::layered::{gaussian, sigma};
use dof::layers::{LayeredImage, RgbImage};
use dof::methods::buffers::{groups_for, read_rgb, slot_words};
use dof_core::error::{Error, Result};
use dof_shaders::layered::{
    LAYERED_MATTE, LayeredParams, OVER, SLOT_WORDS, UNDER, layered_blur, layered_composite, layered_matte, layered_resolve, matte_front,
    matte_hidden,
};
use dof_shaders::lens::ThinLens;

/// Blurs narrower than this `σ` (px) are left out: their kernel is almost all centre.
const MIN_SIGMA: f32 = 0.25;

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
    /// Blur passes run (each separable pair counts once) and their widest radius (px).
    pub blurs: u32,
    pub widest_radius: u32,
    pub buffer_bytes: u64,
}

#[derive(Clone, Copy, PartialEq)]
enum Buf {
    Layer,
    Far,
    Near,
}

enum Op {
    Matte(usize),
    Blur(Buf, f32),
    Composite { layer: Buf, acc: Buf, mode: u32 },
}

/// The dispatch sequence: non-cascaded, or the two cascades joined.
fn schedule(plan: &LayerPlan, cascaded: bool) -> Vec<Op> {
    let mut ops = Vec::new();
    let s = |k: usize| sigma(plan.cocs[k]);
    if !cascaded {
        for k in (0..plan.cocs.len()).rev().filter(|&k| !plan.empty[k]) {
            ops.push(Op::Matte(k));
            ops.push(Op::Blur(Buf::Layer, s(k)));
            ops.push(Op::Composite { layer: Buf::Layer, acc: Buf::Far, mode: OVER });
        }
        return ops;
    }
    // Behind the focus, from the back: join, then blur by the step to the next layer forwards.
    let (mut pending, mut any) = (0.0f32, false);
    for k in (plan.focus_layer..plan.cocs.len()).rev() {
        if !plan.empty[k] {
            if any && pending > 0.0 {
                ops.push(Op::Blur(Buf::Far, pending.sqrt()));
                pending = 0.0;
            }
            ops.push(Op::Matte(k));
            ops.push(Op::Composite { layer: Buf::Layer, acc: Buf::Far, mode: OVER });
            any = true;
        }
        if k > plan.focus_layer {
            pending += s(k).powi(2) - s(k - 1).powi(2);
        }
    }
    // The steps down to the focus layer that no used layer in front took (an empty focus layer).
    if any && pending > 0.0 {
        ops.push(Op::Blur(Buf::Far, pending.sqrt()));
    }
    // In front, from the nearest: join behind, then blur by the step to the next layer backwards.
    let (mut pending, mut any_near) = (0.0f32, false);
    for k in 0..plan.focus_layer {
        if !plan.empty[k] {
            if any_near && pending > 0.0 {
                ops.push(Op::Blur(Buf::Near, pending.sqrt()));
                pending = 0.0;
            }
            ops.push(Op::Matte(k));
            ops.push(Op::Composite { layer: Buf::Layer, acc: Buf::Near, mode: UNDER });
            any_near = true;
        }
        let next = if k + 1 < plan.focus_layer { s(k + 1) } else { 0.0 };
        pending += s(k).powi(2) - next.powi(2);
    }
    if any_near {
        if pending > 0.0 {
            ops.push(Op::Blur(Buf::Near, pending.sqrt()));
        }
        ops.push(Op::Composite { layer: Buf::Near, acc: Buf::Far, mode: OVER });
    }
    ops
}

/// Renders `image` through `lens` by layered DoF on `backend`.
pub fn layered(backend: &mut dyn Backend, image: &LayeredImage, lens: &ThinLens, options: &LayeredOptions) -> Result<LayeredOutput> {
    let plan = plan(image, lens, options)?;
    let (width, height) = (image.width, image.height);
    let pixels = width as u64 * height as u64;
    let ops = schedule(&plan, options.cascaded);
    // Every blur's weights in one buffer.
    let mut weights: Vec<u32> = Vec::new();
    let mut blurs: Vec<(u32, u32)> = Vec::new();
    for op in &ops {
        if let Op::Blur(_, s) = op
            && *s >= MIN_SIGMA
        {
            let w = gaussian(*s);
            blurs.push((weights.len() as u32, (w.len() - 1) as u32));
            weights.extend(w.iter().map(|v| v.to_bits()));
        }
    }
    let slots = pixels * image.max_layers as u64;
    let sizes = [
        (SLOT_WORDS as u64 * slots, "layered/input"),
        (pixels, "layered/counts"),
        (4 * pixels, "layered/layer"),
        (4 * pixels, "layered/tmp"),
        (4 * pixels, "layered/far"),
        (4 * pixels, "layered/near"),
        (weights.len().max(1) as u64, "layered/weights"),
        (3 * pixels, "layered/out"),
    ];
    let max_words = backend.limits().max_buffer_bytes / 4;
    if let Some(&(words, what)) = sizes.iter().find(|s| s.0 > max_words) {
        return Err(Error::TooLarge { what: format!("{what} (words)"), size: words, limit: max_words });
    }
    let buffer_bytes = 4 * sizes.iter().map(|s| s.0).sum::<u64>();
    let input = slot_words(image);
    let widest_radius = blurs.iter().map(|b| b.1).max().unwrap_or(0);
    let blur_count = blurs.len() as u32;
    with_buffers(backend, &sizes, |backend, b| {
        let [input_buf, counts, layer, tmp, far, near, weights_buf, out] = [b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7]];
        backend.write_buffer(input_buf, 0, &input)?;
        backend.write_buffer(counts, 0, &image.counts)?;
        if !weights.is_empty() {
            backend.write_buffer(weights_buf, 0, &weights)?;
        }
        backend.fill(far, 0, 4 * pixels, 0, "layered/clear")?;
        backend.fill(near, 0, 4 * pixels, 0, "layered/clear")?;
        let base = LayeredParams { width, height, max_layers: image.max_layers, ..Default::default() };
        // Every layered kernel runs one item a pixel with the same workgroup size.
        let groups = groups_for(&LAYERED_MATTE, pixels);
        let id = |buf: Buf| -> BufferId {
            match buf {
                Buf::Layer => layer,
                Buf::Far => far,
                Buf::Near => near,
            }
        };
        let mut blur_params = blurs.iter();
        for op in &ops {
            match *op {
                Op::Matte(k) => {
                    let p = LayeredParams { anchors: plan.anchors_of(k), ..base };
                    backend.run(layered_matte::Bindings { input: input_buf, counts, layer }, groups, &p, "layered/matte")?;
                }
                Op::Blur(buf, s) if s >= MIN_SIGMA => {
                    let Some(&(weights_at, radius)) = blur_params.next() else { continue };
                    let h = LayeredParams { radius, weights_at, mode: 0, ..base };
                    let v = LayeredParams { mode: 1, ..h };
                    backend.run(layered_blur::Bindings { src: id(buf), weights: weights_buf, dst: tmp }, groups, &h, "layered/blur")?;
                    backend.run(layered_blur::Bindings { src: tmp, weights: weights_buf, dst: id(buf) }, groups, &v, "layered/blur")?;
                }
                Op::Blur(..) => {}
                Op::Composite { layer: l, acc, mode } => {
                    let p = LayeredParams { mode, ..base };
                    backend.run(layered_composite::Bindings { layer: id(l), acc: id(acc) }, groups, &p, "layered/composite")?;
                }
            }
        }
        backend.run(layered_resolve::Bindings { acc: far, out }, groups, &base, "layered/composite")?;
        let times = backend.submit()?;
        Ok(LayeredOutput {
            image: read_rgb(backend, out, width, height)?,
            times,
            plan: plan.clone(),
            blurs: blur_count,
            widest_radius,
            buffer_bytes,
        })
    })
}
