//! Where the sun is, seen from a site: NREL SPA with atmospheric refraction.
//!
//! The ephemeris is the NREL Solar Position Algorithm (Reda & Andreas, "Solar position algorithm
//! for solar radiation applications", Solar Energy 76(5):577–589, 2004, and the 2007
//! corrigendum; stated uncertainty ±0.0003° for years −2000..6000), as implemented by the
//! `solar-positioning` crate. ΔT comes from [`delta_t_s`](super::delta_t_s), which follows pvlib.
//! Refraction is SPA's own (eq. 41–42), applied here so that one SPA evaluation yields both the
//! geometric and the apparent zenith. `tests/solar_position.rs` checks the result against
//! pvlib's independent SPA (`pvlib.solarposition.spa_python`).

use super::{delta_t_s, SunError};
use chrono::{DateTime, Datelike, Utc};
use glam::DVec3;
use solar_positioning::{Location, SolarPositions};

/// Where the observer stands. Longitude is positive east (campaign.md), elevation above sea
/// level (it sets SPA's topocentric parallax, at most 8.8 arcseconds).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Site {
    pub latitude_deg: f64,
    pub longitude_deg: f64,
    pub elevation_m: f64,
}

/// The air that bends the sunlight: local (station) pressure and temperature.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Atmosphere {
    pub pressure_hpa: f64,
    pub temperature_c: f64,
}

impl Atmosphere {
    /// pvlib's default temperature when none is measured (`spa_python`, 12 °C).
    pub const DEFAULT_TEMPERATURE_C: f64 = 12.0;

    /// The standard atmosphere at `elevation_m`, with [`Self::DEFAULT_TEMPERATURE_C`].
    ///
    /// Pressure as `pvlib.atmosphere.alt2pres`: p = ((44331.514 − h) / 11880.516) ^ (1 / 0.1902632)
    /// hPa (1013.25 hPa at sea level), the U.S. Standard Atmosphere 1976 troposphere solved for
    /// pressure.
    pub fn standard_at(elevation_m: f64) -> Self {
        let base = ((44331.514 - elevation_m) / 11880.516).max(0.0);
        Self {
            pressure_hpa: base.powf(1.0 / 0.1902632),
            temperature_c: Self::DEFAULT_TEMPERATURE_C,
        }
    }
}

/// The sun's topocentric position. Azimuth is from north towards east (east = 90°), as in
/// campaign.md.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolarPosition {
    /// Apparent zenith if refraction was applied, else equal to `geometric_zenith_deg`.
    pub zenith_deg: f64,
    /// Azimuth in [0, 360); refraction does not change it.
    pub azimuth_deg: f64,
    /// Zenith of the straight line to the sun, without refraction.
    pub geometric_zenith_deg: f64,
}

impl SolarPosition {
    /// Altitude above the horizon, 90° − zenith.
    pub fn altitude_deg(&self) -> f64 {
        90.0 - self.zenith_deg
    }

    /// Unit vector towards the sun in the world frame (+x east, +y north, +z up).
    pub fn direction(&self) -> DVec3 {
        sun_direction(self.zenith_deg, self.azimuth_deg)
    }
}

/// Unit vector of a zenith/azimuth pair in the world frame (+x east, +y north, +z up), azimuth
/// from north towards east.
pub fn sun_direction(zenith_deg: f64, azimuth_deg: f64) -> DVec3 {
    let (sin_z, cos_z) = zenith_deg.to_radians().sin_cos();
    let (sin_a, cos_a) = azimuth_deg.to_radians().sin_cos();
    DVec3::new(sin_z * sin_a, sin_z * cos_a, cos_z)
}

/// Angle between two directions in degrees; atan2 of cross and dot keeps it accurate at
/// the microdegree scale where acos of the dot product loses all precision.
pub fn angle_between_deg(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b)).to_degrees()
}

/// Lowest geometric elevation at which SPA applies refraction: the sun's upper limb is still
/// above the horizon, −(0.26667° semi-diameter + 0.5667° refraction at the horizon)
/// (Reda & Andreas 2004, §3.14; pvlib's `atmos_refract` default).
pub const REFRACTION_CUTOFF_ELEVATION_DEG: f64 = -(0.26667 + 0.5667);

/// Atmospheric refraction in degrees (how much it raises the sun) at geometric elevation
/// `elevation_deg`: SPA eq. 42 (Reda & Andreas 2004), Bennett's formula scaled by pressure and
/// temperature; zero below [`REFRACTION_CUTOFF_ELEVATION_DEG`].
pub fn refraction_deg(elevation_deg: f64, atmosphere: &Atmosphere) -> f64 {
    if elevation_deg < REFRACTION_CUTOFF_ELEVATION_DEG {
        return 0.0;
    }
    let phase_deg = elevation_deg + 10.3 / (elevation_deg + 5.11);
    (atmosphere.pressure_hpa / 1010.0) * (283.0 / (273.0 + atmosphere.temperature_c)) * 1.02
        / (60.0 * phase_deg.to_radians().tan())
}

/// The sun's position at `time_utc`, with ΔT estimated from the UTC date as pvlib does, and
/// refraction for `atmosphere` if given (`None`: the geometric position).
pub fn solar_position(
    time_utc: DateTime<Utc>,
    site: &Site,
    atmosphere: Option<&Atmosphere>,
) -> Result<SolarPosition, SunError> {
    let delta_t = delta_t_s(time_utc.year(), time_utc.month())?;
    solar_position_with_delta_t(time_utc, site, atmosphere, delta_t)
}

/// As [`solar_position`], with ΔT (TT − UT1, seconds) given, e.g. from IERS Bulletin A.
pub fn solar_position_with_delta_t(
    time_utc: DateTime<Utc>,
    site: &Site,
    atmosphere: Option<&Atmosphere>,
    delta_t_s: f64,
) -> Result<SolarPosition, SunError> {
    check_site(site)?;
    if let Some(a) = atmosphere {
        check_atmosphere(a)?;
    }
    if !delta_t_s.is_finite() {
        return Err(SunError::DeltaT { value: delta_t_s });
    }
    let location = Location {
        latitude: site.latitude_deg,
        longitude: site.longitude_deg,
    };
    let spa = SolarPositions::new()
        .at(&time_utc, location, site.elevation_m, delta_t_s, None)
        .map_err(|e| SunError::Spa {
            time: time_utc,
            message: e.to_string(),
        })?;
    let geometric_zenith_deg = spa.zenith_angle();
    let zenith_deg = match atmosphere {
        Some(a) => geometric_zenith_deg - refraction_deg(90.0 - geometric_zenith_deg, a),
        None => geometric_zenith_deg,
    };
    Ok(SolarPosition {
        zenith_deg,
        azimuth_deg: spa.azimuth(),
        geometric_zenith_deg,
    })
}

/// SPA's input ranges (Reda & Andreas 2004, Table 1) and the geographic ones; NaN fails every
/// comparison and is rejected with them.
pub(crate) fn check_site(site: &Site) -> Result<(), SunError> {
    if !(-90.0..=90.0).contains(&site.latitude_deg) {
        return Err(SunError::Latitude {
            value: site.latitude_deg,
        });
    }
    if !(-180.0..=180.0).contains(&site.longitude_deg) {
        return Err(SunError::Longitude {
            value: site.longitude_deg,
        });
    }
    if !(site.elevation_m.is_finite() && site.elevation_m >= -6_500_000.0) {
        return Err(SunError::Elevation {
            value: site.elevation_m,
        });
    }
    Ok(())
}

pub(crate) fn check_atmosphere(a: &Atmosphere) -> Result<(), SunError> {
    if !(a.pressure_hpa > 0.0 && a.pressure_hpa <= 5000.0) {
        return Err(SunError::Pressure {
            value: a.pressure_hpa,
        });
    }
    if !(a.temperature_c > -273.15 && a.temperature_c <= 6000.0) {
        return Err(SunError::Temperature {
            value: a.temperature_c,
        });
    }
    Ok(())
}

/// Parses an RFC 3339 time with an explicit offset (campaign.md) into UTC.
pub fn parse_time_utc(text: &str) -> Result<DateTime<Utc>, SunError> {
    DateTime::parse_from_rfc3339(text.trim())
        .map(|t| t.with_timezone(&Utc))
        .map_err(|e| SunError::Time {
            text: text.to_string(),
            message: e.to_string(),
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn direction_follows_the_campaign_frame() {
        let east_horizon = sun_direction(90.0, 90.0);
        assert!((east_horizon - DVec3::X).length() < 1e-12);
        let north_horizon = sun_direction(90.0, 0.0);
        assert!((north_horizon - DVec3::Y).length() < 1e-12);
        assert!((sun_direction(0.0, 123.0) - DVec3::Z).length() < 1e-12);
    }

    #[test]
    fn bad_inputs_are_errors_not_panics() {
        let t = parse_time_utc("2020-06-21T12:00:00Z").unwrap();
        let ok = Site {
            latitude_deg: 46.5,
            longitude_deg: 6.6,
            elevation_m: 400.0,
        };
        for site in [
            Site {
                latitude_deg: 90.1,
                ..ok
            },
            Site {
                latitude_deg: f64::NAN,
                ..ok
            },
            Site {
                longitude_deg: -180.5,
                ..ok
            },
            Site {
                elevation_m: f64::INFINITY,
                ..ok
            },
        ] {
            assert!(solar_position(t, &site, None).is_err(), "{site:?}");
        }
        let bad_air = Atmosphere {
            pressure_hpa: f64::NAN,
            temperature_c: 10.0,
        };
        assert!(solar_position(t, &ok, Some(&bad_air)).is_err());
        assert!(solar_position_with_delta_t(t, &ok, None, f64::NAN).is_err());
        assert!(parse_time_utc("2020-06-21 12:00").is_err());
        assert!(parse_time_utc("2020-06-21T12:00:00").is_err(), "no offset");
    }

    /// pvlib 0.16.1: alt2pres(0) = 101 324.999 Pa, alt2pres(2317) = 76 416.157 Pa.
    #[test]
    fn standard_pressure() {
        assert!((Atmosphere::standard_at(0.0).pressure_hpa - 1013.25).abs() < 0.001);
        assert!((Atmosphere::standard_at(2317.0).pressure_hpa - 764.1616).abs() < 0.001);
    }
}
