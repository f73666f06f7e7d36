//! `skylux compare` as a user runs it: a picture against itself scaled by 1.2 (JSON, text,
//! regions from polygons, the error PNG) and clear errors for bad input.

use glam::DVec3;
use skylux_hps::picture::{rgbe::write_hdr, Picture};
use std::path::Path;
use std::process::{Command, Output};

const VIEW: &str = "-vtv -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 60 -vv 45";

fn skylux(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_skylux"))
        .args(args)
        .output()
        .expect("running the skylux binary")
}

/// A 40 × 30 grey picture whose radiance is `factor` × a gradient of powers of two (so each
/// RGBE mantissa is the same: 0.5 → 128, 0.625 → 160).
fn write(path: &Path, factor: f64) {
    let (w, h) = (40usize, 30usize);
    let radiance: Vec<f64> = (0..w * h)
        .map(|i| factor * f64::from(1u32 << (i % w / 5)))
        .collect();
    write_hdr(
        path,
        &Picture {
            width_px: w as u32,
            height_px: h as u32,
            view: VIEW.into(),
            radiance_rgb: radiance.iter().map(|&r| DVec3::splat(r)).collect(),
            luminance_cd_m2: radiance.iter().map(|r| r * 179.0).collect(),
            luminance_stderr_cd_m2: vec![0.0; w * h],
            samples_per_pixel: 1,
        },
        None,
    )
    .unwrap();
}

#[test]
fn scaled_picture_json_text_regions_and_png() {
    let dir = tempfile::tempdir().unwrap();
    let (m, r) = (dir.path().join("m.hdr"), dir.path().join("r.hdr"));
    write(&m, 0.5);
    write(&r, 0.625);
    // RGBE decodes mantissa m as (m + ½)/256 (RADIANCE's colr_color): the ratio read back is
    // 160.5/128.5, not 1.25.
    let expected = 160.5 / 128.5 - 1.0;
    let regions = dir.path().join("regions.json");
    std::fs::write(
        &regions,
        r#"[{"name": "left", "polygon": [[0, 0], [20, 0], [20, 30], [0, 30]]}]"#,
    )
    .unwrap();
    let png = dir.path().join("error.png");
    let (ms, rs, gs, ps) = (
        m.to_str().unwrap(),
        r.to_str().unwrap(),
        regions.to_str().unwrap(),
        png.to_str().unwrap(),
    );
    let out = skylux(&["compare", ms, rs, "--regions", gs, "--json", "--png", ps]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let summary = &json["summary"];
    assert_eq!(summary["count"], 1200);
    for key in ["mean_abs", "median_abs", "p90_abs", "mean_signed", "rms"] {
        let v = summary[key].as_f64().unwrap();
        assert!((v - expected).abs() < 1e-9, "{key} {v}");
    }
    assert_eq!(json["regions"][0]["name"], "left");
    assert_eq!(json["regions"][0]["pixels"], 600);
    let hist = &json["histogram"];
    let counts: u64 = hist["measured"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_u64().unwrap())
        .sum();
    assert_eq!(counts, 1200);
    assert!(std::fs::metadata(&png).unwrap().len() > 1000);

    let out = skylux(&["compare", ms, rs]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success()
            && text.contains("1200 compared")
            && text.contains(&format!("{expected:.4}")),
        "{text}"
    );
}

#[test]
fn bad_input_is_a_clear_error() {
    let dir = tempfile::tempdir().unwrap();
    let m = dir.path().join("m.hdr");
    write(&m, 1.0);
    let ms = m.to_str().unwrap();
    let missing = dir.path().join("missing.hdr");
    let out = skylux(&["compare", ms, missing.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        !out.status.success() && err.contains("missing.hdr"),
        "{err}"
    );
    let out = skylux(&["compare", ms, ms, "--rendered-view", "-vd 0 -1 0"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success() && err.contains("same view"), "{err}");
    let out = skylux(&["compare", ms, ms, "--min-luminance", "-1"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success() && err.contains("floor"), "{err}");
}
