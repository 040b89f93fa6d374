//! Sample patterns for the reference renderer: stratified lens and pixel-area samples, the
//! concentric disc mapping, and per-pixel random streams.

use rand::seq::SliceRandom;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;

/// Shirley and Chiu's concentric map from the unit square to the unit disc: area-preserving and
/// continuous, so strata of the square stay compact on the disc. `(0.5, 0.5)` maps to the centre.
pub fn concentric_disc(u: f32, v: f32) -> (f32, f32) {
    let a = 2.0 * u - 1.0;
    let b = 2.0 * v - 1.0;
    if a == 0.0 && b == 0.0 {
        return (0.0, 0.0);
    }
    let (r, phi) = if a.abs() > b.abs() {
        (a, std::f32::consts::FRAC_PI_4 * (b / a))
    } else {
        (b, std::f32::consts::FRAC_PI_2 - std::f32::consts::FRAC_PI_4 * (a / b))
    };
    (r * phi.cos(), r * phi.sin())
}

/// A random stream for one pixel of one batch, independent of every other (pixel, batch, seed).
pub fn pixel_rng(seed: u64, batch: u64, pixel: u64) -> Pcg32 {
    let mut z = seed ^ batch.wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ pixel.wrapping_mul(0xd1b5_4a32_d192_ed03);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    Pcg32::seed_from_u64(z ^ (z >> 31))
}

/// One sample: a point of the unit square for the lens and one for the pixel area.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    pub lens: (f32, f32),
    pub pixel: (f32, f32),
}

/// `n` samples jointly stratified over lens and pixel area: both unit squares are cut into the same
/// `nx × ny` grid (`nx = floor(sqrt(n))`, `ny = floor(n / nx)`), each lens stratum paired with a
/// pixel stratum by a random permutation (Latin-style padding, as pbrt's stratified sampler), and
/// the `n − nx·ny` left over drawn uniformly. With `jitter` every point is uniform in its stratum;
/// without, it is the stratum's centre (the left-overs then sit at the centre of the square), so
/// `n = 1` without jitter is the pinhole ray through the pixel centre.
pub fn stratified(n: u32, jitter: bool, rng: &mut Pcg32, out: &mut Vec<Sample>, perm: &mut Vec<u32>) {
    out.clear();
    if n == 0 {
        return;
    }
    let nx = (n as f64).sqrt().floor().max(1.0) as u32;
    let ny = n / nx;
    let cells = nx * ny;
    perm.clear();
    perm.extend(0..cells);
    perm.shuffle(rng);
    let offset = |rng: &mut Pcg32| if jitter { (rng.random::<f32>(), rng.random::<f32>()) } else { (0.5, 0.5) };
    let point = |cell: u32, (du, dv): (f32, f32)| {
        let (i, j) = (cell % nx, cell / nx);
        (((i as f32 + du) / nx as f32).min(ONE_MINUS), ((j as f32 + dv) / ny as f32).min(ONE_MINUS))
    };
    for c in 0..cells {
        let lens = point(c, offset(rng));
        let pixel = point(perm[c as usize], offset(rng));
        out.push(Sample { lens, pixel });
    }
    for _ in cells..n {
        let (lens, pixel) = if jitter {
            ((rng.random::<f32>(), rng.random::<f32>()), (rng.random::<f32>(), rng.random::<f32>()))
        } else {
            ((0.5, 0.5), (0.5, 0.5))
        };
        out.push(Sample { lens, pixel });
    }
}

/// The largest `f32` below 1: keeps samples inside `[0, 1)`.
const ONE_MINUS: f32 = 1.0 - f32::EPSILON / 2.0;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn concentric_maps_into_the_disc() {
        for i in 0..=20 {
            for j in 0..=20 {
                let (x, y) = concentric_disc(i as f32 / 20.0, j as f32 / 20.0);
                assert!(x * x + y * y <= 1.0 + 1e-5);
            }
        }
        assert_eq!(concentric_disc(0.5, 0.5), (0.0, 0.0));
    }

    #[test]
    fn strata_cover_the_square_once() {
        let mut rng = pixel_rng(1, 2, 3);
        let (mut s, mut p) = (Vec::new(), Vec::new());
        stratified(16, true, &mut rng, &mut s, &mut p);
        assert_eq!(s.len(), 16);
        let mut seen = [0u32; 16];
        for smp in &s {
            let cell = |(u, v): (f32, f32)| (u * 4.0) as usize + 4 * (v * 4.0) as usize;
            seen[cell(smp.lens)] |= 1;
            seen[cell(smp.pixel)] |= 2;
        }
        assert!(seen.iter().all(|&b| b == 3));
        stratified(1, false, &mut rng, &mut s, &mut p);
        assert_eq!(s, vec![Sample { lens: (0.5, 0.5), pixel: (0.5, 0.5) }]);
    }
}
