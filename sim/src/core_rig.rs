//! The whole fabric core (`skylux_rtl::SkyluxCore`) on its board: an MT9P031 model on the
//! camera pins, one [`AvalonMemory`] per f2sdram port (port 0 for the frame DMA, port 1 for
//! the ray-box unit), and the HPS's register accesses on the lightweight bridge. The HPS
//! drivers reach it through the bus traits ([`SimCoreRegisters`], [`SimCoreMemory`]) exactly
//! as they reach the board through `MappedWindow`.
//!
//! Two clocks on one picosecond time line: the system clock (`SYS_CLOCK_HZ`) and the sensor's
//! PIXCLK. Each domain's inputs change in a settle of their own before that domain's rising
//! edge (system side: the memories' answers and the register access) or with its falling edge
//! (the pixel bus), never with a rising edge (rtl/src/drive.rs).

use crate::bus::avalon_memory::{
    Access, AddressUnit, AgentOutputs, AvalonMemory, AvalonMemoryConfig, HostCommand, WaitPolicy,
};
use crate::mt9p031::Mt9p031;
use rust_hdl::prelude::*;
use skylux_bus::{check_access, BusError, DmaMemory, RegisterBus};
use skylux_hps::campaign::RawFrame;
use skylux_regmap::{LW_BRIDGE_SPAN_BYTES, READ_LATENCY_CYCLES, SYS_CLOCK_HZ};
use skylux_rtl::drive::{DriveError, Driver};
use skylux_rtl::SkyluxCore;
use std::sync::{Arc, Mutex, MutexGuard};

/// Which f2sdram port a memory answers.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Port {
    /// Port 0: the frame DMA (write only).
    Frames,
    /// Port 1: the ray-box unit.
    RayBox,
}

/// The rig's layout and the bus behaviour.
#[derive(Clone, Debug)]
pub struct CoreRigConfig {
    /// SDRAM behind port 0: must cover the DMA window the HPS programs.
    pub frames: AvalonMemoryConfig,
    /// SDRAM behind port 1: must cover the ray-box window.
    pub raybox: AvalonMemoryConfig,
}

impl CoreRigConfig {
    /// Frame memory of `frame_bytes` at 0x3000_0000 and ray-box memory of `raybox_bytes` at
    /// 0x3800_0000, both with `waitrequest_probability` of random back-pressure.
    pub fn new(frame_bytes: usize, raybox_bytes: usize, waitrequest_probability: f64) -> Self {
        let port = |base: u64, size_bytes: usize, seed: u64| AvalonMemoryConfig {
            width_bytes: 8,
            address_unit: AddressUnit::Words,
            base,
            size_bytes,
            wait: WaitPolicy::random(waitrequest_probability),
            seed,
            ..Default::default()
        };
        Self {
            frames: port(0x3000_0000, frame_bytes, 11),
            raybox: port(0x3800_0000, raybox_bytes, 12),
        }
    }
}

/// What the rig saw on the pins.
#[derive(Clone, Debug, Default)]
pub struct CoreLog {
    /// The samples of every frame the sensor put on the bus, in order.
    pub frames: Vec<RawFrame>,
    pub triggers: u64,
    /// Shield position in steps (0 = closed), from the step pulses while enabled.
    pub shield_position: i64,
    /// Longest stretch of system clocks with the shield away from closed.
    pub shield_open_cycles_max: u64,
    /// RESET_BAR (the core's `reset_n` pin) has been high at least once.
    pub reset_released: bool,
}

/// The simulation state. Use it through [`SharedCore`] and the two bus views, or directly.
pub struct CoreSystem {
    pub driver: Driver<SkyluxCore>,
    pub sensor: Mt9p031,
    pub frames: AvalonMemory,
    pub raybox: AvalonMemory,
    pub log: CoreLog,
    /// External trigger pin level.
    pub ext_trigger: bool,
    sys_cycles: u64,
    pixclk_cycles: u64,
    sys_half_ps: u64,
    pix_half_ps: u64,
    next_sys_ps: u64,
    next_pix_ps: u64,
    sys_high: bool,
    pix_high: bool,
    prev_step: bool,
    prev_trigger: bool,
    open_run: u64,
    scl: bool,
    sda: bool,
}

fn sys_clock(d: &mut SkyluxCore) -> &mut Signal<In, Clock> {
    &mut d.clk
}
fn pix_clock(d: &mut SkyluxCore) -> &mut Signal<In, Clock> {
    &mut d.pixclk
}

impl CoreSystem {
    pub fn new(sensor: Mt9p031, config: CoreRigConfig) -> Self {
        let mut driver = Driver::new(SkyluxCore::default());
        let d = &mut driver.dut;
        d.avs_read.next = false;
        d.avs_write.next = false;
        d.avs_byteenable.next = 0xF.into();
        d.sdata_in.next = true;
        let pix_half_ps = (5e11 / sensor.pixclk_hz).round().max(1.0) as u64;
        Self {
            driver,
            sensor,
            frames: AvalonMemory::new(config.frames),
            raybox: AvalonMemory::new(config.raybox),
            log: CoreLog::default(),
            ext_trigger: false,
            sys_cycles: 0,
            pixclk_cycles: 0,
            sys_half_ps: (5e11 / f64::from(SYS_CLOCK_HZ)).round() as u64,
            pix_half_ps,
            next_sys_ps: 0,
            next_pix_ps: pix_half_ps / 2,
            sys_high: false,
            pix_high: false,
            prev_step: false,
            prev_trigger: false,
            open_run: 0,
            scl: true,
            sda: true,
        }
    }

    /// System-clock cycles run so far.
    pub fn sys_cycles(&self) -> u64 {
        self.sys_cycles
    }

    /// PIXCLK cycles run so far.
    pub fn pixclk_cycles(&self) -> u64 {
        self.pixclk_cycles
    }

    /// Every write the frame DMA made (for window checks).
    pub fn frame_writes(&self) -> &[Access] {
        &self.frames.accesses
    }

    /// Runs until `n` more system-clock rising edges have happened.
    pub fn run(&mut self, n: u64) -> Result<(), DriveError> {
        let end = self.sys_cycles + n;
        while self.sys_cycles < end {
            self.event()?;
        }
        Ok(())
    }

    fn event(&mut self) -> Result<(), DriveError> {
        if self.next_pix_ps < self.next_sys_ps {
            self.next_pix_ps += self.pix_half_ps;
            if self.pix_high {
                self.pix_fall()
            } else {
                self.pix_high = true;
                self.pixclk_cycles += 1;
                self.driver.set_clock(pix_clock, true)
            }
        } else {
            self.next_sys_ps += self.sys_half_ps;
            if self.sys_high {
                self.sys_high = false;
                self.driver.set_clock(sys_clock, false)
            } else {
                self.sys_rise()
            }
        }
    }

    /// PIXCLK falls: the sensor puts the next pixel on the bus.
    fn pix_fall(&mut self) -> Result<(), DriveError> {
        self.pix_high = false;
        let trigger = self.driver.dut.trigger.val();
        let bus = self.sensor.tick_pixclk(trigger);
        if bus.timing.frame_start {
            if let Some(f) = self.sensor.frame_samples() {
                self.log.frames.push(f.clone());
            }
        }
        let d = &mut self.driver.dut;
        d.fval.next = bus.timing.frame_valid;
        d.lval.next = bus.timing.frame_valid && bus.timing.line_valid;
        d.d.next = u64::from(bus.data & 0xFFF).into();
        d.pixclk.next = Clock::from(false);
        self.driver.settle()
    }

    /// The system clock rises: memories, I2C lines and pins first, then the edge.
    fn sys_rise(&mut self) -> Result<(), DriveError> {
        let frames = self.frames.begin_cycle();
        let raybox = self.raybox.begin_cycle();
        let d = &mut self.driver.dut;
        d.dma_waitrequest.next = frames.waitrequest;
        let AgentOutputs {
            waitrequest,
            readdatavalid,
            readdata,
        } = raybox;
        d.rbx_waitrequest.next = waitrequest;
        d.rbx_readdatavalid.next = readdatavalid;
        d.rbx_readdata.next = (readdata as u64).to_bits();
        d.sdata_in.next = self.sda;
        d.ext_trigger.next = self.ext_trigger;
        self.driver.settle()?;

        let d = &self.driver.dut;
        let frame_cmd = HostCommand {
            address: d.dma_address.val().to_u64(),
            read: false,
            write: d.dma_write.val(),
            burstcount: d.dma_burstcount.val().to_u64() as u32,
            writedata: d.dma_writedata.val().to_u64() as u128,
            byteenable: d.dma_byteenable.val().to_u64() as u32,
        };
        let raybox_cmd = HostCommand {
            address: d.rbx_address.val().to_u64(),
            read: d.rbx_read.val(),
            write: d.rbx_write.val(),
            burstcount: d.rbx_burstcount.val().to_u64() as u32,
            writedata: d.rbx_writedata.val().to_u64() as u128,
            byteenable: d.rbx_byteenable.val().to_u64() as u32,
        };
        let (sclk, sda_low, reset_n) = (d.sclk.val(), d.sdata_oe.val(), d.reset_n.val());
        let (step, dir, enable_n, trigger) = (
            d.shield_step.val(),
            d.shield_dir.val(),
            d.shield_enable_n.val(),
            d.trigger.val(),
        );
        self.frames.end_cycle(&frame_cmd);
        self.raybox.end_cycle(&raybox_cmd);

        // A sensor held in reset does not answer: the lines are what the master drives.
        if reset_n {
            self.log.reset_released = true;
            let (scl, sda) = self.sensor.step_i2c(!sclk, sda_low);
            self.scl = scl;
            self.sda = sda;
        } else {
            self.scl = sclk;
            self.sda = !sda_low;
        }
        if trigger && !self.prev_trigger {
            self.log.triggers += 1;
        }
        self.prev_trigger = trigger;
        if step && !self.prev_step && !enable_n {
            self.log.shield_position += if dir { 1 } else { -1 };
        }
        self.prev_step = step;
        if self.log.shield_position != 0 {
            self.open_run += 1;
            self.log.shield_open_cycles_max = self.log.shield_open_cycles_max.max(self.open_run);
        } else {
            self.open_run = 0;
        }

        self.sys_high = true;
        self.sys_cycles += 1;
        self.driver.set_clock(sys_clock, true)
    }

    fn write_word(&mut self, word_address: u32, data: u32) -> Result<(), DriveError> {
        let d = &mut self.driver.dut;
        d.avs_address.next = u64::from(word_address).into();
        d.avs_writedata.next = u64::from(data).into();
        d.avs_write.next = true;
        self.run(1)?;
        self.driver.dut.avs_write.next = false;
        Ok(())
    }

    fn read_word(&mut self, word_address: u32) -> Result<u32, DriveError> {
        let d = &mut self.driver.dut;
        d.avs_address.next = u64::from(word_address).into();
        d.avs_read.next = true;
        self.run(1)?;
        self.driver.dut.avs_read.next = false;
        self.run(READ_LATENCY_CYCLES as u64 - 1)?;
        // The data is valid after the latency's last edge; the next event is at most the
        // falling edge, which moves no flip-flop.
        let data = self.driver.dut.avs_readdata.val().to_u64() as u32;
        self.run(1)?;
        Ok(data)
    }

    fn memory(&mut self, port: Port) -> &mut AvalonMemory {
        match port {
            Port::Frames => &mut self.frames,
            Port::RayBox => &mut self.raybox,
        }
    }
}

impl RegisterBus for CoreSystem {
    fn read32(&mut self, offset: u32) -> Result<u32, BusError> {
        check_access(offset as u64, 4, LW_BRIDGE_SPAN_BYTES as u64, 4)?;
        self.read_word(offset / 4)
            .map_err(|e| BusError::Simulation(e.to_string()))
    }

    fn write32(&mut self, offset: u32, value: u32) -> Result<(), BusError> {
        check_access(offset as u64, 4, LW_BRIDGE_SPAN_BYTES as u64, 4)?;
        self.write_word(offset / 4, value)
            .map_err(|e| BusError::Simulation(e.to_string()))
    }
}

/// The rig, shared between the register view and the memory views.
pub type SharedCore = Arc<Mutex<CoreSystem>>;

fn lock(shared: &SharedCore) -> Result<MutexGuard<'_, CoreSystem>, BusError> {
    shared
        .lock()
        .map_err(|_| BusError::Simulation("the core simulation panicked earlier".into()))
}

/// The lightweight-bridge register window of the simulated core.
#[derive(Clone)]
pub struct SimCoreRegisters(pub SharedCore);

impl RegisterBus for SimCoreRegisters {
    fn read32(&mut self, offset: u32) -> Result<u32, BusError> {
        lock(&self.0)?.read32(offset)
    }
    fn write32(&mut self, offset: u32, value: u32) -> Result<(), BusError> {
        lock(&self.0)?.write32(offset, value)
    }
}

/// The SDRAM behind one f2sdram port, as the HPS's DMA buffer sees it.
#[derive(Clone)]
pub struct SimCoreMemory {
    pub shared: SharedCore,
    pub port: Port,
}

impl DmaMemory for SimCoreMemory {
    fn phys_base(&self) -> u64 {
        self.shared
            .lock()
            .map(|mut s| s.memory(self.port).phys_base())
            .unwrap_or(0)
    }
    fn len_bytes(&self) -> u64 {
        self.shared
            .lock()
            .map(|mut s| s.memory(self.port).len_bytes())
            .unwrap_or(0)
    }
    fn read_bytes(&mut self, offset: u64, buf: &mut [u8]) -> Result<(), BusError> {
        lock(&self.shared)?
            .memory(self.port)
            .read_bytes(offset, buf)
    }
    fn write_bytes(&mut self, offset: u64, data: &[u8]) -> Result<(), BusError> {
        lock(&self.shared)?
            .memory(self.port)
            .write_bytes(offset, data)
    }
}

/// The rig and its three bus views.
pub fn sim_core(
    sensor: Mt9p031,
    config: CoreRigConfig,
) -> (SharedCore, SimCoreRegisters, SimCoreMemory, SimCoreMemory) {
    let shared = Arc::new(Mutex::new(CoreSystem::new(sensor, config)));
    (
        shared.clone(),
        SimCoreRegisters(shared.clone()),
        SimCoreMemory {
            shared: shared.clone(),
            port: Port::Frames,
        },
        SimCoreMemory {
            shared,
            port: Port::RayBox,
        },
    )
}
