//! `dof bench frame --input images` and `--input copied-images`: the frame fed a colour and a
//! depth image every frame, as a renderer's are, read in place or copied in first, gives the frame
//! of the same view fed slot buffers (within what RGBA16F colour keeps), the two inputs give the
//! same frame bit for bit, their input stages are timed, and no frame allocates, uploads or reads
//! back anything, on the CPU backend and on Vulkan.

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
fn image_input_gives_the_layers_frame_and_times_its_stages() {
    let (_, layers) = bench("cpu", "layers");
    for backend in ["cpu", "vulkan"] {
        let mut frames = Vec::new();
        for (input, stages) in
            [("images", &["frame/input"][..]), ("copied-images", &["frame/input-color", "frame/input-depth", "frame/input"][..])]
        {
            let (json, images) = bench(backend, input);
            assert_eq!(json["input"], input);
            assert_eq!(json["layers"], 1);
            for stage in stages {
                let ms = json["stage_ms"][stage].as_f64();
                assert!(ms.is_some_and(|ms| ms >= 0.0), "{backend} {input}: {stage} not timed: {}", json["stage_ms"]);
            }
            let copied = json["stage_ms"]["frame/input-color"].is_f64();
            assert_eq!(copied, input == "copied-images", "{backend} {input}: {}", json["stage_ms"]);
            for counter in ["allocations_per_frame", "uploads_per_frame", "readbacks_per_frame"] {
                assert_eq!(json[counter], 0.0, "{backend} {input}: {counter}");
            }
            assert_eq!(json["submits_per_frame"], 1.0, "{backend} {input}");
            // RGBA16F keeps 11 significant bits: the blurred frames agree to a few of its steps.
            let worst = worst_relative(&layers, &images);
            assert!(worst < 4e-3, "{backend} {input}: the frame from images is {worst} (relative) from the frame from layers");
            frames.push(images);
        }
        assert!(frames[0].data == frames[1].data, "{backend}: reading the images in place and copying them give different frames");
    }
}
