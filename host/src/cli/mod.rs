pub mod bench;
pub mod bench_frame;
pub mod bench_ratios;
pub mod bench_scaling;
pub mod compare;
pub mod eval;
pub mod heap;
pub mod info;
pub mod render;
pub mod scenes;
pub mod soak;
pub mod stress;
#[cfg(feature = "view")]
pub mod view;

use dof::backend::{Backend, CpuBackend, VulkanBackend, VulkanOptions};

/// The names of the frame API's methods (its registry), as a flag's possible values.
pub fn method_names() -> clap::builder::PossibleValuesParser {
    clap::builder::PossibleValuesParser::new(dof::frame::METHODS.iter().map(|m| clap::builder::PossibleValue::new(m.name).help(m.title)))
}

/// Which backends a command runs on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum BackendChoice {
    Cpu,
    Vulkan,
    #[default]
    Both,
}

/// The backends `choice` names. Vulkan failing to start is an error when asked for alone, and a
/// printed note (with the reason and the fix) when `both` was asked for.
pub fn backends(choice: BackendChoice, validation: bool) -> anyhow::Result<Vec<Box<dyn Backend>>> {
    let mut out: Vec<Box<dyn Backend>> = Vec::new();
    if choice != BackendChoice::Vulkan {
        out.push(Box::new(CpuBackend::new()));
    }
    if choice != BackendChoice::Cpu {
        match VulkanBackend::new(&VulkanOptions { validation, ..Default::default() }) {
            Ok(vk) => out.push(Box::new(vk)),
            Err(e) if choice == BackendChoice::Both => eprintln!("note: Vulkan backend unavailable, CPU only: {e}"),
            Err(e) => return Err(e.into()),
        }
    }
    Ok(out)
}
