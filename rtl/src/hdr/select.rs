//! The HDR selection: per grouped word taken by the DMA, the map word and whether to write it
//! ([`super::golden`] is the specification).

use rust_hdl::prelude::*;

/// Bits of a group's position: 2^21 covers the full 1296 x 972 groups of the MT9P031's
/// 2592 x 1944 array (1,259,712; hardware-facts.md §1).
pub const MASK_ADDRESS_BITS: usize = 21;
/// The mask is two block RAMs, 2^20 + 2^18 = 1,310,720 bits, since one of 2^21 would spend
/// 96 M10K on positions no frame has (`golden::mask_slot` places a position).
pub const MASK_LOW_BITS: usize = 20;
pub const MASK_HIGH_BITS: usize = 18;

/// The filled mask and the map word, with no latency: the outputs describe the word at the
/// head of the DMA's FIFO, so the ingest puts them into the beat it pushes when it takes it.
///
/// The mask's block RAM reads synchronously, so it is addressed one cycle ahead with the
/// position of the next head word: 0 after `restart`, the current one plus `take` otherwise.
/// A taken word writes its bit (filled already, or usable now; only usable now in a set's
/// first frame) in the same edge that reads the next position, never the same address.
/// Protocol: `restart` (a frame opens) never comes with `take`, and a frame's first word is
/// taken at the earliest the cycle after `restart`.
#[derive(LogicBlock, Default)]
pub struct HdrSelect {
    pub clock: Signal<In, Clock>,
    /// A frame opens: its first word is group 0. Samples `first_of_set` and `exposure_index`.
    pub restart: Signal<In, Bit>,
    /// The opening frame is a set's first (the longest exposure): the mask's old bits are
    /// not read.
    pub first_of_set: Signal<In, Bit>,
    /// The opening frame's place in its set (the map words' exposure field).
    pub exposure_index: Signal<In, Bits<3>>,
    /// The head word (a grouped word, `skylux_regmap::words::grouped`) is taken this cycle.
    pub take: Signal<In, Bit>,
    pub word: Signal<In, Bits<32>>,
    /// Usable range of the luminance in the map word's units, 2^-11 DN, inclusive (`hdr.min`,
    /// `hdr.max`).
    pub min_q11: Signal<In, Bits<27>>,
    pub max_q11: Signal<In, Bits<27>>,
    /// The head word as a map word (`skylux_regmap::words::hdr_map`).
    pub map_word: Signal<Out, Bits<32>>,
    /// With `take`: write the word, its group is not filled yet. Low without `take` (so the
    /// mask's power-up contents, undefined in Verilog, never reach it between frames).
    pub map_write: Signal<Out, Bit>,
    /// With `take`: the word written is usable, so the map keeps it for good (what the set's
    /// checksum sums: `HdrConfig::map_checksum`).
    pub map_settles: Signal<Out, Bit>,

    mask_low: RAM<Bit, MASK_LOW_BITS>,
    mask_high: RAM<Bit, MASK_HIGH_BITS>,
    pos: DFF<Bits<MASK_ADDRESS_BITS>>,
    set_first: DFF<Bit>,
    index: DFF<Bits<3>>,

    next_pos: Signal<Local, Bits<MASK_ADDRESS_BITS>>,
    luma: Signal<Local, Bits<27>>,
    usable: Signal<Local, Bit>,
    filled: Signal<Local, Bit>,
}

impl Logic for HdrSelect {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, pos, set_first, index);
        self.mask_low.read_clock.next = self.clock.val();
        self.mask_low.write_clock.next = self.clock.val();
        self.mask_high.read_clock.next = self.clock.val();
        self.mask_high.write_clock.next = self.clock.val();

        // ---- where the next head word lies ----------------------------------------------
        self.next_pos.next = self.pos.q.val();
        if self.take.val() {
            self.next_pos.next = self.pos.q.val() + 1;
        }
        if self.restart.val() {
            self.next_pos.next = 0.into();
            self.set_first.d.next = self.first_of_set.val();
            self.index.d.next = self.exposure_index.val();
        }
        self.pos.d.next = self.next_pos.val();
        // Positions below 2^20 in the low RAM, the others in the high one.
        self.mask_low.read_address.next = self.next_pos.val().get_bits::<20>(0);
        self.mask_high.read_address.next = self.next_pos.val().get_bits::<18>(0);

        // ---- the head word --------------------------------------------------------------
        self.luma.next = self.word.val().get_bits::<27>(3);
        self.usable.next = !self.word.val().get_bit(31)
            & !self.word.val().get_bit(30)
            & (self.luma.val() >= self.min_q11.val())
            & (self.luma.val() <= self.max_q11.val());
        self.filled.next = false;
        if !self.set_first.q.val() {
            // The RAMs read at the edge that made `pos` this position.
            if self.pos.q.val().get_bit(20) {
                self.filled.next = self.mask_high.read_data.val();
            } else {
                self.filled.next = self.mask_low.read_data.val();
            }
        }
        self.mask_low.write_address.next = self.pos.q.val().get_bits::<20>(0);
        self.mask_high.write_address.next = self.pos.q.val().get_bits::<18>(0);
        self.mask_low.write_data.next = self.filled.val() | self.usable.val();
        self.mask_high.write_data.next = self.filled.val() | self.usable.val();
        self.mask_low.write_enable.next = self.take.val() & !self.pos.q.val().get_bit(20);
        self.mask_high.write_enable.next = self.take.val() & self.pos.q.val().get_bit(20);

        // Flags, exposure index at bits 29..27, the luminance's Q16.11 below.
        self.map_word.next = (bit_cast::<32, 2>(self.word.val().get_bits::<2>(30)) << 30)
            | (bit_cast::<32, 3>(self.index.q.val()) << 27)
            | bit_cast::<32, 27>(self.luma.val());
        self.map_write.next = self.take.val() & !self.filled.val();
        self.map_settles.next = self.take.val() & !self.filled.val() & self.usable.val();
    }
}
