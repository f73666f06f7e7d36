//! Why two pictures could not be compared: a file, a view, a region file or a setting.

use crate::glare::GlareError;
use std::path::PathBuf;

/// Why two pictures could not be compared.
#[derive(Debug, thiserror::Error)]
pub enum CompareError {
    /// One picture could not be read or fails its checks (NaN, negative, truncated).
    #[error("{}: {source}", path.display())]
    Picture {
        path: PathBuf,
        #[source]
        source: GlareError,
    },
    /// The two views cannot be mapped onto each other.
    #[error("{0}")]
    Views(String),
    /// A region file (mask picture or polygons) is wrong.
    #[error("{}: {message}", path.display())]
    Regions { path: PathBuf, message: String },
    /// A setting is out of range.
    #[error("{0}")]
    Setting(String),
}
