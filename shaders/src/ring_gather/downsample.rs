//! Pass 1: half-resolution colour and signed CoC split into a near part and the rest, each tile's
//! largest near-field radius, and the highlights taken out of the full-resolution colours.

use super::*;

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
    let slots = crate::wg::inclusive_scan(g, sh, 0, crate::wg::Add);
    let m = crate::wg::inclusive_scan(g, sh, 128, crate::wg::Max);
    let widest = crate::wg::inclusive_scan(g, sh, 256, crate::wg::Max);
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
