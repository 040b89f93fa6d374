//! The few float functions the kernels need beyond arithmetic, from the same call on both targets:
//! GLSL.std.450 instructions on SPIR-V (through `num_traits`), the standard library on the CPU.

#[cfg(target_arch = "spirv")]
use spirv_std::num_traits::Float;

#[inline]
pub fn sqrt(x: f32) -> f32 {
    x.sqrt()
}

#[inline]
pub fn floor(x: f32) -> f32 {
    x.floor()
}

#[inline]
pub fn ceil(x: f32) -> f32 {
    x.ceil()
}

#[inline]
pub fn powf(x: f32, y: f32) -> f32 {
    x.powf(y)
}

/// The smaller of `a` and `b` (`b` where they are unordered), as one comparison on both targets.
#[inline]
pub fn minf(a: f32, b: f32) -> f32 {
    if a < b { a } else { b }
}

/// The larger of `a` and `b` (`b` where they are unordered).
#[inline]
pub fn maxf(a: f32, b: f32) -> f32 {
    if a > b { a } else { b }
}

/// `x` clamped to [0, 1] (NaN to 1).
#[inline]
pub fn saturate(x: f32) -> f32 {
    minf(maxf(x, 0.0), 1.0)
}

/// `|x|` (NaN stays NaN).
#[inline]
pub fn absf(x: f32) -> f32 {
    if x < 0.0 { -x } else { x }
}
