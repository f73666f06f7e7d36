//! Why glare could not be evaluated: the picture's file, its values or projection, or a
//! setting.

use crate::picture::rgbe::PictureReadError;
use std::path::PathBuf;

/// Why glare could not be evaluated.
#[derive(Debug, thiserror::Error)]
pub enum GlareError {
    #[error(transparent)]
    Read(#[from] PictureReadError),
    /// The file was read but cannot be used as given.
    #[error("{}: {message}", path.display())]
    Input { path: PathBuf, message: String },
    /// The picture's values or projection are wrong.
    #[error("{0}")]
    Picture(String),
    /// A setting is out of range.
    #[error("{0}")]
    Setting(String),
}
