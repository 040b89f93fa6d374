//! Aperture masks from PNG files (`dof::aperture::image_aperture`): the input is written to a
//! file of this process and read as a mask. A mask that is accepted must be usable: a square of
//! at most 128 texels a side, coverage in [0, 1] with a peak of 1, zero outside the inscribed
//! circle, positive finite area.
//!
//! The input is also given to `parse_aperture` as text when it is UTF-8 (not ending in `.png`,
//! which would name a file), for the `circle`, `blades:` and `star:` syntax.
#![no_main]

use dof::aperture::{ApertureShape, image_aperture, parse_aperture};
use libfuzzer_sys::fuzz_target;
use std::path::PathBuf;
use std::sync::OnceLock;

fn file() -> &'static PathBuf {
    static FILE: OnceLock<PathBuf> = OnceLock::new();
    FILE.get_or_init(|| std::env::temp_dir().join(format!("dof-fuzz-aperture-{}.png", std::process::id())))
}

fn check(shape: &ApertureShape) {
    let k = &shape.kernel;
    assert!(k.area.is_finite() && k.area > 0.0, "area {}", k.area);
    if k.mask == 0 {
        assert!(shape.mask.is_empty());
        return;
    }
    let side = k.mask as usize;
    assert!((2..=128).contains(&side), "mask side {side}");
    assert_eq!(shape.mask.len(), side * side);
    assert!(shape.mask.iter().all(|v| (0.0..=1.0).contains(v)), "coverage outside [0, 1]");
    assert_eq!(shape.mask_words().len(), side * side);
}

fuzz_target!(|data: &[u8]| {
    let path = file();
    std::fs::write(path, data).expect("writing a temporary file");
    if let Ok(shape) = image_aperture(path) {
        check(&shape);
        let peak = shape.mask.iter().fold(0.0f32, |m, &v| m.max(v));
        assert_eq!(peak, 1.0, "the brightest texel is scaled to 1");
        let side = shape.kernel.mask as f32;
        for (t, &v) in shape.mask.iter().enumerate() {
            let (x, y) = ((t as f32 % side) + 0.5, (t as f32 / side).floor() + 0.5);
            let (u, w) = (2.0 * x / side - 1.0, 2.0 * y / side - 1.0);
            assert!(v == 0.0 || u * u + w * w <= 1.0 + 1e-5, "texel {t} lit outside the inscribed circle");
        }
    }
    if let Ok(text) = std::str::from_utf8(data) {
        if !text.to_ascii_lowercase().ends_with(".png") {
            if let Ok(shape) = parse_aperture(text) {
                check(&shape);
            }
        }
    }
});
