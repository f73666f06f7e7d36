//! The MT9P031 as a whole: registers, two-wire target, snapshot trigger, FV/LV timing and
//! pixel values.

use super::frame::{BusState, FrameSettings, FrameTiming, Mode};
use super::i2c_target::{wired_and, I2cTarget, TargetDrive};
use super::pixels::PixelSource;
use super::registers::{addr, Registers, WriteEffect};
use super::timing::{exposure_pixclk, FrameGeometry, ShutterOverhead};
use skylux_hps::campaign::RawFrame;

/// The pixel bus during one PIXCLK period, with the sample on D[11:0] (0 outside LV).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct PixelBus {
    pub timing: BusState,
    pub data: u16,
}

/// One MT9P031.
pub struct Mt9p031 {
    pub registers: Registers,
    pub i2c: I2cTarget,
    pub shutter_overhead: ShutterOverhead,
    /// PIXCLK frequency (converts exposures to seconds for the pixel values).
    pub pixclk_hz: f64,
    pub timing: FrameTiming,
    pixels: Box<dyn PixelSource + Send>,
    frame: Option<RawFrame>,
    prev_trigger_pin: bool,
    /// Snapshot triggers accepted (pin or software).
    pub triggers: u64,
}

impl Mt9p031 {
    /// A sensor at power-up values, in snapshot mode if the registers say so (they do not by
    /// default: the HPS sets Read_Mode_1.Snapshot).
    pub fn new(pixels: Box<dyn PixelSource + Send>, pixclk_hz: f64) -> Self {
        let registers = Registers::default();
        let overhead = ShutterOverhead::default();
        let settings = Self::settings_of(&registers, overhead);
        Self {
            registers,
            i2c: I2cTarget::default(),
            shutter_overhead: overhead,
            pixclk_hz,
            timing: FrameTiming::new(Mode::Snapshot, settings),
            pixels,
            frame: None,
            prev_trigger_pin: false,
            triggers: 0,
        }
    }

    /// The frame settings the registers describe now.
    pub fn settings_of(r: &Registers, overhead: ShutterOverhead) -> FrameSettings {
        let geometry = FrameGeometry::from_registers(r);
        let sw = r.shutter_width_rows();
        FrameSettings {
            geometry,
            shutter_width_rows: sw,
            exposure_pixclk: exposure_pixclk(&geometry, sw, r.read(addr::SHUTTER_DELAY), overhead),
            gain: r.gain(),
            mirror_row: r.mirror_row(),
            mirror_column: r.mirror_column(),
        }
    }

    pub fn settings(&self) -> FrameSettings {
        Self::settings_of(&self.registers, self.shutter_overhead)
    }

    /// One sample of the two-wire bus at the levels the master leaves (true: the master pulls
    /// the line low). Returns the wired-AND levels of SCL and SDA after the sensor reacted.
    pub fn step_i2c(&mut self, master_scl_low: bool, master_sda_low: bool) -> (bool, bool) {
        let before = self.i2c.drive();
        let scl = wired_and(&[master_scl_low, before.scl_low]);
        let sda = wired_and(&[master_sda_low, before.sda_low]);
        self.i2c.step(scl, sda, &mut self.registers);
        for (_, effect) in self.i2c.take_writes() {
            if effect == WriteEffect::SoftwareTrigger {
                self.start_snapshot();
            }
        }
        let TargetDrive { scl_low, sda_low } = self.i2c.drive();
        (
            wired_and(&[master_scl_low, scl_low]),
            wired_and(&[master_sda_low, sda_low]),
        )
    }

    fn start_snapshot(&mut self) {
        if !self.registers.snapshot_mode() {
            return;
        }
        let s = self.settings();
        if self.timing.trigger(s) {
            self.triggers += 1;
        }
    }

    /// One PIXCLK period: the TRIGGER pin's level (a rising edge starts a snapshot exposure),
    /// then FV, LV and the pixel.
    pub fn tick_pixclk(&mut self, trigger_pin: bool) -> PixelBus {
        if trigger_pin && !self.prev_trigger_pin {
            self.start_snapshot();
        }
        self.prev_trigger_pin = trigger_pin;
        let timing = self.timing.tick();
        if timing.frame_start {
            let s = *self.timing.settings();
            self.frame = Some(self.pixels.frame(&s, self.pixclk_hz, timing.frames - 1));
        }
        let data = match (&self.frame, timing.frame_valid && timing.line_valid) {
            (Some(f), true) => f
                .samples_dn
                .get(timing.y as usize * f.width + timing.x as usize)
                .copied()
                .unwrap_or(0),
            _ => 0,
        };
        PixelBus { timing, data }
    }

    /// Renders the frame a snapshot with `settings` reads out (the sensor's frame number
    /// `frame_index`, counting from 0 as [`Self::tick_pixclk`] does), keeps it as
    /// [`Self::frame_samples`] and returns it: for transaction-level models of the fabric,
    /// which do not tick PIXCLK (`crate::fabric_model`).
    pub fn render_frame(&mut self, settings: &FrameSettings, frame_index: u64) -> RawFrame {
        let frame = self.pixels.frame(settings, self.pixclk_hz, frame_index);
        self.frame = Some(frame.clone());
        frame
    }

    /// The samples of the frame on the bus (or the last one).
    pub fn frame_samples(&self) -> Option<&RawFrame> {
        self.frame.as_ref()
    }
}
