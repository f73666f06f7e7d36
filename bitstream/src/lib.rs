//! From rust-hdl to the Cyclone V: Verilog export of every block, and the cross-check harness
//! that keeps the exported Verilog honest (shared/docs/rust-hdl-notes.md section 6 lists real
//! cases where rust-hdl's simulation and its Verilog disagree).

pub mod blocks;
pub mod formal;
pub mod xcheck;
