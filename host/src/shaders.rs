//! The SPIR-V module compiled from `shaders/` by the build script, and the hash of the kernel sources
//! it was compiled from (a test recomputes it to prove the embedded module is not stale).

/// The module's bytes, embedded at build time.
pub static SPIRV: &[u8] = include_bytes!(env!("dof_shaders.spv"));

/// SHA-256 over the kernel crate's sources (`Cargo.toml` and `src/**/*.rs`, in path order) at the
/// time the module was built.
pub const SOURCE_HASH: &str = env!("DOF_SHADERS_SOURCE_HASH");

/// The module as words, as `vkCreateShaderModule` wants it.
pub fn spirv_words() -> Vec<u32> {
    SPIRV.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect()
}
