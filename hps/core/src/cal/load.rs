//! Loading `.cal` files into a program, in order, with calcomp's reading rules.

use std::path::Path;

use super::ast::{Definition, Expr};
use super::context::RayValues;
use super::error::CalError;
use super::eval::Evaluator;
use super::parser::parse_file;
use super::program::CalProgram;

impl CalProgram {
    /// Reads and compiles `path`; its definitions replace earlier ones of the same names.
    pub fn load_file(&mut self, path: &Path) -> Result<(), CalError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| CalError::Io {
            file: file.clone(),
            message: e.to_string(),
        })?;
        self.load_str(&file, &text)
    }

    /// Compiles `text` (named `file` in errors). On a syntax error nothing of `text` is kept.
    pub fn load_str(&mut self, file: &str, text: &str) -> Result<(), CalError> {
        for definition in parse_file(file, text)? {
            let parameters = definition.parameters.as_deref().unwrap_or(&[]);
            let body = fold_constants(self, &definition.body, parameters);
            self.define(&Definition { body, ..definition });
        }
        Ok(())
    }
}

/// `expr` with each name of an already defined `:` constant variable replaced by its value:
/// calcomp folds such a reference when it reads it (`calexpr.c` `rconst`), so a later
/// redefinition of the constant does not reach expressions read before it.
fn fold_constants(program: &CalProgram, expr: &Expr, parameters: &[String]) -> Expr {
    let fold = |e: &Expr| Box::new(fold_constants(program, e, parameters));
    match expr {
        Expr::Name(name) if !parameters.contains(name) => match constant_value(program, name) {
            Some(v) => Expr::Number(v),
            None => expr.clone(),
        },
        Expr::Negate(inner) => Expr::Negate(fold(inner)),
        Expr::Binary(op, a, b) => Expr::Binary(*op, fold(a), fold(b)),
        Expr::Call(name, args) => Expr::Call(
            name.clone(),
            args.iter()
                .map(|a| fold_constants(program, a, parameters))
                .collect(),
        ),
        Expr::Number(_) | Expr::Name(_) => expr.clone(),
    }
}

fn constant_value(program: &CalProgram, name: &str) -> Option<f64> {
    if !program.is_constant_variable(name) {
        return None;
    }
    Evaluator::new(program)
        .variable(name, &RayValues::default())
        .ok()
}
