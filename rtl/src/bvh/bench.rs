//! Driving [`BvhTraversal`]'s streams from Rust, for the tests here and the Verilog
//! cross-check in `skylux-bitstream` (one home for the node, ray and result protocols).

use super::BvhTraversal;
use crate::drive::Driver;
use rust_hdl::prelude::*;
use skylux_regmap::bvh_format::{
    Order, UnitNode, NODE_WORDS, RAY_WORDS, REF_LEAF, REF_VALID, RESULT_END_BIT,
};
use skylux_regmap::raybox_format::{COORD_MAX, COORD_MIN};

fn clock(d: &mut BvhTraversal) -> &mut Signal<In, Clock> {
    &mut d.clock
}

/// What a run saw.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Run {
    /// The result words, in order.
    pub words: Vec<u64>,
    /// Clocks from the first ray word offered to the last end word taken.
    pub cycles: u64,
}

/// A driven block, with garbage on the data inputs whenever their strobe is low (it must be
/// ignored).
pub struct BvhBench {
    pub driver: Driver<BvhTraversal>,
    noise: u64,
}

impl BvhBench {
    pub fn new(seed: u64) -> Self {
        BvhBench {
            driver: Driver::new(BvhTraversal::default()),
            noise: seed | 1,
        }
    }

    /// xorshift64 (Marsaglia 2003): garbage, not statistics.
    fn garbage(&mut self) -> u64 {
        self.noise ^= self.noise << 13;
        self.noise ^= self.noise >> 7;
        self.noise ^= self.noise << 17;
        self.noise
    }

    /// Idle inputs: strobes low, garbage on the data.
    fn quiet(&mut self) {
        let (a, b) = (self.garbage(), self.garbage());
        let d = &mut self.driver.dut;
        d.node_write.next = false;
        d.node_address.next = (a & 0x1FF).into();
        d.node_word.next = ((a >> 9) & 7).into();
        d.node_data.next = b.into();
        d.ray_valid.next = false;
        d.ray_data.next = a.rotate_left(17).into();
        d.result_ready.next = false;
    }

    fn cycle(&mut self) {
        self.driver.cycle(clock).expect("the traversal settles");
    }

    /// `n` clocks with every strobe low.
    pub fn idle(&mut self, n: usize) {
        for _ in 0..n {
            self.quiet();
            self.cycle();
        }
    }

    /// Writes node memory words: node `k` of `nodes` at address `k`, word by word.
    pub fn load(&mut self, nodes: &[[u64; NODE_WORDS]]) {
        for (k, words) in nodes.iter().enumerate() {
            for (w, &data) in words.iter().enumerate() {
                self.quiet();
                let d = &mut self.driver.dut;
                d.node_write.next = true;
                d.node_address.next = (k as u64).into();
                d.node_word.next = (w as u64).into();
                d.node_data.next = data.into();
                self.cycle();
            }
        }
    }

    /// The batch's configuration, held on the inputs.
    pub fn configure(&mut self, node_count: usize, order: Order) {
        let d = &mut self.driver.dut;
        d.node_count.next = (node_count as u64).into();
        d.order.next = order == Order::ChildOrder;
    }

    /// Streams `rays` in and reads results until every ray's end word is taken. Each clock,
    /// `offer()` says whether a ray word is offered (when one is left) and `ready()` whether
    /// a result is taken; `None` when `max_cycles` pass first.
    pub fn run(
        &mut self,
        rays: &[[u64; RAY_WORDS]],
        mut offer: impl FnMut() -> bool,
        mut ready: impl FnMut() -> bool,
        max_cycles: u64,
    ) -> Option<Run> {
        let words: Vec<u64> = rays.iter().flatten().copied().collect();
        let mut sent = 0;
        let mut ends = 0;
        let mut out = Run::default();
        while ends < rays.len() {
            if out.cycles == max_cycles {
                return None;
            }
            self.quiet();
            let d = &mut self.driver.dut;
            if sent < words.len() && offer() {
                d.ray_valid.next = true;
                d.ray_data.next = words[sent].into();
            }
            d.result_ready.next = ready();
            // The handshakes' outputs come from registers: sampled before the edge.
            self.driver.settle().expect("the traversal settles");
            let d = &self.driver.dut;
            if d.ray_valid.val() && d.ray_ready.val() {
                sent += 1;
            }
            if d.result_valid.val() && d.result_ready.val() {
                let w = d.result_data.val().to_u64();
                out.words.push(w);
                ends += (w >> RESULT_END_BIT) as usize;
            }
            self.cycle();
            out.cycles += 1;
        }
        Some(out)
    }

    pub fn busy(&self) -> bool {
        self.driver.dut.busy.val()
    }
}

// ---- trees for the tests ----------------------------------------------------------------

/// A grid box, inclusive corners.
pub type Aabb = ([i32; 3], [i32; 3]);

fn union(a: &Aabb, b: &Aabb) -> Aabb {
    (
        std::array::from_fn(|i| a.0[i].min(b.0[i])),
        std::array::from_fn(|i| a.1[i].max(b.1[i])),
    )
}

/// A real BVH over `leaves` (median split on the longest axis), laid out as the HPS does:
/// node 0 holds the root as its child 0, the others follow depth first.
pub fn build_tree(leaves: &[(u16, Aabb)]) -> Vec<UnitNode> {
    fn bounds(items: &[(u16, Aabb)]) -> Aabb {
        items[1..].iter().fold(items[0].1, |b, it| union(&b, &it.1))
    }
    /// Writes the subtree over `items` and returns its reference.
    fn place(items: &mut [(u16, Aabb)], nodes: &mut Vec<UnitNode>) -> u16 {
        if items.len() == 1 {
            return REF_VALID | REF_LEAF | items[0].0;
        }
        let b = bounds(items);
        let axis = (0..3).max_by_key(|&a| b.1[a] - b.0[a]).unwrap();
        items.sort_by_key(|it| it.1 .0[axis] as i64 + it.1 .1[axis] as i64);
        let index = nodes.len();
        nodes.push(UnitNode::default());
        let (left, right) = items.split_at_mut(items.len() / 2);
        let (lb, rb) = (bounds(left), bounds(right));
        let l = place(left, nodes);
        let r = place(right, nodes);
        nodes[index] = UnitNode {
            lower: [lb.0, rb.0],
            upper: [lb.1, rb.1],
            reference: [l, r],
        };
        REF_VALID | index as u16
    }
    let mut items = leaves.to_vec();
    let root_box = bounds(&items);
    let mut nodes = vec![UnitNode::default()];
    let root = place(&mut items, &mut nodes);
    nodes[0] = UnitNode {
        lower: [root_box.0, [0; 3]],
        upper: [root_box.1, [0; 3]],
        reference: [root, 0],
    };
    nodes
}

/// Every node pushes a leaf and descends, `depth` deep: deeper than the stack overflows.
pub fn chain(depth: usize) -> Vec<UnitNode> {
    (0..depth as u16)
        .map(|i| UnitNode {
            lower: [[COORD_MIN; 3]; 2],
            upper: [[COORD_MAX; 3]; 2],
            reference: [REF_VALID | (i + 1), REF_VALID | REF_LEAF | i],
        })
        .chain([UnitNode {
            lower: [[COORD_MIN; 3]; 2],
            upper: [[COORD_MAX; 3]; 2],
            reference: [REF_VALID | REF_LEAF | 0x3fff, REF_VALID | REF_LEAF | 7],
        }])
        .collect()
}

/// A ring of `len` nodes, each writing a leaf and going on to the next: one visit too many.
pub fn ring(len: usize) -> Vec<UnitNode> {
    (0..len as u16)
        .map(|i| UnitNode {
            lower: [[COORD_MIN; 3]; 2],
            upper: [[COORD_MAX; 3]; 2],
            reference: [REF_VALID | REF_LEAF | i, REF_VALID | ((i + 1) % len as u16)],
        })
        .collect()
}
