//! Building blocks that record kernel sequences on any [`crate::backend::Backend`]: the segmented sort
//! and the prefix scan that the tiled splatting pipeline is made of, usable on a caller's own buffers.
//!
//! - [`scan::ScanScratch`]: an exclusive prefix scan of `u32` words in place, over
//!   `data[offset .. offset + len]` of any buffer; the total lands in [`scan::ScanScratch::total`].
//!   The scratch (block sums per level) is sized once for a largest length and reused.
//! - [`sort::SegmentedSort`]: sorts many lists of `(f32 key, u32 payload)` at once, each list an
//!   `[offset, len]` pair in a segments buffer, from input buffers into output buffers (distinct,
//!   which the caller should initialise as copies of the inputs where words lie outside every list).
//!   Keys order by [`dof_shaders::keys::sort_key`] (a total order: -0 before +0, NaN last).
//!
//! Both only record: nothing runs until the backend's `submit` (or, on a renderer's device, the
//! caller's own submission of its command buffer), and nothing is read back. On Vulkan the same
//! calls record into the command buffer; kernels of a crate's own can run between them (see
//! `VulkanBackend::add_modules` and `examples/own-kernel`).
//!
//! ```
//! use dof_core::backend::{Backend, CpuBackend};
//! use dof_core::ops::{scan::ScanScratch, sort::SegmentedSort};
//!
//! # fn main() -> dof_core::Result<()> {
//! let mut backend = CpuBackend::new();
//!
//! // Scan: counts in the caller's buffer become offsets, the total is read back from the scratch.
//! let counts = [3u32, 0, 2, 5, 1];
//! let data = backend.create_buffer(counts.len() as u64, "my counts")?;
//! backend.write_buffer(data, 0, &counts)?;
//! let scan = ScanScratch::new(&mut backend, 1024)?;
//! scan.record(&mut backend, data, 0, counts.len() as u64)?;
//! backend.submit()?;
//! assert_eq!(backend.read_buffer(data, 0, 5)?, [0, 3, 3, 5, 10]);
//! let (total, at) = scan.total(counts.len() as u64);
//! assert_eq!(backend.read_buffer(total, at, 1)?, [11]);
//!
//! // Segmented sort: two lists, [0, 3) and [3, 5), of the caller's keys and payloads.
//! let keys: Vec<u32> = [2.0f32, -1.0, 0.5, 9.0, 4.0].iter().map(|k| k.to_bits()).collect();
//! let payloads = [0u32, 1, 2, 3, 4];
//! let segments = [0u32, 3, 3, 2];
//! let [seg, keys_in, values_in, keys_out, values_out] =
//!     ["segments", "keys", "payloads", "sorted keys", "sorted payloads"].map(|label| backend.create_buffer(5, label).unwrap());
//! backend.write_buffer(seg, 0, &segments)?;
//! for (buffer, words) in [(keys_in, &keys), (keys_out, &keys)] {
//!     backend.write_buffer(buffer, 0, words)?;
//! }
//! for buffer in [values_in, values_out] {
//!     backend.write_buffer(buffer, 0, &payloads)?;
//! }
//! let sort = SegmentedSort::new(&mut backend, 2, 5, 3)?; // lists, elements, longest list
//! sort.record(&mut backend, seg, 2, keys_in, values_in, keys_out, values_out)?;
//! backend.submit()?;
//! let sorted: Vec<f32> = backend.read_buffer(keys_out, 0, 5)?.into_iter().map(f32::from_bits).collect();
//! assert_eq!(sorted, [-1.0, 0.5, 2.0, 4.0, 9.0]);
//! assert_eq!(backend.read_buffer(values_out, 0, 5)?, [1, 2, 0, 4, 3]);
//!
//! sort.destroy(&mut backend);
//! scan.destroy(&mut backend);
//! for buffer in [data, seg, keys_in, values_in, keys_out, values_out] {
//!     backend.destroy_buffer(buffer);
//! }
//! # Ok(())
//! # }
//! ```

pub mod scan;
pub mod sort;
