//! RADIANCE's object and sky generators, written natively so a scene needs no RADIANCE
//! installation: each takes the words after the program name and the directory the command
//! runs in, and returns the scene text the program would write (names and primitive order as
//! the program's, numbers exact). Bad options are an error saying which and why.

mod args;
mod functions;
mod genblinds;
mod genbox;
mod gendaylit;
mod genprism;
mod genrev;
mod gensky;
mod gensurf;
mod genworm;
mod text;

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
        "gensurf" => gensurf::generate,
        "genworm" => genworm::generate,
        "gensky" => gensky::generate,
        "gendaylit" => gendaylit::generate,
        _ => return None,
    })
}
