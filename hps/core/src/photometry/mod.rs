//! Photometry: spectral curves and their integrals (CIE V(λ), illuminants, camera
//! sensitivities), the machinery both the calibration (`calibration::spectral`) and the
//! simulator's spectral response (`skylux_sim::sensor::spectral`) use.

pub mod spectral;

pub use spectral::{
    cie_daylight, illuminant_a, overlap, read_columns, read_value_columns, Curve, SpectralError,
    VISIBLE_MAX_NM, VISIBLE_MIN_NM,
};
