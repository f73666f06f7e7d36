//! Where the current grouped word lies in its frame, and whether its frame is armed.

use rust_hdl::prelude::*;

/// Counts words into (x, y) group coordinates: a frame's first word (`frame_start` with
/// `word_valid`) is (0, 0), and a line holds `groups_per_line` words (one when zero). The
/// outputs describe the word at the inputs, combinationally; `armed_now` is `armed` as it
/// was sampled with the frame's first word.
#[derive(LogicBlock, Default)]
pub struct SunPosition {
    pub clock: Signal<In, Clock>,
    pub word_valid: Signal<In, Bit>,
    pub frame_start: Signal<In, Bit>,
    pub armed: Signal<In, Bit>,
    pub groups_per_line: Signal<In, Bits<11>>,
    pub pos_x: Signal<Out, Bits<11>>,
    pub pos_y: Signal<Out, Bits<11>>,
    pub armed_now: Signal<Out, Bit>,

    next_x: DFF<Bits<11>>,
    next_y: DFF<Bits<11>>,
    frame_armed: DFF<Bit>,
}

impl Logic for SunPosition {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, next_x, next_y, frame_armed);
        self.pos_x.next = self.next_x.q.val();
        self.pos_y.next = self.next_y.q.val();
        self.armed_now.next = self.frame_armed.q.val();
        if self.word_valid.val() & self.frame_start.val() {
            self.pos_x.next = 0.into();
            self.pos_y.next = 0.into();
            self.armed_now.next = self.armed.val();
            self.frame_armed.d.next = self.armed.val();
        }
        if self.word_valid.val() {
            self.next_x.d.next = self.pos_x.val() + 1;
            self.next_y.d.next = self.pos_y.val();
            if (self.pos_x.val() + 1) >= self.groups_per_line.val() {
                self.next_x.d.next = 0.into();
                self.next_y.d.next = self.pos_y.val() + 1;
            }
        }
    }
}
