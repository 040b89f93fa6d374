//! Texture lookups for the mesh shading. One texel buffer holds every texture with its mip chain
//! (linear RGBA as half floats, [`TEXEL_WORDS`] words a texel: `r | g << 16`, `b | a << 16`), each
//! described by a [`TextureInfo`]; level `l` is `max(1, width >> l)` by `max(1, height >> l)`
//! texels, right after level `l - 1`, each texel the area average of the level above it.
//!
//! A lookup filters over the pixel's footprint ([`UvFootprint`]: the pixel's square carried onto
//! the surface, a parallelogram in the texture): where it covers less than a texel, the finest
//! level, bilinear (or nearest, as the sampler says); where it covers more, a box filter over the
//! parallelogram by quadrature: a grid of probes spread evenly over it (up to
//! [`MAX_PROBES_ACROSS`] along its shorter side and [`MAX_PROBES`] in all), each a trilinear mip
//! lookup at the level whose texels match the probes' spacing. A box over the pixel is what a
//! renderer that samples the pixel's area finely (a path tracer with a box pixel filter) sees;
//! one trilinear lookup (a GPU's isotropic filter) blurs a square texture up to twice as wide,
//! and aligns its boxes with the mip grid. Every step is arithmetic and bit operations, the same
//! on both targets.

use super::mesh::{
    LEVELS_MASK, LEVELS_SHIFT, NEAREST, NO_TEXTURE, TEXEL_WORDS, TEXTURE_WORDS, WRAP_CLAMP, WRAP_MIRROR, WRAP_S_SHIFT, WRAP_T_SHIFT,
};
use crate::exec::Load;
use crate::math::{ceil, floor, maxf, minf, sqrt};

/// Most probes a lookup takes over its footprint.
pub const MAX_PROBES: u32 = 64;
/// Most probes across its footprint's shorter side.
pub const MAX_PROBES_ACROSS: u32 = 8;

#[inline]
pub fn load_f32(m: &impl Load, i: u32) -> f32 {
    f32::from_bits(m.load(i))
}

/// The half float in the low 16 bits of `h`, exactly (every half is an f32).
#[inline]
pub fn half_to_f32(h: u32) -> f32 {
    let sign = if h & 0x8000 != 0 { -1.0 } else { 1.0 };
    let exponent = (h >> 10) & 0x1f;
    let mantissa = h & 0x3ff;
    if exponent == 0 {
        // Zero or subnormal: mantissa · 2^-24, a product of exact values.
        return sign * mantissa as f32 * (1.0 / 16_777_216.0);
    }
    let bits = if exponent == 0x1f { 0x7f80_0000 | (mantissa << 13) } else { ((exponent + 112) << 23) | (mantissa << 13) };
    sign * f32::from_bits(bits)
}

/// `log2(x)` for finite `x >= 1`, within 0.0011: the exponent from the bits plus a cubic in the
/// mantissa that is exact at both ends (a level of detail needs no more).
#[inline]
pub fn log2_level(x: f32) -> f32 {
    let bits = x.to_bits();
    let exponent = ((bits >> 23) & 0xff) as i32 - 127;
    let m = f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000) - 1.0;
    exponent as f32 + m * (1.420_864_5 + m * (-0.577_250_6 + m * 0.156_386_1))
}

/// A linear RGBA value.
#[derive(Clone, Copy, Default)]
pub struct Rgba {
    pub r: f32,
    pub g: f32,
    pub b: f32,
    pub a: f32,
}

impl Rgba {
    pub const WHITE: Rgba = Rgba { r: 1.0, g: 1.0, b: 1.0, a: 1.0 };

    /// `self + (other - self) · t`.
    #[inline]
    fn lerp(self, other: Rgba, t: f32) -> Rgba {
        Rgba {
            r: self.r + (other.r - self.r) * t,
            g: self.g + (other.g - self.g) * t,
            b: self.b + (other.b - self.b) * t,
            a: self.a + (other.a - self.a) * t,
        }
    }

    #[inline]
    fn add(self, other: Rgba) -> Rgba {
        Rgba { r: self.r + other.r, g: self.g + other.g, b: self.b + other.b, a: self.a + other.a }
    }

    #[inline]
    fn scale(self, s: f32) -> Rgba {
        Rgba { r: self.r * s, g: self.g * s, b: self.b * s, a: self.a * s }
    }
}

/// How a pixel's footprint maps into texture coordinates: the change of `(u, v)` across the pixel
/// along its two sides, `a` and `b`. [`UvFootprint::POINT`] reads the finest level.
#[derive(Clone, Copy, Default)]
pub struct UvFootprint {
    pub du_a: f32,
    pub dv_a: f32,
    pub du_b: f32,
    pub dv_b: f32,
}

impl UvFootprint {
    pub const POINT: UvFootprint = UvFootprint { du_a: 0.0, dv_a: 0.0, du_b: 0.0, dv_b: 0.0 };
}

/// Texel index along one axis of `size` texels for the integer coordinate `i` under `wrap`.
#[inline]
fn wrap_index(i: i32, size: u32, wrap: u32) -> u32 {
    let n = size as i32;
    let r = if wrap == WRAP_CLAMP {
        if i < 0 {
            0
        } else if i >= n {
            n - 1
        } else {
            i
        }
    } else if wrap == WRAP_MIRROR {
        let period = 2 * n;
        let m = ((i % period) + period) % period;
        if m < n { m } else { period - 1 - m }
    } else {
        ((i % n) + n) % n
    };
    r as u32
}

/// One level of a texture: its first texel, its size and the sampler's wrap modes.
#[derive(Clone, Copy)]
struct Level {
    offset: u32,
    width: u32,
    height: u32,
    wrap_s: u32,
    wrap_t: u32,
}

impl Level {
    /// Level `l` of the texture whose finest level is `base`.
    fn of(base: Level, l: u32) -> Level {
        let mut level = base;
        let mut k = 0;
        while k < l {
            level.offset += level.width * level.height;
            level.width = if level.width > 1 { level.width >> 1 } else { 1 };
            level.height = if level.height > 1 { level.height >> 1 } else { 1 };
            k += 1;
        }
        level
    }

    #[inline]
    fn texel(&self, texels: &impl Load, x: u32, y: u32) -> Rgba {
        let at = (self.offset + y * self.width + x) * TEXEL_WORDS;
        let (rg, ba) = (texels.load(at), texels.load(at + 1));
        Rgba { r: half_to_f32(rg & 0xffff), g: half_to_f32(rg >> 16), b: half_to_f32(ba & 0xffff), a: half_to_f32(ba >> 16) }
    }

    /// Bilinear between the four texel centres around `(u, v)`; with `nearest`, the texel that
    /// holds `(u, v)` (the same four reads, weighted 1, 0, 0, 0: one code path for both).
    fn read(&self, texels: &impl Load, u: f32, v: f32, nearest: bool) -> Rgba {
        let centre = if nearest { 0.0 } else { 0.5 };
        let (fx, fy) = (u * self.width as f32 - centre, v * self.height as f32 - centre);
        let (x0, y0) = (floor(fx), floor(fy));
        let (ax, ay) = if nearest { (0.0, 0.0) } else { (fx - x0, fy - y0) };
        let (x0, y0) = (x0 as i32, y0 as i32);
        let xa = wrap_index(x0, self.width, self.wrap_s);
        let xb = wrap_index(x0 + 1, self.width, self.wrap_s);
        let ya = wrap_index(y0, self.height, self.wrap_t);
        let yb = wrap_index(y0 + 1, self.height, self.wrap_t);
        let top = self.texel(texels, xa, ya).lerp(self.texel(texels, xb, ya), ax);
        let bottom = self.texel(texels, xa, yb).lerp(self.texel(texels, xb, yb), ax);
        top.lerp(bottom, ay)
    }
}

/// How many probes a minified lookup may take: at most `most` in all and `across` along the
/// footprint's shorter side. Made once for a pass ([`Probes::at_most`], on the host), so the lookup
/// itself has no loop to size its grid.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Probes {
    pub most: u32,
    pub across: u32,
}

impl Probes {
    /// The box filter in full: [`MAX_PROBES`], [`MAX_PROBES_ACROSS`] across.
    pub const FULL: Probes = Probes { most: MAX_PROBES, across: MAX_PROBES_ACROSS };

    /// At most `n` probes (clamped to 1 ..= [`MAX_PROBES`]; 1: one trilinear lookup at the level of
    /// the footprint's longer side, a GPU's isotropic filter), at most `√n` across so that a
    /// smaller budget keeps the probes' grid square.
    pub fn at_most(n: u32) -> Probes {
        let most = if n < 1 {
            1
        } else if n > MAX_PROBES {
            MAX_PROBES
        } else {
            n
        };
        let mut across = 1;
        while across < MAX_PROBES_ACROSS && (across + 1) * (across + 1) <= most {
            across += 1;
        }
        Probes { most, across }
    }

    /// The budget in 12 bits: `most` (7 bits), then `across` (4 bits).
    pub fn word(self) -> u32 {
        self.most | self.across << 7
    }

    /// The budget of [`Probes::word`]'s bits; [`Probes::FULL`] for 0 or a word out of range.
    #[inline]
    pub fn from_word(w: u32) -> Probes {
        let (most, across) = (w & 0x7f, w >> 7 & 0xf);
        if most == 0 || most > MAX_PROBES || across == 0 || across > MAX_PROBES_ACROSS { Probes::FULL } else { Probes { most, across } }
    }
}

/// Texture `index` at `(u, v)` (glTF UVs: origin at the top left) filtered over `footprint` within
/// the budget `probes`; white for [`NO_TEXTURE`] or an index past the
/// table, so a factor times a missing texture is the factor.
#[allow(clippy::too_many_arguments)]
pub fn sample(
    textures: &impl Load,
    texels: &impl Load,
    texture_count: u32,
    index: u32,
    u: f32,
    v: f32,
    footprint: UvFootprint,
    probes: Probes,
) -> [f32; 4] {
    let c = filtered(textures, texels, texture_count, index, u, v, footprint, probes);
    [c.r, c.g, c.b, c.a]
}

#[allow(clippy::too_many_arguments)]
fn filtered(
    textures: &impl Load,
    texels: &impl Load,
    texture_count: u32,
    index: u32,
    u: f32,
    v: f32,
    f: UvFootprint,
    probes: Probes,
) -> Rgba {
    if index == NO_TEXTURE || index >= texture_count {
        return Rgba::WHITE;
    }
    let at = index * TEXTURE_WORDS;
    let (offset, width, height, sampler) = (textures.load(at), textures.load(at + 1), textures.load(at + 2), textures.load(at + 3));
    if width == 0 || height == 0 {
        return Rgba::WHITE;
    }
    let levels = (sampler >> LEVELS_SHIFT) & LEVELS_MASK;
    let levels = if levels == 0 { 1 } else { levels };
    let base = Level { offset, width, height, wrap_s: (sampler >> WRAP_S_SHIFT) & 3, wrap_t: (sampler >> WRAP_T_SHIFT) & 3 };
    // Non-finite UVs (none reach here from a validated mesh) fall back to the first texel.
    let finite = crate::lens::is_finite(u * width as f32) && crate::lens::is_finite(v * height as f32);
    let (u, v) = if finite { (u, v) } else { (0.0, 0.0) };

    // The footprint's sides in level-0 texels.
    let (ax, ay, bx, by) = (f.du_a * width as f32, f.dv_a * height as f32, f.du_b * width as f32, f.dv_b * height as f32);
    let (la, lb) = (sqrt(ax * ax + ay * ay), sqrt(bx * bx + by * by));
    let longest = maxf(la, lb);
    // Magnified (or no footprint): one read of the finest level, as the sampler says. Minified:
    // about a probe a texel along each side, within the budgets, at the level the spacing fits.
    let magnified = !(longest > 1.0) || !crate::lens::is_finite(longest);
    let Probes { most, across } = probes;
    let (na, nb) = if magnified {
        (1, 1)
    } else if la >= lb {
        let nb = probes_along(lb, across);
        (probes_along(la, most / nb), nb)
    } else {
        let na = probes_along(la, across);
        (na, probes_along(lb, most / na))
    };
    let spacing = if magnified { 1.0 } else { maxf(la / na as f32, lb / nb as f32) };
    let lod = if spacing > 1.0 { log2_level(spacing) } else { 0.0 };
    let top = levels - 1;
    let fine = floor(lod) as u32;
    let (fine, blend) = if fine >= top { (top, 0.0) } else { (fine, lod - fine as f32) };
    let reads = if blend > 0.0 { 2 } else { 1 };
    let (level0, level1) = (Level::of(base, fine), Level::of(base, fine + reads - 1));
    let nearest = magnified && sampler & NEAREST != 0;

    // One read site (the kernel inlines every call): probe by probe, level by level.
    let mut sum = Rgba::default();
    let mut i = 0;
    while i < na {
        let s = (i as f32 + 0.5) / na as f32 - 0.5;
        let mut j = 0;
        while j < nb {
            let t = (j as f32 + 0.5) / nb as f32 - 0.5;
            let (pu, pv) = (u + s * f.du_a + t * f.du_b, v + s * f.dv_a + t * f.dv_b);
            let mut k = 0;
            while k < reads {
                let (level, weight) = if k == 0 { (level0, 1.0 - blend) } else { (level1, blend) };
                sum = sum.add(level.read(texels, pu, pv, nearest).scale(weight));
                k += 1;
            }
            j += 1;
        }
        i += 1;
    }
    sum.scale(1.0 / (na * nb) as f32)
}

/// Probes along a side `length` texels long: one a texel, at least 1 and at most `most`.
#[inline]
fn probes_along(length: f32, most: u32) -> u32 {
    let n = ceil(minf(length, most as f32));
    if n < 1.0 { 1 } else { n as u32 }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A budget survives the push constant's word, keeps its grid square, and an unset word is the
    /// full box filter.
    #[test]
    fn probe_budgets_round_trip_and_stay_square() {
        for n in 0..=70 {
            let p = Probes::at_most(n);
            assert_eq!(Probes::from_word(p.word()), p, "{n}");
            assert!(
                p.across * p.across <= p.most && (p.across == MAX_PROBES_ACROSS || (p.across + 1) * (p.across + 1) > p.most),
                "{n}: {p:?}"
            );
        }
        assert_eq!(Probes::at_most(16), Probes { most: 16, across: 4 });
        assert_eq!(Probes::at_most(1000), Probes::FULL);
        assert_eq!(Probes::from_word(0), Probes::FULL);
    }

    #[test]
    fn halves_decode_exactly() {
        for (h, f) in [
            (0x0000u32, 0.0f32),
            (0x3c00, 1.0),
            (0xc000, -2.0),
            (0x3555, 0.333_251_95),
            (0x7bff, 65504.0),
            (0x0001, 5.960_464_5e-8),
            (0x03ff, 6.097_555e-5),
            (0x7c00, f32::INFINITY),
        ] {
            assert_eq!(half_to_f32(h), f, "{h:#x}");
        }
        assert!(half_to_f32(0x7e00).is_nan());
        assert_eq!(half_to_f32(0x8000).to_bits(), (-0.0f32).to_bits());
    }

    #[test]
    fn the_level_of_detail_is_log2_within_a_thousandth() {
        let mut x = 1.0f32;
        while x < 1e6 {
            assert!((log2_level(x) - x.log2()).abs() < 0.0011, "{x}");
            x *= 1.013;
        }
        for k in 0..20 {
            assert_eq!(log2_level((1u32 << k) as f32), k as f32);
        }
    }
}
