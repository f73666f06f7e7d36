//! The cycle budget (`skyluxd --bench-cycle`): how long one full-resolution cycle takes, by
//! stage, on this machine and, estimated, on the DE1-SoC's Cortex-A9.
//!
//! - **Capture** is computed, not measured: the MT9P031 timing model (hardware-facts.md §0,
//!   §1.5) at 96 MHz PIXCLK, full 2592 x 1944 frame, for the five exposures of the HDR case
//!   (1 µs to 500 ms): each frame's exposure (rounded to whole rows, variant A overhead) plus
//!   its readout, and the shield plan's verdict on the ladder.
//! - **Transfer**: the DMA runs during the readout (one raw word per two PIXCLK, 192 MB/s,
//!   under the 64-bit f2sdram port's 800 MB/s at 100 MHz), so it adds only the last frame's
//!   final burst; the **HPS read** of five raw ring slots (descriptor, checksum, unpacking to
//!   samples) is measured here on an ordinary buffer.
//! - **HDR** (five full frames, one core), **sun extraction** and the **daylight-coefficient
//!   update** for 400 sensors (Reinhart MF4, 2305 sky patches, and with the mirrored ground)
//!   are measured with the same library functions the daemon runs (`hdr::merge`,
//!   `sun::extract_sun`, `DaylightCoefficients::apply_into`), median of the repeats.
//!
//! The A9 estimate multiplies the one-core figures by [`A9_SLOWDOWN`], the statement
//! that a core here is roughly ten times the A9. It is a ratio of cores, not a measurement:
//! reads of the uncached DMA buffer on the board are slower still (hardware-facts.md §3.4),
//! so the HPS-read figure is a lower bound there.

use skylux_bus::{BusError, DmaMemory};
use skylux_hps::campaign::BayerPattern;
use skylux_hps::fpga::frames::RingLayout;
use skylux_hps::fpga::sensor::SensorConfig;
use skylux_hps::hdr::merge;
use skylux_hps::timing::median_ms;
use skylux_regmap::descriptor::{self, Descriptor};
use skylux_regmap::words::raw;
use skylux_sim::hdr_case::{HdrCase, EXPOSURES_S, HEIGHT_PX, WIDTH_PX};

/// One core here against one Cortex-A9 core of the DE1-SoC (issue 8: "roughly ten times").
pub const A9_SLOWDOWN: f64 = 10.0;
/// PIXCLK on the board (hardware-facts.md §1.2).
const PIXCLK_HZ: f64 = 96e6;

/// A plain buffer standing for the DMA memory.
struct Buffer(Vec<u8>);

impl DmaMemory for Buffer {
    fn phys_base(&self) -> u64 {
        0
    }
    fn len_bytes(&self) -> u64 {
        self.0.len() as u64
    }
    fn read_bytes(&mut self, offset: u64, buf: &mut [u8]) -> Result<(), BusError> {
        skylux_bus::check_access(offset, buf.len() as u64, self.len_bytes(), 1)?;
        let o = offset as usize;
        buf.copy_from_slice(&self.0[o..o + buf.len()]);
        Ok(())
    }
    fn write_bytes(&mut self, offset: u64, data: &[u8]) -> Result<(), BusError> {
        skylux_bus::check_access(offset, data.len() as u64, self.len_bytes(), 1)?;
        let o = offset as usize;
        self.0[o..o + data.len()].copy_from_slice(data);
        Ok(())
    }
}

/// Runs the budget; prints JSON (and a table unless `json`).
pub fn run(json: bool, repeat: usize) -> anyhow::Result<()> {
    let capture = CaptureModel::new();
    let read = hps_read(repeat);
    let processing = processing(repeat)?;
    let measured = read.ms + processing.hdr_ms + processing.sun_ms + processing.dc_ms;
    let result = serde_json::json!({
        "frame": [WIDTH_PX, HEIGHT_PX],
        "pixclk_hz": PIXCLK_HZ,
        "row_pixclk": capture.row_pixclk,
        "readout_ms_per_frame": capture.readout_ms,
        "exposure_ms": capture.exposure_ms,
        "capture_ms": capture.capture_ms,
        "shield_plan": capture.shield_plan,
        "transfer_bytes": read.transfer_bytes,
        "dma_rate_mb_s": 4.0 / 2.0 * PIXCLK_HZ / 1e6,
        "hps_read_5_frames_ms": read.ms,
        "hdr_5_frames_one_core_ms": processing.hdr_ms,
        "sun_extraction_ms": processing.sun_ms,
        "dc_update_400_sensors_sky_and_ground_ms": processing.dc_ms,
        "dc_update_400_sensors_sky_only_ms": processing.dc_sky_ms,
        "sky_patches": processing.sky_patches,
        "processing_here_ms": measured,
        "a9_slowdown": A9_SLOWDOWN,
        "processing_a9_estimate_ms": measured * A9_SLOWDOWN,
        "cycle_a9_estimate_ms": capture.capture_ms + measured * A9_SLOWDOWN,
        "repeat": repeat,
    });
    println!("{result}");
    if !json {
        eprintln!(
            "capture {:.1} ms (model) | HPS read {:.1} ms | HDR {:.1} ms | sun {:.1} ms | DC \
             {:.2} ms | A9 estimate of the processing {:.0} ms",
            capture.capture_ms,
            read.ms,
            processing.hdr_ms,
            processing.sun_ms,
            processing.dc_ms,
            measured * A9_SLOWDOWN
        );
    }
    Ok(())
}

/// The capture's duration from the timing model: full frames at the default exposures.
struct CaptureModel {
    row_pixclk: u64,
    readout_ms: f64,
    exposure_ms: Vec<f64>,
    capture_ms: f64,
    shield_plan: String,
}

impl CaptureModel {
    fn new() -> Self {
        let sensor = SensorConfig::default();
        let row = crate::fabric_source::row_pixclk(&sensor);
        let readout_ms = crate::fabric_source::readout_pixclk(&sensor) as f64 / PIXCLK_HZ * 1e3;
        let exposures_us: Vec<f64> = EXPOSURES_S.iter().map(|e| e * 1e6).collect();
        let settings = crate::fabric_source::FabricSettings {
            sensor: sensor.clone(),
            i2c: skylux_hps::fpga::sensor::I2cTiming {
                half_period_cycles: 500,
                timeout_cycles: 1_000_000,
            },
            shield: skylux_hps::fpga::sequence::ShieldConfig {
                steps: 3,
                step_period_cycles: 100_000,
                limit_cycles: skylux_regmap::seq::shield_limit::CYCLES.reset,
                trigger_pulse_cycles: 100,
            },
            pixclk_hz: PIXCLK_HZ,
            exposures_us: exposures_us.clone(),
            gains: vec![1.0; exposures_us.len()],
            frame_timeout: std::time::Duration::from_secs(2),
            reset_settle: std::time::Duration::from_millis(2),
            poll_pause: std::time::Duration::from_millis(1),
            active_origin: (16, 54),
        };
        let exposure_ms: Vec<f64> = exposures_us
            .iter()
            .map(|e| {
                let sw = ((e * 1e-6 * PIXCLK_HZ + 426.0) / row as f64)
                    .round()
                    .max(1.0);
                (sw * row as f64 - 426.0).max(0.0) / PIXCLK_HZ * 1e3
            })
            .collect();
        let capture_ms: f64 = exposure_ms.iter().map(|e| e + readout_ms).sum();
        let shield_plan =
            match crate::fabric_source::plan_exposures(&settings, skylux_regmap::SYS_CLOCK_HZ) {
                Ok(p) => format!("{} opening(s): {:?}", p.openings.len(), p.openings),
                Err(e) => format!("refused: {e}"),
            };
        Self {
            row_pixclk: row,
            readout_ms,
            exposure_ms,
            capture_ms,
            shield_plan,
        }
    }
}

/// The HPS reading five raw full frames back from the ring.
struct HpsRead {
    /// Median over the repeats.
    ms: f64,
    transfer_bytes: u64,
}

fn hps_read(repeat: usize) -> HpsRead {
    let payload_words = (WIDTH_PX / 2 * HEIGHT_PX) as u32;
    let stride = (descriptor::PAYLOAD_OFFSET_BYTES + 4 * payload_words).div_ceil(8) * 8;
    let ring = RingLayout {
        window_base: 0,
        slot_stride_bytes: stride,
        slots: 5,
    };
    let mut buffer = Buffer(vec![0u8; 5 * stride as usize]);
    let words: Vec<u32> = (0..payload_words)
        .map(|i| raw::pack((i % 4096) as u16, (i * 7 % 4096) as u16))
        .collect();
    for slot in 0..5u32 {
        let d = Descriptor {
            frame_number: slot,
            timestamp_cycles: 1,
            exposure_index: slot as u8,
            raw: true,
            flags: 0,
            last_line_pixels: WIDTH_PX as u16,
            lines: HEIGHT_PX as u16,
            payload_words,
            checksum: descriptor::checksum(&words),
        };
        let o = (slot * stride) as usize;
        for (i, w) in d.encode().iter().enumerate() {
            buffer.0[o + 4 * i..o + 4 * i + 4].copy_from_slice(&w.to_le_bytes());
        }
        let p = o + descriptor::PAYLOAD_OFFSET_BYTES as usize;
        for (i, w) in words.iter().enumerate() {
            buffer.0[p + 4 * i..p + 4 * i + 4].copy_from_slice(&w.to_le_bytes());
        }
    }
    let mut samples = vec![0u16; WIDTH_PX * HEIGHT_PX];
    let ms = median_ms(repeat, || {
        for slot in 0..5 {
            let Ok(Some(c)) = ring.read_slot(&mut buffer, slot) else {
                return;
            };
            assert!(c.is_good());
            for (pair, w) in samples.chunks_exact_mut(2).zip(&c.words) {
                pair.copy_from_slice(&raw::samples(*w));
            }
        }
    });
    HpsRead {
        ms,
        transfer_bytes: 5 * u64::from(4 * payload_words),
    }
}

/// The processing of one cycle, timed on one core here.
struct Processing {
    hdr_ms: f64,
    sun_ms: f64,
    dc_ms: f64,
    dc_sky_ms: f64,
    sky_patches: usize,
}

fn processing(repeat: usize) -> anyhow::Result<Processing> {
    // HDR, one core.
    let case = HdrCase::new();
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build()?;
    let exposures = case.exposures();
    let mut map = None;
    let hdr_ms = median_ms(repeat, || {
        map = Some(
            one.install(|| merge(&exposures, &case.device, BayerPattern::GRBG, &case.geometry)),
        );
    });
    let map = map.ok_or_else(|| anyhow::anyhow!("no map"))??;

    // Sun extraction on that map.
    let search = skylux_hps::sun::SunSearch::default();
    let sun_ms = median_ms(repeat, || {
        let _ = std::hint::black_box(
            one.install(|| skylux_hps::sun::extract_sun(&map, &case.geometry, &search)),
        );
    });

    // Daylight-coefficient update, 400 sensors, MF4.
    let case = skylux_sim::dc_case::DcCase::new();
    let (dc, lum) = (&case.dc, &case.luminance_cd_m2);
    let mut out = vec![0.0; dc.sensors.len()];
    let dc_ms = median_ms(repeat.max(11), || {
        let _ = one.install(|| dc.apply_into(lum, &mut out));
    });
    let dc_sky_ms = median_ms(repeat.max(11), || case.sky_only_update(&mut out));
    Ok(Processing {
        hdr_ms,
        sun_ms,
        dc_ms,
        dc_sky_ms,
        sky_patches: case.sky_patches,
    })
}
