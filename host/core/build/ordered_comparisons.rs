//! A SPIR-V pass that writes every float comparison with the four ordered relations and `==`, the
//! ones whose NaN semantics WGSL, Metal, HLSL and naga's SPIR-V all share (false when an operand
//! is NaN).
//!
//! rust-gpu's SPIR-V holds unordered comparisons, true when an operand is NaN: `x != x` (Rust's
//! `is_nan`) is `FUnordNotEqual`, and the optimiser writes some negated comparisons as unordered
//! ones. naga's SPIR-V front end reads each as its ordered counterpart, so `is_nan` would be false
//! for NaN; and `!=` is ordered in naga's SPIR-V output but unordered in Metal and HLSL. So each
//! unordered comparison becomes the negation of its ordered complement (`FUnordLessThan(a, b)` is
//! `!(a >= b)`), and `FOrdNotEqual(a, b)` becomes `a < b || a > b`. The kernels test NaN by bits
//! where it matters (`lens::is_finite`), so no result in the suites depends on this pass today; it
//! keeps the translation exact for the ones that will.

use rspirv::dr::{Instruction, Module, Operand};
use rspirv::spirv::{Op, Word};

/// Rewrites `module` in place; returns how many comparisons were rewritten.
pub fn order_float_comparisons(module: &mut Module) -> usize {
    let mut bound = module.header.as_ref().map_or(1, |h| h.bound);
    let mut rewritten = 0;
    for block in module.functions.iter_mut().flat_map(|f| f.blocks.iter_mut()) {
        let mut out = Vec::with_capacity(block.instructions.len());
        for inst in std::mem::take(&mut block.instructions) {
            let (Some(ty), Some(result)) = (inst.result_type, inst.result_id) else {
                out.push(inst);
                continue;
            };
            let operands = inst.operands.clone();
            let mut fresh = || {
                bound += 1;
                bound - 1
            };
            let mut emit = |op: Op, id: Word, operands: Vec<Operand>| out.push(Instruction::new(op, Some(ty), Some(id), operands));
            // `a < b || a > b`, the ordered "not equal", into `id`.
            let ordered_not_equal = |emit: &mut dyn FnMut(Op, Word, Vec<Operand>), fresh: &mut dyn FnMut() -> Word, id: Word| {
                let (less, greater) = (fresh(), fresh());
                emit(Op::FOrdLessThan, less, operands.clone());
                emit(Op::FOrdGreaterThan, greater, operands.clone());
                emit(Op::LogicalOr, id, vec![Operand::IdRef(less), Operand::IdRef(greater)]);
            };
            let complement = match inst.class.opcode {
                Op::FUnordLessThan => Some(Op::FOrdGreaterThanEqual),
                Op::FUnordGreaterThan => Some(Op::FOrdLessThanEqual),
                Op::FUnordLessThanEqual => Some(Op::FOrdGreaterThan),
                Op::FUnordGreaterThanEqual => Some(Op::FOrdLessThan),
                Op::FUnordNotEqual => Some(Op::FOrdEqual),
                _ => None,
            };
            match (inst.class.opcode, complement) {
                (_, Some(ordered)) => {
                    let t = fresh();
                    emit(ordered, t, operands.clone());
                    emit(Op::LogicalNot, result, vec![Operand::IdRef(t)]);
                }
                (Op::FOrdNotEqual, None) => ordered_not_equal(&mut emit, &mut fresh, result),
                (Op::FUnordEqual, None) => {
                    let t = fresh();
                    ordered_not_equal(&mut emit, &mut fresh, t);
                    emit(Op::LogicalNot, result, vec![Operand::IdRef(t)]);
                }
                _ => {
                    out.push(inst);
                    continue;
                }
            }
            rewritten += 1;
        }
        block.instructions = out;
    }
    if let Some(header) = module.header.as_mut() {
        header.bound = bound;
    }
    rewritten
}
