//! Smoke tests of the backend under the validation layer. Like every Vulkan test of the project they
//! fail where Vulkan or the layer is missing, unless `DOF_SKIP_VULKAN=1` asks to skip them.

use super::*;
use crate::backend::push_words;
use dof_shaders::scan::{ADD, BLOCK_SCAN, ScanParams};

fn skip_requested() -> bool {
    std::env::var_os("DOF_SKIP_VULKAN").is_some_and(|v| v == "1")
}

fn backend() -> Option<VulkanBackend> {
    match VulkanBackend::new(&VulkanOptions { validation: true, ..Default::default() }) {
        Ok(b) => Some(b),
        Err(e @ (Error::NoVulkan(_) | Error::NoValidationLayer)) if skip_requested() => {
            eprintln!("DOF_SKIP_VULKAN=1: skipping a Vulkan test on purpose ({e})");
            None
        }
        Err(e) => panic!("Vulkan is required for this test (set DOF_SKIP_VULKAN=1 to skip on purpose): {e}"),
    }
}

#[test]
fn buffers_fill_scan_and_timings_are_clean() -> Result<()> {
    let Some(mut vk) = backend() else { return Ok(()) };
    let info = vk.info();
    assert!(!info.name.is_empty() && info.limits.max_buffer_bytes > 0, "{info:?}");

    // Created buffers read back as zeros; writes and fills land where asked.
    let a = vk.create_buffer(1000, "a")?;
    assert_eq!(vk.buffer_words(a)?, 1000);
    assert_eq!(vk.read_buffer(a, 0, 1000)?, vec![0; 1000]);
    let data: Vec<u32> = (0..1000).collect();
    vk.write_buffer(a, 0, &data)?;
    vk.fill(a, 10, 5, 7, "seven")?;
    let back = vk.read_buffer(a, 0, 1000)?;
    let mut want = data.clone();
    want[10..15].fill(7);
    assert_eq!(back, want);

    // A one-block scan with a direct and an indirect dispatch: exclusive prefix sums, then + sum.
    let n = 700u32;
    let values: Vec<u32> = (0..n).map(|i| i % 13).collect();
    vk.write_buffer(a, 0, &values)?;
    let sums = vk.create_buffer(1, "sums")?;
    let args = vk.create_buffer(4, "args")?;
    vk.write_buffer(args, 1, &[1, 1, 1])?;
    let push = push_words(&ScanParams { len: n, data_offset: 0, sums_offset: 0 });
    vk.dispatch(&BLOCK_SCAN, [1, 1, 1], &[a, sums], &push, "scan")?;
    vk.dispatch_indirect(&ADD, args, 1, &[a, sums], &push, "add")?;
    let times = vk.submit()?;
    let labels: Vec<&str> = times.iter().map(|t| t.label.as_str()).collect();
    // `seven` was submitted by `read_buffer`; its timing waits for this `submit`.
    assert_eq!(labels, ["seven", "scan", "add"]);
    assert!(times.iter().all(|t| t.ms >= 0.0 || t.ms.is_nan()), "{times:?}");
    let total: u32 = values.iter().sum();
    let mut running = total; // the block's inclusive total, added back by `add`
    let want: Vec<u32> = values
        .iter()
        .map(|v| {
            let w = running;
            running += v;
            w
        })
        .collect();
    assert_eq!(vk.read_buffer(a, 0, n as u64)?, want);
    assert_eq!(vk.read_buffer(sums, 0, 1)?, vec![total]);

    vk.fill(a, 0, 1, 1, "again")?;
    vk.destroy_buffer(sums); // while recorded work may use it: freed after the submission
    let times = vk.submit()?;
    assert_eq!(times.iter().map(|t| t.label.as_str()).collect::<Vec<_>>(), ["again"]);
    assert!(vk.submit()?.is_empty());

    // Past one query pool's capacity the recording takes another pool: still one submission.
    let count = recorder::TIMED_PER_POOL as usize + 10;
    for i in 0..count {
        vk.fill(a, 0, 1, i as u32, "many")?;
    }
    let before = vk.counters();
    let times = vk.submit()?;
    assert_eq!(times.len(), count);
    assert!(times.iter().all(|t| t.ms.is_finite() && t.ms >= 0.0), "{:?}", &times[..4]);
    assert_eq!(vk.counters().since(&before).submissions, 1, "one submit is one vkQueueSubmit");
    // And again, reusing both pools.
    for i in 0..count {
        vk.fill(a, 0, 1, i as u32 + 1, "many")?;
    }
    let before = vk.counters();
    assert_eq!(vk.submit()?.len(), count);
    assert_eq!(vk.counters().since(&before).submissions, 1);
    assert_eq!(vk.read_buffer(a, 0, 1)?, vec![count as u32]);

    // Errors, not panics.
    assert!(matches!(vk.read_buffer(a, 999, 2), Err(Error::InvalidArgument(_))));
    assert!(matches!(vk.read_buffer(sums, 0, 1), Err(Error::InvalidArgument(_))));
    assert!(matches!(vk.create_buffer(u64::MAX / 2, "huge"), Err(Error::TooLarge { .. })));
    assert!(matches!(vk.dispatch(&ADD, [1, 1, 1], &[a], &push, "bad"), Err(Error::InvalidArgument(_))));

    assert_eq!(vk.validation_messages(), Vec::<String>::new());
    Ok(())
}

#[test]
fn devices_are_listed() -> Result<()> {
    match list_devices() {
        Ok(devices) => assert!(devices.iter().enumerate().all(|(i, d)| d.index == i)),
        Err(Error::NoVulkan(e)) if skip_requested() => eprintln!("DOF_SKIP_VULKAN=1: skipping ({e})"),
        Err(e) => return Err(e),
    }
    Ok(())
}

/// The layer is live: two fills without a barrier between them are reported as a hazard.
#[test]
fn validation_reports_a_hazard() -> Result<()> {
    let Some(mut vk) = backend() else { return Ok(()) };
    let a = vk.create_buffer(16, "a")?;
    let buffer = vk.buffer(a)?.handle;
    vk.recorder.record(&vk.device, None, &[], |d, cb| {
        // SAFETY: `cb` is recording and the buffer is alive; the missing barrier is the point.
        unsafe {
            d.cmd_fill_buffer(cb, buffer, 0, 64, 1);
            d.cmd_fill_buffer(cb, buffer, 0, 64, 2);
        }
    })?;
    vk.submit()?;
    let messages = vk.take_validation_messages();
    assert!(messages.iter().any(|m| m.contains("SYNC-HAZARD-WRITE-AFTER-WRITE")), "{messages:?}");
    assert!(vk.validation_messages().is_empty());
    Ok(())
}

/// Every kernel's pipeline builds, with and without subgroups where the device has them, and the
/// module passes the layer's checks against the device.
#[test]
fn every_pipeline_builds_cleanly() -> Result<()> {
    let Some(vk) = backend() else { return Ok(()) };
    for subgroups in [false, vk.info.limits.subgroup_kernels] {
        let mut pipelines = Pipelines::new(false, subgroups);
        for kernel in dof_shaders::all_kernels() {
            if kernel.shared_bytes <= vk.info.limits.max_shared_bytes {
                pipelines.get(&vk.device.device, kernel)?;
            }
        }
        pipelines.destroy(&vk.device.device);
    }
    assert_eq!(vk.validation_messages(), Vec::<String>::new());
    Ok(())
}

/// Transfers larger than the staging buffer go through it in pieces.
#[test]
fn large_transfers_are_chunked() -> Result<()> {
    let Some(mut vk) = backend() else { return Ok(()) };
    let words = (memory::STAGING_CHUNK_BYTES / 4 + 1000).min(vk.limits().max_buffer_bytes / 4 - 8);
    let a = vk.create_buffer(words + 8, "large")?;
    let data: Vec<u32> = (0..words as u32).map(|i| i.wrapping_mul(2654435761)).collect();
    vk.write_buffer(a, 8, &data)?;
    assert_eq!(vk.read_buffer(a, 8, words)?, data);
    assert_eq!(vk.read_buffer(a, 0, 8)?, vec![0; 8]);
    assert_eq!(vk.validation_messages(), Vec::<String>::new());
    Ok(())
}

/// The counters count exactly what was done: buffers and bytes, submissions (hidden ones included),
/// readbacks and uploads.
#[test]
fn counters_are_exact() -> Result<()> {
    let Some(mut vk) = backend() else { return Ok(()) };
    let zero = vk.counters();
    assert_eq!(zero, BackendCounters::default());
    let a = vk.create_buffer(100, "a")?;
    let b = vk.create_buffer(0, "b")?; // one word
    let c = vk.counters();
    assert_eq!((c.allocations, c.device_bytes, c.peak_device_bytes, c.submissions), (2, 404, 404, 0));
    vk.write_buffer(a, 0, &[1, 2, 3])?; // submits the zeroing, then the copy
    let c = vk.counters();
    assert_eq!((c.uploads, c.submissions, c.readbacks), (1, 2, 0));
    assert_eq!(vk.read_buffer(a, 0, 3)?, vec![1, 2, 3]); // nothing recorded: one copy
    let c = vk.counters();
    assert_eq!((c.readbacks, c.submissions), (1, 3));
    assert!(vk.submit()?.is_empty()); // nothing recorded: no submission
    assert_eq!(vk.counters().submissions, 3);
    vk.fill(b, 0, 1, 5, "five")?;
    vk.submit()?;
    assert_eq!(vk.counters().submissions, 4);
    vk.destroy_buffer(a);
    let c = vk.counters();
    assert_eq!((c.allocations, c.device_bytes, c.peak_device_bytes), (2, 4, 404));
    // Refused calls count nothing.
    assert!(vk.read_buffer(b, 1, 1).is_err());
    assert!(vk.write_buffer(b, 1, &[1]).is_err());
    assert_eq!(vk.counters(), c);
    // A reset peak is what is held now.
    vk.reset_peak_device_bytes();
    assert_eq!(vk.counters().peak_device_bytes, 4);
    assert_eq!(vk.validation_messages(), Vec::<String>::new());
    Ok(())
}

/// Barriers go only where a command accesses a buffer an earlier one accessed since the last
/// barrier, and synchronization validation finds nothing missing.
#[test]
fn barriers_only_where_commands_share_buffers() -> Result<()> {
    let Some(mut vk) = backend() else { return Ok(()) };
    let a = vk.create_buffer(1024, "a")?;
    let b = vk.create_buffer(1024, "b")?;
    let c = vk.create_buffer(4, "c")?;
    vk.submit()?;
    let barriers = |vk: &VulkanBackend| vk.recorder.barriers();
    let start = barriers(&vk);
    vk.fill(a, 0, 1024, 1, "a")?; // first of the command buffer: a barrier
    vk.fill(b, 0, 1024, 2, "b")?; // disjoint: none
    vk.fill(c, 0, 4, 0, "c")?; // disjoint: none
    assert_eq!(barriers(&vk) - start, 1);
    vk.fill(a, 0, 1024, 3, "a again")?; // a again: one
    assert_eq!(barriers(&vk) - start, 2);
    let push = push_words(&ScanParams { len: 1024, data_offset: 0, sums_offset: 0 });
    vk.dispatch(&BLOCK_SCAN, [1, 1, 1], &[b, c], &push, "scan b")?; // only a since the last barrier: none
    assert_eq!(barriers(&vk) - start, 2);
    vk.dispatch(&BLOCK_SCAN, [1, 1, 1], &[a, c], &push, "scan a")?; // a and c again: one
    assert_eq!(barriers(&vk) - start, 3);
    vk.submit()?;
    let want = |v: u32| (0..1024).map(|i| i * v).collect::<Vec<u32>>();
    assert_eq!(vk.read_buffer(a, 0, 1024)?, want(3));
    assert_eq!(vk.read_buffer(b, 0, 1024)?, want(2));
    assert_eq!(vk.read_buffer(c, 0, 1)?, vec![3 * 1024]);
    assert_eq!(vk.validation_messages(), Vec::<String>::new());
    Ok(())
}

/// A caller's module under its own entry point: here the project's `scan::scan_add` with its entry
/// point renamed (same length) to `mine::scan_add`, run through a descriptor naming that entry.
fn renamed_add_module() -> Vec<u8> {
    let (_, bytes) = crate::shaders::MODULES.iter().find(|(e, _)| *e == "scan::scan_add").expect("the scan_add module");
    let (from, to) = (b"scan::scan_add\0", b"mine::scan_add\0");
    let mut bytes = bytes.to_vec();
    let at = bytes.windows(from.len()).position(|w| w == from).expect("the entry point name in the module");
    bytes[at..at + to.len()].copy_from_slice(to);
    bytes
}

static MINE_ADD: KernelDesc = KernelDesc { entry: "mine::scan_add", ..ADD };

#[test]
fn added_modules_run_and_collisions_are_refused() -> Result<()> {
    let Some(mut vk) = backend() else { return Ok(()) };
    let module = renamed_add_module();
    let project = crate::shaders::MODULES.iter().find(|(e, _)| *e == "scan::scan_add").map(|(_, m)| *m).unwrap();

    // Before it is added, the kernel has no module.
    let a = vk.create_buffer(300, "a")?;
    let sums = vk.create_buffer(2, "sums")?;
    let push = push_words(&ScanParams { len: 300, data_offset: 0, sums_offset: 0 });
    let err = vk.dispatch(&MINE_ADD, [2, 1, 1], &[a, sums], &push, "mine").unwrap_err();
    assert!(err.to_string().contains("add_modules"), "{err}");

    // Refused, all or nothing: a project entry (exactly, or by its unqualified name), a module
    // without the entry point, bytes that are not SPIR-V, the same entry twice.
    let refused = |vk: &mut VulkanBackend, modules: &[(&str, &[u8])], says: &str| {
        let err = vk.add_modules(modules).expect_err("refused");
        assert!(matches!(err, Error::InvalidArgument(_)) && err.to_string().contains(says), "{err}");
    };
    refused(&mut vk, &[("mine::scan_add", &module), ("scan::scan_add", project)], "the project's kernels already have");
    refused(&mut vk, &[("scan_add", project)], "the project's kernels already have");
    refused(&mut vk, &[("mine::other", &module)], "no such entry point");
    refused(&mut vk, &[("mine::scan_add", b"not spir-v")], "not little-endian SPIR-V");
    refused(&mut vk, &[("mine::scan_add", &module), ("mine::scan_add", &module)], "already added");

    // Added, it runs like the project's kernel; adding it again is refused.
    vk.add_modules(&[("mine::scan_add", &module)])?;
    refused(&mut vk, &[("mine::scan_add", &module)], "already added");
    let values: Vec<u32> = (0..300).map(|i| i % 7).collect();
    vk.write_buffer(a, 0, &values)?;
    vk.write_buffer(sums, 0, &[5, 11])?;
    vk.dispatch(&MINE_ADD, [2, 1, 1], &[a, sums], &push, "mine")?;
    vk.submit()?;
    let mine = vk.read_buffer(a, 0, 300)?;
    vk.write_buffer(a, 0, &values)?;
    vk.dispatch(&ADD, [2, 1, 1], &[a, sums], &push, "project")?;
    vk.submit()?;
    assert_eq!(mine, vk.read_buffer(a, 0, 300)?);
    assert_ne!(mine, values);
    assert_eq!(vk.validation_messages(), Vec::<String>::new());
    Ok(())
}

#[test]
fn own_images_are_zeroed_written_copied_and_freed_cleanly() -> Result<()> {
    let Some(mut vk) = backend() else { return Ok(()) };
    let size = [37, 5];
    let color = vk.create_image(ImageFormat::Rgba16Float, size)?;
    let depth = vk.create_image(ImageFormat::D32Float, size)?;
    let out = vk.create_buffer(color.words() + depth.words(), "out")?;
    // Made zeroed.
    vk.copy_image_to_buffer(color, out, 0, "colour")?;
    vk.submit()?;
    assert_eq!(vk.read_buffer(out, 0, color.words())?, vec![0; color.words() as usize]);
    // Written texels come back from the frame's copies, through GENERAL each time.
    let texels: Vec<u32> = (0..color.words() as u32).map(|i| i.wrapping_mul(2_654_435_761)).collect();
    let depths: Vec<u32> = (0..depth.words() as u32).map(|i| (0.25 + i as f32 / 1000.0).to_bits()).collect();
    vk.write_image(&color, &texels)?;
    vk.write_image(&depth, &depths)?;
    for _ in 0..2 {
        vk.copy_image_to_buffer(color, out, 0, "colour")?;
        vk.copy_image_to_buffer(depth, out, color.words(), "depth")?;
        vk.submit()?;
        assert_eq!(vk.read_buffer(out, 0, color.words())?, texels);
        assert_eq!(vk.read_buffer(out, color.words(), depth.words())?, depths);
    }
    // Refused: a wrong texel count, a described size or format unlike the image's, an image not
    // the backend's, an empty one.
    assert!(vk.write_image(&color, &texels[1..]).is_err());
    assert!(vk.write_image(&color.top_left(36, 5), &texels[..36 * 5 * 2]).is_err());
    assert!(vk.write_image(&ImageRef { format: ImageFormat::Rgba32Float, ..color }, &texels).is_err());
    assert!(vk.write_image(&ImageRef { handle: 12345, ..color }, &texels).is_err());
    assert!(vk.create_image(ImageFormat::D32Float, [0, 4]).is_err());
    vk.destroy_image(&color);
    vk.destroy_image(&depth);
    // Gone: writing one again is refused.
    assert!(vk.write_image(&color, &texels).is_err());
    vk.destroy_buffer(out);
    let messages = vk.take_validation_messages();
    assert!(messages.is_empty(), "validation: {messages:?}");
    Ok(())
}
