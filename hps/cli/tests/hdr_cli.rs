//! `skylux hdr` on a simulated capture, and the errors a user will meet.

use std::process::Command;

fn skylux(args: &[&str]) -> (bool, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_skylux"))
        .args(args)
        .env("RUST_BACKTRACE", "0")
        .output()
        .unwrap();
    (
        out.status.success(),
        format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        ),
    )
}

#[test]
fn hdr_command_writes_a_map_and_reports_bad_input_clearly() {
    let dir = tempfile::tempdir().unwrap();
    skylux_sim::capture::write_example_capture(dir.path(), 1).unwrap();

    let d = dir.path().to_str().unwrap();
    let device_path = format!("{d}/device.toml");
    let out = format!("{d}/map.exr");
    let sky = format!("{d}/radiance");
    let (ok, text) = skylux(&[
        "hdr",
        d,
        "--device",
        &device_path,
        "--out",
        &out,
        "--radiance-sky",
        &sky,
    ]);
    assert!(
        ok && text.contains("64x48 groups from 3 exposures") && text.contains("patches filled"),
        "{text}"
    );
    assert!(std::path::Path::new(&out).exists());
    for f in ["sky.hdr", "sky.rad", "skylux_sky.cal"] {
        assert!(std::path::Path::new(&sky).join(f).exists(), "{f}");
    }
    // A missing frame, a frame of the wrong size, a broken device.toml, a missing capture.
    std::fs::remove_file(dir.path().join("e1.pgm")).unwrap();
    let (ok, text) = skylux(&["hdr", d, "--device", &device_path, "--out", &out]);
    assert!(!ok && text.contains("e1.pgm"), "{text}");
    skylux_hps::campaign::RawFrame::new(64, 48)
        .write(&dir.path().join("e1.pgm"))
        .unwrap();
    let (ok, text) = skylux(&["hdr", d, "--device", &device_path, "--out", &out]);
    assert!(
        !ok && text.contains("e1.pgm: 64x48 samples") && text.contains("must match"),
        "{text}"
    );
    let (ok, text) = skylux(&[
        "hdr",
        "/nonexistent/capture",
        "--device",
        &device_path,
        "--out",
        &out,
    ]);
    assert!(
        !ok && text.contains("/nonexistent/capture/capture.toml"),
        "{text}"
    );
    std::fs::write(&device_path, "[sensor]\nblack_level_dn = nan\n").unwrap();
    let (ok, text) = skylux(&["hdr", d, "--device", &device_path, "--out", &out]);
    assert!(!ok && text.contains("device.toml"), "{text}");
    assert!(!text.contains("panicked"), "{text}");
}
