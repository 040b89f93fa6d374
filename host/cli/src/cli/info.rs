//! `dof info`: what this machine offers and whether the kernels agree with their references on it.

use super::{BackendChoice, backends};
use dof::backend::vulkan;
use dof::ops::{scan, sort};
use dof::workload;
use rand::SeedableRng;

#[derive(clap::Args, Default)]
pub struct InfoArgs {
    /// Backends to self-check.
    #[arg(long, value_enum, default_value_t)]
    backend: BackendChoice,
    /// Run Vulkan with the Khronos validation layer (synchronization validation on).
    #[arg(long)]
    validation: bool,
}

pub fn run(args: &InfoArgs) -> anyhow::Result<()> {
    println!(
        "dof {} — kernels: {} entry points, SPIR-V modules {} bytes (source hash {})",
        env!("CARGO_PKG_VERSION"),
        dof_shaders::all_kernels().count(),
        dof::shaders::total_bytes(),
        &dof::shaders::SOURCE_HASH[..12]
    );
    match vulkan::list_devices() {
        Ok(devices) => {
            for d in devices {
                println!(
                    "vulkan device {}: {} ({}), Vulkan {}, driver {}\n  shared memory {} B, workgroup {} invocations, groups {:?}, subgroup {:?} ({}), max buffer {} MiB, timestamp period {} ns",
                    d.index,
                    d.name,
                    d.device_type,
                    d.api_version,
                    d.driver,
                    d.limits.max_shared_bytes,
                    d.limits.max_workgroup_invocations,
                    d.limits.max_workgroup_count,
                    d.limits.subgroup_size,
                    if d.limits.subgroup_kernels { "kernels scan in subgroups" } else { "no subgroup arithmetic: kernels scan without" },
                    d.limits.max_buffer_bytes >> 20,
                    d.timestamp_period_ns
                );
            }
        }
        Err(e) => println!("vulkan: unavailable: {e}"),
    }
    let mut failures = 0;
    for mut backend in backends(args.backend, args.validation)? {
        let b = backend.as_mut();
        let mut rng = rand_pcg::Pcg64::seed_from_u64(7);
        // A mix that touches every class the device has and the global path.
        let lengths = [0, 1, 2, 3, 63, 64, 65, 200, 1000, 3000, 4096, 4097, 9000, 20000];
        let input = workload::lists_with(&lengths, |_, _| workload::random_key(&mut rng));
        let out = sort::sort_on(b, &input)?;
        let (keys, values) = input.reference();
        let sort_ok = out.values == values && out.keys.iter().zip(&keys).all(|(a, b)| a.to_bits() == b.to_bits());
        let words: Vec<u32> = (0..100_000u32).map(|i| i.wrapping_mul(2654435761) >> 20).collect();
        let (scanned, total) = scan::exclusive_scan(b, &words)?;
        let mut acc = 0u32;
        let scan_ok = words.iter().zip(&scanned).all(|(&w, &s)| {
            let ok = s == acc;
            acc = acc.wrapping_add(w);
            ok
        }) && total == acc;
        println!(
            "{:>6} on {}: segmented sort {} ({} lists, largest class {}, {} on the global path), scan {}",
            backend.kind().to_string(),
            backend.device_name(),
            if sort_ok { "ok" } else { "MISMATCH" },
            lengths.len(),
            out.stats.top_class_cap,
            out.stats.global_lists,
            if scan_ok { "ok" } else { "MISMATCH" }
        );
        failures += (!sort_ok) as u32 + (!scan_ok) as u32;
        let diagnostics = backend.take_diagnostics();
        for d in &diagnostics {
            println!("  validation: {d}");
        }
        failures += diagnostics.len() as u32;
    }
    if failures > 0 {
        anyhow::bail!("{failures} self-check(s) failed");
    }
    Ok(())
}
