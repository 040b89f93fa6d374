//! Pass 4: the full-resolution composite of the pixel, the background field, the near field and
//! the highlights' discs.

use super::*;

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
