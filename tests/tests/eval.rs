//! `dof eval`'s engine: every registered method appears for every setting and backend, and the
//! report carries the documented fields.

use dof::backend::{Backend, CpuBackend};
use dof::eval::methods::evaluated_methods;
use dof::eval::{EvalOptions, evaluate};

#[test]
fn quick_evaluation_covers_every_method_and_setting() {
    let mut backends: Vec<Box<dyn Backend>> = vec![Box::new(CpuBackend::new())];
    let options = EvalOptions {
        scenes: vec!["simple".into()],
        methods: vec![],
        quick: true,
        runs: 1,
        progress: false,
        coc_sweep: vec![4.0, 16.0],
        subsamples: 1,
        footprints: true,
        aimed_emitters: false,
        size: None,
    };
    let report = evaluate(&options, &mut backends).unwrap();
    for method in evaluated_methods() {
        for setting in method.settings(true) {
            let found = report.records.iter().filter(|r| r.method == method.name() && r.setting == setting.label).count();
            assert_eq!(found, 1, "{} {}", method.name(), setting.label);
        }
    }
    let pinhole = report.records.iter().find(|r| r.method == "pinhole").unwrap();
    let best_gather = report.records.iter().filter(|r| r.method == "gather").map(|r| r.psnr_db).fold(f64::MIN, f64::max);
    assert!(best_gather > pinhole.psnr_db, "the gather beats the unblurred image");

    let json: serde_json::Value = serde_json::from_str(&report.to_json()).unwrap();
    for field in
        ["scene", "method", "setting", "backend", "device", "time_ms", "stages_ms", "psnr_db", "ssim", "psnr_masked_db", "ssim_masked"]
    {
        assert!(json["records"][0].get(field).is_some(), "report.json records lack `{field}`");
    }
    assert!(report.to_markdown().contains("| method | setting | backend |"));

    // The max-CoC sweep: every backend method with a sweep setting at every target, the aperture
    // scaled so the largest CoC present lands on the target.
    for method in evaluated_methods().iter().filter(|m| m.uses_backend() && m.sweep_setting().is_some()) {
        let points: Vec<f64> = report.coc_sweep.iter().filter(|r| r.method == method.name()).map(|r| r.max_coc_px).collect();
        assert_eq!(points.len(), 2, "{}", method.name());
        for (got, want) in points.iter().zip([4.0, 16.0]) {
            assert!((got - want).abs() < 0.01 * want, "{}: largest CoC {got} px for a target of {want}", method.name());
        }
    }
    assert!(json["coc_sweep"][0].get("max_coc_px").is_some());
    assert!(json["backends"][0]["driver"].as_str().is_some_and(|d| !d.is_empty()), "the report names the driver");
    assert!(json["scenes"][0]["lens"]["aperture_radius"].as_f64().is_some_and(|a| a > 0.0), "and the lens");
    assert!(json["records"].as_array().unwrap().iter().any(|r| r.get("list_histogram").is_some()));

    // Plots: error against time, list lengths and the sweep, each as SVG and PNG.
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("dof-eval-plots-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let files = dof::eval::figures::write_all(&report, &dir).unwrap();
    for stem in ["simple-error-vs-time", "simple-list-lengths", "simple-max-coc"] {
        for ext in ["svg", "png"] {
            let path = dir.join(format!("{stem}.{ext}"));
            assert!(files.contains(&path), "{} not written", path.display());
            assert!(std::fs::metadata(&path).unwrap().len() > 1000, "{} is nearly empty", path.display());
        }
    }
    let svg = std::fs::read_to_string(dir.join("simple-error-vs-time.svg")).unwrap();
    assert!(svg.contains("Pareto front (cpu)") && svg.contains("multilayer (cpu)"), "the legend names the front and the methods");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn unknown_methods_are_named() {
    let mut backends: Vec<Box<dyn Backend>> = vec![Box::new(CpuBackend::new())];
    let options = EvalOptions {
        scenes: vec!["simple".into()],
        methods: vec!["nope".into()],
        quick: true,
        runs: 1,
        progress: false,
        coc_sweep: vec![],
        subsamples: 1,
        footprints: true,
        aimed_emitters: false,
        size: None,
    };
    let err = evaluate(&options, &mut backends).err().unwrap();
    assert!(err.to_string().contains("gather"), "{err}");
}

#[test]
fn a_gltf_scene_is_measured_against_its_accumulation_buffer() {
    let path = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("dof-eval-{}.glb", std::process::id()));
    std::fs::write(&path, dof::scene::export_builtin_glb("simple", 160, 90).unwrap()).unwrap();
    let mut backends: Vec<Box<dyn Backend>> = vec![Box::new(CpuBackend::new())];
    let scenes = vec![path.to_str().unwrap().to_string()];
    let options = EvalOptions {
        scenes,
        methods: vec!["gather".into(), "multilayer".into()],
        quick: true,
        runs: 1,
        progress: false,
        coc_sweep: vec![4.0],
        subsamples: 1,
        footprints: true,
        aimed_emitters: false,
        size: None,
    };
    let report = evaluate(&options, &mut backends).unwrap();
    std::fs::remove_file(&path).unwrap();
    let scene = &report.scenes[0];
    assert!(scene.name.ends_with("-gltf") && scene.reference == "accumulation" && scene.reference_spp == 64, "{scene:?}");
    assert!(scene.multi_layer_share > 0.0, "the peeled image has hidden layers: {scene:?}");
    // No sweep: it needs a built-in scene.
    assert!(report.coc_sweep.is_empty());
    // Order-correct splatting beats the gather inside the partial-occlusion region (seen: 23.3
    // against 22.2 dB).
    let region = |m: &str| report.records.iter().filter(|r| r.method == m).filter_map(|r| r.psnr_masked_db).fold(f64::MIN, f64::max);
    assert!(region("multilayer") > region("gather"), "multilayer {} dB, gather {} dB", region("multilayer"), region("gather"));
}

/// The evaluation runs every registry method through the generic one-shot path: it gives the
/// images each method's own one-shot function gives (bit for bit; layered DoF, whose function
/// plans on the host and whose context plans on the device, to 40 dB), so moving the evaluation
/// onto the registry changed no figure.
#[test]
fn the_generic_path_gives_each_methods_own_image() {
    use dof::eval::methods::{EvaluatedMethod, MethodInput, Registered, Setting};
    use dof::layers::RgbImage;
    use dof::methods::{bokeh, gather, ring_gather, splat};
    use dof::scene::{LayerOptions, builtin, raycast_layers};
    use dof_tests::oracle::{layered, raytrace};

    let scene = builtin("simple").unwrap().with_size(96, 54);
    let lens = scene.lens.thin_lens(&scene.camera).unwrap();
    let ml = raycast_layers(&scene.scene, &scene.camera, &lens, &LayerOptions::default()).unwrap();
    let input = MethodInput::new(ml.layers.clone(), lens, ml.margin);
    let b = &mut CpuBackend::new();
    let (front, depth) = (&input.front, &input.depth);
    let generic =
        |b: &mut CpuBackend, name: &str, setting: Setting| Registered::named(name).unwrap().run(b, &input, &setting).unwrap().image;
    let first = |name: &str| Registered::named(name).unwrap().settings(true).remove(0);
    let options = |name: &str| Registered::named(name).unwrap().options(&first(name)).unwrap();

    let own: Vec<(&str, Setting, RgbImage)> = vec![
        ("gather", first("gather"), gather::gather(b, front, depth, &lens, options("gather").gather_max_radius).unwrap().image),
        (
            "ring-gather",
            first("ring-gather"),
            ring_gather::ring_gather(
                b,
                front,
                depth,
                &lens,
                &ring_gather::RingGatherOptions { rings: options("ring-gather").ring_gather.rings, ..Default::default() },
            )
            .unwrap()
            .image,
        ),
        ("bokeh", first("bokeh"), bokeh::bokeh(b, front, depth, &lens, &Default::default()).unwrap().image),
        (
            "multilayer",
            first("multilayer"),
            splat::splat(b, &input.layers, &lens, &splat::SplatOptions { merge: splat::Merge::None, ..Default::default() }).unwrap().image,
        ),
        (
            "tiled",
            first("tiled"),
            splat::splat(b, &input.layers.front_layer(), &lens, &splat::SplatOptions { merge: splat::Merge::X4, ..Default::default() })
                .unwrap()
                .image,
        ),
        (
            "raytrace",
            first("raytrace"),
            raytrace::raytrace(
                b,
                &input.layers,
                &lens,
                &raytrace::RaytraceOptions { spp: options("raytrace").raytrace.spp, ..Default::default() },
            )
            .unwrap()
            .image,
        ),
    ];
    for (name, setting, image) in own {
        assert!(generic(b, name, setting) == image, "{name}: the evaluation's image differs from the method's own function's");
    }
    let setting = first("layered");
    let options = layered::LayeredOptions { cascaded: true, layers_per_doubling: 2, ..Default::default() };
    let own = layered::layered(b, &input.layers, &lens, &options).unwrap().image;
    assert_eq!(setting.label, "layers_per_doubling=2");
    let psnr = dof::metrics::compare(&generic(b, "layered", setting), &own, None).unwrap().psnr_db;
    assert!(psnr >= 40.0, "layered DoF: the device plan's image is {psnr:.1} dB from the host plan's");
}
