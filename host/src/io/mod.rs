//! Reading and writing images: EXR for linear HDR data (colour, depth, CoC, masks, multi-layer
//! input), PNG previews through a documented tone map.
//!
//! - [`write_exr`] / [`write_exr_with`]: an [`RgbImage`] as linear `f32`
//!   (or half) RGB, plus extra named `f32` planes (`Z`, `coc`, `mask`, …);
//!   [`write_layered_exr`]: a [`LayeredImage`](crate::layers::LayeredImage) as `layer{i}.R/G/B/A/Z`.
//! - [`read_layered_exr`]: an RGB+Z (also Blender's and Nuke's layouts) or multi-layer EXR to a
//!   `LayeredImage` (the background as a fragment at depth `+inf`), with an
//!   [`InputReport`] of what was read and repaired; [`read_rgb_exr`]: the colour of an EXR.
//! - [`read_deep_exr`]: deep OpenEXR files (every sample of every pixel) to a tidy
//!   [`DeepImage`](crate::deep::DeepImage), which `DeepImage::layers` (`scene::deep_layers`) turns
//!   into a `LayeredImage` for a lens; [`is_deep_exr`] tells deep files from flat ones;
//!   `scene::ExrInput` reads either kind as a scene.
//! - [`write_png_preview`]: 8-bit sRGB PNG through [`tonemap()`](tonemap::tonemap) (exposure, ACES
//!   fitted curve, sRGB OETF; formulas in [`tonemap`](mod@tonemap)).
//!
//! # Input channels
//!
//! A channel name `layer.channel` belongs to the layer before the last `.`; names without a `.` form
//! the unnamed layer. In a multi-part file every part's channels are read, and the part name is
//! prefixed to channel names that lack it (`R` in part `rgba` is `rgba.R`; `depth.Z` in part
//! `depth` stays `depth.Z`). Within a layer, colour is `R`, `G`, `B`, alpha `A` (optional: 1 when
//! absent), depth `Z` or `depth` (any letter case; the canonical spelling wins when several are
//! present). The file may hold:
//!
//! | image | channels | read as |
//! |---|---|---|
//! | RGB+Z | unnamed `R`, `G`, `B`, `Z`, (`A`) | one layer |
//! | Blender | `<P>.Combined.R/G/B/A` with `<P>.Depth.Z` (`RenderLayer`, `ViewLayer`, any `<P>`) | one layer named `<P>.Combined` |
//! | Nuke | `rgba.R/G/B/A` or unnamed `R/G/B/A`, with `depth.Z`; one part, or parts `rgba` and `depth` | one layer named `rgba` (or `""`) |
//! | multi-layer | every named layer with colour and depth, `<name>.R/G/B/Z/(A)`, e.g. `layer0.*` | one depth layer each, natural order of names |
//!
//! **Exactly one** of these must be present. None: an error saying what is missing (colour, or the
//! depth of a named colour layer). More than one is ambiguous and an error naming each candidate's
//! channels, to keep one and remove the others: a root RGB+Z image next to complete named layers
//! (it may be the front layer or the flattened image of those layers; nothing says which), two
//! Blender view layers each with `Combined` and `Depth`, `rgba.*` next to an unnamed `R`, `G`, `B`
//! both beside `depth.Z`. Channels that the image does not use (other passes such as Blender's
//! `DiffCol`, a flattened `R`, `G`, `B` without `Z` next to named layers, a `depth.Z` next to a root
//! `Z`, duplicate spellings) are listed in [`InputReport::ignored_channels`] and printed as a
//! note; nothing is dropped silently. In a multi-layer file a named layer with colour but no depth,
//! or only some of R, G, B, is an error.
//!
//! Colour in EXR is premultiplied by alpha, as [`Fragment`](crate::layers::Fragment) colour is:
//! it is read and written as stored. Depth is planar
//! (distance along the view axis) as in [`layers`](crate::layers); a renderer writing radial
//! distance or `1/z` must be converted first. The image is the data window; its corner and the
//! display window are kept ([`InputReport::window`]) and `dof render` writes its result with them,
//! so an offset crop or a data window beyond the display window keeps its place in the frame.
//!
//! # The background
//!
//! The background is data, not a hole: a slot at depth `+inf` or at least [`BACKGROUND_DEPTH`]
//! (10^10: Blender's background depth; `f32::MAX` and half-float `+inf` are beyond it; 65 504 is
//! not a threshold, since real scenes in millimetres reach farther) becomes a fragment at depth
//! `+inf` with alpha 1 and the stored colour (after the colour rules; premultiplied, so a partly
//! transparent background is taken over black). A black sky is a black background fragment. It
//! is always the last fragment of its pixel: a pixel keeps one background (the first in layer
//! order) and further background slots are dropped and counted. In an RGB+Z image the one layer is
//! the whole pixel, so a pixel at background depth is the background whatever its alpha (a
//! transparent film's alpha 0 gives the stored, usually black, colour). A slot with alpha 0 and a
//! black colour is empty whatever its depth ([`write_layered_exr`] writes empty slots as colour 0,
//! A 0, Z `+inf`), and a background fragment is written as Z `+inf`, A 1. A slot with alpha 0 and
//! a colour is light that hides nothing (premultiplied colour: emission), read as a fragment and
//! noted: an image whose alpha is 0 everywhere shows its colour, never black.
//!
//! # NaN/Inf policy
//!
//! Every sample read is checked, repaired or dropped as below, and counted in the
//! [`InputReport`]'s [`SanitizeCounts`] (colour and alpha per sample, depth per fragment), so that
//! the CLI can print what was changed. Written files hold the values as given.
//!
//! | value                               | becomes                                             | counted in       |
//! |-------------------------------------|-----------------------------------------------------|------------------|
//! | colour NaN                          | 0                                                   | `color_nan`      |
//! | colour `+inf`                       | 65 504 ([`COLOR_INF_REPLACEMENT`], max finite half) | `color_inf`      |
//! | colour `-inf`                       | 0                                                   | `color_inf`      |
//! | colour finite (negative included)   | unchanged                                           | —                |
//! | alpha NaN                           | 0, so the slot is empty                             | `alpha_invalid`  |
//! | alpha < 0 or > 1 (`±inf` included)  | clamped to [0, 1]                                   | `alpha_invalid`  |
//! | alpha 0, colour black               | empty slot: no fragment (depth not checked; but see the RGB+Z background above) | `empty_alpha` (info) |
//! | alpha 0, colour not black           | a fragment that hides nothing (emission)            | `emission_only` (noted) |
//! | depth `+inf` or >= [`BACKGROUND_DEPTH`] | the background: depth `+inf`, alpha 1, its colour | `background` (info) |
//! | a second background slot in a pixel | dropped (the first background ends the pixel)      | `behind_background` |
//! | depth NaN, `<= 0`, `-inf`           | fragment dropped (that layer of the pixel is empty) | `depth_invalid`  |
//!
//! Each layer slot of a pixel is checked in the table's order: alpha, then depth, then colour (an
//! RGB+Z pixel at background depth: depth, then colour); the colour of a slot that is empty or
//! dropped is not checked or counted.
//! Colour 65 504 (not `f32::MAX`) keeps sums of many clamped pixels finite in `f32`; finite values
//! above it are kept. [`read_rgb_exr`] applies the colour rules only. The PNG preview maps
//! NaN to black and `+inf` to white (see [`tonemap`](mod@tonemap)).
//!
//! # Errors
//!
//! A missing or unreadable file, a file that is not an EXR, a truncated or corrupt EXR, a zero
//! size, missing R/G/B, missing depth ("needs a Z channel"), several candidate images ("is
//! ambiguous"), layers with different data windows, subsampled channels, deep data (read by [`read_deep_exr`]): each is an [`Error::InvalidArgument`] naming the file and saying
//! what to change. Nothing here panics on file contents: a header announcing more than 4096 times
//! the file's size in pixel data is rejected as corrupt before anything is allocated, and the exr
//! crate decodes on the calling thread inside `catch_unwind`, so that an assertion it trips on
//! corrupt data becomes an error (a panic in its thread pool would abort the process; the price is
//! sequential decompression).

//!
//! # Features
//!
//! The files need the `exr` feature (the `exr` and `png` crates); without it only the tone map and
//! the sanitising rules ([`tonemap`](mod@tonemap), [`sanitize`]) are here.
#![cfg_attr(not(feature = "exr"), allow(rustdoc::broken_intra_doc_links))]

#[cfg(feature = "exr")]
mod channels;
#[cfg(feature = "exr")]
mod deep_codec;
#[cfg(feature = "exr")]
mod deep_exr;
pub mod exr_pattern;
#[cfg(feature = "exr")]
mod exr_read;
#[cfg(feature = "exr")]
mod exr_write;
#[cfg(feature = "exr")]
mod gif_preview;
#[cfg(feature = "exr")]
mod preview;
pub mod sanitize;
pub mod tonemap;

#[cfg(feature = "exr")]
use std::path::Path;

#[cfg(feature = "exr")]
pub use channels::natural_cmp;
#[cfg(feature = "exr")]
pub use deep_exr::{DeepReport, is_deep_exr, read_deep_exr};
#[cfg(feature = "exr")]
pub use exr_read::{ExrLayout, InputReport, MAX_EXR_EDGE, MAX_EXR_SLOTS, check_exr_header, read_layered_exr, read_rgb_exr};
#[cfg(feature = "exr")]
pub use exr_write::{ExrCompression, ExrPrecision, ExrWindow, ExrWriteOptions, write_exr, write_exr_with, write_layered_exr};
#[cfg(feature = "exr")]
pub use gif_preview::{GifPreview, MAX_GIF_EDGE, write_gif_preview};
#[cfg(feature = "eval")]
pub(crate) use preview::write_srgb8;
#[cfg(feature = "exr")]
pub use preview::{write_png_display, write_png_preview};
pub use sanitize::{BACKGROUND_DEPTH, COLOR_INF_REPLACEMENT, SanitizeCounts, is_background_depth};
pub use tonemap::tonemap;

/// The codec crates used here, re-exported so that callers and tests can build or inspect files
/// with exactly the versions this module reads and writes.
#[cfg(feature = "exr")]
pub mod codecs {
    pub use ::exr;
    pub use ::gif;
    pub use ::png;
}

#[cfg(feature = "exr")]
use crate::error::{Error, Result};
#[cfg(feature = "exr")]
use crate::layers::RgbImage;

/// Errors on a zero-sized image or one whose `data` does not hold `width · height` pixels.
#[cfg(feature = "exr")]
fn check_rgb_image(image: &RgbImage, what: &str) -> Result<()> {
    if image.width == 0 || image.height == 0 {
        return Err(Error::invalid(format!(
            "cannot write {what} of zero size ({}x{}): width and height must be positive",
            image.width, image.height
        )));
    }
    let pixels = image.width as u64 * image.height as u64;
    if image.data.len() as u64 != pixels {
        return Err(Error::invalid(format!(
            "cannot write {what}: the image is {}x{} = {pixels} pixels but its data holds {}",
            image.width,
            image.height,
            image.data.len()
        )));
    }
    Ok(())
}

/// A file-system error with the path and, for the usual causes, what to do.
#[cfg(feature = "exr")]
fn fs_error(action: &str, path: &Path, e: &std::io::Error) -> Error {
    use std::io::ErrorKind;
    let path = path.display();
    Error::invalid(match (action, e.kind()) {
        ("open", ErrorKind::NotFound) => format!("cannot open {path}: the file does not exist; check the path"),
        ("create", ErrorKind::NotFound) => {
            format!("cannot create {path}: its directory does not exist; create the directory first")
        }
        (_, ErrorKind::PermissionDenied) => format!("cannot {action} {path}: permission denied"),
        _ => format!("cannot {action} {path}: {e}"),
    })
}

/// Writes a whole file atomically, with the path in any error: the bytes go to a temporary file
/// beside it ([`temp_beside`]), which is then renamed over `path`, so a reader (or a render farm
/// retrying a frame after a worker died) finds the file complete or absent, never cut short.
#[cfg(feature = "exr")]
fn write_file(path: &Path, bytes: &[u8]) -> Result<()> {
    use std::io::Write;
    let temp = temp_beside(path);
    let written = (|| {
        let mut file = std::fs::File::create(&temp)?;
        file.write_all(bytes)?;
        persist(file, &temp, path)
    })();
    written.map_err(|e| {
        let _ = std::fs::remove_file(&temp);
        fs_error("create", path, &e)
    })
}

/// A temporary name beside `path` (hidden, unique to this process and call) for a file that is
/// renamed over `path` once whole.
#[cfg(feature = "exr")]
fn temp_beside(path: &Path) -> std::path::PathBuf {
    use std::sync::atomic::{AtomicU64, Ordering};
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    path.with_file_name(format!(".{name}.{}-{}.part", std::process::id(), COUNTER.fetch_add(1, Ordering::Relaxed)))
}

/// Flushes `file` (written at `temp`) to the disk and renames it over `path`.
#[cfg(feature = "exr")]
fn persist(file: std::fs::File, temp: &Path, path: &Path) -> std::io::Result<()> {
    file.sync_all()?;
    drop(file);
    std::fs::rename(temp, path)
}
