//! Glare at the declared occupant views, every cycle (issue 21 item 3): with the room under
//! the capture's measured sky (`model::install_measured_sky`, the sun as a concentrated
//! source), each view's vertical eye illuminance from an illuminance sensor at the eye facing
//! the view direction, then, while the cycle's time allows, its fisheye luminance picture and
//! Ev and DGP from it by `skylux_hps::glare` (the code of `skylux glare`). A view that does
//! not fit the time left reports the simplified DGPs from the sensor's Ev instead, and says so.

use crate::config::{Config, GlareConfig, ViewConfig};
use serde::{Deserialize, Serialize};
use skylux_hps::engine::render::{self, RenderSettings};
use skylux_hps::engine::{self, Settings, World};
use skylux_hps::glare::{self, metrics, GlareOptions, LuminanceImage};
use skylux_hps::picture::Picture;
use skylux_hps::scene::{Sensor, SourceLocation};
use std::collections::HashMap;
use std::path::Path;
use std::sync::Arc;
use std::time::Instant;

/// How a view's glare was obtained.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum GlareMethod {
    /// The fisheye picture rendered and evaluated: `dgp` is set.
    Render,
    /// Not rendered (see `reason`): Ev from the eye's sensor, DGPs only.
    Dgps,
}

/// One view's glare in a cycle's record.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct ViewGlare {
    pub view: String,
    pub method: GlareMethod,
    /// Vertical eye illuminance, lux: the picture's (Σ L ω cos θ) when rendered, else the
    /// eye sensor's.
    pub ev_lux: f64,
    /// Its Monte-Carlo standard error, lux.
    pub ev_stderr_lux: f64,
    /// Daylight glare probability of the picture (evalglare's defaults); absent without one.
    #[serde(default)]
    pub dgp: Option<f64>,
    /// Simplified DGP from `ev_lux` alone (Wienold 2009).
    pub dgps: f64,
    /// `ev_lux` is below DGP's low-light limit (1000 lx; at night, at dusk, in a dark
    /// corner): `dgp` and `dgps` are then the formulas' floor, not a glare probability.
    #[serde(default)]
    pub low_light: bool,
    /// Glare sources found in the picture.
    #[serde(default)]
    pub sources: Option<usize>,
    /// The illuminance sensor at the eye facing the view direction, lux, and its standard
    /// error: what the picture's Ev must agree with.
    pub sensor_ev_lux: f64,
    pub sensor_ev_stderr_lux: f64,
    /// Why the view was not rendered (method `dgps`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
    /// The picture (EXR, luminance in `Y`), relative to the output directory, when kept.
    #[serde(default)]
    pub image: Option<String>,
    pub render_ms: f64,
}

/// The views a cycle evaluates and its time budget, from the configuration (read each
/// cycle, so a reload applies from the next one).
pub struct ViewRequest<'a> {
    pub views: &'a [ViewConfig],
    pub glare: &'a GlareConfig,
    /// The cycle's budget from the capture's start, ms.
    pub budget_ms: f64,
}

impl<'a> ViewRequest<'a> {
    pub fn from_config(config: &'a Config) -> Self {
        Self {
            views: &config.views,
            glare: &config.glare,
            budget_ms: config.glare.budget_fraction * config.capture.period_s * 1e3,
        }
    }
}

/// Render time per path measured for each view (by name), so that the next cycle knows
/// whether a render fits before starting it.
#[derive(Default)]
pub struct RenderRates {
    ms_per_path: HashMap<String, f64>,
}

/// A render's estimate from the eye sensor's rate is multiplied by this: a camera path adds
/// a primary ray and can see more of the room than a sensor's (a margin, not a measurement).
const SENSOR_RATE_MARGIN: f64 = 1.5;

/// Whether a render estimated at `estimate_ms` fits the `remaining_ms` of the cycle's budget:
/// None if it does, else the reason, in words, for the record.
pub fn render_refusal(estimate_ms: f64, remaining_ms: f64) -> Option<String> {
    if estimate_ms <= remaining_ms {
        None
    } else {
        Some(format!(
            "render estimated at {estimate_ms:.0} ms, over the {:.0} ms left of the cycle's \
             budget (glare.budget_fraction of capture.period_s)",
            remaining_ms.max(0.0)
        ))
    }
}

/// What a cycle's views gave: a record per view, and the pictures rendered (index into
/// `glare`, picture).
#[derive(Default)]
pub struct ViewsOutcome {
    pub glare: Vec<ViewGlare>,
    pub pictures: Vec<(usize, Picture)>,
}

/// Evaluates every view in `world` (under the measured sky already), with `deadline_ms`
/// counted from `started`.
pub fn evaluate_views(
    world: &World,
    views: &[ViewConfig],
    glare: &GlareConfig,
    trace: Settings,
    rates: &mut RenderRates,
    started: Instant,
    deadline_ms: f64,
) -> Result<ViewsOutcome, String> {
    let t = Instant::now();
    let sensors = eye_sensors(world, views, glare, trace)?;
    let sensor_ms_per_path = ms(t) / (views.len().max(1) as f64 * f64::from(glare.sensor_samples));
    let mut records = Vec::with_capacity(views.len());
    let mut pictures = Vec::new();
    for (i, (view, (sensor_lux, sensor_se))) in views.iter().zip(sensors).enumerate() {
        let paths = f64::from(glare.resolution_px).powi(2) * f64::from(glare.samples_per_pixel);
        let rate = rates
            .ms_per_path
            .get(&view.name)
            .copied()
            .unwrap_or(SENSOR_RATE_MARGIN * sensor_ms_per_path);
        let remaining = deadline_ms - ms(started);
        let record = match render_refusal(paths * rate, remaining) {
            Some(reason) => fallback(view, sensor_lux, sensor_se, reason),
            None => {
                let t = Instant::now();
                let (record, picture) = rendered(world, view, glare, trace, sensor_lux, sensor_se)?;
                rates.ms_per_path.insert(view.name.clone(), ms(t) / paths);
                pictures.push((i, picture));
                record
            }
        };
        records.push(record);
    }
    Ok(ViewsOutcome {
        glare: records,
        pictures,
    })
}

/// The eye sensors' Ev (lux, standard error), one engine run for all views.
fn eye_sensors(
    world: &World,
    views: &[ViewConfig],
    glare: &GlareConfig,
    trace: Settings,
) -> Result<Vec<(f64, f64)>, String> {
    let origin = SourceLocation {
        file: Arc::from(Path::new("[[views]]")),
        line: 0,
    };
    let sensors: Vec<Sensor> = views
        .iter()
        .map(|v| {
            let view = v.view();
            Sensor {
                name: v.name.clone(),
                position_m: view.position_m,
                direction: view.direction.normalize(),
                origin: origin.clone(),
            }
        })
        .collect();
    let settings = Settings {
        samples_per_sensor: glare.sensor_samples,
        ..trace
    };
    let result = engine::illuminance(world, &sensors, &settings, &|_, _| {})
        .map_err(|e| format!("eye sensors: {e}"))?;
    Ok(result
        .into_iter()
        .map(|s| (s.illuminance_lux, s.stderr_lux))
        .collect())
}

/// A view reported from its sensor alone.
fn fallback(view: &ViewConfig, sensor_lux: f64, sensor_se: f64, reason: String) -> ViewGlare {
    ViewGlare {
        view: view.name.clone(),
        method: GlareMethod::Dgps,
        ev_lux: sensor_lux,
        ev_stderr_lux: sensor_se,
        dgp: None,
        dgps: metrics::dgps(sensor_lux),
        low_light: sensor_lux < metrics::LOW_LIGHT_LIMIT_LUX,
        sources: None,
        sensor_ev_lux: sensor_lux,
        sensor_ev_stderr_lux: sensor_se,
        reason: Some(reason),
        image: None,
        render_ms: 0.0,
    }
}

/// Renders the view and evaluates its glare as `skylux glare` does with its defaults, on the
/// luminance as the kept EXR stores it (float32), so the file gives the same figures.
fn rendered(
    world: &World,
    view: &ViewConfig,
    glare: &GlareConfig,
    trace: Settings,
    sensor_lux: f64,
    sensor_se: f64,
) -> Result<(ViewGlare, Picture), String> {
    let t = Instant::now();
    let fail = |e: &dyn std::fmt::Display| format!("view {:?}: {e}", view.name);
    let prepared = view.view().prepare().map_err(|e| fail(&e))?;
    let settings = RenderSettings {
        width_px: glare.resolution_px,
        height_px: glare.resolution_px,
        samples_per_pixel: glare.samples_per_pixel,
        trace,
        // Grain would read as glare sources. The filter keeps Ev (within 1 % of rtrace -I at
        // the eye: hps/core/tests/render.rs); the standard error below is the unfiltered
        // pixels' spread, an upper bound.
        filtered: true,
    };
    let picture = render::render(world, &prepared, &settings, &|_, _| {}).map_err(|e| fail(&e))?;
    let image = LuminanceImage {
        width_px: picture.width_px,
        height_px: picture.height_px,
        view: prepared.view.clone(),
        luminance_cd_m2: picture
            .luminance_cd_m2
            .iter()
            .map(|&l| f64::from(l as f32))
            .collect(),
    };
    let report = glare::evaluate(&image, &GlareOptions::default()).map_err(|e| fail(&e))?;
    let ev_se =
        glare::ev_stderr_lux(&image, &picture.luminance_stderr_cd_m2).map_err(|e| fail(&e))?;
    let record = ViewGlare {
        view: view.name.clone(),
        method: GlareMethod::Render,
        ev_lux: report.ev_lux,
        ev_stderr_lux: ev_se,
        dgp: Some(report.dgp),
        dgps: metrics::dgps(report.ev_lux),
        low_light: report.ev_lux < metrics::LOW_LIGHT_LIMIT_LUX,
        sources: Some(report.sources.len()),
        sensor_ev_lux: sensor_lux,
        sensor_ev_stderr_lux: sensor_se,
        reason: None,
        image: None,
        render_ms: ms(t),
    };
    Ok((record, picture))
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_render_runs_only_if_its_estimate_fits_what_is_left() {
        assert_eq!(render_refusal(900.0, 1000.0), None);
        assert_eq!(render_refusal(1000.0, 1000.0), None);
        let why = render_refusal(1500.0, 1000.0).unwrap();
        assert!(
            why.contains("1500 ms") && why.contains("1000 ms left"),
            "{why}"
        );
        // An overrun cycle has nothing left, not a negative budget.
        let why = render_refusal(10.0, -50.0).unwrap();
        assert!(why.contains(" 0 ms left"), "{why}");
    }

    #[test]
    fn night_and_dusk_views_are_flagged_low_light() {
        let view: ViewConfig = toml::from_str(
            "name = \"desk\"\nposition_m = [1.0, 1.0, 1.2]\ndirection = [0.0, 1.0, 0.0]\n",
        )
        .unwrap();
        for (ev_lux, low) in [(0.0, true), (999.0, true), (1000.0, false), (5000.0, false)] {
            let v = fallback(&view, ev_lux, 1.0, "test".into());
            assert_eq!(v.low_light, low, "{ev_lux} lx");
            // The value reported at night is the formula's floor, which the flag qualifies.
            assert!(v.dgps >= 0.184);
        }
    }
}
