//! Stage 2 (optional): hierarchical fragment merging (Franke et al. 2018, §6.1-6.2), 2x2 or 4x4.
//!
//! Each 2x2 step walks the four member cells' lists front to back (each list is in depth order).
//! While all four heads are mergeable (same merge level as this step's input, all out of focus,
//! depths within `merge_depth_ratio`, every colour channel within `merge_color_tol` of its value,
//! equal alpha, so a translucent fragment never merges with an opaque one) they become one fragment:
//! the members' average (premultiplied) colour and their alpha, the depth of the member with the
//! largest CoC, the block's centre, the next level. Otherwise the front-most
//! head is passed through unchanged (never merged again: its level no longer matches). Merging
//! never makes a fragment transparent: all four members or none.
//!
//! Umbra-aware merging (`FLAG_UMBRA_MERGE`): after a merge of opaque members, member fragments inside the merged
//! fragment's umbra (lens as an area light, the merged block's footprint as the occluder, see
//! [`crate::lens::ThinLens::umbra_length`]) are dropped; once the footprint exceeds the aperture the
//! umbra is infinite and everything behind goes.
//!
//! **Shape.** One invocation per pixel, each walking its own pixel's list fragments
//! ([`PixelFragments`]) in its registers; no invocation holds another's state. Each step of the
//! workgroup is two phases with a barrier after each:
//! 1. every 2x2 cell that is asked for its next fragment reads its four members' heads from
//!    workgroup memory, and its members advance (all four after a merge, each skipping what lies in
//!    the merged fragment's umbra on its own; else only the front one); the cell's result goes to
//!    workgroup memory;
//! 2. one invocation per output cell reads its 2x2 cells' results: at 2x2 it stores the fragment;
//!    at 4x4 it makes the 4x4 step over its four 2x2 cells' heads the same way, stores the result
//!    and asks the 2x2 cells it used for their next fragment (after a merge, again while their head
//!    lies in its umbra).
//!
//! Each level reads its members as stored (packed and unpacked), so the lists are those of merging
//! level by level through memory, fragment for fragment. The output cell's list goes into its
//! region of the dense array as it is made, with its count and widest radius.

use super::fragment::Fragment;
use super::pack::PixelFragments;
use super::{FLAG_UMBRA_MERGE, SplatParams, stats};
use crate::exec::{Group, Load, Mem, shared_add};
use crate::footprint;
use crate::lens::ThinLens;

/// 1/√π: the radius of the disc with the area of a unit square.
const INV_SQRT_PI: f32 = 0.564_189_6;

/// World-space radius of the disc with the area of an `edge`-pixel square at depth `z`: one pixel
/// spans `z / (v · pixels_per_unit)` with `v = f·z_f/(z_f − f)` the image distance.
#[inline]
pub fn footprint_radius(lens: &ThinLens, z: f32, edge: f32) -> f32 {
    let v = lens.focal_length * lens.focus_distance / (lens.focus_distance - lens.focal_length);
    edge * INV_SQRT_PI * z / (v * lens.pixels_per_unit)
}

/// Invocations of a merge workgroup.
pub const MERGE_THREADS: u32 = 64;
/// Words of a fragment in workgroup memory: packed ([`Fragment::pack`]) and its footprint.
const REC: usize = 5;
const LANES: usize = MERGE_THREADS as usize;
const QUADS: usize = LANES / 4;
/// Workgroup memory: each invocation's head, in two buffers (one read, one written by a phase 1);
/// whether it has one; each 2x2 cell's result, whether it has one, what is asked of it and the
/// umbra it skips; output cells still walking.
const HEADS: usize = 0;
const LIVE: usize = HEADS + 2 * LANES * REC;
const QHEAD: usize = LIVE + 2 * LANES;
const QHAS: usize = QHEAD + QUADS * REC;
const QFLAG: usize = QHAS + QUADS;
const QSHADOW: usize = QFLAG + QUADS;
const ACTIVE: usize = QSHADOW + QUADS;
pub const MERGE_SHARED: usize = ACTIVE + 1;
/// `QFLAG` bits: the 2x2 cell makes its next fragment in the coming phase 1; and keeps making
/// them while they lie in the umbra at `QSHADOW`.
const NEED: u32 = 1;
const SKIP: u32 = 2;

/// Invocations per output cell of `cell` pixels: one per pixel.
#[inline]
pub const fn invocations_per_cell(cell: u32) -> u32 {
    cell * cell
}

/// The fragment stored at `sh[at..at + REC]`, as a stage reads it after storing it.
#[inline]
fn record<const N: usize>(sh: &[u32; N], at: usize) -> Fragment {
    Fragment::unpack([sh[at], sh[at + 1], sh[at + 2], sh[at + 3]]).with_footprint(sh[at + 4])
}

#[inline]
fn record_depth<const N: usize>(sh: &[u32; N], at: usize) -> f32 {
    f32::from_bits(sh[at + 2])
}

#[inline]
fn put<const N: usize>(sh: &mut [u32; N], at: usize, f: &Fragment) {
    let w = f.pack();
    sh[at] = w[0];
    sh[at + 1] = w[1];
    sh[at + 2] = w[2];
    sh[at + 3] = w[3];
    sh[at + 4] = f.footprint;
}

#[inline]
fn copy<const N: usize>(sh: &mut [u32; N], from: usize, to: usize) {
    let mut w = 0;
    while w < REC {
        sh[to + w] = sh[from + w];
        w += 1;
    }
}

#[inline]
fn min3(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [if b[0] < a[0] { b[0] } else { a[0] }, if b[1] < a[1] { b[1] } else { a[1] }, if b[2] < a[2] { b[2] } else { a[2] }]
}

#[inline]
fn max3(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [if b[0] > a[0] { b[0] } else { a[0] }, if b[1] > a[1] { b[1] } else { a[1] }, if b[2] > a[2] { b[2] } else { a[2] }]
}

/// Whether a colour channel's spread over four members is small enough to merge: relative to its
/// largest magnitude, with a floor so that near-black values merge.
#[inline]
fn channel_close(lo: f32, hi: f32, tol: f32) -> bool {
    let scale = if hi > -lo { hi } else { -lo };
    hi - lo <= tol * (scale + 1.0 / 64.0)
}

/// Whether the four heads at `sh[base + m·REC]` (`m` < 4) may merge at this step.
#[inline]
pub fn mergeable<const N: usize>(sh: &[u32; N], base: usize, level: u32, p: &SplatParams) -> bool {
    let f0 = record(sh, base);
    let (mut zmin, mut zmax, mut cmin, mut cmax) = (f0.depth, f0.depth, f0.color, f0.color);
    let mut m = 0;
    while m < 4 {
        let q = record(sh, base + m * REC);
        // Only fragments of equal alpha merge: a translucent one never joins an opaque one. One
        // that covers part of its pixel's sub-samples keeps its footprint, unmerged.
        if q.level != level
            || q.alpha != f0.alpha
            || !(p.lens.coc_radius_px(q.depth) >= p.merge_min_radius)
            || (q.has_footprint() && q.footprint != footprint::full(p.footprint_side()))
        {
            return false;
        }
        zmin = if q.depth < zmin { q.depth } else { zmin };
        zmax = if q.depth > zmax { q.depth } else { zmax };
        cmin = min3(cmin, q.color);
        cmax = max3(cmax, q.color);
        m += 1;
    }
    // The sky merges with the sky: inf <= inf·ratio.
    let tol = p.merge_color_tol;
    zmax <= zmin * p.merge_depth_ratio
        && channel_close(cmin[0], cmax[0], tol)
        && channel_close(cmin[1], cmax[1], tol)
        && channel_close(cmin[2], cmax[2], tol)
}

/// The fragment the four mergeable members at `sh[base + m·REC]` become, centred on output cell
/// `(ox, oy)` of edge `edge` px.
#[inline]
pub fn merged<const N: usize>(sh: &[u32; N], base: usize, lens: &ThinLens, ox: u32, oy: u32, edge: u32) -> Fragment {
    let f0 = record(sh, base);
    let mut color = [0.0f32; 3];
    let mut depth = f0.depth;
    let mut widest_r = lens.coc_radius_px(f0.depth);
    let mut m = 0;
    while m < 4 {
        let q = record(sh, base + m * REC);
        color = [color[0] + 0.25 * q.color[0], color[1] + 0.25 * q.color[1], color[2] + 0.25 * q.color[2]];
        let r = lens.coc_radius_px(q.depth);
        if r > widest_r {
            depth = q.depth;
            widest_r = r;
        }
        m += 1;
    }
    // The block's centre in half pixels: 2·(o·edge + edge/2).
    Fragment {
        color,
        alpha: f0.alpha,
        depth,
        level: f0.level + 1,
        pos: [2 * ox * edge + edge, 2 * oy * edge + edge],
        footprint: footprint::WHOLE,
    }
}

/// How many of four fragments at `sh[base + m·REC]` exist (`sh[live + m]` nonzero) and which of
/// them is nearest (the first of equals; 4 when none exists).
#[inline]
fn present_and_front<const N: usize>(sh: &[u32; N], base: usize, live: usize) -> (u32, u32) {
    let (mut present, mut front, mut front_z) = (0u32, 4u32, 0.0f32);
    let mut m = 0;
    while m < 4 {
        if sh[live + m] != 0 {
            present += 1;
            let z = record_depth(sh, base + m * REC);
            if front == 4 || z < front_z {
                front = m as u32;
                front_z = z;
            }
        }
        m += 1;
    }
    (present, front)
}

/// The depth behind which a merged fragment of `edge` pixels hides what its members hold, or
/// −∞ when it hides nothing (umbra merging off, or the fragment translucent: what lies behind a
/// translucent fragment shows).
#[inline]
fn umbra_end(p: &SplatParams, out: &Fragment, edge: f32) -> f32 {
    if p.flags & FLAG_UMBRA_MERGE != 0 && out.is_opaque() {
        out.depth + p.lens.umbra_length(out.depth, footprint_radius(&p.lens, out.depth, edge))
    } else {
        f32::NEG_INFINITY
    }
}

/// One invocation's state: its pixel's walk, and what the output cell's first invocation keeps.
#[derive(Clone, Copy)]
struct Lane {
    walk: PixelFragments,
    /// 1 while the walk has a head.
    live: u32,
    /// The invocation's 2x2 cell.
    cx: u32,
    cy: u32,
    merges: u32,
    skipped: u32,
    /// The output cell's fragments so far, their widest radius, how many were capped, and 1 once
    /// its list is done (its first invocation only).
    n: u32,
    widest: f32,
    capped: u32,
    done: u32,
}

impl Lane {
    const EMPTY: Lane =
        Lane { walk: PixelFragments::EMPTY, live: 0, cx: 0, cy: 0, merges: 0, skipped: 0, n: 0, widest: 0.0, capped: 0, done: 1 };

    #[inline]
    fn advance(&mut self, layers: &impl Load, p: &SplatParams) {
        self.live = self.walk.advance(layers, p) as u32;
    }

    /// Writes the output cell's next fragment into its region of the dense array.
    #[inline]
    fn emit<M: Mem>(&mut self, p: &SplatParams, dense: &mut M, o: u32, f: &Fragment) {
        f.store_in(p, dense, p.cell_region(o) + self.n);
        let (r, cut) = f.support(&p.lens, p.max_radius);
        self.widest = if r > self.widest { r } else { self.widest };
        self.capped += cut as u32;
        self.n += 1;
    }
}

/// Per output cell: its merged list, into the cell's region of the dense array
/// ([`SplatParams::cell_region`]); how many fragments it holds, their widest radius and how many
/// were capped, at `cells[o]` and `cells[cells + o]` (f32 bits) as `splat_tile_count` reads them;
/// and the merging statistics.
#[allow(clippy::too_many_arguments)]
pub fn merge_pass<G: Group, R: Load, M: Mem, const N: usize>(
    g: &mut G,
    p: &SplatParams,
    sh: &mut [u32; N],
    layers: R,
    counts: R,
    mut cells: M,
    mut dense: M,
    mut st: M,
) {
    let p = &super::planned(p, &st);
    let outputs = p.cells_x * p.cells_y;
    // Invocations per output cell (a power of two) and 2x2 cells per output cell.
    let shift = if p.cell == 4 { 4 } else { 2 };
    let per_cell = 1u32 << shift;
    let quads = per_cell / 4;
    let per_group = g.size() >> shift;
    let stride = g.num_workgroups()[0] * per_group;
    let mut lane = g.private(Lane::EMPTY);
    let mut base = g.workgroup_id()[0] * per_group;
    while base < outputs {
        g.each_with(&mut lane, |lid, s| {
            *s = Lane::EMPTY;
            let o = base + (lid >> shift);
            let (qg, m) = ((lid >> 2) as usize, lid & 3);
            if o < outputs {
                let qi = (lid & (per_cell - 1)) >> 2;
                let (ox, oy) = (o % p.cells_x, o / p.cells_x);
                (s.cx, s.cy) = if p.cell == 4 { (2 * ox + (qi & 1), 2 * oy + (qi >> 1)) } else { (ox, oy) };
                let (x, y) = (2 * s.cx + (m & 1), 2 * s.cy + (m >> 1));
                if x < p.width && y < p.height {
                    s.walk = PixelFragments::new(&counts, p, y * p.width + x);
                    s.advance(&layers, p);
                }
                s.done = 0;
            }
            if m == 0 {
                sh[QFLAG + qg] = if o < outputs { NEED } else { 0 };
            }
            put(sh, HEADS + lid as usize * REC, &s.walk.head);
            sh[LIVE + lid as usize] = s.live;
            if lid == 0 {
                sh[ACTIVE] = if outputs - base < per_group { outputs - base } else { per_group };
            }
        });
        let mut read = 0usize;
        loop {
            let mut active = 0;
            // Phase 1: the 2x2 cells asked for their next fragment make it.
            g.each_with(&mut lane, |lid, s| {
                active = sh[ACTIVE];
                let (qg, m, i) = ((lid >> 2) as usize, lid & 3, lid as usize);
                let (src, dst) = (read * LANES, (1 - read) * LANES);
                let mut moved = false;
                if active != 0 && sh[QFLAG + qg] & NEED != 0 {
                    let members = HEADS + (src + 4 * qg) * REC;
                    let (present, front) = present_and_front(sh, members, LIVE + src + 4 * qg);
                    if present == 4 && mergeable(sh, members, 0, p) {
                        let out = merged(sh, members, &p.lens, s.cx, s.cy, 2);
                        if m == 0 {
                            put(sh, QHEAD + qg * REC, &out);
                            s.merges += 1;
                        }
                        let shadow = umbra_end(p, &out, 2.0);
                        s.advance(&layers, p);
                        while s.live != 0 && s.walk.head.depth <= shadow {
                            s.advance(&layers, p);
                            s.skipped += 1;
                        }
                        moved = true;
                    } else if m == front {
                        copy(sh, HEADS + (src + i) * REC, QHEAD + qg * REC);
                        s.advance(&layers, p);
                        moved = true;
                    }
                    if m == 0 {
                        sh[QHAS + qg] = (present > 0) as u32;
                    }
                }
                if moved {
                    put(sh, HEADS + (dst + i) * REC, &s.walk.head);
                } else {
                    copy(sh, HEADS + (src + i) * REC, HEADS + (dst + i) * REC);
                }
                sh[LIVE + dst + i] = s.live;
            });
            if active == 0 {
                break;
            }
            read = 1 - read;
            // Phase 2: each output cell takes its next fragment.
            g.each_with(&mut lane, |lid, s| {
                if lid & (per_cell - 1) != 0 || s.done != 0 {
                    return;
                }
                let o = base + (lid >> shift);
                let q0 = (lid >> 2) as usize;
                // The 2x2 cells that made a fragment: one skipping an umbra goes on while its
                // fragment lies in it.
                let mut waiting = 0;
                let mut k = 0;
                while k < quads as usize {
                    let (q, flag) = (q0 + k, sh[QFLAG + q0 + k]);
                    if flag & NEED != 0 {
                        if flag & SKIP != 0 && sh[QHAS + q] != 0 && record_depth(sh, QHEAD + q * REC) <= f32::from_bits(sh[QSHADOW + q]) {
                            s.skipped += 1;
                            waiting += 1;
                        } else {
                            sh[QFLAG + q] = 0;
                        }
                    }
                    k += 1;
                }
                if waiting > 0 {
                    return;
                }
                let (present, front) = if quads == 1 {
                    (sh[QHAS + q0], 0)
                } else {
                    present_and_front(sh, QHEAD + q0 * REC, QHAS + q0)
                };
                if present == 0 {
                    s.done = 1;
                    shared_add(sh, ACTIVE, u32::MAX);
                } else if present == 4 && mergeable(sh, QHEAD + q0 * REC, 1, p) {
                    let out = merged(sh, QHEAD + q0 * REC, &p.lens, s.cx >> 1, s.cy >> 1, 4);
                    s.emit(p, &mut dense, o, &out);
                    s.merges += 1;
                    let shadow = umbra_end(p, &out, 4.0);
                    let mut k = 0;
                    while k < 4 {
                        sh[QFLAG + q0 + k] = NEED | if shadow > f32::NEG_INFINITY { SKIP } else { 0 };
                        sh[QSHADOW + q0 + k] = shadow.to_bits();
                        k += 1;
                    }
                } else {
                    let q = q0 + front as usize;
                    s.emit(p, &mut dense, o, &record(sh, QHEAD + q * REC));
                    sh[QFLAG + q] = NEED;
                }
            });
        }
        // The output cell's count, widest radius and statistics, its invocations' counts summed.
        g.each_with(&mut lane, |lid, s| {
            sh[HEADS + lid as usize] = s.merges;
            sh[HEADS + LANES + lid as usize] = s.skipped;
        });
        g.each_with(&mut lane, |lid, s| {
            let o = base + (lid >> shift);
            if lid & (per_cell - 1) != 0 || o >= outputs {
                return;
            }
            let (mut merges, mut skipped) = (0, 0);
            let mut k = 0;
            while k < per_cell as usize {
                merges += sh[HEADS + lid as usize + k];
                skipped += sh[HEADS + LANES + lid as usize + k];
                k += 1;
            }
            cells.store(o, s.n);
            cells.store(outputs + o, s.widest.to_bits());
            if merges > 0 {
                st.atomic_add(stats::MERGED, merges);
                st.atomic_add(stats::MERGED_INPUTS, 4 * merges);
            }
            if skipped > 0 {
                st.atomic_add(stats::UMBRA_SKIPPED, skipped);
            }
            if s.capped > 0 {
                st.atomic_add(stats::CAPPED, s.capped);
            }
        });
        base += stride;
    }
}

kernel!(
    /// Merged cells of `params.cell` pixels (2 or 4): their fragments, counts and widest radii;
    /// one invocation per pixel ([`invocations_per_cell`]).
    MERGE = splat_merge [64] (SplatParams) shared [u32; MERGE_SHARED] { read layers, read counts, cells, dense, st } => merge_pass
);
