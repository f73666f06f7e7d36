//! The pixel capture block alone, in its PIXCLK domain: what it forwards to the grouper and
//! what it writes into the FIFO (markers, flags, counts), including the FIFO-full paths that
//! the end-to-end tests (tests/tests/capture_path.rs) reach only rarely.

use rust_hdl::prelude::*;
use skylux_rtl::capture::fifo_entry as entry;
use skylux_rtl::capture::PixelCapture;
use skylux_rtl::drive::Driver;

fn clock(d: &mut PixelCapture) -> &mut Signal<In, Clock> {
    &mut d.clock
}

/// A driven block and what it wrote into the FIFO.
struct Bench {
    driver: Driver<PixelCapture>,
    entries: Vec<u64>,
    forwarded: usize,
}

impl Bench {
    fn new(width: u64, height: u64) -> Self {
        let mut driver = Driver::new(PixelCapture::default());
        let d = &mut driver.dut;
        d.enable.next = true;
        d.width.next = width.into();
        d.height.next = height.into();
        let mut b = Bench {
            driver,
            entries: vec![],
            forwarded: 0,
        };
        b.idle(4);
        b
    }

    fn cycle(&mut self, fv: bool, lv: bool, data: u64) {
        let d = &mut self.driver.dut;
        d.frame_valid.next = fv;
        d.line_valid.next = lv;
        d.data.next = data.into();
        self.driver.settle().unwrap();
        if self.driver.dut.fifo_write.val() {
            self.entries.push(self.driver.dut.fifo_data.val().to_u64());
        }
        self.forwarded += usize::from(self.driver.dut.pixel_valid.val());
        self.driver.set_clock(clock, true).unwrap();
        self.driver.set_clock(clock, false).unwrap();
    }

    fn idle(&mut self, n: usize) {
        for _ in 0..n {
            self.cycle(false, false, 0);
        }
    }

    /// A frame of `lines` lines of the given lengths.
    fn frame(&mut self, line_pixels: &[usize]) {
        self.cycle(true, false, 0);
        for &n in line_pixels {
            for x in 0..n {
                self.cycle(true, true, x as u64);
            }
            self.cycle(true, false, 0);
            self.cycle(true, false, 0);
        }
        self.idle(entry::END_MARKER_DELAY as usize + 4);
    }

    fn set_fill(&mut self, fill: u64) {
        self.driver.dut.fifo_fill.next = fill.into();
    }
}

fn end_flags(e: u64) -> Vec<&'static str> {
    [
        (entry::LINE_SHORT_BIT, "LINE_SHORT"),
        (entry::LINE_LONG_BIT, "LINE_LONG"),
        (entry::FRAME_SHORT_BIT, "FRAME_SHORT"),
        (entry::FRAME_LONG_BIT, "FRAME_LONG"),
        (entry::FIFO_OVERFLOW_BIT, "FIFO_OVERFLOW"),
        (entry::FRAMES_SKIPPED_BIT, "FRAMES_SKIPPED"),
    ]
    .into_iter()
    .filter(|(b, _)| e >> b & 1 == 1)
    .map(|(_, n)| n)
    .collect()
}

fn counts(e: u64) -> (u64, u64) {
    (
        (e >> entry::PIXELS_LSB) & 0xFFF,
        (e >> entry::LINES_LSB) & 0xFFF,
    )
}

#[test]
fn well_formed_and_malformed_frames_get_the_right_markers() {
    let mut b = Bench::new(8, 3);
    b.frame(&[8, 8, 8]);
    assert_eq!(b.entries.len(), 2);
    assert_eq!(b.entries[0], entry::START);
    assert_eq!(b.entries[1] & entry::END, entry::END);
    assert!(end_flags(b.entries[1]).is_empty());
    assert_eq!(counts(b.entries[1]), (8, 3));
    assert_eq!(b.forwarded, 24);

    // Short and long lines, a missing line; extra pixels are not forwarded.
    b.entries.clear();
    b.forwarded = 0;
    b.frame(&[5, 11]);
    assert_eq!(
        end_flags(b.entries[1]),
        vec!["LINE_SHORT", "LINE_LONG", "FRAME_SHORT"]
    );
    assert_eq!(counts(b.entries[1]), (11, 2));
    assert_eq!(b.forwarded, 5 + 8);

    // An extra line is counted, flagged and not forwarded.
    b.entries.clear();
    b.forwarded = 0;
    b.frame(&[8, 8, 8, 8]);
    assert_eq!(end_flags(b.entries[1]), vec!["FRAME_LONG"]);
    assert_eq!(counts(b.entries[1]), (8, 4));
    assert_eq!(b.forwarded, 24);
}

#[test]
fn a_full_fifo_skips_frames_and_drops_words_but_always_flags_them() {
    let mut b = Bench::new(4, 2);
    // No room for a frame's markers: the frame is not captured at all ...
    b.set_fill(entry::START_FILL_LIMIT);
    b.frame(&[4, 4]);
    assert!(b.entries.is_empty());
    assert_eq!(b.forwarded, 0);
    // ... and the next captured frame says so.
    b.set_fill(0);
    b.frame(&[4, 4]);
    assert_eq!(end_flags(b.entries[1]), vec!["FRAMES_SKIPPED"]);

    // A word offered while the FIFO is at its data limit is dropped and the frame flagged;
    // the end marker still goes in.
    b.entries.clear();
    b.cycle(true, false, 0);
    b.cycle(true, false, 0);
    b.cycle(true, false, 0);
    b.set_fill(entry::DATA_FILL_LIMIT);
    b.driver.dut.word.next = 0x1234u64.into();
    b.driver.dut.word_valid.next = true;
    b.cycle(true, true, 1);
    b.driver.dut.word_valid.next = false;
    for _ in 0..3 {
        b.cycle(true, true, 1);
    }
    b.cycle(true, false, 0);
    b.idle(entry::END_MARKER_DELAY as usize + 4);
    assert_eq!(b.entries.len(), 2, "{:x?}", b.entries);
    assert_eq!(
        end_flags(b.entries[1]),
        vec!["FRAME_SHORT", "FIFO_OVERFLOW"]
    );
}

#[test]
fn a_line_that_starts_with_frame_valid_keeps_its_first_pixel() {
    // No frame-start blanking: LV rises on FV's first PIXCLK (the sensor model's timing).
    let mut b = Bench::new(8, 2);
    for line in 0..2 {
        for x in 0..8 {
            b.cycle(true, true, (16 * line + x) as u64);
        }
        b.cycle(line == 0, false, 0);
    }
    b.idle(entry::END_MARKER_DELAY as usize + 4);
    assert_eq!(b.entries.len(), 2);
    assert!(
        end_flags(b.entries[1]).is_empty(),
        "{:?}",
        end_flags(b.entries[1])
    );
    assert_eq!(counts(b.entries[1]), (8, 2));
    assert_eq!(b.forwarded, 16);
}
