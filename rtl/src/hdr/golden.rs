//! Golden model of the HDR selection, written from the specification (issue 22 item 1), not
//! from the RTL: frames of grouped words in raster order, no clocks or pipelines.

#[cfg(test)]
use skylux_regmap::words::grouped;
use skylux_regmap::words::hdr_map;

/// Bits of the filled mask: 2^20 for positions below 2^20, then 2^18 (the RTL's two block
/// RAMs, [`crate::hdr::MASK_LOW_BITS`] and [`crate::hdr::MASK_HIGH_BITS`]).
pub const MASK_GROUPS: usize = (1 << 20) + (1 << 18);

/// Where the mask keeps group position `i`: positions count in 21 bits (wrapping); below 2^20
/// they are their own slot, above it their low 18 bits pick one of the last 2^18 slots (no
/// frame has more than 1,259,712 groups, so none alias).
pub fn mask_slot(i: usize) -> usize {
    let p = i % (1 << 21);
    if p < 1 << 20 {
        p
    } else {
        (1 << 20) + p % (1 << 18)
    }
}

pub use skylux_regmap::hdr_values::HdrConfig;

/// Whether a group's word is usable ([`HdrConfig::usable`], the rule the HPS shares).
pub fn usable(config: &HdrConfig, word: u32) -> bool {
    config.usable(word)
}

/// One frame of a set as the fabric sees it.
#[derive(Clone, Debug)]
pub struct SetFrame<'a> {
    /// The frame's place in its set, the map words' exposure field (three bits are kept).
    pub exposure_index: u8,
    /// The first frame of a set: the mask's old contents do not count.
    pub first_of_set: bool,
    pub words: &'a [u32],
}

/// The filled mask, one bit per group position, kept across frames as the block RAM keeps it
/// (zero at power-up).
#[derive(Clone, Debug)]
pub struct FilledMask {
    bits: Vec<bool>,
}

impl Default for FilledMask {
    fn default() -> Self {
        FilledMask {
            bits: vec![false; MASK_GROUPS],
        }
    }
}

impl FilledMask {
    /// What the block emits for `frame`: per word, the map word and whether it is written
    /// (not yet filled). Updates the mask.
    pub fn frame(&mut self, config: &HdrConfig, frame: &SetFrame) -> Vec<(u32, bool)> {
        frame
            .words
            .iter()
            .enumerate()
            .map(|(i, &word)| {
                let bit = &mut self.bits[mask_slot(i)];
                let filled = !frame.first_of_set && *bit;
                *bit = filled || usable(config, word);
                (hdr_map::from_grouped(word, frame.exposure_index), !filled)
            })
            .collect()
    }
}

/// The map a set leaves in memory, declaratively: for each group, the word of the first
/// frame (the longest exposure) in which it is usable, or the last frame's. All frames cover
/// the first frame's groups.
pub fn select(config: &HdrConfig, frames: &[SetFrame]) -> Vec<u32> {
    let Some(last) = frames.last() else {
        return vec![];
    };
    (0..frames[0].words.len())
        .map(|i| {
            let from = frames
                .iter()
                .find(|f| usable(config, f.words[i]))
                .unwrap_or(last);
            hdr_map::from_grouped(from.words[i], from.exposure_index)
        })
        .collect()
}

/// Applies a frame's writes to a map buffer (the DMA's byte enables).
pub fn apply(map: &mut [u32], writes: &[(u32, bool)]) {
    for (m, &(word, write)) in map.iter_mut().zip(writes) {
        if write {
            *m = word;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const OK: bool = false;

    fn g(l: u32, under: bool, over: bool) -> u32 {
        grouped::pack(l, under, over)
    }

    #[test]
    fn the_longest_usable_exposure_wins_by_hand() {
        // Three groups over three exposures, long (index 0) to short (2):
        // group 0 usable in the longest; group 1 over there, usable in 1 and 2 (1 wins);
        // group 2 over everywhere (the last frame's word, flags kept).
        let e0 = [g(1000, OK, OK), g(9, OK, true), g(9, OK, true)];
        let e1 = [g(40, OK, OK), g(2000, OK, OK), g(9, OK, true)];
        let e2 = [g(1, true, OK), g(70, OK, OK), g(7, OK, true)];
        let frames = [
            SetFrame {
                exposure_index: 0,
                first_of_set: true,
                words: &e0,
            },
            SetFrame {
                exposure_index: 1,
                first_of_set: false,
                words: &e1,
            },
            SetFrame {
                exposure_index: 2,
                first_of_set: false,
                words: &e2,
            },
        ];
        let c = HdrConfig::default();
        let map = select(&c, &frames);
        assert_eq!(
            map,
            vec![
                hdr_map::from_grouped(e0[0], 0),
                hdr_map::from_grouped(e1[1], 1),
                hdr_map::from_grouped(e2[2], 2),
            ]
        );
        assert!(hdr_map::over(map[2]));
        // The streamed writes leave the same map, and write each group once it is filled.
        let mut mask = FilledMask::default();
        let mut memory = vec![0xDEAD_BEEF; 3];
        let writes: Vec<_> = frames.iter().map(|f| mask.frame(&c, f)).collect();
        for w in &writes {
            apply(&mut memory, w);
        }
        assert_eq!(memory, map);
        let written: Vec<Vec<bool>> = writes
            .iter()
            .map(|w| w.iter().map(|x| x.1).collect())
            .collect();
        assert_eq!(
            written,
            vec![
                vec![true, true, true],
                vec![false, true, true],
                vec![false, false, true]
            ]
        );
    }

    #[test]
    fn mask_slots_cover_the_full_frame_once() {
        let full = 1296 * 972;
        let mut seen = vec![false; MASK_GROUPS];
        for i in 0..full {
            assert!(!std::mem::replace(&mut seen[mask_slot(i)], true), "{i}");
        }
        assert_eq!(mask_slot((1 << 20) + 5), (1 << 20) + 5);
        assert_eq!(mask_slot((1 << 21) + 3), 3, "21-bit positions wrap");
    }

    #[test]
    fn thresholds_narrow_the_usable_range() {
        let c = HdrConfig {
            min_q11: 100,
            max_q11: 200,
        };
        // Luminances in 2^-14 DN: the thresholds apply to them without their last 3 bits.
        assert!(!usable(&c, g(799, OK, OK)));
        assert!(usable(&c, g(800, OK, OK)));
        assert!(usable(&c, g(1607, OK, OK)));
        assert!(!usable(&c, g(1608, OK, OK)));
        assert!(!usable(&c, g(150, true, OK)));
        assert!(!usable(&HdrConfig::default(), g(150, OK, true)));
    }

    #[test]
    fn a_new_set_ignores_the_old_mask() {
        let c = HdrConfig::default();
        let mut mask = FilledMask::default();
        let w = [g(5, OK, OK)];
        let first = |words| SetFrame {
            exposure_index: 0,
            first_of_set: true,
            words,
        };
        assert!(mask.frame(&c, &first(&w))[0].1);
        // Filled now: a later frame of the same set is masked, a new set's first is not.
        let later = SetFrame {
            exposure_index: 1,
            first_of_set: false,
            words: &w,
        };
        assert!(!mask.frame(&c, &later)[0].1);
        assert!(mask.frame(&c, &first(&w))[0].1);
    }
}
