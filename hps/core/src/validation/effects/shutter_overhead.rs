//! `shutter_overhead`: the shutter integrates each frame for its declared time plus a fixed
//! overhead t0, which biases the shortest exposures, those that measure the sun.
//! Signature: readings lit by the sun over-predicted by more than 3 % on average and by more
//! than the others' mean |error| (a common factor biases both alike). Model: every capture
//! re-merged with t + t0; t0 minimises the fit-set error (a scan over 0.5 to 64 µs in
//! octaves, then a golden-section search between the best's neighbours). Tried only when the
//! signature is there, since each trial re-merges every capture.

use super::fit::{finite_or_worst, fit_error, sunlit_bias};
use super::{FitContext, Fitted, LoopEffect};
use crate::camera::{CameraModel, DeviceConfig};
use crate::hdr::{map_capture, CaptureMap, GroupGeometry};
use crate::model::{capture_terms, load_captures_with, CaptureData, ModelError};
use crate::validation::diagnostics::Variable;
use crate::validation::glazing::GLAZING_ANGULAR_B0;
use crate::validation::terms::{attach, use_reference_outdoor, Terms};
use std::collections::BTreeMap;

/// Widest shutter overhead the fit considers, µs.
const MAX_SHUTTER_OVERHEAD_US: f64 = 100.0;

/// Golden-section iterations after the octave scan.
const GOLDEN_ITERATIONS: usize = 6;

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
        let state = ctx.state;
        if !state.model.concentrated_sun {
            return Ok(None);
        }
        let bias = sunlit_bias(state, ctx.terms, ctx.fit);
        if std::env::var_os("SKYLUX_DEBUG_LOOP").is_some() {
            eprintln!("shutter signature: {bias:?}");
        }
        // The sunlit readings' bias over and above the others': a common factor (dirty
        // glazing) biases both alike and is no overhead's signature.
        let shade_bias = if bias.shade_mean.is_finite() {
            bias.shade_mean
        } else {
            0.0
        };
        let excess = bias.lit_mean - shade_bias;
        if bias.lit_n < 2 || !excess.is_finite() || excess < 0.03 || excess < bias.shade_mean_abs {
            return Ok(None);
        }
        let Some(best) = search_overhead(ctx)? else {
            return Ok(None);
        };
        let Trial {
            overhead_us,
            error,
            captures,
            mut terms,
        } = best;
        attach(ctx.room, &mut terms, ctx.colours);
        let mut parameters = BTreeMap::new();
        parameters.insert("overhead_us".into(), overhead_us);
        let evidence = format!(
            "readings lit by the sun are over-predicted by {:+.1} % on average ({} readings) \
             against {:+.1} % (mean |error| {:.1} %) elsewhere ({}): the short exposures \
             that measure the sun integrate longer than declared",
            100.0 * bias.lit_mean,
            bias.lit_n,
            100.0 * shade_bias,
            100.0 * bias.shade_mean_abs,
            bias.shade_n
        );
        Ok(Some(Fitted {
            state: state.clone(),
            parameters,
            evidence,
            fit_error: error,
            terms: Some(terms),
            captures: Some(captures),
            device: None,
        }))
    }
}

/// One trial overhead: its fit-set error and the captures and terms re-merged with it.
struct Trial {
    overhead_us: f64,
    error: f64,
    captures: Vec<CaptureData>,
    terms: Vec<Terms>,
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
    })
}

/// The overhead of least fit-set error: the octave scan, then
/// [`crate::numerics::golden_section`] between the best's neighbours (the error is unimodal in
/// t0 near its minimum). `None` if the scan gave nothing.
fn search_overhead(ctx: &mut FitContext<'_>) -> Result<Option<Trial>, ModelError> {
    let grid: Vec<f64> = (0..8).map(|k| 0.5 * 2f64.powi(k)).collect();
    let mut best: Option<Trial> = None;
    for &t0 in &grid {
        let t = trial(ctx, t0)?;
        if best.as_ref().is_none_or(|b| t.error < b.error) {
            best = Some(t);
        }
    }
    let Some(scanned) = best else {
        return Ok(None);
    };
    let i = grid
        .iter()
        .position(|g| *g == scanned.overhead_us)
        .unwrap_or(0);
    let (a, b) = (
        if i == 0 { 0.0 } else { grid[i - 1] },
        grid.get(i + 1).copied().unwrap_or(MAX_SHUTTER_OVERHEAD_US),
    );
    // The search sees only errors; the lowest trial's captures and terms are kept aside.
    let start = (scanned.overhead_us, scanned.error);
    let mut kept = scanned;
    let mut failure = None;
    let (x, _) = crate::numerics::golden_section(a, b, start, GOLDEN_ITERATIONS, |t0| {
        if failure.is_some() {
            return f64::INFINITY;
        }
        match trial(ctx, t0) {
            Ok(t) => {
                let e = t.error;
                if e < kept.error {
                    kept = t;
                }
                e
            }
            Err(e) => {
                failure = Some(e);
                f64::INFINITY
            }
        }
    });
    if let Some(e) = failure {
        return Err(e);
    }
    if kept.overhead_us != x {
        // A tie the search broke the other way: take the trial it chose.
        kept = trial(ctx, x)?;
    }
    Ok(Some(kept))
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
