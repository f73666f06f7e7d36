//! Frame DMA (issue 3 item 5; registers `dma.*`; slot and descriptor format
//! `skylux_regmap::descriptor`), in the system clock domain.
//!
//! - [`FrameIngest`]: the clock-domain FIFO's read side: frame markers, beats, checksum, tags
//!   and the capture status.
//! - [`BurstWriter`]: the Avalon-MM burst master writing payload and descriptor into the ring.
//!
//! The two are wired to the FIFO in `skylux_rtl::capture::CapturePath`.

mod ingest;
mod writer;

pub use ingest::{FrameIngest, IngestState};
pub use writer::{
    BurstWriter, WriterState, BEAT_FIFO_ADDRESS_BITS, DESCRIPTOR_BEATS, MAX_BURST_BEATS,
};
