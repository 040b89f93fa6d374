//! A tidy deep image ([`crate::deep`]) to the multi-layer image the methods read, by the rules of
//! Franke et al. 2018 (§4) that make the ray caster's layers ([`super::raycast`]):
//!
//! 1. **Umbra threshold.** Front to back, a sample is left out while it lies within the umbra of
//!    the last opaque sample kept (`ThinLens::umbra_length` of its depth and pixel footprint): no
//!    point of the lens sees it. A translucent sample sets no umbra.
//! 2. **Layer budget.** While a pixel keeps more than `max_layers` samples, the two neighbours
//!    closest in inverse depth merge ("over", at the front one's depth): a CoC is linear in inverse
//!    depth, so these are the two whose blur differs least. The pixel's flattened colour is kept.
//! 3. **Disocclusion buffer** ([`super::raycast::apply_disocclusion`]): outside it a pixel
//!    keeps its samples up to the first opaque one.
//!
//! A sample's share of the in-focus image is its coverage times the light that passes the samples in
//! front of it; [`DeepLayersReport`] sums these shares over what each step left out or moved, in
//! pixels (1.0 is one whole pixel's image).

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::fmt;

use rayon::prelude::*;

use super::camera::CameraFrame;
use super::raycast::apply_disocclusion;
use crate::deep::{DeepImage, DeepSample};
use crate::error::{Error, Result};
use crate::frame::LayerOptions;
use crate::layers::{Fragment, LayeredImage};
use dof_shaders::lens::ThinLens;

/// What turning a deep image into layers left out or merged.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DeepLayersReport {
    /// Samples of the tidy image.
    pub samples: u64,
    /// The most samples a pixel held.
    pub max_samples: u64,
    /// Samples left out in an umbra, and their share of the in-focus image (pixels).
    pub umbra_dropped: u64,
    pub umbra_share: f64,
    /// Samples merged into a nearer neighbour by the layer budget, and their share.
    pub budget_merged: u64,
    pub budget_share: f64,
    /// Pixels that had more samples than layers after the umbra threshold.
    pub budget_pixels: u64,
    /// Fragments left out outside the disocclusion buffer (behind an opaque one: no share).
    pub outside_buffer: u64,
    /// Fragments kept.
    pub fragments: u64,
}

impl std::ops::Add for DeepLayersReport {
    type Output = DeepLayersReport;
    fn add(self, o: DeepLayersReport) -> DeepLayersReport {
        DeepLayersReport {
            samples: self.samples + o.samples,
            max_samples: self.max_samples.max(o.max_samples),
            umbra_dropped: self.umbra_dropped + o.umbra_dropped,
            umbra_share: self.umbra_share + o.umbra_share,
            budget_merged: self.budget_merged + o.budget_merged,
            budget_share: self.budget_share + o.budget_share,
            budget_pixels: self.budget_pixels + o.budget_pixels,
            outside_buffer: self.outside_buffer + o.outside_buffer,
            fragments: self.fragments + o.fragments,
        }
    }
}

impl fmt::Display for DeepLayersReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} samples (at most {} a pixel) to {} fragments: {} left out in umbrae ({:.3} px of the in-focus image), \
             {} merged into nearer ones in {} pixels over the layer budget ({:.3} px moved nearer), {} left out beyond the \
             disocclusion buffer (hidden in focus)",
            self.samples,
            self.max_samples,
            self.fragments,
            self.umbra_dropped,
            self.umbra_share,
            self.budget_merged,
            self.budget_pixels,
            self.budget_share,
            self.outside_buffer
        )
    }
}

impl DeepImage {
    /// The multi-layer image of this tidy image ([`DeepImage::tidy`]) seen through `lens` by a
    /// camera whose pixel footprints `frame` gives (module docs); `options` gives the layer budget
    /// (`max_layers`), the umbra threshold and the disocclusion buffer (on or off) and its edge
    /// ratio. No guard band: the image is what the file holds. `frame` must be the image's size.
    pub fn layers(&self, frame: &CameraFrame, lens: &ThinLens, options: &LayerOptions) -> Result<(LayeredImage, DeepLayersReport)> {
        if (frame.width, frame.height) != (self.width, self.height) {
            return Err(Error::invalid(format!(
                "the camera frame is {}x{} but the deep image {}x{}",
                frame.width, frame.height, self.width, self.height
            )));
        }
        let mut full = LayeredImage::new(self.width, self.height, options.max_layers)?;
        let (w, l) = (self.width as usize, options.max_layers as usize);
        let report = full
            .fragments
            .par_chunks_mut(w * l)
            .zip(full.counts.par_chunks_mut(w))
            .enumerate()
            .map(|(y, (fragments, counts))| {
                let mut report = DeepLayersReport::default();
                let mut kept = Vec::new();
                for x in 0..w {
                    let samples = self.pixel(y * w + x);
                    report.samples += samples.len() as u64;
                    report.max_samples = report.max_samples.max(samples.len() as u64);
                    umbra_walk(samples, frame, lens, options.umbra_threshold, &mut kept, &mut report);
                    if kept.len() > l {
                        report.budget_pixels += 1;
                        merge_to_budget(&mut kept, l, &mut report);
                    }
                    for (slot, k) in fragments[x * l..].iter_mut().zip(&kept) {
                        *slot = Fragment { color: k.sample.color, alpha: k.sample.alpha, depth: k.sample.z };
                    }
                    counts[x] = kept.len() as u32;
                }
                report
            })
            .reduce(DeepLayersReport::default, |a, b| a + b);
        let before: u64 = full.counts.iter().map(|&c| c as u64).sum();
        let layers = if options.disocclusion { apply_disocclusion(full, frame, lens, options, 0).layers } else { full };
        let fragments: u64 = layers.counts.iter().map(|&c| c as u64).sum();
        Ok((layers, DeepLayersReport { outside_buffer: before - fragments, fragments, ..report }))
    }
}

/// A kept sample and the share of the in-focus image it carries.
#[derive(Clone, Copy, Debug)]
struct Kept {
    sample: DeepSample,
    share: f64,
}

/// Step 1 into `kept`: a pixel's samples outside the umbrae of the opaque ones kept before them.
fn umbra_walk(
    samples: &[DeepSample],
    frame: &CameraFrame,
    lens: &ThinLens,
    thin: bool,
    kept: &mut Vec<Kept>,
    report: &mut DeepLayersReport,
) {
    kept.clear();
    let mut transmit = 1.0f64;
    let mut reach = 0.0f32;
    for s in samples {
        let share = transmit * s.alpha as f64;
        transmit *= 1.0 - s.alpha as f64;
        // An umbra that never closes (reach +inf) hides the background too.
        if thin && !kept.is_empty() && (s.z < reach || reach == f32::INFINITY) {
            report.umbra_dropped += 1;
            report.umbra_share += share;
            continue;
        }
        kept.push(Kept { sample: *s, share });
        if s.alpha >= 1.0 {
            let umbra = lens.umbra_length(s.z, frame.pixel_footprint_radius(s.z));
            reach = if umbra.is_nan() { f32::INFINITY } else { s.z + umbra };
        }
    }
}

/// Step 2: merges neighbours of `kept` closest in inverse depth until `budget` are left.
fn merge_to_budget(kept: &mut Vec<Kept>, budget: usize, report: &mut DeepLayersReport) {
    let n = kept.len();
    let inverse = |s: &DeepSample| 1.0 / s.z;
    let gap = |a: &Kept, b: &Kept| (inverse(&a.sample) - inverse(&b.sample)).abs();
    // A linked list over `kept`, and a heap of (gap, left index, version of the left entry).
    let mut next: Vec<usize> = (1..=n).collect();
    let mut prev: Vec<usize> = (0..n).map(|i| i.wrapping_sub(1)).collect();
    let mut alive = vec![true; n];
    let mut version = vec![0u32; n];
    let mut heap: BinaryHeap<Reverse<(u32, usize, u32)>> =
        (0..n - 1).map(|i| Reverse((gap(&kept[i], &kept[i + 1]).to_bits(), i, 0))).collect();
    let mut left = n;
    while left > budget {
        let Some(Reverse((_, i, v))) = heap.pop() else { break };
        if !alive[i] || version[i] != v || next[i] >= n {
            continue;
        }
        let j = next[i];
        let (front, back) = (kept[i], kept[j]);
        let s = dof_shaders::slot::over(front.sample.slot(), back.sample.slot());
        kept[i] = Kept {
            sample: DeepSample { color: s.color, alpha: s.alpha, z: front.sample.z, z_back: back.sample.z_back.max(front.sample.z_back) },
            share: front.share + back.share,
        };
        report.budget_merged += 1;
        report.budget_share += back.share;
        alive[j] = false;
        next[i] = next[j];
        if next[j] < n {
            prev[next[j]] = i;
        }
        left -= 1;
        // The merged entry's gap to the right changed; the left neighbour's entry stays valid.
        version[i] += 1;
        if next[i] < n {
            heap.push(Reverse((gap(&kept[i], &kept[next[i]]).to_bits(), i, version[i])));
        }
        let p = prev[i];
        if p < n {
            version[p] += 1;
            heap.push(Reverse((gap(&kept[p], &kept[i]).to_bits(), p, version[p])));
        }
    }
    let mut i = 0;
    kept.retain(|_| {
        i += 1;
        alive[i - 1]
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::camera::Camera;
    use glam::Vec3;

    fn point(c: f32, alpha: f32, z: f32) -> DeepSample {
        DeepSample { color: [c; 3], alpha, z, z_back: z }
    }

    fn setup() -> (CameraFrame, ThinLens) {
        let camera = Camera::look_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0), 40f32.to_radians(), 1, 1);
        (camera.frame().unwrap(), ThinLens { focal_length: 0.05, aperture_radius: 2.0, focus_distance: 5.0, pixels_per_unit: 2e4 })
    }

    #[test]
    fn two_hundred_translucent_samples_become_the_layer_budget_with_the_same_flat_colour() {
        let samples: Vec<DeepSample> = (0..200).map(|i| point(0.01 * (i % 7) as f32, 0.02, 1.0 + i as f32 * 0.1)).collect();
        let image = DeepImage::from_counts(1, 1, &[200], samples).unwrap();
        let (frame, lens) = setup();
        let options = LayerOptions { max_layers: 4, disocclusion: false, ..Default::default() };
        let (layers, report) = image.layers(&frame, &lens, &options).unwrap();
        assert_eq!(layers.counts[0], 4);
        assert_eq!(report.budget_merged, 196);
        let (flat, _) = image.flatten();
        let (from_layers, _) = layers.front();
        assert!((flat.data[0][0] - from_layers.data[0][0]).abs() < 1e-5, "{:?} {:?}", flat.data[0], from_layers.data[0]);
    }

    #[test]
    fn a_sample_in_the_umbra_of_an_opaque_one_is_left_out_and_one_beyond_is_kept() {
        let (frame, lens) = setup();
        let near = 2.0;
        let umbra = lens.umbra_length(near, frame.pixel_footprint_radius(near));
        assert!(umbra > 0.0 && umbra.is_finite());
        let samples = vec![point(1.0, 1.0, near), point(0.5, 1.0, near + 0.5 * umbra), point(0.25, 1.0, near + 2.0 * umbra)];
        let image = DeepImage::from_counts(1, 1, &[3], samples).unwrap();
        let options = LayerOptions { disocclusion: false, ..Default::default() };
        let (layers, report) = image.layers(&frame, &lens, &options).unwrap();
        assert_eq!(layers.counts[0], 2);
        assert_eq!(report.umbra_dropped, 1);
        assert_eq!(report.umbra_share, 0.0, "behind an opaque sample nothing shows in focus");
    }
}
