//! The work of the BVH traversals on a real workload, counted (issue 22 item 4): what a ray
//! unit that holds a tree in block RAM and traverses it itself would have to do, and what
//! would be left to the HPS. An illuminance run goes through a counting [`BoxTest`] (the
//! software slab test, so the answers are the engine's own) that tallies, per kind of
//! traversal, the queries, the pair tests of interior nodes, the leaves reached and the
//! primitives tested. A sample of the queries is then traversed again on the tree such a unit
//! would hold: one primitive a leaf, so each leaf it reports is one candidate for the HPS's
//! exact test. A closest-hit query is traversed twice there: over its whole interval, every
//! crossed leaf (what a unit streaming candidates, unaware of the best hit so far, traverses
//! and sends), and with pruning by the exact hits (the candidates the HPS, taking them near
//! first and skipping those past its best hit, still tests).

use super::bvh::{Bvh, BvhShape};
use super::error::EngineError;
use super::ray::{Ray, RayBoxQuery};
use super::slab::{Aabb, BoxTest, SlabTest, TraversalKind};
use super::world::World;
use super::Settings;
use crate::scene::{Scene, Sensor};
use std::cell::Cell;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

/// Every how many queries of a kind one is kept for the second traversal.
const SAMPLE_EVERY: u64 = 16;
/// Most queries of a kind kept.
const SAMPLE_MAX: usize = 50_000;

/// Totals of one kind of traversal.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct TraversalCounts {
    pub queries: u64,
    /// Root-box tests (one per query whose tree is not empty).
    pub root_tests: u64,
    /// Interior nodes whose two children were tested together.
    pub pair_tests: u64,
    pub leaves: u64,
    pub primitives: u64,
}

impl TraversalCounts {
    /// Per query: (pair tests, leaves, primitives).
    pub fn per_query(&self) -> (f64, f64, f64) {
        let q = self.queries.max(1) as f64;
        (
            self.pair_tests as f64 / q,
            self.leaves as f64 / q,
            self.primitives as f64 / q,
        )
    }
}

/// A tree's size.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct TreeSize {
    pub nodes: usize,
    pub leaves: usize,
    pub max_depth: usize,
}

impl TreeSize {
    fn of(bvh: &Bvh) -> Self {
        let BvhShape { leaves, max_depth } = bvh.shape();
        TreeSize {
            nodes: bvh.node_count(),
            leaves,
            max_depth,
        }
    }
}

/// The traversals' work over one illuminance run, on the engine's tree and on a unit's.
#[derive(Clone, Debug, serde::Serialize)]
pub struct TraversalStats {
    pub primitives: usize,
    /// The engine's tree (up to four primitives a leaf).
    pub engine_tree: TreeSize,
    /// The unit's tree (one primitive a leaf).
    pub unit_tree: TreeSize,
    /// Every query of the run, on the engine's tree.
    pub closest: TraversalCounts,
    pub crossed: TraversalCounts,
    /// The sampled closest-hit queries: on the engine's tree as the run traversed them; on
    /// the unit's tree over their whole interval (the unit's work and what it sends); on the
    /// unit's tree with pruning by the exact hits (what the HPS tests).
    pub closest_sampled_engine: TraversalCounts,
    pub closest_unit_whole: TraversalCounts,
    pub closest_unit_pruned: TraversalCounts,
    /// The sampled shadow-ray queries: on the engine's tree, and on the unit's (every crossed
    /// leaf in both).
    pub crossed_sampled_engine: TraversalCounts,
    pub crossed_unit: TraversalCounts,
}

#[derive(Default)]
struct Tally {
    queries: AtomicU64,
    root_tests: AtomicU64,
    pair_tests: AtomicU64,
    leaves: AtomicU64,
    primitives: AtomicU64,
}

impl Tally {
    fn counts(&self) -> TraversalCounts {
        let g = |a: &AtomicU64| a.load(Ordering::Relaxed);
        TraversalCounts {
            queries: g(&self.queries),
            root_tests: g(&self.root_tests),
            pair_tests: g(&self.pair_tests),
            leaves: g(&self.leaves),
            primitives: g(&self.primitives),
        }
    }
}

thread_local! {
    /// The traversal this thread is in, and whether its query is sampled.
    static CURRENT: Cell<(TraversalKind, bool)> = const { Cell::new((TraversalKind::Closest, false)) };
}

/// A query kept for the second traversal.
type Sample = (Ray, f64, f64);

/// The counting box test's totals (shared: the world owns one handle, the caller another).
#[derive(Default)]
struct Counter {
    closest: Tally,
    crossed: Tally,
    closest_sampled: Tally,
    crossed_sampled: Tally,
    closest_seen: AtomicU64,
    crossed_seen: AtomicU64,
    closest_samples: Mutex<Vec<Sample>>,
    crossed_samples: Mutex<Vec<Sample>>,
    /// Off while the openings are searched: only the illuminance run's traversals count.
    counting: std::sync::atomic::AtomicBool,
}

impl Counter {
    fn tallies(&self) -> (&Tally, Option<&Tally>) {
        let (kind, sampled) = CURRENT.with(Cell::get);
        match kind {
            TraversalKind::Closest => (&self.closest, sampled.then_some(&self.closest_sampled)),
            TraversalKind::Crossed => (&self.crossed, sampled.then_some(&self.crossed_sampled)),
        }
    }

    fn samples(&self, kind: TraversalKind) -> Vec<Sample> {
        let m = match kind {
            TraversalKind::Closest => &self.closest_samples,
            TraversalKind::Crossed => &self.crossed_samples,
        };
        std::mem::take(&mut *m.lock().unwrap_or_else(|p| p.into_inner()))
    }
}

struct CountingBoxTest(Arc<Counter>);

impl BoxTest for CountingBoxTest {
    fn hits(&self, ray: &RayBoxQuery, boxes: &[Aabb], entry_m: &mut [f64]) {
        SlabTest.hits(ray, boxes, entry_m);
        if !self.0.counting.load(Ordering::Relaxed) {
            return;
        }
        let (tally, sampled) = self.0.tallies();
        for t in std::iter::once(tally).chain(sampled) {
            match boxes.len() {
                1 => t.root_tests.fetch_add(1, Ordering::Relaxed),
                _ => t.pair_tests.fetch_add(1, Ordering::Relaxed),
            };
        }
    }

    fn traversal_begins(&self, kind: TraversalKind, ray: &Ray, t_min_m: f64, t_max_m: f64) {
        let c = &self.0;
        if !c.counting.load(Ordering::Relaxed) {
            return;
        }
        let (tally, seen, samples, sampled_tally) = match kind {
            TraversalKind::Closest => (
                &c.closest,
                &c.closest_seen,
                &c.closest_samples,
                &c.closest_sampled,
            ),
            TraversalKind::Crossed => (
                &c.crossed,
                &c.crossed_seen,
                &c.crossed_samples,
                &c.crossed_sampled,
            ),
        };
        tally.queries.fetch_add(1, Ordering::Relaxed);
        let mut sampled = false;
        if seen.fetch_add(1, Ordering::Relaxed) % SAMPLE_EVERY == 0 {
            let mut samples = samples.lock().unwrap_or_else(|p| p.into_inner());
            if samples.len() < SAMPLE_MAX {
                samples.push((*ray, t_min_m, t_max_m));
                sampled_tally.queries.fetch_add(1, Ordering::Relaxed);
                sampled = true;
            }
        }
        CURRENT.with(|k| k.set((kind, sampled)));
    }

    fn leaf_reached(&self, primitives: usize) {
        if !self.0.counting.load(Ordering::Relaxed) {
            return;
        }
        let (tally, sampled) = self.0.tallies();
        for t in std::iter::once(tally).chain(sampled) {
            t.leaves.fetch_add(1, Ordering::Relaxed);
            t.primitives.fetch_add(primitives as u64, Ordering::Relaxed);
        }
    }
}

/// Runs `engine::illuminance` on `scene` at `sensors` with `settings` (openings found as the
/// bench finds them), counting the traversals' work, then traverses the sampled queries again
/// on a tree of one primitive a leaf.
pub fn measure(
    scene: &Scene,
    sensors: &[Sensor],
    settings: &Settings,
) -> Result<TraversalStats, EngineError> {
    let counter = Arc::new(Counter::default());
    let mut world = World::with_box_test(scene, Box::new(CountingBoxTest(counter.clone())))?;
    let points: Vec<_> = sensors.iter().map(|s| s.position_m).collect();
    super::openings::add_openings(&mut world, &points);
    counter.counting.store(true, Ordering::Relaxed);
    super::illuminance(&world, sensors, settings, &|_, _| {})?;
    let unit_tree = Bvh::build_with_leaf_size(&world.primitive_bounds(), 1);
    let counting = || {
        let c = Counter::default();
        c.counting.store(true, Ordering::Relaxed);
        Arc::new(c)
    };
    let unit = counting();
    let test = CountingBoxTest(unit.clone());
    let (whole, pruned) = (counting(), counting());
    let (whole_test, pruned_test) = (
        CountingBoxTest(whole.clone()),
        CountingBoxTest(pruned.clone()),
    );
    for (ray, t_min_m, t_max_m) in counter.samples(TraversalKind::Closest) {
        unit_tree.visit_crossed(&whole_test, &ray, t_min_m, t_max_m, |_| true);
        unit_tree.closest(
            &pruned_test,
            &ray,
            t_min_m,
            t_max_m,
            |p, t_max| world.primitive_distance_m(p, &ray, t_min_m, t_max),
            |t| *t,
        );
    }
    for (ray, t_min_m, t_max_m) in counter.samples(TraversalKind::Crossed) {
        unit_tree.visit_crossed(&test, &ray, t_min_m, t_max_m, |_| true);
    }
    Ok(TraversalStats {
        primitives: world.primitive_count(),
        engine_tree: TreeSize::of(world.bvh()),
        unit_tree: TreeSize::of(&unit_tree),
        closest: counter.closest.counts(),
        crossed: counter.crossed.counts(),
        closest_sampled_engine: counter.closest_sampled.counts(),
        // Traversed as "crossed": every leaf over the whole interval.
        closest_unit_whole: whole.crossed.counts(),
        closest_unit_pruned: pruned.closest.counts(),
        crossed_sampled_engine: counter.crossed_sampled.counts(),
        crossed_unit: unit.crossed.counts(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A closed box room: the counts are consistent (every query tests its root; leaves carry
    /// primitives; the unpruned traversal of the sample reaches at least the leaves the pruned
    /// one did) and the tree's shape is the tree's.
    #[test]
    fn counts_are_consistent_on_a_box_room() {
        // Five walls of a 4 x 4 x 3 m room open to a uniform sky at the top.
        let text = "void plastic white 0 0 5 .5 .5 .5 0 0\n\
             void glow sky 0 0 4 1000 1000 1000 0\n\
             sky source s 0 0 4 0 0 1 180\n\
             white polygon floor 0 0 12 0 0 0 0 4 0 4 4 0 4 0 0\n\
             white polygon w1 0 0 12 0 0 0 0 0 3 0 4 3 0 4 0\n\
             white polygon w2 0 0 12 4 0 0 4 4 0 4 4 3 4 0 3\n\
             white polygon w3 0 0 12 0 0 0 4 0 0 4 0 3 0 0 3\n\
             white polygon w4 0 0 12 0 4 0 0 4 3 4 4 3 4 4 0\n";
        let scene = crate::scene::parse("room.rad", text.as_bytes()).unwrap();
        let sensors =
            crate::scene::parse_sensors("s.pts", b"2 2 0.8 0 0 1\n1 3 0.8 0 0 1\n").unwrap();
        let settings = Settings {
            samples_per_sensor: 256,
            ..Settings::default()
        };
        let s = measure(&scene, &sensors, &settings).unwrap();
        assert_eq!(s.primitives, 5);
        for t in [s.engine_tree, s.unit_tree] {
            assert_eq!(t.nodes, 2 * t.leaves - 1, "a binary tree: {t:?}");
        }
        assert_eq!(s.unit_tree.leaves, 5, "one primitive a leaf");
        for c in [&s.closest, &s.crossed] {
            assert!(c.queries > 0, "{s:?}");
            assert!(c.root_tests <= c.queries);
            assert!(c.primitives >= c.leaves);
        }
        let n = s.closest_sampled_engine.queries;
        assert!(n > 0);
        for c in [&s.closest_unit_whole, &s.closest_unit_pruned] {
            assert_eq!(c.queries, n);
            assert_eq!(c.leaves, c.primitives, "one primitive a leaf");
        }
        // Pruning only removes work, and every closest query that hits finds a candidate.
        assert!(
            s.closest_unit_whole.leaves >= s.closest_unit_pruned.leaves,
            "{s:?}"
        );
        assert_eq!(s.crossed_unit.queries, s.crossed_sampled_engine.queries);
    }
}
