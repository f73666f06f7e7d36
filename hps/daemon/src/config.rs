//! `skyluxd.toml`: what the daemon measures, where it writes, what it serves and what it may
//! map. Every error names the file, the line (when the text has one) and the field.
//!
//! Relative paths are resolved against the directory of the configuration file, so a config
//! can sit beside its room and camera files.

use chrono::FixedOffset;
use serde::Deserialize;
use skylux_regmap::{LW_BRIDGE_PHYS_BASE, LW_BRIDGE_SPAN_BYTES};
use std::net::SocketAddr;
use std::path::{Path, PathBuf};

mod views;
mod window;
pub use views::{GlareConfig, ViewConfig};
pub use window::{StateConfig, WindowConfig};

/// The API address when the config names none: loopback only (the specification: "bound to
/// 127.0.0.1 by default"); port 8740 is a project choice.
pub const DEFAULT_API_ADDRESS: &str = "127.0.0.1:8740";

/// The DMA buffers' physical region: the `reserved-memory` node with `no-map` of
/// `bitstream/linux/skylux-overlay.dts`, 0x38000000 for 128 MiB (the top of the DE1-SoC's
/// 1 GB DDR3). Only memory the kernel does not map may be handed to the fabric: `no-map`
/// keeps Linux from using it, and /dev/mem then maps it non-cached, which the non-coherent
/// FPGA-to-SDRAM port needs (hardware-facts.md §3.2, §3.4).
pub const DMA_RESERVED_BASE: u64 = 0x3800_0000;
/// Size of the reserved DMA region, bytes (see [`DMA_RESERVED_BASE`]).
pub const DMA_RESERVED_SIZE: u64 = 0x0800_0000;
/// Mapping granularity: the ARM Linux page (mmap offsets and lengths are page multiples).
pub const PAGE_BYTES: u64 = 4096;

/// Why a configuration was refused.
#[derive(Debug, thiserror::Error)]
pub enum ConfigError {
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    /// `line` is 0 when the error has no place in the text.
    #[error("{}", describe(path, *line, field, message))]
    Invalid {
        path: PathBuf,
        line: usize,
        field: String,
        message: String,
    },
}

fn describe(path: &Path, line: usize, field: &str, message: &str) -> String {
    let place = if line > 0 {
        format!("{}:{line}", path.display())
    } else {
        path.display().to_string()
    };
    if field.is_empty() {
        format!("{place}: {message}")
    } else {
        format!("{place}: `{field}`: {message}")
    }
}

/// The whole configuration, paths resolved.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Config {
    pub site: SiteConfig,
    pub camera: CameraConfig,
    pub room: RoomConfig,
    pub capture: ScheduleConfig,
    pub output: OutputConfig,
    #[serde(default)]
    pub api: ApiConfig,
    #[serde(default)]
    pub retry: RetryConfig,
    #[serde(default)]
    pub hardware: HardwareConfig,
    #[serde(default)]
    pub sim: SimConfig,
    #[serde(default)]
    pub fabric: FabricConfig,
    /// Occupants' eyes whose glare each cycle reports (`[[views]]`).
    #[serde(default)]
    pub views: Vec<ViewConfig>,
    #[serde(default)]
    pub glare: GlareConfig,
    /// The file this was read from (set by [`Config::parse`]).
    #[serde(skip)]
    pub path: PathBuf,
}

/// `[site]`, as campaign.md's `campaign.toml` names it, plus the local clock's UTC offset
/// written into every time stamp (campaign.md: RFC 3339 with an explicit offset).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SiteConfig {
    pub latitude_deg: f64,
    pub longitude_deg: f64,
    pub elevation_m: f64,
    /// `+02:00`, `-05:00` or `Z`.
    #[serde(default = "default_utc_offset")]
    pub utc_offset: String,
}

fn default_utc_offset() -> String {
    "+00:00".into()
}

/// `[camera]`: the calibration and the exposure ladder of one HDR capture.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CameraConfig {
    /// `device.toml` (campaign.md).
    pub device: PathBuf,
    /// Integration times, µs, in the order they are taken.
    pub exposures_us: Vec<f64>,
    /// Analog gain: one for every exposure, or one per exposure (a high gain on the longest
    /// lifts a dim sky above the floor without saturating the sun in the shortest).
    #[serde(default)]
    pub gain: Gain,
}

/// `camera.gain`: a number, or an array with one gain per exposure.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(untagged)]
pub enum Gain {
    All(f64),
    PerExposure(Vec<f64>),
}

impl Default for Gain {
    fn default() -> Self {
        Self::All(1.0)
    }
}

impl CameraConfig {
    /// The analog gain of every exposure, in capture order.
    pub fn gains(&self) -> Vec<f64> {
        match &self.gain {
            Gain::All(g) => vec![*g; self.exposures_us.len()],
            Gain::PerExposure(g) => g.clone(),
        }
    }
}

/// `[room]`: the RADIANCE scene and sensor points, as `skylux dc` and `skylux loop` take them.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RoomConfig {
    pub scene: Vec<PathBuf>,
    pub sensors: PathBuf,
    /// Reinhart multiplication factor of the daylight-coefficient patches (1: Tregenza 145).
    #[serde(default = "default_mf")]
    pub mf: usize,
    /// Paths per sensor for the daylight coefficients (and, clamped to 64..2048, for the
    /// sun coefficients, as the offline pipeline does).
    #[serde(default = "default_dc_samples")]
    pub dc_samples: u32,
    #[serde(default = "default_bounces")]
    pub ambient_bounces: u32,
    #[serde(default = "one_u64")]
    pub seed: u64,
    /// Also trace the room under the measured sky by full Monte-Carlo every cycle.
    #[serde(default)]
    pub monte_carlo: bool,
    #[serde(default = "default_mc_samples")]
    pub monte_carlo_samples: u32,
    /// Where the daylight-coefficient matrix is cached (default: `<output.dir>/cache`).
    #[serde(default)]
    pub cache_dir: Option<PathBuf>,
    /// A window whose shading states are declared: every cycle reports every state.
    #[serde(default)]
    pub window: Option<WindowConfig>,
}

fn default_mf() -> usize {
    2
}
fn default_dc_samples() -> u32 {
    50_000
}
fn default_bounces() -> u32 {
    skylux_hps::engine::integrator::CONVERGED_AMBIENT_BOUNCES
}
fn one_u64() -> u64 {
    1
}
fn default_mc_samples() -> u32 {
    1024
}

/// `[capture]`: the schedule.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScheduleConfig {
    /// Seconds between the starts of two captures.
    pub period_s: f64,
}

/// `[output]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OutputConfig {
    /// Results (`results.jsonl`, `illuminance.csv`, `latest.json`), `maps/` and `captures/`.
    pub dir: PathBuf,
    /// Most EXR maps kept; the oldest are deleted (0: no maps written).
    #[serde(default = "default_max_maps")]
    pub max_maps: usize,
    /// Most raw capture folders kept in campaign format under `captures/` (0: none).
    #[serde(default)]
    pub max_captures: usize,
}

fn default_max_maps() -> usize {
    48
}

/// `[api]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ApiConfig {
    #[serde(default = "default_api_address")]
    pub address: String,
    /// Needed to bind anything but a loopback address.
    #[serde(default)]
    pub allow_remote: bool,
}

fn default_api_address() -> String {
    DEFAULT_API_ADDRESS.into()
}

impl Default for ApiConfig {
    fn default() -> Self {
        Self {
            address: default_api_address(),
            allow_remote: false,
        }
    }
}

/// `[retry]`: exponential back-off after a failed cycle.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RetryConfig {
    #[serde(default = "default_initial_s")]
    pub initial_s: f64,
    #[serde(default = "default_max_s")]
    pub max_s: f64,
}

fn default_initial_s() -> f64 {
    2.0
}
fn default_max_s() -> f64 {
    300.0
}

impl Default for RetryConfig {
    fn default() -> Self {
        Self {
            initial_s: default_initial_s(),
            max_s: default_max_s(),
        }
    }
}

/// `[hardware]`: the only physical memory the daemon maps, and who it runs as afterwards.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HardwareConfig {
    /// Physical base of the register window: must be the lightweight bridge's.
    #[serde(default = "default_register_base")]
    pub register_base: u64,
    #[serde(default = "default_register_size")]
    pub register_size: u64,
    /// The frame ring's buffer: inside the reserved DMA region.
    #[serde(default = "default_dma_base")]
    pub dma_base: u64,
    #[serde(default = "default_dma_size")]
    pub dma_size: u64,
    /// `/dev/uioN` of the register window (its map 0) and interrupt; `/dev/mem` when absent.
    #[serde(default)]
    pub uio_device: Option<PathBuf>,
    /// `/dev/udmabufN` (the u-dma-buf driver on the reserved region, bitstream/README.md):
    /// the frame buffer mapped cached, each read preceded by an invalidation of its range and
    /// each write followed by a clean (skylux_bus::udmabuf); its buffer must lie inside
    /// `dma_base`/`dma_size`. Absent: `/dev/mem` with `O_SYNC`, uncached.
    #[serde(default)]
    pub dma_device: Option<PathBuf>,
    /// Unprivileged user and group to run as once the windows are mapped.
    #[serde(default = "default_user")]
    pub user: String,
    #[serde(default)]
    pub group: Option<String>,
}

fn default_register_base() -> u64 {
    LW_BRIDGE_PHYS_BASE as u64
}
fn default_register_size() -> u64 {
    LW_BRIDGE_SPAN_BYTES as u64
}
fn default_dma_base() -> u64 {
    DMA_RESERVED_BASE
}
fn default_dma_size() -> u64 {
    DMA_RESERVED_SIZE
}
fn default_user() -> String {
    "skylux".into()
}

impl Default for HardwareConfig {
    fn default() -> Self {
        Self {
            register_base: default_register_base(),
            register_size: default_register_size(),
            dma_base: default_dma_base(),
            dma_size: default_dma_size(),
            uio_device: None,
            dma_device: None,
            user: default_user(),
            group: None,
        }
    }
}

/// `[sim]`: the simulated world behind `--sim`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SimConfig {
    /// Readout skip of the simulated frames: 2592/skip x 1944/skip samples (1: full size).
    /// The MT9P031 skips 1 to 8 (hardware-facts.md §1); up to 64 for small test worlds.
    #[serde(default = "default_skip")]
    pub skip: u32,
    /// Binning, 1, 2 or 4 dividing `skip`; by default the largest that divides it, as the
    /// Linux driver chooses (hardware-facts.md §1, "Binning rule"): a binned sample keeps
    /// the light of the pixels it averages, a skipped one loses what falls between.
    #[serde(default)]
    pub bin: Option<u32>,
    #[serde(default)]
    pub sky: SimSky,
    #[serde(default = "one_u64")]
    pub seed: u64,
    /// Paths per sensor of the world's own interior illuminance, traced each cycle beside
    /// the measurement (`truth_illuminance` in the record); 0: none.
    #[serde(default = "default_interior_truth_samples")]
    pub interior_truth_samples: u32,
    /// Fault injection schedule (the `sim` source only).
    #[serde(default, rename = "fault")]
    pub faults: Vec<FaultRule>,
    /// What `--sim` captures with: `sim` (the rendered sky through the noise model, fast) or
    /// `fabric` (the cycle-accurate fabric core with its MT9P031 and SDRAM models, driven
    /// by the same `FabricSource` as the board, at the `[fabric]` window; slow: keep the
    /// window small and the exposures short).
    #[serde(default)]
    pub source: SimSourceKind,
}

/// `[sim] source`.
#[derive(Copy, Clone, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum SimSourceKind {
    #[default]
    Sim,
    Fabric,
    /// The behavioural fabric model (`skylux_sim::fabric_model`) behind the same
    /// `FabricSource`: fast enough for the `[fabric]` window at full frame, and its
    /// `[[sim.fault]]`s are hardware faults made at their source.
    #[serde(rename = "fabric-model")]
    FabricModel,
}

/// `[fabric]`: the sensor window the fabric source reads, in the sensor's register units
/// (array pixels: the active array starts at column 16, row 54), and the shield.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FabricConfig {
    #[serde(default = "default_fabric_row_start")]
    pub row_start: u32,
    #[serde(default = "default_fabric_col_start")]
    pub col_start: u32,
    /// Array columns and rows of the window (even); the output is `2 ceil(size / 2 skip)`.
    #[serde(default = "default_fabric_width")]
    pub width: u32,
    #[serde(default = "default_fabric_height")]
    pub height: u32,
    /// Row and column skip, 1 to 8 (hardware-facts.md §1.4).
    #[serde(default = "one_u32")]
    pub skip: u32,
    /// Row and column binning, 1, 2 or 4 dividing `skip` (docs/readout.md): each sample the
    /// mean of bin x bin pixels. 1 (the sensor's reset value) unless set.
    #[serde(default = "one_u32")]
    pub bin: u32,
    /// Stepper steps from closed to open.
    #[serde(default = "default_shield_steps")]
    pub shield_steps: u32,
    /// Wait for an opening's frames beyond twice its light time, seconds.
    #[serde(default = "default_frame_timeout_s")]
    pub frame_timeout_s: f64,
    /// Where the HDR map is made: `fabric` (the default: the fabric writes one map per
    /// capture from grouped words, the HPS reads it instead of five raw frames) or `hps`
    /// (every capture raw, the noise-optimal merge). Issue 22 items 1 and 3,
    /// docs/hdr-fabric.md.
    #[serde(default)]
    pub hdr: HdrWhere,
    /// With `hdr = "fabric"`: take a raw capture (merged on the HPS, kept in campaign format
    /// under `[output] max_captures`) when this many seconds of capture time have passed
    /// since the last raw one, for calibration and audits; the first comes one period after
    /// start. Absent: raw captures only on request (SIGUSR1). With `hdr = "hps"` every
    /// capture is raw and this is not used.
    #[serde(default)]
    pub raw_every_s: Option<f64>,
}

/// `[fabric] hdr`: where the HDR map is made.
#[derive(Copy, Clone, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum HdrWhere {
    Hps,
    #[default]
    Fabric,
}

fn default_fabric_row_start() -> u32 {
    54
}
fn default_fabric_col_start() -> u32 {
    16
}
fn default_fabric_width() -> u32 {
    2592
}
fn default_fabric_height() -> u32 {
    1944
}
fn one_u32() -> u32 {
    1
}
fn default_shield_steps() -> u32 {
    3
}
fn default_frame_timeout_s() -> f64 {
    2.0
}

impl Default for FabricConfig {
    fn default() -> Self {
        Self {
            row_start: default_fabric_row_start(),
            col_start: default_fabric_col_start(),
            width: default_fabric_width(),
            height: default_fabric_height(),
            skip: 1,
            bin: 1,
            shield_steps: default_shield_steps(),
            frame_timeout_s: default_frame_timeout_s(),
            hdr: HdrWhere::default(),
            raw_every_s: None,
        }
    }
}

fn default_skip() -> u32 {
    4
}

fn default_interior_truth_samples() -> u32 {
    1024
}

impl Default for SimConfig {
    fn default() -> Self {
        Self {
            skip: default_skip(),
            bin: None,
            sky: SimSky::Clear,
            seed: 1,
            interior_truth_samples: default_interior_truth_samples(),
            faults: Vec::new(),
            source: SimSourceKind::Sim,
        }
    }
}

/// The simulated sky.
#[derive(Copy, Clone, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum SimSky {
    #[default]
    Clear,
    Overcast,
}

/// `[[sim.fault]]`: make capture attempts `attempt`..`attempt + count - 1` (1-based) fail.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct FaultRule {
    pub attempt: u64,
    #[serde(default = "one_u64")]
    pub count: u64,
    pub kind: FaultKind,
}

/// What an injected fault does.
#[derive(Copy, Clone, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum FaultKind {
    /// The sensor does not answer at all (Chip_Version read NACKed).
    SensorAbsent,
    /// One configuration write is not acknowledged.
    I2cNack,
    /// The frames never arrive.
    DmaTimeout,
    /// A frame arrives with a descriptor flag (FIFO overflow).
    FlaggedFrame,
    /// The output disk is full when the results are written (ENOSPC).
    DiskFull,
    /// The simulated clock steps back [`CLOCK_BACK_S`] before the attempt (a host fault:
    /// an RTC reset or a bad time server).
    ClockBack,
    // Hardware faults of the fabric model only (`[sim] source = "fabric-model"`), made where
    // they happen (`skylux_sim::fabric_model::HardwareFault`).
    /// A device holds SDA low: the I2C master finds the bus stuck.
    I2cBusStuck,
    /// PIXCLK stops in the middle of the first frame.
    PixclkStopped,
    /// One line of the first frame is two pixels short, or long.
    LineShort,
    LineLong,
    /// The first frame has one line fewer, or more, than the window.
    FrameShort,
    FrameLong,
    /// The f2sdram port stalls during the first frame until the FIFOs overflow.
    FifoOverflow,
    /// One payload word of the first frame is corrupted on the port (checksum mismatch).
    BadChecksum,
    /// The first two frames land in each other's ring slots.
    OutOfOrder,
    /// The f2sdram port holds waitrequest during the first frame longer than the driver's
    /// `dma.bus_timeout`: the DMA's sticky `BUS_TIMEOUT`.
    DmaBusTimeout,
    /// The sun accumulators' result registers read all ones (map mode: the cycle must not
    /// believe them, and scans the map for the sun).
    SunGarbage,
    /// The sun accumulators do not count the capture's frames: their sums are the last
    /// capture's (map mode: caught by `sun.frames`, the map is scanned instead).
    SunStale,
}

/// How far a `clock_back` fault steps the simulated clock back, seconds.
pub const CLOCK_BACK_S: i64 = 7200;

impl FaultKind {
    pub fn name(self) -> &'static str {
        match self {
            Self::SensorAbsent => "sensor_absent",
            Self::I2cNack => "i2c_nack",
            Self::DmaTimeout => "dma_timeout",
            Self::FlaggedFrame => "flagged_frame",
            Self::DiskFull => "disk_full",
            Self::ClockBack => "clock_back",
            Self::I2cBusStuck => "i2c_bus_stuck",
            Self::PixclkStopped => "pixclk_stopped",
            Self::LineShort => "line_short",
            Self::LineLong => "line_long",
            Self::FrameShort => "frame_short",
            Self::FrameLong => "frame_long",
            Self::FifoOverflow => "fifo_overflow",
            Self::BadChecksum => "bad_checksum",
            Self::OutOfOrder => "out_of_order",
            Self::DmaBusTimeout => "dma_bus_timeout",
            Self::SunGarbage => "sun_garbage",
            Self::SunStale => "sun_stale",
        }
    }

    /// Faults only the fabric model can make (at their source in the hardware).
    pub fn hardware_only(self) -> bool {
        !matches!(
            self,
            Self::SensorAbsent
                | Self::I2cNack
                | Self::DmaTimeout
                | Self::FlaggedFrame
                | Self::DiskFull
                | Self::ClockBack
        )
    }
}

/// Command-line overrides applied after parsing and before validation.
#[derive(Clone, Debug, Default)]
pub struct Overrides {
    pub output_dir: Option<PathBuf>,
    pub api_address: Option<String>,
}

impl Config {
    /// Reads, resolves and validates `path`.
    pub fn load(path: &Path, overrides: &Overrides) -> Result<Self, ConfigError> {
        let text = std::fs::read_to_string(path).map_err(|source| ConfigError::Io {
            path: path.into(),
            source,
        })?;
        Self::parse(&text, path, overrides)
    }

    /// Parses, resolves and validates `text`; `path` names the file and anchors relative
    /// paths. Never panics, whatever the text.
    pub fn parse(text: &str, path: &Path, overrides: &Overrides) -> Result<Self, ConfigError> {
        let mut config: Config = toml::from_str(text).map_err(|e: toml::de::Error| {
            let line = e
                .span()
                .map(|s| text[..s.start.min(text.len())].matches('\n').count() + 1)
                .unwrap_or(0);
            ConfigError::Invalid {
                path: path.into(),
                line,
                field: String::new(),
                message: e.message().trim().to_string(),
            }
        })?;
        config.path = path.to_path_buf();
        if let Some(dir) = &overrides.output_dir {
            config.output.dir = dir.clone();
        }
        if let Some(a) = &overrides.api_address {
            config.api.address = a.clone();
        }
        let base = path.parent().unwrap_or(Path::new("")).to_path_buf();
        let resolve = |p: &mut PathBuf| {
            if p.is_relative() {
                *p = base.join(&*p);
            }
        };
        resolve(&mut config.camera.device);
        config.room.scene.iter_mut().for_each(resolve);
        resolve(&mut config.room.sensors);
        if overrides.output_dir.is_none() {
            resolve(&mut config.output.dir);
        }
        if let Some(c) = config.room.cache_dir.as_mut() {
            resolve(c);
        }
        if let Some(w) = config.room.window.as_mut() {
            w.resolve(&resolve);
        }
        config.validate(text)?;
        Ok(config)
    }

    /// The local clock's offset.
    pub fn utc_offset(&self) -> FixedOffset {
        parse_offset(&self.site.utc_offset).unwrap_or_else(|| FixedOffset::east_opt(0).expect("0"))
    }

    /// The API address (validated).
    pub fn api_address(&self) -> SocketAddr {
        self.api
            .address
            .parse()
            .unwrap_or_else(|_| SocketAddr::from(([127, 0, 0, 1], 8740)))
    }

    /// Where the daylight-coefficient cache lives.
    pub fn cache_dir(&self) -> PathBuf {
        self.room
            .cache_dir
            .clone()
            .unwrap_or_else(|| self.output.dir.join("cache"))
    }

    /// Each section checks itself; the first field refused is reported with its section, key
    /// and line.
    fn validate(&self, text: &str) -> Result<(), ConfigError> {
        let in_section = |section: &'static str| {
            move |e: FieldError| ConfigError::Invalid {
                path: self.path.clone(),
                line: line_of(text, section, e.key),
                field: format!("{section}.{}", e.key),
                message: e.message,
            }
        };
        self.site.check().map_err(in_section("site"))?;
        self.camera.check().map_err(in_section("camera"))?;
        self.room.check().map_err(in_section("room"))?;
        if let Some(w) = &self.room.window {
            w.check().map_err(in_section("room.window"))?;
        }
        self.capture.check().map_err(in_section("capture"))?;
        self.output.check().map_err(in_section("output"))?;
        self.api.check().map_err(in_section("api"))?;
        self.retry.check().map_err(in_section("retry"))?;
        self.hardware.check().map_err(in_section("hardware"))?;
        self.sim.check().map_err(in_section("sim"))?;
        self.fabric.check().map_err(in_section("fabric"))?;
        self.sim.check_fault_source().map_err(in_section("sim"))?;
        for (i, f) in self.sim.faults.iter().enumerate() {
            f.check()
                .map_err(|e| self.table_error(text, "sim.fault", i, e))?;
        }
        self.glare.check().map_err(in_section("glare"))?;
        views::check_views(&self.views).map_err(|(i, e)| self.table_error(text, "views", i, e))?;
        Ok(())
    }

    /// An error in the `index`-th (0-based) `[[section]]` table, named `section[index].key`.
    fn table_error(&self, text: &str, section: &str, index: usize, e: FieldError) -> ConfigError {
        ConfigError::Invalid {
            path: self.path.clone(),
            line: line_in_table(text, section, index, e.key),
            field: format!("{section}[{index}].{}", e.key),
            message: e.message,
        }
    }
}

/// A field a section refuses, and why.
#[derive(Clone, Debug, PartialEq)]
pub struct FieldError {
    pub key: &'static str,
    pub message: String,
}

fn refuse(key: &'static str, message: impl Into<String>) -> Result<(), FieldError> {
    Err(FieldError {
        key,
        message: message.into(),
    })
}

impl SiteConfig {
    fn check(&self) -> Result<(), FieldError> {
        if !(self.latitude_deg.is_finite() && (-90.0..=90.0).contains(&self.latitude_deg)) {
            return refuse(
                "latitude_deg",
                format!("{} is outside [-90, 90]", self.latitude_deg),
            );
        }
        if !(self.longitude_deg.is_finite() && (-180.0..=180.0).contains(&self.longitude_deg)) {
            return refuse(
                "longitude_deg",
                format!(
                    "{} is outside [-180, 180] (east positive)",
                    self.longitude_deg
                ),
            );
        }
        if !(self.elevation_m.is_finite() && (-500.0..=9000.0).contains(&self.elevation_m)) {
            return refuse(
                "elevation_m",
                format!("{} is outside [-500, 9000] m", self.elevation_m),
            );
        }
        if parse_offset(&self.utc_offset).is_none() {
            return refuse(
                "utc_offset",
                format!("{:?} is not an offset such as +02:00 or Z", self.utc_offset),
            );
        }
        Ok(())
    }
}

impl CameraConfig {
    fn check(&self) -> Result<(), FieldError> {
        let n = self.exposures_us.len();
        if n == 0 || n > skylux_hps::fpga::MAX_EXPOSURES {
            return refuse(
                "exposures_us",
                format!(
                    "{n} exposures: a sequence holds 1 to {} (seq.* registers)",
                    skylux_hps::fpga::MAX_EXPOSURES
                ),
            );
        }
        if let Some(t) = self
            .exposures_us
            .iter()
            .find(|t| !(t.is_finite() && **t > 0.0 && **t <= 10e6))
        {
            return refuse(
                "exposures_us",
                format!("{t} must be a positive time up to 10 s"),
            );
        }
        if let Gain::PerExposure(g) = &self.gain {
            if g.len() != n {
                return refuse(
                    "gain",
                    format!("{} gains for {n} exposures: give one per exposure", g.len()),
                );
            }
        }
        if let Some(g) = self
            .gains()
            .iter()
            .find(|g| !(g.is_finite() && (1.0..=64.0).contains(*g)))
        {
            return refuse("gain", format!("{g} is outside [1, 64]"));
        }
        Ok(())
    }
}

impl RoomConfig {
    fn check(&self) -> Result<(), FieldError> {
        if self.scene.is_empty() {
            return refuse("scene", "name at least one scene file");
        }
        if !(1..=8).contains(&self.mf) {
            return refuse("mf", format!("{} is outside 1..=8", self.mf));
        }
        if self.dc_samples == 0 {
            return refuse("dc_samples", "must be at least 1");
        }
        if self.monte_carlo_samples == 0 {
            return refuse("monte_carlo_samples", "must be at least 1");
        }
        if self.ambient_bounces > 100 {
            return refuse(
                "ambient_bounces",
                format!("{} is above 100", self.ambient_bounces),
            );
        }
        Ok(())
    }
}

impl ScheduleConfig {
    fn check(&self) -> Result<(), FieldError> {
        let p = self.period_s;
        if !(p.is_finite() && (1.0..=86_400.0).contains(&p)) {
            return refuse("period_s", format!("{p} is outside [1, 86400] s"));
        }
        Ok(())
    }
}

impl OutputConfig {
    fn check(&self) -> Result<(), FieldError> {
        if self.dir.as_os_str().is_empty() {
            return refuse("dir", "must name a directory");
        }
        Ok(())
    }
}

impl ApiConfig {
    fn check(&self) -> Result<(), FieldError> {
        let Ok(addr) = self.address.parse::<SocketAddr>() else {
            return refuse(
                "address",
                format!("{:?} is not an IP address and port", self.address),
            );
        };
        if !addr.ip().is_loopback() && !self.allow_remote {
            return refuse(
                "address",
                format!(
                    "{addr} is not a loopback address: the API would be reachable from the \
                     network; set api.allow_remote = true to mean it"
                ),
            );
        }
        Ok(())
    }
}

impl RetryConfig {
    fn check(&self) -> Result<(), FieldError> {
        if !(self.initial_s.is_finite() && self.initial_s > 0.0 && self.max_s.is_finite())
            || self.max_s < self.initial_s
            || self.max_s > 86_400.0
        {
            return refuse(
                "initial_s",
                format!(
                    "initial_s = {} and max_s = {} must satisfy 0 < initial_s <= max_s <= 86400",
                    self.initial_s, self.max_s
                ),
            );
        }
        Ok(())
    }
}

impl SimConfig {
    fn check(&self) -> Result<(), FieldError> {
        // The MT9P031 skips 1 to 8 (hardware-facts.md §1); larger factors make a smaller
        // world for tests that do not look at the sun.
        if !(1..=64).contains(&self.skip) {
            return refuse("skip", format!("{} is outside 1..=64", self.skip));
        }
        match self.readout().check_bin() {
            Ok(()) => Ok(()),
            Err(reason) => refuse("bin", reason),
        }
    }

    /// The simulated frames' readout: the full array, `skip`, and `bin` or the largest
    /// binning that divides `skip`.
    pub fn readout(&self) -> skylux_hps::campaign::Readout {
        let bin = self
            .bin
            .unwrap_or_else(|| skylux_hps::campaign::Readout::largest_bin(self.skip));
        skylux_hps::campaign::Readout {
            bin,
            ..skylux_hps::campaign::Readout::skipping(0, 0, self.skip)
        }
    }

    /// Injected faults only with the `sim` source.
    fn check_fault_source(&self) -> Result<(), FieldError> {
        if self.source == SimSourceKind::Fabric && !self.faults.is_empty() {
            return refuse(
                "source",
                "injected faults ([[sim.fault]]) belong to the `sim` and `fabric-model` \
                 sources; the cycle-accurate fabric source's faults are the simulated \
                 hardware's",
            );
        }
        if self.source == SimSourceKind::Sim {
            if let Some(f) = self.faults.iter().find(|f| f.kind.hardware_only()) {
                return refuse(
                    "fault",
                    format!(
                        "kind \"{}\" is a hardware fault of the fabric model: set [sim] \
                         source = \"fabric-model\"",
                        f.kind.name()
                    ),
                );
            }
        }
        Ok(())
    }
}

impl FaultRule {
    fn check(&self) -> Result<(), FieldError> {
        if self.attempt == 0 || self.count == 0 {
            return refuse("attempt", "attempt (1-based) and count must be at least 1");
        }
        Ok(())
    }
}

impl FabricConfig {
    /// The window as the sensor driver would program it, and the frame timeout.
    fn check(&self) -> Result<(), FieldError> {
        let window = skylux_hps::fpga::sensor::SensorConfig {
            row_start: self.row_start,
            col_start: self.col_start,
            width: self.width,
            height: self.height,
            skip: self.skip,
            bin: self.bin,
            ..Default::default()
        };
        if let Err(skylux_hps::fpga::sensor::SensorError::OutOfRange {
            field,
            value,
            allowed,
        }) = window.validate()
        {
            let key = match field {
                "row_start" => "row_start",
                "col_start" => "col_start",
                "height" => "height",
                "width" => "width",
                "bin" => "bin",
                _ => "skip",
            };
            return refuse(key, format!("{value} is out of range ({allowed})"));
        }
        if !(self.frame_timeout_s.is_finite() && (0.0..=600.0).contains(&self.frame_timeout_s)) {
            return refuse(
                "frame_timeout_s",
                format!("{} is outside 0 to 600 s", self.frame_timeout_s),
            );
        }
        if let Some(s) = self.raw_every_s {
            if !(s.is_finite() && s > 0.0) {
                return refuse("raw_every_s", format!("{s} is not a positive time"));
            }
        }
        Ok(())
    }
}

impl HardwareConfig {
    /// The least-privilege rule: the daemon maps the register window of the lightweight
    /// HPS-to-FPGA bridge (physical 0xFF200000, 2 MiB: hardware-facts.md §3.1, docs/registers.md)
    /// and a DMA buffer inside the reserved, `no-map` region ([`DMA_RESERVED_BASE`],
    /// hardware-facts.md §3.4), nothing else: not the H2F window, the SDRAM the kernel uses,
    /// the peripherals (reset manager, SDRAM controller) nor the GIC. Both windows must be
    /// page-aligned and non-empty.
    pub fn check(&self) -> Result<(), FieldError> {
        let h = self;
        let lw_base = LW_BRIDGE_PHYS_BASE as u64;
        let lw_span = LW_BRIDGE_SPAN_BYTES as u64;
        if h.register_base != lw_base {
            return refuse(
                "register_base",
                format!(
                    "{:#x}: the only register window skyluxd maps is the lightweight bridge's at \
                 {lw_base:#x} (hardware-facts.md §3.1)",
                    h.register_base
                ),
            );
        }
        if h.register_size == 0
            || h.register_size > lw_span
            || !h.register_size.is_multiple_of(PAGE_BYTES)
        {
            return refuse(
                "register_size",
                format!(
                    "{:#x}: must be a non-zero multiple of {PAGE_BYTES:#x} up to the bridge's \
                 {lw_span:#x} bytes",
                    h.register_size
                ),
            );
        }
        if let Some(d) = &h.dma_device {
            let ok = d
                .to_str()
                .and_then(|s| s.strip_prefix("/dev/udmabuf"))
                .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()));
            if !ok {
                return refuse(
                    "dma_device",
                    format!("{}: expected /dev/udmabufN (u-dma-buf)", d.display()),
                );
            }
        }
        let end = h.dma_base.checked_add(h.dma_size);
        let reserved_end = DMA_RESERVED_BASE + DMA_RESERVED_SIZE;
        if h.dma_size == 0
            || !h.dma_base.is_multiple_of(PAGE_BYTES)
            || !h.dma_size.is_multiple_of(PAGE_BYTES)
            || h.dma_base < DMA_RESERVED_BASE
            || end.is_none_or(|e| e > reserved_end)
        {
            return refuse(
                if h.dma_base < DMA_RESERVED_BASE || !h.dma_base.is_multiple_of(PAGE_BYTES) {
                    "dma_base"
                } else {
                    "dma_size"
                },
                format!(
                    "{:#x} + {:#x}: the DMA buffer must be a non-empty, page-aligned part of the \
                 reserved no-map region {DMA_RESERVED_BASE:#x}..{reserved_end:#x} \
                 (bitstream/linux/skylux-overlay.dts; hardware-facts.md §3.4)",
                    h.dma_base, h.dma_size
                ),
            );
        }
        if let Some(u) = &h.uio_device {
            let ok = u
                .to_str()
                .and_then(|s| s.strip_prefix("/dev/uio"))
                .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()));
            if !ok {
                return refuse("uio_device", format!("{}: expected /dev/uioN", u.display()));
            }
        }
        if h.user.is_empty() || h.user == "root" {
            return refuse(
                "user",
                "name the unprivileged user to run as after mapping (not root)",
            );
        }
        Ok(())
    }
}

/// `+HH:MM`, `-HH:MM` or `Z`.
pub fn parse_offset(s: &str) -> Option<FixedOffset> {
    if s == "Z" || s == "z" {
        return FixedOffset::east_opt(0);
    }
    let (sign, rest) = match s.as_bytes().first()? {
        b'+' => (1, &s[1..]),
        b'-' => (-1, &s[1..]),
        _ => return None,
    };
    let (h, m) = rest.split_once(':')?;
    if h.len() != 2 || m.len() != 2 {
        return None;
    }
    let (h, m): (i32, i32) = (h.parse().ok()?, m.parse().ok()?);
    if !(0..=23).contains(&h) || !(0..=59).contains(&m) {
        return None;
    }
    FixedOffset::east_opt(sign * (h * 3600 + m * 60))
}

/// The 1-based line of `key` in `[section]` (0 if not found: a default was used).
fn line_of(text: &str, section: &str, key: &str) -> usize {
    line_in_table(text, section, 0, key)
}

/// The name of the table a header line opens (`[a.b]` or `[[a.b]]`), if it is one.
fn header_name(line: &str) -> Option<&str> {
    let h = line.strip_prefix('[')?.trim_start_matches('[');
    Some(h[..h.find(']').unwrap_or(h.len())].trim())
}

/// The 1-based line of `key` in the `index`-th (0-based) table headed `[section]` or
/// `[[section]]`; without the key (a default was used), that table's header line; 0 if there
/// is no such table.
fn line_in_table(text: &str, section: &str, index: usize, key: &str) -> usize {
    let mut seen = 0usize;
    let mut header = 0usize;
    let mut inside = false;
    for (i, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if let Some(h) = header_name(line) {
            if inside {
                break; // the table ended without the key
            }
            if h == section {
                if seen == index {
                    inside = true;
                    header = i + 1;
                }
                seen += 1;
            }
            continue;
        }
        if inside {
            if let Some(rest) = line.strip_prefix(key) {
                if rest.trim_start().starts_with('=') {
                    return i + 1;
                }
            }
        }
    }
    header
}

#[cfg(test)]
mod tests {
    use super::*;

    pub(crate) const MINIMAL: &str = r#"
[site]
latitude_deg = 46.52
longitude_deg = 6.57
elevation_m = 400.0
utc_offset = "+02:00"
[camera]
device = "device.toml"
exposures_us = [1.0, 100.0]
[room]
scene = ["scene.rad"]
sensors = "sensors.pts"
[capture]
period_s = 60
[output]
dir = "out"
"#;

    fn parse(text: &str) -> Result<Config, ConfigError> {
        Config::parse(
            text,
            Path::new("/etc/skylux/skyluxd.toml"),
            &Overrides::default(),
        )
    }

    #[test]
    fn minimal_config_resolves_paths_and_defaults() {
        let c = parse(MINIMAL).unwrap();
        assert_eq!(c.camera.device, Path::new("/etc/skylux/device.toml"));
        assert_eq!(c.output.dir, Path::new("/etc/skylux/out"));
        assert_eq!(c.api_address().to_string(), DEFAULT_API_ADDRESS);
        assert_eq!(c.hardware.register_base, 0xFF20_0000);
        assert_eq!(c.utc_offset().local_minus_utc(), 7200);
    }

    #[test]
    fn errors_name_line_and_field() {
        let text = MINIMAL.replace("period_s = 60", "period_s = 0.5");
        let e = parse(&text).unwrap_err().to_string();
        assert!(e.contains("skyluxd.toml:14"), "{e}");
        assert!(e.contains("capture.period_s"), "{e}");
        let text = MINIMAL.replace("period_s = 60", "period_s = \"x\"");
        let e = parse(&text).unwrap_err().to_string();
        assert!(e.contains(":14"), "{e}");
        let text = MINIMAL.replace("[output]", "[output]\ncolour = 3");
        let e = parse(&text).unwrap_err().to_string();
        assert!(e.contains("colour"), "{e}");
    }

    /// `camera.gain` is one number for all exposures or one per exposure; a list of the wrong
    /// length or a gain out of range is refused by name.
    #[test]
    fn gain_is_one_for_all_or_one_per_exposure() {
        let with = |gain: &str| {
            parse(&MINIMAL.replace(
                "exposures_us = [1.0, 100.0]",
                &format!("exposures_us = [1.0, 100.0]\ngain = {gain}"),
            ))
        };
        assert_eq!(parse(MINIMAL).unwrap().camera.gains(), [1.0, 1.0]);
        assert_eq!(with("2.5").unwrap().camera.gains(), [2.5, 2.5]);
        assert_eq!(with("[1.0, 7.875]").unwrap().camera.gains(), [1.0, 7.875]);
        for (bad, words) in [
            ("[1.0]", "1 gains for 2 exposures"),
            ("[1.0, 2.0, 3.0]", "3 gains for 2 exposures"),
            ("[1.0, 0.5]", "0.5 is outside [1, 64]"),
            ("[1.0, nan]", "NaN is outside [1, 64]"),
        ] {
            let e = with(bad).unwrap_err().to_string();
            assert!(e.contains("camera.gain") && e.contains(words), "{bad}: {e}");
        }
    }

    #[test]
    fn lines_are_found_under_headers_with_comments() {
        let text = MINIMAL.replace("[capture]", "[capture]   # when");
        let text = text.replace("period_s = 60", "period_s = 0");
        let e = parse(&text).unwrap_err().to_string();
        assert!(e.contains("skyluxd.toml:14"), "{e}");
    }

    /// `[room.window]`: paths resolved beside the configuration, and bad declarations
    /// refused by their field.
    #[test]
    fn window_states_resolve_and_refuse() {
        let window = "[room.window]\npolygons = \"w.rad\"\n\
                      [[room.window.states]]\nname = \"open\"\nbsdf = \"open.xml\"\n";
        let c = parse(&format!("{MINIMAL}{window}")).unwrap();
        let w = c.room.window.unwrap();
        assert_eq!(w.polygons, Path::new("/etc/skylux/w.rad"));
        assert_eq!(w.states[0].bsdf, Path::new("/etc/skylux/open.xml"));
        assert_eq!((w.up, w.view_paths), ([0.0, 0.0, 1.0], 262_144));
        for (bad, words) in [
            (
                "[room.window]\npolygons = \"w.rad\"\nstates = []\n",
                "declare at least one state",
            ),
            (
                &format!("{window}[[room.window.states]]\nname = \"open\"\nbsdf = \"b.xml\"\n"),
                "declared twice",
            ),
            (&window.replace("\"open\"", "\"a b\""), "letters, digits"),
            (
                &window.replace("w.rad\"", "w.rad\"\nup = [0, 0, 0]"),
                "other than zero",
            ),
        ] {
            let e = parse(&format!("{MINIMAL}{bad}")).unwrap_err().to_string();
            assert!(e.contains("room.window") && e.contains(words), "{bad}: {e}");
        }
    }

    #[test]
    fn remote_api_needs_allow_remote() {
        let text = format!("{MINIMAL}[api]\naddress = \"0.0.0.0:8740\"\n");
        let e = parse(&text).unwrap_err().to_string();
        assert!(
            e.contains("api.address") && e.contains("allow_remote"),
            "{e}"
        );
        let text = format!("{MINIMAL}[api]\naddress = \"0.0.0.0:8740\"\nallow_remote = true\n");
        assert!(parse(&text).is_ok());
        let text = format!("{MINIMAL}[api]\naddress = \"[::1]:9000\"\n");
        assert!(parse(&text).is_ok());
    }

    #[test]
    fn hardware_windows_other_than_bridge_and_reserved_dma_are_refused() {
        let with = |extra: &str| parse(&format!("{MINIMAL}[hardware]\n{extra}\n"));
        assert!(with("").is_ok());
        // The H2F window, the SDRAM controller, the reset manager: refused.
        for base in ["0xC0000000", "0xFFC25000", "0xFFD05000", "0xFF201000"] {
            let e = with(&format!("register_base = {base}"))
                .unwrap_err()
                .to_string();
            assert!(e.contains("hardware.register_base"), "{e}");
        }
        let e = with("register_size = 0x400000").unwrap_err().to_string();
        assert!(e.contains("register_size"), "{e}");
        assert!(with("register_size = 0x1000").is_ok());
        // Kernel RAM, a straddle, the end of the region, overflow: refused.
        for (b, s) in [
            ("0x00100000", "0x1000"),
            ("0x37FFF000", "0x2000"),
            ("0x3FFFF000", "0x2000"),
            ("0xFFFFFFFFFFFFF000", "0x2000"),
            ("0x38000800", "0x1000"),
            ("0x38000000", "0"),
        ] {
            let e = with(&format!("dma_base = {b}\ndma_size = {s}"))
                .unwrap_err()
                .to_string();
            assert!(e.contains("hardware.dma_"), "{b} {s}: {e}");
        }
        assert!(with("dma_base = 0x3C000000\ndma_size = 0x04000000").is_ok());
        assert!(with("uio_device = \"/dev/uio0\"").is_ok());
        assert!(with("uio_device = \"/dev/mem\"").is_err());
        // The cached frame buffer only through u-dma-buf's device.
        assert!(with("dma_device = \"/dev/udmabuf0\"").is_ok());
        for bad in [
            "/dev/mem",
            "/dev/udmabuf",
            "/dev/udmabuf0/../mem",
            "udmabuf0",
        ] {
            let e = with(&format!("dma_device = \"{bad}\""))
                .unwrap_err()
                .to_string();
            assert!(e.contains("hardware.dma_device"), "{bad}: {e}");
        }
        assert!(with("user = \"root\"").is_err());
    }

    #[test]
    fn faults_parse() {
        let text = format!(
            "{MINIMAL}[sim]\nskip = 16\nsky = \"overcast\"\n[[sim.fault]]\nattempt = 2\nkind = \"i2c_nack\"\n"
        );
        let c = parse(&text).unwrap();
        assert_eq!(c.sim.sky, SimSky::Overcast);
        assert_eq!(
            c.sim.faults,
            vec![FaultRule {
                attempt: 2,
                count: 1,
                kind: FaultKind::I2cNack
            }]
        );
        let e = parse(&text.replace("i2c_nack", "gremlins"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("gremlins"), "{e}");
        // The error lists the kinds there are, the newest included.
        assert!(
            e.contains("dma_bus_timeout") && e.contains("out_of_order"),
            "{e}"
        );
        // Hardware faults are the fabric model's: refused with the `sim` source, naming the
        // field; accepted with `fabric-model`, refused with the cycle-accurate `fabric`.
        let hw = text.replace("i2c_nack", "pixclk_stopped");
        let e = parse(&hw).unwrap_err().to_string();
        assert!(e.contains("sim.fault") && e.contains("fabric-model"), "{e}");
        let model = hw.replace("[sim]\n", "[sim]\nsource = \"fabric-model\"\n");
        assert_eq!(
            parse(&model).unwrap().sim.source,
            SimSourceKind::FabricModel
        );
        assert!(parse(&model.replace("fabric-model", "fabric")).is_err());
        // A DMA bus timeout is one of them: the plain simulator has no DMA to time out.
        let bus = text.replace("i2c_nack", "dma_bus_timeout");
        let e = parse(&bus).unwrap_err().to_string();
        assert!(
            e.contains("dma_bus_timeout") && e.contains("fabric-model"),
            "{e}"
        );
        let model = bus.replace("[sim]\n", "[sim]\nsource = \"fabric-model\"\n");
        assert_eq!(
            parse(&model).unwrap().sim.faults[0].kind,
            FaultKind::DmaBusTimeout
        );
    }

    /// Binning as the sensor allows it (1, 2, 4 dividing skip), in `[sim]` and `[fabric]`,
    /// refused otherwise with the field named; `[sim]`'s default is the Linux driver's choice.
    #[test]
    fn binning_is_checked_and_defaults_as_linux_picks() {
        let c = parse(&format!("{MINIMAL}[sim]\nskip = 8\n")).unwrap();
        assert_eq!(c.sim.readout().bin, 4);
        let c = parse(&format!("{MINIMAL}[sim]\nskip = 6\n")).unwrap();
        assert_eq!(c.sim.readout().bin, 2);
        let e = parse(&format!("{MINIMAL}[sim]\nskip = 6\nbin = 4\n"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("sim.bin"), "{e}");
        let c = parse(&format!("{MINIMAL}[fabric]\nskip = 4\nbin = 4\n")).unwrap();
        assert_eq!((c.fabric.skip, c.fabric.bin), (4, 4));
        for bad in ["skip = 4\nbin = 3", "skip = 2\nbin = 4"] {
            let e = parse(&format!("{MINIMAL}[fabric]\n{bad}\n"))
                .unwrap_err()
                .to_string();
            assert!(e.contains("fabric.bin"), "{bad}: {e}");
        }
    }

    /// Map mode is the default, a raw cadence is optional and must be a positive time, named
    /// in the error.
    #[test]
    fn maps_by_default_and_a_raw_cadence_is_a_positive_time() {
        let c = parse(MINIMAL).unwrap();
        assert_eq!(
            (c.fabric.hdr, c.fabric.raw_every_s),
            (HdrWhere::Fabric, None)
        );
        let c = parse(&format!(
            "{MINIMAL}[fabric]\nhdr = \"hps\"\nraw_every_s = 60\n"
        ))
        .unwrap();
        assert_eq!(
            (c.fabric.hdr, c.fabric.raw_every_s),
            (HdrWhere::Hps, Some(60.0))
        );
        for bad in ["0", "-5", "nan", "inf"] {
            let e = parse(&format!("{MINIMAL}[fabric]\nraw_every_s = {bad}\n"))
                .unwrap_err()
                .to_string();
            assert!(e.contains("fabric.raw_every_s"), "{bad}: {e}");
        }
    }

    #[test]
    fn offsets() {
        assert_eq!(parse_offset("Z").unwrap().local_minus_utc(), 0);
        assert_eq!(parse_offset("-05:30").unwrap().local_minus_utc(), -19800);
        for bad in ["", "+2", "+24:00", "02:00", "+02:60", "+٠٢:00"] {
            assert!(parse_offset(bad).is_none(), "{bad}");
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(512))]
        /// No input makes the parser panic.
        #[test]
        fn parser_never_panics(text in ".{0,400}") {
            let _ = parse(&text);
        }

        /// Nor does a valid config with one line replaced by anything.
        #[test]
        fn mutated_config_never_panics(line in 0usize..20, junk in ".{0,60}") {
            let mut lines: Vec<String> = MINIMAL.lines().map(String::from).collect();
            let i = line % lines.len();
            lines[i] = junk;
            let _ = parse(&lines.join("\n"));
        }

        /// Any number in any numeric field: an error or a config, never a panic.
        #[test]
        fn numbers_never_panic(v in proptest::num::f64::ANY, k in 0usize..6) {
            let keys = ["latitude_deg", "longitude_deg", "elevation_m", "period_s", "gain", "mf"];
            let text = match keys[k] {
                "gain" => MINIMAL.replace("[room]", &format!("gain = {v:?}\n[room]")),
                "mf" => MINIMAL.replace("[capture]", &format!("mf = {}\n[capture]", v as i64)),
                key => {
                    let re: Vec<String> = MINIMAL
                        .lines()
                        .map(|l| if l.starts_with(key) { format!("{key} = {v:?}") } else { l.into() })
                        .collect();
                    re.join("\n")
                }
            };
            let _ = parse(&text);
        }
    }
}
