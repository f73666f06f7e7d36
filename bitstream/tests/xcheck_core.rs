//! The whole core's Verilog (module `top` exported from a fresh `SkyluxCore`) against its
//! rust-hdl simulation: one recorded run of the core on its simulated board, driven by the HPS
//! drivers (sensor held in reset, released, configured over I2C; capture and DMA configured;
//! a one-exposure sequence captured into SDRAM through a port with random waitrequest), then a
//! ray-box batch on the other port. Icarus replays every input and must match every output at
//! every settle step.

use rand::rngs::StdRng;
use rand::SeedableRng;
use skylux_bitstream::blocks::BLOCKS;
use skylux_bitstream::xcheck::{self, Tool};
use skylux_bus::{RegisterAccess, RegisterBus};
use skylux_hps::fpga::sensor::{I2cTiming, SensorConfig};
use skylux_hps::fpga::sequence::ShieldConfig;
use skylux_hps::fpga::{CaptureConfig, ExposureSlot, Fabric};
use skylux_regmap::raybox;
use skylux_regmap::raybox_format::{result_word, ITEM_BYTES};
use skylux_sim::core_rig::{CoreRigConfig, CoreSystem};
use skylux_sim::mt9p031::{Mt9p031, RampSource};
use skylux_sim::raybox::pairs;

const WINDOW_BASE: u64 = 0x3000_1000;
const RBX_BASE: u64 = 0x3800_0000;

#[test]
fn whole_core_verilog_equals_rust_hdl_on_a_capture_and_a_raybox_batch() {
    if !xcheck::require(&[Tool::Iverilog, Tool::Vvp]) {
        return;
    }
    let capture = CaptureConfig::fitted(8, 4, WINDOW_BASE, 2);
    let memory = 0x1000 + capture.window_size_bytes as usize + 0x1000;
    let sensor = Mt9p031::new(Box::new(RampSource), 96e6);
    let mut rig = CoreSystem::new(sensor, CoreRigConfig::new(memory, 4096, 0.3));
    rig.driver.record();
    let mut f = Fabric::bring_up(rig).expect("bring-up");
    f.sensor_bus_setup(I2cTiming {
        half_period_cycles: 2,
        timeout_cycles: 2_000,
    })
    .unwrap();
    f.sensor_reset_release(true).unwrap();
    // The registers only, without read-back: the trace stays short.
    let config = SensorConfig {
        height: 4,
        width: 8,
        shutter_width_rows: 1,
        ..SensorConfig::default()
    };
    for (r, v) in config.register_writes() {
        f.sensor_write(r, v).unwrap();
    }
    f.capture_configure(&capture).unwrap();
    f.set_exposures(&[ExposureSlot {
        shutter_width_rows: 1,
        shutter_delay: 0,
        gain_code: 8,
    }])
    .unwrap();
    f.configure_shield(&ShieldConfig {
        steps: 1,
        step_period_cycles: 8,
        limit_cycles: 1_000_000,
        trigger_pulse_cycles: 2,
    })
    .unwrap();
    assert_eq!(f.run_sequence(100_000).unwrap().frames, 1);
    let mut written = 0;
    for _ in 0..5_000 {
        written = f.frames_written().unwrap();
        if written == 1 {
            break;
        }
    }
    assert_eq!(written, 1, "the frame reached SDRAM");
    let mut rig = f.into_bus();
    let frame = capture
        .ring
        .read_slot(&mut ReadFrames(&rig), 0)
        .unwrap()
        .expect("a frame in slot 0");
    assert_eq!(frame.descriptor.flags, 0, "{:?}", frame.flag_names());
    assert_eq!(frame.checksum_ok(), Some(true));

    // A ray-box batch on port 1.
    let mut rng = StdRng::seed_from_u64(7);
    let items: Vec<[u64; 6]> = (0..6)
        .map(|_| pairs::random_item(&mut rng).pack())
        .collect();
    let bytes: Vec<u8> = items
        .iter()
        .flatten()
        .flat_map(|w| w.to_le_bytes())
        .collect();
    rig.raybox
        .slice_mut(RBX_BASE, bytes.len())
        .unwrap()
        .copy_from_slice(&bytes);
    let result = RBX_BASE + items.len() as u64 * ITEM_BYTES as u64;
    for (r, v) in [
        (raybox::window_base::REG, RBX_BASE as u32),
        (raybox::window_size::REG, 4096),
        (raybox::work_base::REG, RBX_BASE as u32),
        (raybox::work_count::REG, items.len() as u32),
        (raybox::result_base::REG, result as u32),
        (raybox::bus_timeout::REG, 5000),
        (raybox::ctrl::REG, raybox::ctrl::START.mask()),
    ] {
        rig.write_reg(&r, 0, v).unwrap();
    }
    let mut status = 0;
    for _ in 0..5_000 {
        status = rig.read32(raybox::status::REG.offset).unwrap();
        if raybox::status::DONE.get(status) == 1 {
            break;
        }
    }
    assert_eq!(status, raybox::status::DONE.mask());
    let got: Vec<u64> = rig
        .raybox
        .slice(result, 8 * items.len())
        .unwrap()
        .chunks_exact(8)
        .map(|c| u64::from_le_bytes(c.try_into().unwrap()))
        .collect();
    let want: Vec<u64> = (0..items.len())
        .map(|i| result_word(i as u32, &items[i]).unwrap())
        .collect();
    assert_eq!(got, want, "rust-hdl simulation vs golden model");

    let trace = rig.driver.take_trace();
    let core = BLOCKS.iter().find(|b| b.name == "skylux_core").unwrap();
    let report = xcheck::replay("skylux_core", &(core.verilog)(), &trace).unwrap();
    println!("{}", report.summary());
    assert!(report.steps > 10_000, "trace too short: {}", report.steps);
    assert!(report.is_clean(), "{}", report.summary());
}

/// Port 0's memory as a `DmaMemory`, borrowed from the rig.
struct ReadFrames<'a>(&'a CoreSystem);

impl skylux_bus::DmaMemory for ReadFrames<'_> {
    fn phys_base(&self) -> u64 {
        self.0.frames.config.base
    }
    fn len_bytes(&self) -> u64 {
        self.0.frames.config.size_bytes as u64
    }
    fn read_bytes(&mut self, offset: u64, buf: &mut [u8]) -> Result<(), skylux_bus::BusError> {
        let m = &self.0.frames;
        let src = m
            .slice(m.config.base + offset, buf.len())
            .ok_or(skylux_bus::BusError::Simulation("range".into()))?;
        buf.copy_from_slice(src);
        Ok(())
    }
    fn write_bytes(&mut self, _: u64, _: &[u8]) -> Result<(), skylux_bus::BusError> {
        Err(skylux_bus::BusError::Simulation("read only".into()))
    }
}
