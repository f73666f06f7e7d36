//! The functions that `genrev`, `genworm` and `gensurf` take (of t, or of s and t), in
//! RADIANCE's `.cal` language through the project's calcomp ([`crate::cal`]), with the
//! programs' `-e` definitions and `-f` files and what they add to calcomp: the constant `PI`
//! and the curves `hermite`, `bezier` and `bspline` (gen/genrev.c and its kin).

use crate::cal::{CalProgram, Evaluator, RayValues};
use std::path::Path;

/// What the generators define before the user's text: `PI` and the three curves, each a
/// function of four control values and t (the programs' `l_hermite`, `l_bezier` and
/// `l_bspline`: the cubic Hermite, Bézier and uniform B-spline bases).
const PRELUDE: &str = "PI : 3.14159265358979323846;\n\
    hermite(p0, p1, r0, r1, t) : p0*((2*t-3)*t*t+1) + p1*(-2*t+3)*t*t \
        + r0*((t-2)*t+1)*t + r1*(t-1)*t*t;\n\
    bezier(p1, p2, p3, p4, t) : p1*(1+t*(-3+t*(3-t))) + p2*3*t*(1+t*(-2+t)) \
        + p3*3*t*t*(1-t) + p4*t*t*t;\n\
    bspline(p0, p1, p2, p3, t) : p0*(1/6+t*(-1/2+t*(1/2-1/6*t))) \
        + p1*(2/3+t*t*(-1+1/2*t)) + p2*(1/6+t*(1/2+t*(1/2-1/2*t))) + p3*(1/6*t*t*t);\n";

/// Largest `.cal` file read by `-f`: a guard for a file that is not one.
const MAX_FILE_BYTES: u64 = 1 << 20;

/// A generator's definitions.
pub(super) struct Functions {
    program: CalProgram,
}

impl Functions {
    pub(super) fn new() -> Self {
        let mut program = CalProgram::new();
        program
            .load_str("(generator prelude)", PRELUDE)
            .expect("the prelude is valid .cal");
        Self { program }
    }

    /// Reads the options after the positional arguments, in order: `-e EXPR` and `-f FILE`
    /// (found in `dir`, the command's directory, then on RAYPATH, as the programs' getpath
    /// does) are compiled; the flags in `flags` are returned as met; anything else is an
    /// error with `usage`.
    pub(super) fn options<'a>(
        &mut self,
        options: &'a [String],
        dir: &Path,
        flags: &[&str],
        usage: &str,
    ) -> Result<Vec<&'a str>, String> {
        let mut seen = Vec::new();
        let mut words = options.iter();
        while let Some(word) = words.next() {
            match word.as_str() {
                "-e" => {
                    let text = words.next().ok_or("-e needs an expression")?;
                    self.program
                        .load_str("-e", text)
                        .map_err(|e| format!("-e `{text}`: {e}"))?;
                }
                "-f" => {
                    let name = words.next().ok_or("-f needs a file")?;
                    let path = find_file(name, dir)?;
                    self.program
                        .load_str(&path.display().to_string(), &read_file(&path)?)
                        .map_err(|e| e.to_string())?;
                }
                flag if flags.contains(&flag) => seen.push(flag),
                other => return Err(format!("unknown option `{other}`; usage: {usage}")),
            }
        }
        Ok(seen)
    }

    /// Defines `name(parameters) = expression`, as the programs compile their arguments;
    /// `what` names the argument in errors.
    pub(super) fn define(
        &mut self,
        name: &str,
        parameters: &str,
        expression: &str,
        what: &str,
    ) -> Result<(), String> {
        self.program
            .load_str(what, &format!("{name}({parameters})={expression};"))
            .map_err(|e| format!("{what} `{expression}`: {e}"))
    }

    /// A count given as an expression, rounded as the programs do (`eval(arg) + .5`,
    /// truncated), from 1 to `max`.
    pub(super) fn count(
        &mut self,
        expression: &str,
        what: &str,
        max: usize,
    ) -> Result<usize, String> {
        let name = "N`SYS`";
        self.program
            .load_str(what, &format!("{name}={expression};"))
            .map_err(|e| format!("{what} `{expression}`: {e}"))?;
        let v = Evaluator::new(&self.program)
            .variable(name, &RayValues::default())
            .map_err(|e| format!("{what} `{expression}`: {e}"))?
            + 0.5;
        if !(v >= 1.0 && v < max as f64 + 1.0) {
            return Err(format!("{what} is `{expression}`; expected 1 to {max}"));
        }
        Ok(v as usize)
    }

    /// Whether `name` is defined as a function of `arity` arguments.
    pub(super) fn has_function(&self, name: &str, arity: usize) -> bool {
        self.program.is_defined(name) && self.program.parameter_count(name) == Some(arity)
    }

    /// `name(arguments)`; a value that is not finite is an error naming `what`.
    pub(super) fn value(&self, name: &str, arguments: &[f64], what: &str) -> Result<f64, String> {
        let v = Evaluator::new(&self.program)
            .call(name, arguments, &RayValues::default())
            .map_err(|e| format!("{what}: {e}"))?;
        if !v.is_finite() {
            return Err(format!("{what} is {v} at {arguments:?}"));
        }
        Ok(v)
    }
}

/// `name` as RADIANCE's generators find a `-f` file (getpath on RAYPATH, the command's
/// directory `dir` standing for `.`), then in `dir` itself (`scene::files::search_directories`,
/// the rule every file a scene names follows).
fn find_file(name: &str, dir: &Path) -> Result<std::path::PathBuf, String> {
    // A name inside `dir` stands for the naming and top-level files (their directory is dir).
    let beside = dir.join("generator");
    crate::scene::files::search_directories(name, dir, &beside, &beside)
        .into_iter()
        .map(|d| d.join(name))
        .find(|p| p.is_file())
        .ok_or_else(|| {
            format!(
                "cannot find file `{name}` (in {} or on RAYPATH)",
                dir.display()
            )
        })
}

fn read_file(path: &Path) -> Result<String, String> {
    let size = std::fs::metadata(path)
        .map_err(|e| format!("{}: {e}", path.display()))?
        .len();
    if size > MAX_FILE_BYTES {
        return Err(format!(
            "{}: larger than {MAX_FILE_BYTES} bytes",
            path.display()
        ));
    }
    let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}
