//! Temporal stability: a focus pull rendered by every method of the frame API through **one context**
//! (its buffers made once; per frame the layers ray cast, uploaded, recorded, submitted, read back)
//! against the reference's sequence (thin-lens ray tracing, the same seed every frame). Per frame the
//! PSNR against the reference's frame; per pair of frames the **temporal PSNR**: the PSNR of the
//! method's frame-to-frame change against the reference's, both on the tone-mapped images
//! ([`crate::io::tonemap`], exposure 1; peak 1). Flicker that the reference has not lowers it.

use crate::backend::Backend;
use crate::error::{Error, Result};
use crate::frame::{METHODS, MethodInfo, MethodOptions};
use crate::io::tonemap::tonemap_image;
use crate::layers::RgbImage;
use crate::methods::one_shot::{Runner, method_input};
use crate::metrics::{psnr, psnr_of_mse};
use crate::scene::guard_band::auto_margin;
use crate::scene::{self, Focus, GuardBand, LayerOptions, ReferenceOptions, raycast_layers};
use dof_shaders::lens::ThinLens;

/// What the temporal evaluation runs.
#[derive(Clone, Debug)]
pub struct TemporalOptions {
    pub scene: String,
    pub width: u32,
    pub height: u32,
    pub frames: u32,
    /// The focus pull's end, as a multiple of the scene's focus distance.
    pub focus_to_ratio: f32,
    /// Reference samples per pixel.
    pub spp: u32,
    /// Registry names; empty: all.
    pub methods: Vec<String>,
}

impl TemporalOptions {
    /// `quick`: 64x36, 6 frames, 64 samples; else 160x90, 12 frames, 256 samples.
    pub fn new(quick: bool) -> Self {
        let (width, height, frames, spp) = if quick { (64, 36, 6, 64) } else { (160, 90, 12, 256) };
        TemporalOptions { scene: "simple".into(), width, height, frames, focus_to_ratio: 0.4, spp, methods: Vec::new() }
    }
}

/// One method's sequence.
#[derive(Clone, Debug)]
pub struct TemporalRow {
    pub method: String,
    /// PSNR (dB) of each frame against the reference's.
    pub psnr: Vec<f64>,
    /// Temporal PSNR (dB) of each frame's change from the previous one (one fewer than frames).
    pub temporal_psnr: Vec<f64>,
    /// Allocations during the frames after the first (the context is made once: 0).
    pub later_allocations: u64,
}

impl TemporalRow {
    pub fn mean_psnr(&self) -> f64 {
        mean(&self.psnr)
    }
    pub fn mean_temporal_psnr(&self) -> f64 {
        mean(&self.temporal_psnr)
    }
    /// The worst frame-to-frame change.
    pub fn min_temporal_psnr(&self) -> f64 {
        self.temporal_psnr.iter().copied().fold(f64::INFINITY, f64::min)
    }
}

fn mean(v: &[f64]) -> f64 {
    // Infinite PSNRs (identical changes) are capped at 100 dB for the mean.
    v.iter().map(|p| p.min(100.0)).sum::<f64>() / v.len().max(1) as f64
}

#[derive(Clone, Debug)]
pub struct TemporalReport {
    pub options: TemporalOptions,
    pub focus: Vec<f32>,
    pub rows: Vec<TemporalRow>,
}

/// PSNR of the change `a1 - a0` against `r1 - r0`, all tone-mapped (peak 1).
pub fn temporal_psnr(a0: &RgbImage, a1: &RgbImage, r0: &RgbImage, r1: &RgbImage) -> Result<f64> {
    let n = r0.data.len();
    if [a0, a1, r1].iter().any(|i| i.data.len() != n) || n == 0 {
        return Err(Error::invalid("temporal PSNR needs four images of one size".into()));
    }
    let [a0, a1, r0, r1] = [a0, a1, r0, r1].map(|i| tonemap_image(i, 1.0));
    let mut sum = 0.0;
    for p in 0..n {
        for c in 0..3 {
            let d = (a1[p][c] - a0[p][c]) as f64 - (r1[p][c] - r0[p][c]) as f64;
            sum += d * d;
        }
    }
    Ok(psnr_of_mse(sum / (3 * n) as f64))
}

/// Runs the focus pull for every chosen method on `backend`.
pub fn temporal(options: &TemporalOptions, backend: &mut dyn Backend, progress: bool) -> Result<TemporalReport> {
    if options.frames < 2 {
        return Err(Error::invalid(format!("a temporal evaluation needs at least 2 frames, got {}", options.frames)));
    }
    let builtin = scene::builtin(&options.scene)?;
    let mut camera = builtin.camera;
    camera.width = options.width;
    camera.height = options.height;
    let start = builtin.lens.thin_lens(&camera)?;
    let (f0, f1) = (start.focus_distance, start.focus_distance * options.focus_to_ratio);
    let n = options.frames;
    let focus: Vec<f32> = (0..n).map(|i| f0 + (f1 - f0) * i as f32 / (n - 1) as f32).collect();
    let lenses: Vec<ThinLens> = focus
        .iter()
        .map(|&d| {
            let mut s = builtin.lens;
            s.focus = Focus::Distance(d);
            s.thin_lens(&camera)
        })
        .collect::<Result<_>>()?;
    let mut margin = 0;
    for lens in &lenses {
        margin = margin.max(auto_margin(&builtin.scene, &camera, lens, 1e-3 * lens.focus_distance)?);
    }
    let layer_options = LayerOptions { guard_band: GuardBand::Pixels(margin), ..Default::default() };
    let mut layers = Vec::new();
    let mut references = Vec::new();
    for lens in &lenses {
        layers.push(raycast_layers(&builtin.scene, &camera, lens, &layer_options)?);
        references
            .push(scene::reference(&builtin.scene, &camera, lens, &ReferenceOptions { spp: options.spp, ..Default::default() })?.image);
    }
    let methods: Vec<&MethodInfo> =
        METHODS.iter().filter(|m| options.methods.is_empty() || options.methods.iter().any(|n| n == m.name)).collect();
    if methods.is_empty() {
        return Err(Error::invalid(format!("no method of the frame API among {:?}", options.methods)));
    }
    let mut rows = Vec::new();
    for method in methods {
        let mut runner: Option<Runner> = None;
        let mut images = Vec::new();
        let ran = (|| -> Result<()> {
            for (layered, lens) in layers.iter().zip(&lenses) {
                let input = method_input(method, &layered.layers);
                if runner.is_none() {
                    runner = Some(Runner::new(backend, method, &MethodOptions::default(), &input)?);
                }
                let r = runner.as_mut().ok_or_else(|| Error::invalid("no context".into()))?;
                images.push(layered.crop(&r.frame(backend, &input, lens)?.image));
            }
            Ok(())
        })();
        let later_allocations = runner.as_ref().map_or(0, |r| r.later_allocations);
        if let Some(r) = runner {
            r.destroy(backend);
        }
        ran?;
        let psnr: Vec<f64> = images.iter().zip(&references).map(|(a, r)| psnr(a, r)).collect::<Result<_>>()?;
        let temporal_psnr = (1..images.len())
            .map(|i| temporal_psnr(&images[i - 1], &images[i], &references[i - 1], &references[i]))
            .collect::<Result<Vec<_>>>()?;
        let row = TemporalRow { method: method.name.to_string(), psnr, temporal_psnr, later_allocations };
        if progress {
            eprintln!(
                "temporal: {:<12} mean PSNR {:6.2} dB, mean temporal PSNR {:6.2} dB (worst {:6.2} dB)",
                row.method,
                row.mean_psnr(),
                row.mean_temporal_psnr(),
                row.min_temporal_psnr()
            );
        }
        rows.push(row);
    }
    Ok(TemporalReport { options: options.clone(), focus, rows })
}

impl TemporalReport {
    pub fn to_json(&self) -> String {
        let finite = |v: f64| if v.is_finite() { serde_json::json!(v) } else { serde_json::json!(null) };
        let rows: Vec<_> = self
            .rows
            .iter()
            .map(|r| {
                serde_json::json!({
                    "method": r.method,
                    "psnr_db": r.psnr.iter().map(|&v| finite(v)).collect::<Vec<_>>(),
                    "temporal_psnr_db": r.temporal_psnr.iter().map(|&v| finite(v)).collect::<Vec<_>>(),
                    "mean_psnr_db": finite(r.mean_psnr()),
                    "mean_temporal_psnr_db": finite(r.mean_temporal_psnr()),
                    "min_temporal_psnr_db": finite(r.min_temporal_psnr()),
                    "allocations_after_first_frame": r.later_allocations,
                })
            })
            .collect();
        let o = &self.options;
        serde_json::to_string_pretty(&serde_json::json!({
            "scene": o.scene, "width": o.width, "height": o.height, "frames": o.frames,
            "reference_spp": o.spp, "focus": self.focus, "methods": rows,
        }))
        .unwrap_or_default()
    }

    pub fn to_markdown(&self) -> String {
        let o = &self.options;
        let mut md = format!(
            "# Temporal stability: a focus pull\n\n`{}` at {}x{}, {} frames, focus {:.3} to {:.3}; reference {} samples per pixel, \
             the same seed every frame. PSNR per frame against the reference's; temporal PSNR of each frame-to-frame change \
             against the reference's (tone-mapped, peak 1). Every method through one context made once.\n\n\
             | method | mean PSNR (dB) | mean temporal PSNR (dB) | worst temporal PSNR (dB) | allocations after frame 0 |\n|---|---|---|---|---|\n",
            o.scene,
            o.width,
            o.height,
            o.frames,
            self.focus.first().copied().unwrap_or(0.0),
            self.focus.last().copied().unwrap_or(0.0),
            o.spp
        );
        for r in &self.rows {
            md += &format!(
                "| {} | {:.2} | {:.2} | {:.2} | {} |\n",
                r.method,
                r.mean_psnr(),
                r.mean_temporal_psnr(),
                r.min_temporal_psnr(),
                r.later_allocations
            );
        }
        md
    }

    /// Two figures: PSNR per frame, temporal PSNR per change.
    pub fn figures(&self) -> [(String, super::plot::Figure); 2] {
        use super::plot::{Axis, Figure, Mark, Series, Shape, palette};
        let figure = |title: &str, y: &str, pick: fn(&TemporalRow) -> &Vec<f64>, first: f64| Figure {
            title: title.into(),
            x_label: "frame".into(),
            y_label: y.into(),
            x_axis: Axis::Linear,
            y_axis: Axis::Linear,
            categories: Vec::new(),
            series: self
                .rows
                .iter()
                .enumerate()
                .map(|(i, r)| Series {
                    name: r.method.clone(),
                    colour: palette(i),
                    mark: Mark::Line(Shape::Circle),
                    points: pick(r).iter().enumerate().map(|(k, &v)| (first + k as f64, v.min(100.0))).collect(),
                })
                .collect(),
        };
        [
            ("temporal-psnr".into(), figure("PSNR per frame of a focus pull", "PSNR (dB)", |r| &r.psnr, 0.0)),
            (
                "temporal-change".into(),
                figure("Temporal PSNR: each frame's change against the reference's", "temporal PSNR (dB)", |r| &r.temporal_psnr, 1.0),
            ),
        ]
    }
}
