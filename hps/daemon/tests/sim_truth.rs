//! Issue 24: the daemon's numbers against the simulated world's own truth, not against the
//! offline pipeline (which shares its functions). The example configuration (a whole-sky
//! camera on the roof, read out binned 4 x 4 so every sample keeps its pixels' light) over a
//! May day in Lausanne, clear and overcast. The world's truth is computed without any step of
//! the measurement: the Perez sky's own horizontal illuminance, and the room traced directly
//! under the world's sky and sun (`skyluxd::interior_truth`).
//!
//! Before issue 24 the example read the sky with `skip = 16` (one pixel in 256) into groups ten
//! times the solar disk's solid angle: the disk was diluted under the threshold, never
//! extracted, and spread over whole sky patches: 200-450 klx at noon (+130 % to +390 %), and
//! the camera, facing south, never saw the morning and evening sun. Both fail these bounds.

mod common;

use common::*;
use std::time::Duration;

/// Issue 24: outdoor horizontal illuminance within 5 % of the world in every cycle with the
/// sun above 10°. Held here wherever the world shows a sun (above 3°): with a low sun the
/// twilight sky is what a short ladder loses (under the floor, its patches filled from the
/// brighter ones: 2.6 times the world at 4° before the long exposure's gain) and what the
/// patch-centre cosine misjudges (the sky's 145-point sum).
const OUTDOOR_TOLERANCE: f64 = 0.05;
/// The world shows a sun, and a lit sky, above this altitude (`skyluxd::source`).
const WORLD_SUN_MIN_ALTITUDE_DEG: f64 = 3.0;
/// Issue 24: interior illuminance per sensor within 5 % of the world, median over the day.
const INTERIOR_MEDIAN_TOLERANCE: f64 = 0.05;

/// The records of a simulated day: `cycles` captures `step_s` apart from `start`.
fn simulated_day(sky: &str, start: &str, step_s: u64, cycles: u64) -> Vec<serde_json::Value> {
    let sky_line = format!("sky = \"{sky}\"");
    run(&[("sky = \"clear\"", &sky_line)], start, step_s, cycles)
}

/// The records of the example configuration changed by `replace`.
fn run(replace: &[(&str, &str)], start: &str, step_s: u64, cycles: u64) -> Vec<serde_json::Value> {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("out");
    let log = tmp.path().join("stderr.log");
    let config = config_with(tmp.path(), replace, "");
    sim_records(
        &config,
        &out,
        &log,
        (start, step_s),
        cycles,
        Duration::from_secs(600),
    )
}

/// Outdoor, sun and interior of one day's records against the world.
fn check_day(records: &[serde_json::Value], clear: bool) {
    let (mut sun_in_view, mut extracted) = (0, 0);
    let mut off = vec![];
    for r in records {
        let time = r["time"].as_str().unwrap();
        let sun = &r["sun"];
        let altitude = sun["spa_altitude_deg"].as_f64().unwrap();
        let measured = r["outdoor_horizontal_lux"].as_f64().unwrap();
        let truth = r["truth_outdoor_horizontal_lux"].as_f64().unwrap();
        let flags: Vec<&str> = sun["flags"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f.as_str().unwrap())
            .collect();
        println!(
            "{time}: sun {altitude:5.1} deg, measured {measured:8.0} lux, world {truth:8.0} lux, \
             extracted {}, flags {flags:?}, plausibility {}",
            sun["extracted"], r["plausibility"]
        );
        assert!(
            r.get("plausibility").is_none(),
            "{time}: flagged implausible: {}",
            r["plausibility"]
        );
        if altitude > WORLD_SUN_MIN_ALTITUDE_DEG
            && (measured / truth - 1.0).abs() >= OUTDOOR_TOLERANCE
        {
            off.push(format!(
                "{time}: measured {measured:.0} lux, the world {truth:.0} lux"
            ));
        }
        let extracted_now = sun["extracted"].as_bool().unwrap();
        if !extracted_now {
            assert!(!flags.is_empty(), "{time}: no sun and no reason");
            assert!(
                sun["missing_reason"]
                    .as_str()
                    .is_some_and(|s| !s.is_empty()),
                "{time}: no sun and no reason in words"
            );
            if altitude <= 0.0 {
                assert_eq!(flags, ["no_sun:below_horizon"], "{time}");
            }
        }
        // The whole-sky lens sees the sun whenever the world shows one (above 3°).
        if clear && altitude > WORLD_SUN_MIN_ALTITUDE_DEG {
            sun_in_view += 1;
            extracted += usize::from(extracted_now);
        } else if !clear && altitude > 0.0 {
            assert!(
                !extracted_now,
                "{time}: a sun extracted from an overcast sky"
            );
        }
    }
    assert!(
        off.is_empty(),
        "more than {OUTDOOR_TOLERANCE} from the world: {off:#?}"
    );
    if clear {
        assert!(
            extracted * 100 >= 95 * sun_in_view,
            "the sun extracted in {extracted} of {sun_in_view} clear cycles with it in view"
        );
    }
    let medians = interior_median_errors(records);
    println!("interior, median of measured / world - 1: {medians:?}");
    for (name, e) in medians {
        assert!(
            e.abs() < INTERIOR_MEDIAN_TOLERANCE,
            "{name}: the interior's median error is {:+.1} %",
            100.0 * e
        );
    }
}

#[test]
fn a_clear_day_reads_as_the_simulated_world_and_every_missing_sun_says_why() {
    // 05:00 to 21:40 local, every 40 minutes: sunrise to sunset and the night either side.
    let records = simulated_day("clear", "2017-05-08T05:00:00+02:00", 2400, 26);
    check_day(&records, true);
}

#[test]
fn an_overcast_day_reads_as_the_simulated_world() {
    let records = simulated_day("overcast", "2017-05-08T06:20:00+02:00", 3600, 14);
    check_day(&records, false);
}

/// A readout that skips pixels without binning (skip 8: one pixel in 64) cannot measure the
/// disk: the sun is flagged `undersampled` with its reason, and kept out of the sky, so the
/// outdoor value is the sky's alone (below the world's, never a disk spread over a group).
/// Before issue 24 such a readout read 200-450 klx at noon.
#[test]
fn a_skipping_readout_flags_the_sun_instead_of_integrating_it_as_a_group() {
    let records = run(
        &[("skip = 4 ", "skip = 8 "), ("bin = 4 ", "bin = 1 ")],
        "2017-05-08T12:00:00+02:00",
        1800,
        3,
    );
    for r in &records {
        let time = r["time"].as_str().unwrap();
        let measured = r["outdoor_horizontal_lux"].as_f64().unwrap();
        let truth = r["truth_outdoor_horizontal_lux"].as_f64().unwrap();
        println!(
            "{time}: measured {measured:.0} lux, world {truth:.0} lux, sun {}",
            r["sun"]
        );
        assert_eq!(r["sun"]["extracted"], false, "{time}");
        assert_eq!(
            r["sun"]["flags"],
            serde_json::json!(["no_sun:undersampled"]),
            "{time}"
        );
        assert!(
            r["sun"]["missing_reason"]
                .as_str()
                .is_some_and(|s| s.contains("binned")),
            "{time}: {}",
            r["sun"]
        );
        assert!(
            measured < truth,
            "{time}: {measured} lux above the world's {truth}"
        );
        assert!(
            r.get("plausibility").is_none(),
            "{time}: {}",
            r["plausibility"]
        );
    }
}
