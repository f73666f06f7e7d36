//! A sky for the simulated world: the ground truth the device measures. Deliberately simple
//! and independent of the engine's sky models (those are the product; this is the world).
//!
//! Luminance: the Moon-Spencer overcast gradation `L = Lz (1 + 2 sin h) / 3` (CIE S 011 notes;
//! hardware-facts.md §5.4, "type 16") plus a uniform solar disk of the sun's angular radius
//! (0.2665°, RADIANCE gendaylit's half_sun_angle; hardware-facts.md §6) and nothing below the
//! horizon but a uniform ground.

use glam::DVec3;

/// A sky of an overcast gradation, a solar disk and a uniform ground.
#[derive(Clone, Debug)]
pub struct SimulatedSky {
    pub zenith_luminance_cd_m2: f64,
    /// Unit vector towards the sun (world frame: +x east, +y north, +z up).
    pub sun_direction: DVec3,
    pub sun_luminance_cd_m2: f64,
    /// Angular radius of the solar disk, degrees.
    pub sun_radius_deg: f64,
    pub ground_luminance_cd_m2: f64,
}

impl SimulatedSky {
    /// Luminance seen in `direction`, cd/m².
    pub fn luminance_cd_m2(&self, direction: DVec3) -> f64 {
        let d = direction.normalize();
        if d.z < 0.0 {
            return self.ground_luminance_cd_m2;
        }
        if d.dot(self.sun_direction) >= self.sun_radius_deg.to_radians().cos() {
            return self.sun_luminance_cd_m2;
        }
        self.zenith_luminance_cd_m2 * (1.0 + 2.0 * d.z) / 3.0
    }
}
