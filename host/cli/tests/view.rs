//! `dof view` driven the way CI drives it: under Xvfb (launched here through `xvfb-run` when no
//! display is set) on whatever Vulkan device there is (lavapipe in CI). A missing display, X server
//! or Vulkan device makes these tests fail, never skip.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn dof() -> Command {
    Command::new(env!("CARGO_BIN_EXE_dof"))
}

/// `dof view ARGS`, on the display when one is set, else in a fresh Xvfb through `xvfb-run`.
fn view(args: &[&str]) -> Output {
    let bin = env!("CARGO_BIN_EXE_dof");
    let display = std::env::var("DISPLAY").is_ok_and(|d| !d.is_empty());
    let mut cmd = if display {
        Command::new(bin)
    } else {
        let mut c = Command::new("xvfb-run");
        c.args(["-a", "-s", "-screen 0 1024x768x24", bin]);
        c
    };
    cmd.arg("view").args(args);
    let out = cmd.output().unwrap_or_else(|e| {
        panic!("cannot run {} (without DISPLAY the test needs xvfb-run: apt-get install xvfb): {e}", if display { bin } else { "xvfb-run" })
    });
    println!("--- dof view {}\n{}{}", args.join(" "), String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    out
}

fn run(cmd: &mut Command) -> String {
    let out = cmd.output().expect("run dof");
    let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "{cmd:?} failed:\n{text}");
    text
}

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("view").join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The 8-bit RGB pixels of a PNG.
fn read_png(path: &Path) -> (u32, u32, Vec<u8>) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!((info.color_type, info.bit_depth), (png::ColorType::Rgb, png::BitDepth::Eight));
    buf.truncate(info.buffer_size());
    (info.width, info.height, buf)
}

/// The viewer's screenshot against the PNG preview `dof render` writes for the same scene file,
/// view, lens, method and exposure. Both are the documented tone map (exposure, ACES fit, sRGB
/// OETF; the viewer runs it on the device from the same source), so they must agree to PSNR >= 35
/// dB on 8-bit code values. What remains is float rounding (the frame API's result differs from the
/// one-shot path's by that much; ash_host checks 1e-3 of the peak), the device's `pow` and its
/// float-to-8-bit conversion in the blit; anything the viewer got wrong (no tone map, the OETF
/// twice, a shifted crop, the guard band, a wrong lens, a missing blur, the UI) is far below.
#[test]
fn the_viewer_screenshot_matches_dof_render() {
    let dir = scratch("screenshot");
    let glb = dir.join("simple.glb");
    run(dof().args(["scenes", "--only", "simple", "--width", "256", "--height", "144", "--export"]).arg(&dir));
    assert!(glb.exists());
    let g = glb.to_str().unwrap();
    let mut failures = Vec::new();
    // Each method through its own context; multi-layer without merging, the others as the viewer
    // starts them (single-layer splatting merges 4x4).
    for (method, merge) in [("multilayer", "none"), ("tiled", "4x4"), ("gather", "4x4"), ("ring-gather", "4x4"), ("bokeh", "4x4")] {
        let exr = dir.join(format!("render-{method}.exr"));
        // `dof render` takes `--merge` for the methods that merge only.
        let merges = dof::frame::registry::method(method).is_ok_and(|m| m.takes(dof::frame::MethodOption::Merge));
        let render_merge = if merges { &["--merge", merge][..] } else { &[][..] };
        run(dof()
            .args(["render", "--scene", g, "--method", method])
            .args(render_merge)
            .args(["--backend", "vulkan", "--width", "256", "--height", "144", "--out"])
            .arg(&exr));
        let shot = dir.join(format!("view-{method}.png"));
        let s = shot.to_str().unwrap();
        let out = view(&[
            "--scene",
            g,
            "--method",
            method,
            "--merge",
            merge,
            "--width",
            "256",
            "--height",
            "144",
            "--frames",
            "2",
            "--screenshot",
            s,
            "--hide-ui",
        ]);
        assert!(out.status.success(), "dof view --method {method} failed");
        compare(method, &shot, &exr.with_extension("png"), &mut failures);
        if method == "multilayer" {
            // The switch to raw linear: the render's linear result clamped to [0, 1], sRGB-encoded.
            let raw = dir.join("view-multilayer-raw.png");
            let mut args = vec!["--scene", g, "--method", method, "--merge", merge, "--width", "256", "--height", "144"];
            args.extend(["--frames", "2", "--script", "raw-linear", "--hide-ui", "--screenshot", raw.to_str().unwrap()]);
            assert!(view(&args).status.success(), "dof view --script raw-linear failed");
            let (image, _) = dof::io::read_rgb_exr(&exr).unwrap();
            let linear = dir.join("render-multilayer-raw.png");
            let encoded: Vec<[f32; 3]> = image.data.iter().map(|c| c.map(dof::io::tonemap::srgb_oetf)).collect();
            dof::io::write_png_display(&linear, image.width, image.height, &encoded).unwrap();
            compare("multilayer, raw linear", &raw, &linear, &mut failures);
        }
    }
    // An EXR (the multi-layer image `dof render --method layers` writes): a still image with its
    // edges extended, shown at its own size; at an exposure other than 1 on both sides.
    let layers = dir.join("layers.exr");
    run(dof().args(["render", "--scene", "simple", "--method", "layers", "--width", "160", "--height", "90", "--out"]).arg(&layers));
    let l = layers.to_str().unwrap();
    let exr = dir.join("render-exr.exr");
    run(dof()
        .args([
            "render",
            "--scene",
            l,
            "--method",
            "multilayer",
            "--focus",
            "3",
            "--f-number",
            "2",
            "--exposure",
            "2.5",
            "--backend",
            "vulkan",
            "--out",
        ])
        .arg(&exr));
    let shot = dir.join("view-exr.png");
    let out = view(&[
        "--scene",
        l,
        "--method",
        "multilayer",
        "--merge",
        "none",
        "--focus",
        "3",
        "--f-number",
        "2",
        "--exposure",
        "2.5",
        "--frames",
        "2",
        "--screenshot",
        shot.to_str().unwrap(),
        "--hide-ui",
    ]);
    assert!(out.status.success(), "dof view of an EXR failed");
    compare("exr multilayer, exposure 2.5", &shot, &exr.with_extension("png"), &mut failures);
    assert!(failures.is_empty(), "screenshots differ from dof render's PNG: {failures:?}");
}

/// PSNR in dB of two 8-bit images (the same number of code values): 10 log10(255² / MSE).
fn psnr8(a: &[u8], b: &[u8]) -> f64 {
    assert_eq!(a.len(), b.len());
    let se: f64 = a.iter().zip(b).map(|(x, y)| (*x as f64 - *y as f64).powi(2)).sum();
    let mse = se / a.len() as f64;
    if mse == 0.0 { f64::INFINITY } else { 10.0 * (255.0f64 * 255.0 / mse).log10() }
}

/// The screenshot against the render's PNG preview: PSNR >= 35 dB.
fn compare(what: &str, shot: &Path, png: &Path, failures: &mut Vec<String>) {
    let (w, h, pixels) = read_png(shot);
    let (ww, wh, want) = read_png(png);
    assert_eq!((w, h), (ww, wh), "{what}: size");
    let psnr = psnr8(&pixels, &want);
    let worst = pixels.iter().zip(&want).map(|(a, b)| a.abs_diff(*b)).max().unwrap_or(0);
    println!("{what}: screenshot vs dof render's PNG: PSNR {psnr:.2} dB, largest difference {worst}/255");
    if !(psnr >= 35.0) {
        failures.push(format!("{what}: PSNR {psnr:.2} dB (largest difference {worst}/255)"));
    }
    // Not a blank frame: the render has structure, and so must the screenshot.
    let distinct: std::collections::HashSet<&[u8; 3]> = pixels.as_chunks::<3>().0.iter().collect();
    assert!(distinct.len() > 100, "{what}: the screenshot has only {} colours", distinct.len());
}

/// A resize and every method (and merge level, tile size, a bladed aperture, a click to focus, an
/// orbit and the error against the reference) switched on the way, with the validation layer and
/// synchronization validation on: it must say nothing.
#[test]
fn scripted_resize_and_method_switches_leave_validation_silent() {
    let script = "method=tiled,click=128:72,method=gather,resize=320x176,method=ring-gather,rings=2,method=bokeh,blades=6,method=multilayer,merge=2x2,tile=32,orbit=15,exposure=0.5,raw-linear,error";
    let out = view(&["--scene", "simple", "--width", "256", "--height", "144", "--validation", "--frames", "18", "--script", script]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "dof view failed");
    assert!(text.contains("validation: 0 message(s)"), "validation did not report silence");
    assert!(text.contains("swapchain: 320x176"), "the window was not resized");
    for m in ["tiled", "gather", "ring-gather", "bokeh", "multilayer"] {
        assert!(text.contains(&format!("Method({m})")), "method {m} was not switched to");
    }
    assert!(text.contains("focus: "), "the click did not focus");
    assert!(text.contains("error vs reference: PSNR"), "the error against the reference was not computed");
    assert!(text.contains("Exposure(0.5)") && text.contains("RawLinear"), "the exposure and the raw linear switch were not applied");
    assert!(text.contains("exited cleanly after 18 frames"));
}

/// Closing the window (the scripted close goes through the same path as the window manager's close
/// request) ends the loop early, tears everything down, and the validation layer, which reports
/// every object left alive at vkDestroyDevice and vkDestroyInstance, says nothing.
#[test]
fn closing_the_viewer_exits_cleanly_without_leaks() {
    let out = view(&[
        "--scene",
        "simple",
        "--width",
        "256",
        "--height",
        "144",
        "--validation",
        "--frames",
        "100",
        "--script",
        "method=gather,close",
    ]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "dof view failed");
    assert!(text.contains("validation: 0 message(s)"));
    assert!(text.contains("exited cleanly after 1 frames"), "the close did not end the loop");
}

/// Real input through the X server (XTEST, with `xdotool`): a click focuses on the depth under the
/// cursor and a drag orbits the camera.
#[test]
fn a_click_focuses_and_a_drag_orbits() {
    let bin = env!("CARGO_BIN_EXE_dof");
    let log = scratch("input").join("log.txt");
    // The viewer in the background; once its first frame is up, a click at the window's centre
    // (the scene's near box), then a drag to the right.
    let script = format!(
        r#"set -e
"{bin}" view --scene simple --width 256 --height 144 --hide-ui --frames 14 > "{log}" 2>&1 &
pid=$!
for i in $(seq 600); do grep -q "first frame presented" "{log}" && break; kill -0 $pid || break; sleep 0.1; done
wid=$(xdotool search --name "dof view" | head -n 1)
xdotool mousemove --window "$wid" 100 72 click 1
sleep 1
xdotool mousemove --window "$wid" 60 72 mousedown 1 mousemove --window "$wid" 90 72 mousemove --window "$wid" 140 76 mouseup 1
wait $pid"#,
        log = log.display()
    );
    let display = std::env::var("DISPLAY").is_ok_and(|d| !d.is_empty());
    let status = if display {
        Command::new("sh").args(["-c", &script]).status()
    } else {
        Command::new("xvfb-run").args(["-a", "-s", "-screen 0 1024x768x24", "sh", "-c", &script]).status()
    }
    .expect("run xvfb-run and sh (apt-get install xvfb xdotool)");
    let text = std::fs::read_to_string(&log).unwrap_or_default();
    println!("{text}");
    assert!(status.success(), "the viewer or xdotool failed (is xdotool installed?)");
    assert!(text.contains("focus: "), "the click did not focus");
    let view = |prefix: &str| text.lines().find_map(|l| l.strip_prefix(prefix)).map(|l| l.split(" --focus").next().unwrap().to_string());
    let (start, end) = (view("view at the start: ").unwrap(), view("view at the end: ").unwrap());
    assert_ne!(start, end, "the drag did not move the camera");
}

/// Bad input is a clear error (before any window opens where it can be), never a panic; a
/// screenshot that was asked for is written or the run fails saying why.
#[test]
fn the_viewer_refuses_bad_input_clearly() {
    // An EXR far wider than any window (the case of a panic on the window size).
    let dir = scratch("bad-input");
    let wide_exr = dir.join("wide.exr");
    let wide = dof::layers::RgbImage { width: 100_000, height: 1, data: vec![[0.5; 3]; 100_000] };
    dof::io::write_exr(&wide_exr, &wide, &[("Z", &vec![2.0; 100_000])]).unwrap();
    let deep = format!("{}/../../tests/data/deep/scene-zips.exr", env!("CARGO_MANIFEST_DIR"));
    for (args, expect) in [
        (vec!["--width", "0"], "--width must lie between"),
        (vec!["--focus", "NaN"], "--focus must be a positive finite distance"),
        (vec!["--f-number", "-2"], "--f-number must be a positive finite number"),
        (vec!["--scene", "no/such/file.glb"], "no/such/file.glb"),
        (vec!["--scene", "nosuchscene"], "nosuchscene"),
        (vec!["--screenshot", "x.png"], "--screenshot needs --frames"),
        (vec!["--script", "method=nosuch"], "the methods are multilayer, tiled, gather, ring-gather, bokeh"),
        (vec!["--blades", "2"], "--blades must be 0"),
        (vec!["--texture-probes", "0"], "1 to 64 probes"),
        (vec!["--width", "100000"], "--width must lie between"),
        (vec!["--scene", "x.exr", "--f-number", "NaN"], "--f-number must be a positive finite number"),
        (vec!["--screenshot", "x.jpg", "--frames", "1"], "--screenshot must name a .png file"),
        (vec!["--exposure", "0"], "--exposure must be a positive number"),
        (vec!["--exposure", "inf"], "--exposure must be a positive number"),
        (vec!["--script", "exposure=-1"], "the exposure must be positive"),
        (vec!["--scene", wide_exr.to_str().unwrap(), "--focus", "3", "--f-number", "2"], "declares 100000x1 pixels"),
        (vec!["--frames", "2", "--script", "method=tiled,method=gather,method=bokeh"], "--script has 3 steps"),
        (vec!["--scene", deep.as_str(), "--focus", "3", "--f-number", "2", "--width", "320"], "opens at its own size (48x32)"),
        (vec!["--scene", "in/shot-####.exr", "--focus", "3", "--f-number", "2"], "one EXR image, not a sequence"),
        (vec!["--scene", "in/shot-%04d.exr", "--focus", "3", "--f-number", "2"], "(a sequence, in/shot-####.exr, is for `dof render`)"),
    ] {
        let out = dof().arg("view").args(&args).env_remove("DISPLAY").output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?} was accepted");
        assert!(err.contains(expect), "{args:?}: expected `{expect}` in: {err}");
        assert!(!err.contains("panicked"), "{args:?} panicked: {err}");
    }
    // A size beyond the device is refused up front, naming the flags (the size check alone
    // passed 8192x8192, which then failed as too large for the device); a screenshot asked for is
    // written when the window closes before the last frame, and a run that presents nothing fails
    // saying no screenshot was written.
    let out = view(&["--width", "8192", "--height", "8192", "--frames", "1"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "8192x8192 was accepted");
    assert!(err.contains("--width 8192 --height 8192:"), "the error does not name the flags: {err}");
    assert!(!err.contains("panicked"), "8192x8192 panicked: {err}");

    let shot = dir.join("closed.png");
    let _ = std::fs::remove_file(&shot);
    let out = view(&[
        "--width",
        "64",
        "--height",
        "48",
        "--screenshot",
        shot.to_str().unwrap(),
        "--frames",
        "5",
        "--script",
        "method=tiled,close",
    ]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "the early close failed");
    assert!(shot.exists(), "no screenshot was written on the early close");
    assert!(text.contains("the window closed after 1 of 5 frames"), "the screenshot does not say it is of the last presented frame");
    let (w, h, _) = read_png(&shot);
    assert_eq!((w, h), (64, 48));

    let never = dir.join("never.png");
    let _ = std::fs::remove_file(&never);
    let out = view(&["--width", "64", "--height", "48", "--screenshot", never.to_str().unwrap(), "--frames", "5", "--script", "close"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "a run that presented nothing succeeded with --screenshot");
    assert!(err.contains("no screenshot was written"), "the failure does not say why: {err}");
    assert!(!never.exists());
}

/// With the camera orbiting every frame, a mesh scene's layers are peeled on the device in the
/// frame's command buffer: the library allocates, uploads, reads back and submits nothing of its
/// own in a frame that remade nothing, and validation stays silent.
#[test]
fn an_orbiting_mesh_scene_peels_on_the_device_with_no_transfers() {
    let script = ["orbit=4"; 8].join(",");
    let out = view(&[
        "--scene",
        "fence",
        "--width",
        "192",
        "--height",
        "108",
        "--validation",
        "--hide-ui",
        "--frames",
        "10",
        "--script",
        &script,
    ]);
    let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "{text}");
    assert!(text.contains("validation: 0 message(s)"), "{text}");
    let line = text.lines().find(|l| l.starts_with("library work per frame over")).expect("the steady frames' counters");
    let frames: u32 = line.split_whitespace().nth(5).and_then(|n| n.parse().ok()).expect("a frame count");
    assert!(frames >= 8, "{line}");
    assert!(line.contains(": 0 allocations, 0 uploads, 0 readbacks, 0 submissions of its own"), "{line}");
}
