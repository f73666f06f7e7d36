//! The outdoor plausibility bound (`model::plausibility`) against real skies: every minute of the
//! two measured station records of `shared/data/irradiance` (SURFRAD Alamosa, a clear winter
//! day at 2317 m; NREL MIDC NWTC, an autumn day at 1855 m) must lie under it, or the daemon
//! would flag real light; and the clear noon must reach most of it, or it would flag nothing.

use chrono::{Datelike, TimeDelta};
use skylux_hps::io::irradiance::{read_irradiance_file, ReadOptions, StampConvention};
use skylux_hps::model::plausibility::{clear_sky_ghi_w_m2, global_horizontal_bound_w_m2};
use skylux_hps::sun::{solar_position, Atmosphere, Site};
use std::path::PathBuf;

fn data_path(relative: &str) -> PathBuf {
    let dir = std::env::var_os("SKYLUX_DATA_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared/data"));
    dir.join(relative)
}

/// Per minute with the sun up: (GHI, bound, clear-sky GHI at TL 2), W/m².
fn minutes(file: &str, site: &Site) -> Vec<(f64, f64, f64)> {
    let options = ReadOptions::new(StampConvention::IntervalEnd, TimeDelta::minutes(1));
    let series = read_irradiance_file(&data_path(file), &options).unwrap();
    let atmosphere = Atmosphere::standard_at(site.elevation_m);
    series
        .records
        .iter()
        .filter_map(|r| {
            let ghi = r.ghi_wm2?;
            let mid = r.interval_start_utc + (r.interval_end_utc - r.interval_start_utc) / 2;
            let sun = solar_position(mid, site, Some(&atmosphere)).unwrap();
            let altitude = sun.altitude_deg();
            (altitude > 0.0).then(|| {
                let day = mid.ordinal() as u16;
                (
                    ghi,
                    global_horizontal_bound_w_m2(altitude, site.elevation_m, day),
                    clear_sky_ghi_w_m2(altitude, site.elevation_m, 2.0, day),
                )
            })
        })
        .collect()
}

fn check(label: &str, file: &str, site: &Site) -> f64 {
    let rows = minutes(file, site);
    assert!(rows.len() > 400, "{label}: {} daytime minutes", rows.len());
    let over: Vec<_> = rows.iter().filter(|(g, b, _)| g > b).collect();
    let closest = rows.iter().map(|(g, b, _)| g / b).fold(0.0f64, f64::max);
    let clear_ratio = rows
        .iter()
        .map(|(g, _, c)| g / c.max(1.0))
        .filter(|r| r.is_finite())
        .fold(0.0f64, f64::max);
    println!(
        "{label}: {} daytime minutes, highest GHI / bound {closest:.3}, highest GHI / clear-sky(TL 2) {clear_ratio:.3}",
        rows.len()
    );
    assert!(over.is_empty(), "{label}: minutes over the bound: {over:?}");
    closest
}

#[test]
fn no_minute_of_a_real_sky_exceeds_the_bound_and_a_clear_noon_reaches_most_of_it() {
    let alamosa = Site {
        latitude_deg: 37.70,
        longitude_deg: -105.92,
        elevation_m: 2317.0,
    };
    let nwtc = Site {
        latitude_deg: 39.91,
        longitude_deg: -105.23,
        elevation_m: 1855.0,
    };
    let a = check(
        "SURFRAD Alamosa 2016-01-01",
        "irradiance/surfrad_alamosa_2016-01-01_1min.csv",
        &alamosa,
    );
    let n = check(
        "MIDC NWTC 2018-10-14",
        "irradiance/midc_nwtc_2018-10-14_1min_ghi.csv",
        &nwtc,
    );
    // Not vacuous: a clear day's noon comes within a factor of two of the bound.
    assert!(
        a.max(n) > 0.5,
        "the bound is loose: {a:.3}, {n:.3} of it reached"
    );
}
