//! Pixel capture (issue 3 item 3; registers `capture.*`): the sensor interface in the PIXCLK
//! domain and the clock-domain FIFO into the system clock.
//!
//! - [`PixelCapture`]: FV/LV/D in, checked against the window, pixel stream to the Bayer
//!   grouper, words and frame markers into the FIFO.
//! - [`fifo_entry`]: the FIFO's entry format (words between start and end markers).
//! - [`CapturePath`]: capture, grouper, FIFO and frame DMA together, the block the core wires
//!   to the register file.

pub mod fifo_entry;
mod path;
mod pixel_capture;

pub use path::{CaptureFifo, CapturePath};
pub use pixel_capture::PixelCapture;
