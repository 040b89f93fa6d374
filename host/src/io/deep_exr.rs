//! Deep OpenEXR input (OpenEXR 2.0 deep scan-line and deep tiled parts, single- or multi-part) to a
//! tidy [`DeepImage`].
//!
//! The exr crate parses the headers; the chunks, their pixel offset tables and sample data are read
//! here, with [`deep_codec`](super::deep_codec) for the compressions OpenEXR allows for deep data
//! (none, RLE, ZIPS, ZIP). The exr crate's own block reader bounds a chunk by the size of a flat
//! block, which deep chunks exceed, and OpenEXR's C++ library would bring a C++ build into every
//! build of this crate; the layout is small and documented ("OpenEXR File Layout"), and reading it
//! here keeps every allocation bounded by what the file holds.
//!
//! **Channels.** In each deep part: `R`, `G`, `B` (premultiplied colour; a missing one is 0), `A`
//! (coverage; where absent, the mean of `AR`, `AG`, `AB`, else 1), `Z` (required) and `ZBack`
//! (optional; equal to `Z` when absent), with or without one layer prefix (`rgba.R`, `depth.Z`
//! are read as `R`, `Z`). Other channels are listed in the report, as are flat parts of the file.
//! Per-channel alpha (`AR`, `AG`, `AB`) is reduced to one coverage: samples whose channels differ
//! are counted.
//!
//! **Samples** follow the input rules of [`super`] (the NaN/Inf policy: NaN colour to 0, alpha
//! clamped, NaN, zero or negative `Z` dropped, `Z` at `+inf` or beyond the background threshold the
//! background); a `ZBack` that is NaN or in front of `Z` becomes `Z`. Every deep part of every file
//! read together goes into one image over the union of their data windows (a deep merge), which is
//! then made tidy ([`DeepImage::tidy`]).
//!
//! **Bad files** are refused with a message naming the file and the problem: an offset table
//! pointing outside the file or at a chunk of another part, line or tile; a chunk read twice or
//! never written; pixel offset tables that decrease or disagree with the sample data's size;
//! streams that do not decode to the size declared; more samples than [`MAX_DEEP_SAMPLES`].
//! Nothing is allocated beyond what the file's bytes can decode to.

use std::fmt;
use std::fs::File;
use std::io::{BufReader, Read, Seek, SeekFrom};
use std::path::Path;

use ::exr::meta::BlockDescription;
use ::exr::meta::attribute::{ChannelDescription, SampleType};
use ::exr::meta::header::Header;
use ::exr::prelude::*;

use super::deep_codec::unpack;
use super::exr_read::{check_magic, exr_error, guarded, list, open_regular, walk_headers, word};
use super::fs_error;
use super::sanitize::SanitizeCounts;
use crate::deep::{DeepImage, DeepSample, MAX_DEEP_SAMPLES, TidyReport};
use crate::error::{Error, Result};

/// What reading deep files found and changed.
#[derive(Clone, Debug, PartialEq)]
pub struct DeepReport {
    pub width: u32,
    pub height: u32,
    /// Where the image (the union of the parts' data windows) lies in the files' pixel space, with
    /// the first part's display window: write the result with it to keep its place.
    pub window: super::ExrWindow,
    /// The deep parts read, as `file: part (type, compression)`.
    pub parts: Vec<String>,
    /// Channels read, and those not read (other channels, flat parts).
    pub channels: Vec<String>,
    pub ignored_channels: Vec<String>,
    /// Samples in the files, and after making the image tidy.
    pub samples_read: u64,
    pub samples: u64,
    /// The most samples a pixel holds once tidy.
    pub max_samples: u64,
    /// The NaN/Inf policy's counts over every sample.
    pub counts: SanitizeCounts,
    /// `ZBack` values NaN or in front of `Z`, taken as `Z`.
    pub z_back_repaired: u64,
    /// Samples whose `AR`, `AG`, `AB` differ, reduced to their mean.
    pub coloured_alpha: u64,
    pub tidy: TidyReport,
}

impl fmt::Display for DeepReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}x{} deep image from {}: {} samples read, {} once tidy (at most {} a pixel)",
            self.width,
            self.height,
            self.parts.join(", "),
            self.samples_read,
            self.samples,
            self.max_samples
        )?;
        let c = &self.counts;
        let t = &self.tidy;
        let items = [
            (t.volumes_split, format!("volume samples split where others begin or end inside them (into {} pieces)", t.pieces)),
            (t.merged, "samples merged with others over the same depth range".to_string()),
            (t.behind_background + c.behind_background, "samples behind the background dropped".to_string()),
            (c.depth_invalid, "samples with NaN, zero or negative Z dropped".to_string()),
            (self.z_back_repaired, "ZBack values NaN or in front of Z taken as Z".to_string()),
            (c.color_nan + c.color_inf, "NaN or infinite colour values repaired (NaN to 0, +inf to 65504, -inf to 0)".to_string()),
            (c.alpha_invalid, "alpha values NaN or outside [0, 1] clamped".to_string()),
            (c.empty_alpha, "samples of alpha 0 and no colour dropped (they show and hide nothing)".to_string()),
            (c.emission_only, "samples of alpha 0 with a colour, read as light that hides nothing".to_string()),
            (self.coloured_alpha, "samples whose AR, AG, AB differ, given their mean as coverage".to_string()),
            (c.background, "background samples (Z +inf or beyond the background threshold)".to_string()),
        ];
        for (n, what) in items {
            if n > 0 {
                write!(f, "\n  {n} {what}")?;
            }
        }
        if !self.ignored_channels.is_empty() {
            write!(f, "\n  not read: {}", list(&self.ignored_channels))?;
        }
        Ok(())
    }
}

/// Whether the file at `path` is an OpenEXR file with deep data (the version field's deep flag),
/// from its first 8 bytes. Errors when it cannot be read or is not an OpenEXR file.
pub fn is_deep_exr(path: impl AsRef<Path>) -> Result<bool> {
    let path = path.as_ref();
    let mut file = open_regular(path)?;
    let mut head = Vec::with_capacity(8);
    (&mut file).take(8).read_to_end(&mut head).map_err(|e| fs_error("read", path, &e))?;
    check_magic(path, &head)?;
    Ok(head.len() == 8 && u32::from_le_bytes(word(&head, 4)) & 0x800 != 0)
}

/// Reads every deep part of every file in `paths` into one tidy deep image over the union of their
/// data windows (module docs), with a report of what was read and changed.
pub fn read_deep_exr<P: AsRef<Path>>(paths: &[P]) -> Result<(DeepImage, DeepReport)> {
    let mut report = DeepReport {
        width: 0,
        height: 0,
        window: super::ExrWindow::plain(1, 1),
        parts: Vec::new(),
        channels: Vec::new(),
        ignored_channels: Vec::new(),
        samples_read: 0,
        samples: 0,
        max_samples: 0,
        counts: SanitizeCounts::default(),
        z_back_repaired: 0,
        coloured_alpha: 0,
        tidy: TidyReport::default(),
    };
    let mut parts = Vec::new();
    for path in paths {
        read_file(path.as_ref(), &mut parts, &mut report)?;
    }
    let Some(first) = parts.first() else { return Err(Error::invalid("no deep file given".to_string())) };
    let display = first.display;
    let (mut x0, mut y0, mut x1, mut y1) = (i64::MAX, i64::MAX, i64::MIN, i64::MIN);
    for p in &parts {
        x0 = x0.min(p.origin.0);
        y0 = y0.min(p.origin.1);
        x1 = x1.max(p.origin.0 + p.image.width as i64);
        y1 = y1.max(p.origin.1 + p.image.height as i64);
    }
    let (width, height) = ((x1 - x0) as u64, (y1 - y0) as u64);
    if width > super::MAX_EXR_EDGE as u64 || height > super::MAX_EXR_EDGE as u64 {
        return Err(Error::invalid(format!(
            "the deep parts' data windows span {width}x{height} pixels together, beyond the limit of {} a side",
            super::MAX_EXR_EDGE
        )));
    }
    let (width, height) = (width as u32, height as u32);
    // Each part placed in the union, then all merged and made tidy.
    let placed: Vec<DeepImage> =
        parts.iter().map(|p| place(&p.image, (p.origin.0 - x0) as u32, (p.origin.1 - y0) as u32, width, height)).collect::<Result<_>>()?;
    let merged = match <[DeepImage; 1]>::try_from(placed) {
        Ok([only]) => only,
        Err(placed) => DeepImage::merge(&placed)?,
    };
    let (image, tidy) = merged.tidy()?;
    report.width = width;
    report.height = height;
    report.window = super::ExrWindow { origin: (x0 as i32, y0 as i32), display };
    report.samples = image.samples.len() as u64;
    report.max_samples = image.max_count();
    report.tidy = tidy;
    Ok((image, report))
}

/// A deep part read, with the position of its data window's corner and its display window.
struct Part {
    origin: (i64, i64),
    display: [i32; 4],
    image: DeepImage,
}

/// `image` at `(x, y)` of an empty `width` x `height` image.
fn place(image: &DeepImage, x: u32, y: u32, width: u32, height: u32) -> Result<DeepImage> {
    if (x, y, width, height) == (0, 0, image.width, image.height) {
        return Ok(image.clone());
    }
    let mut counts = vec![0u32; width as usize * height as usize];
    for py in 0..image.height {
        for px in 0..image.width {
            counts[((y + py) * width + x + px) as usize] = image.count((py * image.width + px) as usize) as u32;
        }
    }
    let mut samples = Vec::with_capacity(image.samples.len());
    for gy in 0..height {
        for gx in 0..width {
            if gy >= y && gy < y + image.height && gx >= x && gx < x + image.width {
                samples.extend_from_slice(image.pixel(((gy - y) * image.width + gx - x) as usize));
            }
        }
    }
    DeepImage::from_counts(width, height, &counts, samples)
}

/// Which channel of a deep part feeds which field of a sample.
#[derive(Clone, Copy, Debug, Default)]
struct Fields {
    r: Option<usize>,
    g: Option<usize>,
    b: Option<usize>,
    a: Option<usize>,
    ar: Option<usize>,
    ag: Option<usize>,
    ab: Option<usize>,
    z: usize,
    z_back: Option<usize>,
}

fn read_file(path: &Path, parts: &mut Vec<Part>, report: &mut DeepReport) -> Result<()> {
    let corrupt = |what: String| Error::invalid(format!("{} is corrupt: {what}; re-export it", path.display()));
    let mut file = open_regular(path)?;
    let file_len = file.metadata().map_err(|e| fs_error("read", path, &e))?.len();
    let mut head = Vec::with_capacity(8);
    (&mut file).take(8).read_to_end(&mut head).map_err(|e| fs_error("read", path, &e))?;
    check_magic(path, &head)?;
    let seek = |file: &mut File, at: u64| file.seek(SeekFrom::Start(at)).map(|_| ()).map_err(|e| fs_error("read", path, &e));
    seek(&mut file, 0)?;
    let tables_at =
        walk_headers(&mut BufReader::new(&mut file), |_, _, _, _| {}).ok_or_else(|| corrupt("its headers do not parse".to_string()))?;
    seek(&mut file, 0)?;
    let meta = guarded(path, || MetaData::read_from_buffered(BufReader::new(&mut file), false).map_err(|e| exr_error(path, e)))?;
    let multi_part = meta.headers.len() > 1;

    // The chunk offset tables, one per part, right after the headers.
    seek(&mut file, tables_at)?;
    let mut reader = BufReader::new(&mut file);
    let mut tables = Vec::with_capacity(meta.headers.len());
    for (i, header) in meta.headers.iter().enumerate() {
        if header.chunk_count as u64 > file_len / 8 {
            return Err(corrupt(format!("part {i} announces {} chunks in a file of {file_len} bytes", header.chunk_count)));
        }
        let mut table = vec![0u64; header.chunk_count];
        for entry in &mut table {
            *entry = read_u64(&mut reader).map_err(|_| corrupt("its chunk offset tables are truncated".to_string()))?;
        }
        tables.push(table);
    }
    drop(reader);
    let chunks_at = tables_at + 8 * tables.iter().map(|t| t.len() as u64).sum::<u64>();

    let file_name = path.display().to_string();
    let mut read_any = false;
    for (index, header) in meta.headers.iter().enumerate() {
        let part_name = header.own_attributes.layer_name.as_ref().map_or(format!("part {index}"), |n| format!("part `{n}`"));
        let names: Vec<String> = header.channels.list.iter().map(|c| c.name.to_string()).collect();
        if !header.deep {
            report.ignored_channels.extend(names.iter().map(|n| format!("{n} (flat {part_name})")));
            continue;
        }
        let what = |detail: String| Error::invalid(format!("{}: deep {part_name}: {detail}", path.display()));
        match header.compression {
            Compression::Uncompressed | Compression::RLE | Compression::ZIP1 | Compression::ZIP16 => {}
            other => return Err(what(format!("compression {other:?} is not one OpenEXR allows for deep data (none, RLE, ZIPS, ZIP)"))),
        }
        if let Some(c) = header.channels.list.iter().find(|c| c.sampling != Vec2(1, 1)) {
            return Err(what(format!("channel `{}` is subsampled, which deep data does not allow", c.name)));
        }
        let (fields, used, ignored) = fields_of(&names).map_err(what)?;
        report.channels.extend(used.iter().map(|n| format!("{file_name}: {n}")));
        report.ignored_channels.extend(ignored);
        let (w, h) = (header.layer_size.x(), header.layer_size.y());
        if w == 0 || h == 0 || w > super::MAX_EXR_EDGE || h > super::MAX_EXR_EDGE {
            return Err(what(format!("its data window is {w}x{h}, outside 1 to {} pixels a side", super::MAX_EXR_EDGE)));
        }
        let layout = Layout::of(header);
        let mut blocks =
            Blocks { width: w, height: h, counts: vec![0; w * h], chunks: Vec::new(), samples: 0, seen: vec![false; layout.blocks(w, h)] };
        let mut chunk_file = BufReader::new(&mut file);
        for (k, &offset) in tables[index].iter().enumerate() {
            if offset == 0 {
                return Err(what(format!("chunk {k} was never written (its offset is 0): the file is incomplete")));
            }
            if offset < chunks_at || offset >= file_len {
                return Err(corrupt(format!(
                    "{part_name}'s chunk {k} is at offset {offset}, outside the chunks (bytes {chunks_at} to {file_len})"
                )));
            }
            chunk_file.seek(SeekFrom::Start(offset)).map_err(|e| fs_error("read", path, &e))?;
            read_chunk(&mut chunk_file, file_len, multi_part, index, header, &layout, &fields, &mut blocks, report)
                .map_err(|e| corrupt(format!("{part_name}, chunk {k} at offset {offset}: {e}")))?;
        }
        if let Some(missing) = blocks.seen.iter().position(|s| !s) {
            return Err(what(format!("block {missing} of its pixels is in no chunk: the file is incomplete")));
        }
        let image = blocks.assemble()?;
        report.samples_read += image.samples.len() as u64;
        let kind = if matches!(layout, Layout::Tiles { .. }) { "deep tiles" } else { "deep scan lines" };
        let compression = match header.compression {
            Compression::Uncompressed => "no compression",
            Compression::RLE => "RLE",
            Compression::ZIP1 => "ZIPS",
            _ => "ZIP",
        };
        report.parts.push(format!("{file_name}: {part_name} ({kind}, {compression})"));
        let origin = header.own_attributes.layer_position;
        let d = header.shared_attributes.display_window;
        let display = [d.position.x(), d.position.y(), d.max().x(), d.max().y()];
        parts.push(Part { origin: (origin.x() as i64, origin.y() as i64), display, image });
        read_any = true;
    }
    if !read_any {
        return Err(Error::invalid(format!("{} holds no deep part: read it as a flat EXR", path.display())));
    }
    Ok(())
}

/// The fields of a part's channels (by the name after the last `.`), those used and those not.
fn fields_of(names: &[String]) -> std::result::Result<(Fields, Vec<String>, Vec<String>), String> {
    let mut f = Fields::default();
    let mut z = None;
    let (mut used, mut ignored) = (Vec::new(), Vec::new());
    let prefixes: std::collections::BTreeSet<&str> = names.iter().map(|n| n.rsplit_once('.').map_or("", |(p, _)| p)).collect();
    for (i, name) in names.iter().enumerate() {
        let short = name.rsplit_once('.').map_or(name.as_str(), |(_, s)| s);
        let slot = match short {
            "R" => &mut f.r,
            "G" => &mut f.g,
            "B" => &mut f.b,
            "A" => &mut f.a,
            "AR" => &mut f.ar,
            "AG" => &mut f.ag,
            "AB" => &mut f.ab,
            "Z" => &mut z,
            "ZBack" => &mut f.z_back,
            _ => {
                ignored.push(name.clone());
                continue;
            }
        };
        if slot.is_some() {
            return Err(format!(
                "channel `{name}` repeats a field another layer gives ({}): one deep sample layer a part is supported",
                prefixes.iter().copied().collect::<Vec<_>>().join(", ")
            ));
        }
        *slot = Some(i);
        used.push(name.clone());
    }
    let Some(z) = z else { return Err(format!("it has no Z channel (channels: {})", list(names))) };
    f.z = z;
    if [f.r, f.g, f.b, f.a, f.ar, f.ag, f.ab].iter().all(Option::is_none) {
        return Err(format!("it has no colour or alpha channel (channels: {})", list(names)));
    }
    Ok((f, used, ignored))
}

/// How a part's pixels are cut into chunks.
enum Layout {
    Lines { per_block: usize },
    Tiles { size: (usize, usize) },
}

impl Layout {
    fn of(header: &Header) -> Layout {
        match header.blocks {
            BlockDescription::ScanLines => Layout::Lines { per_block: header.compression.scan_lines_per_block() },
            BlockDescription::Tiles(t) => Layout::Tiles { size: (t.tile_size.x().max(1), t.tile_size.y().max(1)) },
        }
    }

    /// The blocks of the full-resolution level.
    fn blocks(&self, w: usize, h: usize) -> usize {
        match *self {
            Layout::Lines { per_block } => h.div_ceil(per_block),
            Layout::Tiles { size } => w.div_ceil(size.0) * h.div_ceil(size.1),
        }
    }
}

/// A part's chunks as read: per-pixel counts, and each chunk's samples with its rectangle.
struct Blocks {
    width: usize,
    height: usize,
    counts: Vec<u32>,
    /// (x0, y0, w, h, samples in row-major pixel order).
    chunks: Vec<(usize, usize, usize, usize, Vec<DeepSample>)>,
    /// Samples the chunks hold so far.
    samples: u64,
    seen: Vec<bool>,
}

impl Blocks {
    fn assemble(self) -> Result<DeepImage> {
        let mut start = vec![0u64; self.width * self.height + 1];
        for (p, &n) in self.counts.iter().enumerate() {
            start[p + 1] = start[p] + n as u64;
        }
        let mut samples = vec![DeepSample { color: [0.0; 3], alpha: 0.0, z: 0.0, z_back: 0.0 }; start[self.counts.len()] as usize];
        for (x0, y0, w, h, chunk) in &self.chunks {
            let mut i = 0;
            for y in *y0..y0 + h {
                for x in *x0..x0 + w {
                    let p = y * self.width + x;
                    let n = self.counts[p] as usize;
                    samples[start[p] as usize..start[p] as usize + n].copy_from_slice(&chunk[i..i + n]);
                    i += n;
                }
            }
        }
        DeepImage::from_counts(self.width as u32, self.height as u32, &self.counts, samples)
    }
}

fn read_u64(r: &mut impl Read) -> std::io::Result<u64> {
    let mut b = [0; 8];
    r.read_exact(&mut b)?;
    Ok(u64::from_le_bytes(b))
}

fn read_i32(r: &mut impl Read) -> std::io::Result<i32> {
    let mut b = [0; 4];
    r.read_exact(&mut b)?;
    Ok(i32::from_le_bytes(b))
}

fn sample_bytes(c: &ChannelDescription) -> usize {
    match c.sample_type {
        SampleType::F16 => 2,
        SampleType::F32 | SampleType::U32 => 4,
    }
}

/// Reads the chunk at the reader's position into `blocks`; errors say what is wrong with it.
#[allow(clippy::too_many_arguments)]
fn read_chunk(
    r: &mut (impl Read + Seek),
    file_len: u64,
    multi_part: bool,
    index: usize,
    header: &Header,
    layout: &Layout,
    fields: &Fields,
    blocks: &mut Blocks,
    report: &mut DeepReport,
) -> std::result::Result<(), String> {
    let io = |e: std::io::Error| format!("it ends early ({e})");
    if multi_part {
        let part = read_i32(r).map_err(io)?;
        if part as i64 != index as i64 {
            return Err(format!("it belongs to part {part}, not to the part whose table points at it"));
        }
    }
    let origin = header.own_attributes.layer_position;
    let (w, h) = (blocks.width, blocks.height);
    // The block's rectangle within the data window, and its index.
    let (x0, y0, bw, bh, block, table_rows) = match *layout {
        Layout::Lines { per_block } => {
            let y = read_i32(r).map_err(io)? as i64 - origin.y() as i64;
            if y < 0 || y >= h as i64 || !(y as usize).is_multiple_of(per_block) {
                return Err(format!("its first line {} is not the start of a block of the data window", y + origin.y() as i64));
            }
            let y = y as usize;
            let bh = per_block.min(h - y);
            (0, y, w, bh, y / per_block, None)
        }
        Layout::Tiles { size } => {
            let [tx, ty, lx, ly] = [read_i32(r).map_err(io)?, read_i32(r).map_err(io)?, read_i32(r).map_err(io)?, read_i32(r).map_err(io)?];
            if (lx, ly) != (0, 0) {
                // A lower-resolution level: the full resolution is what is read.
                return Ok(());
            }
            let (across, down) = (w.div_ceil(size.0), h.div_ceil(size.1));
            if tx < 0 || ty < 0 || tx as usize >= across || ty as usize >= down {
                return Err(format!("its tile ({tx}, {ty}) lies outside the {across}x{down} tiles of the data window"));
            }
            let (x0, y0) = (tx as usize * size.0, ty as usize * size.1);
            (x0, y0, size.0.min(w - x0), size.1.min(h - y0), ty as usize * across + tx as usize, Some(size))
        }
    };
    if blocks.seen[block] {
        return Err(format!("block {block} was already read from another chunk (the offset table repeats it)"));
    }
    blocks.seen[block] = true;
    let packed_table = read_u64(r).map_err(io)?;
    let packed_samples = read_u64(r).map_err(io)?;
    let unpacked_samples = read_u64(r).map_err(io)?;
    let here = r.stream_position().map_err(io)?;
    if packed_table.saturating_add(packed_samples) > file_len.saturating_sub(here) {
        return Err(format!(
            "it declares {packed_table} + {packed_samples} bytes but the file ends {} bytes on",
            file_len.saturating_sub(here)
        ));
    }
    let mut bytes = vec![0u8; packed_table as usize];
    r.read_exact(&mut bytes).map_err(io)?;
    // The pixel offset table: per row, each pixel's samples and those left of it. A tile's table
    // may cover the whole tile even where the data window clips it.
    let clipped = bw * bh * 4;
    let full = table_rows.map_or(clipped, |(tw, th)| tw * th * 4);
    let table = unpack(header.compression, &bytes, clipped)
        .or_else(|e| if full != clipped { unpack(header.compression, &bytes, full) } else { Err(e) });
    let table = table.map_err(|e| format!("its pixel offset table: {e}"))?;
    let stride = if table.len() == clipped { bw } else { table_rows.map_or(bw, |(tw, _)| tw) };
    let mut total = 0u64;
    let mut row_totals = Vec::with_capacity(bh);
    for y in 0..bh {
        let mut last = 0i64;
        for x in 0..bw {
            let k = (y * stride + x) * 4;
            let cumulative = i32::from_le_bytes(word(&table, k)) as i64;
            if cumulative < last {
                return Err(format!("its pixel offset table decreases at pixel ({}, {}) ({last} then {cumulative})", x0 + x, y0 + y));
            }
            blocks.counts[(y0 + y) * w + x0 + x] = (cumulative - last) as u32;
            last = cumulative;
        }
        row_totals.push(last as u64);
        total += last as u64;
    }
    let per_sample: usize = header.channels.list.iter().map(sample_bytes).sum();
    let read_so_far = blocks.samples + report.samples_read;
    if read_so_far + total > MAX_DEEP_SAMPLES {
        return Err(format!(
            "its pixel offset table brings the samples to {}, beyond the limit of {MAX_DEEP_SAMPLES}",
            read_so_far + total
        ));
    }
    if total * per_sample as u64 != unpacked_samples {
        return Err(format!(
            "its pixel offset table counts {total} samples of {per_sample} bytes, but its sample data declares {unpacked_samples} bytes"
        ));
    }
    let mut bytes = vec![0u8; packed_samples as usize];
    r.read_exact(&mut bytes).map_err(io)?;
    let data = unpack(header.compression, &bytes, unpacked_samples as usize).map_err(|e| format!("its sample data: {e}"))?;
    drop(bytes);

    // Per row, per channel (in the file's order), that row's samples.
    let mut samples = Vec::with_capacity(total as usize);
    let mut values = vec![0f32; header.channels.list.len()];
    let mut at = 0usize;
    let channel_count = header.channels.list.len();
    for &row_total in &row_totals {
        let row_total = row_total as usize;
        let mut starts = Vec::with_capacity(channel_count);
        for c in &header.channels.list {
            starts.push(at);
            at += row_total * sample_bytes(c);
        }
        for k in 0..row_total {
            for (c, channel) in header.channels.list.iter().enumerate() {
                values[c] = value(&data, starts[c], k, channel.sample_type);
            }
            samples.push(sample(&values, fields, report));
        }
    }
    // Samples the input rules drop (NaN depth, empty) leave their pixel: recount per pixel.
    let mut kept = Vec::with_capacity(samples.len());
    let mut i = 0;
    for y in 0..bh {
        for x in 0..bw {
            let p = (y0 + y) * w + x0 + x;
            let n = blocks.counts[p] as usize;
            let before = kept.len();
            kept.extend(samples[i..i + n].iter().flatten());
            blocks.counts[p] = (kept.len() - before) as u32;
            i += n;
        }
    }
    blocks.samples += kept.len() as u64;
    blocks.chunks.push((x0, y0, bw, bh, kept));
    Ok(())
}

/// Sample `k` of the channel stored from byte `start`.
fn value(data: &[u8], start: usize, k: usize, kind: SampleType) -> f32 {
    match kind {
        SampleType::F16 => f16::from_bits(u16::from_le_bytes([data[start + 2 * k], data[start + 2 * k + 1]])).to_f32(),
        SampleType::F32 => f32::from_le_bytes(word(data, start + 4 * k)),
        SampleType::U32 => u32::from_le_bytes(word(data, start + 4 * k)) as f32,
    }
}

/// One stored sample under the input rules (module docs); `None` where they drop it.
fn sample(values: &[f32], f: &Fields, report: &mut DeepReport) -> Option<DeepSample> {
    let get = |i: Option<usize>| i.map(|i| values[i]);
    let coloured = [get(f.ar), get(f.ag), get(f.ab)];
    let alpha = match get(f.a) {
        Some(a) => a,
        None if coloured.iter().any(Option::is_some) => {
            let present: Vec<f32> = coloured.iter().flatten().copied().collect();
            if present.iter().any(|&a| a != present[0]) || present.len() < 3 {
                report.coloured_alpha += 1;
            }
            present.iter().sum::<f32>() / present.len() as f32
        }
        None => 1.0,
    };
    let rgb = [get(f.r).unwrap_or(0.0), get(f.g).unwrap_or(0.0), get(f.b).unwrap_or(0.0)];
    let z = values[f.z];
    let fragment = report.counts.fragment(rgb, alpha, z)?;
    let z_back = match get(f.z_back) {
        _ if fragment.depth == f32::INFINITY => f32::INFINITY,
        Some(b) if b >= fragment.depth => b,
        Some(_) => {
            report.z_back_repaired += 1;
            fragment.depth
        }
        None => fragment.depth,
    };
    Some(DeepSample { color: fragment.color, alpha: fragment.alpha, z: fragment.depth, z_back })
}
