//! Scoring the model on the hold-out set, and the one rule by which an effect is added.

use super::report::ErrorSummary;
use super::sample::Sample;
use super::split::{Comparison, Figure, HoldoutSet, Score};
use std::collections::BTreeMap;

/// The acceptance rule: the hold-out figure must fall, and by more than its block-to-block
/// noise (taken as 0 where it cannot be estimated).
pub fn improves(cmp: &Comparison) -> bool {
    cmp.gain > noise(cmp) && cmp.gain > 0.0
}

/// The comparison's noise, 0 where it cannot be estimated (fewer than two common blocks).
pub fn noise(cmp: &Comparison) -> f64 {
    if cmp.noise.is_finite() {
        cmp.noise
    } else {
        0.0
    }
}

/// Scores every (sample, sensor) reading of the hold-out set.
pub fn score(
    holdout: &HoldoutSet<Sample>,
    predict_capture: &dyn Fn(usize) -> Vec<f64>,
    sensors: &[String],
    clock_offset_s: f64,
) -> (Score, BTreeMap<String, Score>) {
    // `evaluate_grouped` takes one error per sample, so score each sensor and merge.
    let mut per_sensor = BTreeMap::new();
    let mut all_errors: Vec<Score> = Vec::new();
    for (k, name) in sensors.iter().enumerate() {
        let (s, _) = holdout.evaluate_grouped(|smp: &Sample| {
            let m = smp.measured(k, clock_offset_s)?;
            if m <= 0.0 {
                return None;
            }
            Some(((), predict_capture(smp.capture)[k] / m - 1.0))
        });
        per_sensor.insert(name.clone(), s.clone());
        all_errors.push(s);
    }
    // All readings: average the sensors' scores weighted by their counts, per block too.
    let merged = merge_scores(&all_errors);
    (merged, per_sensor)
}

/// Combines per-sensor scores of the same blocks into one (means weighted by counts).
fn merge_scores(scores: &[Score]) -> Score {
    let mut out = Score::default();
    let n: usize = scores.iter().map(|s| s.n).sum();
    if n == 0 {
        return out;
    }
    let nf = n as f64;
    out.n = n;
    out.mean = scores.iter().map(|s| s.mean * s.n as f64).sum::<f64>() / nf;
    out.mean_abs = scores.iter().map(|s| s.mean_abs * s.n as f64).sum::<f64>() / nf;
    out.rmse = (scores
        .iter()
        .map(|s| s.rmse * s.rmse * s.n as f64)
        .sum::<f64>()
        / nf)
        .sqrt();
    out.max_abs = scores.iter().map(|s| s.max_abs).fold(0.0, f64::max);
    let mut blocks: BTreeMap<i64, Vec<Score>> = BTreeMap::new();
    for s in scores {
        for (k, b) in &s.blocks {
            blocks.entry(*k).or_default().push(b.clone());
        }
    }
    out.blocks = blocks
        .into_iter()
        .map(|(k, v)| (k, merge_scores(&v)))
        .collect();
    out
}

pub fn summary(all: &Score, per: &BTreeMap<String, Score>, figure: Figure) -> ErrorSummary {
    ErrorSummary {
        all: all.figure(figure),
        per_sensor: per
            .iter()
            .map(|(k, s)| (k.clone(), s.figure(figure)))
            .collect(),
    }
}
