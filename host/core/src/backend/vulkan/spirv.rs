//! What the backend reads from the SPIR-V module's header instructions: the capabilities it declares
//! (which device features must be enabled) and its entry point names.

/// Capabilities the backend knows how to enable (SPIR-V `Capability` operands).
pub(super) mod cap {
    pub const FLOAT64: u32 = 10;
    pub const INT64: u32 = 11;
    pub const INT16: u32 = 22;
    pub const INT8: u32 = 39;
    pub const VULKAN_MEMORY_MODEL: u32 = 5345;
    pub const VULKAN_MEMORY_MODEL_DEVICE_SCOPE: u32 = 5346;
    /// The capabilities above: each needs a device feature enabled at device creation.
    pub const NEEDS_FEATURE: [u32; 6] = [FLOAT64, INT64, INT16, INT8, VULKAN_MEMORY_MODEL, VULKAN_MEMORY_MODEL_DEVICE_SCOPE];
}

const OP_CAPABILITY: u32 = 17;
const OP_ENTRY_POINT: u32 = 15;
const OP_FUNCTION: u32 = 54;

#[derive(Clone, Debug, Default)]
pub(super) struct ModuleInfo {
    pub capabilities: Vec<u32>,
    pub entry_points: Vec<String>,
}

impl ModuleInfo {
    /// Scans the instructions up to the first function (capabilities and entry points come first).
    pub fn parse(words: &[u32]) -> Self {
        let mut info = ModuleInfo::default();
        let mut i = 5; // past the header
        while let Some(&first) = words.get(i) {
            let (op, len) = (first & 0xffff, (first >> 16) as usize);
            let Some(operands) = words.get(i + 1..i + len.max(1)) else { break };
            match op {
                OP_CAPABILITY => info.capabilities.extend(operands.first()),
                // Execution model, function id, then the name as a NUL-terminated string.
                OP_ENTRY_POINT if operands.len() > 2 => {
                    let bytes: Vec<u8> = operands[2..].iter().flat_map(|w| w.to_le_bytes()).collect();
                    let end = bytes.iter().position(|&b| b == 0).unwrap_or(bytes.len());
                    info.entry_points.push(String::from_utf8_lossy(&bytes[..end]).into_owned());
                }
                OP_FUNCTION => break,
                _ => {}
            }
            i += len.max(1);
        }
        info
    }

    pub fn has(&self, capability: u32) -> bool {
        self.capabilities.contains(&capability)
    }

    /// The module's name for a kernel's entry: the name itself, or else the one entry point that
    /// is that name qualified by a module path (rust-gpu names entry points `module::function`).
    pub fn resolve(&self, entry: &str) -> Option<&str> {
        if let Some(e) = self.entry_points.iter().find(|e| *e == entry) {
            return Some(e);
        }
        let suffix = format!("::{entry}");
        let mut qualified = self.entry_points.iter().filter(|e| e.ends_with(&suffix));
        match (qualified.next(), qualified.next()) {
            (Some(e), None) => Some(e),
            _ => None,
        }
    }
}

/// Every kernel module's SPIR-V words, by the name the build gave it.
fn modules() -> impl Iterator<Item = (&'static str, Vec<u32>)> {
    crate::shaders::MODULES
        .iter()
        .map(|(name, bytes)| (*name, bytes.as_chunks::<4>().0.iter().map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect()))
}

/// The capabilities of all kernel modules together (what the device must support).
pub(super) fn all_capabilities() -> ModuleInfo {
    let mut all = ModuleInfo::default();
    for (_, words) in modules() {
        for c in ModuleInfo::parse(&words).capabilities {
            if !all.capabilities.contains(&c) {
                all.capabilities.push(c);
            }
        }
    }
    all
}

/// The module holding a kernel's entry point, and that entry point's name inside it.
pub(super) fn kernel_module(entry: &str) -> Option<(Vec<u32>, String)> {
    let words = crate::shaders::module_words(entry).or_else(|| {
        // rust-gpu may name entries by their module path (`scan::scan_block`).
        let suffix = format!("::{entry}");
        let mut qualified = modules().filter(|(name, _)| name.ends_with(&suffix));
        match (qualified.next(), qualified.next()) {
            (Some((_, words)), None) => Some(words),
            _ => None,
        }
    })?;
    let name = ModuleInfo::parse(&words).resolve(entry)?.to_string();
    Some((words, name))
}
