//! The effects of the library (issue 9) that act on the measured sky and its light: the
//! sky's colour (`spectral_mismatch`), the glazing's angular transmittance
//! (`glazing_angular`), vignetting beyond the declared polynomial (`vignetting`) and a
//! clipped field of view (`sky_outside_fov`). One test binary, so the harness's shared
//! campaigns (the noise floor) are simulated once.
//!
//! Spectral mismatch with the sky's colour (issue 9): the frames are rendered with the sky's
//! real colour (CIE daylights, a deep blue clear sky, a redder sun, an overcast sky at D65)
//! through measured camera sensitivities, while `device.toml` keeps the weights calibrated
//! under D65. The loop must see the residual follow the sky colour index it measures from the
//! raw frames, name `spectral_mismatch`, fit its slope within tolerance of the truth and cut
//! the hold-out error to a third or to the noise floor.
//!
//! The truth is computed here from the spectral data alone (the camera's curves, V(λ), the
//! CIE daylight basis, D65 and the declared weights), not from the loop's code.
//!
//! Test bed: tests/common/loop_harness.rs.
//!
//! The glazing's angular transmittance (`glazing_angular`, ASHRAE incidence-angle modifier)
//! present in the world and not declared: the loop must name it (not the common factor
//! `glazing_transmittance`), fit b0 within tolerance of the truth, and cut the hold-out error
//! to at most a third or to the noise floor. And the two residual variables that need the
//! glazing's geometry, against the geometry and sun of the simulated world.
//!
//! Test bed: tests/common/loop_harness.rs (one campaign, shared by the tests here).
//!
//! The sky effects of the library (issue 9): the lens's relative illumination steeper than
//! `device.toml` declares (`vignetting`), and a baffle that clips the field of view
//! (`sky_outside_fov`), each present in the simulated world and not declared. The loop must
//! name the effect, fit its parameter within the stated tolerance of the truth, and cut the
//! hold-out error to at most a third of before or to the noise floor of the same campaign
//! (same seed) without the effect.
//!
//! Test bed: tests/common/loop_harness.rs.

mod common;

use common::loop_harness::{assert_improved, effect, run, simulate, simulate_spec, spec, ROOM};
use skylux_hps::camera::DeviceConfig;
use skylux_hps::campaign::Campaign;
use skylux_hps::numerics::pearson;
use skylux_hps::validation::illuminance_loop::LoopOutcome;
use skylux_sim::campaign::{simulate_campaign, TruthRecord};
use skylux_sim::sky_colour::MismatchLine;
use std::path::PathBuf;
use std::sync::OnceLock;

/// The shared data folder: `$SKYLUX_DATA_DIR`, else beside the shared scenes.
fn data_dir() -> PathBuf {
    std::env::var_os("SKYLUX_DATA_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(ROOM).join("../../data"))
}

/// The world's slope of the camera's relative luminance error against its blue / red index
/// ([`MismatchLine`], from the spectral data alone) for the declared weights.
fn true_slope() -> f64 {
    let weights = DeviceConfig::default().response.weights;
    let line = MismatchLine::of_daylights(&data_dir(), weights).unwrap();
    println!(
        "world: error {:+.4} at mean index {:.3}; intercept at index 1: {:+.4}",
        line.mean_error,
        line.mean_index,
        line.error_at_calibration()
    );
    line.slope_per_index
}

/// A clear sky at 20,000 K far from the sun (an overcast second day at D65): the blue sky
/// reads up to 15 % high, the circumsolar sky less, the sun some 4 % low. The loop measures
/// the colour index (the clear day bluer than the overcast one, which gives the calibration's
/// 1), names the effect and fits its slope within 20 % of the truth (it lands high: +8 % and
/// +17 % with two engine versions' noise, the clear day's three fit captures pinning it).
#[test]
#[ignore = "long: the loop on a further campaign; CI runs its short form, scripts/long-tests all"]
fn spectral_mismatch() {
    let truth = true_slope();
    println!("true slope {truth:.4} per unit of blue / red");
    let dir = tempfile::tempdir().unwrap();
    let c = simulate(dir.path(), &["spectral_mismatch=20000"], 123);
    let outcome = run(&c, false);
    let r = &outcome.report;
    println!(
        "before {:?}\nafter {:?}\nrejected {:?}\nnotes {:?}\neffects {:#?}",
        r.before, r.after, r.rejected, r.notes, r.effects
    );
    // The colour index: bluer on the clear day, the calibration's 1 under the overcast sky.
    let mut by_day: std::collections::BTreeMap<String, Vec<f64>> = Default::default();
    for d in &outcome.diagnostics {
        by_day
            .entry(d.time.format("%m-%d").to_string())
            .or_default()
            .push(d.sky_colour_index);
    }
    println!("sky colour index per day: {by_day:?}");
    let clear = &by_day["05-08"];
    let overcast = &by_day["05-09"];
    assert!(clear.iter().all(|c| *c > 1.3 && *c < 1.8), "{clear:?}");
    assert!(
        overcast.iter().all(|c| (c - 1.0).abs() < 0.02),
        "{overcast:?}"
    );
    let e = effect(r, "spectral_mismatch");
    let m = e.parameters["slope_per_index"];
    println!("fitted slope {m:.4}; {}", e.evidence);
    assert!((m / truth - 1.0).abs() <= 0.20, "{m} vs {truth}");
    assert!(e.evidence.contains("colour index"), "{}", e.evidence);
    // The residual table shows the signature before, and it is gone after.
    let row = outcome
        .residuals
        .iter()
        .find(|row| row.variable.starts_with("sky colour index") && row.group == "all")
        .expect("sky colour row");
    println!(
        "residual vs colour: r {:.2} → {:.2}",
        row.before_r, row.after_r
    );
    assert!(row.before_r > 0.5, "{row:?}");
    assert!(row.after_r.abs() < row.before_r / 2.0, "{row:?}");
    assert_improved(r);
}

/// The truth of the world: b0 of the glazing.
const B0: f64 = 0.15;

/// The campaign with the angular effect, its truth and the loop's outcome.
fn angular() -> &'static (tempfile::TempDir, Campaign, Vec<TruthRecord>, LoopOutcome) {
    static CASE: OnceLock<(tempfile::TempDir, Campaign, Vec<TruthRecord>, LoopOutcome)> =
        OnceLock::new();
    CASE.get_or_init(|| {
        let dir = tempfile::tempdir().unwrap();
        let effect = format!("glazing_angular={B0}");
        let truth = simulate_campaign(dir.path(), &spec(&[&effect], 91), &|_, _| {}).unwrap();
        let c = Campaign::open(dir.path()).unwrap();
        let outcome = run(&c, false);
        (dir, c, truth, outcome)
    })
}

#[test]
#[ignore = "long: the loop on a further campaign; CI runs its short form, scripts/long-tests all"]
fn glazing_angular() {
    let r = &angular().3.report;
    println!("{:#?}", r.effects);
    let e = effect(r, "glazing_angular");
    let b0 = e.parameters["b0"];
    assert!((b0 - B0).abs() < 0.03, "b0 {b0} vs {B0}");
    assert!(e.evidence.contains("incidence"), "{}", e.evidence);
    // The angular effect is not mistaken for (or topped up by) a common factor.
    assert!(
        r.effects.iter().all(|e| e.name != "glazing_transmittance"),
        "{:#?}",
        r.effects
    );
    // The acceptance rule of the harness; the noise floor (a second campaign) is simulated
    // only if the one-third rule is not met.
    if r.after.all > r.before.all / 3.0 {
        assert_improved(r);
    }
    println!(
        "hold-out: before {:.2} %, after {:.2} %",
        100.0 * r.before.all,
        100.0 * r.after.all
    );
}

/// The residual table's solar incidence on the glazing and distance from the façade, against
/// the world's: the façade of the reference room is the plane y = 0 facing south (−y), so
/// the incidence is acos(−s_y) of the simulated sun s (NaN below the horizon or from the
/// north), and the sensors at y = 1, 2, 3, 3.9, 4.7 m (`sensors.pts`) are that far from it.
#[test]
#[ignore = "long: the loop on a further campaign; CI runs its short form, scripts/long-tests all"]
fn incidence_and_facade_distance_variables() {
    let (_, _, truth, outcome) = angular();
    let depth = [
        ("S1", 1.0),
        ("S2", 2.0),
        ("S3", 3.0),
        ("S4", 3.9),
        ("S5", 4.7),
    ];
    let mut checked = 0;
    for d in &outcome.diagnostics {
        let t = truth.iter().find(|t| t.time == d.time).expect("truth");
        let s = t.sun_direction;
        let expect = if s.z > 0.0 && -s.y > 0.0 {
            (-s.y).acos().to_degrees()
        } else {
            f64::NAN
        };
        if expect.is_nan() {
            assert!(d.sun_incidence_deg.is_nan(), "{d:?}");
        } else {
            // SPA in the loop and in the world agree to well under 0.01°.
            assert!(
                (d.sun_incidence_deg - expect).abs() < 0.01,
                "{} vs {expect}",
                d.sun_incidence_deg
            );
            checked += 1;
        }
        let y = depth.iter().find(|(n, _)| *n == d.sensor).unwrap().1;
        assert!((d.facade_distance_m - y).abs() < 1e-9, "{d:?}");
    }
    assert!(checked > 10, "{checked}");
    // The signature is in the table: before the effect, the sunlit readings' relative
    // residual grows with the solar incidence, and over all readings it falls with the
    // distance from the façade (the sky is seen at wider angles near the glazing); after, the
    // trend is smaller.
    let sunlit: Vec<(f64, f64)> = outcome
        .diagnostics
        .iter()
        .filter(|d| d.direct_sun_share > 0.05)
        .map(|d| {
            (
                d.sun_incidence_deg,
                d.before_lux / d.measured_before_lux - 1.0,
            )
        })
        .collect();
    let (r_sunlit, slope) = pearson(&sunlit).map_or((f64::NAN, f64::NAN), |p| (p.r, p.slope));
    println!(
        "sunlit readings: {} r {r_sunlit:.2} slope {slope:.4}/deg",
        sunlit.len()
    );
    assert!(sunlit.len() >= 10 && r_sunlit > 0.2 && slope > 0.0);
    let row = |v: &str| {
        outcome
            .residuals
            .iter()
            .find(|r| r.variable.starts_with(v) && r.group == "all")
            .unwrap_or_else(|| panic!("{v} not in the residual table"))
    };
    let depth = row("distance from the facade");
    println!("{depth:?}\n{:?}", row("solar incidence on the glazing"));
    assert!(depth.before_r < -0.3, "{depth:?}");
    assert!(depth.after_r.abs() < depth.before_r.abs(), "{depth:?}");
}

/// The harness's clean campaign's seed: the same noise, with and without the effect.
const SEED: u64 = 11;

/// The true fall-off is the declared polynomial times 1 − 0.4 (α/90°)²: 16 % darker at 60°
/// off-axis. The hold-out error is 5.4 % before. The fit lands at 0.36 (the light the model
/// takes from the extrapolated sky beyond the field keeps part of the fall-off), so the
/// tolerance is 0.06.
#[test]
#[ignore = "long: the loop on a further campaign; CI runs its short form, scripts/long-tests all"]
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
#[ignore = "long: the loop on a further campaign; CI runs its short form, scripts/long-tests all"]
fn sky_outside_fov() {
    // Hourly captures: the sun leaves the clipped field at several of them, in fit and
    // hold-out blocks alike (with the harness's two-hourly captures the gain sat at the
    // hold-out's block-to-block noise).
    let dir = tempfile::tempdir().unwrap();
    let mut hourly = spec(&["fov_limit_deg=52"], SEED);
    hourly.hours = (8..=18).map(f64::from).collect();
    let r = run(&simulate_spec(dir.path(), &hourly), false).report;
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
