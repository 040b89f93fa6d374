//! Depth of field above the core: the data, scenes, references and evaluation around the frame API.
//!
//! The core (`dof-core`: [`frame`], [`backend`], [`ops`], [`aperture`], [`shaders`]) is
//! re-exported here, so `dof::frame::…` and `dof_core::frame::…` name the same items. This crate adds:
//!
//! - [`error`]: its errors, the core's ([`CoreError`]) and those of scene files and plots;
//! - [`layers`]: colour and multi-layer images, the data every method shares;
//! - [`deep`]: deep images (every sample of a pixel), made tidy, flattened and turned into layers;
//! - [`scene`]: lenses, cameras, analytic scenes and their exact references; glTF (feature `gltf`);
//! - [`raster`]: triangle meshes rasterised into multi-layer images and accumulation-buffer references;
//! - [`methods`]: one frame of a host image through any method of the registry (the one-shot path),
//!   with its options;
//! - [`io`]: the display transform and the input rules; EXR and PNG in and out (feature `exr`);
//! - [`metrics`]: PSNR against a reference, full-frame and in the partial-occlusion region; SSIM and
//!   FLIP with the `eval` feature;
//! - [`workload`]: synthetic inputs shaped like the pipeline's (tile-list length mixes);
//! - [`timing`]: medians of timed runs;
//! - `eval` (feature `eval`): every method on every scene and backend, timed and measured (`dof eval`);
//! - `stress` (feature `eval`): the stiff and extreme cases, each with its expectation, on every
//!   method (`dof stress`).
//!
//! The `dof` command and its viewer are the crate `dof-cli` above this one.
//!
//! # Features
//!
//! Without features this is the core with layers, analytic scenes and the one-shot methods, on
//! stable Rust and without rust-gpu. `exr` (EXR and PNG files), `gltf` (glTF scenes), `eval`
//! (evaluation, SSIM and FLIP, plots, stress; implies `exr` and `gltf`) and `progress` (progress
//! bars) add the rest; `rebuild-spirv` compiles the kernels to SPIR-V with rust-gpu (pinned nightly)
//! instead of embedding the prebuilt modules.

pub mod deep;
pub mod error;
#[cfg(feature = "eval")]
pub mod eval;
pub mod io;
pub mod layers;
pub mod memory;
pub mod methods;
pub mod metrics;
mod progress;
pub mod raster;
pub mod scene;
#[cfg(feature = "eval")]
pub mod stress;
pub mod timing;
pub mod workload;

/// The core, re-exported so that `dof::frame::…` and `dof::backend::…` name the same items as
/// `dof_core::…`. [`Error`] is this crate's: the core's errors ([`CoreError`]) and those above it.
pub use dof_core;
pub use dof_core::{Backend, CpuBackend, VulkanBackend, VulkanOptions, dof_shaders};
pub use dof_core::{aperture, backend, frame, kernel_shape, lens, ops, shaders};
pub use error::{CoreError, Error, Result};
pub use layers::{Fragment, LayeredImage, RgbImage};
pub use scene::ThinLens;
