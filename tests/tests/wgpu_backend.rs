//! The wgpu backend (on wgpu's Vulkan backend, lavapipe in CI) against the CPU backend: the
//! backend's own commands, the sort and scan, and every method of the registry.

use dof::CoreError;
use dof::backend::{Backend, CpuBackend, RunKernel, WgpuBackend};
use dof::frame::{ContextDesc, CountBuffer, Extent, Frame, METHODS, MethodOptions, Reads, RgbBuffer, SlotBuffer};
use dof::methods::buffers::{read_rgb, slot_words};
use dof::methods::one_shot::one_shot;
use dof::methods::splat::{Merge, SplatOptions};
use dof::ops::scan::exclusive_scan;
use dof::ops::sort::sort_on_with;
use dof::stress::{noise_with_sky, test_lens};
use dof::workload::{lists_with, random_key};
use dof_shaders::tonemap::{DisplayParams, MODE_LINEAR, MODE_TONEMAP, display_tonemap};
use dof_tests::oracle::splat_stages::splat_with_stages;
use dof_tests::{wgpu, wgpu_device};
use rand::SeedableRng;
use rand_pcg::Pcg64;

#[test]
fn buffers_fills_and_transfers() {
    let Some(mut g) = wgpu() else { return };
    let a = g.create_buffer(40, "a").unwrap();
    assert_eq!(g.read_buffer(a, 0, 40).unwrap(), vec![0; 40], "new buffers are zero");
    let data: Vec<u32> = (0..40).map(|i| i * 3 + 1).collect();
    g.write_buffer(a, 0, &data).unwrap();
    g.fill(a, 10, 5, 7, "seven").unwrap();
    g.fill(a, 20, 3, 0, "zero").unwrap();
    g.submit().unwrap();
    let mut want = data.clone();
    want[10..15].fill(7);
    want[20..23].fill(0);
    assert_eq!(g.read_buffer(a, 0, 40).unwrap(), want);
    assert_eq!(g.read_buffer(a, 38, 2).unwrap(), want[38..]);
    assert!(g.read_buffer(a, 39, 2).is_err(), "a range beyond the buffer");
    assert!(g.fill(a, 39, 2, 1, "beyond").is_err());
    g.destroy_buffer(a);
    assert_eq!(g.counters().device_bytes, 0);
    assert!(g.take_diagnostics().is_empty());
}

#[test]
fn sort_and_scan_match_the_cpu_bit_for_bit() {
    let Some(mut g) = wgpu() else { return };
    let mut cpu = CpuBackend::with_shared_bytes(g.limits().max_shared_bytes);
    let mut rng = Pcg64::seed_from_u64(21);
    let input = lists_with(&[0, 1, 3, 64, 65, 300, 1000, 2048, 4097, 9000, 40_000], |_, _| random_key(&mut rng));
    let on_gpu = sort_on_with(&mut g, &input, None).expect("sort on wgpu");
    let on_cpu = sort_on_with(&mut cpu, &input, Some(false)).expect("sort on the CPU");
    let bits = |k: &[f32]| k.iter().map(|k| k.to_bits()).collect::<Vec<_>>();
    assert!(bits(&on_gpu.keys) == bits(&on_cpu.keys) && on_gpu.values == on_cpu.values, "the sorts differ");

    let words: Vec<u32> = (0..300_000u32).map(|i| i.wrapping_mul(2_654_435_761) >> 20).collect();
    assert!(exclusive_scan(&mut g, &words).unwrap() == exclusive_scan(&mut cpu, &words).unwrap(), "the scans differ");
    assert!(g.take_diagnostics().is_empty());
}

/// Every registered method, one frame through the one-shot path, on both backends: the same image
/// within float rounding (relative 1e-5, as the Vulkan suites allow; the splatting stages before the
/// accumulation are equal bit for bit, below).
#[test]
fn every_method_matches_the_cpu() {
    let Some(mut g) = wgpu() else { return };
    let mut cpu = CpuBackend::with_shared_bytes(g.limits().max_shared_bytes);
    let image = noise_with_sky(48, 32, 3);
    let lens = test_lens(0.02);
    let mut differing = Vec::new();
    for m in METHODS {
        let on_gpu = one_shot(&mut g, m, &MethodOptions::default(), &image, &lens).unwrap_or_else(|e| panic!("{} on wgpu: {e}", m.name));
        let on_cpu =
            one_shot(&mut cpu, m, &MethodOptions::default(), &image, &lens).unwrap_or_else(|e| panic!("{} on the CPU: {e}", m.name));
        let (a, b) = (on_gpu.image.data.as_flattened(), on_cpu.image.data.as_flattened());
        let worst = a
            .iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs() / y.abs().max(1e-2))
            .fold(0.0f32, |w, d| if d.is_nan() { f32::INFINITY } else { w.max(d) });
        let exact = a.iter().zip(b).filter(|(x, y)| x.to_bits() == y.to_bits()).count();
        eprintln!("{}: {exact} of {} values equal bit for bit, largest relative difference {worst:e}", m.name, a.len());
        if worst > 1e-5 {
            differing.push(format!("{}: largest relative difference {worst:e}", m.name));
        }
    }
    assert!(differing.is_empty(), "methods whose wgpu image differs from the CPU's:\n{}", differing.join("\n"));
    assert_eq!(g.counters().device_bytes, 0, "every context freed");
    assert!(g.take_diagnostics().is_empty());
}

/// The splatting stages on wgpu against the CPU, as the Vulkan suite checks them: packed and merged
/// cells, tile counts, the dense array, list lengths, the binned and the sorted lists bit for bit;
/// the image within float rounding.
#[test]
fn splatting_stages_match_the_cpu() {
    let Some(mut g) = wgpu() else { return };
    let img = noise_with_sky(61, 37, 3);
    for (merge, tile, aperture) in [(Merge::X4, 16, 0.01), (Merge::None, 24, 0.004), (Merge::X2, 32, 0.02)] {
        let o = SplatOptions { merge, tile, ..Default::default() };
        let on_gpu = splat_with_stages(&mut g, &img, &test_lens(aperture), &o).unwrap();
        let on_cpu = splat_with_stages(&mut CpuBackend::new(), &img, &test_lens(aperture), &o).unwrap();
        let (a, b) = (&on_gpu.intermediates, &on_cpu.intermediates);
        let what = format!("{merge:?}, tile {tile}");
        for (step, (x, y)) in a.cells.iter().zip(&b.cells).enumerate() {
            assert!(x == y, "cells after step {step} differ ({what})");
        }
        assert_eq!(a.tile_count, b.tile_count, "tile counts ({what})");
        assert!(a.dense == b.dense, "dense fragments ({what})");
        assert_eq!(a.list_lengths, b.list_lengths, "list lengths ({what})");
        assert!(a.binned == b.binned, "binned lists ({what})");
        assert!(a.sorted == b.sorted, "sorted lists ({what})");
        for (p, q) in on_gpu.image.data.iter().zip(&on_cpu.image.data) {
            for c in 0..3 {
                assert!((p[c] - q[c]).abs() <= 1e-5 * q[c].abs().max(1e-2), "{p:?} vs {q:?} ({what})");
            }
        }
    }
}

/// Every method recorded by a renderer into its own command encoder, on its own device and its own
/// buffers: the frame makes, submits, uploads and reads back nothing; outside the encoder it is
/// refused; the image is the CPU's within float rounding.
#[test]
fn a_renderer_records_every_method_into_its_own_encoder() {
    let Some((device, queue, info)) = wgpu_device() else { return };
    let mut backend = WgpuBackend::from_device(device.clone(), queue.clone(), info);
    let mut cpu = CpuBackend::with_shared_bytes(backend.limits().max_shared_bytes);
    let (w, h) = (40, 24);
    let lens = test_lens(0.02);
    for m in METHODS {
        let full = noise_with_sky(w, h, 3);
        let image = if m.reads == Reads::FrontLayer { full.front_layer() } else { full };
        // The renderer's buffers, filled by its own queue.
        let callers = |words: usize, data: &[u32]| {
            let usage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::COPY_SRC;
            let buffer = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("renderer's"),
                size: 4 * words as u64,
                usage,
                mapped_at_creation: false,
            });
            let bytes: Vec<u8> = data.iter().flat_map(|w| w.to_le_bytes()).collect();
            queue.write_buffer(&buffer, 0, &bytes);
            buffer
        };
        let slots = slot_words(&image);
        let pixels = (w * h) as usize;
        let bufs = [callers(slots.len(), &slots), callers(pixels, &image.counts), callers(3 * pixels, &[])];
        let [s, c, o] = bufs.each_ref().map(|b| backend.import_buffer(b, "renderer's").unwrap());
        let frame = Frame::layers(w, h, image.max_layers, lens, SlotBuffer::current(s), CountBuffer(c), RgbBuffer(o));
        let mut ctx = (m.create)(&mut backend, &ContextDesc::new(Extent::new(w, h, 3), MethodOptions::default())).unwrap();
        assert!(matches!(ctx.record(&mut backend, &frame), Err(CoreError::RecordingState(_))), "{}: a frame outside the encoder", m.name);

        let before = backend.counters();
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let mut recording = backend.record_into(&mut encoder).unwrap();
            ctx.record(&mut *recording, &frame).unwrap_or_else(|e| panic!("{}: {e}", m.name));
            assert!(matches!(recording.submit(), Err(CoreError::RecordingState(_))), "{}: a submission inside", m.name);
        }
        let spent = backend.counters().since(&before);
        assert_eq!((spent.allocations, spent.submissions, spent.uploads, spent.readbacks), (0, 0, 0, 0), "{}", m.name);
        assert!(spent.dispatches > 0, "{}: recorded into the encoder", m.name);
        queue.submit([encoder.finish()]);

        let got = read_rgb(&mut backend, o, w, h).unwrap();
        let want = one_shot(&mut cpu, m, &MethodOptions::default(), &image, &lens).unwrap();
        for (p, q) in got.data.iter().zip(&want.image.data) {
            for k in 0..3 {
                assert!((p[k] - q[k]).abs() <= 1e-5 * q[k].abs().max(1e-2), "{}: {p:?} against the CPU's {q:?}", m.name);
            }
        }
        ctx.destroy(&mut backend);
        [s, c, o].into_iter().for_each(|id| backend.destroy_buffer(id));
    }
    assert_eq!(backend.counters().device_bytes, 0, "every context freed, the renderer's buffers never counted");
    assert!(backend.take_diagnostics().is_empty());
}

/// Dispatches and spans carry GPU times where the device has timestamps (lavapipe has); a clear,
/// which has no pass to time, is NaN.
#[test]
fn dispatches_and_spans_are_timed() {
    let Some(mut g) = wgpu() else { return };
    let a = g.create_buffer(1 << 20, "a").unwrap();
    g.begin_span("both").unwrap();
    g.fill(a, 0, 1 << 20, 3, "threes").unwrap();
    g.fill(a, 0, 1 << 19, 0, "zeros").unwrap();
    g.fill(a, 0, 1 << 20, 5, "fives").unwrap();
    g.end_span().unwrap();
    let times = g.submit().unwrap();
    let ms: Vec<f64> = times.iter().map(|t| t.ms).collect();
    assert_eq!(times.iter().map(|t| t.label.as_str()).collect::<Vec<_>>(), ["threes", "zeros", "fives"]);
    assert!(ms[0] >= 0.0 && ms[2] >= 0.0 && ms[1].is_nan(), "{ms:?}");
    let spans = g.take_span_times();
    assert!(spans.len() == 1 && spans[0].ms >= ms[0].max(ms[2]), "{spans:?} over {ms:?}");
    assert!(g.submit().unwrap().is_empty() && g.take_span_times().is_empty());
    assert!(g.begin_span("open").is_ok() && g.submit().is_err(), "a span left open");
    g.destroy_buffer(a);
}

/// Input the numerical contract rejects or clamps (NaN and infinite colours, alphas and depths,
/// negative and huge colours) goes through every method on wgpu as on the CPU.
#[test]
fn non_finite_input_is_handled_as_on_the_cpu() {
    let Some(mut g) = wgpu() else { return };
    let mut cpu = CpuBackend::with_shared_bytes(g.limits().max_shared_bytes);
    let mut image = noise_with_sky(40, 24, 3);
    let bad = [f32::NAN, f32::INFINITY, -f32::INFINITY, -1.0, 3e38, 0.0, -0.0, f32::MIN_POSITIVE / 8.0];
    for (i, f) in image.fragments.iter_mut().enumerate().filter(|(i, _)| i % 7 == 3) {
        let v = bad[(i / 7) % bad.len()];
        match (i / 7) % 3 {
            0 => f.color[i % 3] = v,
            1 => f.alpha = v,
            _ => f.depth = v,
        }
    }
    let lens = test_lens(0.02);
    for m in METHODS {
        let on_gpu = one_shot(&mut g, m, &MethodOptions::default(), &image, &lens).unwrap_or_else(|e| panic!("{} on wgpu: {e}", m.name));
        let on_cpu =
            one_shot(&mut cpu, m, &MethodOptions::default(), &image, &lens).unwrap_or_else(|e| panic!("{} on the CPU: {e}", m.name));
        for (p, q) in on_gpu.image.data.iter().zip(&on_cpu.image.data) {
            for c in 0..3 {
                assert!(p[c].is_finite() && p[c] >= 0.0, "{}: {p:?}", m.name);
                assert!((p[c] - q[c]).abs() <= 1e-5 * q[c].abs().max(1e-2), "{}: {p:?} on wgpu, {q:?} on the CPU", m.name);
            }
        }
    }
}

/// The display kernel on wgpu gives the CPU's 0 and 1 for NaN, infinities, negatives and zeros,
/// with any exposure; elsewhere the sRGB curve's `powf` may differ in the last bit.
#[test]
fn the_display_kernel_handles_non_finite_values_as_on_the_cpu() {
    let Some(mut g) = wgpu() else { return };
    let values = [0.0, 1e-6, 0.18, 1.0, 7.3, 1e5, f32::NAN, -f32::NAN, f32::INFINITY, f32::NEG_INFINITY, -0.5, -0.0];
    let words: Vec<u32> = values.iter().flat_map(|&v| [v, v * 0.5, -v].map(f32::to_bits)).collect();
    let n = values.len() as u32;
    let run = |b: &mut dyn Backend| {
        let rgb = b.create_buffer(words.len() as u64, "rgb").unwrap();
        let rgba = b.create_buffer(4 * n as u64, "rgba").unwrap();
        b.write_buffer(rgb, 0, &words).unwrap();
        let mut out = Vec::new();
        for (mode, exposure) in [(MODE_TONEMAP, 1.0), (MODE_TONEMAP, f32::NAN), (MODE_LINEAR, 1.0)] {
            b.run(display_tonemap::Bindings { rgb, rgba }, [1, 1, 1], &DisplayParams { width: n, height: 1, mode, exposure }, "display")
                .unwrap();
            b.submit().unwrap();
            out.extend(b.read_buffer(rgba, 0, 4 * n as u64).unwrap());
        }
        out
    };
    let (on_gpu, on_cpu) = (run(&mut g), run(&mut CpuBackend::new()));
    for (i, (&a, &b)) in on_gpu.iter().zip(&on_cpu).enumerate() {
        let (x, y) = (f32::from_bits(a), f32::from_bits(b));
        let edge = y == 0.0 || y == 1.0;
        assert!(if edge { a == b } else { (x - y).abs() <= 1e-6 * y }, "word {i}: {x} on wgpu, {y} on the CPU");
    }
}
