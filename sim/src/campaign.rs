//! Simulated measurement campaigns (shared/spec/campaign.md) with effects present in the
//! world but not declared to the model: the test bed of the loop (`skylux sim campaign`).
//!
//! The world at each capture time: the sun where SPA puts it; a clear-sky irradiance model
//! (ASHRAE) or an overcast or partly cloudy variant; the Perez all-weather sky for that
//! irradiance, modulated by clouds the Perez model does not know (so the Perez baseline has
//! a real error to show, as in the field); a ground of the world's reflectance. The camera
//! (the one camera model, through the sensor model) images it into raw frames; the room
//! (the daylighting engine, by direct path tracing of the continuous sky and a `light` sun)
//! gives the lux-meter readings; the pyranometer records the irradiance. With
//! [`TruthSource::Radiance`] RADIANCE's daylight coefficients give them instead
//! ([`crate::radiance_truth`]), so the truth does not come from the engine the loop's model
//! uses.
//!
//! Undeclared effects ([`WorldEffects`]) change the world, never `device.toml` or the scene:
//! the model is told what the campaign's owner believes, not what is true.

use crate::capture::{simulate_capture, CaptureSpec};
use chrono::{DateTime, Datelike, Duration, FixedOffset, NaiveDate, TimeZone, Utc};
use glam::DVec3;
use skylux_hps::camera::{CameraModel, DeviceConfig};
use skylux_hps::campaign::{
    write_luxmeters, CampaignConfig, CampaignFiles, LuxmeterReading, Readout, Site,
};
use skylux_hps::engine::sky::DistantEmitter;
use skylux_hps::engine::{self, Settings, World};
use skylux_hps::io::irradiance::{write_pyranometer_csv, PyranometerRow};
use skylux_hps::sky::perez::{PerezConditions, PerezInput, PerezSky};
use skylux_hps::sun::position::{solar_position, Site as SunSite, SolarPosition};
use skylux_hps::validation::effects::{self, registry, LoopEffect};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// What the sky does on a simulated day.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DaySky {
    Clear,
    Overcast,
    /// Broken clouds: the sun comes and goes, the sky is patchy.
    Partly,
}

impl std::str::FromStr for DaySky {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "clear" => Ok(Self::Clear),
            "overcast" => Ok(Self::Overcast),
            "partly" => Ok(Self::Partly),
            other => Err(format!(
                "unknown sky `{other}`: expected clear, overcast or partly"
            )),
        }
    }
}

/// Effects present in the world and not declared to the model. Each default is "absent".
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorldEffects {
    /// Glazing transmittance relative to the scene's (dirt: < 1).
    pub glazing_transmittance: f64,
    /// Light reaching the lux-meters by a path the scene lacks, as a fraction of the outdoor
    /// horizontal illuminance (lux per lux).
    pub light_leak: f64,
    /// Reflectance of the ground outside (the model assumes 0.2 where the lens does not see it).
    pub ground_reflectance: f64,
    /// The camera's true axis azimuth minus the declared one, degrees.
    pub orientation_azimuth_deg: f64,
    /// The lux-meter logger's clock minus the device's, seconds: a reading of the light at
    /// true time t carries the timestamp t + offset in `luxmeters.csv`.
    pub clock_offset_s: f64,
    /// The shutter's overhead, µs: a frame declared as t integrates for t + overhead (the
    /// MT9P031's electronic shutter adds a fixed fraction of a row time; datasheet
    /// "Exposure" section). Biases the shortest exposures, which measure the sun.
    pub shutter_overhead_us: f64,
    /// Spectral mismatch with the sky's colour: the clear sky's colour temperature far from
    /// the sun, K (0: a spectrally grey world). The frames are rendered with the sky's real
    /// colour through measured camera sensitivities (`crate::sky_colour`) while `device.toml`
    /// keeps the weights calibrated under D65.
    pub spectral_clear_sky_cct_k: f64,
    /// The glazing's angular transmittance beyond the scene's glass: ASHRAE's
    /// incidence-angle modifier parameter b0 (Souka & Safwat 1966; pvlib `iam.ashrae`; 0.05
    /// for clean glass): light crossing the glazing at incidence θ is multiplied by
    /// 1 − b0 (1/cos θ − 1), clamped to [0, 1]. 0: absent.
    pub glazing_angular_b0: f64,
    /// Relative illumination steeper than `device.toml`'s polynomial: every frame is rendered
    /// with the declared V(α) times `1 − v (α / 90°)²` ([`extra_vignetting_factor`]).
    pub extra_vignetting: f64,
    /// A housing or baffle clips the image beyond this off-axis angle, degrees: the sensor
    /// sees nothing there (≥ 180: no clipping, the declared lens alone).
    pub fov_limit_deg: f64,
}

/// The extra relative illumination of the `vignetting` effect at off-axis angle α: the
/// leading term of the even radial polynomial that models a lens's vignetting,
/// 1 + a₂ r² + a₄ r⁴ + … (Goldman, "Vignette and exposure calibration and compensation",
/// IEEE TPAMI 32(12), 2010; Kang & Weiss, ECCV 2000), with the image radius r of the
/// equidistant fisheye proportional to α and normalised at 90°: `1 − v (α / 90°)²`, clamped
/// at 0. One parameter, and the same form the loop fits.
pub fn extra_vignetting_factor(v: f64, off_axis_rad: f64) -> f64 {
    (1.0 - v * (off_axis_rad / std::f64::consts::FRAC_PI_2).powi(2)).max(0.0)
}

impl Default for WorldEffects {
    fn default() -> Self {
        Self {
            glazing_transmittance: 1.0,
            light_leak: 0.0,
            ground_reflectance: 0.2,
            orientation_azimuth_deg: 0.0,
            clock_offset_s: 0.0,
            shutter_overhead_us: 0.0,
            spectral_clear_sky_cct_k: 0.0,
            glazing_angular_b0: 0.0,
            extra_vignetting: 0.0,
            fov_limit_deg: 180.0,
        }
    }
}

impl WorldEffects {
    /// Sets one effect from `NAME=VALUE`: the names of the loop's effect library
    /// (`skylux_hps::validation::effects::registry`), or their aliases.
    pub fn set(&mut self, assignment: &str) -> Result<(), String> {
        let (name, value) = assignment
            .split_once('=')
            .ok_or_else(|| format!("`{assignment}`: expected NAME=VALUE"))?;
        let v: f64 = value
            .trim()
            .parse()
            .map_err(|_| format!("`{assignment}`: `{value}` is not a number"))?;
        if !v.is_finite() {
            return Err(format!("`{assignment}`: the value must be finite"));
        }
        let name = name.trim();
        let effect = registry::find(name).ok_or_else(|| {
            format!(
                "unknown effect `{name}`: expected {}",
                effect_names().join(", ")
            )
        })?;
        let world = WORLD_PARAMETERS
            .iter()
            .find(|w| w.effect.name() == effect.name())
            .ok_or_else(|| {
                format!(
                    "`{assignment}`: {} is not simulated in the world (expected {})",
                    effect.name(),
                    effect_names().join(", ")
                )
            })?;
        if !(world.valid)(v) {
            return Err(format!("`{assignment}`: {name} must be {}", world.range));
        }
        (world.set)(self, v);
        Ok(())
    }
}

/// How an effect of the loop's library is present in the world: the parameter
/// `--effect NAME=VALUE` sets (named by the effect, or by one of its aliases), its range, and
/// its place in [`WorldEffects`].
struct WorldParameter {
    effect: &'static dyn LoopEffect,
    valid: fn(f64) -> bool,
    range: &'static str,
    set: fn(&mut WorldEffects, f64),
}

/// The effects the simulator can put in the world.
const WORLD_PARAMETERS: &[WorldParameter] = &[
    WorldParameter {
        effect: &effects::glazing_transmittance::GlazingTransmittance,
        valid: |v| (0.1..=1.5).contains(&v),
        range: "in [0.1, 1.5]",
        set: |w, v| w.glazing_transmittance = v,
    },
    WorldParameter {
        effect: &effects::light_leak::LightLeak,
        valid: |v| (0.0..=0.2).contains(&v),
        range: "in [0, 0.2]",
        set: |w, v| w.light_leak = v,
    },
    WorldParameter {
        effect: &effects::ground_reflectance::GroundReflectance,
        valid: |v| (0.0..=1.0).contains(&v),
        range: "in [0, 1]",
        set: |w, v| w.ground_reflectance = v,
    },
    WorldParameter {
        effect: &effects::orientation_error::OrientationError,
        valid: |v| v.abs() <= 10.0,
        range: "within ±10 degrees",
        set: |w, v| w.orientation_azimuth_deg = v,
    },
    WorldParameter {
        effect: &effects::clock_offset::ClockOffset,
        valid: |v| v.abs() <= 1800.0,
        range: "within ±1800 seconds",
        set: |w, v| w.clock_offset_s = v,
    },
    WorldParameter {
        effect: &effects::shutter_overhead::ShutterOverhead,
        valid: |v| (0.0..=100.0).contains(&v),
        range: "in [0, 100] µs",
        set: |w, v| w.shutter_overhead_us = v,
    },
    WorldParameter {
        effect: &effects::spectral_mismatch::SpectralMismatch,
        valid: |v| v == 0.0 || (4000.0..=25_000.0).contains(&v),
        range: "0 (off) or a clear-sky colour temperature in [4000, 25000] K",
        set: |w, v| w.spectral_clear_sky_cct_k = v,
    },
    WorldParameter {
        effect: &effects::glazing_angular::GlazingAngular,
        valid: |v| (0.0..=1.0).contains(&v),
        range: "in [0, 1] (ASHRAE b0)",
        set: |w, v| w.glazing_angular_b0 = v,
    },
    WorldParameter {
        effect: &effects::vignetting::Vignetting,
        valid: |v| (0.0..=0.9).contains(&v),
        range: "in [0, 0.9]",
        set: |w, v| w.extra_vignetting = v,
    },
    // The world parameter is the baffle's field of view, degrees (also spelt
    // `fov_limit_deg`, the effect's alias).
    WorldParameter {
        effect: &effects::sky_outside_fov::SkyOutsideFov,
        valid: |v| (20.0..=180.0).contains(&v),
        range: "in [20, 180] degrees",
        set: |w, v| w.fov_limit_deg = v,
    },
];

/// The names `--effect NAME=VALUE` accepts (aliases aside), in the library's order.
pub fn effect_names() -> Vec<&'static str> {
    registry::EFFECTS
        .iter()
        .filter(|e| WORLD_PARAMETERS.iter().any(|w| w.effect.name() == e.name()))
        .map(|e| e.name())
        .collect()
}

/// When the lux-meter logger records: every `cadence_s` seconds within `half_window_s` of
/// each capture (a logger runs continuously; only the readings near captures matter to the
/// loop, and each one costs nothing once the room's sky and sun parts are traced).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LoggerSchedule {
    pub cadence_s: f64,
    pub half_window_s: f64,
}

impl Default for LoggerSchedule {
    /// A reading every 30 s within ±10 min of each capture: enough for the loop to scan clock
    /// offsets of up to ±5 min.
    fn default() -> Self {
        Self {
            cadence_s: 30.0,
            half_window_s: 600.0,
        }
    }
}

impl LoggerSchedule {
    /// The widest window a capture's series may span, s: the light around a capture is
    /// modelled from that capture's sky and sun, which a longer stretch would outlast.
    pub const MAX_HALF_WINDOW_S: f64 = 1800.0;

    /// A logger recording all the time between captures `captures_every_s` apart, every 30 s:
    /// each capture keeps the readings up to half the spacing less one cadence, so windows
    /// never overlap (nor exceed [`Self::MAX_HALF_WINDOW_S`]), and clock offsets up to about
    /// half the spacing stay inside the record.
    pub fn continuous(captures_every_s: f64) -> Self {
        let cadence_s = Self::default().cadence_s;
        Self {
            cadence_s,
            half_window_s: (captures_every_s / 2.0 - cadence_s).clamp(0.0, Self::MAX_HALF_WINDOW_S),
        }
    }

    /// Checks the schedule, naming what is wrong.
    pub fn validate(&self) -> Result<(), String> {
        if !(self.cadence_s.is_finite() && self.cadence_s > 0.0) {
            return Err(format!(
                "logger cadence {} s: must be positive",
                self.cadence_s
            ));
        }
        if !(0.0..=Self::MAX_HALF_WINDOW_S).contains(&self.half_window_s) {
            return Err(format!(
                "logger half window {} s: must be within 0 to {} s",
                self.half_window_s,
                Self::MAX_HALF_WINDOW_S
            ));
        }
        Ok(())
    }
}

/// The sun's transmission through passing clouds around one capture on a partly cloudy day,
/// as a function of time from the capture: the day's [`PassingClouds`] seen from the capture.
#[derive(Clone, Debug)]
struct SunSchedule {
    /// `None`: the sun's transmission is 1 throughout (clear, overcast, or a fixed state).
    /// Else the day's clouds and the capture's time in them, s.
    passing: Option<(Arc<PassingClouds>, f64)>,
}

impl SunSchedule {
    fn steady() -> Self {
        Self { passing: None }
    }

    /// Transmission in [0, 1] at `dt_s` seconds from the capture.
    fn at(&self, dt_s: f64) -> f64 {
        match &self.passing {
            None => 1.0,
            Some((clouds, capture_s)) => clouds.at(capture_s + dt_s),
        }
    }
}

/// The clouds passing over the sun during one partly cloudy day: sunny and shaded spells of
/// random lengths, one sequence for the whole day, so the lux-meters' record is one record
/// whatever capture it is read around (a logger clock offset then reads the light of another
/// moment of the same day, as it would), and not periodic (a periodic one would make an
/// offset of one period look the same as none, which real clouds do not). Soft edges: a cloud
/// edge takes [`PassingClouds::EDGE_S`] to cross the disk.
#[derive(Clone, Debug)]
struct PassingClouds {
    /// Spell edges, s of the local day, increasing.
    edges_s: Vec<f64>,
    sunny_before_first: bool,
}

impl PassingClouds {
    /// Time for a cloud edge to cross the sun's disk, s.
    const EDGE_S: f64 = 20.0;
    /// Spells are drawn this far beyond the first and last captures: the logger's window plus
    /// the largest clock offset the loop searches (±30 min).
    const SPAN_S: f64 = 3600.0;
    /// Shortest and longest spell, s.
    const SPELL_S: (f64, f64) = (60.0, 420.0);

    /// The day's spells around captures at `captures_s` (s of the local day). No capture
    /// falls on an edge (the camera's exposures take a fraction of a second; a sun half behind
    /// a cloud edge at that instant is a case left to other tests): an edge drawn within an
    /// edge time of a capture moves to just clear of it.
    fn new(seed: u64, captures_s: &[f64]) -> Self {
        let first = captures_s.iter().copied().fold(f64::INFINITY, f64::min);
        let last = captures_s.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let (short, long) = Self::SPELL_S;
        let mut edges_s = Vec::new();
        let mut t = first - Self::SPAN_S - long * hash01(seed, 1);
        let mut k = 2;
        while t < last + Self::SPAN_S {
            t += short + (long - short) * hash01(seed, k);
            k += 1;
            let clear = captures_s
                .iter()
                .filter(|c| (t - **c).abs() < Self::EDGE_S)
                .map(|c| {
                    if t < *c {
                        c - Self::EDGE_S
                    } else {
                        c + Self::EDGE_S
                    }
                })
                .next();
            edges_s.push(clear.unwrap_or(t));
        }
        Self {
            edges_s,
            sunny_before_first: hash01(seed, 0) < 0.5,
        }
    }

    /// Transmission in [0, 1] at `t_s` (s of the local day).
    fn at(&self, t_s: f64) -> f64 {
        let passed = self.edges_s.partition_point(|&e| e <= t_s);
        let state = |edges_passed: usize| {
            if edges_passed.is_multiple_of(2) == self.sunny_before_first {
                1.0
            } else {
                0.0
            }
        };
        // Within half an edge time of an edge, a linear ramp between the two states.
        let half = 0.5 * Self::EDGE_S;
        for (i, &e) in self
            .edges_s
            .iter()
            .enumerate()
            .skip(passed.saturating_sub(1))
            .take(2)
        {
            if (t_s - e).abs() < half {
                let w = (t_s - (e - half)) / Self::EDGE_S;
                return state(i) + (state(i + 1) - state(i)) * w;
            }
        }
        state(passed)
    }
}

/// One capture time of the campaign: its day, the day's sky and its passing clouds.
struct Moment {
    date: NaiveDate,
    kind: DaySky,
    /// Local clock hour.
    hour: f64,
    /// The day's clouds, on a partly cloudy day.
    clouds: Option<Arc<PassingClouds>>,
}

/// Per sensor, the room's light from the sky (and its ground) and from the sun between
/// clouds (and its ground), lux: traced apart where the lux-meters log a series, so passing
/// clouds scale the sun's part alone.
struct SkySunParts {
    sky_lux: Vec<f64>,
    sun_lux: Vec<f64>,
}

/// What gives the lux-meters' truth.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TruthSource {
    /// Skylux's own engine (direct path tracing, converged bounces): quick, but the engine
    /// the loop's model also uses, so the test bed is not independent of it.
    #[default]
    Engine,
    /// RADIANCE's rcontrib daylight coefficients ([`crate::radiance_truth`]) with this many
    /// diffuse bounces: independent of Skylux's engine; needs RADIANCE installed.
    Radiance { ambient_bounces: u32 },
}

impl TruthSource {
    /// RADIANCE, converged ([`crate::radiance_truth::CONVERGED_BOUNCES`]).
    pub const RADIANCE: Self = Self::Radiance {
        ambient_bounces: crate::radiance_truth::CONVERGED_BOUNCES,
    };
}

impl std::str::FromStr for TruthSource {
    type Err = String;
    /// `engine`, `radiance` (converged) or `radiance:N` (N diffuse bounces, 1 to 32).
    fn from_str(s: &str) -> Result<Self, String> {
        match s.split_once(':') {
            None if s == "engine" => Ok(Self::Engine),
            None if s == "radiance" => Ok(Self::RADIANCE),
            Some(("radiance", n)) => match n.parse::<u32>() {
                Ok(b) if (1..=32).contains(&b) => Ok(Self::Radiance { ambient_bounces: b }),
                _ => Err(format!(
                    "`{s}`: the bounces after `radiance:` must be a whole number from 1 to 32"
                )),
            },
            _ => Err(format!(
                "unknown truth `{s}`: expected engine, radiance or radiance:BOUNCES"
            )),
        }
    }
}

/// A campaign to simulate.
#[derive(Clone, Debug)]
pub struct CampaignSpec {
    pub name: String,
    pub site: Site,
    /// Offset of the local clock written in every timestamp, seconds east of UTC.
    pub utc_offset_s: i32,
    pub days: Vec<(NaiveDate, DaySky)>,
    /// Local clock times of the captures, hours.
    pub hours: Vec<f64>,
    /// The camera as declared in `device.toml`.
    pub device: DeviceConfig,
    /// Readout skip (1: full resolution); the window is the whole array.
    pub skip: u32,
    pub exposures_us: Vec<f64>,
    /// The room: a folder with `scene.rad` and `sensors.pts`.
    pub room_dir: PathBuf,
    pub effects: WorldEffects,
    /// When the lux-meters log. `None`: one reading per capture time, except on partly
    /// cloudy days or with a clock offset, which log by [`LoggerSchedule::default`] (the
    /// light changes within minutes, and the loop needs the readings around each capture).
    /// `Some`: every capture logs by that schedule (e.g. [`LoggerSchedule::continuous`] for
    /// clock offsets beyond the default's ±5 min).
    pub logger: Option<LoggerSchedule>,
    /// Relative standard deviation of a lux-meter reading.
    pub luxmeter_noise: f64,
    /// Paths per sensor of the engine run that gives the true illuminance.
    pub truth_samples: u32,
    /// What gives the lux-meters' truth (the engine by default).
    pub truth: TruthSource,
    pub seed: u64,
    /// The shared data folder (`spectral/` within), for the spectral-mismatch effect.
    pub spectral_data_dir: Option<PathBuf>,
}

impl CampaignSpec {
    /// The demo's campaign: the reference test module in Lausanne, a clear and an overcast
    /// day in May, captures every hour from 8:00 to 18:00, the camera facing south through
    /// the façade as declared in the spec's example `device.toml`.
    pub fn lausanne(room_dir: PathBuf) -> Self {
        // `$SKYLUX_DATA_DIR`, else the shared data beside the shared scenes.
        let spectral_data_dir =
            skylux_hps::photometry::spectral::data_dir_from_env().or_else(|| {
                let d = room_dir.join("../../data");
                d.join("spectral").is_dir().then_some(d)
            });
        Self {
            name: "lausanne-simulated".into(),
            site: Site {
                latitude_deg: 46.52,
                longitude_deg: 6.57,
                elevation_m: 400.0,
            },
            utc_offset_s: 2 * 3600,
            days: vec![
                (
                    NaiveDate::from_ymd_opt(2017, 5, 8).expect("date"),
                    DaySky::Clear,
                ),
                (
                    NaiveDate::from_ymd_opt(2017, 5, 9).expect("date"),
                    DaySky::Overcast,
                ),
            ],
            hours: (8..=18).map(f64::from).collect(),
            device: DeviceConfig::default(),
            skip: 4,
            exposures_us: vec![1.0, 26.59, 707.1, 18_803.0, 500_000.0],
            room_dir,
            effects: WorldEffects::default(),
            logger: None,
            luxmeter_noise: 0.01,
            truth_samples: 4096,
            truth: TruthSource::Engine,
            seed: 2017,
            spectral_data_dir,
        }
    }
}

/// Why a campaign could not be simulated.
#[derive(Debug, thiserror::Error)]
pub enum SimCampaignError {
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("{0}")]
    Invalid(String),
    #[error(transparent)]
    Capture(#[from] crate::capture::WriteCaptureError),
    #[error(transparent)]
    Scene(#[from] skylux_hps::scene::SceneError),
    #[error(transparent)]
    Sensors(#[from] skylux_hps::scene::SensorsError),
    #[error(transparent)]
    Engine(#[from] skylux_hps::engine::EngineError),
    #[error(transparent)]
    Campaign(#[from] skylux_hps::campaign::CampaignError),
    #[error(transparent)]
    Device(#[from] skylux_hps::camera::DeviceError),
    #[error("the RADIANCE truth: {0}")]
    RadianceTruth(#[from] crate::radiance_truth::RadianceTruthError),
}

/// The truth of one capture time, for tests.
#[derive(Clone, Debug)]
pub struct TruthRecord {
    pub time: DateTime<FixedOffset>,
    pub sun_direction: DVec3,
    pub global_horizontal_lux: f64,
    /// Per sensor, before the lux-meter's effects and noise.
    pub room_lux: Vec<f64>,
}

/// ASHRAE clear-day model for May (ASHRAE Handbook of Fundamentals 1985, ch. 27, table 1,
/// 21 May: A = 1088 W/m², B = 0.205, C = 0.134): DNI = A exp(−B / sin h), DHI = C · DNI.
fn clear_sky_w_m2(altitude_rad: f64) -> (f64, f64) {
    let s = altitude_rad.sin().max(0.02);
    let dni = 1088.0 * (-0.205 / s).exp();
    (dni, 0.134 * dni)
}

/// A deterministic hash to [0, 1).
fn hash01(seed: u64, k: u64) -> f64 {
    let mut s = seed ^ k.wrapping_mul(0x9E37_79B9_7F4A_7C15);
    let x = skylux_hps::engine::rng::splitmix64(&mut s);
    (x >> 11) as f64 / (1u64 << 53) as f64
}

/// Cloud modulation of the sky: a few soft blobs, brighter or darker than Perez.
#[derive(Clone, Debug)]
struct Clouds {
    blobs: Vec<(DVec3, f64, f64)>,
}

impl Clouds {
    fn new(kind: DaySky, seed: u64) -> Self {
        let n = match kind {
            DaySky::Clear => 0,
            DaySky::Overcast => 6,
            DaySky::Partly => 10,
        };
        let blobs = (0..n)
            .map(|i| {
                let az = std::f64::consts::TAU * hash01(seed, 3 * i);
                let alt = (hash01(seed, 3 * i + 1) * 0.9 + 0.05).asin();
                let d = DVec3::new(az.sin() * alt.cos(), az.cos() * alt.cos(), alt.sin());
                let amp = (hash01(seed, 3 * i + 2) - 0.4) * 0.8;
                (d, amp, 0.25)
            })
            .collect();
        Self { blobs }
    }
    fn factor(&self, d: DVec3) -> f64 {
        let mut f = 1.0;
        for &(c, amp, width) in &self.blobs {
            let a = d.angle_between(c);
            f += amp * (-(a / width).powi(2)).exp();
        }
        f.max(0.2)
    }
}

/// Writes the campaign to `out` and returns the truth per capture time.
pub fn simulate_campaign(
    out: &Path,
    spec: &CampaignSpec,
    progress: &dyn Fn(usize, usize),
) -> Result<Vec<TruthRecord>, SimCampaignError> {
    if spec.days.is_empty() || spec.hours.is_empty() {
        return Err(SimCampaignError::Invalid(
            "a campaign needs at least one day and one capture time".into(),
        ));
    }
    if let Some(logger) = &spec.logger {
        logger.validate().map_err(SimCampaignError::Invalid)?;
    }
    write_declared(out, spec)?;
    let mut world = TrueWorld::new(out, spec)?;
    if let TruthSource::Radiance { ambient_bounces } = spec.truth {
        world.radiance = Some(RadianceRoom::new(out, spec, &world, ambient_bounces)?);
    }
    let mut records = Records::default();
    let total = spec.days.len() * spec.hours.len();
    let mut k = 0u64;
    for (day, &(date, kind)) in spec.days.iter().enumerate() {
        let captures_s: Vec<f64> = spec.hours.iter().map(|h| h * 3600.0).collect();
        let clouds = (kind == DaySky::Partly).then(|| {
            Arc::new(PassingClouds::new(
                spec.seed ^ ((day as u64 + 1) << 40) ^ 0x5EED_C10D,
                &captures_s,
            ))
        });
        for &hour in &spec.hours {
            k += 1;
            progress(k as usize - 1, total);
            let moment = Moment {
                date,
                kind,
                hour,
                clouds: clouds.clone(),
            };
            world.capture_time(out, spec, &moment, k, &mut records)?;
        }
    }
    progress(total, total);
    records.write(out)?;
    Ok(records.truth)
}

/// An I/O error on `path`.
fn io_error(path: &Path) -> impl FnOnce(std::io::Error) -> SimCampaignError {
    let path = path.to_path_buf();
    move |source| SimCampaignError::Io { path, source }
}

/// What the campaign's owner declares: the room, `campaign.toml` and `device.toml`.
fn write_declared(out: &Path, spec: &CampaignSpec) -> Result<(), SimCampaignError> {
    std::fs::create_dir_all(out.join("room")).map_err(io_error(out))?;
    for f in ["scene.rad", "sensors.pts"] {
        std::fs::copy(spec.room_dir.join(f), out.join("room").join(f))
            .map_err(io_error(&spec.room_dir.join(f)))?;
    }
    CampaignConfig {
        name: spec.name.clone(),
        site: spec.site.clone(),
        files: CampaignFiles::default(),
    }
    .write(&out.join("campaign.toml"))?;
    spec.device.write(&out.join("device.toml"))?;
    Ok(())
}

/// What the campaign records: the truth, the lux-meters and the pyranometer.
#[derive(Default)]
struct Records {
    truth: Vec<TruthRecord>,
    readings: Vec<LuxmeterReading>,
    pyranometer: Vec<PyranometerRow>,
}

impl Records {
    /// Writes `luxmeters.csv` and `pyranometer.csv`.
    fn write(&self, out: &Path) -> Result<(), SimCampaignError> {
        let path = out.join("luxmeters.csv");
        let mut text = Vec::new();
        write_luxmeters(&mut text, &self.readings).map_err(io_error(&path))?;
        std::fs::write(&path, text).map_err(io_error(&path))?;
        let path = out.join("pyranometer.csv");
        let mut text = Vec::new();
        write_pyranometer_csv(&mut text, &self.pyranometer).map_err(io_error(&path))?;
        std::fs::write(&path, text).map_err(io_error(&path))?;
        Ok(())
    }
}

/// The glazing's angular transmittance in the world: the incidence-angle modifier of light
/// arriving from a direction (1 without the effect).
#[derive(Clone, Copy, Debug)]
struct GlazingIam {
    normal_out: Option<DVec3>,
    b0: f64,
}

impl GlazingIam {
    fn new(world: &World, b0: f64) -> Result<Self, SimCampaignError> {
        if b0 <= 0.0 {
            return Ok(Self {
                normal_out: None,
                b0,
            });
        }
        let g = skylux_hps::validation::glazing::Glazing::of_world(world)
            .map_err(|e| SimCampaignError::Invalid(format!("glazing_angular: {e}")))?;
        if !g.single_orientation() {
            return Err(SimCampaignError::Invalid(format!(
                "glazing_angular: the scene's glazing lies in {} planes facing different ways; \
                 the simulated effect needs one orientation",
                g.planes.len()
            )));
        }
        Ok(Self {
            normal_out: Some(g.primary().normal_out),
            b0,
        })
    }

    fn at(&self, d: DVec3) -> f64 {
        self.normal_out.map_or(1.0, |n| {
            skylux_hps::validation::glazing::iam_ashrae(d.dot(n), self.b0)
        })
    }
}

/// The world as it is, undeclared effects included: the room, the true camera, the glazing.
struct TrueWorld {
    world: World,
    sensors: Vec<skylux_hps::scene::Sensor>,
    iam: GlazingIam,
    true_camera: CameraModel,
    raw_width: usize,
    raw_height: usize,
    offset: FixedOffset,
    sun_site: SunSite,
    /// The camera's channel responses to daylight, where the sky's colour is simulated.
    responses: Option<crate::sky_colour::DaylightResponses>,
    /// With [`TruthSource::Radiance`], RADIANCE's coefficients in place of the engine.
    radiance: Option<RadianceRoom>,
}

/// The room's daylight coefficients from RADIANCE for the whole campaign, and the sun of
/// each capture time among them.
struct RadianceRoom {
    truth: crate::radiance_truth::RadianceTruth,
    /// Per capture time k (from 1), the index of its sun, `None` where it is skipped.
    sun_of_capture: Vec<Option<usize>>,
}

impl RadianceRoom {
    /// One rcontrib run with every capture's sun.
    fn new(
        out: &Path,
        spec: &CampaignSpec,
        world: &TrueWorld,
        ambient_bounces: u32,
    ) -> Result<Self, SimCampaignError> {
        use crate::radiance_truth::{DaylightCoefficients, RadianceTruth, SunSource};
        let radiance = crate::radiance_tools::Radiance::find()
            .map_err(crate::radiance_truth::RadianceTruthError::from)?;
        let mut suns = Vec::new();
        let mut sun_of_capture = vec![None];
        for &(date, _) in &spec.days {
            for &hour in &spec.hours {
                let (_, sun) = world.instant(date, hour)?;
                sun_of_capture.push((sun.altitude_deg() >= MIN_SUN_ALTITUDE_DEG).then(|| {
                    suns.push(SunSource {
                        direction: sun.direction(),
                        solid_angle_sr: sun_solid_angle_sr(),
                    });
                    suns.len() - 1
                }));
            }
        }
        let coefficients = DaylightCoefficients::compute(
            &radiance,
            &out.join("room/scene.rad"),
            &world.sensors,
            &suns,
            ambient_bounces,
        )?;
        Ok(Self {
            truth: RadianceTruth::new(coefficients),
            sun_of_capture,
        })
    }
}

impl RadianceRoom {
    /// [`TrueWorld::trace`] from RADIANCE's coefficients: capture `k`'s sky `above` (or
    /// none), a uniform ground and its sun, each through the glazing's angular
    /// transmittance.
    fn lux(
        &self,
        k: u64,
        iam: &GlazingIam,
        sky: &MomentSky,
        above: Option<&MomentSky>,
        ground_cd_m2: f64,
        sun_cd_m2: f64,
    ) -> Result<Vec<f64>, SimCampaignError> {
        let mut lux = self.truth.ground_lux(ground_cd_m2, &|d| iam.at(d));
        if let Some(above) = above {
            let from_sky = self.truth.sky_lux(&|d| iam.at(d) * above.sky(d));
            lux.iter_mut().zip(from_sky).for_each(|(a, b)| *a += b);
        }
        if sun_cd_m2 > 0.0 {
            let sun = self
                .sun_of_capture
                .get(k as usize)
                .copied()
                .flatten()
                .ok_or_else(|| {
                    SimCampaignError::Invalid(format!("capture {k} has no RADIANCE sun"))
                })?;
            let from_sun = self
                .truth
                .sun_lux(sun, sun_cd_m2 * iam.at(sky.sun_direction));
            lux.iter_mut().zip(from_sun).for_each(|(a, b)| *a += b);
        }
        Ok(lux)
    }
}

/// Capture times with the sun under this altitude are skipped, degrees.
const MIN_SUN_ALTITUDE_DEG: f64 = 3.0;

/// The solid angle of the world's solar disk, sr (the Perez sky's: gendaylit's half-angle).
fn sun_solid_angle_sr() -> f64 {
    std::f64::consts::TAU
        * (1.0
            - skylux_hps::sky::perez::GENDAYLIT_HALF_SUN_ANGLE_DEG
                .to_radians()
                .cos())
}

/// The sky at one capture time: the Perez sky for the day's irradiance, the clouds it does
/// not know, and the sun between them.
#[derive(Clone)]
struct MomentSky {
    kind: DaySky,
    dni: f64,
    dhi: f64,
    schedule: SunSchedule,
    /// The sun's transmission at the capture itself.
    s0: f64,
    perez: PerezSky,
    clouds: Clouds,
    /// The modulated sky integrated on the horizontal, lux.
    diffuse_lux: f64,
    /// The beam on the horizontal between clouds, lux.
    beam_lux: f64,
    /// True outdoor horizontal illuminance at the capture, lux.
    ghi_lux: f64,
    ground_cd_m2: f64,
    sun_cd_m2: f64,
    sun_direction: DVec3,
    sun_cos_half: f64,
}

impl MomentSky {
    fn new(
        spec: &CampaignSpec,
        moment: &Moment,
        seed: u64,
        sun_dir: DVec3,
        altitude: f64,
    ) -> Result<Self, SimCampaignError> {
        let Moment { date, kind, .. } = *moment;
        let (dni_clear, dhi_clear) = clear_sky_w_m2(altitude);
        let ghi_clear = dni_clear * altitude.sin() + dhi_clear;
        // Partly cloudy days hide the sun one time in three (a cloud bank over the capture's
        // whole logger window); the other times, the day's clouds pass over it within minutes
        // (`dni` is then the beam between clouds).
        let (dni, dhi, schedule) = match kind {
            DaySky::Clear => (dni_clear, dhi_clear, SunSchedule::steady()),
            DaySky::Overcast => (0.0, 0.35 * ghi_clear, SunSchedule::steady()),
            DaySky::Partly => {
                if hash01(seed, 99) < 0.35 {
                    (0.0, 0.55 * ghi_clear, SunSchedule::steady())
                } else {
                    (
                        0.85 * dni_clear,
                        0.25 * ghi_clear,
                        SunSchedule {
                            passing: moment.clouds.clone().map(|c| (c, moment.hour * 3600.0)),
                        },
                    )
                }
            }
        };
        let s0 = schedule.at(0.0);
        let perez = PerezSky::new(
            PerezInput::DirectNormalDiffuse {
                direct_normal_w_m2: dni,
                diffuse_horizontal_w_m2: dhi,
            },
            &PerezConditions {
                day_of_year: date.ordinal() as u16,
                ground_reflectance: spec.effects.ground_reflectance,
                ..PerezConditions::gendaylit_ang(sun_dir)
            },
        )
        .map_err(|e| SimCampaignError::Invalid(e.to_string()))?;
        let clouds = Clouds::new(kind, seed);
        let sky = |d: DVec3| perez.luminance_cd_m2(d) * clouds.factor(d);
        let patches = skylux_hps::sky::SkyPatches::reinhart(4);
        let diffuse_lux: f64 = (0..patches.len())
            .map(|p| {
                let c = patches.centre(p);
                sky(c) * c.z * patches.solid_angle_sr(p)
            })
            .sum();
        let beam_lux = if dni > 0.0 {
            perez.direct_normal_illuminance_lux() * altitude.sin()
        } else {
            0.0
        };
        let ghi_lux = diffuse_lux + beam_lux * s0;
        let sun_cd_m2 = if dni > 0.0 {
            perez.sun_luminance_cd_m2() * s0
        } else {
            0.0
        };
        let sun_half = perez.sun_solid_angle_sr() / std::f64::consts::TAU;
        Ok(Self {
            kind,
            dni,
            dhi,
            schedule,
            s0,
            ground_cd_m2: spec.effects.ground_reflectance * ghi_lux / std::f64::consts::PI,
            perez,
            clouds,
            diffuse_lux,
            beam_lux,
            ghi_lux,
            sun_cd_m2,
            sun_direction: sun_dir,
            sun_cos_half: 1.0 - sun_half,
        })
    }

    /// The sky's luminance in direction `d` (above the horizon), the sun left out, cd/m².
    fn sky(&self, d: DVec3) -> f64 {
        self.perez.luminance_cd_m2(d) * self.clouds.factor(d)
    }

    /// The luminance of everything in direction `d`: ground, sun disk or sky, cd/m².
    fn field(&self, d: DVec3) -> f64 {
        if d.z < 0.0 {
            self.ground_cd_m2
        } else if self.sun_cd_m2 > 0.0 && d.dot(self.sun_direction) >= self.sun_cos_half {
            self.sun_cd_m2
        } else {
            self.sky(d)
        }
    }

    /// The pyranometer's record: the sky as it is (clouds and all), not the Perez sky its
    /// irradiance was drawn from.
    fn pyranometer_row(&self, time: DateTime<FixedOffset>, altitude: f64) -> PyranometerRow {
        let dhi_measured = if self.perez.diffuse_horizontal_illuminance_lux() > 0.0 {
            self.dhi * self.diffuse_lux / self.perez.diffuse_horizontal_illuminance_lux()
        } else {
            self.dhi
        };
        PyranometerRow {
            time,
            ghi_wm2: Some(self.s0 * self.dni * altitude.sin() + dhi_measured),
            dhi_wm2: Some(dhi_measured),
            dni_wm2: Some(self.s0 * self.dni),
        }
    }
}

impl TrueWorld {
    fn new(out: &Path, spec: &CampaignSpec) -> Result<Self, SimCampaignError> {
        let scene = skylux_hps::scene::load(out.join("room/scene.rad"))?;
        let sensors = skylux_hps::scene::load_sensors(out.join("room/sensors.pts"))?;
        let world = World::new(&scene)?;
        let iam = GlazingIam::new(&world, spec.effects.glazing_angular_b0)?;
        let mut true_device = spec.device.clone();
        true_device.orientation.axis_azimuth_deg += spec.effects.orientation_azimuth_deg;
        let (raw_width, raw_height) = (2592 / spec.skip as usize, 1944 / spec.skip as usize);
        let offset = FixedOffset::east_opt(spec.utc_offset_s)
            .ok_or_else(|| SimCampaignError::Invalid("UTC offset out of range".into()))?;
        let responses = if spec.effects.spectral_clear_sky_cct_k > 0.0 {
            let dir = spec.spectral_data_dir.as_deref().ok_or_else(|| {
                SimCampaignError::Invalid(
                    "spectral_mismatch needs the shared spectral data: set SKYLUX_DATA_DIR".into(),
                )
            })?;
            Some(
                crate::sky_colour::DaylightResponses::load(dir)
                    .map_err(|e| SimCampaignError::Invalid(e.to_string()))?,
            )
        } else {
            None
        };
        Ok(Self {
            world,
            sensors,
            iam,
            true_camera: CameraModel::new(true_device),
            raw_width: raw_width & !1,
            raw_height: raw_height & !1,
            offset,
            sun_site: SunSite {
                latitude_deg: spec.site.latitude_deg,
                longitude_deg: spec.site.longitude_deg,
                elevation_m: spec.site.elevation_m,
            },
            responses,
            radiance: None,
        })
    }

    /// The capture instant at local clock `hour` of `date`, and where SPA puts the sun.
    fn instant(
        &self,
        date: NaiveDate,
        hour: f64,
    ) -> Result<(DateTime<FixedOffset>, SolarPosition), SimCampaignError> {
        let midnight = self
            .offset
            .from_local_datetime(&date.and_hms_opt(0, 0, 0).expect("midnight"))
            .single()
            .ok_or_else(|| SimCampaignError::Invalid("ambiguous local time".into()))?;
        let time = midnight + Duration::seconds((hour * 3600.0).round() as i64);
        let sun = solar_position(time.with_timezone(&Utc), &self.sun_site, None)
            .map_err(|e| SimCampaignError::Invalid(e.to_string()))?;
        Ok((time, sun))
    }

    /// Simulates one capture time (the k-th): frames, lux-meter readings, the pyranometer's
    /// row and the truth. Times with the sun under 3° are skipped.
    fn capture_time(
        &mut self,
        out: &Path,
        spec: &CampaignSpec,
        moment: &Moment,
        k: u64,
        records: &mut Records,
    ) -> Result<(), SimCampaignError> {
        let Moment { date, kind, .. } = *moment;
        let (time, sun) = self.instant(date, moment.hour)?;
        let altitude = sun.altitude_deg().to_radians();
        if sun.altitude_deg() < MIN_SUN_ALTITUDE_DEG {
            return Ok(());
        }
        let seed = spec.seed ^ (k << 20);
        let sky = Arc::new(MomentSky::new(
            spec,
            moment,
            seed,
            sun.direction(),
            altitude,
        )?);
        self.render_frames(out, spec, time, seed, &sky)?;
        let logger = spec.logger.or_else(|| {
            (kind == DaySky::Partly || spec.effects.clock_offset_s != 0.0)
                .then(LoggerSchedule::default)
        });
        let (room_lux, parts) = self.trace_room(spec, seed, k, &sky, logger.is_some())?;
        let names: Vec<&str> = self.sensors.iter().map(|s| s.name.as_str()).collect();
        let log = LuxmeterLog {
            spec,
            seed,
            time,
            sky: &sky,
            sensors: &names,
        };
        match (logger, parts) {
            (Some(schedule), Some(parts)) => log.series(schedule, &parts, &mut records.readings),
            _ => log.at_capture(&room_lux, &mut records.readings),
        }
        records
            .pyranometer
            .push(sky.pyranometer_row(time, altitude));
        records.truth.push(TruthRecord {
            time,
            sun_direction: sky.sun_direction,
            global_horizontal_lux: sky.ghi_lux,
            room_lux,
        });
        Ok(())
    }

    /// The raw frames of one capture, through the true camera, lens and housing.
    fn render_frames(
        &self,
        out: &Path,
        spec: &CampaignSpec,
        time: DateTime<FixedOffset>,
        seed: u64,
        sky: &Arc<MomentSky>,
    ) -> Result<(), SimCampaignError> {
        // What reaches the sensor through the true lens and housing: the field times the
        // undeclared extra vignetting, and nothing beyond the baffle's field of view.
        let field = {
            let (v, limit_rad) = (
                spec.effects.extra_vignetting,
                spec.effects.fov_limit_deg.to_radians(),
            );
            let camera = self.true_camera.clone();
            let sky = Arc::clone(sky);
            move |d: DVec3| {
                if v == 0.0 && limit_rad >= std::f64::consts::PI {
                    return sky.field(d);
                }
                let alpha = camera.off_axis_rad(d);
                if alpha > limit_rad {
                    0.0
                } else {
                    sky.field(d) * extra_vignetting_factor(v, alpha)
                }
            }
        };
        let stamp = time.format("%Y-%m-%dT%H%M").to_string();
        let capture_dir = out.join("captures").join(&stamp);
        let capture_spec = CaptureSpec {
            time: time.to_rfc3339(),
            // The frames integrate each group's whole cell (`Footprint::Integrated`): what the
            // sensor reads binned by the skip, declared so (docs/readout.md). A skip that no
            // binning divides keeps the idealisation, and its sun is flagged undersampled.
            readout: Readout {
                col_start: 0,
                row_start: 0,
                skip: spec.skip,
                bin: Readout::largest_bin(spec.skip),
            },
            raw_width: self.raw_width,
            raw_height: self.raw_height,
            exposures_us: spec.exposures_us.clone(),
            gains: vec![1.0],
            seed,
            footprint: crate::sensor::Footprint::Integrated,
            // The disk can fall between the groups' centres where the circumsolar sky is
            // too flat to reveal it.
            small_sources: if sky.sun_cd_m2 > 0.0 {
                vec![crate::sensor::SmallSource {
                    direction: sky.sun_direction,
                    radius_rad: sky.sun_cos_half.clamp(-1.0, 1.0).acos(),
                }]
            } else {
                vec![]
            },
        };
        let overhead_us = spec.effects.shutter_overhead_us;
        let Some(responses) = &self.responses else {
            return Ok(simulate_capture_with_overhead(
                &capture_dir,
                &self.true_camera,
                &field,
                &capture_spec,
                overhead_us,
            )?);
        };
        let colour = crate::sky_colour::SkyColour {
            clear_sky_cct_k: (sky.kind != DaySky::Overcast)
                .then_some(spec.effects.spectral_clear_sky_cct_k),
            sun_direction: sky.sun_direction,
            sun_cos_half: sky.sun_cos_half,
            sun_visible: sky.sun_cd_m2 > 0.0,
        };
        crate::sky_colour::simulate_capture_coloured(
            &capture_dir,
            &self.true_camera,
            &field,
            &colour,
            responses,
            &capture_spec,
            overhead_us,
        )?;
        Ok(())
    }

    /// Per sensor, the room's illuminance from `above` (the sky; `None`: dark), a ground of
    /// `ground_cd_m2` and a sun of `sun_cd_m2`, by direct path tracing. A ray leaving the room
    /// along d crossed the glazing at the angle between d and its normal (glass does not
    /// refract): the angular effect scales what it sees, and the sun, by the IAM at that
    /// angle.
    fn trace(
        &mut self,
        settings: &Settings,
        k: u64,
        sky: &MomentSky,
        above: Option<Arc<MomentSky>>,
        ground_cd_m2: f64,
        sun_cd_m2: f64,
    ) -> Result<Vec<f64>, SimCampaignError> {
        let iam = self.iam;
        if let Some(room) = &self.radiance {
            return room.lux(k, &iam, sky, above.as_deref(), ground_cd_m2, sun_cd_m2);
        }
        self.world.set_environment(Some(Arc::new(move |d: DVec3| {
            let l = if d.z < 0.0 {
                ground_cd_m2
            } else {
                above.as_ref().map_or(0.0, |s| s.sky(d))
            };
            DVec3::splat(iam.at(d) * l / engine::WHITE_EFFICACY_LM_PER_W)
        })));
        let sun = sun_cd_m2 * iam.at(sky.sun_direction);
        if sun > 0.0 {
            self.world.add_distant(DistantEmitter::sun(
                sky.sun_direction,
                sky.perez.sun_solid_angle_sr(),
                sun / engine::WHITE_EFFICACY_LM_PER_W,
            ));
        }
        let lux = engine::illuminance(&self.world, &self.sensors, settings, &|_, _| {})?;
        self.world.clear_distant();
        self.world.set_environment(None);
        Ok(lux.iter().map(|s| s.illuminance_lux).collect())
    }

    /// Per sensor, the light at the capture; with a logger, also the sky (and its ground) and
    /// the sun (and its ground) apart.
    fn trace_room(
        &mut self,
        spec: &CampaignSpec,
        seed: u64,
        k: u64,
        sky: &Arc<MomentSky>,
        logging: bool,
    ) -> Result<(Vec<f64>, Option<SkySunParts>), SimCampaignError> {
        let settings = Settings {
            ambient_bounces: skylux_hps::engine::integrator::CONVERGED_AMBIENT_BOUNCES,
            samples_per_sensor: spec.truth_samples,
            seed,
            ..Default::default()
        };
        let above = Some(Arc::clone(sky));
        if !logging {
            let lux = self.trace(&settings, k, sky, above, sky.ground_cd_m2, sky.sun_cd_m2)?;
            return Ok((lux, None));
        }
        let rho = spec.effects.ground_reflectance;
        let pi = std::f64::consts::PI;
        let sky_lux = self.trace(&settings, k, sky, above, rho * sky.diffuse_lux / pi, 0.0)?;
        let sun_lux = if sky.dni > 0.0 {
            let sun_cd_m2 = sky.perez.sun_luminance_cd_m2();
            self.trace(&settings, k, sky, None, rho * sky.beam_lux / pi, sun_cd_m2)?
        } else {
            vec![0.0; self.sensors.len()]
        };
        let now = sky_lux
            .iter()
            .zip(&sun_lux)
            .map(|(a, b)| a + sky.s0 * b)
            .collect();
        Ok((now, Some(SkySunParts { sky_lux, sun_lux })))
    }
}

/// The lux-meters at one capture time: the true light through the undeclared effects on the
/// readings (glazing, leak, clock) and their noise.
struct LuxmeterLog<'a> {
    spec: &'a CampaignSpec,
    seed: u64,
    time: DateTime<FixedOffset>,
    sky: &'a MomentSky,
    sensors: &'a [&'a str],
}

impl LuxmeterLog<'_> {
    /// A reproducible standard Gaussian per reading (Box-Muller from the hash).
    fn gaussian(&self, key: u64) -> f64 {
        let (u1, u2) = (
            hash01(self.seed, key).max(1e-12),
            hash01(self.seed, key + 1),
        );
        (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
    }

    /// A reading of `true_lux` (outdoor `outdoor_lux`) at `dt_s` from the capture, stamped
    /// by the logger's clock.
    fn reading(
        &self,
        sensor: usize,
        dt_s: f64,
        true_lux: f64,
        outdoor_lux: f64,
        key: u64,
    ) -> LuxmeterReading {
        let e = &self.spec.effects;
        let measured = (true_lux * e.glazing_transmittance + e.light_leak * outdoor_lux)
            * (1.0 + self.spec.luxmeter_noise * self.gaussian(key));
        let ms = ((dt_s + e.clock_offset_s) * 1000.0).round() as i64;
        LuxmeterReading {
            time: self.time + Duration::milliseconds(ms),
            sensor: self.sensors[sensor].to_string(),
            illuminance_lux: measured.max(0.0),
        }
    }

    /// One reading per sensor at the capture.
    fn at_capture(&self, room_lux: &[f64], out: &mut Vec<LuxmeterReading>) {
        for (s, &e) in room_lux.iter().enumerate() {
            out.push(self.reading(s, 0.0, e, self.sky.ghi_lux, 1000 + 2 * s as u64));
        }
    }

    /// A series per sensor around the capture, the passing clouds scaling the sun's part.
    fn series(&self, log: LoggerSchedule, parts: &SkySunParts, out: &mut Vec<LuxmeterReading>) {
        let n = (log.half_window_s / log.cadence_s).floor() as i64;
        let sensors = self.sensors.len();
        for j in -n..=n {
            let dt = j as f64 * log.cadence_s;
            let st = self.sky.schedule.at(dt);
            let ghi_then = self.sky.diffuse_lux + st * self.sky.beam_lux;
            for s in 0..sensors {
                let e = parts.sky_lux[s] + st * parts.sun_lux[s];
                let key = 5000 + 2 * ((j + n) as u64 * sensors as u64 + s as u64);
                out.push(self.reading(s, dt, e, ghi_then, key));
            }
        }
    }
}

/// [`simulate_capture`] with a shutter that integrates each frame for its declared time plus
/// `overhead_us` while `capture.toml` declares the time alone: the undeclared overhead.
/// Without an overhead, exactly [`simulate_capture`].
fn simulate_capture_with_overhead(
    dir: &Path,
    camera: &CameraModel,
    field: &(dyn Fn(DVec3) -> f64 + Sync),
    spec: &CaptureSpec,
    overhead_us: f64,
) -> Result<(), crate::capture::WriteCaptureError> {
    if overhead_us == 0.0 {
        return simulate_capture(dir, camera, field, spec).map(|_| ());
    }
    // Render with the true integration times, then declare the nominal ones.
    let actual = CaptureSpec {
        exposures_us: spec.exposures_us.iter().map(|t| t + overhead_us).collect(),
        ..spec.clone()
    };
    let mut written = simulate_capture(dir, camera, field, &actual)?;
    for (entry, &t) in written.exposure.iter_mut().zip(&spec.exposures_us) {
        entry.exposure_us = t;
    }
    written.write(&dir.join("capture.toml"))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// No capture is on an edge, the sun switches within minutes, and the day's record is not
    /// periodic: shifted by any lag from 1 to 30 min it differs from itself (a periodic wave
    /// would match itself at its period and alias a logger's clock offset).
    #[test]
    fn passing_clouds_are_aperiodic_and_no_capture_is_on_an_edge() {
        let captures_s: Vec<f64> = (0..20).map(|k| 30_000.0 + 1800.0 * k as f64).collect();
        for seed in 0..100u64 {
            let c = PassingClouds::new(seed, &captures_s);
            let half = PassingClouds::EDGE_S / 2.0;
            for &t in &captures_s {
                let at = c.at(t);
                assert!(at == 0.0 || at == 1.0, "seed {seed}: {at} at {t}");
                assert_eq!(c.at(t - half), at, "seed {seed}");
                assert_eq!(c.at(t + half), at, "seed {seed}");
            }
            let times: Vec<f64> = (30_000..60_000).step_by(10).map(|t| t as f64).collect();
            let sunny = times.iter().map(|&t| c.at(t)).sum::<f64>() / times.len() as f64;
            assert!((0.3..=0.7).contains(&sunny), "seed {seed}: sunny {sunny}");
            let states: Vec<f64> = captures_s.iter().map(|&t| c.at(t)).collect();
            assert!(
                states.contains(&0.0) && states.contains(&1.0),
                "seed {seed}"
            );
            for lag_s in (60..=1800).step_by(30) {
                let differs = times
                    .iter()
                    .filter(|&&t| (c.at(t) - c.at(t + lag_s as f64)).abs() > 0.5)
                    .count();
                assert!(
                    differs as f64 > 0.2 * times.len() as f64,
                    "seed {seed}: lag {lag_s} s differs at {differs} of {} times",
                    times.len()
                );
            }
        }
    }

    /// Hourly captures: a reading every 30 s to ±29.5 min, so consecutive windows never
    /// overlap and an offset of up to ±29.5 min stays inside each capture's record.
    #[test]
    fn continuous_logger_windows_do_not_overlap() {
        let log = LoggerSchedule::continuous(3600.0);
        assert_eq!(log.cadence_s, 30.0);
        assert_eq!(log.half_window_s, 1770.0);
        assert!(2.0 * log.half_window_s < 3600.0);
        log.validate().unwrap();
        assert_eq!(
            LoggerSchedule::continuous(7200.0).half_window_s,
            LoggerSchedule::MAX_HALF_WINDOW_S
        );
        assert_eq!(LoggerSchedule::continuous(20.0).half_window_s, 0.0);
        let bad = LoggerSchedule {
            cadence_s: 0.0,
            ..log
        };
        assert!(bad.validate().unwrap_err().contains("cadence"));
        let wide = LoggerSchedule {
            half_window_s: 4000.0,
            ..log
        };
        assert!(wide.validate().unwrap_err().contains("half window"));
    }

    #[test]
    fn truth_source_parses() {
        assert_eq!("engine".parse::<TruthSource>(), Ok(TruthSource::Engine));
        assert_eq!("radiance".parse::<TruthSource>(), Ok(TruthSource::RADIANCE));
        assert_eq!(
            "radiance:5".parse::<TruthSource>(),
            Ok(TruthSource::Radiance { ambient_bounces: 5 })
        );
        assert!("radiance:0".parse::<TruthSource>().is_err());
        assert!("rtrace".parse::<TruthSource>().is_err());
    }
}
