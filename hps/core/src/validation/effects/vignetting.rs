//! `vignetting`: the lens's relative illumination falls off more steeply than the declared
//! polynomial. Model: the true relative illumination is the declared V(α) times
//! `1 − v (α / 90°)²`, the leading term of the even radial polynomial 1 + a₂ r² + … that
//! models a lens's fall-off (Goldman, "Vignette and exposure calibration and compensation",
//! IEEE TPAMI 32(12), 2010), with the equidistant fisheye's image radius proportional to α;
//! applied to the map's bins by [`crate::validation::sky_geometry::correct_terms`].
//! Signature: the relative residual falls with the mean off-axis angle of the light reaching
//! the sensor. v is fitted by a scan of [0, 0.9] then a golden-section search.

use super::fit::{finite_or_worst, fit_error, minimise_1d, pearson_r, residual_points, scored};
use super::{FitContext, Fitted, LoopEffect};
use crate::model::ModelError;
use crate::validation::diagnostics::Variable;
use crate::validation::sky_geometry::{correct_terms, light_off_axis_deg, EXTRA_VIGNETTING};
use std::collections::BTreeMap;

pub struct Vignetting;

impl LoopEffect for Vignetting {
    fn name(&self) -> &'static str {
        "vignetting"
    }

    fn aliases(&self) -> &'static [&'static str] {
        &["extra_vignetting"]
    }

    fn revealing_variable(&self) -> Option<(&'static str, Variable)> {
        Some((
            "mean off-axis angle of the light reaching the sensor (deg)",
            |d| d.light_off_axis_deg,
        ))
    }

    fn fit(&self, ctx: &mut FitContext<'_>) -> Result<Option<Fitted>, ModelError> {
        Ok(fit_vignetting(ctx))
    }
}

/// Largest extra vignetting the fit considers.
pub const MAX_EXTRA_VIGNETTING: f64 = 0.9;

/// Fits the extra vignetting v on the fit set: the fit-set error of the terms corrected for
/// each trial v, minimised over [0, [`MAX_EXTRA_VIGNETTING`]]. `None` if the best v is under
/// 0.01 above the current one. Returns the candidate and its corrected terms.
fn fit_vignetting(ctx: &FitContext<'_>) -> Option<Fitted> {
    let (state, raw, dc, geometry, fit) = (
        ctx.state,
        ctx.sky_raw,
        &ctx.room.dc,
        ctx.sky_geometry,
        ctx.fit,
    );
    let error = |v: f64| {
        let st = state.with(EXTRA_VIGNETTING, v);
        finite_or_worst(fit_error(&st, &correct_terms(raw, dc, geometry, &st), fit))
    };
    let (v, _) = minimise_1d(&error, 0.0, MAX_EXTRA_VIGNETTING, 18);
    if v < state.get(EXTRA_VIGNETTING) + 0.01 {
        return None;
    }
    let next = state.with(EXTRA_VIGNETTING, v);
    // Signature: the relative residual grows (negative: under-read) with the off-axis angle
    // of the light reaching the sensor.
    let current = correct_terms(raw, dc, geometry, state);
    let xy = residual_points(state, &current, fit, |capture, t| {
        light_off_axis_deg(t, dc, geometry, capture)
    });
    let r = pearson_r(&xy);
    let mut parameters = BTreeMap::new();
    parameters.insert("extra_vignetting".into(), v);
    let evidence = format!(
        "the relative residual falls as the light reaching the sensors comes from further \
         off the lens's axis (r = {r:.2} over {} readings against its mean off-axis angle): \
         the lens's fall-off is steeper than the declared polynomial, by 1 − {v:.3} (α/90°)²",
        xy.len()
    );
    let terms = correct_terms(raw, dc, geometry, &next);
    Some(scored(ctx, next, parameters, evidence, Some(terms)))
}
