//! FRAME_VALID / LINE_VALID timing, one PIXCLK at a time: the state machine the pixel path is
//! driven with.
//!
//! **API for the capture path.** Build a [`FrameTiming`], start frames with
//! [`FrameTiming::trigger`] (snapshot mode) or let it run free ([`Mode::Continuous`]), and
//! call [`FrameTiming::tick`] once per PIXCLK period. Each tick returns the levels of FV and
//! LV *for that PIXCLK period* and, when both are high, which output pixel (column `x`, line
//! `y` of the frame, in read-out order) D[11:0] carries. Pair it with a frame of samples
//! ([`super::Mt9p031::frame_samples`]) to get the pixel values.
//!
//! Waveform (hardware-facts.md §1.5; the exact placement of FV's edges relative to LV is not
//! in the sources and is modelled as below) [U]:
//! - a row is `t_ROW` PIXCLK: LV high for W PIXCLK (one pixel each), then low for
//!   `t_ROW − W` (horizontal blanking);
//! - FV rises with the first pixel of line 0 and falls with the end of line H−1's last pixel;
//! - then FV stays low for the rest of that row and `max(VB, VB_MIN)` rows (vertical
//!   blanking);
//! - snapshot: a trigger starts the exposure (FV low for `t_EXP` PIXCLK), then the frame as
//!   above; a trigger during the blanking after a frame waits for its end, one during an
//!   exposure or a frame is ignored (counted in [`FrameTiming::ignored_triggers`]);
//! - continuous: frames follow each other, `(H + max(VB, VB_MIN)) t_ROW` apart.

use super::timing::FrameGeometry;

/// Free-running or triggered frames.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Mode {
    Continuous,
    Snapshot,
}

/// Everything a frame needs, latched when it starts (at the trigger in snapshot mode).
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct FrameSettings {
    pub geometry: FrameGeometry,
    pub shutter_width_rows: u32,
    pub exposure_pixclk: u64,
    pub gain: f64,
    pub mirror_row: bool,
    pub mirror_column: bool,
}

/// The pixel bus during one PIXCLK period.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct BusState {
    pub frame_valid: bool,
    pub line_valid: bool,
    /// Output column and line of the pixel on D when both are high.
    pub x: u32,
    pub y: u32,
    /// The first PIXCLK of a frame (FV's rise).
    pub frame_start: bool,
    /// Frames started so far (the one on the bus is `frames − 1`).
    pub frames: u64,
}

#[derive(Copy, Clone, Debug, PartialEq)]
enum Phase {
    WaitTrigger,
    Exposure { left: u64 },
    Rows { row: u32, col: u64 },
    Blank { left: u64 },
}

/// The FV/LV generator.
#[derive(Clone, Debug)]
pub struct FrameTiming {
    pub mode: Mode,
    settings: FrameSettings,
    phase: Phase,
    frames: u64,
    pending: Option<FrameSettings>,
    pub ignored_triggers: u64,
}

impl FrameTiming {
    /// A generator that starts idle (snapshot) or at the first line of a frame (continuous).
    pub fn new(mode: Mode, settings: FrameSettings) -> Self {
        let phase = match mode {
            Mode::Snapshot => Phase::WaitTrigger,
            Mode::Continuous => Phase::Rows { row: 0, col: 0 },
        };
        Self {
            mode,
            settings,
            phase,
            frames: 0,
            pending: None,
            ignored_triggers: 0,
        }
    }

    /// The settings of the frame in progress (or of the last one).
    pub fn settings(&self) -> &FrameSettings {
        &self.settings
    }

    /// Waiting for a trigger (snapshot mode, between frames).
    pub fn idle(&self) -> bool {
        self.phase == Phase::WaitTrigger
    }

    /// Starts a snapshot exposure with these settings. A trigger during the vertical
    /// blanking after a frame is held and starts the exposure when the blanking ends [U]; one
    /// during an exposure or a frame is ignored (returns false).
    pub fn trigger(&mut self, settings: FrameSettings) -> bool {
        if let Phase::Blank { .. } = self.phase {
            if self.mode == Mode::Snapshot && self.pending.is_none() {
                self.pending = Some(settings);
                return true;
            }
        }
        if self.phase != Phase::WaitTrigger {
            self.ignored_triggers += 1;
            return false;
        }
        self.settings = settings;
        self.phase = Phase::Exposure {
            left: settings.exposure_pixclk,
        };
        true
    }

    /// Changes the settings the next continuous frame starts with.
    pub fn set_next_settings(&mut self, settings: FrameSettings) {
        if self.mode == Mode::Continuous {
            self.settings = settings;
        }
    }

    /// Advances one PIXCLK period and returns the bus during it.
    pub fn tick(&mut self) -> BusState {
        let g = self.settings.geometry;
        let row_len = g.row_pixclk().max(u64::from(g.width));
        let mut bus = BusState {
            frames: self.frames,
            ..Default::default()
        };
        loop {
            match self.phase {
                Phase::WaitTrigger => return bus,
                Phase::Exposure { left } => {
                    if left == 0 {
                        self.phase = Phase::Rows { row: 0, col: 0 };
                        continue;
                    }
                    self.phase = Phase::Exposure { left: left - 1 };
                    return bus;
                }
                Phase::Rows { row, col } => {
                    if row == 0 && col == 0 {
                        self.frames += 1;
                        bus.frame_start = true;
                        bus.frames = self.frames;
                    }
                    let active = col < u64::from(g.width);
                    let last_row = row + 1 >= g.height;
                    bus.frame_valid = !last_row || active;
                    bus.line_valid = active;
                    bus.x = col as u32;
                    bus.y = row;
                    self.phase = if col + 1 < row_len {
                        Phase::Rows { row, col: col + 1 }
                    } else if !last_row {
                        Phase::Rows {
                            row: row + 1,
                            col: 0,
                        }
                    } else {
                        Phase::Blank {
                            left: u64::from(
                                g.vertical_blank_rows(self.settings.shutter_width_rows),
                            ) * g.row_pixclk(),
                        }
                    };
                    return bus;
                }
                Phase::Blank { left } => {
                    if left == 0 {
                        self.phase = match self.mode {
                            Mode::Snapshot => Phase::WaitTrigger,
                            Mode::Continuous => Phase::Rows { row: 0, col: 0 },
                        };
                        if let Some(settings) = self.pending.take() {
                            self.trigger(settings);
                        }
                        continue;
                    }
                    self.phase = Phase::Blank { left: left - 1 };
                    return bus;
                }
            }
        }
    }
}
