//! The GPU shape of the hot kernels, held to budgets without a GPU (`dof bench kernels` prints the
//! same numbers for every kernel). Each is read from the embedded SPIR-V ([`dof::kernel_shape`]):
//!
//! - function-storage bytes: per-invocation arrays, which a GPU keeps in local (off-chip) memory
//!   when they are indexed at run time;
//! - run-time indexed function-storage accesses;
//! - integer divisions and remainders by a run-time value (a long instruction sequence each);
//! - barriers in the code (not as executed) and workgroup memory.
//!
//! A budget is the most a kernel may have. Where a kernel meets the shape a GPU wants, the budget
//! is that shape; where it does not yet (the merge), the budget is today's figure, so that it can
//! only improve, with the shape it should reach beside it. Raising a budget needs a reason in the
//! change that raises it.
//!
//! Per frame, the commands of a multi-layer frame are held too, counted by the CPU backend (the
//! same recording as on Vulkan).

use dof::backend::{Backend, CpuBackend, VulkanBackend, VulkanOptions};
use dof::frame::Extent;
use dof::frame::{CountBuffer, DofContext, Frame, RgbBuffer, SlotBuffer, SplatContext, SplatContextDesc};
use dof::kernel_shape::{KernelShape, analyze};
use dof::methods::buffers::{SLOT_WORDS, slot_words};
use dof::methods::splat::{Merge, SplatOptions};
use dof::stress::{noise_with_sky, test_lens};

/// The most a kernel may have of each figure.
struct Budget {
    /// The entry point (`module::function`).
    entry: &'static str,
    function_bytes: u32,
    runtime_indexed: usize,
    runtime_divisions: usize,
    barriers: usize,
    workgroup_bytes: u32,
}

/// The hot kernels of multi-layer splatting and of scatter-as-you-gather, and their budgets.
const BUDGETS: &[Budget] = &[
    // The shape a GPU wants: no per-invocation arrays, no division by a run-time value.
    Budget {
        entry: "sort::sort_shared_1024",
        function_bytes: 0,
        runtime_indexed: 0,
        runtime_divisions: 0,
        barriers: 5,
        workgroup_bytes: 8192,
    },
    Budget {
        entry: "sort::sort_global_step",
        function_bytes: 0,
        runtime_indexed: 0,
        runtime_divisions: 0,
        barriers: 1,
        workgroup_bytes: 0,
    },
    Budget {
        entry: "sort::sort_global_local",
        function_bytes: 0,
        runtime_indexed: 0,
        runtime_divisions: 0,
        barriers: 6,
        workgroup_bytes: 16384,
    },
    // Binning: the cursor walks cells by column and row; the divisions left place a neighbour tile
    // (once per neighbour tile an invocation meets, not per candidate).
    Budget {
        entry: "splat::bin::splat_bin",
        function_bytes: 0,
        runtime_indexed: 0,
        runtime_divisions: 13,
        barriers: 5,
        workgroup_bytes: 7168,
    },
    // Its count: one reduction a thinning level.
    Budget {
        entry: "splat::bin::splat_bin_count",
        function_bytes: 0,
        runtime_indexed: 0,
        runtime_divisions: 9,
        barriers: 14,
        workgroup_bytes: 7168,
    },
    Budget {
        entry: "splat::bin::splat_bin_plan",
        function_bytes: 0,
        runtime_indexed: 0,
        runtime_divisions: 0,
        barriers: 9,
        workgroup_bytes: 2048,
    },
    Budget {
        entry: "splat::bin::splat_tile_count",
        function_bytes: 0,
        runtime_indexed: 0,
        // Each invocation places its cell in its tile once (24-px tiles have 36, 144 or 576 cells).
        runtime_divisions: 13,
        barriers: 3,
        workgroup_bytes: 6144,
    },
    Budget {
        entry: "splat::accumulate::splat_accumulate",
        function_bytes: 256,
        runtime_indexed: 8,
        runtime_divisions: 21,
        barriers: 11,
        workgroup_bytes: 23552,
    },
    // The subgroup variants of the binning and the accumulation: their subgroup path and, for a
    // workgroup that is not whole subgroups, the path without, so more barriers in the code and
    // fewer executed (`subgroups_cut_the_barriers_a_multilayer_frame_executes`).
    Budget {
        entry: "splat::bin::splat_bin::subgroups",
        function_bytes: 0,
        runtime_indexed: 0,
        runtime_divisions: 13,
        barriers: 11,
        workgroup_bytes: 7168,
    },
    Budget {
        entry: "splat::bin::splat_bin_count::subgroups",
        function_bytes: 0,
        runtime_indexed: 0,
        runtime_divisions: 9,
        barriers: 27,
        workgroup_bytes: 7168,
    },
    Budget {
        entry: "splat::accumulate::splat_accumulate::subgroups",
        function_bytes: 256,
        runtime_indexed: 8,
        runtime_divisions: 21,
        barriers: 15,
        workgroup_bytes: 23552,
    },
    Budget {
        entry: "splat::pack::splat_pack",
        function_bytes: 256,
        runtime_indexed: 2,
        runtime_divisions: 12,
        barriers: 1,
        workgroup_bytes: 0,
    },
    // Not the GPU's shape: one invocation walks a 4x4 cell's 16 pixel cursors, kept in
    // function-storage arrays (5 KB an invocation). The shape to reach: merged level by level, no
    // per-invocation arrays (at most 256 bytes). This budget holds the kernel as it is (a cursor's
    // word for the sub-samples its slots cover took it from 5272 bytes and 950 to these).
    Budget {
        entry: "splat::merge::splat_merge",
        function_bytes: 5384,
        runtime_indexed: 992,
        runtime_divisions: 41,
        barriers: 1,
        workgroup_bytes: 0,
    },
    // Scatter-as-you-gather: one invocation a pixel or a tile, the rings turned by rotation, no
    // per-invocation arrays and no division by a run-time value; the tiles' two reductions share
    // one tree.
    Budget {
        entry: "scatter_gather::scatter_gather",
        function_bytes: 0,
        runtime_indexed: 0,
        runtime_divisions: 0,
        barriers: 1,
        workgroup_bytes: 0,
    },
    Budget {
        entry: "scatter_gather::scatter_gather_tiles",
        function_bytes: 0,
        runtime_indexed: 0,
        runtime_divisions: 0,
        barriers: 3,
        workgroup_bytes: 2048,
    },
    Budget {
        entry: "scatter_gather::scatter_gather_dilate",
        function_bytes: 0,
        runtime_indexed: 0,
        runtime_divisions: 0,
        barriers: 1,
        workgroup_bytes: 0,
    },
];

fn shape(entry: &str) -> KernelShape {
    let words = dof::shaders::module_words(entry).unwrap_or_else(|| panic!("no embedded module for {entry}"));
    analyze(&words).unwrap_or_else(|e| panic!("the SPIR-V of {entry}: {e}"))
}

#[test]
fn hot_kernels_stay_within_their_budgets() {
    let mut over = Vec::new();
    for b in BUDGETS {
        let s = shape(b.entry);
        let figures = [
            ("function-storage bytes", s.function_bytes as u64, b.function_bytes as u64),
            ("run-time indexed function-storage accesses", s.runtime_indexed as u64, b.runtime_indexed as u64),
            ("divisions by a run-time value", s.runtime_divisions as u64, b.runtime_divisions as u64),
            ("barriers", s.barriers as u64, b.barriers as u64),
            ("workgroup bytes", s.workgroup_bytes as u64, b.workgroup_bytes as u64),
        ];
        for (what, got, most) in figures {
            if got > most {
                over.push(format!("{}: {got} {what}, budget {most}", b.entry));
            }
        }
    }
    assert!(over.is_empty(), "over budget:\n{}", over.join("\n"));
}

/// Every size class of the shared-memory sort is one kernel with another array size: none divides
/// by a run-time value (the comparator finds its pair with masks).
#[test]
fn no_sort_kernel_divides_by_a_run_time_value() {
    for (entry, _) in dof::shaders::MODULES.iter().filter(|(e, _)| e.starts_with("sort::")) {
        let s = shape(entry);
        assert_eq!(s.runtime_divisions, 0, "{entry}: {s:?}");
    }
}

/// Only the subgroup variants (`::subgroups`) hold subgroup operations, and each does: a device
/// without subgroup arithmetic runs every other module.
#[test]
fn only_the_subgroup_variants_use_subgroup_operations() {
    for kernel in dof_shaders::all_kernels() {
        assert_eq!(shape(kernel.entry).subgroup_ops, 0, "{}", kernel.entry);
        if let Some(variant) = kernel.subgroup_entry {
            assert!(shape(variant).subgroup_ops > 0, "{variant}");
        }
    }
    for (entry, _) in dof::shaders::MODULES.iter().filter(|(e, _)| !e.ends_with("::subgroups")) {
        assert_eq!(shape(entry).subgroup_ops, 0, "{entry}");
    }
}

/// The workgroup barriers one multi-layer frame executes, as the CPU backend counts them (one a
/// step of a kernel body), without subgroups and in subgroups of 8 (lavapipe's) and 32 (NVIDIA's):
/// the binning's reductions and scans and the accumulation's per-batch reduction take a few steps
/// in subgroups where they take `log2 256` without.
#[test]
fn subgroups_cut_the_barriers_a_multilayer_frame_executes() {
    let (w, h, layers) = (96, 64, 4);
    let image = noise_with_sky(w, h, layers);
    let pixels = w as u64 * h as u64;
    let executed = |width: Option<u32>| {
        let mut b = CpuBackend::new();
        b.set_subgroup_size(width).unwrap();
        let slots = b.create_buffer(SLOT_WORDS as u64 * pixels * layers as u64, "caller/fragments").unwrap();
        let counts = b.create_buffer(pixels, "caller/counts").unwrap();
        let out = b.create_buffer(3 * pixels, "caller/output").unwrap();
        b.write_buffer(slots, 0, &slot_words(&image)).unwrap();
        b.write_buffer(counts, 0, &image.counts).unwrap();
        let desc = SplatContextDesc::new(Extent::new(w, h, layers), SplatOptions::default());
        let mut ctx = SplatContext::new(&mut b, &desc).unwrap();
        let before = b.counters();
        ctx.record(&mut b, &Frame::layers(w, h, layers, test_lens(0.05), SlotBuffer::current(slots), CountBuffer(counts), RgbBuffer(out)))
            .unwrap();
        b.submit().unwrap();
        let barriers = b.counters().since(&before).workgroup_barriers;
        (barriers, b.read_buffer(out, 0, 3 * pixels).unwrap())
    };
    let (without, image_without) = executed(None);
    let (in_8, image_8) = executed(Some(8));
    let (in_32, image_32) = executed(Some(32));
    eprintln!("workgroup barriers a frame executes: {without} without subgroups, {in_8} in subgroups of 8, {in_32} in subgroups of 32");
    assert!(image_8 == image_without && image_32 == image_without, "the same image, bit for bit");
    assert!(in_32 * 10 <= without * 7, "in subgroups of 32: {in_32} barriers, against {without} without");
    assert!(in_32 < in_8 && in_8 < without, "{without}, {in_8}, {in_32}");
}

/// Every embedded module parses, and none uses function storage without saying so in the table
/// `dof bench kernels` prints: the analysis covers what the host embeds.
#[test]
fn every_embedded_module_has_a_shape() {
    for (entry, _) in dof::shaders::MODULES {
        let s = shape(entry);
        assert_eq!(s.entry, *entry, "the module's entry point");
        assert!(s.instructions > 0 && s.functions > 0, "{entry}: {s:?}");
    }
}

/// The commands of one multi-layer frame, merged 4x4 and unmerged, as the CPU backend counts them
/// (the same recording the Vulkan backend makes), at most `MAX_COMMANDS`: the statistics' clear,
/// the plan (2), packing, merging, the tile counts, the allocation, binning (its count, its plan
/// and its lists), the sort's plan (3), one dispatch per workgroup-memory size class (7 with 32 KiB
/// of workgroup memory) and the accumulation. Lists longer than the largest class are thinned, so
/// none of the global-memory sort's 22 commands is recorded. Of the dispatches, at most
/// `MAX_EMPTY` are of no workgroup (the size classes no list of the frame needs).
#[test]
fn a_multilayer_frame_records_a_bounded_number_of_commands() {
    const MAX_COMMANDS: u64 = 22;
    const MAX_EMPTY: u64 = 7;
    let mut b = CpuBackend::new();
    let (w, h, layers) = (64, 48, 3);
    let image = noise_with_sky(w, h, layers);
    let pixels = w as u64 * h as u64;
    let slots = b.create_buffer(SLOT_WORDS as u64 * pixels * layers as u64, "caller/fragments").unwrap();
    let counts = b.create_buffer(pixels, "caller/counts").unwrap();
    let out = b.create_buffer(3 * pixels, "caller/output").unwrap();
    b.write_buffer(slots, 0, &slot_words(&image)).unwrap();
    b.write_buffer(counts, 0, &image.counts).unwrap();
    for merge in [Merge::X4, Merge::None] {
        let desc = SplatContextDesc::new(Extent::new(w, h, layers), SplatOptions { merge, ..Default::default() });
        let mut ctx = SplatContext::new(&mut b, &desc).unwrap();
        let before = b.counters();
        ctx.record(&mut b, &Frame::layers(w, h, layers, test_lens(0.02), SlotBuffer::current(slots), CountBuffer(counts), RgbBuffer(out)))
            .unwrap();
        b.submit().unwrap();
        let c = b.counters().since(&before);
        assert!(c.commands <= MAX_COMMANDS, "{merge:?}: {} commands, budget {MAX_COMMANDS}", c.commands);
        assert!(c.empty_dispatches <= MAX_EMPTY, "{merge:?}: {} empty dispatches, budget {MAX_EMPTY}", c.empty_dispatches);
        assert!(c.empty_dispatches < c.dispatches, "{merge:?}: {c:?}");
        ctx.destroy(&mut b);
    }
}

/// Where the driver reports pipeline statistics, each kernel's pipeline has some (registers,
/// spills); where it does not (lavapipe), asking for them is refused with the reason, before any
/// device is made.
#[test]
fn driver_statistics_where_the_device_reports_them() {
    if dof_tests::vulkan().is_none() {
        return;
    }
    match VulkanBackend::new(&VulkanOptions { pipeline_statistics: true, validation: true, ..Default::default() }) {
        Ok(mut vk) => {
            let stats = vk.pipeline_statistics(&dof_shaders::splat::bin::BIN).unwrap();
            assert!(!stats.is_empty() && stats.iter().all(|s| !s.name.is_empty()), "{stats:?}");
        }
        Err(e) => assert!(e.to_string().contains("VK_KHR_pipeline_executable_properties"), "{e}"),
    }
    // A backend made without them refuses the query.
    let Some(mut vk) = dof_tests::vulkan() else { return };
    let refused = vk.pipeline_statistics(&dof_shaders::splat::bin::BIN).unwrap_err();
    assert!(refused.to_string().contains("VulkanOptions::pipeline_statistics"), "{refused}");
}
