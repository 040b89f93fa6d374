//! Stage 5: order-correct accumulation (seed 000 §5.3). One workgroup covers a block of pixels of a
//! tile and walks the tile's depth-sorted list in chunks of 256 fragments staged in workgroup memory;
//! every pixel blends the fragments whose disc covers its centre, front to back.
//!
//! Blending. A fragment standing for `footprint` pixels gives a pixel centre the alpha
//! `footprint · weight / Σ weight` (at most 1; see [`weight`] and [`weight_sum`]): it spreads
//! exactly its own energy. Fragments of one surface must not
//! occlude each other (a blurred wall is not a stack of translucent sheets), so consecutive fragments
//! within `slab_ratio` of the depth of the first form a slab whose alphas add; a slab then
//! composites over what lies behind with coverage `min(Σα, 1)`. A pixel stops once what it can still
//! receive is below [`SATURATED`] (early termination); the workgroup stops when all its pixels have.
//! The result is normalised by the coverage gathered, which fills the frame border (where fragments
//! from outside the image are missing) and holes left by dropped input, and undoes the colour scale
//! of packing.
//!
//! A tile the blur does not reach (`copy`) writes the front colour of every pixel in full precision.

use super::fragment::{Fragment, weight, weight_sum};
use super::pack::front_color;
use super::wg::{inclusive_scan, max};
use super::{SplatParams, THREADS, stats};
use crate::exec::{Group, Mem};

/// Remaining transmittance below which a pixel stops.
pub const SATURATED: f32 = 1.0 / 1024.0;

const T: usize = THREADS as usize;
// Per-pixel state, one word per invocation each (f32 bits).
const ACC_R: usize = 0;
const ACC_G: usize = T;
const ACC_B: usize = 2 * T;
const TRANS: usize = 3 * T;
const SLAB_R: usize = 4 * T;
const SLAB_G: usize = 5 * T;
const SLAB_B: usize = 6 * T;
const SLAB_A: usize = 7 * T;
const SLAB_Z: usize = 8 * T;
/// Entries visited (u32).
const VISITED: usize = 9 * T;
// The staged chunk: one fragment per invocation.
const CH_X: usize = 10 * T;
const CH_Y: usize = 11 * T;
const CH_S: usize = 12 * T;
const CH_A: usize = 13 * T;
const CH_R: usize = 14 * T;
const CH_G: usize = 15 * T;
const CH_B: usize = 16 * T;
const CH_Z: usize = 17 * T;
/// Two halves for the "any pixel still active" scan.
const ACTIVE: usize = 18 * T;
pub const SHARED_WORDS: usize = 20 * T;

#[inline]
fn get<const N: usize>(sh: &[u32; N], field: usize, i: u32) -> f32 {
    f32::from_bits(sh[field + i as usize])
}

#[inline]
fn set<const N: usize>(sh: &mut [u32; N], field: usize, i: u32, v: f32) {
    sh[field + i as usize] = v.to_bits();
}

/// Composites pixel `i`'s open slab over its accumulated colour.
#[inline]
fn close_slab<const N: usize>(sh: &mut [u32; N], i: u32) {
    let a = get(sh, SLAB_A, i);
    if a > 0.0 {
        let cover = if a < 1.0 { a } else { 1.0 };
        let trans = get(sh, TRANS, i);
        let k = trans * cover / a;
        set(sh, ACC_R, i, get(sh, ACC_R, i) + k * get(sh, SLAB_R, i));
        set(sh, ACC_G, i, get(sh, ACC_G, i) + k * get(sh, SLAB_G, i));
        set(sh, ACC_B, i, get(sh, ACC_B, i) + k * get(sh, SLAB_B, i));
        set(sh, TRANS, i, trans * (1.0 - cover));
        set(sh, SLAB_R, i, 0.0);
        set(sh, SLAB_G, i, 0.0);
        set(sh, SLAB_B, i, 0.0);
        set(sh, SLAB_A, i, 0.0);
    }
}

/// What pixel `i` can still receive: its transmittance times what its open slab leaves uncovered.
#[inline]
fn remaining<const N: usize>(sh: &[u32; N], i: u32) -> f32 {
    let open = 1.0 - get(sh, SLAB_A, i);
    get(sh, TRANS, i) * if open > 0.0 { open } else { 0.0 }
}

#[allow(clippy::too_many_arguments)]
pub fn accumulate_pass<G: Group, M: Mem>(
    g: &mut G,
    p: &SplatParams,
    sh: &mut [u32; SHARED_WORDS],
    layers: M,
    counts: M,
    dense: M,
    values: M,
    segments: M,
    copy: M,
    mut out: M,
    mut st: M,
) {
    let [wx, wy, _] = g.workgroup_id();
    let sub = p.tile / p.block;
    let (tx, ty) = (wx / sub, wy / sub);
    let t = ty * p.tiles_x + tx;
    let x0 = tx * p.tile + (wx % sub) * p.block;
    let y0 = ty * p.tile + (wy % sub) * p.block;
    // The pixel of invocation `lid`, or `None` past the block or the image.
    let pixel = |lid: u32| -> (bool, u32, u32) {
        let (x, y) = (x0 + lid % p.block, y0 + lid / p.block);
        (lid < p.block * p.block && x < p.width && y < p.height, x, y)
    };
    let store = |out: &mut M, x: u32, y: u32, c: [f32; 3]| {
        let i = 3 * (y * p.width + x);
        out.store(i, c[0].to_bits());
        out.store(i + 1, c[1].to_bits());
        out.store(i + 2, c[2].to_bits());
    };

    if copy.load(t) != 0 {
        g.each(|lid| {
            let (ok, x, y) = pixel(lid);
            if ok {
                store(&mut out, x, y, front_color(&layers, &counts, p, y * p.width + x));
            }
        });
        return;
    }

    let offset = segments.load(2 * t);
    let len = segments.load(2 * t + 1);
    g.each(|lid| {
        let mut f = ACC_R;
        while f <= SLAB_Z {
            sh[f + lid as usize] = 0;
            f += T;
        }
        set(sh, TRANS, lid, 1.0);
        sh[VISITED + lid as usize] = 0;
    });
    let mut start = 0;
    let mut active = 1;
    while start < len && active != 0 {
        g.each(|lid| {
            let i = start + lid;
            if i < len {
                let f = Fragment::load(&dense, values.load(offset + i));
                let r = f.radius(&p.lens, p.max_radius);
                let c = f.centre();
                set(sh, CH_X, lid, c[0]);
                set(sh, CH_Y, lid, c[1]);
                set(sh, CH_S, lid, r);
                set(sh, CH_A, lid, f.footprint() / weight_sum(c, r));
                set(sh, CH_R, lid, f.color[0]);
                set(sh, CH_G, lid, f.color[1]);
                set(sh, CH_B, lid, f.color[2]);
                set(sh, CH_Z, lid, f.depth);
            }
        });
        let n = if len - start < THREADS { len - start } else { THREADS };
        g.each(|lid| {
            let (ok, x, y) = pixel(lid);
            let mut live = ok && remaining(sh, lid) > SATURATED;
            let mut k = 0;
            while live && k < n {
                let (dx, dy) = (x as f32 + 0.5 - get(sh, CH_X, k), y as f32 + 0.5 - get(sh, CH_Y, k));
                let s = get(sh, CH_S, k);
                let d2 = dx * dx + dy * dy;
                if d2 < s * s {
                    let z = get(sh, CH_Z, k);
                    if get(sh, SLAB_A, lid) > 0.0 && z > get(sh, SLAB_Z, lid) * p.slab_ratio {
                        close_slab(sh, lid);
                    }
                    if get(sh, SLAB_A, lid) == 0.0 {
                        set(sh, SLAB_Z, lid, z);
                    }
                    let a = get(sh, CH_A, k) * weight(d2, s);
                    let a = if a < 1.0 { a } else { 1.0 };
                    set(sh, SLAB_R, lid, get(sh, SLAB_R, lid) + a * get(sh, CH_R, k));
                    set(sh, SLAB_G, lid, get(sh, SLAB_G, lid) + a * get(sh, CH_G, k));
                    set(sh, SLAB_B, lid, get(sh, SLAB_B, lid) + a * get(sh, CH_B, k));
                    set(sh, SLAB_A, lid, get(sh, SLAB_A, lid) + a);
                    live = remaining(sh, lid) > SATURATED;
                }
                k += 1;
            }
            if ok {
                sh[VISITED + lid as usize] += k;
            }
            sh[ACTIVE + lid as usize] = live as u32;
        });
        let s = inclusive_scan(g, sh, ACTIVE, max);
        let mut any = 0;
        g.each(|_| any = sh[s + T - 1]);
        active = any;
        start += THREADS;
    }
    g.each(|lid| {
        let (ok, x, y) = pixel(lid);
        if !ok {
            return;
        }
        close_slab(sh, lid);
        let cover = 1.0 - get(sh, TRANS, lid);
        let norm = if cover > 1e-6 { 1.0 / (cover * p.color_scale) } else { 0.0 };
        let c = [get(sh, ACC_R, lid) * norm, get(sh, ACC_G, lid) * norm, get(sh, ACC_B, lid) * norm];
        store(&mut out, x, y, c);
        let visited = sh[VISITED + lid as usize];
        if visited < len {
            st.atomic_add(stats::EARLY_OUT, 1);
            st.atomic_add(stats::SKIPPED_ENTRIES, len - visited);
        }
    });
}

kernel!(
    /// Front-to-back accumulation of the sorted tile lists (or copy-through) into `out` (3 words a pixel).
    ACCUMULATE = splat_accumulate [256] (SplatParams) shared [u32; 20 * 256]
        { layers, counts, dense, values, segments, copy, out, st } => accumulate_pass
);
