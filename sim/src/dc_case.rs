//! The daylight-coefficient update case that `skylux bench dc` and skyluxd's cycle budget
//! (`skyluxd --bench-cycle`) share: 400 sensors, a Reinhart MF4 sky (2305 patches) and its
//! mirrored ground, so 400 x 4610 coefficients. The matrix is synthetic: the timing of the
//! update (a matrix-vector product) does not depend on its values.

use skylux_hps::engine::DaylightCoefficients;

/// The matrix, the patch luminances it multiplies, and how many of the bins are sky.
pub struct DcCase {
    pub dc: DaylightCoefficients,
    pub luminance_cd_m2: Vec<f64>,
    pub sky_patches: usize,
}

impl DcCase {
    /// 400 sensors, Reinhart MF4 sky and ground.
    pub fn new() -> Self {
        let (sensors, mf) = (400, 4);
        let sky_patches = skylux_hps::sky::SkyPatches::reinhart(mf).len();
        let bins = 2 * sky_patches;
        let dc = DaylightCoefficients {
            sensors: (1..=sensors).map(|i| format!("S{i}")).collect(),
            mf,
            bins,
            lux_per_cd_m2: (0..sensors * bins)
                .map(|i| 1e-4 * ((i % 97) as f64))
                .collect(),
            samples_per_sensor: 0,
        };
        let luminance_cd_m2 = (0..bins).map(|i| 1000.0 + (i % 13) as f64).collect();
        DcCase {
            dc,
            luminance_cd_m2,
            sky_patches,
        }
    }

    /// The update over the sky patches only (the 400 x 2305 budget), into `out`.
    pub fn sky_only_update(&self, out: &mut [f64]) {
        for (s, o) in out.iter_mut().enumerate() {
            *o = self.dc.row(s)[..self.sky_patches]
                .iter()
                .zip(&self.luminance_cd_m2)
                .map(|(c, l)| c * l)
                .sum();
        }
    }
}

impl Default for DcCase {
    fn default() -> Self {
        Self::new()
    }
}
