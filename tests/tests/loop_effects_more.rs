//! The rest of the effect library (issue 9) on simulated campaigns with the effect present in
//! the world and not declared: the loop must name it, fit its parameter within the stated
//! tolerance of the truth, and cut the hold-out error to at most a third of before or to the
//! noise floor of the same campaign without the effect. Also: the loop runs on a partly
//! cloudy day whose light changes from minute to minute, and adds nothing when nothing is
//! missing.
//!
//! Test bed: tests/common/loop_harness.rs.

mod common;

use common::loop_harness::{
    assert_improved, assert_improved_against, effect, run, simulate, simulate_spec, spec_with_sky,
};
use skylux_hps::campaign::Campaign;
use skylux_sim::campaign::DaySky;
use std::sync::OnceLock;

/// Two partly cloudy days without effects: clouds pass over the sun within minutes and the
/// lux-meters log every 30 s around each capture.
fn partly_clean() -> &'static (tempfile::TempDir, Campaign) {
    static CLEAN: OnceLock<(tempfile::TempDir, Campaign)> = OnceLock::new();
    CLEAN.get_or_init(|| {
        let dir = tempfile::tempdir().unwrap();
        let c = simulate_spec(dir.path(), &spec_with_sky(&[], 81, Some(DaySky::Partly)));
        (dir, c)
    })
}

fn partly_floor() -> f64 {
    static FLOOR: OnceLock<f64> = OnceLock::new();
    *FLOOR.get_or_init(|| run(&partly_clean().1, false).report.after.all)
}

/// `--sky partly`: the light changes within minutes (the logged series shows it), and the
/// loop runs on it without adding an effect that is not there.
#[test]
#[ignore = "long: the loop on a further campaign; CI runs its short form, scripts/long-tests all"]
fn partly_cloudy_sky_changes_within_minutes_and_the_loop_runs_on_it() {
    let c = &partly_clean().1;
    // Some reading changes by more than 30 % from one 30 s log to the next: the sun comes
    // and goes (a clear sky changes by well under 1 % in 30 s).
    let mut by_sensor: std::collections::BTreeMap<
        &str,
        Vec<(chrono::DateTime<chrono::FixedOffset>, f64)>,
    > = Default::default();
    for r in &c.luxmeters {
        by_sensor
            .entry(&r.sensor)
            .or_default()
            .push((r.time, r.illuminance_lux));
    }
    let mut jumps = 0;
    for v in by_sensor.values_mut() {
        v.sort_by_key(|p| p.0);
        for w in v.windows(2) {
            let dt = (w[1].0 - w[0].0).num_seconds();
            if dt <= 30 && (w[1].1 / w[0].1 - 1.0).abs() > 0.3 {
                jumps += 1;
            }
        }
    }
    println!("{jumps} jumps of more than 30 % within 30 s");
    assert!(jumps >= 10, "{jumps}");
    let r = run(c, false).report;
    println!("partly cloudy: hold-out {:.2} %", 100.0 * r.after.all);
    assert!(
        !r.effects.iter().any(|e| e.name == "clock_offset"),
        "{:#?}",
        r.effects
    );
    // The device model follows the changing sky: a few percent.
    assert!(r.after.all < 0.08, "{}", r.after.all);
}

/// The logger's clock runs 120 s ahead of the device's on a partly cloudy day: the loop finds
/// the offset to within 20 s from the fit set. The tolerance is what the data can pin: a
/// reading matches its capture equally well anywhere in the sunny or shaded spell around the
/// capture, so only the cloud edges nearest the fit captures (a few to some 90 s away)
/// determine the offset.
#[test]
#[ignore = "long: the loop on a further campaign; CI runs its short form, scripts/long-tests all"]
fn clock_offset() {
    let dir = tempfile::tempdir().unwrap();
    let c = simulate_spec(
        dir.path(),
        &spec_with_sky(&["clock_offset=120"], 81, Some(DaySky::Partly)),
    );
    let r = run(&c, false).report;
    println!(
        "before {:?}\nafter {:?}\nrejected {:?}",
        r.before, r.after, r.rejected
    );
    let e = effect(&r, "clock_offset");
    let dt = e.parameters["logger_minus_device_s"];
    println!("clock offset {dt} s; {}", e.evidence);
    assert!((dt - 120.0).abs() <= 20.0, "{dt}");
    assert!(e.evidence.contains("rate of change"), "{}", e.evidence);
    assert_improved_against(&r, partly_floor());
}

/// Every frame integrates 0.5 µs longer than `capture.toml` declares: the 1 µs frame that
/// measures the sun is 1.5 times brighter than the merge assumes. The loop re-merges with a
/// fitted overhead and finds it within 0.15 µs. (With several µs the sun saturates even the
/// shortest frame and is not extracted at all: that case is not in the library yet.)
#[test]
#[ignore = "long: the loop on a further campaign; CI runs its short form, scripts/long-tests all"]
fn shutter_overhead() {
    let dir = tempfile::tempdir().unwrap();
    let r = run(&simulate(dir.path(), &["shutter_overhead=0.5"], 91), false).report;
    println!(
        "before {:?}\nafter {:?}\nrejected {:?}\nnotes {:?}\neffects {:?}",
        r.before, r.after, r.rejected, r.notes, r.effects
    );
    let e = effect(&r, "shutter_overhead");
    let t0 = e.parameters["overhead_us"];
    println!("overhead {t0} µs; {}", e.evidence);
    assert!((t0 - 0.5).abs() <= 0.15, "{t0}");
    assert_improved(&r);
}
