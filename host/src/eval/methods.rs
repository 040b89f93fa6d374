//! The methods the evaluation (and `dof stress`) runs: the pinhole image, then every method of the
//! frame API's registry ([`crate::frame::METHODS`]) through the one generic path ([`Runner`]), each
//! with the settings its registry entry names for the evaluation ([`crate::frame::Sweep`]).

use crate::backend::{Backend, CommandTime};
use crate::error::Result;
use crate::frame::registry::{self, METHODS};
use crate::frame::{MethodInfo, MethodOptions};
use crate::layers::{LayeredImage, RgbImage};
use crate::methods::one_shot::{OneShot, Runner, method_input, one_shot};
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

/// One setting of a method, as the report names it: `key=value` pairs of the method's options
/// (its registry entry parses them), `default` for its defaults, `-` for the pinhole.
#[derive(Clone, Debug, PartialEq)]
pub struct Setting {
    pub label: String,
}

impl Setting {
    pub fn new(label: impl Into<String>) -> Self {
        Setting { label: label.into() }
    }
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
        vec![Setting::new("-")]
    }
    fn run(&self, _backend: &mut dyn Backend, input: &MethodInput, _setting: &Setting) -> Result<MethodOutput> {
        Ok(MethodOutput { image: input.front.clone(), stages: Vec::new(), figures: BTreeMap::new(), list_histogram: Vec::new() })
    }
}

/// A registry method, run through the one-shot path ([`one_shot`]) and timed frame after frame through
/// one context ([`Runner::time_frames`]), with the settings of its entry's sweep
/// ([`MethodInfo::sweep`]). Its figures are its context's report figures, plus `buffer_bytes` (the
/// context's device bytes with its frame's buffers) and, for the splatting methods, `tile_px` and
/// `merge_steps`.
pub struct Registered(pub &'static MethodInfo);

impl Registered {
    /// The registry method called `name`.
    pub fn named(name: &str) -> Result<Self> {
        Ok(Registered(registry::method(name)?))
    }

    /// The options a setting means (`default`: the method's defaults).
    pub fn options(&self, setting: &Setting) -> Result<MethodOptions> {
        match setting.label.as_str() {
            "default" => Ok(MethodOptions::default()),
            text => Ok(self.0.parse_options(text)?),
        }
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
        self.0.sweep_points(quick).map(|p| Setting::new(if p.is_empty() { "default" } else { p })).collect()
    }
    fn sweep_setting(&self) -> Option<Setting> {
        let point = self.0.sweep.points.get(self.0.sweep.timed?)?;
        Some(Setting::new(if point.is_empty() { "default" } else { point }))
    }
    fn run(&self, backend: &mut dyn Backend, input: &MethodInput, setting: &Setting) -> Result<MethodOutput> {
        let options = self.options(setting)?;
        let out = one_shot(backend, self.0, &options, &input.layers, &input.lens)?;
        Ok(self.output(&options, out))
    }
    /// Frames back to back through one context, as a renderer runs them ([`Runner::time_frames`],
    /// warmed up as [`Warmup::for_backend`] says): one-shot runs with host work between them ran
    /// at lowered GPU clocks.
    fn timed(&self, backend: &mut dyn Backend, input: &MethodInput, setting: &Setting, runs: usize) -> Result<(RunTimes, MethodOutput)> {
        let options = self.options(setting)?;
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
        let mut figures = out.report.figures();
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
