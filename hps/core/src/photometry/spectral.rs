//! Spectral curves: sampled tables read from CSV, linear interpolation, integration over the
//! visible range, CIE daylight of any correlated colour temperature and CIE illuminant A.
//!
//! The tables (V(λ), the CIE daylight basis, D65, measured camera sensitivities) are the
//! project's shared data (`shared/data/spectral`, see its README for provenance and
//! attributions: CIE tables via colour-science 0.4.7, BSD-3; the Nikon D5100 sensitivities
//! measured by the UK National Physical Laboratory; the Canon EOS 5D Mark II curves from the
//! Academy's rawtoaces).

use std::path::Path;

/// Lower end of the integration range, nm: the range of V(λ) used by ISO/CIE 19476 for f1'
/// and the range of the measured camera sensitivities.
pub const VISIBLE_MIN_NM: f64 = 380.0;
/// Upper end of the integration range, nm.
pub const VISIBLE_MAX_NM: f64 = 780.0;

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
        if w.len() == 1 {
            return self.value[0];
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

    /// A curve sampled from `f` every `step_nm` from `from_nm` to `to_nm` (both included).
    pub fn sampled(from_nm: f64, to_nm: f64, step_nm: f64, f: impl Fn(f64) -> f64) -> Self {
        let n = ((to_nm - from_nm) / step_nm).round() as usize;
        let wavelength_nm: Vec<f64> = (0..=n).map(|i| from_nm + i as f64 * step_nm).collect();
        let value = wavelength_nm.iter().map(|&nm| f(nm)).collect();
        Self {
            wavelength_nm,
            value,
        }
    }
}

/// ∫ f dλ over 380-780 nm, trapezoid rule in 1 nm steps.
pub fn integrate_visible(f: impl Fn(f64) -> f64) -> f64 {
    let (lo, hi) = (VISIBLE_MIN_NM as i32, VISIBLE_MAX_NM as i32);
    (lo..hi)
        .map(|nm| 0.5 * (f(nm as f64) + f(nm as f64 + 1.0)))
        .sum()
}

/// ∫ a b dλ over 380-780 nm in 1 nm steps (trapezoid on the linearly interpolated curves): the
/// visible range of V(λ) and of the camera data.
pub fn overlap(a: &Curve, b: &Curve) -> f64 {
    integrate_visible(|nm| a.at(nm) * b.at(nm))
}

/// Why spectral data could not be read. Every variant names the file.
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

/// The header and the data lines of a wavelength table: the first line that starts with
/// "wavelength" is the header (title lines before it are skipped).
fn table(path: &Path) -> Result<(String, Vec<(usize, String)>), SpectralError> {
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
                reason: "no header line starting with \"wavelength\"".into(),
            });
        };
        if l.trim().to_ascii_lowercase().starts_with("wavelength") {
            break l.trim().to_string();
        }
    };
    let rest = lines
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(n, l)| (n + 1, l.to_string()))
        .collect();
    Ok((header, rest))
}

/// Reads the columns `names` of a CSV whose first column is the wavelength in nm (one header
/// line starting with "wavelength"; title lines before it are skipped). Wavelengths must
/// increase; every value must be a finite number.
pub fn read_columns(path: &Path, names: &[&str]) -> Result<Vec<Curve>, SpectralError> {
    let p = path.display().to_string();
    let (header, lines) = table(path)?;
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
    for (line_number, line) in lines {
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        let number = |i: usize| -> Result<f64, SpectralError> {
            let name = columns.get(i).copied().unwrap_or("?");
            let field = fields.get(i).copied().unwrap_or("");
            field
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| SpectralError::Line {
                    path: p.clone(),
                    line: line_number,
                    reason: format!(
                        "column {} ({name}) is {field:?}, not a finite number",
                        i + 1
                    ),
                })
        };
        let nm = number(0)?;
        if let Some(&last) = curves.first().and_then(|c| c.wavelength_nm.last()) {
            if nm <= last {
                return Err(SpectralError::Line {
                    path: p.clone(),
                    line: line_number,
                    reason: format!("wavelength {nm} nm does not increase"),
                });
            }
        }
        for (c, &i) in curves.iter_mut().zip(&index) {
            c.wavelength_nm.push(nm);
            c.value.push(number(i)?);
        }
    }
    if curves.first().is_none_or(|c| c.wavelength_nm.len() < 2) {
        return Err(SpectralError::File {
            path: p,
            reason: "fewer than two samples".into(),
        });
    }
    Ok(curves)
}

/// Reads every column after the wavelength: their header names and curves.
pub fn read_value_columns(path: &Path) -> Result<(Vec<String>, Vec<Curve>), SpectralError> {
    let (header, _) = table(path)?;
    let names: Vec<String> = header
        .split(',')
        .skip(1)
        .map(|s| s.trim().to_string())
        .collect();
    if names.is_empty() {
        return Err(SpectralError::File {
            path: path.display().to_string(),
            reason: format!("the header {header:?} has no column after the wavelength"),
        });
    }
    let refs: Vec<&str> = names.iter().map(String::as_str).collect();
    let curves = read_columns(path, &refs)?;
    Ok((names, curves))
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

/// Second radiation constant c2 = hc/k, m·K (CODATA; the value ITS-90 fixes, 1.4388e-2 m·K,
/// used for the temperature of CIE illuminant A).
pub const SECOND_RADIATION_CONSTANT_M_K: f64 = 1.4388e-2;

/// Temperature of CIE illuminant A on ITS-90, K (CIE 15:2004 §3.1; ISO 11664-2:2007 / CIE S
/// 014-2: "approximately 2856 K").
pub const ILLUMINANT_A_TEMPERATURE_K: f64 = 2856.0;

/// Relative spectral power of a Planckian radiator at `temperature_k`, normalised to 100 at
/// 560 nm: `S(λ) = 100 (560/λ)^5 (e^(c2/(560 nm T)) - 1) / (e^(c2/(λ T)) - 1)`.
pub fn planck_relative(nm: f64, temperature_k: f64) -> f64 {
    let c2_nm_k = SECOND_RADIATION_CONSTANT_M_K * 1e9;
    100.0 * (560.0 / nm).powi(5) * (c2_nm_k / (560.0 * temperature_k)).exp_m1()
        / (c2_nm_k / (nm * temperature_k)).exp_m1()
}

/// CIE standard illuminant A, 300-830 nm in 1 nm steps, 100 at 560 nm: the Planckian radiator
/// at 2856 K with c2 = 1.4388e-2 m·K. CIE 15:2004 (eq. 3.1) writes it with the older pair
/// c2 = 1.435e-2 m·K and T = 2848 K; only c2/T enters, and the two agree to 1.6e-4 relative.
pub fn illuminant_a() -> Curve {
    Curve::sampled(300.0, 830.0, 1.0, |nm| {
        planck_relative(nm, ILLUMINANT_A_TEMPERATURE_K)
    })
}

/// The CIE 1924 photopic luminous efficiency V(λ) from `data_dir/spectral`.
pub fn load_photopic(data_dir: &Path) -> Result<Curve, SpectralError> {
    let path = data_dir.join("spectral/cie_1924_photopic_V.csv");
    Ok(read_columns(&path, &["V"])?.remove(0))
}

/// The tabulated CIE illuminant D65 from `data_dir/spectral`.
pub fn load_d65(data_dir: &Path) -> Result<Curve, SpectralError> {
    let path = data_dir.join("spectral/cie_illuminant_D65.csv");
    Ok(read_columns(&path, &["relative_spd"])?.remove(0))
}

/// The CIE daylight basis S0, S1, S2 from `data_dir/spectral`.
pub fn load_daylight_basis(data_dir: &Path) -> Result<[Curve; 3], SpectralError> {
    let path = data_dir.join("spectral/cie_daylight_basis_S0_S1_S2.csv");
    let [s0, s1, s2]: [Curve; 3] = read_columns(&path, &["S0", "S1", "S2"])?
        .try_into()
        .map_err(|_| SpectralError::File {
            path: path.display().to_string(),
            reason: "expected three columns".into(),
        })?;
    Ok([s0, s1, s2])
}

/// The R, G, B spectral sensitivities of a camera from a CSV with columns `R`, `G`, `B` after
/// the wavelength.
pub fn load_rgb_sensitivities(path: &Path) -> Result<[Curve; 3], SpectralError> {
    let [r, g, b]: [Curve; 3] = read_columns(path, &["R", "G", "B"])?
        .try_into()
        .map_err(|_| SpectralError::File {
            path: path.display().to_string(),
            reason: "expected three columns".into(),
        })?;
    Ok([r, g, b])
}

/// The shared data folder: `$SKYLUX_DATA_DIR` if set.
pub fn data_dir_from_env() -> Option<std::path::PathBuf> {
    std::env::var_os("SKYLUX_DATA_DIR").map(std::path::PathBuf::from)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Illuminant A by this formula against the CIE's tabulated values (CIE 15:2004 table
    /// T.1: 9.7951 at 380 nm, 100 at 560 nm, 241.675 at 780 nm, 37.8121 at 460 nm), which use c2 = 1.435e-2 and
    /// 2848 K: they agree to the 1.6e-4 relative the two constant pairs differ by, scaled by
    /// the distance from 560 nm (at most 7e-4 over 380-780 nm).
    #[test]
    fn illuminant_a_matches_the_cie_table() {
        let a = illuminant_a();
        assert!((a.at(560.0) - 100.0).abs() < 1e-9);
        for (nm, table) in [(380.0, 9.7951), (780.0, 241.675), (460.0, 37.8121)] {
            let rel = a.at(nm) / table - 1.0;
            assert!(rel.abs() < 2e-3, "{nm} nm: {} vs {table}", a.at(nm));
        }
    }

    #[test]
    fn interpolation_and_integration() {
        let c = Curve::sampled(380.0, 780.0, 5.0, |_| 2.0);
        assert_eq!(c.at(382.5), 2.0);
        assert_eq!(c.at(379.0), 0.0);
        assert!((integrate_visible(|nm| c.at(nm)) - 800.0).abs() < 1e-9);
    }
}
