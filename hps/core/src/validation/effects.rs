//! The effect library of the illuminance loop: each effect is a parametric change to the
//! device model, a fit on the fit set only, and the residual signature that is its evidence.
//!
//! Fits minimise the squared relative residual (prediction / measurement − 1) over the fit
//! set; the linear effects (transmittance, leak, ground) have closed forms.

use super::device_model::{parts, predict, CaptureTerms, ModelState};
use super::split::FitSet;
use std::collections::BTreeMap;

/// One fit-set sample: a capture and the lux-meter readings at its time.
#[derive(Clone, Debug)]
pub struct Sample {
    pub capture: usize,
    pub time_utc: chrono::DateTime<chrono::Utc>,
    /// Per sensor (in the room's order); `None` where no reading matched.
    pub measured_lux: Vec<Option<f64>>,
    /// Per sensor, the logger's readings near the capture: (logger timestamp − capture time,
    /// seconds; lux), in time order. What the clock-offset effect re-matches.
    pub series: Vec<Vec<(f64, f64)>>,
}

/// Longest gap between two logger readings across which a reading is interpolated, s.
pub const MAX_INTERPOLATION_GAP_S: f64 = 150.0;

/// The logger's reading at `at_s` (seconds from the capture, logger clock), linearly
/// interpolated between the two readings around it; `None` outside the series or across a
/// gap longer than [`MAX_INTERPOLATION_GAP_S`].
pub fn interpolate(series: &[(f64, f64)], at_s: f64) -> Option<f64> {
    let i = series.partition_point(|(t, _)| *t < at_s);
    if i < series.len() && series[i].0 == at_s {
        return Some(series[i].1);
    }
    if i == 0 || i == series.len() {
        return None;
    }
    let ((t0, v0), (t1, v1)) = (series[i - 1], series[i]);
    if t1 - t0 > MAX_INTERPOLATION_GAP_S || t1 <= t0 {
        return None;
    }
    Some(v0 + (v1 - v0) * (at_s - t0) / (t1 - t0))
}

/// Relative rate of change of a logger series at `at_s`, per minute: the slope of the
/// readings within ±60 s (least squares) over their mean. NaN with fewer than 2 readings.
pub fn relative_rate_per_min(series: &[(f64, f64)], at_s: f64) -> f64 {
    let near: Vec<(f64, f64)> = series
        .iter()
        .copied()
        .filter(|(t, _)| (t - at_s).abs() <= 60.0 + 1e-9)
        .collect();
    if near.len() < 2 {
        return f64::NAN;
    }
    let n = near.len() as f64;
    let (mt, mv) = (
        near.iter().map(|p| p.0).sum::<f64>() / n,
        near.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let (sxy, sxx) = near.iter().fold((0.0, 0.0), |(a, b), (t, v)| {
        (a + (t - mt) * (v - mv), b + (t - mt).powi(2))
    });
    if sxx <= 0.0 || mv <= 0.0 {
        return f64::NAN;
    }
    60.0 * sxy / sxx / mv
}

impl Sample {
    /// Sensor `k`'s reading of the light at the capture time for a logger clock running
    /// `clock_offset_s` ahead of the device's: the matched reading without an offset, else
    /// the series interpolated at the offset.
    pub fn measured(&self, k: usize, clock_offset_s: f64) -> Option<f64> {
        if clock_offset_s == 0.0 {
            return self.measured_lux.get(k).copied().flatten();
        }
        interpolate(self.series.get(k)?, clock_offset_s)
    }
}

impl super::split::Timed for Sample {
    fn time_utc(&self) -> chrono::DateTime<chrono::Utc> {
        self.time_utc
    }
}

/// A sky effect's fit: from the state, the terms without the sky effects, the daylight
/// coefficients and the capture geometry, a candidate and its corrected terms.
pub type SkyFit = fn(
    &ModelState,
    &[CaptureTerms],
    &crate::engine::DaylightCoefficients,
    &super::effect_vignetting::SkyGeometry,
    &FitSet<Sample>,
) -> Option<(Candidate, Vec<CaptureTerms>)>;

/// The effects the loop knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Effect {
    /// The sun spread over its sky patch instead of sampled as a concentrated source.
    SunUndersampling,
    /// Glazing transmittance different from the scene's (dirt, coating, ageing).
    GlazingTransmittance,
    /// Light the scene lacks, proportional to the outdoor horizontal illuminance.
    LightLeak,
    /// Reflectance of the ground the lens does not see.
    GroundReflectance,
    /// The camera's orientation differs from `device.toml`.
    OrientationError,
    /// The lux-meter logger's clock is offset from the device's.
    ClockOffset,
    /// The shutter integrates longer than declared by a fixed overhead.
    ShutterOverhead,
    /// The camera's luminance depends on the sky's colour (spectral mismatch).
    SpectralMismatch,
    /// The glazing's transmittance falls with incidence faster than the scene's glass says.
    GlazingAngular,
    /// The lens's relative illumination falls off more steeply than the declared polynomial.
    Vignetting,
    /// A baffle clips the field of view: the sky beyond is extrapolated, and mis-estimated.
    SkyOutsideFov,
}

impl Effect {
    pub const ALL: [Effect; 11] = [
        Effect::SunUndersampling,
        Effect::GlazingTransmittance,
        Effect::LightLeak,
        Effect::GroundReflectance,
        Effect::OrientationError,
        Effect::ClockOffset,
        Effect::ShutterOverhead,
        Effect::SpectralMismatch,
        Effect::GlazingAngular,
        Effect::Vignetting,
        Effect::SkyOutsideFov,
    ];

    /// The name in reports and in `skylux sim campaign --effect NAME=VALUE`.
    pub fn name(self) -> &'static str {
        match self {
            Effect::SunUndersampling => "sun_undersampling",
            Effect::GlazingTransmittance => "glazing_transmittance",
            Effect::LightLeak => "light_leak",
            Effect::GroundReflectance => "ground_reflectance",
            Effect::OrientationError => "orientation_error",
            Effect::ClockOffset => "clock_offset",
            Effect::ShutterOverhead => "shutter_overhead",
            Effect::SpectralMismatch => "spectral_mismatch",
            Effect::GlazingAngular => "glazing_angular",
            Effect::Vignetting => "vignetting",
            Effect::SkyOutsideFov => "sky_outside_fov",
        }
    }
}

/// (prediction, measurement) pairs of the fit set under `state`.
pub fn pairs(state: &ModelState, terms: &[CaptureTerms], fit: &FitSet<Sample>) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for s in fit.samples() {
        let p = predict(state, &terms[s.capture]);
        for (k, pi) in p.iter().enumerate() {
            if let Some(m) = s.measured(k, state.clock_offset_s) {
                if m > 0.0 && pi.is_finite() {
                    out.push((*pi, m));
                }
            }
        }
    }
    out
}

/// Mean |relative error| of the fit set under `state`.
pub fn fit_error(state: &ModelState, terms: &[CaptureTerms], fit: &FitSet<Sample>) -> f64 {
    let p = pairs(state, terms, fit);
    if p.is_empty() {
        return f64::NAN;
    }
    p.iter().map(|(p, m)| (p / m - 1.0).abs()).sum::<f64>() / p.len() as f64
}

/// Which of the linear effects' parameters are free in a joint fit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FreeLinear {
    pub glazing: bool,
    pub ground: bool,
    pub leak: bool,
}

impl FreeLinear {
    /// The linear effects among `effects`.
    pub fn of(effects: &[Effect]) -> Self {
        Self {
            glazing: effects.contains(&Effect::GlazingTransmittance),
            ground: effects.contains(&Effect::GroundReflectance),
            leak: effects.contains(&Effect::LightLeak),
        }
    }
}

/// Jointly fits the free linear parameters (glazing τ, unseen-ground ρ through u = τ and
/// v = τρ, leak k) on the fit set, minimising Σ (prediction / measurement − 1)²; the others
/// keep their values in `state`. Returns the new state, or `None` if the fit set cannot
/// determine them.
pub fn fit_linear(
    state: &ModelState,
    free: FreeLinear,
    terms: &[CaptureTerms],
    fit: &FitSet<Sample>,
) -> Option<ModelState> {
    // Columns of the design and the constant part of each reading.
    let mut rows: Vec<(Vec<f64>, f64, f64)> = Vec::new();
    for s in fit.samples() {
        let t = &terms[s.capture];
        for (k, (room, ground, outdoor)) in parts(state, t).into_iter().enumerate() {
            let Some(m) = s.measured(k, state.clock_offset_s).filter(|m| *m > 0.0) else {
                continue;
            };
            let (tau, rho, leak) = (
                state.glazing_transmittance,
                state.ground_reflectance,
                state.light_leak,
            );
            let mut cols = Vec::new();
            let mut constant = 0.0;
            match (free.glazing, free.ground) {
                (true, true) => {
                    cols.push(room);
                    cols.push(ground);
                }
                (true, false) => cols.push(room + rho * ground),
                (false, true) => {
                    constant += tau * room;
                    cols.push(tau * ground);
                }
                (false, false) => constant += tau * (room + rho * ground),
            }
            if free.leak {
                cols.push(outdoor);
            } else {
                constant += leak * outdoor;
            }
            rows.push((cols, constant, m));
        }
    }
    let n = rows.first().map_or(0, |r| r.0.len());
    if n == 0 || rows.len() <= n {
        return None;
    }
    let mut a = vec![vec![0.0; n]; n];
    let mut b = vec![0.0; n];
    for (cols, constant, m) in &rows {
        let w = 1.0 / (m * m);
        for i in 0..n {
            b[i] += w * cols[i] * (m - constant);
            for j in 0..n {
                a[i][j] += w * cols[i] * cols[j];
            }
        }
    }
    let x = crate::numerics::linalg::solve(&a, &b)?;
    let mut next = state.clone();
    let mut i = 0;
    match (free.glazing, free.ground) {
        (true, true) => {
            next.glazing_transmittance = x[0].clamp(0.05, 2.0);
            next.ground_reflectance = (x[1] / next.glazing_transmittance).clamp(0.0, 1.0);
            i = 2;
        }
        (true, false) => {
            next.glazing_transmittance = x[0].clamp(0.05, 2.0);
            i = 1;
        }
        (false, true) => {
            next.ground_reflectance = x[0].clamp(0.0, 1.0);
            i = 1;
        }
        (false, false) => {}
    }
    if free.leak {
        next.light_leak = x[i].max(0.0);
    }
    Some(next)
}

/// Pearson's r of a residual signature; NaN where it is undefined, so no threshold passes.
pub fn pearson_r(xy: &[(f64, f64)]) -> f64 {
    crate::numerics::pearson(xy).map_or(f64::NAN, |p| p.r)
}

/// A fitted candidate.
#[derive(Clone, Debug)]
pub struct Candidate {
    pub effect: Effect,
    pub state: ModelState,
    pub parameters: BTreeMap<String, f64>,
    pub evidence: String,
}

/// Readings of the fit set with their capture's terms (re-matched for `state`'s clock
/// offset).
fn readings<'a>(
    state: &ModelState,
    terms: &'a [CaptureTerms],
    fit: &'a FitSet<Sample>,
) -> impl Iterator<Item = (&'a CaptureTerms, usize, f64)> + 'a {
    let offset = state.clock_offset_s;
    fit.samples().iter().flat_map(move |s| {
        (0..s.measured_lux.len()).filter_map(move |k| {
            s.measured(k, offset)
                .filter(|m| *m > 0.0)
                .map(|m| (&terms[s.capture], k, m))
        })
    })
}

/// (x, predicted / measured − 1) for every reading of the fit set under `state`, where
/// `x(capture, terms)` gives the variable per sensor (readings where it is not finite are left
/// out): the points whose correlation is an effect's residual signature.
pub(super) fn residual_points(
    state: &ModelState,
    terms: &[CaptureTerms],
    fit: &FitSet<Sample>,
    mut x: impl FnMut(usize, &CaptureTerms) -> Vec<f64>,
) -> Vec<(f64, f64)> {
    let mut points = Vec::new();
    for s in fit.samples() {
        let t = &terms[s.capture];
        let p = super::device_model::predict(state, t);
        let xs = x(s.capture, t);
        for (k, pk) in p.iter().enumerate() {
            let Some(m) = s.measured(k, state.clock_offset_s).filter(|m| *m > 0.0) else {
                continue;
            };
            if let Some(xk) = xs.get(k).filter(|v| v.is_finite()) {
                points.push((*xk, pk / m - 1.0));
            }
        }
    }
    points
}

/// Widest clock offset the loop scans, seconds.
pub const CLOCK_SCAN_S: f64 = 300.0;

/// Fits the logger's clock offset: a scan of the fit-set error over ±[`CLOCK_SCAN_S`] in 10 s
/// steps, then 1 s steps around the best. `None` without logger series around the captures
/// (one reading per capture cannot show an offset) or if the best offset is the current one.
fn fit_clock_offset(
    state: &ModelState,
    terms: &[CaptureTerms],
    fit: &FitSet<Sample>,
) -> Option<(ModelState, String)> {
    let dense = fit
        .samples()
        .iter()
        .any(|s| s.series.iter().any(|v| v.len() >= 5));
    if !dense {
        return None;
    }
    let at = |dt: f64| {
        let st = ModelState {
            clock_offset_s: dt,
            ..state.clone()
        };
        let e = fit_error(&st, terms, fit);
        (if e.is_finite() { e } else { f64::INFINITY }, st)
    };
    let mut best = (f64::INFINITY, 0.0);
    let steps = (CLOCK_SCAN_S / 10.0) as i32;
    for k in -steps..=steps {
        let dt = 10.0 * k as f64;
        let (e, _) = at(dt);
        if e < best.0 {
            best = (e, dt);
        }
    }
    let coarse = best.1;
    for k in -10..=10 {
        let dt = coarse + k as f64;
        let (e, _) = at(dt);
        if e < best.0 {
            best = (e, dt);
        }
    }
    // An offset shorter than the logger's interval cannot be pinned: between two readings
    // the light is only interpolated, and on a changing sky a shift of a fraction of the
    // interval lowers the fit error by chance (a partly cloudy campaign with no offset found
    // +16 s at 30 s logging, r = 0.20; the true 120 s offset is found as 137 s, r = 0.45).
    let mut steps_s: Vec<f64> = fit
        .samples()
        .iter()
        .flat_map(|s| s.series.iter())
        .flat_map(|v| v.windows(2).map(|w| w[1].0 - w[0].0))
        .filter(|d| *d > 0.0)
        .collect();
    steps_s.sort_by(f64::total_cmp);
    let interval_s = steps_s.get(steps_s.len() / 2).copied().unwrap_or(0.0);
    let shift_s = (best.1 - state.clock_offset_s).abs();
    if !best.0.is_finite() || shift_s < 1.0 || shift_s < interval_s {
        return None;
    }
    // Signature: the residual follows the measured rate of change of the illuminance.
    let xy: Vec<(f64, f64)> = fit
        .samples()
        .iter()
        .flat_map(|s| {
            let p = predict(state, &terms[s.capture]);
            (0..s.series.len())
                .filter_map(|k| {
                    let m = s.measured(k, state.clock_offset_s)?;
                    let rate = relative_rate_per_min(&s.series[k], state.clock_offset_s);
                    (m > 0.0 && rate.is_finite()).then(|| (rate, p[k] / m - 1.0))
                })
                .collect::<Vec<_>>()
        })
        .collect();
    let r = pearson_r(&xy);
    let evidence = format!(
        "the relative residual follows the rate of change of the measured illuminance          (r = {r:.2} over {} readings): the readings are matched at the wrong time;          re-matched {:+.0} s later on the logger's clock",
        xy.len(),
        best.1 - state.clock_offset_s
    );
    Some((at(best.1).1, evidence))
}

/// Fits one of the output-level effects (all but the orientation, which changes the camera
/// and is fitted from the sun's sightings by the loop) on the fit set, from `state`.
///
/// The linear effects are fitted jointly with the linear effects already `accepted`, so
/// an effect added earlier is corrected for the one added now.
pub fn fit_effect(
    effect: Effect,
    state: &ModelState,
    accepted: &[Effect],
    terms: &[CaptureTerms],
    fit: &FitSet<Sample>,
) -> Option<Candidate> {
    let mut with = accepted.to_vec();
    with.push(effect);
    let joint = || fit_linear(state, FreeLinear::of(&with), terms, fit);
    let mut next = state.clone();
    let mut parameters = BTreeMap::new();
    let evidence;
    match effect {
        Effect::SunUndersampling => {
            if state.concentrated_sun {
                return None;
            }
            next.concentrated_sun = true;
            // Signature: the error sits where the direct sun reaches the sensor.
            let (mut lit, mut shade) = (vec![], vec![]);
            for (t, k, m) in readings(state, terms, fit) {
                let e = (predict(state, t)[k] / m - 1.0).abs();
                if t.sun_lux_per_dn_lux[k] * t.sun_dn_lux > 0.05 * m {
                    lit.push(e);
                } else {
                    shade.push(e);
                }
            }
            if lit.is_empty() {
                return None;
            }
            let mean = |v: &[f64]| {
                if v.is_empty() {
                    0.0
                } else {
                    v.iter().sum::<f64>() / v.len() as f64
                }
            };
            evidence = format!(
                "the error sits where direct sun reaches the sensor: mean |relative error| {:.1} % \
                 in {} sunlit readings against {:.1} % in {} others",
                100.0 * mean(&lit),
                lit.len(),
                100.0 * mean(&shade),
                shade.len()
            );
        }
        Effect::GlazingTransmittance => {
            let room_only = ModelState {
                light_leak: 0.0,
                glazing_transmittance: 1.0,
                ..state.clone()
            };
            let rows: Vec<(f64, f64, f64)> = readings(state, terms, fit)
                .map(|(t, k, m)| {
                    (
                        predict(&room_only, t)[k],
                        state.light_leak * t.outdoor_horizontal_lux,
                        m,
                    )
                })
                .collect();
            next = joint()?;
            let tau = next.glazing_transmittance;
            parameters.insert("relative_transmittance".into(), tau);
            let ratios: Vec<f64> = rows.iter().map(|(a, b, m)| (m - b) / a).collect();
            let mean = ratios.iter().sum::<f64>() / ratios.len() as f64;
            let sd = (ratios.iter().map(|r| (r - mean).powi(2)).sum::<f64>()
                / ratios.len().max(2) as f64)
                .sqrt();
            evidence = format!(
                "measured / modelled illuminance is {mean:.3} ± {sd:.3} on every sensor and \
                 under every sky: a common factor on all light through the glazing"
            );
        }
        Effect::LightLeak => {
            let rows: Vec<(f64, f64, f64)> = readings(state, terms, fit)
                .map(|(t, k, m)| {
                    let p = predict(state, t)[k] - state.light_leak * t.outdoor_horizontal_lux;
                    (t.outdoor_horizontal_lux, p, m)
                })
                .collect();
            next = joint()?;
            let k = next.light_leak;
            if k <= 0.0 {
                return None;
            }
            parameters.insert("lux_per_outdoor_lux".into(), k);
            let r = pearson_r(
                &rows
                    .iter()
                    .map(|(eh, p, m)| (*eh, m - p - state.light_leak * eh))
                    .collect::<Vec<_>>(),
            );
            evidence = format!(
                "the residual (measured − model) grows with the outdoor horizontal illuminance \
                 (r = {r:.2}) on every sensor, most in relative terms deep in the room"
            );
        }
        Effect::GroundReflectance => {
            let zero = ModelState {
                ground_reflectance: 0.0,
                ..state.clone()
            };
            let rows: Vec<(f64, f64, f64)> = readings(state, terms, fit)
                .map(|(t, k, m)| {
                    let per_rho = state.glazing_transmittance
                        * t.unseen_ground_lux_per_cd_m2[k]
                        * t.outdoor_horizontal_lux
                        / std::f64::consts::PI;
                    (per_rho, predict(&zero, t)[k], m)
                })
                .collect();
            if rows.iter().all(|r| r.0 <= 0.0) {
                return None;
            }
            next = joint()?;
            let rho = next.ground_reflectance;
            parameters.insert("reflectance".into(), rho);
            let r = pearson_r(
                &rows
                    .iter()
                    .map(|(g, p, m)| (g / m, m / (p + state.ground_reflectance * g) - 1.0))
                    .collect::<Vec<_>>(),
            );
            evidence = format!(
                "the relative residual follows the share of the prediction that comes from \
                 ground the lens does not see (r = {r:.2})"
            );
        }
        // Device-level effects: fitted by the loop, which re-merges or re-projects.
        Effect::OrientationError | Effect::ShutterOverhead => return None,
        // Needs the room's glazing and daylight coefficients: fitted by the loop.
        Effect::GlazingAngular => return None,
        // Sky effects: fitted by the loop, which holds the camera geometry and the daylight
        // coefficients (`effect_vignetting.rs`, `effect_fov.rs`).
        Effect::Vignetting | Effect::SkyOutsideFov => return None,
        Effect::ClockOffset => {
            let (st, ev) = fit_clock_offset(state, terms, fit)?;
            next = st;
            parameters.insert("logger_minus_device_s".into(), next.clock_offset_s);
            evidence = ev;
        }
        Effect::SpectralMismatch => {
            return super::effect_spectral::fit_spectral(state, accepted, terms, fit);
        }
    }
    Some(Candidate {
        effect,
        state: next,
        parameters,
        evidence,
    })
}

/// The shutter overhead's signature in the fit set under `state`: the mean signed relative
/// residual of the readings where the modelled direct sun exceeds 5 % of the measured light
/// (the sunlit readings of `sun_undersampling`'s signature), the mean signed and the mean
/// |relative residual| of the others, and the count of each. An overhead over-estimates
/// what the short exposures measure, the sun first: a positive bias where the sun lights the
/// sensor, over and above the others' (a common factor biases both alike).
pub fn sunlit_bias(
    state: &ModelState,
    terms: &[CaptureTerms],
    fit: &FitSet<Sample>,
) -> (f64, f64, f64, usize, usize) {
    let (mut lit, mut shade) = (Vec::new(), Vec::new());
    for (t, k, m) in readings(state, terms, fit) {
        let p = predict(state, t)[k];
        let direct = state.glazing_transmittance * t.sun_lux_per_dn_lux[k] * t.sun_dn_lux;
        if p > 0.0 && direct > 0.05 * m {
            lit.push(p / m - 1.0);
        } else {
            shade.push(p / m - 1.0);
        }
    }
    let mean = |v: &[f64]| {
        if v.is_empty() {
            f64::NAN
        } else {
            v.iter().sum::<f64>() / v.len() as f64
        }
    };
    let shade_abs: Vec<f64> = shade.iter().map(|r| r.abs()).collect();
    (
        mean(&lit),
        mean(&shade),
        mean(&shade_abs),
        lit.len(),
        shade.len(),
    )
}
