//! What one splatting frame will do, decided on the host from the input before any kernel runs.

use crate::error::{Error, Result};
use crate::layers::LayeredImage;
use crate::aperture::ApertureShape;
use dof_shaders::lens::ThinLens;
use dof_shaders::half::HALF_MAX;
use dof_shaders::splat::fragment::{MAX_EDGE, extent};
use dof_shaders::splat::{MAX_RINGS, TILE_SIZES};

/// Fragment merging before tiling (seed 000 §6.1).
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
    /// Read back every stage's buffers (for tests and debugging).
    pub keep_intermediates: bool,
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
            keep_intermediates: false,
        }
    }
}

/// The frame's plan.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan {
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
    /// Power of two that brings the brightest colour into the half-float range (1 when it already is).
    pub color_scale: f32,
    /// 2x2 merging steps that run, and why fewer than requested do.
    pub merge_steps: u32,
    pub merge_note: Option<String>,
}

impl Plan {
    pub fn tiles(&self) -> u32 {
        self.tiles_x * self.tiles_y
    }
    /// Cell edge and slots per cell after `steps` merging steps.
    pub fn cells(&self, steps: u32) -> (u32, u32, u32, u32) {
        let edge = 1 << steps;
        (edge, self.layers << (2 * steps), self.width.div_ceil(edge), self.height.div_ceil(edge))
    }
}

/// Checks the input and options and plans the frame.
pub fn plan(image: &LayeredImage, lens: &ThinLens, o: &SplatOptions) -> Result<Plan> {
    let bad = |m: String| Err(Error::InvalidArgument(m));
    if !lens.is_valid() {
        return bad(format!("invalid lens: {lens:?}"));
    }
    if !TILE_SIZES.contains(&o.tile) {
        return bad(format!("tile size {} is not one of {TILE_SIZES:?}", o.tile));
    }
    if !(o.merge_depth_ratio.is_finite() && o.merge_depth_ratio >= 1.0) {
        return bad(format!("merge depth ratio must be a finite number >= 1, got {}", o.merge_depth_ratio));
    }
    if !(o.merge_color_tol.is_finite() && o.merge_color_tol >= 0.0 && o.merge_min_radius.is_finite() && o.merge_min_radius >= 0.0) {
        return bad(format!("merge tolerances must be finite and >= 0 ({} and {})", o.merge_color_tol, o.merge_min_radius));
    }
    let ring_limit = (MAX_RINGS * o.tile) as f32;
    let radius_cap = match o.max_radius {
        Some(r) if !(r.is_finite() && r >= 0.5) => return bad(format!("max CoC radius must be at least 0.5 px, got {r}")),
        Some(r) if r > ring_limit => {
            return bad(format!(
                "a CoC radius cap of {r} px exceeds the {ring_limit} px that {MAX_RINGS} rings of {} px tiles reach: use larger tiles or a smaller cap",
                o.tile
            ));
        }
        Some(r) => r,
        None => ring_limit,
    };
    let (w, h) = (image.width, image.height);
    if w == 0 || h == 0 || image.max_layers == 0 {
        return bad(format!("an empty {w}x{h} image with {} layers", image.max_layers));
    }
    if w > MAX_EDGE || h > MAX_EDGE {
        return Err(Error::TooLarge { what: "image edge for splatting (px)".into(), size: w.max(h) as u64, limit: MAX_EDGE as u64 });
    }
    // The CoC is monotonic on each side of the focus plane: the extremes of depth bound it.
    let mut widest = 0.0f32;
    let mut brightest = 0.0f32;
    for (p, &n) in image.counts.iter().enumerate() {
        let slots = &image.fragments[p * image.max_layers as usize..][..n.min(image.max_layers) as usize];
        if n == 0 {
            widest = widest.max(lens.coc_radius_px(f32::INFINITY));
        }
        for f in slots.iter().filter(|f| f.depth > 0.0 && f.color.iter().all(|c| c.is_finite())) {
            widest = widest.max(lens.coc_radius_px(f.depth));
            brightest = f.color.iter().fold(brightest, |m, c| m.max(c.abs()));
        }
    }
    let mut merge_steps = o.merge.steps();
    let mut merge_note = None;
    if merge_steps > 0 && widest < o.merge_min_radius {
        merge_steps = 0;
        merge_note = Some(format!(
            "merging skipped: the largest CoC radius present ({widest:.2} px) is below the merge threshold ({} px)",
            o.merge_min_radius
        ));
    }
    let needed = (widest + extent(merge_steps)).min(radius_cap);
    let rings = ((needed / o.tile as f32).ceil() as u32).clamp(1, MAX_RINGS);
    Ok(Plan {
        width: w,
        height: h,
        layers: image.max_layers,
        tile: o.tile,
        tiles_x: w.div_ceil(o.tile),
        tiles_y: h.div_ceil(o.tile),
        block: if o.tile == 24 { 12 } else { 16 },
        max_coc_radius: widest,
        radius_cap: radius_cap.min((rings * o.tile) as f32),
        rings,
        color_scale: color_scale(brightest),
        merge_steps,
        merge_note,
    })
}

/// The largest power of two `s <= 1` with `brightest · s` within the half-float range.
pub fn color_scale(brightest: f32) -> f32 {
    let mut s = 1.0f32;
    while brightest * s > HALF_MAX && s > f32::MIN_POSITIVE {
        s *= 0.5;
    }
    s
}
