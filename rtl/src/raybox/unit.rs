//! The ray-box unit: a streaming front end that reads work items from SDRAM through an
//! Avalon-MM host port, feeds the slab lanes, and writes the results back.

use super::lane::SlabLane;
use rust_hdl::prelude::*;
use skylux_regmap::raybox_format::{
    COORD_BITS, INDEX_BITS, ITEM_MAGIC, ITEM_WORDS, MANT_BITS, SHIFT_BITS, T_BITS,
};

const CB: usize = COORD_BITS as usize;
const MB: usize = MANT_BITS as usize;
const SB: usize = SHIFT_BITS as usize;
const TB: usize = T_BITS as usize;
const IB: usize = INDEX_BITS as usize;
const CB3: usize = 3 * CB;
const MB2: usize = 2 * MB;
const MB3: usize = 3 * MB;
const SB2: usize = 2 * SB;
const SB3: usize = 3 * SB;

/// Width of the port's word address (64-bit f2sdram port: ADDRESS[28:0], hardware-facts §3.2).
pub const WORD_ADDRESS_BITS: usize = 29;
/// Depth of the read-data and result FIFOs, in 64-bit words.
pub const FIFO_DEPTH: usize = 16;
/// Most lanes the one-hot lane selector supports.
pub const MAX_LANES: usize = 16;

// The field positions below are written for this layout.
const _: () = assert!(
    ITEM_WORDS == 6
        && CB == 21
        && MB == 25
        && SB == 6
        && TB == 32
        && IB == 24
        && MB2 == 50
        && SB2 == 12,
    "the unit's word decoding follows skylux_regmap::raybox_format"
);

#[derive(Copy, Clone, PartialEq, Eq, Debug, LogicState)]
pub enum UnitState {
    /// Waiting for `ctrl_start`.
    Idle,
    /// One cycle: alignment and window checks of the latched batch.
    Check,
    /// Reading items, testing, writing results.
    Run,
    /// No more reads: discard read data, write the results still in flight.
    Finish,
}

/// The ray-box unit with `LANES` slab lanes (1 to [`MAX_LANES`]).
///
/// Configuration and status ports carry the `raybox.*` register fields
/// (`<register>_<field>`; pulses `..._set` set the W1C status bits). The Avalon-MM host port
/// `rbx_*` uses 64-bit word addresses, as f2sdram port 1 (bitstream/quartus/core_ports.md).
///
/// A batch: `ctrl_start` latches `work_base`, `work_count` and `result_base`. The next cycle
/// checks them: a base not 8-byte aligned sets BAD_DESCRIPTOR, a work or result region not
/// inside `[window_base, window_base + window_size)` sets OUT_OF_WINDOW; either ends the batch
/// before any access. Otherwise items are read as one 6-beat burst each, at most
/// `FIFO_DEPTH` words reserved ahead; each complete item whose magic byte is right goes to the
/// next lane in turn; each result is written as a single beat. An item with a wrong magic
/// byte sets BAD_DESCRIPTOR and stops the reading; `ctrl_abort` does the same without the
/// flag. The results of the items already issued are still written, then DONE is pulsed. A
/// stall (waitrequest held, or read data awaited) of `bus_timeout_cycles` ends the batch at
/// once with BUS_TIMEOUT (0 disables the watchdog); read data of an abandoned burst that
/// still arrives later is discarded, counted by `stale`.
#[derive(LogicBlock)]
pub struct RayBoxUnit<const LANES: usize> {
    pub clock: Signal<In, Clock>,
    /// `raybox.ctrl.START` (one-cycle pulse).
    pub ctrl_start: Signal<In, Bit>,
    /// `raybox.ctrl.ABORT` (one-cycle pulse).
    pub ctrl_abort: Signal<In, Bit>,
    pub work_base_addr: Signal<In, Bits<32>>,
    pub work_count_items: Signal<In, Bits<IB>>,
    pub result_base_addr: Signal<In, Bits<32>>,
    pub window_base_addr: Signal<In, Bits<32>>,
    pub window_size_bytes: Signal<In, Bits<32>>,
    pub bus_timeout_cycles: Signal<In, Bits<24>>,
    pub status_busy: Signal<Out, Bit>,
    pub status_done_set: Signal<Out, Bit>,
    pub status_bad_descriptor_set: Signal<Out, Bit>,
    pub status_out_of_window_set: Signal<Out, Bit>,
    pub status_bus_timeout_set: Signal<Out, Bit>,
    pub tests_done_count: Signal<Out, Bits<32>>,
    pub info_lanes: Signal<Out, Bits<8>>,
    pub rbx_address: Signal<Out, Bits<WORD_ADDRESS_BITS>>,
    pub rbx_burstcount: Signal<Out, Bits<8>>,
    pub rbx_read: Signal<Out, Bit>,
    pub rbx_write: Signal<Out, Bit>,
    pub rbx_writedata: Signal<Out, Bits<64>>,
    pub rbx_byteenable: Signal<Out, Bits<8>>,
    pub rbx_waitrequest: Signal<In, Bit>,
    pub rbx_readdata: Signal<In, Bits<64>>,
    pub rbx_readdatavalid: Signal<In, Bit>,

    lanes: [SlabLane; LANES],
    read_fifo: SynchronousFIFO<Bits<64>, 4, 5, 1>,
    result_fifo: SynchronousFIFO<Bits<64>, 4, 5, 1>,

    state: DFF<UnitState>,
    base_work: DFF<Bits<32>>,
    base_result: DFF<Bits<32>>,
    count: DFF<Bits<IB>>,
    work_addr: DFF<Bits<WORD_ADDRESS_BITS>>,
    result_addr: DFF<Bits<WORD_ADDRESS_BITS>>,
    requested: DFF<Bits<IB>>,
    issued: DFF<Bits<IB>>,
    written: DFF<Bits<IB>>,
    reserved: DFF<Bits<5>>,
    outstanding: DFF<Bits<5>>,
    stale: DFF<Bits<5>>,
    in_flight: DFF<Bits<5>>,
    word_index: DFF<Bits<3>>,
    item_ready: DFF<Bit>,
    lane_select: DFF<Bits<MAX_LANES>>,
    watchdog: DFF<Bits<24>>,
    refused: DFF<Bit>,
    cmd_read: DFF<Bit>,
    cmd_write: DFF<Bit>,
    cmd_addr: DFF<Bits<WORD_ADDRESS_BITS>>,
    cmd_burst: DFF<Bits<8>>,
    cmd_data: DFF<Bits<64>>,
    done_pulse: DFF<Bit>,
    bad_pulse: DFF<Bit>,
    window_pulse: DFF<Bit>,
    timeout_pulse: DFF<Bit>,
    // The item being assembled, per-axis fields packed x, y, z as the lanes take them.
    origin: DFF<Bits<CB3>>,
    entry_plane: DFF<Bits<CB3>>,
    exit_plane: DFF<Bits<CB3>>,
    mant_xy: DFF<Bits<MB2>>,
    mant_z: DFF<Bits<MB>>,
    shift_xy: DFF<Bits<SB2>>,
    shift_z: DFF<Bits<SB>>,
    t_min: DFF<Bits<TB>>,
    t_max: DFF<Bits<TB>>,

    // combinational temporaries
    work_lo: Signal<Local, Bits<34>>,
    work_hi: Signal<Local, Bits<34>>,
    result_lo: Signal<Local, Bits<34>>,
    result_hi: Signal<Local, Bits<34>>,
    window_lo: Signal<Local, Bits<34>>,
    window_hi: Signal<Local, Bits<34>>,
    count_wide: Signal<Local, Bits<34>>,
    accepted: Signal<Local, Bit>,
    cmd_free: Signal<Local, Bit>,
    beat: Signal<Local, Bit>,
    issue: Signal<Local, Bit>,
    pop: Signal<Local, Bit>,
    head: Signal<Local, Bits<64>>,
    reserved_n: Signal<Local, Bits<5>>,
    outstanding_n: Signal<Local, Bits<5>>,
    in_flight_n: Signal<Local, Bits<5>>,
    lane_valid: Signal<Local, Bit>,
    lane_hit: Signal<Local, Bit>,
    lane_index: Signal<Local, Bits<IB>>,
    lane_t_near: Signal<Local, Bits<TB>>,
    waiting: Signal<Local, Bit>,
    watchdog_n: Signal<Local, Bits<24>>,
    timed_out: Signal<Local, Bit>,
    more_to_read: Signal<Local, Bit>,
    room_to_read: Signal<Local, Bit>,
    lanes_value: Constant<Bits<8>>,
    last_lane: Constant<Bits<MAX_LANES>>,
    magic: Constant<Bits<8>>,
    item_words_addr: Constant<Bits<WORD_ADDRESS_BITS>>,
    item_words_burst: Constant<Bits<8>>,
    item_words_count: Constant<Bits<5>>,
    read_limit: Constant<Bits<5>>,
    fifo_depth: Constant<Bits<5>>,
}

impl<const LANES: usize> RayBoxUnit<LANES> {
    /// A compile-time check: `LANES` must be 1 to [`MAX_LANES`].
    const LANES_IN_RANGE: () = assert!(LANES >= 1 && LANES <= MAX_LANES);
}

impl<const LANES: usize> Default for RayBoxUnit<LANES> {
    fn default() -> Self {
        let () = Self::LANES_IN_RANGE;
        Self {
            clock: Default::default(),
            ctrl_start: Default::default(),
            ctrl_abort: Default::default(),
            work_base_addr: Default::default(),
            work_count_items: Default::default(),
            result_base_addr: Default::default(),
            window_base_addr: Default::default(),
            window_size_bytes: Default::default(),
            bus_timeout_cycles: Default::default(),
            status_busy: Default::default(),
            status_done_set: Default::default(),
            status_bad_descriptor_set: Default::default(),
            status_out_of_window_set: Default::default(),
            status_bus_timeout_set: Default::default(),
            tests_done_count: Default::default(),
            info_lanes: Default::default(),
            rbx_address: Default::default(),
            rbx_burstcount: Default::default(),
            rbx_read: Default::default(),
            rbx_write: Default::default(),
            rbx_writedata: Default::default(),
            rbx_byteenable: Default::default(),
            rbx_waitrequest: Default::default(),
            rbx_readdata: Default::default(),
            rbx_readdatavalid: Default::default(),
            lanes: std::array::from_fn(|_| SlabLane::default()),
            read_fifo: Default::default(),
            result_fifo: Default::default(),
            state: Default::default(),
            base_work: Default::default(),
            base_result: Default::default(),
            count: Default::default(),
            work_addr: Default::default(),
            result_addr: Default::default(),
            requested: Default::default(),
            issued: Default::default(),
            written: Default::default(),
            reserved: Default::default(),
            outstanding: Default::default(),
            stale: Default::default(),
            in_flight: Default::default(),
            word_index: Default::default(),
            item_ready: Default::default(),
            lane_select: Default::default(),
            watchdog: Default::default(),
            refused: Default::default(),
            cmd_read: Default::default(),
            cmd_write: Default::default(),
            cmd_addr: Default::default(),
            cmd_burst: Default::default(),
            cmd_data: Default::default(),
            done_pulse: Default::default(),
            bad_pulse: Default::default(),
            window_pulse: Default::default(),
            timeout_pulse: Default::default(),
            origin: Default::default(),
            entry_plane: Default::default(),
            exit_plane: Default::default(),
            mant_xy: Default::default(),
            mant_z: Default::default(),
            shift_xy: Default::default(),
            shift_z: Default::default(),
            t_min: Default::default(),
            t_max: Default::default(),
            work_lo: Default::default(),
            work_hi: Default::default(),
            result_lo: Default::default(),
            result_hi: Default::default(),
            window_lo: Default::default(),
            window_hi: Default::default(),
            count_wide: Default::default(),
            accepted: Default::default(),
            cmd_free: Default::default(),
            beat: Default::default(),
            issue: Default::default(),
            pop: Default::default(),
            head: Default::default(),
            reserved_n: Default::default(),
            outstanding_n: Default::default(),
            in_flight_n: Default::default(),
            lane_valid: Default::default(),
            lane_hit: Default::default(),
            lane_index: Default::default(),
            lane_t_near: Default::default(),
            waiting: Default::default(),
            watchdog_n: Default::default(),
            timed_out: Default::default(),
            more_to_read: Default::default(),
            room_to_read: Default::default(),
            lanes_value: Constant::new((LANES as u64).to_bits()),
            last_lane: Constant::new((1u64 << (LANES - 1)).to_bits()),
            magic: Constant::new((ITEM_MAGIC as u64).to_bits()),
            item_words_addr: Constant::new((ITEM_WORDS as u64).to_bits()),
            item_words_burst: Constant::new((ITEM_WORDS as u64).to_bits()),
            item_words_count: Constant::new((ITEM_WORDS as u64).to_bits()),
            read_limit: Constant::new(((FIFO_DEPTH - ITEM_WORDS) as u64).to_bits()),
            fifo_depth: Constant::new((FIFO_DEPTH as u64).to_bits()),
        }
    }
}

impl<const LANES: usize> Logic for RayBoxUnit<LANES> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            state,
            base_work,
            base_result,
            count,
            work_addr,
            result_addr,
            requested,
            issued,
            written,
            reserved,
            outstanding,
            stale,
            in_flight,
            word_index,
            item_ready,
            lane_select,
            watchdog,
            refused,
            cmd_read,
            cmd_write,
            cmd_addr,
            cmd_burst,
            cmd_data,
            done_pulse,
            bad_pulse,
            window_pulse,
            timeout_pulse,
            t_min,
            t_max,
            origin,
            entry_plane,
            exit_plane,
            mant_xy,
            mant_z,
            shift_xy,
            shift_z
        );
        clock!(self, clock, read_fifo, result_fifo);
        // ---- defaults --------------------------------------------------------------------
        self.done_pulse.d.next = false;
        self.bad_pulse.d.next = false;
        self.window_pulse.d.next = false;
        self.timeout_pulse.d.next = false;
        self.read_fifo.write.next = false;
        self.read_fifo.read.next = false;
        self.read_fifo.data_in.next = self.rbx_readdata.val();
        self.result_fifo.write.next = false;
        self.result_fifo.read.next = false;
        self.head.next = self.read_fifo.data_out.val();

        // ---- the port: acceptance and returning read data ---------------------------------
        self.accepted.next =
            (self.cmd_read.q.val() | self.cmd_write.q.val()) & !self.rbx_waitrequest.val();
        self.cmd_free.next =
            !(self.cmd_read.q.val() | self.cmd_write.q.val()) | self.accepted.val();
        if self.accepted.val() {
            self.cmd_read.d.next = false;
            self.cmd_write.d.next = false;
        }
        self.beat.next = self.rbx_readdatavalid.val();
        self.outstanding_n.next = self.outstanding.q.val();
        if self.accepted.val() & self.cmd_read.q.val() {
            self.outstanding_n.next = self.outstanding_n.val() + self.item_words_count.val();
        }
        if self.beat.val() {
            // A beat nobody asked for (a faulty port) must not wrap the count.
            if self.outstanding_n.val().any() {
                self.outstanding_n.next = self.outstanding_n.val() - 1;
            }
            if self.stale.q.val().any() {
                self.stale.d.next = self.stale.q.val() - 1;
            } else if self.state.q.val() == UnitState::Run {
                self.read_fifo.write.next = true;
            }
        }
        self.outstanding.d.next = self.outstanding_n.val();

        // ---- watchdog: a command held under waitrequest, or read data awaited ------------
        self.waiting.next =
            self.cmd_read.q.val() | self.cmd_write.q.val() | self.outstanding.q.val().any();
        self.watchdog_n.next = 0.into();
        if self.waiting.val() & !self.accepted.val() & !self.beat.val() {
            self.watchdog_n.next = self.watchdog.q.val() + 1;
        }
        self.watchdog.d.next = self.watchdog_n.val();
        self.timed_out.next = self.bus_timeout_cycles.val().any()
            & (self.watchdog_n.val() == self.bus_timeout_cycles.val());

        // ---- lanes -----------------------------------------------------------------------
        self.issue.next = false;
        self.lane_valid.next = false;
        self.lane_hit.next = false;
        self.lane_index.next = 0.into();
        self.lane_t_near.next = 0.into();
        for i in 0..LANES {
            self.lanes[i].clock.next = self.clock.val();
            self.lanes[i].in_valid.next = false;
            self.lanes[i].in_index.next = self.issued.q.val();
            self.lanes[i].t_min.next = self.t_min.q.val();
            self.lanes[i].t_max.next = self.t_max.q.val();
            self.lanes[i].origin.next = self.origin.q.val();
            self.lanes[i].entry_plane.next = self.entry_plane.q.val();
            self.lanes[i].exit_plane.next = self.exit_plane.q.val();
            self.lanes[i].mant.next = bit_cast::<MB3, MB2>(self.mant_xy.q.val())
                | (bit_cast::<MB3, MB>(self.mant_z.q.val()) << 50);
            self.lanes[i].shift.next = bit_cast::<SB3, SB2>(self.shift_xy.q.val())
                | (bit_cast::<SB3, SB>(self.shift_z.q.val()) << 12);
            // Lanes take items in turn with equal latency, so at most one answers per cycle.
            if self.lanes[i].out_valid.val() {
                self.lane_valid.next = true;
                self.lane_hit.next = self.lanes[i].out_hit.val();
                self.lane_index.next = self.lanes[i].out_index.val();
                self.lane_t_near.next = self.lanes[i].out_t_near.val();
            }
        }
        self.result_fifo.data_in.next = bit_cast::<64, 32>(self.lane_t_near.val())
            | (bit_cast::<64, 24>(self.lane_index.val()) << 32)
            | (bit_cast::<64, 1>(self.lane_hit.val().into()) << 63);

        // ---- state machine ---------------------------------------------------------------
        self.reserved_n.next = self.reserved.q.val();
        self.in_flight_n.next = self.in_flight.q.val();
        self.pop.next = false;
        self.more_to_read.next = self.requested.q.val() < self.count.q.val();
        self.room_to_read.next = self.reserved.q.val() <= self.read_limit.val();
        self.count_wide.next = bit_cast::<34, 24>(self.count.q.val());
        self.work_lo.next = bit_cast::<34, 32>(self.base_work.q.val());
        self.work_hi.next =
            self.work_lo.val() + (self.count_wide.val() << 5) + (self.count_wide.val() << 4);
        self.result_lo.next = bit_cast::<34, 32>(self.base_result.q.val());
        self.result_hi.next = self.result_lo.val() + (self.count_wide.val() << 3);
        self.window_lo.next = bit_cast::<34, 32>(self.window_base_addr.val());
        self.window_hi.next =
            self.window_lo.val() + bit_cast::<34, 32>(self.window_size_bytes.val());

        match self.state.q.val() {
            UnitState::Idle => {
                // Flush whatever an abandoned batch left behind.
                self.read_fifo.read.next = !self.read_fifo.empty.val();
                self.result_fifo.read.next = !self.result_fifo.empty.val();
                if self.ctrl_start.val() {
                    self.base_work.d.next = self.work_base_addr.val();
                    self.base_result.d.next = self.result_base_addr.val();
                    self.count.d.next = self.work_count_items.val();
                    self.requested.d.next = 0.into();
                    self.issued.d.next = 0.into();
                    self.written.d.next = 0.into();
                    self.reserved_n.next = 0.into();
                    self.in_flight_n.next = 0.into();
                    self.word_index.d.next = 0.into();
                    self.item_ready.d.next = false;
                    self.refused.d.next = false;
                    self.lane_select.d.next = 1.into();
                    // Read data still due from an abandoned batch is not this batch's.
                    self.stale.d.next = self.outstanding_n.val();
                    self.state.d.next = UnitState::Check;
                }
            }
            UnitState::Check => {
                self.read_fifo.read.next = !self.read_fifo.empty.val();
                self.result_fifo.read.next = !self.result_fifo.empty.val();
                self.work_addr.d.next = self.base_work.q.val().get_bits::<WORD_ADDRESS_BITS>(3);
                self.result_addr.d.next = self.base_result.q.val().get_bits::<WORD_ADDRESS_BITS>(3);
                if self.base_work.q.val().get_bits::<3>(0).any()
                    | self.base_result.q.val().get_bits::<3>(0).any()
                {
                    self.bad_pulse.d.next = true;
                    self.done_pulse.d.next = true;
                    self.state.d.next = UnitState::Idle;
                } else if (self.work_lo.val() < self.window_lo.val())
                    | (self.work_hi.val() > self.window_hi.val())
                    | (self.result_lo.val() < self.window_lo.val())
                    | (self.result_hi.val() > self.window_hi.val())
                {
                    self.window_pulse.d.next = true;
                    self.done_pulse.d.next = true;
                    self.state.d.next = UnitState::Idle;
                } else if !self.count.q.val().any() {
                    self.done_pulse.d.next = true;
                    self.state.d.next = UnitState::Idle;
                } else {
                    self.state.d.next = UnitState::Run;
                }
            }
            UnitState::Run => {
                // Issue a complete item when the result FIFO is sure to have room for it.
                self.issue.next =
                    self.item_ready.q.val() & (self.in_flight.q.val() < self.fifo_depth.val());
                self.pop.next =
                    !self.read_fifo.empty.val() & (!self.item_ready.q.val() | self.issue.val());
                if self.ctrl_abort.val() {
                    self.pop.next = false;
                    self.state.d.next = UnitState::Finish;
                }
            }
            UnitState::Finish => {
                self.read_fifo.read.next = !self.read_fifo.empty.val();
                if !self.in_flight.q.val().any() & !self.cmd_read.q.val() & !self.cmd_write.q.val()
                {
                    self.done_pulse.d.next = true;
                    self.bad_pulse.d.next = self.refused.q.val();
                    self.state.d.next = UnitState::Idle;
                }
            }
        }

        // ---- issue to the selected lane --------------------------------------------------
        if self.issue.val() {
            for i in 0..LANES {
                if self.lane_select.q.val().get_bit(i) {
                    self.lanes[i].in_valid.next = true;
                }
            }
            self.lane_select.d.next = self.lane_select.q.val() << 1;
            if (self.lane_select.q.val() & self.last_lane.val()).any() {
                self.lane_select.d.next = 1.into();
            }
            self.issued.d.next = self.issued.q.val() + 1;
            self.in_flight_n.next = self.in_flight_n.val() + 1;
            self.item_ready.d.next = false;
            if self.issued.q.val() + 1 == self.count.q.val() {
                self.state.d.next = UnitState::Finish;
            }
        }

        // ---- assemble an item from the read FIFO -----------------------------------------
        if self.pop.val() {
            self.read_fifo.read.next = true;
            self.reserved_n.next = self.reserved_n.val() - 1;
            self.word_index.d.next = self.word_index.q.val() + 1;
            match self.word_index.q.val().index() {
                0 => {
                    self.origin.d.next = self.head.val().get_bits::<CB3>(0);
                }
                1 => {
                    self.entry_plane.d.next = self.head.val().get_bits::<CB3>(0);
                }
                2 => {
                    self.exit_plane.d.next = self.head.val().get_bits::<CB3>(0);
                }
                3 => {
                    self.mant_xy.d.next = self.head.val().get_bits::<MB2>(0);
                    self.shift_xy.d.next = self.head.val().get_bits::<SB2>(50);
                }
                4 => {
                    self.t_min.d.next = self.head.val().get_bits::<TB>(0);
                    self.t_max.d.next = self.head.val().get_bits::<TB>(32);
                }
                _ => {
                    self.mant_z.d.next = self.head.val().get_bits::<MB>(0);
                    self.shift_z.d.next = self.head.val().get_bits::<SB>(25);
                    self.word_index.d.next = 0.into();
                    if self.head.val().get_bits::<8>(56) == self.magic.val() {
                        self.item_ready.d.next = true;
                    } else {
                        // Refused: stop reading; the items before it are still answered.
                        self.refused.d.next = true;
                        self.state.d.next = UnitState::Finish;
                    }
                }
            }
        }

        // ---- results into the FIFO, and the port's next command --------------------------
        if self.lane_valid.val()
            & ((self.state.q.val() == UnitState::Run) | (self.state.q.val() == UnitState::Finish))
        {
            self.result_fifo.write.next = true;
        }
        if self.accepted.val() & self.cmd_write.q.val() {
            self.written.d.next = self.written.q.val() + 1;
            self.in_flight_n.next = self.in_flight_n.val() - 1;
        }
        if self.cmd_free.val()
            & ((self.state.q.val() == UnitState::Run) | (self.state.q.val() == UnitState::Finish))
        {
            if !self.result_fifo.empty.val() {
                self.cmd_write.d.next = true;
                self.cmd_addr.d.next = self.result_addr.q.val();
                self.cmd_burst.d.next = 1.into();
                self.cmd_data.d.next = self.result_fifo.data_out.val();
                self.result_fifo.read.next = true;
                self.result_addr.d.next = self.result_addr.q.val() + 1;
            } else if (self.state.q.val() == UnitState::Run)
                & self.more_to_read.val()
                & self.room_to_read.val()
                & !self.stale.q.val().any()
            {
                self.cmd_read.d.next = true;
                self.cmd_addr.d.next = self.work_addr.q.val();
                self.cmd_burst.d.next = self.item_words_burst.val();
                self.work_addr.d.next = self.work_addr.q.val() + self.item_words_addr.val();
                self.requested.d.next = self.requested.q.val() + 1;
                self.reserved_n.next = self.reserved_n.val() + self.item_words_count.val();
            }
        }

        // ---- a stalled port ends the batch at once ---------------------------------------
        if ((self.state.q.val() == UnitState::Run) | (self.state.q.val() == UnitState::Finish))
            & self.timed_out.val()
        {
            self.cmd_read.d.next = false;
            self.cmd_write.d.next = false;
            self.timeout_pulse.d.next = true;
            self.done_pulse.d.next = true;
            self.bad_pulse.d.next = false;
            self.state.d.next = UnitState::Idle;
        }
        if self.state.q.val() == UnitState::Idle {
            self.watchdog.d.next = 0.into();
        }

        self.reserved.d.next = self.reserved_n.val();
        self.in_flight.d.next = self.in_flight_n.val();

        // ---- outputs ---------------------------------------------------------------------
        self.status_busy.next = self.state.q.val() != UnitState::Idle;
        self.status_done_set.next = self.done_pulse.q.val();
        self.status_bad_descriptor_set.next = self.bad_pulse.q.val();
        self.status_out_of_window_set.next = self.window_pulse.q.val();
        self.status_bus_timeout_set.next = self.timeout_pulse.q.val();
        self.tests_done_count.next = bit_cast::<32, 24>(self.written.q.val());
        self.info_lanes.next = self.lanes_value.val();
        self.rbx_address.next = self.cmd_addr.q.val();
        self.rbx_burstcount.next = self.cmd_burst.q.val();
        self.rbx_read.next = self.cmd_read.q.val();
        self.rbx_write.next = self.cmd_write.q.val();
        self.rbx_writedata.next = self.cmd_data.q.val();
        self.rbx_byteenable.next = 0xFF.into();
    }
}
