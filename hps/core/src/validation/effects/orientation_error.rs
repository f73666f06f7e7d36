//! `orientation_error`: the camera's orientation differs from `device.toml`. Signature: the
//! sun sightings sit off the SPA sun with the declared orientation; it is judged on them, its
//! own reference instrument, before the effects on the illuminance ([`Stage::Geometry`]).
//! Model: the orientation refitted to the sightings, and every capture's terms recomputed.

use super::fit::fit_error;
use super::{FitContext, Fitted, LoopEffect, Stage};
use crate::camera::{CameraModel, DeviceConfig, ImagePoint};
use crate::model::{capture_terms, CaptureData, ModelError};
use crate::validation::diagnostics::Variable;
use crate::validation::sample::Sample;
use crate::validation::split::FitSet;
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
            fit_orientation(ctx.device, ctx.captures, ctx.terms, ctx.fit)
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
            identified_apart: false,
        }))
    }
}

/// Fits the camera orientation to the fit set's sun sightings; `None` if there are too few
/// or the declared orientation already explains them within 0.2°.
fn fit_orientation(
    device: &DeviceConfig,
    captures: &[CaptureData],
    terms: &[Terms],
    fit: &FitSet<Sample>,
) -> Option<(DeviceConfig, BTreeMap<String, f64>, String)> {
    let camera = CameraModel::new(device.clone());
    let mut sightings = Vec::new();
    let mut offsets = Vec::new();
    for s in fit.samples() {
        let Some(sun) = &terms[s.capture].sun else {
            continue;
        };
        let Some(p): Option<ImagePoint> = camera.project(sun.direction) else {
            continue;
        };
        offsets.push(
            sun.direction
                .angle_between(captures[s.capture].spa_sun)
                .to_degrees(),
        );
        sightings.push(crate::sun::SunObservation {
            image_point: p,
            sun_direction: captures[s.capture].spa_sun,
        });
    }
    if std::env::var_os("SKYLUX_DEBUG_LOOP").is_some() {
        eprintln!(
            "orientation: {} sightings, offsets {offsets:?}",
            sightings.len()
        );
    }
    if sightings.len() < 2 {
        return None;
    }
    let rms = (offsets.iter().map(|o| o * o).sum::<f64>() / offsets.len() as f64).sqrt();
    if rms < 0.2 {
        return None;
    }
    let fitted = match crate::sun::fit_orientation(device, &sightings) {
        Ok(f) => f,
        Err(e) => {
            if std::env::var_os("SKYLUX_DEBUG_LOOP").is_some() {
                eprintln!("orientation fit: {e}");
            }
            return None;
        }
    };
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
        "{} sun sightings sit {rms:.2}° (rms) from the SPA sun with the declared orientation; \
         the fitted orientation leaves {:.3}°",
        sightings.len(),
        fitted.residual_rms_deg
    );
    Some((next, params, evidence))
}
