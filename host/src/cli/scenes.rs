//! `dof scenes`: the built-in scenes with their lens, multi-layer statistics (with and without the
//! disocclusion buffer) and, on request, how many reference samples they need.

use dof::io::write_png_preview;
use dof::layers::RgbImage;
use dof::scene::{AutoOptions, LayerOptions, builtin, builtin_names, raycast_layers, reference_auto};
use std::path::PathBuf;
use std::time::Instant;

#[derive(clap::Args)]
pub struct ScenesArgs {
    /// Only these scenes (comma-separated); default all.
    #[arg(long, value_delimiter = ',')]
    only: Vec<String>,
    /// Also compute each scene's automatic reference (raising the sample count until its noise,
    /// full frame and inside the disocclusion buffer, allows measuring methods up to 40 dB within
    /// 0.5 dB) and report the samples it took. Slow: minutes per scene.
    #[arg(long)]
    reference: bool,
    /// Sample cap of the automatic reference.
    #[arg(long, default_value_t = 4096)]
    max_spp: u32,
    /// Write PNGs of the pinhole image, the disocclusion buffer and the reference here.
    #[arg(long)]
    dump: Option<PathBuf>,
}

pub fn run(args: &ScenesArgs) -> anyhow::Result<()> {
    if let Some(dir) = &args.dump {
        std::fs::create_dir_all(dir)?;
    }
    for &name in builtin_names() {
        if !args.only.is_empty() && !args.only.iter().any(|o| o == name) {
            continue;
        }
        let scene = builtin(name)?;
        let lens = scene.thin_lens()?;
        let start = Instant::now();
        let ml = raycast_layers(&scene.scene, &scene.camera, &lens, &LayerOptions::default())?;
        let (w, wo) = (ml.with_mask, ml.without_mask);
        println!(
            "{name} ({}x{}): {}\n  far-field CoC {:.1} px; layers (L = 4, umbra threshold): {:.3} fragments/px, {:.1}% multi-layer with the disocclusion buffer ({:.1}% of pixels), {:.3} and {:.1}% without; ray cast in {:.2?}",
            scene.camera.width, scene.camera.height, scene.description, lens.far_limit_px(),
            w.fragments_per_pixel(), 100.0 * w.multi_layer_share(), 100.0 * ml.mask_share(),
            wo.fragments_per_pixel(), 100.0 * wo.multi_layer_share(), start.elapsed()
        );
        if let Some(dir) = &args.dump {
            let (front, _) = ml.layers.front();
            write_png_preview(dir.join(format!("{name}-pinhole.png")), &front, 1.0)?;
            let mut mask = RgbImage::new(front.width, front.height);
            for (p, m) in ml.mask.iter().enumerate() {
                let layers = ml.layers.counts[p] as f32;
                mask.data[p] = if *m { [0.25 * layers; 3] } else { [0.0, 0.0, 0.05] };
            }
            write_png_preview(dir.join(format!("{name}-mask.png")), &mask, 1.0)?;
        }
        if args.reference {
            let start = Instant::now();
            let options = AutoOptions { progress: true, max_spp: args.max_spp, region: Some(ml.mask.clone()), ..Default::default() };
            let r = reference_auto(&scene.scene, &scene.camera, &lens, &options)?;
            let db = |v: Option<f64>| v.map_or("n/a".into(), |v| format!("{v:.2} dB"));
            println!(
                "  reference: {} spp, noise {} full frame, {} inside the buffer (required {}){}, {:.1?}",
                r.spp, db(r.noise_psnr_db), db(r.region_noise_psnr_db), db(r.required_psnr_db),
                if r.capped { ", sample cap reached" } else { "" }, start.elapsed()
            );
            if let Some(dir) = &args.dump {
                write_png_preview(dir.join(format!("{name}-reference.png")), &r.image, 1.0)?;
            }
        }
    }
    Ok(())
}
