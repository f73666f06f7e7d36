//! `skylux bench raybox`: the ray-box unit's throughput in cycle-accurate simulation (memory
//! stalls included), its Cyclone V resources from yosys, the projected tests/s at the system
//! clock, next to the software slab test measured on this machine, and the false-miss count
//! of the conservative quantisation over random pairs.

use anyhow::{bail, Context};
use rand::rngs::StdRng;
use rand::SeedableRng;
use rust_hdl::prelude::*;
use skylux_bitstream::blocks::BLOCKS;
use skylux_bitstream::xcheck::{self, Resources, Tool};
use skylux_hps::engine::slab::SlabTest;
use skylux_regmap::raybox;
use skylux_regmap::raybox_format::ITEM_BYTES;
use skylux_rtl::raybox::{RayBoxUnit, SlabLane, DEFAULT_LANES};
use skylux_sim::bus::avalon_memory::AvalonMemoryConfig;
use skylux_sim::raybox::{pairs, RayBoxSystem};
use std::time::Instant;

/// Capacity of the 5CSEMA5 (hardware-facts.md §2: 32,070 ALMs, 397 M10K, 87 DSP blocks).
const DEVICE_ALMS: u64 = 32_070;
const DEVICE_M10K: u64 = 397;
const DEVICE_DSP: u64 = 87;
/// The clock the unit runs on (`sys.clock_hz`); not yet confirmed by Quartus timing analysis.
const FMAX_MHZ: f64 = skylux_regmap::SYS_CLOCK_HZ as f64 / 1e6;
/// Cortex-A9 clock of the DE1-SoC's HPS (hardware-facts.md §2: 925 MHz).
const A9_MHZ: f64 = 925.0;
/// Estimated Cortex-A9 cycles per f64 slab test: per axis 2 subtractions, 2 multiplies, a
/// compare-swap and 2 compare-selects (about 10 VFP operations and 2 loads), 3 axes, plus
/// the loop and early-out branch; VFPv3 issues one double operation per cycle with a 4 to 5
/// cycle multiply latency, partly hidden across axes (ARM Cortex-A9 TRM, "VFP instruction
/// timing"). Not measured on the board.
const A9_CYCLES_PER_TEST: f64 = 60.0;

#[derive(clap::Args)]
pub struct RayboxBenchArgs {
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
    /// Work items in the simulated batch.
    #[arg(long, default_value_t = 2000)]
    items: usize,
    /// Random pairs for the false-miss count.
    #[arg(long, default_value_t = 10_000_000)]
    pairs: u64,
    /// Probability of waitrequest in a cycle of the simulated SDRAM port.
    #[arg(long, default_value_t = 0.1)]
    stall: f64,
    /// Skip the yosys synthesis (resources reported as null).
    #[arg(long)]
    no_synthesis: bool,
    /// Paths per sensor of the illuminance runs whose traversals size the BVH unit's design
    /// (`bvh_unit_design`; 0 leaves it out).
    #[arg(long, default_value_t = 256)]
    traversal_paths: u32,
    /// Only the BVH unit: its design and the built unit's projection (no ray-box simulation,
    /// synthesis or pairs).
    #[arg(long)]
    traversal_only: bool,
}

/// Cycles from START to DONE for a batch of `n` realistic items.
fn simulate(n: usize, stall: f64) -> anyhow::Result<(u64, u64)> {
    let base = 0x2000_0000u64;
    let size = n * (ITEM_BYTES as usize + 8);
    let mut s = RayBoxSystem::<DEFAULT_LANES>::new(AvalonMemoryConfig {
        base,
        size_bytes: size,
        wait: skylux_sim::bus::WaitPolicy::random(stall),
        read_gap_probability: stall / 2.0,
        read_latency_cycles: 12,
        seed: 3,
        ..Default::default()
    });
    let mut rng = StdRng::seed_from_u64(4);
    let bytes: Vec<u8> = (0..n)
        .flat_map(|_| pairs::random_item(&mut rng).pack())
        .flat_map(|w| w.to_le_bytes())
        .collect();
    s.memory
        .slice_mut(base, bytes.len())
        .context("memory model")?
        .copy_from_slice(&bytes);
    let sim = |e: skylux_rtl::drive::DriveError| anyhow::anyhow!("simulation: {e}");
    for (r, v) in [
        (raybox::window_base::REG, base as u32),
        (raybox::window_size::REG, size as u32),
        (raybox::work_base::REG, base as u32),
        (raybox::work_count::REG, n as u32),
        (
            raybox::result_base::REG,
            (base + n as u64 * ITEM_BYTES as u64) as u32,
        ),
    ] {
        s.write_register(r.offset, v).map_err(sim)?;
    }
    s.write_register(raybox::ctrl::REG.offset, raybox::ctrl::START.mask())
        .map_err(sim)?;
    let start = s.cycles();
    loop {
        s.cycle().map_err(sim)?;
        if !s.driver.dut.status_busy.val() && s.cycles() > start + 2 {
            break;
        }
    }
    let cycles = s.cycles() - start;
    let done = s
        .read_register(raybox::tests_done::REG.offset)
        .map_err(sim)? as u64;
    let status = s.read_register(raybox::status::REG.offset).map_err(sim)?;
    if done != n as u64 || status != raybox::status::DONE.mask() {
        bail!("the simulated batch ended with status {status:#x} after {done} of {n} tests");
    }
    Ok((done, cycles))
}

fn synth<B: Block>(name: &str, mut b: B) -> anyhow::Result<Resources> {
    b.connect_all();
    let v = generate_verilog(&b);
    xcheck::synthesize(name, &v).map_err(|e| anyhow::anyhow!("{name}: {e}"))
}

struct Fit {
    per_lane: Resources,
    front_end: Resources,
    others_alms: u64,
    others_dsp: u64,
    others_m10k: u64,
    largest_lanes: u64,
}

fn fit() -> anyhow::Result<Fit> {
    let lane = synth("raybox_lane", SlabLane::default())?;
    let unit = synth("raybox_unit_1", RayBoxUnit::<1>::default())?;
    let sub = |a: u64, b: u64| a.saturating_sub(b);
    let front_end = Resources {
        luts: sub(unit.luts, lane.luts),
        carry_aluts: sub(unit.carry_aluts, lane.carry_aluts),
        flip_flops: sub(unit.flip_flops, lane.flip_flops),
        m10k: sub(unit.m10k, lane.m10k),
        dsp: sub(unit.dsp, lane.dsp),
        mlab: sub(unit.mlab, lane.mlab),
    };
    // Everything else in the core, the capture path included.
    let (mut alms, mut dsp, mut m10k) = (0, 0, 0);
    // The BVH traversal block is not in the core yet (reported apart, `bvh_unit`).
    for block in BLOCKS
        .iter()
        .filter(|b| !b.name.starts_with("raybox") && b.name != "bvh_traversal")
    {
        let r = xcheck::synthesize(block.name, &(block.verilog)())
            .map_err(|e| anyhow::anyhow!("{}: {e}", block.name))?;
        alms += r.alm_estimate();
        dsp += r.dsp;
        m10k += r.m10k;
    }
    let free_alms = sub(DEVICE_ALMS, alms + front_end.alm_estimate());
    let by_alm = free_alms / lane.alm_estimate().max(1);
    let by_dsp = sub(DEVICE_DSP, dsp + front_end.dsp) / lane.dsp.max(1);
    let by_m10k = sub(DEVICE_M10K, m10k + front_end.m10k)
        .checked_div(lane.m10k)
        .unwrap_or(u64::MAX);
    Ok(Fit {
        largest_lanes: by_alm.min(by_dsp).min(by_m10k).min(16),
        per_lane: lane,
        front_end,
        others_alms: alms,
        others_dsp: dsp,
        others_m10k: m10k,
    })
}

/// Software slab tests per second on this machine, one thread.
fn software_rate() -> f64 {
    let mut rng = StdRng::seed_from_u64(8);
    let pairs: Vec<_> = (0..100_000).map(|_| pairs::random_pair(&mut rng)).collect();
    let mut best = f64::INFINITY;
    let mut hits = 0usize;
    for _ in 0..5 {
        let t = Instant::now();
        for _ in 0..10 {
            for (q, b) in &pairs {
                hits += std::hint::black_box(SlabTest::entry(q, b)).is_some() as usize;
            }
        }
        best = best.min(t.elapsed().as_secs_f64());
    }
    std::hint::black_box(hits);
    (pairs.len() * 10) as f64 / best
}

pub fn run(args: &RayboxBenchArgs) -> anyhow::Result<()> {
    let (design, unit) = match args.traversal_paths {
        0 => (serde_json::Value::Null, serde_json::Value::Null),
        n => (
            crate::bench_raybox_traversal::run(n)?,
            crate::bench_raybox_unit::run(n)?,
        ),
    };
    if args.traversal_only {
        let both = serde_json::json!({ "bvh_unit_design": design, "bvh_unit": unit });
        println!("{}", serde_json::to_string_pretty(&both)?);
        return Ok(());
    }
    let (tests, cycles) = simulate(args.items.max(1), args.stall.clamp(0.0, 0.99))?;
    let tests_per_cycle = tests as f64 / cycles as f64;
    let fit = if args.no_synthesis || !xcheck::require(&[Tool::Yosys]) {
        None
    } else {
        Some(fit()?)
    };
    let software = software_rate();
    let report = pairs::check(args.pairs, 12);
    let a9 = A9_MHZ * 1e6 / A9_CYCLES_PER_TEST;
    let projected = tests_per_cycle * FMAX_MHZ * 1e6;
    let opt = |f: &dyn Fn(&Fit) -> u64| fit.as_ref().map(f);
    let json = serde_json::json!({
        "lanes": DEFAULT_LANES,
        "items": tests,
        "cycles": cycles,
        "tests_per_cycle": tests_per_cycle,
        "port_bound_tests_per_cycle": 1.0 / (skylux_regmap::raybox_format::ITEM_WORDS as f64 + 1.0),
        "waitrequest_probability": args.stall,
        "alms": opt(&|f| f.per_lane.alm_estimate()),
        "dsps": opt(&|f| f.per_lane.dsp),
        "m10k": opt(&|f| f.per_lane.m10k),
        "front_end_alms": opt(&|f| f.front_end.alm_estimate()),
        "front_end_m10k": opt(&|f| f.front_end.m10k),
        "rest_of_core_alms": opt(&|f| f.others_alms),
        "rest_of_core_dsps": opt(&|f| f.others_dsp),
        "rest_of_core_m10k": opt(&|f| f.others_m10k),
        "largest_lanes_that_fit": opt(&|f| f.largest_lanes),
        "largest_alms": opt(&|f| f.front_end.alm_estimate() + f.largest_lanes * f.per_lane.alm_estimate()),
        "largest_dsps": opt(&|f| f.front_end.dsp + f.largest_lanes * f.per_lane.dsp),
        "fmax_mhz": FMAX_MHZ,
        "fmax_basis": "system clock target (sys.clock_hz); no Quartus timing analysis yet",
        "projected_tests_per_s": projected,
        "software_tests_per_s": software,
        "a9_estimated_tests_per_s": a9,
        "a9_estimate_basis": format!("{A9_CYCLES_PER_TEST} cycles per f64 slab test at {A9_MHZ} MHz, counted from the operation mix, not measured"),
        "pairs": report.pairs,
        "reference_hits": report.reference_hits,
        "false_misses": report.false_misses,
        "late_entries": report.late_entries,
        "false_hits": report.false_hits,
        "fallbacks": report.fallbacks,
        "bvh_unit_design": design,
        "bvh_unit": unit,
    });
    if args.json {
        println!("{}", serde_json::to_string_pretty(&json)?);
    } else {
        for (k, v) in json.as_object().into_iter().flatten() {
            println!("{k:>28}  {v}");
        }
    }
    if report.false_misses != 0 || report.late_entries != 0 {
        bail!("the quantisation is not conservative: {report:?}");
    }
    Ok(())
}
