//! A splatting frame's options, and the plan it ran with.

use crate::aperture::ApertureShape;

/// Fragment merging before tiling (Franke et al. 2018, §6.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Merge {
    None,
    X2,
    X4,
}

impl Merge {
    /// 2x2 steps.
    pub fn steps(self) -> u32 {
        match self {
            Merge::None => 0,
            Merge::X2 => 1,
            Merge::X4 => 2,
        }
    }
    pub fn name(self) -> &'static str {
        match self {
            Merge::None => "none",
            Merge::X2 => "2x2",
            Merge::X4 => "4x4",
        }
    }
}

impl std::str::FromStr for Merge {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        match s {
            "none" => Ok(Merge::None),
            "2x2" => Ok(Merge::X2),
            "4x4" => Ok(Merge::X4),
            _ => Err(format!("unknown merge level '{s}': use none, 2x2 or 4x4")),
        }
    }
}

#[derive(Clone, Debug)]
pub struct SplatOptions {
    /// Tile edge in pixels: 16, 24 or 32.
    pub tile: u32,
    pub merge: Merge,
    /// Cap on the CoC radius in pixels (default and upper bound: `MAX_RINGS · tile`).
    pub max_radius: Option<f32>,
    /// Merging: a fragment is out of focus from this CoC radius (px) on.
    pub merge_min_radius: f32,
    /// Merging: largest ratio between the deepest and the nearest of four fragments.
    pub merge_depth_ratio: f32,
    /// Merging: largest colour spread per channel, relative to the channel's value.
    pub merge_color_tol: f32,
    /// Drop fragments inside a merged fragment's umbra (§6.2).
    pub umbra_merge: bool,
    /// The aperture shape (default the circle; see [`crate::aperture`]).
    pub aperture: ApertureShape,
    /// The largest sub-sample grid side of the input footprints frames may have
    /// (`FrameInput::Layers::footprint_side`; 0: none, 1 to 4): the context holds a field a
    /// fragment for them, of 1, 4 or 16 bits (side 1, 2, 3 or 4): at 1920x1080 with 4 layers, 4.1 MB
    /// for side 2, 16.6 MB for 4.
    pub footprint_side: u32,
}

impl Default for SplatOptions {
    fn default() -> Self {
        SplatOptions {
            tile: 16,
            merge: Merge::None,
            max_radius: None,
            merge_min_radius: 1.5,
            merge_depth_ratio: 1.1,
            merge_color_tol: 0.25,
            umbra_merge: true,
            aperture: ApertureShape::circle(),
            footprint_side: 0,
        }
    }
}

/// What a splatting frame ran with, as its report reads it back: its size and tiling from the host,
/// the rest from the device's reduction over the input (see `dof_shaders::splat::plan`). A report,
/// not an input: the frame plans on the device, and [`super::SplatReport::plan`] holds this.
#[derive(Clone, Debug, PartialEq)]
pub struct SplatPlanReport {
    pub width: u32,
    pub height: u32,
    pub layers: u32,
    pub tile: u32,
    pub tiles_x: u32,
    pub tiles_y: u32,
    /// Pixel block of one accumulation workgroup.
    pub block: u32,
    /// Largest CoC radius present in the input (px), and the cap applied.
    pub max_coc_radius: f32,
    pub radius_cap: f32,
    /// Tile rings fragments may reach: from the largest radius present, not the configured maximum.
    pub rings: u32,
    /// 2x2 merging steps the frame ran (merging leaves fragments below the merge radius alone).
    pub merge_steps: u32,
}

impl SplatPlanReport {
    pub fn tiles(&self) -> u32 {
        self.tiles_x * self.tiles_y
    }
}
