//! `dof eval`: error against run time for every method, setting, scene and backend.

use super::{BackendChoice, MAX_RUNS, backends, check_count, check_no_duplicates};
use anyhow::Context;
use dof::eval::{EvalOptions, evaluate};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct EvalArgs {
    /// Scenes (comma-separated): built-in names or glTF files (measured against their
    /// accumulation buffer); default all built-in scenes.
    #[arg(long, value_delimiter = ',')]
    scenes: Vec<String>,
    /// Methods (comma-separated); default all.
    #[arg(long, value_delimiter = ',')]
    methods: Vec<String>,
    #[arg(long, value_enum, default_value_t)]
    backend: BackendChoice,
    /// Small images, a 64-spp reference, fewer settings and runs (what CI runs).
    #[arg(long)]
    quick: bool,
    /// Timed runs per point (default 5, 3 with --quick).
    #[arg(long)]
    runs: Option<usize>,
    /// Largest CoC radii (px, comma-separated) of the max-CoC sweep on the first scene (as in
    /// Franke et al. 2018, Fig. 13), at 320x180 (160x90 with --quick); default 4,8,16,32 (4,16
    /// with --quick); `none` for no sweep.
    #[arg(long, value_delimiter = ',')]
    coc_sweep: Vec<String>,
    /// Also run the scaling sweep (time and peak memory against resolution, 640x360 to 1920x1080,
    /// and against the largest CoC, 4 to 96 px, on `railing`; 160x90 to 320x180 with --quick) and
    /// write it as scaling.json, scaling.md, plots and a section of report.md. Slow: see
    /// `dof bench scaling` for a sweep on its own.
    #[arg(long)]
    scaling: bool,
    /// With --scaling: seconds a run may take before the larger points of its series are skipped.
    #[arg(long, default_value_t = dof::eval::scaling::DEFAULT_BUDGET_S)]
    scaling_budget_s: f64,
    /// Leave out the plots (they need a TrueType font, see `dof::eval::plot`).
    #[arg(long)]
    no_plots: bool,
    /// Temporal stability instead: a focus pull on the first of --scenes (default `simple`; 64x36
    /// and 6 frames with --quick, else 160x90 and 12) through every method of the frame API (or
    /// those of --methods), one context each; per-frame PSNR and temporal PSNR (each frame-to-frame
    /// change against the reference's) in temporal.json, temporal.md and plots.
    #[arg(long)]
    temporal: bool,
    /// Sub-samples a pixel of the multi-layer images the methods run on: 1 (point-sampled), 4, 9
    /// or 16 (area-integrated; see docs/scenes-and-references.md).
    #[arg(long, visible_alias = "area-samples", default_value_t = dof::scene::DEFAULT_SUBSAMPLES)]
    subsamples: u32,
    /// Leave out the footprints of area-integrated fragments (which of a pixel's sub-samples saw
    /// each): splatting then spreads every fragment from its pixel's centre.
    #[arg(long)]
    no_footprints: bool,
    /// The built-in scenes' references integrate the light of their emissive spheres with samples
    /// aimed at each (converged at saturated bokeh rims, where uniform samples leave pixels dark by
    /// chance; see docs/scenes-and-references.md). Refused for scenes with translucent surfaces.
    #[arg(long)]
    aimed_emitters: bool,
    /// Image size of the built-in scenes (both or neither; default the scene's own, 160x90 with
    /// --quick).
    #[arg(long, requires = "height")]
    width: Option<u32>,
    #[arg(long, requires = "width")]
    height: Option<u32>,
    #[arg(long, default_value = "out/eval")]
    out: PathBuf,
}

/// The largest CoC radius the sweep takes: wider than the diagonal of any frame it renders
/// (320x180), and exact in f32, so the radius reported is the one asked for.
const MAX_SWEEP_RADIUS: f64 = 1024.0;

fn sweep_targets(args: &EvalArgs) -> anyhow::Result<Vec<f64>> {
    if args.coc_sweep.is_empty() {
        return Ok(dof::eval::default_coc_sweep(args.quick));
    }
    if args.coc_sweep.iter().any(|s| s == "none") {
        return Ok(Vec::new());
    }
    let radii: Vec<f64> = args
        .coc_sweep
        .iter()
        .map(|s| match s.parse::<f64>() {
            Ok(v) if v > 0.0 && v <= MAX_SWEEP_RADIUS => Ok(v),
            _ => anyhow::bail!("--coc-sweep takes radii in pixels above 0 and at most {MAX_SWEEP_RADIUS} (or `none`), got `{s}`"),
        })
        .collect::<anyhow::Result<_>>()?;
    for (i, r) in radii.iter().enumerate() {
        if radii[..i].contains(r) {
            anyhow::bail!("--coc-sweep names the radius {r} twice (`{}`); give each once", args.coc_sweep[i]);
        }
    }
    Ok(radii)
}

/// Every flag checked before any work: counts in range, no scene or method named twice, every
/// scene a built-in name or a glTF file that exists.
fn check_before_work(args: &EvalArgs) -> anyhow::Result<()> {
    if let Some(runs) = args.runs {
        check_count("--runs", "timed runs a point", runs, 1, MAX_RUNS)?;
    }
    if !(args.scaling_budget_s > 0.0 && args.scaling_budget_s.is_finite()) {
        anyhow::bail!("--scaling-budget-s must be a positive number of seconds, got {}", args.scaling_budget_s);
    }
    if !args.scaling && args.scaling_budget_s != dof::eval::scaling::DEFAULT_BUDGET_S {
        anyhow::bail!("--scaling-budget-s applies to the scaling sweep only; add --scaling");
    }
    dof::scene::check_subsamples(args.subsamples).map_err(|e| anyhow::anyhow!("--subsamples: {e}"))?;
    for (value, flag) in [(args.width, "--width"), (args.height, "--height")] {
        if let Some(v) = value.filter(|&v| v == 0 || v > 8192) {
            anyhow::bail!("{flag} must lie between 1 and 8192 px, got {v}");
        }
    }
    check_no_duplicates("--scenes", &args.scenes)?;
    check_no_duplicates("--methods", &args.methods)?;
    let known = dof::scene::builtin_names();
    for scene in &args.scenes {
        let lower = scene.to_ascii_lowercase();
        if lower.ends_with(".gltf") || lower.ends_with(".glb") {
            if !std::path::Path::new(scene).is_file() {
                anyhow::bail!("--scenes: the glTF file {scene} does not exist (or is not a file)");
            }
        } else if !known.contains(&scene.as_str()) {
            anyhow::bail!("--scenes: unknown scene `{scene}`; give a built-in scene ({}) or a .gltf/.glb file", known.join(", "));
        }
    }
    let methods: Vec<&str> = dof::eval::methods::evaluated_methods().iter().map(|m| m.name()).collect();
    if let Some(unknown) = args.methods.iter().find(|m| !methods.contains(&m.as_str())) {
        anyhow::bail!("--methods: unknown method `{unknown}`; the methods are: {}", methods.join(", "));
    }
    Ok(())
}

pub fn run(args: &EvalArgs) -> anyhow::Result<()> {
    if args.temporal {
        return run_temporal(args);
    }
    check_before_work(args)?;
    let coc_sweep = sweep_targets(args)?;
    // Before the long run: the output must be a folder that can be made.
    if args.out.exists() && !args.out.is_dir() {
        anyhow::bail!("--out {} is a file; name a folder for the report and plots", args.out.display());
    }
    std::fs::create_dir_all(&args.out).with_context(|| format!("cannot create --out {}", args.out.display()))?;
    let scenes =
        if args.scenes.is_empty() { dof::scene::builtin_names().iter().map(|s| s.to_string()).collect() } else { args.scenes.clone() };
    let options = EvalOptions {
        scenes,
        methods: args.methods.clone(),
        quick: args.quick,
        runs: args.runs.unwrap_or(if args.quick { 3 } else { 5 }),
        progress: true,
        coc_sweep,
        subsamples: args.subsamples,
        footprints: !args.no_footprints,
        aimed_emitters: args.aimed_emitters,
        size: args.width.zip(args.height),
    };
    if !args.no_plots {
        // Before the long run, so a missing font is reported at once.
        dof::eval::plot::ensure_font().context("the plots need a font; pass --no-plots to leave them out")?;
    }
    let mut backends = backends(args.backend, false)?;
    let mut report = evaluate(&options, &mut backends)?;
    // Host-only methods take no device time; the sweep leaves them out.
    let kernel_methods: Vec<String> = args
        .methods
        .iter()
        .filter(|n| dof::eval::methods::evaluated_methods().iter().any(|m| m.name() == n.as_str() && m.uses_backend()))
        .cloned()
        .collect();
    if args.scaling && !args.methods.is_empty() && kernel_methods.is_empty() {
        eprintln!("note: no scaling sweep: none of the methods asked for runs kernels");
    } else if args.scaling {
        let scaling = dof::eval::scaling::ScalingOptions {
            methods: kernel_methods,
            runs: options.runs.min(3),
            budget_s: args.scaling_budget_s,
            progress: true,
            ..dof::eval::scaling::ScalingOptions::new(args.quick)
        };
        let sweep = dof::eval::scaling::scaling(&scaling, &mut backends)?;
        let path = args.out.join("scaling.json");
        std::fs::write(&path, sweep.to_json()).with_context(|| format!("cannot write {} (in --out)", path.display()))?;
        report.scaling = Some(sweep);
    }
    std::fs::create_dir_all(&args.out).with_context(|| format!("cannot create --out {}", args.out.display()))?;
    let md = report.to_markdown();
    for (name, text) in [("report.json", report.to_json()), ("report.md", md.clone())] {
        let path = args.out.join(name);
        std::fs::write(&path, text).with_context(|| format!("cannot write {} (in --out)", path.display()))?;
    }
    println!("{md}");
    if !report.grids.is_empty() && dof::eval::plot::ensure_font().is_err() {
        eprintln!(
            "note: no TrueType font found, so the image grids are written without their labels (install fonts-dejavu-core or set DOF_PLOT_FONT)"
        );
    }
    for (scene, reference, rows) in &report.grids {
        let path = args.out.join(format!("{scene}-grid.png"));
        dof::eval::grid::write_grid(&path, reference, rows)?;
        let names: Vec<&str> = rows.iter().map(|r| r.0.lines().next().unwrap_or("")).collect();
        println!("wrote {} (rows: reference, {}; left the image, right its error x4)", path.display(), names.join(", "));
    }
    if !args.no_plots {
        let files = dof::eval::figures::write_all(&report, &args.out)?;
        let names: Vec<String> = files.iter().filter_map(|f| Some(f.file_name()?.to_string_lossy().into_owned())).collect();
        println!("wrote {} plots in {}: {}", files.len(), args.out.display(), names.join(", "));
    }
    println!("wrote {} and {}", args.out.join("report.json").display(), args.out.join("report.md").display());
    Ok(())
}

/// `dof eval --temporal`: the focus pull of [`dof::eval::temporal`].
fn run_temporal(args: &EvalArgs) -> anyhow::Result<()> {
    if args.out.exists() && !args.out.is_dir() {
        anyhow::bail!("--out {} is a file; name a folder for the report and plots", args.out.display());
    }
    let mut options = dof::eval::temporal::TemporalOptions::new(args.quick);
    if let Some(scene) = args.scenes.first() {
        options.scene = scene.clone();
    }
    let registry: Vec<String> = args.methods.iter().filter(|n| dof::frame::METHODS.iter().any(|m| m.name == n.as_str())).cloned().collect();
    if !args.methods.is_empty() && registry.is_empty() {
        anyhow::bail!("--temporal compares methods of the frame API; none of --methods {} is one", args.methods.join(","));
    }
    options.methods = registry;
    if !args.no_plots {
        dof::eval::plot::ensure_font().context("the plots need a font; pass --no-plots to leave them out")?;
    }
    std::fs::create_dir_all(&args.out).with_context(|| format!("cannot create --out {}", args.out.display()))?;
    let mut backends = backends(args.backend, false)?;
    let backend = backends.first_mut().context("no backend")?;
    let report = dof::eval::temporal::temporal(&options, backend.as_mut(), true)?;
    let md = report.to_markdown();
    for (name, text) in [("temporal.json", report.to_json()), ("temporal.md", md.clone())] {
        let path = args.out.join(name);
        std::fs::write(&path, text).with_context(|| format!("cannot write {} (in --out)", path.display()))?;
    }
    println!("{md}");
    if !args.no_plots {
        for (stem, figure) in report.figures() {
            let [svg, png] = dof::eval::plot::write(&figure, &args.out.join(stem))?;
            println!("wrote {} and {}", svg.display(), png.display());
        }
    }
    println!("wrote {} and {}", args.out.join("temporal.json").display(), args.out.join("temporal.md").display());
    Ok(())
}
