//! The stiff and extreme cases of the design notes, run on every method of the evaluation's
//! registry (so a new method is stressed without changes here), each with its stated expectation:
//! a correct result within a bound, or a clear error. `dof stress` prints one line per case, method
//! and backend and fails on any failure; `tests/tests/stress.rs` runs every case as a test.
//!
//! Methods run at their last quick setting (the heavier one: for splatting, 4x4 merging).

use crate::backend::Backend;
use crate::error::{CoreError, Error, Result};
use crate::eval::methods::{EvaluatedMethod, MethodInput};
use crate::layers::{Fragment, LayeredImage, RgbImage};
use dof_shaders::lens::ThinLens;

/// What a case expects of a method.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Expect {
    /// The front layer, bit for bit.
    Exact,
    /// The front layer within a relative tolerance.
    Close(f32),
    /// Every pixel equal to the input's flat colour (its first pixel's) within a relative tolerance.
    Flat(f32),
    /// The 8x8 corners of the image equal to a colour within a relative tolerance.
    FlatCorners([f32; 3], f32),
    /// Only finite values.
    Finite,
    /// No pixel darker than the input's darkest colour (per channel, within a relative tolerance,
    /// less 2^-12 of the pixel's brightest channel: a fragment's channels share one exponent, so
    /// a channel far below its fragment's brightest keeps an absolute error of 2^-14 of it): a
    /// bright pixel never takes light from the others.
    NoDarkening(f32),
    /// Pixels farther than `radius` px from every spot (an input front channel above 1e6) keep
    /// their input colour within a relative tolerance: a highlight costs the rest of the frame
    /// nothing beyond its own disc.
    AwayFromSpots { radius: u32, tol: f32 },
    /// Non-finite values only where the input's front was non-finite (nothing spreads).
    NoSpread,
    /// Only finite values, and the red channel's sum within a relative tolerance of the input's.
    Energy(f32),
    /// Two runs give the same image bit for bit.
    Deterministic,
    /// A finite result, or a `TooLarge`/`InvalidArgument`/`InvalidLens` error.
    ResultOrClearError,
    /// An `InvalidLens` error (methods that use the lens).
    InvalidLens,
}

pub struct Case {
    pub name: &'static str,
    /// The stated expectation, in words.
    pub expectation: &'static str,
    pub expect: Expect,
    build: fn() -> (LayeredImage, ThinLens),
}

/// Outcome of one case on one method and backend.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    Pass(String),
    Fail(String),
    /// The case does not apply (a host-only method and a lens error, for instance).
    NotApplicable(&'static str),
}

/// f = 50 mm focused at 2 m, 8000 px per metre of sensor: the far-field CoC is `410·a` px. Shared
/// with the integration tests.
pub fn test_lens(aperture_radius: f32) -> ThinLens {
    ThinLens { focal_length: 0.05, aperture_radius, focus_distance: 2.0, pixels_per_unit: 8000.0 }
}

/// A cheap integer hash: the noise images' (and tests') deterministic randomness.
pub fn hash(i: u32) -> u32 {
    i.wrapping_mul(2654435761).rotate_left(13).wrapping_mul(0x9E37_79B1)
}

/// [`noise_image`] with [`varied`] colours and every 23rd pixel the background alone (the sky: one
/// fragment at depth +inf). Shared with the integration tests.
pub fn noise_with_sky(w: u32, h: u32, layers: u32) -> LayeredImage {
    let mut img = noise_image(w, h, layers, varied);
    let l = layers as usize;
    for p in (0..img.counts.len()).step_by(23) {
        img.counts[p] = 1;
        img.fragments[p * l] = Fragment { color: varied(p as u32), alpha: 1.0, depth: f32::INFINITY };
    }
    img
}

/// `w`x`h`, 1 to `layers` fragments per pixel at distinct depths in `[0.5, 15]`, front to back, the
/// colour of slot `i` from `color(i)`. Shared with the integration tests.
pub fn noise_image(w: u32, h: u32, layers: u32, color: impl Fn(u32) -> [f32; 3]) -> LayeredImage {
    let mut img = LayeredImage::new(w, h, layers).expect("a valid test size");
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            let v = hash(i);
            let mut z = 0.5 + (v >> 8) as f32 % 700.0 / 100.0 + i as f32 * 1e-5;
            for k in 0..1 + v % layers {
                let _ = img.push(x, y, Fragment { color: color(i * 7 + k), alpha: 1.0, depth: z });
                z *= 1.3;
            }
        }
    }
    img
}

/// `img` with every pixel where `keep(pixel)` is false replaced by the background alone (the
/// flat colour [`FLAT`] at depth +inf), and the kept pixels moved to depth 0.6 (near, blurred)
/// with the background behind them.
fn sky_over(img: LayeredImage, keep: impl Fn(u32) -> bool) -> LayeredImage {
    let l = img.max_layers as usize;
    let sky = Fragment { color: FLAT, alpha: 1.0, depth: f32::INFINITY };
    let mut out = LayeredImage::new(img.width, img.height, 2).expect("a valid test size");
    for p in 0..img.counts.len() {
        let (x, y) = (p as u32 % img.width, p as u32 / img.width);
        if keep(p as u32) && img.counts[p] > 0 {
            let front = img.fragments[p * l];
            let _ = out.push(x, y, Fragment { depth: 0.6, ..front });
        }
        let _ = out.push(x, y, sky);
    }
    out
}

/// `w`x`h`, per pixel `panes` translucent panes of alpha `alpha` from depth `z0` on, each `step`
/// behind the last (colours premultiplied: [`varied`] times alpha), over an opaque [`varied`]
/// surface 10% behind the last pane.
fn pane_stack(w: u32, h: u32, panes: u32, alpha: f32, z0: f32, step: f32) -> LayeredImage {
    let mut img = LayeredImage::new(w, h, panes + 1).expect("a valid test size");
    for p in 0..w * h {
        let (x, y) = (p % w, p / w);
        let mut z = z0;
        for k in 0..panes {
            let _ = img.push(x, y, Fragment { color: varied(p * 131 + k).map(|c| c * alpha), alpha, depth: z });
            z += step;
        }
        let _ = img.push(x, y, Fragment::opaque(varied(p), z * 1.1));
    }
    img
}

/// Colours of every scale, some beyond 1000.
pub fn varied(i: u32) -> [f32; 3] {
    let c = hash(i);
    [(c % 97) as f32 / 97.0, (c % 89) as f32 / 8.9, (c % 83) as f32 * 20.0]
}

const FLAT: [f32; 3] = [0.25, 3.0, 1200.0];
/// The colour of the stacked panes (channels of one scale: a fragment's channels share an
/// exponent, and a stack of 100 repeats one rounding 100 times).
const STACK: [f32; 3] = [0.5, 0.3, 0.1];
/// The dim frame of the extreme-HDR cases (measured with 0.5 and 0.3 images).
const DIM: [f32; 3] = [0.5, 0.3, 0.1];

/// A `w`x`h` frame of [`DIM`] at 5 m (CoC radius under 5 px with `test_lens(0.02)`), with the
/// pixels where `spot(pixel)` holds set to `bright` (same depth).
fn dim_with_spots(w: u32, h: u32, bright: [f32; 3], spot: impl Fn(u32) -> bool) -> LayeredImage {
    let mut img = LayeredImage::new(w, h, 1).expect("a valid test size");
    for p in 0..w * h {
        let color = if spot(p) { bright } else { DIM };
        let _ = img.push(p % w, p / w, Fragment { color, alpha: 1.0, depth: 5.0 });
    }
    img
}

pub fn cases() -> Vec<Case> {
    vec![
        Case {
            name: "pinhole",
            expectation: "aperture 0: the front layer, bit for bit",
            expect: Expect::Exact,
            build: || (noise_image(37, 29, 3, varied), test_lens(0.0)),
        },
        Case {
            name: "sub-pixel-coc",
            expectation: "every CoC under one pixel: the front layer within 1e-5",
            expect: Expect::Close(1e-5),
            build: || {
                let mut img = noise_image(40, 33, 2, varied);
                img.fragments.iter_mut().for_each(|f| f.depth = f.depth.max(1.2));
                (img, test_lens(0.0005))
            },
        },
        Case {
            name: "flat-field",
            expectation: "a flat colour stays flat within 1e-3 under blur",
            expect: Expect::Flat(1e-3),
            build: || (noise_image(50, 41, 3, |_| FLAT), test_lens(0.01)),
        },
        Case {
            name: "nan-inf-input",
            expectation: "NaN/Inf colours and NaN, zero, negative depths: nothing non-finite spreads",
            expect: Expect::NoSpread,
            build: || {
                let mut img = noise_image(33, 33, 2, varied);
                let bad = [
                    ([f32::NAN, 1.0, 1.0], 3.0),
                    ([f32::INFINITY, 1.0, 1.0], 3.0),
                    ([1.0; 3], f32::NAN),
                    ([1.0; 3], -2.0),
                    ([1.0; 3], 0.0),
                ];
                for (k, (color, depth)) in bad.into_iter().enumerate() {
                    let p = 100 + 150 * k;
                    img.counts[p] = 1;
                    img.fragments[p * 2] = Fragment { color, alpha: 1.0, depth };
                }
                (img, test_lens(0.02))
            },
        },
        Case {
            name: "hdr-beyond-half",
            expectation: "a 1e6 highlight (beyond half-float 65504) keeps its energy within 3%",
            expect: Expect::Energy(0.03),
            build: || {
                let mut img = LayeredImage::new(48, 48, 1).expect("size");
                for y in 0..48 {
                    for x in 0..48 {
                        let c = if (x, y) == (24, 24) { [1e6, 2e5, 7.0] } else { [0.0; 3] };
                        let _ = img.push(x, y, Fragment { color: c, alpha: 1.0, depth: 5.0 });
                    }
                }
                (img, test_lens(0.05))
            },
        },
        Case {
            name: "colour-at-f32-max",
            expectation: "every 97th pixel at f32::MAX (3.4e38) over a 0.5 frame: finite, non-negative, and no pixel darker than the frame (within 1e-3)",
            expect: Expect::NoDarkening(1e-3),
            build: || (dim_with_spots(64, 48, [f32::MAX; 3], |p| p % 97 == 0), test_lens(0.02)),
        },
        Case {
            name: "colour-1e38",
            expectation: "pixels of 1e38 and 3e38 in single channels over a 0.5 frame: finite, non-negative, no pixel darker than the frame (within 1e-3)",
            expect: Expect::NoDarkening(1e-3),
            build: || {
                let mut img = dim_with_spots(64, 48, [1e38, 0.3, 0.1], |p| p % 89 == 0);
                for p in (40..img.fragments.len()).step_by(131) {
                    img.fragments[p].color = [0.5, 3e38, 0.1];
                }
                (img, test_lens(0.02))
            },
        },
        Case {
            name: "spots-1e12-every-97",
            expectation: "a 1e12 pixel every 97 pixels over a 0.5 frame: no pixel darker than the frame (within 1e-3)",
            expect: Expect::NoDarkening(1e-3),
            build: || (dim_with_spots(96, 64, [1e12; 3], |p| p % 97 == 0), test_lens(0.02)),
        },
        Case {
            name: "spot-1e11-in-dim",
            expectation: "one 1e11 pixel in a dim frame: every pixel beyond 20 px of it keeps its colour within 1e-3",
            expect: Expect::AwayFromSpots { radius: 20, tol: 1e-3 },
            build: || (dim_with_spots(64, 64, [1e11; 3], |p| p == 20 * 64 + 20), test_lens(0.02)),
        },
        Case {
            name: "spots-1e12-over-dim",
            expectation: "a cluster of 1e12 spots in a dim frame: every pixel beyond 20 px of them keeps its colour within 1e-3",
            expect: Expect::AwayFromSpots { radius: 20, tol: 1e-3 },
            build: || {
                let spot = |p: u32| (p % 80) % 5 == 2 && (p / 80) % 5 == 2 && p % 80 < 20 && p / 80 < 20;
                (dim_with_spots(80, 64, [1e12, 2e12, 5e11], spot), test_lens(0.02))
            },
        },
        Case {
            name: "subnormal-colours",
            expectation: "every colour subnormal (below 1.2e-38) or zero: finite and non-negative",
            expect: Expect::Finite,
            build: || (noise_image(40, 33, 3, |i| varied(i).map(|c| c * 1e-42)), test_lens(0.02)),
        },
        Case {
            name: "background-at-limit",
            expectation: "a blurred near square over a background of f32::MAX at +inf (`--background 3e38`): finite, non-negative, and no pixel darker than the square (within 1e-3)",
            expect: Expect::NoDarkening(1e-3),
            build: || {
                let mut img = sky_over(noise_image(96, 96, 1, |_| DIM), |i| (8..88).contains(&(i % 96)) && (8..88).contains(&(i / 96)));
                img.fragments.iter_mut().filter(|f| f.depth.is_infinite()).for_each(|f| f.color = [f32::MAX; 3]);
                (img, test_lens(0.04))
            },
        },
        Case {
            name: "focus-at-focal-length",
            expectation: "z_f = 1.0001 f (CoC of thousands of pixels): a finite image",
            expect: Expect::Finite,
            build: || (noise_image(40, 40, 2, varied), ThinLens { focus_distance: 0.050005, ..test_lens(0.02) }),
        },
        Case {
            name: "coc-beyond-rings",
            expectation: "CoC radius ~1000 px, far beyond every window: capped, finite",
            expect: Expect::Finite,
            build: || (noise_image(64, 48, 2, varied), test_lens(1.0)),
        },
        Case {
            name: "sky-at-infinity",
            expectation: "half the image is a black sky (the background at depth +inf), the other half has no data (no fragment): finite",
            expect: Expect::Finite,
            build: || {
                let mut img = noise_image(48, 32, 2, varied);
                for p in 0..(48 * 16) {
                    img.counts[p] = 1;
                    img.fragments[2 * p] = Fragment { color: [0.0; 3], alpha: 1.0, depth: f32::INFINITY };
                }
                for p in 48 * 16..48 * 24 {
                    img.counts[p] = 0;
                }
                (img, test_lens(0.02))
            },
        },
        Case {
            name: "coloured-sky",
            expectation: "only the background (depth +inf, a flat HDR colour): every pixel keeps that colour within 1e-3",
            expect: Expect::Flat(1e-3),
            build: || (sky_over(noise_image(48, 32, 1, |_| FLAT), |_| false), test_lens(0.03)),
        },
        Case {
            name: "near-object-over-sky",
            expectation: "a blurred near square over a flat coloured sky at +inf: finite, and the sky keeps its colour within 1e-3 in the image's corners, beyond the blur",
            expect: Expect::FlatCorners(FLAT, 1e-3),
            // The square's CoC radius is 19 px; the corners lie at least 32 px from it.
            build: || {
                (
                    sky_over(noise_image(96, 96, 1, varied), |i| (40..56).contains(&(i % 96)) && (40..56).contains(&(i / 96))),
                    test_lens(0.04),
                )
            },
        },
        Case {
            name: "equal-depths",
            expectation: "every fragment at one depth: ties resolve the same way every run",
            expect: Expect::Deterministic,
            build: || {
                let mut img = noise_image(40, 40, 1, varied);
                img.fragments.iter_mut().for_each(|f| f.depth = 0.9);
                (img, test_lens(0.01))
            },
        },
        Case {
            name: "one-pixel",
            expectation: "a 1x1 image: finite, one pixel",
            expect: Expect::Finite,
            build: || (noise_image(1, 1, 2, varied), test_lens(0.02)),
        },
        Case {
            name: "ragged-size",
            expectation: "17x5 (no multiple of any tile): finite, every pixel",
            expect: Expect::Finite,
            build: || (noise_image(17, 5, 2, varied), test_lens(0.01)),
        },
        Case {
            name: "very-wide-image",
            expectation: "40000x2: a finite image, or a clear TooLarge error",
            expect: Expect::ResultOrClearError,
            build: || (noise_image(40_000, 2, 1, varied), test_lens(0.01)),
        },
        Case {
            name: "translucent-stack-in-focus",
            expectation: "100 stacked panes of alpha 0.01 over an opaque surface, aperture 1e-7: the front-to-back composite within 1e-4",
            expect: Expect::Close(1e-4),
            build: || (pane_stack(24, 20, 100, 0.01, 1.0, 0.001), test_lens(1e-7)),
        },
        Case {
            name: "translucent-stack-blurred",
            expectation: "100 stacked panes of alpha 0.01, one colour, over the same colour, out of focus: that colour within \
                          4e-2 (splatting stores alpha in 10 bits, 0.01 as 0.0098, so the panes' light fills less coverage than it \
                          should: measured 1.4% bright on the CPU backend, 2.3% on lavapipe, where these tile lists of 16 384 \
                          entries and more come out without the surface behind; the others within 3e-4)",
            expect: Expect::Flat(4e-2),
            build: || {
                let mut img = pane_stack(40, 36, 100, 0.01, 1.2, 0.001);
                let l = img.max_layers as usize;
                for p in 0..img.counts.len() {
                    for f in &mut img.fragments[p * l..p * l + img.counts[p] as usize] {
                        f.color = STACK.map(|c| c * f.alpha);
                    }
                }
                (img, test_lens(0.008))
            },
        },
        Case {
            name: "alpha-0-glow",
            expectation: "a blurred patch of alpha exactly 0 (light that hides nothing) over an opaque in-focus surface: the light \
                          of both kept (red sum within 3e-2 of the input's composite; the glow is 30% of it. The gathering baseline, \
                          and bokeh sprites over it, spread a blurred near pixel over a sharp one without taking its place: \
                          measured 2.1% bright, the others within 0.2%)",
            expect: Expect::Energy(3e-2),
            build: || {
                let (w, h) = (48u32, 48u32);
                let mut img = LayeredImage::new(w, h, 2).expect("a valid test size");
                for p in 0..w * h {
                    let (x, y) = (p % w, p / w);
                    if (20..28).contains(&x) && (20..28).contains(&y) {
                        let _ = img.push(x, y, Fragment { color: [5.0, 0.5, 0.0], alpha: 0.0, depth: 1.6 });
                    }
                    let _ = img.push(x, y, Fragment::opaque(DIM, 2.0));
                }
                (img, test_lens(0.01))
            },
        },
        Case {
            name: "alpha-0-and-1-in-focus",
            expectation: "slots of alpha exactly 0 (with colour) and exactly 1, aperture 1e-7: the composite (light of the alpha-0 \
                          slots added, nothing behind an alpha-1 slot) within 1e-5",
            expect: Expect::Close(1e-5),
            build: || {
                let mut img = noise_image(30, 22, 3, varied);
                let l = img.max_layers as usize;
                for p in 0..img.counts.len() {
                    if p % 3 == 0 && img.counts[p] > 1 {
                        img.fragments[p * l].alpha = 0.0;
                    }
                }
                (img, test_lens(1e-7))
            },
        },
        Case {
            name: "alpha-out-of-range",
            expectation: "alphas NaN, negative, above 1 and infinite are clamped (NaN to 0), aperture 1e-7: the composite of the \
                          clamped alphas within 1e-5, and finite",
            expect: Expect::Close(1e-5),
            build: || {
                let mut img = noise_image(30, 22, 3, varied);
                let l = img.max_layers as usize;
                let bad = [f32::NAN, -0.5, 1.5, f32::INFINITY, f32::NEG_INFINITY, 0.25];
                for p in 0..img.counts.len() {
                    if img.counts[p] > 1 {
                        img.fragments[p * l].alpha = bad[p % bad.len()];
                    }
                }
                (img, test_lens(1e-7))
            },
        },
        Case {
            name: "footprint-emitters",
            expectation: "sub-pixel emitters (1e4) at partial alpha with footprints on a 4x4 grid (one to fifteen sub-samples, \
                          and bits beyond the grid) over a dim wall in focus, blurred a few px: no pixel darker than the wall (their \
                          light kept is checked on multi-layer splatting in tests/tests/footprints.rs: the single-layer methods \
                          flatten an emitter over the wall into one blurred surface, up to 42% bright here)",
            expect: Expect::NoDarkening(1e-3),
            build: || (footprinted(48, 40, |p| 1.2 + (p % 7) as f32 * 0.1), test_lens(0.01)),
        },
        Case {
            name: "footprint-coc-extremes",
            expectation: "the same footprints with CoC radii from 1e-5 px to beyond every window (~1000 px): finite",
            expect: Expect::Finite,
            build: || (footprinted(40, 32, |p| if p % 2 == 0 { 1.99999 } else { 0.0501 }), test_lens(1.0)),
        },
        Case {
            name: "degenerate-lens",
            expectation: "focus distance below the focal length: an InvalidLens error",
            expect: Expect::InvalidLens,
            build: || (noise_image(16, 16, 1, varied), ThinLens { focus_distance: 0.01, ..test_lens(0.01) }),
        },
    ]
}

/// A dim wall at the test lens' focus with an emitter in front of every 29th pixel 10 px or more
/// inside the frame, at `depth(p)`,
/// covering a varying part of a 4x4 grid (its alpha that share; its mask given in the footprints,
/// some with bits beyond what the grid needs).
fn footprinted(w: u32, h: u32, depth: impl Fn(u32) -> f32) -> LayeredImage {
    let mut img = LayeredImage::new(w, h, 2).expect("a valid test size");
    img.footprints = vec![dof_shaders::footprint::WHOLE; img.fragments.len()];
    img.footprint_side = 4;
    for p in 0..w * h {
        let (x, y) = (p % w, p / w);
        if p % 29 == 0 && (10..w - 10).contains(&x) && (10..h - 10).contains(&y) {
            let mask = hash(p) & 0xffff | if p % 3 == 0 { 0xffff_0000 } else { 0 };
            let alpha = (mask & 0xffff).count_ones() as f32 / 16.0;
            if alpha > 0.0 {
                let _ = img.push(x, y, Fragment { color: [1e4 * alpha, 10.0 * alpha, 0.0], alpha, depth: depth(p) });
                img.footprints[(p * 2) as usize] = mask;
            }
        }
        let _ = img.push(x, y, Fragment::opaque(DIM, 2.0));
    }
    img
}

fn input(img: LayeredImage, lens: ThinLens) -> MethodInput {
    MethodInput::new(img, lens, 0)
}

fn finite(img: &RgbImage) -> bool {
    img.data.iter().all(|p| p.iter().all(|c| c.is_finite()))
}

fn red_sum(img: &RgbImage) -> f64 {
    img.data.iter().map(|p| p[0] as f64).sum()
}

impl Case {
    /// Runs this case on `method` (at its last quick setting) on `backend`.
    pub fn run(&self, method: &dyn EvaluatedMethod, backend: &mut dyn Backend) -> Outcome {
        let (img, lens) = (self.build)();
        let input = input(img, lens);
        let Some(setting) = method.settings(true).pop() else { return Outcome::NotApplicable("no setting") };
        let result = method.run(backend, &input, &setting);
        if !method.uses_backend() && self.expect == Expect::InvalidLens {
            return Outcome::NotApplicable("the method ignores the lens");
        }
        let out = match (result, self.expect) {
            (Err(Error::Core(CoreError::InvalidLens(m))), Expect::InvalidLens) => return Outcome::Pass(format!("error: {m}")),
            (
                Err(e @ Error::Core(CoreError::TooLarge { .. } | CoreError::InvalidArgument(_) | CoreError::InvalidLens(_))),
                Expect::ResultOrClearError,
            ) => {
                return Outcome::Pass(format!("error: {e}"));
            }
            (Err(e), _) => return Outcome::Fail(format!("error: {e}")),
            (Ok(_), Expect::InvalidLens) => return Outcome::Fail("no error for an invalid lens".into()),
            (Ok(out), _) => out.image,
        };
        let front = &input.front;
        if out.width != front.width || out.height != front.height || out.data.len() != front.data.len() {
            return Outcome::Fail(format!("{}x{} out for {}x{} in", out.width, out.height, front.width, front.height));
        }
        let spread =
            out.data.iter().zip(&front.data).filter(|(o, f)| !o.iter().all(|c| c.is_finite()) && f.iter().all(|c| c.is_finite())).count();
        if spread > 0 {
            return Outcome::Fail(format!("{spread} non-finite pixels where the input was finite"));
        }
        if self.expect != Expect::NoSpread && !finite(&out) {
            return Outcome::Fail("non-finite pixels".into());
        }
        // The numerical contract: non-negative input gives non-negative output.
        let negative_in = front.data.iter().any(|p| p.iter().any(|&c| c < 0.0));
        let negative_out = out.data.iter().filter(|p| p.iter().any(|&c| c < 0.0)).count();
        if !negative_in && negative_out > 0 {
            return Outcome::Fail(format!("{negative_out} negative pixels from non-negative input"));
        }
        // Pixel `i`'s largest relative error against `want`, and the worst over the image.
        let off = |i: usize, want: [f32; 3]| {
            let p = out.data[i];
            (0..3).map(|c| (p[c] - want[c]).abs() / want[c].abs().max(1e-3)).fold(0.0f32, f32::max)
        };
        let worst = |want: &dyn Fn(usize) -> [f32; 3]| (0..out.data.len()).map(|i| off(i, want(i))).fold(0.0f32, f32::max);
        match self.expect {
            Expect::Exact if out == *front => Outcome::Pass("identical".into()),
            Expect::Exact => Outcome::Fail(format!("differs from the input by up to {:.2e} (relative)", worst(&|i| front.data[i]))),
            Expect::Close(tol) | Expect::Flat(tol) => {
                let want = |i: usize| if let Expect::Flat(_) = self.expect { front.data[0] } else { front.data[i] };
                let err = worst(&want);
                if err <= tol {
                    Outcome::Pass(format!("within {err:.2e}"))
                } else {
                    // Where: how many pixels are that far off, and the first of them.
                    let far: Vec<usize> = (0..out.data.len()).filter(|&i| off(i, want(i)) > tol).collect();
                    let i = far[0];
                    let (x, y) = (i % out.width as usize, i / out.width as usize);
                    Outcome::Fail(format!(
                        "off by {err:.2e} > {tol:.0e} ({} of {} pixels; the first at ({x}, {y}): {:?} for {:?})",
                        far.len(),
                        out.data.len(),
                        out.data[i],
                        want(i)
                    ))
                }
            }
            Expect::FlatCorners(want, tol) => {
                let (w, h) = (out.width as usize, out.height as usize);
                let corner = |i: usize| (i % w < 8 || i % w >= w - 8) && (i / w < 8 || i / w >= h - 8);
                let err = out
                    .data
                    .iter()
                    .enumerate()
                    .filter(|(i, _)| corner(*i))
                    .map(|(_, p)| (0..3).map(|c| (p[c] - want[c]).abs() / want[c]).fold(0.0f32, f32::max))
                    .fold(0.0f32, f32::max);
                if err <= tol {
                    Outcome::Pass(format!("corners within {err:.2e}"))
                } else {
                    Outcome::Fail(format!("corners off by {err:.2e} > {tol:.0e}"))
                }
            }
            Expect::Energy(tol) => {
                let (got, want) = (red_sum(&out), red_sum(front));
                let rel = (got / want - 1.0).abs();
                if rel <= tol as f64 {
                    Outcome::Pass(format!("energy within {:.2}%", 100.0 * rel))
                } else {
                    Outcome::Fail(format!("energy {got:.4e} vs {want:.4e}"))
                }
            }
            Expect::Deterministic => match method.run(backend, &input, &setting) {
                Ok(again) if again.image == out => Outcome::Pass("two runs identical".into()),
                Ok(_) => Outcome::Fail("two runs differ".into()),
                Err(e) => Outcome::Fail(format!("second run: {e}")),
            },
            Expect::NoDarkening(tol) => {
                let darkest = front.data.iter().fold([f32::INFINITY; 3], |m, p| [m[0].min(p[0]), m[1].min(p[1]), m[2].min(p[2])]);
                let shared = |p: &[f32; 3]| p[0].max(p[1]).max(p[2]) * (1.0 / 4096.0);
                let darker = out.data.iter().filter(|p| (0..3).any(|c| p[c] < darkest[c] * (1.0 - tol) - shared(p))).count();
                if darker == 0 {
                    Outcome::Pass(format!("no pixel below {darkest:?}"))
                } else {
                    Outcome::Fail(format!("{darker} pixels darker than the input's darkest {darkest:?}"))
                }
            }
            Expect::AwayFromSpots { radius, tol } => {
                let w = out.width as usize;
                let spots: Vec<(i64, i64)> = front
                    .data
                    .iter()
                    .enumerate()
                    .filter(|(_, p)| p.iter().any(|&c| c > 1e6))
                    .map(|(i, _)| ((i % w) as i64, (i / w) as i64))
                    .collect();
                let far = |i: usize| {
                    let (x, y) = ((i % w) as i64, (i / w) as i64);
                    spots.iter().all(|&(sx, sy)| (x - sx).pow(2) + (y - sy).pow(2) > (radius as i64).pow(2))
                };
                let checked: Vec<usize> = (0..out.data.len()).filter(|&i| far(i)).collect();
                let err = checked
                    .iter()
                    .map(|&i| {
                        (0..3).map(|c| (out.data[i][c] - front.data[i][c]).abs() / front.data[i][c].abs().max(1e-3)).fold(0.0f32, f32::max)
                    })
                    .fold(0.0f32, f32::max);
                if checked.is_empty() {
                    Outcome::Fail("no pixel lies beyond the spots' reach".into())
                } else if err <= tol {
                    Outcome::Pass(format!("{} pixels beyond {radius} px of {} spots within {err:.2e}", checked.len(), spots.len()))
                } else {
                    Outcome::Fail(format!("pixels beyond {radius} px of the spots off by {err:.2e} > {tol:.0e}"))
                }
            }
            Expect::Finite | Expect::ResultOrClearError => Outcome::Pass("finite".into()),
            Expect::NoSpread => Outcome::Pass("nothing spread".into()),
            Expect::InvalidLens => Outcome::Fail("unreachable".into()),
        }
    }
}

/// Finds a case by name.
pub fn case(name: &str) -> Result<Case> {
    cases().into_iter().find(|c| c.name == name).ok_or_else(|| Error::invalid(format!("no stress case `{name}`")))
}
