//! Depth of field with order-correct, partial-occlusion-aware splatting: the core a renderer links.
//!
//! - [`frame`]: the frame API: a context per device, extent and method that records frames against
//!   the caller's buffers, every method's context with its options, and the registry of methods;
//! - [`backend`]: the CPU and Vulkan backends that run the kernels of the `dof-shaders` crate;
//! - [`ops`]: kernel sequences recorded on any backend (segmented sort, prefix scan), on the caller's
//!   buffers too;
//! - [`aperture`]: aperture shapes (circle, blades, stars, image masks) for splatting and bokeh sprites;
//! - [`lens`]: the thin lens from a camera's focal length, f-number, focus distance and field of
//!   view (or sensor height, or projection matrix);
//! - [`sampling`]: stratified lens samples and the concentric disc mapping (ray tracing's lens samples);
//! - [`shaders`]: the embedded SPIR-V modules (prebuilt in `host/spirv/`, or compiled with the
//!   `rebuild-spirv` feature), and the hash of the kernel sources they were built from;
//! - [`kernel_shape`]: the GPU shape of each embedded kernel, read from its SPIR-V (per-invocation
//!   arrays, workgroup memory, barriers, divisions, subgroup operations), with no GPU;
//! - [`host_memory`]: the machine's memory, installed and free, against which sizes are refused;
//! - [`error`]: the errors of every call.
//!
//! It depends on nothing of the project but the kernels. Multi-layer images, scenes and their
//! references, the rasteriser, EXR/PNG/glTF, metrics and the evaluation are the crate `dof` above
//! it, which re-exports this crate's modules; the `dof` command is the crate `dof-cli`.
//!
//! # Features
//!
//! By default this builds on stable Rust from the prebuilt SPIR-V, without rust-gpu. `vulkan` (on
//! by default) is the Vulkan backend and the caller's Vulkan images: without it the core is the CPU
//! backend alone and builds no Vulkan crate. `png` reads aperture masks from PNG files; `rebuild-spirv` compiles the kernels to SPIR-V with rust-gpu
//! (pinned nightly) instead of embedding the prebuilt modules.

pub mod aperture;
pub mod backend;
pub mod error;
mod extent;
pub mod frame;
pub mod host_memory;
pub mod kernel_shape;
pub mod lens;
pub mod ops;
pub mod sampling;
pub mod shaders;

pub use error::{Error, Result};

pub use backend::{Backend, CpuBackend};
#[cfg(feature = "vulkan")]
pub use backend::{VulkanBackend, VulkanOptions};
/// The kernel crate, so that integrators use the kernel types of the version this crate was built with.
pub use dof_shaders;
pub use dof_shaders::lens::ThinLens;
