//! Inputs that fuzzing (`fuzz/`, cargo-fuzz) found to crash the library or break its promises, each
//! replayed through the library as an ordinary test. The reproducers lie in `fuzz/regressions/<target>/`
//! (the structured `lens` inputs with a `.txt` beside them: the values they decode to, which the
//! tests here spell out); `.ci/fuzz` also replays them with the fuzz targets.
//!
//! A counting allocator records the largest single allocation, so that "refused without allocating"
//! is checked, not only "refused".

use dof::frame::Extent;
use std::alloc::{GlobalAlloc, Layout, System};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

use dof::scene::{ArtistLens, Camera, Vec3, validate_artist_lens};
use dof::{CoreError, Error};

struct Counting;

static LARGEST: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        LARGEST.fetch_max(layout.size(), Ordering::Relaxed);
        unsafe { System.alloc(layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        LARGEST.fetch_max(layout.size(), Ordering::Relaxed);
        unsafe { System.alloc_zeroed(layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        LARGEST.fetch_max(new_size, Ordering::Relaxed);
        unsafe { System.realloc(ptr, layout, new_size) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// The largest single allocation `f` made (other tests of this binary allocate little at a time).
fn largest_allocation<T>(f: impl FnOnce() -> T) -> (T, usize) {
    LARGEST.store(0, Ordering::Relaxed);
    let out = f();
    (out, LARGEST.load(Ordering::Relaxed))
}

fn regression(target: &str, name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../fuzz/regressions").join(target).join(name)
}

/// A primitive whose `POSITION` names an accessor that does not exist: the gltf crate's validation
/// indexes the accessors with it and panics (gltf-json 1.4.1, `mesh.rs`). A reproducer of the `gltf`
/// target (a mutated `"accessors"` key); `scene/gltf_load.rs` checks that reference before the
/// crate validates.
#[test]
fn gltf_position_naming_a_missing_accessor_is_an_error() {
    let path = regression("gltf", "position-accessor-out-of-range.gltf");
    let bytes = std::fs::read(&path).unwrap();
    let err = dof::scene::load_gltf_slice(&bytes).unwrap_err();
    assert!(matches!(err, Error::Scene(_)), "{err}");
    let message = err.to_string();
    assert!(
        message.contains("not a valid glTF 2.0 file") && message.contains("POSITION") && message.contains("accessor 0 does not exist"),
        "{message}"
    );
    let err = dof::scene::load_gltf(&path).unwrap_err();
    assert!(err.to_string().contains("position-accessor-out-of-range.gltf"), "{err}");

    // In a GLB, and with an index far beyond the accessors present.
    let json = br#"{"asset":{"version":"2.0"},"accessors":[],"meshes":[{"primitives":[{"attributes":{"POSITION":4000000000}}]}]}"#;
    let mut glb = Vec::new();
    let padded = json.len().div_ceil(4) * 4;
    glb.extend_from_slice(b"glTF");
    glb.extend_from_slice(&2u32.to_le_bytes());
    glb.extend_from_slice(&(12 + 8 + padded as u32).to_le_bytes());
    glb.extend_from_slice(&(padded as u32).to_le_bytes());
    glb.extend_from_slice(b"JSON");
    glb.extend_from_slice(json);
    glb.resize(12 + 8 + padded, b' ');
    let err = dof::scene::load_gltf_slice(&glb).unwrap_err();
    assert!(err.to_string().contains("POSITION"), "{err}");
}

/// What the gltf crate's accessors unwrap without its validation checking it (gltf 1.4.1): an image
/// with neither `uri` nor `bufferView` (`Image::source`, a reproducer of the `gltf` target: a mutated
/// `"bufferView"` key), an image `bufferView` without `mimeType` (same function), a camera whose
/// `type` names a projection it lacks (`Camera::projection`). Each panics once a primitive uses
/// the image or a node the camera; `scene/gltf_load.rs` refuses them before loading.
#[test]
fn gltf_images_and_cameras_without_what_they_need_are_errors() {
    for (file, expected) in [
        ("image-without-uri-or-buffer-view.gltf", "images[0] has neither a uri nor a bufferView"),
        ("image-buffer-view-without-mime-type.gltf", "images[0] has a bufferView but no mimeType"),
        ("camera-without-its-projection.gltf", "cameras[0] is of type perspective but has no `perspective` object"),
    ] {
        let path = regression("gltf", file);
        let err = dof::scene::load_gltf_slice(&std::fs::read(&path).unwrap()).unwrap_err();
        assert!(matches!(err, Error::Scene(_)), "{file}: {err}");
        assert!(err.to_string().contains(expected), "{file}: {err}");
        let err = dof::scene::load_gltf(&path).unwrap_err();
        assert!(err.to_string().contains(expected), "{file}: {err}");
    }
}

/// A palette PNG of 6x100925440 pixels in 115 bytes: a mask reader that allocates its output
/// before checking the size (1 to 8192 a side) asks for 2.4 GB. A reproducer of the `aperture_png`
/// target (libFuzzer's malloc limit); `aperture.rs` checks the header's size first.
#[test]
fn aperture_png_of_a_huge_size_is_refused_before_its_pixels_are_allocated() {
    let path = regression("aperture_png", "palette-6x100925440.png");
    let (result, largest) = largest_allocation(|| dof::aperture::image_aperture(&path));
    let err = result.unwrap_err();
    assert!(matches!(err, CoreError::InvalidArgument(_)), "{err}");
    assert!(err.to_string().contains("6x100925440 is not a usable size"), "{err}");
    assert!(largest < 16 << 20, "refusing it allocated {largest} bytes at once");
    // Through `--aperture`'s parser too.
    let err = dof::aperture::parse_aperture(path.to_str().unwrap()).unwrap_err();
    assert!(err.to_string().contains("not a usable size"), "{err}");
}

/// A palette PNG whose PLTE chunk is 14 bytes (not whole RGB entries): png 0.18's palette
/// expansion indexes past it and panics. A reproducer of the `aperture_png` target; `aperture.rs`
/// checks the palette (and its transparency chunk) before decoding.
#[test]
fn aperture_png_with_a_partial_palette_entry_is_refused() {
    let path = regression("aperture_png", "palette-of-14-bytes.png");
    let err = dof::aperture::image_aperture(&path).unwrap_err();
    assert!(matches!(err, CoreError::InvalidArgument(_)), "{err}");
    assert!(err.to_string().contains("palette of 14 bytes"), "{err}");
}

/// An artist lens with `max_radius_px` 3.4e38: valid by `ArtistLens::is_valid`, but its CoC
/// diameter `2 · max_radius_px` overflows and the sharp zone's CoC is `inf · 0` = NaN. A reproducer
/// of the `lens` target (`fuzz/regressions/lens/artist-lens-diameter-overflows`); in
/// `scene/lens.rs`, `validate_artist_lens` refuses a radius whose diameter is not finite. (The
/// kernel crate's `signed_coc_px` multiplies `2 · max_radius_px` first.)
#[test]
fn an_artist_lens_whose_coc_diameter_overflows_is_refused() {
    let v = 3.396_151_4e38;
    let lens = ArtistLens { near_start: v, near_end: v, far_start: v, far_end: v, max_radius_px: v };
    let err = validate_artist_lens(&lens).unwrap_err();
    assert!(matches!(err, dof::Error::Core(CoreError::InvalidArgument(_))), "{err}");
    // The largest radius accepted gives a number everywhere.
    let largest = ArtistLens { max_radius_px: f32::MAX / 2.0, ..lens };
    validate_artist_lens(&largest).unwrap();
    for z in [f32::MIN_POSITIVE, 1.0, v, f32::MAX, f32::INFINITY] {
        assert!(!largest.coc_px(z).is_nan(), "depth {z}");
    }
    assert!(validate_artist_lens(&ArtistLens { max_radius_px: f32::MAX, ..lens }).is_err());
}

/// Cameras whose view axis (`target − eye`) or `forward × up` is so short that its squared length
/// is subnormal: `Camera::frame` accepts them, and normalised naively their axes, documented as
/// unit, come out 0.989 and 0.995 long, so pixel rays would be off. Reproducers of the `lens` target
/// (`fuzz/regressions/lens/camera-axes-underflow`, `camera-view-axis-underflows`). In
/// `scene/camera.rs` vectors are scaled by their largest component before normalising.
#[test]
fn a_camera_whose_axes_underflow_is_refused_or_has_unit_axes() {
    let cameras = [
        Camera {
            eye: Vec3::new(1.812_401_4e-22, 1.283_005_8e-22, 1.283_005_8e-22),
            target: Vec3::splat(1.283_005_8e-22),
            up: Vec3::splat(1.283_005_8e-22),
            yfov_radians: 1.283_005_8e-22,
            width: 454_761_243,
            height: 454_761_243,
        },
        Camera {
            eye: Vec3::new(3.474_963_8e-25, 1.212_387_3e-25, 1.212_387_3e-25),
            target: Vec3::new(3.474_906_2e-25, 1.180_075_5e-25, 1.291_309_9e-22),
            up: Vec3::Y,
            yfov_radians: 1.184_157_5e-28,
            width: 370_546_198,
            height: 672_536_086,
        },
    ];
    for camera in cameras {
        if let Ok(frame) = camera.frame() {
            for (name, v) in [("forward", frame.forward), ("right", frame.right), ("up", frame.up)] {
                assert!((v.length() - 1.0).abs() < 1e-3, "{name} is {} long for {camera:?}", v.length());
            }
        }
    }
}

/// Aperture descriptions the frame contexts take on trust (`ApertureShape`'s fields are public):
/// `blades` 2^32 - 1 makes the bokeh kernels loop for ever (the `frame` target's timeout,
/// `fuzz/regressions/frame/aperture-with-4294967295-blades`), and a mask shorter than `side²` is
/// read out of bounds (on the CPU backend a kernel fault in `bokeh::emit_pass`, on a GPU a stray
/// read). The splatting and bokeh contexts refuse an aperture that the constructors in
/// `aperture` could not have made (`ApertureShape::check`).
#[test]
fn frame_contexts_refuse_inconsistent_apertures() {
    use dof::aperture::ApertureShape;
    use dof::backend::CpuBackend;
    use dof::dof_shaders::aperture::Aperture;
    use dof::frame::{BokehContext, BokehContextDesc, SplatContext, SplatContextDesc};
    use dof::methods::bokeh::BokehOptions;
    use dof::methods::splat::SplatOptions;
    let apertures = [
        ApertureShape { kernel: Aperture { blades: u32::MAX, ..Aperture::circle() }, mask: Vec::new() },
        ApertureShape { kernel: Aperture { mask: 64, ..Aperture::circle() }, mask: vec![1.0; 819] },
    ];
    for aperture in apertures {
        let mut b = CpuBackend::new();
        let options = BokehOptions { aperture: aperture.clone(), ..Default::default() };
        let bokeh = BokehContext::new(&mut b, &BokehContextDesc::new(Extent::new(16, 16, 1), options));
        assert!(bokeh.is_err(), "a bokeh context accepted {:?}", aperture.kernel);
        let options = SplatOptions { aperture: aperture.clone(), ..Default::default() };
        let splat = SplatContext::new(&mut b, &SplatContextDesc::new(Extent::new(16, 16, 1), options));
        assert!(splat.is_err(), "a splatting context accepted {:?}", aperture.kernel);
    }
}

/// Every reproducer of the file-format targets, whatever it is: `Ok` or `Err`, no panic (a file
/// dropped into `fuzz/regressions/<target>/` is replayed here without further code).
#[test]
fn every_file_reproducer_gives_a_result() {
    let dir = |t: &str| Path::new(env!("CARGO_MANIFEST_DIR")).join("../fuzz/regressions").join(t);
    let files = |t: &str| -> Vec<PathBuf> { std::fs::read_dir(dir(t)).map(|d| d.map(|e| e.unwrap().path()).collect()).unwrap_or_default() };
    for path in files("gltf") {
        let _ = dof::scene::load_gltf_slice(&std::fs::read(&path).unwrap());
        let _ = dof::scene::load_gltf(&path);
    }
    for path in files("exr") {
        let _ = dof::io::read_layered_exr(&path);
        let _ = dof::io::read_rgb_exr(&path);
    }
    for path in files("aperture_png") {
        let (_, largest) = largest_allocation(|| dof::aperture::image_aperture(&path));
        assert!(largest < 512 << 20, "{}: {largest} bytes at once", path.display());
    }
}
