//! The register file: an Avalon-MM agent (fixed read latency of one cycle, byte enables
//! honoured) generated from `skylux_regmap::MAP` by `build/register_file.rs`.
#![allow(clippy::all, unused_parens)]

use rust_hdl::prelude::*;

include!(concat!(env!("OUT_DIR"), "/register_file.rs"));
