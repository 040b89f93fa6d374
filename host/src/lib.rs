//! Depth of field with order-correct, partial-occlusion-aware splatting: the host library.
//!
//! - [`frame`]: the frame API: a context per device, extent and method that records frames against the caller's buffers;
//! - [`backend`]: the CPU and Vulkan backends that run the kernels of the `dof-shaders` crate;
//! - [`ops`]: kernel sequences recorded on any backend (segmented sort, prefix scan);
//! - [`workload`]: synthetic inputs shaped like the pipeline's (tile-list length mixes);
//! - [`layers`]: colour and multi-layer images, the data every method shares;
//! - [`io`]: the display transform and the input rules; EXR and PNG in and out (feature `exr`);
//! - [`scene`]: lenses, cameras, analytic scenes and their exact references; glTF (feature `gltf`);
//! - [`raster`]: triangle meshes rasterised into multi-layer images and accumulation-buffer references;
//! - [`methods`]: the depth-of-field methods (gathering baseline, tiled splatting), on any backend;
//! - [`metrics`]: PSNR against a reference, full-frame and in the partial-occlusion region; SSIM and
//!   FLIP with the `eval` feature;
//! - `eval` (feature `eval`): every method on every scene and backend, timed and measured (`dof eval`);
//! - `stress` (feature `eval`): the stiff and extreme cases, each with its expectation, on every
//!   method (`dof stress`);
//! - [`shaders`]: the embedded SPIR-V modules (prebuilt in `host/spirv/`, or compiled with the
//!   `rebuild-spirv` feature).
//!
//! # Features
//!
//! Without default features this is the core: kernels, backends, the frame API, methods, layers,
//! analytic scenes, on stable Rust and without rust-gpu. `exr` (EXR and PNG files), `gltf` (glTF
//! scenes), `eval` (evaluation, SSIM and FLIP, plots, stress; implies `exr` and `gltf`), `progress`
//! (progress bars) and `cli` (the `dof` command; everything; the default) add the rest;
//! `rebuild-spirv` compiles the kernels to SPIR-V with rust-gpu (pinned nightly) instead of
//! embedding the prebuilt modules.

pub mod aperture;
pub mod backend;
pub mod error;
#[cfg(feature = "eval")]
pub mod eval;
pub mod frame;
pub mod io;
pub mod layers;
pub mod methods;
pub mod metrics;
pub mod ops;
mod progress;
pub mod raster;
pub mod scene;
pub mod shaders;
pub mod source_hash;
#[cfg(feature = "eval")]
pub mod stress;
pub mod timing;
pub mod workload;

pub use error::{Error, Result};

pub use backend::{Backend, CpuBackend, VulkanBackend, VulkanOptions};
/// The kernel crate, so that integrators use the kernel types of the version this crate was built with.
pub use dof_shaders;
pub use layers::{Fragment, LayeredImage, RgbImage};
pub use scene::ThinLens;
