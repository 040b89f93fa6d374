//! The `dof` command as a user runs it: outputs appear, and bad input gets a clear message and a
//! non-zero exit (never a panic).

use dof::frame::MethodOption;
use std::path::PathBuf;
use std::process::{Command, Output};

fn dof(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_dof")).args(args).output().expect("the dof binary runs")
}

fn temp(name: &str) -> PathBuf {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("dof-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir.join(name)
}

/// Fails unless the command exited non-zero with `needle` in its message and without a panic.
fn assert_fails_with(args: &[&str], needle: &str) {
    let out = dof(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "`dof {}` should fail", args.join(" "));
    assert!(!stderr.contains("panicked"), "`dof {}` panicked:\n{stderr}", args.join(" "));
    assert!(stderr.contains(needle), "`dof {}` should say `{needle}`, said:\n{stderr}", args.join(" "));
}

#[test]
fn renders_a_builtin_scene_to_exr_and_png() {
    let out = temp("simple.exr");
    let o = dof(&["render", "--width", "64", "--height", "36", "--samples", "4", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(std::fs::metadata(&out).unwrap().len() > 0);
    assert!(std::fs::metadata(out.with_extension("png")).unwrap().len() > 0);

    // The written EXR (RGB + Z) is valid input for the image-only methods.
    let layers = temp("simple-layers.exr");
    let o = dof(&["render", "--scene", out.to_str().unwrap(), "--method", "layers", "--out", layers.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_fails_with(&["render", "--scene", out.to_str().unwrap(), "--method", "reference"], "needs the scene's geometry");
}

/// `--backend wgpu` (wgpu's Vulkan over lavapipe here) renders what the CPU renders.
#[test]
fn renders_on_wgpu_as_on_the_cpu() {
    let render = |backend: &str| {
        let out = temp(&format!("fence-{backend}.exr"));
        let args = ["render", "--scene", "fence", "--method", "multilayer", "--merge", "4x4", "--width", "96", "--height", "54"];
        let o = Command::new(env!("CARGO_BIN_EXE_dof"))
            .args(args)
            .args(["--backend", backend, "--out", out.to_str().unwrap()])
            .env("WGPU_BACKEND", "vulkan")
            .output()
            .expect("the dof binary runs");
        assert!(o.status.success(), "--backend {backend}: {}", String::from_utf8_lossy(&o.stderr));
        dof::io::read_rgb_exr(&out).unwrap().0
    };
    let (on_wgpu, on_cpu) = (render("wgpu"), render("cpu"));
    for (p, q) in on_wgpu.data.iter().zip(&on_cpu.data) {
        for c in 0..3 {
            assert!((p[c] - q[c]).abs() <= 1e-5 * q[c].abs().max(1e-2), "{p:?} on wgpu, {q:?} on the CPU");
        }
    }
}

#[test]
fn bad_scenes_are_reported() {
    assert_fails_with(&["render", "--scene", "nope"], "unknown built-in scene");
    assert_fails_with(&["render", "--scene", "/nonexistent/dir/model.gltf"], "model.gltf");
    assert_fails_with(&["render", "--scene", "/nonexistent/dir/in.exr"], "in.exr");
    let garbage = temp("garbage.exr");
    std::fs::write(&garbage, b"v/1\x01 this is not an EXR file at all").unwrap();
    assert_fails_with(&["render", "--scene", garbage.to_str().unwrap(), "--method", "pinhole"], "garbage.exr");
}

#[test]
fn bad_cameras_and_lenses_are_reported() {
    assert_fails_with(&["render", "--width", "0", "--samples", "1"], "--width must lie between 1 and");
    assert_fails_with(&["render", "--aperture-radius", "nan", "--samples", "1"], "aperture radius");
    assert_fails_with(&["render", "--yfov", "180", "--samples", "1"], "field of view");
    assert_fails_with(&["render", "--yfov", "0", "--samples", "1"], "field of view");
    assert_fails_with(&["render", "--focus", "-1", "--samples", "1"], "focus distance");
    assert_fails_with(&["render", "--focus", "0.02", "--focal-length", "50", "--samples", "1"], "shorter than the focus distance");
    assert_fails_with(&["render", "--f-number", "-2", "--samples", "1"], "f-number");
    assert_fails_with(&["render", "--eye", "1,2", "--samples", "1"], "three finite numbers");
    assert_fails_with(&["render", "--out", "image.png", "--samples", "1"], ".exr");
}

#[test]
fn splatting_methods_render_builtin_and_exr_scenes() {
    for (method, extra) in [("tiled", &["--merge", "2x2"][..]), ("multilayer", &["--merge", "4x4", "--tile", "24", "--max-coc", "20"][..])]
    {
        let out = temp(&format!("simple-{method}.exr"));
        let mut args = vec!["render", "--method", method, "--width", "96", "--height", "54", "--out", out.to_str().unwrap()];
        args.extend_from_slice(extra);
        let o = dof(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let stdout = String::from_utf8_lossy(&o.stdout);
        assert!(
            stdout.contains("tiles copied through") && stdout.contains("sort classes used"),
            "the run reports what it left out:\n{stdout}"
        );
        assert!(std::fs::metadata(out.with_extension("png")).unwrap().len() > 0);
    }
    // An EXR has no lens: the command asks for one, then renders with it.
    let layers = temp("exr-input.exr");
    let o = dof(&["render", "--method", "layers", "--width", "64", "--height", "36", "--out", layers.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let input = layers.to_str().unwrap();
    assert_fails_with(&["render", "--scene", input, "--method", "multilayer"], "--focus");
    assert_fails_with(&["render", "--scene", input, "--method", "tiled", "--focus", "4"], "--f-number or --aperture-radius");
    let out = temp("exr-multilayer.exr");
    let o =
        dof(&["render", "--scene", input, "--method", "multilayer", "--focus", "4.2", "--f-number", "1.4", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_fails_with(&["render", "--method", "multilayer", "--tile", "20", "--width", "32", "--height", "32"], "tile size 20");
    assert_fails_with(&["render", "--method", "multilayer", "--merge", "3x3"], "unknown merge level");
    assert_fails_with(
        &["render", "--method", "multilayer", "--max-coc", "1000", "--width", "32", "--height", "32"],
        "between 1 and 384 (px, CoC diameter)",
    );
}

#[test]
fn raytrace_layered_and_shaped_apertures_render() {
    let cases: [(&str, &[&str], &str); 4] = [
        ("raytrace", &["--spp", "4"], "rays per pixel"),
        ("layered", &["--no-cascade"], "layers used for CoC"),
        ("multilayer", &["--aperture", "blades:6:15:0.2"], "sort classes used"),
        ("bokeh", &["--aperture", "star:5"], "bright pixels detected"),
    ];
    for (method, extra, says) in cases {
        let out = temp(&format!("simple-{method}-extra.exr"));
        let mut args = vec!["render", "--method", method, "--width", "96", "--height", "54", "--out", out.to_str().unwrap()];
        args.extend_from_slice(extra);
        let o = dof(&args);
        assert!(o.status.success(), "{method}: {}", String::from_utf8_lossy(&o.stderr));
        assert!(String::from_utf8_lossy(&o.stdout).contains(says), "{method} reports what it did");
        // The context does not count the input's fragments (the device has no such figure): it
        // says so instead of printing 0.
        assert!(!String::from_utf8_lossy(&o.stdout).contains("fragments: 0 in"), "{method} reports an input it did not count");
    }
    // The same methods on an EXR (a multi-layer EXR written first; it needs a lens).
    let layers = temp("extra-layers.exr");
    let o = dof(&["render", "--method", "layers", "--width", "64", "--height", "36", "--out", layers.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for method in ["raytrace", "layered", "bokeh"] {
        let out = temp(&format!("exr-{method}.exr"));
        let o = dof(&[
            "render",
            "--scene",
            layers.to_str().unwrap(),
            "--method",
            method,
            "--focus",
            "4.2",
            "--f-number",
            "1.4",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{method} on an EXR: {}", String::from_utf8_lossy(&o.stderr));
    }
    assert_fails_with(
        &["render", "--method", "gather", "--aperture", "blades:6", "--width", "32", "--height", "32"],
        "option --aperture applies to multilayer, tiled, bokeh only",
    );
    assert_fails_with(&["render", "--method", "multilayer", "--aperture", "hexagon", "--width", "32", "--height", "32"], "blades:N");
    assert_fails_with(&["render", "--method", "raytrace", "--spp", "0", "--width", "32", "--height", "32"], "rays per pixel");
    assert_fails_with(
        &["render", "--method", "layered", "--layers-per-doubling", "9", "--width", "32", "--height", "32"],
        "layers per doubling",
    );
}

/// A built-in scene exported to binary glTF in the temp folder.
fn glb(name: &str, file: &str) -> PathBuf {
    let path = temp(file);
    let bytes = dof::scene::export_builtin_glb(name, 96, 54).expect("export");
    std::fs::write(&path, bytes).expect("write the glb");
    path
}

#[test]
fn renders_a_gltf_scene_on_both_backends() {
    let scene = glb("simple", "simple.glb");
    let s = scene.to_str().unwrap();
    for (method, extra) in
        [("pinhole", vec![]), ("layers", vec![]), ("reference", vec!["--samples", "4"]), ("multilayer", vec!["--merge", "4x4"])]
    {
        let out = temp(&format!("gltf-{method}.exr"));
        let mut args = vec!["render", "--scene", s, "--method", method, "--width", "96", "--height", "54", "--out", out.to_str().unwrap()];
        args.extend(extra);
        let o = dof(&args);
        assert!(o.status.success(), "{method}: {}", String::from_utf8_lossy(&o.stderr));
        assert!(std::fs::metadata(&out).unwrap().len() > 0, "{method} wrote no EXR");
    }
    // The same scene rasterised by the graphics pipeline on lavapipe.
    let out = temp("gltf-vulkan.exr");
    let o = dof(&[
        "render",
        "--scene",
        s,
        "--method",
        "reference",
        "--samples",
        "4",
        "--backend",
        "vulkan",
        "--width",
        "96",
        "--height",
        "54",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "vulkan: {}", String::from_utf8_lossy(&o.stderr));
    // An explicit camera replaces the file's.
    let out = temp("gltf-eye.exr");
    let o = dof(&[
        "render",
        "--scene",
        s,
        "--method",
        "pinhole",
        "--eye",
        "0,1,6",
        "--target",
        "0,0.5,0",
        "--yfov",
        "50",
        "--width",
        "48",
        "--height",
        "27",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "eye: {}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn bad_gltf_input_is_reported() {
    let scene = glb("simple", "whole.glb");
    let bytes = std::fs::read(&scene).unwrap();
    let truncated = temp("truncated.glb");
    std::fs::write(&truncated, &bytes[..bytes.len() / 2]).unwrap();
    assert_fails_with(&["render", "--scene", truncated.to_str().unwrap(), "--method", "pinhole"], "truncated.glb");
    let malformed = temp("malformed.gltf");
    std::fs::write(&malformed, b"{ this is not json").unwrap();
    assert_fails_with(&["render", "--scene", malformed.to_str().unwrap(), "--method", "pinhole"], "malformed.gltf");
    let s = scene.to_str().unwrap();
    assert_fails_with(&["render", "--scene", s, "--eye", "0,1,6"], "--target");
    assert_fails_with(&["render", "--scene", s, "--yfov", "0", "--method", "pinhole"], "field of view");
    assert_fails_with(&["render", "--scene", s, "--focus", "-2", "--method", "pinhole"], "focus");
    assert_fails_with(&["render", "--scene", s, "--focus", "0.01", "--focal-length", "50", "--method", "pinhole"], "focal length");
    assert_fails_with(&["render", "--scene", s, "--width", "0", "--method", "pinhole"], "--width must lie between 1 and");
    assert_fails_with(
        &["render", "--scene", s, "--width", "20000", "--height", "2", "--backend", "vulkan", "--method", "pinhole"],
        "framebuffer",
    );
}

/// The background and the guard band as a user sets them: a coloured sky renders on every path, a
/// guard band beyond its bound or a negative background is refused with a message.
#[test]
fn background_and_guard_band_flags() {
    let out = temp("fence-sky.exr");
    for band in ["auto", "off", "8"] {
        let o = dof(&[
            "render",
            "--scene",
            "fence",
            "--width",
            "64",
            "--height",
            "36",
            "--method",
            "multilayer",
            "--background",
            "1,0.5,0",
            "--guard-band",
            band,
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "--guard-band {band}: {}", String::from_utf8_lossy(&o.stderr));
    }
    assert_fails_with(&["render", "--scene", "fence", "--background", "-1,0,0", "--samples", "1"], "background colour");
    assert_fails_with(&["render", "--scene", "fence", "--guard-band", "500", "--samples", "1"], "guard band");
    assert_fails_with(&["render", "--scene", "fence", "--guard-band", "wide", "--samples", "1"], "auto");
    // An EXR carries its own background (its colour at depth +inf).
    assert_fails_with(
        &[
            "render",
            "--scene",
            out.to_str().unwrap(),
            "--method",
            "gather",
            "--focus",
            "20",
            "--aperture-radius",
            "0.045",
            "--background",
            "0,0,0",
        ],
        "depth +inf",
    );
    let o = dof(&[
        "render",
        "--scene",
        out.to_str().unwrap(),
        "--method",
        "gather",
        "--focus",
        "20",
        "--aperture-radius",
        "0.045",
        "--out",
        temp("fence-sky-gather.exr").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(
        String::from_utf8_lossy(&o.stdout).contains("edge policy"),
        "the EXR's edges are extended: {}",
        String::from_utf8_lossy(&o.stdout)
    );
}

/// Bad flags and outputs are refused before any work, naming the flag and the bound: outputs that
/// would overwrite an input, unwritable places, sizes beyond a documented bound.
#[test]
fn flags_and_outputs_are_checked_before_the_work() {
    // An EXR to read, and an aperture PNG to keep.
    let input = temp("input.exr");
    let o = dof(&["render", "--width", "32", "--height", "18", "--method", "pinhole", "--out", input.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let aperture_png = input.with_extension("png");
    let before = std::fs::read(&input).unwrap();
    assert_fails_with(
        &["render", "--scene", input.to_str().unwrap(), "--method", "pinhole", "--out", input.to_str().unwrap()],
        "would overwrite the input",
    );
    assert_eq!(std::fs::read(&input).unwrap(), before, "the input is untouched");
    // The PNG preview of --out would land on the aperture image.
    assert_fails_with(
        &["render", "--method", "multilayer", "--aperture", aperture_png.to_str().unwrap(), "--out", input.to_str().unwrap()],
        "would overwrite the input",
    );
    assert_fails_with(&["render", "--exposure", "0", "--samples", "1"], "--exposure must be a positive number");
    assert_fails_with(&["render", "--exposure", "-1", "--samples", "1"], "--exposure must be a positive number");
    assert_fails_with(&["render", "--samples", "1000000000"], "must lie between 1 and 65536");
    assert_fails_with(&["render", "--samples", "1", "--out", "/proc/dof-cannot-write-here/x.exr"], "cannot");
    assert_fails_with(&["bench", "sort", "--tiles", "4000000000"], "--tiles must lie between 1 and 1048576");
    let file = temp("not-a-folder");
    std::fs::write(&file, b"x").unwrap();
    assert_fails_with(&["eval", "--quick", "--out", file.to_str().unwrap()], "is a file");
    // Options a method would ignore are refused; --max-coc errors quote the diameter given.
    assert_fails_with(&["render", "--method", "reference", "--aperture", "blades:6", "--samples", "1"], "option --aperture applies to");
    assert_fails_with(&["render", "--method", "raytrace", "--max-coc", "20"], "option --max-coc applies to");
    assert_fails_with(&["render", "--method", "multilayer", "--max-coc", "0"], "got 0");
    assert_fails_with(&["render", "--method", "gather", "--max-coc", "200"], "got 200");
    // Negative coordinates need no `=`.
    let o = dof(&[
        "render",
        "--width",
        "32",
        "--height",
        "18",
        "--method",
        "pinhole",
        "--eye",
        "-0.1,0.2,0.5",
        "--target",
        "0,0,-1",
        "--out",
        temp("negative-eye.exr").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

/// A glTF view whose centre sees nothing needs `--focus`, and then renders (the background).
#[test]
fn focus_is_honoured_when_the_view_centre_sees_nothing() {
    let scene = glb("fence", "fence-focus.glb");
    let s = scene.to_str().unwrap();
    let away = ["render", "--scene", s, "--eye", "0,0,0", "--target", "0,0,1", "--width", "48", "--height", "27", "--method", "multilayer"];
    assert_fails_with(&away, "--focus");
    let out = temp("fence-away.exr");
    let mut args = away.to_vec();
    args.extend(["--focus", "5", "--out", out.to_str().unwrap()]);
    let o = dof(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

/// A device choice that matches nothing names the variable, not a missing driver.
#[test]
fn a_wrong_device_choice_names_the_variable() {
    let out = Command::new(env!("CARGO_BIN_EXE_dof")).args(["info"]).env("DOF_VULKAN_DEVICE", "99").output().expect("the dof binary runs");
    let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(text.contains("DOF_VULKAN_DEVICE") && text.contains("`99`"), "{text}");
    assert!(!text.contains("install a Vulkan driver"), "{text}");
}

/// `dof soak` records frames with changing method, size, aperture and lens through the frame API,
/// and reports flat memory as JSON; `dof bench frame --json` reports no allocation, readback or
/// extra submission per frame.
#[test]
fn soak_and_frame_bench_report_flat_memory_and_no_per_frame_work() {
    let o = dof(&["soak", "--frames", "40", "--backend", "cpu", "--max-size", "48", "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).expect("one JSON object");
    assert_eq!(j["frames"], 40);
    assert_eq!(j["validation_messages"], 0);
    assert_eq!(j["device_bytes_growth"], 0);
    assert!(j["host_bytes_growth"].as_i64().unwrap() <= 1 << 20, "{j}");
    assert_eq!(j["ok"], true);
    let o = dof(&["bench", "frame", "--backend", "cpu", "--scene", "simple", "--width", "64", "--height", "36", "--frames", "2", "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).expect("one JSON object");
    assert_eq!(
        (j["allocations_per_frame"].as_f64(), j["readbacks_per_frame"].as_f64(), j["submits_per_frame"].as_f64()),
        (Some(0.0), Some(0.0), Some(1.0)),
        "{j}"
    );
    assert!(j["device_bytes"].as_u64().unwrap() > 0 && j["gpu_ms"].as_f64().unwrap() > 0.0, "{j}");
    // The dispatch and barrier counts per frame: the CPU backend needs no barriers; Vulkan puts
    // barriers only between dependent commands, so fewer than one a dispatch, and at least one.
    let (commands, dispatches) = (j["commands_per_frame"].as_f64().unwrap(), j["dispatches_per_frame"].as_f64().unwrap());
    assert!(dispatches >= 5.0 && dispatches <= commands, "{j}");
    assert_eq!(j["barriers_per_frame"].as_f64(), Some(0.0), "{j}");
    let o =
        dof(&["bench", "frame", "--backend", "vulkan", "--scene", "simple", "--width", "64", "--height", "36", "--frames", "2", "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("one JSON object");
    assert_eq!(v["dispatches_per_frame"], j["dispatches_per_frame"], "the same frame records the same dispatches on both backends");
    let barriers = v["barriers_per_frame"].as_f64().unwrap();
    assert!(barriers >= 1.0 && barriers <= v["commands_per_frame"].as_f64().unwrap(), "{v}");
    // The frame time: one span a frame around the whole recording, over every timed frame.
    for r in [&j, &v] {
        let (median, p10, p90) =
            (r["frame_ms"].as_f64().unwrap(), r["frame_ms_p10"].as_f64().unwrap(), r["frame_ms_p90"].as_f64().unwrap());
        assert!(median > 0.0 && p10 <= median && median <= p90, "{r}");
        assert_eq!((r["frame_ms_frames"].as_u64(), r["warmup_frames"].as_u64()), (Some(2), Some(2)), "{r}");
        // At least the frames asked for (the time that follows is `timing`'s unit test: on a
        // loaded machine, two first frames on lavapipe can outlast the 500 ms); a pool that did
        // not overflow is not grown.
        let run = r["warmup_frames_run"].as_u64().unwrap();
        assert!(run >= 2, "{r}");
        assert_eq!(r["pool_grown_in_warmup"].as_u64(), Some(0), "{r}");
    }
    assert_fails_with(&["soak", "--frames", "0"], "--frames");
    assert_fails_with(&["bench", "frame", "--frames", "0"], "--frames");
    assert_fails_with(&["bench", "frame", "--warmup", "100001"], "--warmup");
}

/// `dof bench scaling` runs every point asked for, writes JSON, markdown and each plot, and reports
/// the points a budget skipped (never leaves them out silently); bad sizes are refused.
#[test]
fn scaling_bench_writes_points_and_plots_and_reports_skips() {
    let out = temp("scaling");
    let dir = out.to_str().unwrap();
    let args = [
        "bench",
        "scaling",
        "--backend",
        "cpu",
        "--sizes",
        "64x36,96x54",
        "--cocs",
        "2,4",
        "--coc-size",
        "64x36",
        "--methods",
        "gather,multilayer",
        "--runs",
        "1",
        "--json",
        "--out",
        dir,
    ];
    let o = dof(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).expect("one JSON object");
    let points = j["points"].as_array().unwrap();
    assert_eq!(points.len(), 2 * (2 + 2), "{j}");
    for method in ["gather", "multilayer"] {
        let series: Vec<&serde_json::Value> = points.iter().filter(|p| p["method"] == method && p["axis"] == "resolution").collect();
        assert_eq!(series.iter().map(|p| p["pixels"].as_u64().unwrap()).collect::<Vec<_>>(), vec![64 * 36, 96 * 54]);
        let blur: Vec<f64> =
            points.iter().filter(|p| p["method"] == method && p["axis"] == "max_coc").map(|p| p["max_coc_px"].as_f64().unwrap()).collect();
        assert!(blur.len() == 2 && (blur[0] - 2.0).abs() < 0.05 && (blur[1] - 4.0).abs() < 0.05, "{blur:?}");
    }
    for p in points {
        assert!(p["time_ms"].as_f64().is_some_and(|t| t > 0.0) && p["peak_device_bytes"].as_u64().is_some_and(|b| b > 0), "{p}");
        assert!(p.get("skipped").is_none(), "{p}");
    }
    // More pixels hold more device memory.
    let mem = |px: u64| {
        points.iter().find(|p| p["method"] == "gather" && p["pixels"] == px && p["axis"] == "resolution").unwrap()["peak_device_bytes"]
            .as_u64()
            .unwrap()
    };
    assert!(mem(96 * 54) > mem(64 * 36));
    for stem in ["scaling-time-vs-pixels-cpu", "scaling-time-vs-coc-cpu", "scaling-memory-vs-pixels-cpu"] {
        for ext in ["svg", "png"] {
            let path = out.join(format!("{stem}.{ext}"));
            assert!(std::fs::metadata(&path).is_ok_and(|m| m.len() > 1000), "{} not written", path.display());
        }
    }
    assert!(std::fs::read_to_string(out.join("scaling.md")).unwrap().contains("| gather | max_coc=96 | cpu |"));

    // A budget every run exceeds: each series runs its first point and reports the rest as skipped.
    let o = dof(&[
        "bench",
        "scaling",
        "--backend",
        "cpu",
        "--sizes",
        "64x36,96x54",
        "--cocs",
        "none",
        "--methods",
        "gather",
        "--runs",
        "1",
        "--budget-s",
        "1e-9",
        "--no-plots",
        "--json",
        "--out",
        dir,
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let points = j["points"].as_array().unwrap();
    assert_eq!(points.len(), 2);
    assert!(points[0]["time_ms"].as_f64().is_some() && points[0]["runs"] == 0, "{j}");
    assert!(points[1]["time_ms"].is_null() && points[1]["skipped"].as_str().is_some_and(|s| s.contains("budget")), "{j}");

    assert_fails_with(&["bench", "scaling", "--sizes", "64by36"], "WIDTHxHEIGHT");
    assert_fails_with(&["bench", "scaling", "--backend", "cpu", "--sizes", "4x4", "--cocs", "none"], "between 8x8");
    assert_fails_with(&["bench", "scaling", "--backend", "cpu", "--methods", "pinhole"], "runs no kernels");
    std::fs::remove_dir_all(&out).ok();
}

/// The engine-grade gather renders with its knob, refuses a ring count out of range or given to
/// another method; `dof bench ratios` measures both methods per scene and backend and writes them.
#[test]
fn ring_gather_renders_and_cost_ratios_are_measured() {
    let exr = temp("ring.exr");
    let o = dof(&[
        "render",
        "--scene",
        "simple",
        "--method",
        "ring-gather",
        "--rings",
        "3",
        "--width",
        "64",
        "--height",
        "36",
        "--out",
        exr.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("3 rings, 37 samples"), "{}", String::from_utf8_lossy(&o.stdout));
    assert!(exr.exists() && exr.with_extension("png").exists());
    assert_fails_with(
        &["render", "--scene", "simple", "--method", "ring-gather", "--rings", "0", "--width", "64", "--height", "36"],
        "between 1 and 8 (rings)",
    );
    assert_fails_with(
        &["render", "--scene", "simple", "--method", "gather", "--rings", "3"],
        "option --rings applies to ring-gather, scatter-gather only",
    );

    let out = temp("ratios");
    let dir = out.to_str().unwrap();
    let o = dof(&[
        "bench",
        "ratios",
        "--backend",
        "cpu",
        "--scenes",
        "simple,fence",
        "--width",
        "64",
        "--height",
        "36",
        "--spp",
        "4",
        "--runs",
        "1",
        "--json",
        "--out",
        dir,
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rows: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON on stdout");
    let rows = rows.as_array().expect("an array of rows");
    assert_eq!(rows.len(), 2);
    for r in rows {
        let ratio = r["ratio"].as_f64().unwrap();
        assert!(ratio.is_finite() && ratio > 0.0, "{r}");
        assert_eq!(r["multilayer"]["setting"], "merge=4x4 tile=16");
        assert_eq!(r["ring_gather"]["setting"], "rings=5");
        assert!(r["ring_gather"]["psnr_db"].as_f64().unwrap() > 10.0, "{r}");
    }
    assert!(std::fs::read_to_string(out.join("ratios.md")).unwrap().contains("| fence | cpu |"));
    assert_fails_with(&["bench", "ratios", "--backend", "cpu", "--scenes", "nowhere", "--width", "64", "--height", "36"], "nowhere");
}

/// Fails unless the command failed naming `needle` within `seconds` (refused before any work).
fn assert_fails_fast_with(args: &[&str], needle: &str, seconds: u64) {
    let start = std::time::Instant::now();
    assert_fails_with(args, needle);
    assert!(start.elapsed() < std::time::Duration::from_secs(seconds), "`dof {}` took {:?}", args.join(" "), start.elapsed());
}

/// Every sample count has a stated bound, refused up front naming the flag; runs and counts of
/// zero are refused naming the flag, and messages name the flag the user typed.
#[test]
fn sample_counts_and_runs_are_bounded_naming_the_flag() {
    let out = temp("bounded");
    let o = out.to_str().unwrap();
    let ratios = ["bench", "ratios", "--backend", "cpu", "--scenes", "simple", "--width", "32", "--height", "18", "--out", o];
    for (flag, value, says) in
        [("--spp", "4000000000", "65536"), ("--spp", "100000000", "65536"), ("--spp", "0", "--spp"), ("--runs", "0", "--runs")]
    {
        let mut args = ratios.to_vec();
        args.extend([flag, value]);
        assert_fails_fast_with(&args, flag, 10);
        assert_fails_with(&args, says);
    }
    let scenes = ["scenes", "--only", "simple", "--width", "32", "--height", "18", "--raster"];
    for (extra, flag) in [
        (&["--accumulation", "4", "--reference-spp", "4000000000"][..], "--reference-spp"),
        (&["--accumulation", "4000000000"][..], "--accumulation"),
        (&["--accumulation", "0"][..], "--accumulation"),
        (&["--accumulation", "4,4"][..], "twice"),
        (&["--max-spp", "0"][..], "--max-spp"),
        (&["--max-spp", "4000000000"][..], "--max-spp"),
    ] {
        let mut args = scenes.to_vec();
        args.extend(extra);
        assert_fails_fast_with(&args, flag, 10);
        let stderr = String::from_utf8_lossy(&dof(&args).stderr).into_owned();
        assert!(!stderr.contains("start_spp") && !stderr.contains("--samples"), "names another flag: {stderr}");
    }
    assert_fails_fast_with(&["bench", "sort", "--backend", "cpu", "--tiles", "16", "--runs", "0"], "--runs", 10);
    assert_fails_fast_with(&["bench", "sort", "--backend", "cpu", "--tiles", "16", "--runs", "99999999999"], "--runs", 10);
    // The most lists hold about 10^9 keys, some 40 GB of host memory: refused up front where the
    // machine has less free (as CI's has), instead of aborting part way.
    if dof::memory::available().is_some_and(|free| free < 40 << 30) {
        assert_fails_fast_with(&["bench", "sort", "--backend", "cpu", "--tiles", "1048576", "--runs", "1"], "GiB of memory", 10);
    }
    assert_fails_fast_with(&["eval", "--quick", "--backend", "cpu", "--runs", "0", "--out", o], "--runs", 10);
    assert_fails_fast_with(
        &["bench", "scaling", "--backend", "cpu", "--sizes", "32x18", "--cocs", "none", "--runs", "0", "--out", o],
        "--runs",
        10,
    );
}

/// A scene, method or radius named twice, or a name that does not exist, is refused before any
/// work, naming the flag (and the valid names).
#[test]
fn duplicates_and_unknown_names_are_refused_up_front() {
    let out = temp("names");
    let o = out.to_str().unwrap();
    let eval = ["eval", "--quick", "--backend", "cpu", "--no-plots", "--coc-sweep", "none", "--out", o];
    for (extra, says) in [
        (&["--scenes", "simple,simple"][..], "--scenes names `simple` twice"),
        (&["--methods", "gather,gather"][..], "--methods names `gather` twice"),
        (&["--scenes", "simple,nosuch"][..], "railing"),
        (&["--methods", "gather,nosuch"][..], "nosuch"),
    ] {
        let mut args = eval.to_vec();
        args.extend(extra);
        assert_fails_fast_with(&args, says, 10);
    }
    assert_fails_fast_with(&["eval", "--quick", "--backend", "cpu", "--coc-sweep", "4,4", "--out", o], "--coc-sweep", 10);
    assert_fails_fast_with(&["eval", "--quick", "--backend", "cpu", "--coc-sweep", "1000000000", "--out", o], "at most 1024", 10);
    assert!(!out.join("report.json").exists(), "no work was done");
    let ratios = ["bench", "ratios", "--backend", "cpu", "--width", "32", "--height", "18", "--spp", "1", "--runs", "1", "--out", o];
    for (scenes, says) in [("simple,simple", "--scenes names `simple` twice"), ("simple,nosuch", "railing")] {
        let mut args = ratios.to_vec();
        args.extend(["--scenes", scenes]);
        assert_fails_fast_with(&args, says, 10);
    }
    let dir = temp("mitsuba-nosuch");
    assert_fails_fast_with(&["scenes", "--only", "nosuch", "--export-mitsuba", dir.to_str().unwrap()], "nosuch", 10);
    assert_fails_fast_with(&["scenes", "--only", "simple,simple"], "twice", 10);
}

/// An export never deletes or overwrites a file dof did not write; a file given as the folder is
/// named with its flag.
#[test]
fn exports_keep_the_users_files() {
    let dir = temp("mitsuba-user");
    std::fs::create_dir_all(&dir).unwrap();
    let mine = dir.join("simple.xml");
    std::fs::write(&mine, b"<my own scene/>").unwrap();
    let d = dir.to_str().unwrap();
    assert_fails_with(&["scenes", "--only", "simple", "--width", "32", "--height", "18", "--export-mitsuba", d], "simple.xml");
    assert_eq!(std::fs::read(&mine).unwrap(), b"<my own scene/>", "the user's file is kept");
    // The same for the glTF export.
    std::fs::write(dir.join("fence.glb"), b"mine").unwrap();
    assert_fails_with(&["scenes", "--only", "fence", "--width", "32", "--height", "18", "--export", d], "fence.glb");
    assert_eq!(std::fs::read(dir.join("fence.glb")).unwrap(), b"mine");
    // Into a folder of its own, an export runs twice (replacing what it wrote) and keeps other files.
    let fresh = temp("mitsuba-fresh");
    std::fs::create_dir_all(&fresh).unwrap();
    std::fs::write(fresh.join("notes.txt"), b"notes").unwrap();
    for _ in 0..2 {
        let o = dof(&["scenes", "--only", "simple,fence", "--width", "32", "--height", "18", "--export-mitsuba", fresh.to_str().unwrap()]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    assert!(fresh.join("simple.json").exists() && fresh.join("fence.json").exists());
    assert_eq!(std::fs::read(fresh.join("notes.txt")).unwrap(), b"notes");
    // A file where a folder is wanted: the flag and the path are named.
    let file = temp("export-here-is-a-file");
    std::fs::write(&file, b"x").unwrap();
    for flag in ["--export-mitsuba", "--export", "--dump"] {
        assert_fails_with(&["scenes", "--only", "simple", flag, file.to_str().unwrap()], flag);
        assert_fails_with(&["scenes", "--only", "simple", flag, file.to_str().unwrap()], "export-here-is-a-file");
    }
}

/// The files a glTF scene reads (its buffers and textures) are inputs too: an output over one is
/// refused before any work, naming both.
#[test]
fn outputs_never_overwrite_a_scenes_textures() {
    let dir = temp("gltf-texture");
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("scene.gltf");
    std::fs::write(&scene, br#"{"asset":{"version":"2.0"},"buffers":[{"uri":"scene.bin","byteLength":4}],"images":[{"uri":"scene.png"}]}"#)
        .unwrap();
    std::fs::write(dir.join("scene.bin"), [0u8; 4]).unwrap();
    let texture = dir.join("scene.png");
    std::fs::write(&texture, b"the user's texture").unwrap();
    let out = dir.join("scene.exr");
    let args = ["render", "--scene", scene.to_str().unwrap(), "--method", "pinhole", "--out", out.to_str().unwrap()];
    assert_fails_fast_with(&args, "would overwrite the input", 10);
    assert_fails_with(&args, texture.to_str().unwrap());
    assert_eq!(std::fs::read(&texture).unwrap(), b"the user's texture");
    assert!(!out.exists());
}

/// An EXR fixes its own size, view and layers: the flags that would change them are refused, not
/// ignored; a 1x1 aperture image is refused saying why.
#[test]
fn exr_input_refuses_size_view_and_layer_flags_and_tiny_apertures_say_why() {
    let input = temp("fixed.exr");
    let o = dof(&["render", "--width", "32", "--height", "18", "--method", "pinhole", "--out", input.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let base = ["render", "--scene", input.to_str().unwrap(), "--method", "gather", "--focus", "4", "--f-number", "2"];
    for extra in [
        &["--width", "64"][..],
        &["--height", "64"],
        &["--guard-band", "8"],
        &["--eye", "0,0,1"],
        &["--target", "0,0,-1"],
        &["--layers", "2"],
    ] {
        let mut args = base.to_vec();
        args.extend(extra);
        assert_fails_fast_with(&args, extra[0], 10);
        assert_fails_with(&args, "an EXR fixes its own size, view and layers");
    }
    let tiny = temp("tiny-aperture.png");
    let mut encoded = Vec::new();
    {
        let mut encoder = dof::io::codecs::png::Encoder::new(&mut encoded, 1, 1);
        encoder.set_color(dof::io::codecs::png::ColorType::Grayscale);
        encoder.write_header().unwrap().write_image_data(&[255]).unwrap();
    }
    std::fs::write(&tiny, encoded).unwrap();
    let args = ["render", "--method", "multilayer", "--width", "32", "--height", "18", "--aperture", tiny.to_str().unwrap(), "--out"];
    let out = temp("tiny-aperture-out.exr");
    let mut args = args.to_vec();
    args.push(out.to_str().unwrap());
    assert_fails_with(&args, "1x1 is below the minimum size");
    assert_fails_with(&args, "at least 2 pixels");
}

/// Cheap base arguments per subcommand, so that an accepted value finishes in a moment: tiny
/// sizes, one run, one sample, the CPU backend, outputs in a temp folder.
/// A render flag that one method takes runs with that method (the others refuse or ignore it).
fn flag_table_base(sub: &str, flag: &str, dir: &std::path::Path) -> Vec<(String, Option<String>)> {
    let d = |name: &str| dir.join(name).to_str().unwrap().to_string();
    let pairs: Vec<(&str, Option<String>)> = match sub {
        "render" => {
            let sequence = ["--frames", "--focus-to", "--orbit", "--aperture-radius-to", "--f-number-to"].contains(&flag);
            let method = match flag {
                "--rings" => "ring-gather",
                "--lum-threshold" | "--sprites" => "bokeh",
                "--layers-per-doubling" => "layered",
                "--tile" => "multilayer",
                "--max-coc" => "gather",
                _ => "reference",
            };
            vec![
                ("--method", Some(method.into())),
                ("--width", Some("32".into())),
                ("--height", Some("18".into())),
                ("--out", Some(d("render.exr"))),
            ]
            .into_iter()
            .chain((method == "reference").then(|| ("--samples", Some("1".into()))))
            .chain(sequence.then(|| ("--frames", Some("2".into()))))
            .collect()
        }
        "eval" => vec![
            ("--quick", None),
            ("--backend", Some("cpu".into())),
            ("--scenes", Some("simple".into())),
            ("--methods", Some("pinhole".into())),
            ("--runs", Some("1".into())),
            ("--coc-sweep", Some("none".into())),
            ("--no-plots", None),
            ("--out", Some(d("eval"))),
        ],
        "scenes" => vec![("--only", Some("simple".into())), ("--width", Some("32".into())), ("--height", Some("18".into()))],
        "bench sort" => vec![
            ("--backend", Some("cpu".into())),
            ("--tiles", Some("16".into())),
            ("--max-len", Some("64".into())),
            ("--runs", Some("1".into())),
        ],
        "bench frame" => vec![
            ("--backend", Some("cpu".into())),
            ("--scene", Some("simple".into())),
            ("--width", Some("32".into())),
            ("--height", Some("18".into())),
            ("--frames", Some("1".into())),
        ],
        "bench scaling" => vec![
            ("--backend", Some("cpu".into())),
            ("--sizes", Some("32x18".into())),
            ("--cocs", Some("none".into())),
            ("--methods", Some("gather".into())),
            ("--runs", Some("1".into())),
            ("--no-plots", None),
            ("--out", Some(d("scaling"))),
        ],
        "bench ratios" => vec![
            ("--backend", Some("cpu".into())),
            ("--scenes", Some("simple".into())),
            ("--width", Some("32".into())),
            ("--height", Some("18".into())),
            ("--spp", Some("1".into())),
            ("--runs", Some("1".into())),
            ("--out", Some(d("ratios"))),
        ],
        "soak" => vec![("--frames", Some("2".into())), ("--backend", Some("cpu".into())), ("--max-size", Some("16".into()))],
        other => panic!("no base arguments for `dof {other}`: add cheap ones here"),
    };
    pairs.into_iter().map(|(f, v)| (f.to_string(), v)).collect()
}

/// Flag values that are still accepted or refused without naming the flag, each with the reason
/// it is not fixed here.
const FLAG_TABLE_PENDING: &[(&str, &str, &str, &str)] = &[];

/// Every numeric option of every subcommand (from the command's own definition, so a new flag
/// cannot be missed; `view` opens a window and is left out) with 0, -1, huge values and NaN: each
/// is refused with a message naming the flag (and no panic), or succeeds, within 20 s.
#[test]
fn every_numeric_flag_survives_zero_negative_huge_and_nan() {
    let table = dof(&["flag-table"]);
    assert!(table.status.success(), "{}", String::from_utf8_lossy(&table.stderr));
    let table = String::from_utf8_lossy(&table.stdout).into_owned();
    let rows: Vec<(&str, &str)> = table
        .lines()
        .filter_map(|l| {
            let mut parts = l.split('\t');
            Some((parts.next()?, parts.next()?))
        })
        .filter(|(sub, _)| *sub != "view")
        .collect();
    assert!(rows.len() > 20 && rows.contains(&("bench ratios", "--spp")), "{table}");
    let dir = temp("flag-table");
    std::fs::create_dir_all(&dir).unwrap();
    let mut failures = Vec::new();
    for (sub, flag) in rows {
        for value in ["0", "-1", "1e30", "99999999999", "nan"] {
            if FLAG_TABLE_PENDING.iter().any(|p| (p.0, p.1, p.2) == (sub, flag, value)) {
                continue;
            }
            let mut args: Vec<String> = sub.split(' ').map(str::to_string).collect();
            for (f, v) in flag_table_base(sub, flag, &dir) {
                if f != flag {
                    args.push(f);
                    args.extend(v);
                }
            }
            args.push(format!("{flag}={value}"));
            // Into a file, not a pipe: a child writing more than a pipe holds would block.
            let log = dir.join("stderr.txt");
            let mut child = Command::new(env!("CARGO_BIN_EXE_dof"))
                .args(&args)
                .stdout(std::process::Stdio::null())
                .stderr(std::fs::File::create(&log).expect("the log file"))
                .spawn()
                .expect("the dof binary runs");
            let start = std::time::Instant::now();
            let status = loop {
                if let Some(status) = child.try_wait().expect("wait") {
                    break Some(status);
                }
                if start.elapsed() > std::time::Duration::from_secs(20) {
                    child.kill().ok();
                    child.wait().ok();
                    break None;
                }
                std::thread::sleep(std::time::Duration::from_millis(20));
            };
            let stderr = String::from_utf8_lossy(&std::fs::read(&log).unwrap_or_default()).into_owned();
            let run = format!("`dof {}`", args.join(" "));
            match status {
                None => failures.push(format!("{run} ran past 20 s")),
                Some(s) if stderr.contains("panicked") => failures.push(format!("{run} panicked ({s}):\n{stderr}")),
                Some(s) if s.success() => eprintln!("accepted: {run}"),
                Some(s) if s.code().is_none() => failures.push(format!("{run} was killed ({s}):\n{stderr}")),
                Some(_) if !stderr.contains(flag) => failures.push(format!("{run} was refused without naming {flag}:\n{stderr}")),
                Some(_) => {}
            }
        }
    }
    assert!(failures.is_empty(), "{} flag values misbehave:\n{}", failures.len(), failures.join("\n"));
}

/// An EXR whose header declares 20000x20000 pixels in a 3 MB file is refused from the header,
/// quickly and without talk of a device on a CPU run: as a scene, and as a `compare` mask.
#[test]
fn huge_exr_headers_are_refused_before_decoding() {
    let small = temp("header-small.exr");
    let o = dof(&["render", "--width", "8", "--height", "8", "--method", "pinhole", "--out", small.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut bytes = std::fs::read(&small).unwrap();
    let key = b"dataWindow\0box2i\0";
    let at = bytes.windows(key.len()).position(|w| w == key).expect("a data window") + key.len() + 4;
    bytes[at + 8..at + 16].copy_from_slice(&[19999i32.to_le_bytes(), 19999i32.to_le_bytes()].concat());
    bytes.resize(3 << 20, 0);
    let huge = temp("header-huge.exr");
    std::fs::write(&huge, &bytes).unwrap();
    let (s, h) = (small.to_str().unwrap(), huge.to_str().unwrap());
    let out = temp("header-huge-out.exr");
    let render = ["render", "--scene", h, "--method", "gather", "--focus", "4", "--f-number", "2", "--backend", "cpu"];
    let mut args = render.to_vec();
    args.extend(["--out", out.to_str().unwrap()]);
    assert_fails_fast_with(&args, "20000x20000", 5);
    assert_fails_with(&args, "header-huge.exr");
    let stderr = String::from_utf8_lossy(&dof(&args).stderr).into_owned();
    assert!(!stderr.contains("device"), "{stderr}");
    assert_fails_fast_with(&["compare", s, s, "--mask", h], "20000x20000", 5);
}

/// A size beyond the host's limits on a CPU run is refused quickly, without talk of a device.
#[test]
fn host_size_limits_on_a_cpu_run_do_not_blame_a_device() {
    let out = temp("too-large.exr");
    let args = ["render", "--width", "65536", "--height", "65536", "--samples", "1", "--backend", "cpu", "--out", out.to_str().unwrap()];
    assert_fails_fast_with(&args, "too large", 10);
    let stderr = String::from_utf8_lossy(&dof(&args).stderr).into_owned();
    assert!(!stderr.contains("device"), "{stderr}");
}

/// The frames of an animated GIF.
fn gif_frames(path: &std::path::Path) -> usize {
    let file = std::fs::File::open(path).expect("the GIF");
    let mut decoder = dof::io::codecs::gif::DecodeOptions::new().read_info(file).expect("a GIF");
    let mut frames = 0;
    while decoder.read_next_frame().expect("a GIF frame").is_some() {
        frames += 1;
    }
    frames
}

/// `--frames 4` with a focus pull: four EXRs beside `--out`, an animated GIF of four frames, frames
/// that differ, and one context for the sequence (no allocation after the first frame).
#[test]
fn sequence_writes_frames_and_an_animated_preview() {
    let out = temp("seq/pull.exr");
    let o = dof(&[
        "render",
        "--method",
        "ring-gather",
        "--width",
        "48",
        "--height",
        "27",
        "--aperture-radius",
        "0.2",
        "--frames",
        "4",
        "--focus-to",
        "1",
        "--out",
        out.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(stdout.contains("context made once for 4 frames: 0 allocations in the frames after the first"), "{stdout}");
    let frames: Vec<_> = (0..4)
        .map(|i| {
            let path = temp(&format!("seq/pull-{i:04}.exr"));
            dof::io::read_rgb_exr(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display())).0
        })
        .collect();
    assert!(!temp("seq/pull-0004.exr").exists());
    assert_eq!(gif_frames(&temp("seq/pull.gif")), 4);
    for (i, pair) in frames.windows(2).enumerate() {
        assert!(pair[0].data != pair[1].data, "a focus pull's frames {i} and {} are the same", i + 1);
    }
}

/// Every registry method, the references and the pinhole image render a short sequence (an orbit
/// and an aperture ramp); a registry method through one context.
#[test]
fn every_method_renders_a_sequence() {
    let methods = dof::frame::METHODS.iter().map(|m| m.name).chain(["pinhole", "reference", "layers"]);
    for method in methods {
        let out = temp(&format!("seq-all/{method}.exr"));
        // Samples for the methods that take them (the reference's renders, ray tracing's rays).
        let samples = dof::frame::registry::method(method).map_or(method == "reference", |m| m.takes(MethodOption::Samples));
        let samples = if samples { &["--samples", "2"][..] } else { &[][..] };
        let o = dof(&[
            &["render", "--method", method, "--width", "24", "--height", "16"][..],
            samples,
            &["--frames", "2", "--orbit", "3", "--f-number-to", "4", "--out", out.to_str().unwrap()][..],
        ]
        .concat());
        let stdout = String::from_utf8_lossy(&o.stdout);
        assert!(o.status.success(), "{method}: {}", String::from_utf8_lossy(&o.stderr));
        assert!(temp(&format!("seq-all/{method}-0001.exr")).exists(), "{method}: {stdout}");
        assert_eq!(gif_frames(&temp(&format!("seq-all/{method}.gif"))), 2, "{method}");
        if dof::frame::METHODS.iter().any(|m| m.name == method) {
            assert!(stdout.contains("0 allocations in the frames after the first"), "{method}: {stdout}");
        }
    }
}

/// An EXR sequence in (`--scene shot-####.exr`): every matching file in frame order through one
/// context, a focus pull over them, gaps reported, outputs that would overwrite a frame refused.
#[test]
fn exr_sequences_render_in_frame_order_through_one_context() {
    // Three RGB+Z frames of an orbit, written as a compositor would hand them over.
    let src = temp("exr-seq/src/shot.exr");
    let o = dof(&[
        "render",
        "--method",
        "pinhole",
        "--width",
        "40",
        "--height",
        "24",
        "--frames",
        "3",
        "--orbit",
        "4",
        "--out",
        src.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let pattern = temp("exr-seq/src/shot-####.exr");
    let pattern = pattern.to_str().unwrap();
    let out = temp("exr-seq/out/blur.exr");
    let lens = ["--focus", "4", "--aperture-radius", "0.1", "--focus-to", "8"];
    let args = |extra: &[&'static str], out: &str| {
        ["render", "--scene", pattern, "--method", "multilayer"]
            .iter()
            .copied()
            .chain(lens)
            .chain(extra.iter().copied())
            .chain(["--out"])
            .chain([out])
            .map(str::to_string)
            .collect::<Vec<_>>()
    };
    let run = |a: Vec<String>| dof(&a.iter().map(String::as_str).collect::<Vec<_>>());
    let o = run(args(&[], out.to_str().unwrap()));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(stdout.contains("3 frames"), "{stdout}");
    assert!(stdout.contains("context made once for 3 frames: 0 allocations in the frames after the first"), "{stdout}");
    let frames: Vec<_> = (0..3).map(|i| dof::io::read_rgb_exr(temp(&format!("exr-seq/out/blur-{i:04}.exr"))).unwrap().0).collect();
    assert_eq!(gif_frames(&temp("exr-seq/out/blur.gif")), 3);
    assert!(frames[0].data != frames[1].data && frames[1].data != frames[2].data, "the frames of an orbit and a focus pull differ");

    // `--frames 2` renders the first two; more than there are is refused.
    let o = run(args(&["--frames", "2"], temp("exr-seq/two/t.exr").to_str().unwrap()));
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(temp("exr-seq/two/t-0001.exr").exists() && !temp("exr-seq/two/t-0002.exr").exists());
    let too_many = args(&["--frames", "5"], temp("exr-seq/x/t.exr").to_str().unwrap());
    assert_fails_with(&too_many.iter().map(String::as_str).collect::<Vec<_>>(), "has 3 frames");

    // Outputs named like the input frames would overwrite them: refused before any work.
    let clash = args(&[], temp("exr-seq/src/shot.exr").to_str().unwrap());
    assert_fails_with(&clash.iter().map(String::as_str).collect::<Vec<_>>(), "would overwrite the input");
    assert!(dof::io::read_rgb_exr(temp("exr-seq/src/shot-0000.exr")).is_ok());

    // A gap is reported, and the sequence goes on; a frame of another size is refused by name.
    std::fs::rename(temp("exr-seq/src/shot-0001.exr"), temp("exr-seq/src/shot-0007.exr")).unwrap();
    let o = run(args(&[], temp("exr-seq/gap/g.exr").to_str().unwrap()));
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(stderr.contains("frame 1 is missing") && stderr.contains("frames 3 to 6 are missing"), "{stderr}");
    let small = temp("exr-seq/src/small.exr");
    let o = dof(&["render", "--method", "pinhole", "--width", "20", "--height", "24", "--out", small.to_str().unwrap()]);
    assert!(o.status.success());
    std::fs::rename(&small, temp("exr-seq/src/shot-0009.exr")).unwrap();
    let mixed = args(&[], temp("exr-seq/mixed/m.exr").to_str().unwrap());
    assert_fails_with(&mixed.iter().map(String::as_str).collect::<Vec<_>>(), "shot-0009.exr is 20x24");

    // Flags that need geometry, or one file, say so.
    assert_fails_with(
        &["render", "--scene", pattern, "--focus", "4", "--aperture-radius", "0.1", "--frames", "2", "--orbit", "1"],
        "no geometry",
    );
    let one = temp("exr-seq/src/shot-0000.exr");
    assert_fails_with(
        &["render", "--scene", one.to_str().unwrap(), "--focus", "4", "--aperture-radius", "0.1", "--frames", "2"],
        "pattern",
    );
    assert_fails_with(
        &["render", "--scene", temp("exr-seq/none-####.exr").to_str().unwrap(), "--focus", "4", "--aperture-radius", "0.1"],
        "no file",
    );
}

#[test]
fn sequence_flags_are_refused_naming_the_flag() {
    let out = temp("seq-bad/x.exr");
    let o = out.to_str().unwrap();
    let base = ["render", "--method", "pinhole", "--width", "16", "--height", "16", "--out", o];
    let with = |extra: &[&'static str]| base.iter().copied().chain(extra.iter().copied()).collect::<Vec<_>>();
    assert_fails_with(&with(&["--frames", "0"]), "--frames");
    assert_fails_with(&with(&["--frames", "100000"]), "--frames");
    assert_fails_with(&with(&["--frames", "2", "--focus-to", "-1"]), "--focus-to");
    assert_fails_with(&with(&["--frames", "2", "--focus-to", "nan"]), "--focus-to");
    assert_fails_with(&with(&["--frames", "2", "--orbit", "1000"]), "--orbit");
    assert_fails_with(&with(&["--frames", "2", "--f-number-to", "0"]), "--f-number-to");
    assert_fails_with(&with(&["--frames", "2", "--aperture-radius-to", "-0.1"]), "--aperture-radius-to");
    assert_fails_with(&with(&["--focus-to", "2"]), "--frames");
}

/// `dof eval --temporal --quick`: a report with a per-frame PSNR and a temporal PSNR for every
/// method of the frame API, each through one context (no allocation after the first frame).
#[test]
fn eval_temporal_writes_a_temporal_psnr_per_method() {
    let out = temp("eval-temporal");
    let o = dof(&["eval", "--temporal", "--quick", "--backend", "cpu", "--no-plots", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(out.join("temporal.json")).unwrap()).unwrap();
    let rows = json["methods"].as_array().expect("methods");
    assert_eq!(rows.len(), dof::frame::METHODS.len());
    for row in rows {
        let frames = row["psnr_db"].as_array().unwrap().len();
        assert_eq!(frames, json["frames"].as_u64().unwrap() as usize, "{row}");
        assert_eq!(row["temporal_psnr_db"].as_array().unwrap().len(), frames - 1, "{row}");
        assert!(row["mean_temporal_psnr_db"].as_f64().is_some_and(|p| p > 10.0), "{row}");
        assert_eq!(row["allocations_after_first_frame"], 0, "{row}");
    }
    let md = std::fs::read_to_string(out.join("temporal.md")).unwrap();
    assert!(md.contains("| ring-gather |"), "{md}");
}

/// `dof render --scene SCENE --method METHOD --width 64 --height 36 EXTRA.. --out OUT`.
fn render_small(scene: &str, method: &str, extra: &[&str], out: &std::path::Path) -> Output {
    let mut args = vec!["render", "--scene", scene, "--method", method, "--width", "64", "--height", "36"];
    args.extend_from_slice(extra);
    args.extend(["--out", out.to_str().unwrap()]);
    dof(&args)
}

/// A folder holding `NAME.gltf`: one triangle facing the camera at z = -5 (its vertices scaled by
/// `extent`) in the buffer file `buffer`, with `material` (JSON) if given.
fn triangle_gltf(folder: &str, buffer: &str, extent: f32, material: Option<&str>) -> (PathBuf, Vec<u8>) {
    let dir = temp(folder);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let e = extent;
    let vertices: Vec<u8> = [-e, -e, -5.0, e, -e, -5.0, 0.0, e, -5.0].iter().flat_map(|v| v.to_le_bytes()).collect();
    std::fs::write(dir.join(buffer), &vertices).unwrap();
    let (materials, use_material) = match material {
        Some(m) => (format!(r#""materials":[{m}],"#), r#","material":0"#),
        None => (String::new(), ""),
    };
    let gltf = format!(
        r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":[0]}}],"nodes":[{{"mesh":0}}],{materials}
        "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}{use_material}}}]}}],
        "accessors":[{{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[-{e},-{e},-5],"max":[{e},{e},-5]}}],
        "bufferViews":[{{"buffer":0,"byteLength":36}}],"buffers":[{{"uri":"{buffer}","byteLength":36}}]}}"#
    );
    let path = dir.join("scene.gltf");
    std::fs::write(&path, gltf).unwrap();
    (path, vertices)
}

/// A negative number given as its own word (`--frames -1`, `--lum-threshold -inf`) is that
/// option's value, answered by the option's own range check, never taken for an unknown flag.
#[test]
fn negative_values_are_values_not_flags() {
    for (args, needle) in [
        (&["bench", "scaling", "--budget-s", "-1"][..], "--budget-s"),
        (&["render", "--method", "bokeh", "--lum-threshold", "-inf"][..], "--lum-threshold"),
        (&["bench", "frame", "--frames", "-1"][..], "--frames"),
        (&["render", "--width", "-5"][..], "--width"),
        (&["render", "--aperture-radius", "-1e-45"][..], "aperture"),
    ] {
        assert_fails_fast_with(args, needle, 20);
        let stderr = String::from_utf8_lossy(&dof(args).stderr).into_owned();
        assert!(!stderr.contains("unexpected argument"), "`dof {}`: {stderr}", args.join(" "));
    }
}

/// A FIFO given as an EXR input (a scene, one of the pair `compare` reads) is refused as not a
/// regular file at once, instead of waiting for a writer forever.
#[test]
fn a_fifo_as_an_exr_input_is_refused_at_once() {
    let fifo = temp("input-fifo.exr");
    let _ = std::fs::remove_file(&fifo);
    let made = Command::new("mkfifo").arg(&fifo).status().expect("mkfifo runs");
    assert!(made.success(), "mkfifo failed");
    let f = fifo.to_str().unwrap();
    let out = temp("fifo-out.exr");
    assert_fails_fast_with(&["render", "--scene", f, "--method", "gather", "--out", out.to_str().unwrap()], "not a regular file", 20);
    assert_fails_fast_with(&["compare", f, f], "not a regular file", 20);
    let _ = std::fs::remove_file(&fifo);
}

/// `dof bench frame --out` makes its folder and checks that it can write there before any frame
/// runs, as `dof render` does.
#[test]
fn bench_frame_checks_its_output_before_the_frames() {
    let base = [
        "bench",
        "frame",
        "--backend",
        "cpu",
        "--scene",
        "simple",
        "--method",
        "gather",
        "--width",
        "32",
        "--height",
        "18",
        "--frames",
        "1",
    ];
    let mut args = base.to_vec();
    args.extend(["--out", "/dev/null/sub/x.exr"]);
    assert_fails_fast_with(&args, "cannot create the output folder", 20);
    let out = temp("bench-frame-new-folder/frame.exr");
    let _ = std::fs::remove_dir_all(out.parent().unwrap());
    let mut args = base.to_vec();
    args.extend(["--out", out.to_str().unwrap()]);
    let run = dof(&args);
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    assert!(out.is_file(), "bench frame did not write {}", out.display());
}

/// A sequence's outputs never collide with its inputs: frames named like the input pattern (which
/// the next run would read as frames of the shot) are refused, and so are frames of a glTF
/// sequence that would overwrite one of the scene's own files; nothing is written either way.
#[test]
fn sequence_outputs_never_join_or_overwrite_their_inputs() {
    let dir = temp("seq-collide");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let made = dir.join("render.exr");
    let o = dof(&[
        "render",
        "--method",
        "pinhole",
        "--width",
        "24",
        "--height",
        "16",
        "--frames",
        "3",
        "--orbit",
        "2",
        "--out",
        made.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for i in 0..3 {
        std::fs::rename(dir.join(format!("render-{i:04}.exr")), dir.join(format!("shot-{}.exr", 1001 + i))).unwrap();
    }
    let pattern = dir.join("shot-####.exr");
    let out = dir.join("shot.exr");
    let args = [
        "render",
        "--scene",
        pattern.to_str().unwrap(),
        "--method",
        "gather",
        "--focus",
        "4",
        "--aperture-radius",
        "0.1",
        "--out",
        out.to_str().unwrap(),
    ];
    // Outputs are named by frame number: frame 1001's would be its input.
    let before = std::fs::read(dir.join("shot-1001.exr")).unwrap();
    assert_fails_fast_with(&args, "would overwrite the input", 20);
    assert_eq!(std::fs::read(dir.join("shot-1001.exr")).unwrap(), before, "an input was overwritten");

    // A glTF whose buffer is named like the sequence's first frame.
    let (scene, vertices) = triangle_gltf("seq-collide-gltf", "seq-0000.exr", 1.0, None);
    let out = scene.with_file_name("seq.exr");
    let args = ["render", "--scene", scene.to_str().unwrap(), "--method", "gather", "--frames", "1", "--out", out.to_str().unwrap()];
    assert_fails_fast_with(&args, "would overwrite the input", 20);
    assert_eq!(std::fs::read(scene.with_file_name("seq-0000.exr")).unwrap(), vertices, "the scene's buffer was overwritten");
}

/// Colours near f32::MAX (a background, a glTF material) are taken as the numerical contract's
/// 2^100: summing a pixel's sub-samples stays finite, the sky stays bright, and no method writes
/// +inf.
#[test]
fn colours_near_the_float_limit_stay_finite_and_keep_the_sky() {
    let values = |out: &std::path::Path| -> Vec<f32> { dof::io::read_rgb_exr(out).unwrap().0.data.iter().flatten().copied().collect() };
    for method in ["gather", "multilayer", "pinhole", "reference"] {
        let out = temp(&format!("huge-background-{method}.exr"));
        let o = render_small("fence", method, &["--background=3e38,3e38,3e38"], &out);
        assert!(o.status.success(), "{method}: {}", String::from_utf8_lossy(&o.stderr));
        assert!(String::from_utf8_lossy(&o.stderr).contains("2^100"), "{method}: no note of the clamp");
        let v = values(&out);
        assert!(v.iter().all(|v| v.is_finite() && *v >= 0.0), "{method}: a value not finite or negative");
        let bright = v.iter().filter(|v| **v > 1e29).count();
        assert!(bright > v.len() / 10, "{method}: the sky went dark ({bright} bright values of {})", v.len());
    }
    // A glTF material of base colour and emission 1e38.
    let material = r#"{"pbrMetallicRoughness":{"baseColorFactor":[1e38,0,0,1]},"emissiveFactor":[1e38,0,0]}"#;
    let (scene, _) = triangle_gltf("huge-material", "t.bin", 100.0, Some(material));
    for method in ["pinhole", "gather", "multilayer"] {
        let out = scene.with_file_name(format!("{method}.exr"));
        let o = render_small(scene.to_str().unwrap(), method, &["--eye", "0,0,0", "--target", "0,0,-1"], &out);
        assert!(o.status.success(), "{method}: {}", String::from_utf8_lossy(&o.stderr));
        let v = values(&out);
        assert!(v.iter().all(|v| v.is_finite() && *v >= 0.0), "{method}: a value not finite or negative");
        assert!(v.iter().any(|v| *v > 1e29), "{method}: the material's light is lost");
    }
}

/// A sequence too wide for its GIF preview is refused before any frame is rendered, a
/// printf-style sequence name (`shot-%04d.exr`) is answered with its `#` spelling, and a move over
/// one EXR names what can move.
#[test]
fn sequence_names_and_sizes_are_checked_before_the_work() {
    let out = temp("wide-seq/w.exr");
    let args = ["render", "--method", "pinhole", "--width", "65536", "--height", "4", "--frames", "1", "--out", out.to_str().unwrap()];
    assert_fails_fast_with(&args, "GIF preview", 10);
    assert!(!temp("wide-seq/w-0000.exr").exists());
    assert_fails_fast_with(&["render", "--scene", "in/shot-%04d.exr", "--method", "gather"], "in/shot-####.exr", 10);
    // A move over one EXR says what can move instead of suggesting what is refused next.
    let exr = temp("one-exr/layers.exr");
    let o = render_small("fence", "layers", &[], &exr);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let one = ["render", "--scene", exr.to_str().unwrap(), "--method", "gather", "--focus", "4", "--aperture-radius", "0.1"];
    assert_fails_fast_with(&[&one[..], &["--orbit", "2"]].concat(), "no geometry to turn", 10);
    assert_fails_fast_with(&[&one[..], &["--focus-to", "8"]].concat(), "EXR sequence by its pattern", 10);
}

/// An aperture far wider than any lens (30 m): the splatting methods blur with their capped CoC
/// and keep the frame's light; ray tracing through layers, which would see past the layers' end,
/// is refused before any work.
#[test]
fn huge_apertures_blur_or_are_refused() {
    let aperture = ["--aperture-radius", "30"];
    let mean = |method: &str| {
        let out = temp(&format!("huge-aperture-{method}.exr"));
        let o = render_small("simple", method, &aperture, &out);
        assert!(o.status.success(), "{method}: {}", String::from_utf8_lossy(&o.stderr));
        let image = dof::io::read_rgb_exr(&out).unwrap().0;
        image.data.iter().flatten().map(|v| *v as f64).sum::<f64>() / (3 * image.data.len()) as f64
    };
    let (multilayer, tiled) = (mean("multilayer"), mean("tiled"));
    assert!(multilayer > 0.5 * tiled && tiled > 0.05, "multilayer mean {multilayer}, tiled {tiled}: the frame went dark");
    // A sequence whose aperture grows to 1e30 m: one context, its list pool bounded (the lists
    // are thinned to fit), the last frame as bright as a still one.
    let seq = temp("huge-aperture-seq/s.exr");
    let o = render_small("simple", "multilayer", &["--frames", "2", "--aperture-radius-to", "1e30"], &seq);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let last = dof::io::read_rgb_exr(temp("huge-aperture-seq/s-0001.exr")).unwrap().0;
    let last = last.data.iter().flatten().map(|v| *v as f64).sum::<f64>() / (3 * last.data.len()) as f64;
    assert!(last > 0.5 * tiled, "the sequence's last frame went dark ({last} against {tiled})");
    let start = std::time::Instant::now();
    let o = render_small("simple", "raytrace", &aperture, &temp("huge-aperture-raytrace.exr"));
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success()
            && stderr.contains("raytrace (ray tracing through the layers) sees only")
            && stderr.contains("caps the CoC there (multilayer, tiled,"),
        "{stderr}"
    );
    assert!(start.elapsed() < std::time::Duration::from_secs(20), "the refusal took {:?}", start.elapsed());
}

/// A flag of one method given to another is refused naming the flag and the methods that take it,
/// and flags an EXR input fixes (its sub-samples, its footprints) are refused for it, instead of
/// being ignored.
#[test]
fn flags_that_do_not_apply_are_refused() {
    for (method, flag) in [
        ("gather", &["--merge", "4x4"][..]),
        ("gather", &["--tile", "24"][..]),
        ("multilayer", &["--sprites", "100"][..]),
        ("gather", &["--lum-threshold", "2"][..]),
        ("tiled", &["--no-cascade"][..]),
        ("bokeh", &["--layers-per-doubling", "3"][..]),
        ("multilayer", &["--aimed-emitters"][..]),
    ] {
        let out = temp("flags-apply.exr");
        let o = render_small("simple", method, flag, &out);
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success() && stderr.contains(flag[0]) && stderr.contains("only"), "{method} {flag:?}: {stderr}");
    }
    let exr = temp("flags-apply/layers.exr");
    let o = render_small("fence", "layers", &[], &exr);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for flag in [&["--subsamples", "1"][..], &["--no-footprints"][..]] {
        let args = [&["render", "--scene", exr.to_str().unwrap(), "--method", "gather", "--focus", "4"][..], flag].concat();
        assert_fails_fast_with(&args, "does not apply to an EXR input", 10);
    }
}

/// A multi-layer image within the size limits that the machine cannot hold (here, under a 3 GB
/// address-space limit) is a clear error, not an abort.
#[test]
fn an_image_beyond_the_machines_memory_is_an_error() {
    let out = temp("host-memory/o.exr");
    let cmd = format!(
        "ulimit -v 3000000 && exec {} render --scene simple --method gather --width 7800 --height 7800 --guard-band off --out {}",
        env!("CARGO_BIN_EXE_dof"),
        out.display()
    );
    let o = Command::new("bash").args(["-c", &cmd]).output().expect("bash runs");
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.code() == Some(1) && stderr.contains("out of host memory"), "{:?}: {stderr}", o.status);
}

/// An EXR with many passes costs the memory of the channels read, not of every channel: RGB, Z and
/// 32 more passes at 4096x4096 (2.4 GB of samples, 270 MB of them used) render under an
/// address-space limit that decoding every channel would exceed.
#[test]
fn only_the_channels_read_are_decoded() {
    let (w, h) = (4096u32, 4096u32);
    let image = dof::layers::RgbImage { width: w, height: h, data: vec![[0.25, 0.5, 0.75]; (w * h) as usize] };
    let depth = vec![4.0f32; (w * h) as usize];
    let zeros = vec![0.0f32; (w * h) as usize];
    let names: Vec<String> = (0..32).map(|k| format!("aov{k:02}.Y")).collect();
    let mut planes: Vec<(&str, &[f32])> = vec![("Z", &depth)];
    planes.extend(names.iter().map(|n| (n.as_str(), zeros.as_slice())));
    let input = temp("passes.exr");
    dof::io::write_exr_with(&input, &image, &planes, &Default::default()).unwrap();
    let run = |limit_kb: u64, method: &str| {
        let cmd = format!(
            "ulimit -v {limit_kb} && exec {} render --scene {} --method {method} --focus 4 --f-number 2 --out {}",
            env!("CARGO_BIN_EXE_dof"),
            input.display(),
            temp(&format!("passes-{method}.exr")).display()
        );
        Command::new("bash").args(["-c", &cmd]).output().expect("bash runs")
    };
    let o = run(LIMIT_KB, "pinhole");
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{:?}: {stderr}", o.status);
    assert!(stderr.contains("channels not used: aov00.Y"), "the passes not read are named: {stderr}");
    // A frame whose input, context and output would not fit is refused before it is uploaded,
    // where the allocations that follow would abort.
    let o = run(2_500_000, "gather");
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.code() == Some(1) && stderr.contains("out of host memory: a 4096x4096 frame"), "{:?}: {stderr}", o.status);
}

/// The address space `only_the_channels_read_are_decoded` renders in: the binary, its threads and
/// the image read with the channels it uses, but not every channel of the file.
const LIMIT_KB: u64 = 1_800_000;

/// A deep EXR written by OpenEXR's own library (`tools/make_deep_fixtures.py`).
fn deep_fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/deep").join(name)
}

#[test]
fn deep_exr_renders_merges_and_makes_sequences() {
    let deep = deep_fixture("scene-zips.exr");
    let flat = deep_fixture("scene-flat.exr");
    let (deep, flat) = (deep.to_str().unwrap(), flat.to_str().unwrap());
    // In focus the deep file is its flattened composite: the flat layers' front composite.
    let pinhole = |scene: &[&str], name: &str| {
        let out = temp(name);
        let mut args = vec!["render", "--method", "pinhole", "--out", out.to_str().unwrap()];
        scene.iter().for_each(|s| args.extend(["--scene", s]));
        let o = dof(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        dof::io::read_rgb_exr(&out).unwrap().0
    };
    let (a, b) = (pinhole(&[deep], "deep-pinhole.exr"), pinhole(&[flat], "flat-pinhole.exr"));
    let worst = a.data.iter().flatten().zip(b.data.iter().flatten()).map(|(x, y)| (x - y).abs()).fold(0.0f32, f32::max);
    assert!(worst <= 1e-6, "deep and flat differ by {worst}");
    // A deep file merged with itself: every sample twice, merged back by tidying (alpha 1 - (1-a)²).
    // Opaque samples stay as they were; the pane (alpha 0.4) hides 0.64 of the wall.
    let twice = pinhole(&[deep, deep], "deep-twice.exr");
    assert_eq!(twice.get(45, 2), a.get(45, 2), "the wall alone");
    let (pane, wall) = ([0.2f32, 0.6, 0.9], [0.2 + 0.6 * 5.0 / 48.0, 0.3, 0.2 + 0.6 * 10.0 / 32.0]);
    let want: Vec<f32> = (0..3).map(|c| 0.64 * pane[c] + 0.36 * wall[c]).collect();
    let got = twice.get(5, 10);
    assert!((0..3).all(|c| (got[c] - want[c]).abs() < 1e-4), "the pane over the wall: {got:?}, want {want:?}");

    // Blurred: the layers are made for the lens, with --layers fragments a pixel, and reported.
    let out = temp("deep-multilayer.exr");
    let o = dof(&[
        "render",
        "--scene",
        deep,
        "--method",
        "multilayer",
        "--focus",
        "4",
        "--aperture-radius",
        "0.05",
        "--layers",
        "2",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(stdout.contains("deep input to layers (L = 2)") && stdout.contains("left out in umbrae"), "{stdout}");
    assert_fails_with(
        &["render", "--scene", flat, "--layers", "2", "--method", "multilayer", "--focus", "4", "--f-number", "2"],
        "--layers",
    );
    assert_fails_with(&["render", "--scene", deep, "--scene", flat, "--method", "pinhole"], "is a flat EXR");
    assert_fails_with(&["render", "--scene", deep, "--scene", "simple", "--method", "pinhole"], "merge deep EXR files");

    // A sequence of deep frames, its lens moving.
    let dir = temp("deep-seq");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for i in 1..=2 {
        std::fs::copy(deep_fixture("scene-rle.exr"), dir.join(format!("shot-{i:04}.exr"))).unwrap();
    }
    let out = dir.join("blur.exr");
    let pattern = dir.join("shot-####.exr");
    let o = dof(&[
        "render",
        "--scene",
        pattern.to_str().unwrap(),
        "--method",
        "multilayer",
        "--focus",
        "4",
        "--focus-to",
        "10",
        "--aperture-radius",
        "0.05",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let frames: Vec<_> = (1..=2).map(|i| dof::io::read_rgb_exr(dir.join(format!("blur-{i:04}.exr"))).unwrap().0).collect();
    assert_ne!(frames[0], frames[1], "the focus moved (outputs named by the input frames' numbers)");
}

#[test]
fn a_frame_range_renders_its_part_of_the_shot_as_the_whole_shot_does() {
    let dir = temp("frame-range");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let render = |extra: &[&str], out: &str| {
        let out = dir.join(out);
        let mut args = vec![
            "render",
            "--scene",
            "simple",
            "--method",
            "multilayer",
            "--width",
            "48",
            "--height",
            "27",
            "--frames",
            "3",
            "--focus-to",
            "2",
            "--out",
            out.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        let o = dof(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8_lossy(&o.stdout).to_string()
    };
    render(&[], "whole.exr");
    let stdout = render(&["--frame-range", "1:2"], "part.exr");
    assert!(stdout.contains("no preview GIF for a part of the shot"), "{stdout}");
    assert!(!dir.join("part-0000.exr").exists() && !dir.join("part.gif").exists());
    for i in 1..=2 {
        let read = |name: &str| dof::io::read_rgb_exr(dir.join(format!("{name}-{i:04}.exr"))).unwrap().0;
        assert_eq!(read("part"), read("whole"), "frame {i} rendered alone is the whole shot's frame {i}");
    }
    assert_fails_with(&["render", "--scene", "simple", "--frames", "3", "--frame-range", "2:5"], "frames 0 to 2");
    assert_fails_with(&["render", "--scene", "simple", "--frame-range", "0:1"], "give --frames N");
    assert_fails_with(&["render", "--scene", "simple", "--frames", "3", "--frame-range", "2:1"], "FIRST <= LAST");

    // An EXR sequence: by the numbers in its file names, outputs named alike.
    let layers = dir.join("layers.exr");
    let o = dof(&["render", "--method", "layers", "--width", "40", "--height", "24", "--out", layers.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for n in 1001..=1003 {
        std::fs::copy(&layers, dir.join(format!("shot-{n}.exr"))).unwrap();
    }
    let pattern = dir.join("shot-####.exr");
    let run = |extra: &[&str], out: &str| {
        let out = dir.join(out);
        let mut args = vec![
            "render",
            "--scene",
            pattern.to_str().unwrap(),
            "--method",
            "multilayer",
            "--focus",
            "4",
            "--focus-to",
            "6",
            "--f-number",
            "2",
            "--out",
            out.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        let o = dof(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    };
    run(&[], "seq.exr");
    run(&["--frame-range", "1002:1003"], "seqpart.exr");
    assert!(!dir.join("seqpart-1001.exr").exists());
    for n in 1002..=1003 {
        let read = |name: &str| dof::io::read_rgb_exr(dir.join(format!("{name}-{n}.exr"))).unwrap().0;
        assert_eq!(read("seqpart"), read("seq"), "frame {n}");
    }
    assert_fails_with(
        &["render", "--scene", pattern.to_str().unwrap(), "--focus", "4", "--f-number", "2", "--frame-range", "1:5"],
        "none of them",
    );
}

#[test]
fn an_exr_keeps_its_data_and_display_windows() {
    use dof::io::codecs::exr::meta::MetaData;
    use dof::io::{ExrWindow, ExrWriteOptions, write_exr_with};
    // An RGB+Z crop at (5, -3) of a 100x50 frame.
    let (w, h) = (24u32, 16u32);
    let image = dof::layers::RgbImage { width: w, height: h, data: (0..w * h).map(|i| [i as f32 / 400.0, 0.5, 0.25]).collect() };
    let depth: Vec<f32> = (0..w * h).map(|i| if i % w < w / 2 { 2.0 } else { 6.0 }).collect();
    let window = ExrWindow { origin: (5, -3), display: [0, 0, 99, 49] };
    let input = temp("windowed.exr");
    write_exr_with(&input, &image, &[("Z", &depth)], &ExrWriteOptions { window: Some(window), ..Default::default() }).unwrap();
    for method in ["pinhole", "gather"] {
        let out = temp(&format!("windowed-{method}.exr"));
        let o = dof(&[
            "render",
            "--scene",
            input.to_str().unwrap(),
            "--method",
            method,
            "--focus",
            "4",
            "--f-number",
            "2",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let meta = MetaData::read_from_file(&out, false).unwrap();
        let header = &meta.headers[0];
        let position = header.own_attributes.layer_position;
        assert_eq!((position.x(), position.y()), (5, -3), "{method}: the data window's corner");
        let d = header.shared_attributes.display_window;
        assert_eq!((d.position.x(), d.position.y(), d.size.x(), d.size.y()), (0, 0, 100, 50), "{method}: the display window");
    }
}

/// A lit triangle without normals far from the origin shades as one near it (its face normal in
/// f64: the f32 cross product of edges of 1e10 overflows when squared); beyond ±1e12 units, where
/// the f32 rasteriser loses triangles, the scene is refused with a message to scale it down.
#[test]
fn huge_gltf_coordinates_shade_right_or_are_refused() {
    let centre = |extent: f32| {
        let (scene, _) = triangle_gltf(&format!("huge-{extent:e}"), "tri.bin", extent, None);
        let out = scene.with_file_name("pinhole.exr");
        let o = dof(&[
            "render",
            "--scene",
            scene.to_str().unwrap(),
            "--method",
            "pinhole",
            "--eye",
            "0,0,0",
            "--target",
            "0,0,-1",
            "--width",
            "48",
            "--height",
            "32",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        dof::io::read_rgb_exr(&out).unwrap().0.get(24, 16)
    };
    let near = centre(1e5);
    assert!(near[0] > 0.3, "lit, not ambient only: {near:?}");
    assert_eq!(centre(1e10), near);
    let (scene, _) = triangle_gltf("huge-refused", "tri.bin", 1e13, None);
    assert_fails_with(
        &["render", "--scene", scene.to_str().unwrap(), "--method", "pinhole", "--eye", "0,0,0", "--target", "0,0,-1"],
        "beyond ±1e12 units",
    );
}

/// `--translucent-passes` is refused where it would do nothing, and its bound before the scene is read.
#[test]
fn translucent_passes_apply_to_peeled_scenes_only() {
    assert_fails_with(&["render", "--scene", "fence", "--translucent-passes", "8"], "applies to glTF scenes");
    // A file that does not exist: the bound is refused before it is opened.
    assert_fails_with(&["render", "--scene", "/nonexistent/model.glb", "--translucent-passes", "1021"], "more than 1024 peeling passes");
    let scene = glb("simple", "translucent-passes.glb");
    let out = temp("translucent-passes-out.exr");
    let o = dof(&[
        "render",
        "--scene",
        scene.to_str().unwrap(),
        "--method",
        "pinhole",
        "--translucent-passes",
        "0",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

/// `--texture-probes` is bounded, and refused where no texture is filtered.
#[test]
fn texture_probes_are_bounded_and_apply_to_gltf_only() {
    assert_fails_with(&["render", "--scene", "fence", "--texture-probes", "8"], "applies to glTF scenes");
    for n in ["0", "65"] {
        assert_fails_with(&["render", "--scene", "/nonexistent/model.glb", "--texture-probes", n], "1 to 64 probes");
    }
}
