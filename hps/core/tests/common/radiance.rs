//! Finding and running RADIANCE (from the pyradiance wheel, `SKYLUX_RADIANCE_BIN`, or PATH)
//! for the tests that compare with it.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// The folder holding rtrace, gensky and oconv, and the RAYPATH (its lib folder) if known.
pub fn radiance() -> Option<(PathBuf, Option<PathBuf>)> {
    let has = |dir: &Path| dir.join("rtrace").is_file() && dir.join("gensky").is_file();
    if let Some(dir) = std::env::var_os("SKYLUX_RADIANCE_BIN").map(PathBuf::from) {
        if has(&dir) {
            let lib = dir.parent().map(|p| p.join("lib")).filter(|l| l.is_dir());
            return Some((dir, lib));
        }
    }
    let out = Command::new("python3")
        .args([
            "-c",
            "import pyradiance, os; print(os.path.dirname(pyradiance.__file__))",
        ])
        .stderr(Stdio::null())
        .output()
        .ok()?;
    if out.status.success() {
        let root = PathBuf::from(String::from_utf8_lossy(&out.stdout).trim());
        if has(&root.join("bin")) {
            return Some((root.join("bin"), Some(root.join("lib"))));
        }
    }
    std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .find(|d| has(d))
            .map(|d| (d, None))
    })
}

pub fn tool(bin: &Path, lib: &Option<PathBuf>, name: &str) -> Command {
    let mut c = Command::new(bin.join(name));
    if let Some(lib) = lib {
        // "." first, as RADIANCE's default RAYPATH has it: function files beside the scene.
        let mut path = std::ffi::OsString::from(".:");
        path.push(lib);
        c.env("RAYPATH", path);
    }
    c
}

pub fn check_output(mut c: Command, input: Option<&[u8]>) -> Vec<u8> {
    use std::io::Write;
    c.stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    let mut child = c.spawn().unwrap_or_else(|e| panic!("running {c:?}: {e}"));
    let mut stdin = child.stdin.take().unwrap();
    if let Some(input) = input {
        stdin.write_all(input).unwrap();
    }
    drop(stdin);
    let out = child.wait_with_output().unwrap();
    assert!(
        out.status.success(),
        "{c:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out.stdout
}
