//! The EXR readers, every layout (RGB, RGB+Z, Blender, Nuke single- and multi-part, multi-layer,
//! deep scan lines and tiles): the input is written to a file of this process and read with
//! `read_layered_exr`, `read_rgb_exr` and `read_deep_exr`.
//!
//! Every call must return `Ok` or `Err`. What is read must follow the documented NaN/Inf policy:
//! counts within the layer count, fragments sorted front to back with positive depth (`+inf` only
//! for the last, the background), alpha in [0, 1], finite colour; a deep image tidy (samples front
//! to back, `ZBack` not in front of `Z`), its layers for a lens within the layer budget.
#![no_main]

use dof::io::{read_deep_exr, read_layered_exr, read_rgb_exr};
use libfuzzer_sys::fuzz_target;
use std::path::PathBuf;
use std::sync::OnceLock;

fn file() -> &'static PathBuf {
    static FILE: OnceLock<PathBuf> = OnceLock::new();
    FILE.get_or_init(|| std::env::temp_dir().join(format!("dof-fuzz-exr-{}.exr", std::process::id())))
}

/// The exr crate decodes inside the reader's `catch_unwind`, which turns a panic on corrupt data
/// into an error; libFuzzer's panic hook would abort the process first. This hook only records
/// the message: a panic that the reader catches is fine, one that escapes it is reported with its
/// message and aborts (see `fuzz_target!` below).
fn install_quiet_hook() {
    static HOOK: OnceLock<()> = OnceLock::new();
    HOOK.get_or_init(|| {
        std::panic::set_hook(Box::new(|info| {
            *LAST_PANIC.lock().unwrap_or_else(|e| e.into_inner()) = Some(info.to_string());
        }))
    });
}

static LAST_PANIC: std::sync::Mutex<Option<String>> = std::sync::Mutex::new(None);

fuzz_target!(|data: &[u8]| {
    install_quiet_hook();
    if std::panic::catch_unwind(|| run(data)).is_err() {
        let message = LAST_PANIC.lock().unwrap_or_else(|e| e.into_inner()).take();
        eprintln!("a panic escaped the EXR reader: {}", message.unwrap_or_default());
        std::process::abort();
    }
});

fn run(data: &[u8]) {
    let path = file();
    std::fs::write(path, data).expect("writing a temporary file");

    if let Ok((image, report)) = read_layered_exr(path) {
        assert_eq!((image.width, image.height), (report.width, report.height));
        assert_eq!(image.counts.len() as u64, image.width as u64 * image.height as u64);
        assert_eq!(image.fragments.len() as u64, image.counts.len() as u64 * image.max_layers as u64);
        assert_eq!(image.max_layers as usize, report.layers.len());
        let l = image.max_layers as usize;
        for (p, &n) in image.counts.iter().enumerate() {
            assert!(n as usize <= l, "pixel {p}: {n} fragments in {l} layers");
            let pixel = &image.fragments[p * l..p * l + n as usize];
            for (k, f) in pixel.iter().enumerate() {
                assert!(f.depth > 0.0, "pixel {p}: depth {}", f.depth);
                assert!(f.depth.is_finite() || k + 1 == pixel.len(), "pixel {p}: a background that is not last");
                assert!((0.0..=1.0).contains(&f.alpha), "pixel {p}: alpha {}", f.alpha);
                assert!(f.color.iter().all(|c| c.is_finite()), "pixel {p}: colour {:?}", f.color);
            }
            assert!(pixel.windows(2).all(|w| w[0].depth <= w[1].depth), "pixel {p}: not sorted");
        }
        let _ = report.to_string();
    }

    if let Ok((image, report)) = read_rgb_exr(path) {
        assert_eq!((image.width, image.height), (report.width, report.height));
        assert_eq!(image.data.len() as u64, image.width as u64 * image.height as u64);
        assert!(image.data.iter().flatten().all(|c| c.is_finite()), "non-finite colour after the policy");
        let _ = report.to_string();
    }

    if let Ok((image, report)) = read_deep_exr(&[path]) {
        assert_eq!((image.width, image.height), (report.width, report.height));
        assert_eq!(image.offsets.len(), image.pixels() + 1);
        assert_eq!(*image.offsets.last().unwrap(), image.samples.len() as u64);
        for p in 0..image.pixels() {
            let pixel = image.pixel(p);
            for s in pixel {
                assert!(s.z > 0.0 && s.z_back >= s.z, "pixel {p}: depths {} to {}", s.z, s.z_back);
                assert!((0.0..=1.0).contains(&s.alpha), "pixel {p}: alpha {}", s.alpha);
                assert!(s.color.iter().all(|c| c.is_finite()), "pixel {p}: colour {:?}", s.color);
            }
            assert!(pixel.windows(2).all(|w| w[0].z <= w[1].z), "pixel {p}: not sorted");
        }
        let _ = report.to_string();
        let camera =
            dof::scene::Camera::look_at(dof::scene::Vec3::ZERO, dof::scene::Vec3::new(0.0, 0.0, -1.0), 0.7, image.width, image.height);
        let lens = dof::scene::ThinLens { focal_length: 0.05, aperture_radius: 0.02, focus_distance: 4.0, pixels_per_unit: 1e3 };
        let options = dof::frame::LayerOptions { max_layers: 3, ..Default::default() };
        if let Ok((layers, _)) = camera.frame().and_then(|frame| Ok(image.layers(&frame, &lens, &options)?)) {
            assert!(layers.counts.iter().all(|&n| n <= 3));
        }
    }
}
