//! The textures as the shading kernel samples them: each image with its mip chain, packed as half
//! floats (`dof_shaders::raster::texture`). Built at upload from the scene's linear RGBA images,
//! which stay as loaded.

use crate::scene::mesh::pack_halves;
use dof_shaders::raster::mesh::{LEVELS_MASK, LEVELS_SHIFT, TEXEL_WORDS, TextureInfo};
use rayon::prelude::*;
use std::collections::HashMap;

/// Mip levels of a `width` x `height` image: halving (rounding down) to 1x1.
pub fn level_count(width: u32, height: u32) -> u32 {
    32 - width.max(height).max(1).leading_zeros()
}

/// For each texel of a `to`-texel row, the texels of a `from`-texel row it averages and their
/// weights: the share of its interval `[i·from/to, (i+1)·from/to)` each covers (an exact box).
fn box_weights(from: u32, to: u32) -> Vec<Vec<(u32, f32)>> {
    let scale = from as f64 / to as f64;
    (0..to)
        .map(|i| {
            let (a, b) = (i as f64 * scale, (i + 1) as f64 * scale);
            let first = a.floor() as u32;
            let last = (b.ceil() as u32).min(from);
            (first..last)
                .map(|k| {
                    let cover = (b.min(k as f64 + 1.0) - a.max(k as f64)).max(0.0);
                    (k, (cover / scale) as f32)
                })
                .filter(|&(_, w)| w > 0.0)
                .collect()
        })
        .collect()
}

/// The next level of `level` (`width` x `height`, row-major): each texel the area average of the
/// texels it covers, in linear space.
fn downsample(level: &[[f32; 4]], width: u32, height: u32) -> (Vec<[f32; 4]>, u32, u32) {
    let (w, h) = ((width >> 1).max(1), (height >> 1).max(1));
    let (across, down) = (box_weights(width, w), box_weights(height, h));
    // Rows first, then columns: the box is separable.
    let rows: Vec<[f32; 4]> = (0..height as usize)
        .into_par_iter()
        .flat_map_iter(|y| {
            let row = &level[y * width as usize..(y + 1) * width as usize];
            across.iter().map(move |taps| weighted(taps.iter().map(|&(k, wt)| (row[k as usize], wt))))
        })
        .collect();
    let out: Vec<[f32; 4]> = (0..h as usize)
        .into_par_iter()
        .flat_map_iter(|y| {
            let rows = &rows;
            let taps = &down[y];
            (0..w as usize).map(move |x| weighted(taps.iter().map(|&(k, wt)| (rows[k as usize * w as usize + x], wt))))
        })
        .collect();
    (out, w, h)
}

fn weighted(taps: impl Iterator<Item = ([f32; 4], f32)>) -> [f32; 4] {
    let mut sum = [0.0f32; 4];
    for (t, w) in taps {
        for c in 0..4 {
            sum[c] += t[c] * w;
        }
    }
    sum
}

/// The texture table and texel words the kernel samples, for the scene's `textures` over its
/// linear `texels`: every image (textures sharing an image share its chain) followed by its mips.
/// The textures must lie inside the texels (as `RasterScene::validate` checks).
pub fn sampled_textures(textures: &[TextureInfo], texels: &[[f32; 4]]) -> (Vec<TextureInfo>, Vec<u32>) {
    let mut chains: HashMap<(u32, u32, u32), u32> = HashMap::new();
    let mut words: Vec<u32> = Vec::new();
    let table = textures
        .iter()
        .map(|t| {
            let offset = *chains.entry((t.offset, t.width, t.height)).or_insert_with(|| {
                let start = (words.len() / TEXEL_WORDS as usize) as u32;
                let base = &texels[t.offset as usize..t.offset as usize + t.width as usize * t.height as usize];
                words.extend(base.iter().flat_map(|&x| pack_halves(x)));
                let (mut level, mut w, mut h) = (base.to_vec(), t.width, t.height);
                while w > 1 || h > 1 {
                    (level, w, h) = downsample(&level, w, h);
                    words.extend(level.iter().flat_map(|&x| pack_halves(x)));
                }
                start
            });
            let levels = level_count(t.width, t.height) & LEVELS_MASK;
            TextureInfo { offset, sampler: (t.sampler & !(LEVELS_MASK << LEVELS_SHIFT)) | (levels << LEVELS_SHIFT), ..*t }
        })
        .collect();
    (table, words)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_level_is_the_area_average_of_the_one_above() {
        // 3x2 → 1x1: every texel weighs the same.
        let level: Vec<[f32; 4]> = (0..6).map(|i| [i as f32, 1.0, 0.0, 1.0]).collect();
        let (next, w, h) = downsample(&level, 3, 2);
        assert_eq!((w, h), (1, 1));
        assert!((next[0][0] - 2.5).abs() < 1e-6 && (next[0][1] - 1.0).abs() < 1e-6, "{:?}", next[0]);
        // 5 → 2: each output covers two and a half inputs.
        let wts = box_weights(5, 2);
        assert_eq!(wts[0], vec![(0, 0.4), (1, 0.4), (2, 0.2)]);
        assert_eq!(wts[1], vec![(2, 0.2), (3, 0.4), (4, 0.4)]);
        // Weights of every output sum to one, for every size pair a chain meets.
        for from in 1..70u32 {
            for taps in box_weights(from, (from / 2).max(1)) {
                assert!((taps.iter().map(|t| t.1).sum::<f32>() - 1.0).abs() < 1e-5, "{from}");
            }
        }
    }

    #[test]
    fn chains_are_laid_out_as_the_kernel_walks_them() {
        assert_eq!((level_count(1, 1), level_count(4, 4), level_count(5, 3), level_count(1024, 1)), (1, 3, 3, 11));
        let texels = vec![[0.5f32, 0.25, 1.0, 1.0]; 4 * 2 + 1];
        let tex = |offset, width, height| TextureInfo { offset, width, height, sampler: 0 };
        let (table, words) = sampled_textures(&[tex(0, 4, 2), tex(8, 1, 1), tex(0, 4, 2)], &texels);
        assert_eq!(words.len(), (11 + 1) * TEXEL_WORDS as usize);
        assert_eq!(table[0].offset, 0);
        assert_eq!(table[1].offset, 11);
        assert_eq!(table[2].offset, 0, "textures of one image share its chain");
        assert_eq!(table[0].sampler >> LEVELS_SHIFT, 3);
        assert_eq!(words[0], 0x3400_3800, "0.5 and 0.25 as halves");
    }
}
