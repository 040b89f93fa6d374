//! `dof bench kernels`: the GPU shape of every embedded kernel, read from its SPIR-V with no GPU
//! ([`dof::kernel_shape`]): instructions, per-invocation (function-storage) memory and its run-time
//! indexing, workgroup memory, barriers, integer divisions, subgroup operations and bounds checks.
//! The numbers a GPU's compiler turns into local-memory traffic, occupancy and latency; CI holds
//! the hot kernels to budgets (`tests/tests/gpu_shape.rs`).

use anyhow::Context;
use dof::backend::{Backend, VulkanBackend, VulkanOptions};
use dof::kernel_shape::{KernelShape, analyze};
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct KernelsArgs {
    /// One JSON object a line per kernel instead of the table.
    #[arg(long)]
    json: bool,
    /// Only the entry points whose name contains this text (for example `splat`).
    #[arg(long)]
    only: Option<String>,
    /// Read the modules of another build instead of the embedded ones: a folder laid out as
    /// `host/spirv/` (its `manifest.txt` names a file per entry point), for example an earlier
    /// commit's, to compare a kernel change before and after.
    #[arg(long)]
    dir: Option<PathBuf>,
    /// Also what the Vulkan device's driver reports of each kernel's pipeline (registers, spills
    /// and the like; VK_KHR_pipeline_executable_properties), for the embedded kernels: one JSON
    /// object a line per statistic. Refused on a device that does not report them (lavapipe).
    #[arg(long)]
    device: bool,
}

/// The modules to read: the embedded ones, or those `dir`'s manifest names.
fn modules(dir: Option<&Path>) -> anyhow::Result<Vec<(String, Vec<u32>)>> {
    let Some(dir) = dir else {
        return Ok(dof::shaders::MODULES
            .iter()
            .filter_map(|(entry, _)| Some((entry.to_string(), dof::shaders::module_words(entry)?)))
            .collect());
    };
    let manifest = dir.join("manifest.txt");
    let text = std::fs::read_to_string(&manifest).with_context(|| format!("reading {}", manifest.display()))?;
    let mut modules = Vec::new();
    for line in text.lines() {
        if let ["module", entry, file] = line.split_whitespace().collect::<Vec<_>>().as_slice() {
            let path = dir.join(file);
            let bytes = std::fs::read(&path).with_context(|| format!("reading {}", path.display()))?;
            if bytes.len() % 4 != 0 {
                anyhow::bail!("{}: {} bytes is not a whole number of SPIR-V words", path.display(), bytes.len());
            }
            modules.push((entry.to_string(), bytes.as_chunks::<4>().0.iter().map(|c| u32::from_le_bytes(*c)).collect()));
        }
    }
    if modules.is_empty() {
        anyhow::bail!("{} names no module (lines `module ENTRY FILE`)", manifest.display());
    }
    Ok(modules)
}

/// The shape of every module of `dir` (default: the embedded ones) whose entry contains `only`.
pub fn shapes(dir: Option<&Path>, only: Option<&str>) -> anyhow::Result<Vec<KernelShape>> {
    let mut shapes = Vec::new();
    for (entry, words) in modules(dir)? {
        if only.is_some_and(|text| !entry.contains(text)) {
            continue;
        }
        shapes.push(analyze(&words).map_err(|e| anyhow::anyhow!("the SPIR-V of {entry}: {e}"))?);
    }
    Ok(shapes)
}

/// The driver's statistics of every embedded kernel whose entry contains `only`, a JSON object a
/// line.
fn device_statistics(only: Option<&str>) -> anyhow::Result<()> {
    let mut vk = VulkanBackend::new(&VulkanOptions { pipeline_statistics: true, ..Default::default() })?;
    let device = vk.device_name();
    for kernel in dof_shaders::all_kernels().filter(|k| only.is_none_or(|text| k.entry.contains(text))) {
        for s in vk.pipeline_statistics(kernel)? {
            println!(
                "{}",
                serde_json::json!({
                    "device": device, "entry": kernel.entry, "executable": s.executable, "statistic": s.name,
                    "value": s.value, "description": s.description,
                })
            );
        }
    }
    Ok(())
}

pub fn run(args: &KernelsArgs) -> anyhow::Result<()> {
    if args.device {
        if args.dir.is_some() {
            anyhow::bail!("--device reads the embedded kernels' pipelines: leave out --dir");
        }
        return device_statistics(args.only.as_deref());
    }
    let shapes = shapes(args.dir.as_deref(), args.only.as_deref())?;
    if shapes.is_empty() {
        anyhow::bail!("no embedded kernel's name contains {:?}", args.only.as_deref().unwrap_or_default());
    }
    if args.json {
        for shape in &shapes {
            println!("{}", shape.to_json());
        }
        return Ok(());
    }
    println!(
        "{:<44} {:>6} {:>8} {:>7} {:>9} {:>8} {:>4} {:>5} {:>5} {:>5} {:>6}",
        "kernel", "instr", "fn bytes", "fn idx", "wg bytes", "barriers", "div", "rtdiv", "subgr", "atom", "checks"
    );
    for s in &shapes {
        println!(
            "{:<44} {:>6} {:>8} {:>7} {:>9} {:>8} {:>4} {:>5} {:>5} {:>5} {:>6}",
            s.entry,
            s.instructions,
            s.function_bytes,
            s.runtime_indexed,
            s.workgroup_bytes,
            s.barriers,
            s.integer_divisions,
            s.runtime_divisions,
            s.subgroup_ops,
            s.atomics,
            s.bounds_checks
        );
    }
    println!(
        "\nfn bytes: function-storage (per-invocation) memory, summed over the module's variables; fn idx: its accesses \
         with a run-time index (local memory on a GPU); barriers: in the code, not as executed; div: integer divisions \
         and remainders, rtdiv those by a run-time value; checks: slice bounds checks"
    );
    Ok(())
}
