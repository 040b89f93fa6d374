//! Reading and writing images: EXR for linear HDR data (colour, depth, CoC, masks, multi-layer
//! input), PNG previews through a documented tone map.
