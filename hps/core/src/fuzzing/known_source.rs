//! A known source of `skylux calibrate response` (`CAPTURE_DIR=LUMINANCE_CD_M2`).

use crate::calibration::response::parse_known_source;

/// Parses the bytes; a source read has a positive finite luminance, and an error quotes
/// the text it refused.
pub(super) fn known_source(bytes: &[u8]) {
    let text = super::checks::text(bytes);
    match parse_known_source(&text) {
        Ok(s) => assert!(s.luminance_cd_m2.is_finite() && s.luminance_cd_m2 > 0.0),
        Err(e) => assert!(!e.is_empty()),
    }
}
