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

mod evidence;
mod model;
pub mod pyranometer_effects;
mod report_files;
mod sample;

pub use model::ClosureModel;
pub use report_files::write_outputs;
pub use sample::ClosureSample;

use super::report::{EffectReport, ErrorSummary, Report, ReportError};
use super::split::{compare, split, Figure, FitSet, HoldoutSet, Score, SplitError, SplitPlan};
use crate::io::irradiance::{PyranometerTable, StampConvention};
use crate::output::plot;
use crate::output::WriteError;
use crate::sun::{solar_position, Atmosphere, Site, SunError};
use chrono::{DateTime, SecondsFormat, TimeDelta, Utc};
use evidence::{degeneracy_note, evidence, mean, NightOffset};
use pyranometer_effects::PyranometerEffect;
use std::collections::BTreeMap;
use std::path::PathBuf;

pub use sample::NIGHT_MIN_ZENITH_DEG;

/// Half the step of the central difference for d(cos Z)/dt.
const DERIVATIVE_HALF_STEP_S: i64 = 30;

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

/// A model and its scores on the fit and hold-out sets.
#[derive(Clone, Debug, PartialEq)]
pub struct Stage {
    pub model: ClosureModel,
    pub holdout: Score,
    pub fit: Score,
}

/// One effect of the final model, and the final model refitted without it.
#[derive(Clone, Debug)]
pub struct LeaveOneOut {
    pub effect: PyranometerEffect,
    pub without: Stage,
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
    pub leave_one_out: Vec<LeaveOneOut>,
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

/// The fit and hold-out sets of one run, and how a model is scored on them.
struct Sets<'a> {
    options: &'a ClosureOptions,
    /// The fit-set samples the options use (day, and night if asked).
    fit_day: Vec<&'a ClosureSample>,
    holdout: &'a HoldoutSet<ClosureSample>,
    /// GHI − DHI over the fit set's night samples.
    night: Option<NightOffset>,
}

impl<'a> Sets<'a> {
    fn new(
        options: &'a ClosureOptions,
        fit: &'a FitSet<ClosureSample>,
        holdout: &'a HoldoutSet<ClosureSample>,
    ) -> Self {
        let night: Vec<f64> = fit
            .samples()
            .iter()
            .filter(|s| s.zenith_deg > NIGHT_MIN_ZENITH_DEG)
            .map(|s| s.ghi_wm2 - s.dhi_wm2)
            .collect();
        Self {
            options,
            fit_day: fit.samples().iter().filter(|s| options.uses(s)).collect(),
            holdout,
            night: mean(night.iter().copied()).map(|mean_wm2| NightOffset {
                mean_wm2,
                samples: night.len(),
            }),
        }
    }

    fn stage(&self, model: ClosureModel) -> Stage {
        Stage {
            fit: fit_score(&model, &self.fit_day),
            holdout: holdout_score(&model, self.holdout, self.options),
            model,
        }
    }

    /// `effects` fitted jointly on the fit set; `None` where the fit fails.
    fn fit(&self, effects: &[PyranometerEffect]) -> Option<ClosureModel> {
        ClosureModel::fit(effects, &self.fit_day)
    }
}

/// Bayesian information criterion on the fit set: the residual sum of squares, with ln(n) per
/// fitted coefficient, so an effect with more parameters must explain more to rank first, and
/// of two sets that explain the same the simpler wins.
fn bic(stage: &Stage) -> f64 {
    let n = stage.fit.n.max(1) as f64;
    n * (stage.fit.rmse * stage.fit.rmse).max(1e-300).ln()
        + stage.model.active_columns() as f64 * n.ln()
}

/// The share of `current`'s fit-set residual sum of squares that a model scoring `s` explains,
/// in per cent.
fn explained_percent(current: &Stage, s: &Score) -> f64 {
    let b = current.fit.rmse.powi(2);
    if b > 0.0 {
        100.0 * (1.0 - s.rmse.powi(2) / b)
    } else {
        0.0
    }
}

/// What the effect selection arrived at, and why.
struct Selection {
    current: Stage,
    rejected: Vec<String>,
    notes: Vec<String>,
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
    let sets = Sets::new(options, &fit, &holdout);
    let base = sets.stage(ClosureModel::base());
    if sets.fit_day.len() < 10 || base.holdout.n < 10 {
        return Err(ClosureError::Table(format!(
            "too few samples with the sun up (zenith < {}°) or at night: {} in the fit set \
             and {} in the hold-out set, at least 10 each",
            options.max_zenith_deg,
            sets.fit_day.len(),
            base.holdout.n
        )));
    }
    let mut selection = select_effects(&sets, &base);
    drop_effects_without_gain(&sets, &mut selection);
    let Selection {
        current: last,
        rejected,
        mut notes,
    } = selection;
    let (effects, leave_one_out) = final_effects(&sets, &base, &last, &mut notes);
    if effects.is_empty() {
        notes.push("no effect improved the hold-out error by more than its noise".into());
    }
    notes.extend(degeneracy_note(&effects, options.site.latitude_deg));
    notes.extend(run_notes(prepared, &sets, origin, &base, &last));
    let (b, a) = (&base.holdout, &last.holdout);
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
        fit_day: sets.fit_day.into_iter().cloned().collect(),
        base,
        last,
        leave_one_out,
        interval: prepared.interval,
    })
}

/// Forward selection: ranks the effects not yet in the model on the fit set, adds the best
/// while its hold-out gain exceeds the noise, and after each addition refines the set on the
/// fit set ([`refine_stepwise`]).
fn select_effects(sets: &Sets, base: &Stage) -> Selection {
    let mut selection = Selection {
        current: base.clone(),
        rejected: Vec::new(),
        notes: Vec::new(),
    };
    let mut candidates = sets.options.effects.clone();
    candidates.sort();
    candidates.dedup();
    // Effect sets the loop has stood on: the hold-out rule adds, the fit-set BIC may swap or
    // drop, and the two could otherwise take turns for ever.
    let mut visited: Vec<Vec<PyranometerEffect>> = vec![Vec::new()];
    loop {
        selection.rejected.clear();
        let ranked = rank_candidates(
            sets,
            &selection.current,
            &candidates,
            &mut selection.rejected,
        );
        let Some((best, next)) = ranked.first().cloned() else {
            break;
        };
        let current = &selection.current;
        let c = compare(&current.holdout, &next.holdout, Figure::MeanAbs);
        let noise_factor = sets.options.noise_factor;
        if !(c.gain > 0.0 && c.gain > noise_factor * c.noise) {
            selection.rejected.push(format!(
                "{}: best remaining on the fit set ({:.1}% of its residual sum of squares), but \
                 the hold-out mean |r| changed by {:+.3} ± {:.3} W/m² (gain must exceed {} \
                 standard errors); loop stopped",
                best.name(),
                explained_percent(current, &next.fit),
                c.gain,
                c.noise,
                noise_factor
            ));
            for (e, st) in ranked.iter().skip(1) {
                selection.rejected.push(format!(
                    "{}: not tried on the hold-out set (ranked lower, {:.1}% of the fit-set \
                     residual sum of squares)",
                    e.name(),
                    explained_percent(current, &st.fit)
                ));
            }
            break;
        }
        selection.notes.push(format!(
            "{} added: hold-out mean |r| fell {:.3} ± {:.3} W/m² (standard error over {} \
             blocks); fit-set residual sum of squares explained {:.1}%",
            best.name(),
            c.gain,
            c.noise,
            c.blocks,
            explained_percent(current, &next.fit)
        ));
        selection.current = next;
        refine_stepwise(sets, &candidates, &mut selection);
        let mut set = selection.current.model.effects.clone();
        set.sort();
        if visited.contains(&set) {
            selection.notes.push(format!(
                "loop stopped: the effect set {:?} was reached before",
                set.iter().map(|e| e.name()).collect::<Vec<_>>()
            ));
            break;
        }
        visited.push(set);
    }
    selection
}

/// The candidates not in `current`, each added to it and fitted, best (lowest BIC) first; those
/// with nothing identifiable go to `rejected`.
fn rank_candidates(
    sets: &Sets,
    current: &Stage,
    candidates: &[PyranometerEffect],
    rejected: &mut Vec<String>,
) -> Vec<(PyranometerEffect, Stage)> {
    let mut ranked: Vec<(PyranometerEffect, Stage)> = Vec::new();
    for &e in candidates
        .iter()
        .filter(|e| !current.model.effects.contains(e))
    {
        let mut with = current.model.effects.clone();
        with.push(e);
        match sets.fit(&with) {
            Some(m) if !m.all_dropped(e) => ranked.push((e, sets.stage(m))),
            _ => rejected.push(format!(
                "{}: its signature is zero, or spanned by the effects already added, on the \
                 fit set",
                e.name()
            )),
        }
    }
    ranked.sort_by(|a, b| bic(&a.1).total_cmp(&bic(&b.1)));
    ranked
}

/// Stepwise refinement on the fit set: an effect chosen early may have stood in for several
/// faults that later effects explain better. Swaps an effect for one not in the model, or drops
/// it, while that lowers the fit-set BIC (strictly, so this ends).
fn refine_stepwise(sets: &Sets, candidates: &[PyranometerEffect], selection: &mut Selection) {
    for _ in 0..2 * PyranometerEffect::ALL.len() {
        let current = &selection.current;
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
                let Some(m) = sets.fit(&effects) else {
                    continue;
                };
                if new.is_some_and(|n| m.all_dropped(n)) {
                    continue;
                }
                let st = sets.stage(m);
                let better = match &best_change {
                    Some((_, b)) => bic(&st) < bic(b),
                    None => bic(&st) < bic(current) - 1e-9,
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
        selection.notes.push(format!(
            "{what}: fit-set BIC {:.1} → {:.1} (the later effects explain it better)",
            bic(current),
            bic(&st)
        ));
        selection.current = st;
    }
}

/// The loop's own rule applied once more at the end: every effect must still earn its place,
/// its hold-out gain over the model without it above the noise. Drops the worst until all do.
fn drop_effects_without_gain(sets: &Sets, selection: &mut Selection) {
    loop {
        let current = &selection.current;
        let mut worst: Option<(f64, usize, Stage)> = None;
        for i in 0..current.model.effects.len() {
            let mut others = current.model.effects.clone();
            others.remove(i);
            let Some(m) = sets.fit(&others) else {
                continue;
            };
            let without = sets.stage(m);
            let c = compare(&without.holdout, &current.holdout, Figure::MeanAbs);
            let margin = c.gain - sets.options.noise_factor * c.noise;
            if (c.gain <= 0.0 || margin <= 0.0) && worst.as_ref().is_none_or(|w| margin < w.0) {
                worst = Some((margin, i, without));
            }
        }
        let Some((_, i, without)) = worst else {
            break;
        };
        selection.notes.push(format!(
            "{} removed at the end: without it the hold-out mean |r| is {:.3} W/m² against \
             {:.3}, no gain above the noise",
            current.model.effects[i].name(),
            without.holdout.mean_abs,
            current.holdout.mean_abs
        ));
        selection.current = without;
    }
}

/// What each final effect does: its parameters, its evidence and the model without it,
/// refitted on the fit set.
fn final_effects(
    sets: &Sets,
    base: &Stage,
    last: &Stage,
    notes: &mut Vec<String>,
) -> (Vec<EffectReport>, Vec<LeaveOneOut>) {
    let mut leave_one_out = Vec::new();
    let mut effects: Vec<EffectReport> = Vec::new();
    let params = last.model.parameters();
    for (i, &e) in last.model.effects.iter().enumerate() {
        let mut others = last.model.effects.clone();
        others.remove(i);
        let without = sets
            .fit(&others)
            .map(|m| sets.stage(m))
            .unwrap_or_else(|| base.clone());
        let c = compare(&without.holdout, &last.holdout, Figure::MeanAbs);
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
                &last.model,
                &sets.fit_day,
                sets.night,
                &without.fit,
                &last.fit,
            ),
            gain: c.gain,
            fit_error_before: Some(without.fit.mean_abs),
            fit_error_after: Some(last.fit.mean_abs),
        });
        if last.model.dropped.iter().any(|d| *d) {
            notes.push(format!(
                "{}: part of its signature is spanned by the other effects and was not fitted",
                e.name()
            ));
        }
        leave_one_out.push(LeaveOneOut { effect: e, without });
    }
    (effects, leave_one_out)
}

/// The notes that say what the run was given and used: night offset, rows, interval, stamps,
/// split, and the fit-set errors before and after.
fn run_notes(
    prepared: &Prepared,
    sets: &Sets,
    origin: DateTime<Utc>,
    base: &Stage,
    last: &Stage,
) -> Vec<String> {
    let options = sets.options;
    let mut notes = Vec::new();
    if let Some(night) = sets.night {
        notes.push(format!(
            "night (zenith > {NIGHT_MIN_ZENITH_DEG}°, fit set): GHI − DHI averages {:+.2} W/m² \
             over {} samples",
            night.mean_wm2, night.samples
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
         (zenith < {}°{}): {} fit, {} hold-out",
        options.block.num_minutes(),
        rfc3339(&origin),
        options.max_zenith_deg,
        if options.include_night {
            format!(", or night, zenith > {NIGHT_MIN_ZENITH_DEG}°")
        } else {
            String::new()
        },
        sets.fit_day.len(),
        base.holdout.n
    ));
    notes.push(format!(
        "fit set mean |r| {:.3} → {:.3} W/m², RMSE {:.3} → {:.3} W/m²",
        base.fit.mean_abs, last.fit.mean_abs, base.fit.rmse, last.fit.rmse
    ));
    notes
}
