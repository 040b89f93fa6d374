//! The embedded SPIR-V modules: built from the current kernel sources, one per entry point the host
//! refers to. Runs without a Vulkan driver.

use std::collections::BTreeSet;
use std::path::Path;

#[test]
fn embedded_module_was_built_from_the_current_sources() {
    let shaders = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shaders");
    assert_eq!(
        dof::source_hash::shader_source_hash(&shaders),
        dof::shaders::SOURCE_HASH,
        "the embedded SPIR-V was built from other kernel sources than those on disk"
    );
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
