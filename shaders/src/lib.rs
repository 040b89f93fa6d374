//! The compute kernels of the depth-of-field system.
//!
//! Every kernel body here is ordinary Rust that runs twice: compiled to SPIR-V by rust-gpu (the
//! `#[spirv(compute)]` entry points that [`kernel!`] generates) and linked into the host as the CPU
//! backend. See [`exec`] for the execution model and [`kernel`] for how entry points are declared.
#![cfg_attr(target_arch = "spirv", no_std)]
// The CPU backend's lane type (`lane::Wide`) as a portable SIMD vector, on a nightly compiler.
#![cfg_attr(all(not(target_arch = "spirv"), feature = "portable-simd"), feature(portable_simd))]
// Kernel code keeps nested conditions, `% 2` and hand-written clamps: `f32::clamp` asserts its
// bounds, and a panic path is what kernels avoid.
#![allow(clippy::collapsible_if, clippy::manual_is_multiple_of, clippy::manual_clamp)]

pub mod aperture;
pub mod exec;
#[macro_use]
pub mod kernel;
pub mod bokeh;
pub mod fill;
pub mod footprint;
pub mod frame_io;
pub mod gather;
pub mod half;
pub mod keys;
pub mod lane;
pub mod layered;
pub mod lens;
pub mod math;
pub mod peel;
pub mod radiance;
pub mod raster;
pub mod raytrace;
pub mod renderer_peel;
pub mod resolve;
pub mod ring_gather;
pub mod scan;
pub mod scatter_gather;
pub mod slot;
pub mod sort;
pub mod splat;
pub mod texels;
pub mod texture_read;
pub mod tonemap;
pub mod wg;

#[cfg(not(target_arch = "spirv"))]
pub use kernel::{DrawDesc, KernelBindings, KernelDesc};

/// Every kernel, in a stable order: the host builds one pipeline for each.
#[cfg(not(target_arch = "spirv"))]
pub fn all_kernels() -> impl Iterator<Item = &'static KernelDesc> {
    scan::KERNELS
        .iter()
        .chain(fill::KERNELS.iter())
        .chain(sort::KERNELS.iter())
        .chain(gather::KERNELS.iter())
        .chain(ring_gather::KERNELS.iter())
        .chain(scatter_gather::KERNELS.iter())
        .chain(splat::KERNELS.iter())
        .chain(raytrace::KERNELS.iter())
        .chain(layered::KERNELS.iter())
        .chain(bokeh::KERNELS.iter())
        .chain(raster::KERNELS.iter())
        .chain(peel::KERNELS.iter())
        .chain(renderer_peel::KERNELS.iter())
        .chain(resolve::KERNELS.iter())
        .chain(frame_io::KERNELS.iter())
        .chain(radiance::KERNELS.iter())
        .chain(tonemap::KERNELS.iter())
        .copied()
}

/// Every draw through the graphics pipeline (its vertex and fragment entry points have modules too).
#[cfg(not(target_arch = "spirv"))]
pub fn all_draws() -> [&'static DrawDesc; 2] {
    [&bokeh::BOKEH_DRAW, &raster::draw::RASTER_DRAW]
}

/// The entry points of kernels that read textures (modules of their own, run by the wgpu backend
/// alone, with no CPU body).
#[cfg(not(target_arch = "spirv"))]
pub fn all_texture_kernels() -> [&'static str; 1] {
    [texture_read::DEPTH_TEXTURE_WORDS]
}
