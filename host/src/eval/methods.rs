//! The methods the evaluation knows (each with its sweep of settings), behind one trait
//! ([`EvaluatedMethod`], not to be confused with the frame API's `frame::MethodInfo`): adding one means adding it to
//! [`evaluated_methods`]; the evaluation code itself does not change.

use crate::backend::{Backend, CommandTime};
use crate::error::Result;
use crate::layers::{LayeredImage, RgbImage};
use crate::methods::bokeh::{BokehOptions, bokeh};
use crate::methods::gather::{MAX_RADIUS, gather};
use crate::methods::layered::{LayeredOptions, layered};
use crate::methods::raytrace::{RaytraceOptions, raytrace};
use crate::methods::ring_gather::{DEFAULT_RINGS, RingGatherOptions, ring_gather};
use crate::methods::splat::{Merge, SplatOptions, splat};
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

fn radius_setting(r: u32) -> Setting {
    Setting { label: format!("max-radius={r}"), value: Some(r) }
}

/// The gathering baseline; its knob is the largest CoC radius honoured.
pub struct Gather;

impl EvaluatedMethod for Gather {
    fn name(&self) -> &'static str {
        "gather"
    }
    fn uses_backend(&self) -> bool {
        true
    }
    fn settings(&self, quick: bool) -> Vec<Setting> {
        let radii: &[u32] = if quick { &[1, 4] } else { &[1, 4, MAX_RADIUS] };
        radii.iter().map(|&r| radius_setting(r)).collect()
    }
    fn sweep_setting(&self) -> Option<Setting> {
        Some(radius_setting(MAX_RADIUS))
    }
    fn run(&self, backend: &mut dyn Backend, input: &MethodInput, setting: &Setting) -> Result<MethodOutput> {
        let out = gather(backend, &input.front, &input.depth, &input.lens, setting.value)?;
        let figures = BTreeMap::from([("radius_px".to_string(), out.radius as f64), ("buffer_bytes".to_string(), out.buffer_bytes as f64)]);
        Ok(MethodOutput { image: out.image, stages: out.times, figures, list_histogram: Vec::new() })
    }
}

fn rings_setting(rings: u32) -> Setting {
    Setting { label: format!("rings={rings}"), value: Some(rings) }
}

/// The engine-grade gather (after AMD FidelityFX DoF, Unreal Engine's Diaphragm DoF and Jimenez
/// 2014); its knob is the ring count, its default what engines ship ([`DEFAULT_RINGS`]).
pub struct RingGather;

impl EvaluatedMethod for RingGather {
    fn name(&self) -> &'static str {
        "ring-gather"
    }
    fn uses_backend(&self) -> bool {
        true
    }
    fn settings(&self, quick: bool) -> Vec<Setting> {
        let rings: &[u32] = if quick { &[2, DEFAULT_RINGS] } else { &[1, 2, 3, DEFAULT_RINGS, 8] };
        rings.iter().map(|&r| rings_setting(r)).collect()
    }
    fn sweep_setting(&self) -> Option<Setting> {
        Some(rings_setting(DEFAULT_RINGS))
    }
    fn run(&self, backend: &mut dyn Backend, input: &MethodInput, setting: &Setting) -> Result<MethodOutput> {
        let options = RingGatherOptions { rings: setting.value.unwrap_or(DEFAULT_RINGS), ..Default::default() };
        let out = ring_gather(backend, &input.front, &input.depth, &input.lens, &options)?;
        let figures = BTreeMap::from([
            ("samples_per_half_pixel".to_string(), out.samples as f64),
            ("buffer_bytes".to_string(), out.buffer_bytes as f64),
        ]);
        Ok(MethodOutput { image: out.image, stages: out.times, figures, list_histogram: Vec::new() })
    }
}

/// The splatting settings the evaluation sweeps: merge level and tile size. The tile sweep runs
/// merged, where lists are short (unmerged 32-pixel tiles take over 10 s a run on lavapipe), and
/// for the multi-layer method only.
pub const SPLAT_POINTS: [(Merge, u32); 5] = [(Merge::None, 16), (Merge::X2, 16), (Merge::X4, 16), (Merge::X4, 24), (Merge::X4, 32)];

fn splat_setting(index: usize) -> Setting {
    let (merge, tile) = SPLAT_POINTS[index];
    Setting { label: format!("merge={} tile={tile}", merge.name()), value: Some(index as u32) }
}

/// Tiled splatting: single-layer (`tiled`, Selgrad, Franke, Stamminger 2016) on the front layer or
/// multi-layer (`multilayer`, Franke, Hofmann, Stamminger, Selgrad 2018); the knobs are the merge level and the tile size, one of
/// [`SPLAT_POINTS`] (a setting's `value` is its index there).
pub struct Splat {
    pub multi_layer: bool,
}

impl EvaluatedMethod for Splat {
    fn name(&self) -> &'static str {
        if self.multi_layer { "multilayer" } else { "tiled" }
    }
    fn uses_backend(&self) -> bool {
        true
    }
    fn settings(&self, quick: bool) -> Vec<Setting> {
        // Single-layer splatting shares the pipeline; it runs merged only (its unmerged lists cost
        // lavapipe 5.8 s a run on `simple`, like the multi-layer method's, and three minutes of the
        // full evaluation), the merge and tile sweeps are the multi-layer method's.
        let points: &[usize] = if !self.multi_layer {
            &[2]
        } else if quick {
            &[0, 2]
        } else {
            &[0, 1, 2, 3, 4]
        };
        points.iter().map(|&i| splat_setting(i)).collect()
    }
    /// The multi-layer method, merged as a renderer would run it (unmerged lists grow with the
    /// square of the CoC); single-layer splatting costs the same pipeline and is left out.
    fn sweep_setting(&self) -> Option<Setting> {
        self.multi_layer.then(|| splat_setting(2))
    }
    fn run(&self, backend: &mut dyn Backend, input: &MethodInput, setting: &Setting) -> Result<MethodOutput> {
        let (merge, tile) = SPLAT_POINTS[setting.value.unwrap_or(0) as usize % SPLAT_POINTS.len()];
        let options = SplatOptions { merge, tile, ..Default::default() };
        let layers = if self.multi_layer { input.layers.clone() } else { input.layers.front_layer() };
        let out = splat(backend, &layers, &input.lens, &options)?;
        let r = &out.report;
        let figures = BTreeMap::from([
            ("mean_list_length".to_string(), r.mean_list_length()),
            ("max_list_length".to_string(), r.max_list_length() as f64),
            ("fragments".to_string(), r.fragments as f64),
            ("copied_tiles".to_string(), r.copy_tiles as f64),
            ("rings".to_string(), r.plan.as_ref().map_or(0.0, |p| p.rings as f64)),
            ("buffer_bytes".to_string(), r.buffer_bytes as f64),
            ("tile_px".to_string(), tile as f64),
            ("merge_steps".to_string(), merge.steps() as f64),
        ]);
        Ok(MethodOutput { image: out.image, stages: out.stages, figures, list_histogram: r.list_histogram() })
    }
}

/// Thin-lens ray tracing through the multi-layer image; the knob is rays per pixel.
pub struct Raytrace;

impl EvaluatedMethod for Raytrace {
    fn name(&self) -> &'static str {
        "raytrace"
    }
    fn uses_backend(&self) -> bool {
        true
    }
    fn settings(&self, quick: bool) -> Vec<Setting> {
        // 64 spp (another 1.5 dB on `simple`, 5 s a run on lavapipe) is left out to keep the full
        // evaluation within 20 minutes on lavapipe.
        let spp: &[u32] = if quick { &[4, 16] } else { &[16, 32] };
        spp.iter().map(|&n| Setting { label: format!("spp={n}"), value: Some(n) }).collect()
    }
    fn run(&self, backend: &mut dyn Backend, input: &MethodInput, setting: &Setting) -> Result<MethodOutput> {
        let options = RaytraceOptions { spp: setting.value.unwrap_or(16), ..Default::default() };
        let out = raytrace(backend, &input.layers, &input.lens, &options)?;
        let figures = BTreeMap::from([
            ("missed_ray_share".to_string(), out.missed_rays as f64 / out.rays.max(1) as f64),
            ("hierarchy_levels".to_string(), out.levels as f64),
            ("buffer_bytes".to_string(), out.buffer_bytes as f64),
        ]);
        Ok(MethodOutput { image: out.image, stages: out.times, figures, list_histogram: Vec::new() })
    }
}

/// Layered DoF with matting (Schedl, Wimmer 2012); the knobs are the blur (cascaded or one per layer) and the
/// layers per doubling of the CoC.
pub struct Layered;

/// The layered settings: (cascaded, layers per doubling).
const LAYERED_POINTS: [(bool, u32); 4] = [(true, 1), (true, 2), (false, 1), (false, 2)];

fn layered_setting(index: usize) -> Setting {
    let (cascaded, per) = LAYERED_POINTS[index];
    Setting { label: format!("{} layers/doubling={per}", if cascaded { "cascaded" } else { "separate" }), value: Some(index as u32) }
}

impl EvaluatedMethod for Layered {
    fn name(&self) -> &'static str {
        "layered"
    }
    fn uses_backend(&self) -> bool {
        true
    }
    fn settings(&self, _quick: bool) -> Vec<Setting> {
        // One layer per doubling costs about as much on these scenes and loses up to 1.3 dB
        // (`columns`); left out of the evaluation to keep it within 20 minutes on lavapipe.
        [1, 3].iter().map(|&i| layered_setting(i)).collect()
    }
    fn sweep_setting(&self) -> Option<Setting> {
        Some(layered_setting(1))
    }
    fn run(&self, backend: &mut dyn Backend, input: &MethodInput, setting: &Setting) -> Result<MethodOutput> {
        let (cascaded, layers_per_doubling) = LAYERED_POINTS[setting.value.unwrap_or(1) as usize % LAYERED_POINTS.len()];
        let options = LayeredOptions { cascaded, layers_per_doubling, ..Default::default() };
        let out = layered(backend, &input.layers, &input.lens, &options)?;
        let figures = BTreeMap::from([
            ("layers".to_string(), out.plan.cocs.len() as f64),
            ("layers_used".to_string(), out.plan.used_layers() as f64),
            ("blurs".to_string(), out.blurs as f64),
            ("widest_blur_radius".to_string(), out.widest_radius as f64),
            ("buffer_bytes".to_string(), out.buffer_bytes as f64),
        ]);
        Ok(MethodOutput { image: out.image, stages: out.times, figures, list_histogram: Vec::new() })
    }
}

/// Bokeh sprites over a gather (de Rousiers, Pettineo 2012); the knob is the luminance threshold.
pub struct Bokeh;

impl EvaluatedMethod for Bokeh {
    fn name(&self) -> &'static str {
        "bokeh"
    }
    fn uses_backend(&self) -> bool {
        true
    }
    fn settings(&self, _quick: bool) -> Vec<Setting> {
        // Thresholds of 1 and 8 measured the same on every built-in scene; one keeps the evaluation
        // within 20 minutes.
        vec![Setting { label: "lum-threshold=1".into(), value: Some(1) }]
    }
    fn run(&self, backend: &mut dyn Backend, input: &MethodInput, setting: &Setting) -> Result<MethodOutput> {
        let options = BokehOptions { lum_threshold: setting.value.unwrap_or(1) as f32, ..Default::default() };
        let out = bokeh(backend, &input.front, &input.depth, &input.lens, &options)?;
        let figures = BTreeMap::from([
            ("sprites".to_string(), (out.detected - out.overflow) as f64),
            ("sprites_over_capacity".to_string(), out.overflow as f64),
            ("radius_px".to_string(), out.blur_radius as f64),
            ("buffer_bytes".to_string(), out.buffer_bytes as f64),
        ]);
        Ok(MethodOutput { image: out.image, stages: out.times, figures, list_histogram: Vec::new() })
    }
}

/// Every method the evaluation runs, in report order.
pub fn evaluated_methods() -> Vec<Box<dyn EvaluatedMethod>> {
    vec![
        Box::new(Pinhole),
        Box::new(Gather),
        Box::new(RingGather),
        Box::new(Bokeh),
        Box::new(Splat { multi_layer: false }),
        Box::new(Splat { multi_layer: true }),
        Box::new(Layered),
        Box::new(Raytrace),
    ]
}
