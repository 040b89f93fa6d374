//! The options of the registry's methods as one schema: each [`MethodOption`] has a name (the
//! command line's flag, the bindings' keyword), and each method's entry lists the ones it takes as
//! [`OptionSpec`]s, with their kind, unit, bounds and default. The command line, the Python
//! binding, the viewer, the soak and the evaluation hand key/value pairs to
//! [`super::MethodInfo::method_options`], which refuses what the method does not take or what lies
//! out of bounds, and makes the [`MethodOptions`] every context reads its own part of.

use super::bokeh::BokehOptions;
use super::layered::LayeredOptions;
use super::raytrace::{MAX_SPP, RaytraceOptions};
use super::ring_gather::RingGatherOptions;
use super::scatter_gather::ScatterGatherOptions;
use super::splat::{Merge, SplatOptions};
use crate::aperture::parse_aperture;
use crate::error::{Error, Result};

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
    /// Scatter-as-you-gather (rings, radius cap).
    pub scatter_gather: ScatterGatherOptions,
}

/// A setting that some methods take and others would ignore. Each method's entry lists those it
/// takes ([`super::MethodInfo::options`]), with their bounds, so the command line and the bindings
/// refuse the others rather than ignore them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum MethodOption {
    /// Tile edge of the splatting methods.
    Tile,
    /// Fragment merging of the splatting methods.
    Merge,
    /// A cap on the CoC, as a diameter in pixels, for every method that takes one.
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

    /// The keyword of the bindings and of `key=value` settings (`max_coc`): the flag in snake case.
    pub fn key(self) -> String {
        self.flag().trim_start_matches("--").replace('-', "_")
    }

    /// The option a keyword or flag names (`max_coc`, `max-coc` or `--max-coc`; `spp` is
    /// `samples`).
    pub fn from_key(key: &str) -> Option<MethodOption> {
        let key = key.trim_start_matches("--").replace('-', "_");
        let key = if key == "spp" { "samples" } else { key.as_str() };
        MethodOption::ALL.into_iter().find(|o| o.key() == key)
    }

    /// The names of the registered methods that take it, for messages (`multilayer, tiled`).
    pub fn methods(self) -> String {
        super::METHODS.iter().filter(|m| m.takes(self)).map(|m| m.name).collect::<Vec<_>>().join(", ")
    }
}

/// What values an option takes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// A whole number in `min..=max`.
    Count { min: u32, max: u32 },
    /// A finite number in `min..=max`.
    Number { min: f32, max: f32 },
    /// On or off (`true` or `false`).
    Flag,
    /// One of these names.
    Choice(&'static [&'static str]),
    /// An aperture: `circle`, `blades:N[:ROT[:CURV]]`, `star:N[:ROT[:INNER]]` or a PNG mask
    /// ([`crate::aperture::parse_aperture`]).
    Aperture,
}

/// One option as a method takes it: its bounds, its default and where its value goes in that
/// method's options (an option several methods take, such as the CoC cap, has each one's own
/// bounds, default and unit).
#[derive(Clone, Copy, Debug)]
pub struct OptionSpec {
    pub option: MethodOption,
    pub kind: Kind,
    /// What a number counts or measures (`px, CoC diameter`); empty for flags and names.
    pub unit: &'static str,
    /// The value when it is not given, as it would be written; for the CoC cap, the method's own
    /// choice in words.
    pub default: &'static str,
    /// One line for help texts.
    pub help: &'static str,
    /// Writes a checked value into the method's own part of [`MethodOptions`].
    pub apply: fn(&mut MethodOptions, &Setting) -> Result<()>,
}

/// A value given for an option, before its kind and bounds are checked.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Int(i64),
    Number(f64),
    Flag(bool),
    Text(String),
}

impl From<u32> for Value {
    fn from(v: u32) -> Self {
        Value::Int(v.into())
    }
}

impl From<f32> for Value {
    fn from(v: f32) -> Self {
        Value::Number(v.into())
    }
}

impl From<bool> for Value {
    fn from(v: bool) -> Self {
        Value::Flag(v)
    }
}

impl From<&str> for Value {
    fn from(v: &str) -> Self {
        Value::Text(v.into())
    }
}

impl std::fmt::Display for Value {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Value::Int(v) => write!(f, "{v}"),
            Value::Number(v) => write!(f, "{v}"),
            Value::Flag(v) => write!(f, "{v}"),
            Value::Text(v) => f.write_str(v),
        }
    }
}

/// A value checked against its option's kind and bounds: what [`OptionSpec::apply`] writes.
#[derive(Clone, Debug, PartialEq)]
pub enum Setting {
    Count(u32),
    Number(f32),
    Flag(bool),
    Text(String),
}

impl Setting {
    fn wrong(&self, kind: &str) -> Error {
        Error::InvalidArgument(format!("{kind} wanted, got {self:?}"))
    }

    pub fn count(&self) -> Result<u32> {
        match self {
            Setting::Count(v) => Ok(*v),
            _ => Err(self.wrong("a whole number")),
        }
    }

    pub fn number(&self) -> Result<f32> {
        match self {
            Setting::Number(v) => Ok(*v),
            _ => Err(self.wrong("a number")),
        }
    }

    pub fn flag(&self) -> Result<bool> {
        match self {
            Setting::Flag(v) => Ok(*v),
            _ => Err(self.wrong("true or false")),
        }
    }

    pub fn text(&self) -> Result<&str> {
        match self {
            Setting::Text(v) => Ok(v),
            _ => Err(self.wrong("a name")),
        }
    }
}

impl OptionSpec {
    /// `value` if it is of this option's kind and within its bounds; the error names the method,
    /// the option, its unit and its bounds.
    /// `key` is the option as the caller named it (`--max-coc`, `max_coc`).
    fn check(&self, method: &str, key: &str, value: &Value) -> Result<Setting> {
        let bad = |what: String| Err(Error::InvalidArgument(format!("option {key} of {method} {what}, got {value}")));
        let unit = if self.unit.is_empty() { String::new() } else { format!(" ({})", self.unit) };
        // A number bounded above only by the largest float is said as "at least".
        let range =
            |min: f32, max: f32| if max == f32::MAX { format!("finite and at least {min}") } else { format!("between {min} and {max}") };
        match (self.kind, value) {
            (Kind::Count { min, max }, Value::Int(v)) => match u32::try_from(*v) {
                Ok(v) if (min..=max).contains(&v) => Ok(Setting::Count(v)),
                _ => bad(format!("must lie between {min} and {max}{unit}")),
            },
            (Kind::Count { min, max }, Value::Text(s)) => match s.trim().parse::<i64>() {
                Ok(v) => self.check(method, key, &Value::Int(v)),
                Err(_) => bad(format!("is a whole number between {min} and {max}{unit}")),
            },
            (Kind::Count { min, max }, _) => bad(format!("is a whole number between {min} and {max}{unit}")),
            (Kind::Number { .. }, Value::Int(v)) => self.check(method, key, &Value::Number(*v as f64)),
            (Kind::Number { min, max }, Value::Number(v)) => {
                let f = *v as f32;
                if f.is_finite() && (min..=max).contains(&f) {
                    Ok(Setting::Number(f))
                } else {
                    bad(format!("must be {}{unit}", range(min, max)))
                }
            }
            (Kind::Number { min, max }, Value::Text(s)) => match s.trim().parse::<f64>() {
                Ok(v) => self.check(method, key, &Value::Number(v)),
                Err(_) => bad(format!("is a number {}{unit}", range(min, max))),
            },
            (Kind::Number { min, max }, _) => bad(format!("is a number {}{unit}", range(min, max))),
            (Kind::Flag, Value::Flag(v)) => Ok(Setting::Flag(*v)),
            (Kind::Flag, Value::Text(s)) if s == "true" || s == "false" => Ok(Setting::Flag(s == "true")),
            (Kind::Flag, _) => bad("is true or false".into()),
            (Kind::Choice(names), Value::Text(s)) if names.contains(&s.as_str()) => Ok(Setting::Text(s.clone())),
            (Kind::Choice(names), _) => bad(format!("is one of {}", names.join(", "))),
            (Kind::Aperture, Value::Text(s)) => {
                parse_aperture(s)?;
                Ok(Setting::Text(s.clone()))
            }
            (Kind::Aperture, _) => bad("is an aperture: circle, blades:N[:ROT[:CURV]], star:N[:ROT[:INNER]] or a PNG".into()),
        }
    }
}

/// The options of `method` from key/value pairs: each key taken by the method and each value of
/// its kind and within its bounds, or an error naming what is wrong (an option another method
/// takes, one no method takes, a value out of bounds with its unit).
pub(super) fn method_options<K: AsRef<str>>(
    method: &super::MethodInfo,
    values: impl IntoIterator<Item = (K, Value)>,
) -> Result<MethodOptions> {
    let mut options = MethodOptions::default();
    for (key, value) in values {
        let key = key.as_ref();
        let Some(option) = MethodOption::from_key(key) else {
            let known: Vec<String> = method.options.iter().map(|s| s.option.key()).collect();
            let known = if known.is_empty() { "no options".to_string() } else { known.join(", ") };
            return Err(Error::InvalidArgument(format!("unknown option '{key}': {} takes {known}", method.name)));
        };
        let Some(spec) = method.spec(option) else {
            return Err(Error::InvalidArgument(format!(
                "option {key} applies to {} only; {} does not take it",
                option.methods(),
                method.name
            )));
        };
        (spec.apply)(&mut options, &spec.check(method.name, key, &value)?)?;
    }
    Ok(options)
}

/// `key=value` pairs separated by spaces (`merge=4x4 tile=16`), as the evaluation's sweep points
/// and scripts write settings; a bare key is a flag set to true.
pub fn parse_pairs(text: &str) -> Vec<(String, Value)> {
    text.split_whitespace()
        .map(|pair| match pair.split_once('=') {
            Some((k, v)) => (k.to_string(), Value::Text(v.to_string())),
            None => (pair.to_string(), Value::Flag(true)),
        })
        .collect()
}

/// The options' specs. Those of one method are constants; those several methods take are made
/// per method, with its bounds, default and the part of [`MethodOptions`] it reads.
pub mod spec {
    use super::*;

    pub const TILE: OptionSpec = OptionSpec {
        option: MethodOption::Tile,
        kind: Kind::Count { min: 16, max: 32 },
        unit: "px, tile edge: 16, 24 or 32",
        default: "16",
        help: "tile edge of the splatting grid",
        apply: |o, v| {
            o.splat.tile = v.count()?;
            Ok(())
        },
    };
    pub const MERGE: OptionSpec = OptionSpec {
        option: MethodOption::Merge,
        kind: Kind::Choice(&["none", "2x2", "4x4"]),
        unit: "",
        default: "none",
        help: "fragment merging before tiling",
        apply: |o, v| {
            o.splat.merge = v.text()?.parse::<Merge>().map_err(Error::InvalidArgument)?;
            Ok(())
        },
    };
    pub const LUM_THRESHOLD: OptionSpec = OptionSpec {
        option: MethodOption::LumThreshold,
        kind: Kind::Number { min: 0.0, max: f32::MAX },
        unit: "luminance",
        default: "1",
        help: "luminance above its neighbours that makes a pixel a sprite",
        apply: |o, v| {
            o.bokeh.lum_threshold = v.number()?;
            Ok(())
        },
    };
    pub const SPRITES: OptionSpec = OptionSpec {
        option: MethodOption::Sprites,
        kind: Kind::Count { min: 1, max: 1 << 20 },
        unit: "sprites",
        default: "4096",
        help: "sprite capacity a frame",
        apply: |o, v| {
            o.bokeh.capacity = v.count()?;
            Ok(())
        },
    };
    pub const SAMPLES: OptionSpec = OptionSpec {
        option: MethodOption::Samples,
        kind: Kind::Count { min: 1, max: MAX_SPP },
        unit: "rays per pixel",
        default: "16",
        help: "rays traced a pixel",
        apply: |o, v| {
            o.raytrace.spp = v.count()?;
            Ok(())
        },
    };
    pub const NO_CASCADE: OptionSpec = OptionSpec {
        option: MethodOption::NoCascade,
        kind: Kind::Flag,
        unit: "",
        default: "false",
        help: "one blur a layer instead of the cascade",
        apply: |o, v| {
            o.layered.cascaded = !v.flag()?;
            Ok(())
        },
    };
    pub const LAYERS_PER_DOUBLING: OptionSpec = OptionSpec {
        option: MethodOption::LayersPerDoubling,
        kind: Kind::Count { min: 1, max: 4 },
        unit: "layers per doubling of the CoC",
        default: "2",
        help: "depth layers per doubling of the CoC",
        apply: |o, v| {
            o.layered.layers_per_doubling = v.count()?;
            Ok(())
        },
    };

    /// The CoC cap of a method honouring diameters from `min` to `max` px, `default` when not
    /// given (a number, or the method's choice in words); `apply` writes it in the method's unit.
    pub const fn max_coc(min: u32, max: u32, default: &'static str, apply: fn(&mut MethodOptions, &Setting) -> Result<()>) -> OptionSpec {
        OptionSpec {
            option: MethodOption::MaxCoc,
            kind: Kind::Count { min, max },
            unit: "px, CoC diameter",
            default,
            help: "largest CoC diameter the method honours",
            apply,
        }
    }

    /// The aperture's shape, for a method that shapes its blur by it.
    pub const fn aperture(apply: fn(&mut MethodOptions, &Setting) -> Result<()>) -> OptionSpec {
        OptionSpec {
            option: MethodOption::Aperture,
            kind: Kind::Aperture,
            unit: "",
            default: "circle",
            help: "aperture shape: circle, blades:N[:ROT[:CURV]], star:N[:ROT[:INNER]] or a PNG mask",
            apply,
        }
    }

    /// Sample rings of a gather, 1 to `max`, `default` when not given.
    pub const fn rings(
        max: u32,
        default: &'static str,
        help: &'static str,
        apply: fn(&mut MethodOptions, &Setting) -> Result<()>,
    ) -> OptionSpec {
        OptionSpec { option: MethodOption::Rings, kind: Kind::Count { min: 1, max }, unit: "rings", default, help, apply }
    }
}
