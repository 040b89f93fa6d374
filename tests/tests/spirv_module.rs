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
    let mut declared: BTreeSet<String> =
        dof_shaders::all_kernels().flat_map(|k| [Some(k.entry), k.subgroup_entry]).flatten().map(String::from).collect();
    for draw in dof_shaders::all_draws() {
        declared.extend([draw.vertex.to_string(), draw.fragment.to_string()]);
    }
    declared.extend(dof_shaders::all_texture_kernels().map(String::from));
    let embedded: BTreeSet<String> = dof::shaders::MODULES.iter().map(|(e, _)| e.to_string()).collect();
    assert_eq!(embedded, declared, "embedded modules vs kernels declared to the host");
    for entry in &declared {
        let words = dof::shaders::module_words(entry).expect("module");
        let points = entry_points(&words);
        assert_eq!(points, BTreeSet::from([entry.clone()]), "module of {entry} holds other entry points");
    }
}

/// A storage-buffer variable of a module: its descriptor set and binding, and whether it is
/// decorated `NonWritable`.
#[derive(Debug)]
struct StorageBuffer {
    set: u32,
    binding: u32,
    non_writable: bool,
}

/// The module's `StorageBuffer` variables, read from its words: `OpVariable` (storage class 12) with
/// its `OpDecorate` `DescriptorSet` (34), `Binding` (33) and `NonWritable` (24). rust-gpu 0.11
/// decorates the variable of a `&[u32]` entry parameter `NonWritable` (not the member of its block
/// struct, which read-only and writable bindings share); a member decoration would count too.
fn storage_buffers(words: &[u32]) -> Vec<StorageBuffer> {
    const NON_WRITABLE: u32 = 24;
    const BINDING: u32 = 33;
    const DESCRIPTOR_SET: u32 = 34;
    const STORAGE_BUFFER: u32 = 12;
    assert_eq!(words.first(), Some(&0x0723_0203), "not a SPIR-V module");
    let mut decorations: BTreeMap<u32, Vec<(u32, Option<u32>)>> = BTreeMap::new();
    let mut member_non_writable: BTreeMap<u32, BTreeSet<u32>> = BTreeMap::new();
    let mut members: BTreeMap<u32, u32> = BTreeMap::new();
    let mut pointee: BTreeMap<u32, u32> = BTreeMap::new();
    let mut variables = Vec::new();
    let mut at = 5;
    while at < words.len() {
        let (count, opcode) = ((words[at] >> 16) as usize, words[at] & 0xffff);
        assert!(count > 0 && at + count <= words.len(), "malformed instruction at word {at}");
        let ops = &words[at + 1..at + count];
        match opcode {
            // OpDecorate target decoration [literal]
            71 => decorations.entry(ops[0]).or_default().push((ops[1], ops.get(2).copied())),
            // OpMemberDecorate struct member decoration
            72 if ops[2] == NON_WRITABLE => {
                member_non_writable.entry(ops[0]).or_default().insert(ops[1]);
            }
            // OpTypeStruct result members..
            30 => {
                members.insert(ops[0], ops.len() as u32 - 1);
            }
            // OpTypePointer result storage-class type
            32 => {
                pointee.insert(ops[0], ops[2]);
            }
            // OpVariable type result storage-class
            59 if ops[2] == STORAGE_BUFFER => variables.push((ops[0], ops[1])),
            _ => {}
        }
        at += count;
    }
    variables
        .into_iter()
        .map(|(ty, var)| {
            let decorated = decorations.get(&var).map(Vec::as_slice).unwrap_or(&[]);
            let literal = |d: u32| decorated.iter().find(|(k, _)| *k == d).and_then(|(_, v)| *v);
            let block = pointee.get(&ty).copied();
            let every_member = block.is_some_and(|s| {
                let n = members.get(&s).copied().unwrap_or(0);
                n > 0 && member_non_writable.get(&s).is_some_and(|m| m.len() as u32 == n)
            });
            StorageBuffer {
                set: literal(DESCRIPTOR_SET).unwrap_or_else(|| panic!("storage buffer %{var} has no descriptor set")),
                binding: literal(BINDING).unwrap_or_else(|| panic!("storage buffer %{var} has no binding")),
                non_writable: decorated.iter().any(|(k, _)| *k == NON_WRITABLE) || every_member,
            }
        })
        .collect()
}

/// Every kernel's read-only bindings (those its `kernel!` declaration marks `read`, the
/// `KernelDesc::read_only` mask) are exactly its `NonWritable` storage buffers in its SPIR-V, and
/// every storage buffer of a draw's stages is `NonWritable` (graphics stages only read).
#[test]
fn read_only_bindings_are_non_writable_in_the_spirv() {
    let (mut read_only, mut writable) = (0, 0);
    for (kernel, entry) in
        dof_shaders::all_kernels().flat_map(|k| [Some(k.entry), k.subgroup_entry].into_iter().flatten().map(move |e| (k, e)))
    {
        let words = dof::shaders::module_words(entry).expect("module");
        let mut seen = 0u32;
        for b in storage_buffers(&words) {
            let i = b.binding;
            assert_eq!(b.set, 0, "{entry}: binding {i} is not in descriptor set 0");
            assert!(i < kernel.bindings, "{entry}: binding {i} beyond its {} bindings", kernel.bindings);
            assert_eq!(seen & (1 << i), 0, "{entry}: binding {i} twice");
            seen |= 1 << i;
            let declared = kernel.read_only & (1 << i) != 0;
            assert_eq!(b.non_writable, declared, "{entry}: binding {i} NonWritable in the SPIR-V vs declared read-only");
            if declared {
                read_only += 1;
            } else {
                writable += 1;
            }
        }
        // rust-gpu leaves out a binding the kernel never touches (`raster_setup`'s textures): a module
        // holds a subset of the declared bindings, and nothing is there to decorate for the others.
        assert_ne!(seen, 0, "{entry}: no binding in the module");
    }
    // The kernels declare both kinds, so the comparison above saw both answers.
    assert!(read_only > 100 && writable > 50, "{read_only} read-only and {writable} writable bindings checked");
    for draw in dof_shaders::all_draws() {
        for entry in [draw.vertex, draw.fragment] {
            let buffers = storage_buffers(&dof::shaders::module_words(entry).expect("module"));
            assert!(!buffers.is_empty(), "{entry} binds no storage buffer");
            for b in buffers {
                assert!(b.set == 0 && b.binding < draw.bindings, "{entry}: binding {} of set {}", b.binding, b.set);
                assert!(b.non_writable, "{entry}: binding {} is writable", b.binding);
            }
        }
    }
}
