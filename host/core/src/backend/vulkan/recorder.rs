//! Recording: the command buffer that `fill`/`dispatch` append to (the backend's own, or the caller's
//! between `begin_external` and `end_external`), the barriers between commands, GPU timestamps around
//! each timed command, and submission (which waits and harvests the timings). A second command buffer
//! runs one-off host transfers.
//!
//! Barriers follow from what each command declares it reads and writes: the recorder remembers the
//! buffers (and images) the commands since the last barrier read and wrote, and puts a full memory
//! barrier before a command that reads what one of them wrote or writes what one of them read or
//! wrote (a kernel's `read` bindings are reads, its others writes; fills write; copies
//! read their source and write their destination), and before the first command of a command
//! buffer. Commands that share nothing, or only read what they share, run without barriers.
//!
//! Timestamps go into query pools of [`TIMED_PER_POOL`] timed commands each; a recording that times
//! more commands takes (and keeps) another pool, so one `submit` is always one `vkQueueSubmit`.

use super::instance::DeviceCtx;
use crate::backend::{CommandTime, Hazards, SPAN};
use crate::error::{Result, VkContext};
use ash::vk;
use std::collections::VecDeque;

/// Timed commands per query pool; a recording timing more commands uses more pools.
pub(super) const TIMED_PER_POOL: u32 = 2048;
/// Timestamp queries per timed command: before, a second before (see `record`), after.
const QUERIES: u32 = 3;
/// External recordings whose times wait to be taken at most (a caller that never takes them
/// keeps this many sets of query pools).
pub(super) const MAX_PENDING_RECORDINGS: usize = 8;

/// Query pools for one kind of recording and the timed commands of the recording using them.
#[derive(Default)]
struct Queries {
    pools: Vec<vk::QueryPool>,
    /// Pools reset so far in the command buffer being recorded (they are reset on first use).
    reset: usize,
    /// (label, kernel) of each timed command recorded, in order.
    timed: Vec<(String, &'static str)>,
}

impl Queries {
    /// Starts a recording: pools are reset again as it reaches them.
    fn begin(&mut self) {
        self.reset = 0;
        self.timed.clear();
    }

    /// The pool and first query of the next timed command, recording the reset of a pool on its
    /// first use in this command buffer and creating a pool when every one is taken.
    fn next(&mut self, ctx: &DeviceCtx, cb: vk::CommandBuffer, name: &str) -> Result<(vk::QueryPool, u32)> {
        let i = self.timed.len() as u32;
        let (pool, first) = ((i / TIMED_PER_POOL) as usize, (i % TIMED_PER_POOL) * QUERIES);
        let d = &ctx.device;
        if pool == self.pools.len() {
            let info = vk::QueryPoolCreateInfo::default().query_type(vk::QueryType::TIMESTAMP).query_count(QUERIES * TIMED_PER_POOL);
            // SAFETY: a valid create info on a live device; the pool is kept until `destroy`.
            let made = unsafe { d.create_query_pool(&info, None) }.vk("vkCreateQueryPool")?;
            ctx.name(made, name);
            self.pools.push(made);
        }
        if pool == self.reset {
            // SAFETY: `cb` is recording, outside a render pass; no query of the pool is in use by it.
            unsafe { d.cmd_reset_query_pool(cb, self.pools[pool], 0, QUERIES * TIMED_PER_POOL) };
            self.reset += 1;
        }
        Ok((self.pools[pool], first))
    }

    /// The stamps of `count` timed commands of the last recording, or `None` where `wait` is off and
    /// the device has not written them all yet.
    fn stamps(&self, d: &ash::Device, count: usize, wait: bool) -> Result<Option<Vec<u64>>> {
        let mut stamps = vec![0u64; QUERIES as usize * count];
        let per_pool = (QUERIES * TIMED_PER_POOL) as usize;
        let flags = if wait { vk::QueryResultFlags::TYPE_64 | vk::QueryResultFlags::WAIT } else { vk::QueryResultFlags::TYPE_64 };
        for (chunk, &pool) in stamps.chunks_mut(per_pool).zip(&self.pools) {
            // SAFETY: every query in range was reset and written by the recording (or is pending).
            match unsafe { d.get_query_pool_results(pool, 0, chunk, flags) } {
                Ok(()) => {}
                Err(vk::Result::NOT_READY) if !wait => return Ok(None),
                Err(result) => return Err(crate::error::Error::Vulkan { call: "vkGetQueryPoolResults", result }),
            }
        }
        Ok(Some(stamps))
    }

    fn destroy(&mut self, d: &ash::Device) {
        for pool in self.pools.drain(..) {
            // SAFETY: the GPU is done with the pool.
            unsafe { d.destroy_query_pool(pool, None) };
        }
        *self = Queries::default();
    }
}

pub(super) struct Recorder {
    pool: vk::CommandPool,
    main: vk::CommandBuffer,
    once: vk::CommandBuffer,
    fence: vk::Fence,
    /// Whether the queue writes timestamps.
    timestamps: bool,
    /// Whether commands get timestamp pairs of their own (spans always do, where the queue has
    /// timestamps).
    command_timestamps: bool,
    timestamp_mask: u64,
    period_ns: f64,
    /// Whether the queue supports graphics stages (barriers name them only then).
    graphics: bool,
    /// Whether `main` is recording.
    recording: bool,
    main_queries: Queries,
    /// The caller's command buffer, between `begin_external` and `end_external`.
    external: Option<vk::CommandBuffer>,
    /// The open external recording's query pools and timed commands.
    external_queries: Queries,
    /// Ended external recordings whose times were not taken yet, oldest first, each with its own
    /// query pools (so two recordings in one submission, or frames in flight, keep their times).
    external_pending: VecDeque<Queries>,
    /// Query pools of recordings whose times were taken, to be used again.
    external_spare: Vec<Queries>,
    /// Timings of submitted work not yet returned by `take_times`.
    done: Vec<CommandTime>,
    /// The open spans of `main`, innermost last: the pool and first query of each (`None` without
    /// timestamps). A span takes one timed slot of `main_queries` (kernel [`SPAN`]): its first two
    /// stamps where it opens, the third where it closes.
    open_spans: Vec<Option<(vk::QueryPool, u32)>>,
    /// Span timings of submitted work not yet returned by `take_span_times`.
    done_spans: Vec<CommandTime>,
    /// `vkQueueSubmit` calls so far.
    submissions: u64,
    /// What the commands since the last barrier accessed (raw handles), from the start of the
    /// command buffer being recorded.
    hazards: Hazards<u64>,
    /// Barriers `record` put between commands so far (for tests).
    barriers: u64,
}

impl Recorder {
    /// Null handles: `init` fills them in (split so a failure leaves nothing to leak).
    pub fn empty() -> Self {
        Recorder {
            pool: vk::CommandPool::null(),
            main: vk::CommandBuffer::null(),
            once: vk::CommandBuffer::null(),
            fence: vk::Fence::null(),
            timestamps: false,
            command_timestamps: true,
            timestamp_mask: 0,
            period_ns: 1.0,
            graphics: false,
            recording: false,
            main_queries: Queries::default(),
            external: None,
            external_queries: Queries::default(),
            external_pending: VecDeque::new(),
            external_spare: Vec::new(),
            done: Vec::new(),
            open_spans: Vec::new(),
            done_spans: Vec::new(),
            submissions: 0,
            hazards: Hazards::default(),
            barriers: 0,
        }
    }

    pub fn init(&mut self, ctx: &DeviceCtx, timestamp_bits: u32, period_ns: f32) -> Result<()> {
        let d = &ctx.device;
        let pool_info = vk::CommandPoolCreateInfo::default()
            .queue_family_index(ctx.queue_family)
            .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER);
        // SAFETY: create infos on a live device; each handle is stored at once so `destroy` frees it.
        unsafe {
            self.pool = d.create_command_pool(&pool_info, None).vk("vkCreateCommandPool")?;
            let alloc = vk::CommandBufferAllocateInfo::default()
                .command_pool(self.pool)
                .level(vk::CommandBufferLevel::PRIMARY)
                .command_buffer_count(2);
            let buffers = d.allocate_command_buffers(&alloc).vk("vkAllocateCommandBuffers")?;
            self.main = buffers.first().copied().unwrap_or_default();
            self.once = buffers.get(1).copied().unwrap_or_default();
            self.fence = d.create_fence(&vk::FenceCreateInfo::default(), None).vk("vkCreateFence")?;
        }
        ctx.name(self.main, "dof commands");
        ctx.name(self.once, "dof transfers");
        self.timestamps = timestamp_bits > 0;
        self.timestamp_mask = if timestamp_bits >= 64 { u64::MAX } else { (1u64 << timestamp_bits) - 1 };
        self.period_ns = period_ns as f64;
        self.graphics = ctx.graphics;
        Ok(())
    }

    /// `vkQueueSubmit` calls so far.
    pub fn submissions(&self) -> u64 {
        self.submissions
    }

    /// Barriers put between commands so far.
    /// Whether later commands get timestamp pairs of their own ([`crate::Backend::set_command_timestamps`]).
    pub fn set_command_timestamps(&mut self, on: bool) {
        self.command_timestamps = on;
    }

    pub fn barriers(&self) -> u64 {
        self.barriers
    }

    /// Whether the backend's own command buffer holds unsubmitted work.
    pub fn is_recording(&self) -> bool {
        self.recording
    }

    /// The caller's command buffer, between `begin_external` and `end_external`.
    pub fn external_command_buffer(&self) -> Option<vk::CommandBuffer> {
        self.external
    }

    /// Whether commands go into the caller's command buffer.
    pub fn is_external(&self) -> bool {
        self.external.is_some()
    }

    /// Whether the queue supports graphics stages.
    pub fn graphics(&self) -> bool {
        self.graphics
    }

    /// Appends one command to the caller's command buffer (between `begin_external` and
    /// `end_external`) or else to the backend's own (begun on first use): a barrier first where it
    /// is needed (so it sees every earlier write, also those of earlier submissions), then `record`,
    /// bracketed by timestamps when `timing` names it. `accessed` are the raw handles of the buffers
    /// (and images) the command reads or writes, each with whether it writes it: it must name every
    /// one, since commands that share none, or only read what they share, run without a barrier
    /// between them.
    pub fn record(
        &mut self,
        ctx: &DeviceCtx,
        timing: Option<(&str, &'static str)>,
        accessed: &[(u64, bool)],
        record: impl FnOnce(&ash::Device, vk::CommandBuffer),
    ) -> Result<()> {
        let d = &ctx.device;
        let cb = match self.external {
            Some(cb) => cb,
            None => self.begin_main(ctx)?,
        };
        let stamps = match timing {
            Some(_) if self.timestamps && self.command_timestamps => {
                let queries = if self.external.is_some() { &mut self.external_queries } else { &mut self.main_queries };
                Some(queries.next(ctx, cb, "dof timestamps")?)
            }
            _ => None,
        };
        // A barrier only where this command reads something an earlier command since the last
        // barrier wrote, or writes something one read or wrote, and before the first command of a
        // command buffer (`backend::access`).
        if self.hazards.next(accessed) {
            self.barriers += 1;
            full_barrier(d, cb, self.graphics);
        }
        // SAFETY: `cb` is recording; the queries were reset in it and each is written once.
        unsafe {
            // Bottom of pipe: the first stamp waits for all earlier work, the last for this command.
            // The middle one is never read: once a framebuffer has been bound, lavapipe takes a
            // stamp only when its binned scene is next flushed, and it flushes on the next stamp;
            // without it the first stamp would be taken after the command, and every stage would
            // time as zero after the first draw.
            if let Some((pool, query)) = stamps {
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::BOTTOM_OF_PIPE, pool, query);
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::BOTTOM_OF_PIPE, pool, query + 1);
            }
            record(d, cb);
            if let Some((pool, query)) = stamps {
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::BOTTOM_OF_PIPE, pool, query + 2);
            }
        }
        if let Some((label, kernel)) = timing.filter(|_| self.command_timestamps) {
            let queries = if self.external.is_some() { &mut self.external_queries } else { &mut self.main_queries };
            queries.timed.push((label.to_string(), kernel));
        }
        Ok(())
    }

    /// The backend's own command buffer, begun if it is not recording yet.
    fn begin_main(&mut self, ctx: &DeviceCtx) -> Result<vk::CommandBuffer> {
        if !self.recording {
            let begin = vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
            // SAFETY: `main` is not pending (every submission is waited for) and its pool allows reset.
            unsafe { ctx.device.begin_command_buffer(self.main, &begin) }.vk("vkBeginCommandBuffer")?;
            self.recording = true;
            self.main_queries.begin();
            self.hazards.restart();
        }
        Ok(self.main)
    }

    /// Opens a span in the backend's own command buffer: its first stamps wait (bottom of pipe)
    /// for everything recorded before it, as a timed command's do.
    pub fn begin_span(&mut self, ctx: &DeviceCtx, label: &str) -> Result<()> {
        if self.external.is_some() {
            return Err(crate::error::Error::InvalidArgument(format!(
                "span `{label}`: spans time the backend's own submissions, not a caller's command buffer (use take_external_times)"
            )));
        }
        let cb = self.begin_main(ctx)?;
        let slot = if self.timestamps { Some(self.main_queries.next(ctx, cb, "dof timestamps")?) } else { None };
        if let Some((pool, query)) = slot {
            // SAFETY: `cb` is recording, the queries were reset in it; see `record` for the second stamp.
            unsafe {
                ctx.device.cmd_write_timestamp(cb, vk::PipelineStageFlags::BOTTOM_OF_PIPE, pool, query);
                ctx.device.cmd_write_timestamp(cb, vk::PipelineStageFlags::BOTTOM_OF_PIPE, pool, query + 1);
            }
        }
        self.main_queries.timed.push((label.to_string(), SPAN));
        self.open_spans.push(slot);
        Ok(())
    }

    /// Closes the innermost open span: its last stamp waits for every command recorded before it.
    pub fn end_span(&mut self, ctx: &DeviceCtx) -> Result<()> {
        let slot = self.open_spans.pop().ok_or_else(|| crate::error::Error::InvalidArgument("end_span without an open span".into()))?;
        if let Some((pool, query)) = slot {
            // SAFETY: `main` is recording (the span opened in it and nothing submitted it since).
            unsafe { ctx.device.cmd_write_timestamp(self.main, vk::PipelineStageFlags::BOTTOM_OF_PIPE, pool, query + 2) };
        }
        Ok(())
    }

    /// Span timings of everything submitted since the last call, in opening order.
    pub fn take_span_times(&mut self) -> Vec<CommandTime> {
        std::mem::take(&mut self.done_spans)
    }

    /// Submits what is recorded in the backend's own command buffer, waits for it, and keeps its
    /// timings for `take_times` (and its spans' for `take_span_times`). Refused while a span is
    /// open: a span lies inside one submission.
    pub fn flush(&mut self, ctx: &DeviceCtx) -> Result<()> {
        if !self.recording {
            return Ok(());
        }
        if !self.open_spans.is_empty() {
            return Err(crate::error::Error::InvalidArgument(format!(
                "a submission with {} span(s) still open (end_span first; a span lies inside one submission)",
                self.open_spans.len()
            )));
        }
        self.recording = false;
        let timed = std::mem::take(&mut self.main_queries.timed);
        let d = &ctx.device;
        // SAFETY: `main` is recording; the fence is unsignalled (reset after every wait).
        unsafe { d.end_command_buffer(self.main) }.vk("vkEndCommandBuffer")?;
        self.submit_and_wait(ctx, self.main)?;
        let stamps = if self.timestamps && !timed.is_empty() { self.main_queries.stamps(d, timed.len(), true)? } else { None };
        let (spans, times): (Vec<_>, Vec<_>) = self.times(timed, stamps.as_deref()).into_iter().partition(|t| t.kernel == SPAN);
        self.done.extend(times);
        self.done_spans.extend(spans);
        Ok(())
    }

    /// Timings from `stamps` (three a command), or NaN without timestamps.
    fn times(&self, timed: Vec<(String, &'static str)>, stamps: Option<&[u64]>) -> Vec<CommandTime> {
        timed
            .into_iter()
            .enumerate()
            .map(|(i, (label, kernel))| {
                let ms = match stamps {
                    Some(stamps) => {
                        let (first, last) = (stamps[QUERIES as usize * i], stamps[QUERIES as usize * i + 2]);
                        let ticks = (last & self.timestamp_mask).wrapping_sub(first & self.timestamp_mask) & self.timestamp_mask;
                        ticks as f64 * self.period_ns / 1e6
                    }
                    None => f64::NAN,
                };
                CommandTime { label, kernel, ms }
            })
            .collect()
    }

    /// Timings of everything submitted since the last call, in recording order.
    pub fn take_times(&mut self) -> Vec<CommandTime> {
        std::mem::take(&mut self.done)
    }

    /// Records `record` into the one-off command buffer, submits it and waits. Nothing may be
    /// recorded in `main` (callers flush first).
    pub fn run_once(&mut self, ctx: &DeviceCtx, record: impl FnOnce(&ash::Device, vk::CommandBuffer)) -> Result<()> {
        let d = &ctx.device;
        let begin = vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
        // SAFETY: `once` is not pending (every submission is waited for).
        unsafe {
            d.begin_command_buffer(self.once, &begin).vk("vkBeginCommandBuffer")?;
            record(d, self.once);
            d.end_command_buffer(self.once).vk("vkEndCommandBuffer")?;
        }
        self.submit_and_wait(ctx, self.once)
    }

    fn submit_and_wait(&mut self, ctx: &DeviceCtx, cb: vk::CommandBuffer) -> Result<()> {
        let d = &ctx.device;
        let cbs = [cb];
        let submit = [vk::SubmitInfo::default().command_buffers(&cbs)];
        // SAFETY: `cb` is executable; the fence is unsignalled and reset again once waited for.
        unsafe {
            d.queue_submit(ctx.queue, &submit, self.fence).vk("vkQueueSubmit")?;
            self.submissions += 1;
            let waited = d.wait_for_fences(&[self.fence], true, u64::MAX).vk("vkWaitForFences");
            d.reset_fences(&[self.fence]).vk("vkResetFences")?;
            waited
        }
    }

    /// Starts recording into the caller's command buffer `cb` (recording, outside a render pass),
    /// with a barrier ordering the caller's earlier work before the backend's commands. The
    /// backend's own command buffer must hold nothing (callers flush first). Each recording times
    /// its commands with query pools of its own; past [`MAX_PENDING_RECORDINGS`] recordings whose
    /// times were not taken, the oldest one's are dropped.
    pub fn begin_external(&mut self, ctx: &DeviceCtx, cb: vk::CommandBuffer) {
        self.external = Some(cb);
        if self.external_pending.len() >= MAX_PENDING_RECORDINGS {
            // Its pools are reset by this recording's commands, after its own on the queue.
            if let Some(oldest) = self.external_pending.pop_front() {
                self.external_spare.push(oldest);
            }
        }
        self.external_queries = self.external_spare.pop().unwrap_or_default();
        self.external_queries.begin();
        let g = self.graphics;
        let graphics = |flags: vk::PipelineStageFlags| if g { flags } else { vk::PipelineStageFlags::empty() };
        let attachments = if g {
            vk::AccessFlags::COLOR_ATTACHMENT_WRITE | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE
        } else {
            vk::AccessFlags::empty()
        };
        // The caller's compute, transfer, colour- and depth-attachment and shader writes (and, by
        // the execution dependency, its reads at those stages) come before every access of the
        // backend's commands.
        barrier(
            &ctx.device,
            cb,
            // DRAW_INDIRECT on every queue: an earlier recording's indirect dispatches read their
            // arguments there (compute queues have the stage too), before this one rewrites them.
            vk::PipelineStageFlags::COMPUTE_SHADER
                | vk::PipelineStageFlags::TRANSFER
                | vk::PipelineStageFlags::DRAW_INDIRECT
                | graphics(
                    vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT
                        | vk::PipelineStageFlags::EARLY_FRAGMENT_TESTS
                        | vk::PipelineStageFlags::LATE_FRAGMENT_TESTS
                        | vk::PipelineStageFlags::VERTEX_SHADER
                        | vk::PipelineStageFlags::FRAGMENT_SHADER,
                ),
            vk::AccessFlags::SHADER_WRITE | vk::AccessFlags::TRANSFER_WRITE | attachments,
            later_stages(g),
            later_accesses(g),
        );
        self.hazards.after_barrier();
    }

    /// Ends the external recording with a barrier making the backend's writes visible to whatever
    /// the caller records next (compute, indirect, vertex, fragment, colour attachment and transfer
    /// accesses).
    pub fn end_external(&mut self, ctx: &DeviceCtx) {
        let Some(cb) = self.external.take() else { return };
        let g = self.graphics;
        let src = vk::PipelineStageFlags::COMPUTE_SHADER
            | vk::PipelineStageFlags::TRANSFER
            | if g { vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT } else { vk::PipelineStageFlags::empty() };
        let src_access = vk::AccessFlags::SHADER_WRITE
            | vk::AccessFlags::TRANSFER_WRITE
            | if g { vk::AccessFlags::COLOR_ATTACHMENT_WRITE } else { vk::AccessFlags::empty() };
        barrier(&ctx.device, cb, src, src_access, later_stages(g), later_accesses(g));
        self.external_pending.push_back(std::mem::take(&mut self.external_queries));
        self.hazards.restart();
    }

    /// The timings of the oldest ended external recording whose times were not taken, once the
    /// device has written them all: `Ok(None)` until then (never blocks); `Ok(Some(..))` once, after
    /// which they are gone (`Some` of an empty list when there is nothing to take). Without
    /// timestamps the times are NaN.
    pub fn take_external_times(&mut self, ctx: &DeviceCtx) -> Result<Option<Vec<CommandTime>>> {
        let Some(oldest) = self.external_pending.front() else { return Ok(Some(Vec::new())) };
        let stamps = if !self.timestamps || oldest.timed.is_empty() {
            None
        } else {
            match oldest.stamps(&ctx.device, oldest.timed.len(), false)? {
                Some(stamps) => Some(stamps),
                None => return Ok(None),
            }
        };
        let Some(mut done) = self.external_pending.pop_front() else { return Ok(Some(Vec::new())) };
        let times = self.times(std::mem::take(&mut done.timed), stamps.as_deref());
        self.external_spare.push(done);
        Ok(Some(times))
    }

    /// Destroys the pool (and its command buffers), the fence and the query pools. The GPU must be
    /// done with them.
    pub fn destroy(&mut self, device: &ash::Device) {
        self.main_queries.destroy(device);
        self.external_queries.destroy(device);
        for mut q in self.external_pending.drain(..).chain(self.external_spare.drain(..)) {
            q.destroy(device);
        }
        // SAFETY: nothing is pending; null handles are ignored.
        unsafe {
            device.destroy_fence(self.fence, None);
            device.destroy_command_pool(self.pool, None);
        }
        *self = Recorder { submissions: self.submissions, ..Recorder::empty() };
    }
}

/// Every stage a later command may access a buffer or image in (graphics stages only where the
/// queue has them).
fn later_stages(graphics: bool) -> vk::PipelineStageFlags {
    let mut stages = vk::PipelineStageFlags::COMPUTE_SHADER | vk::PipelineStageFlags::TRANSFER | vk::PipelineStageFlags::DRAW_INDIRECT;
    if graphics {
        stages |= vk::PipelineStageFlags::VERTEX_SHADER
            | vk::PipelineStageFlags::FRAGMENT_SHADER
            | vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
    }
    stages
}

/// Every access a later command may make in [`later_stages`].
fn later_accesses(graphics: bool) -> vk::AccessFlags {
    let mut access = vk::AccessFlags::SHADER_READ
        | vk::AccessFlags::SHADER_WRITE
        | vk::AccessFlags::INDIRECT_COMMAND_READ
        | vk::AccessFlags::TRANSFER_READ
        | vk::AccessFlags::TRANSFER_WRITE;
    if graphics {
        access |= vk::AccessFlags::COLOR_ATTACHMENT_READ | vk::AccessFlags::COLOR_ATTACHMENT_WRITE;
    }
    access
}

/// Makes every earlier compute, shader or transfer write visible to every later compute, indirect,
/// vertex, fragment or transfer access, and orders every earlier access (indirect reads included)
/// before them (the shared semantics of the backends: each command sees all writes of the ones
/// before). Graphics stages are named only where the queue supports graphics.
pub(super) fn full_barrier(d: &ash::Device, cb: vk::CommandBuffer, graphics: bool) {
    let mut src = vk::PipelineStageFlags::COMPUTE_SHADER | vk::PipelineStageFlags::TRANSFER;
    let mut dst = vk::PipelineStageFlags::COMPUTE_SHADER | vk::PipelineStageFlags::DRAW_INDIRECT | vk::PipelineStageFlags::TRANSFER;
    if graphics {
        // The draws' shaders read (and may write) storage buffers.
        src |= vk::PipelineStageFlags::VERTEX_SHADER | vk::PipelineStageFlags::FRAGMENT_SHADER;
        dst |= vk::PipelineStageFlags::VERTEX_SHADER | vk::PipelineStageFlags::FRAGMENT_SHADER;
    }
    barrier(
        d,
        cb,
        src,
        vk::AccessFlags::SHADER_WRITE | vk::AccessFlags::TRANSFER_WRITE,
        dst,
        vk::AccessFlags::SHADER_READ
            | vk::AccessFlags::SHADER_WRITE
            | vk::AccessFlags::INDIRECT_COMMAND_READ
            | vk::AccessFlags::TRANSFER_READ
            | vk::AccessFlags::TRANSFER_WRITE,
    );
}

/// One global memory barrier.
pub(super) fn barrier(
    d: &ash::Device,
    cb: vk::CommandBuffer,
    src_stage: vk::PipelineStageFlags,
    src_access: vk::AccessFlags,
    dst_stage: vk::PipelineStageFlags,
    dst_access: vk::AccessFlags,
) {
    let memory = [vk::MemoryBarrier::default().src_access_mask(src_access).dst_access_mask(dst_access)];
    // SAFETY: `cb` is recording (callers' contract).
    unsafe { d.cmd_pipeline_barrier(cb, src_stage, dst_stage, vk::DependencyFlags::empty(), &memory, &[], &[]) };
}
