//! The Verilog cross-check harness.
//!
//! For each block: (a) `verilator --lint-only`; (b) yosys `proc; flatten; check -assert` (no
//! latches, no combinational loops across modules) and `synth_intel_alm -family cyclonev` for
//! the resource figures; (c) Icarus replays a port trace recorded from the rust-hdl simulation
//! (every top-level input at every settle step) and every output must agree at every step.

mod replay;
pub(crate) mod tools;
mod yosys;

pub use replay::{replay, Mismatch, ReplayReport};
pub use tools::{require, Tool, ToolError};
pub use yosys::{structural_check, synthesize, Resources, DEVICE_ALMS};

/// Runs `verilator --lint-only` on a design whose top module is `top`.
pub fn lint(name: &str, verilog: &str) -> Result<(), ToolError> {
    let dir = tools::work_dir(name)?;
    let file = dir.join(format!("{name}.v"));
    std::fs::write(&file, verilog).map_err(|e| ToolError::Io(file.clone(), e))?;
    // WIDTH: rust-hdl writes every literal as 32 bits; UNOPTFLAT: one always block per module
    // (both explained in rust-hdl-notes §5). Real loops are caught by yosys `check -assert`.
    tools::run(
        Tool::Verilator,
        &dir,
        &[
            "--lint-only",
            "-Wall",
            "-Wno-WIDTH",
            "-Wno-UNOPTFLAT",
            "-Wno-DECLFILENAME",
            "-Wno-UNUSED",
            "-Wno-PINCONNECTEMPTY",
            "--top-module",
            "top",
            file.to_str().unwrap(),
        ],
    )
    .map(|_| ())
}
