//! The depth-of-field methods the viewer switches between, each a context of the public frame API
//! created once for the largest frame and recorded into the viewer's command buffer.

use anyhow::Result;
use dof::aperture::parse_aperture;
use dof::backend::{Backend, CommandTime};
use dof::frame::{
    BokehContext, BokehContextDesc, Frame, GatherContext, GatherContextDesc, RingGatherContext, RingGatherContextDesc, RingGatherOptions,
    SplatContext, SplatContextDesc,
};
use dof::methods::bokeh::BokehOptions;
use dof::methods::splat::{Merge, SplatOptions};

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ViewMethod {
    /// Multi-layer tiled splatting (Franke, Hofmann, Stamminger, Selgrad 2018).
    Multilayer,
    /// Single-layer tiled splatting (Selgrad, Franke, Stamminger 2016): the front layer only.
    Tiled,
    /// The gathering baseline (Riguer et al. 2003) on the front layer.
    Gather,
    /// The engine-grade gather (after AMD FidelityFX DoF, Unreal Engine's Diaphragm DoF and
    /// Jimenez 2014) on the front layer: half resolution, `--rings` sample rings.
    RingGather,
    /// Bokeh sprites (de Rousiers, Pettineo 2012) over the gathering baseline.
    Bokeh,
}

impl ViewMethod {
    pub const ALL: [ViewMethod; 5] =
        [ViewMethod::Multilayer, ViewMethod::Tiled, ViewMethod::Gather, ViewMethod::RingGather, ViewMethod::Bokeh];

    pub fn label(self) -> &'static str {
        match self {
            ViewMethod::Multilayer => "multi-layer tiled splatting (Franke et al. 2018)",
            ViewMethod::Tiled => "single-layer tiled splatting (Selgrad et al. 2016)",
            ViewMethod::Gather => "gather (Riguer et al. 2003)",
            ViewMethod::RingGather => "ring gather (engine-grade, after FidelityFX, Unreal, Jimenez 2014)",
            ViewMethod::Bokeh => "bokeh sprites (de Rousiers, Pettineo 2012)",
        }
    }

    /// The name the command line and scripts use.
    pub fn name(self) -> String {
        clap::ValueEnum::to_possible_value(&self).map_or_else(|| format!("{self:?}"), |v| v.get_name().to_string())
    }

    pub fn parse(s: &str) -> Option<ViewMethod> {
        <ViewMethod as clap::ValueEnum>::from_str(s, true).ok()
    }

    /// Whether the method reads only the front layer.
    pub fn front_only(self) -> bool {
        self != ViewMethod::Multilayer
    }
}

/// What the contexts are created with; a change recreates the context it concerns.
#[derive(Clone, Debug, PartialEq)]
pub struct MethodSettings {
    pub method: ViewMethod,
    pub merge: Merge,
    pub tile: u32,
    /// `circle`, `blades:N[:ROT]` or `star:N` (see `dof::aperture`); splatting and bokeh only.
    pub aperture: String,
    /// Sample rings of the ring gather (1 to 8); changed between frames without a new context.
    pub rings: u32,
}

/// The contexts, made on first use of their method, for frames up to `max` (width, height, layers).
pub struct Contexts {
    max: [u32; 3],
    splat: Option<(MethodSettings, SplatContext)>,
    gather: Option<GatherContext>,
    ring_gather: Option<RingGatherContext>,
    bokeh: Option<(String, BokehContext)>,
}

impl Contexts {
    pub fn new(max: [u32; 3]) -> Contexts {
        Contexts { max, splat: None, gather: None, ring_gather: None, bokeh: None }
    }

    pub fn max(&self) -> [u32; 3] {
        self.max
    }

    /// Makes sure the context for `s.method` exists with these settings and holds frames up to
    /// `max`. Only between frames (the last one completed): it may allocate and submit.
    pub fn prepare(&mut self, backend: &mut dyn Backend, s: &MethodSettings, max: [u32; 3]) -> Result<()> {
        let grew = max.iter().zip(self.max).any(|(a, b)| *a > b);
        if grew {
            let grown = [max[0].max(self.max[0]), max[1].max(self.max[1]), max[2].max(self.max[2])];
            // The splatting context resizes itself; the others are made again on use.
            if let Some((_, ctx)) = &mut self.splat {
                ctx.resize(backend, grown[0], grown[1], grown[2])?;
            }
            if let Some(g) = self.gather.take() {
                g.destroy(backend);
            }
            if let Some(g) = self.ring_gather.take() {
                g.destroy(backend);
            }
            if let Some((_, b)) = self.bokeh.take() {
                b.destroy(backend);
            }
            self.max = grown;
        }
        let [w, h, l] = self.max;
        let mut made = true;
        match s.method {
            ViewMethod::Multilayer | ViewMethod::Tiled => {
                let key = MethodSettings { method: ViewMethod::Multilayer, ..s.clone() };
                if self.splat.as_ref().is_none_or(|(k, _)| *k != key) {
                    let options =
                        SplatOptions { tile: s.tile, merge: s.merge, aperture: parse_aperture(&s.aperture)?, ..Default::default() };
                    let mut desc = SplatContextDesc::new(w, h, l, options);
                    desc.image_io = true;
                    let ctx = SplatContext::new(backend, &desc)?;
                    if let Some((_, old)) = self.splat.replace((key, ctx)) {
                        old.destroy(backend);
                    }
                } else {
                    made = false;
                }
            }
            ViewMethod::Gather => {
                if self.gather.is_none() {
                    let mut desc = GatherContextDesc::new(w, h, l);
                    desc.image_io = true;
                    self.gather = Some(GatherContext::new(backend, &desc)?);
                } else {
                    made = false;
                }
            }
            ViewMethod::RingGather => {
                let options = RingGatherOptions { rings: s.rings, ..Default::default() };
                match &mut self.ring_gather {
                    Some(ctx) => {
                        ctx.set_options(options)?;
                        made = false;
                    }
                    None => {
                        let mut desc = RingGatherContextDesc::new(w, h, l);
                        desc.options = options;
                        desc.image_io = true;
                        self.ring_gather = Some(RingGatherContext::new(backend, &desc)?);
                    }
                }
            }
            ViewMethod::Bokeh => {
                if self.bokeh.as_ref().is_none_or(|(k, _)| *k != s.aperture) {
                    let options = BokehOptions { aperture: parse_aperture(&s.aperture)?, ..Default::default() };
                    let mut desc = BokehContextDesc::new(w, h, l, options);
                    desc.image_io = true;
                    let ctx = BokehContext::new(backend, &desc)?;
                    if let Some((_, old)) = self.bokeh.replace((s.aperture.clone(), ctx)) {
                        old.destroy(backend);
                    }
                } else {
                    made = false;
                }
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
        let missing = || anyhow::anyhow!("the context for {method:?} was not prepared");
        match method {
            ViewMethod::Multilayer | ViewMethod::Tiled => self.splat.as_mut().ok_or_else(missing)?.1.record(backend, frame)?,
            ViewMethod::Gather => self.gather.as_mut().ok_or_else(missing)?.record(backend, frame)?,
            ViewMethod::RingGather => self.ring_gather.as_mut().ok_or_else(missing)?.record(backend, frame)?,
            ViewMethod::Bokeh => self.bokeh.as_mut().ok_or_else(missing)?.1.record(backend, frame)?,
        }
        Ok(())
    }

    /// What the last frame of `method` left out or did, as lines for the screen. Reads the
    /// context's statistics back: call only once that frame completed (the viewer does it after
    /// its fence, for the frame before, a few times a second).
    pub fn report(&self, backend: &mut dyn Backend, method: ViewMethod) -> Result<Vec<String>> {
        Ok(match method {
            ViewMethod::Multilayer | ViewMethod::Tiled => match &self.splat {
                Some((_, ctx)) => {
                    let r = ctx.report(backend)?;
                    let rings = r.plan.as_ref().map_or(0, |p| p.rings);
                    let radius = r.plan.as_ref().map_or(0.0, |p| p.max_coc_radius);
                    vec![
                        format!("largest CoC radius {radius:.1} px, {rings} tile rings"),
                        format!("{} fragments tiled; merging replaced {} by {}", r.fragments, r.merged_inputs, r.merged),
                        format!("{} of {} tiles copied unblurred (in focus)", r.copy_tiles, r.tiles),
                        format!("list overflow: {} tiles, {} entries (pool {})", r.overflow_tiles, r.overflow_entries, r.list_capacity),
                        format!("dropped {} fragments, radius capped {}", r.dropped, r.capped),
                    ]
                }
                None => Vec::new(),
            },
            ViewMethod::Gather => match &self.gather {
                Some(ctx) => vec![format!("gather window radius {} px", ctx.radius(backend)?)],
                None => Vec::new(),
            },
            ViewMethod::RingGather => match &self.ring_gather {
                Some(ctx) => {
                    let o = ctx.options();
                    vec![format!(
                        "{} rings, {} samples a half-resolution pixel, CoC radius capped at {} px",
                        o.rings,
                        dof_shaders::ring_gather::samples(o.rings),
                        o.max_radius
                    )]
                }
                None => Vec::new(),
            },
            ViewMethod::Bokeh => match &self.bokeh {
                Some((_, ctx)) => {
                    let (detected, radius) = ctx.detected_and_radius(backend)?;
                    let capacity = BokehOptions::default().capacity as u64;
                    vec![format!(
                        "{detected} bright pixels as sprites ({} beyond the capacity), gather radius {radius} px",
                        detected.saturating_sub(capacity)
                    )]
                }
                None => Vec::new(),
            },
        })
    }

    pub fn destroy(self, backend: &mut dyn Backend) {
        if let Some((_, c)) = self.splat {
            c.destroy(backend);
        }
        if let Some(c) = self.gather {
            c.destroy(backend);
        }
        if let Some(c) = self.ring_gather {
            c.destroy(backend);
        }
        if let Some((_, c)) = self.bokeh {
            c.destroy(backend);
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
