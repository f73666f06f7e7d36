//! `sun_undersampling`: the sun spread over its sky patch instead of sampled as a concentrated
//! source. Signature: the error sits where the direct sun reaches the sensor. Model: hand the
//! sun over as a concentrated source (the product's own model does).

use super::fit::{readings, scored};
use super::{FitContext, Fitted, LoopEffect};
use crate::model::ModelError;
use crate::validation::diagnostics::Variable;
use crate::validation::prediction::predict;
use std::collections::BTreeMap;

pub struct SunUndersampling;

impl LoopEffect for SunUndersampling {
    fn name(&self) -> &'static str {
        "sun_undersampling"
    }

    fn revealing_variable(&self) -> Option<(&'static str, Variable)> {
        Some(("share of direct sun in the model's light", |d| {
            d.direct_sun_share
        }))
    }

    fn fit(&self, ctx: &mut FitContext<'_>) -> Result<Option<Fitted>, ModelError> {
        let state = ctx.state;
        if state.model.concentrated_sun {
            return Ok(None);
        }
        let mut next = state.clone();
        next.model.concentrated_sun = true;
        let (mut lit, mut shade) = (vec![], vec![]);
        for (t, k, m) in readings(state, ctx.terms, ctx.fit) {
            let e = (predict(state, t)[k] / m - 1.0).abs();
            if t.sun_lux_per_dn_lux[k] * t.sun_dn_lux > 0.05 * m {
                lit.push(e);
            } else {
                shade.push(e);
            }
        }
        if lit.is_empty() {
            return Ok(None);
        }
        let mean = |v: &[f64]| {
            if v.is_empty() {
                0.0
            } else {
                v.iter().sum::<f64>() / v.len() as f64
            }
        };
        let evidence = format!(
            "the error sits where direct sun reaches the sensor: mean |relative error| {:.1} % \
             in {} sunlit readings against {:.1} % in {} others",
            100.0 * mean(&lit),
            lit.len(),
            100.0 * mean(&shade),
            shade.len()
        );
        Ok(Some(scored(ctx, next, BTreeMap::new(), evidence, None)))
    }
}
