//! The Bayer grouping block: pixel stream in, 32-bit words out, in the PIXCLK domain.

use super::luma::QuadLuma;
use super::quads::QuadAssembler;
use rust_hdl::prelude::*;
use skylux_regmap::words::raw;

// The raw packing below is written with these positions as literals.
const _: () = assert!(raw::EVEN_LSB == 0 && raw::ODD_LSB == 16);

/// Edges from the clock edge that takes the pixel completing a block to the one after which
/// its grouped word is on `word` with `word_valid` high.
pub const GROUPED_LATENCY: usize = 6;
/// The same for the odd-column pixel of a pair in raw mode.
pub const RAW_LATENCY: usize = 4;

/// Pixel stream to grouped or raw words (`skylux_regmap::words`), one pixel per clock
/// sustained, no back-pressure: the FIFO after it absorbs the bursts (at most one word per
/// two clocks, in either mode).
///
/// Input protocol: see [`QuadAssembler`] (`pixel_valid` per pixel; `line_start` and
/// `frame_start` on a line's and a frame's first pixel). Frames have even width (at most
/// 4096) and even height, as the MT9P031 delivers (hardware-facts.md §1.1: even start,
/// odd size registers). The configuration inputs (`bayer.*` registers) must hold still while
/// a frame is in flight, `raw` included: words of a frame already in the pipeline are not
/// reinterpreted, but a mode change mid-frame would mix the two formats.
#[derive(LogicBlock, Default)]
pub struct BayerGrouper {
    pub clock: Signal<In, Clock>,
    pub pixel: Signal<In, Bits<12>>,
    pub pixel_valid: Signal<In, Bit>,
    pub line_start: Signal<In, Bit>,
    pub frame_start: Signal<In, Bit>,
    /// `bayer.mode.PHASE`.
    pub phase: Signal<In, Bits<2>>,
    /// `bayer.black.LEVEL`.
    pub black: Signal<In, Bits<12>>,
    /// `bayer.valid.MIN` and `.MAX`.
    pub valid_min: Signal<In, Bits<12>>,
    pub valid_max: Signal<In, Bits<12>>,
    /// `bayer.weight_*.Q2_14`.
    pub weight_r: Signal<In, Bits<16>>,
    pub weight_g: Signal<In, Bits<16>>,
    pub weight_b: Signal<In, Bits<16>>,
    /// Raw (calibration) mode.
    pub raw: Signal<In, Bit>,
    pub word: Signal<Out, Bits<32>>,
    pub word_valid: Signal<Out, Bit>,

    quads: QuadAssembler,
    luma: QuadLuma,
    out_valid: DFF<Bit>,
    out_word: DFF<Bits<32>>,
    raw_even: Signal<Local, Bits<32>>,
    raw_odd: Signal<Local, Bits<32>>,
}

impl Logic for BayerGrouper {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, out_valid, out_word);
        clock!(self, clock, quads, luma);

        self.quads.pixel.next = self.pixel.val();
        self.quads.pixel_valid.next = self.pixel_valid.val();
        self.quads.line_start.next = self.line_start.val();
        self.quads.frame_start.next = self.frame_start.val();
        self.quads.raw.next = self.raw.val();

        self.luma.quad_valid.next = self.quads.quad_valid.val();
        self.luma.top_left.next = self.quads.top_left.val();
        self.luma.top_right.next = self.quads.top_right.val();
        self.luma.bottom_left.next = self.quads.bottom_left.val();
        self.luma.bottom_right.next = self.quads.bottom_right.val();
        self.luma.phase.next = self.phase.val();
        self.luma.black.next = self.black.val();
        self.luma.valid_min.next = self.valid_min.val();
        self.luma.valid_max.next = self.valid_max.val();
        self.luma.weight_r.next = self.weight_r.val();
        self.luma.weight_g.next = self.weight_g.val();
        self.luma.weight_b.next = self.weight_b.val();

        // Raw pair: even column in bits [11:0], odd column in bits [27:16].
        self.raw_even.next = bit_cast::<32, 12>(self.quads.top_left.val());
        self.raw_odd.next = bit_cast::<32, 12>(self.quads.top_right.val());

        // Only one of the two paths is fed in a given mode, so they never collide.
        self.out_valid.d.next = self.luma.word_valid.val() | self.quads.pair_valid.val();
        if self.luma.word_valid.val() {
            self.out_word.d.next = self.luma.word.val();
        } else if self.quads.pair_valid.val() {
            self.out_word.d.next = self.raw_even.val() | (self.raw_odd.val() << 16);
        }
        self.word.next = self.out_word.q.val();
        self.word_valid.next = self.out_valid.q.val();
    }
}
