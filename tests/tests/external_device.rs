//! The Vulkan backend inside someone else's renderer: the test plays the renderer. It makes its own
//! instance (validation layer with synchronization validation, its own debug messenger collecting
//! every warning and error), its own device with the backend's required extensions and features,
//! its own buffers and an RGBA32F image, and its own command buffer and fence. The backend is built on
//! those handles (`VulkanBackend::from_raw`), imports the buffers, and records a copy out of the
//! image, a prefix scan, a segmented sort of the imported buffers and a copy back into the image into
//! the renderer's command buffer, between the renderer's own passes. Results must equal the CPU
//! backend's bit for bit, and the validation layer must report nothing, leaks included.
//!
//! Like every Vulkan suite it fails where Vulkan or the layer is missing, unless `DOF_SKIP_VULKAN=1`
//! asks to skip it.

use dof::CoreError;
use dof::backend::vulkan::ash::vk;
use dof::backend::vulkan::gpu_allocator;
use dof::backend::{Backend, BackendCounters, BufferId, CpuBackend, ImageFormat, ImageRef, RawOptions, VulkanBackend};
use dof::frame::Extent;
use dof::frame::{CountBuffer, DofContext, Frame, GatherContext, GatherContextDesc, RgbBuffer, SlotBuffer};
use dof::ops::scan::{ScanScratch, exclusive_scan};
use dof::ops::sort::{SegmentedSort, SortInput, sort_on};
use dof::workload::{lists_with, random_key};
use dof_tests::renderer::{OwnBuffer, Renderer, assert_no_messages};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use std::sync::{Arc, Mutex};

/// The image: odd sizes, 4 words a pixel, 9 scan blocks (two scan levels).
const WIDTH: u32 = 61;
const HEIGHT: u32 = 37;

/// The whole of the test's image, as one copy region.
fn image_region() -> [vk::BufferImageCopy; 1] {
    [vk::BufferImageCopy::default()
        .image_subresource(vk::ImageSubresourceLayers::default().aspect_mask(vk::ImageAspectFlags::COLOR).layer_count(1))
        .image_extent(vk::Extent3D { width: WIDTH, height: HEIGHT, depth: 1 })]
}

/// A sort input with lists of every class and one long enough for the global path.
fn sort_input() -> SortInput {
    let mut rng = Pcg64::seed_from_u64(31);
    lists_with(&[0, 1, 7, 64, 300, 1000, 2048, 4097, 9000, 33], |_, _| random_key(&mut rng))
}

#[test]
fn records_into_the_callers_command_buffer_on_the_callers_device() {
    let Some(mut r) = Renderer::new() else { return };
    let storage = vk::BufferUsageFlags::STORAGE_BUFFER | vk::BufferUsageFlags::TRANSFER_SRC | vk::BufferUsageFlags::TRANSFER_DST;

    // The renderer's data: an RGBA32F image's pixels and a sort problem, in its own buffers.
    let mut rng = Pcg64::seed_from_u64(30);
    // Small words, so the prefix sums stay far from overflowing.
    let pixel_words: Vec<u32> = (0..4 * WIDTH * HEIGHT).map(|_| rng.random_range(0..4096u32)).collect();
    let input = sort_input();
    let n = input.keys.len();
    let key_bits: Vec<u32> = input.keys.iter().map(|k| k.to_bits()).collect();
    let seg_words: Vec<u32> = input.segments.iter().flat_map(|&(o, l)| [o, l]).collect();
    let bytes = |words: usize| words as u64 * 4;

    let pixels_staging = r.buffer(bytes(pixel_words.len()), vk::BufferUsageFlags::TRANSFER_SRC, true);
    let upload = r.buffer(bytes(2 * n + seg_words.len()), vk::BufferUsageFlags::TRANSFER_SRC, true);
    let readback = r.buffer(bytes(pixel_words.len() + 2 * n + 64), vk::BufferUsageFlags::TRANSFER_DST, true);
    let flags = r.buffer(bytes(64), storage, false);
    let segments = r.buffer(bytes(seg_words.len()), storage, false);
    let keys_in = r.buffer(bytes(n), storage, false);
    let values_in = r.buffer(bytes(n), storage, false);
    let keys_out = r.buffer(bytes(n), storage, false);
    let values_out = r.buffer(bytes(n), storage, false);
    let image = r.raw_image(
        vk::Format::R32G32B32A32_SFLOAT,
        [WIDTH, HEIGHT],
        vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST | vk::ImageUsageFlags::SAMPLED,
    );

    // Uploads through the renderer's own staging, its own submission.
    Renderer::write(&pixels_staging, &pixel_words);
    Renderer::write(&upload, &[key_bits.as_slice(), &input.values, &seg_words].concat());
    r.begin();
    // SAFETY: the command buffer is recording; regions lie inside the buffers.
    unsafe {
        let d = &r.device;
        d.cmd_copy_buffer(r.cb, upload.buffer, keys_in.buffer, &[vk::BufferCopy::default().size(bytes(n))]);
        d.cmd_copy_buffer(r.cb, upload.buffer, values_in.buffer, &[vk::BufferCopy::default().src_offset(bytes(n)).size(bytes(n))]);
        let segs = vk::BufferCopy::default().src_offset(bytes(2 * n)).size(bytes(seg_words.len()));
        d.cmd_copy_buffer(r.cb, upload.buffer, segments.buffer, &[segs]);
    }
    r.submit_and_wait();

    // The backend on the renderer's device.
    // SAFETY: the handles are live and outlive the backend; the device enables what the backend
    // requires; the backend is dropped before the renderer destroys anything, after its work completed.
    let mut vk = unsafe { VulkanBackend::from_raw(r.raw(), &RawOptions::default()) }.expect("from_raw");
    assert!(vk.take_diagnostics().is_empty(), "the caller owns the messenger");
    let import = |vk: &mut VulkanBackend, b: &OwnBuffer, label: &str| -> BufferId {
        // SAFETY: a live storage buffer of the device with transfer usage, alive until the backend is dropped.
        unsafe { vk.import_buffer(b.buffer, b.bytes, label) }.expect("import_buffer")
    };
    let (segments_id, keys_in_id, values_in_id) =
        (import(&mut vk, &segments, "segments"), import(&mut vk, &keys_in, "keys"), import(&mut vk, &values_in, "values"));
    let (keys_out_id, values_out_id) = (import(&mut vk, &keys_out, "keys-out"), import(&mut vk, &values_out, "values-out"));
    let flags_id = import(&mut vk, &flags, "flags");
    assert_eq!(vk.buffer_words(keys_in_id).unwrap(), n as u64);
    let after_imports = vk.counters();
    assert_eq!(after_imports, BackendCounters::default(), "imports allocate nothing");

    // What the backend needs of its own, created once before the frames.
    let words = pixel_words.len() as u64;
    let pixels = vk.create_buffer(words, "pixels").expect("create_buffer");
    let scan = ScanScratch::new(&mut vk, words).expect("scan scratch");
    let sort = SegmentedSort::new(&mut vk, input.segments.len() as u32, n as u32, input.max_list_len()).expect("sort");
    let created = vk.counters();
    assert!(created.allocations >= 4 && created.submissions == 0 && created.device_bytes >= bytes(words as usize));

    let mut cpu = CpuBackend::with_shared_bytes(vk.limits().max_shared_bytes);
    let (want_pixels, want_total) = exclusive_scan(&mut cpu, &pixel_words).expect("CPU scan");
    let want_sort = sort_on(&mut cpu, &input).expect("CPU sort");
    let (ref_keys, ref_values) = input.reference();
    let bits = |k: &[f32]| k.iter().map(|k| k.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&want_sort.keys), bits(&ref_keys));
    assert_eq!(want_sort.values, ref_values);

    for frame in 0..2 {
        r.begin();
        // The renderer's pass before: every earlier frame's work is done with what it rewrites; the
        // image gets fresh pixels and the sort outputs start as copies of the inputs.
        r.barrier(
            vk::PipelineStageFlags::ALL_COMMANDS,
            vk::AccessFlags::MEMORY_WRITE,
            vk::PipelineStageFlags::TRANSFER,
            vk::AccessFlags::TRANSFER_READ | vk::AccessFlags::TRANSFER_WRITE,
        );
        r.image_barrier(
            image,
            vk::ImageLayout::UNDEFINED,
            vk::ImageLayout::TRANSFER_DST_OPTIMAL,
            vk::PipelineStageFlags::TRANSFER,
            vk::AccessFlags::empty(),
            vk::PipelineStageFlags::TRANSFER,
            vk::AccessFlags::TRANSFER_WRITE,
        );
        // SAFETY: the command buffer is recording; the image is in TRANSFER_DST_OPTIMAL.
        unsafe {
            r.device.cmd_copy_buffer_to_image(r.cb, pixels_staging.buffer, image, vk::ImageLayout::TRANSFER_DST_OPTIMAL, &image_region())
        };
        r.copy(&keys_in, &keys_out, bytes(n));
        r.copy(&values_in, &values_out, bytes(n));
        // SAFETY: the command buffer is recording; the buffer holds 64 words.
        unsafe { r.device.cmd_fill_buffer(r.cb, flags.buffer, 0, bytes(64), 1) };

        // The backend's part, recorded into the renderer's command buffer.
        let before = vk.counters();
        // SAFETY: the renderer's command buffer is recording, outside a render pass, from a pool of the
        // backend's queue family; the renderer records nothing until end_external.
        unsafe { vk.begin_external(r.cb) }.expect("begin_external");
        let began = vk.counters();
        // The first frame submits the zeroing of the buffers created above (documented); later ones nothing.
        assert_eq!(began.since(&before).submissions, if frame == 0 { 1 } else { 0 }, "frame {frame}");
        // SAFETY: the renderer's live RGBA32F image, TRANSFER_SRC|DST usage, WIDTHxHEIGHT, in the declared layout.
        let written = unsafe {
            ImageRef::vulkan(
                image,
                ImageFormat::Rgba32Float,
                [WIDTH, HEIGHT],
                vk::ImageLayout::TRANSFER_DST_OPTIMAL,
                vk::PipelineStageFlags::TRANSFER,
                vk::AccessFlags::TRANSFER_WRITE,
                vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
            )
        };
        // First: a fill over the renderer's fill (ordered by the barrier opening the recording).
        vk.fill(flags_id, 0, 32, 5, "flags").expect("fill");
        vk.copy_image_to_buffer(written, pixels, 0, "image-in").expect("copy_image_to_buffer");
        scan.record(&mut vk, pixels, 0, words).expect("scan");
        sort.record(&mut vk, segments_id, input.segments.len() as u32, keys_in_id, values_in_id, keys_out_id, values_out_id).expect("sort");
        // The backend left the image in SHADER_READ_ONLY_OPTIMAL; nothing of the renderer's touched it since.
        // SAFETY: as above.
        let left = unsafe {
            ImageRef::vulkan(
                image,
                ImageFormat::Rgba32Float,
                [WIDTH, HEIGHT],
                vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
                vk::PipelineStageFlags::empty(),
                vk::AccessFlags::empty(),
                vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
            )
        };
        vk.copy_buffer_to_image(pixels, 0, left, "image-out").expect("copy_buffer_to_image");
        vk.end_external().expect("end_external");
        let during = vk.counters().since(&began);
        assert_eq!(
            (during.submissions, during.readbacks, during.uploads, during.allocations),
            (0, 0, 0, 0),
            "frame {frame}: the external recording submitted, transferred or allocated: {during:?}"
        );
        assert_eq!(during.device_bytes, created.device_bytes);

        // The renderer's pass after: the image and the sort outputs into its host-visible buffer.
        // SAFETY: the command buffer is recording; the image is in TRANSFER_SRC_OPTIMAL, and the
        // backend's closing barrier made its writes visible to transfers.
        unsafe {
            let d = &r.device;
            d.cmd_copy_image_to_buffer(r.cb, image, vk::ImageLayout::TRANSFER_SRC_OPTIMAL, readback.buffer, &image_region());
            let at = bytes(pixel_words.len());
            d.cmd_copy_buffer(r.cb, keys_out.buffer, readback.buffer, &[vk::BufferCopy::default().dst_offset(at).size(bytes(n))]);
            d.cmd_copy_buffer(
                r.cb,
                values_out.buffer,
                readback.buffer,
                &[vk::BufferCopy::default().dst_offset(at + bytes(n)).size(bytes(n))],
            );
            let flags_at = vk::BufferCopy::default().dst_offset(at + bytes(2 * n)).size(bytes(64));
            d.cmd_copy_buffer(r.cb, flags.buffer, readback.buffer, &[flags_at]);
        }
        r.barrier(
            vk::PipelineStageFlags::TRANSFER,
            vk::AccessFlags::TRANSFER_WRITE,
            vk::PipelineStageFlags::HOST,
            vk::AccessFlags::HOST_READ,
        );
        r.submit_and_wait();

        let times = vk.take_external_times().expect("take_external_times").expect("the work completed, so its times are there");
        let labels: Vec<&str> = times.iter().map(|t| t.label.as_str()).collect();
        assert_eq!(labels[..2], ["flags", "image-in"]);
        assert_eq!(labels.last(), Some(&"image-out"));
        assert!(labels.contains(&"scan/block") && labels.contains(&"sort/classify") && labels.contains(&"sort/global-store"), "{labels:?}");
        assert!(times.iter().all(|t| t.ms.is_finite() && t.ms >= 0.0), "{times:?}");
        assert_eq!(vk.take_external_times().unwrap().map(|t| t.len()), Some(0), "times are taken once");

        let got_pixels = Renderer::read(&readback, 0, pixel_words.len());
        assert_eq!(got_pixels, want_pixels, "frame {frame}: the scanned image differs from the CPU backend's");
        let got_keys = Renderer::read(&readback, pixel_words.len(), n);
        let got_values = Renderer::read(&readback, pixel_words.len() + n, n);
        assert_eq!(got_keys, bits(&want_sort.keys), "frame {frame}: sorted keys differ from the CPU backend's");
        assert_eq!(got_values, want_sort.values, "frame {frame}: sorted payloads differ from the CPU backend's");
        let got_flags = Renderer::read(&readback, pixel_words.len() + 2 * n, 64);
        assert_eq!(got_flags, [[5; 32], [1; 32]].concat(), "frame {frame}: the backend's fill and the renderer's");
        assert_no_messages(r.messages(), &format!("in frame {frame}"));
    }

    // Outside a recording the backend reads its own buffers (through the renderer's queue).
    let (total_buffer, total_offset) = scan.total(words);
    assert_eq!(vk.read_buffer(total_buffer, total_offset, 1).unwrap(), vec![want_total]);

    // Imports are only forgotten; the backend's own buffers are freed with it.
    for id in [segments_id, keys_in_id, values_in_id, keys_out_id, values_out_id, flags_id] {
        vk.destroy_buffer(id);
    }
    assert!(vk.buffer_words(keys_in_id).is_err());
    scan.destroy(&mut vk);
    drop(vk);
    assert_no_messages(r.messages(), "while the backend was dropped");
    assert_no_messages(r.finish(), "when the renderer destroyed its device and instance (a leak of the backend's would show here)");
}

#[test]
fn refuses_what_would_submit_or_allocate_inside_the_callers_recording() {
    let Some(mut r) = Renderer::new() else { return };
    let storage = vk::BufferUsageFlags::STORAGE_BUFFER | vk::BufferUsageFlags::TRANSFER_SRC | vk::BufferUsageFlags::TRANSFER_DST;
    let own = r.buffer(64, storage, false);
    let image = r.raw_image(vk::Format::R32_SFLOAT, [WIDTH, HEIGHT], vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST);

    // The renderer's own gpu-allocator serves the backend too.
    let allocator = gpu_allocator::vulkan::Allocator::new(&gpu_allocator::vulkan::AllocatorCreateDesc {
        instance: r.instance.clone(),
        device: r.device.clone(),
        physical_device: r.physical,
        debug_settings: Default::default(),
        buffer_device_address: false,
        allocation_sizes: Default::default(),
    })
    .expect("allocator");
    let shared = Arc::new(Mutex::new(allocator));
    let opts = RawOptions { debug_names: true, allocator: Some(shared.clone()), ..Default::default() };
    // SAFETY: as in the test above; the allocator was made for this device.
    let mut vk = unsafe { VulkanBackend::from_raw(r.raw(), &opts) }.expect("from_raw");
    drop(opts);
    // SAFETY: a live storage buffer of 64 bytes.
    assert!(unsafe { vk.import_buffer(own.buffer, 62, "odd") }.is_err(), "bytes must be whole words");
    // SAFETY: as above.
    let imported = unsafe { vk.import_buffer(own.buffer, own.bytes, "own") }.expect("import");
    let mine = vk.create_buffer(16, "mine").expect("create_buffer");
    let spare = vk.create_buffer(16, "spare").expect("create_buffer");
    // Outside a recording, imported buffers read and write like any other.
    vk.write_buffer(imported, 0, &[5, 6, 7, 8]).expect("write into an imported buffer");
    assert_eq!(vk.read_buffer(imported, 1, 3).unwrap(), vec![6, 7, 8]);

    // A frame recorded outside begin_external would go into the backend's own command buffer and
    // run at its next submission, after the renderer may have changed what it reads: refused, with
    // nothing recorded. Making the context (its one-time zeroing) may submit.
    let mut ctx = GatherContext::new(&mut vk, &GatherContextDesc::new(Extent::new(4, 4, 1))).expect("a context on the renderer's device");
    let bufs = [16u64, 4, 12].map(|w| vk.create_buffer(w, "frame").expect("create_buffer"));
    let before = vk.counters();
    let outside = ctx.record(
        &mut vk,
        &Frame::layers(4, 4, 1, dof::stress::test_lens(0.01), SlotBuffer::current(bufs[0]), CountBuffer(bufs[1]), RgbBuffer(bufs[2])),
    );
    assert!(matches!(&outside, Err(CoreError::RecordingState(m)) if m.contains("record_into")), "{outside:?}");
    assert_eq!(vk.counters(), before, "the refused frame recorded nothing");
    assert!(vk.submit().unwrap().is_empty(), "nothing was left recorded");
    ctx.destroy(&mut vk);
    bufs.into_iter().for_each(|id| vk.destroy_buffer(id));

    assert!(vk.end_external().is_err(), "end without begin");
    r.begin();
    // SAFETY: the renderer's command buffer is recording, outside a render pass.
    unsafe { vk.begin_external(r.cb) }.expect("begin_external");
    assert!(vk.is_external());
    // SAFETY: as above.
    assert!(unsafe { vk.begin_external(r.cb) }.is_err(), "nested begin");
    vk.fill(imported, 0, 16, 3, "fill").expect("fill");
    vk.fill(mine, 0, 16, 4, "fill").expect("fill");
    // SAFETY: the renderer's R32F image, TRANSFER_DST usage, WIDTHxHEIGHT (discarded: UNDEFINED).
    let target = unsafe {
        ImageRef::vulkan(
            image,
            ImageFormat::R32Float,
            [WIDTH, HEIGHT],
            vk::ImageLayout::UNDEFINED,
            vk::PipelineStageFlags::empty(),
            vk::AccessFlags::empty(),
            vk::ImageLayout::GENERAL,
        )
    };
    // The buffer is too small for the image: refused before recording.
    assert!(vk.copy_buffer_to_image(mine, 0, target, "too small").is_err());
    // SAFETY: as above.
    let undefined_source = unsafe {
        ImageRef::vulkan(
            image,
            ImageFormat::R32Float,
            [WIDTH, HEIGHT],
            vk::ImageLayout::UNDEFINED,
            vk::PipelineStageFlags::empty(),
            vk::AccessFlags::empty(),
            vk::ImageLayout::GENERAL,
        )
    };
    assert!(vk.copy_image_to_buffer(undefined_source, mine, 0, "undefined").is_err(), "nothing defined to copy");
    let before = vk.counters();
    assert!(vk.submit().is_err());
    assert!(vk.read_buffer(mine, 0, 1).is_err());
    assert!(vk.write_buffer(mine, 0, &[1]).is_err());
    assert!(vk.create_buffer(4, "late").is_err());
    assert_eq!(vk.counters(), before, "refused calls count nothing");
    let held = vk.counters().device_bytes;
    vk.destroy_buffer(mine); // used by the recording: its id goes now, its memory once the recording completed
    vk.destroy_buffer(spare); // not used: freed
    assert!(vk.buffer_words(mine).is_err() && vk.buffer_words(spare).is_err());
    assert_eq!(vk.counters().device_bytes, held - 64, "only the unused buffer's bytes are back");
    vk.end_external().expect("end_external");
    assert!(!vk.is_external());
    assert_eq!(vk.release_finished().unwrap(), 0, "not submitted yet: nothing freed");
    r.submit_and_wait();
    assert_eq!(vk.release_finished().unwrap(), 64, "freed once the command buffer completed");
    assert_eq!(vk.counters().device_bytes, held - 128);
    assert_eq!(vk.read_buffer(imported, 0, 16).unwrap(), vec![3; 16]);
    assert_eq!(vk.take_external_times().unwrap().map(|t| t.len()), Some(2));
    assert_eq!(vk.take_external_times().unwrap().map(|t| t.len()), Some(0), "taken once");

    // Two recordings in one submission keep their own times, taken oldest first.
    r.begin();
    for fills in [1u64, 3] {
        // SAFETY: the renderer's command buffer is recording, outside a render pass.
        unsafe { vk.begin_external(r.cb) }.expect("begin_external");
        for i in 0..fills {
            vk.fill(imported, i, 1, 9, "per-recording").expect("fill");
        }
        vk.end_external().expect("end_external");
    }
    r.submit_and_wait();
    assert_eq!(vk.take_external_times().unwrap().map(|t| t.len()), Some(1), "the first recording's times");
    assert_eq!(vk.take_external_times().unwrap().map(|t| t.len()), Some(3), "the second recording's times");
    assert_eq!(vk.take_external_times().unwrap().map(|t| t.len()), Some(0));

    // The CPU backend copies only its own stand-in images.
    let mut cpu = CpuBackend::new();
    let b = cpu.create_buffer(4 * WIDTH as u64 * HEIGHT as u64, "b").unwrap();
    assert!(matches!(cpu.copy_image_to_buffer(target, b, 0, "x"), Err(CoreError::InvalidArgument(_))));
    assert!(matches!(cpu.copy_buffer_to_image(b, 0, target, "x"), Err(CoreError::InvalidArgument(_))));

    drop(vk);
    // The renderer's allocator, which the dropped backend does not hold, goes before its device.
    assert_eq!(Arc::strong_count(&shared), 1);
    drop(shared);
    assert_no_messages(r.messages(), "");
    assert_no_messages(r.finish(), "when the renderer destroyed its device and instance");
}

/// The renderer's messenger is live and sync validation on: two fills of one buffer in its command
/// buffer with no barrier between them are reported (so the empty logs above mean something).
#[test]
fn the_renderers_messenger_reports_hazards() {
    let Some(mut r) = Renderer::new() else { return };
    let b = r.buffer(64, vk::BufferUsageFlags::TRANSFER_DST, false);
    r.begin();
    // SAFETY: the command buffer is recording; the missing barrier is the point.
    unsafe {
        r.device.cmd_fill_buffer(r.cb, b.buffer, 0, 64, 1);
        r.device.cmd_fill_buffer(r.cb, b.buffer, 0, 64, 2);
    }
    r.submit_and_wait();
    let messages = r.messages();
    assert!(messages.iter().any(|m| m.contains("SYNC-HAZARD-WRITE-AFTER-WRITE")), "{messages:?}");
    assert_no_messages(r.finish(), "after the hazard");
}

/// The recording guard (`record_into`) is the backend while it lasts and ends the recording when
/// dropped, or by `end`: either way the closing barrier is recorded, a new recording may begin, and
/// the validation layer stays silent.
#[test]
fn a_recording_guard_ends_the_recording_when_dropped() {
    let Some(r) = Renderer::new() else { return };
    // SAFETY: the renderer's live handles outlive the backend, dropped before `finish`.
    let mut vk = unsafe { VulkanBackend::from_raw(r.raw(), &RawOptions::default()) }.expect("from_raw");
    let buffer = vk.create_buffer(256, "guarded").unwrap();
    vk.submit().unwrap();
    r.begin();
    {
        // SAFETY: the renderer's command buffer is recording, outside a render pass.
        let mut recording = unsafe { vk.record_into(r.cb) }.unwrap();
        assert!(recording.is_external());
        recording.fill(buffer, 0, 256, 7, "guarded/fill").unwrap();
        assert!(recording.submit().is_err(), "no submission inside the recording");
    }
    assert!(!vk.is_external(), "dropping the guard ended the recording");
    // SAFETY: as above.
    let mut recording = unsafe { vk.record_into(r.cb) }.unwrap();
    recording.fill(buffer, 128, 128, 9, "guarded/fill").unwrap();
    recording.end().unwrap();
    assert!(vk.end_external().is_err(), "the recording was ended once, by `end`");
    r.submit_and_wait();
    let words = vk.read_buffer(buffer, 0, 256).unwrap();
    assert!(words[..128].iter().all(|&w| w == 7) && words[128..].iter().all(|&w| w == 9));
    vk.destroy_buffer(buffer);
    drop(vk);
    assert_no_messages(r.finish(), "around two guarded recordings");
}

/// A context dropped during a recording into the renderer's command buffer, which uses its
/// buffers: nothing is freed while that command buffer may still run (not yet submitted, here),
/// everything once it has completed, and the validation layer stays silent (a buffer freed early
/// would be reported at the submission).
#[test]
fn a_context_dropped_during_a_recording_is_freed_once_it_completed() {
    let Some(r) = Renderer::new() else { return };
    // SAFETY: the renderer's live handles outlive the backend, dropped before `finish`.
    let mut vk = unsafe { VulkanBackend::from_raw(r.raw(), &RawOptions::default()) }.expect("from_raw");
    let [slots, counts, out] = [5 * 64, 64, 3 * 64].map(|words| vk.create_buffer(words, "caller").unwrap());
    let words: Vec<u32> = (0..64u32).flat_map(|i| [0.5, 0.25, 0.125, 1.0 + i as f32 / 8.0, 1.0].map(f32::to_bits)).collect();
    vk.write_buffer(slots, 0, &words).unwrap();
    vk.write_buffer(counts, 0, &[1; 64]).unwrap();
    let base = vk.counters().device_bytes;
    let mut ctx = GatherContext::new(&mut vk, &GatherContextDesc::new(Extent::new(8, 8, 1))).unwrap();
    vk.submit().unwrap();
    let held = ctx.device_bytes();
    let lens = dof::stress::test_lens(0.02);
    r.begin();
    {
        // SAFETY: the renderer's command buffer is recording, outside a render pass.
        let mut recording = unsafe { vk.record_into(r.cb) }.unwrap();
        ctx.record(&mut *recording, &Frame::layers(8, 8, 1, lens, SlotBuffer::current(slots), CountBuffer(counts), RgbBuffer(out)))
            .unwrap();
        drop(ctx);
        assert_eq!(recording.release_finished().unwrap(), 0, "the recording uses the buffers");
    }
    assert_eq!(vk.release_finished().unwrap(), 0, "the command buffer was not even submitted");
    assert_eq!(vk.counters().device_bytes, base + held);
    r.submit_and_wait();
    assert_eq!(vk.release_finished().unwrap(), held, "freed once the command buffer completed");
    assert_eq!(vk.counters().device_bytes, base);
    let rgb = vk.read_buffer(out, 0, 3 * 64).unwrap();
    assert!(rgb.iter().all(|&w| f32::from_bits(w).is_finite()) && rgb.iter().any(|&w| f32::from_bits(w) > 0.0));
    [slots, counts, out].into_iter().for_each(|b| vk.destroy_buffer(b));
    drop(vk);
    assert_no_messages(r.finish(), "around a context dropped mid-recording");
}
