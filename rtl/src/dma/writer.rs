//! The Avalon-MM burst master: the frame's beats into its ring slot, then the descriptor.

use rust_hdl::prelude::*;
use skylux_regmap::descriptor;

/// Longest burst: 2^(8-1) beats with the f2sdram port's 8-bit burstcount (hardware-facts.md
/// §3.2, §4).
pub const MAX_BURST_BEATS: u64 = 128;
/// Address bits of the beat FIFO: two full bursts (256 x 64 bits, two M10K blocks), so one
/// burst can be written while the next fills.
pub const BEAT_FIFO_ADDRESS_BITS: usize = 8;
/// The ingest may push a beat while fewer than this many are queued.
pub const BEAT_ROOM_LIMIT: u64 = (1 << BEAT_FIFO_ADDRESS_BITS) - 2;
/// Beats of the descriptor burst.
pub const DESCRIPTOR_BEATS: u64 = (descriptor::BYTES / descriptor::BEAT_BYTES) as u64;

const _: () = assert!(descriptor::BEAT_BYTES == 8 && descriptor::PAYLOAD_OFFSET_BYTES == 64);
const _: () = assert!(DESCRIPTOR_BEATS == 4 && descriptor::MIN_SLOT_BYTES == 72);
const _: () = assert!(descriptor::flag::TRUNCATED == 1 << 22);
// The kernel writes these as literals (rust-hdl turns a named constant in an expression into a
// signal name).
const _: () = assert!(BEAT_ROOM_LIMIT == 254 && MAX_BURST_BEATS == 128);
const _: () = assert!(descriptor::flag::BUS_TIMEOUT == 1 << 23);

/// Where the writer is in a frame.
#[derive(Copy, Clone, PartialEq, Eq, Debug, LogicState)]
pub enum WriterState {
    Idle,
    /// Choosing the next burst (or the descriptor once the frame has ended).
    Plan,
    Burst,
    /// Throwing beats away: the slot is unusable, or the payload outgrew it.
    Drain,
    Descriptor,
    Close,
}

/// Writes a frame into the current ring slot.
///
/// At a frame's opening the slot is checked: window base and stride 8-byte aligned, stride at
/// least [`descriptor::MIN_SLOT_BYTES`], the whole slot inside the window and the window
/// inside the 32-bit address space. A slot that fails is not written at all (the frame's
/// beats are drained, `OUT_OF_WINDOW` is raised, no descriptor, the ring does not advance).
/// In a good slot, bursts of [`MAX_BURST_BEATS`] are issued as soon as that many beats are
/// queued, and the remainder once the frame has ended; a burst that would end past the slot
/// is cut at the slot's end, the rest of the payload is drained and the descriptor says
/// `TRUNCATED`.
/// The descriptor is written last, then `FRAME_DONE` pulses and the ring advances.
///
/// Avalon-MM: address (bytes), burstcount and write are held for the whole burst, and a
/// beat advances only on a cycle with `write && !waitrequest`. A stall longer than
/// `bus_timeout` raises `BUS_TIMEOUT` (once per stall) and flags the frame; the burst still
/// completes, since an Avalon master may not abandon one.
#[derive(LogicBlock)]
pub struct BurstWriter {
    pub clock: Signal<In, Clock>,
    /// `dma.ctrl.RESET`: restart the ring at slot 0 (taken between frames).
    pub restart: Signal<In, Bit>,
    pub window_base: Signal<In, Bits<32>>,
    pub window_size: Signal<In, Bits<32>>,
    pub slot_stride: Signal<In, Bits<32>>,
    pub slots: Signal<In, Bits<8>>,
    pub bus_timeout: Signal<In, Bits<24>>,
    /// From the ingest.
    pub beat_push: Signal<In, Bit>,
    pub beat_data: Signal<In, Bits<64>>,
    /// The beat's byte enables (all set but in HDR mode, where they mask filled groups).
    pub beat_byteenable: Signal<In, Bits<8>>,
    pub frame_open: Signal<In, Bit>,
    pub frame_ended: Signal<In, Bit>,
    pub desc_frame_number: Signal<In, Bits<32>>,
    pub desc_timestamp: Signal<In, Bits<64>>,
    pub desc_info: Signal<In, Bits<32>>,
    pub desc_geometry: Signal<In, Bits<32>>,
    pub desc_words: Signal<In, Bits<32>>,
    pub desc_checksum: Signal<In, Bits<32>>,
    /// To the ingest.
    pub writer_idle: Signal<Out, Bit>,
    pub frame_closed: Signal<Out, Bit>,
    pub beat_room: Signal<Out, Bit>,
    /// `dma.*` status.
    pub dma_status_busy: Signal<Out, Bit>,
    pub dma_status_slot: Signal<Out, Bits<8>>,
    pub dma_status_frame_done_set: Signal<Out, Bit>,
    pub dma_status_out_of_window_set: Signal<Out, Bit>,
    pub dma_status_bus_timeout_set: Signal<Out, Bit>,
    pub dma_frames_written_count: Signal<Out, Bits<32>>,
    /// Avalon-MM host, byte addresses, 64-bit data.
    pub avm_address: Signal<Out, Bits<32>>,
    pub avm_burstcount: Signal<Out, Bits<8>>,
    pub avm_write: Signal<Out, Bit>,
    pub avm_writedata: Signal<Out, Bits<64>>,
    pub avm_byteenable: Signal<Out, Bits<8>>,
    pub avm_waitrequest: Signal<In, Bit>,

    beats: SynchronousFIFO<Bits<64>, BEAT_FIFO_ADDRESS_BITS, { BEAT_FIFO_ADDRESS_BITS + 1 }, 1>,
    /// The beats' byte enables, pushed and popped with them (a separate FIFO keeps the 64-bit
    /// one's layout).
    enables: SynchronousFIFO<Bits<8>, BEAT_FIFO_ADDRESS_BITS, { BEAT_FIFO_ADDRESS_BITS + 1 }, 1>,
    queued: DFF<Bits<{ BEAT_FIFO_ADDRESS_BITS + 1 }>>,
    state: DFF<WriterState>,
    slot: DFF<Bits<8>>,
    slot_offset: DFF<Bits<32>>,
    restart_pending: DFF<Bit>,
    slot_ok: DFF<Bit>,
    slot_addr: DFF<Bits<32>>,
    slot_end: DFF<Bits<33>>,
    addr: DFF<Bits<32>>,
    burst_len: DFF<Bits<8>>,
    beats_left: DFF<Bits<8>>,
    desc_beat: DFF<Bits<2>>,
    flags: DFF<Bits<32>>,
    stall: DFF<Bits<24>>,
    timed_out: DFF<Bit>,
    frames_written: DFF<Bits<32>>,

    pop: Signal<Local, Bit>,
    base_wide: Signal<Local, Bits<33>>,
    size_wide: Signal<Local, Bits<33>>,
    stride_wide: Signal<Local, Bits<33>>,
    slot_end_in_window: Signal<Local, Bits<33>>,
    window_end: Signal<Local, Bits<33>>,
    slot_fits: Signal<Local, Bit>,
    plan_len: Signal<Local, Bits<8>>,
    plan_go: Signal<Local, Bit>,
    room_beats: Signal<Local, Bits<33>>,
    stalled: Signal<Local, Bit>,
    accepted: Signal<Local, Bit>,
    next_slot: Signal<Local, Bits<8>>,
    advance: Signal<Local, Bit>,
    descriptor_beat: Signal<Local, Bits<64>>,
    format_id: Constant<Bits<32>>,
    max_burst: Constant<Bits<8>>,
    descriptor_beats: Constant<Bits<8>>,
    truncated_flag: Constant<Bits<32>>,
    bus_timeout_flag: Constant<Bits<32>>,
}

impl Default for BurstWriter {
    fn default() -> Self {
        BurstWriter {
            clock: Default::default(),
            restart: Default::default(),
            window_base: Default::default(),
            window_size: Default::default(),
            slot_stride: Default::default(),
            slots: Default::default(),
            bus_timeout: Default::default(),
            beat_push: Default::default(),
            beat_data: Default::default(),
            beat_byteenable: Default::default(),
            frame_open: Default::default(),
            frame_ended: Default::default(),
            desc_frame_number: Default::default(),
            desc_timestamp: Default::default(),
            desc_info: Default::default(),
            desc_geometry: Default::default(),
            desc_words: Default::default(),
            desc_checksum: Default::default(),
            writer_idle: Default::default(),
            frame_closed: Default::default(),
            beat_room: Default::default(),
            dma_status_busy: Default::default(),
            dma_status_slot: Default::default(),
            dma_status_frame_done_set: Default::default(),
            dma_status_out_of_window_set: Default::default(),
            dma_status_bus_timeout_set: Default::default(),
            dma_frames_written_count: Default::default(),
            avm_address: Default::default(),
            avm_burstcount: Default::default(),
            avm_write: Default::default(),
            avm_writedata: Default::default(),
            avm_byteenable: Default::default(),
            avm_waitrequest: Default::default(),
            beats: Default::default(),
            enables: Default::default(),
            queued: Default::default(),
            state: Default::default(),
            slot: Default::default(),
            slot_offset: Default::default(),
            restart_pending: Default::default(),
            slot_ok: Default::default(),
            slot_addr: Default::default(),
            slot_end: Default::default(),
            addr: Default::default(),
            burst_len: Default::default(),
            beats_left: Default::default(),
            desc_beat: Default::default(),
            flags: Default::default(),
            stall: Default::default(),
            timed_out: Default::default(),
            frames_written: Default::default(),
            pop: Default::default(),
            base_wide: Default::default(),
            size_wide: Default::default(),
            stride_wide: Default::default(),
            slot_end_in_window: Default::default(),
            window_end: Default::default(),
            slot_fits: Default::default(),
            plan_len: Default::default(),
            plan_go: Default::default(),
            room_beats: Default::default(),
            stalled: Default::default(),
            accepted: Default::default(),
            next_slot: Default::default(),
            advance: Default::default(),
            descriptor_beat: Default::default(),
            format_id: Constant::new((descriptor::FORMAT_ID as u64).into()),
            max_burst: Constant::new(MAX_BURST_BEATS.into()),
            descriptor_beats: Constant::new(DESCRIPTOR_BEATS.into()),
            truncated_flag: Constant::new((descriptor::flag::TRUNCATED as u64).into()),
            bus_timeout_flag: Constant::new((descriptor::flag::BUS_TIMEOUT as u64).into()),
        }
    }
}

impl Logic for BurstWriter {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            queued,
            state,
            slot,
            slot_offset,
            restart_pending,
            slot_ok,
            slot_addr,
            slot_end,
            addr,
            burst_len,
            beats_left,
            desc_beat,
            flags,
            stall,
            timed_out,
            frames_written
        );
        clock!(self, clock, beats, enables);

        // ---- the beat FIFO and its count ------------------------------------------------
        self.beats.write.next = self.beat_push.val();
        self.beats.data_in.next = self.beat_data.val();
        self.enables.write.next = self.beat_push.val();
        self.enables.data_in.next = self.beat_byteenable.val();
        self.pop.next = false;
        self.beat_room.next = self.queued.q.val() < 254;

        // Wide (33- and 64-bit) arithmetic is computed only in the state that needs it: it is
        // slow to simulate. The defaults keep the Verilog free of latches.
        self.base_wide.next = 0.into();
        self.size_wide.next = 0.into();
        self.stride_wide.next = 0.into();
        self.slot_end_in_window.next = 0.into();
        self.window_end.next = 0.into();
        self.slot_fits.next = false;
        self.plan_len.next = self.max_burst.val();
        self.plan_go.next = false;
        self.room_beats.next = 0.into();
        self.descriptor_beat.next = 0.into();

        // ---- Avalon-MM defaults and the stall watchdog ----------------------------------
        self.avm_address.next = self.addr.q.val();
        self.avm_burstcount.next = self.burst_len.q.val();
        self.avm_write.next = false;
        self.avm_writedata.next = 0.into();
        self.avm_byteenable.next = 0xFF.into();
        self.stalled.next = false;
        self.accepted.next = false;
        self.writer_idle.next = false;
        self.frame_closed.next = false;
        self.dma_status_frame_done_set.next = false;
        self.dma_status_out_of_window_set.next = false;
        self.dma_status_bus_timeout_set.next = false;
        self.advance.next = false;
        self.next_slot.next = self.slot.q.val() + 1;
        if self.restart.val() {
            self.restart_pending.d.next = true;
        }

        match self.state.q.val() {
            WriterState::Idle => {
                self.writer_idle.next = true;
                if self.frame_open.val() {
                    self.base_wide.next = bit_cast::<33, 32>(self.window_base.val());
                    self.size_wide.next = bit_cast::<33, 32>(self.window_size.val());
                    self.stride_wide.next = bit_cast::<33, 32>(self.slot_stride.val());
                    self.slot_end_in_window.next =
                        bit_cast::<33, 32>(self.slot_offset.q.val()) + self.stride_wide.val();
                    self.window_end.next = self.base_wide.val() + self.size_wide.val();
                    self.slot_fits.next = !self.window_base.val().get_bits::<3>(0).any()
                        & !self.slot_stride.val().get_bits::<3>(0).any()
                        & (self.slot_stride.val() >= 72)
                        & (self.slot_end_in_window.val() <= self.size_wide.val())
                        & !(self.window_end.val().get_bit(32)
                            & self.window_end.val().get_bits::<32>(0).any());
                    self.flags.d.next = 0.into();
                    self.stall.d.next = 0.into();
                    self.timed_out.d.next = false;
                    self.slot_addr.d.next = self.window_base.val() + self.slot_offset.q.val();
                    self.addr.d.next = self.window_base.val() + self.slot_offset.q.val() + 64;
                    self.slot_end.d.next = self.base_wide.val() + self.slot_end_in_window.val();
                    self.slot_ok.d.next = self.slot_fits.val();
                    if self.slot_fits.val() {
                        self.state.d.next = WriterState::Plan;
                    } else {
                        self.dma_status_out_of_window_set.next = true;
                        self.state.d.next = WriterState::Drain;
                    }
                } else if self.restart_pending.q.val() {
                    self.restart_pending.d.next = false;
                    self.slot.d.next = 0.into();
                    self.slot_offset.d.next = 0.into();
                }
            }
            WriterState::Plan => {
                if self.queued.q.val() < 128 {
                    self.plan_len.next = self.queued.q.val().get_bits::<8>(0);
                }
                self.plan_go.next = (self.queued.q.val() >= 128)
                    | (self.frame_ended.val() & self.queued.q.val().any());
                if self.plan_go.val() {
                    // Beats left before the slot's end (the payload never starts past it).
                    self.room_beats.next =
                        (self.slot_end.q.val() - bit_cast::<33, 32>(self.addr.q.val())) >> 3;
                    if self.room_beats.val() >= bit_cast::<33, 8>(self.plan_len.val()) {
                        self.burst_len.d.next = self.plan_len.val();
                        self.beats_left.d.next = self.plan_len.val();
                        self.state.d.next = WriterState::Burst;
                    } else if self.room_beats.val().any() {
                        // Fill the slot to its end; the rest of the payload is drained.
                        self.burst_len.d.next = self.room_beats.val().get_bits::<8>(0);
                        self.beats_left.d.next = self.room_beats.val().get_bits::<8>(0);
                        self.flags.d.next = self.flags.q.val() | self.truncated_flag.val();
                        self.dma_status_out_of_window_set.next = true;
                        self.state.d.next = WriterState::Burst;
                    } else {
                        self.flags.d.next = self.flags.q.val() | self.truncated_flag.val();
                        self.dma_status_out_of_window_set.next = true;
                        self.state.d.next = WriterState::Drain;
                    }
                } else if self.frame_ended.val() {
                    self.desc_beat.d.next = 0.into();
                    self.addr.d.next = self.slot_addr.q.val();
                    self.burst_len.d.next = self.descriptor_beats.val();
                    self.state.d.next = WriterState::Descriptor;
                }
            }
            WriterState::Burst => {
                self.avm_write.next = true;
                self.avm_writedata.next = self.beats.data_out.val();
                self.avm_byteenable.next = self.enables.data_out.val();
                if self.avm_waitrequest.val() {
                    self.stalled.next = true;
                } else {
                    self.accepted.next = true;
                    self.pop.next = true;
                    self.beats_left.d.next = self.beats_left.q.val() - 1;
                    if self.beats_left.q.val() == 1 {
                        self.addr.d.next =
                            self.addr.q.val() + (bit_cast::<32, 8>(self.burst_len.q.val()) << 3);
                        self.state.d.next = WriterState::Plan;
                    }
                }
            }
            WriterState::Drain => {
                self.pop.next = !self.beats.empty.val();
                if self.frame_ended.val() & !self.queued.q.val().any() {
                    if self.slot_ok.q.val() {
                        self.desc_beat.d.next = 0.into();
                        self.addr.d.next = self.slot_addr.q.val();
                        self.burst_len.d.next = self.descriptor_beats.val();
                        self.state.d.next = WriterState::Descriptor;
                    } else {
                        self.state.d.next = WriterState::Close;
                    }
                }
            }
            WriterState::Descriptor => {
                self.descriptor_beat.next = bit_cast::<64, 32>(self.format_id.val())
                    | (bit_cast::<64, 32>(self.desc_frame_number.val()) << 32);
                if self.desc_beat.q.val() == 1 {
                    self.descriptor_beat.next = self.desc_timestamp.val();
                }
                if self.desc_beat.q.val() == 2 {
                    self.descriptor_beat.next =
                        bit_cast::<64, 32>(self.desc_info.val() | self.flags.q.val())
                            | (bit_cast::<64, 32>(self.desc_geometry.val()) << 32);
                }
                if self.desc_beat.q.val() == 3 {
                    self.descriptor_beat.next = bit_cast::<64, 32>(self.desc_words.val())
                        | (bit_cast::<64, 32>(self.desc_checksum.val()) << 32);
                }
                self.avm_write.next = true;
                self.avm_writedata.next = self.descriptor_beat.val();
                if self.avm_waitrequest.val() {
                    self.stalled.next = true;
                } else {
                    self.accepted.next = true;
                    self.desc_beat.d.next = self.desc_beat.q.val() + 1;
                    if self.desc_beat.q.val() == 3 {
                        self.state.d.next = WriterState::Close;
                    }
                }
            }
            WriterState::Close => {
                self.frame_closed.next = true;
                self.state.d.next = WriterState::Idle;
                if self.slot_ok.q.val() {
                    self.dma_status_frame_done_set.next = true;
                    self.frames_written.d.next = self.frames_written.q.val() + 1;
                    self.advance.next = true;
                }
                if self.restart_pending.q.val() {
                    self.restart_pending.d.next = false;
                    self.slot.d.next = 0.into();
                    self.slot_offset.d.next = 0.into();
                } else if self.advance.val() {
                    if self.next_slot.val() >= self.slots.val() {
                        self.slot.d.next = 0.into();
                        self.slot_offset.d.next = 0.into();
                    } else {
                        self.slot.d.next = self.next_slot.val();
                        self.slot_offset.d.next = self.slot_offset.q.val() + self.slot_stride.val();
                    }
                }
            }
        }

        if self.stalled.val() {
            if (self.stall.q.val() == self.bus_timeout.val()) & !self.timed_out.q.val() {
                self.dma_status_bus_timeout_set.next = true;
                self.flags.d.next = self.flags.q.val() | self.bus_timeout_flag.val();
                self.timed_out.d.next = true;
            }
            if !self.stall.q.val().all() {
                self.stall.d.next = self.stall.q.val() + 1;
            }
        }
        if self.accepted.val() {
            self.stall.d.next = 0.into();
            self.timed_out.d.next = false;
        }

        self.beats.read.next = self.pop.val();
        self.enables.read.next = self.pop.val();
        if self.beat_push.val() & !self.pop.val() {
            self.queued.d.next = self.queued.q.val() + 1;
        }
        if self.pop.val() & !self.beat_push.val() {
            self.queued.d.next = self.queued.q.val() - 1;
        }

        self.dma_status_busy.next = self.state.q.val() != WriterState::Idle;
        self.dma_status_slot.next = self.slot.q.val();
        self.dma_frames_written_count.next = self.frames_written.q.val();
    }
}
