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
