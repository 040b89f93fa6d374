//! The kernels' SPIR-V translated to WGSL by naga, for wgpu (Vulkan, Metal, DX12, GL, WebGPU).
//!
//! Four SPIR-V passes first make each module one naga takes, and translates without changing what
//! it computes ([`non_finite`], [`ordered_comparisons`], [`cross_block`], [`write_only_images`]);
//! then naga parses it,
//! validates it, and writes WGSL. The entry
//! point is named after the kernel function alone (`splat::bin::splat_bin` → `splat_bin`; naga
//! appends `_` to a name ending in a digit): one module holds one entry point, and WGSL has no
//! paths.

use rspirv::binary::Assemble;

#[path = "cross_block.rs"]
mod cross_block;
#[path = "non_finite.rs"]
mod non_finite;
#[path = "ordered_comparisons.rs"]
mod ordered_comparisons;
#[path = "write_only_images.rs"]
mod write_only_images;

/// WGSL for the module of one entry point.
pub fn translate(entry: &str, spirv: &[u8]) -> Result<String, String> {
    let words: Vec<u32> = spirv.as_chunks::<4>().0.iter().map(|w| u32::from_le_bytes(*w)).collect();
    let mut module = rspirv::dr::load_words(&words).map_err(|e| format!("{entry}: cannot load the SPIR-V: {e}"))?;
    non_finite::make_non_finite_constants_runtime(&mut module).map_err(|e| format!("{entry}: {e}"))?;
    ordered_comparisons::order_float_comparisons(&mut module);
    cross_block::spill_cross_block_values(&mut module).map_err(|e| format!("{entry}: {e}"))?;
    write_only_images::mark_write_only_images(&mut module);
    let bytes: Vec<u8> = module.assemble().iter().flat_map(|w| w.to_le_bytes()).collect();

    let options = naga::front::spv::Options { adjust_coordinate_space: false, strict_capabilities: true, block_ctx_dump_prefix: None };
    let mut ir = naga::front::spv::parse_u8_slice(&bytes, &options).map_err(|e| format!("{entry}: naga cannot parse the SPIR-V: {e}"))?;
    let [only] = ir.entry_points.as_mut_slice() else {
        return Err(format!("{entry}: {} entry points in a module of one", ir.entry_points.len()));
    };
    only.name = entry.rsplit("::").next().unwrap_or(entry).to_string();
    let info = naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::all())
        .subgroup_stages(naga::valid::ShaderStages::COMPUTE)
        .subgroup_operations(
            naga::valid::SubgroupOperationSet::BASIC
                | naga::valid::SubgroupOperationSet::ARITHMETIC
                | naga::valid::SubgroupOperationSet::SHUFFLE_RELATIVE,
        )
        .validate(&ir)
        .map_err(|e| format!("{entry}: naga's validation fails: {:?}", e.into_inner()))?;
    naga::back::wgsl::write_string(&ir, &info, naga::back::wgsl::WriterFlags::empty())
        .map_err(|e| format!("{entry}: naga cannot write WGSL: {e}"))
}
