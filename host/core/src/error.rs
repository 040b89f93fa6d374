//! Errors of the core. Nothing on a user-reachable path panics: every failure is one of these. A
//! caller matches on the kind (a frame that needs a larger context, an invalid lens, a context on
//! the wrong backend, a call the recording state does not allow, a resource beyond a limit) and
//! shows the message as it is. (The crate `dof` above wraps them with its own: scene files and
//! plots.)

use thiserror::Error;

#[derive(Debug, Error)]
#[non_exhaustive]
pub enum Error {
    #[error(
        "no usable Vulkan driver: {0}\n  hint: install a Vulkan driver; on Debian/Ubuntu without a GPU, \
         `apt-get install mesa-vulkan-drivers` provides lavapipe (a CPU Vulkan device). \
         The CPU backend (`--backend cpu`) works without Vulkan."
    )]
    NoVulkan(String),
    #[error("the Khronos validation layer was requested but is not installed\n  hint: `apt-get install vulkan-validationlayers`")]
    NoValidationLayer,
    #[cfg(feature = "vulkan")]
    #[error("Vulkan call {call} failed: {result}")]
    Vulkan { call: &'static str, result: ash::vk::Result },
    /// No device of the kind asked for (the wgpu backend: no adapter, or one without a feature the
    /// kernels need).
    #[cfg(feature = "wgpu")]
    #[error("no usable device: {0}")]
    NoDevice(String),
    /// The device reported an error (the wgpu backend: a validation error, a lost device).
    #[cfg(feature = "wgpu")]
    #[error("device error: {0}")]
    Device(String),
    #[error("GPU memory allocation failed: {0}")]
    Allocation(String),
    #[error("kernel `{kernel}` faulted on the CPU backend (an out-of-bounds access): {message}")]
    KernelFault { kernel: &'static str, message: String },
    /// A buffer the backend's memory budget ([`crate::backend::Backend::set_memory_budget`]) has
    /// no room for: nothing was allocated.
    #[error("out of device memory: `{what}` needs {requested} bytes with {held} held, beyond the budget of {budget} bytes")]
    OutOfMemory { what: String, requested: u64, held: u64, budget: u64 },
    #[error("{what} is too large: {size} exceeds the limit {limit}")]
    TooLarge { what: String, size: u64, limit: u64 },
    /// A host allocation the machine refused: nothing was allocated.
    #[error("out of host memory: {what} needs {bytes} bytes, which this machine could not allocate")]
    HostMemory { what: String, bytes: u64 },
    /// A frame larger than the context was made for: resize the context
    /// ([`crate::frame::DofContext::resize`]) between frames, or make it for the largest frame.
    #[error("a {frame} frame exceeds the context's {context} (resize the context)")]
    ResizeNeeded { frame: crate::extent::Extent, context: crate::extent::Extent },
    /// A lens the kernels cannot evaluate (see [`crate::lens`]).
    #[error("invalid lens: {0}")]
    InvalidLens(String),
    /// A context, recording or resource handed to another backend than the one that made it.
    #[error("{0}")]
    WrongBackend(String),
    /// A call the backend's recording state does not allow: a frame outside the caller's command
    /// buffer on a caller's device, or a submission, transfer or allocation inside it.
    #[error("{0}")]
    RecordingState(String),
    #[error("invalid argument: {0}")]
    InvalidArgument(String),
}

pub type Result<T> = std::result::Result<T, Error>;

/// Turns a failed ash call into an [`Error::Vulkan`] naming the call.
#[cfg(feature = "vulkan")]
pub(crate) trait VkContext<T> {
    fn vk(self, call: &'static str) -> Result<T>;
}

#[cfg(feature = "vulkan")]
impl<T> VkContext<T> for std::result::Result<T, ash::vk::Result> {
    fn vk(self, call: &'static str) -> Result<T> {
        self.map_err(|result| Error::Vulkan { call, result })
    }
}

/// `n` copies of `value` in a new vector, or [`Error::HostMemory`] where the allocation fails:
/// for sizes that come from input, so a size the machine cannot hold is an error, not an abort.
pub fn filled<T: Clone>(n: usize, value: T, what: &str) -> Result<Vec<T>> {
    let mut v = Vec::new();
    let bytes = (n as u64).saturating_mul(std::mem::size_of::<T>() as u64);
    v.try_reserve_exact(n).map_err(|_| Error::HostMemory { what: what.to_string(), bytes })?;
    v.resize(n, value);
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_allocation_beyond_the_machine_is_an_error() {
        match filled(usize::MAX / 4, 0u64, "a test buffer") {
            Err(Error::HostMemory { what, bytes }) => assert!(what == "a test buffer" && bytes == u64::MAX, "{what} {bytes}"),
            other => panic!("{:?}", other.map(|v| v.len())),
        }
        assert_eq!(filled(3, 7u8, "small").unwrap(), vec![7, 7, 7]);
    }
}
