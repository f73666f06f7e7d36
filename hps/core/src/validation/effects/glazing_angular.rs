//! `glazing_angular`: the glazing's transmittance falls with the incidence angle more
//! than the scene's glass says (dirt, a coating, another glass).
//!
//! Model: ASHRAE's one-parameter incidence-angle modifier (Souka & Safwat 1966, "Determination
//! of the optimum orientations for the double-exposure, flat-plate collector and its
//! reflectors", Solar Energy 10(4); ASHRAE Standard 93; pvlib `iam.ashrae`, b0 = 0.05 for
//! clean glass): IAM(θ) = 1 − b0 (1/cos θ − 1), clamped to [0, 1]. Light crossing the
//! glazing at incidence θ is multiplied by IAM(θ) on top of the scene's glass.
//!
//! Since RADIANCE-style glass does not refract, light that reaches a sensor from the sky
//! direction d crossed the glazing at the angle between d and the glazing's outward normal:
//! each sky and ground bin of the daylight coefficients is rescaled by IAM at its centre's
//! incidence angle, the sun by IAM at the sun's, and the rows re-applied
//! ([`crate::validation::glazing::AngularGlazing`]). b0 is fitted on the fit set by a scan and golden-section
//! search ([`fit_glazing_angular`]). Signature: the residual of the sunlit readings falls
//! with the solar incidence angle on the glazing (over-prediction growing with the angle).
//!
//! Limitation: one glazing orientation (every plane facing the same way, as in the reference
//! room); with several, the loop does not try the effect.

use super::fit::{finite_or_worst, fit_error, fit_linear, FreeLinear};
use super::{FitContext, Fitted, Found, LoopEffect};
use crate::model::ModelError;
use crate::validation::diagnostics::Variable;
use crate::validation::glazing::{AngularGlazing, GLAZING_ANGULAR_B0};
use crate::validation::prediction::{predict, LoopState, CLOCK_OFFSET_S, GLAZING_TRANSMITTANCE};
use crate::validation::sample::Sample;
use crate::validation::split::FitSet;
use crate::validation::terms::Terms;
use glam::DVec3;
use std::collections::BTreeMap;

/// Largest b0 the fit considers (IAM(60°) = 0 at b0 = 1).
pub const MAX_B0: f64 = 1.0;

pub struct GlazingAngular;

impl LoopEffect for GlazingAngular {
    fn name(&self) -> &'static str {
        "glazing_angular"
    }

    fn aliases(&self) -> &'static [&'static str] {
        &["glazing_angular_b0"]
    }

    fn revealing_variable(&self) -> Option<(&'static str, Variable)> {
        // Its signature on the sunlit readings is the solar incidence angle; over all
        // readings the clearer one is the depth: near the façade the sky is seen through
        // the glazing at wider angles.
        Some(("sensor's distance from the façade (m)", |d| {
            d.facade_distance_m
        }))
    }

    fn fit(&self, ctx: &mut FitContext<'_>) -> Result<Option<Fitted>, ModelError> {
        // Its signature is read on the sunlit readings, whose direct part is the
        // concentrated sun's: while the sun is still spread over its patch, undersampling
        // dominates that residual and the angular fit would explain it away.
        let Some(glazing) = ctx.angular.filter(|_| ctx.state.model.concentrated_sun) else {
            return Ok(None);
        };
        // The terms do not carry the effect yet: it rescales their bins.
        Ok(fit_glazing_angular(
            glazing,
            ctx.state,
            ctx.accepted,
            ctx.terms,
            ctx.fit,
        ))
    }
}

/// Relative residual of the sunlit fit-set readings (modelled direct sun > 5 % of the
/// reading) against the solar incidence angle on the glazing (degrees, from the extracted
/// sun): (angle, residual) pairs.
fn sunlit_by_incidence(
    state: &LoopState,
    terms: &[Terms],
    fit: &FitSet<Sample>,
    normal_out: DVec3,
) -> Vec<(f64, f64)> {
    let (offset, tau) = (state.get(CLOCK_OFFSET_S), state.get(GLAZING_TRANSMITTANCE));
    let mut xy = Vec::new();
    for s in fit.samples() {
        let t = &terms[s.capture];
        let Some(sun) = &t.sun else { continue };
        let cos = sun.direction.dot(normal_out);
        if cos <= 0.0 {
            continue;
        }
        let p = predict(state, t);
        for (k, pk) in p.iter().enumerate() {
            let Some(m) = s.measured(k, offset).filter(|m| *m > 0.0) else {
                continue;
            };
            let direct = tau * t.sun_lux_per_dn_lux[k] * t.sun_dn_lux;
            if direct > 0.05 * m {
                xy.push((cos.clamp(-1.0, 1.0).acos().to_degrees(), pk / m - 1.0));
            }
        }
    }
    xy
}

/// Fits b0 on the fit set from `state` (whose b0 must be 0: `base` are the terms without the
/// effect), with the linear effects already `accepted` refitted at each trial. Returns the
/// candidate, its fit-set error and the terms with the effect. `None` if the best b0 is 0.
fn fit_glazing_angular(
    glazing: &AngularGlazing,
    state: &LoopState,
    accepted: &[&'static dyn LoopEffect],
    base: &[Terms],
    fit: &FitSet<Sample>,
) -> Option<Fitted> {
    let free = FreeLinear::of(accepted);
    let evaluate = |b0: f64| -> (f64, LoopState, Vec<Terms>) {
        let terms = glazing.apply(base, b0);
        let mut st = state.with(GLAZING_ANGULAR_B0, b0);
        if free.any() {
            if let Some(next) = fit_linear(&st, free, &terms, fit) {
                st = next;
            }
        }
        (finite_or_worst(fit_error(&st, &terms, fit)), st, terms)
    };
    // Scan, then golden section between the best's neighbours.
    let step = 0.025;
    let grid: Vec<f64> = (0..=(MAX_B0 / step).round() as usize)
        .map(|k| k as f64 * step)
        .collect();
    let errors: Vec<f64> = grid.iter().map(|&b| evaluate(b).0).collect();
    let i = (0..grid.len()).min_by(|&a, &b| errors[a].total_cmp(&errors[b]))?;
    if i == 0 {
        return None;
    }
    let (x, e) = crate::numerics::golden_section(
        grid[i - 1],
        grid.get(i + 1).copied().unwrap_or(MAX_B0),
        (grid[i], errors[i]),
        20,
        |b0| evaluate(b0).0,
    );
    let best = (e, x);
    let (err, next, terms) = evaluate(best.1);
    let xy = sunlit_by_incidence(state, base, fit, glazing.normal_out);
    let (r, slope) = crate::numerics::pearson(&xy).map_or((f64::NAN, f64::NAN), |p| (p.r, p.slope));
    // The diffuse part: near the façade a sensor sees the sky through the glazing at wider
    // angles, so the over-prediction falls with depth.
    let offset = state.get(CLOCK_OFFSET_S);
    let depth_xy: Vec<(f64, f64)> = fit
        .samples()
        .iter()
        .flat_map(|s| {
            let p = predict(state, &base[s.capture]);
            (0..p.len())
                .filter_map(|k| {
                    let m = s.measured(k, offset).filter(|m| *m > 0.0)?;
                    let depth = *glazing.sensor_depth_m.get(k)?;
                    depth.is_finite().then(|| (depth, p[k] / m - 1.0))
                })
                .collect::<Vec<_>>()
        })
        .collect();
    let (r_depth, _) =
        crate::numerics::pearson(&depth_xy).map_or((f64::NAN, f64::NAN), |p| (p.r, p.slope));
    let mut parameters = BTreeMap::new();
    parameters.insert("b0".into(), next.get(GLAZING_ANGULAR_B0));
    let evidence = format!(
        "the measured / modelled illuminance of the {} sunlit readings falls with the solar \
         incidence angle on the glazing: the relative residual (model / measured − 1) follows \
         the angle (r = {r:.2}, {:+.1} % per 10°), over-prediction growing with it, as a \
         transmittance that falls off with incidence faster than the scene's glass; and over \
         all {} readings the over-prediction falls with the sensor's distance from the façade \
         (r = {r_depth:.2}), whose sky is seen at wider angles near the glazing; ASHRAE \
         incidence-angle modifier fitted",
        xy.len(),
        1000.0 * slope,
        depth_xy.len()
    );
    Some(Fitted {
        state: next,
        parameters,
        evidence,
        fit_error: err,
        terms: Some(terms),
        captures: None,
        device: None,
        found: Found::Residual,
    })
}
