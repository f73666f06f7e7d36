//! The frame slot and its descriptor: what the frame DMA (`dma.*` registers) writes into the
//! window the HPS owns. A hardware/software contract like the register map, written here once:
//! the RTL (`skylux_rtl::dma`), the memory model in `skylux-sim` and the HPS reader
//! (`skylux_hps::fpga::frames`) all use these constants.
//!
//! ```text
//!  window_base ─► slot 0 ─┬─ +0   descriptor, 8 little-endian u32 (32 bytes)
//!                         ├─ +32  reserved (never written)
//!                         └─ +64  payload: the frame's 32-bit words (`words`), in emission order
//!                 slot 1 at window_base + slot_stride, ... slot COUNT-1, then slot 0 again
//! ```
//!
//! The payload is written first, in bursts, then the descriptor (one 4-beat burst), then
//! `dma.status.FRAME_DONE` and `sys.irq_status.FRAME_DONE` are raised. A slot is used only if
//! it lies wholly inside the window; a burst is issued only if it ends inside its slot.
//!
//! **Checksum**: the wrapping 32-bit sum of the payload words as they left the clock-domain
//! FIFO, computed before the DMA writes them. One 32-bit adder in hardware; it catches any lost,
//! duplicated, misplaced or corrupted beat except for exact cancellations, which is all a check
//! between two parts of the same chip needs (it is not a defence against an adversary).

/// Descriptor word 0: ASCII "SKF1" read as a little-endian u32. Identifies the format; a slot
/// the fabric never completed does not carry it (the reader clears it after consuming a frame).
pub const FORMAT_ID: u32 = u32::from_le_bytes(*b"SKF1");
/// Descriptor length in 32-bit words.
pub const WORDS: usize = 8;
/// Descriptor length in bytes.
pub const BYTES: u32 = 4 * WORDS as u32;
/// Offset of the payload from the start of a slot. The gap after the descriptor keeps the
/// payload on a 64-byte boundary (two Cortex-A9 cache lines) and leaves room for a longer
/// descriptor format.
pub const PAYLOAD_OFFSET_BYTES: u32 = 64;
/// Width of a DMA beat in bytes (the 64-bit f2sdram port, hardware-facts.md §3.2). Window base
/// and slot stride must be multiples of it.
pub const BEAT_BYTES: u32 = 8;
/// The smallest usable slot: the descriptor area and one payload beat.
pub const MIN_SLOT_BYTES: u32 = PAYLOAD_OFFSET_BYTES + BEAT_BYTES;

/// Word indices in the descriptor.
pub mod word {
    /// [`super::FORMAT_ID`].
    pub const FORMAT: usize = 0;
    /// Frame number (`tag_frame_number`, latched at FRAME_VALID's rise).
    pub const FRAME_NUMBER: usize = 1;
    /// Timestamp in system clocks, low and high halves (`tag_timestamp`).
    pub const TIMESTAMP_LO: usize = 2;
    pub const TIMESTAMP_HI: usize = 3;
    /// Exposure index in bits [2:0], [`super::RAW_MODE`] and the [`super::flag`] bits.
    pub const INFO: usize = 4;
    /// Pixels in the last line in bits [11:0], lines in bits [27:16] (both saturate at 4095).
    pub const GEOMETRY: usize = 5;
    /// Payload words delivered for the frame (written unless `TRUNCATED`).
    pub const PAYLOAD_WORDS: usize = 6;
    /// Wrapping sum of those words.
    pub const CHECKSUM: usize = 7;
}

/// Mask of the exposure index in [`word::INFO`].
pub const EXPOSURE_INDEX_MASK: u32 = 0x7;
/// [`word::INFO`]: the payload holds raw samples (`capture.ctrl.RAW`), not grouped words.
pub const RAW_MODE: u32 = 1 << 8;
/// [`word::INFO`]: the payload is an HDR map (`hdr.ctrl.ENABLE`, `crate::words::hdr_map`), the
/// set's frames up to this one merged; the checksum is the set's so far as
/// `crate::hdr_values::HdrConfig::map_checksum` defines it (the usable words).
pub const HDR_MAP: u32 = 1 << 9;
/// Position of the last line's pixel count in [`word::GEOMETRY`].
pub const PIXELS_LSB: u32 = 0;
/// Position of the line count in [`word::GEOMETRY`].
pub const LINES_LSB: u32 = 16;
/// Mask of one 12-bit count.
pub const COUNT_MASK: u32 = 0xFFF;

/// Frame flags in [`word::INFO`]. A frame with none set is complete and well-formed.
pub mod flag {
    /// Bit position of the first flag in the info word.
    pub const LSB: u32 = 16;
    /// A line ended before `capture.window.WIDTH` pixels.
    pub const LINE_SHORT: u32 = 1 << LSB;
    /// A line carried more than `capture.window.WIDTH` pixels (the extra ones are dropped).
    pub const LINE_LONG: u32 = 1 << (LSB + 1);
    /// The frame ended before `capture.window.HEIGHT` lines (or its end never arrived).
    pub const FRAME_SHORT: u32 = 1 << (LSB + 2);
    /// The frame carried more than `capture.window.HEIGHT` lines (the extra ones are dropped).
    pub const FRAME_LONG: u32 = 1 << (LSB + 3);
    /// The clock-domain FIFO was full: words of this frame were lost.
    pub const FIFO_OVERFLOW: u32 = 1 << (LSB + 4);
    /// PIXCLK stopped during the frame; the DMA closed it with what had arrived.
    pub const PIXCLK_STOPPED: u32 = 1 << (LSB + 5);
    /// The payload did not fit the slot: the bursts that would have left it were not issued.
    pub const TRUNCATED: u32 = 1 << (LSB + 6);
    /// The port held waitrequest longer than `dma.bus_timeout` during the frame.
    pub const BUS_TIMEOUT: u32 = 1 << (LSB + 7);
    /// At least one frame between the previous descriptor and this one was not captured
    /// (no room in the FIFO for it, or FRAME_VALID rose again within the capture's end latency).
    pub const FRAMES_SKIPPED: u32 = 1 << (LSB + 8);
    /// Every flag.
    pub const ALL: u32 = 0x1FF << LSB;
    /// Flags and their names, for reports.
    pub const NAMES: [(u32, &str); 9] = [
        (LINE_SHORT, "LINE_SHORT"),
        (LINE_LONG, "LINE_LONG"),
        (FRAME_SHORT, "FRAME_SHORT"),
        (FRAME_LONG, "FRAME_LONG"),
        (FIFO_OVERFLOW, "FIFO_OVERFLOW"),
        (PIXCLK_STOPPED, "PIXCLK_STOPPED"),
        (TRUNCATED, "TRUNCATED"),
        (BUS_TIMEOUT, "BUS_TIMEOUT"),
        (FRAMES_SKIPPED, "FRAMES_SKIPPED"),
    ];
}

/// A decoded descriptor.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Descriptor {
    pub frame_number: u32,
    pub timestamp_cycles: u64,
    pub exposure_index: u8,
    pub raw: bool,
    /// The payload is an HDR map ([`HDR_MAP`]).
    pub hdr_map: bool,
    /// [`flag`] bits, at their positions in the info word.
    pub flags: u32,
    pub last_line_pixels: u16,
    pub lines: u16,
    pub payload_words: u32,
    pub checksum: u32,
}

impl Descriptor {
    /// The descriptor's words as the fabric writes them.
    pub const fn encode(&self) -> [u32; WORDS] {
        [
            FORMAT_ID,
            self.frame_number,
            self.timestamp_cycles as u32,
            (self.timestamp_cycles >> 32) as u32,
            (self.exposure_index as u32 & EXPOSURE_INDEX_MASK)
                | if self.raw { RAW_MODE } else { 0 }
                | if self.hdr_map { HDR_MAP } else { 0 }
                | (self.flags & flag::ALL),
            ((self.last_line_pixels as u32 & COUNT_MASK) << PIXELS_LSB)
                | ((self.lines as u32 & COUNT_MASK) << LINES_LSB),
            self.payload_words,
            self.checksum,
        ]
    }

    /// Decodes descriptor words; `None` when word 0 is not [`FORMAT_ID`] (no frame there).
    pub const fn decode(words: &[u32; WORDS]) -> Option<Descriptor> {
        if words[word::FORMAT] != FORMAT_ID {
            return None;
        }
        let info = words[word::INFO];
        let geometry = words[word::GEOMETRY];
        Some(Descriptor {
            frame_number: words[word::FRAME_NUMBER],
            timestamp_cycles: (words[word::TIMESTAMP_HI] as u64) << 32
                | words[word::TIMESTAMP_LO] as u64,
            exposure_index: (info & EXPOSURE_INDEX_MASK) as u8,
            raw: info & RAW_MODE != 0,
            hdr_map: info & HDR_MAP != 0,
            flags: info & flag::ALL,
            last_line_pixels: ((geometry >> PIXELS_LSB) & COUNT_MASK) as u16,
            lines: ((geometry >> LINES_LSB) & COUNT_MASK) as u16,
            payload_words: words[word::PAYLOAD_WORDS],
            checksum: words[word::CHECKSUM],
        })
    }

    /// Whether the frame is complete and well-formed (no flag set).
    pub const fn is_clean(&self) -> bool {
        self.flags == 0
    }
}

/// The checksum of a payload: the wrapping sum of its words.
pub fn checksum(words: &[u32]) -> u32 {
    words.iter().fold(0u32, |s, &w| s.wrapping_add(w))
}

/// Payload capacity of a slot of `stride_bytes`, in 32-bit words (0 if it is too small).
pub const fn payload_capacity_words(stride_bytes: u32) -> u32 {
    if stride_bytes < PAYLOAD_OFFSET_BYTES {
        0
    } else {
        (stride_bytes - PAYLOAD_OFFSET_BYTES) / 4
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip() {
        let d = Descriptor {
            frame_number: 0xDEAD_0001,
            timestamp_cycles: 0x0123_4567_89AB_CDEF,
            exposure_index: 5,
            raw: true,
            hdr_map: true,
            flags: flag::LINE_SHORT | flag::FRAMES_SKIPPED,
            last_line_pixels: 2592,
            lines: 1944,
            payload_words: 1_259_712,
            checksum: 0xCAFE_F00D,
        };
        let w = d.encode();
        assert_eq!(w[0].to_le_bytes(), *b"SKF1");
        assert_eq!(Descriptor::decode(&w), Some(d));
        assert!(!d.is_clean());
        let mut other = w;
        other[0] ^= 1;
        assert_eq!(Descriptor::decode(&other), None);
    }

    #[test]
    fn flags_are_distinct_and_inside_all() {
        let mut seen = 0;
        for (f, _) in flag::NAMES {
            assert_eq!(f.count_ones(), 1);
            assert_eq!(seen & f, 0);
            seen |= f;
        }
        assert_eq!(seen, flag::ALL);
        assert_eq!(flag::ALL & (RAW_MODE | EXPOSURE_INDEX_MASK), 0);
    }

    #[test]
    fn checksum_wraps() {
        assert_eq!(checksum(&[u32::MAX, 2]), 1);
        assert_eq!(payload_capacity_words(PAYLOAD_OFFSET_BYTES - 1), 0);
        assert_eq!(payload_capacity_words(MIN_SLOT_BYTES), 2);
    }
}
