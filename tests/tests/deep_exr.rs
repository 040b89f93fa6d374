//! Deep OpenEXR input, on files written by OpenEXR's own library (`tools/make_deep_fixtures.py`,
//! in `tests/data/deep/`): every layout and compression reads as the same scene given as flat layers,
//! volume samples and coincident samples are made tidy by OpenEXR's rules, in focus every method
//! returns the flattened composite, and damaged files are refused without a panic.

use std::path::{Path, PathBuf};

use dof::backend::CpuBackend;
use dof::deep::DeepImage;
use dof::frame::{LayerOptions, METHODS, MethodOptions};
use dof::io::{DeepReport, read_deep_exr, read_layered_exr};
use dof::layers::LayeredImage;
use dof::methods::one_shot::one_shot;
use dof::scene::{Camera, CameraFrame, ThinLens, Vec3};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("data/deep").join(name)
}

fn read(name: &str) -> (DeepImage, DeepReport) {
    read_deep_exr(&[fixture(name)]).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn frame(image: &DeepImage) -> CameraFrame {
    Camera::look_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0), 40f32.to_radians(), image.width, image.height).frame().unwrap()
}

fn lens(aperture_radius: f32) -> ThinLens {
    ThinLens { focal_length: 0.05, aperture_radius, focus_distance: 4.0, pixels_per_unit: 800.0 }
}

/// Every sample kept: what the flat layers hold.
fn all_kept(image: &DeepImage) -> LayeredImage {
    let options = LayerOptions { max_layers: 3, umbra_threshold: false, disocclusion: false, ..Default::default() };
    image.layers(&frame(image), &lens(0.01), &options).unwrap().0
}

#[test]
fn every_layout_and_compression_reads_as_the_flat_layers() {
    let (flat, _) = read_layered_exr(fixture("scene-flat.exr")).unwrap();
    assert_eq!((flat.width, flat.height, flat.max_layers), (48, 32, 3));
    for name in ["scene-none.exr", "scene-rle.exr", "scene-zips.exr", "scene-tiled.exr", "scene-parts.exr"] {
        let (deep, report) = read(name);
        assert_eq!((deep.width, deep.height), (48, 32), "{name}");
        assert_eq!(report.samples_read, flat.counts.iter().map(|&c| c as u64).sum::<u64>(), "{name}");
        assert_eq!(report.tidy.merged + report.tidy.volumes_split, 0, "{name}: {report}");
        let layers = all_kept(&deep);
        assert_eq!(layers.counts, flat.counts, "{name}");
        assert_eq!(layers.fragments, flat.fragments, "{name}: the samples are read bit for bit");
    }
}

#[test]
fn half_channels_read_within_half_rounding() {
    let (flat, _) = read_layered_exr(fixture("scene-flat.exr")).unwrap();
    let layers = all_kept(&read("scene-half.exr").0);
    assert_eq!(layers.counts, flat.counts);
    for (a, b) in layers.fragments.iter().zip(&flat.fragments) {
        for (x, y) in a.color.iter().chain([&a.alpha]).zip(b.color.iter().chain([&b.alpha])) {
            assert!((x - y).abs() <= 1e-3 * y.abs().max(1e-3), "{a:?} {b:?}");
        }
        assert_eq!(a.depth, b.depth);
    }
}

#[test]
fn volume_and_coincident_samples_are_made_tidy() {
    let (deep, report) = read("volumes.exr");
    assert_eq!(report.tidy.volumes_split, 1, "{report}");
    assert_eq!(report.tidy.merged, 1, "{report}");
    assert_eq!(report.coloured_alpha, 1, "{report}");
    assert_eq!(deep.count(3), 0);
    let (flat, _) = deep.flatten();
    // Pixel 0: a grey medium over [1, 3] (alpha 0.5) split at an opaque red point at 2: its front
    // half lets sqrt(0.5) through, so red is 1 - 0.7071 + 0.7071 and green its front half's 0.2929.
    let front_half = 1.0 - 0.5f32.sqrt();
    assert!((flat.data[0][0] - 1.0).abs() < 1e-5 && (flat.data[0][1] - front_half).abs() < 1e-5, "{:?}", flat.data[0]);
    // Pixel 1: two equal media (alpha 0.3, colour 0.3) over one range: alpha 1 - 0.7², colour the same.
    assert!((flat.data[1][0] - 0.51).abs() < 1e-5, "{:?}", flat.data[1]);
    // Pixel 2: AR, AG, AB of 0.2, 0.4, 0.6 give coverage 0.4.
    assert_eq!(deep.pixel(2)[0].alpha, 0.4);
}

#[test]
fn nan_depths_are_dropped_and_counted() {
    let (deep, report) = read("nan-depth.exr");
    assert_eq!(report.counts.depth_invalid, 48, "{report}");
    assert!(report.to_string().contains("48 samples with NaN, zero or negative Z dropped"), "{report}");
    assert!(deep.samples.iter().all(|s| s.z > 0.0));
}

#[test]
fn in_focus_every_method_returns_the_flattened_composite() {
    let (deep, _) = read("scene-zips.exr");
    let (want, _) = deep.flatten();
    let pinhole = lens(1e-7);
    let (layers, report) = deep.layers(&frame(&deep), &pinhole, &LayerOptions::default()).unwrap();
    // Through a pinhole every umbra is endless: the wall behind the disc is left out, and it showed nothing.
    assert!(report.umbra_dropped > 0 && report.umbra_share == 0.0, "{report}");
    let mut cpu = CpuBackend::new();
    for m in METHODS {
        let out = one_shot(&mut cpu, m, &MethodOptions::default(), &layers, &pinhole).unwrap_or_else(|e| panic!("{}: {e}", m.name));
        for (i, (a, b)) in out.image.data.iter().zip(&want.data).enumerate() {
            for c in 0..3 {
                assert!(
                    (a[c] - b[c]).abs() <= 1e-5 * b[c].abs().max(1e-2),
                    "{}: pixel {i} is {a:?}, the flattened composite {b:?}",
                    m.name
                );
            }
        }
    }
}

#[test]
fn multi_layer_splatting_of_the_deep_file_equals_that_of_the_flat_layers() {
    let (flat, _) = read_layered_exr(fixture("scene-flat.exr")).unwrap();
    let (deep, _) = read("scene-tiled.exr");
    let layers = all_kept(&deep);
    let m = METHODS.iter().find(|m| m.name == "multilayer").unwrap();
    let mut cpu = CpuBackend::new();
    let a = one_shot(&mut cpu, m, &MethodOptions::default(), &layers, &lens(0.01)).unwrap().image;
    let b = one_shot(&mut cpu, m, &MethodOptions::default(), &flat, &lens(0.01)).unwrap().image;
    assert_eq!(a, b);
}

/// A copy of fixture `name` changed by `edit`, in a temporary file.
fn damaged(name: &str, tag: &str, edit: impl FnOnce(&mut Vec<u8>)) -> PathBuf {
    let mut bytes = std::fs::read(fixture(name)).unwrap();
    edit(&mut bytes);
    let path = std::env::temp_dir().join(format!("dof-deep-{}-{tag}-{name}", std::process::id()));
    std::fs::write(&path, bytes).unwrap();
    path
}

fn refused(path: &Path) -> String {
    let e = read_deep_exr(&[path]).err().unwrap_or_else(|| panic!("{} was read", path.display()));
    let _ = std::fs::remove_file(path);
    e.to_string()
}

/// The byte offset of the chunk offset table of a single-part file: right after its header (OpenEXR
/// file layout: magic and version, then `name\0type\0size value` attributes until an empty name).
fn first_table_entry(bytes: &[u8]) -> usize {
    // Skips a zero-terminated name at `at`; true when it is empty.
    let name = |at: &mut usize| {
        let end = *at + bytes[*at..].iter().position(|&b| b == 0).unwrap();
        let empty = end == *at;
        *at = end + 1;
        empty
    };
    let mut at = 8;
    loop {
        if name(&mut at) {
            return at;
        }
        name(&mut at);
        let size = i32::from_le_bytes(bytes[at..at + 4].try_into().unwrap()) as usize;
        at += 4 + size;
    }
}

#[test]
fn damaged_files_are_refused_with_a_message() {
    // Truncated anywhere after the headers.
    let full = std::fs::read(fixture("scene-zips.exr")).unwrap().len();
    for cut in [full - 1, full / 2, full / 4, 400] {
        let e = refused(&damaged("scene-zips.exr", &format!("cut{cut}"), |b| b.truncate(cut)));
        assert!(e.contains("scene-zips.exr"), "{e}");
    }
    // Offset tables that lie: beyond the file, zero (never written), at another chunk.
    let e = refused(&damaged("scene-none.exr", "beyond", |b| {
        let at = first_table_entry(b);
        b[at..at + 8].copy_from_slice(&u64::MAX.to_le_bytes());
    }));
    assert!(e.contains("outside the chunks"), "{e}");
    let e = refused(&damaged("scene-none.exr", "zero", |b| {
        let at = first_table_entry(b);
        b[at..at + 8].copy_from_slice(&0u64.to_le_bytes());
    }));
    assert!(e.contains("never written"), "{e}");
    let e = refused(&damaged("scene-none.exr", "repeat", |b| {
        let at = first_table_entry(b);
        let second: [u8; 8] = b[at + 8..at + 16].try_into().unwrap();
        b[at..at + 8].copy_from_slice(&second);
    }));
    assert!(e.contains("already read"), "{e}");
    // A pixel offset table claiming two billion samples (uncompressed, so it reads as written).
    let e = refused(&damaged("scene-none.exr", "billions", |b| {
        let at = first_table_entry(b);
        let chunk = u64::from_le_bytes(b[at..at + 8].try_into().unwrap()) as usize;
        // y, then three sizes, then the table: its last entry of the first line.
        let table = chunk + 4 + 24;
        b[table + 4 * 47..table + 4 * 48].copy_from_slice(&i32::MAX.to_le_bytes());
    }));
    assert!(e.contains("samples"), "{e}");
}

#[test]
fn random_damage_never_panics() {
    let original = std::fs::read(fixture("scene-zips.exr")).unwrap();
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    let path = std::env::temp_dir().join(format!("dof-deep-{}-random.exr", std::process::id()));
    for _ in 0..300 {
        let mut bytes = original.clone();
        for _ in 0..1 + next() % 4 {
            let i = (next() % bytes.len() as u64) as usize;
            bytes[i] ^= 1 << (next() % 8);
        }
        std::fs::write(&path, &bytes).unwrap();
        // Ok or a clean error; a panic fails the test.
        let _ = read_deep_exr(&[&path]);
    }
    let _ = std::fs::remove_file(path);
}
