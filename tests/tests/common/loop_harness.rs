//! The loop's test bed, shared by `loop_effects.rs` and `loop_effects_more.rs`: simulated
//! campaigns in the reference room in Lausanne with undeclared effects, the loop run on them
//! with small settings, and the acceptance rule (hold-out error after at most a
//! third of before, or at the noise floor of the same campaign without effects).
//!
//! Campaigns: a clear and an overcast day (or the given sky on both), captures every hour
//! from 8:00 to 18:00 at a quarter of the full resolution (skip 4), lux-meters with
//! 1 % noise.
#![allow(dead_code)]

use skylux_hps::campaign::Campaign;
use skylux_hps::validation::illuminance_loop::{run_loop, LoopOptions, LoopOutcome};
use skylux_hps::validation::report::{EffectReport, Report};
use skylux_sim::campaign::{simulate_campaign, CampaignSpec, DaySky};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

pub const ROOM: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../shared/scenes/test-module"
);

/// The test campaign with `effects` (`NAME=VALUE`), on the demo's two days or with `sky` on
/// both.
pub fn spec_with_sky(effects: &[&str], seed: u64, sky: Option<DaySky>) -> CampaignSpec {
    let mut spec = CampaignSpec::lausanne(PathBuf::from(ROOM));
    spec.hours = (8..=18).map(f64::from).collect();
    spec.truth_samples = 16_384;
    spec.seed = seed;
    if let Some(sky) = sky {
        for d in &mut spec.days {
            d.1 = sky;
        }
    }
    for e in effects {
        spec.effects.set(e).unwrap();
    }
    spec
}

pub fn spec(effects: &[&str], seed: u64) -> CampaignSpec {
    spec_with_sky(effects, seed, None)
}

pub fn simulate_spec(dir: &Path, spec: &CampaignSpec) -> Campaign {
    simulate_campaign(dir, spec, &|_, _| {}).expect("simulated campaign");
    Campaign::open(dir).expect("campaign reads back")
}

pub fn simulate(dir: &Path, effects: &[&str], seed: u64) -> Campaign {
    simulate_spec(dir, &spec(effects, seed))
}

pub fn run(campaign: &Campaign, sun_in_map: bool) -> LoopOutcome {
    let mut options = LoopOptions::default();
    options.base.model.concentrated_sun = !sun_in_map;
    options.settings.samples_per_sensor = 30_000;
    run_loop(campaign, &options, &|_, _, _| {}).expect("loop")
}

pub fn effect<'a>(r: &'a Report, name: &str) -> &'a EffectReport {
    r.effects
        .iter()
        .find(|e| e.name == name)
        .unwrap_or_else(|| panic!("{name} not found; report: {r:#?}"))
}

/// The campaign without effects, shared: its hold-out error is the noise floor.
pub fn clean() -> &'static (tempfile::TempDir, Campaign) {
    static CLEAN: OnceLock<(tempfile::TempDir, Campaign)> = OnceLock::new();
    CLEAN.get_or_init(|| {
        let dir = tempfile::tempdir().unwrap();
        let c = simulate(dir.path(), &[], 11);
        (dir, c)
    })
}

pub fn noise_floor() -> f64 {
    static FLOOR: OnceLock<f64> = OnceLock::new();
    *FLOOR.get_or_init(|| run(&clean().1, false).report.after.all)
}

/// Hold-out after at most a third of before, or within 1.25x `floor_error` (the hold-out
/// error of a campaign without effects under the same sky).
pub fn assert_improved_against(r: &Report, floor_error: f64) {
    let floor = 1.25 * floor_error;
    println!(
        "hold-out: before {:.2} %, after {:.2} %, floor {:.2} %",
        100.0 * r.before.all,
        100.0 * r.after.all,
        100.0 * floor
    );
    assert!(
        r.after.all <= r.before.all / 3.0 || r.after.all <= floor,
        "after {} vs before {} (floor {floor})",
        r.after.all,
        r.before.all
    );
}

/// [`assert_improved_against`] the clean campaign of the demo's two days.
pub fn assert_improved(r: &Report) {
    assert_improved_against(r, noise_floor());
}
