//! The BVH ray unit's traversal core (issue 22 item 4; formats and golden model in
//! `skylux_regmap::bvh_format`): the room's tree in block RAM, rays in as f32 words, the
//! leaves each ray may reach out, bit-identical to `bvh_format::result_words`.
//!
//! - [`BvhInterleaved`]: the block (exported to Verilog): node memory, `RAYS_IN_FLIGHT` rays
//!   interleaved through the lanes, output FIFO.
//! - [`BvhTraversal`]: the same ports with one ray in flight (the reference for the cycle
//!   model, `VISIT_CYCLES` a node visit).
//! - [`RayFrontEnd`]: the f32 front end (`bvh_format::grid_ray` in gates).
//! - [`bench`]: the block's streams driven from Rust, for the tests and the Verilog
//!   cross-check.

pub mod bench;
mod front;
mod interleaved;
mod traversal;

pub use front::{DistanceSteps, InverseMantShift, OriginSteps, RayFrontEnd};
pub use interleaved::{
    BvhInterleaved, ContextState, OUTPUT_FIFO_BITS, PIPELINE_CLOCKS, RAYS_IN_FLIGHT,
};
pub use traversal::{
    BvhTraversal, TraversalState, NODE_ADDRESS_BITS, NODE_COUNT_BITS, RESULT_BUFFER_BITS,
    VISIT_CYCLES,
};
