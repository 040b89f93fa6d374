//! GPU timestamps for the wgpu backend's own submissions: a pair around each dispatch's compute
//! pass, resolved when the encoder is submitted. Spans run from the first timed command in them
//! to the last. Without wgpu's `TIMESTAMP_QUERY`, in a caller's encoder, for clears (no pass to
//! time) and beyond [`MAX_TIMED`] commands in one submission, a time is NaN.

use crate::backend::{CommandTime, SPAN};
use crate::error::{Error, Result};
use std::sync::{Arc, Mutex};

/// Commands timed in one submission (two queries each, within wgpu's 4096 a query set).
pub const MAX_TIMED: u32 = wgpu::QUERY_SET_MAX_QUERIES / 2;

/// The query set and the buffers its results pass through, made once.
pub(super) struct Timestamps {
    queries: wgpu::QuerySet,
    resolved: wgpu::Buffer,
    readback: wgpu::Buffer,
    /// Nanoseconds a tick.
    period_ns: f64,
    /// Queries written into the current encoder.
    used: u32,
}

/// A command recorded into the backend's own encoder since the last `submit`.
pub(super) struct Command {
    pub label: String,
    pub kernel: &'static str,
    /// Its first query in the current encoder, until the encoder is submitted.
    query: Option<u32>,
    /// Begin and end in nanoseconds on the device's clock, once read.
    span_ns: Option<(f64, f64)>,
}

impl Command {
    pub fn new(label: &str, kernel: &'static str) -> Command {
        Command { label: label.to_string(), kernel, query: None, span_ns: None }
    }

    fn time(&self) -> CommandTime {
        let ms = self.span_ns.map_or(f64::NAN, |(begin, end)| (end - begin) / 1e6);
        CommandTime { label: self.label.clone(), kernel: self.kernel, ms }
    }
}

impl Timestamps {
    /// Where the device has timestamps.
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue) -> Option<Timestamps> {
        if !device.features().contains(wgpu::Features::TIMESTAMP_QUERY) {
            return None;
        }
        let count = 2 * MAX_TIMED;
        let queries =
            device.create_query_set(&wgpu::QuerySetDescriptor { label: Some("dof timestamps"), ty: wgpu::QueryType::Timestamp, count });
        let buffer = |label, usage| {
            device.create_buffer(&wgpu::BufferDescriptor { label: Some(label), size: 8 * count as u64, usage, mapped_at_creation: false })
        };
        let resolved = buffer("dof timestamps resolved", wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC);
        let readback = buffer("dof timestamps read", wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST);
        Some(Timestamps { queries, resolved, readback, period_ns: queue.get_timestamp_period() as f64, used: 0 })
    }

    /// The pass timestamps for `command`, if one more fits this submission.
    pub fn pass_writes(&mut self, command: &mut Command) -> Option<wgpu::ComputePassTimestampWrites<'_>> {
        if self.used + 2 > 2 * MAX_TIMED {
            return None;
        }
        command.query = Some(self.used);
        self.used += 2;
        Some(wgpu::ComputePassTimestampWrites {
            query_set: &self.queries,
            beginning_of_pass_write_index: Some(self.used - 2),
            end_of_pass_write_index: Some(self.used - 1),
        })
    }

    /// Before the encoder is submitted: its queries resolved into the readback buffer.
    pub fn resolve(&self, encoder: &mut wgpu::CommandEncoder) {
        if self.used > 0 {
            encoder.resolve_query_set(&self.queries, 0..self.used, &self.resolved, 0);
            encoder.copy_buffer_to_buffer(&self.resolved, 0, &self.readback, 0, 8 * self.used as u64);
        }
    }

    /// After the submission completed (`wait` waits for the device): the times of `commands`.
    pub fn read(&mut self, commands: &mut [Command], wait: impl Fn() -> Result<()>) -> Result<()> {
        if self.used == 0 {
            return Ok(());
        }
        let bytes = 8 * self.used as u64;
        let mapped = Arc::new(Mutex::new(None));
        let done = mapped.clone();
        self.readback.map_async(wgpu::MapMode::Read, ..bytes, move |result| {
            if let Ok(mut slot) = done.lock() {
                *slot = Some(result);
            }
        });
        wait()?;
        match mapped.lock().map_err(|_| Error::Device("the timestamps' state is poisoned".into()))?.take() {
            Some(Ok(())) => {}
            Some(Err(e)) => return Err(Error::Device(format!("mapping the timestamps: {e}"))),
            None => return Err(Error::Device("the timestamps were not mapped after the device went idle".into())),
        }
        let view = self.readback.get_mapped_range(..bytes).map_err(|e| Error::Device(format!("reading the timestamps: {e}")))?;
        let ticks: Vec<u64> = view.as_chunks::<8>().0.iter().map(|t| u64::from_le_bytes(*t)).collect();
        drop(view);
        self.readback.unmap();
        for command in commands.iter_mut() {
            if let Some(q) = command.query.take()
                && let (Some(&begin), Some(&end)) = (ticks.get(q as usize), ticks.get(q as usize + 1))
            {
                command.span_ns = Some((begin as f64 * self.period_ns, end as f64 * self.period_ns));
            }
        }
        self.used = 0;
        Ok(())
    }
}

/// The commands' times, and those of the spans (`(label, first command, end)`, in opening order)
/// over them.
pub(super) fn times(commands: &[Command], spans: &[(String, usize, usize)]) -> (Vec<CommandTime>, Vec<CommandTime>) {
    let span_time = |(label, first, end): &(String, usize, usize)| {
        let timed: Vec<(f64, f64)> = commands[*first..*end].iter().filter_map(|c| c.span_ns).collect();
        let begin = timed.iter().map(|t| t.0).fold(f64::INFINITY, f64::min);
        let last = timed.iter().map(|t| t.1).fold(f64::NEG_INFINITY, f64::max);
        let ms = if timed.is_empty() { f64::NAN } else { (last - begin) / 1e6 };
        CommandTime { label: label.clone(), kernel: SPAN, ms }
    };
    (commands.iter().map(Command::time).collect(), spans.iter().map(span_time).collect())
}
