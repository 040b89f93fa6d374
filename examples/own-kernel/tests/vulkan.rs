//! The kernel on Vulkan (validation on) against the CPU backend. Vulkan is required: no skipping.

use own_kernel::{add_to, histogram, sample};

#[test]
fn histogram_on_vulkan_matches_the_cpu() -> dof_core::Result<()> {
    let mut vulkan = dof_core::VulkanBackend::new(&dof_core::VulkanOptions { validation: true, ..Default::default() })?;
    add_to(&mut vulkan)?;
    // Added twice: refused, the entry point is taken.
    let err = add_to(&mut vulkan).unwrap_err();
    assert!(err.to_string().contains("already added"), "{err}");
    // The whole build output holds dof-shaders' entry points too: refused, naming one.
    let err = vulkan.add_modules(own_kernel::MODULES).unwrap_err();
    assert!(err.to_string().contains("the project's kernels already have"), "{err}");
    let mut cpu = dof_core::CpuBackend::new();
    for (n, bins) in [(1, 3), (4097, 10), (300_000, 256)] {
        let values = sample(n);
        assert_eq!(histogram(&mut vulkan, &values, bins)?, histogram(&mut cpu, &values, bins)?, "{n} words, {bins} bins");
    }
    assert_eq!(vulkan.validation_messages(), Vec::<String>::new());
    Ok(())
}
