//! Misuse gets a clear error, never a panic.

use dof::CoreError;
use dof::backend::{Backend, CpuBackend, push_words};
use dof::ops::sort::{SortInput, sort_on};
use dof_shaders::scan::{BLOCK_SCAN, ScanParams};

#[test]
fn payload_count_must_match_keys() {
    let input = SortInput { keys: vec![1.0, 2.0], values: vec![0], segments: vec![(0, 2)] };
    assert!(matches!(sort_on(&mut CpuBackend::new(), &input), Err(CoreError::InvalidArgument(_))));
}

#[test]
fn lists_must_lie_inside_the_keys() {
    let input = SortInput { keys: vec![1.0; 4], values: vec![0; 4], segments: vec![(2, 3)] };
    let err = sort_on(&mut CpuBackend::new(), &input).unwrap_err();
    assert!(err.to_string().contains("runs past"), "{err}");
}

#[test]
fn out_of_bounds_kernel_access_is_a_fault_not_a_crash() {
    let mut cpu = CpuBackend::new();
    let data = cpu.create_buffer(16, "data").unwrap();
    let sums = cpu.create_buffer(1, "sums").unwrap();
    // Claims 4096 words in a 16-word buffer.
    let params = push_words(&ScanParams { len: 4096, data_offset: 0, sums_offset: 0 });
    let err = cpu.dispatch(&BLOCK_SCAN, [4, 1, 1], &[data, sums], &params, "bad").unwrap_err();
    assert!(matches!(err, CoreError::KernelFault { kernel: "scan::scan_block", .. }), "{err}");
}

#[test]
fn dispatches_are_checked_against_the_kernel_and_the_limits() {
    let mut cpu = CpuBackend::new();
    let data = cpu.create_buffer(16, "data").unwrap();
    let params = push_words(&ScanParams::default());
    let wrong_bindings = cpu.dispatch(&BLOCK_SCAN, [1, 1, 1], &[data], &params, "bad").unwrap_err();
    assert!(matches!(wrong_bindings, CoreError::InvalidArgument(_)), "{wrong_bindings}");
    let too_many_groups = cpu.dispatch(&BLOCK_SCAN, [1 << 20, 1, 1], &[data, data], &params, "bad").unwrap_err();
    assert!(matches!(too_many_groups, CoreError::TooLarge { .. }), "{too_many_groups}");
    let short_push = cpu.dispatch(&BLOCK_SCAN, [1, 1, 1], &[data, data], &[], "bad").unwrap_err();
    assert!(matches!(short_push, CoreError::InvalidArgument(_)), "{short_push}");
}

#[test]
fn buffer_ranges_and_ids_are_checked() {
    let mut cpu = CpuBackend::new();
    let b = cpu.create_buffer(4, "b").unwrap();
    assert!(cpu.write_buffer(b, 2, &[1, 2, 3]).is_err());
    assert!(cpu.read_buffer(b, u64::MAX, 2).is_err());
    cpu.destroy_buffer(b);
    assert!(cpu.read_buffer(b, 0, 1).is_err());
}

#[test]
fn kernels_needing_more_workgroup_memory_than_the_device_has_are_refused() {
    let mut cpu = CpuBackend::with_shared_bytes(1024);
    let data = cpu.create_buffer(16, "data").unwrap();
    let params = push_words(&ScanParams::default());
    // scan_block declares 2 KiB of workgroup memory.
    let err = cpu.dispatch(&BLOCK_SCAN, [1, 1, 1], &[data, data], &params, "bad").unwrap_err();
    assert!(matches!(err, CoreError::TooLarge { .. }), "{err}");
}

/// Sample counts beyond the stated bound are refused before anything proportional to them is
/// allocated (4e9 samples per pixel would mean an 80 GB allocation), without naming a CLI flag.
#[test]
fn sample_counts_beyond_the_bound_are_refused() {
    use dof::scene::{AutoOptions, MAX_SPP, ReferenceOptions, builtin, reference, reference_auto};
    let s = builtin("simple").unwrap().with_size(16, 9);
    let lens = s.thin_lens().unwrap();
    let start = std::time::Instant::now();
    for spp in [0, MAX_SPP + 1, 4_000_000_000] {
        let err = reference(&s.scene, &s.camera, &lens, &ReferenceOptions { spp, ..Default::default() }).unwrap_err();
        assert!(matches!(err, dof::Error::Core(CoreError::InvalidArgument(_))) && err.to_string().contains(&MAX_SPP.to_string()), "{err}");
        assert!(!err.to_string().contains("--"), "a library message names no flag: {err}");
    }
    let err = reference_auto(&s.scene, &s.camera, &lens, &AutoOptions { max_spp: 4_000_000_000, ..Default::default() }).unwrap_err();
    assert!(err.to_string().contains(&MAX_SPP.to_string()), "{err}");
    assert!(start.elapsed() < std::time::Duration::from_secs(2), "{:?}", start.elapsed());
}
