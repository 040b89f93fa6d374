//! `dof bench scaling`: time and peak memory of every method against resolution and against the
//! largest CoC (see `dof::eval::scaling`), written as JSON, markdown and plots.

use super::{BackendChoice, MAX_RUNS, backends, check_count};
use anyhow::Context;
use dof::eval::scaling::{DEFAULT_BUDGET_S, ScalingOptions, scaling};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct ScalingArgs {
    #[arg(long, value_enum, default_value_t)]
    backend: BackendChoice,
    /// A built-in scene; the blur scales with the image.
    #[arg(long, default_value = "railing")]
    scene: String,
    /// Frame sizes of the resolution series, WxH, comma-separated (default 640x360,1280x720,1920x1080);
    /// `none` for no resolution series.
    #[arg(long, value_delimiter = ',')]
    sizes: Vec<String>,
    /// Largest CoC radii (px, comma-separated) of the blur series (default 4,8,16,32,64,96); `none`
    /// for no blur series.
    #[arg(long, value_delimiter = ',')]
    cocs: Vec<String>,
    /// Frame size of the blur series, WxH.
    #[arg(long, default_value = "640x360")]
    coc_size: String,
    /// Methods (comma-separated); default every method that runs kernels.
    #[arg(long, value_delimiter = ',')]
    methods: Vec<String>,
    /// Timed runs per point after a warm-up (the median is reported).
    #[arg(long, default_value_t = 3)]
    runs: usize,
    /// Seconds a run may take; once a point is over it, the larger points of that method's series
    /// on that backend are skipped (and reported as skipped), as is a point whose time,
    /// extrapolated from the smaller ones, is over 3 budgets.
    #[arg(long, default_value_t = DEFAULT_BUDGET_S)]
    budget_s: f64,
    /// Folder for scaling.json, scaling.md and the plots.
    #[arg(long, default_value = "out/scaling")]
    out: PathBuf,
    /// Print the JSON on stdout instead of the markdown.
    #[arg(long)]
    json: bool,
    /// Leave out the plots (they need a TrueType font).
    #[arg(long)]
    no_plots: bool,
}

fn parse_size(s: &str) -> anyhow::Result<(u32, u32)> {
    let parsed = s.split_once(['x', 'X']).and_then(|(w, h)| Some((w.trim().parse().ok()?, h.trim().parse().ok()?)));
    parsed.with_context(|| format!("a size is WIDTHxHEIGHT in pixels, such as 1280x720; got `{s}`"))
}

fn is_none(values: &[String]) -> bool {
    values.iter().any(|v| v == "none")
}

pub fn run(args: &ScalingArgs) -> anyhow::Result<()> {
    if args.out.exists() && !args.out.is_dir() {
        anyhow::bail!("--out {} is a file; name a folder for the results", args.out.display());
    }
    check_count("--runs", "timed runs", args.runs, 1, MAX_RUNS)?;
    if !(args.budget_s > 0.0 && args.budget_s.is_finite()) {
        anyhow::bail!("--budget-s must be a positive number of seconds, got {}", args.budget_s);
    }
    let defaults = ScalingOptions::new(false);
    let sizes = match &args.sizes {
        v if v.is_empty() => defaults.sizes,
        v if is_none(v) => Vec::new(),
        v => v.iter().map(|s| parse_size(s)).collect::<anyhow::Result<_>>().context("--sizes")?,
    };
    let cocs = match &args.cocs {
        v if v.is_empty() => defaults.cocs,
        v if is_none(v) => Vec::new(),
        v => v
            .iter()
            .map(|s| s.trim().parse::<f64>().map_err(|_| anyhow::anyhow!("--cocs takes radii in pixels (or `none`), got `{s}`")))
            .collect::<anyhow::Result<_>>()?,
    };
    let options = ScalingOptions {
        scene: args.scene.clone(),
        sizes,
        cocs,
        coc_size: parse_size(&args.coc_size).context("--coc-size")?,
        methods: args.methods.clone(),
        runs: args.runs,
        budget_s: args.budget_s,
        progress: true,
    };
    if !args.no_plots {
        // Before the long run, so a missing font is reported at once.
        dof::eval::plot::ensure_font().context("the plots need a font; pass --no-plots to leave them out")?;
    }
    std::fs::create_dir_all(&args.out).with_context(|| format!("cannot create {}", args.out.display()))?;
    let mut backends = backends(args.backend, false)?;
    let report = scaling(&options, &mut backends)?;
    let files = report.write(&args.out, !args.no_plots)?;
    if args.json {
        println!("{}", report.to_json());
    } else {
        println!("{}", report.to_markdown());
    }
    let names: Vec<String> = files.iter().filter_map(|f| Some(f.file_name()?.to_string_lossy().into_owned())).collect();
    eprintln!("wrote {} files in {}: {}", files.len(), args.out.display(), names.join(", "));
    Ok(())
}
