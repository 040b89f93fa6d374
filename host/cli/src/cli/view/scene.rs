//! What the viewer shows: a built-in analytic scene or a glTF file, rasterised into a multi-layer
//! image by depth peeling on the viewer's device (`raster::MeshPeelContext`, recorded into the
//! frame's command buffer whenever the camera moved; see `frame.rs`), or an EXR, a still multi-layer image whose
//! edges are extended as `dof render` extends them.

use anyhow::{Context, Result, bail};
use dof::backend::Backend;
use dof::layers::{LayeredImage, RgbImage};
use dof::raster::{AccumulateOptions, accumulate, default_near};
use dof::scene::ExrInput;
use dof::scene::{
    self, Camera, LensSettings, MeshScene, ReferenceOptions, Scene, ThinLens, builtin, export_builtin_glb, load_gltf, load_gltf_slice,
};
use std::path::Path;
use std::time::Instant;

/// Fragments per pixel of the multi-layer image (as `dof render --layers`' default).
pub const LAYERS: u32 = 4;

enum Content {
    /// Triangles to peel; with the analytic scene they came from (its exact reference) for a
    /// built-in scene.
    Mesh { mesh: Box<MeshScene>, analytic: Option<Box<Scene>>, near: Option<f32> },
    /// A still image: flat layers, or a deep image whose layers follow the lens.
    Exr(Box<ExrInput>),
}

pub struct SceneSource {
    pub name: String,
    content: Content,
    /// The starting view and lens.
    pub camera: Camera,
    pub lens: LensSettings,
}

/// The multi-layer image of one view, on the host, `margin` pixels larger than the frame on every
/// side; the lens it was made for; how long making it took.
pub struct Layers {
    pub image: LayeredImage,
    pub margin: u32,
    pub lens: ThinLens,
    pub ms: f64,
}

impl SceneSource {
    /// `spec`: a built-in name, a `.gltf`/`.glb` or an `.exr`. Built-in and glTF scenes start at
    /// `size`; an EXR has its own size and needs `focus` and `aperture` (it carries no lens).
    pub fn load(spec: &str, size: [u32; 2], focus: Option<f32>, aperture: Option<scene::Aperture>) -> Result<SceneSource> {
        let lower = spec.to_ascii_lowercase();
        let name = Path::new(spec).file_stem().and_then(|s| s.to_str()).unwrap_or("scene").to_string();
        if lower.ends_with(".exr") {
            if dof::io::exr_pattern::is_pattern(spec) {
                bail!(
                    "--scene {spec}: the viewer shows one EXR image, not a sequence: give one frame's file (`dof render` renders a sequence)"
                );
            }
            if let Some(hashes) = dof::io::exr_pattern::from_printf(spec).filter(|_| !Path::new(spec).exists()) {
                bail!("--scene {spec}: no such file; the viewer shows one EXR image (a sequence, {hashes}, is for `dof render`)");
            }
            let input = ExrInput::read(&[spec])?;
            if let Some(note) = input.note() {
                eprintln!("note: {spec}: {note}");
            }
            let (camera, lens) = crate::cli::render::exr_view(input.size(), focus, aperture, None)?;
            lens.thin_lens(&camera)?;
            return Ok(SceneSource { name, content: Content::Exr(Box::new(input)), camera, lens });
        }
        let (mesh, analytic, camera, mut lens, near) = if lower.ends_with(".gltf") || lower.ends_with(".glb") {
            let mut mesh = load_gltf(Path::new(spec))?;
            let report = mesh.report.to_string();
            if !report.is_empty() {
                eprintln!("note: {spec}: {report}");
            }
            // The file's camera and the lens `dof render` gives it (`MeshScene::default_view`).
            let (camera, near) =
                mesh.default_camera(size[0], Some(size[1])).with_context(|| format!("{spec}: the viewer starts from the file's camera"))?;
            // From the start's eye: orbiting keeps to the outside of objects.
            let solids = mesh.single_sided_solids(camera.eye);
            if solids != Default::default() {
                eprintln!("note: {spec}: {solids}");
            }
            let lens = mesh.lens_focused_at(&camera, focus)?;
            (mesh, None, camera, lens, Some(near))
        } else {
            let b = builtin(spec)?.with_size(size[0], size[1]);
            // The analytic scene as triangles (what `dof scenes --raster` peels), so that every
            // scene goes through the same rasteriser; the analytic scene stays for its reference.
            let mesh = load_gltf_slice(&export_builtin_glb(spec, size[0], size[1])?)?;
            let mut lens = b.lens;
            if let Some(d) = focus {
                lens.focus = scene::Focus::Distance(d);
            }
            (mesh, Some(Box::new(b.scene)), b.camera, lens, None)
        };
        if let Some(a) = aperture {
            lens.aperture = a;
        }
        lens.thin_lens(&camera)?;
        Ok(SceneSource { name, content: Content::Mesh { mesh: Box::new(mesh), analytic, near }, camera, lens })
    }

    /// The mesh of a built-in or glTF scene and its near plane (`None`: from the focus distance);
    /// `None` for an EXR.
    pub fn mesh(&self) -> Option<(&MeshScene, Option<f32>)> {
        match &self.content {
            Content::Mesh { mesh, near, .. } => Some((mesh, *near)),
            Content::Exr(_) => None,
        }
    }

    /// Whether the camera can move (not for an EXR).
    pub fn movable(&self) -> bool {
        matches!(self.content, Content::Mesh { .. })
    }

    /// The frame size of an EXR (the window shows it scaled); `None` for scenes rendered at the
    /// window's size.
    pub fn fixed_size(&self) -> Option<[u32; 2]> {
        match &self.content {
            Content::Exr(input) => Some(input.size().into()),
            Content::Mesh { .. } => None,
        }
    }

    /// Fragment slots a pixel the contexts are made for (the peeled layers, or the EXR's).
    pub fn max_layers(&self) -> u32 {
        match &self.content {
            Content::Exr(input) => match input.as_ref() {
                ExrInput::Flat { layers, .. } => layers.max_layers.max(LAYERS),
                ExrInput::Deep { .. } => LAYERS,
            },
            Content::Mesh { .. } => LAYERS,
        }
    }

    /// Whether the scene has a reference for the "error vs reference" view.
    pub fn has_reference(&self) -> bool {
        matches!(self.content, Content::Mesh { .. })
    }

    /// An EXR's multi-layer image for the lens of `settings` (a deep image's made for it, with
    /// [`LAYERS`] fragments a pixel), its edges extended by its largest CoC
    /// (a mesh scene's layers are peeled on the device instead: see `frame.rs`).
    pub fn exr_layers(&self, camera: &Camera, settings: &LensSettings) -> Result<Layers> {
        let lens = settings.thin_lens(camera)?;
        let start = Instant::now();
        let (image, margin) = match &self.content {
            Content::Mesh { .. } => bail!("a mesh scene's layers are peeled on the device, not made on the host"),
            Content::Exr(input) => {
                let options = dof::frame::LayerOptions { max_layers: LAYERS, ..Default::default() };
                let (layers, _) = input.layers(camera, &lens, &options)?;
                let margin = crate::cli::render::edge_margin(&layers, &lens);
                (layers.extend_edges(margin)?, margin)
            }
        };
        Ok(Layers { image, margin, lens, ms: start.elapsed().as_secs_f64() * 1e3 })
    }

    /// The reference for this view: the exact thin-lens reference of a built-in scene (distributed
    /// ray tracing on the CPU), the accumulation buffer (Haeberli and Akeley 1990) of a glTF scene
    /// on `backend`. `samples` per pixel. Slow: on demand only.
    pub fn reference(&self, backend: &mut dyn Backend, camera: &Camera, settings: &LensSettings, samples: u32) -> Result<RgbImage> {
        let lens = settings.thin_lens(camera)?;
        match &self.content {
            Content::Mesh { analytic: Some(scene), .. } => {
                Ok(scene::reference(scene, camera, &lens, &ReferenceOptions { spp: samples, ..Default::default() })?.image)
            }
            Content::Mesh { mesh, near, .. } => {
                let near = near.unwrap_or_else(|| default_near(lens.focus_distance));
                let options = AccumulateOptions { samples, ..Default::default() };
                Ok(accumulate(backend, &mesh.raster(), camera, &lens, near, &options)?.image)
            }
            Content::Exr(_) => bail!("an EXR has no geometry, so no reference"),
        }
    }
}

impl Layers {
    /// Planar depth of the front fragment at frame pixel `(x, y)` (inside the guard band's
    /// margin), `None` where there is nothing or outside.
    pub fn front_depth(&self, x: u32, y: u32) -> Option<f32> {
        let (x, y) = (x + self.margin, y + self.margin);
        if x >= self.image.width || y >= self.image.height {
            return None;
        }
        let p = (y * self.image.width + x) as usize;
        (self.image.counts[p] > 0)
            .then(|| self.image.fragments[p * self.image.max_layers as usize].depth)
            .filter(|d| d.is_finite() && *d > 0.0)
    }
}
