//! The hash of the kernel crate's sources. The build script includes this file to stamp the SPIR-V
//! it builds (and to refuse prebuilt SPIR-V older than the kernels on disk); the test suite
//! includes it too, to recompute the hash from the files on disk and prove the embedded modules
//! were built from them. Not part of the library: a renderer has no use for it.

use sha2::{Digest, Sha256};
use std::path::{Path, PathBuf};

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// SHA-256 over `Cargo.toml` and `src/**/*.rs` of the crate at `crate_dir`, each as its relative
/// path followed by its bytes, in path order; lowercase hex.
pub fn shader_source_hash(crate_dir: &Path) -> String {
    let mut files = vec![crate_dir.join("Cargo.toml")];
    rust_files(&crate_dir.join("src"), &mut files);
    files.sort();
    let mut hasher = Sha256::new();
    for file in &files {
        let rel = file.strip_prefix(crate_dir).unwrap_or(file);
        hasher.update(rel.to_string_lossy().replace('\\', "/").as_bytes());
        hasher.update(std::fs::read(file).unwrap_or_default());
    }
    hasher.finalize().iter().map(|b| format!("{b:02x}")).collect()
}
