//! An engine-grade gathering depth of field, the kind shipping renderers use by default, built from
//! the published descriptions of AMD FidelityFX DoF, Unreal Engine's Diaphragm DoF and Jimenez 2014
//! ("Next-Generation Post-Processing in Call of Duty: Advanced Warfare"): half-resolution colour and
//! CoC, per-tile near-field CoC dilated over the neighbouring tiles, a fixed budget of sample rings,
//! a background field and a near field gathered separately and composited at full resolution with
//! the near field's coverage as alpha, and a full-resolution path for what is in focus or slightly
//! blurred.
//!
//! Four passes (all sizes in the frame's pixels unless said "half"):
//! 1. [`downsample_pass`]: every half-resolution pixel splits its 2x2 pixels into a near part and
//!    the rest by a continuous weight (0 at a 1 px near CoC radius, 1 at 3 px) and keeps both as
//!    samples: colour, signed radius, and the near part's coverage of the block. The rest weighs
//!    its pixels by how much the composite shows the background field over them, so a sharp pixel
//!    does not tint the field of its blurred neighbours. Each 8x8 tile reduces its largest
//!    near-field radius, and takes out its highlights (at most [`HIGHLIGHTS_PER_TILE`]): blocks
//!    much brighter than their 12 neighbours (less those the emitter lights itself) with a CoC
//!    radius of at least 1/2 px everywhere (a ramp from 1/4 px), whose excess over the neighbours
//!    becomes a disc drawn at full resolution; the gather and the full-resolution path see the
//!    input without it.
//! 2. [`dilate_pass`]: every tile takes the largest near radius of the tiles that radius reaches,
//!    fading in over the last tile of the reach, so a blurred foreground spreads over the sharp
//!    tiles beside it (Unreal's "foreground hole filling", FidelityFX's tile dilation); and how far
//!    to look for highlights whose discs reach it.
//! 3. [`gather_pass`]: every half-resolution pixel reads `1 + 3 R (R + 1)` samples on `R` hexagonal
//!    rings (ring `i` holds `6 i` points of a hexagonal lattice, so the samples cover the disc with
//!    uniform density and no trigonometry) for each of two fields, each with its own kernel (one
//!    set of rings where the two agree). A sample's near share rises continuously from 0 at a 0.5
//!    half-pixel near radius to 1 at 1.5:
//!    - background, as wide as the pixel's own CoC (either side of the focus plane, so a slightly
//!      near pixel's rings never switch off while its neighbours in front still reach it):
//!      scatter-as-gather as in
//!      [`crate::gather`], each sample weighted by its coverage over the inverse of its CoC area, a
//!      sample behind the pixel reaching at most the pixel's own CoC (so a blurred background does
//!      not smear over a sharper object); where the pixel itself is in the near field, the kernel
//!      is the near one and the background seen within it fills in what the pixel hides;
//!    - near, as wide as the tile's dilated near radius: each sample adds the share of its CoC disc
//!      that one lattice cell covers, times its near share; their sum is the near field's coverage
//!      (alpha, 1 for a uniform near field), their weighted mean its colour.
//! 4. [`composite_pass`]: every pixel blends a full-resolution scatter-as-gather of its 3x3
//!    neighbourhood (below a 1 px CoC radius) with the background field, upsampled bilinearly
//!    (from 2 px), adds the discs of the highlights behind it, puts the near field over that by its
//!    coverage and the discs of the near highlights on top.
//!
//! Every decision that a focus pull moves through is a continuous weight, not a threshold (the
//! near split, the dilation, the half- and full-resolution blend, the highlight share), so the
//! image changes smoothly with the lens; only a tile's highlight cap is a count. Samples beyond the
//! frame's edge take the edge pixel (clamp-to-edge addressing), so a blurred object cut by the
//! frame keeps its full coverage there. Non-finite colours and depths are skipped as in the
//! exhaustive gather. What it cannot do, by construction: show what a blurred foreground hides (a
//! single layer), honour CoCs beyond its radius cap, or resolve blur larger than its ring spacing
//! allows (with few rings a large blur is sampled sparsely; the highlight discs cover the worst of
//! it, isolated bright pixels).

use crate::exec::{Group, Load, Mem};
use crate::lens::{ThinLens, is_finite as finite, is_nan, is_pos_inf, is_positive};

/// Half-resolution pixels on a side of a tile (tiles are 16x16 pixels of the frame).
pub const TILE: u32 = 8;
/// A half-resolution pixel's 9 words: its 2x2 pixels split into a near part and the rest by a
/// continuous weight, as two samples: the near part's colour and its share of the block
/// (coverage), the rest's colour, then the two signed CoC radii in half-resolution pixels (the
/// rest's NaN where none of the pixels was valid). Colours are less what the highlight path took.
pub const HALF_WORDS: u32 = 9;
/// A half-resolution pixel's 8 words in the fields buffer: the background field's colour and 1 (0
/// where nothing was gathered), then the near field's premultiplied colour and coverage.
pub const FIELD_WORDS: u32 = 8;
/// A tile's 2 words after dilation: its dilated near-field radius (half-resolution pixels), then 1
/// plus the tiles on each side whose highlights may reach it (0: none does).
pub const DILATED_WORDS: u32 = 2;
/// A sample's near share rises from 0 at this near CoC radius (half-resolution pixels) to 1 at
/// `NEAR_MIN_RADIUS + NEAR_RAMP`: nearly sharp samples belong to the background field, and no
/// sample jumps from one field to the other as the focus moves.
pub const NEAR_MIN_RADIUS: f32 = 0.5;
pub const NEAR_RAMP: f32 = 1.0;
/// Highlights drawn as discs instead of gathered: the scattered share rises from 0 at this CoC
/// radius (pixels of the frame) to 1 at `HIGHLIGHT_MIN_RADIUS + HIGHLIGHT_RAMP`, where a disc is
/// wider than its pixel. Unreal Engine's Diaphragm DoF scatters from 3 px. Left to the gather, an
/// emitter is averaged into the half-resolution field its more blurred neighbours read and
/// upsampled from it: a dim halo 1 to 5 px around it, which the saturating display transform shows
/// (on `highlights` at 320x180 against the converged reference, 561 pixels lit that the reference
/// leaves dark with the earlier ramp from 1/2 px to 1 px, 345 with this one, the gather 79). In
/// focus the share is 0: a block's taken light is one disc, which would spread two sharp emitters
/// of a block over each other's pixels.
pub const HIGHLIGHT_MIN_RADIUS: f32 = 0.25;
pub const HIGHLIGHT_RAMP: f32 = 0.25;
/// ... and from 0 where the block's luminance is this many times its ring of 12 neighbours' to 1 at
/// twice that ...
pub const HIGHLIGHT_CONTRAST: f32 = 4.0;
/// ... and from 0 where the excess over the neighbours has this luminance to 1 at twice that.
pub const HIGHLIGHT_MIN_EXCESS: f32 = 0.25;
/// Highlights a tile holds (1 in 8 of its half-resolution pixels; Unreal caps at 10% of quads).
/// Beyond it a highlight stays in the gather whole, and is counted ([`STATS_CAPPED`]).
pub const HIGHLIGHTS_PER_TILE: u32 = 8;
/// A highlight's 8 words: centre x, y (pixels of the frame), signed CoC radius (pixels), then its
/// colour per unit of disc weight (r, g, b), the spread of its light (pixels, [`disc_weight`]),
/// then 1 unused.
pub const HIGHLIGHT_WORDS: u32 = 8;
/// A tile's highlight record: the count, the farthest reach of its discs (radius plus spread, pixels,
/// bits of an f32), the highlights.
pub const BRIGHT_TILE_WORDS: u32 = 2 + HIGHLIGHTS_PER_TILE * HIGHLIGHT_WORDS;
/// The word of the frame's statistics buffer that counts the highlights left in the gather because
/// their tile held [`HIGHLIGHTS_PER_TILE`] already (word 0 counts the clamped input colours).
pub const STATS_CAPPED: u32 = 1;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct RingGatherParams {
    pub width: u32,
    pub height: u32,
    /// Sample rings (the quality knob): `1 + 3 R (R + 1)` samples a half-resolution pixel for each
    /// field that needs its own kernel.
    pub rings: u32,
    /// Cap on the CoC radius in pixels of the frame.
    pub max_radius: u32,
    pub lens: ThinLens,
}

impl RingGatherParams {
    #[inline]
    pub fn half_width(&self) -> u32 {
        self.width.div_ceil(2)
    }
    #[inline]
    pub fn half_height(&self) -> u32 {
        self.height.div_ceil(2)
    }
    #[inline]
    pub fn tiles_x(&self) -> u32 {
        self.half_width().div_ceil(TILE)
    }
    #[inline]
    pub fn tiles_y(&self) -> u32 {
        self.half_height().div_ceil(TILE)
    }
    /// Tiles on each side a tile's dilation looks at: as far as the capped radius reaches.
    #[inline]
    pub fn dilation_tiles(&self) -> u32 {
        (self.max_radius + 1).div_ceil(2 * TILE)
    }
}

/// Samples per half-resolution pixel with `rings` rings.
#[inline]
pub const fn samples(rings: u32) -> u32 {
    1 + 3 * rings * (rings + 1)
}

#[inline]
fn minf(a: f32, b: f32) -> f32 {
    if a < b { a } else { b }
}

#[inline]
fn maxf(a: f32, b: f32) -> f32 {
    if a > b { a } else { b }
}

#[inline]
fn saturate(x: f32) -> f32 {
    minf(maxf(x, 0.0), 1.0)
}

#[inline]
fn absf(x: f32) -> f32 {
    if x < 0.0 { -x } else { x }
}

#[inline]
fn luminance(c: [f32; 3]) -> f32 {
    0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
}

/// Signed CoC radius in pixels of a sample at depth `z` (negative in front of the focus plane),
/// within `±cap`; the sky (`+inf`) takes the far-field limit. Only for valid depths.
#[inline]
pub fn signed_radius(lens: &ThinLens, z: f32, cap: f32) -> f32 {
    let r = if is_pos_inf(z) { 0.5 * lens.far_limit_px() } else { 0.5 * lens.signed_coc_px(z) };
    maxf(minf(r, cap), -cap)
}

/// The share of a sample of signed radius `s` (half-resolution pixels) that belongs to the near field.
#[inline]
pub fn near_share(s: f32) -> f32 {
    saturate((-s - NEAR_MIN_RADIUS) / NEAR_RAMP)
}

/// The colour of pixel `i` with its depth, or `None` when either is unusable.
#[inline]
fn sample(color: &impl Load, depth: &impl Load, i: u32) -> Option<([f32; 3], f32)> {
    let c = [f32::from_bits(color.load(3 * i)), f32::from_bits(color.load(3 * i + 1)), f32::from_bits(color.load(3 * i + 2))];
    let c = crate::radiance::clamp_color(c);
    let z = f32::from_bits(depth.load(i));
    if finite(c[0]) && finite(c[1]) && finite(c[2]) && is_positive(z) { Some((c, z)) } else { None }
}

/// Unit vector `k` (0..6) of the hexagonal lattice: 60° apart, starting on +x.
#[inline]
fn hex_dir(k: u32) -> [f32; 2] {
    const S: f32 = 0.866_025_4;
    if k == 0 {
        [1.0, 0.0]
    } else if k == 1 {
        [0.5, S]
    } else if k == 2 {
        [-0.5, S]
    } else if k == 3 {
        [-1.0, 0.0]
    } else if k == 4 {
        [-0.5, -S]
    } else {
        [0.5, -S]
    }
}

/// Point `j` (0..6 ring) of hexagonal ring `ring` (>= 1) of the unit lattice: the ring's six sides
/// walked corner to corner, `ring` points a side.
#[inline]
pub fn hex_point(ring: u32, j: u32) -> [f32; 2] {
    let side = j / ring;
    let step = (j % ring) as f32;
    let a = hex_dir(side);
    let b = hex_dir((side + 1) % 6);
    let r = ring as f32;
    [a[0] * r + (b[0] - a[0]) * step, a[1] * r + (b[1] - a[1]) * step]
}

/// A highlight's disc weight at a pixel whose centre is `d` pixels from the disc's centre: the CoC
/// disc of `radius` seen through a pixel and spread over the light's footprint, `spread` its mean
/// distance from the centre (0 for the light of one pixel): 1 inside `radius − 1/2 − spread`, a
/// soft edge `1 + 2·spread` wide out to `radius + 1/2 + spread`: splatting's rim of a fragment
/// standing for a block of pixels ([`crate::splat::fragment::linear_rim`]), with the footprint's
/// width in place of the block's. One pixel's light has the one-pixel soft edge of a single
/// pixel's disc.
#[inline]
pub fn disc_weight(radius: f32, spread: f32, d: f32) -> f32 {
    crate::splat::fragment::linear_rim(d, radius + 0.5 + spread, 1.0 + 2.0 * spread)
}

/// The sum of [`disc_weight`] over every pixel centre of the plane for a disc of `radius` (>= 1/2)
/// and `spread` centred at (`cx`, `cy`): the pixels whose weight is 1 counted row by row, the soft
/// edge summed, so a highlight's disc keeps its energy exactly (in O(radius), not O(radius²)).
pub fn disc_weight_sum(cx: f32, cy: f32, radius: f32, spread: f32) -> f32 {
    let outer = radius + 0.5 + spread;
    let inner = radius - 0.5 - spread;
    let mut sum = 0.0f32;
    let mut y = crate::math::floor(cy - outer);
    let last = crate::math::floor(cy + outer);
    while y <= last {
        let oy = y + 0.5 - cy;
        let b2 = outer * outer - oy * oy;
        if b2 > 0.0 {
            let b = crate::math::sqrt(b2);
            // Whole pixels: centres within the inner radius (none when the soft edge reaches the
            // centre, a footprint wider than the CoC disc).
            let a2 = if inner > 0.0 { inner * inner - oy * oy } else { -1.0 };
            let (lo, hi) = if a2 > 0.0 {
                let a = crate::math::sqrt(a2);
                (crate::math::ceil(cx - a - 0.5), crate::math::floor(cx + a - 0.5))
            } else {
                (1.0, 0.0)
            };
            if hi >= lo {
                sum += hi - lo + 1.0;
            }
            let mut x = crate::math::floor(cx - b - 0.5);
            let end = crate::math::ceil(cx + b - 0.5);
            while x <= end {
                if x < lo || x > hi {
                    let ox = x + 0.5 - cx;
                    sum += disc_weight(radius, spread, crate::math::sqrt(ox * ox + oy * oy));
                }
                x += 1.0;
            }
        }
        y += 1.0;
    }
    sum
}

/// A half-resolution pixel's reduction of its 2x2 pixels.
struct Block {
    /// The near part: colour, share of the block, signed radius; then the rest's colour and radius.
    near: [f32; 3],
    coverage: f32,
    near_radius: f32,
    far: [f32; 3],
    far_radius: f32,
    /// Valid pixels.
    count: u32,
    /// What a [`Cut`] took out of the pixels (summed), and the centre (pixels), signed CoC radius
    /// (pixels) and spread (the mean distance of its pixels' centres from that centre, pixels) of
    /// that light, weighted by its luminance.
    taken: [f32; 3],
    taken_centre: [f32; 2],
    taken_radius: f32,
    taken_spread: f32,
}

/// What the highlight path takes out of a block's 2x2 pixels: `share[k]` of pixel `k`'s excess
/// over the background `over` (per channel, never below it). A share of 0 takes nothing.
#[derive(Clone, Copy)]
struct Cut {
    share: [f32; 4],
    over: [f32; 3],
}

const NO_CUT: Cut = Cut { share: [0.0; 4], over: [0.0; 3] };

impl Cut {
    #[inline]
    fn any(&self) -> bool {
        self.share[0] > 0.0 || self.share[1] > 0.0 || self.share[2] > 0.0 || self.share[3] > 0.0
    }
}

/// Pixel `k`'s colour less what `cut` takes out of it, and that part.
#[inline]
fn cut_pixel(c: [f32; 3], cut: Cut, k: u32) -> ([f32; 3], [f32; 3]) {
    let share = cut.share[k as usize];
    if share <= 0.0 {
        return (c, [0.0; 3]);
    }
    let mut rest = c;
    let mut t = [0.0f32; 3];
    let mut j = 0usize;
    while j < 3 {
        let over = cut.over[j];
        if c[j] > over {
            t[j] = share * (c[j] - over);
            // What stays, as a blend of the pixel and the background rather than `c - t`: an HDR
            // pixel (up to the contract's 2^100) minus its excess would cancel the background to 0.
            rest[j] = (1.0 - share) * c[j] + share * over;
        }
        j += 1;
    }
    (rest, t)
}

/// A pixel's weight in its block's near part: 0 at a 1 px near CoC radius, 1 at 3 px.
#[inline]
fn near_weight(r: f32) -> f32 {
    saturate((-r - 1.0) * 0.5)
}

/// The 2x2 reduction at (`hx`, `hy`): the near part and the rest as two samples, so a blurred
/// foreground's silhouette keeps its own colour and radius through the reduction without being
/// inflated to the whole block (its coverage says how much of the block it is), and no threshold
/// pops as the focus moves. Each pixel's colour is taken less what `cut` takes out of it.
fn block(p: &RingGatherParams, color: &impl Load, depth: &impl Load, hx: u32, hy: u32, cut: Cut) -> Block {
    let cap = p.max_radius as f32;
    let mut sum_r = 0.0f32;
    let mut count = 0u32;
    let mut centre = [0.0f32; 2];
    let mut near = [0.0f32; 3];
    let mut near_r = 0.0f32;
    let mut near_w = 0.0f32;
    let mut rest = [0.0f32; 4];
    let mut rest_b = 0.0f32;
    let mut taken = [0.0f32; 3];
    let mut taken_centre = [0.0f32; 4];
    // Each pixel's share of the taken light's luminance, for its spread.
    let mut taken_l = [0.0f32; 4];
    let mut k = 0u32;
    while k < 4 {
        let x = 2 * hx + k % 2;
        let y = 2 * hy + k / 2;
        if x < p.width && y < p.height {
            if let Some((c, z)) = sample(color, depth, y * p.width + x) {
                let r = signed_radius(&p.lens, z, cap);
                let (c, t) = cut_pixel(c, cut, k);
                taken = [taken[0] + t[0], taken[1] + t[1], taken[2] + t[2]];
                let l = luminance(t);
                taken_l[k as usize] = l;
                taken_centre = [
                    taken_centre[0] + l * (x as f32 + 0.5),
                    taken_centre[1] + l * (y as f32 + 0.5),
                    taken_centre[2] + l * r,
                    taken_centre[3] + l,
                ];
                sum_r += r;
                centre = [centre[0] + x as f32 + 0.5, centre[1] + y as f32 + 0.5];
                count += 1;
                let w = near_weight(r);
                near = [near[0] + w * c[0], near[1] + w * c[1], near[2] + w * c[2]];
                near_r += w * r;
                near_w += w;
                // The rest weighs its pixels by how much the composite will show the background
                // field over them: a sharp pixel is drawn at full resolution by itself, and must not
                // tint the field its blurred neighbours in the block show (a small floor keeps a
                // wholly sharp block's mean).
                let b = (1.0 - w) * (saturate(absf(r) - 1.0) + 1.0e-3);
                rest = [rest[0] + b * c[0], rest[1] + b * c[1], rest[2] + b * c[2], rest[3] + b * r];
                rest_b += b;
            }
        }
        k += 1;
    }
    if count == 0 {
        let z = [0.0f32; 3];
        return Block {
            near: z,
            coverage: 0.0,
            near_radius: 0.0,
            far: z,
            far_radius: f32::NAN,
            count,
            taken: z,
            taken_centre: [0.0; 2],
            taken_radius: 0.0,
            taken_spread: 0.0,
        };
    }
    let n = count as f32;
    let inv = 1.0 / n;
    let radius = 0.5 * sum_r * inv;
    let rest_w = n - near_w;
    let (far, far_radius) = if rest_w > 0.0 && rest_b > 0.0 {
        let i = 1.0 / rest_b;
        ([rest[0] * i, rest[1] * i, rest[2] * i], 0.5 * rest[3] * i)
    } else {
        ([0.0; 3], radius)
    };
    let (near, near_radius) = if near_w > 0.0 {
        let i = 1.0 / near_w;
        ([near[0] * i, near[1] * i, near[2] * i], 0.5 * near_r * i)
    } else {
        ([0.0; 3], radius)
    };
    // Where every pixel is wholly near, the rest is empty (its radius the near one).
    let coverage = if rest_w > 0.0 { near_w * inv } else { 1.0 };
    let centre = [centre[0] * inv, centre[1] * inv];
    let (taken_centre, taken_radius, taken_spread) = if taken_centre[3] > 0.0 {
        let i = 1.0 / taken_centre[3];
        let c = [taken_centre[0] * i, taken_centre[1] * i];
        let mut spread = 0.0f32;
        let mut k = 0u32;
        while k < 4 {
            if taken_l[k as usize] > 0.0 {
                let (dx, dy) = ((2 * hx + k % 2) as f32 + 0.5 - c[0], (2 * hy + k / 2) as f32 + 0.5 - c[1]);
                spread += taken_l[k as usize] * crate::math::sqrt(dx * dx + dy * dy);
            }
            k += 1;
        }
        (c, taken_centre[2] * i, spread * i)
    } else {
        (centre, 2.0 * radius, 0.0)
    };
    Block { near, coverage, near_radius, far, far_radius, count, taken, taken_centre, taken_radius, taken_spread }
}

/// What the highlight path takes out of block (`hx`, `hy`): for each of its pixels, the share of
/// its excess over the background that is scattered, 0 unless the pixel is bright against the
/// background and blurred by at least [`HIGHLIGHT_MIN_RADIUS`]; continuous ramps in between. The
/// background is the ring of 12 pixels around the block (the 4x4 around it) less the pixels of
/// that ring more than [`HIGHLIGHT_CONTRAST`] times as bright as its darkest and as
/// `HIGHLIGHT_CONTRAST * HIGHLIGHT_MIN_EXCESS`: an emitter a few pixels wide that reaches past the
/// block lights part of its ring, which must not count as what it stands out from (with the plain
/// mean, a 3-pixel emitter across two blocks was bright against neither). Colours below that bound
/// are never left out. Each pixel is judged alone, so an emitter pixel in a block with its
/// background (at another depth, maybe the other side of the focus plane) is still taken, and the
/// disc has the CoC of what was taken.
fn highlight(p: &RingGatherParams, color: &impl Load, depth: &impl Load, hx: u32, hy: u32) -> Cut {
    // Twice over the ring: its darkest pixel, then the mean of what is not much brighter.
    let mut darkest = f32::MAX;
    let mut ring = [0.0f32; 3];
    let mut n = 0u32;
    let mut pass = 0u32;
    while pass < 2 {
        let bound = HIGHLIGHT_CONTRAST * maxf(darkest, HIGHLIGHT_MIN_EXCESS);
        let mut k = 0u32;
        while k < 16 {
            let (i, j) = (k % 4, k / 4);
            let inner = (i == 1 || i == 2) && (j == 1 || j == 2);
            let x = 2 * hx as i32 - 1 + i as i32;
            let y = 2 * hy as i32 - 1 + j as i32;
            if !inner && x >= 0 && y >= 0 && (x as u32) < p.width && (y as u32) < p.height {
                if let Some((c, _)) = sample(color, depth, y as u32 * p.width + x as u32) {
                    let l = luminance(c);
                    if pass == 0 {
                        darkest = minf(darkest, l);
                    } else if l <= bound {
                        ring = [ring[0] + c[0], ring[1] + c[1], ring[2] + c[2]];
                        n += 1;
                    }
                }
            }
            k += 1;
        }
        pass += 1;
    }
    if n == 0 {
        return NO_CUT;
    }
    let inv = 1.0 / n as f32;
    let ring = [ring[0] * inv, ring[1] * inv, ring[2] * inv];
    let lr = luminance(ring);
    let mut cut = Cut { share: [0.0; 4], over: ring };
    let mut k = 0u32;
    while k < 4 {
        let x = 2 * hx + k % 2;
        let y = 2 * hy + k / 2;
        if x < p.width && y < p.height {
            if let Some((c, z)) = sample(color, depth, y * p.width + x) {
                let blur = saturate((absf(signed_radius(&p.lens, z, p.max_radius as f32)) - HIGHLIGHT_MIN_RADIUS) / HIGHLIGHT_RAMP);
                let excess = [maxf(c[0] - ring[0], 0.0), maxf(c[1] - ring[1], 0.0), maxf(c[2] - ring[2], 0.0)];
                let (l, le) = (luminance(c), luminance(excess));
                let contrast = if l >= 2.0 * HIGHLIGHT_CONTRAST * lr {
                    1.0
                } else {
                    saturate((l - HIGHLIGHT_CONTRAST * lr) / (HIGHLIGHT_CONTRAST * lr))
                };
                let bright = saturate((le - HIGHLIGHT_MIN_EXCESS) / HIGHLIGHT_MIN_EXCESS);
                cut.share[k as usize] = blur * contrast * bright;
            }
        }
        k += 1;
    }
    cut
}

/// The signed radius (pixels) of the disc that draws what a cut took out of block `b`: the CoC of
/// that light, at least half a pixel (a disc of one pixel).
#[inline]
fn disc_radius(b: &Block) -> f32 {
    let r = b.taken_radius;
    if r < 0.0 { minf(r, -0.5) } else { maxf(r, 0.5) }
}

/// Stores the 9 words of a block's two samples at word `at` of `half`.
#[inline]
fn store_block<M: Mem>(half: &mut M, at: u32, b: &Block) {
    let words = [b.near[0], b.near[1], b.near[2], b.coverage, b.far[0], b.far[1], b.far[2], b.near_radius, b.far_radius];
    let mut w = 0usize;
    while w < 9 {
        half.store(at + w as u32, words[w].to_bits());
        w += 1;
    }
}

/// Copies the 2x2 pixels of block (`hx`, `hy`) from `color` to `fine` less what `cut` takes out of
/// them: the colours the full-resolution path reads. An unusable pixel is copied as it is, so it
/// stays unusable there.
fn store_fine<M: Mem>(p: &RingGatherParams, color: &impl Load, depth: &impl Load, fine: &mut M, hx: u32, hy: u32, cut: Cut) {
    let mut k = 0u32;
    while k < 4 {
        let x = 2 * hx + k % 2;
        let y = 2 * hy + k / 2;
        if x < p.width && y < p.height {
            let i = y * p.width + x;
            let mut words = [color.load(3 * i), color.load(3 * i + 1), color.load(3 * i + 2)];
            if cut.share[k as usize] > 0.0 {
                if let Some((c, _)) = sample(color, depth, i) {
                    let (c, _) = cut_pixel(c, cut, k);
                    words = [c[0].to_bits(), c[1].to_bits(), c[2].to_bits()];
                }
            }
            fine.store(3 * i, words[0]);
            fine.store(3 * i + 1, words[1]);
            fine.store(3 * i + 2, words[2]);
        }
        k += 1;
    }
}

/// One workgroup a tile (8x8 half-resolution pixels): the 2x2 reduction into `half`, the tile's
/// largest near-field radius (half-resolution pixels) into `tiles`, and its highlights (at most
/// [`HIGHLIGHTS_PER_TILE`], in pixel order) into `bright`, their excess taken out of `half` and
/// out of the full-resolution colours copied into `fine`; the highlights beyond a tile's cap are
/// added to word [`STATS_CAPPED`] of `stats`.
#[allow(clippy::too_many_arguments)]
pub fn downsample_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &RingGatherParams,
    sh: &mut [u32; 6 * 64],
    color: R,
    depth: R,
    mut half: M,
    mut tiles: M,
    mut bright: M,
    mut fine: M,
    mut stats: M,
) {
    let [tx, ty, _] = g.workgroup_id();
    let (hw, hh) = (p.half_width(), p.half_height());
    g.each(|lid| {
        let hx = tx * TILE + lid % TILE;
        let hy = ty * TILE + lid / TILE;
        let mut near = 0.0f32;
        let mut flagged = 0u32;
        let mut reach = 0.0f32;
        if hx < hw && hy < hh {
            let b = block(p, &color, &depth, hx, hy, NO_CUT);
            store_block(&mut half, HALF_WORDS * (hy * hw + hx), &b);
            if b.count > 0 {
                near = maxf(maxf(-b.near_radius, -b.far_radius), 0.0);
                let cut = highlight(p, &color, &depth, hx, hy);
                if cut.any() {
                    flagged = 1;
                    let b = block(p, &color, &depth, hx, hy, cut);
                    reach = absf(disc_radius(&b)) + b.taken_spread;
                }
            }
        }
        // Non-negative floats order like their bits.
        sh[lid as usize] = flagged;
        sh[128 + lid as usize] = near.to_bits();
        sh[256 + lid as usize] = reach.to_bits();
    });
    let slots = crate::wg::inclusive_scan(g, sh, 0, crate::wg::add);
    let m = crate::wg::inclusive_scan(g, sh, 128, crate::wg::max);
    let widest = crate::wg::inclusive_scan(g, sh, 256, crate::wg::max);
    let record = BRIGHT_TILE_WORDS * (ty * p.tiles_x() + tx);
    g.each(|lid| {
        let slot = sh[slots + lid as usize];
        let own = if lid == 0 { slot } else { slot - sh[slots + lid as usize - 1] };
        let hx = tx * TILE + lid % TILE;
        let hy = ty * TILE + lid / TILE;
        let mut cut = NO_CUT;
        if own == 1 && slot <= HIGHLIGHTS_PER_TILE {
            cut = highlight(p, &color, &depth, hx, hy);
            // The block again, each pixel less its excess over the background: the prefiltered
            // input of the gather, which the disc's energy comes out of exactly.
            let b = block(p, &color, &depth, hx, hy, cut);
            store_block(&mut half, HALF_WORDS * (hy * hw + hx), &b);
            // What was taken out, spread over the disc of the block's CoC, centred where its light was.
            let radius = disc_radius(&b);
            let (cx, cy) = (b.taken_centre[0], b.taken_centre[1]);
            let scale = 1.0 / disc_weight_sum(cx, cy, absf(radius), b.taken_spread);
            let h = record + 2 + HIGHLIGHT_WORDS * (slot - 1);
            bright.store(h, cx.to_bits());
            bright.store(h + 1, cy.to_bits());
            bright.store(h + 2, radius.to_bits());
            bright.store(h + 3, (b.taken[0] * scale).to_bits());
            bright.store(h + 4, (b.taken[1] * scale).to_bits());
            bright.store(h + 5, (b.taken[2] * scale).to_bits());
            bright.store(h + 6, b.taken_spread.to_bits());
            bright.store(h + 7, 0);
        }
        if hx < hw && hy < hh {
            store_fine(p, &color, &depth, &mut fine, hx, hy, cut);
        }
        if lid == 63 {
            tiles.store(ty * p.tiles_x() + tx, sh[m + 63]);
            let n = sh[slots + 63];
            bright.store(record, if n < HIGHLIGHTS_PER_TILE { n } else { HIGHLIGHTS_PER_TILE });
            bright.store(record + 1, sh[widest + 63]);
            if n > HIGHLIGHTS_PER_TILE {
                stats.atomic_add(STATS_CAPPED, n - HIGHLIGHTS_PER_TILE);
            }
        }
    });
}

/// One invocation a tile: the near-field radius dilated over the tiles that radius reaches
/// (measured from the nearest edges of the two tiles), itself included, and how far to look for
/// highlights whose disc reaches it. A neighbour's radius fades in over the last tile of its reach
/// instead of switching on, so the dilated radius (the near kernel's size) moves continuously.
pub fn dilate_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &RingGatherParams, tiles: R, bright: R, mut dilated: M) {
    let (tw, th) = (p.tiles_x(), p.tiles_y());
    let reach = p.dilation_tiles() as i32;
    crate::wg::for_each_item(g, tw * th, |t| {
        let (tx, ty) = ((t % tw) as i32, (t / tw) as i32);
        let mut widest = 0.0f32;
        let mut look = 0u32;
        let mut dy = -reach;
        while dy <= reach {
            let ny = ty + dy;
            let mut dx = -reach;
            while ny >= 0 && ny < th as i32 && dx <= reach {
                let nx = tx + dx;
                if nx >= 0 && nx < tw as i32 {
                    let n = ny as u32 * tw + nx as u32;
                    let gx = (maxf(absf(dx as f32) - 1.0, 0.0)) * TILE as f32;
                    let gy = (maxf(absf(dy as f32) - 1.0, 0.0)) * TILE as f32;
                    let gap = crate::math::sqrt(gx * gx + gy * gy);
                    let r = f32::from_bits(tiles.load(n));
                    widest = maxf(widest, r * saturate((r - gap) / TILE as f32 + 1.0));
                    // Highlights: radii in pixels of the frame, gaps in half-resolution pixels.
                    let record = BRIGHT_TILE_WORDS * n;
                    if bright.load(record) > 0 && f32::from_bits(bright.load(record + 1)) + 1.0 >= 2.0 * gap {
                        let side = maxf(absf(dx as f32), absf(dy as f32)) as u32 + 1;
                        look = if side > look { side } else { look };
                    }
                }
                dx += 1;
            }
            dy += 1;
        }
        dilated.store(DILATED_WORDS * t, widest.to_bits());
        dilated.store(DILATED_WORDS * t + 1, look);
    });
}

/// What one half-resolution pixel gathers, before normalising.
struct Fields {
    back: [f32; 3],
    back_weight: f32,
    /// What lies behind a near pixel: the background within the kernel, normalised on its own and
    /// blended with `back` by the pixel's near share.
    fill: [f32; 3],
    fill_weight: f32,
    near: [f32; 3],
    near_weight: f32,
}

impl Fields {
    /// Adds the background share of a sample of colour `c`, signed radius `s` and weight `m` (its
    /// share of its block) at distance `d` from a pixel of signed radius `own`, gathered by a kernel
    /// of `radius` and lattice `spacing`.
    #[allow(clippy::too_many_arguments)]
    #[inline]
    fn add_back(&mut self, c: [f32; 3], s: f32, m: f32, d: f32, own: f32, radius: f32, spacing: f32) {
        let w_back = m * (1.0 - near_share(s));
        if w_back <= 0.0 {
            return;
        }
        let own_back = maxf(own, 0.0);
        // Behind the pixel: at most the pixel's own CoC (never through a sharper object); else its
        // own blur, in front of the focus plane too (the part of a slightly near sample that stays
        // in the background field is as blurred as the sample).
        let reach = if s > own { minf(absf(s), own_back) } else { absf(s) };
        // A sample reaches the pixel over a soft edge half a lattice spacing wide.
        let cover = if d == 0.0 { 1.0 } else { saturate(reach - d + 0.5 * spacing) };
        let w = w_back * cover / maxf(reach * reach, 0.25);
        self.back = [self.back[0] + w * c[0], self.back[1] + w * c[1], self.back[2] + w * c[2]];
        self.back_weight += w;
        // Where the pixel itself is in the near field, what lies behind it is unknown in a single
        // layer: the background seen within the kernel (the samples behind the pixel) fills it
        // (where the near field is partly transparent, at its edges, this shows).
        if s > own && near_share(own) > 0.0 {
            let cover = saturate(radius - d + 0.5 * spacing);
            let w = w_back * cover / maxf(radius * radius, 0.25);
            self.fill = [self.fill[0] + w * c[0], self.fill[1] + w * c[1], self.fill[2] + w * c[2]];
            self.fill_weight += w;
        }
    }

    /// Adds the near share of a sample of weight `m`: the share of its CoC disc that one lattice
    /// cell covers.
    #[inline]
    fn add_near(&mut self, c: [f32; 3], s: f32, m: f32, d: f32, spacing: f32) {
        let n = m * near_share(s);
        if n <= 0.0 {
            return;
        }
        let reach = -s;
        let cell = 0.866_025_4 * spacing * spacing;
        let share = minf(cell / (core::f32::consts::PI * reach * reach), 1.0);
        let w = n * saturate(reach - d + 0.5 * spacing) * share;
        self.near = [self.near[0] + w * c[0], self.near[1] + w * c[1], self.near[2] + w * c[2]];
        self.near_weight += w;
    }

    /// Adds both samples of the half-resolution pixel at word `at` of `half` (its near part and
    /// the rest) to the fields `which`.
    #[allow(clippy::too_many_arguments)]
    #[inline]
    fn add_pixel(&mut self, half: &impl Load, at: u32, d: f32, own: f32, radius: f32, spacing: f32, which: u32) {
        let far_r = f32::from_bits(half.load(at + 8));
        if is_nan(far_r) {
            return;
        }
        let cov = f32::from_bits(half.load(at + 3));
        let colour =
            |o: u32| [f32::from_bits(half.load(at + o)), f32::from_bits(half.load(at + o + 1)), f32::from_bits(half.load(at + o + 2))];
        if cov > 0.0 {
            let (c, s) = (colour(0), f32::from_bits(half.load(at + 7)));
            if which & BACK != 0 {
                self.add_back(c, s, cov, d, own, radius, spacing);
            }
            if which & NEAR != 0 {
                self.add_near(c, s, cov, d, spacing);
            }
        }
        if cov < 1.0 {
            let c = colour(4);
            if which & BACK != 0 {
                self.add_back(c, far_r, 1.0 - cov, d, own, radius, spacing);
            }
            if which & NEAR != 0 {
                self.add_near(c, far_r, 1.0 - cov, d, spacing);
            }
        }
    }
}

/// Which fields a ring of samples feeds.
const BACK: u32 = 1;
const NEAR: u32 = 2;

/// The lattice of a kernel of `radius` (half-resolution pixels): its rings and their spacing. The
/// knob's rings spread over the radius, but never closer than one half-resolution pixel (they
/// would read the same pixels again), so a slightly blurred background costs what its blur needs.
/// The spacing moves continuously with the radius, and the rings reach half a spacing beyond it,
/// where every sample's weight has fallen to 0: a ring comes and goes with weight 0, so the ring
/// count never pops.
#[inline]
pub fn lattice(p: &RingGatherParams, radius: f32) -> (u32, f32) {
    let most = if p.rings == 0 { 1 } else { p.rings };
    let spacing = maxf(radius / most as f32, 1.0);
    let needed = crate::math::ceil(radius / spacing + 0.5);
    let rings = if needed < 1.0 {
        1
    } else if needed < most as f32 {
        needed as u32
    } else {
        most
    };
    (rings, spacing)
}

/// The samples of the hexagonal rings ([`lattice`]) of `radius` around (`hx`, `hy`) into the
/// fields `which`.
#[allow(clippy::too_many_arguments)]
fn rings_into(f: &mut Fields, half: &impl Load, p: &RingGatherParams, hx: u32, hy: u32, own: f32, radius: f32, which: u32) {
    let (hw, hh) = (p.half_width(), p.half_height());
    let (rings, spacing) = lattice(p, radius);
    let mut ring = 1u32;
    while ring <= rings {
        let mut j = 0u32;
        while j < 6 * ring {
            let o = hex_point(ring, j);
            let (ox, oy) = (o[0] * spacing, o[1] * spacing);
            // Clamp-to-edge: beyond the frame, the edge pixel.
            let sx = crate::math::floor(hx as f32 + 0.5 + ox);
            let sy = crate::math::floor(hy as f32 + 0.5 + oy);
            let sx = minf(maxf(sx, 0.0), (hw - 1) as f32) as u32;
            let sy = minf(maxf(sy, 0.0), (hh - 1) as f32) as u32;
            f.add_pixel(half, HALF_WORDS * (sy * hw + sx), crate::math::sqrt(ox * ox + oy * oy), own, radius, spacing, which);
            j += 1;
        }
        ring += 1;
    }
}

/// One workgroup a tile, one invocation a half-resolution pixel: both fields into `fields`. Each
/// field has its own kernel: the background one as wide as the pixel's own CoC (widening to the
/// near kernel by the pixel's near share, to fill behind it), the near one as wide as the
/// tile's dilated near radius; one set of rings serves both where the two radii agree.
pub fn gather_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &RingGatherParams, half: R, dilated: R, mut fields: M) {
    let [tx, ty, _] = g.workgroup_id();
    let (hw, hh) = (p.half_width(), p.half_height());
    g.each(|lid| {
        let hx = tx * TILE + lid % TILE;
        let hy = ty * TILE + lid / TILE;
        if hx >= hw || hy >= hh {
            return;
        }
        let at = HALF_WORDS * (hy * hw + hx);
        // The pixel's own radius: its two parts' by the near part's coverage.
        let cov = f32::from_bits(half.load(at + 3));
        let far_r = f32::from_bits(half.load(at + 8));
        let own = far_r + cov * (f32::from_bits(half.load(at + 7)) - far_r);
        let mut f = Fields { back: [0.0; 3], back_weight: 0.0, fill: [0.0; 3], fill_weight: 0.0, near: [0.0; 3], near_weight: 0.0 };
        let near_radius = f32::from_bits(dilated.load(DILATED_WORDS * (ty * p.tiles_x() + tx)));
        let own_valid = !is_nan(own);
        let own_r = if own_valid { own } else { 0.0 };
        // The background kernel is as wide as the pixel's own blur, either side of the focus plane
        // (a slightly near pixel's neighbours in front reach it by their own CoC), widening to the
        // near kernel by the pixel's near share: its rings never switch off while a neighbour they
        // hold still reaches the pixel. Written so that a wholly near pixel's is the near radius
        // exactly, and the two fields share their rings.
        let own_blur = absf(own_r);
        let share = near_share(own_r);
        let back_radius = (1.0 - share) * own_blur + share * maxf(near_radius, own_blur);
        if own_valid {
            f.add_pixel(&half, at, 0.0, own_r, back_radius, 1.0, BACK);
            f.add_pixel(&half, at, 0.0, own_r, near_radius, lattice(p, near_radius).1, NEAR);
        }
        let back = back_radius >= 0.5;
        let near = near_radius >= 0.5;
        if back && near && back_radius == near_radius {
            rings_into(&mut f, &half, p, hx, hy, own_r, back_radius, BACK | NEAR);
        } else {
            if back {
                rings_into(&mut f, &half, p, hx, hy, own_r, back_radius, BACK);
            }
            if near {
                rings_into(&mut f, &half, p, hx, hy, own_r, near_radius, NEAR);
            }
        }
        let at = FIELD_WORDS * (hy * hw + hx);
        // The pixel's own background and the fill, each normalised, blended by the pixel's near
        // share (so neither's sample count sways the other's weight as the kernel changes size).
        let normal = if f.back_weight > 0.0 {
            let inv = 1.0 / f.back_weight;
            [f.back[0] * inv, f.back[1] * inv, f.back[2] * inv]
        } else {
            [0.0; 3]
        };
        let (back, valid) = if f.fill_weight > 0.0 {
            let inv = 1.0 / f.fill_weight;
            let fill = [f.fill[0] * inv, f.fill[1] * inv, f.fill[2] * inv];
            let k = if f.back_weight > 0.0 { near_share(own_r) } else { 1.0 };
            ([normal[0] + k * (fill[0] - normal[0]), normal[1] + k * (fill[1] - normal[1]), normal[2] + k * (fill[2] - normal[2])], 1.0f32)
        } else if f.back_weight > 0.0 {
            (normal, 1.0f32)
        } else {
            ([0.0; 3], 0.0)
        };
        // Premultiplied near colour: its mean times its coverage (at most 1).
        let alpha = minf(f.near_weight, 1.0);
        let scale = if f.near_weight > 0.0 { alpha / f.near_weight } else { 0.0 };
        fields.store(at, back[0].to_bits());
        fields.store(at + 1, back[1].to_bits());
        fields.store(at + 2, back[2].to_bits());
        fields.store(at + 3, valid.to_bits());
        fields.store(at + 4, (f.near[0] * scale).to_bits());
        fields.store(at + 5, (f.near[1] * scale).to_bits());
        fields.store(at + 6, (f.near[2] * scale).to_bits());
        fields.store(at + 7, alpha.to_bits());
    });
}

/// The highlights' discs at pixel (`x`, `y`) of signed radius `own` (pixels; NaN: no valid pixel):
/// those behind the near field (far highlights) and those in front (near ones). A highlight behind
/// a sharper pixel reaches it by at most the pixel's own CoC, as in the gather; behind a pixel of
/// the near field it is the background the near field covers, and reaches it whole.
fn highlights_at(p: &RingGatherParams, bright: &impl Load, dilated: &impl Load, x: u32, y: u32, own: f32) -> ([f32; 3], [f32; 3]) {
    let mut far = [0.0f32; 3];
    let mut near = [0.0f32; 3];
    let (tw, th) = (p.tiles_x(), p.tiles_y());
    let (tx, ty) = (x / (2 * TILE), y / (2 * TILE));
    let look = dilated.load(DILATED_WORDS * (ty * tw + tx) + 1);
    if look == 0 {
        return (far, near);
    }
    let side = (look - 1) as i32;
    let (px, py) = (x as f32 + 0.5, y as f32 + 0.5);
    let own_known = !is_nan(own);
    let own_back = if own_known { maxf(own, 0.0) } else { 0.0 };
    // The pixel's near share, as the gather's (its radius in half-resolution pixels); an invalid
    // pixel is open to everything behind it.
    let open = if own_known { near_share(0.5 * own) } else { 1.0 };
    let mut dy = -side;
    while dy <= side {
        let ny = ty as i32 + dy;
        let mut dx = -side;
        while ny >= 0 && ny < th as i32 && dx <= side {
            let nx = tx as i32 + dx;
            if nx >= 0 && nx < tw as i32 {
                let record = BRIGHT_TILE_WORDS * (ny as u32 * tw + nx as u32);
                let n = bright.load(record);
                let mut k = 0u32;
                while k < n {
                    let h = record + 2 + HIGHLIGHT_WORDS * k;
                    let (cx, cy, s) =
                        (f32::from_bits(bright.load(h)), f32::from_bits(bright.load(h + 1)), f32::from_bits(bright.load(h + 2)));
                    let (ox, oy) = (px - cx, py - cy);
                    let d = crate::math::sqrt(ox * ox + oy * oy);
                    let radius = absf(s);
                    let reach = if s < 0.0 {
                        radius
                    } else {
                        let limited = minf(radius, own_back);
                        limited + open * (radius - limited)
                    };
                    let spread = f32::from_bits(bright.load(h + 6));
                    if d < reach + 0.5 + spread {
                        let w = disc_weight(reach, spread, d);
                        let c =
                            [f32::from_bits(bright.load(h + 3)), f32::from_bits(bright.load(h + 4)), f32::from_bits(bright.load(h + 5))];
                        if s < 0.0 {
                            near = [near[0] + w * c[0], near[1] + w * c[1], near[2] + w * c[2]];
                        } else {
                            far = [far[0] + w * c[0], far[1] + w * c[1], far[2] + w * c[2]];
                        }
                    }
                    k += 1;
                }
            }
            dx += 1;
        }
        dy += 1;
    }
    (far, near)
}

/// The full-resolution path for a pixel in focus or slightly blurred (own colour `c`, signed radius
/// `own` in pixels): scatter as gather over the 3x3 pixels around, as the exhaustive gather does,
/// each radius capped at [`FINE_REACH`] (what the 3x3 window holds; the blend hands over to the
/// background field by 2 px), near-field neighbours left to the near field, and a neighbour behind the pixel reaching
/// it by at most the pixel's own CoC. Written as the pixel's colour plus the weighted differences,
/// so a pixel no neighbour reaches keeps its colour bit for bit.
fn fine_gather(p: &RingGatherParams, color: &impl Load, depth: &impl Load, x: u32, y: u32, c: [f32; 3], own: f32) -> [f32; 3] {
    let own_back = maxf(own, 0.0);
    let mut delta = [0.0f32; 3];
    let own_reach = minf(absf(own), FINE_REACH);
    let mut weight = saturate(own_reach + 0.5) / maxf(own_reach * own_reach, 0.25);
    let mut k = 0u32;
    while k < 9 {
        let (dx, dy) = ((k % 3) as i32 - 1, (k / 3) as i32 - 1);
        let (qx, qy) = (x as i32 + dx, y as i32 + dy);
        if k != 4 && qx >= 0 && qy >= 0 && (qx as u32) < p.width && (qy as u32) < p.height {
            if let Some((cq, zq)) = sample(color, depth, qy as u32 * p.width + qx as u32) {
                let r = signed_radius(&p.lens, zq, p.max_radius as f32);
                let reach = minf(if r > own { minf(absf(r), own_back) } else { absf(r) }, FINE_REACH);
                let d = crate::math::sqrt((dx * dx + dy * dy) as f32);
                // The edge eases in (squared): a neighbour starts to reach the pixel with a weight
                // that grows from 0 with zero slope, so a radius crossing 1/2 px does not pop.
                let edge = saturate(reach - d + 0.5);
                let w = (1.0 - near_weight(r)) * edge * edge / maxf(reach * reach, 0.25);
                if w > 0.0 {
                    delta = [delta[0] + w * (cq[0] - c[0]), delta[1] + w * (cq[1] - c[1]), delta[2] + w * (cq[2] - c[2])];
                    weight += w;
                }
            }
        }
        k += 1;
    }
    let inv = 1.0 / weight;
    [c[0] + delta[0] * inv, c[1] + delta[1] * inv, c[2] + delta[2] * inv]
}

/// The largest radius (pixels) the full-resolution path spreads a pixel over: a 3x3 window.
pub const FINE_REACH: f32 = 1.5;

/// One invocation a pixel of an 8x8 tile: its own colour, the background field by its CoC, the
/// far highlights' discs, the near field over them, the near highlights' discs on top, into `out`
/// (3 words a pixel). The pixels' colours come from `fine`: the input less what the highlight path
/// took out of it.
#[allow(clippy::too_many_arguments)]
pub fn composite_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &RingGatherParams,
    fine: R,
    depth: R,
    fields: R,
    bright: R,
    dilated: R,
    mut out: M,
) {
    let [wx, wy, _] = g.workgroup_id();
    let (hw, hh) = (p.half_width(), p.half_height());
    g.each(|lid| {
        let x = wx * 8 + lid % 8;
        let y = wy * 8 + lid / 8;
        if x >= p.width || y >= p.height {
            return;
        }
        // Bilinear weights of the four half-resolution pixels around this pixel's centre.
        let u = maxf((x as f32 + 0.5) * 0.5 - 0.5, 0.0);
        let v = maxf((y as f32 + 0.5) * 0.5 - 0.5, 0.0);
        let (x0, y0) = (crate::math::floor(u), crate::math::floor(v));
        let (fx, fy) = (u - x0, v - y0);
        let (x0, y0) = (x0 as u32, y0 as u32);
        let mut back = [0.0f32; 3];
        let mut back_weight = 0.0f32;
        let mut near = [0.0f32; 4];
        let mut k = 0u32;
        while k < 4 {
            let hx = if x0 + k % 2 < hw { x0 + k % 2 } else { hw - 1 };
            let hy = if y0 + k / 2 < hh { y0 + k / 2 } else { hh - 1 };
            let w = (if k % 2 == 0 { 1.0 - fx } else { fx }) * (if k / 2 == 0 { 1.0 - fy } else { fy });
            let at = FIELD_WORDS * (hy * hw + hx);
            let valid = f32::from_bits(fields.load(at + 3));
            let wb = w * valid;
            let mut c = 0u32;
            while c < 3 {
                back[c as usize] += wb * f32::from_bits(fields.load(at + c));
                c += 1;
            }
            back_weight += wb;
            let mut n = 0u32;
            while n < 4 {
                near[n as usize] += w * f32::from_bits(fields.load(at + 4 + n));
                n += 1;
            }
            k += 1;
        }
        let i = y * p.width + x;
        let mut base = [0.0f32; 3];
        let mut own = f32::NAN;
        if let Some((c, z)) = sample(&fine, &depth, i) {
            own = signed_radius(&p.lens, z, p.max_radius as f32);
            // Below a 1 px radius the full-resolution gather of the 3x3 pixels around, from 2 px
            // the background field, a blend between.
            let t = saturate(absf(own) - 1.0);
            base = if t < 1.0 { fine_gather(p, &fine, &depth, x, y, c, own) } else { c };
            if t > 0.0 && back_weight > 0.0 {
                let inv = 1.0 / back_weight;
                let mut ch = 0usize;
                while ch < 3 {
                    base[ch] += t * (back[ch] * inv - base[ch]);
                    ch += 1;
                }
            }
        } else if back_weight > 0.0 {
            let inv = 1.0 / back_weight;
            base = [back[0] * inv, back[1] * inv, back[2] * inv];
        }
        let (far_hl, near_hl) = highlights_at(p, &bright, &dilated, x, y, own);
        base = [base[0] + far_hl[0], base[1] + far_hl[1], base[2] + far_hl[2]];
        let alpha = near[3];
        if alpha > 0.0 {
            let keep = 1.0 - alpha;
            base = [base[0] * keep + near[0], base[1] * keep + near[1], base[2] * keep + near[2]];
        }
        base = [base[0] + near_hl[0], base[1] + near_hl[1], base[2] + near_hl[2]];
        out.store(3 * i, base[0].to_bits());
        out.store(3 * i + 1, base[1].to_bits());
        out.store(3 * i + 2, base[2].to_bits());
    });
}

kernel!(
    /// Half-resolution colour and signed CoC, each tile's largest near-field radius and its highlights, taken out of the full-resolution colours.
    RING_GATHER_DOWNSAMPLE = ring_gather_downsample [64] (RingGatherParams) shared [u32; 6 * 64]
        { read color, read depth, half, tiles, bright, fine, stats } => downsample_pass
);
kernel!(
    /// Each tile's near-field radius dilated over the tiles it reaches, and its highlight reach.
    RING_GATHER_DILATE = ring_gather_dilate [64] (RingGatherParams) { read tiles, read bright, dilated } => dilate_pass
);
kernel!(
    /// The background and near fields at half resolution, over hexagonal sample rings.
    RING_GATHER = ring_gather [64] (RingGatherParams) { read half, read dilated, fields } => gather_pass
);
kernel!(
    /// The full-resolution composite of the pixel, the background field, the near field and the highlights' discs.
    RING_GATHER_COMPOSITE = ring_gather_composite [64] (RingGatherParams)
        { read fine, read depth, read fields, read bright, read dilated, out } => composite_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 4] = [&RING_GATHER_DOWNSAMPLE, &RING_GATHER_DILATE, &RING_GATHER, &RING_GATHER_COMPOSITE];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hexagonal_rings_are_distinct_lattice_points_at_the_ring_distance() {
        for ring in 1..=8u32 {
            let mut seen: Vec<[i64; 2]> = Vec::new();
            for j in 0..6 * ring {
                let q = hex_point(ring, j);
                // On the hexagon of "radius" `ring`: between its inradius and its circumradius.
                let d = (q[0] * q[0] + q[1] * q[1]).sqrt();
                assert!(d >= ring as f32 * 0.866 - 1e-4 && d <= ring as f32 + 1e-4, "ring {ring} point {j}: {d}");
                let key = [(q[0] * 1000.0).round() as i64, (q[1] * 1000.0).round() as i64];
                assert!(!seen.contains(&key), "ring {ring} repeats {q:?}");
                seen.push(key);
            }
        }
        assert_eq!(samples(5), 91);
    }
}
