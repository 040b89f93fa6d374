//! Depth peeling with a renderer's own passes (Franke et al. 2018, §4.1-4.3): the renderer draws
//! each pass with its own pipelines into its own colour and depth attachments, and its fragment
//! shader discards what [`keep`] refuses against a per-pixel bound the library writes; the library
//! appends the attachments into the slots and writes the next pass's bound. The bound is in the
//! attachment's own depth encoding (D32 float or D24 unorm, standard or reversed planes), so that a
//! surface is never peeled again by a reach that its own quantised depth does not pass.
//!
//! Kernels (one invocation per pixel):
//! - `peel_renderer_layer`: the attachments of pass `k` (copied into buffers) become the pass's
//!   shaded layer (5 words: r, g, b, alpha, depth), the layout `peel_append` reads, and the next
//!   reach ([`crate::peel::next_reach`], the rule the mesh rasteriser's shading pass applies);
//! - `peel_renderer_bound`: the reach as the bound of pass `k + 1` ([`encoded_bound`]): nothing to
//!   discard in pass 0, everything outside the disocclusion buffer (when it is on) behind an opaque
//!   layer ([`behind_translucent`]) and where the
//!   reach is infinite;
//! - `peel_renderer_draw` (one invocation): the next pass's indirect draw command, zero past the
//!   last useful pass (`peel_plan` decides).

use crate::exec::{Group, Load, Mem};
use crate::frame_io::{DEPTH_REVERSED, DEPTH_UNORM24, FrameIoParams, buffer_depth, color_texels, depth_value, view_depth};
use crate::lens::{ThinLens, is_finite};
use crate::peel::{background_seen, is_surface, next_reach};
use crate::texels;
use crate::wg::for_each_item;

/// The bound of a pass that keeps every fragment (pass 0).
pub const KEEP_ALL: f32 = f32::NEG_INFINITY;
/// The bound of a pixel where a pass keeps nothing.
pub const DISCARD_ALL: f32 = f32::INFINITY;
/// The largest 24-bit unorm.
const UNORM24_MAX: f32 = 16_777_215.0;

/// Whether a fragment whose depth-buffer value is `frag_depth` (`gl_FragCoord.z`, as the attachment
/// will hold it) lies beyond the pixel's `bound` and so belongs to this pass. A bound `b >= 0`
/// keeps `frag_depth > b` (standard planes); a bound `b < 0` keeps `frag_depth < −b` (reversed
/// planes); [`KEEP_ALL`] keeps everything, [`DISCARD_ALL`] (and NaN) nothing. The GLSL form is in
/// `docs/integration.md`.
#[inline]
pub fn keep(frag_depth: f32, bound: f32) -> bool {
    if bound < 0.0 { frag_depth < -bound } else { frag_depth > bound }
}

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct RendererPeelParams {
    /// The attachments: size, colour words a pixel, depth encoding, planes and format.
    pub io: FrameIoParams,
    pub lens: ThinLens,
    /// Pixel footprint radius per unit of depth (`tan(yfov/2) / height`), for the umbra.
    pub footprint_per_depth: f32,
    /// The pass whose bound `peel_renderer_bound` writes (0: keep everything).
    pub pass: u32,
    /// 1: passes after the first keep nothing outside the disocclusion buffer.
    pub disocclusion: u32,
    pub _pad: u32,
}

const _: () = assert!(core::mem::size_of::<RendererPeelParams>() <= 128);

/// The bound a fragment must pass to lie beyond `reach` (view depth) in the attachment's encoding,
/// and beyond `stored` (the depth word this pass left, the layer's own quantised depth): for D24,
/// one whole unorm step beyond the step holding the reach, so that the step's own value is refused
/// whatever way the device rounds. [`DISCARD_ALL`] where nothing a depth buffer holds lies beyond it.
#[inline]
pub fn encoded_bound(io: &FrameIoParams, reach: f32, stored: u32) -> f32 {
    let s = depth_value(io, stored);
    // A reach that is the layer's own depth (a partly covering surface) is its stored value as it
    // is: no round trip through view depth, whose f32 error can exceed half a D24 step.
    let d = if reach == view_depth(io, s) { s } else { buffer_depth(io, reach) };
    if !is_finite(d) || !(s >= 0.0 && s <= 1.0) {
        return DISCARD_ALL;
    }
    let unorm = io.depth_format == DEPTH_UNORM24;
    // D24: whole steps `q`, and the bound one step beyond the reach's step. The fragment depth is an
    // f32 about as fine as the step near 1, so no f32 bound splits the step's own rounding interval
    // from the next one reliably; a whole step beyond refuses every depth the device rounds to `q`
    // (its f32 error is below half a step), and merges surfaces within one step (z-fighting).
    let step = |t: f32| (t * UNORM24_MAX + 0.5) as u32;
    // The stored word's own step is taken as an integer: `s · M` in f32 may round to the next one.
    let own = stored & 0xff_ffff;
    let q = if !unorm {
        0
    } else if d == s {
        own
    } else {
        step(d)
    };
    if io.depth_encoding == DEPTH_REVERSED {
        let t = if unorm {
            let q = if q < own { q } else { own };
            if q < 2 { 0.0 } else { (q - 1) as f32 / UNORM24_MAX }
        } else if d < s {
            d
        } else {
            s
        };
        if t > 0.0 { -t } else { DISCARD_ALL }
    } else if unorm {
        (if q > own { q } else { own } + 1) as f32 / UNORM24_MAX
    } else if d > s {
        d
    } else {
        s
    }
}

/// Whether a depth-buffer value `d` was drawn: the attachment is cleared to the far value (1 for
/// standard planes, 0 for reversed ones), which no fragment the pass kept can hold.
#[inline]
pub fn drawn(io: &FrameIoParams, d: f32) -> bool {
    if io.depth_encoding == DEPTH_REVERSED { d > 0.0 } else { d < 1.0 }
}

pub fn layer_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &RendererPeelParams, color: R, depth: R, mut reach: M, mut layer: M) {
    for_each_item(g, p.io.width * p.io.height, |i| {
        let d = depth_value(&p.io, depth.load(i));
        let z = view_depth(&p.io, d);
        let found = drawn(&p.io, d) && is_surface(z);
        let c = texels::decode_color(color_texels(&p.io), &color, i);
        // Where nothing was drawn the attachment holds the renderer's background (its clear or sky):
        // kept once, in the pass that saw the ray escape, as the mesh peel's shading does.
        let (rgb, alpha, depth) = if found {
            ([c[0], c[1], c[2]], c[3], z)
        } else if background_seen(f32::from_bits(reach.load(i))) {
            ([c[0], c[1], c[2]], 1.0, f32::INFINITY)
        } else {
            ([0.0; 3], 0.0, f32::INFINITY)
        };
        let o = 5 * i;
        layer.store(o, rgb[0].to_bits());
        layer.store(o + 1, rgb[1].to_bits());
        layer.store(o + 2, rgb[2].to_bits());
        layer.store(o + 3, alpha.to_bits());
        layer.store(o + 4, depth.to_bits());
        reach.store(i, next_reach(found, alpha, depth, &p.lens, p.footprint_per_depth).to_bits());
    });
}

/// Whether this pass's layer was a translucent surface (`alpha < 1`): its reach is then its own depth
/// ([`crate::peel::next_reach`]), never the umbra behind an opaque one, and the next pass goes on
/// behind it, also outside the disocclusion buffer (`crate::peel::slots_outside_buffer`).
#[inline]
pub fn behind_translucent(io: &FrameIoParams, reach: f32, stored: u32) -> bool {
    is_finite(reach) && reach == view_depth(io, depth_value(io, stored))
}

pub fn bound_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &RendererPeelParams, depth: R, mask: R, mut reach: M, mut bound: M) {
    for_each_item(g, p.io.width * p.io.height, |i| {
        let b = if p.pass == 0 {
            KEEP_ALL
        } else if p.disocclusion != 0 && mask.load(i) == 0 && !behind_translucent(&p.io, f32::from_bits(reach.load(i)), depth.load(i)) {
            // Outside the buffer the slots end at the first opaque one: nothing more to find behind it.
            reach.store(i, f32::INFINITY.to_bits());
            DISCARD_ALL
        } else {
            encoded_bound(&p.io, f32::from_bits(reach.load(i)), depth.load(i))
        };
        bound.store(i, b.to_bits());
    });
}

pub fn draw_pass<G: Group, R: Load, M: Mem>(g: &mut G, _p: &RendererPeelParams, args: R, mut draw: M) {
    for_each_item(g, 1, |_| {
        // The planned draw command (count, 1, 0, 0), and a zero: a non-indexed or an indexed
        // indirect draw command alike.
        let mut i = 0;
        while i < 4 {
            draw.store(i, args.load(i));
            i += 1;
        }
        draw.store(4, 0);
    });
}

kernel!(
    /// A renderer's pass (its attachments copied into buffers) as a shaded peel layer and the next reach.
    PEEL_RENDERER_LAYER = peel_renderer_layer [256] (RendererPeelParams) { read color, read depth, reach, layer } => layer_pass
);
kernel!(
    /// The bound a renderer's next pass tests its fragments against, in its depth encoding.
    PEEL_RENDERER_BOUND = peel_renderer_bound [256] (RendererPeelParams) { read depth, read mask, reach, bound } => bound_pass
);

kernel!(
    /// The renderer's indirect draw command for the next pass (zero past the last useful one).
    PEEL_RENDERER_DRAW = peel_renderer_draw [64] (RendererPeelParams) { read args, draw } => draw_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 3] = [&PEEL_RENDERER_LAYER, &PEEL_RENDERER_BOUND, &PEEL_RENDERER_DRAW];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frame_io::{DEPTH_F32, DEPTH_STANDARD};

    fn io(encoding: u32, format: u32, far: f32) -> FrameIoParams {
        FrameIoParams { width: 1, height: 1, color_words: 2, depth_encoding: encoding, near: 0.1, far, layers: 1, depth_format: format }
    }

    /// The word a D24 attachment stores for `d`, rounded either way a device may.
    fn d24(d: f32, up: bool) -> u32 {
        let x = d * UNORM24_MAX;
        (if up { crate::math::ceil(x) } else { crate::math::floor(x) }) as u32
    }

    #[test]
    fn keep_all_and_discard_all() {
        for z in [0.0, 1e-7, 0.5, 1.0] {
            assert!(keep(z, KEEP_ALL));
            assert!(!keep(z, DISCARD_ALL));
            assert!(!keep(z, f32::NAN));
        }
    }

    #[test]
    fn d24_never_repeels_its_own_surface() {
        // A partly covering surface (reach = its own depth): a linear reach decoded from the D24
        // word and encoded again may fall below the word's own value; the bound must not.
        for encoding in [DEPTH_STANDARD, DEPTH_REVERSED] {
            for far in [100.0, f32::INFINITY] {
                let p = io(encoding, DEPTH_UNORM24, far);
                let mut z = 0.13f32;
                while z < 90.0 {
                    for up in [false, true] {
                        let word = d24(buffer_depth(&p, z), up);
                        let stored = word as f32 / UNORM24_MAX;
                        let reach = view_depth(&p, stored);
                        let b = encoded_bound(&p, reach, word);
                        // The same surface drawn again gives the same word: its fragment depth is
                        // anywhere in the word's rounding interval.
                        for frag in [stored - 0.49 / UNORM24_MAX, stored, stored + 0.49 / UNORM24_MAX] {
                            assert!(!keep(frag, b), "encoding {encoding} far {far} z {z}: word {word} re-peeled");
                        }
                        // Two steps beyond it is kept (within one step: one surface, z-fighting).
                        let beyond = if encoding == DEPTH_REVERSED { word - 2 } else { word + 2 } as f32 / UNORM24_MAX;
                        assert!(keep(beyond, b), "encoding {encoding} z {z}: two steps beyond word {word} refused");
                    }
                    z *= 1.37;
                }
            }
        }
    }

    #[test]
    fn d32_bound_is_the_reach_or_the_stored_depth() {
        for encoding in [DEPTH_STANDARD, DEPTH_REVERSED] {
            let p = io(encoding, DEPTH_F32, 50.0);
            let (z, reach) = (2.0f32, 3.0f32);
            let word = buffer_depth(&p, z).to_bits();
            let b = encoded_bound(&p, reach, word);
            // The surface itself, and everything up to the reach, is refused; beyond it is kept.
            assert!(!keep(buffer_depth(&p, z), b));
            assert!(!keep(buffer_depth(&p, 2.99), b));
            assert!(keep(buffer_depth(&p, 3.01), b));
            // A reach equal to the surface's depth still refuses the surface's own value.
            let own = encoded_bound(&p, view_depth(&p, f32::from_bits(word)), word);
            assert!(!keep(f32::from_bits(word), own));
            assert!(keep(buffer_depth(&p, 2.01), own));
            // A reach beyond the far plane, or infinite, keeps nothing.
            assert_eq!(encoded_bound(&p, 60.0, word), DISCARD_ALL);
            assert_eq!(encoded_bound(&p, f32::INFINITY, word), DISCARD_ALL);
        }
    }

    #[test]
    fn buffer_depth_inverts_view_depth() {
        for encoding in [DEPTH_STANDARD, DEPTH_REVERSED] {
            for far in [100.0, f32::INFINITY] {
                let p = io(encoding, DEPTH_F32, far);
                for z in [0.1f32, 0.5, 3.0, 42.0, 99.0] {
                    let back = view_depth(&p, buffer_depth(&p, z));
                    assert!((back - z).abs() <= 1e-4 * z, "encoding {encoding} far {far}: {z} came back as {back}");
                }
            }
        }
    }
}
