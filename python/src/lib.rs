//! The Python module `dof`: numpy arrays in and out of every method of the frame registry
//! (`dof::frame::registry::METHODS`), through the library's one-shot path
//! (`dof::methods::one_shot::one_shot`), with the lens built by the library's own lens types
//! (`LensSettings::thin_lens`) as `dof render` builds it for an EXR, and the library's EXR I/O.

use std::path::PathBuf;

use dof::backend::{Backend, WgpuBackend, WgpuOptions};
use dof::frame::{Kind, METHODS, MethodInfo, MethodOptions, Value};
use dof::io::SanitizeCounts;
use dof::layers::{Fragment, LayeredImage, RgbImage};
use dof::methods::one_shot::one_shot;
use dof::scene::{Aperture, Camera, LensSettings, MAX_GUARD_BAND, ThinLens, Vec3};
use dof::{CoreError, CpuBackend, Error, VulkanBackend, VulkanOptions};
use numpy::ndarray::Dimension;
use numpy::ndarray::{Array2, Array3, Array4, ArrayViewD, Axis};
use numpy::{AllowTypeChange, IntoPyArray, PyArray3, PyArrayLikeDyn, PyUntypedArrayMethods};
use pyo3::exceptions::{PyMemoryError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyTuple};

/// A library error as a Python exception: bad input (an invalid argument or lens, a size beyond a
/// limit) is a `ValueError`, anything else (no Vulkan driver, a device failure) a `RuntimeError`;
/// the message is the library's, as the CLI prints it.
fn py_err(e: impl Into<Error>) -> PyErr {
    let e: Error = e.into();
    match e {
        Error::Core(
            CoreError::InvalidArgument(_) | CoreError::InvalidLens(_) | CoreError::ResizeNeeded { .. } | CoreError::TooLarge { .. },
        )
        | Error::Scene(_) => PyValueError::new_err(e.to_string()),
        Error::Core(CoreError::HostMemory { .. }) => PyMemoryError::new_err(e.to_string()),
        _ => PyRuntimeError::new_err(e.to_string()),
    }
}

fn value_error(msg: impl Into<String>) -> PyErr {
    PyValueError::new_err(msg.into())
}

/// The frame API's options from `blur`'s keyword options, checked by the method's registry entry
/// as `dof render` checks its flags: a bool is a flag, an int a count, a float a number and a str a
/// name; an int where a count is wanted is never rounded from a float.
fn method_options(method: &MethodInfo, options: Option<&Bound<'_, PyDict>>) -> PyResult<MethodOptions> {
    let mut values = Vec::new();
    for (key, value) in options.into_iter().flat_map(|o| o.iter()) {
        let key: String = key.extract()?;
        let value = if let Ok(b) = value.cast::<PyBool>() {
            Value::Flag(b.is_true())
        } else if let Ok(i) = value.extract::<i64>() {
            Value::Int(i)
        } else if let Ok(f) = value.extract::<f64>() {
            Value::Number(f)
        } else if let Ok(t) = value.extract::<String>() {
            Value::Text(t)
        } else {
            return Err(value_error(format!("option {key}: expected a bool, a number or a str, got {}", value.get_type().name()?)));
        };
        values.push((key, value));
    }
    method.method_options(values).map_err(py_err)
}

/// The lens as `dof render` builds it for an EXR (which carries no camera): a camera at the origin
/// with `yfov` degrees, the focus and aperture as given, the focal length in mm (default: from the
/// sensor height and the field of view). `pixels_per_unit`, when given, replaces the pixel scale
/// the field of view gives.
#[allow(clippy::too_many_arguments)]
fn lens(
    width: u32,
    height: u32,
    focus: f32,
    aperture_radius: Option<f32>,
    f_number: Option<f32>,
    focal_length: Option<f32>,
    sensor_height: f32,
    yfov: f32,
    pixels_per_unit: Option<f32>,
    metres_per_unit: f32,
) -> PyResult<ThinLens> {
    let aperture = match (aperture_radius, f_number) {
        (Some(_), Some(_)) => return Err(value_error("give the aperture as aperture_radius or f_number, not both")),
        (Some(r), None) => Aperture::Radius(r),
        (None, Some(n)) => Aperture::FNumber(n),
        (None, None) => {
            return Err(value_error("the lens needs an aperture: give aperture_radius (scene units) or f_number (with focus)"));
        }
    };
    if !(yfov > 0.0 && yfov < 180.0) {
        return Err(value_error(format!("yfov (the vertical field of view) must lie strictly between 0 and 180 degrees, got {yfov}")));
    }
    let camera = Camera::look_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0), yfov.to_radians(), width, height);
    let mut settings = LensSettings::photographic(focus, 8.0);
    settings.aperture = aperture;
    settings.focal_length_mm = focal_length;
    settings.sensor_height_mm = sensor_height;
    settings.metres_per_unit = metres_per_unit;
    let mut lens = settings.thin_lens(&camera).map_err(py_err)?;
    if let Some(ppu) = pixels_per_unit {
        if !(ppu > 0.0 && ppu.is_finite()) {
            return Err(value_error(format!(
                "pixels_per_unit (pixels per scene unit on the sensor) must be positive and finite, got {ppu}"
            )));
        }
        lens.pixels_per_unit = ppu;
        if !lens.is_valid() || !lens.far_limit_px().is_finite() {
            return Err(value_error(format!("the lens settings give an unusable lens: {lens:?}")));
        }
    }
    Ok(lens)
}

/// How far the image's edge pixels are extended (the CLI's edge policy for EXR input): the largest
/// CoC radius among its fragments, at most `MAX_GUARD_BAND`.
fn edge_margin(layers: &LayeredImage, lens: &ThinLens) -> u32 {
    let used = layers.counts.iter().enumerate().flat_map(|(p, &n)| {
        let start = p * layers.max_layers as usize;
        layers.fragments[start..start + n.min(layers.max_layers) as usize].iter()
    });
    let largest = used.map(|f| lens.coc_radius_px(f.depth)).fold(0.0f32, f32::max);
    (largest.ceil() as u32).min(MAX_GUARD_BAND)
}

/// Most pixels along one edge (as `dof render`'s `--width`).
const MAX_EDGE: usize = 65536;

fn check_size(h: usize, w: usize) -> PyResult<(u32, u32)> {
    if h == 0 || w == 0 || h > MAX_EDGE || w > MAX_EDGE {
        return Err(value_error(format!("the image must be 1 to {MAX_EDGE} pixels on each side, got {h}x{w} (height x width)")));
    }
    Ok((w as u32, h as u32))
}

/// An RGB image (H, W, 3) and its depth (H, W) as a one-layer image.
fn rgbz_image(rgb: ArrayViewD<'_, f32>, depth: ArrayViewD<'_, f32>) -> PyResult<LayeredImage> {
    let (h, w) = (rgb.shape()[0], rgb.shape()[1]);
    if rgb.shape()[2] != 3 {
        return Err(value_error(format!("rgb must have shape (H, W, 3), got {:?}", rgb.shape())));
    }
    if depth.shape() != [h, w] {
        return Err(value_error(format!("depth must have shape (H, W) = ({h}, {w}) like rgb, got {:?}", depth.shape())));
    }
    let (width, height) = check_size(h, w)?;
    let mut image = LayeredImage::new(width, height, 1).map_err(py_err)?;
    // Infinite and NaN colours under the EXR readers' policy (+inf → 65504, NaN and -inf → 0).
    let mut policy = SanitizeCounts::default();
    for y in 0..h {
        for x in 0..w {
            let color = [0, 1, 2].map(|c| policy.color(rgb[[y, x, c]]));
            image.push(x as u32, y as u32, Fragment { color, alpha: 1.0, depth: depth[[y, x]] }).map_err(py_err)?;
        }
    }
    Ok(image)
}

/// A multi-layer array (H, W, L, 4: r, g, b, depth; or 5 with alpha last) and its counts (H, W).
/// The colour is premultiplied by alpha (the library's slots, OpenEXR's convention, what
/// `read_exr(layers=True)` returns) unless `straight_alpha`, when it is premultiplied here.
fn layered_image(frags: ArrayViewD<'_, f32>, counts: ArrayViewD<'_, i64>, straight_alpha: bool) -> PyResult<LayeredImage> {
    let s = frags.shape();
    let (h, w, l, c) = (s[0], s[1], s[2], s[3]);
    if c != 4 && c != 5 {
        return Err(value_error(format!(
            "a multi-layer image must have shape (H, W, L, 4) (r, g, b, depth) or (H, W, L, 5) (r, g, b, depth, alpha), got {s:?}"
        )));
    }
    if counts.shape() != [h, w] {
        return Err(value_error(format!("counts must have shape (H, W) = ({h}, {w}), got {:?}", counts.shape())));
    }
    let (width, height) = check_size(h, w)?;
    if l == 0 || l > u32::MAX as usize {
        return Err(value_error(format!("a multi-layer image needs at least one layer, got {l}")));
    }
    let mut image = LayeredImage::new(width, height, l as u32).map_err(py_err)?;
    let mut policy = SanitizeCounts::default();
    for y in 0..h {
        for x in 0..w {
            let n = counts[[y, x]];
            if n < 0 || n as usize > l {
                return Err(value_error(format!("counts[{y}, {x}] = {n} must lie between 0 and the {l} layers")));
            }
            for k in 0..n as usize {
                let f = |i: usize| frags[[y, x, k, i]];
                let alpha = if c == 5 { f(4) } else { 1.0 };
                if !(0.0..=1.0).contains(&alpha) {
                    return Err(value_error(format!("alpha {alpha} of layer {k} at ({x}, {y}) must lie in [0, 1]")));
                }
                // A `Fragment` holds premultiplied colour (the library's slots).
                let raw = [0, 1, 2].map(|i| policy.color(f(i)));
                let color = if straight_alpha { dof::dof_shaders::slot::premultiply(raw, alpha) } else { raw };
                image.push(x as u32, y as u32, Fragment { color, alpha, depth: f(3) }).map_err(py_err)?;
            }
        }
    }
    Ok(image)
}

fn make_backend(name: &str) -> PyResult<Box<dyn Backend>> {
    match name {
        "cpu" => Ok(Box::new(CpuBackend::new())),
        "vulkan" => Ok(Box::new(VulkanBackend::new(&VulkanOptions::default()).map_err(py_err)?)),
        "wgpu" => Ok(Box::new(WgpuBackend::new(&WgpuOptions::default()).map_err(py_err)?)),
        _ => Err(value_error(format!("unknown backend '{name}': use 'cpu', 'vulkan' or 'wgpu'"))),
    }
}

fn to_rgb_array(image: &RgbImage) -> PyResult<Array3<f32>> {
    cropped_array(image, 0)
}

/// `image` without `margin` pixels on every side as an (H, W, 3) array; a `MemoryError` where the
/// machine cannot hold it.
fn cropped_array(image: &RgbImage, margin: u32) -> PyResult<Array3<f32>> {
    let (w, h) = (image.width.saturating_sub(2 * margin) as usize, image.height.saturating_sub(2 * margin) as usize);
    let mut data = Vec::new();
    data.try_reserve_exact(3 * w * h)
        .map_err(|_| PyMemoryError::new_err(format!("out of host memory: the {w}x{h} result needs {} bytes", 12 * w * h)))?;
    let (m, row) = (margin as usize, image.width as usize);
    for y in m..m + h {
        data.extend(image.data[y * row + m..y * row + m + w].iter().flatten());
    }
    Array3::from_shape_vec((h, w, 3), data).map_err(shape_error)
}

/// Blurs an image with depth of field and returns the result as a (H, W, 3) float32 array.
///
/// Input, either
///   - `image` RGB (H, W, 3) and `depth` (H, W): linear colour and planar depth in scene units
///     (> 0; +inf is the background), or
///   - `image` a multi-layer array (H, W, L, 4) of fragments (r, g, b, depth), front to back, or
///     (H, W, L, 5) with alpha last, and `depth` the fragment counts per pixel (H, W). The colour
///     of a fragment with alpha is **premultiplied** by it, as OpenEXR stores it and as
///     `read_exr(layers=True)` returns it: a fragment with alpha 0 and a colour is light that hides
///     nothing. With `straight_alpha=True` the colour is straight and is premultiplied here.
///     `footprints` (H, W, L) unsigned integers, with `footprint_side` 1 to 4, gives each
///     fragment the sub-samples of a `side x side` grid of its pixel it covers (bit `j*side + i`
///     for the stratum centred at `((i + 1/2)/side, (j + 1/2)/side)`; 0 for the whole pixel), as
///     a multisampled renderer's sample masks: splatting then spreads it from them.
/// Arrays of other float types are converted to float32.
///
/// The lens, as `dof render` takes it for an EXR: `focus` (planar focus distance, scene units)
/// and the aperture as `aperture_radius` (scene units) or `f_number`; the focal length in mm
/// (default: from `sensor_height` mm and the vertical field of view `yfov` degrees of a camera
/// with the image's height), and `pixels_per_unit` (pixels per scene unit on the sensor) to set
/// the pixel scale directly instead of through `yfov`. `metres_per_unit` is the scene unit's
/// length (it only matters for the millimetre values).
///
/// `method` is a name from `methods()` (default "multilayer", multi-layer tiled splatting);
/// `backend` is "cpu" (default), "vulkan", or "wgpu" (the kernels as WGSL on the device wgpu
/// chooses; `WGPU_BACKEND` narrows it). `options` are the method's options, as `methods()`
/// lists them with their units and bounds, named as the CLI's flags: tile, merge ("none", "2x2",
/// "4x4"), max_coc (a CoC diameter in pixels), aperture (shape), rings, lum_threshold, sprites,
/// spp (or samples), no_cascade, layers_per_doubling. As in the CLI, the image's edge pixels are extended outwards
/// as far as its largest CoC reaches, so blur does not darken at the frame.
///
/// Raises ValueError on bad input (shapes, depths, lens, options) and RuntimeError otherwise (no
/// Vulkan driver, a device failure), with the library's messages.
#[pyfunction]
#[pyo3(signature = (image, depth, *, focus, aperture_radius=None, f_number=None, focal_length=None, sensor_height=24.0, yfov=40.0, pixels_per_unit=None, metres_per_unit=1.0, method="multilayer", backend="cpu", straight_alpha=false, footprints=None, footprint_side=0, **options))]
#[allow(clippy::too_many_arguments)]
fn blur<'py>(
    py: Python<'py>,
    image: PyArrayLikeDyn<'py, f32, AllowTypeChange>,
    depth: &Bound<'py, PyAny>,
    focus: f32,
    aperture_radius: Option<f32>,
    f_number: Option<f32>,
    focal_length: Option<f32>,
    sensor_height: f32,
    yfov: f32,
    pixels_per_unit: Option<f32>,
    metres_per_unit: f32,
    method: &str,
    backend: &str,
    straight_alpha: bool,
    footprints: Option<Bound<'py, PyAny>>,
    footprint_side: u32,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyArray3<f32>>> {
    let info = dof::frame::registry::method(method).map_err(py_err)?;
    let options = method_options(info, options)?;
    if depth.is_none() {
        return Err(value_error(
            "blur needs a second array: an RGB image needs a float depth array (H, W), a multi-layer one its counts (H, W); got None"
                .to_string(),
        ));
    }
    let layers = match image.ndim() {
        3 => {
            let depth: PyArrayLikeDyn<'py, f32, AllowTypeChange> = depth
                .extract()
                .map_err(|_| value_error(format!("an RGB image needs a float depth array (H, W), got {}", describe(depth))))?;
            rgbz_image(image.as_array(), depth.as_array())?
        }
        4 => {
            let counts = whole_numbers(depth, "counts", u32::MAX as u64)?;
            let mut layers = layered_image(image.as_array(), counts.view(), straight_alpha)?;
            match footprints {
                Some(f) => with_footprints(&mut layers, whole_numbers(&f, "footprints", u32::MAX as u64)?.view(), footprint_side)?,
                None if footprint_side != 0 => return Err(value_error("footprint_side without footprints".to_string())),
                None => {}
            }
            layers
        }
        n => {
            return Err(value_error(format!(
                "image must be RGB (H, W, 3) with a depth (H, W), or multi-layer (H, W, L, 4) with counts (H, W); got {n} dimensions"
            )));
        }
    };
    let lens = lens(
        layers.width,
        layers.height,
        focus,
        aperture_radius,
        f_number,
        focal_length,
        sensor_height,
        yfov,
        pixels_per_unit,
        metres_per_unit,
    )?;
    let backend = backend.to_string();
    let result = py.detach(move || -> PyResult<(RgbImage, u32)> {
        let mut b = make_backend(&backend)?;
        let margin = edge_margin(&layers, &lens);
        let padded = layers.extend_edges(margin).map_err(py_err)?;
        let out = one_shot(b.as_mut(), info, &options, &padded, &lens).map_err(py_err)?;
        Ok((out.image, margin))
    })?;
    Ok(cropped_array(&result.0, result.1)?.into_pyarray(py))
}

/// An array of whole numbers from 0 to `max` (sample counts, footprint masks), checked value by
/// value: a NaN, a fraction or a value out of range is a ValueError naming where it is, never
/// cast silently.
fn whole_numbers(array: &Bound<'_, PyAny>, what: &str, max: u64) -> PyResult<numpy::ndarray::ArrayD<i64>> {
    let values: PyArrayLikeDyn<'_, f64, AllowTypeChange> =
        array.extract().map_err(|_| value_error(format!("{what} must be an array of whole numbers, got {}", describe(array))))?;
    let values = values.as_array();
    for (index, &v) in values.indexed_iter() {
        if !(v.is_finite() && v.fract() == 0.0 && v >= 0.0 && v <= max as f64) {
            return Err(value_error(format!("{what}{:?} is {v}; it must be a whole number from 0 to {max}", index.slice())));
        }
    }
    Ok(values.mapv(|v| v as i64))
}

/// What a Python value is, for messages: its type, and its shape if it is an array.
fn describe(value: &Bound<'_, PyAny>) -> String {
    let kind = value.get_type().name().map(|n| n.to_string()).unwrap_or_else(|_| "?".into());
    match value.getattr("shape") {
        Ok(shape) => format!("{kind} of shape {shape}"),
        Err(_) => kind,
    }
}

/// Gives `layers` the footprints `f` (H, W, L) on a `side` grid (1 to 4).
fn with_footprints(layers: &mut LayeredImage, f: ArrayViewD<'_, i64>, side: u32) -> PyResult<()> {
    let (h, w, l) = (layers.height as usize, layers.width as usize, layers.max_layers as usize);
    if f.shape() != [h, w, l] {
        return Err(value_error(format!("footprints must have the fragments' shape ({h}, {w}, {l}); got {:?}", f.shape())));
    }
    if !(1..=4).contains(&side) {
        return Err(value_error(format!("footprint_side must be 1 to 4 with footprints; got {side}")));
    }
    layers.footprints = f.iter().map(|&v| v as u32).collect();
    layers.footprint_side = side;
    Ok(())
}

/// A Python `UserWarning` saying what reading `path` repaired or left out (the note `dof render`
/// prints), so that nothing is changed silently.
fn warn_read(py: Python<'_>, path: &std::path::Path, report: &str) -> PyResult<()> {
    let message = std::ffi::CString::new(format!("{}: {report}", path.display()).replace('\0', " "))
        .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    PyErr::warn(py, &py.get_type::<pyo3::exceptions::PyUserWarning>(), &message, 1)
}

/// Whether an EXR file has a depth channel (`Z` or `depth`, any case, in any layer or part).
fn has_depth_channel(path: &std::path::Path) -> bool {
    use dof::io::codecs::exr::meta::MetaData;
    let Ok(meta) = MetaData::read_from_file(path, false) else { return false };
    meta.headers.iter().flat_map(|h| h.channels.list.iter()).any(|c| {
        let name = c.name.to_string();
        let last = name.rsplit('.').next().unwrap_or("").to_ascii_lowercase();
        last == "z" || last == "depth"
    })
}

/// Reads an EXR with the library's reader (the rules and NaN/Inf policy of `dof render`).
///
/// With `layers=False` (default) returns `(rgb, depth)`: the colour (H, W, 3) float32 and the
/// planar depth (H, W) float32 of an RGB+Z file (Blender's and Nuke's layouts included; +inf is
/// the background), or `depth=None` for a file with colour only. A multi-layer file raises
/// ValueError: read it with `layers=True`.
///
/// With `layers=True` returns `(fragments, counts)`: (H, W, L, 5) float32 fragments (r, g, b,
/// depth, alpha; colour premultiplied by alpha, as the file holds it; front to back) and (H, W)
/// uint32 counts, which `blur` takes as they are.
///
/// Raises ValueError naming the file and the problem on a missing, unreadable or unusable file.
/// What the reader repaired or left out (NaN or infinite colour, bad depth, channels not read) is
/// said in a `UserWarning`, as `dof render` prints it.
#[pyfunction]
#[pyo3(signature = (path, *, layers=false))]
fn read_exr<'py>(py: Python<'py>, path: PathBuf, layers: bool) -> PyResult<Bound<'py, PyTuple>> {
    let (read, note) = py.detach(|| -> PyResult<(Result<LayeredImage, RgbImage>, Option<String>)> {
        match dof::io::read_layered_exr(&path) {
            Ok((image, report)) => {
                if !layers && image.max_layers > 1 {
                    return Err(value_error(format!(
                        "{} is a multi-layer EXR ({}): read it with read_exr(path, layers=True)",
                        path.display(),
                        report.layers.join(", ")
                    )));
                }
                Ok((Ok(image), (report.total() > 0).then(|| report.to_string())))
            }
            Err(e) if !layers && path.is_file() && !has_depth_channel(&path) => match dof::io::read_rgb_exr(&path) {
                Ok((rgb, report)) => Ok((Err(rgb), (report.total() > 0).then(|| report.to_string()))),
                Err(_) => Err(py_err(e)),
            },
            Err(e) => Err(py_err(e)),
        }
    })?;
    if let Some(note) = note {
        warn_read(py, &path, &note)?;
    }
    match read {
        Err(rgb) => (to_rgb_array(&rgb)?.into_pyarray(py), py.None()).into_pyobject(py),
        Ok(image) if !layers => {
            let (rgb, depth) = image.front();
            let depth = Array2::from_shape_vec((image.height as usize, image.width as usize), depth).map_err(shape_error)?;
            (to_rgb_array(&rgb)?.into_pyarray(py), depth.into_pyarray(py)).into_pyobject(py)
        }
        Ok(image) => layered_arrays(py, &image),
    }
}

/// Whether the file at `path` is a deep OpenEXR file (from its first 8 bytes). Raises ValueError
/// when it cannot be read or is not an OpenEXR file.
#[pyfunction]
fn is_deep_exr(path: PathBuf) -> PyResult<bool> {
    dof::io::is_deep_exr(&path).map_err(py_err)
}

/// The files of an EXR sequence as compositors name them (`shot-####.exr`: one run of `#` for the
/// frame number padded to that many digits; as `dof render --scene` takes it), in frame order:
/// a list of `(frame number, path)`. Raises ValueError when nothing matches.
#[pyfunction]
fn exr_sequence(pattern: &str) -> PyResult<Vec<(u64, PathBuf)>> {
    Ok(dof::io::exr_pattern::frames(pattern).map_err(py_err)?.0)
}

/// The fields of a deep sample, in the order of the arrays `read_deep_exr` returns.
const DEEP_FIELDS: [&str; 6] = ["R", "G", "B", "A", "Z", "ZBack"];

/// Reads one deep OpenEXR file, or several merged into one image (as a deep merge does), with the
/// library's reader: deep scan lines or tiles, no compression, RLE, ZIPS or ZIP, the NaN/Inf
/// policy of `dof render`, every pixel made tidy by OpenEXR's rules (sorted by depth, overlapping
/// volume samples split, samples over one depth range merged).
///
/// Returns `(counts, samples)`: the samples per pixel (H, W) uint32, and a dict of flat float32
/// arrays `R`, `G`, `B` (premultiplied), `A`, `Z`, `ZBack`, one entry per sample, pixel after
/// pixel in row-major order and front to back within a pixel. `deep_layers` turns them into the
/// multi-layer image `blur` takes.
///
/// Raises ValueError naming the file and the problem on a missing, flat, damaged or unusable file.
/// What the reader repaired or left out is said in a `UserWarning`.
#[pyfunction]
fn read_deep_exr<'py>(py: Python<'py>, paths: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyTuple>> {
    let paths: Vec<PathBuf> = match paths.extract::<PathBuf>() {
        Ok(one) => vec![one],
        Err(_) => paths.extract()?,
    };
    let (image, report) = py.detach(|| dof::io::read_deep_exr(&paths)).map_err(py_err)?;
    let changed = report.counts.repaired() + report.z_back_repaired + report.coloured_alpha;
    if changed > 0 || !report.ignored_channels.is_empty() {
        warn_read(py, &paths[0], &report.to_string())?;
    }
    deep_arrays(py, &image)
}

/// A library image whose buffer does not fit its size (a library fault) as a RuntimeError.
fn shape_error(e: numpy::ndarray::ShapeError) -> PyErr {
    PyRuntimeError::new_err(format!("an image's buffer does not match its size: {e}"))
}

/// `(counts, samples)` of a deep image, as `read_deep_exr` returns them.
fn deep_arrays<'py>(py: Python<'py>, image: &dof::deep::DeepImage) -> PyResult<Bound<'py, PyTuple>> {
    let counts: Vec<u32> = (0..image.pixels()).map(|p| image.count(p) as u32).collect();
    let counts = Array2::from_shape_vec((image.height as usize, image.width as usize), counts).map_err(shape_error)?;
    let samples = PyDict::new(py);
    for (k, name) in DEEP_FIELDS.iter().enumerate() {
        let field: Vec<f32> = image
            .samples
            .iter()
            .map(|s| match k {
                0..=2 => s.color[k],
                3 => s.alpha,
                4 => s.z,
                _ => s.z_back,
            })
            .collect();
        samples.set_item(name, field.into_pyarray(py))?;
    }
    (counts.into_pyarray(py), samples).into_pyobject(py)
}

/// A deep image from `counts` (H, W) and `samples` (a dict of flat arrays `R`, `G`, `B`, `A`, `Z`
/// and optionally `ZBack`, as `read_deep_exr` returns them), made tidy.
fn deep_image(counts: ArrayViewD<'_, i64>, samples: &Bound<'_, PyDict>) -> PyResult<dof::deep::DeepImage> {
    if counts.ndim() != 2 {
        return Err(value_error(format!("counts must have shape (H, W), got {:?}", counts.shape())));
    }
    let (width, height) = check_size(counts.shape()[0], counts.shape()[1])?;
    let mut n = Vec::with_capacity(counts.len());
    for &c in counts.iter() {
        if !(0..=u32::MAX as i64).contains(&c) {
            return Err(value_error(format!("a sample count must lie between 0 and 2^32 - 1, got {c}")));
        }
        n.push(c as u32);
    }
    let total: u64 = n.iter().map(|&c| c as u64).sum();
    let mut fields: Vec<Vec<f32>> = Vec::with_capacity(6);
    for name in DEEP_FIELDS {
        let Some(array) = samples.get_item(name)? else {
            if name == "ZBack" {
                fields.push(fields[4].clone());
                continue;
            }
            return Err(value_error(format!("samples has no `{name}` array (it needs R, G, B, A, Z and optionally ZBack)")));
        };
        let array: PyArrayLikeDyn<'_, f32, AllowTypeChange> = array.extract()?;
        let values: Vec<f32> = array.as_array().iter().copied().collect();
        if values.len() as u64 != total {
            return Err(value_error(format!("samples[`{name}`] holds {} values, but counts add up to {total}", values.len())));
        }
        fields.push(values);
    }
    let mut policy = SanitizeCounts::default();
    let mut kept_counts = Vec::with_capacity(n.len());
    let mut kept = Vec::with_capacity(total as usize);
    let [r, g, b, a, z, z_back] = &fields[..] else { unreachable!("six fields") };
    let mut stored = (0..total as usize).map(|k| ([r[k], g[k], b[k]], a[k], z[k], z_back[k]));
    for &c in &n {
        let before = kept.len();
        for (rgb, alpha, depth, back) in stored.by_ref().take(c as usize) {
            // The reader's rules: a dropped sample (NaN depth, empty) leaves its pixel; a ZBack
            // that is NaN or in front of Z is Z.
            if let Some(f) = policy.fragment(rgb, alpha, depth) {
                let z_back = if f.depth == f32::INFINITY || back.is_nan() || back < f.depth { f.depth } else { back };
                kept.push(dof::deep::DeepSample { color: f.color, alpha: f.alpha, z: f.depth, z_back });
            }
        }
        kept_counts.push((kept.len() - before) as u32);
    }
    let image = dof::deep::DeepImage::from_counts(width, height, &kept_counts, kept).map_err(py_err)?;
    Ok(image.tidy().map_err(py_err)?.0)
}

/// The multi-layer image of a deep image for a lens, as `dof render` makes it from a deep EXR: the
/// umbra threshold, at most `max_layers` fragments a pixel (neighbours closest in inverse depth
/// merged), the disocclusion buffer (Franke et al. 2018, §4). `counts` and `samples` as
/// `read_deep_exr` returns them; the lens as `blur` takes it.
///
/// Returns `(fragments, counts)` as `read_exr(path, layers=True)` does: (H, W, L, 5) float32
/// (r, g, b, depth, alpha) and (H, W) uint32, which `blur` takes with the same lens.
#[pyfunction]
#[pyo3(signature = (counts, samples, *, focus, aperture_radius=None, f_number=None, focal_length=None, sensor_height=24.0, yfov=40.0, pixels_per_unit=None, metres_per_unit=1.0, max_layers=4))]
#[allow(clippy::too_many_arguments)]
fn deep_layers<'py>(
    py: Python<'py>,
    counts: Bound<'py, PyAny>,
    samples: &Bound<'py, PyDict>,
    focus: f32,
    aperture_radius: Option<f32>,
    f_number: Option<f32>,
    focal_length: Option<f32>,
    sensor_height: f32,
    yfov: f32,
    pixels_per_unit: Option<f32>,
    metres_per_unit: f32,
    max_layers: u32,
) -> PyResult<Bound<'py, PyTuple>> {
    if !(1..=64).contains(&max_layers) {
        return Err(value_error(format!("max_layers must lie between 1 and 64, got {max_layers}")));
    }
    let image = deep_image(whole_numbers(&counts, "counts", u32::MAX as u64)?.view(), samples)?;
    let lens = lens(
        image.width,
        image.height,
        focus,
        aperture_radius,
        f_number,
        focal_length,
        sensor_height,
        yfov,
        pixels_per_unit,
        metres_per_unit,
    )?;
    let camera = Camera::look_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0), yfov.to_radians(), image.width, image.height);
    let options = dof::frame::LayerOptions { max_layers, ..Default::default() };
    let layers = py.detach(|| -> dof::Result<LayeredImage> { Ok(image.layers(&camera.frame()?, &lens, &options)?.0) }).map_err(py_err)?;
    layered_arrays(py, &layers)
}

/// `(fragments, counts)` of a multi-layer image, as `read_exr(path, layers=True)` returns them.
fn layered_arrays<'py>(py: Python<'py>, image: &LayeredImage) -> PyResult<Bound<'py, PyTuple>> {
    let (h, w, l) = (image.height as usize, image.width as usize, image.max_layers as usize);
    let flat: Vec<f32> = image.fragments.iter().flat_map(|f| [f.color[0], f.color[1], f.color[2], f.depth, f.alpha]).collect();
    let frags = Array4::from_shape_vec((h, w, l, 5), flat).map_err(shape_error)?;
    let counts = Array2::from_shape_vec((h, w), image.counts.clone()).map_err(shape_error)?;
    (frags.into_pyarray(py), counts.into_pyarray(py)).into_pyobject(py)
}

/// Writes a linear float32 RGB EXR (ZIP-compressed, lossless) with the library's writer; with
/// `depth` (H, W) also a `Z` channel, which makes the file an RGB+Z image that `read_exr` (and
/// `dof render --scene FILE.exr`) reads back. Values are written as they are.
///
/// Raises ValueError on bad shapes or a file that cannot be written.
#[pyfunction]
#[pyo3(signature = (path, rgb, depth=None))]
fn write_exr(
    py: Python<'_>,
    path: PathBuf,
    rgb: PyArrayLikeDyn<'_, f32, AllowTypeChange>,
    depth: Option<Bound<'_, PyAny>>,
) -> PyResult<()> {
    let view = rgb.as_array();
    if view.ndim() != 3 || view.shape()[2] != 3 {
        return Err(value_error(format!("rgb must have shape (H, W, 3), got {:?}", view.shape())));
    }
    let (h, w) = (view.shape()[0], view.shape()[1]);
    let (width, height) = check_size(h, w)?;
    // Reserved first, so that an image this machine cannot hold is a MemoryError, not an abort.
    let mut data: Vec<[f32; 3]> = Vec::new();
    data.try_reserve_exact(h * w)
        .map_err(|_| py_err(CoreError::HostMemory { what: "the image to write".into(), bytes: (h * w * 12) as u64 }))?;
    data.extend(view.lanes(Axis(2)).into_iter().map(|c| [c[0], c[1], c[2]]));
    let image = RgbImage { width, height, data };
    let depth: Option<Vec<f32>> = match &depth {
        Some(d) => {
            let array: PyArrayLikeDyn<'_, f32, AllowTypeChange> =
                d.extract().map_err(|_| value_error(format!("depth must be a float array (H, W), got {}", describe(d))))?;
            let d = array.as_array();
            if d.shape() != [h, w] {
                return Err(value_error(format!("depth must have shape (H, W) = ({h}, {w}) like rgb, got {:?}", d.shape())));
            }
            Some(d.iter().copied().collect())
        }
        None => None,
    };
    py.detach(|| {
        let extra: Vec<(&str, &[f32])> = depth.as_deref().map(|d| ("Z", d)).into_iter().collect();
        dof::io::write_exr(&path, &image, &extra).map_err(py_err)
    })
}

/// The methods `blur` takes, from the library's registry: a list of dicts with `name` (what
/// `method=` takes), `title`, `paper`, `reads` ("all layers" or "front layer"), `knob` (the
/// name of its quality option, or None) and `options`: the keyword options it takes, each a dict
/// with `key`, `kind` ("count", "number", "flag", "choice" or "aperture"), `min` and `max` (counts
/// and numbers), `choices` (choices), `unit`, `default` and `help`.
#[pyfunction]
fn methods(py: Python<'_>) -> PyResult<Vec<Bound<'_, PyDict>>> {
    METHODS
        .iter()
        .map(|m| {
            let d = PyDict::new(py);
            d.set_item("name", m.name)?;
            d.set_item("title", m.title)?;
            d.set_item("paper", m.paper)?;
            let reads = match m.reads {
                dof::frame::Reads::AllLayers => "all layers",
                dof::frame::Reads::FrontLayer => "front layer",
            };
            d.set_item("reads", reads)?;
            d.set_item("knob", m.knob.map(|k| k.name))?;
            let options = m
                .options
                .iter()
                .map(|spec| {
                    let o = PyDict::new(py);
                    o.set_item("key", spec.option.key())?;
                    let kind = match spec.kind {
                        Kind::Count { min, max } => {
                            o.set_item("min", min)?;
                            o.set_item("max", max)?;
                            "count"
                        }
                        Kind::Number { min, max } => {
                            o.set_item("min", min)?;
                            o.set_item("max", max)?;
                            "number"
                        }
                        Kind::Flag => "flag",
                        Kind::Choice(names) => {
                            o.set_item("choices", names.to_vec())?;
                            "choice"
                        }
                        Kind::Aperture => "aperture",
                    };
                    o.set_item("kind", kind)?;
                    o.set_item("unit", spec.unit)?;
                    o.set_item("default", spec.default)?;
                    o.set_item("help", spec.help)?;
                    Ok(o)
                })
                .collect::<PyResult<Vec<_>>>()?;
            d.set_item("options", options)?;
            Ok(d)
        })
        .collect()
}

/// Depth of field on numpy arrays: multi-layer tiled splatting (Franke et al. 2018) and the other
/// methods of the `dof` library, on the CPU or Vulkan. `blur` blurs, `methods` lists the methods,
/// `read_exr` and `write_exr` read and write EXR files with the library's reader and writer.
#[pymodule]
#[pyo3(name = "_native")]
fn dof_module(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(blur, m)?)?;
    m.add_function(wrap_pyfunction!(read_exr, m)?)?;
    m.add_function(wrap_pyfunction!(read_deep_exr, m)?)?;
    m.add_function(wrap_pyfunction!(is_deep_exr, m)?)?;
    m.add_function(wrap_pyfunction!(exr_sequence, m)?)?;
    m.add_function(wrap_pyfunction!(deep_layers, m)?)?;
    m.add_function(wrap_pyfunction!(write_exr, m)?)?;
    m.add_function(wrap_pyfunction!(methods, m)?)?;
    Ok(())
}
