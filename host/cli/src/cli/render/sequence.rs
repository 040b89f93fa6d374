//! `dof render --frames N`: a sequence in one process. The shot's parameters move linearly over
//! the frames (focus distance to `--focus-to`, aperture radius to `--aperture-radius-to` or the
//! radius of `--f-number-to`, the camera `--orbit` degrees per frame about the vertical axis
//! through the start's point in focus on the view axis). A registry method renders every frame
//! through **one context** made once for the sequence's extent, with its input and output buffers:
//! per frame the layers are made (built-in scenes ray cast, glTF scenes depth-peeled), uploaded,
//! recorded, submitted and read back. The guard band is fixed for the sequence (`auto`: the largest
//! of the frames' own), so every frame has the same extent. The references and the pinhole image
//! render per frame with their own functions. Output: `OUT-0000.exr`, … beside `--out` and an
//! animated preview `OUT.gif` through the PNG previews' tone map. `--frame-range A:B` renders a
//! part of the shot ([`Plan`]): the moves and the guard band span the whole shot, so each frame is
//! the one the whole shot renders, named by its number; no preview is written for a part.
//!
//! An EXR sequence (`--scene shot-####.exr`, see [`super::exr_pattern`]) renders every file that
//! matches, in frame order (the first `--frames N` of them when given), each output named by its
//! input's frame number: the lens as for one EXR, moved by the sequence flags, every frame's edges
//! extended by the largest CoC any frame rendered reaches, so that one context serves them all.
//! Every file must have the first's size and layer count; deep frames are made into layers for
//! their frame's lens.

use super::*;
use dof::io::GifPreview;
use dof::methods::one_shot::{Runner, method_input};
use dof::raster::{accumulate_with, peel_layers_with};
use dof::scene::guard_band::{auto_margin, auto_margin_mesh};

/// Most frames of a sequence.
pub(super) const MAX_FRAMES: u32 = 10_000;
/// The preview's frame time.
const GIF_DELAY_MS: u32 = 80;

/// Where the frames come from.
pub(super) enum Source<'a> {
    Builtin(&'a scene::Scene),
    Gltf {
        mesh: &'a MeshScene,
        near: f32,
    },
    /// The files of an EXR sequence, in frame order.
    Exr(&'a [PathBuf]),
}

/// The frames of a sequence: every frame of the shot (its moves span them all), and those this run
/// renders (`--frame-range`, else all).
pub(super) struct Plan {
    /// Each frame's number: an EXR sequence's from its file name, a built-in or glTF sequence's
    /// index. Outputs are named by it.
    pub numbers: Vec<u64>,
    /// An EXR sequence's files, one a frame; empty otherwise.
    pub files: Vec<PathBuf>,
    /// The indices rendered.
    pub selected: std::ops::Range<usize>,
}

impl Plan {
    /// Whether every frame of the shot is rendered (then a preview GIF is written too).
    pub fn whole(&self) -> bool {
        self.selected.len() == self.numbers.len()
    }

    /// The output of frame `i`: `OUT-1001.exr` beside `out` (at least four digits, as many as the
    /// shot's largest number needs, so that every part of a shot names its frames alike).
    pub fn path(&self, out: &Path, i: usize) -> PathBuf {
        let last = self.numbers.last().copied().unwrap_or(0);
        let digits = (last.max(1).ilog10() + 1).max(4) as usize;
        let stem = out.file_stem().and_then(|s| s.to_str()).unwrap_or("frame");
        out.with_file_name(format!("{stem}-{:0digits$}.exr", self.numbers[i]))
    }
}

/// The sequence `args` asks for, if any: an EXR sequence's files that match `--scene` (the first
/// `--frames N` of them when given), or `--frames N` of a built-in or glTF scene; narrowed to
/// `--frame-range`. Errors on a range with no sequence or outside the shot.
pub(super) fn plan(args: &RenderArgs) -> anyhow::Result<Option<Plan>> {
    let (numbers, files): (Vec<u64>, Vec<PathBuf>) = if super::exr_pattern::is_pattern(args.scene()) {
        let (found, _) = super::exr_pattern::frames(args.scene())?;
        let n = args.frames.map_or(found.len(), |n| n as usize);
        if n > found.len() {
            bail!("--frames {n}: the EXR sequence {} has {} frames", args.scene(), found.len());
        }
        if found.len() > MAX_FRAMES as usize && args.frames.is_none() && args.frame_range.is_none() {
            bail!(
                "the EXR sequence {} has {} frames, more than {MAX_FRAMES}: render a part with --frames N or --frame-range A:B",
                args.scene(),
                found.len()
            );
        }
        found.into_iter().take(n).unzip()
    } else if let Some(n) = args.frames {
        ((0..n as u64).collect(), Vec::new())
    } else {
        if args.frame_range.is_some() {
            bail!("--frame-range picks frames of a sequence: give --frames N (or an EXR sequence such as shot-####.exr)");
        }
        return Ok(None);
    };
    if numbers.is_empty() {
        bail!("the sequence has no frames");
    }
    let selected = match args.frame_range {
        None => 0..numbers.len(),
        Some((a, b)) => {
            let first = numbers.partition_point(|&n| n < a);
            let end = numbers.partition_point(|&n| n <= b);
            if first == end {
                bail!(
                    "--frame-range {a}:{b}: the sequence's frames are {} to {}, none of them in that range",
                    numbers[0],
                    numbers[numbers.len() - 1]
                );
            }
            if files.is_empty() && b >= numbers.len() as u64 {
                bail!("--frame-range {a}:{b}: the sequence has frames 0 to {} (--frames {})", numbers.len() - 1, numbers.len());
            }
            first..end
        }
    };
    if selected.len() > MAX_FRAMES as usize {
        bail!("--frame-range selects {} frames, more than {MAX_FRAMES} in one run", selected.len());
    }
    Ok(Some(Plan { numbers, files, selected }))
}

/// `dof render --scene shot-####.exr`: the sequence's frames through one context (module docs).
pub(super) fn render_exr_sequence(args: &RenderArgs, out: &Path) -> anyhow::Result<()> {
    if args.method == Method::Reference {
        bail!("the exact reference needs the scene's geometry; an EXR sequence has none (use a built-in scene)");
    }
    if args.background.is_some() {
        bail!("--background applies to built-in and glTF scenes; an EXR carries its background as the colour stored at depth +inf");
    }
    let (_, gaps) = super::exr_pattern::frames(args.scene())?;
    for (first, last) in gaps {
        let which = if first == last { format!("frame {first} is") } else { format!("frames {first} to {last} are") };
        eprintln!("note: {which} missing from {}; the sequence goes on with the next file", args.scene());
    }
    let plan = plan(args)?.context("an EXR sequence")?;
    let (first, last) = (plan.numbers[plan.selected.start], plan.numbers[plan.selected.end - 1]);
    println!("{}: {} frames, {first} … {last} (of {} in the shot)", args.scene(), plan.selected.len(), plan.numbers.len());
    let input = ExrInput::read(&plan.files[plan.selected.start..plan.selected.start + 1])?;
    let (camera, settings) = exr_camera(args, input.size())?;
    let lens = settings.thin_lens(&camera).with_context(|| lens_flags(args))?;
    let shots = shots(args, plan.numbers.len() as u32, &camera, &settings, &lens)?;
    render_sequence(args, out, Source::Exr(&plan.files), &shots, &plan)
}

/// One frame of an EXR sequence as layers for its shot (a deep frame's made for its lens), checked
/// against the first's size and layer count; what the reader found is noted when `notes` (the
/// first of the two reads of every file).
fn read_exr_frame(
    args: &RenderArgs,
    path: &Path,
    first: Option<&LayeredImage>,
    (camera, lens): &(Camera, ThinLens),
    notes: bool,
) -> anyhow::Result<(LayeredImage, ExrWindow)> {
    let input = ExrInput::read(&[path])?;
    if let Some(note) = input.note().filter(|_| notes) {
        eprintln!("note: {}: {note}", path.display());
    }
    let layers = exr_layers(args, &input, camera, lens, notes)?;
    if let Some(f) = first.filter(|f| (f.width, f.height, f.max_layers) != (layers.width, layers.height, layers.max_layers)) {
        bail!(
            "{} is {}x{} with {} layers, the sequence's first frame {}x{} with {}: every frame of a sequence has one size",
            path.display(),
            layers.width,
            layers.height,
            layers.max_layers,
            f.width,
            f.height,
            f.max_layers
        );
    }
    Ok((layers, input.window()))
}

/// An EXR frame as the sequence's loop takes a rendered one: its edges extended by `margin`, no
/// disocclusion buffer (an EXR carries none; its mask channel is not written).
fn exr_as_layers(frame: &LayeredImage, margin: u32) -> anyhow::Result<SceneLayers> {
    let stats = frame.stats();
    Ok(SceneLayers {
        layers: frame.extend_edges(margin)?,
        margin,
        mask: vec![false; frame.width as usize * frame.height as usize],
        with_mask: stats,
        without_mask: stats,
    })
}

/// The sequence's flags given, for errors about a frame's lens.
fn sequence_flags(args: &RenderArgs) -> String {
    let given = [
        (args.focus_to, "--focus-to"),
        (args.orbit, "--orbit"),
        (args.aperture_radius_to, "--aperture-radius-to"),
        (args.f_number_to, "--f-number-to"),
    ];
    given.iter().filter_map(|(v, flag)| v.map(|v| format!("{flag} {v}"))).collect::<Vec<_>>().join(", ")
}

/// The frames' cameras and lenses: linear from the start's to the end's.
pub(super) fn shots(
    args: &RenderArgs,
    n: u32,
    camera: &Camera,
    settings: &LensSettings,
    start: &ThinLens,
) -> anyhow::Result<Vec<(Camera, ThinLens)>> {
    let f0 = start.focus_distance;
    let r0 = start.aperture_radius;
    let r1 = match (args.aperture_radius_to, args.f_number_to) {
        (Some(r), _) => r,
        (_, Some(n)) => start.focal_length / (2.0 * n),
        _ => r0,
    };
    let forward = (camera.target - camera.eye).normalize_or_zero();
    let pivot = camera.eye + forward * f0;
    (0..n)
        .map(|i| {
            let t = if n > 1 { i as f32 / (n - 1) as f32 } else { 0.0 };
            let mut cam = *camera;
            if let Some(deg) = args.orbit {
                let turn = glam::Quat::from_rotation_y((deg * i as f32).to_radians());
                cam.eye = pivot + turn * (camera.eye - pivot);
                cam.target = pivot + turn * (camera.target - pivot);
                cam.up = turn * camera.up;
            }
            let mut s = *settings;
            s.focus = Focus::Distance(args.focus_to.map_or(f0, |f1| f0 + t * (f1 - f0)));
            s.aperture = Aperture::Radius(r0 + t * (r1 - r0));
            let lens = s.thin_lens(&cam).with_context(|| format!("frame {i}: {}, {}", lens_flags(args), sequence_flags(args)))?;
            Ok((cam, lens))
        })
        .collect()
}

/// Renders the frames `plan` selects of the sequence of `shots` (one a frame of the whole shot) from
/// `source`, and writes them, and the preview when the whole shot is rendered.
pub(super) fn render_sequence(
    args: &RenderArgs,
    out: &Path,
    source: Source,
    shots: &[(Camera, ThinLens)],
    plan: &Plan,
) -> anyhow::Result<()> {
    let mut b = backend(args.backend)?;
    let margin = match (&source, args.guard_band) {
        // An EXR's edges are extended as far as the largest CoC of any frame rendered reaches
        // (reading the rest of a long shot would defeat a farm's split; beyond the frames' own
        // largest CoC a wider extension adds nothing that reaches them).
        (Source::Exr(files), _) => {
            let mut largest = 0;
            let mut first = None;
            for i in plan.selected.clone() {
                let (frame, _) = read_exr_frame(args, &files[i], first.as_ref(), &shots[i], true)?;
                largest = largest.max(edge_margin(&frame, &shots[i].1));
                first.get_or_insert(frame);
            }
            largest
        }
        (_, GuardBand::Off) => 0,
        (_, GuardBand::Pixels(p)) => p,
        // Over every frame of the shot, so that any part of it renders its frames alike.
        (_, GuardBand::Auto) => {
            let mut largest = 0;
            for (camera, lens) in shots {
                let m = match &source {
                    Source::Builtin(s) => auto_margin(s, camera, lens, 1e-3 * lens.focus_distance)?,
                    Source::Gltf { mesh, near } => auto_margin_mesh(mesh.raster().triangle_positions(), camera, lens, *near)?,
                    Source::Exr(_) => unreachable!("an EXR sequence's margin is its edge policy's"),
                };
                largest = largest.max(m);
            }
            largest
        }
    };
    match (&source, margin) {
        (_, 0) => {}
        (Source::Exr(_), _) => {
            println!("edge policy: every frame's edge pixels extended by {margin} px (the largest CoC radius of any frame)")
        }
        _ => println!("guard band: {margin} px beyond every edge for every frame (the largest the frames need)"),
    }
    let options = args.layer_options(GuardBand::Pixels(margin));
    let method_options = method_options(args)?;
    let mut runner: Option<Runner> = None;
    // A mesh is uploaded once for the shot (its textures' mip chains built once), for the peels and
    // the accumulation buffers of every frame.
    let on_device = match &source {
        Source::Gltf { mesh, .. } => Some(DeviceMesh::upload(b.as_mut(), &mesh.raster())?),
        _ => None,
    };
    // The preview of the whole shot, encoded frame by frame as they come (one frame in memory).
    let gif_path = out.with_extension("gif");
    let mut preview: Option<GifPreview> = None;
    let rendered = (|| -> anyhow::Result<()> {
        for i in plan.selected.clone() {
            let (camera, lens) = &shots[i];
            // An EXR frame is written with its input's windows.
            let mut window = None;
            let layered = match &source {
                Source::Builtin(s) => raycast_layers(s, camera, lens, &options)?,
                Source::Gltf { mesh, near } => {
                    let on_device = on_device.as_ref().context("the uploaded mesh")?;
                    peel_layers_with(b.as_mut(), &mesh.raster(), on_device, camera, lens, *near, &options)?.image
                }
                Source::Exr(files) => {
                    let (frame, at) = read_exr_frame(args, &files[i], None, &shots[i], false)?;
                    window = Some(at);
                    exr_as_layers(&frame, margin)?
                }
            };
            let path = plan.path(out, i);
            let mut kernel_ms = None;
            let image = match args.method {
                Method::Layers => {
                    write_layered_exr(&path, &layered.frame_layers())?;
                    layered.front().0
                }
                Method::Pinhole => match &source {
                    Source::Builtin(s) => scene::pinhole(s, camera, &ReferenceOptions { spp: 16, ..Default::default() })?.image,
                    Source::Gltf { .. } | Source::Exr(_) => layered.front().0,
                },
                Method::Reference => match &source {
                    Source::Builtin(s) => match args.samples {
                        Some(spp) => scene::reference(s, camera, lens, &ReferenceOptions { spp, ..Default::default() })?.image,
                        None => scene::reference_auto(s, camera, lens, &AutoOptions::default())?.image,
                    },
                    Source::Exr(_) => bail!("the exact reference needs the scene's geometry"),
                    Source::Gltf { mesh, near } => {
                        let samples = args.samples.unwrap_or(256);
                        let opts = AccumulateOptions { samples, ..Default::default() };
                        let on_device = on_device.as_ref().context("the uploaded mesh")?;
                        accumulate_with(b.as_mut(), &mesh.raster(), on_device, camera, lens, *near, &opts)?.image
                    }
                },
                Method::Frame(method) => {
                    let input = method_input(method, &layered.layers);
                    if runner.is_none() {
                        let r = Runner::new(b.as_mut(), method, &method_options, &input)?;
                        println!(
                            "{} ({}): one context for the sequence, {}x{} with {} layers, {:.1} MB on the device",
                            method.title,
                            method.paper,
                            input.width,
                            input.height,
                            input.max_layers,
                            r.device_bytes() as f64 / 1e6
                        );
                        runner = Some(r);
                    }
                    let r = runner.as_mut().context("the context")?;
                    let out = r.frame(b.as_mut(), &input, lens)?;
                    kernel_ms = Some(out.stages.iter().map(|t| t.ms).filter(|m| m.is_finite()).sum::<f64>());
                    out.image.crop(margin)
                }
            };
            if args.method != Method::Layers {
                let (_, depth) = layered.front();
                let coc: Vec<f32> = depth.iter().map(|&z| lens.coc_px(z)).collect();
                let mask: Vec<f32> = layered.mask.iter().map(|&m| m as u32 as f32).collect();
                match &source {
                    Source::Exr(_) => {
                        write_exr_with(&path, &image, &[("Z", &depth), ("coc", &coc)], &ExrWriteOptions { window, ..Default::default() })?
                    }
                    _ => write_exr(&path, &image, &[("Z", &depth), ("coc", &coc), ("mask", &mask)])?,
                }
            }
            println!(
                "frame {}: focus {:.3}, aperture radius {:.2} mm, eye {:.3},{:.3},{:.3}{} -> {}",
                plan.numbers[i],
                lens.focus_distance,
                lens.aperture_radius * 1e3,
                camera.eye.x,
                camera.eye.y,
                camera.eye.z,
                kernel_ms.map_or(String::new(), |ms| format!(", {ms:.2} ms in kernels")),
                path.display()
            );
            if plan.whole() {
                if preview.is_none() {
                    preview = Some(GifPreview::create(&gif_path, image.width, image.height, args.exposure, GIF_DELAY_MS)?);
                }
                preview.as_mut().context("the preview")?.push(&image)?;
            }
        }
        Ok(())
    })();
    if let Some(mesh) = on_device {
        mesh.destroy(b.as_mut());
    }
    if let Some(r) = runner {
        if rendered.is_ok() {
            println!("context made once for {} frames: {} allocations in the frames after the first", r.frames, r.later_allocations);
        }
        r.destroy(b.as_mut());
    }
    rendered?;
    let (first, last) = (plan.path(out, plan.selected.start), plan.path(out, plan.selected.end - 1));
    let n = plan.selected.len();
    if !plan.whole() {
        println!("wrote {n} frames ({} … {}); no preview GIF for a part of the shot", first.display(), last.display());
        return Ok(());
    }
    preview.context("no frame for the preview")?.finish()?;
    println!("wrote {n} frames ({} … {}) and {}", first.display(), last.display(), gif_path.display());
    Ok(())
}
