//! The Skylux FPGA fabric, written in rust-hdl and simulated cycle-accurately.
//!
//! Every block has a plain-Rust golden model beside it and is exported to Verilog for the
//! cross-check harness in `skylux-bitstream`.

pub mod avalon;
pub mod bayer;
pub mod bvh;
pub mod capture;
pub mod core;
pub mod dma;
pub mod drive;
pub mod hdr;
pub mod i2c;
pub mod raybox;
pub mod regfile;
pub mod sequencer;
pub mod sun;

pub use core::SkyluxCore;
pub use regfile::RegisterFile;
