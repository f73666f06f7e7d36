//! Scoring the model on the hold-out set, and the one rule by which an effect is added.

use super::report::ErrorSummary;
use super::sample::Sample;
use super::split::{Comparison, Figure, HoldoutSet, Score};
use std::collections::BTreeMap;

/// One-sided significance level of the acceptance test: the chance that an effect which does
/// not help the hold-out set passes the paired test by the blocks' noise alone. The loop
/// tests one candidate (the best single, then the best pair) per round, so the chance of a
/// false discovery in a round is at most about twice this.
pub const ACCEPT_ALPHA: f64 = 0.05;

/// Smallest fall of the hold-out error, as a fraction of the error itself, for an effect to
/// be named. Against an independent world the declared model is never exact (its daylight
/// coefficients are discretised, the sky between patches is interpolated, the lux-meters have
/// a calibration): any flexible effect absorbs a consistent part of that error and passes a
/// pure significance test. What separates an effect from model error is its size: a light
/// leak fitted to model error alone lowered the hold-out error by 10 % of itself (4.9 % to
/// 4.4 %, a RADIANCE-truth campaign without effects), a leak riding along a ground-reflectance
/// campaign by 13 % (1.11 % to 0.97 %), while every effect of the test campaigns lowers it by
/// 47 % or more (docs/loop.md, "Acceptance"; the battery's figures are in BENCHMARKS.md).
pub const MIN_RELATIVE_GAIN: f64 = 0.2;

/// Fewest units (hold-out captures or blocks) for the paired test.
pub const MIN_TEST_UNITS: usize = 2;

/// A hold-out capture's comparison (prediction over measurement) must change by this much
/// (mean |relative change| over its sensors) for the capture to count in the acceptance test:
/// a capture where the candidate
/// changes nothing (an overcast day for an effect on the sun) carries no evidence either way.
/// Decided by how much the comparison moves, never by whether it improves, so selecting the
/// units does not bias the test.
pub const ACTING_CHANGE: f64 = 0.005;

/// The outcome of the acceptance test.
#[derive(Clone, Copy, Debug)]
pub struct Verdict {
    pub accepted: bool,
    /// The fall of the hold-out figure over all blocks.
    pub gain: f64,
    /// The paired t statistic of the per-unit gains.
    pub t: f64,
    /// The one-sided critical value at [`ACCEPT_ALPHA`] for the units' degrees of freedom.
    pub t_critical: f64,
    /// Units in the test.
    pub units: usize,
    /// The gain over the figure before.
    pub relative_gain: f64,
    /// Judged as a confirmation of an effect identified without the lux-meters
    /// ([`Verdict::confirming`]).
    pub confirmation: bool,
}

impl Verdict {
    /// The rule for an effect identified and measured without the lux-meters: the hold-out
    /// error falls relevantly (by [`MIN_RELATIVE_GAIN`] of itself) and the paired test shows
    /// no significant rise. Its false-discovery control is the identifying evidence's.
    pub fn confirming(self) -> Self {
        Self {
            accepted: self.gain > 0.0
                && self.relative_gain >= MIN_RELATIVE_GAIN
                && !(self.t < -self.t_critical),
            confirmation: true,
            ..self
        }
    }

    /// One line for the report: the statistic against its threshold.
    pub fn describe(&self) -> String {
        if self.confirmation {
            return format!(
                "identified without the lux-meters; confirmed by the hold-out set: gain {:.2}                  points ({:.0} % of the error; needs {:.0} %), t = {:.1} over {} units (no                  significant rise: above −{:.2})",
                100.0 * self.gain,
                100.0 * self.relative_gain,
                100.0 * MIN_RELATIVE_GAIN,
                self.t,
                self.units,
                self.t_critical
            );
        }
        format!(
            "gain {:.2} points ({:.0} % of the error; needs {:.0} %), t = {:.1} over {} \
             units (needs {:.2}, one-sided α = {})",
            100.0 * self.gain,
            100.0 * self.relative_gain,
            100.0 * MIN_RELATIVE_GAIN,
            self.t,
            self.units,
            self.t_critical,
            ACCEPT_ALPHA
        )
    }
}

/// The acceptance rule: the hold-out figure falls significantly (a paired one-sided t test of
/// the per-unit falls `diffs` at [`ACCEPT_ALPHA`]: the relative falls at the hold-out captures
/// where the candidate acts, or the sun sightings') and relevantly (from `before` to `after` over the whole hold-out set,
/// by at least [`MIN_RELATIVE_GAIN`] of itself).
pub fn judge(diffs: &[f64], before: f64, after: f64) -> Verdict {
    let units: Vec<(f64, f64)> = diffs.iter().map(|&d| (d, 1.0)).collect();
    judge_weighted(&units, before, after)
}

/// [`judge`] with a weight per unit `(fall, weight)`: a weighted paired t test, the mean and
/// variance weighted (reliability weights) and the degrees of freedom from Kish's effective
/// number of units, (Σw)² / Σw² (Kish 1965, *Survey Sampling*, §11.7); equal weights give the
/// ordinary test. The loop weights each hold-out capture by how much the candidate moves its
/// comparison: an effect that acts strongly at three captures and leaves the others at the
/// noise (a clock offset on a day when the sun comes and goes) is judged on those three, not
/// drowned by the noise of the rest. The weights never depend on whether the capture
/// improved, so they do not bias the test.
pub fn judge_weighted(units: &[(f64, f64)], before: f64, after: f64) -> Verdict {
    let units: Vec<(f64, f64)> = units
        .iter()
        .copied()
        .filter(|(d, w)| d.is_finite() && w.is_finite() && *w > 0.0)
        .collect();
    let sw: f64 = units.iter().map(|u| u.1).sum();
    let sw2: f64 = units.iter().map(|u| u.1 * u.1).sum();
    let n_eff = if sw2 > 0.0 { sw * sw / sw2 } else { 0.0 };
    // Kish's n rounded to the nearest unit (so that equal weights give exactly n), at least 1.
    let m = if units.is_empty() {
        0
    } else {
        (n_eff.round() as usize).max(1)
    };
    let mean = if sw > 0.0 {
        units.iter().map(|(d, w)| w * d).sum::<f64>() / sw
    } else {
        0.0
    };
    let se = if m >= 2 {
        let var = units
            .iter()
            .map(|(d, w)| w * (d - mean).powi(2))
            .sum::<f64>()
            / (sw - sw2 / sw);
        (var / n_eff).sqrt()
    } else {
        f64::NAN
    };
    let t = if se > 0.0 {
        mean / se
    } else if se == 0.0 && mean > 0.0 {
        f64::INFINITY
    } else {
        f64::NAN
    };
    let t_critical = if m >= MIN_TEST_UNITS {
        t_one_sided_95(m - 1)
    } else {
        f64::INFINITY
    };
    let gain = before - after;
    let relative_gain = if before > 0.0 { gain / before } else { 0.0 };
    Verdict {
        accepted: gain > 0.0 && t > t_critical && relative_gain >= MIN_RELATIVE_GAIN,
        gain,
        t,
        t_critical,
        units: m,
        relative_gain,
        confirmation: false,
    }
}

/// Student's t quantile at 0.95 for `df` degrees of freedom (one-sided α = 0.05): the
/// standard table (e.g. NIST/SEMATECH e-Handbook of Statistical Methods, §1.3.6.7.2), the
/// normal quantile 1.645 beyond 30.
fn t_one_sided_95(df: usize) -> f64 {
    const TABLE: [f64; 30] = [
        6.314, 2.920, 2.353, 2.132, 2.015, 1.943, 1.895, 1.860, 1.833, 1.812, 1.796, 1.782, 1.771,
        1.761, 1.753, 1.746, 1.740, 1.734, 1.729, 1.725, 1.721, 1.717, 1.714, 1.711, 1.708, 1.706,
        1.703, 1.701, 1.699, 1.697,
    ];
    match df {
        0 => f64::INFINITY,
        d if d <= 30 => TABLE[d - 1],
        _ => 1.645,
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Falls 1, 2, 3: mean 2, standard deviation 1, t = 2 √3 = 3.464 against 2.920 (df 2).
    #[test]
    fn the_paired_test_matches_the_textbook() {
        let v = judge(&[1.0, 2.0, 3.0], 1.0, 0.5);
        assert!((v.t - 2.0 * 3f64.sqrt()).abs() < 1e-12, "{v:?}");
        assert_eq!((v.units, v.t_critical), (3, 2.920));
        assert!(v.accepted);
        let w = judge_weighted(&[(1.0, 7.0), (2.0, 7.0), (3.0, 7.0)], 1.0, 0.5);
        assert!((w.t - v.t).abs() < 1e-12 && w.units == 3, "{w:?}");
    }

    /// Significant but small: a consistent fall of 10 % of the error is model error absorbed,
    /// not an effect.
    #[test]
    fn a_small_consistent_fall_is_not_relevant() {
        let v = judge(&[0.05, 0.06, 0.05, 0.04, 0.05], 0.049, 0.044);
        assert!(v.t > v.t_critical && !v.accepted, "{v:?}");
    }

    /// One hold-out capture shows an overhead the frames measured: no paired test over one
    /// unit passes, the confirmation does; a rise is never confirmed.
    #[test]
    fn an_effect_identified_apart_is_confirmed_by_a_relevant_fall() {
        let one = judge_weighted(&[(0.74, 0.46)], 0.11, 0.03);
        assert!(!one.accepted);
        assert!(one.confirming().accepted, "{:?}", one.confirming());
        let rise = judge(&[-0.3, -0.4, -0.35, -0.5], 0.02, 0.04);
        assert!(!rise.confirming().accepted);
        let small = judge_weighted(&[(0.74, 0.46)], 0.11, 0.10);
        assert!(!small.confirming().accepted);
    }
}
