//! What the machine's memory holds, where the system says (`/proc/meminfo` on Linux; `None`
//! elsewhere): sizes from input are refused against these before anything is allocated.

use std::sync::OnceLock;

/// One `/proc/meminfo` field (given in KiB there), in bytes.
fn meminfo_bytes(key: &str) -> Option<u64> {
    let info = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = info.lines().find(|l| l.split(':').next() == Some(key))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    kib.checked_mul(1024)
}

/// The memory free for new allocations now: the machine's (`MemAvailable`), or less where the
/// process's address space is limited (`ulimit -v`: the limit less what the process has mapped).
pub fn available() -> Option<u64> {
    available_beside(0)
}

/// [`available`] where the process has `reserved` bytes allocated but not yet touched (zeroed
/// buffers the kernel has not backed yet): they will take that much of the machine's free memory,
/// while the address-space limit counts them already.
pub fn available_beside(reserved: u64) -> Option<u64> {
    let free = meminfo_bytes("MemAvailable")?.saturating_sub(reserved);
    Some(address_space_left().map_or(free, |left| free.min(left)))
}

/// What the address-space limit (`RLIMIT_AS`, from `/proc/self/limits`) leaves beyond what the
/// process has mapped (`VmSize`); `None` where there is no limit.
fn address_space_left() -> Option<u64> {
    let limits = std::fs::read_to_string("/proc/self/limits").ok()?;
    let line = limits.lines().find(|l| l.starts_with("Max address space"))?;
    let limit: u64 = line.trim_start_matches("Max address space").split_whitespace().next()?.parse().ok()?;
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let mapped_kib: u64 = status.lines().find(|l| l.starts_with("VmSize:"))?.split_whitespace().nth(1)?.parse().ok()?;
    Some(limit.saturating_sub(mapped_kib.saturating_mul(1024)))
}

/// All the memory the machine has, RAM and swap: no allocation larger can ever be backed. It is
/// checked before allocating because an overcommitting kernel grants such an allocation and then
/// kills the process when its pages are first touched.
pub fn installed() -> Option<u64> {
    static INSTALLED: OnceLock<Option<u64>> = OnceLock::new();
    *INSTALLED.get_or_init(|| meminfo_bytes("MemTotal")?.checked_add(meminfo_bytes("SwapTotal").unwrap_or(0)))
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_system_says_on_linux() {
        if cfg!(target_os = "linux") {
            let (free, all) = (super::available(), super::installed());
            assert!(free.is_some_and(|f| f > 0) && all.is_some_and(|a| a >= free.unwrap_or(0)), "{free:?} {all:?}");
        }
        assert_eq!(super::meminfo_bytes("NoSuchField"), None);
    }
}
