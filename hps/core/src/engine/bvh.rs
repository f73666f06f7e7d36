//! Bounding volume hierarchy: binned surface-area-heuristic build and flattened depth-first
//! layout as in pbrt-v4 (`BVHAggregate`, Pharr, Jakob & Humphreys, *Physically Based
//! Rendering*, 4th ed., §7.3), with every box test going through [`BoxTest`].

use super::ray::{Ray, RayBoxQuery};
use super::slab::{Aabb, BoxTest, TraversalKind};

/// Most primitives in a leaf; a leaf is also made when splitting would cost more (SAH).
const MAX_LEAF_PRIMITIVES: usize = 4;
/// SAH bins per axis (pbrt-v4 uses 12).
const SAH_BINS: usize = 12;
/// Cost of one box test relative to one primitive test, in the SAH (pbrt-v4: 1/2 traversal).
const TRAVERSAL_COST: f64 = 0.5;

/// One node of the flattened tree: the first child of an interior node follows it directly,
/// `offset` is the second child; a leaf holds `count` primitives from `offset` in
/// [`Bvh::primitive_order`]. `u32` indices keep nodes compact on the 32-bit target.
#[derive(Clone, Copy, Debug)]
struct Node {
    bounds: Aabb,
    offset: u32,
    count: u32,
}

/// Counts of a tree's shape ([`Bvh::shape`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BvhShape {
    pub leaves: usize,
    pub max_depth: usize,
}

/// A BVH over primitives given by their boxes.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    order: Vec<u32>,
    /// Most primitives in a leaf.
    max_leaf: usize,
}

impl Bvh {
    /// Builds the tree over `bounds[i]` for each primitive `i`.
    pub fn build(bounds: &[Aabb]) -> Self {
        Self::build_with_leaf_size(bounds, MAX_LEAF_PRIMITIVES)
    }

    /// [`Bvh::build`] with at most `max_leaf` primitives a leaf (1: every leaf box is one
    /// primitive's: the tree a ray unit would traverse to hand the HPS single candidates).
    pub fn build_with_leaf_size(bounds: &[Aabb], max_leaf: usize) -> Self {
        let mut items: Vec<(u32, Aabb, glam::DVec3)> = bounds
            .iter()
            .enumerate()
            .map(|(i, b)| (i as u32, *b, b.centre_m()))
            .collect();
        let mut bvh = Bvh {
            nodes: Vec::with_capacity(2 * bounds.len()),
            order: Vec::with_capacity(bounds.len()),
            max_leaf: max_leaf.max(1),
        };
        if !items.is_empty() {
            bvh.build_node(&mut items);
        }
        bvh
    }

    /// Primitive indices in leaf order.
    pub fn primitive_order(&self) -> &[u32] {
        &self.order
    }

    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// Node `i` as (bounds, offset, count): an interior node (count 0) has its first child
    /// at `i + 1` and its second at `offset`; a leaf holds `count` primitives from `offset`
    /// of [`Bvh::primitive_order`]. For building a ray unit's copy of the tree.
    pub fn node_parts(&self, i: usize) -> Option<(Aabb, u32, u32)> {
        self.nodes.get(i).map(|n| (n.bounds, n.offset, n.count))
    }

    /// The primitives of leaf node `i` (none for an interior node or an index past the end).
    pub fn leaf_primitives(&self, i: usize) -> &[u32] {
        match self.nodes.get(i) {
            Some(n) if n.count > 0 => self
                .order
                .get(n.offset as usize..(n.offset + n.count) as usize)
                .unwrap_or(&[]),
            _ => &[],
        }
    }

    /// Leaves, and the deepest leaf's depth (the root at depth 0): what a traversal in the
    /// fabric must hold (its node memory and its per-ray stack).
    pub fn shape(&self) -> BvhShape {
        let mut shape = BvhShape::default();
        let mut stack = vec![(0usize, 0usize)];
        while let Some((n, depth)) = stack.pop() {
            let Some(node) = self.nodes.get(n) else {
                continue;
            };
            if node.count > 0 {
                shape.leaves += 1;
                shape.max_depth = shape.max_depth.max(depth);
            } else {
                stack.push((n + 1, depth + 1));
                stack.push((node.offset as usize, depth + 1));
            }
        }
        shape
    }

    fn build_node(&mut self, items: &mut [(u32, Aabb, glam::DVec3)]) -> usize {
        let index = self.nodes.len();
        let bounds = items.iter().fold(Aabb::EMPTY, |b, it| b.union(it.1));
        self.nodes.push(Node {
            bounds,
            offset: 0,
            count: 0,
        });
        let make_leaf = |bvh: &mut Bvh, items: &[(u32, Aabb, glam::DVec3)]| {
            bvh.nodes[index].offset = bvh.order.len() as u32;
            bvh.nodes[index].count = items.len() as u32;
            bvh.order.extend(items.iter().map(|it| it.0));
            index
        };
        if items.len() <= 1 {
            return make_leaf(self, items);
        }
        let centroids = Aabb::from_points(items.iter().map(|it| it.2));
        let extent = centroids.max_m - centroids.min_m;
        let axis = if extent.x >= extent.y && extent.x >= extent.z {
            0
        } else if extent.y >= extent.z {
            1
        } else {
            2
        };
        if extent[axis].partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            // All centroids coincide: no split separates them.
            if items.len() <= self.max_leaf {
                return make_leaf(self, items);
            }
            let mid = items.len() / 2;
            return self.split_at(index, items, mid);
        }
        // Binned SAH (pbrt-v4 §7.3.2): cost of splitting after each bin.
        let lo = centroids.min_m[axis];
        let bin_of =
            |c: f64| (((c - lo) / extent[axis] * SAH_BINS as f64) as usize).min(SAH_BINS - 1);
        let mut bins = [(0usize, Aabb::EMPTY); SAH_BINS];
        for it in items.iter() {
            let b = &mut bins[bin_of(it.2[axis])];
            b.0 += 1;
            b.1 = b.1.union(it.1);
        }
        let mut best = (f64::INFINITY, 0usize);
        for split in 0..SAH_BINS - 1 {
            let (mut n0, mut b0, mut n1, mut b1) = (0, Aabb::EMPTY, 0, Aabb::EMPTY);
            for (i, bin) in bins.iter().enumerate() {
                if i <= split {
                    n0 += bin.0;
                    b0 = b0.union(bin.1);
                } else {
                    n1 += bin.0;
                    b1 = b1.union(bin.1);
                }
            }
            if n0 == 0 || n1 == 0 {
                continue;
            }
            let cost = n0 as f64 * b0.surface_area_m2() + n1 as f64 * b1.surface_area_m2();
            if cost < best.0 {
                best = (cost, split);
            }
        }
        let area = bounds.surface_area_m2().max(f64::MIN_POSITIVE);
        let split_cost = TRAVERSAL_COST + best.0 / area;
        if items.len() <= self.max_leaf && split_cost >= items.len() as f64 {
            return make_leaf(self, items);
        }
        if best.0.is_infinite() {
            let mid = items.len() / 2;
            items.sort_by(|a, b| a.2[axis].total_cmp(&b.2[axis]));
            return self.split_at(index, items, mid);
        }
        let mut mid = 0;
        for i in 0..items.len() {
            if bin_of(items[i].2[axis]) <= best.1 {
                items.swap(i, mid);
                mid += 1;
            }
        }
        self.split_at(index, items, mid)
    }

    fn split_at(
        &mut self,
        index: usize,
        items: &mut [(u32, Aabb, glam::DVec3)],
        mid: usize,
    ) -> usize {
        let (left, right) = items.split_at_mut(mid);
        self.build_node(left);
        let second = self.build_node(right);
        self.nodes[index].offset = second as u32;
        index
    }

    /// The closest primitive hit along `ray` within `[t_min_m, t_max_m]`.
    ///
    /// `intersect(primitive, t_max_m)` tests one primitive and returns its hit closer than
    /// `t_max_m`; `distance` reads a hit's distance. Box tests go through `boxes`.
    /// Generic over the box test, so the software slab test is inlined into the traversal
    /// (through `dyn BoxTest` every node pair was an indirect call: a fifth of the time).
    pub fn closest<H, T: BoxTest + ?Sized>(
        &self,
        boxes: &T,
        ray: &Ray,
        t_min_m: f64,
        t_max_m: f64,
        mut intersect: impl FnMut(u32, f64) -> Option<H>,
        distance: impl Fn(&H) -> f64,
    ) -> Option<H> {
        let root = self.nodes.first()?;
        boxes.traversal_begins(TraversalKind::Closest, ray, t_min_m, t_max_m);
        let mut query = RayBoxQuery::new(ray, t_min_m, t_max_m);
        let mut entry = [f64::INFINITY; 2];
        boxes.hits(&query, std::slice::from_ref(&root.bounds), &mut entry[..1]);
        if entry[0].is_infinite() {
            return None;
        }
        let mut best: Option<H> = None;
        // Depth is at most about 2 log2(n) + bins; 64 is ample, and the stack grows if needed.
        // A fixed array on the machine stack (no allocation per ray); a deeper tree spills
        // into `spill`.
        let mut stack = [(0u32, 0.0f64); 64];
        let mut depth = 0usize;
        let mut spill: Vec<(u32, f64)> = Vec::new();
        let mut current = 0usize;
        loop {
            let node = self.nodes[current];
            if node.count > 0 {
                boxes.leaf_reached(node.count as usize);
                let start = node.offset as usize;
                for &p in &self.order[start..start + node.count as usize] {
                    if let Some(h) = intersect(p, query.t_max_m) {
                        let t = distance(&h);
                        if t < query.t_max_m {
                            query.t_max_m = t;
                            best = Some(h);
                        }
                    }
                }
            } else {
                let first = current + 1;
                let second = node.offset as usize;
                let pair = [self.nodes[first].bounds, self.nodes[second].bounds];
                boxes.hits(&query, &pair, &mut entry);
                match (entry[0].is_finite(), entry[1].is_finite()) {
                    (true, true) => {
                        let (near, far, far_t) = if entry[0] <= entry[1] {
                            (first, second, entry[1])
                        } else {
                            (second, first, entry[0])
                        };
                        if depth < stack.len() {
                            stack[depth] = (far as u32, far_t);
                            depth += 1;
                        } else {
                            spill.push((far as u32, far_t));
                        }
                        current = near;
                        continue;
                    }
                    (true, false) => {
                        current = first;
                        continue;
                    }
                    (false, true) => {
                        current = second;
                        continue;
                    }
                    (false, false) => {}
                }
            }
            // Pop the next node still closer than the best hit.
            loop {
                let popped = if let Some(x) = spill.pop() {
                    Some(x)
                } else if depth > 0 {
                    depth -= 1;
                    Some(stack[depth])
                } else {
                    None
                };
                match popped {
                    None => return best,
                    Some((n, t)) if t <= query.t_max_m => {
                        current = n as usize;
                        break;
                    }
                    Some(_) => {}
                }
            }
        }
    }
}

impl Bvh {
    /// Every primitive whose box the ray crosses within `[t_min_m, t_max_m]`, in no
    /// particular order, handed to `visit` until it returns false: the traversal for shadow
    /// rays, whose answer (a product of transmissions, or 0 at the first opaque surface)
    /// does not depend on the order, so one traversal replaces one closest-hit query per
    /// crossed pane. Box tests go through `boxes`.
    pub fn visit_crossed<T: BoxTest + ?Sized>(
        &self,
        boxes: &T,
        ray: &Ray,
        t_min_m: f64,
        t_max_m: f64,
        mut visit: impl FnMut(u32) -> bool,
    ) {
        let Some(root) = self.nodes.first() else {
            return;
        };
        boxes.traversal_begins(TraversalKind::Crossed, ray, t_min_m, t_max_m);
        let query = RayBoxQuery::new(ray, t_min_m, t_max_m);
        let mut entry = [f64::INFINITY; 2];
        boxes.hits(&query, std::slice::from_ref(&root.bounds), &mut entry[..1]);
        if entry[0].is_infinite() {
            return;
        }
        let mut stack = [0u32; 64];
        let mut depth = 0usize;
        let mut spill: Vec<u32> = Vec::new();
        let mut current = 0usize;
        loop {
            let node = self.nodes[current];
            let mut next = None;
            if node.count > 0 {
                boxes.leaf_reached(node.count as usize);
                let start = node.offset as usize;
                for &p in &self.order[start..start + node.count as usize] {
                    if !visit(p) {
                        return;
                    }
                }
            } else {
                let first = current + 1;
                let second = node.offset as usize;
                let pair = [self.nodes[first].bounds, self.nodes[second].bounds];
                boxes.hits(&query, &pair, &mut entry);
                match (entry[0].is_finite(), entry[1].is_finite()) {
                    (true, true) => {
                        if depth < stack.len() {
                            stack[depth] = second as u32;
                            depth += 1;
                        } else {
                            spill.push(second as u32);
                        }
                        next = Some(first);
                    }
                    (true, false) => next = Some(first),
                    (false, true) => next = Some(second),
                    (false, false) => {}
                }
            }
            current = match next {
                Some(n) => n,
                None => match spill.pop() {
                    Some(n) => n as usize,
                    None if depth > 0 => {
                        depth -= 1;
                        stack[depth] as usize
                    }
                    None => return,
                },
            };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::rng::Rng;
    use crate::engine::slab::SlabTest;
    use glam::DVec3;

    /// `n` boxes with centres in a 10 m cube and half-sizes up to `half_m`, standing in for
    /// primitives.
    fn random_boxes(rng: &mut Rng, n: usize, half_m: f64) -> Vec<Aabb> {
        (0..n)
            .map(|_| {
                let c = DVec3::new(rng.uniform(), rng.uniform(), rng.uniform()) * 10.0;
                let h = DVec3::new(rng.uniform(), rng.uniform(), rng.uniform()) * half_m;
                Aabb {
                    min_m: c - h,
                    max_m: c + h,
                }
            })
            .collect()
    }

    /// A ray from a point in a 14 m cube around the boxes, in a random direction.
    fn random_ray(rng: &mut Rng) -> Ray {
        let o = DVec3::new(rng.uniform(), rng.uniform(), rng.uniform()) * 14.0 - 2.0;
        let d = (DVec3::new(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5).normalize();
        Ray::new(o, d)
    }

    /// Random small boxes standing in for primitives: the BVH must find exactly the closest
    /// hit a brute-force loop finds.
    #[test]
    fn matches_brute_force() {
        let mut rng = Rng::for_stream(11, 0);
        let boxes = random_boxes(&mut rng, 300, 0.5);
        let bvh = Bvh::build(&boxes);
        let mut sorted = bvh.primitive_order().to_vec();
        sorted.sort();
        assert_eq!(sorted, (0..300).collect::<Vec<u32>>());
        for _ in 0..500 {
            let ray = random_ray(&mut rng);
            let q = RayBoxQuery::new(&ray, 0.0, 1e9);
            let brute = boxes
                .iter()
                .enumerate()
                .filter_map(|(i, b)| SlabTest::entry(&q, b).map(|t| (i as u32, t)))
                .min_by(|a, b| a.1.total_cmp(&b.1));
            let fast = bvh.closest(
                &SlabTest,
                &ray,
                0.0,
                1e9,
                |p, tmax| {
                    SlabTest::entry(&q, &boxes[p as usize])
                        .filter(|t| *t < tmax)
                        .map(|t| (p, t))
                },
                |h| h.1,
            );
            assert_eq!(brute.map(|h| h.1), fast.map(|h| h.1));
        }
    }

    /// The unordered traversal offers exactly the primitives whose boxes the ray crosses.
    #[test]
    fn visit_crossed_offers_every_crossed_box() {
        let mut rng = Rng::for_stream(12, 0);
        let boxes = random_boxes(&mut rng, 200, 0.7);
        let bvh = Bvh::build(&boxes);
        for _ in 0..300 {
            let ray = random_ray(&mut rng);
            let t_max = 8.0 * rng.uniform();
            let q = RayBoxQuery::new(&ray, 0.0, t_max);
            let mut brute: Vec<u32> = (0..boxes.len() as u32)
                .filter(|&i| SlabTest::entry(&q, &boxes[i as usize]).is_some())
                .collect();
            let mut offered = Vec::new();
            bvh.visit_crossed(&SlabTest, &ray, 0.0, t_max, |p| {
                if SlabTest::entry(&q, &boxes[p as usize]).is_some() {
                    offered.push(p);
                }
                true
            });
            offered.sort();
            brute.sort();
            assert_eq!(offered, brute);
        }
        // Stopping early stops.
        let ray = Ray::new(DVec3::splat(-1.0), DVec3::ONE.normalize());
        let mut n = 0;
        bvh.visit_crossed(&SlabTest, &ray, 0.0, 1e9, |_| {
            n += 1;
            false
        });
        assert!(n <= 1);
    }

    #[test]
    fn empty_tree_hits_nothing() {
        let bvh = Bvh::build(&[]);
        let ray = Ray::new(DVec3::ZERO, DVec3::Z);
        assert!(bvh
            .closest(&SlabTest, &ray, 0.0, 1.0, |_, _| Some(0.5), |t| *t)
            .is_none());
    }
}
