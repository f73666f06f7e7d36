//! Finding and running the open-source Verilog tools.

use std::path::{Path, PathBuf};
use std::process::Command;

/// An external tool of the harness.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Tool {
    Iverilog,
    Vvp,
    Yosys,
    Verilator,
    /// yosys' SMT bounded model checker and k-induction driver (the formal proofs).
    SmtBmc,
    /// The SMT solver behind `yosys-smtbmc` (Debian package `z3`).
    Z3,
}

impl Tool {
    pub fn command(self) -> &'static str {
        match self {
            Tool::Iverilog => "iverilog",
            Tool::Vvp => "vvp",
            Tool::Yosys => "yosys",
            Tool::Verilator => "verilator",
            Tool::SmtBmc => "yosys-smtbmc",
            Tool::Z3 => "z3",
        }
    }
}

/// Why a tool run failed.
#[derive(Debug, thiserror::Error)]
pub enum ToolError {
    #[error("{0} is not installed (apt-get install iverilog yosys verilator z3)")]
    Missing(&'static str),
    #[error("{tool} failed:\n{output}")]
    Failed { tool: &'static str, output: String },
    #[error("{0}: {1}")]
    Io(PathBuf, std::io::Error),
}

fn present(tool: Tool) -> bool {
    Command::new(tool.command())
        .arg(if tool == Tool::Vvp { "-V" } else { "--version" })
        .output()
        .is_ok()
}

/// Checks that the tools are installed. When one is missing, the harness fails if
/// `SKYLUX_REQUIRE_EDA` is set (as CI sets it) and otherwise returns false so a developer
/// machine without them still runs the rest of the test suite; the skip is printed.
pub fn require(tools: &[Tool]) -> bool {
    let missing: Vec<_> = tools
        .iter()
        .filter(|t| !present(**t))
        .map(|t| t.command())
        .collect();
    if missing.is_empty() {
        return true;
    }
    if std::env::var_os("SKYLUX_REQUIRE_EDA").is_some() {
        panic!("Verilog cross-check tools missing: {missing:?} (SKYLUX_REQUIRE_EDA is set)");
    }
    eprintln!("SKIPPED Verilog cross-check: {missing:?} not installed (CI installs them and sets SKYLUX_REQUIRE_EDA)");
    false
}

/// A scratch directory for one block's tool runs.
pub(crate) fn work_dir(name: &str) -> Result<PathBuf, ToolError> {
    let dir = std::env::temp_dir()
        .join(format!("skylux-xcheck-{}", std::process::id()))
        .join(name);
    std::fs::create_dir_all(&dir).map_err(|e| ToolError::Io(dir.clone(), e))?;
    Ok(dir)
}

/// Runs a tool in `dir`; returns its stdout, or its whole output when it fails.
pub(crate) fn run(tool: Tool, dir: &Path, args: &[&str]) -> Result<String, ToolError> {
    let out = Command::new(tool.command())
        .current_dir(dir)
        .args(args)
        .output()
        .map_err(|_| ToolError::Missing(tool.command()))?;
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    if out.status.success() {
        Ok(String::from_utf8_lossy(&out.stdout).into_owned())
    } else {
        Err(ToolError::Failed {
            tool: tool.command(),
            output: text,
        })
    }
}
