//! The one error of the BSDF reader: it names the file, the XML element and its line, so a
//! bad file is found without a debugger.

use std::fmt;

/// A BSDF file that cannot be read or makes no sense.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BsdfError {
    /// The file as the caller named it.
    pub file: String,
    /// 1-based line of the element (or of the value inside it); 0 when the file has none.
    pub line: u32,
    /// The XML element at fault (`ScatteringData`, `WavelengthDataDirection`, ...).
    pub element: String,
    /// What is wrong, in words.
    pub message: String,
}

impl BsdfError {
    pub(crate) fn new(file: &str, line: u32, element: &str, message: impl Into<String>) -> Self {
        BsdfError {
            file: file.to_string(),
            line,
            element: element.to_string(),
            message: message.into(),
        }
    }
}

impl fmt::Display for BsdfError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}:{}: <{}>: {}",
            self.file, self.line, self.element, self.message
        )
    }
}

impl std::error::Error for BsdfError {}
