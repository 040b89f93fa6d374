//! Scenes, cameras, the exact multi-layer image and the thin-lens reference.

use dof::CoreError;
use dof::layers::LayeredImage;
use dof::metrics::psnr;
use dof::scene::{
    Aperture, AutoOptions, Camera, Focus, LayerOptions, LensSettings, Lighting, Material, Primitive, ReferenceOptions, Scene, Shape, Vec3,
    builtin, builtin_names, pinhole, raycast_layers, reference, reference_auto,
};

/// These suites look at the frame's own pixels: no guard band (its tests are in `sky_and_edges.rs`).
fn frame_only() -> LayerOptions {
    LayerOptions { guard_band: dof::scene::GuardBand::Off, ..LayerOptions::default() }
}

// ---------------------------------------------------------------------------------------------
// Multi-layer images.

fn assert_front_to_back(name: &str, layers: &LayeredImage) {
    for y in 0..layers.height {
        for x in 0..layers.width {
            let frags = layers.pixel(x, y);
            assert!(frags.len() <= layers.max_layers as usize);
            for (i, f) in frags.iter().enumerate() {
                // The background (+inf) only as the last fragment.
                assert!(f.depth > 0.0 && (f.depth.is_finite() || i + 1 == frags.len()), "{name} ({x}, {y}): depth {}", f.depth);
                assert!(f.color.iter().all(|c| c.is_finite() && *c >= 0.0), "{name} ({x}, {y}): colour {:?}", f.color);
                // Only the translucent scenes' panes and cards cover partly.
                let translucent = ["panes", "foliage", "glass"].contains(&name);
                assert!(f.alpha == 1.0 || (translucent && f.alpha > 0.0 && f.alpha < 1.0), "{name} ({x}, {y}): alpha {}", f.alpha);
            }
            for w in frags.windows(2) {
                assert!(w[0].depth <= w[1].depth, "{name} ({x}, {y}): {} then {}", w[0].depth, w[1].depth);
            }
        }
    }
}

/// Distance (pixels) from `(px, py)` to the boundary of the rectangle `[x0, x1] x [y0, y1]`.
fn distance_to_rectangle_boundary(px: f32, py: f32, (x0, y0, x1, y1): (f32, f32, f32, f32)) -> f32 {
    if px >= x0 && px <= x1 && py >= y0 && py <= y1 {
        (px - x0).min(x1 - px).min(py - y0).min(y1 - py)
    } else {
        let dx = (x0 - px).max(px - x1).max(0.0);
        let dy = (y0 - py).max(py - y1).max(0.0);
        (dx * dx + dy * dy).sqrt()
    }
}

/// With the disocclusion buffer, `simple` keeps more than one layer only in bands around the
/// silhouettes, dilated by the CoC: a wide band around the blurred near quad, a thin one around the
/// sharp sphere (as wide as the blurred far plane's CoC behind it). Without it, every pixel where
/// the ray meets more than one surface does.
#[test]
fn simple_has_multiple_layers_only_near_silhouettes() {
    let s = builtin("simple").unwrap().with_size(160, 90);
    let lens = s.thin_lens().unwrap();
    let frame = s.camera.frame().unwrap();
    let ml = raycast_layers(&s.scene, &s.camera, &lens, &frame_only()).unwrap();
    assert_front_to_back("simple", &ml.layers);

    let prims = s.scene.primitives();
    let Shape::Quad { corner, edge_u, edge_v } = prims[2].shape else { panic!("primitive 2 of simple is the quad") };
    let Shape::Sphere { center, radius } = prims[1].shape else { panic!("primitive 1 of simple is the sphere") };
    let corners = [corner, corner + edge_u, corner + edge_v, corner + edge_u + edge_v].map(|c| frame.project(c).unwrap());
    let rect = (
        corners.iter().map(|c| c.0).fold(f32::INFINITY, f32::min),
        corners.iter().map(|c| c.1).fold(f32::INFINITY, f32::min),
        corners.iter().map(|c| c.0).fold(f32::NEG_INFINITY, f32::max),
        corners.iter().map(|c| c.1).fold(f32::NEG_INFINITY, f32::max),
    );
    let quad_band = (lens.coc_px(frame.depth_of(corner)) / 2.0).ceil() + 1.5;
    let far_plane = 12.0;
    let sphere_band = (lens.coc_px(far_plane).max(lens.coc_px(frame.depth_of(center))) / 2.0).ceil() + 2.0;
    let to_centre = center - frame.eye;
    let silhouette = (radius / to_centre.length()).asin();
    let pixel_angle = 2.0 * frame.tan_half_fov / frame.height as f32;

    let (mut near_quad, mut inside_quad, mut near_sphere_only) = (0, 0, 0);
    for y in 0..frame.height {
        for x in 0..frame.width {
            if ml.layers.pixel(x, y).len() < 2 {
                continue;
            }
            let (px, py) = (x as f32 + 0.5, y as f32 + 0.5);
            let dq = distance_to_rectangle_boundary(px, py, rect);
            let dir = frame.direction(px, py).normalize();
            let ds = ((dir.dot(to_centre.normalize()).clamp(-1.0, 1.0).acos() - silhouette) / pixel_angle).abs();
            assert!(
                dq <= quad_band || ds <= sphere_band,
                "({x}, {y}) has {} layers but lies {dq:.1} px from the quad's silhouette (band {quad_band}) and {ds:.1} px from the sphere's (band {sphere_band})",
                ml.layers.pixel(x, y).len()
            );
            if dq <= quad_band {
                near_quad += 1;
                inside_quad += (px > rect.0 && px < rect.2 && py > rect.1 && py < rect.3) as u32;
            } else {
                near_sphere_only += 1;
            }
        }
    }
    assert!(near_quad > 100 && inside_quad > 20 && near_quad - inside_quad > 20, "{near_quad} near the quad, {inside_quad} inside it");
    assert!(near_quad > near_sphere_only, "{near_quad} near the quad, {near_sphere_only} near the sphere only");
    assert_eq!(ml.with_mask, ml.layers.stats());

    // Without the buffer the sphere's interior keeps the plane behind it too.
    let all = raycast_layers(&s.scene, &s.camera, &lens, &LayerOptions { disocclusion: false, ..frame_only() }).unwrap();
    assert_eq!(all.without_mask, all.layers.stats());
    assert_eq!(all.without_mask, ml.without_mask);
    assert_eq!(all.mask, ml.mask);
    assert!(ml.without_mask.multi_layer_pixels > 2 * ml.with_mask.multi_layer_pixels);
    let (cx, cy) = frame.project(center).unwrap();
    let inside = all.layers.pixel(cx as u32, cy as u32);
    assert_eq!(inside.len(), 2, "sphere then far plane: {inside:?}");
    assert!((inside[1].depth - far_plane).abs() < 0.5);
    assert_eq!(ml.layers.pixel(cx as u32, cy as u32).len(), 1);
}

#[test]
fn every_builtin_scene_has_fragments_front_to_back() {
    for name in builtin_names() {
        let s = builtin(name).unwrap().with_size(96, 54);
        let lens = s.thin_lens().unwrap();
        for disocclusion in [true, false] {
            let ml = raycast_layers(&s.scene, &s.camera, &lens, &LayerOptions { disocclusion, ..frame_only() }).unwrap();
            assert_front_to_back(name, &ml.layers);
            let (_, depth) = ml.layers.front();
            for (p, d) in depth.iter().enumerate() {
                if ml.layers.counts[p] > 0 {
                    assert_eq!(*d, ml.layers.fragments[p * 4].depth);
                }
            }
            assert!(ml.with_mask.fragments <= ml.without_mask.fragments);
            assert!(ml.with_mask.fragments >= ml.with_mask.pixels - ml.with_mask.empty_pixels);
        }
    }
}

/// Closely spaced sheets are merged by the umbra threshold; without it they fill the layers.
#[test]
fn umbra_threshold_skips_fragments_in_the_shadow_of_the_one_in_front() {
    let mut prims: Vec<Primitive> = (0..6)
        .map(|i| Primitive {
            shape: Shape::Quad {
                corner: Vec3::new(-1.0, -1.0, -5.0 - 0.01 * i as f32),
                edge_u: Vec3::new(2.0, 0.0, 0.0),
                edge_v: Vec3::new(0.0, 2.0, 0.0),
            },
            material: Material::Emissive([0.1 * i as f32, 0.5, 0.5]),
        })
        .collect();
    prims.push(Primitive {
        shape: Shape::Plane { point: Vec3::new(0.0, 0.0, -20.0), normal: Vec3::Z },
        material: Material::Emissive([1.0; 3]),
    });
    let scene = Scene::new(prims, Lighting::default()).unwrap();
    let camera = Camera::look_at(Vec3::ZERO, -Vec3::Z, 40f32.to_radians(), 160, 90);
    let lens = LensSettings::with_aperture_radius(3.0, 0.04).thin_lens(&camera).unwrap();
    let frame = camera.frame().unwrap();
    let z = 5.0;
    let umbra = lens.umbra_length(z, frame.pixel_footprint_radius(z));
    assert!(umbra > 0.05 && umbra < 15.0, "umbra {umbra}");
    let options = LayerOptions { disocclusion: false, ..frame_only() };
    let with = raycast_layers(&scene, &camera, &lens, &options).unwrap();
    let without = raycast_layers(&scene, &camera, &lens, &LayerOptions { umbra_threshold: false, ..options }).unwrap();
    let depths = |l: &LayeredImage| l.pixel(80, 45).iter().map(|f| f.depth).collect::<Vec<_>>();
    let d = depths(&with.layers);
    assert_eq!(d.len(), 2, "{d:?}");
    assert!((d[0] - 5.0).abs() < 1e-4 && (d[1] - 20.0).abs() < 1e-3, "{d:?}");
    let d = depths(&without.layers);
    assert_eq!(d.len(), 4, "{d:?}");
    assert!(d.iter().all(|z| (5.0..5.04).contains(z)), "{d:?}");
    // A pinhole keeps one layer: every footprint covers its (empty) aperture.
    let pin = LensSettings::with_aperture_radius(3.0, 0.0).thin_lens(&camera).unwrap();
    let one = raycast_layers(&scene, &camera, &pin, &options).unwrap();
    assert_eq!(one.without_mask.multi_layer_pixels, 0);
}

// ---------------------------------------------------------------------------------------------
// References.

/// A pinhole reference with one unjittered sample is the front layer of the ray-cast image, bit for
/// bit; with jitter it is close (it differs only where a pixel's area straddles an edge). Where
/// translucent surfaces lie in front, the front layer is the fragments' composite, front to back.
#[test]
fn pinhole_reference_is_the_front_layer() {
    for name in builtin_names() {
        let s = builtin(name).unwrap().with_size(96, 54);
        let lens = s.thin_lens().unwrap();
        // Enough layers for every translucent surface a pixel shows; `front` flattens them front
        // to back ("over"; the front fragment alone where it is opaque).
        let ml = raycast_layers(&s.scene, &s.camera, &lens, &LayerOptions { max_layers: 16, ..frame_only() }).unwrap();
        let (front, _) = ml.layers.front();
        let exact = ReferenceOptions { spp: 1, jitter: false, ..Default::default() };
        let pin = pinhole(&s.scene, &s.camera, &exact).unwrap();
        assert_eq!(pin.image, front, "{name}: pinhole differs from the front layer");
        assert_eq!(pin.noise_psnr_db, None);
        let closed = dof::scene::ThinLens { aperture_radius: 0.0, ..lens };
        assert_eq!(reference(&s.scene, &s.camera, &closed, &exact).unwrap().image, front, "{name}: aperture 0");
        let jittered = pinhole(&s.scene, &s.camera, &ReferenceOptions { spp: 16, ..Default::default() }).unwrap();
        let p = psnr(&jittered.image, &front).unwrap();
        assert!(p > 20.0, "{name}: jittered pinhole only {p:.1} dB from the front layer");
        if *name != "simple" {
            continue; // textures vary inside pixels elsewhere
        }
        // Away from edges the pixel is constant over its area; most pixels agree closely.
        let close = jittered
            .image
            .data
            .iter()
            .zip(&front.data)
            .filter(|(a, b)| (0..3).all(|k| (a[k] - b[k]).abs() <= 0.02 * b[k].max(0.1)))
            .count();
        assert!(close as f64 > 0.9 * front.data.len() as f64, "{name}: only {close} of {} pixels agree", front.data.len());
    }
}

/// A flat, constant-colour plane filling the view stays exactly that colour under any blur: the
/// reference conserves energy (HDR values included).
#[test]
fn flat_plane_stays_flat() {
    let camera = Camera::look_at(Vec3::new(0.3, -0.2, 0.0), Vec3::new(0.3, -0.2, -1.0), 50f32.to_radians(), 33, 17);
    for material in [
        Material::Emissive([0.25, 0.5, 1.0]),
        Material::Emissive([1.0e5, 7.0e4, 3.0]),
        Material::Diffuse(dof::scene::Albedo::Solid([0.7, 0.6, 0.2])),
    ] {
        let scene = Scene::new(
            vec![Primitive { shape: Shape::Plane { point: Vec3::new(0.0, 0.0, -3.0), normal: Vec3::new(0.0, 0.0, 2.0) }, material }],
            Lighting::default(),
        )
        .unwrap();
        let lens = LensSettings::with_aperture_radius(1.0, 0.3).thin_lens(&camera).unwrap();
        assert!(lens.coc_px(3.0) > 5.0);
        let r = reference(&scene, &camera, &lens, &ReferenceOptions { spp: 24, ..Default::default() }).unwrap();
        let expected = r.image.data[0];
        assert!(expected.iter().all(|c| *c > 0.0));
        if let Material::Emissive(c) = material {
            assert_eq!(expected, c);
        }
        for (i, c) in r.image.data.iter().enumerate() {
            assert_eq!(*c, expected, "pixel {i}");
        }
        assert_eq!(r.noise_psnr_db, Some(f64::INFINITY));
    }
}

/// The blur the ray tracer produces is the CoC the lens model predicts: a tiny emitter out of
/// focus becomes a disc of diameter `coc_px`, keeping its energy.
#[test]
fn reference_bokeh_has_the_predicted_size_and_energy() {
    let camera = Camera::look_at(Vec3::ZERO, -Vec3::Z, 40f32.to_radians(), 96, 96);
    let frame = camera.frame().unwrap();
    let z = 1.5;
    let dot = Vec3::new(0.05, 0.03, -z);
    let scene = Scene::new(
        vec![Primitive { shape: Shape::Sphere { center: dot, radius: 0.01 }, material: Material::Emissive([1000.0, 1000.0, 1000.0]) }],
        Lighting::default(),
    )
    .unwrap();
    for (focus, aperture) in [(4.0, 0.15), (0.9, 0.1)] {
        let lens = LensSettings::with_aperture_radius(focus, aperture).thin_lens(&camera).unwrap();
        let coc = lens.coc_px(z);
        assert!(coc > 8.0 && coc < 30.0, "coc {coc}");
        let blurred = reference(&scene, &camera, &lens, &ReferenceOptions { spp: 1024, ..Default::default() }).unwrap();
        let sharp = pinhole(&scene, &camera, &ReferenceOptions { spp: 256, ..Default::default() }).unwrap();
        let moments = |img: &dof::layers::RgbImage| {
            let (mut e, mut sx, mut sy, mut sxx) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
            for y in 0..img.height {
                for x in 0..img.width {
                    let v = img.get(x, y)[0] as f64;
                    let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
                    e += v;
                    sx += v * px;
                    sy += v * py;
                    sxx += v * (px * px + py * py);
                }
            }
            let (cx, cy) = (sx / e, sy / e);
            (e, cx, cy, sxx / e - cx * cx - cy * cy)
        };
        let (e_blur, cx, cy, var) = moments(&blurred.image);
        let (e_sharp, ..) = moments(&sharp.image);
        eprintln!(
            "focus {focus}: energy ratio {:.4}, bokeh radius {rho_dbg:.3} px vs CoC radius {:.3} px",
            e_blur / e_sharp,
            coc / 2.0,
            rho_dbg = (2.0 * (var - 1.0 / 6.0)).sqrt()
        );
        assert!((e_blur / e_sharp - 1.0).abs() < 0.05, "energy {e_blur} blurred vs {e_sharp} sharp");
        let (px, py) = frame.project(dot).unwrap();
        assert!((cx - px as f64).abs() < 0.3 && (cy - py as f64).abs() < 0.3, "centroid ({cx}, {cy}) vs ({px}, {py})");
        // A uniform disc of radius ρ has E|d|² = ρ²/2; the pixel box adds 1/6, the dot's own disc
        // (radius r) r²/2.
        let r_dot = 0.01 / z as f64 * 96.0 / (2.0 * frame.tan_half_fov as f64);
        let rho = (2.0 * (var - 1.0 / 6.0 - r_dot * r_dot / 2.0)).sqrt();
        assert!((rho / (coc as f64 / 2.0) - 1.0).abs() < 0.05, "bokeh radius {rho:.2} px, CoC radius {:.2} px", coc / 2.0);
    }
}

/// The half-sample noise estimate predicts the actual error against a far better render.
#[test]
fn noise_estimate_is_honest_and_auto_reaches_its_target() {
    let s = builtin("simple").unwrap().with_size(64, 36);
    let lens = s.thin_lens().unwrap();
    let converged = reference(&s.scene, &s.camera, &lens, &ReferenceOptions { spp: 2048, seed: 99, ..Default::default() }).unwrap();
    let cheap = reference(&s.scene, &s.camera, &lens, &ReferenceOptions { spp: 8, seed: 1, ..Default::default() }).unwrap();
    let estimate = cheap.noise_psnr_db.unwrap();
    let actual = psnr(&cheap.image, &converged.image).unwrap();
    eprintln!("8 spp: estimated {estimate:.2} dB, actual {actual:.2} dB");
    assert!((estimate - actual).abs() < 2.0, "estimated {estimate:.2} dB, actual {actual:.2} dB");

    let ml = raycast_layers(&s.scene, &s.camera, &lens, &frame_only()).unwrap();
    let options = AutoOptions { target_psnr_db: 30.0, start_spp: 4, max_spp: 512, region: Some(ml.mask.clone()), ..Default::default() };
    let auto = reference_auto(&s.scene, &s.camera, &lens, &options).unwrap();
    let required = options.required_noise_psnr_db();
    assert!((required - 39.14).abs() < 0.01);
    assert_eq!(auto.required_psnr_db, Some(required));
    assert!(!auto.capped, "{auto:?}");
    assert!(auto.noise_psnr_db.unwrap() >= required && auto.region_noise_psnr_db.unwrap() >= required);
    assert!(auto.region_noise_psnr_db.unwrap() < auto.noise_psnr_db.unwrap(), "the blurred silhouettes are the noisy part");
    assert!(auto.valid_up_to_psnr_db(0.5).unwrap() >= 30.0);
    assert!(psnr(&auto.image, &converged.image).unwrap() > required - 2.0);
    let capped =
        reference_auto(&s.scene, &s.camera, &lens, &AutoOptions { target_psnr_db: 80.0, start_spp: 2, max_spp: 8, ..Default::default() })
            .unwrap();
    assert!(capped.capped && capped.spp == 8, "{capped:?}");
}

#[test]
fn every_builtin_scene_renders_small_and_fast() {
    for name in builtin_names() {
        let t = std::time::Instant::now();
        let s = builtin(name).unwrap().with_size(96, 54);
        assert_eq!(s.name, *name);
        let lens = s.thin_lens().unwrap();
        let ml = raycast_layers(&s.scene, &s.camera, &lens, &frame_only()).unwrap();
        // Visible blur at the default 640x360: some surface has a CoC of at least 10 px there.
        let (_, depth) = ml.layers.front();
        let max_coc = depth.iter().map(|z| lens.coc_px(*z)).fold(0.0f32, f32::max) * 360.0 / 54.0;
        assert!(max_coc >= 10.0, "{name}: largest CoC {max_coc} px at 640x360");
        assert!(ml.without_mask.multi_layer_pixels > 0, "{name}: no depth complexity");
        let r = reference(&s.scene, &s.camera, &lens, &ReferenceOptions { spp: 8, ..Default::default() }).unwrap();
        assert_eq!((r.image.width, r.image.height), (96, 54));
        assert!(r.image.data.iter().flatten().all(|c| c.is_finite() && *c >= 0.0), "{name}");
        assert!(r.image.data.iter().flatten().any(|c| *c > 0.01), "{name}: black");
        let elapsed = t.elapsed();
        eprintln!("{name}: 96x54 layers + 8 spp reference in {elapsed:.2?}");
        assert!(elapsed.as_secs_f64() < 30.0, "{name} took {elapsed:?}");
    }
    // At the default size every scene blurs visibly.
    for name in builtin_names() {
        let s = builtin(name).unwrap();
        assert_eq!((s.camera.width, s.camera.height), (640, 360));
        let lens = s.thin_lens().unwrap();
        let near = s.scene.primitives().len();
        assert!(near > 2 && near < 100, "{name}: {near} primitives");
        assert!(lens.far_limit_px() >= 2.0, "{name}: far limit {} px", lens.far_limit_px());
    }
    let highlights = builtin("highlights").unwrap();
    let hdr = highlights
        .scene
        .primitives()
        .iter()
        .filter(|p| matches!(p.material, Material::Emissive(c) if c.iter().any(|v| *v > 65504.0)))
        .count();
    assert!(hdr > 0, "some highlights exceed the half-float range");
}

// ---------------------------------------------------------------------------------------------
// Cameras and lenses.

#[test]
fn camera_follows_the_gltf_conventions() {
    let camera = Camera::look_at(Vec3::new(1.0, 2.0, 3.0), Vec3::new(1.0, 2.0, -7.0), 60f32.to_radians(), 200, 100);
    let f = camera.frame().unwrap();
    assert!((f.forward - -Vec3::Z).length() < 1e-6 && (f.right - Vec3::X).length() < 1e-6 && (f.up - Vec3::Y).length() < 1e-6);
    let top_left = f.direction(0.0, 0.0);
    assert!(top_left.x < 0.0 && top_left.y > 0.0);
    assert!((f.direction(100.0, 50.0) - -Vec3::Z).length() < 1e-6);
    assert!((top_left.y - (30f32).to_radians().tan()).abs() < 1e-5);
    let ray = f.pixel_ray(17, 81);
    for t in [0.5f32, 3.0, 40.0] {
        let p = ray.at(t);
        assert!((f.depth_of(p) - t).abs() < 1e-4 * t, "t is planar depth");
        let (px, py) = f.project(p).unwrap();
        assert!((px - 17.5).abs() < 1e-3 && (py - 81.5).abs() < 1e-3);
    }
    // Lens rays through one image point meet at the focus plane.
    let focus = 4.0;
    let target = f.lens_ray(40.25, 60.75, 0.0, 0.0, focus).at(focus);
    for (lx, ly) in [(0.1, 0.0), (-0.05, 0.07), (0.0, -0.2)] {
        let r = f.lens_ray(40.25, 60.75, lx, ly, focus);
        assert!((f.depth_of(r.origin)).abs() < 1e-6);
        assert!((r.at(focus) - target).length() < 1e-5);
    }
    assert!(f.project(Vec3::new(1.0, 2.0, 5.0)).is_none());
}

#[test]
fn photographic_and_radius_settings_give_the_same_blur_as_the_camera_geometry() {
    let camera = Camera::look_at(Vec3::ZERO, -Vec3::Z, 40f32.to_radians(), 640, 360);
    let tan = 20f32.to_radians().tan();
    // f from the field of view and a 24 mm sensor; f/2.
    let photo = LensSettings::photographic(3.0, 2.0).thin_lens(&camera).unwrap();
    let f = 0.012 / tan;
    assert!((photo.focal_length - f).abs() < 1e-6);
    assert!((photo.aperture_radius - f / 4.0).abs() < 1e-6);
    // The CoC in pixels is R·|1 − z_f/z|·H / (z_f·tan(fov/2)), the ray tracer's blur.
    for lens in [photo, LensSettings::with_aperture_radius(3.0, 0.05).thin_lens(&camera).unwrap()] {
        for z in [0.5f32, 2.0, 7.0, 100.0] {
            let geometric = lens.aperture_radius * (1.0 - 3.0 / z).abs() * 360.0 / (3.0 * tan);
            assert!((lens.coc_px(z) - geometric).abs() <= 1e-4 * geometric.max(1.0), "z {z}: {} vs {geometric}", lens.coc_px(z));
        }
    }
    // Explicit focal length in a centimetre scene; focusing on a point.
    let cm = LensSettings { metres_per_unit: 0.01, ..LensSettings::photographic(300.0, 4.0).focal_length_mm(50.0) };
    let lens = cm.focused_on(Vec3::new(10.0, 5.0, -250.0)).thin_lens(&camera).unwrap();
    assert!((lens.focal_length - 5.0).abs() < 1e-5 && (lens.focus_distance - 250.0).abs() < 1e-3);
    assert!((lens.aperture_radius - 0.625).abs() < 1e-5);
}

// ---------------------------------------------------------------------------------------------
// Bad input: errors, never panics.

fn is_invalid<T: std::fmt::Debug>(r: dof::Result<T>, needle: &str) {
    match r {
        Err(dof::Error::Core(CoreError::InvalidArgument(m) | CoreError::InvalidLens(m))) => {
            assert!(m.contains(needle), "message `{m}` lacks `{needle}`")
        }
        other => panic!("expected an invalid-argument error mentioning `{needle}`, got {other:?}"),
    }
}

#[test]
fn invalid_cameras_lenses_and_scenes_are_errors() {
    let good = Camera::look_at(Vec3::ZERO, -Vec3::Z, 40f32.to_radians(), 16, 9);
    let lens = LensSettings::with_aperture_radius(2.0, 0.02);
    for (camera, needle) in [
        (Camera { width: 0, ..good }, "size"),
        (Camera { height: 0, ..good }, "size"),
        (Camera { yfov_radians: 0.0, ..good }, "field of view"),
        (Camera { yfov_radians: -0.5, ..good }, "field of view"),
        (Camera { yfov_radians: std::f32::consts::PI, ..good }, "field of view"),
        (Camera { yfov_radians: 4.0, ..good }, "field of view"),
        (Camera { yfov_radians: f32::NAN, ..good }, "field of view"),
        (Camera { eye: Vec3::new(f32::NAN, 0.0, 0.0), ..good }, "finite"),
        (Camera { target: Vec3::ZERO, ..good }, "target"),
        (Camera { up: -Vec3::Z, ..good }, "up"),
        (Camera { up: Vec3::ZERO, ..good }, "up"),
    ] {
        is_invalid(camera.frame(), needle);
        is_invalid(lens.thin_lens(&camera), needle);
    }
    for (settings, needle) in [
        (LensSettings::with_aperture_radius(0.0, 0.02), "focus distance"),
        (LensSettings::with_aperture_radius(-1.0, 0.02), "focus distance"),
        (LensSettings::with_aperture_radius(f32::NAN, 0.02), "focus distance"),
        (LensSettings::with_aperture_radius(f32::INFINITY, 0.02), "focus distance"),
        (lens.focused_on(Vec3::new(0.0, 0.0, 5.0)), "behind"),
        (lens.focused_on(Vec3::new(1.0, 0.0, 0.0)), "behind"),
        (LensSettings::with_aperture_radius(2.0, -0.01), "aperture radius"),
        (LensSettings::with_aperture_radius(2.0, f32::NAN), "aperture radius"),
        (LensSettings::with_aperture_radius(2.0, f32::INFINITY), "aperture radius"),
        (LensSettings::photographic(2.0, 0.0), "f-number"),
        (LensSettings::photographic(2.0, -2.0), "f-number"),
        (LensSettings::photographic(2.0, f32::NAN), "f-number"),
        (LensSettings::photographic(0.04, 2.0).focal_length_mm(50.0), "shorter than the focus distance"),
        (LensSettings::photographic(0.05, 2.0).focal_length_mm(50.0), "shorter than the focus distance"),
        (lens.focal_length_mm(0.0), "focal length"),
        (lens.focal_length_mm(f32::NAN), "focal length"),
        (LensSettings { sensor_height_mm: 0.0, ..lens }, "sensor height"),
        (LensSettings { metres_per_unit: 0.0, ..lens }, "metres per scene unit"),
        (LensSettings { focus: Focus::Distance(-3.0), aperture: Aperture::Radius(0.1), ..lens }, "focus distance"),
    ] {
        is_invalid(settings.thin_lens(&good), needle);
    }

    let s = builtin("simple").unwrap().with_size(16, 9);
    let thin = s.thin_lens().unwrap();
    is_invalid(raycast_layers(&s.scene, &s.camera, &thin, &LayerOptions { max_layers: 0, ..frame_only() }), "layer");
    is_invalid(raycast_layers(&s.scene, &s.camera, &thin, &LayerOptions { edge_depth_ratio: f32::NAN, ..frame_only() }), "edge");
    let broken = dof::scene::ThinLens { focus_distance: thin.focal_length * 0.5, ..thin };
    is_invalid(raycast_layers(&s.scene, &s.camera, &broken, &frame_only()), "lens");
    is_invalid(reference(&s.scene, &s.camera, &broken, &ReferenceOptions::default()), "lens");
    is_invalid(reference(&s.scene, &s.camera, &thin, &ReferenceOptions { spp: 0, ..Default::default() }), "sample");
    is_invalid(reference(&s.scene, &s.camera, &thin, &ReferenceOptions { region: Some(vec![true; 3]), ..Default::default() }), "region");
    is_invalid(reference_auto(&s.scene, &s.camera, &thin, &AutoOptions { start_spp: 1, ..Default::default() }), "start_spp");
    is_invalid(reference_auto(&s.scene, &s.camera, &thin, &AutoOptions { start_spp: 64, max_spp: 32, ..Default::default() }), "start_spp");
    is_invalid(reference_auto(&s.scene, &s.camera, &thin, &AutoOptions { tolerance_db: 0.0, ..Default::default() }), "tolerance");
    is_invalid(reference_auto(&s.scene, &s.camera, &thin, &AutoOptions { target_psnr_db: f64::NAN, ..Default::default() }), "target");
    is_invalid(pinhole(&s.scene, &Camera { width: 0, ..s.camera }, &ReferenceOptions::default()), "size");
    let huge = Camera { width: u32::MAX, height: u32::MAX, ..s.camera };
    assert!(matches!(raycast_layers(&s.scene, &huge, &thin, &frame_only()), Err(dof::Error::Core(CoreError::TooLarge { .. }))));
    assert!(matches!(pinhole(&s.scene, &huge, &ReferenceOptions::default()), Err(dof::Error::Core(CoreError::TooLarge { .. }))));

    let err = builtin("nope").unwrap_err().to_string();
    for name in builtin_names() {
        assert!(err.contains(name), "`{err}` should list `{name}`");
    }

    let white = Material::Emissive([1.0; 3]);
    let prim = |shape| vec![Primitive { shape, material: white }];
    for (prims, needle) in [
        (prim(Shape::Sphere { center: Vec3::ZERO, radius: 0.0 }), "radius"),
        (prim(Shape::Sphere { center: Vec3::ZERO, radius: f32::NAN }), "radius"),
        (prim(Shape::Sphere { center: Vec3::new(f32::INFINITY, 0.0, 0.0), radius: 1.0 }), "centre"),
        (prim(Shape::Cuboid { min: Vec3::ONE, max: Vec3::ZERO }), "min <= max"),
        (prim(Shape::Quad { corner: Vec3::ZERO, edge_u: Vec3::X, edge_v: Vec3::X * 2.0 }), "parallel"),
        (prim(Shape::Plane { point: Vec3::ZERO, normal: Vec3::ZERO }), "normal"),
        (
            vec![Primitive {
                shape: Shape::Plane { point: Vec3::ZERO, normal: Vec3::Z },
                material: Material::Emissive([f32::NAN, 0.0, 0.0]),
            }],
            "colours",
        ),
        (
            vec![Primitive { shape: Shape::Plane { point: Vec3::ZERO, normal: Vec3::Z }, material: Material::Emissive([-1.0, 0.0, 0.0]) }],
            "colours",
        ),
        (
            vec![Primitive {
                shape: Shape::Plane { point: Vec3::ZERO, normal: Vec3::Z },
                material: Material::Diffuse(dof::scene::Albedo::Checker { a: [1.0; 3], b: [0.0; 3], cell: 0.0 }),
            }],
            "checker",
        ),
    ] {
        is_invalid(Scene::new(prims, Lighting::default()), needle);
    }
    is_invalid(Scene::new(vec![], Lighting { direction: Vec3::ZERO, ..Lighting::default() }), "light direction");
    assert!(
        dof::scene::validate_artist_lens(&dof::scene::ArtistLens {
            near_start: 1.0,
            near_end: 2.0,
            far_start: 3.0,
            far_end: 4.0,
            max_radius_px: 4.0
        })
        .is_err()
    );
}

mod fuzz {
    use super::*;
    use proptest::prelude::*;

    fn any_f32() -> impl Strategy<Value = f32> {
        prop_oneof![
            Just(0.0f32),
            Just(-0.0f32),
            Just(f32::NAN),
            Just(f32::INFINITY),
            Just(f32::NEG_INFINITY),
            Just(f32::MIN_POSITIVE),
            Just(f32::MAX),
            -10.0f32..10.0,
            any::<f32>(),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

        /// Arbitrary camera and lens numbers give a valid lens or an error; a valid lens renders a
        /// tiny image with finite, non-negative values.
        #[test]
        fn arbitrary_camera_and_lens_never_panic(
            fov in any_f32(), w in 0u32..5, h in 0u32..5, ex in any_f32(), tz in any_f32(), focus in any_f32(),
            aperture in any_f32(), use_f_number: bool, focal in proptest::option::of(any_f32()),
        ) {
            let s = builtin("simple").unwrap();
            let camera = Camera { eye: Vec3::new(ex, 0.0, 0.0), target: Vec3::new(0.0, 0.0, tz), yfov_radians: fov, width: w, height: h, up: Vec3::Y };
            let settings = LensSettings {
                focus: Focus::Distance(focus),
                aperture: if use_f_number { Aperture::FNumber(aperture) } else { Aperture::Radius(aperture) },
                focal_length_mm: focal,
                ..LensSettings::photographic(1.0, 1.0)
            };
            if let Ok(lens) = settings.thin_lens(&camera) {
                prop_assert!(lens.is_valid());
                let ml = raycast_layers(&s.scene, &camera, &lens, &frame_only()).unwrap();
                for f in &ml.layers.fragments[..] {
                    prop_assert!(!f.depth.is_nan());
                }
                let r = reference(&s.scene, &camera, &lens, &ReferenceOptions { spp: 2, ..Default::default() }).unwrap();
                prop_assert!(r.image.data.iter().flatten().all(|c| c.is_finite() && *c >= 0.0));
            }
        }
    }
}
