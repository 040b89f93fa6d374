//! The mesh as the rasteriser takes it (borrowed, so any loader can hand it over) and its copy on
//! the device.

use crate::backend::{Backend, BufferId};
use crate::error::{CoreError, Error, Result};
use crate::scene::Lighting;
use dof_shaders::raster::mesh::{Light, MATERIAL_WORDS, MeshMaterial, MeshVertex, NO_TEXTURE, TextureInfo};

/// The scenes' limits, which the rasteriser's fields are sized for.
pub use crate::scene::mesh::{MAX_TEXELS, MAX_TRIANGLES};

/// A triangle mesh in world space with its materials, textures and light.
#[derive(Clone, Copy, Debug)]
pub struct RasterScene<'a> {
    pub vertices: &'a [MeshVertex],
    /// `[i0, i1, i2, material]`.
    pub triangles: &'a [[u32; 4]],
    pub materials: &'a [MeshMaterial],
    pub textures: &'a [TextureInfo],
    /// Linear RGBA.
    pub texels: &'a [[f32; 4]],
    pub lighting: Lighting,
}

impl RasterScene<'_> {
    /// Checks what the rasteriser relies on: finite vertex data, triangle indices and material
    /// indices in range, texture references and texel ranges in range, finite material factors,
    /// at most [`MAX_TRIANGLES`] triangles and [`MAX_TEXELS`] texels, finite lighting.
    pub fn validate(&self) -> Result<()> {
        let bad = |m: String| Err(Error::Scene(m));
        if self.triangles.is_empty() {
            return bad("the scene holds no triangles; a scene needs at least one".into());
        }
        if self.triangles.len() as u64 > MAX_TRIANGLES {
            return Err(Error::Core(CoreError::TooLarge {
                what: "triangles of the scene".into(),
                size: self.triangles.len() as u64,
                limit: MAX_TRIANGLES,
            }));
        }
        if self.texels.len() as u64 > MAX_TEXELS {
            return Err(Error::Core(CoreError::TooLarge {
                what: "texels of all textures".into(),
                size: self.texels.len() as u64,
                limit: MAX_TEXELS,
            }));
        }
        for (i, v) in self.vertices.iter().enumerate() {
            let finite = v.position.iter().chain(v.normal.iter()).all(|x| x.is_finite()) && v.u.is_finite() && v.v.is_finite();
            if !finite {
                return bad(format!("vertex {i} has a non-finite position, normal or texture coordinate"));
            }
        }
        let (nv, nm) = (self.vertices.len() as u64, self.materials.len() as u64);
        for (i, t) in self.triangles.iter().enumerate() {
            if t[..3].iter().any(|&k| k as u64 >= nv) {
                return bad(format!("triangle {i} names vertex {:?}, but there are only {nv} vertices", &t[..3]));
            }
            if t[3] as u64 >= nm {
                return bad(format!("triangle {i} names material {}, but there are only {nm} materials", t[3]));
            }
        }
        let nt = self.textures.len() as u64;
        for (i, m) in self.materials.iter().enumerate() {
            for tex in [m.base_texture, m.emissive_texture] {
                if tex != NO_TEXTURE && tex as u64 >= nt {
                    return bad(format!("material {i} names texture {tex}, but there are only {nt} textures"));
                }
            }
            if !m.base.iter().chain(m.emissive.iter()).all(|x| x.is_finite() && *x >= 0.0) || !m.alpha_cutoff.is_finite() {
                return bad(format!("material {i} has a negative or non-finite colour factor or alpha cutoff"));
            }
        }
        for (i, t) in self.textures.iter().enumerate() {
            let end = t.offset as u64 + t.width as u64 * t.height as u64;
            if t.width == 0 || t.height == 0 || end > self.texels.len() as u64 {
                return bad(format!(
                    "texture {i} ({}x{} at texel {}) is empty or runs past the {} texels",
                    t.width,
                    t.height,
                    t.offset,
                    self.texels.len()
                ));
            }
        }
        let l = &self.lighting;
        let colours_ok = l.color.iter().chain(&l.ambient).chain(&l.background).all(|x| x.is_finite() && *x >= 0.0);
        if !l.direction.is_finite() || !(l.direction.length_squared() > 0.0) || !colours_ok {
            return bad("the light needs a finite, non-zero direction and finite, non-negative colours".into());
        }
        Ok(())
    }

    /// The corners of every triangle, world space.
    pub fn triangle_positions(&self) -> impl Iterator<Item = [glam::Vec3; 3]> + '_ {
        self.triangles
            .iter()
            .map(|t| [0, 1, 2].map(|k| glam::Vec3::from(self.vertices.get(t[k] as usize).map_or([0.0; 3], |v| v.position))))
    }

    /// The light in the layout the shading kernel reads (direction normalised).
    pub fn light(&self) -> Light {
        let d = self.lighting.direction.normalize_or_zero();
        Light {
            direction: d.to_array(),
            color: self.lighting.color,
            ambient: self.lighting.ambient,
            background: self.lighting.background,
            ..Light::default()
        }
    }
}

impl crate::scene::MeshScene {
    /// Checks what the rasteriser relies on ([`RasterScene::validate`]).
    pub fn validate(&self) -> Result<()> {
        self.raster().validate()
    }

    /// The scene as the rasteriser takes it.
    pub fn raster(&self) -> RasterScene<'_> {
        RasterScene {
            vertices: &self.vertices,
            triangles: &self.triangles,
            materials: &self.materials,
            textures: &self.textures,
            texels: &self.texels,
            lighting: self.lighting,
        }
    }
}

/// The mesh's buffers on a backend: vertices, triangles, materials, textures, texels (the draw's
/// bindings 0-4; the textures with their mip chains, [`super::mipmap`]). Free them with [`DeviceMesh::destroy`].
pub struct DeviceMesh {
    pub buffers: [BufferId; 5],
    pub triangles: u32,
    pub textures: u32,
    pub bytes: u64,
}

impl DeviceMesh {
    /// Validates and uploads `scene`. Empty tables get one unused entry (buffers cannot be empty).
    pub fn upload(backend: &mut dyn Backend, scene: &RasterScene) -> Result<Self> {
        scene.validate()?;
        let (textures, texels) = super::mipmap::sampled_textures(scene.textures, scene.texels);
        let words: [Vec<u32>; 5] = [
            bytemuck::cast_slice(scene.vertices).to_vec(),
            bytemuck::cast_slice(scene.triangles).to_vec(),
            bytemuck::cast_slice(scene.materials).to_vec(),
            bytemuck::cast_slice(&textures).to_vec(),
            texels,
        ];
        let labels = ["mesh/vertices", "mesh/triangles", "mesh/materials", "mesh/textures", "mesh/texels"];
        let mut buffers = Vec::with_capacity(5);
        let mut bytes = 0;
        for (w, label) in words.iter().zip(labels) {
            let size = (w.len() as u64).max(MATERIAL_WORDS as u64);
            let made = backend.create_buffer(size, label).and_then(|b| {
                buffers.push(b);
                if w.is_empty() { Ok(()) } else { backend.write_buffer(b, 0, w) }
            });
            if let Err(e) = made {
                for b in buffers {
                    backend.destroy_buffer(b);
                }
                return Err(e.into());
            }
            bytes += 4 * size;
        }
        Ok(DeviceMesh {
            buffers: [buffers[0], buffers[1], buffers[2], buffers[3], buffers[4]],
            triangles: scene.triangles.len() as u32,
            textures: scene.textures.len() as u32,
            bytes,
        })
    }

    /// Runs `f` with `scene` uploaded ([`DeviceMesh::upload`]), and frees it after, whatever `f`
    /// returned: one upload for several passes over a scene (a peel and its accumulation buffer
    /// build the textures' mip chains once).
    pub fn scoped<T>(
        backend: &mut dyn Backend,
        scene: &RasterScene,
        f: impl FnOnce(&mut dyn Backend, &DeviceMesh) -> Result<T>,
    ) -> Result<T> {
        let mesh = DeviceMesh::upload(backend, scene)?;
        let result = f(backend, &mesh);
        mesh.destroy(backend);
        result
    }

    pub fn destroy(self, backend: &mut dyn Backend) {
        for b in self.buffers {
            backend.destroy_buffer(b);
        }
    }
}
