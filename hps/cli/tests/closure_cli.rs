//! `skylux closure` as a user runs it, on the real station records of `shared/data/irradiance`
//! (see its README for provenance) converted to the campaign's `pyranometer.csv`.

use chrono::{FixedOffset, TimeDelta};
use skylux_hps::io::irradiance::{
    read_irradiance_file, to_pyranometer_rows, write_pyranometer_csv, PyranometerRow, ReadOptions,
    StampConvention,
};
use skylux_hps::validation::report::Report;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn skylux(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_skylux"))
        .args(args)
        .output()
        .expect("running the skylux binary")
}

fn data_path(relative: &str) -> PathBuf {
    let dir = std::env::var_os("SKYLUX_DATA_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared/data"));
    let path = dir.join(relative);
    assert!(
        path.is_file(),
        "{} not found: set SKYLUX_DATA_DIR to the shared data folder",
        path.display()
    );
    path
}

/// A station file as `pyranometer.csv` rows stamped at each interval's centre.
fn campaign_rows(relative: &str, stamp: StampConvention) -> Vec<PyranometerRow> {
    let s = read_irradiance_file(
        &data_path(relative),
        &ReadOptions::new(stamp, TimeDelta::minutes(1)),
    )
    .unwrap();
    to_pyranometer_rows(&s.records, FixedOffset::east_opt(0).unwrap())
}

fn write(path: &Path, rows: &[PyranometerRow]) {
    let mut out = Vec::new();
    write_pyranometer_csv(&mut out, rows).unwrap();
    std::fs::write(path, out).unwrap();
}

const ALAMOSA: [&str; 6] = ["--lat", "37.70", "--lon", "-105.92", "--elevation", "2317"];

fn run_closure(file: &Path, stamp: &str, out: &Path) -> Report {
    let mut args = vec!["closure", file.to_str().unwrap(), "--stamp", stamp, "--out"];
    args.push(out.to_str().unwrap());
    args.extend(ALAMOSA);
    let o = skylux(&args);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    print!("{stdout}");
    assert!(stdout.contains("hold-out closure residual"));
    Report::read_json(&out.join("report.json")).unwrap()
}

/// SURFRAD Alamosa, written once with centre stamps and once with the file's own end stamps:
/// with the matching `--stamp` both runs see the same sun and write the same report, which
/// finds an effect and at least halves the hold-out error, with its plots.
#[test]
fn surfrad_closure_end_to_end() {
    let dir = tempfile::tempdir().unwrap();
    let centre = campaign_rows(
        "irradiance/surfrad_alamosa_2016-01-01_1min.csv",
        StampConvention::IntervalEnd,
    );
    let end: Vec<PyranometerRow> = centre
        .iter()
        .map(|r| PyranometerRow {
            time: r.time + TimeDelta::seconds(30),
            ..r.clone()
        })
        .collect();
    let (centre_csv, end_csv) = (dir.path().join("centre.csv"), dir.path().join("end.csv"));
    write(&centre_csv, &centre);
    write(&end_csv, &end);
    let a = run_closure(&centre_csv, "centre", &dir.path().join("a"));
    let b = run_closure(&end_csv, "end", &dir.path().join("b"));
    // Only the note naming the stamp convention differs.
    let differing: Vec<(&String, &String)> = a
        .notes
        .iter()
        .zip(&b.notes)
        .filter(|(x, y)| x != y)
        .collect();
    assert_eq!(differing.len(), 1, "{differing:?}");
    assert!(differing[0].0.contains("interval centre") && differing[0].1.contains("interval end"));
    let strip = |r: &Report| Report {
        notes: Vec::new(),
        ..r.clone()
    };
    assert_eq!(strip(&a), strip(&b));
    assert_eq!(a.metric, "mean_abs_wm2");
    assert!(!a.effects.is_empty());
    assert!(
        a.after.all < 0.5 * a.before.all,
        "{} → {}",
        a.before.all,
        a.after.all
    );
    assert_eq!(a.fit_times.len() + a.holdout_times.len(), 1440);
    for f in &a.figures {
        let bytes = std::fs::read(dir.path().join("a").join(f)).unwrap();
        assert!(bytes.starts_with(b"\x89PNG"), "{f}");
    }
    let md = std::fs::read_to_string(dir.path().join("a/report.md")).unwrap();
    assert!(md.contains(&a.effects[0].name));
}

/// The MIDC record has GHI only: the closure says it needs DNI and DHI, and fails cleanly.
#[test]
fn ghi_only_record_is_a_clear_error() {
    let dir = tempfile::tempdir().unwrap();
    let rows = campaign_rows(
        "irradiance/midc_nwtc_2018-10-14_1min_ghi.csv",
        StampConvention::IntervalEnd,
    );
    let csv = dir.path().join("midc.csv");
    write(&csv, &rows);
    let out = dir.path().join("out");
    let o = skylux(&[
        "closure",
        csv.to_str().unwrap(),
        "--lat",
        "39.91",
        "--lon",
        "-105.23",
        "--out",
        out.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(stderr.contains("GHI, DHI and DNI"), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(!out.join("report.json").exists());
}

#[test]
fn bad_arguments_name_the_option() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("p.csv");
    std::fs::write(
        &csv,
        "time,ghi_wm2,dhi_wm2,dni_wm2\n\
         2016-01-01T18:00:00Z,500,50,900\n\
         2016-01-01T18:01:00Z,500,50,900\n",
    )
    .unwrap();
    let out = dir.path().join("o");
    let o = skylux(&[
        "closure",
        csv.to_str().unwrap(),
        "--lat",
        "95",
        "--lon",
        "0",
        "--out",
        out.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && stderr.contains("latitude_deg 95"),
        "{stderr}"
    );
    let o = skylux(&[
        "closure",
        "/no/such/file.csv",
        "--lat",
        "0",
        "--lon",
        "0",
        "--out",
        "x",
    ]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && stderr.contains("/no/such/file.csv"),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
}
