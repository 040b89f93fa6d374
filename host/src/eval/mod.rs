//! The evaluation: every scene × method × quality setting × backend, timed per stage and measured
//! against the scene's reference, full frame and inside the partial-occlusion region. Built-in
//! scenes bring their exact ray-cast layers and thin-lens reference; glTF files (`.gltf`, `.glb`)
//! are depth-peeled and measured against their accumulation buffer, both on the first backend.
//! Methods come from [`methods::evaluated_methods`], so a new method appears here without changes.
//!
//! Timing: one warm-up run, then the median of `runs` runs, per stage (GPU timestamps on Vulkan,
//! wall time per dispatch on the CPU backend). Error: [`crate::metrics`] against the reference.

pub mod backend_info;
pub mod figures;
pub mod grid;
pub mod methods;
pub mod plot;
pub mod ratios;
pub mod report;
pub mod scaling;
pub mod sweep;
pub mod temporal;

use crate::backend::Backend;
use crate::error::{Error, Result};
use crate::layers::RgbImage;
use crate::metrics::compare;
use crate::raster::{AccumulateOptions, DeviceMesh, accumulate_with, peel_layers_with};
use crate::scene::{
    AutoOptions, LayerOptions, ReferenceOptions, SceneLayers, builtin, load_gltf, raycast_layers, reference, reference_auto,
};
use crate::timing::RunTimes;
use dof_shaders::lens::ThinLens;
use methods::{EvaluatedMethod, MethodInput, MethodOutput, Setting, evaluated_methods};
use report::{BackendInfo, Record, Report, SceneInfo};

pub struct EvalOptions {
    pub scenes: Vec<String>,
    /// Method names; empty for all.
    pub methods: Vec<String>,
    /// Small images, a fixed 64-spp reference, the quick settings and 3 timed runs.
    pub quick: bool,
    /// Timed runs per point after the warm-up (the median is reported).
    pub runs: usize,
    pub progress: bool,
    /// Largest CoC radii (px) of the max-CoC sweep on the first scene (at 320x180, 160x90 with
    /// `quick`; 3 timed runs a point); empty for none.
    pub coc_sweep: Vec<f64>,
    /// Sub-samples a pixel of the multi-layer images (`LayerOptions::subsamples`).
    pub subsamples: u32,
    /// Keep the area-integrated fragments' footprints (`LayerOptions::footprints`).
    pub footprints: bool,
    /// The built-in scenes' references integrate their emissive spheres' light with aimed samples
    /// (`ReferenceOptions::aimed_emitters`; scenes with translucency are refused).
    pub aimed_emitters: bool,
    /// Image size of the built-in scenes (`None`: the scene's own, 160x90 with `quick`).
    pub size: Option<(u32, u32)>,
}

/// The default sweep targets: largest CoC radius present, px.
pub fn default_coc_sweep(quick: bool) -> Vec<f64> {
    if quick { vec![4.0, 16.0] } else { vec![4.0, 8.0, 16.0, 32.0] }
}

/// One method at one setting on one backend: a warm-up, then `runs` timed runs
/// ([`EvaluatedMethod::timed`]). Returns the times and the last run's output.
pub fn timed(
    method: &dyn EvaluatedMethod,
    backend: &mut dyn Backend,
    input: &MethodInput,
    setting: &Setting,
    runs: usize,
) -> Result<(RunTimes, MethodOutput)> {
    method.timed(backend, input, setting, runs)
}

/// Runs the evaluation on `backends` (host-only methods run once, on the first).
pub fn evaluate(options: &EvalOptions, backends: &mut [Box<dyn Backend>]) -> Result<Report> {
    let all = evaluated_methods();
    for m in &options.methods {
        if !all.iter().any(|x| x.name() == m) {
            let names: Vec<_> = all.iter().map(|x| x.name()).collect();
            return Err(Error::invalid(format!("unknown method `{m}`; the methods are: {}", names.join(", "))));
        }
    }
    if backends.is_empty() {
        return Err(Error::invalid("the evaluation needs at least one backend".into()));
    }
    let infos = backends.iter().map(|b| BackendInfo::of(b.as_ref())).collect();
    let mut report = Report::new(options.quick, options.runs, infos);
    for scene_arg in &options.scenes {
        let prepared =
            if is_gltf(scene_arg) { prepare_gltf(scene_arg, options, backends[0].as_mut())? } else { prepare_builtin(scene_arg, options)? };
        let gltf = is_gltf(scene_arg);
        let Prepared { name, width, height, lens, ml, reference: exact, reference_spp, reference_noise_psnr_db } = prepared;
        report.scenes.push(SceneInfo {
            name: name.clone(),
            width,
            height,
            lens: (&lens).into(),
            reference: if gltf { "accumulation" } else { "exact" }.into(),
            reference_spp,
            reference_noise_psnr_db,
            fragments_per_pixel: ml.with_mask.fragments_per_pixel(),
            multi_layer_share: ml.with_mask.multi_layer_share(),
            occlusion_region_share: ml.mask_share(),
            guard_band_px: ml.margin,
        });
        let input = MethodInput::new(ml.layers, lens, ml.margin);
        // Per method, the best image on the first backend and its setting, for the grid.
        let mut best: Vec<(String, f64, String, crate::layers::RgbImage)> = Vec::new();
        for method in all.iter().filter(|m| options.methods.is_empty() || options.methods.iter().any(|n| n == m.name())) {
            let targets = if method.uses_backend() { backends.len() } else { 1 };
            for setting in method.settings(options.quick) {
                for (backend_index, backend) in backends.iter_mut().take(targets).enumerate() {
                    let b = backend.as_mut();
                    let (times, output) = timed(method.as_ref(), b, &input, &setting, options.runs)?;
                    let image = input.crop(&output.image);
                    let error = compare(&image, &exact, Some(&ml.mask))?;
                    if backend_index == 0 {
                        let entry = (method.name().to_string(), error.psnr_db, setting.label.clone(), image.clone());
                        match best.iter_mut().find(|b| b.0 == method.name()) {
                            Some(b) if b.1 >= error.psnr_db => {}
                            Some(b) => *b = entry,
                            None => best.push(entry),
                        }
                    }
                    let record = Record {
                        scene: name.clone(),
                        method: method.name().to_string(),
                        setting: setting.label.clone(),
                        backend: if method.uses_backend() { b.kind().to_string() } else { "host".into() },
                        device: if method.uses_backend() { b.device_name() } else { "host".into() },
                        time_ms: times.median_total(),
                        stages_ms: times.median_stages(),
                        psnr_db: error.psnr_db,
                        ssim: error.ssim,
                        psnr_masked_db: error.psnr_masked_db,
                        ssim_masked: error.ssim_masked,
                        flip: error.flip,
                        flip_masked: error.flip_masked,
                        runs: options.runs,
                        figures: output.figures,
                        list_histogram: output.list_histogram,
                    };
                    if options.progress {
                        eprintln!("{}", record.line());
                    }
                    report.records.push(record);
                }
            }
        }
        let rows = best.into_iter().map(|(name, psnr, setting, image)| (grid_label(&name, &setting, psnr), image)).collect();
        report.grids.push((name.clone(), exact, rows));
    }
    if let Some(first) = options.scenes.iter().find(|s| !is_gltf(s)).filter(|_| !options.coc_sweep.is_empty()) {
        // Half the evaluation's size (the gather's cost grows with the square of the radius, and
        // the sweep's largest radius takes lavapipe tens of seconds a run at full size).
        let (w, h) = if options.quick { (160, 90) } else { (320, 180) };
        let scene = builtin(first)?.with_size(w, h);
        let chosen: Vec<&dyn EvaluatedMethod> = all
            .iter()
            .filter(|m| options.methods.is_empty() || options.methods.iter().any(|n| n == m.name()))
            .map(|m| m.as_ref())
            .collect();
        let sweep_options =
            sweep::SweepOptions { targets: options.coc_sweep.clone(), runs: options.runs.min(3), progress: options.progress };
        report.coc_sweep = sweep::coc_sweep(first, &scene, &chosen, backends, &sweep_options)?;
    }
    Ok(report)
}

/// A grid row's label: the method, its setting (where it has one) and its PSNR, one a line.
pub fn grid_label(method: &str, setting: &str, psnr_db: f64) -> String {
    let psnr = if psnr_db.is_finite() { format!("PSNR {psnr_db:.2} dB") } else { "PSNR inf (identical)".into() };
    if setting == "-" { format!("{method}\n{psnr}") } else { format!("{method}\n{setting}\n{psnr}") }
}

/// A scene ready to be measured: its multi-layer image and its reference.
struct Prepared {
    name: String,
    width: u32,
    height: u32,
    lens: ThinLens,
    ml: SceneLayers,
    reference: RgbImage,
    /// Samples per pixel of the exact reference, or renders of the accumulation buffer.
    reference_spp: u32,
    reference_noise_psnr_db: Option<f64>,
}

fn is_gltf(scene: &str) -> bool {
    let lower = scene.to_ascii_lowercase();
    lower.ends_with(".gltf") || lower.ends_with(".glb")
}

/// A built-in scene: the exact ray-cast layers and the thin-lens reference.
fn prepare_builtin(name: &str, options: &EvalOptions) -> Result<Prepared> {
    let mut scene = builtin(name)?;
    if let Some((w, h)) = options.size {
        scene = scene.with_size(w, h);
    } else if options.quick {
        scene = scene.with_size(160, 90);
    }
    let lens = scene.thin_lens()?;
    let layer_options = LayerOptions { subsamples: options.subsamples, footprints: options.footprints, ..LayerOptions::default() };
    let ml = raycast_layers(&scene.scene, &scene.camera, &lens, &layer_options)?;
    let exact = if options.quick {
        let o = ReferenceOptions { spp: 64, progress: options.progress, aimed_emitters: options.aimed_emitters, ..Default::default() };
        reference(&scene.scene, &scene.camera, &lens, &o)?
    } else {
        let auto = AutoOptions {
            max_spp: 1024,
            region: Some(ml.mask.clone()),
            progress: options.progress,
            aimed_emitters: options.aimed_emitters,
            ..Default::default()
        };
        reference_auto(&scene.scene, &scene.camera, &lens, &auto)?
    };
    Ok(Prepared {
        name: name.to_string(),
        width: scene.camera.width,
        height: scene.camera.height,
        lens,
        ml,
        reference: exact.image,
        reference_spp: exact.spp,
        reference_noise_psnr_db: exact.noise_psnr_db,
    })
}

/// A glTF scene with its own camera and the default lens: depth-peeled layers and the
/// accumulation buffer (64 renders quick, 256 otherwise) as the reference, both on `backend`.
fn prepare_gltf(path: &str, options: &EvalOptions, backend: &mut dyn Backend) -> Result<Prepared> {
    let mesh = load_gltf(std::path::Path::new(path))?;
    let (camera, settings, near) = mesh.default_view(if options.quick { 160 } else { 640 }, None)?;
    let lens = settings.thin_lens(&camera)?;
    let raster = mesh.raster();
    let layer_options = LayerOptions { subsamples: options.subsamples, footprints: options.footprints, ..LayerOptions::default() };
    let samples = if options.quick { 64 } else { 256 };
    let acc_options = AccumulateOptions { samples, progress: options.progress, ..Default::default() };
    let (ml, acc) = DeviceMesh::scoped(backend, &raster, |backend, mesh| {
        let peeled = peel_layers_with(backend, &raster, mesh, &camera, &lens, near, &layer_options)?;
        Ok((peeled.image, accumulate_with(backend, &raster, mesh, &camera, &lens, near, &acc_options)?))
    })?;
    let stem = std::path::Path::new(path).file_stem().and_then(|s| s.to_str()).unwrap_or("scene");
    let name = format!("{stem}-gltf");
    Ok(Prepared {
        name,
        width: camera.width,
        height: camera.height,
        lens,
        ml,
        reference: acc.image,
        reference_spp: samples,
        reference_noise_psnr_db: None,
    })
}
