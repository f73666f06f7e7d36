//! Spectral calibration: how well the device's weighted RGB sum matches V(λ), and the weights
//! and filter that match it best.
//!
//! The device's relative spectral responsivity is `s(λ) = T(λ) Σ w_c s_c(λ)` (`s_c` the
//! channel sensitivities, `T` an optional filter's transmittance). Its general V(λ) mismatch
//! index (ISO/CIE 19476:2014, successor of CIE 69:1987; the formula of hardware-facts.md §6):
//!
//! ```text
//! s*(λ) = s(λ) ∫ S_A V dλ / ∫ S_A s dλ          (normalised with CIE illuminant A)
//! f1'   = ∫ |s*(λ) - V(λ)| dλ / ∫ V dλ           (380-780 nm)
//! ```
//!
//! The D65 variant (used by the seed paper for a daylight device) normalises with D65 instead
//! of illuminant A. Integrals are 1 nm trapezoids on linearly interpolated curves
//! ([`crate::photometry::spectral::integrate_visible`]).
//!
//! The weights are fitted in two stages: non-negative least squares of `Σ w_c T s_c ≈ V` on
//! the 1 nm grid (the linear problem the brief names), then a Nelder-Mead refinement of the
//! weight ratios that minimises f1' itself (an L1 objective; f1' is independent of the
//! weights' overall scale). Both results are reported. The weights written to `device.toml`
//! are scaled to sum to 1; `cg` must then be recalibrated ([`super::response`]).

use super::{markdown_table, CalibrationError, StepOutput};
use crate::camera::DeviceConfig;
use crate::numerics::linalg::nnls;
use crate::photometry::spectral::{integrate_visible, read_value_columns, Curve};
use serde::Serialize;
use serde_json::json;
use std::path::{Path, PathBuf};

/// The curves a spectral calibration needs.
#[derive(Clone, Debug)]
pub struct SpectralInputs {
    /// R, G, B relative spectral sensitivities of the camera.
    pub channels: [Curve; 3],
    /// Where the sensitivities came from (for the report).
    pub channels_source: String,
    /// CIE 1924 photopic V(λ).
    pub photopic: Curve,
    /// CIE illuminant A (normalisation of f1' by ISO/CIE 19476).
    pub illuminant_a: Curve,
    /// CIE illuminant D65 (the daylight variant).
    pub d65: Curve,
}

/// f1' of a relative spectral responsivity `s(λ)`, normalised with `illuminant`; a fraction
/// (0.05 is 5 %).
pub fn f1_prime(s: &dyn Fn(f64) -> f64, photopic: &Curve, illuminant: &Curve) -> f64 {
    let sv = integrate_visible(|nm| illuminant.at(nm) * photopic.at(nm));
    let ss = integrate_visible(|nm| illuminant.at(nm) * s(nm));
    let k = sv / ss;
    integrate_visible(|nm| (k * s(nm) - photopic.at(nm)).abs())
        / integrate_visible(|nm| photopic.at(nm))
}

/// The responsivity of weights `w` on `channels` behind an optional filter.
fn responsivity<'a>(
    channels: &'a [Curve; 3],
    filter: Option<&'a Curve>,
    w: [f64; 3],
) -> impl Fn(f64) -> f64 + 'a {
    move |nm| {
        let t = filter.map_or(1.0, |f| f.at(nm));
        t * (w[0] * channels[0].at(nm) + w[1] * channels[1].at(nm) + w[2] * channels[2].at(nm))
    }
}

/// f1' under illuminant A and under D65 for weights `w` (behind `filter`).
pub fn f1_pair(inputs: &SpectralInputs, filter: Option<&Curve>, w: [f64; 3]) -> (f64, f64) {
    let s = responsivity(&inputs.channels, filter, w);
    (
        f1_prime(&s, &inputs.photopic, &inputs.illuminant_a),
        f1_prime(&s, &inputs.photopic, &inputs.d65),
    )
}

/// Non-negative least-squares weights of `Σ w_c T s_c ≈ V` on the 1 nm grid 380-780 nm.
pub fn nnls_weights(inputs: &SpectralInputs, filter: Option<&Curve>) -> Option<[f64; 3]> {
    let grid: Vec<f64> = (380..=780).map(f64::from).collect();
    let rows: Vec<Vec<f64>> = grid
        .iter()
        .map(|&nm| {
            let t = filter.map_or(1.0, |f| f.at(nm));
            inputs.channels.iter().map(|c| t * c.at(nm)).collect()
        })
        .collect();
    let y: Vec<f64> = grid.iter().map(|&nm| inputs.photopic.at(nm)).collect();
    let w = nnls(&rows, &y)?;
    (w.iter().sum::<f64>() > 0.0).then(|| [w[0], w[1], w[2]])
}

/// Minimises `f(u, v)` by Nelder-Mead from `start` with initial step `step`.
fn nelder_mead(f: &dyn Fn([f64; 2]) -> f64, start: [f64; 2], step: [f64; 2]) -> [f64; 2] {
    let mut simplex = [
        start,
        [start[0] + step[0], start[1]],
        [start[0], start[1] + step[1]],
    ];
    let mut values = simplex.map(f);
    for _ in 0..400 {
        let mut order = [0, 1, 2];
        order.sort_by(|&a, &b| values[a].total_cmp(&values[b]));
        let [b, m, w] = order;
        if (values[w] - values[b]).abs() <= 1e-12 * values[b].abs().max(1e-12) {
            break;
        }
        let centroid = [
            0.5 * (simplex[b][0] + simplex[m][0]),
            0.5 * (simplex[b][1] + simplex[m][1]),
        ];
        let along = |t: f64| {
            [
                centroid[0] + t * (simplex[w][0] - centroid[0]),
                centroid[1] + t * (simplex[w][1] - centroid[1]),
            ]
        };
        let reflected = along(-1.0);
        let fr = f(reflected);
        if fr < values[b] {
            let expanded = along(-2.0);
            let fe = f(expanded);
            (simplex[w], values[w]) = if fe < fr {
                (expanded, fe)
            } else {
                (reflected, fr)
            };
        } else if fr < values[m] {
            (simplex[w], values[w]) = (reflected, fr);
        } else {
            let contracted = along(0.5);
            let fc = f(contracted);
            if fc < values[w] {
                (simplex[w], values[w]) = (contracted, fc);
            } else {
                for i in [m, w] {
                    simplex[i] = [
                        0.5 * (simplex[i][0] + simplex[b][0]),
                        0.5 * (simplex[i][1] + simplex[b][1]),
                    ];
                    values[i] = f(simplex[i]);
                }
            }
        }
    }
    let best = (0..3)
        .min_by(|&a, &b| values[a].total_cmp(&values[b]))
        .unwrap_or(0);
    simplex[best]
}

/// Weights that minimise f1' (illuminant A) behind `filter`, started from the NNLS weights:
/// the ratios `w_r / w_g` and `w_b / w_g` are refined by Nelder-Mead (kept non-negative).
/// Returns the NNLS and the refined weights, each scaled to sum to 1.
pub fn fit_weights(
    inputs: &SpectralInputs,
    filter: Option<&Curve>,
) -> Option<([f64; 3], [f64; 3])> {
    let normalise = |w: [f64; 3]| {
        let s: f64 = w.iter().sum();
        w.map(|v| v / s)
    };
    let start = normalise(nnls_weights(inputs, filter)?);
    if start[1] <= 0.0 {
        return Some((start, start));
    }
    // Ratios below 1e-9 are zero (the simplex only approaches a bound).
    let clean = |v: f64| if v.abs() < 1e-9 { 0.0 } else { v.abs() };
    let weights = |p: [f64; 2]| normalise([clean(p[0]), 1.0, clean(p[1])]);
    let objective = |p: [f64; 2]| f1_pair(inputs, filter, weights(p)).0;
    let p0 = [start[0] / start[1], start[2] / start[1]];
    let p = nelder_mead(&objective, p0, [0.05 + 0.2 * p0[0], 0.05 + 0.2 * p0[1]]);
    let refined = weights(p);
    // Keep the NNLS weights if the refinement did not help (it starts there, so it cannot
    // be worse unless the simplex left the start's basin).
    if objective(p) <= f1_pair(inputs, filter, start).0 {
        Some((start, refined))
    } else {
        Some((start, start))
    }
}

/// One row of the report: a set of weights, behind a filter or not, and its f1'.
#[derive(Clone, Debug, Serialize)]
pub struct WeightsResult {
    pub label: String,
    pub weights: [f64; 3],
    /// f1' with illuminant A normalisation (ISO/CIE 19476), fraction.
    pub f1_prime_a: f64,
    /// f1' with D65 normalisation, fraction.
    pub f1_prime_d65: f64,
}

/// A candidate filter with its refitted weights.
#[derive(Clone, Debug, Serialize)]
pub struct FilterResult {
    /// File and column.
    pub name: String,
    pub nnls: WeightsResult,
    pub refined: WeightsResult,
}

/// The spectral calibration's result.
#[derive(Clone, Debug, Serialize)]
pub struct SpectralReport {
    pub sensitivities: String,
    pub illuminant_a: String,
    /// The input device's weights, no filter.
    pub before: WeightsResult,
    /// The green channel alone, no filter.
    pub green_only: WeightsResult,
    /// Fitted weights without a filter: NNLS, then refined to minimise f1'.
    pub fitted_nnls: WeightsResult,
    pub fitted: WeightsResult,
    /// Every candidate filter, best first.
    pub filters: Vec<FilterResult>,
    /// The filter chosen (lowest f1' with refitted weights, if it beats no filter).
    pub chosen_filter: Option<String>,
    /// What goes into device.toml.
    pub after: WeightsResult,
}

fn result(
    inputs: &SpectralInputs,
    filter: Option<&Curve>,
    label: &str,
    w: [f64; 3],
) -> WeightsResult {
    let (a, d) = f1_pair(inputs, filter, w);
    WeightsResult {
        label: label.into(),
        weights: w,
        f1_prime_a: a,
        f1_prime_d65: d,
    }
}

/// Reads every transmittance curve in `path`: a CSV (every column after the wavelength is one
/// filter), or a folder of them (`*.csv`, in name order). Transmittances must lie in [0, 1]
/// (a value above 1.5 is taken as a percentage and scaled by 1/100 for the whole column).
pub fn read_filters(path: &Path) -> Result<Vec<(String, Curve)>, CalibrationError> {
    let files: Vec<PathBuf> = if path.is_dir() {
        let mut v: Vec<PathBuf> = std::fs::read_dir(path)
            .map_err(|e| CalibrationError::input(path, "folder", e.to_string()))?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x.eq_ignore_ascii_case("csv")))
            .collect();
        v.sort();
        if v.is_empty() {
            return Err(CalibrationError::input(
                path,
                "folder",
                "no *.csv transmittance files",
            ));
        }
        v
    } else {
        vec![path.to_path_buf()]
    };
    let mut filters = vec![];
    for f in files {
        let (names, curves) = read_value_columns(&f)?;
        let stem = f
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        for (name, mut curve) in names.into_iter().zip(curves) {
            if curve.value.iter().any(|v| *v < 0.0) {
                return Err(CalibrationError::input(&f, name, "negative transmittance"));
            }
            let max = curve.value.iter().fold(0.0f64, |m, v| m.max(*v));
            if max > 1.5 {
                if max > 100.0 + 1e-9 {
                    return Err(CalibrationError::input(
                        &f,
                        name,
                        format!("transmittance {max} is above 100 %"),
                    ));
                }
                curve.value.iter_mut().for_each(|v| *v /= 100.0);
            }
            filters.push((format!("{stem}:{name}"), curve));
        }
    }
    Ok(filters)
}

/// Runs the spectral calibration: f1' before, fitted weights, and the best filter of
/// `filters` (each with refitted weights). Returns the report and the device with the new
/// weights.
pub fn calibrate_spectral(
    inputs: &SpectralInputs,
    filters: &[(String, Curve)],
    device: &DeviceConfig,
) -> Result<(SpectralReport, DeviceConfig), CalibrationError> {
    let no_fit = |what: &str| CalibrationError::Fit {
        input: inputs.channels_source.clone(),
        reason: format!("{what}: the sensitivities do not overlap V(λ) (all weights 0)"),
    };
    let before = result(inputs, None, "device weights", device.response.weights);
    let green_only = result(inputs, None, "green channel alone", [0.0, 1.0, 0.0]);
    let (nnls_w, refined_w) = fit_weights(inputs, None).ok_or_else(|| no_fit("no filter"))?;
    let fitted_nnls = result(inputs, None, "NNLS fit", nnls_w);
    let fitted = result(inputs, None, "min-f1' fit", refined_w);
    let mut filter_results = vec![];
    for (name, curve) in filters {
        let (n, r) = fit_weights(inputs, Some(curve)).ok_or_else(|| no_fit(name))?;
        filter_results.push(FilterResult {
            name: name.clone(),
            nnls: result(inputs, Some(curve), "NNLS fit", n),
            refined: result(inputs, Some(curve), "min-f1' fit", r),
        });
    }
    filter_results.sort_by(|a, b| a.refined.f1_prime_a.total_cmp(&b.refined.f1_prime_a));
    let (chosen_filter, after) = match filter_results.first() {
        Some(best) if best.refined.f1_prime_a < fitted.f1_prime_a => (
            Some(best.name.clone()),
            WeightsResult {
                label: format!("min-f1' fit behind {}", best.name),
                ..best.refined.clone()
            },
        ),
        _ => (None, fitted.clone()),
    };
    let mut out = device.clone();
    out.response.weights = after.weights;
    let report = SpectralReport {
        sensitivities: inputs.channels_source.clone(),
        illuminant_a: "Planck 2856 K, c2 = 1.4388e-2 m K (CIE 15:2004 §3.1)".into(),
        before,
        green_only,
        fitted_nnls,
        fitted,
        filters: filter_results,
        chosen_filter,
        after,
    };
    Ok((report, out))
}

fn pct(v: f64) -> String {
    format!("{:.2} %", 100.0 * v)
}

fn row(r: &WeightsResult) -> Vec<String> {
    vec![
        r.label.clone(),
        format!(
            "{:.4}, {:.4}, {:.4}",
            r.weights[0], r.weights[1], r.weights[2]
        ),
        pct(r.f1_prime_a),
        pct(r.f1_prime_d65),
    ]
}

impl SpectralReport {
    /// The report as a [`StepOutput`] (JSON and Markdown) with the calibrated device.
    pub fn output(&self, device: DeviceConfig) -> StepOutput {
        let mut md = String::from("# Spectral calibration\n\n");
        md.push_str(&format!(
            "Sensitivities: `{}`. f1' by ISO/CIE 19476 (illuminant A normalisation; illuminant A \
             = {}) and the D65 variant, 380-780 nm, 1 nm trapezoid.\n\n",
            self.sensitivities, self.illuminant_a
        ));
        let header = ["weights", "w_r, w_g, w_b", "f1' (A)", "f1' (D65)"];
        md.push_str(&markdown_table(
            &header,
            &[
                row(&self.before),
                row(&self.green_only),
                row(&self.fitted_nnls),
                row(&self.fitted),
            ],
        ));
        if !self.filters.is_empty() {
            md.push_str("\n## Filters (weights refitted behind each)\n\n");
            let rows: Vec<Vec<String>> = self
                .filters
                .iter()
                .map(|f| {
                    let mut r = row(&f.refined);
                    r[0] = f.name.clone();
                    r.push(pct(f.nnls.f1_prime_a));
                    r
                })
                .collect();
            md.push_str(&markdown_table(
                &[
                    "filter",
                    "w_r, w_g, w_b",
                    "f1' (A)",
                    "f1' (D65)",
                    "f1' (A), NNLS weights",
                ],
                &rows,
            ));
        }
        md.push_str(&format!(
            "\n**Written to device.toml**: {} (weights {:.4}, {:.4}, {:.4}): f1' {} (A), {} \
             (D65); before {} (A). The weights are scaled to sum to 1: recalibrate `cg` \
             (`skylux calibrate response`) after changing them.\n",
            self.after.label,
            self.after.weights[0],
            self.after.weights[1],
            self.after.weights[2],
            pct(self.after.f1_prime_a),
            pct(self.after.f1_prime_d65),
            pct(self.before.f1_prime_a),
        ));
        StepOutput {
            name: "spectral",
            device,
            json: json!({ "step": "spectral", "report": self }),
            markdown: md,
        }
    }
}
