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
        name: "bayer_grouper",
        verilog: fresh::<skylux_rtl::bayer::BayerGrouper>,
    },
];
