//! The BVH ray unit as the engine's traversal (issue 22 item 4): the unit holds a copy of the
//! engine's own tree (`skylux_regmap::bvh_format`), traverses each ray in the fabric and
//! hands back the leaves the ray may reach; the HPS tests their primitives exactly, so the
//! answers are the software traversal's, bit for bit:
//!
//! - the unit's box test is conservative (no false miss, entry never late: the format's
//!   module docs), so every leaf the software traversal reaches is among the candidates, and
//!   extra candidates only add exact tests that find nothing;
//! - closest-hit queries come near first and the HPS skips a candidate whose entry is past
//!   its best hit, as `Bvh::closest` pops its stack; the closest hit does not depend on the
//!   order (up to exact ties of distance, as with the ray-box unit);
//! - shadow-ray queries come in the software traversal's child order, so a product of
//!   transmissions is multiplied in the same order.
//!
//! A ray the unit refuses (a value its grid cannot hold) or a fault of the backend is
//! answered by the software traversal and counted.

use super::bvh::Bvh;
use super::ray::{Ray, RayBoxQuery};
use super::slab::{Aabb, SlabTest};
use crate::fpga::bvh_unit::{check_answer, BvhUnitBackend, BvhUnitError, NodeWords, RayWords};
use skylux_regmap::bvh_format::{
    unpack_result, Order, RayF32, ResultWord, UnitNode, GROWTH_STEPS, MAX_NODES, REF_INDEX_MASK,
    REF_LEAF, REF_VALID,
};
use skylux_regmap::raybox_format::{COORD_FRAC_BITS, COORD_MAX, COORD_MIN, METRES_PER_STEP};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;

/// A candidate whose conservative entry lies within this of the interval's end is checked
/// with the exact f64 test of its own box before its primitive's exact test: the unit's
/// outward rounding and growth (well under a millimetre a axis, more along a grazing ray) put
/// the surface a shadow ray ends on, and its neighbours, among the candidates, where the
/// software traversal's f64 box test leaves them out. A box test costs the A9 half a primitive
/// test (`bench_raybox_unit`), and a miss of a primitive's own box is a miss of the
/// primitive, so the answers do not change.
pub const FAR_END_M: f64 = 0.01;

/// Grid steps per metre.
const STEPS_PER_M: f64 = (1u64 << COORD_FRAC_BITS) as f64;
/// Shortest ray direction the unit's error bound covers (`bvh_format` module docs).
const MIN_DIRECTION_LENGTH: f64 = 0.5;

/// Why a tree cannot go into the unit.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum UnitTreeError {
    #[error("the scene has no primitive: no tree to load")]
    Empty,
    #[error("the tree of {nodes} nodes needs more than the unit's {MAX_NODES} nodes (or 16384 primitives)")]
    TooLarge { nodes: usize },
    #[error("node {node}'s box reaches beyond the unit's ±256 m grid (or is empty)")]
    OutOfRange { node: usize },
    #[error(transparent)]
    Backend(#[from] BvhUnitError),
}

/// A box on the unit's grid: rounded outward and grown by [`GROWTH_STEPS`]; `None` when it
/// leaves the grid's range, is empty or not finite.
pub fn quantise_box(b: &Aabb) -> Option<([i32; 3], [i32; 3])> {
    let (mut lower, mut upper) = ([0; 3], [0; 3]);
    for axis in 0..3 {
        let lo = (b.min_m[axis] * STEPS_PER_M).floor() - GROWTH_STEPS as f64;
        let hi = (b.max_m[axis] * STEPS_PER_M).ceil() + GROWTH_STEPS as f64;
        if !(lo >= COORD_MIN as f64 && hi <= COORD_MAX as f64 && lo <= hi) {
            return None;
        }
        lower[axis] = lo as i32;
        upper[axis] = hi as i32;
    }
    Some((lower, upper))
}

/// A child as the unit holds it: box on the grid and reference.
type UnitChild = ([i32; 3], [i32; 3], u16);

/// The unit's copy of the engine's tree, each leaf of several primitives expanded into a
/// small subtree of one primitive a leaf, so that the unit hands back single primitives
/// (the HPS then tests only those not past its best hit) and the depth-first child order
/// still meets them in [`Bvh::primitive_order`], the software traversal's order.
struct UnitTreeBuilder<'a> {
    bvh: &'a Bvh,
    primitive_bounds: &'a [Aabb],
    nodes: Vec<UnitNode>,
}

impl UnitTreeBuilder<'_> {
    fn allocate(&mut self) -> Result<usize, UnitTreeError> {
        if self.nodes.len() == MAX_NODES {
            return Err(UnitTreeError::TooLarge {
                nodes: self.bvh.node_count(),
            });
        }
        self.nodes.push(UnitNode::default());
        Ok(self.nodes.len() - 1)
    }

    fn set(&mut self, index: usize, a: UnitChild, b: UnitChild) {
        self.nodes[index] = UnitNode {
            lower: [a.0, b.0],
            upper: [a.1, b.1],
            reference: [a.2, b.2],
        };
    }

    /// Engine node `i` as a child of a unit node.
    fn engine_child(&mut self, i: usize) -> Result<UnitChild, UnitTreeError> {
        let (bounds, offset, count) = self
            .bvh
            .node_parts(i)
            .ok_or(UnitTreeError::OutOfRange { node: i })?;
        if count > 0 {
            return self.primitives(i, offset as usize, count as usize);
        }
        let (lo, hi) = quantise_box(&bounds).ok_or(UnitTreeError::OutOfRange { node: i })?;
        let index = self.allocate()?;
        let first = self.engine_child(i + 1)?;
        let second = self.engine_child(offset as usize)?;
        self.set(index, first, second);
        Ok((lo, hi, REF_VALID | index as u16))
    }

    /// Positions `start..start + count` of the primitive order (in engine leaf `leaf`).
    fn primitives(
        &mut self,
        leaf: usize,
        start: usize,
        count: usize,
    ) -> Result<UnitChild, UnitTreeError> {
        if count == 1 {
            let bounds = self
                .bvh
                .primitive_order()
                .get(start)
                .and_then(|&p| self.primitive_bounds.get(p as usize))
                .ok_or(UnitTreeError::OutOfRange { node: leaf })?;
            let (lo, hi) = quantise_box(bounds).ok_or(UnitTreeError::OutOfRange { node: leaf })?;
            if start > REF_INDEX_MASK as usize {
                return Err(UnitTreeError::TooLarge {
                    nodes: self.bvh.node_count(),
                });
            }
            return Ok((lo, hi, REF_VALID | REF_LEAF | start as u16));
        }
        let index = self.allocate()?;
        let half = count / 2;
        let a = self.primitives(leaf, start, half)?;
        let b = self.primitives(leaf, start + half, count - half)?;
        self.set(index, a, b);
        let lo = std::array::from_fn(|k| a.0[k].min(b.0[k]));
        let hi = std::array::from_fn(|k| a.1[k].max(b.1[k]));
        Ok((lo, hi, REF_VALID | index as u16))
    }
}

/// The unit's node memory for `bvh` over primitives whose boxes are `primitive_bounds`:
/// node 0 holds the root as its child 0; a leaf refers to a position in
/// [`Bvh::primitive_order`], which the unit hands back.
pub fn unit_nodes(bvh: &Bvh, primitive_bounds: &[Aabb]) -> Result<Vec<NodeWords>, UnitTreeError> {
    if bvh.node_count() == 0 {
        return Err(UnitTreeError::Empty);
    }
    let mut builder = UnitTreeBuilder {
        bvh,
        primitive_bounds,
        nodes: Vec::new(),
    };
    let root = builder.allocate()?;
    let child = builder.engine_child(0)?;
    builder.set(root, child, ([0; 3], [0; 3], 0));
    Ok(builder.nodes.iter().map(UnitNode::pack).collect())
}

/// A ray's words for the unit (f32: the fabric quantises); `None` for a ray the unit's error
/// bound does not cover (a direction shorter than 1/2, non-finite values).
pub fn ray_words(ray: &Ray, t_min_m: f64, t_max_m: f64) -> Option<RayWords> {
    let d = ray.direction;
    let length = d.length();
    if !(length >= MIN_DIRECTION_LENGTH && length.is_finite() && ray.origin_m.is_finite()) {
        return None;
    }
    if t_min_m.is_nan() || t_max_m.is_nan() {
        return None;
    }
    let o = ray.origin_m;
    // `as f32` rounds to nearest (relative error 2^-24) and overflows to infinity, as the
    // bound assumes; 1/±0 is ±infinity, which the unit clamps.
    Some(
        RayF32 {
            origin_m: [o.x as f32, o.y as f32, o.z as f32],
            inverse_direction: [(1.0 / d.x) as f32, (1.0 / d.y) as f32, (1.0 / d.z) as f32],
            t_min_m: t_min_m as f32,
            t_max_m: t_max_m as f32,
        }
        .pack(),
    )
}

/// Counts of what the unit did.
#[derive(Debug, Default)]
pub struct BvhUnitStats {
    /// Rays the unit answered.
    pub rays: AtomicU64,
    /// Candidates it returned.
    pub candidates: AtomicU64,
    /// Rays it refused, or the HPS did not send (outside the error bound): software answered.
    pub refused: AtomicU64,
    /// Rays whose answer failed (backend error, malformed answer): software answered.
    pub failed: AtomicU64,
    /// Primitives the HPS tested exactly for the rays the unit answered.
    pub primitives: AtomicU64,
    /// Candidates near the interval's end checked with the f64 box test first, and of
    /// those, the ones it dropped.
    pub far_end_box_tests: AtomicU64,
    pub far_end_dropped: AtomicU64,
    /// Of those: closest-hit rays, and the primitives tested for them.
    pub closest_rays: AtomicU64,
    pub closest_primitives: AtomicU64,
}

/// The unit with its loaded tree.
pub struct BvhUnit {
    backend: Box<dyn BvhUnitBackend>,
    /// The primitives' own boxes, by primitive: the far-end check ([`FAR_END_M`]).
    primitive_bounds: Vec<Aabb>,
    pub stats: BvhUnitStats,
    /// The last backend error, kept so a caller can report the fault it survived.
    pub last_error: Mutex<Option<String>>,
}

impl std::fmt::Debug for BvhUnit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("BvhUnit")
            .field("stats", &self.stats)
            .finish()
    }
}

impl BvhUnit {
    /// Loads `bvh` (over primitives whose boxes are `primitive_bounds`) into `backend`.
    pub fn load(
        bvh: &Bvh,
        primitive_bounds: &[Aabb],
        mut backend: Box<dyn BvhUnitBackend>,
    ) -> Result<Self, UnitTreeError> {
        backend.load(&unit_nodes(bvh, primitive_bounds)?)?;
        Ok(Self {
            backend,
            primitive_bounds: primitive_bounds.to_vec(),
            stats: BvhUnitStats::default(),
            last_error: Mutex::new(None),
        })
    }

    /// The unit's candidates for one ray as (position in the primitive order, entry distance
    /// in metres), or
    /// `None` when software must answer it.
    fn candidates(
        &self,
        ray: &Ray,
        t_min_m: f64,
        t_max_m: f64,
        order: Order,
    ) -> Option<Vec<(usize, f64)>> {
        let Some(words) = ray_words(ray, t_min_m, t_max_m) else {
            self.stats.refused.fetch_add(1, Ordering::Relaxed);
            return None;
        };
        let mut answer = Vec::new();
        let outcome = self
            .backend
            .traverse(order, &words, &mut answer)
            .and_then(|()| check_answer(&answer));
        let end = match outcome {
            Ok(end) => end,
            Err(e) => {
                self.stats.failed.fetch_add(1, Ordering::Relaxed);
                if let Ok(mut last) = self.last_error.lock() {
                    *last = Some(e.to_string());
                }
                return None;
            }
        };
        if let ResultWord::End { refusal_code, .. } = unpack_result(end) {
            if refusal_code != 0 {
                self.stats.refused.fetch_add(1, Ordering::Relaxed);
                return None;
            }
        }
        self.stats.rays.fetch_add(1, Ordering::Relaxed);
        self.stats
            .candidates
            .fetch_add(answer.len() as u64 - 1, Ordering::Relaxed);
        Some(
            answer[..answer.len() - 1]
                .iter()
                .filter_map(|&w| match unpack_result(w) {
                    ResultWord::Candidate { candidate: c, .. } => Some((
                        c.leaf as usize,
                        (c.t_near as f64 * METRES_PER_STEP).max(t_min_m),
                    )),
                    ResultWord::End { .. } => None,
                })
                .collect(),
        )
    }

    /// Whether primitive `p`, a candidate at `entry_m`, needs no exact test: its conservative
    /// entry is within [`FAR_END_M`] of `end_m` and the f64 test of its own box misses
    /// `[t_min_m, end_m]`.
    fn beyond_end(&self, ray: &Ray, p: u32, entry_m: f64, t_min_m: f64, end_m: f64) -> bool {
        if entry_m < end_m - FAR_END_M {
            return false;
        }
        let Some(bounds) = self.primitive_bounds.get(p as usize) else {
            return false;
        };
        self.stats.far_end_box_tests.fetch_add(1, Ordering::Relaxed);
        let query = RayBoxQuery::new(ray, t_min_m, end_m);
        let beyond = SlabTest::entry(&query, bounds).is_none();
        if beyond {
            self.stats.far_end_dropped.fetch_add(1, Ordering::Relaxed);
        }
        beyond
    }

    /// [`Bvh::closest`] through the unit.
    pub fn closest<H>(
        &self,
        bvh: &Bvh,
        ray: &Ray,
        t_min_m: f64,
        t_max_m: f64,
        mut intersect: impl FnMut(u32, f64) -> Option<H>,
        distance: impl Fn(&H) -> f64,
    ) -> Option<H> {
        let Some(candidates) = self.candidates(ray, t_min_m, t_max_m, Order::NearFirst) else {
            return bvh.closest(&SlabTest, ray, t_min_m, t_max_m, intersect, distance);
        };
        let mut best: Option<H> = None;
        let mut best_t = t_max_m;
        let mut tested = 0;
        let order = bvh.primitive_order();
        for (position, entry_m) in candidates {
            if entry_m > best_t {
                continue;
            }
            let Some(&p) = order.get(position) else {
                continue;
            };
            if self.beyond_end(ray, p, entry_m, t_min_m, best_t) {
                continue;
            }
            tested += 1;
            if let Some(h) = intersect(p, best_t) {
                let t = distance(&h);
                if t < best_t {
                    best_t = t;
                    best = Some(h);
                }
            }
        }
        self.stats.primitives.fetch_add(tested, Ordering::Relaxed);
        self.stats.closest_rays.fetch_add(1, Ordering::Relaxed);
        self.stats
            .closest_primitives
            .fetch_add(tested, Ordering::Relaxed);
        best
    }

    /// [`Bvh::visit_crossed`] through the unit.
    pub fn visit_crossed(
        &self,
        bvh: &Bvh,
        ray: &Ray,
        t_min_m: f64,
        t_max_m: f64,
        mut visit: impl FnMut(u32) -> bool,
    ) {
        let Some(candidates) = self.candidates(ray, t_min_m, t_max_m, Order::ChildOrder) else {
            return bvh.visit_crossed(&SlabTest, ray, t_min_m, t_max_m, visit);
        };
        let mut tested = 0;
        let order = bvh.primitive_order();
        for (position, entry_m) in candidates {
            let Some(&p) = order.get(position) else {
                continue;
            };
            if self.beyond_end(ray, p, entry_m, t_min_m, t_max_m) {
                continue;
            }
            tested += 1;
            if !visit(p) {
                break;
            }
        }
        self.stats.primitives.fetch_add(tested, Ordering::Relaxed);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::rng::Rng;
    use crate::fpga::bvh_unit::GoldenBvhUnit;
    use glam::DVec3;
    use skylux_regmap::bvh_format::{child_test, grid_ray};

    fn random_direction(rng: &mut Rng) -> DVec3 {
        loop {
            let d = DVec3::new(rng.uniform(), rng.uniform(), rng.uniform()) * 2.0 - 1.0;
            let l = d.length();
            if l > 1e-3 && l <= 1.0 {
                return d / l;
            }
        }
    }

    /// The figure the issue asks for, in CI: over 10^7 random (ray, box) pairs the unit's
    /// test (f32 front end, grown box) never misses a box the f64 slab test hits, and never
    /// enters it later. The draws favour the hard cases: axis-parallel directions, flat and
    /// zero-size boxes, origins on a box's planes, and coordinates near the grid's edge.
    #[test]
    fn no_false_miss_over_ten_million_pairs() {
        let mut rng = Rng::for_stream(22, 4);
        let (mut hits, mut parallel, mut flat, mut edge) = (0u64, 0u64, 0u64, 0u64);
        for k in 0..10_000_000u64 {
            let scale_m = if k % 7 == 0 { 250.0 } else { 12.0 };
            let centre = (DVec3::new(rng.uniform(), rng.uniform(), rng.uniform()) * 2.0 - 1.0)
                * (scale_m - 2.0);
            let half = DVec3::new(rng.uniform(), rng.uniform(), rng.uniform())
                * if k % 5 == 0 { 0.0 } else { 2.0 };
            let mut b = Aabb {
                min_m: centre - half,
                max_m: centre + half,
            };
            if k % 11 == 0 {
                b.max_m.y = b.min_m.y; // flat
                flat += 1;
            }
            // Aim near the box (inside it, or just beside it) from a random origin.
            let spread = half * 1.3 + DVec3::splat(0.01);
            let target = centre
                + (DVec3::new(rng.uniform(), rng.uniform(), rng.uniform()) * 2.0 - 1.0) * spread;
            let mut o =
                (DVec3::new(rng.uniform(), rng.uniform(), rng.uniform()) * 2.0 - 1.0) * scale_m;
            if k % 13 == 0 {
                o.x = b.min_m.x; // on a plane
            }
            let mut d = target - o;
            if k % 3 == 0 {
                // Parallel to one or two axes, the ray staying in the target's planes.
                let a = (k / 3 % 3) as usize;
                d[a] = 0.0;
                o[a] = target[a];
                if k % 2 == 0 {
                    let a2 = (a + 1) % 3;
                    d[a2] = -0.0;
                    o[a2] = target[a2];
                }
                parallel += 1;
            }
            let d = if d.length() > 0.0 {
                d.normalize()
            } else {
                random_direction(&mut rng)
            };
            if scale_m > 100.0 {
                edge += 1;
            }
            let ray = Ray::new(o, d);
            let t_max = if k % 4 == 0 {
                f64::INFINITY
            } else {
                rng.uniform() * 40.0
            };
            let q = RayBoxQuery::new(&ray, 0.0, t_max);
            let Some(truth) = SlabTest::entry(&q, &b) else {
                continue;
            };
            hits += 1;
            let (lo, hi) = quantise_box(&b).expect("in range");
            let words = ray_words(&ray, 0.0, t_max).expect("unit direction");
            let g = grid_ray(&words).expect("representable");
            let (hit, t_near) = child_test(&g, &lo, &hi);
            assert!(hit, "false miss: {ray:?} {b:?} t_max {t_max} entry {truth}");
            assert!(
                t_near as f64 * METRES_PER_STEP <= truth,
                "late entry: {ray:?} {b:?}: {} > {truth}",
                t_near as f64 * METRES_PER_STEP
            );
        }
        assert!(
            hits > 3_000_000 && parallel > 3_000_000 && flat > 900_000 && edge > 1_000_000,
            "{hits} {parallel} {flat} {edge}"
        );
    }

    fn random_boxes(rng: &mut Rng, n: usize) -> Vec<Aabb> {
        (0..n)
            .map(|_| {
                let c = DVec3::new(rng.uniform(), rng.uniform(), rng.uniform()) * 10.0;
                let h = DVec3::new(rng.uniform(), rng.uniform(), rng.uniform()) * 0.6;
                Aabb {
                    min_m: c - h,
                    max_m: c + h,
                }
            })
            .collect()
    }

    /// Through the golden unit, both traversals give exactly the software's answers: the
    /// same closest hit, and the same crossed primitives in the same order.
    #[test]
    fn unit_traversals_equal_software() {
        let mut rng = Rng::for_stream(22, 5);
        let boxes = random_boxes(&mut rng, 300);
        let bvh = Bvh::build(&boxes);
        let unit = BvhUnit::load(&bvh, &boxes, Box::<GoldenBvhUnit>::default()).unwrap();
        for _ in 0..3000 {
            let o = DVec3::new(rng.uniform(), rng.uniform(), rng.uniform()) * 14.0 - 2.0;
            let ray = Ray::new(o, random_direction(&mut rng));
            let t_max = if rng.uniform() < 0.5 {
                1e9
            } else {
                6.0 * rng.uniform()
            };
            let q = RayBoxQuery::new(&ray, 0.0, t_max);
            let hit = |p: u32, tmax: f64| {
                SlabTest::entry(&q, &boxes[p as usize])
                    .filter(|t| *t < tmax)
                    .map(|t| (p, t))
            };
            let soft = bvh.closest(&SlabTest, &ray, 0.0, t_max, hit, |h| h.1);
            let via = unit.closest(&bvh, &ray, 0.0, t_max, hit, |h| h.1);
            assert_eq!(
                soft.map(|h| (h.0, h.1.to_bits())),
                via.map(|h| (h.0, h.1.to_bits()))
            );
            let crossed = |p: u32| SlabTest::entry(&q, &boxes[p as usize]).is_some();
            let (mut a, mut b) = (Vec::new(), Vec::new());
            bvh.visit_crossed(&SlabTest, &ray, 0.0, t_max, |p| {
                if crossed(p) {
                    a.push(p);
                }
                true
            });
            unit.visit_crossed(&bvh, &ray, 0.0, t_max, |p| {
                if crossed(p) {
                    b.push(p);
                }
                true
            });
            assert_eq!(a, b);
        }
        let s = &unit.stats;
        assert_eq!(s.rays.load(Ordering::Relaxed), 6000);
        assert_eq!(s.refused.load(Ordering::Relaxed), 0);
        assert_eq!(s.failed.load(Ordering::Relaxed), 0);
    }

    #[test]
    fn trees_the_unit_cannot_hold_are_refused() {
        let far = [Aabb {
            min_m: DVec3::splat(300.0),
            max_m: DVec3::splat(301.0),
        }];
        let e =
            BvhUnit::load(&Bvh::build(&far), &far, Box::<GoldenBvhUnit>::default()).unwrap_err();
        assert_eq!(e, UnitTreeError::OutOfRange { node: 0 });
        assert_eq!(unit_nodes(&Bvh::build(&[]), &[]), Err(UnitTreeError::Empty));
        let mut rng = Rng::for_stream(22, 6);
        let many = random_boxes(&mut rng, 2000);
        assert!(matches!(
            unit_nodes(&Bvh::build(&many), &many),
            Err(UnitTreeError::TooLarge { .. })
        ));
    }

    /// A backend that answers garbage: the engine answers in software and says why.
    #[test]
    fn a_faulty_backend_is_survived() {
        struct Garbage;
        impl BvhUnitBackend for Garbage {
            fn load(&mut self, _: &[NodeWords]) -> Result<(), BvhUnitError> {
                Ok(())
            }
            fn traverse(
                &self,
                _: Order,
                _: &RayWords,
                out: &mut Vec<u64>,
            ) -> Result<(), BvhUnitError> {
                out.push(0x1234);
                Ok(())
            }
        }
        let mut rng = Rng::for_stream(22, 7);
        let boxes = random_boxes(&mut rng, 20);
        let bvh = Bvh::build(&boxes);
        let unit = BvhUnit::load(&bvh, &boxes, Box::new(Garbage)).unwrap();
        let ray = Ray::new(DVec3::splat(-1.0), DVec3::ONE.normalize());
        let q = RayBoxQuery::new(&ray, 0.0, 1e9);
        let hit = |p: u32, tmax: f64| {
            SlabTest::entry(&q, &boxes[p as usize])
                .filter(|t| *t < tmax)
                .map(|t| (p, t))
        };
        let soft = bvh.closest(&SlabTest, &ray, 0.0, 1e9, hit, |h| h.1);
        assert_eq!(unit.closest(&bvh, &ray, 0.0, 1e9, hit, |h| h.1), soft);
        assert_eq!(unit.stats.failed.load(Ordering::Relaxed), 1);
        assert!(unit
            .last_error
            .lock()
            .unwrap()
            .as_ref()
            .unwrap()
            .contains("end word"));
    }
}
