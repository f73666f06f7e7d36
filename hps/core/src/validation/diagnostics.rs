//! Per reading, the model before and after and the explanatory variables of the effect
//! library: the residual table and plots are drawn from them.

use super::glazing::Glazing;
use super::prediction::{parts, predict, LoopState, GLAZING_TRANSMITTANCE};
use super::report::ResidualRow;
use super::sample::{interpolate, reading_at, relative_rate_per_min};
use super::sky_geometry::{light_off_axis_deg, SkyGeometry};
use super::terms::Terms;
use crate::campaign::Campaign;
use crate::model::{CaptureData, Room};
use chrono::{TimeDelta, Timelike, Utc};

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

/// What the diagnostics are computed from: the loop's data and its model before and after.
pub struct DiagnosticInputs<'a> {
    pub campaign: &'a Campaign,
    pub room: &'a Room,
    pub captures: &'a [CaptureData],
    /// The terms under the final model, and as first computed (for the sun's offset from SPA
    /// under the declared camera).
    pub terms: &'a [Terms],
    pub base_terms: &'a [Terms],
    pub state: &'a LoopState,
    /// The base model's clock offset (the rate of change is read at it).
    pub base_clock_offset_s: f64,
    pub sensor_names: &'a [String],
    pub match_window: TimeDelta,
    /// Per capture, per sensor, the logger's series around it.
    pub series_of: &'a [Vec<Vec<(f64, f64)>>],
    pub base_predictions: &'a [Vec<f64>],
    pub final_predictions: &'a [Vec<f64>],
    /// Per capture, the Perez baseline's prediction.
    pub perez: &'a [Option<Vec<f64>>],
    pub sky_geometry: &'a SkyGeometry,
    pub glazing: Option<&'a Glazing>,
    pub holdout_times: &'a [String],
}

impl DiagnosticInputs<'_> {
    /// The reading matched under the final model's clock offset.
    fn shifted(&self, i: usize, k: usize, matched: Option<f64>, offset: f64) -> Option<f64> {
        if offset == 0.0 {
            matched
        } else {
            interpolate(&self.series_of[i][k], offset)
        }
    }

    /// One diagnostic per reading of every capture.
    pub fn diagnostics(&self) -> Vec<Diagnostic> {
        let offset = self.state.get(super::prediction::CLOCK_OFFSET_S);
        let mut concentrated = self.state.clone();
        concentrated.model.concentrated_sun = true;
        let mut out = Vec::new();
        for (i, c) in self.captures.iter().enumerate() {
            let t = &self.terms[i];
            let capture = CaptureVariables::new(self, &concentrated, i);
            for (k, name) in self.sensor_names.iter().enumerate() {
                let Some(m0) = reading_at(self.campaign, name, c.time, self.match_window) else {
                    continue;
                };
                let Some(m) = self.shifted(i, k, Some(m0), offset) else {
                    continue;
                };
                out.push(self.diagnostic(&capture, t, i, k, m0, m));
            }
        }
        out
    }

    fn diagnostic(
        &self,
        v: &CaptureVariables,
        t: &Terms,
        i: usize,
        k: usize,
        m0: f64,
        m: f64,
    ) -> Diagnostic {
        let c = &self.captures[i];
        let (tau, rho) = (
            self.state.get(GLAZING_TRANSMITTANCE),
            self.state.model.ground_reflectance,
        );
        let direct = t.sun_lux_per_dn_lux[k] * t.sun_dn_lux * tau;
        let total = v.total[k];
        Diagnostic {
            time: c.time,
            sensor: self.sensor_names[k].clone(),
            holdout: v.holdout,
            measured_lux: m,
            measured_before_lux: m0,
            before_lux: self.base_predictions[i][k],
            after_lux: self.final_predictions[i][k],
            outdoor_lux: t.outdoor_horizontal_lux,
            direct_sun_share: if total > 0.0 { direct / total } else { 0.0 },
            unseen_ground_share: if total > 0.0 {
                tau * rho * v.parts[k].1 / total
            } else {
                0.0
            },
            sun_offset_deg: v.sun_offset_deg,
            rate_of_change_per_min: relative_rate_per_min(
                &self.series_of[i][k],
                self.base_clock_offset_s,
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
            sun_incidence_deg: self
                .glazing
                .map_or(f64::NAN, |g| g.primary().incidence_deg(c.spa_sun)),
            facade_distance_m: self.glazing.map_or(f64::NAN, |g| {
                g.facade_distance_m(self.room.sensors[k].position_m)
            }),
            light_off_axis_deg: v.light_off_axis[k],
        }
    }

    /// `illuminance.csv`'s rows for every capture and sensor.
    pub fn illuminance_rows(&self) -> Vec<IlluminanceRow> {
        let offset = self.state.get(super::prediction::CLOCK_OFFSET_S);
        let mut rows = Vec::new();
        for (i, c) in self.captures.iter().enumerate() {
            let time = c.time.to_rfc3339();
            for (k, name) in self.sensor_names.iter().enumerate() {
                let measured = reading_at(self.campaign, name, c.time, self.match_window);
                let shifted = self.shifted(i, k, measured, offset);
                let mut push = |model: &str, lux: f64, measured: Option<f64>| {
                    rows.push(IlluminanceRow {
                        time: time.clone(),
                        sensor: name.clone(),
                        lux_model: lux,
                        lux_measured: measured,
                        model: model.into(),
                    })
                };
                push("hdr-base", self.base_predictions[i][k], measured);
                push("hdr", self.final_predictions[i][k], shifted);
                if let Some(p) = &self.perez[i] {
                    push("perez", p[k], measured);
                }
            }
        }
        rows
    }
}

/// What a capture's diagnostics share.
struct CaptureVariables {
    holdout: bool,
    /// Per sensor, the parts and the prediction with the sun concentrated.
    parts: Vec<(f64, f64, f64)>,
    total: Vec<f64>,
    sun_offset_deg: f64,
    light_off_axis: Vec<f64>,
}

impl CaptureVariables {
    fn new(inputs: &DiagnosticInputs, concentrated: &LoopState, i: usize) -> Self {
        let c = &inputs.captures[i];
        let t = &inputs.terms[i];
        let time = c.time.with_timezone(&Utc).to_rfc3339();
        Self {
            holdout: inputs.holdout_times.contains(&time),
            parts: parts(concentrated, t),
            total: predict(concentrated, t),
            sun_offset_deg: inputs.base_terms[i].sun.as_ref().map_or(f64::NAN, |s| {
                s.direction.angle_between(c.spa_sun).to_degrees()
            }),
            light_off_axis: light_off_axis_deg(t, &inputs.room.dc, inputs.sky_geometry, i),
        }
    }
}
