//! The lens models of `dof_shaders::lens`: thin-lens CoC, its inverse (Schedl and Wimmer 2012, eq. 5-8), the umbra
//! length (Franke et al. 2018, §4.1) and the artist model (de Rousiers and Pettineo).

use dof_shaders::lens::{ArtistLens, ThinLens};
use proptest::prelude::*;

/// Valid thin lenses: f from 5 mm to 0.5 m, focus 1.001 to 200 focal lengths, aperture radius up to
/// 0.2 m, 100 to 100000 pixels per scene unit.
fn lenses() -> impl Strategy<Value = ThinLens> {
    (0.005f32..0.5, 0.001f32..200.0, 0.0f32..0.2, 100.0f32..1e5).prop_map(|(f, k, r, ppu)| ThinLens {
        focal_length: f,
        aperture_radius: r,
        focus_distance: f * (1.0 + k),
        pixels_per_unit: ppu,
    })
}

/// Valid lenses with a visible aperture (the far limit is at least a tenth of a pixel).
fn open_lenses() -> impl Strategy<Value = ThinLens> {
    lenses().prop_filter("aperture too small", |l| l.far_limit_px() > 0.1)
}

fn rel_err(a: f32, b: f32) -> f64 {
    ((a as f64 - b as f64) / b as f64).abs()
}

proptest! {
    #[test]
    fn generated_lenses_are_valid(l in lenses()) {
        prop_assert!(l.is_valid());
    }

    /// inverse(coc(z)) returns z on the near branch.
    #[test]
    fn inverse_undoes_the_near_branch(l in open_lenses(), t in 0.001f32..0.999) {
        let z = l.focus_distance * t;
        let c = l.coc_px(z);
        let (near, far) = l.inverse_px(c);
        prop_assert!(rel_err(near, z) < 1e-5, "z {} -> c {} -> near {}", z, c, near);
        prop_assert!(far >= l.focus_distance);
    }

    /// inverse(coc(z)) returns z on the far branch, inside eq. 8's bound (c < far limit). The far
    /// branch loses precision like c/(K − c) as z grows; depths up to 50 focus distances are checked
    /// against that conditioning.
    #[test]
    fn inverse_undoes_the_far_branch(l in open_lenses(), t in 1.001f32..50.0) {
        let z = l.focus_distance * t;
        let c = l.coc_px(z);
        let k = l.far_limit_px();
        prop_assert!(c < k, "eq. 8: c {} must stay below the far limit {}", c, k);
        let (near, far) = l.inverse_px(c);
        let condition = 1.0 + (c / (k - c)) as f64;
        prop_assert!(rel_err(far, z) < 2e-6 * condition.max(10.0), "z {} -> c {} -> far {} (condition {})", z, c, far, condition);
        prop_assert!(near <= l.focus_distance);
    }

    /// coc(inverse(c)) returns c on both branches; beyond the bound the far depth is infinite.
    #[test]
    fn forward_undoes_the_inverse(l in open_lenses(), s in 0.0f32..4.0) {
        let k = l.far_limit_px();
        let c = k * s;
        let (near, far) = l.inverse_px(c);
        prop_assert!((l.coc_px(near) - c).abs() <= 1e-4 * c.max(1.0));
        if c < k * 0.999 {
            prop_assert!((l.coc_px(far) - c).abs() <= 1e-3 * c.max(1.0), "c {} far {} coc {}", c, far, l.coc_px(far));
        } else if c >= k {
            prop_assert_eq!(far, f32::INFINITY);
        }
    }

    /// In front of the focus plane the CoC shrinks towards it; behind it the CoC grows.
    #[test]
    fn coc_is_monotonic_on_both_sides(l in lenses(), a in 0.001f32..1.0, b in 0.001f32..1.0, g in 1.0f32..1e4, h in 1.0f32..1e4) {
        let zf = l.focus_distance;
        let (n1, n2) = (zf * a.min(b), zf * a.max(b));
        prop_assert!(l.coc_px(n1) >= l.coc_px(n2));
        prop_assert!(l.signed_coc_px(n1) <= 0.0 && l.signed_coc_px(n2) <= 0.0);
        let (f1, f2) = (zf * g.min(h), zf * g.max(h));
        prop_assert!(l.coc_px(f1) <= l.coc_px(f2));
        prop_assert!(l.signed_coc_px(f1) >= 0.0);
        prop_assert_eq!(l.coc_px(zf), 0.0);
    }

    /// Behind the focus plane the CoC approaches the far limit A·f/(z_f − f) from below, which for
    /// A = f/N is f²/(N(z_f − f)); at z = inf it is the limit.
    #[test]
    fn far_field_asymptote(l in open_lenses(), t in 1.0f32..1e6) {
        let k = l.far_limit_px();
        let zf = l.focus_distance;
        let n = l.focal_length / (2.0 * l.aperture_radius);
        let photographic = l.focal_length * l.focal_length / (n * (zf - l.focal_length)) * l.pixels_per_unit;
        prop_assert!(rel_err(k, photographic) < 1e-5);
        let z = zf * t;
        let c = l.coc_px(z);
        prop_assert!(c <= k * (1.0 + 1e-6));
        // K − c(z) = K·z_f/z.
        prop_assert!((k - c) as f64 <= (k as f64) * (zf as f64 / z as f64) * (1.0 + 1e-3) + k as f64 * 1e-6);
        prop_assert_eq!(l.coc_px(f32::INFINITY), k);
        prop_assert!(rel_err(l.coc_px(1e30), k) < 1e-6);
    }

    /// As the focus distance approaches the focal length the CoC grows without bound and stays a
    /// number for every valid depth.
    #[test]
    fn focus_towards_focal_length(f in 0.005f32..0.5, r in 0.001f32..0.2, ppu in 100.0f32..1e5, z_over_f in 0.01f32..1e4) {
        let z = f * z_over_f;
        let mut previous = 0.0f32;
        for e in 1..=6 {
            let zf = f * (1.0 + 10f32.powi(-e));
            let l = ThinLens { focal_length: f, aperture_radius: r, focus_distance: zf, pixels_per_unit: ppu };
            prop_assert!(l.is_valid());
            let c = l.coc_px(z);
            prop_assert!(!c.is_nan(), "NaN at focus {} depth {}", zf, z);
            prop_assert!(c >= 0.0);
            if (z - zf).abs() > 0.01 * zf && (z - f).abs() > 0.02 * f {
                prop_assert!(c >= previous, "CoC must grow as z_f -> f: {} then {}", previous, c);
                previous = c;
            }
            prop_assert!(!l.far_limit_px().is_nan() && !l.coc_px(f32::INFINITY).is_nan());
            prop_assert!(!l.coc_px(f32::MIN_POSITIVE).is_nan() && !l.coc_px(f32::MAX).is_nan());
        }
        // Unbounded: at 1e-6 the far limit alone is a million times the one at 1e-0.
        let wide = ThinLens { focal_length: f, aperture_radius: r, focus_distance: 2.0 * f, pixels_per_unit: ppu };
        let close = ThinLens { focus_distance: f * (1.0 + 1e-6), ..wide };
        prop_assert!(close.far_limit_px() > 1e5 * wide.far_limit_px());
    }

    /// The CoC is proportional to the aperture and vanishes with it.
    #[test]
    fn aperture_towards_zero(l in open_lenses(), t in 0.01f32..100.0) {
        let z = l.focus_distance * t;
        let mut previous = f32::INFINITY;
        for e in 0..8 {
            let small = ThinLens { aperture_radius: l.aperture_radius * 10f32.powi(-e), ..l };
            let c = small.coc_px(z);
            prop_assert!(c <= previous);
            previous = c;
        }
        prop_assert!(previous <= l.coc_px(z) * 1.001e-7 + f32::MIN_POSITIVE);
        let pinhole = ThinLens { aperture_radius: 0.0, ..l };
        for z in [f32::MIN_POSITIVE, 1e-30, z, 1e30, f32::MAX, f32::INFINITY] {
            prop_assert_eq!(pinhole.coc_px(z), 0.0);
        }
    }

    /// Every positive depth, tiny to infinite, gives a number; nothing positive gives NaN.
    #[test]
    fn valid_depths_never_give_nan(l in lenses(), bits in 1u32..0x7f80_0000) {
        let z = f32::from_bits(bits);
        let c = l.coc_px(z);
        prop_assert!(c >= 0.0, "z {} gave {}", z, c);
        prop_assert!(!l.signed_coc_px(z).is_nan());
    }

    /// Depth zero, negative or NaN has no CoC: NaN, never a panic.
    #[test]
    fn invalid_depths_give_nan(l in lenses(), z in -1e30f32..=0.0) {
        prop_assert!(l.coc_px(z).is_nan());
        prop_assert!(l.coc_px(f32::NAN).is_nan());
        prop_assert!(l.umbra_length(z, 0.001).is_nan());
    }

    /// The umbra never closes once the footprint is as wide as the aperture; it is empty for a
    /// point; otherwise it grows with depth and with the footprint, and matches the cone geometry.
    #[test]
    fn umbra_length(l in open_lenses(), a in 0.01f32..100.0, b in 0.01f32..100.0, s in 0.0f32..0.999, s2 in 0.0f32..0.999) {
        let big_r = l.aperture_radius;
        let (z1, z2) = (a.min(b), a.max(b));
        prop_assert_eq!(l.umbra_length(z1, big_r), f32::INFINITY);
        prop_assert_eq!(l.umbra_length(z1, big_r * 1.5), f32::INFINITY);
        prop_assert_eq!(l.umbra_length(z1, 0.0), 0.0);
        let r = big_r * s;
        prop_assert!(l.umbra_length(z1, r) <= l.umbra_length(z2, r));
        let r2 = big_r * s2;
        if r <= r2 {
            prop_assert!(l.umbra_length(z1, r) <= l.umbra_length(z1, r2));
        }
        // The rim ray from the lens edge through the footprint edge meets the axis at the umbra's end.
        let u = l.umbra_length(z1, r) as f64;
        if r > 0.0 {
            let x_at_footprint = big_r as f64 * u / (z1 as f64 + u);
            prop_assert!((x_at_footprint - r as f64).abs() <= 1e-4 * big_r as f64, "{} vs {}", x_at_footprint, r);
        }
    }

    /// The artist model: full blur up to near_end, a linear ramp to 0 at near_start, sharp until
    /// far_start, a linear ramp to full at far_end, full beyond; negative in front.
    #[test]
    fn artist_model_ramps(
        near_end in 0.1f32..5.0, near_len in 0.0f32..5.0, sharp in 0.0f32..5.0, far_len in 0.0f32..20.0,
        max_r in 0.0f32..64.0, t in 0.0f32..1.0, a in 0.0f32..50.0, b in 0.0f32..50.0,
    ) {
        let near_start = near_end + near_len;
        let far_start = near_start + sharp;
        let far_end = far_start + far_len;
        let lens = ArtistLens { near_start, near_end, far_start, far_end, max_radius_px: max_r };
        prop_assert!(lens.is_valid());
        let full = 2.0 * max_r;
        prop_assert_eq!(lens.signed_coc_px(near_end * 0.5), -full);
        prop_assert_eq!(lens.coc_px(far_end + 1.0), full);
        prop_assert_eq!(lens.coc_px(f32::INFINITY), full);
        prop_assert_eq!(lens.coc_px(near_start + sharp * t), 0.0);
        if near_len > 1e-3 {
            let z = near_start - near_len * t;
            prop_assert!((lens.signed_coc_px(z) + full * t).abs() <= 1e-3 * full.max(1.0));
        }
        if far_len > 1e-3 {
            let z = far_start + far_len * t;
            prop_assert!((lens.signed_coc_px(z) - full * t).abs() <= 1e-3 * full.max(1.0));
        }
        // Monotonic on each side, bounded by the maximum.
        let (z1, z2) = (0.01 + a.min(b), 0.01 + a.max(b));
        let (c1, c2) = (lens.signed_coc_px(z1), lens.signed_coc_px(z2));
        prop_assert!(c1 <= c2);
        prop_assert!(c1.abs() <= full && c2.abs() <= full);
        prop_assert!(lens.coc_px(0.0).is_nan() && lens.coc_px(-1.0).is_nan() && lens.coc_px(f32::NAN).is_nan());
    }
}

#[test]
fn inverse_outside_the_bound_and_degenerate_inputs() {
    let l = ThinLens { focal_length: 0.05, aperture_radius: 0.0125, focus_distance: 2.0, pixels_per_unit: 45_000.0 };
    let k = l.far_limit_px();
    assert_eq!(l.inverse_px(k).1, f32::INFINITY);
    assert_eq!(l.inverse_px(2.0 * k).1, f32::INFINITY);
    assert!(l.inverse_px(2.0 * k).0 > 0.0);
    assert_eq!(l.inverse_px(0.0), (2.0, 2.0));
    assert_eq!(l.inverse_px(f32::INFINITY), (0.0, f32::INFINITY));
    let (a, b) = l.inverse_px(f32::NAN);
    assert!(a.is_nan() && b.is_nan());
    let (a, b) = l.inverse_px(-1.0);
    assert!(a.is_nan() && b.is_nan());
    let pinhole = ThinLens { aperture_radius: 0.0, ..l };
    assert_eq!(pinhole.inverse_px(5.0), (0.0, f32::INFINITY));
    assert_eq!(pinhole.umbra_length(3.0, 1e-4), f32::INFINITY);
    assert_eq!(pinhole.umbra_length(3.0, 0.0), 0.0);
}

#[test]
fn invalid_lenses_are_flagged() {
    let ok = ThinLens { focal_length: 0.05, aperture_radius: 0.01, focus_distance: 2.0, pixels_per_unit: 1e4 };
    assert!(ok.is_valid());
    for bad in [
        ThinLens { focus_distance: 0.05, ..ok },
        ThinLens { focus_distance: 0.01, ..ok },
        ThinLens { aperture_radius: -0.01, ..ok },
        ThinLens { aperture_radius: f32::NAN, ..ok },
        ThinLens { pixels_per_unit: 0.0, ..ok },
        ThinLens { focal_length: f32::INFINITY, ..ok },
    ] {
        assert!(!bad.is_valid(), "{bad:?}");
        // Still no panic.
        let _ = (bad.coc_px(1.0), bad.inverse_px(1.0), bad.umbra_length(1.0, 0.001));
    }
    let artist = ArtistLens { near_start: 1.0, near_end: 2.0, far_start: 3.0, far_end: 4.0, max_radius_px: 4.0 };
    assert!(!artist.is_valid());
    assert!(!ArtistLens { near_start: 2.0, near_end: 1.0, far_start: 1.5, far_end: 4.0, max_radius_px: 4.0 }.is_valid());
    assert!(!ArtistLens { near_start: 2.0, near_end: 1.0, far_start: 3.0, far_end: 4.0, max_radius_px: -1.0 }.is_valid());
}
