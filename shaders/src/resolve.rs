//! Area-integrated multi-layer images: the resolve that turns a pixel's `N` sub-sample fragment
//! lists (each front to back, as a ray cast or a peel at sub-sample resolution makes them) into at
//! most `max_layers` fragments of partial coverage. The host's ray caster and peel call
//! [`resolve_pixel`]; the device runs the same function as the `resolve` kernel.
//!
//! The rule, per pixel:
//! 1. **Clusters.** Repeatedly take the nearest fragment `z0` not yet used in any sub-sample; the
//!    cluster is, in every sub-sample, its next fragments with depth `<= z0 · (1 + tolerance)`
//!    (`tolerance` is the layers' edge depth ratio: a larger relative gap is a different surface;
//!    at `z0 = +inf` the cluster is the background).
//! 2. **Coverage of what is still open.** A sub-sample *sees down to* a cluster when its list
//!    still holds a fragment there or behind it; a list that ended in front (an opaque surface
//!    whose umbra hid the rest, or a full list) says nothing about what lies deeper. Within a
//!    sub-sample the cluster's members composite front to back ("over": member `i` weighted by
//!    `t_i = Π_{j<i}(1 − α_j)`, coverage `w_i = t_i α_i`), and `T_s` is what the sub-sample's
//!    earlier clusters let through. Over the sub-samples `s` that see down to the cluster,
//!    `alpha = Σ T_s·Σw / Σ T_s` and premultiplied colour `= Σ T_s·Σ t·c / Σ T_s`: the share of
//!    the light still open that the cluster takes. The front-to-back composite of the clusters
//!    is then the pixel's area mean of its sub-samples' own composites, exactly, at every depth
//!    (so the pinhole image, and every method in focus, see the area mean). A cluster no open
//!    sub-sample sees (hidden in the pinhole, seen from other lens points) weighs the sub-samples
//!    that see down to it alike (`T_s` read as 1). Depth is the `w`-weighted mean depth (the
//!    background stays at `+inf`). So a sub-pixel emitter seen by 1 of 16 sub-samples over a
//!    wall seen by all 16 gets alpha 1/16 with its energy, and the wall alpha 1; an edge pixel
//!    half covered gets its front surface at alpha 0.5 and the surface seen beside it alpha 1,
//!    also where the front surface's sub-samples see past that depth to something farther (a
//!    floor receding from the eye; two objects side by side over the sky). A cluster with
//!    neither coverage nor light is dropped.
//! 3. **At most `max_layers`.** The first `max_layers − 1` clusters are fragments of their own;
//!    every further cluster is composited "over" into the last fragment (its depth stays that of
//!    the first cluster it holds), so no energy is lost; [`Resolved::merged`] counts them.

use crate::exec::{Group, Load, Mem};
use crate::footprint;
pub use crate::footprint::subsample_offset;
use crate::lens::is_finite;
use crate::slot::{self, clamp_alpha, over};
use crate::wg::for_each_item;

/// Most sub-samples a pixel (a 4x4 grid).
pub const MAX_SUBSAMPLES: u32 = 16;

/// A fragment as the resolve reads and writes it: the frame's slot ([`crate::slot`]: colour
/// premultiplied by alpha, depth, alpha).
pub use crate::slot::Slot as Sample;

/// What a resolve produced.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Resolved {
    /// Fragments written, `<= max_layers`.
    pub count: u32,
    /// Clusters composited into the last fragment because the pixel was full.
    pub merged: u32,
}

/// Resolves `subsamples` (at most [`MAX_SUBSAMPLES`]) fragment lists, list `s` holding `count(s)`
/// fragments `fragment(s, k)` front to back (premultiplied colour, alpha read through
/// [`clamp_alpha`]), into at most `max_layers` (`>= 1`) premultiplied fragments, front to back,
/// each handed to `out(k, sample, footprint)` (module docs: the rule) with its
/// [`crate::footprint`]: bit `s` set where sub-sample `s` gave it coverage or light. `tolerance` is
/// the relative depth gap that separates clusters.
pub fn resolve_pixel<C, F, O>(subsamples: u32, count: C, fragment: F, max_layers: u32, tolerance: f32, mut out: O) -> Resolved
where
    C: Fn(u32) -> u32,
    F: Fn(u32, u32) -> Sample,
    O: FnMut(u32, Sample, u32),
{
    let n = if subsamples < MAX_SUBSAMPLES { subsamples } else { MAX_SUBSAMPLES };
    let mut cursor = [0u32; MAX_SUBSAMPLES as usize];
    let mut held = Sample { color: [0.0; 3], depth: 0.0, alpha: 0.0 };
    let mut held_footprint = 0u32;
    let mut holding = false;
    let mut result = Resolved::default();
    loop {
        // The nearest fragment not yet used.
        let mut front = f32::INFINITY;
        let mut any = false;
        let mut s = 0;
        while s < n {
            if cursor[s as usize] < count(s) {
                let d = fragment(s, cursor[s as usize]).depth;
                if !any || d < front {
                    front = d;
                }
                any = true;
            }
            s += 1;
        }
        if !any {
            break;
        }
        let finite = is_finite(front);
        let limit = if finite { front + tolerance * front } else { f32::INFINITY };
        // Sums over the sub-samples that see down to the cluster, each weighted by what its
        // earlier clusters let through (`open`) and alike (`seen`, the fallback).
        let mut seen = 0u32;
        let mut open = 0.0f32;
        let mut covered = 0.0f32;
        let mut covered_open = 0.0f32;
        let mut color = [0.0f32; 3];
        let mut color_open = [0.0f32; 3];
        let mut depth = 0.0f32;
        let mut footprint = 0u32;
        let mut progressed = false;
        let mut s = 0;
        while s < n {
            let c = count(s);
            let mut k = cursor[s as usize];
            if k < c {
                seen += 1;
                let mut through = 1.0f32;
                let mut j = 0;
                while j < k {
                    through *= 1.0 - clamp_alpha(fragment(s, j).alpha);
                    j += 1;
                }
                open += through;
                let mut t = 1.0f32;
                while k < c {
                    let f = fragment(s, k);
                    if !(f.depth <= limit) {
                        break;
                    }
                    let a = clamp_alpha(f.alpha);
                    let w = t * a;
                    if w > 0.0 || (t > 0.0 && (f.color[0] > 0.0 || f.color[1] > 0.0 || f.color[2] > 0.0)) {
                        footprint |= 1 << s;
                    }
                    color[0] += t * f.color[0];
                    color[1] += t * f.color[1];
                    color[2] += t * f.color[2];
                    color_open[0] += through * t * f.color[0];
                    color_open[1] += through * t * f.color[1];
                    color_open[2] += through * t * f.color[2];
                    covered += w;
                    covered_open += through * w;
                    if finite {
                        depth += w * f.depth;
                    }
                    t *= 1.0 - a;
                    k += 1;
                    progressed = true;
                }
                cursor[s as usize] = k;
            }
            s += 1;
        }
        if !progressed {
            // Only a NaN depth stops every list: drop those heads so the loop ends.
            let mut s = 0;
            while s < n {
                if cursor[s as usize] < count(s) {
                    cursor[s as usize] += 1;
                }
                s += 1;
            }
            continue;
        }
        if !(covered > 0.0) && color[0] == 0.0 && color[1] == 0.0 && color[2] == 0.0 {
            continue;
        }
        let (share, color, d) = if open > 0.0 { (covered_open, color_open, open) } else { (covered, color, seen as f32) };
        let cluster = Sample {
            color: [color[0] / d, color[1] / d, color[2] / d],
            alpha: share / d,
            depth: if !finite {
                f32::INFINITY
            } else if covered > 0.0 {
                depth / covered
            } else {
                front
            },
        };
        if !holding {
            held = cluster;
            held_footprint = footprint;
            holding = true;
        } else if result.count + 1 < max_layers {
            out(result.count, held, held_footprint);
            result.count += 1;
            held = cluster;
            held_footprint = footprint;
        } else {
            held = over(held, cluster);
            held_footprint |= footprint;
            result.merged += 1;
        }
    }
    if holding && max_layers > 0 {
        out(result.count, held, held_footprint);
        result.count += 1;
    }
    result
}

/// Side of the sub-sample grid for `n` sub-samples: `n` must be 1, 4, 9 or 16; 0 otherwise.
#[inline]
pub fn grid_side(n: u32) -> u32 {
    match n {
        1 => 1,
        4 => 2,
        9 => 3,
        16 => 4,
        _ => 0,
    }
}

/// The `resolve` kernel's constants.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct ResolveParams {
    /// The resolved image, pixels.
    pub width: u32,
    pub height: u32,
    /// Side of the sub-sample grid ([`grid_side`]): the sub-sample image is `side` times wider and
    /// higher, sub-sample `(i, j)` of pixel `(x, y)` its pixel `(side·x + i, side·y + j)`.
    pub side: u32,
    /// Slots a sub-sample pixel, and slots a resolved pixel.
    pub fine_layers: u32,
    pub layers: u32,
    /// Relative depth gap that separates clusters.
    pub tolerance: f32,
    /// 1: the slot buffer carries each slot's [`crate::footprint`] after the slots
    /// ([`crate::footprint::slot_word`]), and the resolve writes it.
    pub footprints: u32,
    pub _pad: u32,
}

pub fn resolve_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &ResolveParams, fine: R, fine_counts: R, mut fragments: M, mut counts: M) {
    let (w, side) = (p.width, p.side);
    let fine_width = w * side;
    for_each_item(g, w * p.height, |i| {
        let (x, y) = (i % w, i / w);
        let pixel = |k: u32| (y * side + k / side) * fine_width + x * side + k % side;
        let count = |k: u32| {
            let c = fine_counts.load(pixel(k));
            if c < p.fine_layers { c } else { p.fine_layers }
        };
        let fragment = |k: u32, l: u32| slot::load(&fine, pixel(k) * p.fine_layers + l);
        let base = i * p.layers;
        let slots = w * p.height * p.layers;
        let r = resolve_pixel(side * side, count, fragment, p.layers, p.tolerance, |l, s, footprint| {
            slot::store(&mut fragments, base + l, s);
            if p.footprints != 0 {
                fragments.store(footprint::slot_word(slots, base + l), footprint);
            }
        });
        counts.store(i, r.count);
        // Unused slots hold no footprint, as the host's resolve leaves them.
        let mut l = r.count;
        while p.footprints != 0 && l < p.layers {
            fragments.store(footprint::slot_word(slots, base + l), footprint::WHOLE);
            l += 1;
        }
    });
}

kernel!(
    /// Resolves a sub-sample image's slots into the frame's slots (area-integrated layers).
    RESOLVE = resolve [64] (ResolveParams) { read fine, read fine_counts, fragments, counts } => resolve_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 1] = [&RESOLVE];
