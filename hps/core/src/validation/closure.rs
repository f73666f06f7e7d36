//! The pyranometer closure: does GHI = DNI cos Z + DHI hold in a reference record, and if not,
//! which instrument fault explains the residual?
//!
//! The residual r = GHI − (DNI cos Z + DHI) in W/m² is the error. The loop ([`run_closure`]):
//! split the times into fit and hold-out blocks ([`super::split`]); the base model has no
//! parameter (r itself); rank the effects of [`PyranometerEffect`] by how much of the fit-set
//! residual each explains when fitted jointly with those already chosen; add the best, refit,
//! and repeat while the hold-out mean |r| falls by more than `noise_factor` times its standard
//! error over hold-out blocks. The hold-out set is only scored, never fitted on.
//!
//! Only daytime samples (sun zenith below `max_zenith_deg`) enter the fit and the scores:
//! near the horizon the beam term is tiny and refraction and horizon obstructions dominate.
//! Night samples of the fit set (zenith above [`NIGHT_MIN_ZENITH_DEG`]) give the thermal-offset
//! evidence, GHI − DHI with no sky light at all.

use super::pyranometer_effects::{PyranometerEffect, Variable};
use super::report::{EffectReport, ErrorSummary, Report, ReportError};
use super::split::{compare, split, Figure, HoldoutSet, Score, SplitError, SplitPlan, Timed};
use crate::io::irradiance::{PyranometerTable, StampConvention};
use crate::numerics::linalg::least_squares_dropping_collinear;
use crate::output::plot::{self, BarGroup, Frame, Series};
use crate::output::{write_atomic, WriteError};
use crate::sun::{solar_position, Atmosphere, Site, SunError};
use chrono::{DateTime, SecondsFormat, TimeDelta, Utc};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Beyond nautical twilight (sun 12° below the horizon) the sky adds well under 0.01 W/m²:
/// what a pyranometer reads then is its own offset.
pub const NIGHT_MIN_ZENITH_DEG: f64 = 102.0;

/// Half the step of the central difference for d(cos Z)/dt.
const DERIVATIVE_HALF_STEP_S: i64 = 30;

/// One averaging interval with all three channels, and where the sun was.
#[derive(Clone, Debug, PartialEq)]
pub struct ClosureSample {
    /// Centre of the averaging interval.
    pub time_utc: DateTime<Utc>,
    pub ghi_wm2: f64,
    pub dhi_wm2: f64,
    pub dni_wm2: f64,
    /// Apparent (refracted) zenith at `time_utc`.
    pub zenith_deg: f64,
    /// From north towards east.
    pub azimuth_deg: f64,
    /// Solar hour angle, negative in the morning.
    pub hour_angle_deg: f64,
    /// d(cos Z)/dt at `time_utc`, per second.
    pub dcos_zenith_per_s: f64,
}

impl ClosureSample {
    pub fn cos_zenith(&self) -> f64 {
        self.zenith_deg.to_radians().cos()
    }

    /// DNI cos Z, zero with the sun below the horizon.
    pub fn beam_wm2(&self) -> f64 {
        self.dni_wm2 * self.cos_zenith().max(0.0)
    }

    /// The closure residual GHI − (DNI cos Z + DHI).
    pub fn residual_wm2(&self) -> f64 {
        self.ghi_wm2 - self.beam_wm2() - self.dhi_wm2
    }
}

impl Timed for ClosureSample {
    fn time_utc(&self) -> DateTime<Utc> {
        self.time_utc
    }
}

/// How to run the closure.
#[derive(Clone, Debug, PartialEq)]
pub struct ClosureOptions {
    pub site: Site,
    /// Which instant of its interval a row's stamp names.
    pub stamp: StampConvention,
    /// Averaging interval; `None`: the median step between rows.
    pub interval: Option<TimeDelta>,
    /// Daytime: samples with the sun's zenith below this enter the fit and the scores.
    pub max_zenith_deg: f64,
    /// Night samples (zenith above [`NIGHT_MIN_ZENITH_DEG`]) enter the fit and the scores
    /// too: there GHI − DHI is the thermal offset alone, which pins it apart from the
    /// sun-driven effects. Twilight (between the two) never does.
    pub include_night: bool,
    /// Length of the alternating fit / hold-out blocks.
    pub block: TimeDelta,
    /// An effect is kept when the hold-out gain exceeds this many standard errors.
    pub noise_factor: f64,
    /// Candidate effects.
    pub effects: Vec<PyranometerEffect>,
}

impl ClosureOptions {
    /// Whether a sample enters the fit and the scores.
    pub fn uses(&self, s: &ClosureSample) -> bool {
        s.zenith_deg < self.max_zenith_deg
            || (self.include_night && s.zenith_deg > NIGHT_MIN_ZENITH_DEG)
    }

    /// Defaults: interval inferred, zenith below 85° and night, 30-minute blocks, a 1-sigma
    /// gain, all effects.
    pub fn new(site: Site, stamp: StampConvention) -> Self {
        Self {
            site,
            stamp,
            interval: None,
            max_zenith_deg: 85.0,
            include_night: true,
            block: TimeDelta::minutes(30),
            noise_factor: 1.0,
            effects: PyranometerEffect::ALL.to_vec(),
        }
    }
}

/// Why the closure cannot run.
#[derive(Debug, thiserror::Error)]
pub enum ClosureError {
    #[error("closure options: {0}")]
    Options(String),
    #[error("pyranometer table: {0}")]
    Table(String),
    #[error("pyranometer table row {row} (time {time}): {source}")]
    Sun {
        row: usize,
        time: DateTime<Utc>,
        #[source]
        source: SunError,
    },
    #[error(transparent)]
    Split(#[from] SplitError),
    #[error(transparent)]
    Report(#[from] ReportError),
    #[error(transparent)]
    Write(#[from] WriteError),
    #[error(transparent)]
    Plot(#[from] plot::PlotError),
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
}

/// Samples ready for the closure, and what was left out.
#[derive(Clone, Debug, PartialEq)]
pub struct Prepared {
    pub samples: Vec<ClosureSample>,
    pub rows: usize,
    /// Rows lacking GHI, DHI or DNI.
    pub rows_with_gaps: usize,
    pub interval: TimeDelta,
    pub interval_inferred: bool,
}

/// The median positive step between consecutive rows.
fn median_step(times: &[DateTime<Utc>]) -> Option<TimeDelta> {
    let mut steps: Vec<TimeDelta> = times
        .windows(2)
        .map(|w| w[1] - w[0])
        .filter(|d| *d > TimeDelta::zero())
        .collect();
    steps.sort();
    steps.get(steps.len() / 2).copied()
}

fn check_options(o: &ClosureOptions) -> Result<(), ClosureError> {
    let bad = |m: String| Err(ClosureError::Options(m));
    if !(o.max_zenith_deg > 0.0 && o.max_zenith_deg <= 90.0) {
        return bad(format!(
            "max_zenith_deg {} is outside (0, 90]",
            o.max_zenith_deg
        ));
    }
    if !(o.noise_factor.is_finite() && o.noise_factor >= 0.0) {
        return bad(format!("noise_factor {} is not ≥ 0", o.noise_factor));
    }
    if o.block <= TimeDelta::zero() {
        return bad(format!("block {} is not positive", o.block));
    }
    if let Some(i) = o.interval {
        if !(TimeDelta::milliseconds(1)..=TimeDelta::days(1)).contains(&i) {
            return bad(format!("interval {i} is outside 1 ms ..= 1 day"));
        }
    }
    Ok(())
}

/// Turns `pyranometer.csv` rows into closure samples: the interval centre under the stamp
/// convention, the sun there (SPA, standard atmosphere at the site's elevation). Rows without
/// all three channels are counted and left out: the closure needs a measured DNI.
pub fn prepare(
    table: &PyranometerTable,
    options: &ClosureOptions,
) -> Result<Prepared, ClosureError> {
    check_options(options)?;
    let times: Vec<DateTime<Utc>> = table.rows.iter().map(|r| r.time.to_utc()).collect();
    let (interval, interval_inferred) = match options.interval {
        Some(i) => (i, false),
        None => (
            median_step(&times).ok_or_else(|| {
                ClosureError::Table(
                    "cannot infer the averaging interval from fewer than two distinct times; give it"
                        .into(),
                )
            })?,
            true,
        ),
    };
    if !(TimeDelta::milliseconds(1)..=TimeDelta::days(1)).contains(&interval) {
        return Err(ClosureError::Table(format!(
            "inferred interval {interval} is outside 1 ms ..= 1 day; give it"
        )));
    }
    let air = Atmosphere::standard_at(options.site.elevation_m);
    let lat = options.site.latitude_deg.to_radians();
    let half = TimeDelta::seconds(DERIVATIVE_HALF_STEP_S);
    let mut samples = Vec::new();
    let mut rows_with_gaps = 0;
    for (row, (r, &stamp)) in table.rows.iter().zip(&times).enumerate() {
        let (Some(ghi), Some(dhi), Some(dni)) = (r.ghi_wm2, r.dhi_wm2, r.dni_wm2) else {
            rows_with_gaps += 1;
            continue;
        };
        let sun_error = |source| ClosureError::Sun {
            row: row + 1,
            time: stamp,
            source,
        };
        let out_of_range =
            || ClosureError::Table(format!("row {}: time {stamp} out of range", row + 1));
        let (start, end) = options
            .stamp
            .interval(stamp, interval)
            .ok_or_else(out_of_range)?;
        let centre = start + (end - start) / 2;
        let at = |t: DateTime<Utc>| solar_position(t, &options.site, Some(&air)).map_err(sun_error);
        let p = at(centre)?;
        let before = at(centre.checked_sub_signed(half).ok_or_else(out_of_range)?)?;
        let after = at(centre.checked_add_signed(half).ok_or_else(out_of_range)?)?;
        let dcos = (after.zenith_deg.to_radians().cos() - before.zenith_deg.to_radians().cos())
            / (2 * DERIVATIVE_HALF_STEP_S) as f64;
        let (sin_z, cos_z) = p.zenith_deg.to_radians().sin_cos();
        let (sin_a, cos_a) = p.azimuth_deg.to_radians().sin_cos();
        let hour_angle_deg = (-sin_z * sin_a)
            .atan2(lat.cos() * cos_z - lat.sin() * sin_z * cos_a)
            .to_degrees();
        samples.push(ClosureSample {
            time_utc: centre,
            ghi_wm2: ghi,
            dhi_wm2: dhi,
            dni_wm2: dni,
            zenith_deg: p.zenith_deg,
            azimuth_deg: p.azimuth_deg,
            hour_angle_deg,
            dcos_zenith_per_s: dcos,
        });
    }
    if samples.is_empty() {
        return Err(ClosureError::Table(format!(
            "none of the {} rows has GHI, DHI and DNI all measured; the closure needs all three",
            table.rows.len()
        )));
    }
    samples.sort_by_key(|s| s.time_utc);
    Ok(Prepared {
        rows: table.rows.len(),
        rows_with_gaps,
        samples,
        interval,
        interval_inferred,
    })
}

/// A set of effects with jointly fitted coefficients; predicts the residual.
#[derive(Clone, Debug, PartialEq)]
pub struct ClosureModel {
    pub effects: Vec<PyranometerEffect>,
    /// Concatenated coefficients, [`PyranometerEffect::n_columns`] per effect.
    pub coefficients: Vec<f64>,
    /// Per coefficient: not fitted, because the effects before it already span its column.
    pub dropped: Vec<bool>,
}

impl ClosureModel {
    /// The base closure: no effect, the residual is r.
    pub fn base() -> Self {
        Self {
            effects: Vec::new(),
            coefficients: Vec::new(),
            dropped: Vec::new(),
        }
    }

    fn columns(effects: &[PyranometerEffect], s: &ClosureSample) -> Vec<f64> {
        effects
            .iter()
            .flat_map(|e| e.columns(s).into_iter().take(e.n_columns()))
            .collect()
    }

    /// The residual the effects predict for `s`.
    pub fn predicted_wm2(&self, s: &ClosureSample) -> f64 {
        Self::columns(&self.effects, s)
            .iter()
            .zip(&self.coefficients)
            .map(|(c, k)| c * k)
            .sum()
    }

    /// What remains of the residual once the effects are accounted for.
    pub fn corrected_wm2(&self, s: &ClosureSample) -> f64 {
        s.residual_wm2() - self.predicted_wm2(s)
    }

    /// One effect's share of the prediction.
    fn contribution_wm2(&self, effect: PyranometerEffect, s: &ClosureSample) -> f64 {
        let mut k = 0;
        for &e in &self.effects {
            let n = e.n_columns();
            if e == effect {
                return e
                    .columns(s)
                    .iter()
                    .zip(&self.coefficients[k..k + n])
                    .map(|(c, x)| c * x)
                    .sum();
            }
            k += n;
        }
        0.0
    }

    /// Each effect's physical parameters.
    pub fn parameters(&self) -> Vec<(PyranometerEffect, BTreeMap<String, f64>)> {
        let mut k = 0;
        self.effects
            .iter()
            .map(|&e| {
                let n = e.n_columns();
                let p = e.parameters(&self.coefficients[k..k + n]);
                k += n;
                (e, p)
            })
            .collect()
    }

    /// Fits `effects` jointly by least squares on `samples` (daytime fit-set samples only),
    /// in order: a signature column that the effects before it already span is not fitted
    /// (coefficient 0, flagged in `dropped`). `None` for non-finite samples.
    pub fn fit(effects: &[PyranometerEffect], samples: &[&ClosureSample]) -> Option<Self> {
        let rows: Vec<Vec<f64>> = samples.iter().map(|s| Self::columns(effects, s)).collect();
        let y: Vec<f64> = samples.iter().map(|s| s.residual_wm2()).collect();
        let (coefficients, dropped) = least_squares_dropping_collinear(&rows, &y)?;
        Some(Self {
            effects: effects.to_vec(),
            coefficients,
            dropped,
        })
    }

    /// Coefficients actually fitted.
    pub fn active_columns(&self) -> usize {
        self.dropped.iter().filter(|d| !**d).count()
    }

    /// Whether every column of `effect` was dropped (nothing of it is identifiable).
    fn all_dropped(&self, effect: PyranometerEffect) -> bool {
        let mut k = 0;
        for &e in &self.effects {
            let n = e.n_columns();
            if e == effect {
                return self.dropped[k..k + n].iter().all(|d| *d);
            }
            k += n;
        }
        false
    }
}

/// A model and its scores on the fit and hold-out sets.
#[derive(Clone, Debug, PartialEq)]
pub struct Stage {
    pub model: ClosureModel,
    pub holdout: Score,
    pub fit: Score,
}

/// Everything the closure found, for the report and the plots.
#[derive(Clone, Debug)]
pub struct ClosureResult {
    pub report: Report,
    /// The base closure, without any effect.
    pub base: Stage,
    /// The final model.
    pub last: Stage,
    /// Per final effect, the final model without it (refitted on the fit set).
    pub leave_one_out: Vec<(PyranometerEffect, Stage)>,
    /// The fit-set samples used (day and night; the only samples plots may show).
    pub fit_day: Vec<ClosureSample>,
    pub interval: TimeDelta,
}

/// The fit set's figures (whole set only: block-wise noise is a hold-out matter).
fn fit_score(model: &ClosureModel, fit_day: &[&ClosureSample]) -> Score {
    let errors: Vec<f64> = fit_day.iter().map(|s| model.corrected_wm2(s)).collect();
    let n = errors.len();
    if n == 0 {
        return Score::default();
    }
    let nf = n as f64;
    Score {
        n,
        mean: errors.iter().sum::<f64>() / nf,
        mean_abs: errors.iter().map(|e| e.abs()).sum::<f64>() / nf,
        rmse: (errors.iter().map(|e| e * e).sum::<f64>() / nf).sqrt(),
        max_abs: errors.iter().fold(0.0, |m, e| m.max(e.abs())),
        blocks: BTreeMap::new(),
    }
}

fn holdout_score(
    model: &ClosureModel,
    holdout: &HoldoutSet<ClosureSample>,
    options: &ClosureOptions,
) -> Score {
    holdout.evaluate(|s| options.uses(s).then(|| model.corrected_wm2(s)))
}

fn summary(value: f64) -> ErrorSummary {
    ErrorSummary {
        all: value,
        per_sensor: BTreeMap::from([("ghi_closure".to_string(), value)]),
    }
}

fn rfc3339(t: &DateTime<Utc>) -> String {
    t.to_rfc3339_opts(SecondsFormat::AutoSi, true)
}

fn mean(values: impl Iterator<Item = f64>) -> Option<f64> {
    let (n, s) = values.fold((0usize, 0.0), |(n, s), v| (n + 1, s + v));
    (n > 0).then(|| s / n as f64)
}

/// Pearson correlation of two equally long series; 0 where it is undefined (a constant side,
/// fewer than 3 points): such a series explains nothing.
fn pearson_or_zero(a: &[f64], b: &[f64]) -> f64 {
    let pairs: Vec<(f64, f64)> = a.iter().copied().zip(b.iter().copied()).collect();
    crate::numerics::pearson(&pairs).map_or(0.0, |p| p.r)
}

/// The evidence sentence for `effect`, from the fit set only.
fn evidence(
    effect: PyranometerEffect,
    current: &ClosureModel,
    next: &ClosureModel,
    fit_day: &[&ClosureSample],
    night: Option<(f64, usize)>,
    before: &Score,
    after: &Score,
) -> String {
    let residual: Vec<f64> = fit_day.iter().map(|s| current.corrected_wm2(s)).collect();
    let contribution: Vec<f64> = fit_day
        .iter()
        .map(|s| next.contribution_wm2(effect, s))
        .collect();
    let rss = |s: &Score| s.rmse * s.rmse * s.n as f64;
    let explained = if rss(before) > 0.0 {
        100.0 * (1.0 - rss(after) / rss(before))
    } else {
        0.0
    };
    let mut text = format!(
        "{}: it explains {explained:.0}% of the remaining fit-set residual sum of squares \
         (mean |r| {:.2} → {:.2} W/m², correlation {:.2} with the residual)",
        effect.signature(),
        before.mean_abs,
        after.mean_abs,
        pearson_or_zero(&residual, &contribution)
    );
    let halves = || {
        let am = mean(
            fit_day
                .iter()
                .zip(&residual)
                .filter(|(s, _)| s.zenith_deg < 90.0 && s.hour_angle_deg < 0.0)
                .map(|(_, r)| *r),
        );
        let pm = mean(
            fit_day
                .iter()
                .zip(&residual)
                .filter(|(s, _)| s.zenith_deg < 90.0 && s.hour_angle_deg >= 0.0)
                .map(|(_, r)| *r),
        );
        match (am, pm) {
            (Some(am), Some(pm)) => format!(
                "; by day the residual averages {am:+.2} W/m² before solar noon and {pm:+.2} W/m² \
                 after"
            ),
            _ => String::new(),
        }
    };
    let per_beam = || {
        let ratio = |hi: bool| {
            let (r, b) = fit_day
                .iter()
                .zip(&residual)
                .filter(|(s, _)| s.zenith_deg < 90.0 && (s.zenith_deg >= 70.0) == hi)
                .fold((0.0, 0.0), |(r, b), (s, x)| (r + x, b + s.beam_wm2()));
            (b > 0.0).then(|| r / b)
        };
        match (ratio(false), ratio(true)) {
            (Some(lo), Some(hi)) => format!(
                "; residual per unit beam {:+.2}% with the sun above 20° and {:+.2}% below",
                100.0 * lo,
                100.0 * hi
            ),
            _ => String::new(),
        }
    };
    let specific = match effect {
        PyranometerEffect::ThermalOffset => match night {
            Some((m, n)) => format!(
                "; at night (zenith > {NIGHT_MIN_ZENITH_DEG}°) the fit set's GHI − DHI averages \
                 {m:+.2} W/m² over {n} samples"
            ),
            None => String::new(),
        },
        PyranometerEffect::TimestampShift
        | PyranometerEffect::LevelTilt
        | PyranometerEffect::TrackerDrift => halves(),
        PyranometerEffect::CosineResponse | PyranometerEffect::DniScale => per_beam(),
        PyranometerEffect::DhiScale => String::new(),
    };
    text.push_str(&specific);
    text.push('.');
    text
}

/// The sun's hour angle advances 2π per mean solar day (86 400 s): 15° per hour.
const HOUR_ANGLE_RATE_RAD_PER_S: f64 = std::f64::consts::TAU / 86_400.0;

/// A clock error δ moves the sun along its diurnal circle, which to first order looks like a
/// tilt of the GHI sensor about the polar axis: an east–west level tilt q = ω δ cos φ. The
/// closure cannot tell them apart; say so with the numbers of whichever was found.
fn degeneracy_note(effects: &[EffectReport], latitude_deg: f64) -> Option<String> {
    let per_s = HOUR_ANGLE_RATE_RAD_PER_S * latitude_deg.to_radians().cos();
    let find = |name: &str| effects.iter().find(|e| e.name == name);
    if let Some(t) = find(PyranometerEffect::LevelTilt.name()) {
        let (beta, gamma) = (
            t.parameters.get("tilt_deg")?.to_radians(),
            t.parameters.get("tilt_towards_azimuth_deg")?.to_radians(),
        );
        let (north, east) = (beta.sin() * gamma.cos(), beta.sin() * gamma.sin());
        return Some(format!(
            "level_tilt vs timestamp_shift: the closure cannot tell an east–west tilt from a \
             clock error (δ = q / (ω cos φ)); this tilt's east–west part ({:+.3}°, east \
             positive) is the signature of a {:+.0} s clock error, its north–south part \
             ({:+.3}°, north positive) has no clock-error explanation",
            east.asin().to_degrees(),
            east / per_s,
            north.asin().to_degrees()
        ));
    }
    let shift = find(PyranometerEffect::TimestampShift.name())?;
    let d = *shift.parameters.get("shift_s")?;
    Some(format!(
        "timestamp_shift vs level_tilt: a {d:+.1} s clock error has the closure signature of an \
         east–west tilt of the GHI sensor by {:+.3}° (east positive); the closure cannot tell \
         them apart",
        (d * per_s).clamp(-1.0, 1.0).asin().to_degrees()
    ))
}

/// Runs the loop on prepared samples.
pub fn run_closure(
    prepared: &Prepared,
    options: &ClosureOptions,
) -> Result<ClosureResult, ClosureError> {
    check_options(options)?;
    let first = prepared
        .samples
        .first()
        .ok_or_else(|| ClosureError::Table("no samples".into()))?;
    let origin = first
        .time_utc
        .date_naive()
        .and_hms_opt(0, 0, 0)
        .map(|d| d.and_utc())
        .ok_or_else(|| ClosureError::Table("first time has no midnight".into()))?;
    let plan = SplitPlan::alternate(origin, options.block)?;
    let (fit, holdout) = split(prepared.samples.clone(), &plan)?;
    let max_z = options.max_zenith_deg;
    let fit_day: Vec<&ClosureSample> = fit.samples().iter().filter(|s| options.uses(s)).collect();
    let night: Vec<f64> = fit
        .samples()
        .iter()
        .filter(|s| s.zenith_deg > NIGHT_MIN_ZENITH_DEG)
        .map(|s| s.ghi_wm2 - s.dhi_wm2)
        .collect();
    let night_stat = mean(night.iter().copied()).map(|m| (m, night.len()));
    let base = ClosureModel::base();
    let base_holdout = holdout_score(&base, &holdout, options);
    if fit_day.len() < 10 || base_holdout.n < 10 {
        return Err(ClosureError::Table(format!(
            "too few samples with the sun up (zenith < {max_z}°) or at night: {} in the fit set \
             and {} in the hold-out set, at least 10 each",
            fit_day.len(),
            base_holdout.n
        )));
    }
    let base_stage = Stage {
        fit: fit_score(&base, &fit_day),
        holdout: base_holdout.clone(),
        model: base,
    };
    let stage_of = |model: ClosureModel| Stage {
        fit: fit_score(&model, &fit_day),
        holdout: holdout_score(&model, &holdout, options),
        model,
    };
    // Bayesian information criterion on the fit set: the residual sum of squares, with ln(n)
    // per fitted coefficient, so an effect with more parameters must explain more to rank
    // first, and of two sets that explain the same the simpler wins.
    let bic = |stage: &Stage| {
        let n = stage.fit.n.max(1) as f64;
        n * (stage.fit.rmse * stage.fit.rmse).max(1e-300).ln()
            + stage.model.active_columns() as f64 * n.ln()
    };
    let mut current = base_stage.clone();
    let mut rejected = Vec::new();
    let mut notes = Vec::new();
    let mut candidates = options.effects.clone();
    candidates.sort();
    candidates.dedup();
    // Effect sets the loop has stood on: the hold-out rule adds, the fit-set BIC may swap or
    // drop, and the two could otherwise take turns for ever.
    let mut visited: Vec<Vec<PyranometerEffect>> = vec![Vec::new()];
    loop {
        // Rank the effects not yet in the model, on the fit set alone.
        rejected.clear();
        let mut ranked: Vec<(PyranometerEffect, Stage)> = Vec::new();
        for &e in candidates
            .iter()
            .filter(|e| !current.model.effects.contains(e))
        {
            let mut with = current.model.effects.clone();
            with.push(e);
            match ClosureModel::fit(&with, &fit_day) {
                Some(m) if !m.all_dropped(e) => ranked.push((e, stage_of(m))),
                _ => rejected.push(format!(
                    "{}: its signature is zero, or spanned by the effects already added, on the \
                     fit set",
                    e.name()
                )),
            }
        }
        ranked.sort_by(|a, b| bic(&a.1).total_cmp(&bic(&b.1)));
        let explained = |s: &Score| {
            let b = current.fit.rmse.powi(2);
            if b > 0.0 {
                100.0 * (1.0 - s.rmse.powi(2) / b)
            } else {
                0.0
            }
        };
        let Some((best, next)) = ranked.first().cloned() else {
            break;
        };
        let c = compare(&current.holdout, &next.holdout, Figure::MeanAbs);
        if !(c.gain > 0.0 && c.gain > options.noise_factor * c.noise) {
            rejected.push(format!(
                "{}: best remaining on the fit set ({:.1}% of its residual sum of squares), but \
                 the hold-out mean |r| changed by {:+.3} ± {:.3} W/m² (gain must exceed {} \
                 standard errors); loop stopped",
                best.name(),
                explained(&next.fit),
                c.gain,
                c.noise,
                options.noise_factor
            ));
            for (e, st) in ranked.iter().skip(1) {
                rejected.push(format!(
                    "{}: not tried on the hold-out set (ranked lower, {:.1}% of the fit-set \
                     residual sum of squares)",
                    e.name(),
                    explained(&st.fit)
                ));
            }
            break;
        }
        notes.push(format!(
            "{} added: hold-out mean |r| fell {:.3} ± {:.3} W/m² (standard error over {} \
             blocks); fit-set residual sum of squares explained {:.1}%",
            best.name(),
            c.gain,
            c.noise,
            c.blocks,
            explained(&next.fit)
        ));
        current = next;
        // Stepwise refinement on the fit set: an effect chosen early may have stood in for
        // several faults that later effects explain better. Swap an effect for one not in the
        // model, or drop it, while that lowers the fit-set BIC (strictly, so this ends).
        for _ in 0..2 * PyranometerEffect::ALL.len() {
            let mut best_change: Option<(String, Stage)> = None;
            for (i, &old) in current.model.effects.iter().enumerate() {
                let outside = candidates
                    .iter()
                    .filter(|e| !current.model.effects.contains(e))
                    .map(|&e| Some(e));
                for new in outside.chain([None]) {
                    let mut effects = current.model.effects.clone();
                    match new {
                        Some(n) => effects[i] = n,
                        None => {
                            effects.remove(i);
                        }
                    }
                    let Some(m) = ClosureModel::fit(&effects, &fit_day) else {
                        continue;
                    };
                    if new.is_some_and(|n| m.all_dropped(n)) {
                        continue;
                    }
                    let st = stage_of(m);
                    let better = match &best_change {
                        Some((_, b)) => bic(&st) < bic(b),
                        None => bic(&st) < bic(&current) - 1e-9,
                    };
                    if better {
                        let what = match new {
                            Some(n) => format!("{} replaced by {}", old.name(), n.name()),
                            None => format!("{} removed", old.name()),
                        };
                        best_change = Some((what, st));
                    }
                }
            }
            let Some((what, st)) = best_change else {
                break;
            };
            notes.push(format!(
                "{what}: fit-set BIC {:.1} → {:.1} (the later effects explain it better)",
                bic(&current),
                bic(&st)
            ));
            current = st;
        }
        let mut set = current.model.effects.clone();
        set.sort();
        if visited.contains(&set) {
            notes.push(format!(
                "loop stopped: the effect set {:?} was reached before",
                set.iter().map(|e| e.name()).collect::<Vec<_>>()
            ));
            break;
        }
        visited.push(set);
    }
    // Final check with the loop's own rule: every effect must still earn its place, its
    // hold-out gain over the model without it above the noise. Drop the worst until all do.
    loop {
        let mut worst: Option<(f64, usize, Stage)> = None;
        for i in 0..current.model.effects.len() {
            let mut others = current.model.effects.clone();
            others.remove(i);
            let Some(m) = ClosureModel::fit(&others, &fit_day) else {
                continue;
            };
            let without = stage_of(m);
            let c = compare(&without.holdout, &current.holdout, Figure::MeanAbs);
            let margin = c.gain - options.noise_factor * c.noise;
            if (c.gain <= 0.0 || margin <= 0.0) && worst.as_ref().is_none_or(|w| margin < w.0) {
                worst = Some((margin, i, without));
            }
        }
        let Some((_, i, without)) = worst else {
            break;
        };
        notes.push(format!(
            "{} removed at the end: without it the hold-out mean |r| is {:.3} W/m² against \
             {:.3}, no gain above the noise",
            current.model.effects[i].name(),
            without.holdout.mean_abs,
            current.holdout.mean_abs
        ));
        current = without;
    }
    // What each final effect does: the model without it, refitted on the fit set.
    let mut leave_one_out = Vec::new();
    let mut effects: Vec<EffectReport> = Vec::new();
    let params = current.model.parameters();
    for (i, &e) in current.model.effects.iter().enumerate() {
        let mut others = current.model.effects.clone();
        others.remove(i);
        let without = ClosureModel::fit(&others, &fit_day)
            .map(stage_of)
            .unwrap_or_else(|| base_stage.clone());
        let c = compare(&without.holdout, &current.holdout, Figure::MeanAbs);
        effects.push(EffectReport {
            name: e.name().to_string(),
            parameters: params
                .iter()
                .find(|(pe, _)| *pe == e)
                .map(|(_, p)| p.clone())
                .unwrap_or_default(),
            evidence: evidence(
                e,
                &without.model,
                &current.model,
                &fit_day,
                night_stat,
                &without.fit,
                &current.fit,
            ),
            gain: c.gain,
            fit_error_before: Some(without.fit.mean_abs),
            fit_error_after: Some(current.fit.mean_abs),
        });
        if current.model.dropped.iter().any(|d| *d) {
            notes.push(format!(
                "{}: part of its signature is spanned by the other effects and was not fitted",
                e.name()
            ));
        }
        leave_one_out.push((e, without));
    }
    let last = current.clone();
    if effects.is_empty() {
        notes.push("no effect improved the hold-out error by more than its noise".into());
    }
    notes.extend(degeneracy_note(&effects, options.site.latitude_deg));
    if let Some((m, n)) = night_stat {
        notes.push(format!(
            "night (zenith > {NIGHT_MIN_ZENITH_DEG}°, fit set): GHI − DHI averages {m:+.2} W/m² \
             over {n} samples"
        ));
    }
    notes.push(format!(
        "{} rows, {} with a gap in GHI, DHI or DNI left out; interval {} s ({}); stamps at the \
         interval {}; sun by NREL SPA at each interval's centre, standard atmosphere at {} m",
        prepared.rows,
        prepared.rows_with_gaps,
        prepared.interval.num_milliseconds() as f64 / 1000.0,
        if prepared.interval_inferred {
            "median step between rows"
        } else {
            "given"
        },
        match options.stamp {
            StampConvention::IntervalStart => "start",
            StampConvention::IntervalCentre => "centre",
            StampConvention::IntervalEnd => "end",
        },
        options.site.elevation_m
    ));
    notes.push(format!(
        "split: alternate {}-minute blocks from {} (odd blocks held out); samples used \
         (zenith < {max_z}°{}): {} fit, {} hold-out",
        options.block.num_minutes(),
        rfc3339(&origin),
        if options.include_night {
            format!(", or night, zenith > {NIGHT_MIN_ZENITH_DEG}°")
        } else {
            String::new()
        },
        fit_day.len(),
        base_holdout.n
    ));
    notes.push(format!(
        "fit set mean |r| {:.3} → {:.3} W/m², RMSE {:.3} → {:.3} W/m²",
        base_stage.fit.mean_abs, last.fit.mean_abs, base_stage.fit.rmse, last.fit.rmse
    ));
    let (b, a) = (&base_stage.holdout, &last.holdout);
    let secondary = BTreeMap::from([
        ("rmse_wm2_before".to_string(), summary(b.rmse)),
        ("rmse_wm2_after".to_string(), summary(a.rmse)),
        ("max_abs_wm2_before".to_string(), summary(b.max_abs)),
        ("max_abs_wm2_after".to_string(), summary(a.max_abs)),
        ("bias_wm2_before".to_string(), summary(b.mean)),
        ("bias_wm2_after".to_string(), summary(a.mean)),
    ]);
    let report = Report {
        metric: "mean_abs_wm2".into(),
        fit_times: fit.times().iter().map(rfc3339).collect(),
        holdout_times: holdout.times().iter().map(rfc3339).collect(),
        before: summary(b.mean_abs),
        after: summary(a.mean_abs),
        baseline_perez: None,
        effects,
        secondary,
        rejected,
        notes,
        figures: Vec::new(),
    };
    Ok(ClosureResult {
        report,
        fit_day: fit_day.into_iter().cloned().collect(),
        base: base_stage,
        last,
        leave_one_out,
        interval: prepared.interval,
    })
}

/// Writes `report.json`, `report.md` and the PNG plots into `dir` (created if missing);
/// returns the report as written.
pub fn write_outputs(result: &ClosureResult, dir: &Path) -> Result<Report, ClosureError> {
    std::fs::create_dir_all(dir).map_err(|source| ClosureError::Io {
        path: dir.into(),
        source,
    })?;
    let mut report = result.report.clone();
    let mut figures: Vec<(String, String)> = Vec::new();
    let (base, last) = (&result.base, &result.last);
    let n_after = last.model.effects.len();
    let after_label = format!(
        "after ({n_after} effect{})",
        if n_after == 1 { "" } else { "s" }
    );

    // Residual against time of day, fit set, with a break at every gap.
    let day0 = result
        .fit_day
        .first()
        .and_then(|s| s.time_utc.date_naive().and_hms_opt(0, 0, 0))
        .map(|d| d.and_utc());
    if let Some(day0) = day0 {
        let gap = result.interval * 3 / 2;
        let series = |model: &ClosureModel, label: &str| {
            let mut points = Vec::new();
            let mut prev: Option<DateTime<Utc>> = None;
            for s in &result.fit_day {
                if prev.is_some_and(|p| s.time_utc - p > gap) {
                    points.push((f64::NAN, f64::NAN));
                }
                prev = Some(s.time_utc);
                let h = (s.time_utc - day0).num_milliseconds() as f64 / 3.6e6;
                points.push((h, model.corrected_wm2(s)));
            }
            Series {
                label: label.into(),
                points,
            }
        };
        let name = "residual_vs_time.png";
        plot::lines_png(
            &dir.join(name),
            &Frame::new(
                "Closure residual GHI − (DNI cos Z + DHI), fit set",
                "hours UTC",
                "residual (W/m²)",
            ),
            &[
                series(&base.model, "before"),
                series(&last.model, &after_label),
            ],
        )?;
        figures.push((name.into(), "the residual against time, fit set".into()));
    }

    // The residual against the variable that revealed each effect, before and after it.
    let scatter = |v: Variable,
                   before: &ClosureModel,
                   after: &ClosureModel,
                   what: &str,
                   la: &str,
                   lb: &str| {
        let pts = |m: &ClosureModel| {
            result
                .fit_day
                .iter()
                .map(|s| (v.value(s), m.corrected_wm2(s)))
                .collect()
        };
        let name = format!("residual_vs_{}_{what}.png", v.stem());
        let frame = Frame::new(
            &format!(
                "Closure residual against {}, fit set",
                v.stem().replace('_', " ")
            ),
            v.label(),
            "residual (W/m²)",
        );
        plot::scatter_png(
            &dir.join(&name),
            &frame,
            &[
                Series {
                    label: la.into(),
                    points: pts(before),
                },
                Series {
                    label: lb.into(),
                    points: pts(after),
                },
            ],
        )
        .map(|_| name)
    };
    for (e, without) in &result.leave_one_out {
        let name = scatter(
            e.revealing_variable(),
            &without.model,
            &last.model,
            e.name(),
            &format!("without {}", e.name()),
            &after_label,
        )?;
        figures.push((name, format!("the residual that reveals {}", e.name())));
    }
    let name = scatter(
        Variable::ZenithDeg,
        &base.model,
        &last.model,
        "all",
        "before",
        &after_label,
    )?;
    figures.push((name, "the residual against zenith, before and after".into()));

    // Hold-out figures before and after.
    let name = "holdout_errors.png";
    let group = |label: &str, f: fn(&Score) -> f64| BarGroup {
        label: label.into(),
        values: vec![Some(f(&base.holdout)), Some(f(&last.holdout))],
    };
    plot::grouped_bars_png(
        &dir.join(name),
        &Frame::new("Hold-out closure error", "", "W/m²"),
        &["before".to_string(), after_label.clone()],
        &[
            group("mean |r|", |s| s.mean_abs),
            group("RMSE", |s| s.rmse),
            group("max |r|", |s| s.max_abs),
        ],
    )?;
    figures.push((name.into(), "hold-out errors before and after".into()));

    report.figures = figures.iter().map(|(n, _)| n.clone()).collect();
    report.write_json(&dir.join("report.json"))?;
    write_atomic(
        &dir.join("report.md"),
        markdown(&report, result, &figures).as_bytes(),
    )?;
    Ok(report)
}

fn markdown(report: &Report, result: &ClosureResult, figures: &[(String, String)]) -> String {
    let (b, a) = (&result.base.holdout, &result.last.holdout);
    let mut md = String::new();
    let _ = writeln!(md, "# Pyranometer closure\n");
    let _ = writeln!(
        md,
        "The error is the closure residual r = GHI − (DNI cos Z + DHI) in W/m², on daytime \
         hold-out samples only ({} samples). Effects are fitted on the fit set only.\n",
        b.n
    );
    let _ = writeln!(
        md,
        "| hold-out | mean \\|r\\| | RMSE | max \\|r\\| | bias |"
    );
    let _ = writeln!(md, "|---|---|---|---|---|");
    for (label, s) in [("before", b), ("after", a)] {
        let _ = writeln!(
            md,
            "| {label} | {:.3} | {:.3} | {:.3} | {:+.3} |",
            s.mean_abs, s.rmse, s.max_abs, s.mean
        );
    }
    let _ = writeln!(md, "\n## Effects added\n");
    if report.effects.is_empty() {
        let _ = writeln!(md, "None.");
    }
    for e in &report.effects {
        let params: Vec<String> = e
            .parameters
            .iter()
            .map(|(k, v)| format!("`{k}` = {v:.5}"))
            .collect();
        let _ = writeln!(
            md,
            "- **{}** ({}); hold-out gain {:.3} W/m². {}",
            e.name,
            params.join(", "),
            e.gain,
            e.evidence
        );
    }
    if !report.rejected.is_empty() {
        let _ = writeln!(md, "\n## Not added\n");
        for r in &report.rejected {
            let _ = writeln!(md, "- {r}");
        }
    }
    let _ = writeln!(md, "\n## Notes\n");
    for n in &report.notes {
        let _ = writeln!(md, "- {n}");
    }
    let _ = writeln!(md, "\n## Plots\n");
    for (name, caption) in figures {
        let _ = writeln!(md, "![{caption}]({name})\n");
    }
    md
}
