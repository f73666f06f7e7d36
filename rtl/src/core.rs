//! `SkyluxCore`: the whole fabric in one block, as the board top instantiates it. Its wiring
//! is generated from the register map by `build/core.rs`; its ports are the contract in
//! `bitstream/quartus/core_ports.md`.
#![allow(clippy::all, unused_parens)]

use crate::capture::CapturePath;
use crate::raybox::RayBoxUnit;
use crate::sequencer::SensorControl;
use crate::RegisterFile;
use rust_hdl::prelude::*;

/// Ray-box lanes in the core: one lane already saturates its f2sdram port
/// (ARCHITECTURE.md, "Ray-box unit"), so more would cost ALMs and DSPs for nothing.
pub const CORE_RAYBOX_LANES: usize = crate::raybox::DEFAULT_LANES;

include!(concat!(env!("OUT_DIR"), "/core.rs"));
