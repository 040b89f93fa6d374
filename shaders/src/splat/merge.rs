//! Stage 2 (optional): hierarchical fragment merging (Franke et al. 2018, §6.1-6.2), one 2x2 step per dispatch.
//!
//! One invocation per output cell walks the four member cells' lists front to back (each list is in
//! depth order). While all four heads are mergeable (same merge level as this step's input, all out of
//! focus, depths within `merge_depth_ratio`, every colour channel within `merge_color_tol` of its
//! value, equal alpha, so a translucent fragment never merges with an opaque one) they become one
//! fragment: the members' average (premultiplied) colour and their alpha, the depth of the member with the
//! largest CoC, the block's centre, the next level. Otherwise the front-most head is passed through
//! unchanged (never merged again: its level no longer matches). Merging never makes a fragment
//! transparent: all four members or none.
//!
//! Umbra-aware merging (`FLAG_UMBRA_MERGE`): after a merge of opaque members, member fragments
//! inside the merged fragment's umbra (lens as an area light, the merged block's footprint as the occluder, see
//! [`crate::lens::ThinLens::umbra_length`]) are dropped; once the footprint exceeds the aperture the
//! umbra is infinite and everything behind goes.
//!
//! Reads the cell layout of `params.cell`/`cell_cap`/`cells_x`/`cells_y`; writes cells of twice the
//! edge with four times the capacity.

use super::fragment::{Fragment, depth_of};
use super::{FLAG_UMBRA_MERGE, SplatParams, stats};
use crate::exec::{Group, Mem};
use crate::lens::ThinLens;
use crate::wg::for_each_item;

/// 1/√π: the radius of the disc with the area of a unit square.
const INV_SQRT_PI: f32 = 0.564_189_6;

/// World-space radius of the disc with the area of an `edge`-pixel square at depth `z`: one pixel
/// spans `z / (v · pixels_per_unit)` with `v = f·z_f/(z_f − f)` the image distance.
#[inline]
pub fn footprint_radius(lens: &ThinLens, z: f32, edge: f32) -> f32 {
    let v = lens.focal_length * lens.focus_distance / (lens.focus_distance - lens.focal_length);
    edge * INV_SQRT_PI * z / (v * lens.pixels_per_unit)
}

/// Whether four heads may merge at this step.
#[inline]
pub fn mergeable(f: &[Fragment; 4], level: u32, p: &SplatParams) -> bool {
    let mut zmin = f[0].depth;
    let mut zmax = f[0].depth;
    let mut cmin = f[0].color;
    let mut cmax = f[0].color;
    let mut m = 0;
    while m < 4 {
        let q = &f[m];
        // Only fragments of equal alpha merge: a translucent one never joins an opaque one.
        if q.level != level || q.alpha != f[0].alpha || !(p.lens.coc_radius_px(q.depth) >= p.merge_min_radius) {
            return false;
        }
        zmin = if q.depth < zmin { q.depth } else { zmin };
        zmax = if q.depth > zmax { q.depth } else { zmax };
        let mut c = 0;
        while c < 3 {
            cmin[c] = if q.color[c] < cmin[c] { q.color[c] } else { cmin[c] };
            cmax[c] = if q.color[c] > cmax[c] { q.color[c] } else { cmax[c] };
            c += 1;
        }
        m += 1;
    }
    // The sky merges with the sky: inf <= inf·ratio.
    if !(zmax <= zmin * p.merge_depth_ratio) {
        return false;
    }
    let mut c = 0;
    while c < 3 {
        let scale = if cmax[c] > -cmin[c] { cmax[c] } else { -cmin[c] };
        // Relative spread, with a floor so that near-black values merge.
        if cmax[c] - cmin[c] > p.merge_color_tol * (scale + 1.0 / 64.0) {
            return false;
        }
        c += 1;
    }
    true
}

/// The fragment four mergeable members become, centred on output cell `(ox, oy)` of edge `edge` px.
#[inline]
pub fn merged(f: &[Fragment; 4], lens: &ThinLens, ox: u32, oy: u32, edge: u32) -> Fragment {
    let mut color = [0.0f32; 3];
    let mut widest = 0;
    let mut m = 0;
    while m < 4 {
        color[0] += 0.25 * f[m].color[0];
        color[1] += 0.25 * f[m].color[1];
        color[2] += 0.25 * f[m].color[2];
        if lens.coc_radius_px(f[m].depth) > lens.coc_radius_px(f[widest].depth) {
            widest = m;
        }
        m += 1;
    }
    // The block's centre in half pixels: 2·(o·edge + edge/2).
    Fragment { color, alpha: f[0].alpha, depth: f[widest].depth, level: f[0].level + 1, pos: [2 * ox * edge + edge, 2 * oy * edge + edge] }
}

pub fn merge_pass<G: Group, M: Mem>(g: &mut G, p: &SplatParams, cells_in: M, counts_in: M, mut cells_out: M, mut counts_out: M, mut st: M) {
    let out_x = p.cells_x.div_ceil(2);
    let outputs = out_x * p.cells_y.div_ceil(2);
    let level = if p.cell == 1 { 0 } else { 1 };
    let cap_out = 4 * p.cell_cap();
    let edge_out = 2 * p.cell;
    for_each_item(g, outputs, |o| {
        let (ox, oy) = (o % out_x, o / out_x);
        let mut cell = [0u32; 4];
        let mut count = [0u32; 4];
        let mut head = [0u32; 4];
        let mut total = 0;
        let mut m = 0;
        while m < 4 {
            let (cx, cy) = (2 * ox + (m & 1), 2 * oy + (m >> 1));
            if cx < p.cells_x && cy < p.cells_y {
                cell[m as usize] = cy * p.cells_x + cx;
                count[m as usize] = counts_in.load(cell[m as usize]);
                total += count[m as usize];
            }
            m += 1;
        }
        let (mut emitted, mut merges, mut skipped) = (0u32, 0u32, 0u32);
        let mut step = 0;
        // Every step consumes at least one input fragment.
        while step < total {
            step += 1;
            let mut f = [Fragment { color: [0.0; 3], alpha: 1.0, depth: 0.0, level: 0, pos: [0; 2] }; 4];
            let mut present = 0;
            let mut front = 4usize;
            let mut m = 0usize;
            while m < 4 {
                if head[m] < count[m] {
                    f[m] = Fragment::load(&cells_in, cell[m] * p.cell_cap() + head[m]);
                    present += 1;
                    if front == 4 || f[m].depth < f[front].depth {
                        front = m;
                    }
                }
                m += 1;
            }
            if present == 0 {
                break;
            }
            if present == 4 && mergeable(&f, level, p) {
                let out = merged(&f, &p.lens, ox, oy, edge_out);
                out.store(&mut cells_out, o * cap_out + emitted);
                emitted += 1;
                merges += 1;
                // Only an opaque fragment casts an umbra: what lies behind a translucent one shows.
                let umbra = p.flags & FLAG_UMBRA_MERGE != 0 && out.is_opaque();
                let r = footprint_radius(&p.lens, out.depth, edge_out as f32);
                let shadow = out.depth + p.lens.umbra_length(out.depth, r);
                let mut m = 0usize;
                while m < 4 {
                    head[m] += 1;
                    while umbra && head[m] < count[m] && depth_of(&cells_in, cell[m] * p.cell_cap() + head[m]) <= shadow {
                        head[m] += 1;
                        skipped += 1;
                    }
                    m += 1;
                }
            } else {
                f[front].store(&mut cells_out, o * cap_out + emitted);
                emitted += 1;
                head[front] += 1;
            }
        }
        counts_out.store(o, emitted);
        if merges > 0 {
            st.atomic_add(stats::MERGED, merges);
            st.atomic_add(stats::MERGED_INPUTS, 4 * merges);
        }
        if skipped > 0 {
            st.atomic_add(stats::UMBRA_SKIPPED, skipped);
        }
    });
}

kernel!(
    /// One 2x2 merging step over cells of `params.cell` pixels.
    MERGE = splat_merge [256] (SplatParams) { cells_in, counts_in, cells_out, counts_out, st } reads { cells_in, counts_in } => merge_pass
);
