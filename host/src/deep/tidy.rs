//! Tidy deep pixels, by OpenEXR's rules ("Interpreting OpenEXR Deep Pixels", Hillman 2013): sorted
//! by depth, volume samples split where another sample's front or back lies inside them, and
//! samples over the same depth range merged into one.

use rayon::prelude::*;

use super::{DeepImage, DeepSample, MAX_DEEP_SAMPLES};
use crate::error::{CoreError, Error, Result};

/// Most samples one pixel may hold once its volume samples are split: overlapping volumes split
/// each other, so `n` nested ones become up to `n²` pieces.
pub const MAX_TIDY_SAMPLES_PER_PIXEL: usize = 1 << 20;

/// What tidying changed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TidyReport {
    /// Volume samples split because other samples begin or end inside them.
    pub volumes_split: u64,
    /// Pieces those splits made (each split sample becomes two or more).
    pub pieces: u64,
    /// Samples merged into another over the same depth range (each merge removes one).
    pub merged: u64,
    /// Samples behind a pixel's first background sample (depth `+inf`), dropped: it hides them.
    pub behind_background: u64,
}

impl std::ops::Add for TidyReport {
    type Output = TidyReport;
    fn add(self, o: TidyReport) -> TidyReport {
        TidyReport {
            volumes_split: self.volumes_split + o.volumes_split,
            pieces: self.pieces + o.pieces,
            merged: self.merged + o.merged,
            behind_background: self.behind_background + o.behind_background,
        }
    }
}

impl DeepImage {
    /// The image with every pixel tidy (module docs), rows in parallel. Errors when splitting volume
    /// samples makes more than [`MAX_TIDY_SAMPLES_PER_PIXEL`] in a pixel or [`MAX_DEEP_SAMPLES`] in
    /// all.
    pub fn tidy(&self) -> Result<(DeepImage, TidyReport)> {
        let w = self.width as usize;
        let rows: Vec<Result<(Vec<u32>, Vec<DeepSample>, TidyReport)>> = (0..self.height as usize)
            .into_par_iter()
            .map(|y| {
                let mut counts = Vec::with_capacity(w);
                let mut out = Vec::new();
                let mut report = TidyReport::default();
                let mut scratch = Vec::new();
                for x in 0..w {
                    let before = out.len();
                    tidy_pixel(self.pixel(y * w + x), &mut scratch, &mut out, &mut report)
                        .map_err(|n| too_many_pieces(x, y, self.pixel(y * w + x).len(), n))?;
                    counts.push((out.len() - before) as u32);
                }
                Ok((counts, out, report))
            })
            .collect();
        let mut counts = Vec::with_capacity(self.pixels());
        let mut samples = Vec::new();
        let mut report = TidyReport::default();
        for row in rows {
            let (c, s, r) = row?;
            if (samples.len() + s.len()) as u64 > MAX_DEEP_SAMPLES {
                let size = (samples.len() + s.len()) as u64;
                return Err(Error::Core(CoreError::TooLarge { what: "tidy deep image (samples)".into(), size, limit: MAX_DEEP_SAMPLES }));
            }
            counts.extend_from_slice(&c);
            samples.extend_from_slice(&s);
            report = report + r;
        }
        Ok((DeepImage::from_counts(self.width, self.height, &counts, samples)?, report))
    }
}

fn too_many_pieces(x: usize, y: usize, n: usize, pieces: usize) -> Error {
    Error::invalid(format!(
        "deep pixel ({x}, {y}): its {n} samples overlap so much that splitting them makes more than {pieces} pieces \
         (at most {MAX_TIDY_SAMPLES_PER_PIXEL} a pixel); the file is corrupt or its volumes are not meant to overlap"
    ))
}

/// Appends pixel `input`'s tidy samples to `out`; `scratch` is working space. Errs with the number
/// of pieces reached when splitting makes too many.
fn tidy_pixel(
    input: &[DeepSample],
    scratch: &mut Vec<DeepSample>,
    out: &mut Vec<DeepSample>,
    report: &mut TidyReport,
) -> std::result::Result<(), usize> {
    scratch.clear();
    scratch.extend(input.iter().map(|s| DeepSample { z_back: if s.z_back >= s.z { s.z_back } else { s.z }, ..*s }));
    scratch.sort_by(|a, b| a.z.total_cmp(&b.z).then(a.z_back.total_cmp(&b.z_back)));
    // The first background ends the pixel.
    if let Some(b) = scratch.iter().position(|s| s.z == f32::INFINITY) {
        report.behind_background += (scratch.len() - b - 1) as u64;
        scratch.truncate(b + 1);
    }
    if scratch.iter().any(DeepSample::is_volume) {
        split_volumes(scratch, report)?;
    }
    // Merge runs over the same depth range.
    let mut i = 0;
    while i < scratch.len() {
        let mut j = i + 1;
        while j < scratch.len() && scratch[j].z == scratch[i].z && scratch[j].z_back == scratch[i].z_back {
            j += 1;
        }
        out.push(if j - i == 1 { scratch[i] } else { merge_coincident(&scratch[i..j]) });
        report.merged += (j - i - 1) as u64;
        i = j;
    }
    Ok(())
}

/// Splits every volume sample of the sorted `samples` at each other sample's front and back depth
/// that lies strictly inside it, and sorts the pieces.
fn split_volumes(samples: &mut Vec<DeepSample>, report: &mut TidyReport) -> std::result::Result<(), usize> {
    let mut cuts: Vec<f32> = samples.iter().flat_map(|s| [s.z, s.z_back]).filter(|z| z.is_finite()).collect();
    cuts.sort_by(f32::total_cmp);
    cuts.dedup();
    let mut pieces = Vec::with_capacity(samples.len());
    for s in samples.iter() {
        if !s.is_volume() {
            pieces.push(*s);
            continue;
        }
        let first = cuts.partition_point(|&c| c <= s.z);
        let last = cuts.partition_point(|&c| c < s.z_back);
        if first >= last {
            pieces.push(*s);
            continue;
        }
        report.volumes_split += 1;
        let mut front = s.z;
        for &cut in cuts[first..last].iter().chain(std::iter::once(&s.z_back)) {
            pieces.push(piece(s, front, cut));
            report.pieces += 1;
            front = cut;
            if pieces.len() > super::tidy::MAX_TIDY_SAMPLES_PER_PIXEL {
                return Err(pieces.len());
            }
        }
    }
    pieces.sort_by(|a, b| a.z.total_cmp(&b.z).then(a.z_back.total_cmp(&b.z_back)));
    *samples = pieces;
    Ok(())
}

/// The part of volume sample `s` between depths `front` and `back`: a homogeneous medium keeps
/// `(1 − alpha)^f` of the light over the fraction `f` of its depth, and its colour in proportion
/// to the coverage.
fn piece(s: &DeepSample, front: f32, back: f32) -> DeepSample {
    let f = ((back as f64 - front as f64) / (s.z_back as f64 - s.z as f64)).clamp(0.0, 1.0);
    let a = s.alpha as f64;
    let (alpha, scale) = if a >= 1.0 {
        (1.0, 1.0)
    } else if a <= 0.0 {
        (0.0, f)
    } else {
        let alpha = -(f * (-a).ln_1p()).exp_m1();
        (alpha, alpha / a)
    };
    DeepSample { color: s.color.map(|c| (c as f64 * scale) as f32), alpha: alpha as f32, z: front, z_back: back }
}

/// Samples over one depth range as one (OpenEXR's rule): opaque samples hide the rest and average;
/// otherwise the optical depths `-ln(1 − alpha)` add, and each colour weighs by its own.
fn merge_coincident(group: &[DeepSample]) -> DeepSample {
    let opaque: Vec<&DeepSample> = group.iter().filter(|s| s.alpha >= 1.0).collect();
    let (color, alpha) = if !opaque.is_empty() {
        let n = opaque.len() as f64;
        let color = [0, 1, 2].map(|k| (opaque.iter().map(|s| s.color[k] as f64).sum::<f64>() / n) as f32);
        (color, 1.0)
    } else {
        let (mut u, mut v) = (0.0f64, [0.0f64; 3]);
        for s in group {
            let a = s.alpha as f64;
            let ui = -(-a).ln_1p();
            // u/alpha tends to 1 as alpha tends to 0: light that hides nothing keeps its colour.
            let weight = if a > 0.0 { ui / a } else { 1.0 };
            u += ui;
            for k in 0..3 {
                v[k] += s.color[k] as f64 * weight;
            }
        }
        let alpha = -(-u).exp_m1();
        let scale = if u > 0.0 { alpha / u } else { 1.0 };
        (v.map(|c| (c * scale) as f32), alpha as f32)
    };
    DeepSample { color, alpha, z: group[0].z, z_back: group[0].z_back }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(c: f32, alpha: f32, z: f32) -> DeepSample {
        DeepSample { color: [c; 3], alpha, z, z_back: z }
    }

    fn tidy_one(samples: &[DeepSample]) -> (Vec<DeepSample>, TidyReport) {
        let image = DeepImage::from_counts(1, 1, &[samples.len() as u32], samples.to_vec()).unwrap();
        let (t, r) = image.tidy().unwrap();
        (t.samples, r)
    }

    #[test]
    fn sorts_and_merges_coincident_samples() {
        let (s, r) = tidy_one(&[point(0.5, 0.5, 3.0), point(0.2, 0.5, 1.0), point(0.5, 0.5, 3.0)]);
        assert_eq!(s.len(), 2);
        assert_eq!(s[0].z, 1.0);
        assert_eq!(r.merged, 1);
        // Two halves over the same range hide three quarters, and keep their colour ratio.
        assert!((s[1].alpha - 0.75).abs() < 1e-6, "{:?}", s[1]);
        assert!((s[1].color[0] - 0.75).abs() < 1e-6, "{:?}", s[1]);
    }

    #[test]
    fn opaque_coincident_samples_average() {
        let (s, _) = tidy_one(&[point(1.0, 1.0, 2.0), point(3.0, 1.0, 2.0), point(9.0, 0.5, 2.0)]);
        assert_eq!(s, vec![point(2.0, 1.0, 2.0)]);
    }

    #[test]
    fn a_volume_splits_at_a_sample_inside_it_and_keeps_its_transmission() {
        let volume = DeepSample { color: [0.75; 3], alpha: 0.75, z: 1.0, z_back: 3.0 };
        let (s, r) = tidy_one(&[volume, point(1.0, 1.0, 2.0)]);
        assert_eq!(r.volumes_split, 1);
        assert_eq!(s.len(), 3);
        assert_eq!((s[0].z, s[0].z_back), (1.0, 2.0));
        // Half the depth of a medium that lets a quarter through lets half through.
        assert!((s[0].alpha - 0.5).abs() < 1e-6 && (s[0].color[0] - 0.5).abs() < 1e-6, "{:?}", s[0]);
        // The pieces composite back to the whole volume.
        let back = s.iter().find(|p| p.z == 2.0 && p.z_back == 3.0).unwrap();
        assert!((1.0 - (1.0 - s[0].alpha) * (1.0 - back.alpha) - 0.75).abs() < 1e-6);
    }

    #[test]
    fn the_first_background_ends_a_pixel() {
        let (s, r) = tidy_one(&[point(1.0, 1.0, f32::INFINITY), point(0.5, 0.5, 1.0), point(2.0, 1.0, f32::INFINITY)]);
        assert_eq!(s.len(), 2);
        assert_eq!(r.behind_background, 1);
    }

    #[test]
    fn flatten_composites_front_to_back() {
        let image = DeepImage::from_counts(2, 1, &[2, 0], vec![point(0.25, 0.5, 1.0), point(1.0, 1.0, 4.0)]).unwrap();
        let (rgb, depth) = image.flatten();
        assert_eq!(rgb.data[0], [0.75; 3]);
        assert_eq!(depth, vec![1.0, f32::INFINITY]);
        assert_eq!(rgb.data[1], [0.0; 3]);
    }
}
