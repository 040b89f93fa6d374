//! glTF in and out: analytic scenes exported as GLB load back with the same geometry, camera,
//! lighting and materials; hand-written files check node transforms, winding, strips and fans,
//! dropped triangles; bad input gets an error naming what is wrong, never a panic.

use std::path::PathBuf;
use std::sync::atomic::{AtomicU32, Ordering};

use dof::scene::gltf_export::sphere_segments;
use dof::scene::{
    Albedo, CameraFrame, ExportOptions, Material, MeshCamera, MeshScene, Shape, Vec3, builtin, builtin_names, export_builtin_glb,
    export_glb, load_gltf, load_gltf_slice,
};
use dof::{CoreError, Error};
use dof_shaders::raster::mesh::{DOUBLE_SIDED, NEAREST, NO_TEXTURE, WRAP_S_SHIFT, WRAP_T_SHIFT};
use serde_json::{Value, json};

const W: u32 = 320;
const H: u32 = 180;

fn close(a: Vec3, b: Vec3, tol: f32) -> bool {
    (a - b).abs().max_element() <= tol
}

/// Triangles the exporter makes for a shape with the default options.
/// Triangles the exporter makes of `shape` seen through `frame`: a UV sphere of `n` longitude
/// segments has `n · (n − 2)` (its pole rows lose the zero-area triangles), where `n` follows the
/// sphere's projected size: 96 for a large one, 32 for a pixel-sized one.
fn expected_triangles(shape: &Shape, frame: &CameraFrame) -> usize {
    match *shape {
        Shape::Sphere { center, radius } => {
            let n = sphere_segments(center, radius, frame, &ExportOptions::default()) as usize;
            assert!((32..=96).contains(&n) && n.is_multiple_of(2), "{n} segments");
            n * (n - 2)
        }
        Shape::Cuboid { .. } => 12,
        Shape::Quad { .. } | Shape::Plane { .. } => 2,
    }
}

fn load_builtin(name: &str) -> MeshScene {
    let glb = export_builtin_glb(name, W, H).unwrap();
    load_gltf_slice(&glb).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Expectation: every built-in scene comes back with the expected triangle count, one material
/// per primitive (open surfaces double-sided, spheres and boxes single-sided, emission kept even above 65504, checkers as 2x2 nearest/repeat
/// textures decoding to the albedo within 1e-4), the camera (eye, view axis within 1e-4, field of
/// view, aspect ratio) and the lighting; nothing dropped.
#[test]
fn builtin_scenes_round_trip() {
    for &name in builtin_names() {
        let b = builtin(name).unwrap().with_size(W, H);
        let m = load_builtin(name);
        assert!(m.report.is_clean(), "{name}: {:?}", m.report);
        let prims = b.scene.primitives();
        let frame = b.camera.frame().unwrap();
        assert_eq!(m.triangles.len(), prims.iter().map(|p| expected_triangles(&p.shape, &frame)).sum::<usize>(), "{name}");
        assert_eq!(m.materials.len(), prims.len(), "{name}");
        m.validate().unwrap();

        assert_eq!(m.cameras.len(), 1, "{name}");
        let cam = &m.cameras[0];
        assert!(close(cam.eye, b.camera.eye, 1e-4), "{name}: eye {} vs {}", cam.eye, b.camera.eye);
        let forward = (b.camera.target - b.camera.eye).normalize();
        assert!(close(cam.forward, forward, 1e-4), "{name}: forward {} vs {forward}", cam.forward);
        assert!((cam.yfov_radians - b.camera.yfov_radians).abs() < 1e-6, "{name}");
        assert!((cam.aspect_ratio.unwrap() - W as f32 / H as f32).abs() < 1e-6, "{name}");
        let back = cam.camera(W, H).unwrap();
        let (f0, f1) = (back.frame().unwrap(), b.camera.frame().unwrap());
        assert!(close(f0.up, f1.up, 1e-4) && close(f0.right, f1.right, 1e-4), "{name}: camera basis differs");

        let l = b.scene.lighting();
        assert!(close(m.lighting.direction, l.direction.normalize(), 1e-5), "{name}: light direction");
        for k in 0..3 {
            assert!((m.lighting.color[k] - l.color[k]).abs() <= 1e-5, "{name}: light colour");
            assert_eq!(m.lighting.ambient[k], l.ambient[k], "{name}: ambient");
        }

        for (i, (p, mat)) in prims.iter().zip(&m.materials).enumerate() {
            let closed = matches!(p.shape, Shape::Sphere { .. } | Shape::Cuboid { .. });
            assert_eq!(mat.flags & DOUBLE_SIDED == 0, closed, "{name}: material {i}: closed shapes single-sided, open ones double-sided");
            match p.material {
                Material::Emissive(c) => {
                    for k in 0..3 {
                        assert!((mat.emissive[k] - c[k]).abs() <= 1e-5 * c[k].max(1.0), "{name}: emission {:?} vs {c:?}", mat.emissive);
                    }
                    assert_eq!(&mat.base[..3], &[0.0; 3]);
                }
                Material::Diffuse(Albedo::Solid(c)) => assert_eq!(mat.base, [c[0], c[1], c[2], 1.0], "{name}"),
                Material::Diffuse(Albedo::Checker { a, b: bb, .. }) => {
                    assert_ne!(mat.base_texture, NO_TEXTURE, "{name}");
                    let t = m.textures[mat.base_texture as usize];
                    assert_eq!((t.width, t.height), (2, 2));
                    assert_eq!(t.sampler, NEAREST | (0 << WRAP_S_SHIFT) | (0 << WRAP_T_SHIFT), "nearest, repeat");
                    let texels = &m.texels[t.offset as usize..t.offset as usize + 4];
                    for (texel, want) in texels.iter().zip([a, bb, bb, a]) {
                        for k in 0..3 {
                            assert!((texel[k] - want[k]).abs() <= 1e-4, "{name}: texel {texel:?} vs {want:?}");
                        }
                        assert_eq!(texel[3], 1.0);
                    }
                }
            }
        }
    }
    // Emission above the half-float range survives.
    let m = load_builtin("highlights");
    assert!(m.materials.iter().any(|mat| mat.emissive.iter().any(|&e| e > 65504.0)));
}

/// Expectation: on the `railing` floor (a checker plane), the loaded mesh's interpolated texture
/// coordinates pick the same checker colour the analytic scene shades at every pixel ray's hit
/// (up to 0.5% of the samples, those at cell edges).
#[test]
fn checker_parity_matches_the_analytic_scene() {
    let b = builtin("railing").unwrap().with_size(W, H);
    let m = load_builtin("railing");
    let frame = b.camera.frame().unwrap();
    let floor_tris: Vec<_> = m.triangles.iter().filter(|t| t[3] == 0).collect();
    assert_eq!(floor_tris.len(), 2);
    let t = m.textures[m.materials[0].base_texture as usize];
    let (mut tested, mut wrong) = (0, 0);
    for y in (0..H).step_by(3) {
        for x in (0..W).step_by(3) {
            let ray = frame.pixel_ray(x, y);
            let Some(hit) = b.scene.first_hit(&ray, 0.0) else { continue };
            if hit.primitive != 0 {
                continue;
            }
            let p = ray.at(hit.t);
            let want = b.scene.shade(&ray, &hit);
            // The triangle holding p and its interpolated texture coordinates.
            let uv = floor_tris.iter().find_map(|tri| {
                let v: Vec<_> = tri[..3].iter().map(|&i| m.vertices[i as usize]).collect();
                let (p0, p1, p2) = (Vec3::from(v[0].position), Vec3::from(v[1].position), Vec3::from(v[2].position));
                let n = (p1 - p0).cross(p2 - p0);
                let area = n.length_squared();
                let w1 = (p - p0).cross(p2 - p0).dot(n) / area;
                let w2 = (p1 - p0).cross(p - p0).dot(n) / area;
                let w0 = 1.0 - w1 - w2;
                (w0 >= 0.0 && w1 >= 0.0 && w2 >= 0.0)
                    .then(|| (w0 * v[0].u + w1 * v[1].u + w2 * v[2].u, w0 * v[0].v + w1 * v[1].v + w2 * v[2].v))
            });
            let (u, v) = uv.expect("the hit lies on the exported floor");
            let (tx, ty) = (((u - u.floor()) * 2.0) as u32 % 2, ((v - v.floor()) * 2.0) as u32 % 2);
            let albedo = m.texels[(t.offset + ty * 2 + tx) as usize];
            let l = &m.lighting;
            let n = Vec3::Y;
            let lambert = n.dot(l.direction).max(0.0);
            let got: Vec<f32> = (0..3).map(|k| albedo[k] * (l.ambient[k] + l.color[k] * lambert)).collect();
            tested += 1;
            if (0..3).any(|k| (got[k] - want[k]).abs() > 1e-3) {
                wrong += 1;
            }
        }
    }
    assert!(tested > 1000, "{tested} floor samples");
    assert!(wrong * 200 <= tested, "{wrong} of {tested} floor samples pick the other checker colour");
}

/// Expectation: the exported GLB also loads from a file path, giving the same scene.
#[test]
fn glb_file_loads_by_path() {
    let glb = export_builtin_glb("simple", W, H).unwrap();
    let path = temp_path("simple.glb");
    std::fs::write(&path, &glb).unwrap();
    let from_file = load_gltf(&path).unwrap();
    let _ = std::fs::remove_file(&path);
    assert_eq!(from_file, load_gltf_slice(&glb).unwrap());
}

/// Expectation: more sphere segments give more triangles, and invalid options are errors.
#[test]
fn export_options_are_checked() {
    let b = builtin("simple").unwrap();
    let opts = ExportOptions { sphere_segments: 8, plane_half_extent: 10.0 };
    let m = load_gltf_slice(&export_glb(&b.scene, &b.camera, &opts).unwrap()).unwrap();
    assert_eq!(m.triangles.len(), 2 + 8 * 6 + 2);
    // The plane's square is centred at the eye's projection with the given half-extent.
    let (lo, hi) = m.bounds().unwrap();
    assert!(lo.x <= -10.0 + 1e-4 && hi.x >= 10.0 - 1e-4 && hi.x <= 10.0 + 1e-4);
    for bad in [
        ExportOptions { sphere_segments: 3, ..opts },
        ExportOptions { plane_half_extent: 0.0, ..opts },
        ExportOptions { plane_half_extent: f32::NAN, ..opts },
    ] {
        assert!(matches!(export_glb(&b.scene, &b.camera, &bad), Err(dof::Error::Core(CoreError::InvalidArgument(_)))));
    }
}

// ---- hand-written files ----

fn base64(bytes: &[u8]) -> String {
    const A: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut s = String::new();
    for c in bytes.chunks(3) {
        let n = (c[0] as u32) << 16 | (*c.get(1).unwrap_or(&0) as u32) << 8 | *c.get(2).unwrap_or(&0) as u32;
        for k in 0..4 {
            if k <= c.len() {
                s.push(A[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                s.push('=');
            }
        }
    }
    s
}

/// A glTF JSON document with one mesh of one primitive: `positions` (and optional `normals`,
/// `indices`) in one buffer given by `buffer_uri` (a data URI when `None`), the `mode`, and the
/// given nodes (mesh 0 on whichever node names it).
fn document(positions: &[[f32; 3]], normals: Option<&[[f32; 3]]>, indices: Option<&[u32]>, mode: u32, nodes: Value) -> (Value, Vec<u8>) {
    let mut bin = Vec::new();
    let mut views = vec![];
    let mut accessors = vec![];
    let mut attributes = json!({});
    let mut add = |data: Vec<u8>, count: usize, ty: &str, component: u32| {
        views.push(json!({ "buffer": 0, "byteOffset": bin.len(), "byteLength": data.len() }));
        bin.extend(data);
        accessors.push(json!({ "bufferView": views.len() - 1, "componentType": component, "count": count, "type": ty }));
        accessors.len() - 1
    };
    let f = |v: &[[f32; 3]]| v.iter().flatten().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    attributes["POSITION"] = json!(add(f(positions), positions.len(), "VEC3", 5126));
    // glTF requires bounds on positions (NaN left out: f32::min/max ignore it).
    let lo = positions.iter().fold([f32::MAX; 3], |a, p| [0, 1, 2].map(|k| a[k].min(p[k])));
    let hi = positions.iter().fold([f32::MIN; 3], |a, p| [0, 1, 2].map(|k| a[k].max(p[k])));
    if let Some(n) = normals {
        attributes["NORMAL"] = json!(add(f(n), n.len(), "VEC3", 5126));
    }
    let mut prim = json!({ "attributes": attributes, "mode": mode });
    if let Some(i) = indices {
        prim["indices"] = json!(add(i.iter().flat_map(|x| x.to_le_bytes()).collect(), i.len(), "SCALAR", 5125));
    }
    accessors[0]["min"] = json!(lo);
    accessors[0]["max"] = json!(hi);
    let node_count = nodes.as_array().unwrap().len();
    let doc = json!({
        "asset": { "version": "2.0" },
        "scene": 0,
        "scenes": [{ "nodes": [0] }],
        "nodes": nodes,
        "meshes": [{ "name": "test mesh", "primitives": [prim] }],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{ "byteLength": bin.len(), "uri": format!("data:application/octet-stream;base64,{}", base64(&bin)) }],
    });
    assert!(node_count > 0);
    (doc, bin)
}

fn load_doc(doc: &Value) -> dof::error::Result<MeshScene> {
    load_gltf_slice(&serde_json::to_vec(doc).unwrap())
}

fn temp_path(name: &str) -> PathBuf {
    static N: AtomicU32 = AtomicU32::new(0);
    std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "dof-gltf-test-{}-{}-{name}",
        std::process::id(),
        N.fetch_add(1, Ordering::Relaxed)
    ))
}

const TRIANGLE: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
const UP: [[f32; 3]; 3] = [[0.0, 0.0, 1.0]; 3];

fn face_normal(m: &MeshScene, t: usize) -> Vec3 {
    let p = |k: usize| Vec3::from(m.vertices[m.triangles[t][k] as usize].position);
    (p(1) - p(0)).cross(p(2) - p(0))
}

/// Expectation: a child (rotated 90° about Z, scaled 2) under a parent translated by (10, 0, 0)
/// puts (1,0,0) at (10,2,0) and (0,1,0) at (8,0,0), keeps the normal +Z and unit length, and the
/// file's default material is glTF's default (white, single-sided).
#[test]
fn node_hierarchy_gives_world_positions() {
    let h = std::f32::consts::FRAC_1_SQRT_2;
    let nodes = json!([
        { "translation": [10.0, 0.0, 0.0], "children": [1] },
        { "rotation": [0.0, 0.0, h, h], "scale": [2.0, 2.0, 2.0], "mesh": 0 },
    ]);
    let (doc, _) = document(&TRIANGLE, Some(&UP), None, 4, nodes);
    let m = load_doc(&doc).unwrap();
    let pos: Vec<Vec3> = m.vertices.iter().map(|v| Vec3::from(v.position)).collect();
    assert!(close(pos[0], Vec3::new(10.0, 0.0, 0.0), 1e-5), "{pos:?}");
    assert!(close(pos[1], Vec3::new(10.0, 2.0, 0.0), 1e-5), "{pos:?}");
    assert!(close(pos[2], Vec3::new(8.0, 0.0, 0.0), 1e-5), "{pos:?}");
    for v in &m.vertices {
        assert!(close(Vec3::from(v.normal), Vec3::Z, 1e-6), "{:?}", v.normal);
    }
    assert_eq!(m.materials, vec![dof_shaders::raster::mesh::MeshMaterial::default()]);
    assert_eq!(m.lighting, dof::scene::Lighting::default());
    assert!(m.cameras.is_empty() && m.report.is_clean());
}

/// Expectation: a mirroring node (scale −1 on x) keeps the triangle's front face on the side its
/// normal points to: the face normal of the loaded triangle agrees with the vertex normal.
#[test]
fn mirrored_node_keeps_front_faces() {
    for scale in [[-1.0, 1.0, 1.0], [1.0, 1.0, 1.0], [-1.0, -1.0, -1.0]] {
        let (doc, _) = document(&TRIANGLE, Some(&UP), None, 4, json!([{ "scale": scale, "mesh": 0 }]));
        let m = load_doc(&doc).unwrap();
        let n = Vec3::from(m.vertices[0].normal);
        assert!(face_normal(&m, 0).dot(n) > 0.0, "scale {scale:?}: face {} vs normal {n}", face_normal(&m, 0));
    }
}

/// Expectation: a strip and a fan of 5 vertices each become 3 triangles, all facing +Z as the
/// first one does (glTF's strip and fan orders).
#[test]
fn strips_and_fans_become_lists() {
    let strip = [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, 0.0, 0.0]];
    let fan = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 1.0, 0.0]];
    // Strip: (0,1,2) faces -Z; make it +Z by starting with the other zig-zag order.
    let strip: Vec<[f32; 3]> = strip.iter().map(|p| [p[0], -p[1], 0.0]).collect();
    for (mode, pts) in [(5, strip.as_slice()), (6, fan.as_slice())] {
        for indexed in [false, true] {
            let idx: Vec<u32> = (0..5).collect();
            let (doc, _) = document(pts, None, indexed.then_some(idx.as_slice()), mode, json!([{ "mesh": 0 }]));
            let m = load_doc(&doc).unwrap();
            assert_eq!(m.triangles.len(), 3, "mode {mode}");
            for t in 0..3 {
                assert!(face_normal(&m, t).z > 0.0, "mode {mode} triangle {t} faces {}", face_normal(&m, t));
            }
            assert_eq!(m.report.degenerate_triangles, 0);
        }
    }
}

/// Expectation: of a good triangle, one with a repeated index and one with collinear corners, only
/// the good one is kept and two are counted as degenerate; a points primitive alone is an error
/// saying the file holds no triangles.
#[test]
fn zero_area_triangles_are_dropped_and_counted() {
    let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [2.0, 0.0, 0.0]];
    let (doc, _) = document(&pts, None, Some(&[0, 1, 2, 0, 1, 1, 0, 1, 3]), 4, json!([{ "mesh": 0 }]));
    let m = load_doc(&doc).unwrap();
    assert_eq!(m.triangles.len(), 1);
    assert_eq!(m.report.degenerate_triangles, 2);

    let (doc, _) = document(&pts, None, None, 0, json!([{ "mesh": 0 }]));
    let err = load_doc(&doc).unwrap_err().to_string();
    assert!(err.contains("no triangles"), "{err}");
}

// ---- bad input ----

/// Expectation: malformed JSON, a truncated GLB and garbage are errors (`Error::Scene`), no panic.
#[test]
fn malformed_files_are_errors() {
    for bytes in [&b"{ not json"[..], b"", b"glTF\x02\0\0\0", b"{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [{\"mesh\": 7}]}"] {
        let err = load_gltf_slice(bytes).unwrap_err();
        assert!(matches!(err, Error::Scene(_)), "{err}");
    }
    let glb = export_builtin_glb("simple", W, H).unwrap();
    for cut in [glb.len() / 2, glb.len() - 4, 30] {
        let err = load_gltf_slice(&glb[..cut]).unwrap_err();
        assert!(matches!(err, Error::Scene(_)), "cut at {cut}: {err}");
    }
    // A scene with no scenes at all.
    let err = load_gltf_slice(br#"{"asset": {"version": "2.0"}}"#).unwrap_err().to_string();
    assert!(err.contains("no scene"), "{err}");
}

/// Expectation: an index past the vertices, a NaN position and a bad accessor (past its view)
/// are errors saying so and naming the mesh.
#[test]
fn bad_data_is_an_error() {
    let (doc, _) = document(&TRIANGLE, None, Some(&[0, 1, 5]), 4, json!([{ "mesh": 0 }]));
    let err = load_doc(&doc).unwrap_err().to_string();
    assert!(err.contains("out of range") && err.contains("test mesh"), "{err}");

    let nan = [[0.0, 0.0, 0.0], [f32::NAN, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let (doc, _) = document(&nan, None, None, 4, json!([{ "mesh": 0 }]));
    let err = load_doc(&doc).unwrap_err().to_string();
    assert!(err.contains("non-finite") && err.contains("test mesh"), "{err}");

    let (mut doc, _) = document(&TRIANGLE, None, None, 4, json!([{ "mesh": 0 }]));
    doc["accessors"][0]["count"] = json!(4);
    let err = load_doc(&doc).unwrap_err().to_string();
    assert!(err.contains("runs past"), "{err}");
    doc["accessors"][0]["count"] = json!(3);
    doc["accessors"][0]["type"] = json!("VEC2");
    assert!(load_doc(&doc).is_err());
}

/// Expectation: a .gltf whose buffer or image file is missing is an error naming the file; with
/// the buffer file present it loads.
#[test]
fn missing_external_files_are_named() {
    let (mut doc, bin) = document(&TRIANGLE, None, None, 4, json!([{ "mesh": 0 }]));
    let bin_path = temp_path("buffer.bin");
    let name = bin_path.file_name().unwrap().to_str().unwrap().to_owned();
    doc["buffers"][0]["uri"] = json!(name);
    let gltf_path = temp_path("scene.gltf");
    std::fs::write(&gltf_path, serde_json::to_vec(&doc).unwrap()).unwrap();
    let err = load_gltf(&gltf_path).unwrap_err().to_string();
    assert!(err.contains(&name), "{err}");

    std::fs::write(&bin_path, &bin).unwrap();
    assert_eq!(load_gltf(&gltf_path).unwrap().triangles.len(), 1);
    // From memory, the external reference cannot be resolved: an error saying so.
    let err = load_doc(&doc).unwrap_err().to_string();
    assert!(err.contains("external file"), "{err}");

    doc["images"] = json!([{ "uri": "missing_checker_texture.png" }]);
    doc["textures"] = json!([{ "source": 0 }]);
    doc["materials"] = json!([{ "pbrMetallicRoughness": { "baseColorTexture": { "index": 0 } } }]);
    doc["meshes"][0]["primitives"][0]["material"] = json!(0);
    std::fs::write(&gltf_path, serde_json::to_vec(&doc).unwrap()).unwrap();
    let err = load_gltf(&gltf_path).unwrap_err().to_string();
    assert!(err.contains("missing_checker_texture.png"), "{err}");

    let _ = std::fs::remove_file(&gltf_path);
    let _ = std::fs::remove_file(&bin_path);
    let err = load_gltf(&temp_path("does-not-exist.gltf")).unwrap_err().to_string();
    assert!(err.contains("does-not-exist.gltf"), "{err}");
}

/// Expectation: a camera with a zero field of view loads (it is data) but `camera()` refuses it;
/// an orthographic camera is skipped and counted; a perspective one sits at its node.
#[test]
fn cameras_are_checked() {
    let cam = MeshCamera {
        name: Some("flat".into()),
        eye: Vec3::ZERO,
        forward: Vec3::NEG_Z,
        up: Vec3::Y,
        yfov_radians: 0.0,
        aspect_ratio: None,
        znear: 0.1,
    };
    let err = cam.camera(64, 64).unwrap_err().to_string();
    assert!(err.contains("field of view") && err.contains("flat"), "{err}");
    assert!(MeshCamera { yfov_radians: 0.7, ..cam.clone() }.camera(64, 64).is_ok());

    let nodes = json!([
        { "mesh": 0, "children": [1, 2] },
        { "camera": 0, "translation": [1.0, 2.0, 3.0] },
        { "camera": 1 },
    ]);
    let (mut doc, _) = document(&TRIANGLE, None, None, 4, nodes);
    doc["cameras"] = json!([
        { "type": "perspective", "perspective": { "yfov": 0.5, "znear": 0.05 } },
        { "type": "orthographic", "orthographic": { "xmag": 1.0, "ymag": 1.0, "znear": 0.0, "zfar": 10.0 } },
    ]);
    let m = load_doc(&doc).unwrap();
    assert_eq!(m.cameras.len(), 1);
    assert_eq!(m.report.orthographic_cameras, 1);
    let c = &m.cameras[0];
    assert!(
        close(c.eye, Vec3::new(1.0, 2.0, 3.0), 1e-6)
            && close(c.forward, Vec3::NEG_Z, 1e-6)
            && c.yfov_radians == 0.5
            && c.aspect_ratio.is_none()
    );
}

/// Expectation: lights after the first directional one are counted as ignored, and a malformed
/// `dof_ambient` is an error naming the key.
#[test]
fn lights_and_ambient() {
    let nodes = json!([
        { "mesh": 0, "children": [1, 2] },
        { "extensions": { "KHR_lights_punctual": { "light": 0 } } },
        { "extensions": { "KHR_lights_punctual": { "light": 1 } } },
    ]);
    let (mut doc, _) = document(&TRIANGLE, None, None, 4, nodes);
    doc["extensionsUsed"] = json!(["KHR_lights_punctual"]);
    doc["extensions"] = json!({ "KHR_lights_punctual": { "lights": [
        { "type": "directional", "color": [1.0, 0.5, 0.25], "intensity": 2.0 },
        { "type": "point" },
    ] } });
    doc["scenes"][0]["extras"] = json!({ "dof_ambient": [0.1, 0.2, 0.3] });
    let m = load_doc(&doc).unwrap();
    assert_eq!(m.lighting.color, [2.0, 1.0, 0.5]);
    assert!(close(m.lighting.direction, Vec3::Z, 1e-6));
    assert_eq!(m.lighting.ambient, [0.1, 0.2, 0.3]);
    assert_eq!(m.report.ignored_lights, 1);

    doc["scenes"][0]["extras"] = json!({ "dof_ambient": [0.1, -0.2] });
    let err = load_doc(&doc).unwrap_err().to_string();
    assert!(err.contains("dof_ambient"), "{err}");
}

/// Splits a GLB into its JSON and binary chunk.
fn split_glb(glb: &[u8]) -> (Value, Vec<u8>) {
    let word = |at: usize| u32::from_le_bytes(glb[at..at + 4].try_into().unwrap()) as usize;
    let json_len = word(12);
    let json = serde_json::from_slice(&glb[20..20 + json_len]).unwrap();
    let bin_at = 20 + json_len;
    (json, glb[bin_at + 8..bin_at + 8 + word(bin_at)].to_vec())
}

/// Joins JSON and a binary chunk into a GLB.
fn join_glb(json: &Value, bin: &[u8]) -> Vec<u8> {
    dof::scene::gltf_export::glb(serde_json::to_vec(json).unwrap(), bin.to_vec())
}

/// Expectation: material flags and sampler bits follow the file: unlit, mask with its cutoff,
/// blend, single-sided; a linear-magnification, clamp/mirror sampler; a texture naming a texCoord
/// set the primitives lack, beside an emissive texture on set 0, is counted; an emissive texture is decoded; the same image used twice with the
/// same sampler shares one texture.
#[test]
fn material_flags_and_samplers_follow_the_file() {
    use dof_shaders::raster::mesh::{ALPHA_BLEND, ALPHA_MASK, UNLIT, WRAP_CLAMP, WRAP_MIRROR};
    let (mut doc, bin) = split_glb(&export_builtin_glb("railing", W, H).unwrap());
    let m0 = &mut doc["materials"][0];
    m0["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = json!(1);
    m0["extensions"] = json!({ "KHR_materials_unlit": {} });
    m0["alphaMode"] = json!("MASK");
    m0["alphaCutoff"] = json!(0.25);
    m0["doubleSided"] = json!(false);
    m0["emissiveTexture"] = json!({ "index": 0 });
    doc["materials"][2]["alphaMode"] = json!("BLEND");
    doc["materials"][2]["doubleSided"] = json!(true);
    doc["samplers"][0] = json!({ "magFilter": 9729, "wrapS": 33071, "wrapT": 33648 });
    doc["extensionsUsed"] = json!(["KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_materials_unlit"]);
    let m = load_gltf_slice(&join_glb(&doc, &bin)).unwrap();
    // Its base colour reads set 1, which the primitives lack, and its emissive texture set 0.
    assert!(m.report.missing_texture_coordinates > 0 && m.report.mixed_texture_coordinates > 0, "{}", m.report);
    let mat = m.materials[0];
    assert_eq!(mat.flags, UNLIT | ALPHA_MASK);
    assert_eq!(mat.alpha_cutoff, 0.25);
    assert_eq!(mat.emissive_texture, mat.base_texture, "same image, same sampler: one texture");
    assert_eq!(m.materials[2].flags, ALPHA_BLEND | DOUBLE_SIDED);
    let t = m.textures[mat.base_texture as usize];
    assert_eq!(t.sampler, (WRAP_CLAMP << WRAP_S_SHIFT) | (WRAP_MIRROR << WRAP_T_SHIFT));
    // Two checker materials in `railing`, one image each: 8 texels.
    assert_eq!(m.texels.len(), 8);
}

// ---- references outside the .gltf file's folder, special files, lengths ----

/// A fresh temporary folder holding `scene.gltf` (one triangle) whose buffer URI is `uri`;
/// returns the folder, the .gltf path and the buffer's bytes.
fn gltf_in_folder(uri: &str) -> (PathBuf, PathBuf, Vec<u8>) {
    let dir = temp_path("folder");
    std::fs::create_dir_all(&dir).unwrap();
    let (mut doc, bin) = document(&TRIANGLE, None, None, 4, json!([{ "mesh": 0 }]));
    doc["buffers"][0]["uri"] = json!(uri);
    let path = dir.join("scene.gltf");
    std::fs::write(&path, serde_json::to_vec(&doc).unwrap()).unwrap();
    (dir, path, bin)
}

/// Loads `path` on a thread and fails, rather than hangs, if it takes more than 20 s (a FIFO).
fn load_with_timeout(path: &std::path::Path) -> dof::error::Result<MeshScene> {
    let (tx, rx) = std::sync::mpsc::channel();
    let p = path.to_path_buf();
    std::thread::spawn(move || {
        let _ = tx.send(load_gltf(&p));
    });
    rx.recv_timeout(std::time::Duration::from_secs(20)).unwrap_or_else(|_| panic!("loading {} hung", path.display()))
}

const STAY_INSIDE: &str = "must stay inside the folder of the .gltf file";

/// Expectation: a buffer URI that leaves the folder by `..`, an absolute path (to a real file and
/// to /etc/passwd), a `file://` URI to /etc/passwd, `/dev/zero`, and an image URI leaving the
/// folder are refused with an error naming the URI and saying references must stay inside the
/// folder; nothing outside is read.
#[test]
fn references_outside_the_folder_are_refused() {
    let outside_dir = temp_path("outside");
    std::fs::create_dir_all(&outside_dir).unwrap();
    let (_, _, bin) = gltf_in_folder("unused.bin");
    let outside_file = outside_dir.join("buffer.bin");
    std::fs::write(&outside_file, &bin).unwrap();
    let outside_abs = outside_file.to_str().unwrap().to_owned();
    let escape = format!("../{}/buffer.bin", outside_dir.file_name().unwrap().to_str().unwrap());
    for uri in [
        "../../../../etc/passwd",
        "/etc/passwd",
        outside_abs.as_str(),
        "file:///etc/passwd",
        "/dev/zero",
        "file:///dev/zero",
        "sub/../../x.bin",
        escape.as_str(),
        "%2E%2E/%2E%2E/etc/passwd",
    ] {
        let (dir, path, _) = gltf_in_folder(uri);
        let err = load_with_timeout(&path).unwrap_err().to_string();
        assert!(err.contains(STAY_INSIDE), "{uri}: {err}");
        assert!(err.contains(uri), "{uri}: the error names the URI: {err}");
        let _ = std::fs::remove_dir_all(&dir);
    }
    // An image URI is held to the same rule.
    let (dir, path, bin) = gltf_in_folder("buffer.bin");
    std::fs::write(dir.join("buffer.bin"), &bin).unwrap();
    let mut doc: Value = serde_json::from_slice(&std::fs::read(&path).unwrap()).unwrap();
    doc["images"] = json!([{ "uri": "../../../../etc/passwd" }]);
    doc["textures"] = json!([{ "source": 0 }]);
    doc["materials"] = json!([{ "pbrMetallicRoughness": { "baseColorTexture": { "index": 0 } } }]);
    doc["meshes"][0]["primitives"][0]["material"] = json!(0);
    std::fs::write(&path, serde_json::to_vec(&doc).unwrap()).unwrap();
    let err = load_with_timeout(&path).unwrap_err().to_string();
    assert!(err.contains(STAY_INSIDE) && err.contains("../../../../etc/passwd") && err.contains("image 0"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&outside_dir);
}

/// Expectation: references that stay inside the folder load: `sub/../buffer.bin`, `./buffer.bin`
/// and `file:buffer.bin`.
#[test]
fn references_inside_the_folder_load() {
    for uri in ["sub/../buffer.bin", "./buffer.bin", "file:buffer.bin"] {
        let (dir, path, bin) = gltf_in_folder(uri);
        std::fs::write(dir.join("buffer.bin"), &bin).unwrap();
        let m = load_with_timeout(&path).unwrap_or_else(|e| panic!("{uri}: {e}"));
        assert_eq!(m.triangles.len(), 1, "{uri}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}

/// Expectation: a symbolic link inside the folder that points outside it (to a real buffer file)
/// is refused, naming the URI; one pointing inside loads.
#[test]
fn symlinks_cannot_escape_the_folder() {
    let outside_dir = temp_path("outside");
    std::fs::create_dir_all(&outside_dir).unwrap();
    let (dir, path, bin) = gltf_in_folder("link.bin");
    std::fs::write(outside_dir.join("buffer.bin"), &bin).unwrap();
    std::os::unix::fs::symlink(outside_dir.join("buffer.bin"), dir.join("link.bin")).unwrap();
    let err = load_with_timeout(&path).unwrap_err().to_string();
    assert!(err.contains(STAY_INSIDE) && err.contains("link.bin") && err.contains("symbolic link"), "{err}");

    std::fs::remove_file(dir.join("link.bin")).unwrap();
    std::fs::write(dir.join("real.bin"), &bin).unwrap();
    std::os::unix::fs::symlink(dir.join("real.bin"), dir.join("link.bin")).unwrap();
    assert_eq!(load_with_timeout(&path).unwrap().triangles.len(), 1);
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&outside_dir);
}

/// Expectation: a FIFO and a directory inside the folder are refused as not regular files, without
/// blocking on the FIFO; the .gltf path itself being `/dev/zero` or a FIFO is refused the same way.
#[test]
fn special_files_are_refused() {
    let (dir, path, _) = gltf_in_folder("sub");
    std::fs::create_dir(dir.join("sub")).unwrap();
    let err = load_with_timeout(&path).unwrap_err().to_string();
    assert!(err.contains("not a regular file") && err.contains("`sub`"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);

    let err = load_with_timeout(std::path::Path::new("/dev/zero")).unwrap_err().to_string();
    assert!(err.contains("not a regular file") && err.contains("/dev/zero"), "{err}");

    let (dir, path, _) = gltf_in_folder("fifo.bin");
    match std::process::Command::new("mkfifo").arg(dir.join("fifo.bin")).status() {
        Ok(s) if s.success() => {
            let err = load_with_timeout(&path).unwrap_err().to_string();
            assert!(err.contains("not a regular file") && err.contains("fifo.bin"), "{err}");
            let err = load_with_timeout(&dir.join("fifo.bin")).unwrap_err().to_string();
            assert!(err.contains("not a regular file"), "{err}");
        }
        other => eprintln!("skipping the FIFO case: mkfifo is unavailable or failed ({other:?})"),
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Expectation: a buffer file shorter than its byteLength is an error naming the file and both
/// lengths; a longer one is read only up to byteLength and the scene loads.
#[test]
fn buffer_files_are_read_up_to_their_byte_length() {
    let (dir, path, bin) = gltf_in_folder("buffer.bin");
    std::fs::write(dir.join("buffer.bin"), &bin[..bin.len() - 5]).unwrap();
    let err = load_with_timeout(&path).unwrap_err().to_string();
    let (short, want) = ((bin.len() - 5).to_string(), bin.len().to_string());
    assert!(err.contains("buffer.bin") && err.contains(&short) && err.contains(&want) && err.contains("byteLength"), "{err}");

    let mut long = bin.clone();
    long.extend(std::iter::repeat_n(0xAB, 1 << 20));
    std::fs::write(dir.join("buffer.bin"), &long).unwrap();
    let m = load_with_timeout(&path).unwrap();
    assert_eq!(m.triangles.len(), 1);
    assert_eq!(m, load_doc(&document(&TRIANGLE, None, None, 4, json!([{ "mesh": 0 }])).0).unwrap());
    let _ = std::fs::remove_dir_all(&dir);
}

/// Expectation: a GLB whose magic is wrong (`glTX`, or zero bytes) is reported as "not a GLB
/// file (wrong magic …)", not as a JSON error; text garbage still gets the JSON message.
#[test]
fn wrong_glb_magic_is_named() {
    let mut glb = export_builtin_glb("simple", W, H).unwrap();
    glb[..4].copy_from_slice(b"glTX");
    let err = load_gltf_slice(&glb).unwrap_err().to_string();
    assert!(err.contains("not a GLB file (wrong magic `glTX`"), "{err}");
    glb[..4].copy_from_slice(&[0; 4]);
    let err = load_gltf_slice(&glb).unwrap_err().to_string();
    assert!(err.contains("not a GLB file (wrong magic"), "{err}");
    let err = load_gltf_slice(b"{ not json").unwrap_err().to_string();
    assert!(err.contains("not a valid glTF 2.0 file"), "{err}");
}

/// A PNG of `width`x`height` grey pixels without their data: a signature, the header, an empty
/// compressed stream and the end, enough for the loader to read the size (and no more).
fn png_header_only(width: u32, height: u32) -> Vec<u8> {
    fn crc32(bytes: &[u8]) -> u32 {
        let mut c = !0u32;
        for &b in bytes {
            c ^= b as u32;
            for _ in 0..8 {
                c = if c & 1 != 0 { 0xEDB8_8320 ^ (c >> 1) } else { c >> 1 };
            }
        }
        !c
    }
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    let header = [&width.to_be_bytes()[..], &height.to_be_bytes(), &[8, 0, 0, 0, 0]].concat();
    for (kind, data) in [(&b"IHDR"[..], header), (&b"IDAT"[..], vec![0x78, 0x9c, 0x03, 0x00]), (&b"IEND"[..], vec![])] {
        png.extend((data.len() as u32).to_be_bytes());
        let body = [kind, &data[..]].concat();
        png.extend(&body);
        png.extend(crc32(&body).to_be_bytes());
    }
    png
}

/// A texture beyond the texel budget is refused from its header, before anything is decoded or
/// allocated, with its size and a hint.
#[test]
fn a_texture_beyond_the_budget_is_refused_before_decoding() {
    let (mut doc, bin) = split_glb(&export_builtin_glb("railing", W, H).unwrap());
    doc["images"][0] = json!({ "uri": format!("data:image/png;base64,{}", base64(&png_header_only(16384, 16384))) });
    let err = load_gltf_slice(&join_glb(&doc, &bin)).expect_err("a 16384x16384 texture is beyond 2^27 texels");
    let text = err.to_string();
    assert!(matches!(err, dof::Error::Core(CoreError::TooLarge { .. })), "{text}");
    assert!(text.contains("16384x16384") && text.contains("scale the textures down"), "{text}");
}

/// `KHR_texture_transform` and `TEXCOORD_1`: a material's texture reading set 1 through an offset,
/// rotation and scale gives its primitives those coordinates, transformed as the extension's GLSL
/// does (`translation · rotation · scale`).
#[test]
fn texture_transforms_and_the_second_coordinate_set_are_applied() {
    let (mut doc, bin) = split_glb(&export_builtin_glb("railing", W, H).unwrap());
    let plain = load_gltf_slice(&join_glb(&doc, &bin)).unwrap();
    for mesh in doc["meshes"].as_array_mut().unwrap() {
        for prim in mesh["primitives"].as_array_mut().unwrap() {
            if let Some(uv) = prim["attributes"].get("TEXCOORD_0").cloned() {
                prim["attributes"]["TEXCOORD_1"] = uv;
            }
        }
    }
    let rotation = std::f32::consts::FRAC_PI_2;
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = json!({
        "index": 0,
        "texCoord": 1,
        "extensions": { "KHR_texture_transform": { "offset": [0.5, 0.25], "rotation": rotation, "scale": [2.0, 3.0] } },
    });
    doc["extensionsUsed"] = json!(["KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_texture_transform"]);
    let m = load_gltf_slice(&join_glb(&doc, &bin)).unwrap();
    assert!(m.report.is_clean(), "{}", m.report);
    let with_material = |mesh: &MeshScene| -> Vec<usize> {
        let mut v: Vec<usize> = mesh.triangles.iter().filter(|t| t[3] == 0).flat_map(|t| t[..3].iter().map(|&i| i as usize)).collect();
        v.sort_unstable();
        v.dedup();
        v
    };
    let vertices = with_material(&m);
    assert!(!vertices.is_empty());
    assert_eq!(vertices, with_material(&plain));
    for i in vertices {
        let (u, v) = (plain.vertices[i].u, plain.vertices[i].v);
        // Rotation by a quarter turn: (u, v) scaled to (2u, 3v) turns to (-3v, 2u).
        let want = [-3.0 * v + 0.5, 2.0 * u + 0.25];
        let got = [m.vertices[i].u, m.vertices[i].v];
        let close = |a: f32, b: f32| (a - b).abs() <= 1e-6 * b.abs().max(1.0);
        assert!(close(got[0], want[0]) && close(got[1], want[1]), "vertex {i}: {got:?}, want {want:?}");
    }
}

/// Expectation: `COLOR_0` loads as each vertex's linear colour (unsigned bytes normalised, floats
/// as they are, RGB with alpha 1), white without one; a non-finite colour is an error naming it.
#[test]
fn vertex_colours_are_read() {
    let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let floats = |v: &[f32]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    let cases: [(u32, &str, Vec<u8>, [[f32; 4]; 3]); 3] = [
        (
            5121,
            "VEC4",
            vec![255, 0, 0, 255, 0, 51, 0, 255, 0, 0, 255, 0],
            [[1.0, 0.0, 0.0, 1.0], [0.0, 0.2, 0.0, 1.0], [0.0, 0.0, 1.0, 0.0]],
        ),
        (5126, "VEC3", floats(&[0.5, 0.25, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0]), [[0.5, 0.25, 1.0, 1.0], [0.0, 0.0, 0.0, 1.0], [1.0; 4]]),
        (5126, "VEC3", floats(&[0.5, f32::NAN, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0]), [[0.0; 4]; 3]),
    ];
    for (component, ty, data, expect) in cases {
        let (mut doc, mut bin) = document(&positions, None, None, 4, json!([{ "mesh": 0 }]));
        let views = doc["bufferViews"].as_array().unwrap().len();
        doc["bufferViews"].as_array_mut().unwrap().push(json!({ "buffer": 0, "byteOffset": bin.len(), "byteLength": data.len() }));
        let mut accessor = json!({ "bufferView": views, "componentType": component, "count": 3, "type": ty });
        if component != 5126 {
            accessor["normalized"] = json!(true);
        }
        let colors = doc["accessors"].as_array().unwrap().len();
        doc["accessors"].as_array_mut().unwrap().push(accessor);
        doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = json!(colors);
        bin.extend(&data);
        doc["buffers"][0] = json!({ "byteLength": bin.len(), "uri": format!("data:application/octet-stream;base64,{}", base64(&bin)) });
        let loaded = load_doc(&doc);
        if expect[0][0] == 0.0 && expect[2][0] == 0.0 {
            let err = loaded.expect_err("a NaN colour is refused").to_string();
            assert!(err.contains("COLOR_0") && err.contains("non-finite"), "{err}");
            continue;
        }
        let m = loaded.unwrap();
        let half = dof_shaders::raster::texture::half_to_f32;
        for (k, v) in m.vertices.iter().enumerate() {
            let c = [half(v.color[0] & 0xffff), half(v.color[0] >> 16), half(v.color[1] & 0xffff), half(v.color[1] >> 16)];
            assert!((0..4).all(|j| (c[j] - expect[k][j]).abs() < 1e-3), "{ty} vertex {k}: {c:?}, expected {:?}", expect[k]);
        }
    }
    let (doc, _) = document(&positions, None, None, 4, json!([{ "mesh": 0 }]));
    assert!(load_doc(&doc).unwrap().vertices.iter().all(|v| v.color == dof_shaders::raster::mesh::WHITE_HALVES));
}
