//! `dof bench frame`: what a frame of the frame API costs, frame after frame: CPU time to record,
//! device time per stage, the context's device memory, and per frame the allocations, submissions
//! and host readbacks (from the backend's counters, so hidden ones count too).

use super::render::BackendArg;
use anyhow::Context;
use dof::backend::{Backend, BackendCounters, BufferId};
use dof::frame::{ContextDesc, ContextReport, Extent, Frame, MethodInfo, MethodOptions, Reads, SplatOptions};
use dof::layers::LayeredImage;
use dof::methods::buffers::slot_words;
use dof::methods::one_shot;
use dof::methods::splat::Merge;
use dof::scene::{self, GuardBand, LayerOptions, raycast_layers};
use dof_shaders::lens::ThinLens;
use std::collections::BTreeMap;
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
    /// A built-in scene, ray cast once into the multi-layer input (no guard band: a renderer's frame).
    #[arg(long, default_value = "railing")]
    scene: String,
    #[arg(long, default_value_t = 1280)]
    width: u32,
    #[arg(long, default_value_t = 720)]
    height: u32,
    /// Timed frames after one warm-up frame.
    #[arg(long, default_value_t = 10)]
    frames: u32,
    /// Run each frame through the one-shot function instead (a context, its buffers and the
    /// input's per frame, and the result read back): what the frame API saves. The "record" time
    /// is then the whole call.
    #[arg(long)]
    one_shot: bool,
    /// Print one JSON object instead of the table.
    #[arg(long)]
    json: bool,
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
    for (flag, v) in [("--width", args.width), ("--height", args.height)] {
        if !(1..=MAX_EDGE).contains(&v) {
            anyhow::bail!("{flag} must be between 1 and {MAX_EDGE} px, got {v}");
        }
    }
    let builtin = scene::builtin(&args.scene)?;
    let mut camera = builtin.camera;
    camera.width = args.width;
    camera.height = args.height;
    let lens = builtin.lens.thin_lens(&camera)?;
    let layer_options = LayerOptions { guard_band: GuardBand::Off, ..Default::default() };
    let layered = raycast_layers(&builtin.scene, &camera, &lens, &layer_options)?;
    let method = dof::frame::registry::method(&args.method)?;
    let image = match method.reads {
        Reads::AllLayers => layered.layers,
        Reads::FrontLayer => layered.layers.front_layer(),
    };
    let options = MethodOptions { splat: SplatOptions { merge: args.merge, ..Default::default() }, ..Default::default() };
    let mut backend = super::render::backend(args.backend)?;
    let b = backend.as_mut();
    let measured = if args.one_shot {
        one_shot(b, method, &image, &lens, &options, args.frames)?
    } else {
        framed(b, method, &image, &lens, &options, args.frames)?
    };
    let per_frame = |n: u64| n as f64 / args.frames as f64;
    let c = measured.counters;
    if args.json {
        let json = serde_json::json!({
            "method": method.name,
            "merge": args.merge.name(),
            "path": if args.one_shot { "one-shot" } else { "frame-api" },
            "scene": args.scene,
            "backend": b.kind().to_string(),
            "device": b.device_name(),
            "width": image.width,
            "height": image.height,
            "layers": image.max_layers,
            "frames": args.frames,
            "allocations_per_frame": per_frame(c.allocations),
            "submits_per_frame": per_frame(c.submissions),
            "readbacks_per_frame": per_frame(c.readbacks),
            "uploads_per_frame": per_frame(c.uploads),
            "cpu_record_ms": measured.record_ms,
            "gpu_ms": measured.gpu_ms,
            "stage_ms": measured.stages,
            "device_bytes": measured.device_bytes,
            "peak_device_bytes": c.peak_device_bytes,
            "overflow_tiles": measured.overflow_tiles,
            "list_entries": measured.list_entries,
            "list_pool": measured.list_pool,
        });
        println!("{json}");
        return Ok(());
    }
    println!(
        "{} {} merge {} on {} ({}), {}x{} with {} layers, {} frames after a warm-up ({})",
        args.scene,
        method.name,
        args.merge.name(),
        b.kind(),
        b.device_name(),
        image.width,
        image.height,
        image.max_layers,
        args.frames,
        if args.one_shot { "one-shot path" } else { "frame API" }
    );
    println!(
        "per frame: {:.2} allocations, {:.2} submissions, {:.2} readbacks, {:.2} uploads",
        per_frame(c.allocations),
        per_frame(c.submissions),
        per_frame(c.readbacks),
        per_frame(c.uploads)
    );
    println!(
        "CPU time to record a frame: {:.3} ms{}",
        measured.record_ms,
        if b.kind() == dof::backend::BackendKind::Cpu { " (the CPU backend runs the kernels as it records)" } else { "" }
    );
    println!("device time per frame: {:.3} ms", measured.gpu_ms);
    for (stage, ms) in &measured.stages {
        println!("  {stage:<22} {ms:>9.3} ms");
    }
    println!(
        "device memory: context {:.1} MB, backend peak {:.1} MB; lists {} entries in a pool of {}, {} overflowing tiles",
        measured.device_bytes as f64 / 1e6,
        c.peak_device_bytes as f64 / 1e6,
        measured.list_entries,
        measured.list_pool,
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
    list_entries: u64,
    list_pool: u64,
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
        let figure = |name: &str| report.figures.get(name).copied().unwrap_or(0.0) as u64;
        Measured {
            counters,
            record_ms,
            gpu_ms,
            stages,
            device_bytes: bytes,
            overflow_tiles: report.overflow,
            list_entries: figure("list_entries"),
            list_pool: figure("list_pool"),
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
/// recording and one submission.
fn framed(
    b: &mut dyn Backend,
    method: &MethodInfo,
    image: &LayeredImage,
    lens: &ThinLens,
    options: &MethodOptions,
    frames: u32,
) -> anyhow::Result<Measured> {
    let pixels = image.width as u64 * image.height as u64;
    let input = slot_words(image);
    let bufs: Vec<BufferId> = [(input.len() as u64, "bench/fragments"), (pixels, "bench/counts"), (3 * pixels, "bench/output")]
        .iter()
        .map(|&(w, l)| b.create_buffer(w, l))
        .collect::<dof::Result<_>>()?;
    b.write_buffer(bufs[0], 0, &input)?;
    b.write_buffer(bufs[1], 0, &image.counts)?;
    let extent = Extent::new(image.width, image.height, image.max_layers);
    let mut ctx = (method.create)(b, &ContextDesc::new(extent, options.clone()))?;
    let frame = Frame::layers(image.width, image.height, image.max_layers, *lens, bufs[0], bufs[1], bufs[2]);
    ctx.record(b, &frame)?;
    b.submit()?;
    let before = b.counters();
    let (mut record_ms, mut gpu_ms, mut stages) = (0.0, 0.0, BTreeMap::new());
    for _ in 0..frames {
        let start = Instant::now();
        ctx.record(b, &frame)?;
        record_ms += start.elapsed().as_secs_f64() * 1e3 / frames as f64;
        gpu_ms += add_stages(&mut stages, &b.submit()?, frames);
    }
    let counters = b.counters().since(&before);
    let report = ctx.report(b).context("reading the last frame's report")?;
    let device_bytes = ctx.device_bytes();
    ctx.destroy(b);
    bufs.into_iter().for_each(|id| b.destroy_buffer(id));
    Ok(Measured::new(counters, record_ms, gpu_ms, stages, device_bytes, &report))
}

/// The one-shot path, frame after frame.
fn one_shot(
    b: &mut dyn Backend,
    method: &MethodInfo,
    image: &LayeredImage,
    lens: &ThinLens,
    options: &MethodOptions,
    frames: u32,
) -> anyhow::Result<Measured> {
    one_shot::one_shot(b, method, options, image, lens)?;
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
    Ok(Measured::new(counters, record_ms, gpu_ms, stages, last.buffer_bytes, &last.report))
}
