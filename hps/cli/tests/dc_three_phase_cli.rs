//! `skylux dc --three-phase` as a user runs it: the files it writes read back as RADIANCE
//! matrices of the right shapes, V against the closed form of a point facing a window, the
//! product it prints equal to the product of its files, and clear errors for bad input.

use skylux_hps::bsdf::{Band, KlemsTransmission};
use skylux_hps::engine::phase::three_phase;
use skylux_hps::io::radiance_matrix::RadianceMatrix;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn skylux(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_skylux"))
        .args(args)
        .output()
        .expect("running the skylux binary")
}

fn clear_glass() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/data/radiance-corpus/bsdf/sariths-matrix-tutorial/room/matrices/tmtx/clear.xml")
}

/// Irradiance per unit radiance at a point facing a parallel rectangle of sides a and b
/// that starts at the point's foot, at distance h: π times the view factor (Howell C-11,
/// F = 1/(2π) [...]).
fn corner_rectangle(a: f64, b: f64, h: f64) -> f64 {
    let (x, y) = (a / h, b / h);
    let (sx, sy) = ((1.0 + x * x).sqrt(), (1.0 + y * y).sqrt());
    0.5 * (x / sx * (y / sx).atan() + y / sy * (x / sy).atan())
}

/// A room with nothing near the sensors (a far floor keeps the scene non-empty) and a
/// 2 × 1.2 m window polygon in the plane y = 0, written into `dir`.
fn room_and_window(dir: &Path) {
    std::fs::write(
        dir.join("room.rad"),
        "void plastic f 0 0 5 .2 .2 .2 0 0\nf polygon far 0 0 12 50 50 -9 51 50 -9 51 51 -9 50 51 -9\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("window.rad"),
        "void glow g 0 0 4 1 1 1 0\ng polygon w 0 0 12 1 0 0.9 1 0 2.1 3 0 2.1 3 0 0.9\n",
    )
    .unwrap();
}

#[test]
fn matrices_read_back_and_v_is_the_view_factor() {
    let dir = tempfile::tempdir().unwrap();
    let p = |name: &str| dir.path().join(name);
    // No room around the sensor: only the window's polygon matters to V. A floor far away
    // keeps the scene non-empty.
    room_and_window(dir.path());
    // Facing the window (-y) 1 m in front of its lower left corner.
    std::fs::write(p("s.pts"), "1 1 0.9 0 -1 0\n").unwrap();
    // A uniform sky of radiance 1 and ground of 0.5, Tregenza (146 rows).
    let sky: String = std::iter::once("0.5\n".to_string())
        .chain((0..145).map(|_| "1\n".to_string()))
        .collect();
    std::fs::write(
        p("sky.mtx"),
        format!("#?RADIANCE\nNROWS=146\nNCOLS=1\nNCOMP=1\nFORMAT=ascii\n\n{sky}"),
    )
    .unwrap();
    let out_dir = p("out");
    let out = skylux(&[
        "dc",
        "--three-phase",
        "--scene",
        p("room.rad").to_str().unwrap(),
        "--window",
        p("window.rad").to_str().unwrap(),
        "--bsdf",
        clear_glass().to_str().unwrap(),
        "--sensors",
        p("s.pts").to_str().unwrap(),
        "--mf",
        "1",
        "--ab",
        "1",
        "--ad",
        "200000",
        "--d-samples",
        "256",
        "--direct",
        "--sky",
        p("sky.mtx").to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let read = |name: &str| RadianceMatrix::read(&out_dir.join(name)).unwrap();
    let (v, t, d) = (read("v.mtx"), read("t.mtx"), read("d.mtx"));
    assert_eq!((v.rows, v.cols, v.ncomp), (1, 145, 3));
    assert_eq!((t.rows, t.cols), (145, 145));
    assert_eq!((d.rows, d.cols), (145, 146));
    assert_eq!((read("vd.mtx").cols, read("dd.mtx").cols), (145, 146));
    let expected = corner_rectangle(2.0, 1.2, 1.0);
    let got = v.row_sums(0)[0];
    println!("V row sum {got:.5}, closed form {expected:.5}");
    // 200,000 paths: about 0.5 % of standard error.
    assert!((got / expected - 1.0).abs() < 0.03, "{got} vs {expected}");
    // With nothing outside, every D row sees the sky or the ground: sums of 1.
    for s in d.row_sums(0) {
        assert!((s - 1.0).abs() < 1e-9, "{s}");
    }
    // T as written is the XML's.
    let xml = KlemsTransmission::load(&clear_glass(), Band::Visible).unwrap();
    for (a, b) in t.brightness().values.iter().zip(&xml.matrix.values) {
        assert!((a - b).abs() <= 1e-6 * b.abs().max(1e-6), "{a} vs {b}");
    }
    // The printed lux are 179 × the product of the files written.
    let sky = RadianceMatrix::read(&p("sky.mtx")).unwrap();
    let product = three_phase(&v, &t, &d, &sky).unwrap();
    let result = read("result.mtx");
    // Grey V, T, D and sky: one component.
    assert_eq!((result.rows, result.cols, result.ncomp), (1, 1, 1));
    assert!((result.get(0, 0, 0) / product.get(0, 0, 0) - 1.0).abs() < 1e-6);
    let text = String::from_utf8(out.stdout).unwrap();
    let line = text
        .lines()
        .find(|l| l.starts_with("S1,"))
        .expect("a line for S1");
    let printed: f64 = line[3..].parse().unwrap();
    let lux = 179.0 * product.brightness().get(0, 0, 0);
    assert!((printed - lux).abs() <= 0.051, "{printed} vs {lux}");
}

#[test]
fn bad_input_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let p = |name: &str| dir.path().join(name);
    std::fs::write(
        p("room.rad"),
        "void plastic f 0 0 5 .2 .2 .2 0 0\nf polygon far 0 0 12 50 50 -9 51 50 -9 51 51 -9 50 51 -9\n",
    )
    .unwrap();
    std::fs::write(p("s.pts"), "1 1 0.9 0 -1 0\n").unwrap();
    std::fs::write(
        p("window.rad"),
        "void glow g 0 0 4 1 1 1 0\ng sphere w 0 0 4 0 0 0 1\n",
    )
    .unwrap();
    let run = |extra: &[&str]| {
        let mut args = vec![
            "dc",
            "--three-phase",
            "--scene",
            p("room.rad").to_str().unwrap(),
            "--sensors",
            p("s.pts").to_str().unwrap(),
            "--out",
            p("out").to_str().unwrap(),
        ]
        .into_iter()
        .map(String::from)
        .collect::<Vec<_>>();
        args.extend(extra.iter().map(|s| s.to_string()));
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = skylux(&refs);
        assert!(!out.status.success());
        String::from_utf8_lossy(&out.stderr).into_owned()
    };
    // No BSDF: clap says what is missing.
    let e = run(&["--window", p("window.rad").to_str().unwrap()]);
    assert!(e.contains("--bsdf"), "{e}");
    // A window that is not polygons: the file and line.
    let e = run(&[
        "--window",
        p("window.rad").to_str().unwrap(),
        "--bsdf",
        clear_glass().to_str().unwrap(),
    ]);
    assert!(
        e.contains("window.rad:2") && e.contains("not a polygon"),
        "{e}"
    );
}

/// Window states (`--state NAME=XML`): V and D traced once, each state one product. A state
/// with the --bsdf's own XML reads what the --bsdf does; venetian blinds at 45° read what
/// the product of the files written for them gives, and far less than clear glass.
#[test]
fn window_states_are_one_product_each() {
    let dir = tempfile::tempdir().unwrap();
    let p = |name: &str| dir.path().join(name);
    room_and_window(dir.path());
    std::fs::write(p("s.pts"), "1 1 0.9 0 -1 0\n2 2 1.5 0 -1 0\n").unwrap();
    let sky: String = std::iter::once("0.5\n".to_string())
        .chain((0..145).map(|k| format!("{}\n", 1.0 + (k % 5) as f64)))
        .collect();
    std::fs::write(
        p("sky.mtx"),
        format!("#?RADIANCE\nNROWS=146\nNCOLS=1\nNCOMP=1\nFORMAT=ascii\n\n{sky}"),
    )
    .unwrap();
    let ven45 = clear_glass().with_file_name("ven45.xml");
    let out_dir = p("out");
    let again = format!("again={}", clear_glass().display());
    let blinds = format!("ven45={}", ven45.display());
    let out = skylux(&[
        "dc",
        "--three-phase",
        "--scene",
        p("room.rad").to_str().unwrap(),
        "--window",
        p("window.rad").to_str().unwrap(),
        "--bsdf",
        clear_glass().to_str().unwrap(),
        "--state",
        &again,
        "--state",
        &blinds,
        "--sensors",
        p("s.pts").to_str().unwrap(),
        "--mf",
        "1",
        "--ab",
        "1",
        "--ad",
        "50000",
        "--d-samples",
        "64",
        "--sky",
        p("sky.mtx").to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let value = |prefix: &str| -> f64 {
        let line = text
            .lines()
            .find(|l| l.starts_with(prefix))
            .unwrap_or_else(|| panic!("no line {prefix} in {text}"));
        line.rsplit(',').next().unwrap().parse().unwrap()
    };
    let read = |name: &str| RadianceMatrix::read(&out_dir.join(name)).unwrap();
    let (v, d) = (read("v.mtx"), read("d.mtx"));
    let sky = RadianceMatrix::read(&p("sky.mtx")).unwrap();
    for sensor in ["S1", "S2"] {
        let (plain, bsdf, same) = (
            value(&format!("{sensor},")),
            value(&format!("{sensor},bsdf,")),
            value(&format!("{sensor},again,")),
        );
        assert!((plain - bsdf).abs() <= 0.051 && (bsdf - same).abs() <= 0.051);
        let row = if sensor == "S1" { 0 } else { 1 };
        let product = three_phase(&v, &read("t-ven45.mtx"), &d, &sky).unwrap();
        let want = 179.0 * product.brightness().get(row, 0, 0);
        let got = value(&format!("{sensor},ven45,"));
        println!("{sensor}: clear {bsdf} lux, blinds at 45° {got} lux (files: {want:.2})");
        assert!((got - want).abs() <= 0.051 + 1e-6 * want, "{got} vs {want}");
        assert!(
            got < 0.7 * bsdf,
            "the blinds must cut the light: {got} vs {bsdf}"
        );
    }
    // A state on another basis, or a bad name, is refused with the option.
    let bad = skylux(&[
        "dc",
        "--three-phase",
        "--scene",
        p("room.rad").to_str().unwrap(),
        "--window",
        p("window.rad").to_str().unwrap(),
        "--bsdf",
        clear_glass().to_str().unwrap(),
        "--state",
        "no file",
        "--sensors",
        p("s.pts").to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    let e = String::from_utf8_lossy(&bad.stderr);
    assert!(!bad.status.success() && e.contains("--state"), "{e}");
}
