//! IEEE 754 binary16 conversion by integer operations only, so packing gives the same bits on every
//! backend (no dependence on a driver's `packHalf2x16` rounding). Round to nearest, ties to even;
//! overflow becomes infinity, NaN stays NaN (the splatting pipeline clamps and filters before
//! packing, so neither reaches a fragment).

/// The largest finite half-float.
pub const HALF_MAX: f32 = 65504.0;

/// The binary16 bits (low 16 bits of the result) nearest to `v`.
#[inline]
pub fn f32_to_f16(v: f32) -> u32 {
    let x = v.to_bits();
    let sign = (x >> 16) & 0x8000;
    let exp = ((x >> 23) & 0xff) as i32;
    let mant = x & 0x7f_ffff;
    if exp == 0xff {
        return sign | 0x7c00 | if mant != 0 { 0x200 } else { 0 };
    }
    let e = exp - 127 + 15;
    if e >= 0x1f {
        return sign | 0x7c00;
    }
    if e <= 0 {
        // Subnormal half (or zero): the value is m·2^(e−14) units of 2^−24.
        if e < -10 {
            return sign;
        }
        let m = mant | 0x80_0000;
        let shift = (14 - e) as u32;
        let h = m >> shift;
        let rem = m & ((1 << shift) - 1);
        let halfway = 1 << (shift - 1);
        let up = rem > halfway || (rem == halfway && (h & 1) == 1);
        return sign | (h + up as u32);
    }
    let h = ((e as u32) << 10) | (mant >> 13);
    let rem = mant & 0x1fff;
    // A carry out of the mantissa correctly bumps the exponent (up to infinity).
    let up = rem > 0x1000 || (rem == 0x1000 && (h & 1) == 1);
    sign | (h + up as u32)
}

/// The value of the binary16 bits in the low 16 bits of `h` (exact).
#[inline]
pub fn f16_to_f32(h: u32) -> f32 {
    let sign = (h & 0x8000) << 16;
    let e = (h >> 10) & 0x1f;
    let m = h & 0x3ff;
    if e == 0 {
        // Zero or subnormal: m·2^−24, exact in f32.
        let v = m as f32 * 5.960_464_5e-8;
        return if sign != 0 { -v } else { v };
    }
    if e == 31 {
        return f32::from_bits(sign | 0x7f80_0000 | (m << 13));
    }
    f32::from_bits(sign | ((e + 112) << 23) | (m << 13))
}

/// The value of an unsigned small float of 5 exponent bits (bias 15) and `mbits` mantissa bits
/// held in the low bits of `v` (exact): the components of `B10G11R11_UFLOAT_PACK32`.
#[inline]
fn small_float(v: u32, mbits: u32) -> f32 {
    let e = (v >> mbits) & 0x1f;
    let m = v & ((1 << mbits) - 1);
    if e == 0 {
        // Zero or subnormal: m·2^(−14−mbits), exact in f32.
        return m as f32 * f32::from_bits((127 - 14 - mbits) << 23);
    }
    if e == 31 {
        return f32::from_bits(0x7f80_0000 | (m << (23 - mbits)));
    }
    f32::from_bits(((e + 112) << 23) | (m << (23 - mbits)))
}

/// Red, green and blue of a `B10G11R11_UFLOAT_PACK32` texel (exact): red is an 11-bit float in bits
/// 0–10, green one in bits 11–21, blue a 10-bit float in bits 22–31 (6, 6 and 5 mantissa bits, no
/// sign).
#[inline]
pub fn b10g11r11_to_f32(w: u32) -> [f32; 3] {
    [small_float(w & 0x7ff, 6), small_float((w >> 11) & 0x7ff, 6), small_float(w >> 22, 5)]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Known bit patterns of the packed format (Vulkan spec, "Unsigned 11-Bit/10-Bit Floating-Point
    /// Numbers"): each component on its own, then all three together.
    #[test]
    fn b10g11r11_decodes_known_patterns() {
        let r = |bits: u32| b10g11r11_to_f32(bits)[0];
        let g = |bits: u32| b10g11r11_to_f32(bits << 11)[1];
        let b = |bits: u32| b10g11r11_to_f32(bits << 22)[2];
        // 1.0: exponent 15, mantissa 0.
        assert_eq!((r(15 << 6), g(15 << 6), b(15 << 5)), (1.0, 1.0, 1.0));
        // 1.5 and 0.75; the largest finite values (65024 and 64512); the smallest subnormals.
        assert_eq!((r((15 << 6) | 32), g((14 << 6) | 32), b((15 << 5) | 16)), (1.5, 0.75, 1.5));
        assert_eq!((r((30 << 6) | 63), b((30 << 5) | 31)), (65024.0, 64512.0));
        assert_eq!((r(1), b(1)), (2f32.powi(-20), 2f32.powi(-19)));
        assert_eq!(r(63), 63.0 * 2f32.powi(-20), "the largest subnormal");
        assert_eq!((r(0), g(0), b(0)), (0.0, 0.0, 0.0));
        assert!(r(31 << 6).is_infinite() && b(31 << 5).is_infinite() && r((31 << 6) | 1).is_nan() && b((31 << 5) | 1).is_nan());
        // 0.25 red, 2.0 green, 0.5 blue packed in one word.
        let word = (13 << 6) | ((16 << 6) << 11) | ((14 << 5) << 22);
        assert_eq!(b10g11r11_to_f32(word), [0.25, 2.0, 0.5]);
        // A component never reads its neighbour's bits.
        assert_eq!(b10g11r11_to_f32(!(0x7ff << 11))[1], 0.0);
    }
}
