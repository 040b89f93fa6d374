//! `dof bench frame`: what a frame of the frame API costs, frame after frame: CPU time to record,
//! device time per stage, the context's device memory, and per frame the allocations, submissions
//! and host readbacks (from the backend's counters, so hidden ones count too).

use super::render::BackendArg;
use anyhow::Context;
use dof::backend::{Backend, BackendCounters, BufferId};
use dof::frame::{
    BokehContext, BokehContextDesc, Frame, GatherContext, GatherContextDesc, RingGatherContext, RingGatherContextDesc, SplatContext,
    SplatContextDesc,
};
use dof::layers::LayeredImage;
use dof::methods::bokeh::{BokehOptions, bokeh};
use dof::methods::buffers::slot_words;
use dof::methods::gather::gather;
use dof::methods::ring_gather::{RingGatherOptions, ring_gather};
use dof::methods::splat::{Merge, SplatOptions, splat};
use dof::scene::{self, GuardBand, LayerOptions, raycast_layers};
use dof_shaders::lens::ThinLens;
use std::collections::BTreeMap;
use std::time::Instant;

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum FrameMethod {
    /// Multi-layer tiled splatting (Franke, Hofmann, Stamminger, Selgrad 2018).
    Multilayer,
    /// Single-layer tiled splatting (Selgrad, Franke, Stamminger 2016): the front layer only.
    Tiled,
    /// The gathering baseline (Riguer et al. 2003) on the front layer.
    Gather,
    /// The engine-grade gather (after AMD FidelityFX DoF, Unreal Engine's Diaphragm DoF and
    /// Jimenez 2014) at its default of 5 rings.
    RingGather,
    /// Bokeh sprites (de Rousiers, Pettineo 2012) over the gathering baseline.
    Bokeh,
}

/// The method's name as the command line spells it.
fn method_name(method: FrameMethod) -> String {
    clap::ValueEnum::to_possible_value(&method).map_or_else(|| format!("{method:?}"), |v| v.get_name().to_string())
}

#[derive(clap::Args)]
pub struct FrameArgs {
    #[arg(long, value_enum, default_value_t = FrameMethod::Multilayer)]
    method: FrameMethod,
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

/// Most frames `bench frame` runs.
const MAX_FRAMES: u32 = 100_000;

pub fn run(args: &FrameArgs) -> anyhow::Result<()> {
    if args.frames == 0 || args.frames > MAX_FRAMES {
        anyhow::bail!("--frames must be between 1 and {MAX_FRAMES}, got {}", args.frames);
    }
    let builtin = scene::builtin(&args.scene)?;
    let mut camera = builtin.camera.clone();
    camera.width = args.width;
    camera.height = args.height;
    let lens = builtin.lens.thin_lens(&camera)?;
    let layer_options = LayerOptions { guard_band: GuardBand::Off, ..Default::default() };
    let layered = raycast_layers(&builtin.scene, &camera, &lens, &layer_options)?;
    let image = match args.method {
        FrameMethod::Multilayer => layered.layers,
        _ => layered.layers.front_layer(),
    };
    let options = SplatOptions { merge: args.merge, ..Default::default() };
    let mut backend = super::render::backend(args.backend)?;
    let b = backend.as_mut();
    let measured = if args.one_shot {
        one_shot(b, args.method, &image, &lens, &options, args.frames)?
    } else {
        framed(b, args.method, &image, &lens, &options, args.frames)?
    };
    let per_frame = |n: u64| n as f64 / args.frames as f64;
    let c = measured.counters;
    if args.json {
        let json = serde_json::json!({
            "method": method_name(args.method),
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
        method_name(args.method),
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
    overflow_tiles: u32,
    list_entries: u64,
    list_pool: u64,
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

/// A context of any method, as the benchmark drives it.
enum AnyContext {
    Splat(SplatContext),
    Gather(GatherContext),
    RingGather(RingGatherContext),
    Bokeh(BokehContext),
}

impl AnyContext {
    fn new(b: &mut dyn Backend, method: FrameMethod, image: &LayeredImage, options: &SplatOptions) -> dof::Result<Self> {
        let (w, h, l) = (image.width, image.height, image.max_layers);
        Ok(match method {
            FrameMethod::Multilayer | FrameMethod::Tiled => {
                AnyContext::Splat(SplatContext::new(b, &SplatContextDesc::new(w, h, l, options.clone()))?)
            }
            FrameMethod::Gather => AnyContext::Gather(GatherContext::new(b, &GatherContextDesc::new(w, h, l))?),
            FrameMethod::RingGather => AnyContext::RingGather(RingGatherContext::new(b, &RingGatherContextDesc::new(w, h, l))?),
            FrameMethod::Bokeh => AnyContext::Bokeh(BokehContext::new(b, &BokehContextDesc::new(w, h, l, BokehOptions::default()))?),
        })
    }
    fn record(&mut self, b: &mut dyn Backend, f: &Frame) -> dof::Result<()> {
        match self {
            AnyContext::Splat(c) => c.record(b, f),
            AnyContext::Gather(c) => c.record(b, f),
            AnyContext::RingGather(c) => c.record(b, f),
            AnyContext::Bokeh(c) => c.record(b, f),
        }
    }
    fn device_bytes(&self) -> u64 {
        match self {
            AnyContext::Splat(c) => c.device_bytes(),
            AnyContext::Gather(c) => c.device_bytes(),
            AnyContext::RingGather(c) => c.device_bytes(),
            AnyContext::Bokeh(c) => c.device_bytes(),
        }
    }
    /// Overflowing tiles, list entries and the list pool (splatting only).
    fn lists(&self, b: &mut dyn Backend) -> dof::Result<(u32, u64, u64)> {
        match self {
            AnyContext::Splat(c) => c.report(b).map(|r| (r.overflow_tiles, r.list_entries, r.list_capacity)),
            _ => Ok((0, 0, 0)),
        }
    }
    fn destroy(self, b: &mut dyn Backend) {
        match self {
            AnyContext::Splat(c) => c.destroy(b),
            AnyContext::Gather(c) => c.destroy(b),
            AnyContext::RingGather(c) => c.destroy(b),
            AnyContext::Bokeh(c) => c.destroy(b),
        }
    }
}

/// The frame API: one context and the input's buffers, made and filled once; then per frame a
/// recording and one submission.
fn framed(
    b: &mut dyn Backend,
    method: FrameMethod,
    image: &LayeredImage,
    lens: &ThinLens,
    options: &SplatOptions,
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
    let mut ctx = AnyContext::new(b, method, image, options)?;
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
    let (overflow_tiles, list_entries, list_pool) = ctx.lists(b).context("reading the last frame's report")?;
    let device_bytes = ctx.device_bytes();
    ctx.destroy(b);
    bufs.into_iter().for_each(|id| b.destroy_buffer(id));
    Ok(Measured { counters, record_ms, gpu_ms, stages, device_bytes, overflow_tiles, list_entries, list_pool })
}

/// The one-shot path, frame after frame.
fn one_shot(
    b: &mut dyn Backend,
    method: FrameMethod,
    image: &LayeredImage,
    lens: &ThinLens,
    options: &SplatOptions,
    frames: u32,
) -> anyhow::Result<Measured> {
    let (front, depth) = image.front();
    let run = |b: &mut dyn Backend| -> dof::Result<(Vec<dof::backend::CommandTime>, u64, (u32, u64, u64))> {
        Ok(match method {
            FrameMethod::Multilayer | FrameMethod::Tiled => {
                let out = splat(b, image, lens, options)?;
                let r = out.report;
                (out.stages, r.buffer_bytes, (r.overflow_tiles, r.list_entries, r.list_capacity))
            }
            FrameMethod::Gather => {
                let out = gather(b, &front, &depth, lens, None)?;
                (out.times, out.buffer_bytes, (0, 0, 0))
            }
            FrameMethod::RingGather => {
                let out = ring_gather(b, &front, &depth, lens, &RingGatherOptions::default())?;
                (out.times, out.buffer_bytes, (0, 0, 0))
            }
            FrameMethod::Bokeh => {
                let out = bokeh(b, &front, &depth, lens, &BokehOptions::default())?;
                (out.times, out.buffer_bytes, (0, 0, 0))
            }
        })
    };
    run(b)?;
    let before = b.counters();
    let (mut record_ms, mut gpu_ms, mut stages) = (0.0, 0.0, BTreeMap::new());
    let mut last = (0, (0, 0, 0));
    for _ in 0..frames {
        let start = Instant::now();
        let (times, bytes, lists) = run(b)?;
        record_ms += start.elapsed().as_secs_f64() * 1e3 / frames as f64;
        gpu_ms += add_stages(&mut stages, &times, frames);
        last = (bytes, lists);
    }
    let counters = b.counters().since(&before);
    let (device_bytes, (overflow_tiles, list_entries, list_pool)) = last;
    Ok(Measured { counters, record_ms, gpu_ms, stages, device_bytes, overflow_tiles, list_entries, list_pool })
}
