//! What limits multi-layer splatting in the partial-occlusion region of `highlights`:
//! the numbers of docs/measurements.md, "Area-integrated layers", section "Where the region's
//! error comes from".
//!
//! `cargo run --release -p dof --features eval --example highlight_rims -- [SPP] [N,N,..] [OUT.exr]`
//! (`OUT.exr`: the aimed reference, to compare other renderers with through `dof compare`)
//! (or `cargo build --workspace --example highlight_rims` and `target/debug/examples/highlight_rims`).
//!
//! 1. **An aimed reference for the emitters** (`dof::scene::aimed`, what `ReferenceOptions::
//!    aimed_emitters` adds to the reference): the emitters' light integrated with samples aimed at
//!    each sphere, plus the uniform reference of the scene with the emitters black; two seeds are
//!    compared, and its energy against the uniform reference's.
//! 2. **Methods** (pinhole, multi-layer splatting unmerged, the gather) against both references.
//! 3. **Splat kernels and an oracle**: the emitters' fragments splatted on the host without
//!    occlusion (kernel 0 is splatting's own weight and reproduces the method's emitter image) with
//!    other kernels, and every sub-sample splatted from its own position (what a fragment with a
//!    sub-pixel position could do), and the resolve's clusters splatted from their centroids (what a
//!    slot with a sub-pixel position could do).

use dof::eval::methods::{MethodInput, evaluated_methods};
use dof::io::tonemap::tonemap;
use dof::layers::{LayeredImage, RgbImage};
use dof::metrics::{psnr_of_mse, squared_error};
use dof::scene::aimed::{aimed_emitters, emitters_only, without_emitters};
use dof::scene::{LayerOptions, ReferenceOptions, Scene, ThinLens, builtin, raycast_layers, reference};
use dof::{Backend, CpuBackend, Result};
use dof_shaders::resolve::grid_side;
use dof_shaders::splat::fragment::weight;

const WIDTH: u32 = 320;
const HEIGHT: u32 = 180;
/// Pixel points (per side) and lens points (per side) of the aimed estimator (`aimed::sides_for(1024)`).
const PIXEL_SIDE: u32 = 16;
const LENS_SIDE: u32 = 16;

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let spp: u32 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1024);
    let counts: Vec<u32> = args.get(2).map_or(vec![1, 4, 16], |s| s.split(',').filter_map(|v| v.parse().ok()).collect());
    let b = builtin("highlights")?.with_size(WIDTH, HEIGHT);
    let lens = b.thin_lens()?;
    let uniform = |scene: &Scene, seed: u64| -> Result<RgbImage> {
        Ok(reference(scene, &b.camera, &lens, &ReferenceOptions { spp, seed, ..Default::default() })?.image)
    };
    let full = [uniform(&b.scene, 0)?, uniform(&b.scene, 1)?];
    let base = uniform(&without_emitters(&b.scene)?, 0)?;
    let emit_uniform = uniform(&emitters_only(&b.scene)?, 0)?;
    let frame = b.camera.frame()?;
    let aimed = [0, 1].map(|seed| aimed_emitters(&b.scene, &frame, &lens, PIXEL_SIDE, LENS_SIDE, seed));
    let energy = |i: &RgbImage| i.data.iter().map(|p| p.iter().map(|&c| c as f64).sum::<f64>()).sum::<f64>();
    println!(
        "emitters' energy: aimed {:.5e} and {:.5e} (two seeds), uniform {spp} spp {:.5e}",
        energy(&aimed[0]),
        energy(&aimed[1]),
        energy(&emit_uniform)
    );
    let converged = add(&base, &aimed[0]);
    let converged_other = add(&base, &aimed[1]);
    if let Some(path) = args.get(3) {
        dof::io::write_exr(path, &converged, &[])?;
    }

    let mut cpu = CpuBackend::new();
    let backend: &mut dyn Backend = &mut cpu;
    let methods = evaluated_methods();
    for &n in &counts {
        let options = LayerOptions { subsamples: n, ..LayerOptions::default() };
        let layers = raycast_layers(&b.scene, &b.camera, &lens, &options)?;
        let mask = layers.mask.clone();
        let region = mask.iter().filter(|m| **m).count();
        let lit = mask.iter().zip(&aimed[0].data).filter(|(m, c)| **m && tonemap(**c, 1.0).iter().any(|&t| t >= 0.05)).count();
        println!(
            "\nN = {n}: region {region} px ({:.1}% of the frame), {lit} of them lit by the emitters; PSNR full / region (dB)",
            100.0 * region as f64 / mask.len() as f64
        );
        println!("  uniform {spp} spp, seed 1 against seed 0: {}", pair(&full[1], &full[0], &mask));
        println!("  aimed, seed 1 against seed 0:            {}", pair(&converged_other, &converged, &mask));
        println!("  uniform {spp} spp (seed 0) against aimed: {}", pair(&full[0], &converged, &mask));
        let emit_layers = raycast_layers(&emitters_only(&b.scene)?, &b.camera, &lens, &options)?;
        let rest_layers = raycast_layers(&without_emitters(&b.scene)?, &b.camera, &lens, &options)?;
        let mut splat_rest = None;
        let mut splat_emit = None;
        for m in methods.iter().filter(|m| ["pinhole", "multilayer", "gather"].contains(&m.name())) {
            let settings = m.settings(false);
            // Unmerged splatting; the gather at its widest radius.
            let setting = if m.name() == "gather" { settings[settings.len() - 1].clone() } else { settings[0].clone() };
            let run = |backend: &mut dyn Backend, l: &dof::scene::SceneLayers| -> Result<RgbImage> {
                let input = MethodInput::new(l.layers.clone(), lens, l.margin);
                Ok(input.crop(&m.run(backend, &input, &setting)?.image))
            };
            let image = run(backend, &layers)?;
            if m.name() == "multilayer" {
                splat_rest = Some(run(backend, &rest_layers)?);
                splat_emit = Some(run(backend, &emit_layers)?);
            }
            println!(
                "  {:10} against uniform {} | against aimed {} | share of the region's squared error in pixels the emitters light: {:.0}%",
                m.name(),
                pair(&image, &full[0], &mask),
                pair(&image, &converged, &mask),
                100.0 * emitter_share(&image, &converged, &aimed[0], &mask)
            );
        }
        let (Some(rest), Some(emit)) = (splat_rest, splat_emit) else { continue };
        for k in [Kernel::Splat, Kernel::WideRim, Kernel::DiscBox, Kernel::DiscBoxBox] {
            let sim = splat_host(&emit_layers.layers, &lens, emit_layers.margin, k);
            let total = add(&rest, &sim);
            println!(
                "  host splat, {:44}: against splatting's emitters {} | total against uniform {} | against aimed {}",
                k.name(),
                pair(&sim, &emit, &mask),
                pair(&total, &full[0], &mask),
                pair(&total, &converged, &mask)
            );
        }
        if n > 1 {
            let side = grid_side(n);
            let fine = builtin("highlights")?.with_size(WIDTH * side, HEIGHT * side);
            let fine_lens = fine.thin_lens()?;
            let no_buffer = LayerOptions { disocclusion: false, ..LayerOptions::default() };
            let fine_layers = raycast_layers(&emitters_only(&fine.scene)?, &fine.camera, &fine_lens, &no_buffer)?;
            let sim = splat_subsamples(&fine_layers.layers, &fine_lens, fine_layers.margin, side);
            let total = add(&rest, &sim);
            println!(
                "  oracle, each sub-sample from its own position: total against uniform {} | against aimed {}",
                pair(&total, &full[0], &mask),
                pair(&total, &converged, &mask)
            );
            // What a slot with a sub-pixel position could do: the resolve's clusters (5% depth
            // gap) splatted from their centroids; and, with no gap, each sub-sample on its own
            // (the oracle above with the kernel varied).
            for (gap, what) in [(0.05, "each pixel's clusters from their centroid"), (0.0, "each sub-sample from its own position")] {
                for k in [Kernel::Splat, Kernel::DiscBox] {
                    let sim = splat_groups(&fine_layers.layers, &fine_lens, fine_layers.margin, side, gap, k);
                    let total = add(&rest, &sim);
                    println!(
                        "  {what}, {:44}: total against uniform {} | against aimed {}",
                        k.name(),
                        pair(&total, &full[0], &mask),
                        pair(&total, &converged, &mask)
                    );
                }
            }
        }
    }
    Ok(())
}

fn add(a: &RgbImage, b: &RgbImage) -> RgbImage {
    let data = a.data.iter().zip(&b.data).map(|(p, q)| [p[0] + q[0], p[1] + q[1], p[2] + q[2]]).collect();
    RgbImage { width: a.width, height: a.height, data }
}

fn psnr(sum: f64, pixels: usize) -> f64 {
    psnr_of_mse(sum / (3 * pixels.max(1)) as f64)
}

/// "full / region" PSNR of `a` against `r` on the evaluation's display transform.
fn pair(a: &RgbImage, r: &RgbImage, mask: &[bool]) -> String {
    let (mut all, mut inside, mut n) = (0.0, 0.0, 0);
    for (i, &m) in mask.iter().enumerate() {
        let e = squared_error(a.data[i], r.data[i]);
        all += e;
        if m {
            inside += e;
            n += 1;
        }
    }
    format!("{:.2} / {:.2}", psnr(all, mask.len()), psnr(inside, n))
}

/// Share of the region's squared error in pixels the emitters light: where the emitters' light
/// alone (`emitters`, converged) tone-maps to at least 0.05 in some channel.
fn emitter_share(a: &RgbImage, r: &RgbImage, emitters: &RgbImage, mask: &[bool]) -> f64 {
    let (mut sat, mut all) = (0.0, 0.0);
    for (i, &m) in mask.iter().enumerate() {
        if m {
            let e = squared_error(a.data[i], r.data[i]);
            let t = tonemap(emitters.data[i], 1.0);
            all += e;
            if t[0].max(t[1]).max(t[2]) >= 0.05 {
                sat += e;
            }
        }
    }
    sat / all.max(f64::MIN_POSITIVE)
}

#[derive(Clone, Copy)]
enum Kernel {
    /// Splatting's weight: support r + 1/2, a linear rim 1 px wide.
    Splat,
    /// Support r + 1, a linear rim 2 px wide.
    WideRim,
    /// The CoC disc seen through the destination pixel's box (a point source at the centre).
    DiscBox,
    /// The CoC disc convolved with the source pixel's box and the destination's.
    DiscBoxBox,
}

impl Kernel {
    fn name(self) -> &'static str {
        match self {
            Kernel::Splat => "splatting's weight (r + 1/2, rim 1 px)",
            Kernel::WideRim => "r + 1, rim 2 px",
            Kernel::DiscBox => "disc through the destination box",
            Kernel::DiscBoxBox => "disc through source and destination boxes",
        }
    }

    /// Weight at offset `o` (pixel centre minus source) for CoC radius `r`.
    fn weight(self, o: [f32; 2], r: f32) -> f32 {
        let d2 = o[0] * o[0] + o[1] * o[1];
        let tent = |x: f32| (1.0 - x.abs()).max(0.0);
        match self {
            Kernel::Splat => weight(d2, r + 0.5, 1.0),
            Kernel::WideRim => weight(d2, r + 1.0, 2.0),
            Kernel::DiscBox | Kernel::DiscBoxBox => {
                // Midpoint rule over the box (or the tent of two boxes).
                let (g, half) = (24, if matches!(self, Kernel::DiscBoxBox) { 1.0 } else { 0.5 });
                let (mut inside, mut total) = (0.0f32, 0.0f32);
                for j in 0..g {
                    for i in 0..g {
                        let tx = -half + 2.0 * half * (i as f32 + 0.5) / g as f32;
                        let ty = -half + 2.0 * half * (j as f32 + 0.5) / g as f32;
                        let w = if matches!(self, Kernel::DiscBoxBox) { tent(tx) * tent(ty) } else { 1.0 };
                        if (o[0] + tx).powi(2) + (o[1] + ty).powi(2) < r * r {
                            inside += w;
                        }
                        total += w;
                    }
                }
                inside / total
            }
        }
    }
}

/// Adds `color` spread from `(cx, cy)` (frame pixels) with kernel `k` for CoC radius `r`,
/// normalised over the lattice, into `image`.
fn spread(image: &mut RgbImage, cx: f32, cy: f32, r: f32, k: Kernel, color: [f32; 3]) {
    let reach = (r + 2.0).ceil() as i32;
    let (px, py) = (cx.floor() as i32, cy.floor() as i32);
    let mut weights = Vec::new();
    for dy in -reach..=reach {
        for dx in -reach..=reach {
            let (qx, qy) = (px + dx, py + dy);
            let o = [qx as f32 + 0.5 - cx, qy as f32 + 0.5 - cy];
            let w = if r < 1e-3 { f32::from(dx == 0 && dy == 0) } else { k.weight(o, r) };
            weights.push((qx, qy, w));
        }
    }
    let sum: f32 = weights.iter().map(|w| w.2).sum();
    for (qx, qy, w) in weights {
        if w > 0.0 && qx >= 0 && qy >= 0 && (qx as u32) < image.width && (qy as u32) < image.height {
            let q = image.index(qx as u32, qy as u32);
            for c in 0..3 {
                image.data[q][c] += color[c] * w / sum;
            }
        }
    }
}

/// Every coloured fragment of `layers` (frame plus `margin`) splatted from its pixel centre with
/// kernel `k`, without occlusion, cut to the frame.
fn splat_host(layers: &LayeredImage, lens: &ThinLens, margin: u32, k: Kernel) -> RgbImage {
    let mut image = RgbImage::new(layers.width - 2 * margin, layers.height - 2 * margin);
    for y in 0..layers.height {
        for x in 0..layers.width {
            for f in layers.pixel(x, y) {
                if f.color != [0.0; 3] && f.depth.is_finite() {
                    let (cx, cy) = (x as f32 + 0.5 - margin as f32, y as f32 + 0.5 - margin as f32);
                    spread(&mut image, cx, cy, lens.coc_radius_px(f.depth), k, f.color);
                }
            }
        }
    }
    image
}

/// The oracle: point-sampled layers at `side` times the size, each sub-sample's coloured
/// fragments splatted from its own position (the disc through the destination box), weighted by
/// 1 / side².
fn splat_subsamples(fine: &LayeredImage, fine_lens: &ThinLens, fine_margin: u32, side: u32) -> RgbImage {
    let mut image = RgbImage::new(WIDTH, HEIGHT);
    let s = side as f32;
    for y in 0..fine.height {
        for x in 0..fine.width {
            for f in fine.pixel(x, y) {
                if f.color != [0.0; 3] && f.depth.is_finite() {
                    let cx = (x as f32 - fine_margin as f32 + 0.5) / s;
                    let cy = (y as f32 - fine_margin as f32 + 0.5) / s;
                    let color = f.color.map(|c| c / (s * s));
                    spread(&mut image, cx, cy, fine_lens.coc_radius_px(f.depth) / s, Kernel::DiscBox, color);
                }
            }
        }
    }
    image
}

/// The fragments a resolve with sub-pixel positions would make: per pixel, the coloured sub-sample
/// fragments of `fine` grouped by depth (a relative `gap`, as the resolve's clusters; 0 leaves
/// every sub-sample of distinct depth alone), each group splatted once from its sub-samples'
/// centroid with their summed colour / side², with kernel `k`.
fn splat_groups(fine: &LayeredImage, fine_lens: &ThinLens, fine_margin: u32, side: u32, gap: f32, k: Kernel) -> RgbImage {
    let mut image = RgbImage::new(WIDTH, HEIGHT);
    let s = side as f32;
    let m = fine_margin as i64;
    for py in -(m / side as i64 + 1)..(HEIGHT as i64 + m / side as i64 + 1) {
        for px in -(m / side as i64 + 1)..(WIDTH as i64 + m / side as i64 + 1) {
            // (depth, x, y, colour) of every coloured sub-sample fragment of pixel (px, py).
            let mut subs: Vec<(f32, f32, f32, [f32; 3])> = Vec::new();
            for j in 0..side as i64 {
                for i in 0..side as i64 {
                    let (fx, fy) = (px * side as i64 + i + m, py * side as i64 + j + m);
                    if fx < 0 || fy < 0 || fx >= fine.width as i64 || fy >= fine.height as i64 {
                        continue;
                    }
                    for f in fine.pixel(fx as u32, fy as u32) {
                        if f.color != [0.0; 3] && f.depth.is_finite() {
                            let cx = (fx as f32 - fine_margin as f32 + 0.5) / s;
                            let cy = (fy as f32 - fine_margin as f32 + 0.5) / s;
                            subs.push((f.depth, cx, cy, f.color));
                        }
                    }
                }
            }
            subs.sort_by(|a, b| a.0.total_cmp(&b.0));
            let mut start = 0;
            while start < subs.len() {
                let z0 = subs[start].0;
                let mut end = start;
                while end < subs.len() && subs[end].0 <= z0 * (1.0 + gap) {
                    end += 1;
                }
                let g = &subs[start..end];
                let n = g.len() as f32;
                let (cx, cy) = (g.iter().map(|v| v.1).sum::<f32>() / n, g.iter().map(|v| v.2).sum::<f32>() / n);
                let z = g.iter().map(|v| v.0).sum::<f32>() / n;
                let mut color = [0.0f32; 3];
                for v in g {
                    for c in 0..3 {
                        color[c] += v.3[c] / (s * s);
                    }
                }
                spread(&mut image, cx, cy, fine_lens.coc_radius_px(z) / s, k, color);
                start = end;
            }
        }
    }
    image
}
