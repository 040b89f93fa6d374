//! Order-correct depth of field from a deep image against flatten-then-defocus, the way a
//! compositor's ZDefocus-style node takes deep renders today (the deep image flattened to one colour
//! and one depth a pixel first). The numbers of docs/measurements.md, "Deep input".
//!
//! `cargo run --release -p dof --features eval --example deep_order -- [SPP] [WIDTH]`
//!
//! For each built-in scene, at WIDTH x WIDTH·9/16 (default 320):
//!
//! 1. **The deep image**: every surface along each pixel's centre ray (up to 16, no umbra
//!    threshold, no disocclusion buffer), as a deep render stores its samples.
//! 2. **The reference**: ray tracing through all of those samples (Lee et al. 2009's method over
//!    the full deep image) with SPP rays a pixel (default 1024).
//! 3. **Order-correct**: the deep image turned into layers for the lens (`DeepImage::layers`: the
//!    umbra threshold, 4 layers, the disocclusion buffer), then multi-layer tiled splatting.
//! 4. **Flatten, then defocus**: the flattened composite at its front depth, one layer, through
//!    multi-layer splatting (which then has no hidden layer) and through the gather.
//!
//! PSNR against the reference, over the frame and over the partial-occlusion region (the
//! disocclusion buffer of the scene's own layers).

use dof::Result;
use dof::backend::CpuBackend;
use dof::deep::{DeepImage, DeepSample};
use dof::frame::{MethodOptions, RaytraceOptions, registry};
use dof::layers::{Fragment, LayeredImage, RgbImage};
use dof::methods::one_shot::one_shot;
use dof::metrics::compare;
use dof::scene::{GuardBand, LayerOptions, ThinLens, builtin, builtin_names, raycast_layers};

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let spp: u32 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1024);
    let width: u32 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(320);
    let height = width * 9 / 16;
    let mut cpu = CpuBackend::new();
    println!(
        "{width}x{height}, reference: ray tracing through every deep sample, {spp} rays a pixel; PSNR dB, frame / partial-occlusion region"
    );
    println!(
        "| scene | samples/px | region | order-correct (deep to 4 layers, multi-layer splatting) | flatten, then multi-layer splatting | flatten, then gather |"
    );
    println!("|---|---|---|---|---|---|");
    for name in builtin_names() {
        let b = builtin(name)?.with_size(width, height);
        let lens = b.lens.thin_lens(&b.camera)?;
        let all =
            LayerOptions { max_layers: 16, umbra_threshold: false, disocclusion: false, guard_band: GuardBand::Off, ..Default::default() };
        let full = raycast_layers(&b.scene, &b.camera, &lens, &all)?.layers;
        let deep = deep_of(&full)?;
        let region = raycast_layers(&b.scene, &b.camera, &lens, &LayerOptions { guard_band: GuardBand::Off, ..Default::default() })?.mask;

        let reference_options = MethodOptions { raytrace: RaytraceOptions { spp, ..Default::default() }, ..Default::default() };
        let reference = one_shot(&mut cpu, registry::method("raytrace")?, &reference_options, &full, &lens)?.image;
        let (layers, _) = deep.layers(&b.camera.frame()?, &lens, &LayerOptions::default())?;
        let run = |cpu: &mut CpuBackend, method: &str, input: &LayeredImage, lens: &ThinLens| -> Result<RgbImage> {
            Ok(one_shot(cpu, registry::method(method)?, &MethodOptions::default(), input, lens)?.image)
        };
        let ours = run(&mut cpu, "multilayer", &layers, &lens)?;
        let flat = flattened(&deep)?;
        let flat_splat = run(&mut cpu, "multilayer", &flat, &lens)?;
        let flat_gather = run(&mut cpu, "gather", &flat, &lens)?;
        let score = |image: &RgbImage| -> Result<String> {
            let e = compare(image, &reference, Some(&region))?;
            Ok(format!("{:.2} / {:.2}", e.psnr_db, e.psnr_masked_db.unwrap_or(f64::NAN)))
        };
        let share = region.iter().filter(|&&m| m).count() as f64 / region.len() as f64;
        println!(
            "| {name} | {:.2} | {:.1}% | {} | {} | {} |",
            deep.samples.len() as f64 / deep.pixels() as f64,
            100.0 * share,
            score(&ours)?,
            score(&flat_splat)?,
            score(&flat_gather)?
        );
    }
    Ok(())
}

/// The deep image of every fragment of `layers` (point samples).
fn deep_of(layers: &LayeredImage) -> Result<DeepImage> {
    let l = layers.max_layers as usize;
    let mut samples = Vec::new();
    for (p, &n) in layers.counts.iter().enumerate() {
        for f in &layers.fragments[p * l..p * l + n as usize] {
            samples.push(DeepSample { color: f.color, alpha: f.alpha, z: f.depth, z_back: f.depth });
        }
    }
    DeepImage::from_counts(layers.width, layers.height, &layers.counts, samples)
}

/// One opaque layer a pixel: the flattened composite at the front sample's depth.
fn flattened(deep: &DeepImage) -> Result<LayeredImage> {
    let (rgb, depth) = deep.flatten();
    let mut out = LayeredImage::new(deep.width, deep.height, 1)?;
    for p in 0..deep.pixels() {
        if deep.count(p) > 0 {
            out.fragments[p] = Fragment { color: rgb.data[p], alpha: 1.0, depth: depth[p] };
            out.counts[p] = 1;
        }
    }
    Ok(out)
}
