//! The read side of the clock-domain FIFO, in the system clock: frame markers, words paired
//! into 64-bit beats, the payload checksum, the frame tags, and the capture's status.

use crate::capture::fifo_entry as entry;
use crate::hdr::HdrSelect;
use rust_hdl::prelude::*;
use skylux_regmap::descriptor;

/// Where the ingest is in the frame sequence.
#[derive(Copy, Clone, PartialEq, Eq, Debug, LogicState)]
pub enum IngestState {
    /// Between frames: entries are read and dropped until a start marker.
    Idle,
    /// Words go to the beat FIFO until the end marker.
    Frame,
    /// All beats of the frame are queued; waiting for the writer to close it.
    Ended,
}

/// System clocks without a heartbeat edge (bit 10 of the counter: 1024 clocks, 10 µs at
/// 100 MHz) before PIXCLK counts as stopped. The heartbeat toggles every 8 PIXCLK, so any
/// PIXCLK above 1.6 MHz keeps it alive; the sensor's lowest PIXCLK is its 6 MHz EXTCLK
/// (hardware-facts.md §1.2).
const STOP_COUNT_BITS: usize = 11;

// The kernel writes bit positions as literals (rust-hdl turns a named constant in an expression
// into a signal name); these tie the literals to the formats.
const _: () = assert!(STOP_COUNT_BITS == 11);
const _: () = assert!(entry::MARKER_BIT == 32 && entry::END_BIT == 33);
const _: () = assert!(entry::PIXELS_LSB == 0 && entry::LINES_LSB == 12);
const _: () = assert!(entry::LINE_SHORT_BIT == 24 && entry::FRAMES_SKIPPED_BIT == 29);
const _: () = assert!(descriptor::flag::LSB == 16);
const _: () = assert!(descriptor::flag::PIXCLK_STOPPED == 1 << 21);
const _: () = assert!(descriptor::flag::FRAMES_SKIPPED == 1 << 24);
const _: () = assert!(descriptor::RAW_MODE == 1 << 8 && descriptor::LINES_LSB == 16);
const _: () = assert!(descriptor::HDR_MAP == 1 << 9);

/// Reads the FIFO (first-word-fall-through) and turns a frame into beats for the writer plus
/// the descriptor fields. A start marker opens a frame only when the engine is enabled and
/// the writer is idle (otherwise it waits in the FIFO, or is dropped while disabled). The
/// frame closes at its end marker, at a start marker that arrives first (`FRAME_SHORT`), or
/// when PIXCLK stops (`PIXCLK_STOPPED`); an odd word count is padded with a zero word.
/// End markers update the capture status in every state, so `capture.*` works with the DMA
/// disabled. In HDR mode (`hdr_enable`, sampled when a frame opens, grouped mode only) each
/// taken word goes out as its map word through [`HdrSelect`], with byte enables clear for
/// groups already filled; a map frame's descriptor checksum is its set's so far, the sum of
/// the map words that settled (`HdrConfig::map_checksum`). A map frame after
/// `hdr_new_set` begins a set and is its exposure 0; the others count up from their set's
/// first, so a set may span sequences whose exposure tags restart.
#[derive(LogicBlock, Default)]
pub struct FrameIngest {
    pub clock: Signal<In, Clock>,
    pub fifo_data: Signal<In, Bits<{ entry::BITS }>>,
    pub fifo_empty: Signal<In, Bit>,
    pub fifo_fill: Signal<In, Bits<{ entry::FILL_BITS }>>,
    pub fifo_read: Signal<Out, Bit>,
    /// From the PIXCLK domain (synchronised here).
    pub frame_valid_async: Signal<In, Bit>,
    pub heartbeat_async: Signal<In, Bit>,
    /// `dma.ctrl.ENABLE` and `capture.ctrl.RAW`.
    pub enable: Signal<In, Bit>,
    pub raw: Signal<In, Bit>,
    /// Frame tags from the exposure sequencer, latched when FRAME_VALID rises.
    pub tag_exposure_index: Signal<In, Bits<3>>,
    pub tag_frame_number: Signal<In, Bits<32>>,
    pub tag_timestamp: Signal<In, Bits<64>>,
    /// `hdr.*`: write the frames of a set as one map (grouped mode only), the pulse that makes
    /// the next map frame a set's first, and the usable luminance range.
    pub hdr_enable: Signal<In, Bit>,
    pub hdr_new_set: Signal<In, Bit>,
    pub hdr_min_q11: Signal<In, Bits<27>>,
    pub hdr_max_q11: Signal<In, Bits<27>>,
    /// From the writer.
    pub writer_idle: Signal<In, Bit>,
    pub frame_closed: Signal<In, Bit>,
    pub beat_room: Signal<In, Bit>,
    /// To the writer.
    pub beat_push: Signal<Out, Bit>,
    pub beat_data: Signal<Out, Bits<64>>,
    pub beat_byteenable: Signal<Out, Bits<8>>,
    pub frame_open: Signal<Out, Bit>,
    pub frame_ended: Signal<Out, Bit>,
    pub desc_frame_number: Signal<Out, Bits<32>>,
    pub desc_timestamp: Signal<Out, Bits<64>>,
    pub desc_info: Signal<Out, Bits<32>>,
    pub desc_geometry: Signal<Out, Bits<32>>,
    pub desc_words: Signal<Out, Bits<32>>,
    pub desc_checksum: Signal<Out, Bits<32>>,
    /// `capture.*` status.
    pub capture_status_frame_valid: Signal<Out, Bit>,
    pub capture_status_line_short_set: Signal<Out, Bit>,
    pub capture_status_line_long_set: Signal<Out, Bit>,
    pub capture_status_frame_short_set: Signal<Out, Bit>,
    pub capture_status_frame_long_set: Signal<Out, Bit>,
    pub capture_status_fifo_overflow_set: Signal<Out, Bit>,
    pub capture_status_pixclk_stopped_set: Signal<Out, Bit>,
    pub capture_last_frame_pixels: Signal<Out, Bits<12>>,
    pub capture_last_frame_lines: Signal<Out, Bits<12>>,
    pub capture_fifo_high_water_words: Signal<Out, Bits<16>>,
    pub capture_frames_count: Signal<Out, Bits<32>>,
    /// `dma.status.OVERFLOW`: a frame the engine took lost words in the FIFO.
    pub dma_status_overflow_set: Signal<Out, Bit>,
    /// A payload word taken into the open frame this cycle (for the sun accumulators), and
    /// whether it is the frame's first; the frame's exposure index.
    pub taken_valid: Signal<Out, Bit>,
    pub taken_word: Signal<Out, Bits<32>>,
    pub taken_first: Signal<Out, Bit>,
    pub taken_exposure_index: Signal<Out, Bits<3>>,

    hdr: HdrSelect,
    state: DFF<IngestState>,
    fv_meta: DFF<Bit>,
    fv_sync: DFF<Bit>,
    fv_prev: DFF<Bit>,
    hb_meta: DFF<Bit>,
    hb_sync: DFF<Bit>,
    hb_prev: DFF<Bit>,
    since_heartbeat: DFF<Bits<STOP_COUNT_BITS>>,
    pending_exposure: DFF<Bits<3>>,
    pending_frame_number: DFF<Bits<32>>,
    pending_timestamp: DFF<Bits<64>>,
    frame_number: DFF<Bits<32>>,
    timestamp: DFF<Bits<64>>,
    info: DFF<Bits<32>>,
    geometry: DFF<Bits<32>>,
    words: DFF<Bits<32>>,
    checksum: DFF<Bits<32>>,
    half: DFF<Bits<32>>,
    half_valid: DFF<Bit>,
    half_enables: DFF<Bits<4>>,
    hdr_frame: DFF<Bit>,
    /// `NEW_SET` came: the next map frame begins a set.
    new_set_pending: DFF<Bit>,
    /// The current map frame's place in its set (the map words' exposure field).
    set_ordinal: DFF<Bits<3>>,
    /// The set's checksum so far: the wrapping sum of the map words that settled
    /// (`HdrConfig::map_checksum`), a map frame's descriptor checksum.
    set_sum: DFF<Bits<32>>,
    high_water: DFF<Bits<{ entry::FILL_BITS }>>,
    last_high_water: DFF<Bits<{ entry::FILL_BITS }>>,
    last_pixels: DFF<Bits<12>>,
    last_lines: DFF<Bits<12>>,
    frames: DFF<Bits<32>>,

    is_marker: Signal<Local, Bit>,
    is_end: Signal<Local, Bit>,
    is_start: Signal<Local, Bit>,
    is_data: Signal<Local, Bit>,
    payload: Signal<Local, Bits<32>>,
    info_start: Signal<Local, Bits<32>>,
    pixclk_stopped: Signal<Local, Bit>,
    close_now: Signal<Local, Bit>,
    marker_flags: Signal<Local, Bits<32>>,
    // The word a taken entry puts in its beat (grouped or raw, or the map word) and its byte
    // enables.
    out_word: Signal<Local, Bits<32>>,
    out_enables: Signal<Local, Bits<4>>,
    next_ordinal: Signal<Local, Bits<3>>,
}

impl Logic for FrameIngest {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            state,
            fv_meta,
            fv_sync,
            fv_prev,
            hb_meta,
            hb_sync,
            hb_prev,
            since_heartbeat,
            pending_exposure,
            pending_frame_number,
            pending_timestamp,
            frame_number,
            timestamp,
            info,
            geometry,
            words,
            checksum,
            half,
            half_valid,
            half_enables,
            hdr_frame,
            new_set_pending,
            set_ordinal,
            set_sum,
            high_water,
            last_high_water,
            last_pixels,
            last_lines,
            frames
        );
        // ---- synchronisers and the PIXCLK watchdog --------------------------------------
        self.fv_meta.d.next = self.frame_valid_async.val();
        self.fv_sync.d.next = self.fv_meta.q.val();
        self.fv_prev.d.next = self.fv_sync.q.val();
        self.hb_meta.d.next = self.heartbeat_async.val();
        self.hb_sync.d.next = self.hb_meta.q.val();
        self.hb_prev.d.next = self.hb_sync.q.val();
        if self.hb_sync.q.val() != self.hb_prev.q.val() {
            self.since_heartbeat.d.next = 0.into();
        } else if !self.since_heartbeat.q.val().get_bit(10) {
            self.since_heartbeat.d.next = self.since_heartbeat.q.val() + 1;
        }
        self.pixclk_stopped.next = self.since_heartbeat.q.val().get_bit(10);
        self.capture_status_frame_valid.next = self.fv_sync.q.val();
        if self.fv_sync.q.val() & !self.fv_prev.q.val() {
            self.pending_exposure.d.next = self.tag_exposure_index.val();
            self.pending_frame_number.d.next = self.tag_frame_number.val();
            self.pending_timestamp.d.next = self.tag_timestamp.val();
        }
        if self.fifo_fill.val() > self.high_water.q.val() {
            self.high_water.d.next = self.fifo_fill.val();
        }

        // ---- decode the entry at the FIFO's head ----------------------------------------
        self.is_marker.next = !self.fifo_empty.val() & self.fifo_data.val().get_bit(32);
        self.is_end.next = self.is_marker.val() & self.fifo_data.val().get_bit(33);
        self.is_start.next = self.is_marker.val() & !self.fifo_data.val().get_bit(33);
        self.is_data.next = !self.fifo_empty.val() & !self.fifo_data.val().get_bit(32);
        self.payload.next = self.fifo_data.val().get_bits::<32>(0);
        // Capture flags of an end marker, moved to their descriptor positions.
        self.marker_flags.next = 0.into();
        self.marker_flags.next = self
            .marker_flags
            .val()
            .replace_bit(16, self.payload.val().get_bit(24));
        self.marker_flags.next = self
            .marker_flags
            .val()
            .replace_bit(17, self.payload.val().get_bit(25));
        self.marker_flags.next = self
            .marker_flags
            .val()
            .replace_bit(18, self.payload.val().get_bit(26));
        self.marker_flags.next = self
            .marker_flags
            .val()
            .replace_bit(19, self.payload.val().get_bit(27));
        self.marker_flags.next = self
            .marker_flags
            .val()
            .replace_bit(20, self.payload.val().get_bit(28));
        self.marker_flags.next = self
            .marker_flags
            .val()
            .replace_bit(24, self.payload.val().get_bit(29));

        // ---- capture status: every end marker, whatever the DMA does --------------------
        self.fifo_read.next = false;
        self.capture_status_line_short_set.next = false;
        self.capture_status_line_long_set.next = false;
        self.capture_status_frame_short_set.next = false;
        self.capture_status_frame_long_set.next = false;
        self.capture_status_fifo_overflow_set.next = false;
        self.capture_status_pixclk_stopped_set.next = false;
        self.dma_status_overflow_set.next = false;
        if self.is_end.val() & (self.state.q.val() != IngestState::Ended) {
            // Idle and Frame read every end marker (below); Ended leaves it in the FIFO.
            self.capture_status_line_short_set.next = self.payload.val().get_bit(24);
            self.capture_status_line_long_set.next = self.payload.val().get_bit(25);
            self.capture_status_frame_short_set.next = self.payload.val().get_bit(26);
            self.capture_status_frame_long_set.next = self.payload.val().get_bit(27);
            self.capture_status_fifo_overflow_set.next = self.payload.val().get_bit(28);
            self.last_pixels.d.next = self.payload.val().get_bits::<12>(0);
            self.last_lines.d.next = self.payload.val().get_bits::<12>(12);
            self.frames.d.next = self.frames.q.val() + 1;
            self.last_high_water.d.next = self.high_water.q.val();
            self.high_water.d.next = self.fifo_fill.val();
        }
        self.capture_last_frame_pixels.next = self.last_pixels.q.val();
        self.capture_last_frame_lines.next = self.last_lines.q.val();
        self.capture_frames_count.next = self.frames.q.val();
        self.capture_fifo_high_water_words.next =
            bit_cast::<16, { entry::FILL_BITS }>(self.last_high_water.q.val());

        self.info_start.next = bit_cast::<32, 3>(self.pending_exposure.q.val());
        self.info_start.next = self.info_start.val().replace_bit(8, self.raw.val());
        self.info_start.next = self
            .info_start
            .val()
            .replace_bit(9, self.hdr_enable.val() & !self.raw.val());

        // ---- HDR: the map word and whether to write it, for the word taken ---------------
        self.hdr.clock.next = self.clock.val();
        self.hdr.restart.next = false;
        if self.hdr_new_set.val() {
            self.new_set_pending.d.next = true;
        }
        self.next_ordinal.next = self.set_ordinal.q.val() + 1;
        if self.set_ordinal.q.val() == 7 {
            self.next_ordinal.next = 7.into();
        }
        if self.new_set_pending.q.val() {
            self.next_ordinal.next = 0.into();
        }
        self.hdr.first_of_set.next = self.new_set_pending.q.val();
        self.hdr.exposure_index.next = self.next_ordinal.val();
        self.hdr.take.next = false;
        self.hdr.word.next = self.payload.val();
        self.hdr.min_q11.next = self.hdr_min_q11.val();
        self.hdr.max_q11.next = self.hdr_max_q11.val();
        self.out_word.next = self.payload.val();
        self.out_enables.next = 0xF.into();
        if self.hdr_frame.q.val() {
            self.out_word.next = self.hdr.map_word.val();
            if !self.hdr.map_write.val() {
                self.out_enables.next = 0.into();
            }
        }

        // ---- beats ----------------------------------------------------------------------
        // The 64-bit beats are assembled only when pushed (wide values are slow to simulate).
        self.beat_push.next = false;
        self.beat_data.next = 0.into();
        self.beat_byteenable.next = 0xFF.into();
        self.taken_valid.next = false;
        self.taken_word.next = self.payload.val();
        self.taken_first.next = self.words.q.val() == 0;
        self.taken_exposure_index.next = self.info.q.val().get_bits::<3>(0);
        self.frame_open.next = false;
        self.close_now.next = false;

        match self.state.q.val() {
            IngestState::Idle => {
                if self.is_start.val() {
                    if !self.enable.val() {
                        self.fifo_read.next = true;
                    } else if self.writer_idle.val() {
                        self.fifo_read.next = true;
                        self.frame_open.next = true;
                        self.frame_number.d.next = self.pending_frame_number.q.val();
                        self.timestamp.d.next = self.pending_timestamp.q.val();
                        self.info.d.next = self.info_start.val();
                        self.geometry.d.next = 0.into();
                        self.words.d.next = 0.into();
                        self.checksum.d.next = 0.into();
                        self.half_valid.d.next = false;
                        self.hdr.restart.next = true;
                        self.hdr_frame.d.next = self.hdr_enable.val() & !self.raw.val();
                        if self.hdr_enable.val() & !self.raw.val() {
                            self.set_ordinal.d.next = self.next_ordinal.val();
                            self.new_set_pending.d.next = false;
                            if self.new_set_pending.q.val() {
                                self.set_sum.d.next = 0.into();
                            }
                        }
                        self.state.d.next = IngestState::Frame;
                    }
                } else if !self.fifo_empty.val() {
                    self.fifo_read.next = true;
                }
            }
            IngestState::Frame => {
                if self.is_data.val() {
                    if self.beat_room.val() {
                        self.fifo_read.next = true;
                        self.taken_valid.next = true;
                        self.hdr.take.next = true;
                        self.words.d.next = self.words.q.val() + 1;
                        self.checksum.d.next = self.checksum.q.val() + self.payload.val();
                        if self.half_valid.q.val() {
                            self.beat_push.next = true;
                            self.beat_data.next = bit_cast::<64, 32>(self.half.q.val())
                                | (bit_cast::<64, 32>(self.out_word.val()) << 32);
                            self.beat_byteenable.next = bit_cast::<8, 4>(self.half_enables.q.val())
                                | (bit_cast::<8, 4>(self.out_enables.val()) << 4);
                            self.half_valid.d.next = false;
                        } else {
                            self.half.d.next = self.out_word.val();
                            self.half_enables.d.next = self.out_enables.val();
                            self.half_valid.d.next = true;
                        }
                    }
                } else if self.is_end.val() {
                    self.fifo_read.next = true;
                    self.close_now.next = true;
                    self.info.d.next = self.info.q.val() | self.marker_flags.val();
                    self.geometry.d.next = bit_cast::<32, 12>(self.payload.val().get_bits::<12>(0))
                        | (bit_cast::<32, 12>(self.payload.val().get_bits::<12>(12)) << 16);
                    self.dma_status_overflow_set.next = self.payload.val().get_bit(28);
                } else if self.is_start.val() {
                    // The end marker never came: close, and open the next frame from Idle.
                    self.close_now.next = true;
                    self.info.d.next = self.info.q.val().replace_bit(18, true);
                } else if self.pixclk_stopped.val() {
                    self.close_now.next = true;
                    self.info.d.next = self.info.q.val().replace_bit(21, true);
                    self.capture_status_pixclk_stopped_set.next = true;
                }
                if self.close_now.val() {
                    self.state.d.next = IngestState::Ended;
                    if self.half_valid.q.val() {
                        self.beat_push.next = true;
                        self.beat_data.next = bit_cast::<64, 32>(self.half.q.val());
                        self.beat_byteenable.next =
                            bit_cast::<8, 4>(self.half_enables.q.val()) | 0xF0;
                        self.half_valid.d.next = false;
                    }
                }
            }
            IngestState::Ended => {
                if self.frame_closed.val() {
                    self.state.d.next = IngestState::Idle;
                }
            }
        }

        self.frame_ended.next = self.state.q.val() == IngestState::Ended;
        self.desc_frame_number.next = self.frame_number.q.val();
        self.desc_timestamp.next = self.timestamp.q.val();
        self.desc_info.next = self.info.q.val();
        self.desc_geometry.next = self.geometry.q.val();
        self.desc_words.next = self.words.q.val();
        self.desc_checksum.next = self.checksum.q.val();
        if self.hdr_frame.q.val() {
            self.desc_checksum.next = self.set_sum.q.val();
        }
        // A word that settles is taken in a frame's cycle, never in the cycle that opens one
        // (which clears the sum at a set's start).
        if self.hdr_frame.q.val() & self.hdr.map_settles.val() {
            self.set_sum.d.next = self.set_sum.q.val() + self.hdr.map_word.val();
        }
    }
}
