//! Depth peeling on the device (`MeshPeelContext`) against the host oracle `peel_layers` of the
//! same commit: the same slots, counts and disocclusion buffer, bit for bit, on the CPU backend and
//! on Vulkan (a built-in scene's glTF export, the same with alpha-masked materials, a hand-built
//! mesh with an alpha-masked texture, translucent panes); and a frame of peel plus multi-layer splatting with the camera turning, recorded with
//! no allocation, upload or readback and submitted once.

use dof::backend::{Backend, CpuBackend};
use dof::frame::{ContextDesc, Extent, FrameOutput, MethodOptions, RgbBuffer, registry};
use dof::methods::buffers::slot_words;
use dof::raster::{MeshPeelContext, MeshPeelDesc, default_near, peel_layers};
use dof::scene::{Camera, ExportOptions, GuardBand, LayerOptions, MeshScene, Vec3, builtin, export_glb, load_gltf_slice};
use dof_shaders::lens::ThinLens;
use dof_shaders::raster::mesh::{ALPHA_MASK, MeshMaterial, MeshVertex, NEAREST, TextureInfo, UNLIT};
use dof_tests::{assert_clean, vulkan, vulkan_with};

/// A built-in scene exported to glTF and loaded back (what `dof scenes --raster` peels), seen by
/// its own camera at `w` x `h`.
fn builtin_mesh(name: &str, w: u32, h: u32) -> (MeshScene, Camera, ThinLens) {
    let scene = builtin(name).unwrap();
    let mut camera = scene.camera;
    camera.width = w;
    camera.height = h;
    let lens = scene.lens.thin_lens(&camera).unwrap();
    let glb = export_glb(&scene.scene, &scene.camera, &ExportOptions::default()).unwrap();
    (load_gltf_slice(&glb).unwrap(), camera, lens)
}

fn quad(m: &mut MeshScene, corner: Vec3, u: Vec3, v: Vec3, material: u32) {
    let n = u.cross(v).normalize().to_array();
    let base = m.vertices.len() as u32;
    for (p, (tu, tv)) in [(corner, (0.0, 0.0)), (corner + u, (1.0, 0.0)), (corner + u + v, (1.0, 1.0)), (corner + v, (0.0, 1.0))] {
        m.vertices.push(MeshVertex { position: p.to_array(), u: tu, normal: n, v: tv, ..MeshVertex::default() });
    }
    m.triangles.push([base, base + 1, base + 2, material]);
    m.triangles.push([base, base + 2, base + 3, material]);
}

/// Open sky behind a lit wall at 8 and a ground, and near bars through an alpha-masked texture (a
/// 4x1 texture, every other texel transparent) at 1.2, out of focus.
fn masked_bars() -> (MeshScene, Camera, ThinLens) {
    let mut m = MeshScene {
        texels: vec![[0.9, 0.8, 0.7, 1.0], [1.0, 1.0, 1.0, 0.0], [0.9, 0.8, 0.7, 1.0], [1.0, 1.0, 1.0, 0.0]],
        textures: vec![TextureInfo { offset: 0, width: 4, height: 1, sampler: NEAREST }],
        ..MeshScene::default()
    };
    m.materials.push(MeshMaterial { base: [0.2, 0.5, 0.9, 1.0], ..MeshMaterial::default() });
    m.materials.push(MeshMaterial { base: [1.0; 4], base_texture: 0, flags: UNLIT | ALPHA_MASK, ..MeshMaterial::default() });
    m.materials.push(MeshMaterial { base: [0.4, 0.6, 0.3, 1.0], ..MeshMaterial::default() });
    quad(&mut m, Vec3::new(-3.0, -1.0, -8.0), Vec3::new(6.0, 0.0, 0.0), Vec3::new(0.0, 2.5, 0.0), 0);
    quad(&mut m, Vec3::new(-0.6, -0.3, -1.2), Vec3::new(1.2, 0.0, 0.0), Vec3::new(0.0, 0.6, 0.0), 1);
    quad(&mut m, Vec3::new(-6.0, -1.0, 0.0), Vec3::new(12.0, 0.0, 0.0), Vec3::new(0.0, 0.0, -12.0), 2);
    m.lighting.direction = Vec3::new(0.3, 1.0, 0.5);
    m.lighting.background = [0.5, 0.7, 1.0];
    let camera = Camera::look_at(Vec3::new(0.0, 0.2, 1.0), Vec3::new(0.0, 0.2, -8.0), 45f32.to_radians(), 80, 48);
    let lens = ThinLens { focal_length: 0.05, aperture_radius: 0.1, focus_distance: 9.0, pixels_per_unit: 48.0 / 0.024 };
    (m, camera, lens)
}

/// Splits a GLB into its JSON and binary chunk.
fn split_glb(glb: &[u8]) -> (serde_json::Value, Vec<u8>) {
    let word = |at: usize| u32::from_le_bytes(glb[at..at + 4].try_into().unwrap()) as usize;
    let json_len = word(12);
    let json = serde_json::from_slice(&glb[20..20 + json_len]).unwrap();
    let bin_at = 20 + json_len;
    (json, glb[bin_at + 8..bin_at + 8 + word(bin_at)].to_vec())
}

fn base64(bytes: &[u8]) -> String {
    const A: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut s = String::new();
    for c in bytes.chunks(3) {
        let n = (c[0] as u32) << 16 | (*c.get(1).unwrap_or(&0) as u32) << 8 | *c.get(2).unwrap_or(&0) as u32;
        for k in 0..4 {
            s.push(if k <= c.len() { A[(n >> (18 - 6 * k) & 63) as usize] as char } else { '=' });
        }
    }
    s
}

/// The built-in railing as a glTF file whose textured materials are alpha-masked (`MASK`, cutoff
/// 0.5) by a 4x1 texture of opaque and transparent stripes: cut-out bars over a cut-out far field.
fn masked_railing_gltf(w: u32, h: u32) -> (MeshScene, Camera, ThinLens) {
    use dof::io::codecs::png;
    let scene = builtin("railing").unwrap();
    let mut camera = scene.camera;
    camera.width = w;
    camera.height = h;
    let lens = scene.lens.thin_lens(&camera).unwrap();
    let (mut doc, bin) = split_glb(&export_glb(&scene.scene, &scene.camera, &ExportOptions::default()).unwrap());
    let mut encoded = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut encoded, 4, 1);
        encoder.set_color(png::ColorType::Rgba);
        encoder.set_depth(png::BitDepth::Eight);
        let texels = [200, 180, 160, 255, 255, 255, 255, 0, 90, 120, 200, 255, 255, 255, 255, 0];
        encoder.write_header().unwrap().write_image_data(&texels).unwrap();
    }
    let uri = format!("data:image/png;base64,{}", base64(&encoded));
    let images = doc["images"].as_array_mut().expect("the railing has textures");
    for image in images.iter_mut() {
        *image = serde_json::json!({ "uri": uri });
    }
    let mut masked = 0;
    for m in doc["materials"].as_array_mut().unwrap() {
        if !m["pbrMetallicRoughness"]["baseColorTexture"].is_null() {
            m["alphaMode"] = serde_json::json!("MASK");
            m["alphaCutoff"] = serde_json::json!(0.5);
            masked += 1;
        }
    }
    assert!(masked > 0, "no textured material to mask");
    let glb = dof::scene::gltf_export::glb(serde_json::to_vec(&doc).unwrap(), bin);
    let mesh = load_gltf_slice(&glb).unwrap();
    assert!(mesh.materials.iter().any(|m| m.flags & ALPHA_MASK != 0));
    (mesh, camera, lens)
}

/// The device's slots, counts and disocclusion buffer (cut to the frame) after one frame.
fn device_peel(b: &mut dyn Backend, ctx: &mut MeshPeelContext, camera: &Camera, lens: &ThinLens) -> (Vec<u32>, Vec<u32>, Vec<bool>) {
    ctx.record(b, camera, lens).unwrap();
    b.submit().unwrap();
    let s = ctx.slots().clone();
    let pixels = s.width as u64 * s.height as u64;
    let fragments = b.read_buffer(s.fragments, 0, dof::methods::buffers::SLOT_WORDS as u64 * pixels * s.layers as u64).unwrap();
    let counts = b.read_buffer(s.counts, 0, pixels).unwrap();
    let mask = b.read_buffer(s.mask, 0, pixels).unwrap();
    let m = ctx.margin();
    let mut cropped = Vec::new();
    for y in m..s.height - m {
        for x in m..s.width - m {
            cropped.push(mask[(y * s.width + x) as usize] != 0);
        }
    }
    (fragments, counts, cropped)
}

/// Asserts the device peel equals `peel_layers` for these options.
fn assert_same_as_host(b: &mut dyn Backend, mesh: &MeshScene, camera: &Camera, lens: &ThinLens, options: &LayerOptions) {
    let near = default_near(lens.focus_distance);
    let host = peel_layers(b, &mesh.raster(), camera, lens, near, options).unwrap();
    let mut ctx = MeshPeelContext::new(b, &mesh.raster(), camera, lens, &MeshPeelDesc::new(options, near)).unwrap();
    assert_eq!(ctx.margin(), host.image.margin, "the same guard band");
    let (fragments, counts, mask) = device_peel(b, &mut ctx, camera, lens);
    let want = &host.image.layers;
    assert_eq!(counts, want.counts, "slots per pixel");
    assert!(want.counts.iter().any(|&c| c > 1), "the scene has pixels of several layers");
    let want_words = slot_words(want);
    let diff = fragments.iter().zip(&want_words).position(|(a, b)| a != b);
    assert_eq!(diff, None, "first differing slot word (of {})", want_words.len());
    assert_eq!(mask, host.image.mask, "the disocclusion buffer");
    let report = ctx.peel_report(b).unwrap();
    let recorded = options.max_layers + options.translucent_passes;
    assert_eq!(report.recorded, recorded);
    assert_eq!(report.drawn, host.passes.min(recorded), "passes drawn, as the host ran them");
    ctx.destroy(b);
}

fn options(margin: GuardBand, layers: u32, disocclusion: bool) -> LayerOptions {
    LayerOptions { max_layers: layers, guard_band: margin, disocclusion, ..LayerOptions::default() }
}

fn equal_to_host_on(b: &mut dyn Backend) {
    let (fence, camera, lens) = builtin_mesh("fence", 96, 54);
    assert_same_as_host(b, &fence, &camera, &lens, &options(GuardBand::Pixels(6), 4, true));
    assert_same_as_host(b, &fence, &camera, &lens, &options(GuardBand::Auto, 3, false));
    let (railing, camera, lens) = masked_railing_gltf(96, 54);
    assert_same_as_host(b, &railing, &camera, &lens, &options(GuardBand::Auto, 4, true));
    // The mask cuts: the front layer differs from the unmasked export's.
    let (plain, ..) = builtin_mesh("railing", 96, 54);
    let near = default_near(lens.focus_distance);
    let front = |m: &MeshScene, b: &mut dyn Backend| {
        let peeled = peel_layers(b, &m.raster(), &camera, &lens, near, &options(GuardBand::Off, 1, false)).unwrap();
        peeled.image.layers.fragments.iter().map(|f| f.depth.to_bits()).collect::<Vec<_>>()
    };
    assert_ne!(front(&railing, b), front(&plain, b), "the alpha mask cut nothing");
    let (bars, camera, lens) = masked_bars();
    assert_same_as_host(b, &bars, &camera, &lens, &options(GuardBand::Pixels(4), 4, true));
    assert_same_as_host(b, &bars, &camera, &lens, &options(GuardBand::Off, 2, true));
}

/// `panes` (two translucent panes over a wall): the device keeps the host's slots, and outside the
/// disocclusion buffer a pixel behind a pane keeps the pane and what it does not hide.
fn translucent_layers_on(b: &mut dyn Backend) {
    let (panes, camera, lens) = builtin_mesh("panes", 96, 54);
    let opts = options(GuardBand::Pixels(6), 4, true);
    assert_same_as_host(b, &panes, &camera, &lens, &opts);
    let host = peel_layers(b, &panes.raster(), &camera, &lens, default_near(lens.focus_distance), &opts).unwrap();
    let frame = host.image.frame_layers();
    let l = frame.max_layers as usize;
    let behind_pane =
        (0..frame.counts.len()).filter(|&p| !host.image.mask[p] && frame.counts[p] >= 2 && frame.fragments[p * l].alpha < 1.0).count();
    assert!(behind_pane > 100, "{behind_pane} pixels outside the buffer keep a translucent front and what lies behind");
    // Only translucent slots come before the last one outside the buffer.
    for p in (0..frame.counts.len()).filter(|&p| !host.image.mask[p]) {
        let n = frame.counts[p] as usize;
        assert!(frame.fragments[p * l..p * l + n.saturating_sub(1)].iter().all(|f| f.alpha < 1.0), "pixel {p}");
    }
}

/// Twelve red panes of alpha 0.1 before a white wall, peeled into 4 slots: with 9 translucent
/// passes the last slot takes the other eight panes and the wall, in order, as the ray caster would
/// (the light of 12 panes and the wall they let through: green 0.9^12); with none, black shows
/// through the fourth pane (green 0), and the pixel is counted. The device keeps the host's slots.
fn deep_translucent_stack_on(b: &mut dyn Backend) {
    let mut m = MeshScene::default();
    m.materials.push(MeshMaterial { base: [1.0, 1.0, 1.0, 1.0], flags: UNLIT, ..MeshMaterial::default() });
    m.materials.push(MeshMaterial {
        base: [1.0, 0.0, 0.0, 0.1],
        flags: UNLIT | dof_shaders::raster::mesh::ALPHA_BLEND,
        ..MeshMaterial::default()
    });
    quad(&mut m, Vec3::new(-9.0, -9.0, -10.0), Vec3::new(18.0, 0.0, 0.0), Vec3::new(0.0, 18.0, 0.0), 0);
    for k in 0..12 {
        quad(&mut m, Vec3::new(-1.0, -1.0, -2.0 - 0.4 * k as f32), Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 2.0, 0.0), 1);
    }
    let camera = Camera::look_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0), 40f32.to_radians(), 48, 32);
    let lens = ThinLens { focal_length: 0.05, aperture_radius: 0.01, focus_distance: 6.0, pixels_per_unit: 32.0 / 0.024 };
    let near = default_near(lens.focus_distance);
    let peel = |b: &mut dyn Backend, passes: u32| {
        let opts = LayerOptions { translucent_passes: passes, ..options(GuardBand::Off, 4, false) };
        assert_same_as_host(b, &m, &camera, &lens, &opts);
        peel_layers(b, &m.raster(), &camera, &lens, near, &opts).unwrap()
    };
    let centre = |l: &dof::layers::LayeredImage| {
        let p = l.pixel_index(24, 16);
        (dof_shaders::slot::flatten(l.counts[p], |k| l.fragments[p * 4 + k as usize].slot()).0, l.full_and_translucent())
    };
    let (whole, cut) = (peel(b, 9), peel(b, 0));
    let ((rgb, deep), (cut_rgb, cut_deep)) = (centre(&whole.image.layers), centre(&cut.image.layers));
    let through = 0.9f32.powi(12);
    assert!((rgb[0] - 1.0).abs() < 1e-5 && (rgb[1] - through).abs() < 1e-5, "{rgb:?} against [1, {through}, {through}]");
    assert_eq!(deep, 0, "no pixel ends translucent");
    assert!((cut_rgb[0] - (1.0 - 0.9f32.powi(4))).abs() < 1e-5 && cut_rgb[1] == 0.0, "{cut_rgb:?}");
    assert!(cut_deep > 0, "the cut stacks are counted");
    assert_eq!((whole.passes, cut.passes), (13, 4), "passes run: 12 panes and the wall; then the 4 slots");
}

#[test]
fn a_deep_translucent_stack_keeps_its_light_on_the_cpu() {
    deep_translucent_stack_on(&mut CpuBackend::new());
}

#[test]
fn a_deep_translucent_stack_keeps_its_light_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    deep_translucent_stack_on(&mut vk);
    assert_clean(&mut vk);
}

#[test]
fn translucent_layers_peel_alike_on_the_cpu() {
    translucent_layers_on(&mut CpuBackend::new());
}

#[test]
fn translucent_layers_peel_alike_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    translucent_layers_on(&mut vk);
    assert_clean(&mut vk);
}

/// Vulkan drawing through the draws' compute fallbacks (`DrawPath::Compute`) peels exactly as the
/// CPU backend does: the same rasteriser, the same slots, counts and buffer, bit for bit.
#[test]
fn compute_draws_on_vulkan_peel_as_the_cpu_backend_does() {
    use dof::backend::{DrawPath, VulkanOptions};
    let Some(mut vk) = vulkan_with(VulkanOptions { validation: true, draws: DrawPath::Compute, ..Default::default() }) else { return };
    assert!(!vk.draws_through_graphics());
    let mut cpu = CpuBackend::new();
    for (mesh, camera, lens) in [builtin_mesh("fence", 96, 54), masked_bars()] {
        let desc = MeshPeelDesc::new(&options(GuardBand::Pixels(6), 4, true), default_near(lens.focus_distance));
        let mut peeled = Vec::new();
        for b in [&mut cpu as &mut dyn Backend, &mut vk] {
            let mut ctx = MeshPeelContext::new(b, &mesh.raster(), &camera, &lens, &desc).unwrap();
            peeled.push(device_peel(b, &mut ctx, &camera, &lens));
            ctx.destroy(b);
        }
        assert!(peeled[0].1.iter().any(|&c| c > 1), "the scene has pixels of several layers");
        assert!(peeled[0] == peeled[1], "the compute draws' peel differs from the CPU backend's");
    }
    assert_clean(&mut vk);
}

#[test]
fn the_device_peel_equals_the_host_peel_on_the_cpu() {
    equal_to_host_on(&mut CpuBackend::new());
}

#[test]
fn the_device_peel_equals_the_host_peel_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    equal_to_host_on(&mut vk);
    assert_clean(&mut vk);
}

/// The camera turned `deg` degrees about the vertical axis through the point in focus.
fn orbit(camera: &Camera, focus: f32, deg: f32) -> Camera {
    let forward = (camera.target - camera.eye).normalize();
    let pivot = camera.eye + forward * focus;
    let (s, c) = deg.to_radians().sin_cos();
    let turn = |v: Vec3| Vec3::new(v.x * c + v.z * s, v.y, v.z * c - v.x * s);
    Camera { eye: pivot + turn(camera.eye - pivot), target: pivot + turn(camera.target - pivot), ..*camera }
}

/// Peel and multi-layer splatting recorded into one submission per frame, the camera turning every
/// frame: nothing allocated, uploaded or read back, and every pass recorded.
fn orbiting_frames_on(b: &mut dyn Backend) {
    let (fence, camera, lens) = builtin_mesh("fence", 80, 48);
    let layers = 4;
    let near = default_near(lens.focus_distance);
    let desc = MeshPeelDesc::new(&options(GuardBand::Auto, layers, true), near);
    let mut peel = MeshPeelContext::new(b, &fence.raster(), &camera, &lens, &desc).unwrap();
    let [w, h] = peel.size();
    let method = registry::method("multilayer").unwrap();
    let mut dof = (method.create)(b, &ContextDesc::new(Extent::new(w, h, layers), MethodOptions::default())).unwrap();
    let out = b.create_buffer(3 * w as u64 * h as u64, "test/out").unwrap();
    let before = b.counters();
    let frames = 4;
    for i in 0..frames {
        let cam = orbit(&camera, lens.focus_distance, i as f32);
        peel.record(b, &cam, &lens).unwrap();
        dof.record(b, &peel.frame(lens, FrameOutput::Buffer(RgbBuffer(out)))).unwrap();
        let times = b.submit().unwrap();
        // Every pass is recorded, the ones that draw nothing too (one shading dispatch each).
        assert_eq!(times.iter().filter(|t| t.label == "peel/shade").count(), desc.passes().unwrap() as usize, "passes recorded");
    }
    let c = b.counters().since(&before);
    assert_eq!((c.allocations, c.uploads, c.readbacks, c.submissions), (0, 0, 0, frames), "per frame: {c:?}");
    let report = peel.peel_report(b).unwrap();
    assert_eq!(report.recorded, layers + desc.translucent_passes);
    assert!(report.with_surface >= 2, "{report:?}");
    let image = b.read_buffer(out, 0, 3 * w as u64 * h as u64).unwrap();
    assert!(image.iter().all(|&v| f32::from_bits(v).is_finite()) && image.iter().any(|&v| f32::from_bits(v) > 0.0));
    dof.destroy(b);
    peel.destroy(b);
    b.destroy_buffer(out);
}

#[test]
fn an_orbiting_frame_allocates_uploads_and_reads_back_nothing_on_the_cpu() {
    orbiting_frames_on(&mut CpuBackend::new());
}

#[test]
fn an_orbiting_frame_allocates_uploads_and_reads_back_nothing_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    orbiting_frames_on(&mut vk);
    assert_clean(&mut vk);
}

/// Two parallel walls in front of the sky: the third pass finds nothing, and the fourth and later
/// draw nothing, while every pass is still recorded.
fn extra_passes_find_nothing_on(b: &mut dyn Backend) {
    let mut m = MeshScene::default();
    m.materials.push(MeshMaterial { base: [0.8, 0.2, 0.2, 1.0], flags: UNLIT, ..MeshMaterial::default() });
    m.materials.push(MeshMaterial { base: [0.2, 0.8, 0.2, 1.0], flags: UNLIT, ..MeshMaterial::default() });
    quad(&mut m, Vec3::new(-0.5, -0.5, -2.0), Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0), 0);
    quad(&mut m, Vec3::new(-4.0, -4.0, -9.0), Vec3::new(8.0, 0.0, 0.0), Vec3::new(0.0, 8.0, 0.0), 1);
    let camera = Camera::look_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0), 60f32.to_radians(), 128, 80);
    let lens = ThinLens { focal_length: 0.05, aperture_radius: 0.05, focus_distance: 5.0, pixels_per_unit: 80.0 / 0.024 };
    let layers = 6;
    let opts = options(GuardBand::Off, layers, false);
    assert_same_as_host(b, &m, &camera, &lens, &opts);
    let near = default_near(lens.focus_distance);
    let mut ctx = MeshPeelContext::new(b, &m.raster(), &camera, &lens, &MeshPeelDesc::new(&opts, near)).unwrap();
    device_peel(b, &mut ctx, &camera, &lens);
    let report = ctx.peel_report(b).unwrap();
    let recorded = layers + opts.translucent_passes;
    assert_eq!((report.recorded, report.with_surface), (recorded, 2), "{report:?}");
    assert_eq!(report.drawn, 3, "the pass after the last surface draws, the rest do not: {report:?}");
    let figures = ctx.report(b).unwrap().figures();
    assert_eq!(figures["peel_passes_recorded"], recorded as f64);
    ctx.destroy(b);
}

#[test]
fn passes_past_the_last_surface_draw_nothing_on_the_cpu() {
    extra_passes_find_nothing_on(&mut CpuBackend::new());
}

#[test]
fn passes_past_the_last_surface_draw_nothing_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    extra_passes_find_nothing_on(&mut vk);
    assert_clean(&mut vk);
}

#[test]
fn a_peel_context_refuses_bad_views_and_another_backend() {
    let (m, camera, lens) = masked_bars();
    let mut b = CpuBackend::new();
    let desc = MeshPeelDesc::new(&options(GuardBand::Pixels(2), 2, true), 0.01);
    assert!(MeshPeelContext::new(&mut b, &m.raster(), &camera, &lens, &MeshPeelDesc { max_layers: 0, ..desc }).is_err());
    assert!(MeshPeelContext::new(&mut b, &m.raster(), &camera, &lens, &MeshPeelDesc { near: f32::NAN, ..desc }).is_err());
    assert!(MeshPeelContext::new(&mut b, &m.raster(), &camera, &lens, &MeshPeelDesc { edge_depth_ratio: -1.0, ..desc }).is_err());
    let mut ctx = MeshPeelContext::new(&mut b, &m.raster(), &camera, &lens, &desc).unwrap();
    let wider = Camera { width: camera.width + 1, ..camera };
    assert!(ctx.record(&mut b, &wider, &lens).is_err(), "another frame size");
    let bad_lens = ThinLens { focus_distance: f32::NAN, ..lens };
    assert!(ctx.record(&mut b, &camera, &bad_lens).is_err(), "an invalid lens");
    let mut other = CpuBackend::new();
    let err = ctx.record(&mut other, &camera, &lens).unwrap_err().to_string();
    assert!(err.contains("another backend"), "{err}");
    ctx.record(&mut b, &camera, &lens).unwrap();
    ctx.destroy(&mut b);
    assert_eq!(b.counters().device_bytes, 0, "everything freed");
}

/// The band each frame's view needs is computed on the device with the host's rule
/// (`auto_margin_mesh`) and counted when it exceeds the band the context was made with.
fn band_per_view_on(b: &mut dyn Backend) {
    let (fence, camera, lens) = builtin_mesh("fence", 80, 45);
    let near = default_near(lens.focus_distance);
    let host = dof::scene::guard_band::auto_margin_mesh(fence.raster().triangle_positions(), &camera, &lens, near).unwrap();
    assert!(host > 1, "the fence needs a band: {host}");
    for (band, exceeded) in [(GuardBand::Auto, 0), (GuardBand::Pixels(host - 1), 2)] {
        let desc = MeshPeelDesc::new(&options(band, 2, true), near);
        let mut ctx = MeshPeelContext::new(b, &fence.raster(), &camera, &lens, &desc).unwrap();
        for _ in 0..2 {
            ctx.record(b, &camera, &lens).unwrap();
            b.submit().unwrap();
        }
        let report = ctx.peel_report(b).unwrap();
        assert_eq!((report.band_needed, report.band_exceeded_frames), (host, exceeded), "{band:?}: {report:?}");
        ctx.destroy(b);
    }
}

#[test]
fn the_band_a_view_needs_is_found_on_the_device_on_the_cpu() {
    band_per_view_on(&mut CpuBackend::new());
}

#[test]
fn the_band_a_view_needs_is_found_on_the_device_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    band_per_view_on(&mut vk);
    assert_clean(&mut vk);
}
