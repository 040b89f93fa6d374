//! The partial multi-layer image of a mesh by depth peeling (Franke et al. 2018, §4.1-4.3), the rasterised
//! counterpart of [`crate::scene::raycast_layers`] with the same rules:
//!
//! 1. Pass `k` draws every triangle and keeps, per pixel, the nearest fragment beyond `reach`
//!    (nothing for `k = 0`); shading it writes layer `k` and the next `reach` — the umbra behind an
//!    opaque fragment, so everything within it is skipped (the umbra threshold as the minimum
//!    separation of layers), and infinity where the pass found nothing. Where a pass first finds
//!    nothing the pixel's ray escapes: its next layer is the background, at infinite depth.
//! 2. Once a pixel's `max_layers` slots are full, and as long as its last slot lets light through,
//!    later passes composite what they find behind it into that slot (a translucent stack deeper
//!    than the slots keeps its light, as the ray caster keeps it). Passes stop after `max_layers +
//!    translucent_passes`, or as soon as no pixel can take what a next pass would find (every slot
//!    full and the last opaque, or no surface found).
//! 3. The image covers the frame and its guard band ([`crate::scene::guard_band`]), drawn through
//!    the overscanned camera.
//! 4. The disocclusion buffer from the front layer ([`apply_disocclusion`]): pixels outside it keep
//!    their fragments up to the first opaque one (the front one where it is opaque). This is the two-pass variant of §4.3 (the mask is built from the
//!    finished front layer rather than during the peel).
//!
//! This is the oracle of the device path [`super::MeshPeelContext`], which records the same passes
//! with no readback and is tested equal to it slot for slot; the per-pixel rules both apply live in
//! `dof_shaders::peel`.

use super::mesh::{DeviceMesh, RasterScene};
use super::view::View;
use crate::backend::{Backend, BufferId, CommandTime, RunKernel, groups_for, push_words, with_buffers};
use crate::error::{Error, Result};
use crate::layers::{Fragment, LayeredImage};
use crate::scene::guard_band::auto_margin_mesh;
use crate::scene::{Camera, CameraFrame, LayerOptions, SceneLayers, apply_disocclusion, check_subsamples, resolve_subsamples};
use dof_shaders::lens::ThinLens;
use dof_shaders::peel::{behind, is_surface, slot_kept, takes_more, target_slot};
use dof_shaders::raster::draw::{RASTER_DRAW, VIS_WORDS};
use dof_shaders::raster::project::RasterParams;
use dof_shaders::raster::shade::{LAYER, LAYER_WORDS, RASTER_SHADE, ShadeParams, mode_word, raster_shade};
use dof_shaders::raster::texture::MAX_PROBES;
use dof_shaders::resolve::grid_side;

/// The peeled image and what it cost.
pub struct Peeled {
    pub image: SceneLayers,
    /// Peeling passes run (each a draw and a shading dispatch).
    pub passes: u32,
    pub times: Vec<CommandTime>,
}

/// Checks what every raster pass needs: a valid camera, lens and near plane.
pub(crate) fn check_view(camera: &Camera, lens: &ThinLens, near: f32) -> Result<crate::scene::CameraFrame> {
    let frame = camera.frame()?;
    crate::lens::check(lens)?;
    if !(near > 0.0 && near.is_finite() && near < lens.focus_distance) {
        return Err(Error::invalid(format!(
            "the near plane must lie between 0 and the focus distance {}, got {near}",
            lens.focus_distance
        )));
    }
    Ok(frame)
}

/// Most peeling passes a frame (slots and translucent passes together): each is a draw of the
/// whole mesh where a pixel still needs it.
pub const MAX_PASSES: u32 = 1024;

/// Passes a frame for `max_layers` slots and `translucent_passes` more
/// (`LayerOptions::translucent_passes`), refused beyond [`MAX_PASSES`].
pub fn peel_passes(max_layers: u32, translucent_passes: u32) -> Result<u32> {
    max_layers.checked_add(translucent_passes).filter(|&p| p <= MAX_PASSES).ok_or_else(|| {
        Error::invalid(format!(
            "{max_layers} layers and {translucent_passes} translucent passes make more than {MAX_PASSES} peeling passes a frame"
        ))
    })
}

/// Refuses a texture probe budget outside 1 ..= [`MAX_PROBES`] (`LayerOptions::texture_probes`).
pub fn check_texture_probes(probes: u32) -> Result<()> {
    if (1..=MAX_PROBES).contains(&probes) {
        Ok(())
    } else {
        Err(Error::invalid(format!("a texture lookup takes 1 to {MAX_PROBES} probes, got {probes}")))
    }
}

/// The shading pass's constants for a view.
pub(crate) fn shade_params(
    scene: &RasterScene,
    mesh: &DeviceMesh,
    frame: &crate::scene::CameraFrame,
    lens: &ThinLens,
    view: &View,
    mode: u32,
) -> ShadeParams {
    ShadeParams {
        light: scene.light(),
        eye: view.eye(frame).to_array(),
        mode,
        lens: *lens,
        footprint_per_depth: frame.tan_half_fov / frame.height as f32,
        width: frame.width,
        height: frame.height,
        textures: mesh.textures,
        camera: frame.orientation(),
    }
}

/// The buffers every raster pass draws with besides the mesh: the draw command, the reach, the
/// triangles' tile ranges and the visibility target.
pub(crate) struct Pass {
    pub args: BufferId,
    pub reach: BufferId,
    pub bounds: BufferId,
    pub vis: BufferId,
}

impl Pass {
    /// Sizes for [`with_buffers`]; the reach holds `reach_words` (1 when not peeling).
    pub fn sizes(mesh: &DeviceMesh, pixels: u64, reach_words: u64) -> [(u64, &'static str); 4] {
        [
            (4, "raster/args"),
            (reach_words, "raster/reach"),
            (4 * mesh.triangles as u64, "raster/bounds"),
            (VIS_WORDS as u64 * pixels, "raster/vis"),
        ]
    }

    pub fn new(backend: &mut dyn Backend, mesh: &DeviceMesh, b: &[BufferId], reach_words: u64) -> Result<Self> {
        let pass = Pass { args: b[0], reach: b[1], bounds: b[2], vis: b[3] };
        backend.write_buffer(pass.args, 0, &[3 * mesh.triangles, 1, 0, 0])?;
        backend.fill(pass.reach, 0, reach_words, 0, "raster/reach")?;
        Ok(pass)
    }

    /// Draws the mesh once into `vis` as `view` sees it; `peel` keeps only fragments beyond the
    /// reach.
    #[allow(clippy::too_many_arguments)]
    pub fn draw(
        &self,
        backend: &mut dyn Backend,
        mesh: &DeviceMesh,
        view: &View,
        frame: &CameraFrame,
        lens: &ThinLens,
        near: f32,
        peel: bool,
        label: &str,
    ) -> Result<()> {
        let params = RasterParams {
            triangles: mesh.triangles,
            textures: mesh.textures,
            peel: peel as u32,
            ..view.params(frame, lens.focus_distance, near)
        };
        let [v, t, m, tx, tl] = mesh.buffers;
        let size = [frame.width, frame.height];
        Ok(backend.draw_indirect(
            &RASTER_DRAW,
            self.args,
            &[v, t, m, tx, tl, self.reach, self.bounds],
            self.vis,
            size,
            &push_words(&params),
            label,
        )?)
    }

    /// Shades the visibility buffer into `out` (a layer, or the accumulation buffer).
    pub fn shade(&self, backend: &mut dyn Backend, mesh: &DeviceMesh, params: &ShadeParams, out: BufferId, label: &str) -> Result<()> {
        self.shade_words(backend, mesh, &push_words(params), out, None, label)
    }

    /// [`Self::shade`] from push words, over every pixel or with the workgroups read on the device
    /// from `indirect` (buffer, word offset).
    pub fn shade_words(
        &self,
        backend: &mut dyn Backend,
        mesh: &DeviceMesh,
        params: &[u32],
        out: BufferId,
        indirect: Option<(BufferId, u64)>,
        label: &str,
    ) -> Result<()> {
        let [vertices, triangles, materials, textures, texels] = mesh.buffers;
        let bound = raster_shade::Bindings { vis: self.vis, vertices, triangles, materials, textures, texels, out, reach: self.reach };
        let p: ShadeParams = dof_shaders::exec::params(params);
        match indirect {
            Some((args, offset)) => Ok(backend.run_indirect(bound, args, offset, &p, label)?),
            None => Ok(backend.run(bound, groups_for(&RASTER_SHADE, p.width as u64 * p.height as u64), &p, label)?),
        }
    }
}

/// Peels `scene` seen by `camera` through `lens` into a partial multi-layer image (module docs).
pub fn peel_layers(
    backend: &mut dyn Backend,
    scene: &RasterScene,
    camera: &Camera,
    lens: &ThinLens,
    near: f32,
    options: &LayerOptions,
) -> Result<Peeled> {
    DeviceMesh::scoped(backend, scene, |backend, mesh| peel_layers_with(backend, scene, mesh, camera, lens, near, options))
}

/// [`peel_layers`] with `scene` already on the device as `mesh`, which it leaves there
/// ([`DeviceMesh::scoped`]).
#[allow(clippy::too_many_arguments)]
pub fn peel_layers_with(
    backend: &mut dyn Backend,
    scene: &RasterScene,
    mesh: &DeviceMesh,
    camera: &Camera,
    lens: &ThinLens,
    near: f32,
    options: &LayerOptions,
) -> Result<Peeled> {
    check_view(camera, lens, near)?;
    let margin = options.guard_band.resolve(|| Ok(auto_margin_mesh(scene.triangle_positions(), camera, lens, near)?))?;
    check_subsamples(options.subsamples)?;
    // Area-integrated layers: peeled at sub-sample resolution (a `side`-times finer pixel grid
    // whose pixel centres are the stratified sub-samples), then resolved per pixel.
    let side = grid_side(options.subsamples);
    let coarse = camera.overscan(margin).frame()?;
    let fine_camera = sub_sample_camera(camera, side);
    let frame = fine_camera.overscan(margin * side).frame()?;
    check_texture_probes(options.texture_probes)?;
    if options.max_layers == 0 || !(options.edge_depth_ratio >= 0.0) {
        return Err(Error::invalid(format!(
            "need at least one layer and a non-negative edge ratio, got {} and {}",
            options.max_layers, options.edge_depth_ratio
        )));
    }
    frame.check_size("multi-layer image", options.max_layers as u64)?;
    let mut full = LayeredImage::new(frame.width, frame.height, options.max_layers)?;
    let pixels = frame.width as u64 * frame.height as u64;
    let mut sizes = Pass::sizes(mesh, pixels, pixels).to_vec();
    sizes.push((LAYER_WORDS as u64 * pixels, "peel/layer"));
    let result = with_buffers(backend, &sizes, |backend, b| {
        let pass = Pass::new(backend, mesh, b, pixels)?;
        let layer = b[4];
        let view = View::default();
        let shade = shade_params(scene, mesh, &frame, lens, &view, mode_word(LAYER, options.texture_probes));
        let mut times = Vec::new();
        let mut passes = 0;
        let layers = options.max_layers as usize;
        let most = peel_passes(options.max_layers, options.translucent_passes)?;
        for k in 0..most {
            pass.draw(backend, mesh, &view, &frame, lens, near, k > 0, &format!("peel/draw {k}"))?;
            pass.shade(backend, mesh, &shade, layer, &format!("peel/shade {k}"))?;
            times.extend(backend.submit()?);
            passes += 1;
            let words = backend.read_buffer(layer, 0, LAYER_WORDS as u64 * pixels)?;
            let mut found = false;
            for (p, w) in words.as_chunks::<{ LAYER_WORDS as usize }>().0.iter().enumerate() {
                let (alpha, depth) = (f32::from_bits(w[3]), f32::from_bits(w[4]));
                // The device peel's rules (`dof_shaders::peel`), so both keep the same slots.
                if !slot_kept(alpha, depth) {
                    continue;
                }
                // Each pass keeps fragments strictly beyond the last, so layers arrive in order.
                let n = full.counts[p];
                let last = if n > 0 { full.fragments[p * layers + n as usize - 1].alpha } else { 0.0 };
                let target = target_slot(n, options.max_layers, last);
                if target == options.max_layers {
                    continue;
                }
                let rgb = [0, 1, 2].map(|j| f32::from_bits(w[j]));
                let fragment = Fragment { color: dof_shaders::slot::premultiply(rgb, alpha), alpha, depth };
                let slot = &mut full.fragments[p * layers + target as usize];
                if target == n {
                    *slot = fragment;
                    full.counts[p] += 1;
                } else {
                    let s = behind(slot.slot(), fragment.slot());
                    *slot = Fragment { color: s.color, alpha: s.alpha, depth: s.depth };
                }
                found |= is_surface(depth) && takes_more(target, options.max_layers, slot.alpha);
            }
            if !found {
                break;
            }
        }
        Ok((passes, times))
    });
    let (passes, times) = result?;
    let full = if side > 1 { resolve_subsamples(&full, side, options.max_layers, options.edge_depth_ratio)? } else { full };
    let full = if options.footprints { full } else { full.without_footprints() };
    Ok(Peeled { image: apply_disocclusion(full, &coarse, lens, options, margin), passes, times })
}

/// `camera` with a `side`-times finer pixel grid over the same view: its pixel centres are the
/// stratified sub-samples of `camera`'s pixels (`dof_shaders::resolve::subsample_offset`).
pub(crate) fn sub_sample_camera(camera: &Camera, side: u32) -> Camera {
    Camera { width: camera.width.saturating_mul(side), height: camera.height.saturating_mul(side), ..*camera }
}
