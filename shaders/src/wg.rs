//! Workgroup-level building blocks the kernels share: scans and reductions over one word per
//! invocation in workgroup memory (in subgroups where the kernel has them), and the grid-stride
//! loop over items.

pub use crate::exec::{Add, Max, WordOp};
use crate::exec::{Combine, Group};

/// Inclusive scan under `op` of `sh[base .. base + n]`, `n` the workgroup size (one word per
/// invocation, written before the call), using `sh[base + n .. base + 2n]` as well. Returns the
/// offset of the half that holds the result. With subgroups of `s` ([`Group::subgroup_size`]), a
/// scan in each subgroup and a scan of their totals: `2·ceil(log_s n) − 1` barriers (3 for 256
/// invocations in subgroups of 32); without, Hillis-Steele: `log2 n` barriers.
pub fn inclusive_scan<G: Group, O: WordOp, const N: usize>(g: &mut G, sh: &mut [u32; N], base: usize, op: O) -> usize {
    match g.subgroup_size() {
        Some(s) => subgroup_scan(g, sh, base, op, s),
        None => hillis_steele_scan(g, sh, base, op),
    }
}

fn hillis_steele_scan<G: Group, O: WordOp, const N: usize>(g: &mut G, sh: &mut [u32; N], base: usize, op: O) -> usize {
    let threads = g.size();
    let t = threads as usize;
    let mut src = base;
    let mut d = 1u32;
    while d < threads {
        g.each(|lid| {
            let dst = if src == base { base + t } else { base };
            let own = sh[src + lid as usize];
            sh[dst + lid as usize] = if lid >= d { op.apply(sh[src + (lid - d) as usize], own) } else { own };
        });
        src = if src == base { base + t } else { base };
        d *= 2;
    }
    src
}

/// The scan in subgroups of `s`. Level 0 is each subgroup's scan of its `s` words, into the upper
/// half. Level `l + 1` scans the totals of level `l`'s runs of `s` (their last words) the same way,
/// in the lower half (free once level 0 has read it), until a level is a single run. Then, from the
/// top down, each run of a level after the first adds the level above's word before it.
fn subgroup_scan<G: Group, O: WordOp, const N: usize>(g: &mut G, sh: &mut [u32; N], base: usize, op: O, s: u32) -> usize {
    let shift = s.trailing_zeros();
    let out = base + g.size() as usize;
    g.each_combined(op, Combine::Scan, sh, |sh, p| sh[base + p as usize], |sh, p, x| sh[out + p as usize] = x);
    // Up: `below`, `len`: where the level under the next one starts, and its words.
    let (mut below, mut len, mut at, mut levels) = (out, g.size(), base, 0u32);
    while len > s {
        let runs = len >> shift;
        g.each_combined(
            op,
            Combine::Scan,
            sh,
            |sh, p| if p < runs { sh[below + ((p + 1) << shift) as usize - 1] } else { O::IDENTITY },
            |sh, p, x| {
                if p < runs {
                    sh[at + p as usize] = x;
                }
            },
        );
        (below, len, at, levels) = (at, runs, at + runs as usize, levels + 1);
    }
    // Down: `below` is now the top level.
    let (mut upper, mut upper_len) = (below, len);
    while levels > 0 {
        let lower_len = upper_len << shift;
        let lower = if levels == 1 { out } else { upper - lower_len as usize };
        g.each(|p| {
            if p >= s && p < lower_len {
                let i = lower + p as usize;
                sh[i] = op.apply(sh[upper + (p >> shift) as usize - 1], sh[i]);
            }
        });
        (upper, upper_len, levels) = (lower, lower_len, levels - 1);
    }
    out
}

/// Two inclusive scans side by side, `op_a` over `sh[a .. a + n]` and `op_b` over `sh[b .. b + n]`
/// (`n` the workgroup size, one word per invocation each), both restarting wherever the segment id
/// at `sh[segs + i]` changes (ids non-decreasing in `i`): the scans of several short runs at once,
/// one run per segment. Each ping-pongs with the `n` words after it; returns the offsets of the
/// halves that hold the results. Hillis-Steele: log2(n) barriers for both (subgroups have no
/// segmented scan).
pub fn segmented_scans<G: Group, A: WordOp, B: WordOp, const N: usize>(
    g: &mut G,
    sh: &mut [u32; N],
    (a, b, segs): (usize, usize, usize),
    op_a: A,
    op_b: B,
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
            sh[dst_a + i] = if same { op_a.apply(sh[src_a + (lid - d) as usize], own_a) } else { own_a };
            sh[dst_b + i] = if same { op_b.apply(sh[src_b + (lid - d) as usize], own_b) } else { own_b };
        });
        flip = !flip;
        d *= 2;
    }
    if flip { (a + t, b + t) } else { (a, b) }
}

/// The reduction under `op` of `sh[base .. base + n]`, `n` the workgroup size (a power of two;
/// one word per invocation, written before the call), which it overwrites. Every invocation gets
/// the result. With subgroups of `s`, each level reduces runs of `s` words into the first of each
/// (the word its own invocation read), and the last level is reduced by every subgroup at once:
/// `ceil(log_s n)` barriers (2 for 256 invocations in subgroups of 32). Without, a tree halving
/// the active invocations: `log2 n + 1` barriers and `n − 1` operations.
pub fn reduce<G: Group, O: WordOp, const N: usize>(g: &mut G, sh: &mut [u32; N], base: usize, op: O) -> u32 {
    match g.subgroup_size() {
        Some(s) => subgroup_reduce(g, sh, base, op, s),
        None => tree_reduce(g, sh, base, op),
    }
}

fn tree_reduce<G: Group, O: WordOp, const N: usize>(g: &mut G, sh: &mut [u32; N], base: usize, op: O) -> u32 {
    let mut half = g.size() / 2;
    while half > 0 {
        g.each(|lid| {
            if lid < half {
                let i = base + lid as usize;
                sh[i] = op.apply(sh[i], sh[i + half as usize]);
            }
        });
        half /= 2;
    }
    // Read in a step of its own, so that no invocation overwrites the word before all have read it.
    let mut total = 0;
    g.each(|_| total = sh[base]);
    total
}

fn subgroup_reduce<G: Group, O: WordOp, const N: usize>(g: &mut G, sh: &mut [u32; N], base: usize, op: O, s: u32) -> u32 {
    let shift = s.trailing_zeros();
    // The level's words are `len` words `1 << stride` apart.
    let (mut len, mut stride) = (g.size(), 0u32);
    while len > s {
        g.each_combined(
            op,
            Combine::Reduce,
            sh,
            |sh, p| if p < len { sh[base + (p << stride) as usize] } else { O::IDENTITY },
            |sh, p, x| {
                if p < len && p & (s - 1) == 0 {
                    sh[base + (p << stride) as usize] = x;
                }
            },
        );
        (len, stride) = (len >> shift, stride + shift);
    }
    // Every subgroup reads the whole last level, so every invocation gets the total.
    let mut total = O::IDENTITY;
    g.each_combined(
        op,
        Combine::Reduce,
        sh,
        |sh, p| {
            let k = p & (s - 1);
            if k < len { sh[base + (k << stride) as usize] } else { O::IDENTITY }
        },
        |_, _, x| total = x,
    );
    total
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exec::CpuGroup;

    /// A CPU workgroup of `size` in subgroups of `s` (`None`: without), counting its barriers.
    struct Counting {
        group: CpuGroup,
        barriers: u32,
    }

    impl Group for Counting {
        fn size(&self) -> u32 {
            self.group.size
        }
        fn workgroup_id(&self) -> [u32; 3] {
            [0; 3]
        }
        fn num_workgroups(&self) -> [u32; 3] {
            [1; 3]
        }
        fn each(&mut self, f: impl FnMut(u32)) {
            self.barriers += 1;
            self.group.each(f);
        }
        fn invocations(&self) -> core::ops::Range<u32> {
            self.group.invocations()
        }
        fn subgroup_size(&self) -> Option<u32> {
            self.group.subgroup_size()
        }
        fn each_combined<O: WordOp, D: ?Sized>(
            &mut self,
            op: O,
            combine: Combine,
            data: &mut D,
            input: impl FnMut(&D, u32) -> u32,
            output: impl FnMut(&mut D, u32, u32),
        ) {
            self.barriers += 1;
            self.group.each_combined(op, combine, data, input, output);
        }
    }

    fn group(size: u32, s: Option<u32>) -> Counting {
        Counting { group: CpuGroup { size, workgroup_id: [0; 3], num_workgroups: [1; 3], subgroup_size: s, barriers: 0 }, barriers: 0 }
    }

    /// Words that overflow when added and whose maximum moves around.
    fn words(n: usize, seed: u32) -> Vec<u32> {
        let mut x = seed.wrapping_mul(0x9e37_79b9) | 1;
        (0..n)
            .map(|_| {
                x ^= x << 13;
                x ^= x >> 17;
                x ^= x << 5;
                x
            })
            .collect()
    }

    const WIDTHS: [Option<u32>; 7] = [None, Some(2), Some(4), Some(8), Some(32), Some(64), Some(256)];

    #[test]
    fn scans_equal_a_serial_scan_at_every_subgroup_width() {
        for size in [64u32, 256] {
            for s in WIDTHS.into_iter().filter(|s| s.is_none_or(|s| s <= size)) {
                for seed in 1..4 {
                    let input = words(size as usize, seed);
                    let check = |op: &dyn Fn(u32, u32) -> u32, got: &[u32]| {
                        let mut running = None;
                        for (i, (&w, &g)) in input.iter().zip(got).enumerate() {
                            let want = running.map_or(w, |r| op(r, w));
                            assert_eq!(g, want, "word {i} of {size} in subgroups of {s:?}");
                            running = Some(want);
                        }
                    };
                    let mut sh = [0u32; 3 * 256];
                    // At an offset, so a scan that strays out of its two halves shows.
                    sh[256..256 + size as usize].copy_from_slice(&input);
                    let at = inclusive_scan(&mut group(size, s), &mut sh, 256, Add);
                    check(&|a, b| a.wrapping_add(b), &sh[at..at + size as usize]);
                    assert!(sh[..256].iter().all(|&w| w == 0), "the scan wrote below its words");
                    sh[256..256 + size as usize].copy_from_slice(&input);
                    let at = inclusive_scan(&mut group(size, s), &mut sh, 256, Max);
                    check(&|a, b| a.max(b), &sh[at..at + size as usize]);
                }
            }
        }
    }

    #[test]
    fn reductions_equal_a_serial_fold_at_every_subgroup_width() {
        for size in [64u32, 256] {
            for s in WIDTHS.into_iter().filter(|s| s.is_none_or(|s| s <= size)) {
                for seed in 1..4 {
                    let input = words(size as usize, seed);
                    let mut sh = [0u32; 2 * 256];
                    sh[..size as usize].copy_from_slice(&input);
                    let sum = reduce(&mut group(size, s), &mut sh, 0, Add);
                    assert_eq!(sum, input.iter().fold(0u32, |a, &b| a.wrapping_add(b)), "{size} in subgroups of {s:?}");
                    sh[..size as usize].copy_from_slice(&input);
                    let max = reduce(&mut group(size, s), &mut sh, 0, Max);
                    assert_eq!(max, input.iter().copied().max().unwrap_or(0), "{size} in subgroups of {s:?}");
                    assert!(sh[size as usize..].iter().all(|&w| w == 0), "the reduction wrote past its words");
                }
            }
        }
    }

    #[test]
    fn subgroups_of_32_take_fewer_barriers() {
        let barriers = |s, scan: bool| {
            let mut g = group(256, s);
            let mut sh = [1u32; 512];
            if scan {
                inclusive_scan(&mut g, &mut sh, 0, Add);
            } else {
                reduce(&mut g, &mut sh, 0, Add);
            }
            g.barriers
        };
        assert_eq!((barriers(None, true), barriers(Some(32), true)), (8, 3));
        assert_eq!((barriers(None, false), barriers(Some(32), false)), (9, 2));
        assert_eq!((barriers(Some(8), true), barriers(Some(8), false)), (5, 3));
    }
}
