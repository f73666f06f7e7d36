//! `orientation_error`: the camera's orientation differs from `device.toml`. Signature: the
//! sun sightings sit off the SPA sun with the declared orientation; it is judged on them, its
//! own reference instrument, before the effects on the illuminance ([`Stage::Geometry`]).
//! Model: the orientation refitted to the sightings, and every capture's terms recomputed.

use super::fit::fit_error;
use super::{FitContext, Fitted, Found, LoopEffect, Stage};
use crate::camera::{CameraModel, DeviceConfig, ImagePoint};
use crate::model::{capture_terms, CaptureData, ModelError};
use crate::validation::diagnostics::Variable;
use crate::validation::terms::{attach, use_reference_outdoor, Terms};
use std::collections::BTreeMap;

pub struct OrientationError;

impl LoopEffect for OrientationError {
    fn name(&self) -> &'static str {
        "orientation_error"
    }

    fn aliases(&self) -> &'static [&'static str] {
        &["orientation_azimuth_deg"]
    }

    fn stage(&self) -> Stage {
        Stage::Geometry
    }

    fn revealing_variable(&self) -> Option<(&'static str, Variable)> {
        Some(
            ("sun sighting offset from SPA, declared camera (deg)", |d| {
                d.sun_offset_deg
            }),
        )
    }

    fn fit(&self, ctx: &mut FitContext<'_>) -> Result<Option<Fitted>, ModelError> {
        let Some((device, parameters, evidence)) =
            fit_orientation(ctx.device, ctx.captures, ctx.terms)
        else {
            return Ok(None);
        };
        let mut terms = Terms::all(capture_terms(ctx.room, ctx.captures, &device, &|_, _| {})?);
        use_reference_outdoor(&mut terms, ctx.reference_outdoor);
        attach(ctx.room, &mut terms, ctx.colours);
        Ok(Some(Fitted {
            state: ctx.state.clone(),
            parameters,
            evidence,
            fit_error: fit_error(ctx.state, &terms, ctx.fit),
            terms: Some(terms),
            captures: None,
            device: Some(device),
            found: Found::Residual,
        }))
    }
}

/// The declared orientation is questioned only when the sightings sit further than this from
/// SPA (rms, degrees): ten times the scatter of the sightings of a correctly declared camera
/// (0.01-0.02° rms over the battery's campaigns without an effect, `docs/loop.md`), and a
/// tenth of the smallest orientation error the battery draws (2°).
pub const SIGHTING_GATE_DEG: f64 = 0.2;

/// A fitted orientation is taken only if it leaves at most this fraction of the declared
/// offset (rms): the sightings must be a rotation of SPA's suns, not a misdetection (a bright
/// cloud's edge) that no rotation explains.
pub const EXPLAINED_FRACTION: f64 = 0.25;

/// The three angles are fitted only from sightings spread this far apart (degrees, the
/// widest angle between two SPA suns) and at least three of them; closer, the rotation about
/// their common direction is undetermined and only the azimuth is fitted (a levelled camera
/// turned about the vertical, the error a compass leaves).
pub const FULL_FIT_SPREAD_DEG: f64 = 10.0;

/// Fits the camera orientation to the sun sightings of every capture; `None` if there are
/// none, the declared orientation explains them within [`SIGHTING_GATE_DEG`], or no rotation
/// does. Every capture's frames are the camera's own evidence (no lux-meter reading is read
/// here), so the hold-out captures' sightings count too: on a partly cloudy day the sun may
/// be seen once.
fn fit_orientation(
    device: &DeviceConfig,
    captures: &[CaptureData],
    terms: &[Terms],
) -> Option<(DeviceConfig, BTreeMap<String, f64>, String)> {
    let camera = CameraModel::new(device.clone());
    let mut sightings = Vec::new();
    let mut offsets = Vec::new();
    for (t, capture) in terms.iter().zip(captures) {
        let Some(sun) = &t.sun else {
            continue;
        };
        let Some(p): Option<ImagePoint> = camera.project(sun.direction) else {
            continue;
        };
        offsets.push(sun.direction.angle_between(capture.spa_sun).to_degrees());
        sightings.push(crate::sun::SunObservation {
            image_point: p,
            sun_direction: capture.spa_sun,
        });
    }
    let debug = std::env::var_os("SKYLUX_DEBUG_LOOP").is_some();
    if debug {
        eprintln!(
            "orientation: {} sightings, offsets {offsets:?}",
            sightings.len()
        );
    }
    if sightings.is_empty() {
        return None;
    }
    let rms = (offsets.iter().map(|o| o * o).sum::<f64>() / offsets.len() as f64).sqrt();
    if rms < SIGHTING_GATE_DEG {
        return None;
    }
    let azimuth = crate::sun::fit_azimuth(device, &sightings).ok()?;
    let spread_deg = sightings
        .iter()
        .flat_map(|a| sightings.iter().map(|b| a.sun_direction.angle_between(b.sun_direction)))
        .fold(0.0, f64::max)
        .to_degrees();
    let full = (sightings.len() >= 3 && spread_deg >= FULL_FIT_SPREAD_DEG)
        .then(|| crate::sun::fit_orientation(device, &sightings).ok())
        .flatten();
    // The three angles only where they explain what the turn alone leaves.
    let (fitted, what) = match full {
        Some(f)
            if f.residual_rms_deg < 0.5 * azimuth.residual_rms_deg
                && azimuth.residual_rms_deg > SIGHTING_GATE_DEG =>
        {
            (f, "the orientation (azimuth, tilt and roll)")
        }
        _ => (azimuth, "the azimuth (the camera turned about the vertical)"),
    };
    if debug {
        eprintln!(
            "orientation: {what} leaves {:.3}° of {rms:.3}° (spread {spread_deg:.1}°)",
            fitted.residual_rms_deg
        );
    }
    if fitted.residual_rms_deg > EXPLAINED_FRACTION * rms {
        return None;
    }
    let mut next = device.clone();
    next.orientation = fitted.orientation.clone();
    let mut params = BTreeMap::new();
    let d = |a: f64, b: f64| (a - b + 540.0).rem_euclid(360.0) - 180.0;
    params.insert(
        "axis_azimuth_deg".into(),
        d(
            next.orientation.axis_azimuth_deg,
            device.orientation.axis_azimuth_deg,
        ),
    );
    params.insert(
        "axis_altitude_deg".into(),
        next.orientation.axis_altitude_deg - device.orientation.axis_altitude_deg,
    );
    params.insert(
        "roll_deg".into(),
        d(next.orientation.roll_deg, device.orientation.roll_deg),
    );
    let evidence = format!(
        "{} sun sightings (every capture's frames) sit {rms:.2}° (rms) from the SPA sun with \
         the declared orientation; fitting {what} leaves {:.3}°",
        sightings.len(),
        fitted.residual_rms_deg
    );
    Some((next, params, evidence))
}
