//! `clock_offset`: the lux-meter logger's clock is offset from the device's, so readings are
//! matched to captures at the wrong time. Signature: the relative residual follows the rate
//! of change of the logged illuminance. Model: readings re-matched at the offset on the
//! logger's clock (interpolated between logs); visible only where the logger recorded a series
//! around the captures.

use super::fit::{finite_or_worst, fit_error, pearson_r, scored};
use super::{FitContext, Fitted, LoopEffect};
use crate::model::ModelError;
use crate::validation::diagnostics::Variable;
use crate::validation::prediction::{predict, LoopState, CLOCK_OFFSET_S};
use crate::validation::sample::{relative_rate_per_min, Sample, MAX_CLOCK_OFFSET_S};
use crate::validation::split::FitSet;
use crate::validation::terms::Terms;
use std::collections::BTreeMap;

const PARAMETER: &str = "logger_minus_device_s";

pub struct ClockOffset;

impl LoopEffect for ClockOffset {
    fn name(&self) -> &'static str {
        "clock_offset"
    }

    fn aliases(&self) -> &'static [&'static str] {
        &["clock_offset_s"]
    }

    fn revealing_variable(&self) -> Option<(&'static str, Variable)> {
        Some((
            "rate of change of the logged illuminance (relative, per minute)",
            |d| d.rate_of_change_per_min,
        ))
    }

    fn fit(&self, ctx: &mut FitContext<'_>) -> Result<Option<Fitted>, ModelError> {
        let Some((next, evidence)) = fit_clock_offset(ctx.state, ctx.terms, ctx.fit) else {
            return Ok(None);
        };
        let mut parameters = BTreeMap::new();
        parameters.insert(PARAMETER.into(), next.get(CLOCK_OFFSET_S));
        Ok(Some(scored(ctx, next, parameters, evidence, None)))
    }

    fn refresh(&self, state: &LoopState, parameters: &mut BTreeMap<String, f64>) {
        parameters.insert(PARAMETER.into(), state.get(CLOCK_OFFSET_S));
    }
}

/// Fits the logger's clock offset: a scan of the fit-set error over ±[`MAX_CLOCK_OFFSET_S`] in 10 s
/// steps, then 1 s steps around the best. `None` without logger series around the captures
/// (one reading per capture cannot show an offset) or if the best offset is the current one.
fn fit_clock_offset(
    state: &LoopState,
    terms: &[Terms],
    fit: &FitSet<Sample>,
) -> Option<(LoopState, String)> {
    let current = state.get(CLOCK_OFFSET_S);
    let dense = fit
        .samples()
        .iter()
        .any(|s| s.series.iter().any(|v| v.len() >= 5));
    if !dense {
        return None;
    }
    let at = |dt: f64| {
        let st = state.with(CLOCK_OFFSET_S, dt);
        (finite_or_worst(fit_error(&st, terms, fit)), st)
    };
    let mut best = (f64::INFINITY, 0.0);
    let steps = (MAX_CLOCK_OFFSET_S / 10.0) as i32;
    for k in -steps..=steps {
        let dt = 10.0 * k as f64;
        let (e, _) = at(dt);
        if e < best.0 {
            best = (e, dt);
        }
    }
    let coarse = best.1;
    for k in -10..=10 {
        let dt = coarse + k as f64;
        let (e, _) = at(dt);
        if e < best.0 {
            best = (e, dt);
        }
    }
    // An offset shorter than the logger's interval cannot be pinned: between two readings
    // the light is only interpolated, and on a changing sky a shift of a fraction of the
    // interval lowers the fit error by chance.
    let mut steps_s: Vec<f64> = fit
        .samples()
        .iter()
        .flat_map(|s| s.series.iter())
        .flat_map(|v| v.windows(2).map(|w| w[1].0 - w[0].0))
        .filter(|d| *d > 0.0)
        .collect();
    steps_s.sort_by(f64::total_cmp);
    let interval_s = steps_s.get(steps_s.len() / 2).copied().unwrap_or(0.0);
    let shift_s = (best.1 - current).abs();
    if !best.0.is_finite() || shift_s < 1.0 || shift_s < interval_s {
        return None;
    }
    // Signature: the residual follows the measured rate of change of the illuminance.
    let xy: Vec<(f64, f64)> = fit
        .samples()
        .iter()
        .flat_map(|s| {
            let p = predict(state, &terms[s.capture]);
            (0..s.series.len())
                .filter_map(|k| {
                    let m = s.measured(k, current)?;
                    let rate = relative_rate_per_min(&s.series[k], current);
                    (m > 0.0 && rate.is_finite()).then(|| (rate, p[k] / m - 1.0))
                })
                .collect::<Vec<_>>()
        })
        .collect();
    let r = pearson_r(&xy);
    let evidence = format!(
        "the relative residual follows the rate of change of the measured illuminance          (r = {r:.2} over {} readings): the readings are matched at the wrong time;          re-matched {:+.0} s later on the logger's clock",
        xy.len(),
        best.1 - current
    );
    Some((at(best.1).1, evidence))
}
