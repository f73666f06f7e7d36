//! HDR in the fabric (issue 22 item 1): while the exposures of a set stream in, long to short,
//! the frame DMA writes one map (`skylux_regmap::words::hdr_map`) into one buffer instead of
//! one frame per exposure. Each group is written while it is not yet filled; it becomes
//! filled in the first (longest) exposure in which it is usable, so the buffer ends with that
//! exposure's word, without reading memory back. The filled mask is one bit per group in
//! block RAM.
//!
//! - [`HdrSelect`]: the block (exported to Verilog), inside the DMA's ingest.
//! - [`golden`]: the plain-Rust model the tests compare the RTL against.
//! - [`bench`]: the word stream's protocol, for the tests and the Verilog cross-check.

pub mod bench;
pub mod golden;
mod select;

pub use select::{HdrSelect, MASK_ADDRESS_BITS, MASK_HIGH_BITS, MASK_LOW_BITS};
