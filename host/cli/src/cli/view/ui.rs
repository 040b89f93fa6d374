//! The on-screen panel (egui, immediate mode): the lens, the method and its settings, and what the
//! frame cost and left out.

use super::methods::{MethodSettings, ViewMethod};
use dof::methods::splat::Merge;
use dof::scene::{Aperture, ThinLens};

/// What the panel edits.
pub struct Panel {
    pub visible: bool,
    pub settings: MethodSettings,
    pub focus: f32,
    pub aperture: Aperture,
    /// Aperture shape: 0 circle, else this many blades.
    pub blades: u32,
    /// Show the error against the reference (computed on demand for the current view).
    pub show_error: bool,
    /// Exposure multiplier before the tone map (`--exposure`; as `dof render`'s PNG preview).
    pub exposure: f32,
    /// Show the raw linear values clamped to [0, 1] instead of the tone map.
    pub raw_linear: bool,
}

/// What the panel shows.
#[derive(Default)]
pub struct Stats {
    pub device: String,
    pub present_mode: String,
    pub frame: [u32; 2],
    pub fps: f64,
    pub frame_ms: f64,
    /// GPU time per stage of the last timed frame, and their sum.
    pub stages: Vec<(String, f64)>,
    pub gpu_ms: f64,
    /// What the last reported frame left out (from the context's report, read a frame or more late).
    pub report: Vec<String>,
    /// How long making the layers took: the EXR's edges extended, or for a mesh the device peel's
    /// context made (again when the frame size or the lens changes; it peels whenever the camera moves).
    pub layers_ms: f64,
    /// The layers are peeled on the device in the frame whenever the camera moves, with this guard
    /// band (pixels).
    pub device_peel: Option<u32>,
    pub has_reference: bool,
    /// PSNR of the shown frame against the reference, when computed.
    pub error: Option<String>,
    pub problem: Option<String>,
}

impl Panel {
    /// The aperture shape text `dof::aperture::parse_aperture` takes.
    pub fn shape(&self) -> String {
        if self.blades == 0 { "circle".to_string() } else { format!("blades:{}", self.blades) }
    }

    /// Switches the aperture between an f-number and a radius, keeping the same opening.
    fn convert_aperture(&mut self, lens: &ThinLens, to_f_number: bool) {
        let (f, r) = (lens.focal_length, lens.aperture_radius);
        self.aperture = match (to_f_number, self.aperture) {
            (true, Aperture::Radius(_)) if r > 0.0 => Aperture::FNumber(f / (2.0 * r)),
            (true, Aperture::Radius(_)) => Aperture::FNumber(f32::INFINITY),
            (false, Aperture::FNumber(_)) => Aperture::Radius(r),
            (_, a) => a,
        };
    }

    pub fn draw(&mut self, ctx: &egui::Context, stats: &Stats, lens: &ThinLens) {
        if !self.visible {
            return;
        }
        egui::Window::new("dof view").default_pos([4.0, 4.0]).default_width(300.0).default_open(true).resizable(false).show(ctx, |ui| {
            ui.style_mut().spacing.slider_width = 110.0;
            ui.label(format!("{} | {}x{} | {}", stats.device, stats.frame[0], stats.frame[1], stats.present_mode));
            ui.label(format!("{:.1} FPS ({:.1} ms a frame), GPU {:.2} ms", stats.fps, stats.frame_ms, stats.gpu_ms));
            egui::ComboBox::from_label("method").selected_text(self.settings.method.name()).show_ui(ui, |ui| {
                for m in ViewMethod::all() {
                    ui.selectable_value(&mut self.settings.method, m, m.label());
                }
            });
            ui.add(egui::Slider::new(&mut self.focus, 0.05..=1000.0).logarithmic(true).text("focus distance"));
            let mut f_number = matches!(self.aperture, Aperture::FNumber(_));
            if ui.checkbox(&mut f_number, "as f-number").changed() {
                self.convert_aperture(lens, f_number);
            }
            match &mut self.aperture {
                Aperture::FNumber(n) => ui.add(egui::Slider::new(n, 0.5..=64.0).logarithmic(true).text("f-number")),
                Aperture::Radius(r) => ui.add(egui::Slider::new(r, 0.0..=10.0).logarithmic(true).text("aperture radius")),
            };
            ui.add_enabled_ui(!self.raw_linear, |ui| {
                ui.add(egui::Slider::new(&mut self.exposure, 0.01..=100.0).logarithmic(true).text("exposure (tone map)"));
            });
            ui.checkbox(&mut self.raw_linear, "raw linear, clamped to [0, 1] (no tone map)");
            if !(self.exposure > 0.0 && self.exposure.is_finite()) {
                self.exposure = 1.0;
            }
            ui.add_enabled_ui(self.settings.method.0.shaped_aperture(), |ui| {
                ui.add(egui::Slider::new(&mut self.blades, 0..=12).text("blades (0: circle)"));
            });
            if self.blades > 0 && self.blades < 3 {
                self.blades = 3;
            }
            ui.add_enabled_ui(self.settings.method.0.tiles(), |ui| {
                ui.horizontal(|ui| {
                    ui.label("merge");
                    ui.selectable_value(&mut self.settings.merge, Merge::None, "none");
                    ui.selectable_value(&mut self.settings.merge, Merge::X2, "2x2");
                    ui.selectable_value(&mut self.settings.merge, Merge::X4, "4x4");
                });
                ui.horizontal(|ui| {
                    ui.label("tile");
                    for t in [16, 24, 32] {
                        ui.selectable_value(&mut self.settings.tile, t, t.to_string());
                    }
                });
            });
            ui.add_enabled_ui(self.settings.method.0.knob.is_some_and(|k| k.name == "rings"), |ui| {
                ui.add(
                    egui::Slider::new(&mut self.settings.rings, 1..=dof::methods::ring_gather::MAX_SAMPLE_RINGS)
                        .text("rings (ring gather)"),
                );
            });
            ui.label(format!(
                "lens: f = {:.3}, aperture radius {:.4}, focus {:.3}",
                lens.focal_length, lens.aperture_radius, lens.focus_distance
            ));
            egui::CollapsingHeader::new("GPU time per stage (ms)").default_open(true).show(ui, |ui| {
                let stages: Vec<String> = stats.stages.iter().map(|(stage, ms)| format!("{stage} {ms:.1}")).collect();
                ui.label(stages.join(", "));
                match stats.device_peel {
                    Some(margin) => ui.label(format!(
                        "layers: peeled on the device in the frame when the camera moves, guard band {margin} px (context made in {:.0} ms when the size or lens changed)",
                        stats.layers_ms
                    )),
                    None => ui.label(format!("layers: made in {:.0} ms", stats.layers_ms)),
                };
            });
            egui::CollapsingHeader::new("what the frame left out").default_open(true).show(ui, |ui| {
                for line in &stats.report {
                    ui.label(line);
                }
            });
            if stats.has_reference {
                ui.checkbox(&mut self.show_error, "error vs reference (slow: computed on demand)");
                if let Some(e) = &stats.error {
                    ui.label(e);
                }
            }
            if let Some(p) = &stats.problem {
                ui.colored_label(egui::Color32::LIGHT_RED, p);
            }
            ui.label("drag: orbit, wheel: zoom, WASD/QE: fly, click: focus, H: hide panel");
        });
    }
}
