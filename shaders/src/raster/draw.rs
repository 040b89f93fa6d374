//! The rasterising draw: every triangle of the mesh once, depth-tested, writing per pixel the
//! nearest kept fragment as `(triangle + 1, planar depth, b0, b1)` (a visibility buffer; `0` in the
//! first word is "nothing"). Shading happens afterwards in [`super::shade`], once per pixel.
//!
//! A fragment is kept when it lies beyond the near plane, beyond `reach[pixel]` while peeling, and
//! passes its material's alpha test ([`fragment_kept`]). On Vulkan: [`raster_vs`] pulls the
//! vertices, [`raster_fs`] tests and writes, the depth attachment keeps the nearest. On the CPU:
//! [`RASTER_FALLBACK`], a compute rasteriser over 16x16 tiles evaluating the same functions.
//!
//! Buffers: vertices, triangles, materials, textures, texels, reach (one f32 a pixel), and each
//! triangle's tile range (4 words), which only the CPU fallback and its prepass [`RASTER_SETUP`]
//! touch.

use super::mesh::{ALPHA_BLEND, ALPHA_MASK, MATERIAL_WORDS, VERTEX_WORDS};
use super::project::{RasterParams, clip, cover, edges, fetch, pixel_ndc, triangle};
use super::texture::{Probes, UvFootprint, half_to_f32, load_f32, sample};
use crate::exec::{Group, Load, Mem};
use crate::math::{ceil, floor};
use crate::wg::for_each_item;

/// Pixels per side of a [`RASTER_FALLBACK`] workgroup.
pub const TILE: u32 = 16;
/// Words a pixel of the visibility target.
pub const VIS_WORDS: u32 = 4;

/// Interpolated texture coordinates of triangle `t` at barycentrics `(b0, b1)`.
pub fn interpolate_uv(vertices: &impl Load, tri: [u32; 4], b0: f32, b1: f32) -> (f32, f32) {
    let b = [b0, b1, 1.0 - b0 - b1];
    let (mut u, mut v) = (0.0, 0.0);
    let mut k = 0;
    while k < 3 {
        let at = tri[k] * VERTEX_WORDS;
        u += b[k] * load_f32(vertices, at + 3);
        v += b[k] * load_f32(vertices, at + 7);
        k += 1;
    }
    (u, v)
}

/// Interpolated vertex colour (linear RGBA) of triangle `t` at barycentrics `(b0, b1)`.
pub fn interpolate_color(vertices: &impl Load, tri: [u32; 4], b0: f32, b1: f32) -> [f32; 4] {
    let b = [b0, b1, 1.0 - b0 - b1];
    let mut c = [0.0f32; 4];
    let mut k = 0;
    while k < 3 {
        let at = tri[k] * VERTEX_WORDS + 8;
        let (rg, ba) = (vertices.load(at), vertices.load(at + 1));
        c[0] += b[k] * half_to_f32(rg & 0xffff);
        c[1] += b[k] * half_to_f32(rg >> 16);
        c[2] += b[k] * half_to_f32(ba & 0xffff);
        c[3] += b[k] * half_to_f32(ba >> 16);
        k += 1;
    }
    c
}

/// The material's coverage at a point: base alpha times the base texture's alpha (read at the
/// finest level: the alpha test keeps cut-outs as sharp at a distance as near) times the vertex
/// colour's alpha.
#[allow(clippy::too_many_arguments)]
pub fn coverage(
    p: &RasterParams,
    material: u32,
    uv: (f32, f32),
    vertex_alpha: f32,
    materials: &impl Load,
    textures: &impl Load,
    texels: &impl Load,
) -> f32 {
    let at = material * MATERIAL_WORDS;
    let base_texture = materials.load(at + 8);
    load_f32(materials, at + 3)
        * sample(textures, texels, p.textures, base_texture, uv.0, uv.1, UvFootprint::POINT, Probes::FULL)[3]
        * vertex_alpha
}

/// Whether a fragment of triangle `t` at planar depth `depth` is kept (module docs).
#[allow(clippy::too_many_arguments)]
pub fn fragment_kept(
    p: &RasterParams,
    t: u32,
    b0: f32,
    b1: f32,
    depth: f32,
    pixel: u32,
    vertices: &impl Load,
    triangles: &impl Load,
    materials: &impl Load,
    textures: &impl Load,
    texels: &impl Load,
    reach: &impl Load,
) -> bool {
    if !(depth >= p.near) || (p.peel != 0 && !(depth > load_f32(reach, pixel))) {
        return false;
    }
    let tri = triangle(triangles, t);
    let flags = materials.load(tri[3] * MATERIAL_WORDS + 10);
    if flags & (ALPHA_MASK | ALPHA_BLEND) == 0 {
        return true;
    }
    let vertex_alpha = interpolate_color(vertices, tri, b0, b1)[3];
    let alpha = coverage(p, tri[3], interpolate_uv(vertices, tri, b0, b1), vertex_alpha, materials, textures, texels);
    if flags & ALPHA_MASK != 0 { alpha >= load_f32(materials, tri[3] * MATERIAL_WORDS + 7) } else { alpha > 0.0 }
}

/// The triangles the indirect draw command `args` draws (its vertex count over 3, at most the
/// mesh's): what the graphics pipeline draws, so a command of zero vertices costs the fallback no
/// rasterising either.
pub fn drawn_triangles(p: &RasterParams, args: &impl Load) -> u32 {
    let n = args.load(0) / 3;
    if n < p.triangles { n } else { p.triangles }
}

/// Each triangle's conservative tile range for this view ([`tile_bounds`]): the fallback's prepass,
/// so the CPU stand-in reads it instead of projecting every triangle once per tile. (The graphics
/// pipeline neither runs nor reads it.)
#[allow(clippy::too_many_arguments)]
pub fn setup_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &RasterParams,
    vertices: R,
    triangles: R,
    materials: R,
    _textures: R,
    _texels: R,
    _reach: R,
    mut bounds: M,
    args: R,
    _target: R,
) {
    for_each_item(g, drawn_triangles(p, &args), |t| {
        let (v, _, drawn) = fetch(p, t, &vertices, &triangles, &materials);
        let c = [clip(p, v[0]), clip(p, v[1]), clip(p, v[2])];
        let b = if drawn { tile_bounds(p, &c) } else { [1, 1, 0, 0] };
        let mut k = 0;
        while k < 4 {
            bounds.store(4 * t + k, b[k as usize]);
            k += 1;
        }
    });
}

/// The CPU stand-in for the draw: each workgroup owns a 16x16 tile and walks every triangle (a
/// uniform loop), rasterising those whose tile range holds it.
#[allow(clippy::too_many_arguments)]
pub fn fallback_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &RasterParams,
    vertices: R,
    triangles: R,
    materials: R,
    textures: R,
    texels: R,
    reach: R,
    bounds: R,
    args: R,
    mut target: M,
) {
    let [wx, wy, _] = g.workgroup_id();
    let (x0, y0) = (wx * TILE, wy * TILE);
    let count = drawn_triangles(p, &args);
    let mut t = 0;
    while t < count {
        let meets =
            wx >= bounds.load(4 * t) && wy >= bounds.load(4 * t + 1) && wx <= bounds.load(4 * t + 2) && wy <= bounds.load(4 * t + 3);
        if meets {
            let (v, _, _) = fetch(p, t, &vertices, &triangles, &materials);
            let e = edges(&[clip(p, v[0]), clip(p, v[1]), clip(p, v[2])], p.near);
            g.each(|lid| {
                let (x, y) = (x0 + lid % TILE, y0 + lid / TILE);
                if x >= p.width || y >= p.height {
                    return;
                }
                let (qx, qy) = pixel_ndc(p, x, y);
                let (b0, b1, depth) = cover(&e, qx, qy);
                if depth <= 0.0 {
                    return;
                }
                let pi = y * p.width + x;
                let at = pi * VIS_WORDS;
                if target.load(at) != 0 && !(depth < f32::from_bits(target.load(at + 1))) {
                    return;
                }
                if fragment_kept(p, t, b0, b1, depth, pi, &vertices, &triangles, &materials, &textures, &texels, &reach) {
                    target.store(at, ((t + 1) as f32).to_bits());
                    target.store(at + 1, depth.to_bits());
                    target.store(at + 2, b0.to_bits());
                    target.store(at + 3, b1.to_bits());
                }
            });
        }
        t += 1;
    }
}

/// The tiles `[tx0, ty0, tx1, ty1]` (inclusive) whose pixel centres the triangle with clip corners
/// `c` may cover: from its screen bounds when every corner is in front of the near plane, every
/// tile when some corner is not, none (`tx0 > tx1`) when all lie behind it or it misses the image.
fn tile_bounds(p: &RasterParams, c: &[[f32; 3]; 3]) -> [u32; 4] {
    let tiles = [p.width.div_ceil(TILE), p.height.div_ceil(TILE)];
    let behind = [c[0][2] < p.near, c[1][2] < p.near, c[2][2] < p.near];
    if behind[0] && behind[1] && behind[2] {
        return [1, 1, 0, 0];
    }
    if behind[0] || behind[1] || behind[2] {
        return [0, 0, tiles[0] - 1, tiles[1] - 1];
    }
    let (w, h) = (p.width as f32, p.height as f32);
    let mut lo = [f32::MAX, f32::MAX];
    let mut hi = [f32::MIN, f32::MIN];
    let mut k = 0;
    while k < 3 {
        let sx = (c[k][0] / c[k][2] + 1.0) * 0.5 * w;
        let sy = (c[k][1] / c[k][2] + 1.0) * 0.5 * h;
        lo = [lo[0].min(sx), lo[1].min(sy)];
        hi = [hi[0].max(sx), hi[1].max(sy)];
        k += 1;
    }
    // Pixel centres sit at i + 0.5: the first centre at or right of `lo` is ceil(lo - 0.5).
    if !(hi[0] >= 0.5 && hi[1] >= 0.5 && lo[0] <= w - 0.5 && lo[1] <= h - 0.5) {
        return [1, 1, 0, 0];
    }
    let first = |v: f32| ceil(v - 0.5).max(0.0) as u32;
    let last = |v: f32, n: u32| (floor(v - 0.5).max(0.0) as u32).min(n - 1);
    [first(lo[0]) / TILE, first(lo[1]) / TILE, last(hi[0], p.width) / TILE, last(hi[1], p.height) / TILE]
}

kernel!(
    /// Every triangle's tile range for the view: the prepass of the draw's CPU fallback.
    RASTER_SETUP = raster_setup [64] (RasterParams)
        { read vertices, read triangles, read materials, read textures, read texels, read reach, bounds, read args, read target }
        => setup_pass
);

kernel!(
    /// The rasterising draw as a compute kernel: the draw's CPU fallback.
    RASTER_FALLBACK = raster_fallback [256] (RasterParams)
        { read vertices, read triangles, read materials, read textures, read texels, read reach, read bounds, read args, target }
        => fallback_pass
);

/// Vertex stage: vertex `i` is corner `i % 3` of triangle `i / 3`, pulled from the buffers. A
/// triangle that is not drawn (degenerate, or a culled back face) goes outside the clip volume.
#[cfg(target_arch = "spirv")]
#[spirv_std::spirv(vertex)]
#[allow(clippy::too_many_arguments)]
pub fn raster_vs(
    #[spirv(vertex_index)] vertex: i32,
    #[spirv(push_constant)] p: &RasterParams,
    #[spirv(descriptor_set = 0, binding = 0, storage_buffer)] vertices: &[u32],
    #[spirv(descriptor_set = 0, binding = 1, storage_buffer)] triangles: &[u32],
    #[spirv(descriptor_set = 0, binding = 2, storage_buffer)] materials: &[u32],
    #[spirv(position)] position: &mut spirv_std::glam::Vec4,
    bary: &mut spirv_std::glam::Vec2,
    depth: &mut f32,
    #[spirv(flat)] tri: &mut u32,
) {
    use crate::exec::GpuRead;
    let t = vertex as u32 / 3;
    let corner = vertex as u32 % 3;
    let (v, _, drawn) = fetch(p, t, &GpuRead(vertices), &GpuRead(triangles), &GpuRead(materials));
    let c = clip(p, v[corner as usize]);
    *position = if drawn { spirv_std::glam::Vec4::new(c[0], c[1], p.near, c[2]) } else { spirv_std::glam::Vec4::new(2.0, 2.0, 0.5, 1.0) };
    *bary = spirv_std::glam::Vec2::new(if corner == 0 { 1.0 } else { 0.0 }, if corner == 1 { 1.0 } else { 0.0 });
    *depth = c[2];
    *tri = t;
}

/// Fragment stage: the kept fragment's visibility record; the depth test keeps the nearest.
#[cfg(target_arch = "spirv")]
#[spirv_std::spirv(fragment)]
#[allow(clippy::too_many_arguments)]
pub fn raster_fs(
    #[spirv(frag_coord)] coord: spirv_std::glam::Vec4,
    #[spirv(push_constant)] p: &RasterParams,
    #[spirv(descriptor_set = 0, binding = 0, storage_buffer)] vertices: &[u32],
    #[spirv(descriptor_set = 0, binding = 1, storage_buffer)] triangles: &[u32],
    #[spirv(descriptor_set = 0, binding = 2, storage_buffer)] materials: &[u32],
    #[spirv(descriptor_set = 0, binding = 3, storage_buffer)] textures: &[u32],
    #[spirv(descriptor_set = 0, binding = 4, storage_buffer)] texels: &[u32],
    #[spirv(descriptor_set = 0, binding = 5, storage_buffer)] reach: &[u32],
    bary: spirv_std::glam::Vec2,
    depth: f32,
    #[spirv(flat)] tri: u32,
    output: &mut spirv_std::glam::Vec4,
) {
    use crate::exec::GpuRead;
    let pixel = coord.y as u32 * p.width + coord.x as u32;
    let kept = fragment_kept(
        p,
        tri,
        bary.x,
        bary.y,
        depth,
        pixel,
        &GpuRead(vertices),
        &GpuRead(triangles),
        &GpuRead(materials),
        &GpuRead(textures),
        &GpuRead(texels),
        &GpuRead(reach),
    );
    if !kept {
        spirv_std::arch::kill();
    }
    *output = spirv_std::glam::Vec4::new((tri + 1) as f32, depth, bary.x, bary.y);
}

/// The rasterising draw: stages, bindings, push constants and the CPU fallback (bindings: the
/// draw's seven buffers, then the draw command, then the visibility target).
#[cfg(not(target_arch = "spirv"))]
pub const RASTER_DRAW: crate::DrawDesc = crate::DrawDesc {
    vertex: "raster::draw::raster_vs",
    fragment: "raster::draw::raster_fs",
    bindings: 7,
    push_bytes: core::mem::size_of::<RasterParams>() as u32,
    vertices: 3,
    fallback: &RASTER_FALLBACK,
    fallback_tile: TILE,
    fallback_prepass: Some(&RASTER_SETUP),
    depth_test: true,
};
