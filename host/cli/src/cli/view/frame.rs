//! The window's event loop and the frame: the layers (a mesh's peeled on the device in the frame's
//! command buffer whenever the camera moved, an EXR's uploaded once), the depth of field through the frame API into the viewer's command buffer, the blit to the swapchain image, the UI,
//! present; after the fence, a frame later, what the frame cost and left out.

use super::ViewArgs;
use super::controls::{Controls, orbit};
use super::device::{Device, Fit, Owned, TRANSFER};
use super::methods::{Contexts, MethodSettings, stage_times};
use super::scene::{LAYERS, Layers, SceneSource};
use super::script::Step;
use super::swapchain::Swapchain;
use super::ui::{Panel, Stats};
use anyhow::{Context, Result, anyhow, bail};
use dof::backend::vulkan::ash::vk::{self, AccessFlags as Access, ImageLayout as Layout};
use dof::backend::{Backend, BufferId, ImageFormat, ImageRef, RawDevice, RawOptions, RunKernel, VulkanBackend};
use dof::frame::{CountBuffer, Frame, FrameInput, FrameOutput, RgbBuffer, SlotBuffer};
use dof::layers::{LayeredImage, RgbImage};
use dof::methods::buffers::SLOT_WORDS;
use dof::methods::buffers::groups_for;
use dof::raster::{MeshPeelContext, MeshPeelDesc, default_near};
use dof::scene::{Camera, Focus, GuardBand, LayerOptions, LensSettings, MAX_GUARD_BAND, ThinLens};
use dof_shaders::slot::DEPTH_WORD;
use dof_shaders::tonemap::{DISPLAY, DisplayParams, MODE_LINEAR, MODE_TONEMAP, display_tonemap};
use raw_window_handle::{HasDisplayHandle, HasWindowHandle};
use std::time::Instant;
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::WindowEvent;
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::KeyCode;
use winit::window::{Window, WindowId};

/// Samples per pixel of the reference the error view computes.
const REFERENCE_SAMPLES: u32 = 64;

/// The multi-layer image's buffers on the device: all layers, and the front layer alone (what the
/// single-layer methods read). Made by the library (`create_buffer`) and written between frames.
struct Inputs {
    all: (BufferId, BufferId),
    front: (BufferId, BufferId),
    pixels: u64,
    layers: u32,
}

impl Inputs {
    /// Uploads `image`, growing the buffers when it needs more. Only between frames.
    fn upload(inputs: &mut Option<Inputs>, backend: &mut dyn Backend, image: &LayeredImage) -> Result<()> {
        let pixels = image.width as u64 * image.height as u64;
        if inputs.as_ref().is_none_or(|i| i.pixels < pixels || i.layers < image.max_layers) {
            if let Some(old) = inputs.take() {
                old.destroy(backend);
            }
            let layers = image.max_layers.max(LAYERS);
            inputs.replace(Inputs {
                all: (
                    backend.create_buffer(SLOT_WORDS as u64 * pixels * layers as u64, "view/fragments")?,
                    backend.create_buffer(pixels, "view/counts")?,
                ),
                front: (
                    backend.create_buffer(SLOT_WORDS as u64 * pixels, "view/front")?,
                    backend.create_buffer(pixels, "view/front-counts")?,
                ),
                pixels,
                layers,
            });
        }
        let i = inputs.as_ref().context("inputs were just made")?;
        let front = image.front_layer();
        backend.write_buffer(i.all.0, 0, &dof::methods::buffers::slot_words(image))?;
        backend.write_buffer(i.all.1, 0, &image.counts)?;
        backend.write_buffer(i.front.0, 0, &dof::methods::buffers::slot_words(&front))?;
        backend.write_buffer(i.front.1, 0, &front.counts)?;
        Ok(())
    }

    fn destroy(self, backend: &mut dyn Backend) {
        for b in [self.all.0, self.all.1, self.front.0, self.front.1] {
            backend.destroy_buffer(b);
        }
    }
}

/// A mesh scene's layers, peeled on the device into the frame's command buffer when the camera moved. Made
/// again (between frames) when the frame size or the lens changes: its guard band is the automatic
/// one of the view it was made from (Franke et al. 2018, §4; `dof render`'s), fixed while the
/// camera moves, which goes in through push constants.
struct DevicePeel {
    ctx: MeshPeelContext,
    size: [u32; 2],
    lens: LensSettings,
    /// The camera the slots were last peeled for: a still camera keeps them (nothing else writes
    /// them), a moving one peels again in the frame's command buffer.
    peeled: Option<Camera>,
}

impl DevicePeel {
    /// The front depth at frame pixel `(x, y)` of the last peeled frame (one readback, on a click).
    fn front_depth(&self, backend: &mut dyn Backend, x: u32, y: u32) -> Result<Option<f32>> {
        let s = self.ctx.slots();
        let (x, y) = (x + self.ctx.margin(), y + self.ctx.margin());
        if x >= s.width || y >= s.height {
            return Ok(None);
        }
        let p = y as u64 * s.width as u64 + x as u64;
        if backend.read_buffer(s.counts, p, 1)?[0] == 0 {
            return Ok(None);
        }
        let depth = f32::from_bits(backend.read_buffer(s.fragments, SLOT_WORDS as u64 * p * s.layers as u64 + DEPTH_WORD as u64, 1)?[0]);
        Ok(Some(depth).filter(|d| d.is_finite() && *d > 0.0))
    }
}

/// What the frame reads: its size (frame and guard band), slots a pixel, guard band, lens.
#[derive(Clone, Copy)]
struct Shape {
    width: u32,
    height: u32,
    layers: u32,
    margin: u32,
    lens: ThinLens,
}

/// The frame's result on the device, in the library's buffers (as large as the contexts' frames):
/// the linear RGB the frame API writes (3 words a pixel), and what the display pass makes of it,
/// sRGB-encoded RGBA32F (4 words a pixel), which is copied into the target image and blitted into
/// the swapchain image.
struct Display {
    rgb: BufferId,
    rgba: BufferId,
    pixels: u64,
}

impl Display {
    fn destroy(self, backend: &mut dyn Backend) {
        backend.destroy_buffer(self.rgb);
        backend.destroy_buffer(self.rgba);
    }
}

/// The window's part of a frame's linear result, for the error against the reference: the frame's
/// width, the guard band's margin and the window's size.
#[derive(Clone, Copy)]
struct LinearRead {
    frame_width: u32,
    margin: u32,
    size: [u32; 2],
}

/// What a submitted frame asked to be done once it completed.
#[derive(Default)]
struct Pending {
    submitted: bool,
    screenshot: bool,
    linear: Option<LinearRead>,
    free: Vec<egui::TextureId>,
    report: bool,
}

/// Everything that exists while the window is open.
struct Running {
    window: Window,
    surface_fn: dof::backend::vulkan::ash::khr::surface::Instance,
    surface: vk::SurfaceKHR,
    d: Device,
    sc: Option<Swapchain>,
    backend: Option<VulkanBackend>,
    contexts: Option<Contexts>,
    inputs: Option<Inputs>,
    peel: Option<DevicePeel>,
    /// The blurred frame for display (RGBA32F, sRGB-encoded by the display pass), as large as the
    /// contexts' frames.
    target: Option<(Owned<vk::Image>, [u32; 2], bool)>,
    display: Option<Display>,
    /// A host-visible buffer for the screenshot (8-bit swapchain pixels), written by every frame
    /// when --screenshot is given, so that a window closed early still leaves its last image.
    readback: Option<Owned<vk::Buffer>>,
    /// What `readback` holds once its frame completed: the swapchain image's size and whether its
    /// pixels are BGRA.
    shot: Option<([u32; 2], bool)>,
    egui_ctx: egui::Context,
    egui_state: egui_winit::State,
    renderer: Option<egui_ash_renderer::Renderer>,
    error_texture: Option<egui::TextureHandle>,
    layers: Option<(Camera, LensSettings, Layers)>,
    reference: Option<(Camera, LensSettings, RgbImage)>,
    pending: Pending,
    resize: bool,
}

struct App<'a> {
    args: &'a ViewArgs,
    source: SceneSource,
    steps: Vec<Step>,
    running: Option<Running>,
    error: Option<anyhow::Error>,
    camera: Camera,
    lens: LensSettings,
    panel: Panel,
    stats: Stats,
    controls: Controls,
    frames_recorded: u32,
    last_frame: Option<Instant>,
    last_report: Instant,
    closed: bool,
    /// Whether the screenshot (--screenshot) was written.
    screenshot_written: bool,
    /// Wall time between frames and GPU time, summed over every frame but the first (which makes
    /// the pipelines): for the summary at exit.
    timed: (u32, f64, u32, f64),
    /// The library's own work over the frames that remade nothing (no context, peel, input or
    /// buffer made, the camera free to move): frames, and the backend's counters summed.
    steady: (u32, dof::backend::BackendCounters),
}

pub fn run_app(args: &ViewArgs, source: SceneSource, steps: Vec<Step>) -> Result<()> {
    let event_loop = EventLoop::new().map_err(|e| anyhow!("cannot open the display (is DISPLAY set? under CI run with xvfb-run): {e}"))?;
    event_loop.set_control_flow(ControlFlow::Poll);
    let camera = source.camera;
    // The focus as a distance from here on (a scene may focus on a point, which the camera could
    // move past).
    let focus = source.lens.thin_lens(&camera)?.focus_distance;
    let lens = LensSettings { focus: Focus::Distance(focus), ..source.lens };
    let settings = MethodSettings { method: args.method, merge: args.merge, tile: args.tile, aperture: String::new(), rings: args.rings };
    let mut panel = Panel {
        visible: !args.hide_ui,
        settings,
        focus,
        aperture: lens.aperture,
        blades: args.blades,
        show_error: false,
        exposure: args.exposure,
        raw_linear: false,
    };
    panel.settings.aperture = panel.shape();
    let mut app = App {
        args,
        source,
        steps,
        running: None,
        error: None,
        camera,
        lens,
        panel,
        stats: Stats::default(),
        controls: Controls::default(),
        frames_recorded: 0,
        last_frame: None,
        last_report: Instant::now(),
        closed: false,
        screenshot_written: false,
        timed: (0, 0.0, 0, 0.0),
        steady: (0, Default::default()),
    };
    println!("view at the start: {}", view_flags(&app.camera, &app.lens));
    event_loop.run_app(&mut app).map_err(|e| anyhow!("the event loop failed: {e}"))?;
    println!("view at the end: {}", view_flags(&app.camera, &app.lens));
    let messages = app.finish();
    if let Some(e) = app.error {
        return Err(e);
    }
    if app.args.validation {
        println!("validation: {} message(s)", messages.len());
        if !messages.is_empty() {
            bail!("the validation layer reported {} message(s)", messages.len());
        }
    }
    let (n, wall, gn, gpu) = app.timed;
    if n > 0 && gn > 0 {
        println!(
            "frame times after the first frame: {:.1} ms a frame ({:.2} FPS) over {n} frames, GPU {:.1} ms over {gn}",
            wall / n as f64,
            1e3 * n as f64 / wall,
            gpu / gn as f64
        );
    }
    let (steady, c) = app.steady;
    if steady > 0 {
        println!(
            "library work per frame over {steady} frames that remade nothing: {} allocations, {} uploads, {} readbacks, {} submissions of its own (the frame is the viewer's one submission)",
            c.allocations as f64 / steady as f64,
            c.uploads as f64 / steady as f64,
            c.readbacks as f64 / steady as f64,
            c.submissions as f64 / steady as f64
        );
    }
    println!("exited cleanly after {} frames", app.frames_recorded);
    Ok(())
}

impl ApplicationHandler for App<'_> {
    fn resumed(&mut self, el: &ActiveEventLoop) {
        if self.running.is_none()
            && let Err(e) = self.open(el)
        {
            self.fail(el, e);
        }
    }

    fn window_event(&mut self, el: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        let Some(r) = self.running.as_mut() else { return };
        let response = r.egui_state.on_window_event(&r.window, &event);
        match event {
            WindowEvent::CloseRequested => self.close(el),
            WindowEvent::Resized(_) => r.resize = true,
            WindowEvent::RedrawRequested => {
                if let Err(e) = self.frame(el) {
                    self.fail(el, e);
                }
            }
            other => {
                if !response.consumed {
                    let pivot = match self.lens.focus {
                        Focus::Distance(d) => d,
                        Focus::Point(_) => 0.0,
                    };
                    self.controls.event(&other, &mut self.camera, self.source.movable(), pivot);
                }
            }
        }
    }

    fn about_to_wait(&mut self, _el: &ActiveEventLoop) {
        if let Some(r) = &self.running {
            r.window.request_redraw();
        }
    }
}

impl App<'_> {
    fn fail(&mut self, el: &ActiveEventLoop, e: anyhow::Error) {
        if self.error.is_none() {
            self.error = Some(e);
        }
        el.exit();
    }

    /// Closing the window: the last frame completes, then `finish` tears everything down.
    fn close(&mut self, el: &ActiveEventLoop) {
        self.closed = true;
        el.exit();
    }

    /// The window, the device on it, the library on that device, the UI renderer.
    fn open(&mut self, el: &ActiveEventLoop) -> Result<()> {
        let size = self.source.fixed_size().unwrap_or(self.args.size());
        let attributes = Window::default_attributes()
            .with_title(format!("dof view: {}", self.source.name))
            .with_inner_size(PhysicalSize::new(size[0], size[1]));
        let window = el.create_window(attributes).context("cannot create the window")?;
        let display = window.display_handle().map_err(|e| anyhow!("no display handle: {e}"))?.as_raw();
        let handle = window.window_handle().map_err(|e| anyhow!("no window handle: {e}"))?.as_raw();
        let (entry, instance, messenger, log) = Device::instance(display, self.args.validation)?;
        let surface_fn = dof::backend::vulkan::ash::khr::surface::Instance::new(&entry, &instance);
        // SAFETY: the window outlives the surface (destroyed in `finish` before the window drops).
        let surface = unsafe { ash_window::create_surface(&entry, &instance, display, handle, None)? };
        let d = Device::new((entry, instance, messenger, log), &surface_fn, surface, self.args.device.as_deref())?;
        let raw = RawDevice {
            entry: d.entry.clone(),
            instance: d.instance.clone(),
            physical_device: d.physical,
            device: d.device.clone(),
            queue_family: d.queue_family,
            queue: d.queue,
        };
        // SAFETY: the handles are live and outlive the backend (dropped in `finish` first); the
        // device was made with the required version, extensions and features; one thread.
        let backend = unsafe { VulkanBackend::from_raw(raw, &RawOptions { debug_names: self.args.validation, ..Default::default() })? };
        // The size against what the device holds, before anything is made for it.
        let flags = match self.source.fixed_size() {
            Some([w, h]) => format!("--scene {} ({w}x{h} pixels, shown at its own size)", self.args.scene),
            None => format!("--width {} --height {}", size[0], size[1]),
        };
        let frame = size.map(|e| e.saturating_add(2 * MAX_GUARD_BAND));
        let fit = Fit { flags: &flags, window: size, frame, layers: self.source.max_layers() };
        if let Err(e) = d.check_fits(&surface_fn, surface, backend.limits(), &fit) {
            drop(backend);
            d.destroy(Some((&surface_fn, surface)));
            return Err(e);
        }
        let inner = window.inner_size();
        let sc = Swapchain::new(&d, &surface_fn, surface, [inner.width, inner.height], self.args.vsync, None)?;
        let options = egui_ash_renderer::Options { in_flight_frames: 1, srgb_framebuffer: false, ..Default::default() };
        let renderer =
            egui_ash_renderer::Renderer::with_default_allocator(&d.instance, d.physical, d.device.clone(), sc.render_pass, options)
                .map_err(|e| anyhow!("the UI renderer: {e}"))?;
        let egui_ctx = egui::Context::default();
        // Smaller than egui's default: the windows that stay usable on lavapipe are small.
        egui_ctx.set_zoom_factor(0.8);
        let egui_state =
            egui_winit::State::new(egui_ctx.clone(), egui::ViewportId::ROOT, &window, Some(window.scale_factor() as f32), None, None);
        self.stats.device = backend.device_name();
        self.stats.has_reference = self.source.has_reference();
        println!(
            "dof view: {} on {} ({}), {}x{}, present mode {:?}",
            self.source.name,
            backend.device_name(),
            backend.driver(),
            sc.extent.width,
            sc.extent.height,
            sc.present_mode
        );
        self.running = Some(Running {
            window,
            surface_fn,
            surface,
            d,
            sc: Some(sc),
            backend: Some(backend),
            contexts: None,
            inputs: None,
            peel: None,
            target: None,
            display: None,
            readback: None,
            shot: None,
            egui_ctx,
            egui_state,
            renderer: Some(renderer),
            error_texture: None,
            layers: None,
            reference: None,
            pending: Pending::default(),
            resize: false,
        });
        Ok(())
    }

    /// Waits for the frame before and reads what it left: its GPU times, its report (a few times
    /// a second), the screenshot and the linear result when asked for.
    fn complete(&mut self) -> Result<()> {
        let r = self.running.as_mut().context("not running")?;
        // SAFETY: the fence is live; waiting is the one host synchronisation per frame.
        unsafe { r.d.device.wait_for_fences(&[r.d.fence], true, u64::MAX)? };
        let pending = std::mem::take(&mut r.pending);
        if !pending.submitted {
            return Ok(());
        }
        let backend = r.backend.as_mut().context("no backend")?;
        if let Some(times) = backend.take_external_times()? {
            let (stages, total) = stage_times(&times);
            self.stats.stages = stages;
            self.stats.gpu_ms = total;
            if self.frames_recorded > 1 {
                self.timed.2 += 1;
                self.timed.3 += total;
            }
        }
        if pending.report
            && let Some(c) = &r.contexts
        {
            self.stats.report = c.report(backend, self.panel.settings.method)?;
        }
        if let Some(renderer) = r.renderer.as_mut() {
            renderer.free_textures(&pending.free).map_err(|e| anyhow!("the UI renderer: {e}"))?;
        }
        if pending.screenshot {
            write_shot(self.args, &r.readback, r.shot, "the last presented image")?;
            self.screenshot_written = true;
        }
        if let (Some(read), Some(display)) = (pending.linear, &r.display) {
            // The frame completed and nothing writes the buffer until the next one is recorded.
            let [w, h] = read.size;
            let image = super::readback::window_of_rgb(backend, display.rgb, read.frame_width, read.margin, [w, h])?;
            if let Some((camera, lens, reference)) = &r.reference
                && *camera == self.camera
                && *lens == self.lens
                && reference.width == w
                && reference.height == h
            {
                let (psnr, picture) = super::readback::error_view(&image, reference)?;
                let text = format!("PSNR {psnr:.2} dB against the reference ({REFERENCE_SAMPLES} samples a pixel); error x8 below");
                if self.stats.error.as_ref() != Some(&text) {
                    println!("error vs reference: {text}");
                }
                self.stats.error = Some(text);
                r.error_texture = Some(r.egui_ctx.load_texture("error", picture, egui::TextureOptions::NEAREST));
            }
        }
        Ok(())
    }

    /// One frame: the clock, the script and the controls, then the frame itself
    /// ([`Self::frame_in`]) with the window's objects, then, after the last of `--frames`, its
    /// completion.
    fn frame(&mut self, el: &ActiveEventLoop) -> Result<()> {
        self.complete()?;
        let Some(dt) = self.tick(el) else { return Ok(()) };
        let movable = self.source.movable();
        if movable {
            self.controls.fly(&mut self.camera, dt as f32);
        }
        for key in std::mem::take(&mut self.controls.pressed) {
            if key == KeyCode::KeyH {
                self.panel.visible = !self.panel.visible;
            }
        }
        let mut r = self.running.take().context("not running")?;
        let last = self.frame_in(&mut r);
        self.running = Some(r);
        if last? {
            // The screenshot and the last report are read now, then the loop ends.
            self.complete()?;
            el.exit();
        }
        Ok(())
    }

    /// The frame's clock and the script's step: the seconds since the last frame, or `None` when
    /// the frames are done or the window closed.
    fn tick(&mut self, el: &ActiveEventLoop) -> Option<f64> {
        if self.args.frames.is_some_and(|n| self.frames_recorded >= n) || self.closed {
            el.exit();
            return None;
        }
        let now = Instant::now();
        let dt = self.last_frame.map_or(0.0, |t| now.duration_since(t).as_secs_f64());
        self.last_frame = Some(now);
        if dt > 0.0 {
            self.stats.frame_ms = 1e3 * dt;
            if self.frames_recorded > 1 {
                self.timed.0 += 1;
                self.timed.1 += 1e3 * dt;
            }
            self.stats.fps = if self.stats.fps == 0.0 { 1.0 / dt } else { 0.8 * self.stats.fps + 0.2 / dt };
        }
        // Scripted steps, one a frame.
        if let Some(step) = self.steps.get(self.frames_recorded as usize).cloned() {
            self.apply(step, el);
            if self.closed {
                return None;
            }
        }
        Some(dt)
    }

    /// The frame with the window's objects: the UI, the lens and focus, the layers and buffers it
    /// needs, then its commands, submitted and presented. Returns whether it was the last of
    /// `--frames`.
    fn frame_in(&mut self, r: &mut Running) -> Result<bool> {
        if !resize_swapchain(r, self.args.vsync)? {
            return Ok(false);
        }
        let extent = r.sc.as_ref().context("no swapchain")?.extent;
        let fixed = self.source.fixed_size();
        let size = fixed.unwrap_or([extent.width, extent.height]);
        self.camera.width = size[0];
        self.camera.height = size[1];
        let output = self.build_ui(r)?;
        let primitives = r.egui_ctx.tessellate(output.shapes, output.pixels_per_point);
        self.take_panel_lens();
        self.focus_on_click(r, extent, size)?;

        let lens = self.lens.thin_lens(&self.camera)?;
        let before = r.backend.as_ref().context("no backend")?.counters();
        // Whether anything was made this frame (the library's counters count it then).
        let mut remade = false;
        let shape = self.prepare_layers(r, &lens, &mut remade)?;
        self.stats.frame = [size[0], size[1]];
        self.prepare_buffers(r, &shape, size, &mut remade)?;
        let last = self.args.frames.is_some_and(|n| self.frames_recorded + 1 == n);
        // The swapchain image is copied for the screenshot every frame (written after the last).
        let copy_shot = self.args.screenshot.is_some();
        let want_linear = self.panel.show_error && fixed.is_none() && self.source.has_reference();
        if want_linear && r.reference.as_ref().is_none_or(|(c, l, _)| *c != self.camera || *l != self.lens) {
            println!("computing the reference for this view ({REFERENCE_SAMPLES} samples a pixel)...");
            let backend = r.backend.as_mut().context("no backend")?;
            let image = self.source.reference(backend, &self.camera, &self.lens, REFERENCE_SAMPLES)?;
            r.reference = Some((self.camera, self.lens, image));
            remade = true;
        }
        let (w, h) = (extent.width, extent.height);
        if copy_shot && r.readback.as_ref().is_none_or(|b| b.bytes < (w * h * 4) as u64) {
            r.shot = None;
            if let Some(old) = r.readback.take() {
                r.d.destroy_buffer(old);
            }
            r.readback = Some(r.d.host_buffer((w * h * 4) as u64, vk::BufferUsageFlags::TRANSFER_DST)?);
        }
        let renderer = r.renderer.as_mut().context("no UI renderer")?;
        renderer.set_textures(r.d.queue, r.d.pool, &output.textures_delta.set).map_err(|e| anyhow!("the UI renderer: {e}"))?;

        // The swapchain image.
        let sc = r.sc.as_ref().context("no swapchain")?;
        // SAFETY: the semaphore is unsignalled (the frame that waited on it completed).
        let index = match unsafe { sc.loader.acquire_next_image(sc.handle, u64::MAX, sc.acquired, vk::Fence::null()) } {
            Ok((index, suboptimal)) => {
                r.resize |= suboptimal;
                index
            }
            Err(vk::Result::ERROR_OUT_OF_DATE_KHR) => {
                r.resize = true;
                return Ok(false);
            }
            Err(e) => return Err(e).context("vkAcquireNextImageKHR"),
        };

        // Record: the depth of field and the display pass, the blit into the swapchain image, the
        // UI over it, the screenshot's copy.
        let cb = r.d.cb;
        // SAFETY: the command buffer's last submission completed (the fence).
        unsafe {
            r.d.device.reset_command_buffer(cb, vk::CommandBufferResetFlags::empty())?;
            r.d.device
                .begin_command_buffer(cb, &vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT))?;
        }
        let target_image = self.record_dof(r, &shape, &lens)?;
        let image = record_blit(r, index, target_image, &shape, size, fixed.is_some())?;
        let (d, sc) = (&r.d, r.sc.as_ref().context("no swapchain")?);
        // The UI over it, in the render pass (which leaves the image in TRANSFER_SRC_OPTIMAL).
        let pass = vk::RenderPassBeginInfo::default()
            .render_pass(sc.render_pass)
            .framebuffer(sc.framebuffers[index as usize])
            .render_area(vk::Rect2D { offset: vk::Offset2D::default(), extent });
        // SAFETY: recording; the framebuffer is the acquired image's.
        unsafe { d.device.cmd_begin_render_pass(cb, &pass, vk::SubpassContents::INLINE) };
        let renderer = r.renderer.as_mut().context("no UI renderer")?;
        renderer.cmd_draw(cb, extent, output.pixels_per_point, &primitives).map_err(|e| anyhow!("the UI renderer: {e}"))?;
        // SAFETY: recording, inside the render pass begun above.
        unsafe { d.device.cmd_end_render_pass(cb) };
        if let (true, Some(buf)) = (copy_shot, &r.readback) {
            r.shot = Some(([w, h], sc.format == vk::Format::B8G8R8A8_UNORM));
            let region = vk::BufferImageCopy::default()
                .image_subresource(vk::ImageSubresourceLayers::default().aspect_mask(vk::ImageAspectFlags::COLOR).layer_count(1))
                .image_extent(vk::Extent3D { width: w, height: h, depth: 1 });
            // SAFETY: recording; the render pass left the image in TRANSFER_SRC_OPTIMAL and its
            // outgoing dependency made the UI's writes visible to this copy.
            unsafe { d.device.cmd_copy_image_to_buffer(cb, image, Layout::TRANSFER_SRC_OPTIMAL, buf.handle, &[region]) };
            d.memory_barrier((TRANSFER, Access::TRANSFER_WRITE), (vk::PipelineStageFlags::HOST, Access::HOST_READ));
        }
        d.image_barrier(
            image,
            Layout::TRANSFER_SRC_OPTIMAL,
            Layout::PRESENT_SRC_KHR,
            (TRANSFER, Access::empty()),
            (vk::PipelineStageFlags::BOTTOM_OF_PIPE, Access::empty()),
        );

        // Submit and present.
        let (waits, stages, cbs, signals) = ([sc.acquired], [TRANSFER], [cb], [sc.rendered[index as usize]]);
        let submit = vk::SubmitInfo::default()
            .wait_semaphores(&waits)
            .wait_dst_stage_mask(&stages)
            .command_buffers(&cbs)
            .signal_semaphores(&signals);
        // SAFETY: recorded commands; the fence was waited for above and is reset only now that a
        // submission will signal it.
        unsafe {
            d.device.end_command_buffer(cb)?;
            d.device.reset_fences(&[d.fence])?;
            d.device.queue_submit(d.queue, &[submit], d.fence)?;
        }
        if let (false, Some(b)) = (remade, r.backend.as_ref()) {
            let c = b.counters().since(&before);
            let s = &mut self.steady.1;
            self.steady.0 += 1;
            s.allocations += c.allocations;
            s.uploads += c.uploads;
            s.readbacks += c.readbacks;
            s.submissions += c.submissions;
        }
        let report_due = self.last_report.elapsed().as_secs_f64() > 0.5 || last;
        if report_due {
            self.last_report = Instant::now();
        }
        r.pending = Pending {
            submitted: true,
            screenshot: last && copy_shot,
            linear: want_linear.then_some(LinearRead { frame_width: shape.width, margin: shape.margin, size: [size[0], size[1]] }),
            free: output.textures_delta.free,
            report: report_due,
        };
        self.frames_recorded += 1;
        if self.frames_recorded == 1 {
            println!("first frame presented");
        }
        let (swapchains, indices) = ([sc.handle], [index]);
        let present = vk::PresentInfoKHR::default().wait_semaphores(&signals).swapchains(&swapchains).image_indices(&indices);
        // SAFETY: the image was acquired and its rendering signals the semaphore waited on.
        match unsafe { sc.loader.queue_present(d.queue, &present) } {
            Ok(suboptimal) => r.resize |= suboptimal,
            Err(vk::Result::ERROR_OUT_OF_DATE_KHR) => r.resize = true,
            Err(e) => return Err(e).context("vkQueuePresentKHR"),
        }
        Ok(last)
    }

    /// The UI, built before the blur (it edits the lens and the method) and drawn after it.
    fn build_ui(&mut self, r: &mut Running) -> Result<egui::FullOutput> {
        let lens_now = self.lens.thin_lens(&self.camera)?;
        let raw = r.egui_state.take_egui_input(&r.window);
        let (panel, stats, error_texture) = (&mut self.panel, &self.stats, &r.error_texture);
        let output = r.egui_ctx.run(raw, |ctx| {
            panel.draw(ctx, stats, &lens_now);
            if let (true, Some(t)) = (panel.show_error && panel.visible, error_texture) {
                // Half the window wide, at its right.
                let screen = ctx.content_rect();
                let size = t.size_vec2() * (0.5 * screen.width() / t.size_vec2().x);
                egui::Window::new("error vs reference").default_pos([screen.width() / 2.0, 4.0]).show(ctx, |ui| ui.image((t.id(), size)));
            }
        });
        let mut output = output;
        r.egui_state.handle_platform_output(&r.window, std::mem::take(&mut output.platform_output));
        Ok(output)
    }

    /// The lens and method from the panel; an invalid lens is shown and not taken.
    fn take_panel_lens(&mut self) {
        self.panel.settings.aperture = self.panel.shape();
        let candidate = LensSettings { focus: Focus::Distance(self.panel.focus), aperture: self.panel.aperture, ..self.lens };
        match candidate.thin_lens(&self.camera) {
            Ok(_) => {
                self.lens = candidate;
                self.stats.problem = None;
            }
            Err(e) => self.stats.problem = Some(format!("lens not taken: {e}")),
        }
    }

    /// Click to focus: the front depth under the cursor, from the host's copy of an EXR's layers
    /// or read from the device peel's last frame.
    fn focus_on_click(&mut self, r: &mut Running, extent: vk::Extent2D, size: [u32; 2]) -> Result<()> {
        let Some((x, y)) = self.controls.focus_click.take() else { return Ok(()) };
        let backend = r.backend.as_mut().context("no backend")?;
        let (fx, fy) = ((x / extent.width as f64 * size[0] as f64) as u32, (y / extent.height as f64 * size[1] as f64) as u32);
        let depth = match (&r.peel, &r.layers) {
            (Some(peel), _) => peel.front_depth(backend, fx, fy)?,
            (None, Some((_, _, layers))) => layers.front_depth(fx, fy),
            (None, None) => None,
        };
        if let Some(depth) = depth {
            let focused = LensSettings { focus: Focus::Distance(depth), ..self.lens };
            if focused.thin_lens(&self.camera).is_ok() {
                self.lens = focused;
                self.panel.focus = depth;
                println!("focus: {depth:.4} (the depth under the cursor at {x:.0},{y:.0})");
            }
        }
        Ok(())
    }

    /// The layers: a mesh's peel context, made again when the frame size or the lens changed (it
    /// peels whenever the camera moved); an EXR's layers, uploaded again when the lens changed (its
    /// edges).
    fn prepare_layers(&mut self, r: &mut Running, lens: &ThinLens, remade: &mut bool) -> Result<Shape> {
        let backend = r.backend.as_mut().context("no backend")?;
        match self.source.mesh() {
            Some((mesh, near)) => {
                let camera_size = [self.camera.width, self.camera.height];
                if r.peel.as_ref().is_none_or(|p| p.size != camera_size || p.lens != self.lens) {
                    if let Some(old) = r.peel.take() {
                        old.ctx.destroy(backend);
                    }
                    let start = Instant::now();
                    let near = near.unwrap_or_else(|| default_near(lens.focus_distance));
                    let options = LayerOptions {
                        max_layers: LAYERS,
                        guard_band: GuardBand::Auto,
                        texture_probes: self.args.texture_probes,
                        ..Default::default()
                    };
                    let ctx = MeshPeelContext::new(backend, &mesh.raster(), &self.camera, lens, &MeshPeelDesc::new(&options, near))?;
                    self.stats.layers_ms = start.elapsed().as_secs_f64() * 1e3;
                    self.stats.device_peel = Some(ctx.margin());
                    r.peel = Some(DevicePeel { ctx, size: camera_size, lens: self.lens, peeled: None });
                    *remade = true;
                }
                let ctx = &r.peel.as_ref().context("no peel context")?.ctx;
                let [width, height] = ctx.size();
                Ok(Shape { width, height, layers: ctx.layers(), margin: ctx.margin(), lens: *lens })
            }
            None => {
                if r.layers.as_ref().is_none_or(|(c, l, _)| *c != self.camera || *l != self.lens) {
                    let layers = self.source.exr_layers(&self.camera, &self.lens)?;
                    Inputs::upload(&mut r.inputs, backend, &layers.image)?;
                    *remade = true;
                    self.stats.layers_ms = layers.ms;
                    r.layers = Some((self.camera, self.lens, layers));
                }
                let (_, _, layers) = r.layers.as_ref().context("no layers")?;
                let i = &layers.image;
                Ok(Shape { width: i.width, height: i.height, layers: i.max_layers, margin: layers.margin, lens: layers.lens })
            }
        }
    }

    /// The contexts and the output image, for frames up to the window's size plus the widest
    /// guard band (grown, never shrunk, when the window grows), and the display buffers.
    fn prepare_buffers(&mut self, r: &mut Running, shape: &Shape, size: [u32; 2], remade: &mut bool) -> Result<()> {
        let backend = r.backend.as_mut().context("no backend")?;
        let want =
            [shape.width.max(size[0] + 2 * MAX_GUARD_BAND), shape.height.max(size[1] + 2 * MAX_GUARD_BAND), shape.layers.max(LAYERS)];
        let contexts = r.contexts.get_or_insert_with(|| Contexts::new(want));
        let made_before = backend.counters().allocations;
        contexts.prepare(backend, &self.panel.settings, want)?;
        *remade |= backend.counters().allocations != made_before;
        let max = contexts.max();
        if r.target.as_ref().is_none_or(|(_, e, _)| e[0] < max[0] || e[1] < max[1]) {
            *remade = true;
            // SAFETY: the image may be in use by nothing (the frame before completed).
            unsafe { r.d.device.device_wait_idle()? };
            if let Some((old, _, _)) = r.target.take() {
                r.d.destroy_image(old);
            }
            let usage = vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST;
            r.target = Some((r.d.image(vk::Format::R32G32B32A32_SFLOAT, [max[0], max[1]], usage)?, [max[0], max[1]], true));
        }
        let pixels = max[0] as u64 * max[1] as u64;
        if r.display.as_ref().is_none_or(|b| b.pixels < pixels) {
            *remade = true;
            if let Some(old) = r.display.take() {
                old.destroy(backend);
            }
            let rgb = backend.create_buffer(3 * pixels, "view/rgb")?;
            let rgba = match backend.create_buffer(4 * pixels, "view/display") {
                Ok(b) => b,
                Err(e) => {
                    backend.destroy_buffer(rgb);
                    return Err(e.into());
                }
            };
            r.display = Some(Display { rgb, rgba, pixels });
        }
        Ok(())
    }

    /// Records the peel (where the camera moved), the depth of field through the frame API and the
    /// display pass into the frame's command buffer, through the library's guard. Returns the
    /// target image the display pass wrote.
    fn record_dof(&mut self, r: &mut Running, shape: &Shape, lens: &ThinLens) -> Result<vk::Image> {
        let (target, _, fresh) = r.target.as_mut().context("no target")?;
        let (target_image, was_fresh) = (target.handle, *fresh);
        *fresh = false;
        if was_fresh {
            r.d.image_barrier(
                target_image,
                Layout::UNDEFINED,
                Layout::TRANSFER_SRC_OPTIMAL,
                (vk::PipelineStageFlags::TOP_OF_PIPE, Access::empty()),
                (TRANSFER, Access::empty()),
            );
        }
        let (fw, fh) = (shape.width, shape.height);
        // The display pass's result goes into the target image as the library sees it: in
        // TRANSFER_SRC_OPTIMAL, last read by the blit of the frame before (a read: the library's
        // barrier only has to wait for it), left there.
        // SAFETY: our live RGBA32F image, at least the frame's size, TRANSFER_SRC|DST usage, on the
        // backend's queue family, in that layout when the copy runs; alive until the fence.
        let out = unsafe {
            ImageRef::vulkan(
                target_image,
                ImageFormat::Rgba32Float,
                [fw, fh],
                Layout::TRANSFER_SRC_OPTIMAL,
                TRANSFER,
                Access::empty(),
                Layout::TRANSFER_SRC_OPTIMAL,
            )
        };
        let display = r.display.as_ref().context("no display buffers")?;
        let method = self.panel.settings.method;
        // The peel's slots (a single-layer method reads their front slot), or the uploaded ones.
        let ((fragments, counts), slots) = match (&r.peel, &r.inputs) {
            (Some(p), _) => ((p.ctx.slots().fragments, p.ctx.slots().counts), shape.layers),
            (None, Some(inputs)) if method.front_only() => (inputs.front, 1),
            (None, Some(inputs)) => (inputs.all, shape.layers),
            (None, None) => bail!("no inputs"),
        };
        let frame = Frame {
            width: fw,
            height: fh,
            lens: shape.lens,
            input: FrameInput::Layers {
                fragments: SlotBuffer::current(fragments),
                counts: CountBuffer(counts),
                layers: slots,
                footprint_side: 0,
            },
            output: FrameOutput::Buffer(RgbBuffer(display.rgb)),
        };
        // The display pass: the documented tone map (the one PNG previews use, from the same
        // source) at the panel's exposure, or the raw linear values clamped, sRGB-encoded.
        let mode = if self.panel.raw_linear { MODE_LINEAR } else { MODE_TONEMAP };
        let params = DisplayParams { width: fw, height: fh, mode, exposure: self.panel.exposure };
        let (rgb, rgba) = (display.rgb, display.rgba);
        let backend = r.backend.as_mut().context("no backend")?;
        // SAFETY: our command buffer is recording, outside a render pass, from a pool of the
        // backend's queue family; every resource it names outlives the fence wait.
        let mut recording = unsafe { backend.record_into(r.d.cb)? };
        let peeled = match r.peel.as_mut() {
            Some(p) if p.peeled != Some(self.camera) => {
                let recorded = p.ctx.record(&mut *recording, &self.camera, lens);
                p.peeled = recorded.is_ok().then_some(self.camera);
                recorded.map_err(anyhow::Error::from)
            }
            _ => Ok(()),
        };
        let recorded = peeled.and_then(|()| contexts_record(r.contexts.as_mut(), &mut recording, method, &frame)).and_then(|()| {
            let groups = groups_for(&DISPLAY, fw as u64 * fh as u64);
            recording.run(display_tonemap::Bindings { rgb, rgba }, groups, &params, "view/display")?;
            recording.copy_buffer_to_image(rgba, 0, out, "view/display-to-image")?;
            Ok(())
        });
        recording.end()?;
        recorded?;
        Ok(target_image)
    }

    fn apply(&mut self, step: Step, el: &ActiveEventLoop) {
        println!("script: {step:?}");
        match step {
            Step::Method(m) => self.panel.settings.method = m,
            Step::Resize(w, h) => {
                if let Some(r) = self.running.as_mut() {
                    let _ = r.window.request_inner_size(PhysicalSize::new(w, h));
                    // Where the window system has applied it already, no event may come.
                    r.resize = true;
                }
            }
            Step::Focus(d) => self.panel.focus = d,
            Step::FNumber(n) => self.panel.aperture = dof::scene::Aperture::FNumber(n),
            Step::Radius(rad) => self.panel.aperture = dof::scene::Aperture::Radius(rad),
            Step::Blades(n) => self.panel.blades = n,
            Step::Merge(m) => self.panel.settings.merge = m,
            Step::Tile(t) => self.panel.settings.tile = t,
            Step::Rings(n) => self.panel.settings.rings = n,
            Step::Orbit(deg) => orbit(&mut self.camera, deg.to_radians(), 0.0),
            Step::Exposure(e) => self.panel.exposure = e,
            Step::RawLinear => self.panel.raw_linear = !self.panel.raw_linear,
            Step::Click(x, y) => self.controls.focus_click = Some((x, y)),
            Step::Error => self.panel.show_error = !self.panel.show_error,
            Step::Close => self.close(el),
        }
    }

    /// Tears everything down once the loop has ended: the frame in flight completes, the library's
    /// objects go first, then the UI renderer's, then the viewer's own; returns the validation
    /// layer's messages (a leak shows up here, at vkDestroyDevice and vkDestroyInstance).
    fn finish(&mut self) -> Vec<String> {
        let Some(mut r) = self.running.take() else { return Vec::new() };
        if let Err(e) = self.complete_running(&mut r) {
            self.error.get_or_insert(e);
        }
        // SAFETY: nothing may be in use while objects are destroyed.
        unsafe { r.d.device.device_wait_idle().ok() };
        if let Some(mut backend) = r.backend.take() {
            if let Some(c) = r.contexts.take() {
                c.destroy(&mut backend);
            }
            if let Some(i) = r.inputs.take() {
                i.destroy(&mut backend);
            }
            if let Some(p) = r.peel.take() {
                p.ctx.destroy(&mut backend);
            }
            if let Some(b) = r.display.take() {
                b.destroy(&mut backend);
            }
            drop(backend);
        }
        r.error_texture = None;
        drop(r.renderer.take());
        if let Some((t, _, _)) = r.target.take() {
            r.d.destroy_image(t);
        }
        if let Some(b) = r.readback.take() {
            r.d.destroy_buffer(b);
        }
        if let Some(sc) = r.sc.take() {
            sc.destroy(&r.d, true);
        }
        let messages = r.d.take_messages();
        let log = r.d.log.clone();
        let surface_fn = r.surface_fn.clone();
        r.d.destroy(Some((&surface_fn, r.surface)));
        drop(r.window);
        let mut all = messages;
        all.extend(std::mem::take(&mut *log.lock().unwrap_or_else(|e| e.into_inner())));
        all
    }

    /// The frame in flight, completed before teardown. A screenshot that was asked for and not yet
    /// written (the window closed before the last of --frames) is written now, from the last
    /// presented image; where no frame was presented the run fails saying so.
    fn complete_running(&mut self, r: &mut Running) -> Result<()> {
        // SAFETY: the fence is live.
        unsafe { r.d.device.wait_for_fences(&[r.d.fence], true, u64::MAX)? };
        r.pending = Pending::default();
        if let (Some(path), false, None) = (&self.args.screenshot, self.screenshot_written, &self.error) {
            if r.shot.is_none() {
                bail!("the window closed before a frame was presented: no screenshot was written to {}", path.display());
            }
            let how = format!(
                "the last presented image: the window closed after {} of {} frames",
                self.frames_recorded,
                self.args.frames.unwrap_or(0)
            );
            write_shot(self.args, &r.readback, r.shot, &how)?;
            self.screenshot_written = true;
        }
        Ok(())
    }
}

/// Makes the swapchain again where the window was resized; `false` while the window has no area
/// (the frame is skipped).
fn resize_swapchain(r: &mut Running, vsync: bool) -> Result<bool> {
    if !r.resize {
        return Ok(true);
    }
    r.resize = false;
    let size = r.window.inner_size();
    if size.width == 0 || size.height == 0 {
        return Ok(false);
    }
    // SAFETY: waiting for the device before its swapchain's objects are destroyed.
    unsafe { r.d.device.device_wait_idle()? };
    let old = r.sc.take();
    let sc = Swapchain::new(&r.d, &r.surface_fn, r.surface, [size.width, size.height], vsync, old)?;
    println!("swapchain: {}x{}", sc.extent.width, sc.extent.height);
    r.sc = Some(sc);
    Ok(true)
}

/// Records the frame, cut to the window (the guard band is beyond it), blitted from the target
/// image into the acquired swapchain image (`scaled`: an EXR scaled to the window); returns that
/// image, left in TRANSFER_DST_OPTIMAL.
fn record_blit(r: &Running, index: u32, target_image: vk::Image, shape: &Shape, size: [u32; 2], scaled: bool) -> Result<vk::Image> {
    let sc = r.sc.as_ref().context("no swapchain")?;
    let (d, cb, image) = (&r.d, r.d.cb, sc.images[index as usize]);
    let (w, h) = (sc.extent.width, sc.extent.height);
    let m = shape.margin as i32;
    let (sw, sh) = (size[0] as i32, size[1] as i32);
    d.image_barrier(
        image,
        Layout::UNDEFINED,
        Layout::TRANSFER_DST_OPTIMAL,
        (TRANSFER, Access::empty()),
        (TRANSFER, Access::TRANSFER_WRITE),
    );
    let blit = vk::ImageBlit::default()
        .src_subresource(vk::ImageSubresourceLayers::default().aspect_mask(vk::ImageAspectFlags::COLOR).layer_count(1))
        .src_offsets([vk::Offset3D { x: m, y: m, z: 0 }, vk::Offset3D { x: m + sw, y: m + sh, z: 1 }])
        .dst_subresource(vk::ImageSubresourceLayers::default().aspect_mask(vk::ImageAspectFlags::COLOR).layer_count(1))
        .dst_offsets([vk::Offset3D { x: 0, y: 0, z: 0 }, vk::Offset3D { x: w as i32, y: h as i32, z: 1 }]);
    // Same size for rendered scenes (each pixel copied; its value, sRGB-encoded by the display
    // pass, stored as it is in the UNORM swapchain image); an EXR is scaled to the window.
    let filter = if scaled { vk::Filter::LINEAR } else { vk::Filter::NEAREST };
    // SAFETY: recording; both images are in the layouts named, the regions inside them.
    unsafe {
        d.device.cmd_blit_image(cb, target_image, Layout::TRANSFER_SRC_OPTIMAL, image, Layout::TRANSFER_DST_OPTIMAL, &[blit], filter)
    };
    Ok(image)
}

/// Writes the screenshot from the read-back swapchain pixels of a completed frame (`how`: which).
fn write_shot(args: &ViewArgs, readback: &Option<Owned<vk::Buffer>>, shot: Option<([u32; 2], bool)>, how: &str) -> Result<()> {
    let (Some(path), Some(buf), Some(([w, h], bgra))) = (&args.screenshot, readback, shot) else {
        bail!("no presented image was read back for the screenshot");
    };
    // SAFETY: the mapping covers w*h*4 bytes (the buffer is made again, and `shot` cleared, when it
    // is smaller), written by the completed copy and made visible to the host by its barrier.
    let bytes = unsafe { std::slice::from_raw_parts(buf.mapped, (w * h * 4) as usize) };
    super::readback::write_screenshot(path, w, h, bytes, bgra)?;
    println!("wrote {} ({w}x{h}, {how})", path.display());
    Ok(())
}

/// The view as `dof render` flags, to render it again (or compare it) from the command line.
fn view_flags(camera: &Camera, lens: &LensSettings) -> String {
    let v = |p: dof::scene::Vec3| format!("{},{},{}", p.x, p.y, p.z);
    let focus = match lens.focus {
        Focus::Distance(d) => d,
        Focus::Point(_) => lens.thin_lens(camera).map_or(f32::NAN, |l| l.focus_distance),
    };
    let aperture = match lens.aperture {
        dof::scene::Aperture::FNumber(n) => format!("--f-number {n}"),
        dof::scene::Aperture::Radius(r) => format!("--aperture-radius {r}"),
    };
    format!("--eye {} --target {} --yfov {} --focus {focus} {aperture}", v(camera.eye), v(camera.target), camera.yfov_radians.to_degrees())
}

fn contexts_record(
    contexts: Option<&mut Contexts>,
    backend: &mut VulkanBackend,
    method: super::methods::ViewMethod,
    frame: &Frame,
) -> Result<()> {
    contexts.context("no contexts")?.record(backend, method, frame)
}
