//! The checked-in renders of the map must equal what the map renders today, so documentation,
//! C users and the design cannot drift apart. `SKYLUX_BLESS=1` rewrites them.

use std::path::PathBuf;

fn repo_root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

fn check(path: &str, rendered: &str) {
    let file = repo_root().join(path);
    if std::env::var_os("SKYLUX_BLESS").is_some() {
        std::fs::write(&file, rendered).unwrap();
        return;
    }
    let on_disk = std::fs::read_to_string(&file).unwrap_or_default();
    assert!(
        on_disk == rendered,
        "{path} is stale: regenerate it with `SKYLUX_BLESS=1 cargo test -p skylux-regmap`"
    );
}

#[test]
fn markdown_is_current() {
    check(
        skylux_regmap::render::MARKDOWN_PATH,
        &skylux_regmap::render::markdown(),
    );
}

#[test]
fn c_header_is_current() {
    check(
        skylux_regmap::render::C_HEADER_PATH,
        &skylux_regmap::render::c_header(),
    );
}

/// The header is real C: it compiles, and its values agree with the map (checked by a
/// program compiled from it), when a C compiler is present.
#[test]
fn c_header_compiles_and_agrees() {
    use skylux_regmap::{seq, sys};
    let dir = tempdir();
    let source = dir.join("check.c");
    let header = repo_root().join(skylux_regmap::render::C_HEADER_PATH);
    std::fs::write(
        &source,
        format!(
            "#include \"{}\"\n#include <stdio.h>\nint main(void) {{ printf(\"%x %x %x %x\\n\", \
             SKYLUX_SYS_ID_VALUE_VALUE, SKYLUX_SEQ_EXP_GAIN_OFFSET(3), \
             SKYLUX_SEQ_STATUS_DONE_MASK, SKYLUX_I2C_TARGET_RESET); return 0; }}\n",
            header.display()
        ),
    )
    .unwrap();
    let exe = dir.join("check");
    // Never skipped: `cc` is the linker Rust itself uses on Linux, so it is wherever these
    // tests were built.
    let status = std::process::Command::new("cc")
        .arg("-Wall")
        .arg("-Werror")
        .arg(&source)
        .arg("-o")
        .arg(&exe)
        .status()
        .expect("a C compiler (`cc`, the linker Rust uses) to compile the C header");
    assert!(status.success(), "the C header does not compile");
    let out = std::process::Command::new(&exe).output().unwrap();
    let expected = format!(
        "{:x} {:x} {:x} {:x}\n",
        sys::id::VALUE.reset,
        seq::exp_gain::REG.offset_of(3).unwrap(),
        seq::status::DONE.mask(),
        skylux_regmap::i2c::target::REG.reset_value()
    );
    assert_eq!(String::from_utf8_lossy(&out.stdout), expected);
}

fn tempdir() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("skylux-regmap-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
