//! Sun tracking over a campaign (`skylux sun`): per capture, the HDR map (the shared
//! [`map_capture`] path), the sun extracted from it as the loop extracts it, its measured
//! altitude and azimuth next to SPA's, its disk luminance and direct-normal illuminance, and
//! where the disk is saturated even in the shortest exposure, the pyranometer's DNI instead.
//! From the sightings, the camera's orientation (and optionally its principal point), the
//! residual in degrees, and the `device.toml` that follows.
//!
//! The pyranometer's W/m² become lux through the Perez et al. (1990) direct luminous efficacy
//! for the pyranometer's own irradiances, as gendaylit converts them
//! ([`crate::sky::perez::PerezSky::direct_normal_illuminance_lux`]), the conversion the loop's
//! Perez baseline and the simulated world use.

use super::extract::{extract_sun, NoSun, SunFlag, SunSearch, SOLAR_DISK_SR};
use super::orientation::{fit_orientation, OrientationError, SunObservation};
use super::position::{angle_between_deg, solar_position, Atmosphere, Site};
use super::principal_point::{fit_orientation_and_principal_point, CameraFitError};
use crate::camera::{CameraModel, DeviceConfig, ImagePoint};
use crate::campaign::{Campaign, CaptureEntry};
use crate::hdr::{map_capture, CaptureMapError};
use crate::io::irradiance::PyranometerTable;
use crate::output::plot::PlotError;
use crate::output::WriteError;
use crate::sky::perez::{PerezConditions, PerezInput, PerezSky};
use chrono::{DateTime, Datelike, FixedOffset, TimeDelta, Utc};
use glam::DVec3;
use serde::Serialize;
use std::path::PathBuf;

pub use super::tracking_files::{csv_text, write_csv, write_plot, CSV_HEADER};

/// How the sun is looked for and referenced.
#[derive(Clone, Debug)]
pub struct TrackingOptions {
    /// Groups at or above this luminance are sun candidates, cd/m².
    pub threshold_cd_m2: f64,
    /// A bright component farther than this from SPA's sun is not the sun, degrees. 12°, as
    /// the loop searches: an orientation error of several degrees must not hide the sun.
    pub max_offset_deg: f64,
    /// A pyranometer row matches a capture within this time (the loop's Perez baseline uses
    /// 5 minutes).
    pub pyranometer_window: TimeDelta,
    /// Compare with the apparent sun (SPA with refraction for the standard atmosphere at the
    /// site's elevation, pvlib's 12 °C) instead of the geometric one. Field data needs it
    /// (refraction lifts the sun by 0.1° at 10° altitude); the simulator renders the
    /// geometric sun, as the loop assumes.
    pub refraction: bool,
}

impl Default for TrackingOptions {
    fn default() -> Self {
        Self {
            threshold_cd_m2: crate::sun::extract::SUNSHINE_THRESHOLD_CD_M2,
            max_offset_deg: 12.0,
            pyranometer_window: TimeDelta::minutes(5),
            refraction: false,
        }
    }
}

/// SPA's sun farther than this from every imaged group is out of view, degrees: the disk's
/// radius (0.27°) plus the diagonal of a group at skip 8 (16 px at f = 1136 px: 0.8°).
const OUT_OF_VIEW_DEG: f64 = 1.1;

/// Where a capture's direct-normal illuminance comes from.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum DniSource {
    /// Measured on the map: the disk's flux above the circumsolar background.
    Map,
    /// The disk is saturated even in the shortest exposure: the pyranometer's DNI.
    Pyranometer,
    /// Neither.
    None,
}

impl DniSource {
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Map => "map",
            Self::Pyranometer => "pyranometer",
            Self::None => "none",
        }
    }
}

/// The pyranometer at a capture's time, in lux.
#[derive(Clone, Debug, PartialEq)]
pub struct PyranometerDni {
    /// Direct normal irradiance (measured, or derived from GHI and DHI), W/m².
    pub dni_w_m2: f64,
    /// The same as illuminance through the Perez 1990 direct efficacy, lux.
    pub dni_lux: f64,
    /// Difference between the row's stamp and the capture's, seconds.
    pub offset_s: f64,
}

/// One capture's sun.
#[derive(Clone, Debug)]
pub struct SunTrack {
    pub time: DateTime<FixedOffset>,
    pub capture_dir: PathBuf,
    /// SPA's sun (geometric or apparent, as [`TrackingOptions::refraction`] says).
    pub spa_direction: DVec3,
    /// The extracted sun through the camera model it was extracted with.
    pub measured_direction: Option<DVec3>,
    /// Where the extracted sun is on the image (full-array pixels).
    pub image_point: Option<ImagePoint>,
    /// Mean luminance over the disk, cd/m² (from the map, or from the pyranometer's DNI).
    pub disk_luminance_cd_m2: Option<f64>,
    /// Direct-normal illuminance, lux (from the map, or from the pyranometer's DNI).
    pub dni_lux: Option<f64>,
    pub dni_source: DniSource,
    /// The pyranometer at this time, if the campaign has a matching row.
    pub pyranometer: Option<PyranometerDni>,
    /// The extraction's flags.
    pub flags: Vec<SunFlag>,
    /// Why there is no sun, a short machine-readable tag (e.g. `below_threshold`).
    pub no_sun: Option<&'static str>,
    /// What the caller must know, in words (the no-sun reason, a failed fallback).
    pub note: Option<String>,
}

impl SunTrack {
    /// Angle between the measured and SPA's sun, degrees.
    pub fn error_deg(&self) -> Option<f64> {
        self.measured_direction
            .map(|m| angle_between_deg(m, self.spa_direction))
    }

    /// Whether this sighting may enter an orientation fit: a sun was found on the image and
    /// not flagged as partly covered (a cloud shifts its centroid).
    pub fn usable_for_fit(&self) -> bool {
        self.image_point.is_some() && !self.flags.contains(&SunFlag::PartlyCovered)
    }

    /// The reference disk luminance from the pyranometer, cd/m².
    pub fn reference_luminance_cd_m2(&self) -> Option<f64> {
        self.pyranometer.as_ref().map(|p| p.dni_lux / SOLAR_DISK_SR)
    }
}

/// Why tracking could not run. Every variant names the file or folder.
#[derive(Debug, thiserror::Error)]
pub enum TrackingError {
    #[error(transparent)]
    Capture(#[from] CaptureMapError),
    #[error("{path}: {message}")]
    Sun { path: PathBuf, message: String },
    #[error(transparent)]
    Write(#[from] WriteError),
    #[error(transparent)]
    Plot(#[from] PlotError),
}

/// The site of a campaign, for SPA.
pub fn campaign_site(campaign: &Campaign) -> Site {
    Site {
        latitude_deg: campaign.config.site.latitude_deg,
        longitude_deg: campaign.config.site.longitude_deg,
        elevation_m: campaign.config.site.elevation_m,
    }
}

/// The pyranometer's DNI at `time` (nearest row within `window`), in W/m² and in lux.
/// `None` without a matching row, or where neither DNI nor GHI and DHI are given, or where
/// the sun is below the horizon.
pub fn pyranometer_dni(
    table: &PyranometerTable,
    time: DateTime<FixedOffset>,
    sun: DVec3,
    window: TimeDelta,
) -> Option<PyranometerDni> {
    let row = table
        .rows
        .iter()
        .filter(|r| (r.time - time).abs() <= window)
        .min_by_key(|r| (r.time - time).abs())?;
    if sun.z <= 0.0 {
        return None;
    }
    // DHI where only GHI and DNI are given: GHI = DNI sin h + DHI (campaign.md).
    let dhi = row
        .dhi_wm2
        .or_else(|| Some(row.ghi_wm2? - row.dni_wm2? * sun.z));
    let input = match (row.dni_wm2, dhi, row.ghi_wm2) {
        (Some(dni), Some(dhi), _) => PerezInput::DirectNormalDiffuse {
            direct_normal_w_m2: dni,
            diffuse_horizontal_w_m2: dhi.max(0.0),
        },
        (None, Some(dhi), Some(ghi)) => PerezInput::GlobalDiffuse {
            global_horizontal_w_m2: ghi,
            diffuse_horizontal_w_m2: dhi,
        },
        _ => return None,
    };
    let conditions = PerezConditions {
        day_of_year: time.ordinal() as u16,
        ..PerezConditions::gendaylit_ang(sun)
    };
    let sky = PerezSky::new(input, &conditions).ok()?;
    let dni_w_m2 = sky.direct_normal_irradiance_w_m2();
    let dni_lux = sky.direct_normal_illuminance_lux();
    (dni_w_m2.is_finite() && dni_lux.is_finite()).then(|| PyranometerDni {
        dni_w_m2,
        dni_lux,
        offset_s: (row.time - time).num_milliseconds() as f64 / 1000.0,
    })
}

/// SPA's sun for a capture time: geometric, or apparent for the standard atmosphere.
fn spa_sun(
    time: DateTime<FixedOffset>,
    site: &Site,
    refraction: bool,
) -> Result<DVec3, super::SunError> {
    let atmosphere = refraction.then(|| Atmosphere::standard_at(site.elevation_m));
    Ok(solar_position(time.with_timezone(&Utc), site, atmosphere.as_ref())?.direction())
}

/// Tracks the sun in one capture with the camera `device`.
pub fn track_capture(
    entry: &CaptureEntry,
    device: &DeviceConfig,
    site: &Site,
    pyranometer: Option<&PyranometerTable>,
    options: &TrackingOptions,
) -> Result<SunTrack, TrackingError> {
    let spa = spa_sun(entry.time, site, options.refraction).map_err(|e| TrackingError::Sun {
        path: entry.dir.join("capture.toml"),
        message: e.to_string(),
    })?;
    let reference =
        pyranometer.and_then(|t| pyranometer_dni(t, entry.time, spa, options.pyranometer_window));
    let mut track = SunTrack {
        time: entry.time,
        capture_dir: entry.dir.clone(),
        spa_direction: spa,
        measured_direction: None,
        image_point: None,
        disk_luminance_cd_m2: None,
        dni_lux: None,
        dni_source: DniSource::None,
        pyranometer: reference,
        flags: vec![],
        no_sun: None,
        note: None,
    };
    if spa.z <= 0.0 {
        track.no_sun = Some("below_horizon");
        track.note = Some("the sun is below the horizon".into());
        return Ok(track);
    }
    let merged = map_capture(&entry.dir, device)?;
    let search = SunSearch {
        threshold_cd_m2: options.threshold_cd_m2,
        predicted_direction: Some(spa),
        max_offset_deg: options.max_offset_deg,
        ..Default::default()
    };
    let sun = match extract_sun(&merged.map, &merged.geometry, &search) {
        Ok(sun) => sun,
        Err(reason) => {
            record_no_sun(&mut track, &reason, &merged.geometry.direction, spa);
            return Ok(track);
        }
    };
    let camera = CameraModel::new(device.clone());
    track.measured_direction = Some(sun.direction);
    track.image_point = camera.project(sun.direction);
    track.flags = sun.flags.clone();
    if sun.flags.contains(&SunFlag::Saturated) {
        take_pyranometer_dni(&mut track);
    } else if sun.direct_normal_illuminance_lux.is_finite() {
        track.dni_lux = Some(sun.direct_normal_illuminance_lux);
        track.disk_luminance_cd_m2 = Some(sun.disk_luminance_cd_m2);
        track.dni_source = DniSource::Map;
    }
    Ok(track)
}

/// Why no sun was found. Nothing bright, and SPA's sun off the imaged field (`directions`,
/// per group): it is out of view, not hidden (the extraction only knows there is no imaged
/// group near it when none is within its search radius).
fn record_no_sun(track: &mut SunTrack, reason: &NoSun, directions: &[glam::Vec3], spa: DVec3) {
    track.no_sun = Some(reason.tag());
    track.note = Some(reason.to_string());
    if matches!(reason, NoSun::BelowThreshold { .. }) {
        let cos_nearest = directions
            .iter()
            .filter(|d| d.is_finite())
            .map(|d| d.as_dvec3().dot(spa))
            .fold(-1.0f64, f64::max);
        let nearest_deg = cos_nearest.clamp(-1.0, 1.0).acos().to_degrees();
        if nearest_deg > OUT_OF_VIEW_DEG {
            track.no_sun = Some("outside_field_of_view");
            track.note = Some(format!(
                "{reason}; SPA's sun is {nearest_deg:.1} deg from the nearest imaged \
                 group (declared camera): outside the field of view"
            ));
        }
    }
}

/// A disk saturated even in the shortest exposure: the pyranometer's DNI where there is one.
fn take_pyranometer_dni(track: &mut SunTrack) {
    match &track.pyranometer {
        Some(p) if p.dni_lux > 0.0 => {
            track.dni_lux = Some(p.dni_lux);
            track.disk_luminance_cd_m2 = Some(p.dni_lux / SOLAR_DISK_SR);
            track.dni_source = DniSource::Pyranometer;
        }
        Some(p) => {
            track.note = Some(format!(
                "the disk is saturated but the pyranometer's DNI is {:.1} W/m2: no DNI",
                p.dni_w_m2
            ));
        }
        None => {
            track.note = Some(
                "the disk is saturated even in the shortest exposure and no pyranometer \
                 DNI matches this time: no DNI"
                    .into(),
            );
        }
    }
}

/// Tracks the sun in every capture of the campaign; `progress(done, total)`.
pub fn track_campaign(
    campaign: &Campaign,
    device: &DeviceConfig,
    options: &TrackingOptions,
    progress: &dyn Fn(usize, usize),
) -> Result<Vec<SunTrack>, TrackingError> {
    let site = campaign_site(campaign);
    let n = campaign.captures.len();
    let mut out = Vec::with_capacity(n);
    for (i, entry) in campaign.captures.iter().enumerate() {
        progress(i, n);
        out.push(track_capture(
            entry,
            device,
            &site,
            campaign.pyranometer.as_ref(),
            options,
        )?);
    }
    progress(n, n);
    Ok(out)
}

/// Figures of a tracking run.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct TrackingSummary {
    pub captures: usize,
    /// Captures with a sun found on the map.
    pub suns: usize,
    pub saturated: usize,
    pub partly_covered: usize,
    /// Captures whose DNI came from the pyranometer.
    pub dni_from_pyranometer: usize,
    /// Angle between measured and SPA sun over the suns found, degrees.
    pub direction_rms_deg: Option<f64>,
    pub direction_max_deg: Option<f64>,
    /// Relative RMSE of the map's disk luminance against the pyranometer's (where both
    /// exist), and over how many captures.
    pub luminance_rel_rmse: Option<f64>,
    pub luminance_compared: usize,
}

fn rms(values: &[f64]) -> Option<f64> {
    (!values.is_empty())
        .then(|| (values.iter().map(|v| v * v).sum::<f64>() / values.len() as f64).sqrt())
}

/// Counts and error figures of `tracks`; `directions` overrides the measured directions
/// (e.g. through a fitted camera), index by index.
pub fn summarise(tracks: &[SunTrack], directions: Option<&[Option<DVec3>]>) -> TrackingSummary {
    let errors: Vec<f64> = tracks
        .iter()
        .enumerate()
        .filter_map(|(i, t)| {
            let m = match directions {
                Some(d) => d.get(i).copied().flatten(),
                None => t.measured_direction,
            }?;
            Some(angle_between_deg(m, t.spa_direction))
        })
        .collect();
    let rel: Vec<f64> = tracks
        .iter()
        .filter(|t| t.dni_source == DniSource::Map)
        .filter_map(|t| {
            let reference = t.reference_luminance_cd_m2().filter(|r| *r > 0.0)?;
            Some(t.disk_luminance_cd_m2? / reference - 1.0)
        })
        .collect();
    TrackingSummary {
        captures: tracks.len(),
        suns: tracks
            .iter()
            .filter(|t| t.measured_direction.is_some())
            .count(),
        saturated: tracks
            .iter()
            .filter(|t| t.flags.contains(&SunFlag::Saturated))
            .count(),
        partly_covered: tracks
            .iter()
            .filter(|t| t.flags.contains(&SunFlag::PartlyCovered))
            .count(),
        dni_from_pyranometer: tracks
            .iter()
            .filter(|t| t.dni_source == DniSource::Pyranometer)
            .count(),
        direction_rms_deg: rms(&errors),
        direction_max_deg: (!errors.is_empty()).then(|| errors.iter().cloned().fold(0.0, f64::max)),
        luminance_rel_rmse: rms(&rel),
        luminance_compared: rel.len(),
    }
}

/// What to fit from the sightings.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum FitTarget {
    Orientation,
    OrientationAndPrincipalPoint,
}

/// Why no camera fit could be made.
#[derive(Debug, thiserror::Error)]
pub enum FitError {
    #[error("{usable} usable sun sightings among {captures} captures (a sun found and not partly covered): at least {needed} are needed")]
    TooFewSightings {
        usable: usize,
        captures: usize,
        needed: usize,
    },
    #[error(transparent)]
    Orientation(#[from] OrientationError),
    #[error(transparent)]
    Camera(#[from] CameraFitError),
}

/// A camera fitted to a campaign's sun sightings.
#[derive(Clone, Debug)]
pub struct SunFit {
    /// The declared camera with the fitted orientation (and principal point).
    pub device: DeviceConfig,
    pub target: FitTarget,
    /// Indices (into the tracks) of the sightings the fit used: those not partly covered,
    /// and of those the unsaturated ones if there are enough (see [`fit_camera`]).
    pub used: Vec<usize>,
    /// Indices of sightings dropped as outliers (e.g. a reflection taken for the sun).
    pub dropped: Vec<usize>,
    /// Residual per used sighting, degrees, and its RMS and maximum.
    pub residuals_deg: Vec<f64>,
    pub residual_rms_deg: f64,
    pub residual_max_deg: f64,
    /// Standard error of the fitted principal point, pixels (principal-point fits only).
    pub center_sd_px: Option<[f64; 2]>,
}

/// Residual above which a sighting is an outlier: 5 times the median residual of a first fit,
/// and at least 0.2°, well above the centroid noise (a few hundredths of a degree) and below
/// a reflection or a cloud edge taken for the sun.
const OUTLIER_FACTOR: f64 = 5.0;
const OUTLIER_FLOOR_DEG: f64 = 0.2;

/// A fitted camera, its residual per sighting (degrees) and the principal point's standard
/// error (pixels) when it was fitted.
type FitOnce = (DeviceConfig, Vec<f64>, Option<[f64; 2]>);

fn fit_once(
    device: &DeviceConfig,
    sightings: &[SunObservation],
    target: FitTarget,
) -> Result<FitOnce, FitError> {
    let mut fitted = device.clone();
    match target {
        FitTarget::Orientation => {
            let f = fit_orientation(device, sightings)?;
            fitted.orientation = f.orientation;
            Ok((fitted, f.residuals_deg, None))
        }
        FitTarget::OrientationAndPrincipalPoint => {
            let f = fit_orientation_and_principal_point(device, sightings)?;
            fitted.orientation = f.orientation;
            fitted.lens.center_px = f.center_px;
            Ok((fitted, f.residuals_deg, Some(f.center_sd_px)))
        }
    }
}

/// Fits the camera to the usable sightings of `tracks` (extracted with `device`): those
/// not partly covered, and only the unsaturated ones when there are at least 3 (and as many
/// as the fit needs). Drops the sightings beyond the outlier limit of a first fit, and
/// refits once.
pub fn fit_camera(
    device: &DeviceConfig,
    tracks: &[SunTrack],
    target: FitTarget,
) -> Result<SunFit, FitError> {
    let needed = match target {
        FitTarget::Orientation => 2,
        FitTarget::OrientationAndPrincipalPoint => 4,
    };
    let mut used: Vec<usize> = (0..tracks.len())
        .filter(|&i| tracks[i].usable_for_fit())
        .collect();
    if used.len() < needed {
        return Err(FitError::TooFewSightings {
            usable: used.len(),
            captures: tracks.len(),
            needed,
        });
    }
    // A saturated disk gives only the geometric centre of its over-range groups (about a
    // tenth of a degree at skip 4, against hundredths for a measured disk): such sightings
    // enter the fit only when the measured ones are too few.
    let measured: Vec<usize> = used
        .iter()
        .copied()
        .filter(|&i| !tracks[i].flags.contains(&SunFlag::Saturated))
        .collect();
    if measured.len() >= needed.max(3) {
        used = measured;
    }
    let observations = |idx: &[usize]| -> Vec<SunObservation> {
        idx.iter()
            .map(|&i| SunObservation {
                image_point: tracks[i].image_point.expect("usable"),
                sun_direction: tracks[i].spa_direction,
            })
            .collect()
    };
    let (mut fitted, mut residuals, mut center_sd) =
        fit_once(device, &observations(&used), target)?;
    let mut sorted = residuals.clone();
    sorted.sort_by(f64::total_cmp);
    let limit = (OUTLIER_FACTOR * sorted[sorted.len() / 2]).max(OUTLIER_FLOOR_DEG);
    let outliers: Vec<usize> = used
        .iter()
        .zip(&residuals)
        .filter(|(_, r)| **r > limit)
        .map(|(i, _)| *i)
        .collect();
    let mut dropped = vec![];
    if !outliers.is_empty() && used.len() - outliers.len() >= needed {
        used.retain(|i| !outliers.contains(i));
        (fitted, residuals, center_sd) = fit_once(device, &observations(&used), target)?;
        dropped = outliers;
    }
    let n = residuals.len() as f64;
    Ok(SunFit {
        device: fitted,
        target,
        used,
        dropped,
        residual_rms_deg: (residuals.iter().map(|r| r * r).sum::<f64>() / n).sqrt(),
        residual_max_deg: residuals.iter().cloned().fold(0.0, f64::max),
        residuals_deg: residuals,
        center_sd_px: center_sd,
    })
}

/// The sightings' directions through another camera (e.g. the fitted one): each image point
/// unprojected with `device`.
pub fn reproject(tracks: &[SunTrack], device: &DeviceConfig) -> Vec<Option<DVec3>> {
    let camera = CameraModel::new(device.clone());
    tracks
        .iter()
        .map(|t| t.image_point.and_then(|p| camera.unproject(p)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::irradiance::PyranometerRow;

    fn time(text: &str) -> DateTime<FixedOffset> {
        DateTime::parse_from_rfc3339(text).unwrap()
    }

    /// The pyranometer's DNI is matched within the window, converted with the Perez direct
    /// efficacy (between 50 and 130 lm/W for a clear sky), and derived from GHI and DHI when
    /// DNI is missing.
    #[test]
    fn pyranometer_dni_matches_and_converts() {
        let t = time("2017-05-08T12:00:00+02:00");
        let sun = DVec3::new(0.2, -0.5, 0.84).normalize();
        let row = |dt: i64, dni: Option<f64>| PyranometerRow {
            time: t + TimeDelta::seconds(dt),
            ghi_wm2: Some(850.0 * sun.z + 110.0),
            dhi_wm2: Some(110.0),
            dni_wm2: dni,
        };
        let table = PyranometerTable {
            rows: vec![row(-600, Some(100.0)), row(120, Some(850.0))],
            ignored_columns: vec![],
        };
        let p = pyranometer_dni(&table, t, sun, TimeDelta::minutes(5)).unwrap();
        assert_eq!(p.dni_w_m2, 850.0);
        assert_eq!(p.offset_s, 120.0);
        let efficacy = p.dni_lux / p.dni_w_m2;
        assert!((50.0..130.0).contains(&efficacy), "{efficacy} lm/W");
        // Nothing within the window.
        assert!(
            pyranometer_dni(&table, t + TimeDelta::hours(1), sun, TimeDelta::minutes(5)).is_none()
        );
        // DNI derived from GHI and DHI.
        let table = PyranometerTable {
            rows: vec![row(0, None)],
            ignored_columns: vec![],
        };
        let p = pyranometer_dni(&table, t, sun, TimeDelta::minutes(5)).unwrap();
        assert!((p.dni_w_m2 - 850.0).abs() < 1e-9, "{}", p.dni_w_m2);
        // The sun below the horizon: no DNI.
        assert!(pyranometer_dni(&table, t, -sun, TimeDelta::minutes(5)).is_none());
    }
}
