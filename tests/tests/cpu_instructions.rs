//! The CPU backend's copies of a pass compiled for AVX2 and AVX-512 (`dof_shaders::pass_with_simd!`)
//! give the same bits as the baseline copies: the splat walk over footprints, merged and unmerged, with a
//! circle and a shaped aperture. Its own test binary: the switch is process-wide.

use dof::aperture::{ApertureShape, parse_aperture};
use dof::backend::CpuBackend;
use dof::methods::splat::{Merge, SplatOptions, splat};
use dof::scene::{Camera, GuardBand, LayerOptions, builtin, raycast_layers};
use dof_shaders::lane::isa::{self, Isa};

#[test]
fn every_copy_gives_the_baseline_bits() {
    let widest = isa::current();
    if widest != Isa::Avx512 {
        eprintln!("this CPU's widest copy is {widest:?}: the copies beyond it run as that one");
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
        let run = |copy: Isa| {
            isa::limit(copy);
            let out = splat(&mut CpuBackend::new(), &layers, &lens, &o).unwrap();
            isa::limit(Isa::Avx512);
            out.image.data
        };
        let baseline = run(Isa::Baseline);
        assert!(baseline.iter().flatten().any(|&c| c > 0.0), "{name}: an image");
        for copy in [Isa::Avx2, Isa::Avx512] {
            let wide = run(copy);
            for (i, (a, b)) in wide.iter().zip(&baseline).enumerate() {
                assert!(
                    a.map(f32::to_bits) == b.map(f32::to_bits),
                    "{name}, {subsamples} sub-samples: pixel {i}: {a:?} with {copy:?}, {b:?} with the baseline copy"
                );
            }
        }
    }
}
