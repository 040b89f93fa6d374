//! The max-CoC sweep (Franke et al. 2018, Fig. 13): run time against the largest blur in the frame. The scene
//! and focus stay fixed; the aperture is scaled so the largest CoC radius present takes each target
//! value, and the multi-layer image is cast again for that lens (its umbra thinning and disocclusion
//! buffer depend on the aperture). Time only: the references are for the scene's own aperture.

use super::methods::{EvaluatedMethod, MethodInput};
use super::timed;
use crate::backend::Backend;
use crate::error::{Error, Result};
use crate::layers::LayeredImage;
use crate::scene::{BuiltinScene, LayerOptions, raycast_layers};
use dof_shaders::lens::ThinLens;
use serde::Serialize;
use std::collections::BTreeMap;

/// One point of the max-CoC sweep (Franke et al. 2018, Fig. 13): time only; the aperture differs from the
/// scene's, so there is no reference to measure error against.
#[derive(Clone, Debug, Serialize)]
pub struct SweepRecord {
    pub scene: String,
    pub method: String,
    pub setting: String,
    pub backend: String,
    pub device: String,
    pub max_coc_px: f64,
    pub time_ms: f64,
    pub stages_ms: BTreeMap<String, f64>,
    pub runs: usize,
    pub figures: BTreeMap<String, f64>,
}

pub struct SweepOptions {
    /// Largest CoC radii present (px) to time at, each `> 0`.
    pub targets: Vec<f64>,
    /// Timed runs per point after a warm-up.
    pub runs: usize,
    pub progress: bool,
}

/// The largest CoC radius (px) of any fragment of `layers` under `lens` (the sky counts at the
/// far-field limit).
pub fn max_coc_radius(layers: &LayeredImage, lens: &ThinLens) -> f64 {
    let mut max = 0.0f32;
    for y in 0..layers.height {
        for x in 0..layers.width {
            for f in layers.pixel(x, y) {
                max = max.max(lens.coc_radius_px(f.depth));
            }
        }
    }
    max as f64
}

/// `lens` with its aperture scaled so that the largest CoC radius of `layers` becomes `target` px.
/// CoC is proportional to the aperture, so one scale does it.
pub fn lens_for_max_coc(layers: &LayeredImage, lens: &ThinLens, target: f64) -> Result<ThinLens> {
    let now = max_coc_radius(layers, lens);
    if !(target > 0.0 && target.is_finite()) {
        return Err(Error::invalid(format!("a max-CoC sweep target must be a positive number of pixels, got {target}")));
    }
    if !(now > 0.0) {
        return Err(Error::invalid("the sweep scene has no blur to scale (pinhole lens or everything in focus)".into()));
    }
    Ok(ThinLens { aperture_radius: (lens.aperture_radius as f64 * target / now) as f32, ..*lens })
}

/// The input at one sweep target: `base` scaled so the largest CoC radius of `base_layers` (cast
/// with `base`) becomes `target`, the multi-layer image cast again for that lens, and the largest
/// CoC radius (px) then present.
pub fn input_at_max_coc(scene: &BuiltinScene, base: &ThinLens, base_layers: &LayeredImage, target: f64) -> Result<(MethodInput, f64)> {
    let lens = lens_for_max_coc(base_layers, base, target)?;
    let ml = raycast_layers(&scene.scene, &scene.camera, &lens, &LayerOptions::default())?;
    let max_coc_px = max_coc_radius(&ml.layers, &lens);
    Ok((MethodInput::new(ml.layers, lens, ml.margin), max_coc_px))
}

/// Times every method that has a sweep setting at every target, on every backend it runs on.
pub fn coc_sweep(
    name: &str,
    scene: &BuiltinScene,
    methods: &[&dyn EvaluatedMethod],
    backends: &mut [Box<dyn Backend>],
    options: &SweepOptions,
) -> Result<Vec<SweepRecord>> {
    let base = scene.thin_lens()?;
    let base_layers = raycast_layers(&scene.scene, &scene.camera, &base, &LayerOptions::default())?;
    let mut records = Vec::new();
    for &target in &options.targets {
        let (input, max_coc_px) = input_at_max_coc(scene, &base, &base_layers.layers, target)?;
        for method in methods.iter().filter(|m| m.uses_backend()) {
            let Some(setting) = method.sweep_setting() else { continue };
            for backend in backends.iter_mut() {
                let b = backend.as_mut();
                let (times, output) = timed(*method, b, &input, &setting, options.runs)?;
                let record = SweepRecord {
                    scene: name.to_string(),
                    method: method.name().to_string(),
                    setting: setting.label.clone(),
                    backend: b.kind().to_string(),
                    device: b.device_name(),
                    max_coc_px,
                    time_ms: times.median_total(),
                    stages_ms: times.median_stages(),
                    runs: options.runs,
                    figures: output.figures,
                };
                if options.progress {
                    eprintln!(
                        "sweep {name}: {} {} on {} at max CoC {:.1} px: {:.3} ms",
                        record.method, record.setting, record.backend, max_coc_px, record.time_ms
                    );
                }
                records.push(record);
            }
        }
    }
    Ok(records)
}
