//! The TOML files Skylux reads (`device.toml`, `capture.toml`, `campaign.toml`): one error
//! type for all of them, every message naming the file, and the line or the field.

use std::path::{Path, PathBuf};

/// Why a TOML file could not be used.
#[derive(Debug, thiserror::Error)]
pub enum TomlFileError {
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    /// Not TOML, or not the expected shape; `message` names the line where there is one.
    #[error("{path}: {message}")]
    Parse { path: PathBuf, message: String },
    /// A value out of its range; `field` is the dotted key.
    #[error("{path}: {field}: {reason}")]
    Invalid {
        path: PathBuf,
        field: String,
        reason: String,
    },
}

impl TomlFileError {
    /// The file's text, or the error naming it.
    pub(crate) fn read_text(path: &Path) -> Result<String, Self> {
        std::fs::read_to_string(path).map_err(|source| Self::Io {
            path: path.into(),
            source,
        })
    }

    /// A TOML error in `text`, read from `path`, with its line spelled out.
    pub(crate) fn parse(path: impl Into<PathBuf>, text: &str, e: &toml::de::Error) -> Self {
        Self::Parse {
            path: path.into(),
            message: describe(text, e),
        }
    }
}

/// A TOML error with its line number spelled out (`line 12: invalid type ...`).
fn describe(text: &str, e: &toml::de::Error) -> String {
    let message = e.message().trim().to_string();
    match e.span() {
        Some(span) => {
            let line = text[..span.start.min(text.len())].matches('\n').count() + 1;
            format!("line {line}: {message}")
        }
        None => message,
    }
}
