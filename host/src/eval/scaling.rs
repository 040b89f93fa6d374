//! Scaling with resolution and blur: the run time and peak memory of every method that runs kernels,
//! on every backend, against the image size (the blur scaled with the image, as a built-in scene's
//! lens does at any size) and against the largest CoC radius at a fixed size (the aperture scaled as
//! in the max-CoC sweep of [`super::sweep`]). Methods come from [`super::methods::evaluated_methods`], each at
//! its sweep setting or else its first setting; host-only methods take no device time and are left
//! out.
//!
//! Each point: one warm-up run, then `runs` timed runs; the time is the median of the summed stage
//! times (GPU timestamps on Vulkan, wall time per dispatch on the CPU backend), as in the
//! evaluation. Memory: the backend's peak device bytes over the point (its peak is reset first, see
//! [`Backend::reset_peak_device_bytes`]), and for information the process's peak resident memory
//! (Linux `VmHWM`, reset through `/proc/self/clear_refs`; it includes the inputs and, on the CPU
//! backend, the buffers themselves).
//!
//! The budget: once a point of a series (one method on one backend along one axis) takes longer
//! than `budget_s` a run, the larger points of that series are not run, and are reported as skipped
//! with the reason; so is a point whose time, extrapolated from the smaller points of its series, is
//! over [`PREDICTED_BUDGETS`] budgets. A warm-up over the budget is the point's only run. A run that
//! fails skips the rest of its series the same way.

use super::backend_info::BackendInfo;
use super::methods::{EvaluatedMethod, MethodInput, Setting, evaluated_methods};
use super::plot::{Axis, Figure, Mark, Series, Shape, palette};
use super::sweep::{input_at_max_coc, max_coc_radius};
use crate::backend::Backend;
use crate::error::{Error, Result};
use crate::scene::{LayerOptions, builtin, raycast_layers};
use crate::timing::{RunTimes, median};
use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Image sizes of the resolution series by default.
pub const DEFAULT_SIZES: [(u32, u32); 3] = [(640, 360), (1280, 720), (1920, 1080)];
/// Largest CoC radii (px) of the blur series by default.
pub const DEFAULT_COCS: [f64; 6] = [4.0, 8.0, 16.0, 32.0, 64.0, 96.0];
/// Seconds a run may take before the larger points of its series are skipped, by default.
pub const DEFAULT_BUDGET_S: f64 = 20.0;
/// A point whose run time, extrapolated from the smaller points of its series, exceeds this many
/// budgets is not run: one run far over the budget would cost more than the rest of the sweep.
pub const PREDICTED_BUDGETS: f64 = 3.0;
/// Largest side the sweep accepts (a 4K frame is 3840 wide).
const MAX_SIDE: u32 = 8192;

pub struct ScalingOptions {
    /// A built-in scene.
    pub scene: String,
    /// Frame sizes of the resolution series (run smallest first).
    pub sizes: Vec<(u32, u32)>,
    /// Largest CoC radii (px) of the blur series, at `coc_size` (run smallest first).
    pub cocs: Vec<f64>,
    pub coc_size: (u32, u32),
    /// Method names; empty for every method that runs kernels.
    pub methods: Vec<String>,
    /// Timed runs per point after the warm-up.
    pub runs: usize,
    pub budget_s: f64,
    pub progress: bool,
}

impl ScalingOptions {
    /// The defaults on `railing`; `quick` shrinks everything to a few seconds.
    pub fn new(quick: bool) -> Self {
        if quick {
            ScalingOptions {
                scene: "railing".into(),
                sizes: vec![(160, 90), (320, 180)],
                cocs: vec![4.0, 16.0],
                coc_size: (160, 90),
                methods: Vec::new(),
                runs: 1,
                budget_s: DEFAULT_BUDGET_S,
                progress: false,
            }
        } else {
            ScalingOptions {
                scene: "railing".into(),
                sizes: DEFAULT_SIZES.to_vec(),
                cocs: DEFAULT_COCS.to_vec(),
                coc_size: (640, 360),
                methods: Vec::new(),
                runs: 3,
                budget_s: DEFAULT_BUDGET_S,
                progress: false,
            }
        }
    }

    fn check(&self) -> Result<()> {
        let bad = |what: String| Err(Error::invalid(what));
        if self.sizes.is_empty() && self.cocs.is_empty() {
            return bad("the scaling sweep needs image sizes or CoC radii to run at".into());
        }
        for &(w, h) in self.sizes.iter().chain([&self.coc_size]) {
            if w < 8 || h < 8 || w > MAX_SIDE || h > MAX_SIDE {
                return bad(format!("a scaling sweep size must lie between 8x8 and {MAX_SIDE}x{MAX_SIDE}, got {w}x{h}"));
            }
        }
        if let Some(c) = self.cocs.iter().find(|c| !(**c > 0.0 && c.is_finite() && **c <= 1024.0)) {
            return bad(format!("a scaling sweep CoC radius must be a positive number of pixels up to 1024, got {c}"));
        }
        if self.runs == 0 {
            return bad("the scaling sweep needs at least one timed run a point".into());
        }
        if !(self.budget_s > 0.0 && self.budget_s.is_finite()) {
            return bad(format!("the time budget must be a positive number of seconds, got {}", self.budget_s));
        }
        Ok(())
    }
}

/// Which axis a point lies on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SweepAxis {
    /// The image size, the blur scaled with it.
    Resolution,
    /// The largest CoC radius, at a fixed size.
    MaxCoc,
}

impl SweepAxis {
    fn name(self) -> &'static str {
        match self {
            SweepAxis::Resolution => "resolution",
            SweepAxis::MaxCoc => "max CoC",
        }
    }
}

/// One method on one backend at one point; `time_ms` is `None` when the point was skipped.
#[derive(Clone, Debug, Serialize)]
pub struct ScalingPoint {
    pub axis: SweepAxis,
    pub method: String,
    pub setting: String,
    pub backend: String,
    pub device: String,
    /// The frame.
    pub width: u32,
    pub height: u32,
    pub pixels: u64,
    /// What the method runs on: the frame and its guard band.
    pub input_pixels: u64,
    /// Largest CoC radius present (px).
    pub max_coc_px: f64,
    /// Median of the summed stage times.
    pub time_ms: Option<f64>,
    pub stages_ms: BTreeMap<String, f64>,
    /// Median wall-clock time of a whole run (uploads, readback and host work included).
    pub wall_ms: Option<f64>,
    /// Timed runs; 0 when the warm-up alone was over the budget and is what is reported.
    pub runs: usize,
    /// Peak bytes of the backend's buffers during the point.
    pub peak_device_bytes: Option<u64>,
    /// Peak resident memory of the process during the point (information only).
    pub peak_rss_bytes: Option<u64>,
    /// Why the point was not run.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub skipped: Option<String>,
    pub figures: BTreeMap<String, f64>,
}

/// The sweep's output, `scaling.json`.
#[derive(Clone, Debug, Serialize)]
pub struct ScalingReport {
    pub version: String,
    pub scene: String,
    pub runs: usize,
    pub budget_s: f64,
    /// The frame size of the max-CoC series.
    pub coc_size: [u32; 2],
    pub backends: Vec<BackendInfo>,
    pub points: Vec<ScalingPoint>,
}

/// The process's peak resident memory (Linux).
mod rss {
    /// Starts the peak over; false where the system does not allow it.
    pub fn reset_peak() -> bool {
        std::fs::write("/proc/self/clear_refs", "5").is_ok()
    }

    pub fn peak_bytes() -> Option<u64> {
        let status = std::fs::read_to_string("/proc/self/status").ok()?;
        let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
        let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
        Some(kb * 1024)
    }
}

/// The methods the sweep runs, each with its setting.
fn chosen(names: &[String]) -> Result<Vec<(Box<dyn EvaluatedMethod>, Setting)>> {
    let all = evaluated_methods();
    for n in names {
        match all.iter().find(|m| m.name() == n) {
            None => {
                let known: Vec<_> = all.iter().map(|m| m.name()).collect();
                return Err(Error::invalid(format!("unknown method `{n}`; the methods are: {}", known.join(", "))));
            }
            Some(m) if !m.uses_backend() => {
                return Err(Error::invalid(format!("`{n}` runs no kernels; the scaling sweep times methods that do")));
            }
            Some(_) => {}
        }
    }
    Ok(all
        .into_iter()
        .filter(|m| m.uses_backend() && (names.is_empty() || names.iter().any(|n| n == m.name())))
        .filter_map(|m| {
            let setting = m.sweep_setting().or_else(|| m.settings(false).into_iter().next())?;
            Some((m, setting))
        })
        .collect())
}

struct Measured {
    times: RunTimes,
    wall_ms: f64,
    runs: usize,
    peak_device_bytes: u64,
    peak_rss_bytes: Option<u64>,
    figures: BTreeMap<String, f64>,
}

/// A warm-up, then `runs` timed runs unless the warm-up alone was over the budget.
fn measure(
    method: &dyn EvaluatedMethod,
    b: &mut dyn Backend,
    input: &MethodInput,
    setting: &Setting,
    runs: usize,
    budget_s: f64,
) -> Result<Measured> {
    let held = b.counters().device_bytes;
    b.reset_peak_device_bytes();
    let rss_reset = rss::reset_peak();
    let start = Instant::now();
    let mut output = method.run(b, input, setting)?;
    let warm_s = start.elapsed().as_secs_f64();
    let mut times = RunTimes::default();
    let mut walls = Vec::new();
    if warm_s > budget_s {
        times.add(&output.stages);
        walls.push(warm_s * 1e3);
    } else {
        for _ in 0..runs {
            let start = Instant::now();
            output = method.run(b, input, setting)?;
            walls.push(start.elapsed().as_secs_f64() * 1e3);
            times.add(&output.stages);
        }
    }
    let timed_runs = if warm_s > budget_s { 0 } else { runs };
    Ok(Measured {
        times,
        wall_ms: median(walls),
        runs: timed_runs,
        peak_device_bytes: b.counters().peak_device_bytes.saturating_sub(held),
        peak_rss_bytes: if rss_reset { rss::peak_bytes() } else { None },
        figures: output.figures,
    })
}

/// Sorted by pixel count, duplicates removed.
fn ordered_sizes(sizes: &[(u32, u32)]) -> Vec<(u32, u32)> {
    let mut s = sizes.to_vec();
    s.sort_by_key(|&(w, h)| (w as u64 * h as u64, w));
    s.dedup();
    s
}

/// Runs the sweep on `backends`.
pub fn scaling(options: &ScalingOptions, backends: &mut [Box<dyn Backend>]) -> Result<ScalingReport> {
    options.check()?;
    if backends.is_empty() {
        return Err(Error::invalid("the scaling sweep needs at least one backend".into()));
    }
    let methods = chosen(&options.methods)?;
    let scene = builtin(&options.scene)?;
    let infos = backends.iter().map(|b| BackendInfo::of(b.as_ref())).collect();
    let mut report = ScalingReport {
        version: env!("CARGO_PKG_VERSION").to_string(),
        scene: options.scene.clone(),
        runs: options.runs,
        budget_s: options.budget_s,
        coc_size: [options.coc_size.0, options.coc_size.1],
        backends: infos,
        points: Vec::new(),
    };
    // Per (axis, method, backend): why the rest of the series is skipped.
    let mut stopped: BTreeMap<(usize, usize, usize), String> = BTreeMap::new();
    // Per series: (x, wall ms) of the points measured so far.
    let mut history: BTreeMap<(usize, usize, usize), Vec<(f64, f64)>> = BTreeMap::new();
    let mut cocs = options.cocs.clone();
    cocs.sort_by(f64::total_cmp);
    cocs.dedup();
    // Inputs are cast one at a time, just before they are run, so only one is held.
    let mut plan: Vec<(SweepAxis, (u32, u32), Option<f64>)> =
        ordered_sizes(&options.sizes).into_iter().map(|s| (SweepAxis::Resolution, s, None)).collect();
    plan.extend(cocs.iter().map(|&c| (SweepAxis::MaxCoc, options.coc_size, Some(c))));
    let coc_scene = scene.clone().with_size(options.coc_size.0, options.coc_size.1);
    let coc_base = if cocs.is_empty() {
        None
    } else {
        let lens = coc_scene.thin_lens()?;
        let layers = raycast_layers(&coc_scene.scene, &coc_scene.camera, &lens, &LayerOptions::default())?.layers;
        Some((lens, layers))
    };
    for (axis, (w, h), target) in plan {
        let (input, max_coc_px) = match (target, &coc_base) {
            (Some(t), Some((lens, layers))) => input_at_max_coc(&coc_scene, lens, layers, t)?,
            _ => {
                let sized = scene.clone().with_size(w, h);
                let lens = sized.thin_lens()?;
                let ml = raycast_layers(&sized.scene, &sized.camera, &lens, &LayerOptions::default())?;
                let max = max_coc_radius(&ml.layers, &lens);
                (MethodInput::new(ml.layers, lens, ml.margin), max)
            }
        };
        let input_pixels = input.layers.width as u64 * input.layers.height as u64;
        let axis_index = axis as usize;
        for (mi, (method, setting)) in methods.iter().enumerate() {
            for (bi, backend) in backends.iter_mut().enumerate() {
                let b = backend.as_mut();
                let mut point = ScalingPoint {
                    axis,
                    method: method.name().to_string(),
                    setting: setting.label.clone(),
                    backend: b.kind().to_string(),
                    device: b.device_name(),
                    width: w,
                    height: h,
                    pixels: w as u64 * h as u64,
                    input_pixels,
                    max_coc_px,
                    time_ms: None,
                    stages_ms: BTreeMap::new(),
                    wall_ms: None,
                    runs: 0,
                    peak_device_bytes: None,
                    peak_rss_bytes: None,
                    skipped: stopped.get(&(axis_index, mi, bi)).cloned(),
                    figures: BTreeMap::new(),
                };
                let at = match axis {
                    SweepAxis::Resolution => format!("{w}x{h}"),
                    SweepAxis::MaxCoc => format!("max CoC {max_coc_px:.0} px"),
                };
                let key = (axis_index, mi, bi);
                let x = match axis {
                    SweepAxis::Resolution => point.pixels as f64,
                    SweepAxis::MaxCoc => max_coc_px,
                };
                if let Some(predicted) = history.get(&key).and_then(|h| predict(h, x))
                    && point.skipped.is_none()
                    && predicted > PREDICTED_BUDGETS * options.budget_s * 1e3
                {
                    let why = format!(
                        "at {at} a run would take about {:.0} s (extrapolated from the smaller points), over {PREDICTED_BUDGETS} times the budget of {} s",
                        predicted / 1e3,
                        options.budget_s
                    );
                    point.skipped = Some(why.clone());
                    stopped.insert(key, why);
                }
                if point.skipped.is_none() {
                    match measure(method.as_ref(), b, &input, setting, options.runs, options.budget_s) {
                        Ok(m) => {
                            point.time_ms = Some(m.times.median_total());
                            point.stages_ms = m.times.median_stages();
                            point.wall_ms = Some(m.wall_ms);
                            point.runs = m.runs;
                            point.peak_device_bytes = Some(m.peak_device_bytes);
                            point.peak_rss_bytes = m.peak_rss_bytes;
                            point.figures = m.figures;
                            history.entry(key).or_default().push((x, m.wall_ms));
                            if m.wall_ms > options.budget_s * 1e3 {
                                let why = format!("at {at} a run took {:.1} s, over the budget of {} s", m.wall_ms / 1e3, options.budget_s);
                                stopped.insert((axis_index, mi, bi), why);
                            }
                        }
                        Err(e) => {
                            let why = format!("failed at {at}: {e}");
                            point.skipped = Some(why.clone());
                            stopped.insert((axis_index, mi, bi), why);
                        }
                    }
                }
                if options.progress {
                    let what = match (&point.skipped, point.time_ms) {
                        (Some(why), _) => format!("skipped ({why})"),
                        (None, Some(t)) => format!(
                            "{t:.1} ms in kernels ({:.1} ms wall), peak {:.1} MB on the device",
                            point.wall_ms.unwrap_or(0.0),
                            point.peak_device_bytes.unwrap_or(0) as f64 / 1e6
                        ),
                        (None, None) => String::new(),
                    };
                    eprintln!("scaling {} {} {} on {} at {at}: {what}", options.scene, point.method, point.setting, point.backend);
                }
                report.points.push(point);
            }
        }
    }
    Ok(report)
}

/// The run time (ms) at `x` extrapolated from the series' measured `(x, ms)`: from the last point,
/// growing as the last two points did, and at least linearly.
fn predict(measured: &[(f64, f64)], x: f64) -> Option<f64> {
    let &(x1, t1) = measured.last()?;
    let k = match measured {
        [.., a, b] => growth_exponent(&[*a, *b]).unwrap_or(1.0).max(1.0),
        _ => 1.0,
    };
    (x > x1 && x1 > 0.0).then(|| t1 * (x / x1).powf(k))
}

/// The exponent `k` of `y ∝ x^k`, least squares in log-log over the points (at least two distinct x).
pub fn growth_exponent(points: &[(f64, f64)]) -> Option<f64> {
    let logs: Vec<(f64, f64)> = points.iter().filter(|p| p.0 > 0.0 && p.1 > 0.0).map(|p| (p.0.ln(), p.1.ln())).collect();
    let n = logs.len() as f64;
    let (mx, my) = (logs.iter().map(|p| p.0).sum::<f64>() / n, logs.iter().map(|p| p.1).sum::<f64>() / n);
    let sxx: f64 = logs.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = logs.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    (logs.len() >= 2 && sxx > 1e-12).then(|| sxy / sxx)
}

fn shape(backend: &str) -> Shape {
    if backend == "vulkan" { Shape::Triangle } else { Shape::Circle }
}

impl ScalingReport {
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// Distinct `(method, setting, backend)` in run order.
    fn series_keys(&self) -> Vec<(&str, &str, &str)> {
        let mut keys: Vec<(&str, &str, &str)> = Vec::new();
        for p in &self.points {
            let k = (p.method.as_str(), p.setting.as_str(), p.backend.as_str());
            if !keys.contains(&k) {
                keys.push(k);
            }
        }
        keys
    }

    fn series(&self, axis: SweepAxis, method: &str, backend: &str) -> Vec<&ScalingPoint> {
        self.points.iter().filter(|p| p.axis == axis && p.method == method && p.backend == backend).collect()
    }

    /// The x of a point on `axis`: frame pixels, or the largest CoC radius.
    fn x(axis: SweepAxis, p: &ScalingPoint) -> f64 {
        match axis {
            SweepAxis::Resolution => p.pixels as f64,
            SweepAxis::MaxCoc => p.max_coc_px,
        }
    }

    /// Markdown: per axis, a table of time (and peak device memory) per method, backend and point,
    /// with the growth exponent; then every skipped point and why.
    pub fn to_markdown(&self) -> String {
        let mut md = format!("## Scaling with resolution and blur ({})\n\n", self.scene);
        let _ = writeln!(
            md,
            "Time: median of {} runs after a warm-up, summed stage times (ms); a point whose warm-up was over the budget of {} s reports that run alone. \
            Memory: the backend's peak device bytes during the point (MB). `k`: the exponent of time ∝ x^k, least squares over the measured points; \
            k > 1 against pixels grows faster than the pixel count.\n",
            self.runs, self.budget_s
        );
        let mut methods: Vec<&str> = Vec::new();
        for (m, _, _) in self.series_keys() {
            if !methods.contains(&m) {
                methods.push(m);
            }
        }
        for axis in [SweepAxis::Resolution, SweepAxis::MaxCoc] {
            let columns: Vec<&ScalingPoint> = {
                let mut seen: Vec<&ScalingPoint> = Vec::new();
                for p in self.points.iter().filter(|p| p.axis == axis) {
                    if !seen.iter().any(|s| {
                        s.width == p.width
                            && s.height == p.height
                            && (axis == SweepAxis::Resolution || (s.max_coc_px - p.max_coc_px).abs() < 0.5)
                    }) {
                        seen.push(p);
                    }
                }
                seen
            };
            if columns.is_empty() {
                continue;
            }
            let head: Vec<String> = columns
                .iter()
                .map(|p| match axis {
                    SweepAxis::Resolution => format!("{}x{}", p.width, p.height),
                    SweepAxis::MaxCoc => format!("CoC {:.0} px", p.max_coc_px),
                })
                .collect();
            match axis {
                SweepAxis::Resolution => md.push_str("### Against resolution (the blur scaled with the image)\n\n"),
                SweepAxis::MaxCoc => {
                    let _ = writeln!(md, "### Against the largest CoC radius ({}x{})\n", self.coc_size[0], self.coc_size[1]);
                }
            }
            let _ = writeln!(md, "| method | setting | backend | {} | k |", head.join(" | "));
            let _ = writeln!(md, "|---|---|---|{}---|", "---|".repeat(head.len()));
            for (method, setting, backend) in self.series_keys() {
                let series = self.series(axis, method, backend);
                let cells: Vec<String> = series
                    .iter()
                    .map(|p| match (p.time_ms, &p.skipped) {
                        (Some(t), _) => format!("{t:.1} ms, {:.1} MB", p.peak_device_bytes.unwrap_or(0) as f64 / 1e6),
                        (None, Some(_)) => "skipped".into(),
                        (None, None) => "-".into(),
                    })
                    .collect();
                let measured: Vec<(f64, f64)> = series.iter().filter_map(|p| Some((Self::x(axis, p), p.time_ms?))).collect();
                let k = growth_exponent(&measured).map_or("-".into(), |k| format!("{k:.2}"));
                let _ = writeln!(md, "| {method} | {setting} | {backend} | {} | {k} |", cells.join(" | "));
            }
            md.push('\n');
        }
        let skipped: Vec<&ScalingPoint> = self.points.iter().filter(|p| p.skipped.is_some()).collect();
        if !skipped.is_empty() {
            md.push_str("Skipped points:\n\n");
            for p in skipped {
                let at = match p.axis {
                    SweepAxis::Resolution => format!("{}x{}", p.width, p.height),
                    SweepAxis::MaxCoc => format!("max CoC {:.0} px", p.max_coc_px),
                };
                let _ = writeln!(md, "- {} on {} at {at} ({}): {}", p.method, p.backend, p.axis.name(), p.skipped.as_deref().unwrap_or(""));
            }
            md.push('\n');
        }
        md
    }

    /// The figures, by file stem: per backend, time against pixels and against the largest CoC, and
    /// peak device memory against pixels, all log-log with a dashed reference slope.
    pub fn figures(&self) -> Vec<(String, Figure)> {
        let mut backends: Vec<&str> = Vec::new();
        let mut methods: Vec<&str> = Vec::new();
        for p in &self.points {
            if !backends.contains(&p.backend.as_str()) {
                backends.push(&p.backend);
            }
            if !methods.contains(&p.method.as_str()) {
                methods.push(&p.method);
            }
        }
        let mut out = Vec::new();
        type Value = fn(&ScalingPoint) -> Option<f64>;
        let time: Value = |p| p.time_ms;
        let memory: Value = |p| p.peak_device_bytes.map(|b| b as f64 / 1e6);
        let kinds: [(&str, SweepAxis, Value, &str, f64, &str); 3] = [
            ("time-vs-pixels", SweepAxis::Resolution, time, "time (ms, log)", 1.0, "time ∝ pixels (slope 1)"),
            ("time-vs-coc", SweepAxis::MaxCoc, time, "time (ms, log)", 2.0, "time ∝ CoC² (slope 2)"),
            ("memory-vs-pixels", SweepAxis::Resolution, memory, "peak device memory (MB, log)", 1.0, "memory ∝ pixels (slope 1)"),
        ];
        for backend in backends {
            let device = self.points.iter().find(|p| p.backend == backend).map_or(String::new(), |p| p.device.clone());
            for (stem, axis, value, y_label, slope, reference) in kinds {
                let mut series = Vec::new();
                let mut all: Vec<(f64, f64)> = Vec::new();
                for (mi, method) in methods.iter().enumerate() {
                    let points = self.series(axis, method, backend);
                    if points.is_empty() {
                        continue;
                    }
                    let measured: Vec<(f64, f64)> =
                        points.iter().filter_map(|p| Some((Self::x(axis, p), value(p)?))).filter(|p| p.1 > 0.0).collect();
                    let skipped = points.iter().filter(|p| p.skipped.is_some()).count();
                    let mut name = format!("{method} {}", points[0].setting);
                    if skipped > 0 {
                        let _ = write!(name, " ({skipped} skipped)");
                    }
                    all.extend(&measured);
                    series.push(Series { name, colour: palette(mi), mark: Mark::Line(shape(backend)), points: measured });
                }
                if all.is_empty() {
                    continue;
                }
                // The reference through the geometric mean of the values at the smallest x.
                let x0 = all.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
                let x1 = all.iter().map(|p| p.0).fold(0.0, f64::max);
                let at_x0: Vec<f64> = all.iter().filter(|p| p.0 == x0).map(|p| p.1.ln()).collect();
                let y0 = (at_x0.iter().sum::<f64>() / at_x0.len() as f64).exp();
                if x1 > x0 {
                    series.push(Series {
                        name: reference.into(),
                        colour: [120, 120, 120],
                        mark: Mark::Dashed,
                        points: vec![(x0, y0), (x1, y0 * (x1 / x0).powf(slope))],
                    });
                }
                let (x_label, title) = match axis {
                    SweepAxis::Resolution => (
                        "frame pixels (log)",
                        format!(
                            "{}: {} against resolution",
                            self.scene,
                            if stem.starts_with("time") { "time" } else { "peak device memory" }
                        ),
                    ),
                    SweepAxis::MaxCoc => (
                        "largest CoC radius (px, log)",
                        format!("{}: time against the largest CoC ({}x{})", self.scene, self.coc_size[0], self.coc_size[1]),
                    ),
                };
                out.push((
                    format!("scaling-{stem}-{backend}"),
                    Figure {
                        title: format!("{title}, {backend} ({device})"),
                        x_label: x_label.into(),
                        y_label: y_label.into(),
                        x_axis: Axis::Log,
                        y_axis: Axis::Log,
                        categories: Vec::new(),
                        series,
                    },
                ));
            }
        }
        out
    }

    /// Writes `scaling.json`, `scaling.md` and (with `plots`) every figure as SVG and PNG into
    /// `dir`; returns the files written.
    pub fn write(&self, dir: &Path, plots: bool) -> Result<Vec<PathBuf>> {
        let io = |path: &Path, e: std::io::Error| Error::invalid(format!("writing {}: {e}", path.display()));
        std::fs::create_dir_all(dir).map_err(|e| io(dir, e))?;
        let mut written = Vec::new();
        for (name, text) in [("scaling.json", self.to_json()), ("scaling.md", self.to_markdown())] {
            let path = dir.join(name);
            std::fs::write(&path, text).map_err(|e| io(&path, e))?;
            written.push(path);
        }
        if plots {
            for (stem, figure) in self.figures() {
                written.extend(super::plot::write(&figure, &dir.join(stem))?);
            }
        }
        Ok(written)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn growth_exponents_read_slopes() {
        let quadratic: Vec<(f64, f64)> = [1.0, 2.0, 4.0, 8.0].iter().map(|&x| (x, 3.0 * x * x)).collect();
        assert!((growth_exponent(&quadratic).unwrap() - 2.0).abs() < 1e-9);
        assert!((growth_exponent(&[(100.0, 5.0), (400.0, 20.0)]).unwrap() - 1.0).abs() < 1e-9);
        assert_eq!(growth_exponent(&[(1.0, 1.0)]), None);
        assert_eq!(growth_exponent(&[(2.0, 1.0), (2.0, 3.0)]), None);
    }

    #[test]
    fn extrapolation_is_at_least_linear() {
        let near = |got: Option<f64>, want: f64| got.is_some_and(|g| (g - want).abs() < 1e-9 * want);
        assert_eq!(predict(&[], 2.0), None);
        assert_eq!(predict(&[(4.0, 10.0)], 2.0), None);
        assert!(near(predict(&[(1.0, 10.0)], 4.0), 40.0));
        // Quadratic growth between the last two points carries on; slower growth counts as linear.
        assert!(near(predict(&[(1.0, 10.0), (2.0, 40.0)], 4.0), 160.0));
        assert!(near(predict(&[(1.0, 10.0), (2.0, 11.0)], 4.0), 22.0));
    }

    #[test]
    fn bad_options_are_refused() {
        let mut o = ScalingOptions::new(true);
        o.sizes = vec![(0, 90)];
        assert!(scaling(&o, &mut []).unwrap_err().to_string().contains("0x90"));
        let mut o = ScalingOptions::new(true);
        o.cocs = vec![-1.0];
        assert!(scaling(&o, &mut []).unwrap_err().to_string().contains("CoC"));
        let mut o = ScalingOptions::new(true);
        o.methods = vec!["pinhole".into()];
        let mut cpu: Vec<Box<dyn Backend>> = vec![Box::new(crate::backend::CpuBackend::new())];
        assert!(scaling(&o, &mut cpu).unwrap_err().to_string().contains("runs no kernels"));
    }
}
