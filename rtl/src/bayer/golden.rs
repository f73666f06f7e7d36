//! Golden model of the Bayer grouping block, written from the specification (issue 3 item 4
//! and the word format in `skylux_regmap::words`), not from the RTL: it works on a whole
//! frame held in memory and has no notion of clocks, line buffers or pipelines.

use skylux_regmap::words::{grouped, raw};

/// Colours of the four samples of a 2x2 block (`bayer.mode.PHASE`).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Phase {
    Grbg = 0,
    Rggb = 1,
    Bggr = 2,
    Gbrg = 3,
}

/// The colour of one Bayer sample.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Colour {
    Red,
    Green,
    Blue,
}

impl Phase {
    /// All phases, by register value.
    pub const ALL: [Phase; 4] = [Phase::Grbg, Phase::Rggb, Phase::Bggr, Phase::Gbrg];

    /// The phase a `bayer.mode.PHASE` value selects (two bits, so every value is one).
    pub fn from_register(value: u32) -> Phase {
        Phase::ALL[(value & 3) as usize]
    }

    /// The colour at offset (`dx`, `dy`) inside a block: the phase's name lists the colours
    /// of the top-left, top-right, bottom-left and bottom-right samples in read-out order.
    pub fn colour(self, dx: usize, dy: usize) -> Colour {
        use Colour::*;
        let order = match self {
            Phase::Grbg => [Green, Red, Blue, Green],
            Phase::Rggb => [Red, Green, Green, Blue],
            Phase::Bggr => [Blue, Green, Green, Red],
            Phase::Gbrg => [Green, Blue, Red, Green],
        };
        order[2 * (dy & 1) + (dx & 1)]
    }
}

/// The block's configuration, as the `bayer.*` registers hold it.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct BayerConfig {
    pub phase: Phase,
    /// Black level subtracted from every sample (12 bits).
    pub black: u16,
    /// Lowest in-range sample, before black subtraction (12 bits).
    pub valid_min: u16,
    /// Highest in-range sample, before black subtraction (12 bits).
    pub valid_max: u16,
    /// Colour weights, unsigned Q2.14.
    pub weight_r: u16,
    pub weight_g: u16,
    pub weight_b: u16,
    /// Store the samples unchanged instead of grouping them.
    pub raw: bool,
}

impl Default for BayerConfig {
    /// The registers' reset values (grouped mode, since `bayer.mode` has no raw bit yet).
    fn default() -> Self {
        use skylux_regmap::bayer;
        BayerConfig {
            phase: Phase::from_register(bayer::mode::PHASE.reset),
            black: bayer::black::LEVEL.reset as u16,
            valid_min: bayer::valid::MIN.reset as u16,
            valid_max: bayer::valid::MAX.reset as u16,
            weight_r: bayer::weight_r::Q2_14.reset as u16,
            weight_g: bayer::weight_g::Q2_14.reset as u16,
            weight_b: bayer::weight_b::Q2_14.reset as u16,
            raw: false,
        }
    }
}

/// One frame of raw samples, row-major.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Frame {
    pub width: usize,
    pub height: usize,
    /// `width * height` samples of 12 bits.
    pub samples: Vec<u16>,
}

impl Frame {
    pub fn at(&self, x: usize, y: usize) -> u16 {
        self.samples[y * self.width + x]
    }
}

/// The words the block emits for `frame`, in emission order.
///
/// Grouped mode: for each 2x2 block (row pairs top to bottom, blocks left to right), the
/// luminance `w_r R' + w_g (G1' + G2')/2 + w_b B'` with `X' = max(X - black, 0)`, truncated to
/// 14 fractional bits, and the flags "a sample < valid_min" and "a sample > valid_max" on the
/// samples before black subtraction. A trailing odd row or column has no block and yields
/// nothing. Raw mode: every row, each pair of samples (even column, odd column) as one word.
pub fn expected_words(frame: &Frame, config: &BayerConfig) -> Vec<u32> {
    assert_eq!(frame.samples.len(), frame.width * frame.height);
    let mut words = vec![];
    if config.raw {
        for y in 0..frame.height {
            for x in (0..frame.width - frame.width % 2).step_by(2) {
                words.push(raw::pack(frame.at(x, y), frame.at(x + 1, y)));
            }
        }
        return words;
    }
    for by in 0..frame.height / 2 {
        for bx in 0..frame.width / 2 {
            words.push(group(frame, config, bx, by));
        }
    }
    words
}

/// The grouped word of block (`bx`, `by`).
fn group(frame: &Frame, config: &BayerConfig, bx: usize, by: usize) -> u32 {
    // Sums in units of 2^-15: each term is weight (2^-14) times sample, and the green term's
    // halving is carried as a doubling of the others, so everything stays an exact integer.
    let mut twice_luma: u64 = 0;
    let mut under = false;
    let mut over = false;
    for dy in 0..2 {
        for dx in 0..2 {
            let sample = frame.at(2 * bx + dx, 2 * by + dy);
            under |= sample < config.valid_min;
            over |= sample > config.valid_max;
            let above_black = u64::from(sample.saturating_sub(config.black));
            twice_luma += above_black
                * match config.phase.colour(dx, dy) {
                    Colour::Red => 2 * u64::from(config.weight_r),
                    Colour::Green => u64::from(config.weight_g),
                    Colour::Blue => 2 * u64::from(config.weight_b),
                };
        }
    }
    let luma_q14 = twice_luma / 2; // truncation, the format's rounding
    assert!(luma_q14 <= grouped::LUMA_MAX_Q14);
    grouped::pack(luma_q14 as u32, under, over)
}
