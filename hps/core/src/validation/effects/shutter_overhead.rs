//! `shutter_overhead`: the shutter integrates each frame for its declared time plus a fixed
//! overhead t0, which biases the short exposures: those that measure the sun and the bright
//! sky. Identified from the raw frames alone ([`frame_evidence::shutter_overhead`]: the ratio
//! of two exposures' signals in pixels valid in both is the ratio of the true integration
//! times), so it is never confused with an effect of the lux-meters' residual (vignetting,
//! glazing); the lux-meters then confirm it on the hold-out set. Model: every capture
//! re-merged with t + t0. Where the overhead leaves the sun saturated in every frame (several
//! µs against a 1 µs shortest exposure), the map cannot give the sun: it is taken from the
//! pyranometer's direct-normal illuminance as a concentrated source.

use super::{FitContext, Fitted, Found, LoopEffect};
use crate::camera::{CameraModel, DeviceConfig};
use crate::hdr::{map_capture, CaptureMap, GroupGeometry, MapFlag};
use crate::model::{capture_terms, load_captures_with, CaptureData, ModelError};
use crate::validation::diagnostics::Variable;
use crate::validation::effects::fit::{finite_or_worst, fit_error};
use crate::validation::frame_evidence;
use crate::validation::glazing::GLAZING_ANGULAR_B0;
use crate::validation::sky_geometry::reference_direct_normal_lux;
use crate::validation::terms::{attach, use_reference_outdoor, Terms};
use std::collections::BTreeMap;

pub struct ShutterOverhead;

impl LoopEffect for ShutterOverhead {
    fn name(&self) -> &'static str {
        "shutter_overhead"
    }

    fn aliases(&self) -> &'static [&'static str] {
        &["shutter_overhead_us"]
    }

    fn revealing_variable(&self) -> Option<(&'static str, Variable)> {
        Some(("share of direct sun in the model's light", |d| {
            d.direct_sun_share
        }))
    }

    fn fit(&self, ctx: &mut FitContext<'_>) -> Result<Option<Fitted>, ModelError> {
        let Some((overhead_us, identification)) = identify(ctx)? else {
            return Ok(None);
        };
        let Trial {
            overhead_us,
            error,
            captures,
            mut terms,
            suns_from_pyranometer,
        } = trial(ctx, overhead_us)?;
        attach(ctx.room, &mut terms, ctx.colours);
        let mut parameters = BTreeMap::new();
        parameters.insert("overhead_us".into(), overhead_us);
        let sun_note = if suns_from_pyranometer > 0 {
            format!(
                "; re-merged, the sun still saturates every frame at {suns_from_pyranometer} \
                 captures and is taken from the pyranometer's direct-normal illuminance there"
            )
        } else {
            String::new()
        };
        Ok(Some(Fitted {
            state: ctx.state.clone(),
            parameters,
            evidence: format!("{identification}{sun_note}"),
            fit_error: error,
            terms: Some(terms),
            captures: Some(captures),
            device: None,
            found: Found::FramesMeasured,
        }))
    }
}

/// The sun must read this much above the pyranometer's direct-normal illuminance (median
/// over the captures) for an overhead to be named: beyond the sun's colour (a 5,700 K sun
/// reads some 5 % low through the camera's luminance weights, docs/loop.md) and the Perez
/// efficacy's scatter (some 5 %, Perez et al. 1990).
const SUN_OVER_READ: f64 = 0.15;

/// The overhead and the sentence that identified it, from evidence without the lux-meters:
/// the exposures' signal ratios ([`frame_evidence::shutter_overhead`]) where they overlap,
/// else the extracted sun against the pyranometer ([`frame_evidence::sun_over_pyranometer`]),
/// else the sun saturated in every frame while the pyranometer reports a beam (the overhead
/// then has only a lower bound, and the model does not depend on it beyond: the sun comes
/// from the pyranometer). `None`: nothing shows an overhead.
fn identify(ctx: &mut FitContext<'_>) -> Result<Option<(f64, String)>, ModelError> {
    let all: Vec<usize> = (0..ctx.captures.len()).collect();
    let ratios = frame_evidence::shutter_overhead(ctx.campaign, ctx.device, &all)?;
    let suns: Vec<Option<f64>> = ctx
        .terms
        .iter()
        .map(|t| t.sun.as_ref().map(|s| s.direct_normal_illuminance_lux))
        .collect();
    let sun = frame_evidence::sun_over_pyranometer(ctx.campaign, ctx.captures, &suns);
    let camera = CameraModel::new(ctx.device.clone());
    let saturated = ctx
        .captures
        .iter()
        .zip(ctx.terms)
        .filter(|(c, t)| {
            t.sun.is_none()
                && c.spa_sun.z > 0.0
                && sun_over_range(&camera, c)
                && reference_direct_normal_lux(ctx.campaign, c).is_some()
        })
        .count();
    if std::env::var_os("SKYLUX_DEBUG_LOOP").is_some() {
        eprintln!(
            "shutter overhead evidence: ratios {ratios:?}; sun / pyranometer {sun:?}; \
             saturated suns {saturated}"
        );
    }
    if let Some(e) = ratios.filter(|e| e.shows_overhead()) {
        return Ok(Some((
            e.overhead_us,
            format!(
                "the exposures' signal ratios in pixels valid in both (no lux-meter involved) \
                 show the frames integrating {:.2} ± {:.2} µs longer than declared ({} exposure \
                 pairs, {} pixels)",
                e.overhead_us, e.standard_error_us, e.pairs, e.pixels
            ),
        )));
    }
    let mut over: Vec<f64> = sun.iter().map(|(_, r, _)| *r).collect();
    over.sort_by(f64::total_cmp);
    let median_ratio = over.get(over.len() / 2).copied().unwrap_or(f64::NAN);
    // Two captures at least: two suns that read high, or one that reads high and one
    // saturated in every frame, which an overhead explains as well (the sun reads t0 / t
    // higher where it is valid and saturates where it is bright).
    if over.len() + saturated.min(1) >= 2 && median_ratio >= 1.0 + SUN_OVER_READ {
        let mut t0: Vec<f64> = sun.iter().map(|(_, r, t)| t * (r - 1.0)).collect();
        t0.sort_by(f64::total_cmp);
        let overhead_us = t0[t0.len() / 2];
        return Ok(Some((
            overhead_us,
            format!(
                "the sun, measured in the shortest exposure, reads {median_ratio:.2} times the \
                 pyranometer's direct-normal illuminance (median of {} captures; no lux-meter \
                 involved): the shortest frame integrates {overhead_us:.2} µs longer than \
                 declared{}",
                over.len(),
                if saturated > 0 {
                    format!(", and the sun saturates every frame at {saturated} more captures")
                } else {
                    String::new()
                }
            ),
        )));
    }
    if saturated >= 2 && saturated > over.len() {
        // Only a lower bound: the shortest frame's DN at the sun exceeds the valid maximum.
        let (valid_max, shortest) = (
            ctx.device.sensor.valid_max_dn,
            shortest_exposure_us(ctx.campaign).unwrap_or(1.0),
        );
        let overhead_us = search_saturated(ctx, shortest)?;
        return Ok(Some((
            overhead_us,
            format!(
                "the sun saturates every frame (over {valid_max:.0} DN even in the shortest, \
                 {shortest} µs) at {saturated} captures where the pyranometer reports a beam \
                 and SPA puts it in view (no lux-meter involved): the short frames integrate \
                 longer than declared; the overhead, fitted on the lux-meters, is a lower \
                 bound"
            ),
        )));
    }
    Ok(None)
}

/// The campaign's shortest declared exposure, µs.
fn shortest_exposure_us(campaign: &crate::campaign::Campaign) -> Option<f64> {
    campaign
        .captures
        .iter()
        .filter_map(|c| crate::campaign::CaptureConfig::read(&c.dir.join("capture.toml")).ok())
        .flat_map(|cfg| cfg.exposure.into_iter().map(|e| e.exposure_us))
        .min_by(f64::total_cmp)
}

/// With the sun saturated everywhere: the overhead of least fit-set error on an octave grid
/// from the shortest exposure up (the sky's short-exposure groups still depend on it).
fn search_saturated(ctx: &mut FitContext<'_>, shortest_us: f64) -> Result<f64, ModelError> {
    let mut best = (f64::INFINITY, shortest_us);
    for k in 0..6 {
        let t0 = shortest_us * 2f64.powi(k);
        let t = trial(ctx, t0)?;
        if t.error < best.0 {
            best = (t.error, t0);
        }
    }
    Ok(best.1)
}

/// One trial overhead: its fit-set error and the captures and terms re-merged with it.
struct Trial {
    overhead_us: f64,
    error: f64,
    captures: Vec<CaptureData>,
    terms: Vec<Terms>,
    /// Captures whose sun came from the pyranometer (saturated in every frame).
    suns_from_pyranometer: usize,
}

/// Re-merges every capture with `overhead_us` and scores the fit set on the new terms (the
/// glazing's angular effect re-applied if it was added).
fn trial(ctx: &mut FitContext<'_>, overhead_us: f64) -> Result<Trial, ModelError> {
    let device = ctx.device;
    let captures = load_captures_with(
        ctx.campaign,
        &|dir| map_capture_with_overhead(dir, device, overhead_us),
        &|_, _| {},
    )?;
    let mut terms = Terms::all(capture_terms(ctx.room, &captures, device, &|_, _| {})?);
    use_reference_outdoor(&mut terms, ctx.reference_outdoor);
    let suns_from_pyranometer = saturated_suns_from_pyranometer(ctx, &captures, &mut terms)?;
    let b0 = ctx.state.get(GLAZING_ANGULAR_B0);
    if let (Some(g), true) = (ctx.angular, b0 > 0.0) {
        terms = g.apply(&terms, b0);
    }
    let error = finite_or_worst(fit_error(ctx.state, &terms, ctx.fit));
    Ok(Trial {
        overhead_us,
        error,
        captures,
        terms,
        suns_from_pyranometer,
    })
}

/// Where the map shows no sun but the groups at SPA's sun are over-range in every frame, the
/// sun taken from the pyranometer's direct-normal illuminance (Perez 1990 efficacy, as the
/// Perez baseline) with the room's sun coefficients; how many captures.
fn saturated_suns_from_pyranometer(
    ctx: &mut FitContext<'_>,
    captures: &[CaptureData],
    terms: &mut [Terms],
) -> Result<usize, ModelError> {
    let camera = CameraModel::new(ctx.device.clone());
    let mut count = 0;
    for (c, t) in captures.iter().zip(terms.iter_mut()) {
        if t.sun.is_some() || c.spa_sun.z <= 0.0 || !sun_over_range(&camera, c) {
            continue;
        }
        let Some(dn_lux) = reference_direct_normal_lux(ctx.campaign, c) else {
            continue;
        };
        let k = ctx.room.sun_coefficients(c.spa_sun)?;
        t.model.sun_lux_per_dn_lux = k.into_iter().map(|(lux, _)| lux).collect();
        t.model.sun_dn_lux = dn_lux;
        count += 1;
    }
    Ok(count)
}

/// Whether the map's group at SPA's sun is over-range (saturated in every exposure).
fn sun_over_range(camera: &CameraModel, c: &CaptureData) -> bool {
    let Some(p) = camera.project(c.spa_sun) else {
        return false;
    };
    let skip = f64::from(c.readout.skip.max(1));
    let gx = ((p.x_px - f64::from(c.readout.col_start)) / skip / 2.0).floor();
    let gy = ((p.y_px - f64::from(c.readout.row_start)) / skip / 2.0).floor();
    let (w, h) = (c.map.width as f64, c.map.height as f64);
    if !(gx >= 0.0 && gy >= 0.0 && gx < w && gy < h) {
        return false;
    }
    let i = gy as usize * c.map.width + gx as usize;
    c.map.flags.get(i) == Some(&MapFlag::OverRange)
}

/// Merges one capture folder taking each frame's integration time as declared plus
/// `shutter_overhead_us`; without an overhead, exactly [`map_capture`].
pub fn map_capture_with_overhead(
    dir: &std::path::Path,
    device: &DeviceConfig,
    shutter_overhead_us: f64,
) -> Result<CaptureMap, ModelError> {
    if shutter_overhead_us == 0.0 {
        return Ok(map_capture(dir, device)?);
    }
    use crate::campaign::{CaptureConfig, RawFrame};
    use crate::hdr::CaptureMapError;
    let toml_path = dir.join("capture.toml");
    let capture = CaptureConfig::read(&toml_path).map_err(CaptureMapError::from)?;
    let mut frames = Vec::with_capacity(capture.exposure.len());
    for entry in &capture.exposure {
        frames.push(RawFrame::read(&dir.join(&entry.file)).map_err(CaptureMapError::from)?);
    }
    let Some(first) = frames.first() else {
        return Err(ModelError::Sun(format!(
            "{}: no exposure entries",
            toml_path.display()
        )));
    };
    let camera = CameraModel::new(device.clone());
    let geometry = GroupGeometry::new(&camera, &capture.readout, first.width, first.height);
    let exposures: Vec<crate::hdr::Exposure> = frames
        .iter()
        .zip(&capture.exposure)
        .map(|(f, e)| crate::hdr::Exposure {
            frame: f,
            exposure_s: (e.exposure_us + shutter_overhead_us) * 1e-6,
            gain: e.gain,
        })
        .collect();
    let map =
        crate::hdr::merge(&exposures, device, capture.bayer, &geometry).map_err(|source| {
            CaptureMapError::Merge {
                capture: toml_path,
                source,
            }
        })?;
    Ok(CaptureMap {
        capture,
        map,
        geometry,
    })
}
