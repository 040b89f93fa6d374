//! Buffers and their memory, through gpu-allocator: the device-local storage buffers the kernels use
//! and the host-visible staging buffers `write_buffer`/`read_buffer` copy through. The allocator is
//! shared (`Arc<Mutex<_>>`) so a caller's own allocator can serve the backend too.

use crate::error::{Error, Result, VkContext};
use ash::vk;
use gpu_allocator::MemoryLocation;
use gpu_allocator::vulkan::{Allocation, AllocationCreateDesc, AllocationScheme, Allocator};
use std::sync::{Arc, Mutex};

/// The allocator the backend allocates from: its own, or the caller's.
pub type SharedAllocator = Arc<Mutex<Allocator>>;

/// Largest staging buffer; bigger transfers go through it in pieces.
pub(super) const STAGING_CHUNK_BYTES: u64 = 64 << 20;

/// Every use a storage buffer may see: kernels, fills and copies, and indirect dispatch arguments.
pub(super) const STORAGE_USAGE: vk::BufferUsageFlags = vk::BufferUsageFlags::from_raw(
    vk::BufferUsageFlags::STORAGE_BUFFER.as_raw()
        | vk::BufferUsageFlags::TRANSFER_SRC.as_raw()
        | vk::BufferUsageFlags::TRANSFER_DST.as_raw()
        | vk::BufferUsageFlags::INDIRECT_BUFFER.as_raw(),
);

pub(super) struct GpuBuffer {
    pub buffer: vk::Buffer,
    /// `None` only after `destroy` took it.
    allocation: Option<Allocation>,
    pub bytes: u64,
}

impl GpuBuffer {
    pub fn new(
        device: &ash::Device,
        allocator: &mut Allocator,
        bytes: u64,
        usage: vk::BufferUsageFlags,
        location: MemoryLocation,
        name: &str,
    ) -> Result<Self> {
        let info = vk::BufferCreateInfo::default().size(bytes).usage(usage).sharing_mode(vk::SharingMode::EXCLUSIVE);
        // SAFETY: a valid create info on a live device; on every later failure the buffer is destroyed.
        unsafe {
            let buffer = device.create_buffer(&info, None).vk("vkCreateBuffer")?;
            let requirements = device.get_buffer_memory_requirements(buffer);
            let desc = AllocationCreateDesc {
                name,
                requirements,
                location,
                linear: true,
                allocation_scheme: AllocationScheme::GpuAllocatorManaged,
            };
            let allocation = match allocator.allocate(&desc) {
                Ok(a) => a,
                Err(e) => {
                    device.destroy_buffer(buffer, None);
                    return Err(Error::Allocation(e.to_string()));
                }
            };
            if let Err(result) = device.bind_buffer_memory(buffer, allocation.memory(), allocation.offset()) {
                let _ = allocator.free(allocation);
                device.destroy_buffer(buffer, None);
                return Err(Error::Vulkan { call: "vkBindBufferMemory", result });
            }
            Ok(GpuBuffer { buffer, allocation: Some(allocation), bytes })
        }
    }

    /// Destroys the buffer and frees its memory. The GPU must be done with it.
    pub fn destroy(mut self, device: &ash::Device, allocator: &mut Allocator) {
        // SAFETY: the caller guarantees no pending work uses the buffer.
        unsafe { device.destroy_buffer(self.buffer, None) };
        if let Some(allocation) = self.allocation.take() {
            // Freeing only fails for an allocation the allocator does not know, which cannot happen here.
            let _ = allocator.free(allocation);
        }
    }

    /// The mapped bytes of a host-visible buffer.
    pub fn mapped(&mut self) -> Result<&mut [u8]> {
        let bytes = self.bytes as usize;
        self.allocation
            .as_mut()
            .and_then(|a| a.mapped_slice_mut())
            .and_then(|s| s.get_mut(..bytes))
            .ok_or_else(|| Error::Allocation("staging memory is not host-mapped".into()))
    }
}

/// A storage buffer as the backend tracks it: one it made, or one the caller imported.
pub(super) struct StorageBuffer {
    pub handle: vk::Buffer,
    pub words: u64,
    /// The buffer and memory the backend owns; `None` for an imported buffer, which it never frees.
    pub owned: Option<GpuBuffer>,
    pub label: String,
}

/// A host-visible buffer kept between transfers and grown on demand.
pub(super) struct Staging {
    pub location: MemoryLocation,
    pub buffer: Option<GpuBuffer>,
}

impl Staging {
    pub fn new(location: MemoryLocation) -> Self {
        Staging { location, buffer: None }
    }

    /// A staging buffer of at least `bytes` (at most [`STAGING_CHUNK_BYTES`] is ever asked for).
    pub fn get(&mut self, device: &ash::Device, allocator: &mut Allocator, bytes: u64) -> Result<&mut GpuBuffer> {
        if self.buffer.as_ref().is_some_and(|b| b.bytes < bytes)
            && let Some(old) = self.buffer.take()
        {
            old.destroy(device, allocator);
        }
        if self.buffer.is_none() {
            // Powers of two from 64 KiB, so a run of growing transfers reallocates only a few times.
            let size = bytes.next_power_of_two().clamp(64 << 10, STAGING_CHUNK_BYTES.max(bytes));
            let usage = match self.location {
                MemoryLocation::CpuToGpu => vk::BufferUsageFlags::TRANSFER_SRC,
                _ => vk::BufferUsageFlags::TRANSFER_DST,
            };
            self.buffer = Some(GpuBuffer::new(device, allocator, size, usage, self.location, "staging")?);
        }
        self.buffer.as_mut().ok_or_else(|| Error::Allocation("staging buffer missing".into()))
    }

    pub fn destroy(&mut self, device: &ash::Device, allocator: &mut Allocator) {
        if let Some(b) = self.buffer.take() {
            b.destroy(device, allocator);
        }
    }
}
