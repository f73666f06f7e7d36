//! `skylux scene check` on scenes written here and on the tutorial room of the corpus.

use std::path::{Path, PathBuf};
use std::process::Command;

fn check(dir: &Path, args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_skylux"))
        .args(["scene", "check"])
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_scene_in_feet_with_a_generated_box_is_reported() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("room.rad"),
        "void plastic wall 0 0 5 .5 .5 .5 0 0\n\
         void plastic unused 0 0 5 .2 .2 .2 0 0\n\
         void brightfunc wood 2 grain wood.cal 0 0\n\
         wall sphere ball 0 0 4 1 1 1 .5\n\
         !genbox wall room 20 30 10\n",
    )
    .unwrap();
    let (ok, stdout, stderr) = check(dir.path(), &["room.rad", "--json"]);
    assert!(ok, "{stderr}");
    let report: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(report["surfaces"]["polygon"], 6);
    assert_eq!(report["surfaces"]["sphere"], 1);
    assert_eq!(report["modifiers"]["plastic"], 2);
    assert_eq!(
        report["bounds"]["max"],
        serde_json::json!([20.0, 30.0, 10.0])
    );
    assert!(report["units_hint"].as_str().unwrap().starts_with("feet"));
    let unused = report["unused_modifiers"].to_string();
    assert!(
        unused.contains("unused") && unused.contains("wood"),
        "{unused}"
    );
    assert!(report["missing_files"].to_string().contains("wood.cal"));
    assert_eq!(report["engine_loads"], true);
}

#[test]
fn a_missing_include_is_an_error_naming_it() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("top.rad"), "\n!xform objects/gone.rad\n").unwrap();
    let (ok, _, stderr) = check(dir.path(), &["top.rad"]);
    assert!(!ok);
    assert!(
        stderr.contains("top.rad:2") && stderr.contains("objects/gone.rad"),
        "{stderr}"
    );
}

#[test]
fn the_tutorial_room_loads_in_metres() {
    let room = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/data/radiance-corpus/sariths-matrix-tutorial/room");
    assert!(room.is_dir(), "the corpus is missing at {}", room.display());
    let (ok, stdout, stderr) = check(&room, &["materials.rad", "room.rad"]);
    assert!(ok, "{stderr}");
    assert!(stdout.contains("surfaces: 18 polygon"), "{stdout}");
    assert!(stdout.contains("units: metres"), "{stdout}");
    assert!(stdout.contains("glass `Glazing`"), "{stdout}");
    assert!(stdout.contains("engine: loads"), "{stdout}");
}
