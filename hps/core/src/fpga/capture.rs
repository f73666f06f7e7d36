//! The capture path as the HPS programs it: the window the capture block counts against,
//! the Bayer grouping (`bayer.*`), the DMA ring (`dma.*`), the sensor's RESET_BAR pin, and
//! the sticky status bits read back and cleared per frame.

use super::frames::RingLayout;
use super::Fabric;
use skylux_bus::{BusError, RegisterAccess, RegisterBus};
use skylux_regmap::descriptor::PAYLOAD_OFFSET_BYTES;
use skylux_regmap::{bayer, capture, dma, i2c, Field};

/// Bayer grouping settings (ARCHITECTURE.md, "Bayer word format").
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct GroupingConfig {
    /// CFA phase: 0 GRBG (the MT9P031 default), 1 RGGB, 2 BGGR, 3 GBRG.
    pub phase: u32,
    pub black_level_dn: u32,
    pub valid_min_dn: u32,
    pub valid_max_dn: u32,
    /// Colour weights, unsigned Q2.14 (0x4000 = 1.0).
    pub weight_r_q2_14: u32,
    pub weight_g_q2_14: u32,
    pub weight_b_q2_14: u32,
    /// Store samples unchanged (two per word) for calibration instead of grouping them.
    pub raw: bool,
}

impl Default for GroupingConfig {
    /// The registers' reset values.
    fn default() -> Self {
        Self {
            phase: bayer::mode::PHASE.reset,
            black_level_dn: bayer::black::LEVEL.reset,
            valid_min_dn: bayer::valid::MIN.reset,
            valid_max_dn: bayer::valid::MAX.reset,
            weight_r_q2_14: bayer::weight_r::Q2_14.reset,
            weight_g_q2_14: bayer::weight_g::Q2_14.reset,
            weight_b_q2_14: bayer::weight_b::Q2_14.reset,
            raw: false,
        }
    }
}

/// Everything the capture path needs before a sequence.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct CaptureConfig {
    /// The sensor's output window in pixels (what it sends per line and lines per frame).
    pub width_px: u32,
    pub height_px: u32,
    pub grouping: GroupingConfig,
    pub ring: RingLayout,
    /// The DMA window: the fabric never writes outside `[ring.window_base, + window_size)`.
    pub window_size_bytes: u32,
    /// DMA watchdog: system clocks a burst may wait before the frame is abandoned.
    pub bus_timeout_cycles: u32,
}

impl CaptureConfig {
    /// Payload words of one frame.
    pub fn payload_words(&self) -> u64 {
        let (w, h) = (u64::from(self.width_px), u64::from(self.height_px));
        if self.grouping.raw {
            (w / 2) * h
        } else {
            (w / 2) * (h / 2)
        }
    }

    /// Bytes one slot needs: the descriptor block and the payload, rounded to the port's 8.
    pub fn slot_bytes_needed(&self) -> u64 {
        (u64::from(PAYLOAD_OFFSET_BYTES) + 4 * self.payload_words()).div_ceil(8) * 8
    }

    /// A ring of `slots` slots just large enough, at `window_base`.
    pub fn fitted(width_px: u32, height_px: u32, window_base: u64, slots: u8) -> Self {
        let mut c = Self {
            width_px,
            height_px,
            grouping: GroupingConfig::default(),
            ring: RingLayout {
                window_base,
                slot_stride_bytes: 0,
                slots,
            },
            window_size_bytes: 0,
            bus_timeout_cycles: dma::bus_timeout::CYCLES.reset,
        };
        let stride = c.slot_bytes_needed().min(u64::from(u32::MAX)) as u32;
        c.ring.slot_stride_bytes = stride;
        c.window_size_bytes = stride.saturating_mul(u32::from(slots));
        c
    }
}

/// Why the capture path was not configured (nothing is written then).
#[derive(Debug, thiserror::Error)]
pub enum CaptureConfigError {
    #[error("capture configuration: {field} = {value} is out of range ({allowed})")]
    OutOfRange {
        field: &'static str,
        value: u64,
        allowed: &'static str,
    },
    #[error("dma ring: {slots} slots of {stride} bytes do not fit the {window} byte window")]
    RingTooLarge { slots: u8, stride: u32, window: u32 },
    #[error("dma ring: a slot of {stride} bytes is smaller than one frame ({needed} bytes); frames would be TRUNCATED")]
    SlotTooSmall { stride: u32, needed: u64 },
    #[error("register bus: {0}")]
    Bus(#[from] BusError),
}

/// The capture block's and the DMA's sticky error bits, as read (and then cleared).
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct CaptureFaults {
    pub line_short: bool,
    pub line_long: bool,
    pub frame_short: bool,
    pub frame_long: bool,
    pub fifo_overflow: bool,
    pub pixclk_stopped: bool,
    pub dma_out_of_window: bool,
    pub dma_overflow: bool,
    pub dma_bus_timeout: bool,
}

impl CaptureFaults {
    pub fn any(&self) -> bool {
        *self != Self::default()
    }
}

fn fits(field: &'static str, f: &Field, value: u64) -> Result<u32, CaptureConfigError> {
    if value <= u64::from(u32::MAX) && f.fits(value as u32) {
        Ok(value as u32)
    } else {
        Err(CaptureConfigError::OutOfRange {
            field,
            value,
            allowed: "the register field's width",
        })
    }
}

impl<B: RegisterBus> Fabric<B> {
    /// Drives the sensor's RESET_BAR (`i2c.sensor_pins.RESET_N`): `true` releases the sensor.
    /// hardware-facts.md §1.7: the sensor needs 1-2 ms after release before the first I2C
    /// access; on the board the caller sleeps, in simulation the model answers at once.
    pub fn sensor_reset_release(&mut self, released: bool) -> Result<(), BusError> {
        self.bus().write_reg(
            &i2c::sensor_pins::REG,
            0,
            i2c::sensor_pins::RESET_N.word(released.into()),
        )
    }

    /// Programs window, grouping and ring, resets the ring to slot 0 and enables capture and
    /// DMA. Validates everything first: on an error nothing has been written.
    pub fn capture_configure(&mut self, c: &CaptureConfig) -> Result<(), CaptureConfigError> {
        if c.width_px < 2 || c.height_px < 2 {
            return Err(CaptureConfigError::OutOfRange {
                field: "width_px/height_px",
                value: u64::from(c.width_px.min(c.height_px)),
                allowed: "at least 2 x 2",
            });
        }
        let width = fits("width_px", &capture::window::WIDTH, c.width_px.into())?;
        let height = fits("height_px", &capture::window::HEIGHT, c.height_px.into())?;
        let g = &c.grouping;
        let phase = fits("phase", &bayer::mode::PHASE, g.phase.into())?;
        let black = fits(
            "black_level_dn",
            &bayer::black::LEVEL,
            g.black_level_dn.into(),
        )?;
        let vmin = fits("valid_min_dn", &bayer::valid::MIN, g.valid_min_dn.into())?;
        let vmax = fits("valid_max_dn", &bayer::valid::MAX, g.valid_max_dn.into())?;
        let wr = fits(
            "weight_r_q2_14",
            &bayer::weight_r::Q2_14,
            g.weight_r_q2_14.into(),
        )?;
        let wg = fits(
            "weight_g_q2_14",
            &bayer::weight_g::Q2_14,
            g.weight_g_q2_14.into(),
        )?;
        let wb = fits(
            "weight_b_q2_14",
            &bayer::weight_b::Q2_14,
            g.weight_b_q2_14.into(),
        )?;
        let base = fits(
            "ring.window_base",
            &dma::window_base::ADDR,
            c.ring.window_base,
        )?;
        if (base | c.ring.slot_stride_bytes) & 7 != 0 {
            return Err(CaptureConfigError::OutOfRange {
                field: "ring.window_base/slot_stride_bytes",
                value: u64::from(base | c.ring.slot_stride_bytes),
                allowed: "multiples of 8 (the port's width)",
            });
        }
        if c.ring.slots == 0 {
            return Err(CaptureConfigError::OutOfRange {
                field: "ring.slots",
                value: 0,
                allowed: "1 to 255",
            });
        }
        let needed = c.slot_bytes_needed();
        if u64::from(c.ring.slot_stride_bytes) < needed {
            return Err(CaptureConfigError::SlotTooSmall {
                stride: c.ring.slot_stride_bytes,
                needed,
            });
        }
        let ring_bytes = u64::from(c.ring.slot_stride_bytes) * u64::from(c.ring.slots);
        if ring_bytes > u64::from(c.window_size_bytes)
            || u64::from(base) + u64::from(c.window_size_bytes) > 1 << 32
        {
            return Err(CaptureConfigError::RingTooLarge {
                slots: c.ring.slots,
                stride: c.ring.slot_stride_bytes,
                window: c.window_size_bytes,
            });
        }
        let timeout = fits(
            "bus_timeout_cycles",
            &dma::bus_timeout::CYCLES,
            c.bus_timeout_cycles.into(),
        )?;

        let bus = self.bus();
        // Disabled while the settings change: the blocks read them at frame start.
        bus.write_reg(&dma::ctrl::REG, 0, 0)?;
        bus.write_reg(&capture::ctrl::REG, 0, 0)?;
        bus.write_reg(
            &capture::window::REG,
            0,
            capture::window::WIDTH.word(width) | capture::window::HEIGHT.word(height),
        )?;
        bus.write_reg(&bayer::mode::REG, 0, bayer::mode::PHASE.word(phase))?;
        bus.write_reg(&bayer::black::REG, 0, bayer::black::LEVEL.word(black))?;
        bus.write_reg(
            &bayer::valid::REG,
            0,
            bayer::valid::MIN.word(vmin) | bayer::valid::MAX.word(vmax),
        )?;
        bus.write_reg(&bayer::weight_r::REG, 0, bayer::weight_r::Q2_14.word(wr))?;
        bus.write_reg(&bayer::weight_g::REG, 0, bayer::weight_g::Q2_14.word(wg))?;
        bus.write_reg(&bayer::weight_b::REG, 0, bayer::weight_b::Q2_14.word(wb))?;
        bus.write_reg(&dma::window_base::REG, 0, base)?;
        bus.write_reg(&dma::window_size::REG, 0, c.window_size_bytes)?;
        bus.write_reg(&dma::slot_stride::REG, 0, c.ring.slot_stride_bytes)?;
        bus.write_reg(
            &dma::slots::REG,
            0,
            dma::slots::COUNT.word(c.ring.slots.into()),
        )?;
        bus.write_reg(&dma::bus_timeout::REG, 0, timeout)?;
        self.capture_take_faults()?;
        let bus = self.bus();
        bus.write_reg(&dma::ctrl::REG, 0, dma::ctrl::RESET.mask())?;
        bus.write_reg(&dma::ctrl::REG, 0, dma::ctrl::ENABLE.mask())?;
        bus.write_reg(
            &capture::ctrl::REG,
            0,
            capture::ctrl::ENABLE.mask() | capture::ctrl::RAW.word(g.raw.into()),
        )?;
        Ok(())
    }

    /// Reads the sticky fault bits of the capture block and the DMA, and clears them.
    pub fn capture_take_faults(&mut self) -> Result<CaptureFaults, BusError> {
        let bus = self.bus();
        let c = bus.read_reg(&capture::status::REG, 0)?;
        let d = bus.read_reg(&dma::status::REG, 0)?;
        let set = |f: &Field, v: u32| f.get(v) != 0;
        use capture::status as cs;
        use dma::status as ds;
        let faults = CaptureFaults {
            line_short: set(&cs::LINE_SHORT, c),
            line_long: set(&cs::LINE_LONG, c),
            frame_short: set(&cs::FRAME_SHORT, c),
            frame_long: set(&cs::FRAME_LONG, c),
            fifo_overflow: set(&cs::FIFO_OVERFLOW, c),
            pixclk_stopped: set(&cs::PIXCLK_STOPPED, c),
            dma_out_of_window: set(&ds::OUT_OF_WINDOW, d),
            dma_overflow: set(&ds::OVERFLOW, d),
            dma_bus_timeout: set(&ds::BUS_TIMEOUT, d),
        };
        let capture_sticky = [
            cs::LINE_SHORT,
            cs::LINE_LONG,
            cs::FRAME_SHORT,
            cs::FRAME_LONG,
            cs::FIFO_OVERFLOW,
            cs::PIXCLK_STOPPED,
        ]
        .iter()
        .fold(0, |m, f| m | f.mask());
        let dma_sticky = [
            ds::FRAME_DONE,
            ds::OUT_OF_WINDOW,
            ds::OVERFLOW,
            ds::BUS_TIMEOUT,
        ]
        .iter()
        .fold(0, |m, f| m | f.mask());
        bus.write_reg(&capture::status::REG, 0, c & capture_sticky)?;
        bus.write_reg(&dma::status::REG, 0, d & dma_sticky)?;
        Ok(faults)
    }

    /// Frames the DMA has finished since power-up (`dma.frames_written`).
    pub fn frames_written(&mut self) -> Result<u32, BusError> {
        self.bus().read_reg(&dma::frames_written::REG, 0)
    }
}
