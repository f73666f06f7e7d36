//! The fabric HDR selection's settings as values (issue 22 item 1): what the HPS writes to
//! `hdr.*` before a set, and the rule both sides apply. The fabric's block (`skylux_rtl::hdr`)
//! and its golden model, and the HPS's reading of the map (`skylux_hps::hdr::fabric_map`),
//! share it, so the HPS can tell a usable group from the map word alone.

use crate::words::{grouped, hdr_map};

/// The selection's thresholds on the luminance in the map's own units (2^-11 DN), so that
/// the map word decides usability exactly as the grouped word did.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct HdrConfig {
    /// A group is usable at or above this: a floor below which a shorter exposure would do
    /// no worse. 0 leaves it to `bayer.valid.MIN`.
    pub min_q11: u32,
    /// ... and at or below this: a saturation ceiling tighter than `bayer.valid.MAX` if wanted.
    pub max_q11: u32,
}

impl Default for HdrConfig {
    /// The registers' reset values: only the grouped word's flags decide.
    fn default() -> Self {
        HdrConfig {
            min_q11: 0,
            max_q11: hdr_map::LUMA_MASK,
        }
    }
}

impl HdrConfig {
    /// Whether a group's grouped word is usable: no sample out of `bayer.valid`'s range and
    /// the luminance, as the map keeps it, inside the thresholds.
    pub fn usable(&self, grouped_word: u32) -> bool {
        let l = grouped::luma_q14(grouped_word) >> hdr_map::DROPPED_FRAC_BITS;
        grouped::valid(grouped_word) && l >= self.min_q11 && l <= self.max_q11
    }

    /// The same on a map word: a map word is usable exactly when the grouped word it came
    /// from was.
    pub fn usable_map_word(&self, map_word: u32) -> bool {
        let l = hdr_map::luma_q11(map_word);
        !hdr_map::over(map_word)
            && !hdr_map::under(map_word)
            && l >= self.min_q11
            && l <= self.max_q11
    }

    /// The checksum a map's descriptor carries: the wrapping sum of its usable words. The
    /// fabric adds each word as it settles (written while its group was not filled, and
    /// usable), which is the word the map keeps for good, so the HPS can recompute it from
    /// the map alone; a word corrupted on its way to memory changes it, unless the word
    /// stays unusable (then its group is not measured anyway).
    pub fn map_checksum(&self, map_words: &[u32]) -> u32 {
        map_words
            .iter()
            .filter(|&&w| self.usable_map_word(w))
            .fold(0u32, |sum, &w| sum.wrapping_add(w))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn map_words_are_usable_exactly_when_their_grouped_words_were() {
        let c = HdrConfig {
            min_q11: 100,
            max_q11: 200,
        };
        for l in [0u32, 799, 800, 807, 808, 1600, 1607, 1608, 1_000_000] {
            for (under, over) in [(false, false), (true, false), (false, true)] {
                let g = grouped::pack(l, under, over);
                let m = hdr_map::from_grouped(g, 3);
                assert_eq!(c.usable(g), c.usable_map_word(m), "{l} {under} {over}");
            }
        }
        assert!(c.usable(grouped::pack(800, false, false)));
        assert!(!c.usable(grouped::pack(799, false, false)));
        assert!(c.usable(grouped::pack(1607, false, false)));
        assert!(!c.usable(grouped::pack(1608, false, false)));
    }

    #[test]
    fn the_map_checksum_sums_the_usable_words_wrapping() {
        let c = HdrConfig::default();
        let ok = |l| hdr_map::from_grouped(grouped::pack(l, false, false), 0);
        let over = hdr_map::from_grouped(grouped::pack(5, false, true), 1);
        assert_eq!(c.map_checksum(&[ok(8), over, ok(16)]), ok(8) + ok(16));
        let big =
            hdr_map::from_grouped(grouped::pack(grouped::LUMA_MAX_Q14 as u32, false, false), 7);
        assert_eq!(
            c.map_checksum(&[big, big, big]),
            big.wrapping_add(big).wrapping_add(big)
        );
    }
}
