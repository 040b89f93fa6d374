//! The frame API: a splatting context records frame after frame with no allocation, no readback and
//! one submission; it resizes within its bounds; an overflowing list pool is counted and degrades
//! to copied-through tiles instead of writing out of bounds; and every result equals the one-shot
//! path's on both backends.

use dof::CoreError;
use dof::backend::{Backend, BufferId, CpuBackend};
use dof::frame::Extent;
use dof::frame::{CountBuffer, DofContext, Frame, FrameInput, FrameOutput, RgbBuffer, SlotBuffer, SplatContext, SplatContextDesc};
use dof::layers::LayeredImage;
use dof::methods::buffers::{read_rgb, slot_words};
use dof::methods::splat::{Merge, SplatOptions, splat};
use dof::stress::{noise_with_sky, test_lens};
use dof_tests::{assert_clean, vulkan};

/// The caller's buffers for a frame of `image`, sized for `max` (width, height, layers).
fn caller_buffers(b: &mut dyn Backend, max: (u32, u32, u32)) -> [BufferId; 3] {
    let pixels = max.0 as u64 * max.1 as u64;
    [
        b.create_buffer(dof::methods::buffers::SLOT_WORDS as u64 * pixels * max.2 as u64, "caller/fragments").unwrap(),
        b.create_buffer(pixels, "caller/counts").unwrap(),
        b.create_buffer(3 * pixels, "caller/output").unwrap(),
    ]
}

fn upload(b: &mut dyn Backend, bufs: &[BufferId; 3], image: &LayeredImage) {
    b.write_buffer(bufs[0], 0, &slot_words(image)).unwrap();
    b.write_buffer(bufs[1], 0, &image.counts).unwrap();
}

fn frame(image: &LayeredImage, aperture: f32, bufs: &[BufferId; 3]) -> Frame {
    Frame::layers(
        image.width,
        image.height,
        image.max_layers,
        test_lens(aperture),
        SlotBuffer::current(bufs[0]),
        CountBuffer(bufs[1]),
        RgbBuffer(bufs[2]),
    )
}

/// Frames of changing size, layer count and lens through one context: per frame no allocation, no
/// readback, no upload and exactly one submission, and each image equals the one-shot path's.
fn frames_through_one_context(b: &mut dyn Backend) {
    let options = SplatOptions { merge: Merge::X4, ..Default::default() };
    let max = (70, 45, 3);
    let bufs = caller_buffers(b, max);
    let mut ctx = SplatContext::new(b, &SplatContextDesc::new(Extent::new(max.0, max.1, max.2), options.clone())).unwrap();
    let cases = [((70, 45, 3), 0.02), ((33, 20, 2), 0.01), ((70, 45, 3), 0.0), ((64, 40, 1), 0.03), ((70, 45, 3), 0.02)];
    for (i, &((w, h, l), aperture)) in cases.iter().enumerate() {
        let image = noise_with_sky(w, h, l);
        upload(b, &bufs, &image);
        let f = frame(&image, aperture, &bufs);
        let before = b.counters();
        ctx.record(b, &f).unwrap();
        b.submit().unwrap();
        let spent = b.counters().since(&before);
        assert_eq!((spent.allocations, spent.readbacks, spent.uploads, spent.submissions), (0, 0, 0, 1), "frame {i} ({w}x{h}, {l} layers)");
        let got = read_rgb(b, bufs[2], w, h).unwrap();
        let report = ctx.report(b).unwrap();
        assert_eq!(report.overflow_tiles, 0, "frame {i}");
        let expected = splat(b, &image, &test_lens(aperture), &options).unwrap();
        assert!(got.data == expected.image.data, "frame {i} ({w}x{h}, {l} layers, aperture {aperture}) differs from the one-shot path");
        assert_eq!(report.list_entries, expected.report.list_entries, "frame {i}");
    }
    ctx.destroy(b);
    bufs.iter().for_each(|&id| b.destroy_buffer(id));
}

#[test]
fn a_context_records_frames_without_allocating_or_reading_back() {
    frames_through_one_context(&mut CpuBackend::new());
}

#[test]
fn a_context_records_frames_without_allocating_or_reading_back_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    frames_through_one_context(&mut vk);
    assert_clean(&mut vk);
}

/// A pool too small for the frame: the lists that do not fit are thinned, and those that fit even
/// so nowhere are copied through (their sharp fronts), both counted; the others are splatted as
/// usual, nothing is written out of bounds (the CPU backend checks every index), and the one-shot
/// path reruns with the pool the frame wanted.
#[test]
fn an_overflowing_list_pool_is_counted_and_degrades_to_thinned_or_copied_tiles() {
    let mut b = CpuBackend::new();
    let image = noise_with_sky(64, 48, 3);
    let options = SplatOptions::default();
    let bufs = caller_buffers(&mut b, (64, 48, 3));
    upload(&mut b, &bufs, &image);
    let mut desc = SplatContextDesc::new(Extent::new(64, 48, 3), options.clone());
    desc.list_entries = Some(3000);
    let mut ctx = SplatContext::new(&mut b, &desc).unwrap();
    ctx.record(&mut b, &frame(&image, 0.02, &bufs)).unwrap();
    b.submit().unwrap();
    let report = ctx.report(&mut b).unwrap();
    let got = read_rgb(&mut b, bufs[2], 64, 48).unwrap();
    assert!(report.overflow_tiles > 0 && report.overflow_entries > 0, "{report:?}");
    assert!(report.list_entries <= 3000, "{} entries placed in a pool of 3000", report.list_entries);
    assert!(report.summary().contains("OVERFLOW"));
    let front = image.front().0;
    let whole = splat(&mut b, &image, &test_lens(0.02), &options).unwrap();
    assert_eq!(whole.report.overflow_tiles, 0, "the one-shot path reruns with a larger pool");
    // Every tile is either the whole frame's (splatted in the pool) or its sharp fronts (overflow).
    let tiles_x = 64usize.div_ceil(16);
    let mut overflowed = 0;
    for ty in 0..48usize.div_ceil(16) {
        for tx in 0..tiles_x {
            let pixels: Vec<usize> =
                (ty * 16..(ty * 16 + 16).min(48)).flat_map(|y| (tx * 16..(tx * 16 + 16).min(64)).map(move |x| y * 64 + x)).collect();
            let same = pixels.iter().all(|&p| got.data[p] == whole.image.data[p]);
            if !same {
                overflowed += 1;
                for &p in &pixels {
                    assert!(got.data[p].iter().all(|c| c.is_finite()), "pixel {p} of an overflowing tile is not finite");
                }
            }
        }
    }
    assert!(
        overflowed > 0 && overflowed <= report.tiles_cut_short() as usize,
        "{overflowed} tiles differ, {} thinned, {} overflowed",
        report.thinned_tiles,
        report.overflow_tiles
    );
    assert!(got.data.iter().zip(&front.data).any(|(a, b)| a == b));
    ctx.destroy(&mut b);
}

#[test]
fn frames_beyond_the_context_or_its_buffers_are_refused() {
    let mut b = CpuBackend::new();
    let options = SplatOptions::default();
    let mut ctx = SplatContext::new(&mut b, &SplatContextDesc::new(Extent::new(32, 32, 2), options.clone())).unwrap();
    let image = noise_with_sky(40, 20, 2);
    let bufs = caller_buffers(&mut b, (40, 20, 2));
    upload(&mut b, &bufs, &image);
    match ctx.record(&mut b, &frame(&image, 0.01, &bufs)) {
        Err(CoreError::ResizeNeeded { frame, context }) => {
            assert_eq!((frame, context), (dof::frame::Extent::new(40, 20, 2), dof::frame::Extent::new(32, 32, 2)))
        }
        other => panic!("{other:?}"),
    }
    ctx.resize(&mut b, 40, 20, 2).unwrap();
    ctx.record(&mut b, &frame(&image, 0.01, &bufs)).unwrap();
    b.submit().unwrap();
    let small = caller_buffers(&mut b, (8, 8, 1));
    let short = Frame { output: FrameOutput::Buffer(RgbBuffer(small[2])), ..frame(&image, 0.01, &bufs) };
    assert!(matches!(ctx.record(&mut b, &short), Err(CoreError::InvalidArgument(m)) if m.contains("output")));
    let nan_lens = Frame { lens: test_lens(f32::NAN), ..frame(&image, 0.01, &bufs) };
    assert!(matches!(ctx.record(&mut b, &nan_lens), Err(CoreError::InvalidLens(_))));
    assert!(matches!(
        SplatContext::new(&mut b, &SplatContextDesc::new(Extent::new(0, 10, 1), options.clone())),
        Err(CoreError::InvalidArgument(_))
    ));
    assert!(matches!(
        SplatContext::new(&mut b, &SplatContextDesc::new(Extent::new(100_000, 10, 1), options.clone())),
        Err(CoreError::TooLarge { .. })
    ));
    let mut huge_pool = SplatContextDesc::new(Extent::new(16, 16, 1), options);
    huge_pool.list_entries = Some(1 << 40);
    assert!(matches!(SplatContext::new(&mut b, &huge_pool), Err(CoreError::TooLarge { .. })));
    ctx.destroy(&mut b);
}

/// The context's memory is what it reports, and it does not grow frame after frame.
#[test]
fn the_context_holds_its_memory_and_no_more() {
    let mut b = CpuBackend::new();
    let start = b.counters().device_bytes;
    let ctx =
        SplatContext::new(&mut b, &SplatContextDesc::new(Extent::new(96, 64, 4), SplatOptions { merge: Merge::X4, ..Default::default() }))
            .unwrap();
    assert_eq!(b.counters().device_bytes - start, ctx.device_bytes());
    ctx.destroy(&mut b);
    assert_eq!(b.counters().device_bytes, start);
}

/// Image inputs and outputs need a context that holds their buffers, and the CPU backend refuses
/// images it did not make (a Vulkan handle here) with a clear error rather than running on garbage.
#[test]
fn image_frames_need_image_io_and_a_backend_with_images() {
    use dof::backend::{ImageFormat, ImageRef};
    use dof::frame::DepthEncoding;
    let mut b = CpuBackend::new();
    let options = SplatOptions::default();
    // SAFETY: the handles are never used: both records are refused before any command.
    let image = |format| unsafe {
        ImageRef::vulkan(
            dof::backend::vulkan::ash::vk::Image::null(),
            format,
            [16, 16],
            dof::backend::vulkan::ash::vk::ImageLayout::GENERAL,
            dof::backend::vulkan::ash::vk::PipelineStageFlags::empty(),
            dof::backend::vulkan::ash::vk::AccessFlags::empty(),
            dof::backend::vulkan::ash::vk::ImageLayout::GENERAL,
        )
    };
    let f = Frame {
        width: 16,
        height: 16,
        lens: test_lens(0.01),
        input: FrameInput::Images {
            color: image(ImageFormat::Rgba32Float),
            depth: image(ImageFormat::R32Float),
            encoding: DepthEncoding::Linear,
        },
        output: FrameOutput::Image(image(ImageFormat::Rgba32Float)),
    };
    let mut plain = SplatContext::new(&mut b, &SplatContextDesc::new(Extent::new(16, 16, 1), options.clone())).unwrap();
    assert!(matches!(plain.record(&mut b, &f), Err(CoreError::InvalidArgument(m)) if m.contains("image_io")));
    let mut desc = SplatContextDesc::new(Extent::new(16, 16, 1), options);
    desc.image_io = true;
    let mut with_io = SplatContext::new(&mut b, &desc).unwrap();
    let wrong = Frame {
        input: FrameInput::Images {
            color: image(ImageFormat::R32Float),
            depth: image(ImageFormat::R32Float),
            encoding: DepthEncoding::Linear,
        },
        ..f
    };
    assert!(matches!(with_io.record(&mut b, &wrong), Err(CoreError::InvalidArgument(m)) if m.contains("colour")));
    let planes = Frame {
        input: FrameInput::Images {
            color: image(ImageFormat::Rgba32Float),
            depth: image(ImageFormat::R32Float),
            encoding: DepthEncoding::Reversed { near: 0.0, far: 10.0 },
        },
        ..f
    };
    assert!(matches!(with_io.record(&mut b, &planes), Err(CoreError::InvalidArgument(m)) if m.contains("near")));
    assert!(with_io.record(&mut b, &f).is_err(), "not an image of the CPU backend's");
    plain.destroy(&mut b);
    with_io.destroy(&mut b);
}

/// Depth-buffer values become view depth: both conventions, finite and infinite far planes, and
/// the background where an infinite projection puts nothing.
#[test]
fn depth_buffers_decode_to_view_depth() {
    use dof_shaders::frame_io::{DEPTH_REVERSED, DEPTH_STANDARD, FrameIoParams, view_depth};
    let p =
        |enc, far| FrameIoParams { width: 1, height: 1, color_words: 4, depth_encoding: enc, near: 0.1, far, layers: 1, depth_format: 0 };
    for (enc, near_value) in [(DEPTH_STANDARD, 0.0), (DEPTH_REVERSED, 1.0)] {
        for far in [50.0f32, f32::INFINITY] {
            let q = p(enc, far);
            assert!((view_depth(&q, near_value) - 0.1).abs() < 1e-6, "near plane ({enc}, far {far})");
            let at_far = view_depth(&q, 1.0 - near_value);
            assert!(
                if far.is_finite() { (at_far - far).abs() < 1e-3 * far } else { at_far == f32::INFINITY },
                "far plane ({enc}, far {far}): {at_far}"
            );
            // A point at view depth 2: its depth value, and back.
            let z = 2.0f32;
            let d = if far.is_finite() { (1.0 / 0.1 - 1.0 / z) / (1.0 / 0.1 - 1.0 / far) } else { 1.0 - 0.1 / z };
            let d = if enc == DEPTH_REVERSED { 1.0 - d } else { d };
            assert!((view_depth(&q, d) - z).abs() < 1e-4, "{enc}, far {far}: {} for {d}", view_depth(&q, d));
            assert!(view_depth(&q, 1.5).is_nan() && view_depth(&q, f32::NAN).is_nan() && view_depth(&q, -0.1).is_nan());
        }
    }
}

/// The gathering baseline through its context: frames of a multi-layer input (it reads the front
/// slot) with no allocation or readback, each equal to the one-shot gather of the front layer,
/// with the window radius reduced on the device.
#[test]
fn a_gather_context_records_frames_like_the_one_shot_gather() {
    use dof::frame::{GatherContext, GatherContextDesc};
    use dof::methods::gather::{MAX_RADIUS, gather, needed_radius};
    let mut b = CpuBackend::new();
    let bufs = caller_buffers(&mut b, (50, 30, 3));
    let mut ctx = GatherContext::new(&mut b, &GatherContextDesc::new(Extent::new(50, 30, 3))).unwrap();
    for (i, (w, h, l, aperture)) in [(50u32, 30u32, 3u32, 0.02f32), (24, 17, 2, 0.005), (50, 30, 1, 0.0)].into_iter().enumerate() {
        let image = noise_with_sky(w, h, l);
        upload(&mut b, &bufs, &image);
        let before = b.counters();
        ctx.record(&mut b, &frame(&image, aperture, &bufs)).unwrap();
        b.submit().unwrap();
        let spent = b.counters().since(&before);
        assert_eq!((spent.allocations, spent.readbacks, spent.submissions), (0, 0, 1), "frame {i}");
        let got = read_rgb(&mut b, bufs[2], w, h).unwrap();
        let (front, depth) = image.front();
        let expected = gather(&mut b, &front, &depth, &test_lens(aperture), None).unwrap();
        assert!(got.data == expected.image.data, "frame {i} differs from the one-shot gather");
        assert_eq!(ctx.radius(&mut b).unwrap(), needed_radius(&test_lens(aperture), &depth, MAX_RADIUS), "frame {i}");
    }
    ctx.destroy(&mut b);
}

/// Bokeh sprites through their context, on both backends: after the first frame, frames with no
/// allocation or readback and one submission, each equal to the one-shot path (the sprite draw is
/// the graphics pipeline on Vulkan).
fn bokeh_frames(b: &mut dyn Backend) {
    use dof::frame::{BokehContext, BokehContextDesc};
    use dof::methods::bokeh::{BokehOptions, bokeh};
    let options = BokehOptions { lum_threshold: 0.2, coc_threshold: 1.0, ..Default::default() };
    let bufs = caller_buffers(b, (48, 32, 2));
    let mut ctx = BokehContext::new(b, &BokehContextDesc::new(Extent::new(48, 32, 2), options.clone())).unwrap();
    for (i, aperture) in [0.02f32, 0.01, 0.03].into_iter().enumerate() {
        let mut image = noise_with_sky(48, 32, 2);
        // A few highlights, so that sprites are drawn.
        for p in [100usize, 700, 1200] {
            image.fragments[p * 2].color = [40.0, 30.0, 20.0];
        }
        upload(b, &bufs, &image);
        let before = b.counters();
        ctx.record(b, &frame(&image, aperture, &bufs)).unwrap();
        b.submit().unwrap();
        let spent = b.counters().since(&before);
        // The first frame may submit once more: Vulkan creates its draw target at the first draw
        // of a size (and must flush before replacing one).
        if i > 0 {
            assert_eq!((spent.allocations, spent.readbacks, spent.submissions), (0, 0, 1), "frame {i}");
        }
        let got = read_rgb(b, bufs[2], 48, 32).unwrap();
        let (detected, _) = ctx.detected_and_radius(b).unwrap();
        assert!(detected > 0, "frame {i}: no sprite");
        let (front, depth) = image.front();
        let expected = bokeh(b, &front, &depth, &test_lens(aperture), &options).unwrap();
        assert!(got.data == expected.image.data, "frame {i} differs from the one-shot path");
    }
    ctx.destroy(b);
}

#[test]
fn a_bokeh_context_records_frames_like_the_one_shot_path() {
    bokeh_frames(&mut CpuBackend::new());
}

#[test]
fn a_bokeh_context_records_frames_like_the_one_shot_path_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    bokeh_frames(&mut vk);
    assert_clean(&mut vk);
}

/// Images are described by name, and their formats come from Vulkan's: the three the frame API
/// copies are accepted, anything else is refused naming the ones there are.
#[test]
fn images_are_described_by_name_with_formats_from_vulkan() {
    use dof::backend::ImageFormat;
    use dof::backend::vulkan::ash::vk::{self, Handle};
    assert_eq!(ImageFormat::try_from(vk::Format::R16G16B16A16_SFLOAT).unwrap(), ImageFormat::Rgba16Float);
    assert_eq!(ImageFormat::try_from(vk::Format::R32_SFLOAT).unwrap(), ImageFormat::R32Float);
    assert_eq!(ImageFormat::try_from(vk::Format::D32_SFLOAT).unwrap(), ImageFormat::D32Float);
    let refused = ImageFormat::try_from(vk::Format::B8G8R8A8_UNORM).unwrap_err().to_string();
    assert!(refused.contains("B8G8R8A8_UNORM") && refused.contains("R32G32B32A32_SFLOAT"), "{refused}");
    assert!(dof::backend::ImageRef::describe(vk::Image::null(), vk::Format::B8G8R8A8_UNORM, [4, 4]).is_err());
    let image = vk::Image::from_raw(7);
    let desc = dof::backend::ImageRef::describe(image, vk::Format::R32G32B32A32_SFLOAT, [640, 360]).unwrap();
    // SAFETY: never recorded; only the description is compared.
    let kept = unsafe { desc.in_layout(vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL).build() };
    assert_eq!((kept.handle(), kept.extent, kept.format), (7, [640, 360], ImageFormat::Rgba32Float));
    assert_eq!(kept.final_layout, vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL, "left in the layout it was in");
    // SAFETY: as above.
    let written = unsafe {
        desc.in_layout(vk::ImageLayout::UNDEFINED)
            .after(vk::PipelineStageFlags::TRANSFER, vk::AccessFlags::TRANSFER_WRITE)
            .leave_in(vk::ImageLayout::TRANSFER_SRC_OPTIMAL)
            .build()
    };
    assert_eq!(
        (written.layout, written.stage, written.access),
        (vk::ImageLayout::UNDEFINED, vk::PipelineStageFlags::TRANSFER, vk::AccessFlags::TRANSFER_WRITE)
    );
    assert_eq!(written.final_layout, vk::ImageLayout::TRANSFER_SRC_OPTIMAL);
    // SAFETY: as above.
    assert_eq!(unsafe { desc.in_layout(vk::ImageLayout::UNDEFINED).build() }.final_layout, vk::ImageLayout::GENERAL);
}
