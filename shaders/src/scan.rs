//! Exclusive prefix sum over `u32` of any length, in place, by levels: `scan_block` scans blocks of
//! [`BLOCK`] words and writes each block's total to a sums array; the host scans the sums the same way
//! (recursively, until one block remains) and `scan_add` adds each block's offset back. Sums wrap
//! modulo 2^32 on both backends.

use crate::exec::{Group, Load, Mem};
use crate::wg::{Add, inclusive_scan};

pub const THREADS: u32 = 256;
pub const ITEMS: u32 = 4;
/// Words one workgroup scans.
pub const BLOCK: u32 = THREADS * ITEMS;
/// Largest number of workgroups the host dispatches in one dimension; kernels loop over the rest.
pub const MAX_GROUPS: u32 = 65535;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct ScanParams {
    /// Words to scan.
    pub len: u32,
    /// Where they start in `data`.
    pub data_offset: u32,
    /// Where the block sums start in `sums`.
    pub sums_offset: u32,
}

/// Exclusive scan of each block of `data`, block totals to `sums`. Workgroup memory holds the
/// per-invocation totals and the ping-pong half of their scan.
pub fn block_pass<G: Group, M: Mem>(g: &mut G, p: &ScanParams, sh: &mut [u32; 2 * THREADS as usize], mut data: M, mut sums: M) {
    let blocks = p.len.div_ceil(BLOCK);
    let mut block = g.workgroup_id()[0];
    while block < blocks {
        let base = p.data_offset + block * BLOCK;
        let end = p.data_offset + p.len;
        // Each invocation sums its ITEMS consecutive words.
        g.each(|lid| {
            let mut total = 0u32;
            let mut i = 0;
            while i < ITEMS {
                let at = base + lid * ITEMS + i;
                if at < end {
                    total = total.wrapping_add(data.load(at));
                }
                i += 1;
            }
            sh[lid as usize] = total;
        });
        let src = inclusive_scan(g, sh, 0, Add);
        g.each(|lid| {
            let inclusive = sh[src + lid as usize];
            let mut running = if lid == 0 { 0 } else { sh[src + lid as usize - 1] };
            let mut i = 0;
            while i < ITEMS {
                let at = base + lid * ITEMS + i;
                if at < end {
                    let v = data.load(at);
                    data.store(at, running);
                    running = running.wrapping_add(v);
                }
                i += 1;
            }
            if lid == THREADS - 1 {
                sums.store(p.sums_offset + block, inclusive);
            }
        });
        block += g.num_workgroups()[0];
    }
}

/// Adds the scanned block sums back to every word of each block.
pub fn add_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &ScanParams, mut data: M, sums: R) {
    let blocks = p.len.div_ceil(BLOCK);
    let mut block = g.workgroup_id()[0];
    while block < blocks {
        let base = p.data_offset + block * BLOCK;
        let end = p.data_offset + p.len;
        let offset = sums.load(p.sums_offset + block);
        g.each(|lid| {
            let mut i = 0;
            while i < ITEMS {
                let at = base + lid * ITEMS + i;
                if at < end {
                    data.store(at, data.load(at).wrapping_add(offset));
                }
                i += 1;
            }
        });
        block += g.num_workgroups()[0];
    }
}

kernel!(
    /// Exclusive scan within blocks of `BLOCK` words; block totals to `sums`.
    BLOCK_SCAN = scan_block [256 subgroups] (ScanParams) shared [u32; 2 * 256] { data, sums } => block_pass
);
kernel!(
    /// Adds each block's scanned offset to its words.
    ADD = scan_add [256] (ScanParams) { data, read sums } => add_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 2] = [&BLOCK_SCAN, &ADD];
