//! The cycle budget (`skyluxd --bench-cycle`): how long one full-resolution cycle takes, by
//! stage, on this machine and on the DE1-SoC's Cortex-A9. Three kinds of figure, kept apart in
//! the output and in BENCHMARKS.md:
//!
//! - **Computed: the capture.** The MT9P031 timing model (hardware-facts.md §0, §1.5) at 96 MHz
//!   PIXCLK, full 2592 x 1944 frame, for the five exposures of the HDR case (1 µs to 500 ms):
//!   each frame's exposure (rounded to whole rows, variant A overhead) plus its readout, and
//!   the shield plan's verdict on the ladder. No design of the processing shortens it.
//! - **Measured here (x86, one core): the processing.** The DMA runs during the readout (one
//!   raw word per two PIXCLK, 192 MB/s, under the 64-bit f2sdram port's 800 MB/s at 100 MHz),
//!   so it adds only the last frame's final burst; the **HPS read** of five raw ring slots
//!   (descriptor, checksum, unpacking to samples) is measured on an ordinary buffer. The
//!   **HDR merge** (five full frames), **sun extraction** and **daylight-coefficient update**
//!   for 400 sensors (Reinhart MF4, 2305 sky patches, and with the mirrored ground) run the
//!   library functions the daemon runs (`hdr::merge`, `sun::extract_sun`,
//!   `DaylightCoefficients::apply_into`) on a one-thread pool; median of the repeats.
//! - **Modelled: the A9.** `skylux_hps::timing::a9`: per stage, the bytes moved (the uncached
//!   ring, cached DDR3 streams, zero-fills) at published Cortex-A9 rates, and the instructions
//!   of each loop, counted from the armv7 listing of the same code, at the A9's issue and VFP
//!   rates; per pass the larger of the two, passes summed. The work counts that depend on the
//!   data (valid exposures per group, the sun's components and boxes) are taken from the same
//!   case the measurement runs. One core, and the daemon's two (rayon spreads the merge and
//!   the coefficient update). Nothing here ran on the board.
//!
//! Map mode (the default) replaces three stages of the raw path: the read of five raw frames,
//! the merge, and the HPS's scan of the map for the sun, which becomes the accumulators'
//! registers and the arithmetic on their sums (`timing::a9::sun_fabric`; the arithmetic and
//! the background's ring are also measured here on a representative disk, the bridge accesses
//! cannot be). The scan stays in the output as the figure of a cycle whose accumulators gave
//! nothing to believe (`sun_fallback`: no sun in the window, a saturated disk, a fault).

use skylux_bus::{BusError, DmaMemory};
use skylux_hps::campaign::BayerPattern;
use skylux_hps::fpga::frames::RingLayout;
use skylux_hps::fpga::sensor::SensorConfig;
use skylux_hps::hdr::{merge, ExposureFrame, GroupParams, MapFlag};
use skylux_hps::sun::{
    check_sums, fabric_background_cd_m2, sun_from_fabric, FabricSunSearch, SunExposure,
    SOLAR_DISK_SR,
};
use skylux_hps::timing::a9::{self, HdrWork, Stage, SunWork};
use skylux_hps::timing::median_ms;
use skylux_regmap::descriptor::{self, Descriptor};
use skylux_regmap::sun_values::{SunConfig, SunSums};
use skylux_regmap::words::raw;
use skylux_sim::hdr_case::{HdrCase, EXPOSURES_S, HEIGHT_PX, WIDTH_PX};

/// The issue's target from trigger to lux, seconds (issue 22).
const TARGET_CYCLE_S: f64 = 1.0;
/// The factor the budget used before the model (issue 8's "one core here is roughly ten A9
/// cores"), printed only beside the model for comparison.
const OLD_X10: f64 = 10.0;
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
    /// In place, as the mappings read (one pass, `timing::a9::hps_read`).
    fn read_words_le(
        &mut self,
        offset: u64,
        count: usize,
        words: &mut Vec<u32>,
    ) -> Result<(), BusError> {
        skylux_bus::check_access(offset, 4 * count as u64, self.len_bytes(), 1)?;
        let o = offset as usize;
        words.extend(
            self.0[o..o + 4 * count]
                .chunks_exact(4)
                .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]])),
        );
        Ok(())
    }
}

/// Runs the budget; prints JSON (and a table unless `json`).
pub fn run(json: bool, repeat: usize) -> anyhow::Result<()> {
    let capture = CaptureModel::new();
    let read = hps_read(repeat);
    let processing = processing(repeat)?;
    let measured = read.ms + processing.hdr_ms + processing.sun_ms + processing.dc_ms;

    // The A9 model, stage by stage, beside the measurement here.
    let stages: [(Stage, f64); 4] = [
        (a9::hps_read(5.0, read.words_per_frame as f64), read.ms),
        (a9::hdr_merge(&processing.hdr_work), processing.hdr_ms),
        (a9::sun_extraction(&processing.sun_work), processing.sun_ms),
        (
            a9::dc_update(processing.dc_sensors as f64, processing.dc_bins as f64),
            processing.dc_ms,
        ),
    ];
    let a9_one_core_s: f64 = stages.iter().map(|(s, _)| s.seconds(1)).sum();
    let a9_processing_s: f64 = stages.iter().map(|(s, _)| s.seconds(a9::CORES)).sum();
    let capture_s = capture.capture_ms / 1e3;
    let fabric_sun = &processing.sun_fabric;
    let map = MapMode::model(
        &stages,
        &processing.hdr_work,
        a9::sun_fabric(
            fabric_sun.ring_box_groups,
            fabric_sun.ring_values,
            fabric_sun.limb_groups,
        ),
    );
    let a9_map_processing_s = map.processing_s(&map.uncached, a9::CORES);
    let a9_map_one_core_s = map.processing_s(&map.uncached, 1);
    let a9_map_cached_processing_s = map.processing_s(&map.cached, a9::CORES);
    let a9_cycle_s = capture_s + a9_map_processing_s;
    // A map-mode cycle whose sun falls back to the HPS's scan.
    let a9_map_scan_processing_s = map.processing_with_scan_s(&map.uncached, a9::CORES);
    let a9_sun_fabric_ms = map.uncached[2].seconds(a9::CORES) * 1e3;
    let a9_sun_hps_scan_ms = stages[2].0.seconds(a9::CORES) * 1e3;
    let raw_processing_s = a9_processing_s;
    let raw_one_core_s = a9_one_core_s;
    let stage_json = raw_stages_json(&stages);
    let map_mode_json = serde_json::json!({
        "a9_stages": map_stages_json(&map.uncached),
        "a9_stages_cached_read": map_stages_json(&map.cached),
        "replaces": ["hps_read", "hdr_merge", "sun_extraction"],
        "a9_sun_fabric_ms": a9_sun_fabric_ms,
        "a9_sun_hps_scan_ms": a9_sun_hps_scan_ms,
        "a9_processing_hps_sun_scan_s": a9_map_scan_processing_s,
        "a9_cycle_hps_sun_scan_s": capture_s + a9_map_scan_processing_s,
        "a9_processing_s": a9_map_processing_s,
        "a9_processing_one_core_s": a9_map_one_core_s,
        "a9_cycle_s": a9_cycle_s,
        "a9_processing_cached_read_s": a9_map_cached_processing_s,
        "a9_cycle_cached_read_s": capture_s + a9_map_cached_processing_s,
        "provenance": "modelled: skylux_hps::timing::a9 (hps_read_map, hps_read_map_cached, \
                       hdr_fabric_map, sun_fabric; hdr_fabric_map's per-group costs, the \
                       invalidation, sun_fabric's bridge accesses and arithmetic estimated), \
                       not measured",
    });
    // Raw captures (`hdr = "hps"`, or a raw capture on its cadence): five raw frames read
    // and merged on the HPS; the stages measured here and modelled.
    let raw_mode_json = serde_json::json!({
        "a9_processing_s": raw_processing_s,
        "a9_processing_one_core_s": raw_one_core_s,
        "a9_cycle_s": capture_s + raw_processing_s,
        "a9_cycle_one_core_s": capture_s + raw_one_core_s,
        "a9_stages": stage_json,
    });
    let a9_work_json = serde_json::json!({
        "hps_read": {"frames": 5, "words_per_frame": read.words_per_frame},
        "hdr_merge": {
            "groups": processing.hdr_work.groups,
            "exposures": processing.hdr_work.exposures,
            "valid_pairs": processing.hdr_work.valid_pairs,
            "valid_groups": processing.hdr_work.valid_groups,
        },
        "sun_extraction": sun_work_json(&processing.sun_work),
        "sun_fabric": {
            "disk_box_groups": [fabric_sun.side, fabric_sun.side],
            "ring_box_groups": fabric_sun.ring_box_groups,
            "ring_values": fabric_sun.ring_values,
            "limb_groups": fabric_sun.limb_groups,
            "register_accesses": a9::sun_fabric::REGISTER_ACCESSES,
            "lw_bridge_access_s_estimate": a9::LW_BRIDGE_ACCESS_S,
        },
        "dc_update": {"sensors": processing.dc_sensors, "bins": processing.dc_bins},
    });
    let a9_machine_json = serde_json::json!({
        "clock_hz": a9::CLOCK_HZ,
        "issue_instructions_per_cycle": a9::ISSUE_INSTRUCTIONS_PER_CYCLE,
        "ls_fp_slots_per_cycle": a9::LS_FP_SLOTS_PER_CYCLE,
        "vdiv_f64_ops_per_s": a9::VDIV_F64_OPS_PER_S,
        "vsqrt_f64_ops_per_s": a9::VSQRT_F64_OPS_PER_S,
        "vmul_f64_ops_per_s": a9::VMUL_F64_OPS_PER_S,
        "vadd_f64_ops_per_s": a9::VADD_F64_OPS_PER_S,
        "neon_f32_ops_per_s_unused": a9::NEON_F32_OPS_PER_S,
        "dram_peak_bytes_per_s": a9::DRAM_PEAK_BYTES_PER_S,
        "dram_stream_bytes_per_s": a9::DRAM_STREAM_BYTES_PER_S,
        "dram_fill_bytes_per_s": a9::DRAM_FILL_BYTES_PER_S,
        "uncached_read_bytes_per_s": a9::UNCACHED_READ_BYTES_PER_S,
        "cores": a9::CORES,
        "sources": "hps/core/src/timing/a9.rs, [A1] to [A10]",
    });
    let provenance_json = serde_json::json!({
        "computed": "capture_*, readout_ms_per_frame, exposure_ms, dma_rate_mb_s: the MT9P031 timing model",
        "measured": "*_ms of the stages and processing_here_ms: this machine, one core, median of the repeats",
        "modelled": "a9_*, processing_a9_estimate_ms, cycle_a9_estimate_ms: skylux_hps::timing::a9, not run on the board",
        "superseded": "x10_*: the measured figures times 10, for comparison only",
    });
    let result = serde_json::json!({
        "frame": [WIDTH_PX, HEIGHT_PX],
        "pixclk_hz": PIXCLK_HZ,
        "row_pixclk": capture.row_pixclk,
        "readout_ms_per_frame": capture.readout_ms,
        "exposure_ms": capture.exposure_ms,
        "capture_ms": capture.capture_ms,
        "capture_s": capture_s,
        "shield_plan": capture.shield_plan,
        "transfer_bytes": read.transfer_bytes,
        "dma_rate_mb_s": 4.0 / 2.0 * PIXCLK_HZ / 1e6,
        "hps_read_5_frames_ms": read.ms,
        "hdr_5_frames_one_core_ms": processing.hdr_ms,
        "sun_extraction_ms": processing.sun_ms,
        // The sun from the accumulators' sums: the arithmetic and the background's ring
        // (the bridge accesses are the A9 model's only).
        "sun_fabric_here_ms": fabric_sun.ms,
        "dc_update_400_sensors_sky_and_ground_ms": processing.dc_ms,
        "dc_update_400_sensors_sky_only_ms": processing.dc_sky_ms,
        "sky_patches": processing.sky_patches,
        "processing_here_ms": measured,
        // The default design (`[fabric] hdr = "fabric"`), the map read uncached as the
        // example maps it.
        "hdr": "fabric",
        "a9_processing_s": a9_map_processing_s,
        "a9_processing_one_core_s": a9_map_one_core_s,
        "a9_cycle_s": a9_cycle_s,
        "a9_cycle_one_core_s": capture_s + a9_map_one_core_s,
        "a9_cycle_cached_read_s": capture_s + a9_map_cached_processing_s,
        // The sun stage of the default design (the accumulators) and of a cycle that falls
        // back to the HPS's scan of the map, and that cycle.
        "a9_sun_ms": a9_sun_fabric_ms,
        "a9_sun_hps_scan_ms": a9_sun_hps_scan_ms,
        "a9_cycle_hps_sun_scan_s": capture_s + a9_map_scan_processing_s,
        "target_cycle_s": TARGET_CYCLE_S,
        "fabric_map_mode": map_mode_json,
        "raw_mode": raw_mode_json,
        "a9_work": a9_work_json,
        "a9_machine": a9_machine_json,
        // The model's processing over the measured one-core processing here: an output, not
        // an input (it was the fixed factor 10 before the model).
        "a9_slowdown": a9_one_core_s * 1e3 / measured,
        "x10_processing_ms": measured * OLD_X10,
        "x10_cycle_ms": capture.capture_ms + measured * OLD_X10,
        // Kept for readers of the earlier output: the model's figures of the default design.
        "processing_a9_estimate_ms": a9_map_processing_s * 1e3,
        "cycle_a9_estimate_ms": a9_cycle_s * 1e3,
        "provenance": provenance_json,
        "repeat": repeat,
    });
    println!("{result}");
    if !json {
        print_table(&capture, &stages, measured, a9_one_core_s, a9_processing_s);
        eprintln!(
            "map mode (the default), A9 two cores: processing {:.0} ms, cycle {:.0} ms with the \
             map read uncached; {:.0} ms and {:.0} ms read cached (u-dma-buf); the sun {:.2} \
             ms from the accumulators ({:.3} ms of it here), {:.0} ms when the HPS scans the \
             map (cycle {:.0} ms)",
            a9_map_processing_s * 1e3,
            a9_cycle_s * 1e3,
            a9_map_cached_processing_s * 1e3,
            (capture_s + a9_map_cached_processing_s) * 1e3,
            a9_sun_fabric_ms,
            fabric_sun.ms,
            a9_sun_hps_scan_ms,
            (capture_s + a9_map_scan_processing_s) * 1e3
        );
    }
    Ok(())
}

/// Map mode (`[fabric] hdr = "fabric"`, the default): the fabric's map replaces the five raw
/// frames' read and the merge, and its sun accumulators the scan of the map; modelled only
/// (but for the sun's arithmetic, no x86 measurement of it here). The map is read through the
/// mapping `[hardware]` names: uncached (`/dev/mem`, the example) or cached with explicit
/// maintenance (`dma_device`, u-dma-buf).
struct MapMode {
    /// The raw path's stages (read, merge, sun, coefficients), which the map's replace in part.
    raw: Vec<Stage>,
    /// The map's read, its conversion, the sun from the accumulators.
    uncached: [Stage; 3],
    cached: [Stage; 3],
}

impl MapMode {
    fn model(raw: &[(Stage, f64); 4], w: &HdrWork, sun: Stage) -> Self {
        MapMode {
            raw: raw.iter().map(|(s, _)| s.clone()).collect(),
            uncached: [
                a9::hps_read_map(w.groups),
                a9::hdr_fabric_map(w.groups, w.valid_groups),
                sun.clone(),
            ],
            cached: [
                a9::hps_read_map_cached(w.groups),
                a9::hdr_fabric_map(w.groups, w.valid_groups),
                sun,
            ],
        }
    }

    /// The processing with `map`'s stages instead of the raw read, the merge and the scan.
    fn processing_s(&self, map: &[Stage], cores: u32) -> f64 {
        let sum = |stages: &[Stage]| stages.iter().map(|s| s.seconds(cores)).sum::<f64>();
        sum(&self.raw[3..]) + sum(map)
    }

    /// The same with the HPS's scan for the sun instead of the accumulators.
    fn processing_with_scan_s(&self, map: &[Stage], cores: u32) -> f64 {
        let sum = |stages: &[Stage]| stages.iter().map(|s| s.seconds(cores)).sum::<f64>();
        sum(&self.raw[2..]) + sum(&map[..2])
    }
}

fn map_stages_json(stages: &[Stage]) -> Vec<serde_json::Value> {
    stages
        .iter()
        .map(|s| {
            serde_json::json!({
                "stage": s.name,
                "a9_memory_ms": s.memory_s() * 1e3,
                "a9_compute_one_core_ms": s.compute_s() * 1e3,
                "a9_one_core_ms": s.seconds(1) * 1e3,
                "passes": s.passes.iter().map(|p| serde_json::json!({
                    "pass": p.name,
                    "memory_ms": p.memory_s() * 1e3,
                    "compute_one_core_ms": p.compute_s() * 1e3,
                })).collect::<Vec<_>>(),
            })
        })
        .collect()
}

/// The raw path's stages: measured here, modelled on the A9, and the superseded x10.
fn raw_stages_json(stages: &[(Stage, f64)]) -> Vec<serde_json::Value> {
    stages
        .iter()
        .map(|(stage, x86_ms)| {
            serde_json::json!({
                "stage": stage.name,
                "x86_measured_ms": x86_ms,
                "a9_memory_ms": stage.memory_s() * 1e3,
                "a9_compute_one_core_ms": stage.compute_s() * 1e3,
                "a9_one_core_ms": stage.seconds(1) * 1e3,
                "a9_two_cores_ms": stage.seconds(a9::CORES) * 1e3,
                "a9_no_overlap_ms": (stage.memory_s() + stage.compute_s()) * 1e3,
                "x10_ms": x86_ms * OLD_X10,
                "passes": stage.passes.iter().map(|p| serde_json::json!({
                    "pass": p.name,
                    "memory_ms": p.memory_s() * 1e3,
                    "compute_one_core_ms": p.compute_s() * 1e3,
                    "parallel": p.parallel,
                })).collect::<Vec<_>>(),
            })
        })
        .collect()
}

fn sun_work_json(w: &SunWork) -> serde_json::Value {
    serde_json::json!({
        "groups": w.groups,
        "scan_calls_unseen_flagged_valid": w.scan_calls,
        "search_calls_unseen_flagged_valid": w.search_calls,
        "members": w.members,
        "flux_visits": w.flux_visits,
        "chosen_members": w.chosen_members,
        "box_groups": w.box_groups,
        "ring_box_groups": w.ring_box_groups,
        "ring_values": w.ring_values,
    })
}

/// The table on stderr: each stage's measured, modelled and superseded figures.
fn print_table(
    capture: &CaptureModel,
    stages: &[(Stage, f64)],
    measured_ms: f64,
    a9_one_core_s: f64,
    a9_processing_s: f64,
) {
    eprintln!(
        "{:<28} {:>12} {:>10} {:>11} {:>10} {:>10} {:>9}",
        "stage", "x86 meas. ms", "A9 mem ms", "A9 comp ms", "A9 1 core", "A9 2 cores", "old x10"
    );
    eprintln!(
        "{:<28} {:>12} {:>10} {:>11} {:>10.0} {:>10.0} {:>9}",
        "capture (computed, sensor)", "-", "-", "-", capture.capture_ms, capture.capture_ms, "-"
    );
    for (stage, x86_ms) in stages {
        eprintln!(
            "{:<28} {:>12.1} {:>10.0} {:>11.0} {:>10.0} {:>10.0} {:>9.0}",
            stage.name,
            x86_ms,
            stage.memory_s() * 1e3,
            stage.compute_s() * 1e3,
            stage.seconds(1) * 1e3,
            stage.seconds(a9::CORES) * 1e3,
            x86_ms * OLD_X10
        );
    }
    eprintln!(
        "{:<28} {:>12.1} {:>10} {:>11} {:>10.0} {:>10.0} {:>9.0}",
        "processing",
        measured_ms,
        "",
        "",
        a9_one_core_s * 1e3,
        a9_processing_s * 1e3,
        measured_ms * OLD_X10
    );
    eprintln!(
        "{:<28} {:>12.0} {:>10} {:>11} {:>10.0} {:>10.0} {:>9.0}",
        "cycle, trigger to lux",
        capture.capture_ms + measured_ms,
        "",
        "",
        capture.capture_ms + a9_one_core_s * 1e3,
        capture.capture_ms + a9_processing_s * 1e3,
        capture.capture_ms + measured_ms * OLD_X10
    );
    eprintln!(
        "x86: measured on this machine, one core. capture: computed from the sensor timing. \
         A9: modelled (skylux_hps::timing::a9), max(memory, compute) per pass; 2 cores where \
         rayon spreads the work. Target {TARGET_CYCLE_S} s."
    );
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
            map: None,
            sun: None,
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
    words_per_frame: u32,
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
            hdr_map: false,
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
            // A9 model: `timing::a9::ring::UNPACK_PER_WORD`, 5 instructions a word.
            for (pair, w) in samples.chunks_exact_mut(2).zip(&c.words) {
                pair.copy_from_slice(&raw::samples(*w));
            }
        }
    });
    HpsRead {
        ms,
        transfer_bytes: 5 * u64::from(4 * payload_words),
        words_per_frame: payload_words,
    }
}

/// The processing of one cycle, timed on one core here, and the counts the A9 model takes from
/// the same data.
struct Processing {
    hdr_ms: f64,
    sun_ms: f64,
    dc_ms: f64,
    dc_sky_ms: f64,
    sky_patches: usize,
    hdr_work: HdrWork,
    sun_work: SunWork,
    sun_fabric: FabricSunCase,
    dc_sensors: usize,
    dc_bins: usize,
}

/// The sun from the accumulators on the bench's map: a disk at the lens's centre, as many
/// groups wide as the solar disk covers there plus one group of blur on either side, at a
/// hundred times the threshold, summed as the fabric would sum it; the background from the
/// ring around it in the merged map. The log-ramp map has no disk of its own (its bright end
/// is a third of the frame), and the work depends on the box's size, not on the values.
struct FabricSunCase {
    search: FabricSunSearch,
    exposure: SunExposure,
    config: SunConfig,
    sums: SunSums,
    /// Groups per side of the box.
    side: usize,
    /// The work of `fabric_background_cd_m2` (as `extraction_work` counts its ring).
    ring_box_groups: f64,
    ring_values: f64,
    /// The groups `FabricSun::with_limb` walks: the box dilated by two, less the box.
    limb_groups: f64,
    /// Measured here: the source's search and settings, the check, the background, the sun
    /// and its limb.
    ms: f64,
}

impl FabricSunCase {
    fn new(case: &HdrCase, map: &skylux_hps::hdr::LuminanceMap) -> anyhow::Result<Self> {
        let g = &case.geometry;
        let (w, h) = (g.width, g.height);
        let (cx, cy) = (w / 2, h / 2);
        let centre = g.direction[cy * w + cx].as_dvec3();
        let group_sr = f64::from(g.solid_angle_sr[cy * w + cx]);
        let side = (SOLAR_DISK_SR / group_sr).sqrt().ceil() as usize + 2;
        let exposure = SunExposure {
            exposure_s: EXPOSURES_S[0],
            gain: 1.0,
        };
        let search = FabricSunSearch::around(
            centre,
            skylux_hps::model::SUN_MAX_OFFSET_DEG,
            &case.camera,
            &case.readout,
        )
        .ok_or_else(|| anyhow::anyhow!("the lens's centre is outside the lens"))?;
        let config = search.config(&case.camera, &case.readout, (w, h), &exposure)?;
        let l = 100 * config.threshold_q14;
        let (x0, y0) = (cx - side / 2, cy - side / 2);
        let (x1, y1) = (x0 + side - 1, y0 + side - 1);
        let mut sums = SunSums {
            max_l: l,
            min_x: x0 as u16,
            max_x: x1 as u16,
            min_y: y0 as u16,
            max_y: y1 as u16,
            ..SunSums::default()
        };
        for y in y0..=y1 {
            for x in x0..=x1 {
                sums.count += 1;
                sums.sum_l += u64::from(l);
                sums.sum_xl += x as u64 * u64::from(l);
                sums.sum_yl += y as u64 * u64::from(l);
            }
        }
        check_sums(&config, &sums).map_err(|e| anyhow::anyhow!("the bench's sums: {e}"))?;
        // The ring `fabric_background_cd_m2` takes: 2 to 5 groups outside the box.
        let (mut ring_box_groups, mut ring_values) = (0.0, 0.0);
        for y in y0.saturating_sub(5)..=(y1 + 5).min(h - 1) {
            for x in x0.saturating_sub(5)..=(x1 + 5).min(w - 1) {
                ring_box_groups += 1.0;
                let i = y * w + x;
                let outside = x + 2 < x0 || x > x1 + 2 || y + 2 < y0 || y > y1 + 2;
                if outside && g.direction[i].is_finite() && map.flags[i] == MapFlag::Valid {
                    ring_values += 1.0;
                }
            }
        }
        let dilated =
            |lo: usize, hi: usize, n: usize| (hi + 2).min(n - 1) - lo.saturating_sub(2) + 1;
        let limb_groups = (dilated(x0, x1, w) * dilated(y0, y1, h) - side * side) as f64;
        Ok(Self {
            search,
            exposure,
            config,
            sums,
            side,
            ring_box_groups,
            ring_values,
            limb_groups,
            ms: 0.0,
        })
    }

    /// What the source and the cycle compute for one capture.
    fn run(&self, case: &HdrCase, map: &skylux_hps::hdr::LuminanceMap) -> f64 {
        let (w, h) = (case.geometry.width, case.geometry.height);
        let search = FabricSunSearch::around(
            self.search.predicted_direction,
            skylux_hps::model::SUN_MAX_OFFSET_DEG,
            &case.camera,
            &case.readout,
        );
        let config = search.map(|s| s.config(&case.camera, &case.readout, (w, h), &self.exposure));
        let checked = check_sums(&self.config, &self.sums).is_ok();
        let background = fabric_background_cd_m2(map, &case.geometry, &self.sums);
        let sun = sun_from_fabric(
            &self.sums,
            &self.search,
            &case.camera,
            &case.readout,
            &self.exposure,
            background,
        )
        .map(|s| s.with_limb(map, &case.geometry, &self.sums));
        std::hint::black_box((config, checked));
        sun.map_or(f64::NAN, |s| s.direct_normal_illuminance_lux)
    }
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
    let hdr_work = hdr_work(&case, &map);

    // Sun extraction on that map.
    let search = skylux_hps::sun::SunSearch::default();
    let sun_ms = median_ms(repeat, || {
        let _ = std::hint::black_box(
            one.install(|| skylux_hps::sun::extract_sun(&map, &case.geometry, &search)),
        );
    });
    let sun_work = skylux_hps::sun::extraction_work(&map, &case.geometry, &search);

    // The sun from the accumulators' sums, on the same map.
    let mut sun_fabric = FabricSunCase::new(&case, &map)?;
    let fabric_ms = median_ms(repeat.max(11), || {
        std::hint::black_box(sun_fabric.run(&case, &map));
    });
    sun_fabric.ms = fabric_ms;

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
        hdr_work,
        sun_work,
        sun_fabric,
        dc_sensors: dc.sensors.len(),
        dc_bins: dc.bins,
    })
}

/// The merge's work on the case: the (group, exposure) pairs with no sample out of range, as
/// the merge's own `group_row` flags them (the weights do not change the flags), and the
/// groups the map holds valid.
fn hdr_work(case: &HdrCase, map: &skylux_hps::hdr::LuminanceMap) -> HdrWork {
    let (width, height) = (case.geometry.width, case.geometry.height);
    let sensor = &case.device.sensor;
    let params = GroupParams {
        weight_at: [[0.25; 2]; 2],
        black: sensor.black_level_dn,
        valid_min: sensor.valid_min_dn,
        valid_max: sensor.valid_max_dn,
    };
    let (mut signal, mut over, mut under) =
        (vec![0.0; width], vec![false; width], vec![false; width]);
    let mut valid_pairs = 0usize;
    for frame in &case.frames {
        for gy in 0..height {
            frame.group_row(gy, &params, &mut signal, &mut over, &mut under);
            valid_pairs += over
                .iter()
                .zip(&under)
                .filter(|(o, u)| !(**o || **u))
                .count();
        }
    }
    HdrWork {
        groups: (width * height) as f64,
        exposures: case.frames.len() as f64,
        valid_pairs: valid_pairs as f64,
        valid_groups: map.flags.iter().filter(|f| **f == MapFlag::Valid).count() as f64,
    }
}
