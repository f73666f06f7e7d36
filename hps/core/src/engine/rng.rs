//! The random numbers of the engine: xoshiro256++ (Blackman & Vigna, "Scrambled linear
//! pseudorandom number generators", 2021) seeded through SplitMix64, written out here so the
//! sequence is fixed by this file alone (no dependency's version can change a result) and is
//! the same on x86-64 and on the 32-bit ARM target (only `u64` arithmetic).

/// SplitMix64 step (Steele, Lea & Flood 2014): used to expand seeds and to mix stream ids.
pub fn splitmix64(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Numbers a path takes from its stratified point set (`engine::qmc`) before its
/// pseudo-random stream: the longest prefix a generator holds.
pub const STRATIFIED_DIMENSIONS: usize = 24;

/// A xoshiro256++ generator, optionally preceded by a few given numbers (a path's
/// stratified dimensions, `engine::qmc`) that [`Rng::uniform`] returns first.
#[derive(Clone, Debug)]
pub struct Rng {
    s: [u64; 4],
    prefix: [f64; STRATIFIED_DIMENSIONS],
    prefix_len: u8,
    prefix_next: u8,
}

impl Rng {
    /// A generator for one independent stream: the user's seed and a stream id (e.g. sensor
    /// and batch index) are mixed so that neighbouring streams are uncorrelated.
    pub fn for_stream(seed: u64, stream: u64) -> Self {
        let mut sm = seed ^ splitmix64(&mut stream.wrapping_mul(0xD1B5_4A32_D192_ED03));
        let s = [
            splitmix64(&mut sm),
            splitmix64(&mut sm),
            splitmix64(&mut sm),
            splitmix64(&mut sm),
        ];
        Self {
            s,
            prefix: [0.0; STRATIFIED_DIMENSIONS],
            prefix_len: 0,
            prefix_next: 0,
        }
    }

    /// The next calls of [`Rng::uniform`] return `values` (each in [0, 1)) in order, then
    /// the stream resumes where it was.
    pub fn set_prefix(&mut self, values: &[f64; STRATIFIED_DIMENSIONS]) {
        self.prefix = *values;
        self.prefix_len = values.len() as u8;
        self.prefix_next = 0;
    }

    /// Drops what is left of the prefix.
    pub fn clear_prefix(&mut self) {
        self.prefix_len = 0;
        self.prefix_next = 0;
    }

    /// Next 64 random bits (xoshiro256++ reference implementation).
    pub fn next_u64(&mut self) -> u64 {
        let s = &mut self.s;
        let result = s[0].wrapping_add(s[3]).rotate_left(23).wrapping_add(s[0]);
        let t = s[1] << 17;
        s[2] ^= s[0];
        s[3] ^= s[1];
        s[1] ^= s[2];
        s[0] ^= s[3];
        s[2] ^= t;
        s[3] = s[3].rotate_left(45);
        result
    }

    /// Uniform in [0, 1) with 53 random bits.
    pub fn uniform(&mut self) -> f64 {
        if self.prefix_next < self.prefix_len {
            let u = self.prefix[usize::from(self.prefix_next)];
            self.prefix_next += 1;
            return u;
        }
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn streams_differ_and_repeat() {
        let a: Vec<u64> = (0..4)
            .map({
                let mut r = Rng::for_stream(1, 0);
                move |_| r.next_u64()
            })
            .collect();
        let b: Vec<u64> = (0..4)
            .map({
                let mut r = Rng::for_stream(1, 0);
                move |_| r.next_u64()
            })
            .collect();
        let c = Rng::for_stream(1, 1).next_u64();
        assert_eq!(a, b);
        assert_ne!(a[0], c);
    }

    #[test]
    fn uniform_mean_is_one_half() {
        let mut r = Rng::for_stream(7, 3);
        let n = 100_000;
        let mean = (0..n).map(|_| r.uniform()).sum::<f64>() / n as f64;
        // Standard error of the mean of U(0,1) is 1/sqrt(12 n) = 0.0009; allow 5 sigma.
        assert!((mean - 0.5).abs() < 0.0046, "{mean}");
    }
}
