//! The fit / hold-out split by contiguous blocks of time, shaped so that hold-out data cannot
//! leak into a fit.
//!
//! Neighbouring minutes of a sky record are strongly correlated, so a random split would let
//! the fit see the hold-out times' twins and flatter the hold-out error. Blocks of time (half an
//! hour, a day) keep the two sets apart. The API carries the rule:
//! - [`FitSet`] hands out its samples: fitting code takes a `&FitSet<T>`.
//! - [`HoldoutSet`] never hands out a sample. The only way to its values is
//!   [`HoldoutSet::evaluate`], which maps each sample to an error and returns aggregate
//!   figures ([`Score`]), per set and per block; never the samples nor the per-sample errors.
//!
//! The error function given to `evaluate` must be a pure function of the sample and of a fitted
//! model; the type system cannot forbid a closure from smuggling samples out through interior
//! mutability, so that part is a rule for callers, checked in review.
//!
//! ```compile_fail
//! use skylux_hps::validation::split::{split, SplitPlan, Timed};
//! # struct S(chrono::DateTime<chrono::Utc>);
//! # impl Timed for S { fn time_utc(&self) -> chrono::DateTime<chrono::Utc> { self.0 } }
//! # let samples: Vec<S> = Vec::new();
//! # let plan: SplitPlan = todo!();
//! let (_fit, holdout) = split(samples, &plan).unwrap();
//! let leaked = holdout.samples; // private: hold-out samples are not reachable
//! ```

use chrono::{DateTime, TimeDelta, Utc};
use std::collections::BTreeMap;

/// Anything with an instant: a pyranometer row, a lux-meter reading.
pub trait Timed {
    fn time_utc(&self) -> DateTime<Utc>;
}

/// How times are cut into blocks and which blocks are held out.
///
/// Block `k` covers `[origin + k·block, origin + (k+1)·block)`; it is held out when
/// `k mod period == phase`. Alternate half-hours: `block` = 30 min, `period` = 2. One day in
/// three: `block` = 1 day, `origin` = a local midnight, `period` = 3.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SplitPlan {
    pub origin: DateTime<Utc>,
    pub block: TimeDelta,
    pub period: u32,
    pub phase: u32,
}

/// Why a split cannot be made.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum SplitError {
    #[error("split plan: block length must be positive, not {block}")]
    Block { block: TimeDelta },
    #[error(
        "split plan: period must be at least 2 (one fit and one hold-out block), not {period}"
    )]
    Period { period: u32 },
    #[error("split plan: phase {phase} must be below the period {period}")]
    Phase { phase: u32, period: u32 },
    #[error("split plan: time {time} is too far from the origin {origin} to number its block")]
    Range {
        time: DateTime<Utc>,
        origin: DateTime<Utc>,
    },
    #[error(
        "split: no fit samples ({n} samples in {blocks} blocks of {block}); use shorter blocks"
    )]
    EmptyFit {
        n: usize,
        blocks: usize,
        block: TimeDelta,
    },
    #[error(
        "split: no hold-out samples ({n} samples in {blocks} blocks of {block}); use shorter blocks"
    )]
    EmptyHoldout {
        n: usize,
        blocks: usize,
        block: TimeDelta,
    },
}

impl SplitPlan {
    /// Alternate blocks of `block`, counted from `origin`; odd blocks are held out.
    pub fn alternate(origin: DateTime<Utc>, block: TimeDelta) -> Result<Self, SplitError> {
        let plan = Self {
            origin,
            block,
            period: 2,
            phase: 1,
        };
        plan.check()?;
        Ok(plan)
    }

    fn check(&self) -> Result<(), SplitError> {
        if self.block <= TimeDelta::zero() {
            return Err(SplitError::Block { block: self.block });
        }
        if self.period < 2 {
            return Err(SplitError::Period {
                period: self.period,
            });
        }
        if self.phase >= self.period {
            return Err(SplitError::Phase {
                phase: self.phase,
                period: self.period,
            });
        }
        Ok(())
    }

    /// The index of the block holding `time` (negative before the origin).
    pub fn block_index(&self, time: DateTime<Utc>) -> Result<i64, SplitError> {
        self.check()?;
        let range = || SplitError::Range {
            time,
            origin: self.origin,
        };
        let since_ns = (time - self.origin).num_nanoseconds().ok_or_else(range)?;
        let block_ns = self.block.num_nanoseconds().ok_or_else(range)?;
        Ok(since_ns.div_euclid(block_ns))
    }

    /// Whether `time` falls in a hold-out block. Membership depends on the time only, never on
    /// a value, so two records that differ only in their values split identically.
    pub fn is_holdout(&self, time: DateTime<Utc>) -> Result<bool, SplitError> {
        let k = self.block_index(time)?;
        Ok(k.rem_euclid(i64::from(self.period)) == i64::from(self.phase))
    }
}

/// The samples a model may be fitted on, in their original order.
#[derive(Clone, Debug)]
pub struct FitSet<T> {
    samples: Vec<T>,
    blocks: Vec<i64>,
}

impl<T> FitSet<T> {
    pub fn samples(&self) -> &[T] {
        &self.samples
    }

    /// Block index of each sample (as [`SplitPlan::block_index`]), for block-wise checks inside
    /// the fit set.
    pub fn block_indices(&self) -> &[i64] {
        &self.blocks
    }

    pub fn len(&self) -> usize {
        self.samples.len()
    }

    pub fn is_empty(&self) -> bool {
        self.samples.is_empty()
    }
}

impl<T: Timed> FitSet<T> {
    pub fn times(&self) -> Vec<DateTime<Utc>> {
        self.samples.iter().map(Timed::time_utc).collect()
    }
}

/// The held-out samples: reachable only through [`HoldoutSet::evaluate`].
#[derive(Debug)]
pub struct HoldoutSet<T> {
    samples: Vec<T>,
    blocks: Vec<i64>,
}

/// Aggregate error figures of one set or one block (errors in the caller's units).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Score {
    /// Samples that had an error (the error function returned a finite value).
    pub n: usize,
    /// Mean signed error (bias).
    pub mean: f64,
    pub mean_abs: f64,
    pub rmse: f64,
    pub max_abs: f64,
    /// The same figures per block, by block index; empty for a block's own score.
    pub blocks: BTreeMap<i64, Score>,
}

/// Which figure of a [`Score`] a comparison uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Figure {
    MeanAbs,
    Rmse,
}

impl Score {
    pub fn figure(&self, figure: Figure) -> f64 {
        match figure {
            Figure::MeanAbs => self.mean_abs,
            Figure::Rmse => self.rmse,
        }
    }

    fn from_errors(errors: &[(i64, f64)]) -> Score {
        let mut by_block: BTreeMap<i64, Vec<f64>> = BTreeMap::new();
        for &(b, e) in errors {
            by_block.entry(b).or_default().push(e);
        }
        let mut all = Self::flat(errors.iter().map(|&(_, e)| e));
        all.blocks = by_block
            .into_iter()
            .map(|(b, es)| (b, Self::flat(es.into_iter())))
            .collect();
        all
    }

    fn flat(errors: impl Iterator<Item = f64>) -> Score {
        let (mut n, mut sum, mut sum_abs, mut sum_sq, mut max_abs) =
            (0usize, 0.0, 0.0, 0.0, 0.0f64);
        for e in errors {
            n += 1;
            sum += e;
            sum_abs += e.abs();
            sum_sq += e * e;
            max_abs = max_abs.max(e.abs());
        }
        if n == 0 {
            return Score::default();
        }
        let nf = n as f64;
        Score {
            n,
            mean: sum / nf,
            mean_abs: sum_abs / nf,
            rmse: (sum_sq / nf).sqrt(),
            max_abs,
            blocks: BTreeMap::new(),
        }
    }
}

/// How much a figure fell from `before` to `after`, and how noisy that fall is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Comparison {
    /// `before - after` over the whole set (positive: `after` is better).
    pub gain: f64,
    /// Standard error of the gain from its spread over blocks: the standard deviation of the
    /// per-block gains over √(blocks). Infinite with fewer than two common blocks (no estimate).
    pub noise: f64,
    /// Blocks present in both scores.
    pub blocks: usize,
}

/// Compares two scores of the same set, block by block (paired, so the block-to-block spread of
/// the data itself cancels).
pub fn compare(before: &Score, after: &Score, figure: Figure) -> Comparison {
    let gain = before.figure(figure) - after.figure(figure);
    let diffs: Vec<f64> = before
        .blocks
        .iter()
        .filter_map(|(k, b)| {
            after
                .blocks
                .get(k)
                .map(|a| b.figure(figure) - a.figure(figure))
        })
        .collect();
    let m = diffs.len();
    let noise = if m < 2 {
        f64::INFINITY
    } else {
        let mean = diffs.iter().sum::<f64>() / m as f64;
        let var = diffs.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / (m - 1) as f64;
        (var / m as f64).sqrt()
    };
    Comparison {
        gain,
        noise,
        blocks: m,
    }
}

impl<T> HoldoutSet<T> {
    /// Maps every hold-out sample to its error (`None` or a non-finite value: not counted) and
    /// returns the aggregate figures only.
    pub fn evaluate<F: Fn(&T) -> Option<f64>>(&self, error: F) -> Score {
        let errors: Vec<(i64, f64)> = self
            .samples
            .iter()
            .zip(&self.blocks)
            .filter_map(|(s, &b)| error(s).filter(|e| e.is_finite()).map(|e| (b, e)))
            .collect();
        Score::from_errors(&errors)
    }

    /// As [`Self::evaluate`], also per group (e.g. per sensor): the function returns the
    /// sample's group and error.
    pub fn evaluate_grouped<K: Ord + Clone, F: Fn(&T) -> Option<(K, f64)>>(
        &self,
        error: F,
    ) -> (Score, BTreeMap<K, Score>) {
        let mut all = Vec::new();
        let mut groups: BTreeMap<K, Vec<(i64, f64)>> = BTreeMap::new();
        for (s, &b) in self.samples.iter().zip(&self.blocks) {
            if let Some((k, e)) = error(s) {
                if e.is_finite() {
                    all.push((b, e));
                    groups.entry(k).or_default().push((b, e));
                }
            }
        }
        (
            Score::from_errors(&all),
            groups
                .into_iter()
                .map(|(k, es)| (k, Score::from_errors(&es)))
                .collect(),
        )
    }

    pub fn len(&self) -> usize {
        self.samples.len()
    }

    pub fn is_empty(&self) -> bool {
        self.samples.is_empty()
    }
}

impl<T: Timed> HoldoutSet<T> {
    /// The hold-out instants (for the report); times carry no measured value.
    pub fn times(&self) -> Vec<DateTime<Utc>> {
        self.samples.iter().map(Timed::time_utc).collect()
    }
}

/// Splits `samples` by `plan`; both sets keep the original order. Errors if either set would
/// be empty.
pub fn split<T: Timed>(
    samples: Vec<T>,
    plan: &SplitPlan,
) -> Result<(FitSet<T>, HoldoutSet<T>), SplitError> {
    plan.check()?;
    let n = samples.len();
    let mut fit = FitSet {
        samples: Vec::new(),
        blocks: Vec::new(),
    };
    let mut holdout = HoldoutSet {
        samples: Vec::new(),
        blocks: Vec::new(),
    };
    let mut seen = std::collections::BTreeSet::new();
    for s in samples {
        let t = s.time_utc();
        let k = plan.block_index(t)?;
        seen.insert(k);
        if plan.is_holdout(t)? {
            holdout.samples.push(s);
            holdout.blocks.push(k);
        } else {
            fit.samples.push(s);
            fit.blocks.push(k);
        }
    }
    if fit.samples.is_empty() {
        return Err(SplitError::EmptyFit {
            n,
            blocks: seen.len(),
            block: plan.block,
        });
    }
    if holdout.samples.is_empty() {
        return Err(SplitError::EmptyHoldout {
            n,
            blocks: seen.len(),
            block: plan.block,
        });
    }
    Ok((fit, holdout))
}

#[cfg(test)]
mod tests {
    use super::*;
    use chrono::TimeZone;

    #[derive(Clone, Debug)]
    struct Reading {
        time: DateTime<Utc>,
        x: f64,
        y: f64,
    }

    impl Timed for Reading {
        fn time_utc(&self) -> DateTime<Utc> {
            self.time
        }
    }

    fn origin() -> DateTime<Utc> {
        Utc.with_ymd_and_hms(2016, 1, 1, 0, 0, 0).unwrap()
    }

    /// One reading a minute for `minutes`, y = 2x + 1 with a small deterministic wiggle.
    fn readings(minutes: i64) -> Vec<Reading> {
        (0..minutes)
            .map(|m| {
                let x = m as f64 / 60.0;
                Reading {
                    time: origin() + TimeDelta::minutes(m),
                    x,
                    y: 2.0 * x + 1.0 + 0.1 * (m as f64 * 0.7).sin(),
                }
            })
            .collect()
    }

    /// Least-squares line through the fit set: it can only take a `FitSet`.
    fn fit_line(fit: &FitSet<Reading>) -> (f64, f64) {
        let s = fit.samples();
        let n = s.len() as f64;
        let (sx, sy) = (
            s.iter().map(|r| r.x).sum::<f64>(),
            s.iter().map(|r| r.y).sum::<f64>(),
        );
        let sxx = s.iter().map(|r| r.x * r.x).sum::<f64>();
        let sxy = s.iter().map(|r| r.x * r.y).sum::<f64>();
        let slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
        (slope, (sy - slope * sx) / n)
    }

    /// The fit does not change when every hold-out value is altered, while the hold-out
    /// evaluation does: hold-out values reach the evaluation and nothing else.
    #[test]
    fn altering_holdout_values_changes_evaluation_not_fit() {
        let plan = SplitPlan::alternate(origin(), TimeDelta::minutes(30)).unwrap();
        let clean = readings(240);
        let mut altered = clean.clone();
        let mut changed = 0;
        for r in &mut altered {
            if plan.is_holdout(r.time).unwrap() {
                r.y += 1000.0 * (r.x + 1.0);
                changed += 1;
            }
        }
        assert_eq!(changed, 120);
        let (fit_a, hold_a) = split(clean, &plan).unwrap();
        let (fit_b, hold_b) = split(altered, &plan).unwrap();
        let (la, lb) = (fit_line(&fit_a), fit_line(&fit_b));
        assert_eq!(la, lb);
        let err = |line: (f64, f64)| move |r: &Reading| Some(line.0 * r.x + line.1 - r.y);
        let (ea, eb) = (hold_a.evaluate(err(la)), hold_b.evaluate(err(lb)));
        assert!(ea.rmse < 0.2, "clean hold-out rmse {}", ea.rmse);
        assert!(eb.rmse > 100.0, "altered hold-out rmse {}", eb.rmse);
        assert_eq!(ea.n, 120);
        assert_eq!(ea.blocks.len(), 4);
    }

    /// Blocks are contiguous and alternate; sets keep order; membership is by time alone.
    #[test]
    fn alternate_blocks_are_contiguous() {
        let plan = SplitPlan::alternate(origin(), TimeDelta::minutes(30)).unwrap();
        let (fit, hold) = split(readings(120), &plan).unwrap();
        assert_eq!(fit.block_indices(), [vec![0; 30], vec![2; 30]].concat());
        assert_eq!(hold.len(), 60);
        let t = hold.times();
        assert_eq!(t[0], origin() + TimeDelta::minutes(30));
        assert_eq!(t[59], origin() + TimeDelta::minutes(119));
        assert!(fit.times().windows(2).all(|w| w[0] < w[1]));
        // Before the origin, blocks count down: minute −1 is block −1 (held out).
        assert_eq!(plan.block_index(origin() - TimeDelta::minutes(1)), Ok(-1));
        assert_eq!(plan.is_holdout(origin() - TimeDelta::minutes(1)), Ok(true));
    }

    #[test]
    fn bad_plans_and_empty_sets_are_errors() {
        assert!(matches!(
            SplitPlan::alternate(origin(), TimeDelta::zero()),
            Err(SplitError::Block { .. })
        ));
        let mut plan = SplitPlan::alternate(origin(), TimeDelta::days(1)).unwrap();
        assert!(matches!(
            split(readings(60), &plan),
            Err(SplitError::EmptyHoldout {
                n: 60,
                blocks: 1,
                ..
            })
        ));
        plan.phase = 0;
        assert!(matches!(
            split(readings(60), &plan),
            Err(SplitError::EmptyFit { .. })
        ));
        plan.phase = 2;
        assert!(matches!(
            split(readings(60), &plan),
            Err(SplitError::Phase { .. })
        ));
        plan.period = 1;
        assert!(matches!(
            split(readings(60), &plan),
            Err(SplitError::Period { .. })
        ));
        let far = SplitPlan {
            origin: DateTime::<Utc>::MIN_UTC,
            ..SplitPlan::alternate(origin(), TimeDelta::minutes(1)).unwrap()
        };
        assert!(matches!(
            split(readings(3), &far),
            Err(SplitError::Range { .. })
        ));
    }

    /// The paired comparison: a uniform improvement is certain (zero noise), a random
    /// reshuffle of errors is not.
    #[test]
    fn comparison_gain_and_noise() {
        let plan = SplitPlan::alternate(origin(), TimeDelta::minutes(10)).unwrap();
        let (_, hold) = split(readings(240), &plan).unwrap();
        let before = hold.evaluate(|r| Some(r.y - 2.0 * r.x - 1.0 + 0.5));
        let after = hold.evaluate(|r| Some(r.y - 2.0 * r.x - 1.0));
        let c = compare(&before, &after, Figure::Rmse);
        assert!(c.gain > 0.3, "{c:?}");
        assert!(c.noise < c.gain / 5.0, "{c:?}");
        assert_eq!(c.blocks, 12);
        let same = compare(&after, &after, Figure::MeanAbs);
        assert_eq!((same.gain, same.noise), (0.0, 0.0));
        let empty = compare(&Score::default(), &Score::default(), Figure::Rmse);
        assert!(empty.noise.is_infinite());
        // Non-finite errors are not counted.
        let partial = hold.evaluate(|r| Some(if r.x < 1.0 { f64::NAN } else { 1.0 }));
        assert_eq!(partial.n, 90);
        let (all, groups) =
            hold.evaluate_grouped(|r| Some((if r.x < 2.0 { "a" } else { "b" }, r.x)));
        assert_eq!(all.n, 120);
        assert_eq!(groups["a"].n + groups["b"].n, 120);
    }
}
