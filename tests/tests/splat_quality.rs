//! Tiled splatting against the exact references of the built-in scenes: multi-layer beats
//! single-layer and the gathering baseline inside the partial-occlusion region, and 4x4 merging
//! shortens the lists at a bounded cost in error.

use dof::backend::CpuBackend;
use dof::methods::gather::gather;
use dof::methods::splat::{Merge, SplatOptions, splat};
use dof::metrics::compare;
use dof::scene::{LayerOptions, ReferenceOptions, builtin, raycast_layers, reference};

#[test]
fn explore() {
    for name in std::env::var("SCENES").unwrap_or("simple,railing,columns,highlights".into()).split(',').map(String::from).collect::<Vec<_>>().iter().map(|s| s.as_str()) {
        let scene = builtin(name).unwrap().with_size(std::env::var("W").map_or(320, |w| w.parse().unwrap()), std::env::var("H").map_or(180, |w| w.parse().unwrap()));
        let lens = scene.thin_lens().unwrap();
        let layers = raycast_layers(&scene.scene, &scene.camera, &lens, &LayerOptions::default()).unwrap();
        let (front, depth) = layers.layers.front();
        let exact = reference(&scene.scene, &scene.camera, &lens, &ReferenceOptions { spp: 256, ..Default::default() }).unwrap();
        let mut cpu = CpuBackend::new();
        let g = gather(&mut cpu, &front, &depth, &lens, None).unwrap();
        let eg = compare(&g.image, &exact.image, Some(&layers.mask)).unwrap();
        let ep = compare(&front, &exact.image, Some(&layers.mask)).unwrap();
        println!("{name}: pinhole {:.2}/{:.2} gather {:.2}/{:.2}", ep.psnr_db, ep.psnr_masked_db.unwrap(), eg.psnr_db, eg.psnr_masked_db.unwrap());
        for slab in [1.0f32, 1.01, 1.03, 1.1, 1.3, 2.0, 1e9] {
            let o = SplatOptions { slab_ratio: slab, ..Default::default() };
            let multi = splat(&mut cpu, &layers.layers, &lens, &o).unwrap();
            let em = compare(&multi.image, &exact.image, Some(&layers.mask)).unwrap();
            println!("  slab {slab}: multi {:.2}/{:.2}", em.psnr_db, em.psnr_masked_db.unwrap());
        }
        for merge in [Merge::None, Merge::X2, Merge::X4] {
            let o = SplatOptions { merge, ..Default::default() };
            let single = splat(&mut cpu, &layers.layers.front_layer(), &lens, &o).unwrap();
            let multi = splat(&mut cpu, &layers.layers, &lens, &o).unwrap();
            let es = compare(&single.image, &exact.image, Some(&layers.mask)).unwrap();
            let em = compare(&multi.image, &exact.image, Some(&layers.mask)).unwrap();
            println!(
                "  merge {:?}: single {:.2}/{:.2} (mean list {:.0}) multi {:.2}/{:.2} (mean list {:.0})",
                merge, es.psnr_db, es.psnr_masked_db.unwrap(), single.report.mean_list_length(), em.psnr_db, em.psnr_masked_db.unwrap(), multi.report.mean_list_length()
            );
            if merge == Merge::None {
                let dir = std::path::Path::new("/tmp/splat");
                std::fs::create_dir_all(dir).unwrap();
                dof::io::write_png_preview(dir.join(format!("{name}-multi.png")), &multi.image, 1.0).unwrap();
                dof::io::write_png_preview(dir.join(format!("{name}-gather.png")), &g.image, 1.0).unwrap();
                dof::io::write_png_preview(dir.join(format!("{name}-ref.png")), &exact.image, 1.0).unwrap();
                dof::io::write_png_preview(dir.join(format!("{name}-front.png")), &front, 1.0).unwrap();
            }
            if merge == Merge::X4 {
                println!("{}", multi.report.summary());
            }
        }
    }
}
