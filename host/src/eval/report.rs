//! The evaluation's outputs: `report.json` (schema below) and `report.md` (tables in the shape of
//! seed 000 Table 1).
//!
//! `report.json` schema (one object):
//! - `version`: the `dof` version; `quick`: whether `--quick` was used;
//! - `scenes[]`: `name`, `width`, `height`, `reference_spp`, `reference_noise_psnr_db` (estimated
//!   noise of the reference, dB), `fragments_per_pixel`, `multi_layer_share`,
//!   `occlusion_region_share` (share of pixels in the partial-occlusion region, the disocclusion
//!   buffer);
//! - `records[]`, one per scene × method × setting × backend: `scene`, `method`, `setting`,
//!   `backend` (`cpu`, `vulkan`, or `host` for methods without kernels), `device`, `time_ms` (median
//!   over `runs` of the summed stage times), `stages_ms` (median per stage label), `psnr_db`, `ssim`,
//!   `psnr_masked_db`, `ssim_masked` (inside the partial-occlusion region; null when it is empty),
//!   `runs`. PSNR is `null` where it is infinite (identical images).

use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt::Write as _;

#[derive(Clone, Debug, Serialize)]
pub struct SceneInfo {
    pub name: String,
    pub width: u32,
    pub height: u32,
    pub reference_spp: u32,
    pub reference_noise_psnr_db: Option<f64>,
    pub fragments_per_pixel: f64,
    pub multi_layer_share: f64,
    pub occlusion_region_share: f64,
}

#[derive(Clone, Debug, Serialize)]
pub struct Record {
    pub scene: String,
    pub method: String,
    pub setting: String,
    pub backend: String,
    pub device: String,
    pub time_ms: f64,
    pub stages_ms: BTreeMap<String, f64>,
    pub psnr_db: f64,
    pub ssim: f64,
    pub psnr_masked_db: Option<f64>,
    pub ssim_masked: Option<f64>,
    pub runs: usize,
}

fn db(v: Option<f64>) -> String {
    match v {
        Some(v) if v.is_infinite() => "inf".into(),
        Some(v) => format!("{v:.2}"),
        None => "-".into(),
    }
}

impl Record {
    /// One line for progress output.
    pub fn line(&self) -> String {
        format!(
            "{} / {} {} on {}: {:.3} ms, {} dB ({} dB in the occlusion region)",
            self.scene, self.method, self.setting, self.backend, self.time_ms, db(Some(self.psnr_db)), db(self.psnr_masked_db)
        )
    }
}

#[derive(Clone, Debug, Serialize)]
pub struct Report {
    pub version: String,
    pub quick: bool,
    pub scenes: Vec<SceneInfo>,
    pub records: Vec<Record>,
}

impl Report {
    pub fn new(quick: bool) -> Self {
        Report { version: env!("CARGO_PKG_VERSION").to_string(), quick, scenes: Vec::new(), records: Vec::new() }
    }

    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// Markdown: per scene, a table of method, setting, backend, per-stage and total time, and error.
    pub fn to_markdown(&self) -> String {
        let mut md = String::from("# Depth-of-field evaluation\n\n");
        let _ = writeln!(md, "dof {}{}; error against the exact reference on the documented tone map; times are medians of {} runs after a warm-up.\n",
            self.version, if self.quick { " (quick)" } else { "" }, self.records.first().map_or(0, |r| r.runs));
        for s in &self.scenes {
            let _ = writeln!(md, "## {} ({}x{})\n", s.name, s.width, s.height);
            let _ = writeln!(md, "Reference: {} spp (noise {} dB). Multi-layer image: {:.3} fragments/px, {:.1}% of pixels multi-layer; partial-occlusion region {:.1}% of pixels.\n",
                s.reference_spp, db(s.reference_noise_psnr_db), s.fragments_per_pixel, 100.0 * s.multi_layer_share, 100.0 * s.occlusion_region_share);
            md.push_str("| method | setting | backend | stages (ms) | total (ms) | PSNR (dB) | SSIM | PSNR region (dB) | SSIM region |\n|---|---|---|---|---|---|---|---|---|\n");
            for r in self.records.iter().filter(|r| r.scene == s.name) {
                let stages: Vec<String> = r.stages_ms.iter().map(|(k, v)| format!("{k} {v:.3}")).collect();
                let _ = writeln!(md, "| {} | {} | {} | {} | {:.3} | {} | {:.4} | {} | {} |",
                    r.method, r.setting, r.backend, if stages.is_empty() { "-".into() } else { stages.join(", ") }, r.time_ms,
                    db(Some(r.psnr_db)), r.ssim, db(r.psnr_masked_db), r.ssim_masked.map_or("-".into(), |v| format!("{v:.4}")));
            }
            md.push('\n');
        }
        md
    }
}
