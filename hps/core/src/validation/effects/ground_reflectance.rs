//! `ground_reflectance`: the ground the lens does not see reflects more or less than the
//! model's 0.2. Signature: the relative residual follows the share of the prediction from that
//! ground. Model: its reflectance ρ (the product's own parameter), fitted jointly with the
//! other linear effects by least squares.

use super::fit::{joint, pearson_r, readings, scored};
use super::{FitContext, Fitted, Linear, LoopEffect};
use crate::model::ModelError;
use crate::validation::diagnostics::Variable;
use crate::validation::prediction::{predict, LoopState, GLAZING_TRANSMITTANCE};
use std::collections::BTreeMap;

const PARAMETER: &str = "reflectance";

pub struct GroundReflectance;

impl LoopEffect for GroundReflectance {
    fn name(&self) -> &'static str {
        "ground_reflectance"
    }

    fn linear(&self) -> Option<Linear> {
        Some(Linear::Ground)
    }

    fn revealing_variable(&self) -> Option<(&'static str, Variable)> {
        Some(("share of light from the unseen ground", |d| {
            d.unseen_ground_share
        }))
    }

    fn fit(&self, ctx: &mut FitContext<'_>) -> Result<Option<Fitted>, ModelError> {
        let state = ctx.state;
        let mut zero = state.clone();
        zero.model.ground_reflectance = 0.0;
        let tau = state.get(GLAZING_TRANSMITTANCE);
        let rows: Vec<(f64, f64, f64)> = readings(state, ctx.terms, ctx.fit)
            .map(|(t, k, m)| {
                let per_rho = tau * t.unseen_ground_lux_per_cd_m2[k] * t.outdoor_horizontal_lux
                    / std::f64::consts::PI;
                (per_rho, predict(&zero, t)[k], m)
            })
            .collect();
        if rows.iter().all(|r| r.0 <= 0.0) {
            return Ok(None);
        }
        let Some(next) = joint(ctx, self) else {
            return Ok(None);
        };
        let mut parameters = BTreeMap::new();
        parameters.insert(PARAMETER.into(), next.model.ground_reflectance);
        let rho = state.model.ground_reflectance;
        let r = pearson_r(
            &rows
                .iter()
                .map(|(g, p, m)| (g / m, m / (p + rho * g) - 1.0))
                .collect::<Vec<_>>(),
        );
        let evidence = format!(
            "the relative residual follows the share of the prediction that comes from \
             ground the lens does not see (r = {r:.2})"
        );
        Ok(Some(scored(ctx, next, parameters, evidence, None)))
    }

    fn refresh(&self, state: &LoopState, parameters: &mut BTreeMap<String, f64>) {
        parameters.insert(PARAMETER.into(), state.model.ground_reflectance);
    }
}
