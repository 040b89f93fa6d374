//! A small figure description and its one renderer, drawn twice: SVG (text as text) and PNG (through
//! the crate's own PNG writer). The evaluation's figures are built in [`super::figures`]; this module
//! only knows marks, axes and legends.
//!
//! Text needs a TrueType font, loaded once from `DOF_PLOT_FONT` or the usual system paths (Debian's
//! `fonts-dejavu-core` provides one); without a font, drawing fails with an error that says so.

use crate::error::{Error, Result};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    Circle,
    Triangle,
    Square,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Mark {
    Points(Shape),
    /// A solid line through the points, each marked with the shape.
    Line(Shape),
    /// A dashed line without markers (the Pareto front).
    Dashed,
    /// Bars of width 1/`of` at offset `slot` inside each unit of x (grouped histogram bars).
    Bars {
        slot: usize,
        of: usize,
    },
}

#[derive(Clone, Debug)]
pub struct Series {
    pub name: String,
    pub colour: [u8; 3],
    pub mark: Mark,
    pub points: Vec<(f64, f64)>,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Axis {
    Linear,
    /// Values are drawn at their base-10 logarithm and labelled with the value; values `<= 0` are
    /// left out.
    Log,
    /// Unit slots labelled by the given names (x only): slot `i` spans `[i, i + 1)`.
    Categories,
}

#[derive(Clone, Debug)]
pub struct Figure {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub x_axis: Axis,
    pub y_axis: Axis,
    /// Names of the x slots when `x_axis` is [`Axis::Categories`].
    pub categories: Vec<String>,
    pub series: Vec<Series>,
}

const SIZE: (u32, u32) = (1100, 560);
/// Width of the legend column right of the chart.
const LEGEND_WIDTH: u32 = 330;
/// The family the plot font is registered as (the grids' labels use it too).
pub(crate) const FONT: &str = "sans-serif";

/// Distinct colours for series, by index.
pub fn palette(i: usize) -> [u8; 3] {
    const COLOURS: [[u8; 3]; 8] =
        [[31, 119, 180], [214, 39, 40], [44, 160, 44], [255, 127, 14], [148, 103, 189], [140, 86, 75], [227, 119, 194], [23, 190, 207]];
    COLOURS[i % COLOURS.len()]
}

/// Font search order: `DOF_PLOT_FONT`, then common system locations.
const FONT_PATHS: [&str; 5] = [
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
    "/usr/share/fonts/liberation/LiberationSans-Regular.ttf",
];

/// Loads the plot font once; an error says what to install.
pub fn ensure_font() -> Result<()> {
    static FONT_READY: OnceLock<std::result::Result<(), String>> = OnceLock::new();
    FONT_READY
        .get_or_init(|| {
            let candidates: Vec<PathBuf> =
                std::env::var_os("DOF_PLOT_FONT").map(PathBuf::from).into_iter().chain(FONT_PATHS.iter().map(PathBuf::from)).collect();
            let path = candidates.iter().find(|p| p.is_file()).ok_or_else(|| {
                format!(
                    "no TrueType font found (looked in $DOF_PLOT_FONT and {}); install one (`apt-get install fonts-dejavu-core`) or set DOF_PLOT_FONT",
                    FONT_PATHS.join(", ")
                )
            })?;
            let bytes = std::fs::read(path).map_err(|e| format!("reading the font {}: {e}", path.display()))?;
            // The font registry keeps `'static` bytes; one font per process.
            let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
            plotters::style::register_font(FONT, FontStyle::Normal, bytes).map_err(|_| format!("{} is not a usable TrueType font", path.display()))
        })
        .clone()
        .map_err(Error::Plot)
}

/// Writes `stem.svg` and `stem.png`; returns both paths.
pub fn write(figure: &Figure, stem: &Path) -> Result<[PathBuf; 2]> {
    ensure_font()?;
    let svg_path = stem.with_extension("svg");
    let png_path = stem.with_extension("png");
    let mut svg = String::new();
    draw(SVGBackend::with_string(&mut svg, SIZE).into_drawing_area(), figure).map_err(Error::Plot)?;
    std::fs::write(&svg_path, svg).map_err(|e| Error::Plot(format!("writing {}: {e}", svg_path.display())))?;
    let mut rgb = vec![0u8; (SIZE.0 * SIZE.1 * 3) as usize];
    draw(BitMapBackend::with_buffer(&mut rgb, SIZE).into_drawing_area(), figure).map_err(Error::Plot)?;
    crate::io::write_srgb8(&png_path, SIZE.0, SIZE.1, &rgb)?;
    Ok([svg_path, png_path])
}

/// The drawn coordinate of a value on `axis` (`None` where a log axis cannot show it).
fn place(v: f64, axis: Axis) -> Option<f64> {
    match axis {
        Axis::Log if v > 0.0 && v.is_finite() => Some(v.log10()),
        Axis::Log => None,
        _ if v.is_finite() => Some(v),
        _ => None,
    }
}

/// Drawn range of the given coordinates, padded; bars and categories start at 0.
fn range(values: impl Iterator<Item = f64>, axis: Axis, from_zero: bool, slots: usize) -> std::ops::Range<f64> {
    if axis == Axis::Categories {
        return 0.0..slots.max(1) as f64;
    }
    let (mut lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if from_zero {
        lo = lo.min(0.0);
    }
    if !(lo.is_finite() && hi.is_finite()) {
        return 0.0..1.0;
    }
    if hi - lo < 1e-9 {
        let half = if axis == Axis::Log { 0.5 } else { lo.abs().max(1.0) * 0.1 };
        return lo - half..hi + half;
    }
    let pad = 0.06 * (hi - lo);
    (if from_zero && lo == 0.0 { 0.0 } else { lo - pad })..hi + pad
}

/// A tick label: three significant figures of the value the coordinate stands for.
fn tick(v: f64, axis: Axis, categories: &[String]) -> String {
    let value = match axis {
        Axis::Log => 10f64.powf(v),
        Axis::Categories => {
            // Label the slot centres' integer part; the mesh puts ticks at integers and half-integers.
            return if (v - v.floor() - 0.5).abs() < 1e-6 {
                categories.get(v.floor() as usize).cloned().unwrap_or_default()
            } else {
                String::new()
            };
        }
        Axis::Linear => v,
    };
    let a = value.abs();
    if a == 0.0 {
        "0".into()
    } else if a >= 1000.0 || a < 0.01 {
        format!("{value:.2e}")
    } else {
        let decimals = (2 - a.log10().floor() as i32).max(0) as usize;
        let text = format!("{value:.decimals$}");
        if text.contains('.') { text.trim_end_matches('0').trim_end_matches('.').to_string() } else { text }
    }
}

/// The mark of `shape` at `at`, in any coordinate system.
fn marker<DB: DrawingBackend, C: Clone + 'static>(at: C, shape: Shape, colour: RGBColor) -> DynElement<'static, DB, C> {
    match shape {
        Shape::Circle => Circle::new(at, 5, colour.filled()).into_dyn(),
        Shape::Triangle => TriangleMarker::new(at, 7, colour.filled()).into_dyn(),
        Shape::Square => Cross::new(at, 5, colour.stroke_width(2)).into_dyn(),
    }
}

fn draw<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, figure: &Figure) -> std::result::Result<(), String> {
    let fail = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    root.fill(&WHITE).map_err(fail)?;
    let (plot_area, legend_area) = root.split_horizontally(SIZE.0 - LEGEND_WIDTH);
    let placed: Vec<Vec<(f64, f64)>> = figure
        .series
        .iter()
        .map(|s| s.points.iter().filter_map(|&(x, y)| Some((place(x, figure.x_axis)?, place(y, figure.y_axis)?))).collect())
        .collect();
    let bars = figure.series.iter().any(|s| matches!(s.mark, Mark::Bars { .. }));
    let xs = range(placed.iter().flatten().map(|p| p.0), figure.x_axis, false, figure.categories.len());
    let ys = range(placed.iter().flatten().map(|p| p.1), figure.y_axis, bars, 0);
    let mut chart = ChartBuilder::on(&plot_area)
        .caption(&figure.title, (FONT, 22))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(72)
        .build_cartesian_2d(xs, ys)
        .map_err(fail)?;
    let categories = &figure.categories;
    let x_labels = if figure.x_axis == Axis::Categories { 2 * categories.len() + 1 } else { 10 };
    chart
        .configure_mesh()
        .x_desc(&figure.x_label)
        .y_desc(&figure.y_label)
        .x_labels(x_labels)
        .x_label_formatter(&|v| tick(*v, figure.x_axis, categories))
        .y_label_formatter(&|v| tick(*v, figure.y_axis, categories))
        .label_style((FONT, 14))
        .axis_desc_style((FONT, 16))
        .draw()
        .map_err(fail)?;
    for (i, (series, points)) in figure.series.iter().zip(&placed).enumerate() {
        let [r, g, b] = series.colour;
        let colour = RGBColor(r, g, b);
        let style = colour.stroke_width(2);
        match series.mark {
            Mark::Points(shape) => {
                chart.draw_series(points.iter().map(|&p| marker(p, shape, colour))).map_err(fail)?;
            }
            Mark::Line(shape) => {
                chart.draw_series(LineSeries::new(points.iter().copied(), style)).map_err(fail)?;
                chart.draw_series(points.iter().map(|&p| marker(p, shape, colour))).map_err(fail)?;
            }
            Mark::Dashed => {
                chart.draw_series(DashedLineSeries::new(points.iter().copied(), 8, 5, style)).map_err(fail)?;
            }
            Mark::Bars { slot, of } => {
                let width = 0.8 / of.max(1) as f64;
                let bar = |&(x, y): &(f64, f64)| {
                    let left = x + 0.1 + slot as f64 * width;
                    Rectangle::new([(left, 0.0), (left + width, y)], colour.filled())
                };
                chart.draw_series(points.iter().map(bar)).map_err(fail)?;
            }
        }
        // The legend, one row per series, in its own column so it never hides data.
        let y = 70 + 24 * i as i32;
        let key: DynElement<'static, DB, (i32, i32)> = match series.mark {
            Mark::Points(shape) | Mark::Line(shape) => marker((20, y), shape, colour),
            Mark::Bars { .. } => Rectangle::new([(12, y - 6), (28, y + 6)], colour.filled()).into_dyn(),
            Mark::Dashed => PathElement::new(vec![(6, y), (14, y), (20, y)], colour.stroke_width(2)).into_dyn(),
        };
        legend_area.draw(&key).map_err(fail)?;
        if let Mark::Line(_) = series.mark {
            legend_area.draw(&PathElement::new(vec![(8, y), (32, y)], style)).map_err(fail)?;
        }
        legend_area.draw(&Text::new(series.name.clone(), (40, y - 8), (FONT, 14))).map_err(fail)?;
    }
    root.present().map_err(fail)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_read_as_values() {
        assert_eq!(tick(2.0, Axis::Log, &[]), "100");
        assert_eq!(tick(0.5, Axis::Log, &[]), "3.16");
        assert_eq!(tick(12.5, Axis::Linear, &[]), "12.5");
        assert_eq!(tick(5.0, Axis::Linear, &[]), "5");
        assert_eq!(tick(40.0, Axis::Linear, &[]), "40");
        assert_eq!(tick(1.5, Axis::Categories, &["a".into(), "b".into()]), "b");
        assert_eq!(tick(1.0, Axis::Categories, &["a".into(), "b".into()]), "");
    }

    #[test]
    fn log_axes_leave_out_what_they_cannot_show() {
        assert_eq!(place(0.0, Axis::Log), None);
        assert_eq!(place(f64::NAN, Axis::Linear), None);
        assert_eq!(place(100.0, Axis::Log), Some(2.0));
    }
}
