//! The segmented sort on the CPU backend against the stable reference sort.

use dof::backend::CpuBackend;
use dof::ops::sort::{SortInput, sort_on, sort_on_with};
use dof::workload::{lists_with, random_key, tile_lists};
use dof_tests::assert_sorted_like_reference;
use proptest::prelude::*;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

/// Lengths covering the edge cases: empty, single, pair, non-powers of two, exact class capacities
/// and one past them, and lists beyond the largest workgroup-memory class (the global path).
const LENGTHS: [u32; 18] = [0, 1, 2, 3, 5, 63, 64, 65, 127, 129, 1000, 2047, 2049, 4095, 4096, 4097, 6000, 17000];

/// Both strategies of the workgroup-memory classes: the serial merge sort the CPU backend runs and
/// the bitonic network a GPU runs.
fn run(input: &SortInput, shared_bytes: u32) {
    let mut cpu = CpuBackend::with_shared_bytes(shared_bytes);
    for serial in [true, false] {
        let out = sort_on_with(&mut cpu, input, Some(serial)).expect("sort");
        assert_sorted_like_reference(input, &out);
    }
}

fn check_orders(shared_bytes: u32) {
    let mut rng = Pcg64::seed_from_u64(1);
    let random = lists_with(&LENGTHS, |_, _| random_key(&mut rng));
    let sorted = lists_with(&LENGTHS, |_, i| i as f32 * 0.5);
    let reversed = lists_with(&LENGTHS, |_, i| -(i as f32));
    let equal = lists_with(&LENGTHS, |_, _| 4.25);
    for input in [&random, &sorted, &reversed, &equal] {
        run(input, shared_bytes);
    }
}

#[test]
fn every_order_and_length_with_lavapipe_shared_memory() {
    check_orders(32 * 1024);
}

#[test]
fn global_path_with_the_minimum_vulkan_shared_memory() {
    // 16 KiB: the largest class holds 2048 elements, so more lists take the global path.
    check_orders(16 * 1024);
}

#[test]
fn large_classes_of_a_64k_device() {
    check_orders(64 * 1024);
}

#[test]
fn equal_keys_keep_their_input_order() {
    let input = lists_with(&[5000, 300], |_, _| 1.0);
    let out = sort_on(&mut CpuBackend::new(), &input).unwrap();
    assert_eq!(out.values, input.values, "a stable sort of equal keys is the identity");
}

#[test]
fn special_values_have_a_defined_order() {
    let keys = [f32::NAN, 1.0, -0.0, f32::INFINITY, 0.0, f32::NEG_INFINITY, -f32::NAN, -1.0, f32::MIN_POSITIVE];
    let input = lists_with(&[keys.len() as u32], |_, i| keys[i as usize]);
    let out = sort_on(&mut CpuBackend::new(), &input).unwrap();
    let order: Vec<u32> = out.values.clone();
    // -inf, -1, -0.0 and +0.0 tie (input order), min positive, 1, +inf, then both NaNs in input order.
    assert_eq!(order, vec![5, 7, 2, 4, 8, 1, 3, 0, 6]);
}

#[test]
fn tile_lists_shaped_like_franke_2018_fig_12() {
    let input = tile_lists(400, 8192, 3);
    run(&input, 32 * 1024);
}

#[test]
fn empty_input() {
    let out = sort_on(&mut CpuBackend::new(), &SortInput::default()).unwrap();
    assert!(out.keys.is_empty());
}

#[test]
fn words_outside_the_lists_are_untouched() {
    // Two lists with a gap between them and an unsorted tail after them.
    let mut input = lists_with(&[10, 4, 7], |_, i| 100.0 - i as f32);
    input.segments = vec![(0, 10), (14, 7)];
    let out = sort_on(&mut CpuBackend::new(), &input).unwrap();
    assert_eq!(&out.values[10..14], &input.values[10..14]);
    assert_sorted_like_reference(&input, &out);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    #[test]
    fn random_length_mixes(lengths in prop::collection::vec(prop_oneof![0u32..80, 0u32..700, 2000u32..7000], 0..12), seed: u64, small_shared: bool) {
        let mut rng = Pcg64::seed_from_u64(seed);
        let input = lists_with(&lengths, |_, _| if rng.random_bool(0.2) { rng.random_range(0..4) as f32 } else { random_key(&mut rng) });
        run(&input, if small_shared { 16 * 1024 } else { 32 * 1024 });
    }
}
