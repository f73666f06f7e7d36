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

/// Parses the bytes as `fuzz.mtx` in RADIANCE's matrix format (`rfluxmtx`, `gendaymtx`,
/// `dctimestep`, `skylux dc --three-phase`); a matrix read is written back and read again
/// unchanged, and multiplied by a vector of ones.
pub(super) fn radiance_matrix(bytes: &[u8]) {
    use crate::io::radiance_matrix::{MatrixFormat, RadianceMatrix};
    match RadianceMatrix::parse("fuzz.mtx", bytes) {
        Ok(m) => {
            assert_eq!(m.values.len(), m.rows * m.cols * m.ncomp);
            let again = RadianceMatrix::parse("again.mtx", &m.to_bytes(MatrixFormat::Double, &[]))
                .expect("our own output reads back");
            assert_eq!(again, m);
            if let Some(ones) = RadianceMatrix::from_grey(m.cols, 1, vec![1.0; m.cols]) {
                let sums = m.multiply(&ones).expect("shapes chain");
                assert_eq!((sums.rows, sums.ncomp), (m.rows, m.ncomp));
            }
        }
        Err(e) => super::checks::assert_names(&e.to_string(), "fuzz.mtx"),
    }
}
