//! The layer input's fragment slot (the frame API's `FrameInput::Layers`, the peels' output, the
//! input every method reads), and the front-to-back "over" of a pixel's slots.
//!
//! A slot is 5 words, 20 bytes:
//!
//! | word | field |
//! |---|---|
//! | 0, 1, 2 | red, green, blue (f32), **premultiplied** by alpha |
//! | 3 | planar view depth (f32; `+inf` for the background) |
//! | 4 | alpha (f32): the share of the pixel the fragment covers and hides, in [0, 1] |
//!
//! Premultiplied, as OpenEXR and glTF's "over" have it: the colour words are the light the fragment
//! sends towards the camera, alpha is what it hides of what lies behind. So a sub-pixel emitter is a
//! fragment whose colour is its energy and whose alpha is its coverage, an alpha of 0 with a colour
//! is light that hides nothing (emission), and an opaque fragment (alpha 1) holds its colour as it
//! was before alpha existed: an opaque input is the same bits as the 4-word slot it replaces, plus
//! the word 1.0.
//!
//! A pixel's slots lie front to back and are composited over **black**: where the last one is
//! translucent, what it lets through is black (as a pixel with no slot at all is black at infinite
//! depth).
//!
//! Alpha outside [0, 1] is clamped and NaN read as 0 ([`clamp_alpha`]); every method that reads
//! alpha counts what the clamp changed ([`is_alpha_clamped`]).

use crate::exec::{Load, Mem};
use crate::lens::{is_finite, is_positive};

/// Words of one slot.
pub const SLOT_WORDS: u32 = 5;
/// Word of the depth within a slot.
pub const DEPTH_WORD: u32 = 3;
/// Word of alpha within a slot.
pub const ALPHA_WORD: u32 = 4;

/// One slot as read: colour premultiplied by alpha, depth, alpha (as stored, not yet clamped).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slot {
    pub color: [f32; 3],
    pub depth: f32,
    pub alpha: f32,
}

impl Slot {
    /// An opaque slot.
    #[inline]
    pub fn opaque(color: [f32; 3], depth: f32) -> Self {
        Slot { color, depth, alpha: 1.0 }
    }

    /// The slot's words, in the layout above.
    #[inline]
    pub fn words(&self) -> [u32; 5] {
        [self.color[0].to_bits(), self.color[1].to_bits(), self.color[2].to_bits(), self.depth.to_bits(), self.alpha.to_bits()]
    }
}

/// Slot `index` (pixel · layers + layer) of a buffer of slots.
#[inline]
pub fn load(m: &impl Load, index: u32) -> Slot {
    let b = SLOT_WORDS * index;
    Slot {
        color: [f32::from_bits(m.load(b)), f32::from_bits(m.load(b + 1)), f32::from_bits(m.load(b + 2))],
        depth: f32::from_bits(m.load(b + DEPTH_WORD)),
        alpha: f32::from_bits(m.load(b + ALPHA_WORD)),
    }
}

/// The depth of slot `index`, without reading the rest.
#[inline]
pub fn depth_of(m: &impl Load, index: u32) -> f32 {
    f32::from_bits(m.load(SLOT_WORDS * index + DEPTH_WORD))
}

/// The alpha of slot `index`, without reading the rest.
#[inline]
pub fn alpha_of(m: &impl Load, index: u32) -> f32 {
    f32::from_bits(m.load(SLOT_WORDS * index + ALPHA_WORD))
}

/// Writes slot `index`.
#[inline]
pub fn store<M: Mem>(m: &mut M, index: u32, s: Slot) {
    let b = SLOT_WORDS * index;
    m.store(b, s.color[0].to_bits());
    m.store(b + 1, s.color[1].to_bits());
    m.store(b + 2, s.color[2].to_bits());
    m.store(b + DEPTH_WORD, s.depth.to_bits());
    m.store(b + ALPHA_WORD, s.alpha.to_bits());
}

/// A straight colour premultiplied by `alpha`; an opaque colour's bits unchanged.
#[inline]
pub fn premultiply(rgb: [f32; 3], alpha: f32) -> [f32; 3] {
    if alpha == 1.0 { rgb } else { [rgb[0] * alpha, rgb[1] * alpha, rgb[2] * alpha] }
}

/// Alpha as the methods read it: NaN as 0 (the fragment's colour still adds, it hides nothing),
/// below 0 as 0, above 1 as 1; the rest bit for bit.
#[inline]
pub fn clamp_alpha(a: f32) -> f32 {
    if a > 1.0 {
        1.0
    } else if a >= 0.0 {
        a
    } else {
        0.0
    }
}

/// Whether [`clamp_alpha`] changes `a` (NaN, negative, above 1): counted, never silent.
#[inline]
pub fn is_alpha_clamped(a: f32) -> bool {
    !(a >= 0.0 && a <= 1.0)
}

/// "Over": `back` behind `front`, both premultiplied (clamped alphas); `front`'s depth is kept. The
/// area resolve merges clusters beyond its layers with it, and the ray caster what lies behind a
/// full pixel's translucent last slot.
#[inline]
pub fn over(front: Slot, back: Slot) -> Slot {
    let t = 1.0 - front.alpha;
    Slot {
        color: [front.color[0] + t * back.color[0], front.color[1] + t * back.color[1], front.color[2] + t * back.color[2]],
        alpha: front.alpha + t * back.alpha,
        depth: front.depth,
    }
}

/// The front-to-back "over" of premultiplied fragments (Porter, Duff 1984): the colour gathered
/// and the share of light that still passes (1 at the start, 0 once an opaque fragment is added).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Composite {
    pub color: [f32; 3],
    pub transmit: f32,
}

impl Composite {
    pub const EMPTY: Composite = Composite { color: [0.0; 3], transmit: 1.0 };

    /// Adds a fragment of premultiplied colour `c` and (clamped) alpha `a` behind what is there.
    /// Nothing is added once the composite is opaque, so an opaque front fragment gives its colour
    /// bit for bit, whatever lies behind.
    #[inline]
    pub fn add(&mut self, c: [f32; 3], a: f32) {
        let t = self.transmit;
        if self.is_empty() {
            // The first fragment (or one behind fragments that added nothing): its bits as they are.
            self.color = c;
            self.transmit = 1.0 - a;
        } else if t > 0.0 {
            self.color = [self.color[0] + t * c[0], self.color[1] + t * c[1], self.color[2] + t * c[2]];
            self.transmit = t * (1.0 - a);
        }
    }

    /// Whether nothing was added yet (or only fragments that add nothing and hide nothing).
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.transmit >= 1.0 && self.color[0] == 0.0 && self.color[1] == 0.0 && self.color[2] == 0.0
    }

    /// Its alpha (coverage).
    #[inline]
    pub fn alpha(&self) -> f32 {
        1.0 - self.transmit
    }
}

/// Whether a slot is read at all: finite colour and positive depth (the rest is dropped and counted
/// by the methods, never spread).
#[inline]
pub fn is_valid(s: &Slot) -> bool {
    is_finite(s.color[0]) && is_finite(s.color[1]) && is_finite(s.color[2]) && is_positive(s.depth)
}

/// Whether a pixel's `n` slots (`slot_at(k)`) end translucent: some slot is valid and their "over"
/// still lets light through. Black lies behind them then, as an opaque background at infinite
/// depth that every method adds (a pixel composites over black).
#[inline]
pub fn ends_translucent(n: u32, slot_at: impl Fn(u32) -> Slot) -> bool {
    let mut through = 1.0f32;
    let mut valid = false;
    let mut k = 0;
    while k < n {
        let s = slot_at(k);
        if is_valid(&s) {
            valid = true;
            through *= 1.0 - clamp_alpha(s.alpha);
        }
        k += 1;
    }
    valid && through > 0.0
}

/// A pixel's `n` slots (`slot_at(k)`, front to back) flattened to one colour and one depth: the
/// "over" of its valid slots over black at the depth of the front valid one (what a pinhole camera
/// sees, and the single-layer methods' input; an opaque front slot gives its own colour and depth
/// bit for bit). No slot: black at infinite depth. No valid slot: the front slot as it is (the
/// methods then drop it).
#[inline]
pub fn flatten(n: u32, slot_at: impl Fn(u32) -> Slot) -> ([f32; 3], f32) {
    if n == 0 {
        return ([0.0; 3], f32::INFINITY);
    }
    let mut over = Composite::EMPTY;
    let mut depth = f32::NAN;
    let mut k = 0;
    while k < n && over.transmit > 0.0 {
        let s = slot_at(k);
        if is_valid(&s) {
            if !(depth > 0.0) {
                depth = s.depth;
            }
            over.add(s.color, clamp_alpha(s.alpha));
        }
        k += 1;
    }
    if !(depth > 0.0) {
        let s = slot_at(0);
        return (s.color, s.depth);
    }
    (over.color, depth)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn over_of_the_issue_cases() {
        // Two layers: premultiplied (0.8, 0.4, 0.2) at alpha 0.5 over an opaque (0.1, 0.9, 0.1).
        let mut c = Composite::EMPTY;
        c.add([0.8, 0.4, 0.2], 0.5);
        c.add([0.1, 0.9, 0.1], 1.0);
        for (got, want) in c.color.iter().zip([0.85, 0.85, 0.25]) {
            assert!((got - want).abs() < 1e-6, "{:?}", c.color);
        }
        assert_eq!(c.transmit, 0.0);
        // An opaque front: its colour bit for bit, whatever lies behind (even an infinite colour).
        let mut c = Composite::EMPTY;
        c.add([0.3, 0.7, 1e30], 1.0);
        c.add([f32::INFINITY, 1.0, 1.0], 1.0);
        assert_eq!(c.color, [0.3, 0.7, 1e30]);
        // 100 panes of alpha 0.01: 1 − 0.99^100 of them.
        let mut c = Composite::EMPTY;
        for _ in 0..100 {
            c.add([0.01, 0.0, 0.0], 0.01);
        }
        assert!((c.alpha() - (1.0 - 0.99f32.powi(100))).abs() < 1e-5 && (c.color[0] - c.alpha()).abs() < 1e-5);
    }

    #[test]
    fn alpha_clamp() {
        assert_eq!(clamp_alpha(f32::NAN), 0.0);
        assert_eq!(clamp_alpha(-0.5), 0.0);
        assert_eq!(clamp_alpha(1.5), 1.0);
        assert_eq!(clamp_alpha(f32::INFINITY), 1.0);
        assert_eq!(clamp_alpha(0.25), 0.25);
        assert!(is_alpha_clamped(f32::NAN) && is_alpha_clamped(-1e-30) && is_alpha_clamped(1.0001));
        assert!(!is_alpha_clamped(0.0) && !is_alpha_clamped(1.0) && !is_alpha_clamped(0.5));
    }
}
