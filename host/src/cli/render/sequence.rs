//! `dof render --frames N`: a sequence in one process. The shot's parameters move linearly over
//! the frames (focus distance to `--focus-to`, aperture radius to `--aperture-radius-to` or the
//! radius of `--f-number-to`, the camera `--orbit` degrees per frame about the vertical axis
//! through the start's point in focus on the view axis). A registry method renders every frame
//! through **one context** made once for the sequence's extent, with its input and output buffers:
//! per frame the layers are made (built-in scenes ray cast, glTF scenes depth-peeled), uploaded,
//! recorded, submitted and read back. The guard band is fixed for the sequence (`auto`: the largest
//! of the frames' own), so every frame has the same extent. The references and the pinhole image
//! render per frame with their own functions. Output: `OUT-0000.exr`, … beside `--out` and an
//! animated preview `OUT.gif` through the PNG previews' tone map.

use super::*;
use dof::io::write_gif_preview;
use dof::methods::one_shot::{Runner, method_input};
use dof::scene::guard_band::{auto_margin, auto_margin_mesh};

/// Most frames of a sequence.
pub(super) const MAX_FRAMES: u32 = 10_000;
/// The preview's frame time.
const GIF_DELAY_MS: u32 = 80;

/// Where the frames come from.
pub(super) enum Source<'a> {
    Builtin(&'a scene::Scene),
    Gltf { mesh: &'a MeshScene, near: f32 },
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
    camera: &Camera,
    settings: &LensSettings,
    start: &ThinLens,
) -> anyhow::Result<Vec<(Camera, ThinLens)>> {
    let n = args.frames.unwrap_or(1);
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

/// `OUT-0007.exr` beside `out` (at least four digits).
pub(super) fn frame_path(out: &Path, i: u32, frames: u32) -> PathBuf {
    let digits = (frames.saturating_sub(1).max(1).ilog10() + 1).max(4) as usize;
    let stem = out.file_stem().and_then(|s| s.to_str()).unwrap_or("frame");
    out.with_file_name(format!("{stem}-{i:0digits$}.exr"))
}

/// Renders the sequence of `shots` from `source` and writes its frames and preview.
pub(super) fn render_sequence(args: &RenderArgs, out: &Path, source: Source, shots: &[(Camera, ThinLens)]) -> anyhow::Result<()> {
    let n = shots.len() as u32;
    let mut b = backend(args.backend)?;
    let margin = match args.guard_band {
        GuardBand::Off => 0,
        GuardBand::Pixels(p) => p,
        GuardBand::Auto => {
            let mut largest = 0;
            for (camera, lens) in shots {
                let m = match &source {
                    Source::Builtin(s) => auto_margin(s, camera, lens, 1e-3 * lens.focus_distance)?,
                    Source::Gltf { mesh, near } => auto_margin_mesh(mesh.raster().triangle_positions(), camera, lens, *near)?,
                };
                largest = largest.max(m);
            }
            largest
        }
    };
    if margin > 0 {
        println!("guard band: {margin} px beyond every edge for every frame (the largest the frames need)");
    }
    let options = LayerOptions { max_layers: args.layers, guard_band: GuardBand::Pixels(margin), ..Default::default() };
    let method_options = method_options(args)?;
    let mut runner: Option<Runner> = None;
    let mut previews = Vec::with_capacity(shots.len());
    let rendered = (|| -> anyhow::Result<()> {
        for (i, (camera, lens)) in shots.iter().enumerate() {
            let i = i as u32;
            let layered = match &source {
                Source::Builtin(s) => raycast_layers(s, camera, lens, &options)?,
                Source::Gltf { mesh, near } => peel_layers(b.as_mut(), &mesh.raster(), camera, lens, *near, &options)?.image,
            };
            let path = frame_path(out, i, n);
            let mut kernel_ms = None;
            let image = match args.method {
                Method::Layers => {
                    write_layered_exr(&path, &layered.frame_layers())?;
                    layered.front().0
                }
                Method::Pinhole => match &source {
                    Source::Builtin(s) => scene::pinhole(s, camera, &ReferenceOptions { spp: 16, ..Default::default() })?.image,
                    Source::Gltf { .. } => layered.front().0,
                },
                Method::Reference => match &source {
                    Source::Builtin(s) => match args.samples {
                        Some(spp) => scene::reference(s, camera, lens, &ReferenceOptions { spp, ..Default::default() })?.image,
                        None => scene::reference_auto(s, camera, lens, &AutoOptions::default())?.image,
                    },
                    Source::Gltf { mesh, near } => {
                        let samples = args.samples.unwrap_or(256);
                        let opts = AccumulateOptions { samples, ..Default::default() };
                        accumulate(b.as_mut(), &mesh.raster(), camera, lens, *near, &opts)?.image
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
                write_exr(&path, &image, &[("Z", &depth), ("coc", &coc), ("mask", &mask)])?;
            }
            println!(
                "frame {i}: focus {:.3}, aperture radius {:.2} mm, eye {:.3},{:.3},{:.3}{} -> {}",
                lens.focus_distance,
                lens.aperture_radius * 1e3,
                camera.eye.x,
                camera.eye.y,
                camera.eye.z,
                kernel_ms.map_or(String::new(), |ms| format!(", {ms:.2} ms in kernels")),
                path.display()
            );
            previews.push(image);
        }
        Ok(())
    })();
    if let Some(r) = runner {
        if rendered.is_ok() {
            println!("context made once for {} frames: {} allocations in the frames after the first", r.frames, r.later_allocations);
        }
        r.destroy(b.as_mut());
    }
    rendered?;
    let gif = out.with_extension("gif");
    write_gif_preview(&gif, &previews, args.exposure, GIF_DELAY_MS)?;
    println!("wrote {n} frames ({} … {}) and {}", frame_path(out, 0, n).display(), frame_path(out, n - 1, n).display(), gif.display());
    Ok(())
}
