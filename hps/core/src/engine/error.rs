//! Why a scene or a request cannot be traced.

use crate::scene::SourceLocation;

#[derive(Debug, thiserror::Error)]
pub enum EngineError {
    /// Something the scene reader accepts but the engine does not trace (yet); refused rather
    /// than silently traced differently from RADIANCE.
    #[error("{at}: {what}")]
    Unsupported { at: SourceLocation, what: String },

    /// A `BSDF` material whose XML file cannot be read or makes no sense.
    #[error("{at}: BSDF `{material}`: {error}")]
    BsdfFile {
        at: SourceLocation,
        material: String,
        error: Box<crate::bsdf::BsdfError>,
    },

    /// A setting outside its range.
    #[error("invalid setting {name} = {value}: expected {expected}")]
    Setting {
        name: &'static str,
        value: String,
        expected: &'static str,
    },
}
