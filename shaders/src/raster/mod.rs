//! Rasterising triangle meshes (glTF scenes) into the multi-layer image and the
//! accumulation-buffer reference (seed 000 §4).
//!
//! - [`mesh`]: the scene's buffers and the lighting model.

pub mod mesh;
