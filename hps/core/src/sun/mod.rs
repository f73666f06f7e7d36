//! The sun: where it is (NREL SPA, with ΔT and refraction), a short formula to compare, and
//! its extraction from a measured luminance map or from the fabric's accumulators.

mod delta_t;
pub mod extract;
pub mod fabric;
mod michalsky;
pub mod orientation;
pub mod position;
pub mod principal_point;
pub mod tracking;
mod tracking_files;

pub use delta_t::{delta_t_s, DELTA_T_YEARS};
pub use extract::{
    extract_sun, extraction_work, remove_sun, ExtractedSun, NoSun, SunFlag, SunSearch,
    SOLAR_DISK_SR, SUNSHINE_THRESHOLD_CD_M2,
};
pub use fabric::{
    check_sums, fabric_background_cd_m2, sun_from_fabric, FabricSun, FabricSunSearch, SunExposure,
    FABRIC_THRESHOLD_CD_M2,
};
pub use michalsky::solar_position_michalsky;
pub use orientation::{
    fit_azimuth, fit_orientation, OrientationError, OrientationFit, SunObservation,
};
pub use position::{
    angle_between_deg, parse_time_utc, refraction_deg, solar_position, solar_position_with_delta_t,
    sun_direction, Atmosphere, Site, SolarPosition, REFRACTION_CUTOFF_ELEVATION_DEG,
};
pub use principal_point::{fit_orientation_and_principal_point, CameraFit, CameraFitError};

use chrono::{DateTime, Utc};

/// Why a solar position could not be computed; each names the offending input.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum SunError {
    #[error("latitude_deg {value} is outside [-90, 90]")]
    Latitude { value: f64 },
    #[error("longitude_deg {value} is outside [-180, 180] (east positive)")]
    Longitude { value: f64 },
    #[error("elevation_m {value} is not a finite height above -6 500 000 m")]
    Elevation { value: f64 },
    #[error("pressure_hpa {value} is outside (0, 5000]")]
    Pressure { value: f64 },
    #[error("temperature_c {value} is outside (-273.15, 6000]")]
    Temperature { value: f64 },
    #[error("delta_t_s {value} is not finite")]
    DeltaT { value: f64 },
    #[error("month {month} is outside 1..=12")]
    Month { month: u32 },
    #[error("year {year} is outside -1999..=3000, where the ΔT estimate is defined")]
    DeltaTYear { year: i32 },
    #[error("time {text:?} is not RFC 3339 with an explicit offset (e.g. 2017-05-08T10:00:00+02:00): {message}")]
    Time { text: String, message: String },
    #[error("SPA cannot evaluate {time}: {message}")]
    Spa {
        time: DateTime<Utc>,
        message: String,
    },
}
