//! `dof render`: one scene through one method to an EXR (linear HDR, with depth and CoC planes) and a
//! PNG preview beside it.

use anyhow::{Context, bail};
use dof::frame::{METHODS, MethodInfo, MethodOption, MethodOptions, Reach, Value};
use dof::io::{ExrWindow, ExrWriteOptions, write_exr, write_exr_with, write_layered_exr, write_png_preview};
use dof::layers::RgbImage;
use dof::layers::{LayeredImage, crop_plane};
use dof::methods::one_shot::one_shot;
use dof::methods::splat::Merge;
use dof::raster::{AccumulateOptions, DeviceMesh, accumulate_with, check_texture_probes, default_near, peel_layers_with, peel_passes};
use dof::scene::ExrInput;
use dof::scene::{
    self, Aperture, AutoOptions, Camera, Focus, GuardBand, LayerOptions, LensSettings, MAX_GUARD_BAND, MeshScene, ReferenceOptions,
    SceneLayers, Vec3, load_gltf, raycast_layers,
};
use dof_shaders::lens::ThinLens;
use std::path::{Path, PathBuf};

use dof::io::exr_pattern;
mod sequence;

/// What `dof render` makes: the pinhole image, the multi-layer image, a reference, or a frame
/// through any method of the frame API's registry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Method {
    /// The pinhole image (no blur): the front layer.
    Pinhole,
    /// The partial multi-layer image (umbra threshold, disocclusion buffer) as a multi-layer EXR.
    Layers,
    /// The reference: thin-lens distributed ray tracing (built-in scenes), the accumulation buffer
    /// (Haeberli and Akeley 1990; glTF scenes; `--samples` renders, default 256).
    Reference,
    /// A method of the frame API (`dof::frame::METHODS`) on the chosen backend.
    Frame(&'static MethodInfo),
}

impl Method {
    pub fn name(self) -> &'static str {
        match self {
            Method::Pinhole => "pinhole",
            Method::Layers => "layers",
            Method::Reference => "reference",
            Method::Frame(m) => m.name,
        }
    }

    /// The registry method, where it is one.
    fn frame(self) -> Option<&'static MethodInfo> {
        match self {
            Method::Frame(m) => Some(m),
            _ => None,
        }
    }

    /// `--method`'s values: the three of render's own, then the registry's, each with its help.
    fn parser() -> impl clap::builder::TypedValueParser<Value = Method> {
        use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
        let own = [
            PossibleValue::new("pinhole").help("the pinhole image (no blur): the front layer"),
            PossibleValue::new("layers").help("the partial multi-layer image as a multi-layer EXR"),
            PossibleValue::new("reference").help("the exact reference (thin-lens ray tracing; the accumulation buffer for glTF)"),
        ];
        let registry = METHODS.iter().map(|m| PossibleValue::new(m.name).help(format!("{} ({})", m.title, m.paper)));
        PossibleValuesParser::new(own.into_iter().chain(registry)).map(|name| match name.as_str() {
            "pinhole" => Method::Pinhole,
            "layers" => Method::Layers,
            "reference" => Method::Reference,
            other => Method::Frame(METHODS.iter().find(|m| m.name == other).unwrap_or(&METHODS[0])),
        })
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum BackendArg {
    Cpu,
    Vulkan,
    /// The kernels as WGSL on the device wgpu chooses (`WGPU_BACKEND`: vulkan, metal, dx12, gl).
    #[cfg(feature = "wgpu")]
    Wgpu,
}

#[derive(clap::Args)]
pub struct RenderArgs {
    /// A built-in scene name (`simple`, `railing`, `columns`, `highlights`, `fence`, `edges`; `dof
    /// scenes` describes them), a glTF scene (`.gltf` or `.glb`: rasterised and depth-peeled on
    /// `--backend`), or an EXR file (RGB+Z, multi-layer, or deep). Deep EXR files may be given
    /// more than once: their samples merge into one image, as a deep merge does.
    #[arg(long = "scene", default_value = "simple")]
    scenes: Vec<String>,
    #[arg(long, default_value = "reference", value_parser = Method::parser())]
    method: Method,
    /// Image size (built-in and glTF scenes; an EXR has its own).
    #[arg(long)]
    width: Option<u32>,
    #[arg(long)]
    height: Option<u32>,
    /// Focus distance in scene units (planar).
    #[arg(long, allow_negative_numbers = true)]
    focus: Option<f32>,
    /// Aperture as an f-number (focal length from the field of view and sensor height)...
    #[arg(long, conflicts_with = "aperture_radius", allow_negative_numbers = true)]
    f_number: Option<f32>,
    /// ...or as a radius in scene units, as path tracers take it.
    #[arg(long, allow_negative_numbers = true)]
    aperture_radius: Option<f32>,
    /// Focal length in millimetres (default: from the field of view and the sensor height).
    #[arg(long, allow_negative_numbers = true)]
    focal_length: Option<f32>,
    /// Sensor height in millimetres.
    #[arg(long, default_value_t = 24.0)]
    sensor_height: f32,
    /// Camera position, target and vertical field of view in degrees (override the scene's camera).
    #[arg(long, value_parser = parse_vec3, allow_hyphen_values = true)]
    eye: Option<Vec3>,
    #[arg(long, value_parser = parse_vec3, allow_hyphen_values = true)]
    target: Option<Vec3>,
    #[arg(long, allow_negative_numbers = true)]
    yfov: Option<f32>,
    /// Samples per pixel: of the reference (default: raised until the noise is within 0.5 dB of
    /// converged), renders of the accumulation buffer (default 256) or rays of `raytrace` (default
    /// 16); at most 65536.
    #[arg(long, visible_alias = "spp")]
    samples: Option<u32>,
    /// The reference (`--method reference`, built-in scenes): integrate the light of the emissive
    /// spheres with samples aimed at each, converged at saturated bokeh rims (see
    /// docs/scenes-and-references.md). Refused for scenes with translucent surfaces.
    #[arg(long)]
    aimed_emitters: bool,
    /// Splatting and bokeh sprites: the aperture shape, `circle`, `blades:N[:ROTATION_DEGREES[:CURVATURE]]`,
    /// `star:N[:ROTATION_DEGREES[:INNER]]` or a PNG (its luminance as coverage; see `dof::aperture`).
    /// Default `circle`.
    #[arg(long)]
    aperture: Option<String>,
    /// The ring gather: sample rings at half resolution (1 to 8; default 5, 91 samples, what engines
    /// ship).
    #[arg(long)]
    rings: Option<u32>,
    /// Bokeh sprites: luminance above the 5x5 neighbourhood's mean that makes a sprite (default 1).
    #[arg(long, allow_negative_numbers = true)]
    lum_threshold: Option<f32>,
    /// Bokeh sprites: how many the sprite buffer holds (default 4096).
    #[arg(long)]
    sprites: Option<u32>,
    /// Layered DoF: one blur per layer instead of the cascade.
    #[arg(long)]
    no_cascade: bool,
    /// Layered DoF: layers per doubling of the CoC (1 to 4; default 2).
    #[arg(long)]
    layers_per_doubling: Option<u32>,
    /// The margin rendered beyond the frame for built-in and glTF scenes: `auto` (the largest CoC
    /// radius that can reach into the frame, at most 96 px), `off`, or a width in pixels.
    #[arg(long, default_value = "auto", value_parser = parse_guard_band)]
    guard_band: GuardBand,
    /// Fragments per pixel in the multi-layer image (built-in and glTF scenes; 1 to 64).
    #[arg(long, default_value_t = DEFAULT_LAYERS)]
    layers: u32,
    /// glTF scenes: peeling passes past --layers that composite a translucent stack deeper than the
    /// layers into each pixel's last one, in depth order (at most 1024 passes with --layers; a
    /// pass no pixel needs draws nothing). Refused for other inputs: built-in scenes keep such a
    /// stack whole without them.
    #[arg(long, default_value_t = LayerOptions::default().translucent_passes)]
    translucent_passes: u32,
    /// glTF scenes: the most probes a minified texture lookup takes, 1 to 64 (64: the box filter
    /// over the pixel's footprint; 1: one trilinear lookup, a GPU's isotropic filter, which blurs
    /// up to twice as wide). The reference always filters in full.
    #[arg(long, default_value_t = LayerOptions::default().texture_probes)]
    texture_probes: u32,
    /// Sub-samples a pixel of the multi-layer image (built-in and glTF scenes): 1 (point-sampled:
    /// the pixel centre's ray or peel), 4, 9 or 16 (a stratified grid, resolved by depth clusters
    /// into fragments of partial coverage; see docs/scenes-and-references.md).
    #[arg(long, visible_alias = "area-samples", default_value_t = scene::DEFAULT_SUBSAMPLES)]
    subsamples: u32,
    /// Leave out the footprints of area-integrated fragments (which of a pixel's sub-samples saw
    /// each): splatting then spreads every fragment from its pixel's centre.
    #[arg(long)]
    no_footprints: bool,
    /// Output EXR; a PNG preview is written beside it. Default `out/<scene>-<method>.exr`.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Backend that runs the kernels of the blurring methods and the rasteriser.
    #[arg(long, value_enum, default_value = "cpu")]
    backend: BackendArg,
    /// Largest CoC diameter in pixels the blurring methods honour (default: what the scene needs,
    /// up to the method's limit).
    #[arg(long)]
    max_coc: Option<u32>,
    /// Fragment merging before tiling (tiled and multilayer; default none).
    #[arg(long)]
    merge: Option<Merge>,
    /// Tile edge in pixels (tiled and multilayer): 16, 24 or 32 (default 16).
    #[arg(long)]
    tile: Option<u32>,
    /// Background radiance `R,G,B` (linear, finite, not negative): what a ray that hits nothing sees,
    /// a surface at infinite depth that every method blends like any other. Built-in and glTF
    /// scenes; default the scene's own (black, or the sky of `fence` and `edges`; a glTF scene's
    /// extras key `dof_background`). An EXR carries its background as the colour at depth +inf.
    #[arg(long, value_parser = parse_vec3, allow_hyphen_values = true)]
    background: Option<Vec3>,
    /// Exposure multiplier of the PNG preview (positive).
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    exposure: f32,
    /// Render a sequence of N frames in one process (one context for a registry method):
    /// `OUT-0000.exr`, ... beside `--out` and an animated preview `OUT.gif`. Built-in and glTF
    /// scenes; at most 10000.
    #[arg(long, allow_negative_numbers = true)]
    frames: Option<u32>,
    /// Sequences: render only frames A to B of the shot (inclusive), e.g. `1001:1100` for a render
    /// farm's share. An EXR sequence's frames by their numbers in the file names; a built-in or
    /// glTF sequence's by their index (0 to N-1 of `--frames N`). Every frame is the one the whole
    /// shot would render: the moves span the shot, and outputs are named by frame number. No
    /// preview GIF is written for a part of a shot.
    #[arg(long, value_parser = parse_frame_range, allow_negative_numbers = true)]
    frame_range: Option<(u64, u64)>,
    /// Sequences: a focus pull, the focus distance going linearly from the start's to this one.
    #[arg(long, allow_negative_numbers = true)]
    focus_to: Option<f32>,
    /// Sequences: a camera orbit, degrees per frame about the vertical axis through the start's
    /// point in focus on the view axis (-360 to 360).
    #[arg(long, allow_negative_numbers = true)]
    orbit: Option<f32>,
    /// Sequences: an aperture ramp, the aperture radius going linearly from the start's to this
    /// one (scene units)...
    #[arg(long, conflicts_with = "f_number_to", allow_negative_numbers = true)]
    aperture_radius_to: Option<f32>,
    /// ...or to the radius of this f-number.
    #[arg(long, allow_negative_numbers = true)]
    f_number_to: Option<f32>,
}

impl RenderArgs {
    /// The (first) scene given.
    pub(crate) fn scene(&self) -> &str {
        &self.scenes[0]
    }

    /// The multi-layer image's options the command line sets, with `guard_band`.
    pub(crate) fn layer_options(&self, guard_band: GuardBand) -> LayerOptions {
        LayerOptions {
            max_layers: self.layers,
            translucent_passes: self.translucent_passes,
            guard_band,
            subsamples: self.subsamples,
            footprints: !self.no_footprints,
            texture_probes: self.texture_probes,
            ..Default::default()
        }
    }
}

fn parse_frame_range(s: &str) -> Result<(u64, u64), String> {
    let bad = || format!("expected a frame range FIRST:LAST of frame numbers (0 or more, FIRST <= LAST), got `{s}`");
    let (a, b) = s.split_once(':').ok_or_else(bad)?;
    let (a, b) = (a.trim().parse::<u64>().map_err(|_| bad())?, b.trim().parse::<u64>().map_err(|_| bad())?);
    if a > b {
        return Err(bad());
    }
    Ok((a, b))
}

fn parse_vec3(s: &str) -> Result<Vec3, String> {
    let parts: Vec<f32> = s.split(',').map(|p| p.trim().parse::<f32>().map_err(|e| format!("`{p}`: {e}"))).collect::<Result<_, _>>()?;
    match parts[..] {
        [x, y, z] if parts.iter().all(|v| v.is_finite()) => Ok(Vec3::new(x, y, z)),
        _ => Err(format!("expected three finite numbers `x,y,z`, got `{s}`")),
    }
}

fn parse_guard_band(s: &str) -> Result<GuardBand, String> {
    match s {
        "auto" => Ok(GuardBand::Auto),
        "off" => Ok(GuardBand::Off),
        _ => match s.parse::<u32>() {
            Ok(px) if px <= MAX_GUARD_BAND => Ok(GuardBand::Pixels(px)),
            Ok(px) => Err(format!("a guard band of {px} px is beyond the largest, {MAX_GUARD_BAND} px")),
            Err(_) => Err(format!("expected `auto`, `off` or a width in pixels, got `{s}`")),
        },
    }
}

/// What can be checked before any work: the flags' ranges, flags an EXR input would ignore, and
/// outputs that would overwrite an input (the scene file, the buffers and textures of a glTF
/// scene, the aperture image).
fn check_before_work(args: &RenderArgs, out: &Path) -> anyhow::Result<()> {
    check_ranges(args)?;
    if let Some(hashes) = exr_pattern::from_printf(args.scene()).filter(|_| !Path::new(args.scene()).exists()) {
        bail!("--scene {}: no such file; an EXR sequence names its frame number with # (write {hashes})", args.scene());
    }
    if let Some(rgb) = args.background.filter(|c| c.max_element() > dof_shaders::radiance::COLOR_MAX) {
        eprintln!(
            "note: --background {:e},{:e},{:e} is taken as at most 2^100 a channel, the largest colour the methods read",
            rgb.x, rgb.y, rgb.z
        );
    }
    if args.scenes.len() > 1 {
        if let Some(other) = args.scenes.iter().find(|s| !s.to_ascii_lowercase().ends_with(".exr") || exr_pattern::is_pattern(s)) {
            bail!("--scene is given more than once only to merge deep EXR files; {other} is not one (give one scene)");
        }
        if args.frames.is_some() {
            bail!("--frames: deep EXR files given together are one frame; a sequence is named by one pattern");
        }
    }
    let lower = args.scene().to_ascii_lowercase();
    let translucent_passes = args.translucent_passes != LayerOptions::default().translucent_passes;
    let texture_probes = args.texture_probes != LayerOptions::default().texture_probes;
    if lower.ends_with(".gltf") || lower.ends_with(".glb") {
        // Refused before the scene is loaded.
        peel_passes(args.layers, args.translucent_passes)?;
        check_texture_probes(args.texture_probes)?;
    } else if texture_probes {
        bail!("--texture-probes applies to glTF scenes, whose textures are filtered here; {} is not one", args.scene());
    } else if translucent_passes {
        bail!(
            "--translucent-passes applies to glTF scenes, whose layers are peeled; {} is not one (a built-in scene keeps a \
             translucent stack whole without it, an EXR brings its own layers)",
            args.scene()
        );
    }
    if lower.ends_with(".exr") {
        // The layer budget applies to deep input, whose layers are made here.
        let first = match sequence::plan(args)? {
            Some(plan) => plan.files.get(plan.selected.start).cloned(),
            None => Some(args.scene().into()),
        };
        let deep = first.is_some_and(|p| dof::io::is_deep_exr(p).unwrap_or(false));
        let fixed = [
            (args.width.is_some(), "--width"),
            (args.height.is_some(), "--height"),
            (args.guard_band != GuardBand::Auto, "--guard-band"),
            (args.eye.is_some(), "--eye"),
            (args.target.is_some(), "--target"),
            (args.layers != DEFAULT_LAYERS && !deep, "--layers"),
            (args.subsamples != scene::DEFAULT_SUBSAMPLES, "--subsamples"),
            (args.no_footprints, "--no-footprints"),
        ];
        if let Some((_, flag)) = fixed.iter().find(|(given, _)| *given) {
            bail!(
                "{flag} does not apply to an EXR input ({}): an EXR fixes its own size, view and layers \
                 (its edges are extended by the edge policy instead of a guard band; --layers sets the layers of deep input)",
                args.scene()
            );
        }
    }
    // The method's options: a registry method's entry refuses those it does not take and values
    // out of its bounds; render's own methods take none (the reference takes `--samples`).
    match args.method.frame() {
        Some(_) => drop(method_options(args)?),
        None => {
            let name = args.method.name();
            let given = args.method_flags().into_iter().filter(|(flag, _)| !(*flag == "--samples" && name == "reference"));
            if let Some((flag, _)) = given.into_iter().next() {
                let option = MethodOption::from_key(flag).map_or_else(String::new, |o| o.methods());
                bail!("option {flag} applies to {option} only; {name} does not take it");
            }
        }
    }
    if args.aimed_emitters && args.method.name() != "reference" {
        bail!("--aimed-emitters applies to reference only; {} does not take it", args.method.name());
    }
    if !(args.exposure > 0.0 && args.exposure.is_finite()) {
        bail!("--exposure must be a positive number, got {}", args.exposure);
    }
    if let Some(n) = args.samples.filter(|&n| n == 0 || n > MAX_SAMPLES) {
        bail!("--samples/--spp (samples or rays per pixel) must lie between 1 and {MAX_SAMPLES}, got {n}");
    }
    // Every file the run reads, and every file it writes.
    let mut outputs =
        vec![(out.to_path_buf(), "--out".to_string()), (out.with_extension("png"), "the PNG preview beside --out".to_string())];
    let mut inputs: Vec<PathBuf> = args.scenes.iter().map(PathBuf::from).collect();
    let plan = sequence::plan(args)?;
    if let Some(plan) = &plan {
        inputs.extend(plan.files.iter().cloned());
    }
    let edge = args.width.unwrap_or(0).max(args.height.unwrap_or(0));
    if plan.as_ref().is_some_and(|p| p.whole()) && edge > dof::io::MAX_GIF_EDGE {
        bail!(
            "a sequence's GIF preview is at most {} px on an edge; --width/--height {edge} is over it (render single frames instead)",
            dof::io::MAX_GIF_EDGE
        );
    }
    if let Some(plan) = &plan {
        outputs.extend(plan.selected.clone().map(|i| {
            let number = plan.numbers[i];
            (plan.path(out, i), format!("frame {number} of the sequence (from --out)"))
        }));
        if plan.whole() {
            outputs.push((out.with_extension("gif"), "the GIF preview beside --out".to_string()));
        }
    }
    let lower = args.scene().to_ascii_lowercase();
    if lower.ends_with(".gltf") || lower.ends_with(".glb") {
        inputs.extend(scene::gltf_external_files(Path::new(args.scene())));
    }
    if let Some(mask) = args.aperture.as_deref().filter(|a| Path::new(a).extension().is_some()) {
        inputs.push(PathBuf::from(mask));
    }
    // One look-up an output (a sequence may have 10,000 frames on each side).
    let inputs: std::collections::HashMap<PathBuf, &PathBuf> =
        inputs.iter().map(|i| (i.canonicalize().unwrap_or_else(|_| i.clone()), i)).collect();
    for (output, what) in &outputs {
        if let Some(input) = inputs.get(&output.canonicalize().unwrap_or_else(|_| output.clone())) {
            bail!("{what} ({}) would overwrite the input {}; choose another --out", output.display(), input.display());
        }
    }
    if exr_pattern::is_pattern(args.scene()) {
        // Outputs the pattern matches would be read as frames of the shot by the next run.
        if let Some((output, _)) = outputs.iter().find(|(o, _)| exr_pattern::matches(args.scene(), o)) {
            bail!(
                "the outputs of --out {} (such as {}) are named like frames of the input sequence {}: a later run would \
                 read them as frames of the shot; choose another --out",
                out.display(),
                output.display(),
                args.scene()
            );
        }
    }
    Ok(())
}

/// The flags' own ranges, each refused naming the flag (the lens flags' relations, such as a focal
/// length shorter than the focus distance, are checked with the lens).
fn check_ranges(args: &RenderArgs) -> anyhow::Result<()> {
    for (value, flag) in [(args.width, "--width"), (args.height, "--height")] {
        if let Some(v) = value.filter(|&v| v == 0 || v > MAX_EDGE) {
            bail!("{flag} must lie between 1 and {MAX_EDGE} px, got {v}");
        }
    }
    if args.layers == 0 || args.layers > MAX_LAYERS {
        bail!("--layers (fragments per pixel) must lie between 1 and {MAX_LAYERS}, got {}", args.layers);
    }
    scene::check_subsamples(args.subsamples).map_err(|e| anyhow::anyhow!("--subsamples: {e}"))?;
    let positive = [
        (args.focus, "--focus (the focus distance)"),
        (args.f_number, "--f-number"),
        (args.focal_length, "--focal-length (the focal length, mm)"),
        (Some(args.sensor_height), "--sensor-height (the sensor height, mm)"),
    ];
    for (value, flag) in positive {
        if let Some(v) = value.filter(|v| !(*v > 0.0 && v.is_finite())) {
            bail!("{flag} must be a positive finite number, got {v}");
        }
    }
    if let Some(r) = args.aperture_radius.filter(|r| !(*r >= 0.0 && r.is_finite())) {
        bail!("--aperture-radius (the aperture radius) must be a finite number, not negative, got {r}");
    }
    if let Some(deg) = args.yfov.filter(|d| !(*d > 0.0 && *d < 180.0)) {
        bail!("--yfov (the vertical field of view) must lie strictly between 0 and 180 degrees, got {deg}");
    }
    check_sequence(args)?;
    Ok(())
}

/// The sequence flags' ranges, and that they come with `--frames`.
fn check_sequence(args: &RenderArgs) -> anyhow::Result<()> {
    if let Some(n) = args.frames.filter(|n| !(1..=sequence::MAX_FRAMES).contains(n)) {
        bail!("--frames (frames of the sequence) must lie between 1 and {}, got {n}", sequence::MAX_FRAMES);
    }
    for (value, flag) in
        [(args.focus_to, "--focus-to (the end's focus distance)"), (args.f_number_to, "--f-number-to (the end's f-number)")]
    {
        if let Some(v) = value.filter(|v| !(*v > 0.0 && v.is_finite())) {
            bail!("{flag} must be a positive finite number, got {v}");
        }
    }
    if let Some(r) = args.aperture_radius_to.filter(|r| !(*r >= 0.0 && r.is_finite())) {
        bail!("--aperture-radius-to (the end's aperture radius) must be a finite number, not negative, got {r}");
    }
    if let Some(d) = args.orbit.filter(|d| !(d.abs() <= 360.0)) {
        bail!("--orbit (degrees per frame) must lie between -360 and 360, got {d}");
    }
    let moves = [
        (args.focus_to.is_some(), "--focus-to"),
        (args.orbit.is_some(), "--orbit"),
        (args.aperture_radius_to.is_some(), "--aperture-radius-to"),
        (args.f_number_to.is_some(), "--f-number-to"),
    ];
    let sequence = args.frames.is_some() || exr_pattern::is_pattern(args.scene());
    let one_exr = !sequence && args.scene().to_ascii_lowercase().ends_with(".exr");
    if let Some((_, flag)) = moves.iter().find(|(given, _)| *given).filter(|_| !sequence) {
        if one_exr {
            // `--frames` is refused on one EXR, and an EXR has no geometry to turn: say what moves.
            let how = if *flag == "--orbit" {
                "an EXR has no geometry to turn: orbit a built-in or glTF scene with --frames N"
            } else {
                "one EXR is one frame: give an EXR sequence by its pattern (shot-####.exr, one file a frame), or a built-in or \
                 glTF scene with --frames N"
            };
            bail!("{flag} moves the shot over a sequence; {how}");
        }
        bail!("{flag} moves the shot over a sequence: give --frames N (or an EXR sequence such as shot-####.exr)");
    }
    let exr = args.scene().to_ascii_lowercase().ends_with(".exr");
    if args.frames.is_some() && exr && !exr_pattern::is_pattern(args.scene()) {
        bail!("--frames on one EXR: name an EXR sequence by a pattern such as shot-####.exr (its frames are the files that match)");
    }
    if args.orbit.is_some() && exr {
        bail!("--orbit turns the camera of a built-in or glTF scene; an EXR has no geometry to turn");
    }
    Ok(())
}

/// The lens flags given, for the context of a lens the library refuses (their relations, e.g. a
/// focal length not shorter than the focus distance).
fn lens_flags(args: &RenderArgs) -> String {
    let given = [
        (args.focus, "--focus"),
        (args.f_number, "--f-number"),
        (args.aperture_radius, "--aperture-radius"),
        (args.focal_length, "--focal-length"),
        (Some(args.sensor_height), "--sensor-height"),
        (args.yfov, "--yfov"),
    ];
    let flags: Vec<String> = given.iter().filter_map(|(v, flag)| v.map(|v| format!("{flag} {v}"))).collect();
    format!("the lens from {}", flags.join(", "))
}

/// Refuses a lens whose blur reaches past what a [`Reach::WithinLayers`] method (ray tracing
/// through layers) can see: the layers end [`scene::MAX_GUARD_BAND`] px beyond the frame, and a ray
/// leaving them finds nothing, so a wider far-field CoC would darken the frame instead of blurring
/// it. The [`Reach::Capped`] methods cap the blur there instead.
fn check_lens_reach(args: &RenderArgs, lens: &ThinLens) -> anyhow::Result<()> {
    let coc = lens.far_limit_px();
    let reach = dof::scene::MAX_GUARD_BAND as f32;
    let Some(info) = args.method.frame() else { return Ok(()) };
    if info.reach == Reach::WithinLayers && !(coc <= reach) {
        let capped: Vec<&str> = METHODS.iter().filter(|m| m.reach == Reach::Capped).map(|m| m.name).collect();
        bail!(
            "the far-field CoC is {coc:.0} px, but {} ({}) sees only {reach:.0} px beyond the frame, where the layers end: lower \
             the aperture, or use a method that caps the CoC there ({})",
            info.name,
            info.title,
            capped.join(", ")
        );
    }
    Ok(())
}

/// Makes `out`'s folder and checks that `out` can be written, before any work.
pub(crate) fn prepare_output(out: &Path) -> anyhow::Result<()> {
    if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).with_context(|| format!("cannot create the output folder {}", dir.display()))?;
    }
    check_writable(out)
}

/// Fails now, not after the render, when `out` cannot be written: a probe file beside it is
/// created and removed.
fn check_writable(out: &Path) -> anyhow::Result<()> {
    if out.is_dir() {
        bail!("--out {} is a folder; name an .exr file", out.display());
    }
    let dir = out.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let probe = dir.join(format!(".dof-write-probe-{}", std::process::id()));
    std::fs::File::create(&probe).with_context(|| format!("cannot write into {} (for --out {})", dir.display(), out.display()))?;
    std::fs::remove_file(&probe).ok();
    Ok(())
}

fn is_file_scene(scene: &str) -> bool {
    let lower = scene.to_ascii_lowercase();
    [".exr", ".gltf", ".glb"].iter().any(|ext| lower.ends_with(ext))
}

/// Default and largest `--layers`.
const DEFAULT_LAYERS: u32 = 4;
const MAX_LAYERS: u32 = 64;
/// Largest `--width` and `--height`.
const MAX_EDGE: u32 = 65536;

/// Most samples per pixel (`--samples`) any method takes.
use super::MAX_SAMPLES;

pub fn run(args: &RenderArgs) -> anyhow::Result<()> {
    let name = if exr_pattern::is_pattern(args.scene()) {
        exr_pattern::stem(args.scene())
    } else {
        Path::new(args.scene()).file_stem().and_then(|s| s.to_str()).unwrap_or("scene").to_string()
    };
    let method = args.method.name();
    let out = args.out.clone().unwrap_or_else(|| PathBuf::from(format!("out/{name}-{method}.exr")));
    if out.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() != Some("exr") {
        bail!("--out must name an .exr file (a PNG preview is written beside it), got {}", out.display());
    }
    check_before_work(args, &out)?;
    prepare_output(&out)?;
    if is_file_scene(args.scene()) { render_file(args, &out) } else { render_builtin(args, &out) }
}

/// A scene given as a file: a glTF scene (rasterised), or EXR input (the methods that need only the
/// image).
fn render_file(args: &RenderArgs, out: &Path) -> anyhow::Result<()> {
    let lower = args.scene().to_ascii_lowercase();
    if lower.ends_with(".gltf") || lower.ends_with(".glb") {
        return render_gltf(args, out);
    }
    if exr_pattern::is_pattern(args.scene()) {
        return sequence::render_exr_sequence(args, out);
    }
    let input = ExrInput::read(&args.scenes)?;
    if let Some(note) = input.note() {
        eprintln!("note: {}: {note}", args.scenes.join(", "));
    }
    if args.background.is_some() {
        bail!("--background applies to built-in and glTF scenes; an EXR carries its background as the colour stored at depth +inf");
    }
    if args.method == Method::Reference {
        bail!("the exact reference needs the scene's geometry; an EXR has none (use a built-in scene)");
    }
    let window = Some(input.window());
    if args.method == Method::Pinhole {
        let (image, depth) = input.flattened();
        return write_outputs_at(out, &image, &[("Z", &depth)], args.exposure, window);
    }
    // Flat layers are read as stored (`--method layers` writes them back without a lens); a deep
    // image's layers are made for the lens.
    if let (Method::Layers, ExrInput::Flat { layers, .. }) = (args.method, &input) {
        return write_layers(out, layers);
    }
    let (camera, settings) = exr_camera(args, input.size())?;
    let lens = settings.thin_lens(&camera).with_context(|| lens_flags(args))?;
    let layers = exr_layers(args, &input, &camera, &lens, true)?;
    if args.method == Method::Layers {
        return write_layers(out, &layers);
    }
    check_lens_reach(args, &lens)?;
    // Nothing lies beyond an EXR's frame: its edge pixels are extended outwards as far as its
    // largest CoC reaches (the edge policy, the same for every method).
    let margin = edge_margin(&layers, &lens);
    let padded = layers.extend_edges(margin)?;
    if margin > 0 {
        println!(
            "edge policy: the image's edge pixels extended by {margin} px on every side (its largest CoC radius, at most {MAX_GUARD_BAND})"
        );
    }
    let (image, depth) = blur(args, &padded, &lens, margin)?;
    let coc: Vec<f32> = depth.iter().map(|&z| lens.coc_px(z)).collect();
    write_outputs_at(out, &image, &[("Z", &depth), ("coc", &coc)], args.exposure, window)
}

/// `--method layers`: the multi-layer image as a multi-layer EXR, and what it holds.
fn write_layers(out: &Path, layers: &LayeredImage) -> anyhow::Result<()> {
    write_layered_exr(out, layers)?;
    let stats = layers.stats();
    println!(
        "{} layers, {:.3} fragments per pixel, {:.1}% of pixels with more than one",
        layers.max_layers,
        stats.fragments_per_pixel(),
        100.0 * stats.multi_layer_share()
    );
    Ok(())
}

/// The layers of an EXR input for `lens`: a deep image's made by the paper's rules with
/// `--layers` fragments a pixel (its report printed when `print`), flat layers as stored.
pub(super) fn exr_layers(
    args: &RenderArgs,
    input: &ExrInput,
    camera: &Camera,
    lens: &ThinLens,
    print: bool,
) -> anyhow::Result<LayeredImage> {
    let (layers, report) = input.layers(camera, lens, &args.layer_options(GuardBand::Off))?;
    if let Some(r) = report.filter(|_| print) {
        println!("deep input to layers (L = {}): {r}", args.layers);
    }
    Ok(layers)
}

/// The camera and lens settings of an EXR of `size` from the lens flags: it carries no camera, so
/// `--focus` and `--f-number` or `--aperture-radius` are required; the field of view (`--yfov`,
/// default 40 degrees) and sensor height give the scale.
fn exr_camera(args: &RenderArgs, size: (u32, u32)) -> anyhow::Result<(Camera, LensSettings)> {
    let aperture = match (args.f_number, args.aperture_radius) {
        (Some(n), _) => Some(Aperture::FNumber(n)),
        (_, Some(r)) => Some(Aperture::Radius(r)),
        _ => None,
    };
    let (camera, mut settings) = exr_view(size, args.focus, aperture, args.yfov)?;
    settings.focal_length_mm = args.focal_length;
    settings.sensor_height_mm = args.sensor_height;
    Ok((camera, settings))
}

/// The camera and lens settings of an EXR (it has neither): at the origin looking down -Z with
/// `yfov` degrees (default 40), the focus and aperture as given (both required).
pub(crate) fn exr_view(
    (width, height): (u32, u32),
    focus: Option<f32>,
    aperture: Option<Aperture>,
    yfov: Option<f32>,
) -> anyhow::Result<(Camera, LensSettings)> {
    let Some(focus) = focus else {
        bail!(
            "an EXR carries no lens: give --focus (planar focus distance, in the units of its Z channel) and --f-number or --aperture-radius"
        )
    };
    let Some(aperture) = aperture else { bail!("an EXR carries no lens: give --f-number or --aperture-radius (with --focus)") };
    let yfov = yfov.unwrap_or(40.0).to_radians();
    let camera = Camera::look_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0), yfov, width, height);
    let mut settings = LensSettings::photographic(focus, 8.0);
    settings.aperture = aperture;
    Ok((camera, settings))
}

/// How far an EXR's edge pixels are extended: the largest CoC radius among its fragments, at most
/// [`MAX_GUARD_BAND`] (what the guard band of a rendered scene would be for the frame's content).
pub(crate) fn edge_margin(layers: &LayeredImage, lens: &ThinLens) -> u32 {
    let used = layers.counts.iter().enumerate().flat_map(|(p, &n)| {
        let start = p * layers.max_layers as usize;
        layers.fragments[start..start + n.min(layers.max_layers) as usize].iter()
    });
    let largest = used.map(|f| lens.coc_radius_px(f.depth)).fold(0.0f32, f32::max);
    (largest.ceil() as u32).min(MAX_GUARD_BAND)
}

/// Runs a blurring method (gather, ring-gather, tiled, multilayer, raytrace, layered, bokeh) on the chosen
/// backend and prints what it did; `layers` extend `margin` pixels beyond the frame on every side.
/// Returns the frame's image and its front layer's depth.
fn blur(args: &RenderArgs, layers: &LayeredImage, lens: &ThinLens, margin: u32) -> anyhow::Result<(RgbImage, Vec<f32>)> {
    let mut b = backend(args.backend)?;
    let depth = layers.front_depths()?;
    let Method::Frame(method) = args.method else { bail!("{} is not a blurring method", args.method.name()) };
    let out = one_shot(b.as_mut(), method, &method_options(args)?, layers, lens)?;
    let ms: f64 = out.stages.iter().map(|t| t.ms).sum();
    println!("{} ({}) on {}: {ms:.2} ms in kernels", method.title, method.paper, b.device_name());
    println!("{}", out.report.summary);
    // The numerical contract's clamp, counted over the input with the kernels' own rule (splatting
    // also counts it on the device, in its summary above).
    let used = || {
        layers
            .counts
            .iter()
            .enumerate()
            .flat_map(|(p, &n)| &layers.fragments[p * layers.max_layers as usize..][..n.min(layers.max_layers) as usize])
    };
    let clamped = used().filter(|f| dof_shaders::radiance::is_clamped(f.color)).count();
    println!("numerical contract: {clamped} input colour(s) clamped where read (negative, subnormal or above 2^100)");
    let alpha_clamped = used().filter(|f| dof_shaders::slot::is_alpha_clamped(f.alpha)).count();
    if alpha_clamped > 0 {
        println!("alpha: {alpha_clamped} input alpha(s) NaN or outside [0, 1], clamped where read (NaN to 0)");
    }
    let image = out.image;
    Ok((image.crop(margin), crop_plane(&depth, layers.width, margin)))
}

/// The frame API's options from the command line: the method options given, checked by the
/// method's registry entry (kinds, bounds, which it takes).
/// Render's own methods (pinhole, layers, reference) take the defaults, which they do not read.
fn method_options(args: &RenderArgs) -> anyhow::Result<MethodOptions> {
    match args.method.frame() {
        Some(method) => Ok(method.method_options(args.method_flags())?),
        None => Ok(MethodOptions::default()),
    }
}

impl RenderArgs {
    /// The method options given on the command line, by flag.
    fn method_flags(&self) -> Vec<(&'static str, Value)> {
        let flag = |o: MethodOption| o.flag();
        [
            self.tile.map(|v| (flag(MethodOption::Tile), Value::from(v))),
            self.merge.map(|v| (flag(MethodOption::Merge), Value::from(v.name()))),
            self.max_coc.map(|v| (flag(MethodOption::MaxCoc), Value::from(v))),
            self.aperture.as_deref().map(|v| (flag(MethodOption::Aperture), Value::from(v))),
            self.rings.map(|v| (flag(MethodOption::Rings), Value::from(v))),
            self.lum_threshold.map(|v| (flag(MethodOption::LumThreshold), Value::from(v))),
            self.sprites.map(|v| (flag(MethodOption::Sprites), Value::from(v))),
            self.samples.map(|v| (flag(MethodOption::Samples), Value::from(v))),
            self.no_cascade.then(|| (flag(MethodOption::NoCascade), Value::from(true))),
            self.layers_per_doubling.map(|v| (flag(MethodOption::LayersPerDoubling), Value::from(v))),
        ]
        .into_iter()
        .flatten()
        .collect()
    }
}

pub(super) fn backend(choice: BackendArg) -> anyhow::Result<Box<dyn dof::backend::Backend>> {
    let choice = match choice {
        BackendArg::Cpu => super::BackendChoice::Cpu,
        BackendArg::Vulkan => super::BackendChoice::Vulkan,
        #[cfg(feature = "wgpu")]
        BackendArg::Wgpu => return Ok(Box::new(dof::backend::WgpuBackend::new(&Default::default())?)),
    };
    super::backends(choice, false)?.pop().context("no backend")
}

fn render_builtin(args: &RenderArgs, out: &Path) -> anyhow::Result<()> {
    let mut builtin = scene::builtin(args.scene())?;
    if let Some(rgb) = args.background {
        builtin.scene = builtin.scene.with_background(rgb.to_array())?;
    }
    let mut camera: Camera = builtin.camera;
    camera.width = args.width.unwrap_or(camera.width);
    camera.height = args.height.unwrap_or(camera.height);
    camera.eye = args.eye.unwrap_or(camera.eye);
    camera.target = args.target.unwrap_or(camera.target);
    if let Some(deg) = args.yfov {
        camera.yfov_radians = deg.to_radians();
    }
    let settings = lens_settings(args, builtin.lens);
    let lens = settings.thin_lens(&camera).with_context(|| lens_flags(args))?;
    println!(
        "{}: {}x{}, f = {:.1} mm, aperture radius {:.2} mm, focus {:.3}, far-field CoC {:.1} px",
        builtin.name,
        camera.width,
        camera.height,
        lens.focal_length * 1e3,
        lens.aperture_radius * 1e3,
        lens.focus_distance,
        lens.far_limit_px()
    );
    check_lens_reach(args, &lens)?;
    if let Some(plan) = sequence::plan(args)? {
        let shots = sequence::shots(args, plan.numbers.len() as u32, &camera, &settings, &lens)?;
        return sequence::render_sequence(args, out, sequence::Source::Builtin(&builtin.scene), &shots, &plan);
    }
    let options = args.layer_options(args.guard_band);
    let layered = raycast_layers(&builtin.scene, &camera, &lens, &options)?;
    match args.method {
        Method::Pinhole => {
            let r = scene::pinhole(&builtin.scene, &camera, &ReferenceOptions { spp: 16, ..Default::default() })?;
            write_with_planes(args, out, &r.image, &layered, &lens)
        }
        Method::Reference => {
            let reference = match args.samples {
                Some(spp) => {
                    let o = ReferenceOptions { spp, progress: true, aimed_emitters: args.aimed_emitters, ..Default::default() };
                    scene::reference(&builtin.scene, &camera, &lens, &o)?
                }
                None => {
                    let o = AutoOptions { progress: true, aimed_emitters: args.aimed_emitters, ..Default::default() };
                    scene::reference_auto(&builtin.scene, &camera, &lens, &o)?
                }
            };
            println!(
                "reference: {} samples per pixel, estimated noise PSNR {}{}",
                reference.spp,
                reference.noise_psnr_db.map_or("n/a".to_string(), |p| format!("{p:.1} dB")),
                if reference.capped { " (sample cap reached before the target)" } else { "" }
            );
            write_with_planes(args, out, &reference.image, &layered, &lens)
        }
        _ => render_layers(args, out, &layered, &lens),
    }
}

/// The lens flags applied over a scene's lens.
fn lens_settings(args: &RenderArgs, mut settings: LensSettings) -> LensSettings {
    if let Some(d) = args.focus {
        settings.focus = Focus::Distance(d);
    }
    if let Some(n) = args.f_number {
        settings.aperture = Aperture::FNumber(n);
    }
    if let Some(r) = args.aperture_radius {
        settings.aperture = Aperture::Radius(r);
    }
    settings.focal_length_mm = args.focal_length.or(settings.focal_length_mm);
    settings.sensor_height_mm = args.sensor_height;
    settings
}

/// The methods that start from the multi-layer image, whatever made it: the layers themselves, or
/// a blur of them.
fn render_layers(args: &RenderArgs, out: &Path, layered: &SceneLayers, lens: &ThinLens) -> anyhow::Result<()> {
    if args.method == Method::Layers {
        write_layered_exr(out, &layered.frame_layers())?;
        let (w, wo) = (layered.with_mask, layered.without_mask);
        println!(
            "layers: {:.3} fragments per pixel, {:.1}% of pixels multi-layer (without the disocclusion buffer: {:.3}, {:.1}%); buffer covers {:.1}% of pixels",
            w.fragments_per_pixel(),
            100.0 * w.multi_layer_share(),
            wo.fragments_per_pixel(),
            100.0 * wo.multi_layer_share(),
            100.0 * layered.mask_share()
        );
        let (front, _) = layered.front();
        write_png_preview(out.with_extension("png"), &front, args.exposure)?;
        println!("wrote {} and {}", out.display(), out.with_extension("png").display());
        return Ok(());
    }
    if layered.margin > 0 {
        let (w, h) = (layered.layers.width, layered.layers.height);
        let frame = (w - 2 * layered.margin) as f64 * (h - 2 * layered.margin) as f64;
        println!(
            "guard band: {} px beyond every edge, the method runs on {w}x{h} ({:.2}x the frame's pixels)",
            layered.margin,
            w as f64 * h as f64 / frame
        );
    }
    let (image, _) = blur(args, &layered.layers, lens, layered.margin)?;
    write_with_planes(args, out, &image, layered, lens)
}

/// An image with the front layer's depth, its CoC and the disocclusion buffer as extra planes.
fn write_with_planes(args: &RenderArgs, out: &Path, image: &RgbImage, layered: &SceneLayers, lens: &ThinLens) -> anyhow::Result<()> {
    let (_, depth) = layered.front();
    let coc: Vec<f32> = depth.iter().map(|&z| lens.coc_px(z)).collect();
    let mask: Vec<f32> = layered.mask.iter().map(|&m| m as u32 as f32).collect();
    write_outputs(out, image, &[("Z", &depth), ("coc", &coc), ("mask", &mask)], args.exposure)
}

/// A glTF scene: loaded, rasterised and depth-peeled on the chosen backend; its reference is the
/// accumulation buffer.
fn render_gltf(args: &RenderArgs, out: &Path) -> anyhow::Result<()> {
    let mut mesh = load_gltf(Path::new(args.scene()))?;
    if let Some(rgb) = args.background {
        scene::analytic::check_background(rgb.to_array())?;
        mesh.lighting.background = scene::analytic::in_contract(rgb.to_array());
    }
    let report = mesh.report.to_string();
    if !report.is_empty() {
        eprintln!("note: {}: {report}", args.scene());
    }
    let (camera, lens, near) = gltf_view(args, &mesh)?;
    // From the start's eye (a sequence's orbit keeps to the outside of objects).
    let solids = mesh.single_sided_solids(camera.eye);
    if solids != Default::default() {
        println!("{}: {solids}", args.scene());
    }
    println!(
        "{}: {} triangles, {}x{}, f = {:.1} mm, aperture radius {:.2} mm, focus {:.3}, near plane {near}, far-field CoC {:.1} px",
        args.scene(),
        mesh.triangles.len(),
        camera.width,
        camera.height,
        lens.focal_length * 1e3,
        lens.aperture_radius * 1e3,
        lens.focus_distance,
        lens.far_limit_px()
    );
    check_lens_reach(args, &lens)?;
    if let Some(plan) = sequence::plan(args)? {
        let settings = lens_settings(args, mesh.lens_focused_at(&camera, args.focus)?);
        let shots = sequence::shots(args, plan.numbers.len() as u32, &camera, &settings, &lens)?;
        return sequence::render_sequence(args, out, sequence::Source::Gltf { mesh: &mesh, near }, &shots, &plan);
    }
    let mut b = backend(args.backend)?;
    let raster = mesh.raster();
    let options = args.layer_options(args.guard_band);
    // The peel and the accumulation buffer share one upload.
    let (peeled, reference) = DeviceMesh::scoped(b.as_mut(), &raster, |b, mesh| {
        let peeled = peel_layers_with(b, &raster, mesh, &camera, &lens, near, &options)?;
        let ms: f64 = peeled.times.iter().map(|t| t.ms).sum();
        println!("depth peeling on {}: {} passes, {ms:.2} ms", b.device_name(), peeled.passes);
        let deep_stacks = peeled.image.layers.full_and_translucent();
        if deep_stacks > 0 {
            eprintln!(
                "note: {deep_stacks} pixel(s) fill all {} layers with translucent surfaces and still let light through after {} \
                 passes: what lies behind them is left out (black); raise --translucent-passes (or --layers)",
                options.max_layers, peeled.passes
            );
        }
        if args.method != Method::Reference {
            return Ok((peeled, None));
        }
        let samples = args.samples.unwrap_or(256);
        let acc_options = AccumulateOptions { samples, progress: true, ..Default::default() };
        let acc = accumulate_with(b, &raster, mesh, &camera, &lens, near, &acc_options)?;
        let ms: f64 = acc.times.iter().map(|t| t.ms).sum();
        println!("accumulation buffer on {}: {samples} renders, {ms:.2} ms", b.device_name());
        Ok((peeled, Some(acc.image)))
    })?;
    match (args.method, reference) {
        (_, Some(reference)) => write_with_planes(args, out, &reference, &peeled.image, &lens),
        (Method::Pinhole, None) => write_with_planes(args, out, &peeled.image.front().0, &peeled.image, &lens),
        _ => render_layers(args, out, &peeled.image, &lens),
    }
}

/// The view of a glTF scene: `--eye` and `--target` (with `--yfov`, default the file's or 40
/// degrees) when given, else the file's first camera ([`MeshScene::default_view`]); the lens flags
/// over the scene's default lens.
fn gltf_view(args: &RenderArgs, mesh: &MeshScene) -> anyhow::Result<(Camera, ThinLens, f32)> {
    let width = args.width.unwrap_or(640);
    let (mut camera, settings, near) = match (args.eye, args.target) {
        (Some(eye), Some(target)) => {
            let yfov = args.yfov.map(f32::to_radians).or(mesh.cameras.first().map(|c| c.yfov_radians)).unwrap_or(40f32.to_radians());
            let camera = Camera::look_at(eye, target, yfov, width, args.height.unwrap_or(width * 9 / 16));
            let settings = mesh.lens_focused_at(&camera, args.focus)?;
            (camera, settings, None)
        }
        (None, None) if mesh.cameras.is_empty() => {
            bail!("{} has no camera: give --eye X,Y,Z --target X,Y,Z (and --yfov DEGREES, default 40)", args.scene())
        }
        (None, None) => {
            let (camera, near) = mesh.default_camera(width, args.height)?;
            (camera, mesh.lens_focused_at(&camera, args.focus)?, Some(near))
        }
        _ => bail!("give both --eye X,Y,Z and --target X,Y,Z (or neither, to use the file's camera)"),
    };
    if let Some(deg) = args.yfov {
        camera.yfov_radians = deg.to_radians();
    }
    let lens = lens_settings(args, settings).thin_lens(&camera).with_context(|| lens_flags(args))?;
    Ok((camera, lens, near.unwrap_or(default_near(lens.focus_distance))))
}

fn write_outputs(out: &Path, image: &RgbImage, extra: &[(&str, &[f32])], exposure: f32) -> anyhow::Result<()> {
    write_outputs_at(out, image, extra, exposure, None)
}

/// [`write_outputs`] with the EXR's data and display windows (an EXR input's, kept).
fn write_outputs_at(
    out: &Path,
    image: &RgbImage,
    extra: &[(&str, &[f32])],
    exposure: f32,
    window: Option<ExrWindow>,
) -> anyhow::Result<()> {
    write_exr_with(out, image, extra, &ExrWriteOptions { window, ..Default::default() })?;
    let png = out.with_extension("png");
    write_png_preview(&png, image, exposure)?;
    println!("wrote {} and {}", out.display(), png.display());
    Ok(())
}
