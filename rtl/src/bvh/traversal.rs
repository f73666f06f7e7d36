//! The traversal core: the node memory, one ray in flight through two slab lanes (one per
//! child), the per-ray stack and a small output FIFO. Its output is
//! `skylux_regmap::bvh_format::result_words` (format v2: tagged words, candidates streamed
//! as found), word for word.

use super::front::{RayFrontEnd, CB3, MB3, SB3};
use crate::raybox::SlabLane;
use rust_hdl::prelude::*;
use skylux_regmap::bvh_format::{
    Refusal, CANDIDATE_TAG_SHIFT, END_TAG_SHIFT, MAX_NODES, NODE_INDEX_BITS, NODE_WORDS, RAY_WORDS,
    REF_INDEX_MASK, REF_LEAF, REF_VALID, RESULT_END_BIT, STACK_DEPTH, TAG_BITS,
};
use skylux_regmap::raybox_format::T_BITS;

const TB: usize = T_BITS as usize;
/// Width of a node address (`bvh_format::NODE_INDEX_BITS`).
pub const NODE_ADDRESS_BITS: usize = NODE_INDEX_BITS as usize;
/// Width of `node_count`: 0 to `MAX_NODES` inclusive.
pub const NODE_COUNT_BITS: usize = NODE_ADDRESS_BITS + 1;
/// Width of a reference's index (`REF_INDEX_MASK`).
const INDEX_BITS: usize = 14;
const STACK_ADDRESS_BITS: usize = 5;
/// Width of the stack pointer: 0 to `STACK_DEPTH` inclusive.
const SP_BITS: usize = STACK_ADDRESS_BITS + 1;
/// A stack entry: `[31:0]` t_near, `[47:32]` reference; its bits [45:0] are a candidate
/// word's.
const ENTRY_BITS: usize = 48;
/// The output FIFO holds 2^4 words: candidates stream out as found (format v2), so it only
/// smooths the reader's pauses; the traversal waits while it is full.
pub const RESULT_BUFFER_BITS: usize = 4;
const POINTER_BITS: usize = RESULT_BUFFER_BITS + 1;
/// Width of a ray's tag (`bvh_format::TAG_BITS`).
const TAG_WIDTH: usize = TAG_BITS as usize;
/// A FIFO word: the result word's bits [53:0] (a candidate's fields and tag; an end word's
/// use [47:0]), and the end bit at 54.
const RESULT_BITS: usize = 55;
/// A ray writes at most 2 × `MAX_NODES` candidates (each visit takes at most one child and
/// pushes at most one), under 2^11.
const CANDIDATE_COUNT_BITS: usize = 11;

// The field positions below are written for these formats.
const _: () = assert!(
    NODE_WORDS == 5
        && RAY_WORDS == 4
        && STACK_DEPTH == 1 << STACK_ADDRESS_BITS
        && MAX_NODES == 1 << NODE_ADDRESS_BITS
        && REF_VALID == 1 << 15
        && REF_LEAF == 1 << 14
        && REF_INDEX_MASK as usize == (1 << INDEX_BITS) - 1
        && RESULT_END_BIT == 63
        && CANDIDATE_TAG_SHIFT == 46
        && END_TAG_SHIFT == 40
        && TAG_WIDTH == 8
        && 2 * MAX_NODES < 1 << CANDIDATE_COUNT_BITS
        && TB == 32,
    "the traversal follows skylux_regmap::bvh_format"
);

#[derive(Copy, Clone, PartialEq, Eq, Debug, LogicState)]
pub enum TraversalState {
    /// Waiting for a whole ray.
    Idle,
    /// The node `current` is on the node memory's outputs: check it, send both children to
    /// the lanes.
    Visit,
    /// Waiting for the lanes; then the node's decision (push, descend, write a leaf).
    Test,
    /// Taking the stack's top: a leaf is written, a node visited; an empty stack ends the ray.
    Pop,
    /// Writing the ray's end word.
    EndWord,
}

/// The BVH traversal core.
///
/// - Node memory: `node_write` writes `node_data` as word `node_word` (0 to 4) of node
///   `node_address` (`bvh_format` node layout; the magic byte is not kept). Load it while the
///   unit is idle (`busy` low).
/// - `node_count` (at most `MAX_NODES`; larger values count as `MAX_NODES`) and `order` (0
///   near-first, 1 child order) are sampled when a ray starts.
/// - Rays: `RAY_WORDS` words on `ray_data`, each taken on a clock with `ray_valid` and
///   `ray_ready` high. The next ray is taken while one is traversed.
/// - Results: `result_data` is valid with `result_valid` and taken with `result_ready`.
///   A ray's candidates go out as found, then its end word (counting them, refused or not),
///   each word with the ray's tag: the output is `result_words` exactly.
/// - Tags: `tag_count` restarts at 0 on every clock `busy` is low and counts the rays taken
///   (`bvh_format`'s rule).
///
/// Timing (one ray in flight): a node visit takes `VISIT_CYCLES` clocks (the node memory is
/// read at the address of the next visit, so only the lanes' `LANE_LATENCY` adds), an entry
/// taken from the stack one clock, a ray 3 more (its start, the empty stack, its end word).
/// The next ray's words are taken during the traversal; a word leaves 2 clocks after it is
/// written.
#[derive(LogicBlock)]
pub struct BvhTraversal {
    pub clock: Signal<In, Clock>,
    pub node_write: Signal<In, Bit>,
    pub node_address: Signal<In, Bits<NODE_ADDRESS_BITS>>,
    pub node_word: Signal<In, Bits<3>>,
    pub node_data: Signal<In, Bits<64>>,
    pub node_count: Signal<In, Bits<NODE_COUNT_BITS>>,
    pub order: Signal<In, Bit>,
    pub ray_valid: Signal<In, Bit>,
    pub ray_data: Signal<In, Bits<64>>,
    pub ray_ready: Signal<Out, Bit>,
    pub result_valid: Signal<Out, Bit>,
    pub result_data: Signal<Out, Bits<64>>,
    pub result_ready: Signal<In, Bit>,
    /// A ray is being received or traversed, or results wait to be read.
    pub busy: Signal<Out, Bit>,

    front: RayFrontEnd,
    lanes: [SlabLane; 2],
    // Node memory, one RAM per word so a node is read in one clock.
    lower0: RAM<Bits<CB3>, NODE_ADDRESS_BITS>,
    upper0: RAM<Bits<CB3>, NODE_ADDRESS_BITS>,
    lower1: RAM<Bits<CB3>, NODE_ADDRESS_BITS>,
    upper1: RAM<Bits<CB3>, NODE_ADDRESS_BITS>,
    references: RAM<Bits<32>, NODE_ADDRESS_BITS>,
    stack: RAM<Bits<ENTRY_BITS>, STACK_ADDRESS_BITS>,
    results: RAM<Bits<RESULT_BITS>, RESULT_BUFFER_BITS>,

    // The ray being received.
    ray_word0: DFF<Bits<64>>,
    ray_word1: DFF<Bits<64>>,
    ray_word2: DFF<Bits<64>>,
    ray_word3: DFF<Bits<64>>,
    ray_word_index: DFF<Bits<2>>,
    ray_full: DFF<Bit>,
    // The ray being traversed, in grid form.
    origin: DFF<Bits<CB3>>,
    mant: DFF<Bits<MB3>>,
    shift: DFF<Bits<SB3>>,
    t_min: DFF<Bits<TB>>,
    t_max: DFF<Bits<TB>>,
    lower_is_entry: DFF<Bits<CB3>>,
    near_first: DFF<Bit>,
    node_limit: DFF<Bits<NODE_COUNT_BITS>>,
    // Traversal.
    state: DFF<TraversalState>,
    current: DFF<Bits<INDEX_BITS>>,
    visits: DFF<Bits<NODE_COUNT_BITS>>,
    sp: DFF<Bits<SP_BITS>>,
    node_references: DFF<Bits<32>>,
    /// The stack was pushed at the last edge: its RAM returned the old top, this is the new.
    pushed: DFF<Bit>,
    pushed_entry: DFF<Bits<ENTRY_BITS>>,
    refusal: DFF<Bits<8>>,
    candidates: DFF<Bits<CANDIDATE_COUNT_BITS>>,
    /// The ray being traversed's tag, and the next ray's.
    tag: DFF<Bits<TAG_WIDTH>>,
    tag_count: DFF<Bits<TAG_WIDTH>>,
    // Output FIFO: [read, write) holds words written at earlier edges.
    write_ptr: DFF<Bits<POINTER_BITS>>,
    read_ptr: DFF<Bits<POINTER_BITS>>,
    head_valid: DFF<Bit>,

    // combinational temporaries
    current_next: Signal<Local, Bits<INDEX_BITS>>,
    sp_next: Signal<Local, Bits<SP_BITS>>,
    sp_below: Signal<Local, Bits<SP_BITS>>,
    read_ptr_next: Signal<Local, Bits<POINTER_BITS>>,
    fill: Signal<Local, Bits<POINTER_BITS>>,
    room: Signal<Local, Bit>,
    is_busy: Signal<Local, Bit>,
    limit_index: Signal<Local, Bits<INDEX_BITS>>,
    hit0: Signal<Local, Bit>,
    hit1: Signal<Local, Bit>,
    entry0: Signal<Local, Bits<ENTRY_BITS>>,
    entry1: Signal<Local, Bits<ENTRY_BITS>>,
    swap: Signal<Local, Bit>,
    first: Signal<Local, Bits<ENTRY_BITS>>,
    second: Signal<Local, Bits<ENTRY_BITS>>,
    stack_top: Signal<Local, Bits<ENTRY_BITS>>,
    emit: Signal<Local, Bit>,
    emit_entry: Signal<Local, Bits<ENTRY_BITS>>,
    head: Signal<Local, Bits<RESULT_BITS>>,
    sign: Constant<Bits<TB>>,
    max_nodes: Constant<Bits<NODE_COUNT_BITS>>,
    end_flag: Constant<Bits<RESULT_BITS>>,
    buffer_size: Constant<Bits<POINTER_BITS>>,
    stack_depth: Constant<Bits<SP_BITS>>,
    unrepresentable: Constant<Bits<8>>,
    stack_overflow: Constant<Bits<8>>,
    bad_reference: Constant<Bits<8>>,
    runaway: Constant<Bits<8>>,
}

/// Clocks from a visit's start to the next visit's start when the node descends into a
/// node: the node check and lane issue, then `LANE_LATENCY` clocks to the decision.
pub const VISIT_CYCLES: usize = 1 + crate::raybox::LANE_LATENCY;

impl Default for BvhTraversal {
    fn default() -> Self {
        let code = |r: Refusal| Constant::new((r.code() as u64).to_bits());
        Self {
            clock: Default::default(),
            node_write: Default::default(),
            node_address: Default::default(),
            node_word: Default::default(),
            node_data: Default::default(),
            node_count: Default::default(),
            order: Default::default(),
            ray_valid: Default::default(),
            ray_data: Default::default(),
            ray_ready: Default::default(),
            result_valid: Default::default(),
            result_data: Default::default(),
            result_ready: Default::default(),
            busy: Default::default(),
            front: Default::default(),
            lanes: Default::default(),
            lower0: Default::default(),
            upper0: Default::default(),
            lower1: Default::default(),
            upper1: Default::default(),
            references: Default::default(),
            stack: Default::default(),
            results: Default::default(),
            ray_word0: Default::default(),
            ray_word1: Default::default(),
            ray_word2: Default::default(),
            ray_word3: Default::default(),
            ray_word_index: Default::default(),
            ray_full: Default::default(),
            origin: Default::default(),
            mant: Default::default(),
            shift: Default::default(),
            t_min: Default::default(),
            t_max: Default::default(),
            lower_is_entry: Default::default(),
            near_first: Default::default(),
            node_limit: Default::default(),
            state: Default::default(),
            current: Default::default(),
            visits: Default::default(),
            sp: Default::default(),
            node_references: Default::default(),
            pushed: Default::default(),
            pushed_entry: Default::default(),
            refusal: Default::default(),
            candidates: Default::default(),
            tag: Default::default(),
            tag_count: Default::default(),
            write_ptr: Default::default(),
            read_ptr: Default::default(),
            head_valid: Default::default(),
            current_next: Default::default(),
            sp_next: Default::default(),
            sp_below: Default::default(),
            read_ptr_next: Default::default(),
            fill: Default::default(),
            room: Default::default(),
            is_busy: Default::default(),
            limit_index: Default::default(),
            hit0: Default::default(),
            hit1: Default::default(),
            entry0: Default::default(),
            entry1: Default::default(),
            swap: Default::default(),
            first: Default::default(),
            second: Default::default(),
            stack_top: Default::default(),
            emit: Default::default(),
            emit_entry: Default::default(),
            head: Default::default(),
            sign: Constant::new((1u64 << (TB - 1)).to_bits()),
            max_nodes: Constant::new((MAX_NODES as u64).to_bits()),
            end_flag: Constant::new((1u64 << (RESULT_BITS - 1)).to_bits()),
            buffer_size: Constant::new((1u64 << RESULT_BUFFER_BITS).to_bits()),
            stack_depth: Constant::new((STACK_DEPTH as u64).to_bits()),
            unrepresentable: code(Refusal::Unrepresentable),
            stack_overflow: code(Refusal::StackOverflow),
            bad_reference: code(Refusal::BadReference),
            runaway: code(Refusal::Runaway),
        }
    }
}

impl Logic for BvhTraversal {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            ray_word0,
            ray_word1,
            ray_word2,
            ray_word3,
            ray_word_index,
            ray_full,
            origin,
            mant,
            shift,
            t_min,
            t_max,
            lower_is_entry,
            near_first,
            node_limit,
            state,
            current,
            visits,
            sp,
            node_references,
            pushed,
            pushed_entry,
            refusal,
            candidates,
            tag,
            tag_count,
            write_ptr,
            read_ptr,
            head_valid
        );
        self.lower0.read_clock.next = self.clock.val();
        self.lower0.write_clock.next = self.clock.val();
        self.upper0.read_clock.next = self.clock.val();
        self.upper0.write_clock.next = self.clock.val();
        self.lower1.read_clock.next = self.clock.val();
        self.lower1.write_clock.next = self.clock.val();
        self.upper1.read_clock.next = self.clock.val();
        self.upper1.write_clock.next = self.clock.val();
        self.references.read_clock.next = self.clock.val();
        self.references.write_clock.next = self.clock.val();
        self.stack.read_clock.next = self.clock.val();
        self.stack.write_clock.next = self.clock.val();
        self.results.read_clock.next = self.clock.val();
        self.results.write_clock.next = self.clock.val();

        // ---- node memory: loaded word by word ---------------------------------------------
        self.lower0.write_address.next = self.node_address.val();
        self.upper0.write_address.next = self.node_address.val();
        self.lower1.write_address.next = self.node_address.val();
        self.upper1.write_address.next = self.node_address.val();
        self.references.write_address.next = self.node_address.val();
        self.lower0.write_data.next = self.node_data.val().get_bits::<CB3>(0);
        self.upper0.write_data.next = self.node_data.val().get_bits::<CB3>(0);
        self.lower1.write_data.next = self.node_data.val().get_bits::<CB3>(0);
        self.upper1.write_data.next = self.node_data.val().get_bits::<CB3>(0);
        self.references.write_data.next = self.node_data.val().get_bits::<32>(0);
        self.lower0.write_enable.next = self.node_write.val() & (self.node_word.val() == 0);
        self.upper0.write_enable.next = self.node_write.val() & (self.node_word.val() == 1);
        self.lower1.write_enable.next = self.node_write.val() & (self.node_word.val() == 2);
        self.upper1.write_enable.next = self.node_write.val() & (self.node_word.val() == 3);
        self.references.write_enable.next = self.node_write.val() & (self.node_word.val() == 4);

        // ---- rays in ------------------------------------------------------------------------
        self.ray_ready.next = !self.ray_full.q.val();
        if self.ray_valid.val() & !self.ray_full.q.val() {
            self.ray_word_index.d.next = self.ray_word_index.q.val() + 1;
            match self.ray_word_index.q.val().index() {
                0 => {
                    self.ray_word0.d.next = self.ray_data.val();
                }
                1 => {
                    self.ray_word1.d.next = self.ray_data.val();
                }
                2 => {
                    self.ray_word2.d.next = self.ray_data.val();
                }
                _ => {
                    self.ray_word3.d.next = self.ray_data.val();
                    self.ray_full.d.next = true;
                }
            }
        }
        self.front.word0.next = self.ray_word0.q.val();
        self.front.word1.next = self.ray_word1.q.val();
        self.front.word2.next = self.ray_word2.q.val();
        self.front.word3.next = self.ray_word3.q.val();

        // ---- the node on the memory's outputs into the lanes ------------------------------
        // Per axis, the entry plane is the lower corner where the mantissa is positive.
        self.lanes[0].entry_plane.next = (self.lower0.read_data.val()
            & self.lower_is_entry.q.val())
            | (self.upper0.read_data.val() & !self.lower_is_entry.q.val());
        self.lanes[0].exit_plane.next = (self.upper0.read_data.val() & self.lower_is_entry.q.val())
            | (self.lower0.read_data.val() & !self.lower_is_entry.q.val());
        self.lanes[1].entry_plane.next = (self.lower1.read_data.val()
            & self.lower_is_entry.q.val())
            | (self.upper1.read_data.val() & !self.lower_is_entry.q.val());
        self.lanes[1].exit_plane.next = (self.upper1.read_data.val() & self.lower_is_entry.q.val())
            | (self.lower1.read_data.val() & !self.lower_is_entry.q.val());
        for c in 0..2 {
            self.lanes[c].clock.next = self.clock.val();
            self.lanes[c].in_valid.next = false;
            self.lanes[c].in_index.next = 0.into();
            self.lanes[c].origin.next = self.origin.q.val();
            self.lanes[c].mant.next = self.mant.q.val();
            self.lanes[c].shift.next = self.shift.q.val();
            self.lanes[c].t_min.next = self.t_min.q.val();
            self.lanes[c].t_max.next = self.t_max.q.val();
        }

        // ---- defaults ---------------------------------------------------------------------
        self.current_next.next = self.current.q.val();
        self.sp_next.next = self.sp.q.val();
        self.pushed.d.next = false;
        self.emit.next = false;
        self.stack.write_enable.next = false;
        self.stack.write_address.next = self.sp.q.val().get_bits::<STACK_ADDRESS_BITS>(0);
        self.results.write_enable.next = false;
        self.results.write_address.next = self.write_ptr.q.val().get_bits::<RESULT_BUFFER_BITS>(0);
        self.results.write_data.next = 0.into();
        self.fill.next = self.write_ptr.q.val() - self.read_ptr.q.val();
        self.room.next = self.fill.val() != self.buffer_size.val();
        self.limit_index.next = bit_cast::<INDEX_BITS, NODE_COUNT_BITS>(self.node_limit.q.val());

        // The lanes' answers for the node's two children, as stack entries.
        self.hit0.next = self.node_references.q.val().get_bit(15) & self.lanes[0].out_hit.val();
        self.hit1.next = self.node_references.q.val().get_bit(31) & self.lanes[1].out_hit.val();
        self.entry0.next = bit_cast::<ENTRY_BITS, TB>(self.lanes[0].out_t_near.val())
            | (bit_cast::<ENTRY_BITS, 16>(self.node_references.q.val().get_bits::<16>(0)) << 32);
        self.entry1.next = bit_cast::<ENTRY_BITS, TB>(self.lanes[1].out_t_near.val())
            | (bit_cast::<ENTRY_BITS, 16>(self.node_references.q.val().get_bits::<16>(16)) << 32);
        // Near-first: child 1 first only when both are hit and it is entered strictly first.
        self.swap.next = self.near_first.q.val()
            & self.hit0.val()
            & self.hit1.val()
            & ((self.lanes[1].out_t_near.val() ^ self.sign.val())
                < (self.lanes[0].out_t_near.val() ^ self.sign.val()));
        self.first.next = self.entry1.val();
        self.second.next = self.entry0.val();
        if self.hit0.val() & !self.swap.val() {
            self.first.next = self.entry0.val();
            self.second.next = self.entry1.val();
        }
        self.stack_top.next = self.stack.read_data.val();
        if self.pushed.q.val() {
            self.stack_top.next = self.pushed_entry.q.val();
        }
        self.emit_entry.next = self.stack_top.val();
        self.stack.write_data.next = self.second.val();

        match self.state.q.val() {
            TraversalState::Idle => {
                if self.ray_full.q.val() {
                    self.ray_full.d.next = false;
                    self.tag.d.next = self.tag_count.q.val();
                    self.tag_count.d.next = self.tag_count.q.val() + 1;
                    self.origin.d.next = self.front.origin.val();
                    self.mant.d.next = self.front.mant.val();
                    self.shift.d.next = self.front.shift.val();
                    self.t_min.d.next = self.front.t_min.val();
                    self.t_max.d.next = self.front.t_max.val();
                    self.lower_is_entry.d.next = self.front.lower_is_entry.val();
                    self.near_first.d.next = !self.order.val();
                    self.node_limit.d.next = self.node_count.val();
                    if self.node_count.val() > self.max_nodes.val() {
                        self.node_limit.d.next = self.max_nodes.val();
                    }
                    self.current_next.next = 0.into();
                    self.visits.d.next = 0.into();
                    self.sp_next.next = 0.into();
                    self.candidates.d.next = 0.into();
                    self.refusal.d.next = 0.into();
                    if self.front.representable.val() {
                        self.state.d.next = TraversalState::Visit;
                    } else {
                        self.refusal.d.next = self.unrepresentable.val();
                        self.state.d.next = TraversalState::EndWord;
                    }
                }
            }
            TraversalState::Visit => {
                // `traverse`: a reference beyond the memory, then one visit too many.
                if self.current.q.val() >= self.limit_index.val() {
                    self.refusal.d.next = self.bad_reference.val();
                    self.state.d.next = TraversalState::EndWord;
                } else if self.visits.q.val() >= self.node_limit.q.val() {
                    self.refusal.d.next = self.runaway.val();
                    self.state.d.next = TraversalState::EndWord;
                } else if self.room.val() {
                    // Room for the one candidate the decision may write.
                    self.lanes[0].in_valid.next = true;
                    self.lanes[1].in_valid.next = true;
                    self.node_references.d.next = self.references.read_data.val();
                    self.visits.d.next = self.visits.q.val() + 1;
                    self.state.d.next = TraversalState::Test;
                }
            }
            TraversalState::Test => {
                if self.lanes[0].out_valid.val() {
                    if self.hit0.val()
                        & self.hit1.val()
                        & (self.sp.q.val() == self.stack_depth.val())
                    {
                        self.refusal.d.next = self.stack_overflow.val();
                        self.state.d.next = TraversalState::EndWord;
                    } else {
                        if self.hit0.val() & self.hit1.val() {
                            self.stack.write_enable.next = true;
                            self.sp_next.next = self.sp.q.val() + 1;
                            self.pushed.d.next = true;
                            self.pushed_entry.d.next = self.second.val();
                        }
                        self.state.d.next = TraversalState::Pop;
                        if self.hit0.val() | self.hit1.val() {
                            if self.first.val().get_bit(46) {
                                self.emit.next = true;
                                self.emit_entry.next = self.first.val();
                            } else {
                                self.current_next.next =
                                    self.first.val().get_bits::<INDEX_BITS>(32);
                                self.state.d.next = TraversalState::Visit;
                            }
                        }
                    }
                }
            }
            TraversalState::Pop => {
                if !self.sp.q.val().any() {
                    self.state.d.next = TraversalState::EndWord;
                } else if self.stack_top.val().get_bit(46) {
                    if self.room.val() {
                        self.emit.next = true;
                        self.emit_entry.next = self.stack_top.val();
                        self.sp_next.next = self.sp.q.val() - 1;
                    }
                } else {
                    self.current_next.next = self.stack_top.val().get_bits::<INDEX_BITS>(32);
                    self.sp_next.next = self.sp.q.val() - 1;
                    self.state.d.next = TraversalState::Visit;
                }
            }
            TraversalState::EndWord => {
                // The candidates written, refused or not.
                if self.room.val() {
                    self.results.write_enable.next = true;
                    self.results.write_data.next = self.end_flag.val()
                        | bit_cast::<RESULT_BITS, CANDIDATE_COUNT_BITS>(self.candidates.q.val())
                        | (bit_cast::<RESULT_BITS, 8>(self.refusal.q.val()) << 32)
                        | (bit_cast::<RESULT_BITS, TAG_WIDTH>(self.tag.q.val()) << 40);
                    self.write_ptr.d.next = self.write_ptr.q.val() + 1;
                    self.state.d.next = TraversalState::Idle;
                }
            }
        }

        // ---- a candidate into the FIFO ------------------------------------------------
        if self.emit.val() {
            self.results.write_enable.next = true;
            self.results.write_data.next =
                bit_cast::<RESULT_BITS, 46>(self.emit_entry.val().get_bits::<46>(0))
                    | (bit_cast::<RESULT_BITS, TAG_WIDTH>(self.tag.q.val()) << 46);
            self.write_ptr.d.next = self.write_ptr.q.val() + 1;
            self.candidates.d.next = self.candidates.q.val() + 1;
        }
        self.current.d.next = self.current_next.val();
        self.sp.d.next = self.sp_next.val();
        // The node memory and the stack are read at the addresses of the next clock, so the
        // node and the stack's top are on their outputs then.
        self.lower0.read_address.next = self.current_next.val().get_bits::<NODE_ADDRESS_BITS>(0);
        self.upper0.read_address.next = self.current_next.val().get_bits::<NODE_ADDRESS_BITS>(0);
        self.lower1.read_address.next = self.current_next.val().get_bits::<NODE_ADDRESS_BITS>(0);
        self.upper1.read_address.next = self.current_next.val().get_bits::<NODE_ADDRESS_BITS>(0);
        self.references.read_address.next =
            self.current_next.val().get_bits::<NODE_ADDRESS_BITS>(0);
        self.sp_below.next = self.sp_next.val() - 1;
        self.stack.read_address.next = self.sp_below.val().get_bits::<STACK_ADDRESS_BITS>(0);

        // ---- results out: the FIFO read at the next clock's pointer ----------------------
        self.read_ptr_next.next = self.read_ptr.q.val();
        if self.head_valid.q.val() & self.result_ready.val() {
            self.read_ptr_next.next = self.read_ptr.q.val() + 1;
        }
        self.read_ptr.d.next = self.read_ptr_next.val();
        self.results.read_address.next = self.read_ptr_next.val().get_bits::<RESULT_BUFFER_BITS>(0);
        // Words before the write pointer were written at an earlier edge.
        self.head_valid.d.next = self.read_ptr_next.val() != self.write_ptr.q.val();
        self.head.next = 0.into();
        if self.head_valid.q.val() {
            self.head.next = self.results.read_data.val();
        }
        self.result_valid.next = self.head_valid.q.val();
        self.result_data.next = bit_cast::<64, 54>(self.head.val().get_bits::<54>(0))
            | (bit_cast::<64, 1>(self.head.val().get_bits::<1>(54)) << 63);

        self.is_busy.next = (self.state.q.val() != TraversalState::Idle)
            | self.ray_full.q.val()
            | self.ray_word_index.q.val().any()
            | (self.read_ptr.q.val() != self.write_ptr.q.val());
        self.busy.next = self.is_busy.val();
        // The tag rule: restart while idle (a ray is taken only while busy).
        if !self.is_busy.val() {
            self.tag_count.d.next = 0.into();
        }
    }
}
