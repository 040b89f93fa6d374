//! Images a kernel reads or writes in place, texel by texel: a renderer's colour and depth
//! attachments bound as sampled images on the GPU ([`ColorImage`], [`DepthImage`]; declared
//! `texture` and `depth_texture` in [`kernel!`](crate::kernel!)), its output bound as a storage
//! image (`Rgba32fImage`, `Rgba16fImage`; `rgba32f_image`, `rgba16f_image`), and on the CPU the
//! backend's images, packed into words as a copy packs them ([`Packed`]).
//!
//! A texel is what a sampler's fetch returns: four floats, the format's missing components 0 (alpha
//! 1). [`decode`] turns packed words into the same values, exactly for every format here: the half
//! and small floats widen to f32 exactly, and a 24-bit unorm depth is its integer over 2^24 − 1,
//! rounded once.

use crate::exec::{Load, Mem};
use crate::half::{b10g11r11_to_f32, f16_to_f32, f32_to_f16};

/// Packed formats (`Packed::format`): `R32G32B32A32_SFLOAT`, 4 words a texel.
pub const RGBA32F: u32 = 0;
/// `R16G16B16A16_SFLOAT`: 2 words a texel, halves R, G in the first (R low), B, A in the second.
pub const RGBA16F: u32 = 1;
/// `B10G11R11_UFLOAT_PACK32`: 1 word, R in bits 0–10, G in 11–21, B in 22–31.
pub const B10G11R11: u32 = 2;
/// `R32_SFLOAT`, or `D32_SFLOAT`'s depth aspect: 1 word, f32 bits.
pub const R32F: u32 = 3;
/// A 24-bit unorm depth in a word's low bits (`D24_UNORM_S8_UINT`'s or `X8_D24_UNORM_PACK32`'s
/// depth aspect as Vulkan copies it; the high 8 bits undefined and ignored).
pub const D24: u32 = 4;

/// Words a texel of a packed format.
#[inline]
pub fn words_per_texel(format: u32) -> u32 {
    match format {
        RGBA32F => 4,
        RGBA16F => 2,
        _ => 1,
    }
}

/// Texel `i` of packed `words` in `format`, as a fetch returns it.
#[inline]
pub fn decode(format: u32, words: &impl Load, i: u32) -> [f32; 4] {
    if format == R32F || format == D24 { [decode_depth(format, words.load(i)), 0.0, 0.0, 1.0] } else { decode_color(format, words, i) }
}

/// Colour texel `i` of packed `words` in `format` ([`RGBA32F`], [`RGBA16F`] or [`B10G11R11`]).
/// Apart from [`decode`], so that a kernel reading only colour carries no depth decoding.
#[inline]
pub fn decode_color(format: u32, words: &impl Load, i: u32) -> [f32; 4] {
    if format == RGBA16F {
        let (rg, ba) = (words.load(2 * i), words.load(2 * i + 1));
        [f16_to_f32(rg & 0xffff), f16_to_f32(rg >> 16), f16_to_f32(ba & 0xffff), f16_to_f32(ba >> 16)]
    } else if format == B10G11R11 {
        let [r, g, b] = b10g11r11_to_f32(words.load(i));
        [r, g, b, 1.0]
    } else {
        let w = |k: u32| f32::from_bits(words.load(4 * i + k));
        [w(0), w(1), w(2), w(3)]
    }
}

/// The depth a depth word in `format` ([`R32F`] or [`D24`]) holds, as a fetch returns it.
/// Apart from [`decode`], so that a kernel reading only depth carries no colour decoding.
#[inline]
pub fn decode_depth(format: u32, word: u32) -> f32 {
    if format == D24 { (word & 0xff_ffff) as f32 / 16_777_215.0 } else { f32::from_bits(word) }
}

/// Stores texel `i` of `words` in `format` ([`RGBA32F`] or [`RGBA16F`], the formats a kernel
/// writes), as a storage-image write stores it: f32 bits, or each component rounded to the nearest
/// half.
#[inline]
pub fn encode(format: u32, words: &mut impl Mem, i: u32, v: [f32; 4]) {
    if format == RGBA16F {
        words.store(2 * i, f32_to_f16(v[0]) | (f32_to_f16(v[1]) << 16));
        words.store(2 * i + 1, f32_to_f16(v[2]) | (f32_to_f16(v[3]) << 16));
    } else {
        words.store(4 * i, v[0].to_bits());
        words.store(4 * i + 1, v[1].to_bits());
        words.store(4 * i + 2, v[2].to_bits());
        words.store(4 * i + 3, v[3].to_bits());
    }
}

/// A 2D image read texel by texel.
pub trait Texels {
    /// The texel at column `x`, row `y` (row 0 at the top), inside the image.
    fn texel(&self, x: u32, y: u32) -> [f32; 4];
}

/// An image packed into words row after row with no padding, as a copy into a buffer leaves it.
pub struct Packed<L> {
    pub words: L,
    pub width: u32,
    pub format: u32,
}

impl<L: Load> Texels for Packed<L> {
    #[inline]
    fn texel(&self, x: u32, y: u32) -> [f32; 4] {
        decode(self.format, &self.words, y * self.width + x)
    }
}

/// A depth image packed into words as [`Packed`] ([`R32F`] or [`D24`]), decoded by
/// [`decode_depth`] alone.
pub struct PackedDepth<L> {
    pub words: L,
    pub width: u32,
    pub format: u32,
}

impl<L: Load> Texels for PackedDepth<L> {
    #[inline]
    fn texel(&self, x: u32, y: u32) -> [f32; 4] {
        [decode_depth(self.format, self.words.load(y * self.width + x)), 0.0, 0.0, 1.0]
    }
}

/// A 2D image written texel by texel.
pub trait TexelsMut {
    /// Writes the texel at column `x`, row `y` (row 0 at the top), inside the image.
    fn set_texel(&mut self, x: u32, y: u32, v: [f32; 4]);
}

impl<M: Mem> TexelsMut for Packed<M> {
    #[inline]
    fn set_texel(&mut self, x: u32, y: u32, v: [f32; 4]) {
        encode(self.format, &mut self.words, y * self.width + x, v)
    }
}

#[cfg(not(target_arch = "spirv"))]
impl<'a> crate::exec::CpuDispatch<'a> {
    /// The texels of the sampled image at `binding`, as the CPU backend binds it.
    #[inline]
    pub fn texels(&self, binding: usize) -> Packed<crate::exec::CpuMem<'a>> {
        let [width, format] = self.image_layouts[binding];
        Packed { words: crate::exec::CpuMem { words: self.buffers[binding], writable: false }, width, format }
    }

    /// The texels of the storage image at `binding`, writable.
    #[inline]
    pub fn texels_mut(&self, binding: usize) -> Packed<crate::exec::CpuMem<'a>> {
        let [width, format] = self.image_layouts[binding];
        Packed { words: crate::exec::CpuMem { words: self.buffers[binding], writable: true }, width, format }
    }
}

/// A colour image a kernel samples (WGSL `texture_2d<f32>`).
#[cfg(target_arch = "spirv")]
pub type ColorImage = spirv_std::Image!(2D, type=f32, sampled=true, depth=false);
/// A depth image a kernel samples through its depth aspect (WGSL `texture_depth_2d`).
#[cfg(target_arch = "spirv")]
pub type DepthImage = spirv_std::Image!(2D, type=f32, sampled=true, depth=true);

/// An RGBA32F image a kernel writes (WGSL `texture_storage_2d<rgba32float, write>`).
#[cfg(target_arch = "spirv")]
pub type Rgba32fImage = spirv_std::Image!(2D, format = rgba32f, sampled = false);
/// An RGBA16F image a kernel writes (WGSL `texture_storage_2d<rgba16float, write>`).
#[cfg(target_arch = "spirv")]
pub type Rgba16fImage = spirv_std::Image!(2D, format = rgba16f, sampled = false);

#[cfg(target_arch = "spirv")]
impl TexelsMut for &Rgba32fImage {
    #[inline]
    fn set_texel(&mut self, x: u32, y: u32, v: [f32; 4]) {
        // SAFETY: the coordinate lies inside the image (the caller's contract).
        unsafe { self.write(spirv_std::glam::IVec2::new(x as i32, y as i32), spirv_std::glam::Vec4::from_array(v)) }
    }
}

#[cfg(target_arch = "spirv")]
impl TexelsMut for &Rgba16fImage {
    #[inline]
    fn set_texel(&mut self, x: u32, y: u32, v: [f32; 4]) {
        // Rounded to the nearest half first, as `encode` rounds: a store may round to nearest or
        // toward zero (Vulkan allows both), and of a value a half holds exactly, both store it.
        let h = |c: f32| f16_to_f32(f32_to_f16(c));
        let v = [h(v[0]), h(v[1]), h(v[2]), h(v[3])];
        // SAFETY: as above.
        unsafe { self.write(spirv_std::glam::IVec2::new(x as i32, y as i32), spirv_std::glam::Vec4::from_array(v)) }
    }
}

// SPIR-V for Vulkan has no struct holding an image or a pointer to one, so the bound images
// themselves are the texel sources (reached through references).
#[cfg(target_arch = "spirv")]
impl Texels for ColorImage {
    #[inline]
    fn texel(&self, x: u32, y: u32) -> [f32; 4] {
        let t: spirv_std::glam::Vec4 = self.fetch_with_lod(spirv_std::glam::IVec2::new(x as i32, y as i32), 0);
        t.to_array()
    }
}

#[cfg(target_arch = "spirv")]
impl Texels for DepthImage {
    #[inline]
    fn texel(&self, x: u32, y: u32) -> [f32; 4] {
        let t: spirv_std::glam::Vec4 = self.fetch_with_lod(spirv_std::glam::IVec2::new(x as i32, y as i32), 0);
        t.to_array()
    }
}

impl<T: Texels + ?Sized> Texels for &T {
    #[inline]
    fn texel(&self, x: u32, y: u32) -> [f32; 4] {
        (**self).texel(x, y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Words<const N: usize>([u32; N]);
    impl<const N: usize> Load for Words<N> {
        fn len(&self) -> u32 {
            N as u32
        }
        fn load(&self, i: u32) -> u32 {
            self.0[i as usize]
        }
    }

    #[test]
    fn packed_texels_decode_as_a_fetch_returns_them() {
        let one = 1.0f32.to_bits();
        let rgba32 = [0, 0, 0, 0, one, 2.0f32.to_bits(), 3.0f32.to_bits(), 0.5f32.to_bits()];
        let image = Packed { words: Words(rgba32), width: 2, format: RGBA32F };
        assert_eq!(image.texel(1, 0), [1.0, 2.0, 3.0, 0.5]);
        // Halves 1.0 (0x3c00), 2.0 (0x4000), -0.5 (0xb800), 0.25 (0x3400).
        let rgba16 = [0x4000_3c00, 0x3400_b800];
        assert_eq!(decode(RGBA16F, &Words(rgba16), 0), [1.0, 2.0, -0.5, 0.25]);
        assert_eq!(decode(B10G11R11, &Words([15 << 6]), 0), [1.0, 0.0, 0.0, 1.0]);
        // The high byte of a D24 word is ignored; the largest unorm is 1 exactly.
        assert_eq!(decode(D24, &Words([0xab00_0000 | 0xff_ffff]), 0)[0], 1.0);
        assert_eq!(decode_depth(D24, 0x80_0000), 8_388_608.0 / 16_777_215.0);
        let depths = [0.25f32.to_bits(), f32::INFINITY.to_bits()];
        let image = Packed { words: Words(depths), width: 1, format: R32F };
        assert_eq!((image.texel(0, 0)[0], image.texel(0, 1)[0]), (0.25, f32::INFINITY));
        assert_eq!((words_per_texel(RGBA32F), words_per_texel(RGBA16F), words_per_texel(D24)), (4, 2, 1));
    }
}
