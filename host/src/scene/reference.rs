//! The exact depth-of-field reference of an analytic scene: thin-lens distributed ray tracing.
//!
//! Per pixel, `spp` samples jointly stratified over the lens disc (concentric mapping) and the
//! pixel's area (a box filter, as pbrt and Mitsuba integrate), see [`super::sampling::stratified`].
//! Each ray leaves its lens point towards the point where the pinhole ray through its pixel
//! position meets the focus plane ([`CameraFrame::lens_ray`]); its first hit is shaded with the
//! scene's lighting model (past translucent surfaces, every surface it crosses composited front to
//! back, [`Scene::trace`]); the samples are averaged in `f64` and stored as `f32`.
//!
//! **Noise estimate.** The samples are drawn as two independent halves `A` and `B` (each
//! stratified on its own); the image is their pooled mean. With `σ²` the per-sample variance, `MSE(A,
//! B) = σ²(1/n_A + 1/n_B)` while the pooled mean's error against the converged image is
//! `σ²/(n_A + n_B)`, so `PSNR(image, converged) ≈ PSNR(A, B) + 10·log10((1/n_A + 1/n_B)(n_A +
//! n_B))`, i.e. `+6.02 dB` for equal halves (each half alone would be `+3.01 dB`). PSNR here is
//! the evaluation's: on the documented display transform ([`crate::io::tonemap::tonemap`] at
//! exposure 1, ACES fit then sRGB; see [`crate::metrics`]), so highlights far above 1 do not
//! dominate it and the estimate speaks about the numbers the comparisons report.
//!
//! **Auto.** A method with true error `PSNR_m`, measured against a reference with noise `PSNR_r`,
//! reads `PSNR_m − 10·log10(1 + 10^((PSNR_m − PSNR_r)/10))`. [`reference_auto`] doubles the sample
//! count until that bias is below `tolerance_db` for every method up to `target_psnr_db`, i.e.
//! until `PSNR_r >= target + 10·log10(1/(10^(tolerance/10) − 1))` (`target + 9.14 dB` for 0.5 dB),
//! or the cap is reached (reported). Given a `region` (e.g. the partial-occlusion region, where
//! methods are compared too and the noise is usually worse than full-frame), the estimate over that
//! region must reach the requirement as well.
//!
//! Scenes with tiny HDR emitters converge slowly on this metric: a pixel that a bokeh disc barely
//! overlaps is bright after tone mapping but hit by fewer than one sample in `spp`, so the error
//! concentrates in a band at bokeh rims that narrows only slowly as `spp` grows. Expect the cap
//! there, and read [`Reference::valid_up_to_psnr_db`] for what the result can still measure; or
//! set `aimed_emitters`: the emissive spheres' light is then integrated with samples aimed at each
//! ([`super::aimed`]), once a half with its own seed, and added to the uniform samples of the scene
//! with those spheres black, so both halves (and the noise estimate) include it.

use dof_shaders::lens::ThinLens;
use rayon::prelude::*;

use super::aimed;
use super::analytic::Scene;
use super::camera::{Camera, CameraFrame};
use super::sampling::{concentric_disc, pixel_rng, stratified};
use crate::error::{Error, Result};
use crate::layers::RgbImage;
use crate::metrics::{psnr_of_mse, squared_error};
use crate::progress::Progress;

/// One reference render.
#[derive(Clone, Debug, PartialEq)]
pub struct ReferenceOptions {
    /// Samples per pixel, `>= 1` (default 64).
    pub spp: u32,
    /// Jitter samples inside their strata (default on). Off, `spp = 1` traces the centre ray.
    pub jitter: bool,
    pub seed: u64,
    /// Show an `indicatif` progress bar on stderr (feature `progress`; ignored without it).
    pub progress: bool,
    /// Pixels (row-major, `true` = inside) over which a second noise estimate is made, e.g. the
    /// partial-occlusion region where methods are also compared.
    pub region: Option<Vec<bool>>,
    /// Integrate the emissive spheres' light with samples aimed at them (module docs; default off).
    /// Refused for scenes with translucent surfaces.
    pub aimed_emitters: bool,
}

impl Default for ReferenceOptions {
    fn default() -> Self {
        ReferenceOptions { spp: 64, jitter: true, seed: 0, progress: false, region: None, aimed_emitters: false }
    }
}

/// Settings of [`reference_auto`].
#[derive(Clone, Debug, PartialEq)]
pub struct AutoOptions {
    /// Best PSNR (dB, on the display transform) a compared method may reach and still be measured within
    /// `tolerance_db` (default 40).
    pub target_psnr_db: f64,
    /// Largest bias the reference's noise may put on such a measurement (default 0.5 dB).
    pub tolerance_db: f64,
    /// First sample count, `>= 2` (default 16); doubled each round.
    pub start_spp: u32,
    /// Cap on the sample count (default 4096).
    pub max_spp: u32,
    pub seed: u64,
    pub progress: bool,
    /// A pixel region (row-major, `true` = inside) whose own noise estimate must also reach the
    /// requirement, e.g. the partial-occlusion region. `None`: the full frame only.
    pub region: Option<Vec<bool>>,
    /// As [`ReferenceOptions::aimed_emitters`], aimed once with the samples of 1024 spp (or
    /// `max_spp` if lower); the uniform samples then grow as without it.
    pub aimed_emitters: bool,
}

impl Default for AutoOptions {
    fn default() -> Self {
        AutoOptions {
            target_psnr_db: 40.0,
            tolerance_db: 0.5,
            start_spp: 16,
            max_spp: 4096,
            seed: 0,
            progress: false,
            region: None,
            aimed_emitters: false,
        }
    }
}

impl AutoOptions {
    /// The reference noise PSNR these settings require.
    pub fn required_noise_psnr_db(&self) -> f64 {
        self.target_psnr_db + noise_margin_db(self.tolerance_db)
    }
}

/// How far (dB) a reference's noise PSNR must lie above a method's PSNR for the measurement to be
/// biased by at most `tolerance_db`: `10·log10(1/(10^(tolerance/10) − 1))` (9.14 dB for 0.5 dB).
pub fn noise_margin_db(tolerance_db: f64) -> f64 {
    10.0 * (1.0 / (10f64.powf(tolerance_db / 10.0) - 1.0)).log10()
}

/// A reference image and how good it is.
#[derive(Clone, Debug, PartialEq)]
pub struct Reference {
    pub image: RgbImage,
    /// Samples per pixel used.
    pub spp: u32,
    /// Estimated PSNR (dB, on the display transform) of `image` against the converged image; `None` for
    /// `spp = 1`; `+inf` when the two halves agree exactly (e.g. a constant image).
    pub noise_psnr_db: Option<f64>,
    /// The same estimate over the requested region only (`None` without a region or for `spp = 1`).
    pub region_noise_psnr_db: Option<f64>,
    /// What [`reference_auto`] aimed for; `None` for a fixed sample count.
    pub required_psnr_db: Option<f64>,
    /// [`reference_auto`] stopped at `max_spp` before reaching `required_psnr_db`.
    pub capped: bool,
}

impl Reference {
    /// The best method PSNR (dB) this reference measures with a bias of at most `tolerance_db`:
    /// the smaller noise estimate minus [`noise_margin_db`]. `None` without an estimate.
    pub fn valid_up_to_psnr_db(&self, tolerance_db: f64) -> Option<f64> {
        let noise = match (self.noise_psnr_db, self.region_noise_psnr_db) {
            (Some(a), Some(b)) => a.min(b),
            (a, _) => a?,
        };
        Some(noise - noise_margin_db(tolerance_db))
    }
}

/// Mean squared difference of the tone-mapped channels, over `region` when given.
fn tonemapped_mse(a: impl Iterator<Item = [f32; 3]>, b: impl Iterator<Item = [f32; 3]>, region: Option<&[bool]>) -> f64 {
    let mut sum = 0.0f64;
    let mut n = 0usize;
    for (i, (p, q)) in a.zip(b).enumerate() {
        if region.is_none_or(|r| r.get(i).copied().unwrap_or(false)) {
            n += 1;
            sum += squared_error(p, q);
        }
    }
    sum / (3 * n.max(1)) as f64
}

fn check_region(region: &Option<Vec<bool>>, frame: &CameraFrame) -> Result<()> {
    match region {
        Some(r) if r.len() != frame.width as usize * frame.height as usize => {
            Err(Error::invalid(format!("the noise region has {} entries for a {}x{} image", r.len(), frame.width, frame.height)))
        }
        _ => Ok(()),
    }
}

/// Thin-lens reference with a fixed sample count. Errors on an invalid camera or lens, or
/// `spp == 0`.
pub fn reference(scene: &Scene, camera: &Camera, lens: &ThinLens, options: &ReferenceOptions) -> Result<Reference> {
    let frame = camera.frame()?;
    crate::lens::check(lens)?;
    render_fixed(scene, &frame, lens.aperture_radius, lens.focus_distance, options, options.aimed_emitters.then_some(lens))
}

/// The pinhole image (aperture 0) with the same sampling: with `spp = 1` and no jitter, the
/// radiance along each pixel's centre ray.
pub fn pinhole(scene: &Scene, camera: &Camera, options: &ReferenceOptions) -> Result<Reference> {
    let frame = camera.frame()?;
    render_fixed(scene, &frame, 0.0, 1.0, options, None)
}

/// Thin-lens reference whose sample count is raised (doubled from `start_spp`) until its noise
/// estimate reaches [`AutoOptions::required_noise_psnr_db`] or `max_spp` (then `capped`). Errors
/// on an invalid camera, lens or options.
pub fn reference_auto(scene: &Scene, camera: &Camera, lens: &ThinLens, options: &AutoOptions) -> Result<Reference> {
    let frame = camera.frame()?;
    crate::lens::check(lens)?;
    let o = options;
    if !(o.target_psnr_db.is_finite() && o.tolerance_db > 0.0 && o.tolerance_db.is_finite()) {
        return Err(Error::invalid(format!(
            "auto reference: the target PSNR must be finite and the tolerance positive, got {} dB and {} dB",
            o.target_psnr_db, o.tolerance_db
        )));
    }
    if o.start_spp < 2 || o.max_spp < o.start_spp || o.max_spp > MAX_SPP {
        return Err(Error::invalid(format!(
            "auto reference: need 2 <= start_spp <= max_spp <= {MAX_SPP}, got {} and {}",
            o.start_spp, o.max_spp
        )));
    }
    check_region(&o.region, &frame)?;
    frame.check_size("reference image", 1)?;
    let region = o.region.as_deref();
    let required = o.required_noise_psnr_db();
    let pixels = frame.width as usize * frame.height as usize;
    let mut a = Accum::new(pixels);
    let mut b = Accum::new(pixels);
    let rest = if o.aimed_emitters { aim(scene, &frame, lens, o.max_spp.min(1024), o.seed, &mut a, &mut b)? } else { None };
    let scene = rest.as_ref().unwrap_or(scene);
    let mut batch = 0u64;
    let mut m = o.start_spp / 2;
    let (mut estimate, mut region_estimate);
    loop {
        let bar = progress_bar(o.progress, &frame, 2, &format!("reference: +{} spp", 2 * m));
        for acc in [&mut a, &mut b] {
            render_batch(scene, &frame, lens.aperture_radius, lens.focus_distance, m, true, o.seed, batch, bar.as_ref(), acc);
            batch += 1;
        }
        if let Some(bar) = bar {
            bar.finish_and_clear();
        }
        estimate = noise_estimate(&a, &b, None);
        region_estimate = region.map(|r| noise_estimate(&a, &b, Some(r)));
        let reached = estimate >= required && region_estimate.is_none_or(|e| e >= required);
        let total = a.n + b.n;
        if reached || total >= o.max_spp {
            break;
        }
        m = a.n.min((o.max_spp - total) / 2);
        if m == 0 {
            break;
        }
    }
    let capped = !(estimate >= required && region_estimate.is_none_or(|e| e >= required));
    Ok(Reference {
        image: pooled(&frame, &a, &b),
        spp: a.n + b.n,
        noise_psnr_db: Some(estimate),
        region_noise_psnr_db: region_estimate,
        required_psnr_db: Some(required),
        capped,
    })
}

/// Most samples per pixel a reference (and renders an accumulation buffer) takes: refused beyond,
/// before anything proportional to the count is allocated.
pub const MAX_SPP: u32 = 1 << 16;

/// The reference with `options`; with `aimed` (the lens), the emitters' light aimed at them.
fn render_fixed(
    scene: &Scene,
    frame: &CameraFrame,
    radius: f32,
    focus: f32,
    options: &ReferenceOptions,
    aimed: Option<&ThinLens>,
) -> Result<Reference> {
    if options.spp == 0 || options.spp > MAX_SPP {
        return Err(Error::invalid(format!("a reference takes 1 to {MAX_SPP} samples per pixel, got {}", options.spp)));
    }
    check_region(&options.region, frame)?;
    frame.check_size("reference image", 1)?;
    let pixels = frame.width as usize * frame.height as usize;
    let (na, nb) = (options.spp - options.spp / 2, options.spp / 2);
    let mut a = Accum::new(pixels);
    let mut b = Accum::new(pixels);
    let rest = match aimed {
        Some(lens) => aim(scene, frame, lens, options.spp, options.seed, &mut a, &mut b)?,
        None => None,
    };
    let scene = rest.as_ref().unwrap_or(scene);
    let halves = if nb > 0 { 2 } else { 1 };
    let bar = progress_bar(options.progress, frame, halves, &format!("reference: {} spp", options.spp));
    render_batch(scene, frame, radius, focus, na, options.jitter, options.seed, 0, bar.as_ref(), &mut a);
    if nb > 0 {
        render_batch(scene, frame, radius, focus, nb, options.jitter, options.seed, 1, bar.as_ref(), &mut b);
    }
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    let noise_psnr_db = (nb > 0).then(|| noise_estimate(&a, &b, None));
    let region_noise_psnr_db = options.region.as_deref().filter(|_| nb > 0).map(|r| noise_estimate(&a, &b, Some(r)));
    Ok(Reference {
        image: pooled(frame, &a, &b),
        spp: options.spp,
        noise_psnr_db,
        region_noise_psnr_db,
        required_psnr_db: None,
        capped: false,
    })
}

/// Per-pixel radiance sums of one independent half, and the aimed emitters' light it adds (its own
/// estimate, independent of the other half's).
struct Accum {
    sum: Vec<[f64; 3]>,
    n: u32,
    aimed: Option<RgbImage>,
}

impl Accum {
    fn new(pixels: usize) -> Self {
        Accum { sum: vec![[0.0; 3]; pixels], n: 0, aimed: None }
    }

    /// The aimed light at pixel `i` (0 without).
    fn aimed_at(&self, i: usize) -> [f64; 3] {
        self.aimed.as_ref().map_or([0.0; 3], |a| a.data[i].map(f64::from))
    }

    fn mean(&self) -> impl Iterator<Item = [f32; 3]> + '_ {
        let n = self.n.max(1) as f64;
        self.sum.iter().enumerate().map(move |(i, s)| {
            let e = self.aimed_at(i);
            [0, 1, 2].map(|k| (s[k] / n + e[k]) as f32)
        })
    }
}

fn pooled(frame: &CameraFrame, a: &Accum, b: &Accum) -> RgbImage {
    let (na, nb) = (a.n as f64, b.n as f64);
    let n = (na + nb).max(1.0);
    let mut image = RgbImage::new(frame.width, frame.height);
    for (i, ((out, sa), sb)) in image.data.iter_mut().zip(&a.sum).zip(&b.sum).enumerate() {
        let (ea, eb) = (a.aimed_at(i), b.aimed_at(i));
        *out = [0, 1, 2].map(|k| ((sa[k] + sb[k] + ea[k] * na + eb[k] * nb) / n) as f32);
    }
    image
}

/// With a lens that blurs and a scene with emitters: each half's aimed light (seeds `2·seed` and
/// `2·seed + 1`, the samples of `spp`, [`aimed::sides_for`]) into `a` and `b`, and the scene the
/// uniform samples are then taken of (its emitters black). `None`: nothing to aim at.
fn aim(scene: &Scene, frame: &CameraFrame, lens: &ThinLens, spp: u32, seed: u64, a: &mut Accum, b: &mut Accum) -> Result<Option<Scene>> {
    if !(lens.aperture_radius > 0.0) || aimed::emitters(scene).is_empty() {
        return Ok(None);
    }
    let rest = aimed::without_emitters(scene)?;
    let (pixel_side, lens_side) = aimed::sides_for(spp);
    a.aimed = Some(aimed::aimed_emitters(scene, frame, lens, pixel_side, lens_side, seed.wrapping_mul(2)));
    b.aimed = Some(aimed::aimed_emitters(scene, frame, lens, pixel_side, lens_side, seed.wrapping_mul(2).wrapping_add(1)));
    Ok(Some(rest))
}

/// Estimated PSNR of the pooled mean of `a` and `b` against the converged image (module docs).
fn noise_estimate(a: &Accum, b: &Accum, region: Option<&[bool]>) -> f64 {
    let (na, nb) = (a.n as f64, b.n as f64);
    let mse_ab = tonemapped_mse(a.mean(), b.mean(), region);
    let factor = (1.0 / na + 1.0 / nb) * (na + nb);
    psnr_of_mse(mse_ab / factor)
}

fn progress_bar(show: bool, frame: &CameraFrame, passes: u64, message: &str) -> Option<Progress> {
    let template = "{msg} [{elapsed_precise}] {wide_bar} {pos}/{len} rows (eta {eta})";
    Progress::new(show, frame.height as u64 * passes, template, message)
}

/// Adds `n` stratified samples per pixel to `acc`, rows in parallel.
#[allow(clippy::too_many_arguments)]
fn render_batch(
    scene: &Scene,
    frame: &CameraFrame,
    radius: f32,
    focus: f32,
    n: u32,
    jitter: bool,
    seed: u64,
    batch: u64,
    bar: Option<&Progress>,
    acc: &mut Accum,
) {
    let width = frame.width as usize;
    acc.sum.par_chunks_mut(width).enumerate().for_each_init(
        || (Vec::new(), Vec::new(), Vec::new()),
        |(samples, perm, hits), (y, row)| {
            for (x, out) in row.iter_mut().enumerate() {
                let pixel = (y * width + x) as u64;
                let mut rng = pixel_rng(seed, batch, pixel);
                stratified(n, jitter, &mut rng, samples, perm);
                let mut sum = [0.0f64; 3];
                for s in samples.iter() {
                    let (dx, dy) = concentric_disc(s.lens.0, s.lens.1);
                    let ray = frame.lens_ray(x as f32 + s.pixel.0, y as f32 + s.pixel.1, radius * dx, radius * dy, focus);
                    let c = scene.trace_with(&ray, hits);
                    for k in 0..3 {
                        sum[k] += c[k] as f64;
                    }
                }
                for k in 0..3 {
                    out[k] += sum[k];
                }
            }
            if let Some(bar) = bar {
                bar.inc(1);
            }
        },
    );
    acc.n += n;
}
