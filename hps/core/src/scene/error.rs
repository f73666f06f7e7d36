//! Where a scene primitive came from, and everything that can be wrong with a scene file.

use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The primitive types Skylux reads, as listed in [`SceneError::UnsupportedType`] messages.
pub const SUPPORTED_TYPES: &str =
    "plastic, metal, trans, glass, mirror, light, glow, BRTDfunc, mixfunc, brightfunc, colorfunc, \
     brightdata, colordata, colorpict, texfunc, texdata, mixdata, mixpict, brighttext, colortext, mixtext, plasfunc, metfunc, \
     transfunc, plasdata, metdata, transdata, plastic2, metal2, trans2, BSDF, aBSDF, \
     dielectric, interface, spotlight, illum, antimatter, alias (modifiers) and polygon, \
     sphere, cylinder, ring, cone, source, bubble, tube, cup (surfaces)";

/// A file and a 1-based line in it: where a primitive starts, or where a bad token is.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct SourceLocation {
    /// The file as it was given to the loader (or the label given to `scene::parse`).
    pub file: Arc<Path>,
    /// 1-based line number.
    pub line: usize,
}

impl fmt::Display for SourceLocation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}", self.file.display(), self.line)
    }
}

/// The three argument lists every RADIANCE primitive carries, in file order.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum ArgumentList {
    String,
    Integer,
    Real,
}

impl fmt::Display for ArgumentList {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            ArgumentList::String => "string",
            ArgumentList::Integer => "integer",
            ArgumentList::Real => "real",
        })
    }
}

/// Why a scene could not be loaded. Every variant that comes from the text names the file and
/// line (`at`), the primitive (as ``type `identifier` ``) and the field or type at fault, and
/// what was expected.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    #[error("cannot read scene file {}: {source}", path.display())]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },

    #[error("{at}: not UTF-8 text (invalid byte sequence on this line); expected a RADIANCE scene description")]
    NotUtf8 { at: SourceLocation },

    #[error("{at}: quoted string opened with {quote} on this line is never closed; expected a closing {quote}")]
    UnterminatedQuote { at: SourceLocation, quote: char },

    #[error("{at}: unsupported inline command `{command}`: {reason}")]
    UnsupportedCommand {
        at: SourceLocation,
        command: String,
        reason: String,
    },

    #[error("{at}: inline command `!{command}`: {message}")]
    Command {
        at: SourceLocation,
        command: String,
        message: String,
    },

    #[error("{at}: inline command `!{command}` includes a file already being read: include cycle {chain}")]
    IncludeCycle {
        at: SourceLocation,
        command: String,
        chain: String,
    },

    #[error("{at}: inline command `!{command}`: files include files more than {limit} deep ({chain}); expected a shallower chain")]
    IncludeDepth {
        at: SourceLocation,
        command: String,
        limit: usize,
        chain: String,
    },

    #[error("{at}: inline command `!{command}`: cannot read {}: {source}", path.display())]
    MissingInclude {
        at: SourceLocation,
        command: String,
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },

    #[error("{at}: the scene expands to more than {limit} primitives here{}; expected a scene Skylux can hold", if command.is_empty() { String::new() } else { format!(" (inline command `!{command}`)") })]
    TooManyPrimitives {
        at: SourceLocation,
        command: String,
        limit: usize,
    },

    #[error("{at}: unsupported primitive type `{type_name}` (identifier `{identifier}`): {reason}; expected one of {}", SUPPORTED_TYPES)]
    UnsupportedType {
        at: SourceLocation,
        type_name: String,
        identifier: String,
        reason: &'static str,
    },

    #[error("{at}: file ends {context}; expected {expected}")]
    UnexpectedEnd {
        at: SourceLocation,
        context: String,
        expected: String,
    },

    #[error(
        "{at}: {primitive}: {list} argument count is `{token}`; expected a non-negative integer"
    )]
    BadCount {
        at: SourceLocation,
        primitive: String,
        list: ArgumentList,
        token: String,
    },

    #[error("{at}: {primitive}: integer argument {index} is `{token}`; expected an integer")]
    BadInteger {
        at: SourceLocation,
        primitive: String,
        index: usize,
        token: String,
    },

    #[error("{at}: {primitive}: {field} is `{token}`; expected a number")]
    BadReal {
        at: SourceLocation,
        primitive: String,
        field: String,
        token: String,
    },

    #[error("{at}: {primitive}: {field} is `{token}`; expected a finite number")]
    NonFiniteReal {
        at: SourceLocation,
        primitive: String,
        field: String,
        token: String,
    },

    #[error("{at}: {primitive}: found {found} {list} arguments; expected {expected}")]
    ArgumentCount {
        at: SourceLocation,
        primitive: String,
        list: ArgumentList,
        found: usize,
        expected: String,
    },

    #[error("{at}: {primitive}: {field} `{modifier}` is not defined; expected `void` or a material or pattern defined earlier{hint}")]
    UnknownModifier {
        at: SourceLocation,
        primitive: String,
        field: &'static str,
        modifier: String,
        hint: String,
    },

    #[error("{at}: {primitive}: {field} is {value}; expected {expected}")]
    InvalidValue {
        at: SourceLocation,
        primitive: String,
        field: String,
        value: String,
        expected: String,
    },

    #[error("{at}: {primitive}: degenerate polygon, {reason}; expected at least 3 vertices spanning a non-zero area")]
    DegeneratePolygon {
        at: SourceLocation,
        primitive: String,
        reason: String,
    },
}

impl SceneError {
    /// Where in the text the error is, if it comes from the text (not from reading the file).
    pub fn location(&self) -> Option<&SourceLocation> {
        match self {
            SceneError::Io { .. } => None,
            SceneError::NotUtf8 { at }
            | SceneError::UnterminatedQuote { at, .. }
            | SceneError::UnsupportedCommand { at, .. }
            | SceneError::Command { at, .. }
            | SceneError::IncludeCycle { at, .. }
            | SceneError::IncludeDepth { at, .. }
            | SceneError::MissingInclude { at, .. }
            | SceneError::TooManyPrimitives { at, .. }
            | SceneError::UnsupportedType { at, .. }
            | SceneError::UnexpectedEnd { at, .. }
            | SceneError::BadCount { at, .. }
            | SceneError::BadInteger { at, .. }
            | SceneError::BadReal { at, .. }
            | SceneError::NonFiniteReal { at, .. }
            | SceneError::ArgumentCount { at, .. }
            | SceneError::UnknownModifier { at, .. }
            | SceneError::InvalidValue { at, .. }
            | SceneError::DegeneratePolygon { at, .. } => Some(at),
        }
    }
}

/// Line (1-based) of the first invalid UTF-8 byte, for [`SceneError::NotUtf8`].
pub(crate) fn line_of_offset(bytes: &[u8], offset: usize) -> usize {
    1 + bytes[..offset.min(bytes.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
}

/// The text of a file, or an error naming the line of its first invalid byte.
pub(crate) fn utf8<'b>(file: &Arc<Path>, bytes: &'b [u8]) -> Result<&'b str, SceneError> {
    std::str::from_utf8(bytes).map_err(|e| SceneError::NotUtf8 {
        at: SourceLocation {
            file: file.clone(),
            line: line_of_offset(bytes, e.valid_up_to()),
        },
    })
}
