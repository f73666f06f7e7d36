//! The ray-box (slab test) accelerator (issue 7; registers `raybox.*`; memory formats and
//! golden model in `skylux_regmap::raybox_format`).
//!
//! - [`RayBoxUnit`]: the block exported to Verilog: the streaming front end (an Avalon-MM
//!   read/write host on f2sdram port 1) around `LANES` slab lanes.
//! - [`SlabLane`]: one pipelined slab test, one test per clock.
//! - [`PlaneProduct`], [`PlaneDistance`]: the arithmetic leaf cells (Verilog with a Rust model).

mod lane;
mod plane;
mod unit;

pub use lane::{SlabLane, LANE_LATENCY};
pub use plane::{PlaneDistance, PlaneProduct, PRODUCT_BITS};
pub use unit::{RayBoxUnit, UnitState, FIFO_DEPTH, MAX_LANES, WORD_ADDRESS_BITS};

/// Lanes of the unit in the core: one lane takes a test per clock, more than the 64-bit port
/// can feed (seven beats per test; ARCHITECTURE.md, "Ray-box unit").
pub const DEFAULT_LANES: usize = 1;
