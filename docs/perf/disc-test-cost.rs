//! The cost of one disc test of the accumulation on this machine, for the CPU backend's bound
//! (docs/measurements.md, "The CPU backend at 1920x1080"): the inner loop of
//! `shaders/src/splat/accumulate.rs` reduced to the test itself (a pixel against a staged chunk of
//! 256 fragments: depth against the pixel's sharp front, squared distance against the squared
//! radius), entries laid out as the kernel stages them (one array per field), no blending (no
//! entry covers the pixel), so no early exit. One thread; the bound divides by the cores. Run it on
//! an idle machine, or take the process's user time (`/usr/bin/time`) in place of the wall time.
//!
//!   rustc -C opt-level=3 -o /tmp/disc-test-cost docs/perf/disc-test-cost.rs && /tmp/disc-test-cost
use std::hint::black_box;
use std::time::Instant;

const T: usize = 256;

fn main() {
    // Entries whose discs (radius 2) lie far from every pixel of the 16x16 block.
    let (mut cx, mut cy, mut cs, mut cz) = ([0f32; T], [0f32; T], [0f32; T], [0f32; T]);
    for k in 0..T {
        cx[k] = 100.0 + (k % 16) as f32;
        cy[k] = 100.0 + (k / 16) as f32;
        cs[k] = 2.0;
        cz[k] = 1.0 + k as f32 * 1e-3;
    }
    // Behind every entry (so no early exit), and opaque to the compiler, as the kernel's is.
    let sharp_z = black_box(1e9f32);
    let rounds = 20_000u64;
    let start = Instant::now();
    let mut hits = 0u32;
    for _ in 0..rounds {
        let (cx, cy, cs, cz) = (black_box(&cx), black_box(&cy), black_box(&cs), black_box(&cz));
        for lid in 0..T as u32 {
            let (px, py) = ((lid % 16) as f32 + 0.5, (lid / 16) as f32 + 0.5);
            let mut live = true;
            let mut k = 0;
            while live && k < T {
                let (dx, dy) = (px - cx[k], py - cy[k]);
                let s = cs[k];
                let d2 = dx * dx + dy * dy;
                if cz[k] >= sharp_z {
                    live = false;
                } else if d2 < s * s {
                    hits += 1;
                }
                k += 1;
            }
        }
    }
    let tests = rounds * (T * T) as u64;
    let s = start.elapsed().as_secs_f64();
    println!("{tests} disc tests in {s:.3} s: {:.3} ns a test on one thread ({} hits)", s * 1e9 / tests as f64, black_box(hits));
}
