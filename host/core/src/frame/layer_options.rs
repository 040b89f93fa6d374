//! How a multi-layer image is built: the fragments kept per pixel, the umbra threshold, the
//! disocclusion buffer and the guard band. The renderer's own depth peel ([`super::RendererPeel`])
//! reads these options here; the scenes above the core (analytic ray casting and the mesh peel, in
//! the crate `dof`) read the same ones.

use crate::error::{Error, Result};
use dof_shaders::peel::MAX_GUARD_BAND;

/// How the multi-layer image is built.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LayerOptions {
    /// Fragments kept per pixel at most (L), `>= 1`. Default 4.
    pub max_layers: u32,
    /// Depth peeling only: passes past `max_layers` that composite a translucent stack deeper than
    /// the slots into a pixel's last slot, in depth order (`dof_shaders::peel::target_slot`; the
    /// analytic scenes' ray caster does this without a bound). A pass no pixel needs draws nothing
    /// (decided on the device). Default 4: a stack of up to `max_layers + 4` surfaces keeps all its
    /// light; behind a deeper one black shows through, and `SceneLayers` counts such pixels.
    pub translucent_passes: u32,
    /// Thin layers by the umbra threshold (default on). Off: consecutive hits are all kept.
    pub umbra_threshold: bool,
    /// Keep more than the front fragment only inside the disocclusion buffer (default on). The
    /// statistics of both variants are returned either way.
    pub disocclusion: bool,
    /// Relative depth difference between 4-neighbours that counts as a discontinuity (default 0.05).
    pub edge_depth_ratio: f32,
    /// The margin rendered beyond the frame (default [`GuardBand::Auto`]; the scenes resolve it,
    /// in the guard band module of the crate `dof`). A renderer's own peel renders what its attachments hold.
    pub guard_band: GuardBand,
    /// Sub-samples a pixel (1, 4, 9 or 16, a stratified grid): above 1 each sub-sample's ray (or
    /// peel at sub-sample resolution) gives its own fragment list and `dof_shaders::resolve`
    /// groups them by depth into fragments of partial coverage (area-integrated layers). 1: the
    /// pixel centre's ray alone (point-sampled layers; the default here, while the command line
    /// takes `dof::scene::DEFAULT_SUBSAMPLES`). A renderer's own peel is point-sampled.
    pub subsamples: u32,
    /// With more than one sub-sample, keep each fragment's footprint (which sub-samples saw it:
    /// `dof_shaders::footprint`), so splatting spreads it from there. Default on; off, every
    /// fragment stands for its whole pixel (4 bytes a slot less; what the methods other than
    /// splatting read either way).
    pub footprints: bool,
    /// Meshes only: the most probes a minified texture lookup takes (1 to 64; default 64, the box
    /// filter over the pixel's footprint; 1: one trilinear lookup, a GPU's isotropic filter, which
    /// blurs up to twice as wide). A viewer trades texture accuracy for shading time here; the
    /// accumulation buffer always filters in full.
    pub texture_probes: u32,
}

impl Default for LayerOptions {
    fn default() -> Self {
        LayerOptions {
            max_layers: 4,
            translucent_passes: 4,
            umbra_threshold: true,
            disocclusion: true,
            edge_depth_ratio: 0.05,
            guard_band: GuardBand::Auto,
            subsamples: 1,
            footprints: true,
            texture_probes: dof_shaders::raster::texture::MAX_PROBES,
        }
    }
}

/// How wide a margin the multi-layer image gets beyond the frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GuardBand {
    /// None: the methods see nothing beyond the frame (what an EXR offers).
    Off,
    /// The largest CoC radius that can reach into the frame, up to [`MAX_GUARD_BAND`]
    /// (resolved by the scenes of the crate `dof`).
    Auto,
    /// A fixed margin in pixels (at most [`MAX_GUARD_BAND`]).
    Pixels(u32),
}

impl GuardBand {
    /// The margin in pixels this choice gives, `auto` computing it when asked.
    pub fn resolve(self, auto: impl FnOnce() -> Result<u32>) -> Result<u32> {
        match self {
            GuardBand::Off => Ok(0),
            GuardBand::Auto => auto(),
            GuardBand::Pixels(m) if m <= MAX_GUARD_BAND => Ok(m),
            GuardBand::Pixels(m) => Err(Error::TooLarge { what: "guard band (px)".into(), size: m as u64, limit: MAX_GUARD_BAND as u64 }),
        }
    }
}
