//! The BVH traversal core against the golden model (`skylux_regmap::bvh_format`): the f32
//! front end against `grid_ray` field by field; whole batches against `result_words`, word
//! for word, on real trees built over random boxes, trees with garbage nodes (bad references,
//! cycles, chains deeper than the stack), random and hostile rays, both orders, random gaps
//! on the input and back-pressure on the output; and the clocks a ray and a node visit take.

use proptest::prelude::*;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rust_hdl::prelude::*;
use skylux_regmap::bvh_format::{
    grid_ray, result_words, split_rays, Order, RayF32, UnitNode, MAX_NODES, NODE_WORDS, RAY_WORDS,
    REF_INDEX_MASK, REF_LEAF, REF_VALID, STACK_DEPTH,
};
use skylux_regmap::raybox_format::{COORD_MAX, COORD_MIN};
use skylux_rtl::bvh::bench::{build_tree, chain, ring, Aabb, Bench, BvhBlock, Run};
use skylux_rtl::bvh::{BvhInterleaved, BvhTraversal, RayFrontEnd, RAYS_IN_FLIGHT, VISIT_CYCLES};
use skylux_rtl::drive::Driver;

// ---- the front end ---------------------------------------------------------------------

/// f32 bit patterns around every threshold of the conversions, and anything.
fn f32_bits() -> impl Strategy<Value = u32> {
    let exponent = prop_oneof![
        Just(0u32),
        Just(255),
        80u32..=90,   // inverse: under 2^-40 refused
        104u32..=110, // distance: truncated to 0
        132u32..=152, // origin range, distance shifts, inverse clamp
        any::<u8>().prop_map(u32::from),
    ];
    let fraction = prop_oneof![Just(0u32), Just(0x7f_ffff), Just(1), 0u32..0x80_0000];
    (any::<bool>(), exponent, fraction).prop_map(|(s, e, f)| (u32::from(s) << 31) | (e << 23) | f)
}

fn check_front_end(driver: &mut Driver<RayFrontEnd>, fields: [u32; 8]) {
    let words: [u64; RAY_WORDS] =
        std::array::from_fn(|k| fields[2 * k] as u64 | ((fields[2 * k + 1] as u64) << 32));
    let d = &mut driver.dut;
    d.word0.next = words[0].into();
    d.word1.next = words[1].into();
    d.word2.next = words[2].into();
    d.word3.next = words[3].into();
    driver.settle().unwrap();
    let d = &driver.dut;
    let golden = grid_ray(&words);
    assert_eq!(
        d.representable.val(),
        golden.is_some(),
        "{fields:08x?}: {golden:?}"
    );
    let Some(g) = golden else { return };
    let field = |v: u128, w: u32, a: usize| ((v >> (w as usize * a)) & ((1 << w) - 1)) as u64;
    let sext = |v: u64, w: u32| (((v << (64 - w)) as i64) >> (64 - w)) as i32;
    let origin = d.origin.val().to_u128();
    let mant = d.mant.val().to_u128();
    let shift = d.shift.val().to_u64() as u128;
    let lower = d.lower_is_entry.val().to_u128();
    for a in 0..3 {
        assert_eq!(sext(field(origin, 21, a), 21), g.origin[a], "{fields:08x?}");
        assert_eq!(sext(field(mant, 25, a), 25), g.mant[a], "{fields:08x?}");
        assert_eq!(field(shift, 6, a) as u8, g.shift[a], "{fields:08x?}");
        let want = if g.mant[a] > 0 { (1 << 21) - 1 } else { 0 };
        assert_eq!(field(lower, 21, a), want, "{fields:08x?}");
    }
    assert_eq!(
        d.t_min.val().to_u64() as u32 as i32,
        g.t_min,
        "{fields:08x?}"
    );
    assert_eq!(
        d.t_max.val().to_u64() as u32 as i32,
        g.t_max,
        "{fields:08x?}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    #[test]
    fn front_end_equals_grid_ray(fields in prop::array::uniform8(f32_bits())) {
        let mut driver = Driver::new(RayFrontEnd::default());
        check_front_end(&mut driver, fields);
    }
}

#[test]
fn front_end_edges() {
    let mut driver = Driver::new(RayFrontEnd::default());
    let ok = |x: f32| x.to_bits();
    let specials = [
        0.0f32,
        -0.0,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
        f32::MIN_POSITIVE,
        1.0e-45,
        255.99998,
        -255.99998,
        256.0,
        (2.0f32).powi(-40),
        (2.0f32).powi(-41),
        (2.0f32).powi(24),
        16_777_215.0,
        (2.0f32).powi(19) - 0.0001,
        (2.0f32).powi(19),
        -(2.0f32).powi(19),
        (2.0f32).powi(-20),
        (2.0f32).powi(-21),
        1.0,
        -1.0,
    ];
    for &a in &specials {
        for &b in &specials {
            check_front_end(
                &mut driver,
                [ok(a), ok(b), ok(1.0), ok(b), ok(a), ok(-1.0), ok(a), ok(b)],
            );
            check_front_end(&mut driver, [0, 0, 0, ok(a), ok(b), ok(a), ok(b), ok(a)]);
        }
    }
}

// ---- trees -------------------------------------------------------------------------------

/// Scene half-size in grid steps (about 5 m), so random rays meet boxes.
const SCENE: i32 = 20_000;

fn random_box(rng: &mut StdRng) -> Aabb {
    let size = if rng.gen_bool(0.2) { 12_000 } else { 4000 };
    let lo: [i32; 3] = std::array::from_fn(|_| rng.gen_range(-SCENE..SCENE));
    let hi: [i32; 3] = std::array::from_fn(|i| lo[i] + rng.gen_range(0..size));
    (lo, hi)
}

fn random_tree(rng: &mut StdRng) -> Vec<UnitNode> {
    let n = rng.gen_range(1..48);
    let leaves: Vec<(u16, Aabb)> = (0..n)
        .map(|k| {
            let id = if rng.gen_bool(0.2) {
                rng.gen_range(0..=REF_INDEX_MASK)
            } else {
                k as u16
            };
            (id, random_box(rng))
        })
        .collect();
    build_tree(&leaves)
}

/// Damages a tree: references to anywhere (cycles, beyond the count), boxes everywhere,
/// invalid children with garbage behind them.
fn damage(rng: &mut StdRng, nodes: &mut [UnitNode]) {
    let count = nodes.len();
    for _ in 0..rng.gen_range(1..4) {
        let k = rng.gen_range(0..count);
        let c = rng.gen_range(0..2);
        let node = &mut nodes[k];
        match rng.gen_range(0..4) {
            0 => {
                // Often a cycle the ray follows: toward an ancestor, through a box everywhere.
                node.reference[c] = REF_VALID | rng.gen_range(0..count as u16 + 3);
                if rng.gen_bool(0.5) {
                    node.lower[c] = [COORD_MIN; 3];
                    node.upper[c] = [COORD_MAX; 3];
                }
            }
            1 => node.reference[c] = rng.gen(),
            2 => {
                node.lower[c] = [COORD_MIN; 3];
                node.upper[c] = [COORD_MAX; 3];
            }
            _ => node.reference[c] &= !REF_VALID,
        }
    }
}

// ---- rays ----------------------------------------------------------------------------------

fn metres(steps: i32) -> f32 {
    steps as f32 / 4096.0
}

fn random_ray(rng: &mut StdRng, nodes: &[UnitNode]) -> [u64; RAY_WORDS] {
    let origin: [f32; 3] = std::array::from_fn(|_| metres(rng.gen_range(-SCENE..SCENE)));
    // Mostly toward a box of the tree, so hits are common.
    let n = &nodes[rng.gen_range(0..nodes.len())];
    let target: [f32; 3] = std::array::from_fn(|i| metres(n.lower[0][i] / 2 + n.upper[0][i] / 2));
    let mut d: [f32; 3] = if rng.gen_bool(0.7) {
        std::array::from_fn(|i| target[i] - origin[i])
    } else {
        std::array::from_fn(|_| rng.gen_range(-1.0..1.0))
    };
    if rng.gen_bool(0.2) {
        d[rng.gen_range(0..3)] = 0.0; // axis-parallel: an infinite inverse
    }
    let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt().max(1e-6);
    let mut ray = RayF32 {
        origin_m: origin,
        inverse_direction: std::array::from_fn(|i| len / d[i]),
        t_min_m: if rng.gen_bool(0.7) {
            0.0
        } else {
            rng.gen_range(-1.0..3.0)
        },
        t_max_m: if rng.gen_bool(0.5) {
            f32::INFINITY
        } else {
            rng.gen_range(0.0..12.0)
        },
    };
    if rng.gen_bool(0.1) {
        // Hostile fields: the front end must refuse or convert them as the golden model.
        let v = match rng.gen_range(0..7) {
            0 => f32::NAN,
            1 => f32::INFINITY,
            2 => -f32::INFINITY,
            3 => 300.0,
            4 => 0.0,
            5 => 1.0e-13,
            _ => f32::from_bits(rng.gen()),
        };
        match rng.gen_range(0..8) {
            k @ 0..=2 => ray.origin_m[k] = v,
            k @ 3..=5 => ray.inverse_direction[k - 3] = v,
            6 => ray.t_min_m = v,
            _ => ray.t_max_m = v,
        }
    }
    let mut words = ray.pack();
    if rng.gen_bool(0.02) {
        words[rng.gen_range(0..RAY_WORDS)] = rng.gen();
    }
    words
}

// ---- batches -------------------------------------------------------------------------------

struct Batch {
    nodes: Vec<UnitNode>,
    /// Words loaded beyond the node count (stale memory the unit must never read).
    stale: Vec<[u64; NODE_WORDS]>,
    rays: Vec<[u64; RAY_WORDS]>,
    order: Order,
}

fn random_batch(rng: &mut StdRng) -> Batch {
    let mut nodes = match rng.gen_range(0..12) {
        0 => chain(rng.gen_range(STACK_DEPTH - 2..STACK_DEPTH + 3)),
        3 => ring(rng.gen_range(1..6)),
        1 | 2 => {
            let mut t = random_tree(rng);
            damage(rng, &mut t);
            t
        }
        _ => random_tree(rng),
    };
    if rng.gen_bool(0.05) {
        nodes.truncate(0); // no tree at all: node 0 is a bad reference
    }
    let stale = (0..rng.gen_range(0..3))
        .map(|_| {
            let mut n = UnitNode {
                lower: [[COORD_MIN; 3]; 2],
                upper: [[COORD_MAX; 3]; 2],
                reference: [REF_VALID | REF_LEAF | 1, REF_VALID | 2],
            };
            n.reference[1] = rng.gen();
            n.pack()
        })
        .collect();
    let sample = if nodes.is_empty() {
        build_tree(&[(0, random_box(rng))])
    } else {
        nodes.clone()
    };
    let rays = (0..rng.gen_range(1..8))
        .map(|_| random_ray(rng, &sample))
        .collect();
    let order = if rng.gen_bool(0.5) {
        Order::NearFirst
    } else {
        Order::ChildOrder
    };
    Batch {
        nodes,
        stale,
        rays,
        order,
    }
}

/// Each ray's words, with the tags the run gave the rays.
fn per_ray(
    nodes: &[UnitNode],
    rays: &[[u64; RAY_WORDS]],
    order: Order,
    tags: &[u8],
) -> Vec<Vec<u64>> {
    assert_eq!(rays.len(), tags.len());
    rays.iter()
        .zip(tags)
        .map(|(r, &t)| result_words(nodes, r, order, t))
        .collect()
}

/// The block's output split into rays by tag (words of different rays may interleave).
fn split(run: &Run) -> Vec<Vec<u64>> {
    split_rays(&run.words, &run.tags).expect("every word belongs to a ray of the batch")
}

fn load<B: BvhBlock>(bench: &mut Bench<B>, batch: &Batch) {
    let words: Vec<[u64; NODE_WORDS]> = batch
        .nodes
        .iter()
        .map(UnitNode::pack)
        .chain(batch.stale.iter().copied())
        .collect();
    bench.load(&words);
    bench.configure(batch.nodes.len(), batch.order);
}

/// Several batches through one instance (the node memory reloaded between them): each ray's
/// words equal the golden model's, with random input gaps and output back-pressure.
fn batches_equal_result_words<B: BvhBlock>(
    seed: u64,
    offer_p: f64,
    ready_p: f64,
    batches: usize,
    rays: std::ops::Range<usize>,
) -> Result<(), TestCaseError> {
    let mut rng = StdRng::seed_from_u64(seed);
    let mut bench = Bench::<B>::new(seed);
    bench.idle(2);
    for b in 0..batches {
        let mut batch = random_batch(&mut rng);
        let sample = if batch.nodes.is_empty() {
            build_tree(&[(0, random_box(&mut rng))])
        } else {
            batch.nodes.clone()
        };
        let n = rng.gen_range(rays.clone());
        while batch.rays.len() < n {
            batch.rays.push(random_ray(&mut rng, &sample));
        }
        load(&mut bench, &batch);
        let mut gaps = StdRng::seed_from_u64(seed ^ 0x5eed);
        let mut ready = StdRng::seed_from_u64(seed ^ 0xbeef);
        let run = bench
            .run(
                &batch.rays,
                || gaps.gen_bool(offer_p),
                || ready.gen_bool(ready_p),
                2_000_000,
            )
            .expect("every ray ends");
        let want = per_ray(&batch.nodes, &batch.rays, batch.order, &run.tags);
        prop_assert_eq!(&split(&run), &want, "seed {} batch {}", seed, b);
        bench.idle(3);
        prop_assert!(!bench.busy(), "busy after the batch");
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// One ray in flight.
    #[test]
    fn traversal_equals_result_words(
        seed in any::<u64>(),
        offer_p in prop_oneof![Just(1.0f64), 0.2f64..1.0],
        ready_p in prop_oneof![Just(1.0f64), 0.1f64..1.0],
    ) {
        batches_equal_result_words::<BvhTraversal>(seed, offer_p, ready_p, 3, 1..8)?;
    }

    /// Rays interleaved: batches longer than the contexts, so rays enter as others end.
    #[test]
    fn interleaved_equals_result_words(
        seed in any::<u64>(),
        offer_p in prop_oneof![Just(1.0f64), 0.2f64..1.0],
        ready_p in prop_oneof![Just(1.0f64), 0.1f64..1.0],
    ) {
        batches_equal_result_words::<BvhInterleaved>(
            seed, offer_p, ready_p, 3, 1..3 * RAYS_IN_FLIGHT,
        )?;
    }
}

#[test]
fn refusals_and_orders_all_occur_in_the_random_batches() {
    // The generators must reach every refusal, both answers and both orders, or the
    // proptest above would prove little.
    let mut rng = StdRng::seed_from_u64(1);
    let mut codes = [0usize; 5];
    let mut candidates = 0;
    let mut swapped = 0;
    let mut refused_with_candidates = 0;
    for _ in 0..400 {
        let batch = random_batch(&mut rng);
        for r in &batch.rays {
            let words = result_words(&batch.nodes, r, batch.order, 0);
            let code = ((words.last().unwrap() >> 32) & 0xff) as usize;
            codes[code] += 1;
            candidates += words.len() - 1;
            if code != 0 && words.len() > 1 {
                refused_with_candidates += 1;
            }
            let other = match batch.order {
                Order::NearFirst => Order::ChildOrder,
                Order::ChildOrder => Order::NearFirst,
            };
            if result_words(&batch.nodes, r, other, 0) != words {
                swapped += 1;
            }
        }
    }
    assert!(
        codes.iter().all(|&c| c > 5)
            && candidates > 500
            && swapped > 20
            && refused_with_candidates > 5,
        "{codes:?} {candidates} {swapped} {refused_with_candidates}"
    );
}

/// Deep chains, a full memory of nodes and the largest result: the counters and the output
/// FIFO at their limits.
#[test]
fn limits() {
    limits_on::<BvhTraversal>();
    limits_on::<BvhInterleaved>();
}

fn limits_on<B: BvhBlock>() {
    let ray = RayF32 {
        origin_m: [0.5, -0.25, 0.125],
        inverse_direction: [1.0, f32::INFINITY, -4.0],
        t_min_m: 0.0,
        t_max_m: f32::INFINITY,
    }
    .pack();
    let mut bench = Bench::<B>::new(3);
    for (nodes, order) in [
        (chain(STACK_DEPTH), Order::ChildOrder),
        (chain(STACK_DEPTH + 1), Order::ChildOrder),
        (chain(STACK_DEPTH - 1), Order::NearFirst),
        // Every node's two children are leaves or the next node: MAX_NODES visits, about
        // 2 × MAX_NODES candidates, the candidate counter's largest use.
        (
            (0..MAX_NODES as u16)
                .map(|i| UnitNode {
                    lower: [[COORD_MIN; 3]; 2],
                    upper: [[COORD_MAX; 3]; 2],
                    reference: [
                        REF_VALID | REF_LEAF | i,
                        if i + 1 < MAX_NODES as u16 {
                            REF_VALID | (i + 1)
                        } else {
                            REF_VALID | REF_LEAF | 0x3fff
                        },
                    ],
                })
                .collect::<Vec<_>>(),
            Order::ChildOrder,
        ),
        // The same ring closed: one visit too many.
        (
            (0..MAX_NODES as u16)
                .map(|i| UnitNode {
                    lower: [[COORD_MIN; 3]; 2],
                    upper: [[COORD_MAX; 3]; 2],
                    reference: [
                        REF_VALID | REF_LEAF | i,
                        REF_VALID | ((i + 1) % MAX_NODES as u16),
                    ],
                })
                .collect::<Vec<_>>(),
            Order::NearFirst,
        ),
    ] {
        let words: Vec<[u64; NODE_WORDS]> = nodes.iter().map(UnitNode::pack).collect();
        bench.load(&words);
        bench.configure(nodes.len(), order);
        let rays = [ray; RAYS_IN_FLIGHT + 2];
        // Slow output (one word in three clocks): the FIFO fills and the traversal waits.
        let mut k = 0u64;
        let run = bench
            .run(
                &rays,
                || true,
                || {
                    k = (k + 1) % 3;
                    k == 2
                },
                1_000_000,
            )
            .expect("every ray ends");
        let want = per_ray(&nodes, &rays, order, &run.tags);
        assert_eq!(split(&run), want, "{} nodes", nodes.len());
    }
}

// ---- speed -------------------------------------------------------------------------------

/// Node visits and stack pops of one ray, counted along the golden model's traversal.
fn visits_and_pops(nodes: &[UnitNode], words: &[u64; RAY_WORDS], order: Order) -> (u64, u64) {
    use skylux_regmap::bvh_format::child_test;
    let Some(ray) = grid_ray(words) else {
        return (0, 0);
    };
    let (mut visits, mut pops) = (0, 0);
    let mut stack: Vec<(u16, i32)> = vec![];
    let mut current = 0usize;
    loop {
        visits += 1;
        let node = &nodes[current];
        let t: Vec<(bool, u16, i32)> = (0..2)
            .map(|c| {
                let (hit, t) = child_test(&ray, &node.lower[c], &node.upper[c]);
                (
                    node.reference[c] & REF_VALID != 0 && hit,
                    node.reference[c],
                    t,
                )
            })
            .collect();
        let first = usize::from(order == Order::NearFirst && t[0].0 && t[1].0 && t[1].2 < t[0].2);
        let hits: Vec<(u16, i32)> = [first, 1 - first]
            .iter()
            .filter(|&&c| t[c].0)
            .map(|&c| (t[c].1, t[c].2))
            .collect();
        if hits.len() == 2 {
            stack.push(hits[1]);
        }
        let mut next = hits.first().copied();
        loop {
            match next {
                Some((r, _)) if r & REF_LEAF != 0 => next = None,
                Some((r, _)) => {
                    current = (r & REF_INDEX_MASK) as usize;
                    break;
                }
                None => match stack.pop() {
                    Some(e) => {
                        pops += 1;
                        next = Some(e);
                    }
                    None => return (visits, pops),
                },
            }
        }
    }
}

/// Clocks per ray and per node visit with one ray in flight, on random trees of 40 leaves
/// and rays toward their boxes (no back-pressure, no input gaps). Structural bound: each
/// visit takes VISIT_CYCLES clocks, each stack entry one more, each ray three (its start,
/// the empty stack, its end word), and each batch the first ray's words and the last
/// word's way out.
#[test]
fn cycles_per_ray_and_per_visit() {
    let mut rng = StdRng::seed_from_u64(40);
    let mut bench = Bench::<BvhTraversal>::new(40);
    let (mut cycles, mut rays_done, mut visits, mut pops) = (0u64, 0u64, 0u64, 0u64);
    const BATCHES: u64 = 6;
    for _ in 0..BATCHES {
        let leaves: Vec<(u16, Aabb)> = (0..40).map(|k| (k, random_box(&mut rng))).collect();
        let nodes = build_tree(&leaves);
        let rays: Vec<[u64; RAY_WORDS]> = (0..50)
            .map(|_| loop {
                let r = random_ray(&mut rng, &nodes);
                if grid_ray(&r).is_some() {
                    break r;
                }
            })
            .collect();
        let words: Vec<[u64; NODE_WORDS]> = nodes.iter().map(UnitNode::pack).collect();
        bench.load(&words);
        bench.configure(nodes.len(), Order::NearFirst);
        let run = bench.run(&rays, || true, || true, 1_000_000).unwrap();
        // No input gaps: the tags run 0, 1, 2, ...
        assert!(run.tags.iter().enumerate().all(|(k, &t)| t == k as u8));
        let want = per_ray(&nodes, &rays, Order::NearFirst, &run.tags);
        assert_eq!(split(&run), want);
        for r in &rays {
            let (v, p) = visits_and_pops(&nodes, r, Order::NearFirst);
            visits += v;
            pops += p;
        }
        cycles += run.cycles;
        rays_done += rays.len() as u64;
        bench.idle(4);
    }
    let per_ray = cycles as f64 / rays_done as f64;
    let per_visit = cycles as f64 / visits as f64;
    println!(
        "{rays_done} rays, {visits} node visits ({:.2} a ray), {pops} pops: \
         {cycles} clocks, {per_ray:.1} a ray, {per_visit:.2} a node visit \
         (a visit alone: {VISIT_CYCLES})",
        visits as f64 / rays_done as f64
    );
    let bound = visits * VISIT_CYCLES as u64 + pops + rays_done * 3 + BATCHES * 8;
    assert!(cycles <= bound, "{cycles} clocks, bound {bound}");
    assert!(cycles >= visits * VISIT_CYCLES as u64);
}

/// Rays interleaved, on the same trees and rays as `cycles_per_ray_and_per_visit` (no
/// back-pressure, no input gaps). Structural facts checked, not timings: one operation (a
/// node visit, a pop or an end word) issues a clock at most; and on every clock where all
/// `RAYS_IN_FLIGHT` contexts hold a ray one issues, because at most `PIPELINE_CLOCKS`
/// contexts can be busy (issued within the last `PIPELINE_CLOCKS` clocks) and the FIFO
/// always has room when every word is taken.
#[test]
fn interleaved_cycles_per_ray_and_visits_per_clock() {
    let mut rng = StdRng::seed_from_u64(40);
    let mut bench = Bench::<BvhInterleaved>::new(40);
    let (mut cycles, mut rays_done, mut visits, mut pops) = (0u64, 0u64, 0u64, 0u64);
    let (mut full, mut issued_full, mut issued, mut visit_issues) = (0u64, 0u64, 0u64, 0u64);
    let mut held = 0u64;
    const BATCHES: u64 = 6;
    for _ in 0..BATCHES {
        let leaves: Vec<(u16, Aabb)> = (0..40).map(|k| (k, random_box(&mut rng))).collect();
        let nodes = build_tree(&leaves);
        let rays: Vec<[u64; RAY_WORDS]> = (0..50)
            .map(|_| loop {
                let r = random_ray(&mut rng, &nodes);
                if grid_ray(&r).is_some() {
                    break r;
                }
            })
            .collect();
        let words: Vec<[u64; NODE_WORDS]> = nodes.iter().map(UnitNode::pack).collect();
        bench.load(&words);
        bench.configure(nodes.len(), Order::NearFirst);
        let run = bench
            .run_observed(
                &rays,
                || true,
                || true,
                1_000_000,
                |d| {
                    let n = d.rays_held();
                    held += n as u64;
                    issued += u64::from(d.issuing());
                    visit_issues += u64::from(d.issuing_visit());
                    if n == RAYS_IN_FLIGHT {
                        full += 1;
                        issued_full += u64::from(d.issuing());
                    }
                },
            )
            .unwrap();
        assert!(run.tags.iter().enumerate().all(|(k, &t)| t == k as u8));
        let want = per_ray(&nodes, &rays, Order::NearFirst, &run.tags);
        assert_eq!(split(&run), want);
        for r in &rays {
            let (v, p) = visits_and_pops(&nodes, r, Order::NearFirst);
            visits += v;
            pops += p;
        }
        cycles += run.cycles;
        rays_done += rays.len() as u64;
        bench.idle(4);
    }
    println!(
        "{RAYS_IN_FLIGHT} rays in flight: {rays_done} rays, {visits} node visits ({:.2} a ray), \
         {pops} pops: {cycles} clocks, {:.1} a ray, {:.2} node visits a clock; \
         {:.2} rays held on average, all contexts held on {full} clocks ({:.0}%)",
        visits as f64 / rays_done as f64,
        cycles as f64 / rays_done as f64,
        visits as f64 / cycles as f64,
        held as f64 / cycles as f64,
        100.0 * full as f64 / cycles as f64,
    );
    // Every visit, pop and end word is one issue, each on its own clock.
    assert_eq!(visit_issues, visits);
    assert_eq!(issued, visits + pops + rays_done);
    assert!(cycles >= issued);
    assert!(full > 0, "the contexts never filled");
    assert_eq!(
        issued_full, full,
        "a clock with every context held issued nothing"
    );
}

#[test]
fn exports_verilog() {
    for v in [
        generate_verilog(&{
            let mut u = BvhTraversal::default();
            u.connect_all();
            u
        }),
        generate_verilog(&{
            let mut u = BvhInterleaved::default();
            u.connect_all();
            u
        }),
    ] {
        assert!(v.contains("result_ready") && v.contains("diff * $signed(mant)"));
    }
}
