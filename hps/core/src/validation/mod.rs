//! Closing the loop with measured data: compare the model with reference instruments, find
//! the residual, trace it to a missing effect, add it, and report before and after on
//! held-out data.

pub mod closure;
pub mod device_model;
pub mod effect_fov;
pub mod effect_glazing_angular;
pub mod effect_spectral;
pub mod effect_vignetting;
pub mod effects;
pub mod glazing;
pub mod illuminance_loop;
pub mod loop_figures;
pub mod report;
pub mod sky_colour;
pub mod split;
