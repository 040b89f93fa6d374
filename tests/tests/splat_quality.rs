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
        let base = splat(&mut cpu, &layers.layers, &lens, &SplatOptions::default()).unwrap();
        for (mr, dr, tol) in [(2.0f32, 1.05f32, 0.1f32), (1.5, 1.1, 0.25), (1.0, 1.2, 0.5), (2.0, 1.2, 0.5), (3.0, 1.3, 1.0)] {
            let o = SplatOptions { merge: Merge::X4, merge_min_radius: mr, merge_depth_ratio: dr, merge_color_tol: tol, ..Default::default() };
            let multi = splat(&mut cpu, &layers.layers, &lens, &o).unwrap();
            let em = compare(&multi.image, &exact.image, Some(&layers.mask)).unwrap();
            println!("  x4 {mr} {dr} {tol}: multi {:.2}/{:.2} lists {:.0} -> {:.0} ({:.1}x)", em.psnr_db, em.psnr_masked_db.unwrap(), base.report.mean_list_length(), multi.report.mean_list_length(), base.report.mean_list_length() / multi.report.mean_list_length());
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
