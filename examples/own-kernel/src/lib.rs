//! Running a kernel of this crate's own (`own_kernel_shaders::HISTOGRAM`, declared with
//! `dof_shaders::kernel!` in `kernels/`) on dof-core's backends, over the caller's buffers.
//!
//! - CPU: the descriptor carries its CPU entry, so [`dof_core::CpuBackend`] runs it as it is.
//! - Vulkan: [`add_to`] hands this crate's SPIR-V ([`MODULES`], compiled by build.rs) to
//!   [`dof_core::VulkanBackend::add_modules`]; from then on the backend dispatches the kernel like its own.

use dof_core::backend::{Backend, RunKernel};
use own_kernel_shaders::{HistogramParams, histogram as histogram_kernel};

include!(concat!(env!("OUT_DIR"), "/own_modules.rs"));

/// This crate's own modules: rust-gpu's build of `kernels/` also holds an entry point for every
/// kernel of `dof_shaders` (a dependency), which the backend has already (and refuses to take again).
pub fn own_modules() -> Vec<(&'static str, &'static [u8])> {
    MODULES.iter().copied().filter(|(entry, _)| own_kernel_shaders::KERNELS.iter().any(|k| k.entry == *entry)).collect()
}

/// Adds this crate's kernels to a Vulkan backend (refused if one of their entry points is taken).
pub fn add_to(vulkan: &mut dof_core::VulkanBackend) -> dof_core::Result<()> {
    vulkan.add_modules(&own_modules())
}

/// The histogram of `values` (`value % bins`) through the kernel on `backend`: the values in a
/// buffer of the caller's, the counts in another, both made, used and destroyed here.
pub fn histogram(backend: &mut dyn Backend, values: &[u32], bins: u32) -> dof_core::Result<Vec<u32>> {
    let input = backend.create_buffer(values.len().max(1) as u64, "values")?;
    let counts = backend.create_buffer(bins.max(1) as u64, "counts")?;
    let result = (|| {
        backend.write_buffer(input, 0, values)?;
        // New buffers start zeroed on both backends: the kernel adds into `counts`.
        let params = HistogramParams { len: values.len() as u32, bins };
        let groups = (values.len() as u32).div_ceil(own_kernel_shaders::THREADS).clamp(1, 256);
        // The bindings by the names the kernel declares (`kernel!` generates `Bindings`).
        backend.run(histogram_kernel::Bindings { values: input, counts }, [groups, 1, 1], &params, "histogram")?;
        backend.submit()?;
        backend.read_buffer(counts, 0, bins as u64)
    })();
    backend.destroy_buffer(input);
    backend.destroy_buffer(counts);
    result
}

/// The histogram by plain Rust, to check the kernel against.
pub fn histogram_reference(values: &[u32], bins: u32) -> Vec<u32> {
    let mut counts = vec![0; bins as usize];
    for v in values {
        counts[(v % bins) as usize] += 1;
    }
    counts
}

/// Test data: `n` pseudo-random words.
pub fn sample(n: usize) -> Vec<u32> {
    let mut x = 0x9e37_79b9u32;
    (0..n)
        .map(|_| {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            x
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The kernel as a CPU unit test: CPU backend against plain Rust, several lengths and bin counts.
    #[test]
    fn histogram_on_the_cpu_backend() -> dof_core::Result<()> {
        let mut cpu = dof_core::CpuBackend::new();
        for (n, bins) in [(0, 4), (1, 1), (63, 7), (1000, 16), (100_000, 256)] {
            let values = sample(n);
            assert_eq!(histogram(&mut cpu, &values, bins)?, histogram_reference(&values, bins), "{n} words, {bins} bins");
        }
        Ok(())
    }

    #[test]
    fn the_table_holds_the_kernel() {
        assert_eq!(own_modules().iter().map(|(e, _)| *e).collect::<Vec<_>>(), [own_kernel_shaders::HISTOGRAM.entry]);
    }
}
