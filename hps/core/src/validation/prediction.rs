//! The loop's model: the device model ([`ModelState`]) with the parameters the loop's effects
//! add, and the prediction `τ (room + ρ ground) + leak · outdoor` they enter.
//!
//! Each effect's parameters are [`Param`] keys of [`LoopState`], declared beside the code that
//! applies them: those of the prediction formula here, those applied to the terms with that
//! code (`sky_geometry.rs`, `glazing.rs`), the others in the effect's own file.

use super::terms::Terms;
use crate::model::{self, ModelState};

/// A parameter of a loop effect: its key in [`LoopState`] and its value without the effect.
#[derive(Clone, Copy, Debug)]
pub struct Param {
    pub key: &'static str,
    pub default: f64,
}

/// Glazing transmittance relative to the scene's (`glazing_transmittance`).
pub const GLAZING_TRANSMITTANCE: Param = Param {
    key: "glazing_transmittance.relative_transmittance",
    default: 1.0,
};
/// Additive light, lux per lux of outdoor horizontal illuminance (`light_leak`).
pub const LIGHT_LEAK: Param = Param {
    key: "light_leak.lux_per_outdoor_lux",
    default: 0.0,
};
/// The lux-meter logger's clock minus the device's, seconds: readings are matched to a
/// capture at this offset on the logger's clock (`clock_offset`).
pub const CLOCK_OFFSET_S: Param = Param {
    key: "clock_offset.logger_minus_device_s",
    default: 0.0,
};
/// Spectral mismatch: measured / true luminance is `1 + m (c − 1)` at sky colour index `c`
/// (blue / red); this is `m` (0: no mismatch) (`spectral_mismatch`).
pub const SPECTRAL_SLOPE: Param = Param {
    key: "spectral_mismatch.slope_per_index",
    default: 0.0,
};

/// 1 where the frames measured the unseen ground's reflectance (`ground_reflectance`): the
/// joint linear fit then holds it rather than refit it on the lux-meters.
pub const GROUND_FROM_FRAMES: Param = Param {
    key: "ground_reflectance.from_frames",
    default: 0.0,
};

/// The colour index of the calibration source: the simulator's frames, and a device balanced
/// under its calibration source, give 1 for it.
pub const REFERENCE_INDEX: f64 = 1.0;

/// The loop's model: the device model and the values of the effects' parameters (a parameter
/// not set has its default: the effect is absent).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LoopState {
    pub model: ModelState,
    values: Vec<(&'static str, f64)>,
}

impl LoopState {
    /// The parameter's value, if an effect set it.
    pub fn value(&self, p: Param) -> Option<f64> {
        self.values
            .iter()
            .find(|(k, _)| *k == p.key)
            .map(|(_, v)| *v)
    }

    /// The parameter's value, or its default.
    pub fn get(&self, p: Param) -> f64 {
        self.value(p).unwrap_or(p.default)
    }

    pub fn set(&mut self, p: Param, value: f64) {
        match self.values.iter_mut().find(|(k, _)| *k == p.key) {
            Some(slot) => slot.1 = value,
            None => self.values.push((p.key, value)),
        }
    }

    /// A copy with `p` set to `value`.
    pub fn with(&self, p: Param, value: f64) -> Self {
        let mut next = self.clone();
        next.set(p, value);
        next
    }
}

/// The measured-over-true luminance factor at colour index `c` for slope `m` (kept above 0.2
/// so a wild trial slope cannot divide by zero).
pub fn factor(slope: f64, c: f64) -> f64 {
    (1.0 + slope * (c - REFERENCE_INDEX)).max(0.2)
}

/// Sensor `s`'s room light `room` (the model's sky, seen ground and sun, lux) with the
/// measured sky patches and the sun divided by their spectral-mismatch factors under
/// `state`. Unchanged without the effect or without a colour for the capture.
pub fn corrected_room(state: &LoopState, t: &Terms, s: usize, room: f64) -> f64 {
    let m = state.get(SPECTRAL_SLOPE);
    if m == 0.0 {
        return room;
    }
    let Some(sp) = &t.spectral else {
        return room;
    };
    let c_sky = sp.colour.sky_index;
    if !c_sky.is_finite() {
        return room;
    }
    let Some(per_patch) = sp.sky_lux_per_patch.get(s) else {
        return room;
    };
    let (mut measured, mut corrected) = (0.0, 0.0);
    for (p, e) in per_patch.iter().enumerate() {
        let c = sp
            .colour
            .patch_index
            .get(p)
            .copied()
            .filter(|c| c.is_finite())
            .unwrap_or(c_sky);
        measured += e;
        corrected += e / factor(m, c);
    }
    let sun = if state.model.concentrated_sun {
        t.sun_lux_per_dn_lux[s] * t.sun_dn_lux
    } else {
        t.sky_with_sun_lux[s] - t.sky_without_sun_lux[s]
    };
    let c_sun = if sp.colour.sun_index.is_finite() {
        sp.colour.sun_index
    } else {
        c_sky
    };
    room - measured - sun + corrected + sun / factor(m, c_sun)
}

/// Per sensor, the parts the linear effects act on: the room's light without the unseen
/// ground (lux; the measured sky and sun corrected for the spectral mismatch), the unseen
/// ground's light per unit of its reflectance (lux), and the outdoor horizontal illuminance
/// (lux). The prediction is `τ (room + ρ ground) + leak · outdoor`.
pub fn parts(state: &LoopState, t: &Terms) -> Vec<(f64, f64, f64)> {
    model::parts(&state.model, t)
        .into_iter()
        .enumerate()
        .map(|(s, (room, ground, outdoor))| (corrected_room(state, t, s, room), ground, outdoor))
        .collect()
}

/// Illuminance per sensor, lux, for one capture's terms under `state`.
pub fn predict(state: &LoopState, t: &Terms) -> Vec<f64> {
    let (tau, leak, rho) = (
        state.get(GLAZING_TRANSMITTANCE),
        state.get(LIGHT_LEAK),
        state.model.ground_reflectance,
    );
    parts(state, t)
        .into_iter()
        .map(|(room, ground, outdoor)| tau * (room + rho * ground) + leak * outdoor)
        .collect()
}
