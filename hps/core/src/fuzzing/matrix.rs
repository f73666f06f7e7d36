//! Daylight-coefficient matrices (`skylux dc`'s RADIANCE-format cache, read back by the
//! daemon and `skylux loop`).

use crate::engine::DaylightCoefficients;
use std::path::Path;

/// Parses the bytes as `fuzz.dc`; a matrix read is applied to a uniform sky.
pub(super) fn dc_matrix(bytes: &[u8]) {
    match DaylightCoefficients::parse(Path::new("fuzz.dc"), bytes) {
        Ok(dc) => {
            let sky = vec![1.0; dc.bins];
            let lux = dc.apply_seen(&sky);
            assert_eq!(lux.len(), dc.sensors.len());
        }
        Err(e) => super::checks::assert_names(&e, "fuzz.dc"),
    }
}
