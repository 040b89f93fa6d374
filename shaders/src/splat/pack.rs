//! Stage 1: the per-pixel layer slots of the input become packed fragments, one cell per pixel.
//!
//! Input: `layers` (per pixel `params.layers` slots, [`crate::slot`]: premultiplied red, green,
//! blue, depth, alpha as f32 bits, front to back) and `counts` (slots used per pixel). A slot with a
//! non-finite colour or a depth that is not positive (NaN, 0, negative) is dropped and counted: it
//! never spreads. Every other colour goes through the numerical contract's [`clamp_color`]
//! (negative and subnormal channels to 0, channels above `COLOR_MAX` to it; counted when it changes
//! a value), then into the fragment's shared-exponent colour, which holds the whole contract range;
//! alpha through [`clamp_alpha`] (counted). The background arrives as a slot at infinite depth (its
//! CoC the far-field limit) and blends like any surface. A pixel with no slot at all has no data: it
//! gets a black background fragment, as `LayeredImage::front` reads it (a pixel whose slots were all
//! dropped gets nothing and is filled by its neighbours' blur). A pixel whose slots end translucent
//! gets the same black background behind them (a pixel composites over black; counted).
//!
//! The sharp front: a pixel's leading in-focus slots (disc radius at most one pixel) composited
//! front to back in f32 and kept out of the lists. Opaque, or translucent with nothing of the pixel
//! behind it (then over black), it ends the pixel's traversal, and in-focus slots behind it are
//! dropped (counted). Translucent with a blurred slot behind it, it goes into the lists as one
//! in-focus fragment (10-bit alpha, shared-exponent colour), and so do the in-focus slots after it.

use super::fragment::Fragment;
use super::{SplatParams, stats};
use crate::exec::{Group, Mem};
use crate::lens::{is_finite, is_positive};
use crate::radiance::{clamp_color, is_clamped};
use crate::slot::{Composite, Slot, clamp_alpha, is_alpha_clamped};
use crate::wg::for_each_item;

/// The slot `(pixel, k)` of the input ([`crate::slot`]).
#[inline]
pub fn input_slot<M: Mem>(layers: &M, p: &SplatParams, pixel: u32, k: u32) -> Slot {
    crate::slot::load(layers, pixel * p.layers + k)
}

/// Whether a slot may become a fragment.
#[inline]
pub fn is_valid(color: [f32; 3], depth: f32) -> bool {
    is_finite(color[0]) && is_finite(color[1]) && is_finite(color[2]) && is_positive(depth)
}

/// The sharp front of `pixel`: premultiplied colour and depth, or NaN depth when it has none. A
/// sharp front is opaque (or translucent over black, nothing of the pixel behind it): it takes all
/// the coverage left at its depth and ends the pixel's traversal.
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

/// The state of a pixel's sharp front while its slots are read: none yet.
const NO_SHARP: u32 = 0;
/// In-focus slots are being composited into it (each in-focus slot right behind the last).
const SHARP_OPEN: u32 = 1;
/// Opaque: in-focus slots behind it are hidden.
const SHARP_CLOSED: u32 = 2;
/// Translucent and followed by a blurred slot: it went into the cells as one in-focus fragment (so
/// the depth order holds), and later in-focus slots go there too.
const SHARP_FLUSHED: u32 = 3;

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
        let (mut kept, mut dropped, mut clamped, mut alpha_clamped, mut hidden) = (0u32, 0u32, 0u32, 0u32, 0u32);
        // The sharp front: the "over" of the pixel's leading run of in-focus slots, in f32.
        let mut state = NO_SHARP;
        let mut front = Composite::EMPTY;
        let mut front_z = f32::NAN;
        // The light all valid slots let through so far, and how many there were.
        let mut through = 1.0f32;
        let mut valid = 0u32;
        // An empty pixel's black background is one more slot; so is the black behind a pixel whose
        // slots end translucent (a pixel composites over black), added after its slots.
        let mut slots = if n == 0 { 1 } else { n };
        let mut k = 0;
        while k < slots {
            let s = if k >= n { Slot::opaque([0.0; 3], f32::INFINITY) } else { input_slot(&layers, p, i, k) };
            k += 1;
            let (c, z) = (s.color, s.depth);
            if !is_valid(c, z) {
                dropped += 1;
            } else {
                alpha_clamped += is_alpha_clamped(s.alpha) as u32;
                let a = clamp_alpha(s.alpha);
                clamped += is_clamped(c) as u32;
                let c = clamp_color(c);
                valid += 1;
                through *= 1.0 - a;
                let f = Fragment::at_pixel(x, y, c, z).with_alpha(a);
                let in_focus = f.radius(&p.lens, p.max_radius) <= 1.0;
                if in_focus && state == NO_SHARP {
                    front.add(c, a);
                    front_z = z;
                    state = if a >= 1.0 { SHARP_CLOSED } else { SHARP_OPEN };
                } else if in_focus && state == SHARP_OPEN {
                    front.add(c, a);
                    state = if front.transmit > 0.0 { SHARP_OPEN } else { SHARP_CLOSED };
                } else if in_focus && state == SHARP_CLOSED {
                    // Behind an opaque sharp front: invisible here, and it reaches no other pixel.
                    hidden += 1;
                } else {
                    if state == SHARP_OPEN {
                        // A blurred slot behind a translucent front: the front joins the lists.
                        let chain = Fragment::at_pixel(x, y, front.color, front_z).with_alpha(front.alpha());
                        chain.store(&mut cells, i * p.layers + kept);
                        kept += 1;
                        state = SHARP_FLUSHED;
                    }
                    if kept < p.layers {
                        f.store(&mut cells, i * p.layers + kept);
                        kept += 1;
                    } else {
                        // Only the black behind a pixel whose cells are full gets here: it stays
                        // in this pixel, as its front at infinite depth.
                        front = Composite::EMPTY;
                        front.add(c, a);
                        front_z = z;
                        state = SHARP_CLOSED;
                    }
                }
            }
            // A front still open at the end lies over black already (nothing of the pixel behind).
            if k == slots && k == n && valid > 0 && through > 0.0 && state != SHARP_OPEN {
                slots += 1;
                st.atomic_add(stats::BACKED, 1);
            }
        }
        if state == SHARP_OPEN || state == SHARP_CLOSED {
            store_sharp(&mut sharp, i, front.color, front_z);
        } else {
            store_sharp(&mut sharp, i, [0.0; 3], f32::NAN);
        }
        cell_counts.store(i, kept);
        if n == 0 {
            st.atomic_add(stats::SKY, 1);
        }
        if state == SHARP_OPEN || state == SHARP_CLOSED {
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
        if alpha_clamped > 0 {
            st.atomic_add(stats::ALPHA_CLAMPED, alpha_clamped);
        }
    });
}

kernel!(
    /// Input slots → packed fragments in cells of one pixel.
    PACK = splat_pack [256] (SplatParams) { layers, counts, cells, cell_counts, sharp, st } reads { layers, counts } => pack_pass
);
