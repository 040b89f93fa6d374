//! The gathering baseline (in the spirit of Riguer et al. 2003, "scatter as gather"): every pixel
//! averages the neighbours whose circle of confusion covers it, each weighted by the inverse of its
//! CoC area, so a pixel's colour is spread over its circle with constant energy. Depth order is
//! handled only by one rule: a neighbour *behind* the pixel counts with at most the pixel's own CoC,
//! so a blurred background does not smear over a sharper foreground, while a blurred foreground (the
//! near field) does spread over what lies behind it. There is no hidden geometry: a single layer
//! cannot show what the near field covers (partial occlusion), which is what the multi-layer
//! methods add.
//!
//! Radii are capped at the window the kernel scans: the largest CoC radius present, which
//! `gather_plan` reduces on the device into `plan[0]` (whole pixels), at most `max_radius`.
//! Non-finite colours and depths are skipped, so a NaN or Inf pixel never spreads; a pixel whose
//! own value is skipped and that nothing covers comes out black.

use crate::exec::{Group, Load, Mem};
use crate::lens::{ThinLens, is_finite as finite, is_positive};

pub const TILE: u32 = 8;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GatherParams {
    pub width: u32,
    pub height: u32,
    /// Largest CoC radius considered, in whole pixels (the scanned window is `2 r + 1` wide).
    pub max_radius: u32,
    pub _pad: u32,
    pub lens: ThinLens,
}

/// CoC radius in pixels of a sample at depth `z`, capped; sky (`+inf`) takes the far-field radius.
#[inline]
pub fn radius_px(lens: &ThinLens, z: f32, max_radius: f32) -> f32 {
    lens.coc_radius_px(z).min(max_radius)
}

/// Colour of pixel `i` under the numerical contract ([`crate::radiance`]), or `None` when any
/// channel is not finite.
#[inline]
fn colour(color: &impl Load, i: u32) -> Option<[f32; 3]> {
    let c = [f32::from_bits(color.load(3 * i)), f32::from_bits(color.load(3 * i + 1)), f32::from_bits(color.load(3 * i + 2))];
    if finite(c[0]) && finite(c[1]) && finite(c[2]) { Some(crate::radiance::clamp_color(c)) } else { None }
}

/// The planned window radius: the reduction's, within the configured cap.
#[inline]
pub fn planned_radius(p: &GatherParams, plan: &impl Load) -> u32 {
    let r = plan.load(0);
    if r < p.max_radius { r } else { p.max_radius }
}

/// Grid-stride over pixels: the largest CoC radius (capped at `max_radius`, rounded up to whole
/// pixels) of every sample with a positive depth, into `plan[0]` (zeroed before).
pub fn plan_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &GatherParams, sh: &mut [u32; 2 * 256], depth: R, mut plan: M) {
    let stride = g.num_workgroups()[0] * 256;
    let base = g.workgroup_id()[0] * 256;
    let pixels = p.width * p.height;
    g.each(|lid| {
        let mut widest = 0u32;
        let mut i = base + lid;
        while i < pixels {
            let z = f32::from_bits(depth.load(i));
            if is_positive(z) {
                let r = radius_px(&p.lens, z, p.max_radius as f32);
                let whole = r as u32 + if (r as u32) as f32 == r { 0 } else { 1 };
                widest = if whole > widest { whole } else { widest };
            }
            i += stride;
        }
        sh[lid as usize] = widest;
    });
    let m = crate::wg::inclusive_scan(g, sh, 0, crate::wg::Max);
    g.each(|lid| {
        if lid == 255 {
            plan.atomic_max(0, sh[m + lid as usize]);
        }
    });
}

/// One invocation per pixel of an 8x8 tile.
pub fn gather_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &GatherParams, color: R, depth: R, mut out: M, plan: R) {
    let radius = planned_radius(p, &plan);
    let [wx, wy, _] = g.workgroup_id();
    g.each(|lid| {
        let x = wx * TILE + lid % TILE;
        let y = wy * TILE + lid / TILE;
        if x >= p.width || y >= p.height {
            return;
        }
        let max_r = radius as f32;
        let pi = y * p.width + x;
        let zp = f32::from_bits(depth.load(pi));
        let rp = radius_px(&p.lens, zp, max_r);
        let r = radius as i32;
        let mut acc = [0.0f32; 3];
        let mut weight = 0.0f32;
        let mut dy = -r;
        while dy <= r {
            let qy = y as i32 + dy;
            let mut dx = -r;
            while qy >= 0 && qy < p.height as i32 && dx <= r {
                let qx = x as i32 + dx;
                if qx >= 0 && qx < p.width as i32 {
                    let qi = qy as u32 * p.width + qx as u32;
                    let zq = f32::from_bits(depth.load(qi));
                    if let Some(c) = colour(&color, qi).filter(|_| is_positive(zq)) {
                        let rq = radius_px(&p.lens, zq, max_r);
                        // Background behind the pixel blurs over it by at most the pixel's own CoC.
                        let reach = if zq > zp { rq.min(rp) } else { rq } + 0.5;
                        if ((dx * dx + dy * dy) as f32) <= reach * reach {
                            let w = 1.0 / (reach * reach);
                            acc[0] += w * c[0];
                            acc[1] += w * c[1];
                            acc[2] += w * c[2];
                            weight += w;
                        }
                    }
                }
                dx += 1;
            }
            dy += 1;
        }
        let inv = if weight > 0.0 { 1.0 / weight } else { 0.0 };
        out.store(3 * pi, (acc[0] * inv).to_bits());
        out.store(3 * pi + 1, (acc[1] * inv).to_bits());
        out.store(3 * pi + 2, (acc[2] * inv).to_bits());
    });
}

kernel!(
    /// The gathering baseline over a colour (3 words a pixel) and depth (1 word a pixel) image.
    GATHER = gather [64] (GatherParams) { read color, read depth, out, read plan } => gather_pass
);
kernel!(
    /// The largest CoC radius present, into the plan word the gather reads.
    GATHER_PLAN = gather_plan [256 subgroups] (GatherParams) shared [u32; 2 * 256] { read depth, plan } => plan_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 2] = [&GATHER, &GATHER_PLAN];
