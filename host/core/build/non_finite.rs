//! A SPIR-V pass that turns non-finite `f32` constants into values made at run time.
//!
//! The kernels use +∞ as the depth of the sky and NaN as "no value" (the numerical contract). WGSL
//! has no literal for either: a constant expression that is infinite or NaN is a shader-creation
//! error, and naga refuses such constants in every module it validates. The values themselves are
//! fine at run time. So each non-finite constant becomes a private variable holding its bit
//! pattern as `u32`, loaded and bitcast at the start of every function that uses it; a constant
//! composite holding one (an array of depths, a slot) is built there with `OpCompositeConstruct`.
//! The bits, and so every result, are those of the original module.

use rspirv::dr::{Instruction, Module, Operand};
use rspirv::spirv::{Op, StorageClass, Word};
use std::collections::{BTreeMap, BTreeSet};

/// Rewrites `module` in place; returns how many constants were made run-time values.
pub fn make_non_finite_constants_runtime(module: &mut Module) -> Result<usize, String> {
    let Some(f32_type) = find_type(module, |i| i.class.opcode == Op::TypeFloat && i.operands.first() == Some(&Operand::LiteralBit32(32)))
    else {
        return Ok(0);
    };
    // Non-finite scalars, then every constant composite holding one (directly or through another).
    let mut scalars: BTreeMap<Word, u32> = BTreeMap::new();
    let mut composites: Vec<Instruction> = Vec::new();
    let mut tainted: BTreeSet<Word> = BTreeSet::new();
    for inst in &module.types_global_values {
        let Some(id) = inst.result_id else { continue };
        match inst.class.opcode {
            Op::Constant if inst.result_type == Some(f32_type) => {
                if let Some(Operand::LiteralBit32(bits)) = inst.operands.first()
                    && bits & 0x7f80_0000 == 0x7f80_0000
                {
                    scalars.insert(id, *bits);
                    tainted.insert(id);
                }
            }
            Op::ConstantComposite if ids(inst).any(|u| tainted.contains(&u)) => {
                composites.push(inst.clone());
                tainted.insert(id);
            }
            _ if ids(inst).any(|u| tainted.contains(&u)) => {
                return Err(format!(
                    "a non-finite constant is used at module scope by {:?}, which this pass does not rewrite",
                    inst.class.opcode
                ));
            }
            _ => {}
        }
    }
    if tainted.is_empty() {
        return Ok(0);
    }
    module.types_global_values.retain(|i| i.result_id.is_none_or(|id| !tainted.contains(&id)));

    let mut bound = module.header.as_ref().map_or(1, |h| h.bound);
    let mut fresh = || {
        bound += 1;
        bound - 1
    };
    // The private variables, one per non-finite scalar, declared at the end of the module's globals.
    let u32_type =
        match find_type(module, |i| i.class.opcode == Op::TypeInt && i.operands == [Operand::LiteralBit32(32), Operand::LiteralBit32(0)]) {
            Some(id) => id,
            None => {
                let id = fresh();
                module.types_global_values.push(Instruction::new(
                    Op::TypeInt,
                    None,
                    Some(id),
                    vec![Operand::LiteralBit32(32), Operand::LiteralBit32(0)],
                ));
                id
            }
        };
    let pointer_type = match find_type(module, |i| {
        i.class.opcode == Op::TypePointer && i.operands == [Operand::StorageClass(StorageClass::Private), Operand::IdRef(u32_type)]
    }) {
        Some(id) => id,
        None => {
            let id = fresh();
            let operands = vec![Operand::StorageClass(StorageClass::Private), Operand::IdRef(u32_type)];
            module.types_global_values.push(Instruction::new(Op::TypePointer, None, Some(id), operands));
            id
        }
    };
    let mut variables: BTreeMap<Word, Word> = BTreeMap::new();
    for (&constant, &bits) in &scalars {
        let (value, variable) = (fresh(), fresh());
        module.types_global_values.push(Instruction::new(Op::Constant, Some(u32_type), Some(value), vec![Operand::LiteralBit32(bits)]));
        let operands = vec![Operand::StorageClass(StorageClass::Private), Operand::IdRef(value)];
        module.types_global_values.push(Instruction::new(Op::Variable, Some(pointer_type), Some(variable), operands));
        variables.insert(constant, variable);
    }
    // SPIR-V 1.4 and later list every global an entry point uses in its interface.
    for entry in &mut module.entry_points {
        entry.operands.extend(variables.values().map(|&v| Operand::IdRef(v)));
    }

    for function in &mut module.functions {
        // What this function uses, with what it needs: a composite needs its tainted parts.
        let mut used: BTreeSet<Word> = BTreeSet::new();
        for inst in function.blocks.iter().flat_map(|b| &b.instructions) {
            used.extend(ids(inst).filter(|u| tainted.contains(u)));
        }
        for composite in composites.iter().rev() {
            if composite.result_id.is_some_and(|id| used.contains(&id)) {
                used.extend(ids(composite).filter(|u| tainted.contains(u)));
            }
        }
        if used.is_empty() {
            continue;
        }
        let renamed: BTreeMap<Word, Word> = used.iter().map(|&id| (id, fresh())).collect();
        let mut prologue = Vec::new();
        for (&constant, &variable) in variables.iter().filter(|(c, _)| used.contains(c)) {
            let bits = fresh();
            prologue.push(Instruction::new(Op::Load, Some(u32_type), Some(bits), vec![Operand::IdRef(variable)]));
            prologue.push(Instruction::new(Op::Bitcast, Some(f32_type), Some(renamed[&constant]), vec![Operand::IdRef(bits)]));
        }
        // In declaration order, so that a composite's parts are built before it.
        for composite in composites.iter().filter(|c| c.result_id.is_some_and(|id| used.contains(&id))) {
            let id = composite.result_id.map(|id| renamed[&id]);
            let mut built = Instruction::new(Op::CompositeConstruct, composite.result_type, id, composite.operands.clone());
            rename(&mut built, &renamed);
            prologue.push(built);
        }
        let Some(entry) = function.blocks.first_mut() else { continue };
        // Function-scope variables come first in the entry block; one initialised with a rewritten
        // constant is stored to after the prologue instead.
        let locals = entry.instructions.iter().take_while(|i| i.class.opcode == Op::Variable).count();
        let mut stores = Vec::new();
        for local in &mut entry.instructions[..locals] {
            if let Some(Operand::IdRef(init)) = local.operands.get(1).cloned()
                && let Some(&value) = renamed.get(&init)
            {
                local.operands.truncate(1);
                let pointer = local.result_id.ok_or("a variable without a result id")?;
                stores.push(Instruction::new(Op::Store, None, None, vec![Operand::IdRef(pointer), Operand::IdRef(value)]));
            }
        }
        for block in &mut function.blocks {
            for inst in &mut block.instructions {
                rename(inst, &renamed);
            }
        }
        let entry = function.blocks.first_mut().ok_or("a function without blocks")?;
        entry.instructions.splice(locals..locals, prologue.into_iter().chain(stores));
    }
    if let Some(header) = module.header.as_mut() {
        header.bound = bound;
    }
    Ok(scalars.len())
}

/// The ids an instruction's operands refer to.
fn ids(inst: &Instruction) -> impl Iterator<Item = Word> + '_ {
    inst.operands.iter().filter_map(|o| if let Operand::IdRef(id) = o { Some(*id) } else { None })
}

fn rename(inst: &mut Instruction, renamed: &BTreeMap<Word, Word>) {
    for operand in &mut inst.operands {
        if let Operand::IdRef(id) = operand
            && let Some(&new) = renamed.get(id)
        {
            *id = new;
        }
    }
}

fn find_type(module: &Module, matches: impl Fn(&Instruction) -> bool) -> Option<Word> {
    module.types_global_values.iter().find(|i| matches(i)).and_then(|i| i.result_id)
}
