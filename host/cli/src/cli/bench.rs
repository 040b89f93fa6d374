//! `dof bench`: kernel throughput on each backend, as ratios to a CPU reference measured in the same run.

use super::{BackendChoice, MAX_RUNS, backends, check_count};
use dof::backend::with_buffers;
use dof::ops::sort::{SegmentedSort, SortInput};
use dof::timing::{RunTimes, median};
use dof::workload;
use std::time::Instant;

#[derive(clap::Subcommand)]
pub enum BenchCommand {
    /// Segmented depth sort of tile lists shaped like Franke et al. 2018, Fig. 12.
    Sort(SortArgs),
    /// One splatting frame after another through the frame API: record time, device time per
    /// stage, context memory, and allocations, submissions and readbacks per frame.
    Frame(super::bench_frame::FrameArgs),
    /// Time and peak memory of every method against resolution and against the largest CoC, on
    /// `railing` with the blur scaled with the image: JSON, markdown and plots.
    Scaling(super::bench_scaling::ScalingArgs),
    /// Multi-layer tiled splatting (merged 4x4) over the engine-grade gather (5 rings), per
    /// built-in scene and backend, with each one's error against the exact reference.
    Ratios(super::bench_ratios::RatiosArgs),
    /// The GPU shape of every embedded kernel, read from its SPIR-V without a GPU: instructions,
    /// per-invocation memory and its run-time indexing, workgroup memory, barriers, divisions,
    /// subgroup operations.
    Kernels(super::bench_kernels::KernelsArgs),
}

#[derive(clap::Args)]
pub struct SortArgs {
    /// Number of tile lists (3600 = 1280x720 in 16x16 tiles).
    #[arg(long, default_value_t = 3600)]
    tiles: usize,
    /// Longest list; lists above the device's largest workgroup-memory class take the global path.
    #[arg(long, default_value_t = 8192)]
    max_len: u32,
    /// Timed runs per backend (after one warm-up); the median is reported.
    #[arg(long, default_value_t = 5)]
    runs: usize,
    #[arg(long, value_enum, default_value_t)]
    backend: BackendChoice,
    #[arg(long, default_value_t = 1)]
    seed: u64,
}

pub fn run(cmd: &BenchCommand) -> anyhow::Result<()> {
    match cmd {
        BenchCommand::Sort(args) => sort(args),
        BenchCommand::Frame(args) => super::bench_frame::run(args),
        BenchCommand::Scaling(args) => super::bench_scaling::run(args),
        BenchCommand::Ratios(args) => super::bench_ratios::run(args),
        BenchCommand::Kernels(args) => super::bench_kernels::run(args),
    }
}

/// The reference every backend is compared with: `slice::sort_unstable_by` on each list, one thread.
fn std_sort_ms(input: &SortInput, runs: usize) -> f64 {
    let times = (0..runs)
        .map(|_| {
            let mut keys = input.keys.clone();
            let start = Instant::now();
            for &(o, l) in &input.segments {
                keys[o as usize..(o + l) as usize].sort_unstable_by(f32::total_cmp);
            }
            std::hint::black_box(&keys);
            start.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    median(times)
}

/// Most tile lists `bench sort` makes: 2^20, a 16384x16384 image in 16x16 tiles (about 10^9 keys,
/// 40 GB of host memory: refused where the machine has less free).
const MAX_TILES: usize = 1 << 20;
/// Longest list it makes: 2^20 entries.
const MAX_LIST: u32 = 1 << 20;
/// A list's mean length in `workload::tile_lists` (exp(ln 700 + 0.8²/2) ≈ 964), rounded up.
const MEAN_LIST: u32 = 1000;
/// Host bytes a key takes in `bench sort` (see `sort`).
const KEY_BYTES: u128 = 40;

fn sort(args: &SortArgs) -> anyhow::Result<()> {
    if args.tiles == 0 || args.tiles > MAX_TILES {
        anyhow::bail!("--tiles must lie between 1 and {MAX_TILES}, got {}", args.tiles);
    }
    if args.max_len == 0 || args.max_len > MAX_LIST {
        anyhow::bail!("--max-len must lie between 1 and {MAX_LIST}, got {}", args.max_len);
    }
    check_count("--runs", "timed runs", args.runs, 1, MAX_RUNS)?;
    // Lists average about 960 keys (log-normal about 700, `workload::tile_lists`), at most
    // --max-len. Each key is held by the input (key and value), the reference's copy, its bits for
    // the upload, and four buffers of the backend: about 40 bytes.
    let keys = args.tiles as u128 * args.max_len.min(MEAN_LIST) as u128;
    let what = format!("bench sort with --tiles {} --max-len {} (about {keys} keys)", args.tiles, args.max_len);
    dof::memory::check_fits(&what, keys * KEY_BYTES, dof::memory::available())?;
    let input = workload::tile_lists(args.tiles, args.max_len, args.seed);
    let n = input.keys.len();
    anyhow::ensure!(n <= u32::MAX as usize, "{what}: {n} keys, beyond the 2^32 a sort takes");
    let std_ms = std_sort_ms(&input, args.runs);
    let mut hist = [0usize; 8];
    for &(_, l) in &input.segments {
        hist[(l.max(1).ilog2() as usize / 2).min(7)] += 1;
    }
    println!(
        "{} lists, {} keys (mean list {:.0}, longest {}); list lengths by power of four from 1: {:?}",
        input.segments.len(),
        n,
        n as f64 / input.segments.len().max(1) as f64,
        input.max_list_len(),
        hist
    );
    println!("std sort_unstable_by (1 thread): {std_ms:.2} ms, {:.1} Mkeys/s", n as f64 / std_ms / 1e3);
    let key_bits: Vec<u32> = input.keys.iter().map(|k| k.to_bits()).collect();
    let seg: Vec<u32> = input.segments.iter().flat_map(|&(o, l)| [o, l]).collect();
    let lists = input.segments.len() as u32;
    let sizes = [
        (seg.len() as u64, "bench/segments"),
        (n as u64, "bench/keys-in"),
        (n as u64, "bench/values-in"),
        (n as u64, "bench/keys-out"),
        (n as u64, "bench/values-out"),
    ];
    for mut backend in backends(args.backend, false)? {
        with_buffers(backend.as_mut(), &sizes, |b, buf| {
            let (segments, keys_in, values_in, keys_out, values_out) = (buf[0], buf[1], buf[2], buf[3], buf[4]);
            b.write_buffer(segments, 0, &seg)?;
            b.write_buffer(keys_in, 0, &key_bits)?;
            b.write_buffer(values_in, 0, &input.values)?;
            let sort = SegmentedSort::new(b, lists, n as u32, input.max_list_len())?;
            let mut times = RunTimes::default();
            let mut wall_ms = Vec::new();
            // Run 0 is the warm-up: pipeline creation, first touch of memory.
            for run in 0..=args.runs {
                let start = Instant::now();
                sort.record(b, segments, lists, keys_in, values_in, keys_out, values_out)?;
                let commands = b.submit()?;
                if run > 0 {
                    wall_ms.push(start.elapsed().as_secs_f64() * 1e3);
                    times.add(&commands);
                }
            }
            let stats = sort.stats(b);
            sort.destroy(b);
            let stats = stats?;
            let device = times.median_total();
            println!(
                "{:>6} on {}: {:.2} ms in kernels ({:.2} ms wall), {:.1} Mkeys/s, {:.2}x std sort; lists per class {:?} (largest class {}), {} on the global path",
                b.kind().to_string(),
                b.device_name(),
                device,
                median(wall_ms),
                n as f64 / device / 1e3,
                std_ms / device,
                dof_shaders::sort::CLASS_CAPS.iter().zip(&stats.class_counts).filter(|(_, c)| **c > 0).collect::<Vec<_>>(),
                stats.top_class_cap,
                stats.global_lists
            );
            for (stage, ms) in times.median_stages() {
                println!("         {stage:<22} {ms:8.3} ms");
            }
            Ok(())
        })?;
    }
    Ok(())
}
