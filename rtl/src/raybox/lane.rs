//! One slab-test lane: a work item in, one (hit, t_near) out, one test per clock, fixed
//! latency. The arithmetic is the golden model's (`skylux_regmap::raybox_format::test`).

use super::plane::{PlaneDistance, PlaneProduct, PRODUCT_BITS};
use rust_hdl::prelude::*;
use skylux_regmap::raybox_format::{COORD_BITS, INDEX_BITS, MANT_BITS, SHIFT_BITS, T_BITS};

const CB: usize = COORD_BITS as usize;
const MB: usize = MANT_BITS as usize;
const SB: usize = SHIFT_BITS as usize;
const TB: usize = T_BITS as usize;
const IB: usize = INDEX_BITS as usize;
const CB3: usize = 3 * CB;
// The unpacking below is written with these offsets.
const _: () = assert!(CB == 21 && MB == 25 && SB == 6);
const MB3: usize = 3 * MB;
const SB3: usize = 3 * SB;

/// Clock edges from the edge that takes an item (`in_valid` high) to the one after which its
/// result is on `out_*` with `out_valid` high.
pub const LANE_LATENCY: usize = 6;

/// The slab test, pipelined:
///
/// 1. inputs registered;
/// 2. six plane products `(plane - origin) × mant` registered (DSP blocks);
/// 3. six distances, shifted, rounded outward and saturated, registered;
/// 4. pairwise max of the entries and `t_min`, min of the exits and `t_max`;
/// 5. `t_near`, `t_far`;
/// 6. `hit = t_near <= t_far`, registered on the outputs.
///
/// Signed compares flip the sign bit and compare unsigned (rust-hdl-notes §3).
#[derive(LogicBlock)]
pub struct SlabLane {
    pub clock: Signal<In, Clock>,
    pub in_valid: Signal<In, Bit>,
    pub in_index: Signal<In, Bits<IB>>,
    /// Per-axis fields packed x, y, z from bit 0 (a parent cannot index an array port of a
    /// child in rust-hdl's Verilog, so the ports are flat).
    pub origin: Signal<In, Bits<CB3>>,
    pub entry_plane: Signal<In, Bits<CB3>>,
    pub exit_plane: Signal<In, Bits<CB3>>,
    pub mant: Signal<In, Bits<MB3>>,
    pub shift: Signal<In, Bits<SB3>>,
    pub t_min: Signal<In, Bits<TB>>,
    pub t_max: Signal<In, Bits<TB>>,
    pub out_valid: Signal<Out, Bit>,
    pub out_index: Signal<Out, Bits<IB>>,
    pub out_hit: Signal<Out, Bit>,
    pub out_t_near: Signal<Out, Bits<TB>>,

    entry_mul: [PlaneProduct; 3],
    exit_mul: [PlaneProduct; 3],
    entry_dist: [PlaneDistance<0>; 3],
    exit_dist: [PlaneDistance<1>; 3],
    // stage 1
    s1_origin: [DFF<Bits<CB>>; 3],
    s1_entry: [DFF<Bits<CB>>; 3],
    s1_exit: [DFF<Bits<CB>>; 3],
    s1_mant: [DFF<Bits<MB>>; 3],
    s1_shift: [DFF<Bits<SB>>; 3],
    s1_t_min: DFF<Bits<TB>>,
    s1_t_max: DFF<Bits<TB>>,
    s1_valid: DFF<Bit>,
    s1_index: DFF<Bits<IB>>,
    // stage 2
    s2_entry: [DFF<Bits<PRODUCT_BITS>>; 3],
    s2_exit: [DFF<Bits<PRODUCT_BITS>>; 3],
    s2_shift: [DFF<Bits<SB>>; 3],
    s2_t_min: DFF<Bits<TB>>,
    s2_t_max: DFF<Bits<TB>>,
    s2_valid: DFF<Bit>,
    s2_index: DFF<Bits<IB>>,
    // stage 3
    s3_entry: [DFF<Bits<TB>>; 3],
    s3_exit: [DFF<Bits<TB>>; 3],
    s3_t_min: DFF<Bits<TB>>,
    s3_t_max: DFF<Bits<TB>>,
    s3_valid: DFF<Bit>,
    s3_index: DFF<Bits<IB>>,
    // stage 4
    s4_near_xy: DFF<Bits<TB>>,
    s4_near_z: DFF<Bits<TB>>,
    s4_far_xy: DFF<Bits<TB>>,
    s4_far_z: DFF<Bits<TB>>,
    s4_valid: DFF<Bit>,
    s4_index: DFF<Bits<IB>>,
    // stage 5
    s5_near: DFF<Bits<TB>>,
    s5_far: DFF<Bits<TB>>,
    s5_valid: DFF<Bit>,
    s5_index: DFF<Bits<IB>>,
    // stage 6
    s6_hit: DFF<Bit>,
    s6_near: DFF<Bits<TB>>,
    s6_valid: DFF<Bit>,
    s6_index: DFF<Bits<IB>>,
    sign: Constant<Bits<TB>>,
}

impl Default for SlabLane {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            in_valid: Default::default(),
            in_index: Default::default(),
            origin: Default::default(),
            entry_plane: Default::default(),
            exit_plane: Default::default(),
            mant: Default::default(),
            shift: Default::default(),
            t_min: Default::default(),
            t_max: Default::default(),
            out_valid: Default::default(),
            out_index: Default::default(),
            out_hit: Default::default(),
            out_t_near: Default::default(),
            entry_mul: Default::default(),
            exit_mul: Default::default(),
            entry_dist: Default::default(),
            exit_dist: Default::default(),
            s1_origin: Default::default(),
            s1_entry: Default::default(),
            s1_exit: Default::default(),
            s1_mant: Default::default(),
            s1_shift: Default::default(),
            s1_t_min: Default::default(),
            s1_t_max: Default::default(),
            s1_valid: Default::default(),
            s1_index: Default::default(),
            s2_entry: Default::default(),
            s2_exit: Default::default(),
            s2_shift: Default::default(),
            s2_t_min: Default::default(),
            s2_t_max: Default::default(),
            s2_valid: Default::default(),
            s2_index: Default::default(),
            s3_entry: Default::default(),
            s3_exit: Default::default(),
            s3_t_min: Default::default(),
            s3_t_max: Default::default(),
            s3_valid: Default::default(),
            s3_index: Default::default(),
            s4_near_xy: Default::default(),
            s4_near_z: Default::default(),
            s4_far_xy: Default::default(),
            s4_far_z: Default::default(),
            s4_valid: Default::default(),
            s4_index: Default::default(),
            s5_near: Default::default(),
            s5_far: Default::default(),
            s5_valid: Default::default(),
            s5_index: Default::default(),
            s6_hit: Default::default(),
            s6_near: Default::default(),
            s6_valid: Default::default(),
            s6_index: Default::default(),
            sign: Constant::new((1u64 << (TB - 1)).to_bits()),
        }
    }
}

impl Logic for SlabLane {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, s1_t_min, s1_t_max, s1_valid, s1_index, s2_t_min, s2_t_max, s2_valid,
            s2_index, s3_t_min, s3_t_max, s3_valid, s3_index, s4_near_xy, s4_near_z, s4_far_xy,
            s4_far_z, s4_valid, s4_index, s5_near, s5_far, s5_valid, s5_index, s6_hit, s6_near,
            s6_valid, s6_index
        );
        for i in 0..3 {
            self.s1_origin[i].clock.next = self.clock.val();
            self.s1_entry[i].clock.next = self.clock.val();
            self.s1_exit[i].clock.next = self.clock.val();
            self.s1_mant[i].clock.next = self.clock.val();
            self.s1_shift[i].clock.next = self.clock.val();
            self.s2_entry[i].clock.next = self.clock.val();
            self.s2_exit[i].clock.next = self.clock.val();
            self.s2_shift[i].clock.next = self.clock.val();
            self.s3_entry[i].clock.next = self.clock.val();
            self.s3_exit[i].clock.next = self.clock.val();
            // stage 2: products
            self.entry_mul[i].plane.next = self.s1_entry[i].q.val();
            self.entry_mul[i].origin.next = self.s1_origin[i].q.val();
            self.entry_mul[i].mant.next = self.s1_mant[i].q.val();
            self.exit_mul[i].plane.next = self.s1_exit[i].q.val();
            self.exit_mul[i].origin.next = self.s1_origin[i].q.val();
            self.exit_mul[i].mant.next = self.s1_mant[i].q.val();
            self.s2_entry[i].d.next = self.entry_mul[i].product.val();
            self.s2_exit[i].d.next = self.exit_mul[i].product.val();
            self.s2_shift[i].d.next = self.s1_shift[i].q.val();
            // stage 3: distances
            self.entry_dist[i].product.next = self.s2_entry[i].q.val();
            self.entry_dist[i].shift.next = self.s2_shift[i].q.val();
            self.exit_dist[i].product.next = self.s2_exit[i].q.val();
            self.exit_dist[i].shift.next = self.s2_shift[i].q.val();
            self.s3_entry[i].d.next = self.entry_dist[i].t.val();
            self.s3_exit[i].d.next = self.exit_dist[i].t.val();
        }
        // stage 1: inputs, unpacked per axis
        self.s1_origin[0].d.next = self.origin.val().get_bits::<CB>(0);
        self.s1_origin[1].d.next = self.origin.val().get_bits::<CB>(21);
        self.s1_origin[2].d.next = self.origin.val().get_bits::<CB>(42);
        self.s1_entry[0].d.next = self.entry_plane.val().get_bits::<CB>(0);
        self.s1_entry[1].d.next = self.entry_plane.val().get_bits::<CB>(21);
        self.s1_entry[2].d.next = self.entry_plane.val().get_bits::<CB>(42);
        self.s1_exit[0].d.next = self.exit_plane.val().get_bits::<CB>(0);
        self.s1_exit[1].d.next = self.exit_plane.val().get_bits::<CB>(21);
        self.s1_exit[2].d.next = self.exit_plane.val().get_bits::<CB>(42);
        self.s1_mant[0].d.next = self.mant.val().get_bits::<MB>(0);
        self.s1_mant[1].d.next = self.mant.val().get_bits::<MB>(25);
        self.s1_mant[2].d.next = self.mant.val().get_bits::<MB>(50);
        self.s1_shift[0].d.next = self.shift.val().get_bits::<SB>(0);
        self.s1_shift[1].d.next = self.shift.val().get_bits::<SB>(6);
        self.s1_shift[2].d.next = self.shift.val().get_bits::<SB>(12);
        self.s1_t_min.d.next = self.t_min.val();
        self.s1_t_max.d.next = self.t_max.val();
        self.s1_valid.d.next = self.in_valid.val();
        self.s1_index.d.next = self.in_index.val();
        self.s2_t_min.d.next = self.s1_t_min.q.val();
        self.s2_t_max.d.next = self.s1_t_max.q.val();
        self.s2_valid.d.next = self.s1_valid.q.val();
        self.s2_index.d.next = self.s1_index.q.val();
        self.s3_t_min.d.next = self.s2_t_min.q.val();
        self.s3_t_max.d.next = self.s2_t_max.q.val();
        self.s3_valid.d.next = self.s2_valid.q.val();
        self.s3_index.d.next = self.s2_index.q.val();

        // stage 4: pairwise reductions (signed, by flipping the sign bit)
        self.s4_near_xy.d.next = self.s3_entry[0].q.val();
        if (self.s3_entry[1].q.val() ^ self.sign.val())
            > (self.s3_entry[0].q.val() ^ self.sign.val())
        {
            self.s4_near_xy.d.next = self.s3_entry[1].q.val();
        }
        self.s4_near_z.d.next = self.s3_t_min.q.val();
        if (self.s3_entry[2].q.val() ^ self.sign.val()) > (self.s3_t_min.q.val() ^ self.sign.val())
        {
            self.s4_near_z.d.next = self.s3_entry[2].q.val();
        }
        self.s4_far_xy.d.next = self.s3_exit[0].q.val();
        if (self.s3_exit[1].q.val() ^ self.sign.val()) < (self.s3_exit[0].q.val() ^ self.sign.val())
        {
            self.s4_far_xy.d.next = self.s3_exit[1].q.val();
        }
        self.s4_far_z.d.next = self.s3_t_max.q.val();
        if (self.s3_exit[2].q.val() ^ self.sign.val()) < (self.s3_t_max.q.val() ^ self.sign.val()) {
            self.s4_far_z.d.next = self.s3_exit[2].q.val();
        }
        self.s4_valid.d.next = self.s3_valid.q.val();
        self.s4_index.d.next = self.s3_index.q.val();

        // stage 5
        self.s5_near.d.next = self.s4_near_xy.q.val();
        if (self.s4_near_z.q.val() ^ self.sign.val()) > (self.s4_near_xy.q.val() ^ self.sign.val())
        {
            self.s5_near.d.next = self.s4_near_z.q.val();
        }
        self.s5_far.d.next = self.s4_far_xy.q.val();
        if (self.s4_far_z.q.val() ^ self.sign.val()) < (self.s4_far_xy.q.val() ^ self.sign.val()) {
            self.s5_far.d.next = self.s4_far_z.q.val();
        }
        self.s5_valid.d.next = self.s4_valid.q.val();
        self.s5_index.d.next = self.s4_index.q.val();

        // stage 6: decision
        self.s6_hit.d.next =
            (self.s5_near.q.val() ^ self.sign.val()) <= (self.s5_far.q.val() ^ self.sign.val());
        self.s6_near.d.next = self.s5_near.q.val();
        self.s6_valid.d.next = self.s5_valid.q.val();
        self.s6_index.d.next = self.s5_index.q.val();

        self.out_valid.next = self.s6_valid.q.val();
        self.out_index.next = self.s6_index.q.val();
        self.out_hit.next = self.s6_hit.q.val();
        self.out_t_near.next = self.s6_near.q.val();
    }
}
