//! Every method of the frame API's registry, through `dyn DofContext` only: it records any frame
//! within its extent with no allocation, readback or upload and one submission, resizes, equals the
//! one-shot path, is tied to the backend that made it, and reports. Nothing here names a concrete
//! context, so a method added to the registry is covered without a change.

use dof::backend::{Backend, BufferId, CpuBackend};
use dof::frame::{
    ContextDesc, CountBuffer, DofContext, Extent, Frame, Kind, METHODS, MethodInfo, MethodOption, MethodOptions, Reads, RgbBuffer,
    SlotBuffer, Value,
};
use dof::layers::LayeredImage;
use dof::methods::buffers::{read_rgb, slot_words};
use dof::methods::one_shot::one_shot;
use dof::stress::{noise_with_sky, test_lens};
use dof_tests::{assert_clean, vulkan, wgpu};

fn create(b: &mut dyn Backend, m: &MethodInfo, extent: Extent) -> Box<dyn DofContext> {
    (m.create)(b, &ContextDesc::new(extent, MethodOptions::default())).unwrap_or_else(|e| panic!("{}: {e}", m.name))
}

/// The input a method reads: every layer, or the front one.
fn input_for(m: &MethodInfo, w: u32, h: u32, layers: u32) -> LayeredImage {
    let image = noise_with_sky(w, h, layers);
    if m.reads == Reads::FrontLayer { image.front_layer() } else { image }
}

fn caller_buffers(b: &mut dyn Backend, e: Extent) -> [BufferId; 3] {
    let pixels = e.width as u64 * e.height as u64;
    [dof::methods::buffers::SLOT_WORDS as u64 * pixels * e.layers as u64, pixels, 3 * pixels]
        .map(|words| b.create_buffer(words, "caller").unwrap())
}

/// Frames of several sizes within the extent, then a resize to a larger one and a frame there:
/// per frame 0 allocations, readbacks and uploads and 1 submission, finite output, and the same
/// image as the one-shot path.
fn frames_resizes_and_one_shot(b: &mut dyn Backend) {
    for m in METHODS {
        let extent = Extent::new(48, 32, 3);
        let mut ctx = create(b, m, extent);
        assert_eq!((ctx.method(), ctx.extent()), (m.name, extent));
        let grown = Extent::new(64, 40, 3);
        let bufs = caller_buffers(b, grown);
        for (i, &(w, h, l, aperture)) in [(48, 32, 3, 0.02f32), (17, 9, 2, 0.01), (48, 32, 1, 0.0), (64, 40, 3, 0.02)].iter().enumerate() {
            if i == 3 {
                assert!(
                    ctx.record(
                        b,
                        &Frame::layers(
                            w,
                            h,
                            l,
                            test_lens(aperture),
                            SlotBuffer::current(bufs[0]),
                            CountBuffer(bufs[1]),
                            RgbBuffer(bufs[2])
                        )
                    )
                    .is_err(),
                    "{}: beyond",
                    m.name
                );
                ctx.resize(b, grown).unwrap_or_else(|e| panic!("{}: resize: {e}", m.name));
                assert_eq!(ctx.extent(), grown);
            }
            let image = input_for(m, w, h, l);
            b.write_buffer(bufs[0], 0, &slot_words(&image)).unwrap();
            b.write_buffer(bufs[1], 0, &image.counts).unwrap();
            let frame = Frame::layers(
                w,
                h,
                image.max_layers,
                test_lens(aperture),
                SlotBuffer::current(bufs[0]),
                CountBuffer(bufs[1]),
                RgbBuffer(bufs[2]),
            );
            let before = b.counters();
            ctx.record(b, &frame).unwrap_or_else(|e| panic!("{} frame {i}: {e}", m.name));
            b.submit().unwrap();
            let spent = b.counters().since(&before);
            assert_eq!((spent.allocations, spent.readbacks, spent.uploads, spent.submissions), (0, 0, 0, 1), "{} frame {i}", m.name);
            let got = read_rgb(b, bufs[2], w, h).unwrap();
            assert!(got.data.iter().flatten().all(|v| v.is_finite() && *v >= 0.0), "{} frame {i}: not finite and non-negative", m.name);
            let report = ctx.report(b).unwrap();
            assert!(!report.summary.is_empty() && report.overflow == 0, "{} frame {i}: {report:?}", m.name);
            let once = one_shot(b, m, &MethodOptions::default(), &image, &test_lens(aperture)).unwrap();
            assert!(once.image.data == got.data, "{} frame {i} ({w}x{h}, {l} layers): the one-shot path differs", m.name);
        }
        ctx.destroy(b);
        bufs.iter().for_each(|&id| b.destroy_buffer(id));
    }
    assert_eq!(b.counters().device_bytes, 0, "every context and buffer freed");
}

#[test]
fn every_registered_method_records_resizes_and_matches_the_one_shot_path_on_the_cpu() {
    frames_resizes_and_one_shot(&mut CpuBackend::new());
}

#[test]
fn every_registered_method_records_resizes_and_matches_the_one_shot_path_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    frames_resizes_and_one_shot(&mut vk);
    assert_clean(&mut vk);
}

#[test]
fn every_registered_method_records_resizes_and_matches_the_one_shot_path_on_wgpu() {
    let Some(mut g) = wgpu() else { return };
    frames_resizes_and_one_shot(&mut g);
    assert!(g.take_diagnostics().is_empty());
}

/// Every method's frame as a value: made once, checked, then encoded. Encoded, it gives the image
/// the one-shot path gives; its stages are named; the barriers it derives from its commands'
/// reads and writes are the ones the Vulkan backend records; another backend refuses it.
fn recordings_are_values(b: &mut dyn Backend) {
    let (w, h, l) = (40, 24, 3);
    for m in METHODS {
        let extent = Extent::new(w, h, l);
        let mut ctx = create(b, m, extent);
        let bufs = caller_buffers(b, extent);
        let image = input_for(m, w, h, l);
        b.write_buffer(bufs[0], 0, &slot_words(&image)).unwrap();
        b.write_buffer(bufs[1], 0, &image.counts).unwrap();
        b.submit().unwrap();
        let frame =
            Frame::layers(w, h, image.max_layers, test_lens(0.02), SlotBuffer::current(bufs[0]), CountBuffer(bufs[1]), RgbBuffer(bufs[2]));
        let before = b.counters();
        let recording = ctx.recording(b, &frame).unwrap_or_else(|e| panic!("{}: {e}", m.name));
        assert_eq!(b.counters().since(&before).commands, 0, "{}: making the recording records nothing", m.name);
        let commands = recording.commands();
        assert!(!commands.is_empty() && commands.iter().all(|c| !c.label().is_empty()), "{}: {commands:?}", m.name);
        assert!(!recording.stages().is_empty());
        let barriers = recording.barriers();
        assert_eq!(barriers.first(), Some(&0), "{}: the first command waits for what came before", m.name);
        assert!(barriers.len() < commands.len(), "{}: some commands run without a barrier between them", m.name);
        // Every barrier separates a command from one it depends on: it reads or writes something
        // written since the barrier before, or writes something read since then.
        for pair in barriers.windows(2) {
            let (from, at) = (pair[0], pair[1]);
            let later = commands[at].accesses();
            let depends = commands[from..at]
                .iter()
                .flat_map(|c| c.accesses())
                .any(|earlier| later.iter().any(|a| a.resource == earlier.resource && (earlier.writes || a.writes)));
            assert!(depends, "{}: a barrier before command {at} ({:?}) with no dependency", m.name, commands[at]);
        }

        assert!(recording.encode(&mut CpuBackend::new()).is_err(), "{}: another backend", m.name);
        let before = b.counters();
        recording.encode(b).unwrap_or_else(|e| panic!("{}: encode: {e}", m.name));
        b.submit().unwrap();
        let spent = b.counters().since(&before);
        if b.kind() == dof::backend::BackendKind::Vulkan {
            assert_eq!(spent.commands, commands.len() as u64, "{}: one backend command a recorded command", m.name);
            assert_eq!(spent.barriers, barriers.len() as u64, "{}: the backend's barriers are the recording's", m.name);
        } else {
            // The CPU backend runs a draw as its compute fallback: a fill and one or two kernels.
            assert!(spent.commands >= commands.len() as u64, "{}", m.name);
        }
        let got = read_rgb(b, bufs[2], w, h).unwrap();
        let once = one_shot(b, m, &MethodOptions::default(), &image, &test_lens(0.02)).unwrap();
        assert!(once.image.data == got.data, "{}: the encoded recording differs from the one-shot path", m.name);
        ctx.destroy(b);
        bufs.iter().for_each(|&id| b.destroy_buffer(id));
    }
}

#[test]
fn every_method_records_a_frame_as_a_value_on_the_cpu() {
    recordings_are_values(&mut CpuBackend::new());
}

#[test]
fn every_method_records_a_frame_as_a_value_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    recordings_are_values(&mut vk);
    assert_clean(&mut vk);
}

/// A context dropped without `destroy` gives its buffers back: the backend frees them at its next
/// chance (here `release_finished`), and holds what it held before the context was made.
fn dropped_contexts_free_themselves(b: &mut dyn Backend) {
    let extent = Extent::new(24, 16, 2);
    let bufs = caller_buffers(b, extent);
    for m in METHODS {
        let before = b.counters().device_bytes;
        let mut ctx = create(b, m, extent);
        let held = ctx.device_bytes();
        assert_eq!(b.counters().device_bytes - before, held, "{}: the context's bytes", m.name);
        let image = input_for(m, 24, 16, 2);
        b.write_buffer(bufs[0], 0, &slot_words(&image)).unwrap();
        b.write_buffer(bufs[1], 0, &image.counts).unwrap();
        let frame = Frame::layers(
            24,
            16,
            image.max_layers,
            test_lens(0.02),
            SlotBuffer::current(bufs[0]),
            CountBuffer(bufs[1]),
            RgbBuffer(bufs[2]),
        );
        ctx.record(b, &frame).unwrap();
        b.submit().unwrap();
        drop(ctx);
        let freed = b.release_finished().unwrap();
        assert_eq!((freed, b.counters().device_bytes), (held, before), "{}: freed after the drop", m.name);
    }
    bufs.iter().for_each(|&id| b.destroy_buffer(id));
}

#[test]
fn dropped_contexts_free_themselves_on_the_cpu() {
    dropped_contexts_free_themselves(&mut CpuBackend::new());
}

#[test]
fn dropped_contexts_free_themselves_on_vulkan() {
    let Some(mut vk) = vulkan() else { return };
    dropped_contexts_free_themselves(&mut vk);
    assert_clean(&mut vk);
}

/// A context refuses a backend other than the one that made it: recording, resizing and
/// destroying there touch none of that backend's buffers (whose ids may well be the same).
#[test]
fn a_context_is_tied_to_its_backend() {
    let (mut mine, mut other) = (CpuBackend::new(), CpuBackend::new());
    let extent = Extent::new(16, 16, 2);
    for m in METHODS {
        let mut ctx = create(&mut mine, m, extent);
        // The other backend holds buffers of the same ids as the context's.
        let theirs: Vec<BufferId> = (0..64).map(|_| other.create_buffer(8, "theirs").unwrap()).collect();
        let bufs = caller_buffers(&mut other, extent);
        let frame = Frame::layers(16, 16, 1, test_lens(0.01), SlotBuffer::current(bufs[0]), CountBuffer(bufs[1]), RgbBuffer(bufs[2]));
        let refused = ctx.record(&mut other, &frame).expect_err("recording on another backend");
        assert!(refused.to_string().contains("another backend"), "{}: {refused}", m.name);
        assert!(ctx.resize(&mut other, Extent::new(8, 8, 1)).is_err(), "{}: resize on another backend", m.name);
        let before = other.counters();
        ctx.destroy(&mut other);
        assert_eq!(other.counters().device_bytes, before.device_bytes, "{}: destroy on another backend freed its buffers", m.name);
        assert!(theirs.iter().all(|&id| other.buffer_words(id).is_ok()), "{}: another backend's buffer was freed", m.name);
        // The context's buffers stay with their own backend, which frees them when dropped.
        theirs.iter().chain(&bufs).for_each(|&id| other.destroy_buffer(id));
        assert_eq!(other.counters().device_bytes, 0);
    }
}

#[test]
fn unknown_method_names_list_the_registry() {
    let e = dof::frame::registry::method("nosuch").unwrap_err().to_string();
    for m in METHODS {
        assert!(e.contains(m.name), "{e}");
    }
}

/// Every command a method records, at each of its evaluation points and with image input and
/// output, belongs to one of the stages its entry names, so reports file it in the right column.
#[test]
fn every_recorded_command_belongs_to_a_stage_of_its_entry() {
    let b = &mut CpuBackend::new();
    let (w, h, l) = (40, 24, 3);
    for m in METHODS {
        for point in m.sweep.points {
            let options = m.parse_options(point).unwrap_or_else(|e| panic!("{} `{point}`: {e}", m.name));
            for image_io in [false, true] {
                let desc = ContextDesc { image_io, ..ContextDesc::new(Extent::new(w, h, l), options.clone()) };
                let mut ctx = (m.create)(b, &desc).unwrap_or_else(|e| panic!("{} `{point}`: {e}", m.name));
                let bufs = caller_buffers(b, Extent::new(w, h, l));
                let frame = Frame::layers(w, h, l, test_lens(0.02), SlotBuffer::current(bufs[0]), CountBuffer(bufs[1]), RgbBuffer(bufs[2]));
                let recording = ctx.recording(b, &frame).unwrap_or_else(|e| panic!("{}: {e}", m.name));
                for c in recording.commands() {
                    assert!(m.column(c.label()).is_some(), "{} `{point}`: no stage of its entry claims `{}`", m.name, c.label());
                }
                drop(recording);
                ctx.destroy(b);
                bufs.iter().for_each(|&id| b.destroy_buffer(id));
            }
        }
    }
}

/// Every entry's evaluation points parse, its full, quick and timed picks name points it has, and
/// the defaults its options state are the option types' own.
#[test]
fn every_entry_states_parseable_sweeps_and_true_defaults() {
    let defaults = format!("{:?}", MethodOptions::default());
    for m in METHODS {
        let s = m.sweep;
        let picks = s.full.iter().chain(s.quick).chain(s.timed.as_ref());
        assert!(picks.into_iter().all(|&i| i < s.points.len()), "{}: a pick beyond its {} points", m.name, s.points.len());
        assert!(!s.full.is_empty() && !s.quick.is_empty(), "{}", m.name);
        for point in s.points {
            m.parse_options(point).unwrap_or_else(|e| panic!("{} `{point}`: {e}", m.name));
        }
        // Every stated default that is a value (a CoC cap may be the method's choice, in words).
        let values = m.options.iter().filter(|s| s.option != MethodOption::MaxCoc || s.default.parse::<u32>().is_ok());
        for spec in values {
            let parsed = m.parse_options(&format!("{}={}", spec.option.key(), spec.default)).unwrap();
            assert_eq!(format!("{parsed:?}"), defaults, "{} {}: the stated default is not the default", m.name, spec.option.key());
        }
    }
}

/// An option is refused, naming the methods that take it, where a method does not take it; a
/// value is refused, naming the option's bounds and unit, where it lies outside them; a key no
/// method knows is refused, naming the method's own options. The bounds themselves are accepted.
#[test]
fn entries_refuse_options_they_do_not_take_and_values_out_of_bounds() {
    for m in METHODS {
        for option in MethodOption::ALL.into_iter().filter(|&o| !m.takes(o)) {
            let e = m.method_options([(option.key(), Value::Flag(true))]).unwrap_err().to_string();
            assert!(e.contains("applies to") && e.contains(&option.methods()) && e.contains(m.name), "{}: {e}", m.name);
        }
        let e = m.method_options([("nosuch", Value::Int(1))]).unwrap_err().to_string();
        assert!(e.contains("unknown option 'nosuch'"), "{e}");
        for spec in m.options {
            let key = spec.option.key();
            let (inside, outside): (Vec<Value>, Vec<Value>) = match spec.kind {
                Kind::Count { min, max } => (
                    vec![Value::Int(min.into()), Value::Int(max.into())],
                    vec![Value::Int(i64::from(min) - 1), Value::Int(i64::from(max) + 1), Value::Number(min as f64 + 0.5)],
                ),
                Kind::Number { min, max } => (
                    vec![Value::Number(min.into()), Value::Int(1)],
                    vec![Value::Number(f64::from(min) - 1.0), Value::Number(f64::from(max) * 2.0), Value::Number(f64::NAN)],
                ),
                Kind::Flag => (vec![Value::Flag(false), Value::Text("true".into())], vec![Value::Int(1), Value::Text("yes".into())]),
                Kind::Choice(names) => (names.iter().map(|&n| Value::from(n)).collect(), vec![Value::from("3x3")]),
                Kind::Aperture => (vec![Value::from("circle"), Value::from("blades:6")], vec![Value::from("blades:1"), Value::Int(6)]),
            };
            for v in inside {
                m.method_options([(key.as_str(), v.clone())]).unwrap_or_else(|e| panic!("{} {key}={v}: {e}", m.name));
            }
            for v in outside {
                let e = m.method_options([(key.as_str(), v.clone())]).map(|_| ()).unwrap_err().to_string();
                assert!(e.contains(&key), "{} {key}={v}: {e}", m.name);
                if matches!(spec.kind, Kind::Count { .. } | Kind::Number { .. }) && !spec.unit.is_empty() {
                    assert!(e.contains(spec.unit), "{} {key}={v}: the unit is not named: {e}", m.name);
                }
            }
        }
    }
}
