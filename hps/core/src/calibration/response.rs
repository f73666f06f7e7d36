//! Response: the factor `cg` of `L = cg (w · RGB) / (t gain V(α))` from captures of a source
//! of known luminance at several exposures, using the linear region only.
//!
//! Each exposure of each capture is taken on its own. Over the groups of a central region
//! (off-axis angle at most `max_off_axis_deg`), the mean black-subtracted sample of each
//! channel must lie in the linear region, `[min_signal_dn, linear_max_fraction (valid_max −
//! black)]`, and at most 0.1 % of the region's samples may be outside the valid range;
//! otherwise the exposure is excluded (near black or near saturation) and reported. The
//! decision is per exposure, never per group: dropping single noisy groups near a threshold
//! would bias the mean. For a used exposure k the mean rate is `r_k = mean (w · RGB) / (t g
//! V(α))`, and `cg` minimises the relative errors `Σ_k (cg r_k / L_k − 1)²`:
//! `cg = Σ (r_k / L_k) / Σ (r_k / L_k)²`. The report gives each exposure's relative error
//! `cg r_k / L_k − 1`, their mean and maximum.
//!
//! Then the check of the published calibration: each source's captures are merged into
//! luminance maps with the calibrated device, and 3 x 3 groups are averaged over the frames
//! ([`uniform_source_check`]); each reading must be within ±2 % of the source's luminance,
//! and the mean absolute error at most 0.8 %.

use super::{markdown_table, CalibrationError, StepOutput};
use crate::camera::{CameraModel, DeviceConfig};
use crate::campaign::{CaptureConfig, RawFrame};
use crate::hdr::{map_capture, GroupGeometry, LuminanceMap, MapFlag};
use serde::Serialize;
use serde_json::json;
use std::path::{Path, PathBuf};

/// A capture folder of a source of known luminance.
#[derive(Clone, Debug)]
pub struct KnownSource {
    pub dir: PathBuf,
    pub luminance_cd_m2: f64,
}

/// Options of the response fit.
#[derive(Clone, Debug)]
pub struct ResponseOptions {
    /// Only groups at most this far off axis are used, degrees.
    pub max_off_axis_deg: f64,
    /// Exposures whose mean black-subtracted sample of any channel is below this are near
    /// black and excluded, DN.
    pub min_signal_dn: f64,
    /// Exposures whose mean black-subtracted sample of any channel is above this fraction of
    /// `valid_max − black` are near saturation and excluded.
    pub linear_max_fraction: f64,
}

impl Default for ResponseOptions {
    fn default() -> Self {
        Self {
            max_off_axis_deg: 30.0,
            min_signal_dn: 100.0,
            linear_max_fraction: 0.9,
        }
    }
}

/// One exposure and what the fit made of it.
#[derive(Clone, Debug, Serialize)]
pub struct ExposureResult {
    pub capture: String,
    pub file: String,
    pub exposure_us: f64,
    pub gain: f64,
    pub luminance_cd_m2: f64,
    /// Mean black-subtracted R, G, B samples over the region, DN.
    pub mean_dn: [f64; 3],
    /// `None` if used; else why it was excluded.
    pub excluded: Option<String>,
    /// Mean `(w · RGB) / (t g V)` over the region, DN/s.
    pub rate: f64,
    /// `cg rate / L − 1` with the fitted `cg` (used exposures only).
    pub relative_error: Option<f64>,
}

/// The uniform-source check: 3 x 3 groups averaged over the frames, against the truth.
#[derive(Clone, Debug, Serialize)]
pub struct UniformCheck {
    pub luminance_cd_m2: f64,
    pub frames: usize,
    /// Readings (3 x 3 blocks), each the mean of 9 groups over every frame.
    pub readings: usize,
    pub mean_abs_rel_error: f64,
    pub max_abs_rel_error: f64,
    pub mean_rel_error: f64,
    /// Every reading within ±2 % and the mean absolute error at most 0.8 %.
    pub passes: bool,
}

/// The response calibration's result.
#[derive(Clone, Debug, Serialize)]
pub struct ResponseReport {
    pub cg_before: f64,
    pub cg: f64,
    pub exposures: Vec<ExposureResult>,
    pub used: usize,
    pub mean_abs_rel_error: f64,
    pub max_abs_rel_error: f64,
    pub checks: Vec<UniformCheck>,
}

/// Which groups of a geometry lie inside the central region.
fn region(geometry: &GroupGeometry, camera: &CameraModel, max_off_axis_deg: f64) -> Vec<bool> {
    let max = max_off_axis_deg.to_radians();
    geometry
        .direction
        .iter()
        .zip(&geometry.inverse_vignetting)
        .map(|(d, &iv)| d.is_finite() && iv > 0.0 && camera.off_axis_rad(d.as_dvec3()) <= max)
        .collect()
}

/// Averages 3 x 3 blocks of groups over `maps` (same geometry) inside `inside` and compares
/// them with `truth_cd_m2`. Blocks tile the map without overlap; a block counts only if all 9
/// groups are inside and valid in every map.
pub fn uniform_source_check(
    maps: &[&LuminanceMap],
    inside: &[bool],
    truth_cd_m2: f64,
) -> Option<UniformCheck> {
    let first = maps.first()?;
    let (w, h) = (first.width, first.height);
    let mut errors = vec![];
    for by in 0..h / 3 {
        for bx in 0..w / 3 {
            let mut sum = 0.0;
            let mut ok = true;
            'block: for dy in 0..3 {
                for dx in 0..3 {
                    let i = (3 * by + dy) * w + 3 * bx + dx;
                    if !inside.get(i).copied().unwrap_or(false) {
                        ok = false;
                        break 'block;
                    }
                    for m in maps {
                        if m.width != w || m.flags[i] != MapFlag::Valid {
                            ok = false;
                            break 'block;
                        }
                        sum += m.luminance_cd_m2[i] as f64;
                    }
                }
            }
            if ok {
                errors.push(sum / (9 * maps.len()) as f64 / truth_cd_m2 - 1.0);
            }
        }
    }
    if errors.is_empty() {
        return None;
    }
    let n = errors.len() as f64;
    let mean_abs = errors.iter().map(|e| e.abs()).sum::<f64>() / n;
    let max_abs = errors.iter().fold(0.0f64, |m, e| m.max(e.abs()));
    Some(UniformCheck {
        luminance_cd_m2: truth_cd_m2,
        frames: maps.len(),
        readings: errors.len(),
        mean_abs_rel_error: mean_abs,
        max_abs_rel_error: max_abs,
        mean_rel_error: errors.iter().sum::<f64>() / n,
        passes: max_abs <= 0.02 && mean_abs <= 0.008,
    })
}

/// Fits `cg` from `sources` (see the module documentation), then runs the uniform-source
/// check per source luminance with the calibrated device. Returns the report and `device`
/// with the fitted `cg`.
pub fn calibrate_response(
    sources: &[KnownSource],
    device: &DeviceConfig,
    options: &ResponseOptions,
) -> Result<(ResponseReport, DeviceConfig), CalibrationError> {
    if sources.is_empty() {
        return Err(CalibrationError::Fit {
            input: "calibrate response".into(),
            reason: "no capture of a known source given".into(),
        });
    }
    let camera = CameraModel::new(device.clone());
    let s = &device.sensor;
    let black = s.black_level_dn;
    let hi = options.linear_max_fraction * (s.valid_max_dn - black);
    let [wr, wg, wb] = device.response.weights;
    let mut exposures = vec![];
    for source in sources {
        let toml = source.dir.join("capture.toml");
        if !(source.luminance_cd_m2.is_finite() && source.luminance_cd_m2 > 0.0) {
            return Err(CalibrationError::input(
                &source.dir,
                "luminance_cd_m2",
                format!("{} must be a positive number", source.luminance_cd_m2),
            ));
        }
        let capture = CaptureConfig::read(&toml).map_err(crate::hdr::CaptureMapError::from)?;
        let [ro, g1o, g2o, bo] = capture.bayer.offsets();
        let mut cached: Option<(GroupGeometry, Vec<bool>)> = None;
        for entry in &capture.exposure {
            let path = source.dir.join(&entry.file);
            let frame = RawFrame::read(&path).map_err(crate::hdr::CaptureMapError::from)?;
            let t_s = entry.exposure_us * 1e-6;
            if !(t_s > 0.0 && t_s.is_finite() && entry.gain > 0.0 && entry.gain.is_finite()) {
                return Err(CalibrationError::input(
                    &toml,
                    "exposure",
                    format!(
                        "{}: exposure_us {} and gain {} must be positive",
                        entry.file, entry.exposure_us, entry.gain
                    ),
                ));
            }
            // The geometry (the expensive inverse lens map) once per capture and frame size.
            if cached
                .as_ref()
                .is_none_or(|(g, _): &(GroupGeometry, Vec<bool>)| {
                    (2 * g.width, 2 * g.height) != (frame.width, frame.height)
                })
            {
                let g = GroupGeometry::new(&camera, &capture.readout, frame.width, frame.height);
                let inside = region(&g, &camera, options.max_off_axis_deg);
                cached = Some((g, inside));
            }
            let Some((geometry, inside)) = cached.as_ref() else {
                continue;
            };
            let (mut sums, mut rate_sum, mut n, mut outside) = ([0.0f64; 3], 0.0, 0usize, 0usize);
            for gy in 0..geometry.height {
                for gx in 0..geometry.width {
                    let i = gy * geometry.width + gx;
                    if !inside[i] {
                        continue;
                    }
                    let at = |(dx, dy): (usize, usize)| frame.at(2 * gx + dx, 2 * gy + dy) as f64;
                    let raw = [at(ro), at(g1o), at(g2o), at(bo)];
                    outside += raw
                        .iter()
                        .filter(|v| **v < s.valid_min_dn || **v > s.valid_max_dn)
                        .count();
                    let rgb = [
                        raw[0] - black,
                        0.5 * (raw[1] + raw[2]) - black,
                        raw[3] - black,
                    ];
                    for c in 0..3 {
                        sums[c] += rgb[c];
                    }
                    let weighted = wr * rgb[0] + wg * rgb[1] + wb * rgb[2];
                    rate_sum +=
                        weighted * geometry.inverse_vignetting[i] as f64 / (t_s * entry.gain);
                    n += 1;
                }
            }
            if n == 0 {
                return Err(CalibrationError::Fit {
                    input: path.display().to_string(),
                    reason: format!(
                        "no group of the frame lies within {} deg of the optical axis",
                        options.max_off_axis_deg
                    ),
                });
            }
            let mean_dn = sums.map(|v| v / n as f64);
            let lo_mean = mean_dn.iter().fold(f64::INFINITY, |m, v| m.min(*v));
            let hi_mean = mean_dn.iter().fold(f64::NEG_INFINITY, |m, v| m.max(*v));
            let excluded = if lo_mean < options.min_signal_dn {
                Some(format!(
                    "near black: a channel's mean {lo_mean:.1} DN < {} DN",
                    options.min_signal_dn
                ))
            } else if hi_mean > hi {
                Some(format!(
                    "near saturation: a channel's mean {hi_mean:.1} DN > {hi:.1} DN"
                ))
            } else if outside as f64 > 1e-3 * (4 * n) as f64 {
                Some(format!(
                    "{outside} of {} samples outside the valid range",
                    4 * n
                ))
            } else {
                None
            };
            exposures.push(ExposureResult {
                capture: source.dir.display().to_string(),
                file: entry.file.clone(),
                exposure_us: entry.exposure_us,
                gain: entry.gain,
                luminance_cd_m2: source.luminance_cd_m2,
                mean_dn,
                excluded,
                rate: rate_sum / n as f64,
                relative_error: None,
            });
        }
    }
    let used: Vec<&ExposureResult> = exposures.iter().filter(|e| e.excluded.is_none()).collect();
    if used.is_empty() {
        return Err(CalibrationError::Fit {
            input: sources
                .iter()
                .map(|s| s.dir.display().to_string())
                .collect::<Vec<_>>()
                .join(", "),
            reason: "no exposure lies in the linear region (every one is near black or near \
                     saturation: see the exposure list)"
                .into(),
        });
    }
    let (num, den) = used.iter().fold((0.0, 0.0), |(a, b), e| {
        let q = e.rate / e.luminance_cd_m2;
        (a + q, b + q * q)
    });
    let cg = num / den;
    if !(cg.is_finite() && cg > 0.0) {
        return Err(CalibrationError::Fit {
            input: "calibrate response".into(),
            reason: format!("the fitted cg {cg} is not a positive number (no signal?)"),
        });
    }
    for e in exposures.iter_mut().filter(|e| e.excluded.is_none()) {
        e.relative_error = Some(cg * e.rate / e.luminance_cd_m2 - 1.0);
    }
    let errs: Vec<f64> = exposures.iter().filter_map(|e| e.relative_error).collect();
    let mut out = device.clone();
    out.response.cg = cg;
    // The uniform-source check, per distinct luminance, with the calibrated device.
    let mut checks = vec![];
    let mut levels: Vec<f64> = sources.iter().map(|s| s.luminance_cd_m2).collect();
    levels.sort_by(f64::total_cmp);
    levels.dedup();
    let calibrated = CameraModel::new(out.clone());
    for level in levels {
        let mut maps = vec![];
        for s in sources.iter().filter(|s| s.luminance_cd_m2 == level) {
            maps.push(map_capture(&s.dir, &out)?);
        }
        let inside = region(&maps[0].geometry, &calibrated, options.max_off_axis_deg);
        let same: Vec<&LuminanceMap> = maps
            .iter()
            .filter(|m| m.map.width == maps[0].map.width && m.map.height == maps[0].map.height)
            .map(|m| &m.map)
            .collect();
        if let Some(c) = uniform_source_check(&same, &inside, level) {
            checks.push(c);
        }
    }
    let report = ResponseReport {
        cg_before: device.response.cg,
        cg,
        used: errs.len(),
        mean_abs_rel_error: errs.iter().map(|e| e.abs()).sum::<f64>() / errs.len() as f64,
        max_abs_rel_error: errs.iter().fold(0.0f64, |m, e| m.max(e.abs())),
        exposures,
        checks,
    };
    Ok((report, out))
}

impl ResponseReport {
    /// The report as a [`StepOutput`] with the calibrated device.
    pub fn output(&self, device: DeviceConfig) -> StepOutput {
        let mut md = String::from("# Response calibration\n\n");
        md.push_str(&format!(
            "cg = {:.6e} cd/m² s/DN (before {:.6e}), from {} exposures in the linear region: \
             mean |relative error| {:.3} %, max {:.3} %.\n\n",
            self.cg,
            self.cg_before,
            self.used,
            100.0 * self.mean_abs_rel_error,
            100.0 * self.max_abs_rel_error
        ));
        let rows: Vec<Vec<String>> = self
            .exposures
            .iter()
            .map(|e| {
                vec![
                    format!("{}/{}", e.capture, e.file),
                    format!("{}", e.exposure_us),
                    format!("{}", e.gain),
                    format!("{:.4e}", e.luminance_cd_m2),
                    format!(
                        "{:.1}, {:.1}, {:.1}",
                        e.mean_dn[0], e.mean_dn[1], e.mean_dn[2]
                    ),
                    match (&e.excluded, e.relative_error) {
                        (Some(why), _) => format!("excluded: {why}"),
                        (None, Some(err)) => format!("{:+.3} %", 100.0 * err),
                        (None, None) => String::new(),
                    },
                ]
            })
            .collect();
        md.push_str(&markdown_table(
            &[
                "frame",
                "t (µs)",
                "gain",
                "L (cd/m²)",
                "mean R, G, B (DN)",
                "relative error",
            ],
            &rows,
        ));
        if !self.checks.is_empty() {
            md.push_str("\n## Uniform-source check (3 x 3 groups averaged over the frames)\n\n");
            let rows: Vec<Vec<String>> = self
                .checks
                .iter()
                .map(|c| {
                    vec![
                        format!("{:.4e}", c.luminance_cd_m2),
                        c.frames.to_string(),
                        c.readings.to_string(),
                        format!("{:+.3} %", 100.0 * c.mean_rel_error),
                        format!("{:.3} %", 100.0 * c.mean_abs_rel_error),
                        format!("{:.3} %", 100.0 * c.max_abs_rel_error),
                        if c.passes { "yes" } else { "no" }.into(),
                    ]
                })
                .collect();
            md.push_str(&markdown_table(
                &[
                    "L (cd/m²)",
                    "captures",
                    "readings",
                    "mean error",
                    "mean |error|",
                    "max |error|",
                    "within ±2 %, mean ≤ 0.8 %",
                ],
                &rows,
            ));
        }
        StepOutput {
            name: "response",
            device,
            json: json!({ "step": "response", "report": self }),
            markdown: md,
        }
    }
}

/// Parses `DIR=LUMINANCE` (the command line's form of a known source).
pub fn parse_known_source(text: &str) -> Result<KnownSource, String> {
    let (dir, l) = text
        .rsplit_once('=')
        .ok_or_else(|| format!("{text:?}: expected CAPTURE_DIR=LUMINANCE_CD_M2"))?;
    let luminance_cd_m2: f64 = l
        .trim()
        .parse()
        .map_err(|_| format!("{text:?}: {l:?} is not a number"))?;
    if !(luminance_cd_m2.is_finite() && luminance_cd_m2 > 0.0) {
        return Err(format!("{text:?}: the luminance must be a positive number"));
    }
    Ok(KnownSource {
        dir: Path::new(dir).to_path_buf(),
        luminance_cd_m2,
    })
}
