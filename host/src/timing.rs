//! Summaries of per-command times, shared by `dof bench` and the evaluation.

use crate::backend::CommandTime;
use std::collections::BTreeMap;

/// Time per stage label (commands with the same label summed), in label order.
pub fn stage_totals(times: &[CommandTime]) -> BTreeMap<String, f64> {
    let mut stages = BTreeMap::new();
    for t in times {
        *stages.entry(t.label.clone()).or_insert(0.0) += t.ms;
    }
    stages
}

/// The median (the upper one for an even count); 0 for no values.
pub fn median(mut values: Vec<f64>) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// Medians over runs: the total per run and each stage's time per run.
#[derive(Default)]
pub struct RunTimes {
    totals: Vec<f64>,
    stages: BTreeMap<String, Vec<f64>>,
}

impl RunTimes {
    /// Adds one run's command times.
    pub fn add(&mut self, times: &[CommandTime]) {
        let stages = stage_totals(times);
        self.totals.push(stages.values().fold(0.0, |a, b| a + b));
        for (label, ms) in stages {
            self.stages.entry(label).or_default().push(ms);
        }
    }

    pub fn median_total(&self) -> f64 {
        median(self.totals.clone())
    }

    pub fn median_stages(&self) -> BTreeMap<String, f64> {
        self.stages.iter().map(|(k, v)| (k.clone(), median(v.clone()))).collect()
    }

    /// Each stage's mean time per run over all runs (a time the queue could not stamp counts 0);
    /// NaN for a stage never timed at all (a clear on the wgpu backend, a queue without timestamps).
    pub fn mean_stages(&self) -> BTreeMap<String, f64> {
        let runs = self.totals.len().max(1) as f64;
        let mean = |v: &Vec<f64>| {
            let timed: Vec<f64> = v.iter().copied().filter(|t| t.is_finite()).collect();
            if timed.is_empty() { f64::NAN } else { timed.iter().sum::<f64>() / runs }
        };
        self.stages.iter().map(|(k, v)| (k.clone(), mean(v))).collect()
    }
}

/// How a timing run warms up: at least `frames` untimed frames, and on until `ms` of wall time have
/// passed (at most [`Warmup::MAX_FRAMES`]): a GPU raises its clocks only after some busy time, and
/// frames timed before that run several times slower.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Warmup {
    pub frames: u32,
    pub ms: f64,
}

impl Warmup {
    /// The longest warm-up `ms` makes.
    pub const MAX_FRAMES: u32 = 2000;

    /// One frame, and on Vulkan 500 ms: the CPU backend has no clocks of its own to raise.
    pub fn for_backend(kind: crate::backend::BackendKind) -> Warmup {
        Warmup { frames: 1, ms: if kind == crate::backend::BackendKind::Cpu { 0.0 } else { 500.0 } }
    }

    /// Runs `frame` as the warm-up asks (none for 0 frames); returns how many ran.
    pub fn run<E>(&self, mut frame: impl FnMut() -> Result<(), E>) -> Result<u32, E> {
        let start = std::time::Instant::now();
        let mut ran = 0;
        while ran < self.frames || (ran > 0 && ran < Self::MAX_FRAMES && start.elapsed().as_secs_f64() * 1e3 < self.ms) {
            frame()?;
            ran += 1;
        }
        Ok(ran)
    }
}

#[cfg(test)]
mod tests {
    use super::{RunTimes, Warmup};
    use crate::backend::CommandTime;
    use std::time::{Duration, Instant};

    /// A stage never timed is NaN ("not timed"), not 0; a stage timed in some runs is the mean of
    /// its times over all runs.
    #[test]
    fn stages_never_timed_are_nan() {
        let time = |label: &str, ms: f64| CommandTime { label: label.into(), kernel: "k", ms };
        let mut runs = RunTimes::default();
        runs.add(&[time("clear", f64::NAN), time("sort", 2.0), time("sort", 1.0)]);
        runs.add(&[time("clear", f64::NAN), time("sort", f64::NAN)]);
        let stages = runs.mean_stages();
        assert!(stages["clear"].is_nan());
        assert_eq!(stages["sort"], 1.5);
    }

    /// Runs a warm-up of frames that each take `frame_ms`; returns the frames run and the time.
    fn warm(frames: u32, ms: f64, frame_ms: u64) -> (u32, f64) {
        let start = Instant::now();
        let ran = Warmup { frames, ms }
            .run(|| -> Result<(), ()> {
                std::thread::sleep(Duration::from_millis(frame_ms));
                Ok(())
            })
            .unwrap();
        (ran, start.elapsed().as_secs_f64() * 1e3)
    }

    #[test]
    fn a_warm_up_runs_its_frames_then_on_until_its_time_has_passed() {
        // Frames of 5 ms and 60 ms of warm-up: more frames than asked, stopping once past it.
        let (ran, elapsed) = warm(2, 60.0, 5);
        assert!(ran > 2 && elapsed >= 60.0, "{ran} frames in {elapsed} ms");
        // Frames longer than the warm-up time: exactly the frames asked for.
        assert_eq!(warm(2, 10.0, 20).0, 2);
        // No time: the frames asked for; none asked, none run, whatever the time.
        assert_eq!(warm(3, 0.0, 1).0, 3);
        assert_eq!(warm(0, 50.0, 1).0, 0);
    }
}
