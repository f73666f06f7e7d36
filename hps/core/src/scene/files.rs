//! Files a scene names: resolved from the directory of the file that names them, and read
//! only when they are regular files.

use std::path::{Path, PathBuf};

/// `name` as seen from `dir`, without a leading `./` (so messages name `objects/a.rad`).
pub(crate) fn resolve(dir: &Path, name: &str) -> PathBuf {
    let name = Path::new(name);
    let name = name.strip_prefix(".").unwrap_or(name);
    if dir == Path::new(".") {
        name.to_path_buf()
    } else {
        dir.join(name)
    }
}

/// A regular file's bytes: a device or FIFO (`/dev/zero`, `/dev/stdin`) would never end.
pub(crate) fn read_regular_file(path: &Path) -> std::io::Result<Vec<u8>> {
    if !std::fs::metadata(path)?.is_file() {
        return Err(std::io::Error::other("not a regular file"));
    }
    std::fs::read(path)
}

/// The directory a scene file's relative names are taken from.
fn directory_of(file: &Path) -> PathBuf {
    match file.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// Where RADIANCE's `getpath` looks for `name`, in order: an absolute name as it is; a name
/// starting with `.` in the working directory `run` only; any other name in each `RAYPATH`
/// entry ("." by default, meaning `run`). Skylux then tries the naming file's directory and
/// the top-level file's, as for every file a scene names.
pub(crate) fn search_directories(
    name: &str,
    run: &Path,
    naming_file: &Path,
    top_file: &Path,
) -> Vec<PathBuf> {
    if Path::new(name).is_absolute() {
        return vec![PathBuf::new()];
    }
    let mut dirs = Vec::new();
    if name.starts_with('.') {
        dirs.push(run.to_path_buf());
    } else {
        let raypath = std::env::var_os("RAYPATH").unwrap_or_else(|| ".".into());
        for dir in std::env::split_paths(&raypath) {
            dirs.push(if dir == Path::new(".") || dir.as_os_str().is_empty() {
                run.to_path_buf()
            } else {
                dir
            });
        }
    }
    for dir in [directory_of(naming_file), directory_of(top_file)] {
        if !dirs.contains(&dir) {
            dirs.push(dir);
        }
    }
    dirs
}
