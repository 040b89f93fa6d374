//! The depth-of-field methods the viewer switches between, each a context of the public frame API
//! created once for the largest frame and recorded into the viewer's command buffer.

use anyhow::Result;
use dof::backend::{Backend, CommandTime};
use dof::frame::{ContextDesc, DofContext, Extent, Frame, METHODS, Merge, MethodInfo, MethodOption, MethodOptions, Reads, Value};

/// A method of the frame API's registry, as the viewer offers it.
#[derive(Clone, Copy, PartialEq)]
pub struct ViewMethod(pub &'static MethodInfo);

impl std::fmt::Debug for ViewMethod {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl ViewMethod {
    /// Every method of the registry, in its order.
    pub fn all() -> impl Iterator<Item = ViewMethod> {
        METHODS.iter().map(ViewMethod)
    }

    pub fn label(self) -> String {
        format!("{} ({})", self.0.title, self.0.paper)
    }

    /// The name the command line and scripts use.
    pub fn name(self) -> &'static str {
        self.0.name
    }

    pub fn parse(s: &str) -> Option<ViewMethod> {
        Self::all().find(|m| m.name().eq_ignore_ascii_case(s))
    }

    /// The registry's names, for messages.
    pub fn names() -> String {
        Self::all().map(|m| m.name()).collect::<Vec<_>>().join(", ")
    }

    /// Whether the method reads only the front layer.
    pub fn front_only(self) -> bool {
        self.0.reads == Reads::FrontLayer
    }
}

impl std::str::FromStr for ViewMethod {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        ViewMethod::parse(s).ok_or_else(|| format!("unknown method '{s}': the methods are {}", ViewMethod::names()))
    }
}

/// What the contexts are created with; a change recreates the context it concerns.
#[derive(Clone, Debug, PartialEq)]
pub struct MethodSettings {
    pub method: ViewMethod,
    pub merge: Merge,
    pub tile: u32,
    /// `circle`, `blades:N[:ROT]` or `star:N` (see `dof::aperture`); methods with a shaped
    /// aperture only.
    pub aperture: String,
    /// The ring gather's knob (1 to 8 sample rings); changed between frames without a new context.
    pub rings: u32,
}

impl MethodSettings {
    /// The frame API's options these settings make (each method reads its own).
    /// The viewer's controls apply to the methods that take them (the registry entry says which);
    /// the entry checks their values.
    fn options(&self) -> Result<MethodOptions> {
        let m = self.method.0;
        let aperture = (!self.aperture.is_empty()).then(|| ("aperture", Value::from(self.aperture.as_str())));
        // The rings are the ring gather's knob, set on its context after creation; the other gathers
        // keep their own ring counts.
        let given = [("tile", Value::from(self.tile)), ("merge", Value::from(self.merge.name()))];
        let taken = given.into_iter().chain(aperture).filter(|(key, _)| MethodOption::from_key(key).is_some_and(|o| m.takes(o)));
        Ok(m.method_options(taken)?)
    }

    /// What a context of any method is made from: everything but the method and its knob.
    fn key(&self) -> (Merge, u32, String) {
        (self.merge, self.tile, self.aperture.clone())
    }
}

/// The contexts, one slot per registry method, each made on first use for frames up to `max`
/// (width, height, layers).
pub struct Contexts {
    max: [u32; 3],
    slots: Vec<Option<((Merge, u32, String), Box<dyn DofContext>)>>,
}

impl Contexts {
    pub fn new(max: [u32; 3]) -> Contexts {
        Contexts { max, slots: METHODS.iter().map(|_| None).collect() }
    }

    pub fn max(&self) -> [u32; 3] {
        self.max
    }

    fn slot(method: ViewMethod) -> usize {
        METHODS.iter().position(|m| m.name == method.name()).unwrap_or(0)
    }

    /// Makes sure the context for `s.method` exists with these settings and holds frames up to
    /// `max`. Only between frames (the last one completed): it may allocate and submit.
    pub fn prepare(&mut self, backend: &mut dyn Backend, s: &MethodSettings, max: [u32; 3]) -> Result<()> {
        let grew = max.iter().zip(self.max).any(|(a, b)| *a > b);
        if grew {
            let grown = [max[0].max(self.max[0]), max[1].max(self.max[1]), max[2].max(self.max[2])];
            for (_, ctx) in self.slots.iter_mut().flatten() {
                ctx.resize(backend, Extent::new(grown[0], grown[1], grown[2]))?;
            }
            self.max = grown;
        }
        let [w, h, l] = self.max;
        let slot = &mut self.slots[Self::slot(s.method)];
        let mut made = false;
        if slot.as_ref().is_none_or(|(key, _)| *key != s.key()) {
            let desc = ContextDesc { image_io: true, ..ContextDesc::new(Extent::new(w, h, l), s.options()?) };
            let ctx = (s.method.0.create)(backend, &desc)?;
            if let Some((_, old)) = slot.replace((s.key(), ctx)) {
                old.destroy(backend);
            }
            made = true;
        }
        if let (Some(knob), Some((_, ctx))) = (s.method.0.knob, slot.as_mut()) {
            // The viewer's knob control is the ring count, the registry's one knob; it changes without a
            // new context.
            let value = if knob.name == "rings" { s.rings } else { knob.default };
            if ctx.knob() != Some(value) {
                ctx.set_knob(value)?;
            }
        }
        // Creation recorded the zeroing of the new buffers in the backend's own command buffer:
        // run it now, so that no frame's begin_external has anything to flush.
        if made || grew {
            backend.submit()?;
        }
        Ok(())
    }

    /// Records `frame` with the method's context (prepared by [`Contexts::prepare`]).
    pub fn record(&mut self, backend: &mut dyn Backend, method: ViewMethod, frame: &Frame) -> Result<()> {
        let (_, ctx) =
            self.slots[Self::slot(method)].as_mut().ok_or_else(|| anyhow::anyhow!("the context for {} was not prepared", method.name()))?;
        Ok(ctx.record(backend, frame)?)
    }

    /// What the last frame of `method` left out or did, as lines for the screen. Reads the
    /// context's statistics back: call only once that frame completed (the viewer does it after
    /// its fence, for the frame before, a few times a second).
    pub fn report(&self, backend: &mut dyn Backend, method: ViewMethod) -> Result<Vec<String>> {
        Ok(match &self.slots[Self::slot(method)] {
            Some((_, ctx)) => ctx.report(backend)?.summary.lines().map(str::to_string).collect(),
            None => Vec::new(),
        })
    }

    pub fn destroy(self, backend: &mut dyn Backend) {
        for (_, ctx) in self.slots.into_iter().flatten() {
            ctx.destroy(backend);
        }
    }
}

/// GPU time per stage, in first-seen order, and the total.
pub fn stage_times(times: &[CommandTime]) -> (Vec<(String, f64)>, f64) {
    let mut stages: Vec<(String, f64)> = Vec::new();
    for t in times {
        // Splatting's stages by name (plan, pack, merge, bin, accumulate...), the others by kind.
        let top = t.label.split('/').next().unwrap_or(&t.label);
        let stage = match t.label.split('/').nth(1) {
            Some(sub) if top == "splat" => sub.to_string(),
            _ => top.to_string(),
        };
        match stages.iter_mut().find(|(l, _)| *l == stage) {
            Some((_, ms)) => *ms += t.ms,
            None => stages.push((stage, t.ms)),
        }
    }
    let total = times.iter().map(|t| t.ms).sum();
    (stages, total)
}
