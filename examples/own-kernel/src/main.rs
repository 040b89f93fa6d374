//! Runs this crate's own kernel on the CPU backend and on Vulkan (validation on) and checks that both
//! give plain Rust's histogram. Fails where Vulkan or its validation layer is missing.

use own_kernel::{add_to, histogram, histogram_reference, sample};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let (values, bins) = (sample(1 << 20), 64);
    let want = histogram_reference(&values, bins);
    let cpu = histogram(&mut dof_core::CpuBackend::new(), &values, bins)?;
    if cpu != want {
        return Err("the CPU backend's histogram is not plain Rust's".into());
    }
    let mut vulkan = dof_core::VulkanBackend::new(&dof_core::VulkanOptions { validation: true, ..Default::default() })?;
    add_to(&mut vulkan)?;
    let gpu = histogram(&mut vulkan, &values, bins)?;
    let messages = vulkan.validation_messages();
    println!(
        "{} words into {bins} bins on the CPU backend and on {}: {}",
        values.len(),
        vulkan.info().name,
        if gpu == cpu { "same counts" } else { "DIFFERENT counts" }
    );
    if !messages.is_empty() {
        return Err(format!("validation messages: {messages:#?}").into());
    }
    if gpu != cpu {
        return Err("Vulkan's histogram is not the CPU backend's".into());
    }
    Ok(())
}
