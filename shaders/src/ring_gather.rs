//! An engine-grade gathering depth of field, the kind shipping renderers use by default, built from
//! the published descriptions of AMD FidelityFX DoF, Unreal Engine's Diaphragm DoF and Jimenez 2014
//! ("Next-Generation Post-Processing in Call of Duty: Advanced Warfare"): half-resolution colour and
//! CoC, per-tile near-field CoC dilated over the neighbouring tiles, a fixed budget of sample rings,
//! a background field and a near field gathered separately and composited at full resolution with
//! the near field's coverage as alpha, and a full-resolution path for what is in focus or slightly
//! blurred.
//!
//! Four passes (all sizes in the frame's pixels unless said "half"):
//! 1. [`downsample_pass`]: every half-resolution pixel averages its 2x2 pixels' colours and signed
//!    CoC radii (taking the strongest near-field radius and only the near pixels' colour where one
//!    is strongly in front, so foreground silhouettes survive the reduction); each 8x8 tile of them
//!    reduces its largest near-field radius.
//! 2. [`dilate_pass`]: every tile takes the largest near radius of the tiles that radius reaches,
//!    so a blurred foreground spreads over the sharp tiles beside it (Unreal's "foreground hole
//!    filling", FidelityFX's tile dilation).
//! 3. [`gather_pass`]: every half-resolution pixel reads `1 + 3 R (R + 1)` samples on `R` hexagonal
//!    rings (ring `i` holds `6 i` points of a hexagonal lattice, so the samples cover the disc with
//!    uniform density and no trigonometry), spread over its kernel radius: the larger of its own
//!    background CoC and its tile's dilated near radius. Two fields:
//!    - background: scatter-as-gather as in [`crate::gather`], each sample weighted by its coverage
//!      over the inverse of its CoC area, a sample behind the pixel reaching at most the pixel's own
//!      CoC (so a blurred background does not smear over a sharper object); where the pixel itself
//!      is in the near field, the background seen within the kernel fills in what it hides;
//!    - near: samples strongly in front, each adding the share of its CoC disc that one lattice cell
//!      covers; their sum is the near field's coverage (alpha, 1 for a uniform near field), their
//!      weighted mean its colour.
//! 4. [`composite_pass`]: every pixel blends its own colour with the background field, upsampled
//!    bilinearly, by its CoC (the full-resolution colour below a 1 px radius, the background field
//!    from 2 px), then the near field over it by its coverage.
//!
//! Samples beyond the frame's edge take the edge pixel (clamp-to-edge addressing), so a blurred
//! object cut by the frame keeps its full coverage there. Non-finite colours and depths are skipped
//! as in the exhaustive gather. What it cannot do, by construction: show what a blurred foreground
//! hides (a single layer), honour CoCs beyond its radius cap, or resolve blur larger than its ring
//! spacing allows (with few rings a large blur is sampled sparsely).

use crate::exec::{Group, Mem};
use crate::lens::{ThinLens, is_finite as finite, is_nan, is_pos_inf, is_positive};

/// Half-resolution pixels on a side of a tile (tiles are 16x16 pixels of the frame).
pub const TILE: u32 = 8;
/// A half-resolution pixel's 4 words: colour, then its signed CoC radius in half-resolution pixels
/// (NaN where none of its pixels was valid).
pub const HALF_WORDS: u32 = 4;
/// A half-resolution pixel's 8 words in the fields buffer: the background field's colour and 1 (0
/// where nothing was gathered), then the near field's premultiplied colour and coverage.
pub const FIELD_WORDS: u32 = 8;
/// A half-resolution sample counts in the near field only when its near CoC radius exceeds this (in
/// half-resolution pixels): nearly sharp samples belong to the background field.
pub const NEAR_MIN_RADIUS: f32 = 0.5;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct RingGatherParams {
    pub width: u32,
    pub height: u32,
    /// Sample rings (the quality knob): `1 + 3 R (R + 1)` samples a half-resolution pixel.
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
        self.max_radius.div_ceil(2 * TILE)
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

/// Signed CoC radius in pixels of a sample at depth `z` (negative in front of the focus plane),
/// within `±cap`; the sky (`+inf`) takes the far-field limit. Only for valid depths.
#[inline]
pub fn signed_radius(lens: &ThinLens, z: f32, cap: f32) -> f32 {
    let r = if is_pos_inf(z) { 0.5 * lens.far_limit_px() } else { 0.5 * lens.signed_coc_px(z) };
    maxf(minf(r, cap), -cap)
}

/// The colour of pixel `i` with its depth, or `None` when either is unusable.
#[inline]
fn sample<M: Mem>(color: &M, depth: &M, i: u32) -> Option<([f32; 3], f32)> {
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

/// One workgroup a tile (8x8 half-resolution pixels): the 2x2 reduction into `half`, and the tile's
/// largest near-field radius (half-resolution pixels) into `tiles`.
pub fn downsample_pass<G: Group, M: Mem>(
    g: &mut G,
    p: &RingGatherParams,
    sh: &mut [u32; 2 * 64],
    color: M,
    depth: M,
    mut half: M,
    mut tiles: M,
) {
    let [tx, ty, _] = g.workgroup_id();
    let (hw, hh) = (p.half_width(), p.half_height());
    let cap = p.max_radius as f32;
    g.each(|lid| {
        let hx = tx * TILE + lid % TILE;
        let hy = ty * TILE + lid / TILE;
        let mut near = 0.0f32;
        if hx < hw && hy < hh {
            let mut sum = [0.0f32; 3];
            let mut sum_r = 0.0f32;
            let mut count = 0u32;
            let mut near_sum = [0.0f32; 3];
            let mut near_count = 0u32;
            let mut strongest = 0.0f32;
            let mut k = 0u32;
            while k < 4 {
                let x = 2 * hx + k % 2;
                let y = 2 * hy + k / 2;
                if x < p.width && y < p.height {
                    if let Some((c, z)) = sample(&color, &depth, y * p.width + x) {
                        let r = signed_radius(&p.lens, z, cap);
                        sum = [sum[0] + c[0], sum[1] + c[1], sum[2] + c[2]];
                        sum_r += r;
                        count += 1;
                        // "Strongly in front": more than one half-resolution pixel of near blur.
                        if r < -2.0 {
                            near_sum = [near_sum[0] + c[0], near_sum[1] + c[1], near_sum[2] + c[2]];
                            near_count += 1;
                            strongest = minf(strongest, r);
                        }
                    }
                }
                k += 1;
            }
            let at = HALF_WORDS * (hy * hw + hx);
            if count == 0 {
                half.store(at, 0);
                half.store(at + 1, 0);
                half.store(at + 2, 0);
                half.store(at + 3, f32::NAN.to_bits());
            } else {
                let (c, n, r) = if near_count > 0 { (near_sum, near_count, strongest) } else { (sum, count, sum_r / count as f32) };
                let inv = 1.0 / n as f32;
                half.store(at, (c[0] * inv).to_bits());
                half.store(at + 1, (c[1] * inv).to_bits());
                half.store(at + 2, (c[2] * inv).to_bits());
                let r_half = 0.5 * r;
                half.store(at + 3, r_half.to_bits());
                near = maxf(-r_half, 0.0);
            }
        }
        // Non-negative floats order like their bits.
        sh[lid as usize] = near.to_bits();
    });
    let m = crate::wg::inclusive_scan(g, sh, 0, crate::wg::max);
    g.each(|lid| {
        if lid == 63 {
            tiles.store(ty * p.tiles_x() + tx, sh[m + 63]);
        }
    });
}

/// One invocation a tile: the largest near-field radius among the tiles whose radius reaches it
/// (measured from the nearest edges of the two tiles), itself included.
pub fn dilate_pass<G: Group, M: Mem>(g: &mut G, p: &RingGatherParams, tiles: M, mut dilated: M) {
    let (tw, th) = (p.tiles_x(), p.tiles_y());
    let reach = p.dilation_tiles() as i32;
    crate::wg::for_each_item(g, tw * th, |t| {
        let (tx, ty) = ((t % tw) as i32, (t / tw) as i32);
        let mut widest = 0.0f32;
        let mut dy = -reach;
        while dy <= reach {
            let ny = ty + dy;
            let mut dx = -reach;
            while ny >= 0 && ny < th as i32 && dx <= reach {
                let nx = tx + dx;
                if nx >= 0 && nx < tw as i32 {
                    let r = f32::from_bits(tiles.load(ny as u32 * tw + nx as u32));
                    let gx = (maxf(absf(dx as f32) - 1.0, 0.0)) * TILE as f32;
                    let gy = (maxf(absf(dy as f32) - 1.0, 0.0)) * TILE as f32;
                    if r * r >= gx * gx + gy * gy {
                        widest = maxf(widest, r);
                    }
                }
                dx += 1;
            }
            dy += 1;
        }
        dilated.store(t, widest.to_bits());
    });
}

/// The sampling of one half-resolution pixel (radii and distances in half-resolution pixels).
struct Kernel {
    /// The pixel's own signed CoC radius (0 where it has none).
    own: f32,
    /// The kernel radius: the larger of the tile's dilated near radius and the own background radius.
    radius: f32,
    /// The lattice spacing and the area of one lattice cell.
    spacing: f32,
    cell: f32,
}

/// What one half-resolution pixel gathers, before normalising.
struct Fields {
    back: [f32; 3],
    back_weight: f32,
    near: [f32; 3],
    near_weight: f32,
}

impl Fields {
    /// Adds a sample of colour `c` and signed radius `s` at distance `d` from the pixel.
    #[inline]
    fn add(&mut self, c: [f32; 3], s: f32, d: f32, k: &Kernel) {
        // A sample reaches the pixel over a soft edge half a lattice spacing wide.
        let soft = 0.5 * k.spacing;
        if s < -NEAR_MIN_RADIUS {
            let reach = -s;
            let share = minf(k.cell / (core::f32::consts::PI * reach * reach), 1.0);
            let w = saturate(reach - d + soft) * share;
            self.near = [self.near[0] + w * c[0], self.near[1] + w * c[1], self.near[2] + w * c[2]];
            self.near_weight += w;
        } else {
            let s = maxf(s, 0.0);
            let reach = if k.own < -NEAR_MIN_RADIUS {
                // The pixel is in the near field: what lies behind it is unknown in a single
                // layer, so the background field fills it with the background seen within the
                // kernel (where the near field is partly transparent, at its edges, this shows).
                k.radius
            } else if s > k.own {
                // Behind the pixel: at most the pixel's own CoC (never through a sharper object).
                minf(s, maxf(k.own, 0.0))
            } else {
                s
            };
            let cover = if d == 0.0 { 1.0 } else { saturate(reach - d + soft) };
            let w = cover / maxf(reach * reach, 0.25);
            self.back = [self.back[0] + w * c[0], self.back[1] + w * c[1], self.back[2] + w * c[2]];
            self.back_weight += w;
        }
    }
}

/// One workgroup a tile, one invocation a half-resolution pixel: both fields into `fields`.
pub fn gather_pass<G: Group, M: Mem>(g: &mut G, p: &RingGatherParams, half: M, dilated: M, mut fields: M) {
    let [tx, ty, _] = g.workgroup_id();
    let (hw, hh) = (p.half_width(), p.half_height());
    g.each(|lid| {
        let hx = tx * TILE + lid % TILE;
        let hy = ty * TILE + lid / TILE;
        if hx >= hw || hy >= hh {
            return;
        }
        let load = |x: u32, y: u32| {
            let at = HALF_WORDS * (y * hw + x);
            let c = [f32::from_bits(half.load(at)), f32::from_bits(half.load(at + 1)), f32::from_bits(half.load(at + 2))];
            (c, f32::from_bits(half.load(at + 3)))
        };
        let (own_c, own) = load(hx, hy);
        let mut f = Fields { back: [0.0; 3], back_weight: 0.0, near: [0.0; 3], near_weight: 0.0 };
        let rings = if p.rings == 0 { 1 } else { p.rings };
        let near_reach = f32::from_bits(dilated.load(ty * p.tiles_x() + tx));
        let own_valid = !is_nan(own);
        let own_r = if own_valid { own } else { 0.0 };
        let radius = maxf(near_reach, own_r);
        let spacing = radius / rings as f32;
        let k = Kernel { own: own_r, radius, spacing, cell: 0.866_025_4 * spacing * spacing };
        if own_valid {
            f.add(own_c, own, 0.0, &k);
        }
        if radius >= 0.5 {
            let mut ring = 1u32;
            while ring <= rings {
                let mut j = 0u32;
                while j < 6 * ring {
                    let o = hex_point(ring, j);
                    let (ox, oy) = (o[0] * k.spacing, o[1] * k.spacing);
                    // Clamp-to-edge: beyond the frame, the edge pixel.
                    let sx = crate::math::floor(hx as f32 + 0.5 + ox);
                    let sy = crate::math::floor(hy as f32 + 0.5 + oy);
                    let sx = minf(maxf(sx, 0.0), (hw - 1) as f32) as u32;
                    let sy = minf(maxf(sy, 0.0), (hh - 1) as f32) as u32;
                    let (c, s) = load(sx, sy);
                    if !is_nan(s) {
                        f.add(c, s, crate::math::sqrt(ox * ox + oy * oy), &k);
                    }
                    j += 1;
                }
                ring += 1;
            }
        }
        let at = FIELD_WORDS * (hy * hw + hx);
        let (back, valid) = if f.back_weight > 0.0 {
            let inv = 1.0 / f.back_weight;
            ([f.back[0] * inv, f.back[1] * inv, f.back[2] * inv], 1.0f32)
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

/// One invocation a pixel of an 8x8 tile: its own colour, the background field by its CoC, the
/// near field over both, into `out` (3 words a pixel).
pub fn composite_pass<G: Group, M: Mem>(g: &mut G, p: &RingGatherParams, color: M, depth: M, fields: M, mut out: M) {
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
        if let Some((c, z)) = sample(&color, &depth, i) {
            base = c;
            // In focus below a 1 px radius (the full-resolution colour as it is), the background
            // field from 2 px, a blend between.
            let t = saturate(absf(signed_radius(&p.lens, z, p.max_radius as f32)) - 1.0);
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
        let alpha = near[3];
        if alpha > 0.0 {
            let keep = 1.0 - alpha;
            base = [base[0] * keep + near[0], base[1] * keep + near[1], base[2] * keep + near[2]];
        }
        out.store(3 * i, base[0].to_bits());
        out.store(3 * i + 1, base[1].to_bits());
        out.store(3 * i + 2, base[2].to_bits());
    });
}

kernel!(
    /// Half-resolution colour and signed CoC, and each tile's largest near-field radius.
    RING_GATHER_DOWNSAMPLE = ring_gather_downsample [64] (RingGatherParams) shared [u32; 2 * 64] { color, depth, half, tiles } reads { color, depth } => downsample_pass
);
kernel!(
    /// Each tile's near-field radius dilated over the tiles it reaches.
    RING_GATHER_DILATE = ring_gather_dilate [64] (RingGatherParams) { tiles, dilated } reads { tiles } => dilate_pass
);
kernel!(
    /// The background and near fields at half resolution, over hexagonal sample rings.
    RING_GATHER = ring_gather [64] (RingGatherParams) { half, dilated, fields } reads { half, dilated } => gather_pass
);
kernel!(
    /// The full-resolution composite of the pixel, the background field and the near field.
    RING_GATHER_COMPOSITE = ring_gather_composite [64] (RingGatherParams) { color, depth, fields, out } reads { color, depth, fields } => composite_pass
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
