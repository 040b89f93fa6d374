//! Transient buffers placed by lifetime (`Recording::transients`), for every method of the
//! registry, on the CPU backend (placement is the host's; lavapipe gets the same buffers):
//! - transients that share a buffer are used by disjoint runs of commands, at the largest extent
//!   and at a smaller one (whose recording leaves some commands out);
//! - the command that first uses a transient writes it;
//! - a barrier stands between the last use of one transient and the first use of the next in the
//!   same buffer, so the device never sees them at once;
//! - at least four methods (the two splatting methods, the ring gather, bokeh sprites) place transients
//!   together.

use dof::backend::{Backend, CpuBackend, Resource};
use dof::frame::{ContextDesc, CountBuffer, Extent, Frame, METHODS, MethodOptions, Reads, Recording, RgbBuffer, SlotBuffer, TransientUse};
use dof::methods::buffers::{SLOT_WORDS, slot_words};
use dof::stress::{noise_with_sky, test_lens};

const EXTENT: Extent = Extent { width: 64, height: 48, layers: 3 };

fn check(method: &str, rec: &Recording) {
    let uses = rec.transients();
    let barriers = rec.barriers();
    for u in uses {
        assert!(u.first <= u.last && u.last < rec.commands().len(), "{method}: {u:?}");
        let first = rec.commands()[u.first].accesses();
        let on = |writes: bool| first.iter().any(|a| a.resource == Resource::Buffer(u.buffer) && a.writes == writes);
        assert!(on(true) && !on(false), "{method}: `{}` is read by its first command", u.label);
    }
    for (i, a) in uses.iter().enumerate() {
        for b in uses[i + 1..].iter().filter(|b| b.buffer == a.buffer) {
            let (early, late): (&TransientUse, &TransientUse) = if a.last < b.first { (a, b) } else { (b, a) };
            assert!(early.last < late.first, "{method}: `{}` and `{}` share a buffer and overlap", a.label, b.label);
            assert!(
                barriers.iter().any(|&at| early.last < at && at <= late.first),
                "{method}: no barrier between `{}` (last command {}) and `{}` (first {})",
                early.label,
                early.last,
                late.label,
                late.first
            );
        }
    }
}

#[test]
fn transients_sharing_a_buffer_are_used_apart_with_a_barrier_between() {
    let mut b = CpuBackend::new();
    let mut sharing = 0;
    for m in METHODS {
        let mut ctx = (m.create)(&mut b, &ContextDesc::new(EXTENT, MethodOptions::default())).unwrap();
        let mut shared = false;
        for (w, h) in [(EXTENT.width, EXTENT.height), (40, 24)] {
            let image = noise_with_sky(w, h, EXTENT.layers);
            let image = if m.reads == Reads::FrontLayer { image.front_layer() } else { image };
            let pixels = (w * h) as u64;
            let [slots, counts, out] = [SLOT_WORDS as u64 * pixels * image.max_layers as u64, pixels, 3 * pixels]
                .map(|words| b.create_buffer(words, "caller").unwrap());
            b.write_buffer(slots, 0, &slot_words(&image)).unwrap();
            b.write_buffer(counts, 0, &image.counts).unwrap();
            let frame =
                Frame::layers(w, h, image.max_layers, test_lens(0.02), SlotBuffer::current(slots), CountBuffer(counts), RgbBuffer(out));
            let rec = ctx.recording(&b, &frame).unwrap_or_else(|e| panic!("{} at {w}x{h}: {e}", m.name));
            check(m.name, &rec);
            let uses = rec.transients();
            shared |= uses.iter().enumerate().any(|(i, a)| uses[i + 1..].iter().any(|u| u.buffer == a.buffer));
            rec.encode(&mut b).unwrap();
            b.submit().unwrap();
            [slots, counts, out].into_iter().for_each(|id| b.destroy_buffer(id));
        }
        sharing += shared as u32;
        ctx.destroy(&mut b);
    }
    // Multi-layer and single-layer splatting, the ring gather and bokeh sprites.
    assert!(sharing >= 4, "{sharing} methods place two transients in one buffer");
}
