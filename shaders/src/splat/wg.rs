//! Workgroup-wide scans over one word per invocation, in workgroup memory.

use super::THREADS;
use crate::exec::Group;

/// Inclusive scan under `op` of `sh[base .. base + THREADS]` (one word per invocation, written
/// before the call), ping-ponging with `sh[base + THREADS .. base + 2 THREADS]`. Returns the offset
/// of the half that holds the result. Hillis-Steele: log2(THREADS) barriers.
pub fn inclusive_scan<G: Group, const N: usize>(
    g: &mut G,
    sh: &mut [u32; N],
    base: usize,
    op: impl Fn(u32, u32) -> u32,
) -> usize {
    let t = THREADS as usize;
    let mut src = base;
    let mut d = 1u32;
    while d < THREADS {
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

#[inline]
pub fn add(a: u32, b: u32) -> u32 {
    a.wrapping_add(b)
}

#[inline]
pub fn max(a: u32, b: u32) -> u32 {
    if a > b { a } else { b }
}
