//! Multi-layer input for a camera whose [`LensBlur::layers`] is above one: the camera's view is
//! depth-peeled with Bevy's own passes (Franke et al. 2018, §4.1-4.3, through
//! `dof_core::frame::RendererPeel`) and blurred by multi-layer tiled splatting.
//!
//! - **Passes.** A view of `L` layers is drawn `L` times a frame: by `L − 1` pass cameras the
//!   plugin spawns as children of the camera (the same projection, clear colour, fog, ambient and
//!   environment light and exposure; orders just below the camera's; offscreen targets of the
//!   view's size), then by the camera itself, whose main pass is the last layer.
//! - **The test.** Meshes take part through [`PeelMaterial`], a `StandardMaterial` whose main pass
//!   discards a fragment unless it lies beyond the bound the library wrote for the pass (one f32 a
//!   pixel, in the [`ShaderBuffer`] every peel material binds). Outside a peel the bound keeps
//!   everything, so other cameras draw these meshes as usual.
//! - **A frame**, recorded into Bevy's command encoders on Bevy's device: `begin` before the first
//!   pass camera's main pass; after each pass camera's main pass, `append` of its main texture and
//!   depth; after the camera's own main pass, `append` of the last layer, `finish`, the blur into
//!   the camera's other main texture, and the bound reset to "keep all".

use crate::{BevyDevice, Imported, Inner, LensBlur, LensBlurState, depth_encoding, wgpu_backend};
use bevy::asset::uuid_handle;
use bevy::camera::{CameraMainTextureUsages, Hdr, RenderTarget};
use bevy::core_pipeline::prepass::{DeferredPrepass, DepthPrepass};
use bevy::core_pipeline::tonemapping::Tonemapping;
use bevy::pbr::{ExtendedMaterial, MaterialExtension};
use bevy::prelude::*;
use bevy::render::RenderApp;
use bevy::render::camera::ExtractedCamera;
use bevy::render::extract_component::ExtractComponent;
use bevy::render::render_asset::RenderAssets;
use bevy::render::render_resource::{AsBindGroup, TextureFormat, TextureUsages};
use bevy::render::renderer::{RenderContext, ViewQuery};
use bevy::render::storage::{GpuShaderBuffer, ShaderBuffer};
use bevy::render::sync_world::MainEntity;
use bevy::render::view::{ExtractedView, ViewDepthStencilTexture, ViewTarget};
use bevy::shader::ShaderRef;
use dof_core::backend::{Backend, BufferId, ImageRef, WgpuBackend};
use dof_core::dof_shaders::renderer_peel::KEEP_ALL;
use dof_core::frame::{
    DofContext, Extent, FrameOutput, LayerOptions, RendererPeel, RendererPeelDesc, SplatContext, SplatContextDesc, SplatOptions,
};

/// The bound every [`PeelTest`] binds: one f32 a pixel of the largest peeled view.
pub const PEEL_BOUND: Handle<ShaderBuffer> = uuid_handle!("5d0f3f4e-9a7c-4c55-8f43-2b1e7b0d6a91");

/// A `StandardMaterial` that takes part in a peel (module docs).
pub type PeelMaterial = ExtendedMaterial<StandardMaterial, PeelTest>;

/// `base` with the peel test.
pub fn peel_material(base: StandardMaterial) -> PeelMaterial {
    ExtendedMaterial { base, extension: PeelTest::default() }
}

/// The peel test of a [`PeelMaterial`]: its main pass reads [`PEEL_BOUND`].
#[derive(Asset, AsBindGroup, Reflect, Debug, Clone)]
pub struct PeelTest {
    #[storage(100, read_only)]
    bound: Handle<ShaderBuffer>,
}

impl Default for PeelTest {
    fn default() -> Self {
        PeelTest { bound: PEEL_BOUND }
    }
}

impl MaterialExtension for PeelTest {
    fn fragment_shader() -> ShaderRef {
        "embedded://bevy_dof/peel.wesl".into()
    }
}

/// A camera the plugin spawned to draw pass `pass` of its parent's peel.
#[derive(Component, Clone, Copy, Debug, ExtractComponent)]
#[extract_app(RenderApp)]
pub struct PeelPass {
    /// The peeled camera (main world).
    pub owner: Entity,
    pub pass: u32,
    /// The peeled camera's lens.
    pub lens: LensBlur,
}

/// The pass cameras of a peeled camera, for its size and layers.
#[derive(Component)]
pub(crate) struct PeelCameras {
    size: UVec2,
    layers: u32,
    cameras: Vec<Entity>,
}

/// Keeps each peeled camera's pass cameras in step with it (size, layers, order, projection,
/// clear colour, lens), and [`PEEL_BOUND`] large enough for every peeled view.
#[allow(clippy::type_complexity)]
pub(crate) fn sync_pass_cameras(
    mut commands: Commands,
    owners: Query<(Entity, &LensBlur, &Camera, Ref<Projection>, Option<&PeelCameras>, Has<DepthPrepass>, Has<DeferredPrepass>)>,
    mut passes: Query<(&mut Camera, &mut Projection, &mut PeelPass), Without<LensBlur>>,
    unpeeled: Query<(Entity, &PeelCameras), Without<LensBlur>>,
    mut images: ResMut<Assets<Image>>,
    mut buffers: ResMut<Assets<ShaderBuffer>>,
    mut refused: Local<Vec<Entity>>,
) {
    let mut bound_bytes = 0u64;
    for (owner, lens, camera, projection, cameras, depth_prepass, deferred) in &owners {
        let size = camera.physical_viewport_size().filter(|s| s.x > 0 && s.y > 0);
        let peeled = lens.layers > 1 && size.is_some();
        if peeled && (depth_prepass || deferred) && !refused.contains(&owner) {
            log::error!("bevy_dof: camera {owner}: peeling needs forward rendering without a depth prepass; it is not blurred");
            refused.push(owner);
        }
        let peeled = peeled && !depth_prepass && !deferred;
        let Some(size) = size.filter(|_| peeled) else {
            if let Some(old) = cameras {
                despawn_passes(&mut commands, owner, old);
            }
            continue;
        };
        bound_bytes = bound_bytes.max(4 * size.x as u64 * size.y as u64);
        // Pass k draws just before pass k + 1; the camera itself draws the last.
        let order = |pass: u32| camera.order - (lens.layers - 1 - pass) as isize;
        // A pass clears as the camera does (one that draws over what is there clears to the default).
        let clear_color = match camera.clear_color {
            ClearColorConfig::None => ClearColorConfig::Default,
            other => other,
        };
        if cameras.is_none_or(|c| c.size != size || c.layers != lens.layers) {
            if let Some(old) = cameras {
                despawn_passes(&mut commands, owner, old);
            }
            let spawned = (0..lens.layers - 1)
                .map(|pass| {
                    let target = images.add(Image::new_target_texture(size.x, size.y, TextureFormat::Rgba16Float, None));
                    let mut camera_3d = Camera3d::default();
                    camera_3d.depth_texture_usages.0 |= TextureUsages::TEXTURE_BINDING.bits();
                    commands
                        .spawn((
                            camera_3d,
                            Hdr,
                            Msaa::Off,
                            Tonemapping::None,
                            CameraMainTextureUsages(CameraMainTextureUsages::default().0 | TextureUsages::COPY_SRC),
                            Camera { order: order(pass), clear_color, is_active: camera.is_active, ..default() },
                            RenderTarget::Image(target.into()),
                            Projection::clone(&projection),
                            Transform::IDENTITY,
                            PeelPass { owner, pass, lens: *lens },
                            ChildOf(owner),
                        ))
                        .id()
                })
                .collect();
            commands.entity(owner).insert(PeelCameras { size, layers: lens.layers, cameras: spawned });
            continue;
        }
        for &entity in cameras.map(|c| c.cameras.as_slice()).unwrap_or_default() {
            let Ok((mut pass_camera, mut pass_projection, mut pass)) = passes.get_mut(entity) else { continue };
            if pass_camera.order != order(pass.pass) || pass_camera.is_active != camera.is_active {
                pass_camera.order = order(pass.pass);
                pass_camera.is_active = camera.is_active;
            }
            // Extracted every frame whether changed or not.
            pass_camera.bypass_change_detection().clear_color = clear_color;
            // Copied when it changes (a copy marks the pass camera's projection changed, and
            // Bevy recomputes it).
            if projection.is_changed() {
                *pass_projection = Projection::clone(&projection);
            }
            if pass.lens != *lens {
                pass.lens = *lens;
            }
        }
    }
    for (owner, old) in &unpeeled {
        despawn_passes(&mut commands, owner, old);
    }
    if buffers.get(&PEEL_BOUND).is_none_or(|b| b.buffer_size() < bound_bytes) {
        let _ = buffers.insert(&PEEL_BOUND, bound_of(bound_bytes));
    }
}

/// Keeps a view setting `C` of each peeled camera on its pass cameras, so that every layer is
/// shaded as the camera's own pass shades it: copied when the camera's changes or a pass camera
/// lacks it, removed with the camera's.
pub(crate) fn mirror_view_setting<C: Component + Clone>(
    mut commands: Commands,
    owners: Query<(Option<Ref<C>>, &PeelCameras)>,
    passes: Query<Has<C>, With<PeelPass>>,
) {
    for (setting, cameras) in &owners {
        for &pass in &cameras.cameras {
            // A pass camera spawned this frame is there from the next.
            let Ok(has) = passes.get(pass) else { continue };
            match &setting {
                Some(s) if s.is_changed() || !has => {
                    commands.entity(pass).insert(C::clone(s));
                }
                None if has => {
                    commands.entity(pass).remove::<C>();
                }
                _ => {}
            }
        }
    }
}

/// [`PEEL_BOUND`] of `bytes` (at least one word: a binding cannot be empty), keeping everything
/// until a peel writes it.
fn bound_of(bytes: u64) -> ShaderBuffer {
    ShaderBuffer::new(vec![KEEP_ALL; bytes.div_ceil(4).max(1) as usize], default())
}

/// Puts [`PEEL_BOUND`] of `bytes` into `world`'s shader buffers.
pub(crate) fn insert_bound(world: &mut World, bytes: u64) {
    if let Some(mut buffers) = world.get_resource_mut::<Assets<ShaderBuffer>>() {
        let _ = buffers.insert(&PEEL_BOUND, bound_of(bytes));
    }
}

fn despawn_passes(commands: &mut Commands, owner: Entity, cameras: &PeelCameras) {
    for &camera in &cameras.cameras {
        commands.entity(camera).despawn();
    }
    commands.entity(owner).remove::<PeelCameras>();
}

/// A peeled camera's render-world side.
pub(crate) struct Peeled {
    peel: RendererPeel,
    ctx: SplatContext,
    size: [u32; 2],
    layers: u32,
    /// [`PEEL_BOUND`]'s buffer, as imported.
    bound: (wgpu::Buffer, BufferId),
    /// Each pass's main texture and depth (the last: the camera's own).
    textures: Vec<Imported>,
    /// Whether the current frame has begun (a frame whose first pass did not run is skipped).
    begun: bool,
}

impl Peeled {
    pub(crate) fn forget(self, backend: &mut WgpuBackend) {
        for textures in self.textures {
            textures.forget(backend);
        }
        self.peel.destroy(backend);
        self.ctx.destroy(backend);
        backend.destroy_buffer(self.bound.1);
    }

    /// Appends pass `pass` of `colour` and `depth` into Bevy's encoder.
    fn append(
        &mut self,
        backend: &mut WgpuBackend,
        ctx: &mut RenderContext,
        pass: u32,
        colour: ImageRef,
        depth: ImageRef,
    ) -> Result<(), String> {
        let mut recording = backend.record_into(ctx.command_encoder()).map_err(|e| e.to_string())?;
        self.peel.append(&mut *recording, pass, colour, depth).map_err(|e| e.to_string())
    }
}

/// Before the first pass camera's main pass: the peel made (again, when the view's size, its
/// layers or the bound changed) and the frame begun.
#[allow(clippy::too_many_arguments)]
pub(crate) fn peel_begin(
    view: ViewQuery<(&ExtractedCamera, &ExtractedView, &PeelPass)>,
    state: Res<LensBlurState>,
    bounds: Res<RenderAssets<GpuShaderBuffer>>,
    bevy: BevyDevice,
    mut ctx: RenderContext,
) {
    let (camera, extracted, pass) = view.into_inner();
    if pass.pass != 0 {
        return;
    }
    let Ok(mut inner) = state.inner.lock() else { return };
    let Some(bound) = bounds.get(&PEEL_BOUND) else { return };
    let result = begin(&mut inner, camera, extracted, pass, &bound.buffer, &bevy, &mut ctx);
    inner.report(pass.owner, result);
}

#[allow(clippy::too_many_arguments)]
fn begin(
    inner: &mut Inner,
    camera: &ExtractedCamera,
    extracted: &ExtractedView,
    pass: &PeelPass,
    bound: &wgpu::Buffer,
    bevy: &BevyDevice,
    ctx: &mut RenderContext,
) -> Result<(), String> {
    let Some(size) = camera.physical_viewport_size else { return Ok(()) };
    let (width, height) = (size.x, size.y);
    if bound.size() < 4 * width as u64 * height as u64 {
        return Ok(()); // the bound grows with the view's first frames
    }
    let layers = pass.lens.layers;
    let backend = wgpu_backend(&mut inner.backend, bevy);
    let current = inner.peels.get(&pass.owner).is_some_and(|p| p.size == [width, height] && p.layers == layers && p.bound.0 == *bound);
    if !current {
        if let Some(old) = inner.peels.remove(&pass.owner) {
            old.forget(backend);
        }
        let encoding = depth_encoding(extracted.clip_from_view)?;
        let tan_half_fov = 1.0 / extracted.clip_from_view.y_axis.y;
        let options = LayerOptions { max_layers: layers, ..LayerOptions::default() };
        let bound_id = backend.import_buffer(bound, "bevy_dof/peel-bound").map_err(|e| e.to_string())?;
        let desc = RendererPeelDesc::new(&options, width, height, encoding, tan_half_fov, 0);
        let peel = RendererPeel::new(backend, &desc, bound_id, None).map_err(|e| e.to_string())?;
        let mut splat = SplatContextDesc::new(Extent::new(width, height, layers), SplatOptions::default());
        splat.image_io = true;
        let splat = SplatContext::new(backend, &splat).map_err(|e| e.to_string())?;
        // The buffers' zeroing, run now: the frames submit nothing.
        backend.submit().map_err(|e| e.to_string())?;
        let textures = (0..layers).map(|_| Imported::default()).collect();
        let peeled = Peeled { peel, ctx: splat, size: [width, height], layers, bound: (bound.clone(), bound_id), textures, begun: false };
        inner.peels.insert(pass.owner, peeled);
    }
    let backend = inner.backend.as_mut().ok_or("no backend")?;
    let peeled = inner.peels.get_mut(&pass.owner).ok_or("no peel")?;
    let lens = pass.lens.thin_lens(extracted.clip_from_view, height).map_err(|e| e.to_string())?;
    let mut recording = backend.record_into(ctx.command_encoder()).map_err(|e| e.to_string())?;
    peeled.begun = false;
    peeled.peel.begin(&mut *recording, &lens).map_err(|e| e.to_string())?;
    peeled.begun = true;
    Ok(())
}

/// After a pass camera's main pass: its layer appended.
pub(crate) fn peel_append(
    view: ViewQuery<(&ViewTarget, &ViewDepthStencilTexture, &PeelPass)>,
    state: Res<LensBlurState>,
    mut ctx: RenderContext,
) {
    let (target, depth, pass) = view.into_inner();
    let Ok(mut inner) = state.inner.lock() else { return };
    let Inner { backend, peels, .. } = &mut *inner;
    let (Some(backend), Some(peeled)) = (backend.as_mut(), peels.get_mut(&pass.owner)) else { return };
    if !peeled.begun {
        return;
    }
    let result = peeled.textures[pass.pass as usize]
        .images(backend, [target.main_texture(), depth.texture()])
        .map_err(|e| e.to_string())
        .and_then(|[colour, depth]| peeled.append(backend, &mut ctx, pass.pass, colour, depth));
    if result.is_err() {
        peeled.begun = false;
    }
    inner.report(pass.owner, result);
}

/// After the peeled camera's own main pass: the last layer appended, the peel finished, the view
/// blurred into the camera's other main texture, and the bound reset to "keep all". A frame whose
/// first pass did not run leaves the image as it was.
pub(crate) fn peel_finish(
    inner: &mut Inner,
    owner: MainEntity,
    lens: &LensBlur,
    extracted: &ExtractedView,
    target: &ViewTarget,
    depth: &ViewDepthStencilTexture,
    ctx: &mut RenderContext,
) -> Result<(), String> {
    let Inner { backend, peels, .. } = inner;
    let (Some(backend), Some(peeled)) = (backend.as_mut(), peels.get_mut(&owner.id())) else { return Ok(()) };
    if !std::mem::replace(&mut peeled.begun, false) || peeled.layers != lens.layers {
        return Ok(());
    }
    let ([width, height], last) = (peeled.size, peeled.layers - 1);
    let lens = lens.thin_lens(extracted.clip_from_view, height).map_err(|e| e.to_string())?;
    // The main texture holds the last layer; the blur goes into the other one.
    let post = target.post_process_write();
    let [colour, depth, output] = peeled.textures[last as usize]
        .images(backend, [post.source_texture, depth.texture(), post.destination_texture])
        .map_err(|e| e.to_string())?;
    peeled.append(backend, ctx, last, colour, depth)?;
    let mut recording = backend.record_into(ctx.command_encoder()).map_err(|e| e.to_string())?;
    peeled.peel.finish(&mut *recording).map_err(|e| e.to_string())?;
    let frame = peeled.peel.frame(lens, FrameOutput::Image(output));
    peeled.ctx.record(&mut *recording, &frame).map_err(|e| e.to_string())?;
    recording.fill(peeled.bound.1, 0, width as u64 * height as u64, KEEP_ALL.to_bits(), "bevy_dof/peel-bound").map_err(|e| e.to_string())
}
