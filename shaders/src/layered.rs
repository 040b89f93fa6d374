//! Layered depth of field with matting (Schedl and Wimmer 2012): the multi-layer image is
//! decomposed into K depth layers by matting functions, each layer is blurred by a Gaussian of its
//! CoC (`d = 4σ`), and the layers are composited back to front and normalised.
//!
//! Layer `k` (0 nearest) is bounded by anchor depths `a[k-1]` (front) and `a[k]` (back), with
//! `a[-2] = a[-1] = 0` and `a[K-1] = a[K] = +inf`. The host places them (eq. 9) and passes the four a
//! layer needs as `anchors = [a[k-2], a[k-1], a[k], a[k+1]]`. Eq. 3-4:
//! - `ω̇_k(z)` rises linearly over `(a[k-2], a[k-1])`, is 1 on `[a[k-1], a[k]]`, 0 elsewhere (a hard
//!   cut at the back, so hidden fragments are never blended over nearer layers);
//! - `ω_k(z)` is `ω̇_k` except that it falls linearly over `(a[k], a[k+1])` (none where `a[k+1]` is
//!   infinite).
//!
//! The front image takes `ω`, the hidden ones `ω̇` (eq. 2), composited front to back with "over"
//! into premultiplied RGBA. Fragments are opaque (the input carries colour and depth, as for the
//! other methods); a pixel without fragments is the sky, an opaque black fragment at `+inf`.
//! Non-finite colours and non-positive or NaN depths are skipped.
//!
//! The frame context (`dof::frame::LayeredContext`) fixes the candidate layers at creation and plans
//! each frame on the device instead: [`LAYERED_PLAN_BEGIN`] places the anchors from the lens,
//! [`LAYERED_PLAN_REACH`] reduces the signed-CoC range and marks the layers some fragment reaches,
//! [`LAYERED_PLAN_END`] derives the gates of the cascade's blurs; the gated kernels
//! ([`LAYERED_MATTE_AT`], [`LAYERED_BLUR_GATED`], [`LAYERED_COMPOSITE_GATED`]) return at once
//! where the plan word named by their `gate` is 0. The plan buffer's layout is [`PLAN_WORDS`].
//!
//! Buffers of premultiplied RGBA hold 4 words a pixel. The blur is separable with weights from the
//! host (`radius + 1` words from `weights_at`: the centre, then each distance), zero outside the
//! image; the normalisation at the end divides by the composite alpha, which undoes the border's
//! loss and the gaps where the partial multi-layer image holds nothing behind a blurred edge.

use crate::exec::{Group, Load, Mem};
use crate::keys::sort_key;
use crate::lens::{ThinLens, is_finite, is_pos_inf};
use crate::slot::{self, Slot};
use crate::wg::for_each_item;

/// Words per fragment slot of the input ([`crate::slot`]).
pub use crate::slot::SLOT_WORDS;

/// `mode` of the composition pass.
pub const OVER: u32 = 0;
pub const UNDER: u32 = 1;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct LayeredParams {
    pub width: u32,
    pub height: u32,
    /// Fragment slots per pixel of the input.
    pub max_layers: u32,
    /// Blur: taps each side of the centre; 0 copies.
    pub radius: u32,
    /// Blur: first weight in the weights buffer.
    pub weights_at: u32,
    /// Blur: 0 horizontal, 1 vertical. Composition: [`OVER`] or [`UNDER`].
    pub mode: u32,
    /// The gated kernels: the layer matted ([`LAYERED_MATTE_AT`]).
    pub layer: u32,
    /// The gated kernels: the plan word that must not be 0 for the kernel to run ([`ALWAYS`]: run).
    pub gate: u32,
    /// Matting ([`LAYERED_MATTE`]): `[a[k-2], a[k-1], a[k], a[k+1]]`.
    pub anchors: [f32; 4],
    /// The gated kernels: the layer count of the plan.
    pub layers: u32,
    pub _pad: [u32; 3],
}

/// Most candidate layers a device plan holds.
pub const PLAN_LAYERS: u32 = 128;
/// The plan buffer: each layer's signed CoC diameter (px, f32 bits; written at creation).
pub const PLAN_COCS: u32 = 0;
/// `layers - 1` anchors, depth (f32 bits): `a[k]` separates layer `k` from `k + 1`.
pub const PLAN_ANCHORS: u32 = PLAN_LAYERS;
/// Per layer: 1 where some fragment has a non-zero matte in it (and it is in range).
pub const PLAN_USED: u32 = 2 * PLAN_LAYERS;
/// Per layer `k` behind the focus: 1 where a layer behind `k` is used (the far blur before `k` runs).
pub const PLAN_FAR_GATE: u32 = 3 * PLAN_LAYERS;
/// Per layer `k <= focus`: 1 where a layer in front of `k` is used (the near blur before `k` runs).
pub const PLAN_NEAR_GATE: u32 = 4 * PLAN_LAYERS;
/// Three words: the sort key of the largest `-c`, of the largest `c` (signed CoC, capped, 0
/// included), and the fragments beyond the cap.
pub const PLAN_STATS: u32 = 5 * PLAN_LAYERS;
pub const PLAN_WORDS: u32 = PLAN_STATS + 3;
/// A `gate` that always runs.
pub const ALWAYS: u32 = u32::MAX;

/// The device plan's parameters.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct LayeredPlanParams {
    pub width: u32,
    pub height: u32,
    pub max_layers: u32,
    /// Candidate layers (`<= PLAN_LAYERS`), front to back.
    pub layers: u32,
    /// The focus layer (CoC 0).
    pub focus: u32,
    /// Signed CoCs beyond this (px) are capped to it and counted.
    pub max_coc: f32,
    pub _pad: [u32; 2],
    pub lens: ThinLens,
}

/// `ω̇_k(z)`: the matte of hidden fragments.
#[inline]
pub fn matte_hidden(a: &[f32; 4], z: f32) -> f32 {
    if z >= a[1] && z <= a[2] {
        1.0
    } else if z > a[0] && z < a[1] {
        (z - a[0]) / (a[1] - a[0])
    } else {
        0.0
    }
}

/// `ω_k(z)`: the matte of the front fragment.
#[inline]
pub fn matte_front(a: &[f32; 4], z: f32) -> f32 {
    if z > a[2] && z < a[3] && is_finite(a[3]) { (a[3] - z) / (a[3] - a[2]) } else { matte_hidden(a, z) }
}

/// The matte of a translucent fragment: 1 in the layer whose depth range `(a[1], a[2]]` holds it,
/// 0 elsewhere. The ramps of [`matte_front`] and [`matte_hidden`] overlap the neighbouring layers'
/// (a fragment appears in two layers, the nearer hiding the other where it is opaque); a
/// translucent fragment there would be counted twice, so it takes one layer, whole.
#[inline]
pub fn matte_translucent(a: &[f32; 4], z: f32) -> f32 {
    if z > a[1] && z <= a[2] { 1.0 } else { 0.0 }
}

#[inline]
fn load4(m: &impl Load, i: u32) -> [f32; 4] {
    [f32::from_bits(m.load(4 * i)), f32::from_bits(m.load(4 * i + 1)), f32::from_bits(m.load(4 * i + 2)), f32::from_bits(m.load(4 * i + 3))]
}

#[inline]
fn store4<M: Mem>(m: &mut M, i: u32, v: [f32; 4]) {
    m.store(4 * i, v[0].to_bits());
    m.store(4 * i + 1, v[1].to_bits());
    m.store(4 * i + 2, v[2].to_bits());
    m.store(4 * i + 3, v[3].to_bits());
}

/// One pixel's premultiplied RGBA in the layer of `anchors`, from its fragments front to back.
#[inline]
fn matte_pixel(p: &LayeredParams, anchors: &[f32; 4], input: &impl Load, counts: &impl Load, pi: u32) -> [f32; 4] {
    let n = counts.load(pi).min(p.max_layers);
    let mut acc = [0.0f32; 4];
    if n == 0 {
        acc[3] = matte_hidden(anchors, f32::INFINITY);
    }
    let slot_at = |j: u32| slot::load(input, pi * p.max_layers + j);
    // Slots that end translucent have black behind them: one more, opaque, at infinite depth.
    let backed = slot::ends_translucent(n, slot_at);
    let end = if backed { n + 1 } else { n };
    let mut first = true;
    let mut j = 0;
    while j < end {
        let s = if j < n { slot_at(j) } else { Slot::opaque([0.0; 3], f32::INFINITY) };
        if slot::is_valid(&s) {
            let (c, z, a) = (crate::radiance::clamp_color(s.color), s.depth, slot::clamp_alpha(s.alpha));
            let w = if a < 1.0 {
                matte_translucent(anchors, z)
            } else if first {
                matte_front(anchors, z)
            } else {
                matte_hidden(anchors, z)
            };
            first = false;
            // Coverage never exceeds 1; rounding must not make the remainder negative, which would
            // subtract a bright colour (the numerical contract: non-negative output). The colour is
            // premultiplied: the fragment's alpha scales only the coverage it takes.
            let t = (1.0 - acc[3]).max(0.0);
            acc[0] += t * w * c[0];
            acc[1] += t * w * c[1];
            acc[2] += t * w * c[2];
            acc[3] += t * w * a;
        }
        j += 1;
    }
    acc
}

/// One layer's premultiplied RGBA from every pixel's fragments, front to back.
pub fn matte_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &LayeredParams, input: R, counts: R, mut layer: M) {
    for_each_item(g, p.width * p.height, |pi| {
        let acc = matte_pixel(p, &p.anchors, &input, &counts, pi);
        store4(&mut layer, pi, acc);
    });
}

/// Anchor `i` of a device plan: 0 before the first, `+inf` after the last.
#[inline]
fn plan_anchor(plan: &impl Load, layers: u32, i: i32) -> f32 {
    if i < 0 {
        0.0
    } else if i as u32 + 1 >= layers {
        f32::INFINITY
    } else {
        f32::from_bits(plan.load(PLAN_ANCHORS + i as u32))
    }
}

/// `[a[k-2], a[k-1], a[k], a[k+1]]` of layer `k` of a device plan.
#[inline]
fn plan_anchors_of(plan: &impl Load, layers: u32, k: u32) -> [f32; 4] {
    let k = k as i32;
    [plan_anchor(plan, layers, k - 2), plan_anchor(plan, layers, k - 1), plan_anchor(plan, layers, k), plan_anchor(plan, layers, k + 1)]
}

/// Whether a gated kernel runs: its gate is [`ALWAYS`] or names a plan word that is not 0.
#[inline]
fn open(plan: &impl Load, gate: u32) -> bool {
    gate == ALWAYS || plan.load(gate) != 0
}

/// [`matte_pass`] of layer `p.layer` with the anchors of the device plan, where the gate is open.
pub fn matte_at_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &LayeredParams, input: R, counts: R, plan: R, mut layer: M) {
    if !open(&plan, p.gate) {
        return;
    }
    let anchors = plan_anchors_of(&plan, p.layers, p.layer);
    for_each_item(g, p.width * p.height, |pi| {
        let acc = matte_pixel(p, &anchors, &input, &counts, pi);
        store4(&mut layer, pi, acc);
    });
}

/// One pixel of one direction of the separable Gaussian over `src`, zero outside the image.
#[inline]
fn blur_pixel(p: &LayeredParams, src: &impl Load, weights: &impl Load, pi: u32) -> [f32; 4] {
    let r = p.radius as i32;
    let (x, y) = ((pi % p.width) as i32, (pi / p.width) as i32);
    let (limit, at) = if p.mode == 0 { (p.width as i32, x) } else { (p.height as i32, y) };
    let mut acc = [0.0f32; 4];
    let mut i = -r;
    while i <= r {
        let q = at + i;
        if q >= 0 && q < limit {
            let w = f32::from_bits(weights.load(p.weights_at + i.unsigned_abs()));
            let qi = if p.mode == 0 { pi - x as u32 + q as u32 } else { q as u32 * p.width + x as u32 };
            let v = load4(src, qi);
            acc[0] += w * v[0];
            acc[1] += w * v[1];
            acc[2] += w * v[2];
            acc[3] += w * v[3];
        }
        i += 1;
    }
    acc
}

/// One direction of the separable Gaussian, `src` into `dst`, zero outside the image.
pub fn blur_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &LayeredParams, src: R, weights: R, mut dst: M) {
    for_each_item(g, p.width * p.height, |pi| {
        let acc = blur_pixel(p, &src, &weights, pi);
        store4(&mut dst, pi, acc);
    });
}

/// [`blur_pass`] where the gate is open.
pub fn blur_gated_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &LayeredParams, src: R, weights: R, mut dst: M, plan: R) {
    if !open(&plan, p.gate) {
        return;
    }
    for_each_item(g, p.width * p.height, |pi| {
        let acc = blur_pixel(p, &src, &weights, pi);
        store4(&mut dst, pi, acc);
    });
}

/// One pixel of `layer over acc` ([`OVER`]) or `acc over layer` ([`UNDER`]).
#[inline]
fn composite_pixel<M: Mem>(p: &LayeredParams, layer: &impl Load, acc: &mut M, pi: u32) {
    let l = load4(layer, pi);
    let a = load4(acc, pi);
    let (front, back) = if p.mode == OVER { (l, a) } else { (a, l) };
    // A blurred coverage may round above 1: what shows through is never negative.
    let t = (1.0 - front[3]).max(0.0);
    store4(acc, pi, [front[0] + t * back[0], front[1] + t * back[1], front[2] + t * back[2], front[3] + t * back[3]]);
}

/// `acc = layer over acc` ([`OVER`], the layer in front) or `acc = acc over layer` ([`UNDER`]).
pub fn composite_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &LayeredParams, layer: R, mut acc: M) {
    for_each_item(g, p.width * p.height, |pi| composite_pixel(p, &layer, &mut acc, pi));
}

/// [`composite_pass`] where the gate is open.
pub fn composite_gated_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &LayeredParams, layer: R, mut acc: M, plan: R) {
    if !open(&plan, p.gate) {
        return;
    }
    for_each_item(g, p.width * p.height, |pi| composite_pixel(p, &layer, &mut acc, pi));
}

/// The device plan, first pass (one workgroup): the anchors from the candidate layers' CoCs and the
/// lens (eq. 9: between layers `k` and `k + 1` at their mean CoC, `D1` in front of the focus layer,
/// `D2` behind it), the used flags and gates cleared, the range started at 0.
pub fn plan_begin_pass<G: Group, M: Mem>(g: &mut G, p: &LayeredPlanParams, mut plan: M) {
    let (layers, size) = (p.layers, g.size());
    g.each(|lid| {
        let mut i = lid;
        while i < PLAN_LAYERS {
            if i + 1 < layers {
                let mean = 0.5 * (f32::from_bits(plan.load(PLAN_COCS + i)) + f32::from_bits(plan.load(PLAN_COCS + i + 1)));
                let (d1, d2) = p.lens.inverse_px(if mean < 0.0 { -mean } else { mean });
                let anchor = if mean < 0.0 { d1 } else { d2 };
                plan.store(PLAN_ANCHORS + i, anchor.to_bits());
            }
            plan.store(PLAN_USED + i, 0);
            plan.store(PLAN_FAR_GATE + i, 0);
            plan.store(PLAN_NEAR_GATE + i, 0);
            i += size;
        }
        if lid == 0 {
            plan.store(PLAN_STATS, sort_key(0));
            plan.store(PLAN_STATS + 1, sort_key(0));
            plan.store(PLAN_STATS + 2, 0);
        }
    });
}

/// Whether layer `k` of the plan is in range: the first, or its front anchor is finite (layers
/// behind an infinite anchor, past eq. 8's bound, hold nothing).
#[inline]
fn in_range(plan: &impl Load, layers: u32, k: u32) -> bool {
    k == 0 || !is_pos_inf(plan_anchor(plan, layers, k as i32 - 1))
}

/// Marks the layers a fragment at `z` reaches: its own and the neighbours its matte ramps into
/// (the front fragment by `ω`, hidden ones and the sky by `ω̇`, as the matting kernel does).
#[inline]
fn reach<M: Mem>(plan: &mut M, layers: u32, z: f32, front: bool) {
    // The first anchor not in front of `z` (anchors grow front to back).
    let (mut lo, mut hi) = (0u32, layers - 1);
    while lo < hi {
        let mid = (lo + hi) / 2;
        if f32::from_bits(plan.load(PLAN_ANCHORS + mid)) < z {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    let k = lo;
    let mut j = if k > 0 { k - 1 } else { 0 };
    let last = if k + 1 < layers { k + 1 } else { layers - 1 };
    while j <= last {
        if in_range(plan, layers, j) {
            let a = plan_anchors_of(plan, layers, j);
            let w = if front { matte_front(&a, z) } else { matte_hidden(&a, z) };
            if w > 0.0 && plan.load(PLAN_USED + j) == 0 {
                plan.store(PLAN_USED + j, 1);
            }
        }
        j += 1;
    }
}

/// The device plan, second pass (one item a pixel): the signed-CoC range of the fragments (the sky
/// at the far limit, capped at `max_coc` and counted beyond it) and the layers they reach.
pub fn plan_reach_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &LayeredPlanParams, input: R, counts: R, mut plan: M) {
    let layers = p.layers;
    for_each_item(g, p.width * p.height, |pi| {
        let n = counts.load(pi).min(p.max_layers);
        let (mut lo, mut hi, mut capped) = (0.0f32, 0.0f32, 0u32);
        if n == 0 {
            let c = p.lens.far_limit_px();
            if c > p.max_coc {
                capped += 1;
            }
            hi = if c > p.max_coc { p.max_coc } else { c };
            reach(&mut plan, layers, f32::INFINITY, false);
        }
        // Black behind slots that end translucent, as the matting adds it.
        let slot_at = |j: u32| slot::load(&input, pi * p.max_layers + j);
        if slot::ends_translucent(n, slot_at) {
            let c = p.lens.far_limit_px();
            if c > p.max_coc {
                capped += 1;
            }
            hi = if c > p.max_coc { p.max_coc } else { c };
            reach(&mut plan, layers, f32::INFINITY, false);
        }
        let mut first = true;
        let mut j = 0;
        while j < n {
            let s = slot_at(j);
            let z = s.depth;
            if slot::is_valid(&s) {
                let c = p.lens.signed_coc_px(z);
                if is_finite(c) {
                    if c > p.max_coc || c < -p.max_coc {
                        capped += 1;
                    }
                    let c = if c > p.max_coc {
                        p.max_coc
                    } else if c < -p.max_coc {
                        -p.max_coc
                    } else {
                        c
                    };
                    lo = if c < lo { c } else { lo };
                    hi = if c > hi { c } else { hi };
                }
                reach(&mut plan, layers, z, first);
                first = false;
            }
            j += 1;
        }
        // Only where the pixel widens the range so far: most pixels write nothing.
        let (klo, khi) = (sort_key((-lo).to_bits()), sort_key(hi.to_bits()));
        if klo > plan.load(PLAN_STATS) {
            plan.atomic_max(PLAN_STATS, klo);
        }
        if khi > plan.load(PLAN_STATS + 1) {
            plan.atomic_max(PLAN_STATS + 1, khi);
        }
        if capped > 0 {
            plan.atomic_add(PLAN_STATS + 2, capped);
        }
    });
}

/// The device plan, last pass (one invocation): the gates of the cascade's blurs. Behind the focus,
/// the blur before layer `k` runs where a layer behind `k` is used; in front, the blur before layer
/// `k` (and the near field's last blur, at `k = focus`) where a layer in front of `k` is used.
pub fn plan_end_pass<G: Group, M: Mem>(g: &mut G, p: &LayeredPlanParams, mut plan: M) {
    let (layers, focus) = (p.layers, p.focus);
    g.each(|lid| {
        if lid != 0 {
            return;
        }
        let mut any = 0u32;
        let mut k = layers;
        while k > focus {
            k -= 1;
            plan.store(PLAN_FAR_GATE + k, any);
            any |= plan.load(PLAN_USED + k);
        }
        let mut any = 0u32;
        let mut k = 0;
        while k <= focus {
            plan.store(PLAN_NEAR_GATE + k, any);
            any |= plan.load(PLAN_USED + k);
            k += 1;
        }
    });
}

/// Colour divided by the composite alpha (black where nothing covers the pixel).
pub fn resolve_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &LayeredParams, acc: R, mut out: M) {
    for_each_item(g, p.width * p.height, |pi| {
        let a = load4(&acc, pi);
        let inv = if a[3] > 1e-6 { 1.0 / a[3] } else { 0.0 };
        out.store(3 * pi, (a[0] * inv).to_bits());
        out.store(3 * pi + 1, (a[1] * inv).to_bits());
        out.store(3 * pi + 2, (a[2] * inv).to_bits());
    });
}

kernel!(
    /// One depth layer by the matting functions, premultiplied RGBA.
    LAYERED_MATTE = layered_matte [256] (LayeredParams) { read input, read counts, layer } => matte_pass
);
kernel!(
    /// One direction of a separable Gaussian over premultiplied RGBA.
    LAYERED_BLUR = layered_blur [256] (LayeredParams) { read src, read weights, dst } => blur_pass
);
kernel!(
    /// Premultiplied "over" of a layer and the running composite.
    LAYERED_COMPOSITE = layered_composite [256] (LayeredParams) { read layer, acc } => composite_pass
);
kernel!(
    /// The composite normalised by its alpha, as RGB.
    LAYERED_RESOLVE = layered_resolve [256] (LayeredParams) { read acc, out } => resolve_pass
);

kernel!(
    /// The device plan's anchors from the lens; the used flags and gates cleared.
    LAYERED_PLAN_BEGIN = layered_plan_begin [64] (LayeredPlanParams) { plan } => plan_begin_pass
);
kernel!(
    /// The device plan's signed-CoC range and the layers the fragments reach.
    LAYERED_PLAN_REACH = layered_plan_reach [256] (LayeredPlanParams) { read input, read counts, plan } => plan_reach_pass
);
kernel!(
    /// The device plan's gates of the cascade's blurs.
    LAYERED_PLAN_END = layered_plan_end [64] (LayeredPlanParams) { plan } => plan_end_pass
);
kernel!(
    /// One depth layer of the device plan by the matting functions, where its gate is open.
    LAYERED_MATTE_AT = layered_matte_at [256] (LayeredParams) { read input, read counts, read plan, layer } => matte_at_pass
);
kernel!(
    /// One direction of a separable Gaussian, where its gate is open.
    LAYERED_BLUR_GATED = layered_blur_gated [256] (LayeredParams) { read src, read weights, dst, read plan } => blur_gated_pass
);
kernel!(
    /// Premultiplied "over" of a layer and the running composite, where its gate is open.
    LAYERED_COMPOSITE_GATED = layered_composite_gated [256] (LayeredParams) { read layer, acc, read plan } => composite_gated_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 10] = [
    &LAYERED_MATTE,
    &LAYERED_BLUR,
    &LAYERED_COMPOSITE,
    &LAYERED_RESOLVE,
    &LAYERED_PLAN_BEGIN,
    &LAYERED_PLAN_REACH,
    &LAYERED_PLAN_END,
    &LAYERED_MATTE_AT,
    &LAYERED_BLUR_GATED,
    &LAYERED_COMPOSITE_GATED,
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mattes_follow_eq_3_and_4() {
        let a = [1.0, 2.0, 4.0, 8.0];
        assert_eq!(matte_hidden(&a, 0.5), 0.0);
        assert_eq!(matte_hidden(&a, 1.5), 0.5);
        assert_eq!(matte_hidden(&a, 3.0), 1.0);
        assert_eq!(matte_hidden(&a, 5.0), 0.0, "a hard cut at the back");
        assert_eq!(matte_front(&a, 6.0), 0.5, "the front image fades out over (a[k], a[k+1])");
        let last = [1.0, 2.0, f32::INFINITY, f32::INFINITY];
        assert_eq!(matte_front(&last, f32::INFINITY), 1.0, "the sky belongs to the back layer");
        let before_last = [1.0, 2.0, 4.0, f32::INFINITY];
        assert_eq!(matte_front(&before_last, 100.0), 0.0, "no ramp towards an infinite anchor");
        let first = [0.0, 0.0, 4.0, 8.0];
        assert_eq!(matte_hidden(&first, 1e-3), 1.0);
    }
}
