//! Direct-drive simulation: the fast way to run rust-hdl designs (about 50 times faster than
//! the threaded `Simulation` runner; shared/docs/rust-hdl-notes.md section 4), with an optional
//! record of every top-level port at every settle step for the Verilog cross-check.
//!
//! Rule kept here so no test can break it: inputs change in their own settle, never in the
//! same settle as a clock edge (a hold race that exists only in simulation).

use rust_hdl::core::atom::{Atom, AtomKind};
use rust_hdl::core::probe::Probe;
use rust_hdl::core::synth::VCDValue;
use rust_hdl::prelude::*;

/// Why a direct-drive step failed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum DriveError {
    /// The combinational logic did not settle: a loop, or too deep a design.
    NoConvergence { step: u64 },
}

impl std::fmt::Display for DriveError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            DriveError::NoConvergence { step } => write!(f, "logic did not settle at step {step}"),
        }
    }
}
impl std::error::Error for DriveError {}

/// Direction of a top-level port.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum PortDir {
    In,
    Out,
}

/// A top-level port as it appears in the generated Verilog.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Port {
    pub name: String,
    pub width: usize,
    pub dir: PortDir,
}

/// The value of every top-level port after each settle step, as binary strings (MSB first),
/// so that any width and X/Z are represented.
#[derive(Clone, Debug, Default)]
pub struct PortTrace {
    pub ports: Vec<Port>,
    pub steps: Vec<Vec<String>>,
}

struct TopPorts<'a> {
    depth: usize,
    ports: Vec<Port>,
    values: &'a mut Vec<String>,
}

fn vcd_bits(value: &VCDValue, width: usize) -> String {
    let bit = |v: &vcd::Value| match v {
        vcd::Value::V0 => '0',
        vcd::Value::V1 => '1',
        vcd::Value::X => 'x',
        vcd::Value::Z => 'z',
    };
    match value {
        VCDValue::Single(v) => bit(v).to_string(),
        VCDValue::Vector(vs) => {
            let s: String = vs.iter().map(bit).collect();
            format!("{s:0>width$}")
        }
        VCDValue::String(s) => s.clone(),
        VCDValue::Composite(_) => "x".repeat(width),
    }
}

impl Probe for TopPorts<'_> {
    fn visit_start_scope(&mut self, _name: &str, _node: &dyn Block) {
        self.depth += 1;
    }
    fn visit_end_scope(&mut self, _name: &str, _node: &dyn Block) {
        self.depth -= 1;
    }
    fn visit_atom(&mut self, name: &str, signal: &dyn Atom) {
        if self.depth != 1 {
            return;
        }
        let dir = match signal.kind() {
            AtomKind::InputParameter => PortDir::In,
            AtomKind::OutputParameter | AtomKind::OutputPassthrough => PortDir::Out,
            _ => return,
        };
        self.ports.push(Port {
            name: name.to_string(),
            width: signal.bits(),
            dir,
        });
        self.values.push(vcd_bits(&signal.vcd(), signal.bits()));
    }
}

/// Reads the top-level ports of `uut` and their current values.
pub fn top_ports<B: Block>(uut: &B) -> (Vec<Port>, Vec<String>) {
    let mut values = vec![];
    let mut probe = TopPorts {
        depth: 0,
        ports: vec![],
        values: &mut values,
    };
    uut.accept("top", &mut probe);
    let ports = probe.ports;
    (ports, values)
}

/// Selects one clock input of the design under test.
pub type ClockPin<B> = fn(&mut B) -> &mut Signal<In, Clock>;

/// Drives a design directly, settle by settle.
pub struct Driver<B: Block> {
    pub dut: B,
    steps: u64,
    trace: Option<PortTrace>,
}

impl<B: Block> Driver<B> {
    /// Connects the design and checks it (open signals, loops).
    pub fn new(mut dut: B) -> Self {
        dut.connect_all();
        if let Err(e) = check_all(&dut) {
            panic!("design failed rust-hdl's checks: {e:?}");
        }
        Self {
            dut,
            steps: 0,
            trace: None,
        }
    }

    /// Starts recording every top-level port at every settle step.
    pub fn record(&mut self) {
        let (ports, _) = top_ports(&self.dut);
        self.trace = Some(PortTrace {
            ports,
            steps: vec![],
        });
    }

    /// The recording so far (empty if `record` was never called).
    pub fn take_trace(&mut self) -> PortTrace {
        self.trace.take().unwrap_or_default()
    }

    /// Settle steps run so far.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// Propagates the current inputs until nothing changes.
    pub fn settle(&mut self) -> Result<(), DriveError> {
        self.steps += 1;
        if !simulate(&mut self.dut, 1000) {
            return Err(DriveError::NoConvergence { step: self.steps });
        }
        if let Some(trace) = &mut self.trace {
            let (_, values) = top_ports(&self.dut);
            trace.steps.push(values);
        }
        Ok(())
    }

    /// Sets one clock to a level and settles.
    pub fn set_clock(&mut self, clock: ClockPin<B>, level: bool) -> Result<(), DriveError> {
        clock(&mut self.dut).next = Clock::from(level);
        self.settle()
    }

    /// One full period of a clock: the inputs set so far settle first, then the rising edge,
    /// then the falling edge.
    pub fn cycle(&mut self, clock: ClockPin<B>) -> Result<(), DriveError> {
        self.settle()?;
        self.set_clock(clock, true)?;
        self.set_clock(clock, false)
    }
}
