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
}
