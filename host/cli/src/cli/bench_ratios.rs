//! `dof bench ratios`: multi-layer tiled splatting over the engine-grade gather, per built-in scene
//! and backend in one run, with each one's error against the exact reference (see
//! `dof::eval::ratios`), written as JSON and markdown.

use super::{BackendChoice, MAX_RUNS, MAX_SAMPLES, backends, check_builtin_scenes, check_count, check_no_duplicates};
use anyhow::Context;
use dof::eval::ratios::{RatioOptions, ratios, to_markdown};
use dof::scene::builtin_names;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct RatiosArgs {
    #[arg(long, value_enum, default_value_t)]
    backend: BackendChoice,
    /// Built-in scenes (comma-separated); default every one.
    #[arg(long, value_delimiter = ',')]
    scenes: Vec<String>,
    #[arg(long, default_value_t = 1280)]
    width: u32,
    #[arg(long, default_value_t = 720)]
    height: u32,
    /// Samples per pixel of the exact reference.
    #[arg(long, default_value_t = 64)]
    spp: u32,
    /// Timed runs per method and backend after a warm-up (the median is reported).
    #[arg(long, default_value_t = 3)]
    runs: usize,
    /// Folder for ratios.json and ratios.md.
    #[arg(long, default_value = "out/ratios")]
    out: PathBuf,
    /// Print the JSON on stdout instead of the markdown.
    #[arg(long)]
    json: bool,
}

pub fn run(args: &RatiosArgs) -> anyhow::Result<()> {
    if args.out.exists() && !args.out.is_dir() {
        anyhow::bail!("--out {} is a file; name a folder for the results", args.out.display());
    }
    if args.width == 0 || args.height == 0 || args.width > 8192 || args.height > 8192 {
        anyhow::bail!("--width and --height are 1 to 8192 px, got {}x{}", args.width, args.height);
    }
    check_count("--spp", "samples per pixel of the reference", args.spp, 1, MAX_SAMPLES)?;
    check_count("--runs", "timed runs", args.runs, 1, MAX_RUNS)?;
    check_no_duplicates("--scenes", &args.scenes)?;
    check_builtin_scenes("--scenes", &args.scenes)?;
    let scenes = if args.scenes.is_empty() { builtin_names().iter().map(|s| s.to_string()).collect() } else { args.scenes.clone() };
    let options = RatioOptions { scenes, width: args.width, height: args.height, spp: args.spp, runs: args.runs, progress: !args.json };
    let mut backends = backends(args.backend, false)?;
    let rows = ratios(&options, &mut backends)?;
    let md = to_markdown(&rows, args.width, args.height);
    let json = serde_json::to_string_pretty(&rows)?;
    std::fs::create_dir_all(&args.out).with_context(|| format!("cannot create --out {}", args.out.display()))?;
    for (name, text) in [("ratios.json", &json), ("ratios.md", &md)] {
        let path = args.out.join(name);
        std::fs::write(&path, text).with_context(|| format!("cannot write {} (in --out)", path.display()))?;
    }
    if args.json {
        println!("{json}")
    } else {
        println!("{md}")
    }
    Ok(())
}
