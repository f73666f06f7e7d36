//! Replays a rust-hdl port trace in Icarus Verilog and compares every output at every step.

use super::tools::{run, work_dir, Tool, ToolError};
use skylux_rtl::drive::{PortDir, PortTrace};
use std::fmt::Write;

/// One output that differs between the rust-hdl simulation and the Verilog.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Mismatch {
    pub step: usize,
    pub port: String,
    pub rust: String,
    pub verilog: String,
}

/// What a replay found.
#[derive(Clone, Debug, Default)]
pub struct ReplayReport {
    pub steps: usize,
    pub outputs: usize,
    /// Every differing (step, output), in order.
    pub mismatches: Vec<Mismatch>,
}

impl ReplayReport {
    pub fn is_clean(&self) -> bool {
        self.mismatches.is_empty()
    }
    /// A readable summary of the first few mismatches.
    pub fn summary(&self) -> String {
        let mut s = format!(
            "{} mismatches over {} steps x {} outputs",
            self.mismatches.len(),
            self.steps,
            self.outputs
        );
        for m in self.mismatches.iter().take(8) {
            let _ = write!(
                s,
                "\n  step {}: {} rust-hdl {} verilog {}",
                m.step, m.port, m.rust, m.verilog
            );
        }
        s
    }
}

fn tb_name(port: &str) -> String {
    format!("p_{}", port.replace('$', "__"))
}

fn decl(width: usize) -> String {
    if width == 1 {
        String::new()
    } else {
        format!("[{}:0] ", width - 1)
    }
}

/// Writes a testbench that applies the trace's inputs step by step and prints the outputs,
/// runs it under Icarus, and compares.
pub fn replay(name: &str, verilog: &str, trace: &PortTrace) -> Result<ReplayReport, ToolError> {
    let dir = work_dir(name)?;
    let dut = dir.join(format!("{name}.v"));
    std::fs::write(&dut, verilog).map_err(|e| ToolError::Io(dut.clone(), e))?;

    let inputs: Vec<usize> = (0..trace.ports.len())
        .filter(|&i| trace.ports[i].dir == PortDir::In)
        .collect();
    let outputs: Vec<usize> = (0..trace.ports.len())
        .filter(|&i| trace.ports[i].dir == PortDir::Out)
        .collect();
    let mut tb = String::from("`timescale 1ns/1ps\nmodule tb;\n");
    for p in &trace.ports {
        let kind = if p.dir == PortDir::In { "reg" } else { "wire" };
        let _ = writeln!(tb, "{kind} {}{};", decl(p.width), tb_name(&p.name));
    }
    let conns: Vec<String> = trace
        .ports
        .iter()
        .map(|p| format!(".{}({})", p.name, tb_name(&p.name)))
        .collect();
    let _ = writeln!(tb, "top dut({});", conns.join(", "));
    let fmt: Vec<&str> = outputs.iter().map(|_| "%b").collect();
    let args: Vec<String> = outputs
        .iter()
        .map(|&i| tb_name(&trace.ports[i].name))
        .collect();
    let display = format!("$display(\"{}\", {});", fmt.join(" "), args.join(", "));
    let _ = writeln!(tb, "initial begin");
    for (step, values) in trace.steps.iter().enumerate() {
        for &i in &inputs {
            if step == 0 || trace.steps[step - 1][i] != values[i] {
                let _ = writeln!(
                    tb,
                    "  {} = {}'b{};",
                    tb_name(&trace.ports[i].name),
                    trace.ports[i].width,
                    values[i]
                );
            }
        }
        let _ = writeln!(tb, "  #1; {display}");
    }
    let _ = writeln!(tb, "  $finish;\nend\nendmodule");
    let tb_file = dir.join(format!("{name}_tb.v"));
    std::fs::write(&tb_file, tb).map_err(|e| ToolError::Io(tb_file.clone(), e))?;

    let exe = format!("{name}.vvp");
    run(
        Tool::Iverilog,
        &dir,
        &[
            "-g2005",
            "-s",
            "tb",
            "-o",
            &exe,
            dut.to_str().unwrap(),
            tb_file.to_str().unwrap(),
        ],
    )?;
    let out = run(Tool::Vvp, &dir, &["-n", &exe])?;

    let mut report = ReplayReport {
        steps: trace.steps.len(),
        outputs: outputs.len(),
        mismatches: vec![],
    };
    let lines: Vec<&str> = out
        .lines()
        .filter(|l| !l.starts_with("VCD") && !l.trim().is_empty())
        .collect();
    if lines.len() != trace.steps.len() {
        return Err(ToolError::Failed {
            tool: "vvp",
            output: format!("{} lines for {} steps", lines.len(), trace.steps.len()),
        });
    }
    for (step, line) in lines.iter().enumerate() {
        for (k, verilog_value) in line.split_whitespace().enumerate() {
            let port = &trace.ports[outputs[k]];
            let rust_value = &trace.steps[step][outputs[k]];
            if !same_bits(rust_value, verilog_value, port.width) {
                report.mismatches.push(Mismatch {
                    step,
                    port: port.name.clone(),
                    rust: rust_value.clone(),
                    verilog: verilog_value.to_string(),
                });
            }
        }
    }
    Ok(report)
}

/// Compares two binary strings of a `width`-bit value (Icarus prints `%b` at full width).
fn same_bits(rust: &str, verilog: &str, width: usize) -> bool {
    let pad = |s: &str| format!("{s:0>width$}");
    pad(rust).to_lowercase() == pad(verilog).to_lowercase()
}
