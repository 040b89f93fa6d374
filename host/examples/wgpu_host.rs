//! An example renderer on wgpu that adds multi-layer depth of field to its own frames through the
//! public frame API: it draws its scene, peels it with its own passes, and blurs the layers, all
//! in its own command encoder. A template for a wgpu renderer (Bevy's included) to copy from.
//!
//! What the renderer does, and what it hands the library:
//! 1. It makes its own wgpu device (any API wgpu offers: `WGPU_BACKEND` picks one) with
//!    `Features::IMMEDIATES`, which the kernels need, and wraps it with
//!    `WgpuBackend::from_device`.
//! 2. Its own objects: a render pipeline whose WGSL (`wgpu_host/peel.wgsl`) discards a fragment
//!    unless the library's peel test (`dof_peel_keep`) keeps it against the bound the library
//!    writes; an RGBA16F colour and a `Depth32Float` depth attachment; the bound and the indirect
//!    draw command in storage buffers of its own, imported with `import_buffer`; an RGBA32F texture
//!    the result is written into in place (STORAGE_BINDING usage). The textures become the
//!    library's images with `import_texture`.
//! 3. `RendererPeel` and a `SplatContext` are made once (every allocation happens here).
//! 4. Per frame, one command encoder of its own, one submission: the library's `begin`, then for
//!    each layer its own render pass (drawn indirectly from the command the library wrote) and the
//!    library's `append` of the attachments, then `finish` and the depth of field into the output
//!    texture, each library call inside `record_into`. The camera orbits the focus point 2 degrees
//!    a frame. Inside a frame the library allocates, submits, uploads and reads back nothing:
//!    checked on its counters.
//! 5. With `--window`, each frame is shown in a winit window as it is made: our own pass tone-maps
//!    the output texture into the window's image, in the same encoder.
//! 6. Each frame is compared with the same `SplatContext` on the library's CPU backend, run from
//!    the slots the peel wrote (read back after the frame, for the check alone), and the last one
//!    is written as EXR and PNG.
//!
//! `cargo run --example wgpu_host -- [--width W --height H] [--frames N] [--out DIR] [--window]`
//! (`--window --frames 0`: until the window is closed); it exits non-zero when a check fails.

use anyhow::{Context, Result, bail, ensure};
use dof::frame::Extent;
use dof::scene::{LayerOptions, ThinLens};
use dof_core::backend::{Backend, BackendCounters, BufferId, ImageRef, WgpuBackend};
use dof_core::frame::{
    DepthEncoding, DofContext, FrameInput, FrameOutput, Merge, RendererPeel, RendererPeelDesc, SplatContext, SplatContextDesc, SplatOptions,
};
use dof_shaders::slot::SLOT_WORDS;
use glam::{Mat4, Vec3};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

#[path = "common/shared.rs"]
mod shared;
use shared::{CpuCheck, Rgb, Vertex, compare, look_at, peel_scene, projection, write_image};

const USAGE: &str = "usage: wgpu_host [--width W] [--height H] [--frames N] [--out DIR] [--window]";
const COLOUR: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;
const DEPTH: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
const OUTPUT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;

struct Args {
    width: u32,
    height: u32,
    frames: u32,
    out: PathBuf,
    /// Show the frames in a window (winit) as they are made.
    window: bool,
}

fn parse_args() -> Result<Args> {
    let mut args = Args { width: 320, height: 180, frames: 3, out: "out/wgpu_host".into(), window: false };
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        let mut value = || it.next().with_context(|| format!("{arg} needs a value\n{USAGE}"));
        match arg.as_str() {
            "--width" => args.width = value()?.parse()?,
            "--height" => args.height = value()?.parse()?,
            "--frames" => args.frames = value()?.parse()?,
            "--out" => args.out = value()?.into(),
            "--window" => args.window = true,
            "-h" | "--help" => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            _ => bail!("unknown argument `{arg}`\n{USAGE}"),
        }
    }
    ensure!(args.width > 0 && args.height > 0, "width and height must be positive");
    ensure!(args.frames > 0 || args.window, "frames must be positive (0, until the window is closed, needs --window)");
    Ok(args)
}

// ---------------------------------------------------------------------------------------------
// The renderer's own wgpu objects. Nothing here is specific to the library, except the feature
// its device asks for and the peel test in its fragment shader.
// ---------------------------------------------------------------------------------------------

/// The renderer: its device, its peel pass and attachments, its output texture.
struct Renderer {
    adapter: wgpu::Adapter,
    device: wgpu::Device,
    queue: wgpu::Queue,
    info: wgpu::AdapterInfo,
    extent: [u32; 2],
    pipeline: wgpu::RenderPipeline,
    bind_group: wgpu::BindGroup,
    vertices: wgpu::Buffer,
    vertex_count: u32,
    /// The library writes them: one bound a pixel, and the indirect draw command (5 words).
    bound: wgpu::Buffer,
    draw: wgpu::Buffer,
    colour: wgpu::Texture,
    depth: wgpu::Texture,
    views: [wgpu::TextureView; 2],
    output: wgpu::Texture,
    readback: wgpu::Buffer,
}

/// The APIs `WGPU_BACKEND` names, or the primary ones.
fn instance() -> wgpu::Instance {
    wgpu::Instance::new(wgpu::InstanceDescriptor {
        backends: wgpu::Backends::from_env().unwrap_or(wgpu::Backends::PRIMARY),
        ..wgpu::InstanceDescriptor::new_without_display_handle()
    })
}

impl Renderer {
    /// The renderer on an adapter of `instance` (one that can present to `surface`, when given).
    fn new(instance: &wgpu::Instance, surface: Option<&wgpu::Surface<'static>>, extent: [u32; 2]) -> Result<Renderer> {
        let options = wgpu::RequestAdapterOptions { compatible_surface: surface, ..Default::default() };
        let adapter = pollster::block_on(instance.request_adapter(&options)).context("wgpu offers no adapter")?;
        let info = adapter.get_info();
        ensure!(
            adapter.features().contains(wgpu::Features::IMMEDIATES),
            "{} has no immediates, which the library's kernels read",
            info.name
        );
        let descriptor = wgpu::DeviceDescriptor {
            label: Some("renderer"),
            required_features: wgpu::Features::IMMEDIATES | (adapter.features() & wgpu::Features::TIMESTAMP_QUERY),
            required_limits: adapter.limits(),
            ..Default::default()
        };
        let (device, queue) = pollster::block_on(adapter.request_device(&descriptor))?;

        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("peel"),
            source: wgpu::ShaderSource::Wgsl(include_str!("wgpu_host/peel.wgsl").into()),
        });
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("peel"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Storage { read_only: true },
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            }],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("peel"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: PUSH_BYTES,
        });
        let attributes = wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x4];
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("peel"),
            layout: Some(&pipeline_layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs"),
                compilation_options: Default::default(),
                buffers: &[Some(wgpu::VertexBufferLayout {
                    array_stride: size_of::<Vertex>() as u64,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &attributes,
                })],
            },
            primitive: Default::default(),
            depth_stencil: Some(wgpu::DepthStencilState {
                format: DEPTH,
                depth_write_enabled: Some(true),
                depth_compare: Some(wgpu::CompareFunction::Less),
                stencil: Default::default(),
                bias: Default::default(),
            }),
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("fs"),
                compilation_options: Default::default(),
                targets: &[Some(COLOUR.into())],
            }),
            multiview_mask: None,
            cache: None,
        });

        let pixels = extent[0] as u64 * extent[1] as u64;
        let buffer = |label, size, usage| {
            device.create_buffer(&wgpu::BufferDescriptor { label: Some(label), size, usage, mapped_at_creation: false })
        };
        use wgpu::BufferUsages as B;
        // The library fills and writes them (storage, copies); we read them (fragment, indirect).
        let bound = buffer("bound", 4 * pixels, B::STORAGE | B::COPY_DST | B::COPY_SRC);
        let draw = buffer("draw", 20, B::STORAGE | B::COPY_DST | B::COPY_SRC | B::INDIRECT);
        let triangles = peel_scene();
        let vertices = buffer("vertices", (size_of::<Vertex>() * triangles.len()) as u64, B::VERTEX | B::COPY_DST);
        queue.write_buffer(&vertices, 0, bytemuck::cast_slice(&triangles));
        let readback = buffer("readback", 16 * pixels, B::MAP_READ | B::COPY_DST);
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("peel"),
            layout: &layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: bound.as_entire_binding() }],
        });

        let texture = |label, format, usage| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d { width: extent[0], height: extent[1], depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        use wgpu::TextureUsages as T;
        // The library copies colour out (COPY_SRC) and reads depth in a kernel (TEXTURE_BINDING).
        let colour = texture("colour", COLOUR, T::RENDER_ATTACHMENT | T::COPY_SRC);
        let depth = texture("depth", DEPTH, T::RENDER_ATTACHMENT | T::TEXTURE_BINDING);
        // The library writes the result in place (a storage texture); we copy it out, and sample
        // it when showing it.
        let output = texture("output", OUTPUT, T::STORAGE_BINDING | T::COPY_SRC | T::TEXTURE_BINDING);
        let views = [colour.create_view(&Default::default()), depth.create_view(&Default::default())];
        Ok(Renderer {
            adapter,
            device,
            queue,
            info,
            extent,
            pipeline,
            bind_group,
            vertices,
            vertex_count: triangles.len() as u32,
            bound,
            draw,
            colour,
            depth,
            views,
            output,
            readback,
        })
    }

    /// The formats the adapter can present to `surface` in, preferred first.
    fn surface_formats(&self, surface: &wgpu::Surface) -> Vec<wgpu::TextureFormat> {
        surface.get_capabilities(&self.adapter).formats
    }

    /// Records one peel pass: cleared attachments (the background, the far plane), then the
    /// triangles beyond the bound, drawn with the command the library wrote.
    fn peel_pass(&self, encoder: &mut wgpu::CommandEncoder, view_proj: Mat4, background: [f32; 3]) {
        let clear = wgpu::Color { r: background[0] as f64, g: background[1] as f64, b: background[2] as f64, a: 1.0 };
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("peel pass"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &self.views[0],
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations { load: wgpu::LoadOp::Clear(clear), store: wgpu::StoreOp::Store },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &self.views[1],
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
                stencil_ops: None,
            }),
            ..Default::default()
        });
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &self.bind_group, &[]);
        pass.set_vertex_buffer(0, self.vertices.slice(..));
        pass.set_immediates(0, &push_bytes(view_proj, self.extent[0]));
        pass.draw_indirect(&self.draw, 0);
    }

    /// The output texture's texels, copied by our own pass after the frame and read once it ran.
    fn read_output(&self, encoder: &mut wgpu::CommandEncoder) {
        let layout = wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(16 * self.extent[0]), rows_per_image: None };
        let size = wgpu::Extent3d { width: self.extent[0], height: self.extent[1], depth_or_array_layers: 1 };
        encoder.copy_texture_to_buffer(self.output.as_image_copy(), wgpu::TexelCopyBufferInfo { buffer: &self.readback, layout }, size);
    }

    fn output_image(&self) -> Result<Rgb> {
        let slice = self.readback.slice(..);
        slice.map_async(wgpu::MapMode::Read, |_| {});
        self.device.poll(wgpu::PollType::Wait { submission_index: None, timeout: None })?;
        let view = slice.get_mapped_range().map_err(|e| anyhow::anyhow!("reading the output back: {e}"))?;
        let rgba: &[f32] = bytemuck::cast_slice(&view);
        let data = rgba.as_chunks::<4>().0.iter().map(|p| [p[0], p[1], p[2]]).collect();
        drop(view);
        self.readback.unmap();
        Ok(Rgb { width: self.extent[0], height: self.extent[1], data })
    }
}

/// The immediates of both stages: the view-projection matrix (column-major) and the width, padded
/// to the struct's 16-byte alignment.
const PUSH_BYTES: u32 = 80;

fn push_bytes(view_proj: Mat4, width: u32) -> Vec<u8> {
    let mut bytes: Vec<u8> = bytemuck::cast_slice(&view_proj.to_cols_array()).to_vec();
    bytes.extend(width.to_le_bytes());
    bytes.resize(PUSH_BYTES as usize, 0);
    bytes
}

// ---------------------------------------------------------------------------------------------
// The frames.
// ---------------------------------------------------------------------------------------------

/// What the library did in one frame, and what the frame shows.
struct FrameResult {
    image: Rgb,
    counters: BackendCounters,
    record_ms: f64,
}

/// One frame in one encoder of ours: the peel passes, each appended by the library, then the depth
/// of field into our output texture, then (with a window) our pass showing it, and our copy of it;
/// one submission.
#[allow(clippy::too_many_arguments)]
fn run_frame(
    r: &Renderer,
    backend: &mut WgpuBackend,
    peel: &mut RendererPeel,
    ctx: &mut SplatContext,
    images: (ImageRef, ImageRef, ImageRef),
    lens: ThinLens,
    view_proj: Mat4,
    window: Option<(&Blit, &wgpu::TextureView)>,
) -> Result<FrameResult> {
    let background = [0.5, 0.7, 1.0];
    let (colour, depth, output) = images;
    let before = backend.counters();
    let start = Instant::now();
    let mut encoder = r.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("frame") });
    // Each library call inside a recording into our encoder (`record_into`, ended when it drops),
    // our render passes between them.
    peel.begin(&mut *backend.record_into(&mut encoder)?, &lens)?;
    for k in 0..peel.layers() {
        r.peel_pass(&mut encoder, view_proj, background);
        peel.append(&mut *backend.record_into(&mut encoder)?, k, colour, depth)?;
    }
    {
        let mut recording = backend.record_into(&mut encoder)?;
        peel.finish(&mut *recording)?;
        let frame = peel.frame(lens, FrameOutput::Image(output));
        ctx.record(&mut *recording, &frame)?;
    }
    let record_ms = start.elapsed().as_secs_f64() * 1e3;
    if let Some((blit, target)) = window {
        blit.record(&mut encoder, target);
    }
    r.read_output(&mut encoder);
    r.queue.submit([encoder.finish()]);
    let counters = backend.counters().since(&before);
    let diagnostics = backend.take_diagnostics();
    ensure!(diagnostics.is_empty(), "wgpu reported: {}", diagnostics.join("\n"));
    Ok(FrameResult { image: r.output_image()?, counters, record_ms })
}

/// The check's image of the peel's last frame: its slots, read back from the device (outside the
/// frames, for the check alone), through the same context on the CPU backend.
fn check_peel(check: &mut CpuCheck, backend: &mut WgpuBackend, peel: &RendererPeel, lens: ThinLens, output: ImageRef) -> Result<Rgb> {
    let frame = peel.frame(lens, FrameOutput::Image(output));
    let FrameInput::Layers { fragments, counts, layers, .. } = frame.input else { bail!("a peel's frame reads layers") };
    let pixels = frame.width as u64 * frame.height as u64;
    let slots = backend.read_buffer(fragments.0, 0, SLOT_WORDS as u64 * pixels * layers as u64)?;
    let counts = backend.read_buffer(counts.0, 0, pixels)?;
    check.run(&slots, &counts, layers, lens)
}

/// The renderer with the library's objects, frame after frame.
struct Session {
    r: Renderer,
    backend: WgpuBackend,
    peel: RendererPeel,
    ctx: SplatContext,
    check: CpuCheck,
    images: (ImageRef, ImageRef, ImageRef),
    buffers: [BufferId; 2],
    lens: ThinLens,
    projection: Mat4,
    frames: u32,
    failures: Vec<String>,
    last: Option<Rgb>,
}

impl Session {
    fn new(r: Renderer) -> Result<Session> {
        let [w, h] = r.extent;
        let mut backend = WgpuBackend::from_device(r.device.clone(), r.queue.clone(), r.info.clone());
        println!("backend: {} ({})", backend.device_name(), backend.driver());
        let buffers = [backend.import_buffer(&r.bound, "peel/bound")?, backend.import_buffer(&r.draw, "peel/draw")?];
        let images = (backend.import_texture(&r.colour)?, backend.import_texture(&r.depth)?, backend.import_texture(&r.output)?);

        // The library's objects, made once: the peel (standard depth, as `projection` writes it)
        // and the depth of field.
        let (yfov, near, far) = (50f32.to_radians(), 0.1, 100.0);
        let peel_options = LayerOptions { max_layers: 4, ..LayerOptions::default() };
        let encoding = DepthEncoding::Standard { near, far };
        let peel_desc = RendererPeelDesc::new(&peel_options, w, h, encoding, (yfov / 2.0).tan(), r.vertex_count);
        let peel = RendererPeel::new(&mut backend, &peel_desc, buffers[0], Some(buffers[1]))?;
        let splat_options = SplatOptions { merge: Merge::X4, ..SplatOptions::default() };
        let extent = Extent::new(w, h, peel_options.max_layers);
        let mut desc = SplatContextDesc::new(extent, splat_options.clone());
        desc.image_io = true;
        let ctx = SplatContext::new(&mut backend, &desc)?;
        // Creating them recorded the zeroing of their buffers; running it now leaves nothing for
        // the first frame to submit.
        backend.submit()?;
        println!("peel and context: {:.1} MiB of device memory", (peel.device_bytes() + ctx.device_bytes()) as f64 / (1 << 20) as f64);
        let check = CpuCheck::new(backend.limits().max_shared_bytes, &SplatContextDesc::new(extent, splat_options))?;
        let lens = ThinLens { focal_length: 0.05, aperture_radius: 0.02, focus_distance: 3.0, pixels_per_unit: h as f32 / 0.024 };
        let projection = projection(yfov, w as f32 / h as f32, near, far, false);
        Ok(Session { r, backend, peel, ctx, check, images, buffers, lens, projection, frames: 0, failures: Vec::new(), last: None })
    }

    /// The next frame, the camera orbiting the focus point 2 degrees a frame, shown in `window`
    /// when given; checked against the CPU backend.
    fn frame(&mut self, window: Option<(&Blit, &wgpu::TextureView)>) -> Result<()> {
        let i = self.frames;
        self.frames += 1;
        let angle = (2.0 * i as f32).to_radians();
        let target = Vec3::new(0.0, 0.0, -3.0);
        let eye = target + 3.0 * Vec3::new(angle.sin(), 0.0, angle.cos());
        let view_proj = self.projection * look_at(eye, target);
        let frame = run_frame(&self.r, &mut self.backend, &mut self.peel, &mut self.ctx, self.images, self.lens, view_proj, window)?;
        let c = frame.counters;
        println!(
            "frame {i} (orbit {:.0} deg): recorded in {:.2} ms; the library's {} commands: {} allocations, {} submissions, {} readbacks, {} uploads",
            angle.to_degrees(),
            frame.record_ms,
            c.commands,
            c.allocations,
            c.submissions,
            c.readbacks,
            c.uploads
        );
        if (c.allocations, c.submissions, c.readbacks, c.uploads) != (0, 0, 0, 0) {
            self.failures.push(format!("frame {i}: the library allocated, submitted or transferred: {c:?}"));
        }
        let want = check_peel(&mut self.check, &mut self.backend, &self.peel, self.lens, self.images.2)?;
        let (diff, ok) = compare(&frame.image, &want);
        println!(
            "  vs the same context on the CPU backend: largest difference per channel {diff:?}{}",
            if ok { "" } else { ": TOO LARGE" }
        );
        if !ok {
            self.failures.push(format!("frame {i} differs from the CPU backend by {diff:?}"));
        }
        self.last = Some(frame.image);
        Ok(())
    }

    /// The peel's report and the last image written; the library's objects destroyed.
    fn finish(mut self, out: &std::path::Path) -> Result<ExitCode> {
        let report = self.peel.report(&mut self.backend)?;
        println!("peel: {} passes recorded, {} drawn, {} found a surface", report.recorded, report.drawn, report.with_surface);
        if report.with_surface < 3 {
            self.failures.push(format!("the peel found surfaces in {} passes, want 3 (bar, pane, wall)", report.with_surface));
        }
        std::fs::create_dir_all(out)?;
        if let Some(image) = &self.last {
            let path = out.join("peeled");
            write_image(&path, image)?;
            println!("wrote {} and .png", path.with_extension("exr").display());
        }
        // Teardown: the library's objects; our buffers and textures are only forgotten by it.
        self.check.destroy();
        self.peel.destroy(&mut self.backend);
        self.ctx.destroy(&mut self.backend);
        for id in self.buffers {
            self.backend.destroy_buffer(id);
        }
        if self.failures.is_empty() {
            println!("ok");
            Ok(ExitCode::SUCCESS)
        } else {
            eprintln!("FAILED:\n  {}", self.failures.join("\n  "));
            Ok(ExitCode::FAILURE)
        }
    }
}

fn main() -> Result<ExitCode> {
    let args = parse_args()?;
    if args.window {
        return window::run(args);
    }
    let instance = instance();
    let mut session = Session::new(Renderer::new(&instance, None, [args.width, args.height])?)?;
    for _ in 0..args.frames {
        session.frame(None)?;
    }
    session.finish(&args.out)
}

/// Our pass that shows the output texture in a window: a full-screen triangle loading its texels,
/// through a plain x / (1 + x) curve of our own, into the surface's format.
struct Blit {
    pipeline: wgpu::RenderPipeline,
    bind_group: wgpu::BindGroup,
}

impl Blit {
    fn new(r: &Renderer, format: wgpu::TextureFormat) -> Blit {
        let module = r.device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("blit"),
            source: wgpu::ShaderSource::Wgsl(include_str!("wgpu_host/blit.wgsl").into()),
        });
        let pipeline = r.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("blit"),
            layout: None,
            vertex: wgpu::VertexState { module: &module, entry_point: Some("vs"), compilation_options: Default::default(), buffers: &[] },
            primitive: Default::default(),
            depth_stencil: None,
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("fs"),
                compilation_options: Default::default(),
                targets: &[Some(format.into())],
            }),
            multiview_mask: None,
            cache: None,
        });
        let view = r.output.create_view(&Default::default());
        let bind_group = r.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("blit"),
            layout: &pipeline.get_bind_group_layout(0),
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&view) }],
        });
        Blit { pipeline, bind_group }
    }

    fn record(&self, encoder: &mut wgpu::CommandEncoder, target: &wgpu::TextureView) {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("blit"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: target,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations { load: wgpu::LoadOp::Clear(wgpu::Color::BLACK), store: wgpu::StoreOp::Store },
            })],
            ..Default::default()
        });
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &self.bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
}

/// The frames in a window (winit): each presented as it is made, until `--frames` were shown (or,
/// with `--frames 0`, until the window is closed).
mod window {
    use super::{Args, Blit, Renderer, Session, instance};
    use anyhow::Result;
    use std::process::ExitCode;
    use std::sync::Arc;
    use winit::application::ApplicationHandler;
    use winit::event::WindowEvent;
    use winit::event_loop::{ActiveEventLoop, EventLoop};
    use winit::window::{Window, WindowId};

    struct Shown {
        window: Arc<Window>,
        surface: wgpu::Surface<'static>,
        blit: Blit,
        session: Session,
    }

    struct App {
        args: Args,
        shown: Option<Shown>,
        outcome: Option<Result<ExitCode>>,
    }

    impl App {
        fn open(&mut self, event_loop: &ActiveEventLoop) -> Result<Shown> {
            let size = winit::dpi::PhysicalSize::new(self.args.width, self.args.height);
            let attributes = Window::default_attributes().with_title("dof: wgpu_host").with_inner_size(size).with_resizable(false);
            let window = Arc::new(event_loop.create_window(attributes)?);
            let instance = instance();
            let surface = instance.create_surface(window.clone())?;
            let r = Renderer::new(&instance, Some(&surface), [self.args.width, self.args.height])?;
            let formats = r.surface_formats(&surface);
            let format = formats.iter().copied().find(wgpu::TextureFormat::is_srgb).or(formats.first().copied());
            let format = format.ok_or_else(|| anyhow::anyhow!("the window's surface offers no format"))?;
            let config = wgpu::SurfaceConfiguration {
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                format,
                width: self.args.width,
                height: self.args.height,
                present_mode: wgpu::PresentMode::Fifo,
                desired_maximum_frame_latency: 2,
                alpha_mode: wgpu::CompositeAlphaMode::Auto,
                view_formats: vec![],
                color_space: wgpu::SurfaceColorSpace::Auto,
            };
            surface.configure(&r.device, &config);
            let blit = Blit::new(&r, format);
            Ok(Shown { window, surface, blit, session: Session::new(r)? })
        }

        fn redraw(&mut self, event_loop: &ActiveEventLoop) -> Result<()> {
            let Some(shown) = self.shown.as_mut() else { return Ok(()) };
            let frame = match shown.surface.get_current_texture() {
                wgpu::CurrentSurfaceTexture::Success(frame) | wgpu::CurrentSurfaceTexture::Suboptimal(frame) => frame,
                other => anyhow::bail!("the window's next image: {other:?}"),
            };
            let view = frame.texture.create_view(&Default::default());
            shown.session.frame(Some((&shown.blit, &view)))?;
            shown.window.pre_present_notify();
            shown.session.r.queue.present(frame);
            if self.args.frames > 0 && shown.session.frames >= self.args.frames {
                event_loop.exit();
            } else {
                shown.window.request_redraw();
            }
            Ok(())
        }

        fn fail(&mut self, event_loop: &ActiveEventLoop, e: anyhow::Error) {
            self.outcome = Some(Err(e));
            event_loop.exit();
        }
    }

    impl ApplicationHandler for App {
        fn resumed(&mut self, event_loop: &ActiveEventLoop) {
            if self.shown.is_none() {
                match self.open(event_loop) {
                    Ok(shown) => {
                        shown.window.request_redraw();
                        self.shown = Some(shown);
                    }
                    Err(e) => self.fail(event_loop, e),
                }
            }
        }

        fn window_event(&mut self, event_loop: &ActiveEventLoop, _: WindowId, event: WindowEvent) {
            match event {
                WindowEvent::CloseRequested => event_loop.exit(),
                WindowEvent::RedrawRequested => {
                    if let Err(e) = self.redraw(event_loop) {
                        self.fail(event_loop, e);
                    }
                }
                _ => {}
            }
        }
    }

    pub fn run(args: Args) -> Result<ExitCode> {
        let event_loop = EventLoop::new()?;
        let mut app = App { args, shown: None, outcome: None };
        event_loop.run_app(&mut app)?;
        if let Some(outcome) = app.outcome.take() {
            return outcome;
        }
        let shown = app.shown.take().ok_or_else(|| anyhow::anyhow!("the window never opened"))?;
        println!("{} frames shown in the window", shown.session.frames);
        shown.session.finish(&app.args.out)
    }
}
