//! The MT9P031's snapshot time line at transaction level: a TRIGGER rising edge starts the
//! exposure, FRAME_VALID rises after it and falls after the rows, then the vertical blanking
//! (hardware-facts.md §1.5, §1.6), with the times of `crate::mt9p031::frame::FrameTiming`
//! (the same row time, exposure formula and blanking from `crate::mt9p031::timing`) computed
//! once per frame instead of per PIXCLK. The pixel values come from the sensor's own
//! `PixelSource` at FRAME_VALID's rise, as in the cycle-accurate rig.

use super::{FabricModel, HardwareFault};
use crate::mt9p031::FrameSettings;

/// One frame of the sensor, with its times in system clocks.
#[derive(Clone, Debug)]
pub struct SensorFrame {
    /// The sensor's frame count (seeds the noise: `crate::mt9p031::SceneSource`).
    pub index: u64,
    pub settings: FrameSettings,
    pub trigger_at: u64,
    pub rise_at: u64,
    pub fall_at: u64,
    pub idle_at: u64,
    /// Lines and pixels per line the sensor actually sends (a fault may change them).
    pub lines: u32,
    /// PIXCLK stops at this clock (FRAME_VALID then stays high until a reset).
    pub stops_at: Option<u64>,
    /// Frame faults acting on this frame.
    pub faults: Vec<HardwareFault>,
    pub rise_done: bool,
    pub fall_done: bool,
    pub stop_done: bool,
}

/// System clocks without a PIXCLK heartbeat before the ingest closes a frame as
/// `PIXCLK_STOPPED` (`skylux_rtl::dma::ingest`: bit 10 of its counter, 1024 clocks), plus the
/// synchroniser.
pub const PIXCLK_WATCHDOG_CYCLES: u64 = 1024 + 3;

/// The sensor's frames.
#[derive(Clone, Debug, Default)]
pub struct SensorTimeline {
    pub frame: Option<SensorFrame>,
    /// A trigger during the blanking, held until it ends (`FrameTiming::trigger`), with the
    /// settings latched at the trigger.
    pending: Option<FrameSettings>,
    pub frames_started: u64,
    pub ignored_triggers: u64,
    /// PIXCLK has stopped; it runs again after a reset.
    pub pixclk_stopped: bool,
}

impl SensorTimeline {
    /// FRAME_VALID's rise of the current frame.
    pub fn rise_at(&self) -> Option<u64> {
        self.frame.as_ref().map(|f| f.rise_at)
    }

    /// FRAME_VALID's fall of the current frame (never, once PIXCLK stopped before it).
    pub fn fall_at(&self) -> Option<u64> {
        self.frame
            .as_ref()
            .filter(|f| f.stops_at.is_none_or(|s| s >= f.fall_at))
            .map(|f| f.fall_at)
    }

    /// FRAME_VALID at clock `t` (as the sensor drives it).
    pub fn frame_valid(&self, t: u64) -> bool {
        self.frame.as_ref().is_some_and(|f| {
            t >= f.rise_at && (t < f.fall_at || f.stops_at.is_some_and(|s| s < f.fall_at))
        })
    }

    pub fn next_event(&self) -> Option<u64> {
        let f = self.frame.as_ref()?;
        let stopped = f.stops_at.filter(|&s| s < f.fall_at);
        [
            (!f.rise_done).then_some(f.rise_at),
            (!f.fall_done && stopped.is_none()).then_some(f.fall_at),
            stopped
                .filter(|_| !f.stop_done)
                .map(|s| s + PIXCLK_WATCHDOG_CYCLES),
            self.pending.filter(|_| f.fall_done).map(|_| f.idle_at),
        ]
        .into_iter()
        .flatten()
        .min()
    }
}

impl FabricModel {
    /// A rising edge on TRIGGER (or Restart.Trigger): in snapshot mode a frame starts now,
    /// or at the end of the blanking; during an exposure or a frame it is ignored.
    pub(super) fn sensor_trigger(&mut self) {
        if !self.sensor.registers.snapshot_mode() || self.timeline.pixclk_stopped {
            self.timeline.ignored_triggers += 1;
            return;
        }
        let settings = self.sensor.settings();
        let now = self.now;
        match &self.timeline.frame {
            Some(f) if now < f.idle_at => {
                if f.fall_done && self.timeline.pending.is_none() {
                    self.timeline.pending = Some(settings);
                } else {
                    self.timeline.ignored_triggers += 1;
                }
            }
            _ => self.sensor_start_frame(now, settings),
        }
    }

    fn sensor_start_frame(&mut self, at: u64, settings: FrameSettings) {
        let g = settings.geometry;
        let row = g.row_pixclk();
        let row_len = row.max(u64::from(g.width));
        let faults = std::mem::take(&mut self.pending_frame_faults);
        let mut lines = g.height;
        let mut stops_after = None;
        for f in &faults {
            match *f {
                HardwareFault::FrameLength { delta_lines } => {
                    lines = lines.saturating_add_signed(delta_lines).max(1)
                }
                HardwareFault::PixclkStops { after_lines } => stops_after = Some(after_lines),
                _ => {}
            }
        }
        // FrameTiming: the exposure, then the frame from the next PIXCLK; FV high for all
        // rows but the last and the last row's pixels; the rest of that row and the blanking.
        let rise_at = at + self.pix_to_sys(settings.exposure_pixclk + 1);
        let fall_at = rise_at
            + self.pix_to_sys(u64::from(lines.saturating_sub(1)) * row_len + u64::from(g.width));
        let blank = u64::from(g.vertical_blank_rows(settings.shutter_width_rows)) * row;
        let idle_at = rise_at + self.pix_to_sys(u64::from(lines) * row_len + blank);
        let stops_at = stops_after.map(|n| rise_at + self.pix_to_sys(u64::from(n) * row_len));
        self.timeline.frame = Some(SensorFrame {
            index: self.timeline.frames_started,
            settings,
            trigger_at: at,
            rise_at,
            fall_at,
            idle_at,
            lines,
            stops_at,
            faults,
            rise_done: false,
            fall_done: false,
            stop_done: false,
        });
        self.timeline.frames_started += 1;
    }

    /// Soft reset or RESET_BAR: no frame, nothing pending, PIXCLK runs.
    pub(super) fn sensor_reset(&mut self) {
        self.timeline.frame = None;
        self.timeline.pending = None;
        self.timeline.pixclk_stopped = false;
        self.capture_abandon();
    }

    /// The sensor's edges due now.
    pub(super) fn sensor_events(&mut self) {
        let now = self.now;
        let Some(f) = self.timeline.frame.as_mut() else {
            return;
        };
        if !f.rise_done && f.rise_at <= now {
            f.rise_done = true;
            let (settings, index) = (f.settings, f.index);
            let samples = self.sensor.render_frame(&settings, index);
            self.log.frames.push(samples.clone());
            self.capture_frame_start(samples);
        }
        let row_sys = self
            .timeline
            .frame
            .as_ref()
            .map(|f| {
                self.pix_to_sys(f.settings.geometry.row_pixclk().max(1))
                    .max(1)
            })
            .unwrap_or(1);
        let Some(f) = self.timeline.frame.as_mut() else {
            return;
        };
        let stopped = f.stops_at.filter(|&s| s < f.fall_at);
        if let Some(s) = stopped {
            if !f.stop_done && s + PIXCLK_WATCHDOG_CYCLES <= now {
                f.stop_done = true;
                let received_lines = ((s - f.rise_at) / row_sys) as u32;
                self.timeline.pixclk_stopped = true;
                self.capture_pixclk_stopped(received_lines);
            }
        } else if !f.fall_done && f.fall_at <= now {
            f.fall_done = true;
            let (lines, faults) = (f.lines, f.faults.clone());
            self.capture_frame_end(lines, &faults);
        }
        let Some(f) = self.timeline.frame.as_ref() else {
            return;
        };
        if now >= f.idle_at && f.fall_done {
            if let Some(settings) = self.timeline.pending.take() {
                let at = f.idle_at;
                self.sensor_start_frame(at, settings);
            }
        }
    }
}
