//! Turns a 2x2 block into a grouped word (`skylux_regmap::words::grouped`): range flags,
//! black subtraction, colour selection by phase, and the weighted sum.

use rust_hdl::prelude::*;
use skylux_regmap::words::grouped;

/// Block to word, two registered stages.
///
/// Stage 1 registers the range flags, the black-subtracted red and blue samples and the
/// green sum, chosen by phase; stage 2 registers the three products (16x16 multiplies, which
/// map to DSP blocks with registered inputs and outputs). `word` is the sum of the products,
/// combinational from stage 2; the parent registers it.
#[derive(LogicBlock)]
pub struct QuadLuma {
    pub clock: Signal<In, Clock>,
    pub quad_valid: Signal<In, Bit>,
    pub top_left: Signal<In, Bits<12>>,
    pub top_right: Signal<In, Bits<12>>,
    pub bottom_left: Signal<In, Bits<12>>,
    pub bottom_right: Signal<In, Bits<12>>,
    /// `bayer.mode.PHASE`: 0 GRBG, 1 RGGB, 2 BGGR, 3 GBRG (top-left, top-right, bottom-left,
    /// bottom-right).
    pub phase: Signal<In, Bits<2>>,
    pub black: Signal<In, Bits<12>>,
    pub valid_min: Signal<In, Bits<12>>,
    pub valid_max: Signal<In, Bits<12>>,
    /// Unsigned Q2.14.
    pub weight_r: Signal<In, Bits<16>>,
    pub weight_g: Signal<In, Bits<16>>,
    pub weight_b: Signal<In, Bits<16>>,
    pub word_valid: Signal<Out, Bit>,
    pub word: Signal<Out, Bits<32>>,

    // Stage 1: flags and the three colour terms, widened to the multipliers' 16 bits.
    s1_valid: DFF<Bit>,
    s1_under: DFF<Bit>,
    s1_over: DFF<Bit>,
    s1_red: DFF<Bits<16>>,
    s1_green_sum: DFF<Bits<16>>,
    s1_blue: DFF<Bits<16>>,
    // Stage 2: products, in units of 2^-14 (2^-15 for the green sum, halved in the sum).
    s2_valid: DFF<Bit>,
    s2_under: DFF<Bit>,
    s2_over: DFF<Bit>,
    s2_red: DFF<Bits<32>>,
    s2_green: DFF<Bits<32>>,
    s2_blue: DFF<Bits<32>>,

    // Samples minus black, saturated at zero.
    tl_net: Signal<Local, Bits<12>>,
    tr_net: Signal<Local, Bits<12>>,
    bl_net: Signal<Local, Bits<12>>,
    br_net: Signal<Local, Bits<12>>,
    red: Signal<Local, Bits<12>>,
    blue: Signal<Local, Bits<12>>,
    green_1: Signal<Local, Bits<12>>,
    green_2: Signal<Local, Bits<12>>,
    weighted_sum: Signal<Local, Bits<32>>,
    under_bits: Signal<Local, Bits<32>>,
    over_bits: Signal<Local, Bits<32>>,
    under_flag: Constant<Bits<32>>,
    over_flag: Constant<Bits<32>>,
}

impl Default for QuadLuma {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            quad_valid: Default::default(),
            top_left: Default::default(),
            top_right: Default::default(),
            bottom_left: Default::default(),
            bottom_right: Default::default(),
            phase: Default::default(),
            black: Default::default(),
            valid_min: Default::default(),
            valid_max: Default::default(),
            weight_r: Default::default(),
            weight_g: Default::default(),
            weight_b: Default::default(),
            word_valid: Default::default(),
            word: Default::default(),
            s1_valid: Default::default(),
            s1_under: Default::default(),
            s1_over: Default::default(),
            s1_red: Default::default(),
            s1_green_sum: Default::default(),
            s1_blue: Default::default(),
            s2_valid: Default::default(),
            s2_under: Default::default(),
            s2_over: Default::default(),
            s2_red: Default::default(),
            s2_green: Default::default(),
            s2_blue: Default::default(),
            tl_net: Default::default(),
            tr_net: Default::default(),
            bl_net: Default::default(),
            br_net: Default::default(),
            red: Default::default(),
            blue: Default::default(),
            green_1: Default::default(),
            green_2: Default::default(),
            weighted_sum: Default::default(),
            under_bits: Default::default(),
            over_bits: Default::default(),
            under_flag: Constant::new((grouped::UNDER as u64).into()),
            over_flag: Constant::new((grouped::OVER as u64).into()),
        }
    }
}

impl Logic for QuadLuma {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            s1_valid,
            s1_under,
            s1_over,
            s1_red,
            s1_green_sum,
            s1_blue,
            s2_valid,
            s2_under,
            s2_over,
            s2_red,
            s2_green,
            s2_blue
        );

        // ---- stage 1: range flags (before black subtraction), black, colours ------------
        self.s1_valid.d.next = self.quad_valid.val();
        self.s1_under.d.next = (self.top_left.val() < self.valid_min.val())
            | (self.top_right.val() < self.valid_min.val())
            | (self.bottom_left.val() < self.valid_min.val())
            | (self.bottom_right.val() < self.valid_min.val());
        self.s1_over.d.next = (self.top_left.val() > self.valid_max.val())
            | (self.top_right.val() > self.valid_max.val())
            | (self.bottom_left.val() > self.valid_max.val())
            | (self.bottom_right.val() > self.valid_max.val());

        self.tl_net.next = 0.into();
        if self.top_left.val() > self.black.val() {
            self.tl_net.next = self.top_left.val() - self.black.val();
        }
        self.tr_net.next = 0.into();
        if self.top_right.val() > self.black.val() {
            self.tr_net.next = self.top_right.val() - self.black.val();
        }
        self.bl_net.next = 0.into();
        if self.bottom_left.val() > self.black.val() {
            self.bl_net.next = self.bottom_left.val() - self.black.val();
        }
        self.br_net.next = 0.into();
        if self.bottom_right.val() > self.black.val() {
            self.br_net.next = self.bottom_right.val() - self.black.val();
        }

        // Greens sit on the main diagonal for GRBG and GBRG, on the other one for RGGB and BGGR.
        match self.phase.val().index() {
            0 => {
                self.red.next = self.tr_net.val();
                self.blue.next = self.bl_net.val();
                self.green_1.next = self.tl_net.val();
                self.green_2.next = self.br_net.val();
            }
            1 => {
                self.red.next = self.tl_net.val();
                self.blue.next = self.br_net.val();
                self.green_1.next = self.tr_net.val();
                self.green_2.next = self.bl_net.val();
            }
            2 => {
                self.red.next = self.br_net.val();
                self.blue.next = self.tl_net.val();
                self.green_1.next = self.tr_net.val();
                self.green_2.next = self.bl_net.val();
            }
            _ => {
                self.red.next = self.bl_net.val();
                self.blue.next = self.tr_net.val();
                self.green_1.next = self.tl_net.val();
                self.green_2.next = self.br_net.val();
            }
        }
        self.s1_red.d.next = bit_cast::<16, 12>(self.red.val());
        self.s1_blue.d.next = bit_cast::<16, 12>(self.blue.val());
        // Widened before the add, so the carry is kept the same way in Rust and Verilog.
        self.s1_green_sum.d.next =
            bit_cast::<16, 12>(self.green_1.val()) + bit_cast::<16, 12>(self.green_2.val());

        // ---- stage 2: products ----------------------------------------------------------
        self.s2_valid.d.next = self.s1_valid.q.val();
        self.s2_under.d.next = self.s1_under.q.val();
        self.s2_over.d.next = self.s1_over.q.val();
        self.s2_red.d.next = self.s1_red.q.val() * self.weight_r.val();
        self.s2_green.d.next = self.s1_green_sum.q.val() * self.weight_g.val();
        self.s2_blue.d.next = self.s1_blue.q.val() * self.weight_b.val();

        // ---- sum: below 2^30 for every input (regmap words::grouped), so no carry reaches
        // the flag bits and the green product's halving truncates exactly as the format says.
        self.weighted_sum.next =
            self.s2_red.q.val() + (self.s2_green.q.val() >> 1) + self.s2_blue.q.val();
        self.under_bits.next = 0.into();
        if self.s2_under.q.val() {
            self.under_bits.next = self.under_flag.val();
        }
        self.over_bits.next = 0.into();
        if self.s2_over.q.val() {
            self.over_bits.next = self.over_flag.val();
        }
        self.word.next = self.weighted_sum.val() | self.under_bits.val() | self.over_bits.val();
        self.word_valid.next = self.s2_valid.q.val();
    }
}
