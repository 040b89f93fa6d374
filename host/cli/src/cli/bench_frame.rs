//! `dof bench frame`: what a frame of the frame API costs, frame after frame: CPU time to record,
//! device time per stage, the context's device memory, and per frame the allocations, submissions
//! and host readbacks (from the backend's counters, so hidden ones count too).
//!
//! The frame time is one span (a GPU timestamp pair on Vulkan, the wall clock on the CPU backend)
//! around the depth of field's whole recording, frame by frame: its median, 10th and 90th
//! percentiles over the timed frames after the warm-up ones. The per-stage times (each command's
//! own timestamp pair, summed by label) are its profile; with `--orbit` the peel has a span of its
//! own, reported beside the frame time, not inside it.
//!
//! With `--orbit DEG` the multi-layer input is made anew every frame by depth peeling on the device
//! (`raster::MeshPeelContext`, Franke et al. 2018, §4.1-4.3), recorded into the same submission as
//! the depth of field, the camera turning DEG degrees a frame about the point in focus.

use super::render::BackendArg;
use anyhow::Context;
use dof::backend::{Backend, BackendCounters, BufferId, CommandTime};
use dof::frame::{ContextDesc, ContextReport, Extent, MethodInfo, MethodOption, MethodOptions, Reads, RgbBuffer, Value};
use dof::layers::{LayeredImage, RgbImage};
use dof::methods::one_shot::{self, Runner, RunnerInput};
use dof::methods::splat::Merge;
use dof::raster::{MeshPeelContext, MeshPeelDesc, default_near, peel_layers};
use dof::scene::{self, Aperture, Camera, Focus, GuardBand, LayerOptions, LensSettings, MeshScene, raycast_layers};
use dof::timing::Warmup;
use dof_shaders::lens::ThinLens;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

#[derive(clap::Args)]
pub struct FrameArgs {
    /// A method of the frame API (its registry name).
    #[arg(long, default_value = "multilayer", value_parser = super::method_names())]
    method: String,
    /// Fragment merging before tiling.
    #[arg(long, default_value = "4x4")]
    merge: Merge,
    #[arg(long, value_enum, default_value_t = BackendArg::Cpu)]
    backend: BackendArg,
    /// A built-in scene or a glTF file (`.gltf`, `.glb`, seen by its first camera). Without
    /// `--orbit`, made once into the multi-layer input (ray cast, or depth-peeled on the host; no
    /// guard band: a renderer's frame).
    #[arg(long, default_value = "railing")]
    scene: String,
    /// Make the layers anew every frame by depth peeling on the device, in the frame's submission,
    /// the camera turning this many degrees a frame about the point in focus (-360 to 360; 0: a
    /// still camera, layers still made every frame). The guard band is the automatic one of the
    /// first view, fixed for the run.
    #[arg(long, allow_negative_numbers = true)]
    orbit: Option<f32>,
    /// The focus distance (planar, scene units), as in `dof render`.
    #[arg(long, allow_negative_numbers = true)]
    focus: Option<f32>,
    /// The aperture radius (scene units), as in `dof render`.
    #[arg(long, allow_negative_numbers = true)]
    aperture_radius: Option<f32>,
    /// Write the last frame, cut to the frame, to this EXR file.
    #[arg(long)]
    out: Option<PathBuf>,
    #[arg(long, default_value_t = 1280)]
    width: u32,
    #[arg(long, default_value_t = 720)]
    height: u32,
    /// Timed frames, after the warm-up ones (the frame time is their median).
    #[arg(long, default_value_t = 20)]
    frames: u32,
    /// Untimed frames first (pipelines, caches and the list pool settle).
    #[arg(long, default_value_t = 2)]
    warmup: u32,
    /// The warm-up goes on until it has lasted this long too (ms of wall time): a GPU raises its
    /// clocks only after some busy time, and frames timed before run several times slower.
    #[arg(long, default_value_t = 500.0)]
    warmup_ms: f64,
    /// Run each frame through the one-shot function instead (a context, its buffers and the
    /// input's per frame, and the result read back): what the frame API saves. The "record" time
    /// is then the whole call.
    #[arg(long)]
    one_shot: bool,
    /// Print one JSON object instead of the table.
    #[arg(long)]
    json: bool,
    /// Sub-samples a pixel of the multi-layer input (1, 4, 9 or 16; with --orbit the device peel
    /// runs at sub-sample resolution and resolves on the device).
    #[arg(long, visible_alias = "area-samples", default_value_t = scene::DEFAULT_SUBSAMPLES)]
    subsamples: u32,
    /// Leave out the footprints of area-integrated fragments (which of a pixel's sub-samples saw
    /// each): splatting then spreads every fragment from its pixel's centre.
    #[arg(long)]
    no_footprints: bool,
    /// Where the frames come from: `layers`, the multi-layer image in slot buffers; `images`, it
    /// flattened into an RGBA16F colour and a D32 (reversed, infinite far plane) depth image that
    /// the frame reads in place every frame, as a renderer's images are (stage `frame/input`; the
    /// method then sees one layer); or `copied-images`, the same images copied into the context's
    /// buffers first (stages `frame/input-color` and `frame/input-depth` too).
    #[arg(long, value_enum, default_value_t = InputArg::Layers)]
    input: InputArg,
    /// Time only the frame's span (one timestamp pair a frame on Vulkan): no command gets a pair
    /// of its own, so the frame time carries none of their cost, and there is no per-stage profile.
    #[arg(long)]
    span_only: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum InputArg {
    Layers,
    /// Colour and depth images the frame reads in place.
    Images,
    /// The same images, copied into the context's buffers first.
    CopiedImages,
}

/// The largest frame edge `bench frame` takes (that of 4K and beyond; the contexts check the
/// device's own limits).
const MAX_EDGE: u32 = 16384;
/// Most frames `bench frame` runs.
const MAX_FRAMES: u32 = 100_000;

pub fn run(args: &FrameArgs) -> anyhow::Result<()> {
    if args.frames == 0 || args.frames > MAX_FRAMES {
        anyhow::bail!("--frames must be between 1 and {MAX_FRAMES}, got {}", args.frames);
    }
    if args.warmup > MAX_FRAMES {
        anyhow::bail!("--warmup must be between 0 and {MAX_FRAMES}, got {}", args.warmup);
    }
    for (flag, v) in [("--width", args.width), ("--height", args.height)] {
        if !(1..=MAX_EDGE).contains(&v) {
            anyhow::bail!("{flag} must be between 1 and {MAX_EDGE} px, got {v}");
        }
    }
    check_view_flags(args)?;
    scene::check_subsamples(args.subsamples).map_err(|e| anyhow::anyhow!("--subsamples: {e}"))?;
    let method = dof::frame::registry::method(&args.method)?;
    // `--merge` (default 4x4) applies to the methods that merge; the others run with their defaults.
    let merge = method.takes(MethodOption::Merge).then(|| ("merge", Value::from(args.merge.name())));
    let options = method.method_options(merge)?;
    let view = SceneView::new(args)?;
    let warmup = Warmup { frames: args.warmup, ms: args.warmup_ms };
    let mut backend = super::render::backend(args.backend)?;
    let b = backend.as_mut();
    b.set_command_timestamps(!args.span_only);
    let (measured, size, layers) = match args.orbit {
        Some(deg) => {
            let layers = LayerOptions { subsamples: args.subsamples, footprints: !args.no_footprints, ..Default::default() };
            let m = orbiting(b, method, &view, &options, warmup, args.frames, deg, args.out.as_deref(), &layers)?;
            (m, [view.camera.width, view.camera.height], LayerOptions::default().max_layers)
        }
        None => {
            let layered = view.layers(b, args.subsamples, !args.no_footprints)?;
            let image = match (args.input, method.reads) {
                (InputArg::Images | InputArg::CopiedImages, _) | (_, Reads::AllLayers) => layered,
                (_, Reads::FrontLayer) => layered.front_layer(),
            };
            let m = if args.one_shot {
                one_shot(b, method, &image, &view.lens, &options, warmup, args.frames)?
            } else {
                let input = match args.input {
                    InputArg::Layers => RunnerInput::Layers,
                    InputArg::Images => RunnerInput::Images,
                    InputArg::CopiedImages => RunnerInput::CopiedImages,
                };
                framed(b, method, &image, input, &view.lens, &options, warmup, args.frames, args.out.as_deref())?
            };
            let layers = if args.input == InputArg::Layers { image.max_layers } else { 1 };
            (m, [image.width, image.height], layers)
        }
    };
    let per_frame = |n: u64| n as f64 / args.frames as f64;
    let c = measured.counters;
    let frame = Spread::of(&measured.frame_spans);
    let peel = Spread::of(&measured.peel_spans);
    let timing = match b.kind() {
        dof::backend::BackendKind::Cpu => "wall clock around the recording (the CPU backend runs the kernels as it records)",
        _ => "one GPU timestamp pair around the recording",
    };
    if args.json {
        // The frame time (spans), apart: one `json!` of every field passes the macro's recursion limit.
        let spans = serde_json::json!({
            "warmup_frames": args.warmup,
            "frame_timing": if args.one_shot { "none: the one-shot path submits inside its call" } else { timing },
            "frame_ms": frame.map(|f| f.median),
            "frame_ms_p10": frame.map(|f| f.p10),
            "frame_ms_p90": frame.map(|f| f.p90),
            "frame_ms_frames": frame.map_or(0, |f| f.count),
            "peel_span_ms": peel.map(|f| f.median),
            "peel_span_ms_p10": peel.map(|f| f.p10),
            "peel_span_ms_p90": peel.map(|f| f.p90),
            "table1_ms": table1(method.name, &measured.stages),
        });
        let mut json = serde_json::json!({
            "method": method.name,
            "merge": args.merge.name(),
            "input": match args.input {
                InputArg::Layers => "layers",
                InputArg::Images => "images",
                InputArg::CopiedImages => "copied-images",
            },
            "path": if args.one_shot { "one-shot" } else if args.orbit.is_some() { "frame-api+device-peel" } else { "frame-api" },
            "orbit_deg": args.orbit,
            "scene": args.scene,
            "backend": b.kind().to_string(),
            "device": b.device_name(),
            "width": size[0],
            "height": size[1],
            "layers": layers,
            "guard_band_px": measured.margin,
            "guard_band_needed_px_last_frame": measured.band.map(|b| b.0),
            "guard_band_exceeded_frames": measured.band.map(|b| b.1),
            "frames": args.frames,
            "span_only": args.span_only,
            "allocations_per_frame": per_frame(c.allocations),
            "submits_per_frame": per_frame(c.submissions),
            "readbacks_per_frame": per_frame(c.readbacks),
            "uploads_per_frame": per_frame(c.uploads),
            "commands_per_frame": per_frame(c.commands),
            "dispatches_per_frame": per_frame(c.dispatches),
            "empty_dispatches_per_frame": per_frame(c.empty_dispatches),
            "barriers_per_frame": per_frame(c.barriers),
            "workgroup_barriers_per_frame": per_frame(c.workgroup_barriers),
            "cpu_record_ms": measured.record_ms,
            "gpu_ms": measured.gpu_ms,
            "peel_passes_per_frame": measured.peel_passes as f64 / args.frames as f64,
            "peel_ms": measured.peel_ms,
            "peel_passes_drawn_last_frame": measured.peel_drawn.map(|d| d.0),
            "peel_passes_with_surface_last_frame": measured.peel_drawn.map(|d| d.1),
            "dof_ms": measured.gpu_ms - measured.peel_ms,
            "stage_ms": measured.stages,
            "device_bytes": measured.device_bytes,
            "peak_device_bytes": c.peak_device_bytes,
            "overflow_tiles": measured.overflow_tiles,
            "thinned_tiles": measured.thinned_tiles,
            "list_entries": measured.list_entries,
            "list_pool": measured.list_pool,
            "pool_grown_in_warmup": measured.grown,
            "warmup_frames_run": measured.warmed,
        });
        if let (Some(all), serde_json::Value::Object(spans)) = (json.as_object_mut(), spans) {
            all.extend(spans);
        }
        println!("{json}");
        return Ok(());
    }
    println!(
        "{} {} merge {} on {} ({}), {}x{} with {} layers, {} frames after {} warm-up ({})",
        args.scene,
        method.name,
        args.merge.name(),
        b.kind(),
        b.device_name(),
        size[0],
        size[1],
        layers,
        args.frames,
        measured.warmed,
        if args.one_shot {
            "one-shot path"
        } else if args.orbit.is_some() {
            "frame API, layers peeled on the device every frame"
        } else if args.input == InputArg::Images {
            "frame API, colour and depth images read in place every frame"
        } else if args.input == InputArg::CopiedImages {
            "frame API, colour and depth images copied in every frame"
        } else {
            "frame API"
        }
    );
    println!(
        "per frame: {:.2} allocations, {:.2} submissions, {:.2} readbacks, {:.2} uploads; {:.1} commands, {:.1} of them dispatches or draws ({:.1} empty{}), {:.1} barriers",
        per_frame(c.allocations),
        per_frame(c.submissions),
        per_frame(c.readbacks),
        per_frame(c.uploads),
        per_frame(c.commands),
        per_frame(c.dispatches),
        per_frame(c.empty_dispatches),
        if b.kind() == dof::backend::BackendKind::Cpu { "" } else { ", not counted on a GPU" },
        per_frame(c.barriers)
    );
    if b.kind() == dof::backend::BackendKind::Cpu {
        let subgroups = b.limits().subgroup_size.filter(|_| b.limits().subgroup_kernels);
        println!(
            "workgroup barriers executed per frame, summed over workgroups: {:.0} ({})",
            per_frame(c.workgroup_barriers),
            subgroups.map_or("without subgroups".to_string(), |s| format!("in subgroups of {s}"))
        );
    }
    println!(
        "CPU time to record a frame: {:.3} ms{}",
        measured.record_ms,
        if b.kind() == dof::backend::BackendKind::Cpu { " (the CPU backend runs the kernels as it records)" } else { "" }
    );
    match frame {
        Some(f) => println!(
            "frame time (depth of field, {timing}): median {:.3} ms, p10 {:.3}, p90 {:.3} over {} frames",
            f.median, f.p10, f.p90, f.count
        ),
        None => println!("frame time: not measured (the one-shot path submits inside its call; see the stages)"),
    }
    if let Some(p) = peel {
        println!("peeling, beside it (its own span): median {:.3} ms, p10 {:.3}, p90 {:.3}", p.median, p.p10, p.p90);
    }
    println!("device time per frame, the commands' own timestamp pairs summed (the profile below): {:.3} ms", measured.gpu_ms);
    if args.orbit.is_some() {
        println!(
            "  peeling {:.3} ms ({:.1} passes recorded a frame; the last frame's drawn and with a surface: {:?}; guard band {} px), depth of field {:.3} ms",
            measured.peel_ms,
            measured.peel_passes as f64 / args.frames as f64,
            measured.peel_drawn.unwrap_or_default(),
            measured.margin,
            measured.gpu_ms - measured.peel_ms
        );
    }
    for (stage, ms) in &measured.stages {
        if ms.is_nan() {
            println!("  {stage:<22} not timed");
        } else {
            println!("  {stage:<22} {ms:>9.3} ms");
        }
    }
    println!(
        "device memory: context {:.1} MB, backend peak {:.1} MB; lists {} entries in a pool of {} (grown {} time(s) in the warm-up), {} overflowing tiles",
        measured.device_bytes as f64 / 1e6,
        c.peak_device_bytes as f64 / 1e6,
        measured.list_entries,
        measured.list_pool,
        measured.grown,
        measured.overflow_tiles
    );
    Ok(())
}

struct Measured {
    counters: BackendCounters,
    /// Means per frame.
    record_ms: f64,
    gpu_ms: f64,
    stages: BTreeMap<String, f64>,
    device_bytes: u64,
    overflow_tiles: u64,
    thinned_tiles: u64,
    list_entries: u64,
    list_pool: u64,
    /// Times the warm-up grew the context after an overflowing frame.
    grown: u32,
    /// Warm-up frames run (`--warmup`, more where `--warmup-ms` asked for them).
    warmed: u32,
    /// Device time of the peel's commands per frame (labels `peel/...`), part of `gpu_ms`.
    peel_ms: f64,
    /// Peel passes recorded over all timed frames.
    peel_passes: u64,
    /// The guard band of the device peel's image (0 without `--orbit`).
    margin: u32,
    /// The last frame's peel passes that drew and that found a surface (`--orbit`).
    peel_drawn: Option<(u32, u32)>,
    /// The band the last frame's view needed, and the frames that needed more than the image has.
    band: Option<(u32, u32)>,
    /// Per timed frame, the span around the depth of field's recording and around the peel's
    /// (ms; NaN where the queue has no timestamps).
    frame_spans: Vec<f64>,
    peel_spans: Vec<f64>,
}

/// The span labels `bench frame` opens.
const DOF_SPAN: &str = one_shot::FRAME_SPAN;
const PEEL_SPAN: &str = "frame/peel";

/// The spread of per-frame times: median, 10th and 90th percentiles (nearest rank, the upper
/// median for an even count, as `dof::timing::median`), over the finite ones.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Spread {
    median: f64,
    p10: f64,
    p90: f64,
    count: usize,
}

impl Spread {
    fn of(values: &[f64]) -> Option<Spread> {
        let mut v: Vec<f64> = values.iter().copied().filter(|t| t.is_finite()).collect();
        if v.is_empty() {
            return None;
        }
        v.sort_by(f64::total_cmp);
        let at = |q: f64| v[(q * (v.len() - 1) as f64).round() as usize];
        Some(Spread { median: at(0.5), p10: at(0.1), p90: at(0.9), count: v.len() })
    }
}

/// The per-stage means summed into the columns of Franke et al. 2018, Table 1 (merge, splat,
/// sort, apply; the peel's stages apart), as `dof eval` groups them.
fn table1(method: &str, stages: &BTreeMap<String, f64>) -> BTreeMap<&'static str, f64> {
    let mut columns: BTreeMap<&'static str, f64> = ["merge", "splat", "sort", "apply"].into_iter().map(|c| (c, 0.0)).collect();
    for (label, ms) in stages.iter().filter(|(_, ms)| !ms.is_nan()) {
        let column = if label.starts_with("peel/") { "peel" } else { dof::eval::report::table_column(method, label) };
        *columns.entry(column).or_default() += ms;
    }
    columns
}

/// Adds a submission's spans to the frame's and the peel's lists.
fn add_spans(m: &mut Measured, spans: Vec<CommandTime>) {
    for s in spans {
        match s.label.as_str() {
            DOF_SPAN => m.frame_spans.push(s.ms),
            PEEL_SPAN => m.peel_spans.push(s.ms),
            _ => {}
        }
    }
}

impl Measured {
    fn new(
        counters: BackendCounters,
        record_ms: f64,
        gpu_ms: f64,
        stages: BTreeMap<String, f64>,
        bytes: u64,
        report: &ContextReport,
    ) -> Self {
        let figure = |name: &str| report.figure(name).unwrap_or(0.0) as u64;
        let peel_ms = stages.iter().filter(|(l, ms)| l.starts_with("peel/") && !ms.is_nan()).map(|(_, ms)| ms).sum();
        Measured {
            counters,
            record_ms,
            gpu_ms,
            stages,
            device_bytes: bytes,
            overflow_tiles: figure("overflow_tiles"),
            thinned_tiles: figure("thinned_tiles"),
            list_entries: figure("list_entries"),
            list_pool: figure("list_pool"),
            grown: 0,
            warmed: 0,
            peel_ms,
            peel_passes: 0,
            margin: 0,
            peel_drawn: None,
            band: None,
            frame_spans: Vec::new(),
            peel_spans: Vec::new(),
        }
    }
}

/// Mean time per stage label over `frames` frames of command times.
fn add_stages(into: &mut BTreeMap<String, f64>, times: &[dof::backend::CommandTime], frames: u32) -> f64 {
    let mut total = 0.0;
    for t in times {
        let ms = if t.ms.is_finite() { t.ms } else { 0.0 };
        *into.entry(t.label.clone()).or_default() += ms / frames as f64;
        total += ms;
    }
    total / frames as f64
}

/// The frame API: one context and the input's buffers, made and filled once; then per frame a
/// recording and one submission ([`Runner::time_frames`], which also grows the context when a
/// warm-up frame overflowed).
#[allow(clippy::too_many_arguments)]
fn framed(
    b: &mut dyn Backend,
    method: &MethodInfo,
    image: &LayeredImage,
    input: RunnerInput,
    lens: &ThinLens,
    options: &MethodOptions,
    warmup: Warmup,
    frames: u32,
    out: Option<&Path>,
) -> anyhow::Result<Measured> {
    let mut runner = Runner::fed(b, method, options, image, input)?;
    let timed = runner.time_frames(b, image, lens, warmup, frames);
    let device_bytes = runner.device_bytes();
    runner.destroy(b);
    let t = timed?;
    if let Some(out) = out {
        write_exr(&t.last.image, out)?;
    }
    let stages = t.runs.mean_stages();
    let gpu_ms = stages.values().filter(|ms| !ms.is_nan()).sum();
    let mut m = Measured::new(t.counters, t.record_ms, gpu_ms, stages, device_bytes, &t.last.report);
    m.grown = t.grown;
    m.warmed = t.warmed;
    m.frame_spans = t.spans_ms;
    Ok(m)
}

/// The one-shot path, frame after frame.
fn one_shot(
    b: &mut dyn Backend,
    method: &MethodInfo,
    image: &LayeredImage,
    lens: &ThinLens,
    options: &MethodOptions,
    warmup: Warmup,
    frames: u32,
) -> anyhow::Result<Measured> {
    let warmed = warmup.run(|| one_shot::one_shot(b, method, options, image, lens).map(|_| ()))?;
    let before = b.counters();
    let (mut record_ms, mut gpu_ms, mut stages) = (0.0, 0.0, BTreeMap::new());
    let mut last = None;
    for _ in 0..frames {
        let start = Instant::now();
        let out = one_shot::one_shot(b, method, options, image, lens)?;
        record_ms += start.elapsed().as_secs_f64() * 1e3 / frames as f64;
        gpu_ms += add_stages(&mut stages, &out.stages, frames);
        last = Some(out);
    }
    let counters = b.counters().since(&before);
    let last = last.context("no frame ran")?;
    let mut m = Measured::new(counters, record_ms, gpu_ms, stages, last.buffer_bytes, &last.report);
    m.warmed = warmed;
    Ok(m)
}

/// Checks the view flags before anything is loaded or made.
fn check_view_flags(args: &FrameArgs) -> anyhow::Result<()> {
    if let Some(d) = args.orbit.filter(|d| !(d.abs() <= 360.0)) {
        anyhow::bail!("--orbit (degrees per frame) must lie between -360 and 360, got {d}");
    }
    if let Some(f) = args.focus.filter(|f| !(f.is_finite() && *f > 0.0)) {
        anyhow::bail!("--focus (the focus distance) must be a positive finite number, got {f}");
    }
    if let Some(r) = args.aperture_radius.filter(|r| !(r.is_finite() && *r >= 0.0)) {
        anyhow::bail!("--aperture-radius must be a finite number >= 0, got {r}");
    }
    if args.input != InputArg::Layers && (args.orbit.is_some() || args.one_shot) {
        anyhow::bail!("--input images and copied-images feed the frame API's image inputs; they do not combine with --orbit or --one-shot");
    }
    if args.orbit.is_some() && args.one_shot {
        anyhow::bail!("--orbit peels on the device inside the frame API; it does not combine with --one-shot");
    }
    if args.one_shot && args.out.is_some() {
        anyhow::bail!("--out writes a frame of the frame API; it does not combine with --one-shot");
    }
    if let Some(out) = &args.out
        && !out.to_string_lossy().to_lowercase().ends_with(".exr")
    {
        anyhow::bail!("--out must name an .exr file, got {}", out.display());
    }
    if let Some(out) = &args.out {
        // Its folder made and a probe written now, not after the frames ran.
        super::render::prepare_output(out)?;
    }
    Ok(())
}

/// The scene of `--scene` as a mesh (a built-in one exported to glTF, as `dof scenes --raster`
/// does) with its view and lens, and for built-ins the analytic scene too.
struct SceneView {
    mesh: MeshScene,
    analytic: Option<scene::Scene>,
    camera: Camera,
    lens: ThinLens,
    near: f32,
}

impl SceneView {
    fn new(args: &FrameArgs) -> anyhow::Result<Self> {
        let lower = args.scene.to_lowercase();
        let lens_flags = "the lens of --focus and --aperture-radius";
        let with_flags = |mut settings: LensSettings| {
            if let Some(d) = args.focus {
                settings.focus = Focus::Distance(d);
            }
            if let Some(r) = args.aperture_radius {
                settings.aperture = Aperture::Radius(r);
            }
            settings
        };
        let (mesh, analytic, camera, lens, near) = if lower.ends_with(".gltf") || lower.ends_with(".glb") {
            let mut mesh = scene::load_gltf(Path::new(&args.scene))?;
            let (camera, near) = mesh.default_camera(args.width, Some(args.height)).with_context(|| args.scene.clone())?;
            mesh.single_sided_solids(camera.eye);
            let settings = with_flags(mesh.lens_focused_at(&camera, args.focus)?);
            let lens = settings.thin_lens(&camera).context(lens_flags)?;
            (mesh, None, camera, lens, Some(near))
        } else {
            let builtin = scene::builtin(&args.scene)?;
            let mut camera = builtin.camera;
            camera.width = args.width;
            camera.height = args.height;
            let lens = with_flags(builtin.lens).thin_lens(&camera).context(lens_flags)?;
            let mesh = if args.orbit.is_some() {
                let glb = scene::export_glb(&builtin.scene, &builtin.camera, &scene::ExportOptions::default())?;
                scene::load_gltf_slice(&glb)?
            } else {
                MeshScene::default()
            };
            (mesh, Some(builtin.scene), camera, lens, None)
        };
        let near = near.unwrap_or(default_near(lens.focus_distance));
        Ok(SceneView { mesh, analytic, camera, lens, near })
    }

    /// The multi-layer input made once (no guard band): ray cast for a built-in scene, peeled on
    /// the host for a glTF one.
    fn layers(&self, b: &mut dyn Backend, subsamples: u32, footprints: bool) -> anyhow::Result<LayeredImage> {
        let options = LayerOptions { guard_band: GuardBand::Off, subsamples, footprints, ..Default::default() };
        Ok(match &self.analytic {
            Some(analytic) => raycast_layers(analytic, &self.camera, &self.lens, &options)?.layers,
            None => peel_layers(b, &self.mesh.raster(), &self.camera, &self.lens, self.near, &options)?.image.layers,
        })
    }
}

/// `camera` turned `deg` degrees about the vertical axis through the point `focus` ahead on its
/// view axis (as `dof render --orbit` turns it).
fn orbit(camera: &Camera, focus: f32, deg: f32) -> Camera {
    let forward = (camera.target - camera.eye).normalize_or_zero();
    let pivot = camera.eye + forward * focus;
    let turn = glam::Quat::from_rotation_y(deg.to_radians());
    Camera { eye: pivot + turn * (camera.eye - pivot), target: pivot + turn * (camera.target - pivot), up: turn * camera.up, ..*camera }
}

/// The device peel and the method's context, made once; then per frame the camera turned, the
/// peel and the depth of field recorded, and one submission.
#[allow(clippy::too_many_arguments)]
fn orbiting(
    b: &mut dyn Backend,
    method: &MethodInfo,
    view: &SceneView,
    options: &MethodOptions,
    warmup: Warmup,
    frames: u32,
    deg: f32,
    out: Option<&Path>,
    layer_options: &LayerOptions,
) -> anyhow::Result<Measured> {
    let desc = MeshPeelDesc::new(layer_options, view.near);
    let lens = view.lens;
    let mut peel = MeshPeelContext::new(b, &view.mesh.raster(), &view.camera, &lens, &desc)?;
    let [w, h] = peel.size();
    let made = (|| {
        let output = b.create_buffer(3 * w as u64 * h as u64, "bench/output")?;
        let mut options = options.clone();
        options.splat.footprint_side = options.splat.footprint_side.max(peel.footprint_side());
        match (method.create)(b, &ContextDesc::new(Extent::new(w, h, peel.layers()), options)) {
            Ok(ctx) => Ok((output, ctx)),
            Err(e) => {
                b.destroy_buffer(output);
                Err(e)
            }
        }
    })();
    let (output, mut ctx) = match made {
        Ok(made) => made,
        Err(e) => {
            peel.destroy(b);
            return Err(e.into());
        }
    };
    let frame = peel.frame(lens, dof::frame::FrameOutput::Buffer(RgbBuffer(output)));
    let run = (|| -> anyhow::Result<Measured> {
        // Warm-up frames from the first view (the context grown if one overflowed), then one
        // frame per turn.
        let (warmed, grown) = one_shot::warm_up(ctx.as_mut(), b, warmup, |ctx, b| {
            peel.record(b, &view.camera, &lens)?;
            ctx.record(b, &frame)?;
            b.submit()?;
            Ok(())
        })?;
        b.take_span_times();
        let before = b.counters();
        let (mut record_ms, mut gpu_ms, mut stages) = (0.0, 0.0, BTreeMap::new());
        let mut passes = 0;
        let mut spans = Vec::new();
        for i in 1..=frames {
            let camera = orbit(&view.camera, lens.focus_distance, deg * i as f32);
            let start = Instant::now();
            b.begin_span(PEEL_SPAN)?;
            peel.record(b, &camera, &lens)?;
            b.end_span()?;
            b.begin_span(DOF_SPAN)?;
            ctx.record(b, &frame)?;
            b.end_span()?;
            record_ms += start.elapsed().as_secs_f64() * 1e3 / frames as f64;
            let times = b.submit()?;
            spans.extend(b.take_span_times());
            // One shading dispatch a pass recorded, whether or not the pass drew.
            passes += times.iter().filter(|t| t.label == "peel/shade").count() as u64;
            gpu_ms += add_stages(&mut stages, &times, frames);
        }
        let counters = b.counters().since(&before);
        let report = ctx.report(b).context("reading the last frame's report")?;
        let mut m = Measured::new(counters, record_ms, gpu_ms, stages, ctx.device_bytes() + peel.device_bytes(), &report);
        m.peel_passes = passes;
        m.warmed = warmed;
        m.grown = grown;
        add_spans(&mut m, spans);
        m.margin = peel.margin();
        let last = peel.peel_report(b).context("reading the last frame's peel report")?;
        m.peel_drawn = Some((last.drawn, last.with_surface));
        m.band = Some((last.band_needed, last.band_exceeded_frames));
        if let Some(out) = out {
            write_last(b, output, [w, h], peel.margin(), out)?;
        }
        Ok(m)
    })();
    ctx.destroy(b);
    peel.destroy(b);
    b.destroy_buffer(output);
    run
}

/// Reads the RGB result of the last frame, cuts `margin` pixels off every side and writes it.
fn write_last(b: &mut dyn Backend, output: BufferId, size: [u32; 2], margin: u32, out: &Path) -> anyhow::Result<()> {
    write_exr(&dof::methods::buffers::read_rgb(b, output, size[0], size[1])?.crop(margin), out)
}

fn write_exr(image: &RgbImage, out: &Path) -> anyhow::Result<()> {
    dof::io::write_exr(out, image, &[]).with_context(|| format!("--out {}", out.display()))?;
    eprintln!("wrote {}", out.display());
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::Spread;

    #[test]
    fn spread_is_nearest_rank_over_finite_times() {
        let times: Vec<f64> = (1..=20).rev().map(f64::from).chain([f64::NAN]).collect();
        let s = Spread::of(&times).unwrap();
        // 20 finite values 1..=20: ranks 0.1·19 → 2 (3.0), 0.5·19 → 10 (11.0), 0.9·19 → 17 (18.0).
        assert_eq!(s, Spread { median: 11.0, p10: 3.0, p90: 18.0, count: 20 });
        assert_eq!(Spread::of(&[f64::NAN]), None);
        assert_eq!(Spread::of(&[2.5]).map(|s| (s.median, s.p10, s.p90)), Some((2.5, 2.5, 2.5)));
    }
}
