//! The kernels in WGSL (`host/wgsl/`, translated by naga from `host/spirv/` whenever the kernels
//! are rebuilt): one module per SPIR-V module, from the same kernel sources, each one that naga
//! parses as WGSL, validates, and writes as MSL (Metal), HLSL (DX12) and SPIR-V (Vulkan), the
//! languages wgpu hands to drivers. Also the WGSL peel test renderers copy from the docs.

use dof::shaders::{MODULES, SOURCE_HASH};
use naga::valid::{Capabilities, ShaderStages, SubgroupOperationSet, ValidationFlags, Validator};
use std::collections::BTreeMap;
use std::path::Path;

/// `entry point → file` of `host/wgsl/manifest.txt`, and its source hash.
fn manifest() -> (String, BTreeMap<String, String>) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../host/wgsl");
    let text = std::fs::read_to_string(dir.join("manifest.txt")).expect("host/wgsl/manifest.txt");
    let mut hash = String::new();
    let mut modules = BTreeMap::new();
    for line in text.lines().filter(|l| !l.starts_with('#') && !l.trim().is_empty()) {
        match line.split_whitespace().collect::<Vec<_>>().as_slice() {
            ["source-hash", h] => hash = h.to_string(),
            ["module", entry, file] => {
                modules.insert(entry.to_string(), std::fs::read_to_string(dir.join(file)).expect(file));
            }
            _ => panic!("manifest line {line:?}"),
        }
    }
    (hash, modules)
}

#[test]
fn every_kernel_has_its_wgsl_from_the_same_sources() {
    let (hash, modules) = manifest();
    assert_eq!(hash, SOURCE_HASH, "host/wgsl/ was translated from other kernel sources than host/spirv/");
    let spirv: Vec<&str> = MODULES.iter().map(|(entry, _)| *entry).collect();
    let wgsl: Vec<&str> = modules.keys().map(String::as_str).collect();
    assert_eq!(wgsl, spirv, "the entry points of host/wgsl/ and host/spirv/");
}

/// What a wgpu device offers the kernels beyond WGSL's core: push constants ("immediates").
fn capabilities() -> Capabilities {
    Capabilities::IMMEDIATES
}

/// The validator of a kernel's module: a subgroup variant's (`::subgroups`) also has what
/// [`wgpu::Features::SUBGROUP`] gives compute shaders, the others nothing of it.
fn validator(entry: &str) -> Validator {
    if !entry.ends_with("::subgroups") {
        return Validator::new(ValidationFlags::all(), capabilities());
    }
    let mut v = Validator::new(ValidationFlags::all(), capabilities() | Capabilities::SUBGROUP);
    v.subgroup_stages(ShaderStages::COMPUTE)
        .subgroup_operations(SubgroupOperationSet::BASIC | SubgroupOperationSet::ARITHMETIC | SubgroupOperationSet::SHUFFLE_RELATIVE);
    v
}

#[test]
fn every_kernel_translates_to_msl_hlsl_and_spirv() {
    let (_, modules) = manifest();
    let mut failures = Vec::new();
    for (entry, source) in &modules {
        let module = match naga::front::wgsl::parse_str(source) {
            Ok(m) => m,
            Err(e) => {
                failures.push(format!("{entry}: WGSL: {}", e.emit_to_string(source)));
                continue;
            }
        };
        let info = match validator(entry).validate(&module) {
            Ok(info) => info,
            Err(e) => {
                failures.push(format!("{entry}: validation: {:?}", e.into_inner()));
                continue;
            }
        };
        // One entry point, named after the kernel function (naga's namer appends `_` to a name
        // ending in a digit); pipelines take it as the module's only one.
        let short = entry.rsplit("::").next().unwrap_or(entry);
        assert!(matches!(module.entry_points.as_slice(), [only] if only.name.trim_end_matches('_') == short), "{entry}: its entry point");

        // Metal Shading Language 2.0 (macOS 10.13, iOS 11): naga's default, 1.0, has no instance
        // index. Subgroup variants: 2.1 (SIMD-group functions), as wgpu asks for them.
        let subgroups = entry.ends_with("::subgroups");
        let lang_version = if subgroups { (2, 1) } else { (2, 0) };
        let msl = naga::back::msl::Options { lang_version, fake_missing_bindings: true, ..Default::default() };
        if let Err(e) = naga::back::msl::write_string(&module, &info, &msl, &naga::back::msl::PipelineOptions::default()) {
            failures.push(format!("{entry}: MSL: {e}"));
        }
        let immediates = naga::back::hlsl::BindTarget { space: 0, register: 0, ..Default::default() };
        // Subgroup variants: shader model 6.0 (wave intrinsics), as wgpu asks for them.
        let shader_model = if subgroups { naga::back::hlsl::ShaderModel::V6_0 } else { naga::back::hlsl::ShaderModel::V5_1 };
        let hlsl = naga::back::hlsl::Options {
            immediates_target: Some(immediates),
            fake_missing_bindings: true,
            shader_model,
            ..Default::default()
        };
        let mut text = String::new();
        if let Err(e) = naga::back::hlsl::Writer::new(&mut text, &hlsl, &Default::default()).write(&module, &info, None) {
            failures.push(format!("{entry}: HLSL: {e}"));
        }
        if let Err(e) = naga::back::spv::write_vec(&module, &info, &Default::default(), None) {
            failures.push(format!("{entry}: SPIR-V: {e}"));
        }
    }
    assert!(failures.is_empty(), "{} of {} kernels fail:\n{}", failures.len(), modules.len(), failures.join("\n"));
}

/// The WGSL peel test of docs/integration.md (`<!-- wgsl: peel_keep -->`) is the one the wgpu
/// example host's shader holds, verbatim, and that shader is valid WGSL.
#[test]
fn the_documented_wgsl_peel_test_is_the_example_hosts_and_validates() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    let doc = std::fs::read_to_string(format!("{root}/docs/integration.md")).expect("docs/integration.md");
    let after = doc.split_once("<!-- wgsl: peel_keep -->").expect("the peel_keep WGSL snippet").1;
    let snippet = after.split_once("```wgsl\n").and_then(|(_, rest)| rest.split_once("```")).expect("a wgsl block").0;
    assert!(snippet.contains("fn dof_peel_keep"), "{snippet}");
    let shader = std::fs::read_to_string(format!("{root}/host/examples/wgpu_host/peel.wgsl")).expect("the example's shader");
    assert!(shader.contains(snippet), "host/examples/wgpu_host/peel.wgsl does not hold the doc's snippet verbatim");
    let module = naga::front::wgsl::parse_str(&shader).unwrap_or_else(|e| panic!("{}", e.emit_to_string(&shader)));
    Validator::new(ValidationFlags::all(), capabilities()).validate(&module).unwrap_or_else(|e| panic!("{e:?}"));
}
