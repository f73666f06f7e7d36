//! The fabric source on the cycle-accurate core (`skylux_sim::core_rig`: the whole fabric,
//! an MT9P031 model imaging the simulated sky through the declared camera, SDRAM models with
//! random back-pressure), driven through the same `FabricSource` as the board:
//!
//! - the frames it returns are the samples the sensor model put on its pins, bit for bit, and
//!   the exposure times it records are the sensor model's own exposure formula;
//! - `PollWait` ends with a timeout when the sensor is silent (held in reset);
//! - `skyluxd --sim` with `[sim] source = "fabric"` runs a cycle end to end, and its HDR map
//!   equals the offline merge (`hdr::map_capture`) of the frames it kept;
//! - with `[fabric] hdr = "fabric"` the fabric writes one map, equal to the golden model's
//!   selection over the frames the sensor sent, and `skyluxd` runs a cycle on it.
//!
//! The rust-hdl simulation runs 10^3 to 10^4 clocks a second here (1.3k measured on the shared
//! machine), so the window is 16 x 12 output pixels (skip 8) and the exposures a few rows, and
//! the two simulations of a whole capture are `#[ignore]`d (run them with `--ignored`). Native only: under qemu-arm the same
//! simulation is an order of magnitude slower, and the ARM build runs the driver code through
//! tests/tests/hps_driver_backends.rs.

#![cfg(not(target_arch = "arm"))]

mod common;

use common::*;
use skylux_hps::fpga::Fabric;
use skylux_sim::core_rig::{sim_core, CoreRigConfig};
use skylux_sim::mt9p031::timing::exposure_pixclk;
use skylux_sim::mt9p031::{FrameGeometry, Mt9p031, RampSource, ShutterOverhead};
use skyluxd::config::{Config, Overrides};
use skyluxd::fabric_source::sim_fabric_source;
use skyluxd::source::CaptureSource;
use skyluxd::wait::{FrameWait, PollWait, WaitError};
use std::sync::atomic::AtomicBool;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// ~1 min of simulation on an idle machine, several on a loaded one: `--ignored`.
#[test]
#[ignore = "slow cycle-accurate simulation: run with --ignored"]
fn fabric_frames_are_the_sensor_samples_and_exposures_the_sensor_formula() {
    let tmp = tempfile::tempdir().unwrap();
    let path = tiny_fabric_config(tmp.path(), "fabric");
    let config = Config::load(&path, &Overrides::default()).unwrap();
    let (device, _) = skylux_hps::camera::DeviceConfig::read(&config.camera.device).unwrap();
    let stop = Arc::new(AtomicBool::new(false));
    let mut source = sim_fabric_source(&config, &device, stop).unwrap();
    let at = chrono::DateTime::parse_from_rfc3339("2017-05-08T12:00:00+02:00").unwrap();
    let began = Instant::now();
    let set = source.capture(at).unwrap();
    let clocks = source.rig.lock().unwrap().sys_cycles();
    eprintln!(
        "one 2-exposure capture: {clocks} simulated clocks in {:.1} s",
        began.elapsed().as_secs_f64()
    );
    assert_eq!(set.frames.len(), 2);
    assert!(
        set.frame_flags.iter().all(Vec::is_empty),
        "{:?}",
        set.frame_flags
    );
    let rig = source.rig.lock().unwrap();
    assert_eq!(rig.log.frames.len(), 2, "one sensor frame per exposure");
    for (k, (got, sent)) in set.frames.iter().zip(&rig.log.frames).enumerate() {
        assert_eq!((got.width, got.height), (16, 12), "frame {k}");
        assert_eq!(
            got, sent,
            "frame {k}: DMA payload differs from the sensor's samples"
        );
    }
    // Brighter with a longer exposure (the sky is not saturated at 100 rows).
    let mean = |f: &skylux_hps::campaign::RawFrame| {
        f.samples_dn.iter().map(|&v| f64::from(v)).sum::<f64>() / f.samples_dn.len() as f64
    };
    assert!(mean(&set.frames[1]) > mean(&set.frames[0]));
    // The exposure times recorded are the sensor model's formula (variant A) for the shutter
    // widths the sequencer wrote, at 96 MHz.
    let geometry = FrameGeometry::from_registers(&rig.sensor.registers);
    assert_eq!((geometry.width, geometry.height), (16, 12));
    for (k, (slot, e)) in source
        .inner
        .plan()
        .slots
        .iter()
        .zip(&set.config.exposure)
        .enumerate()
    {
        let model = exposure_pixclk(
            &geometry,
            slot.shutter_width_rows,
            0,
            ShutterOverhead::VariantA,
        ) as f64
            / 96e6
            * 1e6;
        assert!(
            (e.exposure_us - model).abs() < 1e-9,
            "exposure {k}: {} µs recorded, {model} µs by the model",
            e.exposure_us
        );
    }
    assert_eq!(set.config.readout.skip, 8);
}

#[test]
fn poll_wait_times_out_when_the_sensor_is_silent() {
    // The rig has no "silent sensor" switch: a sensor held in reset sends nothing.
    let sensor = Mt9p031::new(Box::new(RampSource), 96e6);
    let capture = skylux_hps::fpga::CaptureConfig::fitted(16, 8, 0x3000_0000, 1);
    let (shared, regs, _memory, _raybox) = sim_core(
        sensor,
        CoreRigConfig::new(capture.window_size_bytes as usize + 4096, 4096, 0.0),
    );
    let mut fabric = Fabric::bring_up(regs).unwrap();
    fabric.capture_configure(&capture).unwrap();
    let start = fabric.frames_written().unwrap();
    let mut wait = PollWait {
        max_polls: 2_000,
        pause: Duration::ZERO,
    };
    let stop = AtomicBool::new(false);
    let began = Instant::now();
    match wait.wait_frames(&mut fabric, start, 1, Duration::from_secs(60), &stop) {
        Err(WaitError::Timeout {
            received: 0,
            expected: 1,
            ..
        }) => {}
        other => panic!("{other:?}"),
    }
    assert!(began.elapsed() < Duration::from_secs(30));
    let rig = shared.lock().unwrap();
    assert!(rig.log.frames.is_empty() && !rig.log.reset_released);
    // The bound is what ended it: 2000 polls of a few simulated clocks each.
    assert!(rig.sys_cycles() >= 2_000, "{}", rig.sys_cycles());
}

/// ~1 min of simulation plus the daylight coefficients: `--ignored`.
#[test]
#[ignore = "slow cycle-accurate simulation: run with --ignored"]
fn skyluxd_runs_a_cycle_on_the_simulated_fabric_and_its_map_is_the_offline_merge() {
    // The bare camera: behind the example's ND filter the tiny window's sky is under-range.
    let (tmp, out, r) = one_noon_cycle(tiny_bare_camera_config);
    assert_eq!(r["time"], "2017-05-08T12:00:00+02:00");
    assert!(r["durations_ms"]["capture_ms"].as_f64().unwrap() > 0.0);

    // The kept capture, merged offline with the same (bare) camera, is the daemon's map.
    let capture_dir = out.join(r["capture"].as_str().unwrap());
    let (device, _) =
        skylux_hps::camera::DeviceConfig::read(&tmp.path().join("device.toml")).unwrap();
    let offline = skylux_hps::hdr::map_capture(&capture_dir, &device).unwrap();
    let (daemon_map, _, _) =
        skylux_hps::hdr::read_exr(&out.join(r["map"].as_str().unwrap())).unwrap();
    let a = &offline.map.luminance_cd_m2;
    let b = &daemon_map.luminance_cd_m2;
    assert_eq!(a.len(), b.len());
    assert_eq!(a.len(), 8 * 6);
    let mut compared = 0;
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        if x.is_finite() && *x > 0.0 {
            // The EXR stores f32.
            assert!(
                (f64::from(*y) / f64::from(*x) - 1.0).abs() < 1e-6,
                "group {i}: {y} vs {x}"
            );
            compared += 1;
        }
    }
    assert_eq!(offline.map.flags, daemon_map.flags);
    assert!(
        compared >= 4,
        "{compared} groups compared, flags {:?}",
        offline.map.flags
    );
}

/// The tiny configuration with the fabric making the map ([`tiny_bare_camera_config`]).
fn tiny_map_config(dir: &std::path::Path) -> std::path::PathBuf {
    let path = tiny_bare_camera_config(dir);
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(
        text.contains("hdr = \"hps\" "),
        "tiny_fabric_config's [fabric] hdr line"
    );
    let text = text.replacen("hdr = \"hps\" ", "hdr = \"fabric\" ", 1);
    std::fs::write(&path, text).unwrap();
    path
}

/// The tiny fabric configuration with a camera without the example device's ND 1.0 filter
/// (`cg` 1 instead of 10) and with `valid_min` at 10 DN instead of 40: with the example's,
/// the tiny window's sky stays under-range at 1000 µs (2 to 6 DN), so no group would be
/// usable; with these, the 1000 µs frame's groups (8 to 60 DN) mostly are and the 300 µs
/// frame's mostly are not.
fn tiny_bare_camera_config(dir: &std::path::Path) -> std::path::PathBuf {
    let path = tiny_fabric_config(dir, "fabric");
    // The path as `config_with` writes it.
    let example = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join("daemon/device.toml");
    let device = std::fs::read_to_string(&example).unwrap();
    assert!(
        device.contains("cg = 10.0 "),
        "the example device's cg line"
    );
    let bare = dir.join("device.toml");
    assert!(
        device.contains("valid_min_dn = 40.0"),
        "the example device's valid_min line"
    );
    let device = device.replacen("cg = 10.0 ", "cg = 1.0 ", 1).replacen(
        "valid_min_dn = 40.0",
        "valid_min_dn = 10.0",
        1,
    );
    std::fs::write(&bare, device).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let quoted = format!("\"{}\"", example.display());
    assert!(text.contains(&quoted), "the configuration's device path");
    let text = text.replacen(&quoted, &format!("\"{}\"", bare.display()), 1);
    std::fs::write(&path, text).unwrap();
    path
}

/// ~1 min of simulation: `--ignored`.
#[test]
#[ignore = "slow cycle-accurate simulation: run with --ignored"]
fn the_fabric_map_is_the_golden_selection_of_the_sensor_frames() {
    let tmp = tempfile::tempdir().unwrap();
    let config = Config::load(&tiny_map_config(tmp.path()), &Overrides::default()).unwrap();
    let (device, _) = skylux_hps::camera::DeviceConfig::read(&config.camera.device).unwrap();
    let stop = Arc::new(AtomicBool::new(false));
    let mut source = sim_fabric_source(&config, &device, stop).unwrap();
    let at = chrono::DateTime::parse_from_rfc3339("2017-05-08T12:00:00+02:00").unwrap();
    let set = source.capture(at).unwrap();
    assert!(set.frames.is_empty(), "a map, not frames");
    assert_eq!(set.frame_flags, vec![Vec::<String>::new()]);
    let m = set.fabric_map.as_ref().expect("the fabric's map");
    assert_eq!(
        (m.map.width, m.map.height, m.raw_width, m.raw_height),
        (8, 6, 16, 12)
    );
    // Long to short: the configuration's [300, 1000] µs run as 1000 then 300.
    let e: Vec<f64> = set.config.exposure.iter().map(|e| e.exposure_us).collect();
    assert!(e.len() == 2 && e[0] > e[1], "{e:?}");

    let rig = source.rig.lock().unwrap();
    assert_eq!(rig.log.frames.len(), 2);
    let golden = golden_map(&device, &m.hdr, &rig.log.frames);
    let summary: Vec<(u8, bool, bool, u32)> = m
        .map
        .words
        .iter()
        .map(|&w| {
            use skylux_regmap::words::hdr_map;
            (
                hdr_map::exposure_index(w),
                hdr_map::under(w),
                hdr_map::over(w),
                hdr_map::luma_q11(w),
            )
        })
        .collect();
    eprintln!("map words (exposure, under, over, luma_q11): {summary:?}");
    assert_eq!(m.map.words, golden);
    // The case exercises the selection: groups usable in the longest exposure, and groups
    // the set's last frame wrote.
    let from_longest = summary.iter().filter(|w| w.0 == 0).count();
    assert!(
        from_longest > 0 && from_longest < summary.len(),
        "groups from the longest exposure: {from_longest} of {}",
        summary.len()
    );
}

/// ~1 min of simulation plus the daylight coefficients: `--ignored`.
#[test]
#[ignore = "slow cycle-accurate simulation: run with --ignored"]
fn skyluxd_runs_a_cycle_on_the_fabric_map() {
    let (_tmp, out, r) = one_noon_cycle(tiny_map_config);
    // No raw frames to keep; the map the cycle made is written.
    assert!(r["capture"].is_null(), "{r}");
    let (map, _, _) = skylux_hps::hdr::read_exr(&out.join(r["map"].as_str().unwrap())).unwrap();
    assert_eq!(map.luminance_cd_m2.len(), 8 * 6);
    assert!(
        map.flags.contains(&skylux_hps::hdr::MapFlag::Valid),
        "{:?}",
        map.flags
    );
}

/// One skyluxd cycle at noon on `config(dir)`'s fabric: its scratch folder, output folder
/// and the cycle's record, whose five sensors read finite, non-negative lux.
fn one_noon_cycle(
    config: impl FnOnce(&std::path::Path) -> std::path::PathBuf,
) -> (tempfile::TempDir, std::path::PathBuf, serde_json::Value) {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("out");
    let log = tmp.path().join("stderr.log");
    let config = config(tmp.path());
    let mut child = start(
        &SimRun::new(&config, &out)
            .cycles(1)
            .clock("2017-05-08T12:00:00+02:00", 3600)
            .args(),
        &log,
    );
    let status = wait(&mut child, Duration::from_secs(900));
    let text = std::fs::read_to_string(&log).unwrap();
    assert_eq!(status.code(), Some(0), "{text}");
    let lines = complete_lines(&out.join("results.jsonl"));
    assert_eq!(lines.len(), 1, "{text}");
    let r: serde_json::Value = serde_json::from_str(&lines[0]).unwrap();
    assert_eq!(r["source"], "fabric-sim");
    let lux: Vec<f64> = r["illuminance"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["lux"].as_f64().unwrap())
        .collect();
    assert_eq!(lux.len(), 5);
    assert!(lux.iter().all(|l| l.is_finite() && *l >= 0.0), "{lux:?}");
    (tmp, out, r)
}
