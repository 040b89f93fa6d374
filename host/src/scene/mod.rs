//! Scenes, cameras and lenses, and the exact references computed from analytic scenes.
//!
//! - [`camera`]: the pinhole camera (glTF conventions), pixel and lens rays, planar depth;
//! - [`lens`]: lens settings (photographic or aperture radius) validated into a [`ThinLens`];
//! - [`analytic`]: spheres, boxes, quads and planes, exact ray intersection, the lighting model;
//! - [`builtin`](mod@builtin): named scenes with default camera and lens (`simple`, `railing`, `columns`,
//!   `highlights`);
//! - [`raycast`]: the exact partial multi-layer image (umbra threshold, disocclusion buffer);
//! - [`deep_layers`]: a deep image's layers for a lens, by the ray caster's rules;
//! - `exr_input` (feature `exr`): an EXR given as a scene, flat layers or deep samples;
//! - [`guard_band`]: the margin rendered beyond the frame so blur from outside reaches into it;
//! - [`reference`](mod@reference): thin-lens distributed ray tracing (the ground truth) and the pinhole image;
//! - [`bvh`]: the bounding-volume hierarchy that keeps ray casts cheap;
//! - [`mesh`]: triangle scenes ([`MeshScene`]) as the rasteriser draws them;
//! - [`solids`]: closed opaque meshes drawn single-sided whatever their materials say;
//! - `gltf_load` (feature `gltf`): glTF 2.0 files into a [`MeshScene`];
//! - `gltf_export` (feature `gltf`): analytic scenes out as binary glTF, for rasterising what ray
//!   casting renders;
//! - `mitsuba_export` (feature `eval`): analytic scenes as Mitsuba 3 scenes, for an independent
//!   check of the references;
//! - [`sampling`]: stratified lens/pixel samples and the concentric disc mapping.
//!
//! The lens models themselves live in the kernel crate ([`dof_shaders::lens`]) so the kernels
//! evaluate the same code per fragment; they are re-exported here.

pub mod aimed;
pub mod analytic;
pub mod builtin;
pub mod bvh;
pub mod camera;
pub mod deep_layers;
#[cfg(feature = "exr")]
pub mod exr_input;
#[cfg(feature = "gltf")]
pub mod gltf_export;
#[cfg(feature = "gltf")]
pub mod gltf_load;
pub mod guard_band;
pub mod lens;
pub mod mesh;
#[cfg(feature = "eval")]
pub mod mitsuba_export;
pub mod raycast;
pub mod reference;
pub mod solids;
/// The sampler lives in the core (ray tracing through layers draws its lens samples with it).
pub use dof_core::sampling;

pub use analytic::{Albedo, Hit, Lighting, Material, Primitive, Scene, Shape};
pub use builtin::{BuiltinScene, builtin, builtin_names};
pub use camera::{Camera, CameraFrame, Ray};
pub use deep_layers::DeepLayersReport;
pub use dof_shaders::lens::{ArtistLens, ThinLens};
#[cfg(feature = "exr")]
pub use exr_input::ExrInput;
/// The vector type of the scene API (so users need not depend on `glam` themselves).
pub use glam::Vec3;
#[cfg(feature = "gltf")]
pub use gltf_export::{ExportOptions, export_builtin_glb, export_glb};
#[cfg(feature = "gltf")]
pub use gltf_load::{gltf_external_files, load_gltf, load_gltf_slice};
pub use guard_band::{GuardBand, MAX_GUARD_BAND};
pub use lens::{Aperture, Focus, LensSettings, validate_artist_lens};
pub use mesh::{LoadReport, MeshCamera, MeshScene};
#[cfg(feature = "eval")]
pub use mitsuba_export::{MitsubaExport, MitsubaOptions, MitsubaScene, export_metadata, export_mitsuba};
pub use raycast::{
    DEFAULT_SUBSAMPLES, LayerOptions, SceneLayers, apply_disocclusion, check_subsamples, raycast_layers, resolve_subsamples,
};
pub use reference::{AutoOptions, MAX_SPP, Reference, ReferenceOptions, noise_margin_db, pinhole, reference, reference_auto};
pub use solids::SolidReport;
