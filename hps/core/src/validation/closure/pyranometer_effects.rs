//! The effect library of the pyranometer closure: faults of the reference instruments that
//! leave a signature in the closure residual r = GHI − (DNI cos Z + DHI).
//!
//! Each effect is a parametric model of the residual it causes, linear in its coefficients
//! (exactly, or to first order in a small fault), so that any set of effects is fitted jointly
//! by least squares. [`PyranometerEffect::columns`] gives the regressors of one sample,
//! [`PyranometerEffect::parameters`] turns the fitted coefficients into physical parameters.
//! Two faults with one signature cannot be told apart by the closure alone; where that is so
//! the doc comment says which.

use super::sample::ClosureSample;
use std::collections::BTreeMap;

/// A fault of the reference instruments, as seen through the closure.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum PyranometerEffect {
    /// Thermopile thermal offset: GHI and DHI read `a_ghi`, `a_dhi` W/m² off (negative at
    /// night, from net infrared loss of the dome). r = a_ghi − a_dhi: a constant.
    ThermalOffset,
    /// Timestamp convention or clock error: the values belong to the sun at `t + δ`.
    /// r = DNI (cos Z(t + δ) − cos Z(t)) ≈ δ · DNI · d(cos Z)/dt: changes sign at solar noon.
    TimestampShift,
    /// Cosine response of the GHI pyranometer: it reads the beam as
    /// DNI cos Z (1 + c (1 − cos Z)), so r = c · DNI cos Z (1 − cos Z); c is the relative error
    /// extrapolated to the horizon. Symmetric about solar noon.
    CosineResponse,
    /// GHI pyranometer not level (or an azimuthal response): its normal leans by β towards
    /// azimuth γ, so cos θ = cos β cos Z + sin β sin Z cos(A − γ) and, to first order in β,
    /// r = DNI sin Z (p cos A + q sin A) with p = sin β cos γ, q = sin β sin γ. Antisymmetric
    /// in azimuth about γ.
    LevelTilt,
    /// DNI calibration scale: DNI reads (1 + k) times the truth, r = −k/(1 + k) · DNI cos Z.
    /// A constant fraction of the beam reaching the shaded DHI pyranometer has the same
    /// signature: the closure cannot tell them apart.
    DniScale,
    /// Tracker misalignment that drifts through the day (shading ball uncovering the DHI
    /// pyranometer, or the pyrheliometer missing the sun, more and more away from the time the
    /// tracker was aligned): r = m · DNI cos Z · h, with h the hour angle in hours (positive
    /// after solar noon). The constant part of such a fault is [`Self::DniScale`].
    TrackerDrift,
    /// DHI scale: the shading ball also hides the circumsolar sky, or a DHI calibration error;
    /// DHI reads (1 + k) times the truth, r = −k/(1 + k) · DHI.
    DhiScale,
}

/// A per-sample variable to plot the residual against.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Variable {
    ZenithDeg,
    AzimuthDeg,
    HourAngleDeg,
    BeamWm2,
    DhiWm2,
}

impl Variable {
    pub fn value(self, s: &ClosureSample) -> f64 {
        match self {
            Variable::ZenithDeg => s.zenith_deg,
            Variable::AzimuthDeg => s.azimuth_deg,
            Variable::HourAngleDeg => s.hour_angle_deg,
            Variable::BeamWm2 => s.beam_wm2(),
            Variable::DhiWm2 => s.dhi_wm2,
        }
    }

    /// Axis label with its unit.
    pub fn label(self) -> &'static str {
        match self {
            Variable::ZenithDeg => "solar zenith (deg)",
            Variable::AzimuthDeg => "solar azimuth from north (deg)",
            Variable::HourAngleDeg => "hour angle (deg, afternoon positive)",
            Variable::BeamWm2 => "beam on the horizontal DNI cos Z (W/m²)",
            Variable::DhiWm2 => "DHI (W/m²)",
        }
    }

    /// For file names.
    pub fn stem(self) -> &'static str {
        match self {
            Variable::ZenithDeg => "zenith",
            Variable::AzimuthDeg => "azimuth",
            Variable::HourAngleDeg => "hour_angle",
            Variable::BeamWm2 => "beam",
            Variable::DhiWm2 => "dhi",
        }
    }
}

/// Guards k = −s/(1 + s) against s = −1 (a scale that would make the instrument read
/// nothing): the result stays finite for the report.
fn scale_from_slope(s: f64) -> f64 {
    let d = 1.0 + s;
    if d.abs() < 1e-9 {
        -s / 1e-9_f64.copysign(d)
    } else {
        -s / d
    }
}

impl PyranometerEffect {
    pub const ALL: [PyranometerEffect; 7] = [
        PyranometerEffect::ThermalOffset,
        PyranometerEffect::TimestampShift,
        PyranometerEffect::CosineResponse,
        PyranometerEffect::LevelTilt,
        PyranometerEffect::DniScale,
        PyranometerEffect::TrackerDrift,
        PyranometerEffect::DhiScale,
    ];

    pub fn name(self) -> &'static str {
        match self {
            PyranometerEffect::ThermalOffset => "thermal_offset",
            PyranometerEffect::TimestampShift => "timestamp_shift",
            PyranometerEffect::CosineResponse => "cosine_response",
            PyranometerEffect::LevelTilt => "level_tilt",
            PyranometerEffect::DniScale => "dni_scale",
            PyranometerEffect::TrackerDrift => "tracker_drift",
            PyranometerEffect::DhiScale => "dhi_scale",
        }
    }

    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|e| e.name() == name)
    }

    /// How many coefficients (regressors) the effect has.
    pub fn n_columns(self) -> usize {
        match self {
            PyranometerEffect::LevelTilt => 2,
            _ => 1,
        }
    }

    /// The effect's regressors for one sample: its residual is Σ coefficient · column.
    /// Only the first [`Self::n_columns`] entries are meaningful.
    pub fn columns(self, s: &ClosureSample) -> [f64; 2] {
        let beam = s.beam_wm2();
        let cos_z = s.cos_zenith().max(0.0);
        match self {
            PyranometerEffect::ThermalOffset => [1.0, 0.0],
            PyranometerEffect::TimestampShift => [s.dni_wm2 * s.dcos_zenith_per_s, 0.0],
            PyranometerEffect::CosineResponse => [beam * (1.0 - cos_z), 0.0],
            PyranometerEffect::LevelTilt => {
                let (sin_a, cos_a) = s.azimuth_deg.to_radians().sin_cos();
                let side = s.dni_wm2 * s.zenith_deg.to_radians().sin();
                [side * cos_a, side * sin_a]
            }
            PyranometerEffect::DniScale => [beam, 0.0],
            PyranometerEffect::TrackerDrift => [beam * s.hour_angle_deg / 15.0, 0.0],
            PyranometerEffect::DhiScale => [s.dhi_wm2, 0.0],
        }
    }

    /// Physical parameters from the fitted coefficients (`coefs.len()` = [`Self::n_columns`]).
    pub fn parameters(self, coefs: &[f64]) -> BTreeMap<String, f64> {
        let c = |i: usize| coefs.get(i).copied().unwrap_or(0.0);
        let mut p = BTreeMap::new();
        let mut put = |k: &str, v: f64| {
            p.insert(k.to_string(), v);
        };
        match self {
            PyranometerEffect::ThermalOffset => put("offset_wm2", c(0)),
            PyranometerEffect::TimestampShift => put("shift_s", c(0)),
            PyranometerEffect::CosineResponse => put("relative_error_at_horizon", c(0)),
            PyranometerEffect::LevelTilt => {
                let (px, qx) = (c(0), c(1));
                put("tilt_deg", px.hypot(qx).min(1.0).asin().to_degrees());
                put(
                    "tilt_towards_azimuth_deg",
                    qx.atan2(px).to_degrees().rem_euclid(360.0),
                );
            }
            PyranometerEffect::DniScale => put("dni_relative_error", scale_from_slope(c(0))),
            PyranometerEffect::TrackerDrift => put("beam_fraction_per_hour", c(0)),
            PyranometerEffect::DhiScale => put("dhi_relative_error", scale_from_slope(c(0))),
        }
        p
    }

    /// The variable whose plot against the residual shows the effect.
    pub fn revealing_variable(self) -> Variable {
        match self {
            PyranometerEffect::ThermalOffset => Variable::BeamWm2,
            PyranometerEffect::TimestampShift => Variable::HourAngleDeg,
            PyranometerEffect::CosineResponse => Variable::ZenithDeg,
            PyranometerEffect::LevelTilt => Variable::AzimuthDeg,
            PyranometerEffect::DniScale => Variable::BeamWm2,
            PyranometerEffect::TrackerDrift => Variable::HourAngleDeg,
            PyranometerEffect::DhiScale => Variable::DhiWm2,
        }
    }

    /// The residual signature in words, for the evidence sentence.
    pub fn signature(self) -> &'static str {
        match self {
            PyranometerEffect::ThermalOffset => "a constant residual, independent of the beam",
            PyranometerEffect::TimestampShift => {
                "a residual proportional to DNI·d(cos Z)/dt, of opposite signs before and after solar noon"
            }
            PyranometerEffect::CosineResponse => {
                "a residual proportional to DNI cos Z (1 − cos Z), growing towards low sun on both sides of noon"
            }
            PyranometerEffect::LevelTilt => {
                "a residual proportional to DNI sin Z cos(azimuth − γ), of opposite signs on the two sides of azimuth γ"
            }
            PyranometerEffect::DniScale => "a residual proportional to the beam DNI cos Z",
            PyranometerEffect::TrackerDrift => {
                "a residual proportional to the beam times the hour angle"
            }
            PyranometerEffect::DhiScale => "a residual proportional to DHI",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use chrono::{TimeZone, Utc};

    fn sample(zenith_deg: f64, azimuth_deg: f64) -> ClosureSample {
        ClosureSample {
            time_utc: Utc.with_ymd_and_hms(2016, 1, 1, 18, 0, 0).unwrap(),
            ghi_wm2: 0.0,
            dhi_wm2: 50.0,
            dni_wm2: 900.0,
            zenith_deg,
            azimuth_deg,
            hour_angle_deg: (azimuth_deg - 180.0) / 2.0,
            dcos_zenith_per_s: 1e-4,
        }
    }

    /// The tilt model's first-order residual matches the exact cosine of incidence on a
    /// tilted plane, and its parameters come back from its coefficients.
    #[test]
    fn tilt_is_first_order_exact_and_invertible() {
        let (beta, gamma) = (1.5_f64.to_radians(), 300_f64.to_radians());
        let (p, q) = (beta.sin() * gamma.cos(), beta.sin() * gamma.sin());
        for (z, a) in [(30.0, 120.0), (70.0, 150.0), (80.0, 230.0)] {
            let s = sample(z, a);
            let (zr, ar) = (f64::to_radians(z), f64::to_radians(a));
            let cos_inc = beta.cos() * zr.cos() + beta.sin() * zr.sin() * (ar - gamma).cos();
            let exact = s.dni_wm2 * (cos_inc - zr.cos());
            let cols = PyranometerEffect::LevelTilt.columns(&s);
            let linear = p * cols[0] + q * cols[1];
            // Second order: DNI cos Z β²/2 ≈ 0.3 W/m² at most here.
            assert!(
                (exact - linear).abs() < 0.35,
                "z {z} a {a}: {exact} vs {linear}"
            );
        }
        let params = PyranometerEffect::LevelTilt.parameters(&[p, q]);
        assert!((params["tilt_deg"] - 1.5).abs() < 1e-9);
        assert!((params["tilt_towards_azimuth_deg"] - 300.0).abs() < 1e-9);
    }

    #[test]
    fn scales_and_names_round_trip() {
        // DNI reads 2 % high: r = −0.02/1.02 · beam, slope s = −0.0196…, k = 0.02.
        let s = -0.02 / 1.02;
        let k = PyranometerEffect::DniScale.parameters(&[s])["dni_relative_error"];
        assert!((k - 0.02).abs() < 1e-12);
        assert!(PyranometerEffect::DhiScale.parameters(&[-1.0])["dhi_relative_error"].is_finite());
        for e in PyranometerEffect::ALL {
            assert_eq!(PyranometerEffect::from_name(e.name()), Some(e));
            assert!(!e.parameters(&[0.0, 0.0]).is_empty());
        }
        assert_eq!(PyranometerEffect::from_name("nope"), None);
    }
}
