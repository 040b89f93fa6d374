//! Helpers shared by the integration suites.

pub mod oracle;
pub mod renderer;

use dof::backend::{VulkanBackend, VulkanOptions, WgpuBackend, WgpuOptions};
use dof::layers::RgbImage;
use dof::ops::sort::{SortInput, SortOutput};

/// The Vulkan backend with the Khronos validation layer and synchronization validation on.
///
/// A missing driver or layer fails the test with the reason: CI must never skip the Vulkan suites
/// silently. Setting `DOF_SKIP_VULKAN=1` skips them on purpose (the test prints that it did).
pub fn vulkan() -> Option<VulkanBackend> {
    vulkan_with(VulkanOptions { validation: true, ..Default::default() })
}

/// [`vulkan`] with these options.
pub fn vulkan_with(options: VulkanOptions) -> Option<VulkanBackend> {
    if std::env::var_os("DOF_SKIP_VULKAN").is_some_and(|v| v == "1") {
        eprintln!("DOF_SKIP_VULKAN=1: skipping a Vulkan test on purpose");
        return None;
    }
    match VulkanBackend::new(&options) {
        Ok(vk) => Some(vk),
        Err(e) => panic!("Vulkan is required for this test (set DOF_SKIP_VULKAN=1 to skip on purpose): {e}"),
    }
}

/// The wgpu backend on wgpu's Vulkan backend (lavapipe in CI).
///
/// As with [`vulkan`], a missing device fails the test with the reason; `DOF_SKIP_WGPU=1` skips on
/// purpose, and says so.
pub fn wgpu() -> Option<WgpuBackend> {
    wgpu_with(WgpuOptions { backends: wgpu::Backends::VULKAN, ..Default::default() })
}

/// [`wgpu`] with these options.
pub fn wgpu_with(options: WgpuOptions) -> Option<WgpuBackend> {
    if std::env::var_os("DOF_SKIP_WGPU").is_some_and(|v| v == "1") {
        eprintln!("DOF_SKIP_WGPU=1: skipping a wgpu test on purpose");
        return None;
    }
    match WgpuBackend::new(&options) {
        Ok(backend) => Some(backend),
        Err(e) => panic!("wgpu on Vulkan is required for this test (set DOF_SKIP_WGPU=1 to skip on purpose): {e}"),
    }
}

/// A renderer's wgpu device, made as a renderer makes it: wgpu's Vulkan backend, with the
/// immediates the kernels need. `None` where [`wgpu`] skips.
pub fn wgpu_device() -> Option<(wgpu::Device, wgpu::Queue, wgpu::AdapterInfo)> {
    wgpu()?;
    let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
        backends: wgpu::Backends::VULKAN,
        ..wgpu::InstanceDescriptor::new_without_display_handle()
    });
    let adapter = pollster::block_on(instance.request_adapter(&Default::default())).expect("an adapter");
    let descriptor =
        wgpu::DeviceDescriptor { required_features: wgpu::Features::IMMEDIATES, required_limits: adapter.limits(), ..Default::default() };
    let (device, queue) = pollster::block_on(adapter.request_device(&descriptor)).expect("a device");
    Some((device, queue, adapter.get_info()))
}

/// Fails if the validation layer reported anything.
pub fn assert_clean(vk: &mut VulkanBackend) {
    let messages = vk.take_validation_messages();
    assert!(messages.is_empty(), "validation layer reported {} message(s):\n{}", messages.len(), messages.join("\n"));
}

/// Asserts a sort output equals the reference bit for bit (keys compared as bits, so NaN and -0.0
/// count).
pub fn assert_sorted_like_reference(input: &SortInput, out: &SortOutput) {
    let (keys, values) = input.reference();
    for (s, &(o, l)) in input.segments.iter().enumerate() {
        let r = o as usize..(o + l) as usize;
        let got: Vec<u32> = out.keys[r.clone()].iter().map(|k| k.to_bits()).collect();
        let want: Vec<u32> = keys[r.clone()].iter().map(|k| k.to_bits()).collect();
        assert_eq!(got, want, "keys of list {s} (offset {o}, length {l}) differ from the reference");
        assert_eq!(out.values[r.clone()], values[r], "payloads of list {s} (offset {o}, length {l}) differ");
    }
}

/// A `w` x `h` single-layer image of hashed HDR colours (up to 83 000) and depths (0.5 to 15.5),
/// for the single-layer methods' stiff cases.
pub fn noise_image(w: u32, h: u32) -> (RgbImage, Vec<f32>) {
    let mut img = RgbImage::new(w, h);
    let mut depth = Vec::new();
    for (i, p) in img.data.iter_mut().enumerate() {
        let v = (i as u32).wrapping_mul(2654435761) >> 8;
        *p = [(v % 97) as f32 / 97.0, (v % 89) as f32 / 8.9, (v % 83) as f32 * 1000.0];
        depth.push(0.5 + (v % 300) as f32 / 20.0);
    }
    (img, depth)
}

/// One frame of a registry method's context: its input, lens and size.
pub struct ContextFrame<'a> {
    pub image: &'a dof::layers::LayeredImage,
    pub lens: dof_shaders::lens::ThinLens,
    /// Resize the context to this extent before the frame (between frames, so allowed to allocate).
    pub resize: Option<dof::frame::Extent>,
}

/// Frames through one context of the registry's `method` made for `extent` with `options`, from
/// caller buffers sized for `extent`: asserts that recording and submitting each frame allocates,
/// reads back and uploads nothing and submits once, and returns each frame's image and report.
pub fn context_frames(
    b: &mut dyn dof::backend::Backend,
    method: &str,
    options: &dof::frame::MethodOptions,
    extent: dof::frame::Extent,
    frames: &[ContextFrame],
) -> Vec<(RgbImage, dof::frame::ContextReport)> {
    use dof::frame::{ContextDesc, CountBuffer, Frame, RgbBuffer, SlotBuffer, registry};
    use dof::methods::buffers::{read_rgb, slot_words};
    let method = registry::method(method).unwrap();
    let mut max = extent;
    for f in frames {
        max = max.union(f.resize.unwrap_or(extent));
    }
    let pixels = max.width as u64 * max.height as u64;
    let bufs = [
        b.create_buffer(dof::methods::buffers::SLOT_WORDS as u64 * pixels * max.layers as u64, "caller/fragments").unwrap(),
        b.create_buffer(pixels, "caller/counts").unwrap(),
        b.create_buffer(3 * pixels, "caller/output").unwrap(),
    ];
    let mut ctx = (method.create)(b, &ContextDesc::new(extent, options.clone())).unwrap();
    let mut out = Vec::new();
    for (i, f) in frames.iter().enumerate() {
        if let Some(e) = f.resize {
            ctx.resize(b, e).unwrap();
            assert_eq!(ctx.extent(), e);
        }
        let img = f.image;
        b.write_buffer(bufs[0], 0, &slot_words(img)).unwrap();
        b.write_buffer(bufs[1], 0, &img.counts).unwrap();
        let frame = Frame::layers(
            img.width,
            img.height,
            img.max_layers,
            f.lens,
            SlotBuffer::current(bufs[0]),
            CountBuffer(bufs[1]),
            RgbBuffer(bufs[2]),
        );
        let before = b.counters();
        ctx.record(b, &frame).unwrap();
        b.submit().unwrap();
        let spent = b.counters().since(&before);
        assert_eq!(
            (spent.allocations, spent.readbacks, spent.uploads, spent.submissions),
            (0, 0, 0, 1),
            "{} frame {i} ({}x{}, {} layers)",
            method.name,
            img.width,
            img.height,
            img.max_layers
        );
        let image = read_rgb(b, bufs[2], img.width, img.height).unwrap();
        out.push((image, ctx.report(b).unwrap()));
    }
    ctx.destroy(b);
    bufs.iter().for_each(|&id| b.destroy_buffer(id));
    out
}
