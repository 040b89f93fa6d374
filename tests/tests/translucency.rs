//! Translucent surfaces in the ground truth: the analytic scenes' opacity, the exact
//! thin-lens reference and ray caster on a single pane against the analytic "over", energy, the
//! accumulation buffer blending `BLEND` surfaces in depth order (both panes' orders, both
//! backends), the built-in translucent scenes through glTF (`alphaMode: BLEND`) and Mitsuba (a
//! `mask` BSDF).

use dof::backend::{Backend, CpuBackend};
use dof::metrics::psnr;
use dof::raster::{AccumulateOptions, accumulate, default_near};
use dof::scene::{
    Camera, ExportOptions, GuardBand, LayerOptions, Lighting, Material, MeshScene, MitsubaExport, MitsubaOptions, Primitive,
    ReferenceOptions, Scene, Shape, ThinLens, Vec3, builtin, export_glb, export_mitsuba, load_gltf_slice, pinhole, raycast_layers,
    reference,
};
use dof_shaders::raster::mesh::{ALPHA_BLEND, MeshMaterial, MeshVertex, UNLIT};

const FRONT: [f32; 3] = [0.9, 0.3, 0.1];
const BACK: [f32; 3] = [0.1, 0.5, 0.8];
const SKY: [f32; 3] = [0.4, 0.6, 0.9];

fn facing_quad(x0: f32, y0: f32, x1: f32, y1: f32, z: f32) -> Shape {
    Shape::Quad { corner: Vec3::new(x0, y0, z), edge_u: Vec3::new(x1 - x0, 0.0, 0.0), edge_v: Vec3::new(0.0, y1 - y0, 0.0) }
}

/// A pane of opacity `alpha` at depth `pane_z` over a wall at 6 filling the lower half of the view
/// (sky above), seen at 64x48 from the origin looking down −Z.
fn pane_scene(alpha: f32, pane_z: f32) -> (Scene, Camera) {
    let prims = vec![
        Primitive { shape: facing_quad(-20.0, -20.0, 20.0, 0.0, -6.0), material: Material::Emissive(BACK) },
        Primitive {
            shape: facing_quad(-0.6 * pane_z, -0.3 * pane_z, 0.6 * pane_z, 0.3 * pane_z, -pane_z),
            material: Material::Emissive(FRONT),
        },
    ];
    let scene = Scene::new(prims, Lighting::default()).unwrap().with_background(SKY).unwrap().with_alpha(1, alpha).unwrap();
    (scene, Camera::look_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0), 60f32.to_radians(), 64, 48))
}

fn lens(focus: f32, radius: f32) -> ThinLens {
    ThinLens { focal_length: 0.05, aperture_radius: radius, focus_distance: focus, pixels_per_unit: 48.0 / 0.024 }
}

fn over(alpha: f32, front: [f32; 3], back: [f32; 3]) -> [f32; 3] {
    [0, 1, 2].map(|k| alpha * front[k] + (1.0 - alpha) * back[k])
}

fn close(a: [f32; 3], b: [f32; 3], tol: f32) -> bool {
    a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= tol)
}

#[test]
fn opacity_is_validated() {
    let (scene, _) = pane_scene(1.0, 3.0);
    for bad in [f32::NAN, -0.1, 1.5] {
        let e = scene.clone().with_alpha(1, bad).unwrap_err().to_string();
        assert!(e.contains("[0, 1]"), "{bad}: {e}");
    }
    assert!(scene.clone().with_alpha(7, 0.5).unwrap_err().to_string().contains("no primitive 7"));
    let ball = Scene::new(
        vec![Primitive { shape: Shape::Sphere { center: Vec3::new(0.0, 0.0, -4.0), radius: 1.0 }, material: Material::Emissive(FRONT) }],
        Lighting::default(),
    )
    .unwrap();
    assert!(ball.with_alpha(0, 0.5).unwrap_err().to_string().contains("only quads and planes"));
    assert!(!scene.has_translucency());
    assert!(scene.with_alpha(1, 0.5).unwrap().has_translucency());
}

#[test]
fn an_in_focus_pane_shows_alpha_front_plus_the_rest_of_what_lies_behind() {
    for alpha in [0.0, 0.35, 0.6, 1.0] {
        // In focus at the pane: every lens ray through a pixel meets the pane at the same point.
        let (scene, camera) = pane_scene(alpha, 3.0);
        let thin = lens(3.0, 0.05);
        let r = reference(&scene, &camera, &thin, &ReferenceOptions { spp: 64, ..Default::default() }).unwrap();
        let p = pinhole(&scene, &camera, &ReferenceOptions { spp: 1, jitter: false, ..Default::default() }).unwrap();
        let at = |img: &dof::layers::RgbImage, x: usize, y: usize| img.data[y * 64 + x];
        // Below the horizon over the wall, above it over the sky; far enough in that the wall's
        // own edge (out of focus behind the pane) does not reach the pixel.
        for (x, y, back) in [(32, 30, BACK), (32, 17, SKY)] {
            let want = over(alpha, FRONT, back);
            assert!(close(at(&p.image, x, y), want, 1e-6), "alpha {alpha} pinhole at ({x}, {y}): {:?}, want {want:?}", at(&p.image, x, y));
            assert!(
                close(at(&r.image, x, y), want, 1e-5),
                "alpha {alpha} reference at ({x}, {y}): {:?}, want {want:?}",
                at(&r.image, x, y)
            );
        }
    }
}

#[test]
fn the_ray_caster_keeps_a_translucent_fragment_and_what_it_does_not_hide() {
    let (scene, camera) = pane_scene(0.35, 1.5);
    let thin = lens(6.0, 0.02);
    let options = LayerOptions { guard_band: GuardBand::Off, ..Default::default() };
    let ml = raycast_layers(&scene, &camera, &thin, &options).unwrap();
    let l = ml.layers.max_layers as usize;
    // The pane's centre row, over the wall: outside the disocclusion buffer, yet two fragments.
    let p = 30 * 64 + 32;
    assert!(!ml.mask[p], "the pixel lies inside the pane, away from every edge");
    assert_eq!(ml.layers.counts[p], 2, "the pane and the wall it does not hide");
    let (front, back) = (ml.layers.fragments[p * l], ml.layers.fragments[p * l + 1]);
    assert_eq!((front.alpha, front.color), (0.35, FRONT.map(|c| c * 0.35)), "premultiplied colour");
    assert_eq!((back.alpha, back.color), (1.0, BACK));
    assert!((front.depth - 1.5).abs() < 1e-5 && (back.depth - 6.0).abs() < 1e-5, "{} {}", front.depth, back.depth);
    // Over the sky: the pane, then the background at infinity.
    let q = 17 * 64 + 32;
    assert_eq!(ml.layers.counts[q], 2);
    assert_eq!(ml.layers.fragments[q * l + 1].depth, f32::INFINITY);
    // The same pane opaque keeps one fragment there; of opacity 0 it is not a fragment at all.
    let opaque = raycast_layers(&pane_scene(1.0, 1.5).0, &camera, &thin, &options).unwrap();
    assert_eq!(opaque.layers.counts[p], 1);
    let clear = raycast_layers(&pane_scene(0.0, 1.5).0, &camera, &thin, &options).unwrap();
    assert_eq!((clear.layers.counts[p], clear.layers.fragments[p * l].alpha), (1, 1.0), "the wall alone");
}

#[test]
fn a_full_pixel_keeps_what_its_translucent_last_slot_lets_through() {
    // Six panes of opacity 0.3 at depths 1.5 .. 2.75 in front of the wall (and the sky above it):
    // more translucent surfaces than the 4 slots. The last slot takes the rest "over" (the fourth
    // pane, the two behind it, then the wall or the sky), so the pixel's composite is exact.
    let colours = [[0.9, 0.1, 0.1], [0.1, 0.9, 0.1], [0.1, 0.1, 0.9], [0.8, 0.8, 0.1], [0.1, 0.8, 0.8], [0.8, 0.1, 0.8]];
    let mut prims = vec![Primitive { shape: facing_quad(-20.0, -20.0, 20.0, 0.0, -6.0), material: Material::Emissive(BACK) }];
    for (i, c) in colours.iter().enumerate() {
        let z = 1.5 + 0.25 * i as f32;
        prims.push(Primitive { shape: facing_quad(-0.6 * z, -0.3 * z, 0.6 * z, 0.3 * z, -z), material: Material::Emissive(*c) });
    }
    let mut scene = Scene::new(prims, Lighting::default()).unwrap().with_background(SKY).unwrap();
    for i in 1..=colours.len() {
        scene = scene.with_alpha(i, 0.3).unwrap();
    }
    let camera = Camera::look_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0), 60f32.to_radians(), 64, 48);
    let options = LayerOptions { guard_band: GuardBand::Off, disocclusion: false, ..Default::default() };
    let ml = raycast_layers(&scene, &camera, &lens(6.0, 0.02), &options).unwrap();
    let l = ml.layers.max_layers as usize;
    assert_eq!(l, 4);
    let (image, _) = ml.layers.front();
    for (x, y, back) in [(32usize, 30usize, BACK), (32, 17, SKY)] {
        let p = y * 64 + x;
        assert_eq!(ml.layers.counts[p], 4, "({x}, {y}): full");
        let last = ml.layers.fragments[p * l + 3];
        assert!((last.depth - 2.25).abs() < 1e-5, "the last slot keeps the fourth pane's depth: {}", last.depth);
        assert!((last.alpha - 1.0).abs() < 1e-6, "and hides all behind it once the wall or sky is in: {}", last.alpha);
        let want = colours.iter().rev().fold(back, |behind, c| over(0.3, *c, behind));
        assert!(close(image.data[p], want, 1e-5), "({x}, {y}): {:?}, want {want:?}", image.data[p]);
    }
}

#[test]
fn blur_through_a_pane_keeps_the_energy() {
    // A pane out of focus in the middle of a uniform wall, all inside the frame with its blur: the
    // thin lens moves light between pixels but neither adds nor removes it.
    let prims = vec![
        Primitive { shape: facing_quad(-30.0, -30.0, 30.0, 30.0, -6.0), material: Material::Emissive(BACK) },
        Primitive { shape: facing_quad(-0.3, -0.2, 0.3, 0.2, -1.5), material: Material::Emissive(FRONT) },
    ];
    let scene = Scene::new(prims, Lighting::default()).unwrap().with_alpha(1, 0.6).unwrap();
    let camera = Camera::look_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0), 60f32.to_radians(), 64, 48);
    let thin = lens(6.0, 0.15);
    let blurred = reference(&scene, &camera, &thin, &ReferenceOptions { spp: 256, ..Default::default() }).unwrap();
    let sharp = pinhole(&scene, &camera, &ReferenceOptions { spp: 256, ..Default::default() }).unwrap();
    let total = |img: &dof::layers::RgbImage| img.data.iter().map(|c| c[0] as f64).sum::<f64>();
    let (b, s) = (total(&blurred.image), total(&sharp.image));
    assert!((b - s).abs() <= 2e-3 * s, "energy: blurred {b}, pinhole {s}");
    // And the blur does something: the pane's edge pixels differ.
    let diff = blurred.image.data.iter().zip(&sharp.image.data).map(|(x, y)| (x[0] - y[0]).abs()).fold(0.0f32, f32::max);
    assert!(diff > 0.05, "largest difference {diff}");
}

/// A wall at 8 and two blended panes at `za` (red) and `zb` (blue), each of opacity 0.5, unlit.
fn blended_panes(za: f32, zb: f32) -> MeshScene {
    let mut m = MeshScene::default();
    let material = |rgb: [f32; 3], blend: bool| MeshMaterial {
        base: [rgb[0], rgb[1], rgb[2], if blend { 0.5 } else { 1.0 }],
        flags: UNLIT | if blend { ALPHA_BLEND } else { 0 },
        ..MeshMaterial::default()
    };
    m.materials.extend([material([0.1, 0.8, 0.1], false), material([1.0, 0.0, 0.0], true), material([0.0, 0.0, 1.0], true)]);
    for (i, (half, z)) in [(20.0, 8.0), (1.0, za), (1.0, zb)].into_iter().enumerate() {
        let base = m.vertices.len() as u32;
        for (x, y) in [(-half, -half), (half, -half), (half, half), (-half, half)] {
            m.vertices.push(MeshVertex { position: [x, y, -z], normal: [0.0, 0.0, 1.0], ..MeshVertex::default() });
        }
        m.triangles.push([base, base + 1, base + 2, i as u32]);
        m.triangles.push([base, base + 2, base + 3, i as u32]);
    }
    m
}

fn blend_order_on(b: &mut dyn Backend) {
    let camera = Camera::look_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0), 40f32.to_radians(), 32, 24);
    // A pinhole-sized aperture: every render sees the centre pixel alike.
    let thin = lens(5.0, 1e-6);
    let options = AccumulateOptions { samples: 4, ..Default::default() };
    let centre = |m: &MeshScene, b: &mut dyn Backend| {
        let acc = accumulate(b, &m.raster(), &camera, &thin, default_near(thin.focus_distance), &options).unwrap();
        acc.image.data[12 * 32 + 16]
    };
    let (red, blue, wall) = ([1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.1, 0.8, 0.1]);
    let red_first = centre(&blended_panes(2.0, 3.0), b);
    let blue_first = centre(&blended_panes(3.0, 2.0), b);
    let expect = |near: [f32; 3], far: [f32; 3]| over(0.5, near, over(0.5, far, wall));
    assert!(close(red_first, expect(red, blue), 1e-5), "red in front: {red_first:?}, want {:?}", expect(red, blue));
    assert!(close(blue_first, expect(blue, red), 1e-5), "blue in front: {blue_first:?}, want {:?}", expect(blue, red));
    assert!((red_first[0] - blue_first[0]).abs() > 0.2, "the order must matter: {red_first:?} {blue_first:?}");
}

#[test]
fn the_accumulation_buffer_blends_in_depth_order_on_the_cpu() {
    blend_order_on(&mut CpuBackend::new());
}

#[test]
fn the_accumulation_buffer_blends_in_depth_order_on_vulkan() {
    let Some(mut vk) = dof_tests::vulkan() else { return };
    blend_order_on(&mut vk);
    dof_tests::assert_clean(&mut vk);
}

/// The built-in scene's materials in its GLB export.
fn exported_materials(glb: &[u8]) -> Vec<serde_json::Value> {
    let json_len = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    let doc: serde_json::Value = serde_json::from_slice(&glb[20..20 + json_len]).unwrap();
    doc["materials"].as_array().unwrap().clone()
}

#[test]
fn translucent_builtins_export_blend_and_a_mask() {
    for name in ["panes", "foliage", "glass"] {
        let b = builtin(name).unwrap().with_size(64, 36);
        let translucent: Vec<f32> = (0..b.scene.primitives().len() as u32).map(|i| b.scene.alpha(i)).filter(|a| *a < 1.0).collect();
        assert!(!translucent.is_empty(), "{name} has translucent surfaces");
        let glb = export_glb(&b.scene, &b.camera, &ExportOptions::default()).unwrap();
        let blend: Vec<f32> = exported_materials(&glb)
            .iter()
            .filter(|m| m["alphaMode"] == "BLEND")
            .map(|m| m["pbrMetallicRoughness"]["baseColorFactor"][3].as_f64().unwrap() as f32)
            .collect();
        assert_eq!(blend, translucent, "{name}: one BLEND material per translucent surface");
        let mesh = load_gltf_slice(&glb).unwrap();
        assert_eq!(mesh.materials.iter().filter(|m| m.flags & ALPHA_BLEND != 0).count(), translucent.len());
        let lens = b.thin_lens().unwrap();
        let MitsubaExport::Exact(m) = export_mitsuba(&b.scene, &b.camera, &lens, &MitsubaOptions::default()).unwrap() else {
            panic!("{name} must export exactly")
        };
        assert_eq!(m.xml.matches("<bsdf type=\"mask\">").count(), translucent.len(), "{name}");
        assert!(m.xml.contains(&format!("name=\"max_depth\" value=\"{}\"", 2 + translucent.len())), "{name}");
    }
    // The panes of `panes`: opacity 0.35 and 0.6, in the mask and premultiplied in the emitter.
    let b = builtin("panes").unwrap();
    let lens = b.thin_lens().unwrap();
    let MitsubaExport::Exact(m) = export_mitsuba(&b.scene, &b.camera, &lens, &MitsubaOptions::default()).unwrap() else { panic!() };
    assert!(m.xml.contains("name=\"opacity\" value=\"0.35\"") && m.xml.contains("name=\"opacity\" value=\"0.6\""));
    let premultiplied = [0.2f32, 0.35, 0.7].map(|c| c * 0.35);
    assert!(
        m.xml.contains(&format!("value=\"{}, {}, {}\"", premultiplied[0], premultiplied[1], premultiplied[2])),
        "pane radiance times alpha"
    );
}

#[test]
fn the_accumulation_buffer_of_exported_panes_matches_the_exact_reference() {
    // `panes` through glTF (BLEND) and the rasteriser against the analytic thin-lens reference.
    let b = builtin("panes").unwrap().with_size(96, 54);
    let lens = b.thin_lens().unwrap();
    let mesh = load_gltf_slice(&export_glb(&b.scene, &b.camera, &ExportOptions::default()).unwrap()).unwrap();
    let exact = reference(&b.scene, &b.camera, &lens, &ReferenceOptions { spp: 256, ..Default::default() }).unwrap();
    let near = default_near(lens.focus_distance);
    let acc = accumulate(
        &mut CpuBackend::new(),
        &mesh.raster(),
        &b.camera,
        &lens,
        near,
        &AccumulateOptions { samples: 64, ..Default::default() },
    )
    .unwrap();
    let db = psnr(&acc.image, &exact.image).unwrap();
    eprintln!("panes 96x54: accumulation buffer (64 renders) against the exact reference (256 spp): {db:.2} dB");
    // Seen: 56.5 dB.
    assert!(db > 50.0, "{db} dB");
}
