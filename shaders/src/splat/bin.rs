//! Stage 3: tile lists (Franke et al. 2018, §5.1).
//!
//! - `splat_tile_count` (one cell an invocation, as many tiles a workgroup as that fills):
//!   fragments per tile, each cell's offset inside its tile (a scan of the partially filled cells:
//!   the index that lets every thread take fragments of any pixel evenly), and the largest
//!   fragment radius in the tile.
//! - `splat_alloc` (one invocation per tile): whether any tile within `rings` has fragments whose
//!   largest radius can reach this tile (the lists hold blurred fragments only); a tile none reaches
//!   is copied through.
//! - `splat_bin` (one workgroup per tile): every invocation takes candidates from the neighbours'
//!   fragments (one at a time on a GPU, sixteen consecutive ones where invocations run one after
//!   another: [`candidates_per_thread`]) and keeps those whose disc reaches a pixel centre of the
//!   tile. A neighbour's candidates are its fragments in the dense array, cell by cell in the tile,
//!   each cell's in its region ([`SplatParams::cell_region`], written by packing or merging), found
//!   through the cells' offsets in the tile. Three passes: `splat_bin_count` counts each list at
//!   every thinning level ([`thin_keeps`]), `splat_bin_plan` chooses one cap on list length under
//!   which the lists fit the pool and places them (a scan over the tiles), and `splat_bin` writes
//!   each list in place through a workgroup scan, from the count's test results where it kept them
//!   and testing again beyond. Only a list that fits at no level leaves its tile sharp (counted as
//!   overflow). The destination tile gathers its list (rather than sources scattering with
//!   atomics), and the plan places lists in tile order, so every list comes out in the same place
//!   and order on every backend, in dense order, and the stable sort that follows is
//!   deterministic.

use super::fragment::Fragment;
use super::planned;
use super::{FLAG_SERIAL, SplatParams, THREADS, stats};
use crate::exec::{Group, Load, Mem};
use crate::wg::{Add, Max, for_each_item, inclusive_scan, reduce, segmented_scans};

/// Tiles one workgroup of `splat_tile_count` counts: one cell an invocation, so as many tiles as
/// its invocations hold (16 of 4x4-merged 16-px tiles), or one tile where a tile has more cells
/// than the workgroup has invocations (each then takes a run of consecutive cells).
#[inline]
pub fn tiles_per_count_group(p: &SplatParams) -> u32 {
    let cells = p.cells_per_tile_edge() * p.cells_per_tile_edge();
    if cells >= THREADS { 1 } else { THREADS / cells }
}
/// Candidates one invocation of `splat_bin` tests at a time where a workgroup's invocations run one
/// after another (`FLAG_SERIAL`, the CPU backend): consecutive ones, so that one search for the
/// first one's cell serves them all (binning `railing` at 1920x1080 merged 4x4 took 115 ms with 8,
/// 101 ms with 16). A GPU takes one: adjacent invocations test adjacent candidates, so their loads
/// coalesce and every invocation is busy while a list has 256 candidates left.
pub const SERIAL_CANDIDATES_PER_THREAD: u32 = 16;
const NONE: u32 = u32::MAX;

/// The candidates an invocation of `splat_bin` tests at a time on the device `p` was made for.
#[inline]
pub fn candidates_per_thread(p: &SplatParams) -> u32 {
    if p.flags & FLAG_SERIAL != 0 { SERIAL_CANDIDATES_PER_THREAD } else { 1 }
}

/// `copy[t]`: the tile shows its sharp fronts only (no blur reaches it, or its list fits nowhere).
pub const TILE_COPY: u32 = 1;
/// `copy[t] >> TILE_THIN_SHIFT`: the tile's thinning level (0: its whole list).
pub const TILE_THIN_SHIFT: u32 = 1;
/// Deepest thinning: the widest fragments (radius at least 32 cells) from a lattice of 2^4 = 16
/// cells a side.
pub const MAX_THIN: u32 = 4;

/// Thinning, the fallback for a list too long for the sort or the pool. At level `k` a fragment of
/// radius at least [`thin_radius`]`(j)` for some `j <= k` (the largest such `j`: its own level) is
/// kept only from the source cells on a lattice of `2^j` cells a side, and stands for the `4^j`
/// cells of its lattice block ([`thin_weight`]); narrower fragments are all kept. The list stays
/// sorted and order-correct: the blur of a wide disc is sampled from a coarser grid of sources,
/// as merging does with the sources' colours averaged, and the wider the disc the coarser the
/// grid. Levels go up until the list fits; the frame reports the tiles thinned.
#[inline]
pub fn thin_keeps(p: &SplatParams, thin: u32, cell_x: u32, cell_y: u32, radius: f32) -> bool {
    (cell_x | cell_y) & ((1 << own_level(p, thin, radius)) - 1) == 0
}

/// The level a fragment of radius `radius` is thinned at in a list thinned to level `thin`.
#[inline]
fn own_level(p: &SplatParams, thin: u32, radius: f32) -> u32 {
    let mut j = 0;
    while j < thin && radius >= thin_radius(p, j + 1) {
        j += 1;
    }
    j
}

/// The radius (px) from which fragments are thinned at level `j`: two lattice spacings, so that a
/// thinned disc always covers several lattice points' worth of pixels.
#[inline]
pub fn thin_radius(p: &SplatParams, j: u32) -> f32 {
    (2 * (p.cell << j)) as f32
}

/// The share a kept fragment of radius `radius` takes in a list thinned to level `thin`: the
/// cells of its lattice block.
#[inline]
pub fn thin_weight(p: &SplatParams, thin: u32, radius: f32) -> f32 {
    (1u32 << (2 * own_level(p, thin, radius))) as f32
}

/// Index of cell `c` (row-major inside tile `(tx, ty)`), or `NONE` outside the cell grid.
#[inline]
fn cell_of(p: &SplatParams, tx: u32, ty: u32, c: u32) -> u32 {
    let ct = p.cells_per_tile_edge();
    if c >= ct * ct {
        return NONE;
    }
    let (gx, gy) = (tx * ct + c % ct, ty * ct + c / ct);
    if gx < p.cells_x && gy < p.cells_y { gy * p.cells_x + gx } else { NONE }
}

/// Pixel span `[start, end)` of block `t` of `tile` pixels (a tile, or a cell) along an axis of
/// `size` pixels.
#[inline]
fn span(t: u32, tile: u32, size: u32) -> (f32, f32) {
    let end = if (t + 1) * tile < size { (t + 1) * tile } else { size };
    ((t * tile) as f32, end as f32)
}

/// Distance from `v` to the interval `[lo, hi]` (0 inside).
#[inline]
fn gap(v_lo: f32, v_hi: f32, lo: f32, hi: f32) -> f32 {
    let a = lo - v_hi;
    let b = v_lo - hi;
    let g = if a > b { a } else { b };
    if g > 0.0 { g } else { 0.0 }
}

/// Whether a fragment of radius `r` anywhere inside tile `(sx, sy)` can cover a pixel centre of tile
/// `(tx, ty)`.
#[inline]
pub fn tile_reaches(p: &SplatParams, sx: u32, sy: u32, tx: u32, ty: u32, r: f32) -> bool {
    block_reaches(p, span(sx, p.tile, p.width), span(sy, p.tile, p.height), tx, ty, r)
}

/// Whether a fragment of radius `r` centred anywhere in the block of pixels `[x0, x1] × [y0, y1]`
/// can cover a pixel centre of tile `(tx, ty)`.
#[inline]
fn block_reaches(p: &SplatParams, (sx0, sx1): (f32, f32), (sy0, sy1): (f32, f32), tx: u32, ty: u32, r: f32) -> bool {
    let (tx0, tx1) = span(tx, p.tile, p.width);
    let (ty0, ty1) = span(ty, p.tile, p.height);
    let gx = gap(sx0, sx1, tx0 + 0.5, tx1 - 0.5);
    let gy = gap(sy0, sy1, ty0 + 0.5, ty1 - 0.5);
    gx * gx + gy * gy <= r * r
}

/// Whether a disc of radius `r` centred at `c` (pixels) covers a pixel centre of tile `(tx, ty)`.
#[inline]
fn disc_reaches(p: &SplatParams, c: [f32; 2], r: f32, tx: u32, ty: u32) -> bool {
    let (tx0, tx1) = span(tx, p.tile, p.width);
    let (ty0, ty1) = span(ty, p.tile, p.height);
    let gx = gap(c[0], c[0], tx0 + 0.5, tx1 - 0.5);
    let gy = gap(c[1], c[1], ty0 + 0.5, ty1 - 0.5);
    gx * gx + gy * gy <= r * r
}

/// Per tile: its fragment count, each cell's offset inside it and its widest radius. `cells` holds
/// each cell's fragment count at `cells[c]` and its widest radius (f32 bits, 0 for none) at
/// `cells[n + c]` (`n` cells in the frame, written by `pack` or `merge`); `offsets` gets the offset
/// at `offsets[c]` and the radius again at `offsets[n + c]`, for binning (which writes its keys
/// over `cells`). A workgroup takes [`tiles_per_count_group`] consecutive tiles, an invocation a
/// cell (or a run of cells), the tiles' cells one after another; a scan per tile (segmented) gives
/// the offsets, the tile's count and its widest radius.
pub fn tile_count_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &SplatParams,
    sh: &mut [u32; 6 * THREADS as usize],
    cells: R,
    mut tile_count: M,
    mut offsets: M,
    mut tile_radius: M,
    mut st: M,
) {
    let n_cells = p.cells_x * p.cells_y;
    let tiles = p.tiles_x * p.tiles_y;
    let per_tile = p.cells_per_tile_edge() * p.cells_per_tile_edge();
    let group_tiles = tiles_per_count_group(p);
    let per = per_tile.div_ceil(THREADS);
    let t_usize = THREADS as usize;
    // Workgroup memory: [0, 2T) the counts' scan, [2T, 4T) the radii's, [4T, 5T) each
    // invocation's tile among the workgroup's (the scans' segments), [5T, 6T) its own count.
    let (counts, radii, segs, own) = (0, 2 * t_usize, 4 * t_usize, 5 * t_usize);
    // The tile of invocation `lid` (its index among the group's, and in the frame; none past the
    // frame's last) and the first of its cells in that tile.
    let place = |first_tile: u32, lid: u32| -> (u32, u32, u32) {
        let slot = lid * per / per_tile;
        (slot, first_tile + slot, lid * per - slot * per_tile)
    };
    let groups = tiles.div_ceil(group_tiles);
    let mut group = g.workgroup_id()[0];
    while group < groups {
        let first_tile = group * group_tiles;
        g.each(|lid| {
            let (slot, t, first) = place(first_tile, lid);
            let (total, widest) =
                if slot < group_tiles && t < tiles { run_of_cells(p, &cells, t, first, per, 0, |_, _| {}) } else { (0, 0.0) };
            sh[counts + lid as usize] = total;
            // Radii are positive, so their bits order like the values.
            sh[radii + lid as usize] = widest.to_bits();
            sh[segs + lid as usize] = slot;
            sh[own + lid as usize] = total;
        });
        let (sums, widest) = segmented_scans(g, sh, (counts, radii, segs), Add, Max);
        g.each(|lid| {
            let (slot, t, first) = place(first_tile, lid);
            if slot >= group_tiles || t >= tiles {
                return;
            }
            let inclusive = sh[sums + lid as usize];
            run_of_cells(p, &cells, t, first, per, inclusive - sh[own + lid as usize], |cell, offset| {
                offsets.store(cell, offset);
                offsets.store(n_cells + cell, cells.load(n_cells + cell));
            });
            // The tile's last invocation holds its totals.
            if lid == THREADS - 1 || sh[segs + lid as usize + 1] != slot {
                tile_count.store(t, inclusive);
                tile_radius.store(t, sh[widest + lid as usize]);
                if inclusive > 0 {
                    st.atomic_add(stats::TILED, inclusive);
                }
            }
        });
        group += g.num_workgroups()[0];
    }
}

/// The fragment count and widest radius of the `per` cells of tile `t` from its cell `first` (those
/// inside the grid), calling `f(cell, offset)` for each with its offset in the tile counted on
/// from `running`.
#[allow(clippy::too_many_arguments)]
#[inline]
fn run_of_cells(
    p: &SplatParams,
    cells: &impl Load,
    t: u32,
    first: u32,
    per: u32,
    mut running: u32,
    mut f: impl FnMut(u32, u32),
) -> (u32, f32) {
    let n_cells = p.cells_x * p.cells_y;
    let (tx, ty) = (t % p.tiles_x, t / p.tiles_x);
    let (mut total, mut widest) = (0u32, 0.0f32);
    let mut i = 0;
    while i < per {
        let cell = cell_of(p, tx, ty, first + i);
        if cell != NONE {
            let n = cells.load(cell);
            let r = f32::from_bits(cells.load(n_cells + cell));
            f(cell, running);
            running += n;
            total += n;
            widest = if r > widest { r } else { widest };
        }
        i += 1;
    }
    (total, widest)
}

pub fn alloc_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &SplatParams, tile_count: R, tile_radius: R, mut copy: M, mut st: M) {
    let p = &planned(p, &st);
    let tiles = p.tiles_x * p.tiles_y;
    for_each_item(g, tiles, |t| {
        let (tx, ty) = (t % p.tiles_x, t / p.tiles_x);
        let rings = p.rings as i32;
        let mut reached = false;
        let mut dy = -rings;
        while dy <= rings && !reached {
            let mut dx = -rings;
            while dx <= rings && !reached {
                let (sx, sy) = (tx as i32 + dx, ty as i32 + dy);
                dx += 1;
                if sx < 0 || sy < 0 || sx >= p.tiles_x as i32 || sy >= p.tiles_y as i32 {
                    continue;
                }
                let s = sy as u32 * p.tiles_x + sx as u32;
                reached = tile_count.load(s) > 0
                    && (s == t || tile_reaches(p, sx as u32, sy as u32, tx, ty, f32::from_bits(tile_radius.load(s))));
            }
            dy += 1;
        }
        copy.store(t, !reached as u32);
        if !reached {
            st.atomic_add(stats::COPY_TILES, 1);
        }
    });
}

/// Words of workgroup memory `splat_bin_count` and `splat_bin` use.
const BIN_SHARED: usize = 7 * THREADS as usize;
/// Candidates whose test results the count keeps for the writing pass, per invocation: the bits of
/// a word (`cache[t · THREADS + lid]`).
const CACHED_CANDIDATES: u32 = 32;
/// Thinning levels a tile's list is counted at, 0 (whole) to [`MAX_THIN`]: `thin_counts[t · LEVELS + level]`.
pub const LEVELS: u32 = MAX_THIN + 1;
// Workgroup memory of both binning passes: [0, 2T) a scan or reduction of one word per invocation;
// [2T, 3T) the masks of the step; [3T, 5T) the scan of the neighbours' candidate counts; [5T, 6T)
// the neighbours' tile indices; [6T, 7T) more reductions.
const SCAN: usize = 0;
const MASKS: usize = 2 * THREADS as usize;
const NB_SCAN: usize = 3 * THREADS as usize;
const NB_TILE: usize = 5 * THREADS as usize;

/// The candidate space of tile `(tx, ty)`: the fragments of every neighbour tile within the rings
/// that can reach it (none for a tile copied through), their counts scanned at `sh[nb..]` and
/// their tile indices at `sh[NB_TILE..]`. Returns `nb` and the candidates in all.
fn candidate_space<G: Group, const N: usize>(
    g: &mut G,
    p: &SplatParams,
    sh: &mut [u32; N],
    tile_count: &impl Load,
    tile_radius: &impl Load,
    copied: bool,
    tx: u32,
    ty: u32,
) -> (usize, u32) {
    let t = ty * p.tiles_x + tx;
    let side = 2 * p.rings + 1;
    g.each(|lid| {
        let mut n = 0;
        let mut from = 0;
        if lid < side * side && !copied {
            let (sx, sy) = (tx as i32 + (lid % side) as i32 - p.rings as i32, ty as i32 + (lid / side) as i32 - p.rings as i32);
            if sx >= 0 && sy >= 0 && sx < p.tiles_x as i32 && sy < p.tiles_y as i32 {
                let s = sy as u32 * p.tiles_x + sx as u32;
                let r = f32::from_bits(tile_radius.load(s));
                if s == t || tile_reaches(p, sx as u32, sy as u32, tx, ty, r) {
                    n = tile_count.load(s);
                    from = s;
                }
            }
        }
        sh[NB_SCAN + lid as usize] = n;
        sh[NB_TILE + lid as usize] = from;
    });
    let nb = inclusive_scan(g, sh, NB_SCAN, Add);
    (nb, sh[nb + THREADS as usize - 1])
}

/// Binning, first pass (one workgroup per tile): how long the tile's list is at every thinning
/// level ([`thin_keeps`]; the levels are nested, each keeping a subset of the one before), into
/// `thin_counts`, and each invocation's test results of its first candidates into `cache`. Each
/// invocation takes its candidates ([`candidates_per_thread`] at a time, the workgroup's next
/// ones), then one reduction a level.
pub fn bin_count_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &SplatParams,
    sh: &mut [u32; BIN_SHARED],
    dense: R,
    tile_count: R,
    offsets: R,
    tile_radius: R,
    copy: R,
    mut thin_counts: M,
    mut cache: M,
    st: R,
) {
    let p = &planned(p, &st);
    let [tx, ty, _] = g.workgroup_id();
    let t = ty * p.tiles_x + tx;
    let (nb, total) = candidate_space(g, p, sh, &tile_count, &tile_radius, copy.load(t) != 0, tx, ty);
    let per = candidates_per_thread(p);
    let cached_chunks = CACHED_CANDIDATES >> per.trailing_zeros();
    // Per invocation, the candidates kept at levels 0 to 4 (scalars, not an array: a GPU would
    // keep an array indexed at run time in local memory).
    const _: () = assert!(MAX_THIN == 4);
    // Five words an invocation where the walk reads none: the scan's and the masks' words, the
    // half of the neighbours' scan that does not hold its result, and the last.
    let (a, b, c, e) = (SCAN, SCAN + THREADS as usize, MASKS, 6 * THREADS as usize);
    let d = if nb == NB_SCAN { NB_SCAN + THREADS as usize } else { NB_SCAN };
    g.each(|lid| {
        let (mut k0, mut k1, mut k2, mut k3, mut k4) = (0u32, 0u32, 0u32, 0u32, 0u32);
        let (mut bits, mut chunk) = (0u32, 0u32);
        let mut first = lid * per;
        while first < total {
            let mut mask = 0u32;
            visit_reaching(p, sh, nb, &dense, &offsets, total, first, per, tx, ty, |i, r, cx, cy| {
                mask |= 1 << i;
                k0 += 1;
                k1 += thin_keeps(p, 1, cx, cy, r) as u32;
                k2 += thin_keeps(p, 2, cx, cy, r) as u32;
                k3 += thin_keeps(p, 3, cx, cy, r) as u32;
                k4 += thin_keeps(p, 4, cx, cy, r) as u32;
            });
            if chunk < cached_chunks {
                bits |= mask << (chunk * per);
            }
            first += THREADS * per;
            chunk += 1;
        }
        cache.store(t * THREADS + lid, bits);
        let i = lid as usize;
        (sh[a + i], sh[b + i], sh[c + i], sh[d + i], sh[e + i]) = (k0, k1, k2, k3, k4);
    });
    let (n0, n1, n2) = (reduce(g, sh, a, Add), reduce(g, sh, b, Add), reduce(g, sh, c, Add));
    let (n3, n4) = (reduce(g, sh, d, Add), reduce(g, sh, e, Add));
    g.each(|lid| {
        if lid == 0 {
            let at = t * LEVELS;
            thin_counts.store(at, n0);
            thin_counts.store(at + 1, n1);
            thin_counts.store(at + 2, n2);
            thin_counts.store(at + 3, n3);
            thin_counts.store(at + 4, n4);
        }
    });
}

/// The level and length of tile `t`'s list under a cap of `cap` entries: the first level whose
/// list is at most `cap`, or else the deepest, if it fits the sort (`None` if it does not).
#[inline]
fn level_under(p: &SplatParams, thin_counts: &impl Load, t: u32, cap: u32) -> Option<(u32, u32)> {
    let mut level = 0;
    while level < MAX_THIN && thin_counts.load(t * LEVELS + level) > cap {
        level += 1;
    }
    let n = thin_counts.load(t * LEVELS + level);
    if n <= p.max_list { Some((level, n)) } else { None }
}

/// Binning, the plan (one workgroup for the frame): one cap on list length for every tile, the
/// largest (at most the longest list the sort handles) under which the lists fit the pool, each
/// list thinned to the first level within it; then every list's place in the pool, tile by tile
/// (a scan), written to `segments`, and each tile's level to `copy` ([`TILE_THIN_SHIFT`]). The
/// longest lists are thinned first, where the blur is widest. Only a list whose deepest level
/// exceeds the sort, or that the pool cannot hold even so, leaves its tile sharp. Placement does not
/// depend on the order tiles ran in: the same lists on every backend.
pub fn bin_plan_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &SplatParams,
    sh: &mut [u32; 2 * THREADS as usize],
    thin_counts: R,
    mut copy: M,
    mut segments: M,
    mut st: M,
) {
    let tiles = p.tiles_x * p.tiles_y;
    // Each invocation takes a run of consecutive tiles, so that a scan places them in order.
    let run = tiles.div_ceil(THREADS);
    let cap_total = |cap: u32, lid: u32| -> u32 {
        let mut sum = 0u32;
        let mut t = lid * run;
        while t < tiles && t < (lid + 1) * run {
            if copy.load(t) & TILE_COPY == 0
                && let Some((_, n)) = level_under(p, &thin_counts, t, cap)
            {
                sum += n;
            }
            t += 1;
        }
        sum
    };
    // The largest cap whose lists fit the pool: a binary search (the total grows with the cap).
    let (mut lo, mut hi) = (0u32, p.max_list);
    g.each(|lid| sh[lid as usize] = cap_total(hi, lid));
    if reduce(g, sh, 0, Add) <= p.list_capacity {
        lo = hi;
    }
    while lo < hi {
        let mid = lo + (hi - lo).div_ceil(2);
        g.each(|lid| sh[lid as usize] = cap_total(mid, lid));
        if reduce(g, sh, 0, Add) <= p.list_capacity {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    let cap = lo;
    g.each(|lid| sh[lid as usize] = cap_total(cap, lid));
    let sums = inclusive_scan(g, sh, 0, Add);
    g.each(|lid| {
        let mut at = if lid == 0 { 0 } else { sh[sums + lid as usize - 1] };
        let (mut thinned, mut left_out, mut sharp, mut sharp_entries, mut longest) = (0u32, 0u32, 0u32, 0u32, 0u32);
        let mut t = lid * run;
        while t < tiles && t < (lid + 1) * run {
            let whole = thin_counts.load(t * LEVELS);
            longest = if whole > longest { whole } else { longest };
            let placed = if copy.load(t) & TILE_COPY != 0 { None } else { level_under(p, &thin_counts, t, cap) };
            // The scan's total is at most the pool; a tile past it (a cap of 0 still too much) is
            // left out, in tile order.
            let placed = placed.filter(|&(_, n)| n <= p.list_capacity - at.min(p.list_capacity));
            match placed {
                Some((level, n)) => {
                    segments.store(2 * t, at);
                    segments.store(2 * t + 1, n);
                    copy.store(t, level << TILE_THIN_SHIFT);
                    if level > 0 {
                        thinned += 1;
                        left_out += whole - n;
                    }
                    at += n;
                }
                None => {
                    segments.store(2 * t, 0);
                    segments.store(2 * t + 1, 0);
                    if whole > 0 {
                        copy.store(t, TILE_COPY);
                        sharp += 1;
                        sharp_entries += whole;
                    }
                }
            }
            t += 1;
        }
        if thinned > 0 {
            st.atomic_add(stats::THINNED_TILES, thinned);
            st.atomic_add(stats::THINNED_ENTRIES, left_out);
        }
        if sharp > 0 {
            st.atomic_add(stats::OVERFLOW_TILES, sharp);
            st.atomic_add(stats::OVERFLOW_ENTRIES, sharp_entries);
        }
        if longest > 0 {
            st.atomic_max(stats::MAX_CAPACITY, longest);
        }
        if lid == THREADS - 1 {
            st.atomic_add(stats::LIST_TOP, sh[sums + lid as usize]);
        }
    });
}

/// Binning, second pass (one workgroup per tile): the tile's list at the level and place the plan
/// gave it, in candidate order (the same on every backend), from the count's cached test results
/// where it kept them (a thinned list tests its candidates again). Each step places the
/// invocations' kept candidates through a workgroup scan.
#[allow(clippy::too_many_arguments)]
pub fn bin_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &SplatParams,
    sh: &mut [u32; BIN_SHARED],
    dense: R,
    tile_count: R,
    offsets: R,
    tile_radius: R,
    copy: R,
    segments: R,
    cache: R,
    mut keys: M,
    mut values: M,
    st: R,
) {
    let p = &planned(p, &st);
    let [tx, ty, _] = g.workgroup_id();
    let t = ty * p.tiles_x + tx;
    let (state, out, len) = (copy.load(t), segments.load(2 * t), segments.load(2 * t + 1));
    if state & TILE_COPY != 0 || len == 0 {
        return;
    }
    let thin = state >> TILE_THIN_SHIFT;
    let (nb, total) = candidate_space(g, p, sh, &tile_count, &tile_radius, false, tx, ty);
    let per = candidates_per_thread(p);
    let cached_chunks = CACHED_CANDIDATES >> per.trailing_zeros();
    let t_usize = THREADS as usize;
    let mut running = 0u32;
    let mut start = 0;
    let mut chunk = 0;
    while start < total {
        g.each(|lid| {
            let first = start + lid * per;
            let mask = if chunk < cached_chunks && thin == 0 {
                (cache.load(t * THREADS + lid) >> (chunk * per)) & (u32::MAX >> (32 - per))
            } else {
                let mut mask = 0u32;
                visit_reaching(p, sh, nb, &dense, &offsets, total, first, per, tx, ty, |i, r, cx, cy| {
                    if thin_keeps(p, thin, cx, cy, r) {
                        mask |= 1 << i;
                    }
                });
                mask
            };
            sh[SCAN + lid as usize] = mask.count_ones();
            sh[MASKS + lid as usize] = mask;
        });
        let sums = inclusive_scan(g, sh, SCAN, Add);
        let mut chunk_total = 0;
        g.each(|lid| {
            let mut at = out + running + if lid == 0 { 0 } else { sh[sums + lid as usize - 1] };
            let mask = sh[MASKS + lid as usize];
            let first = start + lid * per;
            let mut cursor = Cursor::at(if mask != 0 { neighbour(sh, nb, first) } else { 0 }, tx, ty);
            let mut i = 0;
            while i < per {
                if mask & (1 << i) != 0 {
                    let j = cursor.candidate(p, sh, nb, NB_TILE, &offsets, first + i);
                    keys.store(at, dense.load(4 * j + 2));
                    values.store(at, j);
                    at += 1;
                }
                i += 1;
            }
            // The same value in every invocation (read before the barrier ends the step).
            chunk_total = sh[sums + t_usize - 1];
        });
        running += chunk_total;
        start += THREADS * per;
        chunk += 1;
    }
}

/// Calls `f(i, radius, cell_x, cell_y)` for each of the `per` candidates from `first` (of `total`)
/// whose disc reaches a pixel centre of tile `(tx, ty)`: `i` its place after `first`, the cell its
/// column and row in the frame's cell grid.
#[allow(clippy::too_many_arguments)]
#[inline]
fn visit_reaching<const N: usize>(
    p: &SplatParams,
    sh: &[u32; N],
    nb: usize,
    dense: &impl Load,
    offsets: &impl Load,
    total: u32,
    first: u32,
    per: u32,
    tx: u32,
    ty: u32,
    mut f: impl FnMut(u32, f32, u32, u32),
) {
    let mut cursor = Cursor::at(neighbour(sh, nb, first), tx, ty);
    let mut i = 0;
    while i < per && first + i < total {
        let at = cursor.candidate(p, sh, nb, NB_TILE, offsets, first + i);
        if cursor.reaches {
            let frag = Fragment::load_in(p, dense, at);
            let r = frag.radius(&p.lens, p.max_radius);
            if disc_reaches(p, frag.centre(), r, tx, ty) {
                f(i, r, cursor.x0 + cursor.x, cursor.y0 + cursor.y);
            }
            i += 1;
        } else {
            // None of the cell's fragments reaches the tile: none is read, and the walk goes on
            // from the next cell's first.
            i = cursor.cell_end(sh, nb) - first;
        }
    }
}

/// The neighbour whose range of the inclusive scan at `sh[nb..]` holds candidate `j` (binary
/// search).
#[inline]
fn neighbour<const N: usize>(sh: &[u32; N], nb: usize, j: u32) -> usize {
    let (mut lo, mut hi) = (0usize, THREADS as usize - 1);
    while lo < hi {
        let mid = (lo + hi) / 2;
        if sh[nb + mid] > j { hi = mid } else { lo = mid + 1 }
    }
    lo
}

/// Where an invocation's consecutive candidates lie, as the last one was found: the neighbour (its
/// index in the scan), and the cell in that neighbour's tile. The next candidate steps on from
/// there, so one binary search over the neighbours ([`neighbour`]) and one over a tile's cells
/// serve all of them. Cells are tracked by their column and row in the tile, so that no step
/// divides.
#[derive(Clone, Copy)]
struct Cursor {
    nb: usize,
    /// The neighbour the fields below belong to (`usize::MAX`: none yet).
    cells_of: usize,
    /// The neighbour tile `tile`'s cells inside the grid: `w × h` of them from cell `first`, at
    /// `(x0, y0)` in the cell grid.
    tile: u32,
    first: u32,
    x0: u32,
    y0: u32,
    w: u32,
    h: u32,
    /// The current cell, its offset in the tile, and the next cell's (`u32::MAX` after the last).
    x: u32,
    y: u32,
    offset: u32,
    next: u32,
    /// The tile the candidates are for, and whether the current cell's widest fragment, anywhere
    /// in the cell, reaches it (if not, none of the cell's fragments does).
    tx: u32,
    ty: u32,
    reaches: bool,
}

impl Cursor {
    #[inline]
    fn at(nb: usize, tx: u32, ty: u32) -> Self {
        Cursor {
            nb,
            cells_of: usize::MAX,
            tile: 0,
            first: 0,
            x0: 0,
            y0: 0,
            w: 0,
            h: 0,
            x: 0,
            y: 0,
            offset: 0,
            next: 0,
            tx,
            ty,
            reaches: false,
        }
    }

    /// The frame's index of the tile's cell `(x, y)`.
    #[inline]
    fn cell(&self, p: &SplatParams, x: u32, y: u32) -> u32 {
        self.first + y * p.cells_x + x
    }

    /// The offset in its tile of the tile's cell `(x, y)`, `u32::MAX` past the last.
    #[inline]
    fn offset_of(&self, p: &SplatParams, offsets: &impl Load, x: u32, y: u32) -> u32 {
        if y < self.h { offsets.load(self.cell(p, x, y)) } else { u32::MAX }
    }

    /// Moves to cell `(x, y)` of the tile.
    #[inline(always)]
    fn go(&mut self, p: &SplatParams, offsets: &impl Load, x: u32, y: u32) {
        (self.x, self.y) = (x, y);
        self.offset = self.offset_of(p, offsets, x, y);
        self.next = if x + 1 < self.w { self.offset_of(p, offsets, x + 1, y) } else { self.offset_of(p, offsets, 0, y + 1) };
        let r = f32::from_bits(offsets.load(p.cells_x * p.cells_y + self.cell(p, x, y)));
        let (cx, cy) = (span(self.x0 + x, p.cell, p.width), span(self.y0 + y, p.cell, p.height));
        self.reaches = block_reaches(p, cx, cy, self.tx, self.ty, r);
    }

    /// The candidate after the current cell's last (its neighbour tile's first fragment is
    /// candidate `sh[nb + self.nb - 1]`, the one after its last `sh[nb + self.nb]`).
    #[inline(always)]
    fn cell_end<const N: usize>(&self, sh: &[u32; N], nb: usize) -> u32 {
        let base = if self.nb == 0 { 0 } else { sh[nb + self.nb - 1] };
        let end = sh[nb + self.nb];
        if self.next < end - base { base + self.next } else { end }
    }

    /// The dense index of candidate `j` (at or after the last one asked for): the `o`-th fragment
    /// of its neighbour tile lies in the last cell whose offset in the tile is at most `o`.
    #[inline(always)]
    fn candidate<const N: usize>(&mut self, p: &SplatParams, sh: &[u32; N], nb: usize, nb_tile: usize, offsets: &impl Load, j: u32) -> u32 {
        while self.nb < THREADS as usize - 1 && sh[nb + self.nb] <= j {
            self.nb += 1;
        }
        let o = j - if self.nb == 0 { 0 } else { sh[nb + self.nb - 1] };
        if self.cells_of != self.nb {
            let ct = p.cells_per_tile_edge();
            let s = sh[nb_tile + self.nb];
            let (x0, y0) = ((s % p.tiles_x) * ct, (s / p.tiles_x) * ct);
            self.cells_of = self.nb;
            self.tile = s;
            self.first = y0 * p.cells_x + x0;
            (self.x0, self.y0) = (x0, y0);
            self.w = if p.cells_x - x0 < ct { p.cells_x - x0 } else { ct };
            self.h = if p.cells_y - y0 < ct { p.cells_y - y0 } else { ct };
            // The cell is in the last row whose first cell's offset is at most `o` (the first
            // row's is 0), at the last column of that row whose offset is.
            let (mut lo, mut hi) = (0, self.h - 1);
            while lo < hi {
                let mid = (lo + hi).div_ceil(2);
                if self.offset_of(p, offsets, 0, mid) <= o { lo = mid } else { hi = mid - 1 }
            }
            let y = lo;
            let (mut lo, mut hi) = (0, self.w - 1);
            while lo < hi {
                let mid = (lo + hi).div_ceil(2);
                if self.offset_of(p, offsets, mid, y) <= o { lo = mid } else { hi = mid - 1 }
            }
            self.go(p, offsets, lo, y);
        }
        while self.next <= o {
            let (x, y) = if self.x + 1 < self.w { (self.x + 1, self.y) } else { (0, self.y + 1) };
            self.go(p, offsets, x, y);
        }
        p.region_in_tile(self.tile, self.x, self.y) + (o - self.offset)
    }
}

kernel!(
    /// Per-tile fragment counts, cell offsets inside tiles and largest radius.
    TILE_COUNT = splat_tile_count [256] (SplatParams) shared [u32; 6 * 256]
        { read cells, tile_count, offsets, tile_radius, st } => tile_count_pass
);
kernel!(
    /// Which tiles no list fragment reaches (copied through).
    ALLOC = splat_alloc [256] (SplatParams) { read tile_count, read tile_radius, copy, st } => alloc_pass
);
kernel!(
    /// Each tile's list length at every thinning level, and the count's cached test results.
    BIN_COUNT = splat_bin_count [256 subgroups] (SplatParams) shared [u32; 7 * 256]
        { read dense, read tile_count, read offsets, read tile_radius, read copy, thin_counts, cache, read st } => bin_count_pass
);
kernel!(
    /// One workgroup: each tile's thinning level and place in the list pool.
    BIN_PLAN = splat_bin_plan [256 subgroups] (SplatParams) shared [u32; 2 * 256]
        { read thin_counts, copy, segments, st } => bin_plan_pass
);
kernel!(
    /// The tile lists: depth keys and dense fragment indices.
    BIN = splat_bin [256 subgroups] (SplatParams) shared [u32; 7 * 256]
        { read dense, read tile_count, read offsets, read tile_radius, read copy, read segments, read cache, keys, values, read st }
        => bin_pass
);
