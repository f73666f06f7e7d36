//! The loop report's figures: relative-error bars per sensor (before, after, Perez, like
//! the published figures) and, for each effect added, the residual against the variable
//! that revealed it, before and after.

use super::diagnostics::Diagnostic;
use super::effects::registry;
use super::illuminance_loop::LoopOutcome;
use crate::output::plot::{grouped_bars_png, scatter_png, BarGroup, Frame, PlotError, Series};
use std::path::Path;

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
        let revealing = registry::find(&e.name).and_then(|x| x.revealing_variable());
        let Some((variable, value)) = revealing else {
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
