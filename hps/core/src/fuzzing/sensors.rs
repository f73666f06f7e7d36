//! `.pts` sensor files (rtrace's input: position and direction per line).

/// Parses the bytes as `fuzz.pts`; every sensor read must be finite with a unit direction.
pub(super) fn pts(bytes: &[u8]) {
    match crate::scene::parse_sensors("fuzz.pts", bytes) {
        Ok(sensors) => {
            for s in sensors {
                let unit = (s.direction.length() - 1.0).abs() < 1e-9;
                assert!(s.position_m.is_finite() && unit, "{}: {:?}", s.name, s);
            }
        }
        Err(e) => super::checks::assert_names(&e.to_string(), "fuzz.pts"),
    }
}
