//! Pass 3: the background and near fields at half resolution, over hexagonal sample rings.

use super::*;

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
