//! The sentences of the report: why an effect was taken, and which effects the closure cannot
//! tell apart.

use super::model::ClosureModel;
use super::pyranometer_effects::PyranometerEffect;
use super::sample::{ClosureSample, NIGHT_MIN_ZENITH_DEG};
use crate::validation::report::EffectReport;
use crate::validation::split::Score;

/// GHI − DHI over the fit set's night samples: the thermal offset alone.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct NightOffset {
    pub mean_wm2: f64,
    pub samples: usize,
}

pub(super) fn mean(values: impl Iterator<Item = f64>) -> Option<f64> {
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
pub(super) fn evidence(
    effect: PyranometerEffect,
    current: &ClosureModel,
    next: &ClosureModel,
    fit_day: &[&ClosureSample],
    night: Option<NightOffset>,
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
    let specific = match effect {
        PyranometerEffect::ThermalOffset => match night {
            Some(night) => format!(
                "; at night (zenith > {NIGHT_MIN_ZENITH_DEG}°) the fit set's GHI − DHI averages \
                 {:+.2} W/m² over {} samples",
                night.mean_wm2, night.samples
            ),
            None => String::new(),
        },
        PyranometerEffect::TimestampShift
        | PyranometerEffect::LevelTilt
        | PyranometerEffect::TrackerDrift => morning_and_afternoon(fit_day, &residual),
        PyranometerEffect::CosineResponse | PyranometerEffect::DniScale => {
            per_unit_beam(fit_day, &residual)
        }
        PyranometerEffect::DhiScale => String::new(),
    };
    text.push_str(&specific);
    text.push('.');
    text
}

/// The daytime residual's mean before and after solar noon: the signature of effects that
/// follow the sun's hour angle.
fn morning_and_afternoon(fit_day: &[&ClosureSample], residual: &[f64]) -> String {
    let am = mean(
        fit_day
            .iter()
            .zip(residual)
            .filter(|(s, _)| s.zenith_deg < 90.0 && s.hour_angle_deg < 0.0)
            .map(|(_, r)| *r),
    );
    let pm = mean(
        fit_day
            .iter()
            .zip(residual)
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
}

/// The residual per unit beam with the sun high and low: the signature of effects that
/// scale the beam.
fn per_unit_beam(fit_day: &[&ClosureSample], residual: &[f64]) -> String {
    let ratio = |hi: bool| {
        let (r, b) = fit_day
            .iter()
            .zip(residual)
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
}

/// The sun's hour angle advances 2π per mean solar day (86 400 s): 15° per hour.
const HOUR_ANGLE_RATE_RAD_PER_S: f64 = std::f64::consts::TAU / 86_400.0;

/// A clock error δ moves the sun along its diurnal circle, which to first order looks like a
/// tilt of the GHI sensor about the polar axis: an east–west level tilt q = ω δ cos φ. The
/// closure cannot tell them apart; say so with the numbers of whichever was found.
pub(super) fn degeneracy_note(effects: &[EffectReport], latitude_deg: f64) -> Option<String> {
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
