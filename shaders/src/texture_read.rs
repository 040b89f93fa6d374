//! A depth texture read into a buffer by a kernel, where a copy cannot do it: wgpu copies no depth
//! out of `Depth24Plus` or `Depth24PlusStencil8` (stored as anything of 24 bits or more), and out of
//! `Depth32Float` only whole textures, never the frame-sized part. The texture is loaded as it is, so the
//! buffer holds each texel's depth as an f32, as a `D32_SFLOAT` copy would; the frame then reads it
//! like one. Only the wgpu backend runs it (Vulkan copies every depth format, and the CPU backend's
//! images are buffers already), so it has no CPU body.

/// Invocations a workgroup.
pub const THREADS: u32 = 64;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct TextureReadParams {
    /// The top-left part of the texture read, in texels.
    pub width: u32,
    pub height: u32,
    /// Where the first texel's word goes; the rest follow row after row, unpadded.
    pub offset_words: u32,
}

/// The SPIR-V entry point (one module of `host/spirv/`, one of `host/wgsl/`).
pub const DEPTH_TEXTURE_WORDS: &str = "texture_read::depth_texture_words";

/// `words[offset + y·width + x]` = the f32 bits of texel (x, y)'s depth, for the top-left
/// `width × height` texels, the workgroups striding over any number of them.
#[cfg(target_arch = "spirv")]
#[spirv_std::spirv(compute(threads(64)))]
pub fn depth_texture_words(
    #[spirv(workgroup_id)] group: spirv_std::glam::UVec3,
    #[spirv(num_workgroups)] groups: spirv_std::glam::UVec3,
    #[spirv(local_invocation_index)] lid: u32,
    #[spirv(push_constant)] p: &TextureReadParams,
    #[spirv(descriptor_set = 0, binding = 0)] depth: &spirv_std::Image!(2D, type=f32, sampled=true, depth=true),
    #[spirv(descriptor_set = 0, binding = 1, storage_buffer)] words: &mut [u32],
) {
    let n = p.width * p.height;
    let stride = groups.x * THREADS;
    let mut i = group.x * THREADS + lid;
    while i < n {
        let at = spirv_std::glam::IVec2::new((i % p.width) as i32, (i / p.width) as i32);
        let texel: spirv_std::glam::Vec4 = depth.fetch(at);
        words[(p.offset_words + i) as usize] = texel.x.to_bits();
        i += stride;
    }
}
