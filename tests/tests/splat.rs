//! Tiled splatting: the stiff and extreme cases on the CPU backend, each with its stated behaviour,
//! and the Vulkan backend against the CPU stage by stage.

use dof::CoreError;
use dof::backend::{Backend, CpuBackend};
use dof::layers::{Fragment, LayeredImage};
use dof::methods::splat::{Merge, SplatOptions, SplatOutput, splat};
use dof::stress::{hash, noise_with_sky, test_lens};
use dof_shaders::half::{f16_to_f32, f32_to_f16};
use dof_shaders::lens::ThinLens;
use dof_shaders::splat::MAX_RINGS;
use dof_tests::oracle::splat_stages::splat_with_stages;
use dof_tests::{assert_clean, vulkan};

fn lens(aperture_radius: f32) -> ThinLens {
    test_lens(aperture_radius)
}

fn front_colors(img: &LayeredImage) -> Vec<[f32; 3]> {
    img.front().0.data
}

fn run(img: &LayeredImage, lens: &ThinLens, o: &SplatOptions) -> SplatOutput {
    splat(&mut CpuBackend::new(), img, lens, o).unwrap()
}

fn all_finite(out: &SplatOutput) -> bool {
    out.image.data.iter().all(|p| p.iter().all(|c| c.is_finite()))
}

#[test]
fn half_conversion_round_trips_and_rounds_to_nearest() {
    for h in 0..=0xffffu32 {
        let v = f16_to_f32(h);
        if v.is_nan() {
            assert!(f16_to_f32(f32_to_f16(v)).is_nan());
        } else {
            assert_eq!(f32_to_f16(v), h, "half {h:#06x} = {v}");
        }
    }
    let mut seed = 1u32;
    for _ in 0..200_000 {
        seed = hash(seed);
        let v = f32::from_bits(seed & 0xbfff_ffff) * if seed & 1 == 0 { 1.0 } else { 1e-3 };
        if !v.is_finite() || v.abs() > 65504.0 {
            continue;
        }
        let h = f32_to_f16(v);
        let err = (f16_to_f32(h) as f64 - v as f64).abs();
        for n in [h.wrapping_sub(1) & 0xffff, (h + 1) & 0xffff] {
            let other = f16_to_f32(n) as f64;
            if other.is_finite() && (other >= 0.0) == (v >= 0.0) {
                assert!(err <= (other - v as f64).abs(), "{v} -> {} but {other} is nearer", f16_to_f32(h));
            }
        }
    }
}

/// A pinhole returns the front layer bit for bit: every tile is copied through, no list is built.
#[test]
fn pinhole_returns_the_front_exactly() {
    let img = noise_with_sky(45, 30, 3);
    let out = run(&img, &lens(0.0), &SplatOptions { merge: Merge::X4, ..Default::default() });
    assert_eq!(out.image.data, front_colors(&img));
    assert_eq!(out.report.copy_tiles, out.report.tiles);
    assert_eq!(out.report.list_entries, 0);
    assert_eq!(out.report.merged, 0, "nothing is blurred enough to merge");
}

/// CoC diameters below one pixel reproduce the input exactly (every fragment is a sharp front).
#[test]
fn sub_pixel_coc_is_exact() {
    let img = noise_with_sky(40, 33, 2);
    // Far-field CoC 0.2 * 0.0005 * 8000 / 1.95 = 0.41 px diameter; near 0.5 m: 1.2 px... keep depths far.
    let mut far = img.clone();
    far.fragments.iter_mut().for_each(|f| f.depth = f.depth.max(1.2));
    let l = lens(0.0005);
    assert!(l.coc_radius_px(1.2) < 0.5);
    let out = run(&far, &l, &SplatOptions::default());
    assert_eq!(out.image.data, front_colors(&far));
    assert_eq!(out.report.list_entries, 0);
}

/// A flat colour stays flat under any blur, merging and tile size (energy conservation and
/// normalisation); the colour is exact in half precision, so only summation rounding remains.
#[test]
fn a_flat_field_stays_flat() {
    let mut img = noise_with_sky(50, 41, 3);
    let flat = [0.25, 3.0, 1200.0];
    img.fragments.iter_mut().for_each(|f| f.color = flat);
    for (merge, tile) in [(Merge::None, 16), (Merge::X4, 16), (Merge::X2, 24), (Merge::X4, 32)] {
        let out = run(&img, &lens(0.01), &SplatOptions { merge, tile, ..Default::default() });
        assert!(out.report.list_entries > 0);
        for (i, p) in out.image.data.iter().enumerate() {
            if img.counts[i] == 0 && out.image.data[i] == [0.0; 3] {
                continue;
            }
            for c in 0..3 {
                assert!((p[c] - flat[c]).abs() <= 1e-4 * flat[c], "pixel {i}: {p:?} ({merge:?}, tile {tile})");
            }
        }
    }
}

/// NaN and infinite colours and invalid depths are dropped and counted; nothing non-finite comes out.
#[test]
fn nan_and_inf_do_not_spread() {
    let mut img = noise_with_sky(33, 33, 2);
    let bad = [
        (16 * 33 + 16, [f32::NAN, 1.0, 1.0], 3.0),
        (5 * 33 + 5, [f32::INFINITY, 1.0, 1.0], 3.0),
        (20 * 33 + 3, [1.0; 3], f32::NAN),
        (9, [1.0; 3], -2.0),
        (10, [1.0; 3], 0.0),
    ];
    for &(p, color, depth) in &bad {
        img.counts[p] = 1;
        img.fragments[p * 2] = Fragment { color, alpha: 1.0, depth };
    }
    let out = run(&img, &lens(0.02), &SplatOptions { merge: Merge::X2, ..Default::default() });
    assert!(all_finite(&out));
    assert_eq!(out.report.dropped, bad.len() as u32);
}

/// HDR beyond the half-float range keeps its energy: every fragment carries its own exponent, nothing
/// is clamped. One 10^6 pixel on black spreads to about 10^6 in total.
#[test]
fn hdr_beyond_half_range_keeps_its_energy() {
    let mut img = LayeredImage::new(48, 48, 1).unwrap();
    for y in 0..48 {
        for x in 0..48 {
            let c = if (x, y) == (24, 24) { [1e6, 2e5, 7.0] } else { [0.0; 3] };
            img.push(x, y, Fragment { color: c, alpha: 1.0, depth: 5.0 }).unwrap();
        }
    }
    let out = run(&img, &lens(0.05), &SplatOptions::default());
    assert_eq!(out.report.clamped, 0);
    let total: f64 = out.image.data.iter().map(|p| p[0] as f64).sum();
    assert!((total / 1e6 - 1.0).abs() < 0.02, "energy {total}");
    assert!(out.image.get(24, 24)[0] < 1e6 / 10.0, "the highlight was spread");
}

/// 1x1 and sizes that are not multiples of the tile are covered to the last pixel; a lone blurred
/// pixel keeps its colour (to half precision).
#[test]
fn tiny_and_ragged_sizes() {
    let mut one = LayeredImage::new(1, 1, 1).unwrap();
    one.push(0, 0, Fragment { color: [0.5, 2.0, 7.0], alpha: 1.0, depth: 0.7 }).unwrap();
    let out = run(&one, &lens(0.02), &SplatOptions { merge: Merge::X4, ..Default::default() });
    for c in 0..3 {
        assert!((out.image.data[0][c] - one.fragments[0].color[c]).abs() <= 1e-3 * one.fragments[0].color[c]);
    }
    for (w, h) in [(17, 5), (33, 47), (3, 70)] {
        let img = noise_with_sky(w, h, 2);
        for tile in [16, 24, 32] {
            let out = run(&img, &lens(0.01), &SplatOptions { tile, ..Default::default() });
            assert!(all_finite(&out) && out.image.data.len() == (w * h) as usize);
            assert!(out.image.data.iter().zip(&img.counts).all(|(p, &n)| n == 0 || p.iter().any(|&c| c > 0.0)));
        }
    }
}

/// The tile size changes how work is split, not what a pixel sees: with distinct depths every pixel
/// blends the same fragments in the same order, so the images are identical.
#[test]
fn tile_sizes_give_the_same_image() {
    let mut img = noise_with_sky(70, 50, 3);
    // Distinct depths: the sky's fragments (all at +inf, a tie whose order follows the binning and
    // so the tile size) moved to distinct far depths.
    img.fragments.iter_mut().enumerate().filter(|(_, f)| f.depth.is_infinite()).for_each(|(i, f)| f.depth = 1e6 + i as f32);
    let base = run(&img, &lens(0.01), &SplatOptions::default());
    for tile in [24, 32] {
        let other = run(&img, &lens(0.01), &SplatOptions { tile, ..Default::default() });
        assert_eq!(other.image, base.image, "tile {tile}");
    }
}

/// All fragments at one depth: ties sort by binning order, which is deterministic; two runs agree bit
/// for bit.
#[test]
fn equal_depths_are_deterministic() {
    let mut img = noise_with_sky(40, 40, 1);
    img.fragments.iter_mut().for_each(|f| f.depth = 0.9);
    let a = run(&img, &lens(0.01), &SplatOptions::default());
    let b = run(&img, &lens(0.01), &SplatOptions::default());
    assert_eq!(a.image, b.image);
    assert!(a.report.list_entries > 0);
}

/// Rings follow the largest CoC present, not the configured maximum; a CoC beyond the last ring is
/// capped (counted), never an error.
#[test]
fn rings_follow_the_largest_coc_and_cap_beyond() {
    let mut img = noise_with_sky(64, 64, 1);
    // Near field only: at 0.5 m the CoC radius is 1.5·K with K = 2·a·f/(z_f − f)·8000 = 410·a.
    img.fragments.iter_mut().for_each(|f| f.depth = 0.5);
    let r_for = |a: f32| lens(a).coc_radius_px(0.5) + 0.5;
    for (a, rings) in [(0.01, 1), (0.038, 2), (0.065, 3)] {
        let out = run(&img, &lens(a), &SplatOptions::default());
        assert_eq!(out.report.plan.as_ref().unwrap().rings, rings, "aperture {a}: radius {}", r_for(a));
        assert_eq!(out.report.capped, 0);
    }
    let huge = run(&img, &lens(0.2), &SplatOptions::default());
    assert_eq!(huge.report.plan.as_ref().unwrap().rings, MAX_RINGS);
    assert!(huge.report.capped > 0 && all_finite(&huge));
    let capped = run(&img, &lens(0.2), &SplatOptions { max_radius: Some(10.0), ..Default::default() });
    assert_eq!(capped.report.plan.as_ref().unwrap().rings, 1);
    assert!(capped.report.capped > 0 && all_finite(&capped));
}

/// What the report says adds up: list entries, sort classes and merging counts.
#[test]
fn the_report_adds_up() {
    let mut img = noise_with_sky(80, 48, 3);
    // Smooth colours, so that blocks merge.
    img.fragments.iter_mut().enumerate().for_each(|(i, f)| {
        f.color = [1.0 + (i / 400) as f32 * 0.01, 0.5, 0.25];
        f.depth = 4.0 * (1 + i % 3) as f32;
    });
    let out = run(&img, &lens(0.03), &SplatOptions { merge: Merge::X4, ..Default::default() });
    let r = &out.report;
    assert_eq!(r.list_entries, r.list_lengths.iter().map(|&n| n as u64).sum::<u64>());
    let nonempty = r.list_lengths.iter().filter(|&&n| n > 0).count() as u32;
    assert_eq!(r.sort.class_counts.iter().sum::<u32>() + r.sort.global_lists, nonempty);
    assert!(r.merged > 0 && r.merged_inputs == 4 * r.merged);
    assert!(r.list_capacity >= r.list_entries);
    assert_eq!(r.input_fragments, Some(img.counts.iter().map(|&n| n as u64).sum::<u64>()));
    assert!(r.summary().contains("sort classes used"));
}

#[test]
fn bad_input_is_an_error() {
    let img = noise_with_sky(20, 20, 2);
    let mut cpu = CpuBackend::new();
    let o = SplatOptions::default();
    assert!(matches!(splat(&mut cpu, &img, &lens(-1.0), &o), Err(CoreError::InvalidLens(_))));
    assert!(matches!(splat(&mut cpu, &img, &ThinLens { focus_distance: 0.01, ..lens(0.01) }, &o), Err(CoreError::InvalidLens(_))));
    assert!(matches!(splat(&mut cpu, &img, &lens(0.01), &SplatOptions { tile: 20, ..o.clone() }), Err(CoreError::InvalidArgument(_))));
    assert!(matches!(
        splat(&mut cpu, &img, &lens(0.01), &SplatOptions { max_radius: Some(1000.0), ..o.clone() }),
        Err(CoreError::InvalidArgument(_))
    ));
    assert!(matches!(
        splat(&mut cpu, &img, &lens(0.01), &SplatOptions { max_radius: Some(f32::NAN), ..o.clone() }),
        Err(CoreError::InvalidArgument(_))
    ));
    assert!(matches!(
        splat(&mut cpu, &img, &lens(0.01), &SplatOptions { merge_depth_ratio: 0.5, ..o.clone() }),
        Err(CoreError::InvalidArgument(_))
    ));
    let wide = LayeredImage::new(40_000, 1, 1).unwrap();
    assert!(matches!(splat(&mut cpu, &wide, &lens(0.01), &o), Err(CoreError::TooLarge { .. })));
}

/// Every stage on Vulkan against the CPU: packed and merged cells, tile counts, the dense array, list
/// lengths, the binned and the sorted lists bit for bit; the image within float rounding.
#[test]
fn vulkan_matches_cpu_stage_by_stage() {
    let Some(mut vk) = vulkan() else { return };
    let img = noise_with_sky(61, 37, 3);
    for (merge, tile, aperture) in [(Merge::X4, 16, 0.01), (Merge::None, 24, 0.004), (Merge::X2, 32, 0.02)] {
        let o = SplatOptions { merge, tile, ..Default::default() };
        let on_vk = splat_with_stages(&mut vk, &img, &lens(aperture), &o).unwrap();
        assert_clean(&mut vk);
        let on_cpu = splat_with_stages(&mut CpuBackend::new(), &img, &lens(aperture), &o).unwrap();
        let (a, b) = (&on_vk.intermediates, &on_cpu.intermediates);
        let what = format!("{merge:?}, tile {tile}");
        for (step, (x, y)) in a.cells.iter().zip(&b.cells).enumerate() {
            assert!(x == y, "cells after step {step} differ ({what})");
        }
        assert_eq!(a.tile_count, b.tile_count, "tile counts ({what})");
        assert!(a.dense == b.dense, "dense fragments ({what})");
        assert_eq!(a.list_lengths, b.list_lengths, "list lengths ({what})");
        assert!(a.binned == b.binned, "binned lists ({what})");
        assert!(a.sorted == b.sorted, "sorted lists ({what})");
        assert!(on_cpu.report.list_entries > 0);
        for (p, q) in on_vk.image.data.iter().zip(&on_cpu.image.data) {
            for c in 0..3 {
                assert!((p[c] - q[c]).abs() <= 1e-5 * q[c].abs().max(1e-2), "{p:?} vs {q:?} ({what})");
            }
        }
        let labels: Vec<&str> = on_vk.stages.iter().map(|t| t.label.as_str()).collect();
        for stage in ["splat/pack", "splat/tile-count", "splat/bin", "splat/accumulate"] {
            assert!(labels.contains(&stage), "{stage} timed on Vulkan ({what})");
        }
        assert_eq!(vk.kind(), dof::backend::BackendKind::Vulkan);
    }
}
