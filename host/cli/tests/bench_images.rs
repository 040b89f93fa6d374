//! `dof bench frame --input images`: the frame fed a colour and a depth image, copied in and
//! converted every frame as a renderer's are, gives the frame of the same view fed slot buffers
//! (within what RGBA16F colour keeps), times those input stages, and allocates, uploads and reads
//! back nothing a frame, on the CPU backend and on Vulkan.

use std::path::PathBuf;
use std::process::{Command, Output};

fn dof(args: &[&str]) -> Output {
    let out = Command::new(env!("CARGO_BIN_EXE_dof")).args(args).output().expect("the dof binary runs");
    assert!(out.status.success(), "`dof {}` failed:\n{}", args.join(" "), String::from_utf8_lossy(&out.stderr));
    out
}

fn temp(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("dof-bench-images-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir.join(name)
}

/// One `bench frame` run of single-layer tiled splatting on `fence` (point-sampled, so the front
/// layer is what a renderer's colour image shows): its JSON and its frame.
fn bench(backend: &str, input: &str) -> (serde_json::Value, dof::layers::RgbImage) {
    let out = temp(&format!("{backend}-{input}.exr"));
    let args = [
        "bench",
        "frame",
        "--scene",
        "fence",
        "--method",
        "tiled",
        "--subsamples",
        "1",
        "--width",
        "96",
        "--height",
        "54",
        "--frames",
        "2",
        "--warmup",
        "1",
        "--warmup-ms",
        "0",
        "--json",
        "--backend",
        backend,
        "--input",
        input,
        "--out",
        out.to_str().unwrap(),
    ];
    let json = serde_json::from_slice(&dof(&args).stdout).expect("one JSON object");
    (json, dof::io::read_rgb_exr(&out).unwrap().0)
}

/// The largest difference between two frames relative to the brightest value of the first.
fn worst_relative(a: &dof::layers::RgbImage, b: &dof::layers::RgbImage) -> f32 {
    assert_eq!((a.width, a.height), (b.width, b.height));
    let peak = a.data.iter().flat_map(|p| p.iter().copied()).fold(0.0f32, f32::max);
    assert!(peak > 0.0, "a black frame");
    a.data.iter().zip(&b.data).flat_map(|(p, q)| (0..3).map(move |k| (p[k] - q[k]).abs())).fold(0.0f32, f32::max) / peak
}

#[test]
fn image_input_gives_the_layers_frame_and_times_its_copies() {
    let (_, layers) = bench("cpu", "layers");
    for backend in ["cpu", "vulkan"] {
        let (json, images) = bench(backend, "images");
        assert_eq!(json["input"], "images");
        assert_eq!(json["layers"], 1);
        for stage in ["frame/input-color", "frame/input-depth", "frame/input"] {
            let ms = json["stage_ms"][stage].as_f64();
            assert!(ms.is_some_and(|ms| ms >= 0.0), "{backend}: {stage} not timed: {}", json["stage_ms"]);
        }
        for counter in ["allocations_per_frame", "uploads_per_frame", "readbacks_per_frame"] {
            assert_eq!(json[counter], 0.0, "{backend}: {counter}");
        }
        assert_eq!(json["submits_per_frame"], 1.0, "{backend}");
        // RGBA16F keeps 11 significant bits: the blurred frames agree to a few of its steps.
        let worst = worst_relative(&layers, &images);
        assert!(worst < 4e-3, "{backend}: the frame from images is {worst} (relative) from the frame from layers");
    }
}
