//! `skylux-bitstream`: Verilog export and the open-source checks.
//!
//! - `verilog [--out DIR]`: writes every block as `DIR/<block>.v` (default `target/verilog`),
//!   and the whole core as `bitstream/quartus/core/skylux_core.v`, the copy Quartus compiles.
//! - `check`: lints, structurally checks and synthesises every block for the Cyclone V and
//!   prints the resource table (Markdown) that BENCHMARKS.md carries.
//! - `formal [PROOF [bmc|ind DEPTH]]`: the formal proofs on the exported core (yosys-smtbmc
//!   with z3): each property by a bounded check and k-induction, and each broken variant
//!   must fail (see the README's "Formal proofs"). With a proof name (`shield`, `dma_window`,
//!   `shield_broken`, `dma_broken`), only that one, optionally one check at one depth.

use skylux_bitstream::blocks::{core_verilog, BLOCKS, CORE_VERILOG_PATH};
use skylux_bitstream::formal;
use skylux_bitstream::xcheck;
use std::path::PathBuf;

use skylux_bitstream::xcheck::DEVICE_ALMS;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = match args.first().map(String::as_str) {
        Some("verilog") => export(
            args.iter()
                .position(|a| a == "--out")
                .and_then(|i| args.get(i + 1))
                .map(PathBuf::from),
        ),
        Some("check") => check(args.get(1).map(String::as_str)),
        Some("formal") => run_formal(&args[1..]),
        _ => Err(
            "usage: skylux-bitstream verilog [--out DIR] | check [BLOCK] | formal [PROOF [bmc|ind DEPTH]]"
                .to_string(),
        ),
    };
    if let Err(e) = result {
        eprintln!("skylux-bitstream: {e}");
        std::process::exit(1);
    }
}

fn export(out: Option<PathBuf>) -> Result<(), String> {
    let dir = out.unwrap_or_else(|| PathBuf::from("target/verilog"));
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    for block in BLOCKS {
        let path = dir.join(format!("{}.v", block.name));
        std::fs::write(&path, (block.verilog)()).map_err(|e| format!("{}: {e}", path.display()))?;
        println!("wrote {}", path.display());
    }
    let core = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(CORE_VERILOG_PATH);
    std::fs::write(&core, core_verilog()).map_err(|e| format!("{}: {e}", core.display()))?;
    println!("wrote {}", core.display());
    Ok(())
}

/// Lint, structure, synthesis and fit of every block, or of the one named.
fn check(only: Option<&str>) -> Result<(), String> {
    if only.is_some_and(|n| BLOCKS.iter().all(|b| b.name != n)) {
        return Err(format!("no block named {:?}", only.unwrap_or_default()));
    }
    println!("| block | LUTs | carry ALUTs | FFs | ALMs (est.) | M10K | DSP | % of 5CSEMA5 ALMs |");
    println!("|---|---|---|---|---|---|---|---|");
    for block in BLOCKS.iter().filter(|b| only.is_none_or(|n| n == b.name)) {
        let v = (block.verilog)();
        let fail = |e: xcheck::ToolError| format!("{}: {e}", block.name);
        xcheck::lint(block.name, &v).map_err(fail)?;
        xcheck::structural_check(block.name, &v).map_err(fail)?;
        let r = xcheck::synthesize(block.name, &v).map_err(fail)?;
        let alms = r.alm_estimate();
        r.check_fit(block.name)?;
        println!(
            "| {} | {} | {} | {} | {} | {} | {} | {:.1} % |",
            block.name,
            r.luts,
            r.carry_aluts,
            r.flip_flops,
            alms,
            r.m10k,
            r.dsp,
            100.0 * alms as f64 / DEVICE_ALMS as f64
        );
    }
    Ok(())
}

fn run_formal(args: &[String]) -> Result<(), String> {
    let proofs: Vec<(formal::Proof, bool)> = vec![
        (formal::shield_proof(), true),
        (formal::dma_window_proof(), true),
        (formal::shield_broken(), false),
        (formal::dma_broken(), false),
        (formal::dma_window_full_range(), false),
    ];
    let selected: Vec<_> = proofs
        .into_iter()
        .filter(|(p, _)| args.first().is_none_or(|n| n == p.name))
        .collect();
    if selected.is_empty() {
        return Err(format!("no proof named {:?}", args[0]));
    }
    let one = match (args.get(1).map(String::as_str), args.get(2)) {
        (Some(kind), Some(depth)) => {
            let depth: u32 = depth.parse().map_err(|_| format!("bad depth {depth}"))?;
            match kind {
                "bmc" => Some(formal::Check::Bmc { depth }),
                "ind" => Some(formal::Check::Induction { depth }),
                _ => return Err(format!("unknown check {kind}")),
            }
        }
        _ => None,
    };
    let mut wrong = Vec::new();
    for (proof, must_hold) in selected {
        let t = std::time::Instant::now();
        let (what, verdict) = match one {
            Some(c) => (format!("{c:?}"), formal::check(&proof, c)),
            None if must_hold => (
                format!("BMC + {}-induction", formal::PROOF_DEPTH),
                formal::prove(&proof, formal::PROOF_DEPTH),
            ),
            None => (
                format!("BMC {}", formal::BROKEN_DEPTH),
                formal::check(
                    &proof,
                    formal::Check::Bmc {
                        depth: formal::BROKEN_DEPTH,
                    },
                ),
            ),
        };
        let verdict = verdict.map_err(|e| format!("{}: {e}", proof.name))?;
        println!(
            "{}: {what}: {verdict:?} ({:.1} s)",
            proof.name,
            t.elapsed().as_secs_f64()
        );
        if one.is_none() && verdict.passed() != must_hold {
            wrong.push(proof.name);
        }
    }
    if wrong.is_empty() {
        Ok(())
    } else {
        Err(format!("unexpected verdicts: {wrong:?}"))
    }
}
