//! Physical bounds on what the device reports about the outdoor light, so a value no sky can
//! give is flagged rather than acted on.
//!
//! - Global horizontal light: the clear-sky global horizontal irradiance of Ineichen & Perez
//!   (2002), "A new airmass independent formulation for the Linke turbidity coefficient",
//!   *Solar Energy* 73(3):151-157 (their eq. for GHc with cg1, cg2, fh1, fh2 and the
//!   exp(0.01 AM^1.8) term), taken at a Linke turbidity of [`CLEANEST_LINKE_TURBIDITY`] (a
//!   clean, dry atmosphere) with the absolute air mass (Kasten & Young 1989 at the site's
//!   standard pressure), times [`CLOUD_ENHANCEMENT`] for broken clouds that add reflected light
//!   to an unobstructed sun, plus [`DIFFUSE_FLOOR_W_M2`] for the bright overcast of a low sun.
//!   In illuminance, times the highest global luminous efficacy of daylight,
//!   [`MAX_DAYLIGHT_EFFICACY_LM_W`].
//! - The sun's direct-normal illuminance: at most the extraterrestrial one
//!   ([`SOLAR_CONSTANT_LUX`] × the eccentricity factor), with [`DIRECT_NORMAL_MARGIN`] for the
//!   measurement.
//!
//! - Interior illuminance: per sensor, the room's daylight coefficients bound how much light
//!   any sky with the cycle's outdoor horizontal illuminance can bring in
//!   ([`interior_bound_lux`]).
//!
//! `tests/plausibility_bounds.rs` holds the irradiance bound against every minute of the two
//! measured station records of `shared/data/irradiance` (it must never flag a real sky) and
//! checks it is not vacuous (the clear noon of Alamosa reaches most of it).

use super::terms::CaptureTerms;
use crate::engine::DaylightCoefficients;
use crate::sky::perez::{eccentricity_factor, SOLAR_CONSTANT_LUX, SOLAR_CONSTANT_W_M2};
use crate::sun::Atmosphere;

/// Linke turbidity of the cleanest atmospheres (Ineichen & Perez 2002 report TL near 2 for
/// clean, dry air; the climatological minimum of Remund et al. 2003 maps is about 2).
pub const CLEANEST_LINKE_TURBIDITY: f64 = 2.0;

/// Broken clouds can raise 1-minute global irradiance to about 1.5 times the clear-sky value
/// (Gueymard 2017, "Cloud and albedo enhancement impacts on solar irradiance using
/// high-frequency measurements", *Solar Energy* 153:755-765).
pub const CLOUD_ENHANCEMENT: f64 = 1.5;

/// An additive margin, W/m², so that the bound does not vanish with a low sun, where
/// diffuse light from bright clouds dominates and the clear-sky model goes to zero. A chosen
/// margin, not a published constant: `tests/plausibility_bounds.rs` checks that no minute of
/// the measured station records exceeds the bound with it.
pub const DIFFUSE_FLOOR_W_M2: f64 = 150.0;

/// Highest global luminous efficacy of daylight, lm/W: measured clear and overcast global
/// efficacies lie between about 95 and 125 lm/W (Perez et al. 1990, *Solar Energy*
/// 44(5):271-289, their Table and Fig. of global efficacy; Littlefair 1985).
pub const MAX_DAYLIGHT_EFFICACY_LM_W: f64 = 125.0;

/// The direct-normal illuminance the device measures may exceed the extraterrestrial value by
/// this factor at most (calibration and HDR error), beyond which it is flagged.
pub const DIRECT_NORMAL_MARGIN: f64 = 1.05;

/// Relative optical air mass of Kasten & Young (1989), *Applied Optics* 28(22):4735-4738:
/// 1 / (cos Z + 0.50572 (96.07995 − Z)^−1.6364), Z the zenith angle in degrees.
pub fn kasten_young_air_mass(zenith_deg: f64) -> f64 {
    let z = zenith_deg.min(90.0);
    1.0 / (z.to_radians().cos() + 0.50572 * (96.07995 - z).powf(-1.6364))
}

/// Ineichen-Perez clear-sky global horizontal irradiance, W/m², for a sun at
/// `altitude_deg` (apparent), a site at `elevation_m`, a Linke turbidity and a day of the
/// year (for the extraterrestrial irradiance); 0 with the sun below the horizon.
pub fn clear_sky_ghi_w_m2(
    altitude_deg: f64,
    elevation_m: f64,
    linke_turbidity: f64,
    day_of_year: u16,
) -> f64 {
    if altitude_deg.is_nan() || altitude_deg <= 0.0 {
        return 0.0;
    }
    let zenith_deg = 90.0 - altitude_deg;
    let pressure_ratio = Atmosphere::standard_at(elevation_m).pressure_hpa / 1013.25;
    let absolute_air_mass = kasten_young_air_mass(zenith_deg) * pressure_ratio;
    let h = elevation_m;
    let cg1 = 5.09e-5 * h + 0.868;
    let cg2 = 3.92e-5 * h + 0.0387;
    let fh1 = (-h / 8000.0).exp();
    let fh2 = (-h / 1250.0).exp();
    let extraterrestrial = SOLAR_CONSTANT_W_M2 * eccentricity_factor(day_of_year);
    let attenuation = (-cg2 * absolute_air_mass * (fh1 + fh2 * (linke_turbidity - 1.0))).exp()
        * (0.01 * absolute_air_mass.powf(1.8)).exp();
    (cg1 * extraterrestrial * altitude_deg.to_radians().sin() * attenuation).max(0.0)
}

/// The highest global horizontal irradiance a real sky gives at this sun altitude and site
/// elevation, W/m².
pub fn global_horizontal_bound_w_m2(altitude_deg: f64, elevation_m: f64, day_of_year: u16) -> f64 {
    CLOUD_ENHANCEMENT
        * clear_sky_ghi_w_m2(
            altitude_deg,
            elevation_m,
            CLEANEST_LINKE_TURBIDITY,
            day_of_year,
        )
        + DIFFUSE_FLOOR_W_M2
}

/// The highest global horizontal illuminance a real sky gives, lux.
pub fn global_horizontal_bound_lux(altitude_deg: f64, elevation_m: f64, day_of_year: u16) -> f64 {
    global_horizontal_bound_w_m2(altitude_deg, elevation_m, day_of_year)
        * MAX_DAYLIGHT_EFFICACY_LM_W
}

/// The highest direct-normal illuminance the sun can give (above the atmosphere), lux.
pub fn direct_normal_bound_lux(day_of_year: u16) -> f64 {
    DIRECT_NORMAL_MARGIN * SOLAR_CONSTANT_LUX * eccentricity_factor(day_of_year)
}

/// Per sensor, the most illuminance (lux) the room can receive in a capture with these
/// terms: the room's highest daylight factor over every direction of the sky times the
/// outdoor horizontal illuminance, plus the ground as measured (or, unseen, as a grey ground
/// of `ground_reflectance`).
///
/// The sky and the sun add to the outdoor horizontal illuminance `E_h = Σ_p L_p z_p Ω_p +
/// E_dn sin α` and to a sensor `E_s = Σ_p DC_sp L_p + K_s E_dn`, so `E_s ≤ max(max_p DC_sp /
/// (z_p Ω_p), K_s / sin α) · E_h` whatever the sky's distribution: a daylight factor no sky
/// can exceed. A prediction above it has counted light twice (the sun both in its patch and
/// as a source, say) or scaled a term wrongly.
pub fn interior_bound_lux(
    dc: &DaylightCoefficients,
    terms: &CaptureTerms,
    ground_reflectance: f64,
) -> Vec<f64> {
    let patches = dc.patches();
    let n = patches.len();
    let unseen_ground_cd_m2 =
        ground_reflectance * terms.outdoor_horizontal_lux / std::f64::consts::PI;
    (0..dc.sensors.len())
        .map(|s| {
            let row = dc.row(s);
            let sky_factor = (0..n)
                .filter_map(|p| {
                    let z = patches.centre(p).z;
                    (z > 0.0).then(|| row[p] / (z * patches.solid_angle_sr(p)))
                })
                .fold(0.0, f64::max);
            let sun_factor = match &terms.sun {
                Some(sun) if sun.direction.z > 0.0 => terms.sun_lux_per_dn_lux[s] / sun.direction.z,
                _ => 0.0,
            };
            let ground_lux: f64 = (0..n)
                .map(|p| {
                    let l = terms.bins_without_sun_cd_m2[n + p];
                    row[n + p]
                        * if l.is_finite() {
                            l
                        } else {
                            unseen_ground_cd_m2
                        }
                })
                .sum();
            sky_factor.max(sun_factor) * terms.outdoor_horizontal_lux + ground_lux
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sky::perez::air_mass;

    #[test]
    fn kasten_young_is_one_at_the_zenith_and_about_38_at_the_horizon() {
        assert!((kasten_young_air_mass(0.0) - 1.0).abs() < 1e-3);
        // Kasten & Young 1989, Table: 37.92 at 90°.
        assert!((kasten_young_air_mass(90.0) - 37.92).abs() < 0.1);
        // Close to the older Kasten 1966 formula away from the horizon.
        assert!((kasten_young_air_mass(60.0) - air_mass(60.0)).abs() < 0.01);
    }

    #[test]
    fn the_bound_grows_with_the_sun_and_the_elevation() {
        let low = global_horizontal_bound_lux(10.0, 0.0, 172);
        let high = global_horizontal_bound_lux(60.0, 0.0, 172);
        let mountain = global_horizontal_bound_lux(60.0, 3000.0, 172);
        assert!(low < high && high < mountain, "{low} {high} {mountain}");
        // No clear sky gives 200 klx at 55° in Lausanne in May (the daemon reading).
        assert!(global_horizontal_bound_lux(55.5, 400.0, 129) < 200_000.0);
        assert_eq!(clear_sky_ghi_w_m2(-5.0, 0.0, 2.0, 1), 0.0);
        assert_eq!(clear_sky_ghi_w_m2(f64::NAN, 0.0, 2.0, 1), 0.0);
    }

    /// A horizontal sensor behind glazing of transmittance 0.5 that sees the whole sky and the
    /// sun: its daylight factor is 0.5 in every direction, so the bound is half the outdoor
    /// light; the sun counted twice (in its patch and as a source) exceeds it.
    #[test]
    fn the_interior_bound_is_the_rooms_highest_daylight_factor_and_catches_a_double_count() {
        use crate::sun::ExtractedSun;
        use glam::DVec3;
        let patches = crate::sky::SkyPatches::tregenza();
        let n = patches.len();
        let tau = 0.5;
        let mut row: Vec<f64> = (0..n)
            .map(|p| tau * patches.centre(p).z * patches.solid_angle_sr(p))
            .collect();
        row.extend(std::iter::repeat_n(0.0, n));
        let dc = DaylightCoefficients {
            sensors: vec!["S1".into()],
            mf: 1,
            bins: 2 * n,
            lux_per_cd_m2: row.clone(),
            samples_per_sensor: 1,
        };
        let sky_cd_m2 = 5000.0;
        let sky_h: f64 = (0..n)
            .map(|p| sky_cd_m2 * patches.centre(p).z * patches.solid_angle_sr(p))
            .sum();
        let altitude = 30f64.to_radians();
        let direction = DVec3::new(0.0, -altitude.cos(), altitude.sin());
        let dn_lux = 80_000.0;
        let outdoor = sky_h + dn_lux * direction.z;
        let mut bins = vec![sky_cd_m2; n];
        bins.extend(std::iter::repeat_n(f64::NAN, n));
        let sky_lux: f64 = (0..n).map(|p| row[p] * sky_cd_m2).sum();
        let terms = CaptureTerms {
            sun: Some(ExtractedSun {
                direction,
                disk_luminance_cd_m2: dn_lux / crate::sun::SOLAR_DISK_SR,
                direct_normal_illuminance_lux: dn_lux,
                background_cd_m2: sky_cd_m2,
                groups: vec![],
                flags: vec![],
            }),
            sun_missing: None,
            sky_with_sun_lux: vec![sky_lux],
            sky_without_sun_lux: vec![sky_lux],
            sun_lux_per_dn_lux: vec![tau * direction.z],
            sun_dn_lux: dn_lux,
            unseen_ground_lux_per_cd_m2: vec![0.0],
            outdoor_horizontal_lux: outdoor,
            unseen_sky_fraction: 0.0,
            saturated_fraction: 0.0,
            bins_with_sun_cd_m2: bins.clone(),
            bins_without_sun_cd_m2: bins,
            bin_seen: vec![true; 2 * n],
        };
        let bound = interior_bound_lux(&dc, &terms, 0.2)[0];
        let right = sky_lux + tau * direction.z * dn_lux;
        assert!((bound / (tau * outdoor) - 1.0).abs() < 1e-9, "{bound}");
        assert!(right <= bound * (1.0 + 1e-9), "{right} > {bound}");
        // The beam also spread over its patch (as the map holds it) and added again.
        let twice = right + tau * direction.z * dn_lux;
        assert!(twice > 1.5 * bound, "{twice} vs {bound}");
    }
}
