//! The frame DMA (`dma.*`, `skylux_rtl::dma::BurstWriter`) per frame: the slot is checked
//! against the window (`OUT_OF_WINDOW`: nothing written, the ring does not advance), the
//! payload is written (cut at the slot's end: `TRUNCATED`), then the descriptor of
//! `skylux_regmap::descriptor` with the checksum the ingest took before the port, then
//! `FRAME_DONE`, `dma.frames_written` and the ring advances. Needed so the ring, the
//! descriptors and the counters `FabricSource` and `PollWait` read are the hardware's.
//!
//! **Map frames** (`hdr.ctrl.ENABLE` in grouped mode, `skylux_rtl::hdr`, docs/hdr-fabric.md):
//! each grouped word goes out as its map word, and only the groups not yet filled in the set
//! are written (the byte enables), as the RTL's golden model
//! [`skylux_rtl::hdr::golden::FilledMask`] decides; the descriptor marks the map and carries
//! the set's checksum so far (the sum of the words that settled, written and usable).

use super::FabricModel;
use skylux_regmap::descriptor::{self, flag, Descriptor};
use skylux_regmap::{dma, sys};
use skylux_rtl::dma::{DESCRIPTOR_BEATS, MAX_BURST_BEATS};
use skylux_rtl::hdr::golden::{FilledMask, HdrConfig, SetFrame};

/// A frame the ingest closed, on its way to memory.
#[derive(Clone, Debug)]
pub struct FrameOut {
    /// The words that left the FIFO (the checksum's).
    pub words: Vec<u32>,
    pub flags: u32,
    pub last_pixels: u32,
    pub lines: u32,
    pub raw: bool,
    /// A map frame: its place in the set and the thresholds, latched when it opened.
    pub map: Option<MapFrame>,
    /// The sun accumulators take its words (`super::sun`).
    pub sun_armed: bool,
    pub tag_index: u32,
    pub tag_frame: u32,
    pub tag_time: u64,
    /// System clocks from the frame's end to its last payload beat.
    pub ready_after: u64,
    /// Injected: one word corrupted on the port.
    pub corrupt: Option<(u32, u32)>,
    /// Injected: this frame and the next swap slots.
    pub swap: bool,
    pub bus_timeout: bool,
}

/// What a map frame carries from its opening (the ingest samples `hdr.*` there).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MapFrame {
    /// The set's first frame: the mask's old bits do not count.
    pub first_of_set: bool,
    /// The frame's place in its set (0 to 7, saturating), the map words' exposure field.
    pub exposure_index: u8,
    pub thresholds: HdrConfig,
}

/// The HDR selection's state across frames (`hdr.*`): the filled mask (block RAM, kept
/// across frames) and the set's frame count.
#[derive(Clone, Debug, Default)]
pub struct HdrState {
    /// `hdr.ctrl.NEW_SET` was pulsed: the next map frame begins a set.
    pub new_set_pending: bool,
    /// The last map frame's place in its set.
    pub ordinal: u8,
    pub mask: FilledMask,
    /// The set's checksum so far (`HdrConfig::map_checksum` of the words that settled).
    pub set_sum: u32,
}

impl HdrState {
    /// A map frame opens: its place in the set (0 after `NEW_SET`, then one up to 7).
    pub fn open(&mut self, thresholds: HdrConfig) -> MapFrame {
        let first_of_set = std::mem::take(&mut self.new_set_pending);
        self.ordinal = if first_of_set {
            0
        } else {
            (self.ordinal + 1).min(7)
        };
        MapFrame {
            first_of_set,
            exposure_index: self.ordinal,
            thresholds,
        }
    }
}

/// A frame being written.
#[derive(Clone, Debug)]
pub struct DmaJob {
    pub done_at: u64,
    pub frame: FrameOut,
}

/// The engine's state.
#[derive(Clone, Debug, Default)]
pub struct DmaEngine {
    /// Frames closed by the ingest, in order (a frame whose start marker found the writer
    /// busy waits behind the one being written, as its marker waits in the FIFO).
    pub jobs: std::collections::VecDeque<DmaJob>,
    /// Slot being written, or next to be written.
    pub slot: u8,
    /// `dma.frames_written`.
    pub frames_written: u32,
    /// `dma.ctrl.RESET` arrived during a frame: taken after it.
    restart_pending: bool,
    /// Injected slot swap: the slot the next frame goes to instead.
    swap_back: Option<u8>,
    /// `hdr.*`: the filled mask and the set's count.
    pub hdr: HdrState,
}

impl DmaEngine {
    pub fn next_event(&self) -> Option<u64> {
        self.jobs.front().map(|j| j.done_at)
    }
}

impl FabricModel {
    /// The ingest hands a frame over; it is in memory after its last bursts and the
    /// descriptor.
    pub(super) fn dma_frame(&mut self, frame: FrameOut) {
        // The accumulators sit beside the ingest: by the frame's end they hold its sums.
        if frame.sun_armed {
            self.sun_frame(&frame.words);
        }
        // The remainder burst (at most MAX_BURST_BEATS) and the descriptor burst.
        let beats = (frame.words.len() as u64).div_ceil(2).min(MAX_BURST_BEATS);
        let mut done_at = self.now + frame.ready_after + beats + DESCRIPTOR_BEATS + 2;
        if let Some(last) = self.dma.jobs.back() {
            done_at = done_at.max(last.done_at + beats + DESCRIPTOR_BEATS);
        }
        self.dma.jobs.push_back(DmaJob { done_at, frame });
    }

    /// `dma.ctrl.RESET`.
    pub(super) fn dma_restart(&mut self) {
        if !self.dma.jobs.is_empty() {
            self.dma.restart_pending = true;
        } else {
            self.dma.slot = 0;
            self.dma.swap_back = None;
        }
    }

    /// Writes `data` at physical `address`; bytes outside the modelled buffer are dropped
    /// (and counted).
    fn memory_write(&mut self, address: u64, data: &[u8]) {
        let base = self.config.memory_base;
        let len = self.memory.len() as u64;
        match address.checked_sub(base) {
            Some(o) if o + data.len() as u64 <= len => {
                let o = o as usize;
                self.memory[o..o + data.len()].copy_from_slice(data);
            }
            _ => self.log.memory_misses += data.len() as u64,
        }
    }

    pub(super) fn dma_events(&mut self) {
        if self.dma.jobs.front().is_none_or(|j| j.done_at > self.now) {
            return;
        }
        let Some(job) = self.dma.jobs.pop_front() else {
            return;
        };
        let f = job.frame;
        let base = u64::from(self.stored(dma::window_base::REG.offset));
        let size = u64::from(self.stored(dma::window_size::REG.offset));
        let stride = u64::from(self.stored(dma::slot_stride::REG.offset));
        let slots = dma::slots::COUNT
            .get(self.stored(dma::slots::REG.offset))
            .max(1) as u8;
        let mut slot = self.dma.slot % slots;
        let mut next = (slot + 1) % slots;
        if let Some(back) = self.dma.swap_back.take() {
            slot = back % slots;
            next = (back + 2) % slots;
        } else if f.swap && slots > 1 {
            self.dma.swap_back = Some(slot);
            slot = next;
        }
        let start = base + u64::from(slot) * stride;
        let usable = base % 8 == 0
            && stride % 8 == 0
            && stride >= u64::from(descriptor::MIN_SLOT_BYTES)
            && start + stride <= base + size
            && base + size <= 1 << 32;
        if !usable {
            self.regs
                .set_bits(dma::status::REG.offset, dma::status::OUT_OF_WINDOW.mask());
            self.irq(&sys::irq_status::DMA_ERROR);
            self.dma.swap_back = None;
            return;
        }
        // Beats of two words: an odd count is padded with a zero word. A map frame's words
        // are the map words, each with whether its group is written (its byte enables).
        let mut payload: Vec<(u32, bool)> = match &f.map {
            Some(m) => {
                let writes = self.dma.hdr.mask.frame(
                    &m.thresholds,
                    &SetFrame {
                        exposure_index: m.exposure_index,
                        first_of_set: m.first_of_set,
                        words: &f.words,
                    },
                );
                let hdr = &mut self.dma.hdr;
                if m.first_of_set {
                    hdr.set_sum = 0;
                }
                for &(word, write) in &writes {
                    if write && m.thresholds.usable_map_word(word) {
                        hdr.set_sum = hdr.set_sum.wrapping_add(word);
                    }
                }
                writes
            }
            None => f.words.iter().map(|&w| (w, true)).collect(),
        };
        if payload.len() % 2 == 1 {
            payload.push((0, true));
        }
        if let Some((i, xor)) = f.corrupt {
            if let Some(w) = payload.get_mut(i as usize) {
                w.0 ^= xor;
            }
        }
        let capacity_words = 2 * ((stride - u64::from(descriptor::PAYLOAD_OFFSET_BYTES)) / 8);
        let mut flags = f.flags;
        if payload.len() as u64 > capacity_words {
            flags |= flag::TRUNCATED;
            payload.truncate(capacity_words as usize);
        }
        let payload_at = start + u64::from(descriptor::PAYLOAD_OFFSET_BYTES);
        if payload.iter().all(|&(_, write)| write) {
            let bytes: Vec<u8> = payload.iter().flat_map(|w| w.0.to_le_bytes()).collect();
            self.memory_write(payload_at, &bytes);
        } else {
            for (i, &(word, write)) in payload.iter().enumerate() {
                if write {
                    self.memory_write(payload_at + 4 * i as u64, &word.to_le_bytes());
                }
            }
        }
        let d = Descriptor {
            frame_number: f.tag_frame,
            timestamp_cycles: f.tag_time,
            exposure_index: (f.tag_index & descriptor::EXPOSURE_INDEX_MASK) as u8,
            raw: f.raw,
            hdr_map: f.map.is_some(),
            flags,
            last_line_pixels: f.last_pixels as u16,
            lines: f.lines as u16,
            payload_words: f.words.len() as u32,
            checksum: match f.map {
                Some(_) => self.dma.hdr.set_sum,
                None => descriptor::checksum(&f.words),
            },
        };
        let bytes: Vec<u8> = d.encode().iter().flat_map(|w| w.to_le_bytes()).collect();
        self.memory_write(start, &bytes);
        if f.bus_timeout {
            self.regs
                .set_bits(dma::status::REG.offset, dma::status::BUS_TIMEOUT.mask());
            self.irq(&sys::irq_status::DMA_ERROR);
        }
        self.regs
            .set_bits(dma::status::REG.offset, dma::status::FRAME_DONE.mask());
        self.irq(&sys::irq_status::FRAME_DONE);
        self.dma.frames_written = self.dma.frames_written.wrapping_add(1);
        self.dma.slot = next;
        if std::mem::take(&mut self.dma.restart_pending) {
            self.dma.slot = 0;
            self.dma.swap_back = None;
        }
    }

    pub(super) fn dma_inputs(&mut self) {
        let busy =
            !self.dma.jobs.is_empty() || self.capture.current.as_ref().is_some_and(|c| c.dma_taken);
        let status =
            dma::status::BUSY.word(busy.into()) | dma::status::SLOT.word(self.dma.slot.into());
        self.regs
            .fabric_inputs
            .insert(dma::status::REG.offset, status);
        self.regs
            .fabric_inputs
            .insert(dma::frames_written::REG.offset, self.dma.frames_written);
    }
}
