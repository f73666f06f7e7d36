//! The device model: the device's own illuminance model, used by `skyluxd` and by the loop.
//! The room's daylight coefficients times the measured sky (and ground) patches, plus the sun
//! as a concentrated source, per capture, decomposed into terms computed once
//! ([`terms::capture_terms`]), then a prediction per sensor ([`prediction::predict`]).

pub mod captures;
pub mod error;
pub mod measured_sky;
pub mod plausibility;
pub mod prediction;
pub mod room;
pub mod terms;

pub use captures::{load_captures, load_captures_with, CaptureData};
pub use error::ModelError;
pub use measured_sky::{install_measured_sky, remove_measured_sky};
pub use prediction::{parts, predict, ModelState};
pub use room::Room;
pub use terms::{capture_terms, CaptureTerms, SunMissing, SUN_MAX_OFFSET_DEG};
