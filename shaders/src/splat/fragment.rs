//! The splatting fragment: 16 bytes, laid out as Franke et al. 2018, Fig. 7.
//!
//! | word | bits 0-15 | bits 16-31 |
//! |---|---|---|
//! | 0 | red (f16) | green (f16) |
//! | 1 | merge level | blue (f16) |
//! | 2 | depth (f32) | |
//! | 3 | x (half pixels) | y (half pixels) |
//!
//! The position is the centre of the fragment's footprint in half-pixel units of the full-resolution
//! image (pixel `x` is centred at `2x + 1`; a merged 2x2 or 4x4 block at a pixel corner), so merged
//! fragments keep an exact position and images up to 32767 pixels wide fit. The merge level (0: one
//! pixel, 1: a 2x2 block, 2: 4x4) says how many pixels the fragment stands for, and how far its
//! members' circles reach beyond its own.
//!
//! The CoC is derived from depth on demand. A fragment is splatted over the disc of radius
//! `coc(depth)/2 + extent(level)`: the CoC widened by half the width of the block of pixels it stands
//! for, with a soft rim that wide ([`extent`], [`weight`]). A merged fragment carries the depth of the
//! member with the largest CoC, so its disc spans its members' (merging "to the largest circle",
//! §6.1). A disc of radius at most 1 reaches only the fragment's own pixel centre: such a fragment is
//! in focus.

use crate::aperture::Aperture;
use crate::exec::{Load, Mem};
use crate::half::{HALF_MAX, f16_to_f32, f32_to_f16};
use crate::lens::ThinLens;
use crate::math::{ceil, floor, sqrt};

pub const WORDS: u32 = 4;
/// Position units per pixel.
pub const POS_UNITS: u32 = 2;
/// Widest and tallest image the position field holds.
pub const MAX_EDGE: u32 = 0xffff / POS_UNITS;
pub const MAX_LEVEL: u32 = 2;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fragment {
    pub color: [f32; 3],
    pub depth: f32,
    pub level: u32,
    /// Centre in half pixels.
    pub pos: [u32; 2],
}

impl Fragment {
    /// A one-pixel fragment at pixel `(x, y)`.
    #[inline]
    pub fn at_pixel(x: u32, y: u32, color: [f32; 3], depth: f32) -> Self {
        Fragment { color, depth, level: 0, pos: [POS_UNITS * x + 1, POS_UNITS * y + 1] }
    }

    #[inline]
    pub fn pack(&self) -> [u32; 4] {
        let h = |c: f32| f32_to_f16(clamp_half(c));
        [
            h(self.color[0]) | (h(self.color[1]) << 16),
            (self.level & 0xffff) | (h(self.color[2]) << 16),
            self.depth.to_bits(),
            (self.pos[0] & 0xffff) | (self.pos[1] << 16),
        ]
    }

    #[inline]
    pub fn unpack(w: [u32; 4]) -> Self {
        Fragment {
            color: [f16_to_f32(w[0] & 0xffff), f16_to_f32(w[0] >> 16), f16_to_f32(w[1] >> 16)],
            depth: f32::from_bits(w[2]),
            level: w[1] & 0xffff,
            pos: [w[3] & 0xffff, w[3] >> 16],
        }
    }

    /// Fragment `index` of a buffer of packed fragments.
    #[inline]
    pub fn load<M: Mem>(m: &M, index: u32) -> Self {
        let b = WORDS * index;
        Self::unpack([m.load(b), m.load(b + 1), m.load(b + 2), m.load(b + 3)])
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
    /// its [`extent`], capped at `cap`, and at least half a pixel (its own pixel).
    #[inline]
    pub fn radius(&self, lens: &ThinLens, cap: f32) -> f32 {
        let r = lens.coc_radius_px(self.depth) + extent(self.level);
        let r = if r < cap { r } else { cap };
        if r > 0.5 { r } else { 0.5 }
    }

    /// Whether the radius was capped (for the report).
    #[inline]
    pub fn is_capped(&self, lens: &ThinLens, cap: f32) -> bool {
        lens.coc_radius_px(self.depth) + extent(self.level) > cap
    }
}

/// Depth of packed fragment `index` without decoding the rest.
#[inline]
pub fn depth_of<M: Mem>(m: &M, index: u32) -> f32 {
    f32::from_bits(m.load(WORDS * index + 2))
}

/// `c` clamped to the finite half-float range.
#[inline]
pub fn clamp_half(c: f32) -> f32 {
    if c > HALF_MAX {
        HALF_MAX
    } else if c < -HALF_MAX {
        -HALF_MAX
    } else {
        c
    }
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
/// over the pixel area does.
#[inline]
pub fn weight(d2: f32, s: f32, w: f32) -> f32 {
    let inner = s - w;
    if inner > 0.0 && d2 <= inner * inner {
        return 1.0;
    }
    let v = (s - sqrt(d2)) / w;
    if v > 0.0 { if v < 1.0 { v } else { 1.0 } } else { 0.0 }
}

/// [`weight`] for the aperture shape `ap` at offset `d` (pixel centre minus fragment centre, `d2`
/// its squared length): the circle's fast path; the shape's gauge in place of the distance; or a
/// mask's coverage at the offset over the CoC radius `s − w/2`. The offset is point-reflected
/// (`mirror = −1`) for a foreground fragment.
#[inline]
pub fn shaped_weight<L: Load>(d: [f32; 2], d2: f32, s: f32, w: f32, ap: &Aperture, mirror: f32, mask: &L) -> f32 {
    if ap.is_circle() {
        return weight(d2, s, w);
    }
    let d = [mirror * d[0], mirror * d[1]];
    if ap.mask > 0 {
        let r = s - 0.5 * w;
        return if r > 0.0 { ap.coverage(mask, [d[0] / r, d[1] / r]) } else { 0.0 };
    }
    let v = (s - ap.gauge(d)) / w;
    if v > 0.0 { if v < 1.0 { v } else { 1.0 } } else { 0.0 }
}

/// The sum of [`shaped_weight`] over every pixel centre (of an unbounded grid) around `c`: what a
/// fragment's weights are divided by, so that it spreads exactly its footprint's energy. Summed
/// exactly for small supports; from [`EXACT_SUM_LIMIT`] beyond the rim on, the integral: for the
/// analytic shapes `A/π · (π(s − w)² + π(s − w)w + πw²/3)` with `A` the unit shape's area (π for
/// the circle), for a mask `A·r²` with `r = s − w/2`; the lattice sum matches either to well under
/// a percent there.
#[inline]
pub fn weight_sum<L: Load>(c: [f32; 2], s: f32, w: f32, ap: &Aperture, mirror: f32, mask: &L) -> f32 {
    if s >= EXACT_SUM_LIMIT + w {
        if ap.mask > 0 {
            let r = s - 0.5 * w;
            return ap.area * r * r;
        }
        let inner = s - w;
        return ap.area * (inner * inner + inner * w + w * w / 3.0);
    }
    let mut sum = 0.0;
    let mut y = ceil(c[1] - s - 0.5);
    let y_end = floor(c[1] + s - 0.5);
    while y <= y_end {
        let dy = y + 0.5 - c[1];
        let mut x = ceil(c[0] - s - 0.5);
        let x_end = floor(c[0] + s - 0.5);
        while x <= x_end {
            let dx = x + 0.5 - c[0];
            sum += shaped_weight([dx, dy], dx * dx + dy * dy, s, w, ap, mirror, mask);
            x += 1.0;
        }
        y += 1.0;
    }
    sum
}
