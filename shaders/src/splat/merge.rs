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
//! One invocation per output cell (`params.cell` 2 or 4 pixels) walks both levels at once from the
//! input ([`cell_fragments`]): no level's fragments are stored but the last, which
//! [`merge_pass`] writes into the cell's region of the dense array as the walk makes it, with
//! the cell's count and widest radius.

use super::fragment::Fragment;
use super::pack::PixelFragments;
use super::{FLAG_UMBRA_MERGE, SplatParams, stats};
use crate::exec::{Group, Load, Mem};
use crate::footprint;
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
        // Only fragments of equal alpha merge: a translucent one never joins an opaque one. One
        // that covers part of its pixel's sub-samples keeps its footprint, unmerged.
        if q.level != level
            || q.alpha != f[0].alpha
            || !(p.lens.coc_radius_px(q.depth) >= p.merge_min_radius)
            || (q.has_footprint() && q.footprint != footprint::full(p.footprint_side()))
        {
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
    let mut widest_r = lens.coc_radius_px(f[0].depth);
    let mut m = 0;
    while m < 4 {
        color[0] += 0.25 * f[m].color[0];
        color[1] += 0.25 * f[m].color[1];
        color[2] += 0.25 * f[m].color[2];
        let r = lens.coc_radius_px(f[m].depth);
        if r > widest_r {
            widest = m;
            widest_r = r;
        }
        m += 1;
    }
    // The block's centre in half pixels: 2·(o·edge + edge/2).
    Fragment {
        color,
        alpha: f[0].alpha,
        depth: f[widest].depth,
        level: f[0].level + 1,
        pos: [2 * ox * edge + edge, 2 * oy * edge + edge],
        footprint: footprint::WHOLE,
    }
}

/// What a fragment reads as after a stage stored it (packed and unpacked): merging reads its
/// members as stored, so results do not depend on whether a level was kept in memory.
#[inline]
fn as_stored(f: &Fragment) -> Fragment {
    Fragment::unpack(f.pack()).with_footprint(f.footprint)
}

/// Merges and umbra-skipped fragments, summed over the levels of one output cell.
#[derive(Clone, Copy)]
pub struct MergeCounts {
    pub merges: u32,
    pub skipped: u32,
}

/// A 2x2 cell of pixels being merged: each member pixel's cursor over its list fragments
/// ([`PixelFragments`]), and bit `m` of `live` set while member `m` has a head.
#[derive(Clone, Copy)]
struct Quad {
    cx: u32,
    cy: u32,
    walk: [PixelFragments; 4],
    live: u32,
}

impl Quad {
    const EMPTY: Quad = Quad { cx: 0, cy: 0, walk: [PixelFragments::EMPTY; 4], live: 0 };

    /// The 2x2 cell `(cx, cy)`: members `m` at pixel `(2cx + (m & 1), 2cy + (m >> 1))`, those
    /// outside the image empty.
    #[inline]
    fn new(layers: &impl Load, counts: &impl Load, p: &SplatParams, cx: u32, cy: u32) -> Self {
        let mut q = Quad { cx, cy, ..Quad::EMPTY };
        let mut m = 0;
        while m < 4 {
            let (x, y) = (2 * cx + (m & 1), 2 * cy + (m >> 1));
            if x < p.width && y < p.height {
                q.walk[m as usize] = PixelFragments::new(counts, p, y * p.width + x);
                q.advance(layers, p, m as usize);
            }
            m += 1;
        }
        q
    }

    #[inline]
    fn has(&self, m: usize) -> bool {
        self.live & (1 << m) != 0
    }

    #[inline]
    fn is_done(&self) -> bool {
        self.live == 0
    }

    /// Member `m`'s head, as a stage reads it after storing it.
    #[inline]
    fn head(&self, m: usize) -> Fragment {
        as_stored(&self.walk[m].head)
    }

    /// Moves member `m` to its next list fragment.
    #[inline]
    fn advance(&mut self, layers: &impl Load, p: &SplatParams, m: usize) {
        if self.walk[m].advance(layers, p) {
            self.live |= 1 << m;
        } else {
            self.live &= !(1 << m);
        }
    }

    /// The next fragment of this 2x2 cell's merged list (one step of the front-to-back walk over its
    /// four pixels; the cell must not be done).
    fn step(&mut self, layers: &impl Load, p: &SplatParams, c: &mut MergeCounts) -> Fragment {
        let mut f = [Fragment::at_pixel(0, 0, [0.0; 3], 0.0); 4];
        let mut present = 0;
        let mut front = 4usize;
        let mut m = 0usize;
        while m < 4 {
            if self.has(m) {
                f[m] = self.head(m);
                present += 1;
                if front == 4 || f[m].depth < f[front].depth {
                    front = m;
                }
            }
            m += 1;
        }
        if present == 4 && mergeable(&f, 0, p) {
            let out = merged(&f, &p.lens, self.cx, self.cy, 2);
            c.merges += 1;
            // Only an opaque fragment casts an umbra: what lies behind a translucent one shows.
            let umbra = p.flags & FLAG_UMBRA_MERGE != 0 && out.is_opaque();
            let shadow = out.depth + p.lens.umbra_length(out.depth, footprint_radius(&p.lens, out.depth, 2.0));
            let mut m = 0usize;
            while m < 4 {
                self.advance(layers, p, m);
                while umbra && self.has(m) && self.walk[m].head.depth <= shadow {
                    self.advance(layers, p, m);
                    c.skipped += 1;
                }
                m += 1;
            }
            out
        } else {
            self.advance(layers, p, front);
            f[front]
        }
    }
}

/// The merged fragments of output cell `o` (cells of `p.cell` = 2 or 4 pixels), front to back,
/// each handed to `emit` as the stage that stores it gets it; returns the merges and skips.
///
/// No level is stored: the pixels' fragments come from the input ([`PixelFragments`]), a
/// 2x2 cell's merged list is walked step by step ([`Quad`]), and the 4x4 walk keeps only the
/// head of each of its four 2x2 lists. Each level reads its members as stored, so the lists are
/// those of merging level by level through memory, fragment for fragment.
pub fn cell_fragments(layers: &impl Load, counts: &impl Load, p: &SplatParams, o: u32, mut emit: impl FnMut(&Fragment)) -> MergeCounts {
    let mut c = MergeCounts { merges: 0, skipped: 0 };
    let (ox, oy) = (o % p.cells_x, o / p.cells_x);
    if p.cell == 2 {
        let mut q = Quad::new(layers, counts, p, ox, oy);
        while !q.is_done() {
            let f = q.step(layers, p, &mut c);
            emit(&f);
        }
        return c;
    }
    // 4x4: the four 2x2 cells' lists, each with its current head.
    let mut q = [Quad::EMPTY; 4];
    let mut head = [Fragment::at_pixel(0, 0, [0.0; 3], 0.0); 4];
    // Bit m: the 2x2 cell m has a head (bool arrays do not compile to SPIR-V).
    let mut has = 0u32;
    let mut m = 0usize;
    while m < 4 {
        q[m] = Quad::new(layers, counts, p, 2 * ox + (m as u32 & 1), 2 * oy + (m as u32 >> 1));
        if !q[m].is_done() {
            head[m] = as_stored(&q[m].step(layers, p, &mut c));
            has |= 1 << m;
        }
        m += 1;
    }
    loop {
        let mut present = 0;
        let mut front = 4usize;
        let mut m = 0usize;
        while m < 4 {
            if has & (1 << m) != 0 {
                present += 1;
                if front == 4 || head[m].depth < head[front].depth {
                    front = m;
                }
            }
            m += 1;
        }
        if present == 0 {
            break;
        }
        if present == 4 && mergeable(&head, 1, p) {
            let out = merged(&head, &p.lens, ox, oy, 4);
            emit(&out);
            c.merges += 1;
            // Only an opaque fragment casts an umbra: what lies behind a translucent one shows.
            let umbra = p.flags & FLAG_UMBRA_MERGE != 0 && out.is_opaque();
            let shadow = out.depth + p.lens.umbra_length(out.depth, footprint_radius(&p.lens, out.depth, 4.0));
            let mut m = 0usize;
            while m < 4 {
                let mut first = true;
                while has & (1 << m) != 0 && (first || (umbra && head[m].depth <= shadow)) {
                    c.skipped += !first as u32;
                    first = false;
                    has = next_head(&mut q[m], &mut head[m], has, m, layers, p, &mut c);
                }
                m += 1;
            }
        } else {
            emit(&head[front]);
            has = next_head(&mut q[front], &mut head[front], has, front, layers, p, &mut c);
        }
    }
    c
}

/// Moves 2x2 cell `m`'s head on (as the 4x4 step reads it, stored); returns `has` with bit `m`
/// cleared once its list is done.
#[inline]
fn next_head(q: &mut Quad, head: &mut Fragment, has: u32, m: usize, layers: &impl Load, p: &SplatParams, c: &mut MergeCounts) -> u32 {
    if q.is_done() {
        return has & !(1 << m);
    }
    *head = as_stored(&q.step(layers, p, c));
    has
}

/// Per output cell: its merged list, into the cell's region of the dense array
/// ([`SplatParams::cell_region`]); how many fragments it holds, their widest radius and how many
/// were capped, at `cells[o]` and `cells[cells + o]` (f32 bits) as `splat_tile_count` reads them;
/// and the merging statistics.
pub fn merge_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &SplatParams, layers: R, counts: R, mut cells: M, mut dense: M, mut st: M) {
    let p = &super::planned(p, &st);
    let outputs = p.cells_x * p.cells_y;
    for_each_item(g, outputs, |o| {
        let (mut n, mut widest, mut capped) = (0u32, 0.0f32, 0u32);
        let region = p.cell_region(o);
        let c = cell_fragments(&layers, &counts, p, o, |f| {
            f.store_in(p, &mut dense, region + n);
            let (r, cut) = f.support(&p.lens, p.max_radius);
            widest = if r > widest { r } else { widest };
            capped += cut as u32;
            n += 1;
        });
        cells.store(o, n);
        cells.store(outputs + o, widest.to_bits());
        if c.merges > 0 {
            st.atomic_add(stats::MERGED, c.merges);
            st.atomic_add(stats::MERGED_INPUTS, 4 * c.merges);
        }
        if c.skipped > 0 {
            st.atomic_add(stats::UMBRA_SKIPPED, c.skipped);
        }
        if capped > 0 {
            st.atomic_add(stats::CAPPED, capped);
        }
    });
}

kernel!(
    /// Merged cells of `params.cell` pixels (2 or 4): their fragments, counts and widest radii.
    MERGE = splat_merge [256] (SplatParams) { read layers, read counts, cells, dense, st } => merge_pass
);
