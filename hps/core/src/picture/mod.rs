//! Pictures of luminance: the [`Picture`] a render produces and its writers, RADIANCE's
//! `.hdr` ([`rgbe`]), OpenEXR ([`exr`]) and a falsecolour PNG with a legend
//! ([`falsecolour`]). Apart from the engine, so that other tools (glare evaluation) read and
//! write the same pictures.

pub mod exr;
pub mod falsecolour;
pub mod rgbe;

use glam::DVec3;
use std::path::{Path, PathBuf};

/// A picture of radiance and luminance, rows from the top, with the view it was taken from.
#[derive(Clone, Debug, PartialEq)]
pub struct Picture {
    pub width_px: u32,
    pub height_px: u32,
    /// The view in RADIANCE's option syntax (`-vtv -vp ...`), as a `VIEW=` line carries it.
    pub view: String,
    /// Mean radiance per pixel, W/sr/m² per RGB channel (what rpict writes).
    pub radiance_rgb: Vec<DVec3>,
    /// 179 × (0.265 R + 0.670 G + 0.065 B) of the radiance, cd/m².
    pub luminance_cd_m2: Vec<f64>,
    /// Standard error of each pixel's luminance, s / √n over its samples (0 for one sample).
    pub luminance_stderr_cd_m2: Vec<f64>,
    pub samples_per_pixel: u32,
}

impl Picture {
    /// Index of pixel (`column`, `row`), row 0 at the top.
    pub fn index(&self, column: u32, row: u32) -> usize {
        row as usize * self.width_px as usize + column as usize
    }
}

/// Why an output file could not be written.
#[derive(Debug, thiserror::Error)]
#[error("{path}: {message}")]
pub struct OutputError {
    pub path: PathBuf,
    pub message: String,
}

pub(crate) fn output_error(path: &Path, message: impl ToString) -> OutputError {
    OutputError {
        path: path.into(),
        message: message.to_string(),
    }
}
