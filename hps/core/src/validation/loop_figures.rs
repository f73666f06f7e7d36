//! The loop report's figures: relative-error bars per sensor (before, after, Perez, like
//! the published figures) and, for each effect added, the residual against the variable
//! that revealed it, before and after.

use super::diagnostics::Diagnostic;
use super::illuminance_loop::LoopOutcome;
use crate::output::plot::{grouped_bars_png, scatter_png, BarGroup, Frame, PlotError, Series};
use std::path::Path;

/// How a plotted variable is read from a diagnostic.
type Reading = fn(&Diagnostic) -> f64;

/// Which variable reveals an effect, and how to read it from a diagnostic.
fn revealing_variable(effect: &str) -> Option<(&'static str, Reading)> {
    Some(match effect {
        "sun_undersampling" => ("share of direct sun in the model's light", |d| {
            d.direct_sun_share
        }),
        "light_leak" => ("outdoor horizontal illuminance (klx)", |d| {
            d.outdoor_lux / 1000.0
        }),
        "glazing_transmittance" => ("measured illuminance (klx)", |d| d.measured_lux / 1000.0),
        "ground_reflectance" => ("share of light from the unseen ground", |d| {
            d.unseen_ground_share
        }),
        "orientation_error" => ("sun sighting offset from SPA, declared camera (deg)", |d| {
            d.sun_offset_deg
        }),
        "shutter_overhead" => ("share of direct sun in the model's light", |d| {
            d.direct_sun_share
        }),
        "clock_offset" => (
            "rate of change of the logged illuminance (relative, per minute)",
            |d| d.rate_of_change_per_min,
        ),
        "spectral_mismatch" => ("sky colour index (blue / red from the raw frames)", |d| {
            d.sky_colour_index
        }),
        // Its signature on the sunlit readings is the solar incidence angle; over all
        // readings the clearer one is the depth: near the façade the sky is seen through
        // the glazing at wider angles.
        "glazing_angular" => ("sensor's distance from the façade (m)", |d| {
            d.facade_distance_m
        }),
        "vignetting" => (
            "mean off-axis angle of the light reaching the sensor (deg)",
            |d| d.light_off_axis_deg,
        ),
        "sky_outside_fov" => (
            "unseen sky fraction of the daylight-coefficient weight",
            |d| d.unseen_sky_fraction,
        ),
        _ => return None,
    })
}

/// Writes the figures into `dir` and returns their file names (relative to `dir`).
pub fn write_loop_figures(dir: &Path, outcome: &LoopOutcome) -> Result<Vec<String>, PlotError> {
    let mut names = Vec::new();
    let r = &outcome.report;
    let mut sensors: Vec<&String> = r.before.per_sensor.keys().collect();
    sensors.sort_by_key(|n| (n.len(), n.to_string()));
    let mut labels = vec!["before".to_string(), "after".to_string()];
    if r.baseline_perez.is_some() {
        labels.push("Perez baseline".into());
    }
    let groups: Vec<BarGroup> = sensors
        .iter()
        .map(|s| {
            let mut values = vec![
                r.before.per_sensor.get(*s).map(|v| 100.0 * v),
                r.after.per_sensor.get(*s).map(|v| 100.0 * v),
            ];
            if let Some(p) = &r.baseline_perez {
                values.push(p.per_sensor.get(*s).map(|v| 100.0 * v));
            }
            BarGroup {
                label: (*s).clone(),
                values,
            }
        })
        .collect();
    let name = "errors_per_sensor.png".to_string();
    grouped_bars_png(
        &dir.join(&name),
        &Frame::new(
            "Hold-out mean |relative error| per sensor",
            "sensor",
            "mean |relative error| (%)",
        ),
        &labels,
        &groups,
    )?;
    names.push(name);
    for e in &r.effects {
        let Some((variable, value)) = revealing_variable(&e.name) else {
            continue;
        };
        let series = |label: &str, residual: fn(&Diagnostic) -> f64| Series {
            label: label.into(),
            points: outcome
                .diagnostics
                .iter()
                .map(|d| (value(d), 100.0 * residual(d)))
                .filter(|p| p.0.is_finite() && p.1.is_finite())
                .collect(),
        };
        let name = format!("residual_{}.png", e.name);
        scatter_png(
            &dir.join(&name),
            &Frame::new(
                &format!("{}: residual before and after", e.name),
                variable,
                "model / measured - 1 (%)",
            ),
            &[
                series("before", |d| d.before_lux / d.measured_before_lux - 1.0),
                series("after", |d| d.after_lux / d.measured_lux - 1.0),
            ],
        )?;
        names.push(name);
    }
    Ok(names)
}
