//! The sensor interface in the PIXCLK domain: FRAME_VALID, LINE_VALID and D[11:0] in, the
//! pixel stream for the Bayer grouper and the FIFO entries (words between frame markers) out.

use super::fifo_entry as entry;
use rust_hdl::prelude::*;

// The kernel writes the end marker's layout as literals (rust-hdl turns a named constant in an
// expression into a signal name); these tie the literals to the format.
const _: () = assert!(entry::PIXELS_LSB == 0 && entry::LINES_LSB == 12);
const _: () = assert!(entry::LINE_SHORT_BIT == 24 && entry::LINE_LONG_BIT == 25);
const _: () = assert!(entry::FRAME_SHORT_BIT == 26 && entry::FRAME_LONG_BIT == 27);
const _: () = assert!(entry::FIFO_OVERFLOW_BIT == 28 && entry::FRAMES_SKIPPED_BIT == 29);

/// Counters are one bit wider than the 12-bit window registers, so a line or frame longer than
/// any window (up to 8191) is still told apart from one that matches it.
const COUNT_BITS: usize = 13;

/// Pixel capture against the programmed window.
///
/// The pins are registered once at the boundary (capture on the PIXCLK rising edge with the
/// sensor's R0x0A[15] = 1, hardware-facts.md §1.2). A pixel is valid while FV and LV are both
/// high. A frame starts at a rise of FV if `enable` (synchronised here) is set, no end marker
/// is still pending and the FIFO has room for the frame's markers; otherwise the frame is
/// skipped and the next captured frame carries `FRAMES_SKIPPED`. A line ends when LV (or FV)
/// falls; the frame ends when FV falls. Pixels beyond `width` and lines beyond `height` are
/// counted but not passed on, so a frame never grows past its window.
///
/// FIFO writes, by priority: a grouper word (dropped, and the frame flagged `FIFO_OVERFLOW`,
/// when the fill has reached [`entry::DATA_FILL_LIMIT`]), the end marker
/// ([`entry::END_MARKER_DELAY`] clocks after FV fell, once the grouper has drained), the
/// start marker (at FV's rise). The margins keep room for both markers of an accepted frame,
/// so a frame that was started is always closed, even when its data overflowed.
///
/// `width`, `height` and `raw` (and the grouper's settings) come from system-clock registers
/// without synchronisation: they must only change while no frame is being captured.
#[derive(LogicBlock)]
pub struct PixelCapture {
    /// PIXCLK.
    pub clock: Signal<In, Clock>,
    pub frame_valid: Signal<In, Bit>,
    pub line_valid: Signal<In, Bit>,
    pub data: Signal<In, Bits<12>>,
    /// `capture.ctrl.ENABLE` (system clock domain; synchronised here).
    pub enable: Signal<In, Bit>,
    /// `capture.window.WIDTH` and `.HEIGHT`.
    pub width: Signal<In, Bits<12>>,
    pub height: Signal<In, Bits<12>>,
    /// To the Bayer grouper.
    pub pixel: Signal<Out, Bits<12>>,
    pub pixel_valid: Signal<Out, Bit>,
    pub line_start: Signal<Out, Bit>,
    pub frame_start: Signal<Out, Bit>,
    /// From the Bayer grouper.
    pub word: Signal<In, Bits<32>>,
    pub word_valid: Signal<In, Bit>,
    /// The FIFO's write side.
    pub fifo_fill: Signal<In, Bits<{ entry::FILL_BITS }>>,
    pub fifo_data: Signal<Out, Bits<{ entry::BITS }>>,
    pub fifo_write: Signal<Out, Bit>,
    /// FRAME_VALID as registered, for the system clock's synchroniser (`capture.status`).
    pub frame_valid_registered: Signal<Out, Bit>,
    /// Toggles every 8 PIXCLK: the system clock watches it to detect a stopped PIXCLK.
    pub heartbeat: Signal<Out, Bit>,

    enable_meta: DFF<Bit>,
    enable_sync: DFF<Bit>,
    fv_r: DFF<Bit>,
    lv_r: DFF<Bit>,
    d_r: DFF<Bits<12>>,
    prev_fv: DFF<Bit>,
    prev_active: DFF<Bit>,
    heartbeat_count: DFF<Bits<4>>,
    in_frame: DFF<Bit>,
    pixels: DFF<Bits<COUNT_BITS>>,
    lines: DFF<Bits<COUNT_BITS>>,
    last_pixels: DFF<Bits<COUNT_BITS>>,
    line_short: DFF<Bit>,
    line_long: DFF<Bit>,
    frame_short: DFF<Bit>,
    frame_long: DFF<Bit>,
    overflow: DFF<Bit>,
    /// A frame was skipped since the last accepted one.
    skipped: DFF<Bit>,
    /// `skipped` as it was when the current frame started: goes into its end marker.
    frame_skipped: DFF<Bit>,
    end_pending: DFF<Bit>,
    end_countdown: DFF<Bits<3>>,

    active: Signal<Local, Bit>,
    fv_rise: Signal<Local, Bit>,
    fv_fall: Signal<Local, Bit>,
    line_end: Signal<Local, Bit>,
    width_wide: Signal<Local, Bits<COUNT_BITS>>,
    height_wide: Signal<Local, Bits<COUNT_BITS>>,
    forward: Signal<Local, Bit>,
    first_of_line: Signal<Local, Bit>,
    lines_now: Signal<Local, Bits<COUNT_BITS>>,
    start_now: Signal<Local, Bit>,
    in_frame_now: Signal<Local, Bit>,
    pixels_now: Signal<Local, Bits<COUNT_BITS>>,
    lines_base: Signal<Local, Bits<COUNT_BITS>>,
    pixels_reported: Signal<Local, Bits<12>>,
    lines_reported: Signal<Local, Bits<12>>,
    end_entry: Signal<Local, Bits<{ entry::BITS }>>,
    data_limit: Constant<Bits<{ entry::FILL_BITS }>>,
    start_limit: Constant<Bits<{ entry::FILL_BITS }>>,
    end_delay: Constant<Bits<3>>,
    start_marker: Constant<Bits<{ entry::BITS }>>,
    end_marker: Constant<Bits<{ entry::BITS }>>,
}

impl Default for PixelCapture {
    fn default() -> Self {
        PixelCapture {
            clock: Default::default(),
            frame_valid: Default::default(),
            line_valid: Default::default(),
            data: Default::default(),
            enable: Default::default(),
            width: Default::default(),
            height: Default::default(),
            pixel: Default::default(),
            pixel_valid: Default::default(),
            line_start: Default::default(),
            frame_start: Default::default(),
            word: Default::default(),
            word_valid: Default::default(),
            fifo_fill: Default::default(),
            fifo_data: Default::default(),
            fifo_write: Default::default(),
            frame_valid_registered: Default::default(),
            heartbeat: Default::default(),
            enable_meta: Default::default(),
            enable_sync: Default::default(),
            fv_r: Default::default(),
            lv_r: Default::default(),
            d_r: Default::default(),
            prev_fv: Default::default(),
            prev_active: Default::default(),
            heartbeat_count: Default::default(),
            in_frame: Default::default(),
            pixels: Default::default(),
            lines: Default::default(),
            last_pixels: Default::default(),
            line_short: Default::default(),
            line_long: Default::default(),
            frame_short: Default::default(),
            frame_long: Default::default(),
            overflow: Default::default(),
            skipped: Default::default(),
            frame_skipped: Default::default(),
            end_pending: Default::default(),
            end_countdown: Default::default(),
            active: Default::default(),
            fv_rise: Default::default(),
            fv_fall: Default::default(),
            line_end: Default::default(),
            width_wide: Default::default(),
            height_wide: Default::default(),
            forward: Default::default(),
            first_of_line: Default::default(),
            lines_now: Default::default(),
            start_now: Default::default(),
            in_frame_now: Default::default(),
            pixels_now: Default::default(),
            lines_base: Default::default(),
            pixels_reported: Default::default(),
            lines_reported: Default::default(),
            end_entry: Default::default(),
            data_limit: Constant::new(entry::DATA_FILL_LIMIT.into()),
            start_limit: Constant::new(entry::START_FILL_LIMIT.into()),
            end_delay: Constant::new(entry::END_MARKER_DELAY.into()),
            start_marker: Constant::new(entry::START.into()),
            end_marker: Constant::new(entry::END.into()),
        }
    }
}

impl Logic for PixelCapture {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            enable_meta,
            enable_sync,
            fv_r,
            lv_r,
            d_r,
            prev_fv,
            prev_active,
            heartbeat_count,
            in_frame,
            pixels,
            lines,
            last_pixels,
            line_short,
            line_long,
            frame_short,
            frame_long,
            overflow,
            skipped,
            frame_skipped,
            end_pending,
            end_countdown
        );
        self.enable_meta.d.next = self.enable.val();
        self.enable_sync.d.next = self.enable_meta.q.val();
        self.fv_r.d.next = self.frame_valid.val();
        self.lv_r.d.next = self.line_valid.val();
        self.d_r.d.next = self.data.val();
        self.prev_fv.d.next = self.fv_r.q.val();
        self.heartbeat_count.d.next = self.heartbeat_count.q.val() + 1;
        self.heartbeat.next = self.heartbeat_count.q.val().get_bit(3);
        self.frame_valid_registered.next = self.fv_r.q.val();

        self.active.next = self.fv_r.q.val() & self.lv_r.q.val();
        self.prev_active.d.next = self.active.val();
        self.fv_rise.next = self.fv_r.q.val() & !self.prev_fv.q.val();
        self.fv_fall.next = !self.fv_r.q.val() & self.prev_fv.q.val() & self.in_frame.q.val();
        self.line_end.next = self.prev_active.q.val() & !self.active.val() & self.in_frame.q.val();
        self.width_wide.next = bit_cast::<COUNT_BITS, 12>(self.width.val());
        self.height_wide.next = bit_cast::<COUNT_BITS, 12>(self.height.val());

        // ---- frame start ----------------------------------------------------------------
        self.start_now.next = false;
        if self.fv_rise.val() & self.enable_sync.q.val() {
            if !self.end_pending.q.val() & (self.fifo_fill.val() < self.start_limit.val()) {
                self.start_now.next = true;
                self.in_frame.d.next = true;
                self.pixels.d.next = 0.into();
                self.lines.d.next = 0.into();
                self.last_pixels.d.next = 0.into();
                self.line_short.d.next = false;
                self.line_long.d.next = false;
                self.frame_short.d.next = false;
                self.frame_long.d.next = false;
                self.overflow.d.next = false;
                self.frame_skipped.d.next = self.skipped.q.val();
                self.skipped.d.next = false;
            } else {
                self.skipped.d.next = true;
            }
        }

        // The frame counts from the PIXCLK of FV's rise: LV may rise with FV (no frame start
        // blanking), and that first pixel belongs to the frame.
        self.in_frame_now.next = self.in_frame.q.val() | self.start_now.val();
        self.pixels_now.next = self.pixels.q.val();
        self.lines_base.next = self.lines.q.val();
        if self.start_now.val() {
            self.pixels_now.next = 0.into();
            self.lines_base.next = 0.into();
        }

        // ---- the pixel stream -----------------------------------------------------------
        self.forward.next = self.in_frame_now.val()
            & self.active.val()
            & (self.pixels_now.val() < self.width_wide.val())
            & (self.lines_base.val() < self.height_wide.val());
        self.first_of_line.next = !self.pixels_now.val().any();
        self.pixel.next = self.d_r.q.val();
        self.pixel_valid.next = self.forward.val();
        self.line_start.next = self.forward.val() & self.first_of_line.val();
        self.frame_start.next =
            self.forward.val() & self.first_of_line.val() & !self.lines_base.val().any();

        // ---- counting against the window ------------------------------------------------
        if self.in_frame_now.val() & self.active.val() & !self.pixels_now.val().all() {
            self.pixels.d.next = self.pixels_now.val() + 1;
        }
        self.lines_now.next = self.lines.q.val();
        if self.line_end.val() {
            if self.pixels.q.val() < self.width_wide.val() {
                self.line_short.d.next = true;
            }
            if self.pixels.q.val() > self.width_wide.val() {
                self.line_long.d.next = true;
            }
            self.last_pixels.d.next = self.pixels.q.val();
            self.pixels.d.next = 0.into();
            if !self.lines.q.val().all() {
                self.lines_now.next = self.lines.q.val() + 1;
            }
            self.lines.d.next = self.lines_now.val();
        }
        if self.fv_fall.val() {
            self.in_frame.d.next = false;
            if self.lines_now.val() < self.height_wide.val() {
                self.frame_short.d.next = true;
            }
            if self.lines_now.val() > self.height_wide.val() {
                self.frame_long.d.next = true;
            }
            self.end_pending.d.next = true;
            self.end_countdown.d.next = self.end_delay.val();
        }

        // ---- the end marker's payload ---------------------------------------------------
        self.pixels_reported.next = self.last_pixels.q.val().get_bits::<12>(0);
        if self.last_pixels.q.val().get_bit(12) {
            self.pixels_reported.next = 0xFFF.into();
        }
        self.lines_reported.next = self.lines.q.val().get_bits::<12>(0);
        if self.lines.q.val().get_bit(12) {
            self.lines_reported.next = 0xFFF.into();
        }
        // ---- FIFO writes ----------------------------------------------------------------
        if self.end_pending.q.val() & self.end_countdown.q.val().any() {
            self.end_countdown.d.next = self.end_countdown.q.val() - 1;
        }
        // The 34-bit entries are built only when written (wide values are slow to simulate).
        self.fifo_write.next = false;
        self.fifo_data.next = 0.into();
        self.end_entry.next = 0.into();
        if self.word_valid.val() {
            if self.fifo_fill.val() < self.data_limit.val() {
                self.fifo_write.next = true;
                self.fifo_data.next = bit_cast::<{ entry::BITS }, 32>(self.word.val());
            } else {
                self.overflow.d.next = true;
            }
        } else if self.end_pending.q.val() & !self.end_countdown.q.val().any() {
            self.end_entry.next = self.end_marker.val()
                | bit_cast::<{ entry::BITS }, 12>(self.pixels_reported.val())
                | (bit_cast::<{ entry::BITS }, 12>(self.lines_reported.val()) << 12);
            self.end_entry.next = self
                .end_entry
                .val()
                .replace_bit(24, self.line_short.q.val());
            self.end_entry.next = self.end_entry.val().replace_bit(25, self.line_long.q.val());
            self.end_entry.next = self
                .end_entry
                .val()
                .replace_bit(26, self.frame_short.q.val());
            self.end_entry.next = self
                .end_entry
                .val()
                .replace_bit(27, self.frame_long.q.val());
            self.end_entry.next = self.end_entry.val().replace_bit(28, self.overflow.q.val());
            self.end_entry.next = self
                .end_entry
                .val()
                .replace_bit(29, self.frame_skipped.q.val());
            self.fifo_write.next = true;
            self.fifo_data.next = self.end_entry.val();
            self.end_pending.d.next = false;
        } else if self.start_now.val() {
            self.fifo_write.next = true;
            self.fifo_data.next = self.start_marker.val();
        }
    }
}
