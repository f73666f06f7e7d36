//! FNV-1a, 64 bits (Fowler, Noll, Vo): a stable hash for cache keys (std's hasher may change
//! between Rust releases, and a cache must outlive the binary that wrote it).

/// The offset basis: the hash of nothing.
pub const FNV1A_OFFSET: u64 = 0xCBF2_9CE4_8422_2325;

/// Folds `bytes` into `hash`.
pub fn fnv1a(hash: &mut u64, bytes: &[u8]) {
    for &b in bytes {
        *hash ^= u64::from(b);
        *hash = hash.wrapping_mul(0x0000_0100_0000_01B3);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv_is_the_published_function() {
        // FNV-1a 64 test vectors (Fowler, Noll, Vo reference code): "" and "a".
        let mut h = FNV1A_OFFSET;
        fnv1a(&mut h, b"");
        assert_eq!(h, 0xcbf2_9ce4_8422_2325);
        fnv1a(&mut h, b"a");
        assert_eq!(h, 0xaf63_dc4c_8601_ec8c);
    }
}
