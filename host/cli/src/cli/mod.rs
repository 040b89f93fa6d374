pub mod bench;
pub mod bench_frame;
pub mod bench_kernels;
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

use dof::backend::{Backend, CpuBackend, Subgroups, VulkanBackend, VulkanOptions};

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

/// The CPU backend, running the kernels' subgroup variants unless `DOF_SUBGROUPS=off` (which the
/// GPU backends read too).
pub fn cpu_backend() -> anyhow::Result<CpuBackend> {
    let mut cpu = CpuBackend::new();
    if !Subgroups::Auto.resolve(true)? {
        cpu.set_subgroup_size(None)?;
    }
    Ok(cpu)
}

/// The backends `choice` names. Vulkan failing to start is an error when asked for alone, and a
/// printed note (with the reason and the fix) when `both` was asked for.
pub fn backends(choice: BackendChoice, validation: bool) -> anyhow::Result<Vec<Box<dyn Backend>>> {
    let mut out: Vec<Box<dyn Backend>> = Vec::new();
    if choice != BackendChoice::Vulkan {
        out.push(Box::new(cpu_backend()?));
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

/// Most samples per pixel any command takes (`--samples`, `--spp`, `--reference-spp`,
/// `--max-spp`, `--accumulation`): 65536 per pixel of a 640x360 reference is already hours of work
/// on two cores.
pub const MAX_SAMPLES: u32 = dof::scene::MAX_SPP;
/// Most timed runs any command takes (`--runs`).
pub const MAX_RUNS: usize = 1000;

/// Refuses a count outside `min..=max`, naming the flag and the bounds.
pub fn check_count<T: PartialOrd + std::fmt::Display>(flag: &str, what: &str, value: T, min: T, max: T) -> anyhow::Result<()> {
    if value < min || value > max {
        anyhow::bail!("{flag} ({what}) must lie between {min} and {max}, got {value}");
    }
    Ok(())
}

/// Refuses a list naming one thing twice (the work would be repeated), naming the flag and the
/// duplicate.
pub fn check_no_duplicates(flag: &str, values: &[String]) -> anyhow::Result<()> {
    for (i, v) in values.iter().enumerate() {
        if values[..i].contains(v) {
            anyhow::bail!("{flag} names `{v}` twice; give each once");
        }
    }
    Ok(())
}

/// Refuses, before any work, a name that is not a built-in scene (with the list of them).
pub fn check_builtin_scenes(flag: &str, names: &[String]) -> anyhow::Result<()> {
    let known = dof::scene::builtin_names();
    if let Some(unknown) = names.iter().find(|n| !known.contains(&n.as_str())) {
        anyhow::bail!("{flag}: unknown built-in scene `{unknown}`; the built-in scenes are: {}", known.join(", "));
    }
    Ok(())
}
