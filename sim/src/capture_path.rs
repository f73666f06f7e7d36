//! The capture path on the bench: the pixel bus drives the rust-hdl `CapturePath` in its
//! PIXCLK domain while the Avalon-MM memory model ([`AvalonMemory`], the f2sdram port) answers
//! its master in the system clock domain, the two clocks interleaved on a picosecond time line.
//!
//! Inputs change in the same settle as their own clock's falling edge, and a falling edge
//! shares the settle of the other clock's next rising edge when that comes first (flops
//! sample only on rising edges, and no domain's inputs reach the other domain's flops
//! combinationally). That roughly halves the settles without the hold race that
//! `skylux_rtl::drive` guards against: no rising edge ever shares a settle with an input
//! change of its own domain or with another rising edge.

use crate::bus::avalon_memory::{
    AddressUnit, AvalonMemory, AvalonMemoryConfig, HostCommand, WaitPolicy,
};
use crate::pixel_bus::{Blanking, Fault, PixelBus, Step};
use rust_hdl::prelude::*;
use skylux_rtl::bayer::golden::BayerConfig;
use skylux_rtl::capture::CapturePath;
use skylux_rtl::drive::{DriveError, Driver};

/// The registers the path reads, and the clocks.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct PathConfig {
    /// `capture.window`.
    pub width: u16,
    pub height: u16,
    /// `bayer.*` and `capture.ctrl.RAW`.
    pub bayer: BayerConfig,
    /// `dma.*`.
    pub window_base: u32,
    pub window_size_bytes: u32,
    pub slot_stride_bytes: u32,
    pub slots: u8,
    pub bus_timeout_cycles: u32,
    pub pixclk_hz: f64,
    pub sys_clock_hz: f64,
}

impl PathConfig {
    /// A window of `width x height` with `slots` slots just large enough for a frame.
    pub fn fitted(width: u16, height: u16, slots: u8) -> Self {
        let words = u32::from(width / 2) * u32::from(height);
        let stride = (skylux_regmap::descriptor::PAYLOAD_OFFSET_BYTES + 4 * words + 7) & !7;
        PathConfig {
            width,
            height,
            bayer: BayerConfig::default(),
            window_base: 0x3000_0000,
            window_size_bytes: stride * u32::from(slots),
            slot_stride_bytes: stride,
            slots,
            bus_timeout_cycles: 1_000_000,
            // MT9P031 maximum (hardware-facts.md §1.2) and the fabric's system clock.
            pixclk_hz: 96e6,
            sys_clock_hz: f64::from(skylux_regmap::SYS_CLOCK_HZ),
        }
    }
}

/// W1C status bits as the register file would hold them, and event counts.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct StatusSeen {
    pub line_short: bool,
    pub line_long: bool,
    pub frame_short: bool,
    pub frame_long: bool,
    pub fifo_overflow: bool,
    pub pixclk_stopped: bool,
    pub out_of_window: bool,
    pub dma_overflow: bool,
    pub bus_timeout: bool,
    pub frames_done: u64,
    pub capture_error_irqs: u64,
    pub dma_error_irqs: u64,
}

/// Counters of a run.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RunCounters {
    pub pixclk_cycles: u64,
    pub sys_cycles: u64,
    /// Active pixels the sensor sent.
    pub pixels_sent: u64,
    /// Deepest FIFO fill reported per frame (`capture.fifo_high_water`).
    pub fifo_high_water: u64,
}

/// The harness.
pub struct CapturePathSim {
    pub driver: Driver<CapturePath>,
    pub bus: PixelBus,
    /// The f2sdram port: byte addresses, writes allowed only in the DMA window, full byte
    /// enables required. The HPS reads it through `skylux_bus::DmaMemory`.
    pub memory: AvalonMemory,
    pub config: PathConfig,
    pub status: StatusSeen,
    pub counters: RunCounters,
    pix_half_ps: u64,
    sys_half_ps: u64,
    next_pix_ps: u64,
    next_sys_ps: u64,
    pix_high: bool,
    sys_high: bool,
    pix_skip: u64,
}

fn pixclk(d: &mut CapturePath) -> &mut Signal<In, Clock> {
    &mut d.pixclk
}
fn sysclk(d: &mut CapturePath) -> &mut Signal<In, Clock> {
    &mut d.clock
}

impl CapturePathSim {
    /// A path configured by `config`, enabled, over a memory that covers the DMA window plus
    /// `guard_bytes` on each side (so a stray write would land in memory and be caught).
    pub fn new(config: PathConfig, policy: WaitPolicy, seed: u64) -> Self {
        let guard_bytes = 4096u64;
        let base = u64::from(config.window_base).saturating_sub(guard_bytes);
        let len = (u64::from(config.window_base) - base)
            + u64::from(config.window_size_bytes)
            + guard_bytes;
        let memory = AvalonMemory::new(
            AvalonMemoryConfig {
                width_bytes: 8,
                address_unit: AddressUnit::Bytes,
                base,
                size_bytes: len as usize,
                write_window: Some((
                    u64::from(config.window_base),
                    u64::from(config.window_size_bytes),
                )),
                require_full_byteenable: true,
                seed,
                ..Default::default()
            }
            .with_wait_policy(policy),
        );
        let mut sim = CapturePathSim {
            driver: Driver::new(CapturePath::default()),
            bus: PixelBus::new(),
            memory,
            config,
            status: StatusSeen::default(),
            counters: RunCounters::default(),
            pix_half_ps: (5e11 / config.pixclk_hz).round().max(1.0) as u64,
            sys_half_ps: (5e11 / config.sys_clock_hz).round().max(1.0) as u64,
            next_pix_ps: 0,
            next_sys_ps: 0,
            pix_high: false,
            sys_high: false,
            pix_skip: 0,
        };
        sim.apply_config();
        sim
    }

    /// Writes `config` to the ports (the register file's outputs) and enables both blocks.
    pub fn apply_config(&mut self) {
        let c = self.config;
        let d = &mut self.driver.dut;
        d.capture_ctrl_enable.next = true;
        d.capture_ctrl_raw.next = c.bayer.raw;
        d.capture_window_width.next = u64::from(c.width & 0xFFF).into();
        d.capture_window_height.next = u64::from(c.height & 0xFFF).into();
        d.bayer_mode_phase.next = (c.bayer.phase as u64).into();
        d.bayer_black_level.next = u64::from(c.bayer.black & 0xFFF).into();
        d.bayer_valid_min.next = u64::from(c.bayer.valid_min & 0xFFF).into();
        d.bayer_valid_max.next = u64::from(c.bayer.valid_max & 0xFFF).into();
        d.bayer_weight_r_q2_14.next = u64::from(c.bayer.weight_r).into();
        d.bayer_weight_g_q2_14.next = u64::from(c.bayer.weight_g).into();
        d.bayer_weight_b_q2_14.next = u64::from(c.bayer.weight_b).into();
        d.dma_ctrl_enable.next = true;
        d.dma_ctrl_reset.next = false;
        d.dma_window_base_addr.next = u64::from(c.window_base).into();
        d.dma_window_size_bytes.next = u64::from(c.window_size_bytes).into();
        d.dma_slot_stride_bytes.next = u64::from(c.slot_stride_bytes).into();
        d.dma_slots_count.next = u64::from(c.slots).into();
        d.dma_bus_timeout_cycles.next = u64::from(c.bus_timeout_cycles & 0xFF_FFFF).into();
    }

    /// Sets the frame tags the exposure sequencer would drive (the timestamp follows the
    /// system clock cycle count by itself).
    pub fn set_tags(&mut self, exposure_index: u8, frame_number: u32) {
        let d = &mut self.driver.dut;
        d.tag_exposure_index.next = u64::from(exposure_index & 7).into();
        d.tag_frame_number.next = u64::from(frame_number).into();
    }

    /// Queues a frame of `width x height` samples with `faults`.
    pub fn push_frame(
        &mut self,
        samples: &[u16],
        width: usize,
        height: usize,
        blanking: &Blanking,
        faults: &[Fault],
    ) {
        self.bus
            .push_frame(samples, width, height, blanking, faults);
    }

    /// Runs until the pixel bus has sent everything and the DMA has been idle (not busy, not
    /// writing) for `quiet_sys_cycles`, or `max_sys_cycles` pass. Returns whether it settled.
    pub fn run_until_idle(
        &mut self,
        quiet_sys_cycles: u64,
        max_sys_cycles: u64,
    ) -> Result<bool, DriveError> {
        let start = self.counters.sys_cycles;
        let mut quiet = 0;
        while self.counters.sys_cycles - start < max_sys_cycles {
            let was = self.counters.sys_cycles;
            self.step()?;
            if self.counters.sys_cycles != was {
                let d = &self.driver.dut;
                if self.bus.is_done() && !d.dma_status_busy.val() && !d.avm_write.val() {
                    quiet += 1;
                    if quiet >= quiet_sys_cycles {
                        return Ok(true);
                    }
                } else {
                    quiet = 0;
                }
            }
        }
        Ok(false)
    }

    /// Runs `sys_cycles` system clock cycles.
    pub fn run_sys_cycles(&mut self, sys_cycles: u64) -> Result<(), DriveError> {
        let end = self.counters.sys_cycles + sys_cycles;
        while self.counters.sys_cycles < end {
            self.step()?;
        }
        Ok(())
    }

    /// One clock event: the earlier of the two clocks' next half-period edges.
    fn step(&mut self) -> Result<(), DriveError> {
        if self.next_pix_ps <= self.next_sys_ps {
            self.next_pix_ps += self.pix_half_ps;
            self.pixclk_event()
        } else {
            self.next_sys_ps += self.sys_half_ps;
            self.sysclk_event()
        }
    }

    fn pixclk_event(&mut self) -> Result<(), DriveError> {
        if self.pix_high {
            // Falling edge: the pins for the next period change with it.
            let mut step = self.bus.next_step();
            while step == Step::Stopped {
                self.pix_skip += 1;
                step = self.bus.next_step();
            }
            if let Step::Tick(p) = step {
                let d = &mut self.driver.dut;
                d.sensor_frame_valid.next = p.frame_valid;
                d.sensor_line_valid.next = p.line_valid;
                d.sensor_data.next = u64::from(p.data & 0xFFF).into();
            }
            self.pix_high = false;
            self.fall(false)
        } else if self.pix_skip > 0 {
            // PIXCLK stopped: this period has no edges (two half periods).
            self.pix_skip -= 1;
            self.next_pix_ps += self.pix_half_ps;
            Ok(())
        } else {
            self.pix_high = true;
            self.counters.pixclk_cycles += 1;
            self.driver.set_clock(pixclk, true)
        }
    }

    fn sysclk_event(&mut self) -> Result<(), DriveError> {
        if self.sys_high {
            // The agent's outputs for the cycle that ends at the next rising edge.
            let wait = self.memory.begin_cycle().waitrequest;
            let d = &mut self.driver.dut;
            d.avm_waitrequest.next = wait;
            d.tag_timestamp.next = self.counters.sys_cycles.into();
            self.sys_high = false;
            self.fall(true)
        } else {
            self.sample_before_edge();
            self.sys_high = true;
            self.counters.sys_cycles += 1;
            self.driver.set_clock(sysclk, true)
        }
    }

    /// A falling edge, with its domain's new inputs. When the next event is the other
    /// clock's rising edge, the fall joins that edge's settle instead of settling alone: a
    /// falling edge moves no flip-flop, and neither domain's inputs reach the other domain's
    /// flip-flops without a register of their own clock in between.
    fn fall(&mut self, sys: bool) -> Result<(), DriveError> {
        let (next_own, next_other, other_rises) = if sys {
            (
                self.next_sys_ps,
                self.next_pix_ps,
                !self.pix_high && self.pix_skip == 0,
            )
        } else {
            (self.next_pix_ps, self.next_sys_ps, !self.sys_high)
        };
        let d = &mut self.driver.dut;
        if sys {
            d.clock.next = Clock::from(false);
        } else {
            d.pixclk.next = Clock::from(false);
        }
        if next_other < next_own && other_rises {
            Ok(())
        } else {
            self.driver.settle()
        }
    }

    /// What the register file and the f2sdram port take at this rising edge. (The first
    /// edge comes before any falling edge: the port's outputs are still their reset values,
    /// waitrequest low, as the DUT sees them.)
    fn sample_before_edge(&mut self) {
        let d = &self.driver.dut;
        let write = d.avm_write.val();
        let host = if write {
            HostCommand {
                address: d.avm_address.val().to_u64(),
                read: false,
                write,
                burstcount: d.avm_burstcount.val().to_u64() as u32,
                writedata: u128::from(d.avm_writedata.val().to_u64()),
                byteenable: d.avm_byteenable.val().to_u64() as u32,
            }
        } else {
            HostCommand::default()
        };
        let s = &mut self.status;
        s.line_short |= d.capture_status_line_short_set.val();
        s.line_long |= d.capture_status_line_long_set.val();
        s.frame_short |= d.capture_status_frame_short_set.val();
        s.frame_long |= d.capture_status_frame_long_set.val();
        s.fifo_overflow |= d.capture_status_fifo_overflow_set.val();
        s.pixclk_stopped |= d.capture_status_pixclk_stopped_set.val();
        s.out_of_window |= d.dma_status_out_of_window_set.val();
        s.dma_overflow |= d.dma_status_overflow_set.val();
        s.bus_timeout |= d.dma_status_bus_timeout_set.val();
        s.frames_done += u64::from(d.irq_frame_done.val());
        s.capture_error_irqs += u64::from(d.irq_capture_error.val());
        s.dma_error_irqs += u64::from(d.irq_dma_error.val());
        let hw = d.capture_fifo_high_water_words.val().to_u64();
        self.counters.fifo_high_water = self.counters.fifo_high_water.max(hw);
        self.counters.pixels_sent = self.bus.pixels_sent;
        self.memory.end_cycle(&host);
    }
}
