//! Stage 5: order-correct accumulation (Franke et al. 2018, §5.3). One workgroup covers a block of pixels of a
//! tile and walks the tile's depth-sorted list in chunks of 256 fragments staged in workgroup memory;
//! every pixel blends the fragments whose disc covers its centre, front to back.
//!
//! Blending. A fragment standing for `footprint` pixels gives a pixel centre the share
//! `w = footprint · weight / Σ weight` of its disc (see [`weight`] and [`weight_sum`]): it spreads
//! exactly its own energy. Its alpha `α` scales that coverage: it adds `w` times its premultiplied
//! colour and spends `w·α` of the pixel ([`surfaces::take`]). (A fragment beside its pixel's
//! nearer ones spends the share of the pixel it covers, not the composite's alpha:
//! [`super::pack::budget_share`].) Front to back, each fragment takes at most the
//! coverage its nearer fragments left (`min(w·α, 1 − used)`): coverage is a budget the near field
//! spends first. A translucent fragment (or one of alpha 0, light that hides nothing) leaves the
//! rest of its share to what lies behind it. Unlike per-fragment
//! alpha compositing (`T ← T·(1 − α)`), the fragments of one blurred surface do not attenuate each
//! other (a blurred wall is not a stack of translucent sheets), and the visible and hidden layers of
//! a background together fill exactly what the foreground leaves. On the built-in scenes this is
//! several dB closer to the exact reference than compositing (README, "Blending"). Different
//! translucent surfaces, told apart by depth and by their summed disc shares, composite instead
//! ([`super::surfaces`]): a pane behind another is seen through it.
//!
//! A pixel's own in-focus front (see `pack`: the "over" of its leading in-focus slots, opaque or over
//! black) is not in any list: it takes all remaining coverage at its depth, which ends the pixel's
//! traversal, and keeps its full f32 colour. A pixel
//! stops early once its coverage is within [`SATURATED`] of full; the workgroup stops when all its
//! pixels have. The result is normalised by the coverage gathered (which fills the frame border,
//! where fragments from outside the image are missing, and holes left by dropped input). Colours are
//! at most `radiance::COLOR_MAX` = 2^100 and the coverage weights sum to at most 1, so the sums stay
//! finite, and so does the normalisation (by a coverage of at least 1e-6). A tile no list reaches
//! (`copy`) writes its sharp fronts directly; a thinned list's wide fragments take the share of
//! their lattice blocks (`bin::thin_weight`).

use super::bin::{TILE_COPY, TILE_THIN_SHIFT, thin_weight};
use super::fragment::{self, Fragment, shaped_weight, weight_sum};
use super::pack::load_sharp;
use super::surfaces::{self, Surfaces};
use super::{SplatParams, THREADS, stats};
use crate::exec::{Group, Load, Mem};
use crate::footprint;
use crate::lane::{LaneMask, Lanes};
use crate::lens::is_nan;
use crate::wg::{Max, reduce};

/// Coverage short of full at which a pixel stops.
pub const SATURATED: f32 = 1.0 / 1024.0;

const T: usize = THREADS as usize;
// Per-pixel state, one word per invocation each (f32 bits): accumulated colour, coverage used,
// depth of the pixel's sharp front (NaN: none) and list entries visited (u32).
const ACC_R: usize = 0;
const ACC_G: usize = T;
const ACC_B: usize = 2 * T;
const USED: usize = 3 * T;
const SHARP_Z: usize = 4 * T;
const VISITED: usize = 5 * T;
// The staged chunk: one fragment per invocation.
const CH_X: usize = 6 * T;
const CH_Y: usize = 7 * T;
const CH_S: usize = 8 * T;
const CH_A: usize = 9 * T;
const CH_R: usize = 10 * T;
const CH_G: usize = 11 * T;
const CH_B: usize = 12 * T;
const CH_Z: usize = 13 * T;
const CH_W: usize = 14 * T;
/// 1 for a background fragment, −1 for a foreground one (its aperture shape is point-reflected).
const CH_M: usize = 15 * T;
/// The fragment's alpha.
const CH_O: usize = 16 * T;
/// The "any pixel still active" reduction (and the list's translucent end's).
const ACTIVE: usize = 17 * T;
/// The pixel's [`Surfaces`] between chunks.
const SURFACES: usize = 18 * T;
/// The fragment's footprint ([`crate::footprint`]; `WHOLE`: splatted from its centre).
const CH_F: usize = SURFACES + surfaces::WORDS * T;
pub const SHARED_WORDS: usize = CH_F + T;

/// The pixels one invocation walks at a time ([`crate::lane`]). On the CPU a workgroup's
/// invocations run one after another, and a pixel's walk is a chain (each covering entry waits for
/// the coverage the last one left): walking eight pixels at once overlaps their chains, and their
/// arithmetic runs in vector registers. On the GPU each invocation walks its own. Each pixel's
/// arithmetic is the same either way, so the images are too.
type Px = crate::lane::Native;
type PxMask = <Px as Lanes>::Mask;
const L: usize = Px::N;
const LANES: u32 = L as u32;
const _: () = assert!(THREADS % LANES == 0);

#[inline]
fn get<const N: usize>(sh: &[u32; N], field: usize, i: u32) -> f32 {
    f32::from_bits(sh[field + i as usize])
}

#[inline]
fn set<const N: usize>(sh: &mut [u32; N], field: usize, i: u32, v: f32) {
    sh[field + i as usize] = v.to_bits();
}

/// `[f(0), .., f(L − 1)]` (written out: `core::array::from_fn` is not for SPIR-V).
#[inline(always)]
fn per_lane<T: Copy + Default>(mut f: impl FnMut(usize) -> T) -> [T; L] {
    let mut a = [T::default(); L];
    let mut l = 0;
    while l < L {
        a[l] = f(l);
        l += 1;
    }
    a
}

/// Pixels `i .. i + L` of `field`.
#[inline]
fn get_px<const N: usize>(sh: &[u32; N], field: usize, i: u32) -> Px {
    Px::from_fn(|l| get(sh, field, i + l as u32))
}

#[inline]
fn set_px<const N: usize>(sh: &mut [u32; N], field: usize, i: u32, v: Px) {
    let mut l = 0;
    while l < L {
        set(sh, field, i + l as u32, v.lane(l));
        l += 1;
    }
}

/// Adds the share `s` of premultiplied colour `c` to pixel `i`, which spends `a` of its coverage.
#[inline]
fn blend<const N: usize>(sh: &mut [u32; N], i: u32, s: f32, a: f32, c: [f32; 3]) {
    set(sh, ACC_R, i, get(sh, ACC_R, i) + s * c[0]);
    set(sh, ACC_G, i, get(sh, ACC_G, i) + s * c[1]);
    set(sh, ACC_B, i, get(sh, ACC_B, i) + s * c[2]);
    set(sh, USED, i, get(sh, USED, i) + a);
}

/// The first of the staged chunk's `n` entries (sorted front to back) at or behind depth `z`, `n`
/// if none (and for a NaN `z`): where a pixel whose sharp front lies at `z` stops.
#[inline]
fn first_behind<const N: usize>(sh: &[u32; N], n: u32, z: f32) -> u32 {
    let (mut lo, mut hi) = (0, n);
    while lo < hi {
        let mid = (lo + hi) / 2;
        if get(sh, CH_Z, mid) >= z { hi = mid } else { lo = mid + 1 }
    }
    lo
}

crate::pass_with_simd! {
#[allow(clippy::too_many_arguments)]
pub fn accumulate_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &SplatParams,
    sh: &mut [u32; SHARED_WORDS],
    sharp: R,
    dense: R,
    values: R,
    segments: R,
    copy: R,
    out: M,
    st: M,
    mask: R,
) {
    // (`pass_with_simd!` takes parameters as plain names.)
    let (mut out, mut st) = (out, st);
    let p = &super::planned(p, &st);
    let [wx, wy, _] = g.workgroup_id();
    let sub = p.tile / p.block();
    let (tx, ty) = (wx / sub, wy / sub);
    let t = ty * p.tiles_x + tx;
    let x0 = tx * p.tile + (wx % sub) * p.block();
    let y0 = ty * p.tile + (wy % sub) * p.block();
    // The pixel of invocation `lid`, and whether it lies inside the block and the image.
    let pixel = |lid: u32| -> (bool, u32, u32) {
        let (x, y) = (x0 + lid % p.block(), y0 + lid / p.block());
        (lid < p.block() * p.block() && x < p.width && y < p.height, x, y)
    };
    let store = |out: &mut M, x: u32, y: u32, c: [f32; 3]| {
        let i = 3 * (y * p.width + x);
        out.store(i, c[0].to_bits());
        out.store(i + 1, c[1].to_bits());
        out.store(i + 2, c[2].to_bits());
    };

    let tile = copy.load(t);
    if tile & TILE_COPY != 0 {
        g.each(|lid| {
            let (ok, x, y) = pixel(lid);
            if ok {
                let (c, z) = load_sharp(&sharp, y * p.width + x);
                store(&mut out, x, y, if is_nan(z) { [0.0; 3] } else { c });
            }
        });
        return;
    }

    let thin = tile >> TILE_THIN_SHIFT;
    let offset = segments.load(2 * t);
    let len = segments.load(2 * t + 1);
    // Where the list's last translucent entry ends. Only a translucent fragment reads a pixel's
    // surfaces, so behind it the walk spends the plain coverage budget (the same result, bit for
    // bit: `Surfaces::take` of an opaque fragment is `surfaces::take`).
    g.each(|lid| {
        let mut end = 0;
        let mut i = lid;
        while i < len {
            if !Fragment::is_opaque_at(&dense, values.load(offset + i)) {
                end = i + 1;
            }
            i += THREADS;
        }
        sh[ACTIVE + lid as usize] = end;
    });
    let translucent_end = reduce(g, sh, ACTIVE, Max);
    g.each(|lid| {
        let mut f = ACC_R;
        while f <= VISITED {
            sh[f + lid as usize] = 0;
            f += T;
        }
        let (ok, x, y) = pixel(lid);
        // No sharp front: NaN, never reached (a comparison with NaN is false), so the background
        // at +inf still blends.
        let z = if ok { load_sharp(&sharp, y * p.width + x).1 } else { f32::NAN };
        set(sh, SHARP_Z, lid, z);
        Surfaces::<f32>::start().store(sh, SURFACES, T, lid);
    });
    let mut start = 0;
    let mut active = 1;
    while start < len && active != 0 {
        g.each(|lid| {
            let i = start + lid;
            if i < len {
                let f = Fragment::load_in(p, &dense, values.load(offset + i));
                let r = f.radius(&p.lens, p.max_radius);
                let c = f.centre();
                set(sh, CH_X, lid, c[0]);
                set(sh, CH_Y, lid, c[1]);
                set(sh, CH_S, lid, r);
                let mirror = if f.depth < p.lens.focus_distance { -1.0 } else { 1.0 };
                // A footprint's weights are normalised already. A thinned list's wide fragments
                // stand for their lattice blocks.
                let share = if f.has_footprint() { 1.0 } else { f.footprint() / weight_sum(c, r, f.rim(), &p.aperture, mirror, &mask) };
                let share = share * thin_weight(p, thin, r);
                set(sh, CH_A, lid, share);
                sh[CH_F + lid as usize] = f.footprint;
                set(sh, CH_W, lid, f.rim());
                set(sh, CH_M, lid, mirror);
                set(sh, CH_O, lid, f.alpha);
                set(sh, CH_R, lid, f.color[0]);
                set(sh, CH_G, lid, f.color[1]);
                set(sh, CH_B, lid, f.color[2]);
                set(sh, CH_Z, lid, f.depth);
            }
        });
        let n = if len - start < THREADS { len - start } else { THREADS };
        g.each(|lid| {
            // Invocation `lid` walks pixels `lid .. lid + LANES` (each alone on the GPU).
            if lid % LANES != 0 {
                return;
            }
            // The pixels' state in registers for the walk: workgroup memory indexed by the
            // invocation is a gather or scatter per access on a SIMD implementation (lavapipe).
            let ok = per_lane(|l| pixel(lid + l as u32).0);
            let px = Px::from_fn(|l| pixel(lid + l as u32).1 as f32 + 0.5);
            let py = Px::from_fn(|l| pixel(lid + l as u32).2 as f32 + 0.5);
            let mut used = get_px(sh, USED, lid);
            let mut acc = [get_px(sh, ACC_R, lid), get_px(sh, ACC_G, lid), get_px(sh, ACC_B, lid)];
            let mut surfaces = Surfaces::<Px>::load(sh, SURFACES, T, lid);
            let live = per_lane(|l| ok[l] && used.lane(l) < 1.0 - SATURATED);
            // Where each pixel's walk ends (its sharp front lies in front of the rest of the
            // list), and the entries it visits, as a walk over every entry in order counts them:
            // up to and including the one that saturates it or lies at or behind its sharp front.
            let end = per_lane(|l| if live[l] { first_behind(sh, n, get(sh, SHARP_Z, lid + l as u32)) } else { 0 });
            // The pixels saturated in this chunk, and the entries they visited. (Lane values, not
            // arrays indexed by the lane inside the walk: on lavapipe, a function-local array indexed
            // by a variable in this loop left pixels black in the stress case
            // `translucent-stack-blurred`, whose walks cross hundreds of chunks.)
            let mut saturated = PxMask::splat(false);
            let mut saturated_after = Px::splat(0.0);
            // The entries each pixel still walks (as f32, exact): its end while it is live, 0
            // once saturated.
            let mut lim = Px::from_fn(|l| end[l] as f32);
            let side = p.footprint_side();
            let mut stop = lim.max_lane() as u32;
            let mut k = 0;
            while k < stop {
                let (cx, cy, s) = (get(sh, CH_X, k), get(sh, CH_Y, k), get(sh, CH_S, k));
                let (dx, dy) = (px - Px::splat(cx), py - Px::splat(cy));
                let d2 = dx * dx + dy * dy;
                // The pixels the entry's disc covers, without a branch per pixel (on the CPU a
                // hit or miss is a coin toss the branch predictor loses).
                let hit = d2.lt(Px::splat(s * s)) & Px::splat(k as f32).lt(lim);
                if hit.any() {
                    let fp = sh[CH_F + k as usize];
                    let rim = get(sh, CH_W, k);
                    let weight = if fp != footprint::WHOLE {
                        footprint::weight_at(fp, side, [dx, dy], s - footprint::REACH, hit)
                    } else if p.aperture.is_circle() {
                        fragment::weight(d2, Px::splat(s), Px::splat(rim))
                    } else {
                        // A shaped aperture: pixel by pixel.
                        let mirror = get(sh, CH_M, k);
                        Px::from_fn(|l| shaped_weight([dx.lane(l), dy.lane(l)], d2.lane(l), s, rim, &p.aperture, mirror, &mask))
                    };
                    let w = Px::splat(get(sh, CH_A, k)) * weight;
                    let alpha = get(sh, CH_O, k);
                    let (f, a) = if start + k < translucent_end {
                        surfaces.take(hit, w, alpha, fp != footprint::WHOLE, get(sh, CH_Z, k), used)
                    } else {
                        surfaces::take(w, alpha, Px::splat(1.0) - used)
                    };
                    acc = [
                        Px::select(hit, acc[0] + f * Px::splat(get(sh, CH_R, k)), acc[0]),
                        Px::select(hit, acc[1] + f * Px::splat(get(sh, CH_G, k)), acc[1]),
                        Px::select(hit, acc[2] + f * Px::splat(get(sh, CH_B, k)), acc[2]),
                    ];
                    used = Px::select(hit, used + a, used);
                    let now = hit & !used.lt(Px::splat(1.0 - SATURATED));
                    if now.any() {
                        saturated = saturated | now;
                        saturated_after = Px::select(now, Px::splat((k + 1) as f32), saturated_after);
                        lim = Px::select(now, Px::splat(0.0), lim);
                        stop = lim.max_lane() as u32;
                    }
                }
                k += 1;
            }
            set_px(sh, ACC_R, lid, acc[0]);
            set_px(sh, ACC_G, lid, acc[1]);
            set_px(sh, ACC_B, lid, acc[2]);
            set_px(sh, USED, lid, used);
            surfaces.store(sh, SURFACES, T, lid);
            let mut l = 0;
            while l < L {
                let q = lid + l as u32;
                let (visited, live) = if saturated.test(l) {
                    (saturated_after.lane(l) as u32, false)
                } else if live[l] {
                    (if end[l] < n { end[l] + 1 } else { n }, end[l] == n)
                } else {
                    (0, false)
                };
                if ok[l] {
                    sh[VISITED + q as usize] += visited;
                }
                sh[ACTIVE + q as usize] = live as u32;
                l += 1;
            }
        });
        active = reduce(g, sh, ACTIVE, Max);
        start += THREADS;
    }
    g.each(|lid| {
        let (ok, x, y) = pixel(lid);
        if !ok {
            return;
        }
        let (c, z) = load_sharp(&sharp, y * p.width + x);
        let rest = 1.0 - get(sh, USED, lid);
        if !is_nan(z) && rest > 0.0 {
            blend(sh, lid, rest, rest, c);
        }
        let cover = get(sh, USED, lid);
        let norm = if cover > 1e-6 { 1.0 / cover } else { 0.0 };
        store(&mut out, x, y, [get(sh, ACC_R, lid) * norm, get(sh, ACC_G, lid) * norm, get(sh, ACC_B, lid) * norm]);
    });
    // The early-out statistics, one pair of atomics per walk's pixels (a pixel's own on the GPU):
    // with a pair per pixel, the counters' cache line kept moving between the CPU's threads.
    g.each(|lid| {
        if lid % LANES != 0 {
            return;
        }
        let (mut early, mut skipped) = (0, 0);
        let mut q = lid;
        while q < lid + LANES {
            let visited = sh[VISITED + q as usize];
            if pixel(q).0 && visited < len {
                early += 1;
                skipped += len - visited;
            }
            q += 1;
        }
        if early > 0 {
            st.atomic_add(stats::EARLY_OUT, early);
            st.atomic_add(stats::SKIPPED_ENTRIES, skipped);
        }
    });
}
}

kernel!(
    /// Front-to-back accumulation of the sorted tile lists (or copy-through) into `out` (3 words a pixel).
    ACCUMULATE = splat_accumulate [256 subgroups] (SplatParams) shared [u32; 23 * 256]
        { read sharp, read dense, read values, read segments, read copy, out, st, read mask } => accumulate_pass
);
