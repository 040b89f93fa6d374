//! Every method that records through the frame API, in one table. An entry is all that the rest of
//! the project knows of a method: its name, the paper it comes from, what it reads, its knob, the
//! options it takes with their units, bounds and defaults ([`super::options`]), the column of
//! Franke et al. 2018's Table 1 each of its stages belongs to, the settings the evaluation sweeps,
//! the tolerances the suites hold it to, and how its context is made. The `dof` command (render,
//! eval, stress, soak, bench, view), the Python binding and the fuzz target read [`METHODS`];
//! adding a method is a kernel, a context implementing [`DofContext`] and an entry here.

use super::bokeh::{BokehContext, BokehContextDesc};
use super::context::{DofContext, Extent};
use super::gather::{GatherContext, GatherContextDesc};
use super::layered::{LayeredContext, LayeredContextDesc};
use super::options::{self, MethodOption, MethodOptions, OptionSpec, Value, spec};
use super::raytrace::{RaytraceContext, RaytraceContextDesc};
use super::ring_gather::{DEFAULT_RINGS, MAX_SAMPLE_RINGS, RingGatherContext, RingGatherContextDesc};
use super::scatter_gather::{ScatterGatherContext, ScatterGatherContextDesc};
use super::splat::{SplatContext, SplatContextDesc};
use crate::aperture::parse_aperture;
use crate::backend::Backend;
use crate::error::{Error, Result};

/// Which fragments of a multi-layer input a method reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reads {
    /// Every fragment slot of every pixel.
    AllLayers,
    /// The front fragment of each pixel. A context handed several slots reads the front one
    /// (the gathers) or treats the input as given (tiled splatting is multi-layer splatting of a
    /// one-layer input: callers hand it the front layer).
    FrontLayer,
}

/// A quality setting that changes between frames without a new context
/// ([`DofContext::set_knob`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Knob {
    /// The flag and script name (`rings`).
    pub name: &'static str,
    pub min: u32,
    pub max: u32,
    /// Fixed before any comparison was run.
    pub default: u32,
}

/// What a context is created for, whatever its method.
#[derive(Clone, Debug)]
pub struct ContextDesc {
    pub extent: Extent,
    pub options: MethodOptions,
    /// Hold the buffers that image inputs and outputs go through ([`super::FrameInput::Images`],
    /// [`super::FrameOutput::Image`]).
    pub image_io: bool,
    /// Frames in flight the context serves, 1 to [`super::MAX_FRAMES_IN_FLIGHT`] (default 1): it
    /// keeps that many copies of what its report reads ([`DofContext::report_frame`]).
    pub frames_in_flight: u32,
}

impl ContextDesc {
    pub fn new(extent: Extent, options: MethodOptions) -> Self {
        ContextDesc { extent, options, image_io: false, frames_in_flight: 1 }
    }
}

/// The column of Franke et al. 2018, Table 1, that a stage's time is reported in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Column {
    /// Input preparation: packing and merging, a hierarchy, mattes, detection.
    Merge,
    /// Tile lists: counts, compaction, allocation, binning and their scans.
    Splat,
    Sort,
    /// What makes the image: accumulation, gathers, tracing, blurs and composition, sprites.
    Apply,
}

impl Column {
    /// The column's name in reports.
    pub fn name(self) -> &'static str {
        match self {
            Column::Merge => "merge",
            Column::Splat => "splat",
            Column::Sort => "sort",
            Column::Apply => "apply",
        }
    }
}

/// The commands whose label starts with `prefix` (a stage, such as `splat/accumulate`), and the
/// column they are reported in. A method's stages are matched in order, the first match wins.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stage {
    pub prefix: &'static str,
    pub column: Column,
}

const fn stage(prefix: &'static str, column: Column) -> Stage {
    Stage { prefix, column }
}

/// Converting image input and output, common to every method.
const FRAME_IO: Stage = stage("frame/", Column::Merge);

/// What the evaluation runs of a method: settings written as `key=value` pairs of its options
/// (`merge=4x4 tile=16`; empty: the defaults).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sweep {
    pub points: &'static [&'static str],
    /// The points a full evaluation runs (indices into `points`).
    pub full: &'static [usize],
    /// The points a quick one runs.
    pub quick: &'static [usize],
    /// The point timed in the max-CoC sweep (Franke et al. 2018, Fig. 13); `None` keeps the method
    /// out of it.
    pub timed: Option<usize>,
}

/// What the suites hold a method to (`tests/tests/oracles.rs` states the reasons).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerances {
    /// In focus: the largest difference from the front composite relative to its value (0: bit
    /// for bit).
    pub in_focus: f32,
    /// Energy: the largest relative change of a channel's mean over the window.
    pub energy: f64,
    /// The CPU backend against Vulkan.
    pub vulkan: VulkanTolerance,
}

/// How far Vulkan may be from the CPU: `|vk - cpu| <= rel · scale` for all but `1 / share` of the
/// pixels (every pixel when `share` is 0), where `scale` is `max(|cpu|, floor)`, or the image's
/// peak.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VulkanTolerance {
    pub rel: f32,
    pub scale: Scale,
    pub share: usize,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scale {
    /// `max(|cpu|, floor)`.
    Value(f32),
    /// The CPU image's largest channel value.
    Peak,
}

const fn tolerances(in_focus: f32, energy: f64, rel: f32, floor: f32) -> Tolerances {
    Tolerances { in_focus, energy, vulkan: VulkanTolerance { rel, scale: Scale::Value(floor), share: 0 } }
}

/// How far past the frame a method's blur may reach.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reach {
    /// It caps the blur (a CoC cap, or discs clipped where the layers end): every lens is taken.
    Capped,
    /// It follows rays through the layers, which end at the guard band: a far-field CoC wider
    /// than the band would darken the frame instead of blurring it.
    WithinLayers,
}

/// One method of the frame API.
pub struct MethodInfo {
    /// The name the command line, scripts and reports use.
    pub name: &'static str,
    /// What it is, for people.
    pub title: &'static str,
    /// Where it comes from (authors, year).
    pub paper: &'static str,
    pub reads: Reads,
    pub knob: Option<Knob>,
    /// The options it takes, with their kinds, units, bounds and defaults; it ignores the others.
    pub options: &'static [OptionSpec],
    /// Its stages by label prefix, and their report columns.
    pub stages: &'static [Stage],
    /// The settings the evaluation runs.
    pub sweep: Sweep,
    pub tolerances: Tolerances,
    /// How far past the frame its blur may reach: lenses beyond a [`Reach::WithinLayers`] method's
    /// reach are refused by the command line.
    pub reach: Reach,
    /// Makes its context: checks the options and the extent, allocates every buffer.
    pub create: fn(&mut dyn Backend, &ContextDesc) -> Result<Box<dyn DofContext>>,
}

impl std::fmt::Debug for MethodInfo {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name)
    }
}

impl MethodInfo {
    /// How it takes `option`, if it does.
    pub fn spec(&self, option: MethodOption) -> Option<&'static OptionSpec> {
        self.options.iter().find(|s| s.option == option)
    }

    /// Whether it takes `option`.
    pub fn takes(&self, option: MethodOption) -> bool {
        self.spec(option).is_some()
    }

    /// Whether it draws the aperture's shape (blades, stars, masks).
    pub fn shaped_aperture(&self) -> bool {
        self.takes(MethodOption::Aperture)
    }

    /// Whether it bins fragments into tiles (tile size and merging).
    pub fn tiles(&self) -> bool {
        self.takes(MethodOption::Tile)
    }

    /// Its options from key/value pairs (keys as `max_coc`, `max-coc` or `--max-coc`): refused
    /// where it does not take a key or a value is not of the option's kind or bounds.
    pub fn method_options<K: AsRef<str>>(&self, values: impl IntoIterator<Item = (K, Value)>) -> Result<MethodOptions> {
        options::method_options(self, values)
    }

    /// Its options from `key=value` pairs separated by spaces (`merge=4x4 tile=16`).
    pub fn parse_options(&self, text: &str) -> Result<MethodOptions> {
        self.method_options(options::parse_pairs(text))
    }

    /// The report column of a command labelled `label`; `None` where no stage of its claims it.
    pub fn column(&self, label: &str) -> Option<Column> {
        self.stages.iter().chain([&FRAME_IO]).find(|s| label.starts_with(s.prefix)).map(|s| s.column)
    }

    /// The evaluation's points for a full (`quick` false) or quick run, as `key=value` text.
    pub fn sweep_points(&self, quick: bool) -> impl Iterator<Item = &'static str> + '_ {
        let picked = if quick { self.sweep.quick } else { self.sweep.full };
        picked.iter().filter_map(|&i| self.sweep.points.get(i).copied())
    }
}

impl PartialEq for MethodInfo {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name
    }
}

fn create_splat(b: &mut dyn Backend, d: &ContextDesc, name: &'static str) -> Result<Box<dyn DofContext>> {
    let mut desc = SplatContextDesc::new(d.extent, d.options.splat.clone());
    desc.image_io = d.image_io;
    desc.frames_in_flight = d.frames_in_flight;
    Ok(Box::new(SplatContext::new(b, &desc)?.named(name)))
}

/// The splatting methods' stages: packing and merging prepare the input, the sort has its own
/// column, the accumulation makes the image, and the rest of `splat/` builds the tile lists.
const SPLAT_STAGES: &[Stage] = &[
    stage("splat/pack", Column::Merge),
    stage("splat/merge", Column::Merge),
    stage("sort/", Column::Sort),
    stage("splat/accumulate", Column::Apply),
    stage("splat/", Column::Splat),
    stage("scan/", Column::Splat),
];

/// The splatting methods' options: the CoC cap reaches 6 rings of the largest tiles (radius 192
/// px); a cap beyond the chosen tile's reach is refused by the context.
const SPLAT_OPTIONS: &[OptionSpec] = &[
    spec::TILE,
    spec::MERGE,
    // The radius cap, in px.
    spec::max_coc(1, 384, "what the scene needs, up to the largest", |o, v| {
        o.splat.max_radius = Some(v.count()? as f32 / 2.0);
        Ok(())
    }),
    spec::aperture(|o, v| {
        o.splat.aperture = parse_aperture(v.text()?)?;
        Ok(())
    }),
];

/// The methods of the frame API, in the order reports list them.
pub static METHODS: &[MethodInfo] = &[
    MethodInfo {
        name: "multilayer",
        title: "multi-layer tiled splatting",
        paper: "Franke, Hofmann, Stamminger, Selgrad 2018",
        reads: Reads::AllLayers,
        knob: None,
        options: SPLAT_OPTIONS,
        stages: SPLAT_STAGES,
        // The merge level and the tile size, timed merged as a renderer would run it (unmerged lists
        // grow with the square of the CoC). The tile sweep runs merged, where lists are short
        // (unmerged 32-pixel tiles take over 10 s a run on lavapipe).
        sweep: Sweep {
            points: &["merge=none tile=16", "merge=2x2 tile=16", "merge=4x4 tile=16", "merge=4x4 tile=24", "merge=4x4 tile=32"],
            full: &[0, 1, 2, 3, 4],
            quick: &[0, 2],
            timed: Some(2),
        },
        // Fragments are stored as half floats: a relative rounding up to 2^-11 a value.
        tolerances: tolerances(0.0, 1e-3, 1e-5, 1e-2),
        reach: Reach::Capped,
        create: |b, d| create_splat(b, d, "multilayer"),
    },
    MethodInfo {
        name: "tiled",
        title: "single-layer tiled splatting",
        paper: "Selgrad, Franke, Stamminger 2016",
        reads: Reads::FrontLayer,
        knob: None,
        options: SPLAT_OPTIONS,
        stages: SPLAT_STAGES,
        // Merged only (its unmerged lists cost lavapipe 5.8 s a run on `simple`, like the
        // multi-layer method's), and out of the max-CoC sweep, which times the same pipeline.
        sweep: Sweep { points: &["merge=4x4 tile=16"], full: &[0], quick: &[0], timed: None },
        tolerances: tolerances(0.0, 1e-3, 1e-5, 1e-2),
        reach: Reach::Capped,
        create: |b, d| create_splat(b, d, "tiled"),
    },
    MethodInfo {
        name: "gather",
        title: "the gathering baseline",
        paper: "Riguer, Tatarchuk, Isidoro 2003",
        reads: Reads::FrontLayer,
        knob: None,
        // A whole-pixel radius, rounded up.
        options: &[spec::max_coc(1, 2 * super::gather::MAX_RADIUS, "the largest", |o, v| {
            o.gather_max_radius = Some(v.count()?.div_ceil(2));
            Ok(())
        })],
        stages: &[stage("gather", Column::Apply)],
        // Its knob is the largest CoC honoured: radius 1, 4 and its largest, 48 px.
        sweep: Sweep { points: &["max_coc=2", "max_coc=8", "max_coc=96"], full: &[0, 1, 2], quick: &[0, 1], timed: Some(2) },
        // In focus the pixel's own weight is not a power of two: two roundings.
        tolerances: tolerances(2.4e-7, 1e-5, 1e-5, 1e-3),
        reach: Reach::Capped,
        create: |b, d| {
            let desc = GatherContextDesc {
                max_radius: d.options.gather_max_radius,
                image_io: d.image_io,
                frames_in_flight: d.frames_in_flight,
                ..GatherContextDesc::new(d.extent)
            };
            Ok(Box::new(GatherContext::new(b, &desc)?))
        },
    },
    MethodInfo {
        name: "ring-gather",
        title: "the engine-grade ring gather",
        paper: "after AMD FidelityFX DoF, Unreal Engine's Diaphragm DoF and Jimenez 2014",
        reads: Reads::FrontLayer,
        knob: Some(Knob { name: "rings", min: 1, max: MAX_SAMPLE_RINGS, default: DEFAULT_RINGS }),
        options: &[
            spec::max_coc(1, 2 * super::ring_gather::MAX_RADIUS, "128", |o, v| {
                o.ring_gather.max_radius = v.count()?.div_ceil(2);
                Ok(())
            }),
            spec::rings(super::ring_gather::MAX_SAMPLE_RINGS, "5", "sample rings at half resolution", |o, v| {
                o.ring_gather.rings = v.count()?;
                Ok(())
            }),
        ],
        stages: &[stage("ring-gather", Column::Apply)],
        // The ring count, timed at its default, what engines ship.
        sweep: Sweep {
            points: &["rings=1", "rings=2", "rings=3", "rings=5", "rings=8"],
            full: &[0, 1, 2, 3, 4],
            quick: &[1, 3],
            timed: Some(3),
        },
        tolerances: tolerances(0.0, 1e-5, 1e-4, 1e-2),
        reach: Reach::Capped,
        create: |b, d| {
            let desc = RingGatherContextDesc {
                options: d.options.ring_gather,
                image_io: d.image_io,
                frames_in_flight: d.frames_in_flight,
                ..RingGatherContextDesc::new(d.extent)
            };
            Ok(Box::new(RingGatherContext::new(b, &desc)?))
        },
    },
    MethodInfo {
        name: "bokeh",
        title: "bokeh sprites over a gather",
        paper: "de Rousiers 2012; Pettineo 2012",
        reads: Reads::FrontLayer,
        knob: None,
        options: &[
            spec::aperture(|o, v| {
                o.bokeh.aperture = parse_aperture(v.text()?)?;
                Ok(())
            }),
            spec::LUM_THRESHOLD,
            spec::SPRITES,
        ],
        // Detection prepares the input, the sprites' compaction is a list's scan, the gather under
        // them and their draw make the image.
        stages: &[
            stage("bokeh/detect", Column::Merge),
            stage("scan/", Column::Splat),
            stage("bokeh/", Column::Apply),
            stage("gather", Column::Apply),
        ],
        // Thresholds of 1 and 8 measured the same on every built-in scene: the default, once.
        sweep: Sweep { points: &["lum_threshold=1"], full: &[0], quick: &[0], timed: None },
        // The sprite rasteriser interpolates what the CPU fallback computes.
        tolerances: Tolerances { in_focus: 2.4e-7, energy: 1e-5, vulkan: VulkanTolerance { rel: 1e-4, scale: Scale::Peak, share: 0 } },
        reach: Reach::Capped,
        create: |b, d| {
            let desc = BokehContextDesc {
                image_io: d.image_io,
                frames_in_flight: d.frames_in_flight,
                ..BokehContextDesc::new(d.extent, d.options.bokeh.clone())
            };
            Ok(Box::new(BokehContext::new(b, &desc)?))
        },
    },
    MethodInfo {
        name: "raytrace",
        title: "ray tracing through the layers",
        paper: "Lee, Eisemann, Seidel 2010",
        reads: Reads::AllLayers,
        knob: None,
        options: &[spec::SAMPLES],
        stages: &[stage("raytrace/hierarchy", Column::Merge), stage("raytrace/", Column::Apply)],
        // Rays per pixel. 64 is left out to keep the full evaluation short on lavapipe.
        sweep: Sweep { points: &["samples=4", "samples=16", "samples=32"], full: &[1, 2], quick: &[0, 1], timed: None },
        // A ray grazing a pixel corner may go either way: one pixel in 200 may differ.
        tolerances: Tolerances { in_focus: 0.0, energy: 1e-5, vulkan: VulkanTolerance { rel: 1e-5, scale: Scale::Value(1.0), share: 200 } },
        reach: Reach::WithinLayers,
        create: |b, d| {
            let desc = RaytraceContextDesc {
                image_io: d.image_io,
                frames_in_flight: d.frames_in_flight,
                ..RaytraceContextDesc::new(d.extent, d.options.raytrace.clone())
            };
            Ok(Box::new(RaytraceContext::new(b, &desc)?))
        },
    },
    MethodInfo {
        name: "layered",
        title: "layered DoF with matting",
        paper: "Schedl, Wimmer 2012",
        reads: Reads::AllLayers,
        knob: None,
        // The largest layer's CoC is the diameter itself.
        options: &[
            spec::max_coc(2, 1024, "256", |o, v| {
                o.layered.max_coc = v.count()? as f32;
                Ok(())
            }),
            spec::NO_CASCADE,
            spec::LAYERS_PER_DOUBLING,
        ],
        stages: &[stage("layered/matte", Column::Merge), stage("layered/", Column::Apply)],
        // Cascaded or one blur per layer, at two layers per doubling of the CoC (one per doubling
        // costs about as much and loses accuracy; left out to keep the evaluation short).
        sweep: Sweep {
            points: &["layers_per_doubling=2", "no_cascade=true layers_per_doubling=2"],
            full: &[0, 1],
            quick: &[0, 1],
            timed: Some(0),
        },
        tolerances: tolerances(0.0, 1e-5, 1e-5, 1.0),
        reach: Reach::Capped,
        create: |b, d| {
            let desc = LayeredContextDesc {
                image_io: d.image_io,
                frames_in_flight: d.frames_in_flight,
                ..LayeredContextDesc::new(d.extent, d.options.layered.clone())
            };
            Ok(Box::new(LayeredContext::new(b, &desc)?))
        },
    },
    MethodInfo {
        name: "scatter-gather",
        title: "scatter-as-you-gather with tile depth separation",
        paper: "Jimenez 2014",
        reads: Reads::FrontLayer,
        knob: None,
        options: &[
            spec::max_coc(1, 2 * super::scatter_gather::MAX_RADIUS, "64", |o, v| {
                o.scatter_gather.max_radius = v.count()?.div_ceil(2);
                Ok(())
            }),
            spec::rings(super::scatter_gather::MAX_RINGS, "3", "sample rings around the pixel", |o, v| {
                o.scatter_gather.rings = v.count()?;
                Ok(())
            }),
        ],
        stages: &[stage("scatter-gather", Column::Apply)],
        // Its default cap (radius 32 px) and the ring gather's (64 px), where its 49 samples thin.
        sweep: Sweep { points: &["max_coc=64", "max_coc=128"], full: &[0, 1], quick: &[0], timed: Some(0) },
        // In focus a tile under half a pixel is copied; on lavapipe Vulkan equals the CPU bit for bit.
        tolerances: tolerances(0.0, 1e-5, 0.0, 1.0),
        reach: Reach::Capped,
        create: |b, d| {
            let desc = ScatterGatherContextDesc {
                options: d.options.scatter_gather,
                image_io: d.image_io,
                frames_in_flight: d.frames_in_flight,
                ..ScatterGatherContextDesc::new(d.extent)
            };
            Ok(Box::new(ScatterGatherContext::new(b, &desc)?))
        },
    },
];

/// The method called `name`; the error lists the names there are.
pub fn method(name: &str) -> Result<&'static MethodInfo> {
    METHODS.iter().find(|m| m.name == name).ok_or_else(|| {
        let names: Vec<&str> = METHODS.iter().map(|m| m.name).collect();
        Error::InvalidArgument(format!("unknown method '{name}': the frame API has {}", names.join(", ")))
    })
}

/// Makes a context of `method` (a convenience for `(method.create)(backend, desc)`).
pub fn create(backend: &mut dyn Backend, method: &MethodInfo, desc: &ContextDesc) -> Result<Box<dyn DofContext>> {
    (method.create)(backend, desc)
}
