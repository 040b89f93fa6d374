//! Depth peeling a mesh on the device, frame after frame: the rasteriser's passes recorded around
//! the device half of the peel ([`crate::frame::peel::PeelSlots`]), with the same rules as the host
//! oracle [`super::peel_layers`] and the same result, slot for slot.
//!
//! Made once: the mesh uploaded, every buffer (slots, reach, visibility target, layer, mask) and the
//! draw target sized for the frame and its guard band, the pipelines built. The guard band is fixed
//! at creation (a margin in pixels, or [`GuardBand::Auto`] resolved once from the creation view),
//! so the draw keeps one size whatever the camera does later; a view that would need a wider band
//! gets this one, and the band each frame's view needs is computed on the device and reported
//! (`PeelReport::band_needed`, `band_exceeded_frames`). Per frame: the camera and lens through push constants only,
//! `max_layers + translucent_passes` passes always recorded (the ones past the last useful pass draw nothing, decided on the device), the
//! disocclusion buffer applied on the device. No allocation, upload, readback or submission.

use super::mesh::{DeviceMesh, RasterScene};
use super::peel::{Pass, check_view, peel_passes, sub_sample_camera};
use super::view::View;
use crate::backend::{Backend, BackendKind, push_words};
use crate::error::{Error, Result};
use crate::frame::context::ContextReport;
use crate::frame::io::{Owned, ready};
use crate::frame::peel::{KERNELS, PeelReport, PeelSlots};
use crate::frame::{CountBuffer, Frame, FrameInput, FrameOutput, SlotBuffer};
use crate::scene::guard_band::{auto_margin_mesh, reach_planes};
use crate::scene::{Camera, GuardBand, LayerOptions, check_subsamples};
use dof_shaders::lens::ThinLens;
use dof_shaders::peel::BandParams;
use dof_shaders::raster::draw::{RASTER_DRAW, RASTER_FALLBACK, RASTER_SETUP, VIS_WORDS};
use dof_shaders::raster::mesh::Light;
use dof_shaders::raster::shade::{LAYER, RASTER_SHADE, ShadeParams, mode_word};
use dof_shaders::resolve::grid_side;

/// What a mesh peel context is made for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshPeelDesc {
    /// Slots a pixel (>= 1).
    pub max_layers: u32,
    /// Passes past `max_layers` for translucent stacks deeper than the slots
    /// (`LayerOptions::translucent_passes`): `max_layers + translucent_passes` passes are recorded
    /// every frame.
    pub translucent_passes: u32,
    /// The near plane (scene units, `0 < near < focus distance`).
    pub near: f32,
    /// The margin beyond the frame, fixed at creation (`Auto`: from the creation view).
    pub guard_band: GuardBand,
    /// Relative depth difference between 4-neighbours that counts as a discontinuity.
    pub edge_depth_ratio: f32,
    /// Keep more than the front slot only inside the disocclusion buffer.
    pub disocclusion: bool,
    /// Sub-samples a pixel (1, 4, 9 or 16): above 1 the passes peel a `side`-times finer grid
    /// (its pixel centres the stratified sub-samples) into slots of their own, which the
    /// `resolve` kernel turns into the frame's area-integrated slots before the disocclusion
    /// buffer (`LayerOptions::subsamples`).
    pub subsamples: u32,
    /// With sub-samples, the resolved slots carry each fragment's footprint
    /// (`LayerOptions::footprints`; [`MeshPeelContext::footprint_side`]).
    pub footprints: bool,
    /// The most probes a minified texture lookup takes (`LayerOptions::texture_probes`).
    pub texture_probes: u32,
}

impl MeshPeelDesc {
    /// Passes a frame: the slots, then those for translucent stacks deeper than them.
    pub fn passes(&self) -> Result<u32> {
        peel_passes(self.max_layers, self.translucent_passes)
    }

    /// The description matching the host path's options (the umbra threshold is always on for
    /// meshes, as in [`super::peel_layers`]).
    pub fn new(options: &LayerOptions, near: f32) -> Self {
        MeshPeelDesc {
            max_layers: options.max_layers,
            translucent_passes: options.translucent_passes,
            near,
            guard_band: options.guard_band,
            edge_depth_ratio: options.edge_depth_ratio,
            disocclusion: options.disocclusion,
            subsamples: options.subsamples,
            texture_probes: options.texture_probes,
            footprints: options.footprints,
        }
    }
}

/// A mesh's depth peel on the device (module docs).
pub struct MeshPeelContext {
    desc: MeshPeelDesc,
    mesh: DeviceMesh,
    /// The frame's slots (what the methods read).
    slots: PeelSlots,
    /// The slots the passes peel into: `slots` itself, or those of the sub-sample grid.
    fine: PeelSlots,
    /// Side of the sub-sample grid (1: point-sampled).
    side: u32,
    pass: Pass,
    light: Light,
    margin: u32,
    /// The frame's size (without the guard band).
    frame_size: [u32; 2],
    /// Bytes of the backend's draw target reserved for this context's draws.
    target_bytes: u64,
    owned: Owned,
}

impl MeshPeelContext {
    /// Uploads `scene` and sizes everything for frames of `camera`'s size; `camera` and `lens` also
    /// resolve an automatic guard band.
    pub fn new(backend: &mut dyn Backend, scene: &RasterScene, camera: &Camera, lens: &ThinLens, desc: &MeshPeelDesc) -> Result<Self> {
        check_view(camera, lens, desc.near)?;
        if desc.max_layers == 0 || !(desc.edge_depth_ratio >= 0.0) {
            return Err(Error::invalid(format!(
                "need at least one layer and a non-negative edge ratio, got {} and {}",
                desc.max_layers, desc.edge_depth_ratio
            )));
        }
        let passes = desc.passes()?;
        scene.validate()?;
        check_subsamples(desc.subsamples)?;
        super::peel::check_texture_probes(desc.texture_probes)?;
        let side = grid_side(desc.subsamples);
        let margin = desc.guard_band.resolve(|| Ok(auto_margin_mesh(scene.triangle_positions(), camera, lens, desc.near)?))?;
        let frame = camera.overscan(margin).frame()?;
        frame.check_size("multi-layer image", desc.max_layers as u64)?;
        let (w, h) = (frame.width, frame.height);
        let fine_frame = sub_sample_camera(camera, side).overscan(margin * side).frame()?;
        fine_frame.check_size("sub-sample multi-layer image", desc.max_layers as u64)?;
        let (fw, fh) = (fine_frame.width, fine_frame.height);
        let pixels = fw as u64 * fh as u64;
        let mut owned = Owned::default();
        let made = (|| {
            // Resolved slots carry each fragment's footprint in its pixel's sub-sample grid.
            let footprint_side = if side > 1 && desc.footprints { side } else { 0 };
            let fine = PeelSlots::new(backend, &mut owned, fw, fh, desc.max_layers, passes, 0)?;
            // Without sub-samples the slots are the fine peel's own (the same buffers).
            let slots = if side > 1 {
                PeelSlots::new(backend, &mut owned, w, h, desc.max_layers, desc.max_layers, footprint_side)?
            } else {
                fine.clone()
            };
            let bounds = owned.make(backend, 4 * scene.triangles.len() as u64, "peel/bounds")?;
            let vis = owned.make(backend, VIS_WORDS as u64 * pixels, "peel/vis")?;
            let pass = Pass { args: fine.args, reach: fine.reach, bounds, vis };
            Ok((slots, fine, pass))
        })();
        let ((slots, fine, pass), owned) = owned.or_free(backend, made)?;
        let mesh = match DeviceMesh::upload(backend, scene) {
            Ok(mesh) => mesh,
            Err(e) => {
                owned.free(backend);
                return Err(e);
            }
        };
        // The backend's draw target (Vulkan) holds a colour and a depth attachment: 16 + 4 bytes a
        // pixel. Reserved now, so that no frame grows it.
        let target_bytes = if backend.kind() == BackendKind::Vulkan { 20 * pixels } else { 0 };
        let ctx = MeshPeelContext {
            desc: *desc,
            mesh,
            slots,
            fine,
            side,
            pass,
            light: scene.light(),
            margin,
            frame_size: [camera.width, camera.height],
            target_bytes,
            owned,
        };
        if let Err(e) = backend.reserve_draw_target(&RASTER_DRAW, [fw, fh]) {
            ctx.destroy(backend);
            return Err(e.into());
        }
        let mut kernels = vec![&RASTER_SHADE, &RASTER_SETUP, &RASTER_FALLBACK];
        kernels.extend(KERNELS);
        Ok(ready(backend, ctx, &kernels, &[&RASTER_DRAW], Self::destroy)?)
    }

    pub fn destroy(self, backend: &mut dyn Backend) {
        if self.owned.check(backend).is_ok() {
            self.mesh.destroy(backend);
        }
        self.owned.free(backend);
    }

    /// Device bytes: the mesh, the peel's buffers and the draw target reserved for it.
    pub fn device_bytes(&self) -> u64 {
        self.mesh.bytes + self.owned.bytes() + self.target_bytes
    }

    /// The guard band's width (pixels), fixed at creation.
    pub fn margin(&self) -> u32 {
        self.margin
    }

    /// The peeled image's size: the frame and its guard band.
    pub fn size(&self) -> [u32; 2] {
        [self.slots.width, self.slots.height]
    }

    /// Slots a pixel.
    pub fn layers(&self) -> u32 {
        self.desc.max_layers
    }

    /// The slots the last recorded frame wrote, as a frame of the frame API over the whole peeled
    /// image (crop its result by [`Self::margin`]).
    pub fn frame(&self, lens: ThinLens, output: FrameOutput) -> Frame {
        let s = &self.slots;
        let input = FrameInput::Layers {
            fragments: SlotBuffer::current(s.fragments),
            counts: CountBuffer(s.counts),
            layers: s.layers,
            footprint_side: s.footprint_side,
        };
        Frame { width: s.width, height: s.height, lens, input, output }
    }

    /// The side of the sub-sample grid of the slots' footprints (0: none; a splatting context for
    /// [`Self::frame`] needs `SplatOptions::footprint_side` at least this).
    pub fn footprint_side(&self) -> u32 {
        self.slots.footprint_side
    }

    /// The device buffers (slots, counts, mask, ...), for tests and callers that read them.
    pub fn slots(&self) -> &PeelSlots {
        &self.slots
    }

    /// Records one frame's peel of the mesh seen by `camera` (of the creation size) through `lens`
    /// into the backend's current command buffer: no allocation, upload, readback or submission.
    pub fn record(&mut self, backend: &mut dyn Backend, camera: &Camera, lens: &ThinLens) -> Result<()> {
        self.owned.check(backend)?;
        backend.check_frame_recording()?;
        if [camera.width, camera.height] != self.frame_size {
            return Err(Error::invalid(format!(
                "a {}x{} camera on a peel context made for {}x{} frames (make another context)",
                camera.width, camera.height, self.frame_size[0], self.frame_size[1]
            )));
        }
        check_view(camera, lens, self.desc.near)?;
        let frame = camera.overscan(self.margin).frame()?;
        if [frame.width, frame.height] != self.size() {
            return Err(Error::invalid("the camera's guard band does not match the context's".into()));
        }
        // The passes draw the sub-sample grid (the frame itself when point-sampled).
        let coarse = frame;
        let frame = sub_sample_camera(camera, self.side).overscan(self.margin * self.side).frame()?;
        let (mesh, slots, pass) = (&self.mesh, &self.fine, &self.pass);
        // The band this view needs (the image keeps the one it was made with), checked before
        // anything is recorded.
        let band = BandParams {
            planes: reach_planes(camera, self.desc.near)?,
            eye: coarse.eye.to_array(),
            triangles: mesh.triangles,
            forward: coarse.forward.to_array(),
            margin: self.margin,
            lens: *lens,
        };
        let view = View::default();
        let shade = push_words(&ShadeParams {
            light: self.light,
            eye: view.eye(&frame).to_array(),
            mode: mode_word(LAYER, self.desc.texture_probes),
            lens: *lens,
            footprint_per_depth: frame.tan_half_fov / frame.height as f32,
            width: frame.width,
            height: frame.height,
            textures: mesh.textures,
            camera: frame.orientation(),
        });
        let vertices = 3 * mesh.triangles;
        slots.begin(backend)?;
        for k in 0..slots.passes {
            slots.plan(backend, k, vertices)?;
            pass.draw(backend, mesh, &view, &frame, lens, self.desc.near, k > 0, "peel/draw")?;
            pass.shade_words(backend, mesh, &shade, slots.layer, Some(slots.shade_args()), "peel/shade")?;
            slots.append(backend, k)?;
        }
        slots.plan(backend, slots.passes, vertices)?;
        if self.side > 1 {
            self.slots.resolve_from(backend, slots, self.side, self.desc.edge_depth_ratio)?;
        }
        self.slots.finish(backend, *lens, self.desc.edge_depth_ratio, self.desc.disocclusion)?;
        Ok(slots.band(backend, mesh.buffers[0], mesh.buffers[1], &band)?)
    }

    /// What the last frame's passes did (reads the device: once the frame completed).
    pub fn peel_report(&self, backend: &mut dyn Backend) -> Result<PeelReport> {
        self.owned.check(backend)?;
        Ok(self.fine.report(backend)?)
    }

    /// [`Self::peel_report`] in the frame API's report shape.
    pub fn report(&self, backend: &mut dyn Backend) -> Result<ContextReport> {
        Ok(self.peel_report(backend)?.context_report(self.margin))
    }
}
