//! `dof soak`: many frames through the frame API while the method, the frame size, the aperture and
//! the lens change every few frames at random within valid ranges (and a splatting context is
//! resized now and then), checking that host memory (the Rust heap, counted by the command's
//! allocator) and device memory (the backend's buffers) stay flat after a warm-up, that the
//! validation layer (synchronization validation included) stays silent, and that every frame's
//! result is finite where its input is.

use super::render::BackendArg;
use dof::backend::{Backend, BufferId, CpuBackend, VulkanBackend, VulkanOptions};
use dof::frame::{
    BokehContext, BokehContextDesc, Frame, GatherContext, GatherContextDesc, RingGatherContext, RingGatherContextDesc, SplatContext,
    SplatContextDesc,
};
use dof::methods::bokeh::BokehOptions;
use dof::methods::buffers::{read_rgb, slot_words};
use dof::methods::ring_gather::{MAX_RINGS, RingGatherOptions};
use dof::methods::splat::{Merge, SplatOptions};
use dof::stress::{noise_with_sky, test_lens};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use std::time::Instant;

#[derive(clap::Args)]
pub struct SoakArgs {
    /// Frames to record (after the warm-up, which is a tenth of them, at least 8).
    #[arg(long, default_value_t = 200)]
    frames: u32,
    #[arg(long, value_enum, default_value_t = BackendArg::Vulkan)]
    backend: BackendArg,
    /// The largest frame (width and height); sizes are drawn up to it.
    #[arg(long, default_value_t = 96)]
    max_size: u32,
    /// Frames between changes of method, size, aperture and lens.
    #[arg(long, default_value_t = 3)]
    every: u32,
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Run Vulkan without the validation layer (it is on by default).
    #[arg(long)]
    no_validation: bool,
    /// Print one JSON object instead of the summary.
    #[arg(long)]
    json: bool,
}

/// Most frames and the largest edge `dof soak` accepts.
const MAX_FRAMES: u32 = 1_000_000;
const MAX_SIZE: u32 = 1024;
const MAX_LAYERS: u32 = 4;
/// The heap may move this much after the warm-up (a frame's transient host data).
const HOST_SLACK_BYTES: i64 = 1 << 20;

/// Resident host memory of this process, from `/proc/self/statm` (0 where there is none).
fn resident_bytes() -> i64 {
    let statm = std::fs::read_to_string("/proc/self/statm").unwrap_or_default();
    statm.split_whitespace().nth(1).and_then(|p| p.parse::<i64>().ok()).map_or(0, |pages| pages * 4096)
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Method {
    Multilayer,
    Tiled,
    Gather,
    RingGather,
    Bokeh,
}

const METHODS: [Method; 5] = [Method::Multilayer, Method::Tiled, Method::Gather, Method::RingGather, Method::Bokeh];

/// The contexts, one per method, all for the same maximum extent.
struct Contexts {
    multilayer: SplatContext,
    tiled: SplatContext,
    gather: GatherContext,
    ring_gather: RingGatherContext,
    bokeh: BokehContext,
}

pub fn run(args: &SoakArgs) -> anyhow::Result<()> {
    if args.frames == 0 || args.frames > MAX_FRAMES {
        anyhow::bail!("--frames must be between 1 and {MAX_FRAMES}, got {}", args.frames);
    }
    if !(16..=MAX_SIZE).contains(&args.max_size) {
        anyhow::bail!("--max-size must be between 16 and {MAX_SIZE}, got {}", args.max_size);
    }
    if args.every == 0 {
        anyhow::bail!("--every must be at least 1");
    }
    let validation = args.backend == BackendArg::Vulkan && !args.no_validation;
    let mut backend: Box<dyn Backend> = match args.backend {
        BackendArg::Cpu => Box::new(CpuBackend::new()),
        BackendArg::Vulkan => Box::new(VulkanBackend::new(&VulkanOptions { validation, ..Default::default() })?),
    };
    let b = backend.as_mut();
    let max = args.max_size;
    let pixels = max as u64 * max as u64;
    // The caller's buffers, made once.
    let bufs: Vec<BufferId> = [(4 * pixels * MAX_LAYERS as u64, "soak/fragments"), (pixels, "soak/counts"), (3 * pixels, "soak/output")]
        .iter()
        .map(|&(w, l)| b.create_buffer(w, l))
        .collect::<dof::Result<_>>()?;
    let splat = |merge| SplatContextDesc::new(max, max, MAX_LAYERS, SplatOptions { merge, ..Default::default() });
    let mut ctx = Contexts {
        multilayer: SplatContext::new(b, &splat(Merge::X4))?,
        tiled: SplatContext::new(b, &splat(Merge::X2))?,
        gather: GatherContext::new(b, &GatherContextDesc::new(max, max, MAX_LAYERS))?,
        ring_gather: RingGatherContext::new(b, &RingGatherContextDesc::new(max, max, MAX_LAYERS))?,
        bokeh: BokehContext::new(
            b,
            &BokehContextDesc::new(max, max, MAX_LAYERS, BokehOptions { lum_threshold: 0.5, ..Default::default() }),
        )?,
    };
    let mut rng = Pcg64::seed_from_u64(args.seed);
    let warm_up = (args.frames / 10).max(8);
    let total = warm_up + args.frames;
    let (mut method, mut w, mut h, mut layers, mut aperture) = (Method::Multilayer, max, max, MAX_LAYERS, 0.01f32);
    let (mut host_after_warm_up, mut rss_after_warm_up, mut device_after_warm_up) = (0i64, 0i64, 0u64);
    let mut messages = Vec::new();
    let mut checked = 0u32;
    let mut resizes = 0u32;
    let mut per_method = [0u32; METHODS.len()];
    let start = Instant::now();
    for frame in 0..total {
        if frame % args.every == 0 {
            method = METHODS[rng.random_range(0..METHODS.len())];
            w = rng.random_range(1..=max);
            h = rng.random_range(1..=max);
            layers = if method == Method::Multilayer { rng.random_range(1..=MAX_LAYERS) } else { 1 };
            if method == Method::RingGather {
                // Its knob changes between frames without reallocating.
                let options = RingGatherOptions { rings: rng.random_range(1..=MAX_RINGS), ..Default::default() };
                ctx.ring_gather.set_options(options)?;
            }
            // Pinhole to strong blur (up to about 40 px of CoC radius with the test lens).
            aperture = if rng.random_bool(0.1) { 0.0 } else { rng.random_range(0.0005f32..0.03) };
            let image = noise_with_sky(w, h, layers);
            b.write_buffer(bufs[0], 0, &slot_words(&image))?;
            b.write_buffer(bufs[1], 0, &image.counts)?;
            // Now and then the multi-layer context is resized (shrunk, then grown back): the path
            // a renderer takes when its window changes.
            if frame > 0 && rng.random_bool(0.05) {
                let smaller = rng.random_range(16..=max);
                ctx.multilayer.resize(b, smaller, smaller, MAX_LAYERS)?;
                ctx.multilayer.resize(b, max, max, MAX_LAYERS)?;
                resizes += 1;
            }
        }
        let mut lens = test_lens(aperture);
        lens.focus_distance = 1.0 + (frame % 7) as f32 * 0.5;
        let f = Frame::layers(w, h, layers, lens, bufs[0], bufs[1], bufs[2]);
        match method {
            Method::Multilayer => ctx.multilayer.record(b, &f)?,
            Method::Tiled => ctx.tiled.record(b, &f)?,
            Method::Gather => ctx.gather.record(b, &f)?,
            Method::RingGather => ctx.ring_gather.record(b, &f)?,
            Method::Bokeh => ctx.bokeh.record(b, &f)?,
        }
        b.submit()?;
        per_method[METHODS.iter().position(|&m| m == method).unwrap_or(0)] += 1;
        messages.extend(b.take_diagnostics());
        // Now and then the result is read back and checked: finite everywhere (the input is).
        if frame % 16 == 0 {
            let out = read_rgb(b, bufs[2], w, h)?;
            if let Some(p) = out.data.iter().position(|c| c.iter().any(|v| !v.is_finite())) {
                anyhow::bail!(
                    "frame {frame} ({method:?}, {w}x{h}, {layers} layers, aperture {aperture}): pixel {p} is not finite: {:?}",
                    out.data[p]
                );
            }
            checked += 1;
        }
        if frame + 1 == warm_up {
            host_after_warm_up = super::heap::live_bytes();
            rss_after_warm_up = resident_bytes();
            device_after_warm_up = b.counters().device_bytes;
        }
    }
    let host_growth = super::heap::live_bytes() - host_after_warm_up;
    // Informational: on lavapipe the resident set also holds device memory, whose pages the
    // allocator's blocks touch as buffers move (resizes, draw targets of new sizes).
    let rss_growth = resident_bytes() - rss_after_warm_up;
    let device_growth = b.counters().device_bytes as i64 - device_after_warm_up as i64;
    let seconds = start.elapsed().as_secs_f64();
    let device_bytes = b.counters().device_bytes;
    let Contexts { multilayer, tiled, gather, ring_gather, bokeh } = ctx;
    multilayer.destroy(b);
    tiled.destroy(b);
    gather.destroy(b);
    ring_gather.destroy(b);
    bokeh.destroy(b);
    bufs.into_iter().for_each(|id| b.destroy_buffer(id));
    let left = b.counters().device_bytes;
    messages.extend(b.take_diagnostics());
    let ok = messages.is_empty() && device_growth == 0 && host_growth <= HOST_SLACK_BYTES && left == 0;
    if args.json {
        let json = serde_json::json!({
            "backend": b.kind().to_string(),
            "device": b.device_name(),
            "validation": validation,
            "frames": args.frames,
            "warm_up_frames": warm_up,
            "frames_per_method": { "multilayer": per_method[0], "tiled": per_method[1], "gather": per_method[2], "ring_gather": per_method[3], "bokeh": per_method[4] },
            "resizes": resizes,
            "checked_frames": checked,
            "validation_messages": messages.len(),
            "host_bytes_growth": host_growth,
            "resident_bytes_growth": rss_growth,
            "device_bytes_growth": device_growth,
            "device_bytes": device_bytes,
            "device_bytes_left_after_destroy": left,
            "seconds": seconds,
            "ok": ok,
        });
        println!("{json}");
    } else {
        println!(
            "{} frames (+{warm_up} warm-up) on {} ({}), validation {}: {} multi-layer, {} single-layer, {} gather, {} ring gather, {} bokeh; {resizes} resizes; {checked} results checked finite; {seconds:.1} s",
            args.frames,
            b.kind(),
            b.device_name(),
            if validation { "on" } else { "off" },
            per_method[0],
            per_method[1],
            per_method[2],
            per_method[3],
            per_method[4]
        );
        println!(
            "after the warm-up: heap {:+} bytes (slack {} MB), resident set {:+.1} MB (with the driver's memory), device memory {:+} bytes (held {:.1} MB, {left} left after destroying everything); validation messages: {}",
            host_growth,
            HOST_SLACK_BYTES >> 20,
            rss_growth as f64 / 1e6,
            device_growth,
            device_bytes as f64 / 1e6,
            messages.len()
        );
    }
    for m in messages.iter().take(10) {
        eprintln!("validation: {m}");
    }
    if !ok {
        anyhow::bail!(
            "the soak failed: {} validation messages, device memory grew by {device_growth} bytes ({left} left after destroy), host memory by {host_growth} bytes",
            messages.len()
        );
    }
    Ok(())
}
