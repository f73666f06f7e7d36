//! Turns the pixel stream into 2x2 blocks (grouped mode) or horizontal pairs (raw mode), with
//! one sensor row held in block RAM.

use rust_hdl::prelude::*;

/// Address width of the line buffer: 4096 samples, enough for the MT9P031's 2592 active
/// columns (hardware-facts.md §1.1) and any window up to 4096 wide.
pub const LINE_ADDRESS_BITS: usize = 12;

/// Stream to blocks.
///
/// A pixel is taken on a clock edge where `pixel_valid` is high (FV && LV, any number of idle
/// cycles in between). `line_start` marks the first pixel of a line and `frame_start` the first
/// of a frame (it implies `line_start`); both are looked at only with `pixel_valid`. Lines
/// alternate top and bottom of a row pair, starting with a top line at `frame_start`.
///
/// The top line of a pair is written into the line buffer at its column; on the bottom line the
/// same column is read back, so when the odd column of a bottom line arrives all four samples
/// of the block are at hand. Outputs are registered, three edges after the pixel that
/// completes the block or pair.
#[derive(LogicBlock, Default)]
pub struct QuadAssembler {
    pub clock: Signal<In, Clock>,
    pub pixel: Signal<In, Bits<12>>,
    pub pixel_valid: Signal<In, Bit>,
    pub line_start: Signal<In, Bit>,
    pub frame_start: Signal<In, Bit>,
    /// Raw mode: emit horizontal pairs of every line instead of blocks.
    pub raw: Signal<In, Bit>,
    /// A block is in `top_left`..`bottom_right` (grouped mode), for one cycle.
    pub quad_valid: Signal<Out, Bit>,
    /// A pair is in `top_left` (even column) and `top_right` (odd column) (raw mode).
    pub pair_valid: Signal<Out, Bit>,
    pub top_left: Signal<Out, Bits<12>>,
    pub top_right: Signal<Out, Bits<12>>,
    pub bottom_left: Signal<Out, Bits<12>>,
    pub bottom_right: Signal<Out, Bits<12>>,

    line_buffer: RAM<Bits<12>, LINE_ADDRESS_BITS>,
    // Stage 1: the inputs, registered at the block's boundary.
    in_valid: DFF<Bit>,
    in_pixel: DFF<Bits<12>>,
    in_line_start: DFF<Bit>,
    in_frame_start: DFF<Bit>,
    // Position state: the column the next pixel takes unless it starts a line, and whether the
    // current line is the bottom one of its pair.
    next_column: DFF<Bits<LINE_ADDRESS_BITS>>,
    bottom_line: DFF<Bit>,
    // Stage 2: aligned with the line buffer's registered read data.
    at_valid: DFF<Bit>,
    at_pixel: DFF<Bits<12>>,
    at_odd_column: DFF<Bit>,
    at_bottom: DFF<Bit>,
    // The even column of the current pair: its own sample and the one above it.
    even_pixel: DFF<Bits<12>>,
    even_above: DFF<Bits<12>>,
    // Stage 3: outputs.
    out_quad: DFF<Bit>,
    out_pair: DFF<Bit>,
    out_top_left: DFF<Bits<12>>,
    out_top_right: DFF<Bits<12>>,
    out_bottom_left: DFF<Bits<12>>,
    out_bottom_right: DFF<Bits<12>>,

    column: Signal<Local, Bits<LINE_ADDRESS_BITS>>,
    bottom: Signal<Local, Bit>,
    above: Signal<Local, Bits<12>>,
}

impl Logic for QuadAssembler {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            in_valid,
            in_pixel,
            in_line_start,
            in_frame_start,
            next_column,
            bottom_line,
            at_valid,
            at_pixel,
            at_odd_column,
            at_bottom,
            even_pixel,
            even_above,
            out_quad,
            out_pair,
            out_top_left,
            out_top_right,
            out_bottom_left,
            out_bottom_right
        );
        self.line_buffer.read_clock.next = self.clock.val();
        self.line_buffer.write_clock.next = self.clock.val();

        // ---- stage 1: inputs ------------------------------------------------------------
        self.in_valid.d.next = self.pixel_valid.val();
        self.in_pixel.d.next = self.pixel.val();
        self.in_line_start.d.next = self.line_start.val() | self.frame_start.val();
        self.in_frame_start.d.next = self.frame_start.val();

        // Position of the registered pixel.
        self.column.next = self.next_column.q.val();
        self.bottom.next = self.bottom_line.q.val();
        if self.in_line_start.q.val() {
            self.column.next = 0.into();
            self.bottom.next = !self.bottom_line.q.val();
        }
        if self.in_frame_start.q.val() {
            self.bottom.next = false;
        }
        if self.in_valid.q.val() {
            self.next_column.d.next = self.column.val() + 1;
            self.bottom_line.d.next = self.bottom.val();
        }

        // Line buffer: top lines write, every pixel reads the same column (used on bottom lines).
        self.line_buffer.write_address.next = self.column.val();
        self.line_buffer.write_data.next = self.in_pixel.q.val();
        self.line_buffer.write_enable.next =
            self.in_valid.q.val() & !self.bottom.val() & !self.raw.val();
        self.line_buffer.read_address.next = self.column.val();

        // ---- stage 2: the pixel and the sample above it ---------------------------------
        self.at_valid.d.next = self.in_valid.q.val();
        self.at_pixel.d.next = self.in_pixel.q.val();
        self.at_odd_column.d.next = self.column.val().get_bit(0);
        self.at_bottom.d.next = self.bottom.val();
        self.above.next = self.line_buffer.read_data.val();

        self.out_quad.d.next = false;
        self.out_pair.d.next = false;
        if self.at_valid.q.val() & !self.at_odd_column.q.val() {
            self.even_pixel.d.next = self.at_pixel.q.val();
            self.even_above.d.next = self.above.val();
        }
        if self.at_valid.q.val() & self.at_odd_column.q.val() {
            if self.raw.val() {
                self.out_pair.d.next = true;
                self.out_top_left.d.next = self.even_pixel.q.val();
                self.out_top_right.d.next = self.at_pixel.q.val();
            } else if self.at_bottom.q.val() {
                self.out_quad.d.next = true;
                self.out_top_left.d.next = self.even_above.q.val();
                self.out_top_right.d.next = self.above.val();
                self.out_bottom_left.d.next = self.even_pixel.q.val();
                self.out_bottom_right.d.next = self.at_pixel.q.val();
            }
        }

        // ---- stage 3: outputs -----------------------------------------------------------
        self.quad_valid.next = self.out_quad.q.val();
        self.pair_valid.next = self.out_pair.q.val();
        self.top_left.next = self.out_top_left.q.val();
        self.top_right.next = self.out_top_right.q.val();
        self.bottom_left.next = self.out_bottom_left.q.val();
        self.bottom_right.next = self.out_bottom_right.q.val();
    }
}
