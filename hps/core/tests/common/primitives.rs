//! Primitive lists from RADIANCE's programs, and their comparison with Skylux's.
#![allow(dead_code)]

use skylux_hps::scene::{self, Primitive};
use std::path::{Path, PathBuf};
use std::process::Command;

/// What RADIANCE writes for `command`, run in `dir`.
pub fn theirs(bin: &Path, lib: &Option<PathBuf>, dir: &Path, command: &str) -> Vec<Primitive> {
    let mut path = std::ffi::OsString::from(bin);
    path.push(":");
    path.push(std::env::var_os("PATH").unwrap_or_default());
    let mut c = Command::new("/bin/sh");
    c.arg("-c").arg(command).current_dir(dir).env("PATH", path);
    if let Some(lib) = lib {
        let mut raypath = std::ffi::OsString::from(".:");
        raypath.push(lib);
        c.env("RAYPATH", raypath);
    }
    let out = c.output().unwrap();
    assert!(
        out.status.success(),
        "`{command}` failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    scene::parse_primitives(format!("output of {command}"), &text)
        .unwrap_or_else(|e| panic!("{command}: {e}\n{text}"))
}

/// Equal lists; reals within `abs + rel * max(|a|, |b|)`.
pub fn assert_same(command: &str, ours: &[Primitive], theirs: &[Primitive], abs: f64, rel: f64) {
    assert_eq!(
        ours.len(),
        theirs.len(),
        "{command}: {} primitives, RADIANCE {}",
        ours.len(),
        theirs.len()
    );
    for (a, b) in ours.iter().zip(theirs) {
        let what = format!("{command}: {} {} {}", b.modifier, b.type_name, b.identifier);
        assert_eq!(
            (&a.modifier, &a.type_name, &a.identifier),
            (&b.modifier, &b.type_name, &b.identifier),
            "{what}"
        );
        assert_eq!(a.strings, b.strings, "{what}");
        assert_eq!(a.integers, b.integers, "{what}");
        assert_eq!(
            a.reals.len(),
            b.reals.len(),
            "{what}: {:?} vs {:?}",
            a.reals,
            b.reals
        );
        // xform writes these three with `%12.6g` (6 significant digits), the rest with more.
        let rel = if matches!(b.type_name.as_str(), "dielectric" | "interface" | "mist") {
            rel.max(1e-6)
        } else {
            rel
        };
        for (x, y) in a.reals.iter().zip(&b.reals) {
            assert!(
                (x - y).abs() <= abs + rel * x.abs().max(y.abs()),
                "{what}: {:?} vs RADIANCE {:?}",
                a.reals,
                b.reals
            );
        }
    }
}
