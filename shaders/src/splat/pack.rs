//! Stage 1: the per-pixel layer slots of the input become fragments. This pass keeps each pixel's
//! sharp front and, unmerged, writes its list fragments; merging makes them again from the input
//! ([`PixelFragments`]: this pass and merging walk a pixel's slots with the same rule), so no
//! level of fragments is stored before its last.
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
use crate::exec::{Group, Load, Mem};
use crate::footprint;
use crate::lens::{is_finite, is_positive};
use crate::radiance::{clamp_color, is_clamped};
use crate::slot::{Composite, Slot, clamp_alpha, is_alpha_clamped};
use crate::wg::for_each_item;

/// The slot `(pixel, k)` of the input ([`crate::slot`]).
#[inline]
pub fn input_slot(layers: &impl Load, p: &SplatParams, pixel: u32, k: u32) -> Slot {
    crate::slot::load(layers, pixel * p.layers + k)
}

/// The footprint of slot `(pixel, k)` where the input has them, else `WHOLE`.
#[inline]
pub fn input_footprint(layers: &impl Load, p: &SplatParams, pixel: u32, k: u32) -> u32 {
    if p.footprint_side() == 0 {
        return footprint::WHOLE;
    }
    let full = footprint::full(p.footprint_side());
    // Bits beyond the grid mean nothing. None of the grid's, or all of them: the whole pixel,
    // splatted from its centre.
    let mask = layers.load(footprint::slot_word(p.width * p.height * p.layers, pixel * p.layers + k)) & full;
    if mask == full { footprint::WHOLE } else { mask }
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
pub fn load_sharp(sharp: &impl Load, pixel: u32) -> ([f32; 3], f32) {
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

/// The premultiplied colour and alpha with which a slot of colour `c`, alpha `a` and footprint `fp`
/// spends the coverage budget of the accumulation, behind slots of its pixel that let `through` of
/// the light pass and cover the sub-samples `covered`.
///
/// A slot's alpha is the composite's: the share of the light still open that it takes
/// ([`crate::resolve`]). The budget adds coverage instead, and that differs where a pixel's surfaces
/// lie side by side: a floor's near half at alpha 1/2 and its far half beside it at alpha 1 would
/// spend 3/2 of a pixel between them, and the far half, of rows farther up, would win the lists'
/// depth order over the near halves of the rows below. A footprint tells the two cases apart. Where
/// the slot's sub-samples `open` lie beside the nearer slots (none of theirs), the light it shows,
/// `through · a`, comes from there; spread evenly over its footprint, it covers `through · a · |fp| /
/// |open|` of the pixel, which is what it spends (at most `a`, with its colour scaled alike). A slot
/// wholly behind nearer ones (no open sub-sample: a wall behind an edge) keeps its alpha, filling
/// what the near field leaves as the budget assumes; so do slots without a footprint.
#[inline]
pub fn budget_share(c: [f32; 3], a: f32, through: f32, fp: u32, covered: u32) -> ([f32; 3], f32) {
    let open = fp & !covered;
    if fp == footprint::WHOLE || open == 0 {
        return (c, a);
    }
    let share = through * a * fp.count_ones() as f32 / open.count_ones() as f32;
    if !(share < a) {
        return (c, a);
    }
    let k = share / a;
    ([c[0] * k, c[1] * k, c[2] * k], share)
}

/// The state of a pixel's sharp front while its slots are read: none yet.
const NO_SHARP: u32 = 0;
/// In-focus slots are being composited into it (each in-focus slot right behind the last).
const SHARP_OPEN: u32 = 1;
/// Opaque: in-focus slots behind it are hidden.
const SHARP_CLOSED: u32 = 2;
/// Translucent and followed by a blurred slot: it went into the lists as one in-focus "chain"
/// fragment (so the depth order holds), and later in-focus slots go there too.
const SHARP_FLUSHED: u32 = 3;

/// A cursor over one pixel's list fragments, front to back, made from its input slots: the one
/// rule for which fragments a pixel puts into the lists (its sharp front's state machine, the chain
/// fragment behind a translucent sharp front, the black behind slots that end translucent). Packing
/// counts them (and unmerged writes them) and merging walks them ([`super::merge`]), so both passes
/// see the same sequence. After the walk it also holds the pixel's sharp front and input
/// statistics.
#[derive(Clone, Copy)]
pub struct PixelFragments {
    pixel: u32,
    /// Slots the pixel holds (its count, at most `layers`).
    pub n: u32,
    /// Slots read: `n`, plus one for an empty pixel's black or the black behind translucent slots.
    slots: u32,
    /// The next slot to read.
    k: u32,
    state: u32,
    /// The sharp front: the "over" of the leading run of in-focus slots, in f32, and its depth.
    front: Composite,
    front_z: f32,
    /// The light all valid slots let through so far, and how many there were.
    through: f32,
    valid: u32,
    /// The sub-samples the valid slots so far cover ([`crate::footprint`]; all for a slot without one).
    covered: u32,
    /// List fragments yielded so far.
    kept: u32,
    /// 1 while a fragment waits behind the chain fragment just yielded (in `held`).
    waiting: u32,
    held: Fragment,
    /// The current list fragment (valid after [`PixelFragments::advance`] returned true), as
    /// made, before it is stored.
    pub head: Fragment,
    pub dropped: u32,
    pub clamped: u32,
    pub alpha_clamped: u32,
    pub hidden: u32,
    /// 1 when black was added behind slots that end translucent.
    pub backed: u32,
}

const NO_FRAGMENT: Fragment = Fragment { color: [0.0; 3], alpha: 1.0, depth: 0.0, level: 0, pos: [0; 2], footprint: footprint::WHOLE };

impl PixelFragments {
    pub const EMPTY: PixelFragments = PixelFragments {
        pixel: 0,
        n: 0,
        slots: 0,
        k: 0,
        state: NO_SHARP,
        front: Composite::EMPTY,
        front_z: f32::NAN,
        through: 1.0,
        valid: 0,
        covered: 0,
        kept: 0,
        waiting: 0,
        held: NO_FRAGMENT,
        head: NO_FRAGMENT,
        dropped: 0,
        clamped: 0,
        alpha_clamped: 0,
        hidden: 0,
        backed: 0,
    };

    /// The cursor before pixel `i`'s first list fragment.
    #[inline]
    pub fn new(counts: &impl Load, p: &SplatParams, i: u32) -> Self {
        let n = counts.load(i);
        let n = if n < p.layers { n } else { p.layers };
        // An empty pixel's black background is one more slot.
        PixelFragments { pixel: i, n, slots: if n == 0 { 1 } else { n }, ..Self::EMPTY }
    }

    /// Moves to the pixel's next list fragment (into `head`); false once there is none.
    pub fn advance(&mut self, layers: &impl Load, p: &SplatParams) -> bool {
        if self.waiting != 0 {
            self.waiting = 0;
            self.head = self.held;
            return true;
        }
        let (x, y) = (self.pixel % p.width, self.pixel / p.width);
        while self.k < self.slots {
            let s = if self.k >= self.n { Slot::opaque([0.0; 3], f32::INFINITY) } else { input_slot(layers, p, self.pixel, self.k) };
            self.k += 1;
            let (c, z) = (s.color, s.depth);
            let mut made = 0u32;
            if !is_valid(c, z) {
                self.dropped += 1;
            } else {
                self.alpha_clamped += is_alpha_clamped(s.alpha) as u32;
                let a = clamp_alpha(s.alpha);
                self.clamped += is_clamped(c) as u32;
                let c = clamp_color(c);
                self.valid += 1;
                let fp = if self.k > self.n { footprint::WHOLE } else { input_footprint(layers, p, self.pixel, self.k - 1) };
                let (spent_c, spent_a) = budget_share(c, a, self.through, fp, self.covered);
                self.covered |= if fp == footprint::WHOLE { u32::MAX } else { fp };
                self.through *= 1.0 - a;
                // In focus as without a footprint: a sharp front stays in its pixel, and keeps the
                // slot's own colour and alpha.
                let in_focus = Fragment::at_pixel(x, y, c, z).radius(&p.lens, p.max_radius) <= 1.0;
                let f = Fragment::at_pixel(x, y, spent_c, z).with_alpha(spent_a).with_footprint(fp);
                if in_focus && self.state == NO_SHARP {
                    self.front.add(c, a);
                    self.front_z = z;
                    self.state = if a >= 1.0 { SHARP_CLOSED } else { SHARP_OPEN };
                } else if in_focus && self.state == SHARP_OPEN {
                    self.front.add(c, a);
                    self.state = if self.front.transmit > 0.0 { SHARP_OPEN } else { SHARP_CLOSED };
                } else if in_focus && self.state == SHARP_CLOSED {
                    // Behind an opaque sharp front: invisible here, and it reaches no other pixel.
                    self.hidden += 1;
                } else {
                    if self.state == SHARP_OPEN {
                        // A blurred slot behind a translucent front: the front joins the lists.
                        self.head = Fragment::at_pixel(x, y, self.front.color, self.front_z).with_alpha(self.front.alpha());
                        self.kept += 1;
                        made = 1;
                        self.state = SHARP_FLUSHED;
                    }
                    if self.kept < p.layers {
                        if made == 0 {
                            self.head = f;
                        } else {
                            self.held = f;
                            self.waiting = 1;
                        }
                        self.kept += 1;
                        made += 1;
                    } else {
                        // Only the black behind a pixel whose lists are full gets here: it stays
                        // in this pixel, as its front at infinite depth.
                        self.front = Composite::EMPTY;
                        self.front.add(c, a);
                        self.front_z = z;
                        self.state = SHARP_CLOSED;
                    }
                }
            }
            // A front still open at the end lies over black already (nothing of the pixel behind).
            if self.k == self.slots && self.k == self.n && self.valid > 0 && self.through > 0.0 && self.state != SHARP_OPEN {
                self.slots += 1;
                self.backed = 1;
            }
            if made > 0 {
                return true;
            }
        }
        false
    }

    /// Whether the pixel has a sharp front (once the walk is done).
    #[inline]
    pub fn has_sharp(&self) -> bool {
        self.state == SHARP_OPEN || self.state == SHARP_CLOSED
    }
}

/// Per pixel: the sharp front and the input statistics. Unmerged (`cell` 1), also the pixel's
/// list fragments: into its region of the dense array ([`SplatParams::cell_region`]), their count
/// at `cells[i]` and their widest radius (f32 bits) at `cells[pixels + i]`, where
/// `splat_tile_count` reads them.
#[allow(clippy::too_many_arguments)]
pub fn pack_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &SplatParams,
    layers: R,
    counts: R,
    mut cells: M,
    mut sharp: M,
    mut dense: M,
    mut st: M,
) {
    let p = &super::planned(p, &st);
    let pixels = p.width * p.height;
    for_each_item(g, pixels, |i| {
        let mut w = PixelFragments::new(&counts, p, i);
        let (mut kept, mut capped) = (0u32, 0u32);
        let mut widest = 0.0f32;
        let region = p.cell_region(i);
        while w.advance(&layers, p) {
            // Merged, only the sharp front and the statistics are this pass's.
            if p.cell == 1 {
                w.head.store_in(p, &mut dense, region + kept);
                let (r, cut) = w.head.support(&p.lens, p.max_radius);
                widest = if r > widest { r } else { widest };
                capped += cut as u32;
            }
            kept += 1;
        }
        if w.has_sharp() {
            store_sharp(&mut sharp, i, w.front.color, w.front_z);
        } else {
            store_sharp(&mut sharp, i, [0.0; 3], f32::NAN);
        }
        if p.cell == 1 {
            cells.store(i, kept);
            cells.store(pixels + i, widest.to_bits());
            if capped > 0 {
                st.atomic_add(stats::CAPPED, capped);
            }
        }
        if w.n == 0 {
            st.atomic_add(stats::SKY, 1);
        }
        if w.has_sharp() {
            st.atomic_add(stats::SHARP, 1);
        }
        if w.backed > 0 {
            st.atomic_add(stats::BACKED, 1);
        }
        if w.hidden > 0 {
            st.atomic_add(stats::HIDDEN_SHARP, w.hidden);
        }
        if w.dropped > 0 {
            st.atomic_add(stats::DROPPED, w.dropped);
        }
        if w.clamped > 0 {
            st.atomic_add(stats::CLAMPED, w.clamped);
        }
        if w.alpha_clamped > 0 {
            st.atomic_add(stats::ALPHA_CLAMPED, w.alpha_clamped);
        }
    });
}

kernel!(
    /// Input slots → sharp fronts, and unmerged each pixel's list fragments, their count and widest
    /// radius.
    PACK = splat_pack [256] (SplatParams) { read layers, read counts, cells, sharp, dense, st } => pack_pass
);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exec::CpuMem;
    use crate::lens::ThinLens;
    use core::sync::atomic::AtomicU32;

    /// Four surfaces side by side, a sub-sample of a 2x2 grid each, at the composite's alphas 1/4,
    /// 1/3, 1/2 and 1: each spends a quarter of the pixel, with a quarter of its colour. Behind
    /// nearer slots, or without a footprint, a slot keeps its alpha.
    #[test]
    fn surfaces_side_by_side_spend_the_share_of_the_pixel_they_cover() {
        let (mut through, mut covered) = (1.0f32, 0u32);
        for k in 0..4 {
            let a = 1.0 / (4 - k) as f32;
            let (c, spent) = budget_share([a, 2.0 * a, 0.0], a, through, 1 << k, covered);
            assert!((spent - 0.25).abs() < 1e-6 && (c[0] - 0.25).abs() < 1e-6 && (c[1] - 0.5).abs() < 1e-6, "{k}: {c:?} {spent}");
            through *= 1.0 - a;
            covered |= 1 << k;
        }
        // A wall behind an edge covering two sub-samples: it shows in the other two, and is whole.
        assert_eq!(budget_share([0.3; 3], 1.0, 0.5, 0b1111, 0b0011), ([0.3; 3], 1.0));
        // Wholly behind the nearer slots, or without a footprint.
        assert_eq!(budget_share([0.3; 3], 1.0, 0.5, 0b0011, 0b0011), ([0.3; 3], 1.0));
        assert_eq!(budget_share([0.3; 3], 1.0, 0.5, footprint::WHOLE, 0b0011), ([0.3; 3], 1.0));
        // Beside a translucent slot's sub-samples: no more than its own alpha.
        assert_eq!(budget_share([0.3; 3], 0.6, 1.0, 0b0011, 0b1100), ([0.3; 3], 0.6));
    }

    /// A 1x1 frame with room for `layers` slots; depth 2 is in focus, 5 and the sky are blurred.
    fn params(layers: u32) -> SplatParams {
        let lens = ThinLens { focal_length: 0.05, aperture_radius: 0.02, focus_distance: 2.0, pixels_per_unit: 8000.0 };
        SplatParams { width: 1, height: 1, layers, cell: 1, max_radius: 16.0, lens, ..SplatParams::default() }
    }

    /// Pixel 0's list fragments (as yielded) and its cursor after the walk.
    fn walk(layers: u32, slots: &[Slot]) -> (Vec<Fragment>, PixelFragments) {
        let p = params(layers);
        let mut words: Vec<u32> = Vec::new();
        for k in 0..layers as usize {
            words.extend(slots.get(k).map_or([0; 5], |s| s.words()));
        }
        let words: Vec<AtomicU32> = words.into_iter().map(AtomicU32::new).collect();
        let count = [AtomicU32::new(slots.len() as u32)];
        let (layers, counts) = (CpuMem { words: &words, writable: false }, CpuMem { words: &count, writable: false });
        let mut w = PixelFragments::new(&counts, &p, 0);
        let mut out = Vec::new();
        while w.advance(&layers, &p) {
            out.push(w.head);
        }
        (out, w)
    }

    fn slot(c: f32, z: f32, alpha: f32) -> Slot {
        Slot { color: [c; 3], depth: z, alpha }
    }

    #[test]
    fn a_translucent_sharp_front_before_a_blurred_slot_joins_the_lists_as_one_chain_fragment() {
        let (f, w) = walk(4, &[slot(0.2, 2.0, 0.5), slot(0.1, 2.0, 0.5), slot(1.0, 5.0, 1.0), slot(0.3, 2.0, 1.0)]);
        assert_eq!(f.len(), 3, "{f:?}");
        // The "over" of the two in-focus slots, at the first one's depth: 0.2 + 0.5·0.1, alpha 0.75.
        assert_eq!((f[0].color, f[0].alpha, f[0].depth), ([0.25; 3], 0.75, 2.0));
        assert_eq!((f[1].color, f[1].depth), ([1.0; 3], 5.0));
        // After the flush, an in-focus slot goes to the lists too.
        assert_eq!((f[2].color, f[2].depth), ([0.3; 3], 2.0));
        assert!(!w.has_sharp());
        assert_eq!(w.backed, 0);
    }

    #[test]
    fn slots_that_end_translucent_get_black_behind_them() {
        let (f, w) = walk(4, &[slot(0.1, 5.0, 0.25)]);
        assert_eq!(f.len(), 2, "{f:?}");
        assert_eq!((f[1].color, f[1].alpha, f[1].depth), ([0.0; 3], 1.0, f32::INFINITY));
        assert_eq!(w.backed, 1);
        // A translucent sharp front with nothing behind it lies over black already: no fragment.
        let (f, w) = walk(4, &[slot(0.1, 2.0, 0.25)]);
        assert!(f.is_empty() && w.has_sharp() && w.backed == 0, "{f:?}");
    }

    #[test]
    fn an_opaque_sharp_front_hides_the_in_focus_slots_behind_it() {
        let (f, w) = walk(4, &[slot(0.5, 2.0, 1.0), slot(0.4, 2.0, 1.0), slot(1.0, 5.0, 1.0)]);
        assert_eq!(f.len(), 1, "{f:?}");
        assert_eq!(f[0].depth, 5.0);
        assert!(w.has_sharp());
        assert_eq!((w.hidden, w.backed), (1, 0));
    }

    #[test]
    fn the_black_behind_full_lists_stays_in_its_pixel_as_the_front() {
        let (f, w) = walk(2, &[slot(0.1, 5.0, 0.5), slot(0.2, 6.0, 0.5)]);
        assert_eq!(f.len(), 2, "{f:?}");
        assert!(w.has_sharp());
        assert_eq!((w.front_z, w.backed), (f32::INFINITY, 1));
    }
}
