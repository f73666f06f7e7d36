//! BSDF XML files (WINDOW 6 / LBNL: Klems matrices and tensor trees): read, then evaluated,
//! integrated and sampled in a few directions, as the engine uses them.

use crate::bsdf::{Band, Bsdf, Scattering};
use glam::DVec3;

pub(super) fn bsdf_xml(bytes: &[u8]) {
    match Bsdf::from_xml(&super::checks::text(bytes), "fuzz.xml", Band::Visible) {
        Ok(bsdf) => exercise(&bsdf),
        Err(e) => super::checks::assert_names(&e.to_string(), "fuzz.xml"),
    }
}

/// Evaluates, integrates and samples in front, behind, oblique and grazing directions.
fn exercise(bsdf: &Bsdf) {
    let directions = [
        DVec3::Z,
        -DVec3::Z,
        DVec3::new(0.6, 0.0, 0.8),
        DVec3::new(-0.3, 0.4, -0.866_025_403_784_438_6),
        DVec3::X,
    ];
    for incident in directions {
        for outgoing in directions {
            let _ = bsdf.eval(incident, outgoing);
        }
        let _ = bsdf.hemispherical(incident, Scattering::Reflection)
            + bsdf.hemispherical(incident, Scattering::Transmission);
        let distribution = bsdf.distribution(incident);
        for k in 0..4 {
            let _ = distribution.sample([k as f64 / 4.0, 0.5, 0.999]);
        }
    }
}
