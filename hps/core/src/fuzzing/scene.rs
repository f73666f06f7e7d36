//! RADIANCE scene files, read as the engine reads them: native inline commands (`!xform`,
//! `!genbox`, `!gensky`, ...) expanded, the shell never run.

use crate::scene::{LoadOptions, Scene};
use std::path::PathBuf;
use std::sync::OnceLock;

/// A private directory for the scene's relative file names (`!xform part.rad`, a BSDF
/// file): one per process, so a scene can only name files that the fuzzer itself made.
fn directory() -> &'static PathBuf {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("skylux-fuzz-scene-{}", std::process::id()));
        let _ = std::fs::create_dir_all(&dir);
        dir
    })
}

/// Loads the bytes as `fuzz.rad` with commands off (the daemon's setting).
pub(super) fn scene(bytes: &[u8]) {
    let dir = directory();
    let options = LoadOptions {
        allow_commands: false,
        working_directory: Some(dir.clone()),
    };
    let label = dir.join("fuzz.rad");
    if let Err(e) = Scene::new().add_bytes_with(&label, bytes, &options) {
        // Every error names a file: this one or one it reads.
        let message = e.to_string();
        assert!(!message.is_empty());
    }
}
