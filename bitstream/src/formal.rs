//! Formal proofs of the fabric's safety properties (issue 23 item 4), on the exported Verilog.
//!
//! The design under proof is cut out of the Verilog of the whole core ([`core_verilog`], the
//! file Quartus compiles, generated from a fresh instance): a block's module and every module
//! below it, untouched. A generated wrapper `formal_top` instantiates that block with every
//! input driven by an `anyseq` signal (any value in any cycle) and states the property as
//! immediate assertions; yosys turns the whole into SMT-LIB (`write_smt2`) and `yosys-smtbmc`
//! checks it with z3, by bounded model checking from the power-up state (the `initial` values,
//! the only reset the fabric has) and by k-induction, which needs no initial state and so
//! covers every depth.
//!
//! k-induction needs the property to be inductive, which the bare property is not (an
//! unreachable state can satisfy it and break it one cycle later). Each proof therefore also
//! asserts a few invariants of the block's registers, read through *probes*: wires of the
//! wrapper connected after `flatten` to the block's internal register outputs (yosys 0.23 has
//! no hierarchical references). The invariants are proven along with the property: nothing is
//! assumed of the block's state except at power-up in the bounded run.
//!
//! The two proofs ([`shield_proof`], [`dma_window_proof`]) and the broken variants
//! ([`shield_broken`], [`dma_broken`]) are described in `bitstream/README.md`, "Formal proofs".

use crate::blocks::core_verilog;
use crate::xcheck::tools::{run, work_dir, Tool, ToolError};
use std::path::PathBuf;

/// The k of the k-induction (and the depth of the bounded base case) of both proofs.
pub const PROOF_DEPTH: u32 = 1;
/// The depth at which the broken variants' counterexamples must be found.
pub const BROKEN_DEPTH: u32 = 8;

/// The tools the proofs need.
pub const TOOLS: &[Tool] = &[Tool::Yosys, Tool::SmtBmc, Tool::Z3];

/// A port of a module of the exported Verilog.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Port {
    pub name: String,
    pub width: u32,
    pub input: bool,
}

/// A wrapper wire connected, after `flatten`, to a net inside the block under proof.
#[derive(Clone, Copy, Debug)]
pub struct Probe {
    /// The wire declared in the wrapper's property code.
    pub wire: &'static str,
    /// The net's path below the block's instance `dut` (e.g. `sequencer.position$q`).
    pub path: &'static str,
}

/// One property of one block.
#[derive(Clone, Debug)]
pub struct Proof {
    pub name: &'static str,
    /// The block's module in the exported Verilog (with its sub-modules).
    pub module: &'static str,
    /// The Verilog of the design (all modules below and including `module`).
    pub design: String,
    /// Property code placed in `formal_top` after the block's instance: it sees every port of
    /// the block as a wire of the same name, the clock as `clock`, and the probes.
    pub property: String,
    pub probes: &'static [Probe],
}

/// How to check a proof.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Check {
    /// Bounded model check from the power-up state, `depth` cycles.
    Bmc { depth: u32 },
    /// k-induction with `depth` steps: if it passes and the bounded check of the same depth
    /// passes, the property holds in every reachable state.
    Induction { depth: u32 },
}

/// The solver's answer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Verdict {
    Passed,
    /// An assertion failed (a counterexample in BMC; a failed induction step otherwise):
    /// which assertions (source lines of the wrapper), at which step, and the trace file.
    Failed {
        step: Option<u32>,
        asserts: Vec<String>,
        trace: PathBuf,
    },
}

impl Verdict {
    pub fn passed(&self) -> bool {
        *self == Verdict::Passed
    }
}

/// Every module of `verilog` named `top` or `top$...`, in file order.
pub fn extract_hierarchy(verilog: &str, top: &str) -> String {
    let sub = format!("{top}$");
    let mut out = String::new();
    let mut keep = false;
    for line in verilog.lines() {
        if let Some(rest) = line.strip_prefix("module ") {
            let name = rest.split('(').next().unwrap_or("").trim();
            keep = name == top || name.starts_with(&sub);
        }
        if keep {
            out.push_str(line);
            out.push('\n');
        }
        if line.starts_with("endmodule") {
            keep = false;
        }
    }
    out
}

/// The ports of `module` as declared in `verilog` (rust-hdl writes one declaration a line:
/// `input wire  [W:0] name;`, `output reg  name;`).
pub fn module_ports(verilog: &str, module: &str) -> Vec<Port> {
    let header = format!("module {module}(");
    let mut ports = Vec::new();
    let mut inside = false;
    for line in verilog.lines() {
        if line.starts_with(&header) {
            inside = true;
            continue;
        }
        if !inside {
            continue;
        }
        if line.starts_with("endmodule") {
            break;
        }
        let t = line.trim();
        let input = t.starts_with("input ");
        if !(input || t.starts_with("output ")) {
            continue;
        }
        let decl = t.trim_end_matches(';');
        let width = match (decl.find('['), decl.find(':')) {
            (Some(a), Some(b)) if a < b => decl[a + 1..b].trim().parse::<u32>().unwrap_or(0) + 1,
            _ => 1,
        };
        let name = decl.split_whitespace().last().unwrap_or("").to_string();
        ports.push(Port { name, width, input });
    }
    ports
}

/// The wrapper module `formal_top`: the block as `dut`, every input but `clock` an `anyseq`
/// wire, every output a wire, each named as the port; then the probes and the property.
pub fn wrapper(proof: &Proof) -> String {
    let ports = module_ports(&proof.design, proof.module);
    assert!(
        ports.iter().any(|p| p.name == "clock"),
        "{}: no clock port in {}",
        proof.name,
        proof.module
    );
    let range = |w: u32| {
        if w > 1 {
            format!("[{}:0] ", w - 1)
        } else {
            String::new()
        }
    };
    let mut v = String::new();
    v.push_str(&format!(
        "// Formal wrapper for {} (generated by skylux_bitstream::formal).\n",
        proof.name
    ));
    v.push_str("module formal_top(input wire clock);\n");
    for p in ports.iter().filter(|p| p.name != "clock") {
        let attr = if p.input { "(* anyseq *) " } else { "" };
        v.push_str(&format!("    {attr}wire {}{};\n", range(p.width), p.name));
    }
    let conns: Vec<String> = ports
        .iter()
        .map(|p| format!("        .{}({})", p.name, p.name))
        .collect();
    v.push_str(&format!(
        "    {} dut(\n{}\n    );\n",
        proof.module,
        conns.join(",\n")
    ));
    v.push_str(&proof.property);
    v.push_str("endmodule\n");
    v
}

/// Runs one check of a proof with z3; the files are kept in a scratch directory named after
/// the proof (the wrapper, the SMT-LIB model, the solver log and, on failure, `trace.vcd`).
pub fn check(proof: &Proof, check: Check) -> Result<Verdict, ToolError> {
    let tag = match check {
        Check::Bmc { depth } => format!("bmc{depth}"),
        Check::Induction { depth } => format!("ind{depth}"),
    };
    let dir = work_dir(&format!("formal-{}-{tag}", proof.name))?;
    let write = |file: &str, text: &str| {
        let path = dir.join(file);
        std::fs::write(&path, text).map_err(|e| ToolError::Io(path, e))
    };
    write("design.v", &proof.design)?;
    write("wrapper.v", &wrapper(proof))?;
    let connects: String = proof
        .probes
        .iter()
        .map(|p| format!("connect -nounset -set {} \\dut.{}; ", p.wire, p.path))
        .collect();
    let script = format!(
        "read_verilog design.v; read_verilog -formal wrapper.v; hierarchy -check -top formal_top; \
         proc; flatten; {connects}opt_clean; check -assert; memory -nomap; opt; \
         async2sync; dffunmap; write_smt2 -wires model.smt2"
    );
    run(Tool::Yosys, &dir, &["-q", "-l", "yosys.log", "-p", &script])?;
    let depth = match check {
        Check::Bmc { depth } | Check::Induction { depth } => depth.to_string(),
    };
    let mut args = vec![
        "-s",
        "z3",
        "--unroll",
        "-t",
        &depth,
        "--dump-vcd",
        "trace.vcd",
    ];
    if let Check::Induction { .. } = check {
        args.push("-i");
    }
    args.push("model.smt2");
    let log = match run(Tool::SmtBmc, &dir, &args) {
        Ok(out) => out,
        Err(ToolError::Failed { output, .. }) => output,
        Err(e) => return Err(e),
    };
    write("smtbmc.log", &log)?;
    if log.contains("Status: PASSED") {
        return Ok(Verdict::Passed);
    }
    if !log.contains("Status: FAILED") {
        return Err(ToolError::Failed {
            tool: "yosys-smtbmc",
            output: log,
        });
    }
    let asserts = log
        .lines()
        .filter_map(|l| l.split("Assert failed in formal_top: ").nth(1))
        .map(str::to_string)
        .collect();
    // "Checking assertions in step N.." is the last step the solver reached.
    let step = log
        .lines()
        .filter_map(|l| l.split("assertions in step ").nth(1))
        .filter_map(|s| s.trim_end_matches('.').parse().ok())
        .next_back();
    Ok(Verdict::Failed {
        step,
        asserts,
        trace: dir.join("trace.vcd"),
    })
}

/// The property's bounded check and its induction step, both at `depth`: `Passed` only if
/// both pass (the property then holds at every depth).
pub fn prove(proof: &Proof, depth: u32) -> Result<Verdict, ToolError> {
    let base = check(proof, Check::Bmc { depth })?;
    if !base.passed() {
        return Ok(base);
    }
    check(proof, Check::Induction { depth })
}

// ---- 1. the lens shield ------------------------------------------------------------------

/// The block holding the shield logic, as the core instantiates it.
pub const SHIELD_MODULE: &str = "skylux_core$sensor$sequencer";

/// The shield ceiling: 0.55 s at 100 MHz (`skylux_rtl::sequencer::SHIELD_LIMIT_MAX_CYCLES`).
pub const SHIELD_CEILING_CYCLES: u64 = 55_000_000;
const _: () = assert!(SHIELD_CEILING_CYCLES == skylux_rtl::sequencer::SHIELD_LIMIT_MAX_CYCLES);

/// Property: `seq_status_shield_open` (the shield's step position is not 0) is never high for
/// more consecutive cycles than `min(L, 55,000,000)`, where `L` is `seq_shield_limit_cycles`
/// at the START that began the sequence; in particular never more than 55,000,000 cycles.
/// Every input (register fields, START, ABORT, the external trigger, FRAME_VALID, the I2C
/// pins, the time base) takes any value in any cycle.
const SHIELD_PROPERTY: &str = r#"
    localparam [31:0] CEILING = 32'd55000000;
    // The ceiling in force: min(seq.shield_limit, 0.55 s) as written when the sequence began
    // (the cycle before BUSY rose, when the sequencer accepted START).
    reg busy_prev = 1'b0;
    reg [31:0] limit_prev = 32'd0;
    reg [31:0] ceiling_r = 32'd0;
    wire started = busy & ~busy_prev;
    wire [31:0] limit_at_start = (limit_prev < CEILING) ? limit_prev : CEILING;
    wire [31:0] ceiling = started ? limit_at_start : ceiling_r;
    // Consecutive cycles the shield has been open, this one included.
    reg [31:0] open_run = 32'd0;
    wire [32:0] open_now = shield_open ? {1'b0, open_run} + 33'd1 : 33'd0;
    always @(posedge clock) begin
        busy_prev <= busy;
        limit_prev <= shield_limit_cycles;
        ceiling_r <= ceiling;
        open_run <= open_now[31:0];
    end
    always @* begin
        assert (ceiling <= CEILING);
        assert (open_now <= {1'b0, ceiling});           // THE PROPERTY
    end

    // Induction invariants on the sequencer's registers (proven with the property).
    wire [2:0] p_state;
    wire [15:0] p_position;
    wire [23:0] p_period;
    wire [31:0] p_limit;
    wire [31:0] p_open;
    wire [47:0] p_cost;
    wire [23:0] p_timer;
    wire s_idle = p_state == 3'd0;
    wire s_open = p_state == 3'd1;
    wire s_close = p_state == 3'd6;
    wire p_shield_open = p_position != 16'd0;
    wire [47:0] open48 = {16'd0, p_open};
    wire [47:0] period48 = {24'd0, p_period};
    wire [47:0] limit48 = {16'd0, p_limit};
    wire [47:0] timer48 = {24'd0, p_timer};
    // Lemma M: close_cost == position * period (48 bits). A multiplier invariant is beyond
    // the solver in an induction step, so M is split: the transition shape T below is
    // proven here (linear), and M follows from T by induction over time with the ring
    // identities (P +- 1) q = P q +- q (checked separately: `RING_IDENTITIES`). Only the two
    // linear consequences of M that the invariants need are assumed, never M itself.
    reg t_valid = 1'b0;
    reg [15:0] t_position = 16'd0;
    reg [47:0] t_cost = 48'd0;
    reg [23:0] t_period = 24'd0;
    always @(posedge clock) begin
        t_valid <= 1'b1;
        t_position <= p_position;
        t_cost <= p_cost;
        t_period <= p_period;
    end
    wire [16:0] pos17 = {1'b0, p_position};
    wire [16:0] prev17 = {1'b0, t_position};
    always @* begin
        if (t_valid)
            assert ((p_position == t_position && p_cost == t_cost && p_period == t_period)
                    || (pos17 == prev17 + 17'd1 && p_cost == t_cost + period48
                        && p_period == t_period)
                    || (pos17 + 17'd1 == prev17 && p_cost == t_cost - period48
                        && p_period == t_period)
                    || (p_position == 16'd0 && p_cost == 48'd0 && t_position == 16'd0));
        else
            assert (p_position == 16'd0 && p_cost == 48'd0);
        assume (p_shield_open || p_cost == 48'd0);          // M with P = 0
        assume (!p_shield_open || p_cost >= period48);      // M with P >= 1
        assume (p_cost[47:40] == 8'd0);                     // M: P q < 2^16 2^24
    end
    always @* begin
        assert (p_state <= 3'd6);
        assert (p_limit == ceiling);
        assert (s_idle || p_period >= 24'd2);
        assert (!s_idle || (!p_shield_open && p_timer == 24'd0));
        assert (s_idle || p_timer < p_period);
        assert (s_idle || s_open || s_close || p_timer == 24'd0);
        assert (!(s_open && !p_shield_open) || p_open == 32'd0);
        assert (!p_shield_open || open_run == p_open);
        assert (s_idle || s_close || !p_shield_open || open48 + p_cost <= limit48);
        assert (!(s_close && p_shield_open && p_timer == 24'd0)
                || open48 + p_cost + 48'd1 <= limit48 + period48);
        assert (!(s_close && p_shield_open && p_timer != 24'd0)
                || open48 + p_cost + 48'd1 <= limit48 + timer48);
    end
"#;

const SHIELD_PROBES: &[Probe] = &[
    Probe {
        wire: "p_state",
        path: "state$q",
    },
    Probe {
        wire: "p_position",
        path: "position$q",
    },
    Probe {
        wire: "p_period",
        path: "period_l$q",
    },
    Probe {
        wire: "p_limit",
        path: "limit_l$q",
    },
    Probe {
        wire: "p_open",
        path: "open_cycles$q",
    },
    Probe {
        wire: "p_cost",
        path: "close_cost$q",
    },
    Probe {
        wire: "p_timer",
        path: "step_timer$q",
    },
];

/// The shield proof on `core` (the Verilog of the whole core, module `skylux_core`).
pub fn shield_proof_of(core: &str) -> Proof {
    Proof {
        name: "shield",
        module: SHIELD_MODULE,
        design: extract_hierarchy(core, SHIELD_MODULE),
        property: SHIELD_PROPERTY.to_string(),
        probes: SHIELD_PROBES,
    }
}

/// The shield proof on the exported core.
pub fn shield_proof() -> Proof {
    shield_proof_of(&core_verilog())
}

/// Marks the start of a property's induction invariants.
const INVARIANTS_MARK: &str = "    // Induction invariants";

/// The property alone, without the induction invariants and probes: what a broken variant
/// is checked with, so that the counterexample found is one to the property itself.
/// (`keep` is appended again, e.g. an environment assumption.)
pub fn property_only(mut proof: Proof, keep: &str) -> Proof {
    if let Some(i) = proof.property.find(INVARIANTS_MARK) {
        proof.property.truncate(i);
    }
    proof.property.push_str(keep);
    proof.probes = &[];
    proof
}

/// The budget comparison that starts closing the shield, as exported, and its broken form
/// (closing starts one cycle late: `>` for `>=`).
pub const SHIELD_COMPARISON: &str =
    "over_budget = (position$q != 32'h0) & (budget_now >= limit48);";
pub const SHIELD_COMPARISON_BROKEN: &str =
    "over_budget = (position$q != 32'h0) & (budget_now > limit48);";

/// The shield proof on a copy of the exported Verilog whose ceiling comparison is off by one.
pub fn shield_broken() -> Proof {
    let core = core_verilog();
    assert_eq!(
        core.matches(SHIELD_COMPARISON).count(),
        1,
        "the shield comparison is not where the broken variant expects it"
    );
    let mut p = shield_proof_of(&core.replace(SHIELD_COMPARISON, SHIELD_COMPARISON_BROKEN));
    p.name = "shield_broken";
    property_only(p, "")
}

// ---- 2. the DMA window -------------------------------------------------------------------

/// The Avalon-MM burst master of the frame DMA, as the core instantiates it.
pub const DMA_MODULE: &str = "skylux_core$capture$writer";

/// Property: every beat the writer puts on the bus lies inside the window, `[window_base,
/// window_base + window_size)`, as programmed when the writer took up the frame (the cycle
/// before `dma_status_busy` rose, when it checked the slot). A beat is a cycle with
/// `avm_write`; beat `i` of a burst addresses `avm_address + 8 i`; all 8 bytes must be inside,
/// both as a byte address and as the word address the core puts on the f2sdram port
/// (`avm_address[31:3]`). Also: `burstcount` is not 0, and address and burstcount hold for
/// the whole burst. Every input (window, stride, slot count, restart, the ingest's beats and
/// frame markers, `waitrequest`) takes any value in any cycle.
const DMA_PROPERTY: &str = r#"
    // The window in force: as programmed when the writer took up the frame.
    reg busy_prev = 1'b0;
    reg [31:0] base_prev = 32'd0, size_prev = 32'd0, base_r = 32'd0, size_r = 32'd0;
    wire opened = dma_status_busy & ~busy_prev;
    wire [31:0] win_base = opened ? base_prev : base_r;
    wire [31:0] win_size = opened ? size_prev : size_r;
    wire [33:0] win_lo = {2'b0, win_base};
    wire [33:0] win_hi = {2'b0, win_base} + {2'b0, win_size};
    // Avalon-MM burst tracking: which beat of which burst this write cycle carries.
    reg in_burst = 1'b0;
    reg [7:0] beat = 8'd0;
    reg [31:0] burst_addr = 32'd0;
    reg [7:0] burst_count = 8'd0;
    wire [7:0] beat_now = in_burst ? beat : 8'd0;
    wire [33:0] beat_addr = {2'b0, avm_address} + {23'd0, beat_now, 3'b000};
    wire [33:0] word_addr = {2'b0, avm_address[31:3], 3'b000} + {23'd0, beat_now, 3'b000};
    always @(posedge clock) begin
        busy_prev <= dma_status_busy;
        base_prev <= window_base;
        size_prev <= window_size;
        base_r <= win_base;
        size_r <= win_size;
        if (avm_write) begin
            burst_addr <= avm_address;
            burst_count <= avm_burstcount;
            in_burst <= 1'b1;
            beat <= beat_now;
            if (!avm_waitrequest) begin
                beat <= beat_now + 8'd1;
                if (beat_now + 8'd1 == avm_burstcount) begin
                    in_burst <= 1'b0;
                    beat <= 8'd0;
                end
            end
        end
    end
    always @* begin
        if (avm_write) begin
            assert (avm_burstcount != 8'd0);
            assert (!in_burst || (avm_address == burst_addr && avm_burstcount == burst_count));
            assert (win_lo <= beat_addr && beat_addr + 34'd8 <= win_hi);   // THE PROPERTY
            assert (win_lo <= word_addr && word_addr + 34'd8 <= win_hi);   // (as a word address)
        end
    end

    // Induction invariants on the writer's registers (proven with the property).
    wire [2:0] p_state;
    wire [31:0] p_addr;
    wire [31:0] p_slot_addr;
    wire [32:0] p_slot_end;
    wire p_slot_ok;
    wire [7:0] p_burst_len;
    wire [7:0] p_beats_left;
    wire [1:0] p_desc_beat;
    localparam IDLE = 3'd0, PLAN = 3'd1, BURST = 3'd2, DRAIN = 3'd3, DESC = 3'd4, CLOSE = 3'd5;
    wire [33:0] addr34 = {2'b0, p_addr};
    wire [33:0] slot34 = {2'b0, p_slot_addr};
    wire [33:0] end34 = {1'b0, p_slot_end};
    always @* begin
        assert (p_state <= CLOSE);
        assert (!(p_state == PLAN || p_state == BURST || p_state == DESC) || p_slot_ok);
        assert (p_state == IDLE || !p_slot_ok
                || (win_lo <= slot34 && end34 <= win_hi && slot34 + 34'd72 <= end34
                    && win_base[2:0] == 3'd0));
        assert (p_state != PLAN || (slot34 + 34'd64 <= addr34 && addr34 <= end34));
        assert (p_state != BURST
                || (p_burst_len != 8'd0 && p_beats_left != 8'd0 && p_beats_left <= p_burst_len
                    && slot34 + 34'd64 <= addr34
                    && addr34 + {23'd0, p_burst_len, 3'b000} <= end34));
        assert (p_state != DESC || (p_addr == p_slot_addr && p_burst_len == 8'd4));
        assert (!in_burst || p_state == BURST || p_state == DESC);
        assert (!in_burst || (burst_addr == p_addr && burst_count == p_burst_len));
        assert (p_state != BURST || beat_now == p_burst_len - p_beats_left);
        assert (p_state != DESC || beat_now == {6'd0, p_desc_beat});
        assert (avm_write == (p_state == BURST || p_state == DESC));
        assert (win_hi < 34'h100000000);
    end
"#;

const DMA_PROBES: &[Probe] = &[
    Probe {
        wire: "p_state",
        path: "state$q",
    },
    Probe {
        wire: "p_addr",
        path: "addr$q",
    },
    Probe {
        wire: "p_slot_addr",
        path: "slot_addr$q",
    },
    Probe {
        wire: "p_slot_end",
        path: "slot_end$q",
    },
    Probe {
        wire: "p_slot_ok",
        path: "slot_ok$q",
    },
    Probe {
        wire: "p_burst_len",
        path: "burst_len$q",
    },
    Probe {
        wire: "p_beats_left",
        path: "beats_left$q",
    },
    Probe {
        wire: "p_desc_beat",
        path: "desc_beat$q",
    },
];

/// The environment restriction of the DMA proof (a known bug, README "Formal proofs"): the
/// window ends below 4 GiB. The writer accepts a window ending exactly at 2^32; after a
/// burst that fills a slot ending there, its 32-bit address wraps to 0 and, with more
/// payload queued, the next burst is planned at address 0 (the room left is computed as
/// 2^32 - 0), outside the window. [`dma_window_full_range`] shows the counterexample.
const DMA_BELOW_4GIB: &str = r#"
    always @* assume ({1'b0, window_base} + {1'b0, window_size} < 33'h100000000);
"#;

/// The DMA window proof on `core` (the Verilog of the whole core).
pub fn dma_window_proof_of(core: &str) -> Proof {
    Proof {
        name: "dma_window",
        module: DMA_MODULE,
        design: extract_hierarchy(core, DMA_MODULE),
        property: dma_property_below_4gib(),
        probes: DMA_PROBES,
    }
}

fn dma_property_below_4gib() -> String {
    format!("{DMA_PROPERTY}{DMA_BELOW_4GIB}")
}

/// The DMA window property without the below-4-GiB restriction (bounded, property only):
/// fails, the known bug.
pub fn dma_window_full_range() -> Proof {
    let p = Proof {
        name: "dma_window_4gib",
        module: DMA_MODULE,
        design: extract_hierarchy(&core_verilog(), DMA_MODULE),
        property: DMA_PROPERTY.to_string(),
        probes: DMA_PROBES,
    };
    property_only(p, "")
}

/// The DMA window proof on the exported core.
pub fn dma_window_proof() -> Proof {
    dma_window_proof_of(&core_verilog())
}

/// The check that cuts a burst at the slot's end, as exported, and its broken form (removed:
/// every planned burst is issued whole).
pub const DMA_SLOT_END_CHECK: &str = "if (room_beats >= ((plan_len) & 33'h1ffffffff)) begin";
pub const DMA_SLOT_END_CHECK_BROKEN: &str = "if (1'b1) begin";

/// The DMA proof on a copy of the exported Verilog without the slot-end check.
pub fn dma_broken() -> Proof {
    let core = core_verilog();
    assert_eq!(
        core.matches(DMA_SLOT_END_CHECK).count(),
        1,
        "the slot-end check is not where the broken variant expects it"
    );
    let mut p = dma_window_proof_of(&core.replace(DMA_SLOT_END_CHECK, DMA_SLOT_END_CHECK_BROKEN));
    p.name = "dma_broken";
    property_only(p, DMA_BELOW_4GIB)
}

/// The arithmetic behind the shield proof's lemma M (`close_cost == position * period`, 48
/// bits, position 16 and period 24 bits wide): with the transition shape T proven in the
/// wrapper, M holds in every reachable state by induction over time from these identities
/// (16-bit position steps do not wrap, and the ring identities (P +- 1) Q = P Q +- Q hold
/// modulo 2^48). Each query must be `unsat`. The two facts the wrapper assumes follow from
/// M by integer arithmetic: P < 2^16 and Q < 2^24 give P Q < 2^40, so the 48-bit product
/// is exact, and P >= 1 then gives P Q >= Q.
pub const RING_IDENTITIES: &str = "\
(declare-const p (_ BitVec 16))
(declare-const P (_ BitVec 48))
(declare-const Q (_ BitVec 48))
(push)
(assert (bvult p #xffff))
(assert (not (= ((_ zero_extend 32) (bvadd p #x0001)) (bvadd ((_ zero_extend 32) p) #x000000000001))))
(check-sat)
(pop)
(push)
(assert (not (= p #x0000)))
(assert (not (= ((_ zero_extend 32) (bvsub p #x0001)) (bvsub ((_ zero_extend 32) p) #x000000000001))))
(check-sat)
(pop)
(push)
(assert (not (= (bvmul (bvadd P #x000000000001) Q) (bvadd (bvmul P Q) Q))))
(check-sat)
(pop)
(push)
(assert (not (= (bvmul (bvsub P #x000000000001) Q) (bvsub (bvmul P Q) Q))))
(check-sat)
(pop)
";

/// Checks [`RING_IDENTITIES`] with z3: true when all four are proven.
pub fn check_ring_identities() -> Result<bool, ToolError> {
    let dir = work_dir("formal-ring-identities")?;
    let file = dir.join("ring.smt2");
    std::fs::write(&file, RING_IDENTITIES).map_err(|e| ToolError::Io(file.clone(), e))?;
    let out = run(Tool::Z3, &dir, &["-smt2", "ring.smt2"])?;
    let answers: Vec<&str> = out.split_whitespace().collect();
    Ok(answers == ["unsat"; 4])
}
