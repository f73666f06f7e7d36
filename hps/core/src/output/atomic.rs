//! Atomic, durable file replacement: a reader sees the old file or the new one, never half of
//! one, and a power cut after the call returns cannot lose the new one.
//!
//! The bytes go to a hidden temporary beside the target (`.name.tmp`), are fsynced, renamed
//! over the target (atomic on POSIX file systems) and the folder is fsynced so the rename
//! itself survives (Linux `rename(2)`, `fsync(2)`: a rename is durable only once the
//! directory is synced).

use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};

/// The temporary's suffix; whatever ends in it beside a target is a leftover of a crash.
pub const TMP_SUFFIX: &str = ".tmp";

/// A file that could not be written, with its path.
#[derive(Debug, thiserror::Error)]
#[error("{}: {source}", path.display())]
pub struct WriteError {
    pub path: PathBuf,
    #[source]
    pub source: std::io::Error,
}

impl WriteError {
    pub fn new(path: &Path, source: std::io::Error) -> Self {
        Self {
            path: path.to_path_buf(),
            source,
        }
    }
}

/// Flushes a file's data and metadata to the disk.
pub fn fsync_file(path: &Path) -> std::io::Result<()> {
    File::open(path)?.sync_all()
}

/// Flushes a directory, so that a rename or a new entry in it survives a power cut.
pub fn fsync_dir(path: &Path) -> std::io::Result<()> {
    File::open(path)?.sync_all()
}

/// The hidden temporary `dir/.name.tmp` that [`write_atomic`] writes before renaming.
pub fn tmp_name(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    path.with_file_name(format!(".{name}{TMP_SUFFIX}"))
}

/// Replaces `path` with `bytes` atomically and durably. `before_rename` runs between the
/// temporary's fsync and the rename (tests use it to stand for a crash there). On failure the
/// temporary is removed and the old file is untouched.
pub fn write_atomic_with(
    path: &Path,
    bytes: &[u8],
    before_rename: impl FnOnce() -> std::io::Result<()>,
) -> Result<(), WriteError> {
    let tmp = tmp_name(path);
    let result = (|| {
        let mut f = File::create(&tmp)?;
        f.write_all(bytes)?;
        f.sync_all()?;
        drop(f);
        before_rename()?;
        std::fs::rename(&tmp, path)?;
        match path.parent() {
            Some(dir) if !dir.as_os_str().is_empty() => fsync_dir(dir),
            _ => Ok(()),
        }
    })();
    result.map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        WriteError::new(path, e)
    })
}

/// [`write_atomic_with`] without a hook.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), WriteError> {
    write_atomic_with(path, bytes, || Ok(()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A failure before the rename leaves the old file and no temporary.
    #[test]
    fn a_failed_write_keeps_the_old_file() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("latest.json");
        write_atomic(&p, b"old\n").unwrap();
        let e =
            write_atomic_with(&p, b"new\n", || Err(std::io::Error::other("crash"))).unwrap_err();
        assert_eq!(e.path, p);
        assert_eq!(std::fs::read(&p).unwrap(), b"old\n");
        assert!(!tmp_name(&p).exists());
        write_atomic(&p, b"new\n").unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"new\n");
    }

    /// A relative path in the current folder has an empty parent: still written.
    #[test]
    fn a_missing_folder_is_an_error_naming_the_file() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("no/such/dir/x.txt");
        let e = write_atomic(&p, b"x").unwrap_err();
        assert!(e.to_string().contains("x.txt"), "{e}");
    }
}
