//! Starting this crate's binaries from tests, on the host and under qemu-user.
//!
//! Under `cargo test --target armv7-unknown-linux-gnueabihf` the test binary runs in
//! qemu-arm (the runner in .cargo/config.toml). A process it starts is executed by the host
//! kernel, which cannot run an ARM executable unless binfmt_misc is set up for qemu; then the
//! child must be started through `qemu-arm -L /usr/arm-linux-gnueabihf` as the runner does.

use std::path::Path;
use std::process::Command;

/// The sysroot Debian's armhf cross toolchain installs (as in .cargo/config.toml's runner).
pub const QEMU_ARM_SYSROOT: &str = "/usr/arm-linux-gnueabihf";

/// A command that runs `exe` here: directly, or through qemu-arm when this is an ARM build
/// the host cannot execute natively (`$SKYLUXD_QEMU` overrides the emulator).
pub fn command_for(exe: &Path) -> Command {
    if cfg!(target_arch = "arm") && !can_exec_directly(exe) {
        let qemu = std::env::var("SKYLUXD_QEMU").unwrap_or_else(|_| "qemu-arm".into());
        let mut c = Command::new(qemu);
        c.arg("-L").arg(QEMU_ARM_SYSROOT).arg(exe);
        c
    } else {
        Command::new(exe)
    }
}

/// Whether the kernel runs `exe` itself (false under qemu-user without binfmt_misc).
/// Depending on how the spawn is emulated, a failed exec shows either as ENOEXEC or as a
/// child that exits with 127 (the shell's "cannot execute"), which neither skyluxd's nor a
/// test binary's `--version` does.
fn can_exec_directly(exe: &Path) -> bool {
    match Command::new(exe)
        .arg("--version")
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status()
    {
        Ok(status) => status.code() != Some(127),
        Err(e) => e.raw_os_error() != Some(libc::ENOEXEC),
    }
}
