//! Stage 1: the per-pixel layer slots of the input become fragments. This pass keeps each pixel's
//! sharp front and counts; the list fragments are made again from the input where they are needed
//! ([`next_kept`], [`kept_fragment`]: merging and `bin::place_pass`), so no slot-per-pixel array of
//! them is ever stored.
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

/// Slots pixel `i` holds (its count, at most `layers`), and the slots packing reads: an empty
/// pixel's black background is one more.
#[inline]
pub fn pixel_slots<M: Mem>(counts: &M, p: &SplatParams, i: u32) -> (u32, u32) {
    let n = counts.load(i);
    let n = if n < p.layers { n } else { p.layers };
    (n, if n == 0 { 1 } else { n })
}

/// Slot `k` of pixel `i` as packing reads it (`n` its count): an empty pixel's only slot is the
/// black background at infinite depth.
#[inline]
pub fn read_slot<M: Mem>(layers: &M, p: &SplatParams, i: u32, n: u32, k: u32) -> ([f32; 3], f32) {
    if n == 0 { ([0.0; 3], f32::INFINITY) } else { input_slot(layers, p, i, k) }
}

/// The one-pixel fragment a valid slot of pixel `i` becomes (its colour clamped to the contract).
#[inline]
pub fn slot_fragment(p: &SplatParams, i: u32, c: [f32; 3], z: f32) -> Fragment {
    Fragment::at_pixel(i % p.width, i / p.width, clamp_color(c), z)
}

/// Whether a fragment goes to the lists: its disc reaches beyond its own pixel centre (a disc of
/// radius at most 1 is in focus and stays with its pixel).
#[inline]
pub fn is_blurred(p: &SplatParams, f: &Fragment) -> bool {
    !(f.radius(&p.lens, p.max_radius) <= 1.0)
}

/// The first slot from `k` on that packing keeps as a list fragment (valid and blurred), or
/// `slots` when none is left: a cursor over a pixel's fragments in slot order.
#[inline]
pub fn next_kept<M: Mem>(layers: &M, p: &SplatParams, i: u32, n: u32, slots: u32, k: u32) -> u32 {
    let mut k = k;
    while k < slots {
        let (c, z) = read_slot(layers, p, i, n, k);
        if is_valid(c, z) && is_blurred(p, &slot_fragment(p, i, c, z)) {
            return k;
        }
        k += 1;
    }
    slots
}

/// The fragment kept slot `k` of pixel `i` becomes, as a stage reads it after storing (packed
/// and unpacked again).
#[inline]
pub fn kept_fragment<M: Mem>(layers: &M, p: &SplatParams, i: u32, n: u32, k: u32) -> Fragment {
    let (c, z) = read_slot(layers, p, i, n, k);
    Fragment::unpack(slot_fragment(p, i, c, z).pack())
}

/// Per pixel: the sharp front and the input statistics. Unmerged (`cell` 1), also the pixel's
/// list fragments: their count at `cells[i]` and their widest radius (f32 bits) at
/// `cells[pixels + i]`, where `splat_tile_count` reads them; the fragments themselves are written
/// only once their place in the dense array is known (`bin::place_pass`).
#[allow(clippy::too_many_arguments)]
pub fn pack_pass<G: Group, M: Mem>(g: &mut G, p: &SplatParams, layers: M, counts: M, mut cells: M, mut sharp: M, mut st: M) {
    let p = &super::plan::planned(p, &st);
    let pixels = p.width * p.height;
    for_each_item(g, pixels, |i| {
        let (n, slots) = pixel_slots(&counts, p, i);
        let (mut kept, mut dropped, mut clamped, mut hidden, mut capped) = (0u32, 0u32, 0u32, 0u32, 0u32);
        let mut widest = 0.0f32;
        let mut front = false;
        let mut k = 0;
        while k < slots {
            let (c, z) = read_slot(&layers, p, i, n, k);
            k += 1;
            if !is_valid(c, z) {
                dropped += 1;
                continue;
            }
            clamped += is_clamped(c) as u32;
            let f = slot_fragment(p, i, c, z);
            if !is_blurred(p, &f) {
                if front {
                    // Behind the sharp front: invisible here, and it reaches no other pixel.
                    hidden += 1;
                } else {
                    store_sharp(&mut sharp, i, f.color, z);
                    front = true;
                }
                continue;
            }
            let r = f.radius(&p.lens, p.max_radius);
            widest = if r > widest { r } else { widest };
            capped += f.is_capped(&p.lens, p.max_radius) as u32;
            kept += 1;
        }
        if !front {
            store_sharp(&mut sharp, i, [0.0; 3], f32::NAN);
        }
        if p.cell == 1 {
            cells.store(i, kept);
            cells.store(pixels + i, widest.to_bits());
            if capped > 0 {
                st.atomic_add(stats::CAPPED, capped);
            }
        }
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
    /// Input slots → sharp fronts, and unmerged each pixel's list fragment count and widest radius.
    PACK = splat_pack [256] (SplatParams) { layers, counts, cells, sharp, st } reads { layers, counts } => pack_pass
);
