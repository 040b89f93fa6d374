//! Compiles the kernel crate to SPIR-V with rust-gpu whenever its sources change, so what runs on
//! Vulkan is always the current kernel source (no binaries are kept in git).

use spirv_builder::SpirvBuilder;
use std::path::Path;

include!("src/source_hash.rs");

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shaders");
    let mut builder = SpirvBuilder::new(&crate_dir, "spirv-unknown-vulkan1.2");
    builder.build_script.defaults = true;
    builder.build_script.env_shader_spv_path = Some(true);
    builder.build()?;
    println!("cargo::rustc-env=DOF_SHADERS_SOURCE_HASH={}", shader_source_hash(&crate_dir));
    println!("cargo::rerun-if-changed={}", crate_dir.join("src").display());
    println!("cargo::rerun-if-changed={}", crate_dir.join("Cargo.toml").display());
    Ok(())
}
