//! `spectral_mismatch`: the device's luminance `L = cg (w · RGB) / (t g V)` is exact
//! only for the spectrum its weights and `cg` were calibrated under. Under a sky of another
//! colour (a deep blue clear sky, a redder sun) each channel responds differently, and the
//! measured luminance is off by a factor that depends on the spectrum: the spectral mismatch
//! that a photometer's f1' summarises (CIE S 023 / ISO/CIE 19476).
//!
//! Model: the measured luminance of a sky patch (and of the sun) is the true one times
//! `1 + m (c − c_ref)`, with `c` the colour index the device measures from its own raw frames
//! (blue / red, [`crate::validation::sky_colour`]) for that patch (the sun's own index for the sun) and
//! `c_ref` = [`REFERENCE_INDEX`], the index of the calibration source (1 for a device whose
//! channels are balanced under it). For CIE daylights of 4,000-25,000 K the mismatch of a
//! Bayer camera with fixed weights is close to linear in blue / red, so one slope `m` covers
//! the blue sky, the overcast sky and the sun. The model divides each measured patch by its
//! factor before the daylight coefficients apply (the ground, lit by the global daylight, is
//! left as measured). `m` is fitted on the fit set by a scan and a golden-section search of
//! the fit-set error, the accepted linear effects refitted at each trial.
//!
//! Identified by the frames: the colour index the raw frames give departs from the
//! calibration source's across the captures (a spread of at least [`MIN_INDEX_SPREAD`]; a
//! world whose skies have the calibration's colour shows none), so the camera's luminance
//! cannot be right under all of them unless its channels match V(λ). The lux-meters then give
//! the slope and confirm it by a relevant fall ([`Verdict::confirming`]); a paired test over
//! the ten or so hold-out captures of two clear days missed it at z = 1.5 with a 40 % fall
//! (campaign #81 of the seed-18 battery). Signature: the relative residual correlates with
//! the sky's colour index across captures (clear against overcast skies).
//!
//! [`Verdict::confirming`]: crate::validation::scoring::Verdict::confirming
//!
//! The correction itself is part of the loop's prediction
//! ([`crate::validation::prediction::corrected_room`]).

use super::fit::{finite_or_worst, fit_error, fit_linear, pearson_r, residual_points, FreeLinear};
use super::{FitContext, Fitted, Found, LoopEffect};
use crate::model::ModelError;
use crate::validation::diagnostics::Variable;
use crate::validation::prediction::{LoopState, REFERENCE_INDEX, SPECTRAL_SLOPE};
use crate::validation::sample::Sample;
use crate::validation::split::FitSet;
use crate::validation::terms::Terms;
use std::collections::BTreeMap;

/// Least spread of the fit set's sky colour indices (max − min) for the slope to be
/// determined: below it every capture has the same colour and the factor is a common scale
/// (the glazing transmittance's signature).
const MIN_INDEX_SPREAD: f64 = 0.05;

/// Slopes scanned before the golden-section search (coarse grid, per unit of index).
const SLOPE_SCAN: (f64, f64, f64) = (-0.6, 0.6, 0.05);

pub struct SpectralMismatch;

impl LoopEffect for SpectralMismatch {
    fn name(&self) -> &'static str {
        "spectral_mismatch"
    }

    fn aliases(&self) -> &'static [&'static str] {
        &["spectral_clear_sky_cct_k"]
    }

    fn revealing_variable(&self) -> Option<(&'static str, Variable)> {
        Some(("sky colour index (blue / red from the raw frames)", |d| {
            d.sky_colour_index
        }))
    }

    fn fit(&self, ctx: &mut FitContext<'_>) -> Result<Option<Fitted>, ModelError> {
        let Some((next, parameters, evidence)) =
            fit_spectral(ctx.state, ctx.accepted, ctx.terms, ctx.fit)
        else {
            return Ok(None);
        };
        let mut fitted = super::fit::scored(ctx, next, parameters, evidence, None);
        fitted.found = Found::FramesIdentified;
        Ok(Some(fitted))
    }

    fn refresh(&self, state: &LoopState, parameters: &mut BTreeMap<String, f64>) {
        parameters.insert("slope_per_index".into(), state.get(SPECTRAL_SLOPE));
    }
}

/// Fits the slope `m` on the fit set from `state`, the linear effects already `accepted`
/// refitted at each trial. `None` if the fit set's skies do not differ in colour (no spread
/// of the index, as on a spectrally grey world) or the best slope is the current one.
fn fit_spectral(
    state: &LoopState,
    accepted: &[&'static dyn LoopEffect],
    terms: &[Terms],
    fit: &FitSet<Sample>,
) -> Option<(LoopState, BTreeMap<String, f64>, String)> {
    let indices: Vec<f64> = fit
        .samples()
        .iter()
        .filter_map(|s| terms[s.capture].spectral.as_ref())
        .map(|sp| sp.colour.sky_index)
        .filter(|c| c.is_finite())
        .collect();
    let (lo, hi) = indices
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| {
            (a.min(*c), b.max(*c))
        });
    if indices.len() < 3 || hi - lo < MIN_INDEX_SPREAD {
        return None;
    }
    let free = FreeLinear::of(accepted);
    let at = |m: f64| -> (f64, LoopState) {
        let mut st = state.with(SPECTRAL_SLOPE, m);
        if free.any() {
            if let Some(next) = fit_linear(&st, free, terms, fit) {
                st = next;
            }
        }
        (finite_or_worst(fit_error(&st, terms, fit)), st)
    };
    let (from, to, step) = SLOPE_SCAN;
    let grid: Vec<f64> = (0..=((to - from) / step).round() as usize)
        .map(|k| from + step * k as f64)
        .collect();
    let errors: Vec<f64> = grid.iter().map(|m| at(*m).0).collect();
    let i = (0..grid.len()).min_by(|&a, &b| errors[a].total_cmp(&errors[b]))?;
    let (x, e) = crate::numerics::golden_section(
        grid[i.saturating_sub(1)],
        grid[(i + 1).min(grid.len() - 1)],
        (grid[i], errors[i]),
        24,
        |m| at(m).0,
    );
    let best = (e, x);
    if !best.0.is_finite() || (best.1 - state.get(SPECTRAL_SLOPE)).abs() < 0.005 {
        return None;
    }
    let (_, next) = at(best.1);
    // Signature: the relative residual under `state` against the capture's sky colour index.
    // The sky colour index is per capture (NaN without one: left out).
    let xy = residual_points(state, terms, fit, |_, t| {
        let c = t
            .spectral
            .as_ref()
            .map_or(f64::NAN, |sp| sp.colour.sky_index);
        vec![c; t.sky_with_sun_lux.len()]
    });
    let r = pearson_r(&xy);
    let mut parameters = BTreeMap::new();
    parameters.insert("slope_per_index".into(), best.1);
    parameters.insert("reference_index".into(), REFERENCE_INDEX);
    let evidence = format!(
        "the raw frames give the sky's colour index (blue / red) from {lo:.2} to {hi:.2} over \
         the fit captures, not the calibration source's alone; the relative residual follows it \
         (r = {r:.2} over {} readings): the camera's \
         luminance depends on the sky's spectrum; each measured patch and the sun divided by \
         1 {:+.3} (c − {REFERENCE_INDEX})",
        xy.len(),
        best.1
    );
    Some((next, parameters, evidence))
}
