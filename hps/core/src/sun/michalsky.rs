//! A short, cheap solar position for comparison with SPA: the Astronomical Almanac's low-precision
//! formulas as given by Michalsky (J. J. Michalsky, "The Astronomical Almanac's algorithm for
//! approximate solar position (1950–2050)", Solar Energy 40(3):227–235, 1988), with the azimuth
//! written as one atan2, which is the quadrant fix of Spencer's comment (Solar Energy 42(4):353,
//! 1989). Stated accuracy 0.01° for 1950–2050. No nutation, no parallax, no ΔT: the few
//! thousandths of a degree these are worth are inside that figure.
//!
//! `tests/solar_position.rs` measures its error against pvlib's SPA.

use super::position::{check_atmosphere, check_site, refraction_deg};
use super::{Atmosphere, Site, SolarPosition, SunError};
use chrono::{DateTime, Utc};

/// Julian day of the Unix epoch, 1970-01-01T00:00Z.
const UNIX_EPOCH_JD: f64 = 2_440_587.5;
/// J2000.0 = 2000-01-01T12:00 (Julian day).
const J2000_JD: f64 = 2_451_545.0;

/// The sun's position after Michalsky (1988); refraction, if asked for, is SPA's
/// ([`refraction_deg`]) so that only the ephemeris differs from [`super::solar_position`].
pub fn solar_position_michalsky(
    time_utc: DateTime<Utc>,
    site: &Site,
    atmosphere: Option<&Atmosphere>,
) -> Result<SolarPosition, SunError> {
    check_site(site)?;
    if let Some(a) = atmosphere {
        check_atmosphere(a)?;
    }
    // Seconds since the epoch are exact in f64 for any chrono date; days then keep ~1e-11 d.
    let unix_s = time_utc.timestamp() as f64 + f64::from(time_utc.timestamp_subsec_nanos()) * 1e-9;
    let n = unix_s / 86_400.0 + UNIX_EPOCH_JD - J2000_JD;

    // Mean longitude and mean anomaly (degrees), ecliptic longitude, obliquity.
    let mean_longitude_deg = (280.460 + 0.985_647_4 * n).rem_euclid(360.0);
    let mean_anomaly = (357.528 + 0.985_600_3 * n).rem_euclid(360.0).to_radians();
    let ecliptic_longitude =
        (mean_longitude_deg + 1.915 * mean_anomaly.sin() + 0.020 * (2.0 * mean_anomaly).sin())
            .rem_euclid(360.0)
            .to_radians();
    let obliquity = (23.439 - 0.000_000_4 * n).to_radians();

    let right_ascension =
        (obliquity.cos() * ecliptic_longitude.sin()).atan2(ecliptic_longitude.cos());
    let declination = (obliquity.sin() * ecliptic_longitude.sin()).asin();

    // Greenwich mean sidereal time in hours; n counts from noon, so 6.697375 h + 12 h is GMST
    // at J2000.0 and n·0.0657098242 + UT-hours advances it at the sidereal rate.
    let ut_hours = (unix_s / 3600.0).rem_euclid(24.0);
    let gmst_h = (6.697_375 + 0.065_709_824_2 * n + ut_hours).rem_euclid(24.0);
    let lmst_deg = gmst_h * 15.0 + site.longitude_deg;
    let hour_angle = (lmst_deg - right_ascension.to_degrees()).to_radians();

    let lat = site.latitude_deg.to_radians();
    let sin_elevation =
        declination.sin() * lat.sin() + declination.cos() * lat.cos() * hour_angle.cos();
    let elevation_deg = sin_elevation.clamp(-1.0, 1.0).asin().to_degrees();
    let azimuth_deg = (-declination.cos() * hour_angle.sin())
        .atan2(declination.sin() * lat.cos() - declination.cos() * hour_angle.cos() * lat.sin())
        .to_degrees()
        .rem_euclid(360.0);

    let geometric_zenith_deg = 90.0 - elevation_deg;
    let zenith_deg = match atmosphere {
        Some(a) => geometric_zenith_deg - refraction_deg(elevation_deg, a),
        None => geometric_zenith_deg,
    };
    Ok(SolarPosition {
        zenith_deg,
        azimuth_deg,
        geometric_zenith_deg,
    })
}
