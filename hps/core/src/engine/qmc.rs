//! Stratified (quasi-Monte Carlo) numbers for the first random decisions of each path.
//!
//! Most of the variance of a sensor's estimate comes from its first few decisions: the
//! directions and portal points sampled at the sensor and at the first surface the path
//! meets. Independent random numbers leave clumps and gaps there; a low-discrepancy point
//! set fills those dimensions evenly. Each pair of dimensions gets its own 2-D Sobol' (0,2)
//! sequence, Owen-scrambled and index-shuffled by the hash of Burley ("Practical hash-based
//! Owen scrambling", JCGT 9(4), 2020; Laine & Karras's permutation), so every 2-D
//! projection is stratified and different pairs are decorrelated ("padding").
//!
//! Unbiased: on top of the scramble each coordinate gets a random digital shift (XOR with a
//! uniform 32-bit word), which makes every point exactly uniform on the 2^32 grid whatever
//! the hash, plus a uniform jitter inside its grid cell; so each point, taken alone, is
//! uniform on the unit cube and each path's estimate has the plain Monte-Carlo expectation.
//! The points of one randomisation are not independent of each other, so the standard error
//! is estimated from several independent randomisations (replicates), not from the spread of
//! single paths (`engine::illuminance`).

use super::rng::{Rng, STRATIFIED_DIMENSIONS};

/// Pairs of dimensions, each its own 2-D sequence.
const PAIRS: usize = STRATIFIED_DIMENSIONS / 2;

/// Laine & Karras's permutation of the bits of `x` (each bit depends only on lower ones), as
/// Burley gives it.
fn laine_karras(mut x: u32, seed: u32) -> u32 {
    x = x.wrapping_add(seed);
    x ^= x.wrapping_mul(0x6c50_b47c);
    x ^= x.wrapping_mul(0xb82f_1e52);
    x ^= x.wrapping_mul(0xc7af_e638);
    x ^= x.wrapping_mul(0x8d22_f6e6);
    x
}

/// Nested uniform scramble of a 32-bit fraction (each bit flipped by a hash of the bits
/// above it).
fn nested_scramble(x: u32, seed: u32) -> u32 {
    laine_karras(x.reverse_bits(), seed).reverse_bits()
}

/// The first two dimensions of Sobol's sequence as 32-bit fractions: the van der Corput
/// sequence and the dimension with direction numbers v_k = v_{k-1} ^ (v_{k-1} >> 1). The
/// second is linear over GF(2) in the index bits, so it is the XOR of four byte-table
/// lookups (a bit loop of 32 steps was a third of the time of a two-bounce path).
fn sobol_2d(index: u32) -> (u32, u32) {
    let t = &SOBOL_DIM1_BYTES;
    let y = t[0][(index & 0xff) as usize]
        ^ t[1][((index >> 8) & 0xff) as usize]
        ^ t[2][((index >> 16) & 0xff) as usize]
        ^ t[3][(index >> 24) as usize];
    (index.reverse_bits(), y)
}

/// Sobol's second dimension by the definition: XOR of v_k over the set bits k of `index`.
const fn sobol_dim1_bits(index: u32) -> u32 {
    let mut y = 0u32;
    let mut v = 1u32 << 31;
    let mut i = index;
    while i != 0 {
        if i & 1 != 0 {
            y ^= v;
        }
        v ^= v >> 1;
        i >>= 1;
    }
    y
}

/// `SOBOL_DIM1_BYTES[b][x]`: the second dimension's contribution of byte `b` of the index
/// holding `x`.
const SOBOL_DIM1_BYTES: [[u32; 256]; 4] = {
    let mut t = [[0u32; 256]; 4];
    let mut b = 0;
    while b < 4 {
        let mut x = 0;
        while x < 256 {
            t[b][x] = sobol_dim1_bits((x as u32) << (8 * b));
            x += 1;
        }
        b += 1;
    }
    t
};

/// One randomisation of the point set: the scramble seeds and digital shifts of each pair.
#[derive(Clone, Debug)]
pub struct Randomisation {
    /// Per pair: index-shuffle seed, the two coordinates' scramble seeds and shifts.
    pairs: [[u32; 5]; PAIRS],
}

impl Randomisation {
    /// Draws a randomisation from `rng`.
    pub fn new(rng: &mut Rng) -> Self {
        let mut pairs = [[0u32; 5]; PAIRS];
        for p in &mut pairs {
            for w in p.iter_mut() {
                *w = (rng.next_u64() >> 32) as u32;
            }
        }
        Self { pairs }
    }

    /// Point `index` of the set, each coordinate in [0, 1); `jitter` supplies the uniform
    /// offsets inside the 2^-32 cells.
    pub fn point(&self, index: u32, jitter: &mut Rng) -> [f64; STRATIFIED_DIMENSIONS] {
        let mut out = [0.0; STRATIFIED_DIMENSIONS];
        for (k, p) in self.pairs.iter().enumerate() {
            let (x, y) = sobol_2d(nested_scramble(index, p[0]));
            let x = nested_scramble(x, p[1]) ^ p[3];
            let y = nested_scramble(y, p[2]) ^ p[4];
            // 2^-32 per grid step; the jitter spreads each value over its cell.
            const STEP: f64 = 1.0 / 4_294_967_296.0;
            out[2 * k] = ((f64::from(x) + jitter.uniform()) * STEP).min(1.0 - f64::EPSILON / 2.0);
            out[2 * k + 1] =
                ((f64::from(y) + jitter.uniform()) * STEP).min(1.0 - f64::EPSILON / 2.0);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first 2^k points of each pair are a (0, k, 2)-net: every elementary interval of
    /// area 2^-k (here 16 × 16 cells for 256 points, and 4 × 64) holds exactly one point,
    /// which is what the scramble must preserve.
    #[test]
    fn pairs_are_stratified() {
        let mut rng = Rng::for_stream(5, 0);
        let r = Randomisation::new(&mut rng);
        let pts: Vec<[f64; STRATIFIED_DIMENSIONS]> =
            (0..256).map(|i| r.point(i, &mut rng)).collect();
        for k in 0..PAIRS {
            for (nx, ny) in [(16usize, 16usize), (4, 64), (256, 1)] {
                let mut seen = vec![0u32; 256];
                for p in &pts {
                    let (cx, cy) = (
                        (p[2 * k] * nx as f64) as usize,
                        (p[2 * k + 1] * ny as f64) as usize,
                    );
                    seen[cx * ny + cy] += 1;
                }
                assert!(seen.iter().all(|&c| c == 1), "pair {k} {nx}x{ny}");
            }
        }
    }

    /// The byte tables give the second dimension exactly as the bit-by-bit definition.
    #[test]
    fn byte_tables_match_the_definition() {
        let mut rng = Rng::for_stream(7, 0);
        for i in (0..4096u32).chain((0..4096).map(|_| (rng.next_u64() >> 32) as u32)) {
            assert_eq!(sobol_2d(i).1, sobol_dim1_bits(i), "{i}");
        }
    }

    /// Each point, over randomisations, is uniform: the mean of a coordinate of one fixed
    /// index over many randomisations is 1/2 and its mean square 1/3.
    #[test]
    fn points_are_uniform_over_randomisations() {
        let mut rng = Rng::for_stream(6, 0);
        let n = 20_000;
        let (mut s, mut s2) = ([0.0; STRATIFIED_DIMENSIONS], [0.0; STRATIFIED_DIMENSIONS]);
        for _ in 0..n {
            let r = Randomisation::new(&mut rng);
            let p = r.point(3, &mut rng);
            for d in 0..STRATIFIED_DIMENSIONS {
                s[d] += p[d];
                s2[d] += p[d] * p[d];
            }
        }
        for d in 0..STRATIFIED_DIMENSIONS {
            // Standard errors: 1/sqrt(12 n) = 0.002 and sqrt(4/45 / n) = 0.0021; 5 sigma.
            assert!((s[d] / n as f64 - 0.5).abs() < 0.0102, "{d}");
            assert!((s2[d] / n as f64 - 1.0 / 3.0).abs() < 0.0106, "{d}");
        }
    }
}
