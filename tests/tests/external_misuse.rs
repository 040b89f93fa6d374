//! Misuse of the frame API inside a renderer's recording, on Vulkan over the renderer's own device
//! and command buffer (`dof_tests::renderer`), for every method's context:
//! - every refused frame is refused before its first command: the backend's count of recorded
//!   commands does not move, so the renderer's command buffer is as it was, and the renderer goes on
//!   recording into it (a valid frame after the refused ones runs, validation silent);
//! - a context destroyed during the recording that uses it keeps its memory until the renderer's
//!   command buffer has completed, then `release_finished` frees it: the device bytes come back to
//!   where they were before the context was made;
//! - a frame refused by one of its commands (not by the frame-level checks) records none of them.

use dof::backend::vulkan::ash::vk;
use dof::backend::{Backend, BufferId, CpuBackend, ImageFormat, ImageRef, RawOptions, VulkanBackend};
use dof::frame::{
    ContextDesc, CountBuffer, DepthEncoding, Extent, Frame, FrameInput, FrameOutput, METHODS, MethodOptions, RgbBuffer, SlotBuffer,
};
use dof::methods::buffers::slot_words;
use dof_tests::renderer::{Renderer, assert_no_messages};

const W: u32 = 32;
const H: u32 = 24;

fn desc() -> ContextDesc {
    let mut desc = ContextDesc::new(Extent::new(W, H, 2), MethodOptions::default());
    desc.image_io = true;
    desc
}

#[test]
fn every_refused_frame_leaves_the_callers_command_buffer_untouched() {
    let Some(mut r) = Renderer::new() else { return };
    // SAFETY: the renderer's live handles outlive the backend, dropped after its work completed.
    let mut vk = unsafe { VulkanBackend::from_raw(r.raw(), &RawOptions::default()) }.expect("from_raw");
    let pixels = (W * H) as u64;
    let image = dof::stress::noise_with_sky(W, H, 2);
    let [fragments, counts, out, small] = [10 * pixels, pixels, 3 * pixels, 3].map(|w| vk.create_buffer(w, "caller").unwrap());
    vk.write_buffer(fragments, 0, &slot_words(&image)).unwrap();
    vk.write_buffer(counts, 0, &image.counts).unwrap();
    // The renderer's images, defined by its own pass (an upload) and left as its attachments are.
    let colour_image = r.image(ImageFormat::Rgba16Float, [W, H]);
    let depth_image = r.image(ImageFormat::D32Float, [W, H]);
    let output_image = r.image(ImageFormat::Rgba32Float, [W, H]);
    let staging = r.host_buffer(8 * pixels);
    // Half-float ones for the colour; read as f32 (about 0.0078) a reversed depth of about 12.8.
    Renderer::write(&staging, &vec![0x3c00_3c00; 2 * pixels as usize]);
    r.begin();
    let read = (vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL, vk::PipelineStageFlags::FRAGMENT_SHADER, vk::AccessFlags::SHADER_READ);
    r.upload_image(&staging, colour_image, ImageFormat::Rgba16Float, [W, H], read.0, read.1, read.2);
    r.upload_image(&staging, depth_image, ImageFormat::D32Float, [W, H], read.0, read.1, read.2);
    r.submit_and_wait();
    let describe = |image, format: ImageFormat, extent: [u32; 2], layout, leave| {
        let d = ImageRef::describe(image, format.vk_format(), extent).unwrap().in_layout(layout).leave_in(leave);
        // SAFETY: the renderer's live images of these formats, with transfer usage, in `layout`;
        // only the valid frame below copies them.
        unsafe { d.build() }
    };
    let ro = vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL;
    let colour = describe(colour_image, ImageFormat::Rgba16Float, [W, H], ro, ro);
    let depth = describe(depth_image, ImageFormat::D32Float, [W, H], ro, ro);
    let lens = dof::stress::test_lens(0.01);
    let layers = Frame::layers(W, H, 2, lens, SlotBuffer::current(fragments), CountBuffer(counts), RgbBuffer(out));
    let images = FrameInput::Images { color: colour, depth, encoding: DepthEncoding::Reversed { near: 0.1, far: f32::INFINITY } };
    let invalid: Vec<(&str, Frame)> = vec![
        ("larger than the context", Frame::layers(W + 1, H, 2, lens, SlotBuffer::current(fragments), CountBuffer(counts), RgbBuffer(out))),
        ("more layers than the context", Frame::layers(W, H, 3, lens, SlotBuffer::current(fragments), CountBuffer(counts), RgbBuffer(out))),
        ("an invalid lens", Frame { lens: dof::stress::test_lens(-1.0), ..layers }),
        ("an output buffer too small", Frame { output: FrameOutput::Buffer(RgbBuffer(small)), ..layers }),
        // Refused by the image copy's own check, while the frame is captured.
        (
            "an output image to be left UNDEFINED",
            Frame {
                output: FrameOutput::Image(describe(
                    output_image,
                    ImageFormat::Rgba32Float,
                    [W, H],
                    vk::ImageLayout::UNDEFINED,
                    vk::ImageLayout::UNDEFINED,
                )),
                ..layers
            },
        ),
        (
            "a depth attachment read as linear depth",
            Frame { input: FrameInput::Images { color: colour, depth, encoding: DepthEncoding::Linear }, ..layers },
        ),
        (
            "a depth format as colour",
            Frame {
                input: FrameInput::Images { color: depth, depth, encoding: DepthEncoding::Standard { near: 0.1, far: 10.0 } },
                ..layers
            },
        ),
        (
            "an image smaller than the frame",
            Frame {
                input: FrameInput::Images {
                    color: colour.top_left(W, H - 1),
                    depth,
                    encoding: DepthEncoding::Standard { near: 0.1, far: 10.0 },
                },
                ..layers
            },
        ),
    ];
    let mut cpu = CpuBackend::new();
    for method in METHODS {
        let mut ctx = (method.create)(&mut vk, &desc()).unwrap();
        let mut foreign = (method.create)(&mut cpu, &desc()).unwrap();
        // Outside a recording the frame would go into the backend's own command buffer: refused.
        let before = vk.counters();
        assert!(ctx.record(&mut vk, &layers).is_err(), "{}: a frame outside begin_external", method.name);
        assert_eq!(vk.counters().since(&before).commands, 0);
        r.begin();
        // SAFETY: the renderer's command buffer is recording, outside a render pass.
        unsafe { vk.begin_external(r.cb) }.expect("begin_external");
        for (what, f) in &invalid {
            let before = vk.counters();
            let refused = ctx.record(&mut vk, f);
            assert!(refused.is_err(), "{}: {what} was recorded", method.name);
            assert_eq!(
                vk.counters().since(&before).commands,
                0,
                "{}: {what} recorded commands before it was refused: {refused:?}",
                method.name
            );
        }
        let before = vk.counters();
        assert!(foreign.record(&mut vk, &layers).is_err(), "{}: a context of another backend", method.name);
        assert_eq!(vk.counters().since(&before).commands, 0, "{}: the foreign context recorded", method.name);
        // The command buffer goes on: a valid frame from images into the buffer, after the refusals.
        let before = vk.counters();
        ctx.record(&mut vk, &Frame { input: images, ..layers }).unwrap_or_else(|e| panic!("{}: {e}", method.name));
        assert!(vk.counters().since(&before).commands > 0, "{}: the valid frame recorded nothing", method.name);
        vk.end_external().expect("end_external");
        r.submit_and_wait();
        let rgb = vk.read_buffer(out, 0, 3 * pixels).unwrap();
        assert!(rgb.iter().any(|&w| f32::from_bits(w) > 0.0), "{}: the valid frame wrote nothing", method.name);
        assert_no_messages(r.messages(), &format!("after {}'s refused frames and its valid one", method.name));
        ctx.destroy(&mut vk);
        foreign.destroy(&mut cpu);
    }
    [fragments, counts, out, small].into_iter().for_each(|id| vk.destroy_buffer(id));
    drop(vk);
    assert_no_messages(r.finish(), "when the renderer destroyed its device");
}

#[test]
fn a_context_destroyed_mid_recording_is_freed_once_the_command_buffer_completed() {
    let Some(r) = Renderer::new() else { return };
    // SAFETY: as above.
    let mut vk = unsafe { VulkanBackend::from_raw(r.raw(), &RawOptions::default()) }.expect("from_raw");
    let pixels = (W * H) as u64;
    let image = dof::stress::noise_with_sky(W, H, 2);
    let [fragments, counts, out] = [10 * pixels, pixels, 3 * pixels].map(|w| vk.create_buffer(w, "caller").unwrap());
    vk.write_buffer(fragments, 0, &slot_words(&image)).unwrap();
    vk.write_buffer(counts, 0, &image.counts).unwrap();
    let frame = Frame::layers(W, H, 2, dof::stress::test_lens(0.01), SlotBuffer::current(fragments), CountBuffer(counts), RgbBuffer(out));
    for method in METHODS {
        let start = vk.counters().device_bytes;
        let ctx = (method.create)(&mut vk, &desc()).unwrap();
        let mut ctx = Some(ctx);
        r.begin();
        // SAFETY: the renderer's command buffer is recording, outside a render pass.
        unsafe { vk.begin_external(r.cb) }.expect("begin_external");
        ctx.as_mut().unwrap().record(&mut vk, &frame).unwrap();
        // Destroyed while the recording that uses it is open: the ids go, the memory stays.
        ctx.take().unwrap().destroy(&mut vk);
        vk.end_external().expect("end_external after a destroy");
        let held = vk.counters().device_bytes - start;
        assert!(held > 0, "{}: the recording's buffers were freed before it ran", method.name);
        assert_eq!(vk.release_finished().unwrap(), 0, "{}: freed before the command buffer ran", method.name);
        r.submit_and_wait();
        assert_eq!(vk.release_finished().unwrap(), held, "{}", method.name);
        assert_eq!(vk.counters().device_bytes, start, "{}: device bytes after completion", method.name);
        let rgb = vk.read_buffer(out, 0, 3 * pixels).unwrap();
        assert!(rgb.iter().any(|&w| f32::from_bits(w) > 0.0), "{}: the frame ran", method.name);
        assert_no_messages(r.messages(), method.name);
    }
    [fragments, counts, out].into_iter().for_each(|id| vk.destroy_buffer(id));
    drop(vk);
    assert_no_messages(r.finish(), "when the renderer destroyed its device (a leak would show here)");
}

/// Wider than 8 · 65 535 pixels: one-item-per-pixel grids of 8x8 tiles exceed the workgroup count.
const WIDE: (u32, u32) = (600_000, 1);

/// The wide frame's input in `b`'s buffers, and the buffers.
fn wide_frame(b: &mut dyn Backend) -> (Frame, [BufferId; 3]) {
    let (w, h) = WIDE;
    let image = dof::stress::noise_with_sky(w, h, 1);
    let pixels = (w * h) as u64;
    let bufs = [dof::methods::buffers::SLOT_WORDS as u64 * pixels, pixels, 3 * pixels].map(|n| b.create_buffer(n, "caller").unwrap());
    b.write_buffer(bufs[0], 0, &slot_words(&image)).unwrap();
    b.write_buffer(bufs[1], 0, &image.counts).unwrap();
    (Frame::layers(w, h, 1, dof::stress::test_lens(0.01), SlotBuffer::current(bufs[0]), CountBuffer(bufs[1]), RgbBuffer(bufs[2])), bufs)
}

fn wide_desc() -> ContextDesc {
    ContextDesc::new(Extent::new(WIDE.0, WIDE.1, 1), MethodOptions::default())
}

/// A frame that passes the frame-level checks but that a command of the method refuses (a dispatch
/// wider than the device's workgroup count, found only while recording) records nothing either:
/// capturing the frame's recording finds it first. On the CPU backend, which runs commands as they are recorded, nothing
/// runs. A method that places transient buffers records a frame of its largest extent when it is
/// made, so the ring gather is refused then, before any frame.
#[test]
fn a_frame_refused_by_one_of_its_commands_records_none_of_them() {
    let mut cpu = CpuBackend::new();
    let (frame, bufs) = wide_frame(&mut cpu);
    let mut refused = Vec::new();
    for method in METHODS {
        let Ok(mut ctx) = (method.create)(&mut cpu, &wide_desc()) else {
            refused.push(method.name);
            continue;
        };
        let before = cpu.counters();
        if let Err(e) = ctx.record(&mut cpu, &frame) {
            assert_eq!(cpu.counters().since(&before).commands, 0, "{}: commands ran before `{e}`", method.name);
            refused.push(method.name);
        }
        ctx.destroy(&mut cpu);
    }
    bufs.into_iter().for_each(|id| cpu.destroy_buffer(id));
    assert!(refused.contains(&"ring-gather") && refused.contains(&"gather"), "{refused:?}");
    eprintln!("cpu: refused at creation or by a command's check, nothing run: {refused:?}");
}

/// The same inside a renderer's recording on Vulkan: the command buffer gets none of the frame.
#[test]
fn a_frame_refused_by_one_of_its_commands_records_none_of_them_on_vulkan() {
    let Some(r) = Renderer::new() else { return };
    // SAFETY: the renderer's live handles outlive the backend, dropped after its work completed.
    let mut vk = unsafe { VulkanBackend::from_raw(r.raw(), &RawOptions::default()) }.expect("from_raw");
    let (frame, bufs) = wide_frame(&mut vk);
    let mut refused = Vec::new();
    for method in METHODS {
        let Ok(mut ctx) = (method.create)(&mut vk, &wide_desc()) else {
            refused.push(method.name);
            continue;
        };
        r.begin();
        // SAFETY: the renderer's command buffer is recording, outside a render pass.
        unsafe { vk.begin_external(r.cb) }.expect("begin_external");
        let before = vk.counters();
        if let Err(e) = ctx.record(&mut vk, &frame) {
            assert_eq!(vk.counters().since(&before).commands, 0, "{}: commands recorded before `{e}`", method.name);
            refused.push(method.name);
        }
        vk.end_external().unwrap();
        r.submit_and_wait();
        ctx.destroy(&mut vk);
    }
    bufs.into_iter().for_each(|id| vk.destroy_buffer(id));
    assert!(refused.contains(&"ring-gather") && refused.contains(&"gather"), "{refused:?}");
    eprintln!("vulkan: refused at creation or by a command's check, nothing recorded: {refused:?}");
    assert_no_messages(r.messages(), "after the wide frames");
    drop(vk);
    assert_no_messages(r.finish(), "when the renderer destroyed its device");
}
