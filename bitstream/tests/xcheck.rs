//! The cross-check harness on the real design and on known-bad designs: every exported block
//! lints, synthesises without latches or loops and simulates in Icarus exactly as in rust-hdl;
//! and a design that rust-hdl exports wrongly is caught.

use rand::{Rng, SeedableRng};
use rust_hdl::prelude::*;
use skylux_bitstream::blocks::BLOCKS;
use skylux_bitstream::xcheck::{self, Tool};
use skylux_rtl::drive::Driver;
use skylux_rtl::RegisterFile;
use skylux_sim::AvalonHost;

const ALL: &[Tool] = &[Tool::Iverilog, Tool::Vvp, Tool::Yosys, Tool::Verilator];

fn fresh_verilog<B: Block + Default>() -> String {
    let mut b = B::default();
    b.connect_all();
    generate_verilog(&b)
}

#[test]
fn every_block_lints_and_has_no_latches_or_loops() {
    if !xcheck::require(ALL) {
        return;
    }
    // Two blocks at a time, the largest first: the tools are single-threaded and the core's
    // synthesis alone takes minutes.
    let mut work: Vec<_> = BLOCKS.iter().map(|b| (b, (b.verilog)())).collect();
    work.sort_by_key(|(_, v)| std::cmp::Reverse(v.len()));
    let next = std::sync::atomic::AtomicUsize::new(0);
    std::thread::scope(|scope| {
        for _ in 0..2 {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some((block, v)) = work.get(i) else { break };
                check_block(block, v);
            });
        }
    });
}

/// Lint, structure, synthesis and the device and core's budget of one exported block.
fn check_block(block: &skylux_bitstream::blocks::ExportedBlock, v: &str) {
    xcheck::lint(block.name, v).unwrap_or_else(|e| panic!("{}: {e}", block.name));
    xcheck::structural_check(block.name, v).unwrap_or_else(|e| panic!("{}: {e}", block.name));
    let r = xcheck::synthesize(block.name, v).unwrap_or_else(|e| panic!("{}: {e}", block.name));
    println!("{}: {r:?}, ~{} ALMs", block.name, r.alm_estimate());
    assert!(
        r.flip_flops > 0,
        "{}: synthesis produced no registers",
        block.name
    );
    // What `skylux-bitstream check` also asserts: the device and the core's budget.
    r.check_fit(block.name)
        .unwrap_or_else(|e| panic!("{}: {e}", block.name));
}

/// Random register transfers (and fabric-side pulses) recorded from the rust-hdl simulation,
/// replayed in Icarus on the exported Verilog.
#[test]
fn register_file_verilog_equals_rust_hdl() {
    if !xcheck::require(ALL) {
        return;
    }
    let mut driver = Driver::new(RegisterFile::default());
    driver.record();
    let mut host = AvalonHost::with_driver(driver);
    let mut rng = rand::rngs::StdRng::seed_from_u64(7);
    let offsets: Vec<u32> = skylux_regmap::reset_image()
        .into_iter()
        .map(|(o, _)| o)
        .chain([0x0FF0, 0x9000, 0x1F_FFFC])
        .collect();
    for _ in 0..500 {
        let offset = offsets[rng.gen_range(0..offsets.len())];
        host.driver.dut.dma_status_overflow_set.next = rng.gen_bool(0.1);
        host.driver.dut.sys_time_lo_cycles.next = (rng.gen::<u32>() as u64).into();
        if rng.gen_bool(0.5) {
            host.write(offset / 4, rng.gen(), rng.gen_range(0..16))
                .unwrap();
        } else {
            host.read(offset / 4).unwrap();
        }
    }
    let trace = host.driver.take_trace();
    let verilog = fresh_verilog::<RegisterFile>();
    let report = xcheck::replay("register_file", &verilog, &trace).unwrap();
    assert!(
        report.steps > 2000,
        "trace too short: {} steps",
        report.steps
    );
    assert!(report.is_clean(), "{}", report.summary());

    // The same trace against a subtly wrong Verilog (the unmapped read value off by one bit)
    // must be caught: the comparison is not vacuous.
    let tampered = verilog.replace("'hdeadbeef", "'hdeadbeee");
    assert!(
        tampered != verilog,
        "the constant is not where the test expects it"
    );
    let report = xcheck::replay("register_file_tampered", &tampered, &trace).unwrap();
    assert!(
        report.mismatches.iter().any(|m| m.port == "avs_readdata"),
        "tampering not caught"
    );
}

/// Rust binds `&` tighter than `==`, Verilog the other way round, and rust-hdl prints nested
/// operators without parentheses (rust-hdl-notes §6 item 1); `a + b` widened after the add
/// keeps the carry in Verilog only (item 2).
#[derive(LogicBlock, Default)]
struct KnownBad {
    a: Signal<In, Bits<8>>,
    b: Signal<In, Bits<8>>,
    c: Signal<In, Bits<8>>,
    unparenthesised: Signal<Out, Bit>,
    parenthesised: Signal<Out, Bit>,
    widened_sum: Signal<Out, Bits<9>>,
}

impl Logic for KnownBad {
    #[hdl_gen]
    fn update(&mut self) {
        self.unparenthesised.next = self.a.val() & self.b.val() == self.c.val();
        self.parenthesised.next = (self.a.val() & self.b.val()) == self.c.val();
        self.widened_sum.next = bit_cast::<9, 8>(self.a.val() + self.b.val());
    }
}

#[test]
fn harness_catches_known_bad_verilog() {
    if !xcheck::require(&[Tool::Iverilog, Tool::Vvp]) {
        return;
    }
    let mut driver = Driver::new(KnownBad::default());
    driver.record();
    let mut rng = rand::rngs::StdRng::seed_from_u64(11);
    for _ in 0..300 {
        driver.dut.a.next = rng.gen_range(0..256u64).into();
        driver.dut.b.next = rng.gen_range(0..256u64).into();
        driver.dut.c.next = rng.gen_range(0..256u64).into();
        driver.settle().unwrap();
    }
    // Cases where the two precedences differ for sure.
    for (a, b, c) in [(0xF0u64, 0x0F, 0x00), (0x03, 0x01, 0x01)] {
        driver.dut.a.next = a.into();
        driver.dut.b.next = b.into();
        driver.dut.c.next = c.into();
        driver.settle().unwrap();
    }
    let trace = driver.take_trace();
    let report = xcheck::replay("known_bad", &fresh_verilog::<KnownBad>(), &trace).unwrap();
    let count = |port: &str| report.mismatches.iter().filter(|m| m.port == port).count();
    assert!(
        count("unparenthesised") > 0,
        "precedence bug not caught: {}",
        report.summary()
    );
    assert!(
        count("widened_sum") > 0,
        "literal-width bug not caught: {}",
        report.summary()
    );
    assert_eq!(
        count("parenthesised"),
        0,
        "false alarm: {}",
        report.summary()
    );
}
