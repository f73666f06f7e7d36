//! The loop's effect library: each effect is a parametric change to the device model, a fit
//! on the fit set only, and the residual signature that is its evidence.
//!
//! One effect is one file in this folder and one line in the [`effects!`] list below: that
//! line declares the file's module and registers its effect, and the loop, the report and
//! `skylux sim campaign --effect` read the list ([`registry::EFFECTS`]). The interface is in
//! [`effect`], the shared fitting tools in [`fit`].
//!
//! Fits minimise the squared relative residual (prediction / measurement − 1) over the fit
//! set; the linear effects (transmittance, leak, ground) have closed forms
//! ([`fit::fit_linear`]).

pub mod effect;
pub mod fit;

pub use effect::{FitContext, Fitted, Found, Linear, LoopEffect, Stage};

/// Declares each effect's module (`NAME.rs` beside this file) and lists its effect in
/// [`registry::EFFECTS`], in order: one line per effect.
macro_rules! effects {
    ($($(#[$attr:meta])* $module:ident :: $effect:ident),* $(,)?) => {
        $($(#[$attr])* pub mod $module;)*

        /// The effect library in the order the loop tries it (ties in the fit-set error go to
        /// the earlier); the report names the effects and `skylux sim campaign --effect
        /// NAME=VALUE` accepts their names.
        pub mod registry {
            use super::LoopEffect;

            /// Every effect the loop knows.
            pub const EFFECTS: &[&dyn LoopEffect] = &[$($(#[$attr])* &super::$module::$effect),*];

            /// The effect of that name, or of that alias.
            pub fn find(name: &str) -> Option<&'static dyn LoopEffect> {
                EFFECTS
                    .iter()
                    .copied()
                    .find(|e| e.name() == name || e.aliases().contains(&name))
            }
        }
    };
}

effects! {
    sun_undersampling::SunUndersampling,
    glazing_transmittance::GlazingTransmittance,
    light_leak::LightLeak,
    ground_reflectance::GroundReflectance,
    orientation_error::OrientationError,
    clock_offset::ClockOffset,
    spectral_mismatch::SpectralMismatch,
    shutter_overhead::ShutterOverhead,
    glazing_angular::GlazingAngular,
    vignetting::Vignetting,
    sky_outside_fov::SkyOutsideFov,
    #[cfg(test)]
    luxmeter_calibration::LuxmeterCalibration,
}
