//! The sun accumulators: on the grouped words of the sun's exposure, the count, Σ L, Σ x·L,
//! Σ y·L, the largest L and the bounding box of the groups at or above a threshold inside a
//! search window ([`super::golden`] is the specification).

use super::position::SunPosition;
use rust_hdl::prelude::*;

/// Cycles from a word at the inputs to the outputs that include it.
pub const SUN_LATENCY: usize = 3;

/// Accumulators over one frame of grouped words, three registered stages.
///
/// Stage 1 registers the word's position (counted from `frame_start` and `groups_per_line`)
/// and whether it counts; stage 2 the products x·L and y·L, each as two 16x16 multiplies of
/// the 15-bit halves of L (rust-hdl has no wider multiply; four DSP blocks); stage 3 adds
/// them to the accumulators. A frame whose first word comes with `armed` low leaves the
/// previous armed frame's sums in place, so the HPS reads them after the whole capture.
#[derive(LogicBlock, Default)]
pub struct SunAccumulators {
    pub clock: Signal<In, Clock>,
    pub word_valid: Signal<In, Bit>,
    /// A grouped word (`skylux_regmap::words::grouped`).
    pub word: Signal<In, Bits<32>>,
    /// With `word_valid`: this word is the first of a frame, group (0, 0).
    pub frame_start: Signal<In, Bit>,
    /// Sampled with a frame's first word: accumulate this frame.
    pub armed: Signal<In, Bit>,
    pub groups_per_line: Signal<In, Bits<11>>,
    /// In 2^-14 DN, the grouped word's luminance field.
    pub threshold_q14: Signal<In, Bits<30>>,
    /// The search window, inclusive, in groups.
    pub x_min: Signal<In, Bits<11>>,
    pub x_max: Signal<In, Bits<11>>,
    pub y_min: Signal<In, Bits<11>>,
    pub y_max: Signal<In, Bits<11>>,

    pub sun_count: Signal<Out, Bits<21>>,
    pub over_count: Signal<Out, Bits<21>>,
    pub sum_l: Signal<Out, Bits<64>>,
    pub sum_xl: Signal<Out, Bits<64>>,
    pub sum_yl: Signal<Out, Bits<64>>,
    pub max_l: Signal<Out, Bits<30>>,
    pub min_x: Signal<Out, Bits<11>>,
    pub max_x: Signal<Out, Bits<11>>,
    pub min_y: Signal<Out, Bits<11>>,
    pub max_y: Signal<Out, Bits<11>>,
    /// Armed frames begun since power-up (wraps): tells the HPS the sums are a new frame's.
    pub armed_frames: Signal<Out, Bits<16>>,

    // Where the current word lies, and whether its frame is armed.
    position: SunPosition,
    // Stage 1.
    s1_first: DFF<Bit>,
    s1_counts: DFF<Bit>,
    s1_over: DFF<Bit>,
    s1_l: DFF<Bits<30>>,
    s1_x: DFF<Bits<11>>,
    s1_y: DFF<Bits<11>>,
    // Stage 2.
    s2_first: DFF<Bit>,
    s2_counts: DFF<Bit>,
    s2_over: DFF<Bit>,
    s2_l: DFF<Bits<30>>,
    s2_x: DFF<Bits<11>>,
    s2_y: DFF<Bits<11>>,
    s2_xl_high: DFF<Bits<32>>,
    s2_xl_low: DFF<Bits<32>>,
    s2_yl_high: DFF<Bits<32>>,
    s2_yl_low: DFF<Bits<32>>,
    // Stage 3: the accumulators.
    acc_count: DFF<Bits<21>>,
    acc_over: DFF<Bits<21>>,
    acc_l: DFF<Bits<64>>,
    acc_xl: DFF<Bits<64>>,
    acc_yl: DFF<Bits<64>>,
    acc_max: DFF<Bits<30>>,
    acc_min_x: DFF<Bits<11>>,
    acc_max_x: DFF<Bits<11>>,
    acc_min_y: DFF<Bits<11>>,
    acc_max_y: DFF<Bits<11>>,
    acc_frames: DFF<Bits<16>>,

    // The current word's luminance.
    luma: Signal<Local, Bits<30>>,
    // The products assembled to 64 bits.
    xl: Signal<Local, Bits<64>>,
    yl: Signal<Local, Bits<64>>,
    // The accumulators as the next word sees them: zero at an armed frame's first word.
    base_count: Signal<Local, Bits<21>>,
    base_over: Signal<Local, Bits<21>>,
    base_l: Signal<Local, Bits<64>>,
    base_xl: Signal<Local, Bits<64>>,
    base_yl: Signal<Local, Bits<64>>,
    base_max: Signal<Local, Bits<30>>,
}

impl Logic for SunAccumulators {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, s1_first, s1_counts, s1_over, s1_l, s1_x, s1_y, s2_first, s2_counts,
            s2_over, s2_l, s2_x, s2_y, s2_xl_high, s2_xl_low, s2_yl_high, s2_yl_low, acc_count,
            acc_over, acc_l, acc_xl, acc_yl, acc_max, acc_min_x, acc_max_x, acc_min_y, acc_max_y,
            acc_frames
        );

        // ---- position: a frame's first word is group (0, 0) --------------------------
        self.position.clock.next = self.clock.val();
        self.position.word_valid.next = self.word_valid.val();
        self.position.frame_start.next = self.frame_start.val();
        self.position.armed.next = self.armed.val();
        self.position.groups_per_line.next = self.groups_per_line.val();

        // ---- stage 1: does the word count ---------------------------------------------
        self.luma.next = self.word.val().get_bits::<30>(0);
        self.s1_first.d.next = self.word_valid.val() & self.frame_start.val() & self.armed.val();
        self.s1_counts.d.next = self.word_valid.val()
            & self.position.armed_now.val()
            & (self.position.pos_x.val() >= self.x_min.val())
            & (self.position.pos_x.val() <= self.x_max.val())
            & (self.position.pos_y.val() >= self.y_min.val())
            & (self.position.pos_y.val() <= self.y_max.val())
            & (self.luma.val() >= self.threshold_q14.val());
        self.s1_over.d.next = self.word.val().get_bit(31);
        self.s1_l.d.next = self.luma.val();
        self.s1_x.d.next = self.position.pos_x.val();
        self.s1_y.d.next = self.position.pos_y.val();

        // ---- stage 2: x·L and y·L as products of the 15-bit halves of L ---------------
        self.s2_first.d.next = self.s1_first.q.val();
        self.s2_counts.d.next = self.s1_counts.q.val();
        self.s2_over.d.next = self.s1_over.q.val();
        self.s2_l.d.next = self.s1_l.q.val();
        self.s2_x.d.next = self.s1_x.q.val();
        self.s2_y.d.next = self.s1_y.q.val();
        self.s2_xl_high.d.next = bit_cast::<16, 11>(self.s1_x.q.val())
            * bit_cast::<16, 15>(self.s1_l.q.val().get_bits::<15>(15));
        self.s2_xl_low.d.next = bit_cast::<16, 11>(self.s1_x.q.val())
            * bit_cast::<16, 15>(self.s1_l.q.val().get_bits::<15>(0));
        self.s2_yl_high.d.next = bit_cast::<16, 11>(self.s1_y.q.val())
            * bit_cast::<16, 15>(self.s1_l.q.val().get_bits::<15>(15));
        self.s2_yl_low.d.next = bit_cast::<16, 11>(self.s1_y.q.val())
            * bit_cast::<16, 15>(self.s1_l.q.val().get_bits::<15>(0));

        // ---- stage 3: accumulate --------------------------------------------------------
        self.xl.next = (bit_cast::<64, 32>(self.s2_xl_high.q.val()) << 15)
            + bit_cast::<64, 32>(self.s2_xl_low.q.val());
        self.yl.next = (bit_cast::<64, 32>(self.s2_yl_high.q.val()) << 15)
            + bit_cast::<64, 32>(self.s2_yl_low.q.val());
        self.base_count.next = self.acc_count.q.val();
        self.base_over.next = self.acc_over.q.val();
        self.base_l.next = self.acc_l.q.val();
        self.base_xl.next = self.acc_xl.q.val();
        self.base_yl.next = self.acc_yl.q.val();
        self.base_max.next = self.acc_max.q.val();
        if self.s2_first.q.val() {
            self.base_count.next = 0.into();
            self.base_over.next = 0.into();
            self.base_l.next = 0.into();
            self.base_xl.next = 0.into();
            self.base_yl.next = 0.into();
            self.base_max.next = 0.into();
            self.acc_min_x.d.next = 0.into();
            self.acc_max_x.d.next = 0.into();
            self.acc_min_y.d.next = 0.into();
            self.acc_max_y.d.next = 0.into();
            self.acc_frames.d.next = self.acc_frames.q.val() + 1;
        }
        self.acc_count.d.next = self.base_count.val();
        self.acc_over.d.next = self.base_over.val();
        self.acc_l.d.next = self.base_l.val();
        self.acc_xl.d.next = self.base_xl.val();
        self.acc_yl.d.next = self.base_yl.val();
        self.acc_max.d.next = self.base_max.val();
        if self.s2_counts.q.val() {
            self.acc_count.d.next = self.base_count.val() + 1;
            if self.s2_over.q.val() {
                self.acc_over.d.next = self.base_over.val() + 1;
            }
            self.acc_l.d.next = self.base_l.val() + bit_cast::<64, 30>(self.s2_l.q.val());
            self.acc_xl.d.next = self.base_xl.val() + self.xl.val();
            self.acc_yl.d.next = self.base_yl.val() + self.yl.val();
            if self.s2_l.q.val() > self.base_max.val() {
                self.acc_max.d.next = self.s2_l.q.val();
            }
            if self.base_count.val() == 0 {
                self.acc_min_x.d.next = self.s2_x.q.val();
                self.acc_max_x.d.next = self.s2_x.q.val();
                self.acc_min_y.d.next = self.s2_y.q.val();
                self.acc_max_y.d.next = self.s2_y.q.val();
            } else {
                if self.s2_x.q.val() < self.acc_min_x.q.val() {
                    self.acc_min_x.d.next = self.s2_x.q.val();
                }
                if self.s2_x.q.val() > self.acc_max_x.q.val() {
                    self.acc_max_x.d.next = self.s2_x.q.val();
                }
                if self.s2_y.q.val() < self.acc_min_y.q.val() {
                    self.acc_min_y.d.next = self.s2_y.q.val();
                }
                if self.s2_y.q.val() > self.acc_max_y.q.val() {
                    self.acc_max_y.d.next = self.s2_y.q.val();
                }
            }
        }

        self.sun_count.next = self.acc_count.q.val();
        self.over_count.next = self.acc_over.q.val();
        self.sum_l.next = self.acc_l.q.val();
        self.sum_xl.next = self.acc_xl.q.val();
        self.sum_yl.next = self.acc_yl.q.val();
        self.max_l.next = self.acc_max.q.val();
        self.min_x.next = self.acc_min_x.q.val();
        self.max_x.next = self.acc_max_x.q.val();
        self.min_y.next = self.acc_min_y.q.val();
        self.max_y.next = self.acc_max_y.q.val();
        self.armed_frames.next = self.acc_frames.q.val();
    }
}
