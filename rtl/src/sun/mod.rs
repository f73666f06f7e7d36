//! The sun in the fabric (issue 22 item 2): while the sun's exposure (the shortest) streams
//! in, accumulators over the grouped words at or above a threshold inside a search window
//! give the HPS the sun's centroid, disk luminance and extent as a handful of registers,
//! without a scan of the map.
//!
//! - [`SunAccumulators`]: the block (exported to Verilog), with `SunPosition` (the word's
//!   group coordinates) inside it.
//! - [`golden`]: the plain-Rust model the tests compare the RTL against.
//! - [`bench`]: the word stream's protocol, for the tests and the Verilog cross-check.

mod accumulators;
pub mod bench;
pub mod golden;
mod position;

pub use accumulators::{SunAccumulators, SUN_LATENCY};
