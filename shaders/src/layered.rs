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
//! Buffers of premultiplied RGBA hold 4 words a pixel. The blur is separable with weights from the
//! host (`radius + 1` words from `weights_at`: the centre, then each distance), zero outside the
//! image; the normalisation at the end divides by the composite alpha, which undoes the border's
//! loss and the gaps where the partial multi-layer image holds nothing behind a blurred edge.

use crate::exec::{Group, Mem};
use crate::lens::{is_finite, is_positive};
use crate::wg::for_each_item;

/// Words per fragment slot of the input: r, g, b, depth.
pub const SLOT_WORDS: u32 = 4;

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
    pub _pad: [u32; 2],
    /// Matting: `[a[k-2], a[k-1], a[k], a[k+1]]`.
    pub anchors: [f32; 4],
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

#[inline]
fn load4<M: Mem>(m: &M, i: u32) -> [f32; 4] {
    [f32::from_bits(m.load(4 * i)), f32::from_bits(m.load(4 * i + 1)), f32::from_bits(m.load(4 * i + 2)), f32::from_bits(m.load(4 * i + 3))]
}

#[inline]
fn store4<M: Mem>(m: &mut M, i: u32, v: [f32; 4]) {
    m.store(4 * i, v[0].to_bits());
    m.store(4 * i + 1, v[1].to_bits());
    m.store(4 * i + 2, v[2].to_bits());
    m.store(4 * i + 3, v[3].to_bits());
}

/// One layer's premultiplied RGBA from every pixel's fragments, front to back.
pub fn matte_pass<G: Group, M: Mem>(g: &mut G, p: &LayeredParams, input: M, counts: M, mut layer: M) {
    for_each_item(g, p.width * p.height, |pi| {
        let n = counts.load(pi).min(p.max_layers);
        let mut acc = [0.0f32; 4];
        if n == 0 {
            acc[3] = matte_hidden(&p.anchors, f32::INFINITY);
        }
        let mut first = true;
        let mut j = 0;
        while j < n {
            let at = (pi * p.max_layers + j) * SLOT_WORDS;
            let c = [f32::from_bits(input.load(at)), f32::from_bits(input.load(at + 1)), f32::from_bits(input.load(at + 2))];
            let z = f32::from_bits(input.load(at + 3));
            if is_finite(c[0]) && is_finite(c[1]) && is_finite(c[2]) && is_positive(z) {
                let w = if first { matte_front(&p.anchors, z) } else { matte_hidden(&p.anchors, z) };
                first = false;
                let t = 1.0 - acc[3];
                acc[0] += t * w * c[0];
                acc[1] += t * w * c[1];
                acc[2] += t * w * c[2];
                acc[3] += t * w;
            }
            j += 1;
        }
        store4(&mut layer, pi, acc);
    });
}

/// One direction of the separable Gaussian, `src` into `dst`, zero outside the image.
pub fn blur_pass<G: Group, M: Mem>(g: &mut G, p: &LayeredParams, src: M, weights: M, mut dst: M) {
    let r = p.radius as i32;
    for_each_item(g, p.width * p.height, |pi| {
        let (x, y) = ((pi % p.width) as i32, (pi / p.width) as i32);
        let (limit, at) = if p.mode == 0 { (p.width as i32, x) } else { (p.height as i32, y) };
        let mut acc = [0.0f32; 4];
        let mut i = -r;
        while i <= r {
            let q = at + i;
            if q >= 0 && q < limit {
                let w = f32::from_bits(weights.load(p.weights_at + i.unsigned_abs()));
                let qi = if p.mode == 0 { pi - x as u32 + q as u32 } else { q as u32 * p.width + x as u32 };
                let v = load4(&src, qi);
                acc[0] += w * v[0];
                acc[1] += w * v[1];
                acc[2] += w * v[2];
                acc[3] += w * v[3];
            }
            i += 1;
        }
        store4(&mut dst, pi, acc);
    });
}

/// `acc = layer over acc` ([`OVER`], the layer in front) or `acc = acc over layer` ([`UNDER`]).
pub fn composite_pass<G: Group, M: Mem>(g: &mut G, p: &LayeredParams, layer: M, mut acc: M) {
    for_each_item(g, p.width * p.height, |pi| {
        let l = load4(&layer, pi);
        let a = load4(&acc, pi);
        let (front, back) = if p.mode == OVER { (l, a) } else { (a, l) };
        let t = 1.0 - front[3];
        store4(&mut acc, pi, [front[0] + t * back[0], front[1] + t * back[1], front[2] + t * back[2], front[3] + t * back[3]]);
    });
}

/// Colour divided by the composite alpha (black where nothing covers the pixel).
pub fn resolve_pass<G: Group, M: Mem>(g: &mut G, p: &LayeredParams, acc: M, mut out: M) {
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
    LAYERED_MATTE = layered_matte [256] (LayeredParams) { input, counts, layer } => matte_pass
);
kernel!(
    /// One direction of a separable Gaussian over premultiplied RGBA.
    LAYERED_BLUR = layered_blur [256] (LayeredParams) { src, weights, dst } => blur_pass
);
kernel!(
    /// Premultiplied "over" of a layer and the running composite.
    LAYERED_COMPOSITE = layered_composite [256] (LayeredParams) { layer, acc } => composite_pass
);
kernel!(
    /// The composite normalised by its alpha, as RGB.
    LAYERED_RESOLVE = layered_resolve [256] (LayeredParams) { acc, out } => resolve_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 4] = [&LAYERED_MATTE, &LAYERED_BLUR, &LAYERED_COMPOSITE, &LAYERED_RESOLVE];

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
