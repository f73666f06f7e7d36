//! Inline commands that cannot be expanded: each is an error naming the file and line of the
//! command (and what is wrong), never a hang or a panic; and `--allow-commands` runs what
//! Skylux does not implement through the shell, in the file's directory.

use skylux_hps::scene::{self, LoadOptions, SceneError, MAX_INCLUDE_DEPTH};
use std::path::Path;

fn write(dir: &Path, name: &str, text: &str) {
    std::fs::write(dir.join(name), text).unwrap();
}

/// Loads `dir/top.rad` and returns the error text; it must start with `file:line:`.
fn error_of(dir: &Path, file: &str, line: usize) -> (SceneError, String) {
    let err = scene::load(dir.join("top.rad")).expect_err("expected an error");
    let text = err.to_string();
    let at = err.location().expect("a location");
    assert_eq!(at.file.file_name().unwrap(), file, "{text}");
    assert_eq!(at.line, line, "{text}");
    (err, text)
}

const MATERIAL: &str = "void plastic m 0 0 5 .5 .5 .5 0 0\n";

#[test]
fn an_include_cycle_is_reported_with_its_chain() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "top.rad", &format!("{MATERIAL}!xform a.rad\n"));
    write(dir.path(), "a.rad", "# a\n!xform -rz 10 b.rad\n");
    write(dir.path(), "b.rad", "\n\n!xform a.rad\n");
    let (err, text) = error_of(dir.path(), "b.rad", 3);
    assert!(matches!(err, SceneError::IncludeCycle { .. }), "{text}");
    assert!(text.contains("top.rad:2 -> "), "{text}");
    assert!(text.contains("a.rad:2 -> "), "{text}");
    assert!(text.contains("b.rad:3 -> "), "{text}");
}

#[test]
fn a_file_including_itself_is_a_cycle() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "top.rad", "!xform -t 1 0 0 top.rad\n");
    let (err, _) = error_of(dir.path(), "top.rad", 1);
    assert!(matches!(err, SceneError::IncludeCycle { .. }), "{err}");
}

#[test]
fn includes_deeper_than_the_limit_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "top.rad", "!xform f0.rad\n");
    for k in 0..=MAX_INCLUDE_DEPTH {
        write(
            dir.path(),
            &format!("f{k}.rad"),
            &format!("!xform f{}.rad\n", k + 1),
        );
    }
    let err = scene::load(dir.path().join("top.rad")).unwrap_err();
    assert!(matches!(err, SceneError::IncludeDepth { .. }), "{err}");
    assert!(
        err.to_string()
            .contains(&format!("more than {MAX_INCLUDE_DEPTH} deep")),
        "{err}"
    );
    assert_eq!(err.location().unwrap().line, 1);
}

#[test]
fn a_missing_include_names_the_command_and_the_file() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        "top.rad",
        &format!("{MATERIAL}\n!xform -rz 90 \\\n  objects/Gone.rad\n"),
    );
    let (err, text) = error_of(dir.path(), "top.rad", 3);
    assert!(matches!(err, SceneError::MissingInclude { .. }), "{text}");
    assert!(text.contains("objects/Gone.rad"), "{text}");
}

#[test]
fn array_copies_are_capped() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        "part.rad",
        &format!("{MATERIAL}m sphere s 0 0 4 0 0 0 1\n"),
    );
    write(
        dir.path(),
        "top.rad",
        "\n!xform -a 1000 -t 1 0 0 -a 1000 -t 0 1 0 part.rad\n",
    );
    let (_, text) = error_of(dir.path(), "top.rad", 2);
    assert!(text.contains("10000"), "{text}");
    // Nested files multiply: each level is under the cap, the product is not expanded.
    write(dir.path(), "row.rad", "!xform -a 9000 -t 1 0 0 part.rad\n");
    write(dir.path(), "top.rad", "!xform -a 9000 -t 0 1 0 row.rad\n");
    let (err, _) = error_of(dir.path(), "top.rad", 1);
    assert!(matches!(err, SceneError::TooManyPrimitives { .. }), "{err}");
}

#[test]
fn generators_with_bad_options_say_which() {
    let dir = tempfile::tempdir().unwrap();
    for (command, needle) in [
        ("genbox m b 1 2", "usage"),
        ("genbox m b 1 -2 3", "positive"),
        ("genbox m b 1 2 3 -r 0.1 -n 4", "segmented"),
        ("genblinds m b 1 1 1 0 30", "nslats"),
        ("genblinds m b 1 1 1 3 30 -r 0.1", "curved"),
        ("genprism m p 2 0 0 1 1", "not enough"),
        ("genprism m p - ", "standard input"),
        ("genprism m p 4 0 0 1 0 1 1 0 1 -l 1 1 0", "extrusion"),
        ("genrev m r 't' 'k*t' 8", "k: undefined variable"),
        (
            "genrev m r 't' '1' 8 -f absent.cal",
            "cannot find file `absent.cal`",
        ),
        ("genrev m r 't' '1' 8 -e 'k=2;;('", "-e `k=2;;(`"),
        ("genrev m r 't' '1' 0", "nseg is `0`"),
        ("genworm m w t 0 0 0.1", "usage"),
        ("gensurf m s s t 0 2 2 -o", "Wavefront"),
        ("gensurf m s s t - 2 2", "standard input"),
        ("gensky 13 1 12", "bad date"),
        ("gensky 3 21 12XYZ", "time zone"),
        ("gensky 3 21 12 -y 2020", "-y"),
        ("gendaylit -ang 40 0 -L 8000 100", "-L"),
        ("gendaylit -ang 40 0", "-W, -G or -P"),
        ("xform -q 1 f.rad", "-q"),
        ("xform", "standard input"),
        (
            "genbox m b 1 1 1 | xform -rz 10 other.rad",
            "must read the pipe",
        ),
    ] {
        write(dir.path(), "top.rad", &format!("{MATERIAL}!{command}\n"));
        let (_, text) = error_of(dir.path(), "top.rad", 2);
        assert!(text.contains(needle), "{command}: `{needle}` not in {text}");
    }
}

#[test]
fn other_commands_need_allow_commands_and_then_run_in_the_file_directory() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("sub")).unwrap();
    write(
        dir.path(),
        "sub/ball.txt",
        "m sphere ball 0 0 4 1 2 3 0.5\n",
    );
    write(dir.path(), "sub/inner.rad", "!cat ball.txt\n");
    write(
        dir.path(),
        "top.rad",
        &format!("{MATERIAL}!xform -t 1 0 0 sub/inner.rad\n"),
    );
    let (err, text) = error_of(dir.path(), "inner.rad", 1);
    assert!(
        matches!(err, SceneError::UnsupportedCommand { .. }),
        "{text}"
    );
    assert!(
        text.contains("`cat`") && text.contains("--allow-commands"),
        "{text}"
    );

    let allow = LoadOptions {
        allow_commands: true,
        ..Default::default()
    };
    let loaded = scene::load_files_with(&[dir.path().join("top.rad")], &allow).unwrap();
    let scene::Shape::Sphere(ball) = &loaded.surfaces()[0].shape else {
        panic!("not a sphere")
    };
    assert_eq!(ball.centre_m, glam::DVec3::new(2.0, 2.0, 3.0));

    write(dir.path(), "top.rad", &format!("{MATERIAL}!false\n"));
    let err = scene::load_files_with(&[dir.path().join("top.rad")], &allow).unwrap_err();
    assert!(err.to_string().contains("the shell reports"), "{err}");
}

#[test]
fn shell_syntax_is_not_run_without_allow_commands() {
    let dir = tempfile::tempdir().unwrap();
    let marker = dir.path().join("ran");
    write(
        dir.path(),
        "top.rad",
        &format!("!genbox m b 1 1 1 > {}\n", marker.display()),
    );
    let (_, text) = error_of(dir.path(), "top.rad", 1);
    assert!(text.contains("shell syntax `>`"), "{text}");
    assert!(!marker.exists());
}

#[test]
fn generated_primitives_are_placed_at_their_command() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        "top.rad",
        &format!("{MATERIAL}\n!genbox m box 1 2 3 \\\n   -b 0.1\n"),
    );
    let loaded = scene::load(dir.path().join("top.rad")).unwrap();
    assert_eq!(loaded.surfaces().len(), 26);
    assert!(loaded.surfaces().iter().all(|s| s.origin.line == 3));
}
