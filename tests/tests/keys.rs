//! The total order on sort keys.

use dof_shaders::keys::sort_key;
use proptest::prelude::*;

proptest! {
    #[test]
    fn key_order_is_numeric_order(a: f32, b: f32) {
        prop_assume!(!a.is_nan() && !b.is_nan());
        let (ka, kb) = (sort_key(a.to_bits()), sort_key(b.to_bits()));
        // `partial_cmp` treats -0.0 == +0.0, which is the order the keys promise.
        prop_assert_eq!(ka.cmp(&kb), a.partial_cmp(&b).unwrap());
    }

    #[test]
    fn nan_sorts_after_everything(payload in 0u32..0x0040_0000, negative: bool, x: f32) {
        let nan = 0x7fc0_0000 | payload | if negative { 0x8000_0000 } else { 0 };
        prop_assert!(f32::from_bits(nan).is_nan());
        prop_assert_eq!(sort_key(nan), u32::MAX);
        if !x.is_nan() {
            prop_assert!(sort_key(x.to_bits()) < u32::MAX);
        }
    }
}

#[test]
fn zeros_tie_and_infinities_bound() {
    assert_eq!(sort_key((-0.0f32).to_bits()), sort_key(0.0f32.to_bits()));
    assert!(sort_key(f32::NEG_INFINITY.to_bits()) < sort_key(f32::MIN.to_bits()));
    assert!(sort_key(f32::INFINITY.to_bits()) > sort_key(f32::MAX.to_bits()));
    assert!(sort_key(f32::from_bits(1).to_bits()) > sort_key(0.0f32.to_bits()));
}
