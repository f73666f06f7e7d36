//! `luxmeter_calibration` (registered in test builds only: the proof that an effect is one
//! file and one registry line): one lux-meter reads a factor c off the truth, so its
//! readings alone are off by that factor. Signature: measured / modelled differs from the
//! other sensors' on one sensor. Model: that sensor's terms scaled by c (least squares on its
//! readings).

use super::fit::{readings, scored};
use super::{FitContext, Fitted, LoopEffect};
use crate::model::ModelError;
use crate::validation::prediction::predict;
use std::collections::BTreeMap;

pub struct LuxmeterCalibration;

impl LoopEffect for LuxmeterCalibration {
    fn name(&self) -> &'static str {
        "luxmeter_calibration"
    }

    fn fit(&self, ctx: &mut FitContext<'_>) -> Result<Option<Fitted>, ModelError> {
        // Per sensor, the least-squares factor c minimising Σ (c p / m − 1)².
        let mut sums: BTreeMap<usize, (f64, f64)> = BTreeMap::new();
        for (t, k, m) in readings(ctx.state, ctx.terms, ctx.fit) {
            let r = predict(ctx.state, t)[k] / m;
            let e = sums.entry(k).or_default();
            e.0 += r;
            e.1 += r * r;
        }
        let factors: Vec<(usize, f64)> = sums
            .into_iter()
            .filter(|(_, (_, rr))| *rr > 0.0)
            .map(|(k, (r, rr))| (k, r / rr))
            .collect();
        let Some(&(sensor, c)) = factors
            .iter()
            .max_by(|a, b| (a.1 - 1.0).abs().total_cmp(&(b.1 - 1.0).abs()))
        else {
            return Ok(None);
        };
        if (c - 1.0).abs() < 0.01 {
            return Ok(None);
        }
        let terms: Vec<_> = ctx
            .terms
            .iter()
            .map(|t| {
                let mut t = t.clone();
                t.sky_with_sun_lux[sensor] *= c;
                t.sky_without_sun_lux[sensor] *= c;
                t.sun_lux_per_dn_lux[sensor] *= c;
                t.unseen_ground_lux_per_cd_m2[sensor] *= c;
                t
            })
            .collect();
        let mut parameters = BTreeMap::new();
        parameters.insert("sensor".into(), sensor as f64);
        parameters.insert("factor".into(), c);
        let evidence = format!(
            "sensor {sensor} alone reads {c:.3} times the model: a lux-meter's calibration"
        );
        Ok(Some(scored(
            ctx,
            ctx.state.clone(),
            parameters,
            evidence,
            Some(terms),
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::super::registry::{self, EFFECTS};
    use super::super::{FitContext, Stage};
    use crate::campaign::{Campaign, CampaignConfig, CampaignFiles, Site};
    use crate::engine::{DaylightCoefficients, Settings, World};
    use crate::model::{CaptureTerms, Room};
    use crate::validation::prediction::{predict, LoopState};
    use crate::validation::sample::Sample;
    use crate::validation::sky_geometry::SkyGeometry;
    use crate::validation::split::{split, SplitPlan};
    use crate::validation::terms::Terms;
    use chrono::{TimeDelta, TimeZone, Utc};

    const ROOM: &str = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/scenes/test-module"
    );

    /// The effect added as one file and one registry line is offered by the registry, and
    /// fitted and ranked through it like the others: on readings where one lux-meter alone
    /// reads 12 % high, it has the lowest fit-set error of every effect the registry fits,
    /// and names the sensor and the factor.
    #[test]
    fn an_effect_added_by_one_file_and_one_registry_line_is_fitted_and_ranked() {
        let effect = registry::find("luxmeter_calibration").expect("registered");
        assert_eq!(effect.stage(), Stage::Greedy);

        let scene = crate::scene::load(format!("{ROOM}/scene.rad")).unwrap();
        let sensors = crate::scene::load_sensors(format!("{ROOM}/sensors.pts")).unwrap();
        let n_sensors = sensors.len();
        let dc = DaylightCoefficients {
            sensors: sensors.iter().map(|s| s.name.clone()).collect(),
            mf: 1,
            bins: 2 * 145,
            lux_per_cd_m2: vec![0.0; n_sensors * 2 * 145],
            samples_per_sensor: 1,
        };
        let mut room = Room {
            world: World::new(&scene).unwrap(),
            sensors,
            dc,
            settings: Settings::default(),
        };
        // Twelve captures an hour apart, the sky's light per sensor varying with the hour.
        let captures = 12;
        let terms: Vec<Terms> = (0..captures)
            .map(|i| {
                let sky: Vec<f64> = (0..n_sensors)
                    .map(|k| 300.0 + 50.0 * i as f64 + 100.0 * k as f64)
                    .collect();
                Terms::new(CaptureTerms {
                    sun: None,
                    sun_missing: Some(crate::model::terms::SunMissing::BelowHorizon { altitude_deg: -10.0 }),
                    sky_with_sun_lux: sky.clone(),
                    sky_without_sun_lux: sky,
                    sun_lux_per_dn_lux: vec![0.0; n_sensors],
                    sun_dn_lux: 0.0,
                    unseen_ground_lux_per_cd_m2: vec![0.0; n_sensors],
                    outdoor_horizontal_lux: 10_000.0 + 1000.0 * i as f64,
                    unseen_sky_fraction: 0.0,
                    saturated_fraction: 0.0,
                    bins_with_sun_cd_m2: vec![],
                    bins_without_sun_cd_m2: vec![],
                    bin_seen: vec![],
                })
            })
            .collect();
        let state = LoopState::default();
        let origin = Utc.with_ymd_and_hms(2017, 5, 8, 6, 0, 0).unwrap();
        let samples: Vec<Sample> = (0..captures)
            .map(|i| {
                let p = predict(&state, &terms[i]);
                let measured = (0..n_sensors)
                    .map(|k| {
                        let wobble = 1.0 + 0.002 * ((i * 7 + k * 3) % 5) as f64;
                        Some(p[k] * wobble * if k == 1 { 1.12 } else { 1.0 })
                    })
                    .collect();
                Sample {
                    capture: i,
                    time_utc: origin + TimeDelta::hours(i as i64),
                    measured_lux: measured,
                    series: vec![vec![]; n_sensors],
                }
            })
            .collect();
        let plan = SplitPlan {
            origin,
            block: TimeDelta::hours(2),
            period: 2,
            phase: 1,
        };
        let (fit, _holdout) = split(samples, &plan).unwrap();
        let campaign = Campaign {
            dir: ROOM.into(),
            config: CampaignConfig {
                name: "synthetic".into(),
                site: Site {
                    latitude_deg: 46.52,
                    longitude_deg: 6.57,
                    elevation_m: 400.0,
                },
                files: CampaignFiles::default(),
            },
            captures: vec![],
            luxmeters: vec![],
            luxmeter_gaps: 0,
            pyranometer: None,
        };
        let geometry = SkyGeometry {
            bin_radial2: vec![vec![]; captures],
            sun_radial2: vec![f64::NAN; captures],
            shown_fov_deg: vec![0.0; captures],
            sun_off_axis_deg: vec![f64::NAN; captures],
            ..SkyGeometry::empty()
        };
        let device = crate::camera::DeviceConfig::default();
        // Every effect of the registry's greedy stage, fitted as the loop fits them.
        let mut ranked = Vec::new();
        for &e in EFFECTS.iter().filter(|e| e.stage() == Stage::Greedy) {
            let mut ctx = FitContext {
                campaign: &campaign,
                room: &mut room,
                device: &device,
                captures: &[],
                state: &state,
                accepted: &[],
                terms: &terms,
                sky_raw: &terms,
                sky_geometry: &geometry,
                fit: &fit,
                reference_outdoor: &[],
                angular: None,
                colours: &[],
            };
            if let Some(f) = e.fit(&mut ctx).unwrap() {
                ranked.push((e.name(), f));
            }
        }
        ranked.sort_by(|a, b| a.1.fit_error.total_cmp(&b.1.fit_error));
        let (name, best) = &ranked[0];
        assert_eq!(
            *name,
            "luxmeter_calibration",
            "ranking: {:?}",
            ranked
                .iter()
                .map(|r| (r.0, r.1.fit_error))
                .collect::<Vec<_>>()
        );
        assert_eq!(best.parameters["sensor"], 1.0);
        assert!(
            (best.parameters["factor"] - 1.12).abs() < 0.01,
            "{:?}",
            best.parameters
        );
        assert!(best.fit_error < 0.005, "{}", best.fit_error);
    }
}
