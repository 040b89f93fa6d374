//! The evaluation's outputs: `report.json` (schema below) and `report.md` (tables in the shape of
//! Franke et al. 2018, Table 1).
//!
//! `report.json` schema (one object):
//! - `version`: the `dof` version; `shaders_hash`: SHA-256 of the kernel sources; `quick`: whether
//!   `--quick` was used; `runs`: timed runs per point after one warm-up;
//! - `backends[]`: `kind`, `device`, `driver` (name and version, and the Vulkan API version);
//! - `scenes[]`: `name`, `width`, `height`, `lens` (`focal_length`, `aperture_radius`,
//!   `focus_distance` in scene units, `pixels_per_unit` on the sensor), `reference` (`exact`:
//!   thin-lens ray tracing of a built-in scene, `accumulation`: the accumulation buffer of a glTF
//!   scene), `reference_spp` (samples per pixel, or renders of the accumulation buffer),
//!   `reference_noise_psnr_db` (estimated noise of the reference, dB), `fragments_per_pixel`, `multi_layer_share`,
//!   `occlusion_region_share` (share of pixels in the partial-occlusion region, the disocclusion
//!   buffer), `guard_band_px` (the margin rendered beyond the frame on every side; every method
//!   runs on the larger image, `(w + 2m)(h + 2m)` pixels);
//! - `records[]`, one per scene × method × setting × backend: `scene`, `method`, `setting`,
//!   `backend` (`cpu`, `vulkan`, or `host` for methods without kernels), `device`, `time_ms` (median
//!   over `runs` of the summed stage times), `stages_ms` (median per stage label), `psnr_db`, `ssim`,
//!   `psnr_masked_db`, `ssim_masked` (inside the partial-occlusion region; null when it is empty),
//!   `flip`, `flip_masked` (mean LDR-FLIP error, lower is better; see [`crate::metrics`]),
//!   `runs`, `figures` (method-specific numbers by name: list lengths, fragments, buffer bytes; see
//!   [`Record::figures`]), `list_histogram` (tiles per list-length bucket as `[upper bound, tiles]`,
//!   buckets by powers of two; only for methods with tile lists). PSNR is `null` where it is
//!   infinite (identical images);
//! - `coc_sweep[]` (Franke et al. 2018, Fig. 13), time against the largest CoC on the sweep scene (the first
//!   scene, at 320x180, or 160x90 with `quick`), the aperture scaled so the largest CoC radius present takes each value: `scene`,
//!   `method`, `setting`, `backend`, `device`, `max_coc_px` (largest CoC radius present, px),
//!   `time_ms`, `stages_ms`, `runs`, `figures`;
//! - `scaling` (only with `dof eval --scaling`): the scaling sweep, as `scaling.json` holds it (see
//!   [`super::scaling::ScalingReport`]): `scene`, `runs`, `budget_s`, `coc_size`, `backends`, and
//!   `points[]`, each `axis` (`resolution` or `max_coc`), `method`, `setting`, `backend`, `device`,
//!   `width`, `height`, `pixels`, `input_pixels` (with the guard band), `max_coc_px`, `time_ms`,
//!   `stages_ms`, `wall_ms`, `runs` (0: the warm-up alone, over the budget), `peak_device_bytes`,
//!   `peak_rss_bytes`, `skipped` (why, where the point was not run), `figures`.

pub use super::backend_info::BackendInfo;
pub use super::sweep::SweepRecord;
use crate::layers::RgbImage;
use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// The thin lens a scene was evaluated with.
#[derive(Clone, Debug, Serialize)]
pub struct LensInfo {
    pub focal_length: f32,
    pub aperture_radius: f32,
    pub focus_distance: f32,
    pub pixels_per_unit: f32,
}

impl From<&dof_shaders::lens::ThinLens> for LensInfo {
    fn from(l: &dof_shaders::lens::ThinLens) -> Self {
        LensInfo {
            focal_length: l.focal_length,
            aperture_radius: l.aperture_radius,
            focus_distance: l.focus_distance,
            pixels_per_unit: l.pixels_per_unit,
        }
    }
}

#[derive(Clone, Debug, Serialize)]
pub struct SceneInfo {
    pub name: String,
    pub width: u32,
    pub height: u32,
    pub lens: LensInfo,
    pub reference: String,
    pub reference_spp: u32,
    pub reference_noise_psnr_db: Option<f64>,
    pub fragments_per_pixel: f64,
    pub multi_layer_share: f64,
    pub occlusion_region_share: f64,
    pub guard_band_px: u32,
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
    /// Mean FLIP error (lower is better), full frame and in the region.
    pub flip: f64,
    pub flip_masked: Option<f64>,
    pub runs: usize,
    /// Method-specific figures: its context's report figures (`mean_list_length`,
    /// `max_list_length`, `copy_tiles`, ... for the splatting methods, `radius_px` for the gathers),
    /// `buffer_bytes` (the context and its frame's buffers), and `tile_px` and `merge_steps` for
    /// the splatting methods.
    pub figures: BTreeMap<String, f64>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub list_histogram: Vec<(u32, u32)>,
}

/// The column of Franke et al. 2018, Table 1, that a stage of the registry method `method`
/// belongs to, as its entry says ([`crate::frame::MethodInfo::column`]): `merge`, `splat`, `sort` or
/// `apply`; `other` for a label no stage of the method claims (the registry's tests hold every
/// recorded label to a stage).
pub fn table_column(method: &str, label: &str) -> &'static str {
    crate::frame::registry::method(method).ok().and_then(|m| m.column(label)).map_or("other", |c| c.name())
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
            self.scene,
            self.method,
            self.setting,
            self.backend,
            self.time_ms,
            db(Some(self.psnr_db)),
            db(self.psnr_masked_db)
        )
    }
}

#[derive(Clone, Debug, Serialize)]
pub struct Report {
    pub version: String,
    /// SHA-256 of the kernel sources the SPIR-V modules were built from.
    pub shaders_hash: String,
    pub quick: bool,
    pub runs: usize,
    pub backends: Vec<BackendInfo>,
    pub scenes: Vec<SceneInfo>,
    pub records: Vec<Record>,
    pub coc_sweep: Vec<SweepRecord>,
    /// The scaling sweep (`dof eval --scaling`; schema in [`super::scaling`]), absent without it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub scaling: Option<super::scaling::ScalingReport>,
    /// Per scene: the reference and each method's best image on the first backend, labelled with
    /// the method, setting and PSNR ([`super::grid_label`]; for the image grids, not in the JSON).
    #[serde(skip)]
    pub grids: Vec<(String, RgbImage, Vec<(String, RgbImage)>)>,
}

impl Report {
    pub fn new(quick: bool, runs: usize, backends: Vec<BackendInfo>) -> Self {
        Report {
            version: env!("CARGO_PKG_VERSION").to_string(),
            shaders_hash: crate::shaders::SOURCE_HASH.to_string(),
            quick,
            runs,
            backends,
            scenes: Vec::new(),
            records: Vec::new(),
            coc_sweep: Vec::new(),
            scaling: None,
            grids: Vec::new(),
        }
    }

    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// Markdown: per scene, a table of method, setting, backend, total time and error, then the
    /// per-stage times in the shape of Franke et al. 2018, Table 1 (every stage label is in `report.json`).
    pub fn to_markdown(&self) -> String {
        let mut md = String::from("# Depth-of-field evaluation\n\n");
        let _ = writeln!(
            md,
            "dof {}{}; error against each scene's reference on the documented tone map; times are medians of {} runs after a warm-up.\n",
            self.version,
            if self.quick { " (quick)" } else { "" },
            self.runs
        );
        for b in &self.backends {
            let _ = writeln!(md, "- {}: {} ({})", b.kind, b.device, b.driver);
        }
        md.push('\n');
        for s in &self.scenes {
            let _ = writeln!(md, "## {} ({}x{})\n", s.name, s.width, s.height);
            let unit = if s.reference == "accumulation" { "renders of the accumulation buffer" } else { "spp, exact" };
            let band =
                (s.width + 2 * s.guard_band_px) as f64 * (s.height + 2 * s.guard_band_px) as f64 / (s.width as f64 * s.height as f64);
            let _ = writeln!(
                md,
                "Reference: {} {unit} (noise {} dB). Multi-layer image: {:.3} fragments/px, {:.1}% of pixels multi-layer; partial-occlusion region {:.1}% of pixels; guard band {} px ({:.2}x the frame's pixels).\n",
                s.reference_spp,
                db(s.reference_noise_psnr_db),
                s.fragments_per_pixel,
                100.0 * s.multi_layer_share,
                100.0 * s.occlusion_region_share,
                s.guard_band_px,
                band
            );
            md.push_str("| method | setting | backend | total (ms) | PSNR (dB) | SSIM | FLIP | PSNR region (dB) | SSIM region | FLIP region |\n|---|---|---|---|---|---|---|---|---|---|\n");
            for r in self.records.iter().filter(|r| r.scene == s.name) {
                let opt = |v: Option<f64>| v.map_or("-".into(), |v| format!("{v:.4}"));
                let _ = writeln!(
                    md,
                    "| {} | {} | {} | {:.3} | {} | {:.4} | {:.4} | {} | {} | {} |",
                    r.method,
                    r.setting,
                    r.backend,
                    r.time_ms,
                    db(Some(r.psnr_db)),
                    r.ssim,
                    r.flip,
                    db(r.psnr_masked_db),
                    opt(r.ssim_masked),
                    opt(r.flip_masked)
                );
            }
            md.push('\n');
            md.push_str(&self.table1(&s.name));
        }
        if let Some(first) = self.coc_sweep.first() {
            let _ = writeln!(md, "## Time against the largest CoC ({}; Franke et al. 2018, Fig. 13)\n", first.scene);
            md.push_str("The aperture scaled so the largest CoC radius present takes each value; time only.\n\n| method | setting | backend | largest CoC radius (px) | total (ms) | mean list |\n|---|---|---|---|---|---|\n");
            for r in &self.coc_sweep {
                let list = r.figures.get("mean_list_length").map_or("-".into(), |v| format!("{v:.0}"));
                let _ =
                    writeln!(md, "| {} | {} | {} | {:.1} | {:.3} | {} |", r.method, r.setting, r.backend, r.max_coc_px, r.time_ms, list);
            }
            md.push('\n');
        }
        if let Some(scaling) = &self.scaling {
            md.push_str(&scaling.to_markdown());
        }
        md
    }

    /// Franke et al. 2018, Table 1, for one scene: per backend and method, the time of each column, the mean list
    /// length, and the error full-frame and in the partial-occlusion region.
    fn table1(&self, scene: &str) -> String {
        let mut md = String::from(
            "Per stage, in the shape of Table 1 of Franke et al. 2018 (ms):\n\n| backend | method | setting | merge | splat | sort | apply | overall | mean list | PSNR (dB) | PSNR region (dB) |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
        );
        for r in self.records.iter().filter(|r| r.scene == scene && r.backend != "host") {
            let mut cols = BTreeMap::new();
            for (label, ms) in &r.stages_ms {
                *cols.entry(table_column(&r.method, label)).or_insert(0.0) += ms;
            }
            let col = |c: &str| cols.get(c).map_or("-".into(), |v: &f64| format!("{v:.2}"));
            let list = r.figures.get("mean_list_length").map_or("-".into(), |v| format!("{v:.0}"));
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {} | {} | {} | {:.2} | {} | {} | {} |",
                r.backend,
                r.method,
                r.setting,
                col("merge"),
                col("splat"),
                col("sort"),
                col("apply"),
                r.time_ms,
                list,
                db(Some(r.psnr_db)),
                db(r.psnr_masked_db)
            );
        }
        md.push('\n');
        md
    }
}
