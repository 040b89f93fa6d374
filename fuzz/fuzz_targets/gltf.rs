//! The glTF/GLB loader, its buffers and its images.
//!
//! Each input is loaded twice:
//! - from memory (`load_gltf_slice`): a `.glb`, or `.gltf` JSON with data URIs;
//! - from a folder (`load_gltf`): the input is split at [`SEP`] into `scene.gltf`, `buffer.bin`
//!   and `image.png` (the parts present), written into a folder of this process, so that external
//!   buffers and images (relative URIs, `file:` URIs, percent escapes, short files) are read too.
//!
//! Every call must return `Ok` or `Err`; a scene that loads must pass its own validation, and its
//! default view and lens must be `Ok` or `Err` as well.
#![no_main]

use dof::scene::{MeshScene, load_gltf, load_gltf_slice};
use libfuzzer_sys::fuzz_target;
use std::path::PathBuf;
use std::sync::OnceLock;

/// Separates the parts of a folder input (`scene.gltf`, `buffer.bin`, `image.png`).
const SEP: &[u8] = b"#dof-fuzz-file#";
const FILES: [&str; 3] = ["scene.gltf", "buffer.bin", "image.png"];

fn folder() -> &'static PathBuf {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("dof-fuzz-gltf-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a temporary folder");
        dir
    })
}

fn split(data: &[u8]) -> Vec<&[u8]> {
    let mut parts = Vec::new();
    let mut rest = data;
    while parts.len() + 1 < FILES.len() {
        match rest.windows(SEP.len()).position(|w| w == SEP) {
            Some(i) => {
                parts.push(&rest[..i]);
                rest = &rest[i + SEP.len()..];
            }
            None => break,
        }
    }
    parts.push(rest);
    parts
}

fn check(scene: dof::Result<MeshScene>) {
    let Ok(scene) = scene else { return };
    scene.validate().expect("a loaded scene passes its own validation");
    assert!(!scene.triangles.is_empty(), "a loaded scene has triangles");
    if let Ok((camera, lens, _near)) = scene.default_view(16, None) {
        let _ = lens.thin_lens(&camera);
    }
    let _ = scene.bounds();
}

fuzz_target!(|data: &[u8]| {
    check(load_gltf_slice(data));

    let dir = folder();
    let parts = split(data);
    for (i, name) in FILES.iter().enumerate() {
        let path = dir.join(name);
        match parts.get(i) {
            Some(bytes) => std::fs::write(&path, bytes).expect("writing a temporary file"),
            None => {
                let _ = std::fs::remove_file(&path);
            }
        }
    }
    check(load_gltf(&dir.join(FILES[0])));
});
