//! Writes `SkyluxCore`, the whole fabric core, from the register map.
//!
//! Every register field of a page is wired to the block that owns the page, by name: a block's
//! port is named after the register-file port it connects to (`seq_count_exposures`), less a
//! prefix for blocks that are also used on their own (`raybox_ctrl_start` -> `ctrl_start`).
//! RW and W1P fields feed the block, RO fields come from it, W1C fields take the block's
//! `..._set` pulse. A block missing a port, or with a port of another width, fails to compile,
//! so the map and the blocks cannot drift apart. What is not a register field (clocks, the time
//! base, interrupt causes, pins, the two Avalon-MM hosts) is wired by hand in `FIXED_WIRING`,
//! and the top-level ports are the contract in `bitstream/quartus/core_ports.md`.

use skylux_regmap::{Access, Block};
use std::fmt::Write;

/// Register page -> (sub-block instance, prefix dropped from the port name).
const OWNERS: &[(&str, &str, &str)] = &[
    ("i2c", "sensor", ""),
    ("seq", "sensor", ""),
    ("capture", "capture", ""),
    ("bayer", "capture", ""),
    ("dma", "capture", ""),
    ("raybox", "raybox", "raybox_"),
    ("sun", "capture", ""),
    ("hdr", "capture", ""),
];

/// Registers wired by hand (block, register): they go to pins, not to a sub-block.
const HAND_WIRED: &[(&str, &str)] = &[("i2c", "sensor_pins")];

const PORTS: &str = r#"
    /// System clock (100 MHz): register file, sequencer, I2C, DMA, ray-box unit.
    pub clk: Signal<In, Clock>,
    /// Avalon-MM agent behind the lightweight HPS-to-FPGA bridge (word address, fixed read
    /// latency 1, no waitrequest).
    pub avs_address: Signal<In, Bits<19>>,
    pub avs_read: Signal<In, Bit>,
    pub avs_write: Signal<In, Bit>,
    pub avs_writedata: Signal<In, Bits<32>>,
    pub avs_byteenable: Signal<In, Bits<4>>,
    pub avs_readdata: Signal<Out, Bits<32>>,
    /// Level-high interrupt to f2h_irq0[0].
    pub irq: Signal<Out, Bit>,
    /// Frame DMA: burst write host on f2sdram port 0 (word address = byte address / 8).
    pub dma_address: Signal<Out, Bits<29>>,
    pub dma_burstcount: Signal<Out, Bits<8>>,
    pub dma_write: Signal<Out, Bit>,
    pub dma_writedata: Signal<Out, Bits<64>>,
    pub dma_byteenable: Signal<Out, Bits<8>>,
    pub dma_waitrequest: Signal<In, Bit>,
    /// Ray-box unit: read/write host on f2sdram port 1 (word address).
    pub rbx_address: Signal<Out, Bits<29>>,
    pub rbx_burstcount: Signal<Out, Bits<8>>,
    pub rbx_read: Signal<Out, Bit>,
    pub rbx_write: Signal<Out, Bit>,
    pub rbx_writedata: Signal<Out, Bits<64>>,
    pub rbx_byteenable: Signal<Out, Bits<8>>,
    pub rbx_waitrequest: Signal<In, Bit>,
    pub rbx_readdata: Signal<In, Bits<64>>,
    pub rbx_readdatavalid: Signal<In, Bit>,
    /// The sensor's pixel clock (up to 96 MHz) and bus.
    pub pixclk: Signal<In, Clock>,
    pub d: Signal<In, Bits<12>>,
    pub fval: Signal<In, Bit>,
    pub lval: Signal<In, Bit>,
    /// STROBE, asynchronous: synchronised here.
    pub strobe: Signal<In, Bit>,
    /// RESET_BAR, from `i2c.sensor_pins.RESET_N` (power-up 0: held in reset).
    pub reset_n: Signal<Out, Bit>,
    pub trigger: Signal<Out, Bit>,
    /// SCLK, push-pull as in the Terasic design (the sensor never stretches the clock).
    pub sclk: Signal<Out, Bit>,
    /// 1 pulls SDATA low; the board top builds the open-drain pin.
    pub sdata_oe: Signal<Out, Bit>,
    /// SDATA as read back, asynchronous (the I2C master synchronises it).
    pub sdata_in: Signal<In, Bit>,
    /// External sequence trigger, synchronised in the board top.
    pub ext_trigger: Signal<In, Bit>,
    pub shield_step: Signal<Out, Bit>,
    pub shield_dir: Signal<Out, Bit>,
    /// Stepper driver enable, active low.
    pub shield_enable_n: Signal<Out, Bit>,

    pub regs: RegisterFile,
    pub sensor: SensorControl,
    pub capture: CapturePath,
    pub raybox: RayBoxUnit<CORE_RAYBOX_LANES>,
    /// Free-running system-clock counter: `sys.time`, and the frames' timestamps.
    time_base: DFF<Bits<64>>,
    strobe_meta: DFF<Bit>,
    strobe_sync: DFF<Bit>,
"#;

const LOCALS: &[&str] = &["time_base", "strobe_meta", "strobe_sync"];

const FIXED_WIRING: &str = r#"
        self.regs.clock.next = self.clk.val();
        self.sensor.clock.next = self.clk.val();
        self.capture.clock.next = self.clk.val();
        self.capture.pixclk.next = self.pixclk.val();
        self.raybox.clock.next = self.clk.val();
        dff_setup!(self, clk, time_base, strobe_meta, strobe_sync);

        // Register agent.
        self.regs.avs_address.next = self.avs_address.val();
        self.regs.avs_read.next = self.avs_read.val();
        self.regs.avs_write.next = self.avs_write.val();
        self.regs.avs_writedata.next = self.avs_writedata.val();
        self.regs.avs_byteenable.next = self.avs_byteenable.val();
        self.avs_readdata.next = self.regs.avs_readdata.val();
        self.irq.next = self.regs.irq.val();

        // Time base.
        self.time_base.d.next = self.time_base.q.val() + 1;
        self.regs.sys_time_lo_cycles.next = self.time_base.q.val().get_bits::<32>(0);
        self.regs.sys_time_hi_cycles.next = self.time_base.q.val().get_bits::<32>(32);
        self.sensor.time_cycles.next = self.time_base.q.val();

        // Interrupt causes.
        self.regs.sys_irq_status_frame_done_set.next = self.capture.irq_frame_done.val();
        self.regs.sys_irq_status_sequence_done_set.next = self.sensor.seq_status_done_set.val();
        self.regs.sys_irq_status_dma_error_set.next = self.capture.irq_dma_error.val();
        self.regs.sys_irq_status_capture_error_set.next = self.capture.irq_capture_error.val();
        self.regs.sys_irq_status_i2c_done_set.next = self.sensor.i2c_status_done_set.val();
        self.regs.sys_irq_status_raybox_done_set.next = self.raybox.status_done_set.val();

        // Sensor pins.
        self.capture.sensor_frame_valid.next = self.fval.val();
        self.capture.sensor_line_valid.next = self.lval.val();
        self.capture.sensor_data.next = self.d.val();
        // The sequencer waits on FRAME_VALID as synchronised into the system clock.
        self.sensor.frame_valid.next = self.capture.capture_status_frame_valid.val();
        self.sensor.ext_trigger.next = self.ext_trigger.val();
        self.sensor.scl_in.next = !self.sensor.scl_low.val();
        self.sensor.sda_in.next = self.sdata_in.val();
        self.sclk.next = !self.sensor.scl_low.val();
        self.sdata_oe.next = self.sensor.sda_low.val();
        self.trigger.next = self.sensor.trigger.val();
        self.shield_step.next = self.sensor.shield_step.val();
        self.shield_dir.next = self.sensor.shield_dir.val();
        self.shield_enable_n.next = !self.sensor.shield_enable.val();
        self.reset_n.next = self.regs.i2c_sensor_pins_reset_n.val();
        self.strobe_meta.d.next = self.strobe.val();
        self.strobe_sync.d.next = self.strobe_meta.q.val();
        self.regs.i2c_sensor_pins_strobe.next = self.strobe_sync.q.val();

        // Frame tags from the sequencer to the capture block.
        self.capture.tag_exposure_index.next = self.sensor.tag_exposure_index.val();
        self.capture.tag_frame_number.next = self.sensor.tag_frame_number.val();
        self.capture.tag_timestamp.next = self.sensor.tag_timestamp.val();

        // Frame DMA host (the block's address is in bytes, 8-byte aligned).
        self.dma_address.next = self.capture.avm_address.val().get_bits::<29>(3);
        self.dma_burstcount.next = self.capture.avm_burstcount.val();
        self.dma_write.next = self.capture.avm_write.val();
        self.dma_writedata.next = self.capture.avm_writedata.val();
        self.dma_byteenable.next = self.capture.avm_byteenable.val();
        self.capture.avm_waitrequest.next = self.dma_waitrequest.val();

        // Ray-box host.
        self.rbx_address.next = self.raybox.rbx_address.val();
        self.rbx_burstcount.next = self.raybox.rbx_burstcount.val();
        self.rbx_read.next = self.raybox.rbx_read.val();
        self.rbx_write.next = self.raybox.rbx_write.val();
        self.rbx_writedata.next = self.raybox.rbx_writedata.val();
        self.rbx_byteenable.next = self.raybox.rbx_byteenable.val();
        self.raybox.rbx_waitrequest.next = self.rbx_waitrequest.val();
        self.raybox.rbx_readdata.next = self.rbx_readdata.val();
        self.raybox.rbx_readdatavalid.next = self.rbx_readdatavalid.val();
"#;

pub fn generate(map: &[Block]) -> String {
    let mut w = String::new();
    writeln!(
        w,
        "// Generated by rtl/build/core.rs from skylux_regmap::MAP. Do not edit.\n"
    )
    .unwrap();
    writeln!(
        w,
        "/// The whole fabric core: register file, sensor control (I2C master, exposure\n\
         /// sequencer, shield), capture path (capture, Bayer grouping, FIFO, DMA) and the\n\
         /// ray-box unit, with the flat ports of `bitstream/quartus/core_ports.md`.\n\
         #[derive(LogicBlock)]\npub struct SkyluxCore {{{PORTS}}}\n"
    )
    .unwrap();

    // Default: every field default.
    let mut names: Vec<&str> = PORTS
        .lines()
        .filter_map(|l| {
            let l = l.trim();
            let l = l.strip_prefix("pub ").unwrap_or(l);
            l.split_once(':')
                .map(|(n, _)| n)
                .filter(|n| !n.starts_with("//") && !n.is_empty() && !n.contains(' '))
        })
        .collect();
    names.dedup();
    writeln!(
        w,
        "impl Default for SkyluxCore {{\n    fn default() -> Self {{\n        Self {{"
    )
    .unwrap();
    for n in &names {
        writeln!(w, "            {n}: Default::default(),").unwrap();
    }
    writeln!(w, "        }}\n    }}\n}}\n").unwrap();
    debug_assert!(LOCALS.iter().all(|l| names.contains(l)));

    writeln!(
        w,
        "impl Logic for SkyluxCore {{\n    #[hdl_gen]\n    fn update(&mut self) {{{FIXED_WIRING}"
    )
    .unwrap();
    writeln!(
        w,
        "        // Register fields, by owner (generated from the map)."
    )
    .unwrap();
    for block in map {
        let Some(&(_, inst, strip)) = OWNERS.iter().find(|o| o.0 == block.name) else {
            continue;
        };
        for reg in block.registers {
            if HAND_WIRED.contains(&(block.name, reg.name)) {
                continue;
            }
            for f in reg.fields {
                let name = format!("{}_{}_{}", block.name, reg.name, f.name.to_lowercase());
                let port = name.strip_prefix(strip).unwrap_or(&name).to_string();
                let indices: Vec<String> = if reg.count > 1 {
                    (0..reg.count).map(|i| format!("[{i}]")).collect()
                } else {
                    vec![String::new()]
                };
                for ix in indices {
                    match f.access {
                        Access::RW | Access::W1P => writeln!(
                            w,
                            "        self.{inst}.{port}{ix}.next = self.regs.{name}{ix}.val();"
                        ),
                        Access::RO => writeln!(
                            w,
                            "        self.regs.{name}{ix}.next = self.{inst}.{port}{ix}.val();"
                        ),
                        Access::W1C => writeln!(
                            w,
                            "        self.regs.{name}_set{ix}.next = self.{inst}.{port}_set{ix}.val();"
                        ),
                        Access::Const => Ok(()),
                    }
                    .unwrap();
                }
            }
        }
    }
    writeln!(w, "    }}\n}}").unwrap();
    w
}
