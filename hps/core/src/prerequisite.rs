//! Tests that need something outside the build (a tool, root, a kernel feature): the one home
//! of the `SKYLUX_REQUIRE_*` rule. Where the prerequisite is missing, a developer's machine
//! still runs the rest of the suite (the test prints `SKIPPED` and passes), but CI, which sets
//! the variable, fails: a test never passes in CI without having run.

/// RADIANCE (rtrace, gensky, oconv, rcalc, pyradiance): the physics comparisons.
pub const REQUIRE_RADIANCE: &str = "SKYLUX_REQUIRE_RADIANCE";
/// The Verilog tools (verilator, yosys, iverilog, z3, dtc): the cross-checks and proofs.
pub const REQUIRE_EDA: &str = "SKYLUX_REQUIRE_EDA";
/// The CI host itself: root, `chattr +i` on the temporary directory's file system, abstract
/// unix sockets. Not set under qemu-arm (`scripts/armv7-tests`), where the emulator stands
/// between the test and the kernel.
pub const REQUIRE_HOST: &str = "SKYLUX_REQUIRE_HOST";

/// Whether a test may go on: true when `available`. When not, panics if `variable` is set,
/// otherwise prints `SKIPPED: {what}` and returns false (the caller returns).
pub fn available_or_skip(available: bool, variable: &str, what: &str) -> bool {
    if available {
        return true;
    }
    if std::env::var_os(variable).is_some() {
        panic!("{what}, and {variable} is set: this test must run here");
    }
    eprintln!("SKIPPED: {what} (set {variable} to make this a failure)");
    false
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn skips_without_the_variable_and_fails_with_it() {
        assert!(available_or_skip(true, "SKYLUX_REQUIRE_NEVER_SET", "x"));
        assert!(!available_or_skip(false, "SKYLUX_REQUIRE_NEVER_SET", "x"));
        // PATH is always set: a missing prerequisite under a set variable panics.
        let r = std::panic::catch_unwind(|| available_or_skip(false, "PATH", "no tool"));
        let message = r.unwrap_err().downcast::<String>().unwrap();
        assert!(
            message.contains("no tool") && message.contains("PATH"),
            "{message}"
        );
    }
}
