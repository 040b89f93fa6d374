//! Building blocks that record kernel sequences on any [`crate::backend::Backend`]: the segmented sort
//! and the prefix scan that the tiled splatting pipeline is made of.

pub mod scan;
pub mod sort;
