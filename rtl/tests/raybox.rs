//! The slab lane against the golden model (`skylux_regmap::raybox_format::test`): random work
//! items, the field extremes and near-ties included, fed back to back and with gaps; and its
//! latency. The whole unit with its memory port is tested in `skylux-sim` (`sim/src/raybox.rs`)
//! and `tests/tests/raybox_offload.rs`.

use proptest::prelude::*;
use proptest::strategy::ValueTree;
use rust_hdl::prelude::*;
use skylux_regmap::raybox_format::{
    test as golden, TestResult, WorkItem, COORD_MAX, COORD_MIN, MANT_MAX, MANT_MIN, SHIFT_MAX,
};
use skylux_rtl::drive::Driver;
use skylux_rtl::raybox::{RayBoxUnit, SlabLane, LANE_LATENCY};

fn clock(d: &mut SlabLane) -> &mut Signal<In, Clock> {
    &mut d.clock
}

fn bits<const N: usize>(v: i64) -> Bits<N> {
    ((v as u64) & ((1u64 << N) - 1)).to_bits()
}

fn present(d: &mut SlabLane, item: Option<(u32, &WorkItem)>) {
    d.in_valid.next = item.is_some();
    let (index, it) = match item {
        Some((i, it)) => (i, *it),
        // Idle cycles carry garbage that must be ignored.
        None => (
            0xABCDE,
            WorkItem {
                origin: [1, 2, 3],
                mant: [7, -7, 7],
                t_max: -1,
                ..Default::default()
            },
        ),
    };
    d.in_index.next = bits::<24>(index as i64);
    let pack = |v: [i32; 3], w: u32| -> u128 {
        (0..3).fold(0u128, |acc, a| {
            acc | (((v[a] as u128) & ((1 << w) - 1)) << (w * a as u32))
        })
    };
    d.origin.next = pack(it.origin, 21).to_bits();
    d.entry_plane.next = pack(it.entry_plane, 21).to_bits();
    d.exit_plane.next = pack(it.exit_plane, 21).to_bits();
    d.mant.next = pack(it.mant, 25).to_bits();
    d.shift.next = pack(it.shift.map(i32::from), 6).to_bits();
    d.t_min.next = bits::<32>(it.t_min as i64);
    d.t_max.next = bits::<32>(it.t_max as i64);
}

/// Runs items through a lane, `gaps[k]` idle cycles before item `k`; returns (cycle, index,
/// result) of every output.
fn run(items: &[WorkItem], gaps: &[usize]) -> Vec<(u64, u32, TestResult)> {
    let mut driver = Driver::new(SlabLane::default());
    let mut out = vec![];
    let mut cycle = 0u64;
    let mut step = |driver: &mut Driver<SlabLane>, item: Option<(u32, &WorkItem)>| {
        present(&mut driver.dut, item);
        driver.cycle(clock).unwrap();
        cycle += 1;
        let d = &driver.dut;
        if d.out_valid.val() {
            out.push((
                cycle,
                d.out_index.val().to_u64() as u32,
                TestResult {
                    hit: d.out_hit.val(),
                    t_near: d.out_t_near.val().to_u64() as u32 as i32,
                },
            ));
        }
    };
    for (k, item) in items.iter().enumerate() {
        for _ in 0..gaps.get(k).copied().unwrap_or(0) {
            step(&mut driver, None);
        }
        step(&mut driver, Some((k as u32, item)));
    }
    for _ in 0..LANE_LATENCY + 2 {
        step(&mut driver, None);
    }
    out
}

fn coord() -> impl Strategy<Value = i32> {
    prop_oneof![
        Just(COORD_MIN),
        Just(COORD_MAX),
        Just(0),
        -8i32..8,
        COORD_MIN..=COORD_MAX,
        COORD_MIN..=COORD_MAX,
    ]
}

fn item_strategy() -> impl Strategy<Value = WorkItem> {
    let mant = prop_oneof![
        Just(MANT_MIN),
        Just(MANT_MAX),
        Just(1 << 23),
        Just(-(1 << 23)),
        -3i32..3,
        MANT_MIN..=MANT_MAX,
    ];
    let shift = prop_oneof![Just(0u8), Just(SHIFT_MAX), Just(23u8), 0u8..=SHIFT_MAX];
    let t = prop_oneof![
        Just(i32::MIN),
        Just(i32::MAX),
        Just(0),
        -100i32..100,
        any::<i32>()
    ];
    (
        prop::array::uniform3(coord()),
        prop::array::uniform3(coord()),
        prop::array::uniform3(coord()),
        prop::array::uniform3(mant),
        prop::array::uniform3(shift),
        t.clone(),
        t,
    )
        .prop_map(
            |(origin, entry_plane, exit_plane, mant, shift, t_min, t_max)| WorkItem {
                origin,
                entry_plane,
                exit_plane,
                mant,
                shift,
                t_min,
                t_max,
            },
        )
}

/// Items near a decision boundary: a box around the origin's neighbourhood with unit-ish
/// inverse directions, so hits, misses and ties all occur.
fn near_tie_strategy() -> impl Strategy<Value = WorkItem> {
    (
        prop::array::uniform3(-4i32..4),
        prop::array::uniform3(-6i32..6),
        prop::array::uniform3(0i32..6),
        prop::array::uniform3(prop_oneof![Just(1i32 << 23), (1i32 << 22)..(1 << 24)]),
        -3i32..3,
        -3i32..12,
    )
        .prop_map(|(origin, lo, size, mant, t_min, t_max)| WorkItem {
            origin,
            entry_plane: lo,
            exit_plane: [lo[0] + size[0], lo[1] + size[1], lo[2] + size[2]],
            mant,
            shift: [23, 23, 23],
            t_min,
            t_max,
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// Every result equals the golden model's, in order, exactly LANE_LATENCY edges after
    /// its item.
    #[test]
    fn lane_equals_golden_model(
        items in prop::collection::vec(prop_oneof![item_strategy(), near_tie_strategy()], 1..40),
        gaps in prop::collection::vec(prop_oneof![Just(0usize), Just(0usize), 1usize..4], 40),
    ) {
        let out = run(&items, &gaps);
        prop_assert_eq!(out.len(), items.len());
        let mut taken_at = 0u64;
        for (k, (item, (cycle, index, result))) in items.iter().zip(&out).enumerate() {
            taken_at += gaps[k] as u64 + 1;
            prop_assert_eq!(*index, k as u32);
            prop_assert_eq!(*result, golden(item), "item {}: {:?}", k, item);
            prop_assert_eq!(*cycle, taken_at + LANE_LATENCY as u64 - 1);
        }
    }
}

#[test]
fn hits_misses_and_ties_all_occur_in_the_near_tie_items() {
    // The near-tie generator must exercise both answers and exact ties (t_near == t_far),
    // or the proptest above would prove little about the decision.
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let (mut hits, mut misses, mut ties) = (0, 0, 0);
    for _ in 0..2000 {
        let item = near_tie_strategy().new_tree(&mut runner).unwrap().current();
        let r = golden(&item);
        if r.hit {
            hits += 1;
        } else {
            misses += 1;
        }
        let mut far = item.t_max;
        for a in 0..3 {
            let p = skylux_regmap::raybox_format::plane_product(
                item.exit_plane[a],
                item.origin[a],
                item.mant[a],
            );
            far = far.min(skylux_regmap::raybox_format::exit_distance(
                p,
                item.shift[a],
            ));
        }
        if r.t_near == far {
            ties += 1;
        }
    }
    assert!(
        hits > 100 && misses > 100 && ties > 20,
        "{hits} {misses} {ties}"
    );
}

#[test]
fn back_to_back_items_one_per_clock() {
    let items: Vec<WorkItem> = (0..20)
        .map(|k| WorkItem {
            origin: [0, 0, 0],
            entry_plane: [k, -1, -1],
            exit_plane: [k + 4, 1, 1],
            mant: [1 << 23, MANT_MAX, MANT_MAX],
            shift: [23, 0, 0],
            t_min: 0,
            t_max: 10,
        })
        .collect();
    let out = run(&items, &[]);
    let want: Vec<(u64, u32, TestResult)> = (0..20)
        .map(|k| {
            (
                k as u64 + LANE_LATENCY as u64,
                k as u32,
                TestResult {
                    hit: k <= 10,
                    t_near: k,
                },
            )
        })
        .collect();
    assert_eq!(out, want);
}

#[test]
fn unit_exports_verilog_for_one_and_several_lanes() {
    for verilog in [
        {
            let mut u = RayBoxUnit::<1>::default();
            u.connect_all();
            generate_verilog(&u)
        },
        {
            let mut u = RayBoxUnit::<3>::default();
            u.connect_all();
            generate_verilog(&u)
        },
    ] {
        assert!(verilog.contains("rbx_readdatavalid"));
        assert!(verilog.contains("diff * $signed(mant)"));
    }
}
