//! Errors of reading and evaluating `.cal` files: each names the file and line, or the name
//! that could not be evaluated.

use std::fmt;

/// A `.cal` file that cannot be read, or an expression that cannot be evaluated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CalError {
    /// Malformed text: `file`, 1-based `line`, what was expected.
    #[error("{file}, line {line}: {message}")]
    Syntax {
        file: String,
        line: u32,
        message: String,
    },
    /// The file could not be read.
    #[error("{file}: {message}")]
    Io { file: String, message: String },
    /// A name used as a variable or function that no file defines and the library lacks.
    #[error("{name}: undefined {kind}")]
    Undefined { name: String, kind: &'static str },
    /// A function called with fewer arguments than its body uses.
    #[error("{name}(): too few arguments")]
    TooFewArguments { name: String },
    /// A parameter called as a function whose argument is not a function name.
    #[error("{name}(): argument not a function")]
    NotAFunction { name: String },
    /// A name defined as a function used as a variable, or the reverse.
    #[error("{name}: {message}")]
    Misuse { name: String, message: String },
    /// Evaluation nested deeper than the evaluator allows (runaway recursion).
    #[error("{name}(): recursion deeper than {limit} levels")]
    TooDeep { name: String, limit: usize },
    /// One evaluation took more steps than the evaluator allows (exponential recursion).
    #[error("{name}(): evaluation longer than {limit} steps")]
    TooLong { name: String, limit: u64 },
}

/// What calcomp prints as a warning and answers 0 for: kept so callers can report it.
#[derive(Debug, Clone, PartialEq)]
pub enum CalWarning {
    DivisionByZero,
    IllegalPower,
    /// A library function returned NaN or infinity (calcomp's "domain error"/"range error").
    DomainError {
        function: String,
    },
}

impl fmt::Display for CalWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CalWarning::DivisionByZero => write!(f, "Division by zero"),
            CalWarning::IllegalPower => write!(f, "Illegal power"),
            CalWarning::DomainError { function } => write!(f, "{function}(): domain error"),
        }
    }
}
