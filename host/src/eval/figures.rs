//! The evaluation's plots, built from a [`Report`] and drawn by [`super::plot`], each as SVG and PNG
//! in the output directory:
//!
//! - `<scene>-error-vs-time`: PSNR in the partial-occlusion region (full frame where a scene has no
//!   region) against median time, log scale, one colour per method, circles for the CPU backend and
//!   triangles for Vulkan, with each backend's Pareto front dashed. Host-only methods take no time
//!   and are drawn as a horizontal line (the pinhole is the floor every method must beat).
//! - `<scene>-tile-size` (Franke et al. 2018, Fig. 14): time against tile size for the splatting methods at the
//!   merge level the tile sweep uses.
//! - `<scene>-list-lengths` (Fig. 12): tiles per list-length bucket, one bar per merge level, from
//!   the multi-layer method on the first backend at its smallest tile size (lists are identical on
//!   both backends).
//! - `<sweep scene>-max-coc` (Fig. 13): time against the largest CoC radius present, log time.
//! - `scaling-*-<backend>` (with `dof eval --scaling`): time and peak device memory against
//!   resolution and time against the largest CoC, see [`super::scaling::ScalingReport::figures`].

use super::plot::{Axis, Figure, Mark, Series, Shape, palette};
use super::report::{Record, Report};
use crate::error::Result;
use std::path::{Path, PathBuf};

/// The points no other point beats on both axes (less time, more PSNR), by increasing time: each
/// point of the front is faster than every point with higher PSNR.
pub fn pareto_front(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut sorted: Vec<(f64, f64)> = points.iter().copied().filter(|p| p.0.is_finite() && p.1.is_finite()).collect();
    // By time, and for equal times the better point first so the worse one is dominated.
    sorted.sort_by(|a, b| a.0.total_cmp(&b.0).then(b.1.total_cmp(&a.1)));
    let mut front: Vec<(f64, f64)> = Vec::new();
    for p in sorted {
        if front.last().is_none_or(|last| p.1 > last.1) {
            front.push(p);
        }
    }
    front
}

fn shape(backend: &str) -> Shape {
    match backend {
        "cpu" => Shape::Circle,
        "vulkan" => Shape::Triangle,
        _ => Shape::Square,
    }
}

/// Methods in report order, so one method keeps its colour across figures.
fn method_colour(report: &Report, method: &str) -> [u8; 3] {
    let mut seen: Vec<&str> = Vec::new();
    for r in &report.records {
        if !seen.contains(&r.method.as_str()) {
            seen.push(&r.method);
        }
    }
    palette(seen.iter().position(|m| *m == method).unwrap_or(seen.len()))
}

/// Distinct `(method, backend)` pairs of `records`, in order.
fn groups<'a>(records: impl Iterator<Item = (&'a str, &'a str)>) -> Vec<(&'a str, &'a str)> {
    let mut out: Vec<(&str, &str)> = Vec::new();
    for g in records {
        if !out.contains(&g) {
            out.push(g);
        }
    }
    out
}

pub fn error_vs_time(report: &Report, scene: &str) -> Option<Figure> {
    let records: Vec<&Record> = report.records.iter().filter(|r| r.scene == scene).collect();
    let timed: Vec<&Record> = records.iter().copied().filter(|r| r.time_ms > 0.0).collect();
    if timed.is_empty() {
        return None;
    }
    let masked = records.iter().all(|r| r.psnr_masked_db.is_some());
    let error = |r: &Record| if masked { r.psnr_masked_db.unwrap_or(f64::NAN) } else { r.psnr_db };
    let mut series = Vec::new();
    for (method, backend) in groups(timed.iter().map(|r| (r.method.as_str(), r.backend.as_str()))) {
        let points = timed.iter().filter(|r| r.method == method && r.backend == backend).map(|r| (r.time_ms, error(r))).collect();
        series.push(Series {
            name: format!("{method} ({backend})"),
            colour: method_colour(report, method),
            mark: Mark::Points(shape(backend)),
            points,
        });
    }
    let (fastest, slowest) = timed.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), r| (lo.min(r.time_ms), hi.max(r.time_ms)));
    for r in records.iter().filter(|r| r.time_ms <= 0.0 && error(r).is_finite()) {
        let name = format!("{} {} (no device time)", r.method, r.setting).replace(" - ", " ");
        series.push(Series {
            name,
            colour: method_colour(report, &r.method),
            mark: Mark::Dashed,
            points: vec![(fastest, error(r)), (slowest, error(r))],
        });
    }
    for (i, backend) in groups(timed.iter().map(|r| ("", r.backend.as_str()))).into_iter().map(|g| g.1).enumerate() {
        let points: Vec<(f64, f64)> = timed.iter().filter(|r| r.backend == backend).map(|r| (r.time_ms, error(r))).collect();
        series.push(Series {
            name: format!("Pareto front ({backend})"),
            colour: if i == 0 { [60, 60, 60] } else { [150, 150, 150] },
            mark: Mark::Dashed,
            points: pareto_front(&points),
        });
    }
    Some(Figure {
        title: format!("{scene}: error against time"),
        x_label: "median time (ms, log scale)".into(),
        y_label: if masked { "PSNR in the partial-occlusion region (dB)".into() } else { "PSNR (dB)".into() },
        x_axis: Axis::Log,
        y_axis: Axis::Linear,
        categories: Vec::new(),
        series,
    })
}

fn figure(r: &Record, name: &str) -> Option<f64> {
    r.figures.get(name).copied()
}

pub fn tile_size(report: &Report, scene: &str) -> Option<Figure> {
    let tiled: Vec<&Record> = report.records.iter().filter(|r| r.scene == scene && figure(r, "tile_px").is_some()).collect();
    // The merge level with the most distinct tile sizes is the tile sweep.
    let steps_of = |r: &Record| figure(r, "merge_steps").unwrap_or(0.0);
    let distinct_tiles = |steps: f64| {
        let mut tiles: Vec<u64> =
            tiled.iter().filter(|r| steps_of(r) == steps).filter_map(|r| figure(r, "tile_px")).map(|t| t as u64).collect();
        tiles.sort_unstable();
        tiles.dedup();
        tiles.len()
    };
    let steps = tiled.iter().map(|r| steps_of(r)).max_by_key(|&s| (distinct_tiles(s), s as u64))?;
    if distinct_tiles(steps) < 2 {
        return None;
    }
    let swept: Vec<&Record> = tiled.into_iter().filter(|r| steps_of(r) == steps).collect();
    let series = groups(swept.iter().map(|r| (r.method.as_str(), r.backend.as_str())))
        .into_iter()
        .map(|(method, backend)| {
            let mut points: Vec<(f64, f64)> = swept
                .iter()
                .filter(|r| r.method == method && r.backend == backend)
                .filter_map(|r| Some((figure(r, "tile_px")?, r.time_ms)))
                .collect();
            points.sort_by(|a, b| a.0.total_cmp(&b.0));
            Series {
                name: format!("{method} ({backend})"),
                colour: method_colour(report, method),
                mark: Mark::Line(shape(backend)),
                points,
            }
        })
        .collect();
    let merge = match steps as u32 {
        0 => "no merge".to_string(),
        s => format!("{0}x{0} merge", 1u32 << s),
    };
    Some(Figure {
        title: format!("{scene}: time against tile size ({merge})"),
        x_label: "tile size (px)".into(),
        y_label: "median time (ms, log scale)".into(),
        x_axis: Axis::Linear,
        y_axis: Axis::Log,
        categories: Vec::new(),
        series,
    })
}

pub fn list_lengths(report: &Report, scene: &str) -> Option<Figure> {
    let with_lists: Vec<&Record> = report.records.iter().filter(|r| r.scene == scene && !r.list_histogram.is_empty()).collect();
    let method = if with_lists.iter().any(|r| r.method == "multilayer") { "multilayer" } else { with_lists.first()?.method.as_str() };
    let backend = with_lists.iter().find(|r| r.method == method)?.backend.as_str();
    let ours: Vec<&Record> = with_lists.iter().copied().filter(|r| r.method == method && r.backend == backend).collect();
    let tile = ours.iter().filter_map(|r| figure(r, "tile_px")).fold(f64::INFINITY, f64::min);
    let chosen: Vec<&Record> = ours.into_iter().filter(|r| figure(r, "tile_px").is_none_or(|t| t == tile)).collect();
    let mut bounds: Vec<u32> = chosen.iter().flat_map(|r| r.list_histogram.iter().map(|b| b.0)).collect();
    bounds.sort_unstable();
    bounds.dedup();
    let series = chosen
        .iter()
        .enumerate()
        .map(|(i, r)| Series {
            name: r.setting.clone(),
            colour: palette(i),
            mark: Mark::Bars { slot: i, of: chosen.len() },
            points: r.list_histogram.iter().filter_map(|&(b, n)| Some((bounds.iter().position(|&x| x == b)? as f64, n as f64))).collect(),
        })
        .collect();
    Some(Figure {
        title: format!("{scene}: list lengths, {method} on {backend}"),
        x_label: "entries per tile list (bucket upper bound)".into(),
        y_label: "tiles".into(),
        x_axis: Axis::Categories,
        y_axis: Axis::Linear,
        categories: bounds.iter().map(|&b| if b == 0 { "0".to_string() } else { format!("<={b}") }).collect(),
        series,
    })
}

pub fn max_coc(report: &Report) -> Option<(String, Figure)> {
    let scene = report.coc_sweep.first()?.scene.clone();
    let sweep: Vec<_> = report.coc_sweep.iter().filter(|r| r.scene == scene).collect();
    let series = groups(sweep.iter().map(|r| (r.method.as_str(), r.backend.as_str())))
        .into_iter()
        .map(|(method, backend)| {
            let points = sweep.iter().filter(|r| r.method == method && r.backend == backend).map(|r| (r.max_coc_px, r.time_ms)).collect();
            let setting = sweep.iter().find(|r| r.method == method).map_or("", |r| r.setting.as_str());
            Series {
                name: format!("{method} {setting} ({backend})"),
                colour: method_colour(report, method),
                mark: Mark::Line(shape(backend)),
                points,
            }
        })
        .collect();
    let figure = Figure {
        title: format!("{scene}: time against the largest CoC"),
        x_label: "largest CoC radius present (px)".into(),
        y_label: "median time (ms, log scale)".into(),
        x_axis: Axis::Linear,
        y_axis: Axis::Log,
        categories: Vec::new(),
        series,
    };
    Some((scene, figure))
}

/// Draws every figure the report has data for into `dir`; returns the files written.
pub fn write_all(report: &Report, dir: &Path) -> Result<Vec<PathBuf>> {
    let mut figures: Vec<(String, Figure)> = Vec::new();
    for s in &report.scenes {
        let named = [
            ("error-vs-time", error_vs_time(report, &s.name)),
            ("tile-size", tile_size(report, &s.name)),
            ("list-lengths", list_lengths(report, &s.name)),
        ];
        figures.extend(named.into_iter().filter_map(|(kind, f)| Some((format!("{}-{kind}", s.name), f?))));
    }
    if let Some((scene, f)) = max_coc(report) {
        figures.push((format!("{scene}-max-coc"), f));
    }
    if let Some(scaling) = &report.scaling {
        figures.extend(scaling.figures());
    }
    let mut written = Vec::new();
    for (stem, f) in figures {
        written.extend(super::plot::write(&f, &dir.join(stem))?);
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pareto_front_keeps_only_undominated_points() {
        let points = [(10.0, 30.0), (1.0, 20.0), (5.0, 25.0), (6.0, 24.0), (1.0, 19.0), (20.0, 30.0), (f64::NAN, 50.0)];
        assert_eq!(pareto_front(&points), vec![(1.0, 20.0), (5.0, 25.0), (10.0, 30.0)]);
        assert!(pareto_front(&[]).is_empty());
    }
}
