//! Stage 1: the per-pixel layer slots of the input become packed fragments, one cell per pixel.
//!
//! Input: `layers` (per pixel `params.layers` slots of 4 words: red, green, blue, depth as f32 bits,
//! front to back) and `counts` (slots used per pixel). A slot with a non-finite colour or a depth that
//! is not positive (NaN, 0, negative) is dropped and counted: it never spreads. Every other colour goes
//! through the numerical contract's [`clamp_color`] (negative and subnormal channels to 0, channels
//! above `COLOR_MAX` to it; counted when it changes a value), then into the fragment's
//! shared-exponent colour, which holds the whole contract range. The background arrives as a slot at
//! infinite depth (its CoC the far-field limit) and blends like any surface. A pixel with no slot
//! at all has no data: it gets a black background fragment, as `LayeredImage::front` reads it (a
//! pixel whose slots were all dropped gets nothing and is filled by its neighbours' blur).

use super::fragment::Fragment;
use super::{SplatParams, stats};
use crate::exec::{Group, Mem};
use crate::lens::{is_finite, is_positive};
use crate::radiance::{clamp_color, is_clamped};
use crate::wg::for_each_item;

/// The slot `(pixel, k)` of the input: colour and depth.
#[inline]
pub fn input_slot<M: Mem>(layers: &M, p: &SplatParams, pixel: u32, k: u32) -> ([f32; 3], f32) {
    let b = 4 * (pixel * p.layers + k);
    (
        [f32::from_bits(layers.load(b)), f32::from_bits(layers.load(b + 1)), f32::from_bits(layers.load(b + 2))],
        f32::from_bits(layers.load(b + 3)),
    )
}

/// Whether a slot may become a fragment.
#[inline]
pub fn is_valid(color: [f32; 3], depth: f32) -> bool {
    is_finite(color[0]) && is_finite(color[1]) && is_finite(color[2]) && is_positive(depth)
}

/// The sharp front of `pixel`: colour and depth, or NaN depth when it has none.
#[inline]
pub fn load_sharp<M: Mem>(sharp: &M, pixel: u32) -> ([f32; 3], f32) {
    let b = 4 * pixel;
    (
        [f32::from_bits(sharp.load(b)), f32::from_bits(sharp.load(b + 1)), f32::from_bits(sharp.load(b + 2))],
        f32::from_bits(sharp.load(b + 3)),
    )
}

#[inline]
fn store_sharp<M: Mem>(sharp: &mut M, pixel: u32, c: [f32; 3], z: f32) {
    let b = 4 * pixel;
    sharp.store(b, c[0].to_bits());
    sharp.store(b + 1, c[1].to_bits());
    sharp.store(b + 2, c[2].to_bits());
    sharp.store(b + 3, z.to_bits());
}

#[allow(clippy::too_many_arguments)]
pub fn pack_pass<G: Group, M: Mem>(
    g: &mut G,
    p: &SplatParams,
    layers: M,
    counts: M,
    mut cells: M,
    mut cell_counts: M,
    mut sharp: M,
    mut st: M,
) {
    let p = &super::plan::planned(p, &st);
    let pixels = p.width * p.height;
    for_each_item(g, pixels, |i| {
        let (x, y) = (i % p.width, i / p.width);
        let n = counts.load(i);
        let n = if n < p.layers { n } else { p.layers };
        let (mut kept, mut dropped, mut clamped, mut hidden) = (0u32, 0u32, 0u32, 0u32);
        let mut front = false;
        // An empty pixel's black background is one more slot.
        let slots = if n == 0 { 1 } else { n };
        let mut k = 0;
        while k < slots {
            let (c, z) = if n == 0 { ([0.0; 3], f32::INFINITY) } else { input_slot(&layers, p, i, k) };
            k += 1;
            if !is_valid(c, z) {
                dropped += 1;
                continue;
            }
            clamped += is_clamped(c) as u32;
            let c = clamp_color(c);
            if Fragment::at_pixel(x, y, c, z).radius(&p.lens, p.max_radius) <= 1.0 {
                if front {
                    // Behind the sharp front: invisible here, and it reaches no other pixel.
                    hidden += 1;
                } else {
                    store_sharp(&mut sharp, i, c, z);
                    front = true;
                }
                continue;
            }
            Fragment::at_pixel(x, y, c, z).store(&mut cells, i * p.layers + kept);
            kept += 1;
        }
        if !front {
            store_sharp(&mut sharp, i, [0.0; 3], f32::NAN);
        }
        cell_counts.store(i, kept);
        if n == 0 {
            st.atomic_add(stats::SKY, 1);
        }
        if front {
            st.atomic_add(stats::SHARP, 1);
        }
        if hidden > 0 {
            st.atomic_add(stats::HIDDEN_SHARP, hidden);
        }
        if dropped > 0 {
            st.atomic_add(stats::DROPPED, dropped);
        }
        if clamped > 0 {
            st.atomic_add(stats::CLAMPED, clamped);
        }
    });
}

kernel!(
    /// Input slots → packed fragments in cells of one pixel.
    PACK = splat_pack [256] (SplatParams) { layers, counts, cells, cell_counts, sharp, st } reads { layers, counts } => pack_pass
);
