//! Depth and colour as renderers have them, through the frame API on both backends: each depth
//! format (D32, D24 with stencil, X8_D24, R32F) under each encoding (standard and reversed Z, each
//! with a finite and an infinite far plane; R32F also linear) and each colour format (RGBA32F,
//! RGBA16F, B10G11R11), from images larger than the frame (the top-left part is used) as often as
//! from images of its size.
//!
//! What is asserted, per case:
//! - the decoded input is within the format's precision of the scene it encodes: colour within
//!   half a unit in the last place (RGBA16F 2^-11 relative, B10G11R11 2^-7 for red and green and
//!   2^-6 for blue), view depth within z·(z/near)·2^-22 (half a step of a 24-bit unorm and the f32
//!   arithmetic, through the derivative of the projection; the f32 formats are finer);
//! - the frame from images equals the frame from buffers holding that decoded input: bit for bit
//!   on the CPU, within 1e-4 relative on Vulkan (where the device does the decoding's arithmetic);
//! - on Vulkan, the frame that samples the images in place (through views) equals, bit for bit,
//!   the frame that copies them first (the device's sampler decodes as the kernel decodes copies).
//!
//! On Vulkan the images are a renderer's own (`dof_tests::renderer`), left by its passes in their
//! attachment layouts, and the frames are recorded into its command buffer; the validation layer
//! must stay silent. The CPU backend's images are always read in place. Formats the device cannot copy from are reported and refused by name. On wgpu
//! they are a renderer's textures (the D24 formats as `Depth24PlusStencil8` and `Depth24Plus`,
//! every depth written by a pass), the frames recorded into its encoder.

use dof::backend::vulkan::ash::vk;
use dof::backend::{Backend, BufferId, CpuBackend, ImageFormat, ImageRef, RawOptions, VulkanBackend};
use dof::frame::{
    ContextDesc, CountBuffer, DepthEncoding, DofContext, Extent, Frame, FrameInput, FrameOutput, MethodOptions, RgbBuffer, SlotBuffer,
    registry,
};
use dof_shaders::frame_io::{
    DEPTH_F32, DEPTH_LINEAR, DEPTH_REVERSED, DEPTH_STANDARD, DEPTH_UNORM24, FrameIoParams, depth_value, view_depth,
};
use dof_shaders::half::{b10g11r11_to_f32, f16_to_f32, f32_to_f16};
use dof_tests::renderer::{Renderer, assert_no_messages};

const W: u32 = 48;
const H: u32 = 32;
const NEAR: f32 = 0.1;
const FAR: f32 = 100.0;
/// The method the frames go through (the input path is the same for every context).
const METHOD: &str = "multilayer";

#[derive(Clone, Copy, Debug)]
struct Case {
    color: ImageFormat,
    depth: ImageFormat,
    encoding: DepthEncoding,
    /// The images' extent (at least the frame's).
    image: [u32; 2],
}

fn cases() -> Vec<Case> {
    let encodings = [
        DepthEncoding::Standard { near: NEAR, far: FAR },
        DepthEncoding::Reversed { near: NEAR, far: FAR },
        DepthEncoding::Standard { near: NEAR, far: f32::INFINITY },
        DepthEncoding::Reversed { near: NEAR, far: f32::INFINITY },
    ];
    let mut cases = Vec::new();
    let depths = [ImageFormat::D32Float, ImageFormat::D24UnormS8Uint, ImageFormat::X8D24UnormPack32, ImageFormat::R32Float];
    for depth in depths {
        for encoding in encodings {
            cases.push((ImageFormat::Rgba16Float, depth, encoding));
        }
    }
    cases.push((ImageFormat::Rgba32Float, ImageFormat::R32Float, DepthEncoding::Linear));
    cases.push((ImageFormat::Rgba32Float, ImageFormat::D32Float, encodings[1]));
    cases.push((ImageFormat::B10G11R11Ufloat, ImageFormat::D24UnormS8Uint, encodings[3]));
    cases.push((ImageFormat::B10G11R11Ufloat, ImageFormat::R32Float, DepthEncoding::Linear));
    // Every other case reads the top-left of larger images.
    cases
        .into_iter()
        .enumerate()
        .map(|(i, (color, depth, encoding))| Case { color, depth, encoding, image: if i % 2 == 1 { [W + 7, H + 5] } else { [W, H] } })
        .collect()
}

/// The scene: smooth HDR colours and view depths from 0.5 to 20, with background pixels (at the
/// far plane, or at infinity where the encoding has one).
fn scene(encoding: DepthEncoding) -> (Vec<[f32; 3]>, Vec<f32>) {
    let background = match encoding {
        DepthEncoding::Standard { far, .. } | DepthEncoding::Reversed { far, .. } => far,
        DepthEncoding::Linear => f32::INFINITY,
    };
    let mut colors = Vec::new();
    let mut depths = Vec::new();
    for y in 0..H {
        for x in 0..W {
            let v = dof::stress::hash(y * W + x);
            colors.push([0.05 + x as f32 / W as f32, 3.0 * (v % 1000) as f32 / 1000.0, 0.25 + (y as f32 / H as f32).powi(2) * 40.0]);
            depths.push(if x + y < 6 { background } else { 0.5 + 19.5 * ((x * 7 + y * 3) % 61) as f32 / 60.0 });
        }
    }
    (colors, depths)
}

/// The depth-buffer value of view depth `z` (in f64), as a projection would write it.
fn depth_buffer_value(encoding: DepthEncoding, z: f32) -> f64 {
    let z = z as f64;
    match encoding {
        DepthEncoding::Linear => z,
        DepthEncoding::Standard { near, far } if far.is_infinite() => 1.0 - near as f64 / z,
        DepthEncoding::Reversed { near, far } if far.is_infinite() => near as f64 / z,
        DepthEncoding::Standard { near, far } => far as f64 * (z - near as f64) / (z * (far as f64 - near as f64)),
        DepthEncoding::Reversed { near, far } => near as f64 * (far as f64 - z) / (z * (far as f64 - near as f64)),
    }
}

/// A small unsigned float of `mbits` mantissa bits nearest to `v` (0 ≤ v, normal range), written
/// here independently of the decoder under test.
fn small_float(v: f32, mbits: u32) -> u32 {
    if v <= 0.0 {
        return 0;
    }
    let e = v.log2().floor() as i32;
    let mut m = ((v as f64 / 2f64.powi(e) - 1.0) * (1u32 << mbits) as f64).round() as u32;
    let mut e = e + 15;
    if m == 1 << mbits {
        m = 0;
        e += 1;
    }
    assert!((1..31).contains(&e), "{v} outside the normal range of the test's encoder");
    ((e as u32) << mbits) | m
}

/// The images' texels (packed as the copies pack them) for `case`, over the images' whole extent:
/// outside the frame they hold junk that must never be read (NaN colour, the near plane).
fn texels(case: &Case) -> (Vec<u32>, Vec<u32>) {
    let (colors, depths) = scene(case.encoding);
    let [iw, ih] = case.image;
    let mut color = Vec::new();
    let mut depth = Vec::new();
    for y in 0..ih {
        for x in 0..iw {
            let inside = x < W && y < H;
            let c = if inside { colors[(y * W + x) as usize] } else { [f32::NAN; 3] };
            let z = if inside { depths[(y * W + x) as usize] } else { NEAR };
            match case.color {
                ImageFormat::Rgba32Float => color.extend([c[0].to_bits(), c[1].to_bits(), c[2].to_bits(), 1f32.to_bits()]),
                ImageFormat::Rgba16Float => {
                    color.extend([f32_to_f16(c[0]) | (f32_to_f16(c[1]) << 16), f32_to_f16(c[2]) | (f32_to_f16(1.0) << 16)])
                }
                ImageFormat::B10G11R11Ufloat if inside => {
                    color.push(small_float(c[0], 6) | (small_float(c[1], 6) << 11) | (small_float(c[2], 5) << 22))
                }
                ImageFormat::B10G11R11Ufloat => color.push(0xffff_ffff),
                other => panic!("{other} is no colour format"),
            }
            let d = if z.is_infinite() && case.encoding == DepthEncoding::Linear {
                f64::INFINITY
            } else {
                depth_buffer_value(case.encoding, z)
            };
            depth.push(if case.depth.is_unorm24() {
                // The stencil (or X8 junk) in the high byte, which the depth aspect's copy leaves undefined.
                (d * 16_777_215.0).round() as u32 | 0xa5 << 24
            } else {
                (d as f32).to_bits()
            });
        }
    }
    (color, depth)
}

/// The kernels' parameters for decoding `case`'s images.
fn io_params(case: &Case) -> FrameIoParams {
    let (depth_encoding, near, far) = match case.encoding {
        DepthEncoding::Linear => (DEPTH_LINEAR, 0.0, 0.0),
        DepthEncoding::Standard { near, far } => (DEPTH_STANDARD, near, far),
        DepthEncoding::Reversed { near, far } => (DEPTH_REVERSED, near, far),
    };
    let depth_format = if case.depth.is_unorm24() { DEPTH_UNORM24 } else { DEPTH_F32 };
    FrameIoParams {
        width: W,
        height: H,
        color_words: case.color.words_per_pixel() as u32,
        depth_encoding,
        near,
        far,
        layers: 1,
        depth_format,
    }
}

/// The frame's input decoded on the host with the shader crate's functions (one slot a pixel: red,
/// green, blue, view depth), after checking it against the scene to the format's precision.
fn decoded_input(case: &Case) -> Vec<u32> {
    let (color, depth) = texels(case);
    let (colors, depths) = scene(case.encoding);
    let p = io_params(case);
    let wpp = case.color.words_per_pixel() as usize;
    let mut slots = Vec::new();
    for y in 0..H as usize {
        for x in 0..W as usize {
            let t = y * case.image[0] as usize + x;
            let c = match case.color {
                ImageFormat::Rgba32Float => [0, 1, 2].map(|k| f32::from_bits(color[wpp * t + k])),
                ImageFormat::Rgba16Float => {
                    let (rg, ba) = (color[wpp * t], color[wpp * t + 1]);
                    [f16_to_f32(rg & 0xffff), f16_to_f32(rg >> 16), f16_to_f32(ba & 0xffff)]
                }
                _ => b10g11r11_to_f32(color[t]),
            };
            let z = view_depth(&p, depth_value(&p, depth[t]));
            let (want_c, want_z) = (colors[y * W as usize + x], depths[y * W as usize + x]);
            let ulp = match case.color {
                ImageFormat::Rgba32Float => [0.0; 3],
                ImageFormat::Rgba16Float => [2f32.powi(-11); 3],
                _ => [2f32.powi(-7), 2f32.powi(-7), 2f32.powi(-6)],
            };
            for k in 0..3 {
                assert!(
                    (c[k] - want_c[k]).abs() <= want_c[k] * ulp[k] * 1.0001,
                    "{case:?} pixel ({x}, {y}) channel {k}: {} for {}",
                    c[k],
                    want_c[k]
                );
            }
            let tolerance = want_z * (want_z / NEAR) * 2f32.powi(-22);
            assert!(
                z == want_z || (z - want_z).abs() <= tolerance,
                "{case:?} pixel ({x}, {y}): view depth {z} for {want_z} (tolerance {tolerance})"
            );
            slots.extend(dof_shaders::slot::Slot::opaque(c, z).words());
        }
    }
    slots
}

fn context(b: &mut dyn Backend) -> Box<dyn DofContext> {
    let mut desc = ContextDesc::new(Extent::new(W, H, 1), MethodOptions::default());
    desc.image_io = true;
    (registry::method(METHOD).unwrap().create)(b, &desc).unwrap()
}

fn frame(input: FrameInput, output: BufferId) -> Frame {
    Frame { width: W, height: H, lens: dof::stress::test_lens(0.01), input, output: FrameOutput::Buffer(RgbBuffer(output)) }
}

/// Buffers of the reference frame: its decoded input, its counts, and two outputs.
fn buffers(b: &mut dyn Backend) -> [BufferId; 4] {
    let pixels = (W * H) as u64;
    let bufs =
        [dof::methods::buffers::SLOT_WORDS as u64 * pixels, pixels, 3 * pixels, 3 * pixels].map(|w| b.create_buffer(w, "test").unwrap());
    b.write_buffer(bufs[1], 0, &vec![1; pixels as usize]).unwrap();
    bufs
}

fn floats(words: &[u32]) -> Vec<f32> {
    words.iter().map(|&w| f32::from_bits(w)).collect()
}

#[test]
fn depth_and_colour_formats_give_the_frame_of_their_decoded_input_on_the_cpu() {
    let mut cpu = CpuBackend::new();
    let mut ctx = context(&mut cpu);
    let [fragments, counts, from_images, from_buffers] = buffers(&mut cpu);
    for case in cases() {
        let (color_texels, depth_texels) = texels(&case);
        let color = cpu.create_image(case.color, case.image).unwrap();
        let depth = cpu.create_image(case.depth, case.image).unwrap();
        cpu.write_image(&color, &color_texels).unwrap();
        cpu.write_image(&depth, &depth_texels).unwrap();
        cpu.write_buffer(fragments, 0, &decoded_input(&case)).unwrap();
        ctx.record(&mut cpu, &frame(FrameInput::Images { color, depth, encoding: case.encoding }, from_images)).unwrap();
        ctx.record(
            &mut cpu,
            &frame(
                FrameInput::Layers { fragments: SlotBuffer::current(fragments), counts: CountBuffer(counts), layers: 1, footprint_side: 0 },
                from_buffers,
            ),
        )
        .unwrap();
        cpu.submit().unwrap();
        let (a, b) =
            (cpu.read_buffer(from_images, 0, 3 * (W * H) as u64).unwrap(), cpu.read_buffer(from_buffers, 0, 3 * (W * H) as u64).unwrap());
        assert!(a == b, "{case:?}: the frame from images differs from the frame of its decoded input");
        assert!(floats(&a).iter().all(|v| v.is_finite()) && floats(&a).iter().any(|&v| v > 0.0), "{case:?}: an empty frame");
        cpu.destroy_image(&color);
        cpu.destroy_image(&depth);
    }
    ctx.destroy(&mut cpu);
}

/// Refusals name the format: a depth format given as colour, a colour format as depth, a depth
/// attachment read as linear depth, a Vulkan format the frame API does not copy.
#[test]
fn refused_formats_name_themselves() {
    let mut cpu = CpuBackend::new();
    let mut ctx = context(&mut cpu);
    let [.., out, _] = buffers(&mut cpu);
    let image = |cpu: &mut CpuBackend, f| cpu.create_image(f, [W, H]).unwrap();
    let (rgba, d32, d24) =
        (image(&mut cpu, ImageFormat::Rgba16Float), image(&mut cpu, ImageFormat::D32Float), image(&mut cpu, ImageFormat::D24UnormS8Uint));
    let reversed = DepthEncoding::Reversed { near: NEAR, far: FAR };
    let refused = |ctx: &mut Box<dyn DofContext>, cpu: &mut CpuBackend, color, depth, encoding| -> String {
        let before = cpu.counters();
        let e = ctx.record(cpu, &frame(FrameInput::Images { color, depth, encoding }, out)).unwrap_err().to_string();
        assert_eq!(cpu.counters().since(&before).commands, 0, "refused before any command: {e}");
        e
    };
    let e = refused(&mut ctx, &mut cpu, d32, d24, reversed);
    assert!(e.contains("colour") && e.contains("D32_SFLOAT"), "{e}");
    let e = refused(&mut ctx, &mut cpu, rgba, rgba, reversed);
    assert!(e.contains("depth") && e.contains("R16G16B16A16_SFLOAT"), "{e}");
    let e = refused(&mut ctx, &mut cpu, rgba, d24, DepthEncoding::Linear);
    assert!(e.contains("D24_UNORM_S8_UINT") && e.contains("Standard"), "{e}");
    let small = cpu.create_image(ImageFormat::D32Float, [W, H - 1]).unwrap();
    let e = refused(&mut ctx, &mut cpu, rgba, small, reversed);
    assert!(e.contains("smaller"), "{e}");
    let e = ImageRef::describe(vk::Image::null(), vk::Format::B8G8R8A8_UNORM, [W, H]).unwrap_err().to_string();
    assert!(e.contains("B8G8R8A8_UNORM") && e.contains("D24_UNORM_S8_UINT") && e.contains("B10G11R11_UFLOAT_PACK32"), "{e}");
    // The same frame with its formats in their places is recorded.
    ctx.record(&mut cpu, &frame(FrameInput::Images { color: rgba, depth: d32, encoding: reversed }, out)).unwrap();
    ctx.destroy(&mut cpu);
}

#[test]
fn depth_and_colour_formats_give_the_frame_of_their_decoded_input_on_vulkan() {
    let Some(mut r) = Renderer::new() else { return };
    // SAFETY: the renderer's live handles outlive the backend, which is dropped (after its work
    // completed) before the renderer destroys anything; the device enables what the backend needs.
    let mut vk = unsafe { VulkanBackend::from_raw(r.raw(), &RawOptions::default()) }.expect("from_raw");
    let mut ctx = context(&mut vk);
    let [fragments, counts, from_images, from_buffers] = buffers(&mut vk);
    let from_sampled = vk.create_buffer(3 * (W * H) as u64, "from sampled images").unwrap();
    let (mut unsupported, mut sampled_cases) = (Vec::new(), 0);
    for format in ImageFormat::ALL {
        let f = r.format_features(format.vk_format());
        let [src, dst, sampled] =
            [vk::FormatFeatureFlags::TRANSFER_SRC, vk::FormatFeatureFlags::TRANSFER_DST, vk::FormatFeatureFlags::SAMPLED_IMAGE]
                .map(|t| f.contains(t));
        eprintln!("{format}: transfer source {src}, destination {dst}, sampled {sampled}");
    }
    for case in cases() {
        let src = vk::FormatFeatureFlags::TRANSFER_SRC;
        let missing: Vec<ImageFormat> =
            [case.color, case.depth].into_iter().filter(|f| !r.format_features(f.vk_format()).contains(src)).collect();
        let (color_texels, depth_texels) = texels(&case);
        let color_image = r.image(case.color, case.image);
        let depth_image = r.image(case.depth, case.image);
        let color_staging = r.host_buffer(4 * color_texels.len() as u64);
        let depth_staging = r.host_buffer(4 * depth_texels.len() as u64);
        Renderer::write(&color_staging, &color_texels);
        Renderer::write(&depth_staging, &depth_texels);
        vk.write_buffer(fragments, 0, &decoded_input(&case)).unwrap();
        // The renderer's passes leave colour sampled-from and depth as a depth attachment.
        let (color_layout, color_stage, color_access) =
            (vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL, vk::PipelineStageFlags::FRAGMENT_SHADER, vk::AccessFlags::SHADER_READ);
        let (depth_layout, depth_stage, depth_access) = if case.depth.is_depth() {
            (
                vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                vk::PipelineStageFlags::LATE_FRAGMENT_TESTS,
                vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE,
            )
        } else {
            (color_layout, color_stage, color_access)
        };
        r.begin();
        r.upload_image(&color_staging, color_image, case.color, case.image, color_layout, color_stage, color_access);
        r.upload_image(&depth_staging, depth_image, case.depth, case.image, depth_layout, depth_stage, depth_access);
        let describe = |image, format: ImageFormat, layout, stage, access| {
            let desc = ImageRef::describe(image, format.vk_format(), case.image).unwrap().in_layout(layout).after(stage, access);
            // SAFETY: the renderer's live image of this format and extent, with transfer usage, in
            // `layout` when the frame runs (its upload's barrier leaves it there).
            unsafe { desc.build() }
        };
        let color = describe(color_image, case.color, color_layout, color_stage, color_access);
        let depth = describe(depth_image, case.depth, depth_layout, depth_stage, depth_access);
        // The same images again, sampled in place through views where the device samples both
        // formats (else the frame copies them as above).
        let sampled = |image: vk::Image, format: ImageFormat, layout, stage, access, view| {
            let desc = ImageRef::describe(image, format.vk_format(), case.image).unwrap().in_layout(layout).after(stage, access);
            // SAFETY: as above, and the view is a live depth- or colour-aspect view of the image.
            unsafe { desc.sampled_through(view).build() }
        };
        let samples =
            [case.color, case.depth].iter().all(|f| r.format_features(f.vk_format()).contains(vk::FormatFeatureFlags::SAMPLED_IMAGE));
        let (color_view, depth_view) = (r.sampled_view(color_image, case.color), r.sampled_view(depth_image, case.depth));
        let color_in_place = sampled(color_image, case.color, color_layout, color_stage, color_access, color_view);
        let depth_in_place = sampled(depth_image, case.depth, depth_layout, depth_stage, depth_access, depth_view);
        assert_eq!(vk.check_image_sample(&color_in_place).is_ok() && vk.check_image_sample(&depth_in_place).is_ok(), samples, "{case:?}");
        sampled_cases += samples as usize;
        // SAFETY: the renderer's command buffer is recording, outside a render pass.
        unsafe { vk.begin_external(r.cb) }.expect("begin_external");
        let recorded = ctx.record(&mut vk, &frame(FrameInput::Images { color, depth, encoding: case.encoding }, from_images));
        if !missing.is_empty() {
            let e = recorded.unwrap_err().to_string();
            assert!(missing.iter().all(|f| e.contains(&f.to_string())), "{case:?}: {e}");
            unsupported.push(format!("{case:?}: {e}"));
            vk.end_external().unwrap();
            r.submit_and_wait();
            continue;
        }
        recorded.unwrap_or_else(|e| panic!("{case:?}: {e}"));
        let in_place = FrameInput::Images { color: color_in_place, depth: depth_in_place, encoding: case.encoding };
        ctx.record(&mut vk, &frame(in_place, from_sampled)).unwrap_or_else(|e| panic!("{case:?} in place: {e}"));
        ctx.record(
            &mut vk,
            &frame(
                FrameInput::Layers { fragments: SlotBuffer::current(fragments), counts: CountBuffer(counts), layers: 1, footprint_side: 0 },
                from_buffers,
            ),
        )
        .unwrap();
        vk.end_external().unwrap();
        r.submit_and_wait();
        let a = floats(&vk.read_buffer(from_images, 0, 3 * (W * H) as u64).unwrap());
        let b = floats(&vk.read_buffer(from_buffers, 0, 3 * (W * H) as u64).unwrap());
        let c = floats(&vk.read_buffer(from_sampled, 0, 3 * (W * H) as u64).unwrap());
        let differing = a.iter().zip(&c).filter(|(x, y)| x.to_bits() != y.to_bits()).count();
        assert_eq!(differing, 0, "{case:?}: the frame sampling the images in place differs from the copied one in {differing} values");
        let worst = a.iter().zip(&b).map(|(x, y)| (x - y).abs() / y.abs().max(1.0)).fold(0.0f32, f32::max);
        assert!(worst <= 1e-4, "{case:?}: the frame from images differs from the frame of its decoded input by {worst} (relative)");
        assert!(a.iter().all(|v| v.is_finite()) && a.iter().any(|&v| v > 0.0), "{case:?}: an empty frame");
        assert_no_messages(r.messages(), &format!("in {case:?}"));
    }
    for line in &unsupported {
        eprintln!("not copyable on this device, refused by name: {line}");
    }
    eprintln!("{sampled_cases} of {} cases sampled in place", cases().len());
    assert!(sampled_cases > 0, "no case sampled its images in place");
    ctx.destroy(&mut vk);
    [fragments, counts, from_images, from_buffers, from_sampled].into_iter().for_each(|id| vk.destroy_buffer(id));
    drop(vk);
    assert_no_messages(r.finish(), "when the renderer destroyed its device");
}

/// The result written into a renderer's RGBA32F and RGBA16F images in place (storage images,
/// through views) equals, bit for bit, the result converted into a buffer and copied into them,
/// and the frame written in place is the frame into a buffer, converted; validation stays silent.
#[test]
fn outputs_written_in_place_equal_the_copied_ones_on_vulkan() {
    let Some(mut r) = Renderer::new() else { return };
    // SAFETY: as in the tests above: the renderer's handles outlive the backend.
    let mut vk = unsafe { VulkanBackend::from_raw(r.raw(), &RawOptions::default()) }.expect("from_raw");
    let mut ctx = context(&mut vk);
    let [fragments, counts, out, _] = buffers(&mut vk);
    let case = cases()[0];
    vk.write_buffer(fragments, 0, &decoded_input(&case)).unwrap();
    let input = FrameInput::Layers { fragments: SlotBuffer::current(fragments), counts: CountBuffer(counts), layers: 1, footprint_side: 0 };
    let pixels = (W * H) as usize;
    let mut in_place_formats = 0;
    for format in [ImageFormat::Rgba32Float, ImageFormat::Rgba16Float] {
        use vk::ImageUsageFlags as U;
        let usage = U::TRANSFER_SRC | U::TRANSFER_DST | U::STORAGE;
        let images = [r.raw_image(format.vk_format(), [W, H], usage), r.raw_image(format.vk_format(), [W, H], usage)];
        let view = r.sampled_view(images[0], format);
        let describe = |image| {
            ImageRef::describe(image, format.vk_format(), [W, H])
                .unwrap()
                .in_layout(vk::ImageLayout::UNDEFINED)
                .leave_in(vk::ImageLayout::TRANSFER_SRC_OPTIMAL)
        };
        // SAFETY: the renderer's live images of this format and extent with storage and transfer
        // usage, the view a live colour view of the first; their contents are discarded.
        let (in_place, copied) = unsafe { (describe(images[0]).sampled_through(view).build(), describe(images[1]).build()) };
        let stores = r.format_features(format.vk_format()).contains(vk::FormatFeatureFlags::STORAGE_IMAGE);
        assert_eq!(vk.check_image_store(&in_place).is_ok(), stores, "{format}");
        in_place_formats += stores as usize;
        let staging = r.host_buffer(4 * 2 * in_place.words());
        r.begin();
        // SAFETY: the renderer's command buffer is recording, outside a render pass.
        unsafe { vk.begin_external(r.cb) }.expect("begin_external");
        for (image, _) in [(in_place, 0), (copied, 1)] {
            ctx.record(&mut vk, &Frame { output: FrameOutput::Image(image), ..frame(input, out) })
                .unwrap_or_else(|e| panic!("{format}: {e}"));
        }
        ctx.record(&mut vk, &frame(input, out)).unwrap();
        vk.end_external().unwrap();
        for (k, image) in images.into_iter().enumerate() {
            let region = vk::BufferImageCopy::default()
                .buffer_offset(4 * k as u64 * in_place.words())
                .image_subresource(vk::ImageSubresourceLayers::default().aspect_mask(vk::ImageAspectFlags::COLOR).layer_count(1))
                .image_extent(vk::Extent3D { width: W, height: H, depth: 1 });
            // SAFETY: recording; the frames left the image in TRANSFER_SRC_OPTIMAL, visible to
            // every later access; the region lies inside the staging buffer.
            unsafe { r.device.cmd_copy_image_to_buffer(r.cb, image, vk::ImageLayout::TRANSFER_SRC_OPTIMAL, staging.buffer, &[region]) };
        }
        r.submit_and_wait();
        let words = in_place.words() as usize;
        let (a, b) = (Renderer::read(&staging, 0, words), Renderer::read(&staging, words, words));
        let rgb = floats(&vk.read_buffer(out, 0, 3 * pixels as u64).unwrap());
        assert_written_in_place(format, &a, &b, &rgb);
        assert_no_messages(r.messages(), &format!("writing {format}"));
    }
    eprintln!("{in_place_formats} of 2 output formats written in place");
    assert!(in_place_formats > 0, "no output format written in place");
    ctx.destroy(&mut vk);
    [fragments, counts, out].into_iter().for_each(|id| vk.destroy_buffer(id));
    drop(vk);
    assert_no_messages(r.finish(), "when the renderer destroyed its device");
}

/// A renderer's depth prepass writes the depth attachment and hands it over described by layout
/// alone (no `.after()`): the frame's copy still waits for that write, by the description's safe
/// default (any earlier write) and the opening barrier of the library's recording (which covers
/// depth-attachment writes). Synchronisation validation must stay silent, and the frame must read
/// the depth the pass wrote.
#[test]
fn a_depth_attachment_described_by_layout_alone_is_waited_for() {
    let Some(mut r) = Renderer::new() else { return };
    // SAFETY: as in the test above: the renderer's handles outlive the backend.
    let mut vk = unsafe { VulkanBackend::from_raw(r.raw(), &RawOptions::default()) }.expect("from_raw");
    let mut ctx = context(&mut vk);
    let [_, _, out, _] = buffers(&mut vk);
    let color_texels: Vec<u32> = (0..W * H).flat_map(|i| [0.25, 0.5, (i % 7) as f32 / 7.0, 1.0].map(f32::to_bits)).collect();
    let color_image = r.image(ImageFormat::Rgba32Float, [W, H]);
    let depth_image = r.image(ImageFormat::D32Float, [W, H]);
    let staging = r.host_buffer(4 * color_texels.len() as u64);
    Renderer::write(&staging, &color_texels);
    let shader_read = (vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL, vk::PipelineStageFlags::FRAGMENT_SHADER, vk::AccessFlags::SHADER_READ);
    r.begin();
    r.upload_image(&staging, color_image, ImageFormat::Rgba32Float, [W, H], shader_read.0, shader_read.1, shader_read.2);
    // Standard depth 0.5 with near 0.1 and far 100 is a view depth of about 0.2.
    r.depth_pass(depth_image, ImageFormat::D32Float, [W, H], 0.5);
    let by_layout = |image, format, layout| {
        // SAFETY: the renderer's live image of this format and extent, with transfer usage, in
        // `layout` when the frame runs.
        unsafe { ImageRef::describe(image, format, [W, H]).unwrap().in_layout(layout).build() }
    };
    let color = by_layout(color_image, vk::Format::R32G32B32A32_SFLOAT, shader_read.0);
    let depth = by_layout(depth_image, vk::Format::D32_SFLOAT, vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    assert_eq!((depth.stage, depth.access), (vk::PipelineStageFlags::ALL_COMMANDS, vk::AccessFlags::MEMORY_WRITE), "the safe default");
    // SAFETY: the renderer's command buffer is recording, outside a render pass.
    unsafe { vk.begin_external(r.cb) }.expect("begin_external");
    let encoding = DepthEncoding::Standard { near: NEAR, far: FAR };
    ctx.record(&mut vk, &frame(FrameInput::Images { color, depth, encoding }, out)).unwrap();
    vk.end_external().unwrap();
    r.submit_and_wait();
    let rgb = floats(&vk.read_buffer(out, 0, 3 * (W * H) as u64).unwrap());
    assert!(rgb.iter().all(|v| v.is_finite()) && rgb.iter().any(|&v| v > 0.0), "an empty frame");
    assert_no_messages(r.messages(), "reading a depth attachment described by layout alone");
    ctx.destroy(&mut vk);
    drop(vk);
    assert_no_messages(r.finish(), "when the renderer destroyed its device");
}

/// A wgpu texture of `format` for an [`ImageFormat`] of the cases (the D24 formats as wgpu's
/// `Depth24Plus` ones, which read back as f32 depths).
fn wgpu_format(format: ImageFormat) -> wgpu::TextureFormat {
    match format {
        ImageFormat::Rgba32Float => wgpu::TextureFormat::Rgba32Float,
        ImageFormat::Rgba16Float => wgpu::TextureFormat::Rgba16Float,
        ImageFormat::B10G11R11Ufloat => wgpu::TextureFormat::Rg11b10Ufloat,
        ImageFormat::R32Float => wgpu::TextureFormat::R32Float,
        ImageFormat::D32Float => wgpu::TextureFormat::Depth32Float,
        ImageFormat::D24UnormS8Uint => wgpu::TextureFormat::Depth24PlusStencil8,
        ImageFormat::X8D24UnormPack32 => wgpu::TextureFormat::Depth24Plus,
    }
}

/// Writes `depths` (row after row, `width` a row) into a depth texture the way a renderer's pass
/// does: a full-screen triangle whose fragments write them as their depth (wgpu copies nothing into
/// a depth texture). The test's own scaffolding, not a kernel of the project's.
fn render_depth(device: &wgpu::Device, queue: &wgpu::Queue, texture: &wgpu::Texture, depths: &[f32], width: u32) {
    let source = format!(
        "@group(0) @binding(0) var<storage, read> depths: array<f32>;
         @vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {{
             let uv = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
             return vec4<f32>(uv * 2.0 - 1.0, 0.5, 1.0);
         }}
         @fragment fn fs(@builtin(position) at: vec4<f32>) -> @builtin(frag_depth) f32 {{
             return depths[u32(at.y) * {width}u + u32(at.x)];
         }}"
    );
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor { label: None, source: wgpu::ShaderSource::Wgsl(source.into()) });
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("depth writer"),
        layout: None,
        vertex: wgpu::VertexState { module: &module, entry_point: Some("vs"), compilation_options: Default::default(), buffers: &[] },
        primitive: Default::default(),
        depth_stencil: Some(wgpu::DepthStencilState {
            format: texture.format(),
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Always),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module: &module,
            entry_point: Some("fs"),
            compilation_options: Default::default(),
            targets: &[],
        }),
        multiview_mask: None,
        cache: None,
    });
    let bytes: Vec<u8> = depths.iter().flat_map(|d| d.to_le_bytes()).collect();
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: bytes.len() as u64,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    queue.write_buffer(&buffer, 0, &bytes);
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[wgpu::BindGroupEntry { binding: 0, resource: buffer.as_entire_binding() }],
    });
    let view = texture.create_view(&Default::default());
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("depth prepass"),
            color_attachments: &[],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &view,
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(0.0), store: wgpu::StoreOp::Store }),
                stencil_ops: texture
                    .format()
                    .has_stencil_aspect()
                    .then_some(wgpu::Operations { load: wgpu::LoadOp::Clear(0xa5), store: wgpu::StoreOp::Store }),
            }),
            ..Default::default()
        });
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
    queue.submit([encoder.finish()]);
}

/// The renderer's textures of `case`, filled: colour by an upload, depth by a pass (an R32F one by
/// an upload). Returns them with their D32-read depths' intended values (f32 depth-buffer values).
fn wgpu_textures(device: &wgpu::Device, queue: &wgpu::Queue, case: &Case) -> (wgpu::Texture, wgpu::Texture) {
    let (color_texels, depth_texels) = texels(case);
    let [iw, ih] = case.image;
    let size = wgpu::Extent3d { width: iw, height: ih, depth_or_array_layers: 1 };
    let texture = |format: ImageFormat, usage: wgpu::TextureUsages| {
        device.create_texture(&wgpu::TextureDescriptor {
            label: Some("renderer's"),
            size,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu_format(format),
            usage,
            view_formats: &[],
        })
    };
    let upload = |t: &wgpu::Texture, texels: &[u32], words: u64| {
        let bytes: Vec<u8> = texels.iter().flat_map(|w| w.to_le_bytes()).collect();
        let layout = wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some((4 * words * iw as u64) as u32), rows_per_image: None };
        queue.write_texture(t.as_image_copy(), &bytes, layout, size);
    };
    let color = texture(case.color, wgpu::TextureUsages::COPY_SRC | wgpu::TextureUsages::COPY_DST | wgpu::TextureUsages::TEXTURE_BINDING);
    upload(&color, &color_texels, case.color.words_per_pixel());
    let depth = if case.depth.is_depth() {
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC | wgpu::TextureUsages::TEXTURE_BINDING;
        let depth = texture(case.depth, usage);
        let values: Vec<f32> = depth_texels
            .iter()
            .map(|&w| if case.depth.is_unorm24() { (w & 0xff_ffff) as f32 / 16_777_215.0 } else { f32::from_bits(w) })
            .collect();
        render_depth(device, queue, &depth, &values, iw);
        depth
    } else {
        let depth = texture(case.depth, wgpu::TextureUsages::COPY_SRC | wgpu::TextureUsages::COPY_DST);
        upload(&depth, &depth_texels, 1);
        depth
    };
    (color, depth)
}

/// Every case through wgpu: the renderer's own textures (colour uploaded, depth written by a pass),
/// sampled in place where both have TEXTURE_BINDING usage (the depth formats' cases), else copied
/// (the R32F depth's cases, whose textures lack it: rows not a multiple of 256 bytes copied row by
/// row), each frame recorded into the renderer's own encoder with nothing made, submitted or
/// read back. The depths read back are the intended ones (an f32 depth bit for bit, a 24-bit one
/// within its step), and the frame equals the CPU backend's from stand-in images holding the same
/// words, within 1e-4 relative; one frame also writes the renderer's RGBA16F texture, equal to the
/// CPU's image within a unit in the last place of a half.
#[test]
fn depth_and_colour_formats_on_wgpu_textures_give_the_cpus_frame() {
    let Some((device, queue, info)) = dof_tests::wgpu_device() else { return };
    let mut g = dof::backend::WgpuBackend::from_device(device.clone(), queue.clone(), info);
    let mut cpu = CpuBackend::new();
    let mut ctx = context(&mut g);
    let mut cpu_ctx = context(&mut cpu);
    let pixels = (W * H) as u64;
    let (out, depth_read, cpu_out) = (
        g.create_buffer(3 * pixels, "out").unwrap(),
        g.create_buffer(pixels, "depth").unwrap(),
        cpu.create_buffer(3 * pixels, "out").unwrap(),
    );
    let out_texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("renderer's output"),
        size: wgpu::Extent3d { width: W, height: H, depth_or_array_layers: 1 },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba16Float,
        usage: wgpu::TextureUsages::COPY_DST | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let out_image = g.import_texture(&out_texture).unwrap();
    for (n, case) in cases().into_iter().enumerate() {
        let (color_texture, depth_texture) = wgpu_textures(&device, &queue, &case);
        let (color, depth) = (g.import_texture(&color_texture).unwrap(), g.import_texture(&depth_texture).unwrap());
        let expected_depth = if case.depth.is_depth() { ImageFormat::D32Float } else { case.depth };
        assert_eq!((color.format, depth.format), (case.color, expected_depth), "{case:?}");

        // The depth as the frame reads it, against the value the pass wrote.
        g.copy_image_to_buffer(depth.top_left(W, H), depth_read, 0, "depth").unwrap();
        let read = g.read_buffer(depth_read, 0, pixels).unwrap();
        let (_, depth_texels) = texels(&case);
        for (i, &word) in read.iter().enumerate() {
            let t = depth_texels[(i as u32 / W * case.image[0] + i as u32 % W) as usize];
            if case.depth.is_unorm24() {
                let want = (t & 0xff_ffff) as f32 / 16_777_215.0;
                let got = f32::from_bits(word);
                assert!((got - want).abs() <= 1.0 / 16_777_215.0, "{case:?} texel {i}: depth {got}, written {want}");
            } else {
                assert_eq!(word, t, "{case:?} texel {i}: an f32 depth is read bit for bit");
            }
        }

        // The frame, recorded into the renderer's encoder.
        let output = if n == 0 { FrameOutput::Image(out_image) } else { FrameOutput::Buffer(RgbBuffer(out)) };
        let input = FrameInput::Images { color, depth, encoding: case.encoding };
        let frame_on = |output| Frame { output, ..frame(input, out) };
        let before = g.counters();
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let mut recording = g.record_into(&mut encoder).unwrap();
            ctx.record(&mut *recording, &frame_on(output)).unwrap_or_else(|e| panic!("{case:?}: {e}"));
        }
        let spent = g.counters().since(&before);
        assert_eq!((spent.allocations, spent.submissions, spent.uploads, spent.readbacks), (0, 0, 0, 0), "{case:?}");
        queue.submit([encoder.finish()]);

        // The CPU's frame from stand-ins holding the words the frame read.
        let (color_texels, _) = texels(&case);
        let cpu_color = cpu.create_image(case.color, case.image).unwrap();
        cpu.write_image(&cpu_color, &color_texels).unwrap();
        let cpu_depth = cpu.create_image(expected_depth, [W, H]).unwrap();
        cpu.write_image(&cpu_depth, &read).unwrap();
        let cpu_frame = Frame {
            output: FrameOutput::Buffer(RgbBuffer(cpu_out)),
            ..frame(FrameInput::Images { color: cpu_color, depth: cpu_depth, encoding: case.encoding }, cpu_out)
        };
        cpu_ctx.record(&mut cpu, &cpu_frame).unwrap();
        cpu.submit().unwrap();
        let want = floats(&cpu.read_buffer(cpu_out, 0, 3 * pixels).unwrap());
        assert!(want.iter().all(|v| v.is_finite()) && want.iter().any(|&v| v > 0.0), "{case:?}: an empty frame");
        if n == 0 {
            let words = g_texture_words(&mut g, &out_image);
            let halves = g.read_buffer(words, 0, 2 * pixels).unwrap();
            g.destroy_buffer(words);
            for (i, w) in want.chunks(3).enumerate() {
                let got = [f16_to_f32(halves[2 * i] & 0xffff), f16_to_f32(halves[2 * i] >> 16), f16_to_f32(halves[2 * i + 1] & 0xffff)];
                for k in 0..3 {
                    assert!(
                        (got[k] - w[k]).abs() <= w[k].abs() * 2f32.powi(-10),
                        "{case:?} pixel {i}: {got:?} in the texture, the CPU's {w:?}"
                    );
                }
                assert_eq!(halves[2 * i + 1] >> 16, f32_to_f16(1.0), "alpha 1");
            }
        } else {
            let got = floats(&g.read_buffer(out, 0, 3 * pixels).unwrap());
            let worst = got.iter().zip(&want).map(|(x, y)| (x - y).abs() / y.abs().max(1.0)).fold(0.0f32, f32::max);
            assert!(worst <= 1e-4, "{case:?}: the wgpu frame differs from the CPU's by {worst} (relative)");
        }
        g.forget_texture(&color);
        g.forget_texture(&depth);
        cpu.destroy_image(&cpu_color);
        cpu.destroy_image(&cpu_depth);
    }
    assert!(g.take_diagnostics().is_empty());
    ctx.destroy(&mut g);
    cpu_ctx.destroy(&mut cpu);
}

/// The words of an output image written in place, `a`, equal those of the one copied into, `b`,
/// and hold the frame's `rgb` (rounded to the nearest half for RGBA16F) with alpha 1.
fn assert_written_in_place(format: ImageFormat, a: &[u32], b: &[u32], rgb: &[f32]) {
    let differing = a.iter().zip(b).filter(|(x, y)| x != y).count();
    assert_eq!(differing, 0, "{format}: the result written in place differs from the copied one in {differing} words");
    let half = |v: f32| f16_to_f32(f32_to_f16(v));
    for (i, c) in rgb.chunks(3).enumerate() {
        let got = if format == ImageFormat::Rgba16Float {
            let (rg, ba) = (a[2 * i], a[2 * i + 1]);
            [f16_to_f32(rg & 0xffff), f16_to_f32(rg >> 16), f16_to_f32(ba & 0xffff), f16_to_f32(ba >> 16)]
        } else {
            [0, 1, 2, 3].map(|k| f32::from_bits(a[4 * i + k]))
        };
        let want = if format == ImageFormat::Rgba16Float { [half(c[0]), half(c[1]), half(c[2]), 1.0] } else { [c[0], c[1], c[2], 1.0] };
        assert_eq!(got.map(f32::to_bits), want.map(f32::to_bits), "{format} pixel {i}");
    }
}

/// The result written into a renderer's RGBA32F and RGBA16F textures in place (write-only storage
/// textures, where they have STORAGE_BINDING usage) equals, bit for bit, the result converted into
/// a buffer and copied into textures without that usage, and is the frame into a buffer, converted;
/// recorded into the renderer's encoder with nothing made, submitted or read back.
#[test]
fn outputs_written_in_place_equal_the_copied_ones_on_wgpu() {
    let Some((device, queue, info)) = dof_tests::wgpu_device() else { return };
    let mut g = dof::backend::WgpuBackend::from_device(device.clone(), queue.clone(), info);
    let mut ctx = context(&mut g);
    let [fragments, counts, out, _] = buffers(&mut g);
    g.write_buffer(fragments, 0, &decoded_input(&cases()[0])).unwrap();
    let input = FrameInput::Layers { fragments: SlotBuffer::current(fragments), counts: CountBuffer(counts), layers: 1, footprint_side: 0 };
    let pixels = (W * H) as usize;
    for (format, texture_format) in
        [(ImageFormat::Rgba32Float, wgpu::TextureFormat::Rgba32Float), (ImageFormat::Rgba16Float, wgpu::TextureFormat::Rgba16Float)]
    {
        let texture = |storage: bool| {
            let usage = wgpu::TextureUsages::COPY_SRC | wgpu::TextureUsages::COPY_DST;
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some("renderer's output"),
                size: wgpu::Extent3d { width: W, height: H, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: texture_format,
                usage: if storage { usage | wgpu::TextureUsages::STORAGE_BINDING } else { usage },
                view_formats: &[],
            })
        };
        let textures = [texture(true), texture(false)];
        let [in_place, copied] = [0, 1].map(|k| g.import_texture(&textures[k]).unwrap());
        assert!(g.check_image_store(&in_place).is_ok(), "{format}");
        let err = g.check_image_store(&copied).unwrap_err().to_string();
        assert!(err.contains("STORAGE_BINDING"), "{format}: {err}");
        let before = g.counters();
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let mut recording = g.record_into(&mut encoder).unwrap();
            for image in [in_place, copied] {
                ctx.record(&mut *recording, &Frame { output: FrameOutput::Image(image), ..frame(input, out) })
                    .unwrap_or_else(|e| panic!("{format}: {e}"));
            }
            ctx.record(&mut *recording, &frame(input, out)).unwrap();
        }
        let spent = g.counters().since(&before);
        assert_eq!((spent.allocations, spent.submissions, spent.uploads, spent.readbacks), (0, 0, 0, 0), "{format}");
        queue.submit([encoder.finish()]);
        let [a, b] = [in_place, copied].map(|image| {
            let words = g_texture_words(&mut g, &image);
            let read = g.read_buffer(words, 0, image.words()).unwrap();
            g.destroy_buffer(words);
            read
        });
        let rgb = floats(&g.read_buffer(out, 0, 3 * pixels as u64).unwrap());
        assert_written_in_place(format, &a, &b, &rgb);
        g.forget_texture(&in_place);
        g.forget_texture(&copied);
    }
    assert!(g.take_diagnostics().is_empty());
    ctx.destroy(&mut g);
}

/// The words of an imported texture, copied into a new buffer of the backend.
fn g_texture_words(g: &mut dof::backend::WgpuBackend, image: &ImageRef) -> BufferId {
    let buffer = g.create_buffer(image.words(), "texture words").unwrap();
    g.copy_image_to_buffer(*image, buffer, 0, "texture words").unwrap();
    buffer
}

/// Textures a frame cannot take are refused by name before anything is recorded: a format it
/// does not read, a multisampled texture, one without the usage its copy needs, a depth texture as
/// the output.
#[test]
fn wgpu_textures_a_frame_cannot_take_are_refused_by_name() {
    let Some((device, queue, info)) = dof_tests::wgpu_device() else { return };
    let mut g = dof::backend::WgpuBackend::from_device(device.clone(), queue, info);
    let texture = |format, usage, samples| {
        device.create_texture(&wgpu::TextureDescriptor {
            label: None,
            size: wgpu::Extent3d { width: W, height: H, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: samples,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage,
            view_formats: &[],
        })
    };
    let attachment = wgpu::TextureUsages::RENDER_ATTACHMENT;
    let e = g.import_texture(&texture(wgpu::TextureFormat::Bgra8Unorm, attachment, 1)).unwrap_err().to_string();
    assert!(e.contains("Bgra8Unorm") && e.contains("Depth24PlusStencil8") && e.contains("Rgba16Float"), "{e}");
    let e = g.import_texture(&texture(wgpu::TextureFormat::Rgba16Float, attachment, 4)).unwrap_err().to_string();
    assert!(e.contains("4 samples"), "{e}");
    let mut ctx = context(&mut g);
    let out = g.create_buffer(3 * (W * H) as u64, "out").unwrap();
    let no_copy = g.import_texture(&texture(wgpu::TextureFormat::Rgba16Float, attachment, 1)).unwrap();
    let depth24 =
        g.import_texture(&texture(wgpu::TextureFormat::Depth24Plus, attachment | wgpu::TextureUsages::TEXTURE_BINDING, 1)).unwrap();
    let copyable = g.import_texture(&texture(wgpu::TextureFormat::Rgba16Float, wgpu::TextureUsages::COPY_SRC, 1)).unwrap();
    let no_binding = g.import_texture(&texture(wgpu::TextureFormat::Depth32Float, attachment, 1)).unwrap();
    let reversed = DepthEncoding::Reversed { near: NEAR, far: FAR };
    let mut refused = |input, output| {
        let before = g.counters();
        let mut encoder = device.create_command_encoder(&Default::default());
        let mut recording = g.record_into(&mut encoder).unwrap();
        let e = ctx.record(&mut *recording, &Frame { output, ..frame(input, out) }).unwrap_err().to_string();
        drop(recording);
        assert_eq!(g.counters().since(&before).commands, 0, "refused before any command: {e}");
        e
    };
    let e = refused(FrameInput::Images { color: no_copy, depth: depth24, encoding: reversed }, FrameOutput::Buffer(RgbBuffer(out)));
    assert!(e.contains("COPY_SRC"), "{e}");
    let e = refused(FrameInput::Images { color: copyable, depth: no_binding, encoding: reversed }, FrameOutput::Buffer(RgbBuffer(out)));
    assert!(e.contains("TEXTURE_BINDING") && e.contains("Depth32Float"), "{e}");
    let e = refused(FrameInput::Images { color: copyable, depth: depth24, encoding: reversed }, FrameOutput::Image(depth24));
    assert!(e.contains("output") && e.contains("D32_SFLOAT"), "{e}");
    assert!(g.take_diagnostics().is_empty());
    ctx.destroy(&mut g);
}
