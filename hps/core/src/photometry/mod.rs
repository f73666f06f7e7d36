//! Photometry: spectral curves and their integrals (CIE V(λ), illuminants, camera
//! sensitivities), the machinery both the calibration (`calibration::spectral`) and the
//! simulator's spectral response (`skylux_sim::sensor::spectral`) use.

pub mod spectral;

/// RADIANCE's luminous efficacy of its "white" radiometric unit, lm/W (RADIANCE `color.h`,
/// `WHTEFFICACY`): luminance = 179 × (0.265 R + 0.670 G + 0.065 B) for RADIANCE's RGB
/// radiance in W sr⁻¹ m⁻². Every conversion between RADIANCE units and photometry uses it.
pub const WHITE_EFFICACY_LM_PER_W: f64 = 179.0;

pub use spectral::{
    cie_daylight, illuminant_a, overlap, read_columns, read_value_columns, Curve, SpectralError,
    VISIBLE_MAX_NM, VISIBLE_MIN_NM,
};
