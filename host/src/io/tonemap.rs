//! The documented tone map: linear HDR radiance → display-encoded sRGB in [0, 1]. PNG previews are
//! this map quantised to 8 bits, and image metrics "on the tone-mapped image" use this function.
//!
//! For each channel `c` independently:
//!
//! 1. **Exposure**: `x = c · exposure`; NaN and negative results become 0 (so the map is total:
//!    NaN, `±inf` and negative inputs never produce NaN).
//! 2. **ACES filmic curve, Narkowicz's fit** (K. Narkowicz, "ACES Filmic Tone Mapping Curve", 2015):
//!    `y = clamp(x·(2.51·x + 0.03) / (x·(2.43·x + 0.59) + 0.14), 0, 1)`.
//!    It maps 0 to 0, is strictly increasing (its derivative's numerator is
//!    `1.408·x² + 0.7028·x + 0.0042 > 0`), and reaches 1 at `x ≈ 7.24` (its limit is
//!    2.51 / 2.43 ≈ 1.033, clamped to 1): radiance above about `7.24 / exposure` saturates to white.
//!    Inputs are capped at 65 504 before the curve so that `+inf` gives 1, not `inf / inf`.
//!    Narkowicz suggests `exposure = 0.6` to match the brightness of the full ACES RRT + sRGB ODT;
//!    the exposure here is the caller's choice (1 by default in the CLI) and the curve is applied
//!    as written above.
//! 3. **sRGB OETF** (IEC 61966-2-1): `v = 12.92·y` for `y <= 0.0031308`, else
//!    `v = 1.055·y^(1/2.4) − 0.055`.
//!
//! 8-bit output is `round(255 · v)` ([`to_u8`]).
//!
//! The per-channel map (exposure, curve, OETF) lives in the kernels crate
//! ([`dof_shaders::tonemap`]), so that the CPU here and the viewer's display pass on the GPU run the
//! same source.

use rayon::prelude::*;

use crate::layers::RgbImage;

/// Input cap before the curve (the largest finite half float); the curve is already 1 far below.
pub use dof_shaders::tonemap::CURVE_INPUT_CAP;
/// Narkowicz's fit of the ACES filmic curve, clamped to [0, 1]. NaN and `x <= 0` give 0.
pub use dof_shaders::tonemap::aces_fitted;
/// The inverse of [`srgb_oetf`] (encoded [0, 1] → linear [0, 1]), for tests and metrics in linear
/// display space. Inputs are clamped to [0, 1]; NaN gives 0.
pub use dof_shaders::tonemap::srgb_eotf;
/// The sRGB opto-electronic transfer function (linear [0, 1] → encoded [0, 1]). Inputs are clamped
/// to [0, 1] first; NaN gives 0; 1 gives exactly 1 (the formula gives 1 − 2⁻²⁴ in `f32`).
pub use dof_shaders::tonemap::srgb_oetf;
/// One channel of [`tonemap`]: exposure, ACES fitted curve, sRGB OETF.
pub use dof_shaders::tonemap::tonemap_channel;

/// The documented tone map of one linear HDR colour: exposure, ACES fitted curve, sRGB OETF (see the
/// module documentation). The result is display-encoded sRGB in [0, 1], never NaN.
#[inline]
pub fn tonemap(rgb: [f32; 3], exposure: f32) -> [f32; 3] {
    rgb.map(|c| tonemap_channel(c, exposure))
}

/// A display-encoded value in [0, 1] to 8 bits: `round(255 · v)`, clamped; NaN gives 0.
#[inline]
pub fn to_u8(v: f32) -> u8 {
    if !(v > 0.0) {
        return 0;
    }
    (v.min(1.0) * 255.0).round() as u8
}

/// [`tonemap`] quantised to 8 bits ([`to_u8`]): the value a PNG preview stores.
#[inline]
pub fn tonemap_to_srgb8(rgb: [f32; 3], exposure: f32) -> [u8; 3] {
    tonemap(rgb, exposure).map(to_u8)
}

/// [`tonemap`] of every pixel, in the image's order.
pub fn tonemap_image(image: &RgbImage, exposure: f32) -> Vec<[f32; 3]> {
    image.data.par_iter().map(|&c| tonemap(c, exposure)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn curve_edges() {
        assert_eq!(aces_fitted(0.0), 0.0);
        assert_eq!(aces_fitted(f32::NAN), 0.0);
        assert_eq!(aces_fitted(f32::INFINITY), 1.0);
        assert_eq!(aces_fitted(-1.0), 0.0);
        assert!(aces_fitted(7.0) < 1.0 && aces_fitted(7.5) == 1.0);
        assert_eq!(tonemap([f32::NAN, f32::INFINITY, f32::NEG_INFINITY], 1.0), [0.0, 1.0, 0.0]);
        assert_eq!(tonemap([1.0; 3], f32::NAN), [0.0; 3]);
    }

    /// The viewer's display pass (the kernel, run here on the CPU backend) is this tone map, bit for
    /// bit, NaN, infinities and negatives included; in raw linear mode it is the OETF of the
    /// clamped values.
    #[test]
    fn the_display_kernel_is_the_tone_map() {
        use crate::backend::{Backend, CpuBackend, RunKernel};
        use dof_shaders::tonemap::{DisplayParams, MODE_LINEAR, MODE_TONEMAP, display_tonemap};
        let values = [0.0, 1e-6, 0.002, 0.18, 0.5, 1.0, 2.0, 7.3, 1e5, f32::NAN, f32::INFINITY, f32::NEG_INFINITY, -0.5, -0.0];
        let pixels: Vec<[f32; 3]> = values.iter().map(|&v| [v, v * 0.5, -v]).collect();
        let words: Vec<u32> = pixels.iter().flat_map(|p| p.map(f32::to_bits)).collect();
        let n = pixels.len() as u32;
        let mut b = CpuBackend::new();
        let rgb = b.create_buffer(words.len() as u64, "rgb").unwrap();
        let rgba = b.create_buffer(4 * n as u64, "rgba").unwrap();
        b.write_buffer(rgb, 0, &words).unwrap();
        for (mode, exposure) in [(MODE_TONEMAP, 1.0), (MODE_TONEMAP, 2.5), (MODE_LINEAR, 1.0)] {
            let params = DisplayParams { width: n, height: 1, mode, exposure };
            b.run(display_tonemap::Bindings { rgb, rgba }, [1, 1, 1], &params, "display").unwrap();
            b.submit().unwrap();
            let got = b.read_buffer(rgba, 0, 4 * n as u64).unwrap();
            for (p, out) in pixels.iter().zip(got.as_chunks::<4>().0) {
                let want = if mode == MODE_LINEAR { p.map(srgb_oetf) } else { tonemap(*p, exposure) };
                let got = [out[0], out[1], out[2]].map(f32::from_bits);
                assert_eq!(got.map(f32::to_bits), want.map(f32::to_bits), "{p:?}, mode {mode}, exposure {exposure}");
                assert_eq!(f32::from_bits(out[3]), 1.0);
            }
        }
    }
}
