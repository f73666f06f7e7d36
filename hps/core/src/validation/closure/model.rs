//! A set of pyranometer effects fitted jointly to the closure residual.

use super::pyranometer_effects::PyranometerEffect;
use super::sample::ClosureSample;
use crate::numerics::linalg::least_squares_dropping_collinear;
use std::collections::BTreeMap;

/// A set of effects with jointly fitted coefficients; predicts the residual.
#[derive(Clone, Debug, PartialEq)]
pub struct ClosureModel {
    pub effects: Vec<PyranometerEffect>,
    /// Concatenated coefficients, [`PyranometerEffect::n_columns`] per effect.
    pub coefficients: Vec<f64>,
    /// Per coefficient: not fitted, because the effects before it already span its column.
    pub dropped: Vec<bool>,
}

impl ClosureModel {
    /// The base closure: no effect, the residual is r.
    pub fn base() -> Self {
        Self {
            effects: Vec::new(),
            coefficients: Vec::new(),
            dropped: Vec::new(),
        }
    }

    fn columns(effects: &[PyranometerEffect], s: &ClosureSample) -> Vec<f64> {
        effects
            .iter()
            .flat_map(|e| e.columns(s).into_iter().take(e.n_columns()))
            .collect()
    }

    /// The residual the effects predict for `s`.
    pub fn predicted_wm2(&self, s: &ClosureSample) -> f64 {
        Self::columns(&self.effects, s)
            .iter()
            .zip(&self.coefficients)
            .map(|(c, k)| c * k)
            .sum()
    }

    /// What remains of the residual once the effects are accounted for.
    pub fn corrected_wm2(&self, s: &ClosureSample) -> f64 {
        s.residual_wm2() - self.predicted_wm2(s)
    }

    /// One effect's share of the prediction.
    pub(super) fn contribution_wm2(&self, effect: PyranometerEffect, s: &ClosureSample) -> f64 {
        let mut k = 0;
        for &e in &self.effects {
            let n = e.n_columns();
            if e == effect {
                return e
                    .columns(s)
                    .iter()
                    .zip(&self.coefficients[k..k + n])
                    .map(|(c, x)| c * x)
                    .sum();
            }
            k += n;
        }
        0.0
    }

    /// Each effect's physical parameters.
    pub fn parameters(&self) -> Vec<(PyranometerEffect, BTreeMap<String, f64>)> {
        let mut k = 0;
        self.effects
            .iter()
            .map(|&e| {
                let n = e.n_columns();
                let p = e.parameters(&self.coefficients[k..k + n]);
                k += n;
                (e, p)
            })
            .collect()
    }

    /// Fits `effects` jointly by least squares on `samples` (daytime fit-set samples only),
    /// in order: a signature column that the effects before it already span is not fitted
    /// (coefficient 0, flagged in `dropped`). `None` for non-finite samples.
    pub fn fit(effects: &[PyranometerEffect], samples: &[&ClosureSample]) -> Option<Self> {
        let rows: Vec<Vec<f64>> = samples.iter().map(|s| Self::columns(effects, s)).collect();
        let y: Vec<f64> = samples.iter().map(|s| s.residual_wm2()).collect();
        let (coefficients, dropped) = least_squares_dropping_collinear(&rows, &y)?;
        Some(Self {
            effects: effects.to_vec(),
            coefficients,
            dropped,
        })
    }

    /// Coefficients actually fitted.
    pub fn active_columns(&self) -> usize {
        self.dropped.iter().filter(|d| !**d).count()
    }

    /// Whether every column of `effect` was dropped (nothing of it is identifiable).
    pub(super) fn all_dropped(&self, effect: PyranometerEffect) -> bool {
        let mut k = 0;
        for &e in &self.effects {
            let n = e.n_columns();
            if e == effect {
                return self.dropped[k..k + n].iter().all(|d| *d);
            }
            k += n;
        }
        false
    }
}
