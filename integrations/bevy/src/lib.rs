//! Order-correct depth of field for Bevy cameras, through `dof-core`'s wgpu backend on Bevy's own
//! device, recorded into Bevy's own command encoders:
//! - by default single-layer tiled splatting (Selgrad, Franke, Stamminger 2016) of the camera's HDR
//!   colour and depth, as the `dof` command's `tiled` method runs it;
//! - with [`LensBlur::layers`] above one, multi-layer tiled splatting (Franke et al. 2018) of the
//!   view depth-peeled by Bevy's own passes, for meshes drawn with a [`PeelMaterial`] (the
//!   [`peel`] module).
//!
//! ```no_run
//! use bevy::prelude::*;
//! use bevy_dof::{LensBlur, LensBlurPlugin, PeelMaterial, peel_material};
//!
//! fn setup(mut commands: Commands, mut meshes: ResMut<Assets<Mesh>>, mut materials: ResMut<Assets<PeelMaterial>>) {
//!     // Four layers a pixel, peeled by Bevy's passes (`LensBlur::default()` blurs one).
//!     commands.spawn((Camera3d::default(), LensBlur { layers: 4, ..default() }));
//!     let material = materials.add(peel_material(StandardMaterial { base_color: Color::WHITE, ..default() }));
//!     commands.spawn((Mesh3d(meshes.add(Cuboid::default())), MeshMaterial3d(material)));
//! }
//!
//! App::new().add_plugins((DefaultPlugins, LensBlurPlugin)).add_systems(Startup, setup).run();
//! ```
//!
//! What the plugin does, per camera with a [`LensBlur`]:
//! - it gives the camera what the library reads and writes: an HDR (RGBA16F) main texture the
//!   library's kernels sample and write in place (a storage texture) and a peel copies from, and a
//!   depth texture the library's kernels bind;
//! - in the render world it keeps one `SplatContext` per camera, made again only when the view's
//!   size changes (the only allocation);
//! - each frame, after the main passes and before tone mapping, it records the frame into Bevy's
//!   command encoder: the main texture and the main pass's depth attachment in (Bevy's
//!   reversed, infinite-far depth), the blurred image out into the other main texture, which the
//!   later passes then read. Nothing is submitted, uploaded or read back.
//!
//! Errors (a device without immediates, a view too large for a buffer) are logged once a camera,
//! and the camera's image is left as it was.

pub mod peel;

pub use peel::{PeelMaterial, PeelTest, peel_material};

use bevy::core_pipeline::tonemapping::tonemapping;
use bevy::core_pipeline::{Core3d, Core3dSystems};
use bevy::ecs::system::SystemParam;
use bevy::pbr::MaterialPlugin;
use bevy::prelude::*;
use bevy::render::camera::ExtractedCamera;
use bevy::render::extract_component::{ExtractComponent, ExtractComponentPlugin};
use bevy::render::render_resource::TextureUsages;
use bevy::render::renderer::{RenderAdapterInfo, RenderContext, RenderDevice, RenderQueue, ViewQuery};
use bevy::render::sync_world::MainEntity;
use bevy::render::view::{ExtractedView, ViewDepthStencilTexture, ViewTarget};
use bevy::render::{Render, RenderApp};
use dof_core::ThinLens;
use dof_core::backend::{Backend, ImageRef, WgpuBackend};
use dof_core::frame::{DepthEncoding, DofContext, Extent, Frame, FrameInput, FrameOutput, SplatContext, SplatContextDesc, SplatOptions};
use dof_core::lens::{Aperture, CameraLens, yfov_from_projection};
use std::collections::HashMap;
use std::sync::Mutex;

/// A camera's lens, as Bevy's own `DepthOfField` describes it, in the scene's units (metres in
/// Bevy's convention). The focal length follows from the camera's field of view and the sensor:
/// `f = sensor_height / (2·tan(yfov/2))`; the circle of confusion is then that of a thin lens of
/// that focal length and f-number focused at `focal_distance` (`dof_core::lens`).
#[derive(Component, Clone, Copy, Debug, PartialEq, ExtractComponent)]
#[extract_app(RenderApp)]
#[require(Camera3d, Msaa::Off, bevy::camera::Hdr)]
pub struct LensBlur {
    /// Distance to the plane in focus, along the view direction.
    pub focal_distance: f32,
    /// The f-number: the aperture's diameter is the focal length over it.
    pub aperture_f_stops: f32,
    /// Height of the sensor (a full-frame sensor is 0.024 tall).
    pub sensor_height: f32,
    /// Layers a pixel: 1 blurs the camera's own colour and depth; more peels the view into that
    /// many layers with Bevy's own passes, one draw of the scene a layer ([`peel`]).
    pub layers: u32,
}

impl Default for LensBlur {
    /// f/2.8 on a full-frame sensor, focused at 3 m.
    fn default() -> Self {
        LensBlur { focal_distance: 3.0, aperture_f_stops: 2.8, sensor_height: 0.024, layers: 1 }
    }
}

impl LensBlur {
    /// The library's thin lens for a view of `projection` (Bevy's `clip_from_view`), `height`
    /// pixels high.
    pub fn thin_lens(&self, projection: Mat4, height: u32) -> dof_core::Result<ThinLens> {
        let yfov = yfov_from_projection(&projection.to_cols_array_2d())?;
        let focal_length = self.sensor_height / (2.0 * (0.5 * yfov).tan());
        CameraLens {
            focal_length,
            aperture: Aperture::FNumber(self.aperture_f_stops),
            focus_distance: self.focal_distance,
            yfov,
            height_px: height,
        }
        .thin_lens()
    }
}

/// Adds [`LensBlur`] to Bevy's 3D cameras.
pub struct LensBlurPlugin;

impl Plugin for LensBlurPlugin {
    fn build(&self, app: &mut App) {
        bevy::asset::embedded_asset!(app, "peel.wesl");
        app.add_plugins((
            ExtractComponentPlugin::<LensBlur>::default(),
            ExtractComponentPlugin::<peel::PeelPass>::default(),
            MaterialPlugin::<PeelMaterial>::default(),
        ))
        .add_systems(PostUpdate, (configure_cameras, peel::sync_pass_cameras.after(bevy::camera::CameraUpdateSystems)))
        .add_systems(
            PostUpdate,
            (
                peel::mirror_view_setting::<bevy::pbr::DistanceFog>,
                peel::mirror_view_setting::<bevy::light::AmbientLight>,
                peel::mirror_view_setting::<bevy::light::EnvironmentMapLight>,
                peel::mirror_view_setting::<bevy::camera::Exposure>,
            )
                .after(peel::sync_pass_cameras),
        );
        let Some(render_app) = app.get_sub_app_mut(RenderApp) else {
            return;
        };
        render_app.init_resource::<LensBlurState>().add_systems(Render, forget_removed_views).add_systems(
            Core3d,
            (
                peel::peel_begin.after(Core3dSystems::Prepass).before(Core3dSystems::MainPass),
                (peel::peel_append, lens_blur).in_set(Core3dSystems::PostProcess).before(tonemapping),
            ),
        );
    }

    fn finish(&self, app: &mut App) {
        // The bound exists before any peel material is prepared: a material whose buffer is not
        // there yet gets Bevy's one-byte fallback buffer, which wgpu refuses as a storage binding.
        peel::insert_bound(app.world_mut(), 4);
    }
}

/// What the library reads and writes: a single-sampled depth texture its kernels bind, and a main
/// texture they sample and write in place, and a peel copies from.
fn configure_cameras(mut cameras: Query<(&mut Camera3d, &mut Msaa, &mut bevy::camera::CameraMainTextureUsages), Changed<LensBlur>>) {
    for (mut camera_3d, mut msaa, mut usages) in &mut cameras {
        camera_3d.depth_texture_usages.0 |= TextureUsages::TEXTURE_BINDING.bits();
        usages.0 |= TextureUsages::TEXTURE_BINDING | TextureUsages::STORAGE_BINDING | TextureUsages::COPY_SRC;
        if *msaa != Msaa::Off {
            log::info!("bevy_dof: multisampling turned off on a camera with LensBlur (its depth is read one sample a pixel)");
            *msaa = Msaa::Off;
        }
    }
}

/// The render world's side: the backend on Bevy's device, and a context per camera.
#[derive(Resource, Default)]
struct LensBlurState {
    inner: Mutex<Inner>,
}

#[derive(Default)]
struct Inner {
    backend: Option<WgpuBackend>,
    /// Single-layer cameras (render-world entities).
    views: HashMap<Entity, View>,
    /// Peeled cameras (main-world entities).
    peels: HashMap<Entity, peel::Peeled>,
    /// Cameras whose error was logged.
    failed: Vec<Entity>,
}

impl Inner {
    /// Logs `result`'s error once for `camera`.
    fn report(&mut self, camera: Entity, result: Result<(), String>) {
        if let Err(e) = result
            && !self.failed.contains(&camera)
        {
            log::error!("bevy_dof: camera {camera}: {e}; its image is left unblurred");
            self.failed.push(camera);
        }
    }
}

/// Bevy's device, queue and adapter, which the backend runs on.
#[derive(SystemParam)]
struct BevyDevice<'w> {
    device: Res<'w, RenderDevice>,
    queue: Res<'w, RenderQueue>,
    adapter: Res<'w, RenderAdapterInfo>,
}

/// The backend on Bevy's device, made on first use.
fn wgpu_backend<'a>(backend: &'a mut Option<WgpuBackend>, bevy: &BevyDevice) -> &'a mut WgpuBackend {
    backend.get_or_insert_with(|| {
        let backend = WgpuBackend::from_device(bevy.device.wgpu_device().clone(), (**bevy.queue).clone(), (**bevy.adapter).clone());
        let subgroups = if backend.limits().subgroup_kernels { "in subgroups" } else { "without subgroups" };
        log::info!("bevy_dof: the kernels scan and reduce {subgroups}");
        backend
    })
}

/// Textures imported once and kept while they are used: Bevy keeps a view's textures across
/// frames (its two main textures swap roles each frame) and makes new ones on a resize.
#[derive(Default)]
struct Imported(Vec<(wgpu::Texture, ImageRef)>);

impl Imported {
    /// The images of `textures` (imported on first use); the textures no longer used are
    /// forgotten, so that the backend does not keep them alive.
    fn images<const N: usize>(&mut self, backend: &mut WgpuBackend, textures: [&wgpu::Texture; N]) -> dof_core::Result<[ImageRef; N]> {
        let mut kept = Vec::with_capacity(N);
        for texture in textures {
            let image = match self.0.iter().position(|(t, _)| t == texture) {
                Some(at) => self.0.swap_remove(at).1,
                None => backend.import_texture(texture)?,
            };
            kept.push((texture.clone(), image));
        }
        for (_, stale) in std::mem::replace(&mut self.0, kept) {
            backend.forget_texture(&stale);
        }
        Ok(std::array::from_fn(|i| self.0[i].1))
    }

    fn forget(self, backend: &mut WgpuBackend) {
        for (_, image) in &self.0 {
            backend.forget_texture(image);
        }
    }
}

/// One single-layer camera's context, for views up to `extent`.
struct View {
    ctx: SplatContext,
    extent: [u32; 2],
    imported: Imported,
}

impl View {
    /// Drops the view: its textures forgotten by the backend, its context's buffers freed once the
    /// device is done with them.
    fn forget(self, backend: &mut WgpuBackend) {
        self.imported.forget(backend);
        self.ctx.destroy(backend);
    }
}

fn forget_removed_views(state: Res<LensBlurState>, views: Query<(Entity, &MainEntity, &LensBlur)>) {
    let Ok(mut inner) = state.inner.lock() else { return };
    let Inner { backend, views: contexts, peels, .. } = &mut *inner;
    if let Some(backend) = backend.as_mut() {
        let single: Vec<Entity> = views.iter().filter(|(_, _, lens)| lens.layers <= 1).map(|(e, _, _)| e).collect();
        let peeled: Vec<Entity> = views.iter().filter(|(_, _, lens)| lens.layers > 1).map(|(_, m, _)| m.id()).collect();
        for (_, view) in contexts.extract_if(|entity, _| !single.contains(entity)) {
            view.forget(backend);
        }
        for (_, peel) in peels.extract_if(|entity, _| !peeled.contains(entity)) {
            peel.forget(backend);
        }
        let _ = backend.release_finished();
    }
}

/// The depth of field of one view, recorded into Bevy's command encoder: from its own colour and
/// depth, or, for a peeled camera, from the layers of its peel.
#[allow(clippy::type_complexity)]
fn lens_blur(
    view: ViewQuery<(Entity, &MainEntity, &ExtractedCamera, &ExtractedView, &ViewTarget, &ViewDepthStencilTexture, &LensBlur)>,
    state: Res<LensBlurState>,
    bevy: BevyDevice,
    mut ctx: RenderContext,
) {
    let (entity, main, camera, extracted, target, depth, lens) = view.into_inner();
    let Ok(mut inner) = state.inner.lock() else { return };
    let result = if camera.viewport.as_ref().is_some_and(|v| v.physical_position != UVec2::ZERO) {
        // The main textures are the target's size, and the library reads a view from their
        // top-left corner.
        Err("a viewport away from the target's top-left corner is not blurred here".into())
    } else if lens.layers > 1 {
        peel::peel_finish(&mut inner, *main, lens, extracted, target, depth, &mut ctx)
    } else {
        record(&mut inner, entity, camera, extracted, target, depth, lens, &bevy, &mut ctx)
    };
    inner.report(main.id(), result);
}

#[allow(clippy::too_many_arguments)]
fn record(
    inner: &mut Inner,
    entity: Entity,
    camera: &ExtractedCamera,
    extracted: &ExtractedView,
    target: &ViewTarget,
    depth: &ViewDepthStencilTexture,
    lens: &LensBlur,
    bevy: &BevyDevice,
    ctx: &mut RenderContext,
) -> Result<(), String> {
    let Some(size) = camera.physical_viewport_size else { return Ok(()) };
    let (width, height) = (size.x, size.y);
    if width == 0 || height == 0 {
        return Ok(());
    }
    let encoding = depth_encoding(extracted.clip_from_view)?;
    let backend = wgpu_backend(&mut inner.backend, bevy);
    // A context for the view, made again when it grows or shrinks.
    if inner.views.get(&entity).is_none_or(|v| v.extent != [width, height]) {
        if let Some(old) = inner.views.remove(&entity) {
            old.forget(backend);
        }
        let mut desc = SplatContextDesc::new(Extent::new(width, height, 1), SplatOptions::default());
        desc.image_io = true;
        let splat = SplatContext::new(backend, &desc).map_err(|e| e.to_string())?;
        // Its buffers' zeroing, run now: the frames submit nothing.
        backend.submit().map_err(|e| e.to_string())?;
        inner.views.insert(entity, View { ctx: splat, extent: [width, height], imported: Imported::default() });
    }
    let view = inner.views.get_mut(&entity).ok_or("no context")?;

    let post = target.post_process_write();
    let [color, depth_image, output] =
        view.imported.images(backend, [post.source_texture, depth.texture(), post.destination_texture]).map_err(|e| e.to_string())?;
    let frame = Frame {
        width,
        height,
        lens: lens.thin_lens(extracted.clip_from_view, height).map_err(|e| e.to_string())?,
        input: FrameInput::Images { color, depth: depth_image, encoding },
        output: FrameOutput::Image(output),
    };
    let mut recording = backend.record_into(ctx.command_encoder()).map_err(|e| e.to_string())?;
    view.ctx.record(&mut *recording, &frame).map_err(|e| e.to_string())
}

/// The library's reading of Bevy's depth: reversed Z, the far plane at infinity or finite.
fn depth_encoding(clip_from_view: Mat4) -> Result<DepthEncoding, String> {
    if clip_from_view.w_axis.w == 1.0 {
        return Err("an orthographic camera has no depth of field here".into());
    }
    // Reversed perspective: z_clip = a·z + b, w_clip = −z, so a = near / (far − near) and
    // b = near·far / (far − near); a = 0 for an infinite far plane.
    let (a, b) = (clip_from_view.z_axis.z, clip_from_view.w_axis.z);
    let (near, far) = if a == 0.0 { (b, f32::INFINITY) } else { (b / (1.0 + a), b / a) };
    if !(near > 0.0 && far > near) {
        return Err(format!("a projection the library does not read (near {near}, far {far}): it reads reversed-Z perspective"));
    }
    Ok(DepthEncoding::Reversed { near, far })
}
