//! `skylux genbsdf` as a user runs it: a Klems XML and its standard errors from a device
//! file, tensor trees (t3, t4), the summary it prints, and clear errors for bad input.
//! (The physics, against genBSDF: hps/core/tests/genbsdf_vs_radiance.rs.)

use skylux_hps::bsdf::{Bsdf, Scattering};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn skylux(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_skylux"))
        .args(args)
        .output()
        .expect("running the skylux binary")
}

fn blind() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../core/tests/fixtures/genbsdf/blind45.rad")
}

const DIM: [&str; 6] = ["0.1", "0.9", "0.1", "0.9", "-0.0176777", "0"];

fn run_ok(args: &[&str]) -> String {
    let out = skylux(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn klems_xml_with_its_errors_and_summary() {
    let dir = tempfile::tempdir().unwrap();
    let (xml, se) = (
        dir.path().join("blind.xml"),
        dir.path().join("blind.se.xml"),
    );
    let blind = blind();
    let mut args = vec![
        "genbsdf",
        blind.to_str().unwrap(),
        "--out",
        xml.to_str().unwrap(),
    ];
    args.extend([
        "--errors",
        se.to_str().unwrap(),
        "--samples",
        "256",
        "--dim",
    ]);
    args.extend(DIM);
    let stdout = run_ok(&args);
    for part in [
        "Reflection Back",
        "Reflection Front",
        "Transmission Back",
        "Transmission Front",
    ] {
        assert!(stdout.contains(part), "{stdout}");
    }
    assert!(stdout.contains("reciprocity, transmission"), "{stdout}");
    let bsdf = Bsdf::load(&xml).unwrap();
    // Light at normal incidence from the room: the 45° slats pass some and reflect some.
    let normal = glam::DVec3::Z;
    let t = bsdf.hemispherical(normal, Scattering::Transmission);
    let r = bsdf.hemispherical(normal, Scattering::Reflection);
    assert!(
        t > 0.2 && t < 0.6 && r > 0.1 && r < 0.5 && t + r < 1.0,
        "T {t} R {r}"
    );
    // The errors file has the same layout: every element's standard error, non-negative.
    let text = std::fs::read_to_string(&se).unwrap();
    assert!(text.contains("standard errors of blind45"));
    assert!(Bsdf::load(&se).is_ok());
    // The command that made the file is in it.
    assert!(std::fs::read_to_string(&xml)
        .unwrap()
        .contains("Created by: skylux genbsdf"));
}

#[test]
fn tensor_trees_isotropic_and_anisotropic() {
    let dir = tempfile::tempdir().unwrap();
    let blind = blind();
    for (tree, log2) in [("t3", "3"), ("t4", "3")] {
        let xml = dir.path().join(format!("blind-{tree}.xml"));
        let mut args = vec![
            "genbsdf",
            blind.to_str().unwrap(),
            "--out",
            xml.to_str().unwrap(),
        ];
        let se = dir.path().join(format!("blind-{tree}.se.xml"));
        args.extend(["--errors", se.to_str().unwrap()]);
        args.extend([
            "--tree",
            tree,
            "--tree-log2",
            log2,
            "--samples",
            "128",
            "--dim",
        ]);
        args.extend(DIM);
        let stdout = run_ok(&args);
        assert!(stdout.contains("TensorTree"), "{stdout}");
        let bsdf = Bsdf::load(&xml).unwrap();
        assert!(bsdf.has_tensor_tree(), "{tree}");
        let t = bsdf.hemispherical(glam::DVec3::new(-0.3, 0.0, 0.954), Scattering::Transmission);
        assert!(t > 0.1 && t < 0.8, "{tree}: T {t}");
        // The errors in the tree's own layout: a tree of the same shape.
        assert!(Bsdf::load(&se).unwrap().has_tensor_tree(), "{tree}");
    }
}

#[test]
fn bad_input_is_a_clear_error() {
    let dir = tempfile::tempdir().unwrap();
    let xml = dir.path().join("x.xml");
    let out_path = xml.to_str().unwrap();
    let check = |args: &[&str], expect: &str| {
        let out = skylux(args);
        assert!(!out.status.success(), "{args:?} succeeded");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(expect), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    };
    check(
        &["genbsdf", "/no/such/device.rad", "--out", out_path],
        "/no/such/device.rad",
    );
    let blind = blind();
    let b = blind.to_str().unwrap();
    // A box with no area, and one wholly in the room.
    check(
        &[
            "genbsdf", b, "--out", out_path, "--dim", "0", "0", "0", "1", "-1", "0",
        ],
        "--dim",
    );
    check(
        &[
            "genbsdf", b, "--out", out_path, "--dim", "0", "1", "0", "1", "0.5", "1",
        ],
        "room",
    );
    check(
        &["genbsdf", b, "--out", out_path, "--samples", "1"],
        "samples per patch",
    );
    check(
        &[
            "genbsdf",
            b,
            "--out",
            out_path,
            "--tree",
            "t4",
            "--tree-log2",
            "9",
        ],
        "resolution",
    );
    // A device file holding a sky.
    let sky = dir.path().join("with-sky.rad");
    std::fs::write(
        &sky,
        "void glow g 0 0 4 1 1 1 0\ng source s 0 0 4 0 0 1 180\n\
         void plastic p 0 0 5 .5 .5 .5 0 0\np polygon f 0 0 12 0 0 -1 1 0 -1 1 1 -1 0 1 -1\n",
    )
    .unwrap();
    check(
        &["genbsdf", sky.to_str().unwrap(), "--out", out_path],
        "sky",
    );
    // A device file with no surface at all.
    let empty = dir.path().join("empty.rad");
    std::fs::write(&empty, "# nothing\n").unwrap();
    check(
        &["genbsdf", empty.to_str().unwrap(), "--out", out_path],
        "no surface",
    );
}
