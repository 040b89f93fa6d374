//! Recording: the command buffer that `fill`/`dispatch` append to, the full barrier in front of every
//! command, GPU timestamps around each timed command, and submission (which waits and harvests the
//! timings). A second command buffer runs one-off host transfers.

use super::instance::DeviceCtx;
use crate::backend::CommandTime;
use crate::error::{Result, VkContext};
use ash::vk;

/// Timed commands per command buffer; past this the recorded work is submitted and a new command
/// buffer begun, transparently.
pub(super) const MAX_TIMED: u32 = 2048;
/// Timestamp queries per timed command: before, a second before (see `record`), after.
const QUERIES: u32 = 3;

pub(super) struct Recorder {
    pool: vk::CommandPool,
    main: vk::CommandBuffer,
    once: vk::CommandBuffer,
    fence: vk::Fence,
    /// Three queries per timed command (see `record`); null where the queue has no timestamps.
    queries: vk::QueryPool,
    timestamp_mask: u64,
    period_ns: f64,
    recording: bool,
    /// (label, kernel) of each timed command recorded in `main`, in order.
    timed: Vec<(String, &'static str)>,
    /// Timings of submitted work not yet returned by `take_times`.
    done: Vec<CommandTime>,
}

impl Recorder {
    /// Null handles: `init` fills them in (split so a failure leaves nothing to leak).
    pub fn empty() -> Self {
        Recorder {
            pool: vk::CommandPool::null(),
            main: vk::CommandBuffer::null(),
            once: vk::CommandBuffer::null(),
            fence: vk::Fence::null(),
            queries: vk::QueryPool::null(),
            timestamp_mask: 0,
            period_ns: 1.0,
            recording: false,
            timed: Vec::new(),
            done: Vec::new(),
        }
    }

    pub fn init(&mut self, ctx: &DeviceCtx, queue_family: u32, timestamp_bits: u32, period_ns: f32) -> Result<()> {
        let d = &ctx.device;
        let pool_info = vk::CommandPoolCreateInfo::default()
            .queue_family_index(queue_family)
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
            if timestamp_bits > 0 {
                let info = vk::QueryPoolCreateInfo::default().query_type(vk::QueryType::TIMESTAMP).query_count(QUERIES * MAX_TIMED);
                self.queries = d.create_query_pool(&info, None).vk("vkCreateQueryPool")?;
            }
        }
        ctx.name(self.main, "dof commands");
        ctx.name(self.once, "dof transfers");
        self.timestamp_mask = if timestamp_bits >= 64 { u64::MAX } else { (1u64 << timestamp_bits) - 1 };
        self.period_ns = period_ns as f64;
        Ok(())
    }

    pub fn is_recording(&self) -> bool {
        self.recording
    }

    /// Appends one command: a full barrier (so it sees every earlier write, also those of earlier
    /// submissions), then `record`, bracketed by timestamps when `timing` names it.
    pub fn record(
        &mut self,
        ctx: &DeviceCtx,
        timing: Option<(&str, &'static str)>,
        record: impl FnOnce(&ash::Device, vk::CommandBuffer),
    ) -> Result<()> {
        if timing.is_some() && self.timed.len() as u32 >= MAX_TIMED {
            self.flush(ctx)?;
        }
        let d = &ctx.device;
        if !self.recording {
            let begin = vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
            // SAFETY: `main` is not pending (every submission is waited for) and its pool allows reset.
            unsafe {
                d.begin_command_buffer(self.main, &begin).vk("vkBeginCommandBuffer")?;
                if self.queries != vk::QueryPool::null() {
                    d.cmd_reset_query_pool(self.main, self.queries, 0, QUERIES * MAX_TIMED);
                }
            }
            self.recording = true;
        }
        let cb = self.main;
        let query = QUERIES * self.timed.len() as u32;
        let timestamps = timing.is_some() && self.queries != vk::QueryPool::null();
        // SAFETY: `cb` is recording; the queries were reset at begin and each is written once.
        unsafe {
            full_barrier(d, cb);
            // Bottom of pipe: the first stamp waits for all earlier work, the last for this command.
            // The middle one is never read: once a framebuffer has been bound, lavapipe takes a
            // stamp only when its binned scene is next flushed, and it flushes on the next stamp;
            // without it the first stamp would be taken after the command, and every stage would
            // time as zero after the first draw.
            if timestamps {
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::BOTTOM_OF_PIPE, self.queries, query);
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::BOTTOM_OF_PIPE, self.queries, query + 1);
            }
            record(d, cb);
            if timestamps {
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::BOTTOM_OF_PIPE, self.queries, query + 2);
            }
        }
        if let Some((label, kernel)) = timing {
            self.timed.push((label.to_string(), kernel));
        }
        Ok(())
    }

    /// Submits what is recorded, waits for it, and keeps its timings for `take_times`.
    pub fn flush(&mut self, ctx: &DeviceCtx) -> Result<()> {
        if !self.recording {
            return Ok(());
        }
        self.recording = false;
        let timed = std::mem::take(&mut self.timed);
        let d = &ctx.device;
        // SAFETY: `main` is recording; the fence is unsignalled (reset after every wait).
        unsafe { d.end_command_buffer(self.main) }.vk("vkEndCommandBuffer")?;
        self.submit_and_wait(ctx, self.main)?;

        let mut stamps = vec![0u64; QUERIES as usize * timed.len()];
        if self.queries != vk::QueryPool::null() && !timed.is_empty() {
            // SAFETY: the submission finished, so every query in range has been written.
            unsafe {
                d.get_query_pool_results(self.queries, 0, &mut stamps, vk::QueryResultFlags::TYPE_64 | vk::QueryResultFlags::WAIT)
            }
            .vk("vkGetQueryPoolResults")?;
        }
        for (i, (label, kernel)) in timed.into_iter().enumerate() {
            let ms = if self.queries == vk::QueryPool::null() {
                f64::NAN
            } else {
                let (first, last) = (stamps[QUERIES as usize * i], stamps[QUERIES as usize * i + 2]);
                let ticks = (last & self.timestamp_mask).wrapping_sub(first & self.timestamp_mask) & self.timestamp_mask;
                ticks as f64 * self.period_ns / 1e6
            };
            self.done.push(CommandTime { label, kernel, ms });
        }
        Ok(())
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

    fn submit_and_wait(&self, ctx: &DeviceCtx, cb: vk::CommandBuffer) -> Result<()> {
        let d = &ctx.device;
        let cbs = [cb];
        let submit = [vk::SubmitInfo::default().command_buffers(&cbs)];
        // SAFETY: `cb` is executable; the fence is unsignalled and reset again once waited for.
        unsafe {
            d.queue_submit(ctx.queue, &submit, self.fence).vk("vkQueueSubmit")?;
            let waited = d.wait_for_fences(&[self.fence], true, u64::MAX).vk("vkWaitForFences");
            d.reset_fences(&[self.fence]).vk("vkResetFences")?;
            waited
        }
    }

    /// Destroys the pool (and its command buffers), the fence and the query pool. The GPU must be idle.
    pub fn destroy(&mut self, device: &ash::Device) {
        // SAFETY: nothing is pending; null handles are ignored.
        unsafe {
            device.destroy_query_pool(self.queries, None);
            device.destroy_fence(self.fence, None);
            device.destroy_command_pool(self.pool, None);
        }
        *self = Recorder::empty();
    }
}

/// Makes every earlier compute or transfer write visible to every later compute, indirect, vertex,
/// fragment or transfer access (the shared semantics of the backends: each command sees all writes of the ones before).
pub(super) fn full_barrier(d: &ash::Device, cb: vk::CommandBuffer) {
    barrier(
        d,
        cb,
        vk::PipelineStageFlags::COMPUTE_SHADER | vk::PipelineStageFlags::TRANSFER,
        vk::AccessFlags::SHADER_WRITE | vk::AccessFlags::TRANSFER_WRITE,
        vk::PipelineStageFlags::COMPUTE_SHADER
            | vk::PipelineStageFlags::DRAW_INDIRECT
            | vk::PipelineStageFlags::VERTEX_SHADER
            | vk::PipelineStageFlags::FRAGMENT_SHADER
            | vk::PipelineStageFlags::TRANSFER,
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
