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
//! of the budget.
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

/// Relative depth step beyond which the next fragment is another surface (as the area-integrated
/// layers cluster depths within 5%, [`crate::resolve`]).
pub const DEPTH_GAP: f32 = 1.05;
/// Most summed disc share one surface gives a pixel: a surface covers a pixel once.
pub const SHARE_MAX: f32 = 1.0;

/// What a fragment of disc share `w` and alpha `alpha` takes of a pixel that has `rest` coverage
/// left: the factor its premultiplied colour is added with, and the coverage it spends. Its
/// coverage `w·α` while that fits; otherwise the rest, with its colour scaled to match (`rest/α`,
/// below `w`). An opaque fragment takes `min(w, rest)` for both, bit for bit as before alpha.
#[inline]
pub fn take(w: f32, alpha: f32, rest: f32) -> (f32, f32) {
    let wa = w * alpha;
    if wa < rest { (w, wa) } else { (rest / alpha, rest) }
}

/// A pixel's walk between surfaces.
#[derive(Clone, Copy)]
pub struct Surfaces {
    /// Depth of the last fragment taken (NaN: none yet).
    pub last_z: f32,
    /// Summed disc share of the current surface's fragments.
    pub share: f32,
    /// Coverage left when the current surface began: the factor its translucent fragments are
    /// scaled by when [`Surfaces::see_through`].
    pub rest: f32,
    /// The current surface has an opaque fragment (before the first: true, nothing to see through).
    pub opaque: bool,
    /// The current surface lies behind a wholly translucent one.
    pub see_through: bool,
}

impl Surfaces {
    /// Before the first fragment.
    pub const START: Surfaces = Surfaces { last_z: f32::NAN, share: 0.0, rest: 1.0, opaque: true, see_through: false };

    /// What a fragment of disc share `w`, alpha `alpha` and depth `z` takes of a pixel that has
    /// spent `used` of its coverage: the factor its premultiplied colour is added with and the
    /// coverage it spends ([`take`], on its share scaled by its surface's rest where it is seen
    /// through a translucent surface).
    #[inline]
    pub fn take(&mut self, w: f32, alpha: f32, z: f32, used: f32) -> (f32, f32) {
        let rest = 1.0 - used;
        // `!(z <= ..)`: the first fragment (NaN) starts a surface too.
        if !(z <= self.last_z * DEPTH_GAP) || self.share + 0.5 * w > SHARE_MAX {
            self.see_through = !self.opaque;
            self.opaque = false;
            self.rest = rest;
            self.share = 0.0;
        }
        self.last_z = z;
        self.share += w;
        if alpha < 1.0 {
            let scale = if self.see_through { self.rest } else { 1.0 };
            take(w * scale, alpha, rest)
        } else {
            self.opaque = true;
            take(w, alpha, rest)
        }
    }
}

/// Words of workgroup memory a pixel's [`Surfaces`] takes, one field every `stride` words from
/// `base` (the walk keeps it between chunks).
pub const WORDS: usize = 4;

impl Surfaces {
    #[inline]
    pub fn load<const N: usize>(sh: &[u32; N], base: usize, stride: usize, i: u32) -> Surfaces {
        let i = base + i as usize;
        let flags = sh[i + 3 * stride];
        Surfaces {
            last_z: f32::from_bits(sh[i]),
            share: f32::from_bits(sh[i + stride]),
            rest: f32::from_bits(sh[i + 2 * stride]),
            opaque: flags & 1 != 0,
            see_through: flags & 2 != 0,
        }
    }

    #[inline]
    pub fn store<const N: usize>(self, sh: &mut [u32; N], base: usize, stride: usize, i: u32) {
        let i = base + i as usize;
        sh[i] = self.last_z.to_bits();
        sh[i + stride] = self.share.to_bits();
        sh[i + 2 * stride] = self.rest.to_bits();
        sh[i + 3 * stride] = self.opaque as u32 | (self.see_through as u32) << 1;
    }
}
