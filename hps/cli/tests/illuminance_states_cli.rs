//! `skylux illuminance --window --state ...` as a user runs it: every state's lux in CSV, the
//! room's matrices traced once and read back for the next sky, clear errors for bad input.
//! (The physics, against rtrace: hps/core/tests/shading_states.rs.)

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn skylux(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_skylux"))
        .args(args)
        .output()
        .expect("running the skylux binary")
}

fn corpus(file: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/data/radiance-corpus")
        .join(file)
}

/// A 4 m × 5 m × 3 m room, its south window (x 1..3, z 0.9..2.1) glazed with a BSDF.
fn room(xml: &Path) -> String {
    let mut s = format!(
        "void BSDF pane\n6 0 {} 0 0 1 .\n0\n0\n\
         void plastic wall 0 0 5 0.5 0.5 0.5 0 0\n\
         pane polygon glazing 0 0 12 1 0 0.9 1 0 2.1 3 0 2.1 3 0 0.9\n",
        xml.display()
    );
    let quads = [
        [[0., 0., 0.], [4., 0., 0.], [4., 5., 0.], [0., 5., 0.]],
        [[0., 0., 3.], [0., 5., 3.], [4., 5., 3.], [4., 0., 3.]],
        [[4., 0., 0.], [4., 0., 3.], [4., 5., 3.], [4., 5., 0.]],
        [[0., 0., 0.], [0., 5., 0.], [0., 5., 3.], [0., 0., 3.]],
        [[0., 5., 0.], [4., 5., 0.], [4., 5., 3.], [0., 5., 3.]],
        [[0., 0., 0.], [0., 0., 0.9], [4., 0., 0.9], [4., 0., 0.]],
        [[0., 0., 2.1], [0., 0., 3.], [4., 0., 3.], [4., 0., 2.1]],
        [[0., 0., 0.9], [0., 0., 2.1], [1., 0., 2.1], [1., 0., 0.9]],
        [[3., 0., 0.9], [3., 0., 2.1], [4., 0., 2.1], [4., 0., 0.9]],
    ];
    for (k, q) in quads.iter().enumerate() {
        s.push_str(&format!("wall polygon w{k} 0 0 12"));
        for c in q {
            s.push_str(&format!(" {} {} {}", c[0], c[1], c[2]));
        }
        s.push('\n');
    }
    s
}

/// A uniform sky and ground and a sun in the south at `altitude_deg`.
fn sky(altitude_deg: f64) -> String {
    let a = altitude_deg.to_radians();
    format!(
        "void glow sky_glow 0 0 4 20 20 20 0\nsky_glow source sky 0 0 4 0 0 1 180\n\
         void glow ground_glow 0 0 4 5 5 5 0\nground_glow source ground 0 0 4 0 0 -1 180\n\
         void light solar 0 0 3 6e6 6e6 6e6\nsolar source sun 0 0 4 0 {} {} 0.533\n",
        -a.cos(),
        a.sin()
    )
}

struct Files {
    dir: tempfile::TempDir,
}

impl Files {
    fn new() -> Self {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path();
        std::fs::write(p.join("room.rad"), room(&corpus("bsdf/frads/2011-SA1.xml"))).unwrap();
        std::fs::write(p.join("high-sun.rad"), sky(60.0)).unwrap();
        std::fs::write(p.join("low-sun.rad"), sky(20.0)).unwrap();
        std::fs::write(
            p.join("window.rad"),
            "void glow w 0 0 4 1 1 1 0\nw polygon window 0 0 12 1 0 0.9 1 0 2.1 3 0 2.1 3 0 0.9\n",
        )
        .unwrap();
        std::fs::write(
            p.join("s.pts"),
            "2 1.5 0.8 0 0 1\n2 4 0.8 0 0 1\n2 3 1.2 0 -1 0\n",
        )
        .unwrap();
        Files { dir }
    }

    fn path(&self, name: &str) -> String {
        self.dir.path().join(name).display().to_string()
    }

    fn run(&self, sky: &str, states: &[String]) -> Output {
        let (room, sky, window, pts, matrices) = (
            self.path("room.rad"),
            self.path(sky),
            self.path("window.rad"),
            self.path("s.pts"),
            self.path("matrices"),
        );
        let mut args = vec![
            "illuminance",
            "--scene",
            &room,
            "--scene",
            &sky,
            "--sensors",
            &pts,
            "--window",
            &window,
            "--matrices",
            &matrices,
            "--window-paths",
            "4096",
            "--d-samples",
            "512",
            "--mf",
            "2",
        ];
        for s in states {
            args.extend(["--state", s.as_str()]);
        }
        skylux(&args)
    }
}

fn states() -> Vec<String> {
    vec![
        format!("satine={}", corpus("bsdf/frads/2011-SA1.xml").display()),
        format!("blinds30={}", corpus("bsdf/frads/blinds30.xml").display()),
    ]
}

fn lux(out: &Output) -> Vec<(String, String, f64)> {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout.clone()).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("state,sensor,lux"));
    lines
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            (f[0].to_string(), f[1].to_string(), f[2].parse().unwrap())
        })
        .collect()
}

#[test]
fn every_state_per_sky_from_matrices_traced_once() {
    let files = Files::new();
    let first = files.run("high-sun.rad", &states());
    let stderr = String::from_utf8_lossy(&first.stderr).to_string();
    assert!(stderr.contains("traced and written to"), "{stderr}");
    assert!(stderr.contains("glazing"), "the glazing is named: {stderr}");
    let high = lux(&first);
    let names: Vec<(&str, &str)> = high
        .iter()
        .map(|(s, n, _)| (s.as_str(), n.as_str()))
        .collect();
    assert_eq!(
        names,
        [
            ("satine", "S1"),
            ("satine", "S2"),
            ("satine", "S3"),
            ("blinds30", "S1"),
            ("blinds30", "S2"),
            ("blinds30", "S3")
        ]
    );
    assert!(high.iter().all(|(_, _, l)| *l > 1.0), "{high:?}");
    // The shade and the blinds give different light.
    assert!((high[0].2 / high[3].2 - 1.0).abs() > 0.05, "{high:?}");

    // The same room under another sky: the matrices are read, not traced.
    let second = files.run("low-sun.rad", &states());
    let stderr = String::from_utf8_lossy(&second.stderr).to_string();
    assert!(stderr.contains("read from"), "{stderr}");
    let low = lux(&second);
    assert!(low
        .iter()
        .zip(&high)
        .any(|(a, b)| (a.2 / b.2 - 1.0).abs() > 0.05));
    // And the first sky again: what the traced matrices gave, to the printed digits.
    let again = lux(&files.run("high-sun.rad", &states()));
    for (a, b) in again.iter().zip(&high) {
        assert!(
            (a.2 - b.2).abs() <= 1e-3 * b.2.abs().max(1.0),
            "{a:?} vs {b:?}"
        );
    }
    // One state alone reads the same matrices and gives that state's numbers.
    let one = lux(&files.run("high-sun.rad", &states()[1..]));
    for (a, b) in one.iter().zip(&high[3..]) {
        assert!(
            (a.2 - b.2).abs() <= 1e-3 * b.2.abs().max(1.0),
            "{a:?} vs {b:?}"
        );
    }
}

#[test]
fn bad_states_are_clear_errors() {
    let files = Files::new();
    let err = |states: &[String]| {
        let out = files.run("high-sun.rad", states);
        assert!(!out.status.success());
        String::from_utf8_lossy(&out.stderr).to_string()
    };
    assert!(err(&["satine".into()]).contains("NAME=XML"));
    let missing = files.path("nothing.xml");
    let e = err(&[format!("gone={missing}")]);
    assert!(e.contains("gone") && e.contains("nothing.xml"), "{e}");
    let twice = states()[0].clone();
    assert!(err(&[twice.clone(), twice]).contains("twice"));
    let bad_name = format!("a b={}", corpus("bsdf/frads/ec60.xml").display());
    assert!(err(&[bad_name]).contains("letters, digits"));
}
