//! Every rust-hdl block of the design, exported to Verilog from a fresh instance (a simulated
//! instance can carry simulation state into `initial` blocks: rust-hdl-notes §6 item 7).

use rust_hdl::prelude::*;

/// A block's name and a constructor for a fresh instance's Verilog.
pub struct ExportedBlock {
    pub name: &'static str,
    pub verilog: fn() -> String,
}

fn fresh<B: Block + Default>() -> String {
    let mut uut = B::default();
    uut.connect_all();
    generate_verilog(&uut)
}

/// All blocks, in data-path order.
pub const BLOCKS: &[ExportedBlock] = &[
    ExportedBlock {
        name: "register_file",
        verilog: fresh::<skylux_rtl::RegisterFile>,
    },
    ExportedBlock {
        name: "sensor_control",
        verilog: fresh::<skylux_rtl::sequencer::SensorControl>,
    },
    ExportedBlock {
        name: "i2c_master",
        verilog: fresh::<skylux_rtl::i2c::I2cMaster>,
    },
    ExportedBlock {
        name: "exposure_sequencer",
        verilog: fresh::<skylux_rtl::sequencer::ExposureSequencer>,
    },
    ExportedBlock {
        name: "bayer_grouper",
        verilog: fresh::<skylux_rtl::bayer::BayerGrouper>,
    },
    ExportedBlock {
        name: "sun_accumulators",
        verilog: fresh::<skylux_rtl::sun::SunAccumulators>,
    },
    ExportedBlock {
        name: "hdr_select",
        verilog: fresh::<skylux_rtl::hdr::HdrSelect>,
    },
    ExportedBlock {
        name: "capture_path",
        verilog: fresh::<skylux_rtl::capture::CapturePath>,
    },
    ExportedBlock {
        name: "skylux_core",
        verilog: fresh::<skylux_rtl::SkyluxCore>,
    },
    ExportedBlock {
        name: "raybox_unit",
        verilog: fresh::<skylux_rtl::raybox::RayBoxUnit<{ skylux_rtl::raybox::DEFAULT_LANES }>>,
    },
    // The BVH ray unit's traversal: `RAYS_IN_FLIGHT` rays interleaved (the one-ray
    // `BvhTraversal` is not exported).
    ExportedBlock {
        name: "bvh_traversal",
        verilog: fresh::<skylux_rtl::bvh::BvhInterleaved>,
    },
];

/// The checked-in copy of the whole core that the Quartus project compiles
/// (`quartus/skylux.qsf`), relative to this crate.
pub const CORE_VERILOG_PATH: &str = "quartus/core/skylux_core.v";

/// The whole core as the board top instantiates it: module `skylux_core` (rust-hdl names the
/// top `top` and its sub-modules `top$...`), ports as in `quartus/core_ports.md`.
pub fn core_verilog() -> String {
    let v = fresh::<skylux_rtl::SkyluxCore>();
    let v = v.replace("module top(", "module skylux_core(");
    let v = v.replace("top$", "skylux_core$");
    format!(
        "// skylux_core: the whole Skylux fabric core, exported from rust-hdl by\n\
         // `cargo run -p skylux-bitstream -- verilog`. Generated: do not edit.\n{v}"
    )
}
