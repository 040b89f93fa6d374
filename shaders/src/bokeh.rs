//! Bokeh sprites (de Rousiers and Pettineo): pixels much brighter than their 5x5
//! neighbourhood are appended to a sprite buffer and drawn as aperture-shaped quads over a
//! blur-based DoF of the rest.
//!
//! 1. [`BOKEH_DETECT`]: per pixel, luminance against the mean of its (up to 24) neighbours in the 5x5
//!    window; above `lum_threshold`, with a CoC radius above `coc_threshold`, the pixel is flagged
//!    and counted by the append counter. [`BOKEH_EMIT`] writes each flagged pixel's sprite at its
//!    slot from a scan of the flags: the chapter's append order is whatever the GPU's atomics give,
//!    which would make the draw's blending order, and so the image's last bits, differ run to run.
//!    The sprite carries the pixel's *excess* over the neighbourhood mean and the pixel enters the
//!    blur as that mean (per channel: where the pixel is darker than the mean in a channel, that
//!    channel stays whole in the blur and the sprite carries none of it, so neither is negative),
//!    so the two together keep the pixel's energy (the chapter leaves the pixel
//!    in the blur as well, which counts it twice). Beyond the buffer's capacity the pixel stays in
//!    the blur whole: counted, never written out of bounds.
//! 2. The blur of the rest: the gathering baseline ([`crate::gather`]) over the detection's output.
//! 3. [`BOKEH_ARGS`]: one invocation writes the indirect draw command (6 vertices, `min(count,
//!    capacity)` instances) on the device: the host never reads the count to draw.
//! 4. The draw: [`BOKEH_DRAW`], instanced quads through the graphics pipeline on Vulkan
//!    ([`bokeh_vs`], [`bokeh_fs`], additive blending into an RGBA32F target); on the CPU backend its
//!    fallback [`BOKEH_SPLAT`], a compute kernel evaluating the same [`sprite_weight`] at every
//!    pixel centre.
//! 5. [`BOKEH_COMBINE`]: blur plus sprites.
//!
//! The draw binds the sprites and the aperture mask (one word when the shape is analytic).
//!
//! Sprite layout (8 words): centre x, y (pixels), support radius `s` (CoC radius + 1/2), mirror
//! (−1 in front of the focus plane), colour r, g, b already divided by the shape's weight sum, 0.

use crate::aperture::Aperture;
use crate::exec::{Group, Load, Mem};
use crate::lens::{ThinLens, is_finite, is_positive};
use crate::splat::fragment::{shaped_weight, weight_sum};
use crate::wg::for_each_item;

pub const SPRITE_WORDS: u32 = 8;
/// Pixels per side of a [`BOKEH_SPLAT`] workgroup.
pub const TILE: u32 = 16;
/// Words of the indirect draw command: vertex count, instance count, first vertex, first instance.
pub const ARGS_WORDS: u32 = 4;
/// Index of the detection counter in the counters buffer (after the draw command).
pub const COUNTER: u32 = ARGS_WORDS;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct BokehParams {
    pub width: u32,
    pub height: u32,
    /// Sprites the buffer holds.
    pub capacity: u32,
    pub _pad: u32,
    /// Luminance above the neighbourhood mean that makes a sprite (`LumThreshold`).
    pub lum_threshold: f32,
    /// Smallest CoC radius (px) that makes a sprite (`CoCThreshold`).
    pub coc_threshold: f32,
    /// Cap on a sprite's CoC radius (px).
    pub max_radius: f32,
    pub _pad2: f32,
    pub lens: ThinLens,
    pub aperture: Aperture,
}

const _: () = assert!(core::mem::size_of::<BokehParams>() <= 128);

/// Rec. 709 luminance.
#[inline]
pub fn luminance(c: [f32; 3]) -> f32 {
    0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
}

#[inline]
fn colour(m: &impl Load, i: u32) -> [f32; 3] {
    crate::radiance::clamp_color([f32::from_bits(m.load(3 * i)), f32::from_bits(m.load(3 * i + 1)), f32::from_bits(m.load(3 * i + 2))])
}

#[inline]
fn usable(c: [f32; 3]) -> bool {
    is_finite(c[0]) && is_finite(c[1]) && is_finite(c[2])
}

/// What sprite `i` adds at offset `d` from its centre (pixel centre minus sprite centre): the
/// splatting weight of its shape, times its pre-normalised colour.
#[inline]
pub fn sprite_weight<L: Load>(d: [f32; 2], s: f32, mirror: f32, ap: &Aperture, mask: &L) -> f32 {
    let d2 = d[0] * d[0] + d[1] * d[1];
    if d2 < s * s { shaped_weight(d, d2, s, 1.0, ap, mirror, mask) } else { 0.0 }
}

/// The detection rule at pixel `pi`: for a bright pixel, its colour, the neighbourhood mean, its CoC
/// radius and depth.
#[inline]
fn bright(p: &BokehParams, color: &impl Load, depth: &impl Load, pi: u32) -> Option<([f32; 3], [f32; 3], f32, f32)> {
    let (x, y) = ((pi % p.width) as i32, (pi / p.width) as i32);
    let c = colour(color, pi);
    let mut sum = [0.0f32; 3];
    let mut n = 0.0f32;
    let mut dy = -2;
    while dy <= 2 {
        let mut dx = -2;
        while dx <= 2 {
            let (qx, qy) = (x + dx, y + dy);
            if (dx != 0 || dy != 0) && qx >= 0 && qy >= 0 && qx < p.width as i32 && qy < p.height as i32 {
                let q = colour(color, qy as u32 * p.width + qx as u32);
                if usable(q) {
                    sum[0] += q[0];
                    sum[1] += q[1];
                    sum[2] += q[2];
                    n += 1.0;
                }
            }
            dx += 1;
        }
        dy += 1;
    }
    let mean = if n > 0.0 { [sum[0] / n, sum[1] / n, sum[2] / n] } else { [0.0; 3] };
    let z = f32::from_bits(depth.load(pi));
    let r = p.lens.coc_radius_px(z).min(p.max_radius);
    if usable(c) && is_positive(z) && luminance(c) - luminance(mean) > p.lum_threshold && r > p.coc_threshold {
        Some((c, mean, r, z))
    } else {
        None
    }
}

/// Detection: a flag per bright pixel (scanned into sprite slots next) and the append counter.
pub fn detect_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &BokehParams, color: R, depth: R, mut flags: M, mut counters: M) {
    for_each_item(g, p.width * p.height, |pi| {
        let hit = bright(p, &color, &depth, pi).is_some();
        if hit {
            counters.atomic_add(COUNTER, 1);
        }
        flags.store(pi, hit as u32);
    });
}

/// Sprites into their slots (the scanned flags, so the order is the image's, the same every run),
/// and the blur's input: per channel the smaller of the pixel and the neighbourhood mean where a
/// sprite took the excess, else the pixel.
pub fn emit_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &BokehParams,
    color: R,
    depth: R,
    slots: R,
    mut sprites: M,
    mut rest: M,
    mask: R,
) {
    for_each_item(g, p.width * p.height, |pi| {
        let mut keep = colour(&color, pi);
        if let Some((c, mean, r, z)) = bright(p, &color, &depth, pi) {
            let i = slots.load(pi);
            if i < p.capacity {
                let centre = [(pi % p.width) as f32 + 0.5, (pi / p.width) as f32 + 0.5];
                let s = r + 0.5;
                let mirror = if z < p.lens.focus_distance { -1.0 } else { 1.0 };
                let norm = 1.0 / weight_sum(centre, s, 1.0, &p.aperture, mirror, &mask);
                // Per channel: the blur keeps the smaller of the pixel and the mean, the sprite the
                // rest. Both are non-negative, and together they are the pixel: a bright pixel
                // darker than its neighbourhood in one channel (a red light among blue) gave that
                // channel a negative sprite and a negative image (found by `tests/oracles.rs`).
                keep = [c[0].min(mean[0]), c[1].min(mean[1]), c[2].min(mean[2])];
                let words =
                    [centre[0], centre[1], s, mirror, (c[0] - keep[0]) * norm, (c[1] - keep[1]) * norm, (c[2] - keep[2]) * norm, 0.0];
                let mut k = 0;
                while k < SPRITE_WORDS {
                    sprites.store(i * SPRITE_WORDS + k, words[k as usize].to_bits());
                    k += 1;
                }
            }
        }
        rest.store(3 * pi, keep[0].to_bits());
        rest.store(3 * pi + 1, keep[1].to_bits());
        rest.store(3 * pi + 2, keep[2].to_bits());
    });
}

/// The indirect draw command from the counter, on the device.
pub fn args_pass<G: Group, M: Mem>(g: &mut G, p: &BokehParams, mut counters: M) {
    g.each(|lid| {
        if lid == 0 {
            let n = counters.load(COUNTER);
            counters.store(0, 6);
            counters.store(1, if n < p.capacity { n } else { p.capacity });
            counters.store(2, 0);
            counters.store(3, 0);
        }
    });
}

/// The CPU backend's draw: every pixel centre of a 16x16 tile against every sprite drawn (RGBA, 4
/// words a pixel, added to what `target` holds, as additive blending does).
pub fn splat_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &BokehParams, sprites: R, mask: R, counters: R, mut target: M) {
    let [wx, wy, _] = g.workgroup_id();
    let n = counters.load(1);
    g.each(|lid| {
        let x = wx * TILE + lid % TILE;
        let y = wy * TILE + lid / TILE;
        if x >= p.width || y >= p.height {
            return;
        }
        let pi = y * p.width + x;
        let mut acc =
            [f32::from_bits(target.load(4 * pi)), f32::from_bits(target.load(4 * pi + 1)), f32::from_bits(target.load(4 * pi + 2))];
        let mut i = 0;
        while i < n {
            let at = i * SPRITE_WORDS;
            let f = |k: u32| f32::from_bits(sprites.load(at + k));
            let w = sprite_weight([x as f32 + 0.5 - f(0), y as f32 + 0.5 - f(1)], f(2), f(3), &p.aperture, &mask);
            if w > 0.0 {
                acc[0] += w * f(4);
                acc[1] += w * f(5);
                acc[2] += w * f(6);
            }
            i += 1;
        }
        target.store(4 * pi, acc[0].to_bits());
        target.store(4 * pi + 1, acc[1].to_bits());
        target.store(4 * pi + 2, acc[2].to_bits());
    });
}

/// `out = blur + sprites` (sprites as RGBA, 4 words a pixel).
pub fn combine_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &BokehParams, blur: R, sprites: R, mut out: M) {
    for_each_item(g, p.width * p.height, |pi| {
        let mut k = 0;
        while k < 3 {
            let v = f32::from_bits(blur.load(3 * pi + k)) + f32::from_bits(sprites.load(4 * pi + k));
            out.store(3 * pi + k, v.to_bits());
            k += 1;
        }
    });
}

kernel!(
    /// Bright-pixel detection: flags and the append counter.
    BOKEH_DETECT = bokeh_detect [256] (BokehParams) { read color, read depth, flags, counters } => detect_pass
);
kernel!(
    /// Sprites into their scanned slots, and the blur's input.
    BOKEH_EMIT = bokeh_emit [256] (BokehParams) { read color, read depth, read slots, sprites, rest, read mask } => emit_pass
);
kernel!(
    /// The indirect draw command from the detection counter.
    BOKEH_ARGS = bokeh_args [64] (BokehParams) { counters } => args_pass
);
kernel!(
    /// The sprites splatted by a compute kernel: the draw's CPU fallback.
    BOKEH_SPLAT = bokeh_splat [256] (BokehParams) { read sprites, read mask, read counters, target } => splat_pass
);
kernel!(
    /// Blur plus sprites.
    BOKEH_COMBINE = bokeh_combine [256] (BokehParams) { read blur, read sprites, out } => combine_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 5] = [&BOKEH_DETECT, &BOKEH_EMIT, &BOKEH_ARGS, &BOKEH_SPLAT, &BOKEH_COMBINE];

/// Vertex stage: instance `i` is sprite `i`, vertices 0..6 its quad's two triangles, grown by half
/// a pixel past the support so every pixel centre with a weight is covered.
#[cfg(target_arch = "spirv")]
#[spirv_std::spirv(vertex)]
#[allow(clippy::too_many_arguments)]
pub fn bokeh_vs(
    #[spirv(vertex_index)] vertex: i32,
    #[spirv(instance_index)] instance: i32,
    #[spirv(push_constant)] p: &BokehParams,
    #[spirv(descriptor_set = 0, binding = 0, storage_buffer)] sprites: &[u32],
    #[spirv(position)] position: &mut spirv_std::glam::Vec4,
    offset: &mut spirv_std::glam::Vec2,
    #[spirv(flat)] colour: &mut spirv_std::glam::Vec4,
    #[spirv(flat)] shape: &mut spirv_std::glam::Vec2,
) {
    // The sprite is read through a function, not a closure: a closure's captures become a struct
    // holding a pointer, which naga cannot translate.
    let at = instance as u32 * SPRITE_WORDS;
    // Corners of the two triangles, in units of the half-width: vertices 1, 3, 4 on the right,
    // 2, 4, 5 at the bottom.
    let v = vertex % 6;
    let cx = if v == 1 || v == 3 || v == 4 { 1.0 } else { -1.0 };
    let cy = if v == 2 || v == 4 || v == 5 { 1.0 } else { -1.0 };
    let half = sprite_f32(sprites, at, 2) + 0.5;
    let d = [cx * half, cy * half];
    let (x, y) = (sprite_f32(sprites, at, 0) + d[0], sprite_f32(sprites, at, 1) + d[1]);
    *position = spirv_std::glam::Vec4::new(2.0 * x / p.width as f32 - 1.0, 2.0 * y / p.height as f32 - 1.0, 0.0, 1.0);
    *offset = spirv_std::glam::Vec2::new(d[0], d[1]);
    *colour = spirv_std::glam::Vec4::new(sprite_f32(sprites, at, 4), sprite_f32(sprites, at, 5), sprite_f32(sprites, at, 6), 0.0);
    *shape = spirv_std::glam::Vec2::new(sprite_f32(sprites, at, 2), sprite_f32(sprites, at, 3));
}

/// Word `k` of the sprite at word `at`, as `f32`.
#[cfg(target_arch = "spirv")]
fn sprite_f32(sprites: &[u32], at: u32, k: u32) -> f32 {
    f32::from_bits(sprites[(at + k) as usize])
}

/// Fragment stage: the sprite's weight at this pixel centre times its colour, added by blending.
#[cfg(target_arch = "spirv")]
#[spirv_std::spirv(fragment)]
pub fn bokeh_fs(
    #[spirv(push_constant)] p: &BokehParams,
    #[spirv(descriptor_set = 0, binding = 1, storage_buffer)] mask: &[u32],
    offset: spirv_std::glam::Vec2,
    #[spirv(flat)] colour: spirv_std::glam::Vec4,
    #[spirv(flat)] shape: spirv_std::glam::Vec2,
    output: &mut spirv_std::glam::Vec4,
) {
    let w = sprite_weight([offset.x, offset.y], shape.x, shape.y, &p.aperture, &crate::exec::GpuRead(mask));
    *output = spirv_std::glam::Vec4::new(w * colour.x, w * colour.y, w * colour.z, 0.0);
}

/// The sprite draw: its stages, its storage buffers and push constants, and the compute kernel that
/// stands in for it on the CPU backend (bindings: the draw's buffers, then the counters holding the
/// draw command, then the RGBA target).
#[cfg(not(target_arch = "spirv"))]
pub const BOKEH_DRAW: crate::DrawDesc = crate::DrawDesc {
    vertex: "bokeh::bokeh_vs",
    fragment: "bokeh::bokeh_fs",
    bindings: 2,
    push_bytes: core::mem::size_of::<BokehParams>() as u32,
    vertices: 6,
    fallback: &BOKEH_SPLAT,
    fallback_tile: TILE,
    fallback_prepass: None,
    depth_test: false,
};
