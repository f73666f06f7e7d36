//! Bayer 2x2 grouping (issue 3 item 4; registers `bayer.*`; word format
//! `skylux_regmap::words`): in the PIXCLK domain, between the capture and the FIFO into the
//! system clock.
//!
//! - [`BayerGrouper`]: the block (the one exported to Verilog).
//! - [`QuadAssembler`]: pixel stream to 2x2 blocks through a one-row line buffer in block RAM.
//! - [`QuadLuma`]: 2x2 block to grouped word (flags, black level, phase, weights).
//! - [`golden`]: the plain-Rust model the tests compare the RTL against.

pub mod golden;
mod grouper;
mod luma;
mod quads;

pub use grouper::{BayerGrouper, GROUPED_LATENCY, RAW_LATENCY};
pub use luma::QuadLuma;
pub use quads::{QuadAssembler, LINE_ADDRESS_BITS};
