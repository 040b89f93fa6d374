//! The splatting fragment: 16 bytes, the fields of Franke et al. 2018, Fig. 7, with the colour in a
//! shared-exponent format wide enough for any colour the numerical contract admits
//! ([`crate::radiance`]) and a coverage field.
//!
//! | word | bits 0-13 | bits 14-23 | bits 24-27 | bits 28-29 | bits 30-31 |
//! |---|---|---|---|---|---|
//! | 0 | red mantissa | green mantissa (bits 14-27) | | merge level | reserved (0) |
//! | 1 | blue mantissa | alpha (10 bits) | exponent (bits 24-31) | | |
//! | 2 | depth (f32) | | | | |
//! | 3 | x (bits 0-15, half pixels) | y (bits 16-31) | | | |
//!
//! Colour ([`encode_color`]): one exponent `E` for the three channels, the f32 exponent of the
//! largest channel (biased by 127, 8 bits), and three 14-bit mantissas `m` with `c = m · 2^(E−13)`:
//! the largest channel keeps a relative error of at most 2^-14 (6.1e-5; a half float's is 4.9e-4),
//! the others an absolute error of at most 2^-14 of the largest. Each fragment has its own exponent,
//! so a 1e12 highlight beside a 0.3 wall costs the wall nothing (the frame-wide colour scale this
//! replaces made it underflow). `E` spans [[`EXP_MIN`], [`EXP_MAX`]]: a colour whose largest channel
//! is below 2^-113 (9.6e-35) is stored as black, and [`crate::radiance::COLOR_MAX`] = 2^100 is the
//! largest. Encoding and decoding multiply by powers of two only, so they are exact and equal on
//! every backend.
//!
//! Alpha ([`encode_alpha`]): coverage in [0, 1] in 10 bits (steps of 1/1023; 0 and 1 exact), the
//! input slot's alpha ([`crate::slot`]). The colour is premultiplied by it, as in the input: the
//! fragment's energy is its colour, whatever the rounding of its alpha. Accumulation scales the
//! fragment's disc coverage by alpha ([`super::accumulate`]); merging keeps it (only fragments of
//! equal alpha merge, so a translucent fragment never joins an opaque one), and only an opaque
//! merged fragment drops what lies in its umbra.
//!
//! The position is the centre of the fragment's footprint in half-pixel units of the full-resolution
//! image (pixel `x` is centred at `2x + 1`; a merged 2x2 or 4x4 block at a pixel corner), so merged
//! fragments keep an exact position and images up to 32767 pixels wide fit. The merge level (0: one
//! pixel, 1: a 2x2 block, 2: 4x4) says how many pixels the fragment stands for, and how far its
//! members' circles reach beyond its own.
//!
//! Ties. A tile list is ordered by the key `(depth, dense index)`: the sort orders depths and is
//! stable, and `bin` gathers every list in increasing dense index (neighbour tiles in row-major
//! order, each tile's fragments in the dense array's order). The dense index orders fragments by
//! tile, then cell (row-major inside the tile), then slot: a function of the fragment's position,
//! merge level (which sets its cell) and layer alone, so equal depths resolve the same way on every
//! backend and schedule, and a frame recorded twice is equal to itself.
//!
//! The CoC is derived from depth on demand. A fragment is splatted over the disc of radius
//! `coc(depth)/2 + extent(level)`: the CoC widened by half the width of the block of pixels it stands
//! for, with a soft rim that wide ([`extent`], [`weight`]). A merged fragment carries the depth of the
//! member with the largest CoC, so its disc spans its members' (merging "to the largest circle",
//! §6.1). A disc of radius at most 1 reaches only the fragment's own pixel centre: such a fragment is
//! in focus.

use super::SplatParams;
use crate::aperture::Aperture;
use crate::exec::{Load, Mem};
use crate::footprint;
use crate::lane::{Lanes, Native as Row};
use crate::lens::ThinLens;
use crate::math::{ceil, floor};
use crate::radiance::clamp_color;

pub const WORDS: u32 = 4;
/// Bytes of a packed fragment.
pub const BYTES: u32 = 4 * WORDS;
/// Position units per pixel.
pub const POS_UNITS: u32 = 2;
/// Widest and tallest image the position field holds.
pub const MAX_EDGE: u32 = 0xffff / POS_UNITS;
pub const MAX_LEVEL: u32 = 2;

/// Bits of each colour mantissa (a channel equal to `2^E` has the mantissa `2^13`).
pub const MANTISSA_BITS: u32 = 14;
const MANTISSA_MASK: u32 = (1 << MANTISSA_BITS) - 1;
/// Range of the shared exponent (unbiased): `2^EXP_MAX` is `radiance::COLOR_MAX`.
pub const EXP_MIN: i32 = -113;
pub const EXP_MAX: i32 = 100;
/// Bits of alpha, and its largest code (alpha 1).
pub const ALPHA_BITS: u32 = 10;
const ALPHA_ONE: u32 = (1 << ALPHA_BITS) - 1;

/// `2^k` for `k` in [-126, 127].
#[inline]
fn pow2(k: i32) -> f32 {
    f32::from_bits(((k + 127) as u32) << 23)
}

/// A colour as three mantissas and a biased exponent (0 for black). The colour goes through
/// [`clamp_color`] first; a non-finite channel must not reach here (pack drops such slots).
#[inline]
pub fn encode_color(c: [f32; 3]) -> ([u32; 3], u32) {
    let c = clamp_color(c);
    let m = if c[0] > c[1] { c[0] } else { c[1] };
    let m = if m > c[2] { m } else { c[2] };
    if !(m >= pow2(EXP_MIN)) {
        return ([0; 3], 0);
    }
    let mut e = ((m.to_bits() >> 23) & 0xff) as i32 - 127;
    let mut out = [0u32; 3];
    // At most twice: rounding the largest mantissa up to 2^14 moves to the next exponent, where it
    // is exactly 2^13.
    let mut pass = 0;
    while pass < 2 {
        let s = pow2(13 - e);
        let mut top = 0;
        let mut i = 0;
        while i < 3 {
            out[i] = (c[i] * s + 0.5) as u32;
            top = if out[i] > top { out[i] } else { top };
            i += 1;
        }
        if top <= MANTISSA_MASK {
            break;
        }
        e += 1;
        pass += 1;
    }
    (out, (e + 127) as u32)
}

/// The colour of mantissas `m` and biased exponent `e`.
#[inline]
pub fn decode_color(m: [u32; 3], e: u32) -> [f32; 3] {
    if e == 0 {
        return [0.0; 3];
    }
    let s = pow2(e as i32 - 127 - 13);
    [m[0] as f32 * s, m[1] as f32 * s, m[2] as f32 * s]
}

/// Alpha in [0, 1] (NaN as 0) as its 10-bit code.
#[inline]
pub fn encode_alpha(a: f32) -> u32 {
    let a = if a > 1.0 {
        1.0
    } else if a > 0.0 {
        a
    } else {
        0.0
    };
    (a * ALPHA_ONE as f32 + 0.5) as u32
}

/// The alpha of code `a`: 0 and 1 exact.
#[inline]
pub fn decode_alpha(a: u32) -> f32 {
    if a >= ALPHA_ONE { 1.0 } else { a as f32 * (1.0 / ALPHA_ONE as f32) }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fragment {
    pub color: [f32; 3],
    /// Coverage in [0, 1]; the colour is premultiplied by it.
    pub alpha: f32,
    pub depth: f32,
    pub level: u32,
    /// Centre in half pixels.
    pub pos: [u32; 2],
    /// The sub-samples of its pixel it covers ([`crate::footprint`]; `WHOLE` for none given). Not
    /// in the 16 bytes: a frame with footprints keeps them in a word of their own per fragment
    /// ([`footprint_field`]), read by [`Fragment::load_in`].
    pub footprint: u32,
}

impl Fragment {
    /// An opaque one-pixel fragment at pixel `(x, y)`.
    #[inline]
    pub fn at_pixel(x: u32, y: u32, color: [f32; 3], depth: f32) -> Self {
        Fragment { color, alpha: 1.0, depth, level: 0, pos: [POS_UNITS * x + 1, POS_UNITS * y + 1], footprint: footprint::WHOLE }
    }

    /// The fragment with coverage `alpha` (its colour premultiplied by it).
    #[inline]
    pub fn with_alpha(self, alpha: f32) -> Self {
        Fragment { alpha, ..self }
    }

    /// The fragment with footprint `footprint`.
    #[inline]
    pub fn with_footprint(self, footprint: u32) -> Self {
        Fragment { footprint, ..self }
    }

    /// Whether it is splatted from its sub-samples ([`crate::footprint::weight`]).
    #[inline]
    pub fn has_footprint(&self) -> bool {
        self.footprint != footprint::WHOLE
    }

    /// Whether it hides everything behind it (its 10-bit alpha is 1).
    #[inline]
    pub fn is_opaque(&self) -> bool {
        self.alpha >= 1.0
    }

    #[inline]
    pub fn pack(&self) -> [u32; 4] {
        let (m, e) = encode_color(self.color);
        [
            m[0] | (m[1] << MANTISSA_BITS) | ((self.level & 3) << 28),
            m[2] | (encode_alpha(self.alpha) << MANTISSA_BITS) | (e << 24),
            self.depth.to_bits(),
            (self.pos[0] & 0xffff) | (self.pos[1] << 16),
        ]
    }

    #[inline(always)]
    pub fn unpack(w: [u32; 4]) -> Self {
        let m = [w[0] & MANTISSA_MASK, (w[0] >> MANTISSA_BITS) & MANTISSA_MASK, w[1] & MANTISSA_MASK];
        Fragment {
            color: decode_color(m, w[1] >> 24),
            alpha: decode_alpha((w[1] >> MANTISSA_BITS) & ALPHA_ONE),
            depth: f32::from_bits(w[2]),
            level: (w[0] >> 28) & 3,
            pos: [w[3] & 0xffff, w[3] >> 16],
            footprint: footprint::WHOLE,
        }
    }

    /// Whether fragment `index` of a buffer of packed fragments is opaque ([`Fragment::is_opaque`]),
    /// from its alpha's bits alone.
    #[inline]
    pub fn is_opaque_at(m: &impl Load, index: u32) -> bool {
        (m.load(WORDS * index + 1) >> MANTISSA_BITS) & ALPHA_ONE == ALPHA_ONE
    }

    /// Fragment `index` of a buffer of packed fragments.
    #[inline(always)]
    pub fn load(m: &impl Load, index: u32) -> Self {
        let b = WORDS * index;
        Self::unpack([m.load(b), m.load(b + 1), m.load(b + 2), m.load(b + 3)])
    }

    /// Fragment `index` of a frame's dense array, with its footprint where the frame has them.
    #[inline(always)]
    pub fn load_in(p: &SplatParams, m: &impl Load, index: u32) -> Self {
        let f = Self::load(m, index);
        let side = p.footprint_side();
        if side == 0 {
            return f;
        }
        let (word, shift, mask) = footprint_field(p, side, index);
        f.with_footprint((m.load(word) >> shift) & mask)
    }

    /// Stores it as fragment `index` of a frame's dense array, with its footprint where the frame
    /// has them (into a field the frame cleared: an add of disjoint bits, as neighbours share its
    /// word).
    #[inline]
    pub fn store_in<M: Mem>(&self, p: &SplatParams, m: &mut M, index: u32) {
        self.store(m, index);
        let side = p.footprint_side();
        if side > 0 && self.footprint != footprint::WHOLE {
            let (word, shift, mask) = footprint_field(p, side, index);
            m.atomic_add(word, (self.footprint & mask) << shift);
        }
    }

    #[inline]
    pub fn store<M: Mem>(&self, m: &mut M, index: u32) {
        let w = self.pack();
        let b = WORDS * index;
        m.store(b, w[0]);
        m.store(b + 1, w[1]);
        m.store(b + 2, w[2]);
        m.store(b + 3, w[3]);
    }

    /// Centre in pixels (pixel `x` spans `[x, x + 1)`).
    #[inline]
    pub fn centre(&self) -> [f32; 2] {
        [self.pos[0] as f32 * 0.5, self.pos[1] as f32 * 0.5]
    }

    /// Width of its soft rim, [`rim`].
    #[inline]
    pub fn rim(&self) -> f32 {
        rim(self.level)
    }

    /// Pixels the fragment stands for.
    #[inline]
    pub fn footprint(&self) -> f32 {
        (1u32 << (2 * self.level)) as f32
    }

    /// Radius in pixels of the disc the fragment is splatted over (its support): its CoC radius plus
    /// its [`extent`] (with a footprint, [`crate::footprint::REACH`]), capped at `cap`, and at least
    /// half a pixel (its own pixel).
    #[inline]
    pub fn radius(&self, lens: &ThinLens, cap: f32) -> f32 {
        self.support(lens, cap).0
    }

    /// Whether the radius was capped (for the report).
    #[inline]
    pub fn is_capped(&self, lens: &ThinLens, cap: f32) -> bool {
        self.support(lens, cap).1
    }

    /// [`Self::radius`] and [`Self::is_capped`] from one evaluation of the CoC.
    #[inline]
    pub fn support(&self, lens: &ThinLens, cap: f32) -> (f32, bool) {
        let reach = if self.has_footprint() { footprint::REACH } else { extent(self.level) };
        let r = lens.coc_radius_px(self.depth) + reach;
        let capped = r > cap;
        let r = if r < cap { r } else { cap };
        (if r > 0.5 { r } else { 0.5 }, capped)
    }
}

/// Bits a footprint of a `side × side` grid takes in the dense array: its sub-samples, rounded up
/// to a power of two (1, 4 or 16), so that fields never straddle words.
#[inline]
pub fn footprint_bits(side: u32) -> u32 {
    let n = side * side;
    if n <= 1 {
        1
    } else if n <= 4 {
        4
    } else {
        16
    }
}

/// Words a frame of `slots` input slots needs for its fragments' footprints on a `side` grid.
#[inline]
pub fn footprint_words(slots: u32, side: u32) -> u32 {
    let per_word = 32 / footprint_bits(side);
    slots.div_ceil(per_word)
}

/// Where a frame with footprints on a `side` grid keeps dense fragment `index`'s: word, shift and
/// mask of its [`footprint_bits`]-wide field, after the most fragments the frame can hold (every
/// cell region, [`SplatParams::dense_slots`]). The frame clears them before it packs.
#[inline]
pub fn footprint_field(p: &SplatParams, side: u32, index: u32) -> (u32, u32, u32) {
    let bits = footprint_bits(side);
    let per_word = 32 / bits;
    let mask = if bits >= 32 { u32::MAX } else { (1 << bits) - 1 };
    (footprint_base(p) + index / per_word, (index % per_word) * bits, mask)
}

/// The first word of a frame's footprint fields in the dense array.
#[inline]
pub fn footprint_base(p: &SplatParams) -> u32 {
    WORDS * p.dense_slots()
}

/// Depth of packed fragment `index` without decoding the rest.
#[inline]
pub fn depth_of(m: &impl Load, index: u32) -> f32 {
    f32::from_bits(m.load(WORDS * index + 2))
}

/// How far a fragment of `level` reaches beyond the CoC circle at its centre: half the edge of the
/// block of pixels it stands for (1, 2 or 4 pixels). A sensor, and the reference, integrate over a
/// pixel's area, so a CoC disc of radius `r` seen through a pixel spreads to `r + 1/2` with a soft
/// rim one pixel wide; a merged block spreads its members' discs the same way over its own width.
#[inline]
pub fn extent(level: u32) -> f32 {
    0.5 * (1u32 << level) as f32
}

/// Width of the soft rim of a fragment of `level`: its block's edge (see [`extent`]).
#[inline]
pub fn rim(level: u32) -> f32 {
    (1u32 << level) as f32
}

/// Support radius from which [`weight_sum`] switches from the exact lattice sum to its integral.
pub const EXACT_SUM_LIMIT: f32 = 4.0;

/// How much of a fragment with support radius `s` and rim width `w` a pixel centre at squared
/// distance `d2` receives, before normalisation: 1 inside `s − w`, falling linearly to 0 at `s`. This
/// is the CoC disc (radius `s − w/2`) seen through a box of the fragment's width, to first order: the
/// edge of a disc that covers half a pixel gives that pixel half a share, as the reference's integral
/// over the pixel area does. Per pixel (`V = f32`) or for several at once ([`crate::lane`]).
#[inline(always)]
pub fn weight<V: Lanes>(d2: V, s: V, w: V) -> V {
    let inner = s - w;
    let interior = V::splat(0.0).lt(inner) & d2.le(inner * inner);
    // `w` is a block's width, a power of two: multiplying by its reciprocal is the division,
    // exactly, and leaves the division off the chain from `d2`.
    V::select(interior, V::splat(1.0), unit_ramp((s - d2.sqrt()) * (V::splat(1.0) / w)))
}

/// The soft rim of [`weight`] at distance (or gauge) `d`: 1 up to `s − w`, falling linearly to 0 at
/// `s`. The ring gather's highlight discs use it too (`ring_gather::disc_weight`).
#[inline(always)]
pub fn linear_rim(d: f32, s: f32, w: f32) -> f32 {
    unit_ramp((s - d) / w)
}

/// `v` clamped to `[0, 1]` (0 for NaN).
#[inline(always)]
fn unit_ramp<V: Lanes>(v: V) -> V {
    let (zero, one) = (V::splat(0.0), V::splat(1.0));
    V::select(zero.lt(v), V::select(v.lt(one), v, one), zero)
}

/// [`weight`] for the aperture shape `ap` at offset `d` (pixel centre minus fragment centre, `d2`
/// its squared length): the circle's fast path; the shape's gauge in place of the distance; or a
/// mask's coverage at the offset over the CoC radius `s − w/2`. The offset is point-reflected
/// (`mirror = −1`) for a foreground fragment.
#[inline(always)]
pub fn shaped_weight<L: Load>(d: [f32; 2], d2: f32, s: f32, w: f32, ap: &Aperture, mirror: f32, mask: &L) -> f32 {
    if ap.is_circle() {
        return weight(d2, s, w);
    }
    let d = [mirror * d[0], mirror * d[1]];
    if ap.mask > 0 {
        let r = s - 0.5 * w;
        return if r > 0.0 { ap.coverage(mask, [d[0] / r, d[1] / r]) } else { 0.0 };
    }
    linear_rim(ap.gauge(d), s, w)
}

/// The sum of [`shaped_weight`] over every pixel centre (of an unbounded grid) around `c`: what a
/// fragment's weights are divided by, so that it spreads exactly its footprint's energy. Summed
/// exactly for small supports; from [`EXACT_SUM_LIMIT`] beyond the rim on, the integral: for the
/// analytic shapes `A/π · (π(s − w)² + π(s − w)w + πw²/3)` with `A` the unit shape's area (π for
/// the circle), for a mask `A·r²` with `r = s − w/2`; the lattice sum matches either to well under
/// a percent there.
#[inline(always)]
pub fn weight_sum<L: Load>(c: [f32; 2], s: f32, w: f32, ap: &Aperture, mirror: f32, mask: &L) -> f32 {
    if s >= EXACT_SUM_LIMIT + w {
        if ap.mask > 0 {
            let r = s - 0.5 * w;
            return ap.area * r * r;
        }
        let inner = s - w;
        return ap.area * (inner * inner + inner * w + w * w / 3.0);
    }
    // A row's weights a lane per pixel (eight on the CPU, one on the GPU), added in the row's
    // order: the same sum, bit for bit. A lane past the row's end weighs +0, which adds nothing.
    let mut sum = 0.0;
    let mut y = ceil(c[1] - s - 0.5);
    let y_end = floor(c[1] + s - 0.5);
    let x_start = ceil(c[0] - s - 0.5);
    let x_end = floor(c[0] + s - 0.5);
    let step = Row::from_fn(|l| l as f32);
    while y <= y_end {
        let dy = y + 0.5 - c[1];
        let mut x = x_start;
        while x <= x_end {
            let xs = Row::splat(x) + step;
            let inside = xs.le(Row::splat(x_end));
            let dx = xs + Row::splat(0.5) - Row::splat(c[0]);
            let d2 = dx * dx + Row::splat(dy * dy);
            let wt = if ap.is_circle() {
                weight(d2, Row::splat(s), Row::splat(w))
            } else {
                Row::from_fn(|l| shaped_weight([dx.lane(l), dy], d2.lane(l), s, w, ap, mirror, mask))
            };
            let wt = Row::select(inside, wt, Row::splat(0.0));
            let mut l = 0;
            while l < Row::N {
                sum += wt.lane(l);
                l += 1;
            }
            x += Row::N as f32;
        }
        y += 1.0;
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::radiance::COLOR_MAX;

    fn round_trip(f: Fragment) -> Fragment {
        Fragment::unpack(f.pack())
    }

    #[test]
    fn fields_round_trip() {
        let f = Fragment { color: [0.5, 2.0, 7.0], alpha: 1.0, depth: 3.25, level: 2, pos: [65535, 1234], footprint: 0 };
        let g = round_trip(f);
        assert_eq!((g.alpha, g.depth, g.level, g.pos), (1.0, 3.25, 2, [65535, 1234]));
        // Dyadic values with few bits are exact.
        assert_eq!(g.color, [0.5, 2.0, 7.0]);
        assert_eq!(f.pack()[0] >> 30, 0, "reserved bits stay 0");
    }

    /// The largest channel keeps 2^-14 relative precision from 2^-113 up to COLOR_MAX; the others
    /// 2^-14 of the largest in absolute terms.
    #[test]
    fn colour_precision_over_the_whole_range() {
        let mut v = 1.1e-34f32;
        while v <= COLOR_MAX {
            for c in [[v, 0.3 * v, 0.01 * v], [0.7 * v, v, 0.0], [0.0, 0.0, v]] {
                let g = round_trip(Fragment::at_pixel(0, 0, c, 1.0)).color;
                let top = c.iter().copied().fold(0.0f32, f32::max);
                for i in 0..3 {
                    let err = (g[i] - c[i]).abs();
                    assert!(err <= top * (1.0 / 16384.0) * 1.0001, "{c:?} -> {g:?}");
                    if c[i] == top {
                        assert!(err <= top * (1.0 / 16384.0) * 1.0001);
                    }
                }
            }
            v *= 7.3;
        }
    }

    #[test]
    fn colour_limits() {
        let enc = |c: [f32; 3]| round_trip(Fragment::at_pixel(0, 0, c, 1.0)).color;
        assert_eq!(enc([f32::MAX, 3e38, 1e38]), [COLOR_MAX; 3]);
        assert_eq!(enc([COLOR_MAX, 0.0, 0.0]), [COLOR_MAX, 0.0, 0.0]);
        assert_eq!(enc([0.0; 3]), [0.0; 3]);
        assert_eq!(enc([1e-40, 1e-36, 0.0]), [0.0; 3], "below 2^-113: black");
        assert_eq!(enc([-1.0, 0.5, 0.25]), [0.0, 0.5, 0.25], "negative channels are 0");
        // Rounding up to the next exponent: 2^14 − 0.25 units of 2^-13.
        let just_below = 2.0 - 1.0 / 32768.0;
        assert_eq!(enc([just_below, 1.0, 0.0]), [2.0, 1.0, 0.0]);
        // 1e12 beside 0.3 in separate fragments: each keeps its own precision.
        let big = enc([1e12, 1e12, 1e12])[0];
        let dim = enc([0.3, 0.3, 0.3])[0];
        assert!((big / 1e12 - 1.0).abs() < 1e-4 && (dim / 0.3 - 1.0).abs() < 1e-4);
    }

    #[test]
    fn encoding_is_exact_and_stable() {
        // Decoding then encoding again changes nothing: a merged or re-packed fragment does not
        // drift.
        for i in 0..2000u32 {
            let v = f32::from_bits(0x0d00_0000 + i.wrapping_mul(2_654_435_761) % 0x6000_0000);
            let c = [v, 0.37 * v, 0.001 * v];
            let once = round_trip(Fragment::at_pixel(1, 2, c, 1.0));
            assert_eq!(round_trip(once), once, "{c:?}");
        }
    }

    #[test]
    fn alpha_codes() {
        assert_eq!(decode_alpha(encode_alpha(1.0)), 1.0);
        assert_eq!(decode_alpha(encode_alpha(0.0)), 0.0);
        assert_eq!(decode_alpha(encode_alpha(f32::NAN)), 0.0);
        assert_eq!(decode_alpha(encode_alpha(7.0)), 1.0);
        assert_eq!(decode_alpha(encode_alpha(-1.0)), 0.0);
        for k in 0..=100 {
            let a = k as f32 / 100.0;
            let g = round_trip(Fragment { alpha: a, ..Fragment::at_pixel(3, 4, [1.0; 3], 2.0) });
            assert!((g.alpha - a).abs() <= 0.5 / 1023.0 + 1e-7, "{a} -> {}", g.alpha);
            assert_eq!((g.color, g.depth, g.level, g.pos), ([1.0; 3], 2.0, 0, [7, 9]));
        }
    }

    #[test]
    fn every_field_has_its_own_bits() {
        let base = Fragment { color: [1.0, 2.0, 3.0], alpha: decode_alpha(600), depth: 4.0, level: 1, pos: [10, 20], footprint: 0 };
        let variants = [
            Fragment { color: [1.5, 2.0, 3.0], ..base },
            Fragment { color: [1.0, 2.5, 3.0], ..base },
            Fragment { color: [1.0, 2.0, 3.5], ..base },
            Fragment { color: [2.0, 4.0, 6.0], ..base },
            Fragment { alpha: decode_alpha(300), ..base },
            Fragment { depth: 5.0, ..base },
            Fragment { level: 2, ..base },
            Fragment { pos: [11, 20], ..base },
            Fragment { pos: [10, 21], ..base },
        ];
        for v in variants {
            let g = round_trip(v);
            assert_eq!(g, v, "{v:?}");
            assert_ne!(v.pack(), base.pack());
        }
        assert_eq!(round_trip(base), base);
        assert_eq!(BYTES, 16);
    }
}
