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
    use super::{Group, Load, Mem};
    use core::sync::atomic::{AtomicU32, Ordering::Relaxed};

    /// A workgroup emulated on one CPU thread: `each` loops over the local ids.
    pub struct CpuGroup {
        pub size: u32,
        pub workgroup_id: [u32; 3],
        pub num_workgroups: [u32; 3],
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
            for lid in 0..self.size {
                f(lid);
            }
        }
        #[inline]
        fn invocations(&self) -> core::ops::Range<u32> {
            0..self.size
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
    }

    impl<'a> CpuDispatch<'a> {
        #[inline]
        pub fn group(&self, size: u32) -> CpuGroup {
            CpuGroup { size, workgroup_id: self.workgroup_id, num_workgroups: self.num_workgroups }
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
    use super::{Group, Load, Mem};
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
pub use gpu::{GpuGroup, GpuMem, GpuRead};
