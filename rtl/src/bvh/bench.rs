//! Driving the traversal blocks' streams from Rust ([`BvhTraversal`], one ray in flight, and
//! [`BvhInterleaved`], several; same ports), for the tests here, the Verilog cross-check in
//! `skylux-bitstream` and the bench (one home for the node, ray and result protocols).

use super::{BvhInterleaved, BvhTraversal};
use crate::drive::Driver;
use rust_hdl::prelude::*;
use skylux_regmap::bvh_format::{
    Order, UnitNode, NODE_WORDS, RAY_WORDS, REF_LEAF, REF_VALID, RESULT_END_BIT,
};
use skylux_regmap::raybox_format::{COORD_MAX, COORD_MIN};

/// The ports both traversal blocks have.
pub struct BvhIo<'a> {
    pub clock: &'a mut Signal<In, Clock>,
    pub node_write: &'a mut Signal<In, Bit>,
    pub node_address: &'a mut Signal<In, Bits<9>>,
    pub node_word: &'a mut Signal<In, Bits<3>>,
    pub node_data: &'a mut Signal<In, Bits<64>>,
    pub node_count: &'a mut Signal<In, Bits<10>>,
    pub order: &'a mut Signal<In, Bit>,
    pub ray_valid: &'a mut Signal<In, Bit>,
    pub ray_data: &'a mut Signal<In, Bits<64>>,
    pub ray_ready: &'a mut Signal<Out, Bit>,
    pub result_valid: &'a mut Signal<Out, Bit>,
    pub result_data: &'a mut Signal<Out, Bits<64>>,
    pub result_ready: &'a mut Signal<In, Bit>,
    pub busy: &'a mut Signal<Out, Bit>,
}

/// A traversal block the bench drives.
pub trait BvhBlock: Block + Default {
    fn io(&mut self) -> BvhIo<'_>;
}

macro_rules! bvh_block {
    ($t:ty) => {
        impl BvhBlock for $t {
            fn io(&mut self) -> BvhIo<'_> {
                BvhIo {
                    clock: &mut self.clock,
                    node_write: &mut self.node_write,
                    node_address: &mut self.node_address,
                    node_word: &mut self.node_word,
                    node_data: &mut self.node_data,
                    node_count: &mut self.node_count,
                    order: &mut self.order,
                    ray_valid: &mut self.ray_valid,
                    ray_data: &mut self.ray_data,
                    ray_ready: &mut self.ray_ready,
                    result_valid: &mut self.result_valid,
                    result_data: &mut self.result_data,
                    result_ready: &mut self.result_ready,
                    busy: &mut self.busy,
                }
            }
        }
    };
}
bvh_block!(BvhTraversal);
bvh_block!(BvhInterleaved);

fn clock<B: BvhBlock>(d: &mut B) -> &mut Signal<In, Clock> {
    d.io().clock
}

/// What a run saw.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Run {
    /// The result words, in order.
    pub words: Vec<u64>,
    /// Each ray's tag, by `bvh_format`'s rule as a HPS sees it: 0 when every end word of the
    /// rays sent before was taken on an earlier clock than the ray's first word (the block
    /// was idle), else one more than the ray before's, modulo 256.
    pub tags: Vec<u8>,
    /// Clocks from the first ray word offered to the last end word taken.
    pub cycles: u64,
}

/// A driven block, with garbage on the data inputs whenever their strobe is low (it must be
/// ignored).
pub struct Bench<B: BvhBlock> {
    pub driver: Driver<B>,
    noise: u64,
}

/// The bench of the unit's block (the one exported to Verilog).
pub type BvhBench = Bench<BvhInterleaved>;

impl<B: BvhBlock> Bench<B> {
    pub fn new(seed: u64) -> Self {
        Bench {
            driver: Driver::new(B::default()),
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
        let d = self.driver.dut.io();
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
                let d = self.driver.dut.io();
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
        let d = self.driver.dut.io();
        d.node_count.next = (node_count as u64).into();
        d.order.next = order == Order::ChildOrder;
    }

    /// Streams `rays` in and reads results until every ray's end word is taken (the block
    /// idle before: the first ray's tag is 0). Each clock,
    /// `offer()` says whether a ray word is offered (when one is left) and `ready()` whether
    /// a result is taken; `None` when `max_cycles` pass first.
    pub fn run(
        &mut self,
        rays: &[[u64; RAY_WORDS]],
        offer: impl FnMut() -> bool,
        ready: impl FnMut() -> bool,
        max_cycles: u64,
    ) -> Option<Run> {
        self.run_observed(rays, offer, ready, max_cycles, |_| {})
    }

    /// [`Self::run`], showing the settled block to `observe` each clock before its edge.
    pub fn run_observed(
        &mut self,
        rays: &[[u64; RAY_WORDS]],
        mut offer: impl FnMut() -> bool,
        mut ready: impl FnMut() -> bool,
        max_cycles: u64,
        mut observe: impl FnMut(&B),
    ) -> Option<Run> {
        let words: Vec<u64> = rays.iter().flatten().copied().collect();
        let mut sent = 0;
        let mut ends = 0;
        let mut next_tag = 0u8;
        let mut out = Run::default();
        while ends < rays.len() {
            if out.cycles == max_cycles {
                return None;
            }
            self.quiet();
            let d = self.driver.dut.io();
            if sent < words.len() && offer() {
                d.ray_valid.next = true;
                d.ray_data.next = words[sent].into();
            }
            d.result_ready.next = ready();
            // The handshakes' outputs come from registers: sampled before the edge.
            self.driver.settle().expect("the traversal settles");
            let d = self.driver.dut.io();
            if d.ray_valid.val() && d.ray_ready.val() {
                if sent % RAY_WORDS == 0 {
                    // Ends taken before this clock: all rays sent so far answered.
                    if ends == sent / RAY_WORDS {
                        next_tag = 0;
                    }
                    out.tags.push(next_tag);
                    next_tag = next_tag.wrapping_add(1);
                }
                sent += 1;
            }
            if d.result_valid.val() && d.result_ready.val() {
                let w = d.result_data.val().to_u64();
                out.words.push(w);
                ends += (w >> RESULT_END_BIT) as usize;
            }
            observe(&self.driver.dut);
            self.cycle();
            out.cycles += 1;
        }
        Some(out)
    }

    pub fn busy(&mut self) -> bool {
        self.driver.dut.io().busy.val()
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
