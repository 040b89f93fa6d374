//! Renders depth of field with `dof-core` on the CPU backend, from a crate outside the repository's
//! workspace on stable Rust, as a renderer would: the frame API over the caller's own buffers. A
//! hand-built two-layer image goes through every method of the registry; each result is checked
//! against what it must give.

use dof_core::backend::{Backend, BufferId, CpuBackend};
use dof_core::frame::{
    ContextDesc, CountBuffer, Extent, Frame, METHODS, MethodOptions, RgbBuffer, SLOT_WORDS, SlotBuffer, SlotLayout, registry,
};
use dof_core::{ThinLens, shaders};

/// The frame: 64x64 pixels, up to 2 fragments each.
const W: u32 = 64;
const H: u32 = 64;
const LAYERS: u32 = 2;
const SQUARE: [f32; 3] = [1.0, 0.5, 0.1];
const BACKGROUND: [f32; 3] = [0.2, 0.2, 0.2];

/// The input in the frame API's layout `SlotLayout::PremultipliedRgbDepthAlpha` (named where the
/// frame is made, so that this writer stops compiling if the layout is ever retired): per pixel
/// `LAYERS` slots of `SLOT_WORDS` = 5 words (r, g, b premultiplied by alpha, depth, alpha), front
/// to back, and a count of the slots used. A grey background at depth 10 behind an orange square
/// (pixels 24 to 39 on both axes) at depth 2.
fn input() -> (Vec<u32>, Vec<u32>) {
    let mut slots = vec![0u32; (SLOT_WORDS * LAYERS * W * H) as usize];
    let mut counts = vec![0u32; (W * H) as usize];
    for y in 0..H {
        for x in 0..W {
            let p = (y * W + x) as usize;
            let mut fragments = Vec::new();
            if (24..40).contains(&x) && (24..40).contains(&y) {
                fragments.push((SQUARE, 2.0f32));
            }
            fragments.push((BACKGROUND, 10.0));
            for (k, (c, z)) in fragments.iter().enumerate() {
                let at = SLOT_WORDS as usize * (p * LAYERS as usize + k);
                slots[at..at + SLOT_WORDS as usize].copy_from_slice(&[c[0], c[1], c[2], *z, 1.0].map(f32::to_bits));
            }
            counts[p] = fragments.len() as u32;
        }
    }
    (slots, counts)
}

fn mean(rgb: &[[f32; 3]]) -> [f64; 3] {
    let mut sum = [0.0f64; 3];
    for p in rgb {
        for c in 0..3 {
            sum[c] += p[c] as f64;
        }
    }
    sum.map(|s| s / rgb.len() as f64)
}

/// One frame of `method` into `out`, read back as RGB.
fn run(cpu: &mut CpuBackend, method: &str, lens: ThinLens, [fragments, counts, out]: [BufferId; 3]) -> dof_core::Result<Vec<[f32; 3]>> {
    let desc = ContextDesc::new(Extent::new(W, H, LAYERS), MethodOptions::default());
    let mut ctx = registry::create(cpu, registry::method(method)?, &desc)?;
    let slots = SlotBuffer(fragments, SlotLayout::PremultipliedRgbDepthAlpha);
    ctx.record(cpu, &Frame::layers(W, H, LAYERS, lens, slots, CountBuffer(counts), RgbBuffer(out)))?;
    cpu.submit()?;
    let words = cpu.read_buffer(out, 0, 3 * (W * H) as u64)?;
    ctx.destroy(cpu);
    Ok(words.as_chunks::<3>().0.iter().map(|c| c.map(f32::from_bits)).collect())
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut cpu = CpuBackend::new();
    let (slots, counts) = input();
    let fragments = cpu.create_buffer(slots.len() as u64, "fragments")?;
    let count_buffer = cpu.create_buffer(counts.len() as u64, "counts")?;
    let out = cpu.create_buffer(3 * (W * H) as u64, "output")?;
    cpu.write_buffer(fragments, 0, &slots)?;
    cpu.write_buffer(count_buffer, 0, &counts)?;
    let io = [fragments, count_buffer, out];

    // 50 mm at 10 m with a 20 mm aperture, 20 000 px per metre on the sensor: the square's CoC is
    // 8 px across, the background is in focus.
    let lens = ThinLens { focal_length: 0.05, aperture_radius: 0.01, focus_distance: 10.0, pixels_per_unit: 20_000.0 };
    println!("CoC of the square: {:.1} px", lens.coc_px(2.0));

    // Multi-layer tiled splatting conserves energy away from the borders: the mean colour of the
    // frame stays the input's.
    let rgb = run(&mut cpu, "multilayer", lens, io)?;
    let input_mean = [0.2 + 0.0625 * 0.8, 0.2 + 0.0625 * 0.3, 0.2 - 0.0625 * 0.1];
    let m = mean(&rgb);
    println!(
        "multilayer: mean colour {:.4} {:.4} {:.4} (input {:.4} {:.4} {:.4})",
        m[0], m[1], m[2], input_mean[0], input_mean[1], input_mean[2]
    );
    for c in 0..3 {
        if (m[c] - input_mean[c]).abs() > 0.01 {
            return Err(format!("channel {c}: mean {} is not the input's {}", m[c], input_mean[c]).into());
        }
    }

    // Every method of the registry on the same frame: the in-focus background far from the square
    // keeps its colour, and the square's blurred colour reaches beyond its edge.
    for method in METHODS {
        let rgb = run(&mut cpu, method.name, lens, io)?;
        let at = |x: u32, y: u32| rgb[(y * W + x) as usize];
        let corner = at(4, 4);
        let beyond_edge = at(41, 32);
        println!("{:>12}: corner {:.3?}, beside the square {:.3?}", method.name, corner, beyond_edge);
        if corner.iter().zip(BACKGROUND).any(|(v, b)| (v - b).abs() > 0.01) {
            return Err(format!("{}: the in-focus background became {corner:?}", method.name).into());
        }
        if !(beyond_edge[0] > BACKGROUND[0] + 0.01) {
            return Err(format!("{}: no blur of the square beyond its edge ({beyond_edge:?})", method.name).into());
        }
    }
    println!(
        "ok: {} methods, {} SPIR-V modules embedded ({} bytes), kernel sources {}",
        METHODS.len(),
        shaders::MODULES.len(),
        shaders::total_bytes(),
        &shaders::SOURCE_HASH[..12]
    );
    Ok(())
}
