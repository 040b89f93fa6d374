//! EXR input: RGB+Z and multi-layer files to a [`LayeredImage`], RGB files to an [`RgbImage`].

use std::fmt;
use std::fs::File;
use std::io::{BufReader, Read, Seek, SeekFrom};
use std::path::Path;

use ::exr::block::reader::ChunksReader;
use ::exr::meta::attribute::SampleType;
use ::exr::meta::header::Header;
use ::exr::prelude::*;
use rayon::prelude::*;

use super::channels::{Group, group_channels, is_depth_sibling};
use super::fs_error;
use super::sanitize::{BACKGROUND_DEPTH, SanitizeCounts};
use crate::error::{Error, Result};
use crate::layers::{Fragment, LayeredImage, RgbImage};

/// How the channels of a file were interpreted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ExrLayout {
    /// Colour only (`R`, `G`, `B`), read by [`read_rgb_exr`].
    Rgb,
    /// One colour image with depth, one layer: `R`, `G`, `B`, a depth channel, optional `A`; or a
    /// colour layer with its depth in a sibling layer as Blender (`<P>.Combined.*` with
    /// `<P>.Depth.Z`) and Nuke (`rgba.*` or `R`, `G`, `B` with `depth.Z`, also as parts) write it.
    RgbZ,
    /// Named layers `<name>.R`, `.G`, `.B`, depth, optional `.A`: one depth layer each.
    MultiLayer,
}

/// What reading a file found and what the NaN/Inf policy changed, for the CLI to print.
#[derive(Clone, Debug, PartialEq)]
pub struct InputReport {
    pub layout: ExrLayout,
    pub width: u32,
    pub height: u32,
    /// The layers read, in the order used to break depth ties (natural order of names; `""` is the
    /// unnamed layer of an RGB or RGB+Z file; an RGB+Z image read from a colour layer and its
    /// sibling depth layer is named after the colour layer, e.g. `ViewLayer.Combined`).
    pub layers: Vec<String>,
    /// The channels read, by full name (e.g. `layer0.R`; in a multi-part file the part name is
    /// prefixed where the channel name lacks it: `rgba.R`).
    pub channels: Vec<String>,
    /// Channels in the file that were not read (other passes, a flattened beauty image next to
    /// named layers, duplicate spellings such as `depth` next to `Z`), each named in the
    /// `Display` output: nothing is dropped without a note.
    pub ignored_channels: Vec<String>,
    /// What the NaN/Inf policy repaired or dropped.
    pub counts: SanitizeCounts,
    /// Where the image lies in the file's pixel space: write the result with it to keep its place.
    pub window: super::ExrWindow,
}

impl InputReport {
    /// Values repaired or dropped by the NaN/Inf policy (see [`SanitizeCounts::repaired`]).
    pub fn repaired(&self) -> u64 {
        self.counts.repaired()
    }

    /// Everything worth a note to the user: [`Self::repaired`], the fragments of alpha 0 read as
    /// emission (`emission_only`) and the channels not read (`ignored_channels`). When it is 0 the whole file was read as it is (apart from empty slots
    /// and background fragments, which are data, not changes).
    pub fn total(&self) -> u64 {
        self.counts.repaired() + self.counts.emission_only + self.ignored_channels.len() as u64
    }
}

impl fmt::Display for InputReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let layout = match self.layout {
            ExrLayout::Rgb => "RGB".to_string(),
            ExrLayout::RgbZ if self.layers.iter().all(|l| l.is_empty()) => "RGB+Z".to_string(),
            ExrLayout::RgbZ => format!("RGB+Z from {}", self.channels.join(", ")),
            ExrLayout::MultiLayer => format!("{} layers ({})", self.layers.len(), self.layers.join(", ")),
        };
        write!(f, "{}x{} {layout}", self.width, self.height)?;
        let c = &self.counts;
        let background = format!("background fragments (depth +inf or >= {BACKGROUND_DEPTH:e}), kept with their colour");
        let items = [
            (c.color_nan, "NaN colour values set to 0"),
            (c.color_inf, "infinite colour values clamped (+inf to 65504, -inf to 0)"),
            (c.alpha_invalid, "alpha values NaN or outside [0, 1] (NaN to 0, others clamped)"),
            (
                c.emission_only,
                "fragments with alpha 0 and a colour, read as light that hides nothing (colour is premultiplied: a glow or \
                 emission; an image whose alpha is 0 everywhere shows its colour)",
            ),
            (c.depth_invalid, "fragments with NaN, zero or negative depth dropped"),
            (
                c.behind_background,
                "fragments behind the background dropped (a second layer at depth +inf or beyond the background \
                 threshold in the same pixel: the first background in layer order ends the pixel)",
            ),
            (c.background, background.as_str()),
        ];
        for (n, what) in items {
            if n > 0 {
                write!(f, "\n  {n} {what}")?;
            }
        }
        if !self.ignored_channels.is_empty() {
            write!(f, "\n  channels not used: {}", list(&self.ignored_channels))?;
        }
        Ok(())
    }
}

/// Reads an RGB+Z or multi-layer EXR into a layered image, detecting which it is (see the [module
/// documentation](super) for the channel names accepted, the rules and the NaN/Inf policy). The
/// file's channels (of every part) may hold these images:
///
/// - **RGB+Z**: the unnamed channels `R`, `G`, `B` and `Z` (or `depth`), `A` optional;
/// - **RGB+Z from sibling layers**: a colour layer without depth and the depth-only layer beside
///   it, as Blender (`<P>.Combined.R/G/B/A` with `<P>.Depth.Z`) and Nuke (`rgba.R/G/B/A`, or the
///   unnamed `R`, `G`, `B`, `A`, with `depth.Z`; in one part or as parts `rgba` and `depth`) write
///   them;
/// - **multi-layer**: every named layer with colour and depth (`<name>.R`, `.G`, `.B` and `.Z` or
///   `.depth`; `.A` optional), one depth layer each, in the natural order of the names;
///   `max_layers` is their number. A named layer with colour channels but no depth, or only some of
///   R, G, B, is then an error. Layers may also be separate parts of a multi-part file (the part
///   name is the layer name).
///
/// Exactly one of these must be present: none is an error saying what is missing, and more than
/// one (a root RGB+Z image next to complete named layers, two Blender view layers, ...) is an
/// error naming each candidate's channels, since nothing says which to read. Channels that no
/// image uses (other passes, a flattened image next to the layers) are listed in the report's
/// `ignored_channels`. Everything read must share one data window.
///
/// Each pixel's fragments are sorted front to back (stable, so equal depths keep the layer
/// order). A slot at depth `+inf` or at least [`BACKGROUND_DEPTH`] is the **background**: a
/// fragment at depth `+inf` with alpha 1 and the stored colour, always the last of its pixel; a
/// pixel keeps one (the first in layer order), and further background slots are dropped and
/// counted (`behind_background`). Colour is premultiplied by alpha in EXR files and in a
/// [`Fragment`], so it is kept as stored (the background is the stored colour over black, alpha 1);
/// a slot of alpha 0 with a colour is light that hides nothing. Depth is taken as planar depth as
/// written.
pub fn read_layered_exr(path: impl AsRef<Path>) -> Result<(LayeredImage, InputReport)> {
    let path = path.as_ref();
    let mut file = ExrFile::open(path)?;
    let (layout, groups) = select_layers(path, &file)?;
    // An RGB+Z image's single layer is the whole pixel (see `SanitizeCounts::sole_fragment`).
    let sole = layout == ExrLayout::RgbZ;
    let (width, height, origin) = file.size_of(path, &groups)?;
    let slots = width as u128 * height as u128 * groups.len() as u128;
    let used: Vec<usize> = groups.iter().flat_map(|g| g.used()).collect();
    let planes = file.decode(path, &used, slots * (std::mem::size_of::<Fragment>() as u128 + 4))?;
    let mut image = LayeredImage::new(width, height, groups.len() as u32)?;
    let mut report = file.report(layout, width, height, &groups);
    report.window = super::ExrWindow { origin, display: file.display };

    struct Planes<'a> {
        rgb: [&'a [f32]; 3],
        alpha: Option<&'a [f32]>,
        depth: &'a [f32],
    }
    let plane = |i: Option<usize>| i.and_then(|i| planes[i].as_deref());
    let mut layer_planes = Vec::with_capacity(groups.len());
    for g in &groups {
        let (Some(r), Some(gr), Some(b), Some(depth)) = (plane(g.r), plane(g.g), plane(g.b), plane(g.depth)) else {
            return Err(Error::invalid(format!("internal: layer `{}` selected without its channels", g.name)));
        };
        layer_planes.push(Planes { rgb: [r, gr, b], alpha: plane(g.a), depth });
    }

    let w = width as usize;
    let layers = groups.len();
    report.counts = image
        .fragments
        .par_chunks_mut(w * layers)
        .zip(image.counts.par_chunks_mut(w))
        .enumerate()
        .map(|(y, (row_fragments, row_counts))| {
            let mut counts = SanitizeCounts::default();
            let mut pixel: Vec<Fragment> = Vec::with_capacity(layers);
            for x in 0..w {
                let p = y * w + x;
                pixel.clear();
                for plane in &layer_planes {
                    let rgb = [plane.rgb[0][p], plane.rgb[1][p], plane.rgb[2][p]];
                    let alpha = plane.alpha.map_or(1.0, |a| a[p]);
                    let depth = plane.depth[p];
                    let fragment = if sole { counts.sole_fragment(rgb, alpha, depth) } else { counts.fragment(rgb, alpha, depth) };
                    if let Some(f) = fragment {
                        pixel.push(f);
                    }
                }
                // Depths are positive here, finite or +inf (the background); the sort is stable, so
                // ties keep layer order and the first background in layer order comes first.
                pixel.sort_by(|a, b| a.depth.total_cmp(&b.depth));
                if let Some(background) = pixel.iter().position(|f| f.depth == f32::INFINITY) {
                    counts.behind_background += (pixel.len() - background - 1) as u64;
                    pixel.truncate(background + 1);
                }
                row_fragments[x * layers..x * layers + pixel.len()].copy_from_slice(&pixel);
                row_counts[x] = pixel.len() as u32;
            }
            counts
        })
        .reduce(SanitizeCounts::default, |a, b| a + b);
    Ok((image, report))
}

/// Reads the colour of an EXR (the unnamed channels `R`, `G`, `B`, as written by
/// [`write_exr`](super::write_exr)) into an [`RgbImage`], as stored (alpha, if any, is not applied).
/// Colour samples follow the NaN/Inf policy and are counted in the report.
pub fn read_rgb_exr(path: impl AsRef<Path>) -> Result<(RgbImage, InputReport)> {
    let path = path.as_ref();
    let mut file = ExrFile::open(path)?;
    let groups = group_channels(&file.names);
    let root = match groups.iter().find(|g| g.name.is_empty()) {
        Some(root) if root.has_rgb() => root.clone(),
        root => {
            let missing = root.map_or(vec!["R", "G", "B"], |r| r.missing_colors());
            return Err(Error::invalid(format!(
                "{} needs the colour channels R, G and B (missing {}); it has the channels {}",
                path.display(),
                missing.join(", "),
                list(&file.names)
            )));
        }
    };
    let colour_only = Group { a: None, depth: None, ..root };
    let groups = [colour_only];
    let (width, height, origin) = file.size_of(path, &groups)?;
    let mut report = file.report(ExrLayout::Rgb, width, height, &groups);
    report.window = super::ExrWindow { origin, display: file.display };
    let g = &groups[0];
    let colour = [g.r, g.g, g.b].into_iter().flatten().collect::<Vec<_>>();
    let decoded = file.decode(path, &colour, width as u128 * height as u128 * 12)?;
    let planes: Vec<&[f32]> = colour.iter().filter_map(|&i| decoded[i].as_deref()).collect();
    if planes.len() != 3 {
        return Err(Error::invalid(format!("internal: {} read without its colour channels", path.display())));
    }
    let mut image = RgbImage::new(width, height);
    report.counts = image
        .data
        .par_chunks_mut(width as usize)
        .enumerate()
        .map(|(y, row)| {
            let mut counts = SanitizeCounts::default();
            for (x, c) in row.iter_mut().enumerate() {
                let p = y * width as usize + x;
                *c = [0, 1, 2].map(|k| counts.color(planes[k][p]));
            }
            counts
        })
        .reduce(SanitizeCounts::default, |a, b| a + b);
    Ok((image, report))
}

/// Opens an EXR input, refusing anything but a regular file before opening it: opening a FIFO
/// blocks until something writes to it, and a directory or a device is no image.
pub(super) fn open_regular(path: &Path) -> Result<File> {
    let meta = std::fs::metadata(path).map_err(|e| fs_error("open", path, &e))?;
    if meta.is_dir() {
        return Err(Error::invalid(format!("{} is a directory, not an EXR file", path.display())));
    }
    if !meta.file_type().is_file() {
        return Err(Error::invalid(format!(
            "{} is not a regular file (a FIFO, socket or device): an EXR input must be a file",
            path.display()
        )));
    }
    File::open(path).map_err(|e| fs_error("open", path, &e))
}

/// An EXR's headers and the channels they declare, by full name (`part.channel` in multi-part
/// files). Pixels are decoded on request, and only for the channels asked for
/// ([`Self::decode`]): a file with dozens of passes costs the memory of the few read.
struct ExrFile {
    file: File,
    headers: Vec<Header>,
    /// The display window, `[x_min, y_min, x_max, y_max]`.
    display: [i32; 4],
    /// Full channel names, in the order of `index`.
    names: Vec<String>,
    /// (part, channel within the part) of each full name.
    index: Vec<(usize, usize)>,
}

impl ExrFile {
    /// Opens `path` and reads its headers, refusing before any pixel is decoded: what is not a
    /// regular EXR file, an empty data window, sizes beyond the limits on EXR input, a header that
    /// announces far more pixel data than the file could hold, deep parts and zero sizes.
    fn open(path: &Path) -> Result<ExrFile> {
        let mut file = open_regular(path)?;
        let file_len = file.metadata().map(|m| m.len()).unwrap_or(0);
        let mut magic = Vec::with_capacity(8);
        (&mut file).take(8).read_to_end(&mut magic).map_err(|e| fs_error("read", path, &e))?;
        check_magic(path, &magic)?;
        // The exr crate swaps the corners of an inverted (empty) data window, so that case is looked
        // for in the raw header.
        file.seek(SeekFrom::Start(0)).map_err(|e| fs_error("read", path, &e))?;
        if let Some((part, [x0, y0, x1, y1])) = empty_data_window(&mut BufReader::new(&mut file)) {
            return Err(Error::invalid(format!(
                "{}: part {part} has a zero size: its data window runs from ({x0}, {y0}) to ({x1}, {y1}), \
                 so there are no pixels to read",
                path.display()
            )));
        }
        let meta = guarded(path, || {
            file.seek(SeekFrom::Start(0)).map_err(|e| fs_error("read", path, &e))?;
            MetaData::read_from_buffered(BufReader::new(&mut file), false).map_err(|e| exr_error(path, e))
        })?;
        check_declared_size(path, &meta)?;
        let announced: u128 = meta.headers.iter().map(|h| h.layer_size.area() as u128 * h.channels.bytes_per_pixel as u128).sum();
        if announced > MAX_EXPANSION * file_len as u128 + EXPANSION_SLACK {
            return Err(Error::invalid(format!(
                "{} is corrupt: its header announces {} MiB of pixel data in a file of {file_len} bytes \
                 (more than {MAX_EXPANSION} times its size); re-export it",
                path.display(),
                announced >> 20
            )));
        }
        for (i, header) in meta.headers.iter().enumerate() {
            let part = header.own_attributes.layer_name.as_ref().map_or(format!("part {i}"), |n| format!("part `{n}`"));
            if header.deep {
                return Err(Error::invalid(format!(
                    "{}: {part} holds deep data, which the flat reader does not read: read it with `read_deep_exr` \
                     (`dof render` and the Python binding's `read_deep_exr` read deep files)",
                    path.display()
                )));
            }
            if header.layer_size.x() == 0 || header.layer_size.y() == 0 {
                return Err(Error::invalid(format!(
                    "{}: {part} has a zero size ({}x{}): there are no pixels to read",
                    path.display(),
                    header.layer_size.x(),
                    header.layer_size.y()
                )));
            }
        }
        let headers = meta.headers.into_vec();
        let d = headers.first().map(|h| h.shared_attributes.display_window).unwrap_or_default();
        let display = [d.position.x(), d.position.y(), d.max().x(), d.max().y()];
        let multi_part = headers.len() > 1;
        let mut names = Vec::new();
        let mut index = Vec::new();
        for (p, header) in headers.iter().enumerate() {
            for (c, channel) in header.channels.list.iter().enumerate() {
                names.push(full_channel_name(multi_part, p, header.own_attributes.layer_name.as_ref(), &channel.name));
                index.push((p, c));
            }
        }
        if names.is_empty() {
            return Err(Error::invalid(format!("{} has no channels", path.display())));
        }
        Ok(ExrFile { file, headers, display, names, index })
    }

    /// The size shared by every used channel of `groups`; errors on a zero size, different data
    /// windows or subsampled channels.
    fn size_of(&self, path: &Path, groups: &[Group]) -> Result<(u32, u32, (i32, i32))> {
        let mut first: Option<(&str, Vec2<usize>, Vec2<i32>)> = None;
        for g in groups {
            for i in g.used() {
                let (p, c) = self.index[i];
                let header = &self.headers[p];
                let channel = &header.channels.list[c];
                if channel.sampling != Vec2(1, 1) {
                    return Err(Error::invalid(format!(
                        "{}: channel `{}` is subsampled ({}x{}); only full-resolution channels are supported: \
                         re-export without subsampling",
                        path.display(),
                        self.names[i],
                        channel.sampling.x(),
                        channel.sampling.y()
                    )));
                }
                let (size, position) = (header.layer_size, header.own_attributes.layer_position);
                match first {
                    None => first = Some((&self.names[i], size, position)),
                    Some((name, s, pos)) if s != size || pos != position => {
                        return Err(Error::invalid(format!(
                            "{}: layer sizes differ: `{}` is {}x{} at ({}, {}) but `{name}` is {}x{} at ({}, {}); \
                             all layers must share one data window",
                            path.display(),
                            self.names[i],
                            size.x(),
                            size.y(),
                            position.x(),
                            position.y(),
                            s.x(),
                            s.y(),
                            pos.x(),
                            pos.y()
                        )));
                    }
                    Some(_) => {}
                }
            }
        }
        let Some((_, size, position)) = first else {
            return Err(Error::invalid(format!("{}: no channels to read", path.display())));
        };
        if size.x() == 0 || size.y() == 0 {
            return Err(Error::invalid(format!(
                "{} has a zero size ({}x{}): there are no pixels to read",
                path.display(),
                size.x(),
                size.y()
            )));
        }
        let too_large = || Error::invalid(format!("{}: size {}x{} is too large", path.display(), size.x(), size.y()));
        Ok((
            u32::try_from(size.x()).map_err(|_| too_large())?,
            u32::try_from(size.y()).map_err(|_| too_large())?,
            (position.x(), position.y()),
        ))
    }

    /// Decodes the channels `used` (indices into [`Self::names`], full-resolution channels of one
    /// data window: [`Self::size_of`] checked them) as `f32` planes, row by row; `None` for every
    /// other channel. Blocks are decoded one at a time on this thread, and only those of the parts
    /// and the resolution level read. Refused first where the planes and `then_bytes` (what the
    /// caller builds from them) need more memory than the machine has free.
    fn decode(&mut self, path: &Path, used: &[usize], then_bytes: u128) -> Result<Vec<Option<Vec<f32>>>> {
        let area = |i: usize| self.headers[self.index[i].0].layer_size.area();
        let planes_bytes: u128 = used.iter().map(|&i| area(i) as u128 * 4).sum();
        let what = format!("decoding {} ({} of its {} channels, then the image)", path.display(), used.len(), self.names.len());
        crate::memory::check_fits(&what, planes_bytes + then_bytes, crate::memory::available())?;
        // Where each (part, channel) goes: its plane, or nowhere.
        let mut slot_of: Vec<Vec<Option<usize>>> = self.headers.iter().map(|h| vec![None; h.channels.list.len()]).collect();
        let mut planes: Vec<Option<Vec<f32>>> = vec![None; self.names.len()];
        for &i in used {
            let (p, c) = self.index[i];
            slot_of[p][c] = Some(i);
            planes[i] = Some(dof_core::error::filled(area(i), 0.0f32, "an EXR channel")?);
        }
        let mut written = vec![0usize; self.names.len()];
        let (headers, names, file) = (&self.headers, &self.names, &mut self.file);
        guarded(path, || {
            file.seek(SeekFrom::Start(0)).map_err(|e| fs_error("read", path, &e))?;
            let reader = ::exr::block::read(BufReader::new(&mut *file), false).map_err(|e| exr_error(path, e))?;
            let wanted = |layer: usize| slot_of[layer].iter().any(Option::is_some);
            let chunks = reader
                .filter_chunks(false, |_, _, block| block.level == Vec2(0, 0) && wanted(block.layer))
                .map_err(|e| exr_error(path, e))?;
            let corrupt = |name: &str| {
                Error::invalid(format!("{}: channel `{name}` has lines outside its data window; the file is corrupt", path.display()))
            };
            for block in chunks.sequential_decompressor(false) {
                let block = block.map_err(|e| exr_error(path, e))?;
                let header = &headers[block.index.layer];
                let width = header.layer_size.x();
                for line in block.lines(&header.channels) {
                    let at = line.location;
                    let Some(i) = slot_of[at.layer][at.channel] else { continue };
                    let Some(plane) = planes[i].as_mut() else { continue };
                    let start = at.position.y() * width + at.position.x();
                    let Some(row) = plane.get_mut(start..start + at.sample_count).filter(|_| at.position.x() + at.sample_count <= width)
                    else {
                        return Err(corrupt(&names[i]));
                    };
                    match header.channels.list[at.channel].sample_type {
                        SampleType::F32 => line.read_samples_into_slice(row).map_err(|e| exr_error(path, e))?,
                        SampleType::F16 => {
                            for (out, v) in row.iter_mut().zip(line.read_samples::<f16>()) {
                                *out = v.map_err(|e| exr_error(path, e))?.to_f32();
                            }
                        }
                        SampleType::U32 => {
                            for (out, v) in row.iter_mut().zip(line.read_samples::<u32>()) {
                                *out = v.map_err(|e| exr_error(path, e))? as f32;
                            }
                        }
                    }
                    written[i] += at.sample_count;
                }
            }
            Ok(())
        })?;
        for &i in used {
            if written[i] != area(i) {
                let size = self.headers[self.index[i].0].layer_size;
                return Err(Error::invalid(format!(
                    "{}: channel `{}` holds {} samples, expected {}x{} = {}; the file is corrupt",
                    path.display(),
                    self.names[i],
                    written[i],
                    size.x(),
                    size.y(),
                    area(i)
                )));
            }
        }
        Ok(planes)
    }

    fn report(&self, layout: ExrLayout, width: u32, height: u32, groups: &[Group]) -> InputReport {
        let mut used: Vec<usize> = groups.iter().flat_map(|g| g.used()).collect();
        used.sort_unstable();
        InputReport {
            layout,
            width,
            height,
            layers: groups.iter().map(|g| g.name.clone()).collect(),
            channels: groups.iter().flat_map(|g| g.used()).map(|i| self.names[i].clone()).collect(),
            ignored_channels: (0..self.names.len()).filter(|i| used.binary_search(i).is_err()).map(|i| self.names[i].clone()).collect(),
            counts: SanitizeCounts::default(),
            window: super::ExrWindow::plain(width, height),
        }
    }
}

/// One way the channels of a file can be read as a layered image.
struct Candidate {
    layout: ExrLayout,
    groups: Vec<Group>,
    /// What it is, with its channels, for the error when a file holds several.
    what: String,
}

/// Finds every image the file holds (see [`read_layered_exr`]) and picks the only one, or errors.
fn select_layers(path: &Path, file: &ExrFile) -> Result<(ExrLayout, Vec<Group>)> {
    let groups = group_channels(&file.names);
    let channels_of = |g: &Group| g.used().map(|i| file.names[i].as_str()).collect::<Vec<_>>().join(", ");
    let mut candidates = Vec::new();

    // The unnamed layer with colour and depth.
    if let Some(root) = groups.iter().find(|g| g.name.is_empty() && g.is_complete()) {
        candidates.push(Candidate {
            layout: ExrLayout::RgbZ,
            groups: vec![root.clone()],
            what: format!("RGB+Z from the unnamed channels {}", channels_of(root)),
        });
    }
    // A colour layer without depth and its sibling depth layer (Blender, Nuke).
    for colour in groups.iter().filter(|g| g.has_rgb() && g.depth.is_none()) {
        for depth in groups.iter().filter(|d| d.is_depth_only() && is_depth_sibling(&colour.name, &d.name)) {
            let pair = Group { depth: depth.depth, ..colour.clone() };
            let name = if colour.name.is_empty() { "the unnamed layer".to_string() } else { format!("`{}`", colour.name) };
            candidates.push(Candidate {
                layout: ExrLayout::RgbZ,
                what: format!("RGB+Z from {name} with the depth of `{}` ({})", depth.name, channels_of(&pair)),
                groups: vec![pair],
            });
        }
    }
    // Every complete named layer.
    let complete: Vec<Group> = groups.iter().filter(|g| !g.name.is_empty() && g.is_complete()).cloned().collect();
    if !complete.is_empty() {
        let names = complete.iter().map(|g| format!("`{}`", g.name)).collect::<Vec<_>>().join(", ");
        let channels = complete.iter().flat_map(|g| g.used()).map(|i| file.names[i].clone()).collect::<Vec<_>>();
        candidates.push(Candidate {
            layout: ExrLayout::MultiLayer,
            groups: complete,
            what: format!("a multi-layer image of the layers {names} ({})", list(&channels)),
        });
    }

    if candidates.len() > 1 {
        let each = candidates.iter().enumerate().map(|(i, c)| format!("({}) {}", i + 1, c.what)).collect::<Vec<_>>();
        return Err(Error::invalid(format!(
            "{} is ambiguous: its channels hold {} different images and nothing says which one to read: {}. Keep the \
             channels of the one to use and remove the others (or export only that layer). Channels: {}",
            path.display(),
            candidates.len(),
            each.join("; "),
            list(&file.names)
        )));
    }
    if let Some(Candidate { layout, groups: chosen, .. }) = candidates.pop() {
        if layout == ExrLayout::MultiLayer
            && let Some(bad) = groups.iter().find(|g| !g.name.is_empty() && g.has_color() && !g.is_complete())
        {
            let problem = if !bad.has_rgb() {
                format!("has only some colour channels (missing {})", bad.missing_colors().join(", "))
            } else {
                "has no depth: it needs a Z channel".to_string()
            };
            return Err(Error::invalid(format!(
                "{}: layer `{}` {problem}; every layer of a multi-layer EXR needs `<layer>.R`, `.G`, `.B` and `.Z` \
                 (`.A` optional). Complete the layer or remove its channels. Channels: {}",
                path.display(),
                bad.name,
                list(&file.names)
            )));
        }
        return Ok((layout, chosen));
    }

    // Nothing to read: say what is missing.
    const SIBLINGS: &str = "or the depth layer beside it that Blender and Nuke write (`<P>.Depth.Z` beside \
                            `<P>.Combined`, `depth.Z` beside `rgba` or the unnamed R, G, B)";
    let depth_layers: Vec<String> =
        groups.iter().filter(|g| !g.name.is_empty() && g.is_depth_only()).map(|g| format!("`{}`", g.name)).collect();
    let unmatched = if depth_layers.is_empty() {
        String::new()
    } else {
        format!("; the file's depth layers ({}) belong to no colour layer", depth_layers.join(", "))
    };
    if groups.iter().any(|g| g.name.is_empty() && g.has_rgb()) {
        return Err(Error::invalid(format!(
            "{} has colour but no depth: it needs a Z channel (planar depth; `depth` is accepted too) {SIBLINGS} to be \
             read as a layered image{unmatched}. Channels: {}. Write the renderer's depth pass into the same file as `Z`",
            path.display(),
            list(&file.names)
        )));
    }
    if let Some(g) = groups.iter().find(|g| g.has_rgb()) {
        return Err(Error::invalid(format!(
            "{}: layer `{}` has colour but no depth: it needs a Z channel (`{}.Z`, planar depth) {SIBLINGS}{unmatched}. \
             Channels: {}",
            path.display(),
            g.name,
            g.name,
            list(&file.names)
        )));
    }
    let root = groups.iter().find(|g| g.name.is_empty());
    let missing = root.map_or(vec!["R", "G", "B"], |r| r.missing_colors());
    let depth = if root.is_some_and(|r| r.depth.is_some()) { "" } else { " and a Z channel (depth)" };
    Err(Error::invalid(format!(
        "{} needs the colour channels R, G and B (missing {}){depth}; it has the channels {}",
        path.display(),
        missing.join(", "),
        list(&file.names)
    )))
}

/// Checks an EXR file's headers alone against the limits on EXR input ([`MAX_EXR_EDGE`] pixels a
/// side, [`MAX_EXR_SLOTS`] pixels x depth layers), before anything is decoded: for a caller that
/// decodes the file itself (a mask plane, say).
pub fn check_exr_header(path: impl AsRef<Path>) -> Result<()> {
    let path = path.as_ref();
    let file = open_regular(path)?;
    let meta = guarded(path, || MetaData::read_from_buffered(BufReader::new(file), false).map_err(|e| exr_error(path, e)))?;
    check_declared_size(path, &meta).map(drop)
}

/// The name a channel is known by: in a multi-part file the part name (or `part<index>`) is
/// prefixed where the channel name lacks it.
pub(super) fn full_channel_name(multi_part: bool, part: usize, part_name: Option<&Text>, channel: &Text) -> String {
    let part_name = part_name.map(|t| t.to_string()).unwrap_or_else(|| format!("part{part}"));
    let name = channel.to_string();
    if !multi_part || name.starts_with(&format!("{part_name}.")) { name } else { format!("{part_name}.{name}") }
}

/// Largest width and height of an EXR input, in pixels.
pub const MAX_EXR_EDGE: usize = 16384;
/// Most pixels x depth layers an EXR input may declare: the slots of a [`LayeredImage`]
/// ([`crate::layers::MAX_SLOTS`], 2^28).
pub const MAX_EXR_SLOTS: u64 = crate::layers::MAX_SLOTS;

/// Refuses, from the headers alone (before any pixel is decoded or allocated), a file whose data
/// window is wider or taller than [`MAX_EXR_EDGE`], or whose pixels times depth layers (the
/// complete colour-and-depth layers its channel names announce, at least one) exceed
/// [`MAX_EXR_SLOTS`]. Returns the most slots a part declares.
fn check_declared_size(path: &Path, meta: &MetaData) -> Result<u64> {
    let multi_part = meta.headers.len() > 1;
    let names: Vec<String> = meta
        .headers
        .iter()
        .enumerate()
        .flat_map(|(p, h)| {
            h.channels.list.iter().map(move |c| full_channel_name(multi_part, p, h.own_attributes.layer_name.as_ref(), &c.name))
        })
        .collect();
    let layers = group_channels(&names).iter().filter(|g| g.is_complete()).count().max(1) as u64;
    let mut most = 0;
    for (i, header) in meta.headers.iter().enumerate() {
        let (w, h) = (header.layer_size.x(), header.layer_size.y());
        let slots = (w as u64).saturating_mul(h as u64).saturating_mul(layers);
        if w > MAX_EXR_EDGE || h > MAX_EXR_EDGE || slots > MAX_EXR_SLOTS {
            let part = header.own_attributes.layer_name.as_ref().map_or(format!("part {i}"), |n| format!("part `{n}`"));
            return Err(Error::invalid(format!(
                "{}: the header of {part} declares {w}x{h} pixels with {layers} depth layer(s), beyond the limit on EXR input \
                 of {MAX_EXR_EDGE} pixels a side and {MAX_EXR_SLOTS} pixels x layers; refused before decoding",
                path.display()
            )));
        }
        most = most.max(slots);
    }
    Ok(most)
}

/// A header announcing more pixel data than this many times the file size plus
/// [`EXPANSION_SLACK`] is corrupt: no EXR compression reaches that ratio on real images, and the
/// check keeps a few flipped header bytes from asking for gigabytes.
const MAX_EXPANSION: u128 = 4096;
const EXPANSION_SLACK: u128 = 256 << 20;

/// Runs the exr crate's decoder, turning a panic inside it into an error: its overflow checks and
/// index assertions can trip on corrupt data. Decoding runs on this thread (`non_parallel`) so that
/// such a panic unwinds to here; in the crate's thread pool it would abort the process.
pub(super) fn guarded<T>(path: &Path, decode: impl FnOnce() -> Result<T>) -> Result<T> {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(decode)) {
        Ok(result) => result,
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "no message".to_string());
            Err(Error::invalid(format!("{} is corrupt: the EXR decoder failed on its data ({what}); re-export it", path.display())))
        }
    }
}

/// Returns the first part whose `dataWindow` has a maximum below its minimum, with its
/// `[xMin, yMin, xMax, yMax]` (see [`walk_headers`]; an irregular header gives `None`, leaving the
/// diagnosis to the exr crate).
fn empty_data_window(r: &mut impl Read) -> Option<(usize, [i32; 4])> {
    let mut found = None;
    walk_headers(r, |part, name, kind, value| {
        if found.is_none() && name == b"dataWindow" && kind == b"box2i" && value.len() == 16 {
            let b: [i32; 4] = std::array::from_fn(|i| i32::from_le_bytes(word(value, 4 * i)));
            if b[2] < b[0] || b[3] < b[1] {
                found = Some((part, b));
            }
        }
    });
    found
}

/// Walks the raw header attributes of every part (OpenEXR file layout: magic, version, then per part
/// `name\0type\0size value` until an empty name; multi-part files end with an empty header),
/// handing `visit` each attribute's part, name, type and value (values over 1 KiB are skipped and
/// handed as empty). Returns the offset of the first byte after the headers (where the chunk offset
/// tables begin), or `None` at the first irregularity.
pub(super) fn walk_headers(r: &mut impl Read, mut visit: impl FnMut(usize, &[u8], &[u8], &[u8])) -> Option<u64> {
    struct Counted<R> {
        inner: R,
        read: u64,
    }
    impl<R: Read> Read for Counted<R> {
        fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
            let n = self.inner.read(buf)?;
            self.read += n as u64;
            Ok(n)
        }
    }
    fn read_i32(r: &mut impl Read) -> Option<i32> {
        let mut b = [0; 4];
        r.read_exact(&mut b).ok()?;
        Some(i32::from_le_bytes(b))
    }
    // Callers hand a `BufReader`: byte by byte is cheap here.
    #[allow(clippy::unbuffered_bytes)]
    fn read_name(r: &mut impl Read) -> Option<Vec<u8>> {
        let mut name = Vec::new();
        for byte in r.bytes() {
            match byte.ok()? {
                0 => return Some(name),
                b if name.len() < 256 => name.push(b),
                _ => return None,
            }
        }
        None
    }
    let r = &mut Counted { inner: r, read: 0 };
    let _magic = read_i32(r)?;
    let flags = read_i32(r)? as u32;
    let multi_part = flags & 0x1000 != 0;
    for part in 0.. {
        let mut attributes = 0;
        loop {
            let name = read_name(r)?;
            if name.is_empty() {
                break;
            }
            attributes += 1;
            let kind = read_name(r)?;
            let size = u64::try_from(read_i32(r)?).ok()?;
            if size <= 1024 {
                let mut value = vec![0; size as usize];
                r.read_exact(&mut value).ok()?;
                visit(part, &name, &kind, &value);
            } else if std::io::copy(&mut r.by_ref().take(size), &mut std::io::sink()).ok()? != size {
                return None;
            } else {
                visit(part, &name, &kind, &[]);
            }
        }
        if !multi_part || attributes == 0 {
            return Some(r.read);
        }
    }
    None
}

/// The four bytes of `bytes` from `at` (callers check the length first).
pub(super) fn word(bytes: &[u8], at: usize) -> [u8; 4] {
    [bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]]
}

/// The OpenEXR magic number, with a hint for common non-EXR files.
pub(super) fn check_magic(path: &Path, head: &[u8]) -> Result<()> {
    const EXR: [u8; 4] = [0x76, 0x2f, 0x31, 0x01];
    if head.len() >= 4 && head[..4] == EXR {
        return Ok(());
    }
    let what = if head.is_empty() {
        "it is empty".to_string()
    } else if head.starts_with(b"\x89PNG") {
        "it is a PNG image".to_string()
    } else if head.starts_with(&[0xff, 0xd8, 0xff]) {
        "it is a JPEG image".to_string()
    } else if head.starts_with(b"II*\0") || head.starts_with(b"MM\0*") {
        "it is a TIFF image".to_string()
    } else if head.len() < 4 {
        format!("it holds only {} bytes", head.len())
    } else {
        format!("it starts with the bytes {:02x?}, not the EXR signature 76 2f 31 01", &head[..4])
    };
    Err(Error::invalid(format!("{} is not an OpenEXR file: {what}", path.display())))
}

pub(super) fn exr_error(path: &Path, e: ::exr::error::Error) -> Error {
    use ::exr::error::Error as E;
    let path = path.display();
    Error::invalid(match e {
        E::Invalid(msg) if msg.contains("missing bytes") => format!(
            "{path} is truncated: the file ends before all the data its header announces ({msg}); \
             re-export or copy it again"
        ),
        E::Invalid(msg) => format!("{path} is not a valid OpenEXR file ({msg}): it is corrupt or truncated; re-export it"),
        E::NotSupported(msg) => format!(
            "{path} is corrupt or uses an OpenEXR feature this reader does not support ({msg}); \
             flat scan-line or tiled images of half, float or uint channels are supported"
        ),
        E::Io(io) => format!("cannot read {path}: {io}"),
        E::Aborted => format!("reading {path} was aborted"),
    })
}

/// At most 24 names, comma-separated.
pub(super) fn list(names: &[String]) -> String {
    const SHOWN: usize = 24;
    let mut s = names.iter().take(SHOWN).map(String::as_str).collect::<Vec<_>>().join(", ");
    if names.len() > SHOWN {
        s += &format!(" and {} more", names.len() - SHOWN);
    }
    if s.is_empty() { "(none)".to_string() } else { s }
}
