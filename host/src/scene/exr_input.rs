//! An EXR given as a scene: flat layers as stored ([`read_layered_exr`]), or deep files
//! ([`read_deep_exr`]) whose layers depend on the lens ([`DeepImage::layers`]). The command line,
//! its sequences and viewer, and the Python binding read EXR input through this one type.

use std::path::Path;

use super::camera::Camera;
use super::deep_layers::DeepLayersReport;
use crate::deep::DeepImage;
use crate::error::{Error, Result};
use crate::frame::LayerOptions;
use crate::io::{DeepReport, InputReport, is_deep_exr, read_deep_exr, read_layered_exr};
use crate::layers::{LayeredImage, RgbImage};
use dof_shaders::lens::ThinLens;

/// An EXR input, read.
#[derive(Clone, Debug)]
pub enum ExrInput {
    /// RGB+Z or multi-layer: the layers as the file holds them.
    Flat { layers: LayeredImage, report: InputReport },
    /// One or more deep files merged, tidy.
    Deep { image: DeepImage, report: DeepReport },
}

impl ExrInput {
    /// Reads `paths`: one flat EXR, or one or more deep EXR files (merged into one deep image).
    /// Errors when several files are given and one is flat.
    pub fn read<P: AsRef<Path>>(paths: &[P]) -> Result<ExrInput> {
        let Some(first) = paths.first() else { return Err(Error::invalid("no EXR file given".to_string())) };
        if paths.len() == 1 && !is_deep_exr(first)? {
            let (layers, report) = read_layered_exr(first)?;
            return Ok(ExrInput::Flat { layers, report });
        }
        for p in paths {
            if !is_deep_exr(p)? {
                return Err(Error::invalid(format!(
                    "{} is a flat EXR: several EXR files merge only when all are deep (a flat one is read alone)",
                    p.as_ref().display()
                )));
            }
        }
        let (image, report) = read_deep_exr(paths)?;
        Ok(ExrInput::Deep { image, report })
    }

    pub fn is_deep(&self) -> bool {
        matches!(self, ExrInput::Deep { .. })
    }

    /// Where the image lies in the file's pixel space (its data window's corner, the display
    /// window): the result is written with it.
    pub fn window(&self) -> crate::io::ExrWindow {
        match self {
            ExrInput::Flat { report, .. } => report.window,
            ExrInput::Deep { report, .. } => report.window,
        }
    }

    pub fn size(&self) -> (u32, u32) {
        match self {
            ExrInput::Flat { layers, .. } => (layers.width, layers.height),
            ExrInput::Deep { image, .. } => (image.width, image.height),
        }
    }

    /// What reading found worth a note (repairs, channels not read, what tidying changed), if
    /// anything.
    pub fn note(&self) -> Option<String> {
        match self {
            ExrInput::Flat { report, .. } => (report.total() > 0).then(|| report.to_string()),
            ExrInput::Deep { report, .. } => Some(report.to_string()),
        }
    }

    /// The multi-layer image the methods read, for a camera (only its pixel footprints are used)
    /// and `lens`: flat layers as stored; a deep image by [`DeepImage::layers`] with `options`,
    /// and its report.
    pub fn layers(&self, camera: &Camera, lens: &ThinLens, options: &LayerOptions) -> Result<(LayeredImage, Option<DeepLayersReport>)> {
        match self {
            ExrInput::Flat { layers, .. } => Ok((layers.try_clone()?, None)),
            ExrInput::Deep { image, .. } => {
                let (layers, report) = image.layers(&camera.frame()?, lens, options)?;
                Ok((layers, Some(report)))
            }
        }
    }

    /// The in-focus image and the front depth: flat layers composited, a deep image flattened.
    pub fn flattened(&self) -> (RgbImage, Vec<f32>) {
        match self {
            ExrInput::Flat { layers, .. } => layers.front(),
            ExrInput::Deep { image, .. } => image.flatten(),
        }
    }
}
