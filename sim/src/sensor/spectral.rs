//! Per-channel spectral response: what each Bayer channel gives for a scene whose spectrum
//! differs from the one the device was calibrated under.
//!
//! The device turns a group into luminance with fixed weights, `L = cg (w · RGB) / (t g V)`
//! (`device.toml` `[response]`). That is exact only for the calibration spectrum. Under
//! another spectrum channel `c` gives `rel_c` times its calibrated signal, with
//!
//! ```text
//! rel_c = [∫ S s_c dλ / ∫ S V dλ] / [∫ S_cal s_c dλ / ∫ S_cal V dλ]
//! ```
//!
//! (`s_c` the channel's spectral sensitivity, `V` the CIE photopic curve), so the device reads
//! `L Σ w_c rel_c / Σ w_c`: the spectral mismatch a photometer's f1' summarises (CIE S 023).
//! Sensitivities, V(λ) and the daylight basis come from `shared/data/spectral` (see its README
//! for provenance); the MT9P031's own curves are not in it, so a measured Bayer CMOS camera
//! stands in for them, and tests say so.

use skylux_hps::campaign::{BayerPattern, Channel};
use std::path::Path;

/// A sampled spectral curve (any unit), linear between samples, zero outside.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    pub wavelength_nm: Vec<f64>,
    pub value: Vec<f64>,
}

impl Curve {
    /// The value at `nm`, linear between samples, 0 outside the sampled range.
    pub fn at(&self, nm: f64) -> f64 {
        let w = &self.wavelength_nm;
        if w.is_empty() || nm < w[0] || nm > w[w.len() - 1] {
            return 0.0;
        }
        let i = w.partition_point(|&x| x <= nm).clamp(1, w.len() - 1);
        let (x0, x1) = (w[i - 1], w[i]);
        let (y0, y1) = (self.value[i - 1], self.value[i]);
        if x1 == x0 {
            y0
        } else {
            y0 + (y1 - y0) * (nm - x0) / (x1 - x0)
        }
    }
}

/// ∫ a b dλ over 380-780 nm in 1 nm steps (trapezoid): the visible range of V(λ) and of the
/// camera data.
pub fn overlap(a: &Curve, b: &Curve) -> f64 {
    let f = |nm: f64| a.at(nm) * b.at(nm);
    (380..780)
        .map(|nm| 0.5 * (f(nm as f64) + f(nm as f64 + 1.0)))
        .sum()
}

/// Why spectral data could not be read.
#[derive(Debug, thiserror::Error)]
pub enum SpectralError {
    #[error("{path}: {reason}")]
    File { path: String, reason: String },
    #[error("{path}, line {line}: {reason}")]
    Line {
        path: String,
        line: usize,
        reason: String,
    },
}

/// Reads the columns `names` of a CSV whose first column is the wavelength in nm (one header
/// line; a non-numeric first line is skipped as a title).
pub fn read_columns(path: &Path, names: &[&str]) -> Result<Vec<Curve>, SpectralError> {
    let p = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| SpectralError::File {
        path: p.clone(),
        reason: e.to_string(),
    })?;
    let mut lines = text.lines().enumerate();
    let header = loop {
        let Some((_, l)) = lines.next() else {
            return Err(SpectralError::File {
                path: p,
                reason: "no header line".into(),
            });
        };
        if l.to_ascii_lowercase().starts_with("wavelength") {
            break l;
        }
    };
    let columns: Vec<&str> = header.split(',').map(str::trim).collect();
    let index: Vec<usize> = names
        .iter()
        .map(|n| {
            columns
                .iter()
                .position(|c| c == n)
                .ok_or_else(|| SpectralError::File {
                    path: p.clone(),
                    reason: format!("no column {n:?} in the header {header:?}"),
                })
        })
        .collect::<Result<_, _>>()?;
    let mut curves = vec![
        Curve {
            wavelength_nm: vec![],
            value: vec![],
        };
        names.len()
    ];
    for (n, line) in lines {
        if line.trim().is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        let number = |i: usize| -> Result<f64, SpectralError> {
            fields
                .get(i)
                .and_then(|f| f.parse::<f64>().ok())
                .filter(|v| v.is_finite())
                .ok_or_else(|| SpectralError::Line {
                    path: p.clone(),
                    line: n + 1,
                    reason: format!("column {} is not a number", i + 1),
                })
        };
        let nm = number(0)?;
        if let Some(&last) = curves[0].wavelength_nm.last() {
            if nm <= last {
                return Err(SpectralError::Line {
                    path: p.clone(),
                    line: n + 1,
                    reason: format!("wavelength {nm} nm does not increase"),
                });
            }
        }
        for (c, &i) in curves.iter_mut().zip(&index) {
            c.wavelength_nm.push(nm);
            c.value.push(number(i)?);
        }
    }
    if curves[0].wavelength_nm.len() < 2 {
        return Err(SpectralError::File {
            path: p,
            reason: "fewer than two samples".into(),
        });
    }
    Ok(curves)
}

/// CIE daylight at correlated colour temperature `cct_k` (4000-25000 K) from the S0, S1, S2
/// basis: CIE 15:2004 §3.1, chromaticity x_D from the two cubic fits, y_D = -3 x² + 2.87 x
/// - 0.275, M1 and M2 from (x_D, y_D).
pub fn cie_daylight(basis: &[Curve; 3], cct_k: f64) -> Curve {
    let t = cct_k.clamp(4000.0, 25000.0);
    let x = if t <= 7000.0 {
        -4.6070e9 / t.powi(3) + 2.9678e6 / t.powi(2) + 0.09911e3 / t + 0.244063
    } else {
        -2.0064e9 / t.powi(3) + 1.9018e6 / t.powi(2) + 0.24748e3 / t + 0.237040
    };
    let y = -3.0 * x * x + 2.870 * x - 0.275;
    let m = 0.0241 + 0.2562 * x - 0.7341 * y;
    let m1 = (-1.3515 - 1.7703 * x + 5.9114 * y) / m;
    let m2 = (0.0300 - 31.4424 * x + 30.0717 * y) / m;
    Curve {
        wavelength_nm: basis[0].wavelength_nm.clone(),
        value: (0..basis[0].value.len())
            .map(|i| basis[0].value[i] + m1 * basis[1].value[i] + m2 * basis[2].value[i])
            .collect(),
    }
}

/// The curves the response needs.
#[derive(Clone, Debug)]
pub struct SpectralData {
    /// R, G, B sensitivities.
    pub channels: [Curve; 3],
    pub photopic: Curve,
    pub daylight_basis: [Curve; 3],
}

impl SpectralData {
    /// Reads `shared/data/spectral` with the Nikon D5100 sensitivities (NPL) as the stand-in
    /// for the MT9P031's.
    pub fn load(data_dir: &Path) -> Result<Self, SpectralError> {
        let d = data_dir.join("spectral");
        let [r, g, b]: [Curve; 3] = read_columns(
            &d.join("camera_sensitivity_nikon_5100_npl.csv"),
            &["R", "G", "B"],
        )?
        .try_into()
        .expect("three columns");
        let [v]: [Curve; 1] = read_columns(&d.join("cie_1924_photopic_V.csv"), &["V"])?
            .try_into()
            .expect("one column");
        let basis: [Curve; 3] = read_columns(
            &d.join("cie_daylight_basis_S0_S1_S2.csv"),
            &["S0", "S1", "S2"],
        )?
        .try_into()
        .expect("three columns");
        Ok(Self {
            channels: [r, g, b],
            photopic: v,
            daylight_basis: basis,
        })
    }
}

/// Each channel's signal relative to the calibration spectrum, per unit luminance.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct ChannelResponse {
    /// R, G, B.
    pub relative: [f64; 3],
}

impl ChannelResponse {
    /// A spectrally grey scene, or the calibration spectrum itself: every channel exact.
    pub const GREY: Self = Self { relative: [1.0; 3] };

    /// The response to `scene` for a device calibrated under `calibration`.
    pub fn of(data: &SpectralData, scene: &Curve, calibration: &Curve) -> Self {
        let per_lux = |s: &Curve, c: &Curve| overlap(s, c) / overlap(s, &data.photopic);
        let relative = std::array::from_fn(|i| {
            per_lux(scene, &data.channels[i]) / per_lux(calibration, &data.channels[i])
        });
        Self { relative }
    }

    /// The channel gain of a sample of `channel`.
    pub fn gain(&self, channel: Channel) -> f64 {
        match channel {
            Channel::Red => self.relative[0],
            Channel::Green => self.relative[1],
            Channel::Blue => self.relative[2],
        }
    }

    /// Relative luminance error of the device's fixed weights under this response:
    /// `Σ w_c rel_c / Σ w_c - 1` (weights R, G, B; G counts once for the mean of G1 and G2).
    pub fn luminance_error(&self, weights: [f64; 3]) -> f64 {
        let sum: f64 = weights.iter().sum();
        weights
            .iter()
            .zip(&self.relative)
            .map(|(w, r)| w * r)
            .sum::<f64>()
            / sum
            - 1.0
    }

    /// Applies the response to a frame of per-group mean signals (black subtracted), sample by
    /// sample, for a raw frame whose first 2x2 block has `pattern`.
    pub fn sample_gain(&self, pattern: BayerPattern, x: usize, y: usize) -> f64 {
        self.gain(pattern.channel(x & 1, y & 1))
    }
}
