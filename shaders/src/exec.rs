//! How one kernel body runs on both backends.
//!
//! A kernel is written once as a function generic over [`Group`] (the workgroup executing it),
//! [`Mem`] (its writable storage buffers) and [`Load`] (its read-only ones, which may only be
//! loaded). `Group::each` runs a closure for every invocation of the workgroup and then
//! synchronises: on the GPU it is "call, then barrier"; on the CPU it is a loop over the local ids,
//! which is one legal schedule of the same program. The rule that makes this work: **code outside
//! `each` must be uniform** (the same for every invocation: loop bounds, workgroup ids, values read from
//! shared memory after a barrier); per-invocation state that must survive a barrier lives in workgroup
//! memory.
//!
//! Storage buffers are arrays of `u32` words (floats travel as their bits). On the CPU they are
//! `[AtomicU32]` accessed with relaxed ordering, so workgroups can run in parallel without any unsafe
//! aliasing; on x86 a relaxed load or store is a plain move.

/// The workgroup that executes a kernel body.
pub trait Group {
    /// Invocations in the workgroup (the `threads(..)` of the entry point).
    fn size(&self) -> u32;
    /// `gl_WorkGroupID`.
    fn workgroup_id(&self) -> [u32; 3];
    /// `gl_NumWorkGroups`.
    fn num_workgroups(&self) -> [u32; 3];
    /// Runs `f(local_index)` for every invocation, then a workgroup barrier that also makes storage
    /// buffer writes of the workgroup visible to it.
    fn each(&mut self, f: impl FnMut(u32));
    /// The local ids this code runs as, for barrier-free code that cannot go through a closure
    /// (one reading sampled images: SPIR-V holds no pointer to an image in a closure's captures):
    /// the invocation's own id on the GPU, every id on the CPU.
    fn invocations(&self) -> core::ops::Range<u32>;

    /// The subgroup size `s` when this workgroup runs as whole subgroups of `s` invocations that
    /// [`Group::each_combined`] combines words across (`s` a power of two, at least 2, the same
    /// for every invocation); `None` in a kernel built without subgroup operations, or where the
    /// subgroups are not whole. Uniform, so code may branch on it.
    #[inline]
    fn subgroup_size(&self) -> Option<u32> {
        None
    }

    /// Like [`Group::each`] over positions instead of local ids: `input(p)` for every position
    /// `p < size`, then `output(p, x)` (both given `data`, which they share), `x` the `combine`
    /// under `op` of the inputs of `p`'s subgroup, then a barrier. Subgroup `k` holds positions
    /// `k·s .. (k+1)·s` (`s` as [`Group::subgroup_size`]); which invocation runs which position is
    /// the backend's (on the GPU it need not be the local id), so `input` may read nothing that
    /// another position's `output` writes in the same step. Without subgroups every position is
    /// its own subgroup.
    #[inline]
    fn each_combined<O: WordOp, D: ?Sized>(
        &mut self,
        _op: O,
        _combine: Combine,
        data: &mut D,
        mut input: impl FnMut(&D, u32) -> u32,
        mut output: impl FnMut(&mut D, u32, u32),
    ) {
        self.each(|p| {
            let x = input(data, p);
            output(data, p, x)
        });
    }
}

/// What [`Group::each_combined`] hands each position of a subgroup.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Combine {
    /// The inclusive scan of the subgroup's inputs up to the position.
    Scan,
    /// The reduction of all the subgroup's inputs.
    Reduce,
}

/// An associative and commutative operation on words that a subgroup can scan or reduce in one
/// instruction: the operations of the workgroup scans and reductions ([`crate::wg`]).
pub trait WordOp: Copy {
    /// `x` such that `apply(x, a) == a` for every `a`.
    const IDENTITY: u32;
    fn apply(self, a: u32, b: u32) -> u32;
    /// The inclusive scan of `v` over the invocation's subgroup, up to and including it (`lane`:
    /// its place in the subgroup of `size`).
    #[cfg(target_arch = "spirv")]
    fn subgroup_inclusive(self, v: u32, lane: u32, size: u32) -> u32;
    /// The reduction of `v` over the invocation's subgroup.
    #[cfg(target_arch = "spirv")]
    fn subgroup_reduce(self, v: u32) -> u32;
}

/// Wrapping addition.
#[derive(Clone, Copy)]
pub struct Add;

/// Unsigned maximum.
#[derive(Clone, Copy)]
pub struct Max;

impl WordOp for Add {
    const IDENTITY: u32 = 0;
    #[inline]
    fn apply(self, a: u32, b: u32) -> u32 {
        a.wrapping_add(b)
    }
    #[cfg(target_arch = "spirv")]
    #[inline]
    fn subgroup_inclusive(self, v: u32, _lane: u32, _size: u32) -> u32 {
        spirv_std::arch::subgroup_inclusive_i_add(v)
    }
    #[cfg(target_arch = "spirv")]
    #[inline]
    fn subgroup_reduce(self, v: u32) -> u32 {
        spirv_std::arch::subgroup_i_add(v)
    }
}

impl WordOp for Max {
    const IDENTITY: u32 = 0;
    #[inline]
    fn apply(self, a: u32, b: u32) -> u32 {
        if a > b { a } else { b }
    }
    /// By shuffles: WGSL and HLSL scan only sums and products in one instruction.
    #[cfg(target_arch = "spirv")]
    #[inline]
    fn subgroup_inclusive(self, v: u32, lane: u32, size: u32) -> u32 {
        let mut x = v;
        let mut d = 1;
        while d < size {
            let before = spirv_std::arch::subgroup_shuffle_up(x, d);
            if lane >= d {
                x = self.apply(before, x);
            }
            d *= 2;
        }
        x
    }
    #[cfg(target_arch = "spirv")]
    #[inline]
    fn subgroup_reduce(self, v: u32) -> u32 {
        spirv_std::arch::subgroup_u_max(v)
    }
}

/// Read access to a storage buffer of `u32` words: all a kernel's read-only binding offers (on the
/// GPU it is declared `&[u32]`, which rust-gpu decorates `NonWritable`), and what a graphics stage's
/// bindings offer (they may not write storage buffers without a device feature).
pub trait Load {
    fn len(&self) -> u32;
    fn load(&self, i: u32) -> u32;
    #[inline]
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// A writable storage buffer of `u32` words.
pub trait Mem: Load {
    fn store(&mut self, i: u32, v: u32);
    /// Atomic add (queue-family scope: visible to every workgroup of the dispatch); returns the previous value.
    fn atomic_add(&mut self, i: u32, v: u32) -> u32;
    /// Atomic unsigned max (queue-family scope); returns the previous value.
    fn atomic_max(&mut self, i: u32, v: u32) -> u32;
}

/// Reads the push constants of a kernel from `u32` words (the CPU side of `#[spirv(push_constant)]`).
#[cfg(not(target_arch = "spirv"))]
pub fn params<P: bytemuck::Pod>(words: &[u32]) -> P {
    let bytes: &[u8] = bytemuck::cast_slice(words);
    bytemuck::pod_read_unaligned(&bytes[..core::mem::size_of::<P>()])
}

#[cfg(not(target_arch = "spirv"))]
mod cpu {
    use super::{Combine, Group, Load, Mem, WordOp};
    use core::sync::atomic::{AtomicU32, AtomicU64, Ordering::Relaxed};

    /// A workgroup emulated on one CPU thread: `each` loops over the local ids. With
    /// `subgroup_size`, it runs as subgroups of that many invocations (a power of two dividing
    /// `size`, at most [`CpuGroup::MAX_SUBGROUP`]): position `p` is local id `p`, and a subgroup's
    /// scan or reduction runs over its inputs in order.
    pub struct CpuGroup {
        pub size: u32,
        pub workgroup_id: [u32; 3],
        pub num_workgroups: [u32; 3],
        pub subgroup_size: Option<u32>,
        /// The barriers it has executed: one an `each` or `each_combined` step.
        pub barriers: u32,
    }

    impl CpuGroup {
        /// The widest subgroup the CPU emulates.
        pub const MAX_SUBGROUP: u32 = 256;
    }

    impl Group for CpuGroup {
        #[inline]
        fn size(&self) -> u32 {
            self.size
        }
        #[inline]
        fn workgroup_id(&self) -> [u32; 3] {
            self.workgroup_id
        }
        #[inline]
        fn num_workgroups(&self) -> [u32; 3] {
            self.num_workgroups
        }
        #[inline]
        fn each(&mut self, mut f: impl FnMut(u32)) {
            self.barriers += 1;
            for lid in 0..self.size {
                f(lid);
            }
        }
        #[inline]
        fn invocations(&self) -> core::ops::Range<u32> {
            0..self.size
        }
        #[inline]
        fn subgroup_size(&self) -> Option<u32> {
            self.subgroup_size
        }
        /// `input` of every position, `op` over each subgroup's inputs, then `output`.
        fn each_combined<O: WordOp, D: ?Sized>(
            &mut self,
            op: O,
            combine: Combine,
            data: &mut D,
            mut input: impl FnMut(&D, u32) -> u32,
            mut output: impl FnMut(&mut D, u32, u32),
        ) {
            let s = self.subgroup_size.unwrap_or(1);
            assert!(
                s.is_power_of_two() && s <= Self::MAX_SUBGROUP && self.size % s == 0,
                "subgroups of {s} in a workgroup of {}",
                self.size
            );
            self.barriers += 1;
            let mut words = [0u32; Self::MAX_SUBGROUP as usize];
            let mut first = 0;
            while first < self.size {
                let lanes = &mut words[..s as usize];
                let mut total = O::IDENTITY;
                for (lane, w) in (0..).zip(lanes.iter_mut()) {
                    *w = input(data, first + lane);
                    total = op.apply(total, *w);
                }
                let mut running = O::IDENTITY;
                for (lane, w) in (0..).zip(lanes.iter()) {
                    running = op.apply(running, *w);
                    output(data, first + lane, if combine == Combine::Scan { running } else { total });
                }
                first += s;
            }
        }
    }

    /// A storage buffer on the CPU backend. Out-of-bounds accesses panic, as rust-gpu's bounds
    /// checks abort the invocation on the GPU: the CPU backend catches them and reports a kernel fault.
    /// So does a write to a binding the kernel declared read-only.
    #[derive(Clone, Copy)]
    pub struct CpuMem<'a> {
        pub words: &'a [AtomicU32],
        pub writable: bool,
    }

    impl CpuMem<'_> {
        #[inline]
        fn writable(&self, i: u32) -> usize {
            assert!(self.writable, "a write (word {i}) to a binding the kernel declares read-only");
            i as usize
        }
    }

    impl Load for CpuMem<'_> {
        #[inline]
        fn len(&self) -> u32 {
            self.words.len() as u32
        }
        #[inline]
        fn load(&self, i: u32) -> u32 {
            self.words[i as usize].load(Relaxed)
        }
    }

    impl Mem for CpuMem<'_> {
        #[inline]
        fn store(&mut self, i: u32, v: u32) {
            self.words[self.writable(i)].store(v, Relaxed)
        }
        #[inline]
        fn atomic_add(&mut self, i: u32, v: u32) -> u32 {
            self.words[self.writable(i)].fetch_add(v, Relaxed)
        }
        #[inline]
        fn atomic_max(&mut self, i: u32, v: u32) -> u32 {
            self.words[self.writable(i)].fetch_max(v, Relaxed)
        }
    }

    /// What the CPU backend hands a kernel's CPU entry for one workgroup.
    pub struct CpuDispatch<'a> {
        pub workgroup_id: [u32; 3],
        pub num_workgroups: [u32; 3],
        pub buffers: &'a [&'a [AtomicU32]],
        pub push: &'a [u32],
        /// The kernel's read-only bindings (`KernelDesc::read_only`).
        pub read_only: u32,
        /// Per binding, for a sampled image (`KernelDesc::images`): its width in texels and its
        /// packed format ([`crate::texels`]); `buffers` holds its packed texels. Empty for a kernel
        /// with no images.
        pub image_layouts: &'a [[u32; 2]],
        /// The subgroups a kernel built with subgroup operations runs as (`CpuGroup::subgroup_size`;
        /// a workgroup narrower than that is one subgroup), `None` for one built without.
        pub subgroup_size: Option<u32>,
        /// Barriers executed, summed over the dispatch's workgroups.
        pub barriers: &'a AtomicU64,
    }

    impl<'a> CpuDispatch<'a> {
        #[inline]
        pub fn group(&self, size: u32) -> CpuGroup {
            CpuGroup {
                size,
                workgroup_id: self.workgroup_id,
                num_workgroups: self.num_workgroups,
                // A workgroup narrower than the subgroups is one subgroup.
                subgroup_size: self.subgroup_size.filter(|_| size.is_power_of_two()).map(|s| s.min(size)),
                barriers: 0,
            }
        }
        /// Books the barriers a workgroup executed.
        #[inline]
        pub fn count_barriers(&self, group: &CpuGroup) {
            self.barriers.fetch_add(group.barriers as u64, Relaxed);
        }
        #[inline]
        pub fn mem(&self, binding: usize) -> CpuMem<'a> {
            CpuMem { words: self.buffers[binding], writable: self.read_only & (1 << binding) == 0 }
        }
    }
}
#[cfg(not(target_arch = "spirv"))]
pub use cpu::{CpuDispatch, CpuGroup, CpuMem};

#[cfg(target_arch = "spirv")]
mod gpu {
    use super::{Combine, Group, Load, Mem, WordOp};
    use spirv_std::arch::{atomic_i_add, atomic_u_max, control_barrier};
    use spirv_std::memory::{Scope, Semantics};

    /// The invocation's view of its workgroup on the GPU.
    pub struct GpuGroup {
        pub size: u32,
        pub local_index: u32,
        pub workgroup_id: [u32; 3],
        pub num_workgroups: [u32; 3],
    }

    impl Group for GpuGroup {
        #[inline]
        fn size(&self) -> u32 {
            self.size
        }
        #[inline]
        fn workgroup_id(&self) -> [u32; 3] {
            self.workgroup_id
        }
        #[inline]
        fn num_workgroups(&self) -> [u32; 3] {
            self.num_workgroups
        }
        #[inline]
        fn each(&mut self, mut f: impl FnMut(u32)) {
            f(self.local_index);
            control_barrier::<
                { Scope::Workgroup as u32 },
                { Scope::Workgroup as u32 },
                { Semantics::WORKGROUP_MEMORY.bits() | Semantics::UNIFORM_MEMORY.bits() | Semantics::ACQUIRE_RELEASE.bits() },
            >();
        }
        #[inline]
        fn invocations(&self) -> core::ops::Range<u32> {
            self.local_index..self.local_index + 1
        }
    }

    /// The invocation's view of its workgroup in a kernel built with subgroup operations: as
    /// [`GpuGroup`], and its place among the subgroups (the `SubgroupSize`, `NumSubgroups`,
    /// `SubgroupId` and `SubgroupLocalInvocationId` built-ins).
    pub struct GpuSubgroupGroup {
        pub group: GpuGroup,
        pub subgroup_size: u32,
        pub num_subgroups: u32,
        pub subgroup_id: u32,
        pub lane: u32,
    }

    impl GpuSubgroupGroup {
        /// The position this invocation runs in `each_combined`: subgroup-major,
        /// whatever the local id (Vulkan does not tie one to the other).
        #[inline]
        fn position(&self) -> u32 {
            self.subgroup_id * self.subgroup_size + self.lane
        }
    }

    impl Group for GpuSubgroupGroup {
        #[inline]
        fn size(&self) -> u32 {
            self.group.size
        }
        #[inline]
        fn workgroup_id(&self) -> [u32; 3] {
            self.group.workgroup_id
        }
        #[inline]
        fn num_workgroups(&self) -> [u32; 3] {
            self.group.num_workgroups
        }
        #[inline]
        fn each(&mut self, f: impl FnMut(u32)) {
            self.group.each(f);
        }
        #[inline]
        fn invocations(&self) -> core::ops::Range<u32> {
            self.group.invocations()
        }
        #[inline]
        fn subgroup_size(&self) -> Option<u32> {
            let s = self.subgroup_size;
            // Whole subgroups only: then positions cover the workgroup once.
            if s >= 2 && s & (s - 1) == 0 && self.num_subgroups * s == self.group.size { Some(s) } else { None }
        }
        #[inline]
        fn each_combined<O: WordOp, D: ?Sized>(
            &mut self,
            op: O,
            combine: Combine,
            data: &mut D,
            mut input: impl FnMut(&D, u32) -> u32,
            mut output: impl FnMut(&mut D, u32, u32),
        ) {
            let p = self.position();
            let v = input(data, p);
            let x = match combine {
                Combine::Scan => op.subgroup_inclusive(v, self.lane, self.subgroup_size),
                Combine::Reduce => op.subgroup_reduce(v),
            };
            output(data, p, x);
            self.group.each(|_| {});
        }
    }

    pub struct GpuMem<'a>(pub &'a mut [u32]);

    /// A read-only storage buffer (declared `&[u32]`, so rust-gpu marks it non-writable).
    pub struct GpuRead<'a>(pub &'a [u32]);

    impl Load for GpuRead<'_> {
        #[inline]
        fn len(&self) -> u32 {
            self.0.len() as u32
        }
        #[inline]
        fn load(&self, i: u32) -> u32 {
            self.0[i as usize]
        }
    }

    impl Load for GpuMem<'_> {
        #[inline]
        fn len(&self) -> u32 {
            self.0.len() as u32
        }
        #[inline]
        fn load(&self, i: u32) -> u32 {
            self.0[i as usize]
        }
    }

    impl Mem for GpuMem<'_> {
        #[inline]
        fn store(&mut self, i: u32, v: u32) {
            self.0[i as usize] = v;
        }
        #[inline]
        fn atomic_add(&mut self, i: u32, v: u32) -> u32 {
            unsafe { atomic_i_add::<u32, { Scope::QueueFamily as u32 }, { Semantics::NONE.bits() }>(&mut self.0[i as usize], v) }
        }
        #[inline]
        fn atomic_max(&mut self, i: u32, v: u32) -> u32 {
            unsafe { atomic_u_max::<u32, { Scope::QueueFamily as u32 }, { Semantics::NONE.bits() }>(&mut self.0[i as usize], v) }
        }
    }
}
#[cfg(target_arch = "spirv")]
pub use gpu::{GpuGroup, GpuMem, GpuRead, GpuSubgroupGroup};
