//! RADIANCE's object and sky generators, written natively so a scene needs no RADIANCE
//! installation: each takes the words after the program name and the directory the command
//! runs in, and returns the scene text the program would write (names and primitive order as
//! the program's, numbers exact). Bad options are an error saying which and why.

mod calc;
mod genblinds;
mod genbox;
mod gendaylit;
mod genprism;
mod genrev;
mod gensky;

use std::path::Path;

/// A generator: the program's arguments and the command's directory, to scene text.
pub(crate) type Generator = fn(&[String], &Path) -> Result<String, String>;

/// The native generator for `program`, if Skylux has one.
pub(crate) fn generator(program: &str) -> Option<Generator> {
    Some(match program {
        "genbox" => genbox::generate,
        "genblinds" => genblinds::generate,
        "genprism" => genprism::generate,
        "genrev" => genrev::generate,
        "gensky" => gensky::generate,
        "gendaylit" => gendaylit::generate,
        _ => return None,
    })
}

/// Argument `index` as a finite number; `what` names it in the error.
fn number(args: &[String], index: usize, what: &str) -> Result<f64, String> {
    let word = args
        .get(index)
        .ok_or_else(|| format!("{what} is missing"))?;
    word.parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("{what} is `{word}`; expected a number"))
}

/// Argument `index` as an integer.
fn integer(args: &[String], index: usize, what: &str) -> Result<i64, String> {
    let word = args
        .get(index)
        .ok_or_else(|| format!("{what} is missing"))?;
    word.parse::<i64>()
        .map_err(|_| format!("{what} is `{word}`; expected an integer"))
}

/// Fails unless there are at least `count` arguments, with the program's usage.
fn require(args: &[String], count: usize, usage: &str) -> Result<(), String> {
    if args.len() < count {
        return Err(format!("{} argument(s) given; usage: {usage}", args.len()));
    }
    Ok(())
}

/// One polygon in RADIANCE text.
fn polygon(out: &mut String, modifier: &str, name: &str, vertices: &[[f64; 3]]) {
    use std::fmt::Write as _;
    let _ = write!(
        out,
        "\n{modifier} polygon {name}\n0\n0\n{}\n",
        vertices.len() * 3
    );
    for v in vertices {
        let _ = writeln!(out, "\t{} {} {}", v[0], v[1], v[2]);
    }
}

/// Any primitive with only real arguments, in RADIANCE text.
fn reals_primitive(out: &mut String, modifier: &str, type_name: &str, name: &str, reals: &[f64]) {
    use std::fmt::Write as _;
    let _ = write!(
        out,
        "\n{modifier} {type_name} {name}\n0\n0\n{}",
        reals.len()
    );
    for r in reals {
        let _ = write!(out, " {r}");
    }
    out.push('\n');
}
