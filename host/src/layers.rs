//! The images every method consumes and produces: a linear HDR colour image, and the multi-layer
//! image (per pixel up to `max_layers` surface fragments, front to back) that partial occlusion needs.
//!
//! Conventions (as glTF and path tracers): row-major, top row first, image +x to the right; depth is
//! planar (distance along the camera's view axis, positive in front of the camera). The background
//! (what a ray that hits nothing sees: the sky) is a fragment at depth `f32::INFINITY`, the last
//! of its pixel; a pixel with no fragment at all (no data) is treated as a black background.
//!
//! Colour is **premultiplied** by alpha (`dof_shaders::slot`): a fragment's colour is the light it
//! sends, its alpha what it hides behind it. A pixel's fragments composite front to back ("over")
//! over black.

use crate::error::{CoreError, Error, Result};

/// Linear HDR RGB, row-major, top row first.
#[derive(Clone, Debug, PartialEq)]
pub struct RgbImage {
    pub width: u32,
    pub height: u32,
    pub data: Vec<[f32; 3]>,
}

impl RgbImage {
    pub fn new(width: u32, height: u32) -> Self {
        RgbImage { width, height, data: vec![[0.0; 3]; width as usize * height as usize] }
    }
    #[inline]
    pub fn index(&self, x: u32, y: u32) -> usize {
        y as usize * self.width as usize + x as usize
    }
    #[inline]
    pub fn get(&self, x: u32, y: u32) -> [f32; 3] {
        self.data[self.index(x, y)]
    }

    /// The image without `margin` pixels on every side (the frame inside a guard band). A margin
    /// that leaves nothing gives an empty image.
    pub fn crop(&self, margin: u32) -> RgbImage {
        let (w, h) = (self.width.saturating_sub(2 * margin), self.height.saturating_sub(2 * margin));
        let data = (0..h).flat_map(|y| (0..w).map(move |x| (x, y))).map(|(x, y)| self.get(x + margin, y + margin)).collect();
        RgbImage { width: w, height: h, data }
    }
}

/// `items` in a new vector with room for `extra` more, or `HostMemory` where the machine cannot
/// hold it.
fn copy_of<T: Copy>(items: &[T], extra: usize, what: &str) -> Result<Vec<T>> {
    let n = items.len().saturating_add(extra);
    let mut v = Vec::new();
    v.try_reserve_exact(n)
        .map_err(|_| CoreError::HostMemory { what: what.to_string(), bytes: (n as u64).saturating_mul(std::mem::size_of::<T>() as u64) })?;
    v.extend_from_slice(items);
    Ok(v)
}

/// A per-pixel plane (depth, mask) without `margin` pixels on every side of a `width`-wide image.
pub fn crop_plane<T: Copy>(plane: &[T], width: u32, margin: u32) -> Vec<T> {
    let height = plane.len() / width.max(1) as usize;
    let (w, m) = (width as usize, margin as usize);
    (m..height.saturating_sub(m)).flat_map(|y| plane[y * w + m..(y + 1) * w - m].iter().copied()).collect()
}

/// One surface sample along a pixel's ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fragment {
    /// Linear HDR radiance (emission included), **premultiplied** by `alpha`: the light the fragment
    /// sends towards the camera.
    pub color: [f32; 3],
    /// Coverage in [0, 1]: the share of what lies behind that the fragment hides; 1 for opaque
    /// surfaces.
    pub alpha: f32,
    /// Planar depth, > 0.
    pub depth: f32,
}

impl Fragment {
    /// An opaque fragment.
    pub fn opaque(color: [f32; 3], depth: f32) -> Self {
        Fragment { color, alpha: 1.0, depth }
    }

    /// The fragment as the layer input's slot (`dof_shaders::slot`).
    pub fn slot(&self) -> dof_shaders::slot::Slot {
        dof_shaders::slot::Slot { color: self.color, depth: self.depth, alpha: self.alpha }
    }
}

/// Per pixel up to `max_layers` fragments sorted front to back. Storage is fixed-size per pixel
/// (Franke et al. 2018, §4.3: the arrays are preallocated for the maximum and partially filled).
#[derive(Clone, Debug, PartialEq)]
pub struct LayeredImage {
    pub width: u32,
    pub height: u32,
    pub max_layers: u32,
    /// Fragments stored per pixel, `<= max_layers`.
    pub counts: Vec<u32>,
    /// Slot `pixel * max_layers + layer`; slots at or beyond `counts[pixel]` are unused.
    pub fragments: Vec<Fragment>,
    /// Each slot's footprint (`dof_shaders::footprint`: the sub-samples of its pixel's
    /// `footprint_side`² grid it covers) where the image was integrated over sub-samples, one per
    /// slot; empty (and `footprint_side` 0) where every slot stands for its whole pixel.
    pub footprints: Vec<u32>,
    pub footprint_side: u32,
}

/// What a multi-layer image holds, for reports.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LayerStats {
    pub pixels: u64,
    pub fragments: u64,
    /// Pixels with more than one fragment.
    pub multi_layer_pixels: u64,
    /// Pixels with no fragment at all (no data; the background is a fragment).
    pub empty_pixels: u64,
}

impl LayerStats {
    pub fn fragments_per_pixel(&self) -> f64 {
        self.fragments as f64 / self.pixels.max(1) as f64
    }
    pub fn multi_layer_share(&self) -> f64 {
        self.multi_layer_pixels as f64 / self.pixels.max(1) as f64
    }
}

/// Most fragment slots a layered image may have (2^28, 5 GiB of fragments): refused before
/// allocating rather than failing inside the allocator.
pub const MAX_SLOTS: u64 = 1 << 28;

const EMPTY: Fragment = Fragment { color: [0.0; 3], alpha: 0.0, depth: f32::INFINITY };

impl LayeredImage {
    /// An image with no fragments. Errors on a zero size or one too large to address.
    pub fn new(width: u32, height: u32, max_layers: u32) -> Result<Self> {
        if width == 0 || height == 0 || max_layers == 0 {
            return Err(Error::invalid(format!(
                "a layered image needs a positive size and layer count, got {width}x{height} with {max_layers} layers"
            )));
        }
        let slots = width as u64 * height as u64 * max_layers as u64;
        if slots > MAX_SLOTS {
            return Err(Error::Core(CoreError::TooLarge { what: "layered image (pixels x layers)".into(), size: slots, limit: MAX_SLOTS }));
        }
        Ok(LayeredImage {
            width,
            height,
            max_layers,
            counts: dof_core::error::filled(width as usize * height as usize, 0, "a layered image's counts")?,
            fragments: dof_core::error::filled(slots as usize, EMPTY, "a layered image's fragments")?,
            footprints: Vec::new(),
            footprint_side: 0,
        })
    }

    #[inline]
    pub fn pixel_index(&self, x: u32, y: u32) -> usize {
        y as usize * self.width as usize + x as usize
    }

    /// The fragments of pixel `(x, y)`, front to back.
    pub fn pixel(&self, x: u32, y: u32) -> &[Fragment] {
        let p = self.pixel_index(x, y);
        let start = p * self.max_layers as usize;
        &self.fragments[start..start + self.counts[p] as usize]
    }

    /// Appends a fragment behind those already stored at `(x, y)`. Returns `false` (and stores
    /// nothing) when the pixel is full; errors when the fragment would break the front-to-back order
    /// or its depth is not a positive number.
    pub fn push(&mut self, x: u32, y: u32, fragment: Fragment) -> Result<bool> {
        if !(fragment.depth > 0.0) {
            return Err(Error::invalid(format!("fragment depth {} at ({x}, {y}) is not positive", fragment.depth)));
        }
        let p = self.pixel_index(x, y);
        let count = self.counts[p] as usize;
        if count == self.max_layers as usize {
            return Ok(false);
        }
        let start = p * self.max_layers as usize;
        if count > 0 && self.fragments[start + count - 1].depth > fragment.depth {
            return Err(Error::invalid(format!("fragments at ({x}, {y}) must be pushed front to back")));
        }
        self.fragments[start + count] = fragment;
        self.counts[p] += 1;
        Ok(true)
    }

    /// Every pixel flattened (`dof_shaders::slot::flatten`): its fragments composited front to back
    /// over black (what a pinhole camera sees; an opaque front fragment's colour as it is) at the
    /// depth of its front fragment (`inf` for the background, and for a pixel without fragments,
    /// which is black). The single-layer methods' input, as the device's `frame_front` makes it.
    pub fn front(&self) -> (RgbImage, Vec<f32>) {
        let mut image = RgbImage::new(self.width, self.height);
        let mut depth = vec![f32::INFINITY; image.data.len()];
        for p in 0..image.data.len() {
            (image.data[p], depth[p]) = self.flattened(p);
        }
        (image, depth)
    }

    /// The depth of every pixel's front, as [`Self::front`] gives it, without the flattened colour;
    /// `HostMemory` where the machine cannot hold it.
    pub fn front_depths(&self) -> Result<Vec<f32>> {
        let mut depths = copy_of(&[], self.counts.len(), "the front depths")?;
        depths.extend((0..self.counts.len()).map(|p| self.flattened(p).1));
        Ok(depths)
    }

    /// A copy, or `HostMemory` where the machine cannot hold one (`clone` would abort).
    pub fn try_clone(&self) -> Result<LayeredImage> {
        Ok(LayeredImage {
            counts: copy_of(&self.counts, 0, "a layered image's counts")?,
            fragments: copy_of(&self.fragments, 0, "a layered image's fragments")?,
            footprints: copy_of(&self.footprints, 0, "a layered image's footprints")?,
            ..*self
        })
    }

    /// Pixel `p` flattened, as in [`Self::front`].
    pub fn flattened(&self, p: usize) -> ([f32; 3], f32) {
        let start = p * self.max_layers as usize;
        let n = self.counts[p].min(self.max_layers);
        dof_shaders::slot::flatten(n, |k| self.fragments[start + k as usize].slot())
    }

    /// Whether pixel `p`'s fragments end translucent, with black behind them
    /// (`dof_shaders::slot::ends_translucent`).
    pub fn ends_translucent(&self, p: usize) -> bool {
        let start = p * self.max_layers as usize;
        dof_shaders::slot::ends_translucent(self.counts[p].min(self.max_layers), |k| self.fragments[start + k as usize].slot())
    }

    /// Pixels whose `max_layers` slots are all used and still let light through, with black
    /// behind: a translucent stack deeper than the layers, whose remainder was left out.
    pub fn full_and_translucent(&self) -> u64 {
        (0..self.counts.len()).filter(|&p| self.counts[p] >= self.max_layers && self.ends_translucent(p)).count() as u64
    }

    /// Every pixel flattened ([`Self::front`]) as an opaque one-layer image: the input of
    /// single-layer methods.
    pub fn front_layer(&self) -> LayeredImage {
        let fragments = (0..self.counts.len())
            .map(|p| {
                let (color, depth) = self.flattened(p);
                Fragment { color, alpha: 1.0, depth }
            })
            .collect();
        LayeredImage {
            width: self.width,
            height: self.height,
            max_layers: 1,
            counts: self.counts.iter().map(|&c| c.min(1)).collect(),
            fragments,
            footprints: Vec::new(),
            footprint_side: 0,
        }
    }

    /// The image without `margin` pixels on every side.
    pub fn crop(&self, margin: u32) -> LayeredImage {
        let (w, h) = (self.width.saturating_sub(2 * margin), self.height.saturating_sub(2 * margin));
        let l = self.max_layers as usize;
        let mut counts = Vec::with_capacity(w as usize * h as usize);
        let mut fragments = Vec::with_capacity(counts.capacity() * l);
        let mut footprints = Vec::new();
        for y in margin..margin + h {
            for x in margin..margin + w {
                let p = self.pixel_index(x, y);
                counts.push(self.counts[p]);
                fragments.extend_from_slice(&self.fragments[p * l..(p + 1) * l]);
                if self.has_footprints() {
                    footprints.extend_from_slice(&self.footprints[p * l..(p + 1) * l]);
                }
            }
        }
        LayeredImage {
            width: w,
            height: h,
            max_layers: self.max_layers,
            counts,
            fragments,
            footprints,
            footprint_side: self.footprint_side,
        }
    }

    /// The edge policy for images with nothing beyond their frame (EXR input): `margin` pixels on
    /// every side, each a copy of the nearest edge pixel's fragments (clamp to edge), so a blurred
    /// object cut by the frame keeps spreading into it as if it went on. Errors like
    /// [`LayeredImage::new`] when the padded image would be too large.
    pub fn extend_edges(&self, margin: u32) -> Result<LayeredImage> {
        let (w, h) = (self.width + 2 * margin, self.height + 2 * margin);
        let mut out = LayeredImage::new(w, h, self.max_layers)?;
        if self.has_footprints() {
            out.footprints = vec![0; out.fragments.len()];
            out.footprint_side = self.footprint_side;
        }
        let l = self.max_layers as usize;
        for y in 0..h {
            let sy = y.saturating_sub(margin).min(self.height - 1);
            for x in 0..w {
                let sx = x.saturating_sub(margin).min(self.width - 1);
                let (p, q) = (out.pixel_index(x, y), self.pixel_index(sx, sy));
                out.counts[p] = self.counts[q];
                out.fragments[p * l..(p + 1) * l].copy_from_slice(&self.fragments[q * l..(q + 1) * l]);
                if self.has_footprints() {
                    out.footprints[p * l..(p + 1) * l].copy_from_slice(&self.footprints[q * l..(q + 1) * l]);
                }
            }
        }
        Ok(out)
    }

    /// Whether the slots carry footprints (one per slot).
    pub fn has_footprints(&self) -> bool {
        self.footprint_side > 0 && self.footprints.len() == self.fragments.len()
    }

    /// The side of the footprints' grid the slots carry, 0 for none (as the frame API's
    /// `FrameInput::Layers::footprint_side` takes it).
    pub fn footprint_grid(&self) -> u32 {
        if self.has_footprints() { self.footprint_side } else { 0 }
    }

    /// The image without its footprints: every slot stands for its whole pixel.
    pub fn without_footprints(mut self) -> LayeredImage {
        self.footprints = Vec::new();
        self.footprint_side = 0;
        self
    }

    pub fn stats(&self) -> LayerStats {
        let mut s = LayerStats { pixels: self.counts.len() as u64, ..Default::default() };
        for &c in &self.counts {
            s.fragments += c as u64;
            s.multi_layer_pixels += (c > 1) as u64;
            s.empty_pixels += (c == 0) as u64;
        }
        s
    }
}
