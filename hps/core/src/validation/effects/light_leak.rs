//! `light_leak`: light reaches the lux-meters by a path the scene lacks, in proportion to the
//! outdoor horizontal illuminance. Signature: the residual (measured − model) grows with the
//! outdoor illuminance. Model: `k · outdoor` added, fitted jointly with the other linear
//! effects by least squares.

use super::fit::{joint, pearson_r, readings, scored};
use super::{FitContext, Fitted, Linear, LoopEffect};
use crate::model::ModelError;
use crate::validation::diagnostics::Variable;
use crate::validation::prediction::{predict, LoopState, LIGHT_LEAK};
use std::collections::BTreeMap;

const PARAMETER: &str = "lux_per_outdoor_lux";

pub struct LightLeak;

impl LoopEffect for LightLeak {
    fn name(&self) -> &'static str {
        "light_leak"
    }

    fn linear(&self) -> Option<Linear> {
        Some(Linear::Leak)
    }

    fn revealing_variable(&self) -> Option<(&'static str, Variable)> {
        Some(("outdoor horizontal illuminance (klx)", |d| {
            d.outdoor_lux / 1000.0
        }))
    }

    fn fit(&self, ctx: &mut FitContext<'_>) -> Result<Option<Fitted>, ModelError> {
        let state = ctx.state;
        let leak = state.get(LIGHT_LEAK);
        let rows: Vec<(f64, f64, f64)> = readings(state, ctx.terms, ctx.fit)
            .map(|(t, k, m)| {
                let p = predict(state, t)[k] - leak * t.outdoor_horizontal_lux;
                (t.outdoor_horizontal_lux, p, m)
            })
            .collect();
        let Some(next) = joint(ctx, self) else {
            return Ok(None);
        };
        let k = next.get(LIGHT_LEAK);
        if k <= 0.0 {
            return Ok(None);
        }
        let mut parameters = BTreeMap::new();
        parameters.insert(PARAMETER.into(), k);
        let r = pearson_r(
            &rows
                .iter()
                .map(|(eh, p, m)| (*eh, m - p - leak * eh))
                .collect::<Vec<_>>(),
        );
        let evidence = format!(
            "the residual (measured − model) grows with the outdoor horizontal illuminance \
             (r = {r:.2}) on every sensor, most in relative terms deep in the room"
        );
        Ok(Some(scored(ctx, next, parameters, evidence, None)))
    }

    fn refresh(&self, state: &LoopState, parameters: &mut BTreeMap<String, f64>) {
        parameters.insert(PARAMETER.into(), state.get(LIGHT_LEAK));
    }
}
