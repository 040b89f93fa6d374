//! Frames in flight, for every method of the registry through `dyn DofContext`: a context made for
//! N frames keeps each of its last N frames' reports apart, and holds only the report buffers
//! more per extra frame.
//! - Two frames that differ (size, lens and, where the method has one, its knob) recorded back to
//!   back into one submission (standalone, and on Vulkan inside one external recording of a
//!   renderer's command buffer with synchronization validation on) each report what the same frame
//!   reports alone through a one-frame context, and write the same image.
//! - A renderer's loop with two command buffers and two fences on one queue, each frame submitted
//!   without waiting for the one before: each frame's report, read after its fence, is its own.
//! - A frame's report is refused once a later recording has taken its slot, and where no such
//!   frame was recorded; a one-frame context keeps only the last.
//! - Device bytes for 1, 2 and 3 frames in flight at 1920x1080 with 4 layers (3 on Vulkan) grow by the same
//!   step, under 1% of the context (printed for `docs/measurements.md`).

use dof::backend::vulkan::ash::vk;
use dof::backend::{Backend, BufferId, CpuBackend, RawOptions, VulkanBackend};
use dof::frame::{
    ContextDesc, ContextReport, CountBuffer, DofContext, Extent, Frame, MAX_FRAMES_IN_FLIGHT, METHODS, MethodInfo, MethodOptions, Reads,
    RgbBuffer, SlotBuffer,
};
use dof::methods::buffers::{read_rgb, slot_words};
use dof::stress::{noise_with_sky, test_lens};
use dof_tests::renderer::{Renderer, assert_no_messages};
use dof_tests::{assert_clean, vulkan};

const EXTENT: Extent = Extent { width: 48, height: 32, layers: 3 };

fn create(b: &mut dyn Backend, m: &MethodInfo, extent: Extent, frames: u32) -> Box<dyn DofContext> {
    let desc = ContextDesc { frames_in_flight: frames, ..ContextDesc::new(extent, MethodOptions::default()) };
    let ctx = (m.create)(b, &desc).unwrap_or_else(|e| panic!("{} with {frames} frames in flight: {e}", m.name));
    assert_eq!(ctx.frames_in_flight(), frames, "{}", m.name);
    ctx
}

/// Two frames that differ in size, lens and knob, each with its own input and output buffers
/// (frames in flight read and write the caller's buffers of their own frame).
struct TwoFrames {
    frames: [Frame; 2],
    buffers: Vec<BufferId>,
}

impl TwoFrames {
    fn new(b: &mut dyn Backend, m: &MethodInfo) -> Self {
        let mut buffers = Vec::new();
        let frames = [(48, 32, 0.01f32), (40, 24, 0.03)].map(|(w, h, aperture)| {
            let image = noise_with_sky(w, h, EXTENT.layers);
            let image = if m.reads == Reads::FrontLayer { image.front_layer() } else { image };
            let pixels = (w * h) as u64;
            let [fragments, counts, out] =
                [dof::methods::buffers::SLOT_WORDS as u64 * pixels * image.max_layers as u64, pixels, 3 * pixels]
                    .map(|words| b.create_buffer(words, "caller").unwrap());
            b.write_buffer(fragments, 0, &slot_words(&image)).unwrap();
            b.write_buffer(counts, 0, &image.counts).unwrap();
            buffers.extend([fragments, counts, out]);
            Frame::layers(w, h, image.max_layers, test_lens(aperture), SlotBuffer::current(fragments), CountBuffer(counts), RgbBuffer(out))
        });
        TwoFrames { frames, buffers }
    }

    /// Records frame `i` (its knob set first, where the method has one).
    fn record(&self, b: &mut dyn Backend, m: &MethodInfo, ctx: &mut dyn DofContext, i: usize) {
        if let Some(knob) = m.knob {
            ctx.set_knob(if i == 0 { knob.default } else { knob.min }).unwrap();
        }
        ctx.record(b, &self.frames[i]).unwrap_or_else(|e| panic!("{} frame {i}: {e}", m.name));
    }

    fn image(&self, b: &mut dyn Backend, i: usize) -> Vec<[f32; 3]> {
        let f = &self.frames[i];
        let dof::frame::FrameOutput::Buffer(RgbBuffer(out)) = f.output else { unreachable!() };
        read_rgb(b, out, f.width, f.height).unwrap().data
    }

    fn free(self, b: &mut dyn Backend) {
        self.buffers.into_iter().for_each(|id| b.destroy_buffer(id));
    }
}

/// Each frame alone through a one-frame context, submitted on its own: its report and image.
fn alone(b: &mut dyn Backend, m: &MethodInfo, two: &TwoFrames) -> Vec<(ContextReport, Vec<[f32; 3]>)> {
    let mut ctx = create(b, m, EXTENT, 1);
    let out = (0..2)
        .map(|i| {
            two.record(b, m, ctx.as_mut(), i);
            b.submit().unwrap();
            (ctx.report(b).unwrap(), two.image(b, i))
        })
        .collect::<Vec<_>>();
    ctx.destroy(b);
    assert!(out[0].0 != out[1].0, "{}: the two frames report the same, so the test could not tell them apart: {:?}", m.name, out[0].0);
    out
}

fn two_frames_keep_their_reports(b: &mut dyn Backend) {
    for m in METHODS {
        let two = TwoFrames::new(b, m);
        let reference = alone(b, m, &two);
        let mut ctx = create(b, m, EXTENT, 2);
        assert!(ctx.report_frame(b, 0).is_err(), "{}: a report before any frame", m.name);
        let before = b.counters();
        two.record(b, m, ctx.as_mut(), 0);
        two.record(b, m, ctx.as_mut(), 1);
        b.submit().unwrap();
        let spent = b.counters().since(&before);
        assert_eq!((spent.allocations, spent.readbacks, spent.uploads, spent.submissions), (0, 0, 0, 1), "{}", m.name);
        for (ago, i) in [(0, 1), (1, 0)] {
            assert_eq!(ctx.report_frame(b, ago).unwrap(), reference[i].0, "{}: the report of frame {i}, {ago} frames ago", m.name);
            assert!(two.image(b, i) == reference[i].1, "{}: frame {i}'s image differs from the frame alone", m.name);
        }
        assert_eq!(ctx.report(b).unwrap(), reference[1].0, "{}: report() is the last frame's", m.name);
        let gone = ctx.report_frame(b, 2).expect_err("a third frame back with two in flight").to_string();
        assert!(gone.contains("gone"), "{}: {gone}", m.name);
        // A third recording, in a submission of its own, takes the first frame's slot.
        two.record(b, m, ctx.as_mut(), 0);
        b.submit().unwrap();
        assert_eq!(ctx.report_frame(b, 0).unwrap(), reference[0].0, "{}: the third frame", m.name);
        assert_eq!(ctx.report_frame(b, 1).unwrap(), reference[1].0, "{}: the second frame after a third", m.name);
        ctx.destroy(b);
        // A one-frame context recording both keeps the last one's report only.
        let mut one = create(b, m, EXTENT, 1);
        two.record(b, m, one.as_mut(), 0);
        two.record(b, m, one.as_mut(), 1);
        b.submit().unwrap();
        assert_eq!(one.report(b).unwrap(), reference[1].0, "{}: one frame in flight", m.name);
        assert!(one.report_frame(b, 1).is_err(), "{}: one frame in flight keeps one report", m.name);
        one.destroy(b);
        two.free(b);
    }
    assert_eq!(b.counters().device_bytes, 0, "every context and buffer freed");
}

#[test]
fn two_frames_in_flight_keep_their_own_reports_on_the_cpu() {
    two_frames_keep_their_reports(&mut CpuBackend::new());
}

#[test]
fn two_frames_in_flight_keep_their_own_reports_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    two_frames_keep_their_reports(&mut vk);
    assert_clean(&mut vk);
}

/// Records `record` into one external recording of the renderer's command buffer, submits it and
/// waits.
fn recorded(vk: &mut VulkanBackend, r: &Renderer, record: &mut dyn FnMut(&mut VulkanBackend)) {
    r.begin();
    // SAFETY: the renderer's command buffer is recording, outside a render pass.
    unsafe { vk.begin_external(r.cb) }.expect("begin_external");
    record(vk);
    vk.end_external().expect("end_external");
    r.submit_and_wait();
}

/// Inside a renderer's command buffer: the two frames recorded back to back into one external
/// recording, one submission, each frame's report as when it runs alone in a recording of its own;
/// synchronization validation silent.
#[test]
fn two_frames_in_one_external_recording_keep_their_own_reports() {
    let Some(r) = Renderer::new() else { return };
    // SAFETY: the renderer's live handles outlive the backend, dropped after its work completed.
    let mut vk = unsafe { VulkanBackend::from_raw(r.raw(), &RawOptions::default()) }.expect("from_raw");
    for m in METHODS {
        let two = TwoFrames::new(&mut vk, m);
        let mut one = create(&mut vk, m, EXTENT, 1);
        let mut reference = Vec::new();
        for i in 0..2 {
            recorded(&mut vk, &r, &mut |vk| two.record(vk, m, one.as_mut(), i));
            reference.push((one.report(&mut vk).unwrap(), two.image(&mut vk, i)));
        }
        one.destroy(&mut vk);
        let mut ctx = create(&mut vk, m, EXTENT, 2);
        recorded(&mut vk, &r, &mut |vk| {
            two.record(vk, m, ctx.as_mut(), 0);
            two.record(vk, m, ctx.as_mut(), 1);
        });
        for (ago, i) in [(0, 1), (1, 0)] {
            assert_eq!(ctx.report_frame(&mut vk, ago).unwrap(), reference[i].0, "{}: frame {i} of one recording", m.name);
            assert!(two.image(&mut vk, i) == reference[i].1, "{}: frame {i}'s image of one recording", m.name);
        }
        assert_no_messages(r.messages(), &format!("{}: two frames in one recording", m.name));
        ctx.destroy(&mut vk);
        two.free(&mut vk);
    }
    drop(vk);
    assert_no_messages(r.finish(), "the end");
}

/// A renderer's loop with two command buffers and two fences on one queue: each frame is
/// submitted without waiting for the one before, so two frames of one context run at once
/// (sharing its transient buffers, ordered by the recordings' barriers). After waiting on a
/// slot's fence, the frame that used it is `report_frame(backend, 1)` and equals that frame alone;
/// synchronization validation stays silent.
#[test]
fn two_frames_running_at_once_keep_their_own_reports() {
    let Some(r) = Renderer::new() else { return };
    let raw = r.raw();
    // SAFETY: the renderer's live handles outlive the backend, dropped after its work completed.
    let mut vk = unsafe { VulkanBackend::from_raw(raw.clone(), &RawOptions::default()) }.expect("from_raw");
    let d = &r.device;
    // SAFETY: plain creation calls on the renderer's live device; destroyed below, once idle.
    let (pool, cbs, fences) = unsafe {
        let info = vk::CommandPoolCreateInfo::default()
            .queue_family_index(raw.queue_family)
            .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER);
        let pool = d.create_command_pool(&info, None).expect("vkCreateCommandPool");
        let alloc =
            vk::CommandBufferAllocateInfo::default().command_pool(pool).level(vk::CommandBufferLevel::PRIMARY).command_buffer_count(2);
        let cbs = d.allocate_command_buffers(&alloc).expect("vkAllocateCommandBuffers");
        let signalled = vk::FenceCreateInfo::default().flags(vk::FenceCreateFlags::SIGNALED);
        let fences = [0, 1].map(|_| d.create_fence(&signalled, None).expect("vkCreateFence"));
        (pool, cbs, fences)
    };
    for m in METHODS {
        let two = TwoFrames::new(&mut vk, m);
        let mut one = create(&mut vk, m, EXTENT, 1);
        let mut reference = Vec::new();
        for i in 0..2 {
            recorded(&mut vk, &r, &mut |vk| two.record(vk, m, one.as_mut(), i));
            reference.push(one.report(&mut vk).unwrap());
        }
        one.destroy(&mut vk);
        let mut ctx = create(&mut vk, m, EXTENT, 2);
        for frame in 0..6 {
            let slot = frame % 2;
            // SAFETY: the fence belongs to the live device; its submission (if any) is in flight.
            unsafe {
                d.wait_for_fences(&[fences[slot]], true, u64::MAX).expect("vkWaitForFences");
                d.reset_fences(&[fences[slot]]).expect("vkResetFences");
            }
            if frame >= 2 {
                // Frame - 2 ran frame `slot` of the two; frame - 1 may still be running.
                let report = ctx.report_frame(&mut vk, 1).unwrap();
                assert_eq!(report, reference[slot], "{}: frame {} read after its fence", m.name, frame - 2);
            }
            // SAFETY: the command buffer's last submission completed (its fence); recorded here
            // outside a render pass, submitted to the queue the backend wraps.
            unsafe {
                d.reset_command_buffer(cbs[slot], vk::CommandBufferResetFlags::empty()).expect("reset");
                let begin = vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
                d.begin_command_buffer(cbs[slot], &begin).expect("vkBeginCommandBuffer");
                vk.begin_external(cbs[slot]).expect("begin_external");
                two.record(&mut vk, m, ctx.as_mut(), slot);
                vk.end_external().expect("end_external");
                d.end_command_buffer(cbs[slot]).expect("vkEndCommandBuffer");
                let cb = [cbs[slot]];
                let submit = [vk::SubmitInfo::default().command_buffers(&cb)];
                d.queue_submit(raw.queue, &submit, fences[slot]).expect("vkQueueSubmit");
            }
        }
        // SAFETY: both fences belong to the live device.
        unsafe { d.wait_for_fences(&fences, true, u64::MAX) }.expect("vkWaitForFences");
        for (ago, i) in [(0, 1), (1, 0)] {
            assert_eq!(ctx.report_frame(&mut vk, ago).unwrap(), reference[i], "{}: the last frames", m.name);
        }
        assert_no_messages(r.messages(), &format!("{}: two frames running at once", m.name));
        ctx.destroy(&mut vk);
        two.free(&mut vk);
    }
    drop(vk);
    // SAFETY: the device is idle (every fence waited on) and the handles are ours.
    unsafe {
        d.device_wait_idle().expect("vkDeviceWaitIdle");
        fences.iter().for_each(|&f| d.destroy_fence(f, None));
        d.destroy_command_pool(pool, None);
    }
    assert_no_messages(r.finish(), "the end");
}

#[test]
fn frames_in_flight_out_of_range_are_refused_before_anything_is_allocated() {
    let mut b = CpuBackend::new();
    for m in METHODS {
        for frames in [0, MAX_FRAMES_IN_FLIGHT + 1] {
            let desc = ContextDesc { frames_in_flight: frames, ..ContextDesc::new(EXTENT, MethodOptions::default()) };
            let e = (m.create)(&mut b, &desc).err().unwrap_or_else(|| panic!("{}: {frames} frames in flight", m.name)).to_string();
            assert!(e.contains("frames in flight"), "{}: {e}", m.name);
            assert_eq!(b.counters().allocations, 0, "{}: allocated before refusing", m.name);
        }
    }
}

/// Device bytes of each method's context for 1, 2 and 3 frames in flight at `extent`: what the
/// backend holds for it, growing by one step of report buffers per frame, under 1% of the context
/// (for the ring gather only its count of clamped input colours).
fn bytes_per_frame_in_flight(b: &mut dyn Backend, extent: Extent) {
    for m in METHODS {
        let bytes = [1, 2, 3].map(|frames| {
            let before = b.counters().device_bytes;
            let ctx = create(b, m, extent, frames);
            let held = b.counters().device_bytes - before;
            assert_eq!(ctx.device_bytes(), held, "{} with {frames} frames in flight: the bytes it reports", m.name);
            ctx.destroy(b);
            held
        });
        let step = bytes[1] - bytes[0];
        assert_eq!(bytes[2] - bytes[1], step, "{}: {bytes:?}", m.name);
        assert!(step * 100 < bytes[0], "{}: a frame in flight adds {step} bytes to {}", m.name, bytes[0]);
        // Every report reads something on the device (at least the count of clamped colours).
        assert!(step > 0, "{}: {step} bytes a frame in flight", m.name);
        eprintln!(
            "{} {}x{}x{} {}: device bytes for 1, 2, 3 frames in flight: {} {} {} (+{step} a frame)",
            b.kind(),
            extent.width,
            extent.height,
            extent.layers,
            m.name,
            bytes[0],
            bytes[1],
            bytes[2]
        );
    }
}

#[test]
fn a_frame_in_flight_adds_only_its_report_buffers_at_1080p_on_the_cpu() {
    bytes_per_frame_in_flight(&mut CpuBackend::new(), Extent::new(1920, 1080, 4));
}

#[test]
fn a_frame_in_flight_adds_only_its_report_buffers_at_1080p_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    // 3 layers: 4 of 20-byte slots (166 MB) exceed lavapipe's 128 MiB storage-buffer range, and
    // the single-layer contexts refuse an extent whose input could not be bound.
    bytes_per_frame_in_flight(&mut vk, Extent::new(1920, 1080, 3));
    assert_clean(&mut vk);
}
