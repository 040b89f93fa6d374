//! Scenes, cameras, the exact multi-layer image and the thin-lens reference.

use dof::Error;
use dof::layers::LayeredImage;
use dof::scene::{
    Aperture, AutoOptions, Camera, Focus, LayerOptions, LensSettings, Lighting, Material, Primitive, ReferenceOptions, Scene,
    Shape, Vec3, builtin, builtin_names, pinhole, raycast_layers, reference, reference_auto,
};

/// Writes a tone-mapped binary PPM (for looking at scenes while developing).
fn write_ppm(path: &std::path::Path, width: u32, height: u32, data: &[[f32; 3]]) {
    let mut bytes = format!("P6\n{width} {height}\n255\n").into_bytes();
    for c in data {
        for v in c {
            let t = dof::scene::tonemap(*v).powf(1.0 / 2.2);
            bytes.push((t * 255.0).round().clamp(0.0, 255.0) as u8);
        }
    }
    std::fs::write(path, bytes).unwrap();
}

/// `cargo test -p dof-tests --test scenes -- --ignored --nocapture report`: statistics of every
/// built-in scene at its default 640x360 and an auto reference; `DOF_DUMP_DIR=dir` also writes
/// PPMs of the pinhole image, the mask and the reference.
#[test]
#[ignore]
fn report() {
    let dump = std::env::var_os("DOF_DUMP_DIR").map(std::path::PathBuf::from);
    let skip_reference = std::env::var_os("DOF_NO_REFERENCE").is_some();
    let env_u32 = |k: &str| std::env::var(k).ok().and_then(|v| v.parse::<u32>().ok());
    let only = std::env::var("DOF_SCENES").ok();
    for name in builtin_names() {
        if only.as_ref().is_some_and(|o| !o.split(',').any(|n| n == *name)) {
            continue;
        }
        let s = builtin(name).unwrap();
        let lens = s.thin_lens().unwrap();
        let t = std::time::Instant::now();
        let ml = raycast_layers(&s.scene, &s.camera, &lens, &LayerOptions::default()).unwrap();
        let dt = t.elapsed();
        println!(
            "{name}: far limit {:.1} px; layers: with mask {:.3} fragments/px, {:.1}% multi-layer; without mask {:.3} fragments/px, {:.1}% multi-layer; mask {:.1}% ({:.2?})",
            lens.far_limit_px(),
            ml.with_mask.fragments_per_pixel(),
            100.0 * ml.with_mask.multi_layer_share(),
            ml.without_mask.fragments_per_pixel(),
            100.0 * ml.without_mask.multi_layer_share(),
            100.0 * ml.mask_share(),
            dt
        );
        if let Some(dir) = &dump {
            let (front, _) = ml.layers.front();
            write_ppm(&dir.join(format!("{name}_front.ppm")), front.width, front.height, &front.data);
            let mask: Vec<[f32; 3]> = (0..ml.mask.len())
                .map(|p| {
                    let c = ml.layers.counts[p] as f32;
                    if ml.mask[p] { [0.3 * c, 0.3 * c, 0.3 * c] } else { [0.0, 0.0, 0.1] }
                })
                .collect();
            write_ppm(&dir.join(format!("{name}_mask.ppm")), front.width, front.height, &mask);
        }
        if skip_reference {
            continue;
        }
        let t = std::time::Instant::now();
        let r = match env_u32("DOF_SPP") {
            Some(spp) => reference(&s.scene, &s.camera, &lens, &ReferenceOptions { spp, progress: true, ..Default::default() }).unwrap(),
            None => {
                let max_spp = env_u32("DOF_MAX_SPP").unwrap_or(AutoOptions::default().max_spp);
                reference_auto(&s.scene, &s.camera, &lens, &AutoOptions { progress: true, max_spp, ..Default::default() }).unwrap()
            }
        };
        println!(
            "{name}: reference {} spp, noise estimate {:.2} dB (required {:.2} dB{}), {:.1?}",
            r.spp,
            r.noise_psnr_db.unwrap(),
            r.required_psnr_db.unwrap_or(f64::NAN),
            if r.capped { ", CAPPED" } else { "" },
            t.elapsed()
        );
        if let Some(dir) = &dump {
            write_ppm(&dir.join(format!("{name}_reference.ppm")), r.image.width, r.image.height, &r.image.data);
        }
    }
}

