//! One closure sample: an averaging interval with all three channels, and where the sun was.

use crate::validation::split::Timed;
use chrono::{DateTime, Utc};

/// Beyond nautical twilight (sun 12° below the horizon) the sky adds well under 0.01 W/m²:
/// what a pyranometer reads then is its own offset.
pub const NIGHT_MIN_ZENITH_DEG: f64 = 102.0;

/// One averaging interval with all three channels, and where the sun was.
#[derive(Clone, Debug, PartialEq)]
pub struct ClosureSample {
    /// Centre of the averaging interval.
    pub time_utc: DateTime<Utc>,
    pub ghi_wm2: f64,
    pub dhi_wm2: f64,
    pub dni_wm2: f64,
    /// Apparent (refracted) zenith at `time_utc`.
    pub zenith_deg: f64,
    /// From north towards east.
    pub azimuth_deg: f64,
    /// Solar hour angle, negative in the morning.
    pub hour_angle_deg: f64,
    /// d(cos Z)/dt at `time_utc`, per second.
    pub dcos_zenith_per_s: f64,
}

impl ClosureSample {
    pub fn cos_zenith(&self) -> f64 {
        self.zenith_deg.to_radians().cos()
    }

    /// DNI cos Z, zero with the sun below the horizon.
    pub fn beam_wm2(&self) -> f64 {
        self.dni_wm2 * self.cos_zenith().max(0.0)
    }

    /// The closure residual GHI − (DNI cos Z + DHI).
    pub fn residual_wm2(&self) -> f64 {
        self.ghi_wm2 - self.beam_wm2() - self.dhi_wm2
    }
}

impl Timed for ClosureSample {
    fn time_utc(&self) -> DateTime<Utc> {
        self.time_utc
    }
}
