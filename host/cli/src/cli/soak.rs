//! `dof soak`: many frames through the frame API while the method, the frame size, the aperture and
//! the lens change every few frames at random within valid ranges (and a splatting context is
//! resized now and then), checking that host memory (the Rust heap, counted by the command's
//! allocator) and device memory (the backend's buffers) stay flat after a warm-up, that the
//! validation layer (synchronization validation included) stays silent, and that every frame's
//! result is finite where its input is.

use super::render::BackendArg;
use dof::backend::{Backend, BufferId, VulkanBackend, VulkanOptions};
use dof::frame::{
    ContextDesc, CountBuffer, DofContext, Extent, Frame, METHODS, MethodInfo, MethodOption, MethodOptions, Reads, RgbBuffer, SlotBuffer,
    Value,
};
use dof::methods::buffers::{SLOT_WORDS, read_rgb, slot_words};
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

/// Options for every method, each where the method takes it: multi-layer splatting merged 4x4,
/// single-layer 2x2 (so both merging paths run), bokeh sprites from a low threshold (the noise
/// makes highlights).
fn options_for(method: &MethodInfo) -> anyhow::Result<MethodOptions> {
    let merge = if method.reads == Reads::AllLayers { "4x4" } else { "2x2" };
    let wanted = [(MethodOption::Merge, Value::from(merge)), (MethodOption::LumThreshold, Value::from(0.5f32))];
    Ok(method.method_options(wanted.into_iter().filter(|(o, _)| method.takes(*o)).map(|(o, v)| (o.key(), v)))?)
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
        BackendArg::Cpu => Box::new(super::cpu_backend()?),
        BackendArg::Vulkan => Box::new(VulkanBackend::new(&VulkanOptions { validation, ..Default::default() })?),
        #[cfg(feature = "wgpu")]
        BackendArg::Wgpu => Box::new(dof::backend::WgpuBackend::new(&Default::default())?),
    };
    let b = backend.as_mut();
    let max = args.max_size;
    let pixels = max as u64 * max as u64;
    // The caller's buffers, made once.
    let bufs: Vec<BufferId> =
        [(SLOT_WORDS as u64 * pixels * MAX_LAYERS as u64, "soak/fragments"), (pixels, "soak/counts"), (3 * pixels, "soak/output")]
            .iter()
            .map(|&(w, l)| b.create_buffer(w, l))
            .collect::<Result<_, dof::CoreError>>()?;
    // One context per method of the registry, all for the same largest frame.
    let extent = Extent::new(max, max, MAX_LAYERS);
    let mut contexts: Vec<Box<dyn DofContext>> = Vec::new();
    for m in METHODS {
        contexts.push((m.create)(b, &ContextDesc::new(extent, options_for(m)?))?);
    }
    let mut rng = Pcg64::seed_from_u64(args.seed);
    let warm_up = (args.frames / 10).max(8);
    let total = warm_up + args.frames;
    let (mut method, mut w, mut h, mut layers, mut aperture) = (0usize, max, max, MAX_LAYERS, 0.01f32);
    let (mut host_after_warm_up, mut rss_after_warm_up, mut device_after_warm_up) = (0i64, 0i64, 0u64);
    let mut messages = Vec::new();
    let mut checked = 0u32;
    let mut resizes = 0u32;
    let mut per_method = vec![0u32; METHODS.len()];
    let start = Instant::now();
    for frame in 0..total {
        if frame % args.every == 0 {
            method = rng.random_range(0..METHODS.len());
            w = rng.random_range(1..=max);
            h = rng.random_range(1..=max);
            layers = if METHODS[method].reads == Reads::AllLayers { rng.random_range(1..=MAX_LAYERS) } else { 1 };
            if let Some(knob) = METHODS[method].knob {
                // A knob changes between frames without reallocating.
                contexts[method].set_knob(rng.random_range(knob.min..=knob.max))?;
            }
            // Pinhole to strong blur (up to about 40 px of CoC radius with the test lens).
            aperture = if rng.random_bool(0.1) { 0.0 } else { rng.random_range(0.0005f32..0.03) };
            let image = noise_with_sky(w, h, layers);
            b.write_buffer(bufs[0], 0, &slot_words(&image))?;
            b.write_buffer(bufs[1], 0, &image.counts)?;
            // Now and then the context is resized (shrunk, then grown back): the path a renderer
            // takes when its window changes.
            if frame > 0 && rng.random_bool(0.05) {
                let smaller = rng.random_range(16..=max);
                contexts[method].resize(b, Extent::new(smaller, smaller, MAX_LAYERS))?;
                contexts[method].resize(b, extent)?;
                resizes += 1;
            }
        }
        let mut lens = test_lens(aperture);
        lens.focus_distance = 1.0 + (frame % 7) as f32 * 0.5;
        let f = Frame::layers(w, h, layers, lens, SlotBuffer::current(bufs[0]), CountBuffer(bufs[1]), RgbBuffer(bufs[2]));
        contexts[method].record(b, &f)?;
        b.submit()?;
        per_method[method] += 1;
        messages.extend(b.take_diagnostics());
        // Now and then the result is read back and checked: finite everywhere (the input is).
        if frame % 16 == 0 {
            let out = read_rgb(b, bufs[2], w, h)?;
            if let Some(p) = out.data.iter().position(|c| c.iter().any(|v| !v.is_finite())) {
                anyhow::bail!(
                    "frame {frame} ({}, {w}x{h}, {layers} layers, aperture {aperture}): pixel {p} is not finite: {:?}",
                    METHODS[method].name,
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
    contexts.into_iter().for_each(|c| c.destroy(b));
    let frames_per_method: serde_json::Map<String, serde_json::Value> =
        METHODS.iter().zip(&per_method).map(|(m, n)| (m.name.to_string(), (*n).into())).collect();
    let counts: Vec<String> = METHODS.iter().zip(&per_method).map(|(m, n)| format!("{n} {}", m.name)).collect();
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
            "frames_per_method": frames_per_method,
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
            "{} frames (+{warm_up} warm-up) on {} ({}), validation {}: {}; {resizes} resizes; {checked} results checked finite; {seconds:.1} s",
            args.frames,
            b.kind(),
            b.device_name(),
            if validation { "on" } else { "off" },
            counts.join(", ")
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
