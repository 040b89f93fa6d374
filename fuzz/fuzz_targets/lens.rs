//! Lens and camera settings: `LensSettings::thin_lens(&camera)` with arbitrary floats (NaN, ±inf,
//! zero, negative, subnormal, huge), the camera's frame and projections, and the artist lens.
//!
//! Every call must return `Ok` or `Err`. A lens that is accepted must be valid with a finite
//! far-field CoC, and its CoC must be a number (not NaN) at every positive depth; an accepted
//! camera must have a finite, orthonormal frame.
#![no_main]

use arbitrary::Arbitrary;
use dof::scene::{Aperture, ArtistLens, Camera, Focus, LensSettings, Vec3, validate_artist_lens};
use libfuzzer_sys::fuzz_target;

#[derive(Arbitrary, Debug)]
enum FocusIn {
    Distance(f32),
    Point([f32; 3]),
}

#[derive(Arbitrary, Debug)]
enum ApertureIn {
    FNumber(f32),
    Radius(f32),
}

/// Mirrors `LensSettings` and `Camera`, field by field.
#[derive(Arbitrary, Debug)]
struct Input {
    focus: FocusIn,
    aperture: ApertureIn,
    focal_length_mm: Option<f32>,
    sensor_height_mm: f32,
    metres_per_unit: f32,
    eye: [f32; 3],
    target: [f32; 3],
    up: Option<[f32; 3]>,
    yfov_radians: f32,
    width: u32,
    height: u32,
    /// Depths and pixel positions to evaluate the lens and camera at.
    depths: [f32; 4],
    pixel: [f32; 2],
    artist: [f32; 5],
}

fuzz_target!(|input: Input| {
    let camera = Camera {
        eye: Vec3::from(input.eye),
        target: Vec3::from(input.target),
        up: input.up.map_or(Vec3::Y, Vec3::from),
        yfov_radians: input.yfov_radians,
        width: input.width,
        height: input.height,
    };
    let settings = LensSettings {
        focus: match input.focus {
            FocusIn::Distance(d) => Focus::Distance(d),
            FocusIn::Point(p) => Focus::Point(Vec3::from(p)),
        },
        aperture: match input.aperture {
            ApertureIn::FNumber(n) => Aperture::FNumber(n),
            ApertureIn::Radius(r) => Aperture::Radius(r),
        },
        focal_length_mm: input.focal_length_mm,
        sensor_height_mm: input.sensor_height_mm,
        metres_per_unit: input.metres_per_unit,
    };

    if let Ok(frame) = camera.frame() {
        assert!(frame.forward.is_finite() && frame.right.is_finite() && frame.up.is_finite());
        // Unit axes also where the view axis or `forward × up` is so short that its squared length
        // is subnormal (finding 5 in fuzz/README.md).
        for v in [frame.forward, frame.right, frame.up] {
            assert!((v.length() - 1.0).abs() < 1e-3, "a frame axis of length {} ({frame:?})", v.length());
        }
        assert!(frame.tan_half_fov.is_finite() && frame.tan_half_fov > 0.0);
        assert!(frame.aspect.is_finite() && frame.aspect > 0.0);
        let [px, py] = input.pixel;
        let _ = frame.direction(px, py);
        let _ = frame.pixel_ray(input.width.wrapping_sub(1), input.height.wrapping_sub(1));
        let _ = frame.project(Vec3::from(input.target));
        let _ = frame.depth_of(Vec3::from(input.eye));
        let _ = frame.pixel_footprint_radius(input.depths[0]);
        let _ = frame.check_size("fuzz", input.width as u64);
        let _ = frame.pixels();
    }

    let _ = settings.focal_length_mm(input.sensor_height_mm).thin_lens(&camera);
    let _ = settings.focused_on(Vec3::from(input.target)).thin_lens(&camera);
    if let Ok(lens) = settings.thin_lens(&camera) {
        assert!(lens.is_valid(), "an accepted lens is valid: {lens:?}");
        let k = lens.far_limit_px();
        assert!(k.is_finite() && k >= 0.0, "far-field CoC {k} of {lens:?}");
        for z in input.depths.into_iter().chain([f32::INFINITY, f32::MIN_POSITIVE, 1.0]) {
            if z > 0.0 {
                let c = lens.coc_px(z);
                assert!(!c.is_nan() && c >= 0.0, "CoC {c} at depth {z} of {lens:?}");
            }
            let r = lens.coc_radius_px(z);
            assert!(!r.is_nan() && r >= 0.0, "CoC radius {r} at depth {z} of {lens:?}");
            let _ = lens.inverse_px(z);
            let _ = lens.umbra_length(z, input.pixel[0]);
        }
    }

    let [near_start, near_end, far_start, far_end, max_radius_px] = input.artist;
    let artist = ArtistLens { near_start, near_end, far_start, far_end, max_radius_px };
    if validate_artist_lens(&artist).is_ok() {
        for z in input.depths {
            let c = artist.coc_px(z);
            if z > 0.0 {
                assert!(!c.is_nan(), "artist CoC {c} at depth {z} of {artist:?}");
            }
        }
    }
});
