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

/// Luminance (cd/m², RADIANCE's 179 lm/W and its RGB weights) that `rtrace -ab 0` sees from
/// the origin along each of `directions` in the scene `text` (written, with its octree, into
/// `dir` under `name`). Rays go in through a file: piped while rtrace answers they would
/// fill both pipes; and as short numbers, since rtrace splits words longer than its buffer.
pub fn rtrace_luminance(
    bin: &Path,
    lib: &Option<PathBuf>,
    dir: &Path,
    name: &str,
    text: &str,
    directions: &[glam::DVec3],
) -> Vec<f64> {
    let rad = dir.join(format!("{name}.rad"));
    std::fs::write(&rad, text).unwrap();
    let mut oconv = tool(bin, lib, "oconv");
    oconv.current_dir(dir).arg(&rad);
    let oct = dir.join(format!("{name}.oct"));
    std::fs::write(&oct, check_output(oconv, None)).unwrap();
    let rays = dir.join(format!("{name}.rays"));
    let input: String = directions
        .iter()
        .map(|d| format!("0 0 0 {:.12e} {:.12e} {:.12e}\n", d.x, d.y, d.z))
        .collect();
    std::fs::write(&rays, input).unwrap();
    let mut rtrace = tool(bin, lib, "rtrace");
    rtrace
        .current_dir(dir)
        .args(["-h", "-w", "-ov", "-ab", "0"])
        .arg(&oct)
        .stdin(std::fs::File::open(&rays).unwrap());
    let run = rtrace.output().unwrap();
    assert!(
        run.status.success(),
        "rtrace: {}",
        String::from_utf8_lossy(&run.stderr)
    );
    let lum: Vec<f64> = String::from_utf8_lossy(&run.stdout)
        .lines()
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|t| t.parse().unwrap()).collect();
            179.0 * (0.265 * v[0] + 0.670 * v[1] + 0.065 * v[2])
        })
        .collect();
    assert_eq!(lum.len(), directions.len(), "rtrace answered every ray");
    lum
}
