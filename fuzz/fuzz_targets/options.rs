//! A method's options as text: the first byte picks a method of the registry, the rest is read as
//! `key=value` pairs (`MethodInfo::parse_options`), as the evaluation, scripts and bindings give
//! them.
//!
//! Parsing must return `Ok` or `Err`. Options the entry accepts must make a context on the CPU
//! backend, or be refused by it with an error (never a kernel fault); a context made must record
//! a small frame whose output is finite and not negative.
#![no_main]

use dof::CoreError;
use dof::backend::{Backend, CpuBackend};
use dof::frame::{ContextDesc, CountBuffer, Extent, Frame, METHODS, RgbBuffer, SlotBuffer};
use dof::methods::buffers::read_rgb;
use dof::scene::ThinLens;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&pick, text)) = data.split_first() else { return };
    let method = &METHODS[pick as usize % METHODS.len()];
    let text = String::from_utf8_lossy(text);
    let Ok(options) = method.parse_options(&text) else { return };
    let (w, h, layers) = (24u32, 16u32, 2u32);
    let b = &mut CpuBackend::new();
    let mut ctx = match (method.create)(b, &ContextDesc::new(Extent::new(w, h, layers), options)) {
        Ok(ctx) => ctx,
        Err(e @ CoreError::KernelFault { .. }) => panic!("{} `{text}`: {e}", method.name),
        Err(_) => return,
    };
    // Opaque slots, one or two a pixel, near and far of the focus, colours varying by pixel.
    let pixels = (w * h) as u64;
    let mut words = Vec::new();
    let mut counts = Vec::new();
    for p in 0..w * h {
        let used = 1 + p % layers;
        counts.push(used);
        for k in 0..layers {
            let depth = 1.0 + 3.0 * k as f32 + (p % 5) as f32 * 0.1;
            words.extend([(p % 7) as f32 / 7.0, 0.5, if k < used { 1.0 } else { 0.0 }, depth, 1.0].map(f32::to_bits));
        }
    }
    let sizes = [words.len() as u64, pixels, 3 * pixels];
    let bufs: Vec<_> = sizes.iter().map(|&n| b.create_buffer(n, "fuzz").expect("a small buffer")).collect();
    b.write_buffer(bufs[0], 0, &words).expect("written");
    b.write_buffer(bufs[1], 0, &counts).expect("written");
    let lens = ThinLens { focal_length: 0.05, aperture_radius: 0.02, focus_distance: 3.0, pixels_per_unit: 2000.0 };
    let frame = Frame::layers(w, h, layers, lens, SlotBuffer::current(bufs[0]), CountBuffer(bufs[1]), RgbBuffer(bufs[2]));
    match ctx.record(b, &frame).and_then(|()| b.submit().map(drop)) {
        Ok(()) => {}
        Err(e @ CoreError::KernelFault { .. }) => panic!("{} `{text}`: {e}", method.name),
        Err(_) => return,
    }
    let out = read_rgb(b, bufs[2], w, h).expect("read back");
    assert!(out.data.iter().flatten().all(|c| c.is_finite() && *c >= 0.0), "{} `{text}`: a channel not finite or negative", method.name);
});
