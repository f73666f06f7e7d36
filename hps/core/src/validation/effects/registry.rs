//! The effect library: one line per effect. The loop tries them in this order (ties in the
//! fit-set error go to the earlier), the report names them, and `skylux sim campaign
//! --effect NAME=VALUE` accepts their names.

use super::LoopEffect;

/// Every effect the loop knows.
pub const EFFECTS: &[&dyn LoopEffect] = &[
    &super::sun_undersampling::SunUndersampling,
    &super::glazing_transmittance::GlazingTransmittance,
    &super::light_leak::LightLeak,
    &super::ground_reflectance::GroundReflectance,
    &super::orientation_error::OrientationError,
    &super::clock_offset::ClockOffset,
    &super::spectral_mismatch::SpectralMismatch,
    &super::shutter_overhead::ShutterOverhead,
    &super::glazing_angular::GlazingAngular,
    &super::vignetting::Vignetting,
    &super::sky_outside_fov::SkyOutsideFov,
    #[cfg(test)]
    &super::luxmeter_calibration::LuxmeterCalibration,
];

/// The effect of that name, or of that alias.
pub fn find(name: &str) -> Option<&'static dyn LoopEffect> {
    EFFECTS
        .iter()
        .copied()
        .find(|e| e.name() == name || e.aliases().contains(&name))
}
