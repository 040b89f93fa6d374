//! Thin-lens ray tracing through the multi-layer image, one shot: the suites' oracle for the frame
//! API's `dof::frame::RaytraceContext`. It allocates, uploads and reads back per call, and records
//! the context's kernels in its order (`dof::frame::raytrace::record_trace`) over its own buffers.

use dof::backend::{Backend, CommandTime, with_buffers};
pub use dof::frame::raytrace::RaytraceOptions;
use dof::frame::raytrace::{lens_samples, record_trace, trace_params};
use dof::layers::{LayeredImage, RgbImage};
use dof::methods::buffers::{read_rgb, slot_words};
use dof_core::error::{Error, Result};
use dof_shaders::lens::ThinLens;
use dof_shaders::raytrace::raytrace_trace;
use dof_shaders::raytrace::{SLOT_WORDS, STATS_WORDS};

pub struct RaytraceOutput {
    pub image: RgbImage,
    pub times: Vec<CommandTime>,
    /// Rays that hit no stored fragment (left the image, or passed behind every fragment where
    /// they ended) and took the deepest fragment there instead.
    pub missed_rays: u64,
    pub rays: u64,
    /// Levels of the min/max hierarchy.
    pub levels: u32,
    pub buffer_bytes: u64,
}

/// Renders `image` through `lens` by ray tracing the layers on `backend`.
pub fn raytrace(backend: &mut dyn Backend, image: &LayeredImage, lens: &ThinLens, options: &RaytraceOptions) -> Result<RaytraceOutput> {
    dof::lens::check(lens)?;
    options.check()?;
    let (width, height) = (image.width, image.height);
    let pixels = width as u64 * height as u64;
    if pixels == 0 || image.max_layers == 0 {
        return Err(Error::InvalidArgument(format!(
            "ray tracing needs a non-empty image, got {width}x{height} with {} layers",
            image.max_layers
        )));
    }
    let (params, hier_cells) = trace_params(width, height, image.max_layers, options, *lens);
    let levels = params.levels;
    let slots = pixels * image.max_layers as u64;
    let sizes = [
        (SLOT_WORDS as u64 * slots, "raytrace/input"),
        (pixels, "raytrace/counts"),
        (2 * hier_cells, "raytrace/hierarchy"),
        (2 * (options.spp * options.patterns) as u64, "raytrace/samples"),
        (3 * pixels, "raytrace/out"),
        (STATS_WORDS as u64, "raytrace/stats"),
    ];
    let max_words = backend.limits().max_buffer_bytes / 4;
    if let Some(&(words, what)) = sizes.iter().find(|s| s.0 > max_words) {
        return Err(Error::TooLarge { what: format!("{what} (words)"), size: words, limit: max_words });
    }
    let buffer_bytes = 4 * sizes.iter().map(|s| s.0).sum::<u64>();
    let input = slot_words(image);
    let samples = lens_samples(options.spp, options.patterns, options.seed);
    with_buffers(backend, &sizes, |backend, b| {
        let [input_buf, counts, hier, samples_buf, out, stats] = [b[0], b[1], b[2], b[3], b[4], b[5]];
        backend.write_buffer(input_buf, 0, &input)?;
        backend.write_buffer(counts, 0, &image.counts)?;
        backend.write_buffer(samples_buf, 0, &samples)?;
        let trace = raytrace_trace::Bindings { input: input_buf, counts, hier, samples: samples_buf, out, stats };
        record_trace(backend, &params, trace)?;
        let times = backend.submit()?;
        let missed = backend.read_buffer(stats, 0, 1)?[0] as u64;
        Ok(RaytraceOutput {
            image: read_rgb(backend, out, width, height)?,
            times,
            missed_rays: missed,
            rays: pixels * options.spp as u64,
            levels,
            buffer_bytes,
        })
    })
}
