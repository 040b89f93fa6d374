//! Workgroup-level building blocks the kernels share: scans over one word per invocation in
//! workgroup memory, and the grid-stride loop over items.

use crate::exec::Group;

/// Inclusive scan under `op` of `sh[base .. base + n]`, `n` the workgroup size (one word per
/// invocation, written before the call), ping-ponging with `sh[base + n .. base + 2n]`. Returns the
/// offset of the half that holds the result. Hillis-Steele: log2(n) barriers.
pub fn inclusive_scan<G: Group, const N: usize>(g: &mut G, sh: &mut [u32; N], base: usize, op: impl Fn(u32, u32) -> u32) -> usize {
    let threads = g.size();
    let t = threads as usize;
    let mut src = base;
    let mut d = 1u32;
    while d < threads {
        g.each(|lid| {
            let dst = if src == base { base + t } else { base };
            let own = sh[src + lid as usize];
            sh[dst + lid as usize] = if lid >= d { op(sh[src + (lid - d) as usize], own) } else { own };
        });
        src = if src == base { base + t } else { base };
        d *= 2;
    }
    src
}

/// Two inclusive scans side by side, `op_a` over `sh[a .. a + n]` and `op_b` over `sh[b .. b + n]`
/// (`n` the workgroup size, one word per invocation each), both restarting wherever the segment id
/// at `sh[segs + i]` changes (ids non-decreasing in `i`): the scans of several short runs at once,
/// one run per segment. Each ping-pongs with the `n` words after it; returns the offsets of the
/// halves that hold the results. Hillis-Steele: log2(n) barriers for both.
pub fn segmented_scans<G: Group, const N: usize>(
    g: &mut G,
    sh: &mut [u32; N],
    (a, b, segs): (usize, usize, usize),
    op_a: impl Fn(u32, u32) -> u32,
    op_b: impl Fn(u32, u32) -> u32,
) -> (usize, usize) {
    let threads = g.size();
    let t = threads as usize;
    let mut flip = false;
    let mut d = 1u32;
    while d < threads {
        g.each(|lid| {
            let (src_a, src_b) = if flip { (a + t, b + t) } else { (a, b) };
            let (dst_a, dst_b) = if flip { (a, b) } else { (a + t, b + t) };
            let i = lid as usize;
            let (own_a, own_b) = (sh[src_a + i], sh[src_b + i]);
            let same = lid >= d && sh[segs + (lid - d) as usize] == sh[segs + i];
            sh[dst_a + i] = if same { op_a(sh[src_a + (lid - d) as usize], own_a) } else { own_a };
            sh[dst_b + i] = if same { op_b(sh[src_b + (lid - d) as usize], own_b) } else { own_b };
        });
        flip = !flip;
        d *= 2;
    }
    if flip { (a + t, b + t) } else { (a, b) }
}

/// The reduction under `op` (associative and commutative) of `sh[base .. base + n]`, `n` the
/// workgroup size (a power of two; one word per invocation, written before the call), which it
/// overwrites: a tree, halving the active invocations at each of its log2(n) barriers, so it does
/// `n − 1` operations where [`inclusive_scan`] does `n log2 n`. Every invocation gets the result.
pub fn reduce<G: Group, const N: usize>(g: &mut G, sh: &mut [u32; N], base: usize, op: impl Fn(u32, u32) -> u32) -> u32 {
    let mut half = g.size() / 2;
    while half > 0 {
        g.each(|lid| {
            if lid < half {
                let i = base + lid as usize;
                sh[i] = op(sh[i], sh[i + half as usize]);
            }
        });
        half /= 2;
    }
    // Read in a step of its own, so that no invocation overwrites the word before all have read it.
    let mut total = 0;
    g.each(|_| total = sh[base]);
    total
}

#[inline]
pub fn add(a: u32, b: u32) -> u32 {
    a.wrapping_add(b)
}

#[inline]
pub fn max(a: u32, b: u32) -> u32 {
    if a > b { a } else { b }
}

/// Runs `f(i)` once for every item `i < n` of a one-dimensional dispatch: one item per invocation,
/// the workgroups striding over the rest (so any `n` fits the dispatch limit).
pub fn for_each_item<G: Group>(g: &mut G, n: u32, mut f: impl FnMut(u32)) {
    let size = g.size();
    let stride = g.num_workgroups()[0] * size;
    let mut base = g.workgroup_id()[0] * size;
    while base < n {
        g.each(|lid| {
            if base + lid < n {
                f(base + lid);
            }
        });
        base += stride;
    }
}
