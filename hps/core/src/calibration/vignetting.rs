//! Vignetting: the polynomial `V(α) = Σ a_i cos^i α` (α the off-axis angle, `V(0) = Σ a_i =
//! 1`) from frames of a uniform source.
//!
//! The capture is merged into a luminance map with vignetting switched off (`V ≡ 1`), so each
//! valid group reads `L V(α)` times a constant. The group values are smoothed in 2-D (the
//! mean of the valid groups in a (2h+1) x (2h+1) window), a polynomial of the chosen order in
//! cos α is fitted to them by linear least squares, and it is scaled so that `V(0) = 1`. The
//! report gives the RMSE and R² of the fit against the smoothed and the unsmoothed group values
//! (both relative to the on-axis value), and the fit's standard error, from the unsmoothed
//! residuals (smoothing a field and fitting it, or fitting the field, give the same
//! coefficients up to edge effects; the smoothed residuals are correlated and would understate
//! it).

use super::{markdown_table, CalibrationError, StepOutput};
use crate::camera::{CameraModel, DeviceConfig};
use crate::hdr::{map_capture, GroupGeometry, LuminanceMap, MapFlag};
use crate::numerics::linalg::{inverse_scaled, least_squares, normal_equations};
use serde::Serialize;
use serde_json::json;
use std::path::Path;

/// Options of the vignetting fit.
#[derive(Clone, Debug)]
pub struct VignettingOptions {
    /// Polynomial order (the spec's is 4: a_0..a_4).
    pub order: usize,
    /// Half-width of the smoothing window, groups (0: no smoothing).
    pub smoothing_half_width: usize,
    /// Groups farther off axis than this are not used, degrees.
    pub max_off_axis_deg: f64,
}

impl Default for VignettingOptions {
    fn default() -> Self {
        Self {
            order: 4,
            smoothing_half_width: 2,
            max_off_axis_deg: 90.0,
        }
    }
}

/// The vignetting fit and how well it explains the frames.
#[derive(Clone, Debug, Serialize)]
pub struct VignettingReport {
    pub source: String,
    /// a_0..a_n, V(0) = 1.
    pub coefficients: Vec<f64>,
    /// The device's coefficients before.
    pub before: Vec<f64>,
    pub groups_used: usize,
    pub smoothing_window_groups: usize,
    pub max_off_axis_deg_seen: f64,
    /// RMS of (value / on-axis value − V(α)) over the smoothed groups.
    pub rmse_smoothed: f64,
    pub r_squared_smoothed: f64,
    /// The same over the unsmoothed groups (includes the frames' noise).
    pub rmse_groups: f64,
    pub r_squared_groups: f64,
    /// (α in degrees, fitted V, its standard error, the device's V before).
    pub table: Vec<(f64, f64, f64, f64)>,
}

/// One group's sample: cos α and the relative value.
struct Sample {
    cos_alpha: f64,
    raw: f64,
    smoothed: f64,
}

/// Fits the vignetting polynomial to a luminance map of a uniform source made with `V ≡ 1`.
pub fn fit_vignetting_map(
    map: &LuminanceMap,
    geometry: &GroupGeometry,
    camera: &CameraModel,
    options: &VignettingOptions,
    source: &str,
) -> Result<VignettingReport, CalibrationError> {
    let fit_error = |reason: String| CalibrationError::Fit {
        input: source.into(),
        reason,
    };
    if options.order == 0 || options.order > 8 {
        return Err(fit_error(format!(
            "polynomial order {} is outside 1..=8",
            options.order
        )));
    }
    let (w, h) = (map.width, map.height);
    let usable: Vec<Option<f64>> = (0..w * h)
        .map(|i| {
            let l = map.luminance_cd_m2[i] as f64;
            let d = geometry.direction[i];
            (map.flags[i] == MapFlag::Valid && l.is_finite() && l > 0.0 && d.is_finite())
                .then_some(l)
        })
        .collect();
    let hw = options.smoothing_half_width as isize;
    let max_alpha = options.max_off_axis_deg.to_radians();
    let mut samples = vec![];
    let mut alpha_seen = 0.0f64;
    for gy in 0..h {
        for gx in 0..w {
            let i = gy * w + gx;
            let Some(raw) = usable[i] else { continue };
            let alpha = camera.off_axis_rad(geometry.direction[i].as_dvec3());
            if alpha > max_alpha {
                continue;
            }
            let (mut sum, mut n) = (0.0, 0usize);
            for dy in -hw..=hw {
                for dx in -hw..=hw {
                    let (x, y) = (gx as isize + dx, gy as isize + dy);
                    if x < 0 || y < 0 || x >= w as isize || y >= h as isize {
                        continue;
                    }
                    if let Some(v) = usable[y as usize * w + x as usize] {
                        sum += v;
                        n += 1;
                    }
                }
            }
            let window = (2 * hw + 1).pow(2) as usize;
            // Half the window at least: groups at the edge of the valid area stay unbiased
            // enough and the border is not over-weighted.
            if 2 * n < window {
                continue;
            }
            alpha_seen = alpha_seen.max(alpha);
            samples.push(Sample {
                cos_alpha: alpha.cos(),
                raw,
                smoothed: sum / n as f64,
            });
        }
    }
    let n_coef = options.order + 1;
    if samples.len() < 4 * n_coef {
        return Err(fit_error(format!(
            "{} usable groups (valid, inside {} deg, with a half-full smoothing window): at \
             least {} are needed",
            samples.len(),
            options.max_off_axis_deg,
            4 * n_coef
        )));
    }
    let powers = |c: f64| -> Vec<f64> { (0..n_coef).map(|k| c.powi(k as i32)).collect() };
    let rows: Vec<Vec<f64>> = samples.iter().map(|s| powers(s.cos_alpha)).collect();
    let ys: Vec<f64> = samples.iter().map(|s| s.smoothed).collect();
    let b = least_squares(&rows, &ys).ok_or_else(|| {
        fit_error(format!(
            "the groups span too little of the field (off-axis up to {:.1} deg) to fit an \
             order-{} polynomial in cos α",
            alpha_seen.to_degrees(),
            options.order
        ))
    })?;
    let on_axis: f64 = b.iter().sum();
    if !(on_axis > 0.0 && on_axis.is_finite()) {
        return Err(fit_error(format!(
            "the fitted on-axis value {on_axis} is not positive"
        )));
    }
    let a: Vec<f64> = b.iter().map(|v| v / on_axis).collect();
    let eval = |c: f64| a.iter().rev().fold(0.0, |acc, k| acc * c + k);
    let stats = |value: &dyn Fn(&Sample) -> f64| {
        let (mut ss_res, mut sum, mut sum2) = (0.0, 0.0, 0.0);
        for s in &samples {
            let y = value(s) / on_axis;
            ss_res += (y - eval(s.cos_alpha)).powi(2);
            sum += y;
            sum2 += y * y;
        }
        let n = samples.len() as f64;
        let ss_tot = sum2 - sum * sum / n;
        ((ss_res / n).sqrt(), 1.0 - ss_res / ss_tot.max(1e-300))
    };
    let (rmse_smoothed, r_squared_smoothed) = stats(&|s| s.smoothed);
    let (rmse_groups, r_squared_groups) = stats(&|s| s.raw);
    // Standard error of V(α) = p(c) / p(1) from the unsmoothed residuals (delta method).
    let (ata, _) = normal_equations(&rows, &ys);
    let sigma2 = rmse_groups.powi(2) * on_axis * on_axis * samples.len() as f64
        / (samples.len() - n_coef) as f64;
    let cov = inverse_scaled(&ata);
    let se = |c: f64| -> f64 {
        let Some(cov) = &cov else { return f64::NAN };
        let g = eval(c);
        let grad: Vec<f64> = (0..n_coef)
            .map(|k| (c.powi(k as i32) - g) / on_axis)
            .collect();
        let mut v = 0.0;
        for i in 0..n_coef {
            for j in 0..n_coef {
                v += grad[i] * cov[i][j] * grad[j];
            }
        }
        (sigma2 * v).max(0.0).sqrt()
    };
    let before = camera.config.lens.vignetting.clone();
    let table = (0..=18)
        .map(|k| 5.0 * k as f64)
        .filter(|deg| deg.to_radians() <= alpha_seen + 1e-9)
        .map(|deg| {
            let c = f64::to_radians(deg).cos();
            (deg, eval(c), se(c), camera.vignetting(deg.to_radians()))
        })
        .collect();
    Ok(VignettingReport {
        source: source.into(),
        coefficients: a,
        before,
        groups_used: samples.len(),
        smoothing_window_groups: 2 * options.smoothing_half_width + 1,
        max_off_axis_deg_seen: alpha_seen.to_degrees(),
        rmse_smoothed,
        r_squared_smoothed,
        rmse_groups,
        r_squared_groups,
        table,
    })
}

/// Merges the capture folder `dir` (a uniform source) with vignetting switched off and fits
/// the polynomial. Returns the report and `device` with the fitted coefficients.
pub fn calibrate_vignetting(
    dir: &Path,
    device: &DeviceConfig,
    options: &VignettingOptions,
) -> Result<(VignettingReport, DeviceConfig), CalibrationError> {
    let mut flat = device.clone();
    flat.lens.vignetting = vec![1.0];
    let merged = map_capture(dir, &flat)?;
    let camera = CameraModel::new(device.clone());
    let report = fit_vignetting_map(
        &merged.map,
        &merged.geometry,
        &camera,
        options,
        &dir.display().to_string(),
    )?;
    let mut out = device.clone();
    out.lens.vignetting = report.coefficients.clone();
    Ok((report, out))
}

impl VignettingReport {
    /// The report as a [`StepOutput`] with the calibrated device.
    pub fn output(&self, device: DeviceConfig) -> StepOutput {
        let mut md = String::from("# Vignetting calibration\n\n");
        md.push_str(&format!(
            "Uniform source: `{}`; {} groups up to {:.1} deg off axis, smoothed over {} x {} \
             groups; V(α) = Σ a_i cos^i α, order {}, V(0) = 1.\n\n",
            self.source,
            self.groups_used,
            self.max_off_axis_deg_seen,
            self.smoothing_window_groups,
            self.smoothing_window_groups,
            self.coefficients.len() - 1
        ));
        md.push_str(&format!(
            "- coefficients a_0..a_{}: {}\n- smoothed: RMSE {:.3} %, R² {:.4}\n- unsmoothed \
             groups: RMSE {:.3} %, R² {:.4}\n\n",
            self.coefficients.len() - 1,
            self.coefficients
                .iter()
                .map(|v| format!("{v:.6}"))
                .collect::<Vec<_>>()
                .join(", "),
            100.0 * self.rmse_smoothed,
            self.r_squared_smoothed,
            100.0 * self.rmse_groups,
            self.r_squared_groups
        ));
        let rows: Vec<Vec<String>> = self
            .table
            .iter()
            .map(|(deg, v, se, before)| {
                vec![
                    format!("{deg:.0}"),
                    format!("{v:.5}"),
                    format!("{se:.2e}"),
                    format!("{before:.5}"),
                ]
            })
            .collect();
        md.push_str(&markdown_table(
            &["α (deg)", "V fitted", "standard error", "V before"],
            &rows,
        ));
        StepOutput {
            name: "vignetting",
            device,
            json: json!({ "step": "vignetting", "report": self }),
            markdown: md,
        }
    }
}
