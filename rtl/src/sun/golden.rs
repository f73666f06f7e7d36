//! Golden model of the sun accumulators, written from the specification (issue 22 item 2), not
//! from the RTL: a whole frame of grouped words in raster order, no clocks or pipelines.

use skylux_regmap::words::grouped;

pub use skylux_regmap::sun_values::{SunConfig, SunSums};

/// Adds a counted group to the sums.
fn add(sums: &mut SunSums, x: u16, y: u16, word: u32) {
    let l = grouped::luma_q14(word);
    if sums.count == 0 {
        (sums.min_x, sums.max_x, sums.min_y, sums.max_y) = (x, x, y, y);
    }
    sums.count += 1;
    sums.over_count += u32::from(grouped::over(word));
    sums.sum_l += u64::from(l);
    sums.sum_xl += u64::from(x) * u64::from(l);
    sums.sum_yl += u64::from(y) * u64::from(l);
    sums.max_l = sums.max_l.max(l);
    sums.min_x = sums.min_x.min(x);
    sums.max_x = sums.max_x.max(x);
    sums.min_y = sums.min_y.min(y);
    sums.max_y = sums.max_y.max(y);
}

/// Whether a group at (`x`, `y`) with `word` counts: inside the window and its luminance at
/// the threshold. The under-range flag does not exclude a group: the disk's blurred limb is
/// dim in the shortest exposure, and leaving it out would bias the flux low; the threshold
/// keeps noise out.
pub fn counts(config: &SunConfig, x: u16, y: u16, word: u32) -> bool {
    (config.x_min..=config.x_max).contains(&x)
        && (config.y_min..=config.y_max).contains(&y)
        && grouped::luma_q14(word) >= config.threshold_q14
}

/// The sums over one frame of grouped words in raster order (`groups_per_line` of them per
/// line, one when zero; a last, partial line is accumulated as far as it goes). Positions are
/// 11-bit counters, as in the fabric: line 2048 is line 0 again.
pub fn accumulate(config: &SunConfig, words: &[u32]) -> SunSums {
    let mut sums = SunSums::default();
    let per_line = usize::from(config.groups_per_line.max(1));
    for (i, &word) in words.iter().enumerate() {
        let (x, y) = ((i % per_line) as u16, ((i / per_line) % 2048) as u16);
        if counts(config, x, y, word) {
            add(&mut sums, x, y, word);
        }
    }
    sums
}

#[cfg(test)]
mod tests {
    use super::*;

    fn config() -> SunConfig {
        SunConfig {
            groups_per_line: 4,
            threshold_q14: 100,
            x_min: 0,
            x_max: 3,
            y_min: 0,
            y_max: 3,
        }
    }

    #[test]
    fn a_two_group_sun_by_hand() {
        // Line 0: 50 (below), 300 at x=1; line 1: 100 at x=2 (at the threshold, over-range),
        // and an under-flagged group at x=3 that reaches the threshold, which counts.
        let words = [
            grouped::pack(50, false, false),
            grouped::pack(300, false, false),
            0,
            0,
            0,
            0,
            grouped::pack(100, false, true),
            grouped::pack(5000, true, false),
        ];
        let s = accumulate(&config(), &words);
        assert_eq!(s.count, 3);
        assert_eq!(s.over_count, 1);
        assert_eq!(s.sum_l, 5400);
        assert_eq!(s.sum_xl, 300 + 2 * 100 + 3 * 5000);
        assert_eq!(s.sum_yl, 100 + 5000);
        assert_eq!(s.max_l, 5000);
        assert_eq!((s.min_x, s.max_x, s.min_y, s.max_y), (1, 3, 0, 1));
        assert_eq!(s.centroid(), Some((15500.0 / 5400.0, 5100.0 / 5400.0)));
    }

    #[test]
    fn the_window_excludes_groups_outside_it() {
        let c = SunConfig {
            x_min: 2,
            y_min: 1,
            ..config()
        };
        let words = vec![grouped::pack(1000, false, false); 16];
        let s = accumulate(&c, &words);
        // x in 2..=3, y in 1..=3: 2 x 3 groups.
        assert_eq!(s.count, 6);
        assert_eq!((s.min_x, s.max_x, s.min_y, s.max_y), (2, 3, 1, 3));
        assert_eq!(s.centroid(), Some((2.5, 2.0)));
    }

    #[test]
    fn nothing_counted_leaves_zeros() {
        let s = accumulate(&config(), &[0; 16]);
        assert_eq!(s, SunSums::default());
        assert_eq!(s.centroid(), None);
    }

    #[test]
    fn the_widest_sums_fit_their_registers() {
        // A full 2592 x 1944 frame at the largest luminance: every sum below 2^64.
        let (width, height) = (1296u64, 972u64);
        let l = grouped::LUMA_MAX_Q14;
        assert!(width * height < 1 << 21, "count");
        assert!(l * width * height < 1 << 52, "sum_l");
        // Σ x over the frame = height · width (width - 1) / 2.
        let sum_x = height * width * (width - 1) / 2;
        assert!(l.checked_mul(sum_x).is_some(), "sum_xl");
        assert!(width < 1 << 11 && height < 1 << 11, "positions");
    }
}
