//! Depth peeling with a renderer's own passes (`frame::RendererPeel`) against the library's own
//! mesh peel (`MeshPeelContext`) of the same view, on the CPU backend and on Vulkan.
//!
//! The "renderer" here is the test's own, on the host: per pass it casts each pixel centre's ray
//! (the rasteriser's sample point) against a scene of quads facing the camera, keeps the nearest
//! fragment that `dof_shaders::renderer_peel::keep` accepts against the library's bound (read back: this
//! test checks the library's logic, not a real-time loop; `examples/ash_host.rs` peels with a GPU
//! pipeline), and writes RGBA16F colour and a D32 or D24 depth attachment, standard or reversed
//! planes. Quads facing the camera have one planar depth over their whole area, so the rasteriser
//! and the ray cast give the same fragments; what differs is precision:
//! - colour goes through RGBA16F: within half a half-float step (2^-11 relative);
//! - depth goes through the attachment's encoding and back: within 1e-4 relative (D24 steps at
//!   these depths are below 1e-5 relative);
//! - counts and the disocclusion buffer are equal.
//!
//! Frames in flight: two frames of different scenes through one peel each keep their own report.
//!
//! And the D24 case does not peel a surface again: a half-covering quad (whose reach is its own
//! depth, no umbra) gives exactly two slots, itself and the background.

use dof::backend::vulkan::ash::vk;
use dof::backend::{Backend, BufferId, CpuBackend, ImageFormat, ImageRef, RawOptions, VulkanBackend};
use dof::frame::peel::{PeelFrameReport, PeelReport};
use dof::frame::{DepthEncoding, RendererPeel, RendererPeelDesc};
use dof::raster::{MeshPeelContext, MeshPeelDesc};
use dof::scene::{Camera, GuardBand, LayerOptions, MeshScene, Vec3};
use dof_shaders::half::f32_to_f16;
use dof_shaders::lens::ThinLens;
use dof_shaders::raster::mesh::{ALPHA_BLEND, MeshMaterial, MeshVertex, UNLIT};
use dof_shaders::renderer_peel::keep;
use dof_tests::renderer::{Renderer, assert_no_messages};

const NEAR: f32 = 0.1;
const FAR: f32 = 100.0;

/// An axis-aligned quad facing the camera (+z): its corner, size, depth plane and material.
#[derive(Clone, Copy)]
struct Quad {
    x: f32,
    y: f32,
    w: f32,
    h: f32,
    z: f32,
    material: u32,
}

struct Scene {
    mesh: MeshScene,
    quads: Vec<Quad>,
    camera: Camera,
    lens: ThinLens,
}

fn scene(quads: Vec<Quad>, materials: Vec<MeshMaterial>) -> Scene {
    let mut mesh = MeshScene { materials, ..MeshScene::default() };
    for q in &quads {
        let base = mesh.vertices.len() as u32;
        for (x, y) in [(q.x, q.y), (q.x + q.w, q.y), (q.x + q.w, q.y + q.h), (q.x, q.y + q.h)] {
            mesh.vertices.push(MeshVertex { position: [x, y, q.z], normal: [0.0, 0.0, 1.0], ..MeshVertex::default() });
        }
        mesh.triangles.push([base, base + 1, base + 2, q.material]);
        mesh.triangles.push([base, base + 2, base + 3, q.material]);
    }
    mesh.lighting.background = [0.5, 0.7, 1.0];
    let camera = Camera::look_at(Vec3::new(0.03, 0.02, 0.0), Vec3::new(0.03, 0.02, -1.0), 50f32.to_radians(), 72, 40);
    let lens = ThinLens { focal_length: 0.05, aperture_radius: 0.1, focus_distance: 3.0, pixels_per_unit: 40.0 / 0.024 };
    Scene { mesh, quads, camera, lens }
}

fn unlit(base: [f32; 4], blend: bool) -> MeshMaterial {
    MeshMaterial { base, flags: UNLIT | if blend { ALPHA_BLEND } else { 0 }, ..MeshMaterial::default() }
}

/// A far wall, a half-covering pane before it, and an opaque near bar before both.
fn layered_scene() -> Scene {
    let quads = vec![
        Quad { x: -5.0, y: -2.0, w: 9.0, h: 5.0, z: -8.0, material: 0 },
        Quad { x: -1.1, y: -0.7, w: 1.6, h: 1.1, z: -3.0, material: 1 },
        Quad { x: -0.33, y: -0.9, w: 0.21, h: 1.5, z: -1.3, material: 2 },
    ];
    scene(quads, vec![unlit([0.2, 0.4, 0.8, 1.0], false), unlit([0.9, 0.3, 0.2, 0.5], true), unlit([0.8, 0.7, 0.1, 1.0], false)])
}

/// One half-covering pane at the focus distance: its reach is its own depth.
fn pane_scene() -> Scene {
    scene(vec![Quad { x: -0.9, y: -0.6, w: 1.5, h: 1.0, z: -3.0, material: 0 }], vec![unlit([0.3, 0.8, 0.4, 0.5], true)])
}

fn options(layers: u32, disocclusion: bool) -> LayerOptions {
    LayerOptions { max_layers: layers, guard_band: GuardBand::Pixels(0), disocclusion, ..LayerOptions::default() }
}

/// The depth-buffer value of planar depth `z` (the renderer's projection).
fn encode(encoding: DepthEncoding, z: f32) -> f32 {
    match encoding {
        DepthEncoding::Standard { near, far } if far.is_infinite() => 1.0 - near / z,
        DepthEncoding::Standard { near, far } => far * (z - near) / (z * (far - near)),
        DepthEncoding::Reversed { near, far } if far.is_infinite() => near / z,
        DepthEncoding::Reversed { near, far } => near * (far - z) / (z * (far - near)),
        DepthEncoding::Linear => z,
    }
}

/// The test's renderer: pass `bound`'s fragments into RGBA16F colour and `format` depth texels.
fn render_pass(s: &Scene, encoding: DepthEncoding, format: ImageFormat, bound: &[u32]) -> (Vec<u32>, Vec<u32>) {
    let frame = s.camera.frame().unwrap();
    let (w, h) = (frame.width, frame.height);
    let (mut color, mut depth) = (Vec::new(), Vec::new());
    let clear = if matches!(encoding, DepthEncoding::Reversed { .. }) { 0.0 } else { 1.0 };
    for y in 0..h {
        for x in 0..w {
            let ray = frame.pixel_ray(x, y);
            let b = f32::from_bits(bound[(y * w + x) as usize]);
            let mut best: Option<(f32, f32, Quad)> = None;
            for q in &s.quads {
                // Planar depth of the quad's plane along the ray (its direction has a unit component
                // along the view axis, -z here).
                let t = (q.z - ray.origin.z) / ray.direction.z;
                let p = ray.at(t);
                let inside = p.x >= q.x && p.x < q.x + q.w && p.y >= q.y && p.y < q.y + q.h;
                let d = encode(encoding, t);
                let d = if format == ImageFormat::D32Float { d } else { (d * 16_777_215.0).round() / 16_777_215.0 };
                if inside && t > NEAR && keep(d, b) && best.is_none_or(|(bt, ..)| t < bt) {
                    best = Some((t, d, *q));
                }
            }
            let (rgba, d) = match best {
                Some((_, d, q)) => (s.mesh.materials[q.material as usize].base, d),
                None => {
                    let bg = s.mesh.lighting.background;
                    ([bg[0], bg[1], bg[2], 1.0], clear)
                }
            };
            let half = |v: f32| f32_to_f16(v);
            color.push(half(rgba[0]) | half(rgba[1]) << 16);
            color.push(half(rgba[2]) | half(rgba[3]) << 16);
            depth.push(if format == ImageFormat::D32Float { d.to_bits() } else { (d * 16_777_215.0).round() as u32 });
        }
    }
    (color, depth)
}

/// The slots, counts and mask a peel left.
fn read_slots(b: &mut dyn Backend, s: &dof::frame::peel::PeelSlots) -> (Vec<f32>, Vec<u32>, Vec<u32>) {
    let pixels = s.width as u64 * s.height as u64;
    let fragments = b.read_buffer(s.fragments, 0, dof::methods::buffers::SLOT_WORDS as u64 * pixels * s.layers as u64).unwrap();
    let counts = b.read_buffer(s.counts, 0, pixels).unwrap();
    let mask = b.read_buffer(s.mask, 0, pixels).unwrap();
    (fragments.into_iter().map(f32::from_bits).collect(), counts, mask)
}

/// The library's own peel of the scene.
fn mesh_peel(a: &mut dyn Attachments, s: &Scene, options: &LayerOptions) -> (Vec<f32>, Vec<u32>, Vec<u32>) {
    let mut ctx = MeshPeelContext::new(a.backend(), &s.mesh.raster(), &s.camera, &s.lens, &MeshPeelDesc::new(options, NEAR)).unwrap();
    assert_eq!(ctx.margin(), 0);
    a.record(&mut |b| ctx.record(b, &s.camera, &s.lens).unwrap());
    let got = read_slots(a.backend(), ctx.slots());
    ctx.destroy(a.backend());
    got
}

/// Where the test's renderer puts its attachments: the CPU backend's images, or Vulkan images of
/// the test's own device.
trait Attachments {
    fn backend(&mut self) -> &mut dyn Backend;
    /// Runs `record` as one recording of the library (the caller's command buffer on Vulkan).
    fn record(&mut self, record: &mut dyn FnMut(&mut dyn Backend));
    /// Writes the pass's texels into the colour attachment and the depth attachment of `format`.
    fn draw(&mut self, format: ImageFormat, color: &[u32], depth: &[u32]) -> (ImageRef, ImageRef);
}

struct CpuAttachments {
    cpu: CpuBackend,
    /// Colour, D32 and D24 depth.
    images: [ImageRef; 3],
}

impl Attachments for CpuAttachments {
    fn backend(&mut self) -> &mut dyn Backend {
        &mut self.cpu
    }
    fn record(&mut self, record: &mut dyn FnMut(&mut dyn Backend)) {
        record(&mut self.cpu);
        self.cpu.submit().unwrap();
    }
    fn draw(&mut self, format: ImageFormat, color: &[u32], depth: &[u32]) -> (ImageRef, ImageRef) {
        let depth_image = self.images[if format == ImageFormat::D32Float { 1 } else { 2 }];
        self.cpu.write_image(&self.images[0], color).unwrap();
        self.cpu.write_image(&depth_image, depth).unwrap();
        (self.images[0], depth_image)
    }
}

struct VulkanAttachments {
    r: Renderer,
    vk: Option<VulkanBackend>,
    /// Colour (RGBA16F), D32 and D24 depth.
    images: [vk::Image; 3],
    extent: [u32; 2],
    staging: [dof_tests::renderer::OwnBuffer; 2],
}

impl Attachments for VulkanAttachments {
    fn backend(&mut self) -> &mut dyn Backend {
        self.vk.as_mut().unwrap()
    }
    fn record(&mut self, record: &mut dyn FnMut(&mut dyn Backend)) {
        self.r.begin();
        let vk = self.vk.as_mut().unwrap();
        // SAFETY: the renderer's command buffer is recording and stays alive until it completed.
        unsafe { vk.begin_external(self.r.cb) }.unwrap();
        record(vk);
        vk.end_external().unwrap();
        self.r.submit_and_wait();
    }
    fn draw(&mut self, format: ImageFormat, color: &[u32], depth: &[u32]) -> (ImageRef, ImageRef) {
        let pick = [(self.images[0], ImageFormat::Rgba16Float), (self.images[if format == ImageFormat::D32Float { 1 } else { 2 }], format)];
        Renderer::write(&self.staging[0], color);
        Renderer::write(&self.staging[1], depth);
        self.r.begin();
        // Left as a renderer's pass leaves them: colour and depth attachment writes done.
        let colour_after = (vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT, vk::AccessFlags::COLOR_ATTACHMENT_WRITE);
        let depth_after = (vk::PipelineStageFlags::LATE_FRAGMENT_TESTS, vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE);
        let layouts = [vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL, vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL];
        let mut refs = Vec::new();
        for (i, after) in [colour_after, depth_after].into_iter().enumerate() {
            let (image, format) = pick[i];
            self.r.upload_image(&self.staging[i], image, format, self.extent, layouts[i], after.0, after.1);
            // SAFETY: the test's live image of this format and extent.
            refs.push(unsafe {
                ImageRef::describe(image, format.vk_format(), self.extent).unwrap().in_layout(layouts[i]).after(after.0, after.1).build()
            });
        }
        self.r.submit_and_wait();
        (refs[0], refs[1])
    }
}

/// The renderer-style peel of `s`, pass by pass.
fn renderer_peel(
    a: &mut dyn Attachments,
    s: &Scene,
    options: &LayerOptions,
    encoding: DepthEncoding,
    format: ImageFormat,
    bound: BufferId,
) -> (Vec<f32>, Vec<u32>, Vec<u32>) {
    let mut peel = make_peel(a, s, options, encoding, format, bound, 1);
    peel_frame(a, &mut peel, s, encoding, format, bound);
    let got = read_slots(a.backend(), peel.slots());
    let report = peel.report(a.backend()).unwrap();
    assert_eq!(report.recorded, options.max_layers);
    assert!(report.with_surface >= 1 && report.drawn >= report.with_surface, "{report:?}");
    peel.destroy(a.backend());
    got
}

fn make_peel(
    a: &mut dyn Attachments,
    s: &Scene,
    options: &LayerOptions,
    encoding: DepthEncoding,
    format: ImageFormat,
    bound: BufferId,
    frames_in_flight: u32,
) -> RendererPeel {
    let frame = s.camera.frame().unwrap();
    let desc = RendererPeelDesc {
        depth_format: format,
        frames_in_flight,
        ..RendererPeelDesc::new(options, frame.width, frame.height, encoding, frame.tan_half_fov, 6)
    };
    RendererPeel::new(a.backend(), &desc, bound, None).unwrap()
}

/// One frame of `s` through `peel`: begin, every pass drawn by the test's renderer against the
/// bound and appended, finish.
fn peel_frame(a: &mut dyn Attachments, peel: &mut RendererPeel, s: &Scene, encoding: DepthEncoding, format: ImageFormat, bound: BufferId) {
    let [w, h] = peel.size();
    a.record(&mut |b| peel.begin(b, &s.lens).unwrap());
    for k in 0..peel.layers() {
        let bounds = a.backend().read_buffer(bound, 0, w as u64 * h as u64).unwrap();
        if k == 0 {
            assert!(bounds.iter().all(|&v| f32::from_bits(v) == f32::NEG_INFINITY), "pass 0 keeps every fragment");
        }
        let (color, depth) = render_pass(s, encoding, format, &bounds);
        let (ci, di) = a.draw(format, &color, &depth);
        a.record(&mut |b| peel.append(b, k, ci, di).unwrap());
    }
    a.record(&mut |b| peel.finish(b).unwrap());
}

/// Frames in flight: two frames of different scenes through a peel made for two each report
/// what the same frame reports alone; a third report back, and a report before any frame, are
/// refused; a one-frame peel keeps only the last frame's.
fn reports_of_frames_in_flight(a: &mut dyn Attachments, bound: BufferId) {
    let scenes = [layered_scene(), pane_scene()];
    let options = options(4, false);
    let (encoding, format) = (ENCODINGS[1], ImageFormat::D32Float);
    let alone: Vec<PeelReport> = scenes
        .iter()
        .map(|s| {
            let mut peel = make_peel(a, s, &options, encoding, format, bound, 1);
            peel_frame(a, &mut peel, s, encoding, format, bound);
            let report = peel.report(a.backend()).unwrap();
            assert!(peel.report_of(a.backend(), 1).is_err(), "a one-frame peel keeps only the last frame's report");
            peel.destroy(a.backend());
            report
        })
        .collect();
    assert_ne!(alone[0], alone[1], "the two frames report alike, so the check below could not fail");
    let mut peel = make_peel(a, &scenes[0], &options, encoding, format, bound, 2);
    assert_eq!(peel.frames_in_flight(), 2);
    assert!(peel.report(a.backend()).is_err(), "a report before any frame");
    for s in &scenes {
        peel_frame(a, &mut peel, s, encoding, format, bound);
    }
    assert_eq!(peel.report_of(a.backend(), 1).unwrap(), alone[0], "the first frame's report");
    assert_eq!(peel.report_of(a.backend(), 0).unwrap(), alone[1], "the second frame's report");
    let typed = peel.report_frame(a.backend(), 1).unwrap();
    assert_eq!(typed.details::<PeelFrameReport>().map(|r| &r.peel), Some(&alone[0]), "the typed report");
    assert!(peel.report_of(a.backend(), 2).is_err(), "a report beyond the frames in flight");
    peel.destroy(a.backend());
}

/// Asserts two peels hold the same slots within the precision of the attachments.
fn assert_close(got: &(Vec<f32>, Vec<u32>, Vec<u32>), want: &(Vec<f32>, Vec<u32>, Vec<u32>), layers: u32, what: &str) {
    assert_eq!(got.1, want.1, "{what}: slots per pixel");
    assert!(want.1.iter().any(|&c| c > 2), "{what}: the scene has pixels of three slots or more");
    assert_eq!(got.2, want.2, "{what}: the disocclusion buffer");
    for (p, &n) in want.1.iter().enumerate() {
        for k in 0..layers as usize {
            // The slot format's words (`dof_shaders::slot`): premultiplied colour, depth, alpha.
            let words = dof::methods::buffers::SLOT_WORDS as usize;
            let at = words * (p * layers as usize + k);
            for c in 0..words {
                let (g, e) = (got.0[at + c], want.0[at + c]);
                // Colour premultiplied by alpha, both rounded to RGBA16F here; depth; alpha.
                let tol = match c {
                    0..3 => 2f32.powi(-10) * e.abs(),
                    3 => 1e-4 * e.abs(),
                    _ => 2f32.powi(-11),
                };
                let same = g == e || (g - e).abs() <= tol;
                assert!(same, "{what}: pixel {p} slot {k} (of {n}) word {c}: {g} against the mesh peel's {e}");
            }
        }
    }
}

const ENCODINGS: [DepthEncoding; 3] = [
    DepthEncoding::Standard { near: NEAR, far: FAR },
    DepthEncoding::Reversed { near: NEAR, far: FAR },
    DepthEncoding::Reversed { near: NEAR, far: f32::INFINITY },
];

fn equal_to_mesh_peel(a: &mut dyn Attachments, bound: BufferId) {
    let s = layered_scene();
    for disocclusion in [false, true] {
        let options = options(4, disocclusion);
        let want = mesh_peel(a, &s, &options);
        for encoding in ENCODINGS {
            for format in [ImageFormat::D32Float, ImageFormat::D24UnormS8Uint] {
                let got = renderer_peel(a, &s, &options, encoding, format, bound);
                assert_close(&got, &want, options.max_layers, &format!("{encoding:?} {format} disocclusion {disocclusion}"));
            }
        }
    }
    // D24: the pane (reach = its own depth) is peeled once, then the background behind it.
    let s = pane_scene();
    let options = options(4, false);
    let want = mesh_peel(a, &s, &options);
    for encoding in ENCODINGS {
        let got = renderer_peel(a, &s, &options, encoding, ImageFormat::D24UnormS8Uint, bound);
        assert!(got.1.iter().all(|&c| c <= 2), "{encoding:?}: a D24 surface peeled again");
        assert!(got.1.contains(&2), "{encoding:?}: the pane was not peeled");
        assert_eq!(got.1, want.1, "{encoding:?}: slots per pixel");
    }
}

#[test]
/// The mesh peel's slots, and each frame in flight's report.
fn renderer_peel_on_the_cpu() {
    let mut cpu = CpuBackend::new();
    let extent = [72, 40];
    let bound = cpu.create_buffer(72 * 40, "test/bound").unwrap();
    let images =
        [ImageFormat::Rgba16Float, ImageFormat::D32Float, ImageFormat::D24UnormS8Uint].map(|f| cpu.create_image(f, extent).unwrap());
    let mut a = CpuAttachments { cpu, images };
    equal_to_mesh_peel(&mut a, bound);
    reports_of_frames_in_flight(&mut a, bound);
}

#[test]
/// The same on the test's own Vulkan device, with validation.
fn renderer_peel_on_vulkan() {
    let Some(mut r) = Renderer::new() else { return };
    let extent = [72, 40];
    let images = [ImageFormat::Rgba16Float, ImageFormat::D32Float, ImageFormat::D24UnormS8Uint].map(|f| r.image(f, extent));
    let staging = [r.host_buffer(8 * 72 * 40), r.host_buffer(4 * 72 * 40)];
    // SAFETY: the renderer's device outlives the backend (dropped before `finish`).
    let mut vk = unsafe { VulkanBackend::from_raw(r.raw(), &RawOptions::default()) }.unwrap();
    let bound = vk.create_buffer(72 * 40, "test/bound").unwrap();
    let mut a = VulkanAttachments { r, vk: Some(vk), images, extent, staging };
    equal_to_mesh_peel(&mut a, bound);
    reports_of_frames_in_flight(&mut a, bound);
    let mut vk = a.vk.take().unwrap();
    dof_tests::assert_clean(&mut vk);
    vk.destroy_buffer(bound);
    drop(vk);
    assert_no_messages(a.r.finish(), "the renderer peel");
}

#[test]
fn renderer_peel_refuses_misuse_before_recording() {
    let mut cpu = CpuBackend::new();
    let s = layered_scene();
    let frame = s.camera.frame().unwrap();
    let (w, h) = (frame.width, frame.height);
    let bound = cpu.create_buffer(w as u64 * h as u64, "test/bound").unwrap();
    let small = cpu.create_buffer(4, "test/small").unwrap();
    let encoding = ENCODINGS[0];
    let desc = RendererPeelDesc::new(&options(3, true), w, h, encoding, frame.tan_half_fov, 6);
    // Creation: a bound buffer too small, a linear encoding, an R32F depth attachment.
    assert!(RendererPeel::new(&mut cpu, &desc, small, None).is_err());
    assert!(RendererPeel::new(&mut cpu, &desc, bound, Some(small)).is_err());
    let linear = RendererPeelDesc { encoding: DepthEncoding::Linear, ..desc };
    assert!(RendererPeel::new(&mut cpu, &linear, bound, None).is_err());
    let r32 = RendererPeelDesc { depth_format: ImageFormat::R32Float, ..desc };
    assert!(RendererPeel::new(&mut cpu, &r32, bound, None).is_err());
    let mut peel = RendererPeel::new(&mut cpu, &desc, bound, None).unwrap();
    let color = cpu.create_image(ImageFormat::Rgba16Float, [w, h]).unwrap();
    let depth = cpu.create_image(ImageFormat::D32Float, [w, h]).unwrap();
    let d24 = cpu.create_image(ImageFormat::D24UnormS8Uint, [w, h]).unwrap();
    let tiny = cpu.create_image(ImageFormat::Rgba16Float, [w - 1, h]).unwrap();
    cpu.submit().unwrap();
    let commands = cpu.counters().commands;
    // Out of order, before begin, after the last pass; the wrong depth format; a small image.
    assert!(peel.append(&mut cpu, 0, color, depth).is_err(), "append before begin");
    assert!(peel.finish(&mut cpu).is_err(), "finish before begin");
    assert_eq!(cpu.counters().commands, commands, "a refused call recorded something");
    peel.begin(&mut cpu, &s.lens).unwrap();
    let commands = cpu.counters().commands;
    assert!(peel.append(&mut cpu, 1, color, depth).is_err(), "pass 1 before pass 0");
    assert!(peel.append(&mut cpu, 0, color, d24).is_err(), "a D24 image on a D32 peel");
    assert!(peel.append(&mut cpu, 0, tiny, depth).is_err(), "an image smaller than the peel");
    assert!(peel.finish(&mut cpu).is_err(), "finish before the last pass");
    assert_eq!(cpu.counters().commands, commands, "a refused call recorded something");
    for k in 0..3 {
        peel.append(&mut cpu, k, color, depth).unwrap();
    }
    assert!(peel.append(&mut cpu, 3, color, depth).is_err(), "a pass beyond the last");
    peel.finish(&mut cpu).unwrap();
    cpu.submit().unwrap();
    peel.destroy(&mut cpu);
}
