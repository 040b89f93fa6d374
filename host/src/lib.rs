//! Depth of field with order-correct, partial-occlusion-aware splatting: the host library.
//!
//! - [`frame`]: the frame API: a context per device, extent and method that records frames against the caller's buffers;
//! - [`backend`]: the CPU and Vulkan backends that run the kernels of the `dof-shaders` crate;
//! - [`ops`]: kernel sequences recorded on any backend (segmented sort, prefix scan);
//! - [`workload`]: synthetic inputs shaped like the pipeline's (tile-list length mixes);
//! - [`layers`]: colour and multi-layer images, the data every method shares;
//! - [`io`]: EXR and PNG in and out;
//! - [`scene`]: lenses, cameras, analytic scenes and their exact references;
//! - [`methods`]: the depth-of-field methods (gathering baseline, tiled splatting), on any backend;
//! - [`eval`]: every method on every scene and backend, timed and measured (`dof eval`);
//! - [`metrics`]: PSNR, SSIM and FLIP against a reference, full-frame and in the partial-occlusion region;
//! - [`stress`]: the stiff and extreme cases, each with its expectation, on every method (`dof stress`);
//! - [`shaders`]: the embedded SPIR-V modules.

pub mod aperture;
pub mod backend;
pub mod error;
pub mod eval;
pub mod frame;
pub mod io;
pub mod layers;
pub mod methods;
pub mod metrics;
pub mod ops;
pub mod raster;
pub mod scene;
pub mod shaders;
pub mod source_hash;
pub mod stress;
pub mod timing;
pub mod workload;

pub use error::{Error, Result};
