//! Fuzz harnesses: one function per reader of outside data, `fn(&[u8])`, that must not
//! panic, hang or allocate without bound on any input (an `Err` is a correct answer).
//!
//! They live in the library, not in `fuzz/`, so that two callers share them: the
//! coverage-guided fuzzers of `fuzz/` (libFuzzer, built apart from the workspace), and the
//! replay test `tests/fuzz_replay.rs`, which runs every committed corpus file through them
//! in CI. See FUZZING.md at the repository root.

mod bsdf;
mod cal;
mod campaign;
mod checks;
mod data_file;
mod device;
mod font;
mod known_source;
mod matrix;
mod pictures;
mod regions;
mod scene;
mod sensors;
mod view;

/// A harness: feeds one input to a reader; panics only on a bug.
pub type Harness = fn(&[u8]);

/// Every harness of this crate by the name of its fuzz target (and corpus folder).
pub const TARGETS: &[(&str, Harness)] = &[
    ("scene", scene::scene),
    ("cal", cal::cal),
    ("bsdf_xml", bsdf::bsdf_xml),
    ("pts", sensors::pts),
    ("campaign", campaign::campaign),
    ("device_toml", device::device_toml),
    ("exr", pictures::exr),
    ("rgbe", pictures::rgbe),
    ("dat", data_file::dat),
    ("view", view::view),
    ("dc_matrix", matrix::dc_matrix),
    ("radiance_matrix", matrix::radiance_matrix),
    ("regions", regions::regions),
    ("known_source", known_source::known_source),
    ("fnt", font::fnt),
];

/// The harness named `name`, if this crate has one.
pub fn harness(name: &str) -> Option<Harness> {
    TARGETS.iter().find(|(n, _)| *n == name).map(|(_, h)| *h)
}

/// Runs every file of `fuzz/corpus/TARGET/` and `fuzz/regressions/TARGET/` under
/// `repository` through `harness`, as CI's replay tests do. Returns how many files ran;
/// fails naming the first file that panics, and when the corpus is missing or empty (a
/// replay of nothing must not pass).
pub fn replay(
    repository: &std::path::Path,
    target: &str,
    harness: Harness,
) -> Result<usize, String> {
    let mut files = Vec::new();
    for folder in ["corpus", "regressions"] {
        let dir = repository.join("fuzz").join(folder).join(target);
        match std::fs::read_dir(&dir) {
            Ok(entries) => files.extend(entries.filter_map(|e| e.ok()).map(|e| e.path())),
            Err(_) if folder == "regressions" => {}
            Err(e) => return Err(format!("{}: {e}", dir.display())),
        }
    }
    files.sort();
    if files.is_empty() {
        return Err(format!("no corpus for the fuzz target `{target}`"));
    }
    for file in &files {
        let bytes = std::fs::read(file).map_err(|e| format!("{}: {e}", file.display()))?;
        std::panic::catch_unwind(|| harness(&bytes))
            .map_err(|_| format!("{}: the harness `{target}` panicked", file.display()))?;
    }
    Ok(files.len())
}
