//! `dof view`: an interactive viewer built only on the public frame API. It owns its window,
//! instance, device, swapchain and command buffer (as an integrator's renderer does), wraps its
//! device with `VulkanBackend::from_raw`, and every frame records the depth of field into its own
//! command buffer between `begin_external` and `end_external`, blits the result into the swapchain
//! image, draws the UI over it and presents. One frame is in flight: the only host wait is the
//! fence of the frame before.
//!
//! Modules: [`device`] (instance, device, validation), [`swapchain`] (surface, swapchain, render
//! pass), [`scene`] (the scene source and its multi-layer image), [`methods`] (the frame API's
//! contexts), [`controls`] (camera), [`ui`] (the egui panel), [`frame`] (the event loop and the
//! per-frame recording), [`readback`] (screenshot, error against the reference), [`script`]
//! (scripted changes for tests).

mod controls;
mod device;
mod frame;
mod methods;
mod readback;
mod scene;
mod script;
mod swapchain;
mod ui;

use anyhow::{Context, Result, bail};
use dof::methods::splat::Merge;
use methods::ViewMethod;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct ViewArgs {
    /// A built-in scene name (`dof scenes` lists them), a glTF scene (`.gltf`/`.glb`; both are
    /// rasterised into layers by depth peeling on the viewer's device), or an EXR (RGB+Z or
    /// multi-layer; a still image: needs --focus and --f-number or --aperture-radius).
    #[arg(long, default_value = "simple")]
    pub scene: String,
    /// A method of the frame API (its registry name: multilayer, tiled, gather, ring-gather, bokeh, ...).
    #[arg(long, default_value = "multilayer")]
    pub method: ViewMethod,
    /// Window size in pixels of built-in and glTF scenes (default 320x180; small: on lavapipe,
    /// Mesa's CPU Vulkan, every pixel costs). An EXR opens at its own size; resizing the window
    /// scales it.
    #[arg(long)]
    pub width: Option<u32>,
    #[arg(long)]
    pub height: Option<u32>,
    /// Focus distance in scene units (planar); default the scene's.
    #[arg(long, allow_negative_numbers = true)]
    pub focus: Option<f32>,
    /// Aperture as an f-number...
    #[arg(long, conflicts_with = "aperture_radius", allow_negative_numbers = true)]
    pub f_number: Option<f32>,
    /// ...or as a radius in scene units.
    #[arg(long, allow_negative_numbers = true)]
    pub aperture_radius: Option<f32>,
    /// Aperture blades (3 to 64; 0 is a circle), splatting and bokeh sprites only.
    #[arg(long, default_value_t = 0)]
    pub blades: u32,
    /// Fragment merging before tiling (multilayer and tiled): none, 2x2 or 4x4.
    #[arg(long, default_value = "4x4")]
    pub merge: Merge,
    /// Tile edge in pixels (multilayer and tiled): 16, 24 or 32.
    #[arg(long, default_value_t = 16)]
    pub tile: u32,
    /// Sample rings of the ring gather at half resolution (1 to 8; 5 is what engines ship).
    #[arg(long, default_value_t = dof::methods::ring_gather::DEFAULT_RINGS)]
    pub rings: u32,
    /// glTF scenes: the most probes a minified texture lookup takes, 1 to 64 (64: the box filter
    /// over the pixel's footprint; fewer shade faster and filter less exactly).
    #[arg(long, default_value_t = dof::frame::LayerOptions::default().texture_probes)]
    pub texture_probes: u32,
    /// Render this many frames, then exit (with --screenshot: after writing the last one).
    #[arg(long)]
    pub frames: Option<u32>,
    /// Write the last presented image (read back from the swapchain image) as PNG; needs --frames.
    #[arg(long)]
    pub screenshot: Option<PathBuf>,
    /// The Khronos validation layer with synchronization validation; exits non-zero if it reported
    /// anything (leaks at exit included).
    #[arg(long)]
    pub validation: bool,
    /// Present with FIFO (vsync); by default MAILBOX or IMMEDIATE where offered, so that frame
    /// times are the renderer's.
    #[arg(long)]
    pub vsync: bool,
    /// Exposure multiplier before the tone map (positive): the same tone map, meaning and default
    /// as the PNG preview `dof render` writes (`--exposure` there). The panel has a slider for it
    /// and a switch to the raw linear values, clamped.
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    pub exposure: f32,
    /// Start with the panel hidden (H toggles it).
    #[arg(long)]
    pub hide_ui: bool,
    /// Changes applied one a frame, for tests: `method=NAME`, `resize=WxH`, `focus=D`,
    /// `f-number=N`, `radius=R`, `exposure=E`, `raw-linear` (toggle the tone map off and on), `blades=N`, `merge=none|2x2|4x4`, `tile=N`, `orbit=DEGREES`,
    /// `click=X:Y` (focus on what is under window pixel X,Y), `error` (toggle the error against
    /// the reference), `close` (as closing the window).
    #[arg(long, value_delimiter = ',')]
    pub script: Vec<String>,
    /// Pick the Vulkan device whose name contains this.
    #[arg(long)]
    pub device: Option<String>,
}

/// Largest window or frame edge the viewer accepts.
const MAX_EDGE: u32 = 8192;

impl ViewArgs {
    /// The window size of a built-in or glTF scene.
    pub fn size(&self) -> [u32; 2] {
        [self.width.unwrap_or(320), self.height.unwrap_or(180)]
    }
}

fn check(args: &ViewArgs) -> Result<()> {
    let [width, height] = args.size();
    for (what, v) in [("--width", width), ("--height", height)] {
        if !(16..=MAX_EDGE).contains(&v) {
            bail!("{what} must lie between 16 and {MAX_EDGE} pixels, got {v}");
        }
    }
    if let Some(d) = args.focus.filter(|d| !(*d > 0.0 && d.is_finite())) {
        bail!("--focus must be a positive finite distance, got {d}");
    }
    if let Some(n) = args.f_number.filter(|n| !(*n > 0.0 && n.is_finite())) {
        bail!("--f-number must be a positive finite number, got {n}");
    }
    if let Some(r) = args.aperture_radius.filter(|r| !(*r >= 0.0 && r.is_finite())) {
        bail!("--aperture-radius must be a finite radius of 0 or more, got {r}");
    }
    if !(args.exposure > 0.0 && args.exposure.is_finite()) {
        bail!("--exposure must be a positive number, got {}", args.exposure);
    }
    if args.blades != 0 && !(3..=64).contains(&args.blades) {
        bail!("--blades must be 0 (a circle) or 3 to 64, got {}", args.blades);
    }
    if ![16, 24, 32].contains(&args.tile) {
        bail!("--tile must be 16, 24 or 32, got {}", args.tile);
    }
    if !(1..=dof::methods::ring_gather::MAX_SAMPLE_RINGS).contains(&args.rings) {
        bail!("--rings must be 1 to {}, got {}", dof::methods::ring_gather::MAX_SAMPLE_RINGS, args.rings);
    }
    if args.frames == Some(0) {
        bail!("--frames must be at least 1");
    }
    dof::raster::check_texture_probes(args.texture_probes)?;
    if let Some(path) = &args.screenshot {
        if args.frames.is_none() {
            bail!("--screenshot needs --frames N (the screenshot is of the last of N frames)");
        }
        if path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() != Some("png") {
            bail!("--screenshot must name a .png file, got {}", path.display());
        }
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).with_context(|| format!("cannot create the folder {}", dir.display()))?;
        }
    }
    Ok(())
}

pub fn run(args: &ViewArgs) -> Result<()> {
    check(args)?;
    let steps = script::parse(&args.script)?;
    if let Some(n) = args.frames.filter(|&n| steps.len() > n as usize) {
        bail!(
            "--script has {} steps, one a frame, but --frames {n} ends the run after {n}: give --frames {} or more",
            steps.len(),
            steps.len()
        );
    }
    let aperture = match (args.f_number, args.aperture_radius) {
        (Some(n), _) => Some(dof::scene::Aperture::FNumber(n)),
        (_, Some(r)) => Some(dof::scene::Aperture::Radius(r)),
        _ => None,
    };
    let source = scene::SceneSource::load(&args.scene, args.size(), args.focus, aperture)?;
    if let Some([w, h]) = source.fixed_size().filter(|_| args.width.is_some() || args.height.is_some()) {
        bail!("--width/--height do not apply to an EXR: it opens at its own size ({w}x{h}); resize the window to scale it");
    }
    if let Some([w, h]) = source.fixed_size()
        && (!(16..=MAX_EDGE).contains(&w) || !(16..=MAX_EDGE).contains(&h))
    {
        bail!(
            "--scene {}: the image is {w}x{h} pixels; the viewer shows an EXR at its own size, in a window of 16 to {MAX_EDGE} \
                 pixels an edge (crop or scale the image, or blur it with dof render)",
            args.scene
        );
    }
    frame::run_app(args, source, steps)
}
