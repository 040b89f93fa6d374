//! What a frame reads and writes, for every context: the caller's buffers or images, how a depth
//! image encodes depth, and the buffers that image inputs and outputs go through on the device.

use crate::backend::{Backend, BackendId, BufferId, ImageFormat, ImageRef, RetireQueue, RunKernel, groups_for, push_words};
use crate::error::{Error, Result};
use crate::extent::Extent;
use dof_shaders::frame_io::{
    DEPTH_F32, DEPTH_LINEAR, DEPTH_REVERSED, DEPTH_STANDARD, DEPTH_UNORM24, FROM_IMAGES, FROM_TEXTURES, FRONT, FrameIoParams, TO_RGBA,
    TO_RGBA16F_IMAGE, TO_RGBA32F_IMAGE, frame_from_images, frame_front, frame_to_rgba,
};
use dof_shaders::lens::ThinLens;
use dof_shaders::radiance::{COUNT_CLAMPED, ClampCountParams, radiance_count_clamped};
/// Words of one layer slot of [`FrameInput::Layers`]: premultiplied red, green, blue, depth,
/// alpha (f32 bits; `dof_shaders::slot`).
pub use dof_shaders::slot::SLOT_WORDS;

/// How a depth image encodes depth.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DepthEncoding {
    /// Planar view depth in scene units (what the methods take).
    Linear,
    /// A depth buffer: 0 at the near plane, 1 at the far plane (`far` may be infinite).
    Standard { near: f32, far: f32 },
    /// A reversed depth buffer: 1 at the near plane, 0 at the far plane (`far` may be infinite;
    /// then 0 is the background).
    Reversed { near: f32, far: f32 },
}

/// The layout of the fragment slots a caller writes, by name: a writer states the one it writes
/// when it makes its [`SlotBuffer`], and a layout the kernels no longer read is removed from this
/// type, so a writer of an older layout stops compiling instead of handing the kernels words they
/// misread.
#[non_exhaustive]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SlotLayout {
    /// [`SLOT_WORDS`] = 5 words a slot, f32 bits: red, green, blue **premultiplied** by alpha,
    /// planar view depth, alpha in [0, 1] (`dof_shaders::slot::Slot::words`).
    PremultipliedRgbDepthAlpha,
}

impl SlotLayout {
    /// The layout the kernels read.
    pub const CURRENT: SlotLayout = SlotLayout::PremultipliedRgbDepthAlpha;

    /// Words of one slot.
    pub fn words(self) -> u32 {
        match self {
            SlotLayout::PremultipliedRgbDepthAlpha => SLOT_WORDS,
        }
    }
}

/// Fragment slots: per pixel `layers` slots in the layout it names (see [`FrameInput::Layers`]),
/// `.0` the backend's buffer. A writer names its layout; a buffer id alone is not slots:
///
/// ```compile_fail,E0061
/// # use dof_core::frame::SlotBuffer;
/// # fn slots(id: dof_core::backend::BufferId) -> SlotBuffer {
/// SlotBuffer(id) // which layout were they written in?
/// # }
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SlotBuffer(pub BufferId, pub SlotLayout);

impl SlotBuffer {
    /// Slots written in the layout the kernels read ([`SlotLayout::CURRENT`]), for writers that
    /// use the library's own (`dof_shaders::slot`, `dof::methods::buffers::slot_words`).
    pub fn current(id: BufferId) -> Self {
        SlotBuffer(id, SlotLayout::CURRENT)
    }
}

/// The caller's buffers a frame reads and writes, each typed by what it holds so that handing one
/// where another belongs does not compile. Each wraps the backend's [`BufferId`] (made by
/// `create_buffer` or `import_buffer`): `CountBuffer(id)` says what `id` holds, `.0` gives it back.
macro_rules! caller_buffer {
    ($($(#[$doc:meta])* $name:ident;)*) => {$(
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub struct $name(pub BufferId);
    )*};
}

caller_buffer! {
    /// Slots used per pixel, one word each.
    CountBuffer;
    /// An RGB image: 3 words (f32 red, green, blue) a pixel, row-major.
    RgbBuffer;
}

/// What a frame reads.
#[derive(Clone, Copy, Debug)]
pub enum FrameInput {
    /// A multi-layer image in the caller's buffers, read only: `fragments` holds per pixel
    /// `layers` slots of [`SLOT_WORDS`] = 5 words (f32 bits: red, green, blue **premultiplied** by
    /// alpha, planar view depth, alpha in [0, 1]; `dof_shaders::slot`), front to back, and `counts`
    /// the slots used per pixel (one word each). A pixel's slots composite front to back over
    /// black; an opaque slot has alpha 1 and its colour as it is. Alpha NaN or outside [0, 1] is
    /// clamped (NaN to 0) and counted in the method's report.
    ///
    /// `footprint_side` 0: the slots stand for whole pixels. 1 to 4: after the slots, `fragments`
    /// holds one word a slot, the slot's footprint, the sub-samples of a `side × side` grid of its
    /// pixel it covers (`dof_shaders::footprint`; bit `j·side + i` for the stratum centred at
    /// `((i + ½)/side, (j + ½)/side)`; 0 for the whole pixel), as an area-integrated layer image or
    /// a multisampled renderer's sample masks give it. Multi-layer and single-layer splatting (with
    /// the circular aperture, on a context created with a `footprint_side` at least this) splat such a slot from its
    /// sub-samples; the other methods read the slots alone.
    Layers { fragments: SlotBuffer, counts: CountBuffer, layers: u32, footprint_side: u32 },
    /// The caller's colour and depth images, one layer: colour RGBA32F, RGBA16F or B10G11R11, depth
    /// a depth attachment as it is (D32, D24 with stencil, X8_D24; read through its depth aspect,
    /// with a `Standard` or `Reversed` encoding) or R32F (any encoding). They are copied into the
    /// context's buffers (needs a context created with `image_io`), the top-left frame-sized part of
    /// images that may be larger, and left in the layouts their [`ImageRef`]s name.
    Images { color: ImageRef, depth: ImageRef, encoding: DepthEncoding },
}

/// Where a frame writes its result.
#[derive(Clone, Copy, Debug)]
pub enum FrameOutput {
    /// 3 words (f32 red, green, blue) a pixel, row-major; written whole.
    Buffer(RgbBuffer),
    /// The caller's RGBA32F or RGBA16F image (alpha 1), its top-left frame-sized part written, left
    /// in its `final_layout` (needs a context created with `image_io`).
    Image(ImageRef),
}

/// One frame: its size (within the context's maximum), the lens, and the caller's resources.
/// Every context records the same description.
#[derive(Clone, Copy, Debug)]
pub struct Frame {
    pub width: u32,
    pub height: u32,
    pub lens: ThinLens,
    pub input: FrameInput,
    pub output: FrameOutput,
}

impl Frame {
    /// A frame of a multi-layer image in buffers, into a buffer. Each buffer is typed by what it
    /// holds, so swapping two does not compile:
    ///
    /// ```
    /// # use dof_core::frame::{CountBuffer, Frame, RgbBuffer, SlotBuffer, SlotLayout};
    /// # fn frame(b: &mut dyn dof_core::Backend, lens: dof_core::ThinLens) -> dof_core::Result<Frame> {
    /// // The slots as this writer writes them: premultiplied colour, depth, alpha.
    /// let slots = SlotBuffer(b.create_buffer(5 * 64, "slots")?, SlotLayout::PremultipliedRgbDepthAlpha);
    /// let counts = CountBuffer(b.create_buffer(64, "counts")?);
    /// let out = RgbBuffer(b.create_buffer(3 * 64, "out")?);
    /// Ok(Frame::layers(8, 8, 1, lens, slots, counts, out))
    /// # }
    /// ```
    ///
    /// ```compile_fail,E0308
    /// # use dof_core::frame::{CountBuffer, Frame, RgbBuffer, SlotBuffer};
    /// # fn frame(lens: dof_core::ThinLens, slots: SlotBuffer, counts: CountBuffer, out: RgbBuffer) -> Frame {
    /// Frame::layers(8, 8, 1, lens, counts, slots, out) // the counts where the slots belong
    /// # }
    /// ```
    pub fn layers(
        width: u32,
        height: u32,
        layers: u32,
        lens: ThinLens,
        fragments: SlotBuffer,
        counts: CountBuffer,
        output: RgbBuffer,
    ) -> Self {
        let input = FrameInput::Layers { fragments, counts, layers, footprint_side: 0 };
        Frame { width, height, lens, input, output: FrameOutput::Buffer(output) }
    }

    /// The frame with its layer input's footprints on a `side × side` grid (0: none; see
    /// [`FrameInput::Layers`]); an image input has none.
    pub fn with_footprints(mut self, side: u32) -> Self {
        if let FrameInput::Layers { ref mut footprint_side, .. } = self.input {
            *footprint_side = side;
        }
        self
    }

    /// The side of the input footprints' sub-sample grid (0: none; see [`FrameInput::Layers`]).
    pub fn footprint_side(&self) -> u32 {
        match self.input {
            FrameInput::Layers { footprint_side, .. } => footprint_side,
            FrameInput::Images { .. } => 0,
        }
    }

    /// Fragment slots per pixel the frame reads.
    pub fn layer_count(&self) -> u32 {
        match self.input {
            FrameInput::Layers { layers, .. } => layers,
            FrameInput::Images { .. } => 1,
        }
    }
}

/// Formats a colour input may have.
const COLOR_FORMATS: [ImageFormat; 3] = [ImageFormat::Rgba32Float, ImageFormat::Rgba16Float, ImageFormat::B10G11R11Ufloat];
/// Formats a depth input may have.
const DEPTH_FORMATS: [ImageFormat; 4] =
    [ImageFormat::D32Float, ImageFormat::D24UnormS8Uint, ImageFormat::X8D24UnormPack32, ImageFormat::R32Float];
/// Formats an image output may have.
const OUTPUT_FORMATS: [ImageFormat; 2] = [ImageFormat::Rgba32Float, ImageFormat::Rgba16Float];

/// Checks what every context checks: a non-empty size within the maximum, a valid lens, buffers
/// large enough, images at least of the frame's size, of a supported format, that the backend can
/// read or write in place or else copy, sane depth planes. (The commands themselves are checked as they are captured, [`super::recording`].)
pub(crate) fn check_frame(backend: &dyn Backend, f: &Frame, owned: &Owned, max: Extent, io: Option<&ImageIo>) -> Result<()> {
    owned.check(backend)?;
    let layers = f.layer_count();
    if f.width == 0 || f.height == 0 || layers == 0 {
        return Err(Error::InvalidArgument(format!("an empty {}x{} frame with {layers} layers", f.width, f.height)));
    }
    if !max.holds(f.width, f.height, layers) {
        return Err(Error::ResizeNeeded { frame: Extent::new(f.width, f.height, layers), context: max });
    }
    crate::lens::check(&f.lens)?;
    let pixels = f.width as u64 * f.height as u64;
    let mut buffers = Vec::new();
    let mut images = Vec::new();
    match f.input {
        FrameInput::Layers { fragments, counts, footprint_side, .. } => {
            if footprint_side > 4 {
                return Err(Error::InvalidArgument(format!("footprints on a {footprint_side}x{footprint_side} grid: the side is 0 to 4")));
            }
            if fragments.1 != SlotLayout::CURRENT {
                return Err(Error::InvalidArgument(format!(
                    "the slots are written in the {:?} layout; the kernels read {:?}",
                    fragments.1,
                    SlotLayout::CURRENT
                )));
            }
            let per_slot = fragments.1.words() as u64 + (footprint_side > 0) as u64;
            buffers.extend([("fragments", fragments.0, per_slot * pixels * layers as u64), ("counts", counts.0, pixels)])
        }
        FrameInput::Images { color, depth, encoding } => {
            let in_place = inputs_in_place(backend, f, color, depth);
            images.extend([
                ("colour", color, COLOR_FORMATS.as_slice(), false, in_place),
                ("depth", depth, DEPTH_FORMATS.as_slice(), false, in_place),
            ]);
            if depth.format.is_depth() && encoding == DepthEncoding::Linear {
                return Err(Error::InvalidArgument(format!(
                    "a {} depth attachment holds depth-buffer values in [0, 1]: give its planes with DepthEncoding::Standard \
                     or Reversed (Linear is for R32F images of view depth)",
                    depth.format
                )));
            }
            if let DepthEncoding::Standard { near, far } | DepthEncoding::Reversed { near, far } = encoding
                && !(near.is_finite() && near > 0.0 && far > near)
            {
                return Err(Error::InvalidArgument(format!(
                    "a depth buffer's planes must satisfy 0 < near < far (far may be infinite), got {near} and {far}"
                )));
            }
        }
    }
    match f.output {
        FrameOutput::Buffer(out) => buffers.push(("output", out.0, 3 * pixels)),
        FrameOutput::Image(out) => images.push(("output", out, OUTPUT_FORMATS.as_slice(), true, output_in_place(backend, f, out))),
    }
    for (what, id, words) in buffers {
        let have = backend.buffer_words(id)?;
        if have < words {
            return Err(Error::InvalidArgument(format!("the {what} buffer holds {have} words, the frame needs {words}")));
        }
    }
    if !images.is_empty() && io.is_none() {
        return Err(Error::InvalidArgument("image inputs and outputs need a context created with `image_io`".into()));
    }
    for (what, image, formats, into_image, in_place) in images {
        if !formats.contains(&image.format) {
            return Err(Error::InvalidArgument(format!(
                "the {what} image is {}; it must be one of {}",
                image.format,
                crate::backend::format_names(formats)
            )));
        }
        if image.extent[0] < f.width || image.extent[1] < f.height {
            return Err(Error::InvalidArgument(format!(
                "the {what} image is {}x{}, smaller than the {}x{} frame",
                image.extent[0], image.extent[1], f.width, f.height
            )));
        }
        if !in_place {
            backend.check_image_copy(&image.top_left(f.width, f.height), into_image)?;
        }
    }
    Ok(())
}

/// Whether the frame reads its input images in place: the backend samples both (else it copies
/// both).
fn inputs_in_place(backend: &dyn Backend, f: &Frame, color: ImageRef, depth: ImageRef) -> bool {
    [color, depth].iter().all(|image| backend.check_image_sample(&image.top_left(f.width, f.height)).is_ok())
}

/// Whether the frame writes its output image in place (else it copies its result into it).
fn output_in_place(backend: &dyn Backend, f: &Frame, image: ImageRef) -> bool {
    backend.check_image_store(&image.top_left(f.width, f.height)).is_ok()
}

/// The pixels of a single-layer context's largest frame (`what` names it in errors), refusing an
/// empty extent and an input whose slots could not fit one buffer of `backend`.
pub(crate) fn context_pixels(backend: &dyn Backend, what: &str, width: u32, height: u32, layers: u32) -> Result<u64> {
    if width == 0 || height == 0 || layers == 0 {
        return Err(Error::InvalidArgument(format!("a {what} context for an empty {width}x{height} extent with {layers} layers")));
    }
    let pixels = width as u64 * height as u64;
    let max_words = backend.limits().max_buffer_bytes / 4;
    let slot_words = SLOT_WORDS as u64 * pixels * layers as u64;
    if slot_words > max_words {
        return Err(Error::TooLarge { what: "input slots (words)".into(), size: slot_words, limit: max_words });
    }
    Ok(pixels)
}

/// Builds a new context's pipelines and submits its buffers' zeroing now, so that its first frame
/// records only its own work; a failure destroys the context. Public for contexts above the core
/// (the mesh peel of the crate `dof`).
pub fn ready<C>(
    backend: &mut dyn Backend,
    ctx: C,
    kernels: &[&'static dof_shaders::KernelDesc],
    draws: &[&'static dof_shaders::DrawDesc],
    destroy: impl FnOnce(C, &mut dyn Backend),
) -> Result<C> {
    match backend.prepare(kernels, draws).and_then(|_| backend.submit().map(drop)) {
        Ok(()) => Ok(ctx),
        Err(e) => {
            destroy(ctx, backend);
            Err(e)
        }
    }
}
/// The buffers a context owns: made one by one, counted, and freed together (also when making a
/// later one fails part way). Dropped without [`Owned::free`] (a context dropped without
/// `destroy`), it hands them to its backend's [`RetireQueue`], which frees them once the device is
/// done with them. Public for contexts above the core (the mesh peel of the crate `dof`).
#[derive(Default)]
pub struct Owned {
    ids: Vec<BufferId>,
    /// The queue of the backend the buffers were made on (set by the first one).
    retire: Option<RetireQueue>,
    bytes: u64,
    /// Each buffer's label and bytes, in the order made (for per-buffer memory tables).
    made: Vec<(String, u64)>,
    /// The backend the buffers were made on (set by the first one).
    owner: Option<BackendId>,
}

impl Owned {
    pub fn make(&mut self, backend: &mut dyn Backend, words: u64, label: &str) -> Result<BufferId> {
        self.check(backend)?;
        let id = backend.create_buffer(words.max(1), label)?;
        self.owner = Some(backend.id());
        self.retire.get_or_insert_with(|| backend.retire_queue());
        self.ids.push(id);
        self.bytes += 4 * words.max(1);
        self.made.push((label.to_string(), 4 * words.max(1)));
        Ok(id)
    }

    /// Refuses a backend other than the one the buffers were made on: its buffers of the same ids
    /// belong to someone else.
    pub fn check(&self, backend: &dyn Backend) -> Result<()> {
        match self.owner {
            Some(owner) if owner != backend.id() => Err(Error::WrongBackend(format!(
                "this context was made on another backend than the {} backend it was handed (contexts are tied to the backend that made them)",
                backend.kind()
            ))),
            _ => Ok(()),
        }
    }

    /// Takes `ids`, made on the same backend by a part of the context (its sort, its scan), to be
    /// freed with the buffers made here; their bytes are the part's to count.
    pub fn adopt(&mut self, ids: &[BufferId]) {
        self.ids.extend_from_slice(ids);
    }

    /// Bytes of every buffer made.
    pub fn bytes(&self) -> u64 {
        self.bytes
    }

    /// Bytes per label, summed over buffers of the same label, in the order first made.
    pub fn table(&self) -> Vec<(String, u64)> {
        let mut rows: Vec<(String, u64)> = Vec::new();
        for (label, bytes) in &self.made {
            match rows.iter_mut().find(|(l, _)| l == label) {
                Some(row) => row.1 += bytes,
                None => rows.push((label.clone(), *bytes)),
            }
        }
        rows
    }

    /// Frees every buffer, on the backend that made them only: handed another backend it frees
    /// nothing there and says so in the log (the buffers go with their own backend).
    pub fn free(mut self, backend: &mut dyn Backend) {
        if let Err(e) = self.check(backend) {
            // Dropped, they go to their own backend's queue.
            log::error!("{e}: nothing freed here; the buffers go back to their own backend");
            return;
        }
        std::mem::take(&mut self.ids).into_iter().for_each(|id| backend.destroy_buffer(id));
    }

    /// `made` when it is `Ok`; otherwise frees everything and passes the error on.
    pub fn or_free<T>(self, backend: &mut dyn Backend, made: Result<T>) -> Result<(T, Owned)> {
        match made {
            Ok(t) => Ok((t, self)),
            Err(e) => {
                self.free(backend);
                Err(e)
            }
        }
    }
}

impl Drop for Owned {
    fn drop(&mut self) {
        if let Some(queue) = &self.retire
            && !self.ids.is_empty()
        {
            queue.retire(std::mem::take(&mut self.ids));
        }
    }
}

/// Buffers image inputs and outputs go through (11 words a pixel): the colour image (later the
/// RGBA result), the depth image, and the one-layer input made from them (later the RGB result).
#[derive(Clone, Copy, Debug)]
pub(crate) struct ImageIo {
    color: BufferId,
    depth: BufferId,
    fragments: BufferId,
    counts: BufferId,
}

impl ImageIo {
    /// Creates the buffers (owned by `owned`) for up to `pixels` pixels.
    pub fn new(backend: &mut dyn Backend, pixels: u64, owned: &mut Owned) -> Result<Self> {
        Ok(ImageIo {
            color: owned.make(backend, 4 * pixels, "frame/io-color")?,
            depth: owned.make(backend, pixels, "frame/io-depth")?,
            fragments: owned.make(backend, SLOT_WORDS as u64 * pixels, "frame/io-fragments")?,
            counts: owned.make(backend, pixels, "frame/io-counts")?,
        })
    }
}

/// The parameters of the frame I/O kernels: `color` and `depth` are the images' formats, where
/// the frame has them.
fn io_params(f: &Frame, color: Option<ImageFormat>, depth: Option<ImageFormat>, layers: u32, encoding: DepthEncoding) -> FrameIoParams {
    let (depth_encoding, near, far) = match encoding {
        DepthEncoding::Linear => (DEPTH_LINEAR, 0.0, 0.0),
        DepthEncoding::Standard { near, far } => (DEPTH_STANDARD, near, far),
        DepthEncoding::Reversed { near, far } => (DEPTH_REVERSED, near, far),
    };
    let color_words = color.map_or(0, |c| c.words_per_pixel() as u32);
    let depth_format = if depth.is_some_and(ImageFormat::is_unorm24) { DEPTH_UNORM24 } else { DEPTH_F32 };
    FrameIoParams { width: f.width, height: f.height, color_words, depth_encoding, near, far, layers, depth_format }
}

/// Records what brings the frame's input into slot buffers: nothing for buffers, the copies and
/// the conversion for images. Returns the fragments and counts buffers the method reads.
pub(crate) fn record_input(backend: &mut dyn Backend, f: &Frame, io: Option<&ImageIo>) -> Result<(BufferId, BufferId)> {
    match (f.input, io) {
        (FrameInput::Layers { fragments, counts, .. }, _) => Ok((fragments.0, counts.0)),
        (FrameInput::Images { color, depth, encoding }, Some(io)) => {
            let (color, depth) = (color.top_left(f.width, f.height), depth.top_left(f.width, f.height));
            let params = io_params(f, Some(color.format), Some(depth.format), 1, encoding);
            let groups = groups_for(&FROM_IMAGES, f.width as u64 * f.height as u64);
            if inputs_in_place(backend, f, color, depth) {
                // Read in place: the kernel samples the caller's images through their views.
                let bindings = [io.fragments, io.counts];
                backend.dispatch_images(&FROM_TEXTURES, groups, &[color, depth], &bindings, &push_words(&params), "frame/input")?;
                return Ok((io.fragments, io.counts));
            }
            // Copied through the context's buffers where the backend cannot sample them (no view,
            // or a format it does not sample; docs/integration.md has the cost).
            backend.copy_image_to_buffer(color, io.color, 0, "frame/input-color")?;
            backend.copy_image_to_buffer(depth, io.depth, 0, "frame/input-depth")?;
            let convert = frame_from_images::Bindings { color: io.color, depth: io.depth, fragments: io.fragments, counts: io.counts };
            backend.run(convert, groups, &params, "frame/input")?;
            Ok((io.fragments, io.counts))
        }
        (FrameInput::Images { .. }, None) => Err(Error::InvalidArgument("image inputs need a context created with `image_io`".into())),
    }
}

/// Records every pixel flattened (`dof_shaders::slot::flatten`: its slots composited front to back
/// over black, at the front slot's depth; black at infinite depth where a pixel has none) as 3
/// colour words and one depth word a pixel: the input of the single-layer gathering methods.
pub(crate) fn record_front(
    backend: &mut dyn Backend,
    f: &Frame,
    slots: (BufferId, BufferId),
    color: BufferId,
    depth: BufferId,
) -> Result<()> {
    let params = io_params(f, None, None, f.layer_count(), DepthEncoding::Linear);
    let groups = groups_for(&FRONT, f.width as u64 * f.height as u64);
    backend.run(frame_front::Bindings { fragments: slots.0, counts: slots.1, color, depth }, groups, &params, "frame/front")
}

/// Records the count of input colours the numerical contract clamps (`dof_shaders::radiance`)
/// among the first `reads` slots of every pixel into `stats[at]` (cleared first): the figure
/// `clamped` of the reports of the methods that clamp where they load colour.
pub(crate) fn record_clamp_count(
    backend: &mut dyn Backend,
    f: &Frame,
    slots: (BufferId, BufferId),
    reads: u32,
    stats: BufferId,
    at: u32,
) -> Result<()> {
    let pixels = f.width * f.height;
    let params = ClampCountParams { pixels, layers: f.layer_count(), stats_at: at, reads };
    backend.fill(stats, at as u64, 1, 0, "frame/clamped")?;
    let bindings = radiance_count_clamped::Bindings { slots: slots.0, counts: slots.1, stats };
    backend.run(bindings, groups_for(&COUNT_CLAMPED, pixels as u64), &params, "frame/clamped")
}

/// The report's words on the input values [`record_clamp_count`] counted.
pub(crate) fn clamped_summary(clamped: u32) -> String {
    if clamped == 0 {
        String::new()
    } else {
        format!("; {clamped} input values clamped (colours negative, subnormal or above 2^100; alphas NaN or outside [0, 1])")
    }
}

/// The buffer the method writes its RGB result into: the caller's, or for an image output the
/// one-layer input's (read only by the stages before).
pub(crate) fn output_buffer(f: &Frame, io: Option<&ImageIo>) -> Result<BufferId> {
    match (f.output, io) {
        (FrameOutput::Buffer(out), _) => Ok(out.0),
        (FrameOutput::Image(_), Some(io)) => Ok(io.fragments),
        (FrameOutput::Image(_), None) => Err(Error::InvalidArgument("image outputs need a context created with `image_io`".into())),
    }
}

/// Records what brings an RGB result into an image output: written in place where the backend
/// writes the image (it has a view), else converted into a buffer and copied.
pub(crate) fn record_output(backend: &mut dyn Backend, f: &Frame, io: Option<&ImageIo>) -> Result<()> {
    if let (FrameOutput::Image(image), Some(io)) = (f.output, io) {
        let image = image.top_left(f.width, f.height);
        let params = io_params(f, Some(image.format), None, 1, DepthEncoding::Linear);
        let groups = groups_for(&TO_RGBA, f.width as u64 * f.height as u64);
        if output_in_place(backend, f, image) {
            // Written in place: the kernel stores into the caller's image through its view.
            let kernel = if image.format == ImageFormat::Rgba16Float { &TO_RGBA16F_IMAGE } else { &TO_RGBA32F_IMAGE };
            return backend.dispatch_images(kernel, groups, &[image], &[io.fragments], &push_words(&params), "frame/output");
        }
        backend.run(frame_to_rgba::Bindings { rgb: io.fragments, rgba: io.color }, groups, &params, "frame/output")?;
        backend.copy_buffer_to_image(io.color, 0, image, "frame/output")?;
    }
    Ok(())
}
