//! The fabric's HDR selection (issue 22 item 1) against the HPS's noise-optimal merge on the
//! same frames: the five noisy 2592 x 1944 frames of `skylux bench hdr` (1 µs to 500 ms, a
//! 150 dB log-ramp field), grouped as the fabric groups them (the Bayer golden model), selected
//! long to short by the HDR golden model (the fabric's map, bit for bit), read into a
//! `LuminanceMap` by the HPS, and compared with the truth. The issue asks the selection's RMS
//! relative error to stay within 1.15x the noise-limited bound (the merge's is 1.002x).

use skylux_hps::campaign::BayerPattern;
use skylux_hps::hdr::{fabric_map, merge, FabricMap, LuminanceMap, MapExposure, MapFlag};
use skylux_regmap::hdr_values::HdrConfig;
use skylux_regmap::words::WEIGHT_ONE;
use skylux_rtl::bayer::golden::{expected_words, BayerConfig, Frame, Phase};
use skylux_rtl::hdr::golden::{select, SetFrame};
use skylux_sim::hdr_case::{HdrCase, EXPOSURES_S};

/// RMS relative error against the truth and RMS noise bound over the groups valid in `map`
/// that have a bound, and their count.
fn accuracy(case: &HdrCase, map: &LuminanceMap, valid_in: &LuminanceMap) -> (f64, f64, usize) {
    let (g, device) = (&case.geometry, &case.device);
    let (mut n, mut sum2, mut bound2) = (0usize, 0.0, 0.0);
    for i in 0..map.luminance_cd_m2.len() {
        if map.flags[i] != MapFlag::Valid
            || valid_in.flags[i] != MapFlag::Valid
            || !g.direction[i].is_finite()
        {
            continue;
        }
        let truth = case.truth_cd_m2(g.direction[i].as_dvec3());
        let rate = truth / g.inverse_vignetting[i] as f64 / device.response.cg;
        let Some(b) = skylux_sim::analysis::hdr_relative_sigma_bound(device, &EXPOSURES_S, rate)
        else {
            continue;
        };
        let e = map.luminance_cd_m2[i] as f64 / truth - 1.0;
        n += 1;
        sum2 += e * e;
        bound2 += b * b;
    }
    let nf = n.max(1) as f64;
    ((sum2 / nf).sqrt(), (bound2 / nf).sqrt(), n)
}

#[test]
fn the_fabric_selection_stays_within_1_15_of_the_noise_bound() {
    let case = HdrCase::new();
    let (device, geometry) = (&case.device, &case.geometry);
    let merged = merge(&case.exposures(), device, BayerPattern::GRBG, geometry).unwrap();

    // The fabric's registers from the device: its black level and valid range, its weights
    // rounded to Q2.14 (0.2, 0.7, 0.1 are 3277, 11469, 1638: their sum is exactly 1).
    let q2_14 = |w: f64| (w * f64::from(WEIGHT_ONE)).round() as u16;
    let [wr, wg, wb] = device.response.weights;
    let bayer = BayerConfig {
        phase: Phase::Grbg,
        black: device.sensor.black_level_dn as u16,
        valid_min: device.sensor.valid_min_dn as u16,
        valid_max: device.sensor.valid_max_dn as u16,
        weight_r: q2_14(wr),
        weight_g: q2_14(wg),
        weight_b: q2_14(wb),
        raw: false,
    };
    // The sequence long to short: index k is the k-th longest exposure.
    let order: Vec<usize> = (0..EXPOSURES_S.len()).rev().collect();
    let grouped: Vec<Vec<u32>> = order
        .iter()
        .map(|&j| {
            let f = &case.frames[j];
            let frame = Frame {
                width: f.width,
                height: f.height,
                samples: f.samples_dn.clone(),
            };
            expected_words(&frame, &bayer)
        })
        .collect();
    let set: Vec<SetFrame> = grouped
        .iter()
        .enumerate()
        .map(|(k, words)| SetFrame {
            exposure_index: k as u8,
            first_of_set: k == 0,
            words,
        })
        .collect();
    let config = HdrConfig::default();
    let map = FabricMap {
        width: geometry.width,
        height: geometry.height,
        words: select(&config, &set),
    };
    let exposures: Vec<MapExposure> = order
        .iter()
        .map(|&j| MapExposure {
            exposure_s: EXPOSURES_S[j],
            gain: 1.0,
        })
        .collect();
    let fabric = fabric_map(
        &map,
        &exposures,
        &config,
        device,
        BayerPattern::GRBG,
        geometry,
    )
    .unwrap();

    // The same groups are valid (a group is valid when any exposure is), except where a
    // weight's rounding moves a sample across a range edge: none here, both see the samples.
    let disagree = (0..fabric.flags.len())
        .filter(|&i| (fabric.flags[i] == MapFlag::Valid) != (merged.flags[i] == MapFlag::Valid))
        .count();
    assert_eq!(disagree, 0, "groups valid in one map only");

    let (merge_rms, bound, n) = accuracy(&case, &merged, &fabric);
    let (fabric_rms, fabric_bound, fabric_n) = accuracy(&case, &fabric, &merged);
    assert_eq!((bound, n), (fabric_bound, fabric_n), "the same groups");
    let (merge_ratio, fabric_ratio) = (merge_rms / bound, fabric_rms / bound);
    println!(
        "{n} groups: bound {:.3} %, merge {:.3} % ({merge_ratio:.3}x), fabric selection {:.3} % ({fabric_ratio:.3}x)",
        100.0 * bound,
        100.0 * merge_rms,
        100.0 * fabric_rms
    );
    assert!(n > 500_000, "too few groups to judge: {n}");
    assert!(merge_ratio < 1.01, "the merge: {merge_ratio}x the bound");
    assert!(
        fabric_ratio < 1.15,
        "the fabric's selection: {fabric_ratio}x the bound"
    );
    // Selection throws information away: it cannot beat the merge by more than noise.
    assert!(
        fabric_ratio > merge_ratio * 0.999,
        "{fabric_ratio} vs {merge_ratio}"
    );
}
