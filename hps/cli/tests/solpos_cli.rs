//! `skylux solpos` as a user runs it, against pvlib rows of the solar-position fixtures
//! (`hps/core/tests/fixtures/solpos/fixtures.csv`, made by `make_fixtures.py` there).

use std::process::{Command, Output};

fn skylux(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_skylux"))
        .args(args)
        .output()
        .expect("running the skylux binary")
}

/// pvlib's answer for one fixture row, with the inputs as the text the file holds.
struct Row {
    fields: Vec<String>,
    apparent_zenith_deg: f64,
    zenith_deg: f64,
    azimuth_deg: f64,
}

/// The first fixture row with the sun up (so refraction matters), and the first with it down.
fn fixture_rows() -> (Row, Row) {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../core/tests/fixtures/solpos/fixtures.csv"
    );
    let text = std::fs::read_to_string(path).expect("fixtures.csv");
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(
        header,
        [
            "time",
            "latitude_deg",
            "longitude_deg",
            "elevation_m",
            "pressure_hpa",
            "temperature_c",
            "delta_t_s",
            "apparent_zenith_deg",
            "zenith_deg",
            "azimuth_deg"
        ]
    );
    let rows: Vec<Row> = lines
        .map(|l| {
            let f: Vec<String> = l.split(',').map(str::to_string).collect();
            Row {
                apparent_zenith_deg: f[7].parse().unwrap(),
                zenith_deg: f[8].parse().unwrap(),
                azimuth_deg: f[9].parse().unwrap(),
                fields: f,
            }
        })
        .collect();
    let mut up = None;
    let mut down = None;
    for r in rows {
        if r.zenith_deg < 80.0 && up.is_none() {
            up = Some(r);
        } else if r.zenith_deg > 100.0 && down.is_none() {
            down = Some(r);
        }
    }
    (up.unwrap(), down.unwrap())
}

fn parse_output(out: &Output) -> (f64, f64) {
    assert!(
        out.status.success(),
        "skylux solpos failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8(out.stdout.clone()).unwrap();
    let lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(lines.len(), 2, "{stdout}");
    assert_eq!(lines[0], "zenith_deg,azimuth_deg");
    let v: Vec<f64> = lines[1].split(',').map(|x| x.parse().unwrap()).collect();
    assert_eq!(v.len(), 2);
    (v[0], v[1])
}

fn row_args(r: &Row) -> Vec<String> {
    let f = &r.fields;
    [
        "solpos",
        "--lat",
        &f[1],
        "--lon",
        &f[2],
        "--time",
        &f[0],
        "--elevation",
        &f[3],
        "--pressure",
        &f[4],
        "--temp",
        &f[5],
    ]
    .iter()
    .map(|s| s.to_string())
    .collect()
}

/// The printed values carry 6 decimals; SPA agrees with pvlib to far better than 1e-4°.
const TOLERANCE_DEG: f64 = 1e-4;

#[test]
fn solpos_matches_pvlib_with_and_without_refraction() {
    let (up, down) = fixture_rows();
    for r in [&up, &down] {
        let args = row_args(r);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let (zenith, azimuth) = parse_output(&skylux(&args));
        assert!(
            (zenith - r.apparent_zenith_deg).abs() < TOLERANCE_DEG,
            "{zenith} vs pvlib {}",
            r.apparent_zenith_deg
        );
        assert!((azimuth - r.azimuth_deg).abs() < TOLERANCE_DEG);

        let mut geometric = args.clone();
        geometric.push("--no-refraction");
        let (zenith, azimuth) = parse_output(&skylux(&geometric));
        assert!(
            (zenith - r.zenith_deg).abs() < TOLERANCE_DEG,
            "{zenith} vs pvlib {}",
            r.zenith_deg
        );
        assert!((azimuth - r.azimuth_deg).abs() < TOLERANCE_DEG);
    }
    // The sun-up row is refracted by a measurable amount, so the first check was not vacuous.
    assert!(up.zenith_deg - up.apparent_zenith_deg > 0.003);
}

#[test]
fn bad_input_is_a_clear_error_not_a_panic() {
    let cases: [(&[&str], &str); 6] = [
        (
            &[
                "--lat",
                "46.5",
                "--lon",
                "6.6",
                "--time",
                "2017-05-08 10:00",
            ],
            "--time",
        ),
        (
            &[
                "--lat",
                "46.5",
                "--lon",
                "6.6",
                "--time",
                "2017-05-08T10:00:00",
            ],
            "--time",
        ),
        (
            &[
                "--lat",
                "91",
                "--lon",
                "6.6",
                "--time",
                "2017-05-08T10:00:00Z",
            ],
            "--lat",
        ),
        (
            &[
                "--lat",
                "NaN",
                "--lon",
                "6.6",
                "--time",
                "2017-05-08T10:00:00Z",
            ],
            "--lat",
        ),
        (
            &[
                "--lat",
                "46.5",
                "--lon",
                "-200",
                "--time",
                "2017-05-08T10:00:00Z",
            ],
            "--lon",
        ),
        (
            &[
                "--lat",
                "46.5",
                "--lon",
                "6.6",
                "--time",
                "2017-05-08T10:00:00Z",
                "--pressure",
                "-3",
            ],
            "--pressure",
        ),
    ];
    for (args, option) in cases {
        let mut full = vec!["solpos"];
        full.extend_from_slice(args);
        let out = skylux(&full);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{full:?} succeeded");
        assert!(!stderr.contains("panicked"), "{full:?}: {stderr}");
        assert!(stderr.contains(option), "{full:?}: {stderr}");
        assert!(out.stdout.is_empty(), "{full:?} printed values");
    }
}

#[test]
fn help_says_a_header_line_is_printed() {
    let out = skylux(&["solpos", "--help"]);
    assert!(out.status.success());
    let help = String::from_utf8_lossy(&out.stdout);
    assert!(
        help.contains("header line `zenith_deg,azimuth_deg`"),
        "{help}"
    );
}
