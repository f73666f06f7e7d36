//! `skylux illuminance` as a user runs it: CSV out, clear errors for bad input.

use std::process::{Command, Output};

fn skylux(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_skylux"))
        .args(args)
        .output()
        .expect("running the skylux binary")
}

/// A uniform sky of radiance 1 W/(sr m²) over a horizontal sensor: E = π W/m², 179 π lux.
/// (The sky's importance sampling, combined with the cosine continuation, makes single
/// samples vary even here, so the check is statistical: within 4 standard errors, and the
/// standard error itself small.)
#[test]
fn uniform_sky_csv() {
    let dir = tempfile::tempdir().unwrap();
    let sky = dir.path().join("sky.rad");
    std::fs::write(
        &sky,
        "void glow g 0 0 4 1 1 1 0\ng source sky 0 0 4 0 0 1 180\n",
    )
    .unwrap();
    let pts = dir.path().join("s.pts");
    std::fs::write(&pts, "0 0 0 0 0 1\n5 5 1 0 0 1\n").unwrap();
    let out = skylux(&[
        "illuminance",
        "--scene",
        sky.to_str().unwrap(),
        "--sensors",
        pts.to_str().unwrap(),
        "--ab",
        "1",
        "--ad",
        "100",
        "--seed",
        "3",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "sensor,lux,stderr_lux");
    assert_eq!(lines.len(), 3);
    for (line, name) in lines[1..].iter().zip(["S1", "S2"]) {
        let f: Vec<&str> = line.split(',').collect();
        assert_eq!(f[0], name);
        let lux: f64 = f[1].parse().unwrap();
        let stderr_lux: f64 = f[2].parse().unwrap();
        let truth = 179.0 * std::f64::consts::PI;
        assert!(
            stderr_lux > 0.0 && stderr_lux < 0.05 * truth,
            "{line}: standard error"
        );
        assert!((lux - truth).abs() < 4.0 * stderr_lux, "{line}");
    }
}

#[test]
fn bad_input_is_a_clear_error() {
    let dir = tempfile::tempdir().unwrap();
    let pts = dir.path().join("s.pts");
    std::fs::write(&pts, "0 0 0 0 0 1\n").unwrap();
    let missing = dir.path().join("missing.rad");
    let out = skylux(&[
        "illuminance",
        "--scene",
        missing.to_str().unwrap(),
        "--sensors",
        pts.to_str().unwrap(),
    ]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("missing.rad") && !err.contains("panicked"),
        "{err}"
    );

    let bad = dir.path().join("bad.rad");
    std::fs::write(
        &bad,
        "void plastic m 0 0 5 .5 .5 .5 0 0\nm polygon p 0 0 5 0 0 0 1 1\n",
    )
    .unwrap();
    let out = skylux(&[
        "illuminance",
        "--scene",
        bad.to_str().unwrap(),
        "--sensors",
        pts.to_str().unwrap(),
    ]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("bad.rad:2") && !err.contains("panicked"),
        "{err}"
    );

    let sky = dir.path().join("sky.rad");
    std::fs::write(
        &sky,
        "void glow g 0 0 4 1 1 1 0\ng source sky 0 0 4 0 0 1 180\n",
    )
    .unwrap();
    let out = skylux(&[
        "illuminance",
        "--scene",
        sky.to_str().unwrap(),
        "--sensors",
        pts.to_str().unwrap(),
        "--ad",
        "0",
    ]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("-ad") && !err.contains("panicked"), "{err}");
}
