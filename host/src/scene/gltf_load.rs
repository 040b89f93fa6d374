//! Loads glTF 2.0 files (`.gltf` with external or embedded data, `.glb`) into a [`MeshScene`].
//!
//! The `gltf` crate parses and validates the document; buffers and images are resolved here rather
//! than by its importer, so that every failure is an error naming the file or part at fault (the
//! importer cannot read embedded images from a slice and can panic on malformed references), and
//! accessors are checked before they are read.
//!
//! What is used:
//! - the default scene (else the first), its whole node hierarchy with world transforms; normals by
//!   the inverse transpose, renormalised; a mirroring transform (negative determinant) reverses the
//!   winding so front faces stay front;
//! - triangle lists, strips and fans (points and lines are skipped and counted), indexed or not;
//!   `POSITION` (required), `NORMAL` and `TEXCOORD_0` (zero when absent);
//! - materials: base colour factor and texture (sRGB), emissive factor × `KHR_materials_emissive_strength`
//!   and texture (sRGB), `KHR_materials_unlit`, `doubleSided`, alpha mode and cutoff; glTF's default
//!   material for primitives without one; textures naming a coordinate set other than 0 use set 0
//!   (counted);
//! - perspective cameras of the scene's nodes (orthographic ones are skipped and counted);
//! - lighting: the first `KHR_lights_punctual` directional light met in the scene (depth first)
//!   gives the direction towards the light (its node's local +Z in world space) and colour ×
//!   intensity; the scene's extras key `"dof_ambient": [r, g, b]` gives the ambient term, else
//!   [`Lighting::default`]'s, and `"dof_background": [r, g, b]` the background radiance (what a
//!   ray that hits nothing sees), else black. Without a directional light the lighting is
//!   [`Lighting::default`].
//!   Other lights are counted as ignored.
//!
//! External files: a buffer or image URI (relative path or `file:` URI, percent-decoded) must stay
//! inside the folder of the .gltf file: absolute paths, `..` leaving the folder (resolved
//! lexically) and symbolic links whose target lies outside the folder are refused. Only regular
//! files are read (never directories, FIFOs, devices or sockets); a buffer file must hold at least
//! its `byteLength` and only that much is read; an image file may hold at most
//! [`MAX_IMAGE_FILE_BYTES`]. Loading from memory, any external file is an error.
//!
//! Zero-area triangles are dropped and counted (see [`super::mesh`]). Errors, never panics:
//! malformed JSON or GLB, missing or unreadable files (named), bad accessors, indices out of range,
//! non-finite data (naming the mesh), no triangles at all, too many triangles or texels.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use dof_shaders::raster::mesh::{
    ALPHA_BLEND, ALPHA_MASK, DOUBLE_SIDED, MeshMaterial, MeshVertex, NEAREST, TextureInfo, UNLIT, WHITE_HALVES, WRAP_CLAMP, WRAP_MIRROR,
    WRAP_REPEAT, WRAP_S_SHIFT, WRAP_T_SHIFT,
};
use glam::{Mat3, Mat4, Vec3};
use gltf::accessor::{DataType, Dimensions};
use gltf::mesh::Mode;

use super::analytic::Lighting;
use super::analytic::in_contract;
use super::mesh::{LoadReport, MAX_TEXELS, MAX_TRIANGLES, MeshCamera, MeshScene, zero_area};
use crate::error::{CoreError, Error, Result};

fn scene_err(m: impl Into<String>) -> Error {
    Error::Scene(m.into())
}

/// Loads a `.gltf` or `.glb` file; external buffers and images are read relative to its folder.
pub fn load_gltf(path: &Path) -> Result<MeshScene> {
    // Only a regular file: a FIFO would block and a device (`/dev/zero`) never ends.
    if let Ok(meta) = std::fs::metadata(path)
        && !meta.file_type().is_file()
    {
        return Err(scene_err(format!(
            "cannot read the glTF file `{}`: it is not a regular file (a directory, FIFO, device or socket)",
            path.display()
        )));
    }
    let bytes = std::fs::read(path).map_err(|e| scene_err(format!("cannot read the glTF file `{}`: {e}", path.display())))?;
    let base = path.parent().map(Path::to_path_buf).unwrap_or_default();
    load(&bytes, Some(&base)).map_err(|e| match e {
        Error::Scene(m) => Error::Scene(format!("{}: {m}", path.display())),
        other => other,
    })
}

/// The external files a `.gltf` or `.glb` file refers to (its buffers and images given by a
/// relative path or `file:` URI, not data URIs), as paths beside it, without reading them: what
/// a command must not overwrite. Best effort: a file that cannot be read or parsed lists none
/// (loading it reports why); a reference that would be refused when loading is listed as it
/// resolves lexically.
pub fn gltf_external_files(path: &Path) -> Vec<PathBuf> {
    // Only a regular file is read (a FIFO would block).
    if !std::fs::metadata(path).is_ok_and(|m| m.file_type().is_file()) {
        return Vec::new();
    }
    let Ok(bytes) = std::fs::read(path) else { return Vec::new() };
    let Ok(gltf) = gltf::Gltf::from_slice_without_validation(&bytes) else { return Vec::new() };
    let json = gltf.document.into_json();
    let base = path.parent().unwrap_or(Path::new(""));
    let uris = json.buffers.iter().filter_map(|b| b.uri.as_deref()).chain(json.images.iter().filter_map(|i| i.uri.as_deref()));
    uris.filter(|uri| !uri.starts_with("data:"))
        .filter_map(|uri| {
            let relative = uri.strip_prefix("file://").or_else(|| uri.strip_prefix("file:")).unwrap_or(uri);
            let relative = percent_decode(relative, "a reference").ok()?;
            Some(base.join(relative))
        })
        .collect()
}

/// Loads glTF from memory (`.glb`, or `.gltf` JSON whose buffers and images are embedded as data
/// URIs or in the GLB's binary chunk); a reference to an external file is an error.
pub fn load_gltf_slice(bytes: &[u8]) -> Result<MeshScene> {
    load(bytes, None)
}

/// Bytes that start like a binary header (a control or non-ASCII byte in the first 12) but not
/// with the GLB magic `glTF`, nor with JSON: a wrong GLB magic, reported as such rather than as
/// the JSON error the parser would give.
fn wrong_glb_magic(bytes: &[u8]) -> Option<Error> {
    let text = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    if bytes.len() < 4 || bytes.starts_with(b"glTF") || text.iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'{') {
        return None;
    }
    let binary = bytes[..bytes.len().min(12)].iter().any(|&b| (b < 0x20 && !b.is_ascii_whitespace()) || b >= 0x7f);
    binary.then(|| {
        scene_err(format!(
            "not a GLB file (wrong magic `{}`, expected `glTF`) and not glTF JSON; the file is damaged or not glTF",
            bytes[..4].escape_ascii()
        ))
    })
}

fn load(bytes: &[u8], base: Option<&Path>) -> Result<MeshScene> {
    if let Some(e) = wrong_glb_magic(bytes) {
        return Err(e);
    }
    let invalid =
        |e: &dyn std::fmt::Display| scene_err(format!("not a valid glTF 2.0 file ({e}); expected glTF JSON or a complete binary .glb"));
    // Parsed, then validated once the references its validation trusts are checked.
    let gltf::Gltf { document, blob } = gltf::Gltf::from_slice_without_validation(bytes).map_err(|e| invalid(&e))?;
    let json = document.into_json();
    check_unvalidated(&json).map_err(|e| invalid(&e))?;
    let document = gltf::Document::from_json(json).map_err(|e| invalid(&e))?;
    let buffers = read_buffers(&document, base, blob)?;
    let mut loader =
        Loader { doc: &document, base, buffers, images: HashMap::new(), textures: HashMap::new(), materials: HashMap::new(), out: empty() };
    let scene = document
        .default_scene()
        .or_else(|| document.scenes().next())
        .ok_or_else(|| scene_err("the glTF file holds no scene, so no triangles; add a scene whose nodes hold meshes"))?;
    loader.out.lighting.ambient = extras_colour(&scene, "dof_ambient")?.unwrap_or(Lighting::default().ambient);
    loader.out.lighting.background = in_contract(extras_colour(&scene, "dof_background")?.unwrap_or(Lighting::default().background));
    let mut light_found = false;
    // Depth first with an explicit stack (no recursion limit on deep files); a node reached twice
    // means the hierarchy is not a tree.
    let mut seen = vec![false; document.nodes().len()];
    let mut stack: Vec<(gltf::Node, Mat4)> = scene.nodes().map(|n| (n, Mat4::IDENTITY)).collect();
    stack.reverse();
    while let Some((node, parent)) = stack.pop() {
        if std::mem::replace(&mut seen[node.index()], true) {
            return Err(scene_err(format!("node {} is reached twice; a glTF node hierarchy must be a tree", node.index())));
        }
        let world = parent * Mat4::from_cols_array_2d(&node.transform().matrix());
        if !world.is_finite() {
            return Err(scene_err(format!("node {} has a non-finite world transform", node.index())));
        }
        if let Some(mesh) = node.mesh() {
            loader.mesh(&mesh, &world)?;
        }
        if let Some(camera) = node.camera() {
            loader.camera(&camera, &world);
        }
        if let Some(light) = node.light() {
            if !light_found && matches!(light.kind(), gltf::khr_lights_punctual::Kind::Directional) {
                light_found = true;
                let direction = world.transform_vector3(Vec3::Z).normalize_or_zero();
                let color = light.color().map(|c| c * light.intensity());
                if direction == Vec3::ZERO || !color.iter().all(|c| c.is_finite() && *c >= 0.0) {
                    return Err(scene_err(format!(
                        "the directional light of node {} needs a non-degenerate transform and a finite, non-negative colour and intensity",
                        node.index()
                    )));
                }
                loader.out.lighting.direction = direction;
                loader.out.lighting.color = color;
            } else {
                loader.out.report.ignored_lights += 1;
            }
        }
        let first_child = stack.len();
        stack.extend(node.children().map(|c| (c, world)));
        stack[first_child..].reverse();
    }
    if loader.out.triangles.is_empty() {
        return Err(scene_err("the glTF file holds no triangles: its scene has no triangle primitives (or only zero-area ones)"));
    }
    loader.out.validate()?;
    Ok(loader.out)
}

/// Errors on what the gltf crate (1.4) trusts without validating, and would panic on: a primitive
/// whose `POSITION` names an accessor that does not exist (its validation indexes the accessors
/// with it), an image with neither `uri` nor `bufferView` or a `bufferView` without `mimeType`, a
/// camera without the projection its `type` names (`Image::source` and `Camera::projection`
/// unwrap them).
fn check_unvalidated(json: &gltf::json::Root) -> std::result::Result<(), String> {
    use gltf::json::camera::Type;
    use gltf::json::mesh::Semantic;
    use gltf::json::validation::Checked;
    for (m, mesh) in json.meshes.iter().enumerate() {
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            if let Some(index) = primitive.attributes.get(&Checked::Valid(Semantic::Positions))
                && index.value() >= json.accessors.len()
            {
                return Err(format!(
                    "meshes[{m}].primitives[{p}].attributes[\"POSITION\"]: accessor {} does not exist; the file has {}",
                    index.value(),
                    json.accessors.len()
                ));
            }
        }
    }
    for (i, image) in json.images.iter().enumerate() {
        match (&image.buffer_view, &image.uri, &image.mime_type) {
            (None, None, _) => return Err(format!("images[{i}] has neither a uri nor a bufferView")),
            (Some(_), _, None) => return Err(format!("images[{i}] has a bufferView but no mimeType")),
            _ => {}
        }
    }
    for (i, camera) in json.cameras.iter().enumerate() {
        let missing = match camera.type_ {
            Checked::Valid(Type::Perspective) if camera.perspective.is_none() => "perspective",
            Checked::Valid(Type::Orthographic) if camera.orthographic.is_none() => "orthographic",
            _ => continue,
        };
        return Err(format!("cameras[{i}] is of type {missing} but has no `{missing}` object"));
    }
    Ok(())
}

fn empty() -> MeshScene {
    MeshScene {
        vertices: vec![],
        triangles: vec![],
        materials: vec![],
        textures: vec![],
        texels: vec![],
        lighting: Lighting::default(),
        cameras: vec![],
        report: LoadReport::default(),
    }
}

/// A colour from the scene's extras (`"KEY": [r, g, b]`), `None` when absent.
fn extras_colour(scene: &gltf::Scene, key: &str) -> Result<Option<[f32; 3]>> {
    let Some(raw) = scene.extras() else { return Ok(None) };
    let value: serde_json::Value =
        serde_json::from_str(raw.get()).map_err(|e| scene_err(format!("the scene's extras are not valid JSON: {e}")))?;
    let Some(v) = value.get(key) else { return Ok(None) };
    let parsed = v.as_array().filter(|a| a.len() == 3).and_then(|a| {
        let c: Vec<f32> = a.iter().filter_map(|x| x.as_f64()).map(|x| x as f32).filter(|x| x.is_finite() && *x >= 0.0).collect();
        <[f32; 3]>::try_from(c).ok()
    });
    parsed
        .map(Some)
        .ok_or_else(|| scene_err(format!("the scene's extras key `{key}` must be [r, g, b] with finite, non-negative numbers, got {v}")))
}

/// The most bytes an image file referenced by a glTF URI may hold (256 MiB); a larger file is
/// refused before it is read.
pub const MAX_IMAGE_FILE_BYTES: u64 = 256 << 20;

/// Largest vertex coordinate (world space, any axis) a scene may hold: beyond it, products of screen
/// coordinates in the f32 rasteriser overflow and triangles vanish. No real asset comes near it (in
/// millimetres it is a billion kilometres); a scene beyond it is refused, to be scaled down.
pub const MAX_COORDINATE: f32 = 1e12;

/// How much of a file a URI may read.
#[derive(Clone, Copy)]
enum ReadLimit {
    /// A buffer: exactly its declared `byteLength`, from a file at least that long.
    Buffer(u64),
    /// An image: the whole file, at most [`MAX_IMAGE_FILE_BYTES`].
    Image,
}

/// Reads a URI's bytes: a base64 data URI, or a file relative to `base` (percent-decoded).
///
/// A file reference must stay inside `base` (the folder of the .gltf file): absolute paths,
/// `file://` URIs with an absolute path, `..` components that leave the folder and symbolic links
/// whose target lies outside it are refused. Only regular files are read (never directories,
/// FIFOs, devices or sockets), and never more than `limit` allows.
fn read_uri(uri: &str, base: Option<&Path>, what: &str, limit: ReadLimit) -> Result<Vec<u8>> {
    if let Some(rest) = uri.strip_prefix("data:") {
        let (_, data) = rest
            .split_once(";base64,")
            .ok_or_else(|| scene_err(format!("{what} has a data URI that is not base64 (`data:...;base64,...` is required)")))?;
        return base64_decode(data).ok_or_else(|| scene_err(format!("{what} has a data URI with invalid base64")));
    }
    let relative = match uri.strip_prefix("file://").or_else(|| uri.strip_prefix("file:")) {
        Some(p) => percent_decode(p, what)?,
        None if uri.contains(':') => {
            return Err(scene_err(format!(
                "{what} refers to `{uri}`, whose URI scheme is not supported; use a relative file path or a data URI"
            )));
        }
        None => percent_decode(uri, what)?,
    };
    let Some(base) = base else {
        return Err(scene_err(format!(
            "{what} refers to the external file `{uri}`, which cannot be resolved when loading from memory; load the file by path, or embed the data"
        )));
    };
    let path = resolve_inside(base, &relative, uri, what)?;
    read_regular_file(&path, uri, what, limit)
}

/// `relative` joined to `base`, refused unless it stays inside `base`: lexically (no absolute
/// path, no `..` leaving the folder) and, where the file exists, after resolving symbolic links.
fn resolve_inside(base: &Path, relative: &str, uri: &str, what: &str) -> Result<PathBuf> {
    use std::path::Component;
    let outside = |why: &str| {
        scene_err(format!(
            "{what} refers to `{uri}`, {why}; buffer and image references must stay inside the folder of the .gltf file ({})",
            if base.as_os_str().is_empty() { Path::new(".").display() } else { base.display() }
        ))
    };
    let mut inside = PathBuf::new();
    for component in Path::new(relative).components() {
        match component {
            Component::Normal(c) => inside.push(c),
            Component::CurDir => {}
            Component::ParentDir => {
                if !inside.pop() {
                    return Err(outside("whose `..` leaves the folder of the .gltf file"));
                }
            }
            Component::RootDir | Component::Prefix(_) => return Err(outside("which is an absolute path")),
        }
    }
    if inside.as_os_str().is_empty() {
        return Err(outside("which names the folder itself, not a file"));
    }
    let base = if base.as_os_str().is_empty() { Path::new(".") } else { base };
    let path = base.join(&inside);
    // Symbolic links: the file's real location must lie inside the folder's real location. A file
    // that does not exist (yet) is reported as unreadable by the read.
    if let Ok(real) = path.canonicalize() {
        let real_base = base
            .canonicalize()
            .map_err(|e| scene_err(format!("{what}: the folder of the .gltf file ({}) cannot be resolved: {e}", base.display())))?;
        if !real.starts_with(&real_base) {
            return Err(outside(&format!(
                "which resolves (through a symbolic link) to `{}`, outside the folder of the .gltf file",
                real.display()
            )));
        }
    }
    Ok(path)
}

/// Reads a regular file within `limit`; directories, FIFOs, devices and sockets are refused by
/// their metadata before they are opened (so a FIFO cannot block and `/dev/zero` is never read),
/// and again by the opened file's metadata.
fn read_regular_file(path: &Path, uri: &str, what: &str, limit: ReadLimit) -> Result<Vec<u8>> {
    use std::io::Read;
    let unreadable = |e: std::io::Error| {
        scene_err(format!(
            "{what} refers to the file `{uri}` ({}), which cannot be read: {e}; put the file there or fix the URI",
            path.display()
        ))
    };
    let not_regular = || {
        scene_err(format!(
            "{what} refers to `{uri}` ({}), which is not a regular file (a directory, FIFO, device or socket); only regular files are read",
            path.display()
        ))
    };
    if !std::fs::metadata(path).map_err(unreadable)?.file_type().is_file() {
        return Err(not_regular());
    }
    let file = std::fs::File::open(path).map_err(unreadable)?;
    let meta = file.metadata().map_err(unreadable)?;
    if !meta.file_type().is_file() {
        return Err(not_regular());
    }
    let len = meta.len();
    // A buffer needs at least its byteLength and reads exactly that; an image reads the whole file,
    // at most the maximum (one byte more tells a file that grew past it after the check).
    let (need, take) = match limit {
        ReadLimit::Buffer(byte_length) => (byte_length, byte_length),
        ReadLimit::Image => (0, MAX_IMAGE_FILE_BYTES + 1),
    };
    let short = |got: u64| {
        scene_err(format!(
            "{what} refers to the file `{uri}` ({}), which holds {got} bytes, fewer than the buffer's byteLength of {need}; the file is truncated or its byteLength is wrong",
            path.display()
        ))
    };
    let too_large = || {
        scene_err(format!(
            "{what} refers to the file `{uri}` ({}), which holds more than {MAX_IMAGE_FILE_BYTES} bytes (256 MiB), the largest image file read",
            path.display()
        ))
    };
    if len < need {
        return Err(short(len));
    }
    if matches!(limit, ReadLimit::Image) && len >= take {
        return Err(too_large());
    }
    let mut data = Vec::with_capacity(len.min(take) as usize);
    file.take(take).read_to_end(&mut data).map_err(unreadable)?;
    let got = data.len() as u64;
    if got < need {
        return Err(short(got));
    }
    if got >= take && matches!(limit, ReadLimit::Image) {
        return Err(too_large());
    }
    Ok(data)
}

fn percent_decode(s: &str, what: &str) -> Result<String> {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'%' {
            let hex = s.get(i + 1..i + 3).and_then(|h| u8::from_str_radix(h, 16).ok());
            let byte = hex.ok_or_else(|| scene_err(format!("{what} has a URI with a bad percent escape: `{s}`")))?;
            out.push(byte);
            i += 3;
        } else {
            out.push(b[i]);
            i += 1;
        }
    }
    String::from_utf8(out).map_err(|_| scene_err(format!("{what} has a URI that does not decode to UTF-8: `{s}`")))
}

/// Standard base64 (padding optional); `None` on any other character.
fn base64_decode(s: &str) -> Option<Vec<u8>> {
    let value = |c: u8| match c {
        b'A'..=b'Z' => Some(c - b'A'),
        b'a'..=b'z' => Some(c - b'a' + 26),
        b'0'..=b'9' => Some(c - b'0' + 52),
        b'+' => Some(62),
        b'/' => Some(63),
        _ => None,
    };
    let s = s.trim_end_matches('=').as_bytes();
    let mut out = Vec::with_capacity(s.len() * 3 / 4);
    let (mut acc, mut bits) = (0u32, 0u32);
    for &c in s {
        acc = (acc << 6) | value(c)? as u32;
        bits += 6;
        if bits >= 8 {
            bits -= 8;
            out.push((acc >> bits) as u8);
            acc &= (1 << bits) - 1;
        }
    }
    Some(out)
}

fn read_buffers(doc: &gltf::Document, base: Option<&Path>, mut blob: Option<Vec<u8>>) -> Result<Vec<Vec<u8>>> {
    let mut out = Vec::new();
    for buffer in doc.buffers() {
        let what = format!("buffer {}", buffer.index());
        let data = match buffer.source() {
            gltf::buffer::Source::Bin => {
                blob.take().ok_or_else(|| scene_err(format!("{what} refers to the binary chunk, but the file has none")))?
            }
            gltf::buffer::Source::Uri(uri) => read_uri(uri, base, &what, ReadLimit::Buffer(buffer.length() as u64))?,
        };
        if data.len() < buffer.length() {
            return Err(scene_err(format!(
                "{what} holds {} bytes but declares {}; the file is truncated or its byteLength is wrong",
                data.len(),
                buffer.length()
            )));
        }
        out.push(data);
    }
    Ok(out)
}

/// Checks that an accessor can be read as one of `allowed` without running past its data.
fn check_accessor(acc: &gltf::Accessor, what: &str, allowed: &[(DataType, Dimensions)], buffers: &[Vec<u8>]) -> Result<()> {
    let bad = |why: String| Err(scene_err(format!("{what} (accessor {}): {why}", acc.index())));
    if !allowed.iter().any(|&(t, d)| t == acc.data_type() && d == acc.dimensions()) {
        return bad(format!("has type {:?} {:?}, expected one of {allowed:?}", acc.data_type(), acc.dimensions()));
    }
    if acc.sparse().is_some() {
        return bad("is sparse; sparse accessors are not supported, write the data densely".into());
    }
    if acc.count() == 0 {
        return bad("has count 0; an accessor needs at least one element".into());
    }
    let Some(view) = acc.view() else { return bad("has no buffer view (all-zero accessors are not supported)".into()) };
    let size = acc.size();
    let stride = view.stride().unwrap_or(size);
    if stride < size {
        return bad(format!("has byte stride {stride}, smaller than its element size {size}"));
    }
    let end = (acc.count() - 1).checked_mul(stride).and_then(|x| x.checked_add(size)).and_then(|x| x.checked_add(acc.offset()));
    let view_end = view.offset().checked_add(view.length());
    let buffer_len = buffers.get(view.buffer().index()).map_or(0, Vec::len);
    match (end, view_end) {
        (Some(end), Some(view_end)) if end <= view.length() && view_end <= buffer_len => Ok(()),
        _ => bad(format!("runs past its buffer view {} or the view past its buffer; the file is truncated or malformed", view.index())),
    }
}

struct Loader<'a> {
    doc: &'a gltf::Document,
    base: Option<&'a Path>,
    buffers: Vec<Vec<u8>>,
    /// (image, sRGB) → offset of its texels, width, height.
    images: HashMap<(usize, bool), (u32, u32, u32)>,
    /// (image, sRGB, sampler bits) → texture index.
    textures: HashMap<(usize, bool, u32), u32>,
    /// glTF material index (`None`: the default material) → material index.
    materials: HashMap<Option<usize>, u32>,
    out: MeshScene,
}

impl Loader<'_> {
    fn mesh(&mut self, mesh: &gltf::Mesh, world: &Mat4) -> Result<()> {
        let name = match mesh.name() {
            Some(n) => format!("mesh {} (`{n}`)", mesh.index()),
            None => format!("mesh {}", mesh.index()),
        };
        let linear = Mat3::from_mat4(*world);
        let normal_matrix = linear.inverse().transpose();
        let mirrored = linear.determinant() < 0.0;
        for prim in mesh.primitives() {
            let what = format!("{name} primitive {}", prim.index());
            let mode = prim.mode();
            if matches!(mode, Mode::Points | Mode::Lines | Mode::LineLoop | Mode::LineStrip) {
                self.out.report.skipped_primitives += 1;
                continue;
            }
            let bufs = &self.buffers;
            let reader = prim.reader(|b| bufs.get(b.index()).map(Vec::as_slice));
            let pos_acc = prim.get(&gltf::Semantic::Positions).ok_or_else(|| scene_err(format!("{what} has no POSITION attribute")))?;
            check_accessor(&pos_acc, &format!("{what} POSITION"), &[(DataType::F32, Dimensions::Vec3)], bufs)?;
            let positions: Vec<[f32; 3]> = reader.read_positions().map(|p| p.collect()).unwrap_or_default();
            let n = positions.len();
            let has_normals = prim.get(&gltf::Semantic::Normals).is_some();
            let normals: Vec<[f32; 3]> = match prim.get(&gltf::Semantic::Normals) {
                Some(acc) => {
                    check_accessor(&acc, &format!("{what} NORMAL"), &[(DataType::F32, Dimensions::Vec3)], bufs)?;
                    reader.read_normals().map(|p| p.collect()).unwrap_or_default()
                }
                None => vec![[0.0; 3]; n],
            };
            // The coordinates its textures read: one set and transform for the primitive, baked
            // into its vertices.
            let mapping = UvMapping::of(&prim.material());
            // Vertex colours (`COLOR_0`, linear), multiplying the base colour; white without.
            let colors: Vec<[u32; 2]> = match prim.get(&gltf::Semantic::Colors(0)) {
                Some(acc) => {
                    let ok = [DataType::F32, DataType::U8, DataType::U16]
                        .into_iter()
                        .flat_map(|t| [(t, Dimensions::Vec3), (t, Dimensions::Vec4)]);
                    check_accessor(&acc, &format!("{what} COLOR_0"), &ok.collect::<Vec<_>>(), bufs)?;
                    let raw: Vec<[f32; 4]> = reader.read_colors(0).map(|c| c.into_rgba_f32().collect()).unwrap_or_default();
                    if let Some(k) = raw.iter().position(|c| !c.iter().all(|x| x.is_finite())) {
                        return Err(scene_err(format!("{what} COLOR_0: vertex {k} has a non-finite colour {:?}", raw[k])));
                    }
                    raw.iter().map(|&c| vertex_color(c)).collect()
                }
                None => vec![WHITE_HALVES; n],
            };
            if mapping.mixed {
                self.out.report.mixed_texture_coordinates += 1;
            }
            let set = mapping.set;
            let uvs: Vec<[f32; 2]> = match prim.get(&gltf::Semantic::TexCoords(set)) {
                Some(acc) => {
                    let ok = [(DataType::F32, Dimensions::Vec2), (DataType::U8, Dimensions::Vec2), (DataType::U16, Dimensions::Vec2)];
                    check_accessor(&acc, &format!("{what} TEXCOORD_{set}"), &ok, bufs)?;
                    let raw = reader.read_tex_coords(set).map(|t| t.into_f32().collect::<Vec<_>>()).unwrap_or_default();
                    raw.into_iter().map(|uv| mapping.apply(uv)).collect()
                }
                None => {
                    self.out.report.missing_texture_coordinates += mapping.textured as u64 * (set != 0) as u64;
                    vec![[0.0; 2]; n]
                }
            };
            if normals.len() != n || uvs.len() != n || colors.len() != n {
                return Err(scene_err(format!("{what}: NORMAL, TEXCOORD_{set} or COLOR_0 has a different count than POSITION ({n})")));
            }
            let indices: Vec<u32> = match prim.indices() {
                Some(acc) => {
                    let ok = [(DataType::U8, Dimensions::Scalar), (DataType::U16, Dimensions::Scalar), (DataType::U32, Dimensions::Scalar)];
                    check_accessor(&acc, &format!("{what} indices"), &ok, bufs)?;
                    reader.read_indices().map(|i| i.into_u32().collect()).unwrap_or_default()
                }
                None => (0..n as u32).collect(),
            };
            if let Some(&bad) = indices.iter().find(|&&i| i as usize >= n) {
                return Err(scene_err(format!("{what}: index {bad} is out of range; the primitive has {n} vertices")));
            }
            let finite = positions.iter().chain(&normals).flatten().chain(uvs.iter().flatten()).all(|x| x.is_finite());
            if !finite {
                return Err(scene_err(format!("{what}: non-finite (NaN or infinite) position, normal or texture coordinate")));
            }
            let material = self.material(prim.material())?;

            let mut world_positions = Vec::with_capacity(n);
            for p in &positions {
                let p = world.transform_point3(Vec3::from(*p));
                if !p.is_finite() {
                    return Err(scene_err(format!("{what}: a vertex is not finite after its node's transform")));
                }
                if p.abs().max_element() > MAX_COORDINATE {
                    return Err(scene_err(format!(
                        "{what}: a vertex lies at ({:e}, {:e}, {:e}), beyond ±{MAX_COORDINATE:e} units, where rasterising in f32 \
                         loses triangles; scale the scene down (its units are free)",
                        p.x, p.y, p.z
                    )));
                }
                world_positions.push(p);
            }
            let mut tris = Vec::new();
            match mode {
                Mode::Triangles => {
                    if !indices.len().is_multiple_of(3) {
                        return Err(scene_err(format!("{what}: {} indices is not a multiple of 3 for a triangle list", indices.len())));
                    }
                    tris.extend(indices.as_chunks::<3>().0.iter().map(|c| [c[0], c[1], c[2]]));
                }
                // glTF's strip order: every odd triangle swaps its last two vertices to keep the winding.
                Mode::TriangleStrip => {
                    for i in 0..indices.len().saturating_sub(2) {
                        let (a, b, c) = (indices[i], indices[i + 1], indices[i + 2]);
                        tris.push(if i % 2 == 0 { [a, b, c] } else { [a, c, b] });
                    }
                }
                Mode::TriangleFan => {
                    for i in 1..indices.len().saturating_sub(1) {
                        tris.push([indices[i], indices[i + 1], indices[0]]);
                    }
                }
                _ => {}
            }
            // Without normals a primitive is flat-shaded: each triangle gets its own corners with its
            // face normal, computed here in f64 (the kernels' f32 cross product of long edges
            // overflows when squared).
            let flat = !has_normals;
            let first = self.out.vertices.len();
            let added = if flat { 3 * tris.len() } else { n };
            if first + added > u32::MAX as usize {
                return Err(Error::Core(CoreError::TooLarge {
                    what: "vertices of the scene".into(),
                    size: (first + added) as u64,
                    limit: u32::MAX as u64,
                }));
            }
            let vertex = |k: usize, normal: [f32; 3]| MeshVertex {
                position: world_positions[k].to_array(),
                u: uvs[k][0],
                normal,
                v: uvs[k][1],
                color: colors[k],
            };
            if !flat {
                for k in 0..n {
                    let nrm = (normal_matrix * Vec3::from(normals[k])).normalize_or_zero();
                    self.out.vertices.push(vertex(k, nrm.to_array()));
                }
            }
            for [a, b, c] in tris {
                let (b, c) = if mirrored { (c, b) } else { (b, c) };
                let v = |i: u32| world_positions[i as usize];
                if a == b || b == c || a == c || zero_area(v(a), v(b), v(c)) {
                    self.out.report.degenerate_triangles += 1;
                    continue;
                }
                let corners = if flat {
                    let (p0, p1, p2) = (v(a).as_dvec3(), v(b).as_dvec3(), v(c).as_dvec3());
                    let normal = (p1 - p0).cross(p2 - p0).normalize_or_zero().as_vec3().to_array();
                    let at = self.out.vertices.len() as u32;
                    for k in [a, b, c] {
                        self.out.vertices.push(vertex(k as usize, normal));
                    }
                    [at, at + 1, at + 2]
                } else {
                    let f = first as u32;
                    [f + a, f + b, f + c]
                };
                self.out.triangles.push([corners[0], corners[1], corners[2], material]);
            }
            if self.out.triangles.len() as u64 > MAX_TRIANGLES {
                return Err(Error::Core(CoreError::TooLarge {
                    what: "triangles of the scene".into(),
                    size: self.out.triangles.len() as u64,
                    limit: MAX_TRIANGLES,
                }));
            }
        }
        Ok(())
    }

    fn camera(&mut self, camera: &gltf::Camera, world: &Mat4) {
        match camera.projection() {
            gltf::camera::Projection::Perspective(p) => self.out.cameras.push(MeshCamera {
                name: camera.name().map(str::to_owned),
                eye: world.transform_point3(Vec3::ZERO),
                forward: world.transform_vector3(Vec3::NEG_Z).normalize_or_zero(),
                up: world.transform_vector3(Vec3::Y).normalize_or_zero(),
                yfov_radians: p.yfov(),
                aspect_ratio: p.aspect_ratio(),
                znear: p.znear(),
            }),
            gltf::camera::Projection::Orthographic(_) => self.out.report.orthographic_cameras += 1,
        }
    }

    /// The index of the material, converting it on first use.
    fn material(&mut self, m: gltf::Material) -> Result<u32> {
        if let Some(&i) = self.materials.get(&m.index()) {
            return Ok(i);
        }
        let what = match m.index() {
            Some(i) => format!("material {i}"),
            None => "the default material".to_owned(),
        };
        let pbr = m.pbr_metallic_roughness();
        let strength = m.emissive_strength().unwrap_or(1.0);
        let mut mat = MeshMaterial {
            base: pbr.base_color_factor(),
            emissive: m.emissive_factor().map(|e| e * strength),
            alpha_cutoff: m.alpha_cutoff().unwrap_or(0.5),
            ..MeshMaterial::default()
        };
        if !mat.base.iter().chain(&mat.emissive).all(|x| x.is_finite() && *x >= 0.0) || !mat.alpha_cutoff.is_finite() {
            return Err(scene_err(format!("{what}: colour factors and emissive strength must be finite and not negative")));
        }
        // Colours above the numerical contract's 2^100 are taken as 2^100, so that shading and
        // summing sub-samples stay finite.
        let [r, g, b] = in_contract([mat.base[0], mat.base[1], mat.base[2]]);
        mat.base = [r, g, b, mat.base[3]];
        mat.emissive = in_contract(mat.emissive);
        if let Some(info) = pbr.base_color_texture() {
            mat.base_texture = self.texture(&info, true, &what)?;
        }
        if let Some(info) = m.emissive_texture() {
            mat.emissive_texture = self.texture(&info, true, &what)?;
        }
        if m.unlit() {
            mat.flags |= UNLIT;
        }
        if m.double_sided() {
            mat.flags |= DOUBLE_SIDED;
        }
        match m.alpha_mode() {
            gltf::material::AlphaMode::Mask => mat.flags |= ALPHA_MASK,
            gltf::material::AlphaMode::Blend => mat.flags |= ALPHA_BLEND,
            gltf::material::AlphaMode::Opaque => {}
        }
        let index = self.out.materials.len() as u32;
        self.out.materials.push(mat);
        self.materials.insert(m.index(), index);
        Ok(index)
    }

    /// The texture index for a material's texture reference, decoding its image on first use.
    fn texture(&mut self, info: &gltf::texture::Info, srgb: bool, what: &str) -> Result<u32> {
        let texture = info.texture();
        let sampler = texture.sampler();
        let wrap = |w: gltf::texture::WrappingMode| match w {
            gltf::texture::WrappingMode::Repeat => WRAP_REPEAT,
            gltf::texture::WrappingMode::ClampToEdge => WRAP_CLAMP,
            gltf::texture::WrappingMode::MirroredRepeat => WRAP_MIRROR,
        };
        let mut bits = (wrap(sampler.wrap_s()) << WRAP_S_SHIFT) | (wrap(sampler.wrap_t()) << WRAP_T_SHIFT);
        if sampler.mag_filter() == Some(gltf::texture::MagFilter::Nearest) {
            bits |= NEAREST;
        }
        let image = texture.source().index();
        if let Some(&t) = self.textures.get(&(image, srgb, bits)) {
            return Ok(t);
        }
        let (offset, width, height) = match self.images.get(&(image, srgb)) {
            Some(&found) => found,
            None => {
                let found = self.decode_image(image, srgb, &format!("{what} texture {}", texture.index()))?;
                self.images.insert((image, srgb), found);
                found
            }
        };
        let index = self.out.textures.len() as u32;
        self.out.textures.push(TextureInfo { offset, width, height, sampler: bits });
        self.textures.insert((image, srgb, bits), index);
        Ok(index)
    }

    /// Decodes an image to linear RGBA f32 appended to the texels (sRGB colour channels decoded when
    /// `srgb`; alpha always linear); returns offset, width and height.
    fn decode_image(&mut self, index: usize, srgb: bool, what: &str) -> Result<(u32, u32, u32)> {
        let image = self.doc.images().nth(index).ok_or_else(|| scene_err(format!("{what}: image {index} does not exist")))?;
        let what = format!("{what} image {index}");
        let (bytes, mime) = match image.source() {
            gltf::image::Source::View { view, mime_type } => {
                let data =
                    self.buffers.get(view.buffer().index()).and_then(|b| b.get(view.offset()..view.offset().checked_add(view.length())?));
                let data = data.ok_or_else(|| scene_err(format!("{what}: its buffer view runs past its buffer")))?;
                (data.to_vec(), Some(mime_type))
            }
            gltf::image::Source::Uri { uri, mime_type } => (read_uri(uri, self.base, &what, ReadLimit::Image)?, mime_type),
        };
        let format = match mime {
            Some("image/png") => Some(image::ImageFormat::Png),
            Some("image/jpeg") => Some(image::ImageFormat::Jpeg),
            _ => None,
        };
        let undecodable = |e: image::ImageError| scene_err(format!("{what} cannot be decoded ({e}); glTF images must be PNG or JPEG"));
        let mut reader = image::ImageReader::new(std::io::Cursor::new(&bytes));
        match format {
            Some(f) => reader.set_format(f),
            None => reader = reader.with_guessed_format().map_err(|e| scene_err(format!("{what} cannot be read ({e})")))?,
        }
        // The size from the header, before decoding anything: a texture beyond the texel budget
        // is refused without allocating it.
        let (width, height) = reader.into_dimensions().map_err(undecodable)?;
        let offset = self.out.texels.len() as u64;
        let total = offset + width as u64 * height as u64;
        if total > MAX_TEXELS {
            return Err(Error::Core(CoreError::TooLarge {
                what: format!("texels of all textures ({what} is {width}x{height}; scale the textures down)"),
                size: total,
                limit: MAX_TEXELS,
            }));
        }
        let decoded = match format {
            Some(f) => image::load_from_memory_with_format(&bytes, f),
            None => image::load_from_memory(&bytes),
        }
        .map_err(undecodable)?;
        let rgba = decoded.to_rgba32f();
        self.out.texels.extend(rgba.pixels().map(|p| {
            let [r, g, b, a] = p.0;
            if srgb { [srgb_to_linear(r), srgb_to_linear(g), srgb_to_linear(b), a] } else { [r, g, b, a] }
        }));
        Ok((offset as u32, width, height))
    }
}

/// A vertex colour as the rasteriser stores it: linear RGBA, clamped to [0, 1] (glTF's range), as
/// half floats.
fn vertex_color(c: [f32; 4]) -> [u32; 2] {
    super::mesh::pack_halves(c.map(|x| x.clamp(0.0, 1.0)))
}

/// The sRGB transfer function's inverse.
fn srgb_to_linear(s: f32) -> f32 {
    if s <= 0.040_45 { s / 12.92 } else { ((s + 0.055) / 1.055).powf(2.4) }
}

/// The texture coordinates a material's textures read: a set (`TEXCOORD_n`) and a
/// `KHR_texture_transform` (offset, rotation, scale), the base colour texture's, else the emissive
/// texture's. The rasteriser reads one set a vertex, so a primitive's coordinates are these, with
/// the transform applied; `mixed` when its two textures ask for different ones.
struct UvMapping {
    set: u32,
    /// `uv' = [m0 m1 m2; m3 m4 m5] · (u, v, 1)`.
    matrix: [f32; 6],
    textured: bool,
    mixed: bool,
}

impl UvMapping {
    fn of(material: &gltf::Material) -> UvMapping {
        let pbr = material.pbr_metallic_roughness();
        let infos: Vec<gltf::texture::Info> = [pbr.base_color_texture(), material.emissive_texture()].into_iter().flatten().collect();
        let one = |info: &gltf::texture::Info| -> (u32, [f32; 6]) {
            match info.texture_transform() {
                Some(t) => {
                    let ([ox, oy], r, [sx, sy]) = (t.offset(), t.rotation(), t.scale());
                    let (c, s) = (r.cos(), r.sin());
                    // Translation · rotation · scale, as the extension's GLSL defines it (column-major:
                    // the rotation's first column is (cos, sin)).
                    (t.tex_coord().unwrap_or(info.tex_coord()), [c * sx, -s * sy, ox, s * sx, c * sy, oy])
                }
                None => (info.tex_coord(), [1.0, 0.0, 0.0, 0.0, 1.0, 0.0]),
            }
        };
        let mappings: Vec<(u32, [f32; 6])> = infos.iter().map(one).collect();
        let (set, matrix) = mappings.first().copied().unwrap_or((0, [1.0, 0.0, 0.0, 0.0, 1.0, 0.0]));
        UvMapping { set, matrix, textured: !mappings.is_empty(), mixed: mappings.iter().any(|m| *m != (set, matrix)) }
    }

    fn apply(&self, [u, v]: [f32; 2]) -> [f32; 2] {
        let m = self.matrix;
        [m[0] * u + m[1] * v + m[2], m[3] * u + m[4] * v + m[5]]
    }
}
