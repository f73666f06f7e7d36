//! `skylux render` as a user runs it: the three files, readable by RADIANCE, and clear errors
//! for bad views.

use std::process::{Command, Output};
#[path = "../../core/tests/common/radiance.rs"]
mod radiance;

fn skylux(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_skylux"))
        .args(args)
        .output()
        .expect("running the skylux binary")
}

const SCENE: &str = "void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n\
    grey polygon floor 0 0 12 -50 -50 0 50 -50 0 50 50 0 -50 50 0\n\
    void glow sky_glow 0 0 4 2 2 2 0\nsky_glow source sky 0 0 4 0 0 1 180\n";

#[test]
fn writes_exr_hdr_and_png() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("scene.rad");
    std::fs::write(&scene, SCENE).unwrap();
    let prefix = dir.path().join("out/view1");
    let out = skylux(&[
        "render",
        "--scene",
        scene.to_str().unwrap(),
        "--view",
        "-vtv -vp 0 0 1.5 -vd 0 1 -1 -vu 0 0 1 -vh 60 -vv 40",
        "-x",
        "24",
        "-y",
        "24",
        "--ab",
        "1",
        "--spp",
        "8",
        "--out",
        prefix.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // 60 x 40 degrees: tan 20° / tan 30° of 24 columns = 15 rows (rpict's normaspect).
    assert!(stdout.contains("24x15 pixels"), "{stdout}");
    for ext in ["exr", "hdr", "png"] {
        let p = dir.path().join(format!("out/view1.{ext}"));
        let len = std::fs::metadata(&p).map(|m| m.len()).unwrap_or(0);
        assert!(len > 100, "{} missing or empty", p.display());
    }
    // Every ray looks 25° to 65° down at the floor, which shows ρ L = 0.5 × 2 W/sr/m²:
    // the mean of the .hdr's pixels (RGBE decoded as RADIANCE's colr_color does) is 1 to the
    // Monte-Carlo error of 360 pixels × 8 paths (the sky's next-event estimation makes single
    // paths noisy).
    let hdr = std::fs::read(dir.path().join("out/view1.hdr")).unwrap();
    let body = hdr
        .windows(12)
        .position(|w| w == b"-Y 15 +X 24\n")
        .expect("resolution line")
        + 12;
    let pixels = &hdr[body..];
    assert_eq!(pixels.len(), 24 * 15 * 4, "flat RGBE scanlines");
    let decoded: Vec<[f64; 3]> = pixels
        .chunks_exact(4)
        .map(|p| {
            let f = 2f64.powi(i32::from(p[3]) - 128 - 8);
            [0, 1, 2].map(|c| (f64::from(p[c]) + 0.5) * f)
        })
        .collect();
    let mean = decoded.iter().map(|p| p[0]).sum::<f64>() / decoded.len() as f64;
    assert!((mean - 1.0).abs() < 0.03, "mean red radiance {mean}");
    assert!(decoded.iter().all(|p| p[0] == p[1] && p[1] == p[2]), "grey");

    if let Some((bin, lib)) = radiance::radiance() {
        let mut c = radiance::tool(&bin, &lib, "getinfo");
        c.arg(dir.path().join("out/view1.hdr"));
        let info = String::from_utf8(radiance::check_output(c, None)).unwrap();
        assert!(info.contains("VIEW= -vtv -vp 0 0 1.5"), "{info}");
        assert!(info.contains("FORMAT=32-bit_rle_rgbe"), "{info}");
        let mut c = radiance::tool(&bin, &lib, "getinfo");
        c.arg("-d").arg(dir.path().join("out/view1.hdr"));
        let dims = String::from_utf8(radiance::check_output(c, None)).unwrap();
        assert!(dims.contains("-Y 15 +X 24"), "{dims}");
    } else {
        skylux_hps::prerequisite::available_or_skip(
            false,
            skylux_hps::prerequisite::REQUIRE_RADIANCE,
            "the getinfo check: RADIANCE not found",
        );
    }
}

#[test]
fn bad_views_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("scene.rad");
    std::fs::write(&scene, SCENE).unwrap();
    let prefix = dir.path().join("x");
    for (view, expect) in [
        ("-vtv -vh wide", "-vh"),
        ("-vtz", "-vtz"),
        ("-vtv -vp 1 2", "-vp"),
        ("-vtv -vh 200", "horizontal view size"),
        ("-vtv -vd 0 0 0", "zero view direction"),
    ] {
        let out = skylux(&[
            "render",
            "--scene",
            scene.to_str().unwrap(),
            "--view",
            view,
            "-x",
            "4",
            "-y",
            "4",
            "--out",
            prefix.to_str().unwrap(),
        ]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{view} accepted");
        assert!(stderr.contains(expect), "{view}: {stderr}");
        assert!(!stderr.contains("panicked"), "{view}: {stderr}");
    }
    // A view file with a bad line is named with its line number.
    let vf = dir.path().join("bad.vf");
    std::fs::write(&vf, "-vtv -vp 0 0 1\n-vd 0 1 x\n").unwrap();
    let out = skylux(&[
        "render",
        "--scene",
        scene.to_str().unwrap(),
        "--view-file",
        vf.to_str().unwrap(),
        "--out",
        prefix.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(
        stderr.contains("bad.vf:2") && stderr.contains("-vd"),
        "{stderr}"
    );
}
