//! RADIANCE function data files (`.dat`, read by `brightdata`, `colordata`, `texdata` and
//! their kin).

use crate::engine::function::data::DataArray;

/// Parses the bytes as `fuzz.dat`, then interpolates inside, at the edges and far outside
/// the grid (the extrapolation and tapering paths), in every dimension.
pub(super) fn dat(bytes: &[u8]) {
    match DataArray::parse("fuzz.dat", &super::checks::text(bytes)) {
        Ok(data) => {
            let n = data.dimension_count();
            for x in [0.0, 0.5, -1.0, 1e30, -1e30, f64::NAN] {
                let point = vec![x; n];
                // Any value is a correct answer (a file's own values may overflow when
                // extrapolated); the test is that every path returns.
                let _ = data.value(&point);
                let _ = data.value(&point[..n.saturating_sub(1)]);
            }
        }
        Err(e) => super::checks::assert_names(&e.to_string(), "fuzz.dat"),
    }
}
