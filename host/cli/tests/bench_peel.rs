//! `dof bench frame --orbit`: the layers peeled on the device every frame, in the frame's one
//! submission, give the frame `dof render` gives for the same glTF view (the host peel and the
//! one-shot method), and the counters say nothing is allocated, uploaded or read back.

use std::path::PathBuf;
use std::process::{Command, Output};

fn dof(args: &[&str]) -> Output {
    let out = Command::new(env!("CARGO_BIN_EXE_dof")).args(args).output().expect("the dof binary runs");
    assert!(out.status.success(), "`dof {}` failed:\n{}", args.join(" "), String::from_utf8_lossy(&out.stderr));
    out
}

fn temp(name: &str) -> PathBuf {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("dof-bench-peel-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir.join(name)
}

/// The built-in fence (out-of-focus bars, open sky above and below) exported as a glTF file.
fn fence_glb() -> PathBuf {
    let dir = temp("export");
    dof(&["scenes", "--only", "fence", "--width", "96", "--height", "54", "--export", dir.to_str().unwrap()]);
    dir.join("fence.glb")
}

#[test]
fn a_still_orbit_writes_the_frame_dof_render_writes() {
    let glb = fence_glb();
    let (a, b) = (temp("bench.exr"), temp("render.exr"));
    let size = ["--width", "96", "--height", "54", "--method", "multilayer", "--backend", "cpu"];
    let mut bench = vec!["bench", "frame", "--scene", glb.to_str().unwrap(), "--orbit", "0", "--frames", "2", "--merge", "none"];
    bench.extend(size);
    bench.extend(["--out", a.to_str().unwrap()]);
    dof(&bench);
    let mut render = vec!["render", "--scene", glb.to_str().unwrap(), "--merge", "none"];
    render.extend(size);
    render.extend(["--out", b.to_str().unwrap()]);
    dof(&render);
    let (a, b) = (dof::io::read_rgb_exr(&a).unwrap().0, dof::io::read_rgb_exr(&b).unwrap().0);
    assert_eq!((a.width, a.height), (96, 54), "cut to the frame");
    let worst = a.data.iter().zip(&b.data).flat_map(|(p, q)| (0..3).map(move |k| (p[k] - q[k]).abs())).fold(0.0f32, f32::max);
    assert!(worst <= 1e-5, "largest difference {worst}");
    assert!(a.data.iter().any(|p| p[0] > 0.0), "not a black frame");
}

#[test]
fn an_orbiting_frame_reports_one_submission_and_no_transfers() {
    let out = dof(&[
        "bench",
        "frame",
        "--scene",
        "fence",
        "--orbit",
        "1",
        "--frames",
        "3",
        "--width",
        "64",
        "--height",
        "36",
        "--backend",
        "cpu",
        "--json",
    ]);
    let json = String::from_utf8_lossy(&out.stdout).into_owned();
    for field in [
        "\"allocations_per_frame\":0.0",
        "\"uploads_per_frame\":0.0",
        "\"readbacks_per_frame\":0.0",
        "\"submits_per_frame\":1.0",
        "\"peel_passes_per_frame\":8.0", // 4 layers and 4 translucent passes, recorded
        "\"path\":\"frame-api+device-peel\"",
    ] {
        assert!(json.contains(field), "{field} in {json}");
    }
    assert!(json.contains("\"peel_ms\":") && json.contains("\"dof_ms\":"), "{json}");
    // The peel's span is reported beside the frame time, each one a frame.
    let j: serde_json::Value = serde_json::from_str(&json).expect("one JSON object");
    assert!(j["frame_ms"].as_f64().unwrap() > 0.0 && j["peel_span_ms"].as_f64().unwrap() > 0.0, "{j}");
    assert_eq!(j["frame_ms_frames"].as_u64(), Some(3), "{j}");
}
