//! The CPU backend's copies of a pass compiled for AVX2 (`dof_shaders::pass_with_avx2!`) give the
//! same bits as the baseline copies: the splat walk over footprints, merged and unmerged, with a
//! circle and a shaped aperture. Its own test binary: the switch is process-wide.

use dof::aperture::{ApertureShape, parse_aperture};
use dof::backend::CpuBackend;
use dof::methods::splat::{Merge, SplatOptions, splat};
use dof::scene::{Camera, GuardBand, LayerOptions, builtin, raycast_layers};
use dof_shaders::lane::isa;

#[test]
fn avx2_and_baseline_copies_give_the_same_bits() {
    if !isa::avx2() {
        eprintln!("this CPU has no AVX2: both runs take the baseline copies");
    }
    let cases = [
        ("highlights", 4, Merge::None, ApertureShape::circle()),
        ("highlights", 16, Merge::X4, ApertureShape::circle()),
        ("railing", 4, Merge::X4, parse_aperture("blades:6").unwrap()),
    ];
    for (name, subsamples, merge, aperture) in cases {
        let aperture = aperture.clone();
        let scene = builtin(name).unwrap();
        let camera = Camera { width: 96, height: 54, ..scene.camera };
        let lens = scene.lens.thin_lens(&camera).unwrap();
        let options = LayerOptions { subsamples, guard_band: GuardBand::Pixels(2), ..LayerOptions::default() };
        let layers = raycast_layers(&scene.scene, &camera, &lens, &options).unwrap().layers;
        let o = SplatOptions { merge, aperture, ..Default::default() };
        let run = |avx2: bool| {
            isa::allow_avx2(avx2);
            let out = splat(&mut CpuBackend::new(), &layers, &lens, &o).unwrap();
            isa::allow_avx2(true);
            out.image.data
        };
        let (wide, baseline) = (run(true), run(false));
        assert!(wide.iter().flatten().any(|&c| c > 0.0), "{name}: an image");
        for (i, (a, b)) in wide.iter().zip(&baseline).enumerate() {
            assert!(
                a.map(f32::to_bits) == b.map(f32::to_bits),
                "{name}, {subsamples} sub-samples: pixel {i}: {a:?} with AVX2, {b:?} without"
            );
        }
    }
}
