//! Where captures come from: the [`CaptureSource`] trait, and [`SimSource`], the simulated
//! camera under a simulated sky (`--sim`).
//!
//! A source hands back the raw exposures of one HDR capture in the form `hdr/` consumes: the
//! campaign `capture.toml` content (time, Bayer phase, readout window, and per exposure its
//! integration time and gain) and one [`RawFrame`] per exposure, with the DMA descriptor flags
//! of each frame. The fabric source (`FabricSource<B: RegisterBus, M: DmaMemory>`, with the
//! whole core of issue 10) implements the same trait over `skylux_hps::fpga`.

use crate::config::{FaultKind, FaultRule, SimConfig, SimSky};
use crate::interior_truth::InteriorTruth;
use chrono::{DateTime, Datelike, FixedOffset, Utc};
use glam::DVec3;
use skylux_hps::camera::{CameraModel, DeviceConfig};
use skylux_hps::campaign::{CaptureConfig, RawFrame};
use skylux_hps::hdr::Exposure;
use skylux_hps::sky::perez::{PerezConditions, PerezInput, PerezSky};
use skylux_hps::sun::{solar_position, Site};

/// One HDR capture as it left the sensor and the DMA.
#[derive(Clone, Debug)]
pub struct CaptureSet {
    /// Start of the exposure sequence.
    pub time: DateTime<FixedOffset>,
    /// What `capture.toml` would hold (its `file` names are where the frames go when the
    /// capture is kept).
    pub config: CaptureConfig,
    /// One frame per `config.exposure` entry, in the same order; none when the fabric made
    /// the map (`fabric_map`).
    pub frames: Vec<RawFrame>,
    /// The fabric's HDR map of the exposures (`[fabric] hdr = "fabric"`), instead of frames.
    pub fabric_map: Option<FabricMapCapture>,
    /// Per frame, the names of the DMA descriptor flags that were set (empty: a good frame).
    pub frame_flags: Vec<Vec<String>>,
    /// In simulation, the world's own outdoor global horizontal illuminance, lux (what the
    /// measurement is checked against); `None` from real hardware.
    pub truth_outdoor_horizontal_lux: Option<f64>,
    /// In simulation, the world's own illuminance per room sensor, lux
    /// (`interior_truth::InteriorTruth`); `None` from real hardware or when not traced.
    pub truth_interior_lux: Option<Vec<f64>>,
}

/// A capture the fabric merged: its map words, the thresholds it used, and the raw frame size
/// the map's groups come from. `config.exposure` lists the set's frames in map order (long to
/// short).
#[derive(Clone, Debug)]
pub struct FabricMapCapture {
    pub map: skylux_hps::hdr::FabricMap,
    pub hdr: skylux_regmap::hdr_values::HdrConfig,
    pub raw_width: usize,
    pub raw_height: usize,
    /// The sun accumulators over the set's shortest exposure (issue 22 item 2), or why they
    /// have nothing to believe (not armed, a fault on `sun.*`): the cycle then scans the map.
    pub sun: Result<FabricSunReading, SunFallback>,
}

/// What the sun accumulators measured, with how they were set up.
#[derive(Clone, Debug, PartialEq)]
pub struct FabricSunReading {
    pub search: skylux_hps::sun::FabricSunSearch,
    /// The frame they summed: the shortest exposure as the sensor ran it.
    pub exposure: skylux_hps::sun::SunExposure,
    pub config: skylux_regmap::sun_values::SunConfig,
    /// Checked against `config` (`sun::check_sums`).
    pub sums: skylux_regmap::sun_values::SunSums,
}

/// Why the sun of a map-mode capture was not taken from the accumulators: a short stable tag
/// (for the record and the metrics) and the details.
#[derive(Clone, Debug, PartialEq)]
pub struct SunFallback {
    /// `not_armed`, `bus`, `unsettled`, `stale`, `inconsistent` (the source's); `none`,
    /// `saturated`, `undersampled`, `scattered`, `not_measurable` (the cycle's, from the
    /// sums).
    pub tag: &'static str,
    pub detail: String,
}

impl SunFallback {
    pub fn new(tag: &'static str, detail: impl Into<String>) -> Self {
        Self {
            tag,
            detail: detail.into(),
        }
    }
}

impl std::fmt::Display for SunFallback {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.tag, self.detail)
    }
}

impl CaptureSet {
    /// The exposures as the HDR merge takes them.
    pub fn exposures(&self) -> Vec<Exposure<'_>> {
        self.frames
            .iter()
            .zip(&self.config.exposure)
            .map(|(frame, e)| Exposure {
                frame,
                exposure_s: e.exposure_us * 1e-6,
                gain: e.gain,
            })
            .collect()
    }
}

/// Why a capture failed. Every variant says what the hardware did, so the log line is
/// enough to act on.
#[derive(Clone, Debug, thiserror::Error, PartialEq)]
pub enum SourceError {
    #[error("sensor absent: {detail}")]
    SensorAbsent { detail: String },
    #[error("I2C NACK at sensor register {register:#04x}: {detail}")]
    I2cNack { register: u8, detail: String },
    /// SDA or SCL held low: no transaction completes, whoever answers (a device or a short on
    /// the bus, or a sensor hung mid-transfer; hardware-facts.md §1.7).
    #[error("I2C bus stuck at sensor register {register:#04x}: {detail}")]
    I2cBusStuck { register: u8, detail: String },
    #[error("DMA timeout: {frames_received} of {frames_expected} frames after {waited_ms} ms")]
    DmaTimeout {
        frames_received: usize,
        frames_expected: usize,
        waited_ms: u64,
    },
    /// The DMA's sticky `dma.status.BUS_TIMEOUT`: the port stalled one burst beyond the
    /// watchdog, so the frames of the capture cannot be trusted whatever their descriptors
    /// say. Its own kind because its remedy is on the board (the f2sdram port's reset, the
    /// SDRAM controller), not in the sensor or the frame.
    #[error(
        "DMA bus timeout: the FPGA-to-SDRAM port held waitrequest longer than dma.bus_timeout \
         ({timeout_cycles} system clocks); a port that never accepts a burst is held in reset: \
         fpgaportrst at 0xFFC25080 must be set from U-Boot before the FPGA touches SDRAM \
         (hardware-facts.md §3.3)"
    )]
    DmaBusTimeout { timeout_cycles: u32 },
    #[error("capture source: {0}")]
    Other(String),
}

impl SourceError {
    /// A short stable name for logs and metrics.
    pub fn kind(&self) -> &'static str {
        match self {
            Self::SensorAbsent { .. } => "sensor_absent",
            Self::I2cNack { .. } => "i2c_nack",
            Self::I2cBusStuck { .. } => "i2c_bus_stuck",
            Self::DmaTimeout { .. } => "dma_timeout",
            Self::DmaBusTimeout { .. } => "dma_bus_timeout",
            Self::Other(_) => "source",
        }
    }
}

/// Something that takes HDR captures.
pub trait CaptureSource {
    /// Takes one capture starting at `at` (the simulated clock in `--sim`, the wall clock on
    /// the board).
    fn capture(&mut self, at: DateTime<FixedOffset>) -> Result<CaptureSet, SourceError>;
    /// Takes one capture of raw frames (kept in campaign format, merged on the HPS), whatever
    /// the source's default: the fabric in map mode makes a map otherwise. Sources that only
    /// make raw frames take their usual capture.
    fn capture_raw(&mut self, at: DateTime<FixedOffset>) -> Result<CaptureSet, SourceError> {
        self.capture(at)
    }
    /// Whether [`CaptureSource::capture`] makes maps (the fabric in map mode), so that raw
    /// captures are worth scheduling.
    fn makes_maps(&self) -> bool {
        false
    }
    /// A name for logs (`sim`, `fabric`).
    fn name(&self) -> &'static str;
}

/// The simulated world: SPA sun, an ASHRAE clear-day or overcast Perez sky, a grey ground,
/// imaged through the declared camera and the MT9P031 noise model
/// (`skylux_sim::capture::simulate_capture`) at reduced resolution, with injected faults.
pub struct SimSource {
    camera: CameraModel,
    site: Site,
    sim: SimConfig,
    exposures_us: Vec<f64>,
    /// Analog gain per exposure.
    gains: Vec<f64>,
    attempts: u64,
    interior: Option<InteriorTruth>,
}

/// Ground reflectance of the simulated world (and the model's default: `ModelState`).
pub(crate) const GROUND_REFLECTANCE: f64 = 0.2;
/// Below this solar altitude the simulated sky is dark (the campaign simulator takes no
/// capture below 3°, sim/src/campaign.rs).
const MIN_SUN_ALTITUDE_DEG: f64 = 3.0;

impl SimSource {
    /// The frames are made in memory, as a camera hands them over: the simulated camera
    /// needs no disk, so a full output disk fails the cycle's writes, not the capture.
    pub fn new(
        device: DeviceConfig,
        site: Site,
        sim: SimConfig,
        exposures_us: Vec<f64>,
        gains: Vec<f64>,
    ) -> Self {
        Self {
            camera: CameraModel::new(device),
            site,
            sim,
            exposures_us,
            gains,
            attempts: 0,
            interior: None,
        }
    }

    /// Also traces the room under the world each capture (`CaptureSet::truth_interior_lux`),
    /// when `interior` is given.
    pub fn with_interior(mut self, interior: Option<InteriorTruth>) -> Self {
        self.interior = interior;
        self
    }

    /// The fault scheduled for the attempt about to be made (1-based), if any.
    pub fn fault_for(faults: &[FaultRule], attempt: u64) -> Option<FaultKind> {
        faults
            .iter()
            .find(|f| attempt >= f.attempt && attempt - f.attempt < f.count)
            .map(|f| f.kind)
    }

    /// Attempts made so far.
    pub fn attempts(&self) -> u64 {
        self.attempts
    }

    /// The luminance of the simulated world in every direction at `at`, cd/m².
    fn world(&self, at: DateTime<FixedOffset>) -> Result<impl Fn(DVec3) -> f64 + Sync, String> {
        sim_world(&self.site, self.sim.sky, at)
    }
}

/// The world's solar disk, when it shows one: a source smaller than the groups of a coarse
/// readout, which the renderer must not let fall between their centres.
pub(crate) fn sim_small_sources(
    site: &Site,
    sky_kind: SimSky,
    at: DateTime<FixedOffset>,
) -> Result<Vec<skylux_sim::sensor::SmallSource>, String> {
    let (sky, direction) = sim_sky(site, sky_kind, at)?;
    Ok(match sky {
        Some((perez, true)) => vec![skylux_sim::sensor::SmallSource {
            direction,
            // Ω = 2π (1 − cos r).
            radius_rad: (1.0 - perez.sun_solid_angle_sr() / std::f64::consts::TAU).acos(),
        }],
        _ => vec![],
    })
}

/// The simulated world's sky at `at`: the Perez sky and whether it has a sun (None with the
/// sun under [`MIN_SUN_ALTITUDE_DEG`]), and the sun's direction.
pub(crate) fn sim_sky(
    site: &Site,
    sky_kind: SimSky,
    at: DateTime<FixedOffset>,
) -> Result<(Option<(PerezSky, bool)>, DVec3), String> {
    let sun = solar_position(at.with_timezone(&Utc), site, None).map_err(|e| e.to_string())?;
    let sun_dir = sun.direction();
    let altitude = sun.altitude_deg();
    if altitude < MIN_SUN_ALTITUDE_DEG {
        return Ok((None, sun_dir));
    }
    let (dni_clear, dhi_clear) = ashrae_clear_day_w_m2(altitude.to_radians());
    let (dni, dhi) = match sky_kind {
        SimSky::Clear => (dni_clear, dhi_clear),
        // Overcast as in the campaign simulator: no beam, 35 % of the clear global.
        SimSky::Overcast => (
            0.0,
            0.35 * (dni_clear * altitude.to_radians().sin() + dhi_clear),
        ),
    };
    let perez = PerezSky::new(
        PerezInput::DirectNormalDiffuse {
            direct_normal_w_m2: dni,
            diffuse_horizontal_w_m2: dhi,
        },
        &PerezConditions {
            day_of_year: at.ordinal() as u16,
            ground_reflectance: GROUND_REFLECTANCE,
            ..PerezConditions::gendaylit_ang(sun_dir)
        },
    )
    .map_err(|e| e.to_string())?;
    Ok((Some((perez, dni > 0.0)), sun_dir))
}

/// The simulated world's own outdoor global horizontal illuminance at `at`, lux: its sky as
/// rendered ([`PerezSky::luminance_cd_m2`] integrated with cos θ on a 0.5° grid) plus the beam
/// on the horizontal: the truth the daemon's measurement is checked against. Not the
/// diffuse illuminance the Perez sky is normalised to: gendaylit normalises with a 145-point
/// sum, whose error (2-3 % of the diffuse light, most with a low sun) a measurement that
/// sums the same 145 patches would share.
pub fn sim_outdoor_horizontal_lux(
    site: &Site,
    sky_kind: SimSky,
    at: DateTime<FixedOffset>,
) -> Result<f64, String> {
    let (sky, sun_dir) = sim_sky(site, sky_kind, at)?;
    Ok(match &sky {
        Some((p, with_sun)) => {
            p.sky_horizontal_illuminance_lux(Default::default())
                + if *with_sun {
                    p.direct_normal_illuminance_lux() * sun_dir.z.max(0.0)
                } else {
                    0.0
                }
        }
        None => 0.0,
    })
}

/// The luminance of the simulated world (SPA sun, ASHRAE clear-day or overcast Perez sky, a
/// grey ground) in every direction at `at`, cd/m²: what [`SimSource`] renders, and what the
/// simulated MT9P031 of the fabric source images.
pub fn sim_world(
    site: &Site,
    sky_kind: SimSky,
    at: DateTime<FixedOffset>,
) -> Result<impl Fn(DVec3) -> f64 + Sync + Send + 'static, String> {
    let horizontal = sim_outdoor_horizontal_lux(site, sky_kind, at)?;
    let (sky, sun_dir) = sim_sky(site, sky_kind, at)?;
    let (ground, sun_cd_m2, sun_cos_half) = match &sky {
        Some((p, with_sun)) => (
            GROUND_REFLECTANCE * horizontal / std::f64::consts::PI,
            if *with_sun {
                p.sun_luminance_cd_m2()
            } else {
                0.0
            },
            1.0 - p.sun_solid_angle_sr() / std::f64::consts::TAU,
        ),
        None => (0.0, 0.0, 1.0),
    };
    Ok(move |d: DVec3| {
        let Some((perez, _)) = &sky else { return 0.0 };
        if d.z < 0.0 {
            ground
        } else if sun_cd_m2 > 0.0 && d.dot(sun_dir) >= sun_cos_half {
            sun_cd_m2
        } else {
            perez.luminance_cd_m2(d)
        }
    })
}

/// ASHRAE clear-day model for May (ASHRAE Handbook of Fundamentals 1985, ch. 27, table 1,
/// 21 May: A = 1088 W/m², B = 0.205, C = 0.134): DNI = A exp(−B / sin h), DHI = C · DNI. The
/// campaign simulator (sim/src/campaign.rs) uses the same model.
fn ashrae_clear_day_w_m2(altitude_rad: f64) -> (f64, f64) {
    let s = altitude_rad.sin().max(0.02);
    let dni = 1088.0 * (-0.205 / s).exp();
    (dni, 0.134 * dni)
}

impl CaptureSource for SimSource {
    fn name(&self) -> &'static str {
        "sim"
    }

    fn capture(&mut self, at: DateTime<FixedOffset>) -> Result<CaptureSet, SourceError> {
        self.attempts += 1;
        let fault = Self::fault_for(&self.sim.faults, self.attempts);
        match fault {
            // MT9P031 register 0x00 is Chip_Version: the first read of bring-up.
            Some(FaultKind::SensorAbsent) => {
                return Err(SourceError::SensorAbsent {
                    detail: "Chip_Version (0x00) read not acknowledged: no device at the \
                             sensor's I2C address (injected)"
                        .into(),
                })
            }
            // Register 0x09 is Shutter_Width_Lower, written for every exposure.
            Some(FaultKind::I2cNack) => {
                return Err(SourceError::I2cNack {
                    register: 0x09,
                    detail: "write of Shutter_Width_Lower not acknowledged (injected)".into(),
                })
            }
            Some(FaultKind::DmaTimeout) => {
                return Err(SourceError::DmaTimeout {
                    frames_received: 0,
                    frames_expected: self.exposures_us.len(),
                    waited_ms: 2000,
                })
            }
            _ => {}
        }
        let field = self.world(at).map_err(SourceError::Other)?;
        let skip = self.sim.skip;
        let spec = skylux_sim::capture::CaptureSpec {
            time: at.to_rfc3339(),
            readout: self.sim.readout(),
            raw_width: (2592 / skip as usize) & !1,
            raw_height: (1944 / skip as usize) & !1,
            exposures_us: self.exposures_us.clone(),
            gains: self.gains.clone(),
            // The same time gives the same frames.
            seed: self.sim.seed ^ (at.timestamp() as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15),
            // The pixels the readout reads: binning keeps their light, skipping loses the rest.
            footprint: skylux_sim::sensor::Footprint::AsRead,
            small_sources: sim_small_sources(&self.site, self.sim.sky, at)
                .map_err(SourceError::Other)?,
        };
        let (config, frames) = skylux_sim::capture::simulate_frames(&self.camera, &field, &spec);
        let mut frame_flags = vec![Vec::new(); frames.len()];
        if fault == Some(FaultKind::FlaggedFrame) {
            // The middle exposure's descriptor reports a capture FIFO overflow.
            let k = frames.len() / 2;
            frame_flags[k].push("FIFO_OVERFLOW".to_string());
        }
        Ok(CaptureSet {
            fabric_map: None,
            time: at,
            config,
            frames,
            frame_flags,
            truth_outdoor_horizontal_lux: Some(
                sim_outdoor_horizontal_lux(&self.site, self.sim.sky, at)
                    .map_err(SourceError::Other)?,
            ),
            truth_interior_lux: match &mut self.interior {
                Some(room) => Some(
                    room.illuminance_lux(&self.site, self.sim.sky, at)
                        .map_err(SourceError::Other)?,
                ),
                None => None,
            },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fault_schedule() {
        let faults = vec![
            FaultRule {
                attempt: 2,
                count: 2,
                kind: FaultKind::I2cNack,
            },
            FaultRule {
                attempt: 5,
                count: 1,
                kind: FaultKind::DmaTimeout,
            },
        ];
        let got: Vec<_> = (1..=6).map(|a| SimSource::fault_for(&faults, a)).collect();
        assert_eq!(
            got,
            vec![
                None,
                Some(FaultKind::I2cNack),
                Some(FaultKind::I2cNack),
                None,
                Some(FaultKind::DmaTimeout),
                None
            ]
        );
    }

    #[test]
    fn sim_source_renders_and_injects() {
        let sim = SimConfig {
            skip: 32,
            faults: vec![
                FaultRule {
                    attempt: 1,
                    count: 1,
                    kind: FaultKind::SensorAbsent,
                },
                FaultRule {
                    attempt: 3,
                    count: 1,
                    kind: FaultKind::FlaggedFrame,
                },
            ],
            ..SimConfig::default()
        };
        let mut s = SimSource::new(
            DeviceConfig::default(),
            Site {
                latitude_deg: 46.52,
                longitude_deg: 6.57,
                elevation_m: 400.0,
            },
            sim,
            vec![10.0, 1000.0, 100_000.0],
            vec![1.0; 3],
        );
        let t = DateTime::parse_from_rfc3339("2017-05-08T12:00:00+02:00").unwrap();
        let e = s.capture(t).unwrap_err();
        assert_eq!(e.kind(), "sensor_absent");
        let a = s.capture(t).unwrap();
        assert_eq!(a.frames.len(), 3);
        assert_eq!((a.frames[0].width, a.frames[0].height), (80, 60));
        assert!(a.frame_flags.iter().all(Vec::is_empty));
        let b = s.capture(t).unwrap();
        assert_eq!(b.frame_flags[1], vec!["FIFO_OVERFLOW".to_string()]);
        // Same time, same frames.
        assert_eq!(a.frames, b.frames);
        // Brighter at noon than in the dark.
        let night = DateTime::parse_from_rfc3339("2017-05-08T01:00:00+02:00").unwrap();
        let n = s.capture(night).unwrap();
        let sum = |f: &RawFrame| f.samples_dn.iter().map(|&v| v as u64).sum::<u64>();
        assert!(sum(&n.frames[2]) < sum(&a.frames[2]));
    }
}
