//! One measurement cycle: capture → HDR map → sun → illuminance per sensor → result record.
//!
//! The illuminance is the offline pipeline's, by the same functions: the HDR merge of
//! `skylux_hps::hdr` (as `hdr::map_capture` does it for a folder), the SPA sun, and
//! the device model `skylux_hps::model::{capture_terms, predict}` with its default state (sun
//! extracted from the map and handed over as a concentrated source, daylight coefficients
//! for the sky and the seen ground, the model's ground reflectance where the lens does not
//! see). So a capture kept by the daemon and run through the loop's code gives the same lux.
//!
//! The daylight coefficients are computed once at start and cached in a file keyed by a hash
//! of the room (scene and sensor files) and the settings. The daemon always uses the matrix
//! as read back from that file (float32), so a cache hit and a fresh computation give
//! bit-identical results.
//!
//! In map mode the sun comes from the fabric's accumulators when they measured it
//! (`sun::sun_from_fabric`, the background from a ring of the map around their box, the
//! blurred limb below their threshold from the map's groups just around it,
//! `FabricSun::with_limb`): the model takes it as found instead of scanning the map. When they did not (not armed, no
//! group at the threshold, a saturated disk, a fault on `sun.*`) the model scans the map as
//! for a raw capture, and the record says which (`sun_source`, `sun_fallback`).
//!
//! With `[[views]]` declared, the cycle also reports glare at each occupant view under the
//! same measured sky (`views.rs`), within the cycle's time budget.

use crate::config::Config;
use crate::source::{CaptureSet, SunFallback};
use crate::views::{evaluate_views, RenderRates, ViewGlare, ViewRequest, ViewsOutcome};
use crate::window_states::{WindowStateRecord, WindowStates};
use chrono::{Datelike, Utc};
use glam::DVec3;
use serde::{Deserialize, Serialize};
use skylux_hps::camera::{CameraModel, DeviceConfig};
use skylux_hps::engine::{self, DaylightCoefficients, Settings, World};
use skylux_hps::hdr::{fabric_map, merge, GroupGeometry, LuminanceMap, MapExposure};
use skylux_hps::model::{
    capture_terms, install_measured_sky, predict, remove_measured_sky, CaptureData, CaptureTerms,
    ModelState, Room,
};
use skylux_hps::numerics::fnv::{fnv1a, FNV1A_OFFSET};
use skylux_hps::picture::Picture;
use skylux_hps::sun::{
    fabric_background_cd_m2, solar_position, sun_from_fabric, ExtractedSun, NoSun, Site, SunFlag,
    SOLAR_DISK_SR,
};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;
use std::time::Instant;

/// The accumulators' box may span this many solar-disk diameters plus
/// [`SCATTER_MARGIN_GROUPS`] before its groups are taken for scattered noise rather than the
/// disk and its limb: the lens blur widens the disk by about a group on each side
/// (`SunSearch::dilation_groups`, two, covers it with a margin).
const SCATTER_LIMIT_DISKS: f64 = 2.0;
const SCATTER_MARGIN_GROUPS: f64 = 4.0;

/// Held while a daylight-coefficient matrix is written to the cache and renamed into place.
static DC_WRITE: Mutex<()> = Mutex::new(());

/// Abandons a daylight-coefficient computation in progress (SIGTERM during the first start):
/// waits for a cache write in progress to finish (it is then whole), makes sure none starts
/// afterwards, and removes any temporary file an earlier crash left. After this the cache
/// holds complete matrices or nothing.
pub fn abandon_dc(cancel: &AtomicBool, config: &Config) {
    let _guard = DC_WRITE.lock().unwrap_or_else(|p| p.into_inner());
    cancel.store(true, Ordering::SeqCst);
    if let Ok(entries) = std::fs::read_dir(config.cache_dir()) {
        for e in entries.flatten() {
            if e.file_name().to_string_lossy().ends_with(".dc.tmp") {
                let _ = std::fs::remove_file(e.path());
            }
        }
    }
}

/// Version of the cache key: bump when the matrix's meaning changes.
const DC_CACHE_VERSION: &str = "skyluxd-dc-v1";

/// Why a cycle failed (after the capture itself).
#[derive(Debug, thiserror::Error)]
pub enum CycleError {
    #[error(transparent)]
    Source(#[from] crate::source::SourceError),
    #[error("exposure {exposure} ({exposure_us} us): frame flagged {flags:?} by the capture path; capture discarded")]
    FlaggedFrame {
        exposure: usize,
        exposure_us: f64,
        flags: Vec<String>,
    },
    #[error("HDR merge: {0}")]
    Hdr(String),
    #[error("sun position: {0}")]
    Sun(String),
    #[error("illuminance: {0}")]
    Model(String),
    #[error("output: {0}")]
    Output(String),
    #[error("disk full: {0}")]
    DiskFull(String),
    #[error("clock: {0}")]
    Clock(String),
}

impl CycleError {
    /// A short stable name for logs and metrics.
    pub fn kind(&self) -> &'static str {
        match self {
            Self::Source(e) => e.kind(),
            Self::FlaggedFrame { .. } => "flagged_frame",
            Self::Hdr(_) => "hdr",
            Self::Sun(_) => "sun",
            Self::Model(_) => "model",
            Self::Output(_) => "output",
            Self::DiskFull(_) => "disk_full",
            Self::Clock(_) => "clock",
        }
    }
}

/// Why the pipeline could not be set up (fatal at start).
#[derive(Debug, thiserror::Error)]
pub enum SetupError {
    #[error("{0}")]
    Device(#[from] skylux_hps::camera::DeviceError),
    #[error("{0}")]
    Scene(#[from] skylux_hps::scene::SceneError),
    #[error("{0}")]
    Sensors(#[from] skylux_hps::scene::SensorsError),
    #[error("{0}")]
    Engine(#[from] skylux_hps::engine::EngineError),
    #[error("{path}: {message}")]
    Cache { path: PathBuf, message: String },
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
}

/// Illuminance at one sensor.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SensorLux {
    pub sensor: String,
    pub lux: f64,
    /// Standard error (Monte-Carlo results only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stderr_lux: Option<f64>,
}

/// The sun of one capture.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SunRecord {
    /// NREL SPA, geometric (as the engine's sun and the offline pipeline).
    pub spa_altitude_deg: f64,
    pub spa_azimuth_deg: f64,
    /// Whether a sun disk was found in the map.
    pub extracted: bool,
    #[serde(default)]
    pub extracted_altitude_deg: Option<f64>,
    #[serde(default)]
    pub extracted_azimuth_deg: Option<f64>,
    /// Direct-normal illuminance of the extracted disk, lux.
    #[serde(default)]
    pub direct_normal_lux: Option<f64>,
    /// `saturated`, `partly_covered`, `other_candidates`; without a sun, `no_sun:` and the
    /// reason, as `sun.csv` writes it (`below_horizon`, `below_threshold`,
    /// `outside_field_of_view`, `far_from_prediction`, `all_saturated`, `not_measurable`):
    /// `extracted = false` never comes without one.
    pub flags: Vec<String>,
    /// Without a sun, why, in words (the flag's long form).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub missing_reason: Option<String>,
}

/// Why a map-mode cycle's sun is the HPS's scan, not the accumulators'.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SunFallbackRecord {
    /// A short stable tag (`SunFallback::tag`): `not_armed`, `bus`, `unsettled`, `stale`,
    /// `inconsistent`, `none`, `saturated`, `undersampled`, `scattered`, `not_measurable`.
    pub reason: String,
    pub detail: String,
}

impl From<&SunFallback> for SunFallbackRecord {
    fn from(f: &SunFallback) -> Self {
        Self {
            reason: f.tag.to_string(),
            detail: f.detail.clone(),
        }
    }
}

/// How long each stage took, milliseconds.
#[derive(Clone, Debug, Default, Serialize, Deserialize, PartialEq)]
pub struct StageDurations {
    pub capture_ms: f64,
    pub hdr_ms: f64,
    /// SPA position, and in map mode the sun from the fabric's accumulators (the scan of the
    /// map, when there is one, is in `terms_ms`).
    pub sun_ms: f64,
    /// Sun extraction, sky and ground patches times daylight coefficients, sun coefficients.
    pub terms_ms: f64,
    /// The model's prediction per sensor from the terms.
    pub illuminance_ms: f64,
    pub monte_carlo_ms: f64,
    /// The occupant views: eye sensors, renders and their glare (`views.rs`).
    #[serde(default)]
    pub views_ms: f64,
    /// Every shading state of the window (`window_states.rs`).
    #[serde(default)]
    pub window_states_ms: f64,
    /// Capture to record, before the output (whose time is a metric: `/v1/metrics`).
    pub total_ms: f64,
}

/// The result of one cycle: one line of `results.jsonl` and `/v1/latest`.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct CycleRecord {
    /// Start of the capture, RFC 3339 with the site's offset.
    pub time: String,
    /// Successful cycles since the daemon started, from 1.
    pub sequence: u64,
    pub source: String,
    /// Where the capture's HDR map was made: `fabric` (the fabric's map of grouped words) or
    /// `hps` (raw frames merged here; the capture can be kept in campaign format).
    #[serde(default = "hdr_hps")]
    pub hdr: String,
    /// Where the sun came from: `fabric` (the fabric's accumulators, map mode) or `hps` (the
    /// HPS's scan of the map: every raw capture, and a map whose accumulators gave nothing
    /// to believe, `sun_fallback`).
    #[serde(default = "hdr_hps")]
    pub sun_source: String,
    /// Map mode with the sun from the HPS's scan: why not from the accumulators.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sun_fallback: Option<SunFallbackRecord>,
    pub sun: SunRecord,
    /// Illuminance per sensor through the daylight coefficients, lux.
    pub illuminance: Vec<SensorLux>,
    /// Full Monte-Carlo illuminance under the measured sky, when `room.monte_carlo` is set.
    #[serde(default)]
    pub monte_carlo: Option<Vec<SensorLux>>,
    /// Glare per declared occupant view (`[[views]]`), in their order.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub views: Vec<ViewGlare>,
    /// Every declared shading state of the window (`[room.window]`): its illuminance per
    /// sensor and each view's Ev and DGPs, as if the window were in that state.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub window_states: Vec<WindowStateRecord>,
    /// Outdoor horizontal illuminance the map implies, lux.
    pub outdoor_horizontal_lux: f64,
    /// Fraction of valid groups over-range.
    pub saturated_fraction: f64,
    /// The map, relative to the output directory (when maps are kept).
    #[serde(default)]
    pub map: Option<String>,
    /// The capture folder, relative to the output directory (when captures are kept).
    #[serde(default)]
    pub capture: Option<String>,
    pub durations_ms: StageDurations,
    /// In simulation, the simulated world's own outdoor global horizontal illuminance, lux,
    /// beside the measured `outdoor_horizontal_lux` (absent on real hardware).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub truth_outdoor_horizontal_lux: Option<f64>,
    /// In simulation, the simulated world's own illuminance per sensor (the room traced
    /// directly under the world's sky and sun), beside the measured `illuminance`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub truth_illuminance: Option<Vec<SensorLux>>,
    /// Values outside physical bounds (`plausibility.rs`): empty when all are plausible.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub plausibility: Vec<String>,
}

fn hdr_hps() -> String {
    "hps".into()
}

impl CycleRecord {
    /// A small valid record: no sun, one sensor at 123.5 lx. For the tests and the API's fuzz
    /// harness, which need a record without running a cycle.
    pub fn minimal(time: &str, source: &str) -> Self {
        CycleRecord {
            time: time.into(),
            sequence: 1,
            source: source.into(),
            hdr: hdr_hps(),
            sun_source: hdr_hps(),
            sun_fallback: None,
            sun: SunRecord {
                spa_altitude_deg: 40.0,
                spa_azimuth_deg: 180.0,
                extracted: false,
                extracted_altitude_deg: None,
                extracted_azimuth_deg: None,
                direct_normal_lux: None,
                flags: vec!["no_sun:below_threshold".into()],
                missing_reason: Some("no sun extracted: no direct sun in the map".into()),
            },
            illuminance: vec![SensorLux {
                sensor: "S1".into(),
                lux: 123.5,
                stderr_lux: None,
            }],
            monte_carlo: None,
            views: vec![],
            window_states: vec![],
            outdoor_horizontal_lux: 1e5,
            saturated_fraction: 0.0,
            map: None,
            capture: None,
            durations_ms: Default::default(),
            truth_outdoor_horizontal_lux: None,
            truth_illuminance: None,
            plausibility: vec![],
        }
    }
}

/// What the cycle hands to the output stage besides the record.
pub struct CycleProducts {
    pub record: CycleRecord,
    pub map: LuminanceMap,
    /// The rendered view pictures: index into `record.views`, and the picture.
    pub view_pictures: Vec<(usize, Picture)>,
    /// The views rendered under the window's states: index into `record.window_states`,
    /// into its views, and the picture.
    pub state_view_pictures: Vec<(usize, usize, Picture)>,
}

/// Everything computed once at start.
pub struct Pipeline {
    pub device: DeviceConfig,
    camera: CameraModel,
    site: Site,
    pub room: Room,
    state: ModelState,
    monte_carlo: Option<Settings>,
    geometry: Option<(GeometryKey, GroupGeometry)>,
    /// What the views' renders took per path, for the next cycle's estimate.
    render_rates: RenderRates,
    /// The cache file the daylight coefficients were read from.
    pub dc_path: PathBuf,
    /// The window's declared shading states, if any.
    window_states: Option<WindowStates>,
}

type GeometryKey = (skylux_hps::campaign::Readout, usize, usize);

/// The engine settings of the room's daylight and sun coefficients.
pub fn room_settings(config: &Config) -> Settings {
    Settings {
        ambient_bounces: config.room.ambient_bounces,
        samples_per_sensor: config.room.dc_samples,
        seed: config.room.seed,
        ..Settings::default()
    }
}

/// The cache key of a room: its files' contents, the patches and the engine settings.
pub fn room_hash(config: &Config) -> Result<u64, SetupError> {
    let mut h = FNV1A_OFFSET;
    fnv1a(&mut h, DC_CACHE_VERSION.as_bytes());
    for p in config.room.scene.iter().chain([&config.room.sensors]) {
        let bytes = std::fs::read(p).map_err(|source| SetupError::Io {
            path: p.clone(),
            source,
        })?;
        fnv1a(&mut h, &(bytes.len() as u64).to_le_bytes());
        fnv1a(&mut h, &bytes);
    }
    let s = room_settings(config);
    for v in [
        config.room.mf as u64,
        u64::from(s.ambient_bounces),
        u64::from(s.samples_per_sensor),
        s.seed,
        u64::from(s.max_specular_events),
    ] {
        fnv1a(&mut h, &v.to_le_bytes());
    }
    Ok(h)
}

impl Pipeline {
    /// Loads the camera and the room, and reads (or computes and caches) the daylight
    /// coefficients. `progress(done, total)` reports the computation.
    pub fn new(config: &Config, progress: &(dyn Fn(u64, u64) + Sync)) -> Result<Self, SetupError> {
        Self::new_cancellable(config, progress, &AtomicBool::new(false))
    }

    /// As [`Pipeline::new`]; once `cancel` is set (by [`abandon_dc`]) a computed matrix is
    /// not written to the cache.
    pub fn new_cancellable(
        config: &Config,
        progress: &(dyn Fn(u64, u64) + Sync),
        cancel: &AtomicBool,
    ) -> Result<Self, SetupError> {
        let (device, warnings) = DeviceConfig::read(&config.camera.device)?;
        for w in warnings {
            tracing::warn!(file = %config.camera.device.display(), "{w}");
        }
        let scene = skylux_hps::scene::load_files(&config.room.scene)?;
        let sensors = skylux_hps::scene::load_sensors(&config.room.sensors)?;
        let mut world = World::new(&scene)?;
        skylux_hps::engine::openings::add_openings(
            &mut world,
            &sensors.iter().map(|s| s.position_m).collect::<Vec<_>>(),
        );
        let settings = room_settings(config);
        let cache_dir = config.cache_dir();
        let dc_path = cache_dir.join(format!("dc-{:016x}.dc", room_hash(config)?));
        let dc = match DaylightCoefficients::read(&dc_path) {
            Ok(dc) if dc.sensors.len() == sensors.len() => {
                tracing::info!(path = %dc_path.display(), "daylight coefficients read from the cache");
                dc
            }
            other => {
                if let Err(e) = other {
                    if dc_path.exists() {
                        tracing::warn!(error = %e, "cached daylight coefficients unusable: recomputing");
                    }
                }
                let started = Instant::now();
                tracing::info!(
                    path = %dc_path.display(),
                    sensors = sensors.len(),
                    "computing the daylight coefficients (not cached yet)"
                );
                let dc = engine::daylight_coefficients(
                    &world,
                    &sensors,
                    config.room.mf,
                    &settings,
                    progress,
                )?;
                std::fs::create_dir_all(&cache_dir).map_err(|source| SetupError::Io {
                    path: cache_dir.clone(),
                    source,
                })?;
                let tmp = dc_path.with_extension("dc.tmp");
                {
                    // Whole or not at all: abandon_dc waits for a write in progress.
                    let _guard = DC_WRITE.lock().unwrap_or_else(|p| p.into_inner());
                    if cancel.load(Ordering::SeqCst) {
                        return Err(SetupError::Cache {
                            path: dc_path.clone(),
                            message: "abandoned (stop requested): not cached".into(),
                        });
                    }
                    dc.write(&tmp)
                        .and_then(|_| crate::output::fsync_file(&tmp))
                        .and_then(|_| std::fs::rename(&tmp, &dc_path))
                        .map_err(|source| {
                            let _ = std::fs::remove_file(&tmp);
                            SetupError::Io {
                                path: dc_path.clone(),
                                source,
                            }
                        })?;
                }
                tracing::info!(
                    path = %dc_path.display(),
                    sensors = sensors.len(),
                    bins = dc.bins,
                    seconds = started.elapsed().as_secs_f64(),
                    "daylight coefficients computed and cached"
                );
                DaylightCoefficients::read(&dc_path).map_err(|message| SetupError::Cache {
                    path: dc_path.clone(),
                    message,
                })?
            }
        };
        let window_states = WindowStates::load(config, &sensors, progress)?;
        let monte_carlo = config.room.monte_carlo.then_some(Settings {
            samples_per_sensor: config.room.monte_carlo_samples,
            ..settings
        });
        Ok(Self {
            camera: CameraModel::new(device.clone()),
            device,
            site: Site {
                latitude_deg: config.site.latitude_deg,
                longitude_deg: config.site.longitude_deg,
                elevation_m: config.site.elevation_m,
            },
            room: Room {
                world,
                sensors,
                dc,
                settings,
            },
            state: ModelState::default(),
            monte_carlo,
            geometry: None,
            render_rates: RenderRates::default(),
            dc_path,
            window_states,
        })
    }

    /// The sensor names, in order.
    pub fn sensor_names(&self) -> Vec<String> {
        self.room.sensors.iter().map(|s| s.name.clone()).collect()
    }

    /// Turns a capture into a record (the fields `map`, `capture` and `sequence` are the
    /// caller's), with the glare of `views`.
    pub fn process(
        &mut self,
        set: &CaptureSet,
        capture_ms: f64,
        source: &str,
        views: &ViewRequest,
    ) -> Result<CycleProducts, CycleError> {
        let started = Instant::now();
        let (raw_width, raw_height) = check_frames(set)?;

        // HDR: as hdr::map_capture, with the geometry kept between cycles.
        let t = Instant::now();
        let r = set.config.readout;
        let map = self.luminance_map(set, raw_width, raw_height)?;
        let hdr_ms = ms(t);

        // Sun: SPA, as the device model's `load_captures` computes it.
        let t = Instant::now();
        let spa = solar_position(set.time.with_timezone(&Utc), &self.site, None)
            .map_err(|e| CycleError::Sun(e.to_string()))?;
        // Map mode: the sun the accumulators measured, if it can be believed.
        let fabric_sun = set
            .fabric_map
            .as_ref()
            .map(|m| self.fabric_sun(set, m, &map));
        let sun_fallback = match &fabric_sun {
            Some(Err(f)) => {
                if matches!(f.tag, "bus" | "unsettled" | "stale" | "inconsistent") {
                    tracing::warn!(reason = f.tag, detail = %f.detail, "sun accumulators: fault, the HPS scans the map");
                } else {
                    tracing::debug!(reason = f.tag, detail = %f.detail, "sun accumulators: the HPS scans the map");
                }
                Some(SunFallbackRecord::from(f))
            }
            _ => None,
        };
        let measured_sun = fabric_sun.and_then(Result::ok);
        let sun_source = if measured_sun.is_some() {
            "fabric"
        } else {
            "hps"
        };
        let sun_ms = ms(t);

        // Terms and prediction: the offline pipeline's functions.
        let t = Instant::now();
        let data = [CaptureData {
            time: set.time,
            map,
            readout: r,
            raw_width,
            raw_height,
            spa_sun: spa.direction(),
            sun: measured_sun,
        }];
        let terms = capture_terms(&mut self.room, &data, &self.device, &|_, _| {})
            .map_err(|e| CycleError::Model(e.to_string()))?;
        let [CaptureData { map, .. }] = data;
        let terms = terms
            .into_iter()
            .next()
            .ok_or_else(|| CycleError::Model("no terms for the capture".into()))?;
        let terms_ms = ms(t);
        let t = Instant::now();
        let lux = predict(&self.state, &terms);
        let illuminance_ms = ms(t);

        let t = Instant::now();
        let monte_carlo = match self.monte_carlo {
            Some(settings) => Some(self.monte_carlo(&map, &terms, &settings)?),
            None => None,
        };
        let monte_carlo_ms = ms(t);

        let t = Instant::now();
        let outcome = if views.views.is_empty() {
            ViewsOutcome::default()
        } else {
            // The budget counts from the capture's start.
            let deadline_ms = views.budget_ms - capture_ms;
            self.views(&map, &terms, views, started, deadline_ms)?
        };
        let views_ms = ms(t);

        let t = Instant::now();
        let mut window_states = self
            .window_states
            .as_ref()
            .map(|w| w.evaluate(&terms, self.state.ground_reflectance));
        let mut state_view_pictures = Vec::new();
        if let Some(Ok(states)) = window_states.as_mut() {
            if !views.views.is_empty() {
                let deadline_ms = views.budget_ms - capture_ms;
                let rendered = self.state_views(&map, &terms, views, started, deadline_ms)?;
                for (k, (state, outcome)) in states.iter_mut().zip(rendered).enumerate() {
                    for (view, g) in state.views.iter_mut().zip(outcome.glare) {
                        view.rendered = Some(g);
                    }
                    state_view_pictures
                        .extend(outcome.pictures.into_iter().map(|(v, p)| (k, v, p)));
                }
            }
        }
        let window_states_ms = ms(t);

        let mut record = CycleRecord {
            time: set.time.to_rfc3339(),
            sequence: 0,
            source: source.to_string(),
            hdr: if set.fabric_map.is_some() {
                "fabric".into()
            } else {
                hdr_hps()
            },
            sun_source: sun_source.into(),
            sun_fallback,
            sun: sun_record(&spa, &terms),
            illuminance: sensor_lux(&self.room.sensors, &lux),
            monte_carlo,
            views: outcome.glare,
            window_states: match &window_states {
                Some(Ok(states)) => states.clone(),
                _ => vec![],
            },
            outdoor_horizontal_lux: terms.outdoor_horizontal_lux,
            saturated_fraction: terms.saturated_fraction,
            map: None,
            capture: None,
            durations_ms: StageDurations {
                capture_ms,
                hdr_ms,
                sun_ms,
                terms_ms,
                illuminance_ms,
                monte_carlo_ms,
                views_ms,
                window_states_ms,
                total_ms: capture_ms + ms(started),
            },
            truth_outdoor_horizontal_lux: set.truth_outdoor_horizontal_lux,
            truth_illuminance: set
                .truth_interior_lux
                .as_ref()
                .map(|truth| sensor_lux(&self.room.sensors, truth)),
            plausibility: vec![],
        };
        let day_of_year = set.time.ordinal() as u16;
        let interior_bound = skylux_hps::model::plausibility::interior_bound_lux(
            &self.room.dc,
            &terms,
            self.state.ground_reflectance,
        );
        record.plausibility = crate::plausibility::check(
            &record,
            self.site.elevation_m,
            day_of_year,
            Some(&interior_bound),
        )
        .into_iter()
        .map(str::to_string)
        .collect();
        if let Some(Err(why)) = window_states {
            record.plausibility.push(format!("window_states:{why}"));
        }
        Ok(CycleProducts {
            record,
            map,
            view_pictures: outcome.pictures,
            state_view_pictures,
        })
    }

    /// The sun from the accumulators' sums of a map-mode capture, with the circumsolar
    /// background from the map, as the model takes an extracted one; or why not.
    fn fabric_sun(
        &self,
        set: &CaptureSet,
        capture: &crate::source::FabricMapCapture,
        map: &LuminanceMap,
    ) -> Result<ExtractedSun, SunFallback> {
        let reading = capture.sun.as_ref().map_err(Clone::clone)?;
        let Some((_, geometry)) = &self.geometry else {
            return Err(SunFallback::new("not_measurable", "no group geometry"));
        };
        let sums = &reading.sums;
        if let Some((cx, cy)) = sums.centroid() {
            let (x, y) = (cx.round() as usize, cy.round() as usize);
            let group_sr = geometry
                .solid_angle_sr
                .get(y * map.width + x)
                .map_or(f64::NAN, |&w| f64::from(w));
            // As `extract_sun` refuses a disk a skipping readout cannot measure.
            let coarse = group_sr.is_nan() || group_sr > SOLAR_DISK_SR / 4.0;
            if geometry.fill_factor < 1.0 && coarse {
                return Err(SunFallback::new(
                    "undersampled",
                    format!(
                        "the readout integrates {:.0} % of each group's cell and the cells are \
                         not much smaller than the solar disk",
                        100.0 * geometry.fill_factor
                    ),
                ));
            }
            // The disk and its blurred limb span a few groups; groups counted far beyond them
            // are noise or another source in the window, and would move the centroid.
            let disk_groups = (SOLAR_DISK_SR / group_sr).sqrt().max(1.0);
            let extent = sums
                .max_x
                .saturating_sub(sums.min_x)
                .max(sums.max_y.saturating_sub(sums.min_y))
                + 1;
            // (NaN, from a centroid off the geometry, is not within.)
            let within =
                f64::from(extent) <= SCATTER_LIMIT_DISKS * disk_groups + SCATTER_MARGIN_GROUPS;
            if !within {
                return Err(SunFallback::new(
                    "scattered",
                    format!(
                        "{} groups counted over {extent} groups, the disk spans {disk_groups:.1}",
                        sums.count
                    ),
                ));
            }
        }
        let background = fabric_background_cd_m2(map, geometry, &reading.sums);
        let sun = sun_from_fabric(
            &reading.sums,
            &reading.search,
            &self.camera,
            &set.config.readout,
            &reading.exposure,
            background,
        )
        .map_err(|e| match e {
            NoSun::BelowThreshold { .. } => SunFallback::new("none", e.to_string()),
            e => SunFallback::new("not_measurable", e.to_string()),
        })?
        .with_limb(map, geometry, sums);
        if sun.flags.contains(&SunFlag::Saturated) {
            return Err(SunFallback::new(
                "saturated",
                format!(
                    "{} of {} groups over-range in the shortest exposure",
                    reading.sums.over_count, reading.sums.count
                ),
            ));
        }
        if !(sun.direct_normal_illuminance_lux.is_finite() && sun.direction.is_finite()) {
            return Err(SunFallback::new(
                "not_measurable",
                format!(
                    "direct-normal illuminance {} lx",
                    sun.direct_normal_illuminance_lux
                ),
            ));
        }
        Ok(sun.into_extracted(&reading.sums, map.width, map.height))
    }

    /// The capture's luminance map: the fabric's map through the merge's calibration, or the
    /// HPS merge of the frames; the group geometry is kept between cycles.
    fn luminance_map(
        &mut self,
        set: &CaptureSet,
        raw_width: usize,
        raw_height: usize,
    ) -> Result<LuminanceMap, CycleError> {
        let r = set.config.readout;
        let key = (r, raw_width, raw_height);
        if self.geometry.as_ref().map(|(k, _)| *k) != Some(key) {
            self.geometry = Some((
                key,
                GroupGeometry::new(&self.camera, &r, raw_width, raw_height),
            ));
        }
        let geometry = match &self.geometry {
            Some((_, g)) => g,
            None => return Err(CycleError::Hdr("no geometry".into())),
        };
        match &set.fabric_map {
            // The fabric's map: each group from one exposure, the merge's calibration.
            Some(m) => {
                let exposures: Vec<MapExposure> = set
                    .config
                    .exposure
                    .iter()
                    .map(|e| MapExposure {
                        exposure_s: e.exposure_us * 1e-6,
                        gain: e.gain,
                    })
                    .collect();
                fabric_map(
                    &m.map,
                    &exposures,
                    &m.hdr,
                    &self.device,
                    set.config.bayer,
                    geometry,
                )
            }
            None => merge(&set.exposures(), &self.device, set.config.bayer, geometry),
        }
        .map_err(|e| CycleError::Hdr(e.to_string()))
    }

    /// Full Monte-Carlo through the engine: the room under the measured sky (the map's
    /// patches with the sun disk removed), a uniform ground of the model's reflectance, and
    /// the extracted sun as a `light` of the solar disk's solid angle.
    fn monte_carlo(
        &mut self,
        map: &LuminanceMap,
        terms: &CaptureTerms,
        settings: &Settings,
    ) -> Result<Vec<SensorLux>, CycleError> {
        let result = self.under_measured_sky(map, terms, |room, _| {
            engine::illuminance(&room.world, &room.sensors, settings, &|_, _| {})
        })?;
        let result = result.map_err(|e| CycleError::Model(format!("Monte-Carlo: {e}")))?;
        Ok(result
            .into_iter()
            .map(|s| SensorLux {
                sensor: s.name,
                lux: s.illuminance_lux,
                stderr_lux: Some(s.stderr_lux),
            })
            .collect())
    }

    /// The occupant views under the measured sky: see `views.rs`.
    fn views(
        &mut self,
        map: &LuminanceMap,
        terms: &CaptureTerms,
        request: &ViewRequest,
        started: Instant,
        deadline_ms: f64,
    ) -> Result<ViewsOutcome, CycleError> {
        let result = self.under_measured_sky(map, terms, |room, rates| {
            evaluate_views(
                &room.world,
                request.views,
                request.glare,
                room.settings,
                rates,
                started,
                deadline_ms,
            )
        })?;
        result.map_err(|e| CycleError::Model(format!("views: {e}")))
    }

    /// The views under each shading state of the window: the room glazed with each state's
    /// BSDF under the measured sky, rendered while the cycle's budget lasts (after it, DGPs
    /// from the eye's sensor, with the reason), as `views` does for the room as built.
    fn state_views(
        &mut self,
        map: &LuminanceMap,
        terms: &CaptureTerms,
        request: &ViewRequest,
        started: Instant,
        deadline_ms: f64,
    ) -> Result<Vec<ViewsOutcome>, CycleError> {
        let (Some(states), Some((_, geometry))) = (self.window_states.as_mut(), &self.geometry)
        else {
            return Ok(vec![]);
        };
        let sky = MeasuredSky {
            map,
            terms,
            geometry,
            mf: self.room.dc.mf,
            state: &self.state,
        };
        let mut out = Vec::with_capacity(states.worlds.len());
        for world in states.worlds.iter_mut() {
            let outcome = sky.with(world, |world| {
                evaluate_views(
                    world,
                    request.views,
                    request.glare,
                    self.room.settings,
                    &mut self.render_rates,
                    started,
                    deadline_ms,
                )
            });
            let outcome = outcome
                .map_err(|e| CycleError::Model(format!("views under a window state: {e}")))?;
            out.push(outcome);
        }
        Ok(out)
    }

    /// Runs `f` on the room with this capture's measured sky installed (its patches, the
    /// ground, the extracted sun: `model::install_measured_sky`), and takes the sky out again.
    fn under_measured_sky<T>(
        &mut self,
        map: &LuminanceMap,
        terms: &CaptureTerms,
        f: impl FnOnce(&Room, &mut RenderRates) -> T,
    ) -> Result<T, CycleError> {
        let geometry = match &self.geometry {
            Some((_, g)) => g,
            None => return Err(CycleError::Model("no geometry".into())),
        };
        let sky = MeasuredSky {
            map,
            terms,
            geometry,
            mf: self.room.dc.mf,
            state: &self.state,
        };
        let room = &mut self.room;
        let rates = &mut self.render_rates;
        sky.install(&mut room.world);
        let result = f(room, rates);
        remove_measured_sky(&mut room.world);
        Ok(result)
    }

    /// Where the daylight coefficients live.
    pub fn dc_path(&self) -> &Path {
        &self.dc_path
    }
}

/// A capture's measured sky (its patches, the ground, the extracted sun), to install in a
/// room's world for the time of a computation: `model::install_measured_sky`.
struct MeasuredSky<'a> {
    map: &'a LuminanceMap,
    terms: &'a CaptureTerms,
    geometry: &'a GroupGeometry,
    mf: usize,
    state: &'a ModelState,
}

impl MeasuredSky<'_> {
    fn install(&self, world: &mut World) {
        install_measured_sky(
            world,
            self.map,
            self.terms,
            self.geometry,
            self.mf,
            self.state,
        );
    }

    /// Runs `f` on `world` under this sky, then takes the sky out again.
    fn with<T>(&self, world: &mut World, f: impl FnOnce(&World) -> T) -> T {
        self.install(world);
        let result = f(world);
        remove_measured_sky(world);
        result
    }
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

fn altitude_deg(d: DVec3) -> f64 {
    d.z.clamp(-1.0, 1.0).asin().to_degrees()
}

/// Azimuth from north towards east, [0, 360) (campaign.md conventions).
fn azimuth_deg(d: DVec3) -> f64 {
    d.x.atan2(d.y).to_degrees().rem_euclid(360.0)
}

/// The frames as a cycle needs them: none flagged by the capture path (a FIFO overflow or a
/// short line means the frame's pixels are not where the geometry says), one per exposure, or
/// the fabric's map. Returns the raw frame size.
fn check_frames(set: &CaptureSet) -> Result<(usize, usize), CycleError> {
    for (k, flags) in set.frame_flags.iter().enumerate() {
        if !flags.is_empty() {
            return Err(CycleError::FlaggedFrame {
                exposure: k,
                exposure_us: set
                    .config
                    .exposure
                    .get(k)
                    .map_or(f64::NAN, |e| e.exposure_us),
                flags: flags.clone(),
            });
        }
    }
    if let Some(m) = &set.fabric_map {
        return Ok((m.raw_width, m.raw_height));
    }
    let (raw_width, raw_height) = match set.frames.first() {
        Some(f) => (f.width, f.height),
        None => return Err(CycleError::Hdr("the capture holds no frame".into())),
    };
    if set.frames.len() != set.config.exposure.len() {
        return Err(CycleError::Hdr(format!(
            "{} frames for {} exposures",
            set.frames.len(),
            set.config.exposure.len()
        )));
    }
    Ok((raw_width, raw_height))
}

/// The cycle record's sun: SPA's, and the extracted one or why there is none.
fn sun_record(spa: &skylux_hps::sun::SolarPosition, terms: &CaptureTerms) -> SunRecord {
    let sun = &terms.sun;
    SunRecord {
        spa_altitude_deg: spa.altitude_deg(),
        spa_azimuth_deg: spa.azimuth_deg,
        extracted: sun.is_some(),
        extracted_altitude_deg: sun.as_ref().map(|s| altitude_deg(s.direction)),
        extracted_azimuth_deg: sun.as_ref().map(|s| azimuth_deg(s.direction)),
        direct_normal_lux: sun.as_ref().map(|s| s.direct_normal_illuminance_lux),
        flags: match (sun, &terms.sun_missing) {
            (Some(s), _) => s.flags.iter().map(|f| f.name().to_string()).collect(),
            (None, Some(why)) => vec![format!("no_sun:{}", why.tag())],
            (None, None) => vec!["no_sun:unexplained".to_string()],
        },
        missing_reason: terms.sun_missing.as_ref().map(|why| why.to_string()),
    }
}

/// One value per sensor, by name, without a standard error.
fn sensor_lux(sensors: &[skylux_hps::scene::Sensor], lux: &[f64]) -> Vec<SensorLux> {
    sensors
        .iter()
        .zip(lux)
        .map(|(s, &lux)| SensorLux {
            sensor: s.name.clone(),
            lux,
            stderr_lux: None,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angles_follow_campaign_conventions() {
        assert!((azimuth_deg(DVec3::new(1.0, 0.0, 0.0)) - 90.0).abs() < 1e-12);
        assert!((azimuth_deg(DVec3::new(0.0, -1.0, 0.0)) - 180.0).abs() < 1e-12);
        assert!((azimuth_deg(DVec3::new(-1.0, 0.0, 0.0)) - 270.0).abs() < 1e-12);
        assert!((altitude_deg(DVec3::new(0.0, 1.0, 1.0).normalize()) - 45.0).abs() < 1e-12);
    }
}
