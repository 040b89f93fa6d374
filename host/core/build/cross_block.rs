//! A SPIR-V pass that carries values used outside the block defining them through function
//! variables.
//!
//! SPIR-V lets a value be used in any block its definition dominates. naga's structured IR, into
//! which its SPIR-V front end translates, scopes a value to the statement block that emits it, and
//! its front end does not spill every use that leaves that scope: a value defined in a loop and used
//! after a `break` out of it, as rust-gpu emits for early exits, fails validation ("not in scope").
//! Here every such value is stored to a fresh function variable right after its definition, and
//! loaded again in each other block that uses it, just before the use. The definition dominates
//! the use, so the store runs first on every path; the values, and so the results, are unchanged.
//! Pointers (which SPIR-V cannot store) and φ operands (naga spills those itself) are left alone.

use rspirv::dr::{Function, Instruction, Module, Operand};
use rspirv::spirv::{Op, StorageClass, Word};
use std::collections::{BTreeMap, BTreeSet};

/// Rewrites `module` in place; returns how many values now pass through variables.
pub fn spill_cross_block_values(module: &mut Module) -> Result<usize, String> {
    let mut bound = module.header.as_ref().map_or(1, |h| h.bound);
    let mut fresh = || {
        bound += 1;
        bound - 1
    };
    let pointer_types: BTreeSet<Word> =
        module.types_global_values.iter().filter(|i| i.class.opcode == Op::TypePointer).filter_map(|i| i.result_id).collect();
    let mut function_pointer: BTreeMap<Word, Word> = module
        .types_global_values
        .iter()
        .filter(|i| i.class.opcode == Op::TypePointer && i.operands.first() == Some(&Operand::StorageClass(StorageClass::Function)))
        .filter_map(|i| match (i.result_id, i.operands.get(1)) {
            (Some(pointer), Some(Operand::IdRef(pointee))) => Some((*pointee, pointer)),
            _ => None,
        })
        .collect();
    let mut new_types = Vec::new();
    let mut spilled = 0;
    for function in &mut module.functions {
        let crossing = crossing_values(function, &pointer_types);
        if crossing.is_empty() {
            continue;
        }
        // One variable per value, declared at the top of the entry block.
        let mut variables: BTreeMap<Word, Word> = BTreeMap::new();
        let mut declarations = Vec::new();
        for (&value, &ty) in &crossing {
            let pointer_type = *function_pointer.entry(ty).or_insert_with(|| {
                let id = fresh();
                let operands = vec![Operand::StorageClass(StorageClass::Function), Operand::IdRef(ty)];
                new_types.push(Instruction::new(Op::TypePointer, None, Some(id), operands));
                id
            });
            let variable = fresh();
            declarations.push(Instruction::new(
                Op::Variable,
                Some(pointer_type),
                Some(variable),
                vec![Operand::StorageClass(StorageClass::Function)],
            ));
            variables.insert(value, variable);
        }
        let defined_in = definitions(function);
        for (block_index, block) in function.blocks.iter_mut().enumerate() {
            let mut rewritten = Vec::with_capacity(block.instructions.len());
            let phis = block.instructions.iter().take_while(|i| i.class.opcode == Op::Phi).count();
            let mut pending_stores = Vec::new();
            for (n, mut inst) in std::mem::take(&mut block.instructions).into_iter().enumerate() {
                if inst.class.opcode != Op::Phi {
                    // Uses from another block load the value just before the instruction (before the
                    // merge instruction that must directly precede a terminator).
                    let mut loads = Vec::new();
                    for operand in &mut inst.operands {
                        if let Operand::IdRef(id) = operand
                            && let Some(&variable) = variables.get(id)
                            && defined_in.get(id) != Some(&block_index)
                        {
                            let loaded = fresh();
                            loads.push(Instruction::new(Op::Load, Some(crossing[id]), Some(loaded), vec![Operand::IdRef(variable)]));
                            *id = loaded;
                        }
                    }
                    let at = match rewritten.last() {
                        Some(last) if is_terminator(inst.class.opcode) && is_merge(last) => rewritten.len() - 1,
                        _ => rewritten.len(),
                    };
                    rewritten.splice(at..at, loads);
                }
                let stores = inst.result_id.and_then(|id| variables.get(&id).map(|&v| (id, v)));
                rewritten.push(inst);
                if let Some((value, variable)) = stores {
                    let store = Instruction::new(Op::Store, None, None, vec![Operand::IdRef(variable), Operand::IdRef(value)]);
                    // φs stay together at the top of their block.
                    if n < phis { pending_stores.push(store) } else { rewritten.push(store) }
                }
                if n + 1 == phis {
                    rewritten.append(&mut pending_stores);
                }
            }
            block.instructions = rewritten;
        }
        let entry = function.blocks.first_mut().ok_or("a function without blocks")?;
        entry.instructions.splice(0..0, declarations);
        spilled += crossing.len();
    }
    module.types_global_values.extend(new_types);
    if let Some(header) = module.header.as_mut() {
        header.bound = bound;
    }
    Ok(spilled)
}

/// `value → type` of the non-pointer values some non-φ instruction uses outside the defining block.
fn crossing_values(function: &Function, pointer_types: &BTreeSet<Word>) -> BTreeMap<Word, Word> {
    let defined_in = definitions(function);
    let types: BTreeMap<Word, Word> = function
        .blocks
        .iter()
        .flat_map(|b| &b.instructions)
        .filter_map(|i| Some((i.result_id?, i.result_type?)))
        .filter(|(_, ty)| !pointer_types.contains(ty))
        .collect();
    let mut crossing = BTreeMap::new();
    for (block_index, block) in function.blocks.iter().enumerate() {
        for inst in block.instructions.iter().filter(|i| i.class.opcode != Op::Phi) {
            for operand in &inst.operands {
                if let Operand::IdRef(id) = operand
                    && let (Some(&def), Some(&ty)) = (defined_in.get(id), types.get(id))
                    && def != block_index
                {
                    crossing.insert(*id, ty);
                }
            }
        }
    }
    crossing
}

/// `value → index of the block defining it`.
fn definitions(function: &Function) -> BTreeMap<Word, usize> {
    let mut defined_in = BTreeMap::new();
    for (index, block) in function.blocks.iter().enumerate() {
        for id in block.instructions.iter().filter_map(|i| i.result_id) {
            defined_in.insert(id, index);
        }
    }
    defined_in
}

fn is_terminator(op: Op) -> bool {
    matches!(op, Op::Branch | Op::BranchConditional | Op::Switch | Op::Return | Op::ReturnValue | Op::Kill | Op::Unreachable)
}

fn is_merge(inst: &Instruction) -> bool {
    matches!(inst.class.opcode, Op::LoopMerge | Op::SelectionMerge)
}
