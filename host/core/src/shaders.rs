//! The SPIR-V compiled from `shaders/` by the build script — one module per entry point — and the
//! hash of the kernel sources it was compiled from (a test recomputes it to prove the embedded
//! modules are not stale).

include!(concat!(env!("OUT_DIR"), "/spirv_modules.rs"));
#[cfg(feature = "wgpu")]
include!(concat!(env!("OUT_DIR"), "/wgsl_modules.rs"));

/// SHA-256 over the kernel crate's sources (`host/core/build/source_hash.rs`) when the modules were
/// built.
pub const SOURCE_HASH: &str = env!("DOF_SHADERS_SOURCE_HASH");

/// The module holding `entry` as words, as `vkCreateShaderModule` wants them.
pub fn module_words(entry: &str) -> Option<Vec<u32>> {
    MODULES
        .iter()
        .find(|(name, _)| *name == entry)
        .map(|(_, bytes)| bytes.as_chunks::<4>().0.iter().map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect())
}

/// The WGSL module holding `entry` (`host/wgsl/`), as the wgpu backend takes it.
#[cfg(feature = "wgpu")]
pub fn wgsl_module(entry: &str) -> Option<&'static str> {
    WGSL_MODULES.iter().find(|(name, _)| *name == entry).map(|(_, source)| *source)
}

/// Total size of the embedded modules in bytes.
pub fn total_bytes() -> usize {
    MODULES.iter().map(|(_, m)| m.len()).sum()
}
