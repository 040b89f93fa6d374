//! The frame API on the CPU backend: context descriptions (extents, layer counts, tile sizes,
//! merging, radius caps, list pools, apertures, bokeh options, image I/O), then a few operations
//! (record and submit a frame, read its report, resize) with arbitrary frame sizes, layer counts,
//! lenses (NaN, ±inf, negative), buffers that may be too small, unknown or shared, their contents
//! (well-formed, or raw words: NaN depths, counts beyond the layers), and images of any format and
//! extent (the CPU backend has none: an error).
//!
//! Every call must return `Ok` or `Err`, never panic; a kernel fault (an out-of-bounds index the
//! CPU backend catches) is a failure too, since on a GPU it would be a stray access. Extents are
//! small (at most 64x64 pixels and 4 layers) or arbitrary; an arbitrary description is only tried
//! where the library must refuse it (a zero size, an edge beyond the splatting limit, input slots
//! beyond the largest buffer, a list pool beyond its limit), and must be refused without
//! allocating it (libFuzzer's malloc limit catches that). Well-formed input through a sane lens
//! must give a finite, non-negative image, and through a pinhole-sized aperture (radius 0 or 1e-7)
//! the input's front composite. Every buffer is freed at the end: nothing leaks on any error path.
#![no_main]

use arbitrary::Arbitrary;
use ash::vk;
use dof::ThinLens;
use dof::aperture::{ApertureShape, star};
use dof::backend::{Backend, BufferId, CpuBackend, ImageFormat, ImageRef};
use dof::dof_shaders::aperture::{Aperture, blades, masked};
use dof::dof_shaders::splat::fragment::MAX_EDGE;
use dof::frame::splat::MAX_LIST_ENTRIES;
use dof::frame::{
    BokehContext, BokehContextDesc, ContextDesc, CountBuffer, DepthEncoding, DofContext, Extent, Frame, FrameInput, FrameOutput,
    GatherContext, GatherContextDesc, METHODS, MethodOptions, RgbBuffer, RingGatherContext, RingGatherContextDesc, RingGatherOptions,
    SlotBuffer, SplatContext, SplatContextDesc, ring_gather,
};
use dof::methods::bokeh::BokehOptions;
use dof::methods::splat::{Merge, SplatOptions};
use dof::{CoreError, Error};
use libfuzzer_sys::fuzz_target;

/// Words of a layer input slot (`dof_shaders::slot`).
const SLOT: u64 = dof::methods::buffers::SLOT_WORDS as u64;

/// Whether inconsistent aperture descriptions are tried (see `ApertureIn::Raw`).
const TRY_RAW_APERTURES: bool = true;

/// The pinhole-sized aperture radius of a sane lens (see `LensIn::Sane`).
const PINHOLE: f32 = 1e-7;
/// How far a method's in-focus frame may be from the front composite, relative: the gathers give
/// the pixel's own sample the weight `w = 1 / (r + 1/2)²` and return `(w·c)·(1/w)`, two roundings
/// (2 ulp) when `w` is not a power of two (a CoC of 1e-7 px; at radius 0 it is 4 and the result
/// exact). Every other method copies the front fragment through bit for bit
/// (`tests/tests/oracles.rs` states it per method).
const IN_FOCUS_TOLERANCE: f32 = 2.4e-7;

/// Largest extent and layer count actually allocated.
const SMALL_EDGE: u32 = 64;
const SMALL_LAYERS: u32 = 4;
/// Largest list pool actually allocated (the default is 2^20 entries).
const SMALL_LIST: u64 = 1 << 20;

#[derive(Arbitrary, Debug, Clone, Copy)]
enum Dim {
    /// 0 to 64.
    Small(u8),
    Any(u32),
}

impl Dim {
    fn get(self) -> u32 {
        match self {
            Dim::Small(v) => v as u32 % (SMALL_EDGE + 1),
            Dim::Any(v) => v,
        }
    }
}

#[derive(Arbitrary, Debug, Clone, Copy)]
enum Layers {
    /// 0 to 4.
    Small(u8),
    Any(u32),
}

impl Layers {
    fn get(self) -> u32 {
        match self {
            Layers::Small(v) => v as u32 % (SMALL_LAYERS + 1),
            Layers::Any(v) => v,
        }
    }
}

#[derive(Arbitrary, Debug)]
enum ApertureIn {
    Circle,
    Blades(u32, f32, f32),
    Star(u32, f32, f32),
    /// A mask of `side²` texels from a seed.
    Masked(u8, u64),
    /// Any kernel description with any mask: inconsistent shapes are possible through the public
    /// fields.
    Raw {
        blades: u32,
        curvature: f32,
        normal: [f32; 2],
        step: [f32; 2],
        inv_inradius: f32,
        area: f32,
        mask_side: u8,
        texels: u16,
    },
}

impl ApertureIn {
    fn shape(&self) -> Option<ApertureShape> {
        match *self {
            ApertureIn::Circle => Some(ApertureShape::circle()),
            ApertureIn::Blades(n, rotation, curvature) => {
                blades(n, rotation, curvature).map(|kernel| ApertureShape { kernel, mask: Vec::new() })
            }
            ApertureIn::Star(n, rotation, inner) => star(n, rotation, inner),
            ApertureIn::Masked(side, seed) => {
                let side = side as u32 % 40;
                let mut rng = Rng(seed);
                let mask: Vec<f32> = (0..side * side).map(|_| (rng.next() % 5) as f32 / 4.0).collect();
                masked(side, &mask).map(|kernel| ApertureShape { kernel, mask })
            }
            ApertureIn::Raw { blades, curvature, normal, step, inv_inradius, area, mask_side, texels } => {
                // The contexts must refuse what the kernels cannot run (finding 6 in
                // fuzz/README.md: 2^32 - 1 blades looped for ever, a mask shorter than its side
                // was read out of bounds).
                let kernel = Aperture { blades, curvature, normal, step, inv_inradius, area, mask: mask_side as u32 };
                let shape = ApertureShape { kernel, mask: vec![1.0; texels as usize % 4096] };
                if !TRY_RAW_APERTURES {
                    return None;
                }
                Some(shape)
            }
        }
    }
}

/// A float: usually a plausible value, sometimes any.
#[derive(Arbitrary, Debug, Clone, Copy)]
enum F {
    Default,
    Small(u8),
    Any(f32),
}

impl F {
    fn get(self, default: f32, scale: f32) -> f32 {
        match self {
            F::Default => default,
            F::Small(v) => v as f32 * scale,
            F::Any(v) => v,
        }
    }
}

#[derive(Arbitrary, Debug, Clone, Copy)]
enum Entries {
    Small(u16),
    Any(u64),
}

#[derive(Arbitrary, Debug)]
enum Method {
    Splat {
        tile: u8,
        any_tile: Option<u32>,
        merge: u8,
        max_radius: Option<F>,
        merge_min_radius: F,
        merge_depth_ratio: F,
        merge_color_tol: F,
        umbra_merge: bool,
        list_entries: Option<Entries>,
        max_list: Option<u32>,
        /// A field the stored corpus holds for a switch the library does not have (each stage in
        /// buffers of its own); kept so that the corpus decodes unchanged.
        _distinct_stage_buffers: bool,
    },
    Gather {
        max_radius: Option<u32>,
    },
    Bokeh {
        lum_threshold: F,
        coc_threshold: F,
        capacity: Option<u32>,
        max_radius: F,
    },
    RingGather {
        rings: u32,
        max_radius: u32,
    },
    /// Any method of the frame API's registry with its default options, so that a method added
    /// there is fuzzed without a change here.
    Registry(u8),
}

#[derive(Arbitrary, Debug)]
struct ContextIn {
    method: Method,
    width: Dim,
    height: Dim,
    layers: Layers,
    aperture: ApertureIn,
    image_io: bool,
}

#[derive(Arbitrary, Debug, Clone, Copy)]
enum LensIn {
    /// Focal length 5 cm, 2000 px a unit: CoC up to about 100 px. `aperture` 0 is a pinhole: radius
    /// 0 where `focus` is even, 1e-7 (every CoC under 1e-5 px) where it is odd.
    Sane {
        aperture: u8,
        focus: u8,
    },
    Raw([f32; 4]),
}

impl LensIn {
    fn get(self) -> ThinLens {
        match self {
            LensIn::Sane { aperture, focus } => ThinLens {
                focal_length: 0.05,
                aperture_radius: if aperture == 0 && focus % 2 == 1 { PINHOLE } else { aperture as f32 * 0.0005 },
                focus_distance: 0.5 + focus as f32 * 0.05,
                pixels_per_unit: 2000.0,
            },
            LensIn::Raw([focal_length, aperture_radius, focus_distance, pixels_per_unit]) => {
                ThinLens { focal_length, aperture_radius, focus_distance, pixels_per_unit }
            }
        }
    }
}

#[derive(Arbitrary, Debug, Clone, Copy)]
struct ImageIn {
    format: u8,
    /// `None`: the frame's size.
    extent: Option<(Dim, Dim)>,
    layouts: u8,
}

impl ImageIn {
    fn get(self, frame: (u32, u32)) -> ImageRef {
        let format = [ImageFormat::Rgba32Float, ImageFormat::Rgba16Float, ImageFormat::R32Float][self.format as usize % 3];
        let layouts = [vk::ImageLayout::UNDEFINED, vk::ImageLayout::GENERAL, vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL];
        let layout = layouts[self.layouts as usize % 3];
        let final_layout = layouts[(self.layouts as usize / 3) % 3];
        // SAFETY: the CPU backend never uses the handle (it has no images and refuses every copy).
        unsafe {
            ImageRef::vulkan(
                vk::Image::null(),
                format,
                self.extent.map_or([frame.0, frame.1], |(w, h)| [w.get(), h.get()]),
                layout,
                vk::PipelineStageFlags::ALL_COMMANDS,
                vk::AccessFlags::MEMORY_WRITE,
                final_layout,
            )
        }
    }
}

#[derive(Arbitrary, Debug, Clone, Copy)]
enum EncodingIn {
    Linear,
    Standard(f32, f32),
    Reversed(f32, f32),
}

#[derive(Arbitrary, Debug, Clone, Copy)]
enum InputIn {
    /// The caller's fragments and counts buffers (0 and 1), or any buffer ids.
    Buffers {
        fragments: u8,
        counts: u8,
    },
    Images {
        color: ImageIn,
        depth: ImageIn,
        encoding: EncodingIn,
    },
}

#[derive(Arbitrary, Debug, Clone, Copy)]
enum OutputIn {
    /// A caller's buffer (2 is the output buffer; 0 and 1 alias the input).
    Buffer(u8),
    Image(ImageIn),
}

#[derive(Arbitrary, Debug, Clone, Copy)]
enum Content {
    /// Counts within the layers, depths positive and sorted (the last sometimes the sky at `+inf`),
    /// colours in [0, 4].
    WellFormed(u64),
    /// Words from the input, as they come.
    Raw,
}

/// A frame's size or layer count: usually within the context's maximum, sometimes anything.
#[derive(Arbitrary, Debug, Clone, Copy)]
enum Within {
    /// 1 to the maximum.
    Max(u8),
    Dim(Dim),
    Layers(Layers),
}

impl Within {
    fn get(self, max: u32) -> u32 {
        match self {
            Within::Max(v) => 1 + v as u32 % max.max(1),
            Within::Dim(d) => d.get(),
            Within::Layers(l) => l.get(),
        }
    }
}

#[derive(Arbitrary, Debug, Clone, Copy)]
struct FrameIn {
    width: Within,
    height: Within,
    layers: Within,
    lens: LensIn,
    input: InputIn,
    output: OutputIn,
    content: Content,
}

#[derive(Arbitrary, Debug, Clone, Copy)]
enum Op {
    Record(FrameIn),
    Resize(Dim, Dim, Layers),
}

/// The caller's buffer sizes, relative to what a frame of the context's maximum needs.
#[derive(Arbitrary, Debug, Clone, Copy)]
enum SizeIn {
    Exact,
    Short(u16),
    Long(u8),
}

#[derive(Arbitrary, Debug)]
struct Input {
    context: ContextIn,
    sizes: [SizeIn; 3],
    ops: Vec<Op>,
    words: Vec<u32>,
}

/// splitmix64.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    fn unit(&mut self) -> f32 {
        (self.next() >> 40) as f32 / (1u64 << 24) as f32
    }
}

/// Whether the library must refuse an extent, and whether it is small enough to allocate.
fn judge(width: u32, height: u32, layers: u32, splat: bool) -> (bool, bool) {
    let slot_bytes = 16 * width as u128 * height as u128 * layers as u128;
    let must_refuse =
        width == 0 || height == 0 || layers == 0 || slot_bytes > 1 << 34 || (splat && (width > MAX_EDGE || height > MAX_EDGE));
    let small = width <= SMALL_EDGE && height <= SMALL_EDGE && layers <= SMALL_LAYERS;
    (must_refuse, small)
}

/// With `DOF_FUZZ_STATS` set, prints how far each input got (for checking what the corpus reaches).
fn stat(what: &str) {
    static ON: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    if *ON.get_or_init(|| std::env::var_os("DOF_FUZZ_STATS").is_some()) {
        eprintln!("stat: {what}");
    }
}

/// `Ok` or a clean `Err`; a kernel fault is a failure.
fn clean<T>(what: &str, r: Result<T, impl Into<Error>>) -> Option<T> {
    match r.map_err(Into::into) {
        Ok(v) => Some(v),
        Err(e @ Error::Core(CoreError::KernelFault { .. })) => panic!("{what}: {e}"),
        Err(_) => None,
    }
}

fn create(b: &mut CpuBackend, c: &ContextIn) -> Option<(Box<dyn DofContext>, (u32, u32, u32))> {
    let (w, h, layers) = (c.width.get(), c.height.get(), c.layers.get());
    let registry = match c.method {
        Method::Registry(i) => Some(&METHODS[i as usize % METHODS.len()]),
        _ => None,
    };
    let splat = matches!(c.method, Method::Splat { .. }) || registry.is_some_and(|m| m.tiles());
    let (mut must_refuse, small) = judge(w, h, layers, splat);
    let context = match &c.method {
        Method::Splat {
            tile,
            any_tile,
            merge,
            max_radius,
            merge_min_radius,
            merge_depth_ratio,
            merge_color_tol,
            umbra_merge,
            list_entries,
            max_list,
            _distinct_stage_buffers: _,
        } => {
            let aperture = c.aperture.shape()?;
            let options = SplatOptions {
                tile: any_tile.unwrap_or([16, 24, 32][*tile as usize % 3]),
                merge: [Merge::None, Merge::X2, Merge::X4][*merge as usize % 3],
                max_radius: max_radius.map(|r| r.get(96.0, 1.0)),
                merge_min_radius: merge_min_radius.get(1.5, 0.25),
                merge_depth_ratio: merge_depth_ratio.get(1.1, 0.05),
                merge_color_tol: merge_color_tol.get(0.25, 0.05),
                umbra_merge: *umbra_merge,
                aperture,
                // The tile byte's upper bits (its lower ones pick the tile), so that the stored corpus
                // decodes unchanged: room for footprints of a 1 to 4 side grid, or none.
                footprint_side: (*tile as u32 >> 2) % 5,
            };
            let list_entries = match list_entries {
                None => None,
                Some(Entries::Small(n)) => Some(*n as u64),
                Some(Entries::Any(n)) => Some(*n),
            };
            if let Some(n) = list_entries {
                if n == 0 || n > MAX_LIST_ENTRIES {
                    must_refuse = true;
                } else if n > SMALL_LIST && !must_refuse {
                    return None;
                }
            }
            if !small && !must_refuse {
                return None;
            }
            let mut desc = SplatContextDesc::new(Extent::new(w, h, layers), options);
            desc.list_entries = list_entries;
            desc.max_list = *max_list;
            desc.image_io = c.image_io;
            SplatContext::new(b, &desc).map(|c| Box::new(c) as Box<dyn DofContext>)
        }
        Method::Gather { max_radius } => {
            if !small && !must_refuse {
                return None;
            }
            let desc = GatherContextDesc {
                max_width: w,
                max_height: h,
                max_layers: layers,
                max_radius: *max_radius,
                image_io: c.image_io,
                frames_in_flight: 1,
            };
            GatherContext::new(b, &desc).map(|c| Box::new(c) as Box<dyn DofContext>)
        }
        Method::Bokeh { lum_threshold, coc_threshold, capacity, max_radius } => {
            if !small && !must_refuse {
                return None;
            }
            let aperture = c.aperture.shape()?;
            let options = BokehOptions {
                lum_threshold: lum_threshold.get(1.0, 0.1),
                coc_threshold: coc_threshold.get(2.0, 0.25),
                capacity: capacity.unwrap_or(4096),
                max_radius: max_radius.get(256.0, 1.0),
                aperture,
            };
            let desc =
                BokehContextDesc { max_width: w, max_height: h, max_layers: layers, options, image_io: c.image_io, frames_in_flight: 1 };
            BokehContext::new(b, &desc).map(|c| Box::new(c) as Box<dyn DofContext>)
        }
        Method::RingGather { rings, max_radius } => {
            if !small && !must_refuse {
                return None;
            }
            let options = RingGatherOptions { rings: *rings, max_radius: *max_radius };
            // Out-of-range options must be refused too.
            must_refuse |= !(1..=ring_gather::MAX_SAMPLE_RINGS).contains(rings) || !(1..=ring_gather::MAX_RADIUS).contains(max_radius);
            let desc = RingGatherContextDesc {
                max_width: w,
                max_height: h,
                max_layers: layers,
                options,
                image_io: c.image_io,
                frames_in_flight: 1,
            };
            RingGatherContext::new(b, &desc).map(|c| Box::new(c) as Box<dyn DofContext>)
        }
        Method::Registry(_) => {
            if !small && !must_refuse {
                return None;
            }
            let method = registry?;
            let desc = ContextDesc { image_io: c.image_io, ..ContextDesc::new(Extent::new(w, h, layers), MethodOptions::default()) };
            (method.create)(b, &desc)
        }
    };
    let context = clean("creating the context", context);
    stat(&format!(
        "context {}: {}",
        if context.is_some() { "created" } else { "refused" },
        match c.method {
            Method::Splat { .. } => "splat",
            Method::Gather { .. } => "gather",
            Method::Bokeh { .. } => "bokeh",
            Method::RingGather { .. } => "ring-gather",
            Method::Registry(_) => registry.map_or("registry", |m| m.name),
        }
    ));
    let context = context?;
    assert!(!must_refuse, "a {w}x{h} context with {layers} layers was accepted: it must be refused");
    Some((context, (w, h, layers)))
}

/// Writes the frame's input into the caller's buffers (as much as fits). Returns the input's front
/// composite (the front fragment's colour, black where a pixel has none) when well-formed input
/// was written whole.
fn fill(b: &mut CpuBackend, bufs: &[BufferId; 3], f: &FrameIn, size: (u32, u32, u32), words: &[u32]) -> Option<Vec<[f32; 3]>> {
    let (w, h, layers) = (size.0 as u64, size.1 as u64, size.2 as u64);
    let cap = |id: BufferId, b: &CpuBackend| b.buffer_words(id).unwrap_or(0);
    let (frag_cap, count_cap) = (cap(bufs[0], b), cap(bufs[1], b));
    match f.content {
        Content::WellFormed(seed) => {
            let mut rng = Rng(seed);
            let pixels = (w * h).min(count_cap);
            let mut counts = Vec::with_capacity(pixels as usize);
            let mut slots = vec![0u32; (SLOT * pixels * layers).min(frag_cap) as usize];
            let whole = pixels == w * h && slots.len() as u64 == SLOT * pixels * layers;
            let mut front = vec![[0.0f32; 3]; pixels as usize];
            for p in 0..pixels {
                let n = rng.next() % (layers.min(SMALL_LAYERS as u64) + 1);
                counts.push(n as u32);
                let mut depth = 0.2 + 2.0 * rng.unit();
                for k in 0..n {
                    let sky = k + 1 == n && rng.next() % 4 == 0;
                    let d = if sky { f32::INFINITY } else { depth };
                    depth += 0.01 + 3.0 * rng.unit();
                    let base = (SLOT * (p * layers + k)) as usize;
                    if base + SLOT as usize <= slots.len() {
                        let rgb = [4.0 * rng.unit(), rng.unit(), rng.unit()];
                        if k == 0 {
                            front[p as usize] = rgb;
                        }
                        slots[base..base + SLOT as usize].copy_from_slice(&dof::dof_shaders::slot::Slot::opaque(rgb, d).words());
                    }
                }
            }
            // Footprints after the slots: any mask, bits beyond the grid too.
            if footprint_side(f) > 0 {
                let room = (frag_cap as usize).saturating_sub(slots.len()).min((pixels * layers) as usize);
                slots.extend((0..room).map(|_| rng.next() as u32));
            }
            let written = b.write_buffer(bufs[0], 0, &slots).is_ok() && b.write_buffer(bufs[1], 0, &counts).is_ok();
            (whole && written).then_some(front)
        }
        Content::Raw => {
            if words.is_empty() {
                return None;
            }
            let cycle = |n: u64| -> Vec<u32> { words.iter().copied().cycle().take(n as usize).collect() };
            let _ = b.write_buffer(bufs[0], 0, &cycle(frag_cap.min(SLOT * SMALL_EDGE as u64 * SMALL_EDGE as u64 * SMALL_LAYERS as u64)));
            let counts: Vec<u32> =
                cycle(count_cap.min(SMALL_EDGE as u64 * SMALL_EDGE as u64)).into_iter().map(|c| c.rotate_left(16)).collect();
            let _ = b.write_buffer(bufs[1], 0, &counts);
            None
        }
    }
}

/// The side of the footprints a frame's input carries after its slots: from a well-formed frame's
/// seed (0 to 5, 5 to be refused; `fill` writes the masks), none for raw words.
fn footprint_side(f: &FrameIn) -> u32 {
    match f.content {
        Content::WellFormed(seed) => ((seed >> 58) % 6) as u32,
        Content::Raw => 0,
    }
}

fn buffer(id: u8, bufs: &[BufferId; 3]) -> BufferId {
    bufs.get(id as usize).copied().unwrap_or(BufferId(id as u32 * 1000))
}

/// Records one frame of `f` through the context, runs it and checks what must hold: a clean `Ok`
/// or `Err`, and for well-formed input through a sane lens into the caller's buffers, finite and
/// non-negative output and, in focus, the front composite.
fn record(b: &mut CpuBackend, ctx: &mut dyn DofContext, bufs: &[BufferId; 3], f: &FrameIn, max: (u32, u32, u32), words: &[u32]) {
    let f = *f;
    let size = (f.width.get(max.0), f.height.get(max.1), f.layers.get(max.2));
    let front = fill(b, bufs, &f, size, words);
    let frame = Frame {
        width: size.0,
        height: size.1,
        lens: f.lens.get(),
        input: match f.input {
            InputIn::Buffers { fragments, counts } => FrameInput::Layers {
                fragments: SlotBuffer::current(buffer(fragments, bufs)),
                counts: CountBuffer(buffer(counts, bufs)),
                layers: size.2,
                footprint_side: footprint_side(&f),
            },
            InputIn::Images { color, depth, encoding } => FrameInput::Images {
                color: color.get((size.0, size.1)),
                depth: depth.get((size.0, size.1)),
                encoding: match encoding {
                    EncodingIn::Linear => DepthEncoding::Linear,
                    EncodingIn::Standard(near, far) => DepthEncoding::Standard { near, far },
                    EncodingIn::Reversed(near, far) => DepthEncoding::Reversed { near, far },
                },
            },
        },
        output: match f.output {
            OutputIn::Buffer(id) => FrameOutput::Buffer(RgbBuffer(buffer(id, bufs))),
            OutputIn::Image(image) => FrameOutput::Image(image.get((size.0, size.1))),
        },
    };
    let recorded = ctx.record(b, &frame);
    if let Err(e) = &recorded {
        stat(&format!("record refused: {}", e.to_string().chars().take(60).collect::<String>()));
    }
    if clean("recording", recorded).is_none() {
        // A refused frame records nothing; drop whatever an error left half recorded.
        let _ = clean("submitting after an error", b.submit());
        return;
    }
    if clean("running the frame", b.submit()).is_none() {
        stat("frame failed on submit");
        return;
    }
    stat(&format!("frame ran: {}", ctx.method()));
    clean("the report", ctx.report(b));
    let sane = matches!(
        (f.content, f.lens, f.input, f.output),
        (Content::WellFormed(_), LensIn::Sane { .. }, InputIn::Buffers { fragments: 0, counts: 1 }, OutputIn::Buffer(2))
    );
    if sane {
        stat("sane frame checked");
        let words = 3 * frame.width as u64 * frame.height as u64;
        let out = b.read_buffer(bufs[2], 0, words).expect("the output of a recorded frame");
        if let Some(bad) = out.iter().position(|w| !(f32::from_bits(*w).is_finite() && f32::from_bits(*w) >= 0.0)) {
            panic!(
                "{}: well-formed input through a sane lens gave an output that is not finite and non-negative at word {bad}: {}",
                ctx.method(),
                f32::from_bits(out[bad])
            );
        }
        // In focus: the front composite.
        let lens = frame.lens;
        if let (Some(front), true) = (front, lens.aperture_radius <= PINHOLE) {
            stat("pinhole frame checked");
            let tolerance = if lens.aperture_radius == 0.0 { 0.0 } else { IN_FOCUS_TOLERANCE };
            for (i, (&got, want)) in out.iter().zip(front.iter().flatten()).enumerate() {
                let got = f32::from_bits(got);
                assert!(
                    got.to_bits() == want.to_bits() || (got - want).abs() <= tolerance * want.abs(),
                    "{}: in focus (aperture radius {}), word {i} is {got}, the front composite {want}",
                    ctx.method(),
                    lens.aperture_radius
                );
            }
        }
    }
}

fn run(input: &Input) {
    let mut b = CpuBackend::new();
    let Some((mut ctx, mut max)) = create(&mut b, &input.context) else {
        assert_eq!(b.counters().device_bytes, 0, "a refused context left buffers behind");
        return;
    };
    // The caller's buffers: fragments, counts and output for the context's maximum, or a little
    // less or more.
    let pixels = max.0 as u64 * max.1 as u64;
    // The fragments' buffer with room for a footprint a slot after the slots.
    let needs = [(SLOT + 1) * pixels * max.2 as u64, pixels, 3 * pixels];
    let mut bufs = [BufferId(0); 3];
    for (i, (&need, size)) in needs.iter().zip(input.sizes).enumerate() {
        let words = match size {
            SizeIn::Exact => need,
            SizeIn::Short(d) => need.saturating_sub(d as u64 % (need + 1)),
            SizeIn::Long(d) => need + d as u64,
        };
        bufs[i] = b.create_buffer(words, "caller").expect("a small caller buffer");
    }
    // Every context made runs one well-formed frame of its largest size through a sane lens into
    // the caller's buffers first, so that the oracles see every input that gets this far (the
    // corpus seldom decodes to such a frame by chance). A pinhole one time in three; the seed is the
    // input's first word, else the extent.
    let seed = input.words.first().copied().unwrap_or(max.0 ^ (max.1 << 8) ^ (max.2 << 16));
    let canonical = FrameIn {
        width: Within::Max((max.0 - 1).min(255) as u8),
        height: Within::Max((max.1 - 1).min(255) as u8),
        layers: Within::Max((max.2 - 1).min(255) as u8),
        lens: LensIn::Sane { aperture: if seed % 3 == 0 { 0 } else { (seed >> 2) as u8 % 40 }, focus: (seed >> 8) as u8 },
        input: InputIn::Buffers { fragments: 0, counts: 1 },
        output: OutputIn::Buffer(2),
        content: Content::WellFormed(seed as u64),
    };
    if max.0 <= 256 && max.1 <= 256 && max.2 <= 256 {
        record(&mut b, ctx.as_mut(), &bufs, &canonical, max, &input.words);
    }
    for op in input.ops.iter().take(4) {
        match *op {
            Op::Record(f) => record(&mut b, ctx.as_mut(), &bufs, &f, max, &input.words),
            Op::Resize(w, h, l) => {
                let (w, h, l) = (w.get(), h.get(), l.get());
                let splat = dof::frame::registry::method(ctx.method()).is_ok_and(|m| m.tiles());
                let (must_refuse, small) = judge(w, h, l, splat);
                if !small && !must_refuse {
                    continue;
                }
                if clean("resizing", ctx.resize(&mut b, Extent::new(w, h, l))).is_some() {
                    assert!(!must_refuse, "a resize to {w}x{h} with {l} layers was accepted: it must be refused");
                    max = (w, h, l);
                }
            }
        }
    }
    ctx.destroy(&mut b);
    bufs.iter().for_each(|&id| b.destroy_buffer(id));
    assert_eq!(b.counters().device_bytes, 0, "buffers leaked");
}

fuzz_target!(|input: Input| run(&input));
