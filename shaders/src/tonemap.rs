//! The documented tone map, one source for both sides: the host's PNG previews and metrics call
//! these functions on the CPU (`dof::io::tonemap`, which documents the map), and the viewer's
//! display pass (`display_tonemap`) runs them on the GPU.
//!
//! Per channel: exposure (`x = c · exposure`; NaN and negative results become 0), Narkowicz's fit
//! of the ACES filmic curve clamped to [0, 1] (inputs capped at 65 504 so that `+inf` gives 1),
//! then the sRGB OETF (IEC 61966-2-1). NaN, `±inf` and negative inputs never give NaN.
//!
//! - `display_tonemap` (one invocation per pixel): the methods' RGB result (3 f32 words a pixel)
//!   as display-encoded sRGB in [0, 1], RGBA32F with alpha 1: tone-mapped ([`MODE_TONEMAP`]) or
//!   the raw linear values clamped to [0, 1] and sRGB-encoded ([`MODE_LINEAR`]).

use crate::exec::{Group, Load, Mem};
use crate::math::powf;
use crate::wg::for_each_item;

/// Input cap before the curve (the largest finite half float); the curve is already 1 far below.
pub const CURVE_INPUT_CAP: f32 = 65504.0;

/// Narkowicz's fit of the ACES filmic curve, clamped to [0, 1]. NaN and `x <= 0` give 0.
#[inline]
pub fn aces_fitted(x: f32) -> f32 {
    if !(x > 0.0) {
        return 0.0;
    }
    let x = x.min(CURVE_INPUT_CAP);
    let y = x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
    // clamp(y, 0, 1), written out: `f32::clamp` asserts its bounds, which SPIR-V has no use for.
    if y < 0.0 {
        0.0
    } else if y > 1.0 {
        1.0
    } else {
        y
    }
}

/// The sRGB opto-electronic transfer function (linear [0, 1] → encoded [0, 1]). Inputs are clamped
/// to [0, 1] first; NaN gives 0; 1 gives exactly 1 (the formula gives 1 − 2⁻²⁴ in `f32`).
#[inline]
pub fn srgb_oetf(linear: f32) -> f32 {
    if !(linear > 0.0) {
        return 0.0;
    }
    if linear >= 1.0 {
        return 1.0;
    }
    let l = linear;
    if l <= 0.0031308 { 12.92 * l } else { 1.055 * powf(l, 1.0 / 2.4) - 0.055 }
}

/// The inverse of [`srgb_oetf`] (encoded [0, 1] → linear [0, 1]). Inputs are clamped to [0, 1];
/// NaN gives 0.
#[inline]
pub fn srgb_eotf(encoded: f32) -> f32 {
    if !(encoded > 0.0) {
        return 0.0;
    }
    let v = encoded.min(1.0);
    if v <= 0.04045 { v / 12.92 } else { powf((v + 0.055) / 1.055, 2.4) }
}

/// The tone map of one linear HDR channel: exposure, ACES fitted curve, sRGB OETF. The result is
/// display-encoded sRGB in [0, 1], never NaN.
#[inline]
pub fn tonemap_channel(c: f32, exposure: f32) -> f32 {
    srgb_oetf(aces_fitted(c * exposure))
}

/// `mode`: the tone map at `exposure`.
pub const MODE_TONEMAP: u32 = 0;
/// `mode`: the raw linear values, clamped to [0, 1] (NaN to 0) and sRGB-encoded; no exposure.
pub const MODE_LINEAR: u32 = 1;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct DisplayParams {
    pub width: u32,
    pub height: u32,
    /// [`MODE_TONEMAP`] or [`MODE_LINEAR`].
    pub mode: u32,
    pub exposure: f32,
}

/// One channel as the display shows it.
#[inline]
pub fn display_channel(p: &DisplayParams, c: f32) -> f32 {
    if p.mode == MODE_LINEAR { srgb_oetf(c) } else { tonemap_channel(c, p.exposure) }
}

pub fn display_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &DisplayParams, rgb: R, mut rgba: M) {
    for_each_item(g, p.width * p.height, |i| {
        let mut k = 0;
        while k < 3 {
            let v = display_channel(p, f32::from_bits(rgb.load(3 * i + k)));
            rgba.store(4 * i + k, v.to_bits());
            k += 1;
        }
        rgba.store(4 * i + 3, 1.0f32.to_bits());
    });
}

kernel!(
    /// The RGB result as display-encoded sRGB (tone-mapped or raw linear), RGBA32F with alpha 1.
    DISPLAY = display_tonemap [256] (DisplayParams) { read rgb, rgba } => display_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 1] = [&DISPLAY];
