//! What the clock-domain FIFO carries: the Bayer words of a frame between a start marker and an
//! end marker, so the frame boundaries and the capture's verdict on the frame cross into the
//! system clock in order with the data, through the one crossing (no separate synchronisers
//! for flags that could arrive before or after the words they describe).
//!
//! ```text
//!  33   32   31                                     0
//! +---+------+--------------------------------------+
//! |END|MARKER|  Bayer word, or marker payload       |
//! +---+------+--------------------------------------+
//! ```
//! The end marker's payload is the received geometry and the capture's flags (below); the
//! start marker's payload is 0.

/// Width of a FIFO entry.
pub const BITS: usize = 34;
/// Set on a start or end marker.
pub const MARKER_BIT: usize = 32;
/// Set on an end marker (with [`MARKER_BIT`]).
pub const END_BIT: usize = 33;

/// End marker payload: pixels in the frame's last line (saturated at 4095) in bits [11:0].
pub const PIXELS_LSB: usize = 0;
/// End marker payload: lines received (saturated at 4095) in bits [23:12].
pub const LINES_LSB: usize = 12;
/// End marker payload flag bits (meanings as the descriptor flags of the same names,
/// `skylux_regmap::descriptor::flag`).
pub const LINE_SHORT_BIT: usize = 24;
pub const LINE_LONG_BIT: usize = 25;
pub const FRAME_SHORT_BIT: usize = 26;
pub const FRAME_LONG_BIT: usize = 27;
pub const FIFO_OVERFLOW_BIT: usize = 28;
pub const FRAMES_SKIPPED_BIT: usize = 29;

/// The start marker.
pub const START: u64 = 1 << MARKER_BIT;
/// An end marker's fixed bits.
pub const END: u64 = (1 << MARKER_BIT) | (1 << END_BIT);

/// Address bits of the FIFO: 128 entries. The system clock drains it at up to one entry per
/// cycle against at most one word per two PIXCLK, so in normal running it holds a few entries;
/// the burst buffering is the DMA's beat FIFO (256 beats, 512 words) behind it. Together they
/// ride out a complete port stall of about 1,300 system clocks (13 µs) at full pixel rate
/// before words are dropped. 128 x 34 bits is one M10K in Quartus.
pub const FIFO_ADDRESS_BITS: usize = 7;
/// Entries the FIFO holds.
pub const FIFO_DEPTH: u64 = 1 << FIFO_ADDRESS_BITS;
/// Width of the FIFO's fill counts.
pub const FILL_BITS: usize = FIFO_ADDRESS_BITS + 1;

/// A data word is written only while the write side's fill is below this, leaving room for a
/// start and an end marker. The write side's fill lags its own last write by one clock and the
/// read pointer by a synchroniser handshake, so it never under-reports by more than one entry.
pub const DATA_FILL_LIMIT: u64 = FIFO_DEPTH - 4;
/// A frame is accepted only while the fill is below this (room for its start and end markers).
pub const START_FILL_LIMIT: u64 = FIFO_DEPTH - 2;

/// PIXCLK edges between the frame-end decision and the end marker's write: longer than the
/// Bayer grouper's latency, so the frame's last word is in the FIFO before its end marker.
pub const END_MARKER_DELAY: u64 = crate::bayer::GROUPED_LATENCY as u64 + 1;
const _: () = assert!(crate::bayer::RAW_LATENCY <= crate::bayer::GROUPED_LATENCY);
