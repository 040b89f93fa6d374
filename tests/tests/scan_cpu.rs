//! The exclusive scan on the CPU backend against a sequential scan.

use dof::backend::CpuBackend;
use dof::ops::scan::exclusive_scan;
use proptest::prelude::*;

fn sequential(values: &[u32]) -> (Vec<u32>, u32) {
    let mut acc = 0u32;
    let out = values
        .iter()
        .map(|&v| {
            let before = acc;
            acc = acc.wrapping_add(v);
            before
        })
        .collect();
    (out, acc)
}

fn check(values: &[u32]) {
    let got = exclusive_scan(&mut CpuBackend::new(), values).expect("scan");
    assert_eq!(got, sequential(values), "scan of {} words", values.len());
}

#[test]
fn lengths_around_block_boundaries() {
    // One block is 1024 words; 1024 * 1024 + 1 needs three levels.
    for len in [0usize, 1, 2, 255, 256, 1023, 1024, 1025, 4096, 100_000, 1024 * 1024 + 1] {
        let values: Vec<u32> = (0..len as u32).map(|i| i.wrapping_mul(2654435761) >> 22).collect();
        check(&values);
    }
}

#[test]
fn sums_wrap_modulo_2_pow_32() {
    check(&vec![u32::MAX / 3; 5000]);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, ..ProptestConfig::default() })]
    #[test]
    fn random_inputs(values in prop::collection::vec(any::<u32>(), 0..5000)) {
        check(&values);
    }
}
