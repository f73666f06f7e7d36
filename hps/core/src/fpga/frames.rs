//! Frames the fabric's DMA wrote: descriptors and payloads read back from the DMA buffer
//! (`skylux_bus::DmaMemory`), checked against their checksum and flags. The slot and
//! descriptor format is `skylux_regmap::descriptor`.

use skylux_bus::{BusError, DmaMemory};
use skylux_regmap::descriptor::{self, flag, Descriptor};

/// Where the ring sits in the DMA buffer, as programmed into `dma.window_base`,
/// `dma.slot_stride` and `dma.slots`.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct RingLayout {
    /// Physical address of slot 0 (`dma.window_base`).
    pub window_base: u64,
    pub slot_stride_bytes: u32,
    pub slots: u8,
}

/// Why a slot could not be read.
#[derive(Debug, thiserror::Error)]
pub enum FrameError {
    #[error("slot {slot}: the ring has {slots} slots")]
    NoSuchSlot { slot: u8, slots: u8 },
    #[error("dma.slot_stride = {stride} bytes: below the {min}-byte minimum slot")]
    StrideTooSmall { stride: u32, min: u32 },
    #[error("slot {slot} at {address:#x} lies outside the DMA buffer ({base:#x}, {len:#x} bytes)")]
    OutsideBuffer {
        slot: u8,
        address: u64,
        base: u64,
        len: u64,
    },
    #[error("slot {slot}: descriptor claims {words} payload words, the slot holds {capacity} (and it is not flagged TRUNCATED)")]
    PayloadTooLong { slot: u8, words: u32, capacity: u32 },
    #[error(transparent)]
    Bus(#[from] BusError),
}

/// A frame read back from its slot.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CapturedFrame {
    pub slot: u8,
    pub descriptor: Descriptor,
    /// The payload words in memory (all `payload_words` of them, or what fits the slot when
    /// the frame is `TRUNCATED`).
    pub words: Vec<u32>,
}

impl CapturedFrame {
    /// Whether the payload's sum equals the descriptor's checksum. `None` when the payload is
    /// incomplete in memory (`TRUNCATED`), or an HDR map (whose checksum sums its usable words
    /// only: [`CapturedFrame::map_checksum_ok`]).
    pub fn checksum_ok(&self) -> Option<bool> {
        if self.descriptor.flags & flag::TRUNCATED != 0 || self.descriptor.hdr_map {
            return None;
        }
        // A9 cost (timing::a9::ring::CHECKSUM_PER_WORD): `ldr`, `subs`, `add`, `bne` a word,
        // memory-bound on the board (4n bytes streamed from the DDR3).
        Some(descriptor::checksum(&self.words) == self.descriptor.checksum)
    }

    /// For an HDR map, whether the descriptor's checksum is the sum of the map's usable words
    /// under `hdr`, the thresholds the set ran with (`HdrConfig::map_checksum`). `None` when
    /// the payload is incomplete in memory or not a map.
    pub fn map_checksum_ok(&self, hdr: &skylux_regmap::hdr_values::HdrConfig) -> Option<bool> {
        if self.descriptor.flags & flag::TRUNCATED != 0 || !self.descriptor.hdr_map {
            return None;
        }
        Some(hdr.map_checksum(&self.words) == self.descriptor.checksum)
    }

    /// Whether the frame can be used as is: no flag, and the checksum matches.
    pub fn is_good(&self) -> bool {
        self.descriptor.is_clean() && self.checksum_ok() == Some(true)
    }

    /// The names of the flags set, for reports.
    pub fn flag_names(&self) -> Vec<&'static str> {
        flag::NAMES
            .iter()
            .filter(|(f, _)| self.descriptor.flags & f != 0)
            .map(|(_, n)| *n)
            .collect()
    }
}

impl RingLayout {
    /// Byte offset of `slot` in `memory`, checked against the buffer.
    fn slot_offset<M: DmaMemory + ?Sized>(&self, memory: &M, slot: u8) -> Result<u64, FrameError> {
        if slot >= self.slots.max(1) {
            return Err(FrameError::NoSuchSlot {
                slot,
                slots: self.slots,
            });
        }
        if self.slot_stride_bytes < descriptor::MIN_SLOT_BYTES {
            return Err(FrameError::StrideTooSmall {
                stride: self.slot_stride_bytes,
                min: descriptor::MIN_SLOT_BYTES,
            });
        }
        let address = self
            .window_base
            .saturating_add(u64::from(slot) * u64::from(self.slot_stride_bytes));
        let outside = FrameError::OutsideBuffer {
            slot,
            address,
            base: memory.phys_base(),
            len: memory.len_bytes(),
        };
        let Some(offset) = address.checked_sub(memory.phys_base()) else {
            return Err(outside);
        };
        if offset.saturating_add(u64::from(self.slot_stride_bytes)) > memory.len_bytes() {
            return Err(outside);
        }
        Ok(offset)
    }

    /// Reads `slot`: `None` when it holds no completed frame (no format identifier).
    pub fn read_slot<M: DmaMemory + ?Sized>(
        &self,
        memory: &mut M,
        slot: u8,
    ) -> Result<Option<CapturedFrame>, FrameError> {
        let offset = self.slot_offset(memory, slot)?;
        let mut raw = [0u8; descriptor::BYTES as usize];
        memory.read_bytes(offset, &mut raw)?;
        let mut words = [0u32; descriptor::WORDS];
        for (w, b) in words.iter_mut().zip(raw.chunks_exact(4)) {
            *w = u32::from_le_bytes([b[0], b[1], b[2], b[3]]);
        }
        let Some(d) = Descriptor::decode(&words) else {
            return Ok(None);
        };
        let capacity = descriptor::payload_capacity_words(self.slot_stride_bytes);
        if d.payload_words > capacity && d.flags & flag::TRUNCATED == 0 {
            return Err(FrameError::PayloadTooLong {
                slot,
                words: d.payload_words,
                capacity,
            });
        }
        let n = d.payload_words.min(capacity) as usize;
        // A9 cost (timing::a9::hps_read): one pass reading the words in place out of the
        // ring, which on the board is the DMA mapping (uncached: 4n bytes at about 64 MB/s,
        // 157 ms for a raw full frame; or cached after the range's invalidation).
        let mut words = Vec::with_capacity(n);
        memory.read_words_le(
            offset + u64::from(descriptor::PAYLOAD_OFFSET_BYTES),
            n,
            &mut words,
        )?;
        Ok(Some(CapturedFrame {
            slot,
            descriptor: d,
            words,
        }))
    }

    /// Marks `slot` consumed (clears its format identifier), so a stale frame is never read
    /// twice.
    pub fn release_slot<M: DmaMemory + ?Sized>(
        &self,
        memory: &mut M,
        slot: u8,
    ) -> Result<(), FrameError> {
        let offset = self.slot_offset(memory, slot)?;
        memory.write_bytes(offset, &[0; 4])?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A plain in-memory DMA buffer.
    struct Buffer {
        base: u64,
        bytes: Vec<u8>,
    }
    impl DmaMemory for Buffer {
        fn phys_base(&self) -> u64 {
            self.base
        }
        fn len_bytes(&self) -> u64 {
            self.bytes.len() as u64
        }
        fn read_bytes(&mut self, offset: u64, buf: &mut [u8]) -> Result<(), BusError> {
            skylux_bus::check_access(offset, buf.len() as u64, self.len_bytes(), 1)?;
            buf.copy_from_slice(&self.bytes[offset as usize..offset as usize + buf.len()]);
            Ok(())
        }
        fn write_bytes(&mut self, offset: u64, data: &[u8]) -> Result<(), BusError> {
            skylux_bus::check_access(offset, data.len() as u64, self.len_bytes(), 1)?;
            self.bytes[offset as usize..offset as usize + data.len()].copy_from_slice(data);
            Ok(())
        }
    }

    fn put_frame(buf: &mut Buffer, offset: usize, d: &Descriptor, payload: &[u32]) {
        for (i, w) in d.encode().iter().enumerate() {
            buf.bytes[offset + 4 * i..offset + 4 * i + 4].copy_from_slice(&w.to_le_bytes());
        }
        let p = offset + descriptor::PAYLOAD_OFFSET_BYTES as usize;
        for (i, w) in payload.iter().enumerate() {
            buf.bytes[p + 4 * i..p + 4 * i + 4].copy_from_slice(&w.to_le_bytes());
        }
    }

    fn descriptor(payload: &[u32], flags: u32) -> Descriptor {
        Descriptor {
            frame_number: 9,
            timestamp_cycles: 1234,
            exposure_index: 2,
            raw: false,
            hdr_map: false,
            flags,
            last_line_pixels: 8,
            lines: 4,
            payload_words: payload.len() as u32,
            checksum: descriptor::checksum(payload),
        }
    }

    #[test]
    fn reads_checks_and_releases_frames() {
        let ring = RingLayout {
            window_base: 0x1000,
            slot_stride_bytes: 128,
            slots: 2,
        };
        let mut buf = Buffer {
            base: 0x1000,
            bytes: vec![0; 256],
        };
        let payload = [1u32, 2, 3, 0xFFFF_FFFF];
        put_frame(&mut buf, 128, &descriptor(&payload, 0), &payload);
        assert_eq!(ring.read_slot(&mut buf, 0).unwrap(), None);
        let f = ring.read_slot(&mut buf, 1).unwrap().unwrap();
        assert_eq!(f.words, payload);
        assert!(f.is_good());
        // One corrupted payload word is caught.
        buf.bytes[128 + 64] ^= 4;
        let f = ring.read_slot(&mut buf, 1).unwrap().unwrap();
        assert_eq!(f.checksum_ok(), Some(false));
        assert!(!f.is_good());
        ring.release_slot(&mut buf, 1).unwrap();
        assert_eq!(ring.read_slot(&mut buf, 1).unwrap(), None);
        assert!(matches!(
            ring.read_slot(&mut buf, 2),
            Err(FrameError::NoSuchSlot { .. })
        ));
    }

    #[test]
    fn bad_layouts_and_descriptors_are_errors_not_panics() {
        let mut buf = Buffer {
            base: 0x1000,
            bytes: vec![0; 256],
        };
        let payload = [7u32; 20];
        put_frame(&mut buf, 0, &descriptor(&payload, 0), &[]);
        let small = RingLayout {
            window_base: 0x1000,
            slot_stride_bytes: 96,
            slots: 1,
        };
        assert!(matches!(
            small.read_slot(&mut buf, 0),
            Err(FrameError::PayloadTooLong { capacity: 8, .. })
        ));
        put_frame(&mut buf, 0, &descriptor(&payload, flag::TRUNCATED), &[]);
        let f = small.read_slot(&mut buf, 0).unwrap().unwrap();
        assert_eq!((f.words.len(), f.checksum_ok()), (8, None));
        assert_eq!(f.flag_names(), vec!["TRUNCATED"]);
        for bad in [
            RingLayout {
                window_base: 0x800,
                slot_stride_bytes: 128,
                slots: 1,
            },
            RingLayout {
                window_base: 0x1000,
                slot_stride_bytes: 1 << 20,
                slots: 1,
            },
            RingLayout {
                window_base: 0x1000,
                slot_stride_bytes: 8,
                slots: 1,
            },
        ] {
            assert!(bad.read_slot(&mut buf, 0).is_err(), "{bad:?}");
        }
    }
}
