//! Texture lookups for the mesh shading: one texel buffer holds every texture (linear RGBA), each
//! described by a [`TextureInfo`]. Magnification is nearest or bilinear as the sampler says; there
//! are no mipmaps (minified textures alias, as in a renderer without them).

use super::mesh::{NEAREST, NO_TEXTURE, TEXEL_WORDS, TEXTURE_WORDS, WRAP_CLAMP, WRAP_MIRROR, WRAP_S_SHIFT, WRAP_T_SHIFT};
use crate::exec::Load;
use crate::math::floor;

#[inline]
pub fn load_f32(m: &impl Load, i: u32) -> f32 {
    f32::from_bits(m.load(i))
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

#[inline]
fn texel(texels: &impl Load, offset: u32, width: u32, x: u32, y: u32) -> [f32; 4] {
    let at = (offset + y * width + x) * TEXEL_WORDS;
    [load_f32(texels, at), load_f32(texels, at + 1), load_f32(texels, at + 2), load_f32(texels, at + 3)]
}

/// Texture `index` at `(u, v)` (glTF UVs: origin at the top left); white for [`NO_TEXTURE`] or an
/// index past the table, so a factor times a missing texture is the factor.
pub fn sample(textures: &impl Load, texels: &impl Load, texture_count: u32, index: u32, u: f32, v: f32) -> [f32; 4] {
    if index == NO_TEXTURE || index >= texture_count {
        return [1.0; 4];
    }
    let at = index * TEXTURE_WORDS;
    let (offset, width, height, sampler) = (textures.load(at), textures.load(at + 1), textures.load(at + 2), textures.load(at + 3));
    if width == 0 || height == 0 {
        return [1.0; 4];
    }
    let wrap_s = (sampler >> WRAP_S_SHIFT) & 3;
    let wrap_t = (sampler >> WRAP_T_SHIFT) & 3;
    // Non-finite UVs (none reach here from a validated mesh) fall back to the first texel.
    let (x, y) = (u * width as f32, v * height as f32);
    let (x, y) = if crate::lens::is_finite(x) && crate::lens::is_finite(y) { (x, y) } else { (0.0, 0.0) };
    if sampler & NEAREST != 0 {
        let tx = wrap_index(floor(x) as i32, width, wrap_s);
        let ty = wrap_index(floor(y) as i32, height, wrap_t);
        return texel(texels, offset, width, tx, ty);
    }
    // Bilinear between the four texel centres around (x, y).
    let (fx, fy) = (x - 0.5, y - 0.5);
    let (x0, y0) = (floor(fx), floor(fy));
    let (ax, ay) = (fx - x0, fy - y0);
    let (x0, y0) = (x0 as i32, y0 as i32);
    let xa = wrap_index(x0, width, wrap_s);
    let xb = wrap_index(x0 + 1, width, wrap_s);
    let ya = wrap_index(y0, height, wrap_t);
    let yb = wrap_index(y0 + 1, height, wrap_t);
    let t00 = texel(texels, offset, width, xa, ya);
    let t10 = texel(texels, offset, width, xb, ya);
    let t01 = texel(texels, offset, width, xa, yb);
    let t11 = texel(texels, offset, width, xb, yb);
    let mut out = [0.0; 4];
    let mut k = 0;
    while k < 4 {
        let top = t00[k] + (t10[k] - t00[k]) * ax;
        let bottom = t01[k] + (t11[k] - t01[k]) * ax;
        out[k] = top + (bottom - top) * ay;
        k += 1;
    }
    out
}
