//! The product's prediction: illuminance per sensor from one capture's terms.

use super::terms::CaptureTerms;
use std::f64::consts::PI;

/// What the device itself applies: the sun handed over as a concentrated source and a
/// reflectance for the ground the lens does not see. (The loop adds its effects on top:
/// `validation::prediction::LoopState`.)
#[derive(Clone, Debug, PartialEq)]
pub struct ModelState {
    /// Hand the sun over as a concentrated source (else it stays in the map's patches).
    pub concentrated_sun: bool,
    /// Reflectance of the ground where the lens does not see it.
    pub ground_reflectance: f64,
}

impl Default for ModelState {
    fn default() -> Self {
        Self {
            concentrated_sun: true,
            ground_reflectance: 0.2,
        }
    }
}

/// Per sensor, the parts of the prediction: the room's light without the unseen ground
/// (lux), the unseen ground's light per unit of its reflectance (lux), and the outdoor
/// horizontal illuminance (lux).
pub fn parts(state: &ModelState, t: &CaptureTerms) -> Vec<(f64, f64, f64)> {
    (0..t.sky_with_sun_lux.len())
        .map(|s| {
            let room = if state.concentrated_sun {
                t.sky_without_sun_lux[s] + t.sun_lux_per_dn_lux[s] * t.sun_dn_lux
            } else {
                t.sky_with_sun_lux[s]
            };
            let ground = t.unseen_ground_lux_per_cd_m2[s] * t.outdoor_horizontal_lux / PI;
            (room, ground, t.outdoor_horizontal_lux)
        })
        .collect()
}

/// Illuminance per sensor, lux, for one capture's terms: `room + ρ ground`.
pub fn predict(state: &ModelState, t: &CaptureTerms) -> Vec<f64> {
    parts(state, t)
        .into_iter()
        .map(|(room, ground, _)| room + state.ground_reflectance * ground)
        .collect()
}
