//! Bus models: an Avalon-MM host standing in for the lightweight HPS-to-FPGA bridge.

mod avalon_host;
pub mod avalon_memory;
mod register_bus;
mod register_model;

pub use avalon_host::AvalonHost;
pub use avalon_memory::{AvalonMemory, AvalonMemoryConfig, WaitPolicy};
pub use register_bus::SimRegisterBus;
pub use register_model::RegisterFileModel;
