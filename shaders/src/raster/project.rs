//! From world-space triangles to the screen, identically in the vertex stage and in the compute
//! rasteriser that stands in for it on the CPU.
//!
//! The clip transform is three rows (`x`, `y`, `w`) applied to `(P, 1)`; `w` is the planar depth
//! from the lens plane. The host builds them for a pinhole or for one lens point with the sheared
//! frustum that keeps the focus plane fixed (the accumulation buffer), plus a sub-pixel jitter.
//! Depth is reversed (`z = near`, so `z/w = near/w`: 1 at the near plane, towards 0 far away),
//! which keeps float depth precise at every distance and clips at the near plane.
//!
//! Vulkan's NDC has +y down, the image convention here (top row first).

use super::mesh::{DOUBLE_SIDED, MATERIAL_WORDS, TRIANGLE_WORDS, VERTEX_WORDS};
use super::texture::load_f32;
use crate::exec::Load;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct RasterParams {
    pub row_x: [f32; 4],
    pub row_y: [f32; 4],
    pub row_w: [f32; 4],
    /// World position of the eye this pass sees from (the lens point), for back-face culling.
    pub eye: [f32; 3],
    /// Near plane, planar depth, `> 0`.
    pub near: f32,
    pub width: u32,
    pub height: u32,
    pub triangles: u32,
    /// Entries in the texture table.
    pub textures: u32,
    /// 1: keep only fragments beyond `reach[pixel]` (depth peeling); 0: every fragment.
    pub peel: u32,
    pub _pad: [u32; 3],
}

const _: () = assert!(core::mem::size_of::<RasterParams>() <= 128);

#[inline]
pub fn vertex_position(vertices: &impl Load, index: u32) -> [f32; 3] {
    let at = index * VERTEX_WORDS;
    [load_f32(vertices, at), load_f32(vertices, at + 1), load_f32(vertices, at + 2)]
}

/// The three vertex indices and the material of triangle `t`.
#[inline]
pub fn triangle(triangles: &impl Load, t: u32) -> [u32; 4] {
    let at = t * TRIANGLE_WORDS;
    [triangles.load(at), triangles.load(at + 1), triangles.load(at + 2), triangles.load(at + 3)]
}

#[inline]
pub fn sub(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[inline]
pub fn dot(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[inline]
pub fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

#[inline]
fn row(r: [f32; 4], p: [f32; 3]) -> f32 {
    r[0] * p[0] + r[1] * p[1] + r[2] * p[2] + r[3]
}

/// Clip-space `(x, y, w)` of a world point.
#[inline]
pub fn clip(p: &RasterParams, world: [f32; 3]) -> [f32; 3] {
    [row(p.row_x, world), row(p.row_y, world), row(p.row_w, world)]
}

/// Whether triangle `tri` (vertex positions `v`) can be seen from the pass's eye: not degenerate,
/// and facing the eye (counter-clockwise seen from it) unless its material is double-sided.
pub fn visible(p: &RasterParams, v: &[[f32; 3]; 3], material: u32, materials: &impl Load) -> bool {
    let n = cross(sub(v[1], v[0]), sub(v[2], v[0]));
    if dot(n, n) == 0.0 {
        return false;
    }
    let flags = materials.load(material * MATERIAL_WORDS + 10);
    flags & DOUBLE_SIDED != 0 || dot(n, sub(v[0], p.eye)) < 0.0
}

/// The three corners of triangle `t` in world space, its material, and whether it is drawn.
pub fn fetch(p: &RasterParams, t: u32, vertices: &impl Load, triangles: &impl Load, materials: &impl Load) -> ([[f32; 3]; 3], u32, bool) {
    let tri = triangle(triangles, t);
    let v = [vertex_position(vertices, tri[0]), vertex_position(vertices, tri[1]), vertex_position(vertices, tri[2])];
    let drawn = visible(p, &v, tri[3], materials);
    (v, tri[3], drawn)
}

/// How the CPU rasteriser covers one triangle, set up once per triangle.
///
/// - Every corner in front of the near plane (the usual case): screen-space edge functions
///   relative to corner 0, then perspective-correct barycentrics from `1/w`. Well conditioned
///   however small or far the triangle is.
/// - Some corner behind it: homogeneous rasterisation (Olano and Greer), which needs no clipping:
///   at NDC point `q`, `λ = e·(qx, qy, 1)` with `e` the adjugate of the matrix of clip corners
///   `(x, y, w)` has the signs of its determinant inside the triangle, the barycentrics are
///   `λ / Σλ` and the planar depth `det / Σλ`. Its cross products lose precision for small, far
///   triangles, which is why it is kept to triangles reaching behind the near plane (large and
///   near by nature).
pub struct Edges {
    pub homogeneous: bool,
    pub e: [[f32; 3]; 3],
    pub det: f32,
    pub s0: [f32; 2],
    pub d1: [f32; 2],
    pub d2: [f32; 2],
    pub area: f32,
    pub inv_w: [f32; 3],
}

pub fn edges(c: &[[f32; 3]; 3], near: f32) -> Edges {
    let homogeneous = c[0][2] < near || c[1][2] < near || c[2][2] < near;
    if homogeneous {
        // M has columns (x_i, y_i, w_i); row i of adj(M) is the cross product of columns j and k.
        let e0 = cross(c[1], c[2]);
        let e1 = cross(c[2], c[0]);
        let e2 = cross(c[0], c[1]);
        let det = dot(c[0], e0);
        return Edges { homogeneous, e: [e0, e1, e2], det, s0: [0.0; 2], d1: [0.0; 2], d2: [0.0; 2], area: 0.0, inv_w: [0.0; 3] };
    }
    let inv_w = [1.0 / c[0][2], 1.0 / c[1][2], 1.0 / c[2][2]];
    let s = [[c[0][0] * inv_w[0], c[0][1] * inv_w[0]], [c[1][0] * inv_w[1], c[1][1] * inv_w[1]], [c[2][0] * inv_w[2], c[2][1] * inv_w[2]]];
    let d1 = [s[1][0] - s[0][0], s[1][1] - s[0][1]];
    let d2 = [s[2][0] - s[0][0], s[2][1] - s[0][1]];
    let area = d1[0] * d2[1] - d1[1] * d2[0];
    Edges { homogeneous, e: [[0.0; 3]; 3], det: 0.0, s0: s[0], d1, d2, area, inv_w }
}

/// Barycentrics `(b0, b1)` and planar depth of NDC point `(qx, qy)` when it lies inside the
/// triangle (edges included); depth 0 when it does not.
#[inline]
pub fn cover(edges: &Edges, qx: f32, qy: f32) -> (f32, f32, f32) {
    if edges.homogeneous {
        let l = [
            edges.e[0][0] * qx + edges.e[0][1] * qy + edges.e[0][2],
            edges.e[1][0] * qx + edges.e[1][1] * qy + edges.e[1][2],
            edges.e[2][0] * qx + edges.e[2][1] * qy + edges.e[2][2],
        ];
        let s = if edges.det > 0.0 { 1.0 } else { -1.0 };
        let sum = l[0] + l[1] + l[2];
        if edges.det == 0.0 || l[0] * s < 0.0 || l[1] * s < 0.0 || l[2] * s < 0.0 || sum * s <= 0.0 {
            return (0.0, 0.0, 0.0);
        }
        return (l[0] / sum, l[1] / sum, edges.det / sum);
    }
    if edges.area == 0.0 {
        return (0.0, 0.0, 0.0);
    }
    let r = [qx - edges.s0[0], qy - edges.s0[1]];
    let b1 = (r[0] * edges.d2[1] - r[1] * edges.d2[0]) / edges.area;
    let b2 = (edges.d1[0] * r[1] - edges.d1[1] * r[0]) / edges.area;
    let b0 = 1.0 - b1 - b2;
    if b0 < 0.0 || b1 < 0.0 || b2 < 0.0 {
        return (0.0, 0.0, 0.0);
    }
    let p = [b0 * edges.inv_w[0], b1 * edges.inv_w[1], b2 * edges.inv_w[2]];
    let sum = p[0] + p[1] + p[2];
    (p[0] / sum, p[1] / sum, 1.0 / sum)
}

/// NDC of the centre of pixel `(x, y)`.
#[inline]
pub fn pixel_ndc(p: &RasterParams, x: u32, y: u32) -> (f32, f32) {
    (2.0 * (x as f32 + 0.5) / p.width as f32 - 1.0, 2.0 * (y as f32 + 0.5) / p.height as f32 - 1.0)
}
