//! Cost ratios: multi-layer tiled splatting (Franke et al. 2018) at its renderer setting (merged
//! 4x4, 16 px tiles) against the engine-grade gather at what engines ship (5 rings), per scene and
//! backend in one run, with each one's error against the exact reference beside its time. The
//! paper (Franke et al. 2018) reports multi-layer 2.4-2.6x slower than its gather on a GTX 1070; the goal here is 1.8x.
//!
//! Both methods run at their sweep setting from [`super::methods`], timed as `dof eval` times them
//! (frames back to back through one context after a warm-up, the median of the timed frames'
//! summed kernel times; [`super::methods::EvaluatedMethod::timed`]).

use super::methods::{EvaluatedMethod, MethodInput, Registered};
use super::timed;
use crate::backend::Backend;
use crate::error::{Error, Result};
use crate::metrics::compare;
use crate::scene::{LayerOptions, ReferenceOptions, builtin, raycast_layers, reference};
use std::collections::BTreeMap;

/// The goal for multi-layer ÷ ring-gather.
pub const GOAL: f64 = 1.8;

pub struct RatioOptions {
    pub scenes: Vec<String>,
    pub width: u32,
    pub height: u32,
    /// Samples per pixel of the exact reference each scene is measured against.
    pub spp: u32,
    /// Timed runs per method and backend after the warm-up.
    pub runs: usize,
    pub progress: bool,
}

/// One method's time and error on one scene and backend.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Timed {
    pub setting: String,
    pub time_ms: f64,
    pub stages_ms: BTreeMap<String, f64>,
    pub psnr_db: f64,
    /// In the partial-occlusion region (where the layers differ from the front).
    pub psnr_masked_db: Option<f64>,
}

#[derive(Clone, Debug, serde::Serialize)]
pub struct RatioRow {
    pub scene: String,
    pub backend: String,
    pub device: String,
    pub multilayer: Timed,
    pub ring_gather: Timed,
    /// Multi-layer time over ring-gather time.
    pub ratio: f64,
}

/// Runs both methods on every scene and backend.
pub fn ratios(options: &RatioOptions, backends: &mut [Box<dyn Backend>]) -> Result<Vec<RatioRow>> {
    if backends.is_empty() || options.scenes.is_empty() || options.runs == 0 || options.spp == 0 {
        return Err(Error::invalid("cost ratios need a backend, a scene, a timed run and a reference sample".into()));
    }
    let mut rows = Vec::new();
    for name in &options.scenes {
        let scene = builtin(name)?.with_size(options.width, options.height);
        let lens = scene.thin_lens()?;
        let ml = raycast_layers(&scene.scene, &scene.camera, &lens, &LayerOptions::default())?;
        let exact = reference(
            &scene.scene,
            &scene.camera,
            &lens,
            &ReferenceOptions { spp: options.spp, progress: options.progress, ..Default::default() },
        )?;
        let input = MethodInput::new(ml.layers.clone(), lens, ml.margin);
        for b in backends.iter_mut() {
            let b = b.as_mut();
            // One method at its sweep setting: time and error.
            let mut measure = |method: &dyn EvaluatedMethod| -> Result<Timed> {
                let setting = method.sweep_setting().ok_or_else(|| Error::invalid(format!("{} has no sweep setting", method.name())))?;
                let (times, output) = timed(method, b, &input, &setting, options.runs)?;
                let error = compare(&input.crop(&output.image), &exact.image, Some(&ml.mask))?;
                let t = Timed {
                    setting: setting.label.clone(),
                    time_ms: times.median_total(),
                    stages_ms: times.median_stages(),
                    psnr_db: error.psnr_db,
                    psnr_masked_db: error.psnr_masked_db,
                };
                if options.progress {
                    eprintln!(
                        "{name} {} {} ({}): {:.1} ms, {:.2} dB ({:.2} dB in the region)",
                        b.kind(),
                        method.name(),
                        t.setting,
                        t.time_ms,
                        t.psnr_db,
                        t.psnr_masked_db.unwrap_or(f64::NAN)
                    );
                }
                Ok(t)
            };
            let multilayer = measure(&Registered::named("multilayer")?)?;
            let ring_gather = measure(&Registered::named("ring-gather")?)?;
            let ratio = multilayer.time_ms / ring_gather.time_ms;
            rows.push(RatioRow {
                scene: name.clone(),
                backend: b.kind().to_string(),
                device: b.device_name(),
                multilayer,
                ring_gather,
                ratio,
            });
        }
    }
    Ok(rows)
}

/// The rows as a markdown table, then per row above the goal the stages that cost most.
pub fn to_markdown(rows: &[RatioRow], width: u32, height: u32) -> String {
    let mut md = format!(
        "Multi-layer tiled splatting (merged 4x4, 16 px tiles) ÷ the ring gather (5 rings) at {width}x{height}; \
         PSNR against the exact reference, full frame / in the partial-occlusion region. Goal: at most {GOAL}x.\n\n\
         | scene | backend | multilayer (ms) | ring-gather (ms) | ratio | multilayer PSNR (dB) | ring-gather PSNR (dB) |\n\
         |---|---|---|---|---|---|---|\n"
    );
    let psnr = |t: &Timed| format!("{:.2} / {}", t.psnr_db, t.psnr_masked_db.map_or("-".into(), |m| format!("{m:.2}")));
    for r in rows {
        md.push_str(&format!(
            "| {} | {} | {:.1} | {:.1} | {:.2}{} | {} | {} |\n",
            r.scene,
            r.backend,
            r.multilayer.time_ms,
            r.ring_gather.time_ms,
            r.ratio,
            if r.ratio > GOAL { " (above goal)" } else { "" },
            psnr(&r.multilayer),
            psnr(&r.ring_gather)
        ));
    }
    let above: Vec<&RatioRow> = rows.iter().filter(|r| r.ratio > GOAL).collect();
    if !above.is_empty() {
        md.push_str(
            "\nWhere the multi-layer frame's time goes, in the rows above the goal (three costliest stages, share of the frame):\n\n",
        );
        for r in above {
            let mut stages: Vec<(&String, &f64)> = r.multilayer.stages_ms.iter().collect();
            stages.sort_by(|a, b| b.1.total_cmp(a.1));
            let total = r.multilayer.time_ms.max(1e-9);
            let top: Vec<String> = stages.iter().take(3).map(|(k, v)| format!("{k} {:.0}%", 100.0 * **v / total)).collect();
            md.push_str(&format!("- {} on {}: {}\n", r.scene, r.backend, top.join(", ")));
        }
    }
    md
}
