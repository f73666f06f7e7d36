//! Driving [`SunAccumulators`] as the grouped-word stream does, for the tests here and the
//! Verilog cross-check in `skylux-bitstream` (one home for the stream's protocol).

use super::golden::{SunConfig, SunSums};
use super::SunAccumulators;
use crate::drive::Driver;
use rust_hdl::prelude::*;

fn clock(d: &mut SunAccumulators) -> &mut Signal<In, Clock> {
    &mut d.clock
}

/// A driven block, with garbage on the data inputs of idle cycles (they must be ignored).
pub struct SunBench {
    pub driver: Driver<SunAccumulators>,
    noise: u64,
}

impl SunBench {
    pub fn new(seed: u64) -> Self {
        SunBench {
            driver: Driver::new(SunAccumulators::default()),
            noise: seed | 1,
        }
    }

    /// xorshift64 (Marsaglia 2003): garbage, not statistics.
    fn garbage(&mut self) -> u64 {
        self.noise ^= self.noise << 13;
        self.noise ^= self.noise >> 7;
        self.noise ^= self.noise << 17;
        self.noise
    }

    pub fn configure(&mut self, c: &SunConfig) {
        let d = &mut self.driver.dut;
        d.groups_per_line.next = u64::from(c.groups_per_line).into();
        d.threshold_q14.next = u64::from(c.threshold_q14).into();
        d.x_min.next = u64::from(c.x_min).into();
        d.x_max.next = u64::from(c.x_max).into();
        d.y_min.next = u64::from(c.y_min).into();
        d.y_max.next = u64::from(c.y_max).into();
    }

    fn cycle(&mut self) {
        self.driver.cycle(clock).expect("the accumulators settle");
    }

    /// `n` cycles with `word_valid` low and garbage on the word, `frame_start` and `armed`.
    pub fn idle(&mut self, n: usize) {
        for _ in 0..n {
            let g = self.garbage();
            let d = &mut self.driver.dut;
            d.word_valid.next = false;
            d.word.next = (g & 0xFFFF_FFFF).into();
            d.frame_start.next = g & (1 << 40) != 0;
            d.armed.next = g & (1 << 41) != 0;
            self.cycle();
        }
    }

    /// One frame of words; `gap()` idle cycles before each. Only the first word's `armed`
    /// matters: the others carry garbage.
    pub fn frame(&mut self, words: &[u32], armed: bool, mut gap: impl FnMut() -> usize) {
        for (i, &w) in words.iter().enumerate() {
            let n = gap();
            self.idle(n);
            let g = self.garbage();
            let d = &mut self.driver.dut;
            d.word_valid.next = true;
            d.word.next = u64::from(w).into();
            d.frame_start.next = i == 0;
            d.armed.next = if i == 0 { armed } else { g & 1 != 0 };
            self.cycle();
        }
    }

    /// The accumulators' outputs.
    pub fn sums(&self) -> SunSums {
        let d = &self.driver.dut;
        let v21 = |s: &Signal<Out, Bits<21>>| s.val().to_u64() as u32;
        let v11 = |s: &Signal<Out, Bits<11>>| s.val().to_u64() as u16;
        SunSums {
            count: v21(&d.sun_count),
            over_count: v21(&d.over_count),
            sum_l: d.sum_l.val().to_u64(),
            sum_xl: d.sum_xl.val().to_u64(),
            sum_yl: d.sum_yl.val().to_u64(),
            max_l: d.max_l.val().to_u64() as u32,
            min_x: v11(&d.min_x),
            max_x: v11(&d.max_x),
            min_y: v11(&d.min_y),
            max_y: v11(&d.max_y),
        }
    }

    /// Armed frames begun, as the block counts them.
    pub fn armed_frames(&self) -> u64 {
        self.driver.dut.armed_frames.val().to_u64()
    }
}
