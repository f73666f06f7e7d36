//! The whole capture path: sensor pins to Avalon-MM writes, across the one clock crossing.

use super::fifo_entry as entry;
use super::pixel_capture::PixelCapture;
use crate::bayer::BayerGrouper;
use crate::dma::{BurstWriter, FrameIngest};
use crate::sun::SunAccumulators;
use rust_hdl::prelude::*;

/// The clock-domain FIFO: rust-hdl's asynchronous FIFO (first-word-fall-through; its pointers
/// cross through handshake synchronisers, so each side's fill is conservative, never low).
pub type CaptureFifo =
    AsynchronousFIFO<Bits<{ entry::BITS }>, { entry::FIFO_ADDRESS_BITS }, { entry::FILL_BITS }, 1>;

/// Capture, Bayer grouper, clock-domain FIFO and frame DMA (with the HDR selection in its
/// ingest, `hdr.*`), and the sun accumulators on the words the DMA takes (`sun.*`).
///
/// Ports are named after the register fields they connect to (`capture_ctrl_enable` is
/// `capture.ctrl.ENABLE`, `dma_status_frame_done_set` pulses `dma.status.FRAME_DONE`), so the
/// core wires them to the generated register file one to one. `pixclk` clocks the sensor
/// side up to the FIFO's write port; `clock` (the 100 MHz system clock) everything after it.
/// The `irq_*` outputs are one-cycle pulses for `sys.irq_status`. The frame tags come from the
/// exposure sequencer (system clock) and are latched when FRAME_VALID rises.
///
/// Configuration that the PIXCLK side uses (`capture_window_*`, `capture_ctrl_raw`,
/// `bayer_*`) must hold still while a frame is captured; `capture_ctrl_enable` is synchronised.
#[derive(LogicBlock, Default)]
pub struct CapturePath {
    pub pixclk: Signal<In, Clock>,
    pub clock: Signal<In, Clock>,
    // Sensor pins (PIXCLK domain).
    pub sensor_frame_valid: Signal<In, Bit>,
    pub sensor_line_valid: Signal<In, Bit>,
    pub sensor_data: Signal<In, Bits<12>>,
    // Registers.
    pub capture_ctrl_enable: Signal<In, Bit>,
    pub capture_ctrl_raw: Signal<In, Bit>,
    pub capture_window_width: Signal<In, Bits<12>>,
    pub capture_window_height: Signal<In, Bits<12>>,
    pub bayer_mode_phase: Signal<In, Bits<2>>,
    pub bayer_black_level: Signal<In, Bits<12>>,
    pub bayer_valid_min: Signal<In, Bits<12>>,
    pub bayer_valid_max: Signal<In, Bits<12>>,
    pub bayer_weight_r_q2_14: Signal<In, Bits<16>>,
    pub bayer_weight_g_q2_14: Signal<In, Bits<16>>,
    pub bayer_weight_b_q2_14: Signal<In, Bits<16>>,
    pub dma_ctrl_enable: Signal<In, Bit>,
    pub dma_ctrl_reset: Signal<In, Bit>,
    pub dma_window_base_addr: Signal<In, Bits<32>>,
    pub dma_window_size_bytes: Signal<In, Bits<32>>,
    pub dma_slot_stride_bytes: Signal<In, Bits<32>>,
    pub dma_slots_count: Signal<In, Bits<8>>,
    pub dma_bus_timeout_cycles: Signal<In, Bits<24>>,
    pub sun_ctrl_enable: Signal<In, Bit>,
    pub sun_ctrl_exposure_index: Signal<In, Bits<3>>,
    pub sun_threshold_q14: Signal<In, Bits<30>>,
    pub sun_window_x_min: Signal<In, Bits<11>>,
    pub sun_window_x_max: Signal<In, Bits<11>>,
    pub sun_window_y_min: Signal<In, Bits<11>>,
    pub sun_window_y_max: Signal<In, Bits<11>>,
    pub hdr_ctrl_enable: Signal<In, Bit>,
    pub hdr_ctrl_new_set: Signal<In, Bit>,
    pub hdr_min_q11: Signal<In, Bits<27>>,
    pub hdr_max_q11: Signal<In, Bits<27>>,
    // Frame tags from the exposure sequencer.
    pub tag_exposure_index: Signal<In, Bits<3>>,
    pub tag_frame_number: Signal<In, Bits<32>>,
    pub tag_timestamp: Signal<In, Bits<64>>,
    // Status (system clock).
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
    pub dma_status_busy: Signal<Out, Bit>,
    pub dma_status_slot: Signal<Out, Bits<8>>,
    pub dma_status_frame_done_set: Signal<Out, Bit>,
    pub dma_status_out_of_window_set: Signal<Out, Bit>,
    pub dma_status_overflow_set: Signal<Out, Bit>,
    pub dma_status_bus_timeout_set: Signal<Out, Bit>,
    pub dma_frames_written_count: Signal<Out, Bits<32>>,
    pub sun_count_groups: Signal<Out, Bits<21>>,
    pub sun_over_count_groups: Signal<Out, Bits<21>>,
    pub sun_sum_l_lo_value: Signal<Out, Bits<32>>,
    pub sun_sum_l_hi_value: Signal<Out, Bits<32>>,
    pub sun_sum_xl_lo_value: Signal<Out, Bits<32>>,
    pub sun_sum_xl_hi_value: Signal<Out, Bits<32>>,
    pub sun_sum_yl_lo_value: Signal<Out, Bits<32>>,
    pub sun_sum_yl_hi_value: Signal<Out, Bits<32>>,
    pub sun_max_l_q14: Signal<Out, Bits<30>>,
    pub sun_box_x_min: Signal<Out, Bits<11>>,
    pub sun_box_x_max: Signal<Out, Bits<11>>,
    pub sun_box_y_min: Signal<Out, Bits<11>>,
    pub sun_box_y_max: Signal<Out, Bits<11>>,
    pub sun_frames_count: Signal<Out, Bits<16>>,
    pub irq_frame_done: Signal<Out, Bit>,
    pub irq_dma_error: Signal<Out, Bit>,
    pub irq_capture_error: Signal<Out, Bit>,
    // Avalon-MM host to the f2sdram port.
    pub avm_address: Signal<Out, Bits<32>>,
    pub avm_burstcount: Signal<Out, Bits<8>>,
    pub avm_write: Signal<Out, Bit>,
    pub avm_writedata: Signal<Out, Bits<64>>,
    pub avm_byteenable: Signal<Out, Bits<8>>,
    pub avm_waitrequest: Signal<In, Bit>,

    capture: PixelCapture,
    grouper: BayerGrouper,
    fifo: CaptureFifo,
    ingest: FrameIngest,
    writer: BurstWriter,
    sun: SunAccumulators,
}

impl Logic for CapturePath {
    #[hdl_gen]
    fn update(&mut self) {
        // ---- PIXCLK domain --------------------------------------------------------------
        self.capture.clock.next = self.pixclk.val();
        self.grouper.clock.next = self.pixclk.val();
        self.fifo.write_clock.next = self.pixclk.val();
        self.capture.frame_valid.next = self.sensor_frame_valid.val();
        self.capture.line_valid.next = self.sensor_line_valid.val();
        self.capture.data.next = self.sensor_data.val();
        self.capture.enable.next = self.capture_ctrl_enable.val();
        self.capture.width.next = self.capture_window_width.val();
        self.capture.height.next = self.capture_window_height.val();
        self.grouper.pixel.next = self.capture.pixel.val();
        self.grouper.pixel_valid.next = self.capture.pixel_valid.val();
        self.grouper.line_start.next = self.capture.line_start.val();
        self.grouper.frame_start.next = self.capture.frame_start.val();
        self.grouper.phase.next = self.bayer_mode_phase.val();
        self.grouper.black.next = self.bayer_black_level.val();
        self.grouper.valid_min.next = self.bayer_valid_min.val();
        self.grouper.valid_max.next = self.bayer_valid_max.val();
        self.grouper.weight_r.next = self.bayer_weight_r_q2_14.val();
        self.grouper.weight_g.next = self.bayer_weight_g_q2_14.val();
        self.grouper.weight_b.next = self.bayer_weight_b_q2_14.val();
        self.grouper.raw.next = self.capture_ctrl_raw.val();
        self.capture.word.next = self.grouper.word.val();
        self.capture.word_valid.next = self.grouper.word_valid.val();
        self.capture.fifo_fill.next = self.fifo.write_fill.val();
        self.fifo.data_in.next = self.capture.fifo_data.val();
        self.fifo.write.next = self.capture.fifo_write.val();

        // ---- system clock domain --------------------------------------------------------
        self.fifo.read_clock.next = self.clock.val();
        self.ingest.clock.next = self.clock.val();
        self.writer.clock.next = self.clock.val();
        self.ingest.fifo_data.next = self.fifo.data_out.val();
        self.ingest.fifo_empty.next = self.fifo.empty.val();
        self.ingest.fifo_fill.next = self.fifo.read_fill.val();
        self.fifo.read.next = self.ingest.fifo_read.val();
        self.ingest.frame_valid_async.next = self.capture.frame_valid_registered.val();
        self.ingest.heartbeat_async.next = self.capture.heartbeat.val();
        self.ingest.enable.next = self.dma_ctrl_enable.val();
        self.ingest.raw.next = self.capture_ctrl_raw.val();
        self.ingest.tag_exposure_index.next = self.tag_exposure_index.val();
        self.ingest.tag_frame_number.next = self.tag_frame_number.val();
        self.ingest.tag_timestamp.next = self.tag_timestamp.val();
        self.ingest.writer_idle.next = self.writer.writer_idle.val();
        self.ingest.frame_closed.next = self.writer.frame_closed.val();
        self.ingest.beat_room.next = self.writer.beat_room.val();
        self.ingest.hdr_enable.next = self.hdr_ctrl_enable.val();
        self.ingest.hdr_new_set.next = self.hdr_ctrl_new_set.val();
        self.ingest.hdr_min_q11.next = self.hdr_min_q11.val();
        self.ingest.hdr_max_q11.next = self.hdr_max_q11.val();

        self.writer.restart.next = self.dma_ctrl_reset.val();
        self.writer.window_base.next = self.dma_window_base_addr.val();
        self.writer.window_size.next = self.dma_window_size_bytes.val();
        self.writer.slot_stride.next = self.dma_slot_stride_bytes.val();
        self.writer.slots.next = self.dma_slots_count.val();
        self.writer.bus_timeout.next = self.dma_bus_timeout_cycles.val();
        self.writer.beat_push.next = self.ingest.beat_push.val();
        self.writer.beat_data.next = self.ingest.beat_data.val();
        self.writer.beat_byteenable.next = self.ingest.beat_byteenable.val();
        self.writer.frame_open.next = self.ingest.frame_open.val();
        self.writer.frame_ended.next = self.ingest.frame_ended.val();
        self.writer.desc_frame_number.next = self.ingest.desc_frame_number.val();
        self.writer.desc_timestamp.next = self.ingest.desc_timestamp.val();
        self.writer.desc_info.next = self.ingest.desc_info.val();
        self.writer.desc_geometry.next = self.ingest.desc_geometry.val();
        self.writer.desc_words.next = self.ingest.desc_words.val();
        self.writer.desc_checksum.next = self.ingest.desc_checksum.val();
        self.writer.avm_waitrequest.next = self.avm_waitrequest.val();

        self.capture_status_frame_valid.next = self.ingest.capture_status_frame_valid.val();
        self.capture_status_line_short_set.next = self.ingest.capture_status_line_short_set.val();
        self.capture_status_line_long_set.next = self.ingest.capture_status_line_long_set.val();
        self.capture_status_frame_short_set.next = self.ingest.capture_status_frame_short_set.val();
        self.capture_status_frame_long_set.next = self.ingest.capture_status_frame_long_set.val();
        self.capture_status_fifo_overflow_set.next =
            self.ingest.capture_status_fifo_overflow_set.val();
        self.capture_status_pixclk_stopped_set.next =
            self.ingest.capture_status_pixclk_stopped_set.val();
        self.capture_last_frame_pixels.next = self.ingest.capture_last_frame_pixels.val();
        self.capture_last_frame_lines.next = self.ingest.capture_last_frame_lines.val();
        self.capture_fifo_high_water_words.next = self.ingest.capture_fifo_high_water_words.val();
        self.capture_frames_count.next = self.ingest.capture_frames_count.val();
        self.dma_status_busy.next = self.writer.dma_status_busy.val();
        self.dma_status_slot.next = self.writer.dma_status_slot.val();
        self.dma_status_frame_done_set.next = self.writer.dma_status_frame_done_set.val();
        self.dma_status_out_of_window_set.next = self.writer.dma_status_out_of_window_set.val();
        self.dma_status_overflow_set.next = self.ingest.dma_status_overflow_set.val();
        self.dma_status_bus_timeout_set.next = self.writer.dma_status_bus_timeout_set.val();
        self.dma_frames_written_count.next = self.writer.dma_frames_written_count.val();
        self.irq_frame_done.next = self.writer.dma_status_frame_done_set.val();
        self.irq_dma_error.next = self.writer.dma_status_out_of_window_set.val()
            | self.writer.dma_status_bus_timeout_set.val()
            | self.ingest.dma_status_overflow_set.val();
        self.irq_capture_error.next = self.ingest.capture_status_line_short_set.val()
            | self.ingest.capture_status_line_long_set.val()
            | self.ingest.capture_status_frame_short_set.val()
            | self.ingest.capture_status_frame_long_set.val()
            | self.ingest.capture_status_fifo_overflow_set.val()
            | self.ingest.capture_status_pixclk_stopped_set.val();
        // ---- the sun accumulators, on the words of the frames the DMA takes -------------
        self.sun.clock.next = self.clock.val();
        self.sun.word_valid.next = self.ingest.taken_valid.val();
        self.sun.word.next = self.ingest.taken_word.val();
        self.sun.frame_start.next = self.ingest.taken_first.val();
        self.sun.armed.next = self.sun_ctrl_enable.val()
            & !self.capture_ctrl_raw.val()
            & (self.ingest.taken_exposure_index.val() == self.sun_ctrl_exposure_index.val());
        self.sun.groups_per_line.next = self.capture_window_width.val().get_bits::<11>(1);
        self.sun.threshold_q14.next = self.sun_threshold_q14.val();
        self.sun.x_min.next = self.sun_window_x_min.val();
        self.sun.x_max.next = self.sun_window_x_max.val();
        self.sun.y_min.next = self.sun_window_y_min.val();
        self.sun.y_max.next = self.sun_window_y_max.val();
        self.sun_count_groups.next = self.sun.sun_count.val();
        self.sun_over_count_groups.next = self.sun.over_count.val();
        self.sun_sum_l_lo_value.next = self.sun.sum_l.val().get_bits::<32>(0);
        self.sun_sum_l_hi_value.next = self.sun.sum_l.val().get_bits::<32>(32);
        self.sun_sum_xl_lo_value.next = self.sun.sum_xl.val().get_bits::<32>(0);
        self.sun_sum_xl_hi_value.next = self.sun.sum_xl.val().get_bits::<32>(32);
        self.sun_sum_yl_lo_value.next = self.sun.sum_yl.val().get_bits::<32>(0);
        self.sun_sum_yl_hi_value.next = self.sun.sum_yl.val().get_bits::<32>(32);
        self.sun_max_l_q14.next = self.sun.max_l.val();
        self.sun_box_x_min.next = self.sun.min_x.val();
        self.sun_box_x_max.next = self.sun.max_x.val();
        self.sun_box_y_min.next = self.sun.min_y.val();
        self.sun_box_y_max.next = self.sun.max_y.val();
        self.sun_frames_count.next = self.sun.armed_frames.val();

        self.avm_address.next = self.writer.avm_address.val();
        self.avm_burstcount.next = self.writer.avm_burstcount.val();
        self.avm_write.next = self.writer.avm_write.val();
        self.avm_writedata.next = self.writer.avm_writedata.val();
        self.avm_byteenable.next = self.writer.avm_byteenable.val();
    }
}
