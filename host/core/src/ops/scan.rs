//! Exclusive prefix scan of `u32` words in place, on any backend (kernels in `dof_shaders::scan`).

use crate::backend::{Backend, BufferId, RunKernel, with_buffers};
use crate::error::{Error, Result};
use dof_shaders::scan::{BLOCK, MAX_GROUPS, ScanParams, scan_add, scan_block};

/// Block-sum buffers for every level of a scan of up to `capacity` words, allocated once and reused
/// frame after frame.
pub struct ScanScratch {
    capacity: u64,
    /// Level `l` holds one word per block of level `l - 1` (level 0 being the data itself).
    levels: Vec<BufferId>,
}

impl ScanScratch {
    pub fn new(backend: &mut dyn Backend, capacity: u64) -> Result<Self> {
        if capacity > u32::MAX as u64 {
            return Err(Error::TooLarge { what: "scan length".into(), size: capacity, limit: u32::MAX as u64 });
        }
        let mut levels: Vec<BufferId> = Vec::new();
        let mut len = capacity.max(1);
        loop {
            let blocks = len.div_ceil(BLOCK as u64);
            match backend.create_buffer(blocks, "scan/sums") {
                Ok(id) => levels.push(id),
                // A failure part way (device memory running out) frees what was made.
                Err(e) => {
                    levels.into_iter().for_each(|id| backend.destroy_buffer(id));
                    return Err(e);
                }
            }
            if blocks == 1 {
                break;
            }
            len = blocks;
        }
        Ok(ScanScratch { capacity, levels })
    }

    /// Device memory the scratch holds, in bytes.
    pub fn bytes(&self) -> u64 {
        let (mut len, mut words) = (self.capacity.max(1), 0);
        loop {
            let blocks = len.div_ceil(BLOCK as u64);
            words += blocks;
            if blocks == 1 {
                return 4 * words;
            }
            len = blocks;
        }
    }

    pub fn destroy(self, backend: &mut dyn Backend) {
        for b in self.levels {
            backend.destroy_buffer(b);
        }
    }

    /// Every buffer the scratch holds (for an owner that frees them with its own).
    pub fn buffers(&self) -> &[BufferId] {
        &self.levels
    }

    /// Where the total of the last scan ends up: word 0 of the top level.
    pub fn total(&self, len: u64) -> (BufferId, u64) {
        let mut level = 0;
        let mut n = len.max(1);
        while n > BLOCK as u64 {
            n = n.div_ceil(BLOCK as u64);
            level += 1;
        }
        (self.levels[level], 0)
    }

    /// Records an exclusive scan of `data[offset .. offset + len]`; afterwards [`Self::total`] holds the sum.
    pub fn record(&self, backend: &mut dyn Backend, data: BufferId, offset: u64, len: u64) -> Result<()> {
        if len > self.capacity {
            return Err(Error::InvalidArgument(format!("scan of {len} words exceeds the scratch capacity {}", self.capacity)));
        }
        let end = offset.checked_add(len).filter(|&e| e <= backend.buffer_words(data).unwrap_or(0));
        if end.is_none() || offset > u32::MAX as u64 {
            return Err(Error::InvalidArgument(format!("scan range {offset}+{len} outside the buffer")));
        }
        if len == 0 {
            // Nothing to scan; the total is zero.
            return backend.fill(self.levels[0], 0, 1, 0, "scan/empty");
        }
        self.record_level(backend, data, offset as u32, len as u32, 0)
    }

    fn record_level(&self, backend: &mut dyn Backend, data: BufferId, offset: u32, len: u32, level: usize) -> Result<()> {
        let sums = self.levels[level];
        let blocks = len.div_ceil(BLOCK);
        let params = ScanParams { len, data_offset: offset, sums_offset: 0 };
        let groups = [blocks.min(MAX_GROUPS), 1, 1];
        backend.run(scan_block::Bindings { data, sums }, groups, &params, "scan/block")?;
        if blocks > 1 {
            self.record_level(backend, sums, 0, blocks, level + 1)?;
            backend.run(scan_add::Bindings { data, sums }, groups, &params, "scan/add")?;
        }
        Ok(())
    }
}

/// Exclusive scan of `values` on `backend`: the scanned words and their total.
pub fn exclusive_scan(backend: &mut dyn Backend, values: &[u32]) -> Result<(Vec<u32>, u32)> {
    let len = values.len() as u64;
    with_buffers(backend, &[(len, "scan/data")], |backend, b| {
        let data = b[0];
        let scratch = ScanScratch::new(backend, len)?;
        let result = (|| {
            backend.write_buffer(data, 0, values)?;
            scratch.record(backend, data, 0, len)?;
            backend.submit()?;
            let scanned = backend.read_buffer(data, 0, len)?;
            let (tb, to) = scratch.total(len);
            Ok((scanned, backend.read_buffer(tb, to, 1)?[0]))
        })();
        scratch.destroy(backend);
        result
    })
}
