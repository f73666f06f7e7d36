//! The traversal core with several rays in flight (issue 22 item 4): `RAYS_IN_FLIGHT` ray
//! contexts share the node memory, the two slab lanes and a stack RAM, so the lanes take a
//! node visit nearly every clock instead of one in `VISIT_CYCLES`. Its output is
//! `skylux_regmap::bvh_format::result_words` per ray (format v2: tagged words; different
//! rays' words interleave, each ray's own in order).
//!
//! Each clock one ready context issues one operation into a fixed pipeline of
//! `PIPELINE_CLOCKS` clocks (node memory and ray fields read, then the lanes):
//! - a node visit (both children through the lanes),
//! - a pop (the stack's top, read at the pipeline's end),
//! - its end word.
//!
//! The operation's completion, the pipeline's last stage, updates that context alone:
//! descend, push, pop, write a candidate or the end word to the output FIFO. A context has
//! one operation in flight at most, so its registers and its stack region are never read
//! while an earlier operation of its own could still change them. Every operation writes at
//! most one word, and one is issued only when the FIFO has room for it and for every
//! operation in flight, so back-pressure never loses or duplicates a word.
//!
//! Timing: a ray costs one operation per node visit, per stack entry taken and for its end
//! word, its own operations `PIPELINE_CLOCKS + 1` = 8 clocks apart (issue, completion, the
//! next issue). At most `PIPELINE_CLOCKS` contexts are busy on a clock, so whenever all
//! `RAYS_IN_FLIGHT` hold a ray (and the FIFO has room) one operation issues: the lanes then
//! take a node visit on every clock not spent on a pop or an end word. Rays enter one per
//! `RAY_WORDS` clocks at most (one 64-bit word a clock). Measured on 40-leaf trees, 50-ray
//! batches, no back-pressure (`rtl/tests/bvh_traversal.rs`): 13.2 clocks a ray and 0.65 node
//! visits a clock, against 64.7 and 0.13 with one ray in flight.

use super::front::{RayFrontEnd, CB3, MB3, SB3};
use crate::raybox::{SlabLane, LANE_LATENCY};
use rust_hdl::prelude::*;
use skylux_regmap::bvh_format::{
    Refusal, CANDIDATE_TAG_SHIFT, END_TAG_SHIFT, MAX_NODES, NODE_INDEX_BITS, NODE_WORDS, RAY_WORDS,
    REF_INDEX_MASK, REF_LEAF, REF_VALID, RESULT_END_BIT, STACK_DEPTH, TAG_BITS,
};
use skylux_regmap::raybox_format::{COORD_BITS, MANT_BITS, T_BITS};

const TB: usize = T_BITS as usize;
const CB: usize = COORD_BITS as usize;
const MB: usize = MANT_BITS as usize;
/// Rays in flight: the visit loop is `PIPELINE_CLOCKS` clocks plus one for the context's
/// next issue, so 8 contexts keep the lanes busy when every context has work.
pub const RAYS_IN_FLIGHT: usize = 8;
const CTX_BITS: usize = 3;
/// Clocks from an operation's issue to its completion: the node memory and ray-field read,
/// then the lanes.
pub const PIPELINE_CLOCKS: usize = 1 + LANE_LATENCY;
/// Pipeline registers after the issue: stage `PIPELINE_CLOCKS - 1` is the completion (the
/// kernel names stages 5 and 6 by literal: rust-hdl's Verilog takes no constant in an index).
const STAGES: usize = PIPELINE_CLOCKS;
const _: () = assert!(STAGES == 7);
const NODE_ADDRESS_BITS: usize = NODE_INDEX_BITS as usize;
const NODE_COUNT_BITS: usize = NODE_ADDRESS_BITS + 1;
const INDEX_BITS: usize = 14;
/// (The stack addresses below shift the context by this literal 5.)
const STACK_ADDRESS_BITS: usize = 5;
const SP_BITS: usize = STACK_ADDRESS_BITS + 1;
/// The shared stack RAM: each context's `STACK_DEPTH` entries at `context << 5`.
const STACK_RAM_BITS: usize = CTX_BITS + STACK_ADDRESS_BITS;
/// A stack entry: `[31:0]` t_near, `[47:32]` reference; bits [45:0] are a candidate word's.
const ENTRY_BITS: usize = 48;
/// The output FIFO: 2^5 words, room for the words of every operation in flight and enough
/// slack that a reader taking a word a clock never stalls the issue.
pub const OUTPUT_FIFO_BITS: usize = 5;
const POINTER_BITS: usize = OUTPUT_FIFO_BITS + 1;
const TAG_WIDTH: usize = TAG_BITS as usize;
/// A FIFO word: the result word's bits [53:0], the end bit at 54.
const RESULT_BITS: usize = 55;
/// A ray writes at most 2 × `MAX_NODES` candidates, under 2^11.
const CANDIDATE_COUNT_BITS: usize = 11;
/// Operations in flight: 0 to `PIPELINE_CLOCKS`.
const INFLIGHT_BITS: usize = 4;
const REFUSAL_BITS: usize = 3;

const _: () = assert!(
    NODE_WORDS == 5
        && RAY_WORDS == 4
        && STACK_DEPTH == 1 << STACK_ADDRESS_BITS
        && MAX_NODES == 1 << NODE_ADDRESS_BITS
        && RAYS_IN_FLIGHT == 1 << CTX_BITS
        && RAYS_IN_FLIGHT > PIPELINE_CLOCKS
        && RAYS_IN_FLIGHT < 1 << TAG_BITS
        && PIPELINE_CLOCKS < 1 << INFLIGHT_BITS
        && PIPELINE_CLOCKS < 1 << OUTPUT_FIFO_BITS
        && REF_VALID == 1 << 15
        && REF_LEAF == 1 << 14
        && REF_INDEX_MASK as usize == (1 << INDEX_BITS) - 1
        && RESULT_END_BIT == 63
        && CANDIDATE_TAG_SHIFT == 46
        && END_TAG_SHIFT == 40
        && TAG_WIDTH == 8
        && 2 * MAX_NODES < 1 << CANDIDATE_COUNT_BITS
        && (Refusal::Runaway as u8) < 1 << REFUSAL_BITS
        && TB == 32
        && CB3 == 3 * CB
        && MB3 == 3 * MB
        && MB == 25, // the mantissas' sign bits, 24, 49 and 74, are literals in the kernel
    "the interleaved traversal follows skylux_regmap::bvh_format"
);

/// A ray context's state; its next operation when ready.
#[derive(Copy, Clone, PartialEq, Eq, Debug, LogicState)]
pub enum ContextState {
    /// No ray.
    Free,
    /// Ready to visit the node `current`.
    Visit,
    /// Ready to take the stack's top.
    Pop,
    /// Ready to write its end word.
    End,
    /// An operation in flight.
    Busy,
}

/// The BVH traversal core, `RAYS_IN_FLIGHT` rays interleaved. Ports as
/// [`super::BvhTraversal`]'s:
///
/// - Node memory: `node_write` writes `node_data` as word `node_word` (0 to 4) of node
///   `node_address`. Load it while the unit is idle (`busy` low).
/// - `node_count` (larger than `MAX_NODES` counts as `MAX_NODES`) and `order` (0 near-first,
///   1 child order) are sampled when a ray enters a context.
/// - Rays: `RAY_WORDS` words on `ray_data`, each taken on a clock with `ray_valid` and
///   `ray_ready` high; a ray enters a free context the clock after its last word.
/// - Results: `result_data` is valid with `result_valid` and taken with `result_ready`;
///   each ray's words in order, rays interleaved, every word tagged.
/// - Tags: `tag_count` restarts at 0 on every clock `busy` is low and counts the rays taken.
#[derive(LogicBlock)]
pub struct BvhInterleaved {
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
    // Node memory: the boxes read at the issue, the references at the completion.
    lower0: RAM<Bits<CB3>, NODE_ADDRESS_BITS>,
    upper0: RAM<Bits<CB3>, NODE_ADDRESS_BITS>,
    lower1: RAM<Bits<CB3>, NODE_ADDRESS_BITS>,
    upper1: RAM<Bits<CB3>, NODE_ADDRESS_BITS>,
    references: RAM<Bits<32>, NODE_ADDRESS_BITS>,
    stack: RAM<Bits<ENTRY_BITS>, STACK_RAM_BITS>,
    results: RAM<Bits<RESULT_BITS>, OUTPUT_FIFO_BITS>,
    // Each context's ray in grid form, written when it enters, read at each issue.
    ray_origin: RAM<Bits<CB3>, CTX_BITS>,
    ray_mant: RAM<Bits<MB3>, CTX_BITS>,
    ray_shift: RAM<Bits<SB3>, CTX_BITS>,
    ray_t_min: RAM<Bits<TB>, CTX_BITS>,
    ray_t_max: RAM<Bits<TB>, CTX_BITS>,

    // The ray being received.
    ray_word0: DFF<Bits<64>>,
    ray_word1: DFF<Bits<64>>,
    ray_word2: DFF<Bits<64>>,
    ray_word3: DFF<Bits<64>>,
    ray_word_index: DFF<Bits<2>>,
    ray_full: DFF<Bit>,
    tag_count: DFF<Bits<TAG_WIDTH>>,

    // Contexts.
    state: [DFF<ContextState>; RAYS_IN_FLIGHT],
    current: [DFF<Bits<NODE_ADDRESS_BITS>>; RAYS_IN_FLIGHT],
    visits: [DFF<Bits<NODE_COUNT_BITS>>; RAYS_IN_FLIGHT],
    sp: [DFF<Bits<SP_BITS>>; RAYS_IN_FLIGHT],
    candidates: [DFF<Bits<CANDIDATE_COUNT_BITS>>; RAYS_IN_FLIGHT],
    refusal: [DFF<Bits<REFUSAL_BITS>>; RAYS_IN_FLIGHT],
    tag: [DFF<Bits<TAG_WIDTH>>; RAYS_IN_FLIGHT],
    node_limit: [DFF<Bits<NODE_COUNT_BITS>>; RAYS_IN_FLIGHT],
    near_first: [DFF<Bit>; RAYS_IN_FLIGHT],

    // The pipeline after the issue: stage s holds the operation issued s + 1 clocks ago.
    p_valid: [DFF<Bit>; STAGES],
    p_ctx: [DFF<Bits<CTX_BITS>>; STAGES],
    p_op: [DFF<ContextState>; STAGES],
    inflight: DFF<Bits<INFLIGHT_BITS>>,

    // Output FIFO: [read, write) holds words written at earlier edges.
    write_ptr: DFF<Bits<POINTER_BITS>>,
    read_ptr: DFF<Bits<POINTER_BITS>>,
    head_valid: DFF<Bit>,

    // combinational temporaries
    // entering
    free_found: Signal<Local, Bit>,
    free_ctx: Signal<Local, Bits<CTX_BITS>>,
    accept: Signal<Local, Bit>,
    limit_in: Signal<Local, Bits<NODE_COUNT_BITS>>,
    // issuing
    issue_found: Signal<Local, Bit>,
    issue_ctx: Signal<Local, Bits<CTX_BITS>>,
    issue_op: Signal<Local, ContextState>,
    issue: Signal<Local, Bit>,
    issue_current: Signal<Local, Bits<NODE_ADDRESS_BITS>>,
    fill: Signal<Local, Bits<POINTER_BITS>>,
    committed: Signal<Local, Bits<POINTER_BITS>>,
    // reads for the completion
    pre_ctx: Signal<Local, Bits<CTX_BITS>>,
    pre_sp: Signal<Local, Bits<SP_BITS>>,
    pre_sp_below: Signal<Local, Bits<SP_BITS>>,
    pre_current: Signal<Local, Bits<NODE_ADDRESS_BITS>>,
    // completion: the context's registers
    done: Signal<Local, Bit>,
    done_ctx: Signal<Local, Bits<CTX_BITS>>,
    done_op: Signal<Local, ContextState>,
    c_visits: Signal<Local, Bits<NODE_COUNT_BITS>>,
    c_sp: Signal<Local, Bits<SP_BITS>>,
    c_candidates: Signal<Local, Bits<CANDIDATE_COUNT_BITS>>,
    c_refusal: Signal<Local, Bits<REFUSAL_BITS>>,
    c_tag: Signal<Local, Bits<TAG_WIDTH>>,
    c_limit: Signal<Local, Bits<NODE_COUNT_BITS>>,
    c_near_first: Signal<Local, Bit>,
    // completion: the decision
    hit0: Signal<Local, Bit>,
    hit1: Signal<Local, Bit>,
    entry0: Signal<Local, Bits<ENTRY_BITS>>,
    entry1: Signal<Local, Bits<ENTRY_BITS>>,
    swap: Signal<Local, Bit>,
    first: Signal<Local, Bits<ENTRY_BITS>>,
    second: Signal<Local, Bits<ENTRY_BITS>>,
    /// The reference taken next (a hit child or the stack's top), if any.
    take: Signal<Local, Bit>,
    take_entry: Signal<Local, Bits<ENTRY_BITS>>,
    limit_index: Signal<Local, Bits<INDEX_BITS>>,
    n_state: Signal<Local, ContextState>,
    n_current: Signal<Local, Bits<NODE_ADDRESS_BITS>>,
    n_visits: Signal<Local, Bits<NODE_COUNT_BITS>>,
    n_sp: Signal<Local, Bits<SP_BITS>>,
    n_candidates: Signal<Local, Bits<CANDIDATE_COUNT_BITS>>,
    n_refusal: Signal<Local, Bits<REFUSAL_BITS>>,
    emit: Signal<Local, Bit>,
    fifo_write: Signal<Local, Bit>,
    read_ptr_next: Signal<Local, Bits<POINTER_BITS>>,
    head: Signal<Local, Bits<RESULT_BITS>>,
    is_busy: Signal<Local, Bit>,
    any_context: Signal<Local, Bit>,
    lower_is_entry: Signal<Local, Bits<CB3>>,
    axis_mask_x: Constant<Bits<CB3>>,
    axis_mask_y: Constant<Bits<CB3>>,
    axis_mask_z: Constant<Bits<CB3>>,

    sign: Constant<Bits<TB>>,
    max_nodes: Constant<Bits<NODE_COUNT_BITS>>,
    end_flag: Constant<Bits<RESULT_BITS>>,
    fifo_size: Constant<Bits<POINTER_BITS>>,
    stack_depth: Constant<Bits<SP_BITS>>,
    unrepresentable: Constant<Bits<REFUSAL_BITS>>,
    stack_overflow: Constant<Bits<REFUSAL_BITS>>,
    bad_reference: Constant<Bits<REFUSAL_BITS>>,
    runaway: Constant<Bits<REFUSAL_BITS>>,
}

impl Default for BvhInterleaved {
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
            ray_origin: Default::default(),
            ray_mant: Default::default(),
            ray_shift: Default::default(),
            ray_t_min: Default::default(),
            ray_t_max: Default::default(),
            ray_word0: Default::default(),
            ray_word1: Default::default(),
            ray_word2: Default::default(),
            ray_word3: Default::default(),
            ray_word_index: Default::default(),
            ray_full: Default::default(),
            tag_count: Default::default(),
            state: Default::default(),
            current: Default::default(),
            visits: Default::default(),
            sp: Default::default(),
            candidates: Default::default(),
            refusal: Default::default(),
            tag: Default::default(),
            node_limit: Default::default(),
            near_first: Default::default(),
            p_valid: Default::default(),
            p_ctx: Default::default(),
            p_op: Default::default(),
            inflight: Default::default(),
            write_ptr: Default::default(),
            read_ptr: Default::default(),
            head_valid: Default::default(),
            free_found: Default::default(),
            free_ctx: Default::default(),
            accept: Default::default(),
            limit_in: Default::default(),
            issue_found: Default::default(),
            issue_ctx: Default::default(),
            issue_op: Default::default(),
            issue: Default::default(),
            issue_current: Default::default(),
            fill: Default::default(),
            committed: Default::default(),
            pre_ctx: Default::default(),
            pre_sp: Default::default(),
            pre_sp_below: Default::default(),
            pre_current: Default::default(),
            done: Default::default(),
            done_ctx: Default::default(),
            done_op: Default::default(),
            c_visits: Default::default(),
            c_sp: Default::default(),
            c_candidates: Default::default(),
            c_refusal: Default::default(),
            c_tag: Default::default(),
            c_limit: Default::default(),
            c_near_first: Default::default(),
            hit0: Default::default(),
            hit1: Default::default(),
            entry0: Default::default(),
            entry1: Default::default(),
            swap: Default::default(),
            first: Default::default(),
            second: Default::default(),
            take: Default::default(),
            take_entry: Default::default(),
            limit_index: Default::default(),
            n_state: Default::default(),
            n_current: Default::default(),
            n_visits: Default::default(),
            n_sp: Default::default(),
            n_candidates: Default::default(),
            n_refusal: Default::default(),
            emit: Default::default(),
            fifo_write: Default::default(),
            read_ptr_next: Default::default(),
            head: Default::default(),
            is_busy: Default::default(),
            any_context: Default::default(),
            lower_is_entry: Default::default(),
            axis_mask_x: Constant::new(((1u64 << CB) - 1).to_bits()),
            axis_mask_y: Constant::new((((1u64 << CB) - 1) << CB).to_bits()),
            axis_mask_z: Constant::new((((1u64 << CB) - 1) << (2 * CB)).to_bits()),
            sign: Constant::new((1u64 << (TB - 1)).to_bits()),
            max_nodes: Constant::new((MAX_NODES as u64).to_bits()),
            end_flag: Constant::new((1u64 << (RESULT_BITS - 1)).to_bits()),
            fifo_size: Constant::new((1u64 << OUTPUT_FIFO_BITS).to_bits()),
            stack_depth: Constant::new((STACK_DEPTH as u64).to_bits()),
            unrepresentable: code(Refusal::Unrepresentable),
            stack_overflow: code(Refusal::StackOverflow),
            bad_reference: code(Refusal::BadReference),
            runaway: code(Refusal::Runaway),
        }
    }
}

/// Observations for the cycle tests (settled values of the current clock).
impl BvhInterleaved {
    /// Contexts holding a ray.
    pub fn rays_held(&self) -> usize {
        self.state
            .iter()
            .filter(|s| s.q.val() != ContextState::Free)
            .count()
    }

    /// An operation is issued this clock.
    pub fn issuing(&self) -> bool {
        self.issue.val()
    }

    /// The operation issued this clock is a node visit.
    pub fn issuing_visit(&self) -> bool {
        self.issue.val() && self.issue_op.val() == ContextState::Visit
    }
}

impl Logic for BvhInterleaved {
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
            tag_count,
            inflight,
            write_ptr,
            read_ptr,
            head_valid
        );
        for i in 0..RAYS_IN_FLIGHT {
            self.state[i].clock.next = self.clock.val();
            self.current[i].clock.next = self.clock.val();
            self.visits[i].clock.next = self.clock.val();
            self.sp[i].clock.next = self.clock.val();
            self.candidates[i].clock.next = self.clock.val();
            self.refusal[i].clock.next = self.clock.val();
            self.tag[i].clock.next = self.clock.val();
            self.node_limit[i].clock.next = self.clock.val();
            self.near_first[i].clock.next = self.clock.val();
            self.state[i].d.next = self.state[i].q.val();
            self.current[i].d.next = self.current[i].q.val();
            self.visits[i].d.next = self.visits[i].q.val();
            self.sp[i].d.next = self.sp[i].q.val();
            self.candidates[i].d.next = self.candidates[i].q.val();
            self.refusal[i].d.next = self.refusal[i].q.val();
            self.tag[i].d.next = self.tag[i].q.val();
            self.node_limit[i].d.next = self.node_limit[i].q.val();
            self.near_first[i].d.next = self.near_first[i].q.val();
        }
        for s in 0..STAGES {
            self.p_valid[s].clock.next = self.clock.val();
            self.p_ctx[s].clock.next = self.clock.val();
            self.p_op[s].clock.next = self.clock.val();
        }
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
        self.ray_origin.read_clock.next = self.clock.val();
        self.ray_origin.write_clock.next = self.clock.val();
        self.ray_mant.read_clock.next = self.clock.val();
        self.ray_mant.write_clock.next = self.clock.val();
        self.ray_shift.read_clock.next = self.clock.val();
        self.ray_shift.write_clock.next = self.clock.val();
        self.ray_t_min.read_clock.next = self.clock.val();
        self.ray_t_min.write_clock.next = self.clock.val();
        self.ray_t_max.read_clock.next = self.clock.val();
        self.ray_t_max.write_clock.next = self.clock.val();

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

        // ---- a whole ray enters the first free context ------------------------------------
        self.free_found.next = false;
        self.free_ctx.next = 0.into();
        for i in 0..RAYS_IN_FLIGHT {
            if (self.state[i].q.val() == ContextState::Free) & !self.free_found.val() {
                self.free_found.next = true;
                self.free_ctx.next = i.to_bits::<CTX_BITS>();
            }
        }
        self.accept.next = self.ray_full.q.val() & self.free_found.val();
        self.limit_in.next = self.node_count.val();
        if self.node_count.val() > self.max_nodes.val() {
            self.limit_in.next = self.max_nodes.val();
        }
        self.ray_origin.write_address.next = self.free_ctx.val();
        self.ray_mant.write_address.next = self.free_ctx.val();
        self.ray_shift.write_address.next = self.free_ctx.val();
        self.ray_t_min.write_address.next = self.free_ctx.val();
        self.ray_t_max.write_address.next = self.free_ctx.val();
        self.ray_origin.write_data.next = self.front.origin.val();
        self.ray_mant.write_data.next = self.front.mant.val();
        self.ray_shift.write_data.next = self.front.shift.val();
        self.ray_t_min.write_data.next = self.front.t_min.val();
        self.ray_t_max.write_data.next = self.front.t_max.val();
        self.ray_origin.write_enable.next = self.accept.val();
        self.ray_mant.write_enable.next = self.accept.val();
        self.ray_shift.write_enable.next = self.accept.val();
        self.ray_t_min.write_enable.next = self.accept.val();
        self.ray_t_max.write_enable.next = self.accept.val();
        if self.accept.val() {
            self.ray_full.d.next = false;
            self.tag_count.d.next = self.tag_count.q.val() + 1;
        }
        for i in 0..RAYS_IN_FLIGHT {
            if self.accept.val() & (self.free_ctx.val().index() == i) {
                self.tag[i].d.next = self.tag_count.q.val();
                self.near_first[i].d.next = !self.order.val();
                self.node_limit[i].d.next = self.limit_in.val();
                self.current[i].d.next = 0.into();
                self.visits[i].d.next = 0.into();
                self.sp[i].d.next = 0.into();
                self.candidates[i].d.next = 0.into();
                self.refusal[i].d.next = 0.into();
                // `traverse`: an unrepresentable ray, then node 0 beyond the memory.
                if !self.front.representable.val() {
                    self.refusal[i].d.next = self.unrepresentable.val();
                    self.state[i].d.next = ContextState::End;
                } else if !self.limit_in.val().any() {
                    self.refusal[i].d.next = self.bad_reference.val();
                    self.state[i].d.next = ContextState::End;
                } else {
                    self.state[i].d.next = ContextState::Visit;
                }
            }
        }

        // ---- issue: the first ready context (lowest index), when the FIFO has room for this
        // operation's word and every word in flight. An issued context is busy for
        // `PIPELINE_CLOCKS` clocks and `RAYS_IN_FLIGHT` is larger, so a ready context waits
        // at most `RAYS_IN_FLIGHT - 1` clocks for the others (FIFO stalls aside). ---------
        self.fill.next = self.write_ptr.q.val() - self.read_ptr.q.val();
        self.committed.next =
            self.fill.val() + bit_cast::<POINTER_BITS, INFLIGHT_BITS>(self.inflight.q.val());
        self.issue_found.next = false;
        self.issue_ctx.next = 0.into();
        self.issue_op.next = ContextState::Free;
        for i in 0..RAYS_IN_FLIGHT {
            if (self.state[i].q.val() != ContextState::Free)
                & (self.state[i].q.val() != ContextState::Busy)
                & !self.issue_found.val()
            {
                self.issue_found.next = true;
                self.issue_ctx.next = i.to_bits::<CTX_BITS>();
                self.issue_op.next = self.state[i].q.val();
            }
        }
        self.issue.next = self.issue_found.val() & (self.committed.val() < self.fifo_size.val());
        self.issue_current.next = 0.into();
        for i in 0..RAYS_IN_FLIGHT {
            if self.issue_ctx.val().index() == i {
                self.issue_current.next = self.current[i].q.val();
            }
            if self.issue.val() & (self.issue_ctx.val().index() == i) {
                self.state[i].d.next = ContextState::Busy;
            }
        }
        // The node and the ray's fields are on the RAMs' outputs at the next clock.
        self.lower0.read_address.next = self.issue_current.val();
        self.upper0.read_address.next = self.issue_current.val();
        self.lower1.read_address.next = self.issue_current.val();
        self.upper1.read_address.next = self.issue_current.val();
        self.ray_origin.read_address.next = self.issue_ctx.val();
        self.ray_mant.read_address.next = self.issue_ctx.val();
        self.ray_shift.read_address.next = self.issue_ctx.val();
        self.ray_t_min.read_address.next = self.issue_ctx.val();
        self.ray_t_max.read_address.next = self.issue_ctx.val();
        self.p_valid[0].d.next = self.issue.val();
        self.p_ctx[0].d.next = self.issue_ctx.val();
        self.p_op[0].d.next = self.issue_op.val();
        for s in 1..STAGES {
            self.p_valid[s].d.next = self.p_valid[s - 1].q.val();
            self.p_ctx[s].d.next = self.p_ctx[s - 1].q.val();
            self.p_op[s].d.next = self.p_op[s - 1].q.val();
        }

        // ---- stage 0: a visit's node and ray into the lanes -------------------------------
        // Per axis, the entry plane is the lower corner where the mantissa is positive (the
        // front end's `lower_is_entry`; a kept ray's mantissa is never 0, so its sign decides).
        self.lower_is_entry.next = 0.into();
        if !self.ray_mant.read_data.val().get_bit(24) {
            self.lower_is_entry.next = self.axis_mask_x.val();
        }
        if !self.ray_mant.read_data.val().get_bit(49) {
            self.lower_is_entry.next = self.lower_is_entry.val() | self.axis_mask_y.val();
        }
        if !self.ray_mant.read_data.val().get_bit(74) {
            self.lower_is_entry.next = self.lower_is_entry.val() | self.axis_mask_z.val();
        }
        self.lanes[0].entry_plane.next = (self.lower0.read_data.val() & self.lower_is_entry.val())
            | (self.upper0.read_data.val() & !self.lower_is_entry.val());
        self.lanes[0].exit_plane.next = (self.upper0.read_data.val() & self.lower_is_entry.val())
            | (self.lower0.read_data.val() & !self.lower_is_entry.val());
        self.lanes[1].entry_plane.next = (self.lower1.read_data.val() & self.lower_is_entry.val())
            | (self.upper1.read_data.val() & !self.lower_is_entry.val());
        self.lanes[1].exit_plane.next = (self.upper1.read_data.val() & self.lower_is_entry.val())
            | (self.lower1.read_data.val() & !self.lower_is_entry.val());
        for c in 0..2 {
            self.lanes[c].clock.next = self.clock.val();
            self.lanes[c].in_valid.next =
                self.p_valid[0].q.val() & (self.p_op[0].q.val() == ContextState::Visit);
            self.lanes[c].in_index.next = 0.into();
            self.lanes[c].origin.next = self.ray_origin.read_data.val();
            self.lanes[c].mant.next = self.ray_mant.read_data.val();
            self.lanes[c].shift.next = self.ray_shift.read_data.val();
            self.lanes[c].t_min.next = self.ray_t_min.read_data.val();
            self.lanes[c].t_max.next = self.ray_t_max.read_data.val();
        }

        // ---- the stage before the completion: its stack top and node references read -----
        // (the context's registers and stack region cannot change while it is in flight)
        self.pre_ctx.next = self.p_ctx[5].q.val();
        self.pre_sp.next = 0.into();
        self.pre_current.next = 0.into();
        for i in 0..RAYS_IN_FLIGHT {
            if self.pre_ctx.val().index() == i {
                self.pre_sp.next = self.sp[i].q.val();
                self.pre_current.next = self.current[i].q.val();
            }
        }
        self.pre_sp_below.next = self.pre_sp.val() - 1;
        self.stack.read_address.next = (bit_cast::<STACK_RAM_BITS, CTX_BITS>(self.pre_ctx.val())
            << 5)
            | bit_cast::<STACK_RAM_BITS, STACK_ADDRESS_BITS>(
                self.pre_sp_below.val().get_bits::<STACK_ADDRESS_BITS>(0),
            );
        self.references.read_address.next = self.pre_current.val();

        // ---- completion: one context's operation decides ----------------------------------
        self.done.next = self.p_valid[6].q.val();
        self.done_ctx.next = self.p_ctx[6].q.val();
        self.done_op.next = self.p_op[6].q.val();
        self.c_visits.next = 0.into();
        self.c_sp.next = 0.into();
        self.c_candidates.next = 0.into();
        self.c_refusal.next = 0.into();
        self.c_tag.next = 0.into();
        self.c_limit.next = 0.into();
        self.c_near_first.next = false;
        for i in 0..RAYS_IN_FLIGHT {
            if self.done_ctx.val().index() == i {
                self.c_visits.next = self.visits[i].q.val();
                self.c_sp.next = self.sp[i].q.val();
                self.c_candidates.next = self.candidates[i].q.val();
                self.c_refusal.next = self.refusal[i].q.val();
                self.c_tag.next = self.tag[i].q.val();
                self.c_limit.next = self.node_limit[i].q.val();
                self.c_near_first.next = self.near_first[i].q.val();
            }
        }
        // The lanes' answers for the node's two children, as stack entries.
        self.hit0.next = self.references.read_data.val().get_bit(15) & self.lanes[0].out_hit.val();
        self.hit1.next = self.references.read_data.val().get_bit(31) & self.lanes[1].out_hit.val();
        self.entry0.next = bit_cast::<ENTRY_BITS, TB>(self.lanes[0].out_t_near.val())
            | (bit_cast::<ENTRY_BITS, 16>(self.references.read_data.val().get_bits::<16>(0)) << 32);
        self.entry1.next = bit_cast::<ENTRY_BITS, TB>(self.lanes[1].out_t_near.val())
            | (bit_cast::<ENTRY_BITS, 16>(self.references.read_data.val().get_bits::<16>(16))
                << 32);
        // Near-first: child 1 first only when both are hit and it is entered strictly first.
        self.swap.next = self.c_near_first.val()
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
        self.limit_index.next = bit_cast::<INDEX_BITS, NODE_COUNT_BITS>(self.c_limit.val());

        self.n_state.next = ContextState::End;
        self.n_current.next = 0.into();
        self.n_visits.next = self.c_visits.val();
        self.n_sp.next = self.c_sp.val();
        self.n_candidates.next = self.c_candidates.val();
        self.n_refusal.next = self.c_refusal.val();
        self.take.next = false;
        self.take_entry.next = self.first.val();
        self.emit.next = false;
        self.stack.write_enable.next = false;
        self.stack.write_address.next = (bit_cast::<STACK_RAM_BITS, CTX_BITS>(self.done_ctx.val())
            << 5)
            | bit_cast::<STACK_RAM_BITS, STACK_ADDRESS_BITS>(
                self.c_sp.val().get_bits::<STACK_ADDRESS_BITS>(0),
            );
        self.stack.write_data.next = self.second.val();
        self.fifo_write.next = false;
        self.results.write_address.next = self.write_ptr.q.val().get_bits::<OUTPUT_FIFO_BITS>(0);
        self.results.write_data.next = 0.into();

        match self.done_op.val() {
            ContextState::Visit => {
                self.n_visits.next = self.c_visits.val() + 1;
                if self.hit0.val() & self.hit1.val() & (self.c_sp.val() == self.stack_depth.val()) {
                    self.n_refusal.next = self.stack_overflow.val();
                } else {
                    if self.hit0.val() & self.hit1.val() {
                        self.stack.write_enable.next = self.done.val();
                        self.n_sp.next = self.c_sp.val() + 1;
                    }
                    self.take.next = self.hit0.val() | self.hit1.val();
                    self.take_entry.next = self.first.val();
                }
            }
            ContextState::Pop => {
                self.n_sp.next = self.c_sp.val() - 1;
                self.take.next = true;
                self.take_entry.next = self.stack.read_data.val();
            }
            ContextState::End => {
                self.n_state.next = ContextState::Free;
                self.fifo_write.next = self.done.val();
                self.results.write_data.next = self.end_flag.val()
                    | bit_cast::<RESULT_BITS, CANDIDATE_COUNT_BITS>(self.c_candidates.val())
                    | (bit_cast::<RESULT_BITS, REFUSAL_BITS>(self.c_refusal.val()) << 32)
                    | (bit_cast::<RESULT_BITS, TAG_WIDTH>(self.c_tag.val()) << 40);
            }
            _ => {}
        }
        // The reference taken: a leaf is written, then the stack's top is next (or the end);
        // a node is visited unless it lies beyond the memory or one visit would be too many.
        if (self.done_op.val() == ContextState::Visit) | (self.done_op.val() == ContextState::Pop) {
            if self.n_refusal.val().any() {
                self.n_state.next = ContextState::End;
            } else if self.take.val() & !self.take_entry.val().get_bit(46) {
                self.n_current.next = self.take_entry.val().get_bits::<NODE_ADDRESS_BITS>(32);
                if self.take_entry.val().get_bits::<INDEX_BITS>(32) >= self.limit_index.val() {
                    self.n_refusal.next = self.bad_reference.val();
                    self.n_state.next = ContextState::End;
                } else if self.n_visits.val() >= self.c_limit.val() {
                    self.n_refusal.next = self.runaway.val();
                    self.n_state.next = ContextState::End;
                } else {
                    self.n_state.next = ContextState::Visit;
                }
            } else {
                if self.take.val() {
                    self.emit.next = true;
                    self.n_candidates.next = self.c_candidates.val() + 1;
                }
                self.n_state.next = ContextState::End;
                if self.n_sp.val().any() {
                    self.n_state.next = ContextState::Pop;
                }
            }
        }
        if self.emit.val() {
            self.fifo_write.next = self.done.val();
            self.results.write_data.next =
                bit_cast::<RESULT_BITS, 46>(self.take_entry.val().get_bits::<46>(0))
                    | (bit_cast::<RESULT_BITS, TAG_WIDTH>(self.c_tag.val()) << 46);
        }
        self.results.write_enable.next = self.fifo_write.val();
        if self.fifo_write.val() {
            self.write_ptr.d.next = self.write_ptr.q.val() + 1;
        }
        for i in 0..RAYS_IN_FLIGHT {
            if self.done.val() & (self.done_ctx.val().index() == i) {
                self.state[i].d.next = self.n_state.val();
                self.current[i].d.next = self.n_current.val();
                self.visits[i].d.next = self.n_visits.val();
                self.sp[i].d.next = self.n_sp.val();
                self.candidates[i].d.next = self.n_candidates.val();
                self.refusal[i].d.next = self.n_refusal.val();
            }
        }
        // Operations in flight: one in at the issue, one out at the completion.
        if self.issue.val() & !self.done.val() {
            self.inflight.d.next = self.inflight.q.val() + 1;
        }
        if !self.issue.val() & self.done.val() {
            self.inflight.d.next = self.inflight.q.val() - 1;
        }

        // ---- results out: the FIFO read at the next clock's pointer ----------------------
        self.read_ptr_next.next = self.read_ptr.q.val();
        if self.head_valid.q.val() & self.result_ready.val() {
            self.read_ptr_next.next = self.read_ptr.q.val() + 1;
        }
        self.read_ptr.d.next = self.read_ptr_next.val();
        self.results.read_address.next = self.read_ptr_next.val().get_bits::<OUTPUT_FIFO_BITS>(0);
        // Words before the write pointer were written at an earlier edge.
        self.head_valid.d.next = self.read_ptr_next.val() != self.write_ptr.q.val();
        self.head.next = 0.into();
        if self.head_valid.q.val() {
            self.head.next = self.results.read_data.val();
        }
        self.result_valid.next = self.head_valid.q.val();
        self.result_data.next = bit_cast::<64, 54>(self.head.val().get_bits::<54>(0))
            | (bit_cast::<64, 1>(self.head.val().get_bits::<1>(54)) << 63);

        self.any_context.next = false;
        for i in 0..RAYS_IN_FLIGHT {
            if self.state[i].q.val() != ContextState::Free {
                self.any_context.next = true;
            }
        }
        self.is_busy.next = self.any_context.val()
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
