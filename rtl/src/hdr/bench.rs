//! Driving [`HdrSelect`] as the DMA's ingest does, for the tests here and the Verilog
//! cross-check in `skylux-bitstream` (one home for the stream's protocol).

use super::golden::{HdrConfig, SetFrame};
use super::HdrSelect;
use crate::drive::Driver;
use rust_hdl::prelude::*;

fn clock(d: &mut HdrSelect) -> &mut Signal<In, Clock> {
    &mut d.clock
}

/// A driven block, with garbage on the inputs that idle cycles must ignore.
pub struct HdrBench {
    pub driver: Driver<HdrSelect>,
    noise: u64,
}

impl HdrBench {
    pub fn new(seed: u64) -> Self {
        HdrBench {
            driver: Driver::new(HdrSelect::default()),
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

    pub fn configure(&mut self, c: &HdrConfig) {
        let d = &mut self.driver.dut;
        d.min_q11.next = u64::from(c.min_q11).into();
        d.max_q11.next = u64::from(c.max_q11).into();
    }

    /// Settles the inputs set, then one rising and falling edge.
    fn cycle(&mut self) {
        self.driver.settle().expect("the selection settles");
        self.edge();
    }

    fn edge(&mut self) {
        self.driver
            .set_clock(clock, true)
            .and_then(|_| self.driver.set_clock(clock, false))
            .expect("the selection settles");
    }

    /// Garbage on the word, `first_of_set` and `exposure_index`; `take` and `restart` low.
    fn garbage_inputs(&mut self) {
        let g = self.garbage();
        let d = &mut self.driver.dut;
        d.take.next = false;
        d.restart.next = false;
        d.word.next = (g & 0xFFFF_FFFF).into();
        d.first_of_set.next = g & (1 << 40) != 0;
        d.exposure_index.next = ((g >> 41) & 7).into();
    }

    /// `n` idle cycles.
    pub fn idle(&mut self, n: usize) {
        for _ in 0..n {
            self.garbage_inputs();
            self.cycle();
        }
    }

    /// One frame: the restart cycle, then the words, `gap()` idle cycles before each. Returns
    /// the map word and write flag the block gave each word as it was taken.
    pub fn frame(&mut self, frame: &SetFrame, mut gap: impl FnMut() -> usize) -> Vec<(u32, bool)> {
        self.garbage_inputs();
        let d = &mut self.driver.dut;
        d.restart.next = true;
        d.first_of_set.next = frame.first_of_set;
        d.exposure_index.next = u64::from(frame.exposure_index & 7).into();
        self.cycle();
        let mut out = Vec::with_capacity(frame.words.len());
        for &w in frame.words {
            let n = gap();
            self.idle(n);
            self.garbage_inputs();
            let d = &mut self.driver.dut;
            d.take.next = true;
            d.word.next = u64::from(w).into();
            self.driver.settle().expect("the selection settles");
            let d = &self.driver.dut;
            out.push((d.map_word.val().to_u64() as u32, d.map_write.val()));
            self.edge();
        }
        out
    }
}
