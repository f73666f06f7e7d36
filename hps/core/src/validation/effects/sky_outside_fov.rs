//! `sky_outside_fov`: a housing or baffle clips the image beyond some off-axis angle, so the
//! map has no valid groups there, the sky patches beyond are filled by
//! [`crate::sky::SkyPatches::aggregate`]'s extrapolation from the nearest seen patches, and
//! the room's view of that sky is mis-estimated.
//!
//! Signature: the field of view the maps show (the largest off-axis angle with valid or
//! over-range groups) is narrower than the declared lens images onto the readout, and the
//! residual follows the unseen sky's share of the daylight-coefficient weight. Model: the
//! filled luminance of every unseen sky patch times a factor k (the extrapolation's bias:
//! the low sky beyond the field is brighter or darker than the seen rows suggest), fitted on
//! the fit set by a 1-D minimisation; the terms are re-computed per trial k from the per-bin
//! luminances ([`crate::validation::sky_geometry::correct_terms`]).
//!
//! The largest part of the sky beyond the field is, in a room with a sunlit window, the sun
//! itself: where SPA puts it inside the declared lens's image but outside the field the maps
//! show, the map cannot measure it, and the model takes its direct-normal illuminance from
//! the pyranometer (the Perez 1990 luminous efficacy, as the loop's Perez baseline and
//! outdoor illuminance do), as a concentrated source.

use super::fit::{
    finite_or_worst, fit_error, minimise_1d, pearson_r, residual_points, residuals_where, scored,
};
use super::{FitContext, Fitted, Found, LoopEffect};
use crate::model::ModelError;
use crate::validation::diagnostics::Variable;
use crate::validation::sky_geometry::{correct_terms, MIN_CLIPPED_DEG, UNSEEN_SKY_FACTOR};
use std::collections::BTreeMap;

pub struct SkyOutsideFov;

impl LoopEffect for SkyOutsideFov {
    fn name(&self) -> &'static str {
        "sky_outside_fov"
    }

    /// The simulator's world parameter: the baffle's field of view, degrees.
    fn aliases(&self) -> &'static [&'static str] {
        &["fov_limit_deg"]
    }

    fn revealing_variable(&self) -> Option<(&'static str, Variable)> {
        Some((
            "unseen sky fraction of the daylight-coefficient weight",
            |d| d.unseen_sky_fraction,
        ))
    }

    fn fit(&self, ctx: &mut FitContext<'_>) -> Result<Option<Fitted>, ModelError> {
        Ok(fit_unseen_sky(ctx))
    }
}

/// Range of the unseen-sky factor the fit considers.
pub const UNSEEN_SKY_FACTOR_RANGE: (f64, f64) = (0.2, 4.0);

/// Fits the unseen-sky factor k on the fit set when the maps show a clipped field of view.
/// Returns the candidate (parameters: the field of view the maps show, degrees, and k) and
/// its corrected terms.
fn fit_unseen_sky(ctx: &FitContext<'_>) -> Option<Fitted> {
    let (state, raw, dc, geometry, fit) = (
        ctx.state,
        ctx.sky_raw,
        &ctx.room.dc,
        ctx.sky_geometry,
        ctx.fit,
    );
    let shown = geometry.median_shown_fov_deg();
    if !shown.is_finite() || geometry.lens_fov_deg - shown < MIN_CLIPPED_DEG {
        return None;
    }
    let error = |k: f64| {
        let st = state.with(UNSEEN_SKY_FACTOR, k);
        finite_or_worst(fit_error(&st, &correct_terms(raw, dc, geometry, &st), fit))
    };
    let (lo, hi) = UNSEEN_SKY_FACTOR_RANGE;
    let (k, _) = minimise_1d(&error, lo, hi, 38);
    let hidden = geometry.hidden_sun.iter().flatten().count();
    if state.value(UNSEEN_SKY_FACTOR).is_some() {
        return None;
    }
    let next = state.with(UNSEEN_SKY_FACTOR, k);
    // Signature: the relative residual follows the unseen sky's share of the weight.
    let current = correct_terms(raw, dc, geometry, state);
    let xy = residual_points(state, &current, fit, |_, t| {
        vec![t.unseen_sky_fraction; t.sky_with_sun_lux.len()]
    });
    let r = pearson_r(&xy);
    let hidden_residual = residuals_where(state, &current, fit, |capture| {
        geometry
            .hidden_sun
            .get(capture)
            .is_some_and(Option::is_some)
    });
    let hidden_note = if hidden_residual.is_empty() {
        String::new()
    } else {
        format!(
            "; the {} fit-set readings whose sun lies beyond that field are off by {:+.1} % \
             on average",
            hidden_residual.len(),
            100.0 * hidden_residual.iter().sum::<f64>() / hidden_residual.len() as f64
        )
    };
    let mut parameters = BTreeMap::new();
    parameters.insert("field_of_view_deg".into(), shown);
    parameters.insert("unseen_sky_factor".into(), k);
    let evidence = format!(
        "the maps show the sky only to {shown:.1}° off-axis where the declared lens images \
         {:.1}°, and the relative residual follows the unseen sky's share of the \
         daylight-coefficient weight (r = {r:.2} over {} readings): a baffle clips the field; \
         the sky beyond is {k:.3} times the extrapolation from the seen rows, and the sun \
         beyond it ({hidden} captures) is taken from the pyranometer{hidden_note}",
        geometry.lens_fov_deg,
        xy.len()
    );
    let terms = correct_terms(raw, dc, geometry, &next);
    let mut fitted = scored(ctx, next, parameters, evidence, Some(terms));
    // The maps show the clipped field (`SkyGeometry::median_shown_fov_deg`): no lux-meter is
    // needed to see a baffle.
    fitted.found = Found::FramesMeasured;
    Some(fitted)
}
