//! Depth peeling into the partial multi-layer image on the device (Franke et al. 2018, §4.1-4.3),
//! and the per-pixel rules the host's peel and ray caster share with it.
//!
//! A frame of peeling is a fixed sequence of passes; between them these kernels run:
//! - `peel_plan` (one invocation) before pass `k` and once after the last: writes pass `k`'s
//!   indirect draw and dispatch arguments, all zero when pass `k - 1` found no surface anywhere (so
//!   passes past the last useful one cost almost nothing), notes which passes ran and found a
//!   surface, and clears the found flag;
//! - `peel_append` (one invocation per pixel) after each pass: the pass's shaded layer becomes the
//!   pixel's next slot where [`slot_kept`] says so (the frame API's `FrameInput::Layers` layout,
//!   [`crate::slot`]: colour premultiplied by the layer's alpha, depth, alpha), or is composited
//!   behind a full pixel's translucent last slot ([`target_slot`]); a kept surface sets the found
//!   flag where the pixel can take more ([`takes_more`]);
//! - after the last pass the disocclusion buffer (§4.3, two-pass variant: built from the finished
//!   front layer): `peel_edges` gives every pixel of a depth discontinuity its tag radius
//!   ([`pair_radius`]), `peel_span` and `peel_mask` find the pixels within that radius of an edge
//!   pixel (the disk `dx² + dy² <= r²`, split into a row pass and a column pass: [`disk_budget`],
//!   [`covers`]), and `peel_mask` then keeps outside the buffer the slots up to the first opaque
//!   one ([`slots_outside_buffer`]; the front slot where it is opaque) and resets every unused slot to black at `+inf` with alpha 0;
//! - `peel_band` (one invocation per triangle) and `peel_band_end` (one invocation): the guard band
//!   this frame's view would need (the largest CoC radius of geometry within [`MAX_GUARD_BAND`]
//!   pixels of the frame, [`nearest_in_reach`] and [`margin_of`], the rules of the host's
//!   `scene::guard_band::auto_margin_mesh`), and a count of the frames whose band exceeded the one
//!   the image was made with.

use crate::exec::{Group, Load, Mem};
use crate::lens::{ThinLens, is_finite, is_nan};
use crate::math::ceil;
use crate::raster::project::{triangle, vertex_position};
use crate::slot::{self, Slot};
use crate::wg::for_each_item;

/// Words a slot ([`crate::slot`]): premultiplied red, green, blue, depth, alpha.
pub use crate::slot::SLOT_WORDS;
/// Words of the indirect arguments: the draw command (4), the shading dispatch (3 and a pad), the
/// append dispatch (3 and a pad).
pub const ARGS_WORDS: u32 = 12;
/// Where the shading pass's dispatch arguments start.
pub const SHADE_ARGS: u32 = 4;
/// Where the append's dispatch arguments start.
pub const APPEND_ARGS: u32 = 8;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct PeelParams {
    pub lens: ThinLens,
    /// The peeled image (frame and guard band), pixels.
    pub width: u32,
    pub height: u32,
    /// Slots a pixel.
    pub layers: u32,
    /// The pass `peel_plan` plans (`passes`: the call after the last pass) and `peel_append` appends.
    pub pass: u32,
    /// Relative depth difference between 4-neighbours that counts as a discontinuity.
    pub edge_depth_ratio: f32,
    /// 1: keep more than the front slot only inside the disocclusion buffer.
    pub disocclusion: u32,
    /// A useful pass's draw: vertices (3 per triangle).
    pub draw_vertices: u32,
    /// A useful pass's shading and append workgroups.
    pub shade_groups: u32,
    pub append_groups: u32,
    /// Passes a frame (at least `layers`): those past `layers` composite a translucent stack deeper
    /// than the slots into the last slot ([`target_slot`]).
    pub passes: u32,
    pub _pad: [u32; 2],
}

const _: () = assert!(core::mem::size_of::<PeelParams>() <= 128);

/// Widest guard band, pixels: 6 tile rings of 16 pixels, the largest CoC radius the splatting
/// methods honour with their default tiles (larger radii are capped there anyway).
pub const MAX_GUARD_BAND: u32 = 96;

/// What the band kernels take: the view within [`MAX_GUARD_BAND`] pixels of the frame from the
/// near plane on, as five inward planes `(n, d)` (`n·p >= d` inside), the eye and view axis, the
/// lens and the band the image has.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct BandParams {
    pub planes: [[f32; 4]; 5],
    pub eye: [f32; 3],
    pub triangles: u32,
    pub forward: [f32; 3],
    /// The guard band the peeled image has, pixels.
    pub margin: u32,
    pub lens: ThinLens,
}

const _: () = assert!(core::mem::size_of::<BandParams>() <= 128);

#[inline]
fn dot3(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Most corners a quadrilateral clipped by five planes has.
const CLIP_CORNERS: usize = 9;

/// Nearest planar depth (along `forward` from `eye`) of the convex polygon of the first `corners`
/// (3 or 4) points of `poly` inside the five `planes`, by clipping it against each (Sutherland and
/// Hodgman 1974); `+inf` where nothing is left.
pub fn nearest_in_reach(planes: &[[f32; 4]; 5], poly: [[f32; 3]; 4], corners: usize, eye: [f32; 3], forward: [f32; 3]) -> f32 {
    let mut cur = [[0.0f32; 3]; CLIP_CORNERS];
    cur[0] = poly[0];
    cur[1] = poly[1];
    cur[2] = poly[2];
    cur[3] = poly[3];
    let mut n = if corners < 4 { corners } else { 4 };
    let mut k = 0;
    while k < 5 {
        let pl = planes[k];
        let normal = [pl[0], pl[1], pl[2]];
        let mut next = [[0.0f32; 3]; CLIP_CORNERS];
        let mut m = 0usize;
        let mut i = 0;
        while i < n {
            let a = cur[i];
            let b = cur[if i + 1 == n { 0 } else { i + 1 }];
            let (da, db) = (dot3(normal, a) - pl[3], dot3(normal, b) - pl[3]);
            if da >= 0.0 && m < CLIP_CORNERS {
                next[m] = a;
                m += 1;
            }
            if (da >= 0.0) != (db >= 0.0) && m < CLIP_CORNERS {
                let t = da / (da - db);
                next[m] = [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t];
                m += 1;
            }
            i += 1;
        }
        cur = next;
        n = m;
        if n == 0 {
            return f32::INFINITY;
        }
        k += 1;
    }
    let mut best = f32::INFINITY;
    let mut i = 0;
    while i < n {
        let p = cur[i];
        let z = dot3([p[0] - eye[0], p[1] - eye[1], p[2] - eye[2]], forward);
        if z < best {
            best = z;
        }
        i += 1;
    }
    best
}

/// The guard band (pixels) for the largest CoC radius `radius` reaching into the frame: rounded
/// up, at most [`MAX_GUARD_BAND`] (also for NaN).
#[inline]
pub fn margin_of(radius: f32) -> u32 {
    if is_nan(radius) {
        return MAX_GUARD_BAND;
    }
    let r = ceil(if radius > 0.0 { radius } else { 0.0 });
    if r >= MAX_GUARD_BAND as f32 { MAX_GUARD_BAND } else { r as u32 }
}

/// Whether a pixel of a shaded peel layer (coverage `alpha`, depth `depth`) becomes a slot: a
/// surface, or the background where this pass saw the pixel's ray escape (coverage 1 at infinite
/// depth; coverage 0 there means the pixel ended in an earlier pass).
#[inline]
pub fn slot_kept(alpha: f32, depth: f32) -> bool {
    is_surface(depth) || alpha > 0.0
}

/// The slot a pass's fragment goes to in a pixel with `n` of its `layers` slots used, the last of
/// coverage `last_alpha`: the next slot while there is one; once they are full, the last one, which
/// takes the fragment behind it ([`behind`]) for as long as it still lets light through; else none
/// (`layers`). So a translucent stack deeper than the slots keeps its light and what it lets
/// through, as the ray caster keeps it.
#[inline]
pub fn target_slot(n: u32, layers: u32, last_alpha: f32) -> u32 {
    if n < layers {
        n
    } else if n > 0 && !is_opaque(last_alpha) {
        n - 1
    } else {
        layers
    }
}

/// Whether a pixel whose slot `target` (of `layers`) just took a surface, leaving it of coverage
/// `alpha`, can take more from a later pass: a slot is free, or the last one still lets light
/// through. A pass after which no pixel can is not drawn, so an opaque scene draws no translucent
/// pass.
#[inline]
pub fn takes_more(target: u32, layers: u32, alpha: f32) -> bool {
    target + 1 < layers || !is_opaque(alpha)
}

/// A full pixel's translucent last slot with `fragment` (premultiplied, lying behind it)
/// composited "over": the slot keeps its depth, and becomes exactly opaque with an opaque fragment
/// (so nothing more is composited into it).
#[inline]
pub fn behind(last: Slot, fragment: Slot) -> Slot {
    let mut s = slot::over(last, fragment);
    if is_opaque(fragment.alpha) {
        s.alpha = 1.0;
    }
    s
}

/// The reach the next pass tests against behind a pixel of a shaded layer (Franke et al. 2018,
/// §4.1): behind an opaque surface its umbra (`ThinLens::umbra_length` of the pixel's footprint,
/// `depth · footprint_per_depth`; infinite once the footprint covers the aperture), behind a
/// partly covering one nothing more than its depth, and infinity where nothing was found.
#[inline]
pub fn next_reach(found: bool, alpha: f32, depth: f32, lens: &ThinLens, footprint_per_depth: f32) -> f32 {
    if !found {
        f32::INFINITY
    } else if alpha < 1.0 {
        depth
    } else {
        let r = depth + lens.umbra_length(depth, depth * footprint_per_depth);
        if is_finite(r) { r } else { f32::INFINITY }
    }
}

/// Whether a fragment of coverage `alpha` hides everything behind it (a translucent one, below 1,
/// lets the rest through; NaN counts as translucent).
#[inline]
pub fn is_opaque(alpha: f32) -> bool {
    alpha >= 1.0
}

/// How many of a pixel's `count` fragments (front to back, coverage `alpha(i)` of the `i`-th) it
/// keeps outside the disocclusion buffer: up to and including the first opaque one. An opaque front
/// fragment is all the pixel shows in focus (Franke et al. 2018, §4.2); behind a translucent one
/// the next fragments still show, and are kept until one hides the rest.
#[inline]
pub fn slots_outside_buffer(count: u32, alpha: impl Fn(u32) -> f32) -> u32 {
    let mut i = 0;
    while i < count {
        if is_opaque(alpha(i)) {
            return i + 1;
        }
        i += 1;
    }
    count
}

/// Whether a pass that found nothing at a pixel whose reach was `reach` sees the background there:
/// only the first such pass (the reach is still finite), later ones see nothing.
#[inline]
pub fn background_seen(reach: f32) -> bool {
    is_finite(reach)
}

/// Whether a layer's depth is a surface (finite), not the background.
#[inline]
pub fn is_surface(depth: f32) -> bool {
    is_finite(depth)
}

/// Whether two front-layer depths form a discontinuity: exactly one is the background, or
/// `|a − b| > ratio · min(a, b)`.
#[inline]
pub fn discontinuous(a: f32, b: f32, ratio: f32) -> bool {
    match (is_finite(a), is_finite(b)) {
        (false, false) => false,
        (true, true) => {
            let d = a - b;
            let d = if d < 0.0 { -d } else { d };
            d > ratio * if a < b { a } else { b }
        }
        _ => true,
    }
}

/// The tag radius (pixels) of the discontinuity between front depths `a` and `b`: `ceil(c / 2)` for
/// the larger CoC `c` of the two (NaN ignored, as `f32::max` does), clamped to `0..=limit`
/// (`limit` where both CoCs are NaN or the radius is not finite); -1 where they are no
/// discontinuity.
#[inline]
pub fn pair_radius(lens: &ThinLens, a: f32, b: f32, ratio: f32, limit: i32) -> i32 {
    if !discontinuous(a, b, ratio) {
        return -1;
    }
    let (ca, cb) = (lens.coc_px(a), lens.coc_px(b));
    let c = if is_nan(ca) {
        cb
    } else if is_nan(cb) || ca > cb {
        ca
    } else {
        cb
    };
    let h = ceil(c * 0.5);
    if !is_finite(h) || !(h < limit as f32) {
        limit
    } else if h < 0.0 {
        0
    } else {
        h as i32
    }
}

/// What is left of the disk of radius `r` along a column `dx` pixels from its centre: `r² − dx²`
/// (negative: the column misses it).
#[inline]
pub fn disk_budget(dx: i32, r: i32) -> i32 {
    r * r - dx * dx
}

/// Whether a pixel `dy` rows from the centre lies in the disk, given that column's budget.
#[inline]
pub fn covers(budget: i32, dy: i32) -> bool {
    budget >= dy * dy
}

/// The front slot's depth of pixel `p`, `+inf` where it has none.
#[inline]
fn front(fragments: &impl Load, counts: &impl Load, p: u32, layers: u32) -> f32 {
    if counts.load(p) > 0 { slot::depth_of(fragments, p * layers) } else { f32::INFINITY }
}

pub fn plan_pass<G: Group, M: Mem>(g: &mut G, p: &PeelParams, mut found: M, mut args: M, mut passes: M) {
    for_each_item(g, 1, |_| {
        let f = found.load(0);
        if p.pass > 0 {
            passes.store(p.passes + p.pass - 1, f);
        }
        if p.pass < p.passes {
            let go = f != 0;
            let pick = |v: u32| if go { v } else { 0 };
            let words = [pick(p.draw_vertices), 1, 0, 0, pick(p.shade_groups), 1, 1, 0, pick(p.append_groups), 1, 1, 0];
            let mut i = 0;
            while i < ARGS_WORDS as usize {
                args.store(i as u32, words[i]);
                i += 1;
            }
            passes.store(p.pass, go as u32);
        }
        found.store(0, 0);
    });
}

pub fn append_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &PeelParams, layer: R, mut fragments: M, mut counts: M, mut found: M) {
    for_each_item(g, p.width * p.height, |i| {
        // The layer's words: r, g, b, alpha, depth (the shading pass's LAYER mode).
        let o = 5 * i;
        let (alpha, depth) = (f32::from_bits(layer.load(o + 3)), f32::from_bits(layer.load(o + 4)));
        if !slot_kept(alpha, depth) {
            return;
        }
        let n = counts.load(i);
        // The last slot's coverage matters only once the slots are full.
        let last = if n >= p.layers && n > 0 { slot::alpha_of(&fragments, i * p.layers + n - 1) } else { 0.0 };
        let target = target_slot(n, p.layers, last);
        if target == p.layers {
            return;
        }
        // The shaded layer's colour is straight; the slot's is premultiplied (an opaque layer's
        // bits unchanged: c · 1 = c).
        let rgb = [f32::from_bits(layer.load(o)), f32::from_bits(layer.load(o + 1)), f32::from_bits(layer.load(o + 2))];
        let fragment = Slot { color: slot::premultiply(rgb, alpha), depth, alpha };
        let at = i * p.layers + target;
        let kept = if target == n {
            counts.store(i, n + 1);
            fragment
        } else {
            behind(slot::load(&fragments, at), fragment)
        };
        slot::store(&mut fragments, at, kept);
        if is_surface(depth) && takes_more(target, p.layers, kept.alpha) && found.load(0) == 0 {
            found.atomic_max(0, 1);
        }
    });
}

pub fn edges_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &PeelParams, fragments: R, counts: R, mut edge: M, mut widest: M) {
    let (w, h) = (p.width, p.height);
    let limit = (if w > h { w } else { h }) as i32;
    for_each_item(g, w * h, |i| {
        let (x, y) = (i % w, i / w);
        let a = front(&fragments, &counts, i, p.layers);
        let r = |q: u32, first: bool| {
            let b = front(&fragments, &counts, q, p.layers);
            // Ordered as the host's pass over pairs (left or upper pixel first).
            if first {
                pair_radius(&p.lens, a, b, p.edge_depth_ratio, limit)
            } else {
                pair_radius(&p.lens, b, a, p.edge_depth_ratio, limit)
            }
        };
        let mut best = -1;
        if x + 1 < w {
            best = best.max(r(i + 1, true));
        }
        if x > 0 {
            best = best.max(r(i - 1, false));
        }
        if y + 1 < h {
            best = best.max(r(i + w, true));
        }
        if y > 0 {
            best = best.max(r(i - w, false));
        }
        // Stored as radius + 1 (0: no edge).
        let e = (best + 1) as u32;
        edge.store(i, e);
        if e > 0 {
            widest.atomic_max(0, e);
        }
    });
}

pub fn span_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &PeelParams, edge: R, widest: R, mut span: M) {
    let (w, h) = (p.width, p.height);
    let reach = widest.load(0) as i32 - 1;
    for_each_item(g, w * h, |i| {
        let (x, y) = ((i % w) as i32, i / w);
        let lo = if x - reach > 0 { x - reach } else { 0 };
        let hi = if x + reach < w as i32 - 1 { x + reach } else { w as i32 - 1 };
        let mut best = -1;
        let mut ex = lo;
        while ex <= hi {
            let e = edge.load(y * w + ex as u32);
            if e > 0 {
                best = best.max(disk_budget(ex - x, e as i32 - 1));
            }
            ex += 1;
        }
        // Stored as budget + 1 (0: no disk reaches this column of the row).
        span.store(i, (best + 1) as u32);
    });
}

pub fn mask_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &PeelParams, span: R, widest: R, mut mask: M, mut fragments: M, mut counts: M) {
    let (w, h) = (p.width, p.height);
    let reach = widest.load(0) as i32 - 1;
    for_each_item(g, w * h, |i| {
        let (x, y) = (i % w, (i / w) as i32);
        let lo = if y - reach > 0 { y - reach } else { 0 };
        let hi = if y + reach < h as i32 - 1 { y + reach } else { h as i32 - 1 };
        let mut tagged = false;
        let mut ey = lo;
        while ey <= hi && !tagged {
            let s = span.load(ey as u32 * w + x);
            tagged = s > 0 && covers(s as i32 - 1, ey - y);
            ey += 1;
        }
        mask.store(i, tagged as u32);
        let mut n = counts.load(i);
        if p.disocclusion != 0 && !tagged && n > 1 {
            // Outside the buffer: the slots up to the first opaque one (what a translucent front
            // slot does not hide is seen in focus too).
            let kept = slots_outside_buffer(n, |k| slot::load(&fragments, i * p.layers + k).alpha);
            if kept < n {
                n = kept;
                counts.store(i, n);
            }
        }
        while n < p.layers {
            slot::store(&mut fragments, i * p.layers + n, Slot { color: [0.0; 3], depth: f32::INFINITY, alpha: 0.0 });
            n += 1;
        }
    });
}

pub fn band_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &BandParams, vertices: R, triangles: R, mut band: M) {
    for_each_item(g, p.triangles, |t| {
        let tri = triangle(&triangles, t);
        let a = vertex_position(&vertices, tri[0]);
        let corners = [a, vertex_position(&vertices, tri[1]), vertex_position(&vertices, tri[2]), a];
        let z = nearest_in_reach(&p.planes, corners, 3, p.eye, p.forward);
        if is_finite(z) {
            let r = p.lens.coc_radius_px(z);
            // Non-negative floats order as their bits.
            if r > 0.0 {
                band.atomic_max(0, r.to_bits());
            }
        }
    });
}

pub fn band_end_pass<G: Group, M: Mem>(g: &mut G, p: &BandParams, mut band: M) {
    for_each_item(g, 1, |_| {
        let geometry = f32::from_bits(band.load(0));
        let background = p.lens.coc_radius_px(f32::INFINITY);
        let needed = margin_of(if geometry > background { geometry } else { background });
        band.store(1, needed);
        if needed > p.margin {
            band.store(2, band.load(2) + 1);
        }
        band.store(0, 0);
    });
}

kernel!(
    /// Plans the next peel pass from the last one's found flag (indirect arguments).
    PEEL_PLAN = peel_plan [64] (PeelParams) { found, args, passes } => plan_pass
);
kernel!(
    /// Appends a shaded peel layer into the slots.
    PEEL_APPEND = peel_append [256] (PeelParams) { read layer, fragments, counts, found } => append_pass
);
kernel!(
    /// The disocclusion buffer's edge pixels and their tag radii.
    PEEL_EDGES = peel_edges [256] (PeelParams) { read fragments, read counts, edge, widest } => edges_pass
);
kernel!(
    /// The disocclusion buffer's row pass: per pixel, the widest disk budget of its row's edges.
    PEEL_SPAN = peel_span [256] (PeelParams) { read edge, read widest, span } => span_pass
);
kernel!(
    /// The disocclusion buffer's column pass, applied to the slots.
    PEEL_MASK = peel_mask [256] (PeelParams) { read span, read widest, mask, fragments, counts } => mask_pass
);

kernel!(
    /// The largest CoC radius of the triangles within the widest guard band of this view.
    PEEL_BAND = peel_band [64] (BandParams) { read vertices, read triangles, band } => band_pass
);
kernel!(
    /// The band this view needs, and whether it exceeds the image's.
    PEEL_BAND_END = peel_band_end [64] (BandParams) { band } => band_end_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 7] = [&PEEL_PLAN, &PEEL_APPEND, &PEEL_EDGES, &PEEL_SPAN, &PEEL_MASK, &PEEL_BAND, &PEEL_BAND_END];
