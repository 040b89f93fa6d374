//! Segmented bitonic sort: many independent lists of `(f32 key, u32 payload)` of different lengths
//! sorted in one pass (the per-tile depth sort of Franke et al. 2018, §5.2).
//!
//! Pipeline (the host records it; see `host/src/ops/sort.rs`):
//! 1. `sort_classify`: every non-empty list goes to the smallest length class whose capacity holds
//!    it, or to the global class when it exceeds the largest class the device's workgroup memory
//!    allows. Empty lists are left out.
//! 2. `sort_plan`: turns the class counts into indirect dispatch arguments, so empty classes cost a
//!    zero-sized dispatch and the CPU never reads the counts back.
//! 3. `sort_shared_*`: one workgroup sorts one list entirely in workgroup memory, 8 bytes an element.
//! 4. Lists above the largest class take the global-memory path: `sort_global_local` sorts blocks of
//!    [`LOCAL_BLOCK`] elements in workgroup memory, then for every larger merge size `sort_global_step`
//!    runs the wide compare-exchange steps in global memory and `sort_global_local` finishes the
//!    narrow ones in workgroup memory; `sort_global_store` gathers the payloads.
//!
//! The network is the all-ascending ("flip") form of bitonic sort, so a list of any length `n` is sorted
//! by skipping every comparator whose upper element lies at or beyond `n`: elements past the end
//! behave as `+inf` padding that never moves. Elements are compared as `(sort_key(key), position)`, a
//! strict total order, so the result is the stable sort under [`crate::keys::sort_key`]: bit-identical
//! on every backend and schedule. Output goes to separate buffers (keys keep their original bits).

use crate::exec::{Group, Load, Mem};
use crate::keys::sort_key;

/// Capacities of the workgroup-memory classes. A class need not be a power of two (see the module
/// note), which lets a 48 KiB device use a 6144-element class.
pub const CLASS_CAPS: [u32; 9] = [64, 128, 256, 512, 1024, 2048, 4096, 6144, 8192];
pub const NUM_CLASSES: u32 = CLASS_CAPS.len() as u32;
/// Index of the global-memory class in the plan's counts.
pub const GLOBAL_CLASS: u32 = NUM_CLASSES;
/// Workgroup memory per element of a class: the transformed key and the element's position.
pub const BYTES_PER_ELEMENT: u32 = 8;
/// Block size of the workgroup-memory steps of the global path: 16 KiB, the minimum every Vulkan
/// device provides.
pub const LOCAL_BLOCK: u32 = 2048;
/// Largest workgroup count in one dimension the plan emits (Vulkan guarantees 65535); kernels loop
/// over the rest.
pub const MAX_GROUPS: u32 = 65535;

/// Layout of the plan buffer (u32 words).
pub mod plan {
    use super::NUM_CLASSES;
    /// `counts[c]`: lists in class `c`, `c <= GLOBAL_CLASS`.
    pub const COUNTS: u32 = 0;
    /// Longest list of the global class.
    pub const GLOBAL_MAX_LEN: u32 = NUM_CLASSES + 1;
    /// Indirect dispatch arguments `[x, y, z]` of class `c` at `CLASS_ARGS + 3 c`.
    pub const CLASS_ARGS: u32 = 12;
    /// Global path: one workgroup per [`super::LOCAL_BLOCK`] elements and list.
    pub const BLOCK_ARGS: u32 = CLASS_ARGS + 3 * NUM_CLASSES;
    /// Global path: one workgroup per 256 comparators of the longest list, per list.
    pub const STEP_ARGS: u32 = BLOCK_ARGS + 3;
    /// Global path: one workgroup per 256 elements of the longest list, per list.
    pub const ELEMENT_ARGS: u32 = STEP_ARGS + 3;
    pub const WORDS: u32 = ELEMENT_ARGS + 3;
}

/// The largest class index whose workgroup memory fits `shared_bytes`.
pub fn top_class_for(shared_bytes: u32) -> u32 {
    let mut top = 0;
    let mut c = 0;
    while c < NUM_CLASSES {
        if CLASS_CAPS[c as usize] * BYTES_PER_ELEMENT <= shared_bytes {
            top = c;
        }
        c += 1;
    }
    top
}

/// The class of a list of length `len >= 1`, given the largest usable class.
#[inline]
pub fn class_of(len: u32, top_class: u32) -> u32 {
    let mut c = 0;
    while c <= top_class {
        if len <= CLASS_CAPS[c as usize] {
            return c;
        }
        c += 1;
    }
    GLOBAL_CLASS
}

/// Smallest power of two `>= n` (1 for 0).
#[inline]
pub fn pow2_ceil(n: u32) -> u32 {
    if n <= 1 { 1 } else { 1 << (32 - (n - 1).leading_zeros()) }
}

/// The two positions compared by comparator `t` of step `j` in merge stage `k` of the flip network.
/// `k` and `j` are powers of two, so blocks are found with masks: no division (a GPU runs an
/// integer division as a long instruction sequence, and this runs for every comparator).
#[inline]
pub fn comparator(t: u32, k: u32, j: u32) -> (u32, u32) {
    // The comparator's pair of `2 j` positions starts at `(t / j) · 2 j`.
    let lo = ((t & !(j - 1)) << 1) + (t & (j - 1));
    if j == k >> 1 {
        // Flip: compare mirrored positions of each k-block (here `2 j = k`).
        let base = (t & !(j - 1)) << 1;
        (lo, base + k - 1 - (t & (j - 1)))
    } else {
        (lo, lo + j)
    }
}

/// Storage of `(key, position)` pairs that a compare-exchange works on.
trait Pairs {
    fn get(&self, i: u32) -> (u32, u32);
    fn set(&mut self, i: u32, key: u32, pos: u32);

    #[inline]
    fn compare_exchange(&mut self, a: u32, b: u32) {
        let (ka, pa) = self.get(a);
        let (kb, pb) = self.get(b);
        if ka > kb || (ka == kb && pa > pb) {
            self.set(a, kb, pb);
            self.set(b, ka, pa);
        }
    }
}

/// Pairs in workgroup memory: keys in `[0, cap)`, positions in `[cap, 2 cap)`, element `i` at
/// `base + i`.
struct SharedPairs<'a, const N: usize> {
    sh: &'a mut [u32; N],
    base: u32,
}

impl<const N: usize> Pairs for SharedPairs<'_, N> {
    #[inline]
    fn get(&self, i: u32) -> (u32, u32) {
        let i = (i - self.base) as usize;
        (self.sh[i], self.sh[N / 2 + i])
    }
    #[inline]
    fn set(&mut self, i: u32, key: u32, pos: u32) {
        let i = (i - self.base) as usize;
        self.sh[i] = key;
        self.sh[N / 2 + i] = pos;
    }
}

/// Pairs in the global scratch buffers, element `i` of the list at `offset + i`.
struct GlobalPairs<'a, M: Mem> {
    keys: &'a mut M,
    pos: &'a mut M,
    offset: u32,
}

impl<M: Mem> Pairs for GlobalPairs<'_, M> {
    #[inline]
    fn get(&self, i: u32) -> (u32, u32) {
        (self.keys.load(self.offset + i), self.pos.load(self.offset + i))
    }
    #[inline]
    fn set(&mut self, i: u32, key: u32, pos: u32) {
        self.keys.store(self.offset + i, key);
        self.pos.store(self.offset + i, pos);
    }
}

/// Runs the compare-exchange steps `j = j_start, j_start/2, .., 1` of stage `k` over the positions
/// `[base, base + span)` of a list of length `len`, held in workgroup memory. With `j_start == k / 2`
/// this includes the flip. Wide steps take one barrier each; once a step only pairs positions inside
/// aligned chunks of `span / size`, each invocation runs all remaining steps on its own chunk without
/// barriers (they touch nothing outside it).
fn local_steps<G: Group, const N: usize>(g: &mut G, sh: &mut [u32; N], base: u32, span: u32, len: u32, k: u32, j_start: u32) {
    let size = g.size();
    let chunk = span / size;
    let mut j = j_start;
    while j > 0 {
        if 2 * j <= chunk {
            g.each(|lid| {
                let mut pairs = SharedPairs { sh: &mut *sh, base };
                let start = base + lid * chunk;
                let mut jj = j;
                while jj > 0 {
                    let mut t = 0;
                    while t < chunk / 2 {
                        let (a, b) = comparator(t, k, jj);
                        if start + b < len {
                            pairs.compare_exchange(start + a, start + b);
                        }
                        t += 1;
                    }
                    jj /= 2;
                }
            });
            return;
        }
        g.each(|lid| {
            let mut pairs = SharedPairs { sh: &mut *sh, base };
            let mut t = lid;
            while t < span / 2 {
                let (a, b) = comparator(t, k, j);
                if base + b < len {
                    pairs.compare_exchange(base + a, base + b);
                }
                t += size;
            }
        });
        j /= 2;
    }
}

/// Full bitonic sort of the positions `[base, base + span)` (`span` a power of two) in workgroup
/// memory: all stages `k = 2 ..= span`.
fn local_sort<G: Group, const N: usize>(g: &mut G, sh: &mut [u32; N], base: u32, span: u32, len: u32) {
    let mut k = 2;
    while k <= span {
        local_steps(g, sh, base, span, len, k, k / 2);
        k *= 2;
    }
}

/// Segments: `segments[2 s]` is the offset of list `s`, `segments[2 s + 1]` its length.
#[inline]
fn segment(segments: &impl Load, s: u32) -> (u32, u32) {
    (segments.load(2 * s), segments.load(2 * s + 1))
}

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct ClassifyParams {
    pub num_segments: u32,
    /// Largest workgroup-memory class the device can run, from [`top_class_for`].
    pub top_class: u32,
}

/// One invocation per list: append it to its class. `lists[c * num_segments + slot]` holds the
/// lists of class `c`; the plan's counts must be zero beforehand.
pub fn classify<G: Group, R: Load, M: Mem>(g: &mut G, p: &ClassifyParams, segments: R, mut plan: M, mut lists: M) {
    let size = g.size();
    let first = g.workgroup_id()[0] * size;
    let stride = g.num_workgroups()[0] * size;
    g.each(|lid| {
        let mut s = first + lid;
        while s < p.num_segments {
            let (_, len) = segment(&segments, s);
            if len > 0 {
                let class = class_of(len, p.top_class);
                let slot = plan.atomic_add(plan::COUNTS + class, 1);
                lists.store(class * p.num_segments + slot, s);
                if class == GLOBAL_CLASS {
                    plan.atomic_max(plan::GLOBAL_MAX_LEN, len);
                }
            }
            s += stride;
        }
    });
}

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct PlanParams {
    pub unused: u32,
}

fn set_args<M: Mem>(plan: &mut M, at: u32, x: u32, y: u32) {
    plan.store(at, x);
    plan.store(at + 1, y);
    plan.store(at + 2, 1);
}

/// One invocation writes the indirect dispatch arguments of every class and of the global path.
pub fn write_plan<G: Group, M: Mem>(g: &mut G, _p: &PlanParams, mut plan: M) {
    g.each(|lid| {
        if lid == 0 {
            let mut c = 0;
            while c < NUM_CLASSES {
                let count = plan.load(plan::COUNTS + c);
                set_args(&mut plan, plan::CLASS_ARGS + 3 * c, count.min(MAX_GROUPS), 1);
                c += 1;
            }
            let lists = plan.load(plan::COUNTS + GLOBAL_CLASS).min(MAX_GROUPS);
            let max_len = plan.load(plan::GLOBAL_MAX_LEN);
            let blocks = max_len.div_ceil(LOCAL_BLOCK).min(MAX_GROUPS);
            let steps = (pow2_ceil(max_len) / 2).div_ceil(256).min(MAX_GROUPS);
            let elements = max_len.div_ceil(256).min(MAX_GROUPS);
            set_args(&mut plan, plan::BLOCK_ARGS, blocks, lists);
            set_args(&mut plan, plan::STEP_ARGS, steps, lists);
            set_args(&mut plan, plan::ELEMENT_ARGS, elements, lists);
        }
    });
}

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct SortParams {
    pub num_segments: u32,
    /// The class this dispatch sorts (for `sort_shared_*`), ignored by the global kernels.
    pub class: u32,
    /// Merge stage `k` of the global path; 0 for the first local pass.
    pub k: u32,
    /// Step `j` of `sort_global_step`.
    pub j: u32,
    /// `sort_shared_*`: 1 to sort each list with one invocation ([`serial_sort`]) instead of the
    /// network, for a device whose invocations of a workgroup run one after another (the CPU
    /// backend), where the network's `n log² n` comparators are all paid one by one.
    pub serial: u32,
}

/// Elements [`serial_sort`] first sorts by insertion.
const SERIAL_RUN: u32 = 16;

/// Stable merges of the sorted runs of `w` elements of `src`, pairwise, into `dst` (positions
/// `[0, len)`). A left run's elements precede the right run's in the input, so taking the right
/// one only when its key is smaller keeps the order under `(key, position)`.
#[inline]
fn merge_runs(src: &impl Pairs, dst: &mut impl Pairs, len: u32, w: u32) {
    let mut lo = 0;
    while lo < len {
        let mid = if lo + w < len { lo + w } else { len };
        let hi = if mid + w < len { mid + w } else { len };
        let (mut i, mut j, mut o) = (lo, mid, lo);
        while i < mid && j < hi {
            let (a, b) = (src.get(i), src.get(j));
            if b.0 < a.0 {
                dst.set(o, b.0, b.1);
                j += 1;
            } else {
                dst.set(o, a.0, a.1);
                i += 1;
            }
            o += 1;
        }
        while i < mid {
            let a = src.get(i);
            dst.set(o, a.0, a.1);
            i += 1;
            o += 1;
        }
        while j < hi {
            let b = src.get(j);
            dst.set(o, b.0, b.1);
            j += 1;
            o += 1;
        }
        lo = hi;
    }
}

/// The serial strategy ([`SortParams::serial`]): one invocation sorts the `len` pairs in
/// workgroup memory, with `scratch` (the list's own stretch of the output buffers) as the second
/// buffer of a merge sort: runs of [`SERIAL_RUN`] by insertion, then bottom-up merges, back and
/// forth. `n log n` steps; the result is the network's, the order under `(key, position)`, which
/// is unique.
fn serial_sort<const N: usize, M: Mem>(sh: &mut [u32; N], scratch: &mut GlobalPairs<'_, M>, len: u32) {
    let mut shared = SharedPairs { sh, base: 0 };
    let mut s = 0;
    while s < len {
        let e = if s + SERIAL_RUN < len { s + SERIAL_RUN } else { len };
        let mut i = s + 1;
        while i < e {
            let (k, p) = shared.get(i);
            let mut m = i;
            while m > s {
                let (pk, pp) = shared.get(m - 1);
                if pk <= k {
                    break;
                }
                shared.set(m, pk, pp);
                m -= 1;
            }
            shared.set(m, k, p);
            i += 1;
        }
        s = e;
    }
    let mut w = SERIAL_RUN;
    let mut in_shared = true;
    while w < len {
        if in_shared {
            merge_runs(&shared, scratch, len, w);
        } else {
            merge_runs(scratch, &mut shared, len, w);
        }
        in_shared = !in_shared;
        w *= 2;
    }
    if !in_shared {
        let mut i = 0;
        while i < len {
            let (k, p) = scratch.get(i);
            shared.set(i, k, p);
            i += 1;
        }
    }
}

/// One workgroup sorts one list of the class in workgroup memory (`N / 2` elements at most), looping
/// over the class's lists when there are more than workgroups.
#[allow(clippy::too_many_arguments)]
pub fn shared_class_pass<G: Group, R: Load, M: Mem, const N: usize>(
    g: &mut G,
    p: &SortParams,
    sh: &mut [u32; N],
    segments: R,
    plan: R,
    lists: R,
    keys_in: R,
    values_in: R,
    mut keys_out: M,
    mut values_out: M,
) {
    let size = g.size();
    let count = plan.load(plan::COUNTS + p.class);
    let mut slot = g.workgroup_id()[0];
    while slot < count {
        let s = lists.load(p.class * p.num_segments + slot);
        let (offset, len) = segment(&segments, s);
        g.each(|lid| {
            let mut i = lid;
            while i < len {
                sh[i as usize] = sort_key(keys_in.load(offset + i));
                sh[N / 2 + i as usize] = i;
                i += size;
            }
        });
        if p.serial != 0 {
            g.each(|lid| {
                if lid == 0 {
                    serial_sort(sh, &mut GlobalPairs { keys: &mut keys_out, pos: &mut values_out, offset }, len);
                }
            });
        } else {
            local_sort(g, sh, 0, pow2_ceil(len), len);
        }
        g.each(|lid| {
            let mut i = lid;
            while i < len {
                let from = offset + sh[N / 2 + i as usize];
                keys_out.store(offset + i, keys_in.load(from));
                values_out.store(offset + i, values_in.load(from));
                i += size;
            }
        });
        slot += g.num_workgroups()[0];
    }
}

/// Runs `body(group, offset, len)` for every global-class list this workgroup handles (workgroup row
/// `y` takes lists `y, y + rows, ..`). Uniform: every invocation sees the same lists.
fn for_each_global_list<G: Group>(
    g: &mut G,
    p: &SortParams,
    plan: &impl Load,
    lists: &impl Load,
    segments: &impl Load,
    mut body: impl FnMut(&mut G, u32, u32),
) {
    let count = plan.load(plan::COUNTS + GLOBAL_CLASS);
    let mut slot = g.workgroup_id()[1];
    while slot < count {
        let (offset, len) = segment(segments, lists.load(GLOBAL_CLASS * p.num_segments + slot));
        body(g, offset, len);
        slot += g.num_workgroups()[1];
    }
}

/// Global path, workgroup-memory part. With `k == 0`: transform the keys of one [`LOCAL_BLOCK`] of a
/// list into the scratch buffers and sort the block. With `k > LOCAL_BLOCK`: load the block from
/// scratch, run the steps `j < LOCAL_BLOCK` of stage `k`, store it back.
#[allow(clippy::too_many_arguments)]
pub fn global_local_pass<G: Group, R: Load, M: Mem, const N: usize>(
    g: &mut G,
    p: &SortParams,
    sh: &mut [u32; N],
    segments: R,
    plan: R,
    lists: R,
    keys_in: R,
    mut scratch_keys: M,
    mut scratch_pos: M,
) {
    let size = g.size();
    for_each_global_list(g, p, &plan, &lists, &segments, |g, offset, len| {
        let mut block = g.workgroup_id()[0];
        // A merge stage wider than the list's padded length has nothing to do for it.
        let active = p.k <= pow2_ceil(len);
        while active && block * LOCAL_BLOCK < len {
            let base = block * LOCAL_BLOCK;
            g.each(|lid| {
                let mut i = lid;
                while i < LOCAL_BLOCK && base + i < len {
                    let at = offset + base + i;
                    if p.k == 0 {
                        sh[i as usize] = sort_key(keys_in.load(at));
                        sh[N / 2 + i as usize] = base + i;
                    } else {
                        sh[i as usize] = scratch_keys.load(at);
                        sh[N / 2 + i as usize] = scratch_pos.load(at);
                    }
                    i += size;
                }
            });
            if p.k == 0 {
                local_sort(g, sh, base, LOCAL_BLOCK, len);
            } else {
                local_steps(g, sh, base, LOCAL_BLOCK, len, p.k, LOCAL_BLOCK / 2);
            }
            g.each(|lid| {
                let mut i = lid;
                while i < LOCAL_BLOCK && base + i < len {
                    scratch_keys.store(offset + base + i, sh[i as usize]);
                    scratch_pos.store(offset + base + i, sh[N / 2 + i as usize]);
                    i += size;
                }
            });
            block += g.num_workgroups()[0];
        }
    });
}

/// Global path: one compare-exchange step `(k, j)` with `j >= LOCAL_BLOCK`, in global memory.
#[allow(clippy::too_many_arguments)]
pub fn global_step_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &SortParams,
    segments: R,
    plan: R,
    lists: R,
    mut scratch_keys: M,
    mut scratch_pos: M,
) {
    let size = g.size();
    let first = g.workgroup_id()[0] * size;
    let stride = g.num_workgroups()[0] * size;
    for_each_global_list(g, p, &plan, &lists, &segments, |g, offset, len| {
        g.each(|lid| {
            let mut pairs = GlobalPairs { keys: &mut scratch_keys, pos: &mut scratch_pos, offset };
            let mut t = first + lid;
            // Stages beyond the list's padded length have nothing to do for it.
            let active = p.k <= pow2_ceil(len);
            while active && t < pow2_ceil(len) / 2 {
                let (a, b) = comparator(t, p.k, p.j);
                if b < len {
                    pairs.compare_exchange(a, b);
                }
                t += stride;
            }
        });
    });
}

/// Global path: write the sorted keys and gather the payloads.
#[allow(clippy::too_many_arguments)]
pub fn global_store_pass<G: Group, R: Load, M: Mem>(
    g: &mut G,
    p: &SortParams,
    segments: R,
    plan: R,
    lists: R,
    keys_in: R,
    values_in: R,
    scratch_pos: R,
    mut keys_out: M,
    mut values_out: M,
) {
    let size = g.size();
    let first = g.workgroup_id()[0] * size;
    let stride = g.num_workgroups()[0] * size;
    for_each_global_list(g, p, &plan, &lists, &segments, |g, offset, len| {
        g.each(|lid| {
            let mut i = first + lid;
            while i < len {
                let from = offset + scratch_pos.load(offset + i);
                keys_out.store(offset + i, keys_in.load(from));
                values_out.store(offset + i, values_in.load(from));
                i += stride;
            }
        });
    });
}

kernel!(
    /// Appends every non-empty list to its length class.
    CLASSIFY = sort_classify [256] (ClassifyParams) { read segments, plan, lists } => classify
);
kernel!(
    /// Indirect dispatch arguments from the class counts.
    PLAN = sort_plan [64] (PlanParams) { plan } => write_plan
);
kernel!(SHARED_64 = sort_shared_64 [32] (SortParams) shared [u32; 2 * 64]
    { read segments, read plan, read lists, read keys_in, read values_in, keys_out, values_out } => shared_class_pass);
kernel!(SHARED_128 = sort_shared_128 [64] (SortParams) shared [u32; 2 * 128]
    { read segments, read plan, read lists, read keys_in, read values_in, keys_out, values_out } => shared_class_pass);
kernel!(SHARED_256 = sort_shared_256 [128] (SortParams) shared [u32; 2 * 256]
    { read segments, read plan, read lists, read keys_in, read values_in, keys_out, values_out } => shared_class_pass);
kernel!(SHARED_512 = sort_shared_512 [256] (SortParams) shared [u32; 2 * 512]
    { read segments, read plan, read lists, read keys_in, read values_in, keys_out, values_out } => shared_class_pass);
kernel!(SHARED_1024 = sort_shared_1024 [256] (SortParams) shared [u32; 2 * 1024]
    { read segments, read plan, read lists, read keys_in, read values_in, keys_out, values_out } => shared_class_pass);
kernel!(SHARED_2048 = sort_shared_2048 [256] (SortParams) shared [u32; 2 * 2048]
    { read segments, read plan, read lists, read keys_in, read values_in, keys_out, values_out } => shared_class_pass);
kernel!(SHARED_4096 = sort_shared_4096 [256] (SortParams) shared [u32; 2 * 4096]
    { read segments, read plan, read lists, read keys_in, read values_in, keys_out, values_out } => shared_class_pass);
kernel!(SHARED_6144 = sort_shared_6144 [256] (SortParams) shared [u32; 2 * 6144]
    { read segments, read plan, read lists, read keys_in, read values_in, keys_out, values_out } => shared_class_pass);
kernel!(SHARED_8192 = sort_shared_8192 [256] (SortParams) shared [u32; 2 * 8192]
    { read segments, read plan, read lists, read keys_in, read values_in, keys_out, values_out } => shared_class_pass);
kernel!(
    /// Global path: transform and sort blocks (`k == 0`), or finish the narrow steps of stage `k`.
    GLOBAL_LOCAL = sort_global_local [256] (SortParams) shared [u32; 2 * 2048]
    { read segments, read plan, read lists, read keys_in, scratch_keys, scratch_pos } => global_local_pass
);
kernel!(
    /// Global path: one wide compare-exchange step in global memory.
    GLOBAL_STEP = sort_global_step [256] (SortParams)
    { read segments, read plan, read lists, scratch_keys, scratch_pos } => global_step_pass
);
kernel!(
    /// Global path: sorted keys and payloads to the outputs.
    GLOBAL_STORE = sort_global_store [256] (SortParams)
    { read segments, read plan, read lists, read keys_in, read values_in, read scratch_pos, keys_out, values_out } => global_store_pass
);

/// The workgroup-memory class kernels, by class index.
#[cfg(not(target_arch = "spirv"))]
pub const SHARED_CLASSES: [&crate::KernelDesc; NUM_CLASSES as usize] =
    [&SHARED_64, &SHARED_128, &SHARED_256, &SHARED_512, &SHARED_1024, &SHARED_2048, &SHARED_4096, &SHARED_6144, &SHARED_8192];

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 14] = [
    &CLASSIFY,
    &PLAN,
    &SHARED_64,
    &SHARED_128,
    &SHARED_256,
    &SHARED_512,
    &SHARED_1024,
    &SHARED_2048,
    &SHARED_4096,
    &SHARED_6144,
    &SHARED_8192,
    &GLOBAL_LOCAL,
    &GLOBAL_STEP,
    &GLOBAL_STORE,
];

#[cfg(test)]
mod tests {
    use super::*;

    /// The flip network with out-of-range comparators skipped sorts every 0-1 sequence of every length
    /// up to 16, hence (zero-one principle) every sequence of those lengths.
    #[test]
    fn network_sorts_every_zero_one_sequence() {
        for len in 0u32..=16 {
            let n = pow2_ceil(len);
            for bits in 0u32..(1 << len) {
                let mut v: Vec<u32> = (0..len).map(|i| (bits >> i) & 1).collect();
                let mut k = 2;
                while k <= n {
                    let mut j = k / 2;
                    while j > 0 {
                        for t in 0..n / 2 {
                            let (a, b) = comparator(t, k, j);
                            assert!(a < b && b < n);
                            if b < len && v[a as usize] > v[b as usize] {
                                v.swap(a as usize, b as usize);
                            }
                        }
                        j /= 2;
                    }
                    k *= 2;
                }
                assert!(v.windows(2).all(|w| w[0] <= w[1]), "len {len} bits {bits:b}: {v:?}");
            }
        }
    }

    #[test]
    fn classes_follow_the_device_limit() {
        assert_eq!(CLASS_CAPS[top_class_for(16 * 1024) as usize], 2048);
        assert_eq!(CLASS_CAPS[top_class_for(32 * 1024) as usize], 4096);
        assert_eq!(CLASS_CAPS[top_class_for(48 * 1024) as usize], 6144);
        assert_eq!(CLASS_CAPS[top_class_for(64 * 1024) as usize], 8192);
        assert_eq!(CLASS_CAPS[top_class_for(1 << 20) as usize], 8192);
        let top = top_class_for(32 * 1024);
        assert_eq!(class_of(1, top), 0);
        assert_eq!(class_of(64, top), 0);
        assert_eq!(class_of(65, top), 1);
        assert_eq!(class_of(4096, top), 6);
        assert_eq!(class_of(4097, top), GLOBAL_CLASS);
    }

    #[test]
    fn the_global_path_block_fits_the_vulkan_minimum() {
        assert_eq!(GLOBAL_LOCAL.shared_bytes, LOCAL_BLOCK * BYTES_PER_ELEMENT);
        const { assert!(GLOBAL_LOCAL.shared_bytes <= 16 * 1024) };
    }

    #[test]
    fn plan_layout_does_not_overlap() {
        const { assert!(plan::GLOBAL_MAX_LEN < plan::CLASS_ARGS) };
        assert_eq!(plan::WORDS, plan::ELEMENT_ARGS + 3);
    }
}
