//! Synthetic inputs with the shape of the pipeline's data, for tests and benchmarks before (and
//! besides) real scenes.

use crate::ops::sort::SortInput;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

/// Tile lists shaped like Franke et al. 2018's Fig. 12: 3600 tiles (1280x720 in 16x16 tiles), list lengths
/// log-normally distributed around a median of 700 fragments with a tail to `max_len`, a few empty
/// (sky) tiles, depths in [0.5, 100] with repeated values (coplanar fragments tie).
pub fn tile_lists(tiles: usize, max_len: u32, seed: u64) -> SortInput {
    let mut rng = Pcg64::seed_from_u64(seed);
    let mut input = SortInput::default();
    for _ in 0..tiles {
        let len = if rng.random_bool(0.03) {
            0
        } else {
            // Box-Muller normal for the log-normal length.
            let (u1, u2): (f64, f64) = (rng.random_range(1e-9..1.0), rng.random());
            let normal = (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos();
            ((700f64.ln() + 0.8 * normal).exp() as u32).min(max_len)
        };
        input.segments.push((input.keys.len() as u32, len));
        for _ in 0..len {
            let depth = if rng.random_bool(0.1) { (rng.random_range(1..40) as f32) * 2.5 } else { rng.random_range(0.5f32..100.0) };
            input.keys.push(depth);
            input.values.push(rng.random());
        }
    }
    input
}

/// Lists of the given lengths (laid out back to back) with keys from `keys`.
pub fn lists_with(lengths: &[u32], mut keys: impl FnMut(usize, u32) -> f32) -> SortInput {
    let mut input = SortInput::default();
    for (l, &len) in lengths.iter().enumerate() {
        input.segments.push((input.keys.len() as u32, len));
        for i in 0..len {
            input.keys.push(keys(l, i));
            input.values.push(input.values.len() as u32);
        }
    }
    input
}

/// Random keys in `[-1000, 1000]` with about a tenth repeated exactly and a sprinkle of the special
/// values (±0, ±inf, NaN) whose order the sort defines.
pub fn random_key(rng: &mut impl Rng) -> f32 {
    match rng.random_range(0..100) {
        0 => 0.0,
        1 => -0.0,
        2 => f32::INFINITY,
        3 => f32::NEG_INFINITY,
        4 => f32::NAN,
        5..=14 => rng.random_range(0..8) as f32,
        _ => rng.random_range(-1000.0f32..1000.0),
    }
}
