//! EXR and PNG input/output: round trips, multi-layer input, bad files, the NaN/Inf policy, the tone
//! map.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU32, Ordering};

use dof::CoreError;
use dof::io::codecs::exr::prelude as exr;
use dof::io::codecs::png;
use dof::io::tonemap::{aces_fitted, srgb_eotf, srgb_oetf, to_u8, tonemap, tonemap_to_srgb8};
use dof::io::{
    BACKGROUND_DEPTH, COLOR_INF_REPLACEMENT, ExrCompression, ExrLayout, ExrPrecision, ExrWriteOptions, SanitizeCounts, read_layered_exr,
    read_rgb_exr, write_exr, write_exr_with, write_layered_exr, write_png_preview,
};
use dof::layers::{Fragment, LayeredImage, RgbImage};
use proptest::prelude::*;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

// ---------------------------------------------------------------------------------------------
// Helpers

/// A unique path under the system temp directory, removed when dropped.
struct TempFile(PathBuf);

impl TempFile {
    fn new(name: &str) -> TempFile {
        static NEXT: AtomicU32 = AtomicU32::new(0);
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        TempFile(std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("dof-image-io-{}-{n}-{name}", std::process::id())))
    }
    fn path(&self) -> &Path {
        &self.0
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

fn random_image(rng: &mut Pcg64, width: u32, height: u32) -> RgbImage {
    let mut image = RgbImage::new(width, height);
    for c in &mut image.data {
        *c = [0; 3].map(|_| match rng.random_range(0..4) {
            0 => rng.random_range(-1.0..1.0f32),
            1 => rng.random_range(0.0..1e-30f32),
            2 => rng.random_range(0.0..1e4f32),
            _ => f32::from_bits(rng.random_range(0..0x7f00_0000u32)), // any positive finite
        });
    }
    image
}

fn err_message<T: std::fmt::Debug>(r: dof::Result<T>) -> String {
    let e = r.expect_err("expected an error");
    assert!(matches!(e, dof::Error::Core(CoreError::InvalidArgument(_))), "expected InvalidArgument, got {e:?}");
    eprintln!("expected error: {e}");
    e.to_string()
}

fn assert_mentions(message: &str, words: &[&str]) {
    for w in words {
        assert!(message.contains(w), "error message should mention `{w}`: {message}");
    }
}

fn channel(name: &str, values: Vec<f32>) -> exr::AnyChannel<exr::FlatSamples> {
    exr::AnyChannel::new(name, exr::FlatSamples::F32(values))
}

/// Writes a single-part EXR with the given `f32` channels using the exr crate directly.
fn write_channels(path: &Path, width: usize, height: usize, channels: Vec<exr::AnyChannel<exr::FlatSamples>>) {
    use exr::WritableImage;
    let image = exr::Image::from_channels((width, height), exr::AnyChannels::sort(channels.into_iter().collect()));
    image.write().to_file(path).unwrap();
}

/// Writes a multi-part EXR: one part per `(name, channels)`, all `width x height`.
fn write_parts(path: &Path, width: usize, height: usize, parts: Vec<(&str, Vec<exr::AnyChannel<exr::FlatSamples>>)>) {
    use exr::WritableImage;
    let layers: Vec<exr::Layer<exr::AnyChannels<exr::FlatSamples>>> = parts
        .into_iter()
        .map(|(name, channels)| {
            exr::Layer::new(
                (width, height),
                exr::LayerAttributes::named(name),
                exr::Encoding::FAST_LOSSLESS,
                exr::AnyChannels::sort(channels.into_iter().collect()),
            )
        })
        .collect();
    let image = exr::Image::from_layers(exr::ImageAttributes::new(exr::IntegerBounds::from_dimensions((width, height))), layers);
    image.write().to_file(path).unwrap();
}

fn half_channel(name: &str, values: Vec<f32>) -> exr::AnyChannel<exr::FlatSamples> {
    exr::AnyChannel::new(name, exr::FlatSamples::F16(values.into_iter().map(exr::f16::from_f32).collect()))
}

/// The background fragment the reader makes of a slot at depth `+inf` or beyond the threshold.
fn background(color: [f32; 3]) -> Fragment {
    Fragment { color, alpha: 1.0, depth: f32::INFINITY }
}

/// One input layer slot of the multi-layer tests: premultiplied colour, alpha, depth.
#[derive(Clone, Copy)]
struct Slot {
    rgb: [f32; 3],
    a: f32,
    z: f32,
}

// ---------------------------------------------------------------------------------------------
// Round trips

#[test]
fn rgbz_round_trip_is_bit_exact_in_f32() {
    let mut rng = Pcg64::seed_from_u64(1);
    let (w, h) = (7, 5);
    let image = random_image(&mut rng, w, h);
    let depth: Vec<f32> = (0..w * h).map(|_| rng.random_range(0.01..1e3f32)).collect();
    let coc: Vec<f32> = (0..w * h).map(|_| rng.random_range(-5.0..5.0f32)).collect();
    let mask: Vec<f32> = (0..w * h).map(|i| (i % 2) as f32).collect();
    let file = TempFile::new("rgbz.exr");
    write_exr(file.path(), &image, &[("Z", &depth), ("coc", &coc), ("mask", &mask)]).unwrap();

    let (layered, report) = read_layered_exr(file.path()).unwrap();
    assert_eq!(report.layout, ExrLayout::RgbZ);
    assert_eq!((report.width, report.height), (w, h));
    assert_eq!(report.layers, [""]);
    assert_eq!(report.ignored_channels, ["coc", "mask"]);
    assert_eq!(report.counts, SanitizeCounts::default());
    assert_eq!((layered.width, layered.height, layered.max_layers), (w, h, 1));
    for y in 0..h {
        for x in 0..w {
            let p = (y * w + x) as usize;
            let frags = layered.pixel(x, y);
            assert_eq!(frags.len(), 1, "pixel ({x}, {y})");
            assert_eq!(frags[0].color.map(f32::to_bits), image.data[p].map(f32::to_bits), "colour at ({x}, {y})");
            assert_eq!(frags[0].depth.to_bits(), depth[p].to_bits(), "depth at ({x}, {y})");
            assert_eq!(frags[0].alpha, 1.0);
        }
    }

    let (rgb, report) = read_rgb_exr(file.path()).unwrap();
    assert_eq!(report.layout, ExrLayout::Rgb);
    assert_eq!(report.ignored_channels, ["Z", "coc", "mask"]);
    assert_eq!((rgb.width, rgb.height), (w, h));
    let bits = |i: &RgbImage| i.data.iter().map(|c| c.map(f32::to_bits)).collect::<Vec<_>>();
    assert_eq!(bits(&rgb), bits(&image));
}

#[test]
fn uncompressed_and_zip_read_back_the_same() {
    let mut rng = Pcg64::seed_from_u64(5);
    let image = random_image(&mut rng, 5, 6);
    let depth: Vec<f32> = (0..30).map(|i| 0.5 + i as f32).collect();
    let zip = TempFile::new("zip.exr");
    let raw = TempFile::new("raw.exr");
    write_exr(zip.path(), &image, &[("Z", &depth)]).unwrap();
    let options = ExrWriteOptions { compression: ExrCompression::None, ..Default::default() };
    write_exr_with(raw.path(), &image, &[("Z", &depth)], &options).unwrap();
    let (a, _) = read_layered_exr(zip.path()).unwrap();
    let (b, _) = read_layered_exr(raw.path()).unwrap();
    assert_eq!(a, b);
    assert!(std::fs::metadata(raw.path()).unwrap().len() >= 30 * 4 * 4, "uncompressed holds every sample");
}

#[test]
fn extra_planes_are_written_bit_exact() {
    let (w, h) = (3usize, 2usize);
    let image = RgbImage::new(w as u32, h as u32);
    let coc = vec![0.5, -1.25, 3.0e-38, 7.0, f32::NAN, f32::INFINITY];
    let file = TempFile::new("planes.exr");
    write_exr(file.path(), &image, &[("coc", &coc)]).unwrap();
    let read = exr::read_first_flat_layer_from_file(file.path()).unwrap();
    let plane = read.layer_data.channel_data.list.iter().find(|c| c.name.eq("coc")).unwrap();
    let exr::FlatSamples::F32(values) = &plane.sample_data else { panic!("coc should be f32") };
    assert_eq!(values.iter().map(|v| v.to_bits()).collect::<Vec<_>>(), coc.iter().map(|v| v.to_bits()).collect::<Vec<_>>());
}

#[test]
fn half_precision_round_trip_is_close() {
    let mut image = RgbImage::new(4, 2);
    let values = [0.0, 1.0, 0.5, 3.25, 1000.0, 0.001, 60000.0, -2.0];
    for (i, c) in image.data.iter_mut().enumerate() {
        *c = [values[i], values[(i + 1) % 8], values[(i + 3) % 8]];
    }
    let depth = vec![1.0f32; 8];
    let file = TempFile::new("half.exr");
    let options = ExrWriteOptions { precision: ExrPrecision::Half, ..Default::default() };
    write_exr_with(file.path(), &image, &[("Z", &depth)], &options).unwrap();
    let (rgb, _) = read_rgb_exr(file.path()).unwrap();
    for (got, want) in rgb.data.iter().zip(&image.data) {
        for k in 0..3 {
            assert!((got[k] - want[k]).abs() <= want[k].abs() * 1e-3, "{got:?} vs {want:?}");
        }
    }
}

#[test]
fn layered_image_round_trip() {
    let mut rng = Pcg64::seed_from_u64(2);
    let (w, h, layers) = (6, 4, 3);
    let mut image = LayeredImage::new(w, h, layers).unwrap();
    for y in 0..h {
        for x in 0..w {
            let n = rng.random_range(0..=layers);
            let mut depth = 0.0;
            for _ in 0..n {
                depth += rng.random_range(0.1..10.0f32);
                let color = [0; 3].map(|_| rng.random_range(0.0..4.0f32));
                image.push(x, y, Fragment { color, alpha: 1.0, depth }).unwrap();
            }
        }
    }
    let file = TempFile::new("layered.exr");
    write_layered_exr(file.path(), &image).unwrap();
    let (back, report) = read_layered_exr(file.path()).unwrap();
    assert_eq!(report.layout, ExrLayout::MultiLayer);
    assert_eq!(report.layers, ["layer0", "layer1", "layer2"]);
    assert_eq!(report.counts.repaired(), 0);
    assert_eq!(back, image, "alpha-1 fragments survive bit for bit");
}

#[test]
fn layered_round_trip_with_partial_alpha() {
    let mut image = LayeredImage::new(2, 1, 2).unwrap();
    image.push(0, 0, Fragment { color: [0.3, 0.6, 0.9], alpha: 0.25, depth: 1.0 }).unwrap();
    image.push(0, 0, Fragment { color: [1.0, 2.0, 3.0], alpha: 1.0, depth: 2.0 }).unwrap();
    image.push(1, 0, Fragment { color: [5.0, 0.0, 0.1], alpha: 0.7, depth: 3.0 }).unwrap();
    let file = TempFile::new("alpha.exr");
    write_layered_exr(file.path(), &image).unwrap();
    let (back, _) = read_layered_exr(file.path()).unwrap();
    for x in 0..2 {
        let (a, b) = (image.pixel(x, 0), back.pixel(x, 0));
        assert_eq!(a.len(), b.len());
        for (f, g) in a.iter().zip(b) {
            assert_eq!((f.alpha, f.depth), (g.alpha, g.depth));
            for k in 0..3 {
                assert!((f.color[k] - g.color[k]).abs() <= 1e-6 * f.color[k].abs().max(1.0), "{f:?} vs {g:?}");
            }
        }
    }
}

/// Premultiplied slots of a 4x2 three-layer image, with layer order unrelated to depth order, empty
/// slots (A = 0 with garbage depth), background slots (Z = inf, A = 1; pixel 4 has two) and partial
/// alpha.
fn multi_layer_slots() -> Vec<Vec<Slot>> {
    let s = |rgb: [f32; 3], a: f32, z: f32| Slot { rgb, a, z };
    let empty = s([0.0; 3], 0.0, 0.0);
    let sky = s([0.0; 3], 1.0, f32::INFINITY);
    let blue_sky = s([0.1, 0.2, 0.9], 1.0, f32::INFINITY);
    // slots[layer][pixel]
    vec![
        vec![
            s([1.0, 0.0, 0.0], 1.0, 5.0),
            s([0.5, 0.5, 0.5], 0.5, 1.0),
            empty,
            s([0.1, 0.2, 0.3], 1.0, 2.0),
            sky,
            s([2.0, 2.0, 2.0], 1.0, 9.0),
            empty,
            s([0.0, 1.0, 0.0], 1.0, 3.0),
        ],
        vec![
            s([0.0, 1.0, 0.0], 1.0, 2.0),
            s([0.0, 0.0, 1.0], 1.0, 4.0),
            empty,
            s([0.4, 0.5, 0.6], 1.0, 2.0), // same depth as layer 0: layer order kept
            s([0.0, 0.0, 7.0], 1.0, 8.0),
            empty,
            empty,
            s([0.0, 0.0, 1.0], 0.25, 1.5),
        ],
        vec![
            s([0.0, 0.0, 1.0], 1.0, 0.5),
            empty,
            s([3.0, 3.0, 3.0], 1.0, 1.0),
            empty,
            blue_sky, // behind the first background of pixel 4 (layer 0's): dropped
            s([1.0, 1.0, 1.0], 1.0, 4.0),
            empty,
            s([1.0, 0.0, 0.0], 1.0, 10.0),
        ],
    ]
}

/// What the reader must produce from `slots`: per pixel, the non-empty finite slots as
/// premultiplied fragments as stored, sorted by depth (stable), then the first background slot (in layer
/// order) as a background fragment with its stored colour.
fn expected_pixels(slots: &[Vec<Slot>]) -> Vec<Vec<Fragment>> {
    (0..slots[0].len())
        .map(|p| {
            let mut frags: Vec<Fragment> = slots
                .iter()
                .map(|l| l[p])
                .filter(|s| s.a > 0.0 && s.z.is_finite())
                .map(|s| Fragment { color: s.rgb, alpha: s.a, depth: s.z })
                .collect();
            frags.sort_by(|a, b| a.depth.total_cmp(&b.depth));
            if let Some(sky) = slots.iter().map(|l| l[p]).find(|s| s.a > 0.0 && s.z == f32::INFINITY) {
                frags.push(background(sky.rgb));
            }
            frags
        })
        .collect()
}

fn assert_matches_expected(image: &LayeredImage, slots: &[Vec<Slot>], width: u32) {
    let expected = expected_pixels(slots);
    assert_eq!(image.max_layers as usize, slots.len());
    for (p, want) in expected.iter().enumerate() {
        let (x, y) = (p as u32 % width, p as u32 / width);
        assert_eq!(image.pixel(x, y), &want[..], "pixel ({x}, {y})");
    }
}

#[test]
fn multi_layer_exr_written_by_the_exr_crate() {
    let slots = multi_layer_slots();
    // Names chosen so that bytewise order (layer10 < layer2) differs from the natural order.
    let names = ["layer1", "layer2", "layer10"];
    let mut channels = Vec::new();
    for (name, layer) in names.iter().zip(&slots) {
        for (k, c) in ["R", "G", "B"].iter().enumerate() {
            channels.push(channel(&format!("{name}.{c}"), layer.iter().map(|s| s.rgb[k]).collect()));
        }
        channels.push(channel(&format!("{name}.A"), layer.iter().map(|s| s.a).collect()));
        channels.push(channel(&format!("{name}.Z"), layer.iter().map(|s| s.z).collect()));
    }
    // A flattened beauty image next to the layers is ignored.
    channels.push(channel("R", vec![0.0; 8]));
    channels.push(channel("G", vec![0.0; 8]));
    channels.push(channel("B", vec![0.0; 8]));
    let file = TempFile::new("multi.exr");
    write_channels(file.path(), 4, 2, channels);

    let (image, report) = read_layered_exr(file.path()).unwrap();
    assert_eq!(report.layout, ExrLayout::MultiLayer);
    assert_eq!(report.layers, names);
    assert_eq!(report.ignored_channels, ["B", "G", "R"]);
    assert_eq!(report.counts.empty_alpha, 8);
    assert_eq!(report.counts.background, 2, "both sky slots of pixel 4 are backgrounds");
    assert_eq!(report.counts.behind_background, 1, "the second is dropped");
    assert_eq!(report.counts.repaired(), 1, "{report}");
    assert_eq!(report.total(), 4, "the dropped slot and the three unused root channels");
    assert_mentions(&report.to_string(), &["channels not used: B, G, R", "1 fragments behind the background dropped"]);
    assert_matches_expected(&image, &slots, 4);
    assert_eq!(image.pixel(0, 1), [Fragment { color: [0.0, 0.0, 7.0], alpha: 1.0, depth: 8.0 }, background([0.0; 3])]);
    for p in 0..8 {
        let (x, y) = (p % 4, p / 4);
        assert!(image.pixel(x, y).windows(2).all(|f| f[0].depth <= f[1].depth), "front to back at ({x}, {y})");
    }
    // Ties keep layer order: pixel 3 has layer1 (0.1..) then layer2 (0.4..) at depth 2.
    assert_eq!(image.pixel(3, 0)[0].color, [0.1, 0.2, 0.3]);
}

#[test]
fn multi_part_exr_one_part_per_layer() {
    use exr::WritableImage;
    let slots = multi_layer_slots();
    let (w, h) = (4usize, 2usize);
    let parts: Vec<exr::Layer<exr::AnyChannels<exr::FlatSamples>>> = slots
        .iter()
        .enumerate()
        .map(|(i, layer)| {
            let mut list = exr::SmallVec::new();
            for (k, c) in ["R", "G", "B"].iter().enumerate() {
                list.push(channel(c, layer.iter().map(|s| s.rgb[k]).collect()));
            }
            list.push(channel("A", layer.iter().map(|s| s.a).collect()));
            list.push(channel("Z", layer.iter().map(|s| s.z).collect()));
            exr::Layer::new(
                (w, h),
                exr::LayerAttributes::named(format!("layer{i}").as_str()),
                exr::Encoding::FAST_LOSSLESS,
                exr::AnyChannels::sort(list),
            )
        })
        .collect();
    let image = exr::Image::from_layers(exr::ImageAttributes::new(exr::IntegerBounds::from_dimensions((w, h))), parts);
    let file = TempFile::new("multipart.exr");
    image.write().to_file(file.path()).unwrap();

    let (layered, report) = read_layered_exr(file.path()).unwrap();
    assert_eq!(report.layout, ExrLayout::MultiLayer);
    assert_eq!(report.layers, ["layer0", "layer1", "layer2"]);
    assert_matches_expected(&layered, &slots, 4);
}

#[test]
fn depth_and_alpha_name_variants() {
    let file = TempFile::new("variants.exr");
    // Lower-case channels, `depth` for Z, no alpha; half floats.
    let half = |v: Vec<f32>| exr::FlatSamples::F16(v.into_iter().map(exr::f16::from_f32).collect());
    let channels = vec![
        exr::AnyChannel::new("r", half(vec![1.0, 2.0])),
        exr::AnyChannel::new("g", half(vec![0.5, 0.25])),
        exr::AnyChannel::new("b", half(vec![0.0, 4.0])),
        exr::AnyChannel::new("depth", half(vec![2.0, 3.0])),
    ];
    write_channels(file.path(), 2, 1, channels);
    let (image, report) = read_layered_exr(file.path()).unwrap();
    assert_eq!(report.layout, ExrLayout::RgbZ);
    assert_eq!(report.channels, ["r", "g", "b", "depth"]);
    assert_eq!(image.pixel(1, 0), [Fragment { color: [2.0, 0.25, 4.0], alpha: 1.0, depth: 3.0 }]);

    // Nuke's `depth.Z` is the depth of an RGB image.
    let file = TempFile::new("nuke.exr");
    let channels = vec![
        channel("R", vec![1.0]),
        channel("G", vec![1.0]),
        channel("B", vec![1.0]),
        channel("A", vec![1.0]),
        channel("depth.Z", vec![4.0]),
    ];
    write_channels(file.path(), 1, 1, channels);
    let (image, report) = read_layered_exr(file.path()).unwrap();
    assert_eq!(report.layout, ExrLayout::RgbZ);
    assert_eq!(image.pixel(0, 0)[0].depth, 4.0);
}

// ---------------------------------------------------------------------------------------------
// The background, and EXR files as Blender and Nuke write them

/// The colour of a fragment or background stored at pixel `p` of the Blender-like fixtures:
/// (premultiplied colour, alpha, depth).
const TOOL_PIXELS: [([f32; 3], f32, f32); 4] = [
    ([0.5, 0.25, 0.125], 1.0, 3.0),        // opaque surface
    ([0.2, 0.1, 0.05], 0.5, 7.5),          // antialiased edge: half covered, kept premultiplied
    ([0.3, 0.6, 0.9], 1.0, 1e10),          // Blender's world background at 1e10, with a colour
    ([0.0, 0.0, 0.0], 0.0, f32::INFINITY), // transparent film: alpha 0 at +inf
];

/// What the reader must make of `TOOL_PIXELS` in an RGB+Z image.
fn tool_pixels_expected() -> [Vec<Fragment>; 4] {
    [
        vec![Fragment { color: [0.5, 0.25, 0.125], alpha: 1.0, depth: 3.0 }],
        vec![Fragment { color: [0.2, 0.1, 0.05], alpha: 0.5, depth: 7.5 }],
        vec![background([0.3, 0.6, 0.9])],
        vec![background([0.0; 3])],
    ]
}

fn tool_channel(name: &str, f: impl Fn(&([f32; 3], f32, f32)) -> f32) -> exr::AnyChannel<exr::FlatSamples> {
    channel(name, TOOL_PIXELS.iter().map(f).collect())
}

/// `<prefix>.R/G/B/A` of `TOOL_PIXELS`.
fn rgba_channels(prefix: &str) -> Vec<exr::AnyChannel<exr::FlatSamples>> {
    let mut channels: Vec<_> = (0..3).map(|k| tool_channel(&format!("{prefix}{}", ["R", "G", "B"][k]), |p| p.0[k])).collect();
    channels.push(tool_channel(&format!("{prefix}A"), |p| p.1));
    channels
}

fn assert_tool_pixels(image: &LayeredImage) {
    assert_eq!((image.width, image.height, image.max_layers), (4, 1, 1));
    for (x, want) in tool_pixels_expected().iter().enumerate() {
        assert_eq!(image.pixel(x as u32, 0), &want[..], "pixel {x}");
    }
}

#[test]
fn blender_combined_with_sibling_depth_layer() {
    for view_layer in ["RenderLayer", "ViewLayer", "My Layer"] {
        let mut channels = rgba_channels(&format!("{view_layer}.Combined."));
        channels.push(tool_channel(&format!("{view_layer}.Depth.Z"), |p| p.2));
        // Passes Blender writes beside them: not the image, each named as unused.
        for c in ["R", "G", "B"] {
            channels.push(channel(&format!("{view_layer}.DiffCol.{c}"), vec![0.7; 4]));
        }
        for c in ["X", "Y", "Z"] {
            channels.push(channel(&format!("{view_layer}.Normal.{c}"), vec![0.0; 4]));
        }
        channels.push(channel(&format!("{view_layer}.Mist.Z"), vec![0.5; 4]));
        let file = TempFile::new("blender.exr");
        write_channels(file.path(), 4, 1, channels);

        let (image, report) = read_layered_exr(file.path()).unwrap();
        assert_eq!(report.layout, ExrLayout::RgbZ, "{view_layer}");
        assert_eq!(report.layers, [format!("{view_layer}.Combined")]);
        let used = ["Combined.R", "Combined.G", "Combined.B", "Combined.A", "Depth.Z"];
        assert_eq!(report.channels, used.map(|c| format!("{view_layer}.{c}")));
        let mut unused: Vec<String> = ["DiffCol.B", "DiffCol.G", "DiffCol.R", "Mist.Z", "Normal.X", "Normal.Y", "Normal.Z"]
            .iter()
            .map(|c| format!("{view_layer}.{c}"))
            .collect();
        unused.sort();
        assert_eq!(report.ignored_channels, unused);
        assert_eq!(report.counts, SanitizeCounts { background: 2, ..Default::default() });
        assert_eq!(report.total(), 7, "the seven unused channels are worth a note");
        let text = report.to_string();
        assert_mentions(
            &text,
            &[
                &format!("RGB+Z from {view_layer}.Combined.R"),
                &format!("{view_layer}.Depth.Z"),
                &format!("channels not used: {}", unused.join(", ")),
                "2 background fragments",
            ],
        );
        assert_tool_pixels(&image);
    }
}

#[test]
fn blender_half_float_file_background_is_infinite() {
    // Blender's default half-float EXR: its background depth 1e10 overflows to +inf.
    let half_of = |name: &str, f: &dyn Fn(&([f32; 3], f32, f32)) -> f32| half_channel(name, TOOL_PIXELS.iter().map(f).collect());
    let channels = vec![
        half_of("ViewLayer.Combined.R", &|p| p.0[0]),
        half_of("ViewLayer.Combined.G", &|p| p.0[1]),
        half_of("ViewLayer.Combined.B", &|p| p.0[2]),
        half_of("ViewLayer.Combined.A", &|p| p.1),
        half_of("ViewLayer.Depth.Z", &|p| p.2),
    ];
    let file = TempFile::new("blender-half.exr");
    write_channels(file.path(), 4, 1, channels);
    let (image, report) = read_layered_exr(file.path()).unwrap();
    assert_eq!(report.layers, ["ViewLayer.Combined"]);
    assert_eq!(report.counts.background, 2);
    let h = |v: f32| exr::f16::from_f32(v).to_f32();
    assert_eq!(image.pixel(0, 0), [Fragment { color: [0.5, 0.25, 0.125], alpha: 1.0, depth: 3.0 }]);
    assert_eq!(image.pixel(2, 0), [background([h(0.3), h(0.6), h(0.9)])]);
    assert_eq!(image.pixel(3, 0), [background([0.0; 3])]);
}

#[test]
fn nuke_two_part_rgba_and_depth() {
    // Nuke names the depth channel `depth.Z` inside the part `depth`, or just `Z`; the rgba part's
    // channels are `R`, `G`, `B`, `A` or `rgba.R`, ...: all four spellings read the same.
    for (colour_prefix, depth_name) in [("", "depth.Z"), ("", "Z"), ("rgba.", "depth.Z"), ("rgba.", "Z")] {
        let rgba = rgba_channels(colour_prefix);
        let depth = vec![tool_channel(depth_name, |p| p.2)];
        // A further part holding another colour layer (a pass): named as unused.
        let diffuse = ["R", "G", "B"].iter().map(|c| channel(c, vec![0.25; 4])).collect();
        let file = TempFile::new("nuke.exr");
        write_parts(file.path(), 4, 1, vec![("rgba", rgba), ("depth", depth), ("diffuse", diffuse)]);

        let (image, report) = read_layered_exr(file.path()).unwrap();
        let case = format!("{colour_prefix}R with {depth_name}");
        assert_eq!(report.layout, ExrLayout::RgbZ, "{case}");
        assert_eq!(report.layers, ["rgba"], "{case}");
        assert_eq!(report.channels, ["rgba.R", "rgba.G", "rgba.B", "rgba.A", "depth.Z"], "{case}");
        assert_eq!(report.ignored_channels, ["diffuse.B", "diffuse.G", "diffuse.R"], "{case}");
        assert_eq!(report.counts, SanitizeCounts { background: 2, ..Default::default() }, "{case}");
        assert_tool_pixels(&image);
    }

    // The single-part Nuke layout: unnamed R, G, B, A with `depth.Z`.
    let mut channels = rgba_channels("");
    channels.push(tool_channel("depth.Z", |p| p.2));
    let file = TempFile::new("nuke-single.exr");
    write_channels(file.path(), 4, 1, channels);
    let (image, report) = read_layered_exr(file.path()).unwrap();
    assert_eq!(report.layers, [""]);
    assert_eq!(report.channels, ["R", "G", "B", "A", "depth.Z"]);
    assert!(report.ignored_channels.is_empty());
    assert_tool_pixels(&image);
}

#[test]
fn sky_colour_is_kept_at_infinity_and_beyond_the_threshold() {
    let sky = [0.25, 0.5, 1.0];
    // Where tools put the background: +inf, Blender's 1e10, f32::MAX; just below the threshold the
    // surface is an ordinary (very far) fragment.
    assert_eq!(BACKGROUND_DEPTH, 1e10);
    let below = 1e10f32.next_down();
    let cases = [(f32::INFINITY, true), (1e10, true), (f32::MAX, true), (below, false), (65504.0, false)];
    for (sky_depth, is_background) in cases {
        let mut image = RgbImage::new(2, 1);
        image.data = vec![[1.0, 0.0, 0.0], sky];
        let depth = [2.0, sky_depth];
        let file = TempFile::new("sky.exr");
        write_exr(file.path(), &image, &[("Z", &depth)]).unwrap();
        let (layered, report) = read_layered_exr(file.path()).unwrap();
        assert_eq!(layered.pixel(0, 0), [Fragment { color: [1.0, 0.0, 0.0], alpha: 1.0, depth: 2.0 }]);
        let want = if is_background { background(sky) } else { Fragment { color: sky, alpha: 1.0, depth: sky_depth } };
        assert_eq!(layered.pixel(1, 0), [want], "sky at {sky_depth}");
        assert_eq!(report.counts, SanitizeCounts { background: is_background as u64, ..Default::default() });
        assert_eq!(report.total(), 0, "nothing was repaired or left out at {sky_depth}");
    }
}

#[test]
fn multi_layer_background_ends_the_pixel() {
    // Per pixel, three layer slots (premultiplied colour, alpha, depth).
    let inf = f32::INFINITY;
    let pixels: [[([f32; 3], f32, f32); 3]; 3] = [
        // A background in the first layer, a surface in front of it in a later layer, and a
        // second background (at 1e12) that is dropped.
        [([0.1, 0.2, 0.3], 1.0, inf), ([1.0, 1.0, 0.0], 0.5, 4.0), ([9.0, 9.0, 9.0], 1.0, 1e12)],
        // A partly transparent background slot: taken over black (its stored colour), alpha 1.
        [([2.0, 0.0, 0.0], 1.0, 1.0), ([0.2, 0.4, 0.6], 0.5, 2e10), ([0.0; 3], 0.0, inf)],
        // Empty slots at +inf (as `write_layered_exr` writes them) are not a background.
        [([0.0; 3], 0.0, inf), ([0.0, 3.0, 0.0], 1.0, 5.0), ([0.0; 3], 0.0, inf)],
    ];
    let mut channels = Vec::new();
    for layer in 0..3 {
        for (k, c) in ["R", "G", "B"].iter().enumerate() {
            channels.push(channel(&format!("layer{layer}.{c}"), pixels.iter().map(|p| p[layer].0[k]).collect()));
        }
        channels.push(channel(&format!("layer{layer}.A"), pixels.iter().map(|p| p[layer].1).collect()));
        channels.push(channel(&format!("layer{layer}.Z"), pixels.iter().map(|p| p[layer].2).collect()));
    }
    let file = TempFile::new("multi-sky.exr");
    write_channels(file.path(), 3, 1, channels);
    let (image, report) = read_layered_exr(file.path()).unwrap();
    assert_eq!(report.layout, ExrLayout::MultiLayer);
    assert_eq!(image.pixel(0, 0), [Fragment { color: [1.0, 1.0, 0.0], alpha: 0.5, depth: 4.0 }, background([0.1, 0.2, 0.3])]);
    assert_eq!(image.pixel(1, 0), [Fragment { color: [2.0, 0.0, 0.0], alpha: 1.0, depth: 1.0 }, background([0.2, 0.4, 0.6])]);
    assert_eq!(image.pixel(2, 0), [Fragment { color: [0.0, 3.0, 0.0], alpha: 1.0, depth: 5.0 }]);
    assert_eq!(report.counts, SanitizeCounts { background: 3, behind_background: 1, empty_alpha: 3, ..Default::default() });
    assert_eq!(report.repaired(), 1, "the dropped second background is a repair");
    assert_mentions(&report.to_string(), &["1 fragments behind the background dropped", "3 background fragments"]);
}

#[test]
fn layered_round_trip_with_background() {
    let mut image = LayeredImage::new(2, 1, 2).unwrap();
    image.push(0, 0, Fragment { color: [0.3, 0.6, 0.9], alpha: 0.25, depth: 1.0 }).unwrap();
    image.push(0, 0, background([0.5, 0.75, 1.0])).unwrap();
    image.push(1, 0, background([0.0; 3])).unwrap();
    let file = TempFile::new("layered-sky.exr");
    write_layered_exr(file.path(), &image).unwrap();
    let (back, report) = read_layered_exr(file.path()).unwrap();
    assert_eq!(back.pixel(0, 0)[1], background([0.5, 0.75, 1.0]));
    assert_eq!(back.pixel(1, 0), [background([0.0; 3])]);
    assert_eq!(back.pixel(0, 0).len(), 2);
    assert_eq!(report.counts.background, 2);
    assert_eq!(report.counts.repaired(), 0);
}

#[test]
fn root_rgbz_next_to_named_layers_is_refused() {
    // The root image may be the front layer or the flattened image of the named layers: refused,
    // naming both candidates' channels.
    let mut channels = vec![channel("R", vec![1.0; 4]), channel("G", vec![1.0; 4]), channel("B", vec![1.0; 4])];
    channels.push(channel("Z", vec![2.0; 4]));
    for l in ["layer0", "layer1"] {
        for c in ["R", "G", "B", "A", "Z"] {
            channels.push(channel(&format!("{l}.{c}"), vec![1.0; 4]));
        }
    }
    let file = TempFile::new("root-and-layers.exr");
    write_channels(file.path(), 2, 2, channels);
    let m = err_message(read_layered_exr(file.path()));
    assert_mentions(
        &m,
        &[
            "root-and-layers.exr is ambiguous",
            "2 different images",
            "(1) RGB+Z from the unnamed channels R, G, B, Z",
            "(2) a multi-layer image of the layers `layer0`, `layer1`",
            "layer0.R, layer0.G, layer0.B, layer0.A, layer0.Z",
            "Keep the channels of the one to use and remove the others",
        ],
    );

    // A root RGB+Z next to named layers that are not images (passes without depth): the root is
    // read, the others named as unused.
    let mut channels = vec![channel("R", vec![1.0; 4]), channel("G", vec![0.5; 4]), channel("B", vec![0.25; 4])];
    channels.push(channel("Z", vec![2.0; 4]));
    for c in ["R", "G", "B"] {
        channels.push(channel(&format!("diffuse.{c}"), vec![0.0; 4]));
    }
    let file = TempFile::new("root-and-passes.exr");
    write_channels(file.path(), 2, 2, channels);
    let (image, report) = read_layered_exr(file.path()).unwrap();
    assert_eq!(report.layout, ExrLayout::RgbZ);
    assert_eq!(report.ignored_channels, ["diffuse.B", "diffuse.G", "diffuse.R"]);
    assert_eq!(report.total(), 3);
    assert_mentions(&report.to_string(), &["channels not used: diffuse.B, diffuse.G, diffuse.R"]);
    assert_eq!(image.pixel(1, 1), [Fragment { color: [1.0, 0.5, 0.25], alpha: 1.0, depth: 2.0 }]);
}

#[test]
fn ambiguous_tool_layouts_are_refused() {
    // Two Blender view layers, each with Combined and Depth.
    let mut channels = Vec::new();
    for view_layer in ["ViewLayer", "Background"] {
        for c in ["R", "G", "B", "A"] {
            channels.push(channel(&format!("{view_layer}.Combined.{c}"), vec![1.0; 4]));
        }
        channels.push(channel(&format!("{view_layer}.Depth.Z"), vec![3.0; 4]));
    }
    let file = TempFile::new("two-view-layers.exr");
    write_channels(file.path(), 2, 2, channels);
    let m = err_message(read_layered_exr(file.path()));
    assert_mentions(
        &m,
        &[
            "is ambiguous",
            "RGB+Z from `Background.Combined` with the depth of `Background.Depth`",
            "RGB+Z from `ViewLayer.Combined` with the depth of `ViewLayer.Depth`",
            "Background.Combined.R, Background.Combined.G, Background.Combined.B, Background.Combined.A, Background.Depth.Z",
        ],
    );

    // Nuke's `rgba.*` and an unnamed R, G, B both beside `depth.Z`.
    let mut channels = rgba_channels("rgba.");
    channels.extend(["R", "G", "B"].map(|c| channel(c, vec![0.0; 4])));
    channels.push(tool_channel("depth.Z", |p| p.2));
    let file = TempFile::new("rgba-and-root.exr");
    write_channels(file.path(), 4, 1, channels);
    assert_mentions(
        &err_message(read_layered_exr(file.path())),
        &["is ambiguous", "RGB+Z from the unnamed layer with the depth of `depth`", "RGB+Z from `rgba` with the depth of `depth`"],
    );

    // Blender's Combined with a depth layer of another view layer: no image, and the message names
    // the depth layer that matched nothing.
    let mut channels = rgba_channels("ViewLayer.Combined.");
    channels.push(tool_channel("Other.Depth.Z", |p| p.2));
    let file = TempFile::new("stray-depth.exr");
    write_channels(file.path(), 4, 1, channels);
    assert_mentions(
        &err_message(read_layered_exr(file.path())),
        &[
            "layer `ViewLayer.Combined` has colour but no depth",
            "`<P>.Depth.Z` beside `<P>.Combined`",
            "(`Other.Depth`) belong to no colour layer",
        ],
    );
}

// ---------------------------------------------------------------------------------------------
// Bad input

#[test]
fn missing_file_is_an_error() {
    let file = TempFile::new("does-not-exist.exr");
    let m = err_message(read_layered_exr(file.path()));
    assert_mentions(&m, &["does not exist", "does-not-exist.exr"]);
    let m = err_message(read_rgb_exr(file.path()));
    assert_mentions(&m, &["does not exist"]);
}

#[test]
fn not_an_exr_is_an_error() {
    let cases: [(&str, &[u8], &str); 4] = [
        ("garbage.exr", b"this is not an image at all", "not an OpenEXR file"),
        ("empty.exr", b"", "empty"),
        ("short.exr", &[0x76, 0x2f], "2 bytes"),
        ("image.png", b"\x89PNG\r\n\x1a\n rest of a png", "PNG"),
    ];
    for (name, bytes, words) in cases {
        let file = TempFile::new(name);
        std::fs::write(file.path(), bytes).unwrap();
        let m = err_message(read_layered_exr(file.path()));
        assert_mentions(&m, &[words, name]);
    }
    // Random bytes after a valid signature.
    let mut rng = Pcg64::seed_from_u64(3);
    for i in 0..20 {
        // Signature, then half the time a plausible version field (2, single part), then noise.
        let mut bytes = vec![0x76, 0x2f, 0x31, 0x01];
        if i % 2 == 0 {
            bytes.extend([2, 0, 0, 0]);
        }
        bytes.extend((0..rng.random_range(0..400)).map(|_| rng.random::<u8>()));
        let file = TempFile::new(&format!("noise{i}.exr"));
        std::fs::write(file.path(), &bytes).unwrap();
        err_message(read_layered_exr(file.path()));
    }
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    err_message(read_layered_exr(&dir));
}

#[test]
fn truncated_exr_is_an_error() {
    let image = RgbImage::new(16, 16);
    let depth = vec![1.0f32; 256];
    let file = TempFile::new("whole.exr");
    write_exr(file.path(), &image, &[("Z", &depth)]).unwrap();
    let bytes = std::fs::read(file.path()).unwrap();
    assert!(read_layered_exr(file.path()).is_ok());
    for cut in [8, 40, bytes.len() / 2, bytes.len() - 20, bytes.len() - 1] {
        let cut_file = TempFile::new(&format!("cut{cut}.exr"));
        std::fs::write(cut_file.path(), &bytes[..cut]).unwrap();
        let m = err_message(read_layered_exr(cut_file.path()));
        assert_mentions(&m, &[&format!("cut{cut}.exr")]);
        assert!(m.contains("truncated") || m.contains("not a valid"), "cut at {cut} of {}: {m}", bytes.len());
    }
}

#[test]
fn missing_colour_or_depth_is_an_error() {
    // No colour at all.
    let file = TempFile::new("only-z.exr");
    write_channels(file.path(), 2, 2, vec![channel("Z", vec![1.0; 4])]);
    let m = err_message(read_layered_exr(file.path()));
    assert_mentions(&m, &["R, G and B", "Z"]);
    assert_mentions(&err_message(read_rgb_exr(file.path())), &["R, G and B"]);

    // Partial colour.
    let file = TempFile::new("rg.exr");
    write_channels(file.path(), 2, 2, vec![channel("R", vec![1.0; 4]), channel("G", vec![1.0; 4]), channel("Z", vec![1.0; 4])]);
    let m = err_message(read_layered_exr(file.path()));
    assert_mentions(&m, &["missing B"]);
    assert!(!m.contains("Z channel"), "the file has a Z channel: {m}");

    // Colour without depth.
    let file = TempFile::new("rgb.exr");
    write_exr(file.path(), &RgbImage::new(2, 2), &[("coc", &[0.0; 4])]).unwrap();
    assert_mentions(&err_message(read_layered_exr(file.path())), &["needs a Z channel", "rgb.exr"]);

    // A named layer without depth next to complete ones.
    let file = TempFile::new("layer-no-z.exr");
    let mut channels = Vec::new();
    for l in ["l0", "l1"] {
        for c in ["R", "G", "B"] {
            channels.push(channel(&format!("{l}.{c}"), vec![1.0; 4]));
        }
    }
    channels.push(channel("l0.Z", vec![1.0; 4]));
    write_channels(file.path(), 2, 2, channels);
    assert_mentions(&err_message(read_layered_exr(file.path())), &["`l1`", "needs a Z channel"]);

    // Only named layers, none with depth.
    let file = TempFile::new("passes.exr");
    let channels = ["R", "G", "B", "A"].iter().map(|c| channel(&format!("ViewLayer.Combined.{c}"), vec![1.0; 4])).collect();
    write_channels(file.path(), 2, 2, channels);
    assert_mentions(&err_message(read_layered_exr(file.path())), &["ViewLayer.Combined", "needs a Z channel"]);
}

#[test]
fn zero_size_is_an_error() {
    // A valid 1x1 file whose data window is patched to be empty (xMax = xMin - 1).
    let file = TempFile::new("one.exr");
    write_exr(file.path(), &RgbImage::new(1, 1), &[("Z", &[1.0])]).unwrap();
    let mut bytes = std::fs::read(file.path()).unwrap();
    let key = b"dataWindow\0box2i\0";
    let at = bytes.windows(key.len()).position(|w| w == key).unwrap() + key.len() + 4;
    bytes[at + 8..at + 12].copy_from_slice(&(-1i32).to_le_bytes());
    let zero = TempFile::new("zero.exr");
    std::fs::write(zero.path(), &bytes).unwrap();
    assert_mentions(&err_message(read_layered_exr(zero.path())), &["zero size", "zero.exr"]);
    assert_mentions(&err_message(read_rgb_exr(zero.path())), &["zero size"]);

    // Writers refuse zero sizes.
    let empty = RgbImage::new(0, 3);
    let out = TempFile::new("zero-out.exr");
    assert_mentions(&err_message(write_exr(out.path(), &empty, &[])), &["zero size"]);
    assert_mentions(&err_message(write_png_preview(out.path(), &empty, 1.0)), &["zero size"]);
}

/// A header that declares a huge image in a file of a few megabytes is refused from the header
/// alone, before anything is decoded or allocated, naming the file, the declared size and the
/// limit (and not "the device": no device is involved in reading a file).
#[test]
fn huge_declared_size_is_refused_from_the_header() {
    let file = TempFile::new("small.exr");
    write_exr(file.path(), &RgbImage::new(2, 2), &[("Z", &[1.0; 4])]).unwrap();
    let mut bytes = std::fs::read(file.path()).unwrap();
    let key = b"dataWindow\0box2i\0";
    let at = bytes.windows(key.len()).position(|w| w == key).unwrap() + key.len() + 4;
    bytes[at + 8..at + 12].copy_from_slice(&19999i32.to_le_bytes());
    bytes[at + 12..at + 16].copy_from_slice(&19999i32.to_le_bytes());
    // Padded to 3 MB: small enough, against 6.4 GB of declared pixel data, to pass the
    // expansion check, so only the size limit stands between the header and the allocation.
    bytes.resize(3 << 20, 0);
    let huge = TempFile::new("huge-header.exr");
    std::fs::write(huge.path(), &bytes).unwrap();
    for rgb in [false, true] {
        let start = std::time::Instant::now();
        let message = if rgb { err_message(read_rgb_exr(huge.path())) } else { err_message(read_layered_exr(huge.path())) };
        assert_mentions(&message, &["huge-header.exr", "20000x20000", &dof::io::MAX_EXR_EDGE.to_string(), "before decoding"]);
        assert!(!message.contains("device"), "{message}");
        assert!(start.elapsed() < std::time::Duration::from_secs(2), "refused after {:?}", start.elapsed());
    }
}

#[test]
fn mismatched_layer_sizes_are_an_error() {
    use exr::WritableImage;
    let layer = |name: &str, w: usize, h: usize| {
        let mut list = exr::SmallVec::new();
        for c in ["R", "G", "B", "Z"] {
            list.push(channel(c, vec![1.0; w * h]));
        }
        exr::Layer::new((w, h), exr::LayerAttributes::named(name), exr::Encoding::FAST_LOSSLESS, exr::AnyChannels::sort(list))
    };
    let image = exr::Image::from_layers(
        exr::ImageAttributes::new(exr::IntegerBounds::from_dimensions((4, 4))),
        vec![layer("layer0", 4, 4), layer("layer1", 3, 4)],
    );
    let file = TempFile::new("mismatch.exr");
    image.write().to_file(file.path()).unwrap();
    assert_mentions(&err_message(read_layered_exr(file.path())), &["sizes differ", "layer0", "layer1", "3x4", "4x4"]);
}

#[test]
fn writer_argument_errors() {
    let image = RgbImage::new(2, 2);
    let out = TempFile::new("args.exr");
    assert_mentions(&err_message(write_exr(out.path(), &image, &[("Z", &[1.0; 3])])), &["`Z`", "3 values", "4 pixels"]);
    assert_mentions(&err_message(write_exr(out.path(), &image, &[("R", &[1.0; 4])])), &["twice"]);
    assert_mentions(&err_message(write_exr(out.path(), &image, &[("a", &[1.0; 4]), ("a", &[1.0; 4])])), &["twice"]);
    for bad in ["", "with space", "naïve"] {
        err_message(write_exr(out.path(), &image, &[(bad, &[1.0; 4])]));
    }
    let inconsistent = RgbImage { width: 2, height: 2, data: vec![[0.0; 3]; 3] };
    err_message(write_exr(out.path(), &inconsistent, &[]));
    err_message(write_png_preview(out.path(), &inconsistent, 1.0));
    for exposure in [0.0, -1.0, f32::NAN, f32::INFINITY] {
        assert_mentions(&err_message(write_png_preview(out.path(), &image, exposure)), &["exposure"]);
    }
    let no_dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("dof-no-such-dir-image-io").join("x.exr");
    assert_mentions(&err_message(write_exr(&no_dir, &image, &[])), &["directory does not exist"]);
    assert!(!out.path().exists(), "failed writes leave no file");
}

// ---------------------------------------------------------------------------------------------
// NaN/Inf policy

#[test]
fn nan_inf_policy_and_counts() {
    let nan = f32::NAN;
    let inf = f32::INFINITY;
    // (premultiplied colour, alpha, depth) per pixel.
    let pixels: [([f32; 3], f32, f32); 10] = [
        ([nan, 0.5, 0.25], 1.0, 2.0),  // colour NaN -> 0
        ([inf, -inf, 1.0], 1.0, 2.0),  // +inf -> 65504, -inf -> 0
        ([1.0, 1.0, 1.0], 1.0, nan),   // depth NaN -> dropped
        ([1.0, 1.0, 1.0], 1.0, 0.0),   // depth 0 -> dropped
        ([1.0, 1.0, 1.0], 1.0, -3.0),  // negative depth -> dropped
        ([1.0, 1.0, 1.0], 1.0, inf),   // sky with colour -> background fragment with that colour
        ([0.0, 0.0, 0.0], 1.0, inf),   // black sky -> black background fragment
        ([0.5, 0.5, 0.5], 2.0, 1.0),   // alpha > 1 -> 1
        ([0.5, 0.5, 0.5], nan, 1.0),   // alpha NaN -> 0: light that hides nothing
        ([-0.5, 0.0, 0.0], 1.0, -inf), // depth -inf -> dropped (colour not looked at)
    ];
    let n = pixels.len();
    let file = TempFile::new("policy.exr");
    let mut channels = Vec::new();
    for (k, c) in ["R", "G", "B"].iter().enumerate() {
        channels.push(channel(c, pixels.iter().map(|p| p.0[k]).collect()));
    }
    channels.push(channel("A", pixels.iter().map(|p| p.1).collect()));
    channels.push(channel("Z", pixels.iter().map(|p| p.2).collect()));
    write_channels(file.path(), n, 1, channels);

    let (image, report) = read_layered_exr(file.path()).unwrap();
    assert_eq!(
        report.counts,
        SanitizeCounts {
            color_nan: 1,
            color_inf: 2,
            alpha_invalid: 2,
            depth_invalid: 4,
            behind_background: 0,
            background: 2,
            empty_alpha: 0,
            emission_only: 1,
        }
    );
    assert_eq!(report.repaired(), 9);
    assert_eq!(report.total(), 10, "backgrounds are data, not repairs; emission is noted");
    let text = report.to_string();
    assert_mentions(
        &text,
        &[
            "1 NaN colour",
            "2 infinite colour",
            "4 fragments with NaN, zero or negative depth",
            "2 background fragments (depth +inf or >= 1e10)",
            "1 fragments with alpha 0 and a colour, read as light that hides nothing",
        ],
    );

    let frag = |x: u32| image.pixel(x, 0);
    assert_eq!(frag(0), [Fragment { color: [0.0, 0.5, 0.25], alpha: 1.0, depth: 2.0 }]);
    assert_eq!(frag(1), [Fragment { color: [COLOR_INF_REPLACEMENT, 0.0, 1.0], alpha: 1.0, depth: 2.0 }]);
    assert_eq!(COLOR_INF_REPLACEMENT, 65504.0);
    assert_eq!(frag(8), [Fragment { color: [0.5; 3], alpha: 0.0, depth: 1.0 }]);
    for x in [2, 3, 4, 9] {
        assert!(frag(x).is_empty(), "pixel {x} should be empty: {:?}", frag(x));
    }
    assert_eq!(frag(5), [background([1.0; 3])], "the sky's colour is kept");
    assert_eq!(frag(6), [background([0.0; 3])], "a black sky is still a background fragment");
    assert_eq!(frag(7), [Fragment { color: [0.5; 3], alpha: 1.0, depth: 1.0 }]);
    for p in 0..n as u32 {
        for f in frag(p) {
            assert!(f.color.iter().all(|c| c.is_finite()) && f.depth > 0.0);
            assert!(f.depth.is_finite() || f.alpha == 1.0, "a background is opaque");
        }
    }

    // The RGB reader applies the colour rules.
    let (rgb, report) = read_rgb_exr(file.path()).unwrap();
    assert_eq!((report.counts.color_nan, report.counts.color_inf), (1, 2));
    assert_eq!(rgb.data[0], [0.0, 0.5, 0.25]);
    assert_eq!(rgb.data[1], [COLOR_INF_REPLACEMENT, 0.0, 1.0]);
    assert_eq!(rgb.data[9], [-0.5, 0.0, 0.0], "finite negative colour is kept");
    assert!(rgb.data.iter().flatten().all(|c| c.is_finite()));
}

// ---------------------------------------------------------------------------------------------
// Tone map and PNG

#[test]
fn tonemap_fixed_points() {
    assert_eq!(tonemap([0.0; 3], 1.0), [0.0; 3]);
    assert_eq!(tonemap([1e6; 3], 1.0), [1.0; 3]);
    assert_eq!(tonemap([f32::INFINITY; 3], 1.0), [1.0; 3]);
    assert_eq!(tonemap([f32::NAN, -1.0, f32::NEG_INFINITY], 1.0), [0.0; 3]);
    // ACES fitted at 1: 2.54 / 3.16.
    assert!((aces_fitted(1.0) - 2.54 / 3.16).abs() < 1e-6);
    assert!((aces_fitted(0.18) - 0.18 * (2.51 * 0.18 + 0.03) / (0.18 * (2.43 * 0.18 + 0.59) + 0.14)).abs() < 1e-7);
    assert!(aces_fitted(7.0) < 1.0 && aces_fitted(7.3) == 1.0, "saturates near x = 7.24");
    // Exposure scales the input.
    assert_eq!(tonemap([0.5; 3], 2.0), tonemap([1.0; 3], 1.0));
    assert_eq!(tonemap([0.3, 0.0, 2.0], 1.0)[0], srgb_oetf(aces_fitted(0.3)));
    // sRGB at known points.
    assert_eq!(srgb_oetf(0.0), 0.0);
    assert_eq!(srgb_oetf(1.0), 1.0);
    assert!((srgb_oetf(0.0031308) - 0.04045).abs() < 1e-5, "the linear segment meets the curve");
    assert!((srgb_oetf(0.5) - 0.735_357).abs() < 1e-6);
    assert!((srgb_oetf(0.18) - 0.461_356).abs() < 1e-5);
    assert!((srgb_oetf(0.001) - 0.01292).abs() < 1e-7);
    assert_eq!(to_u8(srgb_oetf(0.5)), 188);
    assert_eq!(to_u8(srgb_oetf(srgb_eotf(128.0 / 255.0))), 128);
    for i in 0..=100 {
        let v = i as f32 / 100.0;
        assert!((srgb_eotf(srgb_oetf(v)) - v).abs() < 1e-5, "EOTF inverts OETF at {v}");
    }
}

#[test]
fn tonemap_is_monotone_and_approaches_one() {
    let mut previous = 0.0;
    let mut x = 1e-6f32;
    while x < 1e6 {
        let y = tonemap([x; 3], 1.0)[0];
        assert!(y >= previous, "tone map decreases at {x}: {y} < {previous}");
        assert!((0.0..=1.0).contains(&y));
        if x < 7.0 {
            assert!(y < 1.0);
        }
        previous = y;
        x *= 1.01;
    }
    assert_eq!(previous, 1.0);
    assert!(tonemap([5.0; 3], 1.0)[0] > 0.99, "bright values come close to white");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]
    #[test]
    fn tonemap_is_total_and_ordered(a in proptest::num::f32::ANY, b in proptest::num::f32::ANY, e in proptest::num::f32::ANY) {
        let (ta, tb) = (tonemap([a; 3], 1.0)[0], tonemap([b; 3], 1.0)[0]);
        prop_assert!((0.0..=1.0).contains(&ta) && (0.0..=1.0).contains(&tb));
        if a <= b {
            prop_assert!(ta <= tb, "{a} -> {ta}, {b} -> {tb}");
        }
        let t = tonemap([a, b, 1.0], e);
        prop_assert!(t.iter().all(|v| (0.0..=1.0).contains(v)));
    }
}

#[test]
fn png_preview_is_decodable() {
    let (w, h) = (5u32, 3u32);
    let mut image = RgbImage::new(w, h);
    for (i, c) in image.data.iter_mut().enumerate() {
        *c = [i as f32 * 0.1, (i as f32 * 0.37).sin().abs() * 4.0, 1.0 / (1.0 + i as f32)];
    }
    image.data[4] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY];
    let exposure = 1.5;
    let file = TempFile::new("preview.png");
    write_png_preview(file.path(), &image, exposure).unwrap();

    let reader = std::io::BufReader::new(std::fs::File::open(file.path()).unwrap());
    let mut reader = png::Decoder::new(reader).read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!((info.width, info.height), (w, h));
    assert_eq!(info.color_type, png::ColorType::Rgb);
    assert_eq!(info.bit_depth, png::BitDepth::Eight);
    let bytes = &buf[..info.buffer_size()];
    for (p, c) in image.data.iter().enumerate() {
        assert_eq!(bytes[p * 3..p * 3 + 3], tonemap_to_srgb8(*c, exposure), "pixel {p}");
    }
    assert_eq!(bytes[12..15], [0, 255, 0], "NaN -> black, +inf -> white, -inf -> black");
}

#[test]
fn corrupted_files_never_panic() {
    let mut rng = Pcg64::seed_from_u64(4);
    let mut image = random_image(&mut rng, 9, 7);
    image.data[3] = [f32::NAN; 3];
    let depth: Vec<f32> = (0..63).map(|i| 1.0 + i as f32).collect();
    let mut originals = Vec::new();
    for (name, precision, compression) in [
        ("f32", ExrPrecision::Float, ExrCompression::Zip),
        ("f16", ExrPrecision::Half, ExrCompression::Zip),
        ("raw", ExrPrecision::Float, ExrCompression::None),
    ] {
        let file = TempFile::new(&format!("fuzz-{name}.exr"));
        write_exr_with(file.path(), &image, &[("Z", &depth)], &ExrWriteOptions { precision, compression, window: None }).unwrap();
        originals.push(std::fs::read(file.path()).unwrap());
    }
    let mut layered = LayeredImage::new(3, 2, 2).unwrap();
    layered.push(1, 1, Fragment { color: [1.0; 3], alpha: 0.5, depth: 2.0 }).unwrap();
    let file = TempFile::new("fuzz-layered.exr");
    write_layered_exr(file.path(), &layered).unwrap();
    originals.push(std::fs::read(file.path()).unwrap());

    let cases: usize = std::env::var("DOF_FUZZ_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(150);
    let target = TempFile::new("fuzz.exr");
    for case in 0..cases {
        let mut bytes = originals[case % originals.len()].clone();
        for _ in 0..rng.random_range(1..4) {
            let at = rng.random_range(0..bytes.len());
            match rng.random_range(0..3) {
                0 => bytes[at] ^= 1 << rng.random_range(0..8),
                1 => bytes[at] = rng.random(),
                _ => bytes.truncate(at.max(4)),
            }
        }
        std::fs::write(target.path(), &bytes).unwrap();
        // Either outcome is fine; a panic fails the test.
        let _ = read_layered_exr(target.path());
        let _ = read_rgb_exr(target.path());
    }
}

/// Expectation: a FIFO, a device and a directory given as an EXR input are refused as not regular
/// files by every reader (layered, colour, the header check a mask goes through), at once: nothing
/// opens the FIFO, which would wait for a writer forever.
#[test]
fn special_files_are_refused_without_blocking() {
    let dir = TempFile::new("special");
    std::fs::create_dir_all(&dir.0).unwrap();
    let fifo = dir.0.join("shot.exr");
    let mut inputs = vec![(PathBuf::from("/dev/zero"), "not a regular file"), (dir.0.clone(), "is a directory")];
    match std::process::Command::new("mkfifo").arg(&fifo).status() {
        Ok(s) if s.success() => inputs.push((fifo, "not a regular file")),
        other => panic!("mkfifo failed ({other:?}): the FIFO case needs it"),
    }
    for (path, words) in inputs {
        let (tx, rx) = std::sync::mpsc::channel();
        let p = path.clone();
        std::thread::spawn(move || {
            let _ = tx.send([err_message(read_layered_exr(&p)), err_message(read_rgb_exr(&p)), err_message(dof::io::check_exr_header(&p))]);
        });
        let messages = rx.recv_timeout(std::time::Duration::from_secs(20)).unwrap_or_else(|_| panic!("reading {} blocked", path.display()));
        for m in messages {
            assert_mentions(&m, &[words]);
        }
    }
    let _ = std::fs::remove_dir_all(&dir.0);
}

/// A sequence's preview is encoded frame by frame (memory holds one frame): the same bytes as
/// writing every frame at once, and nothing left behind when dropped unfinished.
#[test]
fn a_gif_preview_streams_its_frames_and_leaves_nothing_when_dropped() {
    use dof::io::{GifPreview, write_gif_preview};
    let dir = std::env::temp_dir().join(format!("dof-gif-stream-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let frame = |k: f32| RgbImage { width: 20, height: 12, data: (0..240).map(|i| [i as f32 / 240.0, k, 0.5]).collect() };
    let frames = [frame(0.1), frame(0.7)];
    write_gif_preview(dir.join("all.gif"), &frames, 1.0, 80).unwrap();
    let mut streamed = GifPreview::create(dir.join("streamed.gif"), 20, 12, 1.0, 80).unwrap();
    for f in &frames {
        streamed.push(f).unwrap();
    }
    streamed.finish().unwrap();
    assert_eq!(std::fs::read(dir.join("all.gif")).unwrap(), std::fs::read(dir.join("streamed.gif")).unwrap());
    let mut dropped = GifPreview::create(dir.join("dropped.gif"), 20, 12, 1.0, 80).unwrap();
    dropped.push(&frames[0]).unwrap();
    assert!(dropped.push(&RgbImage::new(4, 4)).is_err(), "a frame of another size");
    drop(dropped);
    let mut names: Vec<String> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    assert_eq!(names, ["all.gif", "streamed.gif"], "no partial or temporary file");
    let _ = std::fs::remove_dir_all(&dir);
}
