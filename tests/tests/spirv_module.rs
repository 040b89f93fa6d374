//! The embedded SPIR-V modules: built from the current kernel sources, one per entry point the host
//! refers to, and the same as the prebuilt artifact `host/spirv/` that crates depending on `dof`
//! without the `rebuild-spirv` feature embed. Runs without a Vulkan driver.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The hash the core's build script stamps the SPIR-V with (not part of the core's library).
#[path = "../../host/core/build/source_hash.rs"]
mod source_hash;

/// Without `rebuild-spirv` the hash comes from `host/spirv/manifest.txt`: this fails when a kernel
/// source changed and the artifact was not regenerated. With it (the workspace) the hash is taken
/// when the build script compiles the kernels.
#[test]
fn embedded_module_was_built_from_the_current_sources() {
    let shaders = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shaders");
    assert_eq!(
        source_hash::shader_source_hash(&shaders),
        dof::shaders::SOURCE_HASH,
        "the embedded SPIR-V was built from other kernel sources than those on disk"
    );
}

/// `host/spirv/` holds exactly the embedded modules (byte for byte, no other `.spv`) and the
/// embedded source hash: the build script rewrites it whenever the kernels compile to something
/// else, so in the workspace this fails only if that did not happen; CI's `git diff --exit-code --
/// host/spirv` then proves the committed artifact is this one.
#[test]
fn the_prebuilt_artifact_is_what_is_embedded() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../host/spirv");
    let text = std::fs::read_to_string(dir.join("manifest.txt")).expect("host/spirv/manifest.txt");
    let mut hash = None;
    let mut files = BTreeMap::new();
    for line in text.lines().filter(|l| !l.trim().is_empty() && !l.starts_with('#')) {
        match line.split_whitespace().collect::<Vec<_>>().as_slice() {
            ["source-hash", h] => hash = Some(h.to_string()),
            ["module", entry, file] => {
                files.insert(entry.to_string(), file.to_string());
            }
            _ => panic!("manifest line {line:?}"),
        }
    }
    assert_eq!(hash.as_deref(), Some(dof::shaders::SOURCE_HASH), "source hash in host/spirv/manifest.txt");
    let embedded: BTreeSet<&str> = dof::shaders::MODULES.iter().map(|(e, _)| *e).collect();
    assert_eq!(files.keys().map(String::as_str).collect::<BTreeSet<_>>(), embedded, "entry points in the manifest");
    for (entry, bytes) in dof::shaders::MODULES {
        let on_disk = std::fs::read(dir.join(&files[*entry])).expect("module file");
        assert!(on_disk == *bytes, "host/spirv/{} differs from the embedded module of {entry}", files[*entry]);
    }
    let named: BTreeSet<&str> = files.values().map(String::as_str).collect();
    for file in std::fs::read_dir(&dir).expect("host/spirv") {
        let name = file.expect("entry").file_name().to_string_lossy().into_owned();
        assert!(!name.ends_with(".spv") || named.contains(name.as_str()), "host/spirv/{name} is named by no entry point");
    }
}

/// The names of the module's `OpEntryPoint`s.
fn entry_points(words: &[u32]) -> BTreeSet<String> {
    assert_eq!(words.first(), Some(&0x0723_0203), "not a SPIR-V module");
    let mut names = BTreeSet::new();
    let mut at = 5;
    while at < words.len() {
        let (count, opcode) = ((words[at] >> 16) as usize, words[at] & 0xffff);
        assert!(count > 0, "malformed instruction at word {at}");
        if opcode == 15 {
            let bytes: Vec<u8> = words[at + 3..at + count].iter().flat_map(|w| w.to_le_bytes()).collect();
            let end = bytes.iter().position(|&b| b == 0).unwrap_or(bytes.len());
            names.insert(String::from_utf8_lossy(&bytes[..end]).into_owned());
        }
        at += count;
    }
    names
}

#[test]
fn every_kernel_the_host_names_has_its_own_module() {
    let mut declared: BTreeSet<String> = dof_shaders::all_kernels().map(|k| k.entry.to_string()).collect();
    for draw in dof_shaders::all_draws() {
        declared.extend([draw.vertex.to_string(), draw.fragment.to_string()]);
    }
    let embedded: BTreeSet<String> = dof::shaders::MODULES.iter().map(|(e, _)| e.to_string()).collect();
    assert_eq!(embedded, declared, "embedded modules vs kernels declared to the host");
    for entry in &declared {
        let words = dof::shaders::module_words(entry).expect("module");
        let points = entry_points(&words);
        assert_eq!(points, BTreeSet::from([entry.clone()]), "module of {entry} holds other entry points");
    }
}
