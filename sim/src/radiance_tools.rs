//! Finding and running the RADIANCE programs (from `SKYLUX_RADIANCE_BIN`, the pyradiance
//! wheel, or PATH): the one place that knows where they are, for the benches and the
//! simulator's independent truth ([`crate::radiance_truth`]).

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// The programs a usable installation must hold.
const REQUIRED: [&str; 5] = ["rtrace", "rcontrib", "oconv", "gendaylit", "gensky"];

/// Why RADIANCE could not be found or a program failed.
#[derive(Debug, thiserror::Error)]
pub enum RadianceError {
    #[error(
        "RADIANCE ({}) not found: install it with `pip install pyradiance`, or set \
         SKYLUX_RADIANCE_BIN to the folder holding rtrace",
        REQUIRED.join(", ")
    )]
    NotFound,
    #[error("running {command}: {source}")]
    Spawn {
        command: String,
        source: std::io::Error,
    },
    #[error("{command} failed: {stderr}")]
    Failed { command: String, stderr: String },
}

/// Where the RADIANCE programs are, and RAYPATH's library folder (the `.cal` files).
#[derive(Clone, Debug)]
pub struct Radiance {
    pub bin: PathBuf,
    pub lib: Option<PathBuf>,
}

impl Radiance {
    /// From `SKYLUX_RADIANCE_BIN`, the pyradiance wheel, or PATH, in that order.
    pub fn find() -> Result<Self, RadianceError> {
        let has = |dir: &Path| REQUIRED.iter().all(|t| dir.join(t).is_file());
        if let Some(dir) = std::env::var_os("SKYLUX_RADIANCE_BIN").map(PathBuf::from) {
            if has(&dir) {
                let lib = dir.parent().map(|p| p.join("lib")).filter(|l| l.is_dir());
                return Ok(Self { bin: dir, lib });
            }
        }
        if let Ok(out) = Command::new("python3")
            .args([
                "-c",
                "import pyradiance, os; print(os.path.dirname(pyradiance.__file__))",
            ])
            .stderr(Stdio::null())
            .output()
        {
            if out.status.success() {
                let root = PathBuf::from(String::from_utf8_lossy(&out.stdout).trim());
                if has(&root.join("bin")) {
                    return Ok(Self {
                        bin: root.join("bin"),
                        lib: Some(root.join("lib")),
                    });
                }
            }
        }
        if let Some(paths) = std::env::var_os("PATH") {
            if let Some(d) = std::env::split_paths(&paths).find(|d| has(d)) {
                return Ok(Self { bin: d, lib: None });
            }
        }
        Err(RadianceError::NotFound)
    }

    /// A command for program `name`, with RAYPATH set to "." then the library folder (as
    /// RADIANCE's default RAYPATH has it: function files beside the scene first).
    pub fn tool(&self, name: &str) -> Command {
        let mut c = Command::new(self.bin.join(name));
        // Inline commands (`!xform ...` in a scene oconv reads) find RADIANCE's programs on
        // PATH: without its folder first they fail and oconv leaves their objects out with a
        // warning (an empty room, lit as open sky).
        let mut path = std::ffi::OsString::from(self.bin.as_os_str());
        if let Some(rest) = std::env::var_os("PATH") {
            path.push(":");
            path.push(rest);
        }
        c.env("PATH", path);
        if let Some(lib) = &self.lib {
            let mut path = std::ffi::OsString::from(".:");
            path.push(lib);
            c.env("RAYPATH", path);
        }
        c
    }

    /// Runs a command to completion; its stdout (stdin as the command has it).
    pub fn output(&self, mut c: Command) -> Result<Vec<u8>, RadianceError> {
        let command = format!("{c:?}");
        let out = c
            .stderr(Stdio::piped())
            .output()
            .map_err(|source| RadianceError::Spawn {
                command: command.clone(),
                source,
            })?;
        if !out.status.success() {
            return Err(RadianceError::Failed {
                command,
                stderr: String::from_utf8_lossy(&out.stderr).trim().to_string(),
            });
        }
        Ok(out.stdout)
    }
}
