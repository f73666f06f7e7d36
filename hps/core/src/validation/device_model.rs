//! The device's model of the room's illuminance, per capture, decomposed so that the loop
//! can add effects without re-tracing: daylight coefficients of the room times the measured
//! sky (and ground) patches, plus the sun as a concentrated source, plus whatever the effects
//! add.
//!
//! What is expensive (HDR merge, sun extraction, daylight and sun coefficients) is computed
//! once per capture and per camera orientation; an effect's parameters then only rescale or
//! add terms, so a fit evaluates thousands of candidate parameter sets in milliseconds.

use crate::camera::{CameraModel, DeviceConfig};
use crate::campaign::Campaign;
use crate::engine::{self, DaylightCoefficients, EngineError, Settings, World};
use crate::hdr::{map_capture, GeometryCache, GroupGeometry, LuminanceMap, MapFlag};
use crate::scene::Sensor;
use crate::sky::SkyPatches;
use crate::sun::{extract_sun, remove_sun, solar_position, ExtractedSun, SunSearch};
use chrono::{DateTime, FixedOffset, Utc};
use glam::DVec3;
use std::f64::consts::PI;

/// Minimum fraction of a patch's solid angle the lens must see for the patch to count as
/// measured.
const MIN_COVERAGE: f64 = 0.3;

/// One capture as the model sees it: the merged map and the sun position from SPA.
pub struct CaptureData {
    pub time: DateTime<FixedOffset>,
    pub map: LuminanceMap,
    pub readout: crate::campaign::Readout,
    pub raw_width: usize,
    pub raw_height: usize,
    /// The sun from SPA (geometric, as the engine's sun).
    pub spa_sun: DVec3,
}

/// Per capture, what the model derives from the map under one camera orientation.
#[derive(Clone, Debug)]
pub struct CaptureTerms {
    /// The sun, if the map shows one.
    pub sun: Option<ExtractedSun>,
    /// Illuminance per sensor from the measured sky and the seen ground, with the sun left
    /// inside the map's patches (spread over its patch: the undersampled sun).
    pub sky_with_sun_lux: Vec<f64>,
    /// The same with the sun disk removed and filled from the circumsolar sky.
    pub sky_without_sun_lux: Vec<f64>,
    /// Per sensor, lux per lux of direct-normal illuminance, for the extracted sun's
    /// direction (0 without a sun).
    pub sun_lux_per_dn_lux: Vec<f64>,
    /// Direct-normal illuminance of the extracted sun, lux (0 without a sun).
    pub sun_dn_lux: f64,
    /// Per sensor, lux per cd/m² of the ground the lens does not see.
    pub unseen_ground_lux_per_cd_m2: Vec<f64>,
    /// Outdoor horizontal illuminance the map implies, lux.
    pub outdoor_horizontal_lux: f64,
    /// Fraction of the sky's daylight-coefficient weight (sensor-averaged) that falls on
    /// patches the lens did not see.
    pub unseen_sky_fraction: f64,
    /// Fraction of valid groups over-range.
    pub saturated_fraction: f64,
    /// Per bin (sky patches, then mirrored ground patches: the daylight coefficients'
    /// order), the map's luminance with the sun left in, cd/m²: unseen sky patches filled as
    /// [`SkyPatches::aggregate`] fills them, unseen ground NaN. What effects acting on the
    /// measured sky itself (vignetting, the field of view, the glazing's angular
    /// transmittance) rescale before the daylight coefficients apply.
    pub bins_with_sun_cd_m2: Vec<f64>,
    /// The same with the sun disk removed and filled from the circumsolar sky.
    pub bins_without_sun_cd_m2: Vec<f64>,
    /// Per bin, whether the lens saw at least `MIN_COVERAGE` of it.
    pub bin_seen: Vec<bool>,
    /// The sky's colour from the raw frames and the per-patch sky light, for the
    /// spectral-mismatch effect (attached by the loop; `None` until then).
    pub spectral: Option<super::effect_spectral::SpectralTerms>,
}

/// The room: its engine world (without sky) and daylight coefficients.
pub struct Room {
    pub world: World,
    pub sensors: Vec<Sensor>,
    pub dc: DaylightCoefficients,
    pub settings: Settings,
}

/// Why the model could not be built.
#[derive(Debug, thiserror::Error)]
pub enum ModelError {
    #[error(transparent)]
    Scene(#[from] crate::scene::SceneError),
    #[error(transparent)]
    Sensors(#[from] crate::scene::SensorsError),
    #[error(transparent)]
    Engine(#[from] crate::engine::EngineError),
    #[error(transparent)]
    Device(#[from] crate::camera::DeviceError),
    #[error(transparent)]
    Capture(#[from] crate::hdr::CaptureMapError),
    #[error("{0}")]
    Sun(String),
}

impl Room {
    /// Loads the campaign's room and computes its daylight coefficients (Reinhart `mf`).
    pub fn load(
        campaign: &Campaign,
        mf: usize,
        settings: Settings,
        progress: &(dyn Fn(u64, u64) + Sync),
    ) -> Result<Self, ModelError> {
        let scene = crate::scene::load(campaign.path(&campaign.config.files.scene))?;
        let sensors = crate::scene::load_sensors(campaign.path(&campaign.config.files.sensors))?;
        let world = World::new(&scene)?;
        let dc = engine::daylight_coefficients(&world, &sensors, mf, &settings, progress)?;
        Ok(Self {
            world,
            sensors,
            dc,
            settings,
        })
    }

    /// Per sensor, lux per lux of direct-normal illuminance from a sun in unit direction
    /// `sun` (with standard errors), at the room's settings with 64 to 2048 paths per sensor
    /// (one direction needs fewer than the whole sky's coefficients).
    pub fn sun_coefficients(&mut self, sun: DVec3) -> Result<Vec<(f64, f64)>, EngineError> {
        let settings = Settings {
            samples_per_sensor: self.settings.samples_per_sensor.clamp(64, 2048),
            ..self.settings
        };
        engine::sun_coefficients(&mut self.world, &self.sensors, sun, &settings)
    }
}

/// Reads and merges every capture of the campaign with the declared camera.
pub fn load_captures(
    campaign: &Campaign,
    device: &DeviceConfig,
    progress: &dyn Fn(usize, usize),
) -> Result<Vec<CaptureData>, ModelError> {
    load_captures_with_overhead(campaign, device, 0.0, progress)
}

/// Merges one capture folder taking each frame's integration time as declared plus
/// `shutter_overhead_us` (the shutter-overhead effect); without an overhead, exactly
/// [`map_capture`].
pub fn map_capture_with_overhead(
    dir: &std::path::Path,
    device: &DeviceConfig,
    shutter_overhead_us: f64,
) -> Result<crate::hdr::CaptureMap, ModelError> {
    if shutter_overhead_us == 0.0 {
        return Ok(map_capture(dir, device)?);
    }
    use crate::campaign::{CaptureConfig, RawFrame};
    use crate::hdr::CaptureMapError;
    let toml_path = dir.join("capture.toml");
    let capture = CaptureConfig::read(&toml_path).map_err(CaptureMapError::from)?;
    let mut frames = Vec::with_capacity(capture.exposure.len());
    for entry in &capture.exposure {
        frames.push(RawFrame::read(&dir.join(&entry.file)).map_err(CaptureMapError::from)?);
    }
    let Some(first) = frames.first() else {
        return Err(ModelError::Sun(format!(
            "{}: no exposure entries",
            toml_path.display()
        )));
    };
    let camera = CameraModel::new(device.clone());
    let geometry = GroupGeometry::new(&camera, &capture.readout, first.width, first.height);
    let exposures: Vec<crate::hdr::Exposure> = frames
        .iter()
        .zip(&capture.exposure)
        .map(|(f, e)| crate::hdr::Exposure {
            frame: f,
            exposure_s: (e.exposure_us + shutter_overhead_us) * 1e-6,
            gain: e.gain,
        })
        .collect();
    let map =
        crate::hdr::merge(&exposures, device, capture.bayer, &geometry).map_err(|source| {
            CaptureMapError::Merge {
                capture: toml_path,
                source,
            }
        })?;
    Ok(crate::hdr::CaptureMap {
        capture,
        map,
        geometry,
    })
}

/// [`load_captures`] with a shutter overhead added to every declared integration time.
pub fn load_captures_with_overhead(
    campaign: &Campaign,
    device: &DeviceConfig,
    shutter_overhead_us: f64,
    progress: &dyn Fn(usize, usize),
) -> Result<Vec<CaptureData>, ModelError> {
    let site = crate::sun::Site {
        latitude_deg: campaign.config.site.latitude_deg,
        longitude_deg: campaign.config.site.longitude_deg,
        elevation_m: campaign.config.site.elevation_m,
    };
    let mut out = Vec::new();
    for (i, c) in campaign.captures.iter().enumerate() {
        progress(i, campaign.captures.len());
        let merged = map_capture_with_overhead(&c.dir, device, shutter_overhead_us)?;
        let spa = solar_position(c.time.with_timezone(&Utc), &site, None)
            .map_err(|e| ModelError::Sun(format!("{}: {e}", c.dir.display())))?;
        out.push(CaptureData {
            time: c.time,
            raw_width: 2 * merged.map.width,
            raw_height: 2 * merged.map.height,
            readout: merged.capture.readout,
            map: merged.map,
            spa_sun: spa.direction(),
        });
    }
    Ok(out)
}

/// Sky and ground bin luminances of a map (sky patches then mirrored ground patches, as the
/// daylight coefficients order them); unseen ground bins are NaN. Returns also the outdoor
/// horizontal illuminance of the sky part.
fn bins(
    patches: &SkyPatches,
    map: &LuminanceMap,
    geometry: &GroupGeometry,
) -> (Vec<f64>, Vec<bool>, f64) {
    let n = patches.len();
    let sky = patches.aggregate(
        map,
        &geometry.direction,
        &geometry.solid_angle_sr,
        MIN_COVERAGE,
    );
    let (mut sum, mut omega) = (vec![0.0f64; n], vec![0.0f64; n]);
    for i in 0..map.luminance_cd_m2.len() {
        let d = geometry.direction[i];
        if map.flags[i] != MapFlag::Valid || !d.is_finite() || d.z >= 0.0 {
            continue;
        }
        let d = d.as_dvec3();
        if let Some(p) = patches.patch_of(DVec3::new(d.x, d.y, -d.z)) {
            let w = geometry.solid_angle_sr[i] as f64;
            sum[p] += w * map.luminance_cd_m2[i] as f64;
            omega[p] += w;
        }
    }
    let mut lum = sky.luminance_cd_m2.clone();
    let mut seen = vec![true; 2 * n];
    for &p in &sky.filled {
        seen[p] = false;
    }
    for p in 0..n {
        if omega[p] >= MIN_COVERAGE * patches.solid_angle_sr(p) {
            lum.push(sum[p] / omega[p]);
        } else {
            lum.push(f64::NAN);
            seen[n + p] = false;
        }
    }
    let horizontal: f64 = (0..n)
        .map(|p| {
            let c = patches.centre(p);
            let l = sky.luminance_cd_m2[p];
            if l.is_finite() {
                l * c.z * patches.solid_angle_sr(p)
            } else {
                0.0
            }
        })
        .sum();
    (lum, seen, horizontal)
}

/// Computes the terms of every capture for the camera `device` (its orientation is what the
/// orientation effect changes).
pub fn capture_terms(
    room: &mut Room,
    captures: &[CaptureData],
    device: &DeviceConfig,
    progress: &dyn Fn(usize, usize),
) -> Result<Vec<CaptureTerms>, ModelError> {
    let camera = CameraModel::new(device.clone());
    let patches = room.dc.patches();
    let n = patches.len();
    let sensors = room.sensors.len();
    let mut out = Vec::with_capacity(captures.len());
    // Captures of one campaign share a readout: compute the geometry once per readout.
    let mut geometries = GeometryCache::default();
    for (k, c) in captures.iter().enumerate() {
        progress(k, captures.len());
        let geometry = geometries.get(&camera, &c.readout, c.raw_width, c.raw_height);
        let search = SunSearch {
            predicted_direction: Some(c.spa_sun),
            max_offset_deg: 12.0,
            ..Default::default()
        };
        let sun = if c.spa_sun.z > 0.0 {
            extract_sun(&c.map, geometry, &search)
                .ok()
                .filter(|s| s.direct_normal_illuminance_lux.is_finite())
        } else {
            None
        };
        let (with_sun, seen, horizontal_map) = bins(&patches, &c.map, geometry);
        // With a sun extracted, the outdoor horizontal illuminance is the sky without the
        // disk plus the disk's direct beam (the disk itself may be over-range in the map).
        let (without_sun, horizontal) = match &sun {
            Some(s) => {
                let (b, _, h) = bins(&patches, &remove_sun(&c.map, s), geometry);
                (
                    b,
                    h + s.direct_normal_illuminance_lux * s.direction.z.max(0.0),
                )
            }
            None => (with_sun.clone(), horizontal_map),
        };
        let unseen_ground: Vec<f64> = (0..sensors)
            .map(|s| {
                (0..n)
                    .filter(|&p| !seen[n + p])
                    .map(|p| room.dc.row(s)[n + p])
                    .sum()
            })
            .collect();
        let (sky_weight, unseen_weight) = (0..sensors).fold((0.0, 0.0), |(a, b), s| {
            let row = room.dc.row(s);
            (
                a + row[..n].iter().sum::<f64>(),
                b + (0..n).filter(|&p| !seen[p]).map(|p| row[p]).sum::<f64>(),
            )
        });
        let (sun_lux_per_dn_lux, sun_dn_lux) = match &sun {
            Some(s) => {
                let k = room.sun_coefficients(s.direction)?;
                (
                    k.into_iter().map(|(c, _)| c).collect(),
                    s.direct_normal_illuminance_lux,
                )
            }
            None => (vec![0.0; sensors], 0.0),
        };
        let valid = c
            .map
            .flags
            .iter()
            .filter(|f| **f != MapFlag::UnderRange)
            .count();
        let over = c
            .map
            .flags
            .iter()
            .filter(|f| **f == MapFlag::OverRange)
            .count();
        out.push(CaptureTerms {
            sky_with_sun_lux: room.dc.apply_seen(&with_sun),
            sky_without_sun_lux: room.dc.apply_seen(&without_sun),
            sun_lux_per_dn_lux,
            sun_dn_lux,
            unseen_ground_lux_per_cd_m2: unseen_ground,
            outdoor_horizontal_lux: horizontal,
            unseen_sky_fraction: if sky_weight > 0.0 {
                unseen_weight / sky_weight
            } else {
                0.0
            },
            saturated_fraction: if valid > 0 {
                over as f64 / valid as f64
            } else {
                0.0
            },
            sun,
            bins_with_sun_cd_m2: with_sun,
            bins_without_sun_cd_m2: without_sun,
            bin_seen: seen,
            spectral: None,
        });
    }
    Ok(out)
}

/// The parameters of the model: the base and every effect the loop may add.
#[derive(Clone, Debug, PartialEq)]
pub struct ModelState {
    /// Hand the sun over as a concentrated source (else it stays in the map's patches).
    pub concentrated_sun: bool,
    /// Glazing transmittance relative to the scene's.
    pub glazing_transmittance: f64,
    /// Additive light, lux per lux of outdoor horizontal illuminance.
    pub light_leak: f64,
    /// Reflectance of the ground where the lens does not see it.
    pub ground_reflectance: f64,
    /// The lux-meter logger's clock minus the device's, seconds: readings are matched to a
    /// capture at this offset on the logger's clock.
    pub clock_offset_s: f64,
    /// Spectral mismatch: measured / true luminance is `1 + m (c − 1)` at sky colour index
    /// `c` (blue / red); this is `m` (0: no mismatch).
    pub spectral_slope: f64,
    /// ASHRAE incidence-angle modifier parameter of the glazing (0: the scene's glass alone).
    /// Applied to the terms (`effect_glazing_angular::apply_glazing_angular`), not by
    /// [`predict`]: terms computed afresh need it re-applied.
    pub glazing_angular_b0: f64,
    /// Extra vignetting v: the true relative illumination is the declared one times
    /// 1 − v (α/90°)² (`effect_vignetting.rs`; applied to the terms, not in [`predict`]).
    pub extra_vignetting: f64,
    /// With the field-of-view effect: the factor on the extrapolated luminance of the sky
    /// patches the lens did not see, and the sun beyond the maps' field filled from the
    /// pyranometer (`effect_fov.rs`; applied to the terms, not in [`predict`]).
    pub unseen_sky_factor: Option<f64>,
}

impl Default for ModelState {
    fn default() -> Self {
        Self {
            concentrated_sun: true,
            glazing_transmittance: 1.0,
            light_leak: 0.0,
            ground_reflectance: 0.2,
            clock_offset_s: 0.0,
            spectral_slope: 0.0,
            glazing_angular_b0: 0.0,
            extra_vignetting: 0.0,
            unseen_sky_factor: None,
        }
    }
}

/// Per sensor, the parts the linear effects act on: the room's light without the unseen
/// ground (lux), the unseen ground's light per unit of its reflectance (lux), and the outdoor
/// horizontal illuminance (lux). The prediction is `τ (room + ρ ground) + leak · outdoor`.
pub fn parts(state: &ModelState, t: &CaptureTerms) -> Vec<(f64, f64, f64)> {
    (0..t.sky_with_sun_lux.len())
        .map(|s| {
            let room = if state.concentrated_sun {
                t.sky_without_sun_lux[s] + t.sun_lux_per_dn_lux[s] * t.sun_dn_lux
            } else {
                t.sky_with_sun_lux[s]
            };
            let room = super::effect_spectral::corrected_room(state, t, s, room);
            let ground = t.unseen_ground_lux_per_cd_m2[s] * t.outdoor_horizontal_lux / PI;
            (room, ground, t.outdoor_horizontal_lux)
        })
        .collect()
}

/// Illuminance per sensor, lux, for one capture's terms under `state`.
pub fn predict(state: &ModelState, t: &CaptureTerms) -> Vec<f64> {
    parts(state, t)
        .into_iter()
        .map(|(room, ground, outdoor)| {
            state.glazing_transmittance * (room + state.ground_reflectance * ground)
                + state.light_leak * outdoor
        })
        .collect()
}
