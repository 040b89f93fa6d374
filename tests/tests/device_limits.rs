//! The device's limits: device memory running out (a budget on the backend stands in for a full
//! device), an extent beyond what the device's buffers can hold, and a list pool too small for the
//! frame. Each is a clear error, or a documented degraded result, with nothing leaked and the
//! backend still usable; never a panic or garbage.

use dof::CoreError;
use dof::backend::{Backend, CpuBackend};
use dof::frame::Extent;
use dof::frame::{
    BokehContext, BokehContextDesc, CountBuffer, DofContext, Frame, GatherContext, GatherContextDesc, RgbBuffer, SlotBuffer, SplatContext,
    SplatContextDesc,
};
use dof::methods::bokeh::BokehOptions;
use dof::methods::buffers::{read_rgb, slot_words};
use dof::methods::splat::{Merge, SplatOptions, splat};
use dof::stress::{noise_with_sky, test_lens};
use dof_tests::{assert_clean, vulkan};

/// Under a budget too small for a context, creation fails with `OutOfMemory` naming the budget,
/// whatever it made is freed, and the same backend then runs a frame once the budget allows.
fn memory_runs_out(b: &mut dyn Backend) {
    let held = b.counters().device_bytes;
    let desc = SplatContextDesc::new(Extent::new(128, 96, 4), SplatOptions { merge: Merge::X4, ..Default::default() });
    // Every budget from nothing to just short of the context fails at a different buffer.
    let need = {
        let ctx = SplatContext::new(b, &desc).unwrap();
        let n = ctx.device_bytes();
        ctx.destroy(b);
        n
    };
    for budget in [0, 4096, need / 3, need / 2, need - 4] {
        b.set_memory_budget(Some(held + budget));
        match SplatContext::new(b, &desc) {
            Err(CoreError::OutOfMemory { budget: got, .. }) => assert_eq!(got, held + budget),
            Err(e) => panic!("budget {budget}: {e}"),
            Ok(_) => panic!("budget {budget} of {need} bytes: the context was created"),
        }
        assert_eq!(b.counters().device_bytes, held, "budget {budget}: buffers left behind");
        assert!(matches!(
            GatherContext::new(b, &GatherContextDesc::new(Extent::new(4096, 4096, 4))),
            Err(CoreError::OutOfMemory { .. }) | Err(CoreError::TooLarge { .. })
        ));
        assert!(matches!(
            BokehContext::new(b, &BokehContextDesc::new(Extent::new(2048, 2048, 1), BokehOptions::default())),
            Err(CoreError::OutOfMemory { .. }) | Err(CoreError::TooLarge { .. })
        ));
        assert_eq!(b.counters().device_bytes, held, "budget {budget}: buffers left behind");
    }
    // The one-shot path says the same, and the message names the budget.
    let image = noise_with_sky(128, 96, 4);
    let e = splat(b, &image, &test_lens(0.02), &desc.options).err().expect("beyond the budget");
    assert!(e.to_string().contains("budget"), "{e}");
    // With room again, the backend works.
    b.set_memory_budget(Some(held + need + (8 << 20)));
    let out = splat(b, &image, &test_lens(0.02), &desc.options).unwrap();
    assert!(out.image.data.iter().all(|p| p.iter().all(|c| c.is_finite())));
    b.set_memory_budget(None);
    assert_eq!(b.counters().device_bytes, held);
}

#[test]
fn running_out_of_memory_is_an_error_and_leaks_nothing() {
    memory_runs_out(&mut CpuBackend::new());
}

#[test]
fn running_out_of_memory_is_an_error_and_leaks_nothing_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    memory_runs_out(&mut vk);
    assert_clean(&mut vk);
}

/// An extent whose buffers exceed what the device can hold in one buffer is refused before anything
/// is allocated, on each backend's own limits.
fn extent_beyond_the_device(b: &mut dyn Backend) {
    let held = b.counters().device_bytes;
    let edge = dof_shaders::splat::fragment::MAX_EDGE;
    for (w, h, l) in [(edge, edge, 64u32), (edge, edge, 4096)] {
        let e = SplatContext::new(b, &SplatContextDesc::new(Extent::new(w, h, l), SplatOptions::default())).err().expect("too large");
        assert!(matches!(e, CoreError::TooLarge { .. }), "{w}x{h}x{l}: {e}");
    }
    assert!(matches!(
        SplatContext::new(b, &SplatContextDesc::new(Extent::new(edge + 1, 16, 1), SplatOptions::default())),
        Err(CoreError::TooLarge { .. })
    ));
    assert!(matches!(
        GatherContext::new(b, &GatherContextDesc::new(Extent::new(1 << 16, 1 << 16, 1 << 12))),
        Err(CoreError::TooLarge { .. })
    ));
    assert_eq!(b.counters().device_bytes, held);
}

#[test]
fn an_extent_beyond_the_device_is_refused_before_allocating() {
    extent_beyond_the_device(&mut CpuBackend::new());
}

#[test]
fn an_extent_beyond_the_device_is_refused_before_allocating_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    extent_beyond_the_device(&mut vk);
    assert_clean(&mut vk);
}

/// A pool too small for the frame on Vulkan: counted, tiles copied through, every pixel finite and
/// the caller's buffer written whole (no stale value survives), validation silent.
#[test]
fn a_list_overflow_on_vulkan_is_counted_and_degrades_cleanly() {
    let Some(mut vk) = vulkan() else { return };
    let b: &mut dyn Backend = &mut vk;
    let image = noise_with_sky(64, 48, 3);
    let pixels = 64 * 48;
    let bufs = [
        b.create_buffer(dof::methods::buffers::SLOT_WORDS as u64 * pixels * 3, "caller/fragments").unwrap(),
        b.create_buffer(pixels, "caller/counts").unwrap(),
        b.create_buffer(3 * pixels, "caller/output").unwrap(),
    ];
    b.write_buffer(bufs[0], 0, &slot_words(&image)).unwrap();
    b.write_buffer(bufs[1], 0, &image.counts).unwrap();
    // A sentinel in the output: every word must be overwritten.
    b.write_buffer(bufs[2], 0, &vec![f32::NAN.to_bits(); 3 * pixels as usize]).unwrap();
    let mut desc = SplatContextDesc::new(Extent::new(64, 48, 3), SplatOptions::default());
    desc.list_entries = Some(2000);
    let mut ctx = SplatContext::new(b, &desc).unwrap();
    ctx.record(b, &Frame::layers(64, 48, 3, test_lens(0.02), SlotBuffer::current(bufs[0]), CountBuffer(bufs[1]), RgbBuffer(bufs[2])))
        .unwrap();
    b.submit().unwrap();
    let report = ctx.report(b).unwrap();
    assert!(report.overflow_tiles > 0 && report.list_entries <= 2000, "{report:?}");
    let out = read_rgb(b, bufs[2], 64, 48).unwrap();
    assert!(out.data.iter().all(|p| p.iter().all(|c| c.is_finite())), "a pixel kept the sentinel or became non-finite");
    ctx.destroy(b);
    bufs.iter().for_each(|&id| b.destroy_buffer(id));
    assert_clean(&mut vk);
}
