//! The BVH traversal core's Verilog (the exported `BvhInterleaved`, from a fresh instance)
//! against its rust-hdl simulation: a recorded run (rays interleaved) (a real tree over random boxes in both orders, a chain deeper
//! than the stack, a ring, hostile rays, random input gaps and output back-pressure, garbage
//! on idle inputs), itself checked against `bvh_format::result_words`, replayed in Icarus;
//! and a tampered Verilog caught.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rust_hdl::prelude::*;
use skylux_bitstream::xcheck::{self, Tool};
use skylux_regmap::bvh_format::{
    result_tag, result_words, split_rays, Order, RayF32, UnitNode, NODE_WORDS, RAY_WORDS,
    STACK_DEPTH,
};
use skylux_rtl::bvh::bench::{build_tree, chain, ring, Aabb, BvhBench};
use skylux_rtl::bvh::{BvhInterleaved, RAYS_IN_FLIGHT};

/// A ray from a random origin toward `target` (grid steps).
fn ray(rng: &mut StdRng, target: [i32; 3]) -> [u64; RAY_WORDS] {
    let origin: [f32; 3] = std::array::from_fn(|_| rng.gen_range(-3.0f32..3.0));
    let d: [f32; 3] = std::array::from_fn(|i| target[i] as f32 / 4096.0 - origin[i]);
    let mut r = RayF32 {
        origin_m: origin,
        inverse_direction: d.map(|d| 1.0 / d),
        t_min_m: 0.0,
        t_max_m: if rng.gen_bool(0.5) {
            f32::INFINITY
        } else {
            rng.gen_range(0.0..8.0)
        },
    };
    if rng.gen_bool(0.1) {
        r.inverse_direction[rng.gen_range(0..3)] = f32::INFINITY;
    }
    if rng.gen_bool(0.08) {
        r.origin_m[rng.gen_range(0..3)] = [f32::NAN, 300.0, -1.0e-30][rng.gen_range(0..3)];
    }
    r.pack()
}

#[test]
fn bvh_traversal_verilog_equals_rust_hdl() {
    if !xcheck::require(&[Tool::Iverilog, Tool::Vvp]) {
        return;
    }
    let mut rng = StdRng::seed_from_u64(22);
    let leaves: Vec<(u16, Aabb)> = (0..24)
        .map(|k| {
            let lo: [i32; 3] = std::array::from_fn(|_| rng.gen_range(-12_000..12_000));
            let hi: [i32; 3] = std::array::from_fn(|i| lo[i] + rng.gen_range(0..6000));
            (k, (lo, hi))
        })
        .collect();
    let tree = build_tree(&leaves);
    let mut bench = BvhBench::new(5);
    bench.driver.record();
    bench.idle(3);
    let mut candidates = 0;
    let mut interleaved = 0;
    for (nodes, order) in [
        (tree.clone(), Order::NearFirst),
        (tree, Order::ChildOrder),
        (chain(STACK_DEPTH + 1), Order::ChildOrder),
        (ring(3), Order::NearFirst),
    ] {
        let packed: Vec<[u64; NODE_WORDS]> = nodes.iter().map(UnitNode::pack).collect();
        bench.load(&packed);
        bench.configure(nodes.len(), order);
        let rays: Vec<[u64; RAY_WORDS]> = (0..2 * RAYS_IN_FLIGHT)
            .map(|_| {
                let (lo, hi) = leaves[rng.gen_range(0..leaves.len())].1;
                ray(&mut rng, std::array::from_fn(|i| lo[i] / 2 + hi[i] / 2))
            })
            .collect();
        let mut gaps = StdRng::seed_from_u64(1);
        let mut ready = StdRng::seed_from_u64(2);
        let run = bench
            .run(
                &rays,
                || gaps.gen_bool(0.7),
                || ready.gen_bool(0.6),
                100_000,
            )
            .expect("every ray ends");
        // The recorded run is itself right, so the replay compares against a meaningful trace.
        let want: Vec<Vec<u64>> = rays
            .iter()
            .zip(&run.tags)
            .map(|(r, &t)| result_words(&nodes, r, order, t))
            .collect();
        assert_eq!(
            split_rays(&run.words, &run.tags),
            Some(want),
            "rust-hdl vs golden, {} nodes",
            nodes.len()
        );
        candidates += run.words.iter().filter(|&&w| w >> 63 == 0).count();
        // A ray's candidate followed by another ray's word: the rays were interleaved.
        interleaved += run
            .words
            .windows(2)
            .filter(|w| w[0] >> 63 == 0 && result_tag(w[0]) != result_tag(w[1]))
            .count();
        bench.idle(2);
    }
    assert!(candidates > 15, "too few candidates: {candidates}");
    assert!(interleaved > 5, "rays hardly interleaved: {interleaved}");

    let trace = bench.driver.take_trace();
    let mut fresh = BvhInterleaved::default();
    fresh.connect_all();
    let verilog = generate_verilog(&fresh);
    let report = xcheck::replay("bvh_traversal", &verilog, &trace).unwrap();
    println!("{}", report.summary());
    assert!(
        report.steps > 3000,
        "trace too short: {} steps",
        report.steps
    );
    assert!(report.is_clean(), "{}", report.summary());

    // The stack overflow's refusal code changed (2 to 3) must be caught on the result data.
    let tampered = verilog.replacen(
        "localparam  stack_overflow = 3'b10",
        "localparam  stack_overflow = 3'b11",
        1,
    );
    assert_ne!(
        tampered, verilog,
        "the constant is not where the test expects it"
    );
    let report = xcheck::replay("bvh_traversal_tampered", &tampered, &trace).unwrap();
    assert!(
        report.mismatches.iter().any(|m| m.port == "result_data"),
        "tampering not caught"
    );
}
