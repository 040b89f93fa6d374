//! The host memory a piece of work will need, against what the machine has free: refused before
//! the work starts, with both figures, rather than aborted part way when an allocation fails.

use crate::error::{Error, Result};

/// The memory the machine has free for new allocations, where the system says; `None` elsewhere.
pub use dof_core::host_memory::available;

/// Refuses `what`, which needs about `needed` bytes, where that is more than `free` (where the
/// system says: `None` skips the check).
pub fn check_fits(what: &str, needed: u128, free: Option<u64>) -> Result<()> {
    match free {
        Some(free) if needed > free as u128 => Err(Error::invalid(format!(
            "{what} needs about {:.1} GiB of memory, and this machine has {:.1} GiB free; refused before starting",
            needed as f64 / (1u64 << 30) as f64,
            free as f64 / (1u64 << 30) as f64
        ))),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn work_needing_more_memory_than_is_free_is_refused() {
        let e = check_fits("decoding big.exr", 18 << 30, Some(16 << 30)).unwrap_err().to_string();
        assert!(e.contains("decoding big.exr needs about 18.0 GiB") && e.contains("16.0 GiB free"), "{e}");
        assert!(check_fits("x", 1 << 30, Some(16 << 30)).is_ok());
        assert!(check_fits("x", u128::MAX, None).is_ok(), "no figure from the system: no check");
        if cfg!(target_os = "linux") {
            assert!(available().is_some_and(|b| b > 0));
        }
    }
}
