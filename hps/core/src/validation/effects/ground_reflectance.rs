//! `ground_reflectance`: the ground the lens does not see reflects more or less than the
//! model's 0.2. Model: its reflectance ρ (the product's own parameter).
//!
//! Measured by the frames where they see the ground (the camera, 10-25° up, sees it below the
//! horizon at every capture): a Lambertian ground lit by the outdoor horizontal illuminance E
//! has the luminance ρ E / π, so each capture's seen ground bins give ρ = π L̄ / E, E the
//! pyranometer's (no lux-meter involved; the median over the captures). The unseen ground is
//! taken to reflect as the seen one. Where the frames see no ground, ρ is fitted jointly with
//! the other linear effects by least squares on the lux-meters; signature: the relative
//! residual follows the share of the prediction from the unseen ground.

use super::fit::{fit_linear, joint, pearson_r, readings, scored, FreeLinear};
use super::{FitContext, Fitted, Found, Linear, LoopEffect};
use crate::model::ModelError;
use crate::validation::diagnostics::Variable;
use crate::validation::prediction::{predict, LoopState, GLAZING_TRANSMITTANCE, GROUND_FROM_FRAMES};
use std::collections::BTreeMap;

const PARAMETER: &str = "reflectance";

/// Fewest captures whose frames see the ground for the frames to measure it.
const MIN_CAPTURES: usize = 3;

/// Least departure of the seen ground's reflectance from the declared one for the effect to be
/// named: the parameter's own tolerance (docs/loop.md, the battery's `TOLERANCES`), within
/// which a ground's reflectance varies over a view (paving, grass, shade), and four standard
/// errors of the captures' median.
const MIN_DEPARTURE: f64 = 0.1;

pub struct GroundReflectance;

impl LoopEffect for GroundReflectance {
    fn name(&self) -> &'static str {
        "ground_reflectance"
    }

    fn linear(&self) -> Option<Linear> {
        Some(Linear::Ground)
    }

    fn revealing_variable(&self) -> Option<(&'static str, Variable)> {
        Some(("share of light from the unseen ground", |d| {
            d.unseen_ground_share
        }))
    }

    fn fit(&self, ctx: &mut FitContext<'_>) -> Result<Option<Fitted>, ModelError> {
        if let Some(seen) = seen_ground(ctx) {
            return Ok(from_frames(ctx, seen));
        }
        let state = ctx.state;
        let mut zero = state.clone();
        zero.model.ground_reflectance = 0.0;
        let tau = state.get(GLAZING_TRANSMITTANCE);
        let rows: Vec<(f64, f64, f64)> = readings(state, ctx.terms, ctx.fit)
            .map(|(t, k, m)| {
                let per_rho = tau * t.unseen_ground_lux_per_cd_m2[k] * t.outdoor_horizontal_lux
                    / std::f64::consts::PI;
                (per_rho, predict(&zero, t)[k], m)
            })
            .collect();
        if rows.iter().all(|r| r.0 <= 0.0) {
            return Ok(None);
        }
        let Some(next) = joint(ctx, self) else {
            return Ok(None);
        };
        let mut parameters = BTreeMap::new();
        parameters.insert(PARAMETER.into(), next.model.ground_reflectance);
        let rho = state.model.ground_reflectance;
        let r = pearson_r(
            &rows
                .iter()
                .map(|(g, p, m)| (g / m, m / (p + rho * g) - 1.0))
                .collect::<Vec<_>>(),
        );
        let evidence = format!(
            "the relative residual follows the share of the prediction that comes from \
             ground the lens does not see (r = {r:.2})"
        );
        Ok(Some(scored(ctx, next, parameters, evidence, None)))
    }

    fn refresh(&self, state: &LoopState, parameters: &mut BTreeMap<String, f64>) {
        parameters.insert(PARAMETER.into(), state.model.ground_reflectance);
    }
}

/// The ground's reflectance the frames measure: median over the captures and its standard
/// error.
#[derive(Clone, Copy, Debug)]
struct SeenGround {
    reflectance: f64,
    standard_error: f64,
    captures: usize,
}

/// ρ = π L̄ / E per capture whose frames see ground bins (L̄ their mean luminance, E the
/// pyranometer's outdoor horizontal illuminance, else the map's); `None` under
/// [`MIN_CAPTURES`].
fn seen_ground(ctx: &FitContext<'_>) -> Option<SeenGround> {
    let mut per_capture: Vec<f64> = Vec::new();
    for (i, t) in ctx.terms.iter().enumerate() {
        let bins = &t.model.bins_without_sun_cd_m2;
        let n = bins.len() / 2;
        let seen: Vec<f64> = (n..2 * n)
            .filter(|&b| t.model.bin_seen.get(b) == Some(&true) && bins[b].is_finite())
            .map(|b| bins[b])
            .collect();
        let outdoor_lux = ctx
            .reference_outdoor
            .get(i)
            .copied()
            .flatten()
            .unwrap_or(t.model.outdoor_horizontal_lux);
        if seen.is_empty() || outdoor_lux.is_nan() || outdoor_lux <= 0.0 {
            continue;
        }
        let mean_cd_m2 = seen.iter().sum::<f64>() / seen.len() as f64;
        per_capture.push(std::f64::consts::PI * mean_cd_m2 / outdoor_lux);
    }
    if per_capture.len() < MIN_CAPTURES {
        return None;
    }
    let captures = per_capture.len();
    let (reflectance, standard_error) =
        crate::numerics::stats::median_and_standard_error(&mut per_capture);
    Some(SeenGround {
        reflectance,
        standard_error,
        captures,
    })
}

/// The effect as the frames measure it: named where the seen ground departs from the declared
/// reflectance by [`MIN_DEPARTURE`] and four standard errors, the accepted linear effects
/// refitted with ρ held; `None` where the frames show the declared ground.
fn from_frames(ctx: &FitContext<'_>, seen: SeenGround) -> Option<Fitted> {
    let declared = ctx.state.model.ground_reflectance;
    let departure = (seen.reflectance - declared).abs();
    if !seen.reflectance.is_finite()
        || departure < MIN_DEPARTURE
        || departure < 4.0 * seen.standard_error
    {
        return None;
    }
    let mut next = ctx.state.with(GROUND_FROM_FRAMES, 1.0);
    next.model.ground_reflectance = seen.reflectance;
    let free = FreeLinear::of(ctx.accepted);
    if free.any() {
        if let Some(refitted) = fit_linear(&next, free, ctx.terms, ctx.fit) {
            next = refitted;
        }
    }
    let mut parameters = BTreeMap::new();
    parameters.insert(PARAMETER.into(), seen.reflectance);
    let evidence = format!(
        "the frames see the ground reflect {:.3} ± {:.3} of the pyranometer's horizontal \
         illuminance (π L / E, median of {} captures; no lux-meter involved), not the declared \
         {declared:.2}; the ground the lens does not see taken to reflect as the seen one",
        seen.reflectance, seen.standard_error, seen.captures
    );
    let mut fitted = scored(ctx, next, parameters, evidence, None);
    fitted.found = Found::FramesMeasured;
    Some(fitted)
}
