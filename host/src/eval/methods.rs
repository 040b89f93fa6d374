//! The methods the evaluation (and `dof stress`) runs: the pinhole image, then every method of the
//! frame API's registry ([`crate::frame::METHODS`]) through the one generic path ([`Runner`]), each
//! with the settings the evaluation sweeps ([`sweep_points`]). A method added to the registry is
//! evaluated with its default options without any change here; an entry in [`sweep_points`] adds
//! a sweep of its knobs.

use crate::backend::{Backend, CommandTime};
use crate::error::Result;
use crate::frame::registry::{self, METHODS};
use crate::frame::{LayeredOptions, MethodInfo, MethodOptions, RaytraceOptions, RingGatherOptions, SplatOptions};
use crate::layers::{LayeredImage, RgbImage};
use crate::methods::gather::MAX_RADIUS;
use crate::methods::one_shot::{OneShot, Runner, method_input, one_shot};
use crate::methods::ring_gather::DEFAULT_RINGS;
use crate::methods::splat::Merge;
use crate::timing::{RunTimes, Warmup};
use dof_shaders::lens::ThinLens;
use std::collections::BTreeMap;

/// What every method may use: the scene's multi-layer image and its front layer, and the lens.
/// The images cover the frame and `margin` pixels of guard band on every side; a method's output
/// is cut to the frame with [`MethodInput::crop`].
pub struct MethodInput {
    pub front: RgbImage,
    pub depth: Vec<f32>,
    pub layers: LayeredImage,
    pub lens: ThinLens,
    pub margin: u32,
}

impl MethodInput {
    pub fn new(layers: LayeredImage, lens: ThinLens, margin: u32) -> Self {
        let (front, depth) = layers.front();
        MethodInput { front, depth, layers, lens, margin }
    }

    /// A method's output cut to the frame.
    pub fn crop(&self, image: &RgbImage) -> RgbImage {
        image.crop(self.margin)
    }
}

/// One quality setting of a method (its knob and value), as the report names it.
#[derive(Clone, Debug, PartialEq)]
pub struct Setting {
    pub label: String,
    pub value: Option<u32>,
}

pub struct MethodOutput {
    pub image: RgbImage,
    /// One entry per recorded command, labelled by stage.
    pub stages: Vec<CommandTime>,
    /// Method-specific figures for the report (list lengths, fragments, buffer bytes, ...), by name.
    pub figures: BTreeMap<String, f64>,
    /// Tiles per list-length bucket `(upper bound, tiles)` (Franke et al. 2018, Fig. 12); empty for methods
    /// without tile lists.
    pub list_histogram: Vec<(u32, u32)>,
}

pub trait EvaluatedMethod {
    fn name(&self) -> &'static str;
    /// Whether the method runs kernels (and so is timed per backend) or is host-only.
    fn uses_backend(&self) -> bool;
    /// The quality settings to sweep; `quick` keeps one or two.
    fn settings(&self, quick: bool) -> Vec<Setting>;
    /// The setting timed in the max-CoC sweep (Franke et al. 2018, Fig. 13); `None` keeps the method out of it.
    fn sweep_setting(&self) -> Option<Setting> {
        None
    }
    fn run(&self, backend: &mut dyn Backend, input: &MethodInput, setting: &Setting) -> Result<MethodOutput>;
    /// A warm-up run, then `runs` timed runs: their times and the last run's output.
    fn timed(&self, backend: &mut dyn Backend, input: &MethodInput, setting: &Setting, runs: usize) -> Result<(RunTimes, MethodOutput)> {
        let mut times = RunTimes::default();
        let mut output = self.run(backend, input, setting)?;
        for _ in 0..runs {
            output = self.run(backend, input, setting)?;
            times.add(&output.stages);
        }
        Ok((times, output))
    }
}

/// The unblurred image: the front layer (what a pinhole camera sees). The floor every method must beat.
pub struct Pinhole;

impl EvaluatedMethod for Pinhole {
    fn name(&self) -> &'static str {
        "pinhole"
    }
    fn uses_backend(&self) -> bool {
        false
    }
    fn settings(&self, _quick: bool) -> Vec<Setting> {
        vec![Setting { label: "-".into(), value: None }]
    }
    fn run(&self, _backend: &mut dyn Backend, input: &MethodInput, _setting: &Setting) -> Result<MethodOutput> {
        Ok(MethodOutput { image: input.front.clone(), stages: Vec::new(), figures: BTreeMap::new(), list_histogram: Vec::new() })
    }
}

/// The splatting settings the evaluation sweeps: merge level and tile size. The tile sweep runs
/// merged, where lists are short (unmerged 32-pixel tiles take over 10 s a run on lavapipe), and
/// for the multi-layer method only.
pub const SPLAT_POINTS: [(Merge, u32); 5] = [(Merge::None, 16), (Merge::X2, 16), (Merge::X4, 16), (Merge::X4, 24), (Merge::X4, 32)];

/// The layered settings: (cascaded, layers per doubling).
const LAYERED_POINTS: [(bool, u32); 4] = [(true, 1), (true, 2), (false, 1), (false, 2)];

fn setting(label: String, value: u32) -> Setting {
    Setting { label, value: Some(value) }
}

fn splat_setting(index: usize) -> Setting {
    let (merge, tile) = SPLAT_POINTS[index];
    setting(format!("merge={} tile={tile}", merge.name()), index as u32)
}

fn layered_setting(index: usize) -> Setting {
    let (cascaded, per) = LAYERED_POINTS[index];
    setting(format!("{} layers/doubling={per}", if cascaded { "cascaded" } else { "separate" }), index as u32)
}

/// What the evaluation sweeps of one registry method: its settings (`quick` keeps one or two), the
/// one timed in the max-CoC sweep (Franke et al. 2018, Fig. 13), and the options a setting means.
pub struct SweepPoints {
    pub settings: fn(quick: bool) -> Vec<Setting>,
    pub sweep: Option<fn() -> Setting>,
    pub options: fn(&Setting) -> MethodOptions,
}

/// The sweep of the registry method `name`; `None` for a method the evaluation runs once with its
/// defaults. Each entry says why its points were chosen.
pub fn sweep_points(name: &str) -> Option<SweepPoints> {
    let points = match name {
        // The gathering baseline; its knob is the largest CoC radius honoured.
        "gather" => SweepPoints {
            settings: |quick| {
                let radii: &[u32] = if quick { &[1, 4] } else { &[1, 4, MAX_RADIUS] };
                radii.iter().map(|&r| setting(format!("max-radius={r}"), r)).collect()
            },
            sweep: Some(|| setting(format!("max-radius={MAX_RADIUS}"), MAX_RADIUS)),
            options: |s| MethodOptions { gather_max_radius: s.value, ..Default::default() },
        },
        // The engine-grade gather: its knob is the ring count, its default what engines ship.
        "ring-gather" => SweepPoints {
            settings: |quick| {
                let rings: &[u32] = if quick { &[2, DEFAULT_RINGS] } else { &[1, 2, 3, DEFAULT_RINGS, 8] };
                rings.iter().map(|&r| setting(format!("rings={r}"), r)).collect()
            },
            sweep: Some(|| setting(format!("rings={DEFAULT_RINGS}"), DEFAULT_RINGS)),
            options: |s| MethodOptions {
                ring_gather: RingGatherOptions { rings: s.value.unwrap_or(DEFAULT_RINGS), ..Default::default() },
                ..Default::default()
            },
        },
        // Multi-layer splatting: the merge level and the tile size, one of [`SPLAT_POINTS`] (a
        // setting's `value` is its index there), timed merged as a renderer would run it (unmerged
        // lists grow with the square of the CoC).
        "multilayer" => SweepPoints {
            settings: |quick| {
                let points: &[usize] = if quick { &[0, 2] } else { &[0, 1, 2, 3, 4] };
                points.iter().map(|&i| splat_setting(i)).collect()
            },
            sweep: Some(|| splat_setting(2)),
            options: splat_options,
        },
        // Single-layer splatting shares the pipeline; it runs merged only (its unmerged lists cost
        // lavapipe 5.8 s a run on `simple`, like the multi-layer method's, and three minutes of the
        // full evaluation), and stays out of the max-CoC sweep, which times the same pipeline.
        "tiled" => SweepPoints { settings: |_| vec![splat_setting(2)], sweep: None, options: splat_options },
        // Rays per pixel. 64 spp (another 1.5 dB on `simple`, 5 s a run on lavapipe) is left out to
        // keep the full evaluation within 20 minutes on lavapipe.
        "raytrace" => SweepPoints {
            settings: |quick| {
                let spp: &[u32] = if quick { &[4, 16] } else { &[16, 32] };
                spp.iter().map(|&n| setting(format!("spp={n}"), n)).collect()
            },
            sweep: None,
            options: |s| MethodOptions {
                raytrace: RaytraceOptions { spp: s.value.unwrap_or(16), ..Default::default() },
                ..Default::default()
            },
        },
        // Cascaded or one blur per layer, and layers per doubling of the CoC. One layer per
        // doubling costs about as much on these scenes and loses up to 1.3 dB (`columns`); left out
        // to keep the evaluation within 20 minutes on lavapipe.
        "layered" => SweepPoints {
            settings: |_| [1, 3].iter().map(|&i| layered_setting(i)).collect(),
            sweep: Some(|| layered_setting(1)),
            options: |s| {
                let (cascaded, layers_per_doubling) = LAYERED_POINTS[s.value.unwrap_or(1) as usize % LAYERED_POINTS.len()];
                MethodOptions { layered: LayeredOptions { cascaded, layers_per_doubling, ..Default::default() }, ..Default::default() }
            },
        },
        // Bokeh sprites: thresholds of 1 and 8 measured the same on every built-in scene; one
        // keeps the evaluation within 20 minutes. (The default threshold is 1.)
        "bokeh" => {
            SweepPoints { settings: |_| vec![setting("lum-threshold=1".into(), 1)], sweep: None, options: |_| MethodOptions::default() }
        }
        _ => return None,
    };
    Some(points)
}

fn splat_options(s: &Setting) -> MethodOptions {
    let (merge, tile) = SPLAT_POINTS[s.value.unwrap_or(0) as usize % SPLAT_POINTS.len()];
    MethodOptions { splat: SplatOptions { merge, tile, ..Default::default() }, ..Default::default() }
}

/// A registry method, run through the one-shot path ([`one_shot`]) and timed frame after frame through
/// one context ([`Runner::time_frames`]), with the settings of
/// [`sweep_points`]. Its figures are its context's report figures, plus `buffer_bytes` (the
/// context's device bytes with its frame's buffers) and, for the splatting methods, `tile_px` and
/// `merge_steps`.
pub struct Registered(pub &'static MethodInfo);

impl Registered {
    /// The registry method called `name`.
    pub fn named(name: &str) -> Result<Self> {
        Ok(Registered(registry::method(name)?))
    }

    fn options(&self, setting: &Setting) -> MethodOptions {
        sweep_points(self.0.name).map_or_else(MethodOptions::default, |p| (p.options)(setting))
    }
}

impl EvaluatedMethod for Registered {
    fn name(&self) -> &'static str {
        self.0.name
    }
    fn uses_backend(&self) -> bool {
        true
    }
    fn settings(&self, quick: bool) -> Vec<Setting> {
        sweep_points(self.0.name).map_or_else(|| vec![Setting { label: "default".into(), value: None }], |p| (p.settings)(quick))
    }
    fn sweep_setting(&self) -> Option<Setting> {
        sweep_points(self.0.name).and_then(|p| p.sweep).map(|s| s())
    }
    fn run(&self, backend: &mut dyn Backend, input: &MethodInput, setting: &Setting) -> Result<MethodOutput> {
        let options = self.options(setting);
        let out = one_shot(backend, self.0, &options, &input.layers, &input.lens)?;
        Ok(self.output(&options, out))
    }
    /// Frames back to back through one context, as a renderer runs them ([`Runner::time_frames`],
    /// warmed up as [`Warmup::for_backend`] says): one-shot runs with host work between them ran
    /// at lowered GPU clocks.
    fn timed(&self, backend: &mut dyn Backend, input: &MethodInput, setting: &Setting, runs: usize) -> Result<(RunTimes, MethodOutput)> {
        let options = self.options(setting);
        let image = method_input(self.0, &input.layers);
        let mut runner = Runner::new(backend, self.0, &options, &image)?;
        let warmup = Warmup::for_backend(backend.kind());
        let timed = runner.time_frames(backend, &image, &input.lens, warmup, runs.max(1) as u32);
        runner.destroy(backend);
        let t = timed?;
        Ok((t.runs, self.output(&options, t.last)))
    }
}

impl Registered {
    /// The evaluation's output of a frame: its image, commands and report figures, with the
    /// context's bytes and the splatting settings.
    fn output(&self, options: &MethodOptions, out: OneShot) -> MethodOutput {
        let mut figures = out.report.figures;
        figures.insert("buffer_bytes".into(), out.buffer_bytes as f64);
        if self.0.tiles() {
            figures.insert("tile_px".into(), options.splat.tile as f64);
            figures.insert("merge_steps".into(), options.splat.merge.steps() as f64);
        }
        MethodOutput { image: out.image, stages: out.stages, figures, list_histogram: out.report.list_histogram }
    }
}

/// Every method the evaluation runs, in report order: the pinhole image, then the registry's.
pub fn evaluated_methods() -> Vec<Box<dyn EvaluatedMethod>> {
    let registered = METHODS.iter().map(|m| Box::new(Registered(m)) as Box<dyn EvaluatedMethod>);
    std::iter::once(Box::new(Pinhole) as Box<dyn EvaluatedMethod>).chain(registered).collect()
}
