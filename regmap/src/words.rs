//! The data words the fabric writes to memory: a hardware/software contract like the register
//! map, so it is written here once and both the RTL (`skylux_rtl::bayer`) and the HPS read it.
//!
//! The Bayer grouping block (`bayer.*` registers) emits 32-bit words in one of two modes:
//!
//! - **Grouped** ([`grouped`]): one word per 2x2 Bayer block, the weighted luminance
//!   `w_r R + w_g (G1 + G2) / 2 + w_b B` of the black-subtracted samples, with an under-range and
//!   an over-range flag.
//! - **Raw** ([`raw`], for calibration): the samples unchanged, two per word.
//!
//! In HDR map mode (`hdr.*`) the DMA writes [`hdr_map`] words instead: one per group over a
//! whole set of exposures.
//!
//! Words leave the block in emission order (below) and the DMA stores them at increasing
//! addresses, so two consecutive words form one little-endian 64-bit beat: the earlier word in
//! bits [31:0].

/// Width of a sensor sample (MT9P031 D[11:0], hardware-facts.md §1.2).
pub const SAMPLE_BITS: u32 = 12;
/// Largest sample value.
pub const SAMPLE_MAX: u32 = (1 << SAMPLE_BITS) - 1;
/// Fractional bits of the colour weights (`bayer.weight_*`, unsigned Q2.14).
pub const WEIGHT_FRAC_BITS: u32 = 14;
/// The weight 1.0 in Q2.14.
pub const WEIGHT_ONE: u32 = 1 << WEIGHT_FRAC_BITS;
/// Largest weight (just below 4.0).
pub const WEIGHT_MAX: u32 = 0xFFFF;

/// Grouped mode: one word per 2x2 block.
///
/// ```text
///  31    30    29                                  0
/// +----+-----+-------------------------------------+
/// |OVER|UNDER|  luminance, unsigned Q16.14         |
/// +----+-----+-------------------------------------+
/// ```
///
/// - Luminance: `w_r R' + w_g (G1' + G2') / 2 + w_b B'` where `X' = max(X - black, 0)` (the
///   black level is subtracted with saturation at zero) and the weights are Q2.14. The exact
///   value is a multiple of 2^-15 (the halving of the green sum adds one bit); the word keeps
///   14 fractional bits and **truncates** (rounds toward zero) the last one. The largest value,
///   4095 x 3 x 0xFFFF / 2^14 < 49140, needs 16 integer bits, so 30 bits in all and nothing
///   valid can overflow (checked at compile time below).
/// - UNDER: at least one of the four samples, before black subtraction, is below
///   `bayer.valid.MIN`.
/// - OVER: at least one of the four samples, before black subtraction, is above
///   `bayer.valid.MAX`.
///
/// The two flags are separate because the HDR merge treats them differently (an over-range
/// block says "take a shorter exposure", an under-range one "a longer one"). A block is valid
/// when neither is set. The luminance is written whatever the flags say; software decides.
///
/// Emission order: blocks of one row pair left to right, row pairs top to bottom, so a frame
/// of `W x H` samples gives [`grouped::words_per_frame`]`(W, H)` = `(W/2)(H/2)` words. The
/// colour of each sample position comes from `bayer.mode.PHASE` (the colours of the top-left,
/// top-right, bottom-left and bottom-right samples: 0 GRBG, 1 RGGB, 2 BGGR, 3 GBRG).
pub mod grouped {
    /// Fractional bits of the luminance.
    pub const LUMA_FRAC_BITS: u32 = super::WEIGHT_FRAC_BITS;
    /// Position of the luminance's least-significant bit.
    pub const LUMA_LSB: u32 = 0;
    /// Width of the luminance field.
    pub const LUMA_WIDTH: u32 = 30;
    /// Mask of the luminance field.
    pub const LUMA_MASK: u32 = ((1 << LUMA_WIDTH) - 1) << LUMA_LSB;
    /// Bit set when a sample of the block is below `bayer.valid.MIN`.
    pub const UNDER_BIT: u32 = 30;
    /// Bit set when a sample of the block is above `bayer.valid.MAX`.
    pub const OVER_BIT: u32 = 31;
    /// Mask of [`UNDER_BIT`].
    pub const UNDER: u32 = 1 << UNDER_BIT;
    /// Mask of [`OVER_BIT`].
    pub const OVER: u32 = 1 << OVER_BIT;

    /// The largest luminance any input can produce, in units of 2^-14: three 12-bit samples
    /// at full scale, all weights at their maximum (G1 + G2 halved counts as one sample).
    pub const LUMA_MAX_Q14: u64 = (super::SAMPLE_MAX as u64) * 3 * (super::WEIGHT_MAX as u64);

    // No valid input may overflow into the flags.
    const _: () = assert!(LUMA_MAX_Q14 < (1u64 << LUMA_WIDTH));
    const _: () = assert!(LUMA_LSB + LUMA_WIDTH <= UNDER_BIT && UNDER_BIT < OVER_BIT);

    /// Packs a grouped word. `luma_q14` is truncated to the field's width.
    pub const fn pack(luma_q14: u32, under: bool, over: bool) -> u32 {
        ((luma_q14 << LUMA_LSB) & LUMA_MASK)
            | if under { UNDER } else { 0 }
            | if over { OVER } else { 0 }
    }
    /// The luminance of a grouped word, in units of 2^-14.
    pub const fn luma_q14(word: u32) -> u32 {
        (word & LUMA_MASK) >> LUMA_LSB
    }
    /// The luminance of a grouped word in digital numbers (sensor units, after weighting).
    pub fn luma(word: u32) -> f64 {
        luma_q14(word) as f64 / (1u32 << LUMA_FRAC_BITS) as f64
    }
    /// Whether a sample of the block was below `bayer.valid.MIN`.
    pub const fn under(word: u32) -> bool {
        word & UNDER != 0
    }
    /// Whether a sample of the block was above `bayer.valid.MAX`.
    pub const fn over(word: u32) -> bool {
        word & OVER != 0
    }
    /// Whether all four samples of the block were inside the valid range.
    pub const fn valid(word: u32) -> bool {
        word & (UNDER | OVER) == 0
    }
    /// Words the block emits for a frame of `width x height` samples (both even).
    pub const fn words_per_frame(width: u32, height: u32) -> u32 {
        (width / 2) * (height / 2)
    }
}

/// The fabric's HDR map (issue 22 item 1, registers `hdr.*`): one word per 2x2 group, written
/// over the exposures of a set into one buffer. Each group holds the grouped word of the
/// longest exposure in which it was usable (exposures run long to short), or, if none was, the
/// set's last exposure's word with its flags; the word says which exposure it came from.
///
/// ```text
///  31    30    29    27 26                          0
/// +----+-----+--------+-----------------------------+
/// |OVER|UNDER|EXPOSURE|  luminance, unsigned Q16.11  |
/// +----+-----+--------+-----------------------------+
/// ```
///
/// - Luminance: the grouped word's Q16.14 field shifted right by [`hdr_map::DROPPED_FRAC_BITS`]
///   (truncated). The integer part is whole (16 bits hold [`grouped::LUMA_MAX_Q14`]); the
///   2^-11 DN step is below 1e-4 of the smallest usable signal (`bayer.valid.MIN` minus
///   black, tens of DN), so dropping three bits costs nothing measurable.
/// - EXPOSURE: the frame's place in its set: 0 for the frame after `hdr.ctrl.NEW_SET` (the
///   longest exposure), one more for each later frame, 7 for the eighth and after.
/// - UNDER, OVER: the grouped word's flags, unchanged.
pub mod hdr_map {
    use super::grouped;

    /// Fractional bits of the luminance.
    pub const LUMA_FRAC_BITS: u32 = 11;
    /// Fractional bits of the grouped word dropped.
    pub const DROPPED_FRAC_BITS: u32 = grouped::LUMA_FRAC_BITS - LUMA_FRAC_BITS;
    /// Width of the luminance field (bit 0 up).
    pub const LUMA_WIDTH: u32 = 27;
    /// Mask of the luminance field.
    pub const LUMA_MASK: u32 = (1 << LUMA_WIDTH) - 1;
    /// Position of the exposure index.
    pub const EXPOSURE_LSB: u32 = 27;
    /// Width of the exposure field (`seq` has up to eight exposures).
    pub const EXPOSURE_WIDTH: u32 = 3;

    // The largest grouped luminance fits, and the fields do not overlap the flags.
    const _: () = assert!(grouped::LUMA_MAX_Q14 >> DROPPED_FRAC_BITS < 1 << LUMA_WIDTH);
    const _: () = assert!(EXPOSURE_LSB + EXPOSURE_WIDTH == grouped::UNDER_BIT);

    /// The map word for a grouped word of exposure `exposure_index` (three bits kept).
    pub const fn from_grouped(word: u32, exposure_index: u8) -> u32 {
        (word & (grouped::OVER | grouped::UNDER))
            | (((exposure_index as u32) & 7) << EXPOSURE_LSB)
            | (grouped::luma_q14(word) >> DROPPED_FRAC_BITS)
    }
    /// The luminance, in units of 2^-11 DN.
    pub const fn luma_q11(word: u32) -> u32 {
        word & LUMA_MASK
    }
    /// The luminance in digital numbers (weighted, black-subtracted), as the merge's signal.
    pub fn luma(word: u32) -> f64 {
        luma_q11(word) as f64 / (1u32 << LUMA_FRAC_BITS) as f64
    }
    /// The place in its set of the frame the word came from.
    pub const fn exposure_index(word: u32) -> u8 {
        ((word >> EXPOSURE_LSB) & 7) as u8
    }
    /// The grouped word's flags.
    pub const fn under(word: u32) -> bool {
        grouped::under(word)
    }
    pub const fn over(word: u32) -> bool {
        grouped::over(word)
    }
}

/// Raw mode (for calibration): the samples unchanged, in sensor read-out order, two per word.
///
/// ```text
///  31   28 27          16 15   12 11           0
/// +-------+--------------+-------+--------------+
/// |   0   | odd column   |   0   | even column  |
/// +-------+--------------+-------+--------------+
/// ```
///
/// Each sample sits in its own 16-bit half, so a raw frame in memory reads on the
/// (little-endian) ARM as a plain `u16` array in read-out order. Every row is emitted (no line
/// buffer is involved), `W/2` words per row, `(W/2) H` words per frame. Phase, black level,
/// valid range and weights are ignored. The peak rate equals the grouped mode's (one word
/// per two pixel clocks), so the FIFO after the block sees no new worst case.
pub mod raw {
    /// Samples per word.
    pub const SAMPLES_PER_WORD: u32 = 2;
    /// Position of the even-column (earlier) sample.
    pub const EVEN_LSB: u32 = 0;
    /// Position of the odd-column (later) sample.
    pub const ODD_LSB: u32 = 16;
    /// Mask of one sample at bit 0.
    pub const SAMPLE_MASK: u32 = super::SAMPLE_MAX;

    /// Packs a raw word. Samples are truncated to 12 bits.
    pub const fn pack(even: u16, odd: u16) -> u32 {
        ((even as u32 & SAMPLE_MASK) << EVEN_LSB) | ((odd as u32 & SAMPLE_MASK) << ODD_LSB)
    }
    /// The even-column sample of a raw word.
    pub const fn even(word: u32) -> u16 {
        ((word >> EVEN_LSB) & SAMPLE_MASK) as u16
    }
    /// The odd-column sample of a raw word.
    pub const fn odd(word: u32) -> u16 {
        ((word >> ODD_LSB) & SAMPLE_MASK) as u16
    }
    /// Both samples of a raw word, in read-out order (even column first).
    pub const fn samples(word: u32) -> [u16; 2] {
        [even(word), odd(word)]
    }
    /// Words the block emits for a frame of `width x height` samples (width even).
    pub const fn words_per_frame(width: u32, height: u32) -> u32 {
        (width / 2) * height
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grouped_round_trip() {
        let w = grouped::pack(grouped::LUMA_MAX_Q14 as u32, true, false);
        assert_eq!(grouped::luma_q14(w), grouped::LUMA_MAX_Q14 as u32);
        assert!(grouped::under(w) && !grouped::over(w) && !grouped::valid(w));
        assert_eq!(grouped::pack(0x4000, false, false), 0x4000);
        assert_eq!(grouped::luma(0x4000), 1.0);
        assert_eq!(grouped::pack(0, false, true), 0x8000_0000);
        assert!(grouped::valid(grouped::pack(u32::MAX, false, false)));
    }

    #[test]
    fn hdr_map_round_trip() {
        let g = grouped::pack(grouped::LUMA_MAX_Q14 as u32, false, true);
        let w = hdr_map::from_grouped(g, 5);
        assert_eq!(hdr_map::exposure_index(w), 5);
        assert!(hdr_map::over(w) && !hdr_map::under(w));
        assert_eq!(
            hdr_map::luma_q11(w),
            (grouped::LUMA_MAX_Q14 >> 3) as u32,
            "integer part whole"
        );
        // 1.0 DN plus 2^-14 (dropped): 1.0 DN.
        let w = hdr_map::from_grouped(grouped::pack(0x4001, true, false), 9);
        assert_eq!(hdr_map::luma(w), 1.0);
        assert_eq!(hdr_map::exposure_index(w), 1, "three bits of the index");
        assert!(hdr_map::under(w) && !hdr_map::over(w));
    }

    #[test]
    fn raw_round_trip() {
        let w = raw::pack(0xABC, 0x123);
        assert_eq!(w, 0x0123_0ABC);
        assert_eq!((raw::even(w), raw::odd(w)), (0xABC, 0x123));
        assert_eq!(raw::samples(w), [0xABC, 0x123]);
        // Bits outside the two 12-bit samples are not part of either.
        assert_eq!(raw::samples(w | 0xF000_F000), [0xABC, 0x123]);
        // Read as two little-endian u16: the samples in read-out order.
        let b = w.to_le_bytes();
        assert_eq!(u16::from_le_bytes([b[0], b[1]]), 0xABC);
        assert_eq!(u16::from_le_bytes([b[2], b[3]]), 0x123);
    }
}
