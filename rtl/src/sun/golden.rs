//! Golden model of the sun accumulators, written from the specification (issue 22 item 2), not
//! from the RTL: a whole frame of grouped words in raster order, no clocks or pipelines.

use skylux_regmap::words::grouped;

/// The accumulators' configuration, as the HPS sets it before the sun's exposure.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct SunConfig {
    /// Groups per line of the window the grouper emits (the frame's width / 2).
    pub groups_per_line: u16,
    /// A group counts when its luminance (2^-14 DN, the grouped word's field) is at least this.
    pub threshold_q14: u32,
    /// The search window, inclusive, in group coordinates: the HPS centres it on the sun's
    /// predicted position, so a bright reflection elsewhere in the field does not pull the
    /// centroid (the HPS's `extract_sun` picks the component nearest the prediction).
    pub x_min: u16,
    pub x_max: u16,
    pub y_min: u16,
    pub y_max: u16,
}

/// What the accumulators hold after a frame.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct SunSums {
    /// Groups that counted.
    pub count: u32,
    /// Of those, groups with a sample above `bayer.valid.MAX`: their luminance is clipped, so
    /// the disk luminance is a lower bound when this is not zero.
    pub over_count: u32,
    /// Σ L, Σ x·L and Σ y·L over the counted groups (L in 2^-14 DN; x, y in groups).
    pub sum_l: u64,
    pub sum_xl: u64,
    pub sum_yl: u64,
    /// The largest L counted.
    pub max_l: u32,
    /// The bounding box of the counted groups (all zero when none counted).
    pub min_x: u16,
    pub max_x: u16,
    pub min_y: u16,
    pub max_y: u16,
}

impl SunSums {
    /// The luminance-weighted centroid in group coordinates (x, y), if any group counted.
    pub fn centroid(&self) -> Option<(f64, f64)> {
        (self.sum_l > 0).then(|| {
            (
                self.sum_xl as f64 / self.sum_l as f64,
                self.sum_yl as f64 / self.sum_l as f64,
            )
        })
    }

    fn add(&mut self, x: u16, y: u16, word: u32) {
        let l = grouped::luma_q14(word);
        if self.count == 0 {
            (self.min_x, self.max_x, self.min_y, self.max_y) = (x, x, y, y);
        }
        self.count += 1;
        self.over_count += u32::from(grouped::over(word));
        self.sum_l += u64::from(l);
        self.sum_xl += u64::from(x) * u64::from(l);
        self.sum_yl += u64::from(y) * u64::from(l);
        self.max_l = self.max_l.max(l);
        self.min_x = self.min_x.min(x);
        self.max_x = self.max_x.max(x);
        self.min_y = self.min_y.min(y);
        self.max_y = self.max_y.max(y);
    }
}

/// Whether a group at (`x`, `y`) with `word` counts: inside the window, no sample under the
/// valid range (a dark sample means the block is not the sun's), luminance at the threshold.
pub fn counts(config: &SunConfig, x: u16, y: u16, word: u32) -> bool {
    (config.x_min..=config.x_max).contains(&x)
        && (config.y_min..=config.y_max).contains(&y)
        && !grouped::under(word)
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
            sums.add(x, y, word);
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
        // Line 0: 50 (below), 300 at x=1; line 1: 100 at x=2 (at the threshold), and an
        // under-flagged bright group at x=3, which does not count.
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
        assert_eq!(s.count, 2);
        assert_eq!(s.over_count, 1);
        assert_eq!(s.sum_l, 400);
        assert_eq!(s.sum_xl, 300 + 2 * 100);
        assert_eq!(s.sum_yl, 100);
        assert_eq!(s.max_l, 300);
        assert_eq!((s.min_x, s.max_x, s.min_y, s.max_y), (1, 2, 0, 1));
        assert_eq!(s.centroid(), Some((500.0 / 400.0, 100.0 / 400.0)));
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
