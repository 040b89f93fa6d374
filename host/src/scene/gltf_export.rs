//! Exports an analytic scene as binary glTF (GLB), so that loading it back
//! ([`load_gltf_slice`](super::gltf_load::load_gltf_slice)) and rasterising gives the image ray
//! casting the analytic scene gives, up to tessellation: the test that the accumulation-buffer
//! reference converges to the exact analytic reference renders this export.
//!
//! - spheres become UV spheres (vertices on the surface, outward unit normals, the seam's vertices
//!   duplicated) with about one longitude segment per pixel of their projected circumference,
//!   between [`MIN_SEGMENTS`] and [`ExportOptions::sphere_segments`]; boxes 12 triangles with face
//!   normals, quads 2 triangles, planes a square of
//!   [`ExportOptions::plane_half_extent`] centred at the camera eye's projection onto the plane;
//!   triangles are counter-clockwise seen from outside (or from the normal's side); quads and
//!   planes are double-sided, as analytic surfaces are, while spheres and boxes are single-sided:
//!   their inner faces are what the ray caster drops as self-occluded (no viewpoint outside sees
//!   them), so culling them keeps the rasterised layers the exact ones;
//! - solid albedo becomes the base colour factor; a checker becomes a 2x2 sRGB texture (16 bits
//!   per channel, so it decodes to the albedo within 1e-4) with nearest filtering and repeat, and
//!   texture coordinates are the analytic surface coordinates over twice the cell size, so the
//!   checker's parity matches the analytic one; emission becomes the emissive factor, with
//!   `KHR_materials_emissive_strength` carrying a maximum above 1;
//! - a translucent quad or plane ([`Scene::alpha`] below 1) gets `alphaMode: BLEND` with its
//!   opacity as the base colour factor's alpha;
//! - the light becomes a `KHR_lights_punctual` directional light, the ambient term the scene's
//!   extras key `dof_ambient`, the background radiance the key `dof_background`; the camera a
//!   perspective camera node of the default scene.

use std::f32::consts::{FRAC_PI_2, PI};

use glam::{Mat3, Quat, Vec3};
use serde_json::{Value, json};

use super::analytic::{Albedo, Lighting, Material, Scene, Shape, surface_coords, tangents};
use super::builtin::builtin;
use super::camera::{Camera, CameraFrame};
use super::mesh::MAX_TRIANGLES;
use crate::error::{CoreError, Error, Result};

/// How finely curved and unbounded shapes are turned into triangles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExportOptions {
    /// Most segments around a sphere's longitude (at least 4; a sphere gets about one per pixel of
    /// its projected circumference, at least [`MIN_SEGMENTS`]); latitude gets half as many.
    pub sphere_segments: u32,
    /// Half the side of the square standing in for an infinite plane, scene units.
    pub plane_half_extent: f32,
}

impl Default for ExportOptions {
    fn default() -> Self {
        ExportOptions { sphere_segments: 96, plane_half_extent: 500.0 }
    }
}

/// The built-in scene `name` with its default camera resized to `width`x`height`, exported with
/// the default options.
pub fn export_builtin_glb(name: &str, width: u32, height: u32) -> Result<Vec<u8>> {
    let b = builtin(name)?.with_size(width, height);
    export_glb(&b.scene, &b.camera, &ExportOptions::default())
}

/// One primitive's triangles: positions, unit normals, texture coordinates and indices.
#[derive(Default)]
struct Part {
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
    uvs: Vec<[f32; 2]>,
    indices: Vec<u32>,
}

impl Part {
    /// Appends the parallelogram `corner, corner + e1, corner + e1 + e2, corner + e2` as two
    /// triangles facing `e1 × e2`; texture coordinates from `uv`. Skips a degenerate one.
    fn parallelogram(&mut self, corner: Vec3, e1: Vec3, e2: Vec3, uv: impl Fn(Vec3, Vec3) -> [f32; 2]) {
        let n = e1.cross(e2);
        if !(n.length_squared() > 0.0) {
            return;
        }
        let n = n.normalize();
        let base = self.positions.len() as u32;
        for p in [corner, corner + e1, corner + e1 + e2, corner + e2] {
            self.positions.push(p);
            self.normals.push(n);
            self.uvs.push(uv(p, n));
        }
        self.indices.extend([0, 1, 2, 0, 2, 3].map(|k| base + k));
    }
}

/// Fewest longitude segments of a sphere: its 32-gon outline keeps 99.4% of the disc's area, so a
/// pixel-sized emitter loses under 1% of its energy to tessellation.
pub const MIN_SEGMENTS: u32 = 32;

/// Longitude segments for a sphere: about one per pixel of its projected circumference (seen from
/// its centre's distance; the whole budget when the eye is near or inside it), even, between
/// [`MIN_SEGMENTS`] and `options.sphere_segments`.
pub fn sphere_segments(center: Vec3, radius: f32, frame: &CameraFrame, options: &ExportOptions) -> u32 {
    let distance = (center - frame.eye).length().max(radius);
    let radius_px = radius / (distance * frame.tan_half_fov) * 0.5 * frame.height as f32;
    let wanted = (2.0 * PI * radius_px).ceil();
    let most = options.sphere_segments;
    if !(wanted < most as f32) {
        return most;
    }
    ((wanted as u32).max(MIN_SEGMENTS).div_ceil(2) * 2).min(most)
}

/// Triangulates one shape; `uv_scale` multiplies the surface coordinates (0 without a texture).
fn tessellate(shape: &Shape, frame: &CameraFrame, uv_scale: f32, options: &ExportOptions) -> Part {
    let camera_eye = frame.eye;
    let mut part = Part::default();
    let uv = |p: Vec3, n: Vec3| {
        let (u, v) = surface_coords(shape, p, n);
        [u * uv_scale, v * uv_scale]
    };
    match *shape {
        Shape::Sphere { center, radius } => {
            let lon = sphere_segments(center, radius, frame, options);
            let lat = lon / 2;
            // Longitude φ from −π to π (the seam at ±π, where the analytic coordinates jump),
            // latitude θ from −π/2 to π/2: p = c + r (cos φ cos θ, sin θ, sin φ cos θ), which is what
            // the analytic surface coordinates (r·φ, r·θ) invert.
            for i in 0..=lat {
                let theta = -FRAC_PI_2 + PI * i as f32 / lat as f32;
                for j in 0..=lon {
                    let phi = -PI + 2.0 * PI * j as f32 / lon as f32;
                    let d = Vec3::new(phi.cos() * theta.cos(), theta.sin(), phi.sin() * theta.cos());
                    part.positions.push(center + radius * d);
                    part.normals.push(d);
                    part.uvs.push([phi * radius * uv_scale, theta * radius * uv_scale]);
                }
            }
            let at = |i: u32, j: u32| i * (lon + 1) + j;
            for i in 0..lat {
                for j in 0..lon {
                    // Counter-clockwise from outside: along θ then along φ. The triangle touching a
                    // pole along its edge has zero area and is left out.
                    if i > 0 {
                        part.indices.extend([at(i, j), at(i + 1, j), at(i, j + 1)]);
                    }
                    if i + 1 < lat {
                        part.indices.extend([at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
                    }
                }
            }
        }
        Shape::Cuboid { min, max } => {
            let d = max - min;
            let (x, y, z) = (Vec3::X * d.x, Vec3::Y * d.y, Vec3::Z * d.z);
            // Each face as corner and two edges whose cross product points outwards.
            let faces = [
                (Vec3::new(max.x, min.y, min.z), y, z),
                (min, z, y),
                (Vec3::new(min.x, max.y, min.z), z, x),
                (min, x, z),
                (Vec3::new(min.x, min.y, max.z), x, y),
                (min, y, x),
            ];
            for (corner, e1, e2) in faces {
                part.parallelogram(corner, e1, e2, uv);
            }
        }
        Shape::Quad { corner, edge_u, edge_v } => part.parallelogram(corner, edge_u, edge_v, uv),
        Shape::Plane { point, normal } => {
            let n = normal.normalize();
            let centre = camera_eye - (camera_eye - point).dot(n) * n;
            let (t, b) = tangents(normal);
            let h = options.plane_half_extent;
            part.parallelogram(centre - h * t - h * b, 2.0 * h * t, 2.0 * h * b, uv);
        }
    }
    part
}

/// Linear value to the sRGB transfer function's encoding, 16 bits.
fn srgb16(linear: f32) -> u16 {
    let l = linear.clamp(0.0, 1.0);
    let s = if l <= 0.003_130_8 { 12.92 * l } else { 1.055 * l.powf(1.0 / 2.4) - 0.055 };
    (s * 65535.0).round() as u16
}

/// The 2x2 checker texture as a 16-bit RGB PNG: texels (0,0) and (1,1) are `a`, the others `b`.
fn checker_png(a: [f32; 3], b: [f32; 3]) -> Result<Vec<u8>> {
    let mut raw = Vec::with_capacity(24);
    for colour in [a, b, b, a] {
        for c in colour {
            raw.extend(srgb16(c).to_be_bytes());
        }
    }
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, 2, 2);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Sixteen);
        enc.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
        let err = |e: png::EncodingError| Error::Scene(format!("cannot encode the checker texture: {e}"));
        let mut w = enc.write_header().map_err(err)?;
        w.write_image_data(&raw).map_err(err)?;
        w.finish().map_err(err)?;
    }
    Ok(out)
}

/// The binary chunk under construction: byte ranges for buffer views, 4-byte aligned.
#[derive(Default)]
struct Bin {
    bytes: Vec<u8>,
    views: Vec<Value>,
}

impl Bin {
    /// Appends `data` as a new buffer view (with `target` when given) and returns its index.
    fn view(&mut self, data: &[u8], target: Option<u32>) -> usize {
        let offset = self.bytes.len();
        self.bytes.extend_from_slice(data);
        while !self.bytes.len().is_multiple_of(4) {
            self.bytes.push(0);
        }
        let mut v = json!({ "buffer": 0, "byteOffset": offset, "byteLength": data.len() });
        if let Some(t) = target {
            v["target"] = json!(t);
        }
        self.views.push(v);
        self.views.len() - 1
    }
}

const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;
const FLOAT: u32 = 5126;
const UNSIGNED_INT: u32 = 5125;
const NEAREST_FILTER: u32 = 9728;
const REPEAT: u32 = 10497;

/// Exports `scene` seen by `camera` as GLB bytes; see the module documentation for the mapping.
/// Errors on an invalid camera, `sphere_segments < 4`, a non-positive or non-finite plane extent,
/// or more than 2^24 triangles.
pub fn export_glb(scene: &Scene, camera: &Camera, options: &ExportOptions) -> Result<Vec<u8>> {
    let frame = camera.frame()?;
    if options.sphere_segments < 4 {
        return Err(Error::invalid(format!("sphere_segments must be at least 4, got {}", options.sphere_segments)));
    }
    if !(options.plane_half_extent > 0.0 && options.plane_half_extent.is_finite()) {
        return Err(Error::invalid(format!("plane_half_extent must be positive and finite, got {}", options.plane_half_extent)));
    }
    let estimate: u64 = scene
        .primitives()
        .iter()
        .map(|p| match p.shape {
            Shape::Sphere { center, radius } => {
                let lon = sphere_segments(center, radius, &frame, options) as u64;
                lon * (lon / 2 * 2 - 2)
            }
            _ => 12,
        })
        .sum();
    if estimate > MAX_TRIANGLES {
        return Err(Error::Core(CoreError::TooLarge {
            what: "triangles of the exported scene".into(),
            size: estimate,
            limit: MAX_TRIANGLES,
        }));
    }

    let mut bin = Bin::default();
    let (mut accessors, mut materials, mut images, mut textures, mut prims) = (vec![], vec![], vec![], vec![], vec![]);
    for (index, prim) in scene.primitives().iter().enumerate() {
        let material_index = materials.len();
        let mut uv_scale = 0.0;
        let closed = matches!(prim.shape, Shape::Sphere { .. } | Shape::Cuboid { .. });
        let mut material = json!({ "doubleSided": !closed });
        match prim.material {
            Material::Diffuse(Albedo::Solid(c)) => {
                material["pbrMetallicRoughness"] = json!({ "baseColorFactor": [c[0], c[1], c[2], 1.0], "metallicFactor": 0.0 });
            }
            Material::Diffuse(Albedo::Checker { a, b, cell }) => {
                uv_scale = 0.5 / cell;
                let view = bin.view(&checker_png(a, b)?, None);
                images.push(json!({ "bufferView": view, "mimeType": "image/png" }));
                textures.push(json!({ "source": images.len() - 1, "sampler": 0 }));
                material["pbrMetallicRoughness"] = json!({
                    "baseColorFactor": [1.0, 1.0, 1.0, 1.0],
                    "baseColorTexture": { "index": textures.len() - 1 },
                    "metallicFactor": 0.0,
                });
            }
            Material::Emissive(c) => {
                let m = c[0].max(c[1]).max(c[2]);
                material["pbrMetallicRoughness"] = json!({ "baseColorFactor": [0.0, 0.0, 0.0, 1.0], "metallicFactor": 0.0 });
                if m > 1.0 {
                    material["emissiveFactor"] = json!([c[0] / m, c[1] / m, c[2] / m]);
                    material["extensions"] = json!({ "KHR_materials_emissive_strength": { "emissiveStrength": m } });
                } else {
                    material["emissiveFactor"] = json!(c);
                }
            }
        }
        // A translucent primitive: glTF's BLEND with its opacity as the base colour's alpha, which
        // the loader reads as the fragment's coverage ("over").
        let alpha = scene.alpha(index as u32);
        if alpha < 1.0 {
            material["pbrMetallicRoughness"]["baseColorFactor"][3] = json!(alpha);
            material["alphaMode"] = json!("BLEND");
        }
        materials.push(material);

        let part = tessellate(&prim.shape, &frame, uv_scale, options);
        let count = part.positions.len();
        let (lo, hi) = part.positions.iter().fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
        let first = accessors.len();
        let floats = |v: &mut Vec<u8>, xs: &[f32]| xs.iter().for_each(|x| v.extend(x.to_le_bytes()));
        let mut pos = Vec::new();
        let mut nrm = Vec::new();
        let mut tex = Vec::new();
        for k in 0..count {
            floats(&mut pos, &part.positions[k].to_array());
            floats(&mut nrm, &part.normals[k].to_array());
            floats(&mut tex, &part.uvs[k]);
        }
        let idx: Vec<u8> = part.indices.iter().flat_map(|i| i.to_le_bytes()).collect();
        let pv = bin.view(&pos, Some(ARRAY_BUFFER));
        accessors.push(
            json!({ "bufferView": pv, "componentType": FLOAT, "count": count, "type": "VEC3", "min": lo.to_array(), "max": hi.to_array() }),
        );
        let nv = bin.view(&nrm, Some(ARRAY_BUFFER));
        accessors.push(json!({ "bufferView": nv, "componentType": FLOAT, "count": count, "type": "VEC3" }));
        let tv = bin.view(&tex, Some(ARRAY_BUFFER));
        accessors.push(json!({ "bufferView": tv, "componentType": FLOAT, "count": count, "type": "VEC2" }));
        let iv = bin.view(&idx, Some(ELEMENT_ARRAY_BUFFER));
        accessors.push(json!({ "bufferView": iv, "componentType": UNSIGNED_INT, "count": part.indices.len(), "type": "SCALAR" }));
        prims.push(json!({
            "attributes": { "POSITION": first, "NORMAL": first + 1, "TEXCOORD_0": first + 2 },
            "indices": first + 3,
            "material": material_index,
            "mode": 4,
        }));
    }

    let Lighting { direction, color, ambient, background } = *scene.lighting();
    let strength = color[0].max(color[1]).max(color[2]);
    let light_colour = if strength > 0.0 { color.map(|c| c / strength) } else { [1.0; 3] };
    // Local −Z is the direction the light travels, so local +Z points towards the light.
    let light_rotation = Quat::from_rotation_arc(Vec3::Z, direction.normalize());
    let camera_rotation = Quat::from_mat3(&Mat3::from_cols(frame.right, frame.up, -frame.forward)).normalize();

    let mut root = json!({
        "asset": { "version": "2.0", "generator": "dof gltf_export" },
        "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_emissive_strength"],
        "extensions": { "KHR_lights_punctual": { "lights": [
            { "type": "directional", "color": light_colour, "intensity": strength }
        ] } },
        "scene": 0,
        "scenes": [{ "nodes": [0, 1, 2], "extras": { "dof_ambient": ambient, "dof_background": background } }],
        "nodes": [
            { "mesh": 0, "name": "analytic scene" },
            { "camera": 0, "name": "camera", "translation": frame.eye.to_array(), "rotation": camera_rotation.to_array() },
            { "name": "light", "rotation": light_rotation.to_array(), "extensions": { "KHR_lights_punctual": { "light": 0 } } },
        ],
        "cameras": [{ "type": "perspective", "perspective": {
            "yfov": camera.yfov_radians, "aspectRatio": frame.aspect, "znear": 0.01
        } }],
        "meshes": [{ "primitives": prims }],
        "materials": materials,
        "accessors": accessors,
        "bufferViews": bin.views,
        "buffers": [{ "byteLength": bin.bytes.len() }],
    });
    if !images.is_empty() {
        root["images"] = json!(images);
        root["textures"] = json!(textures);
        root["samplers"] = json!([{ "magFilter": NEAREST_FILTER, "minFilter": NEAREST_FILTER, "wrapS": REPEAT, "wrapT": REPEAT }]);
    }
    let json = serde_json::to_vec(&root).map_err(|e| Error::Scene(format!("cannot write the glTF JSON: {e}")))?;
    Ok(glb(json, bin.bytes))
}

/// The GLB container: a 12-byte header, the JSON chunk padded with spaces and the binary chunk
/// padded with zeros, each to 4 bytes.
pub fn glb(mut json: Vec<u8>, mut bin: Vec<u8>) -> Vec<u8> {
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }
    let total = 12 + 8 + json.len() + 8 + bin.len();
    let mut out = Vec::with_capacity(total);
    out.extend(b"glTF");
    out.extend(2u32.to_le_bytes());
    out.extend((total as u32).to_le_bytes());
    out.extend((json.len() as u32).to_le_bytes());
    out.extend(b"JSON");
    out.extend(json);
    out.extend((bin.len() as u32).to_le_bytes());
    out.extend(b"BIN\0");
    out.extend(bin);
    out
}
