//! What the effects' fits share: the fit set's readings and errors under a model, the
//! residual signature's points, the joint fit of the linear effects, and 1-D searches.

use super::{FitContext, Fitted, Found, Linear, LoopEffect};
use crate::validation::prediction::{
    parts, predict, LoopState, CLOCK_OFFSET_S, GLAZING_TRANSMITTANCE, GROUND_FROM_FRAMES,
    LIGHT_LEAK,
};
use crate::validation::sample::Sample;
use crate::validation::split::FitSet;
use crate::validation::terms::Terms;
use std::collections::BTreeMap;

/// A fitted candidate scored by its fit-set error, on its own `terms` if it changed them, else
/// on the context's.
pub fn scored(
    ctx: &FitContext<'_>,
    state: LoopState,
    parameters: BTreeMap<String, f64>,
    evidence: String,
    terms: Option<Vec<Terms>>,
) -> Fitted {
    let fit_error = fit_error(&state, terms.as_deref().unwrap_or(ctx.terms), ctx.fit);
    Fitted {
        state,
        parameters,
        evidence,
        fit_error,
        terms,
        captures: None,
        device: None,
        found: Found::Residual,
    }
}

/// Jointly fits the linear effects already added and `effect` ([`fit_linear`]), so an effect
/// added earlier is corrected for the one added now.
pub fn joint(ctx: &FitContext<'_>, effect: &dyn LoopEffect) -> Option<LoopState> {
    let mut with: Vec<&dyn LoopEffect> = ctx.accepted.to_vec();
    with.push(effect);
    fit_linear(ctx.state, FreeLinear::of(&with), ctx.terms, ctx.fit)
}

/// (prediction, measurement) pairs of the fit set under `state`.
pub fn pairs(state: &LoopState, terms: &[Terms], fit: &FitSet<Sample>) -> Vec<(f64, f64)> {
    let offset = state.get(CLOCK_OFFSET_S);
    let mut out = Vec::new();
    for s in fit.samples() {
        let p = predict(state, &terms[s.capture]);
        for (k, pi) in p.iter().enumerate() {
            if let Some(m) = s.measured(k, offset) {
                if m > 0.0 && pi.is_finite() {
                    out.push((*pi, m));
                }
            }
        }
    }
    out
}

/// Mean |relative error| of the fit set under `state`.
pub fn fit_error(state: &LoopState, terms: &[Terms], fit: &FitSet<Sample>) -> f64 {
    let p = pairs(state, terms, fit);
    if p.is_empty() {
        return f64::NAN;
    }
    p.iter().map(|(p, m)| (p / m - 1.0).abs()).sum::<f64>() / p.len() as f64
}

/// Which of the linear effects' parameters are free in a joint fit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FreeLinear {
    pub glazing: bool,
    pub ground: bool,
    pub leak: bool,
}

impl FreeLinear {
    /// The linear effects among `effects`.
    pub fn of(effects: &[&dyn LoopEffect]) -> Self {
        let has = |l: Linear| effects.iter().any(|e| e.linear() == Some(l));
        Self {
            glazing: has(Linear::Glazing),
            ground: has(Linear::Ground),
            leak: has(Linear::Leak),
        }
    }

    /// Whether any linear parameter is free.
    pub fn any(self) -> bool {
        self.glazing || self.ground || self.leak
    }
}

/// Jointly fits the free linear parameters (glazing τ, unseen-ground ρ through u = τ and
/// v = τρ, leak k) on the fit set, minimising Σ (prediction / measurement − 1)²; the others
/// keep their values in `state`, as does a ground reflectance the frames measured
/// ([`GROUND_FROM_FRAMES`]). Returns the new state, or `None` if the fit set cannot
/// determine them.
pub fn fit_linear(
    state: &LoopState,
    free: FreeLinear,
    terms: &[Terms],
    fit: &FitSet<Sample>,
) -> Option<LoopState> {
    let free = FreeLinear {
        ground: free.ground && state.get(GROUND_FROM_FRAMES) == 0.0,
        ..free
    };
    if !free.any() {
        return Some(state.clone());
    }
    let offset = state.get(CLOCK_OFFSET_S);
    let (tau, rho, leak) = (
        state.get(GLAZING_TRANSMITTANCE),
        state.model.ground_reflectance,
        state.get(LIGHT_LEAK),
    );
    // Columns of the design and the constant part of each reading.
    let mut rows: Vec<(Vec<f64>, f64, f64)> = Vec::new();
    for s in fit.samples() {
        let t = &terms[s.capture];
        for (k, (room, ground, outdoor)) in parts(state, t).into_iter().enumerate() {
            let Some(m) = s.measured(k, offset).filter(|m| *m > 0.0) else {
                continue;
            };
            let mut cols = Vec::new();
            let mut constant = 0.0;
            match (free.glazing, free.ground) {
                (true, true) => {
                    cols.push(room);
                    cols.push(ground);
                }
                (true, false) => cols.push(room + rho * ground),
                (false, true) => {
                    constant += tau * room;
                    cols.push(tau * ground);
                }
                (false, false) => constant += tau * (room + rho * ground),
            }
            if free.leak {
                cols.push(outdoor);
            } else {
                constant += leak * outdoor;
            }
            rows.push((cols, constant, m));
        }
    }
    let n = rows.first().map_or(0, |r| r.0.len());
    if n == 0 || rows.len() <= n {
        return None;
    }
    let mut a = vec![vec![0.0; n]; n];
    let mut b = vec![0.0; n];
    for (cols, constant, m) in &rows {
        let w = 1.0 / (m * m);
        for i in 0..n {
            b[i] += w * cols[i] * (m - constant);
            for j in 0..n {
                a[i][j] += w * cols[i] * cols[j];
            }
        }
    }
    let x = crate::numerics::linalg::solve(&a, &b)?;
    let mut next = state.clone();
    let mut i = 0;
    match (free.glazing, free.ground) {
        (true, true) => {
            let tau = x[0].clamp(0.05, 2.0);
            next.set(GLAZING_TRANSMITTANCE, tau);
            next.model.ground_reflectance = (x[1] / tau).clamp(0.0, 1.0);
            i = 2;
        }
        (true, false) => {
            next.set(GLAZING_TRANSMITTANCE, x[0].clamp(0.05, 2.0));
            i = 1;
        }
        (false, true) => {
            next.model.ground_reflectance = x[0].clamp(0.0, 1.0);
            i = 1;
        }
        (false, false) => {}
    }
    if free.leak {
        next.set(LIGHT_LEAK, x[i].max(0.0));
    }
    Some(next)
}

/// Pearson's r of a residual signature; NaN where it is undefined, so no threshold passes.
pub fn pearson_r(xy: &[(f64, f64)]) -> f64 {
    crate::numerics::pearson(xy).map_or(f64::NAN, |p| p.r)
}

/// Readings of the fit set with their capture's terms (re-matched for `state`'s clock
/// offset).
pub fn readings<'a>(
    state: &LoopState,
    terms: &'a [Terms],
    fit: &'a FitSet<Sample>,
) -> impl Iterator<Item = (&'a Terms, usize, f64)> + 'a {
    let offset = state.get(CLOCK_OFFSET_S);
    fit.samples().iter().flat_map(move |s| {
        (0..s.measured_lux.len()).filter_map(move |k| {
            s.measured(k, offset)
                .filter(|m| *m > 0.0)
                .map(|m| (&terms[s.capture], k, m))
        })
    })
}

/// (x, predicted / measured − 1) for every reading of the fit set under `state`, where
/// `x(capture, terms)` gives the variable per sensor (readings where it is not finite are left
/// out): the points whose correlation is an effect's residual signature.
pub fn residual_points(
    state: &LoopState,
    terms: &[Terms],
    fit: &FitSet<Sample>,
    mut x: impl FnMut(usize, &Terms) -> Vec<f64>,
) -> Vec<(f64, f64)> {
    let offset = state.get(CLOCK_OFFSET_S);
    let mut points = Vec::new();
    for s in fit.samples() {
        let t = &terms[s.capture];
        let p = predict(state, t);
        let xs = x(s.capture, t);
        for (k, pk) in p.iter().enumerate() {
            let Some(m) = s.measured(k, offset).filter(|m| *m > 0.0) else {
                continue;
            };
            if let Some(xk) = xs.get(k).filter(|v| v.is_finite()) {
                points.push((*xk, pk / m - 1.0));
            }
        }
    }
    points
}

/// The fit-set residuals (model / measured − 1) of the readings of the captures `select`
/// picks, under `state`.
pub fn residuals_where(
    state: &LoopState,
    terms: &[Terms],
    fit: &FitSet<Sample>,
    select: impl Fn(usize) -> bool,
) -> Vec<f64> {
    let offset = state.get(CLOCK_OFFSET_S);
    fit.samples()
        .iter()
        .filter(|s| select(s.capture))
        .flat_map(|s| {
            let p = predict(state, &terms[s.capture]);
            (0..p.len())
                .filter_map(|k| {
                    let m = s.measured(k, offset).filter(|m| *m > 0.0)?;
                    Some(p[k] / m - 1.0)
                })
                .collect::<Vec<_>>()
        })
        .collect()
}

/// An error that no candidate beats where it is not finite.
pub fn finite_or_worst(e: f64) -> f64 {
    if e.is_finite() {
        e
    } else {
        f64::INFINITY
    }
}

/// Golden-section minimum of `f` on [a, b] after a scan of `steps` + 1 points.
pub fn minimise_1d(f: &dyn Fn(f64) -> f64, a: f64, b: f64, steps: usize) -> (f64, f64) {
    let h = (b - a) / steps as f64;
    let mut best = (a, f(a));
    for i in 1..=steps {
        let x = a + h * i as f64;
        let e = f(x);
        if e < best.1 {
            best = (x, e);
        }
    }
    let (lo, hi) = ((best.0 - h).max(a), (best.0 + h).min(b));
    crate::numerics::golden_section(lo, hi, best, 30, f)
}

/// The sunlit readings' bias against the others' ([`sunlit_bias`]).
#[derive(Clone, Copy, Debug)]
pub struct SunlitBias {
    /// Mean signed relative residual of the sunlit readings (NaN: none).
    pub lit_mean: f64,
    /// Mean signed relative residual of the others (NaN: none).
    pub shade_mean: f64,
    /// Mean |relative residual| of the others (NaN: none).
    pub shade_mean_abs: f64,
    pub lit_n: usize,
    pub shade_n: usize,
}

/// The shutter overhead's signature in the fit set under `state`: the mean signed relative
/// residual of the readings where the modelled direct sun exceeds 5 % of the measured light
/// (the sunlit readings of `sun_undersampling`'s signature), the mean signed and the mean
/// |relative residual| of the others, and the count of each. An overhead over-estimates
/// what the short exposures measure, the sun first: a positive bias where the sun lights the
/// sensor, over and above the others' (a common factor biases both alike).
pub fn sunlit_bias(state: &LoopState, terms: &[Terms], fit: &FitSet<Sample>) -> SunlitBias {
    let tau = state.get(GLAZING_TRANSMITTANCE);
    let (mut lit, mut shade) = (Vec::new(), Vec::new());
    for (t, k, m) in readings(state, terms, fit) {
        let p = predict(state, t)[k];
        let direct = tau * t.sun_lux_per_dn_lux[k] * t.sun_dn_lux;
        if p > 0.0 && direct > 0.05 * m {
            lit.push(p / m - 1.0);
        } else {
            shade.push(p / m - 1.0);
        }
    }
    let mean = |v: &[f64]| {
        if v.is_empty() {
            f64::NAN
        } else {
            v.iter().sum::<f64>() / v.len() as f64
        }
    };
    let shade_abs: Vec<f64> = shade.iter().map(|r| r.abs()).collect();
    SunlitBias {
        lit_mean: mean(&lit),
        shade_mean: mean(&shade),
        shade_mean_abs: mean(&shade_abs),
        lit_n: lit.len(),
        shade_n: shade.len(),
    }
}
