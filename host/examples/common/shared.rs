//! What both example hosts (`ash_host`, `wgpu_host`) share: the scene they peel with their own
//! passes and its camera, the check of their frames (the same `SplatContext` on the library's CPU backend, run
//! from the same slot words: the CPU backend runs the very kernels the device does), and the EXR
//! and PNG files they write.

use anyhow::{Context, Result, ensure};
use dof_core::ThinLens;
use dof_core::backend::{Backend, BufferId, CpuBackend};
use dof_core::frame::{CountBuffer, DofContext, Frame, RgbBuffer, SlotBuffer, SplatContext, SplatContextDesc};
use dof_shaders::slot::SLOT_WORDS;
use dof_shaders::tonemap::tonemap_channel;
use glam::{Mat4, Vec3};

/// A result image: RGB, row-major.
pub struct Rgb {
    pub width: u32,
    pub height: u32,
    pub data: Vec<[f32; 3]>,
}

/// The check every frame is compared with: the same context on the library's CPU backend, run from
/// the same slot words (the CPU backend runs the very kernels the device does).
pub struct CpuCheck {
    cpu: CpuBackend,
    ctx: SplatContext,
    slots: BufferId,
    counts: BufferId,
    out: BufferId,
    extent: [u32; 2],
}

impl CpuCheck {
    pub fn new(shared_bytes: u32, desc: &SplatContextDesc) -> Result<Self> {
        // The device's workgroup memory, so that both plan the same sort.
        let mut cpu = CpuBackend::with_shared_bytes(shared_bytes);
        let pixels = desc.max_width as u64 * desc.max_height as u64;
        let ctx = SplatContext::new(&mut cpu, desc)?;
        let slots = cpu.create_buffer(SLOT_WORDS as u64 * pixels * desc.max_layers as u64, "check/slots")?;
        let counts = cpu.create_buffer(pixels, "check/counts")?;
        let out = cpu.create_buffer(3 * pixels, "check/out")?;
        Ok(CpuCheck { cpu, ctx, slots, counts, out, extent: [desc.max_width, desc.max_height] })
    }

    /// The image of `layers` slots a pixel (`slots`, with their `counts`) through `lens`.
    pub fn run(&mut self, slots: &[u32], counts: &[u32], layers: u32, lens: ThinLens) -> Result<Rgb> {
        let [w, h] = self.extent;
        self.cpu.write_buffer(self.slots, 0, slots)?;
        self.cpu.write_buffer(self.counts, 0, counts)?;
        let (slots, counts, out) = (SlotBuffer::current(self.slots), CountBuffer(self.counts), RgbBuffer(self.out));
        self.ctx.record(&mut self.cpu, &Frame::layers(w, h, layers, lens, slots, counts, out))?;
        self.cpu.submit()?;
        let overflow = self.ctx.report(&mut self.cpu)?.overflow_tiles;
        ensure!(overflow == 0, "the CPU check's list pool overflowed in {overflow} tiles");
        let words = self.cpu.read_buffer(self.out, 0, 3 * w as u64 * h as u64)?;
        let data = words.as_chunks::<3>().0.iter().map(|c| c.map(f32::from_bits)).collect();
        Ok(Rgb { width: w, height: h, data })
    }

    pub fn destroy(mut self) {
        self.ctx.destroy(&mut self.cpu);
        for id in [self.slots, self.counts, self.out] {
            self.cpu.destroy_buffer(id);
        }
    }
}

/// Writes `image` as an EXR (32-bit float RGB) and a PNG preview (the library's tone map,
/// `dof_shaders::tonemap::tonemap_channel`, as the `dof` command's previews).
pub fn write_image(path: &std::path::Path, image: &Rgb) -> Result<()> {
    let w = image.width as usize;
    exr::prelude::write_rgb_file(path.with_extension("exr"), w, image.height as usize, |x, y| {
        let c = image.data[y * w + x];
        (c[0], c[1], c[2])
    })
    .with_context(|| format!("writing {}", path.with_extension("exr").display()))?;
    let bytes: Vec<u8> = image.data.iter().flat_map(|c| c.map(|v| (tonemap_channel(v, 1.0) * 255.0).round() as u8)).collect();
    let file =
        std::fs::File::create(path.with_extension("png")).with_context(|| format!("creating {}", path.with_extension("png").display()))?;
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), image.width, image.height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.write_header()?.write_image_data(&bytes)?;
    Ok(())
}

/// Compares with the CPU check's image: the largest difference per channel, and whether each
/// stays within 1e-3 of the channel's largest reference value.
pub fn compare(got: &Rgb, want: &Rgb) -> ([f32; 3], bool) {
    let mut diff = [0f32; 3];
    let mut peak = [0f32; 3];
    let mut finite = true;
    for (g, w) in got.data.iter().zip(&want.data) {
        for c in 0..3 {
            finite &= g[c].is_finite() == w[c].is_finite();
            diff[c] = diff[c].max((g[c] - w[c]).abs());
            peak[c] = peak[c].max(w[c].abs());
        }
    }
    (diff, finite && (0..3).all(|c| diff[c] <= 1e-3 * peak[c].max(1e-3)))
}

/// A vertex of the peeled scene: position, then colour and coverage.
pub type Vertex = [f32; 7];

/// The peeled scene: a far wall, a half-covering pane in focus and a near bar, as coloured
/// triangles.
pub fn peel_scene() -> Vec<Vertex> {
    let quad = |x0: f32, y0: f32, x1: f32, y1: f32, z: f32, c: [f32; 4]| {
        let v = |x: f32, y: f32| [x, y, z, c[0], c[1], c[2], c[3]];
        [v(x0, y0), v(x1, y0), v(x1, y1), v(x0, y0), v(x1, y1), v(x0, y1)]
    };
    [
        quad(-6.0, -3.0, 6.0, 3.0, -8.0, [0.2, 0.4, 0.8, 1.0]),
        quad(-1.0, -0.8, 0.6, 0.5, -3.0, [0.9, 0.3, 0.2, 0.5]),
        quad(-0.35, -1.2, -0.1, 1.2, -1.3, [0.8, 0.7, 0.1, 1.0]),
    ]
    .concat()
}

/// Clip space from view space (looking down −z), depth 0 at the near plane and 1 at the far plane
/// (the library's `DepthEncoding::Standard`); y down as Vulkan's clip space has it, or up as
/// wgpu's.
pub fn projection(yfov: f32, aspect: f32, near: f32, far: f32, y_down: bool) -> Mat4 {
    let t = 1.0 / (yfov / 2.0).tan();
    let ty = if y_down { -t } else { t };
    let (a, b) = (far / (near - far), near * far / (near - far));
    Mat4::from_cols_array(&[t / aspect, 0.0, 0.0, 0.0, 0.0, ty, 0.0, 0.0, 0.0, 0.0, a, -1.0, 0.0, 0.0, b, 0.0])
}

/// View space of a camera at `eye` looking at `target`, +y up.
pub fn look_at(eye: Vec3, target: Vec3) -> Mat4 {
    let f = (target - eye).normalize();
    let s = f.cross(Vec3::Y).normalize();
    let u = s.cross(f);
    Mat4::from_cols_array(&[s.x, u.x, -f.x, 0.0, s.y, u.y, -f.y, 0.0, s.z, u.z, -f.z, 0.0, -s.dot(eye), -u.dot(eye), f.dot(eye), 1.0])
}
