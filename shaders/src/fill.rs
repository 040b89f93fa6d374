//! One value written over a range of words: the `fill` command where a command encoder clears to
//! zero only (wgpu). The Vulkan and CPU backends fill natively.

use crate::exec::{Group, Mem};

pub const THREADS: u32 = 256;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct FillParams {
    /// The first word.
    pub offset: u32,
    /// How many words.
    pub words: u32,
    pub value: u32,
}

/// Each invocation writes every `THREADS · num_workgroups`-th word from its own.
pub fn fill_pass<G: Group, M: Mem>(g: &mut G, p: &FillParams, mut data: M) {
    let stride = THREADS * g.num_workgroups()[0];
    let first = g.workgroup_id()[0] * THREADS;
    g.each(|lid| {
        let mut i = first + lid;
        while i < p.words {
            data.store(p.offset + i, p.value);
            i += stride;
        }
    });
}

kernel!(
    /// `data[offset .. offset + words] = value`.
    FILL = fill_words [256] (FillParams) { data } => fill_pass
);

#[cfg(not(target_arch = "spirv"))]
pub const KERNELS: [&crate::KernelDesc; 1] = [&FILL];
