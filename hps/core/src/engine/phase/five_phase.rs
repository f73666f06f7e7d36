//! The five-phase method (McNeil 2013, the LBNL tutorial's `5PM.sh`): the three-phase
//! product smears the sun over a sky patch and a Klems patch (0.02-0.06 sr, some 100 times
//! the sun's disk), so a sensor in the beam reads far off. The five-phase keeps the
//! three-phase for the sky and the sun's interreflected light, takes out the sun's direct
//! part as the three-phase has it, and puts back the sun at its actual direction through the
//! window at full resolution (a tensor tree, or the detailed geometry itself):
//!
//! E = V T D (s_sky + s_sun) − V_d T D_d s_sun + C_ds E_dn
//!
//! with V_d the sensors' direct view of the window (paths of one bounce, the first hit ends
//! them: `view_matrix` with `-ab 1`), D_d the window's direct view of the sky (`-ab 0`),
//! s_sun the sun as a sky vector ([`sun_sky_vector`]), C_ds the direct sun coefficients at
//! the sun's direction (`engine::sun_coefficients` on the room blackened, with the window
//! at full resolution) and E_dn the direct-normal irradiance. The sun's direction comes from
//! SPA or from the disk extracted from the sky map; s_sky from the measured luminance map
//! with the sun removed: the image-based five-phase method.

use super::three_phase::three_phase;
use crate::engine::error::EngineError;
use crate::io::radiance_matrix::RadianceMatrix;
use crate::sky::SkyPatches;
use glam::DVec3;

/// The sun alone as a sky vector for D's columns (ground, then Reinhart MF `mf` patches):
/// its direct-normal irradiance `dni_w_m2` as the radiance of the patch holding its
/// direction, DNI / Ω_patch, so that the patch delivers the sun's normal irradiance. None
/// for a sun below the horizon (the ground does not hold it).
pub fn sun_sky_vector(mf: usize, sun_direction: DVec3, dni_w_m2: f64) -> Option<Vec<f64>> {
    let patches = SkyPatches::reinhart(mf);
    let p = patches.patch_of(sun_direction.normalize())?;
    let mut s = vec![0.0; 1 + patches.len()];
    s[1 + p] = dni_w_m2 / patches.solid_angle_sr(p);
    Some(s)
}

/// The three-phase and direct matrices of one window state.
pub struct PhaseMatrices<'a> {
    pub v: &'a RadianceMatrix,
    pub t: &'a RadianceMatrix,
    pub d: &'a RadianceMatrix,
    /// V with `-ab 1` (direct view of the window).
    pub v_direct: &'a RadianceMatrix,
    /// D with `-ab 0` (direct view of the sky).
    pub d_direct: &'a RadianceMatrix,
}

/// Irradiance per sensor, W/m² (times 179 for lux), by the five-phase method: `sky` the
/// sky vector without the sun (grey, D's columns), the sun of `dni_w_m2` in `sun_direction`,
/// `sun_coefficients` C_ds per sensor (irradiance per unit DNI at full resolution). Also
/// returns the three-phase answer with the sun in its patch, for comparison.
pub fn five_phase(
    m: &PhaseMatrices,
    sky: &[f64],
    mf: usize,
    sun_direction: DVec3,
    dni_w_m2: f64,
    sun_coefficients: &[f64],
) -> Result<(Vec<f64>, Vec<f64>), EngineError> {
    let sun = sun_sky_vector(mf, sun_direction, dni_w_m2).unwrap_or_else(|| vec![0.0; sky.len()]);
    if sun.len() != sky.len() || sun_coefficients.len() != m.v.rows {
        return Err(EngineError::Setting {
            name: "five-phase inputs",
            value: format!(
                "{} sky values for MF{mf} ({}), {} sun coefficients for {} sensors",
                sky.len(),
                sun.len(),
                sun_coefficients.len(),
                m.v.rows
            ),
            expected: "one sky value per D column and one sun coefficient per sensor",
        });
    }
    // A column of n values is n x 1: from_grey cannot refuse it.
    let column = |values: Vec<f64>| RadianceMatrix {
        rows: values.len(),
        cols: 1,
        ncomp: 1,
        values,
    };
    let with_sun: Vec<f64> = sky.iter().zip(&sun).map(|(a, b)| a + b).collect();
    let three = three_phase(m.v, m.t, m.d, &column(with_sun))?;
    let direct = three_phase(m.v_direct, m.t, m.d_direct, &column(sun))?;
    let five = (0..m.v.rows)
        .map(|s| three.get(s, 0, 0) - direct.get(s, 0, 0) + sun_coefficients[s] * dni_w_m2)
        .collect();
    Ok((five, (0..m.v.rows).map(|s| three.get(s, 0, 0)).collect()))
}

/// The sky vector of a measured sky (the image-based five-phase): patch luminances in cd/m²
/// (Reinhart patches, `SkyPatches::aggregate` of the luminance map with the sun's disk
/// removed) and the ground's, as RADIANCE radiance (luminance / 179 lm/W), ground first as D's
/// columns. The sun goes in separately: its direction and its direct-normal illuminance
/// from the extracted disk, divided by 179 for [`five_phase`]'s `dni_w_m2`.
pub fn sky_vector_from_luminance(patch_luminance_cd_m2: &[f64], ground_cd_m2: f64) -> Vec<f64> {
    std::iter::once(ground_cd_m2)
        .chain(patch_luminance_cd_m2.iter().copied())
        .map(|l| l / crate::engine::WHITE_EFFICACY_LM_PER_W)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sun_patch_delivers_the_direct_normal_irradiance() {
        let sun = DVec3::new(0.3, -0.8, 0.5).normalize();
        let s = sun_sky_vector(2, sun, 500.0).unwrap();
        let patches = SkyPatches::reinhart(2);
        let p = patches.patch_of(sun).unwrap();
        assert!((s[1 + p] * patches.solid_angle_sr(p) - 500.0).abs() < 1e-9);
        assert_eq!(s.iter().filter(|&&v| v > 0.0).count(), 1);
        assert!(sun_sky_vector(2, -sun, 500.0).is_none());
        let v = sky_vector_from_luminance(&[179.0, 358.0], 17.9);
        for (a, b) in v.iter().zip([0.1, 1.0, 2.0]) {
            assert!((a - b).abs() < 1e-12, "{v:?}");
        }
    }
}
