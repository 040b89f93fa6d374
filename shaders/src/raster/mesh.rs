//! The triangle-mesh scene as the rasteriser's buffers hold it, and how a surface point of it is
//! shaded. Every buffer is an array of words; the host builds them from these `Pod` types.
//!
//! - vertices: [`MeshVertex`], world space, 10 words;
//! - triangles: `[i0, i1, i2, material]`, 4 words;
//! - materials: [`MeshMaterial`], 16 words;
//! - textures: [`TextureInfo`], 4 words; texels: linear RGBA half floats, [`TEXEL_WORDS`] words
//!   each, row-major, top row first (glTF's UV origin is the top left corner), every texture
//!   followed by its mip chain ([`super::texture`]).
//!
//! Lighting model (the analytic scenes' one, so an exported analytic scene renders the same): a lit
//! surface with base colour `a` (the material's factor times its texture times the vertex colour,
//! glTF's `COLOR_0`) and unit normal `n` turned to face the viewer has radiance
//! `a · (ambient + light · max(0, n·l)) + emission`; an unlit one (`KHR_materials_unlit`) has
//! `a + emission`. No shadows, no specular term. Alpha is the base colour's alpha: `MASK` keeps the
//! surface where it reaches the cutoff (then opaque), `BLEND` keeps it with that coverage, `OPAQUE`
//! ignores it.

pub const VERTEX_WORDS: u32 = 10;
pub const TRIANGLE_WORDS: u32 = 4;
pub const MATERIAL_WORDS: u32 = 16;
pub const TEXTURE_WORDS: u32 = 4;
pub const TEXEL_WORDS: u32 = 2;
/// "No texture" in [`MeshMaterial::base_texture`] and [`MeshMaterial::emissive_texture`].
pub const NO_TEXTURE: u32 = u32::MAX;

/// [`MeshMaterial::flags`]: lit by nothing (`KHR_materials_unlit`).
pub const UNLIT: u32 = 1;
/// Both faces are seen; without it back faces are culled.
pub const DOUBLE_SIDED: u32 = 2;
/// Alpha mode `MASK`: kept where alpha >= cutoff, then opaque.
pub const ALPHA_MASK: u32 = 4;
/// Alpha mode `BLEND`: kept with coverage alpha.
pub const ALPHA_BLEND: u32 = 8;

/// [`TextureInfo::sampler`]: nearest-texel magnification (else bilinear).
pub const NEAREST: u32 = 1;
/// Wrap modes, two bits each: S at bit 1, T at bit 3.
pub const WRAP_REPEAT: u32 = 0;
pub const WRAP_CLAMP: u32 = 1;
pub const WRAP_MIRROR: u32 = 2;
pub const WRAP_S_SHIFT: u32 = 1;
pub const WRAP_T_SHIFT: u32 = 3;
/// [`TextureInfo::sampler`]: the number of mip levels (0 reads as 1), five bits at bit 8.
pub const LEVELS_SHIFT: u32 = 8;
pub const LEVELS_MASK: u32 = 0x1f;

#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct MeshVertex {
    pub position: [f32; 3],
    pub u: f32,
    /// Unit shading normal (zero when the file has none: the face normal is used).
    pub normal: [f32; 3],
    pub v: f32,
    /// Linear RGBA vertex colour as half floats (`r | g << 16`, `b | a << 16`), multiplying the
    /// base colour; [`WHITE_HALVES`] without one.
    pub color: [u32; 2],
}

/// White, opaque: the vertex colour of a vertex without one.
pub const WHITE_HALVES: [u32; 2] = [0x3c00_3c00, 0x3c00_3c00];

impl Default for MeshVertex {
    /// At the origin, no normal, no texture coordinates, white.
    fn default() -> Self {
        MeshVertex { position: [0.0; 3], u: 0.0, normal: [0.0; 3], v: 0.0, color: WHITE_HALVES }
    }
}

#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct MeshMaterial {
    /// Linear base colour factor and alpha.
    pub base: [f32; 4],
    /// Linear emission, the emissive strength already applied (may exceed 65504).
    pub emissive: [f32; 3],
    pub alpha_cutoff: f32,
    pub base_texture: u32,
    pub emissive_texture: u32,
    /// [`UNLIT`] | [`DOUBLE_SIDED`] | [`ALPHA_MASK`] | [`ALPHA_BLEND`].
    pub flags: u32,
    pub _pad: [u32; 5],
}

impl Default for MeshMaterial {
    /// glTF's default material: white, lit, opaque, single-sided.
    fn default() -> Self {
        MeshMaterial {
            base: [1.0; 4],
            emissive: [0.0; 3],
            alpha_cutoff: 0.5,
            base_texture: NO_TEXTURE,
            emissive_texture: NO_TEXTURE,
            flags: 0,
            _pad: [0; 5],
        }
    }
}

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct TextureInfo {
    /// First texel in the texel buffer.
    pub offset: u32,
    pub width: u32,
    pub height: u32,
    /// [`NEAREST`], the wrap modes and the mip levels ([`LEVELS_SHIFT`]).
    pub sampler: u32,
}

const _: () = assert!(core::mem::size_of::<MeshVertex>() == 4 * VERTEX_WORDS as usize);
const _: () = assert!(core::mem::size_of::<MeshMaterial>() == 4 * MATERIAL_WORDS as usize);
const _: () = assert!(core::mem::size_of::<TextureInfo>() == 4 * TEXTURE_WORDS as usize);

/// One directional light plus ambient, and the background radiance (the analytic scenes' [`Lighting`](../../dof/scene/struct.Lighting.html)).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Light {
    /// Unit direction towards the light.
    pub direction: [f32; 3],
    pub _pad: f32,
    pub color: [f32; 3],
    pub _pad1: f32,
    pub ambient: [f32; 3],
    pub _pad2: f32,
    /// Radiance where no surface is hit (the background at infinite depth).
    pub background: [f32; 3],
    pub _pad3: f32,
}
