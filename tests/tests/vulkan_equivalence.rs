//! The same kernels on Vulkan (lavapipe in CI) and on the CPU backend give bit-identical results, with
//! the Khronos validation layer and synchronization validation reporting nothing.

use dof::backend::{Backend, CpuBackend};
use dof::ops::scan::exclusive_scan;
use dof::ops::sort::{sort_on, sort_on_with};
use dof::workload::{lists_with, random_key, tile_lists};
use dof_tests::{assert_clean, assert_sorted_like_reference, vulkan};
use rand::SeedableRng;
use rand_pcg::Pcg64;

#[test]
fn sort_matches_cpu_bit_for_bit() {
    let Some(mut vk) = vulkan() else { return };
    let shared = vk.limits().max_shared_bytes;
    let mut cpu = CpuBackend::with_shared_bytes(shared);
    let mut rng = Pcg64::seed_from_u64(11);
    let lengths = [0, 1, 2, 3, 64, 65, 300, 1000, 2048, 4095, 4096, 4097, 6144, 9000, 20000];
    let inputs = [
        lists_with(&lengths, |_, _| random_key(&mut rng)),
        lists_with(&lengths, |_, i| i as f32),
        lists_with(&lengths, |_, i| -(i as f32)),
        lists_with(&lengths, |_, _| 2.0),
        tile_lists(300, 8192, 5),
    ];
    let bits = |k: &[f32]| k.iter().map(|k| k.to_bits()).collect::<Vec<_>>();
    for input in &inputs {
        // The network on Vulkan against both strategies on the CPU: the serial merge sort the
        // CPU backend runs and the network.
        for serial in [true, false] {
            let on_vk = sort_on(&mut vk, input).expect("Vulkan sort");
            assert_clean(&mut vk);
            let on_cpu = sort_on_with(&mut cpu, input, Some(serial)).expect("CPU sort");
            let first_difference = |a: &[u32], b: &[u32]| a.iter().zip(b).position(|(a, b)| a != b);
            let keys = first_difference(&bits(&on_vk.keys), &bits(&on_cpu.keys));
            assert_eq!(keys, None, "keys differ between Vulkan and CPU from that index on ({serial:?})");
            let values = first_difference(&on_vk.values, &on_cpu.values);
            assert_eq!(values, None, "payloads differ between Vulkan and CPU from that index on ({serial:?})");
            assert_eq!(on_vk.stats.class_counts, on_cpu.stats.class_counts, "class plans differ");
            assert_sorted_like_reference(input, &on_vk);
        }
    }
}

/// The serial strategy compiled to SPIR-V and run by one invocation on Vulkan. Lists up to 2048
/// long: lavapipe ends a shader invocation's loops after 65 535 iterations of all its loops
/// together (Mesa's `LP_MAX_TGSI_LOOP_ITERATIONS`), and one invocation merge-sorting a list of
/// about 3 800 reversed keys reaches that (its output then comes back half sorted). No Vulkan
/// device chooses the serial strategy ([`dof::backend::Limits::serial_invocations`]).
#[test]
fn serial_strategy_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    let mut rng = Pcg64::seed_from_u64(13);
    let lengths = [0, 1, 2, 3, 17, 64, 65, 300, 1000, 2047, 2048];
    let inputs = [
        lists_with(&lengths, |_, _| random_key(&mut rng)),
        lists_with(&lengths, |_, i| i as f32),
        lists_with(&lengths, |_, i| -(i as f32)),
        lists_with(&lengths, |_, _| 2.0),
    ];
    for input in &inputs {
        let out = sort_on_with(&mut vk, input, Some(true)).expect("Vulkan sort");
        assert_clean(&mut vk);
        assert_sorted_like_reference(input, &out);
    }
}

#[test]
fn global_path_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    let mut rng = Pcg64::seed_from_u64(12);
    let input = lists_with(&[40_000, 5000, 70_000], |_, _| random_key(&mut rng));
    let out = sort_on(&mut vk, &input).expect("Vulkan sort");
    assert_clean(&mut vk);
    assert_eq!(out.stats.global_lists, 3);
    assert_sorted_like_reference(&input, &out);
}

#[test]
fn scan_matches_cpu_bit_for_bit() {
    let Some(mut vk) = vulkan() else { return };
    let mut cpu = CpuBackend::new();
    for len in [0usize, 1, 1023, 1024, 1025, 70_000, 1024 * 1024 + 3] {
        let values: Vec<u32> = (0..len as u32).map(|i| i.wrapping_mul(0x9e37_79b9) >> 8).collect();
        let on_vk = exclusive_scan(&mut vk, &values).expect("Vulkan scan");
        assert_clean(&mut vk);
        assert_eq!(on_vk, exclusive_scan(&mut cpu, &values).expect("CPU scan"), "scan of {len} words");
    }
}

#[test]
fn per_dispatch_timestamps_are_reported() {
    let Some(mut vk) = vulkan() else { return };
    let input = tile_lists(50, 2000, 9);
    let out = sort_on(&mut vk, &input).expect("Vulkan sort");
    assert_clean(&mut vk);
    assert!(out.times.iter().any(|t| t.label == "sort/classify"));
    assert!(out.times.iter().all(|t| t.ms.is_finite() && t.ms >= 0.0), "{:?}", out.times);
}

mod random_mixes {
    use super::*;
    use proptest::prelude::*;
    use rand::Rng;

    proptest! {
        #![proptest_config(ProptestConfig { cases: 6, ..ProptestConfig::default() })]

        /// Random mixes of list lengths across every class and the global path, on Vulkan with
        /// validation, bit-identical to the CPU backend.
        #[test]
        fn random_length_mixes_match_cpu(lengths in prop::collection::vec(prop_oneof![0u32..70, 0u32..1500, 4000u32..9000], 1..10), seed: u64) {
            let Some(mut vk) = vulkan() else { return Ok(()) };
            let mut rng = Pcg64::seed_from_u64(seed);
            let input = lists_with(&lengths, |_, _| if rng.random_bool(0.3) { rng.random_range(0..3) as f32 } else { random_key(&mut rng) });
            let on_vk = sort_on(&mut vk, &input).expect("Vulkan sort");
            assert_clean(&mut vk);
            let on_cpu = sort_on(&mut CpuBackend::with_shared_bytes(vk.limits().max_shared_bytes), &input).expect("CPU sort");
            prop_assert_eq!(on_vk.values, on_cpu.values);
            let bits = |k: &[f32]| k.iter().map(|k| k.to_bits()).collect::<Vec<_>>();
            prop_assert_eq!(bits(&on_vk.keys), bits(&on_cpu.keys));
        }
    }
}
