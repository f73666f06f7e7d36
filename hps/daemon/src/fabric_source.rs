//! [`FabricSource`]: HDR captures from the Skylux fabric through the `skylux_hps::fpga`
//! drivers, over any [`RegisterBus`] and [`DmaMemory`]: the board's mapped windows
//! (`skyluxd` without `--sim`) or the cycle-accurate core with its MT9P031 and SDRAM models
//! (`[sim] source = "fabric"`, see [`sim_fabric_source`]).
//!
//! One capture: release and configure the sensor (Chip_Version, window, skip, modes, each
//! register read back), program the capture path and the DMA ring (one slot per exposure),
//! split the exposure table into shield openings (`plan_openings_with_gaps`), run each opening's
//! sequence, wait for its frames ([`FrameWait`]: the UIO interrupt or polling, with a
//! timeout), then read every slot, check its descriptor and checksum, release it, and hand the
//! frames over.
//!
//! **Map mode**, the default (`[fabric] hdr = "fabric"`, issue 22 items 1 and 3). The capture
//! path runs grouped with the device's black level, valid range and weights, the exposures run
//! long to short, and the DMA writes the set as one map into one slot (`hdr.*`): the source
//! returns that map ([`FabricMapCapture`]) instead of frames, and the cycle reads it into its
//! luminance map with the merge's calibration. One map read instead of five frames.
//!
//! **The sun in map mode** (issue 22 item 2). Before the openings the source arms the sun
//! accumulators (`sun.*`) for the set's shortest exposure, with a window around SPA's sun
//! through the declared camera and the threshold of `sun::fabric`; after them it reads the
//! sums back, checks that exactly the armed frames were counted and that the sums are ones a
//! frame can give (`sun::check_sums`), and hands them over with the map
//! ([`FabricSunReading`]), so the cycle has the sun without a scan of the map. Anything else
//! (the sun below the horizon or outside the lens, a bus error, sums that changed under the
//! read, a count that did not move, garbage) is handed over as a [`SunFallback`]: the cycle
//! then scans the map as for a raw capture, and says so. A fault there never fails the
//! capture: the map is good without it.
//!
//! **Raw captures** ([`CaptureSource::capture_raw`]; every capture with `hdr = "hps"`): the
//! capture path runs raw (samples unchanged, two per word) into one slot per exposure, and the
//! source returns [`RawFrame`]s, which the daemon merges on the HPS and keeps in campaign
//! format, as a capture from `--sim` or the campaign tools. In map mode the daemon asks for one
//! on its `raw_every_s` cadence or on SIGUSR1, for calibration and audits; both rings fit the
//! DMA buffer, so the switch costs nothing but the capture.
//!
//! **Reads of the DMA buffer.** The FPGA-to-SDRAM port is not cache-coherent (hardware-facts.md
//! §3.2): the buffer is mapped uncached (`/dev/mem` with `O_SYNC` on a `no-map` region,
//! `hardware.rs`), so every read of a slot sees what the fabric wrote, never a stale line.
//! A slot is released (its format identifier cleared) after it is read, so a frame that did
//! not arrive can never be mistaken for an earlier one.

use crate::source::{
    CaptureSet, CaptureSource, FabricMapCapture, FabricSunReading, SourceError, SunFallback,
};
use crate::wait::{FrameWait, PollWait, WaitError};
use chrono::{DateTime, FixedOffset};
use skylux_bus::{DmaMemory, RegisterBus};
use skylux_hps::campaign::{BayerPattern, CaptureConfig, ExposureEntry, RawFrame, Readout};
use skylux_hps::fpga::frames::CapturedFrame;
use skylux_hps::fpga::sensor::{reg, I2cTiming, SensorConfig, SensorError};
use skylux_hps::fpga::sequence::{SequenceError, ShieldConfig};
use skylux_hps::fpga::shield_plan::{plan_openings_with_gaps, OpeningCost};
use skylux_hps::fpga::SunReadError;
use skylux_hps::fpga::{
    CaptureConfig as RingConfig, CaptureFaults, ExposureSlot, Fabric, GroupingConfig, MAX_EXPOSURES,
};
use skylux_hps::hdr::FabricMap;
use skylux_hps::sun::{check_sums, solar_position, FabricSunSearch, Site, SunExposure};
use skylux_regmap::hdr_values::HdrConfig;
use skylux_regmap::sun_values::SunConfig;
use skylux_regmap::words::raw;
use skylux_regmap::words::WEIGHT_ONE;
use std::ops::Range;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Duration;

/// Shutter overhead of the MT9P031 exposure formula, variant A (hardware-facts.md §0 item 2:
/// the Linux drivers' constants), with Shutter_Delay 0: `SO = 208 (Row_Bin + 1) + 98 + 1 −
/// 94` PIXCLK, 213 without binning. The bench settles A against B (§1.6); the simulated
/// sensor uses A.
fn shutter_overhead_pixclk(sensor: &SensorConfig) -> u64 {
    208 * u64::from(row_bin_field(sensor.bin) + 1) + 98 + 1 - 94
}

/// The Row_Bin / Column_Bin field of a bin factor (hardware-facts.md §1, register 0x22: 0, 1,
/// 3 for 1x, 2x, 4x).
fn row_bin_field(bin: u32) -> u32 {
    bin.max(1) - 1
}
/// I2C register writes the sequencer makes before each exposure's trigger (shutter upper and
/// lower, shutter delay, gain) and the bits of one write (start, address, register, two data
/// bytes, each with its acknowledge, stop): for the per-frame cost of a shield opening.
const WRITES_PER_EXPOSURE: u64 = 4;
const BITS_PER_WRITE: u64 = 38;

/// Everything a fabric capture needs besides the hardware.
#[derive(Clone, Debug)]
pub struct FabricSettings {
    /// Window, skip and modes; the shutter and gain are the exposure table's.
    pub sensor: SensorConfig,
    pub i2c: I2cTiming,
    pub shield: ShieldConfig,
    /// The sensor's pixel clock (hardware-facts.md §1.2: 96 MHz with the PLL on the board).
    pub pixclk_hz: f64,
    /// Integration times wanted, µs, in capture order (`camera.exposures_us`).
    pub exposures_us: Vec<f64>,
    /// Analog gain per exposure (`camera.gain`): 1 to 7.875, in the sensor's 1/8 steps.
    pub gains: Vec<f64>,
    /// Longest wait for one opening's frames beyond its expected duration.
    pub frame_timeout: Duration,
    /// Pause after releasing RESET_BAR before the first I2C access (hardware-facts.md §1.7:
    /// 1-2 ms on the board; 0 in simulation, where the model answers at once).
    pub reset_settle: Duration,
    /// Pause between reads of the fabric's clock while waiting out a blanking between
    /// openings (0 in simulation, where time advances only with register accesses).
    pub poll_pause: Duration,
    /// Register value of the first active column and row: the capture's `readout` is in
    /// active pixels (campaign.md), the sensor's `Column_Start`/`Row_Start` in array pixels.
    pub active_origin: (u32, u32),
    /// Map mode: the fabric makes the HDR map (`[fabric] hdr = "fabric"`).
    pub map: Option<MapMode>,
    /// Map mode: where the sun should be, to arm the sun accumulators (`None`: not armed).
    pub sun: Option<SunArming>,
}

/// What the source needs to aim the sun accumulators: the site (SPA's sun at the capture's
/// time), the declared camera (where that sun lands, and the luminance per DN there) and how
/// far from the prediction to look.
#[derive(Clone, Debug)]
pub struct SunArming {
    pub site: Site,
    pub camera: skylux_hps::camera::CameraModel,
    /// As far as the cycle's own search looks (`model::SUN_MAX_OFFSET_DEG`), degrees.
    pub max_offset_deg: f64,
}

/// The accumulators as armed for one capture, and what to expect back.
struct SunArmed {
    search: FabricSunSearch,
    exposure: SunExposure,
    config: SunConfig,
    /// The exposure's index within its opening, which the block matches.
    index: u8,
    /// `sun.frames` before the capture, and the armed frames it must count.
    frames_before: u16,
    frames_expected: u16,
}

/// What map mode programs: the grouping the map's words are made with and the selection's
/// thresholds.
#[derive(Clone, Debug, PartialEq)]
pub struct MapMode {
    pub grouping: GroupingConfig,
    pub hdr: HdrConfig,
}

impl MapMode {
    /// The grouping of `device`: its black level and valid range (DN, rounded), its weights in
    /// Q2.14 (rounded; the merge's calibration then uses the device's own, a difference of at
    /// most 2^-15 per weight), the CFA phase of `bayer`.
    pub fn of_device(device: &skylux_hps::camera::DeviceConfig, bayer: BayerPattern) -> Self {
        let dn = |v: f64| v.round().clamp(0.0, 4095.0) as u32;
        let q2_14 = |w: f64| (w * f64::from(WEIGHT_ONE)).round().clamp(0.0, 65535.0) as u32;
        let [wr, wg, wb] = device.response.weights;
        let phase = match bayer {
            BayerPattern::GRBG => 0,
            BayerPattern::RGGB => 1,
            BayerPattern::BGGR => 2,
            BayerPattern::GBRG => 3,
        };
        MapMode {
            grouping: GroupingConfig {
                phase,
                black_level_dn: dn(device.sensor.black_level_dn),
                valid_min_dn: dn(device.sensor.valid_min_dn),
                valid_max_dn: dn(device.sensor.valid_max_dn),
                weight_r_q2_14: q2_14(wr),
                weight_g_q2_14: q2_14(wg),
                weight_b_q2_14: q2_14(wb),
                raw: false,
            },
            hdr: HdrConfig::default(),
        }
    }
}

impl FabricSettings {
    /// Map mode with `device`'s grouping, if `[fabric] hdr = "fabric"`: the exposures then run
    /// long to short (by integration time times gain), the order the selection needs.
    pub fn with_map(
        mut self,
        config: &crate::config::Config,
        device: &skylux_hps::camera::DeviceConfig,
    ) -> Self {
        if config.fabric.hdr != crate::config::HdrWhere::Fabric {
            return self;
        }
        let mut pairs: Vec<(f64, f64)> = self
            .exposures_us
            .iter()
            .zip(&self.gains)
            .map(|(&e, &g)| (e, g))
            .collect();
        pairs.sort_by(|a, b| (b.0 * b.1).total_cmp(&(a.0 * a.1)));
        (self.exposures_us, self.gains) = pairs.into_iter().unzip();
        self.map = Some(MapMode::of_device(device, bayer_of(&self.sensor)));
        self.sun = Some(SunArming {
            site: Site {
                latitude_deg: config.site.latitude_deg,
                longitude_deg: config.site.longitude_deg,
                elevation_m: config.site.elevation_m,
            },
            camera: skylux_hps::camera::CameraModel::new(device.clone()),
            max_offset_deg: skylux_hps::model::SUN_MAX_OFFSET_DEG,
        });
        self
    }
}

/// The exposure table as the sensor will run it.
#[derive(Clone, Debug, PartialEq)]
pub struct ExposurePlan {
    pub slots: Vec<ExposureSlot>,
    /// What each slot integrates, µs (the formula applied to the rounded shutter width).
    pub exposures_us: Vec<f64>,
    /// What each slot's gain code gives.
    pub gains: Vec<f64>,
    /// The shield openings, as ranges of the table.
    pub openings: Vec<Range<usize>>,
    /// Per opening, how long to wait with the shield closed before starting it, µs: the
    /// vertical blanking the previous opening's last frame leaves, during which the sensor
    /// would hold the first trigger while the shield's open-time limit runs (0 for the first).
    pub settle_before_us: Vec<f64>,
    /// Light time of each opening, µs.
    pub open_time_us: Vec<f64>,
    /// Output size of the window, pixels.
    pub width_px: u32,
    pub height_px: u32,
    pub row_pixclk: u64,
}

/// Output pixels of a window dimension: `2 ceil(size / (2 skip))` (hardware-facts.md §1.5).
fn output_size(size: u32, skip: u32) -> u32 {
    2 * size.div_ceil(2 * skip.max(1))
}

/// Row time in PIXCLK (hardware-facts.md §0 item 1, §1.5):
/// `2 max(W/2 + max(HB, HB_MIN), 41 + 346 (Row_Bin + 1) + 99)` with
/// `HB_MIN = 346 (Row_Bin + 1) + 64 + W_DC / 2`, W_DC 80, 40, 20 for Column_Bin 0, 1, 3
/// (450 PIXCLK without binning). Row and column bin alike.
pub fn row_pixclk(sensor: &SensorConfig) -> u64 {
    let w = output_size(sensor.width, sensor.skip);
    let hb = sensor.horizontal_blank + 1;
    let rb = row_bin_field(sensor.bin);
    let w_dc = match rb {
        0 => 80,
        1 => 40,
        _ => 20,
    };
    let a = w / 2 + hb.max(346 * (rb + 1) + 64 + w_dc / 2);
    let b = 41 + 346 * (rb + 1) + 99;
    2 * u64::from(a.max(b))
}

/// Frame readout in PIXCLK: `(H + max(VB, 9)) t_ROW` (hardware-facts.md §1.5, short
/// exposures).
pub fn readout_pixclk(sensor: &SensorConfig) -> u64 {
    let h = output_size(sensor.height, sensor.skip);
    u64::from(h + (sensor.vertical_blank + 1).max(9)) * row_pixclk(sensor)
}

/// Plans the exposure table: shutter widths closest to the wanted times, the gain code, and
/// the shield openings. Every refusal names the field.
pub fn plan_exposures(s: &FabricSettings, sys_clock_hz: u32) -> Result<ExposurePlan, String> {
    s.sensor.validate().map_err(|e| e.to_string())?;
    if !(s.pixclk_hz.is_finite() && s.pixclk_hz > 0.0) {
        return Err(format!(
            "fabric: pixclk_hz {} is not a frequency",
            s.pixclk_hz
        ));
    }
    if s.exposures_us.is_empty() || s.exposures_us.len() > MAX_EXPOSURES {
        return Err(format!(
            "camera.exposures_us: the fabric takes 1 to {MAX_EXPOSURES} exposures, not {}",
            s.exposures_us.len()
        ));
    }
    if s.gains.len() != s.exposures_us.len() {
        return Err(format!(
            "camera.gain: {} gains for {} exposures",
            s.gains.len(),
            s.exposures_us.len()
        ));
    }
    let mut codes = Vec::with_capacity(s.gains.len());
    for (i, &g) in s.gains.iter().enumerate() {
        let code = (8.0 * g).round();
        if !(g.is_finite() && (8.0..=63.0).contains(&code)) {
            return Err(format!(
                "camera.gain[{i}]: {g} is outside the sensor's analog gain 1 to 7.875 \
                 (Global_Gain codes 8 to 63, hardware-facts.md §1.4)"
            ));
        }
        codes.push(code);
    }
    let row = row_pixclk(&s.sensor);
    let mut slots = Vec::new();
    let mut exposures_us = Vec::new();
    for (i, &e) in s.exposures_us.iter().enumerate() {
        if !(e.is_finite() && e > 0.0) {
            return Err(format!(
                "camera.exposures_us[{i}]: {e} is not a positive time"
            ));
        }
        let wanted = e * 1e-6 * s.pixclk_hz + 2.0 * shutter_overhead_pixclk(&s.sensor) as f64;
        let sw = (wanted / row as f64)
            .round()
            .clamp(1.0, ((1 << 20) - 1) as f64) as u32;
        let pixclk = (u64::from(sw) * row).saturating_sub(2 * shutter_overhead_pixclk(&s.sensor));
        if pixclk == 0 {
            return Err(format!(
                "camera.exposures_us[{i}]: {e} µs is below the sensor's shortest exposure here"
            ));
        }
        slots.push(ExposureSlot {
            shutter_width_rows: sw,
            shutter_delay: 0,
            gain_code: codes[i] as u32,
        });
        exposures_us.push(pixclk as f64 / s.pixclk_hz * 1e6);
    }
    let clock = f64::from(sys_clock_hz.max(1));
    let cost = OpeningCost {
        motion_us: 2.0 * f64::from(s.shield.steps) * f64::from(s.shield.step_period_cycles) / clock
            * 1e6,
        readout_us: readout_pixclk(&s.sensor) as f64 / s.pixclk_hz * 1e6,
        per_frame_us: (WRITES_PER_EXPOSURE * BITS_PER_WRITE * 2) as f64
            * f64::from(s.i2c.half_period_cycles)
            / clock
            * 1e6,
        limit_us: f64::from(s.shield.limit_cycles) / clock * 1e6,
    };
    // The sensor holds a trigger until its vertical blanking ends, and the blanking grows
    // with the shutter width: `max(VB, max(8, SW − H) + 1)` rows (hardware-facts.md §1.5),
    // beyond the `max(VB, 9)` rows in the readout.
    let h = output_size(s.sensor.height, s.sensor.skip);
    let vb = s.sensor.vertical_blank + 1;
    let gaps_us: Vec<f64> = slots
        .iter()
        .map(|slot| {
            let blank = vb.max(8u32.max(slot.shutter_width_rows.saturating_sub(h)) + 1);
            let extra = blank.saturating_sub(vb.max(9));
            (u64::from(extra) * row) as f64 / s.pixclk_hz * 1e6
        })
        .collect();
    let openings =
        plan_openings_with_gaps(&exposures_us, &gaps_us, &cost).map_err(|e| e.to_string())?;
    let open_time_us = openings
        .iter()
        .map(|r| cost.open_time_with_gaps_us(&exposures_us[r.clone()], &gaps_us[r.clone()]))
        .collect();
    let settle_before_us = openings
        .iter()
        .map(|r| match r.start {
            0 => 0.0,
            k => gaps_us[k - 1],
        })
        .collect();
    Ok(ExposurePlan {
        slots,
        exposures_us,
        gains: codes.iter().map(|c| c / 8.0).collect(),
        openings,
        settle_before_us,
        open_time_us,
        width_px: output_size(s.sensor.width, s.sensor.skip),
        height_px: output_size(s.sensor.height, s.sensor.skip),
        row_pixclk: row,
    })
}

/// Captures from the fabric.
pub struct FabricSource<B: RegisterBus, M: DmaMemory, W: FrameWait> {
    fabric: Fabric<B>,
    memory: M,
    wait: W,
    settings: FabricSettings,
    plan: ExposurePlan,
    /// The ring of the default capture: one grouped slot in map mode, else one raw slot per
    /// exposure.
    ring: RingConfig,
    /// The ring of a raw capture (the same as `ring` without map mode).
    raw_ring: RingConfig,
    stop: Arc<AtomicBool>,
}

fn sensor_error(e: SensorError, what: &str) -> SourceError {
    match e {
        SensorError::Nack { reg: r } if r == reg::CHIP_VERSION => SourceError::SensorAbsent {
            detail: format!(
                "{what}: Chip_Version (0x00) read not acknowledged: no sensor answers at I2C \
                 address 0x5D (unplugged, unpowered, or held in reset)"
            ),
        },
        SensorError::WrongChip { found } => SourceError::SensorAbsent {
            detail: format!("{what}: Chip_Version reads {found:#06x}, not an MT9P031 (0x1801)"),
        },
        SensorError::Timeout { reg: r } | SensorError::BusStuck { reg: r } => {
            SourceError::I2cBusStuck {
                register: r,
                detail: format!("{what}: {e}"),
            }
        }
        SensorError::Nack { reg: r }
        | SensorError::Verify { reg: r, .. }
        | SensorError::Refused { reg: r }
        | SensorError::NoCompletion { reg: r, .. } => SourceError::I2cNack {
            register: r,
            detail: format!("{what}: {e}"),
        },
        other => SourceError::Other(format!("{what}: {other}")),
    }
}

fn other(what: &str) -> impl FnOnce(String) -> SourceError + '_ {
    move |e| SourceError::Other(format!("{what}: {e}"))
}

impl<B: RegisterBus, M: DmaMemory, W: FrameWait> FabricSource<B, M, W> {
    /// Brings the fabric up (design ID, register-map version, a scratch round trip through the
    /// bridge), checks that the DMA buffer holds the ring and reads back what the HPS writes,
    /// and plans the exposure table. `stop` ends a wait for frames early (SIGTERM).
    pub fn new(
        bus: B,
        mut memory: M,
        wait: W,
        settings: FabricSettings,
        stop: Arc<AtomicBool>,
    ) -> Result<Self, SourceError> {
        let fabric =
            Fabric::bring_up(bus).map_err(|e| SourceError::Other(format!("bring-up: {e}")))?;
        let plan =
            plan_exposures(&settings, fabric.info().sys_clock_hz).map_err(SourceError::Other)?;
        let base = memory.phys_base().next_multiple_of(8);
        let ring = ring_for(settings.map.as_ref(), &settings, &plan, base);
        let raw_ring = ring_for(None, &settings, &plan, base);
        let end = base - memory.phys_base()
            + u64::from(ring.window_size_bytes.max(raw_ring.window_size_bytes));
        if end > memory.len_bytes() {
            return Err(SourceError::Other(format!(
                "DMA buffer: the ring needs {end} bytes from {:#x}, the buffer has {}: raise \
                 hardware.dma_size or shrink the window",
                memory.phys_base(),
                memory.len_bytes()
            )));
        }
        // The HPS side of the f2sdram path: the mapping must be memory that holds what is
        // written (a wrong base or an unmapped region reads back something else).
        let offset = base - memory.phys_base();
        for pattern in [0xA5A5_5A5Au32, 0x5A5A_A5A5] {
            let bytes = pattern.to_le_bytes();
            memory
                .write_bytes(offset, &bytes)
                .and_then(|_| {
                    let mut back = [0u8; 4];
                    memory.read_bytes(offset, &mut back).map(|_| back)
                })
                .map_err(|e| SourceError::Other(format!("DMA buffer: {e}")))
                .and_then(|back| {
                    (back == bytes).then_some(()).ok_or_else(|| {
                        SourceError::Other(format!(
                            "DMA buffer at {base:#x}: wrote {pattern:#010x}, read {:#010x}: \
                             not RAM the HPS can use (check hardware.dma_base and the \
                             reserved-memory node)",
                            u32::from_le_bytes(back)
                        ))
                    })
                })?;
        }
        for r in [&ring, &raw_ring] {
            for slot in 0..r.ring.slots {
                r.ring
                    .release_slot(&mut memory, slot)
                    .map_err(|e| SourceError::Other(format!("DMA buffer: {e}")))?;
            }
        }
        tracing::info!(
            info = ?fabric.info(),
            width_px = plan.width_px,
            height_px = plan.height_px,
            openings = plan.openings.len(),
            exposures_us = ?plan.exposures_us,
            wait = wait.name(),
            "fabric up"
        );
        Ok(Self {
            fabric,
            memory,
            wait,
            settings,
            plan,
            ring,
            raw_ring,
            stop,
        })
    }

    /// The exposure table as run.
    pub fn plan(&self) -> &ExposurePlan {
        &self.plan
    }

    /// The fabric (for tests and diagnostics).
    pub fn fabric(&mut self) -> &mut Fabric<B> {
        &mut self.fabric
    }

    fn stopped(&self) -> bool {
        self.stop.load(Ordering::Relaxed)
    }

    /// Releases every slot of both rings: nothing of an abandoned capture can be read later.
    fn release_all(&mut self) {
        for ring in [&self.ring, &self.raw_ring] {
            for slot in 0..ring.ring.slots {
                let _ = ring.ring.release_slot(&mut self.memory, slot);
            }
        }
    }

    /// One capture: in map mode a map unless `raw`, else raw frames.
    fn take(&mut self, at: DateTime<FixedOffset>, raw: bool) -> Result<CaptureSet, SourceError> {
        let map = self.settings.map.clone().filter(|_| !raw);
        let ring = match map {
            Some(_) => self.ring,
            None => self.raw_ring,
        };
        self.configure(&ring)?;
        if let Some(map) = &map {
            let f = &mut self.fabric;
            f.hdr_configure(&map.hdr, true)
                .and_then(|_| f.hdr_new_set())
                .map_err(|e| other("hdr")(e.to_string()))?;
        } else if self.settings.map.is_some() {
            // A raw capture between maps: the capture path is raw, which the map needs not to
            // be; disabled all the same, so no register state of map mode stays behind.
            self.fabric
                .hdr_configure(&HdrConfig::default(), false)
                .map_err(|e| other("hdr")(e.to_string()))?;
        }
        let sun = map.as_ref().map(|_| self.arm_sun(at));
        self.run_openings()?;
        let faults = self.take_faults()?;
        let (frames, frame_flags, fabric_map) = match map {
            Some(map) => {
                let (mut m, flags) = self.read_map(&ring, &faults, map.hdr)?;
                if let Some(armed) = sun {
                    m.sun = self.read_sun(armed);
                }
                (vec![], vec![flags], Some(m))
            }
            None => {
                let (frames, flags) = self.read_frames(&ring, &faults)?;
                (frames, flags, None)
            }
        };
        Ok(CaptureSet {
            time: at,
            config: self.capture_config(at),
            frames,
            fabric_map,
            frame_flags,
            truth_outdoor_horizontal_lux: None,
            truth_interior_lux: None,
        })
    }

    /// Sensor out of reset and configured for the first exposure, capture path (with `ring`)
    /// and shield.
    fn configure(&mut self, ring: &RingConfig) -> Result<(), SourceError> {
        let s = &self.settings;
        let f = &mut self.fabric;
        f.sensor_bus_setup(s.i2c)
            .map_err(|e| sensor_error(e, "I2C master setup"))?;
        f.sensor_reset_release(true)
            .map_err(|e| SourceError::Other(format!("RESET_BAR: {e}")))?;
        if !s.reset_settle.is_zero() {
            std::thread::sleep(s.reset_settle);
        }
        let first = self.plan.slots[0];
        let sensor = SensorConfig {
            snapshot: true,
            shutter_width_rows: first.shutter_width_rows,
            shutter_delay: first.shutter_delay,
            global_gain_code: first.gain_code,
            ..s.sensor.clone()
        };
        f.sensor_configure(&sensor)
            .map_err(|e| sensor_error(e, "sensor configuration"))?;
        f.capture_configure(ring)
            .map_err(|e| SourceError::Other(format!("capture path: {e}")))?;
        f.configure_shield(&s.shield)
            .map_err(|e| SourceError::Other(format!("shield: {e}")))?;
        Ok(())
    }

    /// One exposure sequence per shield opening, each waited for until its frames are in.
    fn run_openings(&mut self) -> Result<(), SourceError> {
        let expected = self.plan.slots.len();
        let clock = f64::from(self.fabric.info().sys_clock_hz.max(1));
        let mut received = 0usize;
        for (opening, range) in self.plan.openings.clone().iter().enumerate() {
            let f = &mut self.fabric;
            let settle_cycles = (self.plan.settle_before_us[opening] * 1e-6 * clock).ceil() as u64;
            if settle_cycles > 0 {
                f.wait_cycles(settle_cycles, self.settings.poll_pause)
                    .map_err(|e| other("fabric clock")(e.to_string()))?;
            }
            f.set_exposures(&self.plan.slots[range.clone()])
                .map_err(|e| SourceError::Other(format!("exposure table: {e}")))?;
            let start = f
                .frames_written()
                .map_err(|e| other("dma")(e.to_string()))?;
            // Each status poll takes at least one clock: twice the opening in clocks, plus a
            // margin, bounds a sequence that never ends.
            let open_cycles = self.plan.open_time_us[opening] * 1e-6 * clock;
            let max_polls = (2.0 * open_cycles) as u64 + 200_000;
            let outcome = f.run_sequence(max_polls);
            // A sequence that ended early: the capture path's sticky status says what the
            // frame went through (a stopped PIXCLK keeps FRAME_VALID high, so the sequencer
            // waits until the shield's limit closes it); read and report it with the cause.
            let status = match &outcome {
                Err(SequenceError::I2c { .. }) | Ok(_) => String::new(),
                Err(_) => match self.fabric.capture_take_faults() {
                    Ok(c) if c.any() => format!("; capture status {c:?}"),
                    _ => String::new(),
                },
            };
            outcome.map_err(|e| match e {
                SequenceError::I2c { frames, i2c_status } => SourceError::I2cNack {
                    register: reg::SHUTTER_WIDTH_LOWER,
                    detail: format!(
                        "the sequencer's exposure writes (Shutter_Width, Shutter_Delay, \
                         Global_Gain) failed after {frames} frames of opening {opening}, \
                         i2c.status {i2c_status:#x}"
                    ),
                },
                SequenceError::NoCompletion { polls } => SourceError::DmaTimeout {
                    frames_received: received,
                    frames_expected: expected,
                    waited_ms: (polls as f64 / clock * 1e3) as u64,
                },
                other => {
                    SourceError::Other(format!("sequence (opening {opening}): {other}{status}"))
                }
            })?;
            let timeout = s_timeout(&self.settings, self.plan.open_time_us[opening]);
            let n = range.len() as u32;
            match self
                .wait
                .wait_frames(&mut self.fabric, start, n, timeout, &self.stop)
            {
                Ok(_) => received += range.len(),
                Err(WaitError::Timeout {
                    received: r,
                    waited_ms,
                    ..
                }) => {
                    return Err(SourceError::DmaTimeout {
                        frames_received: received + r as usize,
                        frames_expected: expected,
                        waited_ms,
                    })
                }
                Err(e @ WaitError::Stopped { .. }) => {
                    return Err(SourceError::Other(format!("capture discarded: {e}")))
                }
                Err(e) => return Err(SourceError::Other(format!("frame wait: {e}"))),
            }
        }
        Ok(())
    }

    /// The capture path's sticky faults; a DMA bus timeout fails the capture.
    fn take_faults(&mut self) -> Result<CaptureFaults, SourceError> {
        let faults = self
            .fabric
            .capture_take_faults()
            .map_err(|e| other("capture status")(e.to_string()))?;
        if faults.dma_bus_timeout {
            return Err(SourceError::DmaBusTimeout {
                timeout_cycles: self.ring.bus_timeout_cycles,
            });
        }
        Ok(faults)
    }

    /// Every slot of the capture as a frame, with its flags.
    fn read_frames(
        &mut self,
        ring: &RingConfig,
        faults: &CaptureFaults,
    ) -> Result<(Vec<RawFrame>, Vec<Vec<String>>), SourceError> {
        let expected = self.plan.slots.len();
        let mut frames = Vec::with_capacity(expected);
        let mut frame_flags = Vec::with_capacity(expected);
        // Slot k holds exposure k (the ring restarts at slot 0 with each capture); its
        // descriptor counts the exposure within its opening's table.
        let order: Vec<(usize, usize)> = self
            .plan
            .openings
            .iter()
            .flat_map(|r| r.clone().map(move |k| (k, k - r.start)))
            .collect();
        let mut previous_frame_number: Option<u32> = None;
        for (k, index_in_opening) in order {
            let slot = k as u8;
            let captured = ring
                .ring
                .read_slot(&mut self.memory, slot)
                .map_err(|e| SourceError::Other(format!("slot {slot}: {e}")))?
                .ok_or_else(|| {
                    SourceError::Other(format!(
                        "slot {slot}: no frame although the DMA counted it (ring overwritten?)"
                    ))
                })?;
            // The sequencer numbers the frames it triggers: exposure k's frame follows
            // exposure k-1's, across openings too. A slot holding another frame (a ring
            // pointer that slipped) may carry the expected exposure index when each opening
            // holds one exposure; its frame number does not.
            let number = captured.descriptor.frame_number;
            let order_flag = previous_frame_number
                .filter(|p| number.wrapping_sub(*p) != 1)
                .map(|p| format!("FRAME_ORDER {number} after {p}"));
            previous_frame_number = Some(number);
            let (frame, flags) = self.unpack(&captured, index_in_opening, order_flag)?;
            frames.push(frame);
            frame_flags.push(flags);
        }
        // Sticky faults no descriptor explains: reported on the first frame.
        if faults.any() && frame_flags.iter().all(Vec::is_empty) {
            frame_flags[0].push(format!("CAPTURE_STATUS {faults:?}"));
        }
        Ok((frames, frame_flags))
    }

    /// Map mode: the one slot's map, with its flags (descriptor flags, not a map, the wrong
    /// size).
    fn read_map(
        &mut self,
        ring: &RingConfig,
        faults: &CaptureFaults,
        hdr: HdrConfig,
    ) -> Result<(FabricMapCapture, Vec<String>), SourceError> {
        let captured = ring
            .ring
            .read_slot(&mut self.memory, 0)
            .map_err(|e| SourceError::Other(format!("slot 0: {e}")))?
            .ok_or_else(|| {
                SourceError::Other("slot 0: no map although the DMA counted it".into())
            })?;
        let (w, h) = (self.plan.width_px as usize, self.plan.height_px as usize);
        let d = &captured.descriptor;
        let mut flags: Vec<String> = captured
            .flag_names()
            .iter()
            .map(|n| n.to_string())
            .collect();
        if !d.hdr_map {
            flags.push("NOT_MAP".into());
        }
        // The set's checksum: the sum of the usable words, which the map keeps for good.
        if captured.map_checksum_ok(&hdr) == Some(false) {
            flags.push("CHECKSUM".into());
        }
        if usize::from(d.lines) != h || usize::from(d.last_line_pixels) != w {
            flags.push(format!(
                "SIZE {}x{} (expected {w}x{h})",
                d.last_line_pixels, d.lines
            ));
        }
        // Sticky faults first: they name the cause a bad checksum would only show.
        if faults.any() {
            flags.insert(0, format!("CAPTURE_STATUS {faults:?}"));
        }
        let (gw, gh) = (w / 2, h / 2);
        if flags.is_empty() && captured.words.len() != gw * gh {
            return Err(SourceError::Other(format!(
                "slot 0: {} map words for a {w}x{h} window",
                captured.words.len()
            )));
        }
        let mut words = captured.words;
        words.resize(gw * gh, 0);
        let map = FabricMap {
            width: gw,
            height: gh,
            words,
        };
        Ok((
            FabricMapCapture {
                map,
                hdr,
                raw_width: w,
                raw_height: h,
                sun: Err(SunFallback::new(
                    "not_armed",
                    "the accumulators were not armed",
                )),
            },
            flags,
        ))
    }

    /// Arms the sun accumulators for the capture's shortest exposure (by exposure times gain:
    /// the one whose disk is least likely over-range), or disarms them and says why not.
    fn arm_sun(&mut self, at: DateTime<FixedOffset>) -> Result<SunArmed, SunFallback> {
        use skylux_bus::RegisterAccess;
        use skylux_regmap::sun;
        let mut armed = match self.sun_setup(at) {
            Ok(armed) => armed,
            Err(why) => {
                // Disarmed, so the block does not go on summing frames under an earlier setup.
                let _ = self.fabric.bus().write_reg(&sun::ctrl::REG, 0, 0);
                return Err(why);
            }
        };
        let bus = |e: skylux_bus::BusError| SunFallback::new("bus", e.to_string());
        let frames = self
            .fabric
            .bus()
            .read_reg(&sun::frames::REG, 0)
            .map_err(bus)?;
        armed.frames_before = sun::frames::COUNT.get(frames) as u16;
        self.fabric
            .sun_configure(&armed.config, armed.index, true)
            .map_err(bus)?;
        Ok(armed)
    }

    /// The search, the sun's frame and the accumulators' settings for a capture at `at`: the
    /// exposure index to arm and the frames that index arms (`frames_before` left at 0).
    fn sun_setup(&self, at: DateTime<FixedOffset>) -> Result<SunArmed, SunFallback> {
        let not_armed = |why: String| SunFallback::new("not_armed", why);
        let arming = self
            .settings
            .sun
            .as_ref()
            .ok_or_else(|| not_armed("no site or camera to predict the sun".into()))?;
        let p = &self.plan;
        let k = (0..p.slots.len())
            .min_by(|&a, &b| {
                (p.exposures_us[a] * p.gains[a]).total_cmp(&(p.exposures_us[b] * p.gains[b]))
            })
            .ok_or_else(|| not_armed("no exposure".into()))?;
        // The accumulators match the exposure's index within its opening's table, so every
        // frame of that index is armed, and the sums left are the last one's: it must be k's.
        let index_of = |j: usize| {
            p.openings
                .iter()
                .find(|r| r.contains(&j))
                .map(|r| j - r.start)
        };
        let index = index_of(k).ok_or_else(|| not_armed("exposure outside the plan".into()))?;
        let peers: Vec<usize> = (0..p.slots.len())
            .filter(|&j| index_of(j) == Some(index))
            .collect();
        if peers.last() != Some(&k) {
            return Err(not_armed(format!(
                "exposure {k}, the shortest, is not the last of index {index} in its opening"
            )));
        }
        let spa = solar_position(at.with_timezone(&chrono::Utc), &arming.site, None)
            .map_err(|e| not_armed(format!("solar position: {e}")))?;
        if spa.direction().z <= 0.0 {
            return Err(not_armed(format!(
                "the sun is below the horizon (SPA altitude {:.2} deg)",
                spa.altitude_deg()
            )));
        }
        let readout = self.capture_config(at).readout;
        let search = FabricSunSearch::around(
            spa.direction(),
            arming.max_offset_deg,
            &arming.camera,
            &readout,
        )
        .ok_or_else(|| not_armed("the predicted sun is outside the lens".into()))?;
        let exposure = SunExposure {
            exposure_s: p.exposures_us[k] * 1e-6,
            gain: p.gains[k],
        };
        let groups = ((p.width_px / 2) as usize, (p.height_px / 2) as usize);
        let config = search
            .config(&arming.camera, &readout, groups, &exposure)
            .map_err(|e| not_armed(e.to_string()))?;
        Ok(SunArmed {
            search,
            exposure,
            config,
            index: index as u8,
            frames_before: 0,
            frames_expected: peers.len() as u16,
        })
    }

    /// The sums the armed capture left, if they are the armed frames' and could be a frame's.
    fn read_sun(
        &mut self,
        armed: Result<SunArmed, SunFallback>,
    ) -> Result<FabricSunReading, SunFallback> {
        let armed = armed?;
        let (sums, frames) = self.fabric.sun_read().map_err(|e| match e {
            SunReadError::Bus(e) => SunFallback::new("bus", e.to_string()),
            e @ SunReadError::Unsettled => SunFallback::new("unsettled", e.to_string()),
        })?;
        let counted = frames.wrapping_sub(armed.frames_before);
        if counted != armed.frames_expected {
            return Err(SunFallback::new(
                "stale",
                format!(
                    "sun.frames counted {counted} frames, {} armed",
                    armed.frames_expected
                ),
            ));
        }
        check_sums(&armed.config, &sums).map_err(|e| SunFallback::new("inconsistent", e))?;
        Ok(FabricSunReading {
            search: armed.search,
            exposure: armed.exposure,
            config: armed.config,
            sums,
        })
    }

    /// `capture.toml` of the capture taken at `at`.
    fn capture_config(&self, at: DateTime<FixedOffset>) -> CaptureConfig {
        CaptureConfig {
            time: at.to_rfc3339(),
            bayer: bayer_of(&self.settings.sensor),
            sensor_temperature_c: None,
            readout: Readout {
                col_start: self
                    .settings
                    .sensor
                    .col_start
                    .saturating_sub(self.settings.active_origin.0),
                row_start: self
                    .settings
                    .sensor
                    .row_start
                    .saturating_sub(self.settings.active_origin.1),
                skip: self.settings.sensor.skip,
                bin: self.settings.sensor.bin,
            },
            exposure: self
                .plan
                .exposures_us
                .iter()
                .enumerate()
                .map(|(i, &e)| ExposureEntry {
                    file: format!("exp{i}.pgm"),
                    exposure_us: e,
                    gain: self.plan.gains[i],
                    offset_ms: 0.0,
                })
                .collect(),
        }
    }

    /// A raw-mode slot as samples, with its flags (descriptor flags, a bad checksum, a frame
    /// of the wrong size or exposure index).
    fn unpack(
        &self,
        c: &CapturedFrame,
        exposure_index: usize,
        order_flag: Option<String>,
    ) -> Result<(RawFrame, Vec<String>), SourceError> {
        let (w, h) = (self.plan.width_px as usize, self.plan.height_px as usize);
        let mut flags: Vec<String> = c.flag_names().iter().map(|n| n.to_string()).collect();
        flags.extend(order_flag);
        if c.checksum_ok() == Some(false) {
            flags.push("CHECKSUM".into());
        }
        let d = &c.descriptor;
        if !d.raw {
            flags.push("NOT_RAW".into());
        }
        if usize::from(d.exposure_index) != exposure_index {
            flags.push(format!(
                "EXPOSURE_INDEX {} (expected {exposure_index})",
                d.exposure_index
            ));
        }
        if flags.is_empty() && (usize::from(d.lines) != h || usize::from(d.last_line_pixels) != w) {
            flags.push(format!(
                "SIZE {}x{} (expected {w}x{h})",
                d.last_line_pixels, d.lines
            ));
        }
        let mut samples_dn = vec![0u16; w * h];
        if flags.is_empty() {
            if c.words.len() != w / 2 * h {
                return Err(SourceError::Other(format!(
                    "slot {}: {} payload words for a {w}x{h} raw frame",
                    c.slot,
                    c.words.len()
                )));
            }
            // A9 cost (timing::a9::ring::UNPACK_PER_WORD): `ldr`, `and` with 0x0fff0fff,
            // `str`, loop: 5 instructions a word, memory-bound (4n bytes read, 4n written).
            for (pair, word) in samples_dn.chunks_exact_mut(2).zip(&c.words) {
                pair.copy_from_slice(&raw::samples(*word));
            }
        }
        Ok((
            RawFrame {
                width: w,
                height: h,
                samples_dn,
            },
            flags,
        ))
    }
}

/// The ring: one raw slot per exposure, or with `map` one grouped slot for the map.
fn ring_for(
    map: Option<&MapMode>,
    settings: &FabricSettings,
    plan: &ExposurePlan,
    base: u64,
) -> RingConfig {
    let slots = match map {
        Some(_) => 1,
        None => settings.exposures_us.len() as u8,
    };
    let mut ring = RingConfig::fitted(plan.width_px, plan.height_px, base, slots);
    match map {
        Some(map) => ring.grouping = map.grouping,
        None => {
            ring.grouping.raw = true;
            // Raw mode stores every row: refit the stride to it.
            let stride = ring.slot_bytes_needed().min(u64::from(u32::MAX)) as u32;
            ring.ring.slot_stride_bytes = stride;
            ring.window_size_bytes = stride.saturating_mul(u32::from(slots));
        }
    }
    ring
}

/// The wait for one opening: its light time twice over, plus the configured margin.
fn s_timeout(s: &FabricSettings, open_time_us: f64) -> Duration {
    s.frame_timeout + Duration::from_secs_f64((2.0 * open_time_us * 1e-6).clamp(0.0, 60.0))
}

/// The CFA phase of the read-out window (hardware-facts.md §1.1): GRBG unmirrored, with even
/// starts; mirroring moves it.
fn bayer_of(s: &SensorConfig) -> BayerPattern {
    match (s.mirror_row, s.mirror_column) {
        (false, false) => BayerPattern::GRBG,
        (false, true) => BayerPattern::RGGB,
        (true, false) => BayerPattern::BGGR,
        (true, true) => BayerPattern::GBRG,
    }
}

impl<B: RegisterBus, M: DmaMemory, W: FrameWait> CaptureSource for FabricSource<B, M, W> {
    fn name(&self) -> &'static str {
        "fabric"
    }

    fn capture(&mut self, at: DateTime<FixedOffset>) -> Result<CaptureSet, SourceError> {
        self.capture_with(at, false)
    }

    fn capture_raw(&mut self, at: DateTime<FixedOffset>) -> Result<CaptureSet, SourceError> {
        self.capture_with(at, true)
    }

    fn makes_maps(&self) -> bool {
        self.settings.map.is_some()
    }
}

impl<B: RegisterBus, M: DmaMemory, W: FrameWait> FabricSource<B, M, W> {
    /// A capture, raw if `raw` (map mode otherwise makes a map).
    fn capture_with(
        &mut self,
        at: DateTime<FixedOffset>,
        raw: bool,
    ) -> Result<CaptureSet, SourceError> {
        if self.stopped() {
            return Err(SourceError::Other(
                "capture discarded: stop requested".into(),
            ));
        }
        let result = self.take(at, raw);
        // Read or abandoned, no slot keeps a frame for the next capture.
        self.release_all();
        result
    }
}

/// The fabric's interrupt or polling, as `[hardware] uio_device` says, for the board.
pub fn board_wait(uio: Option<&std::path::Path>) -> Result<crate::wait::AnyWait, WaitError> {
    Ok(match uio {
        Some(p) => crate::wait::AnyWait::Uio(crate::wait::UioWait::open(p)?),
        None => crate::wait::AnyWait::Poll(PollWait {
            max_polls: u64::MAX,
            pause: Duration::from_millis(1),
        }),
    })
}

/// The settings of `[fabric]`: on the board (`sim` false) the sensor at 96 MHz PIXCLK
/// (hardware-facts.md §1.2), 100 kHz I2C, a shield step every millisecond, RESET_BAR settle
/// 2 ms; in the cycle-accurate simulation the same window with a fast I2C bus (4 clocks per
/// half period) and a short shield motion, because the simulation runs ~20k clocks a second.
pub fn fabric_settings(
    config: &crate::config::Config,
    sys_clock_hz: u32,
    sim: bool,
) -> FabricSettings {
    let w = &config.fabric;
    FabricSettings {
        sensor: SensorConfig {
            row_start: w.row_start,
            col_start: w.col_start,
            width: w.width,
            height: w.height,
            skip: w.skip,
            bin: w.bin,
            ..SensorConfig::default()
        },
        i2c: if sim {
            I2cTiming {
                half_period_cycles: 4,
                timeout_cycles: 5_000,
            }
        } else {
            I2cTiming {
                // 100 kHz SCL: half a period of 5 µs.
                half_period_cycles: (sys_clock_hz / 200_000).max(2),
                timeout_cycles: (sys_clock_hz / 100).min((1 << 24) - 1),
            }
        },
        shield: ShieldConfig {
            steps: w.shield_steps,
            step_period_cycles: if sim {
                40
            } else {
                (sys_clock_hz / 1000).max(2)
            },
            limit_cycles: skylux_regmap::seq::shield_limit::CYCLES.reset,
            trigger_pulse_cycles: if sim { 4 } else { 100 },
        },
        pixclk_hz: 96e6,
        exposures_us: config.camera.exposures_us.clone(),
        gains: config.camera.gains(),
        frame_timeout: Duration::from_secs_f64(w.frame_timeout_s),
        reset_settle: if sim {
            Duration::ZERO
        } else {
            Duration::from_millis(2)
        },
        poll_pause: if sim {
            Duration::ZERO
        } else {
            Duration::from_millis(1)
        },
        // The simulated sensor renders its register window as active coordinates.
        active_origin: if sim { (0, 0) } else { (16, 54) },
        map: None,
        sun: None,
    }
}

/// The fabric source over the cycle-accurate core (`[sim] source = "fabric"`): the whole
/// fabric with an MT9P031 model imaging the simulated world through the declared camera, and
/// SDRAM models with random back-pressure, driven through the same `FabricSource` as the
/// board with a polling wait.
pub struct SimFabricSource {
    pub inner: FabricSource<
        skylux_sim::core_rig::SimCoreRegisters,
        skylux_sim::core_rig::SimCoreMemory,
        PollWait,
    >,
    pub rig: skylux_sim::core_rig::SharedCore,
    world: crate::sim_stage::WorldStage,
}

/// A simulated fabric's settings (`fabric_settings` with `sim`), its exposure plan and a frame
/// buffer just large enough for its ring (one raw slot per exposure).
pub fn sim_fabric_plan(
    config: &crate::config::Config,
    device: &skylux_hps::camera::DeviceConfig,
) -> Result<(FabricSettings, ExposurePlan, usize), SourceError> {
    let settings =
        fabric_settings(config, skylux_regmap::SYS_CLOCK_HZ, true).with_map(config, device);
    sim_plan_of(settings)
}

/// [`sim_fabric_plan`] of given settings (map mode's, say).
fn sim_plan_of(
    settings: FabricSettings,
) -> Result<(FabricSettings, ExposurePlan, usize), SourceError> {
    let plan =
        plan_exposures(&settings, skylux_regmap::SYS_CLOCK_HZ).map_err(SourceError::Other)?;
    let bytes = |map| ring_for(map, &settings, &plan, 0).window_size_bytes as usize;
    let memory_bytes = bytes(settings.map.as_ref()).max(bytes(None)) + 4096;
    Ok((settings, plan, memory_bytes))
}

/// Builds [`SimFabricSource`] from the configuration.
pub fn sim_fabric_source(
    config: &crate::config::Config,
    device: &skylux_hps::camera::DeviceConfig,
    stop: Arc<AtomicBool>,
) -> Result<SimFabricSource, SourceError> {
    use skylux_sim::core_rig::{sim_core, CoreRigConfig};
    let (settings, _plan, memory_bytes) = sim_fabric_plan(config, device)?;
    let world = crate::sim_stage::WorldStage::new(config, device)?;
    let sensor = skylux_sim::mt9p031::Mt9p031::new(world.pixel_source(), settings.pixclk_hz);
    // Back-pressure on the frame port as in tests/tests/core_system.rs.
    let (rig, regs, memory, _raybox) =
        sim_core(sensor, CoreRigConfig::new(memory_bytes, 4096, 0.3));
    let wait = PollWait {
        // Each poll is a register read of a few simulated clocks: a bound of ~20 simulated
        // ms beyond the opening, reached in seconds when no frame comes.
        max_polls: 500_000,
        pause: Duration::ZERO,
    };
    let inner = FabricSource::new(regs, memory, wait, settings, stop)?;
    Ok(SimFabricSource { inner, rig, world })
}

impl CaptureSource for SimFabricSource {
    fn name(&self) -> &'static str {
        "fabric-sim"
    }

    fn capture(&mut self, at: DateTime<FixedOffset>) -> Result<CaptureSet, SourceError> {
        self.world.stage(at)?;
        let mut set = self.inner.capture(at)?;
        self.world.attach_truth(&mut set, at)?;
        Ok(set)
    }

    fn capture_raw(&mut self, at: DateTime<FixedOffset>) -> Result<CaptureSet, SourceError> {
        self.world.stage(at)?;
        let mut set = self.inner.capture_raw(at)?;
        self.world.attach_truth(&mut set, at)?;
        Ok(set)
    }

    fn makes_maps(&self) -> bool {
        self.inner.makes_maps()
    }
}
