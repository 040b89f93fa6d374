//! The "GPU shape" of a kernel, read statically from its SPIR-V words without a GPU: counts that
//! predict performance problems before a kernel runs (per-invocation arrays that spill to local
//! memory when indexed at run time, workgroup memory that limits occupancy, barriers, integer
//! divisions, the bounds checks rust-gpu emits on storage-buffer slices).
//!
//! Only the binary layout of the SPIR-V specification is read (the header, then instructions of
//! `word count << 16 | opcode`); malformed input is an `Err`, never a panic.

use std::collections::{HashMap, HashSet};
use std::fmt::Write as _;

/// The first word of every SPIR-V module (in the module's own byte order).
const MAGIC: u32 = 0x0723_0203;
/// Magic, version, generator, id bound, schema.
const HEADER_WORDS: usize = 5;
/// An instruction's first word holds its word count in the high half and its opcode in the low.
const WORD_COUNT_SHIFT: u32 = 16;
const OPCODE_MASK: u32 = 0xFFFF;

// Opcodes (SPIR-V specification, section 3.52; numbers checked against SPIRV-Headers' unified1).
const OP_ENTRY_POINT: u32 = 15;
const OP_TYPE_BOOL: u32 = 20;
const OP_TYPE_INT: u32 = 21;
const OP_TYPE_FLOAT: u32 = 22;
const OP_TYPE_VECTOR: u32 = 23;
const OP_TYPE_MATRIX: u32 = 24;
const OP_TYPE_ARRAY: u32 = 28;
const OP_TYPE_RUNTIME_ARRAY: u32 = 29;
const OP_TYPE_STRUCT: u32 = 30;
const OP_TYPE_POINTER: u32 = 32;
const OP_CONSTANT_TRUE: u32 = 41;
const OP_CONSTANT_FALSE: u32 = 42;
const OP_CONSTANT: u32 = 43;
const OP_CONSTANT_COMPOSITE: u32 = 44;
const OP_CONSTANT_NULL: u32 = 46;
const OP_SPEC_CONSTANT_TRUE: u32 = 48;
const OP_SPEC_CONSTANT_FALSE: u32 = 49;
const OP_SPEC_CONSTANT: u32 = 50;
const OP_SPEC_CONSTANT_COMPOSITE: u32 = 51;
const OP_SPEC_CONSTANT_OP: u32 = 52;
const OP_FUNCTION: u32 = 54;
const OP_FUNCTION_PARAMETER: u32 = 55;
const OP_FUNCTION_END: u32 = 56;
const OP_FUNCTION_CALL: u32 = 57;
const OP_VARIABLE: u32 = 59;
const OP_ACCESS_CHAIN: u32 = 65;
const OP_IN_BOUNDS_ACCESS_CHAIN: u32 = 66;
const OP_PTR_ACCESS_CHAIN: u32 = 67;
const OP_ARRAY_LENGTH: u32 = 68;
const OP_IN_BOUNDS_PTR_ACCESS_CHAIN: u32 = 70;
const OP_COPY_OBJECT: u32 = 83;
const OP_U_DIV: u32 = 134;
const OP_S_DIV: u32 = 135;
const OP_U_MOD: u32 = 137;
const OP_S_REM: u32 = 138;
const OP_S_MOD: u32 = 139;
const OP_U_GREATER_THAN: u32 = 172;
const OP_U_GREATER_THAN_EQUAL: u32 = 174;
const OP_U_LESS_THAN: u32 = 176;
const OP_U_LESS_THAN_EQUAL: u32 = 178;
const OP_CONTROL_BARRIER: u32 = 224;
const OP_MEMORY_BARRIER: u32 = 225;
const OP_ATOMIC_LOAD: u32 = 227;
const OP_ATOMIC_XOR: u32 = 242;
const OP_LOOP_MERGE: u32 = 246;
const OP_ATOMIC_FLAG_TEST_AND_SET: u32 = 318;
const OP_ATOMIC_FLAG_CLEAR: u32 = 319;
const OP_GROUP_NON_UNIFORM_ELECT: u32 = 333;
const OP_GROUP_NON_UNIFORM_QUAD_SWAP: u32 = 366;
const OP_SUBGROUP_BALLOT_KHR: u32 = 4421;
const OP_SUBGROUP_FIRST_INVOCATION_KHR: u32 = 4422;
const OP_SUBGROUP_ALL_KHR: u32 = 4428;
const OP_SUBGROUP_READ_INVOCATION_KHR: u32 = 4432;
const OP_GROUP_NON_UNIFORM_QUAD_ALL_KHR: u32 = 5110;
const OP_GROUP_NON_UNIFORM_QUAD_ANY_KHR: u32 = 5111;
const OP_GROUP_NON_UNIFORM_PARTITION_NV: u32 = 5296;
const OP_ATOMIC_F_MIN_EXT: u32 = 5614;
const OP_ATOMIC_F_MAX_EXT: u32 = 5615;
const OP_ATOMIC_F_ADD_EXT: u32 = 6035;

// Storage classes.
const STORAGE_WORKGROUP: u32 = 4;
const STORAGE_FUNCTION: u32 = 7;

// Type sizes (no padding: an estimate of per-invocation and per-workgroup memory, not a layout).
const BITS_PER_BYTE: u32 = 8;
const BOOL_BYTES: u32 = 4;
const POINTER_BYTES: u32 = 8;

/// Instructions whose result is known at pipeline creation: an index that is one of them does not
/// force an array into indexable (local) memory.
const CONSTANT_OPCODES: [u32; 10] = [
    OP_CONSTANT_TRUE,
    OP_CONSTANT_FALSE,
    OP_CONSTANT,
    OP_CONSTANT_COMPOSITE,
    OP_CONSTANT_NULL,
    OP_SPEC_CONSTANT_TRUE,
    OP_SPEC_CONSTANT_FALSE,
    OP_SPEC_CONSTANT,
    OP_SPEC_CONSTANT_COMPOSITE,
    OP_SPEC_CONSTANT_OP,
];

/// The integer divisions and remainders: tens of instructions each on most GPUs.
const INTEGER_DIVISIONS: [u32; 5] = [OP_U_DIV, OP_S_DIV, OP_U_MOD, OP_S_REM, OP_S_MOD];

/// The unsigned comparisons rust-gpu emits for slice bounds checks (`index < len`).
const UNSIGNED_COMPARISONS: [u32; 4] = [OP_U_LESS_THAN, OP_U_LESS_THAN_EQUAL, OP_U_GREATER_THAN, OP_U_GREATER_THAN_EQUAL];

/// Static GPU-relevant counts of one SPIR-V module.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct KernelShape {
    /// The name of the module's first `OpEntryPoint` (empty when it has none).
    pub entry: String,
    /// Module size in words, header included.
    pub words: usize,
    /// Instructions inside function bodies, `OpFunction` to `OpFunctionEnd` inclusive.
    pub instructions: usize,
    pub functions: usize,
    /// `OpVariable`s in the Function storage class: per-invocation private memory.
    pub function_vars: usize,
    /// Their pointee sizes summed over every function of the module: an upper bound per invocation.
    pub function_bytes: u32,
    /// The Function variables whose type contains an array (at any depth of structs and arrays).
    pub function_arrays: usize,
    pub function_array_bytes: u32,
    /// Access chains into Function memory with a non-constant index: these arrays cannot live in
    /// registers and go to (slow) local memory.
    pub runtime_indexed: usize,
    /// Shared memory per workgroup, which limits how many workgroups fit on a multiprocessor.
    pub workgroup_bytes: u32,
    pub barriers: usize,
    pub memory_barriers: usize,
    pub integer_divisions: usize,
    /// Those whose divisor is not a constant: a driver turns a division by a constant into a
    /// multiply and shifts, but a division by a run-time value stays a long sequence.
    pub runtime_divisions: usize,
    pub subgroup_ops: usize,
    pub atomics: usize,
    /// Unsigned comparisons against an `OpArrayLength`: rust-gpu's storage-buffer bounds checks.
    pub bounds_checks: usize,
    pub loops: usize,
    pub calls: usize,
}

impl KernelShape {
    /// One JSON object whose keys are the field names (the crate has no serde).
    pub fn to_json(&self) -> String {
        let counts: [(&str, u64); 18] = [
            ("words", self.words as u64),
            ("instructions", self.instructions as u64),
            ("functions", self.functions as u64),
            ("function_vars", self.function_vars as u64),
            ("function_bytes", u64::from(self.function_bytes)),
            ("function_arrays", self.function_arrays as u64),
            ("function_array_bytes", u64::from(self.function_array_bytes)),
            ("runtime_indexed", self.runtime_indexed as u64),
            ("workgroup_bytes", u64::from(self.workgroup_bytes)),
            ("barriers", self.barriers as u64),
            ("memory_barriers", self.memory_barriers as u64),
            ("integer_divisions", self.integer_divisions as u64),
            ("runtime_divisions", self.runtime_divisions as u64),
            ("subgroup_ops", self.subgroup_ops as u64),
            ("atomics", self.atomics as u64),
            ("bounds_checks", self.bounds_checks as u64),
            ("loops", self.loops as u64),
            ("calls", self.calls as u64),
        ];
        let mut json = format!("{{\"entry\":{}", json_string(&self.entry));
        for (key, value) in counts {
            let _ = write!(json, ",\"{key}\":{value}");
        }
        json.push('}');
        json
    }
}

/// A JSON string literal: quotes, backslashes and control characters escaped.
fn json_string(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if u32::from(c) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", u32::from(c));
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// Reads the shape of the module `words` (in host byte order, as `vkCreateShaderModule` takes them).
pub fn analyze(words: &[u32]) -> Result<KernelShape, String> {
    let instructions = decode(words)?;
    let facts = ModuleFacts::collect(&instructions)?;
    let mut counter = Counter {
        facts: &facts,
        shape: KernelShape { entry: facts.entry.clone().unwrap_or_default(), words: words.len(), ..Default::default() },
        function_pointers: HashSet::new(),
        in_function: false,
    };
    for instruction in &instructions {
        counter.visit(instruction)?;
    }
    Ok(counter.shape)
}

/// One instruction: its opcode and the words after the first.
struct Instruction<'a> {
    /// Word offset in the module, for error messages.
    offset: usize,
    opcode: u32,
    operands: &'a [u32],
}

impl Instruction<'_> {
    /// Operand `index`, or an error naming the instruction when it is too short.
    fn operand(&self, index: usize) -> Result<u32, String> {
        self.operands.get(index).copied().ok_or_else(|| {
            format!(
                "instruction with opcode {} at word {} has {} operand words, needs more than {index}",
                self.opcode,
                self.offset,
                self.operands.len()
            )
        })
    }

    /// Operands from `index` on (empty when there are fewer).
    fn operands_from(&self, index: usize) -> &[u32] {
        self.operands.get(index..).unwrap_or(&[])
    }
}

/// Splits the module after its header into instructions, checking the magic and every word count.
fn decode(words: &[u32]) -> Result<Vec<Instruction<'_>>, String> {
    if words.len() < HEADER_WORDS {
        return Err(format!("{} words is shorter than the SPIR-V header ({HEADER_WORDS} words)", words.len()));
    }
    if words[0] != MAGIC {
        return Err(if words[0] == MAGIC.swap_bytes() {
            "SPIR-V magic number is byte-swapped: the words are in the wrong byte order".to_string()
        } else {
            format!("not SPIR-V: magic number {:#010x}, expected {MAGIC:#010x}", words[0])
        });
    }
    let mut instructions = Vec::new();
    let mut offset = HEADER_WORDS;
    while offset < words.len() {
        let first = words[offset];
        let count = (first >> WORD_COUNT_SHIFT) as usize;
        if count == 0 {
            return Err(format!("instruction at word {offset} has a word count of 0"));
        }
        let Some(body) = words.get(offset + 1..offset + count) else {
            return Err(format!("instruction at word {offset} needs {count} words, {} remain", words.len() - offset));
        };
        instructions.push(Instruction { offset, opcode: first & OPCODE_MASK, operands: body });
        offset += count;
    }
    Ok(instructions)
}

/// What a type occupies and holds, computed when it is declared (its operands are declared before
/// it, so one forward pass suffices and a malformed cycle cannot recurse).
#[derive(Clone, Copy, Debug, Default)]
struct TypeInfo {
    bytes: u32,
    has_array: bool,
    /// `(storage class, pointee type)` for an `OpTypePointer`.
    pointer: Option<(u32, u32)>,
}

/// Module-wide facts the counting pass looks up: types, constants, array lengths, the entry name.
#[derive(Default)]
struct ModuleFacts {
    types: HashMap<u32, TypeInfo>,
    /// Values of scalar `OpConstant`/`OpSpecConstant` results, for array lengths.
    constant_values: HashMap<u32, u32>,
    /// Results of every constant-defining instruction.
    constants: HashSet<u32>,
    /// Results of `OpArrayLength`, collected up front because a comparison may precede the
    /// definition in word order (blocks need not be in execution order).
    array_lengths: HashSet<u32>,
    entry: Option<String>,
}

impl ModuleFacts {
    fn collect(instructions: &[Instruction]) -> Result<Self, String> {
        let mut facts = Self::default();
        for instruction in instructions {
            facts.record(instruction)?;
        }
        Ok(facts)
    }

    fn record(&mut self, instruction: &Instruction) -> Result<(), String> {
        let opcode = instruction.opcode;
        if opcode == OP_ENTRY_POINT && self.entry.is_none() {
            self.entry = Some(literal_string(instruction.operands_from(2)));
        } else if opcode == OP_ARRAY_LENGTH {
            self.array_lengths.insert(instruction.operand(1)?);
        } else if CONSTANT_OPCODES.contains(&opcode) {
            self.record_constant(instruction)?;
        } else if let Some(info) = self.type_info(instruction)? {
            self.types.insert(instruction.operand(0)?, info);
        }
        Ok(())
    }

    fn record_constant(&mut self, instruction: &Instruction) -> Result<(), String> {
        let id = instruction.operand(1)?;
        self.constants.insert(id);
        if matches!(instruction.opcode, OP_CONSTANT | OP_SPEC_CONSTANT) {
            self.constant_values.insert(id, constant_value(instruction.operands_from(2)));
        }
        Ok(())
    }

    /// The size and contents of a type declaration; `None` for other instructions.
    fn type_info(&self, instruction: &Instruction) -> Result<Option<TypeInfo>, String> {
        let leaf = |bytes| TypeInfo { bytes, ..TypeInfo::default() };
        let info = match instruction.opcode {
            OP_TYPE_BOOL => leaf(BOOL_BYTES),
            OP_TYPE_INT | OP_TYPE_FLOAT => leaf(instruction.operand(1)? / BITS_PER_BYTE),
            OP_TYPE_VECTOR | OP_TYPE_MATRIX => {
                let component = self.type_of(instruction.operand(1)?);
                TypeInfo { bytes: component.bytes.saturating_mul(instruction.operand(2)?), ..component }
            }
            OP_TYPE_ARRAY => {
                let element = self.type_of(instruction.operand(1)?);
                let length = self.constant_values.get(&instruction.operand(2)?).copied().unwrap_or(0);
                TypeInfo { bytes: element.bytes.saturating_mul(length), has_array: true, pointer: None }
            }
            OP_TYPE_RUNTIME_ARRAY => TypeInfo { has_array: true, ..TypeInfo::default() },
            OP_TYPE_STRUCT => self.struct_info(instruction.operands_from(1)),
            OP_TYPE_POINTER => TypeInfo { pointer: Some((instruction.operand(1)?, instruction.operand(2)?)), ..leaf(POINTER_BYTES) },
            _ => return Ok(None),
        };
        Ok(Some(info))
    }

    /// A struct's members laid end to end, without padding.
    fn struct_info(&self, members: &[u32]) -> TypeInfo {
        members.iter().map(|&member| self.type_of(member)).fold(TypeInfo::default(), |acc, member| TypeInfo {
            bytes: acc.bytes.saturating_add(member.bytes),
            has_array: acc.has_array || member.has_array,
            pointer: None,
        })
    }

    /// A declared type, or an empty one (0 bytes) for an unknown id.
    fn type_of(&self, id: u32) -> TypeInfo {
        self.types.get(&id).copied().unwrap_or_default()
    }

    /// The `(storage class, pointee)` of a pointer type id.
    fn pointer(&self, type_id: u32) -> Option<(u32, u32)> {
        self.types.get(&type_id).and_then(|info| info.pointer)
    }
}

/// A constant's value as a `u32`: the low word, saturated when a 64-bit value's high word is set.
fn constant_value(value_words: &[u32]) -> u32 {
    match value_words {
        [low] | [low, 0] => *low,
        [_, _, ..] => u32::MAX,
        [] => 0,
    }
}

/// A SPIR-V literal string: UTF-8 bytes packed little-endian into words, ending with a NUL.
fn literal_string(words: &[u32]) -> String {
    let bytes: Vec<u8> = words.iter().flat_map(|word| word.to_le_bytes()).take_while(|&byte| byte != 0).collect();
    String::from_utf8_lossy(&bytes).into_owned()
}

/// The counting pass, with the provenance of pointers into Function memory.
struct Counter<'a> {
    facts: &'a ModuleFacts,
    shape: KernelShape,
    /// Ids that point into Function memory: its variables, pointer parameters into it, access
    /// chains from and copies of those.
    function_pointers: HashSet<u32>,
    in_function: bool,
}

impl Counter<'_> {
    fn visit(&mut self, instruction: &Instruction) -> Result<(), String> {
        let opcode = instruction.opcode;
        if opcode == OP_FUNCTION {
            self.in_function = true;
            self.shape.functions += 1;
        }
        if self.in_function {
            self.shape.instructions += 1;
        }
        if opcode == OP_FUNCTION_END {
            self.in_function = false;
        }
        match opcode {
            OP_VARIABLE => self.variable(instruction)?,
            OP_FUNCTION_PARAMETER => self.parameter(instruction)?,
            OP_ACCESS_CHAIN | OP_IN_BOUNDS_ACCESS_CHAIN | OP_PTR_ACCESS_CHAIN | OP_IN_BOUNDS_PTR_ACCESS_CHAIN => {
                self.access_chain(instruction)?
            }
            OP_COPY_OBJECT => self.copy_object(instruction)?,
            _ => self.count_opcode(instruction)?,
        }
        Ok(())
    }

    /// Counts a Function or Workgroup variable with its pointee's size.
    fn variable(&mut self, instruction: &Instruction) -> Result<(), String> {
        let storage = instruction.operand(2)?;
        let pointee = self.facts.pointer(instruction.operand(0)?).map(|(_, pointee)| self.facts.type_of(pointee));
        let pointee = pointee.unwrap_or_default();
        let shape = &mut self.shape;
        if storage == STORAGE_WORKGROUP {
            shape.workgroup_bytes = shape.workgroup_bytes.saturating_add(pointee.bytes);
        } else if storage == STORAGE_FUNCTION {
            self.function_pointers.insert(instruction.operand(1)?);
            shape.function_vars += 1;
            shape.function_bytes = shape.function_bytes.saturating_add(pointee.bytes);
            if pointee.has_array {
                shape.function_arrays += 1;
                shape.function_array_bytes = shape.function_array_bytes.saturating_add(pointee.bytes);
            }
        }
        Ok(())
    }

    /// A parameter typed as a pointer into Function memory (a callee indexing its caller's array).
    fn parameter(&mut self, instruction: &Instruction) -> Result<(), String> {
        if self.facts.pointer(instruction.operand(0)?).is_some_and(|(storage, _)| storage == STORAGE_FUNCTION) {
            self.function_pointers.insert(instruction.operand(1)?);
        }
        Ok(())
    }

    /// An access chain from Function memory: its result points there too, and a non-constant index
    /// (the element operand of the pointer chains included) makes it runtime indexed.
    fn access_chain(&mut self, instruction: &Instruction) -> Result<(), String> {
        let base = instruction.operand(2)?;
        if self.function_pointers.contains(&base) {
            self.function_pointers.insert(instruction.operand(1)?);
            let indices = instruction.operands_from(3);
            if indices.iter().any(|index| !self.facts.constants.contains(index)) {
                self.shape.runtime_indexed += 1;
            }
        }
        Ok(())
    }

    fn copy_object(&mut self, instruction: &Instruction) -> Result<(), String> {
        if self.function_pointers.contains(&instruction.operand(2)?) {
            self.function_pointers.insert(instruction.operand(1)?);
        }
        Ok(())
    }

    /// The counts that depend only on the opcode (and, for bounds checks, the operands).
    fn count_opcode(&mut self, instruction: &Instruction) -> Result<(), String> {
        let opcode = instruction.opcode;
        let shape = &mut self.shape;
        match opcode {
            OP_CONTROL_BARRIER => shape.barriers += 1,
            OP_MEMORY_BARRIER => shape.memory_barriers += 1,
            OP_LOOP_MERGE => shape.loops += 1,
            OP_FUNCTION_CALL => shape.calls += 1,
            _ if INTEGER_DIVISIONS.contains(&opcode) => {
                shape.integer_divisions += 1;
                // OpUDiv result-type result dividend divisor
                if !self.facts.constants.contains(&instruction.operand(3)?) {
                    shape.runtime_divisions += 1;
                }
            }
            _ if is_subgroup_op(opcode) => shape.subgroup_ops += 1,
            _ if is_atomic(opcode) => shape.atomics += 1,
            _ if UNSIGNED_COMPARISONS.contains(&opcode) => {
                let operands = [instruction.operand(2)?, instruction.operand(3)?];
                if operands.iter().any(|id| self.facts.array_lengths.contains(id)) {
                    shape.bounds_checks += 1;
                }
            }
            _ => {}
        }
        Ok(())
    }
}

/// `OpGroupNonUniform*` and the KHR/NV subgroup instructions (not the untyped-pointer opcodes
/// 4423..=4427 that sit between them).
fn is_subgroup_op(opcode: u32) -> bool {
    matches!(
        opcode,
        OP_GROUP_NON_UNIFORM_ELECT..=OP_GROUP_NON_UNIFORM_QUAD_SWAP
            | OP_SUBGROUP_BALLOT_KHR
            | OP_SUBGROUP_FIRST_INVOCATION_KHR
            | OP_SUBGROUP_ALL_KHR..=OP_SUBGROUP_READ_INVOCATION_KHR
            | OP_GROUP_NON_UNIFORM_QUAD_ALL_KHR
            | OP_GROUP_NON_UNIFORM_QUAD_ANY_KHR
            | OP_GROUP_NON_UNIFORM_PARTITION_NV
    )
}

/// `OpAtomic*`: the core range, the flag operations and the float extensions.
fn is_atomic(opcode: u32) -> bool {
    (OP_ATOMIC_LOAD..=OP_ATOMIC_XOR).contains(&opcode)
        || matches!(
            opcode,
            OP_ATOMIC_FLAG_TEST_AND_SET | OP_ATOMIC_FLAG_CLEAR | OP_ATOMIC_F_MIN_EXT | OP_ATOMIC_F_MAX_EXT | OP_ATOMIC_F_ADD_EXT
        )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Hand-assembles a module: the header, then each instruction as its opcode and operands.
    fn module(instructions: &[(u32, &[u32])]) -> Vec<u32> {
        let mut words = vec![MAGIC, 0x0001_0500, 0, 100, 0];
        for (opcode, operands) in instructions {
            words.push(((operands.len() as u32 + 1) << WORD_COUNT_SHIFT) | opcode);
            words.extend_from_slice(operands);
        }
        words
    }

    const OP_TYPE_VOID: u32 = 19;
    const OP_TYPE_FUNCTION: u32 = 33;
    const OP_LABEL: u32 = 248;
    const OP_RETURN: u32 = 253;
    const OP_LOAD: u32 = 61;
    const GL_COMPUTE: u32 = 5;

    // Ids of the shared prologue.
    const VOID: u32 = 1;
    const FN_TYPE: u32 = 2;
    const UINT: u32 = 3;
    const C0: u32 = 4;
    const C16: u32 = 5;
    const ARRAY: u32 = 6;
    const PTR_FN_ARRAY: u32 = 7;
    const PTR_FN_UINT: u32 = 8;
    const PTR_WG_ARRAY: u32 = 9;
    const MAIN: u32 = 10;

    /// Types and constants: a `[u32; 16]` array with Function and Workgroup pointers to it, and
    /// the entry point "main" (b"main" packed little-endian, then the NUL word).
    fn prologue() -> Vec<(u32, Vec<u32>)> {
        vec![
            (OP_ENTRY_POINT, vec![GL_COMPUTE, MAIN, u32::from_le_bytes(*b"main"), 0]),
            (OP_TYPE_VOID, vec![VOID]),
            (OP_TYPE_FUNCTION, vec![FN_TYPE, VOID]),
            (OP_TYPE_INT, vec![UINT, 32, 0]),
            (OP_CONSTANT, vec![UINT, C0, 0]),
            (OP_CONSTANT, vec![UINT, C16, 16]),
            (OP_TYPE_ARRAY, vec![ARRAY, UINT, C16]),
            (OP_TYPE_POINTER, vec![PTR_FN_ARRAY, STORAGE_FUNCTION, ARRAY]),
            (OP_TYPE_POINTER, vec![PTR_FN_UINT, STORAGE_FUNCTION, UINT]),
            (OP_TYPE_POINTER, vec![PTR_WG_ARRAY, STORAGE_WORKGROUP, ARRAY]),
        ]
    }

    /// The prologue, then `main` with `body` between its label and return.
    fn kernel(globals: &[(u32, Vec<u32>)], body: &[(u32, Vec<u32>)]) -> Vec<u32> {
        let mut all = prologue();
        all.extend_from_slice(globals);
        all.push((OP_FUNCTION, vec![VOID, MAIN, 0, FN_TYPE]));
        all.push((OP_LABEL, vec![11]));
        all.extend_from_slice(body);
        all.push((OP_RETURN, vec![]));
        all.push((OP_FUNCTION_END, vec![]));
        let borrowed: Vec<(u32, &[u32])> = all.iter().map(|(op, operands)| (*op, operands.as_slice())).collect();
        module(&borrowed)
    }

    #[test]
    fn function_array_indexed_at_run_time_and_by_constant() {
        let (array, index, dynamic, fixed, copy, through_copy) = (20, 21, 22, 23, 24, 25);
        let words = kernel(
            &[],
            &[
                (OP_VARIABLE, vec![PTR_FN_ARRAY, array, STORAGE_FUNCTION]),
                (OP_ACCESS_CHAIN, vec![PTR_FN_UINT, fixed, array, C0]),
                (OP_LOAD, vec![UINT, index, fixed]),
                (OP_ACCESS_CHAIN, vec![PTR_FN_UINT, dynamic, array, index]),
                (OP_COPY_OBJECT, vec![PTR_FN_ARRAY, copy, array]),
                (OP_IN_BOUNDS_ACCESS_CHAIN, vec![PTR_FN_UINT, through_copy, copy, index]),
            ],
        );
        let shape = analyze(&words).unwrap();
        assert_eq!(shape.entry, "main");
        assert_eq!((shape.functions, shape.instructions), (1, 10));
        assert_eq!((shape.function_vars, shape.function_bytes), (1, 64));
        assert_eq!((shape.function_arrays, shape.function_array_bytes), (1, 64));
        assert_eq!(shape.runtime_indexed, 2, "the chain on the variable and the one through its copy");
    }

    #[test]
    fn workgroup_array_division_barrier_and_bounds_check() {
        let (shared, quotient, length, check, buffer, bool_type, ptr_wg_uint) = (20, 21, 22, 23, 24, 25, 26);
        let words = kernel(
            &[
                (OP_VARIABLE, vec![PTR_WG_ARRAY, shared, STORAGE_WORKGROUP]),
                (OP_TYPE_BOOL, vec![bool_type]),
                (OP_TYPE_POINTER, vec![ptr_wg_uint, STORAGE_WORKGROUP, UINT]),
            ],
            &[
                (OP_U_DIV, vec![UINT, quotient, C16, C16]),
                (OP_S_REM, vec![UINT, quotient + 10, C16, quotient]),
                (OP_CONTROL_BARRIER, vec![C16, C16, C16]),
                (OP_ARRAY_LENGTH, vec![UINT, length, buffer, 0]),
                (OP_U_LESS_THAN, vec![bool_type, check, quotient, length]),
                (OP_U_LESS_THAN, vec![bool_type, check + 10, quotient, C16]),
                (OP_ACCESS_CHAIN, vec![ptr_wg_uint, 30, shared, quotient]),
            ],
        );
        let shape = analyze(&words).unwrap();
        assert_eq!(shape.workgroup_bytes, 64);
        assert_eq!((shape.function_vars, shape.function_bytes), (0, 0));
        assert_eq!((shape.integer_divisions, shape.runtime_divisions), (2, 1), "one divides by a constant, one by a value");
        assert_eq!((shape.barriers, shape.memory_barriers), (1, 0));
        assert_eq!(shape.bounds_checks, 1, "only the comparison against the array length");
        assert_eq!(shape.runtime_indexed, 0, "workgroup memory is not Function memory");
    }

    #[test]
    fn nested_sizes_and_pointer_parameters() {
        let (u64_type, c2, vec4, matrix, inner, pair, outer, ptr_outer, ptr_to_ptr) = (20, 21, 22, 23, 24, 25, 26, 27, 28);
        let (callee_type, callee, parameter, element, scalar, plain, runtime_index) = (30, 31, 32, 33, 34, 35, 36);
        let words = kernel(
            &[
                (OP_TYPE_INT, vec![u64_type, 64, 0]),
                (OP_CONSTANT, vec![u64_type, c2, 2, 0]),
                (OP_TYPE_VECTOR, vec![vec4, UINT, 4]),
                (OP_TYPE_MATRIX, vec![matrix, vec4, 4]),
                // { u32, [u32; 16] } is 68 bytes; [that; 2] is 136; { [..; 2], mat4 } is 200.
                (OP_TYPE_STRUCT, vec![inner, UINT, ARRAY]),
                (OP_TYPE_ARRAY, vec![pair, inner, c2]),
                (OP_TYPE_STRUCT, vec![outer, pair, matrix]),
                (OP_TYPE_POINTER, vec![ptr_outer, STORAGE_FUNCTION, outer]),
                (OP_TYPE_POINTER, vec![ptr_to_ptr, STORAGE_FUNCTION, PTR_FN_UINT]),
                (OP_TYPE_FUNCTION, vec![callee_type, VOID, PTR_FN_ARRAY]),
                (OP_FUNCTION, vec![VOID, callee, 0, callee_type]),
                (OP_FUNCTION_PARAMETER, vec![PTR_FN_ARRAY, parameter]),
                (OP_LABEL, vec![40]),
                (OP_ACCESS_CHAIN, vec![PTR_FN_UINT, element, parameter, runtime_index]),
                (OP_RETURN, vec![]),
                (OP_FUNCTION_END, vec![]),
            ],
            &[
                (OP_VARIABLE, vec![ptr_outer, scalar, STORAGE_FUNCTION]),
                (OP_VARIABLE, vec![ptr_to_ptr, plain, STORAGE_FUNCTION]),
                (OP_FUNCTION_CALL, vec![VOID, 41, callee, scalar]),
            ],
        );
        let shape = analyze(&words).unwrap();
        assert_eq!(shape.functions, 2);
        assert_eq!(shape.calls, 1);
        assert_eq!(shape.function_vars, 2);
        assert_eq!(shape.function_bytes, 200 + 8);
        assert_eq!((shape.function_arrays, shape.function_array_bytes), (1, 200));
        assert_eq!(shape.runtime_indexed, 1, "the callee indexes its pointer parameter by a non-constant");
    }

    #[test]
    fn malformed_input_is_an_error() {
        let good = kernel(&[], &[]);
        assert!(analyze(&good).is_ok());
        assert!(analyze(&good[..3]).unwrap_err().contains("header"));
        let mut wrong_magic = good.clone();
        wrong_magic[0] = 0xDEAD_BEEF;
        assert!(analyze(&wrong_magic).unwrap_err().contains("magic"));
        wrong_magic[0] = MAGIC.swap_bytes();
        assert!(analyze(&wrong_magic).unwrap_err().contains("byte order"));
        assert!(analyze(&good[..good.len() - 3]).unwrap_err().contains("remain"));
        let mut zero_count = good.clone();
        zero_count.push(OP_RETURN);
        assert!(analyze(&zero_count).unwrap_err().contains("word count of 0"));
        let short_variable = module(&[(OP_VARIABLE, &[PTR_FN_ARRAY, 20])]);
        assert!(analyze(&short_variable).unwrap_err().contains("operand"));
    }

    #[test]
    fn json_has_every_field() {
        let shape = KernelShape { entry: "a\"b".into(), barriers: 3, ..Default::default() };
        let json = shape.to_json();
        assert!(json.starts_with("{\"entry\":\"a\\\"b\",\"words\":0,"));
        assert!(json.contains("\"barriers\":3,"));
        assert!(json.ends_with("\"calls\":0}"));
        assert_eq!(json.matches(':').count(), 19);
    }
}
