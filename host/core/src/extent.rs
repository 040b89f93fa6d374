//! The size a context is made for.

/// The largest frame a context records: pixels, and fragment slots per pixel of a multi-layer
/// input.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Extent {
    pub width: u32,
    pub height: u32,
    pub layers: u32,
}

impl std::fmt::Display for Extent {
    /// `1920x1080 with 4 layers`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}x{} with {} layer{}", self.width, self.height, self.layers, if self.layers == 1 { "" } else { "s" })
    }
}

impl Extent {
    pub fn new(width: u32, height: u32, layers: u32) -> Self {
        Extent { width, height, layers }
    }

    /// Whether a frame of this size and layer count fits.
    pub fn holds(&self, width: u32, height: u32, layers: u32) -> bool {
        width <= self.width && height <= self.height && layers <= self.layers
    }

    /// The smallest extent holding both.
    pub fn union(&self, other: Extent) -> Extent {
        Extent::new(self.width.max(other.width), self.height.max(other.height), self.layers.max(other.layers))
    }
}
