//! The CPU backend: the kernel bodies of `dof-shaders` as plain Rust. Each dispatch runs its workgroups
//! in parallel on rayon's pool; inside a workgroup the invocations run one after the other between
//! barriers (see `dof_shaders::exec`). Buffers are `[AtomicU32]`, so parallel workgroups never alias
//! mutable memory.

use super::{
    Backend, BackendCounters, BackendId, BackendKind, BufferId, CommandTime, ImageFormat, ImageRef, Limits, RetireQueue, SPAN,
    check_dispatch, check_images,
};
use crate::error::{Error, Result};
use dof_shaders::KernelDesc;
use dof_shaders::exec::CpuDispatch;
use rayon::prelude::*;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::atomic::{AtomicU32, AtomicU64, Ordering::Relaxed};
use std::time::Instant;

/// Workgroup memory the CPU backend pretends to have. It matches lavapipe's 32 KiB by default so both
/// backends take the same sort paths; tests lower it to exercise the global-memory path.
pub const DEFAULT_SHARED_BYTES: u32 = 32 * 1024;

/// The subgroups the CPU backend runs the kernels' subgroup variants in: as wide as it emulates, so
/// a kernel's workgroup is one subgroup and a workgroup scan or reduction one serial pass, the
/// CPU's fastest (the path without subgroups is as fast; GPU widths, such as NVIDIA's 32, run
/// about 5% slower a multi-layer frame). `CpuBackend::set_subgroup_size` sets a GPU's width.
pub const DEFAULT_SUBGROUP_SIZE: u32 = dof_shaders::exec::CpuGroup::MAX_SUBGROUP;

pub struct CpuBackend {
    id: BackendId,
    limits: Limits,
    buffers: Vec<Option<Box<[AtomicU32]>>>,
    times: Vec<CommandTime>,
    /// Open spans (label, start), innermost last; closed spans of the recording, in opening order
    /// (the slot is filled when the span closes); and those of the last submissions.
    open_spans: Vec<(String, Instant, usize)>,
    spans: Vec<CommandTime>,
    submitted_spans: Vec<CommandTime>,
    counters: BackendCounters,
    budget: Option<u64>,
    /// The stand-ins for a renderer's images ([`Backend::create_image`]), by handle − 1.
    images: Vec<Option<CpuImage>>,
    /// Buffers given back by contexts dropped without `destroy`.
    retire: RetireQueue,
}

/// An image stand-in: its format, full extent and texels, packed as its copies pack them (for a
/// D24 format the word holds the stencil, or junk, in its high 8 bits, as Vulkan's copy through the
/// depth aspect may).
struct CpuImage {
    format: ImageFormat,
    extent: [u32; 2],
    texels: Box<[AtomicU32]>,
}

impl Default for CpuBackend {
    fn default() -> Self {
        Self::new()
    }
}

impl CpuBackend {
    pub fn new() -> Self {
        Self::with_shared_bytes(DEFAULT_SHARED_BYTES)
    }

    /// A CPU backend whose reported workgroup memory is `shared_bytes`.
    pub fn with_shared_bytes(shared_bytes: u32) -> Self {
        CpuBackend {
            limits: Limits {
                max_shared_bytes: shared_bytes,
                max_workgroup_invocations: 1024,
                max_workgroup_count: [65535; 3],
                subgroup_size: Some(DEFAULT_SUBGROUP_SIZE),
                subgroup_kernels: true,
                max_buffer_bytes: 1 << 34,
                serial_invocations: true,
            },
            buffers: Vec::new(),
            times: Vec::new(),
            open_spans: Vec::new(),
            spans: Vec::new(),
            submitted_spans: Vec::new(),
            counters: BackendCounters::default(),
            id: BackendId::fresh(),
            budget: None,
            images: Vec::new(),
            retire: RetireQueue::default(),
        }
    }

    /// Runs the kernels' subgroup variants in subgroups of `size` (a power of two from 2 to
    /// [`dof_shaders::exec::CpuGroup::MAX_SUBGROUP`]; a workgroup narrower than that is one
    /// subgroup), or, with `None`, runs the variants without subgroups, as a device without
    /// subgroup arithmetic does. The results are the same bits either way.
    pub fn set_subgroup_size(&mut self, size: Option<u32>) -> Result<()> {
        if let Some(s) = size
            && !(s.is_power_of_two() && (2..=dof_shaders::exec::CpuGroup::MAX_SUBGROUP).contains(&s))
        {
            return Err(Error::InvalidArgument(format!(
                "a subgroup size of {s}: the CPU backend emulates powers of two from 2 to {}",
                dof_shaders::exec::CpuGroup::MAX_SUBGROUP
            )));
        }
        self.limits.subgroup_size = size;
        self.limits.subgroup_kernels = size.is_some();
        Ok(())
    }

    /// Every texel of a stand-in image.
    pub fn read_image(&self, image: &ImageRef) -> Result<Vec<u32>> {
        Ok(self.image(image)?.texels.iter().map(|t| t.load(Relaxed)).collect())
    }

    fn image(&self, image: &ImageRef) -> Result<&CpuImage> {
        let found = (image.handle as usize).checked_sub(1).and_then(|i| self.images.get(i)).and_then(Option::as_ref);
        match found {
            Some(img) if img.format == image.format => Ok(img),
            Some(img) => Err(Error::InvalidArgument(format!("image {} is {}, described as {}", image.handle, img.format, image.format))),
            None => {
                Err(Error::InvalidArgument(format!("unknown image {} (the CPU backend's images come from create_image)", image.handle)))
            }
        }
    }

    fn image_mut(&mut self, image: &ImageRef) -> Result<&mut CpuImage> {
        self.image(image)?;
        self.images[image.handle as usize - 1].as_mut().ok_or_else(|| Error::InvalidArgument("unknown image".into()))
    }

    /// Copies the top-left `image.extent` between a stand-in image and `buffer[offset..]`.
    fn copy_image(&mut self, image: ImageRef, buffer: BufferId, offset_words: u64, into_image: bool, label: &str) -> Result<()> {
        let what = if into_image { "copy_buffer_to_image" } else { "copy_image_to_buffer" };
        self.check_image_copy(&image, into_image)?;
        let start = Instant::now();
        let per_pixel = image.format.words_per_pixel() as usize;
        let [w, h] = image.extent;
        self.range(buffer, offset_words, image.words()).map_err(|e| Error::InvalidArgument(format!("{what} `{label}`: {e}")))?;
        let img = self.image(&image)?;
        let range = self.range(buffer, offset_words, image.words())?;
        let row = img.extent[0] as usize * per_pixel;
        let span = w as usize * per_pixel;
        for y in 0..h as usize {
            let texels = &img.texels[y * row..y * row + span];
            let words = &range[y * span..(y + 1) * span];
            let (from, to) = if into_image { (words, texels) } else { (texels, words) };
            from.iter().zip(to).for_each(|(f, t)| t.store(f.load(Relaxed), Relaxed));
        }
        self.counters.commands += 1;
        self.times.push(CommandTime { label: label.to_string(), kernel: what, ms: start.elapsed().as_secs_f64() * 1e3 });
        Ok(())
    }

    fn buffer(&self, id: BufferId) -> Result<&[AtomicU32]> {
        self.buffers.get(id.0 as usize).and_then(|b| b.as_deref()).ok_or_else(|| Error::InvalidArgument(format!("unknown buffer {}", id.0)))
    }

    fn range(&self, id: BufferId, offset: u64, words: u64) -> Result<&[AtomicU32]> {
        let buffer = self.buffer(id)?;
        let end = offset.checked_add(words).filter(|&end| end <= buffer.len() as u64).ok_or_else(|| {
            Error::InvalidArgument(format!("range {offset}..{offset}+{words} outside buffer {} of {} words", id.0, buffer.len()))
        })?;
        Ok(&buffer[offset as usize..end as usize])
    }

    /// Runs `kernel` bound to `buffers` and `images` (each binding as the kernel declares it: a
    /// stand-in image's texels stand in its binding, with their layout, read-only unless the
    /// kernel writes it).
    fn run(
        &mut self,
        kernel: &'static KernelDesc,
        groups: [u32; 3],
        buffers: &[BufferId],
        images: &[ImageRef],
        push: &[u32],
        label: &str,
    ) -> Result<()> {
        let start = Instant::now();
        let (mut buffers, mut images) = (buffers.iter(), images.iter());
        let mut bound: Vec<&[AtomicU32]> = Vec::with_capacity(kernel.bindings as usize);
        let mut image_layouts = Vec::new();
        for binding in 0..kernel.bindings {
            if kernel.images & (1 << binding) == 0 {
                let id = buffers.next().ok_or_else(|| Error::InvalidArgument(format!("kernel {}: a buffer missing", kernel.entry)))?;
                bound.push(self.buffer(*id)?);
                continue;
            }
            let image = images.next().ok_or_else(|| Error::InvalidArgument(format!("kernel {}: an image missing", kernel.entry)))?;
            let img = self.image(image)?;
            image_layouts.resize(binding as usize + 1, [0, 0]);
            image_layouts[binding as usize] = [img.extent[0], img.format.texels()];
            bound.push(&img.texels);
        }
        let total = groups[0] as u64 * groups[1] as u64 * groups[2] as u64;
        let subgroup_size = self.limits.subgroup_size.filter(|_| kernel.subgroup_entry.is_some());
        let barriers = AtomicU64::new(0);
        let result = catch_unwind(AssertUnwindSafe(|| {
            (0..total).into_par_iter().for_each(|flat| {
                let x = (flat % groups[0] as u64) as u32;
                let y = ((flat / groups[0] as u64) % groups[1] as u64) as u32;
                let z = (flat / (groups[0] as u64 * groups[1] as u64)) as u32;
                (kernel.cpu)(&CpuDispatch {
                    workgroup_id: [x, y, z],
                    num_workgroups: groups,
                    buffers: &bound,
                    push,
                    read_only: kernel.read_only,
                    image_layouts: &image_layouts,
                    subgroup_size,
                    barriers: &barriers,
                });
            })
        }));
        if let Err(panic) = result {
            let message =
                panic.downcast_ref::<String>().cloned().or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string())).unwrap_or_default();
            return Err(Error::KernelFault { kernel: kernel.entry, message });
        }
        self.counters.commands += 1;
        self.counters.dispatches += 1;
        self.counters.workgroup_barriers += barriers.into_inner();
        self.times.push(CommandTime { label: label.to_string(), kernel: kernel.entry, ms: start.elapsed().as_secs_f64() * 1e3 });
        Ok(())
    }
}

impl Backend for CpuBackend {
    fn id(&self) -> BackendId {
        self.id
    }
    fn kind(&self) -> BackendKind {
        BackendKind::Cpu
    }

    fn device_name(&self) -> String {
        format!("CPU ({} threads)", rayon::current_num_threads())
    }

    fn driver(&self) -> String {
        format!("dof {} CPU backend (kernels as Rust, rayon over workgroups)", env!("CARGO_PKG_VERSION"))
    }

    fn limits(&self) -> &Limits {
        &self.limits
    }

    fn set_memory_budget(&mut self, budget: Option<u64>) {
        self.budget = budget;
    }

    fn reset_peak_device_bytes(&mut self) {
        self.counters.reset_peak();
    }

    fn retire_queue(&self) -> RetireQueue {
        self.retire.clone()
    }

    fn release_finished(&mut self) -> Result<u64> {
        // Every command has run by the time it returns: nothing to wait for.
        let before = self.counters.device_bytes;
        self.retire.take().into_iter().for_each(|id| self.destroy_buffer(id));
        Ok(before - self.counters.device_bytes)
    }

    fn create_buffer(&mut self, words: u64, label: &str) -> Result<BufferId> {
        self.release_finished()?;
        let words = words.max(1);
        if words * 4 > self.limits.max_buffer_bytes {
            return Err(Error::TooLarge { what: "buffer on the CPU backend".into(), size: words * 4, limit: self.limits.max_buffer_bytes });
        }
        self.counters.check_budget(self.budget, words * 4, label)?;
        let buffer = zeroed_words(words).ok_or_else(|| Error::HostMemory { what: format!("buffer `{label}`"), bytes: words * 4 })?;
        let slot = self.buffers.iter().position(Option::is_none).unwrap_or(self.buffers.len());
        if slot == self.buffers.len() {
            self.buffers.push(None);
        }
        self.buffers[slot] = Some(buffer);
        self.counters.add_buffer(words * 4);
        Ok(BufferId(slot as u32))
    }

    fn destroy_buffer(&mut self, buffer: BufferId) {
        if let Some(slot) = self.buffers.get_mut(buffer.0 as usize)
            && let Some(b) = slot.take()
        {
            self.counters.remove_buffer(b.len() as u64 * 4);
        }
    }

    fn buffer_words(&self, buffer: BufferId) -> Result<u64> {
        Ok(self.buffer(buffer)?.len() as u64)
    }

    fn write_buffer(&mut self, buffer: BufferId, offset_words: u64, data: &[u32]) -> Result<()> {
        let range = self.range(buffer, offset_words, data.len() as u64)?;
        for (dst, &v) in range.iter().zip(data) {
            dst.store(v, Relaxed);
        }
        self.counters.uploads += 1;
        Ok(())
    }

    fn read_buffer(&mut self, buffer: BufferId, offset_words: u64, words: u64) -> Result<Vec<u32>> {
        let words = self.range(buffer, offset_words, words)?.iter().map(|w| w.load(Relaxed)).collect();
        self.counters.readbacks += 1;
        Ok(words)
    }

    fn fill(&mut self, buffer: BufferId, offset_words: u64, words: u64, value: u32, label: &str) -> Result<()> {
        let start = Instant::now();
        self.range(buffer, offset_words, words)?.par_iter().for_each(|w| w.store(value, Relaxed));
        self.counters.commands += 1;
        self.times.push(CommandTime { label: label.to_string(), kernel: "fill", ms: start.elapsed().as_secs_f64() * 1e3 });
        Ok(())
    }

    fn dispatch(&mut self, kernel: &'static KernelDesc, groups: [u32; 3], buffers: &[BufferId], push: &[u32], label: &str) -> Result<()> {
        check_dispatch(&self.limits, kernel, Some(groups), buffers.len(), 0, push.len())?;
        self.run(kernel, groups, buffers, &[], push, label)?;
        if groups.contains(&0) {
            self.counters.empty_dispatches += 1;
        }
        Ok(())
    }

    fn dispatch_indirect(
        &mut self,
        kernel: &'static KernelDesc,
        args: BufferId,
        args_offset_words: u64,
        buffers: &[BufferId],
        push: &[u32],
        label: &str,
    ) -> Result<()> {
        // Read in place: the device reads its arguments itself, so this is no host readback.
        let a = self.range(args, args_offset_words, 3)?;
        let groups = [a[0].load(Relaxed), a[1].load(Relaxed), a[2].load(Relaxed)];
        check_dispatch(&self.limits, kernel, Some(groups), buffers.len(), 0, push.len())?;
        self.run(kernel, groups, buffers, &[], push, label)?;
        if groups.contains(&0) {
            self.counters.empty_dispatches += 1;
        }
        Ok(())
    }

    fn dispatch_images(
        &mut self,
        kernel: &'static KernelDesc,
        groups: [u32; 3],
        images: &[ImageRef],
        buffers: &[BufferId],
        push: &[u32],
        label: &str,
    ) -> Result<()> {
        check_dispatch(&self.limits, kernel, Some(groups), buffers.len(), images.len(), push.len())?;
        check_images(self, kernel, images)?;
        self.run(kernel, groups, buffers, images, push, label)?;
        if groups.contains(&0) {
            self.counters.empty_dispatches += 1;
        }
        Ok(())
    }

    /// Its stand-ins are sampled where they are: every one of them can be.
    fn check_image_sample(&self, image: &ImageRef) -> Result<()> {
        image.check_sample("dispatch_images")?;
        self.check_image_copy(image, false)
    }

    /// Its RGBA32F and RGBA16F stand-ins are written where they are.
    fn check_image_store(&self, image: &ImageRef) -> Result<()> {
        image.check_store("dispatch_images")?;
        self.check_image_copy(image, true)
    }

    fn copy_image_to_buffer(&mut self, image: ImageRef, buffer: BufferId, offset_words: u64, label: &str) -> Result<()> {
        self.copy_image(image, buffer, offset_words, false, label)
    }

    fn copy_buffer_to_image(&mut self, buffer: BufferId, offset_words: u64, image: ImageRef, label: &str) -> Result<()> {
        self.copy_image(image, buffer, offset_words, true, label)
    }

    /// Its [`ImageRef`] is in GENERAL (the CPU backend ignores layouts and stages); it holds no
    /// device bytes of the backend's.
    fn create_image(&mut self, format: ImageFormat, extent: [u32; 2]) -> Result<ImageRef> {
        if extent[0] == 0 || extent[1] == 0 {
            return Err(Error::InvalidArgument(format!("an empty {}x{} image", extent[0], extent[1])));
        }
        let words = format.words_per_pixel() * extent[0] as u64 * extent[1] as u64;
        let texels = zeroed_words(words).ok_or_else(|| Error::HostMemory { what: "a stand-in image".into(), bytes: words * 4 })?;
        let slot = self.images.iter().position(Option::is_none).unwrap_or(self.images.len());
        if slot == self.images.len() {
            self.images.push(None);
        }
        self.images[slot] = Some(CpuImage { format, extent, texels });
        // Kernels sample it in place: its view is itself.
        Ok(ImageRef::in_table(slot as u64 + 1, slot as u64 + 1, format, extent))
    }

    fn write_image(&mut self, image: &ImageRef, texels: &[u32]) -> Result<()> {
        let img = self.image_mut(image)?;
        if texels.len() != img.texels.len() {
            return Err(Error::InvalidArgument(format!("the image holds {} words, {} given", img.texels.len(), texels.len())));
        }
        img.texels.iter().zip(texels).for_each(|(t, &v)| t.store(v, Relaxed));
        Ok(())
    }

    fn destroy_image(&mut self, image: &ImageRef) {
        if self.image(image).is_ok() {
            self.images[image.handle as usize - 1] = None;
        }
    }

    fn check_image_copy(&self, image: &ImageRef, into_image: bool) -> Result<()> {
        let what = if into_image { "copy_buffer_to_image" } else { "copy_image_to_buffer" };
        image.check_copy(into_image, what)?;
        let have = self.image(image)?.extent;
        if image.extent[0] > have[0] || image.extent[1] > have[1] {
            return Err(Error::InvalidArgument(format!(
                "{what}: the image is {}x{}, described as {}x{}",
                have[0], have[1], image.extent[0], image.extent[1]
            )));
        }
        Ok(())
    }

    fn submit(&mut self) -> Result<Vec<CommandTime>> {
        if let Some((label, ..)) = self.open_spans.last() {
            return Err(Error::InvalidArgument(format!("submit with the span `{label}` still open (end_span first)")));
        }
        self.counters.submissions += 1;
        self.submitted_spans.append(&mut self.spans);
        self.release_finished()?;
        Ok(std::mem::take(&mut self.times))
    }

    // The commands run as they are recorded, so a span is the wall time from its opening to its
    // closing: its commands' times and the recording's own work between them.
    fn begin_span(&mut self, label: &str) -> Result<()> {
        self.spans.push(CommandTime { label: label.to_string(), kernel: SPAN, ms: f64::NAN });
        self.open_spans.push((label.to_string(), Instant::now(), self.spans.len() - 1));
        Ok(())
    }

    fn end_span(&mut self) -> Result<()> {
        let (_, start, slot) = self.open_spans.pop().ok_or_else(|| Error::InvalidArgument("end_span without an open span".into()))?;
        self.spans[slot].ms = start.elapsed().as_secs_f64() * 1e3;
        Ok(())
    }

    fn take_span_times(&mut self) -> Vec<CommandTime> {
        std::mem::take(&mut self.submitted_spans)
    }

    fn counters(&self) -> BackendCounters {
        self.counters
    }
}

/// A buffer of `words` zeroed words, or `None` where it is larger than all the machine's memory or
/// the allocator refuses it (an error for the caller, not an abort). Zeroed by the allocator, so
/// pages never written cost nothing.
fn zeroed_words(words: u64) -> Option<Box<[AtomicU32]>> {
    if crate::host_memory::installed().is_some_and(|bytes| words.saturating_mul(4) > bytes) {
        return None;
    }
    let n = usize::try_from(words).ok()?;
    let layout = std::alloc::Layout::array::<AtomicU32>(n).ok()?;
    if layout.size() == 0 {
        return Some(Box::new([]));
    }
    // SAFETY: the layout has a non-zero size; a non-null result is `n` zeroed, aligned words, and
    // all-zero bytes are a valid `AtomicU32` (it has `u32`'s representation). The box owns the
    // allocation with the same layout it is freed with.
    unsafe {
        let ptr = std::alloc::alloc_zeroed(layout) as *mut AtomicU32;
        (!ptr.is_null()).then(|| Box::from_raw(std::ptr::slice_from_raw_parts_mut(ptr, n)))
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn buffers_are_zeroed_and_an_allocation_beyond_the_machine_is_an_error() {
        let words = super::zeroed_words(1 << 20).unwrap();
        assert!(words.len() == 1 << 20 && words.iter().all(|w| w.load(std::sync::atomic::Ordering::Relaxed) == 0));
        assert!(super::zeroed_words(u64::MAX / 8).is_none());
        // 512 TiB: more than any machine this runs on maps.
        assert!(super::zeroed_words(1 << 47).is_none());
        assert_eq!(super::zeroed_words(0).unwrap().len(), 0);
    }

    use super::*;
    use crate::backend::push_words;
    use dof_shaders::scan::{ADD, ScanParams};

    /// A submission is a `submit` call; the arguments of an indirect dispatch are no host readback.
    #[test]
    fn counters_are_exact() -> Result<()> {
        let mut cpu = CpuBackend::new();
        let a = cpu.create_buffer(10, "a")?;
        let args = cpu.create_buffer(3, "args")?;
        cpu.write_buffer(args, 0, &[1, 1, 1])?;
        let sums = cpu.create_buffer(0, "sums")?;
        let push = push_words(&ScanParams { len: 10, data_offset: 0, sums_offset: 0 });
        cpu.dispatch_indirect(&ADD, args, 0, &[a, sums], &push, "add")?;
        cpu.submit()?;
        assert!(cpu.read_buffer(a, 10, 1).is_err());
        assert_eq!(cpu.read_buffer(a, 0, 10)?, vec![0; 10]);
        cpu.destroy_buffer(args);
        cpu.destroy_buffer(args);
        let c = cpu.counters();
        let want = BackendCounters {
            allocations: 3,
            submissions: 1,
            readbacks: 1,
            uploads: 1,
            commands: 1,
            dispatches: 1,
            empty_dispatches: 0,
            barriers: 0,
            // The one workgroup's one step.
            workgroup_barriers: 1,
            device_bytes: 44,
            peak_device_bytes: 56,
        };
        assert_eq!(c, want);
        // After a reset the peak is what is held, and grows again from there.
        cpu.reset_peak_device_bytes();
        assert_eq!(cpu.counters().peak_device_bytes, 44);
        let b = cpu.create_buffer(2, "b")?;
        cpu.destroy_buffer(b);
        assert_eq!((cpu.counters().device_bytes, cpu.counters().peak_device_bytes), (44, 52));
        Ok(())
    }
}
