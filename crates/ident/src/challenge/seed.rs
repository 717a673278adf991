//! The challenges' seeding: every (seed, index, attempt) gets its own stream of the
//! workspace's generator ([`Lcg`]), started from a SplitMix64 mix of the three so that
//! neighbouring seeds and indices give unrelated records. Integer arithmetic only: the same
//! on every machine.

use crate::random::Lcg;

/// SplitMix64's finaliser (Steele, Lea & Flood 2014): a bijective scramble of 64 bits.
pub fn splitmix64(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// The generator of the `attempt`-th draw of challenge `index` of `seed`.
pub fn stream(seed: u64, index: usize, attempt: usize) -> Lcg {
    let mixed = splitmix64(splitmix64(splitmix64(seed) ^ index as u64) ^ attempt as u64);
    let mut rng = Lcg(mixed);
    rng.bits();
    rng
}

#[cfg(test)]
mod tests {
    use super::*;

    /// SplitMix64's published first outputs from state 0 (the reference C code's
    /// `next()` adds the constant, then scrambles).
    #[test]
    fn splitmix64_matches_the_reference_stream() {
        assert_eq!(splitmix64(0), 0xE220_A839_7B1D_CDAF);
        assert_eq!(splitmix64(0x9E37_79B9_7F4A_7C15), 0x6E78_9E6A_A1B9_65F4);
    }

    #[test]
    fn streams_differ_by_seed_index_and_attempt() {
        let first = |s, i, a| stream(s, i, a).bits();
        let a = first(1, 0, 0);
        assert_ne!(a, first(2, 0, 0));
        assert_ne!(a, first(1, 1, 0));
        assert_ne!(a, first(1, 0, 1));
        assert_eq!(a, first(1, 0, 0));
    }
}
