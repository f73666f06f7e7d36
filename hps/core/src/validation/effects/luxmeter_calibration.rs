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
        parameters.insert("factor".into(), 1.0 / c);
        let evidence = format!(
            "sensor {sensor} alone reads {:.3} times the model: a lux-meter's calibration",
            1.0 / c
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
