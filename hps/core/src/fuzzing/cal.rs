//! `.cal` files (RADIANCE's calcomp language): parsed, then every name they define read as a
//! variable and called as a function, as a modifier would.

use crate::cal::{CalProgram, Evaluator, RayValues};

/// Most names evaluated per input: enough to reach every definition of a small file.
const MAX_NAMES: usize = 24;

pub(super) fn cal(bytes: &[u8]) {
    let text = super::checks::text(bytes);
    let mut program = CalProgram::new();
    if let Err(e) = program.load_str("fuzz.cal", &text) {
        super::checks::assert_names(&e.to_string(), "fuzz.cal");
        return;
    }
    let mut evaluator = Evaluator::new(&program);
    let ray = RayValues::default();
    for name in names(&text) {
        let _ = evaluator.variable(name, &ray);
        let _ = evaluator.call(name, &[0.5, 2.0], &ray);
    }
}

/// The identifiers of the text, first occurrences in order (a superset of its definitions).
fn names(text: &str) -> Vec<&str> {
    let mut out: Vec<&str> = Vec::new();
    let words = text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '.'));
    for word in words {
        let identifier = word.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_');
        if identifier && !out.contains(&word) {
            out.push(word);
            if out.len() == MAX_NAMES {
                break;
            }
        }
    }
    out
}
