//! A kernel of this crate's own, written like the project's (see `dof_shaders::exec` and
//! `dof_shaders::kernel`): a histogram of the caller's words.
//!
//! `kernel!` makes, from one declaration, the `#[spirv(compute)]` entry point (when rust-gpu compiles
//! this crate: the build script of `own-kernel`) and, on the host, the [`HISTOGRAM`] descriptor with
//! its CPU entry. Its SPIR-V entry point is `histogram` (rust-gpu names entry points by their path
//! without the crate name), which must not be one of dof's own.
#![cfg_attr(target_arch = "spirv", no_std)]

use dof_shaders::exec::{Group, Load, Mem};
use dof_shaders::kernel;

/// The push constants: `len` words of `values`, counted into `bins` bins by `value % bins`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub struct HistogramParams {
    pub len: u32,
    pub bins: u32,
}

/// Invocations per workgroup.
pub const THREADS: u32 = 64;

/// The body: a grid-stride loop over the words, one atomic add per word into `counts` (which the
/// caller zeroes). Any number of workgroups covers any length.
pub fn histogram_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &HistogramParams, values: R, mut counts: M) {
    let stride = g.num_workgroups()[0] * THREADS;
    let first = g.workgroup_id()[0] * THREADS;
    let bins = if p.bins == 0 { 1 } else { p.bins };
    g.each(|lid| {
        let mut i = first + lid;
        while i < p.len {
            counts.atomic_add(values.load(i) % bins, 1);
            i += stride;
        }
    });
}

kernel!(
    /// Counts `values` into `counts` (`value % bins`), adding to what `counts` holds.
    HISTOGRAM = histogram [64] (HistogramParams) { read values, counts } => histogram_pass
);

/// This crate's kernels: what the host hands to Vulkan (the SPIR-V build also holds dof-shaders' own
/// entry points, compiled in as a dependency, which the backend already has).
#[cfg(not(target_arch = "spirv"))]
pub static KERNELS: &[&dof_shaders::KernelDesc] = &[&HISTOGRAM];
