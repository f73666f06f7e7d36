//! The fabric source over the behavioural fabric model (`[sim] source = "fabric-model"`):
//! the same `FabricSource` and drivers as the board and the cycle-accurate core, over
//! `skylux_sim::fabric_model`, which runs a full-frame HDR capture in well under a second.
//! It exists so the daemon's real fabric path runs whole cycles at a realistic window, and so
//! `[[sim.fault]]` can make hardware faults at their source (an absent sensor, a stuck bus,
//! a stopped PIXCLK, malformed frames, FIFO overflow, a DMA bus timeout, a corrupted word,
//! frames out of order, sun accumulators that answer garbage or miss the capture) which the
//! drivers must find by themselves.

use crate::config::{Config, FaultKind};
use crate::fabric_source::FabricSource;
use crate::source::{CaptureSet, CaptureSource, SimSource, SourceError};
use crate::wait::PollWait;
use chrono::{DateTime, FixedOffset};
use skylux_sim::fabric_model::{
    fabric_model, FabricModelConfig, HardwareFault, ModelMemory, ModelRegisters, SharedFabric,
};
use std::sync::atomic::AtomicBool;
use std::sync::Arc;
use std::time::Duration;

/// System clocks one register read costs in the daemon's model: about a microsecond, the
/// order of a lightweight-bridge read from the HPS (not measured on the board), so that
/// polling a half-second shield opening takes ~10^5 reads instead of ~10^7 at the core rig's
/// two clocks. Writes are posted: a few clocks.
pub const READ_CYCLES: u64 = 100;
pub const WRITE_CYCLES: u64 = 4;

/// The fabric source over the fabric model, imaging the simulated world.
pub struct SimFabricModelSource {
    pub inner: FabricSource<ModelRegisters, ModelMemory, PollWait>,
    pub model: SharedFabric,
    world: crate::sim_stage::WorldStage,
    faults: Vec<crate::config::FaultRule>,
    attempts: u64,
    /// Lines of the window (where a stopped PIXCLK stops: half-way).
    lines: u32,
}

/// The f2sdram stall of a `dma_bus_timeout` fault, system clocks: twice the watchdog the
/// driver programs (`CaptureConfig::fitted` leaves `dma.bus_timeout` at its reset value,
/// 1,000,000 clocks = 10 ms, and `FabricSource` keeps it), so the stall is beyond it by a
/// margin no rounding in the model removes; 20 ms is still far inside the frame wait
/// (`frame_timeout_s`), so the frames do arrive and it is the DMA's sticky `BUS_TIMEOUT`,
/// not a missing frame, that fails the capture.
pub const DMA_BUS_TIMEOUT_STALL_CYCLES: u64 =
    2 * skylux_regmap::dma::bus_timeout::CYCLES.reset as u64;

/// The hardware fault a `[[sim.fault]]` kind makes in the model (`None`: a host fault the
/// daemon makes itself, `disk_full` and `clock_back`).
pub fn hardware_fault(kind: FaultKind, lines: u32) -> Option<HardwareFault> {
    Some(match kind {
        FaultKind::SensorAbsent => HardwareFault::SensorAbsent,
        // Shutter_Width_Lower: written at configuration and before every exposure.
        FaultKind::I2cNack => HardwareFault::NackRegister(0x09),
        FaultKind::I2cBusStuck => HardwareFault::SdaStuckLow,
        FaultKind::DmaTimeout | FaultKind::PixclkStopped => HardwareFault::PixclkStops {
            after_lines: (lines / 2).max(1),
        },
        // 2 ms of waitrequest: far beyond the FIFOs (~630 words), within dma.bus_timeout.
        FaultKind::FlaggedFrame | FaultKind::FifoOverflow => {
            HardwareFault::PortStall { cycles: 200_000 }
        }
        FaultKind::LineShort => HardwareFault::LineLength {
            line: 1,
            delta_px: -2,
        },
        FaultKind::LineLong => HardwareFault::LineLength {
            line: 1,
            delta_px: 2,
        },
        FaultKind::FrameShort => HardwareFault::FrameLength { delta_lines: -1 },
        FaultKind::FrameLong => HardwareFault::FrameLength { delta_lines: 1 },
        FaultKind::BadChecksum => HardwareFault::CorruptWord {
            word: 5,
            xor: 0x0000_0010,
        },
        FaultKind::OutOfOrder => HardwareFault::SwapSlots,
        FaultKind::DmaBusTimeout => HardwareFault::PortStall {
            cycles: DMA_BUS_TIMEOUT_STALL_CYCLES,
        },
        FaultKind::SunGarbage => HardwareFault::SunGarbage,
        FaultKind::SunStale => HardwareFault::SunStale,
        FaultKind::DiskFull | FaultKind::ClockBack => return None,
    })
}

/// Builds [`SimFabricModelSource`] from the configuration: the `[fabric]` window and the
/// camera's exposures, the simulated fabric's I2C and shield timing (`fabric_settings` with
/// `sim`), a frame buffer just large enough for the ring.
pub fn sim_fabric_model_source(
    config: &Config,
    device: &skylux_hps::camera::DeviceConfig,
    stop: Arc<AtomicBool>,
) -> Result<SimFabricModelSource, SourceError> {
    let (settings, plan, memory_bytes) = crate::fabric_source::sim_fabric_plan(config, device)?;
    let world = crate::sim_stage::WorldStage::new(config, device)?;
    let sensor = skylux_sim::mt9p031::Mt9p031::new(world.pixel_source(), settings.pixclk_hz);
    let (model, regs, memory) = fabric_model(
        sensor,
        FabricModelConfig {
            read_cycles: READ_CYCLES,
            write_cycles: WRITE_CYCLES,
            ..FabricModelConfig::new(memory_bytes)
        },
    );
    let wait = PollWait {
        // 0.5 simulated seconds of polling beyond the sequence's end.
        max_polls: 500_000,
        pause: Duration::ZERO,
    };
    let inner = FabricSource::new(regs, memory, wait, settings, stop)?;
    Ok(SimFabricModelSource {
        inner,
        model,
        world,
        faults: config.sim.faults.clone(),
        attempts: 0,
        lines: plan.height_px,
    })
}

impl SimFabricModelSource {
    fn with_model<T>(&self, f: impl FnOnce(&mut skylux_sim::fabric_model::FabricModel) -> T) -> T {
        match self.model.lock() {
            Ok(mut m) => f(&mut m),
            Err(p) => f(&mut p.into_inner()),
        }
    }
}

impl CaptureSource for SimFabricModelSource {
    fn name(&self) -> &'static str {
        "fabric-model"
    }

    fn capture(&mut self, at: DateTime<FixedOffset>) -> Result<CaptureSet, SourceError> {
        self.capture_with(at, false)
    }

    fn capture_raw(&mut self, at: DateTime<FixedOffset>) -> Result<CaptureSet, SourceError> {
        self.capture_with(at, true)
    }

    fn makes_maps(&self) -> bool {
        self.inner.makes_maps()
    }
}

impl SimFabricModelSource {
    /// One capture (raw if `raw`), with the configured fault of this attempt made in the
    /// model first.
    fn capture_with(
        &mut self,
        at: DateTime<FixedOffset>,
        raw: bool,
    ) -> Result<CaptureSet, SourceError> {
        self.attempts += 1;
        let fault = SimSource::fault_for(&self.faults, self.attempts)
            .and_then(|k| hardware_fault(k, self.lines));
        if let Some(f) = fault {
            tracing::info!(attempt = self.attempts, fault = ?f, "fabric model: hardware fault");
            self.with_model(|m| m.inject(f));
        }
        self.world.stage(at)?;
        let result = if raw {
            self.inner.capture_raw(at)
        } else {
            self.inner.capture(at)
        };
        // A fault lasts one attempt (a stopped PIXCLK until the next configuration's reset).
        self.with_model(|m| m.clear_faults());
        let mut set = result?;
        self.world.attach_truth(&mut set, at)?;
        Ok(set)
    }
}
