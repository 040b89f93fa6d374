//! Which fragments of a pixel's walk belong to one surface, and how surfaces combine: coverage adds
//! within a surface, surfaces composite ("over").
//!
//! The coverage budget of [`super::accumulate`] adds the coverage of every fragment that reaches a
//! pixel. That is right within one surface: the blurred fragments of one surface tile the pixel
//! (their disc shares sum to about 1), so they must not attenuate each other. Across different
//! translucent surfaces it is wrong: two panes of alpha 0.35 and 0.6 in front of a wall hide
//! 0.95 of it by the budget and 0.74 by compositing, and 100 panes of alpha 0.01 hide all of it
//! where 0.99^100 = 37% gets through.
//!
//! A pixel's fragments arrive sorted by depth. A fragment starts a new surface when it lies more
//! than [`DEPTH_GAP`] behind the previous fragment the pixel took (a gap in depth, chained so that a
//! surface at an angle stays one surface), or when more than half its disc share would take the
//! current surface's summed shares past [`SHARE_MAX`] (one surface covers a pixel at most once: more
//! share at the same depth is another surface, as in a stack of panes; the half assigns a fragment
//! to the surface where most of it lies, so the split is unbiased). A translucent fragment whose
//! surface lies behind a wholly translucent one (no opaque fragment among what the pixel took of
//! it) is scaled by the coverage left when its surface began: a pane behind another pane is seen
//! through it (transmittance multiplies) instead of only filling what the nearer one's alpha left
//! of the budget. A fragment with a partial footprint ([`crate::footprint`]) is coverage, not a
//! pane: it counts as opaque here (seen through each other, the side-by-side parts of a floor
//! receding to the horizon, each at partial alpha and a surface of its own, came out up to 0.09
//! darker on the texture check, `tools/texture_check.py`).
//!
//! Everything else keeps the budget (coverage spent front to back, unscaled). Opaque fragments fill
//! what the nearer surfaces leave, even where some hidden layers are missing; and behind a surface
//! with opaque fragments, partial alpha is most likely coverage (area-integrated layers give an
//! opaque surface's edge pixels partial alpha) whose nearer occluder is anti-correlated with it, as
//! the budget assumes. Scaling every translucent fragment by its surface's rest cost 1.9 dB in
//! `columns`' region with area-integrated layers (a far column's edge came out darker); scaling
//! only behind wholly translucent surfaces is what is left. So an input without translucent
//! fragments gives the same image, bit for bit. What this leaves out: a pane behind a partly
//! covering opaque surface, or an opaque surface partly covering behind a pane, takes its share
//! unscaled, as before.

use crate::lane::{LaneMask, Lanes};

/// Relative depth step beyond which the next fragment is another surface (as the area-integrated
/// layers cluster depths within 5%, [`crate::resolve`]).
pub const DEPTH_GAP: f32 = 1.05;
/// Most summed disc share one surface gives a pixel: a surface covers a pixel once.
pub const SHARE_MAX: f32 = 1.0;

/// What a fragment of disc share `w` and alpha `alpha` takes of a pixel that has `rest` coverage
/// left: the factor its premultiplied colour is added with, and the coverage it spends. Its
/// coverage `w·α` while that fits; otherwise the rest, with its colour scaled to match (`rest/α`,
/// below `w`). An opaque fragment takes `min(w, rest)` for both, bit for bit as before alpha.
#[inline(always)]
pub fn take<V: Lanes>(w: V, alpha: f32, rest: V) -> (V, V) {
    let wa = w * V::splat(alpha);
    let fits = wa.lt(rest);
    // `rest / 1` is `rest`: an opaque fragment (the common case) skips the division.
    let scaled = if alpha == 1.0 { rest } else { rest / V::splat(alpha) };
    (V::select(fits, w, scaled), V::select(fits, wa, rest))
}

/// A pixel's walk between surfaces (or several pixels', [`crate::lane`]).
#[derive(Clone, Copy)]
pub struct Surfaces<V: Lanes> {
    /// Depth of the last fragment taken (NaN: none yet).
    pub last_z: V,
    /// Summed disc share of the current surface's fragments.
    pub share: V,
    /// Coverage left when the current surface began: the factor its translucent fragments are
    /// scaled by when [`Surfaces::see_through`].
    pub rest: V,
    /// The current surface has an opaque fragment (before the first: true, nothing to see through).
    pub opaque: V::Mask,
    /// The current surface lies behind a wholly translucent one.
    pub see_through: V::Mask,
}

impl<V: Lanes> Surfaces<V> {
    /// Before the first fragment.
    #[inline(always)]
    pub fn start() -> Surfaces<V> {
        Surfaces {
            last_z: V::splat(f32::NAN),
            share: V::splat(0.0),
            rest: V::splat(1.0),
            opaque: V::Mask::splat(true),
            see_through: V::Mask::splat(false),
        }
    }

    /// What a fragment of disc share `w`, alpha `alpha` and depth `z` takes of the pixels `hit` that
    /// have spent `used` of their coverage: the factor its premultiplied colour is added with and
    /// the coverage it spends ([`take`], on its share scaled by its surface's rest where it is seen
    /// through a translucent surface). `coverage`: its alpha is the share of its pixel it covers
    /// (it has a partial footprint: an edge, or one of surfaces side by side), not a pane's, so it
    /// takes its share unscaled and its surface is not one to see through. The other pixels' state
    /// stays as it was.
    #[inline(always)]
    pub fn take(&mut self, hit: V::Mask, w: V, alpha: f32, coverage: bool, z: f32, used: V) -> (V, V) {
        let rest = V::splat(1.0) - used;
        // `!(z <= ..)`: the first fragment (NaN) starts a surface too.
        let new = !V::splat(z).le(self.last_z * V::splat(DEPTH_GAP)) | V::splat(SHARE_MAX).lt(self.share + V::splat(0.5) * w);
        let see_through = new.pick(!self.opaque, self.see_through);
        let opaque = !new & self.opaque;
        let surface_rest = V::select(new, rest, self.rest);
        let share = V::select(new, V::splat(0.0), self.share) + w;
        let (taken, opaque) = if alpha < 1.0 && !coverage {
            (take(w * V::select(see_through, surface_rest, V::splat(1.0)), alpha, rest), opaque)
        } else {
            (take(w, alpha, rest), V::Mask::splat(true))
        };
        self.last_z = V::select(hit, V::splat(z), self.last_z);
        self.share = V::select(hit, share, self.share);
        self.rest = V::select(hit, surface_rest, self.rest);
        self.opaque = hit.pick(opaque, self.opaque);
        self.see_through = hit.pick(see_through, self.see_through);
        taken
    }
}

/// Words of workgroup memory a pixel's [`Surfaces`] takes, one field every `stride` words from
/// `base` (the walk keeps it between chunks).
pub const WORDS: usize = 4;

impl<V: Lanes> Surfaces<V> {
    /// The state of pixels `i .. i + V::N`.
    #[inline]
    pub fn load<const N: usize>(sh: &[u32; N], base: usize, stride: usize, i: u32) -> Surfaces<V> {
        let i = base + i as usize;
        let word = |f: usize, l: usize| sh[i + f * stride + l];
        Surfaces {
            last_z: V::from_fn(|l| f32::from_bits(word(0, l))),
            share: V::from_fn(|l| f32::from_bits(word(1, l))),
            rest: V::from_fn(|l| f32::from_bits(word(2, l))),
            opaque: V::Mask::from_fn(|l| word(3, l) & 1 != 0),
            see_through: V::Mask::from_fn(|l| word(3, l) & 2 != 0),
        }
    }

    #[inline]
    pub fn store<const N: usize>(self, sh: &mut [u32; N], base: usize, stride: usize, i: u32) {
        let i = base + i as usize;
        let mut l = 0;
        while l < V::N {
            sh[i + l] = self.last_z.lane(l).to_bits();
            sh[i + stride + l] = self.share.lane(l).to_bits();
            sh[i + 2 * stride + l] = self.rest.lane(l).to_bits();
            sh[i + 3 * stride + l] = self.opaque.test(l) as u32 | (self.see_through.test(l) as u32) << 1;
            l += 1;
        }
    }
}
