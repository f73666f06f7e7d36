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
