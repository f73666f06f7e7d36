//! The sensor's parallel output as a waveform: FRAME_VALID, LINE_VALID and D[11:0] per PIXCLK,
//! with blanking, from a raw frame, and with the faults a cable, a sensor or a clock can
//! produce (issue 3 "Fault injection").
//!
//! The blanking here is its own (a short default keeps simulations quick); the MT9P031's real
//! row and frame timing (hardware-facts.md §1.5) lives with the sensor model in `mt9p031/`.

use std::collections::VecDeque;

/// Blanking around the active pixels, in PIXCLK periods.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Blanking {
    /// FV high before the first LV.
    pub fv_to_lv_pixclk: usize,
    /// LV low between lines.
    pub horizontal_pixclk: usize,
    /// FV high after the last LV.
    pub lv_to_fv_pixclk: usize,
    /// FV low after a frame.
    pub vertical_pixclk: usize,
}

impl Default for Blanking {
    fn default() -> Self {
        Blanking {
            fv_to_lv_pixclk: 6,
            horizontal_pixclk: 16,
            lv_to_fv_pixclk: 6,
            vertical_pixclk: 64,
        }
    }
}

/// A fault injected into one frame. Rows and columns are positions in the frame's active
/// area; a position past the frame's end leaves the frame untouched.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Fault {
    /// FRAME_VALID (and LINE_VALID) fall before pixel `column` of `row`; the frame ends there.
    FvDropMidLine { row: usize, column: usize },
    /// LINE_VALID goes low for `pixclk` periods before pixel `column` of `row` (no data lost,
    /// the line is cut in two).
    LvGlitch {
        row: usize,
        column: usize,
        pixclk: usize,
    },
    /// PIXCLK stops for `pixclk` periods before pixel `column` of `row`, pins frozen.
    PixclkStop {
        row: usize,
        column: usize,
        pixclk: usize,
    },
    /// `count` rows more than the frame has (copies of its last row).
    ExtraLines { count: usize },
    /// The last `count` rows are not sent.
    MissingLines { count: usize },
    /// Row `row` loses its last `pixels` pixels.
    ShortLine { row: usize, pixels: usize },
    /// Row `row` carries `pixels` more pixels (copies of its last one).
    LongLine { row: usize, pixels: usize },
}

/// The pins during one PIXCLK period.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct Pins {
    pub frame_valid: bool,
    pub line_valid: bool,
    pub data: u16,
}

/// One PIXCLK period of the waveform.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Step {
    /// PIXCLK ticks with these pins.
    Tick(Pins),
    /// PIXCLK does not tick (the pins hold their last value).
    Stopped,
}

#[derive(Clone, Debug)]
enum Segment {
    /// `cycles` periods with LV low.
    Blank {
        frame_valid: bool,
        cycles: usize,
    },
    /// Active pixels.
    Line {
        samples: Vec<u16>,
    },
    Stop {
        cycles: usize,
    },
}

/// Generates the waveform of a sequence of frames, PIXCLK period by period.
#[derive(Clone, Debug, Default)]
pub struct PixelBus {
    segments: VecDeque<Segment>,
    /// Index within the head segment.
    position: usize,
    last: Pins,
    /// Active pixels (FV and LV high) emitted so far.
    pub pixels_sent: u64,
}

impl PixelBus {
    pub fn new() -> Self {
        Self::default()
    }

    /// Queues a frame of `width x height` samples (row-major) with `faults`.
    pub fn push_frame(
        &mut self,
        samples: &[u16],
        width: usize,
        height: usize,
        blanking: &Blanking,
        faults: &[Fault],
    ) {
        let height = height.min(samples.len().checked_div(width).unwrap_or(0));
        let mut rows: Vec<Vec<u16>> = (0..height)
            .map(|y| samples[y * width..(y + 1) * width].to_vec())
            .collect();
        for f in faults {
            match *f {
                Fault::ExtraLines { count } => {
                    if let Some(last) = rows.last().cloned() {
                        rows.extend(std::iter::repeat_n(last, count));
                    }
                }
                Fault::MissingLines { count } => rows.truncate(rows.len().saturating_sub(count)),
                Fault::ShortLine { row, pixels } => {
                    if let Some(r) = rows.get_mut(row) {
                        r.truncate(r.len().saturating_sub(pixels));
                    }
                }
                Fault::LongLine { row, pixels } => {
                    if let Some(r) = rows.get_mut(row) {
                        let last = r.last().copied().unwrap_or(0);
                        r.extend(std::iter::repeat_n(last, pixels));
                    }
                }
                _ => {}
            }
        }
        let mut frame = vec![Segment::Blank {
            frame_valid: true,
            cycles: blanking.fv_to_lv_pixclk,
        }];
        'rows: for (y, row) in rows.iter().enumerate() {
            // Cut points in this row from the mid-line faults, in column order.
            let mut cuts: Vec<(usize, Fault)> = faults
                .iter()
                .filter_map(|f| match *f {
                    Fault::FvDropMidLine { row, column }
                    | Fault::LvGlitch { row, column, .. }
                    | Fault::PixclkStop { row, column, .. }
                        if row == y && column < row_len(row, &rows) =>
                    {
                        Some((column, *f))
                    }
                    _ => None,
                })
                .collect();
            cuts.sort_by_key(|c| c.0);
            let mut from = 0;
            for (column, fault) in cuts {
                frame.push(Segment::Line {
                    samples: row[from..column].to_vec(),
                });
                from = column;
                match fault {
                    // FV and LV fall together: the vertical blank below follows at once.
                    Fault::FvDropMidLine { .. } => break 'rows,
                    Fault::LvGlitch { pixclk, .. } => frame.push(Segment::Blank {
                        frame_valid: true,
                        cycles: pixclk,
                    }),
                    Fault::PixclkStop { pixclk, .. } => {
                        frame.push(Segment::Stop { cycles: pixclk })
                    }
                    _ => {}
                }
            }
            frame.push(Segment::Line {
                samples: row[from..].to_vec(),
            });
            let gap = if y + 1 == rows.len() {
                blanking.lv_to_fv_pixclk
            } else {
                blanking.horizontal_pixclk
            };
            frame.push(Segment::Blank {
                frame_valid: true,
                cycles: gap,
            });
        }
        frame.push(Segment::Blank {
            frame_valid: false,
            cycles: blanking.vertical_pixclk,
        });
        self.segments.extend(frame.into_iter().filter(|s| match s {
            Segment::Line { samples } => !samples.is_empty(),
            Segment::Blank { cycles, .. } | Segment::Stop { cycles } => *cycles > 0,
        }));
    }

    /// Queues `cycles` PIXCLK periods with FV low.
    pub fn push_idle(&mut self, cycles: usize) {
        if cycles > 0 {
            self.segments.push_back(Segment::Blank {
                frame_valid: false,
                cycles,
            });
        }
    }

    /// Whether every queued period has been emitted.
    pub fn is_done(&self) -> bool {
        self.segments.is_empty()
    }

    /// The next PIXCLK period (FV and LV low once the queue is empty).
    pub fn next_step(&mut self) -> Step {
        let Some(head) = self.segments.front() else {
            self.last = Pins {
                data: self.last.data,
                ..Pins::default()
            };
            return Step::Tick(self.last);
        };
        let (step, len) = match head {
            Segment::Blank {
                frame_valid,
                cycles,
            } => (
                Step::Tick(Pins {
                    frame_valid: *frame_valid,
                    line_valid: false,
                    data: self.last.data,
                }),
                *cycles,
            ),
            Segment::Line { samples } => {
                self.pixels_sent += 1;
                (
                    Step::Tick(Pins {
                        frame_valid: true,
                        line_valid: true,
                        data: samples[self.position],
                    }),
                    samples.len(),
                )
            }
            Segment::Stop { cycles } => (Step::Stopped, *cycles),
        };
        self.position += 1;
        if self.position >= len {
            self.position = 0;
            self.segments.pop_front();
        }
        if let Step::Tick(p) = step {
            self.last = p;
        }
        step
    }
}

fn row_len(row: usize, rows: &[Vec<u16>]) -> usize {
    rows.get(row).map_or(0, Vec::len)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(bus: &mut PixelBus) -> Vec<Step> {
        let mut v = vec![];
        while !bus.is_done() {
            v.push(bus.next_step());
        }
        v
    }

    fn active(steps: &[Step]) -> Vec<u16> {
        steps
            .iter()
            .filter_map(|s| match s {
                Step::Tick(p) if p.frame_valid && p.line_valid => Some(p.data),
                _ => None,
            })
            .collect()
    }

    #[test]
    fn clean_frame_has_every_pixel_in_order_and_blanking() {
        let samples: Vec<u16> = (0..12).collect();
        let b = Blanking::default();
        let mut bus = PixelBus::new();
        bus.push_frame(&samples, 4, 3, &b, &[]);
        let steps = run(&mut bus);
        assert_eq!(active(&steps), samples);
        let expected_len = b.fv_to_lv_pixclk
            + 12
            + 2 * b.horizontal_pixclk
            + b.lv_to_fv_pixclk
            + b.vertical_pixclk;
        assert_eq!(steps.len(), expected_len);
        assert_eq!(bus.pixels_sent, 12);
    }

    #[test]
    fn faults_shape_the_waveform() {
        let samples: Vec<u16> = (0..16).collect();
        let b = Blanking::default();
        let mut bus = PixelBus::new();
        bus.push_frame(
            &samples,
            4,
            4,
            &b,
            &[Fault::FvDropMidLine { row: 1, column: 2 }],
        );
        assert_eq!(active(&run(&mut bus)), vec![0, 1, 2, 3, 4, 5]);

        bus.push_frame(
            &samples,
            4,
            4,
            &b,
            &[Fault::PixclkStop {
                row: 0,
                column: 1,
                pixclk: 7,
            }],
        );
        let steps = run(&mut bus);
        assert_eq!(steps.iter().filter(|s| **s == Step::Stopped).count(), 7);
        assert_eq!(active(&steps), samples);

        bus.push_frame(&samples, 4, 4, &b, &[Fault::ExtraLines { count: 2 }]);
        assert_eq!(active(&run(&mut bus)).len(), 24);
        bus.push_frame(
            &samples,
            4,
            4,
            &b,
            &[
                Fault::MissingLines { count: 1 },
                Fault::ShortLine { row: 0, pixels: 1 },
            ],
        );
        assert_eq!(
            active(&run(&mut bus)),
            vec![0, 1, 2, 4, 5, 6, 7, 8, 9, 10, 11]
        );
    }
}
