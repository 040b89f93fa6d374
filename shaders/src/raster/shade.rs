//! Shading the visibility buffer: per pixel, the kept fragment's radiance, coverage and depth from
//! the mesh (the lighting model of [`super::mesh`]), written as one layer of the multi-layer image
//! or added into the accumulation buffer.
//!
//! Layer mode also writes `reach[pixel]`, the depth the next peel must pass (Franke et al. 2018, §4.1): behind
//! an opaque fragment its umbra (`ThinLens::umbra_length` of the pixel's footprint; infinite once
//! the footprint covers the aperture), behind a partly covering one nothing more than its depth,
//! and infinity where nothing was found (nothing lies behind the background).
//!
//! Where nothing is found the pixel sees the background ([`Light::background`]): a fragment of
//! coverage 1 at infinite depth, written once, in the first pass whose reach was still finite (the
//! pass that found the pixel's ray escaping). A later pass, whose reach is already infinite, writes
//! coverage 0 there: nothing.

use super::draw::{VIS_WORDS, interpolate_color, interpolate_uv};
use super::mesh::{ALPHA_BLEND, Light, MATERIAL_WORDS, UNLIT, VERTEX_WORDS};
use super::project::{cross, dot, sub, triangle, vertex_position};
use super::texture::{Probes, UvFootprint, load_f32, sample};
use crate::exec::{Group, Load, Mem};
use crate::lens::ThinLens;
use crate::math::{absf, sqrt};
use crate::peel::{background_seen, next_reach};
use crate::wg::for_each_item;

/// [`ShadeParams::mode`]'s pass: write layer `(r, g, b, alpha, depth)` and the next reach.
pub const LAYER: u32 = 0;
/// [`ShadeParams::mode`]'s pass: add `alpha · (r, g, b)` into the accumulation buffer (3 words a pixel).
pub const ACCUMULATE: u32 = 1;
/// The bits of [`ShadeParams::mode`] that hold the pass.
const PASS_MASK: u32 = 0xff;
/// Where [`ShadeParams::mode`] holds its [`Probes`] ([`Probes::word`]; 0: [`Probes::FULL`]).
const PROBES_SHIFT: u32 = 8;

/// The `mode` word of a `pass` ([`LAYER`] or [`ACCUMULATE`]) whose minified texture lookups take
/// at most `probes` probes ([`Probes::at_most`]).
pub fn mode_word(pass: u32, probes: u32) -> u32 {
    (pass & PASS_MASK) | Probes::at_most(probes).word() << PROBES_SHIFT
}
/// Words a pixel of a layer.
pub const LAYER_WORDS: u32 = 5;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct ShadeParams {
    pub light: Light,
    /// The eye the pass saw from (normals are turned to face it).
    pub eye: [f32; 3],
    /// The pass and the texture probe budget ([`mode_word`]).
    pub mode: u32,
    pub lens: ThinLens,
    /// Pixel footprint radius per unit of depth (`tan(yfov/2) / height`).
    pub footprint_per_depth: f32,
    pub width: u32,
    pub height: u32,
    pub textures: u32,
    /// The camera's orientation, a unit quaternion `(x, y, z, w)` taking its axes (+x the image's
    /// right, +y its up, −z the view axis) to the world: a pixel's footprint is its square.
    pub camera: [f32; 4],
}

const _: () = assert!(core::mem::size_of::<ShadeParams>() <= 128);

impl ShadeParams {
    /// The pass: [`LAYER`] or [`ACCUMULATE`].
    #[inline]
    pub fn pass(&self) -> u32 {
        self.mode & PASS_MASK
    }

    /// The probes a minified texture lookup takes.
    #[inline]
    pub fn probes(&self) -> Probes {
        Probes::from_word(self.mode >> PROBES_SHIFT)
    }
}

fn normalize(v: [f32; 3]) -> [f32; 3] {
    let l = sqrt(dot(v, v));
    if l > 0.0 { [v[0] / l, v[1] / l, v[2] / l] } else { v }
}

/// `v` turned by the unit quaternion `q` (`x, y, z, w`).
fn rotate(q: [f32; 4], v: [f32; 3]) -> [f32; 3] {
    let axis = [q[0], q[1], q[2]];
    let t = cross(axis, v);
    let t = [2.0 * t[0], 2.0 * t[1], 2.0 * t[2]];
    let u = cross(axis, t);
    [v[0] + q[3] * t[0] + u[0], v[1] + q[3] * t[1] + u[1], v[2] + q[3] * t[2] + u[2]]
}

/// How the pixel at `position` maps into the texture coordinates of the triangle with corners `v`
/// and coordinates `uv`: the pixel's square, `width` across at its planar depth with its sides
/// along the image's axes (the camera's orientation `camera`), carried along the ray from `eye`
/// onto the triangle's plane (a ray differential, Igehy 1999), in the triangle's barycentric
/// frame, then into `(u, v)`.
fn uv_footprint(eye: [f32; 3], camera: [f32; 4], position: [f32; 3], v: [[f32; 3]; 3], uv: [(f32, f32); 3], width: f32) -> UvFootprint {
    let d = sub(position, eye);
    let (e1, e2) = (sub(v[1], v[0]), sub(v[2], v[0]));
    let n = cross(e1, e2);
    let (g11, g12, g22) = (dot(e1, e1), dot(e1, e2), dot(e2, e2));
    let gram = g11 * g22 - g12 * g12;
    if !(gram > 0.0) || !(width > 0.0) {
        return UvFootprint::POINT;
    }
    let (right, up) = (rotate(camera, [1.0, 0.0, 0.0]), rotate(camera, [0.0, 1.0, 0.0]));
    // Seen nearly edge-on the footprint stretches; at most a thousandfold.
    let dn = dot(d, n);
    let floor_dn = 1e-3 * sqrt(dot(d, d) * dot(n, n));
    let dn = if absf(dn) >= floor_dn {
        dn
    } else if dn < 0.0 {
        -floor_dn
    } else {
        floor_dn
    };
    let (du1, dv1, du2, dv2) = (uv[1].0 - uv[0].0, uv[1].1 - uv[0].1, uv[2].0 - uv[0].0, uv[2].1 - uv[0].1);
    let to_uv = |axis: [f32; 3]| {
        let along = dot(axis, n) / dn;
        let step = [width * (axis[0] - d[0] * along), width * (axis[1] - d[1] * along), width * (axis[2] - d[2] * along)];
        let (r1, r2) = (dot(step, e1), dot(step, e2));
        let (alpha, beta) = ((r1 * g22 - r2 * g12) / gram, (r2 * g11 - r1 * g12) / gram);
        (alpha * du1 + beta * du2, alpha * dv1 + beta * dv2)
    };
    let (du_a, dv_a) = to_uv(right);
    let (du_b, dv_b) = to_uv(up);
    UvFootprint { du_a, dv_a, du_b, dv_b }
}

/// The texture coordinates of each corner of triangle `tri`.
fn corner_uvs(vertices: &impl Load, tri: [u32; 4]) -> [(f32, f32); 3] {
    let uv = |k: u32| (load_f32(vertices, k * VERTEX_WORDS + 3), load_f32(vertices, k * VERTEX_WORDS + 7));
    [uv(tri[0]), uv(tri[1]), uv(tri[2])]
}

/// Radiance and coverage of triangle `t` at barycentrics `(b0, b1)` seen from `eye`, its textures
/// filtered over the pixel's square, `pixel_width` across at its depth, its sides along the
/// image's axes (`camera`, the camera's orientation; width 0: read at their finest level) with at
/// most `probes` probes a lookup.
#[allow(clippy::too_many_arguments)]
pub fn shade_point(
    light: &Light,
    eye: [f32; 3],
    camera: [f32; 4],
    texture_count: u32,
    probes: Probes,
    t: u32,
    b0: f32,
    b1: f32,
    pixel_width: f32,
    vertices: &impl Load,
    triangles: &impl Load,
    materials: &impl Load,
    textures: &impl Load,
    texels: &impl Load,
) -> ([f32; 3], f32) {
    let tri = triangle(triangles, t);
    let b = [b0, b1, 1.0 - b0 - b1];
    let v = [vertex_position(vertices, tri[0]), vertex_position(vertices, tri[1]), vertex_position(vertices, tri[2])];
    let mut position = [0.0; 3];
    let mut normal = [0.0; 3];
    let mut k = 0;
    while k < 3 {
        let at = tri[k] * VERTEX_WORDS;
        let mut j = 0;
        while j < 3 {
            position[j] += b[k] * v[k][j];
            normal[j] += b[k] * load_f32(vertices, at + 4 + j as u32);
            j += 1;
        }
        k += 1;
    }
    let face = cross(sub(v[1], v[0]), sub(v[2], v[0]));
    let mut n = if dot(normal, normal) > 0.0 { normalize(normal) } else { normalize(face) };
    // Turned to face the viewer, judged by the true surface (the face), as the analytic scenes do.
    if dot(face, sub(position, eye)) > 0.0 {
        n = [-n[0], -n[1], -n[2]];
    }
    let uv = interpolate_uv(vertices, tri, b0, b1);
    let at = tri[3] * MATERIAL_WORDS;
    let (base_index, emit_index) = (materials.load(at + 8), materials.load(at + 9));
    let footprint = if base_index < texture_count || emit_index < texture_count {
        uv_footprint(eye, camera, position, v, corner_uvs(vertices, tri), pixel_width)
    } else {
        UvFootprint::POINT
    };
    let base_tex = sample(textures, texels, texture_count, base_index, uv.0, uv.1, footprint, probes);
    let emit_tex = sample(textures, texels, texture_count, emit_index, uv.0, uv.1, footprint, probes);
    let vertex = interpolate_color(vertices, tri, b0, b1);
    let flags = materials.load(at + 10);
    let lambert = dot(n, light.direction).max(0.0);
    let mut rgb = [0.0; 3];
    let mut j = 0;
    while j < 3 {
        let base = load_f32(materials, at + j as u32) * base_tex[j] * vertex[j];
        let lit = if flags & UNLIT != 0 { base } else { base * (light.ambient[j] + light.color[j] * lambert) };
        rgb[j] = lit + load_f32(materials, at + 4 + j as u32) * emit_tex[j];
        j += 1;
    }
    let alpha = if flags & ALPHA_BLEND != 0 { (load_f32(materials, at + 3) * base_tex[3] * vertex[3]).clamp(0.0, 1.0) } else { 1.0 };
    (rgb, alpha)
}

#[allow(clippy::too_many_arguments)]
pub fn shade_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &ShadeParams,
    vis: R,
    vertices: R,
    triangles: R,
    materials: R,
    textures: R,
    texels: R,
    mut out: M,
    mut reach: M,
) {
    for_each_item(g, p.width * p.height, |pi| {
        let at = pi * VIS_WORDS;
        let id = f32::from_bits(vis.load(at)) as u32;
        let found = id > 0;
        let (rgb, alpha, depth) = if found {
            let (b0, b1) = (f32::from_bits(vis.load(at + 2)), f32::from_bits(vis.load(at + 3)));
            let depth = f32::from_bits(vis.load(at + 1));
            // The pixel is `2 · footprint_per_depth` scene units across per unit of planar depth.
            let pixel_width = 2.0 * p.footprint_per_depth * depth;
            let (rgb, alpha) = shade_point(
                &p.light,
                p.eye,
                p.camera,
                p.textures,
                p.probes(),
                id - 1,
                b0,
                b1,
                pixel_width,
                &vertices,
                &triangles,
                &materials,
                &textures,
                &texels,
            );
            (rgb, alpha, depth)
        } else if p.pass() == ACCUMULATE || background_seen(f32::from_bits(reach.load(pi))) {
            (p.light.background, 1.0, f32::INFINITY)
        } else {
            ([0.0; 3], 0.0, f32::INFINITY)
        };
        if p.pass() == ACCUMULATE {
            let mut j = 0usize;
            while j < 3 {
                let i = 3 * pi + j as u32;
                out.store(i, (f32::from_bits(out.load(i)) + alpha * rgb[j]).to_bits());
                j += 1;
            }
            return;
        }
        let o = pi * LAYER_WORDS;
        out.store(o, rgb[0].to_bits());
        out.store(o + 1, rgb[1].to_bits());
        out.store(o + 2, rgb[2].to_bits());
        out.store(o + 3, alpha.to_bits());
        out.store(o + 4, depth.to_bits());
        let next = next_reach(found, alpha, depth, &p.lens, p.footprint_per_depth);
        reach.store(pi, next.to_bits());
    });
}

kernel!(
    /// Shades the visibility buffer into a layer (and the next reach) or the accumulation buffer.
    RASTER_SHADE = raster_shade [256] (ShadeParams)
        { read vis, read vertices, read triangles, read materials, read textures, read texels, out, reach } => shade_pass
);
