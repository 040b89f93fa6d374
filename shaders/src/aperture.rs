//! Aperture shapes for splatting: the circle, or an n-blade polygon with rotation and blade
//! curvature, as a *gauge*: a function `N(d) >= 0` of an offset `d` whose unit ball is the shape
//! scaled to circumradius 1, so a fragment of CoC radius `r` covers `{d : N(d) <= r}`.
//!
//! - circle: `N(d) = |d|`;
//! - `n` blades, curvature `c` in `[0, 1]`: `N(d) = (1 − c)·max_i(d·n_i)/cos(π/n) + c·|d|`, with
//!   `n_i` the blades' unit normals (`c = 0` a regular polygon with its vertices on the unit circle,
//!   `c = 1` the circle, between them rounded blades).
//!
//! `N(d) >= |d|` for every shape, so the shape lies inside the circle of the same radius: binning
//! by the circle stays conservative. Orientation: the shape as given appears in the background
//! (behind the focus plane) and point-reflected in the foreground, as a thin lens images it.
//!
//! The normals are passed in as the first one and the rotation between neighbours, and generated
//! by repeated rotation, so kernels need no trigonometry and both backends compute the same values.
//!
//! Any other shape (a star, a user's image) is a *mask*: `mask` x `mask` coverage texels in a buffer
//! spanning the square `[-1, 1]²` around the centre, sampled bilinearly at the offset over the CoC
//! radius. Masks are zero outside the unit disc, so binning by the circle stays conservative here
//! too, and `area` is the mask's integral over the square.

use crate::exec::Load;
use crate::math::{floor, sqrt};

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Aperture {
    /// Blades; 0 for the circle.
    pub blades: u32,
    /// 0: straight blades; 1: the circle.
    pub curvature: f32,
    /// The first blade's unit normal, and `(cos, sin)` of `2π / blades`.
    pub normal: [f32; 2],
    pub step: [f32; 2],
    /// `1 / cos(π / blades)`: scales the polygon's support function to circumradius 1.
    pub inv_inradius: f32,
    /// Area of the unit shape (π for the circle): the weight integral of large fragments.
    pub area: f32,
    /// Side of the coverage mask in texels; 0 for the analytic shapes.
    pub mask: u32,
}

pub const PI: f32 = core::f32::consts::PI;

impl Aperture {
    pub const fn circle() -> Self {
        Aperture { blades: 0, curvature: 1.0, normal: [1.0, 0.0], step: [1.0, 0.0], inv_inradius: 1.0, area: PI, mask: 0 }
    }

    #[inline]
    pub fn is_circle(&self) -> bool {
        self.blades == 0 && self.mask == 0
    }

    /// Mask coverage at `u` (offset over the CoC radius, the square `[-1, 1]²`), bilinear between
    /// texel centres, 0 outside the square.
    #[inline]
    pub fn coverage<L: Load>(&self, mask: &L, u: [f32; 2]) -> f32 {
        let n = self.mask as f32;
        let (fx, fy) = ((u[0] + 1.0) * 0.5 * n - 0.5, (u[1] + 1.0) * 0.5 * n - 0.5);
        if !(fx > -1.0 && fy > -1.0 && fx < n && fy < n) {
            return 0.0;
        }
        let (x0, y0) = (floor(fx), floor(fy));
        let (tx, ty) = (fx - x0, fy - y0);
        let texel = |x: f32, y: f32| -> f32 {
            if x < 0.0 || y < 0.0 || x >= n || y >= n { 0.0 } else { f32::from_bits(mask.load(y as u32 * self.mask + x as u32)) }
        };
        let top = texel(x0, y0) * (1.0 - tx) + texel(x0 + 1.0, y0) * tx;
        let bottom = texel(x0, y0 + 1.0) * (1.0 - tx) + texel(x0 + 1.0, y0 + 1.0) * tx;
        top * (1.0 - ty) + bottom * ty
    }

    /// The gauge `N(d)` (see the module notes).
    #[inline]
    pub fn gauge(&self, d: [f32; 2]) -> f32 {
        let len = sqrt(d[0] * d[0] + d[1] * d[1]);
        if self.blades == 0 {
            return len;
        }
        let mut n = self.normal;
        let mut support = d[0] * n[0] + d[1] * n[1];
        let mut i = 1;
        while i < self.blades {
            n = [n[0] * self.step[0] - n[1] * self.step[1], n[0] * self.step[1] + n[1] * self.step[0]];
            let v = d[0] * n[0] + d[1] * n[1];
            support = if v > support { v } else { support };
            i += 1;
        }
        (1.0 - self.curvature) * support * self.inv_inradius + self.curvature * len
    }
}

/// Host side: the polygon aperture with `blades >= 3`, rotated by `rotation` radians
/// (counter-clockwise, image y down), blade curvature in `[0, 1]`; `None` for bad values.
#[cfg(not(target_arch = "spirv"))]
pub fn blades(blades: u32, rotation: f32, curvature: f32) -> Option<Aperture> {
    if !(3..=64).contains(&blades) || !rotation.is_finite() || !(0.0..=1.0).contains(&curvature) {
        return None;
    }
    let step = 2.0 * core::f64::consts::PI / blades as f64;
    // Vertices at `rotation + i·step`, so edge normals lie half a step further.
    let first = rotation as f64 + 0.5 * step;
    let mut a = Aperture {
        blades,
        curvature,
        normal: [first.cos() as f32, first.sin() as f32],
        step: [step.cos() as f32, step.sin() as f32],
        inv_inradius: (1.0 / (0.5 * step).cos()) as f32,
        area: 0.0,
        mask: 0,
    };
    // Area of {N <= 1}: half the integral of R(φ)² over the angle, R = 1 / N(unit vector).
    let samples = 4096;
    let mut area = 0.0f64;
    for k in 0..samples {
        let phi = (k as f64 + 0.5) / samples as f64 * 2.0 * core::f64::consts::PI;
        let r = 1.0 / a.gauge([phi.cos() as f32, phi.sin() as f32]) as f64;
        area += 0.5 * r * r * (2.0 * core::f64::consts::PI / samples as f64);
    }
    a.area = area as f32;
    Some(a)
}

/// Host side: the aperture of a `side` x `side` coverage mask (row-major, y down, values in
/// `[0, 1]`, zero outside the inscribed circle); `None` for bad values.
#[cfg(not(target_arch = "spirv"))]
pub fn masked(side: u32, texels: &[f32]) -> Option<Aperture> {
    if !(2..=512).contains(&side) || texels.len() != (side * side) as usize || !texels.iter().all(|v| (0.0..=1.0).contains(v)) {
        return None;
    }
    let texel_area = (2.0 / side as f64).powi(2);
    let area = texels.iter().map(|&v| v as f64).sum::<f64>() * texel_area;
    if !(area > 0.0) {
        return None;
    }
    Some(Aperture { blades: 0, curvature: 0.0, normal: [1.0, 0.0], step: [1.0, 0.0], inv_inradius: 1.0, area: area as f32, mask: side })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polygon_areas_and_the_circle_limit() {
        let hex = blades(6, 0.0, 0.0).unwrap();
        let expected = 0.5 * 6.0 * (2.0 * core::f32::consts::PI / 6.0).sin();
        assert!((hex.area - expected).abs() < 1e-3 * expected, "{} vs {expected}", hex.area);
        let round = blades(5, 0.3, 1.0).unwrap();
        assert!((round.area - PI).abs() < 1e-3, "{}", round.area);
        // Vertices on the unit circle, edge midpoints at the inradius.
        assert!((hex.gauge([1.0, 0.0]) - 1.0).abs() < 1e-5);
        let mid = (PI / 6.0).cos();
        assert!((hex.gauge([mid * (PI / 6.0).cos(), mid * (PI / 6.0).sin()]) - 1.0).abs() < 1e-5);
        // Inside the circle of the same radius.
        for k in 0..360 {
            let phi = k as f32 * PI / 180.0;
            let d = [phi.cos(), phi.sin()];
            assert!(hex.gauge(d) >= 1.0 - 1e-5 && blades(5, 0.7, 0.4).unwrap().gauge(d) >= 1.0 - 1e-5);
        }
        assert_eq!(Aperture::circle().gauge([3.0, 4.0]), 5.0);
        assert!(blades(2, 0.0, 0.0).is_none() && blades(6, 0.0, 1.5).is_none() && blades(6, f32::NAN, 0.0).is_none());
    }
}
