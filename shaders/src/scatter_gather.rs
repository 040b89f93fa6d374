//! Scatter-as-you-gather with tile depth separation, after Jimenez 2014 ("Next-Generation
//! Post-Processing in Call of Duty: Advanced Warfare", SIGGRAPH course "Advances in Real-Time
//! Rendering in Games"): a fixed budget of samples on concentric rings per pixel, over the disc of
//! its tile's dilated largest CoC, each sample kept only where its own CoC reaches the pixel and
//! weighted by the inverse of its CoC disc's area, split by depth into a foreground and a
//! background, composited with the foreground's coverage as alpha.
//!
//! Three passes, at full resolution:
//! 1. [`tile_pass`]: one workgroup a 16x16 tile: every pixel's signed CoC radius (capped; NaN
//!    where its colour or depth is unusable) into `coc`, the tile's largest radius and closest
//!    depth into `tiles`, and the frame's largest radius into the statistics.
//! 2. [`dilate_pass`]: one invocation a tile: the largest radius of the tiles that radius reaches
//!    (fading in over the tile beyond its reach, so the kernel's size moves continuously), and the
//!    closest depth of the tiles that reach it, so a blurred foreground spreads over the sharp tiles
//!    beside it and is told apart from what lies behind it there.
//! 3. [`gather_pass`]: one invocation a pixel: the pixel itself and `8 k` samples on ring `k` (`k`
//!    = 1 to the ring count: 1 + 8 + 16 + 24 = 49 samples with 3 rings), rings spaced evenly out to
//!    the tile's dilated radius `R`. A sample of CoC radius `r` at distance `d` (between pixel
//!    centres) counts `spread · alpha`: `spread = saturate(reach − d + 1/2)` (its disc seen through
//!    the pixel; 1 at `d = 0`), `alpha = 1 / (π max(r, 1/2)²)` (a wide blur spreads its light
//!    thin). Its weight goes to the foreground and the background by a smooth ramp on its depth
//!    against the tile's closest ([`back_share`]). Each layer's colour is its weighted mean; its
//!    coverage is its weight over the weight a disc covered by a uniform field of radius `R` gives
//!    through the same samples (clamped to 1). The background covers what the foreground leaves
//!    open, up to its own coverage, and the two are normalised by what they cover together: where
//!    the background covers the rest, the result is the background with the foreground over it by
//!    its coverage; where little reaches the pixel but itself, it is the pixel.
//!
//! The depth rules the other gathers share: a sample behind the pixel reaches it by at most the
//! pixel's own CoC, so a blurred background never smears over a sharper object; behind a pixel of
//! the near field (whose CoC is negative) it reaches it by that pixel's blur instead, the background
//! a single layer guesses for what a blurred foreground hides, which shows where the foreground's
//! coverage falls below 1 (its silhouette). Samples beyond the frame take the edge pixel
//! (clamp-to-edge). Each layer is written as the pixel's colour plus weighted differences, so where
//! every sample is the pixel itself (a kernel radius under 1/2 px: in focus) the output is the input
//! bit for bit. Non-finite colours and depths are skipped; a pixel that is skipped and that nothing
//! reaches comes out black. What it cannot do, by construction (`docs/methods.md`): show what a
//! blurred foreground hides, composite more than two depth layers (what lies behind the foreground
//! is averaged into one background), or honour a CoC beyond its cap.

use crate::exec::{Group, Load, Mem};
use crate::lens::{ThinLens, is_finite as finite, is_nan, is_pos_inf, is_positive};
use crate::math::{absf, maxf, minf, saturate};
use crate::ring_gather::signed_radius;

/// Pixels on a side of a tile.
pub const TILE: u32 = 16;
/// A tile's 2 words, reduced and then dilated: its largest CoC radius (pixels), its closest depth
/// (bits of an f32; +inf where no pixel is usable).
pub const TILE_WORDS: u32 = 2;
/// A sample is foreground at the tile's closest depth and background from this share of that
/// depth behind it on, over a smoothstep.
pub const DEPTH_RAMP: f32 = 0.05;
/// The word of the frame's statistics that holds its largest CoC radius (bits of an f32, pixels,
/// capped); word 0 counts the clamped input colours.
pub const STATS_LARGEST: u32 = 1;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct ScatterGatherParams {
    pub width: u32,
    pub height: u32,
    /// Sample rings around the pixel: `1 + 4 R (R + 1)` samples.
    pub rings: u32,
    /// Cap on the CoC radius, pixels.
    pub max_radius: u32,
    pub lens: ThinLens,
}

impl ScatterGatherParams {
    #[inline]
    pub fn tiles_x(&self) -> u32 {
        self.width.div_ceil(TILE)
    }
    #[inline]
    pub fn tiles_y(&self) -> u32 {
        self.height.div_ceil(TILE)
    }
    /// Tiles on each side the dilation looks at: those the capped radius reaches, and one more
    /// for the fade.
    #[inline]
    pub fn dilation_tiles(&self) -> u32 {
        self.max_radius.div_ceil(TILE) + 1
    }
}

/// Samples per pixel with `rings` rings.
#[inline]
pub const fn samples(rings: u32) -> u32 {
    1 + 4 * rings * (rings + 1)
}

/// The light a sample of CoC radius `r` gives a pixel its disc covers: the inverse of the disc's
/// area, the disc at least a pixel wide.
#[inline]
pub fn sample_alpha(r: f32) -> f32 {
    let r = maxf(r, 0.5);
    1.0 / (core::f32::consts::PI * r * r)
}

/// How much of a pixel at distance `d` (between centres) a disc of radius `reach` covers: a soft
/// edge one pixel wide; a pixel always covers itself.
#[inline]
pub fn spread(reach: f32, d: f32) -> f32 {
    if d == 0.0 { 1.0 } else { saturate(reach - d + 0.5) }
}

/// The background share of a sample at depth `z` in a tile whose closest depth is `closest` (both
/// positive; `closest` may be +inf): 0 at `closest`, rising over a smoothstep to 1 at
/// `closest · (1 + DEPTH_RAMP)`. Depths are ordered by their bits and infinities tested on them.
#[inline]
pub fn back_share(z: f32, closest: f32) -> f32 {
    if z.to_bits() <= closest.to_bits() {
        0.0
    } else if is_pos_inf(z) {
        1.0
    } else {
        let t = saturate((z - closest) / (DEPTH_RAMP * closest));
        t * t * (3.0 - 2.0 * t)
    }
}

/// Cosine and sine of half the angle between neighbouring samples of ring `ring` (>= 1): π/(8
/// ring), at most π/8, by their Taylor series to the x⁹ and x⁸ terms (error under 1e-9), so both
/// backends compute the same bits.
#[inline]
fn half_step(ring: u32) -> (f32, f32) {
    let a = core::f32::consts::PI / (8 * ring) as f32;
    let a2 = a * a;
    let sin = a * (1.0 - a2 * (1.0 / 6.0) * (1.0 - a2 * (1.0 / 20.0) * (1.0 - a2 * (1.0 / 42.0) * (1.0 - a2 * (1.0 / 72.0)))));
    let cos = 1.0 - a2 * 0.5 * (1.0 - a2 * (1.0 / 12.0) * (1.0 - a2 * (1.0 / 30.0) * (1.0 - a2 * (1.0 / 56.0))));
    (cos, sin)
}

/// The colour of pixel `i` under the numerical contract ([`crate::radiance`]); only for pixels
/// whose CoC is not NaN (their channels are finite).
#[inline]
fn colour(color: &impl Load, i: u32) -> [f32; 3] {
    let c = [f32::from_bits(color.load(3 * i)), f32::from_bits(color.load(3 * i + 1)), f32::from_bits(color.load(3 * i + 2))];
    crate::radiance::clamp_color(c)
}

/// The signed CoC radius of pixel `i` (pixels, within the cap), or NaN when its colour or depth
/// is unusable.
#[inline]
fn signed_coc(p: &ScatterGatherParams, color: &impl Load, depth: &impl Load, i: u32) -> f32 {
    let c = [f32::from_bits(color.load(3 * i)), f32::from_bits(color.load(3 * i + 1)), f32::from_bits(color.load(3 * i + 2))];
    let z = f32::from_bits(depth.load(i));
    if finite(c[0]) && finite(c[1]) && finite(c[2]) && is_positive(z) { signed_radius(&p.lens, z, p.max_radius as f32) } else { f32::NAN }
}

/// One workgroup a tile, one invocation a pixel: the pixel's signed CoC radius into `coc`, the
/// tile's largest radius and closest depth into `tiles`, the largest radius into word
/// [`STATS_LARGEST`] of `stats` (atomic max; zeroed before).
pub fn tile_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &ScatterGatherParams,
    sh: &mut [u32; 2 * 256],
    color: R,
    depth: R,
    mut coc: M,
    mut tiles: M,
    mut stats: M,
) {
    let [tx, ty, _] = g.workgroup_id();
    g.each(|lid| {
        let x = tx * TILE + lid % TILE;
        let y = ty * TILE + lid / TILE;
        // Non-negative floats order like their bits: the reductions run on the bits.
        let mut widest = 0u32;
        let mut closest = f32::INFINITY.to_bits();
        if x < p.width && y < p.height {
            let i = y * p.width + x;
            let s = signed_coc(p, &color, &depth, i);
            coc.store(i, s.to_bits());
            if !is_nan(s) {
                widest = absf(s).to_bits();
                closest = depth.load(i);
            }
        }
        sh[lid as usize] = widest;
        sh[256 + lid as usize] = closest;
    });
    let mut half = 128u32;
    while half > 0 {
        g.each(|lid| {
            if lid < half {
                let (i, j) = (lid as usize, (lid + half) as usize);
                sh[i] = if sh[j] > sh[i] { sh[j] } else { sh[i] };
                sh[256 + i] = if sh[256 + j] < sh[256 + i] { sh[256 + j] } else { sh[256 + i] };
            }
        });
        half /= 2;
    }
    g.each(|lid| {
        if lid == 0 {
            let t = TILE_WORDS * (ty * p.tiles_x() + tx);
            tiles.store(t, sh[0]);
            tiles.store(t + 1, sh[256]);
            stats.atomic_max(STATS_LARGEST, sh[0]);
        }
    });
}

/// One invocation a tile of an 8x8 block of tiles: the largest radius of the tiles around that
/// reach it (measured between the nearest edges of the two tiles; a neighbour's radius fades in
/// over the last tile before it reaches, so the kernel's radius moves continuously with the blur)
/// and the closest depth of those that reach it, itself included.
pub fn dilate_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &ScatterGatherParams, tiles: R, mut dilated: M) {
    let [wx, wy, _] = g.workgroup_id();
    let (tw, th) = (p.tiles_x(), p.tiles_y());
    let reach = p.dilation_tiles() as i32;
    g.each(|lid| {
        let (tx, ty) = (wx * 8 + lid % 8, wy * 8 + lid / 8);
        if tx >= tw || ty >= th {
            return;
        }
        let mut widest = 0.0f32;
        let mut closest = f32::INFINITY.to_bits();
        let mut dy = -reach;
        while dy <= reach {
            let ny = ty as i32 + dy;
            let mut dx = -reach;
            while ny >= 0 && ny < th as i32 && dx <= reach {
                let nx = tx as i32 + dx;
                if nx >= 0 && nx < tw as i32 {
                    let n = TILE_WORDS * (ny as u32 * tw + nx as u32);
                    let gx = maxf(absf(dx as f32) - 1.0, 0.0) * TILE as f32;
                    let gy = maxf(absf(dy as f32) - 1.0, 0.0) * TILE as f32;
                    let gap = crate::math::sqrt(gx * gx + gy * gy);
                    let r = f32::from_bits(tiles.load(n));
                    widest = maxf(widest, r * saturate((r - gap) * (1.0 / TILE as f32) + 1.0));
                    if r >= gap {
                        let z = tiles.load(n + 1);
                        closest = if z < closest { z } else { closest };
                    }
                }
                dx += 1;
            }
            dy += 1;
        }
        let t = TILE_WORDS * (ty * tw + tx);
        dilated.store(t, widest.to_bits());
        dilated.store(t + 1, closest);
    });
}

/// What a pixel gathers: per layer the weighted differences from the pixel's colour and the
/// weight, and the weight of a disc a uniform field of the kernel's radius covers.
struct Layers {
    front: [f32; 3],
    front_weight: f32,
    back: [f32; 3],
    back_weight: f32,
    full: f32,
}

/// The pixel being gathered: its colour (0 where unusable), signed radius (NaN where unusable) and
/// depth, and its tile's kernel radius and closest depth.
struct Centre {
    base: [f32; 3],
    own: f32,
    depth: f32,
    radius: f32,
    closest: f32,
}

impl Layers {
    /// Adds the sample at pixel `q`, `d` pixels from the centre's.
    #[inline]
    fn add(&mut self, color: &impl Load, depth: &impl Load, coc: &impl Load, c: &Centre, q: u32, d: f32) {
        self.full += sample_alpha(c.radius) * spread(c.radius, d);
        let s = f32::from_bits(coc.load(q));
        if is_nan(s) {
            return;
        }
        let z = f32::from_bits(depth.load(q));
        let r = absf(s);
        // Behind the pixel: by at most the pixel's own CoC; behind a pixel of the near field, by
        // its blur (what the near field hides). An unusable pixel is open to everything.
        let behind = !is_nan(c.own) && z.to_bits() > c.depth.to_bits();
        let reach = if !behind {
            r
        } else if c.own >= 0.0 {
            minf(r, c.own)
        } else {
            -c.own
        };
        let w = spread(reach, d) * sample_alpha(r);
        if w > 0.0 {
            let q_colour = colour(color, q);
            let back = back_share(z, c.closest);
            let (wf, wb) = (w * (1.0 - back), w * back);
            let diff = [q_colour[0] - c.base[0], q_colour[1] - c.base[1], q_colour[2] - c.base[2]];
            self.front = [self.front[0] + wf * diff[0], self.front[1] + wf * diff[1], self.front[2] + wf * diff[2]];
            self.front_weight += wf;
            self.back = [self.back[0] + wb * diff[0], self.back[1] + wb * diff[1], self.back[2] + wb * diff[2]];
            self.back_weight += wb;
        }
    }
}

/// The colour of a layer: the centre's plus its mean difference (the centre's where it has no
/// weight).
#[inline]
fn mean(base: [f32; 3], sum: [f32; 3], weight: f32) -> [f32; 3] {
    if weight > 0.0 {
        let inv = 1.0 / weight;
        [base[0] + sum[0] * inv, base[1] + sum[1] * inv, base[2] + sum[2] * inv]
    } else {
        base
    }
}

/// The gather at pixel (`x`, `y`) of the centre `c`: its own sample, then the rings.
fn gather_pixel(p: &ScatterGatherParams, color: &impl Load, depth: &impl Load, coc: &impl Load, x: u32, y: u32, c: &Centre) -> [f32; 3] {
    let mut l = Layers { front: [0.0; 3], front_weight: 0.0, back: [0.0; 3], back_weight: 0.0, full: 0.0 };
    l.add(color, depth, coc, c, y * p.width + x, 0.0);
    let rings = if p.rings == 0 { 1 } else { p.rings };
    let spacing = c.radius / rings as f32;
    let (cx, cy) = (x as f32 + 0.5, y as f32 + 0.5);
    let (last_x, last_y) = ((p.width - 1) as f32, (p.height - 1) as f32);
    let mut ring = 1u32;
    while ring <= rings {
        // Ring `ring` holds `8 ring` samples, the first half a step from +x, each next one the last
        // turned by a step (twice the half step).
        let (hc, hs) = half_step(ring);
        let (sc, ss) = (hc * hc - hs * hs, 2.0 * hc * hs);
        let rho = spacing * ring as f32;
        let (mut ux, mut uy) = (hc, hs);
        let mut j = 0u32;
        while j < 8 * ring {
            // Clamp-to-edge: beyond the frame, the edge pixel.
            let sx = minf(maxf(crate::math::floor(cx + rho * ux), 0.0), last_x);
            let sy = minf(maxf(crate::math::floor(cy + rho * uy), 0.0), last_y);
            let (ox, oy) = (sx - x as f32, sy - y as f32);
            let d = crate::math::sqrt(ox * ox + oy * oy);
            l.add(color, depth, coc, c, sy as u32 * p.width + sx as u32, d);
            let turned = ux * sc - uy * ss;
            uy = ux * ss + uy * sc;
            ux = turned;
            j += 1;
        }
        ring += 1;
    }
    let front = mean(c.base, l.front, l.front_weight);
    let back = mean(c.base, l.back, l.back_weight);
    // Coverages against the uniform disc: the foreground's, and the background's within what the
    // foreground leaves open.
    let inv_full = 1.0 / l.full;
    let alpha = saturate(l.front_weight * inv_full);
    let open = minf(1.0 - alpha, l.back_weight * inv_full);
    let covered = alpha + open;
    if !(covered > 0.0) {
        return front;
    }
    let t = open / covered;
    if t >= 1.0 {
        return back;
    }
    [front[0] + t * (back[0] - front[0]), front[1] + t * (back[1] - front[1]), front[2] + t * (back[2] - front[2])]
}

/// One invocation a pixel of an 8x8 block (a quarter of a tile), into `out` (3 words a pixel,
/// finite and non-negative). A tile whose kernel radius is under 1/2 px copies its pixels: every
/// sample would be the pixel itself.
pub fn gather_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &ScatterGatherParams, color: R, depth: R, coc: R, dilated: R, mut out: M) {
    let [wx, wy, _] = g.workgroup_id();
    let t = TILE_WORDS * ((wy / 2) * p.tiles_x() + wx / 2);
    let radius = f32::from_bits(dilated.load(t));
    let closest = f32::from_bits(dilated.load(t + 1));
    g.each(|lid| {
        let x = wx * 8 + lid % 8;
        let y = wy * 8 + lid / 8;
        if x >= p.width || y >= p.height {
            return;
        }
        let i = y * p.width + x;
        let own = f32::from_bits(coc.load(i));
        let usable = !is_nan(own);
        let c = Centre {
            base: if usable { colour(&color, i) } else { [0.0; 3] },
            own,
            depth: if usable { f32::from_bits(depth.load(i)) } else { 0.0 },
            radius,
            closest,
        };
        let v = if radius < 0.5 { c.base } else { gather_pixel(p, &color, &depth, &coc, x, y, &c) };
        out.store(3 * i, maxf(v[0], 0.0).to_bits());
        out.store(3 * i + 1, maxf(v[1], 0.0).to_bits());
        out.store(3 * i + 2, maxf(v[2], 0.0).to_bits());
    });
}

kernel!(
    /// Every pixel's signed CoC radius, each tile's largest radius and closest depth, the frame's largest radius.
    SCATTER_GATHER_TILES = scatter_gather_tiles [256] (ScatterGatherParams) shared [u32; 2 * 256]
        { read color, read depth, coc, tiles, stats } => tile_pass
);
kernel!(
    /// Each tile's largest radius and closest depth over the tiles that reach it.
    SCATTER_GATHER_DILATE = scatter_gather_dilate [64] (ScatterGatherParams) { read tiles, dilated } => dilate_pass
);
kernel!(
    /// The gather over concentric rings, foreground over background, into the output.
    SCATTER_GATHER = scatter_gather [64] (ScatterGatherParams) { read color, read depth, read coc, read dilated, out } => gather_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 3] = [&SCATTER_GATHER_TILES, &SCATTER_GATHER_DILATE, &SCATTER_GATHER];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_half_steps_are_the_rings_cosines_and_sines() {
        for ring in 1..=64u32 {
            let (c, s) = half_step(ring);
            let a = std::f64::consts::PI / (8 * ring) as f64;
            assert!((c as f64 - a.cos()).abs() < 1e-7 && (s as f64 - a.sin()).abs() < 1e-7, "ring {ring}: {c} {s}");
        }
        assert_eq!(samples(3), 49);
    }

    #[test]
    fn the_background_share_ramps_from_the_closest_depth() {
        assert_eq!(back_share(2.0, 2.0), 0.0);
        assert_eq!(back_share(1.0, 2.0), 0.0);
        assert_eq!(back_share(2.0 * (1.0 + DEPTH_RAMP), 2.0), 1.0);
        assert_eq!(back_share(f32::INFINITY, 2.0), 1.0);
        assert_eq!(back_share(f32::INFINITY, f32::INFINITY), 0.0);
        let mid = back_share(2.0 * (1.0 + 0.5 * DEPTH_RAMP), 2.0);
        assert!((mid - 0.5).abs() < 1e-5, "{mid}");
    }
}
