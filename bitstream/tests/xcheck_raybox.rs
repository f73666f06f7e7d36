//! The ray-box unit's Verilog (exported from a fresh instance) against its rust-hdl
//! simulation: a recorded run of the unit with two lanes on the memory model with random
//! waitrequest (three batches: good items, a refused item, a window refusal), replayed in
//! Icarus; and one with a single lane, the configuration the core exports.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rust_hdl::prelude::*;
use skylux_bitstream::xcheck::{self, Tool};
use skylux_regmap::raybox;
use skylux_regmap::raybox_format::{result_word, WorkItem, ITEM_BYTES};
use skylux_rtl::raybox::RayBoxUnit;
use skylux_sim::bus::avalon_memory::AvalonMemoryConfig;
use skylux_sim::raybox::{pairs, RayBoxSystem};

const BASE: u64 = 0x1000;

/// Mostly realistic quantised pairs (hits and misses), some raw field values.
fn item(rng: &mut StdRng) -> [u64; 6] {
    if rng.gen_bool(0.8) {
        return pairs::random_item(rng).pack();
    }
    let mut r = |lo: i32, hi: i32| rng.gen_range(lo..=hi);
    WorkItem {
        origin: [r(-20, 20), r(-20, 20), r(-1 << 20, (1 << 20) - 1)],
        entry_plane: [r(-30, 0), r(-30, 0), r(-30, 0)],
        exit_plane: [r(0, 30), r(0, 30), r(0, 30)],
        mant: [r(1 << 22, 1 << 24), r(-(1 << 24), -(1 << 22)), r(-9, 9)],
        shift: [23, 22, r(0, 63) as u8],
        t_min: r(-5, 5),
        t_max: r(-5, i32::MAX),
    }
    .pack()
}

fn batch<const L: usize>(
    s: &mut RayBoxSystem<L>,
    items: &[[u64; 6]],
    window: u32,
) -> (u32, Vec<u64>) {
    let bytes: Vec<u8> = items
        .iter()
        .flatten()
        .flat_map(|w| w.to_le_bytes())
        .collect();
    s.memory
        .slice_mut(BASE, bytes.len())
        .unwrap()
        .copy_from_slice(&bytes);
    let result = BASE + items.len() as u64 * ITEM_BYTES as u64;
    for (r, v) in [
        (raybox::status::REG, u32::MAX),
        (raybox::window_base::REG, BASE as u32),
        (raybox::window_size::REG, window),
        (raybox::work_base::REG, BASE as u32),
        (raybox::work_count::REG, items.len() as u32),
        (raybox::result_base::REG, result as u32),
        (raybox::bus_timeout::REG, 5000),
        (raybox::ctrl::REG, raybox::ctrl::START.mask()),
    ] {
        s.write_register(r.offset, v).unwrap();
    }
    let status = loop {
        let st = s.read_register(raybox::status::REG.offset).unwrap();
        if raybox::status::DONE.get(st) == 1 {
            break st;
        }
    };
    let words = s
        .memory
        .slice(result, 8 * items.len())
        .unwrap()
        .chunks_exact(8)
        .map(|c| u64::from_le_bytes(c.try_into().unwrap()))
        .collect();
    (status, words)
}

fn check<const L: usize>(seed: u64) {
    let mut rng = StdRng::seed_from_u64(seed);
    let mut s = RayBoxSystem::<L>::new(AvalonMemoryConfig {
        base: BASE,
        size_bytes: 4096,
        wait: skylux_sim::bus::WaitPolicy::random(0.3),
        read_gap_probability: 0.2,
        seed,
        ..Default::default()
    });
    s.driver.record();
    let items: Vec<[u64; 6]> = (0..16).map(|_| item(&mut rng)).collect();
    let (st, got) = batch(&mut s, &items, 4096);
    assert_eq!(st, raybox::status::DONE.mask());
    let want: Vec<u64> = (0..16)
        .map(|i| result_word(i as u32, &items[i]).unwrap())
        .collect();
    assert_eq!(got, want, "rust-hdl simulation vs golden model");
    assert!(got.iter().any(|w| w >> 63 == 1) && got.iter().any(|w| w >> 63 == 0));
    let mut bad = items[..4].to_vec();
    bad[2][5] ^= 1 << 57;
    let (st, _) = batch(&mut s, &bad, 4096);
    assert_eq!(raybox::status::BAD_DESCRIPTOR.get(st), 1);
    let (st, _) = batch(&mut s, &items[..3], 64);
    assert_eq!(raybox::status::OUT_OF_WINDOW.get(st), 1);

    let trace = s.driver.take_trace();
    let mut fresh = RayBoxUnit::<L>::default();
    fresh.connect_all();
    let verilog = generate_verilog(&fresh);
    let name = format!("raybox_unit_{L}");
    let report = xcheck::replay(&name, &verilog, &trace).unwrap();
    println!("{}", report.summary());
    assert!(
        report.steps > 1000,
        "trace too short: {} steps",
        report.steps
    );
    assert!(report.is_clean(), "{}", report.summary());

    // A sign slip in one plane difference must be caught on the written data.
    let tampered = verilog.replacen(
        "diff = $signed(plane) - $signed(origin)",
        "diff = $signed(origin) - $signed(plane)",
        1,
    );
    assert_ne!(
        tampered, verilog,
        "the difference is not where the test expects it"
    );
    let report = xcheck::replay(&format!("{name}_tampered"), &tampered, &trace).unwrap();
    assert!(!report.is_clean(), "tampering not caught");
}

#[test]
fn raybox_unit_verilog_equals_rust_hdl() {
    if !xcheck::require(&[Tool::Iverilog, Tool::Vvp]) {
        return;
    }
    check::<2>(31);
    check::<1>(32);
}
