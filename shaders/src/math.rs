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

/// Arc sine on `[-1, 1]` (clamped), from arithmetic and [`sqrt`] only, so that both targets compute
/// the same bits: GLSL.std.450 `Asin` has no stated precision, and splatting's footprint weights
/// (`crate::footprint`) multiply it by `r²`. `x + x³·P(x²)` up to 1/2, a least-squares fit of
/// degree 4 (relative error under 3e-7 in f32), and `π/2 − 2·asin(√((1 − x)/2))` above. Per
/// value or for several at once ([`crate::lane`]).
#[inline(always)]
pub fn asin<V: crate::lane::Lanes>(x: V) -> V {
    let c = V::splat;
    let negative = x.lt(c(0.0));
    let a = V::select(negative, -x, x);
    let a = V::select(c(1.0).lt(a), c(1.0), a);
    let small = a.le(c(0.5));
    let t = V::select(small, a, (c(0.5) * (c(1.0) - a)).sqrt());
    let u = t * t;
    let p = c(0.166_667_3) + u * (c(0.074_963_33) + u * (c(0.045_331_25) + u * (c(0.024_905_317) + u * c(0.040_875_46))));
    let s = t + t * u * p;
    let r = V::select(small, s, c(core::f32::consts::FRAC_PI_2) - c(2.0) * s);
    V::select(negative, -r, r)
}

#[cfg(test)]
mod tests {
    #[test]
    fn asin_is_within_3e_7_of_the_library() {
        let mut worst = 0.0f64;
        for i in 0..=200_000 {
            let x = -1.0 + 2.0 * i as f32 / 200_000.0;
            let want = (x as f64).asin();
            let err = (super::asin(x) as f64 - want).abs() / want.abs().max(1e-30);
            worst = worst.max(if want == 0.0 { super::asin(x).abs() as f64 } else { err });
        }
        assert!(worst < 3e-7, "worst relative error {worst}");
        assert_eq!(super::asin(2.0f32), core::f32::consts::FRAC_PI_2);
        assert_eq!(super::asin(-7.0f32), -core::f32::consts::FRAC_PI_2);
    }
}
