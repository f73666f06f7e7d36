//! `skylux loop`: the device model against the lux-meters, effect by effect.
//!
//! 1. Merge every capture, extract the sun, and compute the room's daylight coefficients.
//! 2. Split the capture times into fit and hold-out blocks ([`super::split`]).
//! 3. Fit each candidate effect on the fit set; rank them by how much of the fit-set error
//!    each removes; add the best if the hold-out error falls by more than its noise
//!    (its block-to-block standard error); refit; repeat. The hold-out set is only ever
//!    scored, never fitted.
//! 4. Report before and after on the hold-out set, with the Perez baseline from the
//!    pyranometer.

use super::device_model::{
    capture_terms, load_captures, load_captures_with_overhead, predict, CaptureData, CaptureTerms,
    ModelError, ModelState, Room,
};
use super::effect_fov::{fit_unseen_sky, hidden_suns, MIN_CLIPPED_DEG};
use super::effect_glazing_angular::{fit_glazing_angular, AngularGlazing};
use super::effect_vignetting::{correct_terms, fit_vignetting, light_off_axis_deg, SkyGeometry};
use super::effects::{
    fit_effect, fit_error, interpolate, relative_rate_per_min, sunlit_bias, Candidate, Effect,
    Sample, CLOCK_SCAN_S,
};
use super::glazing::Glazing;
use super::report::{EffectReport, ErrorSummary, Report, ResidualRow};
use super::split::{compare, split, Figure, FitSet, HoldoutSet, Score, SplitPlan};
use crate::camera::{DeviceConfig, ImagePoint};
use crate::campaign::Campaign;
use crate::engine::Settings;
use crate::sky::perez::{PerezConditions, PerezSky};
use chrono::{Datelike, TimeDelta, Timelike, Utc};
use std::collections::BTreeMap;

/// How the loop runs.
#[derive(Clone, Debug)]
pub struct LoopOptions {
    /// The model before any effect: what the campaign's owner declared.
    pub base: ModelState,
    /// Reinhart subdivision of the daylight coefficients.
    pub mf: usize,
    /// Engine settings of the daylight and sun coefficients.
    pub settings: Settings,
    /// Length of a fit or hold-out block; blocks alternate.
    pub block: TimeDelta,
    /// A lux-meter reading matches a capture within this time.
    pub match_window: TimeDelta,
    /// Most effects added.
    pub max_effects: usize,
}

impl Default for LoopOptions {
    fn default() -> Self {
        Self {
            base: ModelState::default(),
            mf: 2,
            settings: Settings {
                ambient_bounces: 5,
                samples_per_sensor: 50_000,
                seed: 1,
                ..Default::default()
            },
            block: TimeDelta::hours(2),
            match_window: TimeDelta::minutes(2),
            max_effects: 4,
        }
    }
}

/// A fitted candidate and its fit-set error.
type Ranked = (Candidate, f64);

/// Why the loop could not run.
#[derive(Debug, thiserror::Error)]
pub enum LoopError {
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error(transparent)]
    Split(#[from] super::split::SplitError),
    #[error("{0}")]
    Data(String),
}

/// One line of `illuminance.csv`.
#[derive(Clone, Debug)]
pub struct IlluminanceRow {
    pub time: String,
    pub sensor: String,
    pub lux_model: f64,
    pub lux_measured: Option<f64>,
    /// `hdr` (the final model), `hdr-base` (before effects) or `perez`.
    pub model: String,
}

/// One reading with the model before and after, and the explanatory variables of the
/// effect library: what the residual plots are drawn from.
#[derive(Clone, Debug)]
pub struct Diagnostic {
    pub time: chrono::DateTime<chrono::FixedOffset>,
    pub sensor: String,
    pub holdout: bool,
    /// The reading matched to the capture under the final model (its clock offset).
    pub measured_lux: f64,
    /// The reading matched under the model before effects.
    pub measured_before_lux: f64,
    pub before_lux: f64,
    pub after_lux: f64,
    /// Outdoor horizontal illuminance (pyranometer if present, else the map), lux.
    pub outdoor_lux: f64,
    /// Share of the (concentrated) model's light that is direct sun at this sensor.
    pub direct_sun_share: f64,
    /// Share of the model's light from ground the lens does not see.
    pub unseen_ground_share: f64,
    /// Extracted sun's angle from SPA under the declared camera, degrees (NaN: no sun).
    pub sun_offset_deg: f64,
    /// Relative rate of change of the logged illuminance at the capture, per minute (NaN
    /// without a logger series).
    pub rate_of_change_per_min: f64,
    /// Whether the map showed a sun (1) or not (0).
    pub sun_visible: f64,
    /// SPA sun altitude and azimuth (from north, clockwise), degrees.
    pub sun_altitude_deg: f64,
    pub sun_azimuth_deg: f64,
    /// Fraction of the sky's daylight-coefficient weight on patches the lens did not see.
    pub unseen_sky_fraction: f64,
    /// Fraction of the map's valid groups over-range.
    pub saturated_fraction: f64,
    /// Local clock time of the capture, hours.
    pub local_hour: f64,
    /// The sky's colour index (blue / red from the raw frames; NaN if unreadable).
    pub sky_colour_index: f64,
    /// Angle between the SPA sun and the glazing's outward normal, degrees (NaN: sun below
    /// the horizon or behind the façade, or no glazing found).
    pub sun_incidence_deg: f64,
    /// The sensor's distance from the glazing plane, metres (NaN: no glazing found).
    pub facade_distance_m: f64,
    /// Mean off-axis angle in the camera of the light the model brings to the sensor (sky
    /// and seen ground bins and the sun, weighted by their illuminance), degrees.
    pub light_off_axis_deg: f64,
}

/// How an explanatory variable is read from a diagnostic.
pub type Variable = fn(&Diagnostic) -> f64;

/// The explanatory variables of the residual table, with how each is read.
pub const RESIDUAL_VARIABLES: [(&str, Variable); 16] = [
    ("sun visible (0/1)", |d| d.sun_visible),
    ("sun altitude (deg)", |d| d.sun_altitude_deg),
    ("sun azimuth (deg)", |d| d.sun_azimuth_deg),
    ("share of direct sun", |d| d.direct_sun_share),
    ("share from unseen ground", |d| d.unseen_ground_share),
    ("unseen sky fraction", |d| d.unseen_sky_fraction),
    ("saturated fraction", |d| d.saturated_fraction),
    ("time of day (h)", |d| d.local_hour),
    ("outdoor horizontal illuminance (klx)", |d| {
        d.outdoor_lux / 1000.0
    }),
    ("measured illuminance (klx)", |d| {
        d.measured_before_lux / 1000.0
    }),
    ("rate of change (rel./min)", |d| d.rate_of_change_per_min),
    ("sun offset from SPA (deg)", |d| d.sun_offset_deg),
    ("sky colour index (blue/red)", |d| d.sky_colour_index),
    ("solar incidence on the glazing (deg)", |d| {
        d.sun_incidence_deg
    }),
    ("distance from the facade (m)", |d| d.facade_distance_m),
    ("off-axis angle of the light (deg)", |d| {
        d.light_off_axis_deg
    }),
];

/// The residual table: per variable, over all readings and per sensor, the relative
/// residual's correlation and slope before and after the effects.
pub fn residual_rows(diagnostics: &[Diagnostic]) -> Vec<ResidualRow> {
    let mut groups: Vec<String> = vec!["all".into()];
    for d in diagnostics {
        if !groups.contains(&d.sensor) {
            groups.push(d.sensor.clone());
        }
    }
    let mut rows = Vec::new();
    for (variable, value) in RESIDUAL_VARIABLES {
        for g in &groups {
            let of = |residual: &dyn Fn(&Diagnostic) -> f64| -> Vec<(f64, f64)> {
                diagnostics
                    .iter()
                    .filter(|d| g == "all" || &d.sensor == g)
                    .map(|d| (value(d), residual(d)))
                    .filter(|(x, y)| x.is_finite() && y.is_finite())
                    .collect()
            };
            let before = of(&|d| d.before_lux / d.measured_before_lux - 1.0);
            let after = of(&|d| d.after_lux / d.measured_lux - 1.0);
            // A variable constant over the group (a sensor's distance from the façade, per
            // sensor) has no correlation: NaN rather than rounding noise.
            let fit = |xy: &[(f64, f64)]| {
                if xy.windows(2).all(|w| w[0].0 == w[1].0) {
                    (f64::NAN, f64::NAN)
                } else {
                    crate::numerics::pearson(xy).map_or((f64::NAN, f64::NAN), |p| (p.r, p.slope))
                }
            };
            let (before_r, before_slope) = fit(&before);
            let (after_r, after_slope) = fit(&after);
            rows.push(ResidualRow {
                variable: variable.into(),
                group: g.clone(),
                n: before.len(),
                before_r,
                before_slope,
                after_r,
                after_slope,
            });
        }
    }
    rows
}

/// Everything the loop found.
pub struct LoopOutcome {
    pub report: Report,
    pub rows: Vec<IlluminanceRow>,
    pub diagnostics: Vec<Diagnostic>,
    /// The residual table ([`residual_rows`]).
    pub residuals: Vec<ResidualRow>,
    /// The final model and camera.
    pub state: ModelState,
    pub device: DeviceConfig,
}

/// Scores every (sample, sensor) reading of the hold-out set.
fn score(
    holdout: &HoldoutSet<Sample>,
    predict_capture: &dyn Fn(usize) -> Vec<f64>,
    sensors: &[String],
    clock_offset_s: f64,
) -> (Score, BTreeMap<String, Score>) {
    // `evaluate_grouped` takes one error per sample, so score each sensor and merge.
    let mut per_sensor = BTreeMap::new();
    let mut all_errors: Vec<Score> = Vec::new();
    for (k, name) in sensors.iter().enumerate() {
        let (s, _) = holdout.evaluate_grouped(|smp: &Sample| {
            let m = smp.measured(k, clock_offset_s)?;
            if m <= 0.0 {
                return None;
            }
            Some(((), predict_capture(smp.capture)[k] / m - 1.0))
        });
        per_sensor.insert(name.clone(), s.clone());
        all_errors.push(s);
    }
    // All readings: average the sensors' scores weighted by their counts, per block too.
    let merged = merge_scores(&all_errors);
    (merged, per_sensor)
}

/// Combines per-sensor scores of the same blocks into one (means weighted by counts).
fn merge_scores(scores: &[Score]) -> Score {
    let mut out = Score::default();
    let n: usize = scores.iter().map(|s| s.n).sum();
    if n == 0 {
        return out;
    }
    let nf = n as f64;
    out.n = n;
    out.mean = scores.iter().map(|s| s.mean * s.n as f64).sum::<f64>() / nf;
    out.mean_abs = scores.iter().map(|s| s.mean_abs * s.n as f64).sum::<f64>() / nf;
    out.rmse = (scores
        .iter()
        .map(|s| s.rmse * s.rmse * s.n as f64)
        .sum::<f64>()
        / nf)
        .sqrt();
    out.max_abs = scores.iter().map(|s| s.max_abs).fold(0.0, f64::max);
    let mut blocks: BTreeMap<i64, Vec<Score>> = BTreeMap::new();
    for s in scores {
        for (k, b) in &s.blocks {
            blocks.entry(*k).or_default().push(b.clone());
        }
    }
    out.blocks = blocks
        .into_iter()
        .map(|(k, v)| (k, merge_scores(&v)))
        .collect();
    out
}

fn summary(all: &Score, per: &BTreeMap<String, Score>, figure: Figure) -> ErrorSummary {
    ErrorSummary {
        all: all.figure(figure),
        per_sensor: per
            .iter()
            .map(|(k, s)| (k.clone(), s.figure(figure)))
            .collect(),
    }
}

/// Fits the camera orientation to the fit set's sun sightings; `None` if there are too few
/// or the declared orientation already explains them within 0.2°.
fn fit_orientation_candidate(
    device: &DeviceConfig,
    captures: &[CaptureData],
    terms: &[CaptureTerms],
    fit: &FitSet<Sample>,
) -> Option<(DeviceConfig, BTreeMap<String, f64>, String)> {
    let camera = crate::camera::CameraModel::new(device.clone());
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

/// Widest shutter overhead the loop considers, µs.
const MAX_SHUTTER_OVERHEAD_US: f64 = 100.0;

/// Fits a shutter overhead t0 (every frame integrates its declared time plus t0) when the fit
/// set shows its signature: readings lit by the sun over-predicted by more than 3 % on
/// average and by more than the others' mean |error|. The fit re-merges every capture
/// per trial t0 and minimises the fit-set error: a scan over 0.5 to 64 µs in octaves, then a
/// golden-section search between the best's neighbours. Returns the candidate, its fit-set
/// error and the re-merged captures and their terms.
#[allow(clippy::type_complexity, clippy::too_many_arguments)]
fn fit_shutter_candidate(
    campaign: &Campaign,
    room: &mut Room,
    device: &DeviceConfig,
    state: &ModelState,
    terms: &[CaptureTerms],
    fit: &FitSet<Sample>,
    reference_outdoor: &[Option<f64>],
    angular: Option<&AngularGlazing>,
) -> Result<Option<(Candidate, f64, Vec<CaptureData>, Vec<CaptureTerms>)>, LoopError> {
    if !state.concentrated_sun {
        return Ok(None);
    }
    let (lit_bias, shade_bias, shade_error, lit_n, shade_n) = sunlit_bias(state, terms, fit);
    if std::env::var_os("SKYLUX_DEBUG_LOOP").is_some() {
        eprintln!(
            "shutter signature: lit {lit_bias} ({lit_n}), shade {shade_bias} |{shade_error}| ({shade_n})"
        );
    }
    // The sunlit readings' bias over and above the others': a common factor (dirty glazing)
    // biases both alike and is no overhead's signature.
    let shade_bias = if shade_bias.is_finite() {
        shade_bias
    } else {
        0.0
    };
    let excess = lit_bias - shade_bias;
    if lit_n < 2 || !excess.is_finite() || excess < 0.03 || excess < shade_error {
        return Ok(None);
    }
    let mut evaluate = |t0: f64| -> Result<(f64, Vec<CaptureData>, Vec<CaptureTerms>), LoopError> {
        let caps = load_captures_with_overhead(campaign, device, t0, &|_, _| {})?;
        let mut t = capture_terms(room, &caps, device, &|_, _| {})?;
        use_reference_outdoor(&mut t, reference_outdoor);
        if let (Some(g), true) = (angular, state.glazing_angular_b0 > 0.0) {
            t = g.apply(&t, state.glazing_angular_b0);
        }
        let e = fit_error(state, &t, fit);
        Ok((if e.is_finite() { e } else { f64::INFINITY }, caps, t))
    };
    let grid: Vec<f64> = (0..8).map(|k| 0.5 * 2f64.powi(k)).collect();
    let mut errors = Vec::new();
    let mut best: Option<(f64, f64, Vec<CaptureData>, Vec<CaptureTerms>)> = None;
    for &t0 in &grid {
        let (e, caps, t) = evaluate(t0)?;
        errors.push(e);
        if best.as_ref().is_none_or(|b| e < b.1) {
            best = Some((t0, e, caps, t));
        }
    }
    let Some(mut best) = best else {
        return Ok(None);
    };
    let i = grid.iter().position(|g| *g == best.0).unwrap_or(0);
    let (mut a, mut b) = (
        if i == 0 { 0.0 } else { grid[i - 1] },
        grid.get(i + 1).copied().unwrap_or(MAX_SHUTTER_OVERHEAD_US),
    );
    // Golden-section search (the fit-set error is unimodal in t0 near its minimum).
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..6 {
        let (x1, x2) = (b - g * (b - a), a + g * (b - a));
        let (e1, c1, t1) = evaluate(x1)?;
        let (e2, c2, t2) = evaluate(x2)?;
        if e1 < e2 {
            b = x2;
            if e1 < best.1 {
                best = (x1, e1, c1, t1);
            }
        } else {
            a = x1;
            if e2 < best.1 {
                best = (x2, e2, c2, t2);
            }
        }
    }
    let (t0, err, caps, t) = best;
    let mut parameters = BTreeMap::new();
    parameters.insert("overhead_us".into(), t0);
    let evidence = format!(
        "readings lit by the sun are over-predicted by {:+.1} % on average ({lit_n} readings) \
         against {:+.1} % (mean |error| {:.1} %) elsewhere ({shade_n}): the short exposures \
         that measure the sun integrate longer than declared",
        100.0 * lit_bias,
        100.0 * shade_bias,
        100.0 * shade_error
    );
    Ok(Some((
        Candidate {
            effect: Effect::ShutterOverhead,
            state: state.clone(),
            parameters,
            evidence,
        },
        err,
        caps,
        t,
    )))
}

/// The Perez baseline per capture: the pyranometer's irradiance through gendaylit's model,
/// the same daylight coefficients, the sun as a concentrated source, a ground of 0.2.
/// Also returns the outdoor horizontal illuminance the pyranometer implies (Perez 1990
/// luminous efficacy, as gendaylit converts), per capture.
#[allow(clippy::type_complexity)]
fn perez_predictions(
    campaign: &Campaign,
    room: &mut Room,
    captures: &[CaptureData],
    window: TimeDelta,
) -> Result<(Vec<Option<Vec<f64>>>, Vec<Option<f64>>), LoopError> {
    let Some(table) = &campaign.pyranometer else {
        return Ok((vec![None; captures.len()], vec![None; captures.len()]));
    };
    let mut outdoor = Vec::new();
    let patches = room.dc.patches();
    let n = patches.len();
    let mut out = Vec::new();
    for c in captures {
        let row = nearest_in_time(&table.rows, window, |r| r.time - c.time);
        let Some(row) = row else {
            out.push(None);
            outdoor.push(None);
            continue;
        };
        let Some(input) = row.perez_input() else {
            out.push(None);
            outdoor.push(None);
            continue;
        };
        let conditions = PerezConditions {
            day_of_year: c.time.ordinal() as u16,
            ..PerezConditions::gendaylit_ang(c.spa_sun)
        };
        let Ok(sky) = PerezSky::new(input, &conditions) else {
            out.push(None);
            outdoor.push(None);
            continue;
        };
        outdoor.push(Some(sky.global_horizontal_illuminance_lux()).filter(|l| l.is_finite()));
        let ground = 0.2 * sky.global_horizontal_illuminance_lux() / std::f64::consts::PI;
        let mut lum: Vec<f64> = (0..n)
            .map(|p| sky.luminance_cd_m2(patches.centre(p)))
            .collect();
        lum.extend(std::iter::repeat_n(ground, n));
        let mut e = room
            .dc
            .apply(&lum)
            .map_err(|e| LoopError::Data(e.to_string()))?;
        let dn = sky.direct_normal_illuminance_lux();
        if dn > 0.0 && c.spa_sun.z > 0.0 {
            let k = room
                .sun_coefficients(c.spa_sun)
                .map_err(|e| LoopError::Data(e.to_string()))?;
            for (ei, (ki, _)) in e.iter_mut().zip(k) {
                *ei += ki * dn;
            }
        }
        out.push(Some(e));
    }
    Ok((out, outdoor))
}

/// Where the campaign has a pyranometer, the outdoor horizontal illuminance it implies
/// replaces the map's own estimate (which extrapolates the sky the lens does not see).
fn use_reference_outdoor(terms: &mut [CaptureTerms], outdoor: &[Option<f64>]) {
    for (t, o) in terms.iter_mut().zip(outdoor) {
        if let Some(o) = o {
            t.outdoor_horizontal_lux = *o;
        }
    }
}

/// Runs the loop on an opened campaign. `progress(stage, done, total)`.
pub fn run_loop(
    campaign: &Campaign,
    options: &LoopOptions,
    progress: &(dyn Fn(&str, u64, u64) + Sync),
) -> Result<LoopOutcome, LoopError> {
    let device_path = campaign.path(&campaign.config.files.device);
    let (declared, device_warnings) = DeviceConfig::read(&device_path).map_err(ModelError::from)?;
    let mut captures = load_captures(campaign, &declared, &|i, n| {
        progress("merging captures", i as u64, n as u64)
    })?;
    let mut room = Room::load(campaign, options.mf, options.settings, &|i, n| {
        progress("daylight coefficients", i, n)
    })?;
    let sensor_names: Vec<String> = room.sensors.iter().map(|s| s.name.clone()).collect();
    // The glazing's geometry: residual variables, and the angular effect where the glazing
    // faces one way.
    let glazing = Glazing::of_world(&room.world);
    let angular = glazing
        .as_ref()
        .ok()
        .filter(|g| g.single_orientation())
        .map(|g| {
            let depths: Vec<f64> = room
                .sensors
                .iter()
                .map(|s| g.facade_distance_m(s.position_m))
                .collect();
            AngularGlazing::new(&room.dc, g.primary().normal_out, depths)
        });
    let mut terms = capture_terms(&mut room, &captures, &declared, &|i, n| {
        progress("sky and sun per capture", i as u64, n as u64)
    })?;
    progress("Perez baseline", 0, 1);
    let (perez, reference_outdoor) =
        perez_predictions(campaign, &mut room, &captures, TimeDelta::minutes(5))?;
    use_reference_outdoor(&mut terms, &reference_outdoor);
    // The sky's colour from the raw frames (a separate pass beside the monochrome merge).
    progress("sky colour", 0, 1);
    let colours =
        super::effect_spectral::sky_colours(campaign, &declared, &captures, &room, &terms)?;
    super::effect_spectral::attach(&room, &mut terms, &colours);
    let base_terms = terms.clone();

    // Samples: each capture with the readings at its time, and the logger's series around
    // it (what a clock offset re-matches).
    let logger = LoggerSeries::new(campaign);
    let series_of: Vec<Vec<Vec<(f64, f64)>>> = captures
        .iter()
        .map(|c| {
            sensor_names
                .iter()
                .map(|name| logger.around(name, c.time, CLOCK_SCAN_S + 2.0 * 60.0))
                .collect()
        })
        .collect();
    let mut samples = Vec::new();
    for (i, c) in captures.iter().enumerate() {
        let measured: Vec<Option<f64>> = sensor_names
            .iter()
            .map(|name| reading_at(campaign, name, c.time, options.match_window))
            .collect();
        if measured.iter().any(Option::is_some) {
            samples.push(Sample {
                capture: i,
                time_utc: c.time.with_timezone(&Utc),
                measured_lux: measured,
                series: series_of[i].clone(),
            });
        }
    }
    if samples.is_empty() {
        return Err(LoopError::Data(
            "no lux-meter reading matches any capture time".into(),
        ));
    }
    let origin = samples.iter().map(|s| s.time_utc).min().expect("non-empty");
    let plan = SplitPlan {
        origin,
        block: options.block,
        period: 2,
        phase: 1,
    };
    let (fit, holdout) = split(samples, &plan)?;
    let fit_times: Vec<String> = fit.times().iter().map(|t| t.to_rfc3339()).collect();
    let holdout_times: Vec<String> = holdout.times().iter().map(|t| t.to_rfc3339()).collect();

    let mut state = options.base.clone();
    let mut device = declared.clone();
    let base_predictions: Vec<Vec<f64>> = terms.iter().map(|t| predict(&state, t)).collect();
    let (before_all, before_per) = score(
        &holdout,
        &|c| base_predictions[c].clone(),
        &sensor_names,
        state.clock_offset_s,
    );
    let mut current_holdout = before_all.clone();
    let mut effects = Vec::new();
    let mut rejected = Vec::new();
    let mut notes: Vec<String> = device_warnings
        .into_iter()
        .map(|w| format!("{}: {w}", device_path.display()))
        .collect();
    match &glazing {
        Err(e) => notes.push(format!(
            "glazing: {e}; no solar incidence or façade distance, glazing_angular not tried"
        )),
        Ok(g) if angular.is_none() => notes.push(format!(
            "glazing: {} planes facing different ways; glazing_angular not tried",
            g.planes.len()
        )),
        Ok(_) => {}
    }

    // The geometric effect first, judged against its own reference instrument: the sun
    // sightings against SPA (its signature is there, not in the illuminance).
    {
        if let Some((dev, params, evidence)) =
            fit_orientation_candidate(&device, &captures, &terms, &fit)
        {
            let mut new_terms = capture_terms(&mut room, &captures, &dev, &|_, _| {})?;
            use_reference_outdoor(&mut new_terms, &reference_outdoor);
            super::effect_spectral::attach(&room, &mut new_terms, &colours);
            let offset = |t: &[CaptureTerms]| {
                holdout.evaluate(|s: &Sample| {
                    t[s.capture].sun.as_ref().map(|sun| {
                        sun.direction
                            .angle_between(captures[s.capture].spa_sun)
                            .to_degrees()
                    })
                })
            };
            let (sun_before, sun_after) = (offset(&terms), offset(&new_terms));
            let cmp = compare(&sun_before, &sun_after, Figure::MeanAbs);
            let noise = if cmp.noise.is_finite() {
                cmp.noise
            } else {
                0.0
            };
            let (after_all, _) = score(
                &holdout,
                &|c| predict(&state, &new_terms[c]),
                &sensor_names,
                state.clock_offset_s,
            );
            let illum = compare(&current_holdout, &after_all, Figure::MeanAbs);
            let illum_noise = if illum.noise.is_finite() {
                illum.noise
            } else {
                0.0
            };
            if sun_after.n > 0 && cmp.gain > noise && cmp.gain > 0.0 && illum.gain >= -illum_noise {
                effects.push(EffectReport {
                    name: Effect::OrientationError.name().into(),
                    parameters: params,
                    evidence: format!(
                        "{evidence}; on the hold-out captures the sun sightings moved from \
                         {:.2}° to {:.2}° from SPA",
                        sun_before.mean_abs, sun_after.mean_abs
                    ),
                    gain: illum.gain,
                    fit_error_before: Some(fit_error(&state, &terms, &fit)),
                    fit_error_after: Some(fit_error(&state, &new_terms, &fit)),
                });
                device = dev;
                terms = new_terms;
                current_holdout = after_all;
            } else {
                rejected.push(format!(
                    "orientation_error: hold-out sun offset {:.2}° → {:.2}° (noise {:.2}°), \
                 illuminance error change {:+.2} %: not added",
                    sun_before.mean_abs,
                    sun_after.mean_abs,
                    noise,
                    -100.0 * illum.gain
                ));
            }
        }
    }
    // The sky effects (vignetting, the field of view) rescale the per-bin luminances of the
    // terms without them, under the camera as it now stands.
    let sky_patches = room.dc.patches();
    let mut sky_raw = terms.clone();
    let mut sky_geometry = SkyGeometry::new(&sky_patches, &captures, &terms, &device);
    if sky_geometry.lens_fov_deg - sky_geometry.median_shown_fov_deg() >= MIN_CLIPPED_DEG {
        sky_geometry.hidden_sun = hidden_suns(
            campaign,
            &mut room,
            &captures,
            &terms,
            &device,
            &sky_geometry,
        )?;
    }
    while effects.len() < options.max_effects {
        progress(
            "fitting effects",
            effects.len() as u64,
            options.max_effects as u64,
        );
        let base_fit = fit_error(&state, &terms, &fit);
        let accepted: Vec<Effect> = Effect::ALL
            .into_iter()
            .filter(|x| effects.iter().any(|e| e.name == x.name()))
            .collect();
        let mut candidates: Vec<Ranked> = Vec::new();
        for effect in Effect::ALL {
            if effects
                .iter()
                .any(|e: &EffectReport| e.name == effect.name())
            {
                continue;
            }
            if effect == Effect::OrientationError {
                continue; // judged on the sun sightings above
            }
            if let Some(c) = fit_effect(effect, &state, &accepted, &terms, &fit) {
                let err = fit_error(&c.state, &terms, &fit);
                candidates.push((c, err));
            }
        }
        // The shutter overhead re-merges every capture per trial value: tried only when its
        // signature (a positive bias where the sun lights the sensors) is in the residual.
        let mut shutter: Option<(Vec<CaptureData>, Vec<CaptureTerms>)> = None;
        if !accepted.contains(&Effect::ShutterOverhead) {
            if let Some((c, err, caps, mut t)) = fit_shutter_candidate(
                campaign,
                &mut room,
                &device,
                &state,
                &terms,
                &fit,
                &reference_outdoor,
                angular.as_ref(),
            )? {
                super::effect_spectral::attach(&room, &mut t, &colours);
                candidates.push((c, err));
                shutter = Some((caps, t));
            }
        }
        // The glazing's angular transmittance rescales the bins of the current terms (which
        // do not carry it yet) and re-applies the daylight coefficients.
        let mut angular_terms: Option<Vec<CaptureTerms>> = None;
        // Its signature is read on the sunlit readings, whose direct part is the
        // concentrated sun's: while the sun is still spread over its patch, undersampling
        // dominates that residual and the angular fit would explain it away.
        let angular_ready = state.concentrated_sun && !accepted.contains(&Effect::GlazingAngular);
        if let (Some(g), true) = (&angular, angular_ready) {
            if let Some((c, err, t)) = fit_glazing_angular(g, &state, &accepted, &terms, &fit) {
                candidates.push((c, err));
                angular_terms = Some(t);
            }
        }
        let mut sky_candidates: Vec<(Effect, Vec<CaptureTerms>)> = Vec::new();
        for (effect, fitted) in [
            (Effect::Vignetting, fit_vignetting as super::effects::SkyFit),
            (Effect::SkyOutsideFov, fit_unseen_sky),
        ] {
            if accepted.contains(&effect) {
                continue;
            }
            if let Some((c, t)) = fitted(&state, &sky_raw, &room.dc, &sky_geometry, &fit) {
                let err = fit_error(&c.state, &t, &fit);
                candidates.push((c, err));
                sky_candidates.push((effect, t));
            }
        }
        candidates.sort_by(|a, b| a.1.total_cmp(&b.1));
        let Some((best, best_fit)) = candidates.into_iter().next() else {
            break;
        };
        let (best_terms, best_captures) = match (&best.effect, shutter) {
            (Effect::ShutterOverhead, Some((caps, t))) => (Some(t), Some(caps)),
            _ => (None, None),
        };
        let best_terms = match (&best.effect, angular_terms) {
            (Effect::GlazingAngular, Some(t)) => Some(t),
            _ => best_terms,
        };
        let best_terms = best_terms.or_else(|| {
            sky_candidates
                .into_iter()
                .find(|(e, _)| *e == best.effect)
                .map(|(_, t)| t)
        });
        let candidate_terms = best_terms.as_deref().unwrap_or(&terms);
        if best_fit.is_nan() || best_fit >= base_fit - 0.002 {
            notes.push(format!(
                "no remaining effect lowers the fit-set error by more than 0.2 % (best: {} from \
                 {:.2} % to {:.2} %)",
                best.effect.name(),
                100.0 * base_fit,
                100.0 * best_fit
            ));
            break;
        }
        let (after_all, _) = score(
            &holdout,
            &|c| predict(&best.state, &candidate_terms[c]),
            &sensor_names,
            best.state.clock_offset_s,
        );
        let cmp = compare(&current_holdout, &after_all, Figure::MeanAbs);
        let noise = if cmp.noise.is_finite() {
            cmp.noise
        } else {
            0.0
        };
        if cmp.gain <= noise || cmp.gain <= 0.0 {
            rejected.push(format!(
                "{}: fit-set error {:.2} % → {:.2} %, but the hold-out error changed by {:+.2} % \
                 (noise {:.2} %): not added",
                best.effect.name(),
                100.0 * base_fit,
                100.0 * best_fit,
                -100.0 * cmp.gain,
                100.0 * noise
            ));
            break;
        }
        effects.push(EffectReport {
            name: best.effect.name().into(),
            parameters: best.parameters.clone(),
            evidence: best.evidence.clone(),
            gain: cmp.gain,
            fit_error_before: Some(base_fit),
            fit_error_after: Some(best_fit),
        });
        state = best.state;
        let remerged = best_captures.is_some();
        if let Some(t) = best_terms {
            terms = t;
        }
        if let Some(c) = best_captures {
            captures = c;
        }
        if remerged {
            // New maps: new raw terms for the sky effects, with those already added re-applied.
            sky_raw = terms.clone();
            sky_geometry = SkyGeometry::new(&sky_patches, &captures, &sky_raw, &device);
            if sky_geometry.lens_fov_deg - sky_geometry.median_shown_fov_deg() >= MIN_CLIPPED_DEG {
                sky_geometry.hidden_sun = hidden_suns(
                    campaign,
                    &mut room,
                    &captures,
                    &sky_raw,
                    &device,
                    &sky_geometry,
                )?;
            }
            terms = correct_terms(&sky_raw, &room.dc, &sky_geometry, &state);
        }
        for e in effects.iter_mut() {
            match e.name.as_str() {
                "glazing_transmittance" => {
                    e.parameters
                        .insert("relative_transmittance".into(), state.glazing_transmittance);
                }
                "light_leak" => {
                    e.parameters
                        .insert("lux_per_outdoor_lux".into(), state.light_leak);
                }
                "ground_reflectance" => {
                    e.parameters
                        .insert("reflectance".into(), state.ground_reflectance);
                }
                "clock_offset" => {
                    e.parameters
                        .insert("logger_minus_device_s".into(), state.clock_offset_s);
                }
                "spectral_mismatch" => {
                    e.parameters
                        .insert("slope_per_index".into(), state.spectral_slope);
                }
                _ => {}
            }
        }
        current_holdout = score(
            &holdout,
            &|c| predict(&state, &terms[c]),
            &sensor_names,
            state.clock_offset_s,
        )
        .0;
    }
    if effects.is_empty() {
        notes.push(
            "no effect was added: the declared model explains the fit set within its noise".into(),
        );
    }
    let final_predictions: Vec<Vec<f64>> = terms.iter().map(|t| predict(&state, t)).collect();
    let (after_all, after_per) = score(
        &holdout,
        &|c| final_predictions[c].clone(),
        &sensor_names,
        state.clock_offset_s,
    );

    let baseline = if perez.iter().any(Option::is_some) {
        let (a, p) = score(
            &holdout,
            &|c| {
                perez[c]
                    .clone()
                    .unwrap_or_else(|| vec![f64::NAN; sensor_names.len()])
            },
            &sensor_names,
            state.clock_offset_s,
        );
        Some((a, p))
    } else {
        None
    };

    let mut secondary = BTreeMap::new();
    secondary.insert(
        "before_rmse_rel".into(),
        summary(&before_all, &before_per, Figure::Rmse),
    );
    secondary.insert(
        "after_rmse_rel".into(),
        summary(&after_all, &after_per, Figure::Rmse),
    );
    if let Some((a, p)) = &baseline {
        secondary.insert(
            "baseline_perez_rmse_rel".into(),
            summary(a, p, Figure::Rmse),
        );
    }
    let report = Report {
        metric: "mean_abs_rel_error".into(),
        fit_times,
        holdout_times,
        before: summary(&before_all, &before_per, Figure::MeanAbs),
        after: summary(&after_all, &after_per, Figure::MeanAbs),
        baseline_perez: baseline
            .as_ref()
            .map(|(a, p)| summary(a, p, Figure::MeanAbs)),
        effects,
        secondary,
        rejected,
        notes,
        figures: vec![],
    };

    // Diagnostics per reading, with the variables the effects are judged on.
    let holdout_set: std::collections::HashSet<String> =
        report.holdout_times.iter().cloned().collect();
    let concentrated = ModelState {
        concentrated_sun: true,
        ..state.clone()
    };
    let mut diagnostics = Vec::new();
    for (i, c) in captures.iter().enumerate() {
        let t = &terms[i];
        let parts = super::device_model::parts(&concentrated, t);
        let total = predict(&concentrated, t);
        let sun_offset_deg = base_terms[i].sun.as_ref().map_or(f64::NAN, |s| {
            s.direction.angle_between(c.spa_sun).to_degrees()
        });
        let light_off_axis = light_off_axis_deg(t, &room.dc, &sky_geometry, i);
        for (k, name) in sensor_names.iter().enumerate() {
            let Some(m0) = reading_at(campaign, name, c.time, options.match_window) else {
                continue;
            };
            let m = if state.clock_offset_s == 0.0 {
                Some(m0)
            } else {
                interpolate(&series_of[i][k], state.clock_offset_s)
            };
            let Some(m) = m else {
                continue;
            };
            let direct = t.sun_lux_per_dn_lux[k] * t.sun_dn_lux * state.glazing_transmittance;
            diagnostics.push(Diagnostic {
                time: c.time,
                sensor: name.clone(),
                holdout: holdout_set.contains(&c.time.with_timezone(&Utc).to_rfc3339()),
                measured_lux: m,
                measured_before_lux: m0,
                before_lux: base_predictions[i][k],
                after_lux: final_predictions[i][k],
                outdoor_lux: t.outdoor_horizontal_lux,
                direct_sun_share: if total[k] > 0.0 {
                    direct / total[k]
                } else {
                    0.0
                },
                unseen_ground_share: if total[k] > 0.0 {
                    state.glazing_transmittance * state.ground_reflectance * parts[k].1 / total[k]
                } else {
                    0.0
                },
                sun_offset_deg,
                rate_of_change_per_min: relative_rate_per_min(
                    &series_of[i][k],
                    options.base.clock_offset_s,
                ),
                sun_visible: if t.sun.is_some() { 1.0 } else { 0.0 },
                sun_altitude_deg: c.spa_sun.z.clamp(-1.0, 1.0).asin().to_degrees(),
                sun_azimuth_deg: c
                    .spa_sun
                    .x
                    .atan2(c.spa_sun.y)
                    .to_degrees()
                    .rem_euclid(360.0),
                unseen_sky_fraction: t.unseen_sky_fraction,
                saturated_fraction: t.saturated_fraction,
                local_hour: f64::from(c.time.hour())
                    + f64::from(c.time.minute()) / 60.0
                    + f64::from(c.time.second()) / 3600.0,
                sky_colour_index: t
                    .spectral
                    .as_ref()
                    .map_or(f64::NAN, |sp| sp.colour.sky_index),
                sun_incidence_deg: glazing
                    .as_ref()
                    .map_or(f64::NAN, |g| g.primary().incidence_deg(c.spa_sun)),
                facade_distance_m: glazing.as_ref().map_or(f64::NAN, |g| {
                    g.facade_distance_m(room.sensors[k].position_m)
                }),
                light_off_axis_deg: light_off_axis[k],
            });
        }
    }

    // illuminance.csv rows for every capture and sensor.
    let mut rows = Vec::new();
    for (i, c) in captures.iter().enumerate() {
        let time = c.time.to_rfc3339();
        for (k, name) in sensor_names.iter().enumerate() {
            let measured = reading_at(campaign, name, c.time, options.match_window);
            let shifted = if state.clock_offset_s == 0.0 {
                measured
            } else {
                interpolate(&series_of[i][k], state.clock_offset_s)
            };
            let mut push = |model: &str, lux: f64, measured: Option<f64>| {
                rows.push(IlluminanceRow {
                    time: time.clone(),
                    sensor: name.clone(),
                    lux_model: lux,
                    lux_measured: measured,
                    model: model.into(),
                })
            };
            push("hdr-base", base_predictions[i][k], measured);
            push("hdr", final_predictions[i][k], shifted);
            if let Some(p) = &perez[i] {
                push("perez", p[k], measured);
            }
        }
    }
    let residuals = residual_rows(&diagnostics);
    Ok(LoopOutcome {
        report,
        rows,
        residuals,
        diagnostics,
        state,
        device,
    })
}

/// The item whose time offset (item minus target) is smallest in magnitude and within
/// `window`: the one rule by which readings are matched to capture times.
pub(super) fn nearest_in_time<'a, T>(
    items: impl IntoIterator<Item = &'a T>,
    window: TimeDelta,
    offset: impl Fn(&T) -> TimeDelta,
) -> Option<&'a T> {
    items
        .into_iter()
        .filter(|r| offset(r).abs() <= window)
        .min_by_key(|r| offset(r).abs())
}

/// The lux-meter `sensor`'s reading nearest to `time` within `window`.
fn reading_at<Tz: chrono::TimeZone>(
    campaign: &Campaign,
    sensor: &str,
    time: chrono::DateTime<Tz>,
    window: TimeDelta,
) -> Option<f64> {
    nearest_in_time(
        campaign.luxmeters.iter().filter(|r| r.sensor == sensor),
        window,
        |r| r.time.signed_duration_since(time.clone()),
    )
    .map(|r| r.illuminance_lux)
}

/// The lux-meter readings per sensor in time order, for the series around each capture.
struct LoggerSeries {
    by_sensor: BTreeMap<String, Vec<(chrono::DateTime<Utc>, f64)>>,
}

impl LoggerSeries {
    fn new(campaign: &Campaign) -> Self {
        let mut by_sensor: BTreeMap<String, Vec<(chrono::DateTime<Utc>, f64)>> = BTreeMap::new();
        for r in &campaign.luxmeters {
            by_sensor
                .entry(r.sensor.clone())
                .or_default()
                .push((r.time.with_timezone(&Utc), r.illuminance_lux));
        }
        for v in by_sensor.values_mut() {
            v.sort_by_key(|p| p.0);
        }
        Self { by_sensor }
    }

    /// `sensor`'s readings within `half_window_s` of `time`: (seconds from `time`, lux).
    fn around<Tz: chrono::TimeZone>(
        &self,
        sensor: &str,
        time: chrono::DateTime<Tz>,
        half_window_s: f64,
    ) -> Vec<(f64, f64)> {
        let Some(v) = self.by_sensor.get(sensor) else {
            return Vec::new();
        };
        let t = time.with_timezone(&Utc);
        let half = TimeDelta::milliseconds((half_window_s * 1000.0) as i64);
        let start = v.partition_point(|p| p.0 < t - half);
        v[start..]
            .iter()
            .take_while(|p| p.0 <= t + half)
            .map(|p| ((p.0 - t).num_milliseconds() as f64 / 1000.0, p.1))
            .collect()
    }
}
