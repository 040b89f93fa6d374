//! A SPIR-V pass that marks the storage images of a module which reads none as write-only
//! (`NonReadable` on their variables).
//!
//! rust-gpu declares every storage image read-write, and naga's SPIR-V front end keeps what the
//! variable's decorations say, so the WGSL would be `texture_storage_2d<F, read_write>`: WebGPU
//! has that access only for single-channel formats. A kernel that only stores (the frame's
//! result into the caller's RGBA16F or RGBA32F texture) is `write` there, which every WebGPU
//! device has for those formats.

use rspirv::dr::{Instruction, Module, Operand};
use rspirv::spirv::{Decoration, Op, StorageClass, Word};
use std::collections::HashSet;

/// Decorates `module`'s storage-image variables `NonReadable` when no instruction reads an image;
/// returns how many were marked.
pub fn mark_write_only_images(module: &mut Module) -> usize {
    let reads = module.functions.iter().flat_map(|f| f.blocks.iter()).flat_map(|b| b.instructions.iter());
    if reads.into_iter().any(|i| matches!(i.class.opcode, Op::ImageRead | Op::ImageSparseRead)) {
        return 0;
    }
    // Image types with Sampled = 2 (used without a sampler: storage images).
    let storage_images: HashSet<Word> = module
        .types_global_values
        .iter()
        .filter(|i| i.class.opcode == Op::TypeImage && i.operands.get(5) == Some(&Operand::LiteralBit32(2)))
        .filter_map(|i| i.result_id)
        .collect();
    let pointers: HashSet<Word> = module
        .types_global_values
        .iter()
        .filter(|i| i.class.opcode == Op::TypePointer)
        .filter(|i| matches!(i.operands.as_slice(), [Operand::StorageClass(StorageClass::UniformConstant), Operand::IdRef(to)] if storage_images.contains(to)))
        .filter_map(|i| i.result_id)
        .collect();
    let decorated: HashSet<Word> = module
        .annotations
        .iter()
        .filter(|i| i.class.opcode == Op::Decorate && i.operands.get(1) == Some(&Operand::Decoration(Decoration::NonReadable)))
        .filter_map(|i| match i.operands.first() {
            Some(Operand::IdRef(id)) => Some(*id),
            _ => None,
        })
        .collect();
    let variables: Vec<Word> = module
        .types_global_values
        .iter()
        .filter(|i| i.class.opcode == Op::Variable && i.result_type.is_some_and(|t| pointers.contains(&t)))
        .filter_map(|i| i.result_id)
        .filter(|id| !decorated.contains(id))
        .collect();
    for &variable in &variables {
        module.annotations.push(Instruction::new(
            Op::Decorate,
            None,
            None,
            vec![Operand::IdRef(variable), Operand::Decoration(Decoration::NonReadable)],
        ));
    }
    variables.len()
}
