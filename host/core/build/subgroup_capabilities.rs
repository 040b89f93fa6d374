//! A SPIR-V pass that drops the subgroup capabilities from the modules that use no subgroup
//! instruction or built-in.
//!
//! rust-gpu declares a capability in every module of a build, and the kernels' build enables
//! `GroupNonUniform`, `GroupNonUniformArithmetic` and `GroupNonUniformShuffleRelative` for the entry points that scan in subgroups
//! (`KernelDesc::subgroup_entry`). A device without subgroup arithmetic refuses a module that
//! declares them, used or not, so the other modules must not.

use rspirv::spirv::{BuiltIn, Capability, Decoration, Op};

/// The capabilities this pass manages.
const SUBGROUP: [Capability; 3] =
    [Capability::GroupNonUniform, Capability::GroupNonUniformArithmetic, Capability::GroupNonUniformShuffleRelative];

/// The built-ins that need `GroupNonUniform`.
const SUBGROUP_BUILT_INS: [BuiltIn; 4] =
    [BuiltIn::SubgroupSize, BuiltIn::NumSubgroups, BuiltIn::SubgroupId, BuiltIn::SubgroupLocalInvocationId];

/// `words` without its `OpCapability` instructions for the subgroup capabilities when no
/// instruction of it is a group operation (`OpGroupNonUniform*`) and nothing is decorated with a
/// subgroup built-in; `words` unchanged otherwise. Word-level, so nothing else of the module moves.
pub fn drop_unused_subgroup_capabilities(words: &[u32]) -> Result<Vec<u32>, String> {
    const HEADER: usize = 5;
    let mut uses_subgroups = false;
    let mut at = HEADER;
    let mut spans = Vec::new();
    while at < words.len() {
        let count = (words[at] >> 16) as usize;
        let opcode = words[at] & 0xffff;
        if count == 0 || at + count > words.len() {
            return Err(format!("a malformed instruction at word {at}"));
        }
        let operands = &words[at + 1..at + count];
        if (Op::GroupNonUniformElect as u32..=Op::GroupNonUniformQuadSwap as u32).contains(&opcode) {
            uses_subgroups = true;
        }
        if opcode == Op::Decorate as u32
            && operands.get(1) == Some(&(Decoration::BuiltIn as u32))
            && operands.get(2).is_some_and(|b| SUBGROUP_BUILT_INS.iter().any(|s| *s as u32 == *b))
        {
            uses_subgroups = true;
        }
        if opcode == Op::Capability as u32 && operands.first().is_some_and(|c| SUBGROUP.iter().any(|s| *s as u32 == *c)) {
            spans.push(at..at + count);
        }
        at += count;
    }
    if uses_subgroups {
        return Ok(words.to_vec());
    }
    let mut out = Vec::with_capacity(words.len());
    let mut from = 0;
    for span in spans {
        out.extend_from_slice(&words[from..span.start]);
        from = span.end;
    }
    out.extend_from_slice(&words[from..]);
    Ok(out)
}
