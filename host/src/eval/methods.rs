//! The methods the evaluation knows, behind one trait: adding a method means adding it to
//! [`registry`]; the evaluation code itself does not change.

use crate::backend::{Backend, CommandTime};
use crate::error::Result;
use crate::layers::{LayeredImage, RgbImage};
use crate::methods::gather::{MAX_RADIUS, gather};
use dof_shaders::lens::ThinLens;

/// What every method may use: the scene's multi-layer image and its front layer, and the lens.
pub struct MethodInput {
    pub front: RgbImage,
    pub depth: Vec<f32>,
    pub layers: LayeredImage,
    pub lens: ThinLens,
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
}

pub trait Method {
    fn name(&self) -> &'static str;
    /// Whether the method runs kernels (and so is timed per backend) or is host-only.
    fn uses_backend(&self) -> bool;
    /// The quality settings to sweep; `quick` keeps one or two.
    fn settings(&self, quick: bool) -> Vec<Setting>;
    fn run(&self, backend: &mut dyn Backend, input: &MethodInput, setting: &Setting) -> Result<MethodOutput>;
}

/// The unblurred image: the front layer (what a pinhole camera sees). The floor every method must beat.
pub struct Pinhole;

impl Method for Pinhole {
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
        Ok(MethodOutput { image: input.front.clone(), stages: Vec::new() })
    }
}

/// The gathering baseline; its knob is the largest CoC radius honoured.
pub struct Gather;

impl Method for Gather {
    fn name(&self) -> &'static str {
        "gather"
    }
    fn uses_backend(&self) -> bool {
        true
    }
    fn settings(&self, quick: bool) -> Vec<Setting> {
        let radii: &[u32] = if quick { &[1, 4] } else { &[1, 2, 4, 8, 16, MAX_RADIUS] };
        radii.iter().map(|&r| Setting { label: format!("max-radius={r}"), value: Some(r) }).collect()
    }
    fn run(&self, backend: &mut dyn Backend, input: &MethodInput, setting: &Setting) -> Result<MethodOutput> {
        let out = gather(backend, &input.front, &input.depth, &input.lens, setting.value)?;
        Ok(MethodOutput { image: out.image, stages: out.times })
    }
}

/// Every method the evaluation runs, in report order.
pub fn registry() -> Vec<Box<dyn Method>> {
    vec![Box::new(Pinhole), Box::new(Gather)]
}
