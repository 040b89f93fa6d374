//! The reference with aimed emitter samples (`ReferenceOptions::aimed_emitters`, `dof::scene::aimed`):
//! the same light as the uniform reference, far less noise at saturated bokeh rims, the same image
//! where a scene has no emissive sphere, and refused where translucency would hide light from it.

use dof::layers::RgbImage;
use dof::metrics::psnr;
use dof::scene::{AutoOptions, Lighting, Material, Primitive, ReferenceOptions, Scene, Shape, Vec3, builtin, reference, reference_auto};

fn energy(image: &RgbImage) -> f64 {
    image.data.iter().map(|p| p.iter().map(|&c| c as f64).sum::<f64>()).sum()
}

#[test]
fn aimed_emitters_keep_the_light_and_converge_at_the_rims() {
    let b = builtin("highlights").unwrap().with_size(96, 54);
    let lens = b.thin_lens().unwrap();
    let render = |spp: u32, seed: u64, aimed_emitters: bool| {
        reference(&b.scene, &b.camera, &lens, &ReferenceOptions { spp, seed, aimed_emitters, ..Default::default() }).unwrap()
    };
    let (aimed, aimed_other) = (render(64, 0, true), render(64, 1, true));
    let (uniform, uniform_other) = (render(64, 0, false), render(64, 1, false));
    let dense = render(1024, 2, false);
    // The same light: the emitters' energy (which dominates the frame) against a dense uniform render.
    let (e, e_dense) = (energy(&aimed.image), energy(&dense.image));
    assert!((e / e_dense - 1.0).abs() < 0.01, "aimed {e:.6e} against uniform {e_dense:.6e}");
    // Two seeds agree far better aimed than uniform (display-transform PSNR; the rims dominate).
    let (agree_aimed, agree_uniform) =
        (psnr(&aimed_other.image, &aimed.image).unwrap(), psnr(&uniform_other.image, &uniform.image).unwrap());
    assert!(agree_aimed > agree_uniform + 10.0, "seeds agree to {agree_aimed:.2} dB aimed, {agree_uniform:.2} dB uniform");
    // The noise estimate says so too (34.2 against 26.2 dB when written).
    let (n_aimed, n_uniform) = (aimed.noise_psnr_db.unwrap(), uniform.noise_psnr_db.unwrap());
    assert!(n_aimed > n_uniform + 5.0, "noise estimates {n_aimed:.2} and {n_uniform:.2} dB");
    // The automatic reference takes the same path.
    let auto =
        reference_auto(&b.scene, &b.camera, &lens, &AutoOptions { max_spp: 64, aimed_emitters: true, ..Default::default() }).unwrap();
    assert!(auto.noise_psnr_db.unwrap() > n_uniform + 5.0, "auto: {:?}", auto.noise_psnr_db);
}

#[test]
fn a_scene_without_emissive_spheres_renders_as_without_the_option() {
    let b = builtin("simple").unwrap().with_size(64, 36);
    assert!(dof::scene::aimed::emitters(&b.scene).is_empty());
    let lens = b.thin_lens().unwrap();
    let render = |aimed_emitters: bool| {
        reference(&b.scene, &b.camera, &lens, &ReferenceOptions { spp: 16, aimed_emitters, ..Default::default() }).unwrap()
    };
    assert!(render(true) == render(false), "the same reference");
}

#[test]
fn translucency_in_front_of_an_emitter_is_refused() {
    let prims = vec![
        Primitive { shape: Shape::Sphere { center: Vec3::new(0.0, 0.0, -6.0), radius: 0.05 }, material: Material::Emissive([500.0; 3]) },
        Primitive {
            shape: Shape::Quad { corner: Vec3::new(-1.0, -1.0, -2.0), edge_u: Vec3::new(2.0, 0.0, 0.0), edge_v: Vec3::new(0.0, 2.0, 0.0) },
            material: Material::Emissive([0.2; 3]),
        },
    ];
    let scene = Scene::new(prims, Lighting::default()).unwrap().with_alpha(1, 0.5).unwrap();
    let b = builtin("highlights").unwrap().with_size(32, 18);
    let lens = b.thin_lens().unwrap();
    let err = reference(&scene, &b.camera, &lens, &ReferenceOptions { spp: 4, aimed_emitters: true, ..Default::default() }).unwrap_err();
    assert!(err.to_string().contains("translucent"), "{err}");
}
