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
//! luminances ([`super::effect_vignetting::correct_terms`]).
//!
//! The largest part of the sky beyond the field is, in a room with a sunlit window, the sun
//! itself: where SPA puts it inside the declared lens's image but outside the field the maps
//! show, the map cannot measure it, and the model takes its direct-normal illuminance from
//! the pyranometer (the Perez 1990 luminous efficacy, as the loop's Perez baseline and
//! outdoor illuminance do), as a concentrated source.

use super::device_model::{CaptureData, ModelError, Room};
use super::device_model::{CaptureTerms, ModelState};
use super::effect_vignetting::{correct_terms, minimise_1d, HiddenSun, SkyGeometry};
use super::effects::{fit_error, pearson_r, residual_points, Candidate, Effect, Sample};
use super::split::FitSet;
use crate::camera::{CameraModel, DeviceConfig};
use crate::campaign::Campaign;
use crate::engine::DaylightCoefficients;
use crate::sky::perez::{PerezConditions, PerezSky};
use chrono::{Datelike, TimeDelta};
use std::collections::BTreeMap;

/// Per capture, the sun the declared lens would image (onto the readout) but the maps'
/// field does not show (SPA off-axis angle beyond the capture's shown field of view) and the
/// map did not give: per sensor its lux per lux of direct-normal illuminance and the
/// pyranometer's direct-normal illuminance (nearest row within 5 min), lux. `None` where the
/// sun was extracted, is below the horizon, is within the shown field, lies outside the
/// readout, or no pyranometer row gives a beam.
pub fn hidden_suns(
    campaign: &Campaign,
    room: &mut Room,
    captures: &[CaptureData],
    terms: &[CaptureTerms],
    device: &DeviceConfig,
    geometry: &SkyGeometry,
) -> Result<Vec<Option<HiddenSun>>, ModelError> {
    let camera = CameraModel::new(device.clone());
    let mut out = Vec::with_capacity(captures.len());
    for (i, c) in captures.iter().enumerate() {
        let shown = geometry.shown_fov_deg.get(i).copied().unwrap_or(f64::NAN);
        let alpha = camera.off_axis_rad(c.spa_sun).to_degrees();
        let on_readout = camera.project(c.spa_sun).is_some_and(|p| {
            let (x0, y0) = (
                f64::from(c.readout.col_start),
                f64::from(c.readout.row_start),
            );
            let skip = f64::from(c.readout.skip.max(1));
            p.x_px >= x0
                && p.y_px >= y0
                && p.x_px < x0 + skip * c.raw_width as f64
                && p.y_px < y0 + skip * c.raw_height as f64
        });
        if terms[i].sun.is_some()
            || c.spa_sun.z <= 0.0
            || !on_readout
            || alpha.partial_cmp(&(shown + 0.5)) != Some(std::cmp::Ordering::Greater)
        {
            out.push(None);
            continue;
        }
        let Some(dn) = reference_direct_normal_lux(campaign, c) else {
            out.push(None);
            continue;
        };
        let k = room.sun_coefficients(c.spa_sun)?;
        out.push(Some((k.into_iter().map(|(c, _)| c).collect(), dn)));
    }
    Ok(out)
}

/// The pyranometer's direct-normal illuminance at a capture, lux: its DNI (or GHI and DHI)
/// through the Perez 1990 model as gendaylit converts (the loop's Perez baseline).
fn reference_direct_normal_lux(campaign: &Campaign, c: &CaptureData) -> Option<f64> {
    let table = campaign.pyranometer.as_ref()?;
    let row = super::illuminance_loop::nearest_in_time(&table.rows, TimeDelta::minutes(5), |r| {
        r.time - c.time
    })?;
    let input = row.perez_input()?;
    let conditions = PerezConditions {
        day_of_year: c.time.ordinal() as u16,
        ..PerezConditions::gendaylit_ang(c.spa_sun)
    };
    let dn = PerezSky::new(input, &conditions)
        .ok()?
        .direct_normal_illuminance_lux();
    (dn.is_finite() && dn > 0.0).then_some(dn)
}

/// The maps must show a field at least this much narrower than the declared lens images,
/// degrees, for the effect to be considered (a group at skip 4 spans some 0.4°).
pub const MIN_CLIPPED_DEG: f64 = 2.0;

/// Range of the unseen-sky factor the fit considers.
pub const UNSEEN_SKY_FACTOR_RANGE: (f64, f64) = (0.2, 4.0);

/// Fits the unseen-sky factor k on the fit set when the maps show a clipped field of view.
/// Returns the candidate (parameters: the field of view the maps show, degrees, and k) and
/// its corrected terms.
pub fn fit_unseen_sky(
    state: &ModelState,
    raw: &[CaptureTerms],
    dc: &DaylightCoefficients,
    geometry: &SkyGeometry,
    fit: &FitSet<Sample>,
) -> Option<(Candidate, Vec<CaptureTerms>)> {
    let shown = geometry.median_shown_fov_deg();
    if !shown.is_finite() || geometry.lens_fov_deg - shown < MIN_CLIPPED_DEG {
        return None;
    }
    let error = |k: f64| {
        let st = ModelState {
            unseen_sky_factor: Some(k),
            ..state.clone()
        };
        let e = fit_error(&st, &correct_terms(raw, dc, geometry, &st), fit);
        if e.is_finite() {
            e
        } else {
            f64::INFINITY
        }
    };
    let (lo, hi) = UNSEEN_SKY_FACTOR_RANGE;
    let (k, _) = minimise_1d(&error, lo, hi, 38);
    let hidden = geometry.hidden_sun.iter().flatten().count();
    if state.unseen_sky_factor.is_some() || (hidden == 0 && (k - 1.0).abs() < 0.01) {
        return None;
    }
    let next = ModelState {
        unseen_sky_factor: Some(k),
        ..state.clone()
    };
    // Signature: the relative residual follows the unseen sky's share of the weight.
    let current = correct_terms(raw, dc, geometry, state);
    let xy = residual_points(state, &current, fit, |_, t| {
        vec![t.unseen_sky_fraction; t.sky_with_sun_lux.len()]
    });
    let r = pearson_r(&xy);
    let hidden_residual: Vec<f64> = fit
        .samples()
        .iter()
        .filter(|s| {
            geometry
                .hidden_sun
                .get(s.capture)
                .is_some_and(Option::is_some)
        })
        .flat_map(|s| {
            let p = super::device_model::predict(state, &current[s.capture]);
            (0..p.len())
                .filter_map(|k| {
                    let m = s.measured(k, state.clock_offset_s).filter(|m| *m > 0.0)?;
                    Some(p[k] / m - 1.0)
                })
                .collect::<Vec<_>>()
        })
        .collect();
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
    Some((
        Candidate {
            effect: Effect::SkyOutsideFov,
            state: next,
            parameters,
            evidence,
        },
        terms,
    ))
}
