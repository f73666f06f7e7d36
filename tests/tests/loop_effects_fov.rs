//! The sky effects of the library (issue 9): the lens's relative illumination steeper than
//! `device.toml` declares (`vignetting`), and a baffle that clips the field of view
//! (`sky_outside_fov`), each present in the simulated world and not declared. The loop must
//! name the effect, fit its parameter within the stated tolerance of the truth, and cut the
//! hold-out error to at most a third of before or to the noise floor of the same campaign
//! (same seed) without the effect.
//!
//! Test bed: tests/common/loop_harness.rs.

mod common;

use common::loop_harness::{assert_improved, effect, run, simulate};

/// The harness's clean campaign's seed: the same noise, with and without the effect.
const SEED: u64 = 11;

/// The true fall-off is the declared polynomial times 1 − 0.4 (α/90°)²: 16 % darker at 60°
/// off-axis. The hold-out error is 5.4 % before. The fit lands at 0.36 (the light the model
/// takes from the extrapolated sky beyond the field keeps part of the fall-off), so the
/// tolerance is 0.06.
#[test]
fn vignetting() {
    let dir = tempfile::tempdir().unwrap();
    let r = run(&simulate(dir.path(), &["vignetting=0.4"], SEED), false).report;
    println!(
        "before {:?}\nafter {:?}\nrejected {:?}\neffects {:?}",
        r.before, r.after, r.rejected, r.effects
    );
    let e = effect(&r, "vignetting");
    let v = e.parameters["extra_vignetting"];
    println!("extra vignetting {v}; {}", e.evidence);
    assert!((v - 0.4).abs() <= 0.06, "{v}");
    assert!(e.evidence.contains("off the lens's axis"), "{}", e.evidence);
    assert!(r.before.all > 0.04, "{}", r.before.all);
    assert_improved(&r);
}

/// A baffle darkens the image beyond 52° off-axis (the readout itself reaches 65°
/// horizontally and 82° in the corners). At 70° or 80° nothing the room sees is lost (the
/// hold-out error stays at the clean campaign's 1.6 %); at 52° the sun at 10:00 and 16:00 of
/// the clear day is beyond the field, the model misses its direct light (−12 to −17 %), and
/// the hold-out error is 3.7 %. The loop reads the field the maps show within 1.5° of the
/// baffle's, and fills the sun beyond it from the pyranometer.
#[test]
fn sky_outside_fov() {
    let dir = tempfile::tempdir().unwrap();
    let r = run(&simulate(dir.path(), &["fov_limit_deg=52"], SEED), false).report;
    println!(
        "before {:?}\nafter {:?}\nrejected {:?}\neffects {:?}",
        r.before, r.after, r.rejected, r.effects
    );
    let e = effect(&r, "sky_outside_fov");
    let fov = e.parameters["field_of_view_deg"];
    println!(
        "field of view {fov}°, unseen sky factor {}; {}",
        e.parameters["unseen_sky_factor"], e.evidence
    );
    assert!((fov - 52.0).abs() <= 1.5, "{fov}");
    assert!(e.evidence.contains("baffle"), "{}", e.evidence);
    assert!(r.before.all > 0.03, "{}", r.before.all);
    assert_improved(&r);
}
