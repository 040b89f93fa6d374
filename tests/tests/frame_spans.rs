//! Spans (`Backend::begin_span`/`end_span`): one time around a whole recording, what `dof bench
//! frame` reports as the frame time. A splatting frame recorded inside a span on both backends: the
//! span comes back once per submission, finite and non-negative; on the CPU backend (which runs
//! the kernels as it records) it is at least the sum of its commands' times, on Vulkan at least
//! the longest of its commands and at most the host's wall time around recording and submission.
//! Misuse is refused with an error.

use dof::backend::{Backend, CpuBackend, SPAN};
use dof::frame::Extent;
use dof::frame::{CountBuffer, DofContext, Frame, RgbBuffer, SlotBuffer, SplatContext, SplatContextDesc};
use dof::methods::buffers::{SLOT_WORDS, slot_words};
use dof::methods::splat::{Merge, SplatOptions};
use dof::stress::{noise_with_sky, test_lens};
use dof_tests::{assert_clean, vulkan};
use std::time::Instant;

/// What a span and its frame's commands measured.
struct Timed {
    span_ms: f64,
    command_ms: Vec<f64>,
    wall_ms: f64,
}

/// Three frames of a splatting context, each inside a span, with a command recorded outside the
/// span before it (which the span must not include).
fn spanned_frames(b: &mut dyn Backend) -> Vec<Timed> {
    let (w, h, l) = (96, 54, 3);
    let image = noise_with_sky(w, h, l);
    let pixels = w as u64 * h as u64;
    let bufs = [
        b.create_buffer(SLOT_WORDS as u64 * pixels * l as u64, "caller/fragments").unwrap(),
        b.create_buffer(pixels, "caller/counts").unwrap(),
        b.create_buffer(3 * pixels, "caller/output").unwrap(),
    ];
    b.write_buffer(bufs[0], 0, &slot_words(&image)).unwrap();
    b.write_buffer(bufs[1], 0, &image.counts).unwrap();
    let options = SplatOptions { merge: Merge::X2, ..Default::default() };
    let mut ctx = SplatContext::new(b, &SplatContextDesc::new(Extent::new(w, h, l), options)).unwrap();
    let frame = Frame::layers(w, h, l, test_lens(0.02), SlotBuffer::current(bufs[0]), CountBuffer(bufs[1]), RgbBuffer(bufs[2]));
    let mut out = Vec::new();
    for _ in 0..3 {
        let start = Instant::now();
        b.fill(bufs[2], 0, 3 * pixels, 0, "outside").unwrap();
        b.begin_span("frame").unwrap();
        ctx.record(b, &frame).unwrap();
        b.end_span().unwrap();
        let times = b.submit().unwrap();
        let wall_ms = start.elapsed().as_secs_f64() * 1e3;
        let spans = b.take_span_times();
        assert_eq!(spans.len(), 1, "one span a submission: {spans:?}");
        assert_eq!((spans[0].label.as_str(), spans[0].kernel), ("frame", SPAN));
        assert!(b.take_span_times().is_empty(), "spans are taken once");
        assert!(times.iter().all(|t| t.kernel != SPAN), "spans are not among the commands' times");
        let command_ms = times.iter().filter(|t| t.label != "outside").map(|t| t.ms).collect::<Vec<_>>();
        assert!(command_ms.len() > 5, "a splatting frame records its stages: {times:?}");
        out.push(Timed { span_ms: spans[0].ms, command_ms, wall_ms });
    }
    ctx.destroy(b);
    bufs.iter().for_each(|&id| b.destroy_buffer(id));
    out
}

/// Misuse: closing what is not open, submitting (or reading back, which submits) inside a span.
fn misuse_is_refused(b: &mut dyn Backend) {
    assert!(b.end_span().is_err(), "end_span without begin_span");
    let a = b.create_buffer(4, "a").unwrap();
    b.begin_span("open").unwrap();
    b.fill(a, 0, 4, 1, "fill").unwrap();
    let err = b.submit().unwrap_err().to_string();
    assert!(err.contains("span"), "{err}");
    b.end_span().unwrap();
    b.submit().unwrap();
    assert_eq!(b.take_span_times().len(), 1);
    // Nested spans come back in the order they were opened, the outer one the longer.
    b.begin_span("outer").unwrap();
    b.fill(a, 0, 4, 2, "fill").unwrap();
    b.begin_span("inner").unwrap();
    b.fill(a, 0, 4, 3, "fill").unwrap();
    b.end_span().unwrap();
    b.end_span().unwrap();
    b.submit().unwrap();
    let spans = b.take_span_times();
    assert_eq!(spans.iter().map(|s| s.label.as_str()).collect::<Vec<_>>(), ["outer", "inner"]);
    if spans.iter().all(|s| s.ms.is_finite()) {
        assert!(spans[0].ms >= spans[1].ms, "{spans:?}");
    }
    assert_eq!(b.read_buffer(a, 0, 4).unwrap(), vec![3; 4]);
    b.destroy_buffer(a);
}

#[test]
fn cpu_span_covers_its_commands() {
    let mut cpu = CpuBackend::new();
    for t in spanned_frames(&mut cpu) {
        let sum: f64 = t.command_ms.iter().sum();
        assert!(t.span_ms.is_finite() && t.span_ms >= 0.0, "{}", t.span_ms);
        // The commands run inside the span, one after the other: the span holds them all, give or
        // take the clock's rounding per command.
        let tolerance = 1e-3 * t.command_ms.len() as f64;
        assert!(t.span_ms + tolerance >= sum, "span {} ms < its commands' {sum} ms", t.span_ms);
        assert!(t.span_ms <= t.wall_ms, "span {} ms > the wall time {} ms around it", t.span_ms, t.wall_ms);
    }
    misuse_is_refused(&mut cpu);
}

#[test]
fn vulkan_span_is_one_timestamp_pair_around_the_recording() {
    let Some(mut vk) = vulkan() else { return };
    for t in spanned_frames(&mut vk) {
        let longest = t.command_ms.iter().copied().fold(0.0, f64::max);
        assert!(t.span_ms.is_finite() && t.span_ms >= 0.0, "{}", t.span_ms);
        // The span's stamps bracket every command's own (bottom of pipe, in order on the queue),
        // and the device ran the frame between the recording's start and `submit` returning.
        assert!(t.span_ms + 1e-3 >= longest, "span {} ms < its longest command's {longest} ms", t.span_ms);
        assert!(t.span_ms <= t.wall_ms, "span {} ms > the host's {} ms around recording and submission", t.span_ms, t.wall_ms);
    }
    misuse_is_refused(&mut vk);
    assert_clean(&mut vk);
}
