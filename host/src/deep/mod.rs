//! Deep images: every sample of every pixel, with its depth range and coverage, as production
//! renderers write them to deep OpenEXR files (read by `io::read_deep_exr`, feature `exr`).
//!
//! A deep image is the input the multi-layer method needs, before any choice of layers. This module
//! holds it, makes it tidy, flattens it and turns it into a [`LayeredImage`] by the paper's rules:
//!
//! - [`DeepImage::tidy`]: OpenEXR's "Interpreting Deep Pixels" (Hillman 2013): samples sorted by
//!   depth, volume samples (`z_back > z`) split where they overlap others, samples covering the same
//!   depth range merged, so that a pixel is a front-to-back list of disjoint samples;
//! - [`DeepImage::flatten`]: that list composited "over", front to back (OpenEXR's flattened image);
//! - `DeepImage::layers` (in `scene::deep_layers`, beside the ray caster whose rules it follows):
//!   the umbra threshold and the disocclusion buffer of Franke et al. 2018 (§4) decide which
//!   samples a pixel keeps, and a pixel with more than `max_layers` left merges its closest
//!   neighbours in inverse depth (the CoC is linear in it), so a pixel of 200 samples never
//!   becomes 200 layers; its report says what was merged or left out and how much of the in-focus
//!   image that moved.
//!
//! Colour is premultiplied by alpha, as in OpenEXR and in [`crate::layers::Fragment`].

mod tidy;

use crate::error::{CoreError, Error, Result};
use crate::layers::RgbImage;
use dof_shaders::slot::{Slot, flatten};

/// One sample of a deep pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeepSample {
    /// Premultiplied linear colour.
    pub color: [f32; 3],
    /// Coverage in [0, 1].
    pub alpha: f32,
    /// Front depth (planar, > 0; `+inf` for the background).
    pub z: f32,
    /// Back depth, `>= z`: equal for a point sample, larger for a volume sample.
    pub z_back: f32,
}

impl DeepSample {
    /// Whether the sample spans a depth range.
    pub fn is_volume(&self) -> bool {
        self.z_back > self.z
    }

    pub(crate) fn slot(&self) -> Slot {
        Slot { color: self.color, depth: self.z, alpha: self.alpha }
    }
}

/// Most samples a deep image may hold (2^27, 3 GiB): refused before allocating.
pub const MAX_DEEP_SAMPLES: u64 = 1 << 27;

/// Samples per pixel, row-major, top row first: pixel `p` holds
/// `samples[offsets[p]..offsets[p + 1]]`.
#[derive(Clone, Debug, PartialEq)]
pub struct DeepImage {
    pub width: u32,
    pub height: u32,
    /// `width * height + 1` prefix sums of the samples per pixel.
    pub offsets: Vec<u64>,
    pub samples: Vec<DeepSample>,
}

impl DeepImage {
    /// An image from each pixel's sample count and the samples in pixel order. Errors when the
    /// sizes disagree or the samples exceed [`MAX_DEEP_SAMPLES`].
    pub fn from_counts(width: u32, height: u32, counts: &[u32], samples: Vec<DeepSample>) -> Result<Self> {
        if width == 0 || height == 0 || counts.len() != width as usize * height as usize {
            return Err(Error::invalid(format!(
                "a {width}x{height} deep image needs {} sample counts, got {}",
                width as u64 * height as u64,
                counts.len()
            )));
        }
        let mut offsets = Vec::with_capacity(counts.len() + 1);
        let mut total = 0u64;
        offsets.push(0);
        for &n in counts {
            total += n as u64;
            offsets.push(total);
        }
        if total > MAX_DEEP_SAMPLES {
            return Err(Error::Core(CoreError::TooLarge { what: "deep image (samples)".into(), size: total, limit: MAX_DEEP_SAMPLES }));
        }
        if total != samples.len() as u64 {
            return Err(Error::invalid(format!("the sample counts add up to {total} but {} samples were given", samples.len())));
        }
        Ok(DeepImage { width, height, offsets, samples })
    }

    pub fn pixels(&self) -> usize {
        self.width as usize * self.height as usize
    }

    /// The samples of pixel `p`.
    pub fn pixel(&self, p: usize) -> &[DeepSample] {
        &self.samples[self.offsets[p] as usize..self.offsets[p + 1] as usize]
    }

    /// The samples of pixel `p`'s count.
    pub fn count(&self, p: usize) -> u64 {
        self.offsets[p + 1] - self.offsets[p]
    }

    /// The most samples any pixel holds.
    pub fn max_count(&self) -> u64 {
        (0..self.pixels()).map(|p| self.count(p)).max().unwrap_or(0)
    }

    /// Every pixel's samples composited "over", front to back, over black, with the depth of the
    /// front sample (`inf` where a pixel is empty): OpenEXR's flattened image of a tidy image
    /// ([`Self::tidy`] first), and what every method returns in focus.
    pub fn flatten(&self) -> (RgbImage, Vec<f32>) {
        let mut image = RgbImage::new(self.width, self.height);
        let mut depth = vec![f32::INFINITY; self.pixels()];
        for p in 0..self.pixels() {
            let s = self.pixel(p);
            (image.data[p], depth[p]) = flatten(s.len() as u32, |k| s[k as usize].slot());
        }
        (image, depth)
    }

    /// The samples of several deep images of one frame in one image, as a deep merge does: each
    /// pixel holds every image's samples (tidy the result to order them). Errors when the sizes
    /// differ or the samples exceed [`MAX_DEEP_SAMPLES`].
    pub fn merge(images: &[DeepImage]) -> Result<DeepImage> {
        let Some(first) = images.first() else { return Err(Error::invalid("no deep image to merge".to_string())) };
        if let Some(other) = images.iter().find(|i| (i.width, i.height) != (first.width, first.height)) {
            return Err(Error::invalid(format!(
                "deep images of different sizes cannot merge: {}x{} and {}x{}",
                first.width, first.height, other.width, other.height
            )));
        }
        let counts: Vec<u32> =
            (0..first.pixels()).map(|p| images.iter().map(|i| i.count(p)).sum::<u64>().min(u32::MAX as u64) as u32).collect();
        let total: u64 = images.iter().map(|i| i.samples.len() as u64).sum();
        if total > MAX_DEEP_SAMPLES {
            return Err(Error::Core(CoreError::TooLarge {
                what: "merged deep image (samples)".into(),
                size: total,
                limit: MAX_DEEP_SAMPLES,
            }));
        }
        let mut samples = Vec::with_capacity(total as usize);
        for p in 0..first.pixels() {
            for image in images {
                samples.extend_from_slice(image.pixel(p));
            }
        }
        DeepImage::from_counts(first.width, first.height, &counts, samples)
    }
}

pub use tidy::TidyReport;
