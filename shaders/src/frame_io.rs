//! What a renderer hands the frame API, in the layouts the methods read, and back.
//!
//! - `frame_from_textures` (one invocation per pixel): a colour image and a depth image, sampled in
//!   place ([`crate::texels`]), become one fragment slot per
//!   pixel ([`crate::slot`]; alpha 1: a renderer's colour image is what its camera sees, and its
//!   alpha channel, often a clear value, is not read). The depth is either linear (planar view
//!   depth, as the methods take it) or a depth buffer's value, turned into view depth from the
//!   projection's near and far planes (standard or reversed Z, a far plane at infinity allowed). Where reversed or infinite projections put nothing (the far plane at
//!   infinity), the depth is +inf: the background, which every method blends like a surface.
//! - `frame_from_images`: the same, from images copied into buffers (where a backend cannot sample
//!   them): colour RGBA32F, RGBA16F as half bits, or B10G11R11 packed floats; the depth word an f32
//!   (R32F, D32) or a 24-bit unorm in the low bits (D24 through its depth aspect; the high 8 bits
//!   are undefined and ignored), decoded as a fetch would return them.
//! - `frame_front` (one invocation per pixel): a multi-layer input flattened to one colour (3 words)
//!   and one depth (1 word) a pixel: the front-to-back "over" of the pixel's slots over black
//!   ([`Composite`]; an opaque front slot's colour bit for bit) at the front slot's depth, black at
//!   infinite depth where a pixel has no slot: the input of the single-layer gathering methods.
//! - `frame_to_rgba32f_image`, `frame_to_rgba16f_image` (one invocation per pixel): the methods' RGB
//!   result (3 f32 words a pixel) written into the caller's RGBA32F or RGBA16F image with alpha 1,
//!   in place (a storage image).
//! - `frame_to_rgba`: the same into a buffer, packed as the image's copy takes it.

use crate::exec::{Group, Load, Mem};
use crate::slot::{self, Slot};
use crate::texels::{self, Packed, PackedDepth, Texels, TexelsMut};
use crate::wg::for_each_item;

/// `depth_encoding`: planar view depth as it is.
pub const DEPTH_LINEAR: u32 = 0;
/// `depth_encoding`: a depth buffer, 0 at the near plane and 1 at the far plane.
pub const DEPTH_STANDARD: u32 = 1;
/// `depth_encoding`: a reversed depth buffer, 1 at the near plane and 0 at the far plane.
pub const DEPTH_REVERSED: u32 = 2;

/// `depth_format`: the depth word is an f32 (R32F, or D32 through its depth aspect).
pub const DEPTH_F32: u32 = 0;
/// `depth_format`: the depth word holds a 24-bit unorm in its low bits (D24 through its depth
/// aspect, as Vulkan copies it: the high 8 bits undefined).
pub const DEPTH_UNORM24: u32 = 1;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct FrameIoParams {
    pub width: u32,
    pub height: u32,
    /// Words a pixel of the colour buffer: 4 (RGBA32F), 2 (RGBA16F as half bits) or 1 (B10G11R11
    /// packed floats).
    pub color_words: u32,
    pub depth_encoding: u32,
    /// The projection's near and far planes (scene units; `far` may be +inf), for encoded depths.
    pub near: f32,
    pub far: f32,
    /// Slots per pixel of a multi-layer input (`frame_front`).
    pub layers: u32,
    /// How a depth word holds its value: [`DEPTH_F32`] or [`DEPTH_UNORM24`].
    pub depth_format: u32,
}

/// The depth-buffer (or linear) value a depth word holds.
#[inline]
pub fn depth_value(p: &FrameIoParams, word: u32) -> f32 {
    texels::decode_depth(depth_texels(p), word)
}

/// View depth from a depth-buffer value `d` (NaN outside `[0, 1]`).
#[inline]
pub fn view_depth(p: &FrameIoParams, d: f32) -> f32 {
    if p.depth_encoding == DEPTH_LINEAR {
        return d;
    }
    if !(d >= 0.0 && d <= 1.0) {
        return f32::NAN;
    }
    let infinite_far = p.far == f32::INFINITY;
    // Standard: z = n·f / (f − d·(f − n)); reversed: z = n·f / (n + d·(f − n)). With the far plane
    // at infinity they become n / (1 − d) and n / d.
    let (num, den) = if p.depth_encoding == DEPTH_STANDARD {
        if infinite_far { (p.near, 1.0 - d) } else { (p.near * p.far, p.far - d * (p.far - p.near)) }
    } else if infinite_far {
        (p.near, d)
    } else {
        (p.near * p.far, p.near + d * (p.far - p.near))
    };
    if den <= 0.0 { f32::INFINITY } else { num / den }
}

/// The packed format ([`crate::texels`]) of the copied colour image.
#[inline]
pub fn color_texels(p: &FrameIoParams) -> u32 {
    if p.color_words == 1 {
        texels::B10G11R11
    } else if p.color_words == 2 {
        texels::RGBA16F
    } else {
        texels::RGBA32F
    }
}

/// The packed format ([`crate::texels`]) of the copied depth image.
#[inline]
pub fn depth_texels(p: &FrameIoParams) -> u32 {
    if p.depth_format == DEPTH_UNORM24 { texels::D24 } else { texels::R32F }
}

/// A colour and a depth image as one opaque fragment slot a pixel (the images sampled in place, or
/// copied: [`from_copies_pass`]). A grid-stride loop over the pixels with no closure: sampled
/// images cannot be captured by one in SPIR-V.
pub fn from_images_pass<G: Group, C: Texels, D: Texels, M: Mem>(
    g: &mut G,
    p: &FrameIoParams,
    color: C,
    depth: D,
    mut fragments: M,
    mut counts: M,
) {
    let n = p.width * p.height;
    let stride = g.num_workgroups()[0] * g.size();
    let lanes = g.invocations();
    let mut base = g.workgroup_id()[0] * g.size();
    while base < n {
        let mut i = base + lanes.start;
        while i < n && i < base + lanes.end {
            // One division a pixel: the remainder from the quotient.
            let y = i / p.width;
            let x = i - y * p.width;
            let [r, gr, b, _] = color.texel(x, y);
            let z = view_depth(p, depth.texel(x, y)[0]);
            slot::store(&mut fragments, i, Slot::opaque([r, gr, b], z));
            counts.store(i, 1);
            i += 1;
        }
        base += stride;
    }
}

/// [`from_images_pass`] over images copied into buffers.
pub fn from_copies_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &FrameIoParams, color: R, depth: R, fragments: M, counts: M) {
    let color = Packed { words: color, width: p.width, format: color_texels(p) };
    let depth = PackedDepth { words: depth, width: p.width, format: depth_texels(p) };
    from_images_pass(g, p, color, depth, fragments, counts)
}

pub fn front_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &FrameIoParams, fragments: R, counts: R, mut color: M, mut depth: M) {
    for_each_item(g, p.width * p.height, |i| {
        let (c, z) = slot::flatten(counts.load(i).min(p.layers), |k| slot::load(&fragments, i * p.layers + k));
        color.store(3 * i, c[0].to_bits());
        color.store(3 * i + 1, c[1].to_bits());
        color.store(3 * i + 2, c[2].to_bits());
        depth.store(i, z.to_bits());
    });
}

/// The RGB result as an RGBA image with alpha 1 (written in place, or into a buffer:
/// [`to_rgba_pass`]). A closure-free grid-stride loop, as [`from_images_pass`].
pub fn to_image_pass<G: Group, R: Load, T: TexelsMut>(g: &mut G, p: &FrameIoParams, rgb: R, mut out: T) {
    let n = p.width * p.height;
    let stride = g.num_workgroups()[0] * g.size();
    let lanes = g.invocations();
    let mut base = g.workgroup_id()[0] * g.size();
    while base < n {
        let mut i = base + lanes.start;
        while i < n && i < base + lanes.end {
            let c = |k: u32| f32::from_bits(rgb.load(3 * i + k));
            let y = i / p.width;
            out.set_texel(i - y * p.width, y, [c(0), c(1), c(2), 1.0]);
            i += 1;
        }
        base += stride;
    }
}

/// [`to_image_pass`] into a buffer the image is then copied from, packed as RGBA32F or RGBA16F.
pub fn to_rgba_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &FrameIoParams, rgb: R, rgba: M) {
    to_image_pass(g, p, rgb, Packed { words: rgba, width: p.width, format: color_texels(p) })
}

kernel!(
    /// A colour and a depth image, sampled in place, as one fragment slot per pixel.
    FROM_TEXTURES = frame_from_textures [256] (FrameIoParams) { texture color, depth_texture depth, fragments, counts } => from_images_pass
);
kernel!(
    /// A colour and a depth image copied into buffers as one fragment slot per pixel.
    FROM_IMAGES = frame_from_images [256] (FrameIoParams) { read color, read depth, fragments, counts } => from_copies_pass
);
kernel!(
    /// The front slot of a multi-layer input as colour and depth.
    FRONT = frame_front [256] (FrameIoParams) { read fragments, read counts, color, depth } => front_pass
);
kernel!(
    /// The RGB result as RGBA32F or RGBA16F with alpha 1, into a buffer.
    TO_RGBA = frame_to_rgba [256] (FrameIoParams) { read rgb, rgba } => to_rgba_pass
);
kernel!(
    /// The RGB result written in place into an RGBA32F image, alpha 1.
    TO_RGBA32F_IMAGE = frame_to_rgba32f_image [256] (FrameIoParams) { read rgb, rgba32f_image out } => to_image_pass
);
kernel!(
    /// The RGB result written in place into an RGBA16F image, alpha 1.
    TO_RGBA16F_IMAGE = frame_to_rgba16f_image [256] (FrameIoParams) { read rgb, rgba16f_image out } => to_image_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 6] = [&FROM_TEXTURES, &FROM_IMAGES, &FRONT, &TO_RGBA, &TO_RGBA32F_IMAGE, &TO_RGBA16F_IMAGE];

/// The depth-buffer value of view depth `z` under `p`'s encoding (the inverse of [`view_depth`]):
/// `z` itself for linear depth, +inf for `z` beyond the far plane or not finite (nothing a depth
/// buffer can hold lies there).
#[inline]
pub fn buffer_depth(p: &FrameIoParams, z: f32) -> f32 {
    if p.depth_encoding == DEPTH_LINEAR {
        return z;
    }
    if !(z > 0.0) || !(z < p.far) {
        return f32::INFINITY;
    }
    let infinite_far = p.far == f32::INFINITY;
    // Standard: d = f·(z − n) / (z·(f − n)), or 1 − n/z with the far plane at infinity; reversed:
    // d = n·(f − z) / (z·(f − n)), or n/z.
    if p.depth_encoding == DEPTH_STANDARD {
        if infinite_far { 1.0 - p.near / z } else { p.far * (z - p.near) / (z * (p.far - p.near)) }
    } else if infinite_far {
        p.near / z
    } else {
        p.near * (p.far - z) / (z * (p.far - p.near))
    }
}
