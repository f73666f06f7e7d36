//! The Skylux FPGA fabric, written in rust-hdl and simulated cycle-accurately.
//!
//! Every block has a plain-Rust golden model beside it and is exported to Verilog for the
//! cross-check harness in `skylux-bitstream`.

pub mod avalon;
pub mod bayer;
pub mod drive;
pub mod regfile;

pub use regfile::RegisterFile;
