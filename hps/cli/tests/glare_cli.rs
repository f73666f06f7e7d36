//! `skylux glare` as a user runs it: the JSON and text reports on the corpus's fisheye
//! photograph (checked against the values its PROVENANCE.txt records from evalglare), the
//! PNG with the sources outlined, and clear errors for bad pictures.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn skylux(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_skylux"))
        .args(args)
        .output()
        .expect("running the skylux binary")
}

fn corpus_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/data/radiance-corpus/glare-testimage")
}

fn corpus_image() -> String {
    corpus_dir()
        .join("resources/evalglare/testimage.hdr")
        .to_string_lossy()
        .into_owned()
}

/// The number after `key` in PROVENANCE.txt.
fn provenance_value(key: &str) -> f64 {
    let text = std::fs::read_to_string(corpus_dir().join("PROVENANCE.txt")).unwrap();
    let rest = &text[text.find(key).expect("key in PROVENANCE.txt") + key.len()..];
    let number: String = rest
        .trim_start()
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '.')
        .collect();
    number.parse().unwrap()
}

#[test]
fn json_text_and_png() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("sources.png");
    let out = skylux(&[
        "glare",
        &corpus_image(),
        "--json",
        "--png",
        png.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: serde_json::Value = serde_json::from_str(&stdout).expect("--json prints JSON");
    for key in ["ev_lux", "dgp", "dgi", "ugr", "cgi", "vcp"] {
        assert!(json[key].is_f64(), "{key} missing in {json}");
    }
    let ev = json["ev_lux"].as_f64().unwrap();
    let dgp = json["dgp"].as_f64().unwrap();
    assert!((ev - provenance_value("E_v =")).abs() < 1e-3 * ev, "{ev}");
    assert!((dgp - provenance_value("dgp")).abs() < 0.005, "{dgp}");
    let sources = json["sources"].as_array().expect("sources is a list");
    assert_eq!(sources.len(), 3);
    for s in sources {
        for key in [
            "column_px",
            "row_px",
            "solid_angle_sr",
            "mean_luminance_cd_m2",
            "position_index",
        ] {
            assert!(s[key].is_f64(), "source {key} missing: {s}");
        }
        assert_eq!(s["direction"].as_array().map(Vec::len), Some(3));
    }
    let bytes = std::fs::read(&png).expect("the PNG is written");
    assert!(bytes.starts_with(b"\x89PNG") && bytes.len() > 1000);

    let out = skylux(&["glare", &corpus_image(), "-b", "5"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success());
    assert!(
        text.contains("DGP ") && text.contains("glare source(s)"),
        "{text}"
    );
}

#[test]
fn bad_pictures_fail_with_a_clear_message() {
    let dir = tempfile::tempdir().unwrap();
    let no_view = dir.path().join("no_view.hdr");
    let mut bytes = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n".to_vec();
    bytes.extend_from_slice(&[100, 100, 100, 130].repeat(4));
    std::fs::write(&no_view, &bytes).unwrap();
    let whole = std::fs::read(corpus_image()).unwrap();
    let cut = dir.path().join("cut.hdr");
    std::fs::write(&cut, &whole[..whole.len() / 2]).unwrap();
    let corpus = corpus_image();
    let cases: [(&[&str], &str); 4] = [
        (&["glare", no_view.to_str().unwrap()], "no view"),
        (&["glare", cut.to_str().unwrap()], "truncated"),
        (
            &["glare", &corpus, "--view", "-vtv -vh 60 -vv 60"],
            "looks like a fisheye",
        ),
        (&["glare", &corpus, "-r", "-1"], "must be a positive number"),
    ];
    for (args, message) in cases {
        let out = skylux(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?} succeeded");
        assert!(stderr.contains(message), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}
