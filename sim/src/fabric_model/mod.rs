//! A behavioural (transaction-level) model of the whole Skylux fabric behind the same bus
//! traits as the cycle-accurate core (`crate::core_rig`): `RegisterBus` on the lightweight
//! bridge and `DmaMemory` for the f2sdram frame buffer. It exists because the rust-hdl core
//! runs ~10^3 clocks a second, so the daemon's real fabric path (`skyluxd`'s `FabricSource`)
//! cannot be exercised at a realistic window or cycled after every fault; this model runs a
//! full-frame HDR capture in well under a second.
//!
//! It is written from the hardware's contract, not from the driver: the register semantics of
//! `skylux_regmap::MAP` (through [`RegisterFileModel`]), the block behaviour documented in the
//! RTL (`skylux_rtl::{i2c, sequencer, capture, dma}`), the MT9P031 model of `crate::mt9p031`
//! (registers, frame geometry, exposure formula, pixel values) and hardware-facts.md.
//!
//! **Time.** The model keeps one system-clock time line (`SYS_CLOCK_HZ`). Every register
//! access costs a fixed number of clocks ([`FabricModelConfig::read_cycles`],
//! `write_cycles`): the core rig's costs by default (a read is `READ_LATENCY_CYCLES + 1`
//! clocks, a write 1), so that polling loops bound a wait exactly as on the core. Between
//! accesses the blocks jump from event to event (I2C transaction end, shield step phases,
//! trigger, FRAME_VALID edges, the DMA's descriptor write) instead of ticking clocks.
//!
//! Blocks, one file each: [`i2c`] (the register-transaction master), [`sequencer`] (exposure
//! sequencer and lens shield with its open-time interlock), [`sensor`] (the MT9P031's
//! snapshot time line), [`capture`] (window checks, raw/grouped words, the clock-domain
//! FIFO), [`dma`] (ring slots, payload, descriptor and checksum; the `hdr.*` map frames),
//! [`sun`] (the `sun.*` accumulators over the armed frame's grouped words).
//! Faults are injected at their source ([`HardwareFault`]): the drivers see only what the
//! hardware would show.

pub mod capture;
pub mod dma;
pub mod i2c;
pub mod sensor;
pub mod sequencer;
pub mod sun;

use crate::bus::RegisterFileModel;
use crate::mt9p031::Mt9p031;
use skylux_bus::{check_access, BusError, DmaMemory, RegisterBus};
use skylux_regmap::{sys, LW_BRIDGE_SPAN_BYTES, READ_LATENCY_CYCLES, SYS_CLOCK_HZ};
use std::sync::{Arc, Mutex, MutexGuard};

/// How the model is set up.
#[derive(Clone, Debug)]
pub struct FabricModelConfig {
    /// Physical base of the frame buffer the HPS hands to the DMA (as the core rig's port 0).
    pub memory_base: u64,
    /// Its size, bytes.
    pub memory_bytes: usize,
    /// System clocks one register read costs (the core rig: `READ_LATENCY_CYCLES + 1`).
    pub read_cycles: u64,
    /// System clocks one register write costs (the core rig: 1).
    pub write_cycles: u64,
}

impl FabricModelConfig {
    /// A frame buffer of `memory_bytes` at 0x3000_0000 (the core rig's port 0) and the core
    /// rig's access costs.
    pub fn new(memory_bytes: usize) -> Self {
        Self {
            memory_base: 0x3000_0000,
            memory_bytes,
            read_cycles: READ_LATENCY_CYCLES as u64 + 1,
            write_cycles: 1,
        }
    }
}

/// A hardware fault, produced where it happens on the board.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum HardwareFault {
    /// No device answers at the sensor's address (unplugged or unpowered): every address byte
    /// is not acknowledged (`crate::mt9p031::I2cFault::Absent`).
    SensorAbsent,
    /// A device holds SDA low: the master sees it at START (`I2cFault::SdaStuckLow`).
    SdaStuckLow,
    /// A device holds SCL low: every transaction runs into the watchdog
    /// (`I2cFault::SclStuckLow`).
    SclStuckLow,
    /// The sensor does not acknowledge the register-address byte of this register (a
    /// marginal bus that fails one transaction pattern).
    NackRegister(u8),
    /// PIXCLK stops after this many lines of the next frame (FRAME_VALID stays high); it runs
    /// again after RESET_BAR or a soft reset.
    PixclkStops { after_lines: u32 },
    /// One line of the next frame carries `delta_px` pixels more (or fewer) than the window.
    LineLength { line: u32, delta_px: i32 },
    /// The next frame carries `delta_lines` lines more (or fewer) than the window.
    FrameLength { delta_lines: i32 },
    /// During the next frame the f2sdram port holds waitrequest for `cycles` system clocks:
    /// the FIFOs fill, words are dropped (`FIFO_OVERFLOW`) beyond their capacity, and a stall
    /// beyond `dma.bus_timeout` is `BUS_TIMEOUT`.
    PortStall { cycles: u64 },
    /// One payload word of the next frame is corrupted on its way into SDRAM (after the
    /// checksum was taken): `xor` flips its bits in memory.
    CorruptWord { word: u32, xor: u32 },
    /// The next two frames are written into each other's slots (the ring pointer glitches):
    /// frames delivered out of order.
    SwapSlots,
    /// The sun accumulators' result registers read all ones until [`FabricModel::clear_faults`]
    /// ([`sun::SunFault::Garbage`]).
    SunGarbage,
    /// The sun accumulators skip armed frames until [`FabricModel::clear_faults`]: their sums
    /// and `sun.frames` stay the last frame's ([`sun::SunFault::Stale`]).
    SunStale,
}

/// The model's state: every block and the frame buffer.
pub struct FabricModel {
    pub config: FabricModelConfig,
    /// The register file (RW, W1C, W1P, RO and Const fields of `skylux_regmap::MAP`).
    pub regs: RegisterFileModel,
    /// The image sensor (registers, I2C faults, pixel values).
    pub sensor: Mt9p031,
    /// The frame buffer behind port 0.
    pub memory: Vec<u8>,
    /// System clocks since power-up.
    pub now: u64,
    pub i2c: i2c::I2cMaster,
    pub seq: sequencer::Sequencer,
    pub timeline: sensor::SensorTimeline,
    pub capture: capture::CaptureBlock,
    pub dma: dma::DmaEngine,
    pub sun: sun::SunBlock,
    /// The frame faults waiting for the next frame (applied in order, one frame each unless
    /// they combine).
    pub pending_frame_faults: Vec<HardwareFault>,
    /// What the model saw, for tests.
    pub log: ModelLog,
}

/// What happened, for tests and diagnostics.
#[derive(Clone, Debug, Default)]
pub struct ModelLog {
    /// Sensor frames read out (as the sensor sent them, before the capture's window).
    pub frames: Vec<skylux_hps::campaign::RawFrame>,
    pub triggers: u64,
    /// Longest shield-open stretch, system clocks.
    pub shield_open_cycles_max: u64,
    /// DMA writes that fell outside the modelled frame buffer (bytes dropped).
    pub memory_misses: u64,
    /// RESET_BAR has been released at least once.
    pub reset_released: bool,
    /// Events the model failed to consume (a model bug; tests assert 0).
    pub stuck_events: u64,
}

impl FabricModel {
    pub fn new(sensor: Mt9p031, config: FabricModelConfig) -> Self {
        Self {
            memory: vec![0; config.memory_bytes],
            config,
            regs: RegisterFileModel::default(),
            sensor,
            now: 0,
            i2c: i2c::I2cMaster::default(),
            seq: sequencer::Sequencer::default(),
            timeline: sensor::SensorTimeline::default(),
            capture: capture::CaptureBlock::default(),
            dma: dma::DmaEngine::default(),
            sun: sun::SunBlock::default(),
            pending_frame_faults: Vec::new(),
            log: ModelLog::default(),
        }
    }

    /// Injects a fault: I2C faults act on the sensor's two-wire target at once and last until
    /// [`Self::clear_faults`]; frame faults act on the next frame(s).
    pub fn inject(&mut self, fault: HardwareFault) {
        use crate::mt9p031::I2cFault;
        match fault {
            HardwareFault::SensorAbsent => self.sensor.i2c.fault = I2cFault::Absent,
            HardwareFault::SdaStuckLow => self.sensor.i2c.fault = I2cFault::SdaStuckLow,
            HardwareFault::SclStuckLow => self.sensor.i2c.fault = I2cFault::SclStuckLow,
            HardwareFault::NackRegister(r) => self.i2c.nack_register = Some(r),
            HardwareFault::SunGarbage => self.sun.fault = Some(sun::SunFault::Garbage),
            HardwareFault::SunStale => self.sun.fault = Some(sun::SunFault::Stale),
            other => self.pending_frame_faults.push(other),
        }
    }

    /// Removes every injected fault (a stopped PIXCLK stays stopped until a reset).
    pub fn clear_faults(&mut self) {
        self.sensor.i2c.fault = crate::mt9p031::I2cFault::None;
        self.i2c.nack_register = None;
        self.sun.fault = None;
        self.pending_frame_faults.clear();
    }

    /// Converts PIXCLK periods into system clocks (rounded).
    pub fn pix_to_sys(&self, pixclk: u64) -> u64 {
        (pixclk as f64 * f64::from(SYS_CLOCK_HZ) / self.sensor.pixclk_hz.max(1.0)).round() as u64
    }

    /// Runs the fabric for `cycles` system clocks.
    pub fn run(&mut self, cycles: u64) {
        let end = self.now.saturating_add(cycles);
        let mut repeats = 0u32;
        while let Some(t) = self.next_event().filter(|&t| t <= end) {
            // An event that firing does not consume would loop for ever: a model bug, counted
            // and skipped rather than hanging the caller.
            repeats = if t <= self.now { repeats + 1 } else { 0 };
            if repeats > 64 {
                self.log.stuck_events += 1;
                break;
            }
            self.now = self.now.max(t);
            self.fire();
        }
        self.now = self.now.max(end);
    }

    /// The earliest pending event of any block.
    fn next_event(&self) -> Option<u64> {
        [
            self.i2c.next_event(),
            self.sequencer_next_event(),
            self.timeline.next_event(),
            self.dma.next_event(),
        ]
        .into_iter()
        .flatten()
        .min()
    }

    /// Handles every event due at `now`, in a fixed order (sensor pins first, then the blocks
    /// that watch them).
    fn fire(&mut self) {
        self.sensor_events();
        self.dma_events();
        self.i2c_events();
        self.sequencer_events();
    }

    /// The value of a W1C/RW register as stored.
    fn stored(&mut self, offset: u32) -> u32 {
        self.regs.read(offset)
    }

    /// Raises causes in `sys.irq_status`.
    fn irq(&mut self, field: &skylux_regmap::Field) {
        self.regs
            .set_bits(sys::irq_status::REG.offset, field.mask());
    }

    /// RO fields of the block at `offset` as they are now.
    fn refresh_inputs(&mut self, offset: u32) {
        use skylux_regmap::{capture, dma, i2c, seq, sun};
        match offset & !(skylux_regmap::BLOCK_SPAN_BYTES - 1) {
            b if b == sys::BLOCK.base => {
                let now = self.now;
                self.regs
                    .fabric_inputs
                    .insert(sys::time_lo::REG.offset, now as u32);
                self.regs
                    .fabric_inputs
                    .insert(sys::time_hi::REG.offset, (now >> 32) as u32);
            }
            b if b == i2c::BLOCK.base => self.i2c_inputs(),
            b if b == seq::BLOCK.base => self.sequencer_inputs(),
            b if b == capture::BLOCK.base => self.capture_inputs(),
            b if b == dma::BLOCK.base => self.dma_inputs(),
            b if b == sun::BLOCK.base => self.sun_inputs(),
            _ => {}
        }
    }

    /// A register read from the HPS.
    pub fn read_register(&mut self, offset: u32) -> u32 {
        self.run(self.config.read_cycles.saturating_sub(1));
        self.refresh_inputs(offset);
        let v = self.regs.read(offset);
        self.run(1.min(self.config.read_cycles));
        v
    }

    /// A register write from the HPS; the blocks see it at the end of its cycle.
    pub fn write_register(&mut self, offset: u32, value: u32) {
        self.regs.write(offset, value, 0xF);
        let pulse = self.regs.last_pulse.take();
        self.after_write(offset, value, pulse);
        self.run(self.config.write_cycles);
    }

    fn after_write(&mut self, offset: u32, value: u32, pulse: Option<(u32, u32)>) {
        use skylux_regmap::{dma as d, hdr as h, i2c as i, seq as s};
        if offset == i::sensor_pins::REG.offset {
            self.sensor_pins_written(i::sensor_pins::RESET_N.get(value) != 0);
        }
        let Some((at, bits)) = pulse else { return };
        if at == i::ctrl::REG.offset && i::ctrl::START.get(bits) != 0 {
            self.hps_i2c_start();
        } else if at == s::ctrl::REG.offset {
            if s::ctrl::START.get(bits) != 0 {
                self.sequencer_start();
            }
            if s::ctrl::ABORT.get(bits) != 0 {
                self.sequencer_abort();
            }
        } else if at == d::ctrl::REG.offset && d::ctrl::RESET.get(bits) != 0 {
            self.dma_restart();
        } else if at == h::ctrl::REG.offset && h::ctrl::NEW_SET.get(bits) != 0 {
            self.dma.hdr.new_set_pending = true;
        }
    }
}

/// The model, shared between the register view and the memory view.
pub type SharedFabric = Arc<Mutex<FabricModel>>;

fn lock(shared: &SharedFabric) -> Result<MutexGuard<'_, FabricModel>, BusError> {
    shared
        .lock()
        .map_err(|_| BusError::Simulation("the fabric model panicked earlier".into()))
}

/// The lightweight-bridge register window of the model.
#[derive(Clone)]
pub struct ModelRegisters(pub SharedFabric);

impl RegisterBus for ModelRegisters {
    fn read32(&mut self, offset: u32) -> Result<u32, BusError> {
        check_access(offset as u64, 4, LW_BRIDGE_SPAN_BYTES as u64, 4)?;
        Ok(lock(&self.0)?.read_register(offset))
    }
    fn write32(&mut self, offset: u32, value: u32) -> Result<(), BusError> {
        check_access(offset as u64, 4, LW_BRIDGE_SPAN_BYTES as u64, 4)?;
        lock(&self.0)?.write_register(offset, value);
        Ok(())
    }
}

/// The frame buffer as the HPS's DMA buffer sees it (uncached: every read sees what the
/// fabric wrote, hardware-facts.md §3.2).
#[derive(Clone)]
pub struct ModelMemory(pub SharedFabric);

impl DmaMemory for ModelMemory {
    fn phys_base(&self) -> u64 {
        self.0.lock().map(|m| m.config.memory_base).unwrap_or(0)
    }
    fn len_bytes(&self) -> u64 {
        self.0.lock().map(|m| m.memory.len() as u64).unwrap_or(0)
    }
    fn read_bytes(&mut self, offset: u64, buf: &mut [u8]) -> Result<(), BusError> {
        let m = lock(&self.0)?;
        check_access(offset, buf.len() as u64, m.memory.len() as u64, 1)?;
        let o = offset as usize;
        buf.copy_from_slice(&m.memory[o..o + buf.len()]);
        Ok(())
    }
    fn write_bytes(&mut self, offset: u64, data: &[u8]) -> Result<(), BusError> {
        let mut m = lock(&self.0)?;
        check_access(offset, data.len() as u64, m.memory.len() as u64, 1)?;
        let o = offset as usize;
        m.memory[o..o + data.len()].copy_from_slice(data);
        Ok(())
    }
}

/// The model and its two bus views.
pub fn fabric_model(
    sensor: Mt9p031,
    config: FabricModelConfig,
) -> (SharedFabric, ModelRegisters, ModelMemory) {
    let shared = Arc::new(Mutex::new(FabricModel::new(sensor, config)));
    (
        shared.clone(),
        ModelRegisters(shared.clone()),
        ModelMemory(shared),
    )
}
