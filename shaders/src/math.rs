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
