//! `clock_offset`: the lux-meter logger's clock is offset from the device's, so readings are
//! matched to captures at the wrong time. Signature: the relative residual follows the rate
//! of change of the logged illuminance. Model: readings re-matched at the offset on the
//! logger's clock (interpolated between logs); visible only where the logger recorded a series
//! around the captures.

use super::fit::{pairs, pearson_r, scored};
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
        let Some(found) = fit_clock_offset(ctx.state, ctx.terms, ctx.fit) else {
            return Ok(None);
        };
        let mut parameters = BTreeMap::new();
        parameters.insert(PARAMETER.into(), found.state.get(CLOCK_OFFSET_S));
        let mut fitted = scored(ctx, found.state, parameters, found.evidence, None);
        if found.clear {
            fitted.found = super::Found::Series;
        }
        Ok(Some(fitted))
    }

    fn refresh(&self, state: &LoopState, parameters: &mut BTreeMap<String, f64>) {
        parameters.insert(PARAMETER.into(), state.get(CLOCK_OFFSET_S));
    }
}

/// Step of the coarse scan, s: the loggers' usual cadence (a reading every 30 s), so the
/// coarse minimum lies within one step of the true offset.
const COARSE_STEP_S: f64 = 30.0;

/// Fewest compared readings at a trial offset, as a fraction of the most at any: an offset
/// where the series no longer covers the captures compares fewer readings, whose error is
/// not comparable.
const MIN_COVERAGE: f64 = 0.8;

/// The scale-free error must fall by this fraction of itself at the fitted offset for the
/// offset to be identified apart (tried before the other effects, as a nuisance that changes
/// which readings are compared).
const CLEAR_FALL: f64 = 0.2;

/// A fitted offset.
struct Found {
    state: LoopState,
    evidence: String,
    /// The scale-free error fell clearly ([`CLEAR_FALL`]).
    clear: bool,
}

/// The fit set's readings at a logger offset: how many, and their mean |relative error|
/// after the best common factor on the model (least squares in the ratio), so a factor on
/// all light (dirty glazing) does not hide the timing.
fn scale_free_error(state: &LoopState, terms: &[Terms], fit: &FitSet<Sample>) -> (usize, f64) {
    let q: Vec<f64> = pairs(state, terms, fit)
        .iter()
        .map(|(p, m)| p / m)
        .filter(|q| q.is_finite())
        .collect();
    let (s1, s2) = q.iter().fold((0.0, 0.0), |(a, b), x| (a + x, b + x * x));
    if q.is_empty() || s2 <= 0.0 {
        return (0, f64::NAN);
    }
    let c = s1 / s2;
    let e = q.iter().map(|x| (c * x - 1.0).abs()).sum::<f64>() / q.len() as f64;
    (q.len(), e)
}

/// Fits the logger's clock offset: a scan of the scale-free fit-set error
/// ([`scale_free_error`]) over ±[`MAX_CLOCK_OFFSET_S`] in [`COARSE_STEP_S`] steps (offsets
/// whose readings cover under [`MIN_COVERAGE`] of the best-covered are left out), then 5 s and
/// 1 s steps around the best. `None` without logger series around the captures (one reading
/// per capture cannot show an offset) or if the best offset is the current one.
fn fit_clock_offset(state: &LoopState, terms: &[Terms], fit: &FitSet<Sample>) -> Option<Found> {
    let current = state.get(CLOCK_OFFSET_S);
    let dense = fit
        .samples()
        .iter()
        .any(|s| s.series.iter().any(|v| v.len() >= 5));
    if !dense {
        return None;
    }
    let at = |dt: f64| scale_free_error(&state.with(CLOCK_OFFSET_S, dt), terms, fit);
    let steps = (MAX_CLOCK_OFFSET_S / COARSE_STEP_S).round() as i32;
    let coarse: Vec<(f64, usize, f64)> = (-steps..=steps)
        .map(|k| {
            let dt = COARSE_STEP_S * k as f64;
            let (n, e) = at(dt);
            (dt, n, e)
        })
        .collect();
    let most = coarse.iter().map(|c| c.1).max().unwrap_or(0);
    let min_n = (MIN_COVERAGE * most as f64).ceil() as usize;
    let feasible = |n: usize, e: f64| n >= min_n.max(1) && e.is_finite();
    let mut best = (f64::INFINITY, current);
    for &(dt, n, e) in &coarse {
        if feasible(n, e) && e < best.0 {
            best = (e, dt);
        }
    }
    // Between two states of the sky (sun out, sun hidden) a shifted reading often finds the
    // same state: offsets away from the truth can match nearly as well. Among the coarse
    // offsets within the error's own noise of the best (a relative 1/√n over n readings),
    // the one nearest to no offset is taken: the smaller error of the logger's clock is the
    // likelier.
    let tolerance = 1.0 + 1.0 / (most.max(1) as f64).sqrt();
    if let Some(&(dt, _, e)) = coarse
        .iter()
        .filter(|(_, n, e)| feasible(*n, *e) && *e <= best.0 * tolerance)
        .min_by(|a, b| a.0.abs().total_cmp(&b.0.abs()))
    {
        best = (e, dt);
    }
    if std::env::var_os("SKYLUX_DEBUG_LOOP").is_some() {
        let curve: Vec<String> = coarse
            .iter()
            .filter(|c| c.2 <= 2.0 * best.0)
            .map(|c| format!("{:+.0}:{:.2}%({})", c.0, 100.0 * c.2, c.1))
            .collect();
        eprintln!("clock scan near the best: {}", curve.join(" "));
    }
    for (step, half) in [(5.0, 6), (1.0, 5)] {
        let centre = best.1;
        for k in -half..=half {
            let dt = centre + step * k as f64;
            if dt.abs() > MAX_CLOCK_OFFSET_S {
                continue;
            }
            let (n, e) = at(dt);
            if feasible(n, e) && e < best.0 {
                best = (e, dt);
            }
        }
    }
    // An offset shorter than two of the logger's intervals cannot be pinned: between two
    // readings the light is only interpolated, and where a cloud edge passes between them a
    // shift of up to an interval either way lowers the fit error by chance (+35 s with 30 s
    // logs and no offset in battery campaign #12, after a leak and the glazing's angular
    // loss had taken the rest of the residual).
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
    if !best.0.is_finite() || shift_s < 1.0 || shift_s < 2.0 * interval_s {
        return None;
    }
    let (_, e_current) = at(current);
    let clear = e_current.is_finite() && best.0 <= (1.0 - CLEAR_FALL) * e_current;
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
        "the relative residual follows the rate of change of the measured illuminance \
         (r = {r:.2} over {} readings): the readings are matched at the wrong time; \
         re-matched {:+.0} s later on the logger's clock, the error after a common factor \
         falls from {:.1} % to {:.1} %",
        xy.len(),
        best.1 - current,
        100.0 * e_current,
        100.0 * best.0
    );
    Some(Found {
        state: state.with(CLOCK_OFFSET_S, best.1),
        evidence,
        clear,
    })
}
