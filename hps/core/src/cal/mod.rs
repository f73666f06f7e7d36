//! RADIANCE's `.cal` language (calcomp): the function files that `*func`, `*data`, `brightfunc`
//! and `texfunc` modifiers name, read once into a compiled program that the engine evaluates
//! per ray without looking a name up.
//!
//! Semantics follow calcomp's manual and RADIANCE's `src/common/calexpr.c`, `caldefn.c` and
//! `calfunc.c` (LBNL): `=` and `:` definitions, later definitions replacing earlier ones,
//! functions with lazily evaluated arguments (so `if` and recursion work), functions passed
//! as arguments, and the library (`if select min max rand floor ceil sqrt sin cos tan asin
//! acos atan atan2 exp log log10`). A division by zero or a domain error gives 0 and a warning,
//! as calcomp does; an undefined name, a missing argument or runaway recursion is an error.
//! `tests/cal_vs_rcalc.rs` checks every figure against RADIANCE's `rcalc` run live.

mod ast;
mod context;
mod error;
mod eval;
mod lexer;
mod library;
mod load;
mod parser;
mod program;

pub use context::{CalContext, RayValues, RayVariable};
pub use error::{CalError, CalWarning};
pub use eval::Evaluator;
pub use program::{CalProgram, SymbolId};
