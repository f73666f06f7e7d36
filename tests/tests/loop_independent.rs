//! The loop on worlds it was not tuned for (issue 18's four cases): a room, a site and days
//! drawn by the battery generator (`skylux_sim::battery`, seed 1818: not the reference room,
//! not Lausanne), the lux-meters' truth from RADIANCE's daylight coefficients (rcontrib, not
//! Skylux's engine), one or two undeclared effects at magnitudes the library's own tests never
//! used. RADIANCE comes from the pyradiance wheel (`pip install pyradiance`), as CI installs
//! it; without it the simulation fails with an error that says so.
//!
//! All four pass since the acceptance became the projection test over every hold-out reading
//! (`scoring::judge_projection`), the clouds aperiodic, the model's bounces converged and the
//! pairs led by a nuisance (docs/loop.md). They take about 3.5 minutes of two cores.

mod common;

use common::loop_harness::run;
use skylux_hps::campaign::Campaign;
use skylux_hps::validation::report::Report;
use skylux_sim::battery::{battery_campaigns, BatteryCase};
use skylux_sim::campaign::simulate_campaign;

/// The independent world: the generator's first case without effects, with `effects` put in
/// and, where the clock must be followed, broken clouds on every day.
fn world(effects: &[(&'static str, f64)], partly: bool) -> (tempfile::TempDir, Campaign) {
    let mut case: BatteryCase = battery_campaigns(12, 1818)
        .into_iter()
        .find(|c| c.class == "none")
        .expect("the battery has cases without effects");
    case.effects = effects.to_vec();
    if partly {
        case.make_partly_cloudy();
    }
    let dir = tempfile::tempdir().expect("temp dir");
    let room = dir.path().join("room-src");
    case.write_room(&room).expect("room written");
    let spec = case.spec(room).expect("campaign spec");
    let out = dir.path().join("campaign");
    simulate_campaign(&out, &spec, &|_, _| {}).expect("simulated campaign (needs RADIANCE)");
    let campaign = Campaign::open(&out).expect("campaign reads back");
    (dir, campaign)
}

fn named(r: &Report) -> Vec<&str> {
    r.effects.iter().map(|e| e.name.as_str()).collect()
}

fn parameter(r: &Report, effect: &str, name: &str) -> f64 {
    let e = r
        .effects
        .iter()
        .find(|e| e.name == effect)
        .unwrap_or_else(|| panic!("{effect} not named: {:?}", named(r)));
    e.parameters[name]
}

#[test]
#[ignore = "long: the loop on a further campaign; CI runs its short form, scripts/long-tests all"]
fn a_seven_minute_logger_clock_offset_is_fitted_within_30_s() {
    let (_dir, campaign) = world(&[("clock_offset", 420.0)], true);
    let r = run(&campaign, false).report;
    assert_eq!(named(&r), ["clock_offset"]);
    let fitted = parameter(&r, "clock_offset", "logger_minus_device_s");
    assert!(
        (fitted - 420.0).abs() <= 30.0,
        "fitted {fitted} s for 420 s"
    );
    assert!(
        r.after.all <= 0.5 * r.before.all,
        "{:?} → {:?}",
        r.before,
        r.after
    );
}

#[test]
#[ignore = "long: the loop on a further campaign; CI runs its short form, scripts/long-tests all"]
fn a_clock_offset_with_dirty_glazing_are_both_found() {
    let (_dir, campaign) = world(
        &[("clock_offset", 420.0), ("glazing_transmittance", 0.85)],
        true,
    );
    let r = run(&campaign, false).report;
    let clock = parameter(&r, "clock_offset", "logger_minus_device_s");
    let tau = parameter(&r, "glazing_transmittance", "relative_transmittance");
    assert!((clock - 420.0).abs() <= 30.0, "clock {clock} s for 420 s");
    assert!((tau - 0.85).abs() <= 0.03, "transmittance {tau} for 0.85");
    assert!(
        r.after.all <= 0.5 * r.before.all,
        "{:?} → {:?}",
        r.before,
        r.after
    );
}

/// A 9 µs overhead saturates the sun's core in every frame wherever it is high; the groups
/// at the sun's edge, valid in the 1 µs and 26.6 µs frames both, read (26.6 + 9) / (1 + 9)
/// apart instead of 26.6: the overhead, with no lux-meter involved. The hold-out error it
/// causes, over that of the same world without it (the model's own against RADIANCE, some 2 %
/// here), is at least halved: the loop need not absorb the model's error to show that.
#[test]
#[ignore = "long: the loop on a further campaign; CI runs its short form, scripts/long-tests all"]
fn a_9_us_shutter_overhead_is_named_as_such_and_not_as_vignetting() {
    let (_dir, campaign) = world(&[("shutter_overhead", 9.0)], false);
    let r = run(&campaign, false).report;
    let names = named(&r);
    assert!(names.contains(&"shutter_overhead"), "{names:?}");
    assert!(!names.contains(&"vignetting"), "{names:?}");
    let t0 = parameter(&r, "shutter_overhead", "overhead_us");
    assert!((t0 - 9.0).abs() <= 1.0, "overhead {t0} µs for 9 µs");
    let (_plain_dir, plain) = world(&[], false);
    let floor = run(&plain, false).report.before.all;
    assert!(
        r.after.all - floor <= 0.5 * (r.before.all - floor),
        "{:?} → {:?}, without the overhead {floor}",
        r.before,
        r.after
    );
}

#[test]
fn a_world_without_effects_gets_none() {
    let (_dir, campaign) = world(&[], false);
    let r = run(&campaign, false).report;
    assert!(r.effects.is_empty(), "{:?}: {:#?}", named(&r), r.effects);
    assert_eq!(r.before, r.after);
}
