//! Camera calibration (issue 4, item 4): each step fits part of `device.toml` from
//! measurements and reports how well it fits.
//!
//! - [`spectral`]: f1' of the camera's spectral match to V(λ) (ISO/CIE 19476, illuminant A
//!   normalisation, and the D65 variant), the RGB weights that minimise it, and the choice of
//!   a filter from a set of transmittance curves;
//! - [`vignetting`]: the polynomial V(α) = Σ a_i cos^i α from frames of a uniform source;
//! - [`response`]: the response `cg` from captures of a source of known luminance, linear
//!   region only, and the uniform-source check of the published calibration;
//! - [`geometry`]: focal length, principal point, k1..k4 and orientation from point
//!   correspondences (image point and known direction), by Levenberg-Marquardt.
//!
//! Every step returns a report (serialisable to JSON, and as Markdown) and the updated
//! [`DeviceConfig`]; [`write_outputs`] writes `device.toml` and the report atomically.

pub mod geometry;
pub mod response;
pub mod spectral;
pub mod vignetting;

use crate::camera::{DeviceConfig, DeviceError};
use crate::hdr::CaptureMapError;
use crate::output::{write_atomic, WriteError};
use crate::photometry::SpectralError;
use std::path::{Path, PathBuf};

/// Why a calibration step failed. Every variant names the file (or the input) and the field.
#[derive(Debug, thiserror::Error)]
pub enum CalibrationError {
    #[error(transparent)]
    Spectral(#[from] SpectralError),
    #[error(transparent)]
    Device(#[from] DeviceError),
    #[error(transparent)]
    Capture(#[from] CaptureMapError),
    #[error(transparent)]
    Write(#[from] WriteError),
    #[error("{path}: cannot serialise the report: {message}")]
    Json { path: PathBuf, message: String },
    /// A measurement file has a missing column, a value that is not a finite number, or too
    /// few usable rows.
    #[error("{path}: {field}: {reason}")]
    Input {
        path: PathBuf,
        field: String,
        reason: String,
    },
    /// The measurements do not determine the fit.
    #[error("{input}: {reason}")]
    Fit { input: String, reason: String },
}

impl CalibrationError {
    pub(crate) fn input(path: &Path, field: impl Into<String>, reason: impl Into<String>) -> Self {
        Self::Input {
            path: path.into(),
            field: field.into(),
            reason: reason.into(),
        }
    }
}

/// What one step writes.
pub struct StepOutput {
    /// The step's name: the report files are `<name>_report.json` and `<name>_report.md`.
    pub name: &'static str,
    pub device: DeviceConfig,
    pub json: serde_json::Value,
    pub markdown: String,
}

/// Writes `out_dir/device.toml` (through [`DeviceConfig::write`], which validates it, to a
/// temporary file renamed into place) and the step's report as JSON and Markdown (atomic
/// writes). Returns the paths written.
pub fn write_outputs(out_dir: &Path, step: &StepOutput) -> Result<Vec<PathBuf>, CalibrationError> {
    std::fs::create_dir_all(out_dir).map_err(|source| WriteError::new(out_dir, source))?;
    let device_path = out_dir.join("device.toml");
    let tmp = out_dir.join("device.toml.tmp");
    step.device.write(&tmp)?;
    std::fs::rename(&tmp, &device_path).map_err(|source| WriteError::new(&device_path, source))?;
    let json_path = out_dir.join(format!("{}_report.json", step.name));
    let text = serde_json::to_string_pretty(&step.json).map_err(|e| CalibrationError::Json {
        path: json_path.clone(),
        message: e.to_string(),
    })?;
    write_atomic(&json_path, text.as_bytes())?;
    let md_path = out_dir.join(format!("{}_report.md", step.name));
    write_atomic(&md_path, step.markdown.as_bytes())?;
    Ok(vec![device_path, json_path, md_path])
}

/// Reads a CSV with a header line into rows of named numeric fields: every column in
/// `required` must exist, and every value of those columns must be a finite number.
pub(crate) fn read_numeric_csv(
    path: &Path,
    required: &[&str],
) -> Result<Vec<Vec<f64>>, CalibrationError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CalibrationError::input(path, "file", e.to_string()))?;
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty() && !l.trim_start().starts_with('#'));
    let Some((_, header)) = lines.next() else {
        return Err(CalibrationError::input(path, "header", "the file is empty"));
    };
    let columns: Vec<&str> = header.split(',').map(str::trim).collect();
    let index: Vec<usize> = required
        .iter()
        .map(|name| {
            columns.iter().position(|c| c == name).ok_or_else(|| {
                CalibrationError::input(
                    path,
                    *name,
                    format!("missing column (the header is {header:?})"),
                )
            })
        })
        .collect::<Result<_, _>>()?;
    let mut rows = vec![];
    for (n, line) in lines {
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        let row = index
            .iter()
            .zip(required)
            .map(|(&i, name)| {
                let text = fields.get(i).copied().unwrap_or("");
                text.parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .ok_or_else(|| {
                        CalibrationError::input(
                            path,
                            *name,
                            format!("line {}: {text:?} is not a finite number", n + 1),
                        )
                    })
            })
            .collect::<Result<Vec<f64>, _>>()?;
        rows.push(row);
    }
    Ok(rows)
}

/// A Markdown table from a header and rows of cells.
pub(crate) fn markdown_table(header: &[&str], rows: &[Vec<String>]) -> String {
    let mut s = format!("| {} |\n|", header.join(" | "));
    for _ in header {
        s.push_str("---|");
    }
    s.push('\n');
    for r in rows {
        s.push_str(&format!("| {} |\n", r.join(" | ")));
    }
    s
}
