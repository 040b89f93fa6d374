//! Every method that records through the frame API, in one table: its name, the paper it comes
//! from, what it reads, its quality knob and how its context is made. The `dof` command (render,
//! eval, stress, soak, bench, view) and the fuzz target iterate [`METHODS`]; adding a method is a
//! kernel, a context implementing [`DofContext`] and an entry here.

use super::bokeh::{BokehContext, BokehContextDesc, BokehOptions};
use super::context::{DofContext, Extent};
use super::gather::{GatherContext, GatherContextDesc};
use super::layered::{LayeredContext, LayeredContextDesc, LayeredOptions};
use super::raytrace::{RaytraceContext, RaytraceContextDesc, RaytraceOptions};
use super::ring_gather::{DEFAULT_RINGS, MAX_SAMPLE_RINGS, RingGatherContext, RingGatherContextDesc, RingGatherOptions};
use super::splat::{SplatContext, SplatContextDesc, SplatOptions};
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

/// Every method's options, by method. A context reads its own; the others are ignored.
#[derive(Clone, Debug, Default)]
pub struct MethodOptions {
    /// Tiled splatting, single- and multi-layer (tile, merging, radius cap, aperture shape).
    pub splat: SplatOptions,
    /// The gathering baseline's cap on the CoC radius (px; default and bound
    /// [`super::gather::MAX_RADIUS`]).
    pub gather_max_radius: Option<u32>,
    pub ring_gather: RingGatherOptions,
    pub bokeh: BokehOptions,
    /// Ray tracing through the layers (rays per pixel, sample patterns, seed).
    pub raytrace: RaytraceOptions,
    /// Layered DoF (cascading, layers per doubling, first and largest layer CoC).
    pub layered: LayeredOptions,
}

/// A setting of [`MethodOptions`] that some methods take and others would ignore. Each method's
/// entry lists those it takes ([`MethodInfo::takes`]), so the command line and the bindings refuse
/// the others rather than ignore them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MethodOption {
    /// Tile edge of the splatting methods.
    Tile,
    /// Fragment merging of the splatting methods.
    Merge,
    /// A cap on the CoC (each method's own radius or diameter cap).
    MaxCoc,
    /// The aperture's shape (blades, stars, masks).
    Aperture,
    /// Sample rings of the ring gather.
    Rings,
    /// Luminance that makes a bokeh sprite.
    LumThreshold,
    /// Bokeh sprite capacity.
    Sprites,
    /// Rays per pixel of ray tracing.
    Samples,
    /// Layered DoF with one blur per layer.
    NoCascade,
    /// Layered DoF's layers per doubling of the CoC.
    LayersPerDoubling,
}

impl MethodOption {
    pub const ALL: [MethodOption; 10] = [
        MethodOption::Tile,
        MethodOption::Merge,
        MethodOption::MaxCoc,
        MethodOption::Aperture,
        MethodOption::Rings,
        MethodOption::LumThreshold,
        MethodOption::Sprites,
        MethodOption::Samples,
        MethodOption::NoCascade,
        MethodOption::LayersPerDoubling,
    ];

    /// The command line's flag (`--max-coc`).
    pub fn flag(self) -> &'static str {
        match self {
            MethodOption::Tile => "--tile",
            MethodOption::Merge => "--merge",
            MethodOption::MaxCoc => "--max-coc",
            MethodOption::Aperture => "--aperture",
            MethodOption::Rings => "--rings",
            MethodOption::LumThreshold => "--lum-threshold",
            MethodOption::Sprites => "--sprites",
            MethodOption::Samples => "--samples",
            MethodOption::NoCascade => "--no-cascade",
            MethodOption::LayersPerDoubling => "--layers-per-doubling",
        }
    }

    /// The keyword of the bindings (`max_coc`): the flag in snake case.
    pub fn key(self) -> String {
        self.flag().trim_start_matches("--").replace('-', "_")
    }

    /// The names of the registered methods that take it, for messages (`multilayer, tiled`).
    pub fn methods(self) -> String {
        METHODS.iter().filter(|m| m.takes(self)).map(|m| m.name).collect::<Vec<_>>().join(", ")
    }
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
    /// The settings of [`MethodOptions`] it takes; it ignores the others.
    pub options: &'static [MethodOption],
    /// Makes its context: checks the options and the extent, allocates every buffer.
    pub create: fn(&mut dyn Backend, &ContextDesc) -> Result<Box<dyn DofContext>>,
}

impl std::fmt::Debug for MethodInfo {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name)
    }
}

impl MethodInfo {
    /// Whether it takes `option`.
    pub fn takes(&self, option: MethodOption) -> bool {
        self.options.contains(&option)
    }

    /// Whether it draws the aperture's shape (blades, stars, masks).
    pub fn shaped_aperture(&self) -> bool {
        self.takes(MethodOption::Aperture)
    }

    /// Whether it reads the tile size and merging of [`SplatOptions`].
    pub fn tiles(&self) -> bool {
        self.takes(MethodOption::Tile)
    }
}

impl PartialEq for MethodInfo {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name
    }
}

fn create_splat(b: &mut dyn Backend, d: &ContextDesc, name: &'static str) -> Result<Box<dyn DofContext>> {
    let mut desc = SplatContextDesc::new(d.extent.width, d.extent.height, d.extent.layers, d.options.splat.clone());
    desc.image_io = d.image_io;
    desc.frames_in_flight = d.frames_in_flight;
    Ok(Box::new(SplatContext::new(b, &desc)?.named(name)))
}

/// The methods of the frame API, in the order reports list them.
pub static METHODS: &[MethodInfo] = &[
    MethodInfo {
        name: "multilayer",
        title: "multi-layer tiled splatting",
        paper: "Franke, Hofmann, Stamminger, Selgrad 2018",
        reads: Reads::AllLayers,
        knob: None,
        options: &[MethodOption::Tile, MethodOption::Merge, MethodOption::MaxCoc, MethodOption::Aperture],
        create: |b, d| create_splat(b, d, "multilayer"),
    },
    MethodInfo {
        name: "tiled",
        title: "single-layer tiled splatting",
        paper: "Selgrad, Franke, Stamminger 2016",
        reads: Reads::FrontLayer,
        knob: None,
        options: &[MethodOption::Tile, MethodOption::Merge, MethodOption::MaxCoc, MethodOption::Aperture],
        create: |b, d| create_splat(b, d, "tiled"),
    },
    MethodInfo {
        name: "gather",
        title: "the gathering baseline",
        paper: "Riguer, Tatarchuk, Isidoro 2003",
        reads: Reads::FrontLayer,
        knob: None,
        options: &[MethodOption::MaxCoc],
        create: |b, d| {
            let desc = GatherContextDesc {
                max_radius: d.options.gather_max_radius,
                image_io: d.image_io,
                frames_in_flight: d.frames_in_flight,
                ..GatherContextDesc::new(d.extent.width, d.extent.height, d.extent.layers)
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
        options: &[MethodOption::MaxCoc, MethodOption::Rings],
        create: |b, d| {
            let desc = RingGatherContextDesc {
                options: d.options.ring_gather,
                image_io: d.image_io,
                frames_in_flight: d.frames_in_flight,
                ..RingGatherContextDesc::new(d.extent.width, d.extent.height, d.extent.layers)
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
        options: &[MethodOption::Aperture, MethodOption::LumThreshold, MethodOption::Sprites],
        create: |b, d| {
            let desc = BokehContextDesc {
                image_io: d.image_io,
                frames_in_flight: d.frames_in_flight,
                ..BokehContextDesc::new(d.extent.width, d.extent.height, d.extent.layers, d.options.bokeh.clone())
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
        options: &[MethodOption::Samples],
        create: |b, d| {
            let desc = RaytraceContextDesc {
                image_io: d.image_io,
                frames_in_flight: d.frames_in_flight,
                ..RaytraceContextDesc::new(d.extent.width, d.extent.height, d.extent.layers, d.options.raytrace.clone())
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
        options: &[MethodOption::MaxCoc, MethodOption::NoCascade, MethodOption::LayersPerDoubling],
        create: |b, d| {
            let desc = LayeredContextDesc {
                image_io: d.image_io,
                frames_in_flight: d.frames_in_flight,
                ..LayeredContextDesc::new(d.extent.width, d.extent.height, d.extent.layers, d.options.layered.clone())
            };
            Ok(Box::new(LayeredContext::new(b, &desc)?))
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
